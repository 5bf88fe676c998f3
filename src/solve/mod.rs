//! `exactcheck solve [FILE|-]`: one problem in JSON, the answer in JSON (the
//! contract described in docs/solve.md).
//!
//! The contract is a set of types: each kind has an input struct read with serde derive
//! (`deny_unknown_fields`, so a misspelt or extra field is an error naming it; a repeated field
//! is an error too), numbers read exactly by the deserializers of [`number`], and an answer
//! struct serialized as the JSON output. `serde_path_to_error` prefixes every error with the
//! field path (`cylinder.beta.cos: ...`). A UTF-8 byte-order mark at the start is skipped. The
//! JSON Schema of each kind's input is generated from the same types ([`schema`]) and committed
//! as `docs/schema/<kind>.json` (a test keeps the files current).
//!
//! Adding a kind is one file: a module with an input type, an answer type and an
//! implementation of [`Kind`], plus its line in [`kinds`].

pub mod conic;
pub mod cylinder_sphere;
pub mod depth;
pub mod finite;
pub mod number;
pub mod ph_offset;
pub mod plane_plane;
pub mod ruled_line;
pub mod ruled_plane;
pub mod sphere_interpolation;

use crate::Error;
use schemars::JsonSchema;
use serde::de::{Deserialize, DeserializeOwned};
use serde::Serialize;
use serde_json::Value;

/// The refusal of f64 computation whose numbers leave f64's range (squares that vanish or
/// overflow), after the field or command it concerns.
pub(crate) const F64_OUT_OF_RANGE: &str = "f64 underflows/overflows here; use exact mode";

/// How numbers are read and computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Exact arithmetic; JSON floating literals are refused.
    Exact,
    /// f64 arithmetic; JSON floating literals are accepted, non-finite values refused.
    Float,
    /// Both, side by side.
    Both,
}

/// One kind of problem: its name, its input type (whose schema is published) and its solver.
pub trait Kind {
    /// The value of the problem's `"kind"` field.
    const NAME: &'static str;
    /// The input as exact mode reads it; its JSON Schema is `docs/schema/<NAME>.json`.
    type Input: DeserializeOwned + JsonSchema;
    /// Reads the problem text (the kind is already checked) and answers it.
    ///
    /// # Errors
    /// [`Error::Input`] naming the field for bad input or degenerate geometry.
    fn answer(text: &str, mode: Mode) -> Result<Value, Error>;
}

/// [`Kind::answer`] for a kind with an exact and a float solver: the exact answer, the float
/// one, or (`--both`) the exact answer with the float one attached by `attach`.
///
/// # Errors
/// What the solvers return.
pub(crate) fn by_mode<E: Serialize, F: Serialize>(
    text: &str,
    mode: Mode,
    exact: fn(&str) -> Result<E, Error>,
    float: fn(&str) -> Result<F, Error>,
    attach: fn(&mut E, F),
) -> Result<Value, Error> {
    match mode {
        Mode::Exact => to_json(&exact(text)?, mode),
        Mode::Float => to_json(&float(text)?, mode),
        Mode::Both => {
            let mut answer = exact(text)?;
            attach(&mut answer, float(text)?);
            to_json(&answer, mode)
        }
    }
}

/// A kind of `solve` and how it is answered.
#[derive(Clone, Copy)]
pub struct KindEntry {
    /// The kind's name.
    pub name: &'static str,
    solver: Solver,
}

#[derive(Clone, Copy)]
struct Solver {
    answer: fn(&str, Mode) -> Result<Value, Error>,
    schema: fn() -> schemars::Schema,
}

fn schema_of<T: JsonSchema>() -> schemars::Schema {
    schemars::schema_for!(T)
}

fn answered<K: Kind>() -> KindEntry {
    KindEntry {
        name: K::NAME,
        solver: Solver {
            answer: K::answer,
            schema: schema_of::<K::Input>,
        },
    }
}

