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
//! constant (the image of the true gcd divides the image gcd and keeps its degree). A
//! fraction is cancelled ([`RatFun`]'s operations) by exact division by the divisors already
//! met (a denominator `W^5` whose numerator carries `W^2` loses it by two divisions) until the
//! test proves numerator and denominator coprime; only when neither settles it does the
//! remainder sequence run. Sums keep the least common denominator (the gcd of the two
//! denominators, small polynomials), and a sum over coprime denominators is in lowest terms
//! without any gcd with its numerator. The gcd crates for Rust (none multivariate over Q with
//! these limits) could not replace this.

use crate::modp::ModP;
use crate::poly::{Poly, SizeError, Var};
use crate::Rational;
use exactcheck_core::{Field, Ring, Rng};
use std::any::Any;

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
    /// expression is defined where none of them vanishes.
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
        let g = poly_gcd(&self.den, &o.den)?;
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

    /// `self * o`.
    pub fn mul(&self, o: &Self) -> Result<Self, SizeError> {
        Self::reduced(
            self.num.try_mul(&o.num)?,
            self.den.try_mul(&o.den)?,
            self,
            o,
        )
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
    pub fn derivative(&self, v: Var) -> Result<Self, SizeError> {
        let dn = poly_derivative(&self.num, v);
        if self.den.is_constant() {
            return Ok(RatFun {
                num: dn,
                ..self.clone()
            });
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

/// Adds the condition `p != 0` to `conditions` (monic polynomials whose zeros are excluded)
/// without repeating a zero already excluded: `p` is reduced to its square-free part
/// `p / gcd(p, dp/dx_1, ..., dp/dx_n)` (exact over a field of characteristic 0), and the common
/// factor with every condition already listed is divided out; what remains, if not constant,
/// is added. `(t + 1)^2` after `t + 1` adds nothing, `x^2 - 1` after `x - 1` adds `x + 1`. When
/// a gcd exceeds a limit, `p` is added as it is (the same zeros, less tidy).
pub fn push_condition<C: Field>(conditions: &mut Vec<Poly<C>>, p: &Poly<C>) {
    if p.is_constant() {
        return;
    }
    let tidy = || -> Result<Poly<C>, SizeError> {
        let mut g = p.clone();
        for v in p.variables() {
            g = poly_gcd(&g, &poly_derivative(p, v))?;
        }
        let mut q = div_exact(p, &g).expect("the gcd divides the polynomial");
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

/// The seed of the residues [`certified_coprime`] substitutes (any fixed value: the test is
/// sound for every choice, and a bad one only costs a fallback).
const COPRIME_SEED: u64 = 0x6763_645f_6d6f_6470;

/// Both polynomials as polynomials with rational coefficients, `None` for another field.
fn as_rational<'a, C: Field>(
    a: &'a Poly<C>,
    b: &'a Poly<C>,
) -> Option<(&'a Poly<Rational>, &'a Poly<Rational>)> {
    let a = (a as &dyn Any).downcast_ref::<Poly<Rational>>()?;
    let b = (b as &dyn Any).downcast_ref::<Poly<Rational>>()?;
    Some((a, b))
}

/// The residues substituted for variables `0..n` (the same for every call).
fn residues(n: usize) -> Vec<ModP> {
    let mut rng = Rng::new(COPRIME_SEED);
    (0..n).map(|_| ModP::random(&mut rng)).collect()
}

/// The image of `p` modulo `2^61 - 1` as a polynomial in `v` (coefficient `i` of `v^i`), every
/// other variable `w` replaced by `at[w]`; `None` when a coefficient's denominator is a
/// multiple of the prime.
fn image_in(p: &Poly<Rational>, v: Var, at: &[ModP]) -> Option<Vec<ModP>> {
    let mut out = vec![ModP::ZERO; p.degree_in(v) as usize + 1];
    for (m, c) in p.terms() {
        let mut x = ModP::from_rational(c).ok()?;
        let mut e_v = 0;
        for (w, e) in m.exponents() {
            if w == v {
                e_v = e as usize;
            } else {
                x *= at[w as usize].pow_u64(u64::from(e));
            }
        }
        out[e_v] += x;
    }
    Some(out)
}

/// `f` without its zero leading coefficients.
fn trimmed(mut f: Vec<ModP>) -> Vec<ModP> {
    while f.last().is_some_and(ModP::is_zero) {
        f.pop();
    }
    f
}

/// The remainder of `f` by `g` (`g` trimmed, not zero) modulo the prime.
fn rem_mod_p(mut f: Vec<ModP>, g: &[ModP]) -> Vec<ModP> {
    let inv = g[g.len() - 1]
        .inv()
        .expect("a trimmed polynomial leads with a unit");
    while f.len() >= g.len() {
        let q = f[f.len() - 1] * inv;
        let shift = f.len() - g.len();
        for (i, gi) in g.iter().enumerate() {
            f[shift + i] -= q * *gi;
        }
        f.pop();
        f = trimmed(f);
    }
    f
}

/// The degree of the gcd of `f` and `g` modulo the prime (`None` when both are zero).
fn gcd_degree_mod_p(f: Vec<ModP>, g: Vec<ModP>) -> Option<usize> {
    let (mut f, mut g) = (trimmed(f), trimmed(g));
    while !g.is_empty() {
        let r = rem_mod_p(f, &g);
        f = g;
        g = r;
    }
    f.len().checked_sub(1)
}

/// Whether `a` and `b` are proved coprime by their images modulo `2^61 - 1` (see the module
/// documentation): `Some(true)` when proved, `Some(false)` when not (they probably share a
/// factor), `None` when the coefficients are not rational (the test does not apply).
///
/// Soundness: let `g` be the gcd over Q and `v` a variable of both. Scaled to be primitive over
/// the rationals whose denominators are prime to `p`, `g` and `a / g` have such coefficients
/// (Gauss's lemma), so the substitution `phi` (reduction modulo `p`, then the residues) maps
/// `g` to a divisor of both images. When the image of `a` keeps its degree in `v`, the leading
/// coefficient of `g` (a factor of `a`'s) does not vanish under `phi`, so `phi(g)` has the
/// degree of `g` in `v`, at most that of the image gcd. Degree 0 for every shared `v` leaves
/// `g` without the shared variables, and `g` divides both, so it is constant.
pub fn certified_coprime<C: Field>(a: &Poly<C>, b: &Poly<C>) -> Option<bool> {
    let (a, b) = as_rational(a, b)?;
    if a.is_zero() || b.is_zero() {
        return Some(a.is_constant() && b.is_constant() && !(a.is_zero() && b.is_zero()));
    }
    let vb = b.variables();
    let shared: Vec<Var> = a
        .variables()
        .into_iter()
        .filter(|v| vb.contains(v))
        .collect();
    let n = shared
        .iter()
        .chain(&vb)
        .chain(&a.variables())
        .map(|&v| v as usize + 1)
        .max()
        .unwrap_or(0);
    let at = residues(n);
    for v in shared {
        let (Some(fa), Some(fb)) = (image_in(a, v, &at), image_in(b, v, &at)) else {
            return Some(false);
        };
        let keeps = |f: &[ModP]| f.last().is_some_and(|c| !c.is_zero());
        if !keeps(&fa) && !keeps(&fb) {
            return Some(false);
        }
        if gcd_degree_mod_p(fa, fb) != Some(0) {
            return Some(false);
        }
    }
    Some(true)
}

/// Whether `h` may divide `p` (rational coefficients): `false` when, in a variable of `h`, the
/// image of `h` modulo the prime keeps its degree and does not divide the image of `p` (then
/// `h` does not divide `p`, and the exact division need not be tried); `true` otherwise.
fn div_image_possible<C: Field>(p: &Poly<C>, h: &Poly<C>) -> bool {
    let Some((p, h)) = as_rational(p, h) else {
        return true;
    };
    let Some(&v) = h.variables().first() else {
        return true;
    };
    let n = p
        .variables()
        .iter()
        .chain(&h.variables())
        .map(|&w| w as usize + 1)
        .max()
        .unwrap_or(0);
    let at = residues(n);
    let (Some(fp), Some(fh)) = (image_in(p, v, &at), image_in(h, v, &at)) else {
        return true;
    };
    if fh.last().is_none_or(ModP::is_zero) {
        return true;
    }
    trimmed(rem_mod_p(fp, &fh)).is_empty()
}

/// The partial derivative of `p` in `v`.
pub fn poly_derivative<C: Ring>(p: &Poly<C>, v: Var) -> Poly<C> {
    Poly::from_terms(p.terms().filter_map(|(m, c)| {
        let e = m.exponent(v);
        (e > 0).then(|| {
            let exps: Vec<(Var, u32)> = m
                .exponents()
                .into_iter()
                .map(|(w, k)| (w, if w == v { k - 1 } else { k }))
                .filter(|&(_, k)| k > 0)
                .collect();
            (exps, c.scale_i64(i64::from(e)))
        })
    }))
}

/// `a / b` when `b` divides `a` exactly (`None` otherwise, or for `b = 0`): division by the
/// leading term in the monomial order until nothing is left. The remainder is kept in an
/// ordered map (exponents from the highest variable down, which is the order of
/// [`crate::poly`]), so each step costs the terms of `b` times a logarithm rather than a pass
/// over the whole remainder.
pub fn div_exact<C: Field>(a: &Poly<C>, b: &Poly<C>) -> Option<Poly<C>> {
    let (_, bc) = b.leading_term()?;
    let binv = bc.inv().ok()?;
    let n = a
        .variables()
        .iter()
        .chain(&b.variables())
        .map(|&v| v as usize + 1)
        .max()
        .unwrap_or(0);
    let key = |exps: &[(Var, u32)]| {
        let mut k = vec![0u32; n];
        for &(v, e) in exps {
            k[n - 1 - v as usize] = e;
        }
        k
    };
    let bterms: Vec<(Vec<u32>, C)> = b
        .terms()
        .map(|(m, c)| (key(&m.exponents()), c.clone()))
        .collect();
    let ((blead, _), brest) = bterms.split_first()?;
    let mut rest: std::collections::BTreeMap<Vec<u32>, C> = a
        .terms()
        .map(|(m, c)| (key(&m.exponents()), c.clone()))
        .collect();
    let mut quotient = Vec::new();
    while let Some((m, c)) = rest.pop_last() {
        let q: Vec<u32> = m
            .iter()
            .zip(blead)
            .map(|(x, y)| x.checked_sub(*y))
            .collect::<Option<_>>()?;
        let qc = c.mul_ref(&binv);
        for (bm, bc) in brest {
            let k: Vec<u32> = q.iter().zip(bm).map(|(x, y)| x + y).collect();
            let t = qc.mul_ref(bc);
            match rest.entry(k) {
                std::collections::btree_map::Entry::Occupied(mut o) => {
                    let v = o.get().sub_ref(&t);
                    if v.is_zero() {
                        o.remove();
                    } else {
                        *o.get_mut() = v;
                    }
                }
                std::collections::btree_map::Entry::Vacant(v) => {
                    v.insert(t.neg_ref());
                }
            }
        }
        let exps: Vec<(Var, u32)> = (0..n)
            .rev()
            .filter(|&i| q[i] > 0)
            .map(|i| ((n - 1 - i) as Var, q[i]))
            .collect();
        quotient.push((exps, qc));
    }
    Some(Poly::from_terms(quotient))
}

/// A term: its exponents and its coefficient.
type Term<C> = (Vec<(Var, u32)>, C);

/// The coefficients of `p` as a polynomial in `v`: entry `i` is the coefficient of `v^i` (a
/// polynomial in the other variables).
pub(crate) fn coefficients_in<C: Ring>(p: &Poly<C>, v: Var) -> Vec<Poly<C>> {
    let mut buckets: Vec<Vec<Term<C>>> = vec![Vec::new(); p.degree_in(v) as usize + 1];
    for (m, c) in p.terms() {
        let e = m.exponent(v) as usize;
        let rest: Vec<(Var, u32)> = m.exponents().into_iter().filter(|&(w, _)| w != v).collect();
        buckets[e].push((rest, c.clone()));
    }
    buckets.into_iter().map(Poly::from_terms).collect()
}

/// Why a gcd computation with a budget of terms stopped.
#[derive(Debug)]
pub(crate) enum GcdError {
    /// A product exceeded a named limit.
    Size(SizeError),
    /// The remainders together had more terms than the budget.
    Capped,
}

impl From<SizeError> for GcdError {
    fn from(e: SizeError) -> GcdError {
        GcdError::Size(e)
    }
}

/// The gcd of the coefficients of `p` in `v` (monic), the terms of all remainders taken from
/// `budget`.
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
        let shift = Poly::monomial(C::one(), &[(v, dr - dg)]);
        r = lc_g
            .try_mul(&r)?
            .sub_ref(&lc_r.try_mul(&shift)?.try_mul(g)?);
        *budget = budget.checked_sub(r.len()).ok_or(GcdError::Capped)?;
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
        GcdError::Capped => unreachable!("no computation produces usize::MAX terms"),
    })
}

/// [`poly_gcd`], taking the terms of every pseudo-remainder from `budget` and stopping with
/// [`GcdError::Capped`] when it runs out (a bound on the work for callers that can do without
/// the gcd).
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
fn prs_gcd<C: Field>(a: &Poly<C>, b: &Poly<C>, budget: &mut usize) -> Result<Poly<C>, GcdError> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;
    use crate::Rational;

    fn p(text: &str, vars: &mut Vars) -> Poly<Rational> {
        parse_poly(text, vars).unwrap()
    }

    #[test]
    fn gcd_of_products_is_the_common_factor() {
        let mut vars = Vars::from_names(["x", "y", "z"]);
        let common = p("x*y - z^2 + 3", &mut vars);
        let a = common.mul_ref(&p("x + y + 1", &mut vars));
        let b = common
            .mul_ref(&p("x - 2*z", &mut vars))
            .scale(&Rational::from(7));
        assert_eq!(poly_gcd(&a, &b).unwrap(), common.make_monic());
        let one = poly_gcd(&p("x + 1", &mut vars), &p("x - 1", &mut vars)).unwrap();
        assert!(one.is_one());
        // A content in the other variables: gcd(y x + y, y^2 x) = y.
        let g = poly_gcd(&p("y*x + y", &mut vars), &p("y^2*x", &mut vars)).unwrap();
        assert_eq!(g, p("y", &mut vars));
    }

    #[test]
    fn exact_division_and_its_refusal() {
        let mut vars = Vars::from_names(["x", "y"]);
        let a = p("x^3 - y^3", &mut vars);
        let b = p("x - y", &mut vars);
        assert_eq!(div_exact(&a, &b).unwrap(), p("x^2 + x*y + y^2", &mut vars));
        assert!(div_exact(&p("x^2 + 1", &mut vars), &b).is_none());
    }

    #[test]
    fn fractions_cancel_and_differentiate() {
        let mut vars = Vars::from_names(["x"]);
        let x = RatFun::from_poly(p("x", &mut vars));
        let one = RatFun::from_poly(p("1", &mut vars));
        let xm1 = x.add(&one, true).unwrap();
        let f = x
            .mul(&x)
            .unwrap()
            .add(&one, true)
            .unwrap()
            .div(&xm1)
            .unwrap()
            .unwrap();
        assert_eq!(f.numerator(), &p("x + 1", &mut vars));
        assert!(f.denominator().is_one());
        assert_eq!(f.conditions(), &[p("x - 1", &mut vars)]);
        // d/dx 1/(x - 1) = -1/(x - 1)^2.
        let g = one.div(&xm1).unwrap().unwrap().derivative(0).unwrap();
        assert_eq!(g.numerator(), &p("-1", &mut vars));
        assert_eq!(g.denominator(), &p("(x - 1)^2", &mut vars));
        assert!(xm1.add(&xm1, true).unwrap().recip().is_none());
    }

    #[test]
    fn the_coprimality_certificate_decides_the_clear_cases() {
        let mut vars = Vars::from_names(["x", "y", "z"]);
        let a = p("x*y + z + 1", &mut vars);
        let b = p("x - y^2 + 3*z", &mut vars);
        assert_eq!(certified_coprime(&a, &b), Some(true));
        // A planted common factor is never certified away.
        let c = p("x + z^2 - 2", &mut vars);
        assert_eq!(
            certified_coprime(&a.mul_ref(&c), &b.mul_ref(&c)),
            Some(false)
        );
        // Without shared variables the gcd is constant.
        assert_eq!(
            certified_coprime(&p("x + 1", &mut vars), &p("y + 2", &mut vars)),
            Some(true)
        );
        // Other coefficient fields: the test does not apply.
        let r = crate::poly::Poly::<crate::Radical>::one();
        assert_eq!(certified_coprime(&r, &r), None);
    }

    #[test]
    fn cancellation_divides_out_the_divisors_met() {
        // The curvature pattern: a numerator carrying W^2 over W^5 ends over W^3.
        let mut vars = Vars::from_names(["t", "w"]);
        let w = p("w*t^2 + 2*t + 1", &mut vars);
        let n = p("t^3 - w + 5", &mut vars);
        let num = n.mul_ref(&w).mul_ref(&w);
        let den = w.try_pow(5).unwrap();
        let (got_n, got_d) = cancel(num, den, std::slice::from_ref(&w)).unwrap();
        assert_eq!(got_d, w.try_pow(3).unwrap().make_monic());
        assert_eq!(got_n.mul_ref(&w.try_pow(3).unwrap()), n.mul_ref(&got_d));
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// Against the remainder sequence: a certified pair has gcd 1 there, and a pair with a
        /// planted non-constant factor is never certified.
        #[test]
        fn certificate_agrees_with_the_remainder_sequence(
            ca in proptest::collection::vec(-3i64..=3, 6),
            cb in proptest::collection::vec(-3i64..=3, 6),
            cc in proptest::collection::vec(-3i64..=3, 3),
        ) {
            let mut vars = Vars::from_names(["x", "y"]);
            let monos = ["1", "x", "y", "x*y", "x^2", "y^2"];
            let build = |cs: &[i64], vars: &mut Vars| {
                let text: Vec<String> = cs.iter().zip(monos).map(|(c, m)| format!("({c})*{m}")).collect();
                p(&text.join(" + "), vars)
            };
            let (a, b) = (build(&ca, &mut vars), build(&cb, &mut vars));
            let c = build(&cc, &mut vars).add_ref(&p("x*y", &mut vars));
            if certified_coprime(&a, &b) == Some(true) && !a.is_constant() && !b.is_constant() {
                let mut budget = usize::MAX;
                proptest::prop_assert!(prs_gcd(&a, &b, &mut budget).unwrap().is_constant());
            }
            if !a.is_zero() && !b.is_zero() {
                proptest::prop_assert_eq!(
                    certified_coprime(&a.mul_ref(&c), &b.mul_ref(&c)),
                    Some(false)
                );
            }
        }
    }
}
