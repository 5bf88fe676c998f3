//! Whether the conditions of an identity leave a real point at all: the domains, the relations,
//! the polynomials declared non-zero (hypotheses and denominators) and the sign conditions of
//! the square roots. An identity "proved" on an empty set says nothing, so an empty set is
//! reported as [`super::DecideError::Vacuous`].
//!
//! * **Square roots eliminated.** A variable `y` whose domain is `y >= 0`, which occurs in one
//!   condition only, a relation `D y^2 - N` (`D`, `N` free of `y`), has a value exactly where
//!   `N / D >= 0` (with `D != 0`), so `y` and its relation give way to the condition
//!   `N D >= 0`. For a non-constant `D` that condition also holds where `D = N = 0`: it is
//!   weaker than the real one, so it shows emptiness but not a point.
//! * **One variable at a time.** The conditions in the single variable `x`, with its domain,
//!   are decided exactly on the sign chart of the product of their polynomials on the domain
//!   ([`super::chart`]): every root in the domain and one rational point of every gap is
//!   tested (the signs of the polynomials are constant on a gap; at an irrational root they
//!   are decided by [`sign_at_real_root`]). When no root or sample satisfies them, no `x`
//!   does, and so no point satisfies all the conditions. Relations that have no
//!   real value of `x` by themselves are not counted as empty: they are read over the complex
//!   numbers, as their consistency is (`s^2 = -1` for the imaginary unit).
//! * **A point.** When every condition is in one variable and each variable has a value, the
//!   set is not empty; otherwise nothing is claimed here ([`Points::Unknown`]) and the
//!   counter-example search may still find a point ([`super::witness`]).

use super::chart::{chart, rational, univariate, Cell};
use super::hypotheses::root_parts;
use super::{PointField, VarDomain};
use crate::poly::{Poly, Var};
use crate::univariate::{sign_at_real_root, UPoly};
use crate::Rational;
use exactcheck_core::{Ring, Sign};

/// The largest degree of the product of a variable's conditions that [`points`] decides
/// exactly (beyond it nothing is claimed).
const MAX_CONDITION_DEGREE: usize = 256;

/// What [`points`] found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Points {
    /// A point satisfies every condition.
    Found,
    /// No value of the variable satisfies its conditions: no point satisfies them all.
    Empty(Var),
    /// Neither shown.
    Unknown,
}

/// What a condition asks of its polynomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Zero,
    NonZero,
    NonNegative,
}

impl Kind {
    fn holds(self, s: Sign) -> bool {
        match self {
            Kind::Zero => s == Sign::Zero,
            Kind::NonZero => s != Sign::Zero,
            Kind::NonNegative => s != Sign::Negative,
        }
    }
}

/// A condition: the polynomial, what it must satisfy, and whether it is the real condition
/// (`false`: a weaker one, good for emptiness only).
struct Condition<C: Ring> {
    poly: Poly<C>,
    kind: Kind,
    exact: bool,
}

