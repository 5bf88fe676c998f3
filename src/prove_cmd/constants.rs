//! `exactcheck prove` with real algebraic constants outside the square-root field next to
//! variables (`x + cos(pi/5)`, `sin(x + pi/7)`, `x*sqrt(2 + sqrt(2))`): the constants are
//! abstracted from the sides, relations and hypotheses, replaced by polynomials in one primitive
//! element `c` of their field, and the statement is decided over Q with `m(c) = 0`
//! (`exactcheck_exact::prove::AlgebraicConstants`); a non-zero reduction gets an exact
//! counter-example at `c = theta` from the search over `Q(theta)`.

use super::{prove_over, ProveArgs, Sides};
use crate::Error;
use exactcheck_exact::expr::{abstract_constants, needs_algebraic, Expr};
use exactcheck_exact::poly::{Poly, Var, Vars};
use exactcheck_exact::prove::{
    AlgebraicConstants, ConstantPoint, CoordinateOutcome, IdentityReport, IdentitySpec,
    IdentityVerdict, PointField, Statement, VarDomain,
};
use exactcheck_exact::ratfun::RatFun;
use exactcheck_exact::{Radical, Rational};
use std::process::ExitCode;

/// Whether a side, relation or hypothesis has a constant the square-root field cannot hold.
pub(crate) fn needs_constants(
    sides: &Sides,
    relations: &[(Expr, Expr)],
    nonzero: &[(Expr, Expr, String)],
) -> bool {
    any_needs_constants(
        sides
            .lhs
            .iter()
            .chain(sides.rhs.into_iter().flatten())
            .chain(relations.iter().flat_map(|(a, b)| [a, b]))
            .chain(nonzero.iter().flat_map(|(a, b, _)| [a, b])),
    )
}

/// Whether one of `exprs` has a constant the square-root field cannot hold (`cos(pi/5)`,
/// `sqrt(2 + sqrt(2))`).
pub(crate) fn any_needs_constants<'a>(exprs: impl IntoIterator<Item = &'a Expr>) -> bool {
    exprs.into_iter().any(needs_algebraic::<Radical>)
}

/// Why a statement's constants were not put in one field.
pub(crate) enum ConstantsError {
    /// The expression at this index has a constant the evaluator refuses: the reason.
    Expr(usize, String),
    /// The field of all the constants (past the `algebraic-degree` or `factor-combinations`
    /// limit): the one-line reason, naming the constants.
    Field(String),
}

/// The expressions of one statement (sides, relations, hypotheses, a corrected form: every
/// expression decided together) with their real algebraic constants in one field: the field's
/// primitive element as the variable `c` and each expression with every constant replaced by
/// its polynomial in `c`, in the order given; `None` when no constant is irrational. Both front
/// ends of the identity engine, `prove` and the claims files, decide such a statement by this
/// one function followed by [`settle`].
pub(crate) fn abstract_statement(
    exprs: &[&Expr],
) -> Result<Option<(AlgebraicConstants, Vec<Expr>)>, ConstantsError> {
    let mut leaves = Vec::new();
    let mut taken = Vec::new();
    let mut abstracted = Vec::with_capacity(exprs.len());
    for (i, e) in exprs.iter().enumerate() {
        e.collect_variables(&mut taken);
        abstracted.push(
            abstract_constants(e, &mut leaves)
                .map_err(|err| ConstantsError::Expr(i, err.to_string()))?,
        );
    }
    let texts: Vec<String> = leaves.iter().map(|l| l.text.clone()).collect();
    let constants = AlgebraicConstants::new(leaves, &taken).map_err(|e| {
        ConstantsError::Field(format!(
            "the field of the constants {}: {e}",
            texts.join(", ")
        ))
    })?;
    Ok(constants.map(|k| {
        let filled = abstracted.iter().map(|e| k.fill(e)).collect();
        (k, filled)
    }))
}

/// Decides the statement with its algebraic constants in a primitive element (see the module
/// documentation).
///
/// # Errors
/// [`Error::Input`] for a constant the evaluator refuses, a field past the `algebraic-degree`
/// or `factor-combinations` limit, and the errors of [`prove_over`].
pub(crate) fn prove_with_constants(
    args: &ProveArgs,
    sides: &Sides,
    relations: &[(Expr, Expr)],
    nonzero: &[(Expr, Expr, String)],
    domains: &[super::Domain],
) -> Result<ExitCode, Error> {
    // Every expression with the part of the statement it belongs to, for the errors.
    let mut exprs: Vec<&Expr> = Vec::new();
    let mut parts: Vec<String> = Vec::new();
    for e in sides.lhs {
        exprs.push(e);
        parts.push("LHS".into());
    }
    for e in sides.rhs.into_iter().flatten() {
        exprs.push(e);
        parts.push("RHS".into());
    }
    for (i, (a, b)) in relations.iter().enumerate() {
        exprs.extend([a, b]);
        parts.extend([format!("--where #{}", i + 1), format!("--where #{}", i + 1)]);
    }
    for (a, b, text) in nonzero {
        exprs.extend([a, b]);
        parts.extend([format!("--where {text:?}"), format!("--where {text:?}")]);
    }
    let (k, filled) = match abstract_statement(&exprs) {
        Ok(Some(found)) => found,
        Ok(None) => return prove_over::<Radical>(args, sides, relations, nonzero, domains, None),
        Err(ConstantsError::Expr(i, why)) => {
            return Err(Error::Input(format!("{}: {why}", parts[i])))
        }
        Err(ConstantsError::Field(why)) => return Err(Error::Input(why)),
    };
    let mut filled = filled.into_iter();
    let mut next = || filled.next().expect("one filled expression per expression");
    let l: Vec<Expr> = sides.lhs.iter().map(|_| next()).collect();
    let r: Option<Vec<Expr>> = sides.rhs.map(|r| r.iter().map(|_| next()).collect());
    let rels: Vec<(Expr, Expr)> = relations.iter().map(|_| (next(), next())).collect();
    let nz: Vec<(Expr, Expr, String)> = nonzero
        .iter()
        .map(|(_, _, t)| (next(), next(), t.clone()))
        .collect();
    let filled = Sides {
        lhs: &l,
        rhs: r.as_deref(),
        shape: sides.shape,
    };
    prove_over::<Rational>(args, &filled, &rels, &nz, domains, Some(&k))
}

