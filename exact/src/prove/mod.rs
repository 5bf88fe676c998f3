//! The proof engine: decide a polynomial identity `residual = 0` exactly, for all values of its
//! variables, or for all values satisfying declared relations and lying in declared domains.
//!
//! * **proved** — the residual expands to the zero polynomial, or its normal form modulo a
//!   Gröbner basis of the relations is zero (then it vanishes wherever the relations hold, in
//!   particular inside any domains), or it vanishes under the hypotheses (the non-zero
//!   polynomials and the domains, including the signs of square roots; see [`decide_where`]),
//!   which are then reported;
//! * **fails** — the normal form is non-zero and an exact real point is found that lies in the
//!   domains, where every relation vanishes and the residual does not; the point (rational, or in
//!   the square-root field [`Radical`]), the residual there and the normal form (what the two
//!   sides really differ by) are reported;
//! * **undecided** — the normal form is non-zero but the search found no such point. A non-zero
//!   normal form only says "not in the ideal of the relations", which is not always "false at
//!   some real point in the domains" (`x^2 + y^2 = 0` has the single real point 0, a domain may
//!   exclude every point where the residual is non-zero), so this is reported, never a verdict.
//!
//! Inconsistent relations (the reduced Gröbner basis contains a non-zero constant, i.e. the
//! relations have no common complex point, e.g. `1 = 2` or `x = 1, x = 2`) and malformed domains
//! (empty, a variable out of range or given twice) are a [`DecideError`]: anything would follow
//! from them, so nothing is decided. So are conditions without a common real point
//! ([`DecideError::Vacuous`]: `sqrt(x)` for `x < 0`), which [`identity::decide_identity`]
//! decides for the conditions in one variable (module `vacuous`); when it cannot, and no point
//! satisfying them is found either, a proof says so ([`IdentityReport::no_point_found`]).
//!
//! # The counter-example search
//! First come [`SMALL_ATTEMPTS`] points of small height, so that the counter-example reported is
//! a simple one (`t = 1/2, w = 1` rather than `t = 11/16, w = 7/4`): every variable of the
//! statement runs through the rationals of its domain by increasing height `max(|n|, d)`
//! (`0, 1, -1, 1/2, 2, -1/2, -2, 1/3, ...`, [`small_height_rationals`]), the points ordered by
//! the largest position any coordinate takes in its list, then by the sum of the positions.
//! Then come [`SEARCH_ATTEMPTS`] attempts at random points. Each attempt builds a point variable
//! by variable, every value exact:
//! 1. every variable gets its small-height value, or in the random attempts a small rational
//!    drawn from its domain (`n/d`, `|n| <= 9`, `d <= 4`, without a domain; else from the box,
//!    see [`VarDomain`]);
//! 2. on even attempts (and always when all relations are unit circles), each unit circle
//!    `c^2 + s^2 = 1` is given the rational point `((1 - tau^2)/(1 + tau^2), 2 tau/(1 + tau^2))`
//!    for a small rational `tau` (in the small-height attempts, the value of `c`); on odd
//!    attempts the circles are treated like other relations;
//! 3. the remaining relations are solved one variable at a time: a relation whose only
//!    unassigned variable is `v`, after substituting the values fixed so far, is a univariate
//!    polynomial; its roots are taken exactly — linear roots, real roots of quadratics
//!    (`(-b ± sqrt(b^2 - 4ac)) / 2a`, in [`Radical`] when the discriminant is rational) and
//!    rational roots of higher degrees with rational coefficients (isolated by
//!    [`crate::univariate`]) — and one root inside `v`'s domain is chosen at random; when no
//!    relation is univariate, the next variable of some relation keeps its drawn value;
//! 4. the point is then *verified* exactly: every relation evaluates to zero, every value lies
//!    in its domain, and the residual (not the normal form) is non-zero. Only a verified point is
//!    reported.
//!
//!
//! Last come at most [`CELL_ATTEMPTS`] *cell points*, for a residual non-zero only on a narrow
//! region (`sqrt((t^2 - 2)^2) = 2 - t^2` on `-1 < t < 3/2` fails only above `sqrt(2)`): one
//! variable at a time, the others fixed at the first small-height points, the variable takes the
//! simplest rational of every gap between the real roots (isolated exactly) of the residual, the
//! radicands and the denominators with the square roots eliminated, inside its domain; each point
//! found moves the next variable in turn. Each is an attempt as above, verified the same way
//! (see the `cells` module).
//!
//! The search is deterministic (fixed seeds) so that verdicts are reproducible; it makes at most
//! [`SMALL_ATTEMPTS`] + [`SEARCH_ATTEMPTS`] + [`CELL_ATTEMPTS`] attempts.
//!
//! # One engine for every front end
//! [`identity::decide_identity`] takes an identity as a spec (sides or residuals, relations,
//! domains, hypotheses, a corrected form, the variable names) and returns a typed report, which
//! the command-line tool words with one formatter. `prove`, claims files and the built-in
//! catalogue all go through it, so that they share one counter-example rule.

