//! `exactcheck prove` with formulas as printed: rational functions and `diff`. Each identity
//! below was refused before ("division by a non-constant expression", "unknown function
//! 'diff'"); now it is decided exactly, with the divisors that must not vanish named, and a
//! counter-example never sits on a pole.

use crate::timed;

use timed::{prove_json, run_text as run};

/// `prove ARGS --json` as a JSON object, with its exit status.
#[test]
fn the_rational_unit_circle_is_proved_for_every_real_t() {
    let (code, out, _) = run(&["prove", "((1-t^2)/(1+t^2))^2 + (2*t/(1+t^2))^2", "1"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.starts_with("proved: "), "{out}");
    assert!(
        out.contains("where t^2 + 1 != 0 (no real zero): no real point is excluded"),
        "{out}"
    );
    let (_, j) = prove_json(&["((1-t^2)/(1+t^2))^2 + (2*t/(1+t^2))^2", "1"]);
    assert_eq!(j["verdict"], "proved");
    assert_eq!(
        j["conditions"],
        serde_json::json!([{"nonzero": "t^2 + 1", "real_zero_free": true}])
    );
}

#[test]
fn a_cancelled_factor_is_still_a_side_condition() {
    let (code, out, _) = run(&["prove", "(x^2-1)/(x-1)", "x+1"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.starts_with("proved: "), "{out}");
    assert!(out.trim_end().ends_with("where x != 1"), "{out}");
    // A divisor with a real zero is listed without the "no real zero" note.
    let (_, j) = prove_json(&["(x^2-1)/(x-1)", "x+1"]);
    assert_eq!(j["conditions"][0]["real_zero_free"], false);
}

#[test]
fn derivatives_of_fractions_are_exact() {
    let (code, out, _) = run(&["prove", "diff(t^3/(1+t), t)", "(2*t^3+3*t^2)/(1+t)^2"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.starts_with("proved: "), "{out}");
    // (1 + t)^2 excludes no point that 1 + t does not: one condition.
    assert!(out.trim_end().ends_with("where t != -1"), "{out}");
    let (code, out, _) = run(&["prove", "diff(1/(1+t^2), t, 2)", "(6*t^2-2)/(1+t^2)^3"]);
    assert_eq!(code, 0, "{out}");
    let (code, out, _) = run(&["prove", "diff(x^5*y, x, 3)", "60*x^2*y"]);
    assert_eq!(
        (code, out.trim_end()),
        (0, "proved: LHS - RHS expands to 0")
    );
    // A wrong derivative (the quotient rule with the wrong sign) fails.
    let (code, out, _) = run(&["prove", "diff(t/(1+t), t)", "(1+2*t)/(1+t)^2"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails: at t = "), "{out}");
}

#[test]
fn a_counter_example_avoids_the_poles() {
    for _ in 0..3 {
        let (code, j) = prove_json(&["1/x", "1/y"]);
        assert_eq!(code, 1);
        assert_eq!(j["verdict"], "fails");
        let x: exactcheck_exact::Rational = j["point"]["x"].as_str().unwrap().parse().unwrap();
        let y: exactcheck_exact::Rational = j["point"]["y"].as_str().unwrap().parse().unwrap();
        assert!(
            x != exactcheck_exact::Rational::ZERO && y != exactcheck_exact::Rational::ZERO,
            "{j}"
        );
        // The value is that of the fractions, 1/x - 1/y, not of the cleared numerator y - x.
        let v: exactcheck_exact::Rational = j["value"].as_str().unwrap().parse().unwrap();
        assert_eq!(v, &x.recip().unwrap() - &y.recip().unwrap(), "{j}");
    }
    // The only rational values the search draws near a pole: x = 1 is never chosen, so the
    // point is verified off x - 1 = 0 as well.
    let (code, j) = prove_json(&["1/(x-1)", "0"]);
    assert_eq!(code, 1, "{j}");
    let x: exactcheck_exact::Rational = j["point"]["x"].as_str().unwrap().parse().unwrap();
    assert_ne!(x, exactcheck_exact::Rational::ONE);
}

#[test]
fn relations_with_fractions_are_cleared_into_hypotheses() {
    let (code, out, _) = run(&["prove", "y", "m*x", "--where", "m = y/x"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("modulo m = y/x, where x != 0"), "{out}");
    // Without the hypothesis x != 0 the claim y = m x would not follow for x = 0, y != 0: the
    // counter-example search must respect it, so a false claim fails off x = 0.
    let (code, j) = prove_json(&["y", "2*m*x", "--where", "m = y/x"]);
    assert_eq!(code, 1, "{j}");
    assert_ne!(j["point"]["x"], "0", "{j}");
}

#[test]
fn polynomial_identities_keep_their_path_and_wording() {
    let (code, out, _) = run(&["prove", "(a+b)^2", "a^2 + 2 a b + b^2"]);
    assert_eq!(
        (code, out.trim_end()),
        (0, "proved: LHS - RHS expands to 0")
    );
    let (_, j) = prove_json(&["(a+b)^2", "a^2 + 2 a b + b^2"]);
    assert!(j.get("conditions").is_none(), "{j}");
    // Division by a constant stays polynomial.
    let (code, out, _) = run(&["prove", "x/2 + x/2", "x"]);
    assert_eq!(
        (code, out.trim_end()),
        (0, "proved: LHS - RHS expands to 0")
    );
}

#[test]
fn bad_fractions_and_calls_are_one_line() {
    for (args, needle) in [
        (
            &["prove", "1/(x-x)", "1"][..],
            "LHS: division by zero at 2: the divisor x - x is identically zero",
        ),
        (&["prove", "x^-1 * (y-y)^-2", "1"][..], "identically zero"),
        (
            &["prove", "diff(x^2, 2)", "1"][..],
            "the second argument must be a variable name, not 2",
        ),
        (
            &["prove", "diff(x^2, x^2)", "1"][..],
            "must be a variable name",
        ),
        (&["prove", "diff(x^2)", "1"][..], "takes 2 or 3 arguments"),
        (
            &["prove", "diff(x^2, x, -1)", "1"][..],
            "non-negative integer",
        ),
        (&["prove", "diff(x^2, x, 101)", "1"][..], "diff-order = 100"),
    ] {
        let (code, out, err) = run(args);
        assert_eq!(code, 2, "{args:?}: {out} {err}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    // The limit can be raised.
    let (code, out, _) = run(&[
        "prove",
        "diff(x^200, x, 101)",
        "0",
        "--limit",
        "diff-order=200",
    ]);
    assert_eq!(code, 1, "{out}");
}
