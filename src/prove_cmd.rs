//! `exactcheck prove 'LHS' ['RHS'] [--where 'A = B' | --where 'r > 0' ...] [--random K]`: the
//! user's own polynomial identities.
//!
//! The sides may be two vectors or two matrices of one shape: the identity is then one statement
//! per component for the identity engine (and one random test per component), the verdict
//! `proved` only when every component is, a failure or an undecided result naming its
//! components (`in component 2 (y)`, `entry (1, 2)`); sides of different shapes are an input
//! error.
//!
//! Both sides (and each relation) are parsed in the expression syntax (numbers, `sqrt(k)`,
//! `diff(E, t[, k])`, variables, `+ - * / ^`, parentheses) with the function library of
//! `exactcheck_exact::expr::library` (`dot`, `cross`, `norm2`, `det` of `[[a, b], [c, d]]`,
//! `bezier`, `subs`, ...) resolved to a scalar, expanded, and `LHS - RHS` is reduced
//! modulo the relations (unit circles `c^2 + s^2 = 1` in closed form, others by a Gröbner
//! basis) by the identity engine `exactcheck_exact::prove::decide_identity`, and the verdict is
//! worded by the formatter claims files and the catalogue use too ([`crate::phrase`]). With a
//! division by a non-constant anywhere, the sides are rational functions (`Expr::to_ratfun`): the identity is decided with the
//! denominators cleared, and the divisors met are reported as side conditions. `pi`, `e` and `i`
//! are refused as variables. A `--where` with `<`, `<=`, `>` or `>=` is a domain (`r > 0`,
//! `0 <= t <= 1`, constant bounds only; an angle of sin, cos and tan in multiples of pi, which
//! becomes signs of its cosine and sine: `conditions`): counter-examples are searched inside the domains. A
//! `--where 'w != 0'` is a hypothesis. Square roots of expressions become variables with their
//! relations and sign conditions (`prove::square_roots`), and a proof that needs hypotheses
//! names the ones it used.
//! Inconsistent relations (`1 = 2`; `x = 1` and `x = 2`) are an input error. `--random K`
//! evaluates instead at K random points modulo a prime drawn at random per run
//! (`exactcheck_exact::prove::random`, which proves the printed error bound), in the same
//! language: the library's functions resolved, `diff`, `integrate`, `sum`, `binomial` and
//! `factorial` lowered to arithmetic, divisions evaluated with the points where a divisor
//! vanishes skipped, algebraic constants evaluated modulo p in the quotient ring of their
//! field's minimal polynomial and angles on their unit circles (a failure then confirmed by an
//! exact counter-example). Exit status:
//! 0 proved or holds, 1 fails or undecided, 2 bad input. An identity between constants whose
//! nested square roots do not denest (`sqrt(2 + sqrt(2))`) is decided in the real algebraic
//! numbers (`exactcheck_exact::algebraic`).

mod conditions;
pub(crate) mod constants;

use conditions::parse_where;
pub use conditions::{parse_where_with, split_where, var_domains, Domain, Where};
mod random;

use crate::claims::Verdict;
use crate::phrase::Phrasing;
use crate::Error;
use clap::Args;
use exactcheck_core::Ring;
use exactcheck_exact::expr::library::{self, Shape};
use exactcheck_exact::expr::{
    angle_variable, angles, constant_base, first_reserved, has_constant_angle, has_trig, is_latex,
    ratfun_sides, register_angle_bases, split_equation, Coefficient, Expr, ExprError, PI,
};
use exactcheck_exact::poly::{Poly, Var, Vars};
use exactcheck_exact::prove::{
    decide_identity, square_roots, AlgebraicConstants, EngineError, FractionIdentity,
    IdentityReport, IdentitySpec, IdentityVerdict, Part, PointField, SquareRoot, Statement,
    SumRanges, VarDomain,
};
use exactcheck_exact::ratfun::RatFun;
use exactcheck_exact::{Algebraic, Radical, Rational};
use random::random_test;
use serde_json::json;
use std::cell::RefCell;
use std::fmt::Display;
use std::process::ExitCode;

