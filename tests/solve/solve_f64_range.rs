//! `solve` and `plot` where numbers leave f64's range: exact answers whose f64 twins are beyond
//! it are printed (twins `null`, listed in `approx_out_of_range`), f64 computation that
//! underflows or overflows is refused in one line (exit status 2) instead of panicking, a conic
//! next to a parabola is decided without thousands of halvings, and `plane_plane --both` keeps
//! the exact answer whatever the float part does.

use crate::common;

use common::{has_null_number, solve_stdin};
use exactcheck::solve::{solve, Mode};
use proptest::prelude::*;
use serde_json::{json, Value};

/// The exact answer (exit status 0, valid JSON, every `null` number listed).
fn exact_answer(problem: &str) -> Value {
    let o = solve_stdin(problem.as_bytes(), &[]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{problem}: {err}");
    let v: Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
    assert!(!has_null_number(&v), "{v}");
    v
}

fn listed(v: &Value) -> Vec<&str> {
    v["approx_out_of_range"]
        .as_array()
        .expect("approx_out_of_range")
        .iter()
        .map(|p| p.as_str().expect("a path"))
        .collect()
}

#[test]
fn plane_plane_with_a_normal_of_10_to_400_has_its_unit_direction() {
    // The direction (0, 0, 10^400) is beyond f64's range; its unit vector is exactly (0, 0, 1).
    // The twin of the unit direction was `inf / inf` = NaN and the answer was refused.
    let v = exact_answer(
        r#"{"kind":"plane_plane","planes":[{"normal":["10^400",0,0],"point":[1,1,1]},{"normal":[0,1,0],"point":[2,1,1]}]}"#,
    );
    assert_eq!(v["outcome"], "line");
    assert_eq!(v["unit_direction"], json!(["0", "0", "1"]));
    assert_eq!(v["approx"]["unit_direction"], json!([0.0, 0.0, 1.0]));
    assert_eq!(v["approx"]["direction"][2], Value::Null);
    assert_eq!(listed(&v), ["approx.direction[2]"]);
    assert!(v["direction"][2].as_str().unwrap().len() > 400);
}

#[test]
fn plane_plane_unit_direction_outside_the_field_is_approximated_from_exact_values() {
    // n1 x n2 = (0, -10^400 (1 + sqrt 2), 10^400): |n1 x n2|^2 is not a square in the field,
    // so the unit direction is an expression, and its twin comes from c^2 / |n1 x n2|^2.
    let v = exact_answer(
        r#"{"kind":"plane_plane","planes":[{"normal":["10^400",0,0],"point":[0,0,0]},{"normal":[0,1,"1+sqrt(2)"],"point":[0,0,0]}]}"#,
    );
    assert_eq!(v["unit_direction_in_field"], false);
    let u = &v["approx"]["unit_direction"];
    let (y, z) = (u[1].as_f64().unwrap(), u[2].as_f64().unwrap());
    // (-(1 + sqrt 2), 1) / sqrt(4 + 2 sqrt 2).
    let n = (4.0 + 2.0 * 2f64.sqrt()).sqrt();
    assert!((y + (1.0 + 2f64.sqrt()) / n).abs() < 1e-12, "{u}");
    assert!((z - 1.0 / n).abs() < 1e-12, "{u}");
    assert_eq!(u[0], 0.0);
}

#[test]
fn cylinder_sphere_with_10_to_400_coordinates_is_answered() {
    // The twins of the curve points were NaN (a term of 10^400 minus another).
    let v = exact_answer(
        r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0,0],"radius":"10^400","beta":{"cos":1,"sin":0},"gamma":{"cos":1,"sin":0}},"sphere":{"center":["10^400",0,0],"radius":"2*10^400"},"samples":8}"#,
    );
    assert_eq!(v["intersects"], true);
    let paths = listed(&v);
    assert!(paths.contains(&"points[0].approx[0]"), "{paths:?}");
    assert!(v["points"][0]["point"][0].is_string() || v["points"][0].is_object());
}

#[test]
fn ruled_plane_with_a_9999_digit_coefficient_is_answered() {
    // Weighted points of 10^9999 times sqrt(2) and sqrt(6): their twins were NaN.
    let big = "9".repeat(9999);
    let v = exact_answer(&format!(
        r#"{{"kind":"ruled_plane","base":[[0,0,-1],[1,1,-1],[0,2,-1]],"directions":[[-1,1,"sqrt(2)"],[-1,-1,"sqrt(6)"]],"plane":[0,0,"{big}",0]}}"#
    ));
    let paths = listed(&v);
    assert!(paths.contains(&"approx.weights[0]"), "{paths:?}");
    assert!(
        paths
            .iter()
            .any(|p| p.starts_with("approx.weighted_points")),
        "{paths:?}"
    );
    assert_eq!(v["approx"]["weights"][0], Value::Null);
    assert!(v["weights"][0].as_str().unwrap().len() > 9000);
}

