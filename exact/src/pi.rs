//! A certified enclosure of pi: rational bounds `lo < pi < hi` as close as asked.
//!
//! Machin's formula `pi = 16 atan(1/5) - 4 atan(1/239)` with the alternating series
//! `atan(1/x) = sum_k (-1)^k / ((2k + 1) x^(2k + 1))`, summed in fixed point with `s` fraction
//! bits. Every term is computed as an exact floor, `t_k = floor(2^s / ((2k + 1) x^(2k + 1)))`
//! (nested floor divisions of positive integers equal the floor of the whole quotient), so each
//! term is off by less than one unit of `2^-s`; the sum stops at the first term that floors to 0,
//! whose true value, and so the whole alternating tail, is below one unit. With `n` terms summed
//! the series value lies within `n + 1` units of the fixed-point sum; the two sums combine with
//! weights 16 and 4 into the bounds. Nothing is rounded that is not accounted for, and no
//! floating-point number is used.
//!
//! Hand-written because the dependency set has no arbitrary-precision constant with certified
//! rational bounds (the `num` crates have integers and rationals only), and the series is a few
//! lines on the workspace's big integers.

use crate::Rational;
use num_bigint::BigInt;
use num_traits::Zero;

/// `floor(2^s atan(1/x))` up to the returned error bound in units of `2^-s`: `(sum, error)`
/// with `|2^s atan(1/x) - sum| <= error`.
fn atan_inv(x: u32, s: u64) -> (BigInt, BigInt) {
    let x2 = BigInt::from(x) * BigInt::from(x);
    // p = floor(2^s / x^(2k + 1)), exactly (nested floors).
    let mut p = (BigInt::from(1) << s) / BigInt::from(x);
    let mut sum = BigInt::zero();
    let mut k: u64 = 0;
    loop {
        let t = &p / BigInt::from(2 * k + 1);
        if t.is_zero() {
            break;
        }
        if k % 2 == 0 {
            sum += t;
        } else {
            sum -= t;
        }
        p /= &x2;
        k += 1;
    }
    // k floored terms (each within one unit) and a tail below one unit.
    (sum, BigInt::from(k + 1))
}

/// Rational bounds `(lo, hi)` with `lo < pi < hi` and `hi - lo <= 2^-bits`.
///
/// ```
/// use exactcheck_exact::pi::enclosure;
/// use exactcheck_exact::Rational;
///
/// let (lo, hi) = enclosure(20);
/// assert!(lo > Rational::new(333, 106).unwrap() && hi < Rational::new(22, 7).unwrap());
/// assert!(&hi - &lo <= Rational::from_dyadic(&1.into(), 20));
/// ```
pub fn enclosure(bits: u32) -> (Rational, Rational) {
    // Guard bits for the error terms (16 (n5 + 1) + 4 (n239 + 1) units, n about s / 4.6).
    let guard = 16 + u64::from(64 - u64::from(bits).leading_zeros());
    let s = u64::from(bits) + guard + 8;
    let (a5, e5) = atan_inv(5, s);
    let (a239, e239) = atan_inv(239, s);
    let mid = a5 * 16 - a239 * 4;
    // One more unit each side: the bounds are strict (pi is irrational, the sums are dyadic).
    let err = e5 * 16 + e239 * 4 + 1;
    (
        Rational::from_dyadic(&(&mid - &err), s),
        Rational::from_dyadic(&(&mid + &err), s),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// pi to 100 decimals, as published.
    const PI_100: &str = "3.1415926535897932384626433832795028841971693993751058209749445923078164062862089986280348253421170679";

    #[test]
    fn encloses_the_published_digits() {
        let digits: Rational = PI_100.parse().unwrap();
        let ulp =
            Rational::from_dyadic(&BigInt::from(1), 0) / Rational::from(BigInt::from(10).pow(100));
        for bits in [1, 2, 10, 53, 64, 200, 320] {
            let (lo, hi) = enclosure(bits);
            assert!(lo < hi);
            assert!(&hi - &lo <= Rational::from_dyadic(&BigInt::from(1), u64::from(bits)));
            // pi lies in [digits, digits + 10^-100].
            assert!(lo < &digits + &ulp, "bits {bits}");
            assert!(hi > digits, "bits {bits}");
        }
        // At 320 bits (about 96 decimals) the enclosure pins the first 95 published decimals.
        let (lo, hi) = enclosure(320);
        let cut = Rational::from(BigInt::from(10).pow(95));
        let floor = |q: &Rational| {
            let scaled = q * &cut;
            scaled.numer() / scaled.denom()
        };
        let want: BigInt = PI_100[..97].replace('.', "").parse().unwrap();
        assert_eq!(floor(&lo), want);
        assert_eq!(floor(&hi), want);
    }

    #[test]
    fn classical_bounds() {
        let (lo, hi) = enclosure(40);
        assert!(lo > Rational::new(103993, 33102).unwrap());
        assert!(hi < Rational::new(355, 113).unwrap());
    }

    proptest::proptest! {
        /// Enclosures at different precisions overlap (each contains pi) and shrink.
        #[test]
        fn enclosures_are_consistent(a in 1u32..400, b in 1u32..400) {
            let (lo_a, hi_a) = enclosure(a);
            let (lo_b, hi_b) = enclosure(b);
            proptest::prop_assert!(lo_a < hi_b && lo_b < hi_a);
            proptest::prop_assert!(&hi_a - &lo_a <= Rational::from_dyadic(&BigInt::from(1), u64::from(a)));
        }
    }
}
