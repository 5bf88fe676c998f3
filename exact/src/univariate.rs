//! Dense univariate polynomials over [`Rational`] and exact real root isolation.
//!
//! The question this module answers for the rest of the workspace is SPEC §2's: with the rational
//! circle parameter `tau`, the discriminant `A(t)^2 - B(t)` of Spaeth's cylinder/sphere
//! intersection, times `(1 + tau^2)^2`, is a polynomial `D(tau)` with rational coefficients, and the
//! surfaces meet exactly where `D >= 0`. [`UPoly::nonnegative_set`] describes that set exactly, as a
//! union of closed intervals whose finite endpoints are real roots of `D`, each isolated by a
//! [`RootInterval`] with rational endpoints (or given exactly, when the root is rational).
//! Nothing here uses floating point for a decision.
//!
//! A caveat for SPEC §2's callers: `tau = tan(t/2)` misses `t = pi`. The sign there is the sign
//! of the limit of `D(tau) / (1 + tau^2)^2` as `tau -> inf`, i.e. of the coefficient of `tau^4`
//! (zero if the degree dropped below 4); check it separately.
//!
//! # Representation
//! A [`UPoly`] is the vector of its coefficients from the constant term up, without trailing
//! zeros (the zero polynomial is the empty vector), so the representation is canonical and `==`
//! is equality of polynomials. [`UPoly`] implements [`Ring`].
//!
//! # Algorithms
//! * Division with remainder over Q; gcds by Euclid's algorithm in which every remainder is
//!   replaced by its primitive part (integer coefficients with gcd 1, see [`UPoly::content`]):
//!   the *primitive remainder sequence*, which keeps the coefficients as small as the remainders'
//!   true sizes instead of letting the denominators grow as in the plain rational sequence.
//! * Square-free parts `p / gcd(p, p')` and Yun's square-free decomposition
//!   ([`UPoly::square_free_decomposition`]); root multiplicities come from the latter.
//! * Sturm sequences, likewise normalised to primitive polynomials (positive factors only, which
//!   leaves every sign, hence every sign-variation count, unchanged). Counting uses the Sturm
//!   sequence of the square-free part: the number of distinct roots in `(a, b]` is
//!   `V(a) - V(b)`, also when `a` or `b` is a root.
//! * Isolation by bisection of `(-2^k, 2^k)`, with `2^k` above Cauchy's root bound, driven by
//!   Sturm counts; a midpoint that is a root is recorded exactly and the bisection continues
//!   from non-roots on either side of it (so no interval ever ends at a root). Afterwards every
//!   interval is tested for a *rational* root: if the primitive square-free part has leading coefficient `l`,
//!   a rational root `p/q` has `q | l` (rational root theorem), so `l * root` is an integer;
//!   bisecting until the interval is shorter than `1/l` leaves at most one candidate `k / l`,
//!   which is evaluated exactly. Hence [`RootInterval::is_exact`] holds **exactly when the root is
//!   rational**.
//! * Refinement ([`UPoly::refine`]) bisects on the sign of the square-free part, which changes
//!   across every isolated root.
//! * The sign on each gap between consecutive roots ([`UPoly::sign_chart`]) follows from the
//!   leading coefficient and the multiplicities, without further evaluation.
//!
//! # Limits
//! Dense representation: fine for the low degrees of the workspace (the discriminants are of
//! degree at most 4), usable into the tens; Sturm sequences cost `O(n^2)` polynomial
//! operations. Isolation of irrational roots bisects about `log2(l * 2^k)` times per root, `l` as
//! above, so a square-free part with a huge leading coefficient makes it slower, never wrong.

use crate::poly::{Poly, Var};
use crate::Rational;
use exactcheck_core::{Ring, Sign, ZeroDivisor};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::One;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// The largest degree [`UPoly::from_poly`] accepts (the representation is dense).
pub const MAX_FROM_POLY_DEGREE: u32 = 1 << 16;

/// A dense univariate polynomial with [`Rational`] coefficients, in canonical form (see the
/// module documentation).
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct UPoly {
    /// Coefficients from degree 0 up; the last one (if any) is non-zero.
    coeffs: Vec<Rational>,
}

/// The error of [`UPoly::from_poly`].
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FromPolyError {
    /// A variable other than the requested one occurs.
    #[error("the polynomial is not univariate: variable #{0} occurs besides the requested one")]
    OtherVariable(Var),
    /// The degree exceeds [`MAX_FROM_POLY_DEGREE`].
    #[error("degree {0} is too large for a dense univariate polynomial")]
    DegreeTooLarge(u32),
}

/// An isolating interval of one real root of a polynomial.
///
/// Either `lo == hi`, and the root is exactly that rational number, or `lo < hi`, and the root
/// lies in the **open** interval `(lo, hi)`, which contains no other root; then neither endpoint
/// is a root. The intervals returned by [`UPoly::isolate_roots`] are exact exactly when the root
/// is rational.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct RootInterval {
    /// The lower end.
    pub lo: Rational,
    /// The upper end (`>= lo`).
    pub hi: Rational,
}

/// A real root with its multiplicity.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Root {
    /// The isolating interval.
    pub interval: RootInterval,
    /// The multiplicity (`>= 1`).
    pub multiplicity: u32,
}

/// The signs of a polynomial along the real line: its distinct real roots, increasing, and its
/// (constant) sign on each gap between them.
///
/// `gaps.len() == roots.len() + 1`: `gaps[0]` is the sign on `(-inf, root 0)`, `gaps[i]` on
/// `(root i-1, root i)`, the last on `(last root, +inf)`. For the zero polynomial `roots` is
/// empty and `gaps == [Sign::Zero]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SignChart {
    /// The distinct real roots, increasing.
    pub roots: Vec<Root>,
    /// The sign on each open gap.
    pub gaps: Vec<Sign>,
}

