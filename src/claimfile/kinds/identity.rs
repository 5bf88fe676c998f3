//! `identity` claims: decided by the identity engine as `prove` decides its identities, one
//! statement per component.

use super::*;

/// An identity claim through the identity engine; with the outcome, why the claim's corrected
/// form is not proved equal to its `rhs` (if it is not).
pub(super) fn identity<C: PointField + Display>(
    check: &Check,
) -> Result<(Outcome, Option<String>), Fault> {
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
    let mut vars = Vars::new();
    // `sqrt` of a non-constant becomes a variable with its relation and sign condition.
    vars.allow_roots();
    let mut coordinates = Vec::new();
    for (l, r) in lhs.iter().zip(rhs) {
        let (l, r) = exactcheck_exact::expr::ratfun_sides::<C>(l, r, &mut vars)
            .map_err(|(rhs, err)| Fault::Input(if rhs { "rhs" } else { "lhs" }, err.to_string()))?;
        coordinates.push(Statement::Sides(l, r));
    }
    // The names of the components (`component 2 (y)`, `entry (1, 2)`), as `prove` names them.
    let labels: Vec<String> = match shape {
        Shape::Scalar => Vec::new(),
        s => (0..s.len()).map(|k| s.component(k)).collect(),
    };
    let corrected_fns = match corrected {
        Some(xs) => Some(
            xs.iter()
                .map(|x| to_ratfun::<C>(x, &mut vars, "corrected"))
                .collect::<Result<Vec<_>, _>>()?,
        ),
        None => None,
    };
    let mut relations = Vec::new();
    for (a, b) in &conditions.relations {
        relations.push((
            to_ratfun::<C>(a, &mut vars, "where")?,
            to_ratfun::<C>(b, &mut vars, "where")?,
        ));
    }
    // Hypotheses `A != B`, cleared of denominators (which become hypotheses too).
    let mut hypotheses: Vec<Poly<C>> = Vec::new();
    let mut nonzero_texts: Vec<(String, String)> = Vec::new();
    for (a, b, text) in &conditions.nonzero {
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
        relations.push((
            RatFun::from_poly(root.relation()),
            RatFun::from_poly(Poly::zero()),
        ));
    }
    let suffix = if roots.is_empty() {
        String::new()
    } else {
        let c: Vec<String> = roots
            .iter()
            .filter(|r| !r.defined_everywhere())
            .map(SquareRoot::condition)
            .collect();
        if c.is_empty() {
            " (the square roots are defined everywhere)".to_string()
        } else {
            format!(" (the square roots are defined where {})", c.join(", "))
        }
    };
    // Every angle `x` of sin, cos, tan: its cosine and sine lie on the unit circle. pi is the
    // transcendental constant: an indeterminate while deciding.
    let crate::prove_cmd::Angles {
        list: angle_list,
        pi,
        pi_in_relations,
        mixed,
        user_relations,
    } = crate::prove_cmd::add_angles(&vars, &mut relations);
    let mut domains: Vec<(Var, Domain)> = Vec::new();
    for (v, d, text) in &conditions.domains {
        let var = vars.get(v).ok_or_else(|| {
            Fault::Input(
                "where",
                format!("{text:?}: {v} does not occur in the identity or its relations"),
            )
        })?;
        domains.push((var, d.clone()));
    }
    domains.extend(roots.iter().map(|r| (r.var, SquareRoot::<C>::domain())));
    let spec = IdentitySpec {
        relations,
        domains,
        hypotheses,
        corrected: corrected_fns,
        ..IdentitySpec::new(vars, coordinates)
    };
    let phrasing = Phrasing {
        voice: Voice::ClaimsFile,
        vars: &spec.vars,
        relations: conditions
            .relation_texts
            .iter()
            .cloned()
            .chain(
                angle_list
                    .iter()
                    .map(|a| format!("cos({0})^2 + sin({0})^2 = 1", a.name)),
            )
            .collect(),
        domains: conditions
            .domains
            .iter()
            .map(|(_, _, t)| t.clone())
            .collect(),
        labels,
        corrected: corrected
            .iter()
            .flatten()
            .map(ToString::to_string)
            .collect(),
        nonzero_texts,
        domain_texts: conditions
            .domains
            .iter()
            .map(|(n, _, t)| (n.clone(), t.trim().to_string()))
            .collect(),
        suffix,
    };
    let report = decide_identity(&spec).map_err(|e| {
        let key = match &e {
            EngineError::Size(Part::Relation(_), _) | EngineError::Decide(..) => "where",
            EngineError::Size(..) => "lhs",
        };
        Fault::Input(key, phrasing.error(&e))
    })?;
    let mut report = report;
    crate::prove_cmd::sound_counter_example(&mut report, pi_in_relations, &mixed);
    let method = phrasing.method::<C>();
    let evidence = match &report.verdict {
        IdentityVerdict::Fails {
            coordinate: k,
            point,
            value,
            normal_form,
        } if pi.is_some() || !angle_list.is_empty() => {
            // pi is the constant: the value is a polynomial in it, the point leaves it out; an
            // angle's cosine and sine are shown as the angle.
            let (value, note) = match (pi, &spec.coordinates[*k]) {
                (Some(p), Statement::Sides(l, r)) => {
                    let res = if l.is_polynomial() && r.is_polynomial() {
                        l.numerator().clone() - r.numerator()
                    } else {
                        FractionIdentity::new(l, r)
                            .map(|f| f.residual)
                            .unwrap_or_else(|_| normal_form.clone())
                    };
                    (
                        crate::prove_cmd::in_pi::<C>(&res, point, p)
                            .display(&spec.vars)
                            .to_string(),
                        ", a non-zero polynomial in pi, and pi is transcendental, so it is not zero",
                    )
                }
                _ => (value.to_string(), ""),
            };
            let named: Vec<(String, String)> = point
                .iter()
                .filter(|(v, _)| Some(*v) != pi)
                .map(|(v, q)| (spec.vars.name(*v).unwrap_or("?").to_string(), q.to_string()))
                .collect();
            let at = exactcheck_exact::expr::describe_point(&named);
            format!(
                "{}{}{} LHS - RHS = {value}{note}; LHS - RHS{} reduces{} to {}",
                match phrasing.labels.get(*k) {
                    Some(label) => format!("in {label}: "),
                    None => String::new(),
                },
                if at.is_empty() {
                    "everywhere".to_string()
                } else {
                    format!("at {}", at.join(", "))
                },
                if user_relations == 0 {
                    ""
                } else {
                    " (where the relations hold)"
                },
                if report.cleared[*k] {
                    " with the denominators cleared"
                } else {
                    ""
                },
                phrasing.modulo(),
                exactcheck_exact::prove::factored(normal_form, &spec.vars),
            )
        }
        _ => phrasing.evidence(&report),
    };
    let correction_problem = phrasing.correction_problem(&report);
    let (verdict, erratum) = match &report.verdict {
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
    Ok((
        Outcome {
            verdict,
            method,
            evidence,
            erratum,
        },
        correction_problem,
    ))
}
