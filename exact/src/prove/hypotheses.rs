//! Proofs that use the hypotheses: the polynomials declared non-zero (the `nonzero` of
//! [`super::decide_where`]: `w != 0` in a `where`, the denominators of a fraction identity) and
//! the domains (`w > 0`, `t >= 0`, the sign condition `y >= 0` of a square root).
//!
//! * **Non-zero hypotheses** (Rabinowitsch): `h != 0` adds the relation `1 - h z` with a fresh
//!   variable `z`. The residual reduces to zero modulo a Gröbner basis of the relations and these
//!   exactly when `h^k residual` lies in the ideal of the relations for some `k` (the saturation),
//!   so the residual vanishes wherever the relations hold and `h` does not. A domain that excludes
//!   0 (`w > 0`) gives `w != 0`, and a strict bound `c` (`t < 1`) gives `t - c != 0`.
//! * **Sign conditions** (the branch of a square root): a variable `y` with `y >= 0` in its
//!   domain and a relation `D y^2 - N` (`D`, `N` free of `y`) is the non-negative root of
//!   `N / D`, when `D` has no zero on the points considered (a non-zero constant; a polynomial
//!   without a real zero; or one the relations and the non-zero hypotheses in use exclude:
//!   adding `D` to them leaves no common point). With `y^2` replaced by `N / D` and the result
//!   multiplied by `D^h` (`h` the half degree in `y`), the residual is `A + B y` (`A`, `B` free
//!   of `y`); if `D A^2 - B^2 N` vanishes (decided the same way, recursively for the other
//!   roots) and `-A B >= 0` on the domains, then `A + B y = 0` at every point: `(B y)^2 = A^2`,
//!   so `B = 0` forces `A = 0`, else `y = |A / B| = -A / B`; and the residual, `(A + B y) /
//!   D^h`, vanishes too. The sign of `-A B` is shown by a sufficient test: shifted so every
//!   bounded variable is non-negative (`v = lo + u` or `v = hi - u`), every coefficient is
//!   non-negative and every unbounded variable has even exponents; else by the sign decision
//!   of the `signs` module (a factor in one variable by its real roots against its interval, a
//!   product by the signs of its factors), which also shows a denominator `D` of a strict sign
//!   on the domains nowhere zero. The sign facts it used are reported with the hypotheses.
//!
//! When the identity holds under all the hypotheses, a smaller set that still proves it is found
//! greedily (drop one hypothesis, decide again, keep it dropped if the proof survives), with at
//! most [`MAX_HYPOTHESIS_DROPS`] extra decisions; the set reported is the one the proof used.

use super::signs::{self, SignFact, SignOn};
use super::{PointField, VarDomain};
use crate::poly::{groebner, Poly, Var};
use crate::{Radical, Rational};
use exactcheck_core::Ring;

/// The most hypotheses the minimization tries to drop (each try is one more Gröbner basis);
/// past it the remaining hypotheses are reported as used.
pub const MAX_HYPOTHESIS_DROPS: usize = 16;

/// A hypothesis a proof used.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Hypothesis {
    /// `nonzero[i] != 0` (an index into the polynomials declared non-zero).
    NonZero(usize),
    /// The domain of the variable: the non-zero polynomials it implies and its sign.
    Domain(Var),
}

/// The outcome of [`prove_under_hypotheses`].
pub(super) enum Outcome<C: Ring> {
    /// The identity holds where the hypotheses do; the hypotheses and the sign facts the proof
    /// used.
    Proved(Vec<Hypothesis>, Vec<SignFact<C>>),
    /// Not shown; what was tried (empty when there is no hypothesis to use).
    NotProved(String),
}

/// The data of one decision.
struct Problem<'a, C: PointField> {
    residual: &'a Poly<C>,
    relations: &'a [Poly<C>],
    nonzero: &'a [Poly<C>],
    dom: &'a [VarDomain],
}

/// A root: the variable `y`, and `N` and `D` from its relation `D y^2 - N` (a constant `D` is
/// divided out: `N / D` over 1).
#[derive(Clone)]
struct Root<C: Ring> {
    var: Var,
    square: Poly<C>,
    denominator: Poly<C>,
}

