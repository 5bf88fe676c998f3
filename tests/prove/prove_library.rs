//! `exactcheck prove` with the function library of the expression language: vectors, matrices,
//! determinants and Bezier curves written as printed, resolved to scalars before the identity is
//! decided.

use crate::timed;

use timed::run_text as run;

fn proved(lhs: &str, rhs: &str) {
    let (code, out, err) = run(&["prove", lhs, rhs]);
    assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
    assert!(out.starts_with("proved"), "{lhs} = {rhs}: {out}");
}

#[test]
fn vector_functions_are_resolved() {
    proved("dot(vec(a,b),vec(a,b))", "a^2+b^2");
    proved(
        "norm2(bezier(t, vec(1,0), vec(1,1), vec(0,1)))",
        "(1 - t^2)^2 + (2*t - t^2)^2",
    );
    proved("cross([a, b], [c, d])", "a*d - b*c");
    proved("dot(cross([a1, a2, a3], [b1, b2, b3]), [a1, a2, a3])", "0");
    proved("subs(bernstein(1, 2, t), t, 1/2)", "1/2");
}

#[test]
fn determinants_and_matrix_products_are_resolved() {
    proved("det([[a, b], [c, d]])", "a*d - b*c");
    proved(
        "det([[a, b], [c, d]] * [[p, q], [r, s]])",
        "det([[a, b], [c, d]]) * det([[p, q], [r, s]])",
    );
    proved(
        "det([[1, a, a^2], [1, b, b^2], [1, c, c^2]])",
        "(b - a)*(c - a)*(c - b)",
    );
    proved("x([[0, -1], [1, 0]] * [u, v])", "-v");
    // A rational identity through the library: the determinant of a matrix of fractions.
    let (code, out, _) = run(&["prove", "det([[1/(1+t^2), t], [0, 1+t^2]])", "1"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("t^2 + 1 != 0"), "{out}");
}

#[test]
fn a_wrong_matrix_identity_fails_with_a_counter_example() {
    let (code, out, _) = run(&["prove", "det([[a, b], [c, d]])", "a*d + b*c"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails"), "{out}");
}

#[test]
fn shapes_that_do_not_fit_are_one_line_errors() {
    for (lhs, want) in [
        (
            "det([[1, 2, 3], [4, 5, 6]])",
            "det at 0 takes a square matrix, not a 2x3 matrix",
        ),
        (
            "det([[1, 2], [3, 4]] * [[1, 2, 3]])",
            "a product of a 2x2 matrix at 4 and a 1x3 matrix at 23: the sizes do not match",
        ),
        ("vec(1, 2)", "LHS is a vector of 2, RHS is a scalar"),
        ("dot(vec(1, 2))", "dot at 0 takes 2 arguments, not 1"),
    ] {
        let (code, out, err) = run(&["prove", lhs, "0"]);
        assert_eq!(code, 2, "{lhs}: {out}{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(want), "{lhs}: {err}");
    }
}

#[test]
fn vector_and_matrix_identities_are_proved_component_by_component() {
    proved("[[0, -1], [1, 0]] * [u, v]", "[-v, u]");
    proved(
        "cross([a1, a2, a3], [b1, b2, b3])",
        "-cross([b1, b2, b3], [a1, a2, a3])",
    );
    proved(
        "transpose([[a, b], [c, d]] * [[p, q], [r, s]])",
        "transpose([[p, q], [r, s]]) * transpose([[a, b], [c, d]])",
    );
    // The hodograph of a quadratic Bezier curve: diff of a vector is taken per coordinate.
    proved(
        "diff(bezier(t, [x0, y0], [x1, y1], [x2, y2]), t)",
        "2*bezier(t, [x1 - x0, y1 - y0], [x2 - x1, y2 - y1])",
    );
    proved("integrate([1, 2*t, 3*t^2], t, 0, u)", "[u, u^2, u^3]");
    // Without RHS, every component is compared with 0.
    let (code, out, err) = run(&["prove", "cross([a1, a2, a3], [a1, a2, a3])"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.starts_with("proved: LHS - RHS expands to 0 in each of the 3 components"),
        "{out}"
    );
}

#[test]
fn a_failing_component_is_named_with_its_counter_example() {
    let (code, out, err) = run(&[
        "prove",
        "diff(bezier(t, [0, 0], [1, 1], [2, 0]), t)",
        "[2, 2 - 2*t]",
        "--where",
        "0 < t < 1",
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        out.starts_with("fails: in component 2 (y): at t = 1/2: LHS - RHS = -1"),
        "{out}"
    );
    let (code, out, _) = run(&["prove", "[[a, b], [c, d]]", "[[a, b], [c, d + 1]]"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails: in entry (2, 2): "), "{out}");
    // Every undecided component is named.
    let (code, out, _) = run(&["prove", "[x, y]", "[0, 0]", "--where", "x^2 + y^2 = 0"]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.starts_with("undecided: in component 1 (x): ")
            && out.contains("(also undecided: component 2 (y))"),
        "{out}"
    );
}

#[test]
fn the_json_of_a_vector_identity_carries_each_component() {
    let (code, out, _) = run(&["prove", "--json", "[[0, -1], [1, 0]] * [u, v]", "[-v, 2*u]"]);
    assert_eq!(code, 1, "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("one JSON object");
    assert_eq!(v["verdict"], "fails");
    assert_eq!(v["shape"], "a vector of 2");
    assert_eq!(v["failing_component"], "component 2 (y)");
    let verdicts: Vec<&str> = v["components"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["verdict"].as_str().unwrap())
        .collect();
    assert_eq!(verdicts, ["proved", "fails"]);
    assert_eq!(v["components"][1]["component"], "component 2 (y)");
}

#[test]
fn random_evaluation_tests_every_component() {
    let (code, out, err) = run(&[
        "prove",
        "--random",
        "20",
        "[[0, -1], [1, 0]] * [u, v]",
        "[-v, u]",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.starts_with("holds: in each of the 2 components: LHS - RHS vanishes at all 20 points"),
        "{out}"
    );
    assert!(out.contains("random primes, one per component"), "{out}");
    let (code, out, _) = run(&[
        "prove",
        "--random",
        "20",
        "[[0, -1], [1, 0]] * [u, v]",
        "[-v, 2*u]",
    ]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("fails: in component 2 (y): "), "{out}");
}

#[test]
fn sides_of_different_shapes_are_one_line_errors() {
    for (lhs, rhs, want) in [
        (
            "[a, b]",
            "[a, b, c]",
            "LHS is a vector of 2, RHS is a vector of 3",
        ),
        ("[a, b]", "a", "LHS is a vector of 2, RHS is a scalar"),
        (
            "[[a, b], [c, d]]",
            "[[a, b, c], [d, f, g]]",
            "LHS is a 2x2 matrix, RHS is a 2x3 matrix",
        ),
        (
            "[a, b, c, d]",
            "[[a, b], [c, d]]",
            "LHS is a vector of 4, RHS is a 2x2 matrix",
        ),
    ] {
        for random in [false, true] {
            let mut args = vec!["prove", lhs, rhs];
            if random {
                args.extend(["--random", "5"]);
            }
            let (code, out, err) = run(&args);
            assert_eq!(code, 2, "{lhs} = {rhs}: {out}{err}");
            assert!(out.is_empty() && err.lines().count() == 1, "{err}");
            assert!(err.contains(want), "{lhs} = {rhs}: {err}");
        }
    }
}
