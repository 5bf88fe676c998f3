//! Signs of polynomials on the domains (a box of intervals, one per variable), each one proved:
//!
//! * a non-zero constant has its sign;
//! * a polynomial in one variable `v` with rational coefficients: its real roots are isolated
//!   exactly and its sign on each open gap between them is known; the gaps and roots that meet
//!   the domain of `v` (compared with its rational ends exactly, [`super::chart`]) give the
//!   sign: `1 - x > 0` on `-1 < x < 1`, `t (1 - t) >= 0` on `0 <= t <= 1`;
//! * a sum of terms `c v1^e1 ... vk^ek`, each of a known sign on the box (an even power is
//!   `>= 0`, an odd power has the sign of its variable's domain), all of one sign;
//! * a product: the polynomial factored square-free ([`crate::poly::square_free`]), the sign of
//!   the constant, the monomial factor and each odd power of a factor decided as above and
//!   multiplied; an even power of a factor is `>= 0`.
//!
//! Anything else has no sign here (not shown, not disproved). Each factor decided from a
//! domain, other than a variable itself, is recorded as a [`SignFact`], so that a proof names
//! the sign facts it used.

use super::chart::{chart, univariate, Cell};
use super::{PointField, VarDomain};
use crate::poly::{square_free, Poly, Var};
use crate::{Radical, Rational};
use exactcheck_core::{Ring, Sign};
use std::cmp::Ordering;

/// A sign shown at every point of the domains.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SignOn {
    /// `> 0`.
    Positive,
    /// `>= 0`.
    NonNegative,
    /// `< 0`.
    Negative,
    /// `<= 0`.
    NonPositive,
}

impl SignOn {
    /// Whether the sign excludes zero.
    pub fn strict(self) -> bool {
        matches!(self, SignOn::Positive | SignOn::Negative)
    }

    /// Whether the sign is `> 0` or `>= 0`.
    pub fn non_negative(self) -> bool {
        matches!(self, SignOn::Positive | SignOn::NonNegative)
    }

    /// The sign from the direction (`>= 0` or `<= 0`) and the strictness.
    fn from_parts(non_negative: bool, strict: bool) -> SignOn {
        match (non_negative, strict) {
            (true, true) => SignOn::Positive,
            (true, false) => SignOn::NonNegative,
            (false, true) => SignOn::Negative,
            (false, false) => SignOn::NonPositive,
        }
    }

    /// The sign of the negation.
    fn neg(self) -> SignOn {
        SignOn::from_parts(!self.non_negative(), self.strict())
    }

    /// The sign of a product.
    fn mul(self, other: SignOn) -> SignOn {
        SignOn::from_parts(
            self.non_negative() == other.non_negative(),
            self.strict() && other.strict(),
        )
    }

    /// The sign of the `e`-th power, `e >= 1`.
    fn pow(self, e: u32) -> SignOn {
        if e % 2 == 0 {
            SignOn::from_parts(true, self.strict())
        } else {
            self
        }
    }

    /// The sign of a sum, when both have one direction.
    fn add(self, other: SignOn) -> Option<SignOn> {
        (self.non_negative() == other.non_negative())
            .then(|| SignOn::from_parts(self.non_negative(), self.strict() || other.strict()))
    }

    /// The relation to zero: `> 0`, `>= 0`, `< 0`, `<= 0`.
    pub fn relation(self) -> &'static str {
        match self {
            SignOn::Positive => "> 0",
            SignOn::NonNegative => ">= 0",
            SignOn::Negative => "< 0",
            SignOn::NonPositive => "<= 0",
        }
    }
}

/// A sign fact a proof used: `poly` has the sign `sign` wherever the variables `vars` lie in
/// their domains (`x - 1 < 0` on `-1 < x < 1`); `poly` has a positive leading coefficient.
#[derive(Clone, Debug, PartialEq)]
pub struct SignFact<C: exactcheck_core::Ring> {
    /// The polynomial.
    pub poly: Poly<C>,
    /// Its sign.
    pub sign: SignOn,
    /// The variables whose domains show it, increasing (none when it holds everywhere).
    pub vars: Vec<Var>,
}

/// The sign of `p` on the box `signs` (module documentation), recording in `facts` the sign
/// facts of the factors decided from a domain; `None` when no sign is shown (then `facts` may
/// hold facts of factors decided before the failure, which the caller drops).
pub fn sign_on<C: PointField>(
    p: &Poly<C>,
    signs: &[VarDomain],
    facts: &mut Vec<SignFact<C>>,
) -> Option<SignOn> {
    if let Some(c) = p.constant_value() {
        return coefficient_sign(&c);
    }
    if let Some(s) = factor_sign(p, signs, facts) {
        return Some(s);
    }
    let f = square_free(p)?;
    let mut sign = coefficient_sign(&f.unit)?;
    for &(v, e) in &f.monomial {
        let s = variable_sign(&domain_of(signs, v));
        sign = sign.mul(if e % 2 == 0 {
            s.map_or(SignOn::NonNegative, |s| s.pow(e))
        } else {
            s?
        });
    }
    for (q, e) in &f.factors {
        let s = if e % 2 == 0 {
            SignOn::NonNegative
        } else {
            factor_sign(q, signs, facts)?
        };
        sign = sign.mul(s);
    }
    Some(sign)
}

