//! Expressions: the one grammar for every textual number or polynomial in the workspace. A parser
//! to an AST with positions, the conversion of the AST to a [`Poly`] over any coefficient type
//! implementing [`Coefficient`], the exact evaluation of constant expressions
//! ([`Expr::eval_constant`]) and a printer.
//!
//! Every entry point reads text through [`parse_expr`]: `prove` and the claim catalogue (via
//! [`parse_poly`]), and the `FromStr` of [`Rational`], [`crate::Radical`] and
//! [`crate::ComplexRadical`] (every number string of `solve`), which parse and then evaluate the
//! constant expression exactly in their type. So `"2 sqrt(4)"`, `"1e3"` and `"(2+sqrt(2))/3"` mean
//! the same everywhere, and the limits below hold for every input. The parser is hand-written
//! recursive descent: the grammar is small, and positions, the juxtaposition rule, the lexing of
//! scientific notation and the error messages are easier to control than with a generator.
//!
//! # Syntax
//! ```text
//! sum      := product (('+' | '-') product)*
//! product  := unary (('*' | '/') unary | implicit)*
//! implicit := power                          (juxtaposition, not starting with a number)
//! unary    := ('-' | '+') unary | power
//! power    := atom ('^' exponent)?
//! exponent := ('-' | '+') exponent | atom ('^' exponent)?   (right-associative)
//! atom     := number | variable | 'sqrt' '(' sum ')' | '(' sum ')'
//! number   := [0-9]+ ('.' [0-9]+)? ([eE] [+-]? [0-9]+)?
//! variable := [A-Za-z_][A-Za-z0-9_]*          (not followed by '('; not the word sqrt)
//! ```
//! White space may appear between tokens.
//!
//! * **Numbers are exact**: a decimal is the fraction it denotes (`0.1 = 1/10`), and scientific
//!   notation is read exactly (`1e3 = 1000`, `2.5e-3 = 1/400`, `1E+5`, `5e0`). The exponent
//!   belongs to the number only when `e`/`E` follows the digits directly and is followed by an
//!   optional sign and at least one digit; otherwise `2e` is the product `2*e` of the number 2
//!   and the variable `e`, and `2e+x` is `2*e + x`.
//! * **Juxtaposition multiplies**, binding like `*`: `2x`, `2 sqrt(2)`, `x y`, `(a+b)(a-b)`,
//!   `c^2 x^3`. A juxtaposed factor takes no sign of its own (`x -y` is a difference) and may not
//!   start with a number (`2 3` and `x 2` are errors: write `*`).
//! * **Functions**: the only function is `sqrt`. A name followed by `(` is a function call, so
//!   `sin(x)` is the error `unknown function 'sin'` rather than the product `sin*(x)`; write the
//!   `*` for a product (`x*(y+1)`).
//! * `^` binds tighter than unary minus (`-x^2 = -(x^2)`) and is right-associative
//!   (`x^2^3 = x^8`). Its exponent must evaluate to an integer constant with absolute value at
//!   most [`MAX_EXPONENT`]; it may carry a sign (`2^-3 = 1/8`), but a negative exponent needs a
//!   non-zero constant base. Likewise a division is allowed only by an expression that evaluates
//!   to a non-zero constant (`3/4*x`).
//! * `sqrt(...)` takes a constant and needs a coefficient type that has the root (over
//!   [`Rational`], only of perfect squares; [`crate::Radical`] denests; [`crate::ComplexRadical`]
//!   takes the principal root).
//! * A variable in a constant context ([`Expr::eval_constant`]) is an error naming it, except
//!   the names the target type defines ([`Coefficient::named_constant`]: `i` for
//!   [`crate::ComplexRadical`]).
//!
//! # Limits
//! No input makes the parser, the conversion or the evaluation panic or allocate without bound:
//! * nesting of parentheses, signs and exponents: at most [`MAX_DEPTH`] levels;
//! * `^` exponents: `|k| <= ` [`MAX_EXPONENT`]; a variable's exponent must fit in `u32`;
//! * the decimal exponent of a number: `|e| <= ` [`MAX_DECIMAL_EXPONENT`];
//! * every constant (a number, a folded constant, a polynomial coefficient) has at most
//!   [`MAX_CONSTANT_BITS`] bits. Powers are **predicted** before they are computed (the size of
//!   `c^k` is at least `k` times that of `c`, [`Coefficient::size_bits`]), and every product
//!   and power is checked after it is computed, so no intermediate result exceeds about twice the
//!   limit: `((2^10000)^10000)^10000` is refused at once.
//!
//! # Conversion
//! [`Expr::to_poly`] expands bottom-up with the fast polynomial arithmetic of [`crate::poly`]:
//! sums are added pairwise (balanced), the factors of a product multiplied smallest first with
//! the constant factors folded into one scalar, powers by binary powering. Variables are looked
//! up (and added) in a [`Vars`] table, in order of first appearance. [`Expr::eval_constant`]
//! evaluates a constant expression in any [`Coefficient`] type with the same rules and limits.
//!
//! # Errors
//! Every error is an [`ExprError`] with the byte position of the offending token or
//! sub-expression, e.g. `unexpected ')' at 14: expected a number, a variable or '('`.

use crate::poly::{Poly, Vars};
use crate::rational::Rational;
use exactcheck_core::{binomial, Ring};
use num_bigint::{BigInt, BigUint};
use num_traits::{Signed, ToPrimitive};
use std::fmt;
use std::str::FromStr;

/// The deepest nesting of parentheses, signs and exponents the parser accepts.
pub const MAX_DEPTH: usize = 256;

/// The largest absolute value of an exponent after `^`.
pub const MAX_EXPONENT: u32 = 10_000;

/// The largest absolute value of the decimal exponent of a number (`1e100000`).
pub const MAX_DECIMAL_EXPONENT: u32 = 100_000;

/// The largest size in bits of any constant: a number, a folded constant expression, or a
/// coefficient of a polynomial built by [`Expr::to_poly`] (about 301,000 decimal digits).
pub const MAX_CONSTANT_BITS: u64 = 1_000_000;

// ------------------------------------------------------------------------------ coefficients

