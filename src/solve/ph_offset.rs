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
//! made exact ([`rational_zeros`]), the others refined to `precision`.
//!
//! # The smallest radius of curvature
//! Each side (left: `w > 0`, distances `r > 0`; right: `w < 0`, `r < 0`) is asked of
//! [`PhCurve::min_radius`], which returns the exact minimum when it is attained at an end point
//! or an exactly isolated critical point, and otherwise a certified enclosure `(lo, hi]`. Here
//! the enclosure is upgraded when the minimum sits at a *rational* critical point that the
//! subdivision only enclosed: the rational zeros of the critical polynomial
//! `2 sigma' w - sigma w'` are found exactly ([`rational_zeros`], also for radical coefficients,
//! via the rational components), and the radius `m` there is accepted when `lo < m <= hi` and
//! [`PhCurve::is_min_radius`] proves it (`sigma^2 - 2 m w >= 0` on `[0, 1]` with a zero).
//! The two sides are then compared exactly: an exact value against an enclosure containing it
//! is decided by `is_min_radius` and by whether the other side's offset at that distance has a
//! cusp; two overlapping enclosures are reported as their joint enclosure, side
//! `left_or_right`. A curve with `w = 0` identically (a straight line) has no finite radius:
//! `min_radius_of_curvature` is `null`. Where it is attained (`at`): for an exact minimum `m`
//! the zeros of `sigma^2 - 2 m w`; for an enclosure the minimisers themselves, isolated as zeros
//! of the critical polynomial ([`minimisers`]).
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

use super::number::{
    rational_zeros, unit_zeros, Coords, ExactNumber, FloatNumber, SectionScalar, DEFAULT_WIDTH_LOG2,
};
use super::{by_mode, parse, Kind, Mode};
use crate::Error;
use exactcheck_core::ph::{MinRadius, PhCurve, RadiusBound, Side};
use exactcheck_core::roots::{self, IsolatedRoot};
use exactcheck_core::{Bernstein, RationalBezierCurve, Ring, Sign, Vec3};
use exactcheck_exact::{Radical, Rational};
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::de::{Deserializer, Error as _};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::borrow::Cow;

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

fn problem<N, T: SectionScalar>(
    input: &Input<N>,
    num: impl Fn(&N) -> T,
) -> Result<Problem<T>, Error> {
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

// ------------------------------------------------------------------ the computation

/// Which sides attain the overall smallest radius.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sides {
    Left,
    Right,
    Both,
    /// Two overlapping enclosures: not decided at this precision.
    Undecided,
}

impl Sides {
    fn of(side: Side) -> Self {
        match side {
            Side::Left => Sides::Left,
            Side::Right => Sides::Right,
        }
    }

    fn name(self) -> &'static str {
        match self {
            Sides::Left => "left",
            Sides::Right => "right",
            Sides::Both => "both",
            Sides::Undecided => "left_or_right",
        }
    }
}

/// A smallest radius with the side(s) attaining it.
#[derive(Clone, Debug)]
struct Radius<T> {
    value: RadiusBound<T>,
    sides: Sides,
    at: Vec<IsolatedRoot<T>>,
}

fn signed<T: Ring>(side: Side, m: &T) -> T {
    match side {
        Side::Left => m.clone(),
        Side::Right => m.neg_ref(),
    }
}

/// The parameters where `sigma^2 - 2 r w` vanishes, rational ones exact, the others refined.
fn cusp_zeros<T: SectionScalar>(curve: &PhCurve<T>, r: &T, width: &T) -> Vec<IsolatedRoot<T>> {
    unit_zeros(&curve.cusp_polynomial(r), width)
}

