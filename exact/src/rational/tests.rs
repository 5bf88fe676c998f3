use super::*;
use crate::ParseRationalError;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).unwrap()
}

/// `from_dyadic` against the division, inline and boxed, odd and even numerators.
#[test]
fn from_dyadic_is_the_quotient() {
    let nums = [0i64, 1, -1, 6, -12, 1 << 40, -(3 << 50), i64::MAX, i64::MIN];
    for &n in &nums {
        for big in [0u32, 70, 200] {
            let num = BigInt::from(n) << big;
            for exp in [0u64, 1, 3, 64, 125, 126, 127, 300] {
                let expected = Rational::from(num.clone()) / Rational::from(BigInt::from(1) << exp);
                let got = Rational::from_dyadic(&num, exp);
                assert_eq!(got, expected, "{num} / 2^{exp}");
                assert_eq!(got.is_inline(), expected.is_inline(), "{num} / 2^{exp}");
            }
        }
    }
}

#[test]
fn canonical_construction() {
    assert_eq!(q(6, -4), q(-3, 2));
    assert_eq!(q(0, -7), Rational::ZERO);
    assert!(q(6, -4).is_canonical());
    assert_eq!(Rational::new(1, 0), Err(ZeroDivisor));
}

#[test]
fn inline_parts_are_the_canonical_pair() {
    assert_eq!(q(6, -4).inline_parts(), Some((-3, 2)));
    assert_eq!(Rational::ZERO.inline_parts(), Some((0, 1)));
    let big = Rational::from(BigInt::from(1) << 200u32);
    assert_eq!(big.inline_parts(), None);
}

#[test]
fn small_arithmetic() {
    assert_eq!(q(1, 3) + q(1, 6), q(1, 2));
    assert_eq!(q(1, 3) - q(1, 3), Rational::ZERO);
    assert_eq!(q(2, 3) * q(9, 4), q(3, 2));
    assert_eq!(q(2, 3) / q(4, 9), q(3, 2));
    assert_eq!(q(-5, 7).recip(), Ok(q(-7, 5)));
    assert!(q(-1, 2) < q(1, 3));
    assert!(q(1, 3) > q(1, 4));
}

#[test]
fn overflow_promotes_and_demotes() {
    let big = Rational::from_i128_ratio(i128::MAX, 3).unwrap();
    assert!(big.is_inline());
    let sq = big.square();
    assert!(!sq.is_inline());
    assert!(sq.is_canonical());
    let back = &sq / &big;
    assert!(back.is_inline());
    assert_eq!(back, big);
    let m = Rational::from_i128_ratio(i128::MIN, 1).unwrap();
    assert!(!m.is_inline());
    assert!(m.is_canonical());
    assert_eq!(-(-m.clone()), m);
}

#[test]
fn parse_and_print() {
    for s in ["0", "-12", "3/4", "-7/9"] {
        assert_eq!(s.parse::<Rational>().unwrap().to_string(), s);
    }
    assert_eq!("0.125".parse::<Rational>().unwrap(), q(1, 8));
    assert_eq!("-0.5".parse::<Rational>().unwrap(), q(-1, 2));
    assert_eq!("6/-4".parse::<Rational>().unwrap(), q(-3, 2));
    assert!(matches!(
        "1/0".parse::<Rational>(),
        Err(ParseRationalError::DivisionByZero { pos: 2 })
    ));
    for bad in ["", "1/", "a", "1.2.3", "1.", "0x10", "2 3", "1e", "sin(1)"] {
        assert!(bad.parse::<Rational>().is_err(), "{bad:?} parsed");
    }
    // The one grammar: signs, products, powers and perfect-square roots are constants too.
    assert_eq!("--1".parse::<Rational>().unwrap(), q(1, 1));
    assert_eq!(" 2^-3 ".parse::<Rational>().unwrap(), q(1, 8));
    assert_eq!("sqrt(9/4)".parse::<Rational>().unwrap(), q(3, 2));
}

#[test]
fn scientific_notation_is_exact() {
    // Regression: the old parser had no exponents ("1e3" was malformed, "5e0" rejected).
    assert_eq!("1e3".parse::<Rational>().unwrap(), q(1000, 1));
    assert_eq!("2.5e-3".parse::<Rational>().unwrap(), q(1, 400));
    assert_eq!("1E+5".parse::<Rational>().unwrap(), q(100_000, 1));
    assert_eq!("5e0".parse::<Rational>().unwrap(), q(5, 1));
    assert_eq!("-0.0e7".parse::<Rational>().unwrap(), Rational::ZERO);
    // The digits limit counts the decimal exponent: 1e10000 has 10,001 digits.
    assert_eq!(
        "1e10000".parse::<Rational>().unwrap_err().to_string(),
        "at 0: digits of a number exceeds the limit digits = 10000 digits (found 10001; \
         raise it with --limit digits=N)"
    );
    assert!("1e-9999".parse::<Rational>().is_ok());
}

