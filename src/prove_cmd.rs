//! `exactcheck prove 'LHS' ['RHS'] [--where 'A = B' | --where 'r > 0' ...] [--random K]`: the
//! user's own polynomial identities.
//!
//! Both sides (and each relation) are parsed in the expression syntax (numbers, `sqrt(k)`,
//! `diff(E, t[, k])`, variables, `+ - * / ^`, parentheses), expanded, and `LHS - RHS` is reduced
//! modulo the relations (unit circles `c^2 + s^2 = 1` in closed form, others by a Gröbner
//! basis); see `exactcheck_exact::prove`. With a division by a non-constant anywhere, the sides
//! are rational functions (`Expr::to_ratfun`): the identity is decided with the denominators
//! cleared (`prove::decide_fraction`), and the divisors met are reported as side conditions. A `--where` with `<`, `<=`, `>` or `>=` is a domain (`r > 0`,
//! `0 <= t <= 1`, constant bounds only): counter-examples are searched inside the domains.
//! Inconsistent relations (`1 = 2`; `x = 1` and `x = 2`) are an input error. `--random K`
//! evaluates instead at K random points modulo a prime drawn at random per run
//! (`exactcheck_exact::prove::random`, which proves the printed error bound). Exit status:
//! 0 proved or holds, 1 fails or undecided, 2 bad input. An identity between constants whose
//! nested square roots do not denest (`sqrt(2 + sqrt(2))`) is decided in the real algebraic
//! numbers (`exactcheck_exact::algebraic`).

use crate::Error;
use clap::Args;
use exactcheck_core::Ring;
use exactcheck_exact::expr::{parse_expr, Coefficient, Expr, ExprError};
use exactcheck_exact::poly::{Poly, Var, Vars};
use exactcheck_exact::prove::{
    counter_example, decide_fraction, decide_in, real_zero_free, where_clause, DecideError,
    Decision, Domain, FractionIdentity, PointField, HOLDS_THRESHOLD_LOG2, MAX_RANDOM_TRIALS,
};
use exactcheck_exact::ratfun::RatFun;
use exactcheck_exact::{Algebraic, Radical, Rational};
use serde_json::json;
use std::fmt::Display;
use std::process::ExitCode;