mod cells;
mod chart;
mod constants;
mod domain;
mod factored;
mod fraction;
mod heights;
mod hypotheses;
pub mod identity;
pub mod random;
mod roots;
mod signs;
mod sum_ranges;
mod vacuous;

pub use constants::{AlgebraicConstants, ConstantPoint, ConstantValue, CONSTANT_ATTEMPTS};
pub use domain::VarDomain;
pub use factored::factored;
pub use fraction::{decide_fraction, real_zero_free, where_clause, FractionIdentity};
pub use heights::small_height_rationals;
use heights::small_points;
pub use hypotheses::{Hypothesis, MAX_HYPOTHESIS_DROPS};
pub use identity::{
    decide_identity, CoordinateOutcome, CorrectionVerdict, EngineError, IdentityReport,
    IdentitySpec, IdentityVerdict, Part, Statement, UsedHypothesis,
};
pub use roots::{square_roots, SquareRoot};
pub use signs::{SignFact, SignOn};
pub use sum_ranges::SumRanges;
pub use vacuous::{points, Points};

pub use random::{
    random_identity_test, size_bound, RandomDecision, RandomReport, Seed, SizeBound,
    HOLDS_THRESHOLD_LOG2, MAX_RANDOM_TRIALS,
};

use crate::expr::Coefficient;
use crate::poly::{groebner, Poly, Var};
use crate::univariate::UPoly;
use crate::{ComplexRadical, Radical, Rational};
use exactcheck_core::{Field, Ring, Rng};
use std::fmt;

/// Random attempts of the counter-example search.
pub const SEARCH_ATTEMPTS: usize = 200;

/// Attempts at points of small height, before the random ones.
pub const SMALL_ATTEMPTS: usize = 100;

/// The most points of the cell phase of the search (module `cells`).
pub const CELL_ATTEMPTS: usize = 300;

/// The small-height points whose coordinates the cell phase fixes while it moves one variable.
const CELL_BASES: usize = 8;

/// A coefficient field the counter-example search can evaluate at real points with coordinates
/// in [`Radical`]: the values of its polynomials there lie in [`PointField::Value`].
pub trait PointField: Field + Coefficient {
    /// The field of the values at radical points (the coefficients adjoined the radicals).
    type Value: Field + fmt::Display + fmt::Debug + Clone;
    /// A coefficient as a value.
    fn lift(&self) -> Self::Value;
    /// A coordinate as a value.
    fn lift_radical(r: &Radical) -> Self::Value;
    /// The coefficient as a real radical, `None` when it is not real (then relations with it are
    /// not solved, only checked).
    fn to_radical(&self) -> Option<Radical>;
    /// The field's name in a method (`Q`, `Q(sqrt)`).
    fn field_name() -> &'static str;
}

impl PointField for Rational {
    type Value = Radical;
    fn lift(&self) -> Radical {
        Radical::from(self)
    }
    fn lift_radical(r: &Radical) -> Radical {
        r.clone()
    }
    fn to_radical(&self) -> Option<Radical> {
        Some(Radical::from(self))
    }
    fn field_name() -> &'static str {
        "Q"
    }
}

impl PointField for Radical {
    type Value = Radical;
    fn lift(&self) -> Radical {
        self.clone()
    }
    fn lift_radical(r: &Radical) -> Radical {
        r.clone()
    }
    fn to_radical(&self) -> Option<Radical> {
        Some(self.clone())
    }
    fn field_name() -> &'static str {
        "Q(sqrt)"
    }
}

