//! `regress --formula` with calculus as `prove` prints it: `diff` of square roots and angles and
//! `integrate` of trigonometric polynomials, lowered to the derivative or the antiderivative at
//! the bounds with `sqrt`, `sin` and `cos` calls, which both sides evaluate (the exact side
//! exactly). The exact outputs are checked against the closed forms computed independently in
//! f64 from the inputs the report names.

use super::regress_language::{refused, report};
use serde_json::Value;

/// The worst samples of a report as (input, exact output as f64, float output).
fn worst_samples(r: &Value) -> Vec<(f64, f64, f64)> {
    r["worst"]
        .as_array()
        .expect("a list of worst samples")
        .iter()
        .map(|w| {
            let s = &w["original"];
            (
                s["inputs"][0].as_f64().expect("an input"),
                s["exact_outputs_f64"][0].as_f64().expect("an exact output"),
                s["float_outputs"][0].as_f64().expect("a float output"),
            )
        })
        .collect()
}

/// Runs the regression of `formula` over `domain` and checks every sample compared, the exact
/// side decided, the float side within `max_ulps` (when given), and the exact outputs of the
/// worst samples against `closed_form` (within `1e-12` relative plus `1e-15` absolute: the
/// closed form is evaluated in f64).
fn regressed(formula: &str, domain: &str, max_ulps: Option<f64>, closed_form: fn(f64) -> f64) {
    let r = report(formula, domain);
    assert_eq!(r["name"], formula, "{r}");
    assert_eq!(r["compared"], 500, "{formula}: {r}");
    assert_eq!(r["undecided"], 0, "{formula}: {r}");
    assert_eq!(r["domain_errors"], 0, "{formula}: {r}");
    let ulps = r["max_ulps"].as_f64().unwrap();
    assert!(ulps.is_finite(), "{formula}: {r}");
    assert!(max_ulps.is_none_or(|m| ulps < m), "{formula}: {r}");
    let worst = worst_samples(&r);
    assert!(!worst.is_empty(), "{formula}: {r}");
    for (x, exact, float) in worst {
        let want = closed_form(x);
        assert!(
            (exact - want).abs() <= 1e-12 * want.abs() + 1e-15,
            "{formula} at {x}: exact {exact}, closed form {want}"
        );
        assert!(float.is_finite(), "{formula} at {x}: {float}");
    }
}

#[test]
fn derivative_of_a_square_root_as_printed() {
    regressed("diff(sqrt(1 + t^2), t)", "t in [0, 10]", Some(8.0), |t| {
        t / (1.0 + t * t).sqrt()
    });
    regressed("diff(t*sqrt(t), t)", "t in [0.5, 4]", Some(8.0), |t| {
        1.5 * t.sqrt()
    });
}

#[test]
fn derivatives_of_angles_as_printed() {
    regressed("diff(sin(x)^2, x)", "x in [0.1, 1.4]", Some(64.0), |x| {
        (2.0 * x).sin()
    });
    regressed("diff(tan(x), x)", "x in [0, 1]", Some(64.0), |x| {
        1.0 / x.cos().powi(2)
    });
}

#[test]
fn integral_of_a_trigonometric_polynomial_as_printed() {
    regressed("integrate(t*sin(t), t, 0, x)", "x in [0, 3]", None, |x| {
        x.sin() - x * x.cos()
    });
    regressed(
        "integrate(cos(t), t, 0, x^2)",
        "x in [0, 1.5]",
        Some(64.0),
        |x| (x * x).sin(),
    );
}

#[test]
fn integrands_the_exact_conversion_refuses_are_one_line_errors() {
    refused(
        "integrate(sqrt(1 + t^2), t, 0, x)",
        &["integrate", "which changes with t"],
    );
    refused(
        "integrate(tan(t), t, 0, x)",
        &["integrate", "divides by an expression in t"],
    );
}
