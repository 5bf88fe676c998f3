//! `exactcheck prove` with angles as papers print them: rational multiples of angle variables
//! (`tan(x/2)`, `cos(3x/4)`) are decided in the base angle `x/L`, and constant angles that are
//! not multiples of pi (`sin(1)`, `cos(2 + pi/3)`) in the constant base angle, whose cosine and
//! sine satisfy only their circle (Lindemann–Weierstrass). A false identity fails with an exact
//! counter-example, which the tests evaluate again; with pi outside an angle next to a constant
//! angle the answer is undecided.

use crate::timed;

use exactcheck_exact::Rational;
use timed::{prove_json, run_text as run};

fn proved(lhs: &str, rhs: &str) -> String {
    let (code, out, err) = run(&["prove", lhs, rhs]);
    assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("proved: "), "{lhs} = {rhs}: {out}");
    out
}

fn fails(lhs: &str, rhs: &str) -> String {
    let (code, out, err) = run(&["prove", lhs, rhs]);
    assert_eq!(code, 1, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("fails: "), "{lhs} = {rhs}: {out}");
    out
}

/// The rational number written at the start of `text` (up to a comma, semicolon, colon or
/// space).
fn number_at(text: &str) -> Rational {
    let end = text.find([',', ';', ':', ' ']).unwrap_or(text.len());
    text[..end].parse().unwrap()
}

/// The value after `name = ` in `text`.
fn value_of(text: &str, name: &str) -> Rational {
    let key = format!("{name} = ");
    let at = text
        .find(&key)
        .unwrap_or_else(|| panic!("{name} in {text}"))
        + key.len();
    number_at(&text[at..])
}

