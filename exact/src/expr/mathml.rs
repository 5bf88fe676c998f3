//! MathML from expression trees: the layout of [`super::latex`] (one set of decisions for both
//! printers) spelled in MathML Core (`math`, `mrow`, `mi`, `mn`, `mo`, `mfrac`, `msqrt`, `msup`,
//! `msub`, `msubsup`, `munderover`), which Chromium renders natively (no scripts, no fonts).
//!
//! Greek letters are written as their Unicode characters, a function name as an upright `mi`
//! followed by the invisible function application `U+2061`, juxtaposition as the invisible
//! times `U+2062`, minus as `U+2212`. A multi-letter italic identifier (`\mathit{ab}`) is an
//! `mi` with `font-style: italic` (MathML Core draws multi-letter `mi` upright).
//! Hand-written for the same reason as the LaTeX printer: the output language is small and fixed.

use super::latex::{equation_layout, greek_char, layout, BigOp, Layout, Notation, Op};
use super::Expr;

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

fn write(l: &Layout, out: &mut String) {
    match l {
        Layout::Row(items) => {
            out.push_str("<mrow>");
            items.iter().for_each(|x| write(x, out));
            out.push_str("</mrow>");
        }
        Layout::Num(d) => out.push_str(&format!("<mn>{}</mn>", escape(d))),
        Layout::Ident(s) => {
            if s.chars().count() == 1 {
                out.push_str(&format!("<mi>{}</mi>", escape(s)))
            } else {
                out.push_str(&format!(
                    "<mi style=\"font-style: italic\">{}</mi>",
                    escape(s)
                ))
            }
        }
        Layout::Greek(g) => {
            let c = greek_char(g).expect("the layout has only known Greek letter names");
            out.push_str(&format!("<mi>{c}</mi>"))
        }
        Layout::Func(f) => out.push_str(&format!("<mi mathvariant=\"normal\">{}</mi>", escape(f))),
        Layout::Op(op) => out.push_str(match op {
            Op::Plus => "<mo>+</mo>",
            Op::Minus => "<mo>\u{2212}</mo>",
            Op::Dot => "<mo>\u{22c5}</mo>",
            Op::Cross => "<mo>\u{d7}</mo>",
            Op::Juxtapose => "<mo>\u{2062}</mo>",
            // A thin space after a function name, as LaTeX puts after `\cos` (`cos t`, not `cost`).
            Op::Apply => "<mo rspace=\"0.1667em\">\u{2061}</mo>",
            Op::Equals => "<mo>=</mo>",
            Op::Comma | Op::TightComma => "<mo>,</mo>",
            Op::Bang => "<mo>!</mo>",
        }),
        Layout::Upright(s) => {
            out.push_str(&format!("<mi mathvariant=\"normal\">{}</mi>", escape(s)))
        }
        Layout::Big(op, lo, hi) => {
            let (tag, sign) = match op {
                BigOp::Sum => ("munderover", "\u{2211}"),
                BigOp::Integral => ("msubsup", "\u{222b}"),
            };
            out.push_str(&format!("<{tag}><mo>{sign}</mo>"));
            write(lo, out);
            write(hi, out);
            out.push_str(&format!("</{tag}>"));
        }
        Layout::Binom(a, b) => {
            out.push_str("<mrow><mo>(</mo><mfrac linethickness=\"0\">");
            write(a, out);
            write(b, out);
            out.push_str("</mfrac><mo>)</mo></mrow>");
        }
        Layout::Frac(a, b) => {
            out.push_str("<mfrac>");
            write(a, out);
            write(b, out);
            out.push_str("</mfrac>");
        }
        Layout::Bold(x) => {
            out.push_str("<mstyle mathvariant=\"bold\">");
            write(x, out);
            out.push_str("</mstyle>");
        }
        Layout::Sqrt(x) => {
            out.push_str("<msqrt>");
            write(x, out);
            out.push_str("</msqrt>");
        }
        Layout::Abs(x) => {
            out.push_str("<mrow><mo>|</mo>");
            write(x, out);
            out.push_str("<mo>|</mo></mrow>");
        }
        Layout::Matrix { rows, det } => {
            let fence = if *det { ("|", "|") } else { ("(", ")") };
            out.push_str(&format!("<mrow><mo>{}</mo><mtable>", fence.0));
            for row in rows {
                out.push_str("<mtr>");
                for entry in row {
                    out.push_str("<mtd>");
                    write(entry, out);
                    out.push_str("</mtd>");
                }
                out.push_str("</mtr>");
            }
            out.push_str(&format!("</mtable><mo>{}</mo></mrow>", fence.1));
        }
        Layout::Sup(b, e) => {
            out.push_str("<msup>");
            write(b, out);
            write(e, out);
            out.push_str("</msup>");
        }
        Layout::Sub(b, s) => {
            out.push_str("<msub>");
            write(b, out);
            write(s, out);
            out.push_str("</msub>");
        }
        Layout::Fenced(x) => {
            out.push_str("<mrow><mo>(</mo>");
            write(x, out);
            out.push_str("<mo>)</mo></mrow>");
        }
    }
}

