//! [`UPoly`] arithmetic: construction, division with remainder, primitive gcds, square-free
//! decomposition, evaluation, printing and the ring operators.

use super::*;
use crate::poly::Poly;
use exactcheck_core::ZeroDivisor;
use num_traits::One;
use std::fmt;
use std::ops::Mul;

// ------------------------------------------------------------------------------ UPoly basics

impl UPoly {
    /// The zero polynomial.
    pub fn zero() -> UPoly {
        UPoly { coeffs: Vec::new() }
    }

    /// The constant polynomial `1`.
    pub fn one() -> UPoly {
        UPoly::constant(Rational::ONE)
    }

    /// The constant polynomial `c`.
    pub fn constant(c: Rational) -> UPoly {
        UPoly::from_coeffs(vec![c])
    }

    /// The polynomial `x`.
    pub fn x() -> UPoly {
        UPoly::monomial(Rational::ONE, 1)
    }

    /// The polynomial `c * x^k`.
    pub fn monomial(c: Rational, k: usize) -> UPoly {
        let mut coeffs = vec![Rational::ZERO; k];
        coeffs.push(c);
        UPoly::from_coeffs(coeffs)
    }

    /// The polynomial with these coefficients, **from the constant term up**
    /// (`[1, 0, 3]` is `3*x^2 + 1`); trailing zeros are dropped.
    pub fn from_coeffs(mut coeffs: Vec<Rational>) -> UPoly {
        while coeffs.last().is_some_and(Ring::is_zero) {
            coeffs.pop();
        }
        UPoly { coeffs }
    }

    /// The polynomial with these integer coefficients, from the constant term up.
    pub fn from_i64_coeffs(coeffs: &[i64]) -> UPoly {
        UPoly::from_coeffs(coeffs.iter().map(|&c| Rational::from_integer(c)).collect())
    }

    /// The monic polynomial `prod_i (x - r_i)` (repeated roots give repeated factors).
    pub fn from_roots(roots: &[Rational]) -> UPoly {
        roots.iter().fold(UPoly::one(), |acc, r| {
            acc.mul_impl(&UPoly::from_coeffs(vec![-r, Rational::ONE]))
        })
    }

    /// The coefficients from the constant term up (empty for the zero polynomial).
    pub fn coeffs(&self) -> &[Rational] {
        &self.coeffs
    }

    /// The coefficient of `x^k` (zero beyond the degree).
    pub fn coeff(&self, k: usize) -> Rational {
        self.coeffs.get(k).cloned().unwrap_or(Rational::ZERO)
    }

    /// The degree; **0 for the zero polynomial** (check [`UPoly::is_zero`] where it matters).
    pub fn degree(&self) -> usize {
        self.coeffs.len().saturating_sub(1)
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// Whether this is a constant (including zero).
    pub fn is_constant(&self) -> bool {
        self.coeffs.len() <= 1
    }

    /// The leading coefficient (zero for the zero polynomial).
    pub fn leading_coefficient(&self) -> Rational {
        self.coeffs.last().cloned().unwrap_or(Rational::ZERO)
    }

    /// The value at `x` (Horner's scheme, exact).
    pub fn eval(&self, x: &Rational) -> Rational {
        if x.is_zero() {
            return self.coeff(0);
        }
        let mut acc = Rational::ZERO;
        for c in self.coeffs.iter().rev() {
            acc = acc.mul_ref(x).add_ref(c);
        }
        acc
    }

    /// The exact sign of the value at `x`.
    pub fn sign_at(&self, x: &Rational) -> Sign {
        self.eval(x).signum()
    }

    /// The sign for all sufficiently large `x` (the sign of the leading coefficient).
    pub fn sign_at_pos_inf(&self) -> Sign {
        self.leading_coefficient().signum()
    }

    /// The sign for all sufficiently negative `x`.
    pub fn sign_at_neg_inf(&self) -> Sign {
        let s = self.sign_at_pos_inf();
        if self.degree() % 2 == 1 {
            sign_neg(s)
        } else {
            s
        }
    }

    /// The derivative.
    pub fn derivative(&self) -> UPoly {
        UPoly::from_coeffs(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| c.mul_ref(&Rational::from_integer(k as i64)))
                .collect(),
        )
    }

    /// `c * self`.
    pub fn scale(&self, c: &Rational) -> UPoly {
        if c.is_zero() {
            return UPoly::zero();
        }
        UPoly {
            coeffs: self.coeffs.iter().map(|a| a.mul_ref(c)).collect(),
        }
    }

