//! `instances` claims: exact evaluation at given instances and evaluation at random points
//! modulo a random prime (as `prove --random`).

use super::*;
use exactcheck_exact::Algebraic;

/// The outcome, and for the random part the typed fields `prove --random --json` prints.
pub(super) fn instances(check: &Check) -> Result<(Outcome, Map<String, Value>), Fault> {
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
            return Ok((outcome, Map::new()));
        }
    }
    let exact_note = if at.is_empty() {
        String::new()
    } else {
        format!("LHS - RHS is exactly 0 at all {} given instances", at.len())
    };
    let Some(trials) = *random else {
        return Ok((
            Outcome {
                verdict: Verdict::Holds,
                method: "exact evaluation at the given instances".into(),
                evidence: exact_note,
                erratum: None,
            },
            Map::new(),
        ));
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
    // The coordinates are tested in parallel, each with its own prime (drawn from the seed and
    // the coordinate's identity), and worded as `prove --random` words them.
    let decisions: Vec<RandomDecision> = lhs
        .par_iter()
        .zip(rhs.par_iter())
        .map(|(l, r)| random_identity_test(l, r, &names, &circles, trials, seed_of_run))
        .collect::<Result<_, String>>()
        .map_err(|e| Fault::Input("lhs", e))?;
    let labels: Vec<String> = if lhs.len() == 1 {
        Vec::new()
    } else {
        (0..lhs.len()).map(|c| shape.component(c)).collect()
    };
    let phrased = crate::phrase::phrase_random(
        &decisions,
        &labels,
        trials,
        seed_of_run,
        &crate::phrase::RandomOptions {
            fresh_seed: "remove `seed`",
            points: "random",
            otherwise: "",
            exact_counter_example: "",
        },
    );
    let method = format!(
        "{}{}",
        phrased.method,
        if at.is_empty() {
            ""
        } else {
            " and exact instances"
        }
    );
    let fields = crate::phrase::random::random_fields(&phrased, &decisions, *shape, seed_of_run);
    let evidence = if exact_note.is_empty() {
        phrased.evidence
    } else {
        format!("{}; {exact_note}", phrased.evidence)
    };
    let erratum = match &decisions[phrased.shown] {
        RandomDecision::Fails {
            report,
            point,
            value,
        } => {
            let at: Vec<String> = point.iter().map(|(v, x)| format!("{v} = {x}")).collect();
            Some(Box::new(Erratum {
                printed: vec![Equation {
                    lhs: lhs[phrased.shown].clone(),
                    rhs: rhs[phrased.shown].clone(),
                }],
                correction: format!(
                    "LHS - RHS = {value} (mod p = {}) at {}: not zero modulo p, so not zero over Q",
                    report.prime,
                    at.join(", ")
                ),
                ..Erratum::default()
            }))
        }
        RandomDecision::Refuted { exact, .. } => Some(Box::new(Erratum {
            printed: vec![Equation {
                lhs: lhs[phrased.shown].clone(),
                rhs: rhs[phrased.shown].clone(),
            }],
            correction: format!(
                "LHS - RHS = {} at {}, exactly",
                exact.value,
                exact.point.join(", ")
            ),
            ..Erratum::default()
        })),
        _ => None,
    };
    Ok((
        Outcome {
            verdict: phrased.verdict,
            method,
            evidence,
            erratum,
        },
        fields,
    ))
}
