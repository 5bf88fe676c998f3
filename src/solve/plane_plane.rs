//! `solve` kind `plane_plane`: the intersection line of two planes given in
//! normal form `{normal, point}`.
//!
//! Exact mode reads the numbers into the radical field (so `"sqrt(2)/2"` is exact), or into the
//! problem's number field when a value leaves it (`"cos(pi/8)"`), and runs the
//! construction of `exactcheck_core::planes`, which needs no unit normals: the outcome (`line`,
//! `parallel`, `coincident`) is decided by exact zero tests, the point is the one nearest the
//! origin, `Q = [(d1|n2|^2 - d2 n1.n2) n1 + (d2|n1|^2 - d1 n1.n2) n2] / |n1 x n2|^2`, and the
//! direction is `n1 x n2`. The unit direction `(n1 x n2)/sqrt(k)`, `k = |n1 x n2|^2`, is given
//! exactly when `sqrt(k)` lies in the radical field (always for rational `k` whose factoring
//! succeeds), otherwise as the exact expression `c/sqrt(k)` of each coordinate, flagged by
//! `unit_direction_in_field: false`. The answer reports the exact checks that the point lies on
//! both planes and that it is the point nearest the origin (`Q . direction = 0`).
//!
//! `--float` runs the **published JavaScript** (`exactcheck_float::wabis`, the code under test),
//! after normalising the normals in f64 as the function requires; it returns a unit direction
//! oriented `n2 x n1` as published, and `null` (outcome `parallel`) for parallel *and* coincident
//! planes, which it does not tell apart. `--both` gives the exact answer with the float one
//! under `float`.
//!
//! A zero normal is an input error naming the field (`planes[1].normal: zero vector`).

use super::number::{Coords, ExactNumber, FieldNumber, FloatNumber};
use super::scalar::Scalar;
use super::{finite, FloatKind, Kind, Problem};
use crate::Error;
use exactcheck_core::planes::{intersect, Plane, PlanePair};
use exactcheck_core::{Ring, Sign, Sqrt, Vec3};
use exactcheck_float::wabis::{interction_line_of_2_areas, length, scale, V3};
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::de::{Deserializer, Error as _};
use serde::{Deserialize, Serialize};
use std::borrow::Cow;

// ------------------------------------------------------------------ input

/// The problem, with numbers of type `N` ([`ExactNumber`] in exact mode, [`FloatNumber`] with
/// `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "plane_plane",
    description = "Two planes in normal form {normal, point}: how they meet (line, parallel, coincident), the point of the line nearest the origin, the direction n1 x n2 and the unit direction. Normals need not be unit vectors. Exact mode reads exact numbers (radicals allowed); --float runs the published JavaScript InterctionLineOf2Areas ported to f64."
)]
pub struct Input<N> {
    /// `"plane_plane"`.
    #[schemars(extend("const" = "plane_plane"))]
    pub kind: String,
    /// Exactly two planes.
    pub planes: Pair<PlaneInput<N>>,
}

/// A plane `normal . x = normal . point`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PlaneInput<N> {
    /// A non-zero normal vector (any length).
    pub normal: Coords<N, 3>,
    /// A point of the plane.
    pub point: Coords<N, 3>,
}

/// Exactly two values: a JSON array whose wrong length is reported as
/// "expected 2 planes, found M".
#[derive(Debug)]
pub struct Pair<T>(pub [T; 2]);

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Pair<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Vec::<T>::deserialize(d)?;
        let found = v.len();
        <[T; 2]>::try_from(v)
            .map(Pair)
            .map_err(|_| D::Error::custom(format!("expected 2 planes, found {found}")))
    }
}

impl<T: JsonSchema> JsonSchema for Pair<T> {
    fn schema_name() -> Cow<'static, str> {
        format!("Pair_{}", T::schema_name()).into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let item = generator.subschema_for::<T>();
        json_schema!({
            "type": "array",
            "items": item,
            "minItems": 2,
            "maxItems": 2
        })
    }
}

