//! Fractions whose denominator is kept as a product of powers of polynomials, never reduced:
//! the cheap way to decide whether two rational expressions are equal.
//!
//! `N1/D1 = N2/D2` holds as rational functions exactly when `N1 D2 - N2 D1 = 0`: the verdict
//! needs no lowest terms. A [`Fraction`] is `num / (f_1^e_1 ... f_k^e_k)` with the `f_i`
//! non-constant and pairwise different (compared by equality, never by a gcd), each as it was
//! divided by: not made monic, so the integer coefficients of a written denominator stay
//! integers (scaling to a monic factor would make every product with it a product of
//! fractions). A factor met twice with different constant multiples is then kept twice, which
//! costs a larger product but no wrong result. A sum takes the
//! least common multiple of the two factor lists structurally (the larger exponent of equal
//! factors) and multiplies each numerator by the factors it misses; a product adds the
//! exponents; a power multiplies them; a reciprocal makes the numerator the one factor
//! and the expanded factors the numerator; a derivative raises the exponent of every factor
//! that contains the variable by one (the quotient rule for a product of powers). Nothing is
//! cancelled, so the operations cost products and sums only, where [`super::RatFun`] divides
//! every numerator by the common factors it finds. [`Fraction::cross_residual`] then
//! cross-multiplies two fractions once.
//!
//! The divisors met are kept as met (each once by equality, in order) and turned into
//! conditions only when asked ([`Fraction::conditions`]): [`push_condition`] on them in that
//! order, which gives the conditions [`super::RatFun`] records step by step (each is the
//! square-free part of its divisor without the factors of the ones before, whichever way the
//! lists were merged), so a fraction's conditions are those of the rational function the same
//! operations build. A divisor met in several places (the same denominator in two terms, or in
//! both sides of an identity) is then reduced once, not at every operation. Every operation answers `None` when a product passes a limit or the
//! factor list grows past [`MAX_FACTORS`]: the caller then takes the route through
//! [`super::RatFun`].

use super::{cancel, poly_derivative, push_condition, RatFun};
use crate::poly::{Poly, Var};
use exactcheck_core::{Field, Ring};

/// The most distinct factors a [`Fraction`]'s denominator may have; past it the operations
/// answer `None` (a nesting of many different divisors is reduced by gcds instead).
pub const MAX_FACTORS: usize = 16;

/// `num / prod f^e` with the divisors met (see the module documentation).
#[derive(Clone, Debug)]
pub struct Fraction<C: Ring> {
    num: Poly<C>,
    factors: Vec<(Poly<C>, u32)>,
    /// The divisors met: non-constant, pairwise different, in the order met.
    divisors: Vec<Poly<C>>,
}

/// A denominator: non-constant, pairwise different factors with exponents at least 1.
type Factors<C> = [(Poly<C>, u32)];

impl<C: Field> Fraction<C> {
    /// The polynomial `p` over 1, with no conditions.
    pub fn from_poly(p: Poly<C>) -> Self {
        Fraction {
            num: p,
            factors: Vec::new(),
            divisors: Vec::new(),
        }
    }

    /// The rational function `r` with its denominator as one factor, and its conditions.
    pub fn from_ratfun(r: &RatFun<C>) -> Self {
        let den = r.denominator();
        Fraction {
            num: r.numerator().clone(),
            factors: if den.is_constant() {
                Vec::new()
            } else {
                vec![(den.clone(), 1)]
            },
            divisors: r.conditions().to_vec(),
        }
    }

    /// The numerator.
    pub fn numerator(&self) -> &Poly<C> {
        &self.num
    }

    /// The factors of the denominator and their exponents.
    pub fn factors(&self) -> &Factors<C> {
        &self.factors
    }

    /// The denominator: the product of the factors expanded (1 without factors); `None` past a
    /// limit.
    pub fn denominator(&self) -> Option<Poly<C>> {
        times(&Poly::one(), &self.factors)
    }

    /// The conditions of the divisors met, as [`RatFun::conditions`] (see the module
    /// documentation).
    pub fn conditions(&self) -> Vec<Poly<C>> {
        let mut conditions = Vec::with_capacity(self.divisors.len());
        for d in &self.divisors {
            push_condition(&mut conditions, d);
        }
        conditions
    }

    /// The conditions, consuming the fraction.
    pub fn into_conditions(self) -> Vec<Poly<C>> {
        self.conditions()
    }

