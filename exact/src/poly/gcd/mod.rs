//! The multivariate gcd of polynomials over a field: the primitive remainder sequence
//! ([`poly_gcd`]), its budgeted form for callers that can do without it (`gcd_capped`), and the
//! modular certificate of coprimality ([`certified_coprime`], module `coprime`) that settles
//! most gcds met in practice without a remainder sequence. Rational functions
//! ([`crate::ratfun`]) cancel with them, and square-free factoring ([`super::factor`]) is built
//! on them.
//!
//! # The remainder sequence
//! [`poly_gcd`] is the recursive primitive-remainder-sequence algorithm over the field of
//! coefficients: in the main variable `v` (the highest index present), each polynomial is its
//! content (the gcd of its coefficients in `v`, polynomials in the other variables, computed
//! recursively) times a primitive part; the gcd is the gcd of the contents times the last
//! non-zero pseudo-remainder of the primitive parts, each remainder made primitive (and monic)
//! before the next step. Every product is taken with [`Poly::try_mul`], so the `degree` and
//! `terms` limits bound the work.
//!
//! # Cheap cancellation
//! The remainder sequence is expensive on the large numerators that derivatives and products
//! of fractions build, and almost every gcd met there is 1. So, with rational coefficients,
//! two polynomials are first tested for coprimality by their images modulo the prime
//! `2^61 - 1` ([`certified_coprime`]): for each variable `v` they share, the other variables
//! are replaced by fixed residues and the univariate gcd in `v` is computed modulo `p`; degree
//! 0 for every `v`, with a leading coefficient that does not vanish, proves the gcd over Q
//! constant (the image of the true gcd divides the image gcd and keeps its degree). The gcd
//! crates for Rust (none multivariate over Q with these limits) could not replace this. The
//! certificate is in `coprime`, the remainder sequence here.

mod coprime;

pub(crate) use coprime::div_image_possible;
pub use coprime::{certified_coprime, certified_square_free};

use super::{div_exact, Poly, SizeError, Var};
use crate::{Radical, Rational};
use exactcheck_core::{Field, Ring};
use std::any::Any;

/// A term: its exponents and its coefficient.
type Term<C> = (Vec<(Var, u32)>, C);

/// The coefficients of `p` as a polynomial in `v`: entry `i` is the coefficient of `v^i` (a
/// polynomial in the other variables).
pub(super) fn coefficients_in<C: Ring>(p: &Poly<C>, v: Var) -> Vec<Poly<C>> {
    let mut buckets: Vec<Vec<Term<C>>> = vec![Vec::new(); p.degree_in(v) as usize + 1];
    for (m, c) in p.terms() {
        let e = m.exponent(v) as usize;
        let rest: Vec<(Var, u32)> = m.exponents().into_iter().filter(|&(w, _)| w != v).collect();
        buckets[e].push((rest, c.clone()));
    }
    buckets.into_iter().map(Poly::from_terms).collect()
}

/// Why a gcd computation with a budget of work stopped.
#[derive(Debug)]
pub(crate) enum GcdError {
    /// A product exceeded a named limit.
    Size(SizeError),
    /// The products of the remainder sequences together cost more than the budget
    /// ([`product_work`]).
    Capped,
}

/// The size of the largest coefficient of `p` in 64-bit words (at least 1): rational
/// coefficients by their bits ([`Rational::bits`]), those of the square-root field by the bits
/// of their rational parts together (a coefficient `a + b sqrt(2)` costs what `a` and `b` do);
/// those of other fields count one word.
fn coefficient_words<C: Field>(p: &Poly<C>) -> usize {
    let any = p as &dyn Any;
    let bits = if let Some(q) = any.downcast_ref::<Poly<Rational>>() {
        q.coefficients().iter().map(Rational::bits).max()
    } else if let Some(q) = any.downcast_ref::<Poly<Radical>>() {
        q.coefficients()
            .iter()
            .map(|c| c.terms().iter().map(|(_, r)| r.bits()).sum::<u64>())
            .max()
    } else {
        None
    };
    usize::try_from(bits.unwrap_or(0) / 64)
        .unwrap_or(usize::MAX)
        .saturating_add(1)
}

/// The work of the product `a b` charged to a gcd budget: the term products, each weighted by
/// the words of the two coefficients multiplied (a product of `k`-word numbers costs about
/// `k^2` word products). Counting coefficient size as well as terms bounds the time of a
/// remainder sequence whose coefficients swell while its term counts stay small.
fn product_work<C: Field>(a: &Poly<C>, b: &Poly<C>) -> usize {
    a.len()
        .saturating_mul(b.len())
        .saturating_mul(coefficient_words(a))
        .saturating_mul(coefficient_words(b))
}

impl From<SizeError> for GcdError {
    fn from(e: SizeError) -> GcdError {
        GcdError::Size(e)
    }
}

