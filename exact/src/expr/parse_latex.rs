//! LaTeX math notation, read by the one parser as the ASCII it stands for.
//!
//! A text is LaTeX when it has a `\`, `{`, `}` or `$`. Then:
//! * delimiters `$..$`, `$$..$$`, `\(..\)`, `\[..\]` at its ends (and a final `.` or `,`) are
//!   dropped; spacing (`\,` `\;` `\:` `\!` `\ ` `~` `\quad` `\qquad` `\displaystyle` `\limits`)
//!   is white space; `{..}` groups; `\left( \right)`, `\bigl[ \bigr]` and the other sizes are
//!   the parentheses and brackets; `\ast` is `*`, `\cdot` and `\times` the products
//!   [`MulOp::Dot`] and [`MulOp::Cross`] (`*` between scalars, the dot and cross products between
//!   vectors: [`library`](crate::expr::library)), `\div` is `/`; `^\circ` is degrees;
//! * a bold name `\mathbf{v}` (`\vec`, `\boldsymbol`, `\bm`; one name) is the call
//!   [`BOLD`](crate::expr::library::BOLD) of the name, which the library resolves to its
//!   definition; a norm `\|v\|` (`\lVert v \rVert`) is `sqrt(norm2(v))`, and `\|v\|^2` is
//!   `norm2(v)`;
//! * a name is one letter (adjacent letters are a product, `2ab` is `2*a*b`), a Greek letter
//!   (`\theta`, or `θ`), or `\mathit{word}`, `\mathrm{word}`, `\operatorname{word}`, each with an
//!   optional subscript of letters, digits and Greek letters: `x_{12}` is the name `x_12`,
//!   `\theta_1` is `theta_1`. A word that is a Greek letter's name (`theta`) or `pi` stays one
//!   name, and a function name directly before `(` stays a call (`sqrt(2)`);
//! * `\frac{a}{b}` (`\dfrac`, `\tfrac`, `\cfrac`; `\frac12`), `\sqrt{x}` (`\sqrt[2]{x}`),
//!   `\binom{n}{k}`, `\pi`;
//! * `\sin`, `\cos`, `\tan` with parentheses, or without them on a run of numbers, letters,
//!   Greek letters and `\pi` (`\sin 2x`, `\sin\theta`), or on one group or fraction
//!   (`\sin\frac{\theta}{2}`); a power goes before the argument (`\sin^2\theta` is
//!   `sin(theta)^2`). A power after such a run (`\sin x^2`), a `(` after a lone number
//!   (`\sin 2(x+1)`) and `\sin^{-1}` are refused as ambiguous;
//! * `\sum_{k=a}^{b} E` is `sum(k, a, b, E)`, the summand `E` being the product term that
//!   follows; `\int_{a}^{b} E\,dt` (or `\mathrm{d}t`) is `integrate(E, t, a, b)`, the integrand
//!   reaching to its differential; `\frac{d}{dt} E` (`\mathrm{d}`, `\partial`, orders
//!   `\frac{d^2}{dt^2}`) is `diff(E, t)`, `E` the product term that follows, and
//!   `\frac{df}{dt}`, `\frac{\partial f}{\partial t}` is `diff(f, t)`;
//! * matrices (`\begin{pmatrix} a & b \\ c & d \end{pmatrix}` and the other matrix
//!   environments), determinants (`vmatrix`, bars around a matrix, `\det`): see the child
//!   module `matrix`;
//! * any other command is refused, naming it.

use super::*;
use crate::expr::latex::{greek_char, greek_name};
use matrix::environment_end;
pub(super) use matrix::{determinant, is_matrix_literal};
use std::borrow::Cow;

#[path = "parse_latex_matrix.rs"]
mod matrix;

/// Spacing commands, read as white space (`\limits` places a sum's limits only).
const SPACING: &[&str] = &[
    "quad",
    "qquad",
    "displaystyle",
    "textstyle",
    "limits",
    "nolimits",
];

/// The size prefixes of a delimiter (`\left(`, `\bigr]`).
const SIZES: &[&str] = &[
    "left", "right", "bigl", "bigr", "Bigl", "Bigr", "biggl", "biggr", "Biggl", "Biggr", "big",
    "Big", "bigg", "Bigg",
];

