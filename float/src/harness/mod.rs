//! The regression harness: float code against exact results on random inputs.
//!
//! After CGAL's `Kernel_checker`, every evaluation runs in two kernels — `f64` and an exact
//! [`ExactScalar`] — on the *same* inputs: the random doubles are converted exactly, so any
//! difference is the float code's rounding error and nothing else. A formula is written once,
//! generic over the scalar ([`Formula`]); [`regress`] draws inputs from an [`InputGen`] with a
//! seeded [`Rng`], measures each output's error in ulps and relative terms, aggregates them into
//! a [`Report`], keeps the worst cases and shrinks each to a short reproducible one.
//!
//! # Outcomes of one sample
//! * **compared** — both sides evaluated; the sample's error is the largest over its outputs.
//! * **outside the exact domain** — the exact side reported a [`ZeroDivisor`]: the inputs are not
//!   in the formula's domain (e.g. `x == y` for `1/(x - y)`). Skipped and counted.
//! * **float failure** — the exact side succeeded but the float side reported a zero divisor,
//!   produced a NaN or an infinity, or returned a different number of outputs. Its error is
//!   infinite; it is compared (it counts in the maximum, the median and the thresholds). An
//!   infinite float output is a failure even where the exact value itself lies beyond
//!   `f64::MAX`. (A finite float output whose error is too large for a double also reads `inf`
//!   ulps without being a failure.)
//! * **undecided** — the exact side could not decide a comparison or a sign up to its
//!   precision cap (a value behind an irrational root that may be exactly zero). Skipped and
//!   counted, never guessed.
//! * **invalid inputs** — the generator returned the wrong number of inputs or a non-finite one.
//!   Skipped and counted (built-in generators never do this).
//!
//! # Subjects, sweeps and shards
//! [`run`] sweeps any [`Subject`] — a generic [`Formula`] through [`Generic`], a float program
//! compiled from text, or a user's executable as the float side — over samples `0..samples`
//! of a seeded generator, or over one [`Shard`] of them. The exact side of each chunk of
//! samples runs on all cores; results are aggregated in sample order. A report keeps its
//! statistics as mergeable summaries ([`crate::summary`]), so the shards of a sweep merge
//! ([`crate::merge`]) into the report of the whole sweep: same counts, maxima, worst cases and
//! medians.
//!
//! Each sample's error is also measured as Herbie does: `log2(1 + n)` bits for `n` doubles
//! between the float result and the correctly rounded exact one, the largest over the outputs;
//! the report gives the mean and the maximum. As in Herbie, the infinities are the doubles just
//! past `±f64::MAX` in this count: an overflow to `+inf` where the exact value rounds to `+inf`
//! is 0 bits (though a float failure in ulps, see above), `+inf` where it rounds to a finite
//! double is the ordinal distance between them. A NaN, a zero divisor or a missing output is 64
//! bits.
//!
//! # Shrinking
//! A kept worst case is simplified greedily and deterministically: passes over the inputs try,
//! simplest first, all inputs rounded together to `k` significant bits, all inputs scaled by a
//! common power of two toward magnitude 1, and then for each input: zero, `±1`, the neighbouring
//! powers of two, the nearby integers, the input rounded to `k` significant bits (`k = 1, 2, ...`),
//! the input moved toward magnitude 1 by a power of two, and its absolute value. A change is kept
//! when the inputs become strictly simpler — fewer significant bits in total, then binary
//! exponents closer to 0, then fewer negative signs — and the case stays bad: its error is at
//! least [`Options::shrink_fraction`] of the original error (or stays infinite when that was
//! infinite), with the exact side still defined and the inputs still inside the set the
//! generator samples ([`InputGen::contains`]: the box, the `--domain`, the interval bounds of an
//! FPCore `:pre`; the rest of a `:pre` is the exact side's domain). Passes repeat until nothing
//! changes or the evaluation budget ([`Options::shrink_budget`]) is spent.
//!
//! # Formulas must not panic
//! The exact scalars' `/` operator panics on a zero divisor (as `BigRational`'s does). Formulas
//! divide with [`exactcheck_core::Field::checked_div`] or [`exactcheck_core::Field::inv`] and
//! propagate the [`ZeroDivisor`] with `?`; the harness then counts the sample instead of crashing.

