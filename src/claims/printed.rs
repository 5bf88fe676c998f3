//! Printed decimals judged against exact values: the one home of "is this printed number the
//! exact value correctly rounded?" for every claim that quotes a paper's decimals.
//!
//! A printed decimal with `d` digits after the point is *correctly rounded* when the exact value
//! lies in `[printed - 10^-d / 2, printed + 10^-d / 2]` (closed: a tie such as `12.625 -> 12.6`
//! is accepted, as both roundings of a tie are correct roundings); the comparisons are exact
//! ([`RealConstant::cmp_rational`]: the ordered field [`Radical`], real algebraic numbers, and
//! values in pi through a certified enclosure of pi). The exact decimal shown next to a
//! printed one is itself certified: the integer nearest to `x 10^p` is checked by exact
//! comparisons with its half-integer neighbours.

use exactcheck_core::{Field, Ring};
use exactcheck_exact::real_constant::RealConstant;
use exactcheck_exact::{Radical, Rational};
use num_bigint::{BigInt, Sign as BigSign};
use num_integer::Integer;
use num_traits::Zero;
use std::cmp::Ordering;

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

/// The exact comparison of `v` with `q`, its error (a limit) as one line.
fn cmp(v: &RealConstant, q: &Rational) -> Result<Ordering, String> {
    v.cmp_rational(q).map_err(|e| e.to_string())
}

/// Half a unit of the `p`-th place.
fn half_ulp(p: u32) -> Rational {
    inv_pow10(p).mul_ref(&Rational::new(1, 2).expect("2 != 0"))
}

/// Is `v` rounded to `p` places the printed value?
///
/// # Errors
/// The `pi-bits` limit, when a value in pi is too close to a rounding boundary.
pub fn rounds_to_of(v: &RealConstant, printed: &Rational, p: u32) -> Result<bool, String> {
    let half = half_ulp(p);
    Ok(cmp(v, &printed.sub_ref(&half))? != Ordering::Less
        && cmp(v, &printed.add_ref(&half))? != Ordering::Greater)
}

/// Is `v` exactly halfway between two `p`-place decimals, one of them `printed` (a tie: both
/// roundings are correct, e.g. `12.625 -> 12.6` or `12.7`)?
///
/// # Errors
/// As [`rounds_to_of`].
pub fn ties_of(v: &RealConstant, printed: &Rational, p: u32) -> Result<bool, String> {
    let half = half_ulp(p);
    Ok(cmp(v, &printed.sub_ref(&half))? == Ordering::Equal
        || cmp(v, &printed.add_ref(&half))? == Ordering::Equal)
}

/// Is `v` truncated toward zero to `p` places the printed value?
///
/// # Errors
/// As [`rounds_to_of`].
pub fn truncates_to_of(v: &RealConstant, printed: &Rational, p: u32) -> Result<bool, String> {
    let ulp = inv_pow10(p);
    if printed.signum() == exactcheck_core::Sign::Positive
        || (printed.is_zero() && cmp(v, &Rational::ZERO)? != Ordering::Less)
    {
        Ok(cmp(v, printed)? != Ordering::Less && cmp(v, &printed.add_ref(&ulp))? == Ordering::Less)
    } else {
        Ok(cmp(v, &printed.sub_ref(&ulp))? == Ordering::Greater
            && cmp(v, printed)? != Ordering::Greater)
    }
}

/// `x` correctly rounded to `p` places (a half goes up, toward `+inf`), certified by exact
/// comparisons.
pub fn decimal(x: &Radical, p: u32) -> String {
    decimal_of(&RealConstant::Radical(x.clone()), p).expect(FIELD_IS_EXACT)
}

/// The promise of the Radical wrappers: comparisons in the square-root field have no limit.
const FIELD_IS_EXACT: &str = "comparisons in the square-root field are exact and have no limit";