/// The two planes with numbers mapped by `num`; a zero normal is an error naming the field.
fn planes<N, T: Ring>(input: &Input<N>, num: impl Fn(&N) -> T) -> Result<[Plane<T>; 2], Error> {
    let v = |c: &Coords<N, 3>| Vec3::new(num(&c.0[0]), num(&c.0[1]), num(&c.0[2]));
    let mut out = Vec::with_capacity(2);
    for (i, p) in input.planes.0.iter().enumerate() {
        let plane = Plane::through(v(&p.normal), &v(&p.point));
        if plane.normal.is_zero() {
            return Err(Error::Input(format!("planes[{i}].normal: zero vector")));
        }
        out.push(plane);
    }
    Ok(out
        .try_into()
        .expect("Pair holds exactly two planes, each pushed or returned as an error"))
}

// ------------------------------------------------------------------ answers

/// The exact answer.
#[derive(Debug, Serialize)]
pub(crate) struct ExactAnswer {
    kind: &'static str,
    mode: &'static str,
    /// `line`, `parallel` or `coincident`.
    outcome: &'static str,
    /// The point of the line nearest the origin (`null` without a line).
    point: Option<[String; 3]>,
    /// `n1 x n2`.
    direction: Option<[String; 3]>,
    /// `direction / |direction|`: radicals, or expressions `c/sqrt(k)` (see
    /// `unit_direction_in_field`).
    unit_direction: Option<[String; 3]>,
    /// Whether `unit_direction` is given as numbers of the field the problem is computed in
    /// (the radical field, or the problem's number field).
    unit_direction_in_field: Option<bool>,
    /// Exact check: the point satisfies both plane equations.
    on_both_planes: Option<bool>,
    /// Exact check: `point . direction = 0`, so the point is the one nearest the origin.
    nearest_to_origin: Option<bool>,
    approx: Option<Approx>,
    /// `--both`: the float answer, or why the float computation gave none.
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<FloatPart>,
    /// `--both`: whether the float outcome is the exact one (`parallel` counts for
    /// `coincident`, which the published function does not tell apart); absent when the float
    /// computation failed.
    #[serde(skip_serializing_if = "Option::is_none")]
    float_agrees: Option<bool>,
    /// `--both`: the disagreement, or the float failure, in words.
    #[serde(skip_serializing_if = "Option::is_none")]
    float_note: Option<String>,
}

/// The float part of `--both`: an answer, or the failure of the float computation (input f64
/// cannot hold, a non-finite result), which does not take the exact answer with it.
#[derive(Debug, Serialize)]
#[serde(untagged)]
enum FloatPart {
    Answer(FloatAnswer),
    Failed {
        mode: &'static str,
        method: &'static str,
        error: String,
    },
}

#[derive(Debug, Serialize)]
struct Approx {
    point: [f64; 3],
    direction: [f64; 3],
    unit_direction: [f64; 3],
}

/// The answer of the published JavaScript.
#[derive(Debug, Serialize)]
pub(crate) struct FloatAnswer {
    kind: &'static str,
    mode: &'static str,
    /// What was run.
    method: &'static str,
    /// `line`, or `parallel` when the function returned `null` (also for coincident planes).
    outcome: &'static str,
    /// The published `Q`.
    point: Option<[f64; 3]>,
    /// The published `q`: `n2 x n1` normalised.
    unit_direction: Option<[f64; 3]>,
}

const FLOAT_METHOD: &str = "the published JavaScript InterctionLineOf2Areas ported to f64 operation for operation (exactcheck_float::wabis), after normalising each normal in f64 (V3.Scale(n, 1/V3.Length(n))) as it requires; q is n2 x n1 normalised; null (parallel or coincident planes) is outcome parallel";

fn strings<T: Scalar>(v: &Vec3<T>) -> [String; 3] {
    [v.x.to_string(), v.y.to_string(), v.z.to_string()]
}