/// Decides whether `residual` vanishes wherever `relations` hold, `nonzero` does not vanish and
/// the variables lie in `dom` (see the module documentation).
pub(super) fn prove_under_hypotheses<C: PointField>(
    residual: &Poly<C>,
    relations: &[Poly<C>],
    nonzero: &[Poly<C>],
    dom: &[VarDomain],
) -> Outcome<C> {
    let problem = Problem {
        residual,
        relations,
        nonzero,
        dom,
    };
    let mut all: Vec<Hypothesis> = (0..nonzero.len())
        .filter(|&i| !nonzero[i].is_constant())
        .map(Hypothesis::NonZero)
        .collect();
    all.extend(
        (0..dom.len())
            .filter(|&v| dom[v] != VarDomain::all())
            .map(|v| Hypothesis::Domain(v as Var)),
    );
    if all.is_empty() {
        return Outcome::NotProved(String::new());
    }
    let tried = "; the hypotheses (each non-zero one by a Rabinowitsch variable, the signs of the domains and of the square roots) were used too";
    let mut facts = match problem.attempt(&all) {
        Ok(Some(facts)) => facts,
        Ok(None) => return Outcome::NotProved(format!("{tried}, without a proof")),
        Err(e) => return Outcome::NotProved(format!("{tried}: {e}")),
    };
    let mut used = all.clone();
    for h in all.iter().take(MAX_HYPOTHESIS_DROPS) {
        let without: Vec<Hypothesis> = used.iter().copied().filter(|u| u != h).collect();
        if let Ok(Some(f)) = problem.attempt(&without) {
            used = without;
            facts = f;
        }
    }
    Outcome::Proved(used, facts)
}

impl<C: PointField> Problem<'_, C> {
    /// The polynomials hypothesis `h` declares non-zero.
    fn nonzero_of(&self, h: Hypothesis) -> Vec<Poly<C>> {
        match h {
            Hypothesis::NonZero(i) => vec![self.nonzero[i].clone()],
            Hypothesis::Domain(v) => {
                let d = &self.dom[v as usize];
                let x = Poly::<C>::var(v);
                let shifted = |c: &Rational| {
                    let c = C::from_rational(c).expect("a field holds the rationals");
                    x.sub_ref(&Poly::constant(c))
                };
                let mut out = Vec::new();
                if !d.contains(&Radical::zero()) {
                    out.push(x.clone());
                }
                for (c, strict) in [&d.lower, &d.upper].into_iter().flatten() {
                    if *strict && !c.is_zero() {
                        out.push(shifted(c));
                    }
                }
                out
            }
        }
    }

    /// Whether the residual is shown zero under the hypotheses `set`: the sign facts the proof
    /// used when it is.
    fn attempt(
        &self,
        set: &[Hypothesis],
    ) -> Result<Option<Vec<SignFact<C>>>, exactcheck_core::limits::LimitError> {
        let nvars = self.dom.len();
        let mut gens = self.relations.to_vec();
        let mut z = nvars as Var;
        for &h in set {
            for p in self.nonzero_of(h) {
                gens.push(Poly::one().sub_ref(&p.mul_ref(&Poly::var(z))));
                z += 1;
            }
        }
        let basis = if gens.is_empty() {
            Vec::new()
        } else {
            groebner(&gens)?
        };
        // The hypotheses contradict the relations: nothing is claimed from that.
        if basis.iter().any(|b| b.is_constant() && !b.is_zero()) {
            return Ok(None);
        }
        let mut signs = vec![VarDomain::all(); nvars];
        for &h in set {
            if let Hypothesis::Domain(v) = h {
                signs[v as usize] = self.dom[v as usize].clone();
            }
        }
        let mut facts = Vec::new();
        let roots: Vec<Root<C>> = (0..nvars)
            .filter(|&y| {
                signs[y]
                    .lower
                    .as_ref()
                    .is_some_and(|(lo, _)| lo.signum() != exactcheck_core::Sign::Negative)
            })
            .filter_map(|y| self.root(y as Var, &basis, &signs, &mut facts))
            .collect();
        Ok(branch_zero(self.residual, &roots, &basis, &signs, &mut 0, &mut facts).then_some(facts))
    }

    /// `y` as a root: a relation `D y^2 - N` with `D` and `N` free of `y` and `D` without a
    /// zero on the variety of `basis` (module documentation) or of a strict sign on `signs`
    /// ([`signs::sign_on`]; its sign facts are added to `facts`).
    fn root(
        &self,
        y: Var,
        basis: &[Poly<C>],
        signs: &[VarDomain],
        facts: &mut Vec<SignFact<C>>,
    ) -> Option<Root<C>> {
        self.relations.iter().find_map(|r| {
            let (d, n) = root_parts(r, y)?;
            if let Some(a) = d.constant_value() {
                let inv = a.inv().ok()?;
                return Some(Root {
                    var: y,
                    square: n.scale(&inv),
                    denominator: Poly::one(),
                });
            }
            let zero_free = nowhere_zero(&d, basis) || {
                let mut found = Vec::new();
                let strict = signs::sign_on(&d, signs, &mut found).is_some_and(SignOn::strict);
                if strict {
                    add_facts(facts, found);
                }
                strict
            };
            zero_free.then_some(Root {
                var: y,
                square: n,
                denominator: d,
            })
        })
    }
}

