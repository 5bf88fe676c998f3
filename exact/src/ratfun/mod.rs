//! Rational functions: fractions `num / den` of multivariate polynomials over a field, kept in
//! lowest terms, with the list of divisors met on the way.
//!
//! A [`RatFun`] is what an expression with division by polynomials denotes
//! ([`crate::expr::Expr::to_ratfun`]). Every operation cancels the common factor of numerator
//! and denominator with [`poly_gcd`] and makes the denominator monic (leading coefficient 1 in
//! the monomial order of [`crate::poly`]), so equal rational functions have equal
//! representations. The fraction alone forgets where the expression was undefined:
//! `(x^2 - 1)/(x - 1)` is `x + 1` over 1. So every divisor met (a polynomial divided by, or
//! raised to a negative power) is kept, monic and without repeats, in [`RatFun::conditions`]:
//! the expression means the fraction wherever none of them vanishes.
//!
//! # The greatest common divisor
//! Cancelling needs the multivariate gcd, which lives with the polynomials ([`crate::poly::gcd`]:
//! the primitive remainder sequence, and the modular certificate of coprimality that settles
//! almost every gcd met here without it). A fraction is cancelled ([`RatFun`]'s operations) by
//! exact division by the divisors already met (a denominator `W^5` whose numerator carries
//! `W^2` loses it by two divisions) until the certificate proves numerator and denominator
//! coprime; only when neither settles it does the remainder sequence run. Sums keep the least
//! common denominator (the gcd of the two denominators, small polynomials), and a sum over
//! coprime denominators is in lowest terms without any gcd with its numerator.
//!
//! # Identities without cancelling
//! Deciding whether two expressions are equal needs no lowest terms: [`Fraction`] keeps the
//! denominator as a product of powers of the divisors met, compared by equality, and two
//! fractions are cross-multiplied once ([`Fraction::cross_residual`]). The identity front ends
//! take that route first ([`crate::expr::ratfun_sides`]) and reduce only the smaller side when
//! the residual vanishes. The module is `factored`.

use crate::poly::gcd::div_image_possible;
use crate::poly::{Poly, SizeError, Var};
use exactcheck_core::{Field, Ring};

mod factored;
#[cfg(test)]
mod tests;

use crate::poly::gcd::certified_square_free;
pub use crate::poly::gcd::{certified_coprime, poly_gcd};
pub use crate::poly::{div_exact, poly_derivative};
pub use factored::{Fraction, MAX_FACTORS};

/// A fraction of polynomials in lowest terms with a monic denominator, and the divisors met.
#[derive(Clone, Debug, PartialEq)]
pub struct RatFun<C: Ring> {
    num: Poly<C>,
    den: Poly<C>,
    conditions: Vec<Poly<C>>,
}

impl<C: Field> RatFun<C> {
    /// The polynomial `p` as the fraction `p / 1`, with no conditions.
    pub fn from_poly(p: Poly<C>) -> Self {
        RatFun {
            num: p,
            den: Poly::one(),
            conditions: Vec::new(),
        }
    }

    /// The numerator.
    pub fn numerator(&self) -> &Poly<C> {
        &self.num
    }

    /// The denominator (monic; 1 for a polynomial).
    pub fn denominator(&self) -> &Poly<C> {
        &self.den
    }

    /// The divisors met while building the fraction (monic, non-constant, each once): the
    /// expression is defined where none of them vanishes. Every zero of the denominator is a
    /// zero of one of them (each operation records the divisor whose factors it puts in the
    /// denominator), so they exclude the poles.
    pub fn conditions(&self) -> &[Poly<C>] {
        &self.conditions
    }

    /// The numerator, consuming the fraction.
    pub fn into_numerator(self) -> Poly<C> {
        self.num
    }

    /// `1 / denominator`, with the conditions of `self` (the denominator is monic and coprime
    /// to 1, so this is in lowest terms).
    pub fn denominator_reciprocal(&self) -> Self {
        RatFun {
            num: Poly::one(),
            den: self.den.clone(),
            conditions: self.conditions.clone(),
        }
    }

