//! The lexer and the recursive-descent parser of the grammar in the module documentation, and
//! the exact value of number tokens (decimals, scientific notation).

use super::eval::check_constant;
use super::*;
use crate::poly::{Poly, Vars};
use num_bigint::BigUint;
use std::str::FromStr;

/// LaTeX math notation read as the ASCII it stands for (`\\frac`, `\\sqrt`, Greek letters,
/// `\\sum`, `\\int`, ...): the part of this parser that only LaTeX input reaches.
#[path = "parse_latex.rs"]
mod latex_input;

/// The name of the call a list `[a, b, ...]` parses to (only with calls,
/// [`parse_expr_with_calls`]): a vector, or a matrix when the items are rows.
pub const LIST: &str = "[]";

/// Names of mathematical functions that the exact grammar does not have: `exp (x)` stays the
/// error "unknown function" with a space too, never the product of a variable `exp` and `x`.
const FUNCTION_LIKE_NAMES: &[&str] = &[
    "abs", "acos", "acosh", "arccos", "arcosh", "arcsin", "arctan", "arsinh", "artanh", "asin",
    "asinh", "atan", "atan2", "atanh", "cbrt", "ceil", "cosh", "cot", "csc", "erf", "erfc", "exp",
    "exp2", "expm1", "floor", "gamma", "hypot", "lg", "ln", "log", "log10", "log1p", "log2", "max",
    "min", "mod", "pow", "sec", "sgn", "sign", "sinh", "tanh",
];

// ------------------------------------------------------------------------------ lexer

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tok {
    Num,
    Ident,
    Plus,
    Minus,
    Star,
    Slash,
    Caret,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Comma,
    /// `°`: degrees, a postfix meaning `* pi/180`.
    Degree,
    /// `π`: the constant pi, a token of its own (`2πr` is `2*pi*r`).
    Pi,
    /// `√`: the square root of the atom that follows (`√2`, `√(x + 1)`).
    Root,
    /// A run of superscript digits with an optional sign (`²`, `⁻¹`): an exponent.
    Superscript,
    /// `=`: only inside the limits of `\\sum_{k=1}` and between the sides of an equation.
    Equals,
    /// LaTeX `{`: grouping.
    LBrace,
    /// LaTeX `}`.
    RBrace,
    /// `|`: a bar of an absolute value `|E|`.
    Bar,
    /// `!`: the factorial of the atom before it.
    Bang,
    /// LaTeX `_` that does not belong to a name (`\\sum_`, `\\int_`).
    Underscore,
    /// A LaTeX command other than a name, an operator or a delimiter (`\\frac`, `\\sin`).
    Command,
    End,
    Bad(char),
}

#[derive(Clone, Copy, Debug)]
struct Token {
    tok: Tok,
    start: usize,
    end: usize,
}

const EXPECT_OPERAND: &str = "a number, a variable or '('";
const EXPECT_EXPONENT: &str = "an integer exponent (a number, a sign or '(')";

struct Parser<'a> {
    src: &'a str,
    cur: Token,
    depth: usize,
    /// Whether `name(arg, ...)` is read as an [`ExprKind::Call`] ([`parse_expr_with_calls`]).
    calls: bool,
    /// Whether the text is LaTeX (it has a `\\`, `{`, `}` or `$`): adjacent letters are a
    /// product, and commands are read.
    latex: bool,
    /// How many integrands are open: inside one, a juxtaposed `d` starts the differential.
    integrand: usize,
    /// How many absolute values `|..|` are open at this level of parentheses: inside one, a
    /// `|` after an operand closes it.
    bars: usize,
    /// How many LaTeX norms `\|v\|` are open: inside one, `\|` closes it.
    norms: usize,
}

/// The product a `*` token spells: `\cdot`, `·`, `⋅` are [`MulOp::Dot`], `\times`, `×`
/// [`MulOp::Cross`] (the dot and cross products between vectors), anything else `*`.
fn product_operator(text: &str) -> MulOp {
    match text {
        "\\cdot" | "\u{b7}" | "\u{22c5}" => MulOp::Dot,
        "\\times" | "\u{d7}" => MulOp::Cross,
        _ => MulOp::Times,
    }
}

impl<'a> Parser<'a> {
    fn new(src: &'a str, calls: bool, latex: bool) -> Self {
        let mut p = Parser {
            src,
            calls,
            latex,
            integrand: 0,
            bars: 0,
            norms: 0,
            cur: Token {
                tok: Tok::End,
                start: 0,
                end: 0,
            },
            depth: 0,
        };
        p.cur = p.lex(0);
        p
    }

