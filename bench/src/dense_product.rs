//! `exactcheck bench w1` and `exactcheck bench dense`: polynomial expansion.
//!
//! * **W1** is Chiang's ruled-surface/plane theorem proved by expansion, built with the `Ring`
//!   API exactly as `scripts/anchors/w1_identity.py` builds it for every tool (Bernstein forms,
//!   products and sums over `Poly<Rational>`; [`exactcheck_exact::w1::ring_identity`]); the
//!   timed region is build plus expansion plus the zero test, the anchors' `total_s`.
//! * **dense** is Fateman's dense product `f (f + 1)` with `f = (1 + x_1 + ... + x_v)^k`, the
//!   case where packed monomials and machine-word coefficients matter most
//!   (`scripts/anchors/w1_dense.py` is the same product in python-flint, SymPy and SymEngine).
//!   The timed region is the product alone; `f` is built before.
//!
//! Both print their check values as text or as one JSON line with the anchors' field names.

use super::{Elapsed, Stopwatch};
use crate::args::check_count;
use crate::Error;
use exactcheck_core::Ring;
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::w1::ring_identity;
use exactcheck_exact::Rational;

/// The largest `m + n` of `bench w1` (binomials stay far inside `i64`; (13, 21) takes well under
/// a second, and the expansion grows about as `(m + n)^3`).
pub const MAX_W1_DEGREE: u32 = 48;
/// The largest `--k` of `bench dense` (with 4 variables, `f (f + 1)` at k = 30 has 91,881 terms
/// from 2.4 * 10^7 term products per factor pair).
pub const MAX_DENSE_K: usize = 30;
/// The largest `--vars` of `bench dense`.
pub const MAX_DENSE_VARS: usize = 8;

/// Runs `bench w1` at degrees `(m, n)`.
///
/// # Errors
/// [`Error::Usage`] when `m` or `n` is zero or `m + n` exceeds [`MAX_W1_DEGREE`].
pub fn bench_w1(m: u32, n: u32, negative: bool, json: bool) -> Result<String, Error> {
    let m = check_count("--m", m as usize, MAX_W1_DEGREE as usize - 1, "")? as u32;
    let n = check_count("--n", n as usize, MAX_W1_DEGREE as usize - 1, "")? as u32;
    if m + n > MAX_W1_DEGREE {
        return Err(Error::Usage(format!(
            "--m {m} and --n {n}: m + n must be at most {MAX_W1_DEGREE}"
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
            "W1 (Chiang's ruled-surface/plane theorem by expansion), m = {m}, n = {n}{}\n  variables: {}, expanded x-component LHS: {} terms\n  x-component residual: {}\n  weight residual: {}\n  time: {:.2} ms",
            if negative { ", phi(0, 0) perturbed by 1/7" } else { "" },
            w.variables,
            w.lhs_x_terms,
            verdict(x_zero),
            verdict(weight_zero),
            seconds * 1e3
        )
    })
}

/// The check values of a dense product: its number of terms, the sum of its coefficients (its
/// value at `(1, ..., 1)`) and its largest coefficient, both in decimal.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DenseChecks {
    /// Number of terms.
    pub terms: usize,
    /// Sum of the coefficients.
    pub coeff_sum: String,
    /// Largest coefficient.
    pub max_coeff: String,
}

/// `f (f + 1)` with `f = (1 + x_1 + ... + x_v)^k`, timed (the product only), with its checks.
pub fn dense_product(k: u32, v: usize) -> (Elapsed, DenseChecks) {
    type P = Poly<Rational>;
    let mut vars = Vars::new();
    let mut f = P::one();
    for i in 0..v {
        f += vars.poly::<Rational>(&format!("x{}", i + 1));
    }
    let f = f.pow(k);
    let g = &f + &P::one();
    let watch = Stopwatch::start();
    let h = &f * &g;
    let elapsed = watch.elapsed();
    let mut sum = Rational::zero();
    let mut max: Option<&Rational> = None;
    for c in h.coefficients() {
        sum += c;
        if max.is_none_or(|m| c > m) {
            max = Some(c);
        }
    }
    let checks = DenseChecks {
        terms: h.len(),
        coeff_sum: sum.to_string(),
        max_coeff: max.map_or_else(|| "0".into(), ToString::to_string),
    };
    (elapsed, checks)
}

/// Runs `bench dense`.
///
/// # Errors
/// [`Error::Usage`] for `--k` or `--vars` outside their ranges.
pub fn bench_dense(k: usize, v: usize, json: bool) -> Result<String, Error> {
    let k = check_count("--k", k, MAX_DENSE_K, "")? as u32;
    let v = check_count("--vars", v, MAX_DENSE_VARS, "")?;
    let (Elapsed { wall: seconds, cpu }, c) = dense_product(k, v);
    Ok(if json {
        format!(
            "{{\"tool\": \"exactcheck\", \"k\": {k}, \"vars\": {v}, \"seconds\": {seconds}, \"cpu_seconds\": {cpu}, \"terms\": {}, \"coeff_sum\": \"{}\", \"max_coeff\": \"{}\"}}",
            c.terms, c.coeff_sum, c.max_coeff
        )
    } else {
        format!(
            "dense product f (f + 1), f = (1 + x1 + ... + x{v})^{k}\n  terms: {}\n  sum of coefficients: {}\n  largest coefficient: {}\n  time: {:.2} ms",
            c.terms,
            c.coeff_sum,
            c.max_coeff,
            seconds * 1e3
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dense_checks_match_closed_forms() {
        // f(1,...,1) = (v + 1)^k, so the coefficient sum of f (f + 1) is 5^4 (5^4 + 1).
        let (_, c) = dense_product(4, 4);
        assert_eq!(c.terms, 495); // monomials of total degree <= 8 in 4 variables: C(12, 4)
        assert_eq!(c.coeff_sum, (625u64 * 626).to_string());
        // (1 + x + y)^2 ((1 + x + y)^2 + 1), expanded by SymPy: 15 terms, largest coefficient 14.
        let (_, c) = dense_product(2, 2);
        assert_eq!(c.terms, 15);
        assert_eq!(c.coeff_sum, (9u64 * 10).to_string());
        assert_eq!(c.max_coeff, "14");
        // The size, expanded by SymPy: 4845 terms, largest coefficient 672672000.
        let (_, c) = dense_product(8, 4);
        assert_eq!(c.terms, 4845);
        assert_eq!(c.coeff_sum, "152588281250");
        assert_eq!(c.max_coeff, "672672000");
    }

    #[test]
    fn w1_reports_proved_and_the_negative_not() {
        let text = bench_w1(2, 3, false, true).expect("valid sizes");
        assert!(text.contains("\"x_identity_zero\": true, \"weight_identity_zero\": true"));
        let text = bench_w1(2, 3, true, true).expect("valid sizes");
        assert!(text.contains("\"x_identity_zero\": false, \"weight_identity_zero\": false"));
        assert!(bench_w1(30, 30, false, true).is_err());
        assert!(bench_w1(0, 3, false, true).is_err());
    }
}
