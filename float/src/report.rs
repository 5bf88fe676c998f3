//! The result of a regression run: plain data with public fields (so the CLI can emit JSON)
//! and a readable `Display`.
//!
//! Exact numbers are kept as strings in the workspace's exact syntax (`n` or `n/d`, lowest
//! terms), so they can be fed back as exact input; their nearest doubles sit beside them.
//! `Display` abbreviates long exact values (a dyadic `n/d` reads `n/2^k`, very long numerals are
//! elided); the fields always hold them in full.

use crate::json::{measure, measures, opt_measures};
use crate::shard::Shard;
use crate::summary::{BitsSum, Distribution};
use serde::{Deserialize, Serialize};
use std::fmt;

/// One compared input vector: the inputs, both evaluations and their errors.
///
/// In JSON, non-finite measures read `"inf"` (JSON has no infinity).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Case {
    /// The inputs as doubles (`Debug` formatting of `f64` round-trips them exactly).
    #[serde(with = "measures")]
    pub inputs: Vec<f64>,
    /// The same inputs as exact rationals, `n` or `n/d`.
    pub inputs_exact: Vec<String>,
    /// The exact outputs, `n` or `n/d`; a value known only as an enclosure (not exact) refined
    /// to a rational approximation reads `~` and 25 significant digits (truncated).
    pub exact_outputs: Vec<String>,
    /// The exact outputs rounded to the nearest values of the report's precision (doubles, or
    /// binary32 values).
    #[serde(with = "measures")]
    pub exact_outputs_f64: Vec<f64>,
    /// The float outputs; `None` when the float evaluation reported a zero divisor.
    #[serde(with = "opt_measures")]
    pub float_outputs: Option<Vec<f64>>,
    /// Each output's error in ulps of the exact value (see [`crate::ulps_error`]).
    #[serde(with = "measures")]
    pub ulps_per_output: Vec<f64>,
    /// Each output's relative error (see [`crate::rel_error`]).
    #[serde(with = "measures")]
    pub rel_per_output: Vec<f64>,
    /// The largest error in ulps over the outputs (infinite for a float failure).
    #[serde(with = "measure")]
    pub ulps: f64,
    /// The largest relative error over the outputs (infinite for a float failure).
    #[serde(with = "measure")]
    pub rel: f64,
    /// Herbie's bits of error, the largest over the outputs (an infinity counted by its ordinal
    /// distance as in Herbie; 64 for a NaN, a zero divisor or a missing output).
    #[serde(with = "measure")]
    pub bits: f64,
    /// Whether the float side failed: a zero divisor, a NaN or infinite output, or a different
    /// number of outputs than the exact side.
    pub float_failure: bool,
}

/// A kept worst case of a run, with its shrunk form.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct WorstCase {
    /// The sample index: [`crate::sample_inputs`]`(gen, seed, index)` regenerates the inputs.
    pub index: usize,
    /// The case as sampled.
    pub original: Case,
    /// The shrunk case (equal to `original` when nothing simpler stayed bad enough); `None`
    /// when shrinking was off or the original error was 0.
    pub shrunk: Option<Case>,
    /// How many simplifications were accepted.
    pub shrink_steps: usize,
    /// How many candidate inputs were evaluated while shrinking.
    pub shrink_evaluations: usize,
    /// Where the error of the sample comes from (formulas and FPCore programs only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub explanation: Option<Explanation>,
}

/// One operation's local error: its bits of error when fed the exact values of its operands
/// rounded to doubles, against the exact value of the subexpression it computes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct OperationError {
    /// The operation (`subtraction`, `square root`, ...).
    pub operation: String,
    /// The subexpression it computes.
    pub at: String,
    /// Herbie's bits of error of the operation alone.
    #[serde(with = "measure")]
    pub bits: f64,
}