#[test]
fn big_rational_round_trip() {
    let x: Rational = "123456789012345678901234567890123456789012345/98765432109876543210987"
        .parse()
        .unwrap();
    assert!(!x.is_inline());
    let b = x.to_big_rational();
    assert_eq!(Rational::from(b), x);
}

/// A big rational `n / (den_factor * m)` from seeded random limbs (canonicalised).
fn random_big(st: &mut exactcheck_core::Rng, limbs: usize, den_factor: u64) -> BigRational {
    let mut rnd = |k: usize| {
        let v: Vec<u64> = (0..k).map(|_| st.next_u64()).collect();
        crate::bigint::biguint_from_limbs(&v)
    };
    let n = BigInt::from(rnd(limbs)) * if limbs % 2 == 0 { 1 } else { -1 };
    let d = BigInt::from(rnd(limbs)) * den_factor + 1u32;
    BigRational::new(n, d * den_factor)
}

#[test]
fn big_plus_word_matches_reference() {
    // The limb-kernel path (add_big_word) against add_big and num-rational, with shared
    // denominator factors so that g = gcd(b, d) and g2 = gcd(t, g) are non-trivial.
    let mut st = exactcheck_core::Rng::new(0xadd);
    let words: [(i64, i64); 12] = [
        (1, 1),
        (-1, 1),
        (7, 30),
        (-11, 60),
        (1, 2),
        (5, 4096),
        (-3, 1 << 40),
        (i64::MAX, 1),
        (i64::MIN + 1, 3),
        (13, 2_147_483_647),
        (-1, 9_007_199_254_740_881),
        (1_000_000_007, 999_999_999_999),
    ];
    for limbs in [3usize, 4, 5, 40] {
        for factor in [1u64, 6, 30, 1 << 20, 2_147_483_647] {
            let x = random_big(&mut st, limbs, factor);
            let fx = Rational::from(x.clone());
            assert!(!fx.is_inline());
            for (n, d) in words {
                let y = BigRational::new(n.into(), d.into());
                let fy = q(n, d);
                let (xb, xd) = fx.big_parts();
                let (yb, yd) = fy.big_parts();
                for sub in [false, true] {
                    let expected = if sub { &x - &y } else { &x + &y };
                    let got = fx.add_impl(&fy, sub);
                    assert!(got.is_canonical(), "{x} {y} {sub}");
                    assert_eq!(got.to_big_rational(), expected, "{x} +- {y}");
                    let reference = add_big(&xb, &xd, &yb, &yd, sub);
                    assert_eq!(got, reference);
                    // Word operand first: y + x and y - x.
                    let back = fy.add_impl(&fx, sub);
                    let expected = if sub { &y - &x } else { &y + &x };
                    assert!(back.is_canonical());
                    assert_eq!(back.to_big_rational(), expected);
                }
            }
        }
    }
}

#[test]
fn big_plus_word_cancels_and_demotes() {
    // x + w where the sum is zero, an integer, or fits inline again.
    let big = Rational::from_i128_ratio(i128::MAX, 7).unwrap().square();
    assert!(!big.is_inline());
    let w = q(1, 49);
    let s = &big + &w;
    assert_eq!(&s - &w, big);
    assert_eq!(&(&s - &big) - &w, Rational::ZERO);
    // Big integer minus a word integer, and a big value whose difference is inline.
    let two64 = Rational::from(BigInt::from(1) << 127u32);
    assert!(!two64.is_inline());
    let d = &two64 - &q(1, 1);
    assert!(d.is_inline());
    assert_eq!(d.inline_parts(), Some((i128::MAX, 1)));
    assert_eq!(&q(1, 1) - &two64, -d);
}

#[test]
fn pairwise_sum() {
    let v: Vec<Rational> = (1..=10).map(|k| q(1, k * (k + 1))).collect();
    assert_eq!(exactcheck_core::pairwise_sum(v), q(10, 11));
    assert_eq!(
        exactcheck_core::pairwise_sum(Vec::<Rational>::new()),
        Rational::ZERO
    );
}

