//! `exactcheck prove` with `diff` and `integrate` of square roots and angles: the derivative of
//! `sqrt(R)` follows the chain rule (`R' / (2 sqrt(R))`, a fraction whose divisor becomes a
//! condition), an integrand that is a polynomial in the integration variable, its cosine and
//! its sine is integrated exactly, and one that holds another function of the variable (a root)
//! is refused with one line instead of being taken as a constant.

use crate::timed;

use timed::{prove_json, run_text as run};

fn verdict(l: &str, r: &str) -> (i32, String) {
    let (code, j) = prove_json(&[l, r]);
    (
        code,
        j["verdict"]
            .as_str()
            .unwrap_or_else(|| panic!("{j}"))
            .to_string(),
    )
}

#[test]
fn derivatives_of_square_roots_follow_the_chain_rule() {
    for (l, r) in [
        ("diff(sqrt(x), x)", "1/(2*sqrt(x))"),
        ("diff(sqrt(x^2 + 1), x)", "x/sqrt(x^2 + 1)"),
        ("diff(x*sqrt(x), x)", "3*sqrt(x)/2"),
        ("diff(1/sqrt(x), x)", "-1/(2*x*sqrt(x))"),
        ("diff(sqrt(x), x, 2)", "-1/(4*x*sqrt(x))"),
        // A root inside a radicand, and an angle inside one.
        (
            "diff(sqrt(1 + sqrt(x)), x)",
            "1/(4*sqrt(x)*sqrt(1 + sqrt(x)))",
        ),
        (
            "diff(sqrt(1 + sin(x)^2), x)",
            "sin(x)*cos(x)/sqrt(1 + sin(x)^2)",
        ),
        // A root that does not change with the variable is a constant of the derivative.
        ("diff(sqrt(y)*x^2, x)", "2*x*sqrt(y)"),
        ("diff(sqrt(2)*x, x)", "sqrt(2)"),
    ] {
        assert_eq!(verdict(l, r), (0, "proved".into()), "{l} = {r}");
    }
}

