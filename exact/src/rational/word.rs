//! Addition and multiplication of inline rationals whose numerators and denominators all fit
//! in one machine word (`i64`): the common case of polynomial coefficients. Every product of
//! two such parts is below `2^126` in magnitude and every sum of two products below `2^127`, so
//! the `i128` results need no overflow checks (the general inline kernels check every `i128`
//! product, a library call each). The methods are Henrici's, as in the general kernels.

use super::{div_small, Rational, Repr};
use crate::gcd::{gcd_u128, gcd_u64};

/// The four parts as words, when they all fit.
#[inline(always)]
pub(super) fn words(a: i128, b: i128, c: i128, d: i128) -> Option<(i64, i64, i64, i64)> {
    Some((
        i64::try_from(a).ok()?,
        i64::try_from(b).ok()?,
        i64::try_from(c).ok()?,
        i64::try_from(d).ok()?,
    ))
}

/// `gcd(|x|, y)` for `y >= 1` of one word and `x` of up to 128 bits.
#[inline]
fn gcd_with_word(x: i128, y: u64) -> i128 {
    match i64::try_from(x) {
        Ok(x) => gcd_u64(x.unsigned_abs(), y) as i128,
        Err(_) => gcd_u128(x.unsigned_abs(), u128::from(y)) as i128,
    }
}

/// `(a/b) (c/d)` for canonical word parts (`b, d >= 1`).
#[inline]
pub(super) fn mul_words(a: i64, b: i64, c: i64, d: i64) -> Rational {
    if a == 0 || c == 0 {
        return Rational::ZERO;
    }
    // Cancel the crossed gcds; `g <= d` (or `b`) is a positive word, so the divisions are exact
    // and cannot overflow.
    let (a, d) = match d {
        1 => (a, d),
        _ => match gcd_u64(a.unsigned_abs(), d as u64) as i64 {
            1 => (a, d),
            g => (a / g, d / g),
        },
    };
    let (c, b) = match b {
        1 => (c, b),
        _ => match gcd_u64(c.unsigned_abs(), b as u64) as i64 {
            1 => (c, b),
            g => (c / g, b / g),
        },
    };
    Rational(Repr::Small(
        i128::from(a) * i128::from(c),
        i128::from(b) * i128::from(d),
    ))
}

/// `a/b + c/d` for canonical word parts (`b, d >= 1`).
#[inline]
pub(super) fn add_words(a: i64, b: i64, c: i64, d: i64) -> Rational {
    let (a, b, c, d) = (i128::from(a), i128::from(b), i128::from(c), i128::from(d));
    if b == d {
        let s = a + c;
        if b == 1 {
            return Rational(Repr::Small(s, 1));
        }
        if s == 0 {
            return Rational::ZERO;
        }
        let g = gcd_with_word(s, b as u64);
        return Rational(Repr::Small(div_small(s, g), div_small(b, g)));
    }
    // a/b + c = (a + c b)/b, already reduced (and likewise with the roles swapped).
    if d == 1 {
        return Rational(Repr::Small(a + c * b, b));
    }
    if b == 1 {
        return Rational(Repr::Small(a * d + c, d));
    }
    let g = i128::from(gcd_u64(b as u64, d as u64));
    if g == 1 {
        let n = a * d + c * b;
        if n == 0 {
            return Rational::ZERO;
        }
        return Rational(Repr::Small(n, b * d));
    }
    let (b1, d1) = (b / g, d / g);
    let t = a * d1 + c * b1;
    if t == 0 {
        return Rational::ZERO;
    }
    let g2 = gcd_with_word(t, g as u64);
    Rational(Repr::Small(div_small(t, g2), b1 * (d / g2)))
}