#[test]
fn ph_offset_with_u_of_10_to_200_is_answered() {
    // The cusp's `point_approx` overflows: it was refused as an f64 computation.
    let v = exact_answer(
        r#"{"kind":"ph_offset","u":["10^200",1],"v":[1,10],"start":[0,0],"r":[3,"63/5",15]}"#,
    );
    let paths = listed(&v);
    assert!(
        paths.contains(&"offsets[0].cusps[0].point_approx[0]"),
        "{paths:?}"
    );
    assert!(v["offsets"][0]["cusps"][0]["point_approx"][0].is_null());
}

#[test]
fn conic_rulings_with_a_normal_of_10_to_400_are_answered() {
    // A plane through the apex: the rulings' twins were computed in f64 from the twins of the
    // normal (`-a c + b sqrt(D)` = `-inf + inf`, NaN); they come from the exact directions now.
    let v = exact_answer(r#"{"kind":"conic","plane":["10^400",1,1,0]}"#);
    assert_eq!(v["type"], "line_pair");
    let paths = listed(&v);
    // The first ruling is (0, -10^800, 10^800 + 1): its first twin is 0, the others listed.
    assert!(
        paths.contains(&"degenerate.rulings[0].approx[1]"),
        "{paths:?}"
    );
    assert_eq!(v["degenerate"]["rulings"][0]["approx"][0], json!(0.0));
    for r in v["degenerate"]["rulings"].as_array().expect("rulings") {
        assert!(r["direction"].is_array(), "{r}");
    }
}

/// Refused in one line naming f64's range, exit status 2, nothing on standard output.
fn assert_f64_refusal(o: &std::process::Output, what: &str) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{what}: {err}");
    assert!(!err.contains("panicked"), "{what}: {err}");
    assert_eq!(err.lines().count(), 1, "{what}: {err}");
    assert!(
        err.contains("f64 underflows/overflows here; use exact mode"),
        "{what}: {err}"
    );
    assert!(o.stdout.is_empty(), "{what}");
}

