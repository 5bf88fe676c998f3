//! Unit tests of the exact answer.

use super::answer::{ExactAnswer, TangentPoint};
use crate::solve::parse;
use crate::Error;

fn exact(text: &str) -> Result<ExactAnswer, Error> {
    super::exact::exact(parse(text)?)
}

fn problem(center: &str, radius: &str) -> String {
    format!(
        r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":5,"beta":{{"cos":1,"sin":0}},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":{center},"radius":{radius}}},"samples":4}}"#
    )
}

#[test]
fn the_touching_circle_is_reported_and_checked() {
    // The reported example: centre (0,0,3) on the axis, R = r = 5.
    let a = exact(&problem("[0,0,3]", "5")).unwrap();
    assert_eq!(a.contact, "tangent");
    assert_eq!(a.contact_by_axis_distance, "tangent");
    assert!(a.methods_agree);
    assert!(a.tangent_points.is_empty());
    let c = a.tangent_circle.expect("a touching circle");
    assert_eq!(c.center, ["0", "0", "3"]);
    assert_eq!(c.radius, "5");
    assert_eq!(c.u, "3");
    assert!(c.on_both_surfaces);
    assert!(a.all_points_on_both_surfaces);
}

#[test]
fn the_figure_eight_touches_at_its_crossing_point() {
    // centre (2,0,0), R = 7 = r + delta: touching at (-5, 0, 0), t = pi.
    let a = exact(&problem("[2,0,0]", "7")).unwrap();
    assert_eq!(a.contact, "crossing");
    assert!(a.methods_agree);
    assert!(a.tangent_circle.is_none());
    assert_eq!(a.tangent_points.len(), 1);
    match &a.tangent_points[0] {
        TangentPoint::Exact {
            tau,
            point,
            on_both_surfaces,
            ..
        } => {
            assert_eq!(tau, "infinity (t = pi)");
            assert_eq!(point, &["-5", "0", "0"]);
            assert!(on_both_surfaces);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_sqrt_term_is_written_with_its_sign_as_the_operator() {
    use super::exact::plus_sqrt_term;
    use exactcheck_core::Sign;
    assert_eq!(
        plus_sqrt_term("1/2", Sign::Negative, "3", "5"),
        "1/2 - 3*sqrt(5)"
    );
    assert_eq!(
        plus_sqrt_term("1/2", Sign::Positive, "3", "5"),
        "1/2 + 3*sqrt(5)"
    );
    assert_eq!(
        plus_sqrt_term("1", Sign::Negative, "1 + sqrt(2)", "3"),
        "1 - (1 + sqrt(2))*sqrt(3)"
    );
}

#[test]
fn field_points_with_a_sqrt_term_are_checked_on_both_surfaces_exactly() {
    // The field path's check splits each surface equation into its field part and its
    // sqrt(D) part: the points of u = -A +- sqrt(A^2 - B) pass (here u^2 = 49 - 1 - 25 at
    // t = pi/2), those of a wrong radicand fail.
    use exactcheck_core::cylinder_sphere::{Angle, CylinderSphere};
    use exactcheck_core::{Ring, Vec3};
    use exactcheck_exact::algebraic::FieldElement as F;
    let q = F::from_i64;
    let level = Angle {
        cos: q(1),
        sin: q(0),
    };
    let cs = CylinderSphere {
        a: q(0),
        b: q(0),
        r: q(5),
        beta: level.clone(),
        gamma: level,
        center: Vec3::new(q(1), q(0), q(0)),
        radius: q(7),
    };
    let (c, s) = (q(0), q(1));
    let (a, b) = cs.coefficients_at(&c, &s);
    let disc = a.square() - &b;
    let (pts, ok) = super::field::quadratic_points(&cs, &c, &s, &a.neg_ref(), &disc);
    assert!(ok);
    assert_eq!(pts[0].0[2], "0 - 1*sqrt(23)");
    let wrong = disc.add_ref(&q(1));
    let (_, ok) = super::field::quadratic_points(&cs, &c, &s, &a.neg_ref(), &wrong);
    assert!(!ok);
}
