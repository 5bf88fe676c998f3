//! `regress --formula` with the whole expression language, end to end through the binary: the
//! library's functions and `diff`, `sum`, `binomial`, `integrate` lowered to the arithmetic
//! both sides evaluate, vector values and constants refused with one line.

use serde_json::Value;
use std::process::{Command, Output};

fn exactcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// The first entry's report of `regress --formula FORMULA --json` over `domain`.
pub(crate) fn report(formula: &str, domain: &str) -> Value {
    let o = exactcheck(&[
        "regress",
        "--formula",
        formula,
        "--domain",
        domain,
        "--samples",
        "500",
        "--seed",
        "3",
        "--json",
    ]);
    assert!(
        o.status.success(),
        "{formula}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc: Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
    doc["entries"][0].clone()
}

pub(crate) fn refused(formula: &str, needles: &[&str]) {
    let o = exactcheck(&["regress", "--formula", formula, "--samples", "10"]);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{formula}: {err}");
    assert_eq!(err.lines().count(), 1, "{formula}: {err}");
    assert!(!err.contains("panicked"), "{formula}: {err}");
    for n in needles {
        assert!(err.contains(n), "{formula}: {err:?} lacks {n:?}");
    }
}

#[test]
fn library_formulas_are_regressed() {
    for (formula, domain) in [
        ("diff(t^3/(1+t), t)", "t in [0, 1]"),
        (
            "sum(k, 0, 3, binomial(3, k) t^k*(1-t)^(3-k))",
            "t in [0, 1]",
        ),
        (
            "det([[a, b], [c, d]])",
            "a in [-1, 1], b in [-1, 1], c in [-1, 1], d in [-1, 1]",
        ),
        ("norm2(bezier(t, [0, 0], [1, 2], [3, 1]))", "t in [0, 1]"),
        ("integrate(x t^2, t, 0, 1) + factorial(3)", "x in [-1, 1]"),
    ] {
        let r = report(formula, domain);
        assert_eq!(r["name"], formula, "{r}");
        assert_eq!(r["compared"], 500, "{formula}: {r}");
        // Small polynomials and one quotient on [0, 1]: a few ulps at most.
        assert!(r["max_ulps"].as_f64().unwrap() < 64.0, "{formula}: {r}");
    }
}

#[test]
fn the_float_side_of_a_derivative_is_the_expanded_derivative() {
    // diff((x - 1)^8, x) expands to 8 x^7 - 56 x^6 + ...: near x = 1 the expanded form cancels
    // catastrophically, which the regression shows (the factored form would not).
    let r = report("diff((x - 1)^8, x)", "x in [0.99, 1.01]");
    assert!(r["max_ulps"].as_f64().unwrap() > 1e6, "{r}");
}

#[test]
fn matrices_and_constants_are_one_line_errors() {
    // A vector is one output per coordinate; a matrix is refused.
    refused(
        "[[x, y]]",
        &["--formula", "a 1x2 matrix", "vector of outputs"],
    );
    refused("transpose([[x, y, 1]])", &["a 3x1 matrix"]);
    refused("2 e x", &["'e' at 2", "constant e"]);
    refused("x + e", &["'e' at 4", "Euler"]);
    refused(
        "integrate(sqrt(t), t, 0, x)",
        &["integrate", "sqrt(t)", "which changes with t"],
    );
    refused("sum(k, 0, 1/2, k x)", &["sum", "integer constant"]);
    refused(
        "integrate(x/t, t, 1, 2)",
        &["integrate", "divides by an expression in t"],
    );
}
