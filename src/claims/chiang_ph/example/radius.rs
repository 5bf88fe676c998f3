//! `chiang.ph_radius`: the smallest radius of curvature and the cusps of the offsets at the
//! printed radii, decided exactly two ways (module doc of [`super`]).

use super::*;

pub(super) fn root_text(t: &IsolatedRoot<Rational>) -> String {
    match t {
        IsolatedRoot::Exact(x) => format!("t = {x}"),
        IsolatedRoot::Between(lo, hi) => format!(
            "t in ({lo}, {hi}) (about {})",
            decimal(&radical(&t.midpoint()), 5)
        ),
    }
}

/// The cusps of the example's `r`-offset, each isolated root refined to width `<= 10^-6`.
pub(super) fn cusps_of(
    curve: &PhCurve<Rational>,
    r: &Rational,
) -> Result<Vec<Cusp<Rational>>, String> {
    let f = curve.cusp_polynomial(r);
    let width = q(1, 1_000_000);
    Ok(curve
        .offset_cusps(r)
        .map_err(|e| e.to_string())?
        .into_iter()
        .map(|c| Cusp {
            t: refine(&f, &c.t, &width),
            multiplicity: c.multiplicity,
        })
        .collect())
}

pub(super) fn cusps_text(cusps: &[Cusp<Rational>]) -> String {
    if cusps.is_empty() {
        return "no cusp".into();
    }
    let list: Vec<String> = cusps
        .iter()
        .map(|c| {
            format!(
                "{} ({})",
                root_text(&c.t),
                if c.multiplicity == 1 {
                    "simple".to_string()
                } else {
                    format!("multiplicity {}", c.multiplicity)
                }
            )
        })
        .collect();
    format!(
        "{} cusp{}: {}",
        cusps.len(),
        if cusps.len() == 1 { "" } else { "s" },
        list.join(", ")
    )
}

/// The cusps of the example's `r`-offset the second way: the common zeros in `[0, 1]` of the
/// quotient-rule numerators `W X' - X W'`, `W Y' - Y W'` of the rational offset curve, and
/// whether their monic gcd equals the monic cusp polynomial `sigma^2 - 2 r w`.
pub(super) fn cusps_from_offset(
    curve: &PhCurve<Rational>,
    r: &Rational,
) -> Result<(Vec<IsolatedRoot<Rational>>, bool), String> {
    let [w, x, y, _] = curve.offset(r).hom_coordinates();
    let numerator = |c: &Bernstein<Rational>| {
        w.mul(&c.derivative())
            .checked_sub(&c.mul(&w.derivative()))
            .expect("products of the same degrees")
    };
    let (nx, ny) = (numerator(&x), numerator(&y));
    let roots = common_unit_roots(&[nx.clone(), ny.clone()])
        .map_err(|_| format!("r = {r}: the offset's derivative vanishes identically"))?;
    let g = gcd(&[nx, ny]).map_err(|_| "zero numerators".to_string())?;
    let c = gcd(&[curve.cusp_polynomial(r)]).map_err(|_| "zero cusp polynomial".to_string())?;
    Ok((roots, g == c))
}

