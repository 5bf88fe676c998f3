//! Shrinking a kept worst case to a short reproducible one (see the harness's module docs).

use super::{evaluate_one, Evaluated, FloatSideError, Subject};
use crate::convert::{binary_exponent, pow2, round_to_bits, significant_bits, truncate_to_bits};
use crate::gen::InputGen;
use crate::harness::Options;

/// The result of shrinking one case.
pub(super) struct Shrunk {
    pub(super) inputs: Vec<f64>,
    pub(super) ev: Evaluated,
    pub(super) steps: usize,
    pub(super) evaluations: usize,
}

/// The simplicity of an input vector, smaller is simpler: total significant bits, total distance
/// of the binary exponents from 0, number of negative inputs.
pub(super) fn complexity(x: &[f64]) -> (u32, u64, usize) {
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
pub(super) fn coordinate_candidates(x: f64) -> Vec<f64> {
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
pub(super) fn global_candidates(x: &[f64]) -> Vec<Vec<f64>> {
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

/// Shrinks the case of sample `index` (its inputs `start`, its evaluation `start_ev`) within
/// the set `gen` samples ([`InputGen::contains`]): a candidate outside it is never evaluated.
/// (A precondition beyond the sampled set is the exact side's: a candidate outside it is
/// outside the domain and rejected like any undefined one.)
///
/// # Errors
/// A fatal error of the float side (an external program that failed).
pub(super) fn shrink(
    subject: &(impl Subject + ?Sized),
    gen: &(impl InputGen + ?Sized),
    index: usize,
    start: &[f64],
    start_ev: &Evaluated,
    options: &Options,
) -> Result<Shrunk, FloatSideError> {
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
    let attempt = |cur: &mut Shrunk, cand: Vec<f64>| -> Result<Option<bool>, FloatSideError> {
        if cand == cur.inputs
            || complexity(&cand) >= complexity(&cur.inputs)
            || !gen.contains(&cand)
        {
            return Ok(Some(false));
        }
        if cur.evaluations >= options.shrink_budget {
            return Ok(None);
        }
        cur.evaluations += 1;
        Ok(match evaluate_one(subject, index, &cand)? {
            Ok(ev) if bad_enough(&ev) => {
                cur.inputs = cand;
                cur.ev = ev;
                cur.steps += 1;
                Some(true)
            }
            _ => Some(false),
        })
    };
    'passes: loop {
        let mut changed = false;
        for cand in global_candidates(&cur.inputs) {
            match attempt(&mut cur, cand)? {
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
                match attempt(&mut cur, cand)? {
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
    Ok(cur)
}
