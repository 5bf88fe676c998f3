//! LaTeX from expression trees, with a [`Notation`] for variable names.
//!
//! # One layout, two printers
//! An [`Expr`] is first turned into a small **layout tree** (`Layout`: rows, numbers,
//! identifiers, operators, fractions, roots, scripts, parentheses) in which every decision about
//! the mathematics is taken once: which products become fractions, where the precedence of the
//! operators needs parentheses, where a thin space and where a `\cdot` separates factors, how a
//! power of `cos beta` is written (`\cos^{2}\beta`). The LaTeX printer here ([`to_latex`]) and the
//! MathML printer ([`super::to_mathml`]) only spell that layout, so the two always show the same
//! formula.
//!
//! # Printing rules
//! * a number `n/d` is `\frac{n}{d}`, its sign outside (`-\frac{3}{4}`); integers as digits;
//! * a product with divisions is `\frac{numerator}{denominator}` (the sign of a leading negative
//!   factor pulled in front); the factors of a product are juxtaposed with a thin space `\,`,
//!   except that a factor starting with a number is separated by `\cdot` (`2\cdot 3`, `x\cdot 2`);
//! * `\sqrt{..}`, `x^{k}`; `\left( .. \right)` only where precedence needs it: a sum as a factor
//!   or operand, a negative term after `+`/`-` or as a later factor, any compound base of a
//!   power;
//! * the calculus functions print as in a paper: `sum(k, a, b, E)` is `\sum_{k=a}^{b} E`,
//!   `integrate(E, t, a, b)` is `\int_{a}^{b} E\,\mathrm{d}t`, `diff(E, t)` is
//!   `\frac{\mathrm{d}}{\mathrm{d}t} E` (`diff(E, t, k)` with `\mathrm{d}^{k}` and `t^{k}`),
//!   `binomial(n, k)` is `\binom{n}{k}`, `factorial(n)` is `n!` (with other numbers of
//!   arguments they print as any call);
//! * a function call `f(a, b)` ([`ExprKind::Call`]) is `\operatorname{f}\left(a, b\right)` (or,
//!   when the notation lists `f`, its entry: `r_{0}\left(3\right)`), and a call with the empty
//!   name is a tuple, `\left(a, b\right)` (a vector in an erratum);
//! * an equation is `lhs = rhs` ([`equation_to_latex`]).
//!
//! # Names
//! [`Notation`] maps a variable name to LaTeX (`cb` -> `\cos\beta`). The LaTeX given for a name
//! is read into a small structured form (function names, Greek letters, identifiers, digits,
//! one subscript), so MathML is derived from the same entry. Unlisted names follow default rules:
//! Greek letter names (`beta` -> `\beta`, `Gamma` -> `\Gamma`), trailing digits as a subscript
//! (`p0` -> `p_{0}`, `q12` -> `q_{12}`), `a_b` -> `a_{b}` (with `q0_x` -> `q_{0,x}`), one letter as
//! is, any other name as an italic word (`\mathit{ab}`).
//!
//! Hand-written: the two output languages are tiny and fixed, and the layout decisions above are
//! the point of the module; a general typesetting crate would not know the notation of the papers.

use super::{is_decimal_name, AddOp, Expr, ExprKind, MulOp};
use crate::rational::Rational;
use exactcheck_core::Sign;
use std::collections::HashMap;

// ------------------------------------------------------------------------------ names

/// Function names LaTeX has a command for (`\cos`); others print as `\operatorname{..}`.
const FUNCTIONS: [&str; 12] = [
    "sin", "cos", "tan", "cot", "sec", "csc", "log", "ln", "exp", "det", "min", "max",
];

/// Greek letters by name with their Unicode characters (for MathML). `omicron` is absent: LaTeX
/// has no command for it.
const GREEK: [(&str, char); 35] = [
    ("alpha", 'α'),
    ("beta", 'β'),
    ("gamma", 'γ'),
    ("delta", 'δ'),
    ("epsilon", 'ϵ'),
    ("zeta", 'ζ'),
    ("eta", 'η'),
    ("theta", 'θ'),
    ("iota", 'ι'),
    ("kappa", 'κ'),
    ("lambda", 'λ'),
    ("mu", 'μ'),
    ("nu", 'ν'),
    ("xi", 'ξ'),
    ("pi", 'π'),
    ("rho", 'ρ'),
    ("sigma", 'σ'),
    ("tau", 'τ'),
    ("upsilon", 'υ'),
    ("phi", 'ϕ'),
    ("chi", 'χ'),
    ("psi", 'ψ'),
    ("omega", 'ω'),
    ("varphi", 'φ'),
    ("vartheta", 'ϑ'),
    ("Gamma", 'Γ'),
    ("Delta", 'Δ'),
    ("Theta", 'Θ'),
    ("Lambda", 'Λ'),
    ("Xi", 'Ξ'),
    ("Pi", 'Π'),
    ("Sigma", 'Σ'),
    ("Upsilon", 'Υ'),
    ("Phi", 'Φ'),
    ("Omega", 'Ω'),
];