/// One side's smallest radius, upgraded to exact at a rational critical point (module doc).
fn side_radius<T: SectionScalar>(
    curve: &PhCurve<T>,
    side: Side,
    tolerance: &T,
    width: &T,
) -> Option<Radius<T>> {
    let MinRadius { value, .. } = curve
        .min_radius(side, tolerance)
        .expect("called only when sigma has no zero in [0, 1]")?;
    let value = match value {
        RadiusBound::Within(lo, hi) if T::EXACT => {
            let crit = curve.radius_critical_polynomial();
            let exact = if crit.is_zero() {
                None
            } else {
                rational_zeros(&crit.to_power()).into_iter().find_map(|t| {
                    let m = signed(side, &curve.radius_at(&t)?);
                    (m > lo
                        && m <= hi
                        && curve
                            .is_min_radius(&m, side)
                            .expect("sigma has no zero in [0, 1]"))
                    .then_some(m)
                })
            };
            match exact {
                Some(m) => RadiusBound::Exact(m),
                None => RadiusBound::Within(lo, hi),
            }
        }
        other => other,
    };
    let at = match &value {
        RadiusBound::Exact(m) => cusp_zeros(curve, &signed(side, m), width),
        RadiusBound::Within(_, hi) => minimisers(curve, side, hi, width),
    };
    Some(Radius {
        at,
        value,
        sides: Sides::of(side),
    })
}

/// Where `side`'s radius `rho` attains its minimum when only an enclosure `(lo, hi]` of the
/// minimum is known (module doc): the zeros in `[0, 1]` of the critical polynomial
/// `2 sigma' w - sigma w'` (isolated by [`unit_zeros`], rational ones exact, the others refined
/// to `width`) that are local minima of `rho` with `rho <= hi` there. The minimum is attained
/// at an interior critical point, so it is attained among them. A local minimum is a zero
/// where the critical polynomial, signed for the side, changes sign from negative to positive
/// (`rho'` has the sign of `sigma (2 sigma' w - sigma w')` on the left, the opposite on the
/// right); `rho <= hi` is the sign of `sigma^2 - 2 hi w` there, decided exactly
/// ([`roots::sign_at_root`]). An exact zero is kept when [`PhCurve::is_min_radius`] proves
/// its radius the minimum.
fn minimisers<T: SectionScalar>(
    curve: &PhCurve<T>,
    side: Side,
    hi: &T,
    width: &T,
) -> Vec<IsolatedRoot<T>> {
    let crit = curve.radius_critical_polynomial();
    if crit.is_zero() {
        return Vec::new();
    }
    let crit_side = match side {
        Side::Left => crit.clone(),
        Side::Right => crit.map(Ring::neg_ref),
    };
    let below = curve.cusp_polynomial(&signed(side, hi));
    unit_zeros(&crit, width)
        .into_iter()
        .filter(|c| match c {
            IsolatedRoot::Exact(t) => curve.radius_at(t).is_some_and(|r| {
                let m = signed(side, &r);
                m.sign() == Sign::Positive
                    && curve
                        .is_min_radius(&m, side)
                        .expect("sigma has no zero in [0, 1]")
            }),
            IsolatedRoot::Between(a, b) => {
                crit_side.eval(a).sign() == Sign::Negative
                    && crit_side.eval(b).sign() == Sign::Positive
                    && roots::sign_at_root(&below, &crit, c) != Sign::Positive
            }
        })
        .collect()
}

/// Whether the offset at `side`'s distance `m > 0` has a cusp: `m >= rho_min(side)`.
fn reaches<T: SectionScalar>(curve: &PhCurve<T>, side: Side, m: &T) -> bool {
    !curve
        .offset_cusps(&signed(side, m))
        .expect("sigma has no zero in [0, 1]")
        .is_empty()
}