/// Where the error of one sample comes from: the operations that lose bits when fed exact
/// operands (local error), and the relative condition number of the exact function there.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Explanation {
    /// The output explained (the one with the largest error), 0-based.
    pub output: usize,
    /// Herbie's bits of error of that output at the sample.
    #[serde(with = "measure")]
    pub bits: f64,
    /// The operations losing more than [`Explanation::DOMINANT_BITS`] bits, most first (at most
    /// three); empty when none does.
    pub operations: Vec<OperationError>,
    /// Why the local errors were not computed (an external program as the float side, or an
    /// undecided exact value), when they were not.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub operations_note: Option<String>,
    /// The relative condition number `sum_i |x_i df/dx_i / f|` of the output, from the exact
    /// derivative; `None` when it is undefined (see `condition_note`).
    #[serde(with = "opt_measure", default)]
    pub condition: Option<f64>,
    /// Why there is no condition number, when there is none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub condition_note: Option<String>,
}

impl Explanation {
    /// An operation losing more bits than this is named; a correctly rounded operation loses
    /// at most 1 (one double away).
    pub const DOMINANT_BITS: f64 = 2.0;

    /// The bits a result of this conditioning is expected to lose: `log2(cond)`, 0 below 1.
    pub fn expected_bits(&self) -> Option<f64> {
        self.condition.map(|c| c.max(1.0).log2())
    }

    /// The verdict on conditioning against the algorithm, one sentence.
    pub fn verdict(&self) -> String {
        let lost = self.bits;
        let Some(c) = self.condition else {
            let why = self.condition_note.as_deref().unwrap_or("undefined");
            return format!(
                "no condition number ({why}); the result loses {} bits",
                fmt_bits(lost)
            );
        };
        let expect = self.expected_bits().unwrap_or(0.0);
        // Within a few bits of what the conditioning predicts: the problem's, not the code's.
        let margin = 3.0;
        if expect < margin {
            if lost <= Self::DOMINANT_BITS {
                format!("well-conditioned (cond {}) and accurate here", fmt_cond(c))
            } else {
                format!(
                    "well-conditioned (cond {}): the algorithm loses {} bits",
                    fmt_cond(c),
                    fmt_bits(lost)
                )
            }
        } else if lost <= expect + margin {
            format!(
                "ill-conditioned here (cond ~ {}, expect ~{} bits lost): the loss is the problem's, not the algorithm's",
                fmt_cond(c),
                fmt_bits(expect)
            )
        } else {
            format!(
                "conditioning (cond ~ {}) accounts for ~{} bits: the algorithm loses {} bits more",
                fmt_cond(c),
                fmt_bits(expect),
                fmt_bits(lost - expect)
            )
        }
    }

    /// The local-error sentence.
    pub fn local(&self) -> String {
        if let Some(note) = &self.operations_note {
            return format!("local error not computed: {note}");
        }
        if self.operations.is_empty() {
            return format!(
                "no dominant loss: no operation fed exact operands loses more than {} bits",
                fmt_bits(Self::DOMINANT_BITS)
            );
        }
        let parts: Vec<String> = self
            .operations
            .iter()
            .map(|o| {
                format!(
                    "the {} in {} loses {} bits",
                    o.operation,
                    o.at,
                    fmt_bits(o.bits)
                )
            })
            .collect();
        parts.join("; ")
    }
}

/// Bits for humans: one decimal, none when whole.
fn fmt_bits(b: f64) -> String {
    let s = format!("{b:.1}");
    s.strip_suffix(".0").map_or(s.clone(), str::to_string)
}

/// A condition number for humans: 3 significant digits in a middle range, else `1e15`.
fn fmt_cond(c: f64) -> String {
    if c == 0.0 {
        "0".into()
    } else if (1e-3..1e4).contains(&c) {
        let s = format!("{c:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{c:.0e}")
    }
}

/// `Option<f64>` as a measure or `null`.
mod opt_measure {
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
        match v {
            Some(x) => crate::json::measure::serialize(x, s),
            None => s.serialize_none(),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
        #[derive(Deserialize)]
        struct Wrap(#[serde(with = "crate::json::measure")] f64);
        Ok(Option::<Wrap>::deserialize(d)?.map(|w| w.0))
    }
}

/// How many compared samples exceeded an error level.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ThresholdCount {
    /// The level, in ulps.
    #[serde(with = "measure")]
    pub ulps: f64,
    /// The number of compared samples whose error is strictly greater.
    pub count: usize,
}

