//! Real algebraic numbers: exact arithmetic, comparison and printing of numbers such as
//! `sqrt(2 + sqrt(2))`, `cos(2 pi / 7)` or the middle real root of `x^3 - 3x + 1`.
//!
//! # Representation
//! An [`Algebraic`] is a *defining polynomial* `f`, primitive with integer coefficients, a
//! positive leading coefficient and no repeated factor, together with an isolating interval of
//! one real root of `f` (a [`RootInterval`] with rational, in practice dyadic, endpoints):
//! * a rational number is always given exactly: `f` is linear and the interval is the point;
//! * an irrational number has an open interval `(lo, hi)` containing exactly one root of `f`,
//!   neither endpoint a root; `f` has no rational root at all (rational roots are divided out
//!   whenever a polynomial is formed), so it has degree at least 2.
//!
//! # Minimal and defining polynomials
//! The defining polynomial is the **minimal polynomial**: every polynomial a result is a root
//! of (a resultant, a substitution, a Graeffe step) is factored over Z
//! ([`UPoly::irreducible_factors`], Zassenhaus' algorithm) and only the irreducible factor with
//! a root in the isolating interval is kept, so degrees stay at the degree of the number
//! (`sqrt(2 + sqrt 2) + sqrt(2 - sqrt 2)` is a root of the quartic `x^4 - 8 x^2 + 8`, not of the
//! degree-16 resultant, which has it as a factor). Roots of cyclotomic-derived
//! polynomials ([`Algebraic::cos_pi`], [`Algebraic::sin_pi`]) and their Moebius images
//! `(a x + b)/(c x + d)` are known to be irreducible and are not factored again. The one
//! exception: when factoring gives up (recombination past the `factor-combinations` limit) the
//! square-free polynomial stays, [`Algebraic::minimal_polynomial`] answers `None` and
//! [`Algebraic::checked_minimal_polynomial`] the limit's error, which every number field
//! ([`NumberField`], [`primitive_element`]) passes on rather than compute modulo a polynomial
//! that may be reducible. **Every other decision stays exact** regardless: a root is selected by a sign change across an isolating interval, zero and equality tests
//! reduce to gcds and interval inclusion, and no floating-point number is ever consulted.

//! # Operations
//! * `-x`, `1/x`, `x + q`, `q x` ([`Algebraic::mobius`]): substitution in the polynomial, which
//!   keeps it minimal;
//! * `x + y`, `x * y`: the resultants `Res_t(f(t), g(x - t))` and `Res_t(f(t), t^n g(x/t))`
//!   ([`UPoly::resultant`], evaluated at integer points and interpolated), reduced as above;
//!   the root is selected by interval arithmetic on refined operand intervals until only one
//!   isolating interval of the result polynomial meets the enclosure;
//! * `sqrt(x)` for `x >= 0`: `f(t^2)` and the positive root;
//! * comparison: equal numbers are detected by `gcd(f, g)` having the root in both intervals,
//!   different ones by refining both intervals until they separate.
//!
//! The anchors are FLINT's `qqbar` (which likewise factors every polynomial), Sage's `QQbar` and Mathematica's `Root`. The arithmetic here is hand-written
//! because no crate of the dependency set offers exact real algebraic numbers.
//!
//! # Limits
//! The degree of the defining polynomial is checked by [`Coefficient::check_limits`] against
//! the `algebraic-degree` limit ([`limits::ALGEBRAIC_DEGREE`]) after every operation of the
//! expression evaluator; an operation on two numbers within the limit `d` computes a resultant
//! of degree at most `d^2`.
//!
//! # Layout
//! Here: the type, construction, comparison and the trait implementations; `arith`: the
//! arithmetic and the root selection; `trig`: cosines, sines and tangents of rational multiples
//! of pi; `display`: printing as radicals or as `Root(...)`; `field`: number fields `Q(theta)`
//! and primitive elements of several numbers; `names`: elements printed as polynomials in the
//! values the user wrote; `element`: elements of one number field as an ordered field
//! ([`FieldElement`]).