/// The self-intersections of the example's `r`-offset, decided exactly by
/// [`exactcheck_exact::planar::self_intersections_xy`] (resultant of the divided differences,
/// every candidate pair excluded or certified): the number of crossings and a sentence with the
/// cusps, the crossings (parameter intervals, approximate point, certificate) and what was
/// excluded.
///
/// # Errors
/// When the cusps or the crossings cannot be decided (base curve singular in `[0, 1]`, a
/// tangential self-contact the finder cannot certify within its budget: named, never guessed).
pub fn self_intersections_of(r: &Rational) -> Result<(usize, String), String> {
    let curve = example_curve();
    let cusps = cusps_of(&curve, r)?;
    let found = self_intersections_xy(&curve.offset(r), Budget::default())
        .map_err(|e| format!("r = {r}: self-intersection not decided: {e}"))?;
    let n = found.crossings.len();
    let crossings = if n == 0 {
        if found.excluded_pairs == 0 {
            "no self-intersection (certified: the resultant of the divided differences leaves no candidate pair of parameters in [0, 1])".to_string()
        } else {
            format!(
                "no self-intersection (certified: all {} candidate parameter pairs of the resultant excluded exactly)",
                found.excluded_pairs
            )
        }
    } else {
        let list: Vec<String> = found
            .crossings
            .iter()
            .map(|c| {
                format!(
                    "C(s) = C(t) for s in [{}, {}], t in [{}, {}] (s ~ {:.6}, t ~ {:.6}, at ~ ({:.4}, {:.4}); certificate: {:?})",
                    c.s_interval.lo,
                    c.s_interval.hi,
                    c.t_interval.lo,
                    c.t_interval.hi,
                    c.s,
                    c.t,
                    c.point[0],
                    c.point[1],
                    c.certificate
                )
            })
            .collect();
        format!(
            "{n} self-intersection{}: {}",
            if n == 1 { "" } else { "s" },
            list.join("; ")
        )
    };
    Ok((
        n,
        format!(
            "r = {r}: {} and {crossings} (both decided exactly)",
            cusps_text(&cusps)
        ),
    ))
}

/// [`self_intersections_of`]'s sentence.
///
/// # Errors
/// As [`self_intersections_of`].
pub fn self_intersection_evidence(r: &Rational) -> Result<String, String> {
    self_intersections_of(r).map(|(_, text)| text)
}