fn approx<T: Scalar>(v: &Vec3<T>) -> [f64; 3] {
    [v.x.approx(), v.y.approx(), v.z.approx()]
}

/// The exact answer, in the radical field or in the problem's number field.
fn exact<N, T: Scalar + Sqrt>(
    input: Input<N>,
    num: impl Fn(&N) -> T,
) -> Result<ExactAnswer, Error> {
    let [p1, p2] = planes(&input, num)?;
    let none = |outcome| ExactAnswer {
        kind: "plane_plane",
        mode: "exact",
        outcome,
        point: None,
        direction: None,
        unit_direction: None,
        unit_direction_in_field: None,
        on_both_planes: None,
        nearest_to_origin: None,
        approx: None,
        float: None,
        float_agrees: None,
        float_note: None,
    };
    match intersect(&p1, &p2) {
        PlanePair::Parallel => Ok(none("parallel")),
        PlanePair::Coincident => Ok(none("coincident")),
        PlanePair::ZeroNormal { which } => Err(Error::Input(format!(
            "planes[{}].normal: zero vector",
            which.index()
        ))),
        PlanePair::Line { point, direction } => {
            let k = direction.norm_squared();
            // The unit direction's twins come from exact values, not `direction / |direction|`
            // in f64 (which is `inf / inf` once `|direction|` is beyond f64's range): the exact
            // unit vector when it is in the field, else `sign(c) sqrt(c^2 / k)`, `c^2 / k <= 1`.
            let (unit, in_field, unit_f) = match k.sqrt() {
                Some(root) => {
                    let u = direction
                        .div_scalar(&root)
                        .expect("sqrt(|q|^2) != 0 for the non-zero direction of a line");
                    (strings(&u), true, approx(&u))
                }
                None => (
                    direction
                        .map(|c| {
                            if c.is_zero() {
                                "0".to_string()
                            } else {
                                format!("{}/sqrt({k})", numerator(&c.to_string()))
                            }
                        })
                        .into_array(),
                    false,
                    direction
                        .map(|c| {
                            let magnitude = c
                                .square()
                                .checked_div(&k)
                                .expect("|q|^2 != 0 for the non-zero direction of a line")
                                .approx()
                                .sqrt();
                            if c.sign() == Sign::Negative {
                                -magnitude
                            } else {
                                magnitude + 0.0
                            }
                        })
                        .into_array(),
                ),
            };
            Ok(ExactAnswer {
                point: Some(strings(&point)),
                direction: Some(strings(&direction)),
                unit_direction: Some(unit),
                unit_direction_in_field: Some(in_field),
                on_both_planes: Some(p1.value(&point).is_zero() && p2.value(&point).is_zero()),
                nearest_to_origin: Some(point.dot(&direction).is_zero()),
                approx: Some(Approx {
                    point: approx(&point),
                    direction: approx(&direction),
                    unit_direction: unit_f,
                }),
                ..none("line")
            })
        }
    }
}

/// The normal normalised the JavaScript way, `V3.Scale(n, 1/V3.Length(n))`; an error naming the
/// field when its f64 length is 0 or not finite (`|n|^2` underflows or overflows), where the
/// normalised vector would be NaN or zero.
fn unit_f64(n: &Vec3<f64>, i: usize) -> Result<V3, Error> {
    let v = [n.x, n.y, n.z];
    let l = length(&v);
    if !(l.is_finite() && l > 0.0) {
        return Err(Error::Input(format!(
            "planes[{i}].normal: its f64 length is {l}, so it cannot be normalised in f64 as the published function requires; use exact mode"
        )));
    }
    Ok(scale(&v, 1.0 / l))
}