/// The Unicode character of a Greek letter name.
pub(super) fn greek_char(name: &str) -> Option<char> {
    GREEK.iter().find(|(n, _)| *n == name).map(|(_, c)| *c)
}

/// The name of a Unicode Greek letter (`θ` is `theta`), for reading: the table's characters,
/// and `ε` (the common form of epsilon) as `epsilon`. `π` is not a name but the constant pi.
pub(super) fn greek_name(c: char) -> Option<&'static str> {
    match c {
        'π' => None,
        'ε' => Some("epsilon"),
        _ => GREEK.iter().find(|(_, g)| *g == c).map(|(n, _)| *n),
    }
}

/// One piece of a variable's printed name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Glyph {
    /// An upright function name applied to what follows (`\cos`, `\operatorname{arc}`).
    Function(String),
    /// A Greek letter by name (`beta`).
    Greek(String),
    /// An italic identifier: one letter, or a word (`\mathit{ab}`).
    Ident(String),
    /// Upright digits.
    Digits(String),
    /// A comma (between two parts of a subscript).
    Comma,
}

/// A variable's printed name: glyphs, and a subscript on the last of them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Symbol {
    pub(super) body: Vec<Glyph>,
    pub(super) sub: Vec<Glyph>,
}

/// How variable names are printed: explicit entries (name -> LaTeX, read into a structured form
/// so that MathML comes from the same entry) and the default rules of the module documentation
/// for every other name.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Notation {
    entries: HashMap<String, Symbol>,
}

impl Notation {
    /// No entries: every name by the default rules.
    pub fn new() -> Self {
        Self::default()
    }

    /// A notation with these entries ([`Notation::set`] for each).
    ///
    /// # Errors
    /// The first entry whose LaTeX is outside the accepted subset.
    pub fn from_pairs<N: AsRef<str>, L: AsRef<str>>(
        pairs: impl IntoIterator<Item = (N, L)>,
    ) -> Result<Self, String> {
        let mut n = Notation::new();
        for (name, latex) in pairs {
            n.set(name.as_ref(), latex.as_ref())?;
        }
        Ok(n)
    }

    /// Prints the variable `name` as `latex`, which may use: letters and digits, Greek letters
    /// (`\beta`), function names (`\cos`, `\operatorname{arc}`), `\mathit{word}`, one subscript
    /// `_{..}` (or `_x`) at the end, and spaces.
    ///
    /// # Errors
    /// A command or character outside that subset, or an empty form.
    pub fn set(&mut self, name: &str, latex: &str) -> Result<(), String> {
        let sym = parse_symbol(latex).map_err(|e| format!("notation {name} = {latex:?}: {e}"))?;
        self.entries.insert(name.to_string(), sym);
        Ok(())
    }

    /// The structured name of a variable (its entry, or the default rules).
    pub(super) fn symbol(&self, name: &str) -> Symbol {
        self.entries
            .get(name)
            .cloned()
            .unwrap_or_else(|| default_symbol(name))
    }

    /// The LaTeX of a variable name.
    pub fn latex(&self, name: &str) -> String {
        let mut out = String::new();
        write_latex(&symbol_layout(&self.symbol(name)), &mut out);
        out
    }
}