/// The claim `chiang.ph_radius`.
pub(crate) fn radius_check() -> Result<Outcome, String> {
    let curve = example_curve();
    let tolerance = q(1, 1_000_000);
    let left = curve
        .min_radius(Side::Left, &tolerance)
        .map_err(|e| e.to_string())?
        .ok_or("the example has no curvature on the left")?;
    let right = curve
        .min_radius(Side::Right, &tolerance)
        .map_err(|e| e.to_string())?;
    let RadiusBound::Exact(rho) = left.value.clone() else {
        return Ok(Outcome {
            verdict: Verdict::Undecided,
            method: "exact root isolation".into(),
            evidence: format!("the smallest radius was only enclosed: {:?}", left.value),
            erratum: None,
        });
    };
    let attained: Vec<String> = left.attained.iter().map(root_text).collect();
    let w: Vec<String> = curve
        .curvature_numerator()
        .coeffs()
        .iter()
        .map(ToString::to_string)
        .collect();
    let printed = rational(PRINTED_MIN_RADIUS)?;
    let p = places(PRINTED_MIN_RADIUS);
    let exact = radical(&rho);
    let rounded = rounds_to(&exact, &printed, p);
    let tie = ties(&exact, &printed, p);
    let radius_text = format!(
        "smallest radius of curvature exactly {rho} = {} at {} (w = u v' - u' v has Bernstein coefficients ({}), so the curve turns left everywhere; right side: {}); printed {PRINTED_MIN_RADIUS}: {}, deviation {}",
        decimal(&exact, 6),
        attained.join(", "),
        w.join(", "),
        if right.is_none() { "no curvature, no finite radius" } else { "curved too" },
        match (rounded, tie) {
            (true, true) => format!("correctly rounded, a tie ({rho} lies exactly halfway between two {p}-place decimals; round-half-to-even gives {PRINTED_MIN_RADIUS})"),
            (true, false) => format!(
                "correctly rounded, not a tie (|exact - printed| = {} < {}, half a unit of the last printed place)",
                rho.sub_ref(&printed).abs(),
                inv_pow10(p).mul_ref(&q(1, 2))
            ),
            (false, _) => "NOT correctly rounded".to_string(),
        },
        deviation_text(&radical(&printed).sub_ref(&exact))
    );
    // A value strictly between the printed radius and the exact one (if they differ).
    let between = printed.add_ref(&rho).mul_ref(&q(1, 2));
    let mut radii: Vec<(String, Rational)> = vec![
        ("3".into(), q(3, 1)),
        (
            format!("{PRINTED_MIN_RADIUS} (= {printed}, as printed)"),
            printed.clone(),
        ),
    ];
    if between != rho {
        radii.push((
            format!("{between} (between the printed {PRINTED_MIN_RADIUS} and the exact minimum)"),
            between.clone(),
        ));
    }
    radii.push((format!("{rho} (the exact minimum)"), rho.clone()));
    radii.push(("15".into(), q(15, 1)));
    let mut lines = Vec::new();
    let mut count = Vec::new();
    for (label, r) in &radii {
        let cusps = cusps_of(&curve, r)?;
        let (roots, same) = cusps_from_offset(&curve, r)?;
        let agree = same
            && roots.len() == cusps.len()
            && roots
                .iter()
                .zip(&cusps)
                .all(|(a, c)| a.lo() <= c.t.hi() && c.t.lo() <= a.hi());
        if !agree {
            return Ok(Outcome {
                verdict: Verdict::Undecided,
                method: "exact root isolation, two ways".into(),
                evidence: format!(
                    "r = {label}: the cusp polynomial gives {} but the offset's derivative vanishes at {} (monic gcd equal to the cusp polynomial: {same})",
                    cusps_text(&cusps),
                    roots.iter().map(root_text).collect::<Vec<_>>().join(", ")
                ), erratum: None, });
        }
        lines.push(format!(
            "r = {label}: {}; cross-check: the offset's derivative numerators W X' - X W', W Y' - Y W' have monic gcd equal to sigma^2 - 2 r w and {} common zero(s) in [0, 1]",
            cusps_text(&cusps),
            roots.len()
        ));
        count.push((r.clone(), cusps));
    }
    let cusps_at = |r: &Rational| {
        count
            .iter()
            .find(|(x, _)| x == r)
            .map(|(_, c)| c.clone())
            .expect("computed above")
    };
    let at_printed = cusps_at(&printed);
    let mut failures = Vec::new();
    // The printed cusp counts found false: (r, printed count, computed count).
    let mut wrong_counts: Vec<(Rational, usize, usize)> = Vec::new();
    if !rounded {
        failures.push(format!(
            "the smallest radius is {rho}, not {PRINTED_MIN_RADIUS}"
        ));
    }
    let one_cusp = at_printed.len() == 1;
    if !one_cusp {
        wrong_counts.push((printed.clone(), 1, at_printed.len()));
        failures.push(format!(
            "\"r = {PRINTED_MIN_RADIUS}: exactly one cusp\" fails: at r = {printed} exactly there is {}",
            cusps_text(&at_printed)
        ));
    }
    if between != rho {
        let c = cusps_at(&between);
        if c.len() != 2 {
            wrong_counts.push((between.clone(), 2, c.len()));
            failures.push(format!(
                "\"r > {PRINTED_MIN_RADIUS}: two cusps\" fails: at r = {between} > {PRINTED_MIN_RADIUS} there is {}",
                cusps_text(&c)
            ));
        }
    }
    // Self-intersections, decided exactly (exact::planar): none below the minimum radius, at
    // least one crossing at r = 15.
    let (below, below_text) = self_intersections_of(&q(3, 1))?;
    let (above, above_text) = self_intersections_of(&q(15, 1))?;
    let (at_printed_crossings, at_printed_text) = self_intersections_of(&printed)?;
    if below != 0 {
        failures.push(format!(
            "\"r < {PRINTED_MIN_RADIUS}: no self-intersection\" fails: {below_text}"
        ));
    }
    if above == 0 {
        failures.push(format!(
            "\"r > {PRINTED_MIN_RADIUS}: self-intersection\" fails: {above_text}"
        ));
    }
    let parts = format!(
        "As printed: \"smallest radius 12.6\" — {}; \"r < 12.6: no self-intersection\" — {} (and no r below the exact minimum has a cusp); \"r = 12.6: one cusp\" — {}; \"r > 12.6: self-intersection and two cusps\" — {}{}",
        if rounded { "correct as a rounding" } else { "wrong" },
        below_text,
        if one_cusp { "holds".into() } else { format!("fails ({at_printed_text}; {at_printed_crossings} crossing(s))") },
        above_text,
        if between != rho {
            format!("; but at r = {between} (> 12.6): {}", cusps_text(&cusps_at(&between)))
        } else {
            String::new()
        }
    );
    let corrected = format!(
        "Corrected: the smallest radius is {rho} = {} at {}; the r-offset has no cusp for r < {rho}, one double cusp (at {}) for r = {rho}, and two simple cusps for r > {rho}; self-intersections decided exactly at r = 3 ({below}), r = {printed} ({at_printed_crossings}) and r = 15 ({above}).",
        decimal(&exact, 6),
        attained.join(", "),
        attained.join(", ")
    );
    let evidence = format!(
        "{radius_text}. {}. {parts}. {}",
        lines.join(". "),
        if failures.is_empty() {
            "Every part decided here holds.".to_string()
        } else {
            format!("{}. {corrected}", failures.join("; "))
        }
    );
    Ok(Outcome {
        verdict: if failures.is_empty() {
            Verdict::Holds
        } else {
            Verdict::Fails
        },
        method: "exact: smallest radius by PhCurve::min_radius (candidate certified by root isolation of sigma^2 - 2 m w); cusps = zeros of sigma^2 - 2 r w with multiplicity, cross-checked by the gcd of the rational offset's derivative numerators".into(),
        erratum: (!failures.is_empty()).then(|| {
            radius_erratum(
                &printed,
                (!rounded).then_some(&rho),
                &wrong_counts,
                (&rho, cusps_at(&rho).len()),
                at_printed_crossings,
                &corrected,
            )
        }),
        evidence,
    })
}

