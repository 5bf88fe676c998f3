//! Tests of the LaTeX printer.

use super::*;
use crate::expr::parse_expr_with_calls;

fn tex(s: &str) -> String {
    to_latex(&parse_expr_with_calls(s).expect("parses"), &Notation::new())
}

fn spaeth() -> Notation {
    Notation::from_pairs([
        ("cb", "\\cos\\beta"),
        ("sb", "\\sin\\beta"),
        ("ct", "\\cos t"),
    ])
    .expect("valid notation")
}

#[test]
fn default_names() {
    let n = Notation::new();
    assert_eq!(n.latex("beta"), "\\beta");
    assert_eq!(n.latex("Gamma"), "\\Gamma");
    assert_eq!(n.latex("p0"), "p_{0}");
    assert_eq!(n.latex("q12"), "q_{12}");
    assert_eq!(n.latex("a_b"), "a_{b}");
    assert_eq!(n.latex("q0_x"), "q_{0,x}");
    assert_eq!(n.latex("x_beta"), "x_{\\beta}");
    assert_eq!(n.latex("beta2"), "\\beta_{2}");
    assert_eq!(n.latex("x"), "x");
    assert_eq!(n.latex("ab"), "\\mathit{ab}");
    assert_eq!(n.latex("_x3"), "\\mathit{\\_x}_{3}");
}

#[test]
fn notation_entries_and_errors() {
    let n = spaeth();
    assert_eq!(n.latex("cb"), "\\cos\\beta");
    assert_eq!(n.latex("ct"), "\\cos t");
    let m = Notation::from_pairs([("w", "\\operatorname{arc} w_{0}"), ("k", "\\mathit{ab}")])
        .expect("valid");
    assert_eq!(m.latex("w"), "\\operatorname{arc}w_{0}");
    assert_eq!(m.latex("k"), "\\mathit{ab}");
    let bad = Notation::from_pairs([("x", "\\frac{1}{2}")]).unwrap_err();
    assert_eq!(
        bad,
        "notation x = \"\\\\frac{1}{2}\": the command \\frac is not accepted (letters, \
         digits, Greek letters, function names such as \\cos, \\mathit{..} and one \
         subscript are)"
    );
    assert!(Notation::from_pairs([("x", "")]).is_err());
    assert!(Notation::from_pairs([("x", "a_{1}_{2}")]).is_err());
    assert!(Notation::from_pairs([("x", "a$")]).is_err());
}

#[test]
fn every_node_kind() {
    assert_eq!(tex("3"), "3");
    assert_eq!(tex("0.75"), "\\frac{3}{4}");
    assert_eq!(
        to_latex(
            &Expr::number(Rational::new(-3, 4).unwrap()),
            &Notation::new()
        ),
        "-\\frac{3}{4}"
    );
    assert_eq!(tex("x"), "x");
    assert_eq!(tex("-x"), "-x");
    assert_eq!(tex("a + b - c"), "a + b - c");
    assert_eq!(tex("-a + b"), "-a + b");
    assert_eq!(tex("2 x y"), "2\\,x\\,y");
    assert_eq!(tex("2*3"), "2 \\cdot 3");
    assert_eq!(tex("x*2"), "x \\cdot 2");
    assert_eq!(tex("x/2"), "\\frac{x}{2}");
    assert_eq!(tex("3 x y/4"), "\\frac{3\\,x\\,y}{4}");
    assert_eq!(tex("(a + b)/(2*3)"), "\\frac{a + b}{2 \\cdot 3}");
    assert_eq!(tex("-x/2"), "-\\frac{x}{2}");
    assert_eq!(tex("x^2"), "x^{2}");
    assert_eq!(tex("x^(k+1)"), "x^{k + 1}");
    assert_eq!(tex("sqrt(2)"), "\\sqrt{2}");
    assert_eq!(tex("3 sqrt(2)/2"), "\\frac{3\\,\\sqrt{2}}{2}");
    assert_eq!(tex("f(x, y)"), "\\operatorname{f}\\left(x, y\\right)");
    assert_eq!(tex("sum(k, 0, n, k^2)"), "\\sum_{k = 0}^{n} k^{2}");
    assert_eq!(
        tex("integrate(1 + t, t, 0, 1)"),
        "\\int_{0}^{1} \\left(1 + t\\right)\\,\\mathrm{d}t"
    );
    assert_eq!(
        tex("diff(x^3, x)"),
        "\\frac{\\mathrm{d}}{\\mathrm{d}x}x^{3}"
    );
    assert_eq!(
        tex("diff(f(t), t, 2)"),
        "\\frac{\\mathrm{d}^{2}}{\\mathrm{d}t^{2}}\\operatorname{f}\\left(t\\right)"
    );
    assert_eq!(tex("binomial(n, k)"), "\\binom{n}{k}");
    assert_eq!(tex("factorial(n)"), "n!");
    assert_eq!(tex("factorial(n + 1)"), "\\left(n + 1\\right)!");
    // other numbers of arguments print as any call
    assert_eq!(
        tex("binomial(n)"),
        "\\operatorname{binomial}\\left(n\\right)"
    );
    let r0 = Notation::from_pairs([("r0", "r_0")]).unwrap();
    let call = parse_expr_with_calls("r0(3)").unwrap();
    assert_eq!(to_latex(&call, &r0), "r_{0}\\left(3\\right)");
    assert_eq!(tex("p0 q1"), "p_{0}\\,q_{1}");
    assert_eq!(
        to_latex(
            &Expr::tuple(vec![
                Expr::number(Rational::from_integer(-20)),
                Expr::var("y")
            ]),
            &Notation::new()
        ),
        "\\left(-20, y\\right)"
    );
    assert_eq!(
        equation_to_latex(
            &Expr::var("x"),
            &parse_expr_with_calls("a/2").unwrap(),
            &Notation::new()
        ),
        "x = \\frac{a}{2}"
    );
}

