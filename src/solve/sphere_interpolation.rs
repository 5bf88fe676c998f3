//! `solve` kind `sphere_interpolation` (Juettler, "the linear problem"): a rational curve on
//! the unit sphere through given points at given parameters, via the preimage lines (12) of the
//! points under delta and a curve meeting each line at its parameter (a nullspace of a linear
//! system), mapped back by delta. Exact only: rational input runs over Q, radical input over the
//! radical field, values outside it (`"cos(pi/8)"`) over the problem's number field. The answer checks exactly that the curve passes through every point.

use super::number::{Coords, ExactNumber, FieldNumber};
use super::scalar::Scalar;
use super::{Kind, Problem};
use crate::Error;
use exactcheck_core::sphere_interpolation::interpolate;
use exactcheck_core::{Hom4, Vec3};
use exactcheck_exact::algebraic::FieldElement;
use exactcheck_exact::{Radical, Rational};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// The problem.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "sphere_interpolation",
    description = "Juettler's linear problem: a rational curve on the unit sphere through the given points at the given parameters. Exact only."
)]
pub struct Input<N = ExactNumber> {
    /// `"sphere_interpolation"`.
    #[schemars(extend("const" = "sphere_interpolation"))]
    pub kind: String,
    /// Points on the unit sphere, Cartesian.
    pub points: Vec<Coords<N, 3>>,
    /// One distinct parameter per point.
    pub params: Vec<N>,
}

/// The answer.
#[derive(Debug, Serialize)]
pub struct Answer {
    kind: &'static str,
    mode: &'static str,
    /// Degree of the curve.
    degree: usize,
    /// Weights, exact.
    weights: Vec<String>,
    /// Control points (`null` where a weight is 0), exact.
    points: Vec<Option<[String; 3]>>,
    preimage_degree: usize,
    /// The degree plain stereographic projection needs, if computed.
    sigma_degree: Option<usize>,
    passes_through_all_points: bool,
    approx: Approx,
}

#[derive(Debug, Serialize)]
struct Approx {
    weights: Vec<f64>,
    points: Vec<Option<[f64; 3]>>,
}

/// The kind.
pub struct SphereInterpolation;

impl Kind for SphereInterpolation {
    const NAME: &'static str = "sphere_interpolation";
    type Input = Input;
    type Answer = Answer;

    fn compute_in_field(problem: &Problem) -> Result<Answer, Error> {
        let input: Input<FieldNumber> = problem.input_in_field(&[])?;
        crate::limits::POINTS.check_usize(input.points.len())?;
        let points: Vec<Vec3<FieldElement>> = input
            .points
            .into_iter()
            .map(|Coords([x, y, z])| Vec3::new(x.0, y.0, z.0))
            .collect();
        let params: Vec<FieldElement> = input.params.into_iter().map(|t| t.0).collect();
        solve(&points, &params)
    }

    fn compute(input: Input) -> Result<Answer, Error> {
        crate::limits::POINTS.check_usize(input.points.len())?;
        let points: Vec<Vec3<Radical>> = input
            .points
            .into_iter()
            .map(|Coords([x, y, z])| Vec3::new(x.0, y.0, z.0))
            .collect();
        let params: Vec<Radical> = input.params.into_iter().map(|t| t.0).collect();
        // Rational input runs over the (faster) rationals; radicals over the radical field.
        let rational = points
            .iter()
            .all(|p| p.x.is_rational() && p.y.is_rational() && p.z.is_rational())
            && params.iter().all(Radical::is_rational);
        if rational {
            let r = |x: &Radical| {
                x.to_rational()
                    .expect("is_rational was checked for every number")
            };
            let points: Vec<Vec3<Rational>> = points.iter().map(|p| p.map(r)).collect();
            let params: Vec<Rational> = params.iter().map(r).collect();
            solve(&points, &params)
        } else {
            solve(&points, &params)
        }
    }
}

fn solve<T: Scalar>(points: &[Vec3<T>], params: &[T]) -> Result<Answer, Error> {
    let hom: Vec<Hom4<T>> = points.iter().map(Hom4::from_point).collect();
    let r = interpolate(&hom, params).map_err(|e| Error::Input(e.to_string()))?;
    let weights = r.curve.weights();
    let pts = r.curve.points();
    // The exact check the answer promises: at each parameter the curve is the given point.
    let passes = hom
        .iter()
        .zip(params)
        .all(|(k, t)| r.curve.eval_hom(t).proj_eq(k));
    Ok(Answer {
        kind: "sphere_interpolation",
        mode: "exact",
        degree: r.degree,
        weights: weights.iter().map(ToString::to_string).collect(),
        points: pts
            .iter()
            .map(|p| {
                p.as_ref()
                    .map(|p| [p.x.to_string(), p.y.to_string(), p.z.to_string()])
            })
            .collect(),
        preimage_degree: r.degree / 2,
        sigma_degree: r.sigma_degree,
        passes_through_all_points: passes,
        approx: Approx {
            weights: weights.iter().map(Scalar::approx).collect(),
            points: pts
                .iter()
                .map(|p| {
                    p.as_ref()
                        .map(|p| [p.x.approx(), p.y.approx(), p.z.approx()])
                })
                .collect(),
        },
    })
}
