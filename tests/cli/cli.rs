//! End-to-end tests of the `exactcheck` binary: output contracts and exit statuses.

use crate::common;

use common::solve_stdin;
use std::process::Output;

fn exactcheck(args: &[&str]) -> Output {
    common::exactcheck()
        .args(args)
        .output()
        .expect("the binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn regress_reports_worst_cases_reproducibly() {
    let args = [
        "regress",
        "bezier-cubic",
        "--samples",
        "300",
        "--seed",
        "9",
        "--worst",
        "1",
    ];
    let (a, b) = (exactcheck(&args), exactcheck(&args));
    assert!(a.status.success());
    let s = stdout(&a);
    assert!(s.contains("300 samples, seed 9"), "{s}");
    assert!(s.contains("error in ulps"), "{s}");
    assert_eq!(s, stdout(&b));
}

#[test]
fn bad_input_is_one_line_and_status_2() {
    for args in [
        &["regress", "cylinder-sphere", "--samples", "0"][..],
        &["regress", "no-such-kernel"][..],
        &["frobnicate"][..],
    ] {
        let o = exactcheck(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(err.contains("error"), "{args:?}: {err}");
    }
    let o = exactcheck(&["regress", "cylinder-sphere", "--samples", "0"]);
    assert_eq!(String::from_utf8_lossy(&o.stderr).lines().count(), 1);
}

#[test]
fn solve_sphere_interpolation_passes_through_the_points() {
    use exactcheck_core::{Hom4, RationalBezierCurve, Vec3};
    use exactcheck_exact::radical::Radical;
    let cases = [
        (
            r#"[["9/11","6/11","-2/11"],["1/3","-2/3","2/3"]]"#,
            r#"[0, 1]"#,
        ),
        (
            r#"[["9/11","6/11","-2/11"],["1/3","-2/3","2/3"],[0,0,1],["3/5","4/5",0]]"#,
            r#"[0,"1/3","2/3",1]"#,
        ),
        (
            r#"[["9/11","6/11","-2/11"],["1/3","-2/3","2/3"],[0,0,-1],["3/5","4/5",0],["2/7","3/7","6/7"]]"#,
            r#"[0,"1/4","1/2","3/4",1]"#,
        ),
        (
            r#"[["1/sqrt(2)","1/sqrt(2)",0],[0,"sqrt(3)/2","1/2"],[1,0,0]]"#,
            r#"[0,"1/2",1]"#,
        ),
    ];
    for (points, params) in cases {
        let problem =
            format!(r#"{{"kind":"sphere_interpolation","points":{points},"params":{params}}}"#);
        let o = solve_stdin(&problem, &[]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let answer: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
        assert_eq!(answer["kind"], "sphere_interpolation");
        assert_eq!(answer["mode"], "exact");
        // Rebuild the curve from the printed exact numbers and evaluate it at each parameter.
        let num = |v: &serde_json::Value| {
            v.as_str()
                .expect("string")
                .parse::<Radical>()
                .expect("parses back")
        };
        let weights: Vec<Radical> = answer["weights"]
            .as_array()
            .unwrap()
            .iter()
            .map(num)
            .collect();
        let pts: Vec<Vec3<Radical>> = answer["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                let a = p.as_array().expect("no zero weights in these cases");
                Vec3::new(num(&a[0]), num(&a[1]), num(&a[2]))
            })
            .collect();
        let curve = RationalBezierCurve::from_weights_points(&weights, &pts).unwrap();
        let given: serde_json::Value = serde_json::from_str(points).unwrap();
        let given_params: serde_json::Value = serde_json::from_str(params).unwrap();
        let as_exact = |v: &serde_json::Value| match v {
            serde_json::Value::String(s) => s.parse::<Radical>().unwrap(),
            other => other.as_i64().unwrap().into(),
        };
        for (p, t) in given
            .as_array()
            .unwrap()
            .iter()
            .zip(given_params.as_array().unwrap())
        {
            let a = p.as_array().unwrap();
            let k = Hom4::from_point(&Vec3::new(
                as_exact(&a[0]),
                as_exact(&a[1]),
                as_exact(&a[2]),
            ));
            assert!(curve.eval_hom(&as_exact(t)).proj_eq(&k), "{problem}");
        }
        let degree = answer["degree"].as_u64().unwrap();
        assert_eq!(degree as usize, weights.len() - 1);
        if let Some(sigma) = answer["sigma_degree"].as_u64() {
            assert!(degree <= sigma);
        }
    }
}

#[test]
fn solve_rejects_bad_problems_with_status_2() {
    for (problem, needle) in [
        (r#"{"kind":"nope"}"#, "unknown kind"),
        (r#"not json"#, "malformed JSON"),
        (r#"{"points":[]}"#, "missing field \"kind\""),
        (
            r#"{"kind":"sphere_interpolation","points":[[0.5,0.5,0]],"params":[0]}"#,
            "floating-point",
        ),
        (
            r#"{"kind":"sphere_interpolation","points":[[1,1,0]],"params":[0]}"#,
            "not on the unit sphere",
        ),
        (
            r#"{"kind":"sphere_interpolation","points":[[1,0,0],[0,1,0]],"params":[0,0]}"#,
            "are equal",
        ),
        (
            r#"{"kind":"sphere_interpolation","points":[["1/0",0,0]],"params":[0]}"#,
            "division by zero",
        ),
        (
            r#"{"kind":"sphere_interpolation","points":[[1,0]],"params":[0]}"#,
            "expected 3 coordinates",
        ),
        (
            r#"{"kind":"sphere_interpolation","points":[[1,0,0]],"params":[0,1]}"#,
            "1 points but 2 parameters",
        ),
    ] {
        let o = solve_stdin(problem, &[]);
        assert_eq!(o.status.code(), Some(2), "{problem}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(needle), "{problem}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
}

fn cylinder_sphere_problem(beta: &str, gamma: &str, center: &str, radius: &str) -> String {
    format!(
        r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":5,"beta":{beta},"gamma":{gamma}}},"sphere":{{"center":{center},"radius":{radius}}},"samples":8}}"#
    )
}

#[test]
fn solve_cylinder_sphere_spaeth_examples() {
    let zero = r#"{"cos":1,"sin":0}"#;
    let answer = |problem: String| -> serde_json::Value {
        let o = solve_stdin(&problem, &[]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    // Example 3: no intersection, by both exact methods.
    let e3 = answer(cylinder_sphere_problem(zero, zero, "[6,7,8]", "1"));
    assert_eq!(e3["intersects"], false);
    assert_eq!(e3["contact_by_axis_distance"], "disjoint");
    assert_eq!(e3["points"].as_array().unwrap().len(), 0);
    // Examples 1 and 2 (2 with its radians taken as rational rotations): points on both surfaces.
    let e1 = answer(cylinder_sphere_problem(zero, zero, "[1,0,0]", "7"));
    let e2 = answer(cylinder_sphere_problem(
        r#"{"radians":1}"#,
        r#"{"radians":-1}"#,
        "[1,2,4]",
        "5",
    ));
    for e in [&e1, &e2] {
        assert_eq!(e["intersects"], true);
        assert_eq!(e["methods_agree"], true);
        assert!(!e["points"].as_array().unwrap().is_empty());
        assert_eq!(e["all_points_on_both_surfaces"], true);
    }
    assert_eq!(e1["components"], 2);
    assert!(e2["approximated_angles"].as_array().unwrap().len() == 2);
    // Example 1's exact points re-parsed and checked independently: x^2 + y^2 = 25 and
    // (x-1)^2 + y^2 + z^2 = 49.
    use exactcheck_core::Ring;
    use exactcheck_exact::Radical;
    for p in e1["points"].as_array().unwrap() {
        let c: Vec<Radical> = p["exact"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_str().unwrap().parse().unwrap())
            .collect();
        assert_eq!(c[0].square() + c[1].square(), Radical::from(25));
        let x1 = c[0].clone() - Radical::from(1);
        assert_eq!(
            x1.square() + c[1].square() + c[2].square(),
            Radical::from(49)
        );
    }
    // A sphere touching the cylinder from outside: one tangency point, exactly (5, 0, 3).
    let t = answer(cylinder_sphere_problem(zero, zero, "[8,0,3]", "3"));
    assert_eq!(t["contact"], "tangent");
    assert_eq!(t["contact_by_axis_distance"], "tangent");
    let tp = t["tangent_points"].as_array().unwrap();
    assert_eq!(tp.len(), 1);
    assert_eq!(tp[0]["point"], serde_json::json!(["5", "0", "3"]));
    assert_eq!(tp[0]["on_both_surfaces"], true);
}

#[test]
fn solve_cylinder_sphere_rejects_bad_input() {
    for (problem, needle) in [
        (
            cylinder_sphere_problem(
                r#"{"cos":1,"sin":1}"#,
                r#"{"cos":1,"sin":0}"#,
                "[1,0,0]",
                "7",
            ),
            "cos^2 + sin^2",
        ),
        (
            cylinder_sphere_problem(
                r#"{"cos":1,"sin":0}"#,
                r#"{"cos":1,"sin":0}"#,
                "[1,0,0]",
                "0",
            ),
            "sphere.radius must be positive",
        ),
        (
            cylinder_sphere_problem(r#"{"cos":1,"sin":0}"#, r#"{"cos":1,"sin":0}"#, "[1,0]", "7"),
            "sphere.center",
        ),
        (
            cylinder_sphere_problem(r#"{"cos":1}"#, r#"{"cos":1,"sin":0}"#, "[1,0,0]", "7"),
            "cylinder.beta.sin",
        ),
    ] {
        let o = solve_stdin(&problem, &[]);
        assert_eq!(o.status.code(), Some(2), "{problem}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(needle), "{problem}: {err}");
    }
    // Float mode accepts radians and float literals.
    let o = solve_stdin(
        cylinder_sphere_problem(
            r#"{"radians":1.0}"#,
            r#"{"radians":-1.0}"#,
            "[1.0,2.0,4.0]",
            "5.0",
        ),
        &["--float"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

// ------------------------------------------------------------------------------- prove

fn prove_json(args: &[&str]) -> (Option<i32>, serde_json::Value) {
    let mut all = vec!["prove"];
    all.extend_from_slice(args);
    all.push("--json");
    let o = exactcheck(&all);
    let v = serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|_| panic!("{args:?}: not JSON: {}", stdout(&o)));
    (o.status.code(), v)
}

fn stderr_line(args: &[&str]) -> String {
    let o = exactcheck(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    err
}

#[test]
fn prove_random_is_sound_for_multiples_of_the_old_prime() {
    // Old wrong answers: all three said `holds` (fixed modulus 2^61 - 1).
    for (lhs, rhs, k) in [
        ("2305843009213693951*x", "0", "5"),
        ("x + 2305843009213693951", "x", "20"),
        ("x^2305843009213693951", "x", "20"),
        (
            "2305843009213693951*2305843009213693921*2305843009213693907*x",
            "0",
            "3",
        ),
        (
            "4611686018427388039*4611686018427388073*4611686018427388081*4611686018427388091*x",
            "0",
            "3",
        ),
    ] {
        let (code, v) = prove_json(&[lhs, rhs, "--random", k]);
        assert_eq!(v["verdict"], "fails", "{lhs}: {v}");
        assert_eq!(code, Some(1));
        let p = v["prime"].as_u64().unwrap();
        assert!(p >= 1 << 62, "{v}");
    }
    // A true identity with a chosen seed is reproduced (same prime, same answer) but carries no
    // bound; with a fresh seed it holds with the bound, the seed and the prime printed.
    let args = [
        "(x+y)^3",
        "x^3 + 3*x^2*y + 3*x*y^2 + y^3",
        "--random",
        "3",
        "--seed",
        "11",
    ];
    let (code, v) = prove_json(&args);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(0), Some("holds (reproduced)")),
        "{v}"
    );
    assert_eq!(v["seed"], 11);
    assert!(v.get("log2_error_bound").is_none(), "{v}");
    assert_eq!(prove_json(&args).1, v);
    let (code, v) = prove_json(&args[..4]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(0), Some("holds")),
        "{v}"
    );
    assert!(v["log2_error_bound"].as_f64().unwrap() < -30.0);
    let text = stdout(&exactcheck(&["prove", "x", "x", "--random", "2"]));
    assert!(text.starts_with("holds") && text.contains("seed") && text.contains("prime"));
}

#[test]
fn prove_random_with_a_chosen_seed_cannot_be_aimed_at_its_prime() {
    // `x = 0` with seed 7 fails and prints its prime p. `p x = 0` with the same seed was then
    // evaluated modulo that same p and answered `holds` with "probability <= 2^-55.9". The
    // prime now depends on the identity too: p x = 0 fails, modulo another prime.
    let (code, v) = prove_json(&["x", "0", "--random", "5", "--seed", "7"]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("fails")),
        "{v}"
    );
    let p = v["prime"].as_u64().unwrap();
    let crafted = format!("{p}*x");
    let (code, w) = prove_json(&[&crafted, "0", "--random", "5", "--seed", "7"]);
    assert_eq!(
        (code, w["verdict"].as_str()),
        (Some(1), Some("fails")),
        "{w}"
    );
    let q = w["prime"].as_u64().unwrap();
    assert_ne!(p, q);
    assert_ne!(p % q, 0, "the prime used divides the coefficient");
    // A weak bound under a chosen seed is named as what a fresh seed would give.
    let (code, v) = prove_json(&[
        "0*x^2305843009213693951",
        "0",
        "--random",
        "10",
        "--seed",
        "3",
    ]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("undecided")),
        "{v}"
    );
    let evidence = v["evidence"].as_str().unwrap();
    assert!(
        evidence.contains("the error bound a fresh seed would give is"),
        "{v}"
    );
}

#[test]
fn prove_counter_examples_give_every_variable_of_both_sides() {
    // `a` cancels from the residual b^3; the point used to be `b = 3/2` alone.
    let (code, v) = prove_json(&["(a+b)^3", "a^3 + 3a^2 b + 3 a b^2"]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("fails")),
        "{v}"
    );
    let point = v["point"].as_object().unwrap();
    assert!(point.contains_key("a") && point.contains_key("b"), "{v}");
    let text = stdout(&exactcheck(&["prove", "(a+b)^3", "a^3 + 3a^2 b + 3 a b^2"]));
    assert!(text.starts_with("fails: at a = "), "{text}");
    // A variable only in a relation is given too, as before.
    let (_, v) = prove_json(&["x + y", "y", "--where", "x = 2 z"]);
    let point = v["point"].as_object().unwrap();
    assert!(
        ["x", "y", "z"].iter().all(|n| point.contains_key(*n)),
        "{v}"
    );
}

#[test]
fn prove_random_says_undecided_when_the_bound_is_weak() {
    // Degree 2^61: one bit per point; 10 points are not enough for `holds`.
    let (code, v) = prove_json(&["0*x^2305843009213693951", "0", "--random", "10"]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("undecided")),
        "{v}"
    );
    assert!(v["evidence"].as_str().unwrap().contains("more points"));
    // Bounds beyond 64 bits never wrap.
    let (code, v) = prove_json(&[
        "0*((x^4294967296)^4294967296)^4294967296",
        "0",
        "--random",
        "3",
    ]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("undecided")),
        "{v}"
    );
}

#[test]
fn prove_random_limits_are_one_line_errors() {
    // Old: `--random 4294967295` ran four billion trials.
    assert!(stderr_line(&["prove", "x", "x", "--random", "4294967295"]).contains("100000"));
    assert!(stderr_line(&["prove", "x", "x", "--random", "0"]).contains("100000"));
    assert!(
        stderr_line(&["prove", "sqrt(x + sqrt(2))*x", "0", "--random", "3"])
            .contains("without --random")
    );
    assert!(stderr_line(&["prove", "tan(pi/2)*x", "0", "--random", "3"]).contains("undefined"));
    stderr_line(&["prove", "x", "0", "--random", "3", "--where", "x > 0"]);
    stderr_line(&["prove", "x", "0", "--random", "3", "--where", "x*y = 1"]);
}

#[test]
fn prove_inconsistent_relations_are_errors() {
    // Old wrong answers: both said `proved`.
    assert!(stderr_line(&["prove", "x", "0", "--where", "1 = 2"]).contains("inconsistent"));
    assert!(
        stderr_line(&["prove", "x", "0", "--where", "x = 1", "--where", "x = 2"])
            .contains("inconsistent")
    );
}

#[test]
fn prove_fails_at_a_point_of_the_relations() {
    // Old: `undecided` for both.
    let (code, v) = prove_json(&["c^2 + s^2", "1", "--where", "c^2 + s^2 = 2"]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("fails")),
        "{v}"
    );
    let c: exactcheck_exact::Radical = v["point"]["c"].as_str().unwrap().parse().unwrap();
    let s: exactcheck_exact::Radical = v["point"]["s"].as_str().unwrap().parse().unwrap();
    use exactcheck_core::Ring;
    assert_eq!(c.square() + s.square(), exactcheck_exact::Radical::from(2));
    assert_eq!(v["value"], "1");
    let (code, v) = prove_json(&["x", "1", "--where", "x = 2"]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("fails")),
        "{v}"
    );
    assert_eq!(v["point"]["x"], "2");
    // No real point where the residual is non-zero: undecided, saying what was searched.
    let (code, v) = prove_json(&["x", "0", "--where", "x^2 + y^2 = 0"]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("undecided")),
        "{v}"
    );
    assert!(
        v["evidence"].as_str().unwrap().contains("searched")
            || v["evidence"].as_str().unwrap().contains("checked")
    );
}

#[test]
fn prove_domains_keep_counter_examples_inside() {
    let (code, v) = prove_json(&["r + R", "0", "--where", "r > 0", "--where", "R >= 1/2"]);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (Some(1), Some("fails")),
        "{v}"
    );
    let r: exactcheck_exact::Rational = v["point"]["r"].as_str().unwrap().parse().unwrap();
    let big_r: exactcheck_exact::Rational = v["point"]["R"].as_str().unwrap().parse().unwrap();
    assert!(r > exactcheck_exact::Rational::ZERO);
    assert!(big_r >= exactcheck_exact::Rational::new(1, 2).unwrap());
    let (_, v) = prove_json(&["t - t^2", "0", "--where", "0 <= t <= 1"]);
    let t: exactcheck_exact::Rational = v["point"]["t"].as_str().unwrap().parse().unwrap();
    assert!(t > exactcheck_exact::Rational::ZERO && t < exactcheck_exact::Rational::ONE);
    // x^2 = 4 with x < 0 fails at -2 only.
    let (_, v) = prove_json(&["x", "2", "--where", "x^2 = 4", "--where", "x < 0"]);
    assert_eq!(v["point"]["x"], "-2", "{v}");
    // Bad domains: one line, status 2.
    for bad in ["2 < x < 1", "x > y", "x >= 1 = 2", "0 < x > 1", "x < z"] {
        stderr_line(&["prove", "x", "0", "--where", bad]);
    }
    stderr_line(&["prove", "x", "0", "--where", "x > 0", "--where", "x < 1"]);
}

#[test]
fn prove_accepts_a_leading_minus() {
    // Old: clap took '-x^2' for an option and printed a usage error.
    let o = exactcheck(&["prove", "-x^2", "-(x^2)"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(stdout(&o).starts_with("proved"));
    let o = exactcheck(&["prove", "x", "0", "--where", "-x = 1"]);
    assert!(stdout(&o).starts_with("fails"), "{}", stdout(&o));
}

/// Regression: input outside the grammar was misread as variables and juxtaposition
/// (`1e3` as the variable `e3`, `exp(2x)` as `exp*(2x)`) and answered `fails`. Scientific
/// notation is now read exactly; an unknown function is a one-line error, exit 2.
#[test]
fn prove_reads_scientific_notation_and_refuses_unknown_functions() {
    for (lhs, rhs) in [
        ("1e3", "1000"),
        ("1e5", "100000"),
        ("x + 2.5e-3", "x + 0.0025"),
        ("1E+5 x", "100000 x"),
    ] {
        let (code, v) = prove_json(&[lhs, rhs]);
        assert_eq!(code, Some(0), "{lhs} = {rhs}: {v}");
        assert_eq!(v["verdict"], "proved", "{lhs} = {rhs}: {v}");
    }
    for args in [["exp(x)", "x"], ["exp(2x)", "exp(x)^2"]] {
        let o = exactcheck(&["prove", args[0], args[1]]);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(o.stdout.is_empty(), "{args:?}: no verdict may be printed");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains("unknown function 'exp'"), "{err}");
    }
}