mod accumulate;
mod merge;
mod shrink;

pub use crate::shard::{Shard, Sweep};
pub use merge::{check_consistent, merge, MergeError};

use accumulate::Accumulator;

use crate::convert::{rel_error, ulps_error_in};
use crate::gen::InputGen;
use crate::report::{Case, Report, WorstCase};
use crate::scalar::ExactScalar;
use crate::summary::herbie_bits_in;
use exactcheck_core::Rng;
use exactcheck_core::{OrderedField, ZeroDivisor};
pub use exactcheck_exact::to_f64::Format;
use num_rational::BigRational;
use std::cmp::Ordering;
use std::marker::PhantomData;

/// A formula written once, generic over the scalar, with one or more outputs.
///
/// # Example
/// ```
/// use exactcheck_core::{OrderedField, ZeroDivisor};
/// use exactcheck_float::Formula;
///
/// /// `a*a - b*b`: exact in rationals, catastrophic cancellation in f64 near `a = b`.
/// struct DiffOfSquares;
///
/// impl Formula for DiffOfSquares {
///     fn name(&self) -> String {
///         "a*a - b*b".into()
///     }
///     fn arity(&self) -> usize {
///         2
///     }
///     fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
///         Ok(vec![x[0].square() - x[1].square()])
///     }
/// }
/// ```
pub trait Formula {
    /// A short name for reports.
    fn name(&self) -> String;
    /// The number of inputs; `eval` is only called with slices of this length.
    fn arity(&self) -> usize;
    /// The outputs at `x`, or [`ZeroDivisor`] outside the formula's domain.
    ///
    /// Divide with `checked_div` / `inv` and `?` (see the module docs); do not panic.
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor>;

    /// The float side: by default the same generic [`Formula::eval`] at `f64`. Override it to
    /// regress existing float code (not written generically) against the generic exact
    /// reference `eval`; it must compute the same mathematical function.
    fn eval_f64(&self, x: &[f64]) -> Result<Vec<f64>, ZeroDivisor> {
        self.eval::<f64>(x)
    }
}

impl<F: Formula + ?Sized> Formula for &F {
    fn name(&self) -> String {
        (**self).name()
    }
    fn arity(&self) -> usize {
        (**self).arity()
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        (**self).eval(x)
    }
    fn eval_f64(&self, x: &[f64]) -> Result<Vec<f64>, ZeroDivisor> {
        (**self).eval_f64(x)
    }
}

/// Tuning of [`regress`].
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// How many worst cases to keep (K). Default 5.
    pub worst: usize,
    /// Error levels, in ulps, whose exceedances are counted. Default `[1, 4, 1000]`.
    pub thresholds: Vec<f64>,
    /// Whether to shrink the worst cases. Default `true`.
    pub shrink: bool,
    /// A simplification is kept while the error stays at least this fraction of the original
    /// error; in `(0, 1]`. Default `0.5`.
    pub shrink_fraction: f64,
    /// At most this many evaluations (float and exact) per shrunk case. Default 3000.
    pub shrink_budget: usize,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            worst: 5,
            thresholds: vec![1.0, 4.0, 1e3],
            shrink: true,
            shrink_fraction: 0.5,
            shrink_budget: 3000,
        }
    }
}

/// Why [`regress`] could not run.
#[derive(Clone, Debug, PartialEq)]
pub enum RegressError {
    /// The generator's inputs do not fit the formula.
    ArityMismatch {
        /// The formula's arity.
        formula: usize,
        /// The generator's arity.
        generator: usize,
    },
    /// An option is out of range.
    InvalidOptions(String),
    /// The float side failed for good (an external program crashed, hung or answered garbage);
    /// the message names the sample.
    FloatSide(String),
    /// The observer of [`run_observed`] stopped the sweep; the message says why.
    Observer(String),
}

impl std::fmt::Display for RegressError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RegressError::ArityMismatch { formula, generator } => write!(
                f,
                "the formula takes {formula} inputs but the generator makes {generator}"
            ),
            RegressError::InvalidOptions(why) => write!(f, "invalid regression options: {why}"),
            RegressError::FloatSide(why) | RegressError::Observer(why) => f.write_str(why),
        }
    }
}

