//! `exactcheck prove` with angles and pi: `sin`, `cos`, `tan` of integer combinations of angle
//! variables plus rational multiples of pi are decided exactly modulo the unit circles of the
//! angles (rational multiples and constant angles: `prove_angles_as_printed`); `pi` is the transcendental constant, never a free variable. Every decision path has a
//! false identity it rejects, with an exact counter-example angle (its cosine and sine).

use crate::timed;

use timed::{prove_json, run_text as run};

/// `prove LHS RHS` is proved.
pub(crate) fn proved(lhs: &str, rhs: &str) {
    let (code, out, err) = run(&["prove", lhs, rhs]);
    assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("proved: "), "{lhs} = {rhs}: {out}");
}

/// `prove LHS RHS` fails, with the text of the verdict.
pub(crate) fn fails(lhs: &str, rhs: &str) -> String {
    let (code, out, err) = run(&["prove", lhs, rhs]);
    assert_eq!(code, 1, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("fails: "), "{lhs} = {rhs}: {out}");
    out
}

#[test]
fn the_pythagorean_identity_and_multiple_angles_are_proved() {
    let (code, out, _) = run(&["prove", "sin(x)^2 + cos(x)^2", "1"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.starts_with("proved: ") && out.contains("modulo cos(x)^2 + sin(x)^2 = 1"),
        "{out}"
    );
    proved("sin(3x)", "3 sin(x) - 4 sin(x)^3");
    proved("cos(2x)", "1 - 2 sin(x)^2");
    proved("cos(x + y)", "cos(x) cos(y) - sin(x) sin(y)");
    proved("sin(2x - 3y)", "sin(2x) cos(3y) - cos(2x) sin(3y)");
    let out = fails("sin(3x)", "3 sin(x) - 3 sin(x)^3");
    assert!(out.contains("x = angle with cos x = "), "{out}");
}

#[test]
fn the_wrong_addition_formula_fails_at_an_exact_angle() {
    let out = fails("cos(x+y)", "cos(x) cos(y) + sin(x) sin(y)");
    assert!(out.contains("x = angle with cos x = "), "{out}");
    assert!(out.contains("y = angle with cos y = "), "{out}");
    assert!(out.contains("to -2*sin(x)*sin(y)"), "{out}");
    let (code, j) = prove_json(&["cos(x+y)", "cos(x) cos(y) + sin(x) sin(y)"]);
    assert_eq!(code, 1);
    // The point is exact: a rational point of each circle.
    let c: exactcheck_exact::Rational = j["point"]["cos(x)"].as_str().unwrap().parse().unwrap();
    let s: exactcheck_exact::Rational = j["point"]["sin(x)"].as_str().unwrap().parse().unwrap();
    assert_eq!(&c * &c + &s * &s, exactcheck_exact::Rational::ONE);
}

#[test]
fn constants_at_rational_multiples_of_pi_are_radicals() {
    proved("cos(pi/4)", "sqrt(2)/2");
    proved("sin(x + pi/3)", "sin(x)/2 + sqrt(3)/2 cos(x)");
    proved("tan(pi/12)", "2 - sqrt(3)");
    proved("cos(x + 2pi)", "cos(x)");
    let out = fails("sin(pi/6)", "sqrt(3)/2");
    assert!(out.contains("a non-zero constant"), "{out}");
}

#[test]
fn tangents_are_fractions_with_their_side_condition() {
    let (code, out, _) = run(&["prove", "tan(x)", "sin(x)/cos(x)"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.trim_end().ends_with("where cos(x) != 0"), "{out}");
    proved("tan(2x)", "2 tan(x)/(1 - tan(x)^2)");
    let out = fails("tan(2x)", "2 tan(x)/(1 + tan(x)^2)");
    assert!(out.contains("x = angle with"), "{out}");
}

#[test]
fn pi_is_the_transcendental_constant() {
    let out = fails("pi", "3");
    assert!(
        out.contains("LHS - RHS = pi - 3, a non-zero polynomial in pi, and pi is transcendental"),
        "{out}"
    );
    assert!(!out.contains("pi = "), "pi is never given a value: {out}");
    proved("2*pi - pi", "pi");
    proved("(pi + 1)^2", "pi^2 + 2 pi + 1");
    let out = fails("pi*x", "3*x");
    assert!(!out.contains("pi = "), "{out}");
    let (_, j) = prove_json(&["pi*x", "3*x"]);
    assert!(j["point"].get("pi").is_none(), "{j}");
    assert!(
        j["method"].as_str().unwrap().contains("transcendental"),
        "{j}"
    );
}

#[test]
fn derivatives_of_angles_by_the_chain_rule() {
    proved("diff(sin(x), x)", "cos(x)");
    proved("diff(cos(3x), x)", "-3 sin(3x)");
    proved("diff(tan(x), x)", "1 + tan(x)^2");
    fails("diff(sin(2x), x)", "cos(2x)");
}

#[test]
fn a_variable_that_is_also_an_angle_is_never_given_a_false_point() {
    proved("diff(x sin(x), x)", "sin(x) + x cos(x)");
    let (code, out, _) = run(&["prove", "x sin(x)", "x"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("undecided: "), "{out}");
    assert!(out.contains("both as a number and as an angle"), "{out}");
}

#[test]
fn angles_that_cannot_be_decided_are_one_line_errors() {
    for (lhs, needle) in [
        ("sin(x^2)", "not linear"),
        ("tan(pi/2)", "tan(pi/2) is undefined"),
        ("sin(100000 x)", "angle-multiple = 1000"),
        ("sin(sqrt(2))", "sqrt"),
        ("diff(x, pi)", "pi is a constant"),
    ] {
        let (code, out, err) = run(&["prove", lhs, "0"]);
        assert_eq!(code, 2, "{lhs}: {out}");
        assert!(out.is_empty(), "{lhs}: {out}");
        assert_eq!(err.trim_end().lines().count(), 1, "{lhs}: {err}");
        assert!(err.contains(needle), "{lhs}: {err}");
    }
    let (code, _, err) = run(&["prove", "sin(7x)", "0", "--limit", "angle-multiple=6"]);
    assert_eq!(code, 2);
    assert!(err.contains("angle-multiple = 6"), "{err}");
}

#[test]
fn algebraic_constants_next_to_variables() {
    let (code, out, _) = run(&["prove", "x + cos(pi/5)", "x + (1+sqrt(5))/4"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("with c = cos(pi/5), 4*c^2 - 2*c - 1 = 0"),
        "{out}"
    );
    proved("sin(x+pi/5)", "sin(x)*cos(pi/5)+cos(x)*sin(pi/5)");
    proved("x*cos(2*pi/7)", "x*(2*cos(pi/7)^2 - 1)");
    proved("x*sqrt(2 + sqrt(2))", "2*x*cos(pi/8)");
    // With a square root of an expression and its sign condition.
    let (code, out, _) = run(&[
        "prove",
        "sqrt(x^2)*cos(pi/7)",
        "x*cos(pi/7)",
        "--where",
        "x >= 0",
    ]);
    assert_eq!(code, 0, "{out}");
    let (code, out, _) = run(&["prove", "x*cos(2*pi/7)", "x/2"]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.starts_with("fails: at x = 1: LHS - RHS = Root("),
        "{out}"
    );
    fails("sin(x + pi/7)", "sin(x)*cos(pi/7) + cos(x)*sin(pi/7) + 1/5");
}

#[test]
fn every_multiple_of_pi_is_exact_between_constants() {
    // cos(2 pi/7) is a root of 8c^3 + 4c^2 - 4c - 1.
    let c = "8*cos(2*pi/7)^3 + 4*cos(2*pi/7)^2 - 4*cos(2*pi/7)";
    proved(c, "1");
    fails(c, "2");
    proved("cos(2*pi/7) + cos(4*pi/7) + cos(6*pi/7)", "-1/2");
    fails("cos(2*pi/7) + cos(4*pi/7)", "-1/2");
    proved("cos(pi/5)", "(1 + sqrt(5))/4");
    proved("sin(pi/7)^2 + cos(pi/7)^2", "1");
    proved("tan(pi/5)^2", "5 - 2*sqrt(5)");
    fails("tan(pi/5)^2", "5 - sqrt(5)");
    let (code, out, err) = run(&["prove", "cos(2*pi/1009)", "0"]);
    assert_eq!(code, 2, "{out}");
    assert!(err.contains("algebraic-degree = 64"), "{err}");
}
