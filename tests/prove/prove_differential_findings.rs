//! Verdicts that the differential tester (`fuzz/differential/verdicts.py`: random identities,
//! true by construction or perturbed, against their values at 50 digits) found wrong or
//! incomplete, each pinned with what the identity really is.

use crate::prove_trig::{fails, proved};
use crate::timed;

use timed::{prove_json, run_text as run};

/// Pi next to a constant outside the square-root field (`sin(pi/7)`, a root of a sextic): the
/// difference is a non-zero polynomial in pi with coefficients in the constants' field, so it is
/// not zero (pi is transcendental over the algebraic numbers), as with `sqrt(2)` in the
/// square-root field: `fails`, with pi kept as pi in the value and no rational value given to it.
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
/// field is decided whichever comes first (`sqrt(2 + sqrt(2))*pi`, `pi*sqrt(2 + sqrt(2))`): pi is
/// an indeterminate next to the constants' field, as the real algebraic numbers have no pi.
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

/// Claims files decide the same statements by the same path: the value in pi is the evidence
/// and the correction; the erratum has no residual line that would only repeat the difference.
#[test]
fn claims_files_take_pi_next_to_an_algebraic_constant() {
    let path =
        std::env::temp_dir().join(format!("exactcheck-pi-field-{}.toml", std::process::id()));
    std::fs::write(
        &path,
        r#"
[[claim]]
id = "sum"
kind = "identity"
lhs = "pi + sin(pi/7)"
rhs = "0"
expect = "fails"

[[claim]]
id = "scaled"
kind = "identity"
lhs = "x*pi + cos(pi/7)*pi"
rhs = "x*pi"
expect = "fails"

[[claim]]
id = "commuted"
kind = "identity"
lhs = "sqrt(2 + sqrt(2))*pi"
rhs = "pi*sqrt(2 + sqrt(2))"
"#,
    )
    .unwrap();
    let rows = crate::common::verify_json(path.to_str().unwrap(), 0);
    std::fs::remove_file(&path).ok();
    let sum = rows.row("sum");
    assert_eq!(sum["verdict"], "fails", "{sum}");
    assert_eq!(sum["value"], "c + pi", "{sum}");
    assert_eq!(
        sum["erratum"]["correction"], "LHS - RHS = c + pi at the counter-example",
        "{sum}"
    );
    assert!(
        sum["erratum"]["residual"]
            .as_array()
            .is_none_or(Vec::is_empty),
        "{sum}"
    );
    let scaled = rows.row("scaled");
    assert_eq!(scaled["verdict"], "fails", "{scaled}");
    assert_eq!(scaled["value"], "pi*c", "{scaled}");
    assert_eq!(scaled["point"]["x"], "0", "{scaled}");
    assert_eq!(rows.row("commuted")["verdict"], "proved");
}

/// An angle with a sum's index and a multiple of pi outside the square-root field
/// (`sin(k*x + pi/5)`, as a Fourier sum is written) is split by the addition formula before the
/// sum is unrolled, so its constants join the field like those of `sin(x + pi/5)`.
#[test]
fn angles_with_a_sum_index_take_any_multiple_of_pi() {
    proved(
        "sum(k, 1, 2, sin(k*x + pi/10))",
        "sin(x + pi/10) + sin(2*x + pi/10)",
    );
    proved(
        "sum(k, 1, 3, cos(k*x - 2*pi/7))",
        "cos(x - 2*pi/7) + cos(2*x - 2*pi/7) + cos(3*x - 2*pi/7)",
    );
    let out = fails("sum(k, 1, 2, sin(k*x + pi/5))", "sin(x + pi/5) + sin(2*x)");
    assert!(out.contains("x = angle with cos x = "), "{out}");
}