    /// The token starting at or after byte `at` (skipping white space).
    fn lex(&self, at: usize) -> Token {
        let at = if self.latex {
            latex_input::skip_spacing(self.src, at)
        } else {
            at
        };
        let rest = &self.src[at..];
        let Some((off, ch)) = rest.char_indices().find(|(_, c)| !c.is_whitespace()) else {
            return Token {
                tok: Tok::End,
                start: self.src.len(),
                end: self.src.len(),
            };
        };
        let start = at + off;
        if self.latex {
            if let Some(t) = self.lex_latex(start) {
                return t;
            }
        }
        let bytes = self.src.as_bytes();
        let run = |mut i: usize, ok: fn(u8) -> bool| {
            while i < bytes.len() && ok(bytes[i]) {
                i += 1;
            }
            i
        };
        let (tok, end) = match ch {
            '0'..='9' => {
                let mut end = run(start, |b| b.is_ascii_digit());
                if end + 1 < bytes.len() && bytes[end] == b'.' && bytes[end + 1].is_ascii_digit() {
                    end = run(end + 1, |b| b.is_ascii_digit());
                }
                // A decimal exponent: `e`/`E`, an optional sign, at least one digit. Otherwise
                // the `e` starts a name (`2e` = 2*e).
                if end < bytes.len() && matches!(bytes[end], b'e' | b'E') {
                    let mut d = end + 1;
                    if d < bytes.len() && matches!(bytes[d], b'+' | b'-') {
                        d += 1;
                    }
                    if d < bytes.len() && bytes[d].is_ascii_digit() {
                        end = run(d, |b| b.is_ascii_digit());
                    }
                }
                (Tok::Num, end)
            }
            'A'..='Z' | 'a'..='z' | '_' => (
                Tok::Ident,
                run(start, |b| b.is_ascii_alphanumeric() || b == b'_'),
            ),
            '+' => (Tok::Plus, start + 1),
            '-' => (Tok::Minus, start + 1),
            '*' => (Tok::Star, start + 1),
            '/' => (Tok::Slash, start + 1),
            '^' => (Tok::Caret, start + 1),
            '(' => (Tok::LParen, start + 1),
            ')' => (Tok::RParen, start + 1),
            '[' => (Tok::LBracket, start + 1),
            ']' => (Tok::RBracket, start + 1),
            ',' => (Tok::Comma, start + 1),
            '=' => (Tok::Equals, start + 1),
            '|' => (Tok::Bar, start + 1),
            '!' => (Tok::Bang, start + 1),
            '°' => (Tok::Degree, start + '°'.len_utf8()),
            // The notation of printed mathematics, as text copied from a typeset page has it.
            '\u{2212}' => (Tok::Minus, start + ch.len_utf8()),
            '\u{b7}' | '\u{22c5}' | '\u{d7}' | '\u{2217}' => (Tok::Star, start + ch.len_utf8()),
            '\u{f7}' | '\u{2215}' => (Tok::Slash, start + ch.len_utf8()),
            'π' => (Tok::Pi, start + ch.len_utf8()),
            c if super::latex::greek_name(c).is_some() => (Tok::Ident, start + c.len_utf8()),
            '√' => (Tok::Root, start + ch.len_utf8()),
            c if superscript_value(c).is_some() => {
                let len = rest[off..]
                    .char_indices()
                    .find(|&(_, c)| superscript_value(c).is_none())
                    .map_or(rest.len() - off, |(i, _)| i);
                (Tok::Superscript, start + len)
            }
            c => (Tok::Bad(c), start + c.len_utf8()),
        };
        Token { tok, start, end }
    }

    fn bump(&mut self) {
        self.cur = self.lex(self.cur.end);
    }

