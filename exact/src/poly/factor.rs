//! Square-free factorization of multivariate polynomials over a field of characteristic 0: a
//! polynomial as a constant times a monomial times powers of square-free, pairwise coprime
//! polynomials, so that a residual prints as `-3 (t - 1)^2 t^2 w0 w1^2 w2` instead of its forty
//! expanded terms.
//!
//! Hand-written because it needs the workspace's own polynomial type and gcd
//! ([`super::gcd::poly_gcd`]); the Rust crates that factor polynomials (none multivariate over
//! Q with this representation) would need a conversion both ways for every call.
//!
//! # Algorithm
//! 1. The leading coefficient is the constant factor; the rest is monic.
//! 2. The monomial factor: the smallest exponent of every variable over all terms.
//! 3. Recursively in the main variable `v` (the highest index present): the content (the gcd of
//!    the coefficients in `v`, a polynomial in the other variables) is factored the same way,
//!    and the primitive part by **Yun's algorithm** with the derivative in `v`:
//!    `a0 = gcd(f, f')`, `b1 = f / a0`, `d1 = f' / a0 - b1'`, then `a_i = gcd(b_i, d_i)`,
//!    `b_(i+1) = b_i / a_i`, `d_(i+1) = d_i / a_i - b_(i+1)'` until `b` is constant; `a_i` is
//!    the product of the factors of multiplicity `i`. Every factor of a primitive polynomial
//!    contains `v`, so the derivative in `v` sees every repeated factor.
//!
//! The factors are square-free and pairwise coprime (those of the content do not contain `v`,
//! those of the primitive part are primitive in `v`), but not necessarily irreducible:
//! `x^2 - y^2` stays one factor.
//!
//! # Limits
//! Factoring is for printing, so it must never dominate a run: a polynomial of more than
//! [`FACTOR_MAX_TERMS`] terms is not factored, and the factorization gives up when the
//! products of the remainder sequences of its gcds have cost [`FACTOR_WORK`] in all (term
//! products weighted by the sizes of the coefficients multiplied, so that a sequence whose
//! coefficients swell to thousands of digits stops as early as one whose terms multiply), or a
//! product passes a named limit. Then [`square_free`]
//! answers `None` and the caller prints the expanded form. These bounds decide only how a
//! result is printed, never a result, so they are constants rather than limits of the registry
//! (which refuse inputs).

use super::gcd::{content_in, gcd_capped, GcdError};
use super::{div_exact, poly_derivative};
use super::{Poly, Var};
use exactcheck_core::{Field, Ring};

/// The most terms of a polynomial [`square_free`] factors.
pub const FACTOR_MAX_TERMS: usize = 2_000;

/// The most work of all pseudo-remainder products together in the gcds of one [`square_free`]:
/// term products, each weighted by the 64-bit words of the two coefficients
/// (the `product_work` of [`crate::ratfun`]).
pub const FACTOR_WORK: usize = 10_000_000;

/// `unit * x^monomial * prod f^e` ([`square_free`]).
#[derive(Clone, Debug)]
pub struct Factorization<C> {
    /// The constant factor: the leading coefficient of the polynomial.
    pub unit: C,
    /// The monomial factor `(variable, exponent)`, by increasing variable.
    pub monomial: Vec<(Var, u32)>,
    /// The other factors and their multiplicities: each monic, non-constant, square-free,
    /// without a monomial factor, pairwise coprime; multiplicities at least 1.
    pub factors: Vec<(Poly<C>, u32)>,
}

impl<C: Field> Factorization<C> {
    /// The product `unit * x^monomial * prod f^e`, expanded.
    pub fn expand(&self) -> Poly<C> {
        let mut p = Poly::monomial(self.unit.clone(), &self.monomial);
        for (f, e) in &self.factors {
            for _ in 0..*e {
                p = p.mul_ref(f);
            }
        }
        p
    }
}

