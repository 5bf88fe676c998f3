//! `solve` kind `ph_offset` (Chiang, "PH curves"): a planar Pythagorean-hodograph curve
//! from its preimage `u(t), v(t)` (Bernstein coefficients) and start point, its offsets at one
//! or several signed distances `r` as exact rational Bezier curves, the smallest radius of
//! curvature and the cusps of every offset, all decided exactly.
//!
//! # The mathematics (in [`exactcheck_core::ph`])
//! The hodograph is `B' = (u^2 - v^2, 2uv)`, its length the polynomial `sigma = u^2 + v^2`; the
//! base curve `B` (degree `n = 2k + 1`, in the plane `z = 0`) has the control points
//! `p_{i+1} = p_i + h_i / n`. The rotated normal field `V = (-Y', X', sigma)` (degree `n - 1`)
//! makes `B(t) + s V(t)` a ruled surface whose section by `z = r` is, by Chiang's theorem, the
//! rational Bezier curve of degree `2n - 1` with weight polynomial `sigma` (degree-elevated) and
//! points `C(t) = B(t) + (r / sigma) V(t)`: at distance exactly `|r|` from `B(t)` along the left
//! normal (right for `r < 0`), lifted to height `r`. The answer gives these control points with
//! `z = r` (`points`); their projection to `z = 0` is the planar offset.
//!
//! The signed curvature is `2 w / sigma^2` with `w = u v' - u' v`; the offset at distance `r`
//! has a cusp exactly where `sigma^2 - 2 r w = 0` (`r` equals the signed radius of curvature).
//! Its zeros in `[0, 1]` are isolated exactly (Bernstein–Descartes subdivision), rational ones
//! made exact (`rational_zeros`), the others refined to `precision`.
//!
//! # The smallest radius of curvature
//! Each side (left: `w > 0`, distances `r > 0`; right: `w < 0`, `r < 0`) is asked of
//! [`PhCurve::min_radius`], which returns the exact minimum when it is attained at an end point
//! or an exactly isolated critical point, and otherwise a certified enclosure `(lo, hi]`. Here
//! the enclosure is upgraded when the minimum sits at a *rational* critical point that the
//! subdivision only enclosed: the rational zeros of the critical polynomial
//! `2 sigma' w - sigma w'` are found exactly (`rational_zeros`, also for radical coefficients,
//! via the rational components), and the radius `m` there is accepted when `lo < m <= hi` and
//! [`PhCurve::is_min_radius`] proves it (`sigma^2 - 2 m w >= 0` on `[0, 1]` with a zero).
//! The two sides are then compared exactly: an exact value against an enclosure containing it
//! is decided by `is_min_radius` and by whether the other side's offset at that distance has a
//! cusp; two overlapping enclosures are reported as their joint enclosure, side
//! `left_or_right`. A curve with `w = 0` identically (a straight line) has no finite radius:
//! `min_radius_of_curvature` is `null`. Where it is attained (`at`): for an exact minimum `m`
//! the zeros of `sigma^2 - 2 m w`; for an enclosure the minimisers themselves, isolated as zeros
//! of the critical polynomial (`minimisers`).
//!
//! # Degenerate input
//! `u = v = 0` and unequal lengths are refused (one line naming the field). Where `sigma`
//! vanishes in `[0, 1]` (common zeros of `u` and `v`) the base curve is singular: the outcome is
//! `singular_base`, the offsets are still given (their weights vanish there: `poles`), and the
//! radius and cusps are `null`, because the curvature `2 w / sigma^2` and the cusp criterion
//! (which divides by `sigma`) are undefined at those parameters. `r = 0` is answered (the offset
//! is the curve itself, degree-elevated) with the outcome `r_zero`.
//!
//! # Float mode
//! `--float` runs the same generic code in `f64`: zero tests are comparisons with `0.0` and the
//! root isolation stops where f64 cannot halve an interval, so multiplicities, exact parameters
//! and the singular-base test are heuristics there; the radius enclosure is bisected to a width
//! relative to the radii sampled along the curve (an absolute `2^-50` would be below the f64
//! spacing of radii larger than 1/2, and the bisection would not end).
//!
//! # Limits
//! At most [`MAX_COEFFICIENTS`] coefficients in `u` and `v` (degree `4k <= 60` of the cusp
//! polynomial, whose Bernstein products use binomial coefficients in 64-bit integers). In exact
//! mode their sizes in bits together are held to the `ph-bits` limit before any work.