    fn text(&self, t: Token) -> &'a str {
        &self.src[t.start..t.end]
    }

    fn unexpected(&self, expected: &'static str) -> ExprError {
        let t = self.cur;
        let found = match t.tok {
            Tok::End => "end of input".to_string(),
            Tok::Bad(c) => format!("character '{}'", c.escape_debug()),
            Tok::Equals => "character '='".to_string(),
            _ => format!("'{}'", self.text(t)),
        };
        ExprError::Unexpected {
            pos: t.start,
            found,
            expected,
        }
    }

    fn enter(&mut self) -> Result<(), ExprError> {
        self.depth += 1;
        limits::DEPTH
            .check_usize(self.depth)
            .map_err(|error| ExprError::Limit {
                pos: self.cur.start,
                error,
            })
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    fn parse_all(mut self) -> Result<Expr, ExprError> {
        let e = self.parse_sum()?;
        if self.cur.tok != Tok::End {
            return Err(self.unexpected("an operator or end of input"));
        }
        Ok(e)
    }

    fn parse_sum(&mut self) -> Result<Expr, ExprError> {
        let first = self.parse_product()?;
        if !matches!(self.cur.tok, Tok::Plus | Tok::Minus) {
            return Ok(first);
        }
        let pos = first.pos;
        let mut items = vec![(AddOp::Plus, first)];
        while let Tok::Plus | Tok::Minus = self.cur.tok {
            let op = if self.cur.tok == Tok::Plus {
                AddOp::Plus
            } else {
                AddOp::Minus
            };
            self.bump();
            items.push((op, self.parse_product()?));
        }
        Ok(Expr {
            kind: ExprKind::Sum(items),
            pos,
        })
    }

    /// Whether the current token can begin a factor written by juxtaposition (`2x`, `x y`,
    /// `(a+b)(a-b)`, `c^2 x^3`): implicit multiplication, binding like `*`. A number cannot:
    /// `2 3` or `x 2` is more likely a typo than a product, so it stays an error.
    fn starts_implicit_factor(&self) -> bool {
        match self.cur.tok {
            Tok::Ident => !(self.integrand > 0 && self.at_differential()),
            Tok::LParen | Tok::Pi | Tok::Root | Tok::LBrace => true,
            // Inside an open absolute value, a bar after an operand closes it (`|a b|`);
            // elsewhere it opens one (`2|x|`).
            Tok::Bar => self.bars == 0,
            // A closing bar (`\right|`) ends the absolute value instead, and `&`, `\\`,
            // `\end{..}` end a matrix entry.
            Tok::Command => !self.closes_bar() && !self.ends_matrix_entry(),
            Tok::LBracket => self.latex,
            _ => false,
        }
    }

    /// The name of an identifier token: its text, or in LaTeX the name it spells
    /// (`\\theta_{1}` is `theta_1`).
    fn ident_name(&self, t: Token) -> String {
        if self.latex || !self.text(t).is_ascii() {
            latex_input::name_of(self.text(t))
        } else {
            self.text(t).to_string()
        }
    }

    fn parse_product(&mut self) -> Result<Expr, ExprError> {
        let first = self.parse_unary()?;
        if !matches!(self.cur.tok, Tok::Star | Tok::Slash) && !self.starts_implicit_factor() {
            return Ok(first);
        }
        let pos = first.pos;
        let mut items = vec![(MulOp::Times, first)];
        loop {
            match self.cur.tok {
                Tok::Star | Tok::Slash => {
                    let op = if self.cur.tok == Tok::Star {
                        product_operator(self.text(self.cur))
                    } else {
                        MulOp::Divide
                    };
                    self.bump();
                    items.push((op, self.parse_unary()?));
                }
                // A juxtaposed factor takes no sign of its own: `x -y` stays a difference.
                _ if self.starts_implicit_factor() => {
                    items.push((MulOp::Times, self.parse_power()?))
                }
                _ => break,
            }
        }
        Ok(Expr {
            kind: ExprKind::Product(items),
            pos,
        })
    }

    /// `unary := ('-' | '+') unary | power`.
    fn parse_unary(&mut self) -> Result<Expr, ExprError> {
        self.parse_signed(Self::parse_power)
    }

    /// Signs in front of what `rest` parses: `('-' | '+') signed | rest` (unary minus and
    /// signed exponents share it).
    fn parse_signed(
        &mut self,
        rest: fn(&mut Self) -> Result<Expr, ExprError>,
    ) -> Result<Expr, ExprError> {
        self.enter()?;
        let r = match self.cur.tok {
            Tok::Minus | Tok::Plus => {
                let (pos, neg) = (self.cur.start, self.cur.tok == Tok::Minus);
                self.bump();
                self.parse_signed(rest).map(|e| {
                    if neg {
                        Expr {
                            kind: ExprKind::Neg(Box::new(e)),
                            pos,
                        }
                    } else {
                        e
                    }
                })
            }
            _ => rest(self),
        };
        self.leave();
        r
    }

    fn parse_power(&mut self) -> Result<Expr, ExprError> {
        let base = self.parse_atom(EXPECT_OPERAND)?;
        let base = self.parse_degrees(base)?;
        let base = self.parse_factorial(base)?;
        self.parse_power_tail(base)
    }

    /// `atom '!'`: the call `factorial(atom)`; `n!!` (the double factorial) is refused.
    fn parse_factorial(&mut self, atom: Expr) -> Result<Expr, ExprError> {
        if self.cur.tok != Tok::Bang {
            return Ok(atom);
        }
        self.bump();
        if self.cur.tok == Tok::Bang {
            return Err(ExprError::BadCall {
                pos: self.cur.start,
                name: "'!!'".into(),
                why: "the double factorial is not supported; the factorial of a factorial is \
                      written (n!)!"
                    .into(),
            });
        }
        let pos = atom.pos;
        Ok(Expr {
            kind: ExprKind::Call("factorial".into(), vec![atom]),
            pos,
        })
    }

    /// `atom '°'`: the angle in degrees as the product `atom * pi / 180`.
    fn parse_degrees(&mut self, atom: Expr) -> Result<Expr, ExprError> {
        if self.cur.tok != Tok::Degree {
            return Ok(atom);
        }
        let at = self.cur.start;
        self.bump();
        let pos = atom.pos;
        Ok(Expr {
            kind: ExprKind::Product(vec![
                (MulOp::Times, atom),
                (
                    MulOp::Times,
                    Expr {
                        kind: ExprKind::Var(PI.to_string()),
                        pos: at,
                    },
                ),
                (
                    MulOp::Divide,
                    Expr {
                        kind: ExprKind::Number(Rational::from_integer(180)),
                        pos: at,
                    },
                ),
            ]),
            pos,
        })
    }

    /// `'^' exponent` after `base`, or a superscript exponent (`x²`, `x⁻¹`), if present.
    fn parse_power_tail(&mut self, base: Expr) -> Result<Expr, ExprError> {
        let exp = match self.cur.tok {
            Tok::Caret => {
                self.bump();
                self.parse_exponent()?
            }
            Tok::Superscript => {
                let t = self.cur;
                self.bump();
                superscript_exponent(self.text(t), t.start)?
            }
            _ => return Ok(base),
        };
        Ok(power(base, exp))
    }

    /// `exponent := ('-' | '+') exponent | atom ('^' exponent)?`.
    fn parse_exponent(&mut self) -> Result<Expr, ExprError> {
        self.parse_signed(|p| {
            let base = p.parse_atom(EXPECT_EXPONENT)?;
            if p.cur.tok == Tok::Bang {
                return Err(ExprError::BadCall {
                    pos: p.cur.start,
                    name: "'!'".into(),
                    why: "a factorial in an exponent is ambiguous: write 2^(n!) or (2^n)!".into(),
                });
            }
            p.parse_power_tail(base)
        })
    }

    fn parse_atom(&mut self, expected: &'static str) -> Result<Expr, ExprError> {
        let t = self.cur;
        match t.tok {
            Tok::Num => {
                let q = number_value(self.text(t), t.start)?;
                self.bump();
                Ok(Expr {
                    kind: ExprKind::Number(q),
                    pos: t.start,
                })
            }
            Tok::Ident if self.ident_name(t) == "sqrt" => {
                self.bump();
                if self.cur.tok != Tok::LParen {
                    return Err(self.unexpected("'(' after sqrt"));
                }
                let arg = self.parse_parenthesized()?;
                Ok(Expr {
                    kind: ExprKind::Sqrt(Box::new(arg)),
                    pos: t.start,
                })
            }
            Tok::Ident => {
                self.bump();
                let name = self.ident_name(t);
                let name = name.as_str();
                // In an exponent (an integer constant), only a built-in or library function is
                // called: another name before `(` is the exponent, and the `(` starts the next
                // factor (`t^i (1-t)^(3-i)`), also with calls.
                // In LaTeX, a letter or Greek letter before `(` is a factor (`n(n+1)`): only a
                // word (`sqrt(2)`) or `\\operatorname{f}` is called.
                let latex_factor = self.latex && !latex_input::is_function_word(self.text(t));
                let known = !latex_factor
                    && (FUNCTIONS.contains(&name)
                        || (self.calls && super::library::function_names().contains(&name)));
                // `t (1 - t)`, with white space before the `(`, is a product as printed, unless
                // the name is a built-in or library function; `f(x)` is a call.
                let spaced = (self.cur.start > t.end || latex_factor)
                    && !FUNCTION_LIKE_NAMES.contains(&name);
                let call_here = if expected == EXPECT_EXPONENT {
                    known
                } else {
                    (self.calls && !spaced) || known
                };
                if self.cur.tok == Tok::LParen && call_here {
                    let args = self.parse_arguments()?;
                    return Ok(Expr {
                        kind: ExprKind::Call(name.to_string(), args),
                        pos: t.start,
                    });
                }
                // In an exponent, a name that is not a function is the exponent, and a `(`
                // after it starts the next juxtaposed factor: `t^i (1-t)^(3-i)`.
                if self.cur.tok == Tok::LParen && expected != EXPECT_EXPONENT && !spaced {
                    return Err(ExprError::UnknownFunction {
                        pos: t.start,
                        name: name.to_string(),
                    });
                }
                Ok(Expr {
                    kind: ExprKind::Var(name.to_string()),
                    pos: t.start,
                })
            }
            Tok::LParen => self.parse_parenthesized(),
            Tok::Bar => self.parse_bars(),
            Tok::LBrace => self.parse_group(),
            Tok::Command => self.parse_command(),
            // In LaTeX, brackets group like parentheses (`\\left[ .. \\right]`).
            Tok::LBracket if self.latex => self.parse_enclosed(Tok::RBracket, "an operator or ']'"),
            Tok::LBracket if self.calls => self.parse_list(),
            Tok::Pi => {
                self.bump();
                Ok(Expr {
                    kind: ExprKind::Var(PI.to_string()),
                    pos: t.start,
                })
            }
            Tok::Root => {
                self.bump();
                self.enter()?;
                let grouped = self.cur.tok == Tok::LParen;
                let arg = self.parse_atom(EXPECT_OPERAND);
                self.leave();
                let arg = arg?;
                // `√x²` is printed for both `√(x²)` and `(√x)²`, which differ for x < 0; after
                // parentheses, `√(x + 1)²`, the power is the root's.
                if !grouped && matches!(self.cur.tok, Tok::Caret | Tok::Superscript) {
                    return Err(ExprError::Unexpected {
                        pos: self.cur.start,
                        found: format!("a power after √{arg}"),
                        expected: "√ of an atom without a power: write √(x²) or (√x)²",
                    });
                }
                Ok(Expr {
                    kind: ExprKind::Sqrt(Box::new(arg)),
                    pos: t.start,
                })
            }
            _ => Err(self.unexpected(expected)),
        }
    }

    /// `'(' sum (',' sum)* ')'`, the current token being `(`: the arguments of a call.
    fn parse_arguments(&mut self) -> Result<Vec<Expr>, ExprError> {
        self.enter()?;
        let args = self.inner_level(Self::parse_argument_list);
        self.leave();
        args
    }

    fn parse_argument_list(&mut self) -> Result<Vec<Expr>, ExprError> {
        self.bump();
        let mut args = vec![self.parse_sum()?];
        loop {
            match self.cur.tok {
                Tok::Comma => {
                    self.bump();
                    args.push(self.parse_sum()?);
                }
                Tok::RParen => {
                    self.bump();
                    return Ok(args);
                }
                _ => return Err(self.unexpected("an operator, ',' or ')'")),
            }
        }
    }

    /// `'[' sum (',' sum)* ']'`, the current token being `[`: a list (a vector, or a matrix of
    /// rows), the call [`LIST`] for the library to resolve.
    fn parse_list(&mut self) -> Result<Expr, ExprError> {
        self.enter()?;
        let open = self.cur.start;
        self.bump();
        let mut items = Vec::new();
        let r = loop {
            match self.inner_level(Self::parse_sum) {
                Ok(e) => items.push(e),
                Err(e) => break Err(e),
            }
            match self.cur.tok {
                Tok::Comma => self.bump(),
                Tok::RBracket => {
                    self.bump();
                    break Ok(());
                }
                _ => break Err(self.unexpected("an operator, ',' or ']'")),
            }
        };
        self.leave();
        r?;
        Ok(Expr {
            kind: ExprKind::Call(LIST.to_string(), items),
            pos: open,
        })
    }

    /// `parse` at a new level of parentheses, braces, bars or arguments: a `d` there is a factor,
    /// not the differential of an integral, and a `|` there does not close a bar opened outside.
    pub(super) fn inner_level<T>(
        &mut self,
        parse: impl FnOnce(&mut Self) -> Result<T, ExprError>,
    ) -> Result<T, ExprError> {
        let integrand = std::mem::take(&mut self.integrand);
        let bars = std::mem::take(&mut self.bars);
        let r = parse(self);
        self.integrand = integrand;
        self.bars = bars;
        r
    }

    /// `'|' sum '|'`, the current token being the opening bar: `abs(sum)` (module
    /// documentation of [`super`] for the rule of the bars). A closing bar followed by a factor
    /// written without an operator, with two or more bars after it at this level than the open
    /// ones need, is refused: `|a|b|c|` is both `|a|*b*|c|` and `|a*|b|*c|`.
    fn parse_bars(&mut self) -> Result<Expr, ExprError> {
        self.enter()?;
        let open = self.cur.start;
        self.bump();
        let outer = self.bars;
        let inner = self.inner_level(|p| {
            p.bars = outer + 1;
            p.parse_sum()
        });
        self.leave();
        let inner = inner?;
        let bad = |pos: usize, why: &str| ExprError::BadCall {
            pos,
            name: "'|'".into(),
            why: why.into(),
        };
        if self.cur.tok != Tok::Bar {
            return Err(bad(
                open,
                "the absolute value opened here is not closed by '|' (or a bar after an operand \
                 inside parentheses does not close a bar opened outside them)",
            ));
        }
        let close = self.cur.start;
        self.bump();
        let juxtaposed =
            matches!(
                self.cur.tok,
                Tok::Ident | Tok::Num | Tok::LParen | Tok::Bar | Tok::Pi | Tok::Root | Tok::LBrace
            ) || (self.cur.tok == Tok::Command && !self.closes_bar() && !self.ends_matrix_entry());
        if juxtaposed && bars_ahead(&self.src[close + 1..]) >= self.bars + 2 {
            return Err(bad(
                close,
                "ambiguous bars: |a|b|c| is |a|*b*|c| or |a*|b|*c|; write the operator after \
                 the closing bar (|a|*b) or use abs(..)",
            ));
        }
        // In LaTeX, bars around a matrix are its determinant.
        if self.latex && latex_input::is_matrix_literal(&inner) {
            return Ok(latex_input::determinant(inner, open));
        }
        Ok(Expr {
            kind: ExprKind::Call(ABS.to_string(), vec![inner]),
            pos: open,
        })
    }

    /// `'(' sum ')'`, the current token being `(`.
    /// The expression's position becomes that of the `(`.
    fn parse_parenthesized(&mut self) -> Result<Expr, ExprError> {
        self.parse_enclosed(Tok::RParen, "an operator or ')'")
    }

    /// `'{' sum '}'`, the current token being `{`: a LaTeX group.
    fn parse_group(&mut self) -> Result<Expr, ExprError> {
        self.parse_enclosed(Tok::RBrace, "an operator or '}'")
    }

    /// The opening token, a sum, then `close`; the position of the opening token.
    fn parse_enclosed(&mut self, close: Tok, expected: &'static str) -> Result<Expr, ExprError> {
        self.enter()?;
        let open = self.cur.start;
        self.bump();
        let inner = self.inner_level(Self::parse_sum);
        self.leave();
        let inner = inner?;
        if self.cur.tok != close {
            return Err(self.unexpected(expected));
        }
        self.bump();
        Ok(Expr { pos: open, ..inner })
    }
}

