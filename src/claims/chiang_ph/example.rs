//! The worked example (section 3): `u = (10, -1)`, `v = (1, 10)`, `p0 = (0, 0, 0)`, a
//! cubic PH curve. Every printed number is data (strings as printed) and judged against the
//! exact value computed by [`exactcheck_core::ph`] over [`Rational`].
//!
//! * `chiang.ph_points` — `p1..p3` against the control points integrated from the hodograph
//!   (`p_{i+1} = p_i + h_i / 3`), entry by entry; the base curve's derivative is checked against
//!   `(u^2 - v^2, 2uv)` at rational parameters.
//! * `chiang.ph_normals` — `q0..q2` against `V = (-Y', X', sigma)`: per control vector equal?,
//!   horizontally perpendicular to the hodograph coefficient `h_i` (the derived `q_i` is
//!   `(-h_iy, h_ix, sigma_i)`, perpendicular by construction)?, at 45 degrees (`|xy| = z`; the
//!   45-degree property is one of `V(t)`, the derived middle vector is horizontal)? Then every
//!   sign pattern of the printed non-zero entries is tried against the left field
//!   `(-Y', X', sigma)` (the claim's `V`) and the right field `(Y', -X', sigma)`: the patterns
//!   that give each are reported.
//! * `chiang.ph_radius` — the smallest radius of curvature exactly
//!   ([`PhCurve::min_radius`]: a candidate certified by root isolation), the printed decimal
//!   judged (a tie is named), and the cusps at the printed radii counted exactly two
//!   independent ways: the zeros of `sigma^2 - 2 r w` with multiplicity
//!   ([`PhCurve::offset_cusps`]), and the common zeros of the quotient-rule numerators
//!   `W X' - X W'`, `W Y' - Y W'` of the rational offset curve itself (its derivative;
//!   [`common_unit_roots`]), whose monic gcd must equal the monic cusp polynomial. Each part of
//!   the printed sentence is decided as printed; a value strictly between the printed 12.6 and
//!   the exact minimum is a counter-example to "r > 12.6: two cusps".
//! * `chiang.ph_offsets` — every printed decimal of `r0` and `w0` against the exact value:
//!   fraction, certified decimal, deviation, and computed readings (the exact value or its
//!   magnitude — a lost minus sign — rounded or truncated to the printed digits).

use super::{example_curve, q};
use crate::claims::printed::{
    decimal, deviation_text, inv_pow10, places, radical, rational, rounds_to, ties, truncates_to,
};
use crate::claims::{Equation, Erratum, Outcome, Verdict};
use exactcheck_core::ph::{Cusp, PhCurve, RadiusBound, Side};
use exactcheck_core::roots::{common_unit_roots, gcd, refine, IsolatedRoot};
use exactcheck_core::{Bernstein, OrderedField, Ring, Vec3};
use exactcheck_exact::expr::{AddOp, Expr, ExprKind, MulOp};
use exactcheck_exact::planar::{self_intersections_xy, Budget};
use exactcheck_exact::poly::CoeffExpr;
use exactcheck_exact::Rational;

/// The printed control points `p1, p2, p3` (the paper: "p1 = (33, 20/3, 0), p2 = (79/3, 119/3,
/// 0), p3 = (-20/3, 33, 0)").
pub const PRINTED_POINTS: [[&str; 3]; 3] = [
    ["33", "20/3", "0"],
    ["79/3", "119/3", "0"],
    ["-20/3", "33", "0"],
];

/// The printed control vectors `q0, q1, q2` of the rotated normal field.
pub const PRINTED_NORMALS: [[&str; 3]; 3] =
    [["20", "99", "101"], ["99", "20", "0"], ["20", "99", "101"]];

/// The printed smallest radius of the osculating circle.
pub const PRINTED_MIN_RADIUS: &str = "12.6";

/// The printed offsets: `(r, r0)` for `r = 3, 12.6, 15`.
pub const PRINTED_OFFSETS: [(&str, [&str; 3]); 3] = [
    ("3", ["0.594", "2.94", "3"]),
    ("12.6", ["2.5", "12.4", "12.6"]),
    ("15", ["2.96", "14.7", "15"]),
];

/// The printed weight of `r0`, the same for every `r`.
pub const PRINTED_W0: &str = "101";

const AXES: [&str; 3] = ["x", "y", "z"];

fn coords(p: &Vec3<Rational>) -> [Rational; 3] {
    [p.x.clone(), p.y.clone(), p.z.clone()]
}

