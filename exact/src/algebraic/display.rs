//! Printing [`Algebraic`] numbers in the expression syntax, so that the text reads back
//! ([`std::str::FromStr`]) as the same number where it is a radical:
//! * a rational number as itself (`-3/4`);
//! * a quadratic irrational as `(p + q*sqrt(r))/d` in lowest terms with `r` square-free as far as
//!   trial division by the primes below 1000 shows (`(1 + sqrt(5))/4`, `1 + sqrt(2)`,
//!   `-sqrt(2)/2`);
//! * a root of an even quartic `g(x^2)`, `g` quadratic, as `±sqrt(b)` with `b` the quadratic
//!   irrational `x^2`, pulling a square denominator out (`sqrt(2 + sqrt(2))/2`);
//! * anything else as `Root(f, lo, hi) ≈ decimal`: the defining polynomial in `x`, the isolating
//!   interval and 10 decimals of the value (`≈` marks the only approximate part).

use super::Algebraic;
use crate::univariate::UPoly;
use crate::{Radical, Rational};
use exactcheck_core::Sqrt;
use exactcheck_core::{Ring, Sign};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;

/// `n = s^2 * m` for `n > 0` with `m` free of squares of primes below 1000 (and not a square
/// itself): `(s, m)`.
fn square_part(n: &BigInt) -> (BigInt, BigInt) {
    let mut s = BigInt::one();
    let mut m = n.clone();
    let mut p = 2u32;
    while p < 1000 {
        let pp = BigInt::from(p * p);
        while (&m % &pp).is_zero() {
            m /= &pp;
            s *= p;
        }
        p += if p == 2 { 1 } else { 2 };
    }
    let r = m.sqrt();
    if &r * &r == m {
        s *= r;
        m = BigInt::one();
    }
    (s, m)
}

/// `(p + q sqrt(r)) / d` in the expression syntax, `d > 0`, `q != 0`, `r > 1` square-free.
fn fmt_quadratic(p: &BigInt, q: &BigInt, r: &BigInt, d: &BigInt) -> String {
    let g = p.gcd(q).gcd(d);
    let (p, q, d) = (p / &g, q / &g, d / &g);
    let surd = if q.abs().is_one() {
        format!("sqrt({r})")
    } else {
        format!("{}*sqrt({r})", q.abs())
    };
    let num = if p.is_zero() {
        if q.is_negative() {
            format!("-{surd}")
        } else {
            surd
        }
    } else {
        let op = if q.is_negative() { "-" } else { "+" };
        format!("{p} {op} {surd}")
    };
    match (d.is_one(), p.is_zero()) {
        (true, _) => num,
        (false, true) => format!("{num}/{d}"),
        (false, false) => format!("({num})/{d}"),
    }
}

/// The integer coefficients of the primitive `f`.
fn int_coeffs(f: &UPoly) -> Vec<BigInt> {
    f.coeffs().iter().map(Rational::numer).collect()
}

impl Algebraic {
    /// `(p, q, r, d)` with the number `(p + q sqrt(r)) / d`, for a quadratic irrational
    /// (defining polynomial of degree 2).
    fn quadratic_parts(&self) -> Option<(BigInt, BigInt, BigInt, BigInt)> {
        if self.poly.degree() != 2 {
            return None;
        }
        let c = int_coeffs(&self.poly);
        let (c0, b, a) = (&c[0], &c[1], &c[2]);
        let disc: BigInt = b * b - BigInt::from(4) * a * c0;
        let (s, r) = square_part(&disc);
        let two_a = BigInt::from(2) * a;
        let vertex = Rational::from(-b.clone())
            * Rational::from(two_a.clone())
                .recip()
                .expect("a quadratic's leading coefficient is not zero");
        let q = match self.compare(&Algebraic::from_rational(vertex)) {
            Ordering::Greater => s,
            _ => -s,
        };
        let p = -b.clone();
        let g = p.gcd(&q).gcd(&two_a);
        Some((p / &g, q / &g, r, two_a / &g))
    }

    /// The radical form of a quadratic irrational.
    fn quadratic_form(&self) -> Option<String> {
        let (p, q, r, d) = self.quadratic_parts()?;
        Some(fmt_quadratic(&p, &q, &r, &d))
    }

