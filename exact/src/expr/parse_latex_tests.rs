//! LaTeX input: each construct against the ASCII it stands for, and the refusals.

use crate::expr::{parse_expr, parse_expr_with_calls, split_equation, to_latex, Notation};

/// The LaTeX text and the ASCII text parse to the same tree (compared as printed).
pub(super) fn same(latex: &str, ascii: &str) {
    let l = parse_expr_with_calls(latex).unwrap_or_else(|e| panic!("{latex:?}: {e}"));
    let a = parse_expr_with_calls(ascii).unwrap_or_else(|e| panic!("{ascii:?}: {e}"));
    assert_eq!(l.to_string(), a.to_string(), "{latex:?} against {ascii:?}");
}

/// The refusal of `latex`, which must name `part`.
pub(super) fn refused(latex: &str, part: &str) {
    match parse_expr_with_calls(latex) {
        Ok(e) => panic!("{latex:?} was read as {e}"),
        Err(e) => assert!(e.to_string().contains(part), "{latex:?}: {e}"),
    }
}

#[test]
fn delimiters_spacing_and_groups() {
    same("$\\frac{1}{2}$", "1/2");
    same("$$x^2 + 1.$$", "x^2 + 1");
    same("\\(x + y\\)", "x + y");
    same("\\[ x + y, \\]", "x + y");
    same("a\\,b\\;c\\:d\\!f~g\\quad h\\qquad k", "a*b*c*d*f*g*h*k");
    same("{x + 1}^{2}", "(x + 1)^2");
    same(
        "\\left(x + 1\\right)\\left[y - 1\\right]",
        "(x + 1)*(y - 1)",
    );
    same("\\bigl(x + 1\\bigr)^2 \\Bigl[y\\Bigr]", "(x + 1)^2*(y)");
    // `\cdot` and `\times` are kept as written (dot and cross products between vectors),
    // `\ast` is `*`.
    same("a \\cdot b \\times c \\div d", "a · b × c/d");
    same("a \\ast b", "a*b");
    same("30^\\circ + x^{\\circ}", "30° + x°");
}

#[test]
fn letters_are_a_product_in_latex_only() {
    same("$2ab$", "2*a*b");
    same("{ab}", "a*b");
    // ASCII keeps its names.
    assert_eq!(parse_expr("2ab").unwrap().to_string(), "2*ab");
    // A Greek letter's name and `pi` stay one name; a function name before `(` stays a call.
    same("$theta + pi + sqrt(2)$", "theta + pi + sqrt(2)");
}

#[test]
fn fractions_roots_powers_binomials() {
    same("\\frac{a}{b}", "a/b");
    same(
        "\\dfrac{x+1}{2} + \\tfrac13 + \\frac12",
        "(x+1)/2 + 1/3 + 1/2",
    );
    same("\\frac\\pi2 + \\frac a2", "pi/2 + a/2");
    same(
        "\\sqrt{x + 1} + \\sqrt[2]{y} + \\sqrt2",
        "sqrt(x + 1) + sqrt(y) + sqrt(2)",
    );
    same(
        "x^{2} + x^2 + x^{-1} + x^{1/2}",
        "x^2 + x^2 + x^(-1) + x^(1/2)",
    );
    same(
        "\\binom{n}{2} + \\binom52",
        "binomial(n, 2) + binomial(5, 2)",
    );
    same("\\sqrt[3]{x} + \\sqrt[2]{y}", "x^(1/3) + sqrt(y)");
    refused("\\sqrt[x]{2}", "an integer constant of at least 2");
    refused("\\sqrt[1]{2}", "an integer constant of at least 2");
    refused("\\sqrt12", "write {12}");
    refused("\\frac123", "write {23}");
}

#[test]
fn functions_with_and_without_parentheses() {
    same("\\sin(x + y)", "sin(x + y)");
    same("\\sin\\left(x\\right)", "sin(x)");
    same("\\sin x", "sin(x)");
    same("\\sin 2x", "sin(2*x)");
    same("\\sin 2\\pi t", "sin(2*pi*t)");
    same("\\sin\\theta", "sin(theta)");
    same(
        "\\sin^2\\theta + \\cos^{2}\\beta",
        "sin(theta)^2 + cos(beta)^2",
    );
    same("\\sin x \\cos y", "sin(x)*cos(y)");
    same("\\sin x + 1", "sin(x) + 1");
    same("\\tan\\frac{\\theta}{2}", "tan(theta/2)");
    same(
        "\\sin\\theta(1 + \\cos\\theta)",
        "sin(theta)*(1 + cos(theta))",
    );
    same("\\cos 60^\\circ", "cos(60°)");
    refused("\\sin x^2", "ambiguous");
    refused("\\sin 2(x + 1)", "ambiguous");
    refused("\\sin^{-1} x", "ambiguous");
    refused("\\sin + x", "the argument of a function");
}