/// The smaller of the two sides' radii, compared exactly (module doc).
fn overall<T: SectionScalar>(
    curve: &PhCurve<T>,
    left: Option<Radius<T>>,
    right: Option<Radius<T>>,
) -> Option<Radius<T>> {
    use RadiusBound::{Exact, Within};
    let (a, b) = match (left, right) {
        (None, x) | (x, None) => return x,
        (Some(a), Some(b)) => (a, b),
    };
    let both = |value: RadiusBound<T>, sides: Sides, a: &Radius<T>, b: &Radius<T>| {
        let mut at = a.at.clone();
        at.extend(b.at.iter().cloned());
        Radius { value, sides, at }
    };
    match (&a.value, &b.value) {
        (Exact(x), Exact(y)) => Some(if x < y {
            a
        } else if y < x {
            b
        } else {
            both(Exact(x.clone()), Sides::Both, &a, &b)
        }),
        (Exact(_), Within(..)) | (Within(..), Exact(_)) => {
            let (e, w) = if matches!(a.value, Exact(_)) {
                (a, b)
            } else {
                (b, a)
            };
            let (Exact(x), Within(lo, hi)) = (&e.value, &w.value) else {
                unreachable!("matched one exact and one enclosed value above")
            };
            let other = match w.sides {
                Sides::Left => Side::Left,
                _ => Side::Right,
            };
            Some(if x <= lo {
                e
            } else if x > hi {
                w
            } else if curve
                .is_min_radius(x, other)
                .expect("sigma has no zero in [0, 1]")
            {
                both(Exact(x.clone()), Sides::Both, &e, &w)
            } else if reaches(curve, other, x) {
                // rho_other < x <= hi: the enclosure shrinks to (lo, x).
                Radius {
                    value: Within(lo.clone(), x.clone()),
                    ..w
                }
            } else {
                e
            })
        }
        (Within(lo_a, hi_a), Within(lo_b, hi_b)) => Some(if hi_a <= lo_b {
            a
        } else if hi_b <= lo_a {
            b
        } else {
            let lo = if lo_a < lo_b { lo_a } else { lo_b }.clone();
            let hi = if hi_a < hi_b { hi_a } else { hi_b }.clone();
            both(Within(lo, hi), Sides::Undecided, &a, &b)
        }),
    }
}

/// One offset, computed.
struct OffsetData<T> {
    r: T,
    outcome: &'static str,
    curve: RationalBezierCurve<T>,
    /// `None` on a singular base.
    cusps: Option<Vec<(IsolatedRoot<T>, usize)>>,
}

/// Everything the answer reports, in `T`.
struct Computed<T> {
    curve: PhCurve<T>,
    singular: bool,
    poles: Vec<IsolatedRoot<T>>,
    line: bool,
    left: Option<Radius<T>>,
    right: Option<Radius<T>>,
    min: Option<Radius<T>>,
    offsets: Vec<OffsetData<T>>,
    single: bool,
}

/// The tolerance of the radius bisection: `width` in exact arithmetic; in f64 at least `1e-9`
/// times the largest radius sampled where the curve bends (module doc, "Float mode").
fn radius_tolerance<T: SectionScalar>(curve: &PhCurve<T>, width: &T) -> T {
    if T::EXACT {
        return width.clone();
    }
    let mut scale = T::one();
    for k in 0..=256 {
        let t = T::from_i64(k) / T::from_i64(256);
        if let Some(rho) = curve.radius_at(&t) {
            let a = rho.abs();
            if a > scale && a.approx().is_finite() {
                scale = a;
            }
        }
    }
    let rel =
        scale * T::from_rational(&Rational::new(1, 1_000_000_000).expect("a non-zero denominator"));
    if rel > *width {
        rel
    } else {
        width.clone()
    }
}

fn compute<T: SectionScalar>(p: Problem<T>) -> Computed<T> {
    let Problem {
        curve,
        radii,
        single,
        width,
    } = p;
    let zeros = curve.speed_zeros();
    let singular = !zeros.is_empty();
    // Over the reals the zeros of sigma = u^2 + v^2 are exactly the common zeros of u and v;
    // exact mode gives them as sigma's zeros (rational ones exact, the others refined).
    let poles = if singular && T::EXACT {
        unit_zeros(&curve.speed(), &width)
    } else {
        zeros
    };
    let line = curve.curvature_numerator().is_zero();
    let (left, right, min) = if singular {
        (None, None, None)
    } else {
        let tol = radius_tolerance(&curve, &width);
        let left = side_radius(&curve, Side::Left, &tol, &width);
        let right = side_radius(&curve, Side::Right, &tol, &width);
        let min = overall(&curve, left.clone(), right.clone());
        (left, right, min)
    };
    let offsets = radii
        .into_iter()
        .map(|r| {
            let outcome = if singular {
                "singular_base"
            } else if r.is_zero() {
                "r_zero"
            } else {
                "offset"
            };
            let cusps = (!singular).then(|| {
                let poly = curve.cusp_polynomial(&r);
                cusp_zeros(&curve, &r, &width)
                    .into_iter()
                    .map(|t| {
                        let m = roots::multiplicity(&poly, &t);
                        (t, m)
                    })
                    .collect()
            });
            OffsetData {
                curve: curve.offset(&r),
                r,
                outcome,
                cusps,
            }
        })
        .collect();
    Computed {
        curve,
        singular,
        poles,
        line,
        left,
        right,
        min,
        offsets,
        single,
    }
}

