//! `exactcheck prove --random K` with algebraic constants, angles and square roots of
//! expressions: constants are evaluated in `F_p[c]/(m)` for the minimal polynomial `m` of their
//! field, angles on their unit circles, roots as `w` with `w^2` the radicand; a true identity
//! holds with the proved bound, a false one fails only with an exact counter-example, and the
//! bad constants are one-line errors.

use crate::timed;

use timed::{prove_json, run_text as run};

/// `prove LHS RHS --random 20` holds with a bound below 2^-30.
fn holds(lhs: &str, rhs: &str) -> String {
    let (code, out, err) = run(&["prove", lhs, rhs, "--random", "20"]);
    assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("holds: "), "{lhs} = {rhs}: {out}");
    assert!(out.contains("probability <= 2^-"), "{out}");
    out
}

/// `prove LHS RHS --random 20` fails with an exact counter-example.
fn fails(lhs: &str, rhs: &str) -> String {
    let (code, out, err) = run(&["prove", lhs, rhs, "--random", "20"]);
    assert_eq!(code, 1, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("fails: at "), "{lhs} = {rhs}: {out}");
    assert!(out.contains("evaluated exactly"), "{out}");
    out
}

/// `prove LHS RHS --random 20` is undecided: the sides differ at a point modulo the prime, which
/// is no counter-example.
fn undecided(lhs: &str, rhs: &str) -> String {
    let (code, out, err) = run(&["prove", lhs, rhs, "--random", "20"]);
    assert_eq!(code, 1, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("undecided: "), "{lhs} = {rhs}: {out}");
    out
}

#[test]
fn true_identities_with_constants_hold() {
    let out = holds("(x + sqrt(2))^2", "x^2 + 2*x*sqrt(2) + 2");
    assert!(out.contains("with c = sqrt(2), c^2 - 2 = 0"), "{out}");
    assert!(out.contains("m of degree 2"), "{out}");
    holds("x*cos(pi/8)", "x*sqrt(2 + sqrt(2))/2");
    let out = holds("x*cos(2*pi/7)", "x*(2*cos(pi/7)^2 - 1)");
    assert!(out.contains("m of degree"), "{out}");
    holds("y*sqrt(2 + sqrt(3))", "y*(sqrt(6) + sqrt(2))/2");
    holds("x/(sqrt(2) - 1)", "x*(sqrt(2) + 1)");
}

#[test]
fn true_identities_with_angles_hold() {
    let out = holds("sin(x)^2 + cos(x)^2", "1");
    assert!(out.contains("angle x on its unit circle"), "{out}");
    holds("sin(3*x)", "3*sin(x) - 4*sin(x)^3");
    holds("cos(x + y)", "cos(x)*cos(y) - sin(x)*sin(y)");
    let out = holds("tan(x + y)", "(tan(x) + tan(y))/(1 - tan(x)*tan(y))");
    assert!(out.contains("cosine of a tan vanishes skipped"), "{out}");
    // An angle with a multiple of pi: its constants join the field.
    holds("sin(x + pi/7)", "sin(x)*cos(pi/7) + cos(x)*sin(pi/7)");
    holds("cos(2*x + pi/4)", "(cos(2*x) - sin(2*x))*sqrt(2)/2");
}

#[test]
fn false_identities_fail_with_an_exact_counter_example() {
    let out = fails("(x + sqrt(2))^2", "x^2 + 2*x*sqrt(3) + 2");
    assert!(out.contains("at x = 1: LHS - RHS = "), "{out}");
    assert!(out.contains("sqrt(2)") && out.contains("sqrt(3)"), "{out}");
    let out = fails("cos(x + y)", "cos(x)*cos(y) + sin(x)*sin(y)");
    assert!(out.contains("x = angle with cos x = "), "{out}");
    assert!(out.contains("y = angle with cos y = "), "{out}");
    let out = fails("x*cos(2*pi/7)", "x/2");
    assert!(out.contains("Root(") || out.contains("≈"), "{out}");
    fails("sin(3*x)", "3*sin(x) - 3*sin(x)^3");
    // The JSON answer carries the point and the exact value.
    let (code, v) = prove_json(&[
        "cos(x + y)",
        "cos(x)*cos(y) + sin(x)*sin(y)",
        "--random",
        "5",
    ]);
    assert_eq!(code, 1);
    assert_eq!(v["verdict"], "fails");
    assert!(v["counter_example"].as_array().unwrap().len() == 2, "{v}");
    let value: exactcheck_exact::Rational = v["value"].as_str().unwrap().parse().unwrap();
    assert!(!exactcheck_core::Ring::is_zero(&value));
}

