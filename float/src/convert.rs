//! Exact conversions between `f64` and rationals, and the error measures of the harness.
//!
//! Every finite double is a dyadic rational `±m·2^e`, so [`f64_to_rational`] is exact. The way
//! back, [`rational_to_f64`], rounds to nearest with ties to even over the whole binary64 range:
//! gradual underflow into the subnormals, and overflow to `±inf` exactly where IEEE 754 puts it
//! (at `2^1024 - 2^970`, the midpoint between `f64::MAX` and the next power of two). It is
//! computed with big integers only (one long division and a remainder comparison), and the tests
//! check it against a slow reference that compares every answer with both of its neighbours by
//! exact arithmetic, and against Rust's own correctly rounded decimal parser.
//!
//! The error measures ([`ulps_error`], [`rel_error`]) are computed exactly in rationals and only
//! the final quotient is rounded, so a measured error of `0.5` ulp really is half an ulp.

pub use exactcheck_exact::to_f64::{pow2, rational_to_f64};
use exactcheck_exact::to_f64::{Format, FRACTION_BITS, MIN_EXP};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// A finite non-zero double as `(negative, m, e)` with `x = ±m·2^e` and `m` odd.
fn decompose(x: f64) -> Option<(bool, u64, i32)> {
    if !x.is_finite() || x == 0.0 {
        return None;
    }
    let bits = x.to_bits();
    let neg = bits >> 63 == 1;
    let biased = ((bits >> FRACTION_BITS) & 0x7ff) as i32;
    let frac = bits & ((1u64 << FRACTION_BITS) - 1);
    let (m, e) = if biased == 0 {
        (frac, MIN_EXP)
    } else {
        (frac | (1u64 << FRACTION_BITS), biased - 1075)
    };
    let tz = m.trailing_zeros();
    Some((neg, m >> tz, e + tz as i32))
}

/// The bit length of a non-zero `u64`.
fn bit_len(m: u64) -> u32 {
    64 - m.leading_zeros()
}

/// The number of significant bits of `x`: the length of its mantissa from the leading to the
/// trailing one bit (`1` for a power of two, `53` at most, `0` for zero and non-finite values).
pub fn significant_bits(x: f64) -> u32 {
    decompose(x).map_or(0, |(_, m, _)| bit_len(m))
}

/// `floor(log2 |x|)` for a finite non-zero `x` (`-1074` for the smallest subnormal), `None`
/// for zero and non-finite values.
pub fn binary_exponent(x: f64) -> Option<i32> {
    decompose(x).map(|(_, m, e)| e + bit_len(m) as i32 - 1)
}

/// `x` rounded to `k` significant bits (to nearest, ties to even; toward zero in the one case
/// where nearest would overflow past `f64::MAX`).
///
/// `k = 0` gives `0` with the sign of `x`; values that already have at most `k` significant bits,
/// zeros and non-finite values are returned unchanged.
pub fn round_to_bits(x: f64, k: u32) -> f64 {
    let Some((neg, m, e)) = decompose(x) else {
        return x;
    };
    if k == 0 {
        return if neg { -0.0 } else { 0.0 };
    }
    let len = bit_len(m);
    if len <= k {
        return x;
    }
    let d = len - k;
    let kept = m >> d;
    let rest = m & ((1u64 << d) - 1);
    let half = 1u64 << (d - 1);
    let up = rest > half || (rest == half && kept & 1 == 1);
    let scale = e + d as i32;
    let mut mag = (kept + u64::from(up)) as f64 * pow2(scale);
    if mag.is_infinite() {
        mag = kept as f64 * pow2(scale);
    }
    if neg {
        -mag
    } else {
        mag
    }
}

/// `x` truncated (rounded toward zero) to `k` significant bits.
///
/// `k = 0` gives `0` with the sign of `x`; values that already have at most `k` significant bits,
/// zeros and non-finite values are returned unchanged.
pub fn truncate_to_bits(x: f64, k: u32) -> f64 {
    let Some((neg, m, e)) = decompose(x) else {
        return x;
    };
    if k == 0 {
        return if neg { -0.0 } else { 0.0 };
    }
    let len = bit_len(m);
    if len <= k {
        return x;
    }
    let d = len - k;
    // Exact: k <= 53 bits at a weight >= 2^-1074, and no larger than |x|.
    let mag = (m >> d) as f64 * pow2(e + d as i32);
    if neg {
        -mag
    } else {
        mag
    }
}

