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
    rational_to_format(q, FRACTION_BITS, MIN_EXP, MAX_EXP)
}

/// `q` rounded to nearest even in the binary format of [`positive_ratio_to_format`], with its
/// sign (a zero is `+0.0`; a zero denominator gives NaN).
fn rational_to_format(q: &BigRational, fraction: u32, min_exp: i32, max_exp: i32) -> f64 {
    let (nsign, n) = split_sign(q.numer());
    let (dsign, d) = split_sign(q.denom());
    if d.is_zero() {
        return f64::NAN;
    }
    if n.is_zero() {
        return 0.0;
    }
    let neg = (nsign == BigSign::Minus) != (dsign == BigSign::Minus);
    let mag = positive_ratio_to_format(&n, &d, fraction, min_exp, max_exp);
    if neg {
        -mag
    } else {
        mag
    }
}

fn split_sign(x: &BigInt) -> (BigSign, BigUint) {
    (x.sign(), x.magnitude().clone())
}

/// `n / d` rounded to nearest even in the binary format with `fraction` explicit fraction bits,
/// smallest subnormal `2^min_exp` and largest binary exponent `max_exp` (at most binary64's, so
/// the result is exactly an `f64`), for `n, d > 0`; beyond the format's range, `inf`.
fn positive_ratio_to_format(
    n: &BigUint,
    d: &BigUint,
    fraction: u32,
    min_exp: i32,
    max_exp: i32,
) -> f64 {
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
    if e > i64::from(max_exp) {
        return f64::INFINITY;
    }
    if e < i64::from(min_exp) - 2 {
        // n/d < 2^(min_exp - 2), below half the smallest subnormal.
        return 0.0;
    }
    // The weight of the last mantissa bit: `fraction + 1` significant bits, or fewer among the
    // subnormals.
    let u = (e - i64::from(fraction)).max(i64::from(min_exp));
    let (num, den) = if u >= 0 {
        (n.clone(), d << u as usize)
    } else {
        (n << (-u) as usize, d.clone())
    };
    let (m, r) = num.div_rem(&den);
    let twice_r: BigUint = r << 1usize;
    let odd = m.bit(0);
    let up = twice_r > den || (twice_r == den && odd);
    // m < 2^(fraction + 1) by the choice of u, so it fits a u64 and converts exactly.
    let m = m.iter_u64_digits().next().unwrap_or(0) + u64::from(up);
    // The product is exact (m ≤ 2^53, weight ≥ 2^-1074) unless it overflows to inf.
    let x = m as f64 * pow2(u as i32);
    // Rounding up to 2^(max_exp + 1) is an overflow of the format.
    if x >= pow2(max_exp) * 2.0 {
        f64::INFINITY
    } else {
        x
    }
}

/// The binary32 value nearest to `q` (ties to even, gradual underflow, overflow to `±inf` at
/// `2^128 - 2^103`), as the `f64` holding it exactly: the one correctly rounded conversion to
/// binary32. Rounding `q` to a double first and that double to binary32 is not the same (a
/// double can lie exactly on a binary32 tie that `q` misses).
pub fn rational_to_f32(q: &BigRational) -> f64 {
    rational_to_format(q, 23, -149, 127)
}

/// An IEEE 754 binary interchange format a float side computes in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Format {
    /// binary64 (`f64`, 53 significant bits): the default.
    #[default]
    Binary64,
    /// binary32 (`f32`, 24 significant bits).
    Binary32,
}

