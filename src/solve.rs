//! `exactcheck solve [FILE|-]`: one problem in JSON, the answer in JSON (DESIGN.md, "The solve
//! contract").
//!
//! Input numbers are JSON integers or strings in the exact number syntax (integers, fractions,
//! decimals meaning their exact value, `sqrt(k)`, `+ - * /`, parentheses); JSON floating-point
//! literals are refused in exact mode. Output numbers are strings in the same syntax, with `approx`
//! f64 twins.

use crate::Error;
use exactcheck_core::sphere_interpolation::interpolate;
use exactcheck_core::{Hom4, OrderedField, Vec3};
use exactcheck_exact::radical::Radical;
use exactcheck_exact::Rational;
use serde_json::{json, Map, Value};
use std::fmt::Display;

/// How numbers are read and computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Exact arithmetic; JSON floating literals are refused.
    Exact,
    /// f64 arithmetic; JSON floating literals are accepted.
    Float,
    /// Both, side by side.
    Both,
}

/// The kinds of DESIGN.md, with the ones this version answers.
const KINDS: [(&str, bool); 7] = [
    ("sphere_interpolation", true),
    ("ruled_plane", false),
    ("ruled_line", false),
    ("plane_plane", false),
    ("cylinder_sphere", true),
    ("conic", false),
    ("ph_offset", false),
];

/// Reads a problem from a file (`-` or none: standard input).
///
/// # Errors
/// [`Error::Io`] when the file cannot be read.
pub fn read_problem(path: Option<&str>) -> Result<String, Error> {
    use std::io::Read;
    match path {
        None | Some("-") => {
            let mut s = String::new();
            std::io::stdin()
                .read_to_string(&mut s)
                .map_err(|source| Error::Io {
                    path: "-".into(),
                    source,
                })?;
            Ok(s)
        }
        Some(p) => std::fs::read_to_string(p).map_err(|source| Error::Io {
            path: p.into(),
            source,
        }),
    }
}

/// Solves one problem given as JSON text.
///
/// # Errors
/// [`Error::Input`] naming the field for malformed JSON, an unknown kind, wrong arity, bad
/// numbers, division by zero or degenerate geometry.
pub fn solve(text: &str, mode: Mode) -> Result<Value, Error> {
    let v: Value =
        serde_json::from_str(text).map_err(|e| Error::Input(format!("malformed JSON: {e}")))?;
    let obj = v
        .as_object()
        .ok_or_else(|| Error::Input("the problem must be a JSON object".into()))?;
    let kind = obj
        .get("kind")
        .ok_or_else(|| Error::Input("missing field \"kind\"".into()))?
        .as_str()
        .ok_or_else(|| Error::Input("\"kind\" must be a string".into()))?;
    match KINDS.iter().find(|(k, _)| *k == kind) {
        None => {
            let known: Vec<&str> = KINDS.iter().map(|(k, _)| *k).collect();
            Err(Error::Input(format!(
                "unknown kind {kind:?} (kinds: {})",
                known.join(", ")
            )))
        }
        Some((_, false)) => Err(Error::Input(format!(
            "kind {kind:?} is not answered by this version yet (answered: {})",
            KINDS
                .iter()
                .filter(|k| k.1)
                .map(|k| k.0)
                .collect::<Vec<_>>()
                .join(", ")
        ))),
        Some(_) => match kind {
            "sphere_interpolation" => sphere_interpolation(obj, mode),
            "cylinder_sphere" => crate::solve_cs::cylinder_sphere(obj, mode),
            _ => unreachable!("every answered kind is dispatched"),
        },
    }
}

/// An exact number of the problem: a JSON integer or a string in the number syntax.
pub(crate) fn exact_number(v: &Value, field: &str) -> Result<Radical, Error> {
    match v {
        Value::Number(n) if n.is_i64() => Ok(Radical::from(n.as_i64().unwrap_or_default())),
        Value::Number(n) if n.is_u64() => n
            .to_string()
            .parse::<Radical>()
            .map_err(|e| Error::Input(format!("{field}: {e}"))),
        Value::Number(n) => Err(Error::Input(format!(
            "{field}: {n} is a JSON floating-point literal, which is not exact; write it as a string (\"{n}\" means exactly that decimal) or use --float"
        ))),
        Value::String(s) => s.parse::<Radical>().map_err(|e| Error::Input(format!("{field}: {e}"))),
        other => Err(Error::Input(format!("{field}: expected a number, found {other}"))),
    }
}

