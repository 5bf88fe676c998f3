//! `prove --random K`: the identity evaluated at random points modulo a random prime
//! (`exactcheck_exact::prove::random`), one test per component of a vector or matrix identity.

use super::{fresh_seed, to_poly, ProveArgs};
use crate::claims::Verdict;
use crate::phrase::random::random_fields;
use crate::phrase::{phrase_random, RandomOptions};
use crate::Error;
use exactcheck_exact::expr::library::Shape;
use exactcheck_exact::expr::Expr;
use exactcheck_exact::poly::{Var, Vars};
use exactcheck_exact::prove::MAX_RANDOM_TRIALS;
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
    use exactcheck_exact::prove::{random_identity_test, unit_circle_pairs, Seed};
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
    // One test per component, each with its own prime (drawn from the seed and the component's
    // identity); the shown component is chosen by the formatter.
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
    let labels: Vec<String> = match shape {
        Shape::Scalar => Vec::new(),
        s => (0..s.len()).map(|k| s.component(k)).collect(),
    };
    let phrased = phrase_random(
        &decisions,
        &labels,
        trials,
        seed_of_run,
        &RandomOptions {
            fresh_seed: "run without --seed",
            points: "--random",
            otherwise: " or exact mode (no --random)",
            exact_counter_example: "; run without --random for an exact counter-example",
        },
    );
    let code = match phrased.verdict {
        Verdict::Proved | Verdict::Holds => ExitCode::SUCCESS,
        Verdict::Fails | Verdict::Undecided => ExitCode::from(1),
    };
    let (verdict, evidence, method) = (phrased.verdict_text, &phrased.evidence, &phrased.method);
    if args.json {
        let mut obj = serde_json::Map::new();
        obj.insert("verdict".into(), json!(verdict));
        obj.insert("method".into(), json!(method));
        obj.insert("evidence".into(), json!(evidence));
        obj.extend(random_fields(&phrased, &decisions, shape, seed_of_run));
        crate::output::println(serde_json::Value::Object(obj))?;
    } else {
        crate::output::println(format_args!("{verdict}: {evidence} [{method}]"))?;
    }
    Ok(code)
}