/// Whether the `relations` (`= 0`), the `nonzero` polynomials and the domains `dom` (one per
/// variable) have a common real point (module documentation).
pub fn points<C: PointField>(
    relations: &[Poly<C>],
    nonzero: &[Poly<C>],
    dom: &[VarDomain],
) -> Points {
    let mut conds: Vec<Condition<C>> = relations
        .iter()
        .map(|p| (p, Kind::Zero))
        .chain(nonzero.iter().map(|p| (p, Kind::NonZero)))
        .map(|(p, kind)| Condition {
            poly: p.clone(),
            kind,
            exact: true,
        })
        .collect();
    let root_domain = VarDomain {
        lower: Some((Rational::ZERO, false)),
        upper: None,
        integer: false,
    };
    let mut eliminated = vec![false; dom.len()];
    for (y, d) in dom.iter().enumerate() {
        if *d != root_domain {
            continue;
        }
        let y = y as Var;
        let with: Vec<usize> = (0..conds.len())
            .filter(|&i| conds[i].poly.degree_in(y) > 0)
            .collect();
        let [i] = with.as_slice() else {
            continue;
        };
        if conds[*i].kind != Kind::Zero {
            continue;
        }
        let Some((den, num)) = root_parts(&conds[*i].poly, y) else {
            continue;
        };
        conds[*i] = Condition {
            exact: den.is_constant(),
            poly: num.mul_ref(&den),
            kind: Kind::NonNegative,
        };
        eliminated[y as usize] = true;
    }
    let mut found = true;
    for (x, d) in dom.iter().enumerate() {
        if eliminated[x] {
            continue;
        }
        let x = x as Var;
        let own: Vec<&Condition<C>> = conds.iter().filter(|c| c.poly.variables() == [x]).collect();
        if own.is_empty() {
            continue;
        }
        match one_variable(x, &own, d) {
            // Relations without a real point in `x`, alone, are read over the complex numbers
            // (`s^2 = -1` for the imaginary unit), as the consistency of relations is.
            Some(false) if complex_only(x, &own) => found = false,
            Some(false) => return Points::Empty(x),
            Some(true) => found &= own.iter().all(|c| c.exact),
            None => found = false,
        }
    }
    // Conditions in several variables are not decided here, nor a false constant one.
    let decided = |c: &Condition<C>| match c.poly.variables().len() {
        0 => rational(&c.poly).is_some_and(|q| c.kind.holds(q.coefficient(&[]).signum())),
        1 => true,
        _ => false,
    };
    if found && conds.iter().all(decided) {
        Points::Found
    } else {
        Points::Unknown
    }
}

/// Whether the relations among `conds` (the conditions `= 0`) have no real value of `x` on
/// the whole line.
fn complex_only<C: PointField>(x: Var, conds: &[&Condition<C>]) -> bool {
    let relations: Vec<&Condition<C>> = conds
        .iter()
        .copied()
        .filter(|c| c.kind == Kind::Zero)
        .collect();
    !relations.is_empty() && one_variable(x, &relations, &VarDomain::all()) == Some(false)
}

