//! `solve ruled_plane`: the answers are checked by exact substitution (the curve lies on the
//! plane and on the surface), the degenerate outcomes and the poles are pinned, and every class
//! of bad input is a one-line error naming the field (exit status 2).

use crate::common;

use common::refused;
use common::solve_stdin;
use exactcheck::solve::{solve, Mode};
use exactcheck_core::{Bernstein, Field, OrderedField, Ring, Rng, Sign, Vec3};
use exactcheck_exact::{Radical, Rational};
use serde_json::Value;

fn r(s: &str) -> Radical {
    s.parse()
        .unwrap_or_else(|e| panic!("{s:?} does not parse back: {e}"))
}

fn radicals(v: &Value) -> Vec<Radical> {
    v.as_array()
        .expect("an array")
        .iter()
        .map(|x| match x {
            Value::String(s) => r(s),
            Value::Number(n) => r(&n.to_string()),
            other => panic!("not a number: {other}"),
        })
        .collect()
}

fn vec3(v: &Value) -> Vec3<Radical> {
    let c = radicals(v);
    Vec3::new(c[0].clone(), c[1].clone(), c[2].clone())
}

/// A random small exact number, as text: rational, or with `sqrt(2)` / `sqrt(3)` when `radical`.
fn number(rng: &mut Rng, radical: bool) -> String {
    let a = rng.below(13) as i64 - 6;
    let b = rng.below(4) + 1;
    if radical && rng.chance(0.4) {
        let c = rng.below(7) as i64 - 3;
        let k = if rng.chance(0.5) { 2 } else { 3 };
        format!("{a}/{b} + ({c})*sqrt({k})")
    } else {
        format!("{a}/{b}")
    }
}

fn points(rng: &mut Rng, count: usize, radical: bool) -> String {
    let pts: Vec<String> = (0..count)
        .map(|_| {
            let c: Vec<String> = (0..3)
                .map(|_| format!("\"{}\"", number(rng, radical)))
                .collect();
            format!("[{}]", c.join(","))
        })
        .collect();
    format!("[{}]", pts.join(","))
}