/// Arguments of `exactcheck prove`.
#[derive(Debug, Args)]
pub struct ProveArgs {
    /// The left-hand side (a leading minus is part of the expression: '-x^2').
    #[arg(allow_hyphen_values = true)]
    pub lhs: String,
    /// The right-hand side (default 0).
    #[arg(allow_hyphen_values = true)]
    pub rhs: Option<String>,
    /// A relation `A = B` the variables satisfy, e.g. `c^2 + s^2 = 1`, or a domain with constant
    /// bounds, e.g. `r > 0`, `0 <= t <= 1`, `R >= 1/2` (repeatable; one domain per variable).
    /// Inconsistent relations are an error.
    #[arg(long = "where", value_name = "RELATION", allow_hyphen_values = true)]
    pub relations: Vec<String>,
    /// Instead of expanding, evaluate both sides at K random points (1 to 100000) modulo a prime
    /// drawn at random from [2^62, 2^63) for this run: `fails` at a non-zero point, `holds`
    /// when the proved error bound is below 2^-30, else `undecided` with the bound. Relations
    /// must be unit circles `c^2 + s^2 = 1`; no domains, no sqrt.
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

/// A `--where` argument (or a claims file's `where` entry): a relation or a domain.
pub enum Where {
    /// `A = B`.
    Relation(Expr, Expr),
    /// A variable's bounds.
    Domain(String, Domain),
}

/// Parses `--where #i` (`what` names it): `A = B`, or a chain `a < v`, `v >= a`, `a <= v < b`
/// with a variable `v` and constants `a`, `b`.
fn parse_where(text: &str, what: &str) -> Result<Where, Error> {
    parse_where_with(text, what, &parse)
}

/// [`parse_where`] with the expression parser given (the claims files resolve their
/// definitions and functions in it): `parse(text, what)`.
///
/// # Errors
/// [`Error::Input`] naming `what` for a malformed relation or domain.
pub fn parse_where_with(
    text: &str,
    what: &str,
    parse: &dyn Fn(&str, &str) -> Result<Expr, Error>,
) -> Result<Where, Error> {
    // Split at the comparison operators.
    let mut parts = Vec::new();
    let mut ops = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find(['<', '>']) {
        parts.push(&rest[..i]);
        let strict = !rest[i + 1..].starts_with('=');
        ops.push((rest.as_bytes()[i] == b'<', strict));
        rest = &rest[i + if strict { 1 } else { 2 }..];
    }
    parts.push(rest);
    if ops.is_empty() {
        let sides: Vec<&str> = text.split('=').collect();
        if sides.len() != 2 {
            return Err(Error::Input(format!(
                "{what}: {text:?} must have the form 'A = B' (one '='), or a domain such as 'r > 0' or '0 <= t <= 1'"
            )));
        }
        return Ok(Where::Relation(
            parse(sides[0], &format!("{what} left side"))?,
            parse(sides[1], &format!("{what} right side"))?,
        ));
    }
    let bad = |why: &str| {
        Error::Input(format!(
            "{what}: {text:?} is not a domain ({why}); write e.g. 'r > 0', 'R >= 1/2' or '0 <= t <= 1'"
        ))
    };
    if parts.iter().any(|p| p.contains('=')) {
        return Err(bad("'=' mixed with '<' or '>'"));
    }
    if ops.len() > 2 || (ops.len() == 2 && ops[0].0 != ops[1].0) {
        return Err(bad("at most two bounds, both '<' or both '>'"));
    }
    let exprs = parts
        .iter()
        .map(|p| parse(p, what))
        .collect::<Result<Vec<Expr>, Error>>()?;
    let var_at: Vec<usize> = exprs
        .iter()
        .enumerate()
        .filter(|(_, e)| matches!(e.kind, exactcheck_exact::expr::ExprKind::Var(_)))
        .map(|(i, _)| i)
        .collect();
    let vi = match (var_at.as_slice(), ops.len()) {
        ([i], 1) => *i,
        ([1], 2) => 1,
        _ => {
            return Err(bad(
                "one side must be a single variable, the other(s) constants",
            ))
        }
    };
    let exactcheck_exact::expr::ExprKind::Var(name) = &exprs[vi].kind else {
        unreachable!("vi indexes a variable (var_at holds only variables)")
    };
    let name = name.clone();
    let constant = |e: &Expr| -> Result<Rational, Error> {
        let mut scratch = Vars::new();
        let p = e
            .to_poly::<Rational>(&mut scratch)
            .map_err(|err| Error::Input(format!("{what}: {err}")))?;
        if !scratch.is_empty() {
            return Err(bad("bounds must be constants"));
        }
        Ok(p.constant_value()
            .expect("a polynomial without variables is a constant"))
    };
    let mut domain = Domain::all();
    for (k, &(less, strict)) in ops.iter().enumerate() {
        // parts[k] op parts[k + 1].
        let (other, var_left) = if k + 1 == vi {
            (k, false)
        } else {
            (k + 1, true)
        };
        let c = constant(&exprs[other])?;
        // var_left: v op c; else c op v. `less` with v on the left is an upper bound.
        let upper = less == var_left;
        if upper {
            domain.upper = Some((c, strict));
        } else {
            domain.lower = Some((c, strict));
        }
    }
    Ok(Where::Domain(name, domain))
}

/// A fresh seed from the operating system's randomness (the keys of std's `RandomState`).
pub fn fresh_seed() -> u64 {
    use std::hash::{BuildHasher, Hasher};
    let mut h = std::collections::hash_map::RandomState::new().build_hasher();
    h.write_u64(0x5EED);
    h.finish()
}

/// `prove --random K`: randomized identity testing modulo a random prime, no expansion.
fn random_test(
    args: &ProveArgs,
    trials: u64,
    lhs: &Expr,
    rhs: &Expr,
    relations: &[(Expr, Expr)],
    has_domains: bool,
) -> Result<ExitCode, Error> {
    use exactcheck_exact::prove::{random_identity_test, unit_circle_pairs, RandomDecision, Seed};
    let trials = match u32::try_from(trials) {
        Ok(k) if (1..=MAX_RANDOM_TRIALS).contains(&k) => k,
        _ => {
            return Err(Error::Usage(format!(
                "--random takes 1 to {MAX_RANDOM_TRIALS} points, not {trials}"
            )))
        }
    };
    if has_domains {
        return Err(Error::Usage(
            "--random does not take domains ('r > 0'); run without --random".into(),
        ));
    }
    let mut vars = Vars::new();
    let mut rels = Vec::new();
    for (i, (a, b)) in relations.iter().enumerate() {
        let a = to_poly::<Rational>(a, &mut vars, &format!("--where #{}", i + 1))?;
        let b = to_poly::<Rational>(b, &mut vars, &format!("--where #{}", i + 1))?;
        rels.push(a - b);
    }
    let (pairs, others) = unit_circle_pairs(&rels);
    if !others.is_empty() {
        return Err(Error::Usage(
            "--random supports only unit-circle relations 'c^2 + s^2 = 1'".into(),
        ));
    }
    let name = |v: Var| {
        vars.name(v)
            .expect("relation variables are in the table")
            .to_string()
    };
    let circles: Vec<(String, String)> = pairs.iter().map(|&(c, s)| (name(c), name(s))).collect();
    let mut names = Vec::new();
    lhs.collect_variables(&mut names);
    rhs.collect_variables(&mut names);
    let chosen = args.seed.map(Seed::Chosen);
    let seed_of_run = chosen.unwrap_or_else(|| Seed::Fresh(fresh_seed()));
    let seed = seed_of_run.value();
    let decision = random_identity_test(lhs, rhs, &names, &circles, trials, seed_of_run)
        .map_err(Error::Input)?;
    let report = match &decision {
        RandomDecision::Holds { report, .. }
        | RandomDecision::Reproduced { report }
        | RandomDecision::Undecided { report, .. }
        | RandomDecision::Fails { report, .. } => report,
    };
    let method = format!(
        "evaluation at {trials} random points modulo the random prime p = {} (seed {seed}{}{})",
        report.prime,
        if chosen.is_some() { ", chosen" } else { "" },
        if report.redrawn > 0 {
            format!(", {} primes dividing a divisor redrawn", report.redrawn)
        } else {
            String::new()
        }
    );
    let show = |l: f64| {
        if l == f64::NEG_INFINITY {
            "0".to_string()
        } else {
            // Rounded up, so the printed bound is still a bound.
            format!("2^{:.1}", (l * 10.0).ceil() / 10.0)
        }
    };
    let mut log2 = None;
    let (verdict, evidence, code) = match &decision {
        RandomDecision::Holds { bound, log2_bound, .. } => {
            log2 = Some(*log2_bound);
            (
                "holds",
                format!(
                    "LHS - RHS vanishes at all {trials} points; with LHS - RHS = F/D ({bound}), a false identity passes with probability <= {} (below the threshold 2^{HOLDS_THRESHOLD_LOG2})",
                    show(*log2_bound)
                ),
                ExitCode::SUCCESS,
            )
        }
        RandomDecision::Reproduced { .. } => (
            "holds (reproduced)",
            format!(
                "LHS - RHS vanishes at all {trials} points modulo the prime drawn from the chosen seed {seed} and the identity; a chosen seed gives no probability bound (it need not be independent of the identity): run without --seed for a fresh seed and the proved bound"
            ),
            ExitCode::SUCCESS,
        ),
        RandomDecision::Undecided { bound, log2_bound, .. } => {
            log2 = Some(*log2_bound);
            let why = match bound {
                Some(b) => format!(
                    "with LHS - RHS = F/D ({b}) the error bound{} is {}, not below the threshold 2^{HOLDS_THRESHOLD_LOG2}",
                    if chosen.is_some() { " a fresh seed would give" } else { "" },
                    show(*log2_bound)
                ),
                None => "the size and degree bounds of LHS - RHS do not fit in 64 bits, so no error bound can be given".to_string(),
            };
            (
                "undecided",
                format!("LHS - RHS vanishes at all {trials} points, but {why}; use more points (--random up to {MAX_RANDOM_TRIALS}) or exact mode (no --random)"),
                ExitCode::from(1),
            )
        }
        RandomDecision::Fails { point, value, .. } => (
            "fails",
            format!(
                "LHS - RHS = {value} (mod p) at {}, so it is not zero; run without --random for an exact counter-example",
                point.iter().map(|(v, x)| format!("{v} = {x}")).collect::<Vec<_>>().join(", ")
            ),
            ExitCode::from(1),
        ),
    };
    if args.json {
        let mut obj = json!({"verdict": verdict, "method": method, "evidence": evidence,
            "seed": seed, "prime": report.prime});
        if let Some(l) = log2 {
            obj["log2_error_bound"] = if l.is_finite() { json!(l) } else { json!(null) };
        }
        crate::output::println(&obj)?;
    } else {
        crate::output::println(format_args!("{verdict}: {evidence} [{method}]"))?;
    }
    Ok(code)
}

/// The longest value or polynomial the text verdict prints in full.
const SHOWN_CHARS: usize = 2_000;

/// `text` for the one-line text verdict: in full up to [`SHOWN_CHARS`] characters, else its
/// beginning and its length (a counter-example of `(x+y)^5000` is a number of 3,500 digits and
/// a polynomial of 7 MB); `--json` always has the exact text in full.
fn abbreviate(text: String) -> String {
    if text.len() <= SHOWN_CHARS {
        return text;
    }
    let mut cut = SHOWN_CHARS / 2;
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    format!(
        "{}... [{} characters in all; --json shows it in full]",
        &text[..cut],
        text.len()
    )
}

fn parse(text: &str, what: &str) -> Result<Expr, Error> {
    parse_expr(text).map_err(|e| Error::Input(format!("{what}: {e}")))
}

/// Runs `exactcheck prove`.
///
/// # Errors
/// [`Error::Input`] for a malformed expression, relation or domain, a division by zero or by a
/// non-constant, inconsistent relations; [`Error::Usage`] for a bad `--random` request.
pub fn run(args: &ProveArgs) -> Result<ExitCode, Error> {
    let lhs = parse(&args.lhs, "LHS")?;
    let rhs = match &args.rhs {
        Some(r) => Some(parse(r, "RHS")?),
        None => None,
    };
    let mut relations = Vec::new();
    let mut domains: Vec<(String, Domain, String)> = Vec::new();
    for (i, r) in args.relations.iter().enumerate() {
        let what = format!("--where #{}", i + 1);
        match parse_where(r, &what)? {
            Where::Relation(a, b) => relations.push((a, b)),
            Where::Domain(v, d) => {
                if d.is_empty() {
                    return Err(Error::Input(format!("{what}: the domain {r:?} is empty")));
                }
                if domains.iter().any(|(w, _, _)| *w == v) {
                    return Err(Error::Input(format!(
                        "{what}: {v} already has a domain (give both bounds in one, e.g. '0 <= {v} <= 1')"
                    )));
                }
                domains.push((v, d, r.clone()));
            }
        }
    }
    if let Some(k) = args.random {
        let zero = parse("0", "RHS")?;
        return random_test(
            args,
            k,
            &lhs,
            rhs.as_ref().unwrap_or(&zero),
            &relations,
            !domains.is_empty(),
        );
    }
    // Radicals need the radical coefficient field; everything else runs over Q.
    let radical = std::iter::once(&args.lhs)
        .chain(&args.rhs)
        .chain(&args.relations)
        .any(|s| s.contains("sqrt"));
    if radical {
        if relations.is_empty() && domains.is_empty() {
            if let Some(code) = prove_algebraic_constants(args, &lhs, rhs.as_ref())? {
                return Ok(code);
            }
        }
        prove_over::<Radical>(args, &lhs, rhs.as_ref(), &relations, &domains)
    } else {
        prove_over::<Rational>(args, &lhs, rhs.as_ref(), &relations, &domains)
    }
}

/// An identity between constants with a square root the square-root field [`Radical`] refuses
/// (a nested radical that does not denest, such as `sqrt(2 + sqrt(2))`), decided exactly in the
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
    let refused = |e: &Expr| matches!(e.eval_constant::<Radical>(), Err(ExprError::NoSqrt { .. }));
    if !names.is_empty() || !(refused(lhs) || rhs.is_some_and(refused)) {
        return Ok(None);
    }
    let eval = |e: &Expr, what: &str| {
        e.eval_constant::<Algebraic>()
            .map_err(|err| Error::Input(format!("{what}: {err}")))
    };
    let l = eval(lhs, "LHS")?;
    let r = match rhs {
        Some(e) => eval(e, "RHS")?,
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

fn prove_over<C: PointField + Display>(
    args: &ProveArgs,
    lhs: &Expr,
    rhs: Option<&Expr>,
    relations: &[(Expr, Expr)],
    domains: &[(String, Domain, String)],
) -> Result<ExitCode, Error> {
    let mut vars = Vars::new();
    let l = to_ratfun::<C>(lhs, &mut vars, "LHS")?;
    let r = match rhs {
        Some(e) => to_ratfun::<C>(e, &mut vars, "RHS")?,
        None => RatFun::from_poly(Poly::zero()),
    };
    // Relations between fractions are cleared of their denominators, which become
    // hypotheses (non-zero).
    let mut rels = Vec::new();
    let mut hypotheses: Vec<Poly<C>> = Vec::new();
    for (i, (a, b)) in relations.iter().enumerate() {
        let what = format!("--where #{}", i + 1);
        let a = to_ratfun::<C>(a, &mut vars, &what)?;
        let b = to_ratfun::<C>(b, &mut vars, &what)?;
        if a.is_polynomial() && b.is_polynomial() {
            rels.push(a.into_numerator() - b.into_numerator());
        } else {
            let cleared =
                FractionIdentity::new(&a, &b).map_err(|e| Error::Input(format!("{what}: {e}")))?;
            rels.push(cleared.residual);
            hypotheses.extend(cleared.conditions);
        }
    }
    // A polynomial identity takes the polynomial path; fractions are cleared.
    let fraction = if l.is_polynomial() && r.is_polynomial() && hypotheses.is_empty() {
        None
    } else {
        Some(FractionIdentity::new(&l, &r).map_err(|e| Error::Input(format!("LHS - RHS: {e}")))?)
    };
    let mut doms: Vec<(Var, Domain)> = Vec::new();
    for (v, d, text) in domains {
        let var = vars.get(v).ok_or_else(|| {
            Error::Input(format!(
                "--where {text:?}: {v} does not occur in the identity or its relations"
            ))
        })?;
        doms.push((var, d.clone()));
    }
    let name = |v: Var| {
        vars.name(v)
            .expect("the engine reports only variables of the table")
            .to_string()
    };
    let residual = match &fraction {
        None => l.numerator().clone() - r.numerator(),
        Some(f) => f.residual.clone(),
    };
    // The points excluded: the divisors of the sides and of the relations.
    let mut excluded: Vec<Poly<C>> = fraction.iter().flat_map(|f| f.conditions.clone()).collect();
    for h in &hypotheses {
        if !excluded.contains(h) {
            excluded.push(h.clone());
        }
    }
    let (cleared, where_nonzero) = match &fraction {
        None => ("", String::new()),
        Some(_) => (
            " with the denominators cleared",
            where_clause(&excluded, &vars),
        ),
    };
    let conditions: Vec<&str> = args.relations.iter().map(String::as_str).collect();
    let modulo = if relations.is_empty() {
        String::new()
    } else {
        let rel_texts: Vec<&str> = conditions
            .iter()
            .copied()
            .filter(|t| !t.contains(['<', '>']))
            .collect();
        format!(" modulo {}", rel_texts.join(", "))
    };
    let within = if domains.is_empty() {
        String::new()
    } else {
        let d: Vec<&str> = domains.iter().map(|(_, _, t)| t.as_str()).collect();
        format!(" for {}", d.join(", "))
    };
    let decision = match &fraction {
        None => decide_in(&residual, &rels, &doms, vars.len()),
        Some(f) => decide_fraction(f, &rels, &hypotheses, &doms, vars.len()),
    }
    .map_err(|e| match e {
        DecideError::Inconsistent => Error::Input(format!(
            "--where: the relations {} are inconsistent (their Groebner basis contains a non-zero constant): no point satisfies them, so nothing can be proved from them",
            modulo.trim_start_matches(" modulo ")
        )),
        DecideError::EmptyDomain(v) => Error::Input(format!("--where: the domain of {} is empty", name(v))),
        DecideError::DuplicateDomain(v) => Error::Input(format!("--where: {} has two domains", name(v))),
        DecideError::UnknownVariable(v) => Error::Input(format!("--where: a domain names variable #{v}, which is not in use")),
        // The limits of a Groebner basis of the relations: say which part of the command.
        DecideError::Limit(e) => Error::Input(format!("--where: {e}")),
    })?;
    let (verdict, code) = match &decision {
        Decision::Proved { .. } => ("proved", ExitCode::SUCCESS),
        Decision::Fails { .. } => ("fails", ExitCode::from(1)),
        Decision::Undecided { .. } => ("undecided", ExitCode::from(1)),
    };
    let terms = residual.len();
    // A counter-example gives every variable of both sides, the relations and the excluded
    // denominators (domains name only those), also those that cancel from the residual.
    let statement: Vec<&Poly<C>> = [
        l.numerator(),
        l.denominator(),
        r.numerator(),
        r.denominator(),
    ]
    .into_iter()
    .chain(&rels)
    .chain(&excluded)
    .collect();
    let evidence = match &decision {
        Decision::Proved { expanded_terms } if *expanded_terms == 0 => {
            format!("LHS - RHS{cleared} expands to 0{where_nonzero}")
        }
        Decision::Proved { expanded_terms } => {
            format!("LHS - RHS{cleared} expands to {expanded_terms} terms, which reduce to 0{modulo}{where_nonzero}")
        }
        Decision::Fails {
            normal_form,
            point,
            value,
        } => {
            let at: Vec<String> = counter_example(point, &statement)
                .iter()
                .map(|(v, q)| format!("{} = {q}", name(*v)))
                .collect();
            let value = abbreviate(value.to_string());
            let nf = abbreviate(normal_form.display(&vars).to_string());
            if fraction.is_some() {
                // `LHS - RHS` is the normal form over the cleared denominator.
                format!(
                    "at {}{} LHS - RHS = {value}; LHS - RHS{cleared} reduces{modulo} to {nf}, not zero{where_nonzero}",
                    abbreviate(at.join(", ")),
                    if relations.is_empty() { "" } else { " (where the relations hold)" },
                )
            } else if at.is_empty() {
                // No variable: the identity is between constants, and their difference is the
                // counter-example (old: "at  LHS - RHS = ...", an empty point).
                format!(
                    "LHS - RHS = {value}, a non-zero constant{}, so LHS = RHS + ({nf})",
                    if relations.is_empty() { "" } else { " (where the relations hold)" },
                )
            } else {
                format!(
                    "at {}{} LHS - RHS = {value}; LHS - RHS reduces{modulo} to {nf}, so LHS = RHS + ({nf})",
                    abbreviate(at.join(", ")),
                    if relations.is_empty() { "" } else { " (where the relations hold)" },
                )
            }
        }
        Decision::Undecided {
            normal_form,
            searched,
        } => format!(
            "LHS - RHS{cleared} reduces{modulo} to {} (not zero), but no point{within} where it is non-zero was found{where_nonzero}: {searched}",
            abbreviate(normal_form.display(&vars).to_string())
        ),
    };
    if args.json {
        let mut obj = json!({
            "verdict": verdict,
            "method": format!("symbolic expansion over {}[{}]{modulo}{within}", if std::any::type_name::<C>().contains("Radical") { "Q(sqrt)" } else { "Q" }, vars.names().join(",")),
            "evidence": evidence,
            "residual_terms": terms,
        });
        if fraction.is_some() {
            obj["conditions"] = excluded
                .iter()
                .map(|p| json!({"nonzero": p.display(&vars).to_string(), "real_zero_free": real_zero_free(p) == Some(true)}))
                .collect::<Vec<_>>()
                .into();
        }
        if let Decision::Fails {
            point,
            value,
            normal_form,
        } = &decision
        {
            obj["point"] = counter_example(point, &statement)
                .iter()
                .map(|(v, q)| (name(*v), json!(q.to_string())))
                .collect::<serde_json::Map<_, _>>()
                .into();
            obj["value"] = json!(value.to_string());
            obj["normal_form"] = json!(normal_form.display(&vars).to_string());
        }
        crate::output::println(&obj)?;
    } else {
        crate::output::println(format_args!("{verdict}: {evidence}"))?;
    }
    Ok(code)
}