/// An end of an [`Interval`]: an infinity or a real root.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Bound {
    /// Minus infinity (the interval is unbounded below).
    NegInf,
    /// A real root of the polynomial the interval was computed for (included in the interval).
    Root(RootInterval),
    /// Plus infinity (the interval is unbounded above).
    PosInf,
}

/// A closed interval of the real line, possibly unbounded or a single point: the set of `x` with
/// `lo <= x <= hi` (a finite end is included, an infinite end is not a point).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Interval {
    /// The lower end ([`Bound::NegInf`] or a root).
    pub lo: Bound,
    /// The upper end (a root or [`Bound::PosInf`]).
    pub hi: Bound,
}

// ------------------------------------------------------------------------------ small helpers

fn half() -> Rational {
    Rational::new(1, 2).unwrap_or(Rational::ONE)
}

fn midpoint(a: &Rational, b: &Rational) -> Rational {
    a.add_ref(b) * half()
}

/// `floor(x)` as an integer.
fn floor(x: &Rational) -> BigInt {
    x.numer().div_floor(&x.denom())
}

fn sign_neg(s: Sign) -> Sign {
    match s {
        Sign::Negative => Sign::Positive,
        Sign::Zero => Sign::Zero,
        Sign::Positive => Sign::Negative,
    }
}

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
            Some(lc) => self.scale(&lc.recip().unwrap_or(Rational::ONE)),
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
        Rational::from(BigInt::from(num_gcd)) * Rational::from(den_lcm).recip().unwrap_or_default()
    }

    /// The primitive part `self / content`: integer coefficients with gcd 1 and the sign of
    /// `self` (zero stays zero).
    pub fn primitive_part(&self) -> UPoly {
        let c = self.content();
        if c.is_zero() || c.is_one() {
            return self.clone();
        }
        self.scale(&c.recip().unwrap_or(Rational::ONE))
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

    fn add_impl(&self, rhs: &UPoly) -> UPoly {
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

    fn neg_impl(&self) -> UPoly {
        UPoly {
            coeffs: self.coeffs.iter().map(Ring::neg_ref).collect(),
        }
    }

    fn sub_impl(&self, rhs: &UPoly) -> UPoly {
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

    fn mul_impl(&self, rhs: &UPoly) -> UPoly {
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
    fn exact_div(&self, d: &UPoly) -> UPoly {
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
    poly: &'a UPoly,
    var: &'a str,
}

impl fmt::Display for UPolyDisplay<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.poly.is_zero() {
            return f.write_str("0");
        }
        let mut first = true;
        for (k, c) in self.poly.coeffs.iter().enumerate().rev() {
            if c.is_zero() {
                continue;
            }
            let s = c.to_string();
            let (negative, mag) = match s.strip_prefix('-') {
                Some(rest) => (true, rest),
                None => (false, s.as_str()),
            };
            match (first, negative) {
                (true, true) => f.write_str("-")?,
                (true, false) => {}
                (false, true) => f.write_str(" - ")?,
                (false, false) => f.write_str(" + ")?,
            }
            first = false;
            if k == 0 {
                f.write_str(mag)?;
            } else {
                if mag != "1" {
                    write!(f, "{mag}*")?;
                }
                f.write_str(self.var)?;
                if k > 1 {
                    write!(f, "^{k}")?;
                }
            }
        }
        Ok(())
    }
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

macro_rules! upoly_binop {
    ($tr:ident, $m:ident, $atr:ident, $am:ident, $k:ident) => {
        impl<'a, 'b> $tr<&'b UPoly> for &'a UPoly {
            type Output = UPoly;
            fn $m(self, rhs: &'b UPoly) -> UPoly {
                self.$k(rhs)
            }
        }
        impl<'b> $tr<&'b UPoly> for UPoly {
            type Output = UPoly;
            fn $m(self, rhs: &'b UPoly) -> UPoly {
                self.$k(rhs)
            }
        }
        impl<'a> $tr<UPoly> for &'a UPoly {
            type Output = UPoly;
            fn $m(self, rhs: UPoly) -> UPoly {
                self.$k(&rhs)
            }
        }
        impl $tr<UPoly> for UPoly {
            type Output = UPoly;
            fn $m(self, rhs: UPoly) -> UPoly {
                self.$k(&rhs)
            }
        }
        impl<'b> $atr<&'b UPoly> for UPoly {
            fn $am(&mut self, rhs: &'b UPoly) {
                *self = self.$k(rhs);
            }
        }
        impl $atr<UPoly> for UPoly {
            fn $am(&mut self, rhs: UPoly) {
                *self = self.$k(&rhs);
            }
        }
    };
}

upoly_binop!(Add, add, AddAssign, add_assign, add_impl);
upoly_binop!(Sub, sub, SubAssign, sub_assign, sub_impl);
upoly_binop!(Mul, mul, MulAssign, mul_assign, mul_impl);

impl Neg for UPoly {
    type Output = UPoly;
    fn neg(self) -> UPoly {
        self.neg_impl()
    }
}

impl Neg for &UPoly {
    type Output = UPoly;
    fn neg(self) -> UPoly {
        self.neg_impl()
    }
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

impl Ring for UPoly {
    fn zero() -> Self {
        UPoly::zero()
    }
    fn one() -> Self {
        UPoly::one()
    }
    fn from_i64(n: i64) -> Self {
        UPoly::constant(Rational::from_integer(n))
    }
    fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.sub_impl(rhs)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(rhs)
    }
    fn neg_ref(&self) -> Self {
        self.neg_impl()
    }
}

// ------------------------------------------------------------------------------ Sturm chains

/// The Sturm sequence of a non-zero polynomial, normalised to primitive parts after `p`.
fn sturm_chain(p: &UPoly) -> Vec<UPoly> {
    let mut seq = vec![p.clone()];
    let d = p.derivative();
    if d.is_zero() {
        return seq;
    }
    seq.push(d.primitive_part());
    loop {
        let n = seq.len();
        let r = seq[n - 2].rem(&seq[n - 1]);
        if r.is_zero() {
            return seq;
        }
        seq.push(r.neg_impl().primitive_part());
    }
}

/// Number of sign changes of a sequence of signs, zeros skipped.
fn count_variations(signs: impl IntoIterator<Item = Sign>) -> usize {
    let mut last = Sign::Zero;
    let mut n = 0;
    for s in signs {
        if s == Sign::Zero {
            continue;
        }
        if last != Sign::Zero && s != last {
            n += 1;
        }
        last = s;
    }
    n
}

/// The number of sign variations of a Sturm sequence at `x`.
pub fn sign_variations(seq: &[UPoly], x: &Rational) -> usize {
    count_variations(seq.iter().map(|p| p.sign_at(x)))
}

/// The square-free part of a polynomial prepared for root finding: primitive, positive leading
/// coefficient, with its Sturm chain.
struct SquareFree {
    chain: Vec<UPoly>,
}

impl SquareFree {
    /// For a non-zero polynomial.
    fn new(p: &UPoly) -> SquareFree {
        let sqf = p.square_free_part().primitive_part();
        SquareFree {
            chain: sturm_chain(&sqf),
        }
    }

    fn poly(&self) -> &UPoly {
        &self.chain[0]
    }

    fn var_at(&self, x: &Rational) -> usize {
        sign_variations(&self.chain, x)
    }

    fn var_neg_inf(&self) -> usize {
        count_variations(self.chain.iter().map(UPoly::sign_at_neg_inf))
    }

    fn var_pos_inf(&self) -> usize {
        count_variations(self.chain.iter().map(UPoly::sign_at_pos_inf))
    }

    /// A power of two strictly above Cauchy's bound `1 + max |a_i / a_n|`: every real root lies
    /// strictly inside `(-b, b)`.
    fn root_bound(&self) -> Rational {
        let p = self.poly();
        let lc = p.leading_coefficient();
        let lc_abs = if lc.signum() == Sign::Negative {
            -lc
        } else {
            lc
        };
        let mut m = Rational::ZERO;
        for c in &p.coeffs[..p.coeffs.len() - 1] {
            let a = if c.signum() == Sign::Negative {
                c.neg_ref()
            } else {
                c.clone()
            };
            if a > m {
                m = a;
            }
        }
        let bound = Rational::ONE + m / lc_abs;
        let mut b = Rational::ONE;
        let two = Rational::from_integer(2);
        while b <= bound {
            b *= &two;
        }
        b
    }

    /// Isolating intervals of all real roots, sorted; rational roots exact.
    fn isolate(&self) -> Vec<RootInterval> {
        let p = self.poly();
        if p.is_constant() {
            return Vec::new();
        }
        let b = self.root_bound();
        let lo = b.neg_ref();
        let (vlo, vhi) = (self.var_neg_inf(), self.var_pos_inf());
        let mut out = Vec::new();
        // (a, b, V(a), V(b), number of roots in the open interval); endpoints are never roots.
        let mut stack = vec![(lo, b, vlo, vhi, vlo - vhi)];
        while let Some((a, c, va, vc, count)) = stack.pop() {
            match count {
                0 => {}
                1 => out.push(RootInterval { lo: a, hi: c }),
                _ => {
                    let m = midpoint(&a, &c);
                    let vm = self.var_at(&m);
                    if p.sign_at(&m) != Sign::Zero {
                        stack.push((m.clone(), c, vm, vc, vm - vc));
                        stack.push((a, m, va, vm, va - vm));
                        continue;
                    }
                    // The midpoint is a root: record it exactly, and split at non-roots `ml < m <
                    // mr` close enough that `[ml, mr]` holds no other root, so that no interval
                    // ever has a root as an end. (`V(m)` ignores the zero at `m`, so it counts
                    // the roots in `(m, +inf)`.)
                    out.push(RootInterval::exact(m.clone()));
                    let mut d = c.sub_ref(&m).mul_ref(&half());
                    let (ml, vml, mr, vmr) = loop {
                        let (ml, mr) = (m.sub_ref(&d), m.add_ref(&d));
                        if p.sign_at(&ml) != Sign::Zero && p.sign_at(&mr) != Sign::Zero {
                            let (vml, vmr) = (self.var_at(&ml), self.var_at(&mr));
                            if vml - vmr == 1 {
                                break (ml, vml, mr, vmr);
                            }
                        }
                        d *= half();
                    };
                    stack.push((mr, c, vmr, vc, vmr - vc));
                    stack.push((a, ml, va, vml, va - vml));
                }
            }
        }
        out.sort_by(|x, y| x.lo.cmp(&y.lo).then_with(|| x.hi.cmp(&y.hi)));
        out.into_iter().map(|ri| self.exactify(ri)).collect()
    }

    /// Bisects `(lo, hi)` (an isolating interval, `s_lo` the sign at `lo`) once; returns the exact
    /// root if the midpoint is one.
    fn bisect(&self, lo: &mut Rational, hi: &mut Rational, s_lo: Sign) -> Option<Rational> {
        let m = midpoint(lo, hi);
        let s = self.poly().sign_at(&m);
        if s == Sign::Zero {
            return Some(m);
        }
        if s == s_lo {
            *lo = m;
        } else {
            *hi = m;
        }
        None
    }

    /// Makes the interval exact if its root is rational (see the module documentation).
    fn exactify(&self, ri: RootInterval) -> RootInterval {
        if ri.is_exact() {
            return ri;
        }
        let p = self.poly();
        let l = p.leading_coefficient(); // a positive integer
        let s_lo = p.sign_at(&ri.lo);
        let (mut lo, mut hi) = (ri.lo, ri.hi);
        while (hi.sub_ref(&lo)).mul_ref(&l) >= Rational::ONE {
            if let Some(r) = self.bisect(&mut lo, &mut hi, s_lo) {
                return RootInterval::exact(r);
            }
        }
        // At most one integer k with lo * l < k < hi * l.
        let k = floor(&lo.mul_ref(&l)) + 1;
        let cand = Rational::from(k) / &l;
        if cand < hi && p.sign_at(&cand) == Sign::Zero {
            return RootInterval::exact(cand);
        }
        RootInterval { lo, hi }
    }

    /// Refines an isolating interval to width at most `width`.
    fn refine(&self, ri: &RootInterval, width: &Rational) -> RootInterval {
        if ri.is_exact() {
            return ri.clone();
        }
        let p = self.poly();
        let s_lo = p.sign_at(&ri.lo);
        let s_hi = p.sign_at(&ri.hi);
        assert!(
            s_lo != Sign::Zero && s_hi == sign_neg(s_lo),
            "UPoly::refine: {ri} is not an isolating interval of a root of this polynomial"
        );
        if ri.width() <= *width {
            return ri.clone();
        }
        assert!(
            width.signum() == Sign::Positive,
            "UPoly::refine: the width must be positive"
        );
        let (mut lo, mut hi) = (ri.lo.clone(), ri.hi.clone());
        while hi.sub_ref(&lo) > *width {
            if let Some(r) = self.bisect(&mut lo, &mut hi, s_lo) {
                return RootInterval::exact(r);
            }
        }
        RootInterval { lo, hi }
    }

    /// `x` compared with the root isolated by `ri`.
    fn compare(&self, ri: &RootInterval, x: &Rational) -> Ordering {
        if ri.is_exact() {
            return x.cmp(&ri.lo);
        }
        if *x <= ri.lo {
            return Ordering::Less;
        }
        if *x >= ri.hi {
            return Ordering::Greater;
        }
        let p = self.poly();
        match p.sign_at(x) {
            Sign::Zero => Ordering::Equal,
            s if s == p.sign_at(&ri.lo) => Ordering::Less,
            _ => Ordering::Greater,
        }
    }
}

// ------------------------------------------------------------------------------ root finding

impl UPoly {
    /// The Sturm sequence of `self`: `self`, its derivative, then the negated remainders of
    /// Euclid's algorithm, each after the first replaced by its primitive part (a positive
    /// multiple, so the sign variations are those of the classical sequence). Its last element
    /// is `gcd(self, self')` up to a constant. Empty for the zero polynomial.
    pub fn sturm_sequence(&self) -> Vec<UPoly> {
        if self.is_zero() {
            return Vec::new();
        }
        sturm_chain(self)
    }

    /// The number of **distinct** real roots in the half-open interval `(lo, hi]` (0 when
    /// `lo >= hi`, and for the zero polynomial, whose roots are not isolated).
    pub fn count_roots(&self, lo: &Rational, hi: &Rational) -> usize {
        if self.is_zero() || lo >= hi {
            return 0;
        }
        let s = SquareFree::new(self);
        s.var_at(lo) - s.var_at(hi)
    }

    /// The number of distinct real roots (0 for the zero polynomial).
    pub fn count_real_roots(&self) -> usize {
        if self.is_constant() {
            return 0;
        }
        let s = SquareFree::new(self);
        s.var_neg_inf() - s.var_pos_inf()
    }

    /// Isolating intervals of all distinct real roots: sorted, pairwise disjoint, each holding
    /// exactly one root; exact (`lo == hi`) **exactly when the root is rational**. Empty for
    /// constants and for the zero polynomial.
    pub fn isolate_roots(&self) -> Vec<RootInterval> {
        if self.is_constant() {
            return Vec::new();
        }
        SquareFree::new(self).isolate()
    }

    /// The distinct real roots with their multiplicities, increasing.
    pub fn roots(&self) -> Vec<Root> {
        if self.is_constant() {
            return Vec::new();
        }
        let intervals = SquareFree::new(self).isolate();
        let factors = self.square_free_decomposition();
        intervals
            .into_iter()
            .map(|interval| {
                let multiplicity = multiplicity_in(&factors, &interval);
                Root {
                    interval,
                    multiplicity,
                }
            })
            .collect()
    }

    /// The multiplicity of the root isolated by `ri` (an interval from [`UPoly::isolate_roots`]
    /// of this polynomial, or any interval satisfying the [`RootInterval`] contract); 0 if `ri`
    /// holds no root.
    pub fn multiplicity(&self, ri: &RootInterval) -> u32 {
        multiplicity_in(&self.square_free_decomposition(), ri)
    }

    /// A refinement of the isolating interval `ri` of width at most `width`, containing the same
    /// root (exact if a bisection point hits it).
    ///
    /// # Panics
    /// When `ri` is not exact and its endpoints are not of opposite signs for the square-free
    /// part of `self` (so it does not isolate one of its roots, e.g. for the zero polynomial), or
    /// when `width <= 0` and the interval is not exact.
    pub fn refine(&self, ri: &RootInterval, width: &Rational) -> RootInterval {
        if ri.is_exact() {
            return ri.clone();
        }
        assert!(!self.is_zero(), "UPoly::refine: the zero polynomial");
        SquareFree::new(self).refine(ri, width)
    }

    /// The rational `x` compared with the root isolated by `ri` (an isolating interval of a root
    /// of `self`): `Less` when `x` is below the root.
    pub fn compare_with_root(&self, ri: &RootInterval, x: &Rational) -> Ordering {
        if ri.is_exact() || self.is_zero() {
            return x.cmp(&ri.lo);
        }
        SquareFree::new(self).compare(ri, x)
    }

    /// The roots with multiplicities and the sign on every gap between them (see
    /// [`SignChart`]). The gap signs follow from the sign at `+inf` and the parity of the
    /// multiplicities.
    pub fn sign_chart(&self) -> SignChart {
        let roots = self.roots();
        let mut gaps = vec![Sign::Zero; roots.len() + 1];
        let mut s = self.sign_at_pos_inf();
        gaps[roots.len()] = s;
        for (i, r) in roots.iter().enumerate().rev() {
            if r.multiplicity % 2 == 1 {
                s = sign_neg(s);
            }
            gaps[i] = s;
        }
        SignChart { roots, gaps }
    }

    /// The set `{x in R : self(x) >= 0}` as a union of disjoint closed intervals, increasing:
    /// the whole line for zero and for positive constants, empty for negative constants;
    /// isolated points (touching points, [`UPoly::touching_points`]) are degenerate intervals
    /// with `lo == hi`.
    pub fn nonnegative_set(&self) -> Vec<Interval> {
        let SignChart { roots, gaps } = self.sign_chart();
        let mut out = Vec::new();
        if self.is_zero() {
            out.push(Interval {
                lo: Bound::NegInf,
                hi: Bound::PosInf,
            });
            return out;
        }
        let mut start = (gaps[0] == Sign::Positive).then_some(Bound::NegInf);
        for (i, r) in roots.into_iter().enumerate() {
            let start_here = start
                .take()
                .unwrap_or_else(|| Bound::Root(r.interval.clone()));
            if gaps[i + 1] == Sign::Positive {
                start = Some(start_here);
            } else {
                out.push(Interval {
                    lo: start_here,
                    hi: Bound::Root(r.interval),
                });
            }
        }
        if let Some(lo) = start {
            out.push(Interval {
                lo,
                hi: Bound::PosInf,
            });
        }
        out
    }

    /// The touching points: roots where `self <= 0` on both sides (necessarily of even
    /// multiplicity), i.e. the isolated points of [`UPoly::nonnegative_set`]. For SPEC §2's
    /// discriminant they are the tangencies of the two surfaces.
    pub fn touching_points(&self) -> Vec<Root> {
        let SignChart { roots, gaps } = self.sign_chart();
        roots
            .into_iter()
            .enumerate()
            .filter(|(i, _)| gaps[*i] == Sign::Negative && gaps[i + 1] == Sign::Negative)
            .map(|(_, r)| r)
            .collect()
    }

    /// Whether `self(x) > 0` for some real `x`: a positive leading coefficient (positive
    /// constants included) or a real root of odd multiplicity (a sign change). No isolation is
    /// needed: the odd-multiplicity factors of the square-free decomposition are tested for real
    /// roots by a Sturm count.
    pub fn positive_somewhere(&self) -> bool {
        if self.sign_at_pos_inf() == Sign::Positive {
            return true;
        }
        if self.is_constant() {
            return false;
        }
        let odd = self
            .square_free_decomposition()
            .into_iter()
            .filter(|(_, i)| i % 2 == 1)
            .fold(UPoly::one(), |acc, (f, _)| acc.mul_impl(&f));
        odd.count_real_roots() > 0
    }

    /// Whether `self(x) >= 0` for some real `x`: zero, a positive leading coefficient, or any
    /// real root.
    pub fn nonnegative_somewhere(&self) -> bool {
        if self.is_zero() || self.sign_at_pos_inf() == Sign::Positive {
            return true;
        }
        self.count_real_roots() > 0
    }
}

/// The multiplicity of the root isolated by `ri` from a square-free decomposition.
fn multiplicity_in(factors: &[(UPoly, u32)], ri: &RootInterval) -> u32 {
    for (f, i) in factors {
        let holds = if ri.is_exact() {
            f.sign_at(&ri.lo) == Sign::Zero
        } else {
            // f is square-free and divides the square-free part: it changes sign across the
            // root exactly when the root is one of its own.
            f.sign_at(&ri.lo) * f.sign_at(&ri.hi) == Sign::Negative
        };
        if holds {
            return *i;
        }
    }
    0
}

// ------------------------------------------------------------------------------ intervals

impl RootInterval {
    /// The exact root `r` (`lo == hi == r`).
    pub fn exact(r: Rational) -> RootInterval {
        RootInterval {
            lo: r.clone(),
            hi: r,
        }
    }

    /// Whether the root is given exactly (`lo == hi`).
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }

    /// The root, when it is given exactly.
    pub fn exact_value(&self) -> Option<&Rational> {
        self.is_exact().then_some(&self.lo)
    }

    /// `hi - lo`.
    pub fn width(&self) -> Rational {
        self.hi.sub_ref(&self.lo)
    }

    /// `(lo + hi) / 2`.
    pub fn midpoint(&self) -> Rational {
        midpoint(&self.lo, &self.hi)
    }

    /// A floating-point approximation of the midpoint, **for display only**.
    pub fn to_f64(&self) -> f64 {
        self.midpoint().to_f64()
    }
}

impl fmt::Display for RootInterval {
    /// `r` for an exact root, `(lo, hi)` otherwise.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_exact() {
            write!(f, "{}", self.lo)
        } else {
            write!(f, "({}, {})", self.lo, self.hi)
        }
    }
}

