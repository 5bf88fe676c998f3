//! `exactcheck prove 'LHS' ['RHS'] [--where 'A = B' ...]`: the user's own polynomial identities.
//!
//! Both sides (and each relation) are parsed in the expression syntax (numbers, `sqrt(k)`,
//! variables, `+ - * / ^`, parentheses), expanded, and `LHS - RHS` is reduced modulo the
//! relations (unit circles `c^2 + s^2 = 1` in closed form, others by a Gröbner basis). Exit
//! status: 0 proved, 1 fails or undecided, 2 bad input.

use crate::Error;
use clap::Args;
use exactcheck_core::Field;
use exactcheck_exact::expr::{parse_expr, Coefficient, Expr};
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::prove::{decide, Decision};
use exactcheck_exact::{Radical, Rational};
use serde_json::json;
use std::fmt::Display;
use std::process::ExitCode;

/// Arguments of `exactcheck prove`.
#[derive(Debug, Args)]
pub struct ProveArgs {
    /// The left-hand side.
    pub lhs: String,
    /// The right-hand side (default 0).
    pub rhs: Option<String>,
    /// A relation `A = B` the variables satisfy (repeatable), e.g. `c^2 + s^2 = 1`.
    #[arg(long = "where", value_name = "RELATION")]
    pub relations: Vec<String>,
    /// Instead of expanding, evaluate both sides at K random points modulo the prime
    /// 2^61 - 1 (fast on huge expressions): `holds` with the Schwartz-Zippel error bound, or
    /// `fails`. Relations must be unit circles `c^2 + s^2 = 1`.
    #[arg(long, value_name = "K")]
    pub random: Option<u32>,
    /// Seed of the random points of `--random`.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

fn collect_vars(e: &Expr, out: &mut Vec<String>) {
    use exactcheck_exact::expr::ExprKind;
    match &e.kind {
        ExprKind::Number(_) => {}
        ExprKind::Var(v) => {
            if !out.contains(v) {
                out.push(v.clone());
            }
        }
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => collect_vars(x, out),
        ExprKind::Pow(a, b) => {
            collect_vars(a, out);
            collect_vars(b, out);
        }
        ExprKind::Sum(ts) => ts.iter().for_each(|(_, t)| collect_vars(t, out)),
        ExprKind::Product(fs) => fs.iter().for_each(|(_, f)| collect_vars(f, out)),
    }
}

/// `prove --random K`: randomized identity testing modulo p, no expansion.
fn random_test(
    args: &ProveArgs,
    trials: u32,
    lhs: &Expr,
    rhs: &Expr,
    relations: &[(Expr, Expr)],
) -> Result<ExitCode, Error> {
    use exactcheck_exact::prove::{random_identity_test, unit_circle_pairs, RandomDecision};
    if trials == 0 {
        return Err(Error::Usage("--random needs at least 1 point".into()));
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
    let name = |v| vars.name(v).unwrap_or("?").to_string();
    let circles: Vec<(String, String)> = pairs.iter().map(|&(c, s)| (name(c), name(s))).collect();
    let mut names = Vec::new();
    collect_vars(lhs, &mut names);
    collect_vars(rhs, &mut names);
    let decision = random_identity_test(lhs, rhs, &names, &circles, trials, args.seed)
        .map_err(Error::Input)?;
    let method = format!(
        "evaluation at {trials} random points modulo 2^61 - 1 (seed {})",
        args.seed
    );
    let (verdict, evidence, code) = match &decision {
        RandomDecision::Holds { degree, log2_bound, .. } => (
            "holds",
            format!("LHS - RHS vanishes at all {trials} points; total degree <= {degree}, so a false identity passes with probability <= 2^{log2_bound:.1}"),
            ExitCode::SUCCESS,
        ),
        RandomDecision::Fails { point, value } => (
            "fails",
            format!(
                "LHS - RHS = {value} (mod p) at {}; run without --random for an exact counter-example",
                point.iter().map(|(v, x)| format!("{v} = {x}")).collect::<Vec<_>>().join(", ")
            ),
            ExitCode::from(1),
        ),
    };
    if args.json {
        println!(
            "{}",
            json!({"verdict": verdict, "method": method, "evidence": evidence})
        );
    } else {
        println!("{verdict}: {evidence} [{method}]");
    }
    Ok(code)
}

fn parse(text: &str, what: &str) -> Result<Expr, Error> {
    parse_expr(text).map_err(|e| Error::Input(format!("{what}: {e}")))
}

/// Runs `exactcheck prove`.
///
/// # Errors
/// [`Error::Input`] for a malformed expression or relation, a division by zero or by a
/// non-constant.
pub fn run(args: &ProveArgs) -> Result<ExitCode, Error> {
    let lhs = parse(&args.lhs, "LHS")?;
    let rhs = match &args.rhs {
        Some(r) => Some(parse(r, "RHS")?),
        None => None,
    };
    let mut relations = Vec::new();
    for (i, r) in args.relations.iter().enumerate() {
        let parts: Vec<&str> = r.split('=').collect();
        if parts.len() != 2 {
            return Err(Error::Input(format!(
                "--where #{}: {r:?} must have the form 'A = B' (one '=')",
                i + 1
            )));
        }
        relations.push((
            parse(parts[0], &format!("--where #{} left side", i + 1))?,
            parse(parts[1], &format!("--where #{} right side", i + 1))?,
        ));
    }
    if let Some(k) = args.random {
        let zero = parse("0", "RHS")?;
        return random_test(args, k, &lhs, rhs.as_ref().unwrap_or(&zero), &relations);
    }
    // Radicals need the radical coefficient field; everything else runs over Q.
    let radical = std::iter::once(&args.lhs)
        .chain(&args.rhs)
        .chain(&args.relations)
        .any(|s| s.contains("sqrt"));
    if radical {
        prove_over::<Radical>(args, &lhs, rhs.as_ref(), &relations)
    } else {
        prove_over::<Rational>(args, &lhs, rhs.as_ref(), &relations)
    }
}

fn to_poly<C: Coefficient>(e: &Expr, vars: &mut Vars, what: &str) -> Result<Poly<C>, Error> {
    e.to_poly::<C>(vars)
        .map_err(|err| Error::Input(format!("{what}: {err}")))
}

fn prove_over<C: Field + Coefficient + Display>(
    args: &ProveArgs,
    lhs: &Expr,
    rhs: Option<&Expr>,
    relations: &[(Expr, Expr)],
) -> Result<ExitCode, Error> {
    let mut vars = Vars::new();
    let l = to_poly::<C>(lhs, &mut vars, "LHS")?;
    let r = match rhs {
        Some(e) => to_poly::<C>(e, &mut vars, "RHS")?,
        None => Poly::zero(),
    };
    let mut rels = Vec::new();
    for (i, (a, b)) in relations.iter().enumerate() {
        let a = to_poly::<C>(a, &mut vars, &format!("--where #{}", i + 1))?;
        let b = to_poly::<C>(b, &mut vars, &format!("--where #{}", i + 1))?;
        rels.push(a - b);
    }
    let residual = l - r;
    let modulo = if args.relations.is_empty() {
        String::new()
    } else {
        format!(" modulo {}", args.relations.join(", "))
    };
    let decision = decide(&residual, &rels, vars.len());
    let (verdict, code) = match &decision {
        Decision::Proved { .. } => ("proved", ExitCode::SUCCESS),
        Decision::Fails { .. } => ("fails", ExitCode::from(1)),
        Decision::Undecided { .. } => ("undecided", ExitCode::from(1)),
    };
    let terms = residual.len();
    let evidence = match &decision {
        Decision::Proved { expanded_terms } if *expanded_terms == 0 => {
            "LHS - RHS expands to 0".to_string()
        }
        Decision::Proved { expanded_terms } => {
            format!("LHS - RHS expands to {expanded_terms} terms, which reduce to 0{modulo}")
        }
        Decision::Fails { normal_form, point, value } => {
            let at: Vec<String> = point
                .iter()
                .filter(|(v, _)| residual.variables().contains(v) || rels.iter().any(|r| r.variables().contains(v)))
                .map(|(v, q)| format!("{} = {q}", vars.name(*v).unwrap_or("?")))
                .collect();
            format!(
                "at {} LHS - RHS = {value}; LHS - RHS reduces{modulo} to {}, so LHS = RHS + ({})",
                at.join(", "),
                normal_form.display(&vars),
                normal_form.display(&vars)
            )
        }
        Decision::Undecided { normal_form } => format!(
            "LHS - RHS reduces{modulo} to {} (not zero), but no point satisfying the relations was found where it is non-zero",
            normal_form.display(&vars)
        ),
    };
    if args.json {
        let mut obj = json!({
            "verdict": verdict,
            "method": format!("symbolic expansion over {}[{}]{}", if std::any::type_name::<C>().contains("Radical") { "Q(sqrt)" } else { "Q" }, vars.names().join(","), modulo),
            "evidence": evidence,
            "residual_terms": terms,
        });
        if let Decision::Fails {
            point,
            value,
            normal_form,
        } = &decision
        {
            obj["point"] = point
                .iter()
                .map(|(v, q)| {
                    (
                        vars.name(*v).unwrap_or("?").to_string(),
                        json!(q.to_string()),
                    )
                })
                .collect::<serde_json::Map<_, _>>()
                .into();
            obj["value"] = json!(value.to_string());
            obj["normal_form"] = json!(normal_form.display(&vars).to_string());
        }
        println!("{obj}");
    } else {
        println!("{verdict}: {evidence}");
    }
    Ok(code)
}