/// Whether `d` has no zero on the points of the variety of `basis` considered: no real zero at
/// all ([`super::real_zero_free`]), or no common complex zero with `basis` (a Gröbner basis of
/// `basis` and `d` holds a non-zero constant).
fn nowhere_zero<C: PointField>(d: &Poly<C>, basis: &[Poly<C>]) -> bool {
    if super::real_zero_free(d) == Some(true) {
        return true;
    }
    let mut gens = basis.to_vec();
    gens.push(d.clone());
    groebner(&gens).is_ok_and(|b| b.iter().any(|p| p.is_constant() && !p.is_zero()))
}

/// `(D, N)` when `r = D y^2 - N` with `D` and `N` free of `y`.
pub(super) fn root_parts<C: PointField>(r: &Poly<C>, y: Var) -> Option<(Poly<C>, Poly<C>)> {
    if r.degree_in(y) != 2 {
        return None;
    }
    let mut square = Vec::new();
    let mut rest = Vec::new();
    for (m, c) in r.terms() {
        let e: Vec<(Var, u32)> = m.exponents().into_iter().filter(|&(v, _)| v != y).collect();
        match m.exponent(y) {
            0 => rest.push((e, c.neg_ref())),
            2 => square.push((e, c.clone())),
            _ => return None,
        }
    }
    Some((Poly::from_terms(square), Poly::from_terms(rest)))
}

/// `N / a` for the first relation `a y^2 - N` of `relations` with `a` a constant and `N` free
/// of `y`: `y` is then a square root of `N / a` (either sign).
pub(super) fn square_of<C: PointField>(relations: &[Poly<C>], y: Var) -> Option<Poly<C>> {
    relations.iter().find_map(|r| {
        let (d, n) = root_parts(r, y)?;
        let inv = d.constant_value()?.inv().ok()?;
        Some(n.scale(&inv))
    })
}

/// The most polynomials [`branch_zero`] squares in one decision (each squaring can double the
/// degree).
const MAX_BRANCH_STEPS: usize = 64;

/// Whether `p` vanishes at every point of the variety of `basis` inside `signs`, by reduction
/// and, for the roots, the sign argument of the module documentation; the sign facts used are
/// added to `facts`.
fn branch_zero<C: PointField>(
    p: &Poly<C>,
    roots: &[Root<C>],
    basis: &[Poly<C>],
    signs: &[VarDomain],
    steps: &mut usize,
    facts: &mut Vec<SignFact<C>>,
) -> bool {
    let p = if basis.is_empty() {
        p.clone()
    } else {
        p.reduce(basis)
    };
    if p.is_zero() {
        return true;
    }
    *steps += 1;
    if *steps > MAX_BRANCH_STEPS {
        return false;
    }
    // The root of highest index first: an inner root has a lower index than the roots whose
    // radicands contain it, so `A`, `B` and `E` hold only roots still to be eliminated.
    let Some(k) = (0..roots.len())
        .filter(|&k| p.degree_in(roots[k].var) > 0)
        .max_by_key(|&k| roots[k].var)
    else {
        return false;
    };
    let root = &roots[k];
    let rest: Vec<Root<C>> = roots
        .iter()
        .enumerate()
        .filter(|&(j, _)| j != k)
        .map(|(_, r)| r.clone())
        .collect();
    let Some((a, b)) = split(&p, root.var, &root.square, &root.denominator) else {
        return false;
    };
    if b.is_zero() {
        return branch_zero(&a, &rest, basis, signs, steps, facts);
    }
    let Some(n) = (|| {
        let a2 = a.try_mul(&a).ok()?.try_mul(&root.denominator).ok()?;
        let b2 = b.try_mul(&b).ok()?.try_mul(&root.square).ok()?;
        Some(a2.sub_ref(&b2))
    })() else {
        return false;
    };
    if !branch_zero(&n, &rest, basis, signs, steps, facts) {
        return false;
    }
    let Ok(ab) = a.try_mul(&b) else {
        return false;
    };
    let minus_ab = ab.neg_ref();
    non_negative_with(&minus_ab, signs, facts)
        || (!basis.is_empty() && non_negative_with(&minus_ab.reduce(basis), signs, facts))
}

