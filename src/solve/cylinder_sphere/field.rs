//! The exact answer of `cylinder_sphere` for input in a real number field `Q(theta)` (values
//! such as `"cos(pi/8)"`, `"sqrt(2 + sqrt(3))"`): the same analysis as over Q, its discriminant
//! with coefficients in the field ([`analyze_in_field`]), sample points in the field or, where a
//! sample's discriminant is not a square there, as `p0 + p1*sqrt(D)` with `p0`, `p1`, `D` in
//! the field, each checked exactly on both surfaces.

use super::answer::{
    Coefficients, CurvePoint, ExactAnswer, Parametrization, PointText, Sample, TangentPoint,
};
use super::exact::{interval_ends, plus_sqrt_term, sample_taus, tangent_circle, touching_angle};
use super::input::{configuration, exact_angle, Input};
use super::{contact_name, on_both, strings};
use crate::solve::number::FieldNumber;
use crate::Error;
use exactcheck_core::cylinder_sphere::{unit_circle_point, Contact, CylinderSphere};
use exactcheck_core::{OrderedField, Ring, Sign, Vec3};
use exactcheck_exact::algebraic::FieldElement;
use exactcheck_exact::cylinder_sphere::analyze_in_field;

type F = FieldElement;

fn approx(v: &Vec3<F>) -> [f64; 3] {
    [v.x.to_f64() + 0.0, v.y.to_f64() + 0.0, v.z.to_f64() + 0.0]
}

pub(super) fn exact_in_field(input: Input<FieldNumber>) -> Result<ExactAnswer, Error> {
    let mut notes = Vec::new();
    let (cs, n_samples) = configuration(
        &input,
        |x| x.0.clone(),
        |a, p| {
            exact_angle(
                a,
                p,
                &mut notes,
                |x| x.0.clone(),
                |q| F::rational(q.clone()),
            )
        },
    )?;
    let width = match &input.precision {
        None => None,
        Some(FieldNumber(w)) => {
            let Some(w) = w.to_rational() else {
                return Err(Error::Input(format!(
                    "precision must be a rational number, not {w}"
                )));
            };
            if w.sign() != Sign::Positive {
                return Err(Error::Input("precision must be positive".into()));
            }
            crate::solve::number::check_precision(&w)?;
            Some(w)
        }
    };
    let analysis = analyze_in_field(&cs);
    let by_distance = cs.contact_by_distance();
    let coeffs = cs.trig_coefficients();
    let p = &analysis.discriminant;
    let taus = sample_taus(n_samples, &analysis.nonnegative);
    let mut samples = Vec::new();
    let mut points = Vec::new();
    let mut all_on_both = true;
    for tau in &taus {
        if p.sign_at(tau) == Sign::Negative {
            continue;
        }
        let angle = unit_circle_point(tau).expect("1 + tau^2 > 0 for rational tau");
        let (c, s) = (
            F::rational(angle.cos.clone()),
            F::rational(angle.sin.clone()),
        );
        let (a, b) = cs.coefficients_at(&c, &s);
        let disc = a.square() - &b;
        let minus_a = a.neg_ref();
        let (us, pts): (Vec<String>, Vec<PointText>) = match disc.sqrt_in_field() {
            Some(root) => {
                let us: Vec<F> = if disc.is_zero() {
                    vec![minus_a]
                } else {
                    vec![minus_a.sub_ref(&root), minus_a.add_ref(&root)]
                };
                let pts: Vec<Vec3<F>> = us.iter().map(|u| cs.point(&c, &s, u)).collect();
                all_on_both &= pts.iter().all(|x| on_both(&cs, x));
                (
                    us.iter().map(ToString::to_string).collect(),
                    pts.iter().map(|x| (strings(x), approx(x))).collect(),
                )
            }
            None => {
                let (pts, ok) = quadratic_points(&cs, &c, &s, &minus_a, &disc);
                all_on_both &= ok;
                let d = disc.to_string();
                let m = minus_a.to_string();
                (
                    vec![format!("{m} - sqrt({d})"), format!("{m} + sqrt({d})")],
                    pts,
                )
            }
        };
        samples.push(Sample {
            tau: tau.to_string(),
            cos: angle.cos.to_string(),
            sin: angle.sin.to_string(),
            t_degrees: 2.0 * tau.to_f64().atan().to_degrees(),
            u: us,
            points: pts.iter().map(|p| p.0.clone()).collect(),
        });
        points.extend(
            pts.into_iter()
                .map(|(exact, approx)| CurvePoint { exact, approx }),
        );
    }
    // Touching points: every multiple root of the discriminant.
    let mut tangent_points = Vec::new();
    for tp in &analysis.tangent_params {
        let (angle, tau_text) = match touching_angle(tp.as_ref(), |r, w| p.try_refine(r, w))? {
            Ok(at) => at,
            Err(isolated) => {
                tangent_points.push(isolated);
                continue;
            }
        };
        let (c, s) = (F::rational(angle.cos), F::rational(angle.sin));
        let (a, _) = cs.coefficients_at(&c, &s);
        let x = cs.point(&c, &s, &a.neg_ref());
        let ok = on_both(&cs, &x);
        all_on_both &= ok;
        tangent_points.push(TangentPoint::Exact {
            tau: tau_text,
            point: strings(&x),
            approx: approx(&x),
            on_both_surfaces: ok,
        });
    }
    let tangent_circle = analysis
        .touching_circle
        .then(|| tangent_circle(&cs, F::to_f64));
    if let Some(c) = &tangent_circle {
        all_on_both &= c.on_both_surfaces;
    }
    let intervals = interval_ends(&analysis.nonnegative, |r, w| p.try_refine(r, w), &width)?;
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
        coefficients: Coefficients::new(&coeffs, ToString::to_string),
        parametrization: Parametrization {
            angle: "cos t = (1 - tau^2)/(1 + tau^2), sin t = 2*tau/(1 + tau^2) (tau = infinity at t = pi)",
            u: "-A(t) +- sqrt(P(tau))/(1 + tau^2)",
            p: p.display("tau").to_string(),
            point: "Rx(gamma) Ry(beta) (a + r cos t, b + r sin t, u)",
            real_for_tau_in: intervals,
            real_at_t_pi: analysis.sign_at_pi != Sign::Negative,
        },
        samples,
        points,
        all_points_on_both_surfaces: all_on_both,
        approximated_angles: notes,
        float: None,
    })
}