/// Arguments of `exactcheck prove`.
#[derive(Debug, Args)]
pub struct ProveArgs {
    /// The left-hand side (a leading minus is part of the expression: '-x^2'). Besides sqrt and
    /// diff, the sides may use vec, dot, cross, norm2, x, y, z, at, det, transpose, bernstein,
    /// bezier, subs, lists [a, b] and matrices [[a, b], [c, d]] (docs/formulas.md). Two vectors
    /// or two matrices of one shape are compared component by component.
    #[arg(allow_hyphen_values = true)]
    pub lhs: String,
    /// The right-hand side (default 0). Without it, a left-hand side with one `=` outside
    /// parentheses and braces is the whole equation: 'x^2 - 1 = (x - 1)(x + 1)'.
    #[arg(allow_hyphen_values = true)]
    pub rhs: Option<String>,
    /// A relation `A = B` the variables satisfy, e.g. `c^2 + s^2 = 1`, or a domain with constant
    /// bounds, e.g. `r > 0`, `0 <= t <= 1`, `R >= 1/2`, or for an angle of sin, cos and tan in
    /// multiples of pi, `0 <= theta <= pi` (repeatable, or a comma-separated list:
    /// `a >= 0, b >= 0`, `a, b > 0`; one domain per variable).
    /// Inconsistent relations are an error.
    #[arg(long = "where", value_name = "RELATION", allow_hyphen_values = true)]
    pub relations: Vec<String>,
    /// A definition `NAME = VALUE` the sides and relations may use, as a claims file's
    /// `[define]` entry (repeatable): a vector `u = [u1, u2, u3]`, a matrix
    /// `M = [[a, b], [c, d]]`, a scalar, or a function `f(t) = t^2`. A bold name of LaTeX input
    /// (`\mathbf{u}`, `\vec{u}`) must be defined: it names a vector or a matrix.
    #[arg(long = "define", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub defines: Vec<String>,
    /// Instead of expanding, evaluate both sides at K random points (1 to 100000) modulo a prime
    /// drawn at random from [2^62, 2^63) for this run: `fails` at a non-zero point, `holds`
    /// when the proved error bound is below 2^-30, else `undecided` with the bound. Relations
    /// must be unit circles `c^2 + s^2 = 1`; no domains. Constants (`sqrt(2)`, `cos(pi/8)`) are
    /// evaluated in F_p[c]/(m) for the minimal polynomial m of their field, angles of sin, cos,
    /// tan on their unit circles; a failure is then confirmed by an exact counter-example. A
    /// square root of an expression is a root w with w^2 its radicand, for either sign: a
    /// difference is then `undecided`.
    #[arg(long, value_name = "K")]
    pub random: Option<u64>,
    /// Seed of `--random` (default: a fresh random seed, printed, per run). The prime is drawn
    /// from the seed and the identity; a chosen seed reproduces a run but gives no error bound:
    /// all-zero is then `holds (reproduced)`.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

/// A fresh seed from the operating system's randomness (the keys of std's `RandomState`).
pub fn fresh_seed() -> u64 {
    use std::hash::{BuildHasher, Hasher};
    let mut h = std::collections::hash_map::RandomState::new().build_hasher();
    h.write_u64(0x5EED);
    h.finish()
}

/// Parses `text` (named `what` in messages), resolving the library functions (`dot`, `det`,
/// `bezier`, matrices, ...) to a scalar expression; a free variable `pi`, `e` or `i` is refused
/// ([`reserved_constant`](exactcheck_exact::expr::reserved_constant)).
fn parse(text: &str, what: &str) -> Result<Expr, Error> {
    parse_in(&RefCell::default(), text, what)
}

/// `parse` with the definitions of `--define`.
fn parse_in(defs: &RefCell<library::Defs>, text: &str, what: &str) -> Result<Expr, Error> {
    let e = defs
        .borrow_mut()
        .resolve_scalar(text)
        .map_err(|e| Error::Input(format!("{what}: {e}")))?;
    match first_reserved([&e]) {
        Some(why) => Err(Error::Input(format!("{what}: {why}"))),
        None => Ok(e),
    }
}

/// Parses a side of `prove` (named `what` in messages) with the library functions resolved: a
/// scalar, a vector or a matrix; a free variable `pi`, `e` or `i` in a component is refused.
fn parse_value(
    text: &str,
    what: &str,
    defs: &RefCell<library::Defs>,
) -> Result<library::Val, Error> {
    let v = defs
        .borrow_mut()
        .resolve_text(text)
        .map_err(|e| Error::Input(format!("{what}: {e}")))?;
    match first_reserved(&v.components()) {
        Some(why) => Err(Error::Input(format!("{what}: {why}"))),
        None => Ok(v),
    }
}

/// The variables the relations fix to a rational number (`n = 4`, `1/2 = R`), each once.
fn fixed_values(relations: &[(Expr, Expr)]) -> Vec<(String, Rational)> {
    let mut out: Vec<(String, Rational)> = Vec::new();
    for (a, b) in relations {
        for (var, value) in [(a, b), (b, a)] {
            let exactcheck_exact::expr::ExprKind::Var(name) = &var.kind else {
                continue;
            };
            if name == PI || out.iter().any(|(n, _)| n == name) {
                continue;
            }
            if let Ok(q) = value.eval_constant::<Rational>() {
                out.push((name.clone(), q));
            }
        }
    }
    out
}

/// The two sides of `prove`, read in one language: a plain side beside a LaTeX side is read
/// as LaTeX too when that reading is what the LaTeX side suggests: the plain reading has a
/// name the LaTeX side lacks (`uv` in `2uv`), and the LaTeX reading only adds letters the
/// LaTeX side has (`u` and `v`). A note on standard error says so. A plain side that LaTeX
/// does not read (`x1`) stays plain.
/// The note is left out when `quiet`.
fn read_sides(
    lhs: &str,
    rhs: Option<&str>,
    defs: &RefCell<library::Defs>,
    quiet: bool,
) -> Result<(library::Val, Option<library::Val>), Error> {
    let mut l = parse_value(lhs, "LHS", defs)?;
    let Some(rhs) = rhs else {
        return Ok((l, None));
    };
    let mut r = parse_value(rhs, "RHS", defs)?;
    let names = |v: &library::Val| {
        let mut out = Vec::new();
        for e in v.components() {
            e.collect_variables(&mut out);
        }
        out
    };
    let reread = |plain: &str, value: &library::Val, latex: &library::Val, what: &str| {
        let (before, beside) = (names(value), names(latex));
        if before.iter().all(|n| beside.contains(n)) {
            return None;
        }
        let v = parse_value(&format!("${plain}$"), what, defs).ok()?;
        let after = names(&v);
        let fits = after
            .iter()
            .all(|n| before.contains(n) || beside.contains(n))
            && after.iter().any(|n| !before.contains(n));
        fits.then(|| {
            let joined: Vec<String> = before
                .iter()
                .filter(|n| !after.contains(n))
                .map(|n| format!("'{n}'"))
                .collect();
            if !quiet {
                eprintln!(
                    "exactcheck: note: {what} is read as LaTeX, like the other side: adjacent letters multiply ({} {} of one-letter variables)",
                    joined.join(", "),
                    if joined.len() == 1 { "is a product" } else { "are products" }
                );
            }
            v
        })
    };
    match (is_latex(lhs), is_latex(rhs)) {
        (true, false) => r = reread(rhs, &r, &l, "RHS").unwrap_or(r),
        (false, true) => l = reread(lhs, &l, &r, "LHS").unwrap_or(l),
        _ => {}
    }
    Ok((l, Some(r)))
}

/// The definitions of `--define NAME=VALUE` (in the order given), each checked at once, and
/// the values `fixed` for their variables ([`fixed_values`]).
fn definitions(texts: &[String], fixed: &[(String, Rational)]) -> Result<library::Defs, Error> {
    let mut entries = Vec::new();
    for (i, text) in texts.iter().enumerate() {
        let Some((name, value)) = text
            .split_once('=')
            .filter(|(n, v)| !n.trim().is_empty() && !v.trim().is_empty())
        else {
            return Err(Error::Input(format!(
                "--define #{}: {text:?} must have the form NAME = VALUE (e.g. 'u = [u1, u2, u3]')",
                i + 1
            )));
        };
        entries.push((
            name.trim().to_string(),
            library::DefText::Scalar(value.trim().to_string()),
        ));
    }
    entries.extend(
        fixed
            .iter()
            .map(|(n, v)| (n.clone(), library::DefText::Scalar(format!("({v})")))),
    );
    let mut defs = library::Defs::new(entries)
        .map_err(|(name, why)| Error::Input(format!("--define {name}: {why}")))?;
    defs.resolve_all()
        .map_err(|e| Error::Input(format!("--define: {e}")))?;
    Ok(defs)
}

/// The two sides of `prove`, component by component, and their one shape.
pub(crate) struct Sides<'a> {
    pub(crate) lhs: &'a [Expr],
    /// `None`: the right side is zero in every component.
    pub(crate) rhs: Option<&'a [Expr]>,
    pub(crate) shape: Shape,
}