/// [`rounds_to_of`] in the square-root field.
pub fn rounds_to(v: &Radical, printed: &Rational, p: u32) -> bool {
    rounds_to_of(&RealConstant::Radical(v.clone()), printed, p).expect(FIELD_IS_EXACT)
}

/// [`ties_of`] in the square-root field.
pub fn ties(v: &Radical, printed: &Rational, p: u32) -> bool {
    ties_of(&RealConstant::Radical(v.clone()), printed, p).expect(FIELD_IS_EXACT)
}

/// [`truncates_to_of`] in the square-root field.
pub fn truncates_to(v: &Radical, printed: &Rational, p: u32) -> bool {
    truncates_to_of(&RealConstant::Radical(v.clone()), printed, p).expect(FIELD_IS_EXACT)
}

/// [`deviation_text_of`] in the square-root field.
pub fn deviation_text(x: &Radical) -> String {
    deviation_text_of(&RealConstant::Radical(x.clone())).expect(FIELD_IS_EXACT)
}

/// [`decimal`] of any exact value.
///
/// # Errors
/// As [`rounds_to_of`].
pub fn decimal_of(x: &RealConstant, p: u32) -> Result<String, String> {
    let c = nearest_integer(&x.scale(&pow10(p)))?;
    let sign = if c.sign() == BigSign::Minus { "-" } else { "" };
    let digits = c.magnitude().to_string();
    let p = p as usize;
    Ok(if p == 0 {
        format!("{sign}{digits}")
    } else {
        let digits = format!("{digits:0>w$}", w = p + 1);
        let (int, frac) = digits.split_at(digits.len() - p);
        format!("{sign}{int}.{frac}")
    })
}

/// The integer `c` nearest to `x`, a half going up: the one with `c - 1/2 <= x < c + 1/2`,
/// decided by exact comparisons. The candidate comes from an enclosure of `x` of width at most
/// `1/4`, so it is the answer or a neighbour of it.
fn nearest_integer(x: &RealConstant) -> Result<BigInt, String> {
    let half = Rational::new(1, 2).expect("2 != 0");
    let mut bits = 2;
    let lo = loop {
        match x.enclosure(bits) {
            Some((lo, hi)) if hi.sub_ref(&lo) <= half => break lo,
            _ if bits >= 1 << 16 => {
                return Err(format!("the value {x} could not be enclosed to 1/2"))
            }
            _ => bits *= 2,
        }
    };
    let shifted = lo.add_ref(&half);
    let mut c: BigInt = shifted.numer().div_floor(&shifted.denom());
    loop {
        let cq = Rational::from(c.clone());
        if cmp(x, &cq.sub_ref(&half))? == Ordering::Less {
            c -= 1;
        } else if cmp(x, &cq.add_ref(&half))? != Ordering::Less {
            c += 1;
        } else {
            return Ok(c);
        }
    }
}