/// The number of bars `|` in `rest` at its level of parentheses, brackets and braces (up to
/// the first unmatched closing one).
fn bars_ahead(rest: &str) -> usize {
    let mut depth = 0usize;
    let mut bars = 0;
    for c in rest.chars() {
        match c {
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' | ',' if depth == 0 => break,
            ')' | ']' | '}' => depth -= 1,
            '|' if depth == 0 => bars += 1,
            _ => {}
        }
    }
    bars
}

/// `base ^ exp`; a half-integer constant exponent, as printed (`(1 + t^2)^(3/2)`, `x^0.5`), is a
/// power of the square root: `sqrt(base)^n` for the exponent n/2.
fn power(base: Expr, exp: Expr) -> Expr {
    let pos = base.pos;
    if let Ok(q) = exp.eval_constant::<Rational>() {
        if q.denom() == BigInt::from(2) {
            let root = Expr {
                kind: ExprKind::Sqrt(Box::new(base)),
                pos,
            };
            if q.numer() == BigInt::from(1) {
                return root;
            }
            let mut n = Expr::number(Rational::from(q.numer()));
            n.pos = exp.pos;
            if let ExprKind::Neg(inner) = &mut n.kind {
                inner.pos = exp.pos;
            }
            return Expr {
                kind: ExprKind::Pow(Box::new(root), Box::new(n)),
                pos,
            };
        }
    }
    Expr {
        kind: ExprKind::Pow(Box::new(base), Box::new(exp)),
        pos,
    }
}

