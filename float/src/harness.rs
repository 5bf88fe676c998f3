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
//! * **invalid inputs** — the generator returned the wrong number of inputs or a non-finite one.
//!   Skipped and counted (built-in generators never do this).
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
//! infinite), with the exact side still defined. Passes repeat until nothing changes or the
//! evaluation budget ([`Options::shrink_budget`]) is spent.
//!
//! # Formulas must not panic
//! The exact scalars' `/` operator panics on a zero divisor (as `BigRational`'s does). Formulas
//! divide with [`exactcheck_core::Field::checked_div`] or [`exactcheck_core::Field::inv`] and
//! propagate the [`ZeroDivisor`] with `?`; the harness then counts the sample instead of crashing.

use crate::convert::{
    binary_exponent, pow2, rel_error, round_to_bits, significant_bits, truncate_to_bits, ulps_error,
};
use crate::gen::InputGen;
use crate::report::{Case, Report, ThresholdCount, WorstCase};
use crate::scalar::ExactScalar;
use exactcheck_core::Rng;
use exactcheck_core::{OrderedField, ZeroDivisor};
use num_rational::BigRational;
use std::cmp::Ordering;

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
}

impl std::fmt::Display for RegressError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RegressError::ArityMismatch { formula, generator } => write!(
                f,
                "the formula takes {formula} inputs but the generator makes {generator}"
            ),
            RegressError::InvalidOptions(why) => write!(f, "invalid regression options: {why}"),
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
}

impl std::fmt::Display for CaseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CaseError::InvalidInputs => f.write_str("wrong number of inputs or a non-finite input"),
            CaseError::OutsideDomain => f.write_str("the inputs lie outside the formula's domain"),
        }
    }
}

impl std::error::Error for CaseError {}

/// The inputs of sample `index` of a run with this generator and seed: how a report's worst case
/// is reproduced.
pub fn sample_inputs(gen: &(impl InputGen + ?Sized), seed: u64, index: usize) -> Vec<f64> {
    gen.sample(&mut Rng::for_sample(seed, index as u64))
}

/// One comparison, before it is turned into strings.
#[derive(Clone, Debug)]
struct Evaluated {
    exact: Vec<BigRational>,
    float: Option<Vec<f64>>,
    ulps: Vec<f64>,
    rel: Vec<f64>,
    max_ulps: f64,
    max_rel: f64,
    failure: bool,
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
            exact_outputs: self.exact.iter().map(|q| q.to_string()).collect(),
            exact_outputs_f64: self
                .exact
                .iter()
                .map(crate::convert::rational_to_f64)
                .collect(),
            float_outputs: self.float.clone(),
            ulps_per_output: self.ulps.clone(),
            rel_per_output: self.rel.clone(),
            ulps: self.max_ulps,
            rel: self.max_rel,
            float_failure: self.failure,
        }
    }
}

fn evaluate<E: ExactScalar>(
    formula: &(impl Formula + ?Sized),
    x: &[f64],
) -> Result<Evaluated, CaseError> {
    if x.len() != formula.arity() {
        return Err(CaseError::InvalidInputs);
    }
    let exact_in: Vec<E> = x
        .iter()
        .map(|&v| E::from_f64_exact(v))
        .collect::<Option<_>>()
        .ok_or(CaseError::InvalidInputs)?;
    let exact_out = formula
        .eval(&exact_in)
        .map_err(|ZeroDivisor| CaseError::OutsideDomain)?;
    let exact: Vec<BigRational> = exact_out.iter().map(E::to_big_rational).collect();
    let float = formula.eval_f64(x).ok();
    let failure = match &float {
        Some(f) => f.len() != exact.len() || f.iter().any(|v| !v.is_finite()),
        None => true,
    };
    let mut ulps = Vec::with_capacity(exact.len());
    let mut rel = Vec::with_capacity(exact.len());
    for (i, q) in exact.iter().enumerate() {
        match float.as_ref().and_then(|f| f.get(i)) {
            Some(&a) => {
                ulps.push(ulps_error(a, q));
                rel.push(rel_error(a, q));
            }
            None => {
                ulps.push(f64::INFINITY);
                rel.push(f64::INFINITY);
            }
        }
    }
    let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
    let (max_ulps, max_rel) = (max(&ulps), max(&rel));
    Ok(Evaluated {
        max_ulps: if failure { f64::INFINITY } else { max_ulps },
        max_rel: if failure { f64::INFINITY } else { max_rel },
        exact,
        float,
        ulps,
        rel,
        failure,
    })
}

