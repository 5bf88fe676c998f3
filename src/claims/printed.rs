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

/// A printed decimal read exactly (`"0.705"` is `141/200`).
pub fn rational(text: &str) -> Result<Rational, String> {
    text.parse::<Rational>()
        .map_err(|e| format!("printed decimal {text:?}: {e}"))
}

/// Digits after the decimal point of a printed decimal.
pub fn places(text: &str) -> u32 {
    text.split_once('.').map_or(0, |(_, f)| f.len() as u32)
}

/// `10^p`.
pub fn pow10(p: u32) -> Rational {
    Rational::from_integer(10i64.pow(p))
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

/// `x` correctly rounded to `p` places, certified by exact comparisons.
pub fn decimal(x: &Radical, p: u32) -> String {
    let xs = x.scale(&pow10(p));
    let mut c = xs.to_f64().round() as i64;
    loop {
        let lo = radical(&Rational::new(2 * c - 1, 2).expect("2 != 0"));
        let hi = radical(&Rational::new(2 * c + 1, 2).expect("2 != 0"));
        if xs < lo {
            c -= 1;
        } else if xs >= hi {
            c += 1;
        } else {
            break;
        }
    }
    let unit = 10i64.pow(p);
    let sign = if c < 0 { "-" } else { "" };
    let a = c.abs();
    if p == 0 {
        format!("{sign}{a}")
    } else {
        format!("{sign}{}.{:0w$}", a / unit, a % unit, w = p as usize)
    }
}

/// `x` to about three significant digits, with its sign.
pub fn deviation_text(x: &Radical) -> String {
    if x.is_zero() {
        return "0".into();
    }
    let magnitude = x.to_f64().abs().log10().floor() as i32;
    let p = (2 - magnitude).clamp(0, 12) as u32;
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
    }
}