impl PointField for ComplexRadical {
    type Value = ComplexRadical;
    fn lift(&self) -> ComplexRadical {
        self.clone()
    }
    fn lift_radical(r: &Radical) -> ComplexRadical {
        ComplexRadical::from(r.clone())
    }
    fn to_radical(&self) -> Option<Radical> {
        self.is_real().then(|| self.re.clone())
    }
    fn field_name() -> &'static str {
        "Q(sqrt, i)"
    }
}

/// The decision on an identity.
#[derive(Clone, Debug)]
pub enum Decision<C: PointField> {
    /// The residual is zero (modulo the relations).
    Proved {
        /// Terms of the expanded residual before reduction (0 when it expanded to zero outright).
        expanded_terms: usize,
        /// The hypotheses the proof used (empty when the residual is zero modulo the relations
        /// alone); see [`decide_where`].
        hypotheses: Vec<Hypothesis>,
        /// The signs on the domains the proof used (see [`decide_where`]).
        signs: Vec<SignFact<C>>,
    },
    /// A counter-example: the point lies in the domains, the relations hold, the residual does
    /// not vanish (all verified exactly).
    Fails {
        /// The normal form of the residual modulo the relations.
        normal_form: Poly<C>,
        /// The point: a value for every variable (by index).
        point: RadicalPoint,
        /// The residual's value there (non-zero).
        value: C::Value,
    },
    /// Non-zero normal form, but no point in the domains and on the relations' variety was found
    /// where the residual is non-zero.
    Undecided {
        /// The normal form of the residual modulo the relations.
        normal_form: Poly<C>,
        /// What was searched, in words.
        searched: String,
    },
}

/// Why nothing was decided.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DecideError {
    /// The relations have no common (complex) point: their Gröbner basis contains a non-zero
    /// constant.
    Inconsistent,
    /// A domain no real number satisfies (e.g. `1 < v < 0`).
    EmptyDomain(Var),
    /// Two domains for one variable.
    DuplicateDomain(Var),
    /// A domain for a variable index outside `0..nvars`.
    UnknownVariable(Var),
    /// The conditions leave no real point: no value of the variable satisfies the domains,
    /// the relations, the non-zero hypotheses and the sign conditions of the square roots that
    /// are in it alone (module `vacuous`), so a proof would say nothing.
    Vacuous(Var),
    /// The Gröbner basis of the relations, or the reduction, exceeded a named limit.
    Limit(exactcheck_core::limits::LimitError),
}

impl From<exactcheck_core::limits::LimitError> for DecideError {
    fn from(e: exactcheck_core::limits::LimitError) -> DecideError {
        DecideError::Limit(e)
    }
}