/// Commands whose braced word is a name (`\mathrm{d}` is `d`).
const NAME_WORDS: &[&str] = &["mathit", "mathrm", "operatorname", "mathnormal"];

/// Mathematical commands the formula language has no exact reading of, with what they denote
/// (their refusal says so instead of only "not read").
const UNSUPPORTED_MATH: &[(&str, &str)] = &[
    ("log", "the logarithm"),
    ("ln", "the logarithm"),
    ("lg", "the logarithm"),
    ("exp", "the exponential function"),
    ("lim", "a limit"),
    ("infty", "infinity"),
    ("sinh", "a hyperbolic function"),
    ("cosh", "a hyperbolic function"),
    ("tanh", "a hyperbolic function"),
    ("arcsin", "an inverse trigonometric function"),
    ("arccos", "an inverse trigonometric function"),
    ("arctan", "an inverse trigonometric function"),
    ("prod", "a product with limits"),
];

const FRACTIONS: &[&str] = &["frac", "dfrac", "tfrac", "cfrac"];
const BINOMIALS: &[&str] = &["binom", "dbinom", "tbinom"];

const EXPECT_ARGUMENT: &str = "'{' or one character (the argument of a LaTeX command)";

/// The text to parse with the LaTeX delimiters at its ends blanked (byte positions kept), and
/// whether it is LaTeX.
pub(super) fn prepare(text: &str) -> (Cow<'_, str>, bool) {
    if !text.contains(['\\', '{', '}', '$']) {
        return (Cow::Borrowed(text), false);
    }
    let mut s = text.to_string();
    let blank = |s: &mut String, at: usize, n: usize| s.replace_range(at..at + n, &" ".repeat(n));
    let end = s.trim_end().len();
    if let Some(close) = ["$$", "$", "\\)", "\\]"]
        .into_iter()
        .find(|c| s[..end].ends_with(c))
    {
        blank(&mut s, end - close.len(), close.len());
    }
    let start = s.len() - s.trim_start().len();
    if let Some(open) = ["$$", "$", "\\(", "\\["]
        .into_iter()
        .find(|o| s[start..].starts_with(o))
    {
        blank(&mut s, start, open.len());
    }
    // The punctuation that ends a displayed formula.
    let end = s.trim_end().len();
    if s[..end].ends_with(['.', ',']) {
        blank(&mut s, end - 1, 1);
    }
    matrix::blank_alignment(&mut s);
    (Cow::Owned(s), true)
}

/// The letters of a command word starting at `at` (empty at or past the end of `src`, or
/// inside a character).
fn word_at(src: &str, at: usize) -> &str {
    let rest = src.get(at..).unwrap_or("");
    &rest[..rest
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(rest.len())]
}

/// The first byte at or after `at` that is neither white space nor a spacing command.
pub(super) fn skip_spacing(src: &str, mut at: usize) -> usize {
    loop {
        let rest = &src[at..];
        let trimmed = rest.trim_start();
        at += rest.len() - trimmed.len();
        if trimmed.starts_with('~') {
            at += 1;
        } else if let Some(after) = trimmed.strip_prefix('\\') {
            if after.starts_with([',', ';', ':', '!', ' ']) {
                at += 2;
            } else if SPACING.contains(&word_at(src, at + 1)) {
                at += 1 + word_at(src, at + 1).len();
            } else {
                return at;
            }
        } else {
            return at;
        }
    }
}

/// The end of a braced group starting at `at` (a `{`), after its matching `}`.
fn group_end(src: &str, at: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (i, c) in src[at..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(at + i + 1);
                }
            }
            _ => {}
        }
    }
    None
}

/// Whether `text` (a subscript's contents) spells a name: letters, digits, commas, spaces,
/// Greek letters and the name commands.
fn is_name_text(text: &str) -> bool {
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if c == '\\' {
            let word = word_at(rest, 1);
            if greek_char(word).is_none() && !NAME_WORDS.contains(&word) {
                return false;
            }
            rest = &rest[1 + word.len()..];
        } else if c.is_ascii_alphanumeric() || matches!(c, ',' | ' ' | '{' | '}') {
            rest = &rest[1..];
        } else {
            return false;
        }
    }
    !name_of(text).is_empty()
}