pub(crate) fn array<'a>(obj: &'a Map<String, Value>, field: &str) -> Result<&'a Vec<Value>, Error> {
    obj.get(field)
        .ok_or_else(|| Error::Input(format!("missing field {field:?}")))?
        .as_array()
        .ok_or_else(|| Error::Input(format!("{field:?} must be an array")))
}

pub(crate) fn vec3(v: &Value, field: &str) -> Result<Vec3<Radical>, Error> {
    let a = v
        .as_array()
        .ok_or_else(|| Error::Input(format!("{field}: expected an array of 3 numbers")))?;
    if a.len() != 3 {
        return Err(Error::Input(format!(
            "{field}: expected 3 coordinates, found {}",
            a.len()
        )));
    }
    Ok(Vec3::new(
        exact_number(&a[0], &format!("{field}[0]"))?,
        exact_number(&a[1], &format!("{field}[1]"))?,
        exact_number(&a[2], &format!("{field}[2]"))?,
    ))
}

/// The output form of an exact number: the string (round-trips as input).
pub(crate) fn out<T: Display>(x: &T) -> Value {
    Value::String(x.to_string())
}

/// An exact scalar the answers can be printed from.
trait Printable: OrderedField + Display {
    fn approx(&self) -> f64;
}

impl Printable for Rational {
    fn approx(&self) -> f64 {
        self.to_f64() + 0.0
    }
}

impl Printable for Radical {
    fn approx(&self) -> f64 {
        self.to_f64() + 0.0
    }
}

fn sphere_interpolation(obj: &Map<String, Value>, mode: Mode) -> Result<Value, Error> {
    if mode != Mode::Exact {
        return Err(Error::Input(
            "sphere_interpolation is an exact linear problem: --float and --both are not available for it".into(),
        ));
    }
    let pts = array(obj, "points")?;
    let prm = array(obj, "params")?;
    let points: Vec<Vec3<Radical>> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| vec3(p, &format!("points[{i}]")))
        .collect::<Result<_, _>>()?;
    let params: Vec<Radical> = prm
        .iter()
        .enumerate()
        .map(|(i, t)| exact_number(t, &format!("params[{i}]")))
        .collect::<Result<_, _>>()?;
    // Rational input runs over the (faster) rationals; radicals over the radical field.
    let rational = points
        .iter()
        .all(|p| p.x.is_rational() && p.y.is_rational() && p.z.is_rational())
        && params.iter().all(Radical::is_rational);
    if rational {
        let r = |x: &Radical| x.to_rational().unwrap_or_default();
        let points: Vec<Vec3<Rational>> = points.iter().map(|p| p.map(r)).collect();
        let params: Vec<Rational> = params.iter().map(r).collect();
        interpolation_answer(&points, &params)
    } else {
        interpolation_answer(&points, &params)
    }
}

fn interpolation_answer<T: Printable>(points: &[Vec3<T>], params: &[T]) -> Result<Value, Error> {
    let hom: Vec<Hom4<T>> = points.iter().map(Hom4::from_point).collect();
    let r = interpolate(&hom, params).map_err(|e| Error::Input(e.to_string()))?;
    let weights = r.curve.weights();
    let pts = r.curve.points();
    let point_json = |p: &Option<Vec3<T>>, f: fn(&T) -> Value| match p {
        Some(p) => Value::Array(vec![f(&p.x), f(&p.y), f(&p.z)]),
        None => Value::Null,
    };
    // The exact check the answer promises: at each parameter the curve is the given point.
    let passes = hom
        .iter()
        .zip(params)
        .all(|(k, t)| r.curve.eval_hom(t).proj_eq(k));
    Ok(json!({
        "kind": "sphere_interpolation",
        "mode": "exact",
        "degree": r.degree,
        "weights": weights.iter().map(out).collect::<Vec<_>>(),
        "points": pts.iter().map(|p| point_json(p, |x| out(x))).collect::<Vec<_>>(),
        "preimage_degree": r.degree / 2,
        "sigma_degree": r.sigma_degree,
        "passes_through_all_points": passes,
        "approx": {
            "weights": weights.iter().map(|w| json!(w.approx())).collect::<Vec<_>>(),
            "points": pts.iter().map(|p| point_json(p, |x| json!(x.approx()))).collect::<Vec<_>>(),
        },
    }))
}