#[test]
fn half_angle_formulas_are_proved_in_the_base_angle() {
    let out = proved("sin(x)", "2 tan(x/2)/(1 + tan(x/2)^2)");
    assert!(out.contains("cos(x/2)^2 + sin(x/2)^2 = 1"), "{out}");
    proved("cos(x)", "(1 - tan(x/2)^2)/(1 + tan(x/2)^2)");
    proved("tan(x)", "2 tan(x/2)/(1 - tan(x/2)^2)");
    proved("cos(3x/4)", "4 cos(x/4)^3 - 3 cos(x/4)");
    proved("sin(x/2)^2", "(1 - cos(x))/2");
    proved("diff(sin(x/2), x)", "cos(x/2)/2");
    // The half angle in a hypothesis counts too: the base of x is x/2 everywhere.
    let (code, out, err) = run(&[
        "prove",
        "sin(x)",
        "2 s c",
        "--where",
        "s = sin(x/2)",
        "--where",
        "c = cos(x/2)",
    ]);
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn a_misprinted_weierstrass_formula_fails_at_an_exact_point() {
    // sin(x) = 2 t/(1 - t^2) with t = tan(x/2): the printed denominator has the wrong sign.
    let out = fails("sin(x)", "2 tan(x/2)/(1 - tan(x/2)^2)");
    assert!(out.contains("x = angle with cos(x/2) = "), "{out}");
    let (c, s) = (value_of(&out, "cos(x/2)"), value_of(&out, "sin(x/2)"));
    assert_eq!(&c * &c + &s * &s, Rational::ONE, "{out}");
    // Evaluate both sides again at the point: sin(x) = 2 s c, tan(x/2) = s/c.
    let two = Rational::from_integer(2);
    let t = s.checked_div(&c).unwrap();
    let lhs = &(&two * &s) * &c;
    let rhs = (&two * &t)
        .checked_div(&(Rational::ONE - &(&t * &t)))
        .unwrap();
    let difference = lhs - rhs;
    assert_ne!(difference, Rational::ZERO);
    assert_eq!(value_of(&out, "LHS - RHS"), difference, "{out}");
}

#[test]
fn constant_angles_are_decided_by_lindemann_weierstrass() {
    proved("sin(2)", "2 sin(1) cos(1)");
    let out = proved("cos(1)^2 + sin(1)^2", "1");
    assert!(out.contains("cos(1)^2 + sin(1)^2 = 1"), "{out}");
    proved("sin(2 + pi/3)", "sin(2)/2 + sqrt(3)/2 cos(2)");
    proved("tan(1)", "sin(1)/cos(1)");
    proved("cos(1/2)^2", "(1 + cos(1))/2");
    proved("sin(x + 1)", "sin(x) cos(1) + cos(x) sin(1)");
    let out = fails("sin(1)", "0");
    assert_eq!(
        out.trim_end(),
        "fails: LHS - RHS = sin(1), a non-zero polynomial in cos(1), sin(1) modulo cos(1)^2 + \
         sin(1)^2 = 1, and cos(1) + i sin(1) = e^i is transcendental (Lindemann–Weierstrass), so \
         it is not zero; LHS - RHS reduces modulo cos(1)^2 + sin(1)^2 = 1 to sin(1)"
    );
    let out = fails("sin(2)", "2 sin(1)");
    assert!(out.contains("Lindemann–Weierstrass"), "{out}");
    // With an angle variable: the point gives x, the constant angle stays itself.
    let out = fails("sin(x + 1)", "sin(x) + sin(1)");
    assert!(out.contains("at x = angle with cos x = "), "{out}");
    assert!(!out.contains("cos(1) = "), "{out}");
    assert!(out.contains("Lindemann–Weierstrass"), "{out}");
    let (code, json) = prove_json(&["sin(1)", "0"]);
    assert_eq!(code, 1);
    assert_eq!(json["verdict"], "fails", "{json}");
    assert_eq!(json["value"], "sin(1)", "{json}");
}

#[test]
fn pi_next_to_a_constant_angle_is_undecided() {
    let (code, out, err) = run(&["prove", "sin(1) + pi", "0"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("undecided: "), "{out}");
    assert!(
        out.contains("algebraically independent is not known"),
        "{out}"
    );
    // pi alone still fails (it is transcendental), and so does a constant angle alone.
    fails("cos(1)^2 + sin(1)^2", "pi");
}

#[test]
fn values_of_constant_angles_stay_one_line_errors() {
    for (args, needle) in [
        (
            &["prove", "sin(sqrt(2))", "0"][..],
            "the angle sqrt(2) is irrational",
        ),
        (&["prove", "sin(x^2)", "0"][..], "not linear"),
        (
            &["prove", "sin(x/2001) + sin(x)", "0"][..],
            "angle-multiple",
        ),
    ] {
        let (code, out, err) = run(args);
        assert_eq!(code, 2, "{args:?}: {out}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn the_randomized_test_agrees() {
    for (lhs, rhs) in [
        ("sin(x)", "2 tan(x/2)/(1 + tan(x/2)^2)"),
        ("sin(2)", "2 sin(1) cos(1)"),
        ("cos(3x/4 + 1)", "cos(3x/4) cos(1) - sin(3x/4) sin(1)"),
    ] {
        let (code, out, err) = run(&["prove", lhs, rhs, "--random", "20"]);
        assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
        assert!(out.starts_with("holds: "), "{out}");
    }
    let (code, out, err) = run(&[
        "prove",
        "sin(x)",
        "2 tan(x/2)/(1 - tan(x/2)^2)",
        "--random",
        "20",
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        out.starts_with("fails: at x = angle with cos(x/2) = "),
        "{out}"
    );
    let (code, out, err) = run(&["prove", "sin(1)", "0", "--random", "20"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("fails: LHS - RHS = "), "{out}");
    assert!(out.contains("Lindemann–Weierstrass"), "{out}");
}

#[test]
fn a_claims_file_identity_with_a_half_angle() {
    let (code, out, err) = run(&["verify", "tests/claims_file/half_angles.toml"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("2 claims, 2 as expected"), "{out}");
    assert!(out.contains("x = angle with cos(x/2) = "), "{out}");
}