impl std::error::Error for RegressError {}

/// Why a single case could not be compared (see [`check`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CaseError {
    /// Wrong number of inputs, or a non-finite input.
    InvalidInputs,
    /// The exact evaluation reported a zero divisor: the inputs lie outside the domain.
    OutsideDomain,
    /// The exact side could not decide a comparison or a sign (a value that may be exactly
    /// zero, behind an irrational root) up to its precision cap, or an exact intermediate
    /// exceeded its size limit: counted, never guessed.
    Undecided,
    /// The exact evaluation ran past a limit on its work that bounds every sample (the
    /// `loop-iterations` of a program's loops): counted apart, with the limit named.
    LimitExceeded {
        /// The limit's name.
        limit: &'static str,
        /// Its value in force.
        value: u64,
    },
}

impl std::fmt::Display for CaseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CaseError::InvalidInputs => f.write_str("wrong number of inputs or a non-finite input"),
            CaseError::OutsideDomain => f.write_str("the inputs lie outside the formula's domain"),
            CaseError::Undecided => {
                f.write_str(
                    "the exact side could not decide a sign up to its precision cap, or exceeded its size limit",
                )
            }
            CaseError::LimitExceeded { limit, value } => write!(
                f,
                "the exact evaluation exceeds the limit {limit} = {value} (raise it with --limit {limit}=N)"
            ),
        }
    }
}

impl std::error::Error for CaseError {}

/// The exact value of one output: a rational that is the true value (`exact`), or, for a real
/// number behind an irrational square root, a rational approximation close enough that the
/// error of any double against it is the error against the true value to far below an ulp.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactValue {
    /// The value (or its approximation).
    pub value: BigRational,
    /// Whether `value` is the true value.
    pub exact: bool,
}

impl ExactValue {
    /// A value known exactly.
    pub fn exact(value: BigRational) -> ExactValue {
        ExactValue { value, exact: true }
    }
}

/// A float side that failed for good: an external program crashed, hung or answered garbage.
/// The message is one line naming the sample.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FloatSideError(pub String);

impl std::fmt::Display for FloatSideError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for FloatSideError {}

/// What the harness regresses: an exact side and a float side on the same input doubles.
///
/// Every subject goes through the one sweep ([`run`]): a [`Formula`] written generically over
/// the scalar (through [`Generic`]), a float program compiled from text, or a user's executable
/// as the float side. The exact side is called from several threads at once (hence `Sync`);
/// the float side is called from the sweep's thread only, in batches, in sample order.
pub trait Subject: Sync {
    /// A short name for reports.
    fn name(&self) -> String;
    /// The number of inputs.
    fn arity(&self) -> usize;
    /// What computes the float results, for reports: shards of a sweep merge only when it is
    /// the same (the built-in code's name, a formula's text, an external program's command).
    fn float_side(&self) -> String;
    /// The exact outputs at `x` (one `ExactValue` per output).
    ///
    /// # Errors
    /// [`CaseError::OutsideDomain`] outside the formula's domain, [`CaseError::Undecided`] when
    /// the exact side could not decide, [`CaseError::InvalidInputs`] for inputs it cannot take.
    fn exact(&self, x: &[f64]) -> Result<Vec<ExactValue>, CaseError>;
    /// The float outputs of sample `index` at `x`; `None` when the float side reported a zero
    /// divisor (a float failure).
    ///
    /// # Errors
    /// A [`FloatSideError`] ends the sweep (an external program that failed).
    fn float(&self, index: usize, x: &[f64]) -> Result<Option<Vec<f64>>, FloatSideError>;
    /// The float outputs of samples `first, first + 1, ...`; by default one [`Subject::float`]
    /// call each. An external program overrides it to pipeline the batch.
    ///
    /// # Errors
    /// As [`Subject::float`].
    fn float_batch(
        &self,
        first: usize,
        xs: &[Vec<f64>],
    ) -> Result<Vec<Option<Vec<f64>>>, FloatSideError> {
        xs.iter()
            .enumerate()
            .map(|(k, x)| self.float(first + k, x))
            .collect()
    }
    /// Called once when the sweep (worst cases shrunk) is done; by default nothing. An external
    /// program is told its input has ended and checked to have kept the protocol to the end.
    ///
    /// # Errors
    /// As [`Subject::float`]: the sweep's report is not given.
    fn finish(&self) -> Result<(), FloatSideError> {
        Ok(())
    }
    /// The format the float side computes in: its results, the exact value's correct rounding,
    /// ulps and Herbie's bits are those of this format (binary64 by default).
    fn format(&self) -> Format {
        Format::Binary64
    }
}

