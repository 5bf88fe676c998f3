//! `chiang.ph_offsets`: every printed decimal of the offsets' `r0` and `w0` against the exact
//! value (module doc of [`super`]).

use super::*;

/// One printed value of the offsets' table against the exact one.
#[derive(Clone, Debug)]
pub struct OffsetRow {
    /// The offset distance as printed.
    pub r: String,
    /// `r0.x`, `r0.y`, `r0.z` or `w0`.
    pub name: String,
    /// The printed digits.
    pub printed: String,
    /// The exact value.
    pub exact: Rational,
    /// The exact value correctly rounded to 6 places (certified).
    pub exact_decimal: String,
    /// `printed - exact` to about 3 significant digits.
    pub deviation: String,
    /// Whether the printed digits are the exact value correctly rounded.
    pub correctly_rounded: bool,
    /// The computed readings that reproduce the printed digits (the exact value truncated; its
    /// magnitude rounded or truncated: a lost minus sign).
    pub reproduced_by: Vec<String>,
}

/// The rows of `chiang.ph_offsets`: `r0.x, r0.y, r0.z, w0` for each printed `r`.
///
/// # Errors
/// A printed decimal that does not parse; a zero weight.
pub fn ph_offsets_rows() -> Result<Vec<OffsetRow>, String> {
    let curve = example_curve();
    let mut rows = Vec::new();
    for (r_text, r0) in PRINTED_OFFSETS {
        let r = rational(r_text)?;
        let offset = curve.offset(&r);
        let w0 = offset.weights()[0].clone();
        let p0 = offset.points()[0]
            .clone()
            .ok_or_else(|| format!("r = {r_text}: the weight w0 is zero"))?;
        let mut items: Vec<(String, &str, Rational)> = (0..3)
            .map(|a| (format!("r0.{}", AXES[a]), r0[a], coords(&p0)[a].clone()))
            .collect();
        items.push(("w0".into(), PRINTED_W0, w0));
        for (name, text, exact) in items {
            let printed = rational(text)?;
            let p = places(text);
            let x = radical(&exact);
            let magnitude = radical(&exact.abs());
            let correctly_rounded = rounds_to(&x, &printed, p);
            let mut reproduced_by = Vec::new();
            if !correctly_rounded {
                if truncates_to(&x, &printed, p) {
                    reproduced_by.push("the exact value truncated".to_string());
                }
                if exact.signum() == exactcheck_core::Sign::Negative {
                    if rounds_to(&magnitude, &printed, p) {
                        reproduced_by
                            .push("the magnitude of the exact value correctly rounded (a lost minus sign)".to_string());
                    } else if truncates_to(&magnitude, &printed, p) {
                        reproduced_by.push(
                            "the magnitude of the exact value truncated (a lost minus sign)"
                                .to_string(),
                        );
                    }
                }
            }
            rows.push(OffsetRow {
                r: r_text.into(),
                name,
                printed: text.into(),
                exact_decimal: decimal(&x, 6),
                deviation: deviation_text(&radical(&printed).sub_ref(&x)),
                correctly_rounded,
                reproduced_by,
                exact,
            });
        }
    }
    Ok(rows)
}

pub(super) fn reading(r: &OffsetRow) -> String {
    if r.correctly_rounded {
        "yes".into()
    } else if r.reproduced_by.is_empty() {
        "**no**; neither the exact value nor its magnitude, rounded or truncated".into()
    } else {
        format!("**no**; reproduced by {}", r.reproduced_by.join("; "))
    }
}

/// The offsets' table as Markdown (for docs/papers/chiang.md).
pub fn ph_offsets_markdown(rows: &[OffsetRow]) -> String {
    let mut s = String::from(
        "| r | value | printed | exact | exact decimal | deviation (printed - exact) | correctly rounded? |\n| --- | --- | --- | --- | --- | --- | --- |\n",
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | `{}` | {} | {} | {} |\n",
            r.r,
            r.name,
            r.printed,
            r.exact,
            r.exact_decimal,
            r.deviation,
            reading(r)
        ));
    }
    s
}