mod arith;
mod display;
mod element;
mod field;
mod names;
mod poly_roots;
#[cfg(test)]
mod poly_roots_tests;
#[cfg(test)]
mod tests;
mod trig;

pub use display::root_variable;
pub use element::FieldElement;
pub use field::{primitive_element, FieldError, NumberField, PrimitiveElement};
pub use poly_roots::{FieldUPoly, FieldUPolyDisplay};
pub use trig::TrigError;

use crate::coefficient::{Coefficient, Trig, TrigRefusal};
use crate::univariate::{RootInterval, UPoly};
use crate::Rational;
use exactcheck_core::limits::{self, LimitError};
use exactcheck_core::{Field, Ring, Sign, ZeroDivisor};
use num_traits::ToPrimitive;
use std::cmp::Ordering;

/// A real algebraic number, exactly: see the [module documentation](self).
#[derive(Clone)]
pub struct Algebraic {
    /// Primitive, integer coefficients, positive leading coefficient, square-free, no rational
    /// root unless linear.
    poly: UPoly,
    /// Exact iff the number is rational; otherwise isolates the number among the roots of `poly`.
    iv: RootInterval,
    /// Whether `poly` is known to be irreducible (hence the minimal polynomial): false only
    /// when factoring gave up.
    minimal: bool,
}

/// The error of [`Algebraic::root_of`].
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RootError {
    /// The polynomial is zero (every number is a root).
    #[error("the zero polynomial has no isolated roots")]
    ZeroPolynomial,
    /// The index is not below the number of distinct real roots.
    #[error("root index {index} is out of range: the polynomial has {count} distinct real roots")]
    IndexOutOfRange {
        /// The index asked for.
        index: usize,
        /// The number of distinct real roots.
        count: usize,
    },
}

impl Algebraic {
    /// The rational number `q`.
    pub fn from_rational(q: Rational) -> Algebraic {
        let poly = UPoly::from_coeffs(vec![-q.clone(), Rational::ONE]).primitive_part();
        Algebraic {
            poly,
            iv: RootInterval::exact(q),
            minimal: true,
        }
    }

    /// The integer `n`.
    pub fn from_integer(n: i64) -> Algebraic {
        Algebraic::from_rational(Rational::from_integer(n))
    }

    /// The real root number `index` (from 0, in increasing order, counting each distinct root
    /// once) of the non-zero polynomial `poly`.
    ///
    /// # Errors
    /// [`RootError::ZeroPolynomial`], or [`RootError::IndexOutOfRange`] with the number of
    /// distinct real roots.
    pub fn root_of(poly: &UPoly, index: usize) -> Result<Algebraic, RootError> {
        if poly.is_zero() {
            return Err(RootError::ZeroPolynomial);
        }
        let f = poly.square_free_part().primitive_part();
        let roots = f.isolate_roots();
        match roots.get(index) {
            Some(ri) => Ok(Algebraic::from_isolated(f, ri.clone(), &roots, false)),
            None => Err(RootError::IndexOutOfRange {
                index,
                count: roots.len(),
            }),
        }
    }

    /// The defining polynomial (integer coefficients, primitive, square-free; see the
    /// [module documentation](self) for when it is minimal).
    pub fn defining_polynomial(&self) -> &UPoly {
        &self.poly
    }

    /// The minimal polynomial over Q (primitive, integer coefficients, positive leading
    /// coefficient) when the defining polynomial is known to be irreducible, `None` otherwise.
    pub fn minimal_polynomial(&self) -> Option<&UPoly> {
        self.minimal.then_some(&self.poly)
    }