/// A [`Formula`] as a [`Subject`]: its generic `eval` in the exact scalar `E` against its
/// `eval_f64`.
pub struct Generic<'a, F: ?Sized, E> {
    formula: &'a F,
    scalar: PhantomData<fn() -> E>,
}

impl<'a, F: Formula + ?Sized, E: ExactScalar> Generic<'a, F, E> {
    /// Wraps `formula`.
    pub fn new(formula: &'a F) -> Self {
        Generic {
            formula,
            scalar: PhantomData,
        }
    }
}

impl<F: Formula + Sync + ?Sized, E: ExactScalar> Subject for Generic<'_, F, E> {
    fn name(&self) -> String {
        self.formula.name()
    }
    fn arity(&self) -> usize {
        self.formula.arity()
    }
    fn float_side(&self) -> String {
        format!("built-in {}", self.formula.name())
    }
    fn exact(&self, x: &[f64]) -> Result<Vec<ExactValue>, CaseError> {
        if x.len() != self.formula.arity() {
            return Err(CaseError::InvalidInputs);
        }
        let exact_in: Vec<E> = x
            .iter()
            .map(|&v| E::from_f64_exact(v))
            .collect::<Option<_>>()
            .ok_or(CaseError::InvalidInputs)?;
        let out = self
            .formula
            .eval(&exact_in)
            .map_err(|ZeroDivisor| CaseError::OutsideDomain)?;
        Ok(out
            .iter()
            .map(|v| ExactValue::exact(v.to_big_rational()))
            .collect())
    }
    fn float(&self, _index: usize, x: &[f64]) -> Result<Option<Vec<f64>>, FloatSideError> {
        Ok(self.formula.eval_f64(x).ok())
    }
}

/// The inputs of sample `index` of a run with this generator and seed: how a report's worst case
/// is reproduced.
pub fn sample_inputs(gen: &(impl InputGen + ?Sized), seed: u64, index: usize) -> Vec<f64> {
    gen.sample(&mut Rng::for_sample(seed, index as u64))
}

/// One comparison, before it is turned into strings.
#[derive(Clone, Debug)]
pub(crate) struct Evaluated {
    exact: Vec<ExactValue>,
    float: Option<Vec<f64>>,
    ulps: Vec<f64>,
    rel: Vec<f64>,
    pub(crate) max_ulps: f64,
    max_rel: f64,
    bits: f64,
    failure: bool,
    /// The format the errors are measured in.
    format: Format,
}

/// An exact output for reports: `n` or `n/d` when exact, else `~` and 25 significant digits.
fn exact_text(v: &ExactValue) -> String {
    if v.exact {
        v.value.to_string()
    } else {
        format!("~{}", crate::convert::decimal_digits(&v.value, 25))
    }
}

impl Evaluated {
    fn to_case(&self, inputs: &[f64]) -> Case {
        Case {
            inputs: inputs.to_vec(),
            inputs_exact: inputs
                .iter()
                .map(|&x| {
                    crate::convert::f64_to_rational(x)
                        .map_or_else(|| "NaN".into(), |q| q.to_string())
                })
                .collect(),
            exact_outputs: self.exact.iter().map(exact_text).collect(),
            exact_outputs_f64: self
                .exact
                .iter()
                .map(|v| self.format.round(&v.value))
                .collect(),
            float_outputs: self.float.clone(),
            ulps_per_output: self.ulps.clone(),
            rel_per_output: self.rel.clone(),
            ulps: self.max_ulps,
            rel: self.max_rel,
            bits: self.bits,
            float_failure: self.failure,
        }
    }
}