#[test]
fn dyadic_sums_match_num_rational() {
    // add_big's power-of-two path: one or both denominators powers of two, the other with an
    // odd factor; numerators with and without trailing zeros; results that cancel to zero.
    let mut st = exactcheck_core::Rng::new(0xd1ad);
    for _ in 0..300 {
        let mut big = |bits: u32| {
            let v: Vec<u64> = (0..3).map(|_| st.next_u64()).collect();
            BigInt::from(crate::bigint::biguint_from_limbs(&v)) >> (192 - bits)
        };
        let (a, c) = (big(150) << 3u32, -big(140));
        let odd = big(60) | BigInt::one();
        for (eb, ed, with_odd) in [
            (130u32, 140u32, false),
            (200, 5, true),
            (3, 250, true),
            (128, 128, false),
        ] {
            let b = BigInt::one() << eb;
            let d = (BigInt::one() << ed) * if with_odd { odd.clone() } else { BigInt::one() };
            let (x, y) = (
                BigRational::new(a.clone(), b),
                BigRational::new(c.clone(), d),
            );
            let (fx, fy) = (Rational::from(&x), Rational::from(&y));
            for (got, expected) in [
                (&fx + &fy, &x + &y),
                (&fx - &fy, &x - &y),
                (&fy - &fx, &y - &x),
                (&fx - &fx, BigRational::zero()),
            ] {
                assert!(got.is_canonical(), "{x} {y}");
                assert_eq!(got.to_big_rational(), expected, "{x} {y}");
            }
        }
    }
}

/// Reduction of one-word numerators and denominators (the 64-bit gcd path) and of values
/// beyond one word, against num-rational.
#[test]
fn reduction_in_one_word_and_beyond() {
    let cases: [(i128, i128); 9] = [
        (6, -4),
        (-6, 4),
        (i64::MIN as i128, 2),
        (i64::MIN as i128, -1),
        (i64::MAX as i128, i64::MAX as i128),
        (i64::MAX as i128 + 1, 6),
        (12, i64::MAX as i128 + 1),
        (-(1i128 << 100), 1 << 90),
        (0, -5),
    ];
    for (n, d) in cases {
        let got = Rational::from_i128_ratio(n, d).expect("d != 0");
        let expected = BigRational::new(BigInt::from(n), BigInt::from(d));
        assert_eq!(got.numer(), *expected.numer(), "{n}/{d}");
        assert_eq!(got.denom(), *expected.denom(), "{n}/{d}");
    }
}

/// The inline tier's divisions (64-bit where both operands fit a word, `i128` otherwise)
/// against num-rational: construction, sums, differences, products and quotients of parts
/// around `2^63`, `2^64` and `2^100`, of both signs, with common factors planted.
#[test]
fn inline_arithmetic_at_word_boundaries_matches_num_rational() {
    let mut st = exactcheck_core::Rng::new(0x64);
    let edges: [i128; 8] = [
        1,
        3,
        i64::MAX as i128,
        i64::MAX as i128 + 1,
        u64::MAX as i128,
        u64::MAX as i128 + 1,
        1 << 100,
        (1 << 100) + 7,
    ];
    let part = |st: &mut exactcheck_core::Rng| -> i128 {
        let base = match st.below(3) {
            0 => edges[st.below(8) as usize] - st.below(3) as i128,
            1 => (st.next_u64() >> st.below(64)) as i128,
            _ => (st.next_u64() as i128) << st.below(40),
        };
        // A planted factor so that the gcds are not all 1.
        let f = [1i128, 2, 6, 1 << 20, 1_000_003][st.below(5) as usize];
        (base.max(1) / f).max(1) * f
    };
    for _ in 0..2000 {
        let (a, b, c, d) = (part(&mut st), part(&mut st), part(&mut st), part(&mut st));
        let (a, c) = if st.below(2) == 0 { (-a, c) } else { (a, -c) };
        let x = Rational::from_i128_ratio(a, b).unwrap();
        let y = Rational::from_i128_ratio(c, d).unwrap();
        let (rx, ry) = (
            BigRational::new(BigInt::from(a), BigInt::from(b)),
            BigRational::new(BigInt::from(c), BigInt::from(d)),
        );
        assert_eq!(x.to_big_rational(), rx, "{a}/{b}");
        for (got, expected) in [
            (&x + &y, &rx + &ry),
            (&x - &y, &rx - &ry),
            (&x * &y, &rx * &ry),
            (&x / &y, &rx / &ry),
        ] {
            assert!(got.is_canonical(), "{a}/{b} and {c}/{d}");
            assert_eq!(got.to_big_rational(), expected, "{a}/{b} and {c}/{d}");
        }
    }
    // i64::MIN over -1 and its neighbours through the signed constructor.
    assert_eq!(
        Rational::new(i64::MIN, -1).unwrap().to_big_rational(),
        BigRational::from(-BigInt::from(i64::MIN))
    );
    assert_eq!(q(i64::MIN, 2), Rational::from_integer(i64::MIN / 2));
}