/// `x` to three significant digits (`+0.00211`, `-1.23e-40` is `-0.000...0123`), with its sign;
/// the number of places is found by exact rounding, however small `x` is.
///
/// # Errors
/// As [`rounds_to_of`].
pub fn deviation_text_of(x: &RealConstant) -> Result<String, String> {
    if x.sign().map_err(|e| e.to_string())? == exactcheck_core::Sign::Zero {
        return Ok("0".into());
    }
    // The fewest places at which |x| rounds to at least 100: while x rounds to 0 the places
    // double; once the rounded value has k digits, 3 - k more places (or k - 3 fewer, after a
    // doubling went past) give 3.
    let mut p: u32 = 0;
    loop {
        let c = nearest_integer(&x.scale(&pow10(p)))?;
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
    let s = decimal_of(x, p)?;
    Ok(if s.starts_with('-') {
        s
    } else {
        format!("+{s}")
    })
}

/// A simple closed form whose correct rounding to `places` places is `printed`, the simplest
/// found first: a fraction `n/d` with `2 <= d <= 12` (other than the decimal itself), a square
/// root `±sqrt(a/b)` with `b <= 12`, or `(a + b sqrt(c))/d` with `c` in 2, 3, 5, 6, 7,
/// `1 <= d <= 6`, `1 <= |b| <= 3` (from three places on). Each family is searched exactly: the candidate integers next
/// to the printed value are found by exact rounding and every candidate is judged by
/// [`rounds_to_of`]. `None` for fewer than two places (too many forms round to such a decimal) or
/// when no form of the families fits.
pub fn closed_form_guess(printed: &Rational, places: u32) -> Option<String> {
    if places < 2 {
        return None;
    }
    let fits =
        |x: &Radical| rounds_to_of(&RealConstant::Radical(x.clone()), printed, places) == Ok(true);
    let round = |x: &Radical| nearest_integer(&RealConstant::Radical(x.clone())).ok();
    let near = |c: BigInt| [&c - 1, c.clone(), c + 1];
    let int = |n: &BigInt| Rational::from(n.clone());
    // n/d.
    for d in 2..=12i64 {
        let dq = Rational::from_integer(d);
        for n in near(round(&radical(&printed.mul_ref(&dq)))?) {
            let x = int(&n).checked_div(&dq).ok()?;
            if x != *printed && fits(&radical(&x)) {
                return Some(x.to_string());
            }
        }
    }
    // ±sqrt(a/b), a/b not the square of a fraction.
    let sign = if printed.signum() == exactcheck_core::Sign::Negative {
        -1
    } else {
        1
    };
    for b in 1..=12i64 {
        let bq = Rational::from_integer(b);
        for a in near(round(&radical(&printed.mul_ref(printed).mul_ref(&bq)))?) {
            if a <= BigInt::zero() {
                continue;
            }
            let Some(r) = Radical::sqrt_rational(&int(&a).checked_div(&bq).ok()?) else {
                continue;
            };
            let x = r.scale(&Rational::from_integer(sign));
            if x.to_rational().is_none() && fits(&x) {
                return Some(x.to_string());
            }
        }
    }
    // (a + b sqrt(c))/d: from three places on (at two, about one in ten of these forms rounds
    // to any given decimal, so a fit would say nothing).
    if places < 3 {
        return None;
    }
    for d in 1..=6i64 {
        let dq = Rational::from_integer(d);
        for c in [2u64, 3, 5, 6, 7] {
            for b in [1i64, -1, 2, -2, 3, -3] {
                let surd = Radical::sqrt_of(c).scale(&Rational::from_integer(b));
                let rest = radical(&printed.mul_ref(&dq)).sub_ref(&surd);
                for a in near(round(&rest)?) {
                    let x = radical(&int(&a)).add_ref(&surd).scale(&dq.inv().ok()?);
                    if fits(&x) {
                        return Some(x.to_string());
                    }
                }
            }
        }
    }
    None
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
    fn misprints_get_the_simplest_closed_form() {
        let q = |s: &str| s.parse::<Rational>().unwrap();
        let g = |s: &str| closed_form_guess(&q(s), places(s));
        assert_eq!(g("0.866").as_deref(), Some("sqrt(3)/2"));
        assert_eq!(g("0.3333").as_deref(), Some("1/3"));
        assert_eq!(g("-0.7071").as_deref(), Some("-sqrt(2)/2"));
        assert_eq!(g("0.2679").as_deref(), Some("2 - sqrt(3)"));
        assert_eq!(g("1.6180").as_deref(), Some("1/2 + sqrt(5)/2"));
        // The decimal itself is no guess, one place is too few, and most decimals fit nothing.
        assert_eq!(g("0.25"), None);
        assert_eq!(g("0.9"), None);
        assert_eq!(g("0.123456"), None);
        // Every guess rounds to the printed decimal.
        for s in ["0.866", "0.3333", "0.2679", "1.6180", "0.57735"] {
            let x: Radical = g(s).unwrap().parse().unwrap();
            assert!(rounds_to(&x, &q(s), places(s)), "{s}");
        }
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