#[test]
fn a_conic_whose_squares_leave_f64s_range_is_refused_in_float_mode() {
    // |normal|^2 underflows to 0 (the angle rule saw a zero normal and panicked) or
    // overflows.
    for (normal, modes) in [
        ("[1e-200, 0, 1e-200]", &["--float"][..]),
        (r#"["1/10^200", 0, "1/10^200"]"#, &["--float", "--both"][..]),
        ("[1e200, 0, 1e200]", &["--float"][..]),
    ] {
        let problem = format!(r#"{{"kind":"conic","normal":{normal},"point":[1,1,1]}}"#);
        for mode in modes {
            let o = solve_stdin(problem.as_bytes(), &[mode]);
            assert_f64_refusal(&o, &format!("{mode} {problem}"));
        }
    }
}

#[test]
fn plot_of_a_conic_beyond_f64s_range_is_refused() {
    // The drawing data was inf or NaN and `f64::clamp` panicked on the view box.
    let dir = std::env::temp_dir().join(format!("exactcheck-f64-range-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    for (name, normal) in [
        ("big", r#"["10^400", 1, 1]"#),
        ("tiny", r#"["1/10^200", 0, "1/10^200"]"#),
    ] {
        let input = dir.join(format!("{name}.json"));
        std::fs::write(
            &input,
            format!(r#"{{"kind":"conic","normal":{normal},"point":[1,1,1]}}"#),
        )
        .expect("write");
        let o = common::exactcheck()
            .arg("plot")
            .arg(&input)
            .arg("-o")
            .arg(dir.join(format!("{name}.svg")))
            .output()
            .expect("runs");
        assert_f64_refusal(&o, name);
        assert!(!dir.join(format!("{name}.svg")).exists());
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_conic_next_to_a_parabola_is_decided() {
    // c^2 - (a^2 + b^2) = 2/10^3000 + 1/10^6000: an ellipse whose weights have a complex pair of
    // zeros about 10^-1500 from the real axis. Their isolation halved the unit interval
    // thousands of times (past 30 s); it is decided by the quadratic's discriminant now.
    let v = solve(
        r#"{"kind":"conic","normal":[1,0,"1+1/10^3000"],"point":[1,1,1]}"#,
        Mode::Exact,
    )
    .expect("an answer");
    assert_eq!(v["type"], "ellipse");
    assert_eq!(v["type_by_bezier"], "ellipse");
    for piece in v["pieces"].as_array().expect("pieces") {
        assert_eq!(piece["poles"], json!([]), "{piece}");
    }
    // Its neighbour on the other side: a hyperbola with two real poles about 10^-1500 apart,
    // separated at the weight's vertex.
    let v = solve(
        r#"{"kind":"conic","normal":[1,0,"1-1/10^3000"],"point":[1,1,1]}"#,
        Mode::Exact,
    )
    .expect("an answer");
    assert_eq!(v["type"], "hyperbola");
    assert_eq!(v["type_by_bezier"], "hyperbola");
    let poles: usize = v["pieces"]
        .as_array()
        .expect("pieces")
        .iter()
        .map(|p| p["poles"].as_array().expect("poles").len())
        .sum();
    assert_eq!(poles, 2, "{v}");
}

// ------------------------------------------------------------------ plane_plane --both

/// A rational `p/q` as exact text.
fn ratio() -> impl Strategy<Value = (i64, i64)> {
    (-9i64..=9, 1i64..=12)
}

fn text((p, q): (i64, i64)) -> String {
    format!("{p}/{q}")
}

/// Exactly parallel (`coincident == false`) or coincident rational plane pairs: `n2 = k n1`,
/// and the second point on the first plane (moved within it along `n1 x e`) or off it (moved
/// along `n1`).
fn parallel_pair() -> impl Strategy<Value = (String, bool)> {
    (
        prop::array::uniform3(ratio()),
        ratio(),
        prop::array::uniform3(ratio()),
        ratio(),
        any::<bool>(),
    )
        .prop_filter("non-zero normal and factor", |(n, k, _, s, _)| {
            n.iter().any(|c| c.0 != 0) && k.0 != 0 && s.0 != 0
        })
        .prop_map(|(n, k, p, s, coincident)| {
            let n1 = n.map(text);
            let n2 = n.map(|c| format!("({})*({})", text(k), text(c)));
            let p1 = p.map(text);
            // Within the plane: along n1 x (1, 0, 0) = (0, n_z, -n_y) when that is non-zero,
            // else along (0, 1, 0); off it: along n1.
            let shift: [String; 3] = if coincident {
                if n[1].0 != 0 || n[2].0 != 0 {
                    ["0".into(), text(n[2]), format!("-({})", text(n[1]))]
                } else {
                    ["0".into(), "1".into(), "0".into()]
                }
            } else {
                n.map(text)
            };
            let p2: Vec<String> = (0..3)
                .map(|i| format!("{} + ({})*({})", p1[i], text(s), shift[i]))
                .collect();
            let plane = |n: &[String], p: &[String]| json!({"normal": n, "point": p});
            let problem = json!({
                "kind": "plane_plane",
                "planes": [plane(&n1, &p1), plane(&n2, &p2)],
            });
            (problem.to_string(), coincident)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 80, failure_persistence: None, ..ProptestConfig::default() })]

    /// `--both` on exactly parallel or coincident planes always gives the exact answer; a float
    /// `line` is flagged as a disagreement, a float failure is a note beside the exact answer.
    #[test]
    fn both_keeps_the_exact_answer_and_flags_disagreements((problem, coincident) in parallel_pair()) {
        let v = solve(&problem, Mode::Both).unwrap_or_else(|e| panic!("{problem}: {e}"));
        prop_assert!(!has_null_number(&v), "{}", v);
        prop_assert_eq!(&v["outcome"], if coincident { "coincident" } else { "parallel" });
        let float = &v["float"];
        match float["outcome"].as_str() {
            Some("parallel") => {
                prop_assert_eq!(&v["float_agrees"], &json!(true));
                prop_assert!(v.get("float_note").is_none(), "{}", v);
            }
            Some("line") => {
                prop_assert_eq!(&v["float_agrees"], &json!(false));
                let note = v["float_note"].as_str().expect("a note");
                prop_assert!(note.starts_with("disagreement: "), "{}", note);
            }
            other => {
                prop_assert!(other.is_none(), "{}", v);
                prop_assert!(float["error"].is_string(), "{}", v);
                prop_assert!(v.get("float_agrees").is_none(), "{}", v);
                prop_assert!(v["float_note"].as_str().expect("a note").starts_with("the f64 computation gave no answer: "));
            }
        }
    }
}

#[test]
fn both_answers_exit_status_0_where_the_float_part_fails() {
    // Coincident planes n2 = 3 n1: the published function divides by 1 - r^2 = 0 where
    // n2 x n1 is not rounded to zero (NaN); and 10^400, which f64 cannot read.
    for problem in [
        r#"{"kind":"plane_plane","planes":[{"normal":["1/3","1/7","1/11"],"point":[0,0,0]},{"normal":[1,"3/7","3/11"],"point":[0,0,0]}]}"#,
        r#"{"kind":"plane_plane","planes":[{"normal":[1,1,0],"point":[1,0,0]},{"normal":[0,"sqrt(2)","sqrt(2)"],"point":[0,0,"10^400"]}]}"#,
    ] {
        let o = solve_stdin(problem.as_bytes(), &["--both"]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(0), "{problem}: {err}");
        let v: Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
        assert!(v["outcome"].is_string(), "{v}");
        assert!(
            v.get("float_agrees") == Some(&json!(false)) || v["float"]["error"].is_string(),
            "{v}"
        );
    }
}