// ------------------------------------------------------------------ answers

/// A parameter in `[0, 1]`: an isolating interval, its midpoint, and the value when exact.
#[derive(Debug, Serialize)]
struct Parameter<V> {
    interval: [V; 2],
    approx: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    exact: Option<V>,
}

fn parameter<T: SectionScalar, V>(z: &IsolatedRoot<T>, v: &impl Fn(&T) -> V) -> Parameter<V> {
    match z {
        IsolatedRoot::Exact(t) => Parameter {
            interval: [v(t), v(t)],
            approx: t.approx(),
            exact: Some(v(t)),
        },
        IsolatedRoot::Between(lo, hi) => Parameter {
            interval: [v(lo), v(hi)],
            approx: z.midpoint().approx(),
            exact: None,
        },
    }
}

/// The smallest radius of curvature.
#[derive(Debug, Serialize)]
struct RadiusOut<V> {
    #[serde(skip_serializing_if = "Option::is_none")]
    exact: Option<V>,
    /// `[lo, hi]`: `lo < rho_min <= hi`.
    #[serde(skip_serializing_if = "Option::is_none")]
    interval: Option<[V; 2]>,
    approx: f64,
    side: &'static str,
    /// Where it is attained: the zeros of `sigma^2 - 2 m w` (exact value `m`), or the local
    /// minima of the radius at most `hi` (enclosure `(lo, hi]`), isolated exactly.
    at: Vec<Parameter<V>>,
}

#[derive(Debug, Serialize)]
struct BySide<V> {
    left: Option<RadiusOut<V>>,
    right: Option<RadiusOut<V>>,
}

/// A cusp of an offset.
#[derive(Debug, Serialize)]
struct CuspOut<V> {
    t: Parameter<V>,
    /// As a zero of `sigma^2 - 2 r w` (exact mode only: f64 cannot decide it).
    #[serde(skip_serializing_if = "Option::is_none")]
    multiplicity: Option<usize>,
    /// The offset point at an exact parameter (`[x, y, r]`).
    #[serde(skip_serializing_if = "Option::is_none")]
    point: Option<[V; 3]>,
    /// The offset point at the parameter's midpoint, in f64.
    point_approx: [f64; 3],
}

#[derive(Debug, Serialize)]
struct OffsetApprox {
    weights: Vec<f64>,
    points: Vec<Option<[f64; 3]>>,
}

/// One offset.
#[derive(Debug, Serialize)]
struct OffsetOut<V> {
    r: V,
    outcome: &'static str,
    /// The weights `w_k` (the speed `sigma`, degree-elevated to `2n - 1`).
    weights: Vec<V>,
    /// The control points `[x, y, r]` (`null` where the weight is 0).
    points: Vec<Option<[V; 3]>>,
    /// `w_k` times the control points: always defined (a direction where `w_k = 0`).
    weighted_points: Vec<[V; 3]>,
    /// `null` on a singular base.
    cusps: Option<Vec<CuspOut<V>>>,
    /// Exact mode, rational input only: the offset's self-intersections, decided exactly
    /// ([`self_intersections`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    self_intersections: Option<Value>,
    #[serde(skip_serializing_if = "Option::is_none")]
    approx: Option<OffsetApprox>,
}

