//! The answer types of `cylinder_sphere` in exact mode, and [`exact_answer`], which builds the
//! answer from the analysis of the discriminant and the sample points for both exact paths (over
//! Q and in a number field): the touching points or circle, the interval ends and the
//! parametrization are computed the same way in both.

use super::float::FloatAnswer;
use super::input::AngleNote;
use super::{approx3, contact_name, on_both, strings};
use crate::solve::scalar::Scalar;
use crate::Error;
use exactcheck_core::cylinder_sphere::{
    unit_circle_point, Angle, Contact, CylinderSphere, TrigCoefficients,
};
use exactcheck_core::limits::LimitError;
use exactcheck_core::Sign;
use exactcheck_exact::cylinder_sphere::{Analysis, Discriminant};
use exactcheck_exact::univariate::{Bound, RootBoundedInterval, RootInterval};
use exactcheck_exact::Rational;
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

/// The sample points of the curve as an exact path computed them, and whether every one was
/// checked exactly on both surfaces.
pub(super) struct Curve {
    samples: Vec<Sample>,
    points: Vec<CurvePoint>,
    pub(super) all_on_both: bool,
}

impl Default for Curve {
    fn default() -> Self {
        Curve {
            samples: Vec::new(),
            points: Vec::new(),
            all_on_both: true,
        }
    }
}

impl Curve {
    /// The sample at the rational parameter `tau` (angle `angle`): its values of `u` and its
    /// points, exactly as text and approximately.
    pub(super) fn push(
        &mut self,
        tau: &Rational,
        angle: &Angle<Rational>,
        us: Vec<String>,
        pts: Vec<PointText>,
    ) {
        self.samples.push(Sample {
            tau: tau.to_string(),
            cos: angle.cos.to_string(),
            sin: angle.sin.to_string(),
            t_degrees: 2.0 * tau.to_f64().atan().to_degrees(),
            u: us,
            points: pts.iter().map(|p| p.0.clone()).collect(),
        });
        self.points.extend(
            pts.into_iter()
                .map(|(exact, approx)| CurvePoint { exact, approx }),
        );
    }
}

/// The exact answer for the configuration `cs` (over Q or in a number field), its `analysis`
/// and its sample `curve`: the touching points (each checked exactly on both surfaces), the
/// touching circle, the real tau-intervals (irrational ends refined to `width` when one is
/// asked for), the comparison with the distance method and the parametrization.
///
/// # Errors
/// The refinement's limit error.
pub(super) fn exact_answer<T: Scalar, P: Discriminant>(
    cs: &CylinderSphere<T>,
    analysis: Analysis<P>,
    width: &Option<Rational>,
    curve: Curve,
    notes: Vec<AngleNote>,
) -> Result<ExactAnswer, Error> {
    let p = &analysis.discriminant;
    let refine = |r: &RootInterval, w: &Rational| p.refine_root(r, w);
    let mut all_on_both = curve.all_on_both;
    // Touching points: every multiple root of the discriminant.
    let mut tangent_points = Vec::new();
    for tp in &analysis.tangent_params {
        let (angle, tau_text) = match touching_angle(tp.as_ref(), refine)? {
            Ok(at) => at,
            Err(isolated) => {
                tangent_points.push(isolated);
                continue;
            }
        };
        let (c, s) = (T::from_rational(&angle.cos), T::from_rational(&angle.sin));
        let (a, _) = cs.coefficients_at(&c, &s);
        let x = cs.point(&c, &s, &a.neg_ref());
        let ok = on_both(cs, &x);
        all_on_both &= ok;
        tangent_points.push(TangentPoint::Exact {
            tau: tau_text,
            point: strings(&x),
            approx: approx3(&x),
            on_both_surfaces: ok,
        });
    }
    let tangent_circle = analysis.touching_circle.then(|| tangent_circle(cs));
    if let Some(c) = &tangent_circle {
        all_on_both &= c.on_both_surfaces;
    }
    let intervals = interval_ends(&analysis.nonnegative, refine, width)?;
    let by_distance = cs.contact_by_distance();
    Ok(ExactAnswer {
        kind: "cylinder_sphere",
        mode: "exact",
        intersects: analysis.contact != Contact::Disjoint,
        contact: contact_name(analysis.contact),
        contact_by_axis_distance: contact_name(by_distance),
        methods_agree: analysis.contact == by_distance
            && analysis.touching() == Some(cs.touching_by_distance()),
        components: analysis.components,
        tangent_points,
        tangent_circle,
        coefficients: Coefficients::new(&cs.trig_coefficients(), ToString::to_string),
        parametrization: Parametrization {
            angle: "cos t = (1 - tau^2)/(1 + tau^2), sin t = 2*tau/(1 + tau^2) (tau = infinity at t = pi)",
            u: "-A(t) +- sqrt(P(tau))/(1 + tau^2)",
            p: p.text("tau"),
            point: "Rx(gamma) Ry(beta) (a + r cos t, b + r sin t, u)",
            real_for_tau_in: intervals,
            real_at_t_pi: analysis.sign_at_pi != Sign::Negative,
        },
        samples: curve.samples,
        points: curve.points,
        all_points_on_both_surfaces: all_on_both,
        approximated_angles: notes,
        float: None,
    })
}

