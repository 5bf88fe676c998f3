//! `value` claims: exact values against printed decimals, componentwise for vectors and
//! matrices.

use super::*;

/// How a value claim's exact value was computed, for the outcome's method.
fn value_method(v: &RealConstant) -> &'static str {
    match v {
        RealConstant::Radical(_) => "exact evaluation in Q(sqrt)",
        RealConstant::Algebraic(_) => {
            "exact real algebraic arithmetic (defining polynomial and isolating interval)"
        }
        RealConstant::Pi { .. } => {
            "exact evaluation as a rational function of pi, compared through a certified enclosure of pi (Machin's series with rational error bounds)"
        }
    }
}

fn value(expr: &Expr, name: Option<&Expr>, printed_list: &[String]) -> Result<Outcome, Fault> {
    let v = RealConstant::from_expr(expr).map_err(|e| Fault::Input("expr", e.to_string()))?;
    let judge = |e: String| Fault::Input("expr", e);
    let mut notes = Vec::new();
    let mut all_exact = true;
    let mut wrong = Vec::new();
    let max_places = printed_list
        .iter()
        .map(|p| printed::places(p))
        .max()
        .unwrap_or(0);
    for p in printed_list {
        let q = printed::rational(p).map_err(|e| Fault::Input("printed", e))?;
        let places = printed::places(p);
        if v.cmp_rational(&q).map_err(|e| judge(e.to_string()))? == Ordering::Equal {
            notes.push(format!("{p} is the exact value"));
            continue;
        }
        all_exact = false;
        let correct = printed::decimal_of(&v, places).map_err(judge)?;
        if printed::rounds_to_of(&v, &q, places).map_err(judge)? {
            notes.push(if printed::ties_of(&v, &q, places).map_err(judge)? {
                format!("{p}: a correct rounding to {places} places (a tie: both neighbours are)")
            } else {
                format!("{p}: correctly rounded to {places} places")
            });
        } else {
            let dev = v.rational_minus(&q);
            let how = if printed::truncates_to_of(&v, &q, places).map_err(judge)? {
                " (truncated, not rounded)"
            } else {
                ""
            };
            let guess = match printed::closed_form_guess(&q, places) {
                Some(g) => format!("; the printed {p} is the rounding of {g}"),
                None => String::new(),
            };
            notes.push(format!(
                "{p}: wrong{how}; correctly rounded to {places} places it is {correct} (printed - exact = {}){guess}",
                printed::deviation_text_of(&dev).map_err(judge)?
            ));
            wrong.push((p.clone(), q, correct, dev));
        }
    }
    let verdict = if !wrong.is_empty() {
        Verdict::Fails
    } else if all_exact {
        Verdict::Proved
    } else {
        Verdict::Holds
    };
    let shown = printed::decimal_of(&v, max_places + 4).map_err(judge)?;
    let evidence = format!("exact value {v} = {shown}...; {}", notes.join("; "));
    let erratum = if wrong.is_empty() {
        None
    } else {
        let label = name.cloned().unwrap_or_else(|| expr.clone());
        let mut e = Erratum {
            correction: format!("the exact value is {v} = {shown}..."),
            ..Erratum::default()
        };
        // The decimals as printed (digits and trailing zeros kept), not as fractions.
        for (p, q, correct, dev) in &wrong {
            let c = printed::rational(correct).map_err(Fault::Internal)?;
            e.printed.push(Equation {
                lhs: label.clone(),
                rhs: as_printed(p, q),
            });
            e.corrected.push(Equation {
                lhs: label.clone(),
                rhs: as_printed(correct, &c),
            });
            // A deviation with no radical form (`Root(...)`) is written as the difference.
            let lhs = difference(&as_printed(p, q), &label);
            let rhs = value_expr(dev).unwrap_or_else(|_| difference(&as_printed(p, q), expr));
            e.residual.push(Equation { lhs, rhs });
        }
        Some(Box::new(e))
    };
    Ok(Outcome {
        verdict,
        method: format!("{}; printed decimals judged exactly", value_method(&v)),
        evidence,
        erratum,
    })
}

/// The components of a printed tuple, row or matrix (`"(1/2, 0.7071)"`, `"[1, 2]"`,
/// `"[[1, 2], [3, 4]]"`), by rows; a single decimal is one component.
pub(super) fn printed_tuple(text: &str) -> Vec<String> {
    text.replace(['(', ')', '[', ']'], "")
        .split(',')
        .map(|p| p.trim().to_string())
        .collect()
}

/// A value claim: each component judged as a scalar is ([`value`]); a vector's verdict is the
/// worst of its components', the evidence and erratum name each component.
pub(super) fn values(
    exprs: &[Expr],
    names: &[Expr],
    printed: &[Vec<String>],
) -> Result<Outcome, Fault> {
    if exprs.len() == 1 {
        return value(&exprs[0], names.first(), &printed[0]);
    }
    let mut outs = Vec::new();
    for (k, (e, p)) in exprs.iter().zip(printed).enumerate() {
        outs.push((k + 1, value(e, names.get(k), p)?));
    }
    let verdict = if outs.iter().any(|(_, o)| o.verdict == Verdict::Fails) {
        Verdict::Fails
    } else if outs.iter().all(|(_, o)| o.verdict == Verdict::Proved) {
        Verdict::Proved
    } else {
        Verdict::Holds
    };
    let evidence = outs
        .iter()
        .map(|(k, o)| format!("component {k}: {}", o.evidence))
        .collect::<Vec<_>>()
        .join("; ");
    let mut erratum: Option<Box<Erratum>> = None;
    for (k, o) in &outs {
        if let Some(e) = &o.erratum {
            let all = erratum.get_or_insert_with(Default::default);
            if !all.correction.is_empty() {
                all.correction.push_str("; ");
            }
            all.correction
                .push_str(&format!("component {k}: {}", e.correction));
            all.printed.extend(e.printed.iter().cloned());
            all.corrected.extend(e.corrected.iter().cloned());
            all.residual.extend(e.residual.iter().cloned());
        }
    }
    Ok(Outcome {
        verdict,
        method: "exact evaluation of each component; printed decimals judged exactly".into(),
        evidence,
        erratum,
    })
}
