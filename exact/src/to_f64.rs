//! The workspace's one conversion from exact rationals to `f64`: round to nearest, ties to even,
//! over the whole binary64 range (gradual underflow into the subnormals, overflow to `±inf`
//! exactly where IEEE 754 puts it, at `2^1024 - 2^970`). Computed with big integers only (one
//! long division and a remainder comparison); [`crate::Rational::to_f64`] adds a fast path for
//! small values. `exactcheck-float` re-exports these functions and tests them against a slow
//! reference and against Rust's correctly rounded decimal parser.

use num_bigint::{BigInt, BigUint, Sign as BigSign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::Zero;

/// The number of explicit fraction bits of a binary64 number.
pub const FRACTION_BITS: u32 = 52;
/// The exponent of the smallest subnormal, `2^-1074`.
pub const MIN_EXP: i32 = -1074;
/// The largest binary exponent of a finite double (`f64::MAX < 2^1024`).
pub const MAX_EXP: i32 = 1023;

/// `2^p` as an `f64`, exactly, for `p` in `[-1074, 1023]`; `0` below that range and `inf` above.
pub fn pow2(p: i32) -> f64 {
    if p > MAX_EXP {
        f64::INFINITY
    } else if p >= -1022 {
        f64::from_bits(((p + 1023) as u64) << FRACTION_BITS)
    } else if p >= MIN_EXP {
        f64::from_bits(1u64 << (p - MIN_EXP))
    } else {
        0.0
    }
}

/// The double nearest to `q`, ties to even (IEEE 754 round-to-nearest), with gradual underflow
/// and overflow to `±inf`.
///
/// A negative `q` too small for the smallest subnormal rounds to `-0.0`, as IEEE arithmetic does.
/// A ratio with a zero denominator (only constructible with `Ratio::new_raw`) gives NaN. The
/// arguments need not be in lowest terms.
pub fn rational_to_f64(q: &BigRational) -> f64 {
    let (nsign, n) = split_sign(q.numer());
    let (dsign, d) = split_sign(q.denom());
    if d.is_zero() {
        return f64::NAN;
    }
    if n.is_zero() {
        return 0.0;
    }
    let neg = (nsign == BigSign::Minus) != (dsign == BigSign::Minus);
    let mag = positive_ratio_to_f64(&n, &d);
    if neg {
        -mag
    } else {
        mag
    }
}

fn split_sign(x: &BigInt) -> (BigSign, BigUint) {
    (x.sign(), x.magnitude().clone())
}

/// `n / d` rounded to nearest even, for `n, d > 0`.
fn positive_ratio_to_f64(n: &BigUint, d: &BigUint) -> f64 {
    // e = floor(log2(n / d)) is bn - bd or one less.
    let bn = n.bits() as i64;
    let bd = d.bits() as i64;
    let mut e = bn - bd;
    let below = if e >= 0 {
        *n < (d << e as usize)
    } else {
        (n << (-e) as usize) < *d
    };
    if below {
        e -= 1;
    }
    if e > i64::from(MAX_EXP) {
        return f64::INFINITY;
    }
    if e < i64::from(MIN_EXP) - 2 {
        // n/d < 2^-1076 < 2^-1075, below half the smallest subnormal.
        return 0.0;
    }
    // The weight of the last mantissa bit: 53 significant bits, or fewer among the subnormals.
    let u = (e - i64::from(FRACTION_BITS)).max(i64::from(MIN_EXP));
    let (num, den) = if u >= 0 {
        (n.clone(), d << u as usize)
    } else {
        (n << (-u) as usize, d.clone())
    };
    let (m, r) = num.div_rem(&den);
    let twice_r: BigUint = r << 1usize;
    let odd = m.bit(0);
    let up = twice_r > den || (twice_r == den && odd);
    // m < 2^53 by the choice of u, so it fits a u64 and converts exactly.
    let m = m.iter_u64_digits().next().unwrap_or(0) + u64::from(up);
    // The product is exact (m ≤ 2^53, weight ≥ 2^-1074) unless it overflows to inf.
    m as f64 * pow2(u as i32)
}

/// `sum_i c_i sqrt(d_i)` (`d_i >= 0`) as an `f64`, for display: never NaN, whatever the size of
/// the `c_i` and `d_i`. Where every `c_i` and `d_i` is a normal double and the sum is finite, it
/// is `sum_i f64(c_i) * sqrt(f64(d_i))`; otherwise term `c sqrt(d)` is taken as
/// `(c 2^-a)(sqrt(d 2^-2b)) 2^(a+b)` with both factors near 1 (each correctly rounded), the
/// terms are summed scaled by the largest power of two, and the sum is scaled back, saturating
/// to `±inf` or `0` beyond f64's range. Terms that cancel are not resolved (the sum of rounded
/// terms can be far from the value, even of the wrong sign).
pub fn sum_of_roots_to_f64(terms: &[(BigRational, BigRational)]) -> f64 {
    let terms: Vec<&(BigRational, BigRational)> = terms
        .iter()
        .filter(|(c, d)| !c.numer().is_zero() && !d.numer().is_zero())
        .collect();
    let quick: Option<f64> = terms
        .iter()
        .map(|(c, d)| {
            let (cf, df) = (rational_to_f64(c), rational_to_f64(d));
            (cf.is_normal() && df.is_normal()).then(|| cf * df.sqrt())
        })
        .sum();
    if let Some(x) = quick.filter(|x| x.is_finite()) {
        return x;
    }
    let log2 = |q: &BigRational| q.numer().bits() as i64 - q.denom().bits() as i64;
    let scaled: Vec<(f64, i64)> = terms
        .iter()
        .map(|(c, d)| {
            let a = log2(c);
            let b = log2(d) / 2;
            let cf = rational_to_f64(&shifted(c.numer(), c.denom(), -a));
            let df = rational_to_f64(&shifted(d.numer(), d.denom(), -2 * b));
            (cf * df.sqrt(), a + b)
        })
        .collect();
    let Some(top) = scaled.iter().map(|&(_, e)| e).max() else {
        return 0.0;
    };
    let sum: f64 = scaled
        .iter()
        .map(|&(t, e)| t * pow2(i32::try_from(e - top).unwrap_or(i32::MIN)))
        .sum();
    // `sum * 2^top` in steps that are exact powers of two: `top` may be far beyond f64's
    // exponent range, where the product saturates.
    let (mut x, mut e) = (sum, top);
    while e != 0 && x != 0.0 && x.is_finite() {
        let step = e.clamp(-1000, 1000);
        x *= pow2(step as i32);
        e -= step;
    }
    x
}

/// `num / den * 2^shift` (`den > 0`).
fn shifted(num: &BigInt, den: &BigInt, shift: i64) -> BigRational {
    let k = shift.unsigned_abs() as usize;
    if shift >= 0 {
        BigRational::new_raw(num << k, den.clone())
    } else {
        BigRational::new_raw(num.clone(), den << k)
    }
}