use super::number::{Coords, ExactNumber, FieldNumber, FloatNumber};
use super::scalar::{Scalar, DEFAULT_WIDTH_LOG2};
use super::{parse, FloatKind, Kind};
use crate::Error;
use exactcheck_core::ph::PhCurve;
use exactcheck_core::{Bernstein, Sign, Vec3};
use exactcheck_exact::Rational;
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::de::{Deserializer, Error as _};
use serde::Deserialize;
use serde_json::Value;
use std::borrow::Cow;

mod answer;
mod compute;

use answer::{render, Answer, OffsetOut};
use compute::compute;

/// The most Bernstein coefficients accepted in `u` and `v` (`k <= 15`).
pub const MAX_COEFFICIENTS: usize = 16;

// ------------------------------------------------------------------ input

/// One offset distance or a non-empty list of them.
#[derive(Debug)]
pub enum Radii<N> {
    /// `"r": 3`: one offset, answered at the top level of the answer.
    One(N),
    /// `"r": [3, "63/5"]`: one offset per distance, in `offsets`.
    Many(Vec<N>),
}

impl<'de, N: Deserialize<'de>> Deserialize<'de> for Radii<N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match Value::deserialize(d)? {
            Value::Array(items) => {
                if items.is_empty() {
                    return Err(D::Error::custom(
                        "an empty array: give one distance or a non-empty array of distances",
                    ));
                }
                items
                    .into_iter()
                    .enumerate()
                    .map(|(i, x)| {
                        N::deserialize(x).map_err(|e| D::Error::custom(format!("element {i}: {e}")))
                    })
                    .collect::<Result<Vec<N>, D::Error>>()
                    .map(Radii::Many)
            }
            other => N::deserialize(other)
                .map(Radii::One)
                .map_err(D::Error::custom),
        }
    }
}

impl<N: JsonSchema> JsonSchema for Radii<N> {
    fn schema_name() -> Cow<'static, str> {
        format!("Radii_{}", N::schema_name()).into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let item = generator.subschema_for::<N>();
        json_schema!({
            "description": "The signed offset distance r (r > 0: left of the direction of travel, r < 0: right), or a non-empty array of distances: one offset is answered per distance (in `offsets`, in the given order); a single number answers the offset's fields at the top level.",
            "anyOf": [item.clone(), {"type": "array", "items": item, "minItems": 1}]
        })
    }
}

/// The problem, with numbers of type `N` ([`ExactNumber`] in exact mode, [`FloatNumber`] with
/// `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "ph_offset",
    description = "A planar Pythagorean-hodograph curve from u(t), v(t) in Bernstein form (same number of coefficients, 1..16; degree n = 2k + 1) and its start point, and its offsets at the signed distances r as exact rational Bezier curves of degree 2n - 1 (Chiang's cyclographic construction: the section of B(t) + s V(t) by z = r), with the smallest radius of curvature and every offset's cusps decided exactly. Exact mode reads exact numbers (sqrt allowed); --float any finite number."
)]
pub struct Input<N> {
    /// `"ph_offset"`.
    #[schemars(extend("const" = "ph_offset"))]
    pub kind: String,
    /// The Bernstein coefficients of `u` (at least one, at most 16).
    pub u: Vec<N>,
    /// The Bernstein coefficients of `v` (as many as `u`; `u` and `v` not both zero).
    pub v: Vec<N>,
    /// The start point `[x, y]` of the curve (its first control point).
    pub start: Coords<N, 2>,
    /// The signed offset distance, or a non-empty array of distances.
    pub r: Radii<N>,
    /// The width to which irrational parameters and an irrational smallest radius are enclosed
    /// (positive; default 2^-50).
    pub precision: Option<N>,
}

/// `2^-DEFAULT_WIDTH_LOG2`.
fn default_width() -> Rational {
    format!("1/{}", 1u64 << DEFAULT_WIDTH_LOG2)
        .parse()
        .expect("a rational literal")
}

/// The problem in the scalar `T`, checked.
struct Problem<T> {
    curve: PhCurve<T>,
    radii: Vec<T>,
    single: bool,
    width: T,
}