    /// The fraction with every polynomial (numerator, denominator, conditions) mapped by `f`,
    /// which must preserve sums, products and coprimality (a renaming of the variables); the
    /// denominator and the conditions are made monic again in the new monomial order.
    pub fn map_polys(&self, f: impl Fn(&Poly<C>) -> Poly<C>) -> Self {
        let (num, den) = monic_den(f(&self.num), f(&self.den));
        RatFun {
            num,
            den,
            conditions: self.conditions.iter().map(|c| f(c).make_monic()).collect(),
        }
    }

    /// The same fraction with `conditions` as its divisors met: for an expression shown equal
    /// to this one as rational functions ([`Fraction::cross_residual`]), whose lowest terms are
    /// therefore these, but whose own divisors are `conditions` (which must exclude the zeros
    /// of the denominator).
    pub fn with_conditions(&self, conditions: Vec<Poly<C>>) -> Self {
        RatFun {
            conditions,
            ..self.clone()
        }
    }

    /// Whether the denominator is 1 and no divisor was met.
    pub fn is_polynomial(&self) -> bool {
        self.den.is_one() && self.conditions.is_empty()
    }

    /// `num / den` in lowest terms, with the conditions of `a` and `b`.
    fn reduced(num: Poly<C>, den: Poly<C>, a: &Self, b: &Self) -> Result<Self, SizeError> {
        let mut conditions = a.conditions.clone();
        for c in &b.conditions {
            push_condition(&mut conditions, c);
        }
        let (num, den) = cancel(num, den, &conditions)?;
        Ok(RatFun {
            num,
            den,
            conditions,
        })
    }

    /// `self + o` (`o` negated when `minus`).
    pub fn add(&self, o: &Self, minus: bool) -> Result<Self, SizeError> {
        let sign = |p: Poly<C>| if minus { p.neg_ref() } else { p };
        if self.den == o.den {
            let num = self.num.add_ref(&sign(o.num.clone()));
            return Self::reduced(num, self.den.clone(), self, o);
        }
        // Over the least common denominator `b (d / g)`, `g = gcd(b, d)`: with `g = 1` the
        // sum `(a d + c b) / (b d)` of two fractions in lowest terms is in lowest terms (a
        // common factor of it and `b` would divide `c b` and so `a d`, but `a` and `d` are prime
        // to `b`), so no gcd with the numerator is needed.
        // Two powers of one condition (`W^2` and `W^3`) have the smaller power as their gcd.
        let g = match (self.denominator_as_power(), o.denominator_as_power()) {
            (Some((h, a)), Some((h2, b))) if h == h2 => h.try_pow(a.min(b))?,
            _ => poly_gcd(&self.den, &o.den)?,
        };
        let (bg, dg) = if g.is_constant() {
            (self.den.clone(), o.den.clone())
        } else {
            (
                div_exact(&self.den, &g).expect("the gcd divides the denominator"),
                div_exact(&o.den, &g).expect("the gcd divides the denominator"),
            )
        };
        let num = self.num.try_mul(&dg)?.add_ref(&sign(o.num.try_mul(&bg)?));
        let den = self.den.try_mul(&dg)?;
        if g.is_constant() {
            let mut conditions = self.conditions.clone();
            for c in &o.conditions {
                push_condition(&mut conditions, c);
            }
            let (num, den) = if num.is_zero() {
                (num, Poly::one())
            } else {
                monic_den(num, den)
            };
            return Ok(RatFun {
                num,
                den,
                conditions,
            });
        }
        Self::reduced(num, den, self, o)
    }

    /// `-self`.
    pub fn neg(&self) -> Self {
        RatFun {
            num: self.num.neg_ref(),
            ..self.clone()
        }
    }

    /// `self * o`. With `a/b` and `c/d` in lowest terms, `gcd(ac, bd) = gcd(a, d) gcd(c, b)`:
    /// when the certificate proves `a, d` and `c, b` coprime (small polynomials rather than the
    /// product), `ac / bd` is in lowest terms as it stands (`bd` is monic as `b` and `d` are).
    pub fn mul(&self, o: &Self) -> Result<Self, SizeError> {
        let num = self.num.try_mul(&o.num)?;
        let den = self.den.try_mul(&o.den)?;
        let coprime =
            |x: &Poly<C>, y: &Poly<C>| y.is_one() || certified_coprime(x, y) == Some(true);
        if !num.is_zero() && coprime(&self.num, &o.den) && coprime(&o.num, &self.den) {
            let mut conditions = self.conditions.clone();
            for c in &o.conditions {
                push_condition(&mut conditions, c);
            }
            return Ok(RatFun {
                num,
                den,
                conditions,
            });
        }
        Self::reduced(num, den, self, o)
    }