/// The end of a name's subscript at `at` (`_1`, `_{12}`, `_\theta`), or `at` without one.
fn subscript_end(src: &str, at: usize) -> usize {
    let Some(after) = src[at..].strip_prefix('_') else {
        return at;
    };
    let end = match after.chars().next() {
        Some('{') => group_end(src, at + 1).filter(|&e| is_name_text(&src[at + 2..e - 1])),
        Some(c) if c.is_ascii_alphanumeric() => Some(at + 2),
        Some('\\') if greek_char(word_at(src, at + 2)).is_some() => {
            Some(at + 2 + word_at(src, at + 2).len())
        }
        _ => None,
    };
    end.unwrap_or(at)
}

/// The name a name token spells (module documentation): `\theta_{1}` is `theta_1`,
/// `\mathrm{d}` is `d`, `θ` is `theta`, `q_{0,x}` is `q_0_x`.
pub(super) fn name_of(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if c == '\\' {
            let word = word_at(rest, 1);
            if !NAME_WORDS.contains(&word) {
                out.push_str(word);
            }
            rest = &rest[1 + word.len()..];
            continue;
        }
        match c {
            '{' | '}' | ' ' => {}
            ',' => out.push('_'),
            c => match greek_name(c) {
                Some(name) => out.push_str(name),
                None => out.push(c),
            },
        }
        rest = &rest[c.len_utf8()..];
    }
    out
}

/// Whether a word of several letters stays one name in LaTeX (module documentation).
fn whole_word(word: &str, before_paren: bool) -> bool {
    greek_char(word).is_some()
        || word == PI
        || (before_paren
            && (word == "sqrt"
                || FUNCTIONS.contains(&word)
                || FUNCTION_LIKE_NAMES.contains(&word)
                || crate::expr::library::function_names().contains(&word)))
}

/// Whether a name token may be called with `(`: a word of several letters, or
/// `\\operatorname{..}`.
pub(super) fn is_function_word(text: &str) -> bool {
    (text.len() > 1 && text.chars().all(|c| c.is_ascii_alphabetic()))
        || text.starts_with("\\operatorname")
}

/// Which side of an absolute value a command is: `\left|`, `\bigl|`, `\lvert` open it,
/// `\right|`, `\bigr|`, `\rvert` close it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Bar {
    Open,
    Close,
}

/// The side of an absolute value the command `text` stands for, if it is one.
fn bar(text: &str) -> Option<Bar> {
    let word = word_at(text, 1);
    let sized = text.trim_end().ends_with('|') && SIZES.contains(&word);
    match word {
        "lvert" => Some(Bar::Open),
        "rvert" => Some(Bar::Close),
        "left" | "bigl" | "Bigl" | "biggl" | "Biggl" if sized => Some(Bar::Open),
        "right" | "bigr" | "Bigr" | "biggr" | "Biggr" if sized => Some(Bar::Close),
        _ => None,
    }
}