impl Sides<'_> {
    /// The names of the components (empty for a scalar identity), for [`Phrasing::labels`].
    fn labels(&self) -> Vec<String> {
        match self.shape {
            Shape::Scalar => Vec::new(),
            s => (0..s.len()).map(|k| s.component(k)).collect(),
        }
    }
}

/// A hint when a name of several letters is spelled by one-letter variables of the same
/// formula (`ac` beside `a` and `c`): outside LaTeX, adjacent letters are one name, so `2ac` is 2
/// times the variable `ac`, which is rarely what a paper means.
pub(crate) fn joined_names_hint(sides: &[&Expr]) -> Option<String> {
    let mut names = Vec::new();
    for e in sides {
        e.collect_variables(&mut names);
    }
    let letters: Vec<char> = names
        .iter()
        .filter_map(|n| {
            let mut c = n.chars();
            c.next().filter(|_| c.next().is_none())
        })
        .collect();
    let joined: Vec<&String> = names
        .iter()
        .filter(|n| n.len() > 1 && n.chars().all(|c| letters.contains(&c)))
        .collect();
    let first = joined.first()?;
    let list = joined
        .iter()
        .map(|n| format!("'{n}'"))
        .collect::<Vec<_>>()
        .join(", ");
    let product = first
        .chars()
        .map(String::from)
        .collect::<Vec<_>>()
        .join("*");
    Some(format!(
        "{list} {} one variable, not a product of the one-letter variables beside it: write '{product}' for the product (in LaTeX input, within $...$, adjacent letters multiply)",
        if joined.len() == 1 { "is" } else { "are each" }
    ))
}

