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
//! One driver answers every kind ([`solve`]): the problem's envelope is read once
//! ([`input::Problem`]), the kind is looked up in the registry ([`kinds`]), the typed input is
//! read and computed by the kind, and the answer serialized by `to_json`. The kinds compute
//! generically in the scalars of `scalar`.
//!
//! Adding a kind is a module with an input type, a compute and an answer type (an
//! implementation of `Kind`, and of `FloatKind` for `--float`), plus its line in
//! [`kinds`]; the schema, golden and malformed-corpus tests then require its schema file, a
//! golden answer and a malformed case.

pub mod conic;
pub mod cylinder_sphere;
pub mod depth;
pub(crate) mod field;
pub mod finite;
pub mod input;
pub mod number;
pub mod ph_offset;
pub mod plane_plane;
pub mod ruled_line;
pub mod ruled_plane;
pub(crate) mod scalar;
pub mod sphere_interpolation;

pub use input::{parse, problem_kind, read_problem, Problem};

use crate::Error;
use schemars::JsonSchema;
use serde::de::DeserializeOwned;
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

/// One kind of problem: its name, its input type (whose schema is published), its exact
/// computation and its answer.
pub(crate) trait Kind {
    /// The value of the problem's `"kind"` field.
    const NAME: &'static str;
    /// The input as exact mode reads it; its JSON Schema is `docs/schema/<NAME>.json`.
    type Input: DeserializeOwned + JsonSchema;
    /// The exact answer.
    type Answer: Serialize;
    /// Answers the problem exactly.
    ///
    /// # Errors
    /// [`Error::Input`] naming the field for bad input or degenerate geometry; [`Error::Limit`].
    fn compute(input: Self::Input) -> Result<Self::Answer, Error>;
    /// Answers a problem whose values leave the radical field (`"cos(pi/8)"`): a kind that
    /// accepts exact numbers reads them into the problem's number field
    /// ([`Problem::input_in_field`]) and computes in its scalar. The default, for kinds whose
    /// exact input is rational, reads [`Kind::Input`], which refuses such a value naming it.
    ///
    /// # Errors
    /// As [`Kind::compute`].
    fn compute_in_field(problem: &Problem) -> Result<Self::Answer, Error> {
        Self::compute(problem.input()?)
    }
    /// Whether the kind's exact input is rational and every other exact value (a square root
    /// such as `"sqrt(2)"` too) is answered in the problem's number field
    /// ([`Kind::compute_in_field`]).
    const RATIONAL_OR_FIELD: bool = false;
}

/// A kind answered in f64 too (`--float`), and both ways side by side (`--both`, where its
/// exact answer takes the f64 one by [`Attach`]).
pub(crate) trait FloatKind: Kind {
    /// The input as `--float` reads it.
    type FloatInput: DeserializeOwned;
    /// The f64 answer.
    type FloatAnswer: Serialize;
    /// Answers the problem in f64.
    ///
    /// # Errors
    /// As [`Kind::compute`], and [`Error::Input`] where f64 cannot hold the numbers.
    fn compute_float(input: Self::FloatInput) -> Result<Self::FloatAnswer, Error>;
}

/// An exact answer that takes the f64 answer of `--both` (or the f64 computation's failure).
pub(crate) trait Attach<F> {
    /// Puts the f64 answer into the exact answer.
    ///
    /// # Errors
    /// The f64 computation's failure, where the answer does not report it.
    fn attach(&mut self, float: Result<F, Error>) -> Result<(), Error>;
}

/// An exact answer with a slot for the f64 answer of `--both`, which the f64 computation's
/// failure fails as a whole: [`Attach`] follows.
pub(crate) trait FloatSlot {
    /// The f64 answer.
    type Float;
    /// The slot (`float` in the JSON answer).
    fn float_slot(&mut self) -> &mut Option<Box<Self::Float>>;
}

impl<A: FloatSlot> Attach<A::Float> for A {
    fn attach(&mut self, float: Result<A::Float, Error>) -> Result<(), Error> {
        *self.float_slot() = Some(Box::new(float?));
        Ok(())
    }
}

/// A kind of `solve` in the registry ([`kinds`]): its name, how it is answered, its schema.
#[derive(Clone, Copy)]
pub struct KindEntry {
    /// The kind's name.
    pub name: &'static str,
    /// Why `--float` and `--both` are refused, for an exact-only kind.
    exact_only: Option<&'static str>,
    answer: fn(&Problem, Mode) -> Result<Value, Error>,
    schema: fn() -> schemars::Schema,
}

fn schema_of<T: JsonSchema>() -> schemars::Schema {
    schemars::schema_for!(T)
}