    /// The minimal polynomial, factoring the defining polynomial again (with the
    /// `factor-combinations` limit in force) when it is not known to be irreducible.
    ///
    /// # Errors
    /// The `factor-combinations` [`exactcheck_core::limits::LimitError`] when factoring gives up.
    pub fn checked_minimal_polynomial(&self) -> Result<UPoly, exactcheck_core::limits::LimitError> {
        if self.minimal {
            return Ok(self.poly.clone());
        }
        let factors = self.poly.irreducible_factors()?;
        Ok(factors
            .into_iter()
            .find(|g| has_root_in(g, &self.iv))
            .map(|g| arith::normalise(&g))
            .expect("one irreducible factor has the isolated root"))
    }

    /// The current isolating interval (a point for a rational number).
    pub fn interval(&self) -> &RootInterval {
        &self.iv
    }

    /// The value, if it is rational.
    pub fn to_rational(&self) -> Option<&Rational> {
        self.iv.exact_value()
    }

    /// Whether the number is rational.
    pub fn is_rational(&self) -> bool {
        self.iv.is_exact()
    }

    /// An interval `[lo, hi]` containing the number, of width at most `2^-bits` (a point for a
    /// rational number).
    pub fn enclosure(&self, bits: u32) -> (Rational, Rational) {
        if self.iv.is_exact() {
            return (self.iv.lo.clone(), self.iv.lo.clone());
        }
        let width = Rational::from_dyadic(&num_bigint::BigInt::from(1), u64::from(bits));
        if self.iv.width() <= width {
            return (self.iv.lo.clone(), self.iv.hi.clone());
        }
        let ri = self.poly.refine(&self.iv, &width);
        (ri.lo, ri.hi)
    }

    /// The sign, exactly.
    pub fn sign(&self) -> Sign {
        if let Some(q) = self.to_rational() {
            return q.signum();
        }
        sign_by_refinement(8, |bits| self.enclosure(bits))
    }

    /// Exact equality of two irrational numbers: the gcd of the defining polynomials must vanish
    /// at `self`, which is then a root of `other`'s polynomial, and equal to `other` exactly when
    /// it lies in `other`'s isolating interval (whose ends are not roots).
    fn equal_irrational(&self, other: &Algebraic) -> bool {
        if self.iv.hi <= other.iv.lo || other.iv.hi <= self.iv.lo {
            return false;
        }
        if self.poly == other.poly {
            // Same polynomial: the same root iff the isolating intervals overlap, and they do.
            return has_root_in(
                &self.poly,
                &RootInterval {
                    lo: self.iv.lo.clone().max(other.iv.lo.clone()),
                    hi: self.iv.hi.clone().min(other.iv.hi.clone()),
                },
            );
        }
        let h = self.poly.gcd(&other.poly);
        if h.degree() == 0 || !has_root_in(&h, &self.iv) {
            return false;
        }
        let mut bits = 8;
        loop {
            let (lo, hi) = self.enclosure(bits);
            if other.iv.lo < lo && hi < other.iv.hi {
                return true;
            }
            if hi <= other.iv.lo || other.iv.hi <= lo {
                return false;
            }
            bits *= 2;
        }
    }

    /// The order of two numbers, exactly.
    pub fn compare(&self, other: &Algebraic) -> Ordering {
        match (self.to_rational(), other.to_rational()) {
            (Some(a), Some(b)) => return a.cmp(b),
            (None, None) if self.equal_irrational(other) => return Ordering::Equal,
            _ => {}
        }
        // Different numbers: refine both until the enclosures separate.
        let mut bits = 8;
        loop {
            let (alo, ahi) = self.enclosure(bits);
            let (blo, bhi) = other.enclosure(bits);
            if ahi < blo {
                return Ordering::Less;
            }
            if bhi < alo {
                return Ordering::Greater;
            }
            bits *= 2;
        }
    }

    /// The degree of the defining polynomial.
    pub fn degree(&self) -> usize {
        self.poly.degree()
    }