/// The default rules (module documentation).
fn default_symbol(name: &str) -> Symbol {
    if let Some(k) = name.find('_').filter(|&k| k > 0 && k + 1 < name.len()) {
        let base = default_symbol(&name[..k]);
        let rest = default_symbol(&name[k + 1..]);
        let mut sub = base.sub;
        if !sub.is_empty() {
            sub.push(Glyph::Comma);
        }
        sub.extend(rest.body);
        if !rest.sub.is_empty() {
            sub.push(Glyph::Comma);
            sub.extend(rest.sub);
        }
        return Symbol {
            body: base.body,
            sub,
        };
    }
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    if !stem.is_empty() && stem.len() < name.len() && !stem.ends_with('_') {
        let base = default_symbol(stem);
        let mut sub = base.sub;
        if !sub.is_empty() {
            sub.push(Glyph::Comma);
        }
        sub.push(Glyph::Digits(name[stem.len()..].to_string()));
        return Symbol {
            body: base.body,
            sub,
        };
    }
    let glyph = if greek_char(name).is_some() {
        Glyph::Greek(name.to_string())
    } else if name.chars().all(|c| c.is_ascii_digit()) && !name.is_empty() {
        Glyph::Digits(name.to_string())
    } else {
        Glyph::Ident(name.to_string())
    };
    Symbol {
        body: vec![glyph],
        sub: Vec::new(),
    }
}

/// Reads the LaTeX subset of [`Notation::set`].
fn parse_symbol(latex: &str) -> Result<Symbol, String> {
    let mut body = Vec::new();
    let mut sub = Vec::new();
    let mut rest = latex;
    while let Some(c) = rest.chars().next() {
        if c.is_whitespace() {
            rest = &rest[c.len_utf8()..];
        } else if c == '_' {
            if !sub.is_empty() || body.is_empty() {
                return Err("a subscript without a base or a second subscript".into());
            }
            let after = &rest[1..];
            let (inner, tail) = if let Some(inner) = after.strip_prefix('{') {
                let end = inner.find('}').ok_or("an unclosed '{'")?;
                (&inner[..end], &inner[end + 1..])
            } else {
                let ch = after.chars().next().ok_or("an empty subscript")?;
                (&after[..ch.len_utf8()], &after[ch.len_utf8()..])
            };
            let s = parse_symbol(inner)?;
            if !s.sub.is_empty() {
                return Err("a nested subscript".into());
            }
            sub = s.body;
            rest = tail;
        } else if !sub.is_empty() {
            return Err("text after the subscript".into());
        } else if let Some(after) = rest.strip_prefix('\\') {
            let word_len = after
                .find(|c: char| !c.is_ascii_alphabetic())
                .unwrap_or(after.len());
            let word = &after[..word_len];
            let tail = &after[word_len..];
            if word == "operatorname" || word == "mathit" {
                let inner = tail.strip_prefix('{').ok_or("'{' expected")?;
                let end = inner.find('}').ok_or("an unclosed '{'")?;
                let text = &inner[..end];
                if text.is_empty() || !text.chars().all(|c| c.is_ascii_alphanumeric()) {
                    return Err(format!("the word {text:?}"));
                }
                body.push(if word == "mathit" {
                    Glyph::Ident(text.into())
                } else {
                    Glyph::Function(text.into())
                });
                rest = &inner[end + 1..];
            } else if FUNCTIONS.contains(&word) {
                body.push(Glyph::Function(word.into()));
                rest = tail;
            } else if greek_char(word).is_some() {
                body.push(Glyph::Greek(word.into()));
                rest = tail;
            } else if word.is_empty() && tail.starts_with(',') {
                rest = &tail[1..];
            } else {
                return Err(format!(
                    "the command \\{word} is not accepted (letters, digits, Greek letters, function names such as \\cos, \\mathit{{..}} and one subscript are)"
                ));
            }
        } else if c.is_ascii_alphabetic() {
            body.push(Glyph::Ident(c.to_string()));
            rest = &rest[1..];
        } else if c.is_ascii_digit() {
            let end = rest
                .find(|c: char| !c.is_ascii_digit())
                .unwrap_or(rest.len());
            body.push(Glyph::Digits(rest[..end].into()));
            rest = &rest[end..];
        } else if c == ',' {
            body.push(Glyph::Comma);
            rest = &rest[1..];
        } else {
            return Err(format!("the character {c:?}"));
        }
    }
    if body.is_empty() {
        return Err("an empty name".into());
    }
    Ok(Symbol { body, sub })
}

// ------------------------------------------------------------------------------ layout

/// An operator or separator of the layout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Op {
    Plus,
    Minus,
    /// `\cdot` between factors.
    Dot,
    /// `\times` between factors (a cross product as written).
    Cross,
    /// Juxtaposition: a thin space in LaTeX, invisible times in MathML.
    Juxtapose,
    /// Function application after a function name (no LaTeX; `&#x2061;` in MathML).
    Apply,
    Equals,
    Comma,
    /// A comma inside a name (`q_{0,x}`).
    TightComma,
    /// The factorial sign after its operand.
    Bang,
}