/// A relation `A = B` between rational functions, as the engine takes it.
pub(crate) type Relation<C> = (RatFun<C>, RatFun<C>);

/// The relation `m(c) = 0` of the primitive element over `C`, its variable entered in `vars`,
/// and the domain of `c` (the isolating interval of `theta`, so that any root of `m` the engine
/// picks is `theta` itself): what both front ends add to the statement.
///
/// # Errors
/// The conversion's error, in words.
pub(crate) fn constant_relation<C: PointField>(
    k: &AlgebraicConstants,
    vars: &mut Vars,
) -> Result<(Relation<C>, (Var, VarDomain)), String> {
    let m = k
        .relation()
        .to_ratfun::<C>(vars)
        .map_err(|e| format!("the minimal polynomial: {e}"))?;
    let c = vars
        .get(&k.name)
        .ok_or("the minimal polynomial has no variable")?;
    Ok(((m, RatFun::from_poly(Poly::zero())), (c, k.domain())))
}

/// After the engine has decided a statement with algebraic constants: a component it left
/// undecided (a non-zero reduction) gets its exact counter-example at `c = theta`
/// ([`search`]), is marked failing and the point returned; otherwise why no point was found
/// joins the search's text. `pi` is the variable of pi (no rational value), `mixed` the names
/// used both as numbers and as angles.
pub(crate) fn settle<C: PointField>(
    k: &AlgebraicConstants,
    spec: &IdentitySpec<C>,
    report: &mut IdentityReport<C>,
    pi: Option<Var>,
    mixed: &[String],
) -> Option<ConstantPoint> {
    let found = search(k, spec, report, pi, mixed);
    let IdentityVerdict::Undecided {
        searched,
        coordinate,
        ..
    } = &mut report.verdict
    else {
        return None;
    };
    match found {
        Ok(p) => {
            report.outcomes[*coordinate] = CoordinateOutcome::Fails;
            Some(p)
        }
        Err(why) => {
            *searched = format!("{searched}; at the exact value of {}: {why}", k.name);
            None
        }
    }
}

/// The polynomial over Q, for a coefficient field whose values here are rational (the constants'
/// statements are over Q).
fn rational<C: PointField>(p: &Poly<C>) -> Option<Poly<Rational>> {
    let mut terms = Vec::with_capacity(p.len());
    for (m, c) in p.terms() {
        terms.push((m.exponents(), c.to_radical()?.to_rational()?));
    }
    Some(Poly::from_terms(terms))
}

fn rational_ratfun<C: PointField>(f: &RatFun<C>) -> Option<RatFun<Rational>> {
    let (n, d) = (rational(f.numerator())?, rational(f.denominator())?);
    RatFun::from_poly(n).div(&RatFun::from_poly(d)).ok()?
}

/// The exact counter-example at `c = theta` for a statement the engine left undecided, or why
/// there is none to give (the reason joins the engine's).
pub fn search<C: PointField>(
    k: &AlgebraicConstants,
    spec: &IdentitySpec<C>,
    report: &IdentityReport<C>,
    pi: Option<Var>,
    mixed: &[String],
) -> Result<ConstantPoint, String> {
    if !mixed.is_empty() {
        return Err(format!(
            "{} is both a number and an angle",
            mixed.join(", ")
        ));
    }
    let c = spec
        .vars
        .get(&k.name)
        .ok_or("the constants cancelled from the statement")?;
    let unsupported = || "a coefficient outside Q".to_string();
    let IdentityVerdict::Undecided { coordinate, .. } = &report.verdict else {
        return Err("no component is undecided".into());
    };
    let Some(Statement::Sides(l, r)) = spec.coordinates.get(*coordinate) else {
        return Err("the statement is a residual, not a pair of sides".into());
    };
    let (l, r) = (
        rational_ratfun(l).ok_or_else(unsupported)?,
        rational_ratfun(r).ok_or_else(unsupported)?,
    );
    let minimal = k.field.modulus().primitive_part().to_poly(c);
    let mut relations = Vec::new();
    for (a, b) in &spec.relations {
        if !(a.is_polynomial() && b.is_polynomial()) {
            return Err("a relation between fractions".into());
        }
        let p = rational(&(a.numerator().clone() - b.numerator())).ok_or_else(unsupported)?;
        if p != minimal && p != -minimal.clone() {
            relations.push(p);
        }
    }
    let conditions = report
        .conditions
        .iter()
        .map(rational)
        .collect::<Option<Vec<_>>>()
        .ok_or_else(unsupported)?;
    k.counter_example(c, &l, &r, &relations, &conditions, &spec.domains, pi)
}
