//! Tests of the products and powers as printed: `\cdot`, `\times`, bold names, norms, matrix
//! powers.

use super::*;
use crate::poly::Vars;

/// Definitions of the vectors `a`, `b`, `c` (3 symbolic coordinates each), `p`, `q` (2
/// coordinates) and the matrices `M` (2x2) and `R` (2x3).
fn vectors() -> Defs {
    let entries = [
        ("a", "[a1, a2, a3]"),
        ("b", "[b1, b2, b3]"),
        ("c", "[c1, c2, c3]"),
        ("p", "[p1, p2]"),
        ("q", "[q1, q2]"),
        ("M", "[[m11, m12], [m21, m22]]"),
        ("R", "[[1, 2, 3], [4, 5, 6]]"),
    ];
    Defs::new(
        entries
            .iter()
            .map(|(n, t)| (n.to_string(), DefText::Scalar(t.to_string())))
            .collect(),
    )
    .expect("valid definitions")
}

/// The components of `text`, resolved and expanded (square roots as variables of `vars`),
/// printed.
fn expanded(d: &mut Defs, vars: &mut Vars, text: &str) -> Vec<String> {
    let v = d
        .resolve_text(text)
        .unwrap_or_else(|e| panic!("{text}: {e}"));
    v.components()
        .iter()
        .map(|e| {
            let f = e
                .to_ratfun::<Rational>(vars)
                .unwrap_or_else(|e| panic!("{text}: {e}"));
            format!(
                "{} / {}",
                f.numerator().display(vars),
                f.denominator().display(vars)
            )
        })
        .collect()
}

/// Whether `lhs` and `rhs` expand to the same value in every component.
fn identity(d: &mut Defs, lhs: &str, rhs: &str) -> bool {
    let mut vars = Vars::new();
    vars.allow_roots();
    expanded(d, &mut vars, lhs) == expanded(d, &mut vars, rhs)
}

fn refusal(d: &mut Defs, text: &str) -> String {
    match d.resolve_text(text) {
        Ok(v) => panic!("{text} resolved to {}", v.shape()),
        Err(e) => e.message,
    }
}

#[test]
fn cdot_and_times_are_the_dot_and_cross_products_of_vectors() {
    let mut d = vectors();
    assert!(identity(
        &mut d,
        "\\mathbf{a}\\cdot\\mathbf{b}",
        "dot(a, b)"
    ));
    assert!(identity(&mut d, "\\vec{a}\\times\\vec{b}", "cross(a, b)"));
    assert!(identity(
        &mut d,
        "\\mathbf{p}\\times\\mathbf{q}",
        "p1 q2 - p2 q1"
    ));
    // Scalars between the vectors scale the product; the operator written is kept.
    assert!(identity(
        &mut d,
        "\\mathbf{a}\\cdot 2\\mathbf{b}",
        "2 dot(a, b)"
    ));
    assert!(identity(
        &mut d,
        "3\\mathbf{a}\\times\\mathbf{b}",
        "3 cross(a, b)"
    ));
    // The triple product reads from the left; BAC-CAB with parentheses.
    assert!(identity(
        &mut d,
        "\\mathbf{a}\\times\\mathbf{b}\\cdot\\mathbf{c}",
        "det([a, b, c])"
    ));
    assert!(identity(
        &mut d,
        "\\mathbf{a}\\times(\\mathbf{b}\\times\\mathbf{c})",
        "\\mathbf{b}(\\mathbf{a}\\cdot\\mathbf{c}) - \\mathbf{c}(\\mathbf{a}\\cdot\\mathbf{b})"
    ));
    // Its false twin does not expand to zero.
    assert!(!identity(
        &mut d,
        "\\mathbf{a}\\times(\\mathbf{b}\\times\\mathbf{c})",
        "\\mathbf{c}(\\mathbf{a}\\cdot\\mathbf{b}) - \\mathbf{b}(\\mathbf{a}\\cdot\\mathbf{c})"
    ));
    assert!(!identity(
        &mut d,
        "\\mathbf{a}\\times\\mathbf{b}",
        "\\mathbf{b}\\times\\mathbf{a}"
    ));
    // In text, `·` and `×` are the same products.
    assert!(identity(&mut d, "a · b", "dot(a, b)"));
    assert!(identity(&mut d, "a × b", "cross(a, b)"));
    // Between scalars, and a matrix and a vector, they are the ordinary product.
    assert!(identity(&mut d, "x \\cdot y \\times z", "x y z"));
    assert!(identity(&mut d, "\\mathbf{M}\\cdot\\mathbf{p}", "M p"));
    assert!(identity(&mut d, "\\mathbf{M}\\times\\mathbf{M}", "M M"));
}

