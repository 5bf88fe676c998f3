//! The real-roots benchmark workload: all real roots of an integer polynomial, each isolated
//! in an interval of width at most `2^-53`, on three families (the anchors in
//! `bench/scripts/anchors/real_roots.py` build the same polynomials):
//!
//! * [`wilkinson`]`(n)` = `prod_{j=1..n} (n x - j)`: `n` simple rational roots `j/n` in `(0, 1]`,
//!   evenly spaced, with coefficients of about `n log2(2n)` bits (ill-conditioned in the power
//!   basis: `f64` evaluation cannot decide signs near the roots).
//! * [`random`]`(d)`: the coefficients `c_0, ..., c_d` are the first `d + 1` outputs of
//!   SplitMix64 ([`exactcheck_core::rng::splitmix64`]) from the state `d`, read as signed 64-bit
//!   integers; `c_d = 0` becomes 1. Few real roots (about `(2/pi) ln d`), near `-1` and `1`.
//! * [`mignotte`]`(n)` = `x^n - 2 (10 x - 1)^2`: a pair of roots near `1/10` closer than
//!   `10^(-n/2)`, so the isolating intervals must be far narrower than `2^-53`.
//!
//! [`solve`] is the timed task: from the integer coefficients to the sorted list
//! ([`integer_real_roots_to`] with width `2^-53`).

use super::descartes::integer_real_roots_to;
use super::RootInterval;
use crate::Rational;
use exactcheck_core::rng::splitmix64;
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// The largest degree of the benchmark families accepted by the `real-roots` benchmark (`exactcheck-bench real-roots`).
pub const MAX_BENCH_DEGREE: usize = 2000;

/// The instances of the side-by-side comparison (`scripts/compare.py`) with their check value,
/// the number of real roots (python-flint and SymPy find the same): `(family, degree, roots)`.
/// One list for the criterion benchmark and the tests that pin the counts.
pub const COMPARISON: [(Family, usize, usize); 6] = [
    (Family::Wilkinson, 20, 20),
    (Family::Wilkinson, 40, 40),
    (Family::Random, 50, 4),
    (Family::Random, 100, 2),
    (Family::Mignotte, 20, 4),
    (Family::Mignotte, 40, 4),
];

/// The three benchmark families.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// [`wilkinson`].
    Wilkinson,
    /// [`random`].
    Random,
    /// [`mignotte`].
    Mignotte,
}

impl Family {
    /// The lower-case name used on the command line and in the JSON line.
    pub fn name(self) -> &'static str {
        match self {
            Family::Wilkinson => "wilkinson",
            Family::Random => "random",
            Family::Mignotte => "mignotte",
        }
    }

    /// The polynomial of this family at `degree`, coefficients from the constant term up.
    pub fn polynomial(self, degree: usize) -> Vec<BigInt> {
        match self {
            Family::Wilkinson => wilkinson(degree),
            Family::Random => random(degree),
            Family::Mignotte => mignotte(degree),
        }
    }
}

/// `prod_{j=1..n} (n x - j)`, coefficients from the constant term up.
pub fn wilkinson(n: usize) -> Vec<BigInt> {
    let nn = BigInt::from(n);
    let mut p = vec![BigInt::one()];
    for j in 1..=n {
        // p * (n x - j)
        let mut next = vec![BigInt::zero(); p.len() + 1];
        for (i, c) in p.iter().enumerate() {
            next[i] -= c * BigInt::from(j);
            next[i + 1] += c * &nn;
        }
        p = next;
    }
    p
}

/// The first `d + 1` SplitMix64 outputs from the state `d` as signed 64-bit coefficients
/// (constant term first), the leading one replaced by 1 if zero.
pub fn random(d: usize) -> Vec<BigInt> {
    let mut state = d as u64;
    let mut c: Vec<BigInt> = (0..=d)
        .map(|_| BigInt::from(splitmix64(&mut state) as i64))
        .collect();
    if c[d].is_zero() {
        c[d] = BigInt::one();
    }
    c
}

/// `x^n - 2 (10 x - 1)^2 = x^n - 200 x^2 + 40 x - 2`, coefficients from the constant term up.
pub fn mignotte(n: usize) -> Vec<BigInt> {
    let mut c = vec![BigInt::zero(); n.max(2) + 1];
    c[n] += 1;
    c[2] -= 200;
    c[1] += 40;
    c[0] -= 2;
    while c.last().is_some_and(Zero::is_zero) {
        c.pop();
    }
    c
}

/// `2^-53`, the width of the benchmark's intervals.
pub fn target_width() -> Rational {
    Rational::from(BigInt::one()) / Rational::from(BigInt::one() << 53u32)
}

/// All real roots of the integer polynomial `coeffs` (not zero), sorted, each of width at most
/// `2^-53` (exact when an evaluation point hit it).
///
/// # Panics
/// For the zero polynomial (every benchmark polynomial is non-zero).
pub fn solve(coeffs: &[BigInt]) -> Vec<RootInterval> {
    integer_real_roots_to(coeffs, &target_width()).expect("a benchmark polynomial is not zero")
}