    /// `self / o`, recording the numerator of `o` as a condition; `None` when `o` is
    /// identically zero.
    pub fn div(&self, o: &Self) -> Result<Option<Self>, SizeError> {
        let Some(inv) = o.recip() else {
            return Ok(None);
        };
        self.mul(&inv).map(Some)
    }

    /// `1 / self`, recording the numerator as a condition; `None` for zero.
    pub fn recip(&self) -> Option<Self> {
        if self.num.is_zero() {
            return None;
        }
        let mut conditions = self.conditions.clone();
        push_condition(&mut conditions, &self.num);
        let (num, den) = monic_den(self.den.clone(), self.num.clone());
        Some(RatFun {
            num,
            den,
            conditions,
        })
    }

    /// `self^k` (`k` may be negative: then the numerator is recorded as a condition); `None`
    /// for a negative power of zero.
    pub fn pow(&self, k: i64) -> Result<Option<Self>, SizeError> {
        let base = if k < 0 {
            match self.recip() {
                Some(r) => r,
                None => return Ok(None),
            }
        } else {
            self.clone()
        };
        let e = u32::try_from(k.unsigned_abs()).map_err(|_| SizeError::ExponentOverflow)?;
        // Numerator and denominator are coprime, so their powers are too.
        Ok(Some(RatFun {
            num: base.num.try_pow(e)?,
            den: base.den.try_pow(e)?,
            conditions: base.conditions,
        }))
    }

    /// The derivative in `v` by the quotient rule, `(N' D - N D') / D^2` in lowest terms; the
    /// conditions stay (the derivative is defined where the function is).
    ///
    /// A denominator `h^k` with `h` one of the conditions (the common case: `W^2` after one
    /// derivative of `X/W`) is differentiated without forming `D^2`: `(N' h - k N h') /
    /// h^(k + 1)`, which is in lowest terms when the certificate proves its numerator prime to
    /// `h` (the only factor of the denominator).
    pub fn derivative(&self, v: Var) -> Result<Self, SizeError> {
        let dn = poly_derivative(&self.num, v);
        if self.den.is_constant() {
            return Ok(RatFun {
                num: dn,
                ..self.clone()
            });
        }
        if let Some((h, k)) = self.denominator_as_power() {
            let dh = poly_derivative(h, v);
            let num = dn
                .try_mul(h)?
                .sub_ref(&self.num.try_mul(&dh)?.scale_i64(i64::from(k)));
            if !num.is_zero() && certified_coprime(&num, h) == Some(true) {
                return Ok(RatFun {
                    num,
                    den: self.den.try_mul(h)?,
                    conditions: self.conditions.clone(),
                });
            }
        }
        let dd = poly_derivative(&self.den, v);
        let num = dn.try_mul(&self.den)?.sub_ref(&self.num.try_mul(&dd)?);
        let den = self.den.try_mul(&self.den)?;
        let (num, den) = cancel(num, den, &self.conditions)?;
        Ok(RatFun {
            num,
            den,
            conditions: self.conditions.clone(),
        })
    }
}

impl<C: Field> RatFun<C> {
    /// `(h, k)` when the denominator is `h^k` for one of the conditions `h` (`k >= 1`).
    fn denominator_as_power(&self) -> Option<(&Poly<C>, u32)> {
        let degree = self.den.total_degree();
        self.conditions.iter().find_map(|h| {
            let dh = h.total_degree();
            if dh == 0 || degree % dh != 0 {
                return None;
            }
            let k = u32::try_from(degree / dh).ok()?;
            h.try_pow(k).is_ok_and(|p| p == self.den).then_some((h, k))
        })
    }
}

