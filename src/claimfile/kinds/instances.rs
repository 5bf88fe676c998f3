//! `instances` claims: exact evaluation at given instances and evaluation at random points
//! modulo a random prime (as `prove --random`).

use super::*;
use exactcheck_exact::Algebraic;

pub(super) fn instances(check: &Check) -> Result<Outcome, Fault> {
    let Check::Instances {
        shape,
        lhs,
        rhs,
        conditions,
        random,
        seed,
        at,
    } = check
    else {
        unreachable!("instances() is called for instances claims")
    };
    let mut names = Vec::new();
    for e in lhs.iter().chain(rhs) {
        e.collect_variables(&mut names);
    }
    for (a, b) in &conditions.relations {
        a.collect_variables(&mut names);
        b.collect_variables(&mut names);
    }
    // `pi` is the constant, not a variable an instance gives a value to.
    names.retain(|n| n != exactcheck_exact::expr::PI);
    // Constants outside the square-root field (`cos(pi/5)`) are evaluated as real algebraic
    // numbers, as `prove` evaluates an identity between constants.
    let algebraic = crate::prove_cmd::constants::any_needs_constants(
        lhs.iter()
            .chain(rhs)
            .chain(conditions.relations.iter().flat_map(|(a, b)| [a, b])),
    );
    // Exact instances: independent, so checked in parallel, then read in order (the first
    // instance with a fault of the file or a non-zero residual is the one reported, as when
    // they ran one after another).
    let instance = |k: usize, point: &Vec<(String, Expr)>| -> Result<Option<Outcome>, Fault> {
        let missing: Vec<&String> = names
            .iter()
            .filter(|n| !point.iter().any(|(v, _)| v == *n))
            .collect();
        if !missing.is_empty() {
            return Err(Fault::Input(
                "at",
                format!(
                    "instance {} gives no value to {}",
                    k + 1,
                    missing
                        .iter()
                        .map(|s| s.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            ));
        }
        // `a - b` at the instance: `None` when it is zero, else its exact value.
        let difference_at = |a: &Expr, b: &Expr| -> Result<Option<String>, Fault> {
            // The substitution respects the binders of diff, integrate and sum (a `diff` in a
            // substituted variable is taken first); what remains is lowered and evaluated.
            let at = |e: &Expr| -> Result<Expr, Fault> {
                let mut x = e.clone();
                for (v, val) in point {
                    x = defs::substitute_free(&x, v, val)
                        .map_err(|why| Fault::Input("at", format!("instance {}: {why}", k + 1)))?;
                }
                Ok(x)
            };
            let bad = |err: exactcheck_exact::expr::ExprError| {
                Fault::Input("at", format!("instance {}: {err}", k + 1))
            };
            let (a, b) = (at(a)?, at(b)?);
            Ok(if algebraic {
                let d = exactcheck_exact::expr::eval_lowered::<Algebraic>(&a).map_err(bad)?
                    - exactcheck_exact::expr::eval_lowered::<Algebraic>(&b).map_err(bad)?;
                (!d.is_zero()).then(|| d.to_string())
            } else {
                let d = exactcheck_exact::expr::eval_lowered::<Radical>(&a)
                    .map_err(bad)?
                    .sub_ref(&exactcheck_exact::expr::eval_lowered::<Radical>(&b).map_err(bad)?);
                (!d.is_zero()).then(|| d.to_string())
            })
        };
        for (i, (a, b)) in conditions.relations.iter().enumerate() {
            if difference_at(a, b)?.is_some() {
                return Err(Fault::Input(
                    "at",
                    format!(
                        "instance {} does not satisfy the relation {:?}",
                        k + 1,
                        conditions.relation_texts[i]
                    ),
                ));
            }
        }
        for (c, (l, r)) in lhs.iter().zip(rhs).enumerate() {
            if let Some(d) = difference_at(l, r)? {
                let coords = if lhs.len() == 1 {
                    String::new()
                } else {
                    format!(" (in {})", shape.component(c))
                };
                let shown: Vec<String> = point.iter().map(|(v, x)| format!("{v} = {x}")).collect();
                let erratum = Erratum {
                    printed: vec![Equation {
                        lhs: l.clone(),
                        rhs: r.clone(),
                    }],
                    correction: format!("LHS - RHS = {d} at instance {}", k + 1),
                    counter_example: point
                        .iter()
                        .map(|(v, x)| Equation {
                            lhs: var(v),
                            rhs: x.clone(),
                        })
                        .collect(),
                    // A value with no radical form (`Root(...)`) is in the correction only.
                    residual: value_expr(&d)
                        .map(|v| {
                            vec![Equation {
                                lhs: difference(l, r),
                                rhs: v,
                            }]
                        })
                        .unwrap_or_default(),
                    ..Erratum::default()
                };
                return Ok(Some(Outcome {
                    verdict: Verdict::Fails,
                    method: "exact evaluation at the given instances".into(),
                    evidence: format!(
                        "at instance {} ({}) LHS - RHS = {d}{coords}, not zero",
                        k + 1,
                        shown.join(", ")
                    ),
                    erratum: Some(Box::new(erratum)),
                }));
            }
        }
        Ok(None)
    };
    let found: Vec<Result<Option<Outcome>, Fault>> = at
        .par_iter()
        .enumerate()
        .map(|(k, point)| instance(k, point))
        .collect();
    for f in found {
        if let Some(outcome) = f? {
            return Ok(outcome);
        }
    }
    let exact_note = if at.is_empty() {
        String::new()
    } else {
        format!("LHS - RHS is exactly 0 at all {} given instances", at.len())
    };
    let Some(trials) = *random else {
        return Ok(Outcome {
            verdict: Verdict::Holds,
            method: "exact evaluation at the given instances".into(),
            evidence: exact_note,
            erratum: None,
        });
    };
    // Random evaluation modulo a random prime (prove --random).
    let mut vars = Vars::new();
    let mut rels = Vec::new();
    for (a, b) in &conditions.relations {
        rels.push(
            to_poly::<Rational>(a, &mut vars, "where")?
                - to_poly::<Rational>(b, &mut vars, "where")?,
        );
    }
    let (pairs, others) = unit_circle_pairs(&rels);
    if !others.is_empty() {
        return Err(Fault::Input(
            "where",
            "random evaluation supports only unit-circle relations 'c^2 + s^2 = 1'".into(),
        ));
    }
    let vname = |v: Var| {
        vars.name(v)
            .expect("relation variables are in the table")
            .to_string()
    };
    let circles: Vec<(String, String)> = pairs.iter().map(|&(c, s)| (vname(c), vname(s))).collect();
    let seed_of_run = match seed {
        Some(s) => Seed::Chosen(*s),
        None => Seed::Fresh(crate::prove_cmd::fresh_seed()),
    };
    let seed = seed_of_run.value();
    let chosen = if matches!(seed_of_run, Seed::Chosen(_)) {
        ", chosen"
    } else {
        ""
    };
    let show = |l: f64| {
        if l == f64::NEG_INFINITY {
            "0".to_string()
        } else {
            format!("2^{:.1}", (l * 10.0).ceil() / 10.0)
        }
    };
    let mut worst = f64::NEG_INFINITY;
    let mut primes = Vec::new();
    let mut undecided = None;
    let mut reproduced = false;
    // The coordinates are tested in parallel and read in order; each has its own prime (drawn
    // from the seed and the coordinate's identity).
    let decisions: Vec<Result<RandomDecision, String>> = lhs
        .par_iter()
        .zip(rhs.par_iter())
        .map(|(l, r)| random_identity_test(l, r, &names, &circles, trials, seed_of_run))
        .collect();
    for (c, ((l, r), d)) in lhs.iter().zip(rhs).zip(decisions).enumerate() {
        let d = d.map_err(|e| Fault::Input("lhs", e))?;
        let coords = if lhs.len() == 1 {
            String::new()
        } else {
            format!(" (in {})", shape.component(c))
        };
        match d {
            RandomDecision::Holds {
                report, log2_bound, ..
            } => {
                primes.push(report.prime);
                worst = worst.max(log2_bound);
            }
            RandomDecision::Reproduced { report } => {
                primes.push(report.prime);
                reproduced = true;
            }
            RandomDecision::Undecided {
                report, log2_bound, ..
            } => {
                primes.push(report.prime);
                worst = worst.max(log2_bound);
                undecided.get_or_insert(coords);
            }
            RandomDecision::Fails {
                report,
                point,
                value,
            } => {
                let at: Vec<String> = point.iter().map(|(v, x)| format!("{v} = {x}")).collect();
                let erratum = Erratum {
                    printed: vec![Equation {
                        lhs: l.clone(),
                        rhs: r.clone(),
                    }],
                    correction: format!(
                        "LHS - RHS = {value} (mod p = {}) at {}: not zero modulo p, so not zero over Q",
                        report.prime,
                        at.join(", ")
                    ),
                    ..Erratum::default()
                };
                return Ok(Outcome {
                    verdict: Verdict::Fails,
                    method: format!(
                        "evaluation at {trials} random points modulo the random prime p = {} (seed {seed}{chosen})",
                        report.prime
                    ),
                    evidence: format!(
                        "LHS - RHS = {value} (mod p) at {}{coords}, so it is not zero{}",
                        at.join(", "),
                        if exact_note.is_empty() { String::new() } else { format!("; {exact_note}") }
                    ),
                    erratum: Some(Box::new(erratum)),
                });
            }
        }
    }
    let primes = match primes.as_slice() {
        [p] => format!("the random prime p = {p}"),
        many => format!(
            "random primes ({}, one per coordinate)",
            many.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    let method = format!(
        "evaluation at {trials} random points modulo {primes} (seed {seed}{chosen}){}",
        if at.is_empty() {
            ""
        } else {
            " and exact instances"
        }
    );
    let extra = if exact_note.is_empty() {
        String::new()
    } else {
        format!("; {exact_note}")
    };
    Ok(match undecided {
        None if reproduced => Outcome {
            verdict: Verdict::Holds,
            method,
            evidence: format!(
                "LHS - RHS vanishes at all {trials} points modulo the prime drawn from the chosen seed {seed} and the identity (a reproduced run); a chosen seed gives no probability bound (it need not be independent of the identity): remove `seed` for a fresh seed and the proved bound{extra}"
            ),
            erratum: None,
        },
        None => Outcome {
            verdict: Verdict::Holds,
            method,
            evidence: format!(
                "LHS - RHS vanishes at all {trials} points; a false identity passes with probability <= {} (proved bound, below the threshold 2^{HOLDS_THRESHOLD_LOG2}){extra}",
                show(worst)
            ),
            erratum: None,
        },
        Some(coords) => Outcome {
            verdict: Verdict::Undecided,
            method,
            evidence: format!(
                "LHS - RHS vanishes at all {trials} points, but the error bound{coords}{} is {}, not below 2^{HOLDS_THRESHOLD_LOG2}; use more points (random up to {MAX_RANDOM_TRIALS}){extra}",
                if chosen.is_empty() { "" } else { " a fresh seed would give" },
                show(worst)
            ),
            erratum: None,
        },
    })
}