fn float_answer(input: Input<FloatNumber>) -> Result<FloatAnswer, Error> {
    let [p1, p2] = planes(&input, |x| x.0)?;
    let (n1, n2) = (unit_f64(&p1.normal, 0)?, unit_f64(&p2.normal, 1)?);
    // The published function takes each plane's point as given.
    let pt = |i: usize| input.planes.0[i].point.0.each_ref().map(|x| x.0);
    let result = interction_line_of_2_areas(&pt(0), &n1, &pt(1), &n2);
    Ok(FloatAnswer {
        kind: "plane_plane",
        mode: "float",
        method: FLOAT_METHOD,
        outcome: if result.is_some() { "line" } else { "parallel" },
        point: result.map(|(q, _)| q.map(|c| c + 0.0)),
        unit_direction: result.map(|(_, q)| q.map(|c| c + 0.0)),
    })
}

/// The kind.
pub struct PlanePlaneKind;

impl Kind for PlanePlaneKind {
    const NAME: &'static str = "plane_plane";
    type Input = Input<ExactNumber>;
    type Answer = ExactAnswer;

    fn compute(input: Self::Input) -> Result<ExactAnswer, Error> {
        exact(input, |x: &ExactNumber| x.0.clone())
    }

    fn compute_in_field(problem: &Problem) -> Result<ExactAnswer, Error> {
        let input: Input<FieldNumber> = problem.input_in_field(&[])?;
        exact(input, |x: &FieldNumber| x.0.clone())
    }
}

impl FloatKind for PlanePlaneKind {
    type FloatInput = Input<FloatNumber>;
    type FloatAnswer = FloatAnswer;

    fn compute_float(input: Self::FloatInput) -> Result<FloatAnswer, Error> {
        float_answer(input)
    }
}

/// `--both`: the float answer and whether its outcome agrees, or the float computation's
/// failure as a note (it does not take the exact answer with it). Near-parallel rounding
/// makes the published function return a finite `line` for some exactly parallel or
/// coincident planes, and NaN for others (`1 - r^2 = 0` with `n2 x n1` not rounded to
/// zero).
impl super::Attach<FloatAnswer> for ExactAnswer {
    fn attach(&mut self, float: Result<FloatAnswer, Error>) -> Result<(), Error> {
        let answer = self;
        let float = float.and_then(|f| {
            finite::check(&f, finite::Approx::Refused)
                .map(|_| f)
                .map_err(|e| Error::Input(e.to_string()))
        });
        match float {
            Ok(f) => {
                let agrees = matches!(
                    (answer.outcome, f.outcome),
                    ("line", "line") | ("parallel" | "coincident", "parallel")
                );
                if !agrees {
                    answer.float_note = Some(format!(
                        "disagreement: the planes are exactly {}, the f64 computation says {}{}",
                        if answer.outcome == "line" {
                            "not parallel (they meet in a line)"
                        } else {
                            answer.outcome
                        },
                        f.outcome,
                        if f.outcome == "line" {
                            " (rounding left n2 x n1 non-zero)"
                        } else {
                            " (n2 x n1 rounded to zero)"
                        }
                    ));
                }
                answer.float_agrees = Some(agrees);
                answer.float = Some(FloatPart::Answer(f));
            }
            Err(Error::Input(e)) => {
                answer.float_note = Some(format!("the f64 computation gave no answer: {e}"));
                answer.float = Some(FloatPart::Failed {
                    mode: "float",
                    method: FLOAT_METHOD,
                    error: e,
                });
            }
            Err(e) => return Err(e),
        }
        Ok(())
    }
}