fn triple(p: &[Rational; 3]) -> String {
    format!("({}, {}, {})", p[0], p[1], p[2])
}

fn parse_triple(p: &[&str; 3]) -> Result<[Rational; 3], String> {
    Ok([rational(p[0])?, rational(p[1])?, rational(p[2])?])
}

// ------------------------------------------------------------------------------ ph_points

/// `chiang.ph_points` for printed `p1, p2, p3` (data; a planted misprint gives `fails` naming
/// the entry).
///
/// # Errors
/// A printed entry that does not parse.
pub fn ph_points_with(printed: &[[&str; 3]; 3]) -> Result<Outcome, String> {
    let curve = example_curve();
    let base = curve.base();
    // The base curve's derivative is the hodograph (u^2 - v^2, 2uv) at rational parameters.
    let tangent = base.hodograph();
    for j in 0..=8 {
        let t = q(j, 8);
        let (u, v) = (curve.u().eval(&t), curve.v().eval(&t));
        let h = tangent.eval(&t);
        if h.x != u.mul_ref(&u).sub_ref(&v.mul_ref(&v)) || h.y != u.mul_ref(&v).scale_i64(2) {
            return Err(format!(
                "the integrated control points do not have the hodograph (u^2 - v^2, 2uv) at t = {t}"
            ));
        }
    }
    let derived = base.control_points();
    let mut mismatches = Vec::new();
    let mut table = Vec::new();
    for (i, p) in printed.iter().enumerate() {
        let printed_q = parse_triple(p)?;
        let d = coords(&derived[i + 1]);
        for a in 0..3 {
            if printed_q[a] != d[a] {
                mismatches.push(format!(
                    "p{}.{}: printed {}, derived {}",
                    i + 1,
                    AXES[a],
                    p[a],
                    d[a]
                ));
            }
        }
        table.push(format!(
            "p{} printed ({}) derived {}",
            i + 1,
            p.join(", "),
            triple(&d)
        ));
    }
    let method = "exact rational arithmetic: p_{i+1} = p_i + h_i / 3 from the hodograph's Bernstein coefficients h_i of (u^2 - v^2, 2uv); B'(t) = (u^2 - v^2, 2uv) checked at t = j/8";
    Ok(if mismatches.is_empty() {
        Outcome {
            verdict: Verdict::Holds,
            method: method.into(),
            evidence: format!(
                "all 9 printed entries equal the derived ones exactly: {}",
                table.join("; ")
            ),
            erratum: None,
        }
    } else {
        Outcome {
            verdict: Verdict::Fails,
            method: method.into(),
            evidence: format!(
                "{} of 9 printed entries differ: {}. Derived: {}",
                mismatches.len(),
                mismatches.join("; "),
                table.join("; ")
            ),
            erratum: None,
        }
    })
}

// ------------------------------------------------------------------------------ ph_normals

/// The sign patterns (as lists of the flipped entries) of the printed non-zero entries that
/// make `printed` equal to `field`.
fn sign_patterns(printed: &[[Rational; 3]; 3], field: &[[Rational; 3]]) -> Vec<Vec<String>> {
    let slots: Vec<(usize, usize)> = (0..3)
        .flat_map(|i| (0..3).map(move |a| (i, a)))
        .filter(|&(i, a)| !printed[i][a].is_zero())
        .collect();
    let mut found = Vec::new();
    for mask in 0u32..(1 << slots.len()) {
        let mut p = printed.clone();
        let mut flipped = Vec::new();
        for (bit, &(i, a)) in slots.iter().enumerate() {
            if mask >> bit & 1 == 1 {
                p[i][a] = p[i][a].neg_ref();
                flipped.push(format!("q{i}.{}", AXES[a]));
            }
        }
        if p.iter().zip(field).all(|(x, y)| x == y) {
            found.push(flipped);
        }
    }
    found
}

fn pattern_text(patterns: &[Vec<String>], slots: usize) -> String {
    match patterns {
        [] => format!("no sign pattern of the {slots} non-zero printed entries gives it"),
        [one] => format!(
            "exactly one of the 2^{slots} sign patterns gives it: a minus sign on {}",
            one.join(", ")
        ),
        many => format!(
            "{} sign patterns give it: {}",
            many.len(),
            many.iter()
                .map(|p| p.join(", "))
                .collect::<Vec<_>>()
                .join(" | ")
        ),
    }
}

