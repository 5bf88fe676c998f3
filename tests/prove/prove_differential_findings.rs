//! Verdicts that the differential tester (`fuzz/differential/verdicts.py`: random identities,
//! true by construction or perturbed, against their values at 50 digits) found wrong or
//! incomplete, each pinned with what the identity really is.

use crate::timed;

use timed::{prove_json, run_text as run};

/// `prove LHS RHS` fails, with the text of the verdict.
fn fails(lhs: &str, rhs: &str) -> String {
    let (code, out, err) = run(&["prove", lhs, rhs]);
    assert_eq!(code, 1, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("fails: "), "{lhs} = {rhs}: {out}");
    out
}

/// `prove LHS RHS` is proved.
fn proved(lhs: &str, rhs: &str) {
    let (code, out, err) = run(&["prove", lhs, rhs]);
    assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("proved: "), "{lhs} = {rhs}: {out}");
}

/// Pi next to a constant outside the square-root field (`sin(pi/7)`, a root of a sextic): the
/// difference is a non-zero polynomial in pi with coefficients in the constants' field, so it is
/// not zero (pi is transcendental over the algebraic numbers), as with `sqrt(2)` (square-root
/// field), where it already failed. Before, no rational value could be given to pi and the
/// verdict was `undecided`, with a reason naming an internal variable number.
#[test]
fn pi_next_to_an_algebraic_constant_fails_as_a_polynomial_in_pi() {
    let out = fails("pi + sin(pi/7)", "0");
    assert!(
        out.contains("LHS - RHS = c + pi, a non-zero polynomial in pi"),
        "{out}"
    );
    assert!(out.contains("pi is transcendental"), "{out}");
    assert!(out.contains("with c = sin(pi/7)"), "{out}");
    assert!(!out.contains("variable #"), "{out}");
    // The square-root field says the same of sqrt(2).
    let out = fails("pi + sqrt(2)", "0");
    assert!(out.contains("a non-zero polynomial in pi"), "{out}");
    // The same with a variable: a rational point for x, pi kept as pi.
    let out = fails("x*pi + cos(pi/7)*pi", "x*pi");
    assert!(
        out.contains("at x = 0: LHS - RHS = pi*c, a non-zero polynomial in pi"),
        "{out}"
    );
    // Pi that cancels leaves a number.
    let out = fails("x*pi + cos(pi/7)", "x*pi");
    assert!(out.contains("LHS - RHS = Root("), "{out}");
    assert!(!out.contains("polynomial in pi"), "{out}");
    // pi^2 sin(pi/7) (as integrate(t, t, 0, pi/7) sin(pi/7) gives) is not zero either.
    let out = fails("integrate(t, t, 0, pi/7)*sin(pi/7)", "0");
    assert!(out.contains("1/98*pi^2*c"), "{out}");
    // Pi in a divisor: the value is a fraction of polynomials in pi and c.
    let out = fails("(pi + cos(pi/7))/pi", "1");
    assert!(
        out.contains("LHS - RHS = (c)/(pi), a quotient of non-zero polynomials in pi"),
        "{out}"
    );
    // What holds is still proved, and a difference free of pi is still a number.
    proved("pi*cos(pi/7) + pi", "pi*(cos(pi/7) + 1)");
    proved("(pi + cos(pi/7))/pi", "1 + cos(pi/7)/pi");
    let out = fails("pi + cos(2*pi/7)", "pi + 1/2");
    assert!(out.contains("Root("), "{out}");
    assert!(!out.contains("polynomial in pi"), "{out}");
}

#[test]
fn pi_next_to_an_algebraic_constant_in_json() {
    let (code, j) = prove_json(&["pi*y + sin(pi/7)*pi", "pi*y"]);
    assert_eq!(code, 1, "{j}");
    assert_eq!(j["verdict"], "fails", "{j}");
    assert_eq!(j["value"], "pi*c", "{j}");
    assert!(j["point"]["y"].is_string(), "{j}");
    assert!(j["point"].get("pi").is_none(), "{j}");
    let (code, j) = prove_json(&["pi + sin(pi/7)", "pi"]);
    assert_eq!(code, 1, "{j}");
    assert_eq!(
        j["value"], "Root(64*z^6 - 112*z^4 + 56*z^2 - 7, 111/256, 7/16) ≈ 0.4338837391",
        "{j}"
    );
    let (code, j) = prove_json(&["pi^2 - sin(pi/7)", "0"]);
    assert_eq!(code, 1, "{j}");
    assert_eq!(j["value"], "-c + pi^2", "{j}");
}

/// A constant identity with pi outside an angle next to a constant outside the square-root
/// field was refused when the constant came first (`sqrt(2 + sqrt(2))*pi`: the real algebraic
/// numbers have no pi), and decided when pi came first: pi is now an indeterminate in both.
#[test]
fn pi_outside_an_angle_is_decided_in_either_order() {
    proved("sqrt(2 + sqrt(2))*pi", "pi*sqrt(2 + sqrt(2))");
    proved("pi*sqrt(2 + sqrt(2))", "sqrt(2 + sqrt(2))*pi");
    let out = fails("cos(pi/7)*pi", "2");
    assert!(
        out.contains("c*pi - 2, a non-zero polynomial in pi"),
        "{out}"
    );
    // An integral with pi in a bound and such a constant in the integrand.
    proved(
        "integrate(-6*t^2*sqrt(sqrt(2)/4 + 1/2)/7, t, pi/3, pi)",
        "-26*pi^3*sqrt(sqrt(2) + 2)/189",
    );
    let out = fails("integrate(t^2, t, 0, pi)*sqrt(2 + sqrt(2))", "0");
    assert!(out.contains("1/3*pi^3*c"), "{out}");
    // Constants alone still go to the real algebraic numbers.
    let (code, out, _) = run(&["prove", "sqrt(2 + sqrt(2))^2", "2 + sqrt(2)"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("LHS - RHS = 0 exactly"), "{out}");
}
