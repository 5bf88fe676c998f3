//! The workload `chiang-identity`: Chiang's ruled-surface/plane theorem proved by expansion, a
//! sparse polynomial identity, built with the `Ring` API exactly as
//! `bench/scripts/anchors/chiang_identity.py` builds it for every tool (Bernstein forms,
//! products and sums over `Poly<Rational>`; [`ring_identity`]); the timed region is build plus
//! expansion plus the zero test, the anchors' `total_s`. [`identity_text`] is the same identity
//! as text (`bench/scripts/anchors/chiang_text.py`), the input of the whole `exactcheck prove`
//! path in the criterion benchmark `poly`.
//!
//! Prints its check values as text or as one JSON line with the anchors' field names.

mod ring;
#[cfg(test)]
mod tests;
mod text;

pub use ring::{ring_identity, ring_residuals, RingIdentity};
pub use text::identity_text;

use crate::{Elapsed, Stopwatch};
use exactcheck::args::check_count;
use exactcheck::Error;
use exactcheck_core::Ring;

/// The largest `m + n` (binomials stay far inside `i64`; (13, 21) takes well under a second, and
/// the expansion grows about as `(m + n)^3`).
pub const MAX_DEGREE: u32 = 48;

/// Runs the workload at degrees `(m, n)`.
///
/// # Errors
/// [`Error::Usage`] when `m` or `n` is zero or `m + n` exceeds [`MAX_DEGREE`].
pub fn run(m: u32, n: u32, negative: bool, json: bool) -> Result<String, Error> {
    let m = check_count("--m", m as usize, MAX_DEGREE as usize - 1, "")? as u32;
    let n = check_count("--n", n as usize, MAX_DEGREE as usize - 1, "")? as u32;
    if m + n > MAX_DEGREE {
        return Err(Error::Usage(format!(
            "--m {m} and --n {n}: m + n must be at most {MAX_DEGREE}"
        )));
    }
    let watch = Stopwatch::start();
    let w = ring_identity(m, n, negative);
    let (x_zero, weight_zero) = (w.x_residual.is_zero(), w.weight_residual.is_zero());
    let Elapsed { wall: seconds, cpu } = watch.elapsed();
    Ok(if json {
        format!(
            "{{\"tool\": \"exactcheck\", \"m\": {m}, \"n\": {n}, \"negative\": {negative}, \"nvars\": {}, \"lhs_x_terms\": {}, \"total_s\": {seconds}, \"cpu_seconds\": {cpu}, \"x_identity_zero\": {x_zero}, \"weight_identity_zero\": {weight_zero}}}",
            w.variables, w.lhs_x_terms
        )
    } else {
        let verdict = |zero: bool| if zero { "zero (proved)" } else { "not zero" };
        format!(
            "chiang-identity (Chiang's ruled-surface/plane theorem by expansion), m = {m}, n = {n}{}\n  variables: {}, expanded x-component LHS: {} terms\n  x-component residual: {}\n  weight residual: {}\n  time: {:.2} ms",
            if negative { ", phi(0, 0) perturbed by 1/7" } else { "" },
            w.variables,
            w.lhs_x_terms,
            verdict(x_zero),
            verdict(weight_zero),
            seconds * 1e3
        )
    })
}
