//! The `--float` answer of `cylinder_sphere`: the generic formulas evaluated in f64.

use super::answer::Coefficients;
use super::contact_name;
use super::input::{configuration, float_angle, Input};
use crate::solve::number::FloatNumber;
use crate::Error;
use exactcheck_core::cylinder_sphere::Contact;
use serde::Serialize;

#[derive(Debug, Serialize)]
struct FloatSample {
    t: f64,
    cos: f64,
    sin: f64,
    u: Vec<f64>,
    points: Vec<[f64; 3]>,
}

/// The `--float` answer.
#[derive(Debug, Serialize)]
pub struct FloatAnswer {
    kind: &'static str,
    mode: &'static str,
    intersects: bool,
    contact_by_axis_distance: &'static str,
    coefficients: Coefficients<f64>,
    samples: Vec<FloatSample>,
}

pub(super) fn float_answer(input: Input<FloatNumber>) -> Result<FloatAnswer, Error> {
    let (cs, n) = configuration(&input, |x| x.0, float_angle)?;
    let coeffs = cs.trig_coefficients();
    if !coeffs
        .a
        .iter()
        .chain(coeffs.b.iter())
        .all(|x| x.is_finite())
    {
        return Err(Error::Input(
            "--float: the coefficients of A and B overflow f64 for this input; use exact mode"
                .into(),
        ));
    }
    let sampler = exactcheck_float::sampler::DiscSampler::new(&cs);
    let mut samples = Vec::new();
    for k in 0..n {
        let t = std::f64::consts::TAU * k as f64 / n as f64;
        let (s, c) = t.sin_cos();
        let u: Vec<f64> = sampler
            .roots(t)
            .map(|(a, b)| vec![a, b])
            .unwrap_or_default();
        let points: Vec<[f64; 3]> = u.iter().map(|u| cs.point(&c, &s, u).into_array()).collect();
        if !u
            .iter()
            .chain(points.iter().flatten())
            .all(|x| x.is_finite())
        {
            return Err(Error::Input(format!(
                "--float: the curve point at t = {t} overflows f64 for this input; use exact mode"
            )));
        }
        samples.push(FloatSample {
            t,
            cos: c,
            sin: s,
            u,
            points,
        });
    }
    let contact = cs.contact_by_distance();
    Ok(FloatAnswer {
        kind: "cylinder_sphere",
        mode: "float",
        intersects: contact != Contact::Disjoint,
        contact_by_axis_distance: contact_name(contact),
        coefficients: Coefficients::new(&coeffs, |x| *x),
        samples,
    })
}
