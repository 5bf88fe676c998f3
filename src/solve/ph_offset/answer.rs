//! The answer of `ph_offset`: the computation rendered with exact strings or f64 numbers.

use super::compute::{Computed, OffsetData, Radius};
use crate::solve::scalar::Scalar;
use exactcheck_core::ph::RadiusBound;
use exactcheck_core::roots::IsolatedRoot;
use exactcheck_core::Vec3;
use serde::Serialize;
use serde_json::Value;

/// A parameter in `[0, 1]`: an isolating interval, its midpoint, and the value when exact.
#[derive(Debug, Serialize)]
pub(super) struct Parameter<V> {
    pub(super) interval: [V; 2],
    pub(super) approx: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) exact: Option<V>,
}

pub(super) fn parameter<T: Scalar, V>(z: &IsolatedRoot<T>, v: &impl Fn(&T) -> V) -> Parameter<V> {
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
pub(super) struct RadiusOut<V> {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) exact: Option<V>,
    /// `[lo, hi]`: `lo < rho_min <= hi`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) interval: Option<[V; 2]>,
    pub(super) approx: f64,
    pub(super) side: &'static str,
    /// Where it is attained: the zeros of `sigma^2 - 2 m w` (exact value `m`), or the local
    /// minima of the radius at most `hi` (enclosure `(lo, hi]`), isolated exactly.
    pub(super) at: Vec<Parameter<V>>,
}

#[derive(Debug, Serialize)]
pub(super) struct BySide<V> {
    pub(super) left: Option<RadiusOut<V>>,
    pub(super) right: Option<RadiusOut<V>>,
}

/// A cusp of an offset.
#[derive(Debug, Serialize)]
pub(super) struct CuspOut<V> {
    pub(super) t: Parameter<V>,
    /// As a zero of `sigma^2 - 2 r w` (exact mode only: f64 cannot decide it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) multiplicity: Option<usize>,
    /// The offset point at an exact parameter (`[x, y, r]`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) point: Option<[V; 3]>,
    /// The offset point at the parameter's midpoint, in f64.
    pub(super) point_approx: [f64; 3],
}

#[derive(Debug, Serialize)]
pub(super) struct OffsetApprox {
    pub(super) weights: Vec<f64>,
    pub(super) points: Vec<Option<[f64; 3]>>,
}

/// One offset.
#[derive(Debug, Serialize)]
pub(super) struct OffsetOut<V> {
    pub(super) r: V,
    pub(super) outcome: &'static str,
    /// The weights `w_k` (the speed `sigma`, degree-elevated to `2n - 1`).
    pub(super) weights: Vec<V>,
    /// The control points `[x, y, r]` (`null` where the weight is 0).
    pub(super) points: Vec<Option<[V; 3]>>,
    /// `w_k` times the control points: always defined (a direction where `w_k = 0`).
    pub(super) weighted_points: Vec<[V; 3]>,
    /// `null` on a singular base.
    pub(super) cusps: Option<Vec<CuspOut<V>>>,
    /// Exact mode, rational input only: the offset's self-intersections, decided exactly
    /// ([`self_intersections`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) self_intersections: Option<Value>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) approx: Option<OffsetApprox>,
}

/// The answer, with numbers of type `V` (exact strings, or f64 with `--float`).
#[derive(Debug, Serialize)]
pub(crate) struct Answer<V> {
    pub(super) kind: &'static str,
    pub(super) mode: &'static str,
    /// For an array of distances: `offsets` or `singular_base` (a single distance: the offset's
    /// own `outcome`, flattened below).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) outcome: Option<&'static str>,
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub(super) single: Option<OffsetOut<V>>,
    pub(super) base_degree: usize,
    pub(super) degree: usize,
    pub(super) base: Vec<[V; 2]>,
    pub(super) hodograph: Vec<[V; 2]>,
    pub(super) speed: Vec<V>,
    pub(super) rotated_normal: Vec<[V; 3]>,
    pub(super) curvature_numerator: Vec<V>,
    pub(super) poles: Vec<Parameter<V>>,
    pub(super) min_radius_of_curvature: Option<RadiusOut<V>>,
    pub(super) min_radius_by_side: Option<BySide<V>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) note: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) offsets: Option<Vec<OffsetOut<V>>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) base_approx: Option<Vec<[f64; 2]>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) float: Option<Box<Answer<f64>>>,
}

pub(super) const SINGULAR_NOTE: &str = "the parametric speed u^2 + v^2 vanishes at the parameters in `poles`: the base curve is singular there and every offset has a pole there; the curvature 2w/sigma^2 and the cusp criterion sigma^2 - 2rw = 0 are undefined at those parameters, so no radius of curvature and no cusps are given";
pub(super) const LINE_NOTE: &str = "w = u v' - u' v is identically zero: the curve is a straight line, its radius of curvature is infinite and its offsets have no cusps";

pub(super) fn radius_out<T: Scalar, V>(r: &Radius<T>, v: &impl Fn(&T) -> V) -> RadiusOut<V> {
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

pub(super) fn xy<T, V>(p: &Vec3<T>, v: &impl Fn(&T) -> V) -> [V; 2] {
    [v(&p.x), v(&p.y)]
}

pub(super) fn three<T, V>(p: &Vec3<T>, v: &impl Fn(&T) -> V) -> [V; 3] {
    [v(&p.x), v(&p.y), v(&p.z)]
}

pub(super) fn offset_out<T: Scalar, V>(o: &OffsetData<T>, v: &impl Fn(&T) -> V) -> OffsetOut<V> {
    let weights = o.curve.weights();
    let points = o.curve.points();
    let approx3 = |p: &Vec3<T>| three(p, &Scalar::approx);
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
            weights: weights.iter().map(Scalar::approx).collect(),
            points: points.iter().map(|p| p.as_ref().map(approx3)).collect(),
        }),
    }
}

pub(super) fn render<T: Scalar, V>(
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
                .map(|p| xy(p, &Scalar::approx))
                .collect()
        }),
        float: None,
    }
}
