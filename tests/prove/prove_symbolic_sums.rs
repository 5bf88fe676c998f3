//! `exactcheck prove` with sums to a symbolic bound, as printed (`sum(k, 1, n, k^2)`): the sum
//! of a polynomial in the index is its closed form, the identity is decided as an identity of
//! polynomials in the bound's variables, and a counter-example gives them integer values inside
//! the sum's range. The same in `--random` and in claims files; a summand that is not a
//! polynomial in the index is refused in one line, and so is a symbolic bound in
//! `regress --formula`. Also the gaps of `--random` this closes: negative integer exponents
//! and pi outside an angle.

use crate::timed;

use timed::{prove_json, run_text as run};

fn proved(l: &str, r: &str) {
    let (code, j) = prove_json(&[l, r]);
    assert_eq!(
        (code, j["verdict"].as_str()),
        (0, Some("proved")),
        "{l} = {r}: {j}"
    );
}

/// Fails, with the counter-example point (names to values) and the value of LHS - RHS there.
fn fails(l: &str, r: &str) -> serde_json::Value {
    let (code, j) = prove_json(&[l, r]);
    assert_eq!(
        (code, j["verdict"].as_str()),
        (1, Some("fails")),
        "{l} = {r}: {j}"
    );
    j
}

fn refused(l: &str, r: &str, says: &str) {
    let (code, out, err) = run(&["prove", l, r]);
    assert_eq!(code, 2, "{l} = {r}: {out}{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains(says), "{l} = {r}: {err}");
}

#[test]
fn printed_power_sums_are_proved() {
    for (l, r) in [
        ("sum(k, 1, n, k)", "n*(n+1)/2"),
        ("sum(k, 1, n, k^2)", "n*(n+1)*(2*n+1)/6"),
        ("sum(k, 1, n, k^3)", "n^2*(n+1)^2/4"),
        ("sum(k, 1, n, k^3)", "sum(k, 1, n, k)^2"),
        ("sum(k, 1, n, k^4)", "n*(n+1)*(2*n+1)*(3*n^2+3*n-1)/30"),
        ("sum(k, 1, n, 2*k - 1)", "n^2"),
        ("sum(k, 1, n, k*(k+1))", "n*(n+1)*(n+2)/3"),
        ("sum(k, m, n, k)", "(n - m + 1)*(n + m)/2"),
        ("sum(k, 0, n - 1, 2*k + 1)", "n^2"),
        ("sum(i, 1, n, sum(j, 1, i, j))", "n*(n+1)*(n+2)/6"),
        ("sum(k, 1, n, a*k + b)", "a*n*(n+1)/2 + b*n"),
        ("sum(k, 1, n, k/m)", "n*(n+1)/(2*m)"),
        ("sum(k, 1, n, sqrt(2)*k)", "sqrt(2)*n*(n+1)/2"),
    ] {
        proved(l, r);
    }
}

#[test]
fn misprints_fail_at_an_integer_inside_the_range() {
    // n^2 (n+1)^2 / 2 is twice the sum: at n = 1, 1 != 2.
    let j = fails("sum(k, 1, n, k^3)", "n^2*(n+1)^2/2");
    assert_eq!(j["point"]["n"], "1", "{j}");
    assert_eq!(j["value"], "-1", "{j}");
    // The sum from 1 to n of 1 is n, not n + 1: at n = 0 the sum is empty.
    let j = fails("sum(k, 1, n, 1)", "n + 1");
    assert_eq!(j["point"]["n"], "0", "{j}");
    // n^2/2 agrees with no sum at a non-integer point only: the point is an integer.
    for (l, r) in [
        ("sum(k, 1, n, k)", "n^2/2"),
        ("sum(k, 1, n, k^2)", "n^3/3"),
        ("sum(k, m, n, k)", "(n - m)*(n + m)/2"),
        ("sum(k, 2, n, k)", "n*(n+1)/2"),
    ] {
        let j = fails(l, r);
        for (name, value) in j["point"].as_object().unwrap() {
            let q: i64 = value
                .as_str()
                .unwrap()
                .parse()
                .unwrap_or_else(|_| panic!("{l}: {j}"));
            if name == "n" && l.contains("(k, 2, n") {
                assert!(q >= 1, "{l}: {j}");
            }
            if name == "n" && l.contains("(k, 1, n") {
                assert!(q >= 0, "{l}: {j}");
            }
        }
    }
    // A domain of the user's narrows the search: n >= 1.
    let (code, out, _) = run(&["prove", "sum(k, 1, n, k^2)", "n^2", "--where", "n >= 1"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails: at n = 2:"), "{out}");
}

#[test]
fn summands_that_are_not_polynomials_in_the_index_are_refused() {
    refused(
        "sum(k, 0, n, x^k)",
        "(x^(n+1) - 1)/(x - 1)",
        "the exponent of x^k depends on the summation index k",
    );
    refused(
        "sum(k, 0, n, binomial(k, 2))",
        "(n+1)*n*(n-1)/6",
        "binomial(k, 2) depends on the summation index k",
    );
    refused("sum(k, 1, n, 1/k)", "0", "divides by an expression in k");
    refused("sum(k, 1, n, sqrt(k))", "0", "which changes with k");
    refused("sum(k, 1, n/2, k)", "0", "must take integer values");
    // An inner range that is reversed for k = 0 (sum(j, 2, 0, ...) is empty, its closed form
    // is not).
    refused(
        "sum(k, 0, n, sum(j, 2, k, 1))",
        "0",
        "is not shown to be non-empty",
    );
}

#[test]
fn random_mode_and_claims_files_take_symbolic_sums() {
    let (code, out, err) = run(&[
        "prove",
        "sum(k, 1, n, k^2)",
        "n*(n+1)*(2*n+1)/6",
        "--random",
        "10",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("holds: "), "{out}");
    let (code, out, _) = run(&[
        "prove",
        "sum(k, 1, n, k^3)",
        "n^2*(n+1)^2/2",
        "--random",
        "10",
    ]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails: "), "{out}");
    let path = std::env::temp_dir().join(format!("exactcheck-sums-{}.toml", std::process::id()));
    std::fs::write(
        &path,
        r#"
[[claim]]
id = "squares"
kind = "identity"
lhs = "sum(k, 1, n, k^2)"
rhs = "n*(n+1)*(2*n+1)/6"

[[claim]]
id = "cubes"
kind = "identity"
lhs = "sum(k, 1, n, k^3)"
rhs = "n^2*(n+1)^2/2"
expect = "fails"
"#,
    )
    .unwrap();
    let rows = crate::common::verify_json(path.to_str().unwrap(), 0);
    std::fs::remove_file(&path).ok();
    assert_eq!(rows.row("squares")["verdict"], "proved");
    let cubes = rows.row("cubes");
    assert_eq!(cubes["verdict"], "fails", "{cubes}");
    assert_eq!(cubes["point"]["n"], "1", "{cubes}");
}

#[test]
fn regress_refuses_a_symbolic_bound() {
    let (code, out, err) = run(&["regress", "--formula", "sum(k, 1, n, k^2)"]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(err.contains("needs integer constant bounds"), "{err}");
}

#[test]
fn random_mode_takes_negative_exponents_and_pi() {
    for (l, r) in [
        ("x^(-1)*x", "1"),
        ("(1+t^2)^(-2)*(1+t^2)^2", "1"),
        ("x^-2", "1/x^2"),
    ] {
        let (code, out, err) = run(&["prove", l, r, "--random", "10"]);
        assert_eq!(code, 0, "{l} = {r}: {out}{err}");
        assert!(out.starts_with("holds: "), "{out}");
    }
    let (code, out, _) = run(&["prove", "(1+t^2)^(-2)", "1/(1+t^2)", "--random", "10"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails: "), "{out}");
    // pi outside an angle: a non-zero rational function of pi is not zero at pi.
    let (code, out, _) = run(&["prove", "pi*sqrt(2)", "0", "--random", "5"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails: LHS - RHS = "), "{out}");
    assert!(
        out.contains("pi, which is transcendental, is no root of it"),
        "{out}"
    );
    let (code, out, _) = run(&[
        "prove",
        "(pi + sqrt(2))^2",
        "pi^2 + 2*sqrt(2)*pi + 2",
        "--random",
        "5",
    ]);
    assert_eq!(code, 0, "{out}");
    // Next to a constant angle nothing is known: undecided.
    let (code, out, _) = run(&["prove", "pi*sin(1)", "0", "--random", "5"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("undecided: "), "{out}");
}

#[test]
fn a_bound_fixed_by_a_relation_is_substituted_where_a_number_is_needed() {
    // `binomial(n, k)` in a sum to n needs n as a number: `--where 'n = 4'` gives it, and a
    // note says so.
    for (lhs, rhs, fixed) in [
        (
            "\\sum_{k=0}^{n} \\binom{n}{k} t^k (1-t)^{n-k}",
            "1",
            "n = 4",
        ),
        ("\\sum_{k=0}^{n} \\binom{n}{k}", "2^n", "n = 5"),
        ("n!", "120", "n = 5"),
        ("binomial(n, 2)", "n*(n-1)/2", "n = 7, m = 3"),
    ] {
        let (code, out, err) = run(&["prove", lhs, rhs, "--where", fixed]);
        assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
        assert!(out.starts_with("proved"), "{out}");
        assert!(err.contains("substituted into the sides"), "{err}");
        // Only the variables of the sides are named.
        assert!(!err.contains("m = 3"), "{err}");
    }
    // The false twin fails at the fixed value.
    let (code, out, err) = run(&[
        "prove",
        "\\sum_{k=0}^{n} \\binom{n}{k}",
        "31",
        "--where",
        "n = 5",
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("fails"), "{out}");
    // A value that does not make the statement readable leaves the first error, alone.
    let (code, out, err) = run(&[
        "prove",
        "\\sum_{k=0}^{n} \\binom{n}{k}",
        "2^n",
        "--where",
        "n = 1/2",
    ]);
    assert_eq!(code, 2, "{out}{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        err.contains("binomial(n, k) depends on the summation index"),
        "{err}"
    );
    // A relation that the statement does not need stays a relation.
    let (code, out, err) = run(&["prove", "x^2", "4", "--where", "x = 2"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("modulo x = 2") && !err.contains("substituted"),
        "{out}{err}"
    );
}
