//! The exact conversions against slow, independent references.
//!
//! * `f64 -> BigRational` against num-rational's own `Ratio::from_float`, and round trips over
//!   random bit patterns (every finite double, subnormals and both zeros included).
//! * `BigRational -> f64` against a reference that knows nothing of the fast algorithm: a binary
//!   search over bit patterns for the largest double below `|q|`, then an exact comparison of
//!   the distances to it and to the next double, ties to the even pattern; and against Rust's
//!   correctly rounded decimal parser on random decimal strings.

use exactcheck_float::{f64_to_rational, rational_to_f64, ulp, ulps_error, Rng};
use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

fn exact(x: f64) -> BigRational {
    f64_to_rational(x).expect("finite")
}

/// `2^1024 - 2^970`: the midpoint between `f64::MAX` and `2^1024`; from here up, rounding
/// overflows.
fn overflow_threshold() -> BigRational {
    BigRational::from_integer((BigInt::one() << 1024usize) - (BigInt::one() << 970usize))
}

/// The slow reference rounding (see the module docs).
fn reference_round(q: &BigRational) -> f64 {
    let neg = q.is_negative();
    let a = q.abs();
    let mag = if a >= overflow_threshold() {
        f64::INFINITY
    } else {
        // The largest pattern b with from_bits(b) <= a (positive doubles are ordered like
        // their patterns).
        let (mut lo, mut hi) = (0u64, f64::MAX.to_bits());
        while lo < hi {
            let mid = lo + (hi - lo).div_ceil(2);
            if exact(f64::from_bits(mid)) <= a {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        let below = f64::from_bits(lo);
        if lo == f64::MAX.to_bits() {
            below
        } else {
            let above = f64::from_bits(lo + 1);
            let d_below = &a - exact(below);
            let d_above = exact(above) - &a;
            if d_below < d_above || (d_below == d_above && lo % 2 == 0) {
                below
            } else {
                above
            }
        }
    };
    if neg {
        -mag
    } else {
        mag
    }
}

fn random_bigint(rng: &mut Rng, bits: u64) -> BigInt {
    let words = bits.div_ceil(64).max(1);
    let mut digits: Vec<u32> = Vec::new();
    for _ in 0..words {
        let w = rng.next_u64();
        digits.push(w as u32);
        digits.push((w >> 32) as u32);
    }
    let x = BigInt::from_slice(Sign::Plus, &digits);
    x >> (words * 64 - bits) as usize
}

/// Random rationals of every kind: small and huge numerators and denominators, scaled into the
/// subnormal and overflow ranges, exact midpoints between doubles and points next to them.
fn random_rational(rng: &mut Rng) -> BigRational {
    let kind = rng.below(4);
    let sign = if rng.below(2) == 0 { 1 } else { -1 };
    let q = match kind {
        0 | 1 => {
            let (nb, db) = (1 + rng.below(200), 1 + rng.below(200));
            let n = random_bigint(rng, nb);
            let d = random_bigint(rng, db) + BigInt::one();
            let shift = rng.below(2300) as i64 - 1150;
            let mut q = BigRational::new(n, d);
            let p = BigRational::from_integer(BigInt::one() << shift.unsigned_abs() as usize);
            if shift >= 0 {
                q *= p;
            } else {
                q /= p;
            }
            q
        }
        _ => {
            // Next to or exactly at the midpoint of two adjacent doubles.
            let bits = rng.next_u64() & !(1u64 << 63);
            let x = f64::from_bits(bits);
            if !x.is_finite() || x == f64::MAX {
                return BigRational::from_integer(BigInt::from(3));
            }
            let y = f64::from_bits(bits + 1);
            let mid = (exact(x) + exact(y)) / BigRational::from_integer(BigInt::from(2));
            let tiny = BigRational::new(BigInt::one(), BigInt::one() << 1200usize);
            match rng.below(3) {
                0 => mid,
                1 => mid + tiny,
                _ => mid - tiny,
            }
        }
    };
    if sign < 0 {
        -q
    } else {
        q
    }
}

#[test]
fn round_trips_over_random_bit_patterns() {
    let mut rng = Rng::new(0xF64);
    let specials = [
        0.0,
        -0.0,
        f64::from_bits(1),
        -f64::from_bits(1),
        f64::from_bits((1u64 << 52) - 1),
        f64::MIN_POSITIVE,
        f64::MAX,
        -f64::MAX,
        1.0,
        1.0 + f64::EPSILON,
    ];
    let randoms = (0..100_000).map(|_| f64::from_bits(rng.next_u64()));
    let mut checked = 0;
    for x in specials.into_iter().chain(randoms) {
        let q = f64_to_rational(x);
        if !x.is_finite() {
            assert!(q.is_none(), "{x} has no exact value");
            continue;
        }
        let q = q.expect("finite");
        assert_eq!(Some(&q), BigRational::from_float(x).as_ref(), "{x:e}");
        let back = rational_to_f64(&q);
        if x == 0.0 {
            assert_eq!(back.to_bits(), 0, "both zeros come back as +0");
        } else {
            assert_eq!(back.to_bits(), x.to_bits(), "{x:e}");
        }
        checked += 1;
    }
    assert!(checked > 99_000);
}

#[test]
fn rounding_matches_the_slow_reference() {
    let mut rng = Rng::new(0x5EED);
    for i in 0..3000 {
        let q = random_rational(&mut rng);
        let fast = rational_to_f64(&q);
        let slow = reference_round(&q);
        assert_eq!(
            fast.to_bits(),
            slow.to_bits(),
            "case {i}: {q} -> {fast:e}, expected {slow:e}"
        );
    }
}

#[test]
fn rounding_at_the_edges_matches_the_slow_reference() {
    let two = |k: i64| {
        let p = BigRational::from_integer(BigInt::one() << k.unsigned_abs() as usize);
        if k >= 0 {
            p
        } else {
            p.recip()
        }
    };
    let mut cases = vec![
        BigRational::zero(),
        overflow_threshold(),
        overflow_threshold() - two(-5),
        two(1024),
        two(-1075),
        two(-1075) + two(-1200),
        two(-1075) * BigRational::from_integer(BigInt::from(3)),
        two(-1022) - two(-1075),
        two(-1022) - two(-1076),
        two(-2000),
    ];
    cases.extend(cases.clone().into_iter().map(|q| -q));
    for q in cases {
        assert_eq!(
            rational_to_f64(&q).to_bits(),
            reference_round(&q).to_bits(),
            "{q}"
        );
    }
}

#[test]
fn rounding_matches_the_decimal_parser() {
    let mut rng = Rng::new(10);
    for _ in 0..5000 {
        let digits = 1 + rng.below(30) as usize;
        let mantissa: String = (0..digits)
            .map(|_| char::from(b'0' + rng.below(10) as u8))
            .collect();
        let exp = rng.below(680) as i64 - 360;
        let text = format!("{mantissa}e{exp}");
        let parsed: f64 = text.parse().expect("a decimal");
        let m: BigInt = mantissa.parse().expect("digits");
        let p = BigRational::from_integer(BigInt::from(10).pow(exp.unsigned_abs() as u32));
        let q = if exp >= 0 {
            BigRational::from_integer(m) * p
        } else {
            BigRational::from_integer(m) / p
        };
        assert_eq!(rational_to_f64(&q).to_bits(), parsed.to_bits(), "{text}");
    }
}

fn next_up(x: f64) -> f64 {
    if x >= 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

proptest! {
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn every_finite_double_round_trips(bits in any::<u64>()) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite() && x != 0.0);
        prop_assert_eq!(rational_to_f64(&exact(x)).to_bits(), bits);
    }

    #[test]
    fn neighbours_are_one_ulp_away(bits in 0u64..0x7FEF_FFFF_FFFF_FFFF) {
        // For a positive x, the next double up is exactly ulp(x) away; the one below is one ulp
        // away too, except at a power of two, where the gap below is half as wide.
        let x = f64::from_bits(bits);
        let up = next_up(x);
        prop_assert_eq!(ulps_error(up, &exact(x)), 1.0);
        prop_assert_eq!(exact(up) - exact(x), exact(ulp(x)));
        if bits > 0 {
            let down = f64::from_bits(bits - 1);
            let power_of_two = bits & ((1u64 << 52) - 1) == 0 && bits >> 52 > 1;
            let expected = if power_of_two { 0.5 } else { 1.0 };
            prop_assert_eq!(ulps_error(down, &exact(x)), expected);
            prop_assert_eq!(ulps_error(-x, &exact(x)), 2.0 * exact_ratio(x));
        }
    }
}

/// `|x| / ulp(x)`, rounded: the error of `-x` against `x` is twice this.
fn exact_ratio(x: f64) -> f64 {
    rational_to_f64(&(exact(x).abs() / exact(ulp(x))))
}