fn problem<N, T: Scalar>(input: &Input<N>, num: impl Fn(&N) -> T) -> Result<Problem<T>, Error> {
    for (name, list) in [("u", &input.u), ("v", &input.v)] {
        if list.is_empty() {
            return Err(Error::Input(format!(
                "{name}: at least one Bernstein coefficient is needed (k + 1 for degree k)"
            )));
        }
        if list.len() > MAX_COEFFICIENTS {
            return Err(Error::Input(format!(
                "{name}: {} Bernstein coefficients, at most {MAX_COEFFICIENTS} are supported",
                list.len()
            )));
        }
    }
    if input.u.len() != input.v.len() {
        return Err(Error::Input(format!(
            "v: {} Bernstein coefficients but u has {}: u and v must have the same degree",
            input.v.len(),
            input.u.len()
        )));
    }
    let u = Bernstein::new(input.u.iter().map(&num).collect());
    let v = Bernstein::new(input.v.iter().map(&num).collect());
    if u.is_zero() && v.is_zero() {
        return Err(Error::Input(
            "u, v: both are zero, so the hodograph (u^2 - v^2, 2uv) vanishes: there is no curve"
                .into(),
        ));
    }
    let Coords([x, y]) = &input.start;
    let start = Vec3::new(num(x), num(y), T::zero());
    let curve = PhCurve::new(u, v, start).map_err(|e| Error::Input(format!("u, v: {e}")))?;
    let width = match &input.precision {
        Some(p) => {
            let w = num(p);
            if w.sign() != Sign::Positive {
                return Err(Error::Input("precision: must be positive".into()));
            }
            super::number::check_precision(&w)?;
            w
        }
        None => T::from_rational(&default_width()),
    };
    let (radii, single) = match &input.r {
        Radii::One(r) => (vec![num(r)], true),
        Radii::Many(rs) => (rs.iter().map(&num).collect(), false),
    };
    Ok(Problem {
        curve,
        radii,
        single,
        width,
    })
}

fn exact_answer<N, T: Scalar>(
    input: &Input<N>,
    lift: impl Fn(&N) -> T,
) -> Result<Answer<String>, Error> {
    let p = problem(input, lift)?;
    Ok(render(&compute(p), "exact", ToString::to_string))
}

/// Every number of the problem.
fn numbers(input: &Input<ExactNumber>) -> impl Iterator<Item = &ExactNumber> {
    let radii: Vec<&ExactNumber> = match &input.r {
        Radii::One(r) => vec![r],
        Radii::Many(rs) => rs.iter().collect(),
    };
    input
        .u
        .iter()
        .chain(&input.v)
        .chain(input.start.0.iter())
        .chain(radii)
        .chain(input.precision.iter())
}

/// The largest base degree whose offsets get `self_intersections` (the exact resultant behind
/// it grows fast: a septic's offsets take seconds, see `exactcheck_exact::planar`).
pub const SELF_INTERSECTION_MAX_DEGREE: usize = 5;

/// The name of a crossing's certificate in the answer.
fn certificate_name(c: exactcheck_exact::planar::Certificate) -> &'static str {
    use exactcheck_exact::planar::Certificate;
    match c {
        Certificate::Exact => "Exact",
        Certificate::RationalParameter => "RationalParameter",
        Certificate::PoincareMiranda => "PoincareMiranda",
    }
}

/// The offset's self-intersections for `solve`: decided exactly by
/// [`exactcheck_exact::planar::self_intersections_xy`] (every crossing certified, or certified
/// none), or why not (a singular base, a degree above [`SELF_INTERSECTION_MAX_DEGREE`], a
/// contact the finder cannot certify).
fn self_intersections(curve: &PhCurve<Rational>, r: &Rational) -> Value {
    use exactcheck_exact::planar::{self_intersections_xy, Budget};
    let interval = |ri: &exactcheck_exact::univariate::RootInterval| {
        serde_json::json!({
            "interval": [ri.lo.to_string(), ri.hi.to_string()],
            "approx": ri.to_f64(),
        })
    };
    if curve.degree() > SELF_INTERSECTION_MAX_DEGREE {
        return serde_json::json!({
            "decided": false,
            "note": format!("not computed for base degree {} > {SELF_INTERSECTION_MAX_DEGREE} (the exact resultant grows quickly)", curve.degree()),
        });
    }
    if !curve.speed_zeros().is_empty() {
        return serde_json::json!({
            "decided": false,
            "note": "the base curve is singular in [0, 1], so the offset has poles",
        });
    }
    match self_intersections_xy(&curve.offset(r), Budget::default()) {
        Ok(found) => serde_json::json!({
            "decided": true,
            "count": found.crossings.len(),
            "crossings": found.crossings.iter().map(|c| serde_json::json!({
                "s": interval(&c.s_interval),
                "t": interval(&c.t_interval),
                "point_approx": c.point,
                "certificate": certificate_name(c.certificate),
            })).collect::<Vec<_>>(),
        }),
        Err(e) => serde_json::json!({"decided": false, "note": e.to_string()}),
    }
}