/// A term: its exponents and its coefficient.
type Term<C> = (Vec<(Var, u32)>, C);

/// `D^h p = A + B y` with `y^2` replaced by `N / D` (`square` / `denominator`, `h` the half
/// degree of `p` in `y`); `None` past a size limit.
pub(super) fn split<C: PointField>(
    p: &Poly<C>,
    y: Var,
    square: &Poly<C>,
    denominator: &Poly<C>,
) -> Option<(Poly<C>, Poly<C>)> {
    let deg = p.degree_in(y) as usize;
    let mut parts: Vec<Vec<Term<C>>> = vec![Vec::new(); deg + 1];
    for (m, c) in p.terms() {
        let k = m.exponent(y) as usize;
        let e: Vec<(Var, u32)> = m.exponents().into_iter().filter(|&(v, _)| v != y).collect();
        parts[k].push((e, c.clone()));
    }
    // The powers N^j D^(h - j) for j = 0..=h.
    let h = deg / 2;
    let mut n_powers = vec![Poly::one()];
    let mut d_powers = vec![Poly::one()];
    for j in 1..=h {
        n_powers.push(n_powers[j - 1].try_mul(square).ok()?);
        d_powers.push(d_powers[j - 1].try_mul(denominator).ok()?);
    }
    let mut a = Poly::zero();
    let mut b = Poly::zero();
    for (k, terms) in parts.into_iter().enumerate() {
        if terms.is_empty() {
            continue;
        }
        let j = k / 2;
        let factor = n_powers[j].try_mul(&d_powers[h - j]).ok()?;
        let part = Poly::from_terms(terms).try_mul(&factor).ok()?;
        if k % 2 == 0 {
            a = a.add_ref(&part);
        } else {
            b = b.add_ref(&part);
        }
    }
    Some((a, b))
}

/// The sufficient test of the module documentation for `p >= 0` on `signs`, else the sign
/// decision of [`signs::sign_on`] (exact for a polynomial in one variable with rational
/// coefficients; a product of factors of known signs).
pub(super) fn non_negative<C: PointField>(p: &Poly<C>, signs: &[VarDomain]) -> bool {
    non_negative_with(p, signs, &mut Vec::new())
}

/// [`non_negative`], adding to `facts` the sign facts of the domains it used.
fn non_negative_with<C: PointField>(
    p: &Poly<C>,
    signs: &[VarDomain],
    facts: &mut Vec<SignFact<C>>,
) -> bool {
    if p.is_zero() || shifted_coefficients_non_negative(p, signs) {
        return true;
    }
    let mut found = Vec::new();
    let shown = signs::sign_on(p, signs, &mut found).is_some_and(SignOn::non_negative);
    if shown {
        add_facts(facts, found);
    }
    shown
}

/// `found` added to `facts`, each fact once.
fn add_facts<C: PointField>(facts: &mut Vec<SignFact<C>>, found: Vec<SignFact<C>>) {
    for f in found {
        if !facts.contains(&f) {
            facts.push(f);
        }
    }
}