/// The two curve points `u = -A +- w`, `w = sqrt(disc)`, where `disc` is not a square in the
/// field: the point is affine in `u`, `x = x0 + u d`, so each coordinate is `p0 + p1 w` with
/// `p0 = x0 - A d` and `p1 = +-d`. Both surface equations are split into their part in the field
/// and their `w` part (`w^2 = disc`), each checked to be exactly zero.
pub(super) fn quadratic_points(
    cs: &CylinderSphere<F>,
    c: &F,
    s: &F,
    minus_a: &F,
    disc: &F,
) -> (Vec<PointText>, bool) {
    let x0 = cs.point(c, s, &F::zero());
    let d = &cs.point(c, s, &F::one()) - &x0;
    let p0 = &x0 + &d.scale(minus_a);
    let (axis_q, axis_d) = cs.axis();
    // |v0 + w v1|^2 = (|v0|^2 + disc |v1|^2) + 2 w (v0 . v1).
    let vanishes = |v0: &Vec3<F>, v1: &Vec3<F>, rhs: &F| {
        let field_part = v0.norm_squared() + disc.mul_ref(&v1.norm_squared()) - rhs;
        field_part.is_zero() && v0.dot(v1).is_zero()
    };
    let on_sphere = vanishes(&(&p0 - &cs.center), &d, &cs.radius.square());
    let on_cylinder = vanishes(
        &(&p0 - &axis_q).cross(&axis_d),
        &d.cross(&axis_d),
        &cs.r.square(),
    );
    // The sign of w changes neither check: both points lie on both surfaces or neither.
    let ok = on_sphere && on_cylinder;
    let root = disc.to_f64().sqrt();
    let dt = disc.to_string();
    let coord = |q0: &F, q1: &F| -> (String, f64) {
        let text = if q1.is_zero() {
            q0.to_string()
        } else {
            plus_sqrt_term(&q0.to_string(), q1.sign(), &q1.abs().to_string(), &dt)
        };
        (text, q0.to_f64() + q1.to_f64() * root + 0.0)
    };
    let mut pts = Vec::new();
    for sign in [-1i64, 1] {
        let p1 = d.scale(&F::from_i64(sign));
        let (cx, cy, cz) = (
            coord(&p0.x, &p1.x),
            coord(&p0.y, &p1.y),
            coord(&p0.z, &p1.z),
        );
        pts.push(([cx.0, cy.0, cz.0], [cx.1, cy.1, cz.1]));
    }
    (pts, ok)
}
