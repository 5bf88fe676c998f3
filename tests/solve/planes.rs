//! The two-plane intersection end to end (the `planes` half): `solve plane_plane` on
//! random exact input (rational and radical coordinates) checked by exact substitution, the
//! degenerate and malformed inputs, the published JavaScript port against the exact construction
//! on well-conditioned input (proptest, stated bound), and the regression report finding a
//! planted near-parallel case.

use crate::common;

use common::solve_stdin as solve_cli;
use exactcheck::regress::planes::{bin_of, measure, normal_at_angle, report, PlaneCase};
use exactcheck::solve::{solve, Mode};
use exactcheck_core::planes::{intersect, Plane, PlanePair};
use exactcheck_core::{Field, Ring, Rng, Vec3};
use exactcheck_exact::{Radical, Rational};
use exactcheck_float::wabis::{interction_line_of_2_areas, length, scale, V3};
use exactcheck_float::{f64_to_rational, rational_to_f64, ulp, ExactScalar};
use num_traits::Signed;
use proptest::prelude::*;
use serde_json::Value;

/// A small random number of the exact syntax and its value: a rational, or a rational plus a
/// rational multiple of `sqrt(k)`.
fn number(rng: &mut Rng, radical: bool) -> String {
    let mut q = || {
        let n = rng.below(19) as i64 - 9;
        let d = rng.below(4) + 1;
        format!("({n}/{d})")
    };
    let a = q();
    if radical {
        let b = q();
        let k = [2, 3, 5, 6][rng.below(4) as usize];
        format!("{a} + {b}*sqrt({k})")
    } else {
        a
    }
}

fn vector(rng: &mut Rng, radical: bool) -> [String; 3] {
    [
        number(rng, radical),
        number(rng, radical),
        number(rng, radical),
    ]
}

fn problem(planes: &[([String; 3], [String; 3]); 2]) -> String {
    let v = |a: &[String; 3]| format!("[\"{}\",\"{}\",\"{}\"]", a[0], a[1], a[2]);
    format!(
        r#"{{"kind":"plane_plane","planes":[{{"normal":{},"point":{}}},{{"normal":{},"point":{}}}]}}"#,
        v(&planes[0].0),
        v(&planes[0].1),
        v(&planes[1].0),
        v(&planes[1].1)
    )
}

fn radical(s: &str) -> Radical {
    s.parse()
        .unwrap_or_else(|e| panic!("{s:?} does not parse back: {e}"))
}

fn vec3(s: &[String; 3]) -> Vec3<Radical> {
    Vec3::new(radical(&s[0]), radical(&s[1]), radical(&s[2]))
}

fn answer_vec(a: &Value, key: &str) -> Vec3<Radical> {
    let v: Vec<Radical> = a[key]
        .as_array()
        .unwrap_or_else(|| panic!("{key} in {a}"))
        .iter()
        .map(|x| radical(x.as_str().expect("an exact string")))
        .collect();
    Vec3::new(v[0].clone(), v[1].clone(), v[2].clone())
}

#[test]
fn random_exact_lines_lie_on_both_planes_nearest_the_origin() {
    let mut rng = Rng::new(9);
    let (mut lines, mut radical_inputs, mut in_field) = (0, 0, 0);
    for i in 0..240 {
        let rad = i % 2 == 1;
        let planes = [
            (vector(&mut rng, rad), vector(&mut rng, rad)),
            (vector(&mut rng, rad), vector(&mut rng, false)),
        ];
        let (n1, p1) = (vec3(&planes[0].0), vec3(&planes[0].1));
        let (n2, p2) = (vec3(&planes[1].0), vec3(&planes[1].1));
        if n1.is_zero() || n2.is_zero() || n1.cross(&n2).is_zero() {
            continue;
        }
        let text = problem(&planes);
        let a = solve(&text, Mode::Exact).unwrap_or_else(|e| panic!("{text}: {e}"));
        assert_eq!(a["outcome"], "line", "{text}");
        let q = answer_vec(&a, "point");
        let dir = answer_vec(&a, "direction");
        // Exactly on both planes, direction n1 x n2 orthogonal to both normals, and nearest the
        // origin: Q . direction = 0.
        assert!((n1.dot(&q) - n1.dot(&p1)).is_zero(), "{text}");
        assert!((n2.dot(&q) - n2.dot(&p2)).is_zero(), "{text}");
        assert_eq!(dir, n1.cross(&n2), "{text}");
        assert!(dir.dot(&n1).is_zero() && dir.dot(&n2).is_zero(), "{text}");
        assert!(q.dot(&dir).is_zero(), "{text}");
        // A point further along the line is further from the origin.
        let further = q.add_scaled(&Radical::from(1), &dir);
        assert!(further.norm_squared() > q.norm_squared(), "{text}");
        assert_eq!(a["on_both_planes"], true);
        assert_eq!(a["nearest_to_origin"], true);
        if a["unit_direction_in_field"] == true {
            let u = answer_vec(&a, "unit_direction");
            assert_eq!(u.norm_squared(), Radical::from(1), "{text}");
            assert!(
                u.cross(&dir).is_zero() && u.dot(&dir) > Radical::from(0),
                "{text}"
            );
            in_field += 1;
        } else {
            let u = a["unit_direction"].as_array().expect("expressions");
            assert!(
                u.iter()
                    .all(|c| c == "0" || c.as_str().unwrap().contains("/sqrt(")),
                "{a}"
            );
        }
        lines += 1;
        radical_inputs += usize::from(rad);
    }
    assert!(
        lines >= 200 && radical_inputs >= 100 && in_field >= 100,
        "{lines} lines, {radical_inputs} radical, {in_field} unit directions in the field"
    );
}