/// Every weight `w_k` and control point `r_k` of the three printed offsets, exactly, as
/// Markdown (the weights do not depend on `r`: they are `sigma` elevated to degree 5).
///
/// # Errors
/// A printed `r` that does not parse; a zero weight.
pub fn weights_markdown() -> Result<String, String> {
    let curve = example_curve();
    let mut s = String::from("| r | k | w_k | r_k |\n| --- | --- | --- | --- |\n");
    for (r_text, _) in PRINTED_OFFSETS {
        let r = rational(r_text)?;
        let offset = curve.offset(&r);
        for (k, (w, p)) in offset.weights().iter().zip(offset.points()).enumerate() {
            let p = p.ok_or_else(|| format!("r = {r_text}: w{k} is zero"))?;
            s.push_str(&format!("| {r} | {k} | {w} | {} |\n", triple(&coords(&p))));
        }
    }
    Ok(s)
}

/// The claim `chiang.ph_offsets`.
pub(crate) fn offsets_check() -> Result<Outcome, String> {
    let rows = ph_offsets_rows()?;
    let curve = example_curve();
    // The weights for every printed r, and whether they are the same.
    let mut weights = Vec::new();
    for (r_text, _) in PRINTED_OFFSETS {
        weights.push(curve.offset(&rational(r_text)?).weights());
    }
    let same = weights.windows(2).all(|w| w[0] == w[1]);
    let sigma: Vec<String> = curve
        .speed()
        .coeffs()
        .iter()
        .map(ToString::to_string)
        .collect();
    let weights_text = format!(
        "all weights w0..w5 = ({}) {} (the z-components of V elevated: sigma = ({}) in degree 2; the cutting planes z = r share the normal (0, 0, 1))",
        weights[0].iter().map(ToString::to_string).collect::<Vec<_>>().join(", "),
        if same { "for every r" } else { "differ between the r" },
        sigma.join(", ")
    );
    let row_text = |r: &OffsetRow| {
        format!(
            "r = {}: {} printed {}, exact {} = {}, deviation {} [{}]",
            r.r,
            r.name,
            r.printed,
            r.exact,
            r.exact_decimal,
            r.deviation,
            if r.correctly_rounded {
                "correctly rounded".to_string()
            } else if r.reproduced_by.is_empty() {
                "not correctly rounded; not the exact value or its magnitude, rounded or truncated"
                    .to_string()
            } else {
                format!("not correctly rounded; {}", r.reproduced_by.join(", "))
            }
        )
    };
    let wrong = rows.iter().filter(|r| !r.correctly_rounded).count();
    let points = curve.base().control_points()[0].clone();
    let q0 = curve.rotated_normal().control_points()[0].clone();
    let sigma0 = curve.speed().coeffs()[0].clone();
    // r0 = p0 + (r / sigma_0) q0: the first control point of the section (the end point C(0)).
    for (r_text, _) in PRINTED_OFFSETS {
        let r = rational(r_text)?;
        let by_formula = points.add_scaled(
            &r.checked_div(&sigma0)
                .map_err(|_| "sigma_0 = 0: the offset has a pole at t = 0".to_string())?,
            &q0,
        );
        if curve.offset(&r).points()[0] != Some(by_formula) {
            return Err(format!(
                "r = {r_text}: the section's r0 is not p0 + (r / sigma_0) q0"
            ));
        }
    }
    let evidence = format!(
        "{wrong} of {} printed values are not the exact value correctly rounded. r0 = p0 + (r / sigma_0) q0 = ({}, {}, {}) + (r / {}) ({}, {}, {}) (checked equal to the section's first control point for each r). Table: {}. {weights_text}",
        rows.len(),
        points.x,
        points.y,
        points.z,
        sigma0,
        q0.x,
        q0.y,
        q0.z,
        rows.iter().map(row_text).collect::<Vec<_>>().join("; ")
    );
    Ok(Outcome {
        verdict: if wrong == 0 && same {
            Verdict::Holds
        } else {
            Verdict::Fails
        },
        method: "exact rational offsets (Chiang's theorem on the PH curve's ruled surface); each printed decimal compared exactly with its rounding interval; readings computed (truncation, magnitude)".into(),
        erratum: (wrong > 0)
            .then(|| offsets_erratum(&rows, &points, &q0, &sigma0))
            .transpose()?
            .map(Box::new),
        evidence,
    })
}