/// A large operator with limits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum BigOp {
    /// `\sum`, limits under and over.
    Sum,
    /// `\int`, limits as sub- and superscript.
    Integral,
}

/// The layout tree both printers spell (module documentation).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Layout {
    Row(Vec<Layout>),
    /// Digits.
    Num(String),
    /// An italic identifier (one letter or a word).
    Ident(String),
    /// A Greek letter by name.
    Greek(String),
    /// An upright function name.
    Func(String),
    /// An upright letter that is not a function (the `d` of a differential).
    Upright(String),
    /// A large operator with its lower and upper limit.
    Big(BigOp, Box<Layout>, Box<Layout>),
    /// A binomial coefficient.
    Binom(Box<Layout>, Box<Layout>),
    Op(Op),
    Frac(Box<Layout>, Box<Layout>),
    Sqrt(Box<Layout>),
    /// In bold: a name that denotes a vector or matrix (`\mathbf{v}`).
    Bold(Box<Layout>),
    /// Between vertical bars: the absolute value.
    Abs(Box<Layout>),
    Sup(Box<Layout>, Box<Layout>),
    Sub(Box<Layout>, Box<Layout>),
    /// In parentheses.
    Fenced(Box<Layout>),
    /// A matrix by rows (a vector is one column), between parentheses or, for its
    /// determinant, between bars.
    Matrix {
        rows: Vec<Vec<Layout>>,
        det: bool,
    },
}

fn glyph_layout(g: &Glyph) -> Layout {
    match g {
        Glyph::Function(f) => Layout::Func(f.clone()),
        Glyph::Greek(n) => Layout::Greek(n.clone()),
        Glyph::Ident(s) => Layout::Ident(s.clone()),
        Glyph::Digits(d) => Layout::Num(d.clone()),
        Glyph::Comma => Layout::Op(Op::TightComma),
    }
}

/// Glyphs in a row, a function name followed by the application operator.
fn glyphs_layout(glyphs: &[Glyph]) -> Vec<Layout> {
    let mut out = Vec::new();
    for (k, g) in glyphs.iter().enumerate() {
        out.push(glyph_layout(g));
        if matches!(g, Glyph::Function(_)) && k + 1 < glyphs.len() {
            out.push(Layout::Op(Op::Apply));
        }
    }
    out
}

fn row(mut items: Vec<Layout>) -> Layout {
    if items.len() == 1 {
        items.pop().expect("one item")
    } else {
        Layout::Row(items)
    }
}

/// The layout of a name, with an optional exponent (a function-led name takes the exponent on
/// the function: `\cos^{2}\beta`).
fn symbol_layout_pow(sym: &Symbol, exponent: Option<Layout>) -> Layout {
    let mut body = glyphs_layout(&sym.body);
    if !sym.sub.is_empty() {
        let last = body.pop().expect("a symbol has a body");
        body.push(Layout::Sub(
            Box::new(last),
            Box::new(row(glyphs_layout(&sym.sub))),
        ));
    }
    match exponent {
        None => row(body),
        Some(e) => {
            if matches!(sym.body.first(), Some(Glyph::Function(_))) && sym.body.len() > 1 {
                let f = body.remove(0);
                body.insert(0, Layout::Sup(Box::new(f), Box::new(e)));
                row(body)
            } else if body.len() == 1 {
                Layout::Sup(Box::new(body.pop().expect("one item")), Box::new(e))
            } else {
                Layout::Sup(Box::new(Layout::Fenced(Box::new(row(body)))), Box::new(e))
            }
        }
    }
}

fn symbol_layout(sym: &Symbol) -> Layout {
    symbol_layout_pow(sym, None)
}

/// Whether the printed expression begins with a minus sign.
fn starts_with_minus(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Neg(_) => true,
        ExprKind::Number(q) => q.signum() == Sign::Negative,
        ExprKind::Sum(items) => items
            .first()
            .is_some_and(|(op, x)| *op == AddOp::Minus || starts_with_minus(x)),
        ExprKind::Product(items) => items
            .first()
            .is_some_and(|(op, x)| !op.divides() && starts_with_minus(x)),
        _ => false,
    }
}

