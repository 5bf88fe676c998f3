//! The compiler from the `prove` syntax ([`crate::expr`]) to a [`Program`], for
//! `regress --formula`.
//!
//! The tree is kept as written, because the float side evaluates it in that order:
//! * a sum `t0 ± t1 ± t2` is the left-to-right chain `(t0 ± t1) ± t2` (a leading `-` on the
//!   first term, which the parser never produces, is a negation);
//! * a product `f0 op f1 op f2` is the left-to-right chain of `*` and `/` (a leading `/` means
//!   `1 / f0`); juxtaposition is `*`. Unlike [`Expr::to_poly`](crate::expr::Expr::to_poly),
//!   division by a non-constant is allowed: a zero divisor is a matter of the sample (outside the
//!   domain on the exact side, `inf`/NaN on the float side);
//! * `a^k`: the exponent must evaluate to an integer constant (exactly, in [`Rational`]) with
//!   `|k| <=` the `formula-exponent` limit; it becomes [`Node::Pow`] with [`PowStyle::Multiply`] (the
//!   float side multiplies, it does not call `pow`);
//! * numbers are exact literals ([`Node::Const`]; the float side rounds them once);
//!   `sqrt(...)` of any subexpression is [`Node::Sqrt`]; unary minus is [`Node::Neg`];
//! * a variable is [`Node::Input`]: with an explicit variable list its index there (an unknown
//!   name is an error naming it and the list), otherwise the variables in order of first
//!   appearance, reading left to right.
//!
//! No constant folding: `1/3` is the double division `1.0 / 3.0`, as in the source.
use super::{Node, PowStyle, Program};
use crate::expr::{parse_expr, AddOp, Expr, ExprError, ExprKind, MulOp};
use crate::rational::Rational;
use exactcheck_core::limits::{self, LimitError};
use num_traits::ToPrimitive;

/// An error of compiling a formula: a syntax error of the one grammar, or one of the rules
/// above, with the byte position it refers to.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CompileError {
    /// A syntax error (or a constant exponent that cannot be evaluated) of [`crate::expr`].
    #[error(transparent)]
    Expr(#[from] ExprError),
    /// A variable not in the given list.
    #[error("unknown variable '{name}' at {pos}: the variables are {list}")]
    UnknownVariable {
        /// Byte position of the variable.
        pos: usize,
        /// Its name.
        name: String,
        /// The given variables, comma-separated (`(none)` for an empty list).
        list: String,
    },
    /// An entry of the given variable list that is not a variable name of the grammar (an empty
    /// entry, as in `x,,y`, or `2x`).
    #[error("{name:?} in the variable list is not a variable name")]
    BadVariable {
        /// The entry.
        name: String,
    },
    /// A name that appears twice in the given variable list.
    #[error("variable '{name}' is listed twice")]
    DuplicateVariable {
        /// The name.
        name: String,
    },
    /// An exponent that is not an integer constant.
    #[error("exponent at {pos} must be an integer constant, found {found}")]
    BadExponent {
        /// Byte position of the exponent.
        pos: usize,
        /// The exponent (its expression, or its value).
        found: String,
    },
    /// An exponent beyond the `formula-exponent` limit ([`limits::FORMULA_EXPONENT`]).
    #[error("exponent at {pos}: {error}")]
    ExponentTooLarge {
        /// Byte position of the exponent.
        pos: usize,
        /// The limit exceeded, with the exponent found.
        error: LimitError,
    },
}

impl CompileError {
    /// The byte position the error refers to (0 for a duplicate in the variable list).
    pub fn position(&self) -> usize {
        match self {
            CompileError::Expr(e) => e.position(),
            CompileError::UnknownVariable { pos, .. }
            | CompileError::BadExponent { pos, .. }
            | CompileError::ExponentTooLarge { pos, .. } => *pos,
            CompileError::DuplicateVariable { .. } | CompileError::BadVariable { .. } => 0,
        }
    }
}

/// The variable table of one compilation.
struct Vars {
    names: Vec<String>,
    fixed: bool,
}

impl Vars {
    fn index(&mut self, name: &str, pos: usize) -> Result<usize, CompileError> {
        if let Some(i) = self.names.iter().position(|n| n == name) {
            return Ok(i);
        }
        if self.fixed {
            return Err(CompileError::UnknownVariable {
                pos,
                name: name.to_string(),
                list: if self.names.is_empty() {
                    "(none)".to_string()
                } else {
                    self.names.join(", ")
                },
            });
        }
        self.names.push(name.to_string());
        Ok(self.names.len() - 1)
    }
}