/// Runs `exactcheck prove`.
///
/// # Errors
/// [`Error::Input`] for a malformed expression, relation or domain, a division by zero or by a
/// non-constant, inconsistent relations; [`Error::Usage`] for a bad `--random` request.
pub fn run(args: &ProveArgs) -> Result<ExitCode, Error> {
    // One argument with one `=` outside parentheses and braces is the equation `LHS = RHS`.
    let split = match args.rhs {
        None => split_equation(&args.lhs),
        Some(_) => None,
    };
    let (lhs_text, rhs_text) = match &split {
        Some((l, r)) => (l.as_str(), Some(r)),
        None => (args.lhs.as_str(), args.rhs.as_ref()),
    };
    let defs = RefCell::new(definitions(&args.defines, &[])?);
    let mut relations = Vec::new();
    let mut nonzero = Vec::new();
    let mut domains: Vec<Domain> = Vec::new();
    let texts = args
        .relations
        .iter()
        .enumerate()
        .flat_map(|(i, r)| split_where(r).into_iter().map(move |t| (i, t)));
    for (i, r) in texts {
        let r = &r;
        let what = format!("--where #{}", i + 1);
        match parse_where(r, &what, &defs)? {
            Where::Relation(a, b) => relations.push((a, b)),
            Where::NonZero(a, b) => nonzero.push((a, b, r.trim().to_string())),
            Where::Domain(d) => {
                let v = &d.name;
                if d.bounds.is_empty() {
                    return Err(Error::Input(format!("{what}: the domain {r:?} is empty")));
                }
                if domains.iter().any(|w| w.name == *v) {
                    return Err(Error::Input(format!(
                        "{what}: {v} already has a domain (give both bounds in one, e.g. '0 <= {v} <= 1')"
                    )));
                }
                domains.push(d);
            }
        }
    }
    // A statement that only reads with a variable fixed by a relation (`binomial(n, k)` or
    // `2^n` with `--where 'n = 4'`) is decided with it substituted, and a note says so.
    let decide = |fixed: &[(String, Rational)]| {
        decide_sides(
            args,
            (lhs_text, rhs_text.map(String::as_str)),
            fixed,
            (&relations, &nonzero, &domains),
        )
    };
    match decide(&[]) {
        Err(Error::Input(first)) => {
            let fixed = fixed_values(&relations);
            if fixed.is_empty() {
                return Err(Error::Input(first));
            }
            match decide(&fixed) {
                Ok(code) => {
                    let mut names = Vec::new();
                    for text in std::iter::once(lhs_text).chain(rhs_text.map(String::as_str)) {
                        if let Ok(e) = exactcheck_exact::expr::parse_expr_with_calls(text) {
                            e.collect_variables(&mut names);
                        }
                    }
                    let list: Vec<String> = fixed
                        .iter()
                        .filter(|(n, _)| names.contains(n))
                        .map(|(n, v)| format!("{n} = {v}"))
                        .collect();
                    eprintln!(
                        "exactcheck: note: decided with {} from --where substituted into the sides, which need {}",
                        list.join(", "),
                        if list.len() == 1 { "it as a number" } else { "them as numbers" }
                    );
                    Ok(code)
                }
                Err(_) => Err(Error::Input(first)),
            }
        }
        other => other,
    }
}

/// The conditions of `prove` as parsed: relations, hypotheses `A != B`, domains.
type Conditions<'a> = (&'a [(Expr, Expr)], &'a [(Expr, Expr, String)], &'a [Domain]);