/// `x += w` and `x -= w` on a big `x` and a word-sized `w` (updated in place on reused buffers)
/// against the by-reference kernel and num-rational, including results that cancel to zero or
/// fall back to the inline tier, and a running sum whose operands grow past the buffers' sizes.
#[test]
fn in_place_big_plus_word_matches_reference() {
    let mut st = exactcheck_core::Rng::new(0x1a5e);
    let words: [(i64, i64); 6] = [
        (1, 1),
        (-11, 60),
        (5, 4096),
        (i64::MIN + 1, 3),
        (13, 2_147_483_647),
        (-1, 9_007_199_254_740_881),
    ];
    for limbs in [3usize, 4, 9, 40, 300] {
        for factor in [1u64, 6, 30, 1 << 20] {
            let x = Rational::from(random_big(&mut st, limbs, factor));
            for (n, d) in words {
                let w = q(n, d);
                for sub in [false, true] {
                    let expected = x.add_impl(&w, sub);
                    let mut got = x.clone();
                    if sub {
                        got -= &w;
                    } else {
                        got += &w;
                    }
                    assert!(got.is_canonical(), "{x} {w} {sub}");
                    assert_eq!(got, expected, "{x} +- {w}");
                    let big = x.to_big_rational();
                    let wb = w.to_big_rational();
                    assert_eq!(
                        got.to_big_rational(),
                        if sub { &big - &wb } else { &big + &wb }
                    );
                }
            }
        }
    }
    // Cancellation to zero and to the inline tier.
    let big = Rational::from_i128_ratio(i128::MAX, 7).unwrap().square();
    let w = q(1, 49);
    let mut s = big.clone();
    s += &w;
    s -= &w;
    assert_eq!(s, big);
    s -= &big.clone();
    assert!(s.is_zero());
    let mut two127 = Rational::from(BigInt::from(1) << 127u32);
    two127 -= q(1, 1);
    assert_eq!(two127.inline_parts(), Some((i128::MAX, 1)));
    // A running sum of word-sized terms, each step against num-rational.
    let mut acc = Rational::from(random_big(&mut st, 5, 30));
    let mut reference = acc.to_big_rational();
    for k in 1..400i64 {
        let w = q(if k % 3 == 0 { -k } else { 7 * k + 1 }, 1 + k * (k % 17));
        reference += w.to_big_rational();
        acc += w;
        assert!(acc.is_canonical());
    }
    assert_eq!(acc.to_big_rational(), reference);
}

/// The one-word kernels (every part of both operands in `i64`: products and sums formed in
/// `i128` without overflow checks) against num-rational, at the extremes of the word range
/// (`i64::MIN` numerators, `i64::MAX` denominators, whose negation leaves the word path) and
/// with planted common factors so that every branch of Henrici's method is taken.
#[test]
fn word_parts_match_num_rational_at_the_extremes() {
    let mut st = exactcheck_core::Rng::new(0x77);
    let edges: [i64; 7] = [1, 2, 3, i64::MAX, i64::MAX - 1, 1 << 62, 3 << 61];
    let part = |st: &mut exactcheck_core::Rng| -> i64 {
        match st.below(3) {
            0 => edges[st.below(7) as usize],
            1 => (st.next_u64() >> (1 + st.below(63))) as i64,
            _ => [6i64, 10, 15, 1 << 20, 1_000_003][st.below(5) as usize],
        }
        .max(1)
    };
    for _ in 0..4000 {
        let (a, b, c, d) = (part(&mut st), part(&mut st), part(&mut st), part(&mut st));
        let a = match st.below(4) {
            0 => -a,
            1 => i64::MIN,
            _ => a,
        };
        let c = if st.below(2) == 0 { -c } else { c };
        // Equal denominators and integer operands are their own branches.
        let d = match st.below(4) {
            0 => b,
            1 => 1,
            _ => d,
        };
        let (x, y) = (q(a, b), q(c, d));
        let (rx, ry) = (
            BigRational::new(BigInt::from(a), BigInt::from(b)),
            BigRational::new(BigInt::from(c), BigInt::from(d)),
        );
        for (got, expected) in [
            (&x + &y, &rx + &ry),
            (&x - &y, &rx - &ry),
            (&y - &x, &ry - &rx),
            (&x * &y, &rx * &ry),
            (x.square(), &rx * &rx),
        ] {
            assert!(got.is_canonical(), "{a}/{b} and {c}/{d}");
            assert_eq!(got.to_big_rational(), expected, "{a}/{b} and {c}/{d}");
        }
    }
}