/// What the conversion needs of a coefficient type: the image of a rational number, inverses (for
/// division by constants) and square roots (for `sqrt`).
///
/// Implemented here for [`Rational`]; a square-root field or a finite field implements it beside
/// its definition (`impl exactcheck_exact::expr::Coefficient for ...`).
pub trait Coefficient: Ring {
    /// The image of a rational number, `None` if it has none (e.g. a denominator divisible by the
    /// characteristic).
    fn from_rational(q: &Rational) -> Option<Self>;
    /// The inverse, `None` for zero (or any non-invertible element).
    fn try_inverse(&self) -> Option<Self>;
    /// A square root in the type, `None` if there is none.
    fn try_sqrt(&self) -> Option<Self>;
    /// Appended to the error message when [`Coefficient::try_sqrt`] fails (e.g. which field
    /// would have the root); empty by default.
    fn sqrt_hint() -> &'static str {
        ""
    }
    /// A lower bound for the size in bits of the value that grows linearly under powers:
    /// `size_bits(x^k) >= k * size_bits(x)` (for a rational `n/d`,
    /// `floor(log2 |n|) + floor(log2 d)`; 0 for zero and units such as `±1`). The size limit
    /// [`MAX_CONSTANT_BITS`] predicts powers with it and checks results against it. The default,
    /// 0, suits types of fixed size (a finite field), which need no limit.
    fn size_bits(&self) -> u64 {
        0
    }
    /// Whether [`Coefficient::size_bits`] is at most `max`; a type may answer faster than by
    /// computing the size (every coefficient of every product is checked).
    fn size_within(&self, max: u64) -> bool {
        self.size_bits() <= max
    }
    /// The value of a name in a constant expression ([`Expr::eval_constant`]), `None` for a name
    /// the type does not define (the default: every name). [`crate::ComplexRadical`] defines `i`.
    fn named_constant(_name: &str) -> Option<Self> {
        None
    }
}

/// `floor(log2 |n|)`, 0 for zero.
pub(crate) fn log2_floor(n: &BigInt) -> u64 {
    n.bits().saturating_sub(1)
}

impl Coefficient for Rational {
    fn from_rational(q: &Rational) -> Option<Self> {
        Some(q.clone())
    }
    fn try_inverse(&self) -> Option<Self> {
        self.recip().ok()
    }
    /// The non-negative root of a rational whose numerator and denominator are perfect squares.
    fn try_sqrt(&self) -> Option<Self> {
        let (n, d) = (self.numer(), self.denom());
        if n.is_negative() {
            return None;
        }
        let (rn, rd) = (n.sqrt(), d.sqrt());
        if &rn * &rn == n && &rd * &rd == d {
            Some(Rational::from(num_rational::BigRational::new(rn, rd)))
        } else {
            None
        }
    }
    fn sqrt_hint() -> &'static str {
        " (it is irrational: a radical coefficient field is needed)"
    }
    fn size_bits(&self) -> u64 {
        log2_floor(&self.numer()) + log2_floor(&self.denom())
    }
    /// Inline values (two machine words) are far below any limit used here.
    fn size_within(&self, max: u64) -> bool {
        (self.is_inline() && max >= 256) || self.size_bits() <= max
    }
}

// ------------------------------------------------------------------------------ AST

/// `+` or `-` in a sum.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AddOp {
    /// Addition.
    Plus,
    /// Subtraction.
    Minus,
}

/// `*` or `/` in a product.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MulOp {
    /// Multiplication.
    Times,
    /// Division (by a non-zero constant).
    Divide,
}

/// A parsed expression: a node and the byte position where it starts in the source.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What the node is.
    pub kind: ExprKind,
    /// The byte offset of its first token in the source (0 for built nodes, if one likes).
    pub pos: usize,
}

/// The kinds of [`Expr`] nodes. Sums and products are n-ary, so long chains stay shallow.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A number (the parser produces non-negative integers and decimals).
    Number(Rational),
    /// A variable by name.
    Var(String),
    /// Unary minus.
    Neg(Box<Expr>),
    /// `t_0 op_1 t_1 op_2 t_2 ...`; the first operator applies to the first term (the parser
    /// always gives `Plus` there).
    Sum(Vec<(AddOp, Expr)>),
    /// `f_0 op_1 f_1 ...`; the first operator applies to the first factor (`Divide` there means
    /// `1 / f_0`; the parser always gives `Times`).
    Product(Vec<(MulOp, Expr)>),
    /// `base ^ exponent`.
    Pow(Box<Expr>, Box<Expr>),
    /// `sqrt(arg)`.
    Sqrt(Box<Expr>),
}

impl Expr {
    /// A node at position 0 (for building expressions in code).
    pub fn new(kind: ExprKind) -> Self {
        Expr { kind, pos: 0 }
    }
}

// ------------------------------------------------------------------------------ errors