/// `chiang.ph_normals` for printed `q0, q1, q2` (data).
///
/// # Errors
/// A printed entry that does not parse.
pub fn ph_normals_with(printed: &[[&str; 3]; 3]) -> Result<Outcome, String> {
    let curve = example_curve();
    let [hx, hy] = curve.hodograph();
    let sigma = curve.speed();
    let left: Vec<[Rational; 3]> = curve
        .rotated_normal()
        .control_points()
        .iter()
        .map(coords)
        .collect();
    let right: Vec<[Rational; 3]> = (0..3)
        .map(|i| {
            [
                hy.coeffs()[i].clone(),
                hx.coeffs()[i].neg_ref(),
                sigma.coeffs()[i].clone(),
            ]
        })
        .collect();
    let p = [
        parse_triple(&printed[0])?,
        parse_triple(&printed[1])?,
        parse_triple(&printed[2])?,
    ];
    let mut per_point = Vec::new();
    let mut wrong = 0;
    for i in 0..3 {
        let h = (hx.coeffs()[i].clone(), hy.coeffs()[i].clone());
        let dot = p[i][0].mul_ref(&h.0).add_ref(&p[i][1].mul_ref(&h.1));
        let horizontal = p[i][0]
            .mul_ref(&p[i][0])
            .add_ref(&p[i][1].mul_ref(&p[i][1]));
        let at45 = horizontal == p[i][2].mul_ref(&p[i][2])
            && p[i][2].signum() != exactcheck_core::Sign::Negative;
        let d = &left[i];
        let d45 = d[0].mul_ref(&d[0]).add_ref(&d[1].mul_ref(&d[1])) == d[2].mul_ref(&d[2]);
        let equal = p[i] == *d;
        if !equal {
            wrong += 1;
        }
        per_point.push(format!(
            "q{i}: printed {}, derived {} — {}; hodograph coefficient h{i} = ({}, {}): printed (x, y) . h{i} = {dot} ({}); |xy|^2 = {horizontal}, z^2 = {}: {} (derived q{i} {} at 45 degrees){}",
            triple(&p[i]),
            triple(d),
            if equal { "equal" } else { "NOT equal" },
            h.0,
            h.1,
            if dot.is_zero() { "perpendicular" } else { "NOT perpendicular" },
            p[i][2].mul_ref(&p[i][2]),
            if at45 { "at 45 degrees" } else { "not at 45 degrees" },
            if d45 { "is" } else { "is not" },
            if right[i] == p[i] { "; equal to the right-normal field's (Y', -X', sigma) control vector" } else { "" }
        ));
    }
    // V(t) itself is at 45 degrees everywhere (checked at rational t).
    let field = curve.rotated_normal();
    let all45 = (0..=8).all(|j| {
        let v = field.eval(&q(j, 8));
        v.x.mul_ref(&v.x).add_ref(&v.y.mul_ref(&v.y)) == v.z.mul_ref(&v.z)
    });
    let slots = p.iter().flatten().filter(|x| !x.is_zero()).count();
    let magnitudes_equal = p
        .iter()
        .zip(&left)
        .all(|(a, b)| a.iter().zip(b).all(|(x, y)| x.abs() == y.abs()));
    let left_patterns = sign_patterns(&p, &left);
    let right_patterns = sign_patterns(&p, &right);
    let evidence = format!(
        "{}. V(t) = (-Y', X', sigma) is at 45 degrees at t = j/8: {all45} (a property of V(t), not of each control vector). Magnitudes: {}. Left field (-Y', X', sigma) (the claim's V): {}. Right field (Y', -X', sigma): {}.{}",
        per_point.join("; "),
        if magnitudes_equal {
            "every printed entry has the magnitude of the derived one (only signs differ)"
        } else {
            "some printed magnitudes differ from the derived ones"
        },
        pattern_text(&left_patterns, slots),
        pattern_text(&right_patterns, slots),
        if wrong == 0 {
            String::new()
        } else {
            format!(
                " The printed q0, q1, q2 are not the rotated normal field: {wrong} of 3 control vectors differ from (-Y', X', sigma); corrected: q0 = {}, q1 = {}, q2 = {}",
                triple(&left[0]),
                triple(&left[1]),
                triple(&left[2])
            )
        }
    );
    Ok(Outcome {
        verdict: if wrong == 0 && all45 {
            Verdict::Holds
        } else {
            Verdict::Fails
        },
        method: "exact rational arithmetic: V's control vectors (-h_iy, h_ix, sigma_i) from the hodograph and speed coefficients; every sign pattern of the printed non-zero entries compared with the left and the right normal fields".into(),
        erratum: (wrong > 0 || !all45).then(|| {
            let differ: Vec<usize> = (0..3).filter(|&i| p[i] != left[i]).collect();
            let hodograph = (0..3).map(|i| {
                Equation::named(
                    &format!("h{i}"),
                    Expr::tuple(vec![hx.coeffs()[i].to_expr(), hy.coeffs()[i].to_expr()]),
                )
            });
            let speed =
                (0..3).map(|i| Equation::named(&format!("sigma{i}"), sigma.coeffs()[i].to_expr()));
            Box::new(Erratum {
                printed: differ
                    .iter()
                    .map(|&i| Equation::named(&format!("q{i}"), tuple3(&p[i])))
                    .collect(),
                corrected: differ
                    .iter()
                    .map(|&i| Equation::named(&format!("q{i}"), tuple3(&left[i])))
                    .collect(),
                correction: format!(
                    "the control vectors of the rotated normal field V(t) = (-Y'(t), X'(t), sigma(t)) are (-h_iy, h_ix, sigma_i) from the hodograph and speed coefficients; {} of 3 printed vectors differ from them ({})",
                    differ.len(),
                    if magnitudes_equal { "only in signs" } else { "in magnitudes too" }
                ),
                counter_example: hodograph.chain(speed).collect(),
                residual: differ
                    .iter()
                    .map(|&i| {
                        let diff: [Rational; 3] =
                            std::array::from_fn(|k| p[i][k].sub_ref(&left[i][k]));
                        Equation::new(
                            Expr::new(ExprKind::Sum(vec![
                                (AddOp::Plus, tuple3(&p[i])),
                                (AddOp::Minus, tuple3(&left[i])),
                            ])),
                            tuple3(&diff),
                        )
                    })
                    .collect(),
                notation: Vec::new(),
            })
        }),
        evidence,
    })
}