/// The kinds of `solve`, in their fixed order (every one is answered).
pub fn kinds() -> [KindEntry; 7] {
    [
        answered::<sphere_interpolation::SphereInterpolation>(),
        answered::<ruled_plane::RuledPlane>(),
        answered::<ruled_line::RuledLine>(),
        answered::<plane_plane::PlanePlaneKind>(),
        answered::<cylinder_sphere::CylinderSphereKind>(),
        answered::<conic::ConicKind>(),
        answered::<ph_offset::PhOffset>(),
    ]
}

fn find_kind(kind: &str) -> Result<Solver, Error> {
    let all = kinds();
    match all.iter().find(|k| k.name == kind) {
        None => Err(Error::Input(format!(
            "unknown kind {kind:?} (kinds: {})",
            all.iter().map(|k| k.name).collect::<Vec<_>>().join(", ")
        ))),
        Some(k) => Ok(k.solver),
    }
}

/// Reads an input file (`-` or none: standard input) as UTF-8 text, at most the `file-size`
/// limit of bytes: the one reader of every command's input files.
///
/// # Errors
/// [`Error::Io`] when the file cannot be read or is not UTF-8; [`Error::Limit`] when it is
/// larger than the `file-size` limit (read no further than the limit).
pub fn read_problem(path: Option<&str>) -> Result<String, Error> {
    use std::io::Read;
    let limit = &exactcheck_core::limits::FILE_SIZE;
    let shown = path.unwrap_or("-");
    let io = |source| Error::Io {
        path: shown.into(),
        source,
    };
    let reader: Box<dyn Read> = match path {
        None | Some("-") => Box::new(std::io::stdin()),
        Some(p) => Box::new(std::fs::File::open(p).map_err(io)?),
    };
    let mut bytes = Vec::new();
    reader
        .take(limit.get().saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > limit.get() {
        return Err(Error::Limit(
            limit.exceeded(format!("{shown}: more than {} bytes", limit.get())),
        ));
    }
    String::from_utf8(bytes).map_err(|e| {
        io(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "not UTF-8 (invalid byte at offset {})",
                e.utf8_error().valid_up_to()
            ),
        ))
    })
}

/// The text without a leading UTF-8 byte-order mark.
fn without_bom(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}

/// The problem's `"kind"`.
///
/// # Errors
/// [`Error::Input`] for malformed JSON, a non-object, a missing or non-string kind;
/// [`Error::Limit`] of `depth` for arrays and objects nested deeper than the limit.
pub fn problem_kind(text: &str) -> Result<String, Error> {
    let text = without_bom(text);
    let v: Value = depth::parse_json(text)
        .map_err(|(_, e)| Error::Limit(e))?
        .map_err(|e| Error::Input(format!("malformed JSON: {e}")))?;
    let obj = v
        .as_object()
        .ok_or_else(|| Error::Input("the problem must be a JSON object".into()))?;
    Ok(obj
        .get("kind")
        .ok_or_else(|| Error::Input("missing field \"kind\"".into()))?
        .as_str()
        .ok_or_else(|| Error::Input("\"kind\" must be a string".into()))?
        .to_string())
}

/// The `radicands` limit on all the exact numbers of a problem together: each may be within
/// it while the field the answer is computed in (spanned by all of them) is not. Strings that do
/// not parse are left to the kind's reader, which names their field.
///
/// # Errors
/// [`Error::Limit`] of `radicands`.
fn check_radicands_together(text: &str) -> Result<(), Error> {
    fn strings<'a>(v: &'a Value, out: &mut Vec<&'a str>) {
        match v {
            Value::String(s) => out.push(s),
            Value::Array(items) => items.iter().for_each(|x| strings(x, out)),
            Value::Object(map) => map.values().for_each(|x| strings(x, out)),
            _ => {}
        }
    }
    let mut de = serde_json::Deserializer::from_str(without_bom(text));
    // The depth was bounded by `problem_kind`'s scan.
    de.disable_recursion_limit();
    let Ok(v) = Value::deserialize(&mut de) else {
        return Ok(());
    };
    let mut texts = Vec::new();
    strings(&v, &mut texts);
    let values: Vec<exactcheck_exact::Radical> = texts
        .iter()
        .filter_map(|s| number::parse_radical(s).ok())
        .collect();
    exactcheck_exact::Radical::check_radicands_together(&values).map_err(Error::Limit)
}