/// The mergeable summaries behind a report's medians and means ([`crate::summary`]).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    /// The errors in ulps.
    pub ulps: Distribution,
    /// The relative errors.
    pub rel: Distribution,
    /// Herbie's bits of error.
    pub bits: BitsSum,
}

/// The result of [`crate::regress`] / [`crate::run`], of one shard or of a whole sweep.
///
/// A sample's error is the largest over its outputs. Statistics are over the compared samples
/// (float failures included, with infinite error) and read 0 when none was compared. Medians
/// and means are read from [`Report::summary`] (exact up to [`crate::summary::EXACT_DISTINCT`]
/// distinct values, then to 8 mantissa bits), so shards merge into the whole.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Report {
    /// The formula's name.
    pub formula: String,
    /// What computed the float results ([`crate::Subject::float_side`]): shards of one sweep
    /// share it, and `merge` refuses shards whose float sides differ.
    pub float_side: String,
    /// The generator's description.
    pub generator: String,
    /// The format the float side computes in and the errors are measured in: `binary64` or
    /// `binary32` (ulps and Herbie's bits of that format).
    #[serde(default = "binary64")]
    pub precision: String,
    /// The number of inputs.
    pub arity: usize,
    /// The number of samples of the whole sweep.
    pub samples: usize,
    /// The seed of the run.
    pub seed: u64,
    /// The part of the sweep this report covers (`None`: all of it).
    #[serde(with = "shard_text")]
    pub shard: Option<Shard>,
    /// The first sample index covered.
    pub first_sample: usize,
    /// One past the last sample index covered.
    pub end_sample: usize,
    /// How many worst cases were kept at most.
    pub keep: usize,
    /// Samples evaluated on both sides and compared.
    pub compared: usize,
    /// Samples skipped because the exact evaluation reported a zero divisor (outside the domain).
    pub domain_errors: usize,
    /// Samples skipped because the generator gave a wrong number of inputs or a non-finite one.
    pub invalid_inputs: usize,
    /// Samples skipped because the exact side could not decide a sign up to its precision cap
    /// (or an exact intermediate exceeded its size limit).
    pub undecided: usize,
    /// Samples whose exact evaluation ran past a limit on its work ([`Report::limit_stop`]).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub limit_stops: usize,
    /// The limits that stopped them, one per distinct limit, sorted by name; in JSON an array
    /// of `{"limit": NAME, "value": N}` (left out when empty).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub limit_stop: Vec<LimitStop>,
    /// Compared samples whose reference is not exact: an enclosure of the true value (behind an
    /// irrational root, a function or a loop carried as an enclosure), refined until its
    /// rounding is decided.
    pub refined: usize,
    /// Compared samples where the float side failed (infinite error).
    pub float_failures: usize,
    /// The largest error in ulps.
    #[serde(with = "measure")]
    pub max_ulps: f64,
    /// The median error in ulps (the mean of the two middle values for an even count).
    #[serde(with = "measure")]
    pub median_ulps: f64,
    /// The mean error in ulps over the samples with a finite error.
    #[serde(with = "measure")]
    pub mean_ulps: f64,
    /// The largest relative error.
    #[serde(with = "measure")]
    pub max_rel: f64,
    /// The median relative error.
    #[serde(with = "measure")]
    pub median_rel: f64,
    /// The mean of Herbie's bits of error (`log2(1 + n)`, `n` the doubles between the float
    /// result and the correctly rounded exact value, the infinities counted as the doubles past
    /// `±f64::MAX`; 64 for a NaN, a zero divisor or a missing output), as Herbie reports a
    /// benchmark's error.
    #[serde(with = "measure")]
    pub bits_of_error: f64,
    /// The largest bits of error.
    #[serde(with = "measure")]
    pub max_bits: f64,
    /// The largest error in ulps of each output separately.
    #[serde(with = "measures")]
    pub max_ulps_per_output: Vec<f64>,
    /// The number of samples above each of [`crate::Options::thresholds`].
    pub above: Vec<ThresholdCount>,
    /// The worst cases, worst first (larger ulps error, then larger relative error, then the
    /// earlier sample).
    pub worst: Vec<WorstCase>,
    /// The mergeable summaries the medians and means are read from (in JSON only in shard
    /// reports, where `merge` needs them).
    #[serde(default)]
    pub summary: Summary,
}