#[test]
fn without_an_exact_counter_example_the_answer_is_undecided() {
    // x is both a number and an angle: a rational point gives x and its cosine and sine
    // independent values, so it is no counter-example.
    let out = undecided("x + sin(x)", "x");
    assert!(out.contains("both as a number and as an angle"), "{out}");
}

#[test]
fn calculus_with_roots_and_angles_as_printed() {
    // Lowered to the derivative or the antiderivative at the bounds with sqrt, sin and cos.
    holds("integrate(t*sin(t), t, 0, x)", "sin(x) - x*cos(x)");
    holds("diff(sin(x)^2, x)", "sin(2*x)");
    holds("diff(tan(x), x)", "1 + tan(x)^2");
    let out = holds("diff(sqrt(1 + t^2), t)", "t/sqrt(1 + t^2)");
    assert!(
        out.contains("sqrt(1 + t^2) as w with w^2 = the radicand"),
        "{out}"
    );
    holds("diff(sqrt(x), x, 2)", "-1/(4*x*sqrt(x))");
    fails("diff(sin(x)^2, x)", "2*sin(x)");
    // With a root, a difference at a point is no counter-example: the roots take either sign.
    let out = undecided("diff(sqrt(1 + t^2), t)", "1/sqrt(1 + t^2)");
    assert!(out.contains("either sign"), "{out}");
    let out = undecided("sqrt(x)*sqrt(y)", "sqrt(x*y)");
    assert!(out.contains("either sign"), "{out}");
}

#[test]
fn a_chosen_seed_reproduces_the_run() {
    let args = [
        "prove",
        "(x + sqrt(2))^2",
        "x^2 + 2*x*sqrt(2) + 2",
        "--random",
        "5",
        "--seed",
        "9",
    ];
    let (code, out, _) = run(&args);
    assert_eq!(code, 0, "{out}");
    assert!(out.starts_with("holds (reproduced): "), "{out}");
    assert_eq!(run(&args).1, out);
}

#[test]
fn bad_constants_are_one_line_errors() {
    for (lhs, want) in [
        ("tan(pi/2)*x", "undefined"),
        ("sqrt(-2)*x", "sqrt"),
        ("sin(x^2)", "not linear"),
        ("sqrt(x + sqrt(2))*x", "square root of a constant"),
    ] {
        let (code, out, err) = run(&["prove", lhs, "0", "--random", "5"]);
        assert_eq!(code, 2, "{lhs}: {out}{err}");
        assert!(out.is_empty(), "{lhs}: {out}");
        assert_eq!(err.lines().count(), 1, "{lhs}: {err}");
        assert!(err.contains(want), "{lhs}: {err}");
    }
}

#[test]
fn claims_files_random_instances_take_constants_and_angles() {
    let dir = std::env::temp_dir().join(format!("exactcheck-random30-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("claims.toml");
    std::fs::write(
        &path,
        r#"
[[claim]]
id = "triple"
kind = "instances"
lhs = "sin(3*x)"
rhs = "3*sin(x) - 4*sin(x)^3"
random = 10

[[claim]]
id = "wrong"
kind = "instances"
lhs = "(x + sqrt(2))^2"
rhs = "x^2 + 2*x*sqrt(3) + 2"
random = 10
expect = "fails"

[[claim]]
id = "octant"
kind = "instances"
lhs = "x*cos(pi/8)"
rhs = "x*sqrt(2 + sqrt(2))/2"
random = 10
"#,
    )
    .unwrap();
    let (code, out, err) = run(&["verify", path.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("3 claims, 3 as expected"), "{out}");
    assert!(
        out.contains("at x = 1: LHS - RHS = 2*sqrt(2) - 2*sqrt(3)"),
        "{out}"
    );
}
