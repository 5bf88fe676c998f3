//! The workload `real-roots`: exact real root isolation. All real roots of one of the
//! benchmark's polynomials ([`exactcheck_exact::univariate::bench_instances`]: Wilkinson products, SplitMix64
//! random polynomials, Mignotte polynomials), each in an interval of width at most `2^-53`, by
//! Descartes' rule with Newton refinement ([`exactcheck_exact::univariate::integer_real_roots_to`]).
//! The timed region is the anchors' (`bench/scripts/anchors/real_roots.py`): from the integer
//! coefficients to the final sorted list, after the same untimed warm-up as the anchors (the
//! roots of `x^2 - 2`: at a tenth of a millisecond, the first execution of the code, with cold
//! caches and first-touch page faults, would otherwise cost as much as the isolation). The JSON
//! line carries the intervals as exact rationals.

use crate::{Elapsed, Stopwatch};
use clap::ValueEnum;
use exactcheck::args::check_count;
use exactcheck::Error;
use exactcheck_core::Ring;
use exactcheck_exact::univariate::bench_instances::{self, Family, MAX_BENCH_DEGREE};
use exactcheck_exact::univariate::RootInterval;
use exactcheck_exact::Rational;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

/// The families of polynomials on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum RootFamily {
    /// `prod_{j=1..n} (n x - j)`.
    Wilkinson,
    /// SplitMix64 coefficients from the state `d` as signed 64-bit integers.
    Random,
    /// `x^n - 2 (10 x - 1)^2`.
    Mignotte,
}

impl From<RootFamily> for Family {
    fn from(f: RootFamily) -> Family {
        match f {
            RootFamily::Wilkinson => Family::Wilkinson,
            RootFamily::Random => Family::Random,
            RootFamily::Mignotte => Family::Mignotte,
        }
    }
}

/// Runs the workload.
///
/// # Errors
/// [`Error::Usage`] when the degree is 0 or above [`MAX_BENCH_DEGREE`].
pub fn run(family: RootFamily, degree: usize, json: bool) -> Result<String, Error> {
    let degree = check_count("--degree", degree, MAX_BENCH_DEGREE, "")?;
    let family = Family::from(family);
    let coeffs = family.polynomial(degree);
    let warm_up = bench_instances::solve(&[BigInt::from(-2), BigInt::zero(), BigInt::one()]);
    debug_assert_eq!(warm_up.len(), 2);
    let watch = Stopwatch::start();
    let roots = bench_instances::solve(&coeffs);
    let Elapsed { wall: seconds, cpu } = watch.elapsed();
    let name = family.name();
    Ok(if json {
        let list: Vec<String> = roots
            .iter()
            .map(|r| format!("[\"{}\", \"{}\"]", r.lo, r.hi))
            .collect();
        format!(
            "{{\"tool\": \"exactcheck\", \"version\": \"{}\", \"family\": \"{name}\", \"degree\": {degree}, \"seconds\": {seconds}, \"cpu_seconds\": {cpu}, \"real_roots\": {}, \"roots\": [{}]}}",
            env!("CARGO_PKG_VERSION"),
            roots.len(),
            list.join(", ")
        )
    } else {
        let mut s = format!(
            "real-roots (to width 2^-53), family {name}, degree {degree}: {} real roots\n",
            roots.len()
        );
        for r in &roots {
            s += &format!("  {}\n", describe(r));
        }
        s + &format!("  time: {:.3} ms", seconds * 1e3)
    })
}

/// `floor(x 10^k)` as a decimal string with `k` digits after the point.
fn decimal(x: &Rational, k: usize) -> String {
    let scaled = x.numer() * BigInt::from(10u32).pow(k as u32);
    let v = scaled.div_floor(&x.denom());
    let (neg, digits) = (
        v.sign() == num_bigint::Sign::Minus,
        v.magnitude().to_string(),
    );
    let digits = format!("{digits:0>width$}", width = k + 1);
    let (int, frac) = digits.split_at(digits.len() - k);
    format!("{}{int}.{frac}", if neg { "-" } else { "" })
}

/// A root as a decimal: the interval's lower end with as many digits as its width resolves
/// (at least 16), or the exact value.
fn describe(r: &RootInterval) -> String {
    if r.is_exact() {
        return format!("{} (exact: {})", decimal(&r.lo, 16), r.lo);
    }
    let w = r.width();
    let mut k = 16;
    let mut ten_k = Rational::from(BigInt::from(10u32).pow(16));
    while k < 400 && w.mul_ref(&ten_k) < Rational::ONE {
        k += 1;
        ten_k *= Rational::from_integer(10);
    }
    format!("{} (width {:.1e})", decimal(&r.lo, k), w.to_f64())
}