impl Report {
    /// Recomputes the medians, the mean and the bits of error from [`Report::summary`].
    pub fn refresh_statistics(&mut self) {
        self.median_ulps = self.summary.ulps.median();
        self.mean_ulps = self.summary.ulps.mean_finite();
        self.median_rel = self.summary.rel.median();
        self.bits_of_error = self.summary.bits.mean();
    }

    /// The report as JSON (non-finite measures as `"inf"`); the summaries only in a shard's
    /// report (up to 65,536 values each: what `merge` needs, noise elsewhere).
    pub fn to_json(&self) -> serde_json::Value {
        let mut v = serde_json::to_value(self).expect("a report serialises to JSON");
        if self.shard.is_none() {
            if let Some(o) = v.as_object_mut() {
                o.remove("summary");
            }
        }
        v
    }
}

/// `Option<Shard>` as `"I/N"` or `null`.
mod shard_text {
    use super::Shard;
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &Option<Shard>, s: S) -> Result<S::Ok, S::Error> {
        match v {
            Some(sh) => s.serialize_str(&sh.to_string()),
            None => s.serialize_none(),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Shard>, D::Error> {
        Option::<String>::deserialize(d)?
            .map(|t| t.parse().map_err(serde::de::Error::custom))
            .transpose()
    }
}

/// An error measure for humans: `inf`, plain decimals in a middle range, scientific otherwise.
pub(crate) fn fmt_measure(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else if v.is_infinite() {
        if v > 0.0 { "inf" } else { "-inf" }.into()
    } else if v == 0.0 {
        "0".into()
    } else if (1e-3..1e5).contains(&v.abs()) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.3e}")
    }
}

/// An exact value for humans: `n/2^k` for dyadic denominators, long numerals elided.
fn fmt_exact(s: &str) -> String {
    if s.starts_with('~') {
        return s.to_string();
    }
    fn elide(digits: &str) -> String {
        const KEEP: usize = 12;
        let n = digits.trim_start_matches('-').len();
        if n <= 2 * KEEP + 6 {
            digits.to_string()
        } else {
            format!(
                "{}...{}[{n} digits]",
                &digits[..KEEP + usize::from(digits.starts_with('-'))],
                &digits[digits.len() - KEEP..]
            )
        }
    }
    match s.split_once('/') {
        None => elide(s),
        Some((n, d)) => {
            let d_big = d.parse::<num_bigint::BigUint>().ok();
            let pow = d_big.as_ref().and_then(|b| {
                let k = b.trailing_zeros()?;
                (b.count_ones() == 1 && k > 10).then_some(k)
            });
            match pow {
                Some(k) => format!("{}/2^{k}", elide(n)),
                None => format!("{}/{}", elide(n), elide(d)),
            }
        }
    }
}

fn list(items: impl IntoIterator<Item = String>) -> String {
    let v: Vec<String> = items.into_iter().collect();
    format!("[{}]", v.join(", "))
}

fn write_case(f: &mut fmt::Formatter<'_>, c: &Case, indent: &str) -> fmt::Result {
    writeln!(
        f,
        "{indent}inputs        {}",
        list(c.inputs.iter().map(|x| format!("{x:?}")))
    )?;
    writeln!(
        f,
        "{indent}  exactly     {}",
        list(c.inputs_exact.iter().map(|s| fmt_exact(s)))
    )?;
    writeln!(
        f,
        "{indent}exact output  {}",
        list(c.exact_outputs.iter().map(|s| fmt_exact(s)))
    )?;
    writeln!(
        f,
        "{indent}  nearest     {}",
        list(c.exact_outputs_f64.iter().map(|x| format!("{x:?}")))
    )?;
    match &c.float_outputs {
        Some(v) => writeln!(
            f,
            "{indent}float output  {}",
            list(v.iter().map(|x| format!("{x:?}")))
        ),
        None => writeln!(f, "{indent}float output  (division by zero)"),
    }
}