impl fmt::Debug for RootInterval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self} ~ {}", self.to_f64())
    }
}

impl fmt::Display for Bound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Bound::NegInf => f.write_str("-inf"),
            Bound::PosInf => f.write_str("+inf"),
            Bound::Root(r) if r.is_exact() => write!(f, "{r}"),
            Bound::Root(r) => write!(f, "root in {r}"),
        }
    }
}

impl Bound {
    /// A floating-point approximation (infinities included), **for display only**.
    pub fn to_f64(&self) -> f64 {
        match self {
            Bound::NegInf => f64::NEG_INFINITY,
            Bound::PosInf => f64::INFINITY,
            Bound::Root(r) => r.to_f64(),
        }
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{}, {}]", self.lo, self.hi)
    }
}

impl Interval {
    /// Whether the interval is a single point (both ends the same root).
    pub fn is_point(&self) -> bool {
        self.lo == self.hi
    }

    /// Whether the rational `x` lies in the interval; `poly` is the polynomial whose roots the
    /// finite ends are (the one [`UPoly::nonnegative_set`] was called on).
    pub fn contains(&self, poly: &UPoly, x: &Rational) -> bool {
        let above_lo = match &self.lo {
            Bound::NegInf => true,
            Bound::PosInf => false,
            Bound::Root(r) => poly.compare_with_root(r, x) != Ordering::Less,
        };
        let below_hi = match &self.hi {
            Bound::NegInf => false,
            Bound::PosInf => true,
            Bound::Root(r) => poly.compare_with_root(r, x) != Ordering::Greater,
        };
        above_lo && below_hi
    }
}