/// Reads the sides (with the values `fixed` substituted for their variables) and decides
/// the statement under the conditions; the hints about the sides are printed on the first
/// reading only (without `fixed`).
fn decide_sides(
    args: &ProveArgs,
    (lhs_text, rhs_text): (&str, Option<&str>),
    fixed: &[(String, Rational)],
    (relations, nonzero, domains): Conditions,
) -> Result<ExitCode, Error> {
    let defs = RefCell::new(definitions(&args.defines, fixed)?);
    let (lhs_value, rhs_value) = read_sides(lhs_text, rhs_text, &defs, !fixed.is_empty())?;
    let shape = lhs_value.dims();
    let lhs = lhs_value.components();
    let rhs = match rhs_value {
        Some(v) => {
            if v.dims() != shape {
                return Err(Error::Input(format!(
                    "the sides differ in shape: LHS is {shape}, RHS is {}; an identity compares sides of one shape component by component",
                    v.dims()
                )));
            }
            Some(v.components())
        }
        None => None,
    };
    let sides: Vec<&Expr> = lhs.iter().chain(rhs.iter().flatten()).collect();
    if let Some(hint) = joined_names_hint(&sides).filter(|_| fixed.is_empty()) {
        eprintln!("exactcheck: hint: {hint}");
    }
    let tied: Vec<(&Expr, &Expr)> = relations.iter().map(|(a, b)| (a, b)).collect();
    if let Some(why) = exactcheck_exact::expr::library::diff_against_relations(&sides, &tied) {
        return Err(Error::Input(format!("--where: {why}")));
    }
    if args.random.is_some() && !nonzero.is_empty() {
        return Err(Error::Usage(
            "--random does not take hypotheses ('w != 0'); run without --random".into(),
        ));
    }
    if let Some(k) = args.random {
        let zeros = vec![parse("0", "RHS")?; lhs.len()];
        return random_test(
            args,
            k,
            (&lhs, rhs.as_ref().unwrap_or(&zeros), shape),
            relations,
            !domains.is_empty(),
        );
    }
    // Radicals (also those of sin and cos at multiples of pi) need the radical coefficient
    // field; everything else runs over Q.
    let radical = lhs
        .iter()
        .chain(rhs.iter().flatten())
        .chain(relations.iter().flat_map(|(a, b)| [a, b]))
        .chain(nonzero.iter().flat_map(|(a, b, _)| [a, b]))
        .any(|e| has_trig(e) || exactcheck_exact::expr::library::has_sqrt(e));
    let sides = Sides {
        lhs: &lhs,
        rhs: rhs.as_deref(),
        shape,
    };
    if radical {
        if relations.is_empty() && domains.is_empty() && nonzero.is_empty() && lhs.len() == 1 {
            let rhs = rhs.as_ref().map(|r| &r[0]);
            if let Some(code) = prove_algebraic_constants(args, &lhs[0], rhs)? {
                return Ok(code);
            }
        }
        if constants::needs_constants(&sides, relations, nonzero) {
            return constants::prove_with_constants(args, &sides, relations, nonzero, domains);
        }
        prove_over::<Radical>(args, &sides, relations, nonzero, domains, None)
    } else {
        prove_over::<Rational>(args, &sides, relations, nonzero, domains, None)
    }
}

/// An identity between constants with a square root the square-root field [`Radical`] refuses
/// (a nested radical that does not denest, such as `sqrt(2 + sqrt(2))`) or a sine, cosine or
/// tangent of a multiple of pi outside it (`cos(2*pi/7)`), decided exactly in the
/// real algebraic numbers ([`Algebraic`]). `None` when a side has a variable or both sides lie
/// in the square-root field, which then decides the identity as before.
fn prove_algebraic_constants(
    args: &ProveArgs,
    lhs: &Expr,
    rhs: Option<&Expr>,
) -> Result<Option<ExitCode>, Error> {
    let mut names = Vec::new();
    lhs.collect_variables(&mut names);
    if let Some(r) = rhs {
        r.collect_variables(&mut names);
    }
    // `pi` inside `sin`, `cos`, `tan` is an angle, not a variable.
    names.retain(|n| n != exactcheck_exact::expr::PI);
    // A square root outside the field, or a sine or cosine of a multiple of pi whose value is
    // not in it (`cos(2*pi/7)`); the other errors come back the same from `Algebraic`.
    let refused = |e: &Expr| {
        matches!(
            e.eval_constant::<Radical>(),
            Err(ExprError::NoSqrt { .. } | ExprError::BadCall { .. })
        )
    };
    // `sin(1)` has no algebraic value: such statements are decided with the constant angle.
    let constant_angle = has_constant_angle(lhs) || rhs.is_some_and(has_constant_angle);
    if !names.is_empty() || constant_angle || !(refused(lhs) || rhs.is_some_and(refused)) {
        return Ok(None);
    }
    // Pi outside an angle has no algebraic value: such a side (`pi*sqrt(2 + sqrt(2))`) is a
    // polynomial in pi, decided with pi an indeterminate next to the constants' field.
    let eval = |e: &Expr, what: &str| match e.eval_constant::<Algebraic>() {
        Err(ExprError::NotConstant { name, .. }) if name == PI => Ok(None),
        Err(err) => Err(Error::Input(format!("{what}: {err}"))),
        Ok(v) => Ok(Some(v)),
    };
    let Some(l) = eval(lhs, "LHS")? else {
        return Ok(None);
    };
    let r = match rhs.map(|e| eval(e, "RHS")).transpose()? {
        Some(Some(v)) => v,
        Some(None) => return Ok(None),
        None => Algebraic::zero(),
    };
    let difference = l.clone() - r.clone();
    let (verdict, code, evidence) = if difference.is_zero() {
        (
            "proved",
            ExitCode::SUCCESS,
            format!("LHS - RHS = 0 exactly: both sides are {l}"),
        )
    } else {
        (
            "fails",
            ExitCode::from(1),
            format!("LHS - RHS = {difference}, a non-zero constant (LHS = {l}, RHS = {r})"),
        )
    };
    let method = "exact arithmetic of real algebraic numbers (resultants, isolating intervals)";
    if args.json {
        crate::output::println(json!({
            "verdict": verdict,
            "method": method,
            "evidence": evidence,
            "residual_terms": usize::from(!difference.is_zero()),
        }))?;
    } else {
        crate::output::println(format_args!("{verdict}: {evidence}"))?;
    }
    Ok(Some(code))
}