    /// The composition `self(q(x))`.
    pub fn compose(&self, q: &UPoly) -> UPoly {
        let mut acc = UPoly::zero();
        for c in self.coeffs.iter().rev() {
            acc = acc.mul_impl(q).add_impl(&UPoly::constant(c.clone()));
        }
        acc
    }

    /// The monic associate `self / leading_coefficient` (zero stays zero).
    pub fn monic(&self) -> UPoly {
        match self.coeffs.last() {
            None => UPoly::zero(),
            Some(lc) if lc.is_one() => self.clone(),
            Some(lc) => self.scale(&lc.recip().expect("the leading coefficient is not zero")),
        }
    }

    /// The content: the positive rational `c` such that `self / c` has integer coefficients with
    /// gcd 1 (zero for the zero polynomial). The sign stays with the primitive part.
    pub fn content(&self) -> Rational {
        if self.is_zero() {
            return Rational::ZERO;
        }
        let mut num_gcd = num_bigint::BigUint::from(0u32);
        let mut den_lcm = BigInt::one();
        for c in &self.coeffs {
            if c.is_zero() {
                continue;
            }
            num_gcd = crate::gcd::gcd_biguint(&num_gcd, c.numer().magnitude());
            let d = c.denom();
            if !d.is_one() {
                let g = BigInt::from(crate::gcd::gcd_bigint_abs(&den_lcm, &d));
                den_lcm = &den_lcm / g * d;
            }
        }
        Rational::from(BigInt::from(num_gcd))
            * Rational::from(den_lcm)
                .recip()
                .expect("a product of denominators is not zero")
    }

    /// The primitive part `self / content`: integer coefficients with gcd 1 and the sign of
    /// `self` (zero stays zero).
    pub fn primitive_part(&self) -> UPoly {
        let c = self.content();
        if c.is_zero() || c.is_one() {
            return self.clone();
        }
        self.scale(&c.recip().expect("the content checked non-zero above"))
    }

    /// `self * x^k`.
    pub fn shift_up(&self, k: usize) -> UPoly {
        if self.is_zero() {
            return UPoly::zero();
        }
        let mut coeffs = vec![Rational::ZERO; k];
        coeffs.extend(self.coeffs.iter().cloned());
        UPoly { coeffs }
    }

    // ------------------------------------------------------------------ arithmetic kernels

    pub(super) fn add_impl(&self, rhs: &UPoly) -> UPoly {
        let (long, short) = if self.coeffs.len() >= rhs.coeffs.len() {
            (self, rhs)
        } else {
            (rhs, self)
        };
        let mut coeffs = long.coeffs.clone();
        for (a, b) in coeffs.iter_mut().zip(&short.coeffs) {
            *a += b;
        }
        UPoly::from_coeffs(coeffs)
    }

    pub(super) fn neg_impl(&self) -> UPoly {
        UPoly {
            coeffs: self.coeffs.iter().map(Ring::neg_ref).collect(),
        }
    }

    pub(super) fn sub_impl(&self, rhs: &UPoly) -> UPoly {
        let n = self.coeffs.len().max(rhs.coeffs.len());
        let coeffs = (0..n)
            .map(|k| match (self.coeffs.get(k), rhs.coeffs.get(k)) {
                (Some(a), Some(b)) => a.sub_ref(b),
                (Some(a), None) => a.clone(),
                (None, Some(b)) => b.neg_ref(),
                (None, None) => Rational::ZERO,
            })
            .collect();
        UPoly::from_coeffs(coeffs)
    }

    pub(super) fn mul_impl(&self, rhs: &UPoly) -> UPoly {
        if self.is_zero() || rhs.is_zero() {
            return UPoly::zero();
        }
        let mut coeffs = vec![Rational::ZERO; self.coeffs.len() + rhs.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for (j, b) in rhs.coeffs.iter().enumerate() {
                if !b.is_zero() {
                    coeffs[i + j] += a.mul_ref(b);
                }
            }
        }
        // The product of the leading coefficients is non-zero: no trailing zero.
        UPoly { coeffs }
    }

    // ------------------------------------------------------------------ division and gcd