    /// `±sqrt(b)` for a root of an even quartic `g(x^2)` with `g` quadratic, denested by the
    /// square-root field ([`Radical`]) when the root is a sum of square roots of rationals
    /// (`sqrt(5 - 2*sqrt(6)) = -sqrt(2) + sqrt(3)`).
    fn nested_form(&self) -> Option<String> {
        let f = &self.poly;
        if !is_even_quartic(f) {
            return None;
        }
        let g = UPoly::from_coeffs(vec![f.coeff(0), f.coeff(2), f.coeff(4)]);
        let square = Algebraic::select(&g, true, |bits| Some(self.square_enclosure(bits)));
        let (p, q, r, d) = square.quadratic_parts()?;
        let negative = self.sign() == Sign::Negative;
        let inv_d = Rational::from(d.clone()).recip().ok()?;
        if let Some(root) = Radical::sqrt_rational(&Rational::from(r.clone())).and_then(|sr| {
            let beta = Radical::from(Rational::from(p.clone()) * &inv_d)
                + sr * Radical::from(Rational::from(q.clone()) * &inv_d);
            Sqrt::sqrt(&beta)
        }) {
            let root = if negative { -root } else { root };
            return Some(root.to_string_over_common_denominator());
        }
        let minus = if negative { "-" } else { "" };
        let s = d.sqrt();
        if &s * &s == d {
            // sqrt((p + q sqrt r)/s^2) = sqrt(p + q sqrt r)/s
            let num = fmt_quadratic(&p, &q, &r, &BigInt::one());
            let g = p.gcd(&q).gcd(&d);
            if g.is_one() {
                return Some(if s.is_one() {
                    format!("{minus}sqrt({num})")
                } else {
                    format!("{minus}sqrt({num})/{s}")
                });
            }
        }
        Some(format!("{minus}sqrt({})", fmt_quadratic(&p, &q, &r, &d)))
    }

    /// The value to `digits` decimals, rounded (an approximation for display only).
    pub fn to_decimal(&self, digits: u32) -> String {
        let scale = BigInt::from(10).pow(digits);
        let width = Rational::from(BigInt::from(4) * &scale)
            .recip()
            .expect("4 * 10^digits is not zero");
        let mid = match self.to_rational() {
            Some(q) => q.clone(),
            None => self.poly.refine(&self.iv, &width).midpoint(),
        };
        let scaled = mid * Rational::from(scale.clone());
        // round half away from zero
        let twice = scaled.scale_i64(2);
        let (n, d): (BigInt, BigInt) = (twice.numer(), twice.denom());
        let rounded: BigInt = if n.is_negative() {
            let m: BigInt = -n + &d;
            let q: BigInt = m / (d * 2);
            -q
        } else {
            let m: BigInt = n + &d;
            m / (d * 2)
        };
        let neg = rounded.is_negative();
        let mag = rounded.abs().to_string();
        let digits = digits as usize;
        let padded = format!("{mag:0>width$}", width = digits + 1);
        let (int, frac) = padded.split_at(padded.len() - digits);
        let sign = if neg { "-" } else { "" };
        if digits == 0 {
            format!("{sign}{int}")
        } else {
            format!("{sign}{int}.{frac}")
        }
    }
}

/// Whether an irrational number with minimal polynomial `f` may print as a radical
/// ([`Algebraic::radical_form`]): `f` is quadratic, or an even quartic. For any other `f` the
/// radical form is `None`, so a printer that has another form to offer need not build the
/// number at all.
pub(super) fn may_print_as_radical(f: &UPoly) -> bool {
    f.degree() == 2 || is_even_quartic(f)
}

/// Whether `f` is `g(x^2)` with `g` quadratic.
fn is_even_quartic(f: &UPoly) -> bool {
    f.degree() == 4 && f.coeff(1).is_zero() && f.coeff(3).is_zero()
}

impl Algebraic {
    /// The number as a rational or a radical when the display finds one (the quadratic and
    /// even-quartic forms above), `None` where it would print `Root(...)`: always `None` for an
    /// irrational number whose polynomial fails [`may_print_as_radical`].
    pub fn radical_form(&self) -> Option<String> {
        if let Some(q) = self.to_rational() {
            return Some(q.to_string());
        }
        self.quadratic_form().or_else(|| self.nested_form())
    }

    /// The printed number with the polynomial of a `Root(...)` written in the variable `var`
    /// (`Root(8*z^3 + 16*z^2 + 6*z - 1, 1/16, 1/8) ≈ 0.1234898019`): for a number shown next to
    /// a statement whose variables include `x`. Radicals and rationals print as with
    /// [`fmt::Display`].
    pub fn display_in(&self, var: &str) -> String {
        if let Some(s) = self.radical_form() {
            return s;
        }
        format!(
            "Root({}, {}, {}) ≈ {}",
            self.poly.display(var),
            self.iv.lo,
            self.iv.hi,
            self.to_decimal(10)
        )
    }
}

/// The variable for the polynomial of a `Root(...)` shown next to a statement: `x` when the
/// statement has no variable (a value alone prints as it always has), else the first of `z`,
/// `z1`, `z2`, ... that `taken` (the statement's variable names) does not contain.
pub fn root_variable<S: AsRef<str>>(taken: &[S]) -> String {
    if taken.is_empty() {
        return "x".to_string();
    }
    std::iter::once("z".to_string())
        .chain((1..).map(|i| format!("z{i}")))
        .find(|n| !taken.iter().any(|t| t.as_ref() == n))
        .expect("some name is free")
}

impl fmt::Display for Algebraic {
    /// See the module documentation of `exact/src/algebraic/display.rs`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.display_in("x"))
    }
}

impl fmt::Debug for Algebraic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}