fn to_ratfun<C: Coefficient + exactcheck_core::Field>(
    e: &Expr,
    vars: &mut Vars,
    what: &str,
) -> Result<RatFun<C>, Error> {
    e.to_ratfun::<C>(vars)
        .map_err(|err| Error::Input(format!("{what}: {err}")))
}

fn to_poly<C: Coefficient>(e: &Expr, vars: &mut Vars, what: &str) -> Result<Poly<C>, Error> {
    e.to_poly::<C>(vars)
        .map_err(|err| Error::Input(format!("{what}: {err}")))
}

/// Decides `lhs = rhs` over `C` (the core of [`run`]); `constants`, when given, are the
/// statement's algebraic constants as polynomials in the variable of their primitive element,
/// whose minimal polynomial joins the relations ([`constants`]).
pub(crate) fn prove_over<C: PointField + Display>(
    args: &ProveArgs,
    sides: &Sides,
    relations: &[(Expr, Expr)],
    nonzero: &[(Expr, Expr, String)],
    domains: &[Domain],
    constants: Option<&AlgebraicConstants>,
) -> Result<ExitCode, Error> {
    let mut vars = Vars::new();
    // `sqrt` of a non-constant becomes a variable with its relation and sign condition.
    vars.allow_roots();
    // The base angles of everything decided together (`x/2` for `sin(x/2)` and `sin(x)`).
    let decided: Vec<&Expr> = sides
        .lhs
        .iter()
        .chain(sides.rhs.into_iter().flatten())
        .chain(relations.iter().flat_map(|(a, b)| [a, b]))
        .chain(nonzero.iter().flat_map(|(a, b, _)| [a, b]))
        .collect();
    register_angle_bases(&decided, &mut vars).map_err(|e| Error::Input(e.to_string()))?;
    let mut coordinates = Vec::new();
    for (k, lhs) in sides.lhs.iter().enumerate() {
        let what = |side: &str| match sides.shape {
            Shape::Scalar => side.to_string(),
            s => format!("{side}, {}", s.component(k)),
        };
        let (l, r) = match sides.rhs {
            Some(r) => ratfun_sides::<C>(lhs, &r[k], &mut vars).map_err(|(rhs, err)| {
                Error::Input(format!("{}: {err}", what(if rhs { "RHS" } else { "LHS" })))
            })?,
            None => (
                to_ratfun::<C>(lhs, &mut vars, &what("LHS"))?,
                RatFun::from_poly(Poly::zero()),
            ),
        };
        coordinates.push(Statement::Sides(l, r));
    }
    let mut rels = Vec::new();
    for (i, (a, b)) in relations.iter().enumerate() {
        let what = format!("--where #{}", i + 1);
        rels.push((
            to_ratfun::<C>(a, &mut vars, &what)?,
            to_ratfun::<C>(b, &mut vars, &what)?,
        ));
    }
    // Hypotheses `A != B`, cleared of denominators (which become hypotheses too).
    let mut hypotheses: Vec<Poly<C>> = Vec::new();
    let mut nonzero_texts: Vec<(String, String)> = Vec::new();
    for (i, (a, b, text)) in nonzero.iter().enumerate() {
        let what = format!("--where {text:?}");
        let a = to_ratfun::<C>(a, &mut vars, &what)?;
        let b = to_ratfun::<C>(b, &mut vars, &what)?;
        let cleared =
            FractionIdentity::new(&a, &b).map_err(|e| Error::Input(format!("{what}: {e}")))?;
        if cleared.residual.is_zero() {
            return Err(Error::Input(format!(
                "--where #{}: {text:?} is false everywhere (both sides are the same)",
                i + 1
            )));
        }
        nonzero_texts.push((cleared.residual.display(&vars).to_string(), text.clone()));
        hypotheses.push(cleared.residual);
        hypotheses.extend(cleared.conditions);
    }
    let roots =
        square_roots::<C>(&mut vars).map_err(|e| Error::Input(format!("square root: {e}")))?;
    for root in &roots {
        rels.push(root.relation());
    }
    let angles = add_angles(&vars, &mut rels);
    let (angle_list, pi) = (&angles.list, angles.pi);
    // The minimal polynomial of the constants' primitive element (after the angles, so that it
    // does not count as a relation of the user's).
    let constant_domain = match constants {
        Some(k) => {
            let (m, domain) = crate::prove_cmd::constants::constant_relation::<C>(k, &mut vars)
                .map_err(Error::Input)?;
            rels.push(m);
            Some(domain)
        }
        None => None,
    };
    let circle_texts: Vec<String> = angle_list
        .iter()
        .map(|a| format!("cos({0})^2 + sin({0})^2 = 1", a.name))
        .collect();
    if let Some(d) = domains.iter().find(|d| d.name == PI) {
        return Err(Error::Input(format!(
            "--where {:?}: pi is a constant, not a variable: it takes no domain",
            d.text
        )));
    }
    let bounds = var_domains(&vars, domains).map_err(|e| Error::Input(format!("--where {e}")))?;
    let mut doms: Vec<(Var, VarDomain)> = bounds.bounds.clone();
    doms.extend(roots.iter().map(|r| (r.var, SquareRoot::<C>::domain())));
    doms.extend(constant_domain);
    // The variables of sums' symbolic bounds are integers inside the sums' ranges.
    let sums = SumRanges::of(decided.iter().copied());
    sums.add_domains(&vars, &mut doms);
    let spec = IdentitySpec {
        relations: rels,
        domains: doms,
        hypotheses,
        ..IdentitySpec::new(vars, coordinates)
    };
    let mut phrasing = Phrasing {
        relations: conditions::relation_texts(&args.relations),
        circles: circle_texts,
        domains: domains.iter().map(|d| d.text.clone()).collect(),
        labels: sides.labels(),
        nonzero_texts,
        domain_texts: Phrasing::domain_texts(bounds.texts.iter().map(|(n, t)| (n, t)), constants),
        roots: Phrasing::root_texts(&roots, &spec.vars),
        pi,
        constants,
        ..Phrasing::new(&spec.vars)
    };
    let report = decide_identity(&spec).map_err(|e| {
        let part = match &e {
            EngineError::Decide(..) => "--where".to_string(),
            EngineError::Size(Part::Relation(i), _) => format!("--where #{}", i + 1),
            EngineError::Size(..) => "LHS - RHS".to_string(),
        };
        Error::Input(format!("{part}: {}", phrasing.error(&e)))
    })?;
    let mut report = report;
    sound_counter_example(&spec, &mut report, &angles);
    sums.check(&spec.vars, &mut report);
    // With algebraic constants, a non-zero reduction gets its counter-example at c = theta.
    // (Not with a constant angle: the search would give its cosine and sine rational values.)
    phrasing.constant_point = constants
        .filter(|_| constant_base(&spec.vars).is_none())
        .and_then(|k| {
            crate::prove_cmd::constants::settle(k, &spec, &mut report, pi, &angles.mixed)
        });
    let code = match phrasing.verdict(&report) {
        Verdict::Proved | Verdict::Holds => ExitCode::SUCCESS,
        Verdict::Fails | Verdict::Undecided => ExitCode::from(1),
    };
    if args.json {
        crate::output::println(phrasing.json(&spec, &report, sides.shape))?;
    } else {
        crate::output::println(format_args!(
            "{}: {}",
            phrasing.verdict(&report),
            phrasing.evidence(&spec, &report)
        ))?;
    }
    Ok(code)
}

