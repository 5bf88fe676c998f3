//! [`ComplexRadical`]: the multi-quadratic numbers with `i = sqrt(-1)` adjoined, as pairs
//! `re + im i` of [`Radical`]s; inverse through the norm `re^2 + im^2`, principal square roots by
//! the half-angle formula when they are multi-quadratic.

use super::field::write_abs_term;
use super::Radical;
use crate::rational::Rational;
use exactcheck_core::{Field, OrderedField, Ring, Sign, Sqrt, ZeroDivisor};
use std::fmt;

// ====================================================================== complex radicals

/// A Gaussian multi-quadratic number `re + im i` (`i = sqrt(-1)`), for the conjugate-imaginary
/// focal lines of Juettler's Satz 5 (docs/papers/juttler.md). A field, not ordered. Canonical whenever its
/// parts are, so `==` is equality.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct ComplexRadical {
    /// The real part.
    pub re: Radical,
    /// The imaginary part.
    pub im: Radical,
}

impl ComplexRadical {
    /// `re + im i`.
    pub fn new(re: Radical, im: Radical) -> ComplexRadical {
        ComplexRadical { re, im }
    }

    /// The imaginary unit `i`.
    pub fn i() -> ComplexRadical {
        ComplexRadical {
            re: Radical::default(),
            im: Radical::one(),
        }
    }

    /// The complex conjugate `re - im i`.
    pub fn conj(&self) -> ComplexRadical {
        ComplexRadical {
            re: self.re.clone(),
            im: -&self.im,
        }
    }

    /// The squared modulus `re^2 + im^2` (a non-negative [`Radical`], zero only for zero).
    pub fn norm_sqr(&self) -> Radical {
        self.re.square_impl() + self.im.square_impl()
    }

    /// Whether the imaginary part is zero.
    pub fn is_real(&self) -> bool {
        self.im.is_zero()
    }

    /// The principal square root (real part positive, or zero with a non-negative imaginary
    /// part) when it is a Gaussian multi-quadratic number: `sqrt(-2) = sqrt(2) i`,
    /// `sqrt(2 i) = 1 + i`. `None` otherwise.
    pub fn principal_sqrt(&self) -> Option<ComplexRadical> {
        if self.im.is_zero() {
            return Some(if self.re.sign() == Sign::Negative {
                ComplexRadical::new(Radical::default(), (-&self.re).sqrt_impl()?)
            } else {
                ComplexRadical::from(self.re.sqrt_impl()?)
            });
        }
        let modulus = self.norm_sqr().sqrt_impl()?;
        let half = Rational::new(1, 2).ok()?;
        let u = (&modulus + &self.re).scale(&half).sqrt_impl()?;
        let v = (&modulus - &self.re).scale(&half).sqrt_impl()?;
        let v = if self.im.sign() == Sign::Negative {
            -v
        } else {
            v
        };
        let y = ComplexRadical::new(u, v);
        (y.square() == *self).then_some(y)
    }

