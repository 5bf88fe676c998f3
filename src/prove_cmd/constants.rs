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
    AlgebraicConstants, ConstantPoint, Domain, IdentityReport, IdentitySpec, IdentityVerdict,
    PointField, Statement,
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
    sides
        .lhs
        .iter()
        .chain(sides.rhs.into_iter().flatten())
        .chain(relations.iter().flat_map(|(a, b)| [a, b]))
        .chain(nonzero.iter().flat_map(|(a, b, _)| [a, b]))
        .any(needs_algebraic::<Radical>)
}

/// Decides the statement with its algebraic constants in a primitive element (see the module
/// documentation).
///
/// # Errors
/// [`Error::Input`] for a constant the evaluator refuses, a field past the `algebraic-degree`
/// limit, and the errors of [`prove_over`].
pub(crate) fn prove_with_constants(
    args: &ProveArgs,
    sides: &Sides,
    relations: &[(Expr, Expr)],
    nonzero: &[(Expr, Expr, String)],
    domains: &[(String, Domain, String)],
) -> Result<ExitCode, Error> {
    let mut leaves = Vec::new();
    let mut taken = Vec::new();
    let mut abstracted = |e: &Expr, what: &str| {
        e.collect_variables(&mut taken);
        abstract_constants(e, &mut leaves).map_err(|err| Error::Input(format!("{what}: {err}")))
    };
    let l = sides
        .lhs
        .iter()
        .map(|e| abstracted(e, "LHS"))
        .collect::<Result<Vec<_>, _>>()?;
    let r = sides
        .rhs
        .map(|r| {
            r.iter()
                .map(|e| abstracted(e, "RHS"))
                .collect::<Result<Vec<_>, _>>()
        })
        .transpose()?;
    let mut rels = Vec::new();
    for (i, (a, b)) in relations.iter().enumerate() {
        let what = format!("--where #{}", i + 1);
        rels.push((abstracted(a, &what)?, abstracted(b, &what)?));
    }
    let mut nz = Vec::new();
    for (a, b, text) in nonzero {
        let what = format!("--where {text:?}");
        nz.push((abstracted(a, &what)?, abstracted(b, &what)?, text.clone()));
    }
    let texts: Vec<String> = leaves.iter().map(|l| l.text.clone()).collect();
    let constants = AlgebraicConstants::new(leaves, &taken).map_err(|e| {
        Error::Input(format!(
            "the field of the constants {}: {e}",
            texts.join(", ")
        ))
    })?;
    let Some(k) = constants else {
        return prove_over::<Radical>(args, sides, relations, nonzero, domains, None);
    };
    let l: Vec<Expr> = l.iter().map(|e| k.fill(e)).collect();
    let r: Option<Vec<Expr>> = r.map(|r| r.iter().map(|e| k.fill(e)).collect());
    let rels: Vec<(Expr, Expr)> = rels.iter().map(|(a, b)| (k.fill(a), k.fill(b))).collect();
    let nz: Vec<(Expr, Expr, String)> = nz
        .iter()
        .map(|(a, b, t)| (k.fill(a), k.fill(b), t.clone()))
        .collect();
    let filled = Sides {
        lhs: &l,
        rhs: r.as_deref(),
        shape: sides.shape,
    };
    prove_over::<Rational>(args, &filled, &rels, &nz, domains, Some(&k))
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
    excluded: &[Var],
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
    k.counter_example(c, &l, &r, &relations, &conditions, &spec.domains, excluded)
}

/// The point of a counter-example by name (`c` is the constant, not a coordinate).
pub fn named_point(point: &ConstantPoint, vars: &Vars) -> Vec<(String, String)> {
    point
        .values
        .iter()
        .map(|(v, q)| (vars.name(*v).unwrap_or("?").to_string(), q.to_string()))
        .collect()
}