/// The exact value of a finite double as a rational, `None` for NaN and infinities.
///
/// Both zeros map to `0` (a rational has no signed zero). The result is in lowest terms: an odd
/// numerator over a power of two, or an integer.
pub fn f64_to_rational(x: f64) -> Option<BigRational> {
    if !x.is_finite() {
        return None;
    }
    let Some((neg, m, e)) = decompose(x) else {
        return Some(BigRational::zero());
    };
    let mut numer = BigInt::from(m);
    if neg {
        numer = -numer;
    }
    if e >= 0 {
        Some(BigRational::from_integer(numer << e as usize))
    } else {
        let denom = BigInt::one() << (-e) as usize;
        // Already in lowest terms: `m` is odd and the denominator a power of two.
        Some(BigRational::new_raw(numer, denom))
    }
}

/// The spacing of doubles at `x`: `2^(e-52)` for a normal `x` with `2^e ≤ |x| < 2^(e+1)`, and the
/// smallest subnormal `2^-1074` for zero and subnormal `x`. `ulp(±inf) = inf`, `ulp(NaN) = NaN`.
///
/// At a power of two this is the gap *above* `|x|` (the gap below is half as wide).
pub fn ulp(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x.is_infinite() {
        return f64::INFINITY;
    }
    let biased = ((x.to_bits() >> FRACTION_BITS) & 0x7ff) as i32;
    if biased == 0 {
        pow2(MIN_EXP)
    } else {
        pow2(biased - 1023 - FRACTION_BITS as i32)
    }
}

/// The error of `approx` in units in the last place of the exact value:
/// `|approx - exact| / ulp(round(exact))`, computed exactly and rounded once.
///
/// `round(exact)` is the double nearest to `exact` ([`rational_to_f64`]); where that overflows,
/// the ulp of `f64::MAX` (`2^971`) is used. Hence `ulp(0)` is the smallest subnormal. A NaN or
/// infinite `approx` has an infinite error; a finite error too large for a double also reads
/// `inf`.
pub fn ulps_error(approx: f64, exact: &BigRational) -> f64 {
    ulps_error_rounded(approx, exact, rational_to_f64(exact))
}

/// [`ulps_error`] given `rounded = rational_to_f64(exact)` (the harness needs the rounded value
/// for Herbie's bits too, and rounds once).
pub(crate) fn ulps_error_rounded(approx: f64, exact: &BigRational, rounded: f64) -> f64 {
    ulps_error_in(Format::Binary64, approx, exact, rounded)
}

/// [`ulps_error`] in the units of `format`: `|approx - exact| / ulp(rounded)` with `rounded`
/// the value of `format` nearest to `exact` ([`Format::round`]) and the format's ulp (of its
/// largest finite value where `rounded` overflows). For binary32, `approx` is any double (a
/// binary32 result is one).
pub fn ulps_error_in(format: Format, approx: f64, exact: &BigRational, rounded: f64) -> f64 {
    let Some((an, ad)) = dyadic_parts(approx) else {
        return f64::INFINITY;
    };
    let unit = if rounded.is_finite() {
        format.ulp(rounded)
    } else {
        format.ulp(format.max())
    };
    // `unit` is a power of two `un / ud` with one of them 1.
    let Some((un, ud)) = dyadic_parts(unit) else {
        return f64::INFINITY;
    };
    // |an/ad - n/d| / (un/ud) = |an d - n ad| ud / (ad d un), never reduced: the one rounding
    // divides the integers (`rational_to_f64` takes any ratio; a gcd of big operands costs more
    // than the whole measure).
    let (n, d) = (exact.numer(), exact.denom());
    let diff = (&an * d - n * &ad).abs();
    rational_to_f64(&BigRational::new_raw(diff * ud, ad * d * un))
}

/// A finite double as an unreduced ratio of integers `(n, 2^k)` or `(n 2^k, 1)`.
fn dyadic_parts(x: f64) -> Option<(BigInt, BigInt)> {
    if !x.is_finite() {
        return None;
    }
    let Some((neg, m, e)) = decompose(x) else {
        return Some((BigInt::zero(), BigInt::one()));
    };
    let m = if neg {
        -BigInt::from(m)
    } else {
        BigInt::from(m)
    };
    Some(if e >= 0 {
        (m << e as usize, BigInt::one())
    } else {
        (m, BigInt::one() << (-e) as usize)
    })
}