/// The square-free factorization of a non-zero `p` (module documentation); `None` for zero and
/// when a bound of the module documentation is reached.
pub fn square_free<C: Field>(p: &Poly<C>) -> Option<Factorization<C>> {
    if p.len() > FACTOR_MAX_TERMS {
        return None;
    }
    let (_, lc) = p.leading_term()?;
    let unit = lc.clone();
    let monic = p.scale(&unit.inv().ok()?);
    let vars = monic.variables();
    let monomial: Vec<(Var, u32)> = vars
        .iter()
        .map(|&v| {
            (
                v,
                monic.terms().map(|(m, _)| m.exponent(v)).min().unwrap_or(0),
            )
        })
        .filter(|&(_, e)| e > 0)
        .collect();
    let rest = if monomial.is_empty() {
        monic
    } else {
        Poly::from_terms(monic.terms().map(|(m, c)| {
            let exps: Vec<(Var, u32)> = m
                .exponents()
                .into_iter()
                .map(|(v, e)| {
                    let low = monomial
                        .iter()
                        .find(|(w, _)| *w == v)
                        .map_or(0, |&(_, k)| k);
                    (v, e - low)
                })
                .filter(|&(_, e)| e > 0)
                .collect();
            (exps, c.clone())
        }))
    };
    let mut factors = Vec::new();
    square_free_into(&rest, &mut factors, &mut FACTOR_WORK.clone()).ok()?;
    Some(Factorization {
        unit,
        monomial,
        factors,
    })
}

