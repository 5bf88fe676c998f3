//! `identity` claims: decided by the identity engine as `prove` decides its identities, one
//! statement per component; real algebraic constants outside the square-root field
//! (`cos(pi/5)`, `sqrt(2 + sqrt(2))`) next to variables are put in one number field by the
//! function `prove` uses ([`crate::prove_cmd::constants::abstract_statement`]) and a non-zero
//! reduction gets its exact counter-example at the field's generator
//! ([`crate::prove_cmd::constants::settle`]).

use super::*;
use crate::prove_cmd::constants::{self as prove_constants, ConstantsError};
use exactcheck_exact::prove::{AlgebraicConstants, ConstantValue};

/// The expressions of an identity claim with its algebraic constants as polynomials in the
/// primitive element `c` of their field, in the places of the claim's own.
pub(super) struct Filled {
    k: AlgebraicConstants,
    lhs: Vec<Expr>,
    rhs: Vec<Expr>,
    corrected: Option<Vec<Expr>>,
    relations: Vec<(Expr, Expr)>,
    nonzero: Vec<(Expr, Expr, String)>,
}

/// An identity claim: in the number field of its constants when one lies outside the
/// square-root field, else over the field the claim asks for (`radical` or Q).
pub(super) fn identity_claim(check: &Check) -> Result<Decision, Fault> {
    let Check::Identity {
        lhs,
        rhs,
        conditions,
        corrected,
        radical,
        ..
    } = check
    else {
        unreachable!("identity_claim() is called for identity claims")
    };
    // Every expression decided, with the key it is read from.
    let exprs: Vec<(&'static str, &Expr)> = lhs
        .iter()
        .map(|e| ("lhs", e))
        .chain(rhs.iter().map(|e| ("rhs", e)))
        .chain(corrected.iter().flatten().map(|e| ("corrected", e)))
        .chain(
            conditions
                .relations
                .iter()
                .flat_map(|(a, b)| [a, b])
                .chain(conditions.nonzero.iter().flat_map(|(a, b, _)| [a, b]))
                .map(|e| ("where", e)),
        )
        .collect();
    let (keys, exprs): (Vec<&'static str>, Vec<&Expr>) = exprs.into_iter().unzip();
    if prove_constants::any_needs_constants(exprs.iter().copied()) {
        match prove_constants::abstract_statement(&exprs) {
            Ok(Some((k, filled))) => {
                let mut filled = filled.into_iter();
                let mut next = || filled.next().expect("one filled expression per expression");
                let filled = Filled {
                    lhs: lhs.iter().map(|_| next()).collect(),
                    rhs: rhs.iter().map(|_| next()).collect(),
                    corrected: corrected
                        .as_ref()
                        .map(|xs| xs.iter().map(|_| next()).collect()),
                    relations: conditions
                        .relations
                        .iter()
                        .map(|_| (next(), next()))
                        .collect(),
                    nonzero: conditions
                        .nonzero
                        .iter()
                        .map(|(_, _, t)| (next(), next(), t.clone()))
                        .collect(),
                    k,
                };
                return identity::<Rational>(check, Some(&filled));
            }
            Ok(None) => {}
            Err(ConstantsError::Expr(i, why)) => return Err(Fault::Input(keys[i], why)),
            Err(ConstantsError::Field(why)) => return Err(Fault::Input("lhs", why)),
        }
    }
    if *radical {
        identity::<Radical>(check, None)
    } else {
        identity::<Rational>(check, None)
    }
}

/// An identity claim through the identity engine (with its constants in a number field when
/// `constants` is given); with the outcome, why the claim's corrected form is not proved equal
/// to its `rhs` (if it is not), and the report's typed fields as `prove --json` prints them.
fn identity<C: PointField + Display>(
    check: &Check,
    constants: Option<&Filled>,
) -> Result<Decision, Fault> {
    let Check::Identity {
        shape,
        lhs,
        rhs,
        names,
        conditions,
        corrected,
        ..
    } = check
    else {
        unreachable!("identity() is called for identity claims")
    };
    // The expressions decided: the claim's own, or with the constants in the field.
    let (lhs_in, rhs_in, corrected_in, relations_in, nonzero_in) = match constants {
        Some(f) => (
            &f.lhs,
            &f.rhs,
            f.corrected.as_ref(),
            &f.relations,
            &f.nonzero,
        ),
        None => (
            lhs,
            rhs,
            corrected.as_ref(),
            &conditions.relations,
            &conditions.nonzero,
        ),
    };
    let k = constants.map(|f| &f.k);
    let sides: Vec<&Expr> = lhs_in.iter().chain(rhs_in.iter()).collect();
    let tied: Vec<(&Expr, &Expr)> = relations_in.iter().map(|(a, b)| (a, b)).collect();
    if let Some(why) = exactcheck_exact::expr::library::diff_against_relations(&sides, &tied) {
        return Err(Fault::Input("where", why));
    }
    let mut vars = Vars::new();
    // `sqrt` of a non-constant becomes a variable with its relation and sign condition.
    vars.allow_roots();
    // The base angles of everything decided together (`x/2` for `sin(x/2)` and `sin(x)`).
    let decided: Vec<&Expr> = lhs_in
        .iter()
        .chain(rhs_in.iter())
        .chain(corrected_in.into_iter().flatten())
        .chain(relations_in.iter().flat_map(|(a, b)| [a, b]))
        .chain(nonzero_in.iter().flat_map(|(a, b, _)| [a, b]))
        .collect();
    exactcheck_exact::expr::register_angle_bases(&decided, &mut vars)
        .map_err(|e| Fault::Input("lhs", e.to_string()))?;
    let mut coordinates = Vec::new();
    for (l, r) in lhs_in.iter().zip(rhs_in) {
        let (l, r) = exactcheck_exact::expr::ratfun_sides::<C>(l, r, &mut vars)
            .map_err(|(rhs, err)| Fault::Input(if rhs { "rhs" } else { "lhs" }, err.to_string()))?;
        coordinates.push(Statement::Sides(l, r));
    }
    // The names of the components (`component 2 (y)`, `entry (1, 2)`), as `prove` names them.
    let labels: Vec<String> = match shape {
        Shape::Scalar => Vec::new(),
        s => (0..s.len()).map(|k| s.component(k)).collect(),
    };
    let corrected_fns = match corrected_in {
        Some(xs) => Some(
            xs.iter()
                .map(|x| to_ratfun::<C>(x, &mut vars, "corrected"))
                .collect::<Result<Vec<_>, _>>()?,
        ),
        None => None,
    };
    let mut relations = Vec::new();
    for (a, b) in relations_in {
        relations.push((
            to_ratfun::<C>(a, &mut vars, "where")?,
            to_ratfun::<C>(b, &mut vars, "where")?,
        ));
    }
    // Hypotheses `A != B`, cleared of denominators (which become hypotheses too).
    let mut hypotheses: Vec<Poly<C>> = Vec::new();
    let mut nonzero_texts: Vec<(String, String)> = Vec::new();
    for (a, b, text) in nonzero_in {
        let a = to_ratfun::<C>(a, &mut vars, "where")?;
        let b = to_ratfun::<C>(b, &mut vars, "where")?;
        let cleared =
            FractionIdentity::new(&a, &b).map_err(|e| Fault::Input("where", e.to_string()))?;
        if cleared.residual.is_zero() {
            return Err(Fault::Input(
                "where",
                format!("{text:?} is false everywhere (both sides are the same)"),
            ));
        }
        nonzero_texts.push((cleared.residual.display(&vars).to_string(), text.clone()));
        hypotheses.push(cleared.residual);
        hypotheses.extend(cleared.conditions);
    }
    let roots = square_roots::<C>(&mut vars).map_err(|e| Fault::Input("lhs", e.to_string()))?;
    for root in &roots {
        relations.push(root.relation());
    }
    // Every angle `x` of sin, cos, tan: its cosine and sine lie on the unit circle. pi is the
    // transcendental constant: an indeterminate while deciding.
    let angles = crate::prove_cmd::add_angles(&vars, &mut relations);
    let (angle_list, pi) = (&angles.list, angles.pi);
    // The minimal polynomial of the constants' primitive element and its isolating interval
    // (after the angles, so that it does not count as a relation of the claim's).
    let constant_domain = match k {
        Some(k) => {
            let (m, domain) =
                prove_constants::constant_relation::<C>(k, &mut vars).map_err(Fault::Internal)?;
            relations.push(m);
            Some(domain)
        }
        None => None,
    };
    let bounds = crate::prove_cmd::var_domains(&vars, &conditions.domains)
        .map_err(|e| Fault::Input("where", e))?;
    let mut domains: Vec<(Var, VarDomain)> = bounds.bounds.clone();
    domains.extend(roots.iter().map(|r| (r.var, SquareRoot::<C>::domain())));
    domains.extend(constant_domain);
    // The variables of sums' symbolic bounds are integers inside the sums' ranges.
    let sums = exactcheck_exact::prove::SumRanges::of(decided.iter().copied());
    sums.add_domains(&vars, &mut domains);
    let spec = IdentitySpec {
        relations,
        domains,
        hypotheses,
        corrected: corrected_fns,
        ..IdentitySpec::new(vars, coordinates)
    };
    let mut phrasing = Phrasing {
        relations: conditions.relation_texts.clone(),
        circles: angle_list
            .iter()
            .map(|a| format!("cos({0})^2 + sin({0})^2 = 1", a.name))
            .collect(),
        domains: conditions.domains.iter().map(|d| d.text.clone()).collect(),
        labels,
        corrected: corrected
            .iter()
            .flatten()
            .map(ToString::to_string)
            .collect(),
        nonzero_texts,
        domain_texts: Phrasing::domain_texts(bounds.texts.iter().map(|(n, t)| (n, t)), k),
        roots: Phrasing::root_texts(&roots, &spec.vars),
        pi,
        constants: k,
        ..Phrasing::new(&spec.vars)
    };
    let report = match decide_identity(&spec) {
        // Conditions without a common real point: nothing is proved, and the claim says why.
        Err(e @ EngineError::Decide(_, DecideError::Vacuous(_))) => {
            return Ok(Decision {
                outcome: Outcome {
                    verdict: Verdict::Undecided,
                    method: phrasing.method::<C>(),
                    evidence: phrasing.error(&e),
                    erratum: None,
                },
                problem: None,
                report: Default::default(),
            })
        }
        other => other,
    };
    let report = report.map_err(|e| {
        let key = match &e {
            EngineError::Size(Part::Relation(_), _) | EngineError::Decide(..) => "where",
            EngineError::Size(..) => "lhs",
        };
        Fault::Input(key, phrasing.error(&e))
    })?;
    let mut report = report;
    crate::prove_cmd::sound_counter_example(&spec, &mut report, &angles);
    sums.check(&spec.vars, &mut report);
    // With algebraic constants, a non-zero reduction gets its counter-example at c = theta (not
    // with a constant angle: the search would give its cosine and sine rational values).
    phrasing.constant_point = k
        .filter(|_| exactcheck_exact::expr::constant_base(&spec.vars).is_none())
        .and_then(|k| prove_constants::settle(k, &spec, &mut report, pi, &angles.mixed));
    let method = phrasing.method::<C>();
    let mut evidence = phrasing.evidence(&spec, &report);
    // A failing identity whose names of several letters are spelled by its one-letter variables
    // (`2ac` beside `a` and `c`) was most likely meant as a product.
    if matches!(report.verdict, IdentityVerdict::Fails { .. }) {
        let sides: Vec<&Expr> = lhs.iter().chain(rhs).collect();
        if let Some(hint) = crate::prove_cmd::joined_names_hint(&sides) {
            evidence.push_str(&format!(" (hint: {hint})"));
        }
    }
    let correction_problem = phrasing.correction_problem(&report);
    let fields = phrasing.fields(&spec, &report, *shape);
    let printed: Vec<Equation> = if names.is_empty() {
        lhs.iter()
            .zip(rhs)
            .map(|(l, r)| Equation {
                lhs: l.clone(),
                rhs: r.clone(),
            })
            .collect()
    } else {
        names
            .iter()
            .zip(lhs)
            .map(|(n, l)| Equation {
                lhs: n.clone(),
                rhs: l.clone(),
            })
            .collect()
    };
    let (verdict, erratum) = match &report.verdict {
        IdentityVerdict::Undecided { coordinate, .. } if phrasing.constant_point.is_some() => {
            let p = phrasing.constant_point.as_ref().expect("matched");
            let mut counter_example = Vec::new();
            let mut residual_at = difference(&lhs[*coordinate], &rhs[*coordinate]);
            let mut plain = true;
            for (name, q) in crate::phrase::named_point(p, &spec.vars) {
                let value = value_expr(&q)?;
                if name.contains('(') {
                    plain = false;
                } else {
                    residual_at = defs::substitute_free(&residual_at, &name, &value)
                        .map_err(Fault::Internal)?;
                }
                counter_example.push(Equation {
                    lhs: var(&name),
                    rhs: value,
                });
            }
            // The value as a formula: its radical form, else (a `Root`, or a value in pi) the
            // difference at the point when every coordinate is a plain variable and there is
            // one (without coordinates it would only repeat the difference).
            let (number, in_pi) = match &p.value {
                ConstantValue::Number(a) => (value_expr(a), false),
                ConstantValue::InPi { .. } => (
                    Err(Fault::Internal(
                        "a value in pi and the field's generator is not a formula".into(),
                    )),
                    true,
                ),
            };
            let residual = match number {
                Ok(v) => vec![Equation {
                    lhs: difference(&lhs[*coordinate], &rhs[*coordinate]),
                    rhs: v,
                }],
                Err(_) if plain && !(in_pi && counter_example.is_empty()) => vec![Equation {
                    lhs: difference(&lhs[*coordinate], &rhs[*coordinate]),
                    rhs: residual_at,
                }],
                Err(_) => Vec::new(),
            };
            let erratum = Erratum {
                printed,
                correction: phrasing.erratum_correction(&report),
                counter_example,
                residual,
                ..Erratum::default()
            };
            (Verdict::Fails, Some(Box::new(erratum)))
        }
        IdentityVerdict::Proved { .. } => (Verdict::Proved, None),
        IdentityVerdict::Undecided { .. } => (Verdict::Undecided, None),
        IdentityVerdict::Fails {
            coordinate: k,
            point,
            value,
            ..
        } => {
            let mut counter_example = Vec::new();
            for (v, q) in point.iter().filter(|(v, _)| Some(*v) != pi) {
                let name = spec
                    .vars
                    .name(*v)
                    .expect("the engine reports only variables of the table");
                counter_example.push(Equation {
                    lhs: var(name),
                    rhs: value_expr(q)?,
                });
            }
            let mut erratum = Erratum {
                printed,
                correction: phrasing.erratum_correction(&report),
                counter_example,
                residual: vec![Equation {
                    lhs: difference(&lhs[*k], &rhs[*k]),
                    rhs: value_expr(value)?,
                }],
                ..Erratum::default()
            };
            if let (Some(CorrectionVerdict::Proved), Some(cx)) = (&report.correction, corrected) {
                erratum.corrected = cx
                    .iter()
                    .enumerate()
                    .map(|(j, x)| match names.get(j) {
                        Some(n) => Equation {
                            lhs: n.clone(),
                            rhs: x.clone(),
                        },
                        None => Equation {
                            lhs: x.clone(),
                            rhs: rhs[j].clone(),
                        },
                    })
                    .collect();
            }
            (Verdict::Fails, Some(Box::new(erratum)))
        }
    };
    Ok(Decision {
        outcome: Outcome {
            verdict,
            method,
            evidence,
            erratum,
        },
        problem: correction_problem,
        report: fields,
    })
}
