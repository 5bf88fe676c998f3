//! Merging the shards of a sweep into the report of the whole sweep.
//!
//! Shard `i/N` of a sweep of `S` samples covers the sample indices `[(i-1)S/N, iS/N)` of the
//! seeded stream, so the shards partition the sweep. Counts add up, maxima are maxima, the
//! threshold counts add up; the K worst of the whole sweep are among the K worst of the shards
//! (the order of badness is total: error, then relative error, then sample index), and each was
//! shrunk deterministically from its own inputs, so the merged worst cases are the single run's.
//! Medians, means and bits of error are read from the merged mergeable summaries
//! ([`crate::summary`]), as a single run reads them from its own.

use super::worse;
use crate::convert::ulps_error;
use crate::report::{Case, Report, WorstCase};
use num_rational::BigRational;

/// Why shard reports do not merge.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MergeError(pub String);

impl std::fmt::Display for MergeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for MergeError {}

/// Checks that a report agrees with itself: every sample of its range counted once; the
/// counts of its summaries recounted against `compared`; maxima, threshold counts, medians,
/// means and bits of error read back from the summaries; the worst cases present, in order,
/// inside the range, the first of them the maximum, and each one's error recomputed from its
/// outputs where its exact value is exact. A report `run` wrote passes; an edited one, or one
/// cut short, does not.
///
/// # Errors
/// The first disagreement, one line.
pub fn check_consistent(r: &Report) -> Result<(), String> {
    let covered = r.end_sample.checked_sub(r.first_sample).ok_or_else(|| {
        format!(
            "its sample range {}..{} is empty backwards",
            r.first_sample, r.end_sample
        )
    })?;
    let outcomes = [
        r.compared,
        r.domain_errors,
        r.invalid_inputs,
        r.undecided,
        r.limit_stops,
    ]
    .iter()
    .try_fold(0usize, |a, &b| a.checked_add(b));
    if outcomes != Some(covered) {
        return Err(format!(
            "compared {} + outside the domain {} + invalid {} + undecided {} + stopped by a limit {} is not the {covered} samples it covers",
            r.compared, r.domain_errors, r.invalid_inputs, r.undecided, r.limit_stops
        ));
    }
    if (r.limit_stops == 0) != r.limit_stop.is_empty() {
        return Err(format!(
            "its limit_stops is {} but its limit_stop lists {} limits",
            r.limit_stops,
            r.limit_stop.len()
        ));
    }
    if let Some(w) = r.limit_stop.windows(2).find(|w| w[0].limit >= w[1].limit) {
        return Err(format!(
            "its limit stops {} and {} are not distinct limits sorted by name",
            w[0], w[1]
        ));
    }
    for (what, n) in [("refined", r.refined), ("float failures", r.float_failures)] {
        if n > r.compared {
            return Err(format!("{what} {n} exceed compared {}", r.compared));
        }
    }
    let compared = r.compared as u64;
    let recount = [
        ("ulps", r.summary.ulps.len()),
        ("relative error", r.summary.rel.len()),
        ("bits of error", r.summary.bits.count),
    ];
    for (what, n) in recount {
        if n != compared {
            return Err(format!(
                "its {what} summary holds {n} samples, not the {compared} compared"
            ));
        }
    }
    for (what, v, d) in [
        ("max_ulps", r.max_ulps, &r.summary.ulps),
        ("max_rel", r.max_rel, &r.summary.rel),
    ] {
        if !d.largest_is(v) {
            return Err(format!(
                "{what} {v:?} is not the largest value of its summary ({:?})",
                d.largest()
            ));
        }
    }
    let failures = r.float_failures as u64;
    if failures > r.summary.ulps.infinite() || failures > r.summary.rel.infinite() {
        return Err(format!(
            "{} float failures but fewer infinite errors in its summaries",
            r.float_failures
        ));
    }
    if !(0.0..=64.0).contains(&r.max_bits)
        || (r.compared == 0 && r.max_bits != 0.0)
        || !r.summary.bits.within(r.max_bits)
    {
        return Err(format!(
            "max_bits {:?} does not bound its bits of error (at most 64)",
            r.max_bits
        ));
    }
    if r.compared == 0 && !r.max_ulps_per_output.is_empty() {
        return Err("max_ulps_per_output is not empty with nothing compared".into());
    }
    if let Some(u) = r
        .max_ulps_per_output
        .iter()
        .find(|u| u.is_nan() || **u < 0.0 || **u > r.max_ulps)
    {
        return Err(format!(
            "max_ulps_per_output holds {u:?}, not within 0..=max_ulps {:?}",
            r.max_ulps
        ));
    }
    for t in &r.above {
        let (lo, hi) = r.summary.ulps.count_above(t.ulps);
        let n = t.count as u64;
        if t.ulps.is_nan() || n < lo || n > hi {
            return Err(format!(
                "{} samples above {:?} ulps, but its summary has {}",
                t.count,
                t.ulps,
                if lo == hi {
                    lo.to_string()
                } else {
                    format!("{lo} to {hi}")
                }
            ));
        }
    }
    let mut reread = r.clone();
    reread.refresh_statistics();
    for (what, have, want) in [
        ("median_ulps", r.median_ulps, reread.median_ulps),
        ("mean_ulps", r.mean_ulps, reread.mean_ulps),
        ("median_rel", r.median_rel, reread.median_rel),
        ("bits_of_error", r.bits_of_error, reread.bits_of_error),
    ] {
        if have.to_bits() != want.to_bits() {
            return Err(format!("{what} {have:?} is not its summary's {want:?}"));
        }
    }
    check_worst(r)
}