// ------------------------------------------------------------------------------ tests

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n, d).unwrap()
    }

    fn int(n: i64) -> Rational {
        Rational::from_integer(n)
    }

    fn p(c: &[i64]) -> UPoly {
        UPoly::from_i64_coeffs(c)
    }

    #[test]
    fn canonical_and_arithmetic() {
        let a = UPoly::from_coeffs(vec![int(1), int(2), int(0), int(0)]);
        assert_eq!(a.coeffs().len(), 2);
        assert_eq!(a.degree(), 1);
        let b = p(&[-1, 0, 1]);
        assert_eq!(&a + &b, p(&[0, 2, 1]));
        assert_eq!(&a - &a, UPoly::zero());
        assert_eq!(&a * &b, p(&[-1, -2, 1, 2]));
        assert_eq!(-&a, p(&[-1, -2]));
        assert_eq!(a.scale(&q(1, 2)), UPoly::from_coeffs(vec![q(1, 2), int(1)]));
        assert_eq!(b.eval(&int(3)), int(8));
        assert_eq!(b.derivative(), p(&[0, 2]));
        assert_eq!(b.compose(&a), p(&[0, 4, 4]));
        assert_eq!(UPoly::from_roots(&[int(1), int(-1)]), b);
        assert!(UPoly::zero().is_zero());
        assert_eq!(UPoly::zero().degree(), 0);
        assert_eq!(Ring::pow(&a, 2), p(&[1, 4, 4]));
    }

    #[test]
    fn division_and_gcd() {
        let a = p(&[-1, 0, 0, 1]); // x^3 - 1
        let b = p(&[-1, 1]); // x - 1
        let (quo, r) = a.div_rem(&b);
        assert_eq!(quo, p(&[1, 1, 1]));
        assert!(r.is_zero());
        let (quo, r) = a.div_rem(&p(&[1, 2]));
        assert_eq!(&quo * &p(&[1, 2]) + &r, a);
        assert!(r.degree() < 1);
        assert_eq!(a.checked_div_rem(&UPoly::zero()), Err(ZeroDivisor));
        let g = p(&[-1, 0, 1]).gcd(&a);
        assert_eq!(g, b);
        assert_eq!(UPoly::zero().gcd(&UPoly::zero()), UPoly::zero());
        assert_eq!(UPoly::zero().gcd(&p(&[0, 3])), p(&[0, 1]));
    }

    #[test]
    fn content_and_primitive_part() {
        let a = UPoly::from_coeffs(vec![q(-2, 3), q(4, 9), int(2)]);
        assert_eq!(a.content(), q(2, 9));
        assert_eq!(a.primitive_part(), p(&[-3, 2, 9]));
        let n = a.neg_ref();
        assert_eq!(n.primitive_part(), p(&[3, -2, -9]));
    }

    #[test]
    fn square_free() {
        // (x-1)^3 (x+2)^2 (x^2+1)
        let f = Ring::pow(&p(&[-1, 1]), 3) * Ring::pow(&p(&[2, 1]), 2) * p(&[1, 0, 1]);
        let f = f.scale(&q(-3, 2));
        assert_eq!(
            f.square_free_part(),
            p(&[-1, 1]) * p(&[2, 1]) * p(&[1, 0, 1])
        );
        let dec = f.square_free_decomposition();
        assert_eq!(
            dec,
            vec![(p(&[1, 0, 1]), 1), (p(&[2, 1]), 2), (p(&[-1, 1]), 3)]
        );
        let roots = f.roots();
        assert_eq!(roots.len(), 2);
        assert_eq!(roots[0].interval, RootInterval::exact(int(-2)));
        assert_eq!(roots[0].multiplicity, 2);
        assert_eq!(roots[1].interval, RootInterval::exact(int(1)));
        assert_eq!(roots[1].multiplicity, 3);
    }

    #[test]
    fn display_and_poly_round_trip() {
        let a = UPoly::from_coeffs(vec![int(1), q(-1, 2), int(3)]);
        assert_eq!(a.to_string(), "3*x^2 - 1/2*x + 1");
        assert_eq!(p(&[0, -1, 0, 1]).display("tau").to_string(), "tau^3 - tau");
        assert_eq!(p(&[-5]).to_string(), "-5");
        assert_eq!(UPoly::zero().to_string(), "0");
        let mut vars = crate::poly::Vars::new();
        let parsed: Poly<Rational> =
            crate::expr::parse_poly(&a.display("t").to_string(), &mut vars).unwrap();
        let t = vars.get("t").unwrap();
        assert_eq!(UPoly::from_poly(&parsed, t).unwrap(), a);
        assert_eq!(a.to_poly(t), parsed);
        let two: Poly<Rational> = crate::expr::parse_poly("t*s + 1", &mut vars).unwrap();
        let s = vars.get("s").unwrap();
        assert_eq!(
            UPoly::from_poly(&two, t),
            Err(FromPolyError::OtherVariable(s))
        );
        let c: Poly<Rational> = crate::expr::parse_poly("7/3", &mut vars).unwrap();
        assert_eq!(UPoly::from_poly(&c, s).unwrap(), UPoly::constant(q(7, 3)));
    }

    #[test]
    fn sturm_counts() {
        // x^2 - 2: roots +-sqrt 2.
        let f = p(&[-2, 0, 1]);
        let seq = f.sturm_sequence();
        assert_eq!(seq.len(), 3);
        assert_eq!(f.count_real_roots(), 2);
        assert_eq!(f.count_roots(&int(0), &int(2)), 1);
        assert_eq!(f.count_roots(&int(-2), &int(2)), 2);
        assert_eq!(f.count_roots(&int(2), &int(-2)), 0);
        // Half-open: (x-1)(x-2) on (1, 2] counts 2 only, on (0, 1] counts 1.
        let g = p(&[2, -3, 1]);
        assert_eq!(g.count_roots(&int(1), &int(2)), 1);
        assert_eq!(g.count_roots(&int(0), &int(1)), 1);
        assert_eq!(g.count_roots(&int(0), &int(2)), 2);
        assert_eq!(p(&[1, 0, 1]).count_real_roots(), 0);
        assert_eq!(p(&[3]).count_real_roots(), 0);
        assert_eq!(UPoly::zero().count_real_roots(), 0);
    }

    #[test]
    fn isolation_and_refinement() {
        // (x^2 - 2)(3x - 1)(x + 5)^2
        let f = p(&[-2, 0, 1]) * p(&[-1, 3]) * Ring::pow(&p(&[5, 1]), 2);
        let roots = f.isolate_roots();
        assert_eq!(roots.len(), 4);
        assert_eq!(roots[0], RootInterval::exact(int(-5)));
        assert!(!roots[1].is_exact());
        assert_eq!(roots[2], RootInterval::exact(q(1, 3)));
        assert!(!roots[3].is_exact());
        let w = q(1, 1000000);
        let r = f.refine(&roots[3], &w);
        assert!(r.width() <= w);
        assert!(r.lo.square() < int(2) && r.hi.square() > int(2) && r.lo > int(0));
        assert!((r.to_f64() - std::f64::consts::SQRT_2).abs() < 1e-6);
        assert_eq!(f.multiplicity(&roots[0]), 2);
        assert_eq!(f.multiplicity(&roots[1]), 1);
        assert_eq!(f.multiplicity(&RootInterval::exact(int(7))), 0);
        assert_eq!(f.compare_with_root(&roots[3], &q(141, 100)), Ordering::Less);
        assert_eq!(
            f.compare_with_root(&roots[3], &q(142, 100)),
            Ordering::Greater
        );
    }

    #[test]
    fn rational_roots_with_awkward_denominators_are_exact() {
        let rs = [q(1, 3), q(-7, 5), q(22, 7), q(1, 97)];
        let f = UPoly::from_roots(&rs).scale(&q(-4, 9));
        let got: Vec<Rational> = f
            .isolate_roots()
            .iter()
            .map(|r| r.exact_value().cloned().unwrap())
            .collect();
        let mut want = rs.to_vec();
        want.sort();
        assert_eq!(got, want);
    }

    #[test]
    fn midpoint_roots_leave_no_root_endpoints() {
        // x^3 - 2x: the first bisection point 0 is a root.
        let f = p(&[0, -2, 0, 1]);
        let roots = f.isolate_roots();
        assert_eq!(roots.len(), 3);
        assert_eq!(roots[1], RootInterval::exact(int(0)));
        for r in [&roots[0], &roots[2]] {
            assert_ne!(f.sign_at(&r.lo), Sign::Zero);
            assert_ne!(f.sign_at(&r.hi), Sign::Zero);
            let fine = f.refine(r, &q(1, 1 << 20));
            assert!(fine.width() <= q(1, 1 << 20));
        }
        // Roots at dyadic points, hit by bisection at several levels.
        let g = UPoly::from_roots(&[int(0), int(2), int(-3), q(1, 2), q(3, 4)]) * p(&[-3, 0, 1]);
        let roots = g.isolate_roots();
        assert_eq!(roots.len(), 7);
        assert_eq!(roots.iter().filter(|r| r.is_exact()).count(), 5);
        for r in roots.iter().filter(|r| !r.is_exact()) {
            assert_ne!(g.sign_at(&r.lo), Sign::Zero);
            assert_ne!(g.sign_at(&r.hi), Sign::Zero);
        }
    }

    #[test]
    fn wilkinson_and_close_roots() {
        // Wilkinson's polynomial of degree 20: all roots integers, found exactly.
        let rs: Vec<Rational> = (1..=20).map(int).collect();
        let w = UPoly::from_roots(&rs);
        let got: Vec<Rational> = w
            .isolate_roots()
            .iter()
            .map(|r| r.exact_value().cloned().unwrap())
            .collect();
        assert_eq!(got, rs);
        // Clustered roots 1/1000, 1/1001, 1/1002 and an irrational pair sqrt(10^-6 + 1/7).
        let f = UPoly::from_roots(&[q(1, 1000), q(1, 1001), q(1, 1002)])
            * UPoly::from_coeffs(vec![-(q(1, 1000000) + q(1, 7)), int(0), int(1)]);
        let roots = f.isolate_roots();
        assert_eq!(roots.len(), 5);
        assert_eq!(roots[1], RootInterval::exact(q(1, 1002)));
        assert_eq!(roots[2], RootInterval::exact(q(1, 1001)));
        assert_eq!(roots[3], RootInterval::exact(q(1, 1000)));
        assert!(!roots[0].is_exact() && !roots[4].is_exact());
    }

    #[test]
    #[should_panic(expected = "not an isolating interval")]
    fn refine_rejects_non_isolating_intervals() {
        p(&[-2, 0, 1]).refine(
            &RootInterval {
                lo: int(-2),
                hi: int(2),
            },
            &q(1, 10),
        );
    }

    /// The discriminant `D(tau)` of SPEC §2 for the unit-parameter cylinder `x = 5 cos t`,
    /// `y = 5 sin t`, `z = u` and the sphere with centre `(d, e, f)` and radius `rr`:
    /// `u^2 - 2 f u + f^2 + (5c - d)^2 + (5s - e)^2 - rr^2 = 0`, so
    /// `A^2 - B = rr^2 - (5c - d)^2 - (5s - e)^2`, times `(1 + tau^2)^2`.
    fn cylinder_sphere_disc(d: i64, e: i64, rr: i64) -> UPoly {
        let one_plus = p(&[1, 0, 1]);
        let c_num = p(&[1, 0, -1]); // (1 - tau^2)
        let s_num = p(&[0, 2]); // 2 tau
        let x = c_num.scale(&int(5)) - one_plus.scale(&int(d));
        let y = s_num.scale(&int(5)) - one_plus.scale(&int(e));
        one_plus.square().scale(&int(rr * rr)) - x.square() - y.square()
    }

    #[test]
    fn spaeth_examples() {
        // Example 1: centre (1,0,0), R = 7: real for every t.
        let d1 = cylinder_sphere_disc(1, 0, 7);
        assert_eq!(d1, p(&[33, 0, 46, 0, 13]));
        assert_eq!(
            d1.nonnegative_set(),
            vec![Interval {
                lo: Bound::NegInf,
                hi: Bound::PosInf
            }]
        );
        assert!(d1.positive_somewhere());
        // Example 3: centre (6,7,8), R = 1: no intersection.
        let d3 = cylinder_sphere_disc(6, 7, 1);
        assert!(!d3.nonnegative_somewhere());
        assert!(!d3.positive_somewhere());
        assert!(d3.nonnegative_set().is_empty());
        // Tangency: centre (6,0,0), R = 1 touches the cylinder at t = 0 (tau = 0) only.
        let dt = cylinder_sphere_disc(6, 0, 1);
        assert_eq!(dt, p(&[0, 0, -120, 0, -120]));
        assert!(dt.nonnegative_somewhere());
        assert!(!dt.positive_somewhere());
        let zero = RootInterval::exact(int(0));
        assert_eq!(
            dt.nonnegative_set(),
            vec![Interval {
                lo: Bound::Root(zero.clone()),
                hi: Bound::Root(zero.clone())
            }]
        );
        let touching = dt.touching_points();
        assert_eq!(touching.len(), 1);
        assert_eq!(touching[0].interval, zero);
        assert_eq!(touching[0].multiplicity, 2);
        // A genuine crossing: centre (5,0,0), R = 2: an arc around t = 0.
        let dc = cylinder_sphere_disc(5, 0, 2);
        let set = dc.nonnegative_set();
        assert_eq!(set.len(), 1);
        assert!(set[0].contains(&dc, &int(0)));
        assert!(!set[0].contains(&dc, &int(1)));
        assert!(dc.touching_points().is_empty());
    }

    #[test]
    fn nonnegative_sets_of_simple_shapes() {
        // -(x-1)^2 (x-3): >= 0 on (-inf, 3], with 1 inside.
        let f = Ring::pow(&p(&[-1, 1]), 2) * p(&[3, -1]);
        let set = f.nonnegative_set();
        assert_eq!(set.len(), 1);
        assert_eq!(set[0].lo, Bound::NegInf);
        assert_eq!(set[0].hi, Bound::Root(RootInterval::exact(int(3))));
        // (x^2 - 2)(x - 5): [-sqrt2, sqrt2] and [5, inf).
        let g = p(&[-2, 0, 1]) * p(&[-5, 1]);
        let set = g.nonnegative_set();
        assert_eq!(set.len(), 2);
        assert!(set[0].contains(&g, &int(0)));
        assert!(!set[0].contains(&g, &int(2)));
        assert!(set[1].contains(&g, &int(5)) && set[1].contains(&g, &int(500)));
        assert_eq!(set[1].to_string(), "[5, +inf]");
        // Constants and zero.
        assert_eq!(UPoly::zero().nonnegative_set().len(), 1);
        assert_eq!(p(&[2]).nonnegative_set().len(), 1);
        assert!(p(&[-2]).nonnegative_set().is_empty());
        assert!(!p(&[-2]).nonnegative_somewhere());
        assert!(UPoly::zero().nonnegative_somewhere());
        assert!(!UPoly::zero().positive_somewhere());
        // Odd degree, negative leading coefficient: positive somewhere.
        assert!(p(&[0, 0, 0, -1]).positive_somewhere());
        // -(x^2+1)^2 (x-1)^2: nowhere >= 0 except x = 1.
        let h = -(Ring::pow(&p(&[1, 0, 1]), 2) * Ring::pow(&p(&[-1, 1]), 2));
        assert!(!h.positive_somewhere());
        assert!(h.nonnegative_somewhere());
        assert_eq!(h.touching_points().len(), 1);
    }

    #[test]
    fn sign_chart_gaps() {
        // x^3 (x - 2)^2 (x + 1): roots -1, 0, 2.
        let f = Ring::pow(&p(&[0, 1]), 3) * Ring::pow(&p(&[-2, 1]), 2) * p(&[1, 1]);
        let chart = f.sign_chart();
        assert_eq!(
            chart.gaps,
            vec![
                Sign::Positive,
                Sign::Negative,
                Sign::Positive,
                Sign::Positive
            ]
        );
        for (i, x) in [int(-2), q(-1, 2), int(1), int(3)].iter().enumerate() {
            assert_eq!(f.sign_at(x), chart.gaps[i]);
        }
        assert_eq!(UPoly::zero().sign_chart().gaps, vec![Sign::Zero]);
    }

    #[test]
    fn large_coefficients() {
        // Roots 10^30 + 1/3 and -1/(10^25), plus x^2 - 3.
        let big = Rational::from(num_bigint::BigInt::from(10u32).pow(30)) + q(1, 3);
        let tiny = Rational::from(num_bigint::BigInt::from(10u32).pow(25))
            .recip()
            .unwrap()
            .neg_ref();
        let f = UPoly::from_roots(&[big.clone(), tiny.clone()]) * p(&[-3, 0, 1]);
        let roots = f.isolate_roots();
        assert_eq!(roots.len(), 4);
        assert_eq!(roots[1], RootInterval::exact(tiny));
        assert_eq!(roots[3], RootInterval::exact(big));
    }
}