impl Parser<'_> {
    /// The LaTeX token at `start` (not white space), or `None` where the ASCII lexer reads on.
    pub(super) fn lex_latex(&self, start: usize) -> Option<Token> {
        let src = self.src;
        let rest = &src[start..];
        let ch = rest.chars().next()?;
        let token = |tok, end| Some(Token { tok, start, end });
        match ch {
            '{' => token(Tok::LBrace, start + 1),
            '}' => token(Tok::RBrace, start + 1),
            '_' => token(Tok::Underscore, start + 1),
            // A matrix's entry separator (`a & b`).
            '&' => token(Tok::Command, start + 1),
            '^' => {
                let at = skip_spacing(src, start + 1);
                let r = &src[at..];
                let len = if r.starts_with("{\\circ}") {
                    7
                } else if word_at(src, at + 1) == "circ" && r.starts_with('\\') {
                    5
                } else {
                    return None;
                };
                token(Tok::Degree, at + len)
            }
            'A'..='Z' | 'a'..='z' => {
                let word = word_at(src, start);
                let end = start + word.len();
                if word.len() > 1 && whole_word(word, src[end..].starts_with('(')) {
                    return token(Tok::Ident, subscript_end(src, end));
                }
                token(Tok::Ident, subscript_end(src, start + 1))
            }
            '\\' => {
                let word = word_at(src, start + 1);
                let after = start + 1 + word.len();
                if word.is_empty() {
                    let len = rest[1..].chars().next().map_or(0, char::len_utf8);
                    return token(Tok::Command, start + 1 + len);
                }
                match word {
                    "begin" | "end" => {
                        token(Tok::Command, environment_end(src, start).unwrap_or(after))
                    }
                    "cdot" | "times" | "ast" => token(Tok::Star, after),
                    "div" => token(Tok::Slash, after),
                    "pi" => token(Tok::Pi, after),
                    w if SIZES.contains(&w) => {
                        let at = skip_spacing(src, after);
                        let tok = match src[at..].chars().next() {
                            Some('(') => Tok::LParen,
                            Some(')') => Tok::RParen,
                            Some('[') => Tok::LBracket,
                            Some(']') => Tok::RBracket,
                            Some(c) => return token(Tok::Command, at + c.len_utf8()),
                            None => return token(Tok::Command, after),
                        };
                        token(tok, at + 1)
                    }
                    w if greek_char(w).is_some() => token(Tok::Ident, subscript_end(src, after)),
                    w if NAME_WORDS.contains(&w) && src[after..].starts_with('{') => {
                        match group_end(src, after) {
                            Some(e) if is_name_text(&src[after + 1..e - 1]) => {
                                token(Tok::Ident, subscript_end(src, e))
                            }
                            _ => token(Tok::Command, after),
                        }
                    }
                    _ => token(Tok::Command, after),
                }
            }
            _ => None,
        }
    }

    /// Whether the current token closes an absolute value (`\right|`, `\rvert`) or a norm
    /// (`\rVert`, or `\|` inside a norm).
    pub(super) fn closes_bar(&self) -> bool {
        self.cur.tok == Tok::Command
            && (bar(self.text(self.cur)) == Some(Bar::Close) || self.closes_norm())
    }

    fn closes_norm(&self) -> bool {
        self.cur.tok == Tok::Command
            && match self.text(self.cur) {
                "\\rVert" => true,
                "\\|" | "\\Vert" => self.norms > 0,
                _ => false,
            }
    }

    /// A bold name (`\mathbf{v}`, `\vec{v}`, `\boldsymbol{v}`, `\bm{v}`; the current token
    /// being the command): the call [`BOLD`](crate::expr::library::BOLD) of the name, which
    /// the library resolves to the vector or matrix the name is defined as.
    fn parse_bold(&mut self, command: &str, pos: usize) -> Result<Expr, ExprError> {
        self.bump();
        let arg = self.tex_arg(command, false)?;
        if !matches!(arg.kind, ExprKind::Var(_)) {
            return Err(self.refuse(
                arg.pos,
                command,
                format!("{command} takes one name ({command}{{v}}, {command}{{v_1}}), not {arg}"),
            ));
        }
        Ok(Expr {
            kind: ExprKind::Call(crate::expr::library::BOLD.to_string(), vec![arg]),
            pos,
        })
    }

    /// A norm `\|v\|` or `\lVert v \rVert` (the current token opening it): the length
    /// `sqrt(norm2(v))`, and `\|v\|^2` is `norm2(v)`.
    fn parse_norm(&mut self, command: &str, pos: usize) -> Result<Expr, ExprError> {
        self.bump();
        self.norms += 1;
        let inner = self.inner_level(Self::parse_sum);
        let closed = self.closes_norm();
        self.norms -= 1;
        let inner = inner?;
        if !closed {
            return Err(self.refuse(
                pos,
                command,
                "the norm opened here is not closed by \\| (or \\rVert)",
            ));
        }
        self.bump();
        let norm2 = Expr {
            kind: ExprKind::Call("norm2".to_string(), vec![inner]),
            pos,
        };
        // `^2` or `^{2}` directly after the norm: its square.
        let saved = (self.cur, self.depth);
        if self.cur.tok == Tok::Caret {
            self.bump();
            let braced = self.cur.tok == Tok::LBrace;
            if braced {
                self.bump();
            }
            if self.cur.tok == Tok::Num && self.text(self.cur) == "2" {
                self.bump();
                if !braced || self.cur.tok == Tok::RBrace {
                    if braced {
                        self.bump();
                    }
                    return Ok(norm2);
                }
            }
        }
        (self.cur, self.depth) = saved;
        Ok(Expr {
            kind: ExprKind::Sqrt(Box::new(norm2)),
            pos,
        })
    }

    /// Whether the current token is the `d` of a differential (`dt`, `\mathrm{d}t`).
    pub(super) fn at_differential(&self) -> bool {
        self.latex && self.cur.tok == Tok::Ident && self.ident_name(self.cur) == "d"
    }

    fn refuse(&self, pos: usize, name: &str, why: impl Into<String>) -> ExprError {
        ExprError::BadCall {
            pos,
            name: name.to_string(),
            why: why.into(),
        }
    }

    /// A LaTeX command (the current token) as an atom.
    pub(super) fn parse_command(&mut self) -> Result<Expr, ExprError> {
        self.enter()?;
        let r = self.parse_command_inner();
        self.leave();
        r
    }

    fn parse_command_inner(&mut self) -> Result<Expr, ExprError> {
        let t = self.cur;
        let text = self.text(t);
        let word = &text[1..];
        if FRACTIONS.contains(&word) || BINOMIALS.contains(&word) || word == "sqrt" {
            self.bump();
        }
        let call = |name: &str, args: Vec<Expr>| Expr {
            kind: ExprKind::Call(name.to_string(), args),
            pos: t.start,
        };
        match word {
            w if FRACTIONS.contains(&w) => self.parse_fraction(text, t.start),
            w if BINOMIALS.contains(&w) => {
                let n = self.tex_arg(text, true)?;
                let k = self.tex_arg(text, false)?;
                Ok(call("binomial", vec![n, k]))
            }
            "sqrt" => {
                // `\sqrt[n]{x}`: the square root for n = 2, else `x^(1/n)` (of a constant).
                let mut index = None;
                if self.cur.tok == Tok::LBracket {
                    self.bump();
                    let n = self.parse_sum()?;
                    if self.cur.tok != Tok::RBracket {
                        return Err(self.unexpected("an operator or ']'"));
                    }
                    self.bump();
                    let k = n
                        .eval_constant::<Rational>()
                        .ok()
                        .filter(|k| k.is_integer() && *k >= Rational::from_integer(2));
                    match k {
                        Some(k) if k == Rational::from_integer(2) => {}
                        Some(k) => index = Some((k, n.pos)),
                        None => {
                            return Err(self.refuse(
                                n.pos,
                                "\\sqrt",
                                format!("the index of the root must be an integer constant of at least 2, not {n}"),
                            ))
                        }
                    }
                }
                let arg = self.tex_arg(text, false)?;
                Ok(match index {
                    None => Expr {
                        kind: ExprKind::Sqrt(Box::new(arg)),
                        pos: t.start,
                    },
                    Some((k, pos)) => {
                        let exponent = Expr {
                            pos,
                            ..Expr::number(k.recip().expect("the index is at least 2"))
                        };
                        Expr {
                            kind: ExprKind::Pow(Box::new(arg), Box::new(exponent)),
                            pos: t.start,
                        }
                    }
                })
            }
            w if TRIG_FUNCTIONS.contains(&w) => {
                self.bump();
                self.parse_trig(w, t.start)
            }
            "sum" => {
                self.bump();
                let (k, a, b) = self.parse_sum_limits(text)?;
                let summand = self.parse_product()?;
                Ok(call("sum", vec![k, a, b, summand]))
            }
            "int" => {
                self.bump();
                self.parse_integral(text, t.start)
            }
            "det" => self.parse_det(t.start),
            "mathbf" | "vec" | "boldsymbol" | "bm" => self.parse_bold(text, t.start),
            "|" | "lVert" | "Vert" => self.parse_norm(text, t.start),
            _ if text.starts_with("\\begin{") => self.parse_environment(),
            _ if text == "&" || text == "\\\\" || text.starts_with("\\end") => Err(self.refuse(
                t.start,
                text,
                "a matrix's entry or row separator, or \\end, outside a matrix environment",
            )),
            _ if bar(text) == Some(Bar::Open) => {
                self.bump();
                let inner = self.inner_level(Self::parse_sum)?;
                if !self.closes_bar() {
                    return Err(self.refuse(
                        t.start,
                        text,
                        "the absolute value opened here is not closed by \\right| (or \\rvert)",
                    ));
                }
                self.bump();
                // Bars around a matrix are its determinant.
                if is_matrix_literal(&inner) {
                    return Ok(determinant(inner, t.start));
                }
                Ok(call(crate::expr::ABS, vec![inner]))
            }
            _ if text.contains('|') || matches!(word, "vert" | "lvert" | "rvert" | "mid") => {
                Err(self.refuse(
                    t.start,
                    text,
                    "a bar that neither opens nor closes an absolute value: write \\left| x \\right| or \\lvert x \\rvert",
                ))
            }
            w if UNSUPPORTED_MATH.iter().any(|(c, _)| *c == w) => {
                let what = UNSUPPORTED_MATH
                    .iter()
                    .find(|(c, _)| *c == w)
                    .map_or("", |(_, what)| what);
                Err(self.refuse(
                    t.start,
                    text,
                    format!("{what} is not supported: the formula language is exact arithmetic with roots, sin, cos and tan, sums, integrals and derivatives of polynomials (see docs/formulas.md)"),
                ))
            }
            _ => Err(self.refuse(
                t.start,
                text,
                "this LaTeX command is not read (LaTeX input reads \\frac, \\sqrt, \\binom, \\sin, \\cos, \\tan, \\sum, \\int, \\det, \\begin{pmatrix}, \\pi, Greek letters, \\mathrm{..}, \\mathbf{..}, \\|v\\|, \\cdot, \\times, \\left( \\right) and spacing; see docs/formulas.md)",
            )),
        }
    }

    /// The argument of a command: a group `{..}`, or one character (`\frac12`) or command.
    /// `cut`: a number of several digits may give its first digit (the first argument of
    /// `\frac12`); elsewhere that is refused as misleading (`\sqrt12`).
    fn tex_arg(&mut self, command: &str, cut: bool) -> Result<Expr, ExprError> {
        match self.cur.tok {
            Tok::LBrace => self.parse_group(),
            Tok::Num => {
                let t = self.cur;
                let text = self.text(t);
                if text.len() > 1 && !cut {
                    return Err(self.refuse(
                        t.start,
                        command,
                        format!("the argument {text} without braces is its first digit only in LaTeX: write {{{text}}}"),
                    ));
                }
                self.cur.end = t.start + 1;
                self.parse_atom(EXPECT_ARGUMENT)
            }
            Tok::Ident if !self.at_differential() => {
                let t = self.cur;
                self.bump();
                Ok(Expr {
                    kind: ExprKind::Var(self.ident_name(t)),
                    pos: t.start,
                })
            }
            Tok::Pi | Tok::Command => self.parse_atom(EXPECT_ARGUMENT),
            _ => Err(self.unexpected(EXPECT_ARGUMENT)),
        }
    }

    /// `\frac` and its arguments (after the command): a derivative `\frac{d}{dt}`, or a
    /// quotient.
    fn parse_fraction(&mut self, command: &str, pos: usize) -> Result<Expr, ExprError> {
        if self.cur.tok == Tok::LBrace {
            let saved = (self.cur, self.depth);
            if let Some(d) = self.try_derivative(pos)? {
                return Ok(d);
            }
            (self.cur, self.depth) = saved;
        }
        let num = self.tex_arg(command, true)?;
        let den = self.tex_arg(command, false)?;
        Ok(Expr {
            kind: ExprKind::Product(vec![(MulOp::Times, num), (MulOp::Divide, den)]),
            pos,
        })
    }

    /// Whether the current token is the `d` (or, with `partial`, the `\partial`) of a
    /// derivative.
    fn at_d(&self, partial: bool) -> bool {
        if partial {
            self.cur.tok == Tok::Command && self.text(self.cur) == "\\partial"
        } else {
            self.cur.tok == Tok::Ident && self.ident_name(self.cur) == "d"
        }
    }

    /// An optional `^order` of a derivative.
    fn derivative_order(&mut self) -> Result<Option<Expr>, ExprError> {
        if self.cur.tok != Tok::Caret {
            return Ok(None);
        }
        self.bump();
        self.tex_arg("the order of a derivative", false).map(Some)
    }

    /// `{d f}{d t}` or `{d}{d t} E` (with `\partial`, and orders `d^2`, `t^2`), the current
    /// token being the first `{`; `None` (and the tokens to read again) when the fraction is
    /// not a derivative.
    fn try_derivative(&mut self, pos: usize) -> Result<Option<Expr>, ExprError> {
        self.bump();
        let partial = self.cur.tok == Tok::Command;
        if !self.at_d(partial) {
            return Ok(None);
        }
        self.bump();
        let Ok(order) = self.derivative_order() else {
            return Ok(None);
        };
        let f = if self.cur.tok == Tok::RBrace {
            None
        } else {
            match self.parse_sum() {
                Ok(f) => Some(f),
                Err(_) => return Ok(None),
            }
        };
        if self.cur.tok != Tok::RBrace {
            return Ok(None);
        }
        self.bump();
        if self.cur.tok != Tok::LBrace {
            return Ok(None);
        }
        self.bump();
        if !self.at_d(partial) {
            return Ok(None);
        }
        self.bump();
        if self.cur.tok != Tok::Ident {
            return Ok(None);
        }
        let v = self.cur;
        let var = Expr {
            kind: ExprKind::Var(self.ident_name(v)),
            pos: v.start,
        };
        self.bump();
        let Ok(var_order) = self.derivative_order() else {
            return Ok(None);
        };
        if partial && self.at_d(true) {
            return Err(self.refuse(
                self.cur.start,
                "\\partial",
                "mixed partial derivatives are not read: write one \\frac{\\partial}{\\partial x} after another",
            ));
        }
        if self.cur.tok != Tok::RBrace {
            return Ok(None);
        }
        self.bump();
        let same = match (&order, &var_order) {
            (None, None) => true,
            (Some(a), Some(b)) => {
                a.eval_constant::<Rational>().ok() == b.eval_constant::<Rational>().ok()
            }
            _ => false,
        };
        if !same {
            return Err(self.refuse(
                pos,
                "\\frac",
                "the orders of the d above and below differ (write \\frac{d^2}{dt^2})",
            ));
        }
        let e = match f {
            Some(f) => f,
            None => self.parse_product()?,
        };
        let mut args = vec![e, var];
        args.extend(order);
        Ok(Some(Expr {
            kind: ExprKind::Call("diff".to_string(), args),
            pos,
        }))
    }

    /// The argument of `\sin`, `\cos`, `\tan` (after the command, module documentation).
    fn parse_trig(&mut self, name: &str, pos: usize) -> Result<Expr, ExprError> {
        let command = format!("\\{name}");
        let exp = if self.cur.tok == Tok::Caret {
            self.bump();
            let e = self.parse_exponent()?;
            if e.eval_constant::<Rational>()
                .is_ok_and(|q| q.signum() == exactcheck_core::Sign::Negative)
            {
                return Err(self.refuse(
                    e.pos,
                    &command,
                    format!("a negative power such as {command}^{{-1}} is ambiguous (the inverse function or one over the power): write \\frac{{1}}{{{command} x}}"),
                ));
            }
            Some(e)
        } else {
            None
        };
        let arg = if self.cur.tok == Tok::LParen {
            self.parse_parenthesized()?
        } else {
            self.trig_run(&command)?
        };
        let call = Expr {
            kind: ExprKind::Call(name.to_string(), vec![arg]),
            pos,
        };
        Ok(match exp {
            Some(e) => power(call, e),
            None => call,
        })
    }

    /// A function's argument without parentheses: a run of numbers, letters, Greek letters
    /// and `\pi` (a number first only), or one group or fraction.
    fn trig_run(&mut self, command: &str) -> Result<Expr, ExprError> {
        let pos = self.cur.start;
        let mut items = Vec::new();
        loop {
            let t = self.cur;
            let item = match t.tok {
                Tok::Num if items.is_empty() => self.parse_atom(EXPECT_OPERAND)?,
                Tok::LBrace if items.is_empty() => self.parse_group()?,
                Tok::Command if items.is_empty() && FRACTIONS.contains(&&self.text(t)[1..]) => {
                    self.parse_command()?
                }
                Tok::Pi => self.parse_atom(EXPECT_OPERAND)?,
                Tok::Ident if !self.at_differential() => {
                    let name = self.ident_name(t);
                    if name == "sqrt"
                        || FUNCTIONS.contains(&name.as_str())
                        || FUNCTION_LIKE_NAMES.contains(&name.as_str())
                    {
                        break;
                    }
                    self.bump();
                    Expr {
                        kind: ExprKind::Var(name),
                        pos: t.start,
                    }
                }
                _ => break,
            };
            items.push(self.parse_degrees(item)?);
        }
        if items.is_empty() {
            return Err(self.unexpected(
                "the argument of a function: '(' or a run of numbers and letters (\\sin 2x)",
            ));
        }
        if matches!(self.cur.tok, Tok::Caret | Tok::Superscript) {
            return Err(self.refuse(
                self.cur.start,
                command,
                format!("a power after an argument without parentheses is ambiguous: write {command}(x^2) or ({command} x)^2"),
            ));
        }
        if self.cur.tok == Tok::LParen
            && items.len() == 1
            && matches!(items[0].kind, ExprKind::Number(_))
        {
            return Err(self.refuse(
                self.cur.start,
                command,
                format!("a number then '(' after {command} is ambiguous: write {command}(2(x+1)) or {command}(2)\\,(x+1)"),
            ));
        }
        if items.len() == 1 {
            return Ok(items.pop().expect("one item"));
        }
        Ok(Expr {
            kind: ExprKind::Product(items.into_iter().map(|e| (MulOp::Times, e)).collect()),
            pos,
        })
    }

    /// The limits of `\sum` or `\int`, `_lower` and `^upper` in either order.
    fn limits(
        &mut self,
        command: &str,
        mut lower: impl FnMut(&mut Self) -> Result<Expr, ExprError>,
    ) -> Result<Option<(Expr, Expr)>, ExprError> {
        let (mut lo, mut hi) = (None, None);
        for _ in 0..2 {
            match self.cur.tok {
                Tok::Underscore if lo.is_none() => {
                    self.bump();
                    lo = Some(lower(self)?);
                }
                Tok::Caret if hi.is_none() => {
                    self.bump();
                    hi = Some(self.tex_arg(command, false)?);
                }
                _ => break,
            }
        }
        Ok(lo.zip(hi))
    }

    /// `_{k=a}^{b}` after `\sum`: the index variable and the bounds.
    fn parse_sum_limits(&mut self, command: &str) -> Result<(Expr, Expr, Expr), ExprError> {
        let pos = self.cur.start;
        let mut index = None;
        let bounds = self.limits(command, |p| {
            if p.cur.tok != Tok::LBrace {
                return Err(p.unexpected("'{' and the index, as in \\sum_{k=1}^{n}"));
            }
            p.bump();
            let t = p.cur;
            if t.tok != Tok::Ident {
                return Err(p.unexpected("the index variable, as in \\sum_{k=1}^{n}"));
            }
            p.bump();
            index = Some(Expr {
                kind: ExprKind::Var(p.ident_name(t)),
                pos: t.start,
            });
            if p.cur.tok != Tok::Equals {
                return Err(p.unexpected("'=' and the first index, as in \\sum_{k=1}^{n}"));
            }
            p.bump();
            let a = p.parse_sum()?;
            if p.cur.tok != Tok::RBrace {
                return Err(p.unexpected("an operator or '}'"));
            }
            p.bump();
            Ok(a)
        })?;
        match (index, bounds) {
            (Some(k), Some((a, b))) => Ok((k, a, b)),
            _ => Err(self.refuse(
                pos,
                command,
                "a sum needs its index and both bounds: \\sum_{k=a}^{b}",
            )),
        }
    }

    /// `\int_{a}^{b} E\,dt` after `\int`.
    fn parse_integral(&mut self, command: &str, pos: usize) -> Result<Expr, ExprError> {
        let Some((a, b)) = self.limits(command, |p| p.tex_arg(command, false))? else {
            return Err(self.refuse(
                pos,
                command,
                "an integral needs both limits: \\int_{a}^{b} E\\,dt",
            ));
        };
        self.integrand += 1;
        let body = if self.at_differential() {
            Ok(Expr::number(Rational::from_integer(1)))
        } else {
            self.parse_sum()
        };
        self.integrand -= 1;
        let body = body?;
        if !self.at_differential() {
            return Err(
                self.unexpected("the differential (dt or \\mathrm{d}t) that ends the integral")
            );
        }
        self.bump();
        let v = self.cur;
        if v.tok != Tok::Ident {
            return Err(self.unexpected("the variable of the differential (dt)"));
        }
        self.bump();
        let t = Expr {
            kind: ExprKind::Var(self.ident_name(v)),
            pos: v.start,
        };
        Ok(Expr {
            kind: ExprKind::Call("integrate".to_string(), vec![body, t, a, b]),
            pos,
        })
    }
}

#[cfg(test)]
#[path = "parse_latex_tests.rs"]
mod tests;