/// The value of a superscript digit, or the sign of a superscript sign (as `-1` and `-2`).
fn superscript_value(c: char) -> Option<i8> {
    Some(match c {
        '⁰' => 0,
        '¹' => 1,
        '²' => 2,
        '³' => 3,
        '⁴' => 4,
        '⁵' => 5,
        '⁶' => 6,
        '⁷' => 7,
        '⁸' => 8,
        '⁹' => 9,
        '⁻' => -1,
        '⁺' => -2,
        _ => return None,
    })
}

/// The exponent a run of superscripts denotes (`²` is 2, `⁻¹` is -1): an optional sign, then
/// digits.
fn superscript_exponent(text: &str, pos: usize) -> Result<Expr, ExprError> {
    let mut digits = String::new();
    let mut negative = false;
    for (i, c) in text.char_indices() {
        match superscript_value(c) {
            Some(d @ 0..=9) => digits.push(char::from(b'0' + d as u8)),
            Some(sign) if i == 0 && digits.is_empty() => negative = sign == -1,
            _ => {
                return Err(ExprError::Unexpected {
                    pos: pos + i,
                    found: format!("the superscript {text}"),
                    expected: "a superscript exponent: digits after an optional sign (x², x⁻¹)",
                })
            }
        }
    }
    if digits.is_empty() {
        return Err(ExprError::Unexpected {
            pos,
            found: format!("the superscript {text}"),
            expected: "a superscript exponent: digits after an optional sign (x², x⁻¹)",
        });
    }
    let n = Expr {
        kind: ExprKind::Number(number_value(&digits, pos)?),
        pos,
    };
    Ok(if negative {
        Expr {
            kind: ExprKind::Neg(Box::new(n)),
            pos,
        }
    } else {
        n
    })
}

