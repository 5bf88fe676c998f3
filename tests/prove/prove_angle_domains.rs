//! `exactcheck prove` with the domain of an angle of sin, cos and tan given as printed, in
//! multiples of pi (`0 <= theta <= pi`, `-\pi \le \theta \le \pi`): it becomes the signs of the
//! cosine and sine of the angle's base (`sin(theta/2) >= 0` for `0 <= theta <= 2 pi`), which say
//! exactly the same over a quarter or a half turn. Half-angle formulas with their square roots
//! are then proved; their false twins fail at a point inside the domain; other arcs are
//! refused in one line.

use crate::timed;

use timed::{prove_verdict as verdict, run_text as run};

/// The exact value of `name` at the counter-example (`"0"`, `"-1"`, `"sqrt(2)/2"`).
fn at<'a>(j: &'a serde_json::Value, name: &str) -> &'a str {
    j["point"][name]
        .as_str()
        .unwrap_or_else(|| panic!("no {name} in {j}"))
}

#[test]
fn half_angle_formulas_are_proved_on_their_domains() {
    for args in [
        &[
            "sqrt(1-cos(theta)^2)",
            "sin(theta)",
            "--where",
            "0 <= theta <= pi",
        ][..],
        &[
            "\\sqrt{\\frac{1-\\cos\\theta}{2}}",
            "\\sin\\frac{\\theta}{2}",
            "--where",
            "0 <= theta <= 2pi",
        ],
        &[
            "\\sqrt{\\frac{1+\\cos\\theta}{2}}",
            "\\cos\\frac{\\theta}{2}",
            "--where",
            "-\\pi \\le \\theta \\le \\pi",
        ],
        &["sqrt(1-sin(x)^2)", "cos(x)", "--where", "-pi/2 < x < pi/2"],
        &[
            "sqrt((1-cos(t))/(1+cos(t)))",
            "tan(t/2)",
            "--where",
            "0 <= t < pi",
        ],
        &[
            "sqrt(1-cos(x)^2)",
            "-sin(x)",
            "--where",
            "$\\pi \\leq x \\leq 2\\pi$",
        ],
    ] {
        let (code, v, j) = verdict(args);
        assert_eq!((code, v.as_str()), (0, "proved"), "{args:?}: {j}");
        let evidence = j["evidence"].as_str().unwrap_or_default();
        assert!(evidence.contains(" 0 since "), "{args:?}: {evidence}");
    }
}

#[test]
fn the_false_twins_fail_inside_the_domain() {
    // On -pi <= theta <= 0 the root is -sin(theta): the point has sin(theta) <= 0.
    let (code, v, j) = verdict(&[
        "sqrt(1-cos(theta)^2)",
        "sin(theta)",
        "--where",
        "-pi <= theta <= 0",
    ]);
    assert_eq!((code, v.as_str()), (1, "fails"), "{j}");
    assert!(at(&j, "sin(theta)").starts_with('-'), "{j}");
    // A full turn says nothing about the sign.
    let (code, v, j) = verdict(&[
        "sqrt(1-cos(theta)^2)",
        "sin(theta)",
        "--where",
        "0 <= theta <= 2pi",
    ]);
    assert_eq!((code, v.as_str()), (1, "fails"), "{j}");
    // On -pi < t <= 0, tan(t/2) <= 0 while the root is not negative; the point has
    // sin(t/2) <= 0 < cos(t/2).
    let (code, v, j) = verdict(&[
        "sqrt((1-cos(t))/(1+cos(t)))",
        "tan(t/2)",
        "--where",
        "-pi < t <= 0",
    ]);
    assert_eq!((code, v.as_str()), (1, "fails"), "{j}");
    assert!(at(&j, "sin(t/2)").starts_with('-'), "{j}");
    assert!(!at(&j, "cos(t/2)").starts_with('-'), "{j}");
    // On pi/2 <= x <= pi, cos(x) <= 0: sqrt(1 - sin(x)^2) = -cos(x), not cos(x).
    let (code, v, j) = verdict(&["sqrt(1-sin(x)^2)", "cos(x)", "--where", "pi/2 < x <= pi"]);
    assert_ne!(v, "proved", "{j}");
    assert_eq!(code, 1, "{j}");
}

#[test]
fn other_angle_domains_are_one_line_naming_the_problem() {
    for (args, expected) in [
        (
            &["sqrt(1-sin(x)^2)", "cos(x)", "--where", "0 <= x <= pi/3"][..],
            "a quarter or a half turn between multiples of pi/2",
        ),
        (
            &["sqrt(1-sin(x)^2)", "cos(x)", "--where", "0 <= x <= 1"],
            "x is an angle of sin, cos or tan: give its domain in multiples of pi",
        ),
        (
            &["sqrt(1-sin(x)^2)", "cos(x)", "--where", "1 <= x <= pi"],
            "a bound in multiples of pi and one without",
        ),
        (
            &["sqrt(1-cos(x)^2)", "sin(x)", "--where", "0 < x <= pi"],
            "one end open and one closed",
        ),
        (
            &["x*sin(x)", "0", "--where", "0 <= x <= pi"],
            "x is used as a number",
        ),
        (
            &["sin(x)", "0", "--where", "0 <= y <= pi"],
            "y is not an angle of sin, cos or tan",
        ),
    ] {
        let mut all = vec!["prove"];
        all.extend_from_slice(args);
        let (code, out, err) = run(&all);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert!(err.contains(expected), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
}

#[test]
fn comparisons_may_be_typed_in_latex_or_unicode() {
    let (code, out, err) = run(&["prove", "sqrt(x^2)", "x", "--where", "x ≥ 0"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = run(&["prove", "sqrt(x^2)", "x", "--where", "x \\geq 0"]);
    assert_eq!(code, 0, "{out}{err}");
    // A domain in LaTeX is not a relation: the verdict does not reduce modulo it.
    assert!(!out.contains("modulo"), "{out}");
}

#[test]
fn a_claims_file_takes_angle_domains() {
    let path = std::env::temp_dir().join(format!("exactcheck-angle-{}.toml", std::process::id()));
    std::fs::write(
        &path,
        r#"[paper]
name = "angles"
title = "Half-angle formulas"

[[claim]]
id = "half.sin"
statement = "sin of half the angle from its cosine"
kind = "identity"
lhs = '\sqrt{\frac{1-\cos\theta}{2}}'
rhs = '\sin\frac{\theta}{2}'
where = ['0 \le \theta \le 2\pi']
"#,
    )
    .unwrap();
    let (code, out, err) = run(&["verify", path.to_str().unwrap()]);
    std::fs::remove_file(&path).ok();
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("1 claims, 1 as expected") || out.contains("1 claim, 1 as expected"),
        "{out}"
    );
}