/// Adds the condition `p != 0` to `conditions` (monic polynomials whose zeros are excluded)
/// without repeating a zero already excluded: `p` is reduced to its square-free part
/// `p / gcd(p, dp/dx_1, ..., dp/dx_n)` (exact over a field of characteristic 0; `p` itself,
/// without any derivative, when its images modulo a prime prove it square-free), and the common
/// factor with every condition already listed is divided out; what remains, if not constant,
/// is added. `(t + 1)^2` after `t + 1` adds nothing, `x^2 - 1` after `x - 1` adds `x + 1`. When
/// a gcd exceeds a limit, `p` is added as it is (the same zeros, less tidy).
///
/// Before any gcd, a condition already listed (`p` itself, or `W^3` after `W`) is divided out
/// of `p` by exact division as often as it divides: what is left has the same zeros outside
/// the listed ones, so the result is the same, and the common case (a divisor met again, or a
/// power of one) needs no gcd at all.
pub fn push_condition<C: Field>(conditions: &mut Vec<Poly<C>>, p: &Poly<C>) {
    if p.is_constant() {
        return;
    }
    let mut rest = p.make_monic();
    if conditions.contains(&rest) {
        return;
    }
    for c in conditions.iter() {
        while !rest.is_constant() && div_image_possible(&rest, c) {
            match div_exact(&rest, c) {
                Some(q) => rest = q,
                None => break,
            }
        }
    }
    if rest.is_constant() {
        return;
    }
    let rest = &rest;
    let tidy = || -> Result<Poly<C>, SizeError> {
        // A square-free certificate modulo a prime spares the derivatives and their gcds.
        let mut g = if certified_square_free(rest) == Some(true) {
            Poly::one()
        } else {
            rest.clone()
        };
        for v in rest.variables() {
            if g.is_constant() {
                break;
            }
            g = poly_gcd(&g, &poly_derivative(rest, v))?;
        }
        let mut q = if g.is_constant() {
            rest.clone()
        } else {
            div_exact(rest, &g).expect("the gcd divides the polynomial")
        };
        for c in conditions.iter() {
            let common = poly_gcd(&q, c)?;
            if !common.is_constant() {
                q = div_exact(&q, &common).expect("the gcd divides the polynomial");
            }
        }
        Ok(q.make_monic())
    };
    match tidy() {
        Ok(q) if q.is_constant() => {}
        Ok(q) => conditions.push(q),
        Err(_) => {
            let m = p.make_monic();
            if !conditions.contains(&m) {
                conditions.push(m);
            }
        }
    }
}

/// `(num, den)` scaled so that `den` is monic.
fn monic_den<C: Field>(num: Poly<C>, den: Poly<C>) -> (Poly<C>, Poly<C>) {
    match den.leading_term().map(|(_, c)| c.inv()) {
        Some(Ok(inv)) if !inv.is_one() => (num.scale(&inv), den.scale(&inv)),
        _ => (num, den),
    }
}

/// `num / den` with their gcd cancelled and `den` monic (`0 / 1` for a zero numerator): the
/// divisors in `hints` that divide both are divided out while [`certified_coprime`] cannot
/// prove the two coprime; when it still cannot, the remainder sequence ([`poly_gcd`]) cancels
/// what is left. See the module documentation.
fn cancel<C: Field>(
    mut num: Poly<C>,
    mut den: Poly<C>,
    hints: &[Poly<C>],
) -> Result<(Poly<C>, Poly<C>), SizeError> {
    if num.is_zero() {
        return Ok((num, Poly::one()));
    }
    while !den.is_constant() {
        match certified_coprime(&num, &den) {
            None => break,
            Some(true) => return Ok(monic_den(num, den)),
            Some(false) => {}
        }
        let divided = hints.iter().filter(|h| !h.is_constant()).find_map(|h| {
            let d = div_exact(&den, h)?;
            div_image_possible(&num, h).then(|| div_exact(&num, h).map(|n| (n, d)))?
        });
        match divided {
            Some((n, d)) => (num, den) = (n, d),
            None => break,
        }
    }
    if den.is_constant() {
        return Ok(monic_den(num, den));
    }
    let g = poly_gcd(&num, &den)?;
    if g.is_constant() {
        return Ok(monic_den(num, den));
    }
    let num = div_exact(&num, &g).expect("the gcd divides the numerator");
    let den = div_exact(&den, &g).expect("the gcd divides the denominator");
    Ok(monic_den(num, den))
}