    /// Division with remainder: `(q, r)` with `self = q * d + r` and `r = 0` or
    /// `deg r < deg d`, or [`ZeroDivisor`] when `d` is zero.
    pub fn checked_div_rem(&self, d: &UPoly) -> Result<(UPoly, UPoly), ZeroDivisor> {
        let Some(lc) = d.coeffs.last() else {
            return Err(ZeroDivisor);
        };
        if self.coeffs.len() < d.coeffs.len() {
            return Ok((UPoly::zero(), self.clone()));
        }
        let lc_inv = lc.recip()?;
        let dd = d.degree();
        let n = self.degree();
        let mut r = self.coeffs.clone();
        let mut q = vec![Rational::ZERO; n - dd + 1];
        for k in (0..=n - dd).rev() {
            let c = r[k + dd].mul_ref(&lc_inv);
            if c.is_zero() {
                continue;
            }
            for (j, dj) in d.coeffs.iter().enumerate().take(dd) {
                if !dj.is_zero() {
                    r[k + j] -= c.mul_ref(dj);
                }
            }
            r[k + dd] = Rational::ZERO;
            q[k] = c;
        }
        r.truncate(dd);
        Ok((UPoly::from_coeffs(q), UPoly::from_coeffs(r)))
    }

    /// Division with remainder: `(q, r)` with `self = q * d + r` and `r = 0` or `deg r < deg d`.
    ///
    /// # Panics
    /// When `d` is the zero polynomial (use [`UPoly::checked_div_rem`] to get an error instead).
    pub fn div_rem(&self, d: &UPoly) -> (UPoly, UPoly) {
        self.checked_div_rem(d)
            .expect("UPoly::div_rem: division by the zero polynomial")
    }

    /// The remainder of [`UPoly::div_rem`].
    ///
    /// # Panics
    /// When `d` is the zero polynomial.
    pub fn rem(&self, d: &UPoly) -> UPoly {
        self.div_rem(d).1
    }

    /// Whether `d` divides `self` (`0` divides only `0`).
    pub fn is_divisible_by(&self, d: &UPoly) -> bool {
        if d.is_zero() {
            return self.is_zero();
        }
        self.rem(d).is_zero()
    }

    /// The quotient of a division known to be exact.
    pub(super) fn exact_div(&self, d: &UPoly) -> UPoly {
        let (q, r) = self.div_rem(d);
        debug_assert!(r.is_zero(), "inexact division");
        q
    }

    /// The monic greatest common divisor (`gcd(0, 0) = 0`), by the primitive remainder sequence.
    pub fn gcd(&self, other: &UPoly) -> UPoly {
        let (mut a, mut b) = (self.primitive_part(), other.primitive_part());
        if a.degree() < b.degree() {
            std::mem::swap(&mut a, &mut b);
        }
        while !b.is_zero() {
            let r = a.rem(&b).primitive_part();
            a = b;
            b = r;
        }
        a.monic()
    }

    /// The monic square-free part `self / gcd(self, self')`: the same distinct roots (real and
    /// complex), each simple. Zero stays zero; a non-zero constant gives `1`.
    pub fn square_free_part(&self) -> UPoly {
        if self.is_zero() {
            return UPoly::zero();
        }
        let g = self.gcd(&self.derivative());
        self.exact_div(&g).monic()
    }

    /// Yun's square-free decomposition: pairs `(f_i, i)` with `f_i` monic, square-free, pairwise
    /// coprime and of positive degree, increasing `i`, such that
    /// `self = leading_coefficient * prod f_i^i`. Empty for constants (and for zero).
    pub fn square_free_decomposition(&self) -> Vec<(UPoly, u32)> {
        let mut out = Vec::new();
        if self.is_constant() {
            return out;
        }
        let p = self.monic();
        let dp = p.derivative();
        let a = p.gcd(&dp);
        let mut b = p.exact_div(&a);
        let c = dp.exact_div(&a);
        let mut d = c.sub_impl(&b.derivative());
        let mut i = 1u32;
        while !b.is_constant() {
            let f = b.gcd(&d);
            b = b.exact_div(&f);
            let c = d.exact_div(&f);
            d = c.sub_impl(&b.derivative());
            if !f.is_constant() {
                out.push((f, i));
            }
            i += 1;
        }
        out
    }

    // ------------------------------------------------------------------ conversions

    /// The univariate polynomial of a [`Poly`] in which at most the variable `var` occurs.
    ///
    /// # Errors
    /// [`FromPolyError::OtherVariable`] when another variable occurs,
    /// [`FromPolyError::DegreeTooLarge`] beyond [`MAX_FROM_POLY_DEGREE`].
    pub fn from_poly(p: &Poly<Rational>, var: Var) -> Result<UPoly, FromPolyError> {
        if let Some(&v) = p.variables().iter().find(|&&v| v != var) {
            return Err(FromPolyError::OtherVariable(v));
        }
        let deg = p.degree_in(var);
        if deg > MAX_FROM_POLY_DEGREE {
            return Err(FromPolyError::DegreeTooLarge(deg));
        }
        let mut coeffs = vec![Rational::ZERO; deg as usize + 1];
        for (m, c) in p.terms() {
            coeffs[m.exponent(var) as usize] += c;
        }
        Ok(UPoly::from_coeffs(coeffs))
    }