/// The relative error `|approx - exact| / |exact|`, computed exactly and rounded once.
///
/// When `exact` is zero the error is `0` if `approx` is zero and `inf` otherwise. A NaN or
/// infinite `approx` has an infinite error.
pub fn rel_error(approx: f64, exact: &BigRational) -> f64 {
    let Some((an, ad)) = dyadic_parts(approx) else {
        return f64::INFINITY;
    };
    if exact.is_zero() {
        return if an.is_zero() { 0.0 } else { f64::INFINITY };
    }
    // |an/ad - n/d| / |n/d| = |an d - n ad| / (ad |n|), unreduced (see `ulps_error`).
    let (n, d) = (exact.numer(), exact.denom());
    let diff = (&an * d - n * &ad).abs();
    rational_to_f64(&BigRational::new_raw(diff, ad * n.abs()))
}

/// The correctly rounded sum of finite doubles (Python's `math.fsum`): each is added exactly as an
/// integer multiple of `2^-1074`, and the exact sum is rounded once. Non-finite values are skipped.
pub fn fsum(xs: &[f64]) -> f64 {
    let mut sum = BigInt::zero();
    for &x in xs {
        if let Some((neg, m, e)) = decompose(x) {
            let v = BigInt::from(m) << (e - MIN_EXP) as usize;
            if neg {
                sum -= v;
            } else {
                sum += v;
            }
        }
    }
    rational_to_f64(&BigRational::new_raw(
        sum,
        BigInt::one() << (-MIN_EXP) as usize,
    ))
}