/// The answer, with numbers of type `V` (exact strings, or f64 with `--float`).
#[derive(Debug, Serialize)]
struct Answer<V> {
    kind: &'static str,
    mode: &'static str,
    /// For an array of distances: `offsets` or `singular_base` (a single distance: the offset's
    /// own `outcome`, flattened below).
    #[serde(skip_serializing_if = "Option::is_none")]
    outcome: Option<&'static str>,
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    single: Option<OffsetOut<V>>,
    base_degree: usize,
    degree: usize,
    base: Vec<[V; 2]>,
    hodograph: Vec<[V; 2]>,
    speed: Vec<V>,
    rotated_normal: Vec<[V; 3]>,
    curvature_numerator: Vec<V>,
    poles: Vec<Parameter<V>>,
    min_radius_of_curvature: Option<RadiusOut<V>>,
    min_radius_by_side: Option<BySide<V>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    note: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    offsets: Option<Vec<OffsetOut<V>>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    base_approx: Option<Vec<[f64; 2]>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<Box<Answer<f64>>>,
}

const SINGULAR_NOTE: &str = "the parametric speed u^2 + v^2 vanishes at the parameters in `poles`: the base curve is singular there and every offset has a pole there; the curvature 2w/sigma^2 and the cusp criterion sigma^2 - 2rw = 0 are undefined at those parameters, so no radius of curvature and no cusps are given";
const LINE_NOTE: &str = "w = u v' - u' v is identically zero: the curve is a straight line, its radius of curvature is infinite and its offsets have no cusps";

fn radius_out<T: SectionScalar, V>(r: &Radius<T>, v: &impl Fn(&T) -> V) -> RadiusOut<V> {
    let two = T::from_i64(2);
    let (exact, interval, approx) = match &r.value {
        RadiusBound::Exact(m) => (Some(v(m)), None, m.approx()),
        RadiusBound::Within(lo, hi) => {
            (None, Some([v(lo), v(hi)]), (lo.add_ref(hi) / two).approx())
        }
    };
    RadiusOut {
        exact,
        interval,
        approx,
        side: r.sides.name(),
        at: r.at.iter().map(|z| parameter(z, v)).collect(),
    }
}

fn xy<T, V>(p: &Vec3<T>, v: &impl Fn(&T) -> V) -> [V; 2] {
    [v(&p.x), v(&p.y)]
}

fn three<T, V>(p: &Vec3<T>, v: &impl Fn(&T) -> V) -> [V; 3] {
    [v(&p.x), v(&p.y), v(&p.z)]
}

fn offset_out<T: SectionScalar, V>(o: &OffsetData<T>, v: &impl Fn(&T) -> V) -> OffsetOut<V> {
    let weights = o.curve.weights();
    let points = o.curve.points();
    let approx3 = |p: &Vec3<T>| three(p, &SectionScalar::approx);
    let cusps = o.cusps.as_ref().map(|cs| {
        cs.iter()
            .map(|(t, multiplicity)| {
                let at = |t: &T| {
                    o.curve
                        .eval(t)
                        .expect("the weight sigma has no zero in [0, 1] on a regular base")
                };
                CuspOut {
                    t: parameter(t, v),
                    multiplicity: T::EXACT.then_some(*multiplicity),
                    point: t.exact().map(|t| three(&at(t), v)),
                    point_approx: approx3(&at(&t.midpoint())),
                }
            })
            .collect()
    });
    OffsetOut {
        r: v(&o.r),
        outcome: o.outcome,
        weights: weights.iter().map(v).collect(),
        points: points
            .iter()
            .map(|p| p.as_ref().map(|p| three(p, v)))
            .collect(),
        weighted_points: o
            .curve
            .control()
            .iter()
            .map(|h| [v(&h.0[1]), v(&h.0[2]), v(&h.0[3])])
            .collect(),
        cusps,
        self_intersections: None,
        approx: T::EXACT.then(|| OffsetApprox {
            weights: weights.iter().map(SectionScalar::approx).collect(),
            points: points.iter().map(|p| p.as_ref().map(approx3)).collect(),
        }),
    }
}