/// The exact value of a number token (`12`, `0.25`, `2.5e-3`), within the `digits` limit (the
/// digits written plus the absolute value of the decimal exponent) and the `constant-bits` limit.
fn number_value(text: &str, pos: usize) -> Result<Rational, ExprError> {
    let limit = |error| ExprError::Limit { pos, error };
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(k) => (&text[..k], Some(&text[k + 1..])),
        None => (text, None),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let written = (int.len() + frac.len()) as u64;
    // The lexer gives an optional sign and at least one digit; an exponent beyond i64 is far
    // beyond any limit.
    let e10: i64 = match exponent {
        None => 0,
        Some(e) => e.parse().map_err(|_| {
            limit(limits::DIGITS.exceeded(format!("more than {}", i64::MAX.unsigned_abs())))
        })?,
    };
    limits::DIGITS
        .check(written.saturating_add(e10.unsigned_abs()))
        .map_err(limit)?;
    // The value is digits * 10^(e10 - frac.len()); every decimal digit is more than 3.3 bits,
    // so a literal with more digits than the size limit allows is refused before it is
    // converted.
    let max_bits = limits::CONSTANT_BITS.get();
    let too_large = || limit(limits::CONSTANT_BITS.exceeded(format!("more than {max_bits}")));
    let all = format!("{int}{frac}");
    let significant = all.trim_start_matches('0');
    let scale = e10 - frac.len() as i64;
    let max_digits = (max_bits as f64 / std::f64::consts::LOG2_10) as u64 + 1;
    if (significant.len() as u64).saturating_add(scale.unsigned_abs()) > max_digits {
        return Err(too_large());
    }
    if significant.is_empty() {
        return Ok(Rational::ZERO);
    }
    let m: BigUint = significant
        .parse()
        .expect("a number token is a non-empty string of decimal digits");
    let m = BigInt::from(m);
    let p = BigInt::from(10u32).pow(u32::try_from(scale.unsigned_abs()).map_err(|_| too_large())?);
    let q = if scale >= 0 {
        Rational::from(m * p)
    } else {
        Rational::from(num_rational::BigRational::new(m, p))
    };
    check_constant(&q, pos)?;
    Ok(q)
}