fn problem(base: &str, directions: &str, plane: &str) -> String {
    format!(r#"{{"kind":"ruled_plane","base":{base},"directions":{directions},"plane":{plane}}}"#)
}

/// Bezier curve with exact control points, evaluated by de Casteljau per coordinate.
fn bezier(ctrl: &[Vec3<Radical>], t: &Radical) -> Vec3<Radical> {
    let coord =
        |f: fn(&Vec3<Radical>) -> Radical| Bernstein::new(ctrl.iter().map(f).collect()).eval(t);
    Vec3::new(
        coord(|p| p.x.clone()),
        coord(|p| p.y.clone()),
        coord(|p| p.z.clone()),
    )
}

/// Checks one exact answer against the problem by substitution at parameters `k / 23`; returns
/// the number of parameters checked (poles skipped).
fn check_curve(problem: &str, answer: &Value) -> usize {
    let input: Value = serde_json::from_str(problem).unwrap();
    let base: Vec<Vec3<Radical>> = input["base"].as_array().unwrap().iter().map(vec3).collect();
    let dirs: Vec<Vec3<Radical>> = input["directions"]
        .as_array()
        .unwrap()
        .iter()
        .map(vec3)
        .collect();
    let pl = radicals(&input["plane"]);
    let normal = Vec3::new(pl[0].clone(), pl[1].clone(), pl[2].clone());
    let (m, n) = (dirs.len() - 1, base.len() - 1);
    assert_eq!(answer["kind"], "ruled_plane");
    assert_eq!(answer["mode"], "exact");
    assert_eq!(answer["degree"], m + n);
    let weights = radicals(&answer["weights"]);
    let weighted: Vec<Vec3<Radical>> = answer["weighted_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(vec3)
        .collect();
    assert_eq!(weights.len(), m + n + 1);
    assert_eq!(weighted.len(), m + n + 1);
    // points[k] is null exactly where w_k = 0, and w_k r_k otherwise.
    for (k, p) in answer["points"].as_array().unwrap().iter().enumerate() {
        if weights[k].is_zero() {
            assert!(p.is_null(), "{problem}: points[{k}]");
        } else {
            assert_eq!(
                vec3(p).scale(&weights[k]),
                weighted[k],
                "{problem}: points[{k}]"
            );
        }
    }
    let w = Bernstein::new(weights.clone());
    let mut checked = 0;
    for k in 0..=23 {
        let t = Radical::from(Rational::new(k, 23).unwrap());
        let nv = normal.dot(&bezier(&dirs, &t));
        let wt = w.eval(&t);
        // The weight polynomial is N.V (elevated): the same function.
        assert_eq!(wt, nv, "{problem}: weight at t = {k}/23");
        if wt.is_zero() {
            continue;
        }
        let x = bezier(&weighted, &t).div_scalar(&wt).unwrap();
        assert!(
            normal.dot(&x).add_ref(&pl[3]).is_zero(),
            "{problem}: off the plane"
        );
        let offset = normal.dot(&bezier(&base, &t)).add_ref(&pl[3]);
        let s = offset.neg_ref().checked_div(&nv).unwrap();
        let on_surface = bezier(&base, &t).add_scaled(&s, &bezier(&dirs, &t));
        assert_eq!(x, on_surface, "{problem}: not S(s(t), t) at t = {k}/23");
        // The answer's ruling parameter gives the same s.
        let rp = &answer["ruling_parameter"];
        let num = Bernstein::new(radicals(&rp["numerator"])).eval(&t);
        let den = Bernstein::new(radicals(&rp["denominator"])).eval(&t);
        assert_eq!(
            num.checked_div(&den).unwrap(),
            s,
            "{problem}: ruling_parameter"
        );
        checked += 1;
    }
    // Every pole is a zero of the weight polynomial inside its interval.
    for pole in answer["poles"].as_array().expect("poles for a curve") {
        let lo = r(pole["interval"][0].as_str().unwrap());
        let hi = r(pole["interval"][1].as_str().unwrap());
        assert!(Radical::zero() <= lo && lo <= hi && hi <= Radical::one());
        if pole["exact"].is_string() {
            assert_eq!(lo, hi);
            assert!(w.eval(&lo).is_zero(), "{problem}: exact pole");
        } else {
            assert!(lo < hi);
            assert_ne!(w.eval(&lo).sign(), Sign::Zero);
        }
    }
    checked
}

/// 240 random exact problems over several (m, n), with rational and radical coordinates,
/// through the library; each curve is checked at 24 parameters.
#[test]
fn random_exact_sections_lie_on_the_plane_and_on_the_surface() {
    let shapes = [
        (0, 1),
        (1, 1),
        (1, 2),
        (2, 1),
        (2, 3),
        (3, 5),
        (1, 4),
        (3, 3),
    ];
    let mut rng = Rng::new(0x5EC7_1011);
    let mut checked_params = 0;
    let mut radical_problems = 0;
    for i in 0..240 {
        let (m, n) = shapes[i % shapes.len()];
        let radical = i % 2 == 1;
        let p = problem(
            &points(&mut rng, n + 1, radical),
            &points(&mut rng, m + 1, radical),
            &format!(
                "[\"{}\",\"{}\",\"{}\",\"{}\"]",
                number(&mut rng, radical),
                number(&mut rng, radical),
                number(&mut rng, radical),
                number(&mut rng, radical)
            ),
        );
        let answer = match solve(&p, Mode::Exact) {
            Ok(a) => a,
            // A random normal can be zero; that is refused, and must be.
            Err(e) => {
                assert!(
                    e.to_string().contains("plane: normal (a, b, c) is zero"),
                    "{e}"
                );
                continue;
            }
        };
        radical_problems += usize::from(p.contains("sqrt"));
        if answer["outcome"] == "curve" {
            checked_params += check_curve(&p, &answer);
        }
    }
    assert!(checked_params > 200 * 20, "{checked_params}");
    assert!(radical_problems > 80, "{radical_problems}");
}

/// A few through the binary, in exact mode (`--both` carries the f64 answer along).
#[test]
fn the_binary_answers_the_same() {
    let mut rng = Rng::new(7);
    for i in 0..4 {
        let p = problem(
            &points(&mut rng, 3, i % 2 == 0),
            &points(&mut rng, 2, true),
            r#"[1,"-1/2","sqrt(2)",3]"#,
        );
        let o = solve_stdin(p.as_bytes(), &["--both"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let a: Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(a, {
            let mut lib = solve(&p, Mode::Exact).unwrap();
            lib["float"] = solve(&p, Mode::Float).unwrap();
            lib
        });
        if a["outcome"] == "curve" {
            assert!(check_curve(&p, &a) > 0);
        }
        // The f64 weights agree with the exact ones.
        for (e, f) in a["approx"]["weights"]
            .as_array()
            .unwrap()
            .iter()
            .zip(a["float"]["weights"].as_array().unwrap())
        {
            let (e, f) = (e.as_f64().unwrap(), f.as_f64().unwrap());
            assert!((e - f).abs() <= 1e-12 * (1.0 + e.abs()), "{e} {f}");
        }
    }
}

/// Chiang's Example 4 in Q(sqrt 2, sqrt 6): the weights print as exact radicals.
#[test]
fn example4_weights_are_exact_radicals() {
    let p = problem(
        "[[0,0,-1],[1,1,-1],[0,2,-1]]",
        r#"[[-1,1,"sqrt(2)"],[-1,-1,"sqrt(6)"]]"#,
        "[0,0,1,0]",
    );
    let a = solve(&p, Mode::Exact).unwrap();
    assert_eq!(a["outcome"], "curve");
    assert_eq!(
        a["weights"],
        serde_json::json!([
            "sqrt(2)",
            "2*sqrt(2)/3 + sqrt(6)/3",
            "sqrt(2)/3 + 2*sqrt(6)/3",
            "sqrt(6)"
        ])
    );
    assert_eq!(a["poles"], serde_json::json!([]));
    assert!(check_curve(&p, &a) == 24);
}

fn z_directions(zs: &[&str]) -> String {
    let v: Vec<String> = zs.iter().map(|z| format!("[1,0,\"{z}\"]")).collect();
    format!("[{}]", v.join(","))
}

#[test]
fn a_rational_pole_is_given_exactly() {
    // N.V = 1 - 3t against z = 0: the ruling at t = 1/3 is parallel to the plane.
    let p = problem(
        "[[0,0,1],[1,0,2]]",
        &z_directions(&["1", "-2"]),
        "[0,0,1,0]",
    );
    let a = solve(&p, Mode::Exact).unwrap();
    assert_eq!(a["outcome"], "curve");
    let poles = a["poles"].as_array().unwrap();
    assert_eq!(poles.len(), 1);
    assert_eq!(poles[0]["exact"], "1/3");
    assert_eq!(poles[0]["interval"], serde_json::json!(["1/3", "1/3"]));
    assert_eq!(poles[0]["multiplicity"], 1);
    assert_eq!(poles[0]["ruling_in_plane"], false);
    assert_eq!(poles[0]["removable"], false);
    check_curve(&p, &a);
}

#[test]
fn an_irrational_pole_is_given_by_an_isolating_interval() {
    // N.V = t^2 - 1/2 (Bernstein -1/2, -1/2, 1/2): the pole 1/sqrt 2.
    let p = problem(
        "[[0,0,1],[1,0,1]]",
        &z_directions(&["-1/2", "-1/2", "1/2"]),
        "[0,0,1,0]",
    );
    for precision in [None, Some("1/10^12")] {
        let p = match precision {
            None => p.clone(),
            Some(w) => p.replace("}", &format!(",\"precision\":\"{w}\"}}")),
        };
        let a = solve(&p, Mode::Exact).unwrap();
        let poles = a["poles"].as_array().unwrap();
        assert_eq!(poles.len(), 1, "{a}");
        assert!(poles[0].get("exact").is_none());
        let lo = r(poles[0]["interval"][0].as_str().unwrap());
        let hi = r(poles[0]["interval"][1].as_str().unwrap());
        let half = r("1/2");
        assert!(lo.square() < half && half < hi.square(), "{lo} {hi}");
        let want_width = r(precision.unwrap_or("1/2^50"));
        assert!(hi.sub_ref(&lo) <= want_width);
        let approx = poles[0]["approx"].as_f64().unwrap();
        assert!((approx - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-12);
        assert!(lo.is_rational() && hi.is_rational());
        check_curve(&p, &a);
    }
}

#[test]
fn a_ruling_in_the_plane_at_a_pole_is_reported_and_whether_the_pole_cancels() {
    // N.V = 1 - 3t and N.B + d = 1 - 3t: the ruling at 1/3 lies in z = 0 and the factor
    // (1 - 3t) divides all homogeneous coordinates: removable.
    let p = problem(
        "[[0,0,1],[1,0,-2]]",
        &z_directions(&["1", "-2"]),
        "[0,0,1,0]",
    );
    let a = solve(&p, Mode::Exact).unwrap();
    let pole = &a["poles"][0];
    assert_eq!(pole["exact"], "1/3");
    assert_eq!(pole["ruling_in_plane"], true);
    assert_eq!(pole["removable"], true);
    check_curve(&p, &a);
    // N.V = (1 - 3t)^2 (Bernstein 1, -2, 4), offset 1 - 3t: ruling in the plane, double zero
    // of the weight, only one factor cancels: still a pole.
    let p = problem(
        "[[0,0,1],[1,0,-2]]",
        &z_directions(&["1", "-2", "4"]),
        "[0,0,1,0]",
    );
    let a = solve(&p, Mode::Exact).unwrap();
    let pole = &a["poles"][0];
    assert_eq!(pole["exact"], "1/3");
    assert_eq!(pole["multiplicity"], 2);
    assert_eq!(pole["ruling_in_plane"], true);
    assert_eq!(pole["removable"], false);
    check_curve(&p, &a);
    // An irrational common zero: N.V = t^2 - 1/2, N.B + d = 2 (t^2 - 1/2) (Bernstein -1, -1, 1).
    let p = problem(
        "[[0,0,-1],[1,0,-1],[0,1,1]]",
        &z_directions(&["-1/2", "-1/2", "1/2"]),
        "[0,0,1,0]",
    );
    let a = solve(&p, Mode::Exact).unwrap();
    let pole = &a["poles"][0];
    assert!(pole.get("exact").is_none());
    assert_eq!(pole["ruling_in_plane"], true);
    assert_eq!(pole["multiplicity"], 1);
    check_curve(&p, &a);
}

#[test]
fn rulings_parallel_to_the_plane_are_an_outcome_not_a_division_by_zero() {
    // Horizontal rulings, base from z = -1 to z = 1: one ruling (t = 1/2) lies in z = 0.
    let p = problem("[[0,0,-1],[1,0,1]]", "[[0,1,0],[1,1,0]]", "[0,0,1,0]");
    for mode in [Mode::Exact, Mode::Float] {
        let a = solve(&p, mode).unwrap();
        assert_eq!(a["outcome"], "parallel_rulings");
        assert!(a.get("poles").is_none());
        let rulings = a["rulings_in_plane"].as_array().unwrap();
        assert_eq!(rulings.len(), 1);
        assert_eq!(rulings[0]["approx"], 0.5);
        assert!(a["weights"]
            .as_array()
            .unwrap()
            .iter()
            .all(|w| w == "0" || w == 0.0));
        assert!(a["points"].as_array().unwrap().iter().all(Value::is_null));
    }
    assert_eq!(
        solve(&p, Mode::Exact).unwrap()["rulings_in_plane"][0]["exact"],
        "1/2"
    );
    // Base at height 1: no ruling meets the plane.
    let p = problem("[[0,0,1],[1,0,1]]", "[[0,1,0]]", "[0,0,1,0]");
    let a = solve(&p, Mode::Exact).unwrap();
    assert_eq!(a["outcome"], "parallel_rulings");
    assert_eq!(a["rulings_in_plane"], serde_json::json!([]));
}

#[test]
fn zero_directions_are_no_rulings_not_parallel_rulings() {
    // V = 0: no rulings, the surface is the base curve (z from -1 to 1), which meets z = 0 at
    // t = 1/2 only. It used to be called `parallel_rulings` with a ruling in the plane.
    let p = problem("[[0,0,-1],[1,0,1]]", "[[0,0,0],[0,0,0]]", "[0,0,1,0]");
    for mode in [Mode::Exact, Mode::Float] {
        let a = solve(&p, mode).unwrap();
        assert_eq!(a["outcome"], "degenerate_no_rulings", "{a}");
        assert!(a.get("rulings_in_plane").is_none() && a.get("poles").is_none());
        assert_eq!(a["base_curve_in_plane"], false);
        let points = a["base_points_in_plane"].as_array().unwrap();
        assert_eq!(points.len(), 1);
        assert_eq!(points[0]["approx"], 0.5);
    }
    // A base curve in the plane (it used to be `surface_in_plane`): the whole curve, no list.
    let p = problem("[[0,0,0],[1,2,0]]", "[[0,0,0]]", "[0,0,1,0]");
    let a = solve(&p, Mode::Exact).unwrap();
    assert_eq!(a["outcome"], "degenerate_no_rulings");
    assert_eq!(a["base_curve_in_plane"], true);
    assert!(a.get("base_points_in_plane").is_none());
}

#[test]
fn a_surface_in_the_plane_is_an_outcome() {
    let p = problem(
        "[[0,0,0],[1,2,0]]",
        "[[0,1,0],[1,\"sqrt(2)\",0]]",
        "[0,0,2,0]",
    );
    for mode in [Mode::Exact, Mode::Float, Mode::Both] {
        let a = solve(&p, mode).unwrap();
        assert_eq!(a["outcome"], "surface_in_plane");
        assert!(a.get("poles").is_none() && a.get("rulings_in_plane").is_none());
    }
}

#[test]
fn float_mode_finds_the_same_poles() {
    let p = problem(
        "[[0,0,1],[1,0,1]]",
        &z_directions(&["-1/2", "-1/2", "1/2"]),
        "[0,0,1,0]",
    );
    let a = solve(&p, Mode::Float).unwrap();
    assert_eq!(a["mode"], "float");
    let poles = a["poles"].as_array().unwrap();
    assert_eq!(poles.len(), 1);
    let approx = poles[0]["approx"].as_f64().unwrap();
    assert!((approx - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-9);
    // Exact-only fields are absent, not guessed.
    assert!(poles[0].get("ruling_in_plane").is_none());
}

#[test]
fn the_degree_limit_is_accepted_up_to_and_refused_beyond() {
    let line = |k: usize| {
        let v: Vec<String> = (0..k).map(|i| format!("[{i},1,{}]", i % 3)).collect();
        format!("[{}]", v.join(","))
    };
    // m + n = 1 + 59 = 60: answered, in both modes.
    let p = problem(&line(60), &line(2), "[1,1,1,-3]");
    for mode in [Mode::Exact, Mode::Float] {
        let a = solve(&p, mode).unwrap();
        assert_eq!(a["degree"], 60);
    }
    // m + n = 1 + 60 = 61: refused.
    let p = problem(&line(61), &line(2), "[1,1,1,-3]");
    refused(&p, &[], &["base, directions", "m + n = 1 + 60 = 61"]);
}

#[test]
fn bad_input_is_one_line_naming_the_field() {
    let base = "[[0,0,-1],[1,1,-1],[0,2,-1]]";
    let dirs = "[[-1,1,1],[-1,-1,2]]";
    for mode in [&[][..], &["--float"][..], &["--both"][..]] {
        refused(
            &problem(base, dirs, "[0,0,0,1]"),
            mode,
            &["plane: normal (a, b, c) is zero"],
        );
        refused(
            &problem(base, dirs, "[0,0,1]"),
            mode,
            &["plane", "expected 4 coordinates, found 3"],
        );
        refused(
            &problem("[[0,0,-1],[1,1,-1],[0,2]]", dirs, "[0,0,1,0]"),
            mode,
            &["base[2]", "expected 3 coordinates"],
        );
        refused(
            &problem("[]", dirs, "[0,0,1,0]"),
            mode,
            &["base: at least one control point"],
        );
        refused(
            &problem(base, "[]", "[0,0,1,0]"),
            mode,
            &["directions: at least one control vector"],
        );
        refused(
            &problem(base, dirs, "[0,0,1,0],\"planes\":1"),
            mode,
            &["unknown field `planes`"],
        );
        refused(
            &problem(base, dirs, "[0,0,1,0],\"precision\":0"),
            mode,
            &["precision: must be positive"],
        );
        refused(
            r#"{"kind":"ruled_plane","base":[[0,0,1]],"plane":[0,0,1,0]}"#,
            mode,
            &["missing field `directions`"],
        );
    }
    // JSON floating literals: exact mode refuses them by field, --float reads them.
    refused(
        &problem("[[0,0.5,-1]]", dirs, "[0,0,1,0]"),
        &[],
        &["base[0][1]", "floating-point literal", "\"0.5\""],
    );
    let o = solve_stdin(
        problem("[[0,0.5,-1]]", dirs, "[0,0,1,0]").as_bytes(),
        &["--float"],
    );
    assert!(o.status.success());
    // Degree above the limit through the binary.
    let many: Vec<String> = (0..62).map(|i| format!("[{i},0,1]")).collect();
    refused(
        &problem(&format!("[{}]", many.join(",")), "[[0,0,1]]", "[0,0,1,0]"),
        &[],
        &["base, directions", "61", "exceeds the limit 60"],
    );
}

#[test]
fn exact_strings_round_trip() {
    // Every exact string of an answer parses back to a number the next problem accepts.
    let p = problem(
        "[[0,0,-1],[1,1,-1],[0,2,-1]]",
        r#"[[-1,1,"sqrt(2)"],[-1,-1,"sqrt(6)"]]"#,
        "[0,0,1,0]",
    );
    let a = solve(&p, Mode::Exact).unwrap();
    let pts = a["points"].to_string();
    let again = problem(&pts, r#"[[0,0,1]]"#, "[1,1,1,0]");
    let b = solve(&again, Mode::Exact).unwrap();
    assert_eq!(b["degree"], 3);
}