/// Whether the printed expression begins with a digit (then a preceding factor is separated by
/// `\cdot`).
fn starts_with_number(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Number(_) => true,
        ExprKind::Pow(b, _) => starts_with_number(b),
        ExprKind::Product(items) => {
            // A product with divisions is a fraction: it starts with its bar, not a digit.
            items.iter().all(|(op, _)| !op.divides())
                && items.first().is_some_and(|(_, x)| starts_with_number(x))
        }
        _ => false,
    }
}

fn number_layout(q: &Rational) -> Layout {
    let neg = q.signum() == Sign::Negative;
    let (n, d) = (q.numer(), q.denom());
    let n = if neg { -n } else { n };
    let mag = if q.is_integer() {
        Layout::Num(n.to_string())
    } else {
        Layout::Frac(
            Box::new(Layout::Num(n.to_string())),
            Box::new(Layout::Num(d.to_string())),
        )
    };
    if neg {
        Layout::Row(vec![Layout::Op(Op::Minus), mag])
    } else {
        mag
    }
}

fn fenced(l: Layout) -> Layout {
    Layout::Fenced(Box::new(l))
}

/// Whether the printed expression ends in the operand of `\sum` or of a derivative
/// `\frac{d}{dt}`, which reads on over the factors written after it: such a factor is not
/// followed by another one without parentheses (`\left(\sum_{k=1}^{n} k\right)\,c`).
fn ends_open(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Call(name, args) => matches!(
            (name.as_str(), args.len()),
            ("sum", 4) | ("diff", 2) | ("diff", 3)
        ),
        // A negated sum or negative operand is in parentheses (see `layout`).
        ExprKind::Neg(x) => {
            !matches!(x.kind, ExprKind::Sum(_)) && !starts_with_minus(x) && ends_open(x)
        }
        ExprKind::Product(items) => {
            items.iter().all(|(op, _)| !op.divides())
                && items.last().is_some_and(|(_, x)| ends_open(x))
        }
        _ => false,
    }
}

/// Whether a call prints in a paper's notation that a power or a factorial sign after it would
/// enter (`\sum`, `\int`, a derivative, `n!`).
fn big_call(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Call(name, args)
        if matches!((name.as_str(), args.len()),
            ("sum", 4) | ("integrate", 4) | ("diff", 2 | 3) | ("factorial", 1)))
}

/// Whether `e` is a product with a `\cdot` or `\times` written in it ([`MulOp::Dot`],
/// [`MulOp::Cross`]): as a factor of another product it is in parentheses, since those
/// products group from the left (`u \times (v \times w)`).
fn has_vector_product(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Product(items)
        if items.iter().skip(1).any(|(op, _)| matches!(op, MulOp::Dot | MulOp::Cross)))
}

/// Factors with their operators: `\cdot` and `\times` as written ([`MulOp::Dot`],
/// [`MulOp::Cross`]), else juxtaposed (`\,`, or `\cdot` before a number); sums, later
/// negative factors, factors ending in an open operand ([`ends_open`]) before another factor and
/// products with a written `\cdot` or `\times` in parentheses.
fn factors_layout(factors: &[(MulOp, &Expr)], n: &Notation) -> Layout {
    let mut out = Vec::new();
    for (k, (op, f)) in factors.iter().enumerate() {
        let l = layout(f, n);
        let needs = matches!(f.kind, ExprKind::Sum(_))
            || (k > 0 && starts_with_minus(f))
            || (k + 1 < factors.len() && ends_open(f))
            || has_vector_product(f);
        if k > 0 {
            out.push(Layout::Op(match op {
                MulOp::Dot => Op::Dot,
                MulOp::Cross => Op::Cross,
                _ if starts_with_number(f) && !needs => Op::Dot,
                _ => Op::Juxtapose,
            }));
        }
        out.push(if needs { fenced(l) } else { l });
    }
    row(out)
}