/// The erratum of `chiang.ph_offsets`: for every printed `r` with a wrong value the printed and
/// the exact first control point `r0(r)`, the formula it follows (`p0 + (r / sigma_0) q0`, with
/// the computed data), the first wrong value as the counter-example and `printed - exact` for
/// each wrong value.
pub(super) fn offsets_erratum(
    rows: &[OffsetRow],
    p0: &Vec3<Rational>,
    q0: &Vec3<Rational>,
    sigma0: &Rational,
) -> Result<Erratum, String> {
    let wrong: Vec<&OffsetRow> = rows.iter().filter(|r| !r.correctly_rounded).collect();
    let mut rs: Vec<&str> = wrong.iter().map(|r| r.r.as_str()).collect();
    rs.dedup();
    let tuple = |v: &Vec3<Rational>| tuple3(&coords(v));
    let at = |r: &str| -> Result<Expr, String> {
        Ok(Expr::new(ExprKind::Call(
            "r0".into(),
            vec![rational(r)?.to_expr()],
        )))
    };
    let point = |r: &str, exact: bool| -> Result<Expr, String> {
        let coords = ["r0.x", "r0.y", "r0.z"].map(|name| {
            rows.iter()
                .find(|row| row.r == r && row.name == name)
                .ok_or_else(|| format!("r = {r}: no row {name}"))
                .and_then(|row| {
                    if exact {
                        Ok(row.exact.to_expr())
                    } else {
                        rational(&row.printed).map(|q| q.to_expr())
                    }
                })
        });
        Ok(Expr::tuple(coords.into_iter().collect::<Result<_, _>>()?))
    };
    let mut printed = Vec::new();
    let mut corrected = vec![Equation::new(
        Expr::new(ExprKind::Call("r0".into(), vec![Expr::var("r")])),
        Expr::new(ExprKind::Sum(vec![
            (AddOp::Plus, tuple(p0)),
            (
                AddOp::Plus,
                Expr::new(ExprKind::Product(vec![
                    (MulOp::Times, Expr::var("r")),
                    (MulOp::Divide, sigma0.to_expr()),
                    (MulOp::Times, tuple(q0)),
                ])),
            ),
        ])),
    )];
    for r in &rs {
        printed.push(Equation::new(at(r)?, point(r, false)?));
        corrected.push(Equation::new(at(r)?, point(r, true)?));
    }
    let first = wrong.first().ok_or("no wrong value")?;
    let residual = wrong
        .iter()
        .map(|row| {
            let p = rational(&row.printed)?;
            Ok(Equation::new(
                Expr::new(ExprKind::Sum(vec![
                    (AddOp::Plus, p.to_expr()),
                    (AddOp::Minus, row.exact.to_expr()),
                ])),
                p.sub_ref(&row.exact).to_expr(),
            ))
        })
        .collect::<Result<Vec<_>, String>>()?;
    let parts: Vec<String> = wrong
        .iter()
        .map(|r| {
            format!(
                "for r = {}, {} = {} (printed {})",
                r.r, r.name, r.exact_decimal, r.printed
            )
        })
        .collect();
    Ok(Erratum {
        printed,
        corrected,
        correction: format!(
            "the exact values correctly rounded to 6 places: {}",
            parts.join("; ")
        ),
        counter_example: vec![
            Equation::named("r", rational(&first.r)?.to_expr()),
            Equation::named(&first.name.replace('.', "_"), first.exact.to_expr()),
        ],
        residual,
        notation: vec![("r0".into(), "r_0".into())],
    })
}