/// `q` in scientific notation with `digits` significant digits, truncated toward zero
/// (`1.41421e0`): how an approximated exact value is shown (it is marked `~` by the caller).
pub fn decimal_digits(q: &BigRational, digits: usize) -> String {
    use num_integer::Integer;
    if q.is_zero() {
        return "0".into();
    }
    let digits = digits.max(1);
    let a = q.abs();
    let ten = BigInt::from(10);
    let log2 = a.numer().bits() as f64 - a.denom().bits() as f64;
    let mut e = (log2 * std::f64::consts::LOG10_2).floor() as i64;
    // floor(a * 10^(digits - 1 - e)), with e corrected until it has exactly `digits` digits.
    let scaled = |e: i64| {
        let k = digits as i64 - 1 - e;
        let p = num_traits::pow(ten.clone(), k.unsigned_abs() as usize);
        if k >= 0 {
            (a.numer() * p).div_floor(a.denom())
        } else {
            a.numer().div_floor(&(a.denom() * p))
        }
    };
    let lo = num_traits::pow(ten.clone(), digits - 1);
    let hi = &lo * &ten;
    let mut t = scaled(e);
    while t >= hi {
        e += 1;
        t = scaled(e);
    }
    while t < lo {
        e -= 1;
        t = scaled(e);
    }
    let s = t.to_string();
    let sign = if q.is_negative() { "-" } else { "" };
    if digits == 1 {
        format!("{sign}{s}e{e}")
    } else {
        format!("{sign}{}.{}e{e}", &s[..1], &s[1..])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn fsum_rounds_once() {
        assert_eq!(fsum(&[0.1; 10]), 1.0);
        assert_eq!(fsum(&[1e100, 1.0, -1e100]), 1.0);
        assert_eq!(fsum(&[f64::from_bits(1), -f64::from_bits(1), 0.5]), 0.5);
        assert_eq!(fsum(&[]), 0.0);
    }

    #[test]
    fn decimal_digits_truncate() {
        assert_eq!(decimal_digits(&q(1, 3), 5), "3.3333e-1");
        assert_eq!(decimal_digits(&q(-2, 1), 3), "-2.00e0");
        assert_eq!(decimal_digits(&q(999, 1), 2), "9.9e2");
        assert_eq!(decimal_digits(&q(1000, 1), 1), "1e3");
        assert_eq!(decimal_digits(&q(0, 1), 4), "0");
    }

    #[test]
    fn powers_of_two() {
        assert_eq!(pow2(0), 1.0);
        assert_eq!(pow2(-1), 0.5);
        assert_eq!(pow2(-1074), f64::from_bits(1));
        assert_eq!(pow2(-1022), f64::MIN_POSITIVE);
        assert_eq!(pow2(1023), 2f64.powi(1023));
        assert_eq!(pow2(1024), f64::INFINITY);
        assert_eq!(pow2(-1075), 0.0);
    }

    #[test]
    fn small_exact_conversions() {
        assert_eq!(f64_to_rational(0.5), Some(q(1, 2)));
        assert_eq!(f64_to_rational(-3.0), Some(q(-3, 1)));
        assert_eq!(f64_to_rational(-0.0), Some(q(0, 1)));
        assert_eq!(f64_to_rational(f64::NAN), None);
        assert_eq!(f64_to_rational(f64::NEG_INFINITY), None);
        // 0.1 is 3602879701896397 / 2^55.
        let tenth = f64_to_rational(0.1).unwrap();
        assert_eq!(tenth.numer(), &BigInt::from(3602879701896397u64));
        assert_eq!(tenth.denom(), &(BigInt::one() << 55usize));
    }

    #[test]
    fn hand_rounded_values() {
        assert_eq!(rational_to_f64(&q(1, 3)), 1.0 / 3.0);
        assert_eq!(rational_to_f64(&q(-2, 3)), -2.0 / 3.0);
        assert_eq!(rational_to_f64(&q(1, 10)), 0.1);
        // 1 + 2^-53 is a tie between 1 and 1 + 2^-52: ties to even gives 1.
        let tie = BigRational::one() + BigRational::new(BigInt::one(), BigInt::one() << 53usize);
        assert_eq!(rational_to_f64(&tie), 1.0);
        // 1 + 3·2^-53 is a tie between 1 + 2^-52 (odd) and 1 + 2^-51 (even).
        let tie = BigRational::one() + BigRational::new(BigInt::from(3), BigInt::one() << 53usize);
        assert_eq!(rational_to_f64(&tie), 1.0 + 2f64.powi(-51));
        // Half the smallest subnormal ties to 0; a hair more rounds up to it.
        let half_min = BigRational::new(BigInt::one(), BigInt::one() << 1075usize);
        assert_eq!(rational_to_f64(&half_min), 0.0);
        let above = half_min.clone() + BigRational::new(BigInt::one(), BigInt::one() << 1200usize);
        assert_eq!(rational_to_f64(&above), f64::from_bits(1));
        assert_eq!(rational_to_f64(&-above), -f64::from_bits(1));
        // 3/2 of the smallest subnormal ties to 2 of them (even).
        let three_halves = BigRational::new(BigInt::from(3), BigInt::one() << 1075usize);
        assert_eq!(rational_to_f64(&three_halves), f64::from_bits(2));
    }

    #[test]
    fn overflow_boundary() {
        let two_1024 = BigRational::from_integer(BigInt::one() << 1024usize);
        let half_ulp_max = BigRational::from_integer(BigInt::one() << 970usize);
        let midpoint = two_1024.clone() - half_ulp_max.clone();
        assert_eq!(rational_to_f64(&midpoint), f64::INFINITY);
        let eps = BigRational::one();
        assert_eq!(rational_to_f64(&(midpoint.clone() - eps)), f64::MAX);
        assert_eq!(rational_to_f64(&-midpoint), f64::NEG_INFINITY);
        assert_eq!(
            rational_to_f64(&(two_1024 * BigRational::from_integer(BigInt::from(7)))),
            f64::INFINITY
        );
    }

    #[test]
    fn unnormalised_and_degenerate_ratios() {
        let q = BigRational::new_raw(BigInt::from(6), BigInt::from(-4));
        assert_eq!(rational_to_f64(&q), -1.5);
        let bad = BigRational::new_raw(BigInt::one(), BigInt::zero());
        assert!(rational_to_f64(&bad).is_nan());
    }

    #[test]
    fn ulp_values() {
        assert_eq!(ulp(1.0), f64::EPSILON);
        assert_eq!(ulp(-1.0), f64::EPSILON);
        assert_eq!(ulp(1.5), f64::EPSILON);
        assert_eq!(ulp(2.0), 2.0 * f64::EPSILON);
        assert_eq!(ulp(0.0), f64::from_bits(1));
        assert_eq!(ulp(f64::from_bits(12345)), f64::from_bits(1));
        assert_eq!(ulp(f64::MIN_POSITIVE), f64::from_bits(1));
        assert_eq!(ulp(f64::MAX), 2f64.powi(971));
        assert_eq!(ulp(f64::INFINITY), f64::INFINITY);
        assert!(ulp(f64::NAN).is_nan());
        // ulp(x) is the gap from |x| to the next double up.
        for x in [0.1f64, 3.0, 1e300, 1e-310, 123456.789] {
            assert_eq!(f64::from_bits(x.to_bits() + 1) - x, ulp(x));
        }
    }

    #[test]
    fn hand_checked_ulps_errors() {
        // 0.1 vs 1/10: 0.1 = 3602879701896397/2^55, 1/10 = 3602879701896396.8/2^55,
        // ulp(0.1) = 2^-56 -> error 0.2·2^-55 / 2^-56 = 0.4 ulp.
        assert_eq!(ulps_error(0.1, &q(1, 10)), 0.4);
        assert_eq!(ulps_error(1.0, &q(1, 1)), 0.0);
        assert_eq!(ulps_error(1.0 + f64::EPSILON, &q(1, 1)), 1.0);
        assert_eq!(ulps_error(1.0 - f64::EPSILON / 2.0, &q(1, 1)), 0.5);
        assert_eq!(ulps_error(f64::from_bits(3), &q(0, 1)), 3.0);
        assert_eq!(ulps_error(-2.0, &q(2, 1)), 4.0 / (2.0 * f64::EPSILON));
        assert_eq!(ulps_error(f64::NAN, &q(1, 1)), f64::INFINITY);
        assert_eq!(ulps_error(f64::INFINITY, &q(1, 1)), f64::INFINITY);
        // Relative errors.
        assert_eq!(rel_error(1.5, &q(1, 1)), 0.5);
        assert_eq!(rel_error(-1.0, &q(1, 1)), 2.0);
        assert_eq!(rel_error(0.0, &q(0, 1)), 0.0);
        assert_eq!(rel_error(1e-300, &q(0, 1)), f64::INFINITY);
        assert_eq!(rel_error(f64::NAN, &q(0, 1)), f64::INFINITY);
        // |0.1 - 1/10| = 2^-55 / 5, relative to 1/10: exactly 2^-54.
        assert_eq!(rel_error(0.1, &q(1, 10)), 2f64.powi(-54));
    }

    #[test]
    fn bit_helpers() {
        assert_eq!(significant_bits(0.0), 0);
        assert_eq!(significant_bits(1.0), 1);
        assert_eq!(significant_bits(-3.0), 2);
        assert_eq!(significant_bits(0.1), 52);
        assert_eq!(significant_bits(1.0 + f64::EPSILON), 53);
        assert_eq!(significant_bits(f64::from_bits(1)), 1);
        assert_eq!(binary_exponent(1.0), Some(0));
        assert_eq!(binary_exponent(0.75), Some(-1));
        assert_eq!(binary_exponent(f64::from_bits(1)), Some(-1074));
        assert_eq!(binary_exponent(0.0), None);
        assert_eq!(round_to_bits(0.1, 1), 0.125);
        assert_eq!(round_to_bits(-0.1, 3), -0.09375); // 1.10|011 -> 1.10
        assert_eq!(round_to_bits(-0.1, 4), -0.1015625); // 1.100|11 -> 1.101
        assert_eq!(round_to_bits(1.5, 1), 2.0); // tie to even
        assert_eq!(round_to_bits(2.5, 2), 2.0); // 10.1 -> 10 (even)
        assert_eq!(round_to_bits(3.5, 2), 4.0); // 11.1 -> 100
        assert_eq!(round_to_bits(f64::MAX, 3), 1.75 * 2f64.powi(1023));
        assert_eq!(round_to_bits(7.0, 0), 0.0);
        assert_eq!(truncate_to_bits(-0.1, 4), -0.09375);
        assert_eq!(truncate_to_bits(3.5, 2), 3.0);
        assert_eq!(truncate_to_bits(f64::MAX, 1), 2f64.powi(1023));
        assert_eq!(truncate_to_bits(f64::from_bits(3), 1), f64::from_bits(2));
        assert_eq!(truncate_to_bits(5.0, 3), 5.0);
        assert!(round_to_bits(f64::NAN, 3).is_nan());
    }
}