    /// The rational function in lowest terms with the conditions of the divisors met: the
    /// numerator over the product of the factors, cancelled with the factors as the divisors
    /// to try first (as [`RatFun`]'s operations cancel). Lowest terms with a monic denominator
    /// are unique, so this is the [`RatFun`] the same operations build step by step. `None`
    /// past a limit.
    pub fn to_ratfun(&self) -> Option<RatFun<C>> {
        let den = times(&Poly::one(), &self.factors)?;
        let hints: Vec<Poly<C>> = self.factors.iter().map(|(f, _)| f.clone()).collect();
        let (num, den) = cancel(self.num.clone(), den, &hints).ok()?;
        Some(RatFun {
            num,
            den,
            conditions: self.conditions(),
        })
    }

    /// The terms of the numerator and of the factors together: the size that decides which of
    /// two equal fractions is cheaper to reduce.
    pub fn terms(&self) -> usize {
        self.num.len() + self.factors.iter().map(|(f, _)| f.len()).sum::<usize>()
    }

    /// A fraction of `num` over `factors` with the divisors `divisors`; zero has no factors,
    /// and a list longer than [`MAX_FACTORS`] is `None`.
    fn build(num: Poly<C>, factors: Vec<(Poly<C>, u32)>, divisors: Vec<Poly<C>>) -> Option<Self> {
        let factors = if num.is_zero() { Vec::new() } else { factors };
        (factors.len() <= MAX_FACTORS).then_some(Fraction {
            num,
            factors,
            divisors,
        })
    }

    /// The divisors of `self`, then those of `o` not among them (the order of [`RatFun`]'s
    /// operations).
    fn merged_divisors(&self, o: &Self) -> Vec<Poly<C>> {
        let mut divisors = self.divisors.clone();
        for d in &o.divisors {
            if !divisors.contains(d) {
                divisors.push(d.clone());
            }
        }
        divisors
    }

    /// `self + o` (`o` negated when `minus`) over the structural least common multiple of the
    /// two denominators.
    pub fn add(&self, o: &Self, minus: bool) -> Option<Self> {
        let (lcm, miss_a, miss_b) = common_multiple(&self.factors, &o.factors);
        let b = times(&o.num, &miss_b)?;
        let b = if minus { b.neg_ref() } else { b };
        let num = times(&self.num, &miss_a)?.add_ref(&b);
        Self::build(num, lcm, self.merged_divisors(o))
    }

    /// `-self`.
    pub fn neg(&self) -> Self {
        Fraction {
            num: self.num.neg_ref(),
            ..self.clone()
        }
    }

    /// `self * o`: the numerators multiplied, the exponents of equal factors added.
    pub fn mul(&self, o: &Self) -> Option<Self> {
        let num = self.num.try_mul(&o.num).ok()?;
        let mut factors = self.factors.clone();
        for (f, e) in &o.factors {
            match factors.iter_mut().find(|(g, _)| g == f) {
                Some((_, k)) => *k = k.checked_add(*e)?,
                None => factors.push((f.clone(), *e)),
            }
        }
        Self::build(num, factors, self.merged_divisors(o))
    }

    /// `1 / self`, recording the numerator as a divisor; `None` for zero.
    pub fn recip(&self) -> Option<Self> {
        if self.num.is_zero() {
            return None;
        }
        let mut divisors = self.divisors.clone();
        let (num, factors) = match self.num.constant_value() {
            Some(c) => {
                let inv = c.inv().ok()?;
                (times(&Poly::constant(inv), &self.factors)?, Vec::new())
            }
            None => {
                if !divisors.contains(&self.num) {
                    divisors.push(self.num.clone());
                }
                (
                    times(&Poly::one(), &self.factors)?,
                    vec![(self.num.clone(), 1)],
                )
            }
        };
        Self::build(num, factors, divisors)
    }

    /// `self^k` (`k` may be negative: then the numerator is recorded as a divisor); `None`
    /// for a negative power of zero.
    pub fn pow(&self, k: i64) -> Option<Self> {
        let base = if k < 0 { self.recip()? } else { self.clone() };
        let e = u32::try_from(k.unsigned_abs()).ok()?;
        if e == 0 {
            return Self::build(Poly::one(), Vec::new(), base.divisors);
        }
        let num = base.num.try_pow(e).ok()?;
        let factors = base
            .factors
            .iter()
            .map(|(f, x)| Some((f.clone(), x.checked_mul(e)?)))
            .collect::<Option<_>>()?;
        Self::build(num, factors, base.divisors)
    }