impl fmt::Display for WorstCase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let o = &self.original;
        writeln!(
            f,
            "sample {}: {} ulps, relative {}{}",
            self.index,
            fmt_measure(o.ulps),
            fmt_measure(o.rel),
            if o.float_failure {
                " (float failure)"
            } else {
                ""
            }
        )?;
        write_case(f, o, "    ")?;
        if let Some(s) = &self.shrunk {
            let bits: u32 = s
                .inputs
                .iter()
                .map(|&x| crate::convert::significant_bits(x))
                .sum();
            writeln!(
                f,
                "  shrunk ({} steps, {} evaluations, {bits} significant bits in all): {} ulps, relative {}{}",
                self.shrink_steps,
                self.shrink_evaluations,
                fmt_measure(s.ulps),
                fmt_measure(s.rel),
                if s.float_failure { " (float failure)" } else { "" }
            )?;
            write_case(f, s, "    ")?;
        }
        if let Some(e) = &self.explanation {
            let which = if e.output > 0 || self.original.exact_outputs.len() > 1 {
                format!(" (output {})", e.output + 1)
            } else {
                String::new()
            };
            writeln!(
                f,
                "  explained at sample {}{which}: {} bits lost",
                self.index,
                fmt_bits(e.bits)
            )?;
            writeln!(f, "    local error: {}", e.local())?;
            writeln!(f, "    conditioning: {}", e.verdict())?;
        }
        Ok(())
    }
}

impl Report {
    /// The number of samples this report covers (its shard's, or the whole sweep's).
    fn covered(&self) -> usize {
        self.end_sample.saturating_sub(self.first_sample)
    }
}

/// The precision of a report read without one: every report before binary32 was binary64.
fn binary64() -> String {
    "binary64".into()
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.precision == "binary64" {
            writeln!(f, "regress `{}` ({} inputs)", self.formula, self.arity)?;
        } else {
            // Only a precision other than the default is named, on the title line, and the
            // measures below are in its units.
            writeln!(
                f,
                "regress `{}` ({} inputs, in {}: errors in {} ulps and bits)",
                self.formula, self.arity, self.precision, self.precision
            )?;
        }
        writeln!(f, "  inputs: {}", self.generator)?;
        let covered = match self.shard {
            Some(s) => format!(
                "shard {s}: samples {}..{} of {}",
                self.first_sample, self.end_sample, self.samples
            ),
            None => format!("{} samples", self.samples),
        };
        write!(
            f,
            "  {covered}, seed {}: {} compared, {} outside the exact domain, {} float failures, {} invalid inputs",
            self.seed,
            self.compared,
            self.domain_errors,
            self.float_failures,
            self.invalid_inputs
        )?;
        if self.undecided > 0 {
            write!(f, ", {} undecided", self.undecided)?;
        }
        if self.limit_stops > 0 {
            let names: Vec<String> = self.limit_stop.iter().map(ToString::to_string).collect();
            write!(
                f,
                ", {} stopped by the limit{} {}",
                self.limit_stops,
                if names.len() > 1 { "s" } else { "" },
                if names.is_empty() {
                    "of the exact side".to_string()
                } else {
                    names.join(", ")
                }
            )?;
        }
        writeln!(f)?;
        if self.refined > 0 {
            writeln!(
                f,
                "  {} compared samples have a reference that is not exact: an enclosure of the true value, refined until its rounding is decided",
                self.refined
            )?;
        }
        if self.compared == 0 && self.undecided > 0 && self.undecided == self.covered() {
            // Say why: the exact side gave up on every sample at its precision cap (or size
            // limit), never a guess.
            writeln!(
                f,
                "  no sample was compared: the exact side left every sample undecided, no sign or rounding decided within its precision cap of {} bits (the exact value cancels more bits than that, or may be exactly zero) or an exact intermediate beyond the limit {}",
                exactcheck_exact::program::MAX_PRECISION,
                exactcheck_core::limits::CONSTANT_BITS.name()
            )?;
        } else if self.compared == 0 {
            // No measure is an error of 0: say that nothing was measured.
            writeln!(f, "  no sample was compared: no error was measured")?;
        } else {
            writeln!(
                f,
                "  error in ulps: max {}, median {}, mean {} (finite errors)",
                fmt_measure(self.max_ulps),
                fmt_measure(self.median_ulps),
                fmt_measure(self.mean_ulps)
            )?;
            if self.max_ulps_per_output.len() > 1 {
                writeln!(
                    f,
                    "  max ulps per output: {} (a sample's error is the worst over its {} outputs)",
                    list(self.max_ulps_per_output.iter().map(|&u| fmt_measure(u))),
                    self.max_ulps_per_output.len()
                )?;
            }
            writeln!(
                f,
                "  relative error: max {}, median {}",
                fmt_measure(self.max_rel),
                fmt_measure(self.median_rel)
            )?;
            writeln!(
                f,
                "  bits of error (Herbie's measure): mean {}, max {}",
                fmt_measure(self.bits_of_error),
                fmt_measure(self.max_bits)
            )?;
            if !self.above.is_empty() {
                let parts: Vec<String> = self
                    .above
                    .iter()
                    .map(|t| {
                        let pct = if self.compared == 0 {
                            0.0
                        } else {
                            100.0 * t.count as f64 / self.compared as f64
                        };
                        format!("> {} ulps: {} ({pct:.1}%)", fmt_measure(t.ulps), t.count)
                    })
                    .collect();
                writeln!(f, "  {}", parts.join(", "))?;
            }
        }
        if !self.worst.is_empty() {
            writeln!(
                f,
                "  worst {} (inputs reproducible with sample_inputs(gen, {}, sample)):",
                self.worst.len(),
                self.seed
            )?;
            for (i, w) in self.worst.iter().enumerate() {
                write!(f, "  {}. {w}", i + 1)?;
            }
        }
        Ok(())
    }
}

