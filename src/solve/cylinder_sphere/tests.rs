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