/// An error of parsing or converting an expression, with the byte position it refers to.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ExprError {
    /// A token that does not fit the grammar.
    #[error("unexpected {found} at {pos}: expected {expected}")]
    Unexpected {
        /// Byte position of the token.
        pos: usize,
        /// The token, quoted (or `end of input`).
        found: String,
        /// What would have fitted.
        expected: &'static str,
    },
    /// Division by an expression that is not constant.
    #[error("division by a non-constant expression at {pos}")]
    NonConstantDivisor {
        /// Byte position of the divisor.
        pos: usize,
    },
    /// Division by an expression that evaluates to zero.
    #[error("division by zero at {pos}")]
    DivisionByZero {
        /// Byte position of the divisor.
        pos: usize,
    },
    /// An exponent that is not a non-negative integer constant.
    #[error("exponent at {pos} must be a non-negative integer constant, found {found}")]
    BadExponent {
        /// Byte position of the exponent.
        pos: usize,
        /// The exponent (its expression, or its value).
        found: String,
    },
    /// An exponent whose absolute value exceeds [`MAX_EXPONENT`].
    #[error("exponent {exponent} at {pos} is too large (absolute value at most {max})")]
    ExponentTooLarge {
        /// Byte position of the exponent.
        pos: usize,
        /// Its value.
        exponent: String,
        /// The limit, [`MAX_EXPONENT`].
        max: u32,
    },
    /// A negative exponent of a base that is not a non-zero constant.
    #[error(
        "negative exponent at {pos}: only a non-zero constant can be raised to a negative power"
    )]
    NegativeExponent {
        /// Byte position of the exponent.
        pos: usize,
    },
    /// A name followed by `(` that is not a known function.
    #[error(
        "unknown function '{name}' at {pos}: the only function is sqrt (write '{name}*(...)' \
         for a product)"
    )]
    UnknownFunction {
        /// Byte position of the name.
        pos: usize,
        /// The name.
        name: String,
    },
    /// A variable where a constant is required ([`Expr::eval_constant`]).
    #[error("variable '{name}' at {pos} where a constant number is expected{hint}")]
    NotConstant {
        /// Byte position of the variable.
        pos: usize,
        /// Its name.
        name: String,
        /// A hint for names that are constants elsewhere (`i`).
        hint: &'static str,
    },
    /// A number whose decimal exponent exceeds [`MAX_DECIMAL_EXPONENT`] in absolute value.
    #[error(
        "decimal exponent {exponent} at {pos} is out of range (absolute value at most {max}, \
         MAX_DECIMAL_EXPONENT)"
    )]
    DecimalExponentTooLarge {
        /// Byte position of the number.
        pos: usize,
        /// The exponent as written.
        exponent: String,
        /// The limit, [`MAX_DECIMAL_EXPONENT`].
        max: u32,
    },
    /// A constant (a number, a folded constant or a polynomial coefficient) that would exceed
    /// [`MAX_CONSTANT_BITS`] bits.
    #[error("constant too large at {pos}: more than {max} bits (limit MAX_CONSTANT_BITS)")]
    ConstantTooLarge {
        /// Byte position of the number, product or power.
        pos: usize,
        /// The limit, [`MAX_CONSTANT_BITS`].
        max: u64,
    },
    /// A power or product whose exponents would exceed `u32::MAX`.
    #[error("exponent overflow at {pos}: a variable's exponent would exceed {max}", max = u32::MAX)]
    ExponentOverflow {
        /// Byte position of the power or product.
        pos: usize,
    },
    /// `sqrt` of an expression that is not constant.
    #[error("sqrt of a non-constant expression at {pos}")]
    NonConstantSqrt {
        /// Byte position of the argument.
        pos: usize,
    },
    /// `sqrt` of a constant whose root is not in the coefficient field.
    #[error("sqrt({arg}) at {pos} does not lie in the coefficient field{hint}")]
    NoSqrt {
        /// Byte position of the `sqrt`.
        pos: usize,
        /// The argument, printed.
        arg: String,
        /// The coefficient type's hint ([`Coefficient::sqrt_hint`]).
        hint: &'static str,
    },
    /// A number with no image in the coefficient ring.
    #[error("the number {number} at {pos} has no image in the coefficient ring")]
    Unrepresentable {
        /// Byte position of the number.
        pos: usize,
        /// The number.
        number: String,
    },
    /// Nesting deeper than [`MAX_DEPTH`].
    #[error("expression nested too deeply at {pos} (more than {max} levels)")]
    TooDeep {
        /// Byte position where the limit was hit.
        pos: usize,
        /// The limit, [`MAX_DEPTH`].
        max: usize,
    },
}

impl ExprError {
    /// The byte position the error refers to.
    pub fn position(&self) -> usize {
        match self {
            ExprError::Unexpected { pos, .. }
            | ExprError::NonConstantDivisor { pos }
            | ExprError::DivisionByZero { pos }
            | ExprError::BadExponent { pos, .. }
            | ExprError::ExponentTooLarge { pos, .. }
            | ExprError::ExponentOverflow { pos }
            | ExprError::NegativeExponent { pos }
            | ExprError::UnknownFunction { pos, .. }
            | ExprError::NotConstant { pos, .. }
            | ExprError::DecimalExponentTooLarge { pos, .. }
            | ExprError::ConstantTooLarge { pos, .. }
            | ExprError::NonConstantSqrt { pos }
            | ExprError::NoSqrt { pos, .. }
            | ExprError::Unrepresentable { pos, .. }
            | ExprError::TooDeep { pos, .. } => *pos,
        }
    }
}

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
}