/// Compares the float and exact evaluations of `formula` at one input vector: the building block
/// of [`regress`], for pinning a reported worst case in a unit test.
///
/// # Errors
/// [`CaseError::InvalidInputs`] for a wrong number of inputs or a non-finite one,
/// [`CaseError::OutsideDomain`] when the exact evaluation reports a zero divisor.
pub fn check<E: ExactScalar>(
    formula: &(impl Formula + ?Sized),
    inputs: &[f64],
) -> Result<Case, CaseError> {
    evaluate::<E>(formula, inputs).map(|ev| ev.to_case(inputs))
}

/// The order of badness: larger ulps error, then larger relative error, then earlier sample.
fn worse(a: (f64, f64, usize), b: (f64, f64, usize)) -> Ordering {
    b.0.total_cmp(&a.0)
        .then(b.1.total_cmp(&a.1))
        .then(a.2.cmp(&b.2))
}

/// The median of a sorted slice (the mean of the two middle values for an even length; 0 when
/// empty).
fn median(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    if n == 0 {
        0.0
    } else if n % 2 == 1 {
        sorted[n / 2]
    } else {
        let (a, b) = (sorted[n / 2 - 1], sorted[n / 2]);
        if a == b {
            a
        } else {
            a + (b - a) / 2.0
        }
    }
}

/// Runs `formula` on `samples` inputs from `gen` in `f64` and in the exact scalar `E` and reports
/// the float errors.
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
    formula: &(impl Formula + ?Sized),
    gen: &(impl InputGen + ?Sized),
    samples: usize,
    seed: u64,
    options: &Options,
) -> Result<Report, RegressError> {
    if !(options.shrink_fraction > 0.0 && options.shrink_fraction <= 1.0) {
        return Err(RegressError::InvalidOptions(format!(
            "shrink_fraction = {} is not in (0, 1]",
            options.shrink_fraction
        )));
    }
    if let Some(t) = options.thresholds.iter().find(|t| t.is_nan()) {
        return Err(RegressError::InvalidOptions(format!("threshold {t}")));
    }
    if formula.arity() != gen.arity() {
        return Err(RegressError::ArityMismatch {
            formula: formula.arity(),
            generator: gen.arity(),
        });
    }

    let mut ulps_all = Vec::with_capacity(samples.min(1 << 20));
    let mut rel_all = Vec::with_capacity(samples.min(1 << 20));
    let (mut domain_errors, mut invalid_inputs, mut float_failures) = (0, 0, 0);
    let (mut mean, mut finite) = (0.0f64, 0usize);
    let mut max_per_output: Vec<f64> = Vec::new();
    // The K worst so far, worst first: (sample, inputs, evaluation).
    let mut kept: Vec<(usize, Vec<f64>, Evaluated)> = Vec::new();

    for i in 0..samples {
        let x = sample_inputs(gen, seed, i);
        let ev = match evaluate::<E>(formula, &x) {
            Ok(ev) => ev,
            Err(CaseError::InvalidInputs) => {
                invalid_inputs += 1;
                continue;
            }
            Err(CaseError::OutsideDomain) => {
                domain_errors += 1;
                continue;
            }
        };
        if ev.failure {
            float_failures += 1;
        }
        if ev.max_ulps.is_finite() {
            finite += 1;
            mean += (ev.max_ulps - mean) / finite as f64;
        }
        if max_per_output.len() < ev.ulps.len() {
            max_per_output.resize(ev.ulps.len(), 0.0);
        }
        for (m, &u) in max_per_output.iter_mut().zip(&ev.ulps) {
            *m = m.max(u);
        }
        ulps_all.push(ev.max_ulps);
        rel_all.push(ev.max_rel);
        if options.worst > 0 {
            let key = (ev.max_ulps, ev.max_rel, i);
            let pos = kept.partition_point(|(j, _, e)| {
                worse((e.max_ulps, e.max_rel, *j), key) == Ordering::Less
            });
            if pos < options.worst {
                kept.insert(pos, (i, x, ev));
                kept.truncate(options.worst);
            }
        }
    }

    ulps_all.sort_by(f64::total_cmp);
    rel_all.sort_by(f64::total_cmp);
    let above = options
        .thresholds
        .iter()
        .map(|&t| ThresholdCount {
            ulps: t,
            count: ulps_all.len() - ulps_all.partition_point(|&u| u <= t),
        })
        .collect();

    let worst = kept
        .into_iter()
        .map(|(index, inputs, ev)| {
            let original = ev.to_case(&inputs);
            let (shrunk, steps, evaluations) = if options.shrink && ev.max_ulps > 0.0 {
                let s = shrink::<E>(formula, &inputs, &ev, options);
                (Some(s.ev.to_case(&s.inputs)), s.steps, s.evaluations)
            } else {
                (None, 0, 0)
            };
            WorstCase {
                index,
                original,
                shrunk,
                shrink_steps: steps,
                shrink_evaluations: evaluations,
            }
        })
        .collect();

    Ok(Report {
        formula: formula.name(),
        generator: gen.describe(),
        arity: formula.arity(),
        samples,
        seed,
        compared: ulps_all.len(),
        domain_errors,
        invalid_inputs,
        float_failures,
        max_ulps: ulps_all.last().copied().unwrap_or(0.0),
        median_ulps: median(&ulps_all),
        mean_ulps: mean,
        max_rel: rel_all.last().copied().unwrap_or(0.0),
        median_rel: median(&rel_all),
        max_ulps_per_output: max_per_output,
        above,
        worst,
    })
}