#[test]
fn ambiguous_or_undefined_vector_products_are_refused() {
    let mut d = vectors();
    for (text, needle) in [
        (
            "\\mathbf{a}\\cdot\\mathbf{b}\\times\\mathbf{c}",
            "ambiguous",
        ),
        ("\\mathbf{a}\\cdot\\mathbf{b}\\cdot\\mathbf{c}", "ambiguous"),
        (
            "\\mathbf{a}\\times\\mathbf{b}\\times\\mathbf{c}",
            "not associative",
        ),
        ("\\mathbf{a}\\cdot 2\\times\\mathbf{b}", "write parentheses"),
        (
            "\\mathbf{M}\\cdot\\mathbf{M}",
            "\\cdot between a 2x2 matrix",
        ),
        (
            "\\mathbf{a}\\cdot\\mathbf{p}",
            "vectors of 3 and 2 coordinates",
        ),
        (
            "\\mathbf{a}\\, \\mathbf{b}",
            "write dot(u, v) or cross(u, v)",
        ),
        // A bold name that is not defined is never a scalar variable.
        (
            "\\mathbf{x}\\times\\mathbf{b}",
            "the bold name x at 0 is not defined",
        ),
        ("\\vec{n}", "--define 'n = [n1, n2, n3]'"),
        ("\\mathbf{a b}", "takes one name"),
        ("|\\mathbf{M}|", "ambiguous (its determinant or a norm)"),
    ] {
        let m = refusal(&mut d, text);
        assert!(m.contains(needle), "{text}: {m}");
    }
}

#[test]
fn norms_and_lengths() {
    let mut d = vectors();
    assert!(identity(&mut d, "\\|\\mathbf{a}\\|^2", "norm2(a)"));
    assert!(identity(
        &mut d,
        "\\lVert\\mathbf{a}\\rVert^{2}",
        "norm2(a)"
    ));
    assert!(identity(&mut d, "\\|\\mathbf{a}\\|", "sqrt(norm2(a))"));
    assert!(identity(&mut d, "|\\mathbf{a}|", "sqrt(norm2(a))"));
    assert!(identity(&mut d, "abs(p)", "sqrt(p1^2 + p2^2)"));
    // Lagrange's identity.
    assert!(identity(
        &mut d,
        "\\|\\mathbf{a}\\times\\mathbf{b}\\|^2",
        "\\|\\mathbf{a}\\|^2\\|\\mathbf{b}\\|^2 - (\\mathbf{a}\\cdot\\mathbf{b})^2"
    ));
    // A scalar's bars stay its absolute value.
    let mut vars = Vars::new();
    vars.allow_roots();
    assert_eq!(expanded(&mut d, &mut vars, "|x|").len(), 1);
}

#[test]
fn matrix_powers() {
    let mut d = vectors();
    assert!(identity(&mut d, "M^2", "M M"));
    assert!(identity(&mut d, "M^5", "M M M M M"));
    assert!(identity(&mut d, "\\mathbf{M}^{3}", "M (M M)"));
    assert!(identity(&mut d, "M^0", "[[1, 0], [0, 1]]"));
    assert!(identity(&mut d, "M^1", "M"));
    assert!(identity(&mut d, "det(M^2)", "det(M)^2"));
    assert!(identity(&mut d, "[[1, 1], [0, 1]]^64", "[[1, 64], [0, 1]]"));
    for (text, needle) in [
        (
            "R^2",
            "a power of a 2x3 matrix at 0: only a square matrix has powers",
        ),
        ("M^-1", "must be a non-negative integer constant"),
        ("M^k", "the exponent k of the matrix power"),
        (
            "M^(1/2)",
            "a 2x2 matrix at 0 where a scalar is expected (the argument of sqrt)",
        ),
        ("M^65", "matrix-power = 64"),
        ("a^2", "a vector of 3 at 0 where a scalar is expected"),
        ("2^M", "where a scalar is expected (an exponent)"),
    ] {
        let m = refusal(&mut d, text);
        assert!(m.contains(needle), "{text}: {m}");
    }
    // The size of the entries is bounded before they are built.
    let m = refusal(&mut d, "[[1, 1, 1], [0, 1, 1], [1, 0, 1]]^64");
    assert!(m.contains("nodes"), "{m}");
}

#[test]
fn written_products_print_as_written_and_read_back() {
    use crate::expr::{parse_expr_with_calls, to_latex, Notation};
    for text in [
        "\\mathbf{a}\\cdot\\mathbf{b}",
        "\\vec{a}\\times(\\vec{b}\\times\\vec{c})",
        "(\\mathbf{a}\\times\\mathbf{b})\\cdot\\mathbf{c}",
        "\\frac{\\mathbf{a}\\cdot\\mathbf{b}}{2}",
    ] {
        let e = parse_expr_with_calls(text).unwrap();
        let tex = to_latex(&e, &Notation::new());
        let plain = e.to_string();
        let mut d = vectors();
        assert!(identity(&mut d, text, &tex), "{text} -> {tex}");
        assert!(identity(&mut d, text, &plain), "{text} -> {plain}");
    }
    let e = parse_expr_with_calls("\\mathbf{a}\\times\\mathbf{b}").unwrap();
    assert_eq!(e.to_string(), "bold(a) \u{d7} bold(b)");
    assert_eq!(
        to_latex(&e, &Notation::new()),
        "\\mathbf{a} \\times \\mathbf{b}"
    );
}
