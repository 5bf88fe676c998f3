//! `prove --random K`: the identity evaluated at random points modulo a random prime
//! (`exactcheck_exact::prove::random`), one test per component of a vector or matrix identity.

use super::{fresh_seed, to_poly, ProveArgs};
use crate::Error;
use exactcheck_exact::expr::library::Shape;
use exactcheck_exact::expr::Expr;
use exactcheck_exact::poly::{Var, Vars};
use exactcheck_exact::prove::{HOLDS_THRESHOLD_LOG2, MAX_RANDOM_TRIALS};
use exactcheck_exact::Rational;
use serde_json::json;
use std::process::ExitCode;

/// `prove --random K`: randomized identity testing modulo a random prime, no expansion.
pub(super) fn random_test(
    args: &ProveArgs,
    trials: u64,
    (lhs, rhs, shape): (&[Expr], &[Expr], Shape),
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
    for e in lhs.iter().chain(rhs) {
        e.collect_variables(&mut names);
    }
    let chosen = args.seed.map(Seed::Chosen);
    let seed_of_run = chosen.unwrap_or_else(|| Seed::Fresh(fresh_seed()));
    let seed = seed_of_run.value();
    // One test per component, each with its own prime (drawn from the seed and the component's
    // identity). The verdict shown is the first failing component's, else the first undecided
    // one's, else the component with the weakest bound (a false identity has a false component,
    // which passes with at most its own bound).
    let mut decisions = Vec::new();
    for (k, (l, r)) in lhs.iter().zip(rhs).enumerate() {
        let d = random_identity_test(l, r, &names, &circles, trials, seed_of_run).map_err(|e| {
            Error::Input(match shape {
                Shape::Scalar => e,
                s => format!("{}: {e}", s.component(k)),
            })
        })?;
        decisions.push(d);
    }
    let rank = |d: &RandomDecision| match d {
        RandomDecision::Fails { .. } => (3, 0.0),
        RandomDecision::Undecided { log2_bound, .. } => (2, *log2_bound),
        RandomDecision::Holds { log2_bound, .. } => (1, *log2_bound),
        RandomDecision::Reproduced { .. } => (0, 0.0),
    };
    let shown = (0..decisions.len())
        .max_by(|&a, &b| {
            let (ra, la) = rank(&decisions[a]);
            let (rb, lb) = rank(&decisions[b]);
            // The first of equals: a later component wins only when strictly worse.
            ra.cmp(&rb).then(la.total_cmp(&lb)).then(b.cmp(&a))
        })
        .expect("an identity has at least one component");
    let decision = &decisions[shown];
    let report = match decision {
        RandomDecision::Holds { report, .. }
        | RandomDecision::Reproduced { report }
        | RandomDecision::Undecided { report, .. }
        | RandomDecision::Fails { report, .. } => report,
    };
    let primes: Vec<u64> = decisions
        .iter()
        .map(|d| match d {
            RandomDecision::Holds { report, .. }
            | RandomDecision::Reproduced { report }
            | RandomDecision::Undecided { report, .. }
            | RandomDecision::Fails { report, .. } => report.prime,
        })
        .collect();
    let (prime_text, prefix) = match shape {
        Shape::Scalar => (
            format!("the random prime p = {}", report.prime),
            String::new(),
        ),
        s => {
            let undecided: Vec<String> = (0..decisions.len())
                .filter(|&k| matches!(decisions[k], RandomDecision::Undecided { .. }))
                .map(|k| s.component(k))
                .collect();
            (
                format!(
                    "random primes, one per component ({}; p = {} in {})",
                    primes
                        .iter()
                        .map(u64::to_string)
                        .collect::<Vec<_>>()
                        .join(", "),
                    report.prime,
                    s.component(shown)
                ),
                match decision {
                    RandomDecision::Fails { .. } => format!("in {}: ", s.component(shown)),
                    RandomDecision::Undecided { .. } => {
                        format!("undecided in {}: ", undecided.join(", "))
                    }
                    _ => format!("in each of the {} components: ", s.len()),
                },
            )
        }
    };
    let method = format!(
        "evaluation at {trials} random points modulo {prime_text} (seed {seed}{}{}{})",
        if chosen.is_some() { ", chosen" } else { "" },
        if report.redrawn > 0 {
            format!(", {} primes dividing a divisor redrawn", report.redrawn)
        } else {
            String::new()
        },
        if report.poles > 0 {
            format!(", {} points where a divisor vanishes skipped", report.poles)
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
    let (verdict, evidence, code) = match decision {
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
    let evidence = format!("{prefix}{evidence}");
    if args.json {
        let mut obj = json!({"verdict": verdict, "method": method, "evidence": evidence,
            "seed": seed, "prime": report.prime});
        if shape != Shape::Scalar {
            obj["shape"] = json!(shape.to_string());
            obj["components"] = decisions
                .iter()
                .enumerate()
                .map(|(k, d)| {
                    let (verdict, log2) = match d {
                        RandomDecision::Holds { log2_bound, .. } => ("holds", Some(*log2_bound)),
                        RandomDecision::Reproduced { .. } => ("holds (reproduced)", None),
                        RandomDecision::Undecided { log2_bound, .. } => {
                            ("undecided", Some(*log2_bound))
                        }
                        RandomDecision::Fails { .. } => ("fails", None),
                    };
                    let mut c = json!({"component": shape.component(k), "verdict": verdict,
                        "prime": primes[k]});
                    if let Some(l) = log2 {
                        c["log2_error_bound"] = if l.is_finite() { json!(l) } else { json!(null) };
                    }
                    c
                })
                .collect::<Vec<_>>()
                .into();
        }
        if let Some(l) = log2 {
            obj["log2_error_bound"] = if l.is_finite() { json!(l) } else { json!(null) };
        }
        crate::output::println(&obj)?;
    } else {
        crate::output::println(format_args!("{verdict}: {evidence} [{method}]"))?;
    }
    Ok(code)
}