/// Parses an expression to its AST.
///
/// # Errors
/// [`ExprError::Unexpected`] for text that does not fit the grammar, [`ExprError::Limit`]
/// beyond the `depth` limit of nesting or the `digits` or `constant-bits` limit of a number.
pub fn parse_expr(text: &str) -> Result<Expr, ExprError> {
    let (src, latex) = latex_input::prepare(text);
    let e = Parser::new(&src, false, latex).parse_all()?;
    // LaTeX writes some library functions without their names (`\det`, a matrix
    // environment, bars around a matrix, a bold name): this grammar has no calls for them.
    match latex.then(|| library_call(&e)).flatten() {
        Some((name, pos)) => Err(ExprError::UnknownFunction { pos, name }),
        None => Ok(e),
    }
}

/// The first call in `e` (in reading order) of a function this grammar does not call (not
/// one of [`FUNCTIONS`]), with its position.
fn library_call(e: &Expr) -> Option<(String, usize)> {
    if let ExprKind::Call(name, _) = &e.kind {
        if !FUNCTIONS.contains(&name.as_str()) {
            return Some((name.clone(), e.pos));
        }
    }
    let mut found = None;
    let _ = e.try_map_children(|x| match library_call(x) {
        Some(hit) => {
            found = Some(hit);
            Err(())
        }
        None => Ok(x.clone()),
    });
    found
}