#[test]
fn greek_letters_and_subscripts() {
    same("\\theta", "theta");
    same("θ + α", "theta + alpha");
    same("$θ$", "theta");
    same("\\pi + π", "pi + pi");
    same("\\Gamma \\omega", "Gamma*omega");
    same("x_1 + x_{12} + p_{x} + p_x", "x_1 + x_12 + p_x + p_x");
    same(
        "\\theta_1 + \\theta_{ab} + q_{0,x}",
        "theta_1 + theta_ab + q_0_x",
    );
    same("\\mathrm{d} + \\mathit{ab}", "d + ab");
}

#[test]
fn sums_integrals_derivatives() {
    same("\\sum_{k=1}^{n} k^2", "sum(k, 1, n, k^2)");
    same("\\sum_{k=1}^n k + 1", "sum(k, 1, n, k) + 1");
    same("\\sum^{n}_{k=0} 2k x", "sum(k, 0, n, 2*k*x)");
    same(
        "\\sum\\limits_{i=0}^{3}\\binom{3}{i}t^i(1-t)^{3-i}",
        "sum(i, 0, 3, binomial(3, i)*t^i*(1-t)^(3-i))",
    );
    same("\\int_0^1 t^2\\,dt", "integrate(t^2, t, 0, 1)");
    same(
        "\\int_{a}^{b} t + 1 \\, \\mathrm{d}t",
        "integrate(t + 1, t, a, b)",
    );
    same("\\int_0^1 dt", "integrate(1, t, 0, 1)");
    same(
        "\\int_0^1 (t + d)\\,d\\theta",
        "integrate(t + d, theta, 0, 1)",
    );
    same("\\frac{d}{dt} t^3", "diff(t^3, t)");
    same(
        "\\frac{\\mathrm{d}}{\\mathrm{d}t} t^3 x + 1",
        "diff(t^3*x, t) + 1",
    );
    same("\\frac{\\partial}{\\partial x} x^2 y", "diff(x^2*y, x)");
    same("\\frac{\\partial f}{\\partial x}", "diff(f, x)");
    same("\\frac{d^2}{dt^2} t^3", "diff(t^3, t, 2)");
    same("\\frac{d}{2} + \\frac{d}{d}", "d/2 + d/d");
    refused("\\sum_{k=1} k", "both bounds");
    refused("\\sum_{k=1}^10 k", "write {10}");
    refused("\\int_0^1 t^2", "the differential");
    refused("\\int t\\,dt", "both limits");
    refused("\\frac{d^2}{dt} t", "orders");
    refused(
        "\\frac{\\partial^2 f}{\\partial x \\partial y}",
        "mixed partial",
    );
}

#[test]
fn unknown_commands_are_named() {
    refused("\\log x", "\\log");
    refused("\\exp(x)", "\\exp");
    refused("\\lim x", "\\lim");
    for (command, what) in [
        ("\\log x", "the logarithm is not supported"),
        ("\\ln(x)", "the logarithm is not supported"),
        (
            "e^x + \\exp(x)",
            "the exponential function is not supported",
        ),
        ("\\lim_{x} x", "a limit is not supported"),
        ("\\sum_{k=1}^{\\infty} k", "infinity is not supported"),
    ] {
        refused(command, what);
    }
    refused("\\left| x", "not closed");
    refused("\\vert x \\vert", "neither opens nor closes");
    refused("\\{x\\}", "\\{");
}

#[test]
fn bars_are_the_absolute_value() {
    same("\\left| x - y \\right|", "abs(x - y)");
    same("\\lvert x \\rvert^2", "abs(x)^2");
    same("\\bigl| \\frac{a}{2} \\bigr| \\cdot 3", "abs(a/2) · 3");
}

#[test]
fn factorials_and_plain_bars() {
    same(
        "\\frac{n!}{k!(n-k)!}",
        "factorial(n)/(factorial(k)*factorial(n - k))",
    );
    same("$5! + (n+1)!^2$", "factorial(5) + factorial(n + 1)^2");
    same("$|x|^2 + |a - b|$", "abs(x)^2 + abs(a - b)");
    refused("\\frac{n!!}{2}", "double factorial");
}

#[test]
fn equations_split_at_their_one_top_level_equals() {
    let (l, r) = split_equation("x^2-1 = (x-1)(x+1)").unwrap();
    same(&l, "x^2-1");
    same(&r, "(x-1)(x+1)");
    let (l, r) = split_equation("$\\sum_{k=1}^{n} k = \\frac{n(n+1)}{2}$").unwrap();
    same(&l, "sum(k, 1, n, k)");
    same(&r, "(n*(n+1))/2");
    // The sides of a LaTeX equation stay LaTeX: `ab` is a product on both.
    let (l, r) = split_equation("\\frac{ab}{b} = ab").unwrap();
    same(&l, "(a*b)/b");
    same(&r, "a*b");
    assert!(split_equation("a = b = c").is_none());
    assert!(split_equation("a + b").is_none());
    // Positions are within the side.
    let err = parse_expr(&split_equation("x = 2 * * 3").unwrap().1).unwrap_err();
    assert!(err.to_string().contains("at 5"), "{err}");
}