/// The layout of an expression (module documentation).
pub(super) fn layout(e: &Expr, n: &Notation) -> Layout {
    match &e.kind {
        ExprKind::Number(q) => number_layout(q),
        ExprKind::Var(name) => symbol_layout(&n.symbol(name)),
        ExprKind::Neg(x) => {
            let inner = layout(x, n);
            let needs = matches!(x.kind, ExprKind::Sum(_)) || starts_with_minus(x);
            Layout::Row(vec![
                Layout::Op(Op::Minus),
                if needs { fenced(inner) } else { inner },
            ])
        }
        ExprKind::Sum(items) => {
            let mut out = Vec::new();
            for (k, (op, x)) in items.iter().enumerate() {
                match (k, op) {
                    (0, AddOp::Plus) => {}
                    (_, AddOp::Plus) => out.push(Layout::Op(Op::Plus)),
                    (_, AddOp::Minus) => out.push(Layout::Op(Op::Minus)),
                }
                let l = layout(x, n);
                let needs = matches!(x.kind, ExprKind::Sum(_))
                    || ((k > 0 || *op == AddOp::Minus) && starts_with_minus(x));
                out.push(if needs { fenced(l) } else { l });
            }
            row(out)
        }
        ExprKind::Product(items) => {
            let num: Vec<(MulOp, &Expr)> = items
                .iter()
                .filter(|(op, _)| !op.divides())
                .map(|(op, x)| (*op, x))
                .collect();
            let den: Vec<(MulOp, &Expr)> = items
                .iter()
                .filter(|(op, _)| op.divides())
                .map(|(_, x)| (MulOp::Times, x))
                .collect();
            if den.is_empty() {
                return factors_layout(&num, n);
            }
            // Pull the sign of a leading negative factor in front of the fraction.
            let mut num = num;
            let mut negated = None;
            let mut negative = false;
            if let Some((_, first)) = num.first() {
                match &first.kind {
                    ExprKind::Neg(x) => {
                        negative = true;
                        num[0].1 = x;
                    }
                    ExprKind::Number(q) if q.signum() == Sign::Negative => {
                        negative = true;
                        negated = Some(Expr::new(ExprKind::Number(-q.clone())));
                    }
                    _ => {}
                }
            }
            if let Some(abs) = &negated {
                num[0].1 = abs;
            }
            let one = Expr::new(ExprKind::Number(Rational::from_integer(1)));
            let num_l = if num.is_empty() || (num.len() == 1 && is_one(num[0].1)) {
                layout(&one, n)
            } else if num.len() == 1 {
                layout(num[0].1, n)
            } else {
                factors_layout(&num, n)
            };
            let den_l = if den.len() == 1 {
                layout(den[0].1, n)
            } else {
                factors_layout(&den, n)
            };
            let frac = Layout::Frac(Box::new(num_l), Box::new(den_l));
            if negative {
                Layout::Row(vec![Layout::Op(Op::Minus), frac])
            } else {
                frac
            }
        }
        ExprKind::Pow(base, exp) => {
            let e = layout(exp, n);
            if let ExprKind::Var(name) = &base.kind {
                return symbol_layout_pow(&n.symbol(name), Some(e));
            }
            let b = layout(base, n);
            let simple = matches!(&base.kind, ExprKind::Number(q) if q.is_integer() && q.signum() != Sign::Negative)
                || (matches!(base.kind, ExprKind::Call(..)) && !big_call(base));
            Layout::Sup(Box::new(if simple { b } else { fenced(b) }), Box::new(e))
        }
        ExprKind::Sqrt(x) => Layout::Sqrt(Box::new(layout(x, n))),
        ExprKind::Call(name, args)
            if name == super::library::BOLD
                && matches!(
                    args.as_slice(),
                    [Expr {
                        kind: ExprKind::Var(_),
                        ..
                    }]
                ) =>
        {
            Layout::Bold(Box::new(layout(&args[0], n)))
        }
        ExprKind::Call(name, args) if name == super::ABS && args.len() == 1 => {
            Layout::Abs(Box::new(layout(&args[0], n)))
        }
        ExprKind::Call(name, args) if name == super::LIST && !args.is_empty() => {
            matrix_layout(args, false, n)
        }
        ExprKind::Call(name, args)
            if name == "det"
                && matches!(&args[..], [m] if matches!(&m.kind, ExprKind::Call(l, rows)
                    if l == super::LIST && !rows.is_empty()
                        && rows.iter().all(|r| matches!(&r.kind, ExprKind::Call(l, _) if l == super::LIST)))) =>
        {
            let ExprKind::Call(_, rows) = &args[0].kind else {
                unreachable!("checked by the guard")
            };
            matrix_layout(rows, true, n)
        }
        ExprKind::Call(name, args) if args.is_empty() && is_decimal_name(name) => {
            Layout::Num(name.clone())
        }
        ExprKind::Call(name, args) if calculus_layout(name, args, n).is_some() => {
            calculus_layout(name, args, n).expect("checked by the guard")
        }
        ExprKind::Call(name, args) => {
            let mut inner = Vec::new();
            for (k, a) in args.iter().enumerate() {
                if k > 0 {
                    inner.push(Layout::Op(Op::Comma));
                }
                inner.push(layout(a, n));
            }
            let args_l = fenced(row(inner));
            if name.is_empty() {
                args_l
            } else if let Some(sym) = n.entries.get(name) {
                Layout::Row(vec![symbol_layout(sym), Layout::Op(Op::Apply), args_l])
            } else {
                Layout::Row(vec![
                    Layout::Func(name.clone()),
                    Layout::Op(Op::Apply),
                    args_l,
                ])
            }
        }
    }
}