fn exact(input: Input<ExactNumber>) -> Result<Answer<String>, Error> {
    // Checked before any work: the exact curve's coefficients grow from these.
    let bits = input
        .u
        .iter()
        .chain(&input.v)
        .map(|x| exactcheck_exact::expr::Coefficient::size_bits(&x.0))
        .fold(0u64, u64::saturating_add);
    crate::limits::PH_BITS
        .check(bits)
        .map_err(|e| Error::Input(format!("u, v: {e}")))?;
    // Rational input runs over the (faster) rationals; radicals over the radical field.
    if numbers(&input).all(|x| x.0.is_rational()) {
        let mut answer = exact_answer(&input, |x: &ExactNumber| {
            x.0.to_rational()
                .expect("is_rational was checked for every number")
        })?;
        let p = problem(&input, |x| {
            x.0.to_rational()
                .expect("is_rational was checked for every number")
        })?;
        let outs = answer
            .single
            .iter_mut()
            .chain(answer.offsets.iter_mut().flatten());
        for (out, r) in outs.zip(&p.radii) {
            out.self_intersections = Some(self_intersections(&p.curve, r));
        }
        Ok(answer)
    } else {
        exact_answer(&input, |x: &ExactNumber| x.0.clone())
    }
}

/// The exact answer in the problem's number field (values outside the radical field); the
/// size check of [`exact`] applies to the field elements' coefficients.
fn exact_in_field(input: Input<FieldNumber>) -> Result<Answer<String>, Error> {
    let bits = input
        .u
        .iter()
        .chain(&input.v)
        .flat_map(|x| x.0.poly().coeffs().to_vec())
        .map(|c| exactcheck_exact::expr::Coefficient::size_bits(&c))
        .fold(0u64, u64::saturating_add);
    crate::limits::PH_BITS
        .check(bits)
        .map_err(|e| Error::Input(format!("u, v: {e}")))?;
    exact_answer(&input, |x: &FieldNumber| x.0.clone())
}

fn float_answer(input: Input<FloatNumber>) -> Result<Answer<f64>, Error> {
    let p = problem(&input, |x| x.0)?;
    let overflow = || {
        Error::Input(
            "the f64 computation overflows or underflows for these numbers; use exact mode".into(),
        )
    };
    // The core code expects the exact facts sigma != 0 and sigma^2 - 2 r w != 0 as polynomials;
    // in f64 the products can underflow to zero or overflow.
    let sigma = p.curve.speed();
    if sigma.is_zero() || sigma.coeffs().iter().any(|x| !x.is_finite()) {
        return Err(overflow());
    }
    for r in &p.radii {
        let f = p.curve.cusp_polynomial(r);
        if f.is_zero() || f.coeffs().iter().any(|x| !x.is_finite()) {
            return Err(overflow());
        }
    }
    let computed = compute(p);
    // The singular-base test is a heuristic in f64 (a zero of u^2 + v^2 at an end of [0, 1] can
    // be lost to rounding in the power-basis round trip): a cusp where the offset's weight is
    // exactly zero in f64 is such a missed singular point, and is reported instead of evaluated.
    for o in &computed.offsets {
        for (t, _) in o.cusps.iter().flatten() {
            let at = t.exact().copied().unwrap_or_else(|| t.midpoint());
            if o.curve.eval(&at).is_err() {
                return Err(Error::Input(format!(
                    "in f64 the offset's weight vanishes at the cusp parameter t = {at}: the base curve is singular there (u^2 + v^2 = 0), which the f64 heuristics cannot decide; use exact mode"
                )));
            }
        }
    }
    let answer = render(&computed, "float", |x: &f64| *x + 0.0);
    let finite = |list: &[OffsetOut<f64>]| {
        list.iter().all(|o| {
            o.weights.iter().all(|x| x.is_finite())
                && o.weighted_points.iter().flatten().all(|x| x.is_finite())
        })
    };
    let ok = answer
        .single
        .iter()
        .all(|o| finite(std::slice::from_ref(o)))
        && answer.offsets.as_deref().is_none_or(finite)
        && answer.base.iter().flatten().all(|x| x.is_finite());
    if !ok {
        return Err(overflow());
    }
    Ok(answer)
}