/// Compares exact and float outputs of one sample.
/// Errors are measured in `format`: ulps of the format's value nearest to the exact value, and
/// Herbie's bits over the format's ordinal distance (the format's width for a NaN).
fn compare(exact: Vec<ExactValue>, float: Option<Vec<f64>>, format: Format) -> Evaluated {
    let width = match format {
        Format::Binary64 => 64.0,
        Format::Binary32 => 32.0,
    };
    let failure = match &float {
        Some(f) => f.len() != exact.len() || f.iter().any(|v| !v.is_finite()),
        None => true,
    };
    let mut ulps = Vec::with_capacity(exact.len());
    let mut rel = Vec::with_capacity(exact.len());
    let mut bits: f64 = match &float {
        Some(f) if f.len() == exact.len() => 0.0,
        _ => width,
    };
    for (i, q) in exact.iter().enumerate() {
        match float.as_ref().and_then(|f| f.get(i)) {
            Some(&a) => {
                let rounded = format.round(&q.value);
                ulps.push(ulps_error_in(format, a, &q.value, rounded));
                rel.push(rel_error(a, &q.value));
                bits = bits.max(herbie_bits_in(format, a, rounded));
            }
            None => {
                ulps.push(f64::INFINITY);
                rel.push(f64::INFINITY);
                bits = width;
            }
        }
    }
    let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
    let (max_ulps, max_rel) = (max(&ulps), max(&rel));
    Evaluated {
        max_ulps: if failure { f64::INFINITY } else { max_ulps },
        max_rel: if failure { f64::INFINITY } else { max_rel },
        bits,
        exact,
        float,
        ulps,
        rel,
        failure,
        format,
    }
}

/// The exact side at one input vector, after the check every sample gets: the subject's arity,
/// finite inputs.
fn exact_side(subject: &(impl Subject + ?Sized), x: &[f64]) -> Result<Vec<ExactValue>, CaseError> {
    if x.len() != subject.arity() || x.iter().any(|v| !v.is_finite()) {
        return Err(CaseError::InvalidInputs);
    }
    subject.exact(x)
}

/// Both sides at one input vector (sample `index`, for the float side's error messages).
pub(crate) fn evaluate_one(
    subject: &(impl Subject + ?Sized),
    index: usize,
    x: &[f64],
) -> Result<Result<Evaluated, CaseError>, FloatSideError> {
    let exact = match exact_side(subject, x) {
        Ok(e) => e,
        Err(e) => return Ok(Err(e)),
    };
    let float = subject.float(index, x)?;
    Ok(Ok(compare(exact, float, subject.format())))
}

/// Compares the float and exact evaluations of `formula` at one input vector: the building block
/// of [`regress`], for pinning a reported worst case in a unit test.
///
/// # Errors
/// [`CaseError::InvalidInputs`] for a wrong number of inputs or a non-finite one,
/// [`CaseError::OutsideDomain`] when the exact evaluation reports a zero divisor.
pub fn check<E: ExactScalar>(
    formula: &(impl Formula + Sync + ?Sized),
    inputs: &[f64],
) -> Result<Case, CaseError> {
    check_subject(&Generic::<_, E>::new(formula), inputs)
        .expect("a generic formula's float side does not fail for good")
}

/// [`check`] for any [`Subject`].
///
/// # Errors
/// The outer error: the float side failed for good; the inner: as [`check`].
pub fn check_subject(
    subject: &(impl Subject + ?Sized),
    inputs: &[f64],
) -> Result<Result<Case, CaseError>, FloatSideError> {
    Ok(evaluate_one(subject, 0, inputs)?.map(|ev| ev.to_case(inputs)))
}

/// The order of badness: larger ulps error, then larger relative error, then earlier sample.
pub(crate) fn worse(a: (f64, f64, usize), b: (f64, f64, usize)) -> Ordering {
    b.0.total_cmp(&a.0)
        .then(b.1.total_cmp(&a.1))
        .then(a.2.cmp(&b.2))
}

