//! The exact answer of `cylinder_sphere` for input in a real number field `Q(theta)` (values
//! such as `"cos(pi/8)"`, `"sqrt(2 + sqrt(3))"`): the same analysis as over Q, its discriminant
//! with coefficients in the field ([`analyze_in_field`]), sample points in the field or, where a
//! sample's discriminant is not a square there, as `p0 + p1*sqrt(D)` with `p0`, `p1`, `D` in
//! the field, each checked exactly on both surfaces.

use super::answer::{exact_answer, Curve, ExactAnswer, PointText};
use super::exact::{plus_sqrt_term, sample_taus};
use super::input::{configuration, exact_angle, Input};
use super::{approx3, on_both, strings};
use crate::solve::number::FieldNumber;
use crate::Error;
use exactcheck_core::cylinder_sphere::{unit_circle_point, CylinderSphere};
use exactcheck_core::{OrderedField, Ring, Sign, Vec3};
use exactcheck_exact::algebraic::FieldElement;
use exactcheck_exact::cylinder_sphere::analyze_in_field;

type F = FieldElement;

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
    let p = &analysis.discriminant;
    let taus = sample_taus(n_samples, &analysis.nonnegative);
    let mut curve = Curve::default();
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
                curve.all_on_both &= pts.iter().all(|x| on_both(&cs, x));
                (
                    us.iter().map(ToString::to_string).collect(),
                    pts.iter().map(|x| (strings(x), approx3(x))).collect(),
                )
            }
            None => {
                let (pts, ok) = quadratic_points(&cs, &c, &s, &minus_a, &disc);
                curve.all_on_both &= ok;
                let d = disc.to_string();
                let m = minus_a.to_string();
                (
                    vec![format!("{m} - sqrt({d})"), format!("{m} + sqrt({d})")],
                    pts,
                )
            }
        };
        curve.push(tau, &angle, us, pts);
    }
    exact_answer(&cs, analysis, &width, curve, notes)
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