/// The worst-case part of [`check_consistent`].
fn check_worst(r: &Report) -> Result<(), String> {
    let wanted = r.keep.min(r.compared);
    if r.worst.len() != wanted {
        return Err(format!(
            "{} worst cases, not {wanted} (keep {}, compared {})",
            r.worst.len(),
            r.keep,
            r.compared
        ));
    }
    let key = |w: &WorstCase| (w.original.ulps, w.original.rel, w.index);
    for (k, w) in r.worst.iter().enumerate() {
        if !(r.first_sample..r.end_sample).contains(&w.index) {
            return Err(format!(
                "worst case {} is sample {}, outside {}..{}",
                k + 1,
                w.index,
                r.first_sample,
                r.end_sample
            ));
        }
        if k > 0 && worse(key(&r.worst[k - 1]), key(w)) != std::cmp::Ordering::Less {
            return Err(format!(
                "worst case {} (sample {}) is not worse than the next",
                k,
                r.worst[k - 1].index
            ));
        }
        check_case(&w.original, r)
            .map_err(|why| format!("worst case sample {}: {why}", w.index))?;
    }
    if let Some(w) = r.worst.first() {
        if w.original.ulps.to_bits() != r.max_ulps.to_bits() {
            return Err(format!(
                "the worst case (sample {}) has {:?} ulps, not max_ulps {:?}",
                w.index, w.original.ulps, r.max_ulps
            ));
        }
    }
    Ok(())
}

/// One kept case against its report: its measures within the report's maxima and its error
/// recomputed from its outputs.
fn check_case(c: &Case, r: &Report) -> Result<(), String> {
    let n = c.exact_outputs.len();
    if c.ulps_per_output.len() != n || c.rel_per_output.len() != n {
        return Err(format!(
            "{n} exact outputs but {} ulps and {} relative errors",
            c.ulps_per_output.len(),
            c.rel_per_output.len()
        ));
    }
    let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
    let (ulps, rel) = if c.float_failure {
        (f64::INFINITY, f64::INFINITY)
    } else {
        (max(&c.ulps_per_output), max(&c.rel_per_output))
    };
    if c.ulps.to_bits() != ulps.to_bits() || c.rel.to_bits() != rel.to_bits() {
        return Err(format!(
            "its error {:?} ulps, relative {:?}, is not the largest of its outputs' ({ulps:?}, {rel:?})",
            c.ulps, c.rel
        ));
    }
    if !(c.rel <= r.max_rel && c.bits <= r.max_bits) {
        return Err(format!(
            "relative error {:?} or bits {:?} above the report's maxima",
            c.rel, c.bits
        ));
    }
    if let (false, Some(float)) = (c.float_failure, &c.float_outputs) {
        for (i, (text, &a)) in c.exact_outputs.iter().zip(float).enumerate() {
            // `~` marks a refined approximation of an irrational value: nothing to recompute.
            if text.starts_with('~') {
                continue;
            }
            let q: BigRational = text
                .parse()
                .map_err(|_| format!("exact output {} {text:?} is not a rational", i + 1))?;
            let u = ulps_error(a, &q);
            if u.to_bits() != c.ulps_per_output[i].to_bits() {
                return Err(format!(
                    "output {} is {u:?} ulps from its exact value, not the {:?} recorded",
                    i + 1,
                    c.ulps_per_output[i]
                ));
            }
        }
    }
    Ok(())
}

