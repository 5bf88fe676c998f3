//! The workload `dense-product`: Fateman's dense product `f (f + 1)` with
//! `f = (1 + x_1 + ... + x_v)^k`, the case where packed monomials and machine-word coefficients
//! matter most (`bench/scripts/anchors/dense_product.py` is the same product in python-flint,
//! SymPy and SymEngine). The timed region is the product alone; `f` is built before. Prints its
//! check values as text or as one JSON line with the anchors' field names.

use crate::{Elapsed, Stopwatch};
use exactcheck::args::check_count;
use exactcheck::Error;
use exactcheck_core::Ring;
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::Rational;

/// The largest `--k` (with 4 variables, `f (f + 1)` at k = 30 has 91,881 terms from
/// 2.4 * 10^7 term products per factor pair).
pub const MAX_K: usize = 30;
/// The largest `--vars`.
pub const MAX_VARS: usize = 8;

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

/// Runs the workload.
///
/// # Errors
/// [`Error::Usage`] for `--k` or `--vars` outside their ranges.
pub fn run(k: usize, v: usize, json: bool) -> Result<String, Error> {
    let k = check_count("--k", k, MAX_K, "")? as u32;
    let v = check_count("--vars", v, MAX_VARS, "")?;
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
        // The default size, expanded by SymPy: 4845 terms, largest coefficient 672672000.
        let (_, c) = dense_product(8, 4);
        assert_eq!(c.terms, 4845);
        assert_eq!(c.coeff_sum, "152588281250");
        assert_eq!(c.max_coeff, "672672000");
    }

    #[test]
    fn sizes_outside_the_limits_are_refused() {
        assert!(run(0, 4, true).is_err());
        assert!(run(MAX_K + 1, 4, true).is_err());
        assert!(run(2, MAX_VARS + 1, true).is_err());
    }
}