/// Appends the square-free factors of `p` (without a monomial factor) to `out`.
fn square_free_into<C: Field>(
    p: &Poly<C>,
    out: &mut Vec<(Poly<C>, u32)>,
    budget: &mut usize,
) -> Result<(), GcdError> {
    let Some(&v) = p.variables().iter().max() else {
        return Ok(());
    };
    let content = content_in(p, v, budget)?;
    let primitive = if content.is_constant() {
        p.clone()
    } else {
        square_free_into(&content, out, budget)?;
        div_exact(p, &content).expect("the content divides the polynomial")
    };
    let exact = |a: &Poly<C>, b: &Poly<C>| div_exact(a, b).expect("the gcd divides");
    // Yun's algorithm in v.
    let d = poly_derivative(&primitive, v);
    let a0 = gcd_capped(&primitive, &d, budget)?;
    let mut b = exact(&primitive, &a0);
    let mut dd = exact(&d, &a0).sub_ref(&poly_derivative(&b, v));
    let mut i = 1u32;
    while !b.is_constant() {
        let a = gcd_capped(&b, &dd, budget)?;
        if !a.is_constant() {
            out.push((a.make_monic(), i));
        }
        let c = exact(&dd, &a);
        b = exact(&b, &a);
        dd = c.sub_ref(&poly_derivative(&b, v));
        i += 1;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::gcd::poly_gcd;
    use crate::poly::Vars;
    use crate::Rational;
    use exactcheck_core::Ring;
    use proptest::prelude::*;

    fn p(text: &str, vars: &mut Vars) -> Poly<Rational> {
        parse_poly(text, vars).unwrap()
    }

    /// Checks the properties of the module documentation for `f` of `p`.
    fn check(p: &Poly<Rational>, f: &Factorization<Rational>) {
        assert_eq!(&f.expand(), p, "the product of the factors is the input");
        for (i, (a, e)) in f.factors.iter().enumerate() {
            assert!(*e >= 1 && !a.is_constant());
            assert!(a.leading_term().unwrap().1.is_one(), "monic: {a:?}");
            let mut g = a.clone();
            for v in a.variables() {
                g = poly_gcd(&g, &poly_derivative(a, v)).unwrap();
            }
            assert!(g.is_constant(), "{a:?} is not square-free");
            for v in a.variables() {
                assert!(
                    a.terms().any(|(m, _)| m.exponent(v) == 0),
                    "{a:?}: monomial factor"
                );
            }
            for (b, _) in &f.factors[i + 1..] {
                assert!(poly_gcd(a, b).unwrap().is_constant(), "{a:?}, {b:?}");
            }
        }
    }

    #[test]
    fn bernstein_residual_factors() {
        let mut vars = Vars::from_names(["t", "w0", "w1", "w2"]);
        let q = p("-3 w0 w1^2 w2 t^2 (1-t)^2", &mut vars);
        assert!(q.len() > 2);
        let f = square_free(&q).unwrap();
        check(&q, &f);
        assert_eq!(f.unit, Rational::from(-3));
        assert_eq!(f.monomial, vec![(0, 2), (1, 1), (2, 2), (3, 1)]);
        assert_eq!(f.factors, vec![(p("t - 1", &mut vars), 2)]);
    }

    #[test]
    fn content_and_primitive_part_both_factor() {
        let mut vars = Vars::from_names(["x", "y"]);
        // Content in y: (x + 1)^3; primitive part (y - x)^2 (y + 2).
        let q = p("5/2 (x + 1)^3 (y - x)^2 (y + 2)", &mut vars);
        let f = square_free(&q).unwrap();
        check(&q, &f);
        assert_eq!(f.unit, Rational::new(5, 2).unwrap());
        assert!(f.factors.contains(&(p("x + 1", &mut vars), 3)));
        assert!(f.factors.contains(&(p("y - x", &mut vars), 2)));
        assert!(f.factors.contains(&(p("y + 2", &mut vars), 1)));
        // Square-free, not irreducible: x^2 - y^2 stays one factor.
        let d = p("x^2 - y^2", &mut vars);
        assert_eq!(square_free(&d).unwrap().factors, vec![(d.make_monic(), 1)]);
        // Constants and zero.
        let c = square_free(&p("-7", &mut vars)).unwrap();
        assert!(c.monomial.is_empty() && c.factors.is_empty());
        assert!(square_free(&Poly::<Rational>::zero()).is_none());
    }

    #[test]
    fn too_many_terms_is_not_factored() {
        let mut vars = Vars::from_names(["x", "y", "z"]);
        let big = p("(x + y + z + 1)^25", &mut vars);
        assert!(big.len() > FACTOR_MAX_TERMS);
        assert!(square_free(&big).is_none());
    }

    /// A small random polynomial in `x, y, z` from the drawn coefficients.
    fn small_poly(coeffs: &[i64], vars: &mut Vars) -> Poly<Rational> {
        let monos = ["1", "x", "y", "z", "x y"];
        let text: Vec<String> = coeffs
            .iter()
            .zip(monos)
            .map(|(c, m)| format!("({c}) * {m}"))
            .collect();
        p(&text.join(" + "), vars)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Products of random factors with random multiplicities, a content and a monomial:
        /// the factors multiply back to the input, are monic, square-free and pairwise coprime,
        /// and the multiplicities account for the degree in each variable.
        #[test]
        fn factors_multiply_back_and_are_square_free_and_coprime(
            fs in proptest::collection::vec(
                (proptest::collection::vec(-3i64..=3, 5), 1u32..=3), 1..=3),
            unit in (-9i64..=9).prop_filter("non-zero", |u| *u != 0),
            mx in 0u32..=2,
            mz in 0u32..=2,
        ) {
            let mut vars = Vars::from_names(["x", "y", "z"]);
            let mut q = Poly::monomial(Rational::from(unit), &[(0, mx), (2, mz)]);
            for (c, e) in &fs {
                let f = small_poly(c, &mut vars);
                if f.is_zero() {
                    continue;
                }
                q = q.mul_ref(&f.pow(*e));
            }
            // Within the work bound the factors are checked; past it there is no answer.
            if let Some(f) = square_free(&q) {
                check(&q, &f);
            }
        }
    }
}