fn render<T: SectionScalar, V>(
    c: &Computed<T>,
    mode: &'static str,
    v: impl Fn(&T) -> V,
) -> Answer<V> {
    let base = c.curve.base();
    let [hx, hy] = c.curve.hodograph();
    let mut offsets: Vec<OffsetOut<V>> = c.offsets.iter().map(|o| offset_out(o, &v)).collect();
    let (outcome, single, offsets) = if c.single {
        (None, offsets.pop(), None)
    } else {
        let outcome = if c.singular {
            "singular_base"
        } else {
            "offsets"
        };
        (Some(outcome), None, Some(offsets))
    };
    let note = if c.singular {
        Some(SINGULAR_NOTE)
    } else if c.line {
        Some(LINE_NOTE)
    } else {
        None
    };
    Answer {
        kind: "ph_offset",
        mode,
        outcome,
        single,
        base_degree: c.curve.degree(),
        degree: 2 * c.curve.degree() - 1,
        base: base.control_points().iter().map(|p| xy(p, &v)).collect(),
        hodograph: hx
            .coeffs()
            .iter()
            .zip(hy.coeffs())
            .map(|(x, y)| [v(x), v(y)])
            .collect(),
        speed: c.curve.speed().coeffs().iter().map(&v).collect(),
        rotated_normal: c
            .curve
            .rotated_normal()
            .control_points()
            .iter()
            .map(|p| three(p, &v))
            .collect(),
        curvature_numerator: c
            .curve
            .curvature_numerator()
            .coeffs()
            .iter()
            .map(&v)
            .collect(),
        poles: c.poles.iter().map(|z| parameter(z, &v)).collect(),
        min_radius_of_curvature: c.min.as_ref().map(|r| radius_out(r, &v)),
        min_radius_by_side: (!c.singular).then(|| BySide {
            left: c.left.as_ref().map(|r| radius_out(r, &v)),
            right: c.right.as_ref().map(|r| radius_out(r, &v)),
        }),
        note,
        offsets,
        base_approx: T::EXACT.then(|| {
            base.control_points()
                .iter()
                .map(|p| xy(p, &SectionScalar::approx))
                .collect()
        }),
        float: None,
    }
}

fn exact_answer<T: SectionScalar + std::fmt::Display>(
    input: &Input<ExactNumber>,
    lift: impl Fn(&Radical) -> T,
) -> Result<Answer<String>, Error> {
    let p = problem(input, |x| lift(&x.0))?;
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
                "certificate": format!("{:?}", c.certificate),
            })).collect::<Vec<_>>(),
        }),
        Err(e) => serde_json::json!({"decided": false, "note": e.to_string()}),
    }
}

fn exact(text: &str) -> Result<Answer<String>, Error> {
    let input: Input<ExactNumber> = parse(text)?;
    // Checked before any work: the exact curve's coefficients grow from these.
    let bits = input
        .u
        .iter()
        .chain(&input.v)
        .map(|x| exactcheck_exact::expr::Coefficient::size_bits(&x.0))
        .fold(0u64, u64::saturating_add);
    exactcheck_core::limits::PH_BITS
        .check(bits)
        .map_err(|e| Error::Input(format!("u, v: {e}")))?;
    // Rational input runs over the (faster) rationals; radicals over the radical field.
    if numbers(&input).all(|x| x.0.is_rational()) {
        let mut answer = exact_answer(&input, |x| {
            x.to_rational()
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
        exact_answer(&input, Clone::clone)
    }
}

fn float_answer(text: &str) -> Result<Answer<f64>, Error> {
    let input: Input<FloatNumber> = parse(text)?;
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

    fn answer(text: &str, mode: Mode) -> Result<Value, Error> {
        by_mode(text, mode, exact, float_answer, |e, f| {
            e.float = Some(Box::new(f))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_exact::Rational;

    fn q(s: &str) -> Rational {
        s.parse().expect("a rational")
    }

    fn solve(text: &str) -> Value {
        PhOffset::answer(text, Mode::Exact).expect("answered")
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