/// Reads a problem into its input type; every error is one line naming the field path.
///
/// # Errors
/// [`Error::Limit`] of `depth` for arrays and objects nested deeper than the limit.
/// [`Error::Input`]: `malformed JSON: ...` for syntax errors, `PATH: ...` for everything the
/// types refuse (unknown or repeated fields, wrong types, bad numbers).
pub fn parse<T: DeserializeOwned>(text: &str) -> Result<T, Error> {
    let text = without_bom(text);
    depth::check_json(text).map_err(|(_, e)| Error::Limit(e))?;
    let mut de = serde_json::Deserializer::from_str(text);
    // The depth was bounded by the scan above (module `depth`).
    de.disable_recursion_limit();
    let value: T = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        if inner.is_syntax() || inner.is_eof() {
            Error::Input(format!("malformed JSON: {inner}"))
        } else if path == "." {
            Error::Input(inner.to_string())
        } else {
            Error::Input(format!("{path}: {inner}"))
        }
    })?;
    de.end()
        .map_err(|e| Error::Input(format!("malformed JSON: {e}")))?;
    Ok(value)
}

/// A serialized answer as a JSON value: the one place answers are serialized, after the check
/// that every `f64` in it is finite ([`finite`]; JSON has no NaN or infinity, and `serde_json`
/// would write `null`). With `mode` [`Mode::Exact`] or [`Mode::Both`], an infinite `approx` twin
/// of an exact value (beyond f64's range) is kept as `null` and its path listed in the answer's
/// `approx_out_of_range`; every other non-finite number is an error.
///
/// # Errors
/// [`Error::Input`] naming the field of the first non-finite number that is refused.
pub(crate) fn to_json<T: Serialize>(answer: &T, mode: Mode) -> Result<Value, Error> {
    let approx = match mode {
        Mode::Float => finite::Approx::Refused,
        Mode::Exact | Mode::Both => finite::Approx::Listed,
    };
    let out_of_range = finite::check(answer, approx).map_err(|e| Error::Input(e.to_string()))?;
    let mut value = serde_json::to_value(answer)
        .expect("answers hold only strings, finite numbers, infinite approximations (null), booleans and arrays");
    if !out_of_range.is_empty() {
        match value.as_object_mut() {
            Some(object) => {
                object.insert("approx_out_of_range".into(), out_of_range.into());
            }
            None => {
                return Err(Error::Input(format!(
                    "{}: the f64 approximation of an exact value is out of f64's range",
                    out_of_range[0]
                )))
            }
        }
    }
    Ok(value)
}

/// Solves one problem given as JSON text.
///
/// # Errors
/// [`Error::Input`] naming the field for malformed JSON, an unknown kind, wrong arity, bad
/// numbers, division by zero or degenerate geometry.
pub fn solve(text: &str, mode: Mode) -> Result<Value, Error> {
    let kind = problem_kind(text)?;
    check_radicands_together(text)?;
    let solver = find_kind(&kind)?;
    (solver.answer)(without_bom(text), mode)
}

/// The JSON Schema of a kind's input, pretty-printed with a final newline (the content of
/// `docs/schema/<kind>.json`).
///
/// # Errors
/// [`Error::Usage`] for an unknown kind.
pub fn schema(kind: &str) -> Result<String, Error> {
    let solver = find_kind(kind).map_err(|e| Error::Usage(e.to_string()))?;
    let text = serde_json::to_string_pretty(&(solver.schema)()).expect("a schema is plain JSON");
    Ok(text + "\n")
}

/// An exact scalar the answers can be printed from.
pub(crate) trait Printable: exactcheck_core::OrderedField + std::fmt::Display {
    /// The nearest f64, with `-0` printed as `0`.
    fn approx(&self) -> f64;
}

impl Printable for exactcheck_exact::Rational {
    fn approx(&self) -> f64 {
        self.to_f64() + 0.0
    }
}

impl Printable for exactcheck_exact::Radical {
    fn approx(&self) -> f64 {
        self.to_f64() + 0.0
    }
}