/// The expression `ascii`, its LaTeX and that LaTeX read back.
fn latex_read_back(ascii: &str) -> (crate::expr::Expr, String, crate::expr::Expr) {
    let e = parse_expr_with_calls(ascii).unwrap();
    let latex = to_latex(&e, &Notation::new());
    let back = parse_expr_with_calls(&latex).unwrap_or_else(|e| panic!("{latex:?}: {e}"));
    (e, latex, back)
}

#[test]
fn printed_latex_reads_back() {
    for ascii in [
        "x^2 - 2*x*y/3 + (y + 1)^3",
        "-(x + 1)*(-y)",
        "sqrt(x + 1)/2 - 3/4",
        "sum(k, 1, n, k^2) + integrate(t^2, t, 0, 1) + diff(t^3, t) + diff(t^3, t, 2)",
        "binomial(n, 2) + sin(theta)^2 + cos(2*x)",
        "theta_1 + alpha*beta + ab",
        "sum(k, 1, n, k)*c + diff(x^2, x)*y - sum(k, 1, n, k)^2",
        "factorial(n)/(factorial(k)*factorial(n - k)) + factorial(factorial(3))^2",
        "abs(x)*abs(y - 1) + integrate(t, t, 0, 1)*c",
    ] {
        let (_, latex, back) = latex_read_back(ascii);
        assert_eq!(to_latex(&back, &Notation::new()), latex, "{ascii:?}");
    }
    // The same tree, not only the same LaTeX: a factor after \sum stays outside the sum.
    for ascii in [
        "sum(k, 1, n, k)*c",
        "-sum(k, 1, n, k)*c",
        "diff(x^2, x)*y",
        "sum(k, 1, n, k)^2",
        "factorial(factorial(n))",
    ] {
        let (e, latex, back) = latex_read_back(ascii);
        assert_eq!(back.to_string(), e.to_string(), "{latex:?}");
    }
}

#[test]
fn truncated_commands_are_errors_not_panics() {
    // A `^` or `\\` at the very end, or before a character of several bytes.
    for text in [
        "$x^",
        "$x^\u{ff}",
        "$x\\",
        "p1\\2+p3^\u{ffff}",
        "$0.6^\u{fffd}6{3",
    ] {
        assert!(parse_expr_with_calls(text).is_err(), "{text:?}");
    }
}

#[test]
fn bold_names_and_norms() {
    same("\\mathbf{u}", "bold(u)");
    same(
        "\\vec{u} + \\boldsymbol{v} - \\bm{w}",
        "bold(u) + bold(v) - bold(w)",
    );
    same("\\vec u \\cdot \\mathbf{v_1}", "bold(u) · bold(v_1)");
    same("\\|\\mathbf{u}\\|^2", "norm2(bold(u))");
    same("\\lVert u \\rVert^{2}", "norm2(u)");
    same("\\|u\\|", "sqrt(norm2(u))");
    same("\\|u\\|^3", "sqrt(norm2(u))^3");
    same("2\\|u - v\\| + 1", "2*sqrt(norm2(u - v)) + 1");
    refused("\\mathbf{2}", "takes one name");
    refused("\\mathbf{u v}", "takes one name");
    refused("\\|u", "the norm opened here is not closed");
    refused("\\rVert", "not read");
}

#[test]
fn library_functions_without_calls_are_refused_by_the_grammar_without_calls() {
    // `\det`, a matrix, a bold name and a norm are library calls: `parse_expr` (no calls)
    // refuses them by name instead of printing a call it cannot read back.
    for (latex, name) in [
        ("\\det2tl", "det"),
        ("\\mathbf{u}", "bold"),
        ("\\|u\\|^2", "norm2"),
    ] {
        match parse_expr(latex) {
            Ok(e) => panic!("{latex:?} was read as {e}"),
            Err(e) => assert!(
                e.to_string()
                    .contains(&format!("unknown function '{name}'")),
                "{latex:?}: {e}"
            ),
        }
        assert!(parse_expr_with_calls(latex).is_ok(), "{latex:?}");
    }
    assert!(parse_expr("\\begin{pmatrix} a & b \\end{pmatrix}").is_err());
    // The functions of every grammar stay.
    assert!(parse_expr("\\binom{4}{2} + \\sin x + |x|").is_ok());
}