fn math(l: &Layout) -> String {
    let mut out = String::from("<math display=\"block\">");
    write(l, &mut out);
    out.push_str("</math>");
    out
}

/// The expression as a `<math display="block">` element of MathML Core, names by `notation`.
pub fn to_mathml(e: &Expr, notation: &Notation) -> String {
    math(&layout(e, notation))
}

/// The equation `lhs = rhs` as a `<math display="block">` element.
pub fn equation_to_mathml(lhs: &Expr, rhs: &Expr, notation: &Notation) -> String {
    math(&equation_layout(lhs, rhs, notation))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr_with_calls;

    fn ml(s: &str, n: &Notation) -> String {
        to_mathml(&parse_expr_with_calls(s).expect("parses"), n)
    }

    #[test]
    fn calculus_functions() {
        let n = Notation::new();
        assert_eq!(
            ml("sum(k, 1, n, k)", &n),
            "<math display=\"block\"><mrow><munderover><mo>\u{2211}</mo><mrow><mi>k</mi><mo>=</mo>\
             <mn>1</mn></mrow><mi>n</mi></munderover><mi>k</mi></mrow></math>"
        );
        assert_eq!(
            ml("integrate(t, t, 0, 1)", &n),
            "<math display=\"block\"><mrow><msubsup><mo>\u{222b}</mo><mn>0</mn><mn>1</mn></msubsup>\
             <mi>t</mi><mo>\u{2062}</mo><mi mathvariant=\"normal\">d</mi><mi>t</mi></mrow></math>"
        );
        assert_eq!(
            ml("binomial(n, 2)", &n),
            "<math display=\"block\"><mrow><mo>(</mo><mfrac linethickness=\"0\"><mi>n</mi><mn>2</mn>\
             </mfrac><mo>)</mo></mrow></math>"
        );
    }

    #[test]
    fn elements() {
        let n = Notation::new();
        assert_eq!(ml("x", &n), "<math display=\"block\"><mi>x</mi></math>");
        assert_eq!(
            ml("3/4 - p0", &n),
            "<math display=\"block\"><mrow><mfrac><mn>3</mn><mn>4</mn></mfrac><mo>\u{2212}</mo>\
             <msub><mi>p</mi><mn>0</mn></msub></mrow></math>"
        );
        assert_eq!(
            ml("sqrt(2) x^2", &n),
            "<math display=\"block\"><mrow><msqrt><mn>2</mn></msqrt><mo>\u{2062}</mo>\
             <msup><mi>x</mi><mn>2</mn></msup></mrow></math>"
        );
        assert_eq!(
            ml("(a + b)*2", &n),
            "<math display=\"block\"><mrow><mrow><mo>(</mo><mrow><mi>a</mi><mo>+</mo><mi>b</mi>\
             </mrow><mo>)</mo></mrow><mo>\u{22c5}</mo><mn>2</mn></mrow></math>"
        );
        assert_eq!(
            ml("ab + beta", &n),
            "<math display=\"block\"><mrow><mi style=\"font-style: italic\">ab</mi><mo>+</mo>\
             <mi>β</mi></mrow></math>"
        );
        assert_eq!(
            ml("f(x)", &n),
            "<math display=\"block\"><mrow><mi mathvariant=\"normal\">f</mi><mo rspace=\"0.1667em\">\u{2061}</mo>\
             <mrow><mo>(</mo><mi>x</mi><mo>)</mo></mrow></mrow></math>"
        );
    }

    #[test]
    fn notation_is_shared_with_latex() {
        let n = Notation::from_pairs([("cb", "\\cos\\beta")]).unwrap();
        assert_eq!(
            ml("cb^2", &n),
            "<math display=\"block\"><mrow><msup><mi mathvariant=\"normal\">cos</mi><mn>2</mn>\
             </msup><mo rspace=\"0.1667em\">\u{2061}</mo><mi>β</mi></mrow></math>"
        );
        assert_eq!(
            equation_to_mathml(&Expr::var("x"), &Expr::var("y"), &Notation::new()),
            "<math display=\"block\"><mrow><mi>x</mi><mo>=</mo><mi>y</mi></mrow></math>"
        );
        assert_eq!(escape("a<b&c>"), "a&lt;b&amp;c&gt;");
    }
}