/// Whether some `x` in `d` satisfies `conds` (each a polynomial in `x` alone); `None` when
/// not decided (coefficients not rational, an integer domain, a degree past
/// [`MAX_CONDITION_DEGREE`]).
fn one_variable<C: PointField>(x: Var, conds: &[&Condition<C>], d: &VarDomain) -> Option<bool> {
    if d.integer {
        return None;
    }
    let mut tests: Vec<(UPoly, Kind)> = Vec::new();
    for c in conds {
        tests.push((univariate(&c.poly, x)?, c.kind));
    }
    // The product of the conditions' polynomials: on each gap of its chart on the domain every
    // condition keeps one truth value.
    let mut product = Poly::<Rational>::one();
    let mut degree = 0;
    for p in conds.iter().filter_map(|c| rational(&c.poly)) {
        if p.is_constant() {
            continue;
        }
        degree += p.degree_in(x) as usize;
        if degree > MAX_CONDITION_DEGREE {
            return None;
        }
        product = product.mul_ref(&p);
    }
    let prod = UPoly::from_poly(&product, x).ok()?;
    let holds = |cell: &Cell| match cell {
        Cell::Gap { sample, .. } => tests.iter().all(|(q, k)| k.holds(q.sign_at(sample))),
        Cell::Root(r) => tests
            .iter()
            .all(|(q, k)| k.holds(sign_at_real_root(q, &prod, r))),
    };
    Some(chart(&prod, d).iter().any(holds))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;

    fn decide(rels: &[&str], nonzero: &[&str], dom: &[VarDomain], names: &[&str]) -> Points {
        let mut vars = Vars::from_names(names);
        let mut p = |t: &str| parse_poly::<Rational>(t, &mut vars).unwrap();
        let rels: Vec<Poly<Rational>> = rels.iter().map(|t| p(t)).collect();
        let nonzero: Vec<Poly<Rational>> = nonzero.iter().map(|t| p(t)).collect();
        points(&rels, &nonzero, dom)
    }

    fn bound(lo: Option<(i64, bool)>, hi: Option<(i64, bool)>) -> VarDomain {
        VarDomain {
            lower: lo.map(|(c, s)| (Rational::from(c), s)),
            upper: hi.map(|(c, s)| (Rational::from(c), s)),
            integer: false,
        }
    }

    #[test]
    fn a_root_of_a_negative_radicand_leaves_no_point() {
        let root = bound(Some((0, false)), None);
        // sqrt(x) with x < 0: empty; with x <= 0 the point 0; with x > 0 a point.
        let names = ["x", "y"];
        let case = |x: VarDomain| decide(&["y^2 - x"], &[], &[x, root.clone()], &names);
        assert_eq!(case(bound(None, Some((0, true)))), Points::Empty(0));
        assert_eq!(case(bound(None, Some((0, false)))), Points::Found);
        assert_eq!(case(bound(Some((0, true)), None)), Points::Found);
        assert_eq!(case(VarDomain::all()), Points::Found);
        // sqrt(x - 1) sqrt(1 - x) for x > 2: x = 1 is the only point of both radicands.
        let names = ["x", "y", "z"];
        let two = |x: VarDomain| {
            decide(
                &["y^2 - (x - 1)", "z^2 - (1 - x)"],
                &[],
                &[x, root.clone(), root.clone()],
                &names,
            )
        };
        assert_eq!(two(bound(Some((2, true)), None)), Points::Empty(0));
        assert_eq!(two(VarDomain::all()), Points::Found);
    }

    #[test]
    fn irrational_points_are_decided_exactly() {
        // 2 - x^2 >= 0 meets x > 1 in (1, sqrt 2]; -(x^2 - 2)^2 >= 0 is only +-sqrt 2.
        let root = bound(Some((0, false)), None);
        let names = ["x", "y"];
        let case = |radicand: &str, x: VarDomain| {
            decide(
                &[&format!("y^2 - ({radicand})")],
                &[],
                &[x, root.clone()],
                &names,
            )
        };
        assert_eq!(case("2 - x^2", bound(Some((1, true)), None)), Points::Found);
        assert_eq!(
            case("2 - x^2", bound(Some((2, true)), None)),
            Points::Empty(0)
        );
        assert_eq!(
            case("-(x^2 - 2)^2", bound(Some((1, true)), None)),
            Points::Found
        );
        assert_eq!(
            case("-(x^2 - 2)^2", bound(Some((1, true)), Some((1, false)))),
            Points::Empty(0)
        );
        assert_eq!(
            case("-(x^2 - 2)^2", bound(Some((2, false)), None)),
            Points::Empty(0)
        );
        // A relation and a hypothesis: x^2 = 2 with x < 0 is -sqrt 2; x^2 - 2 != 0 excludes both.
        let free = |dom: VarDomain, nonzero: &[&str]| decide(&["x^2 - 2"], nonzero, &[dom], &["x"]);
        assert_eq!(free(bound(None, Some((0, true))), &[]), Points::Found);
        assert_eq!(free(bound(Some((2, true)), None), &[]), Points::Empty(0));
        assert_eq!(free(VarDomain::all(), &["x^2 - 2"]), Points::Empty(0));
        // A relation without a real point is read over the complex numbers.
        let unit = decide(&["s^2 + 1"], &[], &[bound(Some((0, true)), None)], &["s"]);
        assert_eq!(unit, Points::Unknown);
    }

    #[test]
    fn several_variables_are_not_decided_unless_one_alone_is_empty() {
        let all = VarDomain::all();
        let names = ["x", "y"];
        assert_eq!(
            decide(&["x^2 + y^2 - 1"], &[], &[all.clone(), all.clone()], &names),
            Points::Unknown
        );
        assert_eq!(
            decide(
                &["x^2 + y^2 - 1"],
                &[],
                &[bound(Some((2, true)), None), all.clone()],
                &names
            ),
            Points::Unknown
        );
        // x^2 = 2 has no point above 2, whatever y does.
        assert_eq!(
            decide(
                &["x^2 - 2", "x*y - 1"],
                &[],
                &[bound(Some((2, true)), None), all],
                &names
            ),
            Points::Empty(0)
        );
    }
}