    /// The derivative in `v`: with `S` the factors containing `v`, `(N' prod_S h - N sum_S
    /// e_h h' prod_(S - h) g) / (prod h^e prod_S h)`; the divisors stay.
    pub fn derivative(&self, v: Var) -> Option<Self> {
        let dn = poly_derivative(&self.num, v);
        let moving: Vec<usize> = (0..self.factors.len())
            .filter(|&i| self.factors[i].0.degree_in(v) > 0)
            .collect();
        let product_except = |skip: Option<usize>| -> Option<Poly<C>> {
            moving
                .iter()
                .filter(|&&i| Some(i) != skip)
                .try_fold(Poly::one(), |acc, &i| acc.try_mul(&self.factors[i].0).ok())
        };
        let mut num = dn.try_mul(&product_except(None)?).ok()?;
        for &i in &moving {
            let (h, e) = &self.factors[i];
            let term = self
                .num
                .try_mul(&poly_derivative(h, v).scale_i64(i64::from(*e)))
                .ok()?
                .try_mul(&product_except(Some(i))?)
                .ok()?;
            num = num.sub_ref(&term);
        }
        let mut factors = self.factors.clone();
        for &i in &moving {
            factors[i].1 = factors[i].1.checked_add(1)?;
        }
        Self::build(num, factors, self.divisors.clone())
    }

    /// `self - o` over the structural least common multiple `M` of the denominators, times `M`:
    /// the polynomial that vanishes exactly where `self = o` off the zeros of the factors (zero
    /// exactly when the two are equal rational functions). `None` past a limit.
    pub fn cross_residual(&self, o: &Self) -> Option<Poly<C>> {
        let (_, miss_a, miss_b) = common_multiple(&self.factors, &o.factors);
        Some(times(&self.num, &miss_a)?.sub_ref(&times(&o.num, &miss_b)?))
    }
}

/// `p prod f^e` over `factors`, within the limits.
fn times<C: Field>(p: &Poly<C>, factors: &Factors<C>) -> Option<Poly<C>> {
    factors.iter().try_fold(p.clone(), |acc, (f, e)| {
        acc.try_mul(&f.try_pow(*e).ok()?).ok()
    })
}