/// The printed number `text` as the numerator of `text/sqrt(k)`: as it is when the quotient
/// reads back as the same value and plainly so (a number, `-2`, `-cos(2*pi/7)`, a product),
/// in parentheses when it is a sum or a difference, or has a division of its own, at its top
/// level (`(-1 - sqrt(2))`, `(-1/2)`). The printers write binary `+` and `-` with a space on
/// each side and a leading minus without one.
fn numerator(text: &str) -> String {
    let mut depth = 0usize;
    let mut prev = ' ';
    let mut compound = false;
    for (i, ch) in text.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            '/' if depth == 0 => compound = true,
            '+' | '-' if depth == 0 && i > 0 && prev == ' ' => compound = true,
            _ => {}
        }
        prev = ch;
    }
    if compound {
        format!("({text})")
    } else {
        text.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact(text: &str) -> Result<ExactAnswer, Error> {
        super::exact(crate::solve::parse(text)?, |x: &ExactNumber| x.0.clone())
    }

    #[test]
    fn a_numerator_is_parenthesized_only_when_the_quotient_would_read_otherwise() {
        for (text, want) in [
            ("-2", "-2"),
            ("1", "1"),
            ("-cos(2*pi/7)", "-cos(2*pi/7)"),
            ("3*sqrt(2)", "3*sqrt(2)"),
            ("sqrt(2 - sqrt(2))", "sqrt(2 - sqrt(2))"),
            ("cos(pi/8)^2", "cos(pi/8)^2"),
            ("-1 - sqrt(2)", "(-1 - sqrt(2))"),
            ("6 - 7*cos(pi/8)", "(6 - 7*cos(pi/8))"),
            ("1 + sqrt(5)", "(1 + sqrt(5))"),
            ("-1/2", "(-1/2)"),
            ("sqrt(3)/3", "(sqrt(3)/3)"),
        ] {
            assert_eq!(numerator(text), want, "{text}");
            // The quotient reads back as the same value as the parenthesized one.
            let plain: exactcheck_exact::Algebraic = format!("{}/sqrt(7)", numerator(text))
                .parse()
                .unwrap_or_else(|e| panic!("{text}: {e}"));
            let safe: exactcheck_exact::Algebraic = format!("({text})/sqrt(7)").parse().unwrap();
            assert_eq!(plain, safe, "{text}");
        }
    }

    #[test]
    fn radical_unit_direction_and_expression_fallback() {
        // x = 0 and y = 0 with the normals (1, 0, 0), (1, 1, 0): direction (0, 0, 1).
        let a = exact(r#"{"kind":"plane_plane","planes":[{"normal":[1,0,0],"point":[0,0,0]},{"normal":[1,1,0],"point":[0,0,0]}]}"#).unwrap();
        assert_eq!(a.unit_direction, Some(["0".into(), "0".into(), "1".into()]));
        // Direction (1, 1, 1) has norm sqrt(3): exact in the field.
        let b = exact(r#"{"kind":"plane_plane","planes":[{"normal":[1,-1,0],"point":[1,0,0]},{"normal":[0,1,-1],"point":[0,0,2]}]}"#).unwrap();
        assert_eq!(b.unit_direction_in_field, Some(true));
        assert_eq!(b.unit_direction.unwrap()[0], "sqrt(3)/3");
        assert_eq!(b.on_both_planes, Some(true));
        assert_eq!(b.nearest_to_origin, Some(true));
        // n1 = (1, 0, 0), n2 = (0, 1, 1 + sqrt(2)): k = 1 + (1 + sqrt(2))^2 = 4 + 2 sqrt(2), whose
        // square root is not multi-quadratic (its norm 16 - 8 = 8 is not a square).
        let c = exact(r#"{"kind":"plane_plane","planes":[{"normal":[1,0,0],"point":[0,0,0]},{"normal":[0,1,"1+sqrt(2)"],"point":[0,0,0]}]}"#).unwrap();
        assert_eq!(c.unit_direction_in_field, Some(false));
        let u = c.unit_direction.unwrap();
        assert_eq!(
            u,
            [
                "0".to_string(),
                "(-1 - sqrt(2))/sqrt(4 + 2*sqrt(2))".into(),
                "1/sqrt(4 + 2*sqrt(2))".into()
            ]
        );
        let ap = c.approx.unwrap();
        let n: f64 = ap.unit_direction.iter().map(|x| x * x).sum();
        assert!((n - 1.0).abs() < 1e-12, "{ap:?}");
    }
}