    pub(super) fn mul_borrowed(&self, rhs: &ComplexRadical) -> ComplexRadical {
        let re = self.re.mul_impl(&rhs.re) - self.im.mul_impl(&rhs.im);
        let im = self.re.mul_impl(&rhs.im) + self.im.mul_impl(&rhs.re);
        ComplexRadical { re, im }
    }
    pub(super) fn mul_owned(self, rhs: &ComplexRadical) -> ComplexRadical {
        self.mul_borrowed(rhs)
    }
    pub(super) fn add_owned(self, rhs: &ComplexRadical) -> ComplexRadical {
        ComplexRadical {
            re: self.re + &rhs.re,
            im: self.im + &rhs.im,
        }
    }
    pub(super) fn add_borrowed(&self, rhs: &ComplexRadical) -> ComplexRadical {
        self.clone().add_owned(rhs)
    }
    pub(super) fn sub_owned(self, rhs: &ComplexRadical) -> ComplexRadical {
        ComplexRadical {
            re: self.re - &rhs.re,
            im: self.im - &rhs.im,
        }
    }
    pub(super) fn sub_borrowed(&self, rhs: &ComplexRadical) -> ComplexRadical {
        self.clone().sub_owned(rhs)
    }
    pub(super) fn inv_impl(&self) -> Result<ComplexRadical, ZeroDivisor> {
        let n = self.norm_sqr().inv_impl()?;
        Ok(ComplexRadical {
            re: self.re.mul_impl(&n),
            im: -self.im.mul_impl(&n),
        })
    }
    pub(super) fn div_borrowed(&self, rhs: &ComplexRadical) -> ComplexRadical {
        match rhs.inv_impl() {
            Ok(r) => self.mul_borrowed(&r),
            Err(_) => {
                panic!("ComplexRadical division by zero (use Field::checked_div to handle it)")
            }
        }
    }
    pub(super) fn div_owned(self, rhs: &ComplexRadical) -> ComplexRadical {
        self.div_borrowed(rhs)
    }
    pub(super) fn neg_borrowed(&self) -> ComplexRadical {
        ComplexRadical {
            re: self.re.neg_borrowed(),
            im: self.im.neg_borrowed(),
        }
    }
    pub(super) fn neg_in_place(self) -> ComplexRadical {
        ComplexRadical {
            re: -self.re,
            im: -self.im,
        }
    }
}

impl Ring for ComplexRadical {
    fn zero() -> Self {
        ComplexRadical::default()
    }
    fn one() -> Self {
        ComplexRadical::from(Radical::one())
    }
    fn from_i64(n: i64) -> Self {
        ComplexRadical::from(Radical::from(n))
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_borrowed(rhs)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.sub_borrowed(rhs)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_borrowed(rhs)
    }
    fn neg_ref(&self) -> Self {
        -self
    }
    fn square(&self) -> Self {
        // (a + b i)^2 = a^2 - b^2 + 2ab i
        let ab = self.re.mul_impl(&self.im);
        ComplexRadical {
            re: self.re.square_impl() - self.im.square_impl(),
            im: ab.scale(&Rational::from_integer(2)),
        }
    }
}

impl Field for ComplexRadical {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        self.inv_impl()
    }
    fn checked_div(&self, rhs: &Self) -> Result<Self, ZeroDivisor> {
        Ok(self.mul_borrowed(&rhs.inv_impl()?))
    }
}

impl Sqrt for ComplexRadical {
    /// The principal square root, see [`ComplexRadical::principal_sqrt`].
    fn sqrt(&self) -> Option<Self> {
        self.principal_sqrt()
    }
}

impl From<Radical> for ComplexRadical {
    fn from(re: Radical) -> Self {
        ComplexRadical {
            re,
            im: Radical::default(),
        }
    }
}

impl From<Rational> for ComplexRadical {
    fn from(q: Rational) -> Self {
        ComplexRadical::from(Radical::from(q))
    }
}

impl fmt::Display for ComplexRadical {
    /// `re + im*i` in the number syntax: `1/2 - sqrt(3)/2*i`, `(1 + sqrt(2))*i`, `i`, `-i`; a
    /// real value prints as a [`Radical`]. [`FromStr`](std::str::FromStr) reads it back.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.im.is_zero() {
            return fmt::Display::fmt(&self.re, f);
        }
        let has_re = !self.re.is_zero();
        if has_re {
            fmt::Display::fmt(&self.re, f)?;
        }
        match self.im.terms.as_slice() {
            [(m, c)] => {
                let negative = c.signum() == Sign::Negative;
                f.write_str(match (has_re, negative) {
                    (true, true) => " - ",
                    (true, false) => " + ",
                    (false, true) => "-",
                    (false, false) => "",
                })?;
                if m.is_one() && (c.is_one() || (-c).is_one()) {
                    f.write_str("i")
                } else {
                    write_abs_term(f, m, c)?;
                    f.write_str("*i")
                }
            }
            _ => {
                if has_re {
                    f.write_str(" + ")?;
                }
                write!(f, "({})*i", self.im)
            }
        }
    }
}

impl fmt::Debug for ComplexRadical {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}
