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

use crate::poly::{Poly, SizeError, Var};
use exactcheck_core::{Field, Ring};

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
        let (num, den) = lowest_terms(num, den)?;
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
        let num = self
            .num
            .try_mul(&o.den)?
            .add_ref(&sign(o.num.try_mul(&self.den)?));
        Self::reduced(num, self.den.try_mul(&o.den)?, self, o)
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
        let (num, den) = lowest_terms(num, den)?;
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

/// `num / den` with their gcd cancelled and `den` monic (`0 / 1` for a zero numerator).
fn lowest_terms<C: Field>(num: Poly<C>, den: Poly<C>) -> Result<(Poly<C>, Poly<C>), SizeError> {
    if num.is_zero() {
        return Ok((num, Poly::one()));
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
/// leading term in the monomial order until nothing is left.
pub fn div_exact<C: Field>(a: &Poly<C>, b: &Poly<C>) -> Option<Poly<C>> {
    let (bm, bc) = b.leading_term()?;
    let (bm, binv) = (bm.exponents(), bc.inv().ok()?);
    let mut rest = a.clone();
    let mut quotient = Vec::new();
    while let Some((m, c)) = rest.leading_term() {
        let m = m.exponents();
        let mut q = Vec::with_capacity(m.len());
        for &(v, e) in &m {
            let d = bm.iter().find(|(w, _)| *w == v).map_or(0, |&(_, k)| k);
            if e < d {
                return None;
            }
            if e > d {
                q.push((v, e - d));
            }
        }
        if bm.iter().any(|(w, _)| !m.iter().any(|(v, _)| v == w)) {
            return None;
        }
        let qc = c.mul_ref(&binv);
        let term = Poly::monomial(qc.clone(), &q);
        rest = rest.sub_ref(&term.mul_ref(b));
        quotient.push((q, qc));
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
    if a.is_constant() || b.is_constant() {
        return Ok(Poly::one());
    }
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
}