impl<'a> Parser<'a> {
    fn new(src: &'a str) -> Self {
        let mut p = Parser {
            src,
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
        let rest = &self.src[at..];
        let Some((off, ch)) = rest.char_indices().find(|(_, c)| !c.is_whitespace()) else {
            return Token {
                tok: Tok::End,
                start: self.src.len(),
                end: self.src.len(),
            };
        };
        let start = at + off;
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
        if self.depth > MAX_DEPTH {
            return Err(ExprError::TooDeep {
                pos: self.cur.start,
                max: MAX_DEPTH,
            });
        }
        Ok(())
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
        matches!(self.cur.tok, Tok::Ident | Tok::LParen)
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
                        MulOp::Times
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

    fn parse_unary(&mut self) -> Result<Expr, ExprError> {
        self.enter()?;
        let r = match self.cur.tok {
            Tok::Minus | Tok::Plus => {
                let (pos, neg) = (self.cur.start, self.cur.tok == Tok::Minus);
                self.bump();
                self.parse_unary().map(|e| {
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
            _ => self.parse_power(),
        };
        self.leave();
        r
    }

    fn parse_power(&mut self) -> Result<Expr, ExprError> {
        let base = self.parse_atom(EXPECT_OPERAND)?;
        self.parse_power_tail(base)
    }

    /// `'^' exponent` after `base`, if present.
    fn parse_power_tail(&mut self, base: Expr) -> Result<Expr, ExprError> {
        if self.cur.tok != Tok::Caret {
            return Ok(base);
        }
        self.bump();
        let exp = self.parse_exponent()?;
        let pos = base.pos;
        Ok(Expr {
            kind: ExprKind::Pow(Box::new(base), Box::new(exp)),
            pos,
        })
    }

    /// `exponent := ('-' | '+') exponent | atom ('^' exponent)?`.
    fn parse_exponent(&mut self) -> Result<Expr, ExprError> {
        self.enter()?;
        let r = match self.cur.tok {
            Tok::Minus | Tok::Plus => {
                let (pos, neg) = (self.cur.start, self.cur.tok == Tok::Minus);
                self.bump();
                self.parse_exponent().map(|e| {
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
            _ => self
                .parse_atom(EXPECT_EXPONENT)
                .and_then(|e| self.parse_power_tail(e)),
        };
        self.leave();
        r
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
            Tok::Ident if self.text(t) == "sqrt" => {
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
                if self.cur.tok == Tok::LParen {
                    return Err(ExprError::UnknownFunction {
                        pos: t.start,
                        name: self.text(t).to_string(),
                    });
                }
                Ok(Expr {
                    kind: ExprKind::Var(self.text(t).to_string()),
                    pos: t.start,
                })
            }
            Tok::LParen => self.parse_parenthesized(),
            _ => Err(self.unexpected(expected)),
        }
    }

    /// `'(' sum ')'`, the current token being `(`.
    /// The expression's position becomes that of the `(`.
    fn parse_parenthesized(&mut self) -> Result<Expr, ExprError> {
        self.enter()?;
        let open = self.cur.start;
        self.bump();
        let inner = self.parse_sum();
        self.leave();
        let inner = inner?;
        if self.cur.tok != Tok::RParen {
            return Err(self.unexpected("an operator or ')'"));
        }
        self.bump();
        Ok(Expr { pos: open, ..inner })
    }
}

/// The exact value of a number token (`12`, `0.25`, `2.5e-3`), within [`MAX_DECIMAL_EXPONENT`]
/// and [`MAX_CONSTANT_BITS`].
fn number_value(text: &str, pos: usize) -> Result<Rational, ExprError> {
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(k) => (&text[..k], Some(&text[k + 1..])),
        None => (text, None),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let e10: i64 = match exponent {
        None => 0,
        Some(e) => {
            let too_large = || ExprError::DecimalExponentTooLarge {
                pos,
                exponent: e.to_string(),
                max: MAX_DECIMAL_EXPONENT,
            };
            let v: i64 = e.parse().map_err(|_| too_large())?;
            if v.unsigned_abs() > u64::from(MAX_DECIMAL_EXPONENT) {
                return Err(too_large());
            }
            v
        }
    };
    let too_large = ExprError::ConstantTooLarge {
        pos,
        max: MAX_CONSTANT_BITS,
    };
    // The value is digits * 10^(e10 - frac.len()); every decimal digit is more than 3.3 bits,
    // so a literal with more digits than the limit allows is refused before it is converted.
    let all = format!("{int}{frac}");
    let significant = all.trim_start_matches('0');
    let scale = e10 - frac.len() as i64;
    let max_digits = (MAX_CONSTANT_BITS as f64 / std::f64::consts::LOG2_10) as u64 + 1;
    if significant.len() as u64 + scale.unsigned_abs() > max_digits {
        return Err(too_large);
    }
    if significant.is_empty() {
        return Ok(Rational::ZERO);
    }
    let m: BigUint = significant
        .parse()
        .expect("a number token is a non-empty string of decimal digits");
    let m = BigInt::from(m);
    let p = BigInt::from(10u32).pow(
        u32::try_from(scale.unsigned_abs()).expect("bounded by MAX_DECIMAL_EXPONENT and digits"),
    );
    let q = if scale >= 0 {
        Rational::from(m * p)
    } else {
        Rational::from(num_rational::BigRational::new(m, p))
    };
    check_constant(&q, pos)?;
    Ok(q)
}

/// `Err(ConstantTooLarge)` when `c` has more than [`MAX_CONSTANT_BITS`] bits.
fn check_constant<C: Coefficient>(c: &C, pos: usize) -> Result<(), ExprError> {
    if !c.size_within(MAX_CONSTANT_BITS) {
        Err(ExprError::ConstantTooLarge {
            pos,
            max: MAX_CONSTANT_BITS,
        })
    } else {
        Ok(())
    }
}

/// Parses an expression to its AST.
///
/// # Errors
/// [`ExprError::Unexpected`] for text that does not fit the grammar, [`ExprError::TooDeep`]
/// beyond [`MAX_DEPTH`] levels of nesting.
pub fn parse_expr(text: &str) -> Result<Expr, ExprError> {
    Parser::new(text).parse_all()
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

// ------------------------------------------------------------------------------ conversion

impl Expr {
    /// The polynomial this expression denotes, over `C`; variables are looked up (and added) in
    /// `vars`.
    ///
    /// # Errors
    /// Division by a non-constant expression or by zero, exponents that are not integer
    /// constants (or exceed [`MAX_EXPONENT`], or overflow, or are negative on a non-constant
    /// base), `sqrt` of a non-constant or of a constant whose root is not in `C`, numbers with no
    /// image in `C`, coefficients beyond [`MAX_CONSTANT_BITS`].
    pub fn to_poly<C: Coefficient>(&self, vars: &mut Vars) -> Result<Poly<C>, ExprError> {
        match &self.kind {
            ExprKind::Number(q) => {
                C::from_rational(q)
                    .map(Poly::constant)
                    .ok_or_else(|| ExprError::Unrepresentable {
                        pos: self.pos,
                        number: q.to_string(),
                    })
            }
            ExprKind::Var(name) => Ok(Poly::var(vars.var(name))),
            ExprKind::Neg(x) => Ok(-x.to_poly::<C>(vars)?),
            ExprKind::Sum(items) => {
                let mut parts = Vec::with_capacity(items.len());
                for (op, x) in items {
                    let p = x.to_poly::<C>(vars)?;
                    parts.push(match op {
                        AddOp::Plus => p,
                        AddOp::Minus => -p,
                    });
                }
                Ok(Poly::sum(parts))
            }
            ExprKind::Product(items) => {
                let (a, b) = product_pair(items, self.pos, vars)?;
                let p = a
                    .checked_mul(&b)
                    .ok_or(ExprError::ExponentOverflow { pos: self.pos })?;
                check_coefficients(&p, self.pos)?;
                Ok(p)
            }
            ExprKind::Pow(base, exp) => {
                let k = exponent_value(exp)?;
                let b = base.to_poly::<C>(vars)?;
                if let Some(c) = b.constant_value() {
                    return Ok(Poly::constant(constant_power(c, k, self.pos, exp.pos)?));
                }
                let k =
                    u32::try_from(k).map_err(|_| ExprError::NegativeExponent { pos: exp.pos })?;
                // The coefficient of a vertex monomial of the Newton polytope of b^k is the k-th
                // power of b's, so predict with the largest coefficient before expanding.
                let largest = b.coefficients().iter().map(C::size_bits).max();
                if largest.unwrap_or(0).saturating_mul(u64::from(k)) > MAX_CONSTANT_BITS {
                    return Err(ExprError::ConstantTooLarge {
                        pos: self.pos,
                        max: MAX_CONSTANT_BITS,
                    });
                }
                let p = b
                    .checked_pow(k)
                    .ok_or(ExprError::ExponentOverflow { pos: self.pos })?;
                check_coefficients(&p, self.pos)?;
                Ok(p)
            }
            ExprKind::Sqrt(arg) => {
                let p = arg.to_poly::<C>(vars)?;
                let c = p
                    .constant_value()
                    .ok_or(ExprError::NonConstantSqrt { pos: arg.pos })?;
                sqrt_of(c, self.pos, arg).map(Poly::constant)
            }
        }
    }

    /// The exact value of a constant expression in `C`: numbers, `sqrt`, `+ - * /` and integer
    /// powers, with the limits of the module documentation. A name is looked up with
    /// [`Coefficient::named_constant`] (`i` for [`crate::ComplexRadical`]); any other variable
    /// is an error naming it and its position.
    ///
    /// ```
    /// use exactcheck_exact::{expr::parse_expr, Radical, Rational};
    ///
    /// let q: Rational = parse_expr("2.5e-3 + 1/2^2").unwrap().eval_constant().unwrap();
    /// assert_eq!(q, Rational::new(101, 400).unwrap());
    /// let r: Radical = parse_expr("2 sqrt(8)").unwrap().eval_constant().unwrap();
    /// assert_eq!(r.to_string(), "4*sqrt(2)");
    /// let e = parse_expr("1 + x").unwrap().eval_constant::<Rational>().unwrap_err();
    /// assert_eq!(e.to_string(), "variable 'x' at 4 where a constant number is expected");
    /// ```
    ///
    /// # Errors
    /// A variable, division by zero, a bad exponent, a square root not in `C`, a number with no
    /// image in `C`, a constant beyond [`MAX_CONSTANT_BITS`].
    pub fn eval_constant<C: Coefficient>(&self) -> Result<C, ExprError> {
        match &self.kind {
            ExprKind::Number(q) => C::from_rational(q).ok_or_else(|| ExprError::Unrepresentable {
                pos: self.pos,
                number: q.to_string(),
            }),
            ExprKind::Var(name) => C::named_constant(name).ok_or_else(|| ExprError::NotConstant {
                pos: self.pos,
                name: name.clone(),
                hint: if name == "i" {
                    " (the imaginary unit i exists only for complex numbers)"
                } else {
                    ""
                },
            }),
            ExprKind::Neg(x) => Ok(-x.eval_constant::<C>()?),
            ExprKind::Sum(items) => {
                let mut acc = C::zero();
                for (op, x) in items {
                    let v = x.eval_constant::<C>()?;
                    match op {
                        AddOp::Plus => acc += v,
                        AddOp::Minus => acc -= v,
                    }
                    check_constant(&acc, self.pos)?;
                }
                Ok(acc)
            }
            ExprKind::Product(items) => {
                let mut acc = C::one();
                for (op, x) in items {
                    let v = x.eval_constant::<C>()?;
                    match op {
                        MulOp::Times => acc *= v,
                        MulOp::Divide => match v.try_inverse() {
                            Some(inv) => acc *= inv,
                            None => return Err(ExprError::DivisionByZero { pos: x.pos }),
                        },
                    }
                    check_constant(&acc, self.pos)?;
                }
                Ok(acc)
            }
            ExprKind::Pow(base, exp) => {
                let k = exponent_value(exp)?;
                let b = base.eval_constant::<C>()?;
                constant_power(b, k, self.pos, exp.pos)
            }
            ExprKind::Sqrt(arg) => sqrt_of(arg.eval_constant::<C>()?, self.pos, arg),
        }
    }
}

/// The square root of the constant `c` (the value of `arg`, in `sqrt` at `pos`).
fn sqrt_of<C: Coefficient>(c: C, pos: usize, arg: &Expr) -> Result<C, ExprError> {
    c.try_sqrt().ok_or_else(|| ExprError::NoSqrt {
        pos,
        arg: arg.to_string(),
        hint: C::sqrt_hint(),
    })
}

/// `c^k` for a constant `c` and `|k| <= MAX_EXPONENT`, by binary powering with the size limit:
/// refused at once when `k * size_bits(c)` exceeds [`MAX_CONSTANT_BITS`] (a lower bound of the
/// result's size), and checked after every multiplication, so no intermediate value exceeds
/// about twice the limit. `pos` is the power's position, `exp_pos` its exponent's.
fn constant_power<C: Coefficient>(
    c: C,
    k: i64,
    pos: usize,
    exp_pos: usize,
) -> Result<C, ExprError> {
    let base = if k < 0 {
        c.try_inverse()
            .ok_or(ExprError::DivisionByZero { pos: exp_pos })?
    } else {
        c
    };
    let mut e = k.unsigned_abs();
    if base.size_bits().saturating_mul(e) > MAX_CONSTANT_BITS {
        return Err(ExprError::ConstantTooLarge {
            pos,
            max: MAX_CONSTANT_BITS,
        });
    }
    let mut acc = C::one();
    let mut sq = base;
    while e > 0 {
        if e & 1 == 1 {
            acc = acc.mul_ref(&sq);
            check_constant(&acc, pos)?;
        }
        e >>= 1;
        if e > 0 {
            sq = sq.square();
            check_constant(&sq, pos)?;
        }
    }
    Ok(acc)
}

/// `Err(ConstantTooLarge)` when a coefficient of `p` exceeds [`MAX_CONSTANT_BITS`].
fn check_coefficients<C: Coefficient>(p: &Poly<C>, pos: usize) -> Result<(), ExprError> {
    p.coefficients()
        .iter()
        .try_for_each(|c| check_constant(c, pos))
}

/// A product's value as two factors `(a, b)`, `b` the largest factor and `a` the product of the
/// others (multiplied smallest first, with the constant factors folded into the smallest).
fn product_pair<C: Coefficient>(
    items: &[(MulOp, Expr)],
    pos: usize,
    vars: &mut Vars,
) -> Result<(Poly<C>, Poly<C>), ExprError> {
    let mut scalar = C::one();
    let mut factors: Vec<Poly<C>> = Vec::new();
    for (op, x) in items {
        let p = x.to_poly::<C>(vars)?;
        match (op, p.constant_value()) {
            (MulOp::Times, Some(c)) => scalar *= c,
            (MulOp::Times, None) => factors.push(p),
            (MulOp::Divide, None) => return Err(ExprError::NonConstantDivisor { pos: x.pos }),
            (MulOp::Divide, Some(c)) => match c.try_inverse() {
                Some(inv) => scalar *= inv,
                None => return Err(ExprError::DivisionByZero { pos: x.pos }),
            },
        }
        check_constant(&scalar, pos)?;
    }
    // Smallest first; the scalar goes into the smallest factor.
    factors.sort_by_key(Poly::len);
    let Some(b) = factors.pop() else {
        return Ok((Poly::constant(scalar), Poly::one()));
    };
    let mut it = factors.into_iter();
    let Some(first) = it.next() else {
        return Ok((Poly::constant(scalar), b));
    };
    let mut a = first.scale(&scalar);
    for f in it {
        a = a
            .checked_mul(&f)
            .ok_or(ExprError::ExponentOverflow { pos })?;
        check_coefficients(&a, pos)?;
    }
    Ok((a, b))
}

/// The value of an exponent expression: an integer constant with `|k| <= MAX_EXPONENT`.
fn exponent_value(e: &Expr) -> Result<i64, ExprError> {
    let bad = |found: String| ExprError::BadExponent { pos: e.pos, found };
    let q: Rational = match e.eval_constant() {
        Ok(q) => q,
        Err(ExprError::NotConstant { .. }) => return Err(bad(e.to_string())),
        Err(err) => return Err(err),
    };
    if !q.is_integer() {
        return Err(bad(q.to_string()));
    }
    match q.numer().to_i64() {
        Some(k) if k.unsigned_abs() <= u64::from(MAX_EXPONENT) => Ok(k),
        _ => Err(ExprError::ExponentTooLarge {
            pos: e.pos,
            exponent: q.to_string(),
            max: MAX_EXPONENT,
        }),
    }
}

// ------------------------------------------------------------------------------ printing

/// Binding strength of a node when printed (higher binds tighter).
fn precedence(e: &Expr) -> u8 {
    match e.kind {
        ExprKind::Sum(_) => 1,
        ExprKind::Product(_) => 2,
        ExprKind::Neg(_) => 3,
        ExprKind::Pow(..) => 4,
        ExprKind::Number(_) | ExprKind::Var(_) | ExprKind::Sqrt(_) => 5,
    }
}

/// Writes `e`, in parentheses when it binds less tightly than `min`.
fn write_at(f: &mut fmt::Formatter<'_>, e: &Expr, min: u8) -> fmt::Result {
    if precedence(e) < min {
        write!(f, "({e})")
    } else {
        write!(f, "{e}")
    }
}

impl fmt::Display for Expr {
    /// The expression in the syntax of the module documentation, with the parentheses it needs;
    /// the output parses back to an expression with the same value.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            ExprKind::Number(q) => {
                if q.is_integer() && !q.numer().is_negative() {
                    write!(f, "{q}")
                } else {
                    write!(f, "({q})")
                }
            }
            ExprKind::Var(name) => f.write_str(name),
            ExprKind::Neg(x) => {
                f.write_str("-")?;
                write_at(f, x, 3)
            }
            ExprKind::Sum(items) => {
                for (k, (op, x)) in items.iter().enumerate() {
                    match (k, op) {
                        (0, AddOp::Plus) => {}
                        (0, AddOp::Minus) => f.write_str("-")?,
                        (_, AddOp::Plus) => f.write_str(" + ")?,
                        (_, AddOp::Minus) => f.write_str(" - ")?,
                    }
                    write_at(f, x, 2)?;
                }
                Ok(())
            }
            ExprKind::Product(items) => {
                for (k, (op, x)) in items.iter().enumerate() {
                    match (k, op) {
                        (0, MulOp::Times) => {}
                        (0, MulOp::Divide) => f.write_str("1/")?,
                        (_, MulOp::Times) => f.write_str("*")?,
                        (_, MulOp::Divide) => f.write_str("/")?,
                    }
                    write_at(f, x, 3)?;
                }
                Ok(())
            }
            ExprKind::Pow(base, exp) => {
                write_at(f, base, 5)?;
                f.write_str("^")?;
                // Right-associative: a power may stand bare as the exponent.
                match exp.kind {
                    ExprKind::Pow(..) => write!(f, "{exp}"),
                    _ => write_at(f, exp, 5),
                }
            }
            ExprKind::Sqrt(x) => write!(f, "sqrt({x})"),
        }
    }
}

// ------------------------------------------------------------------------------ workload W1

/// Workload W1 as text: Chiang's ruled-surface / plane theorem (SPEC §4), x component, as the two
/// sides of a polynomial identity in `t, a, b, c, d, px0.., py0.., pz0.., qx0.., qy0.., qz0..`,
/// exactly as `shared/anchors/w1_text.py M N` prints them:
///
/// * LHS `(N.V(t)) Bx(t) - (N.B(t) + d) Vx(t)` with the Bernstein forms written unexpanded,
///   `C(n,j)*t^j*(1-t)^(n-j)`;
/// * RHS `sum_k B_k^{m+n}(t) P_kx` with the theorem's `P_k` and `phi(m,n,i,j)` as reduced
///   fractions `p/q`.
///
/// For `(m, n) = (8, 13)` the pair is about 9.5 kB over 74 variables, and both sides expand to
/// 5,841 terms.
///
/// # Panics
/// When `m + n > 67` (binomial coefficients beyond `u64`).
pub fn w1_text(m: u32, n: u32) -> (String, String) {
    let bern = |deg: u32, i: u32| format!("{}*t^{}*(1-t)^{}", binomial(deg, i), i, deg - i);
    let dot_q = |i: u32| format!("(a*qx{i}+b*qy{i}+c*qz{i})");
    let dot_p = |j: u32| format!("(a*px{j}+b*py{j}+c*pz{j}+d)");
    let join = |v: Vec<String>| v.join("+");
    let nv = format!(
        "({})",
        join(
            (0..=m)
                .map(|i| format!("{}*{}", bern(m, i), dot_q(i)))
                .collect()
        )
    );
    let bx = format!(
        "({})",
        join((0..=n).map(|j| format!("{}*px{j}", bern(n, j))).collect())
    );
    let nb = format!(
        "({})",
        join(
            (0..=n)
                .map(|j| format!("{}*{}", bern(n, j), dot_p(j)))
                .collect()
        )
    );
    let vx = format!(
        "({})",
        join((0..=m).map(|i| format!("{}*qx{i}", bern(m, i))).collect())
    );
    let lhs = format!("{nv}*{bx}-{nb}*{vx}");
    let mut terms = Vec::new();
    for k in 0..=m + n {
        let mut inner = Vec::new();
        for i in k.saturating_sub(n)..=k.min(m) {
            let j = k - i;
            let (num, den) = (binomial(m, i) * binomial(n, j), binomial(m + n, k));
            let g = num_integer::gcd(num, den);
            inner.push(format!(
                "{}/{}*({}*px{j}-{}*qx{i})",
                num / g,
                den / g,
                dot_q(i),
                dot_p(j)
            ));
        }
        terms.push(format!("{}*({})", bern(m + n, k), join(inner)));
    }
    (lhs, join(terms))
}

// ------------------------------------------------------------------------------ tests

#[cfg(test)]
mod tests {
    use super::*;

    type P = Poly<Rational>;

    fn poly(s: &str, vars: &mut Vars) -> P {
        parse_poly(s, vars).unwrap_or_else(|e| panic!("{s:?}: {e}"))
    }

    fn err(s: &str) -> String {
        match parse_poly::<Rational>(s, &mut Vars::new()) {
            Ok(p) => panic!("{s:?} parsed to {p:?}"),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn precedence_and_associativity() {
        let mut v = Vars::new();
        let x = poly("x", &mut v);
        assert_eq!(poly("-x^2", &mut v), -x.square());
        assert_eq!(poly("x^2^3", &mut v), x.pow(8));
        assert_eq!(poly("(x^2)^3", &mut v), x.pow(6));
        assert_eq!(poly("2^3^2", &mut v), P::from_i64(512));
        assert_eq!(poly("1 - 2 - 3", &mut v), P::from_i64(-4));
        assert_eq!(poly("12/3/2", &mut v), P::from_i64(2));
        assert_eq!(poly("3/4*x*4", &mut v), x.scale_i64(3));
        assert_eq!(poly(" 0.1 * 10 ", &mut v), P::one());
        assert_eq!(poly("x^(1+1)", &mut v), x.square());
        assert_eq!(poly("x^0", &mut v), P::one());
        assert_eq!(poly("--x", &mut v), x);
        assert_eq!(poly("+x", &mut v), x);
        assert_eq!(poly("sqrt(9/4)*2", &mut v), P::from_i64(3));
        assert_eq!(poly("x/(1+1)*2", &mut v), x);
    }

    #[test]
    fn error_messages() {
        assert_eq!(
            err("(a + b) * (c))"),
            "unexpected ')' at 13: expected an operator or end of input"
        );
        assert_eq!(
            err("1 + )"),
            "unexpected ')' at 4: expected a number, a variable or '('"
        );
        assert_eq!(err("x/y"), "division by a non-constant expression at 2");
        assert_eq!(err("x/(1-1)"), "division by zero at 2");
        assert_eq!(
            err("sqrt(2)"),
            "sqrt(2) at 0 does not lie in the coefficient field (it is irrational: a radical \
             coefficient field is needed)"
        );
        assert_eq!(err("sqrt(x)"), "sqrt of a non-constant expression at 4");
        assert_eq!(
            err("sqrt + 1"),
            "unexpected '+' at 5: expected '(' after sqrt"
        );
        assert_eq!(
            err("x^-1"),
            "negative exponent at 2: only a non-zero constant can be raised to a negative power"
        );
        assert_eq!(
            err("x^*2"),
            "unexpected '*' at 2: expected an integer exponent (a number, a sign or '(')"
        );
        assert_eq!(err("0^-1"), "division by zero at 2");
        assert_eq!(
            err("x^(1/2)"),
            "exponent at 2 must be a non-negative integer constant, found 1/2"
        );
        assert_eq!(
            err("x^y"),
            "exponent at 2 must be a non-negative integer constant, found y"
        );
        assert_eq!(
            err("x^10001"),
            "exponent 10001 at 2 is too large (absolute value at most 10000)"
        );
        assert_eq!(
            err("2^-10001"),
            "exponent -10001 at 2 is too large (absolute value at most 10000)"
        );
        assert_eq!(
            err("1 # 2"),
            "unexpected character '#' at 2: expected an operator or end of input"
        );
        assert_eq!(
            err(""),
            "unexpected end of input at 0: expected a number, a variable or '('"
        );
        assert_eq!(
            err("1."),
            "unexpected character '.' at 1: expected an operator or end of input"
        );
        assert_eq!(
            err("(1"),
            "unexpected end of input at 2: expected an operator or ')'"
        );
        assert!(err(&"(".repeat(1000)).starts_with("expression nested too deeply"));
        assert!(err(&"-".repeat(1000)).starts_with("expression nested too deeply"));
        let deep_pow = format!("x{}", "^1".repeat(1000));
        assert!(err(&deep_pow).starts_with("expression nested too deeply"));
        assert!(err("((x^10000)^10000)^10000").starts_with("exponent overflow at 0"));
    }

    #[test]
    fn scientific_notation_and_juxtaposition() {
        let mut v = Vars::new();
        // Regression: "1e3" was the product 1*e3 of a variable e3, "1e5" likewise.
        assert_eq!(poly("1e3", &mut v), P::from_i64(1000));
        assert_eq!(poly("1e5", &mut v), P::from_i64(100_000));
        assert!(v.is_empty(), "no variable e3 or e5: {v:?}");
        let x = poly("x", &mut v);
        assert_eq!(poly("x + 2.5e-3", &mut v), poly("x + 0.0025", &mut v));
        assert_eq!(
            poly("2.5e-3", &mut v),
            P::constant(Rational::new(1, 400).unwrap())
        );
        assert_eq!(poly("1E+5", &mut v), P::from_i64(100_000));
        assert_eq!(poly("5e0", &mut v), P::from_i64(5));
        assert_eq!(poly("2e3x", &mut v), x.scale_i64(2000));
        // Without digits after it, `e` is a variable: 2e = 2*e, 2e+x = 2*e + x.
        let e = poly("e", &mut v);
        assert_eq!(poly("2e", &mut v), e.scale_i64(2));
        assert_eq!(poly("2e+x", &mut v), e.scale_i64(2) + x.clone());
        assert_eq!(poly("2E-x", &mut v), poly("2*E - x", &mut v));
        assert_eq!(poly("2 sqrt(4) x", &mut v), x.scale_i64(4));
        assert_eq!(poly("(x+1)(x-1)", &mut v), x.square() - P::one());
        assert_eq!(poly("2^-2*4x", &mut v), x);
        assert_eq!(
            err("1e100001"),
            "decimal exponent 100001 at 0 is out of range (absolute value at most 100000, \
             MAX_DECIMAL_EXPONENT)"
        );
        assert_eq!(
            err("1e99999999999999999999999"),
            "decimal exponent 99999999999999999999999 at 0 is out of range (absolute value at \
             most 100000, MAX_DECIMAL_EXPONENT)"
        );
        // A number may not be juxtaposed after a factor: `2 3` is a typo, not 6.
        assert_eq!(
            err("2 3"),
            "unexpected '3' at 2: expected an operator or end of input"
        );
        assert_eq!(
            err("x 2"),
            "unexpected '2' at 2: expected an operator or end of input"
        );
    }

    #[test]
    fn unknown_functions_are_errors() {
        // Regression: `sin(x)` was the product sin*x of a variable sin.
        assert_eq!(
            err("sin(x)"),
            "unknown function 'sin' at 0: the only function is sqrt (write 'sin*(...)' for a \
             product)"
        );
        assert_eq!(
            err("2 sin(2x)"),
            "unknown function 'sin' at 2: the only function is sqrt (write 'sin*(...)' for a \
             product)"
        );
        assert!(err("x (y+1)").starts_with("unknown function 'x' at 0"));
        let mut v = Vars::new();
        assert_eq!(poly("x*(y+1)", &mut v), poly("x y + x", &mut v));
    }

    #[test]
    fn constant_size_limits() {
        let too_large = "constant too large at 0: more than 1000000 bits (limit MAX_CONSTANT_BITS)";
        // Regression: this aborted the process allocating; now refused before computing.
        assert_eq!(err("((2^10000)^10000)^10000"), too_large);
        assert_eq!(err("(2^10000)^10000"), too_large);
        assert_eq!(err("(3/2^10000)^10000 x"), too_large);
        assert_eq!(err("(2^10000 x + 1)^10000"), too_large);
        // The limit is on bits: 2^999999 fits, 2^1000001 does not.
        let mut v = Vars::new();
        assert!(parse_poly::<Rational>("(2^1000)^999 * 2^999", &mut v).is_ok());
        assert!(err("(2^1000)^1000 * 2^1000").starts_with("constant too large"));
        assert!(err("(2^1000 x)^1000 * (2^1000 y)^1000").starts_with("constant too large"));
        let long = "9".repeat(301_100);
        assert!(err(&long).starts_with("constant too large at 0"));
        assert!(err("1e-100000 * 1e-100000 * 1e-100000 * 1e-100000").starts_with("constant too"));
        // The evaluator has the same limits.
        let e = parse_expr("((2^1024)^1024)^1024").unwrap();
        assert_eq!(
            e.eval_constant::<Rational>().unwrap_err().to_string(),
            too_large
        );
        // An exponent is a constant expression too, evaluated with the limits.
        assert!(err("x^((2^10000)^10000)").starts_with("constant too large at 2"));
    }

    #[test]
    fn constant_evaluation() {
        let ev = |s: &str| parse_expr(s).unwrap().eval_constant::<Rational>();
        assert_eq!(ev("3/4 - 1/4").unwrap(), Rational::new(1, 2).unwrap());
        assert_eq!(ev("(1/2)^-3 + 2^0").unwrap(), Rational::from_integer(9));
        assert_eq!(ev("2 sqrt(1e4)").unwrap(), Rational::from_integer(200));
        assert_eq!(
            ev("1 + y^2").unwrap_err().to_string(),
            "variable 'y' at 4 where a constant number is expected"
        );
        assert_eq!(
            ev("1/(2-2)").unwrap_err().to_string(),
            "division by zero at 2"
        );
        assert_eq!(
            ev("2^x").unwrap_err().to_string(),
            "exponent at 2 must be a non-negative integer constant, found x"
        );
    }

    #[test]
    fn expression_printing_round_trips() {
        for s in [
            "-x^2",
            "(a + b)*(c - d)/3",
            "x^2^3",
            "(x^2)^3",
            "-(a - b)",
            "a - -b",
            "a*-b",
            "sqrt(4)*x + 0.25",
            "2*(x + 1)^3 - 1/2*y",
            "2^-3*x + 2.5e-3",
            "(1/2)^-(1+1)",
        ] {
            let e = parse_expr(s).unwrap();
            let printed = e.to_string();
            let mut v1 = Vars::new();
            let mut v2 = Vars::new();
            let p1: P = e.to_poly(&mut v1).unwrap();
            let p2: P = parse_poly(&printed, &mut v2).unwrap();
            assert_eq!(v1, v2, "{s} -> {printed}");
            assert_eq!(p1, p2, "{s} -> {printed}");
        }
    }

    #[test]
    fn w1_text_matches_the_anchor() {
        let (lhs, rhs) = w1_text(2, 3);
        assert_eq!(
            lhs,
            "(1*t^0*(1-t)^2*(a*qx0+b*qy0+c*qz0)+2*t^1*(1-t)^1*(a*qx1+b*qy1+c*qz1)+1*t^2*(1-t)^0*\
             (a*qx2+b*qy2+c*qz2))*(1*t^0*(1-t)^3*px0+3*t^1*(1-t)^2*px1+3*t^2*(1-t)^1*px2+1*t^3*\
             (1-t)^0*px3)-(1*t^0*(1-t)^3*(a*px0+b*py0+c*pz0+d)+3*t^1*(1-t)^2*(a*px1+b*py1+c*pz1+d)\
             +3*t^2*(1-t)^1*(a*px2+b*py2+c*pz2+d)+1*t^3*(1-t)^0*(a*px3+b*py3+c*pz3+d))*(1*t^0*\
             (1-t)^2*qx0+2*t^1*(1-t)^1*qx1+1*t^2*(1-t)^0*qx2)"
        );
        assert!(rhs.starts_with("1*t^0*(1-t)^5*(1/1*((a*qx0+b*qy0+c*qz0)*px0-(a*px0+b*py0+c*pz0+d)*qx0))+5*t^1*(1-t)^4*(3/5*("));
        let (l, r) = w1_text(8, 13);
        // `w1_text.py 8 13 | wc -c` gives 9500: both lines and their newlines.
        assert_eq!(l.len() + r.len() + 2, 9500);
    }

    #[test]
    fn w1_small_identity() {
        let (lhs, rhs) = w1_text(2, 3);
        let mut v = Vars::new();
        let l = poly(&lhs, &mut v);
        let r = poly(&rhs, &mut v);
        assert_eq!(l, r);
        assert_eq!(v.len(), 26);
    }
}