    /// The absolute value.
    pub fn abs(&self) -> Algebraic {
        if self.sign() == Sign::Negative {
            self.neg_ref()
        } else {
            self.clone()
        }
    }

    /// The non-negative square root, `None` for a negative number.
    pub fn sqrt(&self) -> Option<Algebraic> {
        match self.sign() {
            Sign::Negative => None,
            Sign::Zero => Some(Algebraic::zero()),
            Sign::Positive => Some(self.sqrt_positive()),
        }
    }

    /// The real root of index `n >= 2`: for an odd `n` the one real root (of the sign of
    /// `self`), for an even `n` the non-negative root, `None` for a negative number. A root
    /// of `f(t^n)`, `f` the minimal polynomial, selected by the root bounds of the enclosure.
    ///
    /// # Errors
    /// The `algebraic-degree` limit when `n` times the degree exceeds it (checked before
    /// `f(t^n)` is formed).
    pub fn nth_root(&self, n: u32) -> Result<Option<Algebraic>, LimitError> {
        if n < 2 {
            return Ok((n == 1).then(|| self.clone()));
        }
        match self.sign() {
            Sign::Zero => Ok(Some(Algebraic::zero())),
            Sign::Negative if n % 2 == 0 => Ok(None),
            Sign::Negative => Ok(self.neg_impl().nth_root(n)?.map(|r| r.neg_impl())),
            Sign::Positive => {
                if let Some(q) = self.to_rational() {
                    if let Ok(Some(r)) = Coefficient::try_nth_root(q, n) {
                        return Ok(Some(Algebraic::from_rational(r)));
                    }
                }
                limits::ALGEBRAIC_DEGREE.check_usize(self.degree().saturating_mul(n as usize))?;
                Ok(Some(self.nth_root_positive(n)))
            }
        }
    }

    /// The multiplicative inverse, or [`ZeroDivisor`] for zero.
    pub fn inverse(&self) -> Result<Algebraic, ZeroDivisor> {
        if self.is_zero() {
            return Err(ZeroDivisor);
        }
        let zero = Rational::ZERO;
        let one = Rational::ONE;
        Ok(self.mobius(&zero, &one, &one, &zero))
    }
}

// ------------------------------------------------------------------------------ traits

impl PartialEq for Algebraic {
    fn eq(&self, other: &Algebraic) -> bool {
        self.compare(other) == Ordering::Equal
    }
}

impl Eq for Algebraic {}

impl PartialOrd for Algebraic {
    fn partial_cmp(&self, other: &Algebraic) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Algebraic {
    fn cmp(&self, other: &Algebraic) -> Ordering {
        self.compare(other)
    }
}

impl Default for Algebraic {
    fn default() -> Algebraic {
        Algebraic::zero()
    }
}

impl From<Rational> for Algebraic {
    fn from(q: Rational) -> Algebraic {
        Algebraic::from_rational(q)
    }
}

impl From<i64> for Algebraic {
    fn from(n: i64) -> Algebraic {
        Algebraic::from_integer(n)
    }
}

exactcheck_core::ring_ops! {
    impl[] Algebraic;
    Neg::neg: |a| a.neg_impl();
    Add::add, AddAssign::add_assign: |a, b| a.add_impl(b);
    Sub::sub, SubAssign::sub_assign: |a, b| a.add_impl(&b.neg_impl());
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_impl(b);
    Div::div, DivAssign::div_assign: |a, b| a.mul_impl(&b.inverse().expect("division of an algebraic number by zero"));
}

impl Ring for Algebraic {
    fn zero() -> Self {
        Algebraic::from_integer(0)
    }
    fn one() -> Self {
        Algebraic::from_integer(1)
    }
    fn from_i64(n: i64) -> Self {
        Algebraic::from_integer(n)
    }
    fn is_zero(&self) -> bool {
        self.to_rational().is_some_and(|q| q.is_zero())
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(rhs)
    }
    fn neg_ref(&self) -> Self {
        self.neg_impl()
    }
    fn square(&self) -> Self {
        self.square_impl()
    }
}

impl Field for Algebraic {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        self.inverse()
    }
}