/// The angle of a touching parameter (a multiple root of the discriminant, `None` for
/// `t = pi`) with its printed `tau`, when the root is rational; otherwise the isolated touching
/// point, its interval refined by `refine` to width `2^-40`.
///
/// # Errors
/// The refinement's limit error.
fn touching_angle(
    tp: Option<&RootInterval>,
    refine: impl FnOnce(&RootInterval, &Rational) -> Result<RootInterval, LimitError>,
) -> Result<Result<(Angle<Rational>, String), TangentPoint>, Error> {
    Ok(match tp {
        None => Ok((
            Angle {
                cos: Rational::from_integer(-1),
                sin: Rational::ZERO,
            },
            "infinity (t = pi)".to_string(),
        )),
        Some(ri) => match ri.exact_value() {
            Some(v) => Ok((
                unit_circle_point(v).expect("1 + tau^2 > 0 for rational tau"),
                v.to_string(),
            )),
            None => {
                let w = Rational::new(1, 1 << 40).expect("2^40 != 0");
                let refined = refine(ri, &w)?;
                Err(TangentPoint::Isolated {
                    tau_interval: [refined.lo.to_string(), refined.hi.to_string()],
                    approx: TauApprox {
                        tau: refined.to_f64(),
                    },
                })
            }
        },
    })
}

/// The real tau-intervals with their ends: exact, infinite, or isolated (refined by `refine` to
/// the width `width` when one is asked for).
fn interval_ends(
    nonnegative: &[RootBoundedInterval],
    refine: impl Fn(&RootInterval, &Rational) -> Result<RootInterval, LimitError>,
    width: &Option<Rational>,
) -> Result<Vec<[End; 2]>, Error> {
    let refine = |r: &RootInterval| -> Result<RootInterval, Error> {
        match width {
            Some(w) if !r.is_exact() => Ok(refine(r, w)?),
            _ => Ok(r.clone()),
        }
    };
    let end = |x: &Bound| -> Result<End, Error> {
        Ok(match x {
            Bound::NegInf => End::Exact("-inf".into()),
            Bound::PosInf => End::Exact("+inf".into()),
            Bound::Root(r) => match r.exact_value() {
                Some(v) => End::Exact(v.to_string()),
                None => {
                    let r = refine(r)?;
                    End::Isolated {
                        interval: [r.lo.to_string(), r.hi.to_string()],
                        approx: r.to_f64(),
                    }
                }
            },
        })
    };
    nonnegative
        .iter()
        .map(|iv| Ok([end(&iv.lo)?, end(&iv.hi)?]))
        .collect()
}

/// The touching circle of a configuration whose discriminant vanishes identically: centre and
/// radius from the geometry (the sphere's centre on the axis, the cylinder's radius), `u` from
/// `A` at `t = 0`, and the exact check at four of its points.
fn tangent_circle<T: Scalar>(cs: &CylinderSphere<T>) -> TangentCircle {
    let (_, normal) = cs.axis();
    let (a0, _) = cs.coefficients_at(&T::one(), &T::zero());
    let u = a0.neg_ref();
    let quarter_turns = [(1, 0), (0, 1), (-1, 0), (0, -1)];
    let ok = quarter_turns.iter().all(|&(c, s)| {
        let (c, s) = (T::from_i64(c), T::from_i64(s));
        let x = cs.point(&c, &s, &u);
        let rel = &x - &cs.center;
        on_both(cs, &x) && rel.norm_squared() == cs.r.square() && rel.dot(&normal).is_zero()
    });
    TangentCircle {
        center: strings(&cs.center),
        radius: cs.r.to_string(),
        normal: strings(&normal),
        u: u.to_string(),
        on_both_surfaces: ok,
        approx: CircleApprox {
            center: approx3(&cs.center),
            radius: cs.r.approx(),
        },
    }
}