/// Samples evaluated between two calls of the progress callback (and the batch of a float
/// side's [`Subject::float_batch`]).
pub const CHUNK: usize = 512;

/// Runs `formula` on `samples` inputs from `gen` in `f64` and in the exact scalar `E` and reports
/// the float errors: [`run`] with the formula's generic evaluation, the whole sweep, no progress.
///
/// Sample `i` draws from [`Rng::for_sample`]`(seed, i)` (see [`sample_inputs`]), so a run is
/// reproducible from its seed and each worst case from `(seed, index)`. See the module docs for
/// how samples are classified and worst cases shrunk.
///
/// # Errors
/// When the formula's and the generator's arities differ, or an option is out of range.
///
/// # Example
/// ```
/// use exactcheck_core::{OrderedField, ZeroDivisor};
/// use exactcheck_exact::PlainRational;
/// use exactcheck_float::{regress, Formula, Options, UniformBox};
///
/// struct Sum;
/// impl Formula for Sum {
///     fn name(&self) -> String { "x + y".into() }
///     fn arity(&self) -> usize { 2 }
///     fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
///         Ok(vec![x[0].add_ref(&x[1])])
///     }
/// }
///
/// let gen = UniformBox::cube(2, -1.0, 1.0)?;
/// let report = regress::<PlainRational>(&Sum, &gen, 200, 7, &Options::default())?;
/// assert!(report.max_ulps <= 0.5); // IEEE addition is correctly rounded
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn regress<E: ExactScalar>(
    formula: &(impl Formula + Sync + ?Sized),
    gen: &(impl InputGen + ?Sized),
    samples: usize,
    seed: u64,
    options: &Options,
) -> Result<Report, RegressError> {
    let sweep = Sweep {
        samples,
        seed,
        shard: None,
    };
    run(&Generic::<_, E>::new(formula), gen, sweep, options, &|_| {})
}

/// The K worst so far, worst first: (sample, inputs, evaluation).
type Kept = Vec<(usize, Vec<f64>, Evaluated)>;

/// Runs a sweep (or one shard of it) of `subject` on inputs from `gen` and reports the float
/// errors. `progress` is called with the number of samples done after every [`CHUNK`].
///
/// The exact side of a chunk is evaluated on all cores; samples are aggregated in index order,
/// so the report does not depend on the number of threads. A shard's report merges with the
/// others' into the whole sweep's ([`crate::merge`]).
///
/// # Errors
/// When the subject's and the generator's arities differ, an option is out of range, or the
/// float side failed for good.
pub fn run(
    subject: &(impl Subject + ?Sized),
    gen: &(impl InputGen + ?Sized),
    sweep: Sweep,
    options: &Options,
    progress: &dyn Fn(usize),
) -> Result<Report, RegressError> {
    run_observed(subject, gen, sweep, options, progress, &mut |_| Ok(()))
}

/// One compared sample as the sweep measured it, for per-sample exports ([`run_observed`]).
#[derive(Clone, Copy, Debug)]
pub struct Observed<'a> {
    /// The sample index.
    pub index: usize,
    /// The inputs.
    pub inputs: &'a [f64],
    /// The exact outputs.
    pub exact: &'a [ExactValue],
    /// The float outputs (`None`: the float side reported a zero divisor).
    pub float: Option<&'a [f64]>,
    /// Each output's error in ulps.
    pub ulps: &'a [f64],
    /// The sample's error in ulps (infinite for a float failure).
    pub max_ulps: f64,
    /// The sample's bits of error (Herbie's measure).
    pub bits: f64,
}