impl Program {
    /// Compiles a parsed formula (see the module documentation of `program::compile`): inputs
    /// `vars` in that order when given, else the variables in order of first appearance; one
    /// output; no slots, no precondition; the name is the printed expression (the caller may
    /// overwrite it).
    ///
    /// # Errors
    /// An unknown, duplicate or malformed variable, an exponent that is not an integer constant or exceeds
    /// the `formula-exponent` limit, or an error evaluating a constant exponent.
    pub fn from_expr(expr: &Expr, vars: Option<&[String]>) -> Result<Program, CompileError> {
        let mut table = Vars {
            names: Vec::new(),
            fixed: vars.is_some(),
        };
        for name in vars.unwrap_or_default() {
            let is_name =
                parse_expr(name).is_ok_and(|e| matches!(&e.kind, ExprKind::Var(v) if v == name));
            if !is_name {
                return Err(CompileError::BadVariable { name: name.clone() });
            }
            if table.names.contains(name) {
                return Err(CompileError::DuplicateVariable { name: name.clone() });
            }
            table.names.push(name.clone());
        }
        let out = compile(expr, &mut table)?;
        Ok(Program {
            name: expr.to_string(),
            inputs: table.names,
            slots: 0,
            pre: None,
            outputs: vec![out],
        })
    }

    /// Parses `text` in the `prove` syntax ([`crate::expr::parse_expr`]) and compiles it with
    /// [`Program::from_expr`]; the name is `text`, trimmed.
    ///
    /// # Errors
    /// A syntax error, or an error of [`Program::from_expr`].
    pub fn parse(text: &str, vars: Option<&[String]>) -> Result<Program, CompileError> {
        let expr = parse_expr(text)?;
        let mut p = Program::from_expr(&expr, vars)?;
        p.name = text.trim().to_string();
        Ok(p)
    }
}

fn compile(e: &Expr, vars: &mut Vars) -> Result<Node, CompileError> {
    Ok(match &e.kind {
        ExprKind::Number(q) => Node::Const(q.clone()),
        ExprKind::Var(name) => Node::Input(vars.index(name, e.pos)?),
        ExprKind::Neg(a) => Node::Neg(Box::new(compile(a, vars)?)),
        ExprKind::Sqrt(a) => Node::Sqrt(Box::new(compile(a, vars)?)),
        ExprKind::Call(name, _) => {
            return Err(CompileError::Expr(ExprError::UnknownFunction {
                pos: e.pos,
                name: name.clone(),
            }))
        }
        ExprKind::Sum(items) => {
            let mut acc: Option<Node> = None;
            for (op, t) in items {
                let t = compile(t, vars)?;
                acc = Some(match (acc, op) {
                    (None, AddOp::Plus) => t,
                    (None, AddOp::Minus) => Node::Neg(Box::new(t)),
                    (Some(a), AddOp::Plus) => Node::Add(Box::new(a), Box::new(t)),
                    (Some(a), AddOp::Minus) => Node::Sub(Box::new(a), Box::new(t)),
                });
            }
            acc.unwrap_or(Node::Const(Rational::ZERO))
        }
        ExprKind::Product(items) => {
            let mut acc: Option<Node> = None;
            for (op, f) in items {
                let f = compile(f, vars)?;
                acc = Some(match (acc, op) {
                    (None, MulOp::Times) => f,
                    (None, MulOp::Divide) => {
                        Node::Div(Box::new(Node::Const(Rational::ONE)), Box::new(f))
                    }
                    (Some(a), MulOp::Times) => Node::Mul(Box::new(a), Box::new(f)),
                    (Some(a), MulOp::Divide) => Node::Div(Box::new(a), Box::new(f)),
                });
            }
            acc.unwrap_or(Node::Const(Rational::ONE))
        }
        ExprKind::Pow(base, exp) => {
            let b = compile(base, vars)?;
            Node::Pow(Box::new(b), exponent(exp)?, PowStyle::Multiply)
        }
    })
}

/// The value of an exponent: an integer constant with `|k|` within the `formula-exponent` limit.
fn exponent(e: &Expr) -> Result<i32, CompileError> {
    let bad = |found: String| CompileError::BadExponent { pos: e.pos, found };
    let q: Rational = match e.eval_constant() {
        Ok(q) => q,
        Err(ExprError::NotConstant { .. }) => return Err(bad(e.to_string())),
        Err(err) => return Err(err.into()),
    };
    if !q.is_integer() {
        return Err(bad(q.to_string()));
    }
    let limit = &limits::FORMULA_EXPONENT;
    q.numer()
        .to_i64()
        .filter(|k| limit.check(k.unsigned_abs()).is_ok())
        .and_then(|k| i32::try_from(k).ok())
        .ok_or_else(|| CompileError::ExponentTooLarge {
            pos: e.pos,
            error: limit.exceeded(q.to_string()),
        })
}