    /// The same polynomial as a [`Poly`] in the variable `var`.
    pub fn to_poly(&self, var: Var) -> Poly<Rational> {
        Poly::from_terms(
            self.coeffs
                .iter()
                .enumerate()
                .filter(|(_, c)| !c.is_zero())
                .map(|(k, c)| ([(var, k as u32)], c.clone())),
        )
    }

    /// The polynomial printed with the variable name `var`, e.g. `3*x^2 - 1/2*x + 1` (the
    /// expression syntax of [`crate::expr`]; it parses back to the same polynomial).
    pub fn display<'a>(&'a self, var: &'a str) -> UPolyDisplay<'a> {
        UPolyDisplay { poly: self, var }
    }
}

/// A [`UPoly`] with its variable name, for printing ([`UPoly::display`]).
pub struct UPolyDisplay<'a> {
    pub(super) poly: &'a UPoly,
    pub(super) var: &'a str,
}

impl fmt::Display for UPolyDisplay<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let terms = self.poly.coeffs.iter().enumerate().rev();
        write_terms(
            f,
            self.var,
            terms.filter(|(_, c)| !c.is_zero()).map(|(k, c)| {
                let s = c.to_string();
                match s.strip_prefix('-') {
                    Some(rest) => (k, true, rest.to_string()),
                    None => (k, false, s),
                }
            }),
        )
    }
}

/// Writes the polynomial in `var` with the non-zero terms `(degree, negative, magnitude)`,
/// highest degree first (`magnitude` the text of the coefficient's absolute value), as
/// `3*x^2 - 1/2*x + 1`, and `0` for no terms: the one layout of [`UPoly::display`] and of the
/// polynomials with coefficients in a number field (`crate::algebraic::FieldUPoly`), which
/// differ only in how a coefficient is written.
pub(crate) fn write_terms(
    f: &mut fmt::Formatter<'_>,
    var: &str,
    terms: impl Iterator<Item = (usize, bool, String)>,
) -> fmt::Result {
    let mut first = true;
    for (k, negative, mag) in terms {
        match (first, negative) {
            (true, true) => f.write_str("-")?,
            (true, false) => {}
            (false, true) => f.write_str(" - ")?,
            (false, false) => f.write_str(" + ")?,
        }
        first = false;
        if k == 0 {
            f.write_str(&mag)?;
        } else {
            if mag != "1" {
                write!(f, "{mag}*")?;
            }
            f.write_str(var)?;
            if k > 1 {
                write!(f, "^{k}")?;
            }
        }
    }
    if first {
        f.write_str("0")?;
    }
    Ok(())
}

impl fmt::Display for UPoly {
    /// The expression syntax with the variable `x`; see [`UPoly::display`] for another name.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.display("x"), f)
    }
}

impl fmt::Debug for UPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.display("x"), f)
    }
}

// ------------------------------------------------------------------------------ operators

exactcheck_core::ring_ops! {
    impl[] UPoly;
    Neg::neg: |a| a.neg_impl();
    Add::add, AddAssign::add_assign: |a, b| a.add_impl(b);
    Sub::sub, SubAssign::sub_assign: |a, b| a.sub_impl(b);
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_impl(b);
}

impl Mul<&Rational> for &UPoly {
    type Output = UPoly;
    /// Multiplication by a scalar.
    fn mul(self, rhs: &Rational) -> UPoly {
        self.scale(rhs)
    }
}

impl Mul<&Rational> for UPoly {
    type Output = UPoly;
    /// Multiplication by a scalar.
    fn mul(self, rhs: &Rational) -> UPoly {
        self.scale(rhs)
    }
}

impl Mul<Rational> for UPoly {
    type Output = UPoly;
    /// Multiplication by a scalar.
    fn mul(self, rhs: Rational) -> UPoly {
        self.scale(&rhs)
    }
}

impl From<Rational> for UPoly {
    fn from(c: Rational) -> Self {
        UPoly::constant(c)
    }
}

ring_by_impls! {
    UPoly;
    zero: UPoly::zero();
    one: UPoly::one();
    from_i64: |n| UPoly::constant(Rational::from_integer(n));
    is_zero: |p| p.coeffs.is_empty();
}
