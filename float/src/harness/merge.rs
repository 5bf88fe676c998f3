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
use crate::report::Report;

/// Why shard reports do not merge.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MergeError(pub String);

impl std::fmt::Display for MergeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for MergeError {}

/// Merges the reports of all `N` shards of one sweep (in any order) into the report a single
/// run of the sweep gives.
///
/// # Errors
/// No report; reports of different sweeps (formula, inputs, arity, samples, seed, kept worst
/// cases, thresholds or shard count differ); a report that is not a shard, a shard given twice,
/// a shard missing, or a shard whose sample range is not its part of the sweep.
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
        &mut out.refined,
        &mut out.float_failures,
    ] {
        *c = 0;
    }
    out.max_ulps = 0.0;
    out.max_rel = 0.0;
    out.max_bits = 0.0;
    out.max_ulps_per_output.clear();
    out.above.iter_mut().for_each(|t| t.count = 0);
    let mut worst = Vec::new();
    for r in reports {
        out.compared += r.compared;
        out.domain_errors += r.domain_errors;
        out.invalid_inputs += r.invalid_inputs;
        out.undecided += r.undecided;
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