/// The result of shrinking one case.
struct Shrunk {
    inputs: Vec<f64>,
    ev: Evaluated,
    steps: usize,
    evaluations: usize,
}

/// The simplicity of an input vector, smaller is simpler: total significant bits, total distance
/// of the binary exponents from 0, number of negative inputs.
fn complexity(x: &[f64]) -> (u32, u64, usize) {
    let bits = x.iter().map(|&v| significant_bits(v)).sum();
    let exps = x
        .iter()
        .map(|&v| binary_exponent(v).map_or(0, |e| u64::from(e.unsigned_abs())))
        .sum();
    let negs = x.iter().filter(|&&v| v < 0.0).count();
    (bits, exps, negs)
}

/// `-0.0` becomes `0.0` (a shrunk input should read simply).
fn plain_zero(v: f64) -> f64 {
    if v == 0.0 {
        0.0
    } else {
        v
    }
}

/// Simpler replacements for one input, simplest first (not necessarily all simpler, nor
/// distinct; the caller filters).
fn coordinate_candidates(x: f64) -> Vec<f64> {
    let mut c = vec![0.0];
    let Some(e) = binary_exponent(x) else {
        return c;
    };
    let s = x.signum();
    c.push(s);
    c.push(s * pow2(e));
    c.push(s * pow2(e + 1));
    c.push(x.trunc());
    c.push(x.round());
    for k in 1..significant_bits(x) {
        c.push(round_to_bits(x, k));
        c.push(truncate_to_bits(x, k));
    }
    c.push(x * pow2(-e));
    c.push(x * pow2(-e / 2));
    c.push(x.abs());
    c.into_iter()
        .filter(|v| v.is_finite())
        .map(plain_zero)
        .collect()
}