/// Merges the reports of all `N` shards of one sweep (in any order) into the report a single
/// run of the sweep gives.
///
/// # Errors
/// No report; reports of different sweeps (formula, inputs, arity, samples, seed, kept worst
/// cases, thresholds or shard count differ); a report that is not a shard, a shard given twice,
/// a shard missing, a shard whose sample range is not its part of the sweep, or a shard that
/// disagrees with itself ([`check_consistent`]).
pub fn merge(reports: &[Report]) -> Result<Report, MergeError> {
    let err = |s: String| Err(MergeError(s));
    let Some(first) = reports.first() else {
        return err("no shard report to merge".into());
    };
    let Some(count) = first.shard.map(|s| s.count) else {
        return err("report 1 is not a shard report (it has no shard I/N)".into());
    };
    let mut seen = vec![false; count];
    for (k, r) in reports.iter().enumerate() {
        let same = |what: &str, a: String, b: String| {
            if a == b {
                Ok(())
            } else {
                Err(MergeError(format!(
                    "report {} is of another sweep: {what} {b} (report 1: {a})",
                    k + 1
                )))
            }
        };
        same("formula", first.formula.clone(), r.formula.clone())?;
        same("float side", first.float_side.clone(), r.float_side.clone())?;
        same("precision", first.precision.clone(), r.precision.clone())?;
        same("inputs", first.generator.clone(), r.generator.clone())?;
        same("arity", first.arity.to_string(), r.arity.to_string())?;
        same("samples", first.samples.to_string(), r.samples.to_string())?;
        same("seed", first.seed.to_string(), r.seed.to_string())?;
        same("worst kept", first.keep.to_string(), r.keep.to_string())?;
        let levels =
            |r: &Report| format!("{:?}", r.above.iter().map(|t| t.ulps).collect::<Vec<_>>());
        same("thresholds", levels(first), levels(r))?;
        let Some(s) = r.shard else {
            return err(format!(
                "report {} is not a shard report (it has no shard I/N)",
                k + 1
            ));
        };
        same("shard count", count.to_string(), s.count.to_string())?;
        if seen[s.index - 1] {
            return err(format!("shard {s} is given twice"));
        }
        seen[s.index - 1] = true;
        let range = s.range(r.samples);
        if (r.first_sample, r.end_sample) != (range.start, range.end) {
            return err(format!(
                "shard {s} covers samples {}..{}, not its part {}..{}",
                r.first_sample, r.end_sample, range.start, range.end
            ));
        }
        check_consistent(r)
            .map_err(|why| MergeError(format!("shard {s} is inconsistent: {why}")))?;
    }
    let missing: Vec<String> = seen
        .iter()
        .enumerate()
        .filter(|(_, &s)| !s)
        .map(|(i, _)| format!("{}/{count}", i + 1))
        .collect();
    if !missing.is_empty() {
        return err(format!("shard(s) missing: {}", missing.join(", ")));
    }

    let mut out = first.clone();
    out.shard = None;
    out.first_sample = 0;
    out.end_sample = first.samples;
    out.worst.clear();
    out.summary = Default::default();
    for c in [
        &mut out.compared,
        &mut out.domain_errors,
        &mut out.invalid_inputs,
        &mut out.undecided,
        &mut out.limit_stops,
        &mut out.refined,
        &mut out.float_failures,
    ] {
        *c = 0;
    }
    out.max_ulps = 0.0;
    out.max_rel = 0.0;
    out.max_bits = 0.0;
    out.max_ulps_per_output.clear();
    out.limit_stop.clear();
    out.above.iter_mut().for_each(|t| t.count = 0);
    let mut worst = Vec::new();
    for r in reports {
        out.compared += r.compared;
        out.domain_errors += r.domain_errors;
        out.invalid_inputs += r.invalid_inputs;
        out.undecided += r.undecided;
        out.limit_stops += r.limit_stops;
        for stop in &r.limit_stop {
            if let Some(other) = out
                .limit_stop
                .iter()
                .find(|o| o.limit == stop.limit && o.value != stop.value)
            {
                return err(format!(
                    "shards stopped at different values of the limit {}: {} and {} (run every shard with the same --limit)",
                    stop.limit, other.value, stop.value
                ));
            }
            crate::report::note_limit_stop(&mut out.limit_stop, stop);
        }
        out.refined += r.refined;
        out.float_failures += r.float_failures;
        out.max_ulps = out.max_ulps.max(r.max_ulps);
        out.max_rel = out.max_rel.max(r.max_rel);
        out.max_bits = out.max_bits.max(r.max_bits);
        if out.max_ulps_per_output.len() < r.max_ulps_per_output.len() {
            out.max_ulps_per_output
                .resize(r.max_ulps_per_output.len(), 0.0);
        }
        for (m, &u) in out
            .max_ulps_per_output
            .iter_mut()
            .zip(&r.max_ulps_per_output)
        {
            *m = m.max(u);
        }
        for (t, s) in out.above.iter_mut().zip(&r.above) {
            t.count += s.count;
        }
        out.summary.ulps.merge(&r.summary.ulps);
        out.summary.rel.merge(&r.summary.rel);
        out.summary.bits.merge(&r.summary.bits);
        worst.extend(r.worst.iter().cloned());
    }
    let key = |w: &crate::report::WorstCase| (w.original.ulps, w.original.rel, w.index);
    worst.sort_by(|a, b| worse(key(a), key(b)));
    worst.truncate(out.keep);
    out.worst = worst;
    out.refresh_statistics();
    Ok(out)
}
