//! Parsing the exact number types from text (`FromStr` for [`Rational`], [`Radical`],
//! [`ComplexRadical`] and [`Algebraic`]): a constant expression of the one grammar, evaluated
//! exactly in the type. Kept with the grammar rather than beside each type so that the number
//! types do not depend on the expression language (which is built on them).

use super::{parse_expr, Expr, ExprError};
use crate::{Algebraic, ComplexRadical, Radical, Rational};
use std::str::FromStr;

/// The error of parsing a [`Rational`] from text: the expression error of the one grammar
/// ([`crate::expr`]), with the position of the problem. The name is kept for callers.
pub type ParseRationalError = ExprError;

impl FromStr for Rational {
    type Err = ParseRationalError;

    /// Parses a constant expression of the one grammar of [`crate::expr`] and evaluates it
    /// exactly: `-12`, `3/4`, `-0.125` (a decimal is the exact fraction it denotes), `2.5e-3`
    /// (`= 1/400`), `2^-3`, `sqrt(9/4)`; white space is allowed between tokens.
    ///
    /// # Errors
    /// A syntax error, a variable (`"a"`), division by zero, an irrational `sqrt`, or a constant
    /// beyond the limits of [`crate::expr`], each with its position.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        parse_expr(s)?.eval_constant()
    }
}

/// The error of parsing a [`Radical`] or [`ComplexRadical`]: the expression error of the one
/// grammar ([`crate::expr`]), with the position of the problem. The name is kept for callers.
///
/// ```
/// use exactcheck_exact::{ParseRadicalError as E, Radical};
///
/// let parse = |s: &str| s.parse::<Radical>().unwrap_err();
/// assert!(matches!(parse("2 * * 3"), E::Unexpected { pos: 4, .. }));
/// assert!(matches!(parse("log(1)"), E::UnknownFunction { pos: 0, .. }));
/// assert!(matches!(parse("1/(2 - 2)"), E::DivisionByZero { pos: 2 }));
/// assert!(matches!(parse("sqrt(-2)"), E::NoSqrt { pos: 0, .. }));
/// assert_eq!(
///     parse("x + 1").to_string(),
///     "variable 'x' at 0 where a constant number is expected"
/// );
/// ```
pub type ParseRadicalError = ExprError;

impl FromStr for Radical {
    type Err = ParseRadicalError;

    /// Parses a constant expression of the one grammar of [`crate::expr`] and evaluates it
    /// exactly: integers, decimals (`0.1` is exactly 1/10), scientific notation (`2.5e-3` is
    /// 1/400), `sqrt(...)` of any expression with a multi-quadratic root, `+ - * /`,
    /// juxtaposition (`2 sqrt(2)`), unary signs, parentheses and integer powers `^k`
    /// (`|k|` within the `exponent` limit) — e.g. `"1/sqrt(2)"`, `"(2+sqrt(2))/3"`,
    /// `"sqrt(3 - 2*sqrt(2))"`, `"-3/4"`.
    ///
    /// # Errors
    /// An [`ExprError`] naming the problem and its position: malformed input, a variable
    /// (including `i`: use [`ComplexRadical`]), an unknown function, division by zero, a square
    /// root not in the type (`sqrt(-1)`, `sqrt(sqrt(2))`), a constant beyond the size limit.
    ///
    /// A function value outside the field (`cos(pi/8)`) is refused with its exact value and
    /// degree ([`ExprError::BadCall`] naming the expression); a square root outside it keeps its
    /// own reason ([`ExprError::NoSqrt`]).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let e = parse_expr(s)?;
        e.eval_constant().map_err(|err| Radical::refusal(&e, err))
    }
}

impl Radical {
    /// The error of evaluating the constant `e` in this field, made precise: a function value
    /// outside the field (`cos(pi/8)`, refused by the trigonometric evaluator as a call) is named
    /// with its exact value and degree; every other error (a square root outside the field
    /// keeps its own reason) is returned unchanged.
    #[must_use]
    pub fn refusal(e: &Expr, err: ExprError) -> ExprError {
        match err {
            ExprError::BadCall { .. } => match e.eval_constant::<crate::Algebraic>() {
                Ok(v) => ExprError::BadCall {
                    pos: e.pos,
                    name: e.to_string(),
                    why: format!(
                        "its value {v} is a real algebraic number of degree {}, outside the \
                         field of square roots of rationals that this computation uses",
                        v.degree()
                    ),
                },
                Err(_) => err,
            },
            other => other,
        }
    }
}

impl FromStr for ComplexRadical {
    type Err = ParseRadicalError;

    /// Parses the syntax of [`Radical`]'s `FromStr` with the imaginary unit as `i` or
    /// `sqrt(-1)`; `sqrt` takes the principal root (`sqrt(-4) = 2*i`).
    ///
    /// # Errors
    /// As for [`Radical`]; `sqrt(z)` fails when the principal root of `z` is not a Gaussian
    /// multi-quadratic number.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        parse_expr(s)?.eval_constant()
    }
}

impl FromStr for Algebraic {
    type Err = ExprError;
    /// A constant expression of the one grammar ([`crate::expr`]), evaluated exactly:
    /// `"sqrt(2 + sqrt(2))/2"`.
    fn from_str(s: &str) -> Result<Algebraic, Self::Err> {
        parse_expr(s)?.eval_constant()
    }
}