/// A list literal's layout: a matrix when every item is a list (its rows), else a vector
/// printed as one column.
fn matrix_layout(items: &[Expr], det: bool, n: &Notation) -> Layout {
    let rows = items
        .iter()
        .map(|item| match &item.kind {
            ExprKind::Call(l, entries) if l == super::LIST => {
                entries.iter().map(|e| layout(e, n)).collect()
            }
            _ => vec![layout(item, n)],
        })
        .collect();
    Layout::Matrix { rows, det }
}

/// The operand of a large operator, a derivative or a factorial, in parentheses when it is a
/// sum (or, before `!`, anything but a name, a natural number or a call that is not in a
/// paper's notation).
fn operand(e: &Expr, n: &Notation, tight: bool) -> Layout {
    let l = layout(e, n);
    let plain = if tight {
        matches!(&e.kind, ExprKind::Var(_))
            || (matches!(&e.kind, ExprKind::Call(..)) && !big_call(e))
            || matches!(&e.kind, ExprKind::Number(q) if q.is_integer() && q.signum() != Sign::Negative)
    } else {
        !matches!(e.kind, ExprKind::Sum(_)) && !starts_with_minus(e)
    };
    if plain {
        l
    } else {
        fenced(l)
    }
}

/// `sum`, `integrate`, `diff`, `binomial` and `factorial` in a paper's notation (module
/// documentation); `None` for other calls and other numbers of arguments.
fn calculus_layout(name: &str, args: &[Expr], n: &Notation) -> Option<Layout> {
    let d = || Layout::Upright("d".into());
    Some(match (name, args) {
        ("sum", [k, a, b, e]) => Layout::Row(vec![
            Layout::Big(
                BigOp::Sum,
                Box::new(Layout::Row(vec![
                    layout(k, n),
                    Layout::Op(Op::Equals),
                    layout(a, n),
                ])),
                Box::new(layout(b, n)),
            ),
            operand(e, n, false),
        ]),
        ("integrate", [e, t, a, b]) => Layout::Row(vec![
            Layout::Big(
                BigOp::Integral,
                Box::new(layout(a, n)),
                Box::new(layout(b, n)),
            ),
            operand(e, n, false),
            Layout::Op(Op::Juxtapose),
            d(),
            layout(t, n),
        ]),
        ("diff", [e, t]) => Layout::Row(vec![
            Layout::Frac(
                Box::new(d()),
                Box::new(Layout::Row(vec![d(), layout(t, n)])),
            ),
            operand(e, n, false),
        ]),
        ("diff", [e, t, k]) => {
            let k = layout(k, n);
            Layout::Row(vec![
                Layout::Frac(
                    Box::new(Layout::Sup(Box::new(d()), Box::new(k.clone()))),
                    Box::new(Layout::Row(vec![
                        d(),
                        Layout::Sup(Box::new(layout(t, n)), Box::new(k)),
                    ])),
                ),
                operand(e, n, false),
            ])
        }
        ("binomial", [a, b]) => Layout::Binom(Box::new(layout(a, n)), Box::new(layout(b, n))),
        ("factorial", [a]) => Layout::Row(vec![operand(a, n, true), Layout::Op(Op::Bang)]),
        _ => return None,
    })
}

fn is_one(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Number(q) if q.is_integer() && q.numer() == 1.into())
}

// ------------------------------------------------------------------------------ LaTeX

/// Appends `s`, with a space when `out` ends in a control word and `s` starts with a letter
/// (`\cos t`, not `\cost`).
fn push_tex(out: &mut String, s: &str) {
    if s.starts_with(|c: char| c.is_ascii_alphabetic()) {
        let tail = out.trim_end_matches(|c: char| c.is_ascii_alphabetic());
        if tail.len() < out.len() && tail.ends_with('\\') {
            out.push(' ');
        }
    }
    out.push_str(s);
}