/// A triple as a tuple expression.
fn tuple3(p: &[Rational; 3]) -> Expr {
    Expr::tuple(p.iter().map(CoeffExpr::to_expr).collect())
}

// ------------------------------------------------------------------------------ ph_radius

fn root_text(t: &IsolatedRoot<Rational>) -> String {
    match t {
        IsolatedRoot::Exact(x) => format!("t = {x}"),
        IsolatedRoot::Between(lo, hi) => format!(
            "t in ({lo}, {hi}) (about {})",
            decimal(&radical(&t.midpoint()), 5)
        ),
    }
}

/// The cusps of the example's `r`-offset, each isolated root refined to width `<= 10^-6`.
fn cusps_of(curve: &PhCurve<Rational>, r: &Rational) -> Result<Vec<Cusp<Rational>>, String> {
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

fn cusps_text(cusps: &[Cusp<Rational>]) -> String {
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
fn cusps_from_offset(
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
pub(super) fn radius_check() -> Result<Outcome, String> {
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
fn radius_erratum(
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

// ------------------------------------------------------------------------------ ph_offsets

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

fn reading(r: &OffsetRow) -> String {
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
pub(super) fn offsets_check() -> Result<Outcome, String> {
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
fn offsets_erratum(
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_exact_r0_of_r_15_and_the_printed_digits() {
        let rows = ph_offsets_rows().unwrap();
        let x15 = rows
            .iter()
            .find(|r| r.r == "15" && r.name == "r0.x")
            .unwrap();
        assert_eq!(x15.exact, q(-300, 101));
        assert!(!x15.correctly_rounded);
        assert!(x15.reproduced_by.is_empty(), "{:?}", x15.reproduced_by);
        let x3 = rows
            .iter()
            .find(|r| r.r == "3" && r.name == "r0.x")
            .unwrap();
        assert_eq!(x3.exact, q(-60, 101));
        assert_eq!(
            x3.reproduced_by,
            vec![
                "the magnitude of the exact value correctly rounded (a lost minus sign)"
                    .to_string()
            ]
        );
        assert!(rows
            .iter()
            .filter(|r| r.name == "w0")
            .all(|r| r.correctly_rounded));
    }

    #[test]
    fn self_intersections_are_decided_exactly() {
        let (n, e) = self_intersections_of(&q(15, 1)).unwrap();
        assert_eq!(n, 1, "{e}");
        assert!(
            e.contains("2 cusps") && e.contains("1 self-intersection: C(s) = C(t)"),
            "{e}"
        );
        let (n, e) = self_intersections_of(&q(101, 8)).unwrap();
        assert_eq!(n, 0, "{e}");
        assert!(e.contains("1 cusp: t = 1/2 (multiplicity 2)"), "{e}");
        assert!(e.contains("no self-intersection (certified"), "{e}");
    }
}