/// A failure whose point is not a real counter-example becomes undecided: when a relation
/// involves pi (the point satisfies it with pi at a rational value, not at pi), or when a
/// variable is also an angle (the point gives the variable and the cosine and sine of the angle
/// independent values).
pub fn sound_counter_example<C: PointField>(
    spec: &IdentitySpec<C>,
    report: &mut IdentityReport<C>,
    angles: &Angles,
) {
    let why = if angles.pi_in_relations {
        "a relation involves pi, and the counter-example search satisfies it with pi a rational value, not at pi".to_string()
    } else if let Some(u) = &angles.constant_in_relations {
        format!("a relation involves cos({u}) or sin({u}), and the counter-example search satisfies it with them at a rational point of their circle, not at the constant angle {u}")
    } else if !angles.mixed.is_empty() {
        format!(
            "{} {} both as a number and as an angle of sin, cos or tan, and the counter-example search gives a number and the angle's cosine and sine independent values",
            angles.mixed.join(", "),
            if angles.mixed.len() == 1 { "occurs" } else { "occur" }
        )
    } else if let Some(why) = pi_with_constant_angle(spec, report, angles) {
        why
    } else {
        return;
    };
    if let IdentityVerdict::Fails {
        coordinate,
        normal_form,
        ..
    } = &report.verdict
    {
        report.verdict = IdentityVerdict::Undecided {
            coordinate: *coordinate,
            normal_form: normal_form.clone(),
            searched: format!("a point was found, but it is not a counter-example: {why}"),
        };
    }
}