/// [`parse_expr`] for a grammar with function calls: `name(arg, ...)` (a name directly followed
/// by `(`, at least one argument, arguments separated by `,`) is an [`ExprKind::Call`], which
/// the caller resolves (the claims files define `dot`, `cross`, `bezier`, ...); `sqrt(x)` stays
/// [`ExprKind::Sqrt`]. The conversions of this module ([`Expr::to_poly`],
/// [`Expr::eval_constant`]) refuse a call that is left unresolved.
///
/// # Errors
/// As [`parse_expr`].
pub fn parse_expr_with_calls(text: &str) -> Result<Expr, ExprError> {
    let (src, latex) = latex_input::prepare(text);
    Parser::new(&src, true, latex).parse_all()
}

/// Whether `text` is read as LaTeX: it has a command, a brace or a `$` (plain text has none).
pub fn is_latex(text: &str) -> bool {
    latex_input::prepare(text).1
}

/// The two sides of an equation written as one text, `LHS = RHS`, when it has exactly one `=`
/// outside parentheses, brackets and braces (`\\sum_{k=1}^{n} k = \\frac{n(n+1)}{2}`); `None`
/// otherwise. The sides of a LaTeX text stay LaTeX.
pub fn split_equation(text: &str) -> Option<(String, String)> {
    let (src, latex) = latex_input::prepare(text);
    let mut p = Parser::new(&src, true, latex);
    let mut depth = 0usize;
    let mut at = None;
    loop {
        match p.cur.tok {
            Tok::End => break,
            Tok::LParen | Tok::LBracket | Tok::LBrace => depth += 1,
            Tok::RParen | Tok::RBracket | Tok::RBrace => depth = depth.saturating_sub(1),
            Tok::Equals if depth == 0 => {
                if at.is_some() {
                    return None;
                }
                at = Some(p.cur.start);
            }
            _ => {}
        }
        p.bump();
    }
    let at = at?;
    // A closing `$` keeps a LaTeX side LaTeX without moving its positions.
    let mark = if p.latex { "$" } else { "" };
    Some((
        format!("{}{mark}", &src[..at]),
        format!("{}{mark}", &src[at + 1..]),
    ))
}

impl FromStr for Expr {
    type Err = ExprError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        parse_expr(s)
    }
}

/// Parses an expression and expands it to a polynomial over `C`, looking variables up (and
/// adding new ones) in `vars`.
///
/// # Errors
/// Every [`ExprError`]: syntax, division by a non-constant or by zero, bad exponents, `sqrt`
/// outside the coefficient field.
pub fn parse_poly<C: Coefficient>(text: &str, vars: &mut Vars) -> Result<Poly<C>, ExprError> {
    parse_expr(text)?.to_poly(vars)
}