/// A `ph_offset` problem with rational numbers, read and checked as `solve` reads it: the curve
/// and the distances (for `plot FILE.json`).
///
/// # Errors
/// What `solve` refuses, and [`Error::Input`] for irrational numbers (the figure is computed
/// over the rationals).
pub fn rational_problem(text: &str) -> Result<(PhCurve<Rational>, Vec<Rational>), Error> {
    let input: Input<ExactNumber> = parse(text)?;
    if let Some(x) = numbers(&input).find(|x| !x.0.is_rational()) {
        return Err(Error::Input(format!(
            "{}: plot draws ph_offset problems with rational numbers only (solve answers radical ones)",
            x.0
        )));
    }
    let p = problem(&input, |x| {
        x.0.to_rational()
            .expect("every number was checked rational")
    })?;
    Ok((p.curve, p.radii))
}

/// The kind.
pub struct PhOffset;

impl Kind for PhOffset {
    const NAME: &'static str = "ph_offset";
    type Input = Input<ExactNumber>;
    type Answer = Answer<String>;

    fn compute(input: Self::Input) -> Result<Self::Answer, Error> {
        exact(input)
    }

    fn compute_in_field(problem: &super::Problem) -> Result<Self::Answer, Error> {
        exact_in_field(problem.input_in_field(&[])?)
    }
}

impl FloatKind for PhOffset {
    type FloatInput = Input<FloatNumber>;
    type FloatAnswer = Answer<f64>;

    fn compute_float(input: Self::FloatInput) -> Result<Self::FloatAnswer, Error> {
        float_answer(input)
    }
}

impl super::FloatSlot for Answer<String> {
    type Float = Answer<f64>;
    fn float_slot(&mut self) -> &mut Option<Box<Answer<f64>>> {
        &mut self.float
    }
}

#[cfg(test)]
mod tests {
    use super::compute::{side_radius, Sides};
    use super::*;
    use exactcheck_core::ph::{MinRadius, RadiusBound, Side};
    use exactcheck_core::roots::IsolatedRoot;
    use exactcheck_exact::Rational;

    fn q(s: &str) -> Rational {
        s.parse().expect("a rational")
    }

    fn solve(text: &str) -> Value {
        crate::solve::solve(text, crate::solve::Mode::Exact).expect("answered")
    }

    #[test]
    fn chiang_example_radius_is_exact() {
        let a = solve(r#"{"kind":"ph_offset","u":[10,-1],"v":[1,10],"start":[0,0],"r":3}"#);
        assert_eq!(a["outcome"], "offset");
        assert_eq!(a["degree"], 5);
        assert_eq!(a["base"][1], serde_json::json!(["33", "20/3"]));
        let m = &a["min_radius_of_curvature"];
        assert_eq!(m["side"], "left");
        // sigma(t) = 101 (1 - t)^2 + ... ; the minimum is checked with is_min_radius.
        let value: Rational = q(m["exact"].as_str().expect("exact"));
        let c = crate::claims::chiang_ph::example_curve();
        assert!(c.is_min_radius(&value, Side::Left).unwrap());
        assert!(a["cusps"].as_array().unwrap().is_empty());
    }

    #[test]
    fn a_rational_critical_point_the_subdivision_only_encloses_is_made_exact() {
        // Found by search: core's min_radius encloses the right side's minimum (its critical
        // point 1/4 is only enclosed by the subdivision of 2 sigma' w - sigma w'); the rational
        // zeros of that polynomial make it exact, 9/32, proved by is_min_radius.
        let c = PhCurve::new(
            Bernstein::new(vec![q("-1/2"), q("-1"), q("-3/2")]),
            Bernstein::new(vec![q("-3/2"), q("1/2"), q("-3/2")]),
            Vec3::new(q("0"), q("0"), q("0")),
        )
        .unwrap();
        let tol = q("1/1024");
        let MinRadius { value, .. } = c.min_radius(Side::Right, &tol).unwrap().unwrap();
        assert!(matches!(value, RadiusBound::Within(..)), "{value:?}");
        let r = side_radius(&c, Side::Right, &tol, &tol).unwrap();
        assert_eq!(r.value, RadiusBound::Exact(q("9/32")));
        assert_eq!(r.at, vec![IsolatedRoot::Exact(q("1/4"))]);
        assert_eq!(r.sides, Sides::Right);
        assert!(c.is_min_radius(&q("9/32"), Side::Right).unwrap());
    }
}
