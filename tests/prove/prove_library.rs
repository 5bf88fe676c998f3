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
        ("vec(1, 2)", "a vector of 2 where a scalar is expected"),
        ("dot(vec(1, 2))", "dot at 0 takes 2 arguments, not 1"),
    ] {
        let (code, out, err) = run(&["prove", lhs, "0"]);
        assert_eq!(code, 2, "{lhs}: {out}{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(want), "{lhs}: {err}");
    }
}