impl Format {
    /// FPCore's name of the format: `binary64`, `binary32`.
    pub fn name(self) -> &'static str {
        match self {
            Format::Binary64 => "binary64",
            Format::Binary32 => "binary32",
        }
    }

    /// The format named `name` ([`Format::name`]).
    pub fn from_name(name: &str) -> Option<Format> {
        [Format::Binary64, Format::Binary32]
            .into_iter()
            .find(|f| f.name() == name)
    }

    /// The value of the format nearest to `q` (ties to even), as an `f64` ([`rational_to_f64`],
    /// [`rational_to_f32`]).
    pub fn round(self, q: &BigRational) -> f64 {
        match self {
            Format::Binary64 => rational_to_f64(q),
            Format::Binary32 => rational_to_f32(q),
        }
    }

    /// Whether the double `x` is a value of the format (NaN and the infinities are).
    pub fn holds(self, x: f64) -> bool {
        match self {
            Format::Binary64 => true,
            Format::Binary32 => f64::from(x as f32).to_bits() == x.to_bits() || x.is_nan(),
        }
    }

    /// The spacing of the format's values at `x` (a value of the format): `ulp(x)` as for
    /// doubles, with the smallest subnormal for zero and subnormals, `inf` for infinities.
    pub fn ulp(self, x: f64) -> f64 {
        match self {
            Format::Binary64 => {
                if x.is_nan() {
                    f64::NAN
                } else if x.is_infinite() {
                    f64::INFINITY
                } else {
                    let biased = ((x.to_bits() >> FRACTION_BITS) & 0x7ff) as i32;
                    if biased == 0 {
                        pow2(MIN_EXP)
                    } else {
                        pow2(biased - 1023 - FRACTION_BITS as i32)
                    }
                }
            }
            Format::Binary32 => {
                if x.is_nan() {
                    return f64::NAN;
                }
                if x.is_infinite() {
                    return f64::INFINITY;
                }
                let a = x.abs();
                if a < pow2(-126) {
                    return pow2(-149);
                }
                // floor(log2 |x|) of a normal binary32 value, from its double's exponent.
                let e = ((a.to_bits() >> FRACTION_BITS) & 0x7ff) as i32 - 1023;
                pow2(e - 23)
            }
        }
    }

    /// The largest finite value of the format.
    pub fn max(self) -> f64 {
        match self {
            Format::Binary64 => f64::MAX,
            Format::Binary32 => f64::from(f32::MAX),
        }
    }

    /// The position of `x` (a value of the format, not NaN) in the format's ordered values: the
    /// ordinal whose differences count the values between two numbers (Herbie's ordinal
    /// distance), with `±0` both at 0 and the infinities one past the largest finite values.
    pub fn ordinal(self, x: f64) -> i64 {
        let mag = match self {
            Format::Binary64 => (x.abs().to_bits() & !(1u64 << 63)) as i64,
            Format::Binary32 => i64::from((x.abs() as f32).to_bits()),
        };
        if x.is_sign_negative() {
            -mag
        } else {
            mag
        }
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;
    use num_traits::Signed;
    use proptest::prelude::*;

    fn dyadic(m: i64, e: i32) -> BigRational {
        let m = BigRational::from_integer(BigInt::from(m));
        if e >= 0 {
            m * BigRational::from_integer(BigInt::from(1) << e as usize)
        } else {
            m / BigRational::from_integer(BigInt::from(1) << (-e) as usize)
        }
    }

    fn exact32(x: f32) -> BigRational {
        BigRational::from_float(f64::from(x)).expect("finite")
    }

    /// The slow reference: among the binary32 neighbours of a first guess, the nearest to `q`
    /// by exact comparison, the even one at a tie; overflow where the nearest is past
    /// `f32::MAX` by at least half its ulp.
    fn nearest_f32_slow(q: &BigRational) -> f64 {
        let guess = rational_to_f64(q) as f32;
        let mut cands: Vec<f32> = Vec::new();
        let mut x = if guess.is_infinite() {
            f32::MAX.copysign(guess)
        } else {
            guess
        };
        for _ in 0..3 {
            x = x.next_down();
        }
        for _ in 0..7 {
            if x.is_finite() {
                cands.push(x);
            }
            x = x.next_up();
        }
        let dist = |c: f32| (exact32(c) - q).abs();
        let best = cands
            .iter()
            .copied()
            .min_by(|&a, &b| {
                dist(a)
                    .cmp(&dist(b))
                    .then_with(|| (a.to_bits() & 1).cmp(&(b.to_bits() & 1)))
            })
            .expect("candidates");
        // Past the largest finite value: overflow at the midpoint to 2^128 and beyond.
        let limit = exact32(f32::MAX) + dyadic(1, 103);
        if q.abs() >= limit {
            return if q.numer().sign() == BigSign::Minus {
                f64::NEG_INFINITY
            } else {
                f64::INFINITY
            };
        }
        f64::from(best)
    }

    #[test]
    fn binary32_ties_and_near_ties_are_decided_from_the_rational() {
        // 1 + 2^-24 is the tie between 1 and 1 + 2^-23: to even (1).
        assert_eq!(rational_to_f32(&dyadic((1 << 24) + 1, -24)), 1.0);
        // 1 + 3 * 2^-24 is the tie between 1 + 2^-23 and 1 + 2^-22: to even (1 + 2^-22).
        assert_eq!(
            rational_to_f32(&dyadic((1 << 24) + 3, -24)),
            1.0 + f64::powi(2.0, -22)
        );
        // Just above the tie, by less than half a double's ulp: the double rounds to the tie,
        // and the tie to even, so `(q as f64) as f32` is 1, while q rounds up.
        let above = dyadic((1 << 24) + 1, -24) + dyadic(1, -60);
        assert_eq!(rational_to_f64(&above) as f32, 1.0);
        assert_eq!(rational_to_f32(&above), 1.0 + f64::powi(2.0, -23));
        let below = dyadic((1 << 24) + 3, -24) - dyadic(1, -60);
        assert_eq!(
            f64::from(rational_to_f64(&below) as f32),
            1.0 + f64::powi(2.0, -22)
        );
        assert_eq!(rational_to_f32(&below), 1.0 + f64::powi(2.0, -23));
        // A third, negative values, subnormals and overflow.
        let third = BigRational::new(BigInt::from(1), BigInt::from(3));
        assert_eq!(rational_to_f32(&third), f64::from(1.0f32 / 3.0));
        assert_eq!(rational_to_f32(&-third), f64::from(-1.0f32 / 3.0));
        assert_eq!(
            rational_to_f32(&dyadic(1, -149)),
            f64::from(f32::from_bits(1))
        );
        assert_eq!(rational_to_f32(&dyadic(1, -150)), 0.0); // tie with 0: to even
        assert_eq!(
            rational_to_f32(&(dyadic(1, -150) + dyadic(1, -200))),
            f64::from(f32::from_bits(1))
        );
        let max = exact32(f32::MAX);
        assert_eq!(rational_to_f32(&max), f64::from(f32::MAX));
        assert_eq!(
            rational_to_f32(&(max.clone() + dyadic(1, 103) - dyadic(1, 50))),
            f64::from(f32::MAX)
        );
        assert_eq!(rational_to_f32(&(max + dyadic(1, 103))), f64::INFINITY);
        assert_eq!(
            Format::Binary32.round(&dyadic(-(1 << 30), 200)),
            f64::NEG_INFINITY
        );
    }

    #[test]
    fn binary32_ulps_and_ordinals() {
        let f = Format::Binary32;
        assert_eq!(f.ulp(1.0), f64::powi(2.0, -23));
        assert_eq!(f.ulp(-3.0), f64::powi(2.0, -22));
        assert_eq!(f.ulp(0.0), f64::powi(2.0, -149));
        assert_eq!(f.ulp(f64::from(f32::MIN_POSITIVE)), f64::powi(2.0, -149));
        assert_eq!(Format::Binary64.ulp(1.0), f64::EPSILON);
        let one = f.ordinal(1.0);
        assert_eq!(f.ordinal(f64::from(1.0f32.next_up())), one + 1);
        assert_eq!(f.ordinal(-0.0), f.ordinal(0.0));
        assert_eq!(f.ordinal(f64::from(-f32::from_bits(1))), -1);
        assert!(f.holds(0.1f32.into()) && !f.holds(0.1));
        assert_eq!(Format::from_name("binary32"), Some(f));
        assert_eq!(Format::from_name("binary80"), None);
    }

    proptest! {
        /// Near-ties built by hand: a binary32 midpoint moved by a tiny dyadic or rational
        /// amount (or not at all), at any binade, against the slow reference.
        #[test]
        fn binary32_rounding_matches_the_slow_reference(
            m in (1i64 << 23)..(1i64 << 24),
            e in -175i32..110,
            shift in -3i32..=3,
            far in 30i32..90,
            third in any::<bool>(),
            neg in any::<bool>(),
        ) {
            // The midpoint above m 2^e (m has 24 bits): (2m + 1) 2^(e-1).
            let mid = dyadic(2 * m + 1, e - 1);
            let tiny = if third {
                dyadic(1, e - far) / BigRational::from_integer(BigInt::from(3))
            } else {
                dyadic(1, e - far)
            };
            let q = mid + tiny * BigRational::from_integer(BigInt::from(shift));
            let q = if neg { -q } else { q };
            prop_assert_eq!(rational_to_f32(&q), nearest_f32_slow(&q));
        }
    }
}