/// Whether a count is zero (a field left out of the JSON when it is).
fn is_zero(n: &usize) -> bool {
    *n == 0
}

/// A limit on the work of one sample that stopped samples of a sweep: its name and the value in
/// force (`loop-iterations = 10000`, as it prints).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct LimitStop {
    /// The limit's name (`loop-iterations`).
    pub limit: String,
    /// Its value in force.
    pub value: u64,
}

impl fmt::Display for LimitStop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}", self.limit, self.value)
    }
}

/// Adds `stop` to the distinct limit stops `into`, kept sorted (by name, then value).
pub(crate) fn note_limit_stop(into: &mut Vec<LimitStop>, stop: &LimitStop) {
    if let Err(at) = into.binary_search(stop) {
        into.insert(at, stop.clone());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_read_well() {
        assert_eq!(fmt_measure(f64::INFINITY), "inf");
        assert_eq!(fmt_measure(0.0), "0");
        assert_eq!(fmt_measure(0.5), "0.5");
        assert_eq!(fmt_measure(12.0), "12");
        assert_eq!(fmt_measure(8589934592.0), "8.590e9");
        assert_eq!(fmt_measure(1.1e-16), "1.100e-16");
    }

    #[test]
    fn exact_values_read_well() {
        assert_eq!(fmt_exact("3/4"), "3/4");
        assert_eq!(fmt_exact("-7"), "-7");
        assert_eq!(fmt_exact("5/4096"), "5/2^12");
        let long = format!("-{}", "9".repeat(40));
        assert_eq!(fmt_exact(&long), "-999999999999...999999999999[40 digits]");
        let d = num_bigint::BigUint::from(1u8) << 100usize;
        assert_eq!(fmt_exact(&format!("1/{d}")), "1/2^100");
        assert_eq!(fmt_exact("1/3"), "1/3");
    }

    #[test]
    fn limit_stops_keep_each_limit_once_sorted_by_name() {
        let stop = |limit: &str, value| LimitStop {
            limit: limit.to_string(),
            value,
        };
        let mut stops = Vec::new();
        note_limit_stop(&mut stops, &stop("loop-value-bits", 64));
        note_limit_stop(&mut stops, &stop("loop-iterations", 300));
        note_limit_stop(&mut stops, &stop("loop-value-bits", 64));
        assert_eq!(
            stops,
            vec![stop("loop-iterations", 300), stop("loop-value-bits", 64)]
        );
        assert_eq!(stops[0].to_string(), "loop-iterations = 300");
        assert_eq!(
            serde_json::to_value(&stops).expect("JSON"),
            serde_json::json!([
                {"limit": "loop-iterations", "value": 300},
                {"limit": "loop-value-bits", "value": 64}
            ])
        );
    }
}