fn escape_word(s: &str) -> String {
    s.replace('_', "\\_")
}

fn write_latex(l: &Layout, out: &mut String) {
    match l {
        Layout::Row(items) => items.iter().for_each(|x| write_latex(x, out)),
        Layout::Num(d) => push_tex(out, d),
        Layout::Ident(s) => {
            if s.chars().count() == 1 {
                push_tex(out, s)
            } else {
                push_tex(out, &format!("\\mathit{{{}}}", escape_word(s)))
            }
        }
        Layout::Greek(g) => push_tex(out, &format!("\\{g}")),
        Layout::Func(f) => {
            if FUNCTIONS.contains(&f.as_str()) {
                push_tex(out, &format!("\\{f}"))
            } else {
                push_tex(out, &format!("\\operatorname{{{}}}", escape_word(f)))
            }
        }
        Layout::Op(op) => out.push_str(match op {
            Op::Plus => " + ",
            Op::Minus => {
                if out.is_empty() || out.ends_with(['{', '(', ' ']) {
                    "-"
                } else {
                    " - "
                }
            }
            Op::Dot => " \\cdot ",
            Op::Cross => " \\times ",
            Op::Juxtapose => "\\,",
            Op::Apply => "",
            Op::Equals => " = ",
            Op::Comma => ", ",
            Op::TightComma => ",",
            Op::Bang => "!",
        }),
        Layout::Upright(s) => push_tex(out, &format!("\\mathrm{{{}}}", escape_word(s))),
        Layout::Big(op, lo, hi) => {
            push_tex(
                out,
                match op {
                    BigOp::Sum => "\\sum",
                    BigOp::Integral => "\\int",
                },
            );
            out.push_str("_{");
            write_latex(lo, out);
            out.push_str("}^{");
            write_latex(hi, out);
            out.push_str("} ");
        }
        Layout::Binom(a, b) => {
            out.push_str("\\binom{");
            write_latex(a, out);
            out.push_str("}{");
            write_latex(b, out);
            out.push('}');
        }
        Layout::Frac(a, b) => {
            out.push_str("\\frac{");
            write_latex(a, out);
            out.push_str("}{");
            write_latex(b, out);
            out.push('}');
        }
        Layout::Bold(x) => {
            out.push_str("\\mathbf{");
            write_latex(x, out);
            out.push('}');
        }
        Layout::Sqrt(x) => {
            out.push_str("\\sqrt{");
            write_latex(x, out);
            out.push('}');
        }
        Layout::Abs(x) => {
            out.push_str("\\left|");
            write_latex(x, out);
            out.push_str("\\right|");
        }
        Layout::Matrix { rows, det } => {
            let env = if *det { "vmatrix" } else { "pmatrix" };
            out.push_str(&format!("\\begin{{{env}}}"));
            for (i, row) in rows.iter().enumerate() {
                if i > 0 {
                    out.push_str(" \\\\ ");
                }
                for (j, entry) in row.iter().enumerate() {
                    if j > 0 {
                        out.push_str(" & ");
                    }
                    write_latex(entry, out);
                }
            }
            out.push_str(&format!("\\end{{{env}}}"));
        }
        Layout::Sup(b, e) => {
            write_latex(b, out);
            out.push_str("^{");
            write_latex(e, out);
            out.push('}');
        }
        Layout::Sub(b, s) => {
            write_latex(b, out);
            out.push_str("_{");
            write_latex(s, out);
            out.push('}');
        }
        Layout::Fenced(x) => {
            out.push_str("\\left(");
            write_latex(x, out);
            out.push_str("\\right)");
        }
    }
}

/// The expression as LaTeX math (no `$`), names by `notation` (module documentation).
pub fn to_latex(e: &Expr, notation: &Notation) -> String {
    let mut out = String::new();
    write_latex(&layout(e, notation), &mut out);
    out
}

/// The equation `lhs = rhs` as LaTeX math.
pub fn equation_to_latex(lhs: &Expr, rhs: &Expr, notation: &Notation) -> String {
    let mut out = String::new();
    write_latex(&equation_layout(lhs, rhs, notation), &mut out);
    out
}

pub(super) fn equation_layout(lhs: &Expr, rhs: &Expr, n: &Notation) -> Layout {
    Layout::Row(vec![layout(lhs, n), Layout::Op(Op::Equals), layout(rhs, n)])
}

#[cfg(test)]
#[path = "latex_tests.rs"]
mod tests;