/// Why a counter-example of a statement with pi and a constant angle is none: its value there is
/// a polynomial in pi and the angle's cosine and sine, and whether pi and `e^{iu}` are
/// algebraically independent is not known.
fn pi_with_constant_angle<C: PointField>(
    spec: &IdentitySpec<C>,
    report: &IdentityReport<C>,
    angles: &Angles,
) -> Option<String> {
    let pi = angles.pi?;
    let IdentityVerdict::Fails {
        coordinate, point, ..
    } = &report.verdict
    else {
        return None;
    };
    let (angle, _) = constant_base(&spec.vars)?;
    let q = crate::phrase::in_constant_angle(spec, *coordinate, point, &angle, Some(pi))?;
    let in_angle = q.degree_in(angle.cos) > 0 || q.degree_in(angle.sin) > 0;
    (in_angle && q.degree_in(pi) > 0).then(|| {
        let u = &angle.name;
        format!(
            "there it is {}, a non-zero polynomial in pi, cos({u}) and sin({u}), and whether pi \
             and cos({u}) + i sin({u}) are algebraically independent is not known",
            q.display(&spec.vars)
        )
    })
}

/// The angles of sin, cos and tan in a statement, and what decides whether its counter-examples
/// are sound ([`sound_counter_example`]).
pub struct Angles {
    /// The angles.
    pub list: Vec<exactcheck_exact::expr::Angle>,
    /// The constant pi, when the statement has it (an indeterminate while deciding: it is
    /// transcendental, so a polynomial identity in it holds iff it holds with pi indeterminate).
    pub pi: Option<Var>,
    /// Whether a relation of the user's involves pi.
    pub pi_in_relations: bool,
    /// The constant angle (`1`), when a relation of the user's or of a square root involves its
    /// cosine or sine.
    pub constant_in_relations: Option<String>,
    /// The angles that are also used as numbers.
    pub mixed: Vec<String>,
}

/// Appends the unit circle `cos(x)^2 + sin(x)^2 = 1` of every angle `x` to `relations` and
/// reports the angles ([`Angles`]); the one setup of `prove` and claims files.
pub fn add_angles<C: PointField>(
    vars: &Vars,
    relations: &mut Vec<(RatFun<C>, RatFun<C>)>,
) -> Angles {
    let list = angles(vars);
    let user_relations = relations.len();
    for a in &list {
        relations.push((
            RatFun::from_poly(a.relation()),
            RatFun::from_poly(Poly::zero()),
        ));
    }
    let pi = vars.get(PI);
    let pi_in_relations = pi.is_some_and(|p| {
        relations[..user_relations].iter().any(|(a, b)| {
            [a, b]
                .iter()
                .any(|f| f.numerator().degree_in(p) > 0 || f.denominator().degree_in(p) > 0)
        })
    });
    let mixed = list
        .iter()
        .filter_map(|a| angle_variable(&a.name))
        .filter(|x| vars.get(x).is_some())
        .collect();
    let constant_in_relations = constant_base(vars).and_then(|(a, base)| {
        let involved = relations[..user_relations].iter().any(|(f, g)| {
            [f, g].iter().any(|f| {
                [a.cos, a.sin]
                    .iter()
                    .any(|&v| f.numerator().degree_in(v) > 0 || f.denominator().degree_in(v) > 0)
            })
        });
        involved.then(|| base.name())
    });
    Angles {
        list,
        pi,
        pi_in_relations,
        constant_in_relations,
        mixed,
    }
}

#[cfg(test)]
mod tests {
    use super::split_where;

    #[test]
    fn where_lists_split_at_top_level_commas() {
        assert_eq!(split_where("x = 1"), ["x = 1"]);
        assert_eq!(split_where("a >= 0, b > 1/2"), ["a >= 0", "b > 1/2"]);
        assert_eq!(split_where("a, b, c != 0"), ["a != 0", "b != 0", "c != 0"]);
        assert_eq!(
            split_where("0 <= t <= 1, s = [1, 2]"),
            ["0 <= t <= 1", "s = [1, 2]"]
        );
        assert_eq!(split_where("x = binomial(3, 1)"), ["x = binomial(3, 1)"]);
        // A bare name without a shared comparison stays as written (and is refused when parsed).
        assert_eq!(split_where("a, b"), ["a", "b"]);
        assert_eq!(split_where("a, 2 b > 0"), ["a", "2 b > 0"]);
    }
}