/// Simpler replacements for the whole vector, simplest first.
fn global_candidates(x: &[f64]) -> Vec<Vec<f64>> {
    let mut c = Vec::new();
    let max_bits = x.iter().map(|&v| significant_bits(v)).max().unwrap_or(0);
    for k in 1..max_bits {
        c.push(x.iter().map(|&v| plain_zero(round_to_bits(v, k))).collect());
    }
    let top = x
        .iter()
        .filter_map(|&v| binary_exponent(v))
        .max_by_key(|&e| (e.unsigned_abs(), e));
    if let Some(e) = top {
        for shift in [-e, -e / 2] {
            // Only exact scalings (no bit lost to underflow, no overflow).
            let y: Vec<f64> = x.iter().map(|&v| v * pow2(shift)).collect();
            let exact = x
                .iter()
                .zip(&y)
                .all(|(&v, &w)| w.is_finite() && w * pow2(-shift) == v && (v == 0.0) == (w == 0.0));
            if exact && shift != 0 {
                c.push(y);
            }
        }
    }
    // Translations that keep the differences to one input while moving that input to a simple
    // value: near-degenerate inputs agree in their leading bits, and it is the differences that
    // carry the degeneracy.
    if x.len() > 1 {
        for (j, &anchor) in x.iter().enumerate() {
            let Some(e) = binary_exponent(anchor) else {
                continue;
            };
            let s = anchor.signum();
            for simple in [s * pow2(e), s, s * pow2(e + 1)] {
                if simple == anchor {
                    continue;
                }
                let y: Vec<f64> = x
                    .iter()
                    .enumerate()
                    .map(|(i, &v)| {
                        if i == j {
                            simple
                        } else {
                            plain_zero(simple + (v - anchor))
                        }
                    })
                    .collect();
                if y.iter().all(|v| v.is_finite()) {
                    c.push(y);
                }
            }
        }
    }
    c
}

fn shrink<E: ExactScalar>(
    formula: &(impl Formula + ?Sized),
    start: &[f64],
    start_ev: &Evaluated,
    options: &Options,
) -> Shrunk {
    let target = start_ev.max_ulps;
    let bad_enough = |ev: &Evaluated| {
        if target.is_infinite() {
            ev.max_ulps.is_infinite()
        } else {
            ev.max_ulps >= options.shrink_fraction * target
        }
    };
    let mut cur = Shrunk {
        inputs: start.to_vec(),
        ev: start_ev.clone(),
        steps: 0,
        evaluations: 0,
    };
    // Tries one candidate; `None` when the budget is spent, else whether it was taken.
    let attempt = |cur: &mut Shrunk, cand: Vec<f64>| -> Option<bool> {
        if cand == cur.inputs || complexity(&cand) >= complexity(&cur.inputs) {
            return Some(false);
        }
        if cur.evaluations >= options.shrink_budget {
            return None;
        }
        cur.evaluations += 1;
        match evaluate::<E>(formula, &cand) {
            Ok(ev) if bad_enough(&ev) => {
                cur.inputs = cand;
                cur.ev = ev;
                cur.steps += 1;
                Some(true)
            }
            _ => Some(false),
        }
    };
    'passes: loop {
        let mut changed = false;
        for cand in global_candidates(&cur.inputs) {
            match attempt(&mut cur, cand) {
                None => break 'passes,
                Some(true) => {
                    changed = true;
                    break;
                }
                Some(false) => {}
            }
        }
        for i in 0..cur.inputs.len() {
            let mut tried: Vec<u64> = Vec::new();
            for v in coordinate_candidates(cur.inputs[i]) {
                if tried.contains(&v.to_bits()) {
                    continue;
                }
                tried.push(v.to_bits());
                let mut cand = cur.inputs.clone();
                cand[i] = v;
                match attempt(&mut cur, cand) {
                    None => break 'passes,
                    Some(true) => {
                        changed = true;
                        break;
                    }
                    Some(false) => {}
                }
            }
        }
        if !changed {
            break;
        }
    }
    cur
}

#[cfg(test)]
mod tests {
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
    fn medians() {
        assert_eq!(median(&[]), 0.0);
        assert_eq!(median(&[3.0]), 3.0);
        assert_eq!(median(&[1.0, 2.0]), 1.5);
        assert_eq!(median(&[1.0, f64::INFINITY]), f64::INFINITY);
        assert_eq!(median(&[f64::INFINITY, f64::INFINITY]), f64::INFINITY);
        assert_eq!(median(&[1.0, 2.0, 9.0]), 2.0);
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
