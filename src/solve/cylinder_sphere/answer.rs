//! The answer types of `cylinder_sphere` in exact mode.

use super::float::FloatAnswer;
use super::input::AngleNote;
use exactcheck_core::cylinder_sphere::TrigCoefficients;
use serde::Serialize;

/// A trigonometric polynomial: its basis and coefficients.
#[derive(Debug, Serialize)]
pub(super) struct TrigPoly<T> {
    pub(super) basis: &'static [&'static str],
    pub(super) coefficients: Vec<T>,
}

/// A and B of `u^2 + 2 A u + B = 0`.
#[derive(Debug, Serialize)]
pub(super) struct Coefficients<T> {
    #[serde(rename = "A")]
    pub(super) a: TrigPoly<T>,
    #[serde(rename = "B")]
    pub(super) b: TrigPoly<T>,
}

impl<T> Coefficients<T> {
    pub(super) fn new<S>(c: &TrigCoefficients<S>, f: impl Fn(&S) -> T) -> Self {
        Coefficients {
            a: TrigPoly {
                basis: &["1", "cos t", "sin t"],
                coefficients: c.a.iter().map(&f).collect(),
            },
            b: TrigPoly {
                basis: &["1", "cos t", "sin t", "cos^2 t", "cos t sin t", "sin^2 t"],
                coefficients: c.b.iter().map(&f).collect(),
            },
        }
    }
}

/// A touching point.
#[derive(Debug, Serialize)]
#[serde(untagged)]
pub(super) enum TangentPoint {
    /// At a rational tau (or t = pi), with the point exactly.
    Exact {
        tau: String,
        point: [String; 3],
        approx: [f64; 3],
        on_both_surfaces: bool,
    },
    /// At an irrational tau, given by an isolating interval.
    Isolated {
        tau_interval: [String; 2],
        approx: TauApprox,
    },
}

#[derive(Debug, Serialize)]
pub(super) struct TauApprox {
    pub(super) tau: f64,
}

/// The circle along which the surfaces touch (discriminant identically zero).
#[derive(Debug, Serialize)]
pub(super) struct TangentCircle {
    /// Its centre (the sphere's centre, on the axis).
    pub(super) center: [String; 3],
    /// Its radius (the cylinder's).
    pub(super) radius: String,
    /// The normal of its plane (the axis direction).
    pub(super) normal: [String; 3],
    /// Its cylinder coordinate `u = -A(t)` (constant).
    pub(super) u: String,
    /// Exact check at `t = 0, pi/2, pi, 3 pi/2`: the points `x(t, u)` lie on both surfaces, at
    /// distance `radius` from `center`, in the plane through `center` normal to `normal`.
    pub(super) on_both_surfaces: bool,
    pub(super) approx: CircleApprox,
}

#[derive(Debug, Serialize)]
pub(super) struct CircleApprox {
    pub(super) center: [f64; 3],
    pub(super) radius: f64,
}

/// An end of a real tau-interval.
#[derive(Debug, Serialize)]
#[serde(untagged)]
pub(super) enum End {
    Exact(String),
    Isolated { interval: [String; 2], approx: f64 },
}

#[derive(Debug, Serialize)]
pub(super) struct Parametrization {
    pub(super) angle: &'static str,
    pub(super) u: &'static str,
    #[serde(rename = "P")]
    pub(super) p: String,
    pub(super) point: &'static str,
    pub(super) real_for_tau_in: Vec<[End; 2]>,
    pub(super) real_at_t_pi: bool,
}

#[derive(Debug, Serialize)]
pub(super) struct Sample {
    pub(super) tau: String,
    pub(super) cos: String,
    pub(super) sin: String,
    pub(super) t_degrees: f64,
    pub(super) u: Vec<String>,
    pub(super) points: Vec<[String; 3]>,
}

/// A point exactly as text, and its f64 approximation.
pub(super) type PointText = ([String; 3], [f64; 3]);

#[derive(Debug, Serialize)]
pub(super) struct CurvePoint {
    pub(super) exact: [String; 3],
    pub(super) approx: [f64; 3],
}

/// The exact answer.
#[derive(Debug, Serialize)]
pub struct ExactAnswer {
    pub(super) kind: &'static str,
    pub(super) mode: &'static str,
    pub(super) intersects: bool,
    pub(super) contact: &'static str,
    pub(super) contact_by_axis_distance: &'static str,
    pub(super) methods_agree: bool,
    pub(super) components: usize,
    pub(super) tangent_points: Vec<TangentPoint>,
    pub(super) tangent_circle: Option<TangentCircle>,
    pub(super) coefficients: Coefficients<String>,
    pub(super) parametrization: Parametrization,
    pub(super) samples: Vec<Sample>,
    pub(super) points: Vec<CurvePoint>,
    pub(super) all_points_on_both_surfaces: bool,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub(super) approximated_angles: Vec<AngleNote>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) float: Option<FloatAnswer>,
}
