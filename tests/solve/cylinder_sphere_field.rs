//! `cylinder_sphere` over a number field: problems whose values leave the square-root field
//! (`"cos(pi/8)"`, `"sqrt(2 + sqrt(3))"`) are answered exactly, the discriminant's decision agreeing
//! with the axis-distance method, every sample point checked exactly on both surfaces.

use crate::common;

use common::refused;
use common::solve_stdin as solve;

fn problem(beta: &str, axis_point: &str, center: &str, radius: &str, extra: &str) -> String {
    format!(
        r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":{axis_point},"radius":1,"beta":{beta},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":{center},"radius":{radius}}}{extra}}}"#
    )
}

const PI_8: &str = r#"{"cos":"cos(pi/8)","sin":"sin(pi/8)"}"#;
const ZERO: &str = r#"{"cos":1,"sin":0}"#;

fn answer(problem: &str) -> serde_json::Value {
    let o = solve(problem.as_bytes(), &[]);
    assert!(
        o.status.success(),
        "{problem}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).expect("JSON answer")
}

fn assert_agrees(a: &serde_json::Value, contact: &str) {
    assert_eq!(a["mode"], "exact");
    assert_eq!(a["contact"], contact, "{a}");
    assert_eq!(a["contact_by_axis_distance"], contact);
    assert_eq!(a["methods_agree"], true);
    assert_eq!(a["all_points_on_both_surfaces"], true);
}

#[test]
fn a_tilted_cylinder_and_a_sphere_of_radius_sqrt_2_plus_sqrt_3_cross() {
    let a = answer(&problem(
        PI_8,
        "[0,0]",
        "[1,0,0]",
        r#""sqrt(2 + sqrt(3))""#,
        r#","samples":4"#,
    ));
    assert_agrees(&a, "crossing");
    assert_eq!(a["intersects"], true);
    let points = a["points"].as_array().unwrap();
    assert!(!points.is_empty());
    // Every point's approximation lies on the sphere |x - (1,0,0)| = sqrt(2 + sqrt(3)).
    let r2 = 2.0 + 3f64.sqrt();
    for p in points {
        let x: Vec<f64> = p["approx"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let d2 = (x[0] - 1.0).powi(2) + x[1].powi(2) + x[2].powi(2);
        assert!((d2 - r2).abs() < 1e-9, "{p}");
    }
    // The sample coordinates outside the field are written p0 +- p1*sqrt(D), never "+ -".
    let text = a["samples"].to_string();
    assert!(text.contains("sqrt("), "{text}");
    assert!(!text.contains("+ -"), "{text}");
}

#[test]
fn a_sphere_touching_at_an_irrational_tau_gives_an_isolated_touching_point() {
    // The sphere of radius 1 about (2 cos(pi/8), 2 sin(pi/8), 0) touches the unit cylinder about
    // the z axis at t = pi/8, tau = tan(pi/16).
    let a = answer(&problem(
        ZERO,
        "[0,0]",
        r#"["2*cos(pi/8)","2*sin(pi/8)",0]"#,
        "1",
        "",
    ));
    assert_agrees(&a, "tangent");
    let tps = a["tangent_points"].as_array().unwrap();
    assert_eq!(tps.len(), 1, "{a}");
    let tau = tps[0]["approx"]["tau"].as_f64().unwrap();
    assert!(
        (tau - (std::f64::consts::PI / 16.0).tan()).abs() < 1e-9,
        "{tau}"
    );
    let [lo, hi] = [0, 1].map(|i| tps[0]["tau_interval"][i].as_str().unwrap().to_string());
    assert_ne!(lo, hi);
}

#[test]
fn a_sphere_away_from_the_cylinder_is_disjoint_and_radians_angles_are_noted() {
    let a = answer(&problem(
        r#"{"radians":0.5}"#,
        r#"["cos(pi/8)",0]"#,
        "[10,0,0]",
        r#""sqrt(2 + sqrt(3))""#,
        "",
    ));
    assert_agrees(&a, "disjoint");
    assert_eq!(a["intersects"], false);
    assert_eq!(a["approximated_angles"][0]["field"], "cylinder.beta");
}

#[test]
fn a_sphere_touching_at_a_rational_tau_gives_an_exact_touching_point() {
    // Axis through (cos(pi/8), 0): the sphere of radius 1 about (2 + cos(pi/8), 0, 0) touches
    // the cylinder at t = 0 at the point (1 + cos(pi/8), 0, 0).
    let a = answer(&problem(
        ZERO,
        r#"["cos(pi/8)",0]"#,
        r#"["2 + cos(pi/8)",0,0]"#,
        "1",
        "",
    ));
    assert_agrees(&a, "tangent");
    let tp = &a["tangent_points"][0];
    assert_eq!(tp["tau"], "0", "{a}");
    assert_eq!(tp["point"][0], "1 + cos(pi/8)");
    assert_eq!(tp["on_both_surfaces"], true);
}

#[test]
fn field_input_off_the_unit_circle_or_with_an_irrational_precision_is_refused() {
    let off = problem(
        r#"{"cos":"cos(pi/8)","sin":"cos(pi/8)"}"#,
        "[0,0]",
        "[1,0,0]",
        "2",
        "",
    );
    refused(&off, &[], &["cylinder.beta: cos^2 + sin^2 = ", "!= 1"]);
    let precision = problem(PI_8, "[0,0]", "[1,0,0]", "2", r#","precision":"sqrt(2)""#);
    refused(&precision, &[], &["precision must be a rational number"]);
}

#[test]
fn square_roots_alone_are_answered_in_their_field() {
    // |(sqrt(2), sqrt(3), 0)| = sqrt(5) > 1 + 1: disjoint; sqrt(5) - 1 < 2: crossing for R = 2.
    let far = answer(&problem(
        ZERO,
        "[0,0]",
        r#"["sqrt(2)","sqrt(3)",0]"#,
        "1",
        "",
    ));
    assert_agrees(&far, "disjoint");
    let near = answer(&problem(
        ZERO,
        "[0,0]",
        r#"["sqrt(2)","sqrt(3)",0]"#,
        "2",
        "",
    ));
    assert_agrees(&near, "crossing");
    assert!(near["coefficients"].to_string().contains("sqrt("), "{near}");
    // Touching from outside at t = pi/4: centre (3/sqrt(2), 3/sqrt(2), 0), R = 2.
    let touch = answer(&problem(
        ZERO,
        "[0,0]",
        r#"["3*sqrt(2)/2","3*sqrt(2)/2",5]"#,
        "2",
        "",
    ));
    assert_agrees(&touch, "tangent");
    let tp = &touch["tangent_points"][0];
    assert!(tp["tau_interval"].is_array(), "{touch}");
    let tau = tp["approx"]["tau"].as_f64().unwrap();
    assert!(
        (tau - (std::f64::consts::PI / 8.0).tan()).abs() < 1e-9,
        "{tau}"
    );
}