#[test]
fn a_root_is_not_a_constant_of_its_own_variable() {
    for (l, r) in [
        ("diff(sqrt(x), x)", "0"),
        ("diff(1/sqrt(x), x)", "0"),
        ("diff(sqrt(x^2 + 1), x)", "x"),
    ] {
        let (code, j) = prove_json(&[l, r]);
        assert_eq!(
            (code, j["verdict"].as_str()),
            (1, Some("fails")),
            "{l} = {r}: {j}"
        );
    }
    // The counter-example is checked: at x = 1 the derivative of sqrt(x) is 1/2.
    let (code, out, _) = run(&["prove", "diff(sqrt(x), x)", "0"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("LHS - RHS = 1/2"), "{out}");
}

#[test]
fn integrands_with_functions_of_the_variable_are_refused() {
    for (l, held) in [
        ("integrate(sqrt(t)*sin(t), t, 0, pi)", "sqrt(t)"),
        ("integrate(sqrt(t), t, 0, 1)", "sqrt(t)"),
        ("integrate(t*sqrt(1 + t^2), t, 0, 1)", "sqrt(1 + t^2)"),
        ("diff(integrate(sqrt(t), t, 0, x), x)", "sqrt(t)"),
    ] {
        let (code, _, err) = run(&["prove", l, "0"]);
        assert_eq!(code, 2, "{l}: {err}");
        assert_eq!(err.lines().count(), 1, "{l}: {err}");
        assert!(
            err.contains(&format!("holds {held}, which changes with")),
            "{l}: {err}"
        );
    }
}

#[test]
fn roots_and_angles_free_of_the_integration_variable_stay_themselves() {
    for (l, r) in [
        ("integrate(sqrt(y)*t, t, 0, 1)", "sqrt(y)/2"),
        ("integrate(t*sqrt(1 + y^2), t, 0, 2)", "2*sqrt(y^2 + 1)"),
        ("integrate(t*sin(y), t, 0, 1)", "sin(y)/2"),
        (
            "integrate(sqrt(y)/(1 + y^2)*t^2, t, 0, 3)",
            "9*sqrt(y)/(1 + y^2)",
        ),
    ] {
        assert_eq!(verdict(l, r), (0, "proved".into()), "{l} = {r}");
    }
    // The same root on both sides is one root: a false identity fails at a real point.
    let (code, j) = prove_json(&["integrate(sqrt(y)*t, t, 0, 1)", "sqrt(y)"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
}

#[test]
fn half_integer_exponents_as_printed_are_square_roots() {
    for (l, r) in [
        ("x^(1/2)", "sqrt(x)"),
        ("(1 + t^2)^(3/2)", "(1 + t^2)*sqrt(1 + t^2)"),
        ("diff((1 + t^2)^(3/2), t)", "3*t*sqrt(1 + t^2)"),
        ("8^(-3/2)", "sqrt(2)/32"),
        ("x^0.5*x^0.5", "x"),
    ] {
        assert_eq!(verdict(l, r), (0, "proved".into()), "{l} = {r}");
    }
    // Another exponent is a root of a constant only.
    let (code, _, err) = run(&["prove", "x^(1/3)", "1"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("or half of one"), "{err}");
}

#[test]
fn trigonometric_polynomials_integrate_exactly() {
    for (l, r) in [
        ("integrate(sin(x), x, 0, pi)", "2"),
        ("integrate(cos(t)^2, t, 0, 2*pi)", "pi"),
        ("integrate(t*sin(t), t, 0, pi)", "pi"),
        ("integrate(cos(t), t, 0, x)", "sin(x)"),
        ("integrate(sin(t)^3, t, 0, x)", "2/3 - cos(x) + cos(x)^3/3"),
        (
            "diff(integrate(sin(t)^2*cos(t), t, 0, x), x)",
            "sin(x)^2*cos(x)",
        ),
        (
            "integrate(cos(2*t + pi/3), t, 0, x)",
            "sin(2*x + pi/3)/2 - sqrt(3)/4",
        ),
        ("integrate(cos(t)/y, t, 0, pi/2)", "1/y"),
    ] {
        assert_eq!(verdict(l, r), (0, "proved".into()), "{l} = {r}");
    }
    // A false value fails with an exact counter-example.
    let (code, out, _) = run(&["prove", "integrate(sin(x), x, 0, pi)", "1"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("LHS - RHS = 1"), "{out}");
}

#[test]
fn a_constant_bound_of_a_trigonometric_integral_is_an_angle() {
    let (code, out, err) = run(&["prove", "integrate(sin(t), t, 0, 1)", "1 - cos(1)"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("proved: "), "{out}");
}

#[test]
fn trigonometric_integrals_refuse_bounds_that_are_not_angles() {
    for (l, says) in [
        (
            "integrate(sin(t), t, 0, x^2)",
            "the bound x^2, which is not an angle",
        ),
        (
            "integrate(sin(t), t, 0, sqrt(2))",
            "the bound sqrt(2), which is not an angle",
        ),
        (
            "integrate(tan(t), t, 0, x)",
            "divides by an expression in t",
        ),
    ] {
        let (code, _, err) = run(&["prove", l, "0"]);
        assert_eq!(code, 2, "{l}: {err}");
        assert_eq!(err.lines().count(), 1, "{l}: {err}");
        assert!(err.contains(says), "{l}: {err}");
    }
}

#[test]
fn a_derivative_of_a_root_at_a_point() {
    for (l, r) in [
        ("subs(diff(sqrt(x), x), x, 4)", "1/4"),
        ("subs(diff(sqrt(x^2 + 1), x), x, 0)", "0"),
        (
            "subs(diff(x*sqrt(1 + x^2), x), x, y)",
            "sqrt(1 + y^2) + y^2/sqrt(1 + y^2)",
        ),
    ] {
        assert_eq!(verdict(l, r), (0, "proved".into()), "{l} = {r}");
    }
    assert_eq!(
        verdict("subs(diff(sqrt(x), x), x, 4)", "1/2"),
        (1, "fails".into())
    );
    // Where the root's derivative divides by zero there is none: one line, exit 2.
    let (code, _, err) = run(&["prove", "subs(diff(sqrt(x), x), x, 0)", "0"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("division by zero"), "{err}");
}