impl Coefficient for Algebraic {
    fn from_rational(q: &Rational) -> Option<Self> {
        Some(Algebraic::from_rational(q.clone()))
    }
    fn try_inverse(&self) -> Option<Self> {
        self.inverse().ok()
    }
    /// The non-negative root of a non-negative number.
    fn try_sqrt(&self) -> Option<Self> {
        self.sqrt()
    }
    fn try_abs(&self) -> Option<Self> {
        Some(self.abs())
    }
    fn try_nth_root(&self, n: u32) -> Result<Option<Self>, LimitError> {
        self.nth_root(n)
    }
    fn nth_root_hint() -> &'static str {
        ": a negative number has no real root of even index"
    }
    fn sqrt_hint() -> &'static str {
        " (it is negative: no real square root)"
    }
    /// The size of a rational value; 0 for an irrational one, whose size is bounded by the
    /// `algebraic-degree` limit instead (the coefficients of the defining polynomial of `x^k`
    /// need not grow linearly in `k`, so they give no lower bound).
    fn size_bits(&self) -> u64 {
        self.to_rational().map_or(0, Coefficient::size_bits)
    }
    fn check_limits(&self) -> Result<(), LimitError> {
        limits::ALGEBRAIC_DEGREE.check_usize(self.degree())
    }
    /// Every rational multiple of pi: [`Algebraic::cos_pi`], [`Algebraic::sin_pi`],
    /// [`Algebraic::tan_pi`]; a multiple whose numerator or denominator does not fit an `i64`
    /// has a degree past every limit.
    fn trig_of_pi(r: &Rational, which: Trig) -> Option<Result<Self, TrigRefusal>> {
        let (Some(p), Some(q)) = (r.numer().to_i64(), r.denom().to_i64()) else {
            return Some(Err(TrigRefusal::Limit(
                limits::ALGEBRAIC_DEGREE
                    .exceeded(format!("more than {}", limits::ALGEBRAIC_DEGREE.get())),
            )));
        };
        let v = match which {
            Trig::Cos => Algebraic::cos_pi(p, q),
            Trig::Sin => Algebraic::sin_pi(p, q),
            Trig::Tan => Algebraic::tan_pi(p, q),
        };
        Some(v.map_err(|e| match e {
            TrigError::TanUndefined { .. } => {
                let angle = crate::coefficient::angle_text(r);
                TrigRefusal::Why(format!("tan({angle}) is undefined: cos({angle}) = 0"))
            }
            TrigError::Limit(l) => TrigRefusal::Limit(l),
            other => TrigRefusal::Why(other.to_string()),
        }))
    }
}

/// Whether the square-free `g` has a root in the open interval `iv`, whose ends are not roots of
/// `g` and which holds at most one of its roots (an isolating interval of a root of a multiple of
/// `g`, or a part of one): exactly when `g` changes sign across it.
pub(super) fn has_root_in(g: &UPoly, iv: &RootInterval) -> bool {
    g.sign_at(&iv.lo) * g.sign_at(&iv.hi) == Sign::Negative
}

/// The sign of a non-zero real number from its enclosures at `start`, `2 start`, `4 start`, ...
/// bits: the first enclosure that excludes 0 decides it. The caller guarantees the number is not
/// 0 (an irrational number, or a non-zero element of a number field), so the loop ends.
pub(crate) fn sign_by_refinement(
    start: u32,
    enclosure: impl Fn(u32) -> (Rational, Rational),
) -> Sign {
    let mut bits = start;
    loop {
        let (lo, hi) = enclosure(bits);
        if lo.signum() == Sign::Positive {
            return Sign::Positive;
        }
        if hi.signum() == Sign::Negative {
            return Sign::Negative;
        }
        bits *= 2;
    }
}