/// The exact answer of a problem: in the problem's number field when a value leaves the radical
/// field (or, for a kind whose exact input is rational, when a value is irrational), else as the
/// kind reads exact numbers (rationals, radicals).
fn exact_answer<K: Kind>(problem: &Problem) -> Result<K::Answer, Error> {
    let in_field = problem.algebraic_values().is_some()
        || (K::RATIONAL_OR_FIELD && !problem.irrational_values()?.is_empty());
    if in_field {
        K::compute_in_field(problem)
    } else {
        K::compute(problem.input()?)
    }
}

/// The f64 answer of a problem.
fn float_answer<K: FloatKind>(problem: &Problem) -> Result<K::FloatAnswer, Error> {
    K::compute_float(problem.input()?)
}

/// The driver of a kind with both modes: the exact answer, the f64 one, or (`--both`) the
/// exact answer (computed first: its errors are the answer's) with the f64 one attached.
fn answer_both_ways<K: FloatKind>(problem: &Problem, mode: Mode) -> Result<Value, Error>
where
    K::Answer: Attach<K::FloatAnswer>,
{
    match mode {
        Mode::Exact => to_json(&exact_answer::<K>(problem)?, mode),
        Mode::Float => to_json(&float_answer::<K>(problem)?, mode),
        Mode::Both => {
            let mut answer = exact_answer::<K>(problem)?;
            answer.attach(float_answer::<K>(problem))?;
            to_json(&answer, mode)
        }
    }
}

/// The driver of an exact-only kind (the mode was checked by [`solve`]).
fn answer_exactly<K: Kind>(problem: &Problem, mode: Mode) -> Result<Value, Error> {
    to_json(&exact_answer::<K>(problem)?, mode)
}

impl KindEntry {
    /// A kind answered exactly and in f64.
    fn both_ways<K: FloatKind>() -> KindEntry
    where
        K::Answer: Attach<K::FloatAnswer>,
    {
        KindEntry {
            name: K::NAME,
            exact_only: None,
            answer: answer_both_ways::<K>,
            schema: schema_of::<K::Input>,
        }
    }

    /// A kind answered exactly only: `--float` and `--both` are refused, before the problem is
    /// read, with "NAME is WHY: --float and --both are not available for it".
    fn exact_only<K: Kind>(why: &'static str) -> KindEntry {
        KindEntry {
            name: K::NAME,
            exact_only: Some(why),
            answer: answer_exactly::<K>,
            schema: schema_of::<K::Input>,
        }
    }
}

/// The registry of the kinds of `solve`, in their fixed order: one line per kind. Schema
/// generation (`solve --schema`, `docs/schema/`), the golden answers and the malformed corpus
/// are checked against it.
pub fn kinds() -> [KindEntry; 7] {
    [
        KindEntry::exact_only::<sphere_interpolation::SphereInterpolation>(
            "an exact linear problem",
        ),
        KindEntry::both_ways::<ruled_plane::RuledPlane>(),
        KindEntry::both_ways::<ruled_line::RuledLine>(),
        KindEntry::both_ways::<plane_plane::PlanePlaneKind>(),
        KindEntry::both_ways::<cylinder_sphere::CylinderSphereKind>(),
        KindEntry::both_ways::<conic::ConicKind>(),
        KindEntry::both_ways::<ph_offset::PhOffset>(),
    ]
}

fn find_kind(kind: &str) -> Result<KindEntry, Error> {
    let all = kinds();
    match all.iter().find(|k| k.name == kind) {
        None => Err(Error::Input(format!(
            "unknown kind {kind:?} (kinds: {})",
            all.iter().map(|k| k.name).collect::<Vec<_>>().join(", ")
        ))),
        Some(k) => Ok(*k),
    }
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

/// Solves one problem given as JSON text: its envelope is read once ([`Problem::read`]), the
/// kind found in the registry ([`kinds`]), and the kind's driver reads the typed input and
/// answers.
///
/// # Errors
/// [`Error::Input`] naming the field for malformed JSON, an unknown kind, wrong arity, bad
/// numbers, division by zero or degenerate geometry; [`Error::Limit`].
pub fn solve(text: &str, mode: Mode) -> Result<Value, Error> {
    let problem = Problem::read(text)?;
    let entry = find_kind(problem.kind())?;
    if let (Some(why), Mode::Float | Mode::Both) = (entry.exact_only, mode) {
        return Err(Error::Input(format!(
            "{} is {why}: --float and --both are not available for it",
            entry.name
        )));
    }
    (entry.answer)(&problem, mode)
}

/// The JSON Schema of a kind's input, pretty-printed with a final newline (the content of
/// `docs/schema/<kind>.json`).
///
/// # Errors
/// [`Error::Usage`] for an unknown kind.
pub fn schema(kind: &str) -> Result<String, Error> {
    let entry = find_kind(kind).map_err(|e| Error::Usage(e.to_string()))?;
    let text = serde_json::to_string_pretty(&(entry.schema)()).expect("a schema is plain JSON");
    Ok(text + "\n")
}