/// The sign of one factor: a single term by the domains of its variables; a univariate
/// polynomial by its sign chart; a sum of terms of one known sign. A factor of several terms
/// is recorded in `facts`.
fn factor_sign<C: PointField>(
    p: &Poly<C>,
    signs: &[VarDomain],
    facts: &mut Vec<SignFact<C>>,
) -> Option<SignOn> {
    if p.len() == 1 {
        // One term: its sign follows from the domains of its variables, hypotheses of their
        // own.
        return term_sum_sign(p, signs);
    }
    let vars = p.variables();
    let sign = match vars.as_slice() {
        [v] => univariate_sign(p, *v, &domain_of(signs, *v)),
        _ => None,
    }
    .or_else(|| term_sum_sign(p, signs))?;
    // The variables whose domains the sign rests on (none: it holds everywhere).
    let vars: Vec<Var> = vars
        .into_iter()
        .filter(|&v| {
            signs
                .get(v as usize)
                .is_some_and(|d| *d != VarDomain::all())
        })
        .collect();
    // Recorded with a positive leading coefficient: `x - 1 < 0`, not `-x + 1 > 0`.
    let negative = coefficient_sign(p.leading_term()?.1)? == SignOn::Negative;
    let fact = SignFact {
        poly: if negative { p.neg_ref() } else { p.clone() },
        sign: if negative { sign.neg() } else { sign },
        vars,
    };
    if !facts.contains(&fact) {
        facts.push(fact);
    }
    Some(sign)
}

/// The sign of a non-zero real coefficient.
fn coefficient_sign<C: PointField>(c: &C) -> Option<SignOn> {
    let r = c.to_radical()?;
    match r.partial_cmp(&Radical::zero())? {
        Ordering::Greater => Some(SignOn::Positive),
        Ordering::Less => Some(SignOn::Negative),
        Ordering::Equal => None,
    }
}

/// The domain of `v` in `signs`, the whole line when `signs` gives none.
fn domain_of(signs: &[VarDomain], v: Var) -> VarDomain {
    signs.get(v as usize).cloned().unwrap_or_default()
}

/// The sign a domain gives its variable, if any: `v > 0` from a lower end above 0 (or a strict
/// 0), `v >= 0` from a lower end 0, and the same below.
fn variable_sign(d: &VarDomain) -> Option<SignOn> {
    let zero = Rational::ZERO;
    if let Some((lo, strict)) = &d.lower {
        if *lo > zero || (*lo == zero && *strict) {
            return Some(SignOn::Positive);
        }
        if *lo == zero {
            return Some(SignOn::NonNegative);
        }
    }
    if let Some((hi, strict)) = &d.upper {
        if *hi < zero || (*hi == zero && *strict) {
            return Some(SignOn::Negative);
        }
        if *hi == zero {
            return Some(SignOn::NonPositive);
        }
    }
    None
}

/// The sign of `p`, a sum of terms each of a known sign on the box, all of one direction.
fn term_sum_sign<C: PointField>(p: &Poly<C>, signs: &[VarDomain]) -> Option<SignOn> {
    let mut total: Option<SignOn> = None;
    for (m, c) in p.terms() {
        let mut s = coefficient_sign(c)?;
        for (v, e) in m.exponents() {
            let d = variable_sign(&domain_of(signs, v));
            s = s.mul(if e % 2 == 0 {
                d.map_or(SignOn::NonNegative, |d| d.pow(e))
            } else {
                d?
            });
        }
        total = Some(match total {
            None => s,
            Some(t) => t.add(s)?,
        });
    }
    total
}