/// The coefficient test of the module documentation for `p >= 0` on `signs`.
fn shifted_coefficients_non_negative<C: PointField>(p: &Poly<C>, signs: &[VarDomain]) -> bool {
    let Some(mut q) = p
        .coefficients()
        .iter()
        .all(|c| c.to_radical().is_some())
        .then(|| p.map_coeffs(|c| c.to_radical().expect("checked to be real above")))
    else {
        return false;
    };
    let mut bounded = vec![false; signs.len()];
    for v in q.variables() {
        let Some(d) = signs.get(v as usize) else {
            continue;
        };
        let x = Poly::<Radical>::var(v);
        let shifted = match (&d.lower, &d.upper) {
            (Some((lo, _)), _) => x.add_ref(&Poly::constant(Radical::from(lo))),
            (None, Some((hi, _))) => Poly::constant(Radical::from(hi)).sub_ref(&x),
            (None, None) => continue,
        };
        q = q.substitute(v, &shifted);
        bounded[v as usize] = true;
    }
    q.terms().all(|(m, c)| {
        *c >= Radical::zero()
            && m.exponents()
                .iter()
                .all(|&(v, e)| e % 2 == 0 || bounded.get(v as usize).copied().unwrap_or(false))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;

    fn p(text: &str, vars: &mut Vars) -> Poly<Rational> {
        parse_poly(text, vars).unwrap()
    }

    fn non_negative_domain() -> VarDomain {
        VarDomain {
            lower: Some((Rational::ZERO, false)),
            upper: None,
            integer: false,
        }
    }

    #[test]
    fn a_root_of_a_fraction_needs_its_denominator_non_zero() {
        let mut vars = Vars::from_names(["x", "y", "w", "z"]);
        let rel = p("w^2*y - x", &mut vars);
        let dom = vec![VarDomain::all(); 4];
        let problem = Problem {
            residual: &Poly::zero(),
            relations: std::slice::from_ref(&rel),
            nonzero: &[],
            dom: &dom,
        };
        // y vanishes with x on the relation: w is no root of x/y there.
        let basis = groebner(std::slice::from_ref(&rel)).unwrap();
        let all = vec![VarDomain::all(); 4];
        assert!(problem.root(2, &basis, &all, &mut Vec::new()).is_none());
        // With y != 0 (the Rabinowitsch relation 1 - z y) it is.
        let with = groebner(&[rel.clone(), p("1 - z*y", &mut vars)]).unwrap();
        let root = problem.root(2, &with, &all, &mut Vec::new()).unwrap();
        assert_eq!(
            (root.square, root.denominator),
            (p("x", &mut vars), p("y", &mut vars))
        );
        // A denominator without a real zero needs nothing; a constant one is divided out.
        let rels = [p("w^2*(y^2 + 1) - x", &mut vars), p("2*w^2 - x", &mut vars)];
        let problem = Problem {
            relations: &rels[..1],
            ..problem
        };
        assert!(problem.root(2, &[], &all, &mut Vec::new()).is_some());
        let problem = Problem {
            relations: &rels[1..],
            ..problem
        };
        let root = problem.root(2, &[], &all, &mut Vec::new()).unwrap();
        assert_eq!(root.square, p("x/2", &mut vars));
        assert!(root.denominator.is_one());
    }

    #[test]
    fn the_branch_of_a_root_of_a_fraction_decides() {
        // w = sqrt(1/x), v = sqrt(x): w v = 1 on the non-negative roots, not w v = -1.
        let mut vars = Vars::from_names(["x", "w", "v"]);
        let rels = [p("w^2*x - 1", &mut vars), p("v^2 - x", &mut vars)];
        let mut dom = vec![
            VarDomain::all(),
            non_negative_domain(),
            non_negative_domain(),
        ];
        let proved = |residual: &str, vars: &mut Vars, dom: &[VarDomain]| {
            matches!(
                prove_under_hypotheses(&p(residual, vars), &rels, &[], dom),
                Outcome::Proved(..)
            )
        };
        assert!(proved("w*v - 1", &mut vars, &dom));
        assert!(!proved("w*v + 1", &mut vars, &dom));
        // w x = v for x >= 0: the sign of x w is shown from the domains.
        dom[0] = non_negative_domain();
        assert!(proved("w*x - v", &mut vars, &dom));
        assert!(!proved("w*x + v", &mut vars, &dom));
        // A power of the root: w^3 x^2 = w (w^2 x) x = w x, the denominator multiplied in.
        assert!(proved("w^3*x^2 - v", &mut vars, &dom));
    }
}