/// The erratum of `chiang.ph_radius`, from what the check found false: the smallest radius
/// (`wrong_radius`: the exact one, when the printed value is not its correct rounding) and the
/// cusp counts (`wrong_counts`: `r`, the printed count, the computed count); `at_minimum` is the
/// count at the exact minimum radius, `crossings` the self-intersections at the printed radius.
pub(super) fn radius_erratum(
    printed: &Rational,
    wrong_radius: Option<&Rational>,
    wrong_counts: &[(Rational, usize, usize)],
    at_minimum: (&Rational, usize),
    crossings: usize,
    corrected: &str,
) -> Box<Erratum> {
    let int = |k: usize| Expr::number(Rational::from_integer(k as i64));
    let call = |f: &str, r: &Rational| Expr::new(ExprKind::Call(f.into(), vec![r.to_expr()]));
    let minus =
        |a: Expr, b: Expr| Expr::new(ExprKind::Sum(vec![(AddOp::Plus, a), (AddOp::Minus, b)]));
    let mut e = Erratum {
        correction: corrected
            .strip_prefix("Corrected: ")
            .unwrap_or(corrected)
            .to_string(),
        notation: vec![
            ("rho_min".into(), "\\rho_{min}".into()),
            ("n_cusps".into(), "n_{cusps}".into()),
            ("n_crossings".into(), "n_{crossings}".into()),
        ],
        ..Erratum::default()
    };
    if let Some(rho) = wrong_radius {
        e.printed
            .push(Equation::named("rho_min", printed.to_expr()));
        e.corrected.push(Equation::named("rho_min", rho.to_expr()));
        e.residual.push(Equation::new(
            minus(Expr::var("rho_min"), printed.to_expr()),
            rho.sub_ref(printed).to_expr(),
        ));
    }
    for (r, said, found) in wrong_counts {
        e.printed
            .push(Equation::new(call("n_cusps", r), int(*said)));
        e.counter_example
            .push(Equation::new(call("n_cusps", r), int(*found)));
        e.residual.push(Equation::new(
            minus(call("n_cusps", r), int(*said)),
            Expr::number(Rational::from_integer(*found as i64 - *said as i64)),
        ));
    }
    if !wrong_counts.is_empty() {
        e.counter_example
            .push(Equation::new(call("n_crossings", printed), int(crossings)));
        e.corrected.push(Equation::new(
            call("n_cusps", at_minimum.0),
            int(at_minimum.1),
        ));
    }
    Box::new(e)
}