/// The structural least common multiple of two denominators (equal factors with the larger
/// exponent), and what each misses of it.
#[allow(clippy::type_complexity)]
fn common_multiple<C: Field>(
    a: &Factors<C>,
    b: &Factors<C>,
) -> (
    Vec<(Poly<C>, u32)>,
    Vec<(Poly<C>, u32)>,
    Vec<(Poly<C>, u32)>,
) {
    let mut lcm = a.to_vec();
    for (f, e) in b {
        match lcm.iter_mut().find(|(g, _)| g == f) {
            Some((_, k)) => *k = (*k).max(*e),
            None => lcm.push((f.clone(), *e)),
        }
    }
    let missing = |side: &Factors<C>| -> Vec<(Poly<C>, u32)> {
        lcm.iter()
            .filter_map(|(f, e)| {
                let have = side.iter().find(|(g, _)| g == f).map_or(0, |&(_, k)| k);
                (*e > have).then(|| (f.clone(), e - have))
            })
            .collect()
    };
    let (miss_a, miss_b) = (missing(a), missing(b));
    (lcm, miss_a, miss_b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;
    use crate::Rational;
    use proptest::prelude::*;

    /// A small polynomial in `x, y` from drawn coefficients.
    fn small(coeffs: &[i64], vars: &mut Vars) -> Poly<Rational> {
        let monos = ["1", "x", "y", "x y", "x^2"];
        let text: Vec<String> = coeffs
            .iter()
            .zip(monos)
            .map(|(c, m)| format!("({c}) * {m}"))
            .collect();
        parse_poly(&text.join(" + "), vars).unwrap()
    }

    /// The two paths agree: equal values (zero cross residual against the reduced fraction),
    /// equal conditions, and the fraction reduced at the end is the rational function.
    fn agree(f: &Fraction<Rational>, r: &RatFun<Rational>) {
        let reduced = Fraction::from_ratfun(r);
        assert!(
            f.cross_residual(&reduced).unwrap().is_zero(),
            "{f:?} vs {r:?}"
        );
        assert_eq!(f.conditions(), r.conditions(), "{f:?} vs {r:?}");
        assert_eq!(f.to_ratfun().as_ref(), Some(r), "{f:?} vs {r:?}");
    }

    #[test]
    fn equal_factors_are_shared_and_the_residual_is_cleared_once() {
        let mut vars = Vars::from_names(["x", "y"]);
        let w = Fraction::from_poly(parse_poly::<Rational>("x^2 + 1", &mut vars).unwrap());
        let x = Fraction::from_poly(parse_poly::<Rational>("x", &mut vars).unwrap());
        // x/w^2 + 1/w = (x + w)/w^2: one factor with exponent 2, nothing cancelled.
        let a = x.mul(&w.pow(-2).unwrap()).unwrap();
        let b = w.recip().unwrap();
        let s = a.add(&b, false).unwrap();
        assert_eq!(s.factors().len(), 1);
        assert_eq!(s.factors()[0].1, 2);
        assert_eq!(s.conditions().len(), 1);
        // (x^2 - 1)/(x - 1) = x + 1: the residual vanishes, the condition is x - 1.
        let num = Fraction::from_poly(parse_poly::<Rational>("x^2 - 1", &mut vars).unwrap());
        let den = Fraction::from_poly(parse_poly::<Rational>("x - 1", &mut vars).unwrap());
        let q = num.mul(&den.recip().unwrap()).unwrap();
        let rhs = Fraction::from_poly(parse_poly::<Rational>("x + 1", &mut vars).unwrap());
        assert!(q.cross_residual(&rhs).unwrap().is_zero());
        assert!(!q.cross_residual(&x).unwrap().is_zero());
        assert_eq!(
            q.conditions()[0],
            parse_poly::<Rational>("x - 1", &mut vars).unwrap()
        );
    }

    #[test]
    fn a_divisor_keeps_its_integer_coefficients_and_repeats_are_reduced_once() {
        let mut vars = Vars::from_names(["x", "y"]);
        let d = parse_poly::<Rational>("2 x^2 + 2 y^2 + 4", &mut vars).unwrap();
        let inv = Fraction::from_poly(d.clone()).recip().unwrap();
        assert_eq!(inv.factors(), &[(d.clone(), 1)]);
        // The same denominator in two terms: one factor, one condition, made monic.
        let x = Fraction::from_poly(parse_poly::<Rational>("x", &mut vars).unwrap());
        let s = x.mul(&inv).unwrap().add(&inv, false).unwrap();
        assert_eq!(s.factors().len(), 1);
        assert_eq!(s.conditions(), vec![d.make_monic()]);
    }

    #[test]
    fn a_factor_list_past_the_budget_is_refused() {
        let mut vars = Vars::from_names(["x"]);
        let mut acc = Fraction::from_poly(Poly::<Rational>::one());
        for k in 1..=MAX_FACTORS as i64 {
            let f = parse_poly::<Rational>(&format!("x + {k}"), &mut vars).unwrap();
            acc = acc.mul(&Fraction::from_poly(f).recip().unwrap()).unwrap();
        }
        let last = parse_poly::<Rational>("x - 1", &mut vars).unwrap();
        assert!(acc
            .mul(&Fraction::from_poly(last).recip().unwrap())
            .is_none());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Random chains of `+ - * / ^` and derivatives on small polynomials: the factored
        /// fraction equals the rational function in lowest terms the same operations build
        /// (zero cross residual), with the same conditions.
        #[test]
        fn factored_arithmetic_agrees_with_ratfun(
            polys in proptest::collection::vec(proptest::collection::vec(-3i64..=3, 5), 2..=5),
            ops in proptest::collection::vec((0u8..6, 0usize..5, -2i64..=2), 1..=6),
        ) {
            let mut vars = Vars::from_names(["x", "y"]);
            let ps: Vec<Poly<Rational>> = polys.iter().map(|c| small(c, &mut vars)).collect();
            let mut f = Fraction::from_poly(ps[0].clone());
            let mut r = RatFun::from_poly(ps[0].clone());
            for (op, i, k) in ops {
                let p = ps[i % ps.len()].clone();
                let (pf, pr) = (Fraction::from_poly(p.clone()), RatFun::from_poly(p));
                let next = match op {
                    0 => Some((f.add(&pf, false), r.add(&pr, false).ok())),
                    1 => Some((f.add(&pf, true), r.add(&pr, true).ok())),
                    2 => Some((f.mul(&pf), r.mul(&pr).ok())),
                    3 => pr.recip().map(|inv| (f.mul(&pf.recip().unwrap()), r.mul(&inv).ok())),
                    4 => r.pow(k).ok().flatten().map(|q| (f.pow(k), Some(q))),
                    _ => Some((f.derivative(0), r.derivative(0).ok())),
                };
                let Some((Some(f2), Some(r2))) = next else { continue };
                f = f2;
                r = r2;
                agree(&f, &r);
            }
        }
    }
}