#[test]
fn precedence() {
    assert_eq!(tex("(a + b) c"), "\\left(a + b\\right)\\,c");
    assert_eq!(tex("a - (b - c)"), "a - \\left(b - c\\right)");
    assert_eq!(tex("a + (-b)"), "a + \\left(-b\\right)");
    assert_eq!(tex("a - -b"), "a - \\left(-b\\right)");
    assert_eq!(tex("a*(-b)"), "a\\,\\left(-b\\right)");
    assert_eq!(tex("-(a + b)"), "-\\left(a + b\\right)");
    assert_eq!(tex("--a"), "-\\left(-a\\right)");
    assert_eq!(tex("-a b"), "-a\\,b");
    assert_eq!(tex("(a + b)^2"), "\\left(a + b\\right)^{2}");
    assert_eq!(tex("(a b)^2"), "\\left(a\\,b\\right)^{2}");
    assert_eq!(tex("(-a)^2"), "\\left(-a\\right)^{2}");
    assert_eq!(tex("-a^2"), "-a^{2}");
    assert_eq!(tex("(1/2)^2"), "\\left(\\frac{1}{2}\\right)^{2}");
    assert_eq!(tex("2^3"), "2^{3}");
    assert_eq!(tex("x^2^3"), "x^{2^{3}}");
    assert_eq!(tex("(x^2)^3"), "\\left(x^{2}\\right)^{3}");
    assert_eq!(tex("sqrt(2)^2"), "\\left(\\sqrt{2}\\right)^{2}");
    assert_eq!(tex("x*2^k"), "x \\cdot 2^{k}");
    assert_eq!(tex("a + b c - d/2"), "a + b\\,c - \\frac{d}{2}");
}

#[test]
fn names_with_functions() {
    let n = spaeth();
    let e = parse_expr_with_calls("cb*(a + r*ct) + u*sb").unwrap();
    assert_eq!(
        to_latex(&e, &n),
        "\\cos\\beta\\,\\left(a + r\\,\\cos t\\right) + u\\,\\sin\\beta"
    );
    let e = parse_expr_with_calls("cb^2 + ct^2 + p0^2 + ab^3").unwrap();
    assert_eq!(
        to_latex(&e, &n),
        "\\cos^{2}\\beta + \\cos^{2}t + p_{0}^{2} + \\mathit{ab}^{3}"
    );
    let two = Notation::from_pairs([("w", "u v")]).unwrap();
    let e = parse_expr_with_calls("w^2").unwrap();
    assert_eq!(to_latex(&e, &two), "\\left(uv\\right)^{2}");
}

#[test]
fn calls_that_read_on_are_grouped_before_more_factors() {
    // The operand of \sum and of a derivative is the product that follows, so a factor after
    // one of them would join it: the call goes in parentheses.
    assert_eq!(
        tex("sum(k, 1, n, k)*c"),
        "\\left(\\sum_{k = 1}^{n} k\\right)\\,c"
    );
    assert_eq!(
        tex("diff(x^2, x)*y"),
        "\\left(\\frac{\\mathrm{d}}{\\mathrm{d}x}x^{2}\\right)\\,y"
    );
    assert_eq!(
        tex("-sum(k, 1, n, k)*c"),
        "\\left(-\\sum_{k = 1}^{n} k\\right)\\,c"
    );
    assert_eq!(
        tex("a*sum(k, 1, n, k)*c/2"),
        "\\frac{a\\,\\left(\\sum_{k = 1}^{n} k\\right)\\,c}{2}"
    );
    // Last in its product it needs none; an integral ends at its differential.
    assert_eq!(tex("c*sum(k, 1, n, k)"), "c\\,\\sum_{k = 1}^{n} k");
    assert_eq!(
        tex("integrate(t, t, 0, 1)*c"),
        "\\int_{0}^{1} t\\,\\mathrm{d}t\\,c"
    );
    // A power or a factorial sign of such a call is outside parentheses.
    assert_eq!(
        tex("sum(k, 1, n, k)^2"),
        "\\left(\\sum_{k = 1}^{n} k\\right)^{2}"
    );
    assert_eq!(tex("factorial(n)^2"), "\\left(n!\\right)^{2}");
    assert_eq!(tex("factorial(factorial(n))"), "\\left(n!\\right)!");
    assert_eq!(tex("binomial(n, k)^2"), "\\binom{n}{k}^{2}");
}