impl fmt::Display for DecideError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DecideError::Inconsistent => f.write_str(
                "the relations are inconsistent (their Groebner basis contains a non-zero constant): no point satisfies them, so nothing can be decided",
            ),
            DecideError::EmptyDomain(v) => write!(f, "the domain of variable #{v} is empty"),
            DecideError::DuplicateDomain(v) => {
                write!(f, "variable #{v} has two domains (give both bounds in one)")
            }
            DecideError::UnknownVariable(v) => {
                write!(f, "a domain names variable #{v}, which is not in use")
            }
            DecideError::Vacuous(v) => write!(
                f,
                "no value of variable #{v} satisfies the domains, the relations, the hypotheses and the conditions under which the square roots and the fractions are defined: the claim is vacuous"
            ),
            DecideError::Limit(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for DecideError {}

/// Splits relations into unit-circle pairs `c^2 + s^2 - 1` (recognised up to sign) and others.
pub fn unit_circle_pairs<C: Field>(relations: &[Poly<C>]) -> (Vec<(Var, Var)>, Vec<Poly<C>>) {
    let mut pairs = Vec::new();
    let mut others = Vec::new();
    for r in relations {
        match circle_pair(r) {
            Some(p)
                if !pairs
                    .iter()
                    .any(|&(c, s): &(Var, Var)| [c, s].contains(&p.0) || [c, s].contains(&p.1)) =>
            {
                pairs.push(p)
            }
            _ => others.push(r.clone()),
        }
    }
    (pairs, others)
}

fn circle_pair<C: Field>(r: &Poly<C>) -> Option<(Var, Var)> {
    if r.len() != 3 {
        return None;
    }
    let mut squares = Vec::new();
    let mut constant = None;
    let mut square_coeff = None;
    for (m, c) in r.terms() {
        let e = m.exponents();
        match e.as_slice() {
            [] => constant = Some(c.clone()),
            [(v, 2)] => {
                if square_coeff.get_or_insert_with(|| c.clone()) != c {
                    return None;
                }
                squares.push(*v);
            }
            _ => return None,
        }
    }
    let (k, a) = (constant?, square_coeff?);
    // a c^2 + a s^2 - a = 0.
    if squares.len() == 2 && k == a.neg_ref() {
        Some((squares[0], squares[1]))
    } else {
        None
    }
}

/// A small rational `n/d`, `|n| <= 9`, `1 <= d <= 4`, for the counter-example search.
pub(crate) fn small_rational(rng: &mut Rng) -> Rational {
    let n = (rng.next_u64() % 19) as i64 - 9;
    let d = (rng.next_u64() % 4) as i64 + 1;
    Rational::new(n, d).expect("the denominator is at least 1")
}

/// Decides `residual = 0` modulo `relations` for all values (see the module documentation):
/// [`decide_in`] without domains. `nvars` is the number of variables in use (`0..nvars`).
///
/// # Errors
/// [`DecideError::Inconsistent`] for inconsistent relations.
pub fn decide<C: PointField>(
    residual: &Poly<C>,
    relations: &[Poly<C>],
    nvars: usize,
) -> Result<Decision<C>, DecideError> {
    decide_in(residual, relations, &[], nvars)
}

/// Decides `residual = 0` modulo `relations` for the values in `domains` (variables without a
/// domain range over all reals); see the module documentation.
///
/// # Errors
/// [`DecideError`] for inconsistent relations, an empty domain, two domains for one variable or
/// a domain for a variable outside `0..nvars`.
pub fn decide_in<C: PointField>(
    residual: &Poly<C>,
    relations: &[Poly<C>],
    domains: &[(Var, VarDomain)],
    nvars: usize,
) -> Result<Decision<C>, DecideError> {
    decide_where(residual, relations, &[], domains, nvars)
}

/// [`decide_in`] where the polynomials `nonzero` do not vanish (hypotheses `w != 0`, the
/// denominators of an identity between fractions, [`decide_fraction`]): a counter-example must
/// make every one of them non-zero. When the residual does not reduce to zero modulo the
/// relations alone, the proof uses the hypotheses: each non-zero polynomial (by a Rabinowitsch
/// variable), the non-zero values and the signs the domains imply, and the sign conditions of
/// square roots (a variable `y >= 0` with a relation `a y^2 - E`); [`Decision::Proved`] then lists
/// a minimal set of hypotheses that still proves it (see the `hypotheses` module).
///
/// # Errors
/// As [`decide_in`].
pub fn decide_where<C: PointField>(
    residual: &Poly<C>,
    relations: &[Poly<C>],
    nonzero: &[Poly<C>],
    domains: &[(Var, VarDomain)],
    nvars: usize,
) -> Result<Decision<C>, DecideError> {
    let dom = domain_table(domains, nvars)?;
    let (pairs, others) = unit_circle_pairs(relations);
    let basis = consistent_basis(relations, &others)?;
    let expanded_terms = residual.len();
    if residual.is_zero() {
        return Ok(Decision::Proved {
            expanded_terms: 0,
            hypotheses: Vec::new(),
            signs: Vec::new(),
        });
    }
    let mut nf = residual.try_reduce_unit_circle(&pairs)?;
    if !basis.is_empty() && !nf.is_zero() {
        nf = nf.reduce(&basis);
    }
    if nf.is_zero() {
        return Ok(Decision::Proved {
            expanded_terms,
            hypotheses: Vec::new(),
            signs: Vec::new(),
        });
    }
    let tried = match hypotheses::prove_under_hypotheses(residual, relations, nonzero, &dom) {
        hypotheses::Outcome::Proved(used, signs) => {
            return Ok(Decision::Proved {
                expanded_terms,
                hypotheses: used,
                signs,
            })
        }
        hypotheses::Outcome::NotProved(tried) => tried,
    };
    Ok(match search(residual, relations, nonzero, &pairs, &others, &dom, nvars) {
        Ok((point, value)) => Decision::Fails {
            normal_form: nf.clone(),
            point,
            value,
        },
        Err(cell_points) => Decision::Undecided {
            searched: format!(
                "{} exact candidate points (small rationals by increasing height, then random ones{}, inside the domains if any{}{}) were checked, none satisfies the relations{}{} with a non-zero residual{tried}",
                SMALL_ATTEMPTS + SEARCH_ATTEMPTS + cell_points,
                if cell_points == 0 {
                    String::new()
                } else {
                    format!(", then {cell_points} between the real roots of the residual, the radicands and the denominators along each variable")
                },
                if pairs.is_empty() { "" } else { ", rational points of the unit circles" },
                if others.is_empty() && pairs.is_empty() {
                    ""
                } else {
                    ", relations solved one variable at a time: rational roots and real roots of quadratics"
                },
                if dom.iter().any(|d| *d != VarDomain::all()) { " in the domains" } else { "" },
                if nonzero.is_empty() { "" } else { " off the zeros of the denominators" },
            ),
            normal_form: nf,
        },
    })
}

/// The domain of every variable `0..nvars` (the whole line where `domains` gives none).
///
/// # Errors
/// [`DecideError`] for a domain of a variable outside `0..nvars`, two domains for one
/// variable, an empty domain.
pub(crate) fn domain_table(
    domains: &[(Var, VarDomain)],
    nvars: usize,
) -> Result<Vec<VarDomain>, DecideError> {
    let mut dom = vec![VarDomain::all(); nvars];
    let mut seen = vec![false; nvars];
    for (v, d) in domains {
        let i = *v as usize;
        if i >= nvars {
            return Err(DecideError::UnknownVariable(*v));
        }
        if seen[i] {
            return Err(DecideError::DuplicateDomain(*v));
        }
        if d.is_empty() {
            return Err(DecideError::EmptyDomain(*v));
        }
        seen[i] = true;
        dom[i] = d.clone();
    }
    Ok(dom)
}

/// The Gröbner basis of `relations` (empty when `others`, the relations besides the unit
/// circles, is: distinct unit circles alone always have common points).
///
/// # Errors
/// [`DecideError::Inconsistent`] when the basis holds a non-zero constant, a limit.
pub(crate) fn consistent_basis<C: PointField>(
    relations: &[Poly<C>],
    others: &[Poly<C>],
) -> Result<Vec<Poly<C>>, DecideError> {
    if others.is_empty() {
        return Ok(Vec::new());
    }
    let basis = groebner(relations)?;
    if basis.iter().any(|b| b.is_constant() && !b.is_zero()) {
        return Err(DecideError::Inconsistent);
    }
    Ok(basis)
}

/// Whether the counter-example search finds a real point where the `relations` hold, the
/// `nonzero` polynomials do not vanish and every variable lies in `dom`: the search for a
/// counter-example to `1 = 0`, whose residual is non-zero everywhere.
pub(crate) fn witness<C: PointField>(
    relations: &[Poly<C>],
    nonzero: &[Poly<C>],
    dom: &[VarDomain],
) -> bool {
    let (pairs, others) = unit_circle_pairs(relations);
    search(
        &Poly::one(),
        relations,
        nonzero,
        &pairs,
        &others,
        dom,
        dom.len(),
    )
    .is_ok()
}

/// A point: a value for every variable (by index).
pub type RadicalPoint = Vec<(Var, Radical)>;

/// The counter-example to report from a [`Decision::Fails`] point: the values of the variables
/// that occur in `statement` (the identity's sides and its relations), in index order.
///
/// The search gives every variable in use a value (in its domain), including those that cancel
/// from the residual: `(a + b)^3 = a^3 + 3 a^2 b + 3 a b^2` fails at `a = .., b = 3/2`, and a
/// report of `b = 3/2` alone is not a point of the statement. Restricting to `statement` leaves
/// out only variables a caller's table holds for other statements.
pub fn counter_example<C: Field>(point: &RadicalPoint, statement: &[&Poly<C>]) -> RadicalPoint {
    let mut used = std::collections::HashSet::new();
    for p in statement {
        used.extend(p.variables());
    }
    point
        .iter()
        .filter(|(v, _)| used.contains(v))
        .cloned()
        .collect()
}

/// The counter-example search of the module documentation: a verified point and the residual's
/// value there, or the number of cell points checked in vain.
fn search<C: PointField>(
    residual: &Poly<C>,
    relations: &[Poly<C>],
    nonzero: &[Poly<C>],
    pairs: &[(Var, Var)],
    others: &[Poly<C>],
    dom: &[VarDomain],
    nvars: usize,
) -> Result<(RadicalPoint, C::Value), usize> {
    // Relations as real radical polynomials, for solving (those with non-real coefficients are
    // only checked).
    let real = |r: &Poly<C>| -> Option<Poly<Radical>> {
        r.coefficients()
            .iter()
            .all(|c| c.to_radical().is_some())
            .then(|| r.map_coeffs(|c| c.to_radical().expect("checked to be real above")))
    };
    let all_real: Vec<Poly<Radical>> = relations.iter().filter_map(real).collect();
    let others_real: Vec<Poly<Radical>> = others.iter().filter_map(real).collect();
    // One attempt from the drawn values `base`; `taus`, when given, are the parameters of the
    // unit circles (one per pair), else the circles are solved like the other relations.
    let attempt = |base: Vec<Rational>,
                   taus: Option<Vec<Rational>>,
                   rng: &mut Rng|
     -> Option<(RadicalPoint, C::Value)> {
        let mut point: Vec<Option<Radical>> = vec![None; nvars];
        let to_solve = if let Some(taus) = taus {
            for (&(c, s), tau) in pairs.iter().zip(taus) {
                let t2 = tau.square();
                let den = (Rational::ONE + &t2)
                    .recip()
                    .expect("1 + tau^2 >= 1 is not zero");
                point[c as usize] = Some(Radical::from((Rational::ONE - &t2) * &den));
                point[s as usize] = Some(Radical::from(tau.scale_i64(2) * &den));
            }
            &others_real
        } else {
            &all_real
        };
        if !solve_relations(to_solve, &base, dom, &mut point, rng) {
            return None;
        }
        let values: Vec<Radical> = point
            .into_iter()
            .zip(base)
            .map(|(p, b)| p.unwrap_or_else(|| Radical::from(b)))
            .collect();
        if !values.iter().zip(dom).all(|(x, d)| d.contains(x)) {
            return None;
        }
        let lifted: Vec<C::Value> = values.iter().map(C::lift_radical).collect();
        if !relations.iter().all(|r| r.eval(&lifted, C::lift).is_zero()) {
            return None;
        }
        // Never a pole: every denominator is non-zero at the point.
        if nonzero.iter().any(|d| d.eval(&lifted, C::lift).is_zero()) {
            return None;
        }
        let value = residual.eval(&lifted, C::lift);
        (!value.is_zero()).then(|| {
            let point = values
                .into_iter()
                .enumerate()
                .map(|(i, q)| (i as Var, q))
                .collect();
            (point, value)
        })
    };
    // Small heights first (their own generator for the choice among roots, so that the random
    // attempts after them are those of a search without them).
    let mut active = vec![false; nvars];
    for p in std::iter::once(residual).chain(relations).chain(nonzero) {
        for v in p.variables() {
            active[v as usize] = true;
        }
    }
    let mut small_rng = Rng::new(0x5EED_0001);
    for (k, base) in small_points(dom, &active, SMALL_ATTEMPTS)
        .into_iter()
        .enumerate()
    {
        let taus = (k % 2 == 0 || others.is_empty()).then(|| {
            pairs
                .iter()
                .map(|&(c, _)| base[c as usize].clone())
                .collect()
        });
        if let Some(found) = attempt(base, taus, &mut small_rng) {
            return Ok(found);
        }
    }
    let mut rng = Rng::new(0x5EED);
    for k in 0..SEARCH_ATTEMPTS {
        let base: Vec<Rational> = (0..nvars).map(|v| dom[v].sample(&mut rng)).collect();
        let taus = (k % 2 == 0 || others.is_empty())
            .then(|| pairs.iter().map(|_| small_rational(&mut rng)).collect());
        if let Some(found) = attempt(base, taus, &mut rng) {
            return Ok(found);
        }
    }
    // The cells of the sign charts along each variable (module `cells`), the others at the
    // first small-height points, then at the cell values found for one variable.
    let mut cell_rng = Rng::new(0x5EED_0003);
    let in_pair = |v: Var| pairs.iter().any(|&(c, s)| c == v || s == v);
    let cell = cells::Search {
        residual,
        relations,
        nonzero,
        dom,
        active: &active,
        circle: &in_pair,
    };
    cell.run(small_points(dom, &active, CELL_BASES), &mut |point| {
        let taus = others.is_empty().then(|| {
            pairs
                .iter()
                .map(|&(c, _)| point[c as usize].clone())
                .collect()
        });
        attempt(point, taus, &mut cell_rng)
    })
}

/// Step 3 of the search: fixes variables of `rels` one at a time (solving univariate relations,
/// else keeping the drawn `base` value). `false` when a univariate relation has no usable root
/// in its variable's domain.
fn solve_relations(
    rels: &[Poly<Radical>],
    base: &[Rational],
    dom: &[VarDomain],
    point: &mut [Option<Radical>],
    rng: &mut Rng,
) -> bool {
    if rels.is_empty() {
        return true;
    }
    loop {
        let mut progress = false;
        let mut open_var = None;
        for r in rels {
            let mut q = r.clone();
            for v in r.variables() {
                if let Some(x) = &point[v as usize] {
                    q = q.substitute(v, &Poly::constant(x.clone()));
                }
            }
            let vars = q.variables();
            match vars.as_slice() {
                [] => {}
                [v] => {
                    let roots: Vec<Radical> = real_roots(&q, *v)
                        .into_iter()
                        .filter(|x| dom[*v as usize].contains(x))
                        .collect();
                    if roots.is_empty() {
                        return false;
                    }
                    let pick = rng.below(roots.len() as u64) as usize;
                    point[*v as usize] = Some(roots[pick].clone());
                    progress = true;
                }
                [_, _, ..] => {
                    // Fix the variable of highest degree first, so that the one solved for
                    // last has a low degree (`p^2222 - c^4 + s^2 = 1`: fix p, then c, solve a
                    // quadratic in s).
                    let highest = *vars
                        .iter()
                        .max_by_key(|&&v| q.degree_in(v))
                        .expect("two or more variables");
                    open_var.get_or_insert(highest);
                }
            }
        }
        if !progress {
            match open_var {
                Some(v) => point[v as usize] = Some(Radical::from(&base[v as usize])),
                None => return true,
            }
        }
    }
}

/// The highest degree of a one-variable relation whose rational roots the counter-example
/// search isolates.
const MAX_SEARCH_DEGREE: usize = 64;

/// Real roots of a polynomial in the one variable `v` found exactly: linear roots, real roots of
/// quadratics with a rational discriminant, rational roots when the coefficients are rational
/// (up to degree [`MAX_SEARCH_DEGREE`]).
fn real_roots(q: &Poly<Radical>, v: Var) -> Vec<Radical> {
    let deg = q.degree_in(v) as usize;
    let mut coeffs = vec![Radical::zero(); deg + 1];
    for (m, c) in q.terms() {
        coeffs[m.exponent(v) as usize] = c.clone();
    }
    match deg {
        0 => Vec::new(),
        1 => coeffs[1]
            .inv()
            .map(|i| vec![-(&coeffs[0] * &i)])
            .unwrap_or_default(),
        2 => {
            let (a, b, c) = (&coeffs[2], &coeffs[1], &coeffs[0]);
            let disc = b * b - &(a * c).scale(&Rational::from_integer(4));
            let Some(sq) = disc.to_rational().and_then(|d| Radical::sqrt_rational(&d)) else {
                return Vec::new();
            };
            let Ok(den) = a.scale(&Rational::from_integer(2)).inv() else {
                return Vec::new();
            };
            let mut roots = vec![(-b - &sq) * &den];
            if !sq.is_zero() {
                roots.push((-b + &sq) * &den);
            }
            roots
        }
        // Isolating every real root of a high-degree polynomial costs far more than this search
        // gains from it (the search fixes high-degree variables first, so this is rare).
        d if d > MAX_SEARCH_DEGREE => Vec::new(),
        _ => {
            let Some(rat) = coeffs
                .iter()
                .map(Radical::to_rational)
                .collect::<Option<Vec<Rational>>>()
            else {
                return Vec::new();
            };
            UPoly::from_coeffs(rat)
                .roots()
                .into_iter()
                .filter_map(|r| r.interval.exact_value().cloned())
                .map(Radical::from)
                .collect()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;

    fn p(text: &str, vars: &mut Vars) -> Poly<Rational> {
        parse_poly(text, vars).unwrap()
    }

    #[test]
    fn quadratic_roots_are_exact() {
        let mut vars = Vars::from_names(["x"]);
        let q = p("x^2 - 2", &mut vars).map_coeffs(|c| Radical::from(c));
        let roots = real_roots(&q, 0);
        assert_eq!(roots.len(), 2);
        for r in roots {
            assert!((&r * &r - Radical::from(2)).is_zero());
        }
        let cubic = p("x^3 - 1/8", &mut vars).map_coeffs(|c| Radical::from(c));
        assert_eq!(
            real_roots(&cubic, 0),
            vec![Radical::from(Rational::new(1, 2).unwrap())]
        );
    }

    fn failing_point(
        text: &str,
        names: &[&str],
        domains: &[(Var, VarDomain)],
    ) -> Vec<(String, String)> {
        let mut vars = Vars::from_names(names);
        let residual = p(text, &mut vars);
        match decide_in(&residual, &[], domains, vars.len()).unwrap() {
            Decision::Fails { point, .. } => point
                .iter()
                .map(|(v, x)| (vars.name(*v).unwrap().to_string(), x.to_string()))
                .collect(),
            other => panic!("{text}: {other:?}"),
        }
    }

    #[test]
    fn the_counter_example_has_small_height() {
        let names = ["t", "w0", "w1", "w2"];
        let residual = "-3 w0 w1^2 w2 t^2 (1-t)^2";
        let at = |pairs: &[(&str, &str)]| -> Vec<(String, String)> {
            pairs
                .iter()
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect()
        };
        // Without domains: t = 0 and t = 1 are zeros, so t = -1 with every weight 1.
        assert_eq!(
            failing_point(residual, &names, &[]),
            at(&[("t", "-1"), ("w0", "1"), ("w1", "1"), ("w2", "1")])
        );
        // 0 < t < 1 and positive weights: t = 1/2, w = 1.
        let open = |lo: i64, hi: Option<i64>| VarDomain {
            lower: Some((Rational::from(lo), true)),
            upper: hi.map(|h| (Rational::from(h), true)),
            integer: false,
        };
        let domains = [
            (0, open(0, Some(1))),
            (1, open(0, None)),
            (2, open(0, None)),
            (3, open(0, None)),
        ];
        assert_eq!(
            failing_point(residual, &names, &domains),
            at(&[("t", "1/2"), ("w0", "1"), ("w1", "1"), ("w2", "1")])
        );
        // A domain without small rationals still gets points (its own samples).
        let far = [(
            0,
            VarDomain {
                lower: Some((Rational::new(1000001, 1000).unwrap(), true)),
                upper: Some((Rational::new(1000002, 1000).unwrap(), true)),
                integer: false,
            },
        )];
        let pt = failing_point("t - 1000", &["t"], &far);
        assert_eq!(pt.len(), 1);
    }

    #[test]
    fn domains() {
        let d = VarDomain {
            lower: Some((Rational::ZERO, true)),
            upper: Some((Rational::ONE, false)),
            integer: false,
        };
        assert!(!d.contains(&Radical::zero()) && d.contains(&Radical::one()));
        let mut rng = Rng::new(3);
        for _ in 0..100 {
            assert!(d.contains(&Radical::from(d.sample(&mut rng))));
        }
        let empty = VarDomain {
            lower: Some((Rational::ONE, false)),
            upper: Some((Rational::ONE, true)),
            integer: false,
        };
        assert!(empty.is_empty());
    }
}