/// [`run`], calling `observe` with every compared sample in sample order (from the sweep's
/// thread); an `Err` from it ends the sweep with [`RegressError::Observer`].
///
/// # Errors
/// As [`run`], and [`RegressError::Observer`].
pub fn run_observed(
    subject: &(impl Subject + ?Sized),
    gen: &(impl InputGen + ?Sized),
    sweep: Sweep,
    options: &Options,
    progress: &dyn Fn(usize),
    observe: &mut dyn FnMut(&Observed<'_>) -> Result<(), String>,
) -> Result<Report, RegressError> {
    use rayon::prelude::*;
    if !(options.shrink_fraction > 0.0 && options.shrink_fraction <= 1.0) {
        return Err(RegressError::InvalidOptions(format!(
            "shrink_fraction = {} is not in (0, 1]",
            options.shrink_fraction
        )));
    }
    if let Some(t) = options.thresholds.iter().find(|t| t.is_nan()) {
        return Err(RegressError::InvalidOptions(format!("threshold {t}")));
    }
    if let Some(s) = sweep.shard {
        if s.index == 0 || s.index > s.count {
            return Err(RegressError::InvalidOptions(format!("shard {s}")));
        }
    }
    let format = subject.format();
    if subject.arity() != gen.arity() {
        return Err(RegressError::ArityMismatch {
            formula: subject.arity(),
            generator: gen.arity(),
        });
    }
    let range = sweep
        .shard
        .map_or(0..sweep.samples, |s| s.range(sweep.samples));
    let mut acc = Accumulator::new(options);
    let mut kept: Kept = Vec::new();
    let mut done = 0;
    let mut start = range.start;
    while start < range.end {
        let end = (start + CHUNK).min(range.end);
        let inputs: Vec<Vec<f64>> = (start..end)
            .map(|i| sample_inputs(gen, sweep.seed, i))
            .collect();
        let exact: Vec<Result<Vec<ExactValue>, CaseError>> =
            inputs.par_iter().map(|x| exact_side(subject, x)).collect();
        // The float side only where the exact side is defined.
        // The float side only where the exact side is defined, in runs of consecutive samples
        // (slices of the chunk, so the batch's sample labels stay right).
        let mut floats = vec![None; inputs.len()];
        let mut k = 0;
        while k < inputs.len() {
            if exact[k].is_err() {
                k += 1;
                continue;
            }
            let mut j = k + 1;
            while j < inputs.len() && exact[j].is_ok() {
                j += 1;
            }
            let out = subject
                .float_batch(start + k, &inputs[k..j])
                .map_err(|e| RegressError::FloatSide(e.0))?;
            if out.len() != j - k {
                return Err(RegressError::FloatSide(format!(
                    "the float side answered {} of the {} samples from sample {}",
                    out.len(),
                    j - k,
                    start + k
                )));
            }
            for (slot, o) in floats[k..j].iter_mut().zip(out) {
                *slot = Some(o);
            }
            k = j;
        }
        // The measures (exact rational arithmetic) on all cores too.
        let evaluated: Vec<Result<Evaluated, CaseError>> = exact
            .into_par_iter()
            .zip(floats.into_par_iter())
            .map(|(e, float)| {
                e.map(|e| {
                    compare(
                        e,
                        float.expect("the float side of a defined sample"),
                        format,
                    )
                })
            })
            .collect();
        for (k, (x, ev)) in inputs.into_iter().zip(evaluated).enumerate() {
            match ev {
                Err(e) => acc.skip(e),
                Ok(ev) => {
                    acc.add(&ev);
                    observe(&Observed {
                        index: start + k,
                        inputs: &x,
                        exact: &ev.exact,
                        float: ev.float.as_deref(),
                        ulps: &ev.ulps,
                        max_ulps: ev.max_ulps,
                        bits: ev.bits,
                    })
                    .map_err(RegressError::Observer)?;
                    keep(&mut kept, options.worst, start + k, x, ev);
                }
            }
        }
        done += end - start;
        progress(done);
        start = end;
    }

    let worst = kept
        .into_iter()
        .map(|(index, inputs, ev)| {
            let original = ev.to_case(&inputs);
            let (shrunk, steps, evaluations) = if options.shrink && ev.max_ulps > 0.0 {
                let s = shrink::shrink(subject, gen, index, &inputs, &ev, options)
                    .map_err(|e| RegressError::FloatSide(e.0))?;
                (Some(s.ev.to_case(&s.inputs)), s.steps, s.evaluations)
            } else {
                (None, 0, 0)
            };
            Ok(WorstCase {
                index,
                original,
                shrunk,
                shrink_steps: steps,
                shrink_evaluations: evaluations,
                explanation: None,
            })
        })
        .collect::<Result<Vec<_>, RegressError>>()?;
    subject.finish().map_err(|e| RegressError::FloatSide(e.0))?;
    Ok(acc.report(subject, gen.describe(), sweep, options, worst))
}

/// Inserts a case into the K worst, keeping them worst first.
fn keep(kept: &mut Kept, k: usize, i: usize, x: Vec<f64>, ev: Evaluated) {
    if k == 0 {
        return;
    }
    let key = (ev.max_ulps, ev.max_rel, i);
    let pos =
        kept.partition_point(|(j, _, e)| worse((e.max_ulps, e.max_rel, *j), key) == Ordering::Less);
    if pos < k {
        kept.insert(pos, (i, x, ev));
        kept.truncate(k);
    }
}

#[cfg(test)]
mod tests {
    use super::shrink::{complexity, coordinate_candidates, global_candidates};
    use super::*;
    use crate::gen::UniformBox;
    use exactcheck_exact::PlainRational;

    struct Cancel;
    impl Formula for Cancel {
        fn name(&self) -> String {
            "(x + y) - x".into()
        }
        fn arity(&self) -> usize {
            2
        }
        fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
            Ok(vec![x[0].add_ref(&x[1]).sub_ref(&x[0])])
        }
    }

    #[test]
    fn complexity_orders_simplicity() {
        assert!(complexity(&[0.0]) < complexity(&[1.0]));
        assert!(complexity(&[1.0]) < complexity(&[0.5]));
        assert!(complexity(&[0.5]) < complexity(&[-0.5]));
        assert!(complexity(&[-0.5]) < complexity(&[0.75]));
        assert!(complexity(&[3.0, 1.0]) < complexity(&[0.1, 1.0]));
    }

    #[test]
    fn candidates_are_finite_and_include_the_simple_ones() {
        let c = coordinate_candidates(-1234.5678);
        assert!(c.iter().all(|v| v.is_finite()));
        for v in [0.0, -1.0, -1024.0, -2048.0, -1234.0, -1235.0, 1234.5678] {
            assert!(c.contains(&v), "{v} missing");
        }
        assert_eq!(coordinate_candidates(0.0), vec![0.0]);
        let g = global_candidates(&[1e300, 3.0]);
        assert!(g.iter().all(|y| y.iter().all(|v| v.is_finite())));
        // Joint roundings, the common scaling, and translations keeping the difference.
        let g = global_candidates(&[1.75, 1.875]);
        assert!(g.contains(&vec![2.0, 2.0]));
        assert!(g.contains(&vec![1.0, 1.125]));
        assert!(g.contains(&vec![0.875, 1.0]));
    }

    #[test]
    fn check_classifies() {
        let case = check::<PlainRational>(&Cancel, &[1.0, 1e-20]).expect("defined");
        assert!(case.ulps > 1e6);
        assert_eq!(case.float_outputs, Some(vec![0.0]));
        assert_eq!(
            check::<PlainRational>(&Cancel, &[1.0]).err(),
            Some(CaseError::InvalidInputs)
        );
        assert_eq!(
            check::<PlainRational>(&Cancel, &[1.0, f64::NAN]).err(),
            Some(CaseError::InvalidInputs)
        );
    }

    #[test]
    fn options_and_arity_are_validated() {
        let gen = UniformBox::cube(3, 0.0, 1.0).expect("valid");
        let err = regress::<PlainRational>(&Cancel, &gen, 10, 1, &Options::default());
        assert_eq!(
            err.err(),
            Some(RegressError::ArityMismatch {
                formula: 2,
                generator: 3
            })
        );
        let gen = UniformBox::cube(2, 0.0, 1.0).expect("valid");
        let bad = Options {
            shrink_fraction: 0.0,
            ..Options::default()
        };
        assert!(matches!(
            regress::<PlainRational>(&Cancel, &gen, 10, 1, &bad),
            Err(RegressError::InvalidOptions(_))
        ));
        let empty =
            regress::<PlainRational>(&Cancel, &gen, 0, 1, &Options::default()).expect("runs");
        assert_eq!(
            (empty.compared, empty.max_ulps, empty.worst.len()),
            (0, 0.0, 0)
        );
    }
}
