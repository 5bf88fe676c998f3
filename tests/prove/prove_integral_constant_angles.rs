//! `exactcheck prove` with definite integrals of trigonometric integrands whose bounds hold pi
//! outside the square-root field (`pi/7`, `x + pi/5`): the integral is its value `G(b) - G(a)`,
//! whose `cos(pi/7)` or `sin(x + pi/5)` are decided like constants written by hand (one
//! primitive element of their field, the addition formulas for an angle with a variable).

use crate::timed;

use timed::{prove_json, run_text as run};

fn verdict(l: &str, r: &str) -> (i32, String) {
    let (code, j) = prove_json(&[l, r]);
    let v = j["verdict"]
        .as_str()
        .unwrap_or_else(|| panic!("{l} = {r}: {j}"));
    (code, v.to_string())
}

#[test]
fn integrals_to_constant_angles_are_decided() {
    for (l, r) in [
        (
            "integrate(t*cos(t), t, 0, pi/7)",
            "pi/7*sin(pi/7) + cos(pi/7) - 1",
        ),
        ("integrate(sin(t)^2, t, 0, pi/7)", "pi/14 - sin(2*pi/7)/4"),
        (
            "integrate(cos(t), t, pi/7, 2*pi/7)",
            "sin(2*pi/7) - sin(pi/7)",
        ),
        // A bound in the square-root field still goes the fast way.
        (
            "integrate(t*cos(t), t, 0, pi/3)",
            "pi/3*sin(pi/3) + cos(pi/3) - 1",
        ),
    ] {
        assert_eq!(verdict(l, r), (0, "proved".into()), "{l} = {r}");
    }
}

#[test]
fn integrals_to_an_angle_with_a_variable_are_expanded_by_the_addition_formulas() {
    for (l, r) in [
        ("integrate(cos(t), t, 0, x + pi/5)", "sin(x + pi/5)"),
        (
            "integrate(cos(t), t, 0, x + pi/5)",
            "sin(x)*cos(pi/5) + cos(x)*sin(pi/5)",
        ),
        (
            "integrate(y*sin(t), t, x, x + pi/7)",
            "y*(cos(x) - cos(x + pi/7))",
        ),
    ] {
        assert_eq!(verdict(l, r), (0, "proved".into()), "{l} = {r}");
    }
}

#[test]
fn a_misprinted_value_fails_with_a_sentence() {
    for (l, r) in [
        ("integrate(sin(t)^2, t, 0, pi/7)", "pi/14 + sin(2*pi/7)/4"),
        (
            "integrate(t*cos(t), t, 0, pi/7)",
            "pi/7*sin(pi/7) - cos(pi/7) + 1",
        ),
        (
            "integrate(cos(t), t, 0, x + pi/5)",
            "sin(x)*cos(pi/5) - cos(x)*sin(pi/5)",
        ),
    ] {
        let (code, out, err) = run(&["prove", l, r]);
        assert_eq!(code, 1, "{l} = {r}: {out}{err}");
        assert!(out.starts_with("fails: "), "{l} = {r}: {out}");
        assert!(out.contains("LHS - RHS"), "{l} = {r}: {out}");
        assert_eq!(out.lines().count(), 1, "{out}");
    }
}

#[test]
fn a_bound_that_is_not_an_angle_is_still_refused_in_one_line() {
    let (code, out, err) = run(&["prove", "integrate(cos(t), t, 0, pi^2)", "sin(pi^2)"]);
    assert_eq!(code, 2, "{out}{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("integrate"), "{err}");
}