/// The same problem through the CLI, exit status and one-line errors.
fn refused(problem: &str, needles: &[&str]) {
    common::refused(problem, &[], needles);
}

fn outcome(problem: &str, flags: &[&str]) -> Value {
    let o = solve_cli(problem, flags);
    assert!(
        o.status.success(),
        "{problem}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).expect("JSON")
}

#[test]
fn degenerate_and_malformed_planes() {
    let pp = |n1: &str, p1: &str, n2: &str, p2: &str| {
        format!(
            r#"{{"kind":"plane_plane","planes":[{{"normal":{n1},"point":{p1}}},{{"normal":{n2},"point":{p2}}}]}}"#
        )
    };
    // Parallel: x + 2y + 3z = 3 and the same normal scaled by -sqrt(2) through the origin.
    let parallel = pp(
        "[1,2,3]",
        "[0,0,1]",
        r#"["-sqrt(2)","-2*sqrt(2)","-3*sqrt(2)"]"#,
        "[0,0,0]",
    );
    let a = outcome(&parallel, &[]);
    assert_eq!(a["outcome"], "parallel");
    assert!(a["point"].is_null() && a["direction"].is_null());
    // The published function cannot tell: null, reported as parallel.
    assert_eq!(outcome(&parallel, &["--float"])["outcome"], "parallel");
    let coincident = pp("[1,2,3]", "[0,0,1]", r#"["1/2",1,"3/2"]"#, "[3,0,0]");
    assert_eq!(outcome(&coincident, &[])["outcome"], "coincident");
    assert_eq!(
        outcome(&coincident, &["--both"])["float"]["outcome"],
        "parallel"
    );
    refused(
        &pp("[1,2,3]", "[0,0,1]", "[0,0,0]", "[1,1,1]"),
        &["planes[1].normal: zero vector"],
    );
    refused(
        &pp("[0,0,0]", "[0,0,1]", "[0,0,1]", "[1,1,1]"),
        &["planes[0].normal: zero vector"],
    );
    // --float refuses a zero normal the same way (the JavaScript would return null).
    let o = solve_cli(pp("[1,2,3]", "[0,0,1]", "[0,0,0]", "[1,1,1]"), &["--float"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("planes[1].normal: zero vector"));
    // An f64 length that overflows: the normal cannot be normalised as the function requires.
    let o = solve_cli(
        pp(r#"["10^200","10^200",0]"#, "[0,0,1]", "[0,0,1]", "[1,1,1]"),
        &["--float"],
    );
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("planes[0].normal: its f64 length is inf"),
        "{err}"
    );
    refused(
        &pp("[1,2]", "[0,0,1]", "[0,0,1]", "[1,1,1]"),
        &["planes[0].normal", "expected 3 coordinates, found 2"],
    );
    refused(
        r#"{"kind":"plane_plane","planes":[{"normal":[1,0,0]},{"normal":[0,0,1],"point":[1,1,1]}]}"#,
        &["planes[0]", "missing field `point`"],
    );
    refused(
        r#"{"kind":"plane_plane","planes":[{"normal":[1,0,0],"point":[0,0,0]}]}"#,
        &["planes", "expected 2 planes, found 1"],
    );
    refused(r#"{"kind":"plane_plane"}"#, &["missing field `planes`"]);
    refused(
        r#"{"kind":"plane_plane","planes":[{"normal":[1,0,0],"point":[0,0,0],"w":1},{"normal":[0,0,1],"point":[1,1,1]}]}"#,
        &["planes[0]", "unknown field `w`"],
    );
    refused(
        r#"{"kind":"plane_plane","planes":[{"normal":[1,0.5,0],"point":[0,0,0]},{"normal":[0,0,1],"point":[1,1,1]}]}"#,
        &["planes[0].normal[1]", "floating-point literal"],
    );
}

#[test]
fn float_mode_is_the_published_function() {
    // x = 1 written with the normal (2, 0, 0) and y = 2: the port normalises the normals first,
    // as the function requires, and returns q = n2 x n1 normalised.
    let a = outcome(
        r#"{"kind":"plane_plane","planes":[{"normal":[2,0,0],"point":[1,5,7]},{"normal":[0,1,0],"point":[3,2,-1]}]}"#,
        &["--float"],
    );
    assert_eq!(a["mode"], "float");
    assert!(a["method"]
        .as_str()
        .unwrap()
        .contains("InterctionLineOf2Areas"));
    assert_eq!(a["point"], serde_json::json!([1.0, 2.0, 0.0]));
    assert_eq!(a["unit_direction"], serde_json::json!([0.0, 0.0, -1.0]));
}

fn unit(v: V3) -> V3 {
    scale(&v, 1.0 / length(&v))
}

/// Well-conditioned planes: unit normals (normalised in f64) at an angle in `[0.1, pi/2]`.
fn well_conditioned() -> impl Strategy<Value = (PlaneCase, f64)> {
    let v = || prop::array::uniform3(-1.0f64..1.0);
    let p = || prop::array::uniform3(-10.0f64..10.0);
    (v(), v(), 0.1f64..std::f64::consts::FRAC_PI_2, p(), p())
        .prop_filter("non-degenerate directions", |(a, b, ..)| {
            let (la, lb) = (length(a), length(b));
            la > 0.1 && lb > 0.1 && length(&exactcheck_float::wabis::mult(a, b)) > 0.1 * la * lb
        })
        .prop_map(|(a, b, theta, p1, p2)| {
            let n1 = unit(a);
            let n2 = normal_at_angle(&n1, &b, theta);
            (PlaneCase { p1, n1, p2, n2 }, theta)
        })
}

/// The stated bound for angles above 0.1 rad: the point within 2^10 ulps of
/// `S = max(|Q|_inf, |P1|_inf, |P2|_inf)`, the unit direction within 16 ulps of 1. (The point's
/// condition number is about `1/sin^2(theta) <= 101` times the few roundings of `d_i`, `r` and the
/// sums; the direction's about `1/sin(theta) <= 10.1`.)
const POINT_BOUND_ULPS: f64 = 1024.0;
const DIRECTION_BOUND_ULPS: f64 = 16.0;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]
    #[test]
    fn published_port_agrees_with_exact_on_well_conditioned_planes((case, _theta) in well_conditioned()) {
        let ex = |v: &V3| Vec3::new(
            Rational::from_f64_exact(v[0]).unwrap(),
            Rational::from_f64_exact(v[1]).unwrap(),
            Rational::from_f64_exact(v[2]).unwrap(),
        );
        let a = Plane::through(ex(&case.n1), &ex(&case.p1));
        let b = Plane::through(ex(&case.n2), &ex(&case.p2));
        let PlanePair::Line { point, direction } = intersect(&a, &b) else {
            panic!("not a line: {case:?}");
        };
        let (qf, dirf) = interction_line_of_2_areas(&case.p1, &case.n1, &case.p2, &case.n2)
            .expect("the published function finds a line");
        let inf = |v: &V3| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let qmax = point.map(|c| rational_to_f64(&c.to_big_rational()).abs());
        let s = inf(&[qmax.x, qmax.y, qmax.z]).max(inf(&case.p1)).max(inf(&case.p2));
        let err = |f: f64, e: &Rational, unit: f64| {
            rational_to_f64(&((f64_to_rational(f).unwrap() - e.to_big_rational()).abs()
                / f64_to_rational(unit).unwrap()))
        };
        let point_err = [0, 1, 2].iter().map(|&i| err(qf[i], &point[i], ulp(s))).fold(0.0, f64::max);
        prop_assert!(point_err <= POINT_BOUND_ULPS, "point error {point_err} ulps at {case:?}");
        // The exact unit direction of n2 x n1 = -(n1 x n2), compared through its square: the
        // error of q_i against u_i = -c_i/|c| is |q_i |c| + c_i| / |c|, and |c| is computed in
        // f64 from the exact |c|^2 (relative error 2^-53, far below the bound).
        let g = rational_to_f64(&direction.norm_squared().to_big_rational()).sqrt();
        let dir_err = [0, 1, 2].iter().map(|&i| {
            let ui = -rational_to_f64(&direction[i].to_big_rational()) / g;
            (dirf[i] - ui).abs() / ulp(1.0)
        }).fold(0.0, f64::max);
        prop_assert!(dir_err <= DIRECTION_BOUND_ULPS, "direction error {dir_err} ulps at {case:?}");
        // The harness's measure agrees that this case is in the wide-angle bin.
        let m = measure(&case).expect("a line");
        prop_assert_eq!(bin_of(m.angle), 0);
    }
}

#[test]
fn regress_report_puts_a_planted_near_parallel_case_in_the_worst_bin() {
    // 300 well-conditioned cases (angles in [0.3, 1.5] rad) and one near-parallel case planted at
    // index 1000 (angle about 1e-7 rad, where 1 - r*r still evaluates to a non-zero double).
    let mut rng = exactcheck_float::Rng::new(5);
    let mut draw = |lo: f64, hi: f64| rng.uniform(lo, hi);
    let mut cases = Vec::new();
    let make = |a: V3, b: V3, theta: f64, p1: V3, p2: V3| {
        let n1 = unit(a);
        let n2 = normal_at_angle(&n1, &b, theta);
        PlaneCase { p1, n1, p2, n2 }
    };
    let mut v3 = |lo: f64, hi: f64| [draw(lo, hi), draw(lo, hi), draw(lo, hi)];
    while cases.len() < 300 {
        let (a, b, p1, p2) = (
            v3(-1.0, 1.0),
            v3(-1.0, 1.0),
            v3(-10.0, 10.0),
            v3(-10.0, 10.0),
        );
        let theta = 0.3 + (p1[0] + 10.0) / 20.0 * 1.2;
        if length(&a) > 0.1 && length(&exactcheck_float::wabis::mult(&a, &b)) > 0.1 {
            cases.push((cases.len(), make(a, b, theta, p1, p2)));
        }
    }
    let planted = make(
        [1.0, 2.0, 2.0],
        [0.0, 1.0, -1.0],
        1e-7,
        [3.0, -4.0, 5.0],
        [-2.0, 7.0, 1.0],
    );
    cases.push((1000, planted));
    let r = report(5, cases, 3);
    assert_eq!(r.measured, 301);
    let worst = r.worst_bin().expect("bins");
    assert_eq!(worst.count, 1, "{r}");
    assert_eq!(worst.worst.map(|w| w.0), Some(1000), "{r}");
    assert!((1e-8..1e-6).contains(&worst.hi), "{r}");
    assert_eq!(r.worst.len(), 3);
    assert_eq!(r.worst[0].0, 1000, "{r}");
    // The well-conditioned bins stay small; the planted case is far above them.
    let others = r
        .bins
        .iter()
        .filter(|b| b.count > 0 && b.hi != worst.hi)
        .fold(0.0f64, |m, b| m.max(b.point_max));
    assert!(
        others < POINT_BOUND_ULPS && worst.point_max > 1e6 * others.max(1.0),
        "{r}"
    );
}

#[test]
fn exact_solver_and_generic_construction_agree_on_a_radical_example() {
    // n1 = (1, 1, 0) through (1, 0, 0), n2 = (0, sqrt 2, sqrt 2) through (0, 0, 2): the line
    // through (0, 1, 1) with direction sqrt 2 (1, -1, 1).
    let a = solve(
        r#"{"kind":"plane_plane","planes":[{"normal":[1,1,0],"point":[1,0,0]},{"normal":[0,"sqrt(2)","sqrt(2)"],"point":[0,0,2]}]}"#,
        Mode::Exact,
    )
    .unwrap();
    let q = answer_vec(&a, "point");
    assert_eq!(q, Vec3::<Radical>::from_i64(0, 1, 1));
    let s2 = Radical::sqrt_of(2);
    assert_eq!(
        answer_vec(&a, "direction"),
        Vec3::<Radical>::from_i64(1, -1, 1).scale(&s2)
    );
    let third = Radical::sqrt_of(3).checked_div(&Radical::from(3)).unwrap();
    assert_eq!(
        answer_vec(&a, "unit_direction"),
        Vec3::<Radical>::from_i64(1, -1, 1).scale(&third)
    );
}
