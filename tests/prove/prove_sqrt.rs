//! `exactcheck prove` and claims files with square roots of expressions (`sqrt(E)`, the
//! non-negative root, a variable `y` with `y^2 = E`, `y >= 0`) and with hypotheses the proof
//! uses (`w != 0` by a Rabinowitsch variable, `w > 0`, the signs of the roots): each decision
//! path proves what holds and rejects a false identity with an exact counter-example.

use crate::timed;

use timed::{prove_json, run_text as run};

/// `prove ARGS --json` as a JSON object, with its exit status.
fn point(j: &serde_json::Value, name: &str) -> String {
    j["point"][name]
        .as_str()
        .unwrap_or_else(|| panic!("{name} in {j}"))
        .to_string()
}

#[test]
fn sqrt_of_a_square_needs_the_sign_of_its_argument() {
    let (code, j) = prove_json(&["sqrt(x^2)", "x", "--where", "x >= 0"]);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    assert_eq!(
        j["hypotheses_used"],
        serde_json::json!(["x >= 0", "sqrt(x^2) >= 0"])
    );
    // Without the domain it fails at a negative x, where the root is the non-negative one.
    let (code, j) = prove_json(&["sqrt(x^2)", "x"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
    let x: exactcheck_exact::Rational = point(&j, "x").parse().unwrap();
    let root: exactcheck_exact::Rational = point(&j, "sqrt(x^2)").parse().unwrap();
    assert!(x < exactcheck_exact::Rational::ZERO, "{j}");
    assert_eq!(root, -x, "{j}");
    // On the wrong side it fails too: x <= -1 is where sqrt(x^2) = -x.
    let (code, j) = prove_json(&["sqrt(x^2)", "-x", "--where", "x <= -1"]);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    let (code, j) = prove_json(&["sqrt(x^2)", "x", "--where", "x <= -1"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
}

#[test]
fn what_holds_for_both_roots_is_proved_by_ideal_membership() {
    for (l, r) in [
        ("sqrt(x^2 + y^2)^2", "x^2 + y^2"),
        ("sqrt(x)^3", "x*sqrt(x)"),
        ("sqrt(1 + sqrt(x))^2", "1 + sqrt(x)"),
        ("(sqrt(x) - 1)*(sqrt(x) + 1)", "x - 1"),
        ("sqrt(x + 1)", "sqrt(1 + x)"),
    ] {
        let (code, j) = prove_json(&[l, r]);
        assert_eq!(
            (code, j["verdict"].as_str()),
            (0, Some("proved")),
            "{l} = {r}: {j}"
        );
        assert!(j.get("hypotheses_used").is_none(), "{l} = {r}: {j}");
    }
    let (code, out, _) = run(&["prove", "sqrt(x)^2", "x"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.trim_end()
            .ends_with("(the square roots are defined where x >= 0)"),
        "{out}"
    );
    let (_, out, _) = run(&["prove", "sqrt(x^2 + y^2)^2", "x^2 + y^2"]);
    assert!(
        out.trim_end()
            .ends_with("(the square roots are defined everywhere)"),
        "{out}"
    );
    // False ones are rejected with the non-negative root at an exact point.
    for (l, r) in [
        ("sqrt(x^2 + y^2)", "x + y"),
        ("sqrt(x)^2", "x + 1"),
        ("sqrt(1 + sqrt(x))", "1 + sqrt(x)"),
        ("sqrt(x)", "-sqrt(x)"),
    ] {
        let (code, j) = prove_json(&[l, r]);
        assert_eq!(
            (code, j["verdict"].as_str()),
            (1, Some("fails")),
            "{l} = {r}: {j}"
        );
    }
}

#[test]
fn products_of_roots_use_the_signs_of_the_roots() {
    let (code, j) = prove_json(&["sqrt(x)*sqrt(y)", "sqrt(x*y)"]);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    let (code, j) = prove_json(&["sqrt(sqrt(x)^2)", "sqrt(x)"]);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    let (code, j) = prove_json(&["sqrt(x)*sqrt(y)", "-sqrt(x*y)"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
}

#[test]
fn a_root_defined_at_one_point_only_is_undecided() {
    // sqrt(-x^2) is defined only at x = 0, where it is 0: true, but neither ideal membership
    // nor the sign argument shows it, and no real counter-example exists.
    let (code, out, err) = run(&["prove", "sqrt(-x^2)", "0"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("undecided: "), "{out}");
    assert!(
        out.contains("(the square roots are defined where -x^2 >= 0)"),
        "{out}"
    );
    assert!(
        out.contains("the hypotheses (each non-zero one by a Rabinowitsch variable"),
        "{out}"
    );
    // A false identity with the same root is rejected at x = 0.
    let (code, j) = prove_json(&["sqrt(-x^2)", "1"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
    assert_eq!(point(&j, "x"), "0", "{j}");
    let (code, out, _) = run(&["prove", "sqrt(x^2*y^2)", "x*y"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails: "), "{out}");
}

#[test]
fn a_claim_that_needs_a_non_zero_hypothesis_says_so() {
    // The tangent of a rational quadratic Bezier curve at t = 0, cleared by hand: w0^2 X0 =
    // 2 w0 w1 (x1 - x0). Dividing by w0 needs w0 != 0; the residual is not in the ideal.
    let claim = [
        "w0*X0",
        "2*w1*(x1 - x0)",
        "--where",
        "w0^2*X0 = 2*w0*w1*(x1 - x0)",
    ];
    let mut with = claim.to_vec();
    with.extend(["--where", "w0 != 0"]);
    let (code, j) = prove_json(&with);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    assert_eq!(j["hypotheses_used"], serde_json::json!(["w0 != 0"]));
    let mut positive = claim.to_vec();
    positive.extend(["--where", "w0 > 0"]);
    let (code, j) = prove_json(&positive);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    assert_eq!(j["hypotheses_used"], serde_json::json!(["w0 > 0"]));
    // Without it: w0 = 0 makes the relation hold for every X0.
    let (code, j) = prove_json(&claim);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
    assert_eq!(point(&j, "w0"), "0", "{j}");
    // A hypothesis the proof does not need is not reported.
    let mut extra = with.clone();
    extra.extend(["--where", "x1 != x0"]);
    let (code, j) = prove_json(&extra);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    assert_eq!(j["hypotheses_used"], serde_json::json!(["w0 != 0"]));
    // A false claim is still rejected under the hypothesis, off its zero.
    let (code, j) = prove_json(&[
        "w0*X0",
        "w1*(x1 - x0)",
        "--where",
        "w0^2*X0 = 2*w0*w1*(x1 - x0)",
        "--where",
        "w0 != 0",
    ]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
    assert_ne!(point(&j, "w0"), "0", "{j}");
}

#[test]
fn the_denominators_of_a_fraction_identity_are_hypotheses_too() {
    // With x q = x y, (q - y)/x = 0: the cleared residual q - y is not in the ideal of the
    // relation, but it is once the denominator x is non-zero.
    let (code, j) = prove_json(&["(q - y)/x", "0", "--where", "x*q = x*y"]);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    let text = j["evidence"].as_str().unwrap();
    assert!(text.contains("using the hypotheses x != 0"), "{text}");
    let (code, j) = prove_json(&["(q - y)/x", "1", "--where", "x*q = x*y"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
    assert_ne!(point(&j, "x"), "0", "{j}");
}

#[test]
fn the_claims_file_uses_its_hypotheses() {
    let (code, out, err) = run(&["verify", "tests/claims_file/hypotheses.toml", "--json"]);
    assert_eq!(code, 0, "{out}{err}");
    let rows: serde_json::Value = serde_json::from_str(&out).unwrap();
    let rows = rows.as_array().unwrap();
    let row = |id: &str| {
        rows.iter()
            .find(|r| r["id"] == id)
            .unwrap_or_else(|| panic!("{id} in {rows:?}"))
    };
    for r in rows {
        assert_eq!(r["as_expected"], true, "{r}");
    }
    let evidence = |id: &str| row(id)["evidence"].as_str().unwrap().to_string();
    assert!(
        evidence("hypotheses.bezier_tangent").contains("using the hypotheses w0 > 0"),
        "{}",
        evidence("hypotheses.bezier_tangent")
    );
    assert!(
        evidence("hypotheses.quotient").contains("using the hypotheses x != 0"),
        "{}",
        evidence("hypotheses.quotient")
    );
    assert!(
        evidence("sqrt.abs").contains("using the hypotheses x >= 0, sqrt(x^2) >= 0"),
        "{}",
        evidence("sqrt.abs")
    );
    assert_eq!(row("sqrt.abs_everywhere")["verdict"], "fails");
    assert_eq!(row("hypotheses.quotient_without")["verdict"], "fails");
}

#[test]
fn bad_roots_and_hypotheses_are_one_line_errors() {
    for (args, needle) in [
        (
            vec!["prove", "sqrt(-1 - x^2)", "1"],
            "the radicand is negative for all real values",
        ),
        (vec!["prove", "sqrt(-2)", "1"], "it is negative"),
        (
            vec!["prove", "x", "x", "--where", "x != x"],
            "is false everywhere",
        ),
        (vec!["prove", "x", "x", "--where", "x != 1 = 2"], "'A != B'"),
        (
            vec!["prove", "sqrt(x + sqrt(2))", "1", "--random", "10"],
            "--random",
        ),
        (
            vec!["prove", "x", "1", "--where", "x != 0", "--random", "10"],
            "--random",
        ),
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert_eq!(
            err.lines().filter(|l| !l.contains("hint:")).count(),
            1,
            "{args:?}: {err}"
        );
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn hypotheses_as_a_paper_lists_them() {
    // One `--where` with a comma-separated list is several hypotheses, and `a, b >= 0` gives
    // both variables the bound; each proves what the two separate arguments prove.
    for list in ["a >= 0, b >= 0", "a, b >= 0"] {
        let (code, j) = prove_json(&["sqrt(a^2*b^2)", "a*b", "--where", list]);
        assert_eq!(
            (code, j["verdict"].as_str()),
            (0, Some("proved")),
            "{list}: {j}"
        );
        assert_eq!(
            j["hypotheses_used"],
            serde_json::json!(["a >= 0", "b >= 0", "sqrt(a^2*b^2) >= 0"]),
            "{list}"
        );
    }
    // Only one of the two: fails at an exact point with b < 0.
    let (code, j) = prove_json(&["sqrt(a^2*b^2)", "a*b", "--where", "a >= 0"]);
    assert_eq!((code, j["verdict"].as_str()), (1, Some("fails")), "{j}");
    // Commas inside a call do not split the relation.
    let (code, j) = prove_json(&["x", "3", "--where", "x = binomial(3, 1)"]);
    assert_eq!((code, j["verdict"].as_str()), (0, Some("proved")), "{j}");
    let (code, out, err) = run(&["prove", "x", "0", "--where", "a, b"]);
    assert_eq!(code, 2, "{out}{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn the_sign_of_a_polynomial_in_one_variable_is_decided_on_its_interval() {
    // `sqrt(S^2) = S` needs `S >= 0` where the variable lies: decided exactly from the real roots
    // of `S` (the coefficient test cannot show `t (1 - t) >= 0` on [0, 1]).
    for (l, r, w) in [
        ("sqrt(t^2*(1-t)^2)", "t*(1-t)", "0 <= t <= 1"),
        ("sqrt((1-t^2)^2)", "1 - t^2", "-1 <= t <= 1"),
        ("sqrt((t^2 - 2)^2)", "2 - t^2", "-1 < t < 1"),
    ] {
        let (code, j) = prove_json(&[l, r, "--where", w]);
        assert_eq!(
            (code, j["verdict"].as_str()),
            (0, Some("proved")),
            "{l} = {r}, {w}: {j}"
        );
    }
    // Past the interval where the sign holds, an exact counter-example.
    for (l, r, w) in [
        ("sqrt(t^2*(1-t)^2)", "t*(1-t)", "0 <= t <= 2"),
        ("sqrt((t^2 - 2)^2)", "2 - t^2", "-1 < t < 2"),
    ] {
        let (code, j) = prove_json(&[l, r, "--where", w]);
        assert_eq!(
            (code, j["verdict"].as_str()),
            (1, Some("fails")),
            "{l} = {r}, {w}: {j}"
        );
    }
    // A radicand positive on the whole line is defined everywhere, though some coefficients
    // are negative.
    let (code, out, _) = run(&["prove", "sqrt(x^2 - 2*x + 2)^2", "x^2 - 2*x + 2"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("the square roots are defined everywhere"),
        "{out}"
    );
}
