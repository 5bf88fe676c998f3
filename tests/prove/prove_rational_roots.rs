//! `exactcheck prove` with square roots of rational functions (`sqrt(1/x)`, `sqrt(N/D)`: a
//! root variable `y` with `y^2 D = N`, `D != 0`, `y >= 0`) and absolute values (`abs(E)`, the
//! root of `E^2`), as papers print them: proved, fails with an exact counter-example, or
//! undecided with what was tried; in exact mode, with `--random`, in claims files and in
//! `regress --formula`.

use crate::common;
use crate::timed;

use timed::{prove_json, run_text as run};

/// The verdict and exit status of `prove LHS RHS [--where W]...`.
fn verdict(l: &str, r: &str, wheres: &[&str]) -> (i32, String) {
    let mut args = vec![l, r];
    for w in wheres {
        args.extend(["--where", w]);
    }
    let (code, j) = prove_json(&args);
    let v = j["verdict"].as_str().unwrap_or_else(|| panic!("{j}"));
    (code, v.to_string())
}

fn proved(cases: &[(&str, &str, &[&str])]) {
    for (l, r, w) in cases {
        assert_eq!(verdict(l, r, w), (0, "proved".into()), "{l} = {r} {w:?}");
    }
}

#[test]
fn roots_of_fractions_are_decided_with_the_sign_of_the_root() {
    proved(&[
        ("sqrt(1/x)", "1/sqrt(x)", &["x > 0"]),
        // Both sides are defined only for x > 0: the identity holds where they are.
        ("sqrt(1/x)", "1/sqrt(x)", &[]),
        ("sqrt(x/y)", "sqrt(x)/sqrt(y)", &["x > 0", "y > 0"]),
        (
            "sqrt(1 - (2*t/(1 + t^2))^2)",
            "(1 - t^2)/(1 + t^2)",
            &["-1 <= t <= 1"],
        ),
        (
            "sqrt((1 - t^2)^2/(1 + t^2)^2)",
            "abs(1 - t^2)/(1 + t^2)",
            &[],
        ),
        ("sqrt(1/x)^2", "1/x", &[]),
        ("(x/sqrt(x^2 + y^2))^2 + (y/sqrt(x^2 + y^2))^2", "1", &[]),
        // The half-angle formula on the unit circle, with the sign of the sine.
        (
            "sqrt((1 - c)/(1 + c))",
            "s/(1 + c)",
            &["c^2 + s^2 = 1", "s >= 0", "c > -1"],
        ),
    ]);
}

#[test]
fn wrong_roots_of_fractions_fail_at_an_exact_point() {
    for (l, r, w, at) in [
        (
            "sqrt(1 - (2*t/(1 + t^2))^2)",
            "(1 - t^2)/(1 + t^2)",
            &[][..],
            "t = 2",
        ),
        ("sqrt(x^2/y^2)", "x/y", &[], "x = -1/2, y = 1"),
        (
            "sqrt((1 - c)/(1 + c))",
            "s/(1 + c)",
            &["c^2 + s^2 = 1"],
            "s = -1",
        ),
    ] {
        let mut args = vec!["prove", l, r];
        for x in w {
            args.extend(["--where", x]);
        }
        let (code, out, err) = run(&args);
        assert_eq!(code, 1, "{l} = {r}: {out}{err}");
        assert!(out.starts_with("fails: at "), "{l} = {r}: {out}");
        assert!(out.contains(at), "{l} = {r}: {out}");
    }
}

#[test]
fn absolute_values_are_roots_of_squares() {
    proved(&[
        ("abs(x)", "x", &["x >= 0"]),
        ("abs(x)", "-x", &["x <= 0"]),
        ("abs(x*y)", "abs(x)*abs(y)", &[]),
        ("abs(x)^2", "x^2", &[]),
        ("abs(x)", "sqrt(x^2)", &[]),
        ("abs(x - y)", "abs(y - x)", &[]),
        ("abs(x/y)", "abs(x)/abs(y)", &[]),
        ("sqrt(x^2/y^2)", "abs(x/y)", &[]),
        ("abs(-3)", "3", &[]),
        ("abs(1 - sqrt(2))", "sqrt(2) - 1", &[]),
        // The area of a parallelogram: |cross product| = sqrt(|a|^2 |b|^2 - (a.b)^2).
        (
            "abs(a1*b2 - a2*b1)",
            "sqrt((a1^2 + a2^2)*(b1^2 + b2^2) - (a1*b1 + a2*b2)^2)",
            &[],
        ),
        // The curvature of the parabola (t, t^2): |x'y'' - y'x''| / (x'^2 + y'^2)^(3/2).
        (
            "abs(1*2 - 2*t*0)/sqrt((1^2 + (2*t)^2)^3)",
            "2/(1 + 4*t^2)^(3/2)",
            &[],
        ),
        ("diff(abs(x), x)", "x/abs(x)", &[]),
    ]);
    // |x| = x fails at x = -1, |x + y| = |x| + |y| at a point of opposite signs.
    let (code, out, _) = run(&["prove", "abs(x)", "x"]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.starts_with("fails: at x = -1, abs(x) = 1: LHS - RHS = 2"),
        "{out}"
    );
    let (code, j) = prove_json(&["abs(x + y)", "abs(x) + abs(y)"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
}

#[test]
fn roots_defined_nowhere_and_bad_calls_are_one_line() {
    for (l, says) in [
        ("sqrt(-1/(1 + x^2))", "defined nowhere"),
        ("abs(x, y)", "abs at 0: takes 1 argument, not 2"),
    ] {
        let (code, out, err) = run(&["prove", l, "0"]);
        assert_eq!((code, out.as_str()), (2, ""), "{l}: {err}");
        assert_eq!(err.lines().count(), 1, "{l}: {err}");
        assert!(err.contains(says), "{l}: {err}");
    }
}

#[test]
fn random_mode_takes_roots_of_fractions_and_absolute_values() {
    for (l, r) in [
        ("abs(x)^2", "x^2"),
        ("abs(x)", "sqrt(x^2)"),
        ("sqrt(1/x)^2*x", "1"),
    ] {
        let (code, j) = prove_json(&[l, r, "--random", "20"]);
        assert_eq!(
            (code, j["verdict"].as_str()),
            (0, Some("holds")),
            "{l} = {r}: {j}"
        );
    }
    // A difference for one sign of a root is no refutation.
    let (code, j) = prove_json(&["abs(x)", "x", "--random", "20"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("undecided")), "{j}");
}

#[test]
fn claims_files_decide_them_with_the_same_engine() {
    let rows = common::verify_json("tests/claims_file/rational_roots.toml", 0);
    assert_eq!(
        rows.verdicts(),
        ["proved", "proved", "fails", "proved", "fails"],
        "{:?}",
        rows.rows
    );
    assert!(
        rows.evidence("roots.abs_misprint").contains("x = -1"),
        "{:?}",
        rows.rows
    );
}

#[test]
fn regress_evaluates_abs_in_floating_point_and_exactly() {
    let (code, out, err) = run(&[
        "regress",
        "--formula",
        "abs(x - 1) + sqrt(1/x)",
        "--domain",
        "x in [0.5, 2]",
        "--samples",
        "200",
        "--seed",
        "3",
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let r = &doc["entries"][0];
    assert_eq!(r["compared"], 200, "{r}");
    assert_eq!(r["undecided"], 0, "{r}");
    assert!(r["max_ulps"].as_f64().is_some_and(|u| u < 8.0), "{r}");
}
