//! Identities between rational functions: `L = R` with `L = a/b`, `R = c/d` is decided as the
//! polynomial identity `a (d/g) - c (b/g) = 0`, `g = gcd(b, d)` (the denominators cleared by
//! their least common multiple: `a - c` when they are equal) wherever the denominators and
//! every divisor met in `L` and `R` are non-zero; the counter-example search avoids those zeros.

use super::{decide_where, DecideError, Decision, PointField, VarDomain};
use crate::poly::{Poly, SizeError, Var, Vars};
use crate::ratfun::{div_exact, poly_gcd, push_condition, RatFun};
use crate::univariate::UPoly;
use crate::Rational;
use exactcheck_core::{Field, Ring, Sign};
use std::fmt::Display;

/// `L = R` with the denominators cleared.
#[derive(Clone, Debug)]
pub struct FractionIdentity<C: Ring> {
    /// `L - R` times the least common multiple of the denominators, `num(L) den(R)/g -
    /// num(R) den(L)/g` with `g` their gcd: zero exactly where `L = R` (off the conditions).
    pub residual: Poly<C>,
    /// `den(L) den(R) / g`, by which `residual` is `L - R` multiplied.
    pub denominator: Poly<C>,
    /// The divisors met in `L` and `R` (monic, non-constant, each once; they include the
    /// zeros of the denominators): `L = R` is meant where none vanishes.
    pub conditions: Vec<Poly<C>>,
}

impl<C: Field> FractionIdentity<C> {
    /// `lhs = rhs` with the denominators cleared.
    ///
    /// # Errors
    /// [`SizeError`] when a product exceeds the `degree` or `terms` limit.
    pub fn new(lhs: &RatFun<C>, rhs: &RatFun<C>) -> Result<Self, SizeError> {
        let (a, b) = (lhs.numerator(), lhs.denominator());
        let (c, d) = (rhs.numerator(), rhs.denominator());
        // Clearing by the lcm rather than the product keeps the residual as small as the
        // numerators allow: equal denominators (the common case) cost one subtraction.
        let (residual, denominator) = if b == d {
            (a.sub_ref(c), b.clone())
        } else {
            let g = poly_gcd(b, d)?;
            let bg = div_exact(b, &g).expect("the gcd divides the denominator");
            let dg = div_exact(d, &g).expect("the gcd divides the denominator");
            (a.try_mul(&dg)?.sub_ref(&c.try_mul(&bg)?), b.try_mul(&dg)?)
        };
        // Each side's conditions are already tidy among themselves and cover the zeros of its
        // denominator ([`RatFun::conditions`]): only those of the right side are merged in.
        let mut conditions = lhs.conditions().to_vec();
        for p in rhs.conditions() {
            push_condition(&mut conditions, p);
        }
        Ok(FractionIdentity {
            residual,
            denominator,
            conditions,
        })
    }
}

/// Decides `L = R` (cleared into `identity`) modulo `relations`, for the values in `domains`
/// where every condition of `identity` and every polynomial of `hypotheses` (the conditions of
/// relations between fractions) is non-zero: [`decide_where`] on the cleared residual. A
/// counter-example's value is that of `L - R` (the residual divided by the denominator there).
///
/// # Errors
/// As [`super::decide_in`].
pub fn decide_fraction<C: PointField>(
    identity: &FractionIdentity<C>,
    relations: &[Poly<C>],
    hypotheses: &[Poly<C>],
    domains: &[(Var, VarDomain)],
    nvars: usize,
) -> Result<Decision<C>, DecideError> {
    let mut nonzero = identity.conditions.clone();
    nonzero.extend(hypotheses.iter().cloned());
    let decision = decide_where(&identity.residual, relations, &nonzero, domains, nvars)?;
    Ok(match decision {
        Decision::Fails {
            normal_form,
            point,
            value,
        } => {
            let mut at = vec![C::Value::zero(); nvars];
            for (v, x) in &point {
                at[*v as usize] = C::lift_radical(x);
            }
            let den = identity.denominator.eval(&at, C::lift);
            let value = den
                .inv()
                .map(|inv| value.mul_ref(&inv))
                .expect("the search avoids the zeros of the denominators");
            Decision::Fails {
                normal_form,
                point,
                value,
            }
        }
        other => other,
    })
}

/// Whether `p` has no real zero: `Some(true)` when shown, `Some(false)` when it has one,
/// `None` when not decided. A polynomial in one variable with rational coefficients is decided
/// exactly by isolating its real roots ([`crate::univariate`]); in several variables the
/// sufficient test is that every exponent is even, every coefficient has the same sign and
/// the constant term is not zero (a sum of even powers with a positive constant, up to sign).
pub fn real_zero_free<C: PointField>(p: &Poly<C>) -> Option<bool> {
    if let Some(c) = p.constant_value() {
        return Some(!c.is_zero());
    }
    let rational: Vec<Rational> = p
        .coefficients()
        .iter()
        .map(|c| c.to_radical().and_then(|r| r.to_rational()))
        .collect::<Option<_>>()?;
    let vars = p.variables();
    if let [v] = vars.as_slice() {
        let mut coeffs = vec![Rational::ZERO; p.degree_in(*v) as usize + 1];
        for ((m, _), c) in p.terms().zip(&rational) {
            coeffs[m.exponent(*v) as usize] = c.clone();
        }
        return Some(UPoly::from_coeffs(coeffs).roots().is_empty());
    }
    let even = p
        .terms()
        .all(|(m, _)| m.exponents().iter().all(|&(_, e)| e % 2 == 0));
    let first = rational.first().map(Rational::signum);
    let same_sign = rational.iter().all(|c| Some(c.signum()) == first);
    let constant = p.terms().any(|(m, _)| m.exponents().is_empty());
    (even && same_sign && constant && first != Some(Sign::Zero)).then_some(true)
}

/// The side conditions as a clause of a verdict: `""` when there are none, else
/// `", where x != 1, t^2 + 1 != 0 (no real zero)"`, followed by `": no real point is excluded"`
/// when no condition has a real zero. [`real_zero_free`] is decided once per condition.
pub fn where_clause<C: PointField + Display>(conditions: &[Poly<C>], vars: &Vars) -> String {
    if conditions.is_empty() {
        return String::new();
    }
    let mut all_free = true;
    let parts: Vec<String> = conditions
        .iter()
        .map(|p| {
            let free = real_zero_free(p) == Some(true);
            all_free &= free;
            let note = if free { " (no real zero)" } else { "" };
            match p.variables().as_slice() {
                [v] if p.degree_in(*v) == 1 && p.coefficient(&[(*v, 1)]).is_one() => {
                    let name = vars.name(*v).unwrap_or("?");
                    format!(
                        "{name} != {}",
                        Poly::constant(p.coefficient(&[]).neg_ref()).display(vars)
                    )
                }
                _ => format!("{} != 0{note}", p.display(vars)),
            }
        })
        .collect();
    let mut w = format!(", where {}", parts.join(", "));
    if all_free {
        w.push_str(": no real point is excluded");
    }
    w
}
