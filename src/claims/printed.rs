//! Printed decimals judged against exact values: the one home of "is this printed number the
//! exact value correctly rounded?" for every claim that quotes a paper's decimals.
//!
//! A printed decimal with `d` digits after the point is *correctly rounded* when the exact value
//! lies in `[printed - 10^-d / 2, printed + 10^-d / 2]` (closed: a tie such as `12.625 -> 12.6`
//! is accepted, as both roundings of a tie are correct roundings); the comparisons are exact (the
//! ordered field [`Radical`], which contains every rational). The exact decimal shown next to a
//! printed one is itself certified: the integer nearest to `x 10^p` is checked by exact
//! comparisons with its half-integer neighbours.

use exactcheck_core::{Field, Ring};
use exactcheck_exact::{Radical, Rational};
use num_bigint::{BigInt, Sign as BigSign};
use num_integer::Integer;
use num_traits::{One, Zero};

/// A printed decimal read exactly (`"0.705"` is `141/200`).
pub fn rational(text: &str) -> Result<Rational, String> {
    text.parse::<Rational>()
        .map_err(|e| format!("printed decimal {text:?}: {e}"))
}

/// Digits after the decimal point of a printed decimal.
pub fn places(text: &str) -> u32 {
    text.split_once('.').map_or(0, |(_, f)| f.len() as u32)
}

/// `10^p`, exact at any `p`.
pub fn pow10(p: u32) -> Rational {
    Rational::from(BigInt::from(10u32).pow(p))
}

/// `10^-p`.
pub fn inv_pow10(p: u32) -> Rational {
    pow10(p).inv().expect("10^p is not zero")
}

/// A rational as an element of [`Radical`].
pub fn radical(q: &Rational) -> Radical {
    Radical::from(q.clone())
}

/// Is `v` rounded to `p` places the printed value?
pub fn rounds_to(v: &Radical, printed: &Rational, p: u32) -> bool {
    let half = inv_pow10(p).mul_ref(&Rational::new(1, 2).expect("2 != 0"));
    radical(&printed.sub_ref(&half)) <= *v && *v <= radical(&printed.add_ref(&half))
}

/// Is `v` exactly halfway between two `p`-place decimals, one of them `printed` (a tie: both
/// roundings are correct, e.g. `12.625 -> 12.6` or `12.7`)?
pub fn ties(v: &Radical, printed: &Rational, p: u32) -> bool {
    let half = radical(&inv_pow10(p).mul_ref(&Rational::new(1, 2).expect("2 != 0")));
    let d = v.sub_ref(&radical(printed));
    d == half || d == half.neg_ref()
}

/// Is `v` truncated toward zero to `p` places the printed value?
pub fn truncates_to(v: &Radical, printed: &Rational, p: u32) -> bool {
    let ulp = inv_pow10(p);
    let pr = radical(printed);
    if printed.signum() == exactcheck_core::Sign::Positive
        || (printed.is_zero() && *v >= Radical::default())
    {
        pr <= *v && *v < radical(&printed.add_ref(&ulp))
    } else {
        radical(&printed.sub_ref(&ulp)) < *v && *v <= pr
    }
}

/// `x` correctly rounded to `p` places (a half goes up, toward `+inf`), certified by exact
/// comparisons.
pub fn decimal(x: &Radical, p: u32) -> String {
    let c = nearest_integer(&x.scale(&pow10(p)));
    let sign = if c.sign() == BigSign::Minus { "-" } else { "" };
    let digits = c.magnitude().to_string();
    let p = p as usize;
    if p == 0 {
        format!("{sign}{digits}")
    } else {
        let digits = format!("{digits:0>w$}", w = p + 1);
        let (int, frac) = digits.split_at(digits.len() - p);
        format!("{sign}{int}.{frac}")
    }
}

/// The integer `c` nearest to `x`, a half going up: the one with `c - 1/2 <= x < c + 1/2`,
/// decided by exact comparisons. The candidate comes from an integer approximation of `x` within
/// `1/4` ([`scaled_approximation`]), so it is the answer or a neighbour of it.
pub fn nearest_integer(x: &Radical) -> BigInt {
    let n = x.terms().len().max(1) as u64;
    // Each term is approximated within 2 units of 2^-g: the sum is within 1/4 when 2^g >= 8 n.
    let g = 64 - (8 * n).leading_zeros() as u64;
    let a = scaled_approximation(x, g);
    let mut c: BigInt = (a + (BigInt::one() << (g - 1))) >> g;
    let half = Rational::new(1, 2).expect("2 != 0");
    loop {
        let cq = Rational::from(c.clone());
        if *x < radical(&cq.sub_ref(&half)) {
            c -= 1;
        } else if *x >= radical(&cq.add_ref(&half)) {
            c += 1;
        } else {
            return c;
        }
    }
}