/// The sign of `p`, a polynomial in the one variable `v` with rational coefficients, on the
/// domain `d` of `v`: from its sign chart on the domain ([`chart`]), the gaps and roots of `p`
/// that meet it.
fn univariate_sign<C: PointField>(p: &Poly<C>, v: Var, d: &VarDomain) -> Option<SignOn> {
    let u = univariate(p, v)?;
    let mut direction: Option<bool> = None;
    let mut strict = true;
    for cell in chart(&u, d) {
        let positive = match cell {
            Cell::Root(_) => {
                strict = false;
                continue;
            }
            Cell::Gap { sign, .. } => match sign {
                Sign::Positive => true,
                Sign::Negative => false,
                Sign::Zero => return None,
            },
        };
        if direction.is_some_and(|dir| dir != positive) {
            return None;
        }
        direction = Some(positive);
    }
    // A point domain at a root: p is 0 there, `>= 0` (and `<= 0`).
    Some(SignOn::from_parts(direction.unwrap_or(true), strict))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;
    use crate::prove::chart::tests::dom as interval;

    fn p(text: &str, vars: &mut Vars) -> Poly<Rational> {
        parse_poly(text, vars).unwrap()
    }

    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n, d).unwrap()
    }

    /// The sign of `text` on `dom` (variables `x`, `y`), and the facts recorded.
    fn sign(text: &str, dom: &[VarDomain]) -> (Option<SignOn>, Vec<String>) {
        let mut vars = Vars::from_names(["x", "y"]);
        let q = p(text, &mut vars);
        let mut facts = Vec::new();
        let s = sign_on(&q, dom, &mut facts);
        let shown = facts
            .iter()
            .map(|f| format!("{} {}", f.poly.display(&vars), f.sign.relation()))
            .collect();
        (s, shown)
    }

    #[test]
    fn a_univariate_factor_has_the_sign_of_the_gaps_and_roots_in_its_domain() {
        let open = interval(Some((r(-1, 1), true)), Some((r(1, 1), true)));
        let closed = interval(Some((r(-1, 1), false)), Some((r(1, 1), false)));
        let all = VarDomain::all();
        let dom = |d: &VarDomain| vec![d.clone(), all.clone()];
        assert_eq!(sign("1 - x", &dom(&open)).0, Some(SignOn::Positive));
        assert_eq!(sign("x - 1", &dom(&open)).0, Some(SignOn::Negative));
        // The root 1 is in the closed interval: only >= 0.
        assert_eq!(sign("1 - x", &dom(&closed)).0, Some(SignOn::NonNegative));
        assert_eq!(sign("1 - x^2", &dom(&open)).0, Some(SignOn::Positive));
        assert_eq!(sign("1 - x^2", &dom(&closed)).0, Some(SignOn::NonNegative));
        // An irrational root inside the domain splits it: no sign.
        assert_eq!(sign("x^2 - 1/2", &dom(&open)).0, None);
        // Without a domain only a polynomial of one sign on the whole line has one.
        assert_eq!(sign("1 - x", &dom(&all)).0, None);
        assert_eq!(sign("x^2 + 1", &dom(&all)).0, Some(SignOn::Positive));
        // No domains given at all: the whole line.
        assert_eq!(sign("x^2 - 2*x + 2", &[]).0, Some(SignOn::Positive));
        assert_eq!(sign("x^2 - 2*x + 2", &[]).1, ["x^2 - 2*x + 2 > 0"]);
        // The root sqrt(2) against the end 3/2 exactly: 2 - x^2 > 0 below it only.
        let below = interval(Some((r(0, 1), false)), Some((r(7, 5), false)));
        let past = interval(Some((r(0, 1), false)), Some((r(3, 2), false)));
        assert_eq!(sign("2 - x^2", &dom(&below)).0, Some(SignOn::Positive));
        assert_eq!(sign("2 - x^2", &dom(&past)).0, None);
    }

    #[test]
    fn a_product_multiplies_the_signs_of_its_factors_and_names_them() {
        let open = interval(Some((r(-1, 1), true)), Some((r(1, 1), true)));
        let non_negative = interval(Some((Rational::ZERO, false)), None);
        let dom = vec![open.clone(), non_negative.clone()];
        // y (1 - x): y >= 0 by its domain, 1 - x > 0 on the interval.
        let (s, facts) = sign("y - x*y", &dom);
        assert_eq!(s, Some(SignOn::NonNegative));
        assert_eq!(facts.len(), 1, "{facts:?}");
        assert_eq!(facts, ["x - 1 < 0"]);
        let (s, _) = sign("x*y - y", &dom);
        assert_eq!(s, Some(SignOn::NonPositive));
        // x y has no sign: x changes sign on the interval.
        assert_eq!(sign("x*y", &dom).0, None);
        // An even power of a factor of unknown sign is >= 0.
        assert_eq!(sign("y*(x - 1/2)^2", &dom).0, Some(SignOn::NonNegative));
        // Several variables: a sum of terms of one sign (y >= 0, x + 1 > 0 on the box).
        let dom2 = vec![interval(Some((r(0, 1), true)), None), non_negative.clone()];
        assert_eq!(sign("x*y + 2*x + y^2", &dom2).0, Some(SignOn::Positive));
        assert_eq!(sign("x*y - 2*x", &dom2).0, None);
    }
}