/// The gcd of the coefficients of `p` in `v` (monic), the work of all remainder sequences
/// taken from `budget`.
pub(crate) fn content_in<C: Field>(
    p: &Poly<C>,
    v: Var,
    budget: &mut usize,
) -> Result<Poly<C>, GcdError> {
    let mut g = Poly::zero();
    for c in coefficients_in(p, v) {
        g = gcd_capped(&g, &c, budget)?;
        if g.is_constant() && !g.is_zero() {
            break;
        }
    }
    Ok(g)
}

/// The pseudo-remainder of `f` by `g` in `v`: `lc(g)^k f - q g` of degree in `v` below `g`'s.
/// The work of each step's two products ([`product_work`]) is taken from `budget` before they
/// are formed.
fn pseudo_remainder<C: Field>(
    f: &Poly<C>,
    g: &Poly<C>,
    v: Var,
    budget: &mut usize,
) -> Result<Poly<C>, GcdError> {
    let dg = g.degree_in(v);
    let lc_g = coefficients_in(g, v)
        .pop()
        .expect("a polynomial has a coefficient");
    let mut r = f.clone();
    while !r.is_zero() && r.degree_in(v) >= dg {
        let dr = r.degree_in(v);
        let lc_r = coefficients_in(&r, v)
            .pop()
            .expect("a polynomial has a coefficient");
        let work = product_work(&lc_g, &r).saturating_add(product_work(&lc_r, g));
        *budget = budget.checked_sub(work).ok_or(GcdError::Capped)?;
        let shift = Poly::monomial(C::one(), &[(v, dr - dg)]);
        r = lc_g
            .try_mul(&r)?
            .sub_ref(&lc_r.try_mul(&shift)?.try_mul(g)?);
    }
    Ok(r)
}

/// The greatest common divisor of two polynomials over a field, monic (0 only for two zeros);
/// see the module documentation.
///
/// # Errors
/// [`SizeError`] when a product of the remainder sequence exceeds the `degree` or `terms`
/// limit.
pub fn poly_gcd<C: Field>(a: &Poly<C>, b: &Poly<C>) -> Result<Poly<C>, SizeError> {
    gcd_capped(a, b, &mut usize::MAX.clone()).map_err(|e| match e {
        GcdError::Size(e) => e,
        GcdError::Capped => unreachable!("no computation does usize::MAX work"),
    })
}

/// [`poly_gcd`], taking the work of every pseudo-remainder step ([`product_work`]) from
/// `budget` and stopping with [`GcdError::Capped`] when it runs out (a bound on the time for
/// callers that can do without the gcd).
pub(crate) fn gcd_capped<C: Field>(
    a: &Poly<C>,
    b: &Poly<C>,
    budget: &mut usize,
) -> Result<Poly<C>, GcdError> {
    if a.is_zero() {
        return Ok(b.make_monic());
    }
    if b.is_zero() {
        return Ok(a.make_monic());
    }
    if a.is_constant() || b.is_constant() || certified_coprime(a, b) == Some(true) {
        return Ok(Poly::one());
    }
    prs_gcd(a, b, budget)
}

/// The remainder sequence of [`gcd_capped`] for two non-zero, non-constant polynomials,
/// without the coprimality test at the top (the inner gcds of contents still use it).
pub(crate) fn prs_gcd<C: Field>(
    a: &Poly<C>,
    b: &Poly<C>,
    budget: &mut usize,
) -> Result<Poly<C>, GcdError> {
    let (va, vb) = (a.variables(), b.variables());
    let v = *va
        .iter()
        .chain(&vb)
        .max()
        .expect("non-constant polynomials have variables");
    if !vb.contains(&v) {
        return gcd_capped(&content_in(a, v, budget)?, b, budget);
    }
    if !va.contains(&v) {
        return gcd_capped(a, &content_in(b, v, budget)?, budget);
    }
    let (ca, cb) = (content_in(a, v, budget)?, content_in(b, v, budget)?);
    let content = gcd_capped(&ca, &cb, budget)?;
    let pa = div_exact(a, &ca).expect("the content divides the polynomial");
    let pb = div_exact(b, &cb).expect("the content divides the polynomial");
    let (mut f, mut g) = if pa.degree_in(v) >= pb.degree_in(v) {
        (pa, pb)
    } else {
        (pb, pa)
    };
    loop {
        let r = pseudo_remainder(&f, &g, v, budget)?;
        if r.is_zero() {
            break;
        }
        if r.degree_in(v) == 0 {
            g = Poly::one();
            break;
        }
        let cr = content_in(&r, v, budget)?;
        let r = div_exact(&r, &cr)
            .expect("the content divides the polynomial")
            .make_monic();
        f = g;
        g = r;
    }
    Ok(content.try_mul(&g)?.make_monic())
}