/// An integer `a` with `|x 2^g - a| < 2 t`, `t` the number of terms of `x`: each term `c sqrt(m)`
/// from the integer square root of `m 4^k`, `k` large enough for the coefficient.
fn scaled_approximation(x: &Radical, g: u64) -> BigInt {
    let mut sum = BigInt::zero();
    for (m, c) in x.terms() {
        let (num, den) = (c.numer(), c.denom());
        let term = if m.is_one() {
            // floor(c 2^g): within 1.
            (num << g).div_floor(&den)
        } else {
            // |c| < 2^e, sqrt(m) 2^k in [s, s + 1), k = g + e: num s / (den 2^e) is within
            // |c| 2^-e < 1 of c sqrt(m) 2^g, and the floor within 1 more.
            let e = (num.bits() + 1).saturating_sub(den.bits());
            let k = g + e;
            let s = BigInt::from((m.to_biguint() << (2 * k)).sqrt());
            (num * s).div_floor(&(den << e))
        };
        sum += term;
    }
    sum
}

/// `x` to three significant digits (`+0.00211`, `-1.23e-40` is `-0.000...0123`), with its sign;
/// the number of places is found by exact rounding, however small `x` is.
pub fn deviation_text(x: &Radical) -> String {
    if x.is_zero() {
        return "0".into();
    }
    // The fewest places at which |x| rounds to at least 100: while x rounds to 0 the places
    // double; once the rounded value has k digits, 3 - k more places (or k - 3 fewer, after a
    // doubling went past) give 3.
    let mut p: u32 = 0;
    loop {
        let c = nearest_integer(&x.scale(&pow10(p)));
        let k = if c.is_zero() {
            0
        } else {
            c.magnitude().to_string().len() as u32
        };
        if k >= 3 {
            p -= p.min(k - 3);
            break;
        }
        p += if k == 0 { p.max(1) } else { 3 - k };
    }
    let s = decimal(x, p);
    if s.starts_with('-') {
        s
    } else {
        format!("+{s}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(s: &str) -> Radical {
        s.parse().unwrap()
    }

    #[test]
    fn rounding_intervals_are_exact() {
        let q = |s: &str| s.parse::<Rational>().unwrap();
        // sqrt 2 = 1.41421...: rounds to 1.41 and 1.414, not to 1.42; truncates to 1.41.
        assert!(rounds_to(&r("sqrt(2)"), &q("1.41"), 2));
        assert!(rounds_to(&r("sqrt(2)"), &q("1.414"), 3));
        assert!(!rounds_to(&r("sqrt(2)"), &q("1.42"), 2));
        assert!(truncates_to(&r("sqrt(2)"), &q("1.41"), 2));
        assert!(!truncates_to(&r("sqrt(2)"), &q("1.42"), 2));
        // -sqrt(2)/2 = -0.7071...: rounds to -0.707, truncates to -0.707, never to -0.705.
        assert!(rounds_to(&r("-sqrt(2)/2"), &q("-0.707"), 3));
        assert!(truncates_to(&r("-sqrt(2)/2"), &q("-0.707"), 3));
        assert!(!rounds_to(&r("-sqrt(2)/2"), &q("-0.705"), 3));
        assert!(!truncates_to(&r("-sqrt(2)/2"), &q("-0.705"), 3));
        // Boundaries: 0.125 rounds to 0.12 and 0.13 (inclusive interval), truncates to 0.12.
        assert!(rounds_to(&r("1/8"), &q("0.12"), 2));
        assert!(rounds_to(&r("1/8"), &q("0.13"), 2));
        assert!(truncates_to(&r("1/8"), &q("0.12"), 2));
        assert!(!truncates_to(&r("1/8"), &q("0.13"), 2));
        // Ties: 101/8 = 12.625 is halfway between 12.62 and 12.63 and not a tie at 1 place.
        assert!(ties(&r("101/8"), &q("12.62"), 2));
        assert!(ties(&r("101/8"), &q("12.63"), 2));
        assert!(!ties(&r("101/8"), &q("12.6"), 1));
        assert!(!ties(&r("sqrt(2)"), &q("1.41"), 2));
    }

    #[test]
    fn certified_decimals() {
        assert_eq!(decimal(&r("sqrt(2)"), 6), "1.414214");
        assert_eq!(decimal(&r("-sqrt(2)/2"), 3), "-0.707");
        assert_eq!(decimal(&r("2/3"), 0), "1");
        assert_eq!(deviation_text(&r("-0.705 + sqrt(2)/2")), "+0.00211");
        assert_eq!(deviation_text(&Radical::default()), "0");
        // Beyond 64-bit integers: 10^19, 40 places, a deviation of 10^-17 and of 10^-60.
        assert_eq!(decimal(&r("10^19"), 2), "10000000000000000000.00");
        assert_eq!(decimal(&r("1/3"), 40), format!("0.{}", "3".repeat(40)));
        assert_eq!(decimal(&r("-1/3"), 40), format!("-0.{}", "3".repeat(40)));
        assert_eq!(
            decimal(&r("sqrt(2)"), 30),
            "1.414213562373095048801688724210"
        );
        assert_eq!(deviation_text(&r("10^-17")), "+0.0000000000000000100");
        assert_eq!(
            deviation_text(&r("-2/3 * 10^-60")),
            format!("-0.{}667", "0".repeat(60))
        );
        assert_eq!(deviation_text(&r("123456")), "+123456");
        assert_eq!(deviation_text(&r("-0.5")), "-0.500");
        // Three radicals: 1.4142... + 1.7320... - 2.2360... = 0.9102...
        assert_eq!(decimal(&r("sqrt(2) + sqrt(3) - sqrt(5)"), 0), "1");
    }

    /// `round(n 10^d / q)`, a half going up, in plain integer arithmetic.
    fn rounded_ratio(n: &BigInt, q: &BigInt, d: u32) -> BigInt {
        let scaled = n * BigInt::from(10u32).pow(d);
        (BigInt::from(2) * scaled + q).div_floor(&(BigInt::from(2) * q))
    }

    /// The text `c 10^-d` with `d` places, from a string of the digits of `|c|`.
    fn shift(c: &BigInt, d: u32) -> String {
        let digits = format!("{:0>w$}", c.magnitude().to_string(), w = d as usize + 1);
        let (int, frac) = digits.split_at(digits.len() - d as usize);
        let sign = if c.sign() == BigSign::Minus { "-" } else { "" };
        if d == 0 {
            format!("{sign}{int}")
        } else {
            format!("{sign}{int}.{frac}")
        }
    }

    proptest::proptest! {
        /// `decimal` of a rational `n / q` is `round(n 10^d / q)` computed directly.
        #[test]
        fn decimals_of_rationals_are_the_integer_rounding(
            a in proptest::prelude::any::<i64>(),
            b in proptest::prelude::any::<i64>(),
            q in 1i64..=i64::MAX,
            small in 1i64..1000,
            d in 0u32..60,
        ) {
            for (n, q) in [
                (BigInt::from(a), BigInt::from(q)),
                (BigInt::from(a) * BigInt::from(b), BigInt::from(small)),
                (BigInt::from(a % 1000), BigInt::from(q)),
            ] {
                let x = radical(&(Rational::from(n.clone()) / Rational::from(q.clone())));
                let want = shift(&rounded_ratio(&n, &q, d), d);
                proptest::prop_assert_eq!(decimal(&x, d), want, "{}/{} to {} places", n, q, d);
            }
        }

        /// `decimal` of `sqrt(m)` is `floor((isqrt(4 m 10^2d) + 1) / 2)`: floor(y + 1/2) is
        /// floor((floor(2y) + 1) / 2).
        #[test]
        fn decimals_of_square_roots_are_the_integer_rounding(m in 2u64..1_000_000, d in 0u32..60) {
            let four_m = BigInt::from(4 * m) * BigInt::from(10u32).pow(2 * d);
            let c = (four_m.sqrt() + 1) / 2;
            let x = Radical::sqrt_of(m);
            let want = shift(&c, d);
            proptest::prop_assert_eq!(decimal(&x, d), want.clone(), "sqrt({}) to {} places", m, d);
            let neg = format!("-{want}");
            // -sqrt(m) 10^d is never a half (it is irrational or an integer): the mirror image.
            proptest::prop_assert_eq!(decimal(&x.neg_ref(), d), neg);
        }
    }
}
