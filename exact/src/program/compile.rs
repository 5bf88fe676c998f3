//! The compiler from the `prove` syntax ([`crate::expr`]) to a [`Program`], for
//! `regress --formula`.
//!
//! The tree is kept as written, because the float side evaluates it in that order:
//! * a sum `t0 ± t1 ± t2` is the left-to-right chain `(t0 ± t1) ± t2` (a leading `-` on the
//!   first term, which the parser never produces, is a negation);
//! * a product `f0 op f1 op f2` is the left-to-right chain of `*` and `/` (a leading `/` means
//!   `1 / f0`); juxtaposition is `*`. One operation is a binary node, more are one flat
//!   [`Node::Chain`], so that a sum of thousands of terms costs no stack per term. Unlike [`Expr::to_poly`](crate::expr::Expr::to_poly),
//!   division by a non-constant is allowed: a zero divisor is a matter of the sample (outside the
//!   domain on the exact side, `inf`/NaN on the float side);
//! * `a^k`: the exponent must evaluate to an integer constant (exactly, in [`Rational`]) with
//!   `|k| <=` the `formula-exponent` limit; it becomes [`Node::Pow`] with [`PowStyle::Multiply`] (the
//!   float side multiplies, it does not call `pow`);
//! * the C library's functions `sin`, `cos`, `tan`, `exp`, `log` (also `ln`), `asin`, `acos`,
//!   `atan`, `atan2`, `sinh`, `cosh`, `tanh`, `asinh`, `acosh`, `atanh`, `exp2`, `expm1`,
//!   `log2`, `log10`, `log1p`, `pow`, `hypot`, `cbrt` are [`Node::Fun`] (libm on the float side,
//!   a certified enclosure on the exact side), and the name `pi` is the constant, never a
//!   variable;
//! * numbers are exact literals ([`Node::Const`]; the float side rounds them once);
//!   `sqrt(...)` of any subexpression is [`Node::Sqrt`]; unary minus is [`Node::Neg`];
//! * a variable is [`Node::Input`]: with an explicit variable list its index there (an unknown
//!   name is an error naming it and the list), otherwise the variables in order of first
//!   appearance, reading left to right.
//!
//! No constant folding: `1/3` is the double division `1.0 / 3.0`, as in the source.
//!
//! The formula is the one expression language of `prove` and the claims files: it is first
//! resolved by the function library ([`crate::expr::library`]: vectors, matrices, `det`, `dot`,
//! `cross`, `norm2`, `bezier`, `bernstein`, `subs`, `at`, ...), which must give a scalar or a
//! vector (one output per coordinate; a matrix is [`CompileError::NotScalar`]), and then
//! lowered ([`crate::expr::lower`]):
//! `binomial` and `factorial` become their integer values, `sum` the unrolled sum of its terms,
//! `diff` and `integrate` their exact result expanded as a rational function. Both sides of the
//! regression evaluate that one lowered tree, so what is compared for a `diff` is the float
//! evaluation of the expanded derivative, not a finite difference. The variables are those of
//! the formula as written (a variable that the lowering removes, as in `diff(x^2, y)`, is still
//! an input). `pi` is the constant pi (its exact side a certified enclosure, its float side
//! `std::f64::consts::PI`); `e` and `i` are constants, never variables, and a formula naming one
//! is refused ([`CompileError::Reserved`]). The elementary functions (`sin`, `exp`, `log`, ...)
//! are calls of the program.
use super::{ChainOp, Format, Func, Node, PowStyle, Program};
use crate::expr::library::{Defs, Val};
use crate::expr::{
    lower, parse_expr, parse_expr_with_calls, reserved_constant, symbolic_sum_ranges, AddOp, Expr,
    ExprError, ExprKind, MulOp, PI,
};
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
    /// A call of a function that a regressed formula does not have.
    #[error("unknown function '{name}' at {pos}: a regressed formula calls sqrt, {list} (write '{name}*(...)' for a product)", list = formula_functions())]
    UnknownFunction {
        /// Byte position of the call.
        pos: usize,
        /// The name.
        name: String,
    },
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
    /// An error of the function library (an unknown function, a wrong arity, shapes that do not
    /// fit, ...); the message carries the position.
    #[error("{0}")]
    Resolve(String),
    /// A formula whose value is a matrix (a vector is one output per coordinate).
    #[error("the formula is {shape}; a regressed formula has a scalar value or a vector of outputs (take a row, e.g. at(M, 1), or give each output as its own --formula)")]
    NotScalar {
        /// The shape found (`a vector of 2`).
        shape: String,
    },
    /// A constant of mathematics (`pi`, `e`, `i`) used as a variable.
    #[error("'{name}' at {pos}: {why}")]
    Reserved {
        /// Byte position of the name.
        pos: usize,
        /// The name.
        name: String,
        /// Why it is refused.
        why: &'static str,
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
            | CompileError::UnknownFunction { pos, .. }
            | CompileError::Reserved { pos, .. }
            | CompileError::BadExponent { pos, .. }
            | CompileError::ExponentTooLarge { pos, .. } => *pos,
            CompileError::DuplicateVariable { .. }
            | CompileError::BadVariable { .. }
            | CompileError::Resolve(_)
            | CompileError::NotScalar { .. } => 0,
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
        if let Some(why) = reserved(name) {
            return Err(CompileError::Reserved {
                pos,
                name: name.to_string(),
                why,
            });
        }
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

/// Why `name` is a constant and not a variable of a regressed formula, `None` for a variable.
fn reserved(name: &str) -> Option<&'static str> {
    if name == PI {
        return Some("pi is the constant pi, not a variable");
    }
    reserved_constant(name)
}

impl Program {
    /// Compiles a parsed formula (see the module documentation of `program::compile`: resolved
    /// by the library, lowered, compiled): inputs `vars` in that order when given, else the
    /// variables in order of first appearance; one output, or one per coordinate of a vector
    /// value; no slots, no precondition; the name is the printed expression (the caller may
    /// overwrite it).
    ///
    /// # Errors
    /// An unknown, duplicate or malformed variable, a constant used as a variable, a library
    /// error or a matrix value, an error of the lowering, an exponent that is not an integer
    /// constant or exceeds the `formula-exponent` limit, or an error evaluating a constant
    /// exponent.
    pub fn from_expr(expr: &Expr, vars: Option<&[String]>) -> Result<Program, CompileError> {
        let mut table = Vars {
            names: Vec::new(),
            fixed: vars.is_some(),
        };
        for name in vars.unwrap_or_default() {
            let is_name =
                parse_expr(name).is_ok_and(|e| matches!(&e.kind, ExprKind::Var(v) if v == name));
            if !is_name || reserved(name).is_some() {
                return Err(CompileError::BadVariable { name: name.clone() });
            }
            if table.names.contains(name) {
                return Err(CompileError::DuplicateVariable { name: name.clone() });
            }
            table.names.push(name.clone());
        }
        // A scalar is one output, a vector one output per coordinate.
        let resolved = match Defs::default()
            .with_calls(&formula_function_names())
            .resolve_expr(expr)
            .map_err(|e| CompileError::Resolve(e.to_string()))?
        {
            Val::Scalar(e) => vec![e],
            Val::Vector(v) => v,
            v => return Err(CompileError::NotScalar { shape: v.shape() }),
        };
        if !table.fixed {
            // The inputs are the variables in the order written (`det([[a, b], [c, d]])` has
            // a, b, c, d, though its expansion starts a*d), even one the lowering removes, but
            // not a name the library replaces (the variable of `subs`).
            let mut present = Vec::new();
            for r in &resolved {
                r.collect_variables(&mut present);
            }
            let mut names = Vec::new();
            expr.collect_variables(&mut names);
            names.retain(|n| present.contains(n));
            for n in present {
                if !names.contains(&n) {
                    names.push(n);
                }
            }
            table
                .names
                .extend(names.into_iter().filter(|n| reserved(n).is_none()));
        }
        // A sum to a symbolic bound has no term-by-term evaluation in floating point.
        if let Some((a, b)) = resolved.iter().find_map(|r| symbolic_sum_ranges(r).pop()) {
            return Err(CompileError::Expr(ExprError::BadCall {
                pos: b.pos,
                name: "sum".into(),
                why: format!(
                    "the range {a}..{b} has a bound that is not an integer constant: a \
                     regressed formula adds the terms of a sum in floating point, which needs \
                     integer constant bounds (prove decides a sum with a symbolic bound exactly, \
                     in closed form)"
                ),
            }));
        }
        let outputs = resolved
            .iter()
            .map(|r| compile(&lower(r)?, &mut table))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Program {
            name: expr.to_string(),
            inputs: table.names,
            slots: 0,
            pre: None,
            outputs,
            precision: Format::Binary64,
            input_precision: Vec::new(),
        })
    }

    /// Compiles several formulas as the outputs of one program, in order (each may itself be
    /// a vector of outputs): the inputs are `vars` when given, else the variables of all of them
    /// in order of first appearance; the name is the texts joined by `; `.
    ///
    /// # Errors
    /// As [`Program::parse`], with the formula's number (from 1) when there are several.
    pub fn parse_outputs(texts: &[String], vars: Option<&[String]>) -> Result<Program, String> {
        let which = |k: usize, e: CompileError| {
            if texts.len() == 1 {
                e.to_string()
            } else {
                format!("formula {}: {e}", k + 1)
            }
        };
        // Each formula alone first (an error names the one it is in), for its variables.
        let mut names: Vec<String> = vars.map(<[String]>::to_vec).unwrap_or_default();
        let mut exprs = Vec::with_capacity(texts.len());
        for (k, text) in texts.iter().enumerate() {
            let expr = parse_expr_with_calls(text).map_err(|e| which(k, e.into()))?;
            let alone = Program::from_expr(&expr, vars).map_err(|e| which(k, e))?;
            for n in alone.inputs {
                if !names.contains(&n) {
                    names.push(n);
                }
            }
            exprs.push(expr);
        }
        let mut outputs = Vec::new();
        for (k, expr) in exprs.iter().enumerate() {
            let p = Program::from_expr(expr, Some(&names)).map_err(|e| which(k, e))?;
            outputs.extend(p.outputs);
        }
        Ok(Program {
            name: texts
                .iter()
                .map(|t| t.trim())
                .collect::<Vec<_>>()
                .join("; "),
            inputs: names,
            slots: 0,
            pre: None,
            outputs,
            precision: Format::Binary64,
            input_precision: Vec::new(),
        })
    }

    /// Parses `text` in the `prove` syntax with the library's calls
    /// ([`crate::expr::parse_expr_with_calls`]) and compiles it with
    /// [`Program::from_expr`]; the name is `text`, trimmed.
    ///
    /// # Errors
    /// A syntax error, or an error of [`Program::from_expr`].
    pub fn parse(text: &str, vars: Option<&[String]>) -> Result<Program, CompileError> {
        let expr = parse_expr_with_calls(text)?;
        let mut p = Program::from_expr(&expr, vars)?;
        p.name = text.trim().to_string();
        Ok(p)
    }
}

fn compile(e: &Expr, vars: &mut Vars) -> Result<Node, CompileError> {
    Ok(match &e.kind {
        ExprKind::Number(q) => Node::Const(q.clone()),
        ExprKind::Var(name) if name == PI => Node::Fun(Func::Pi, Vec::new()),
        ExprKind::Var(name) => Node::Input(vars.index(name, e.pos)?),
        ExprKind::Neg(a) => Node::Neg(Box::new(compile(a, vars)?)),
        ExprKind::Sqrt(a) => Node::Sqrt(Box::new(compile(a, vars)?)),
        ExprKind::Call(name, args) if name == crate::expr::ABS => {
            let [a] = args.as_slice() else {
                return Err(CompileError::Expr(ExprError::BadCall {
                    pos: e.pos,
                    name: name.clone(),
                    why: format!("it takes 1 argument, found {}", args.len()),
                }));
            };
            Node::Abs(Box::new(compile(a, vars)?))
        }
        ExprKind::Call(name, args) if formula_function(name).is_some() => {
            let f = formula_function(name).expect("a function");
            if args.len() != f.arity() {
                return Err(CompileError::Expr(ExprError::BadCall {
                    pos: e.pos,
                    name: name.clone(),
                    why: format!(
                        "it takes {} argument{}, found {}",
                        f.arity(),
                        if f.arity() == 1 { "" } else { "s" },
                        args.len()
                    ),
                }));
            }
            let args = args
                .iter()
                .map(|a| compile(a, vars))
                .collect::<Result<Vec<_>, _>>()?;
            Node::Fun(f, args)
        }
        ExprKind::Call(name, _) if crate::expr::FUNCTIONS.contains(&name.as_str()) => {
            return Err(CompileError::Expr(ExprError::BadCall {
                pos: e.pos,
                name: name.clone(),
                why: "a regressed formula is evaluated as written, operation by operation, in \
                      f64 and exactly; expand the call first (its exact value is what prove \
                      computes)"
                    .into(),
            }))
        }
        ExprKind::Call(name, _) => {
            return Err(CompileError::UnknownFunction {
                pos: e.pos,
                name: name.clone(),
            })
        }
        ExprKind::Sum(items) => {
            let op = |op: &AddOp| match op {
                AddOp::Plus => ChainOp::Add,
                AddOp::Minus => ChainOp::Sub,
            };
            // A leading `-` is a negation.
            let first = |op: &AddOp, t: Node| match op {
                AddOp::Plus => t,
                AddOp::Minus => Node::Neg(Box::new(t)),
            };
            compile_chain(items, vars, Rational::ZERO, first, op)?
        }
        ExprKind::Product(items) => {
            let op = |op: &MulOp| match op {
                MulOp::Times | MulOp::Dot | MulOp::Cross => ChainOp::Mul,
                MulOp::Divide => ChainOp::Div,
            };
            // A leading `/` is a reciprocal.
            let first = |op: &MulOp, f: Node| match op {
                MulOp::Times | MulOp::Dot | MulOp::Cross => f,
                MulOp::Divide => Node::Div(Box::new(Node::Const(Rational::ONE)), Box::new(f)),
            };
            compile_chain(items, vars, Rational::ONE, first, op)?
        }
        ExprKind::Pow(base, exp) => {
            let b = compile(base, vars)?;
            Node::Pow(Box::new(b), exponent(exp)?, PowStyle::Multiply)
        }
    })
}

/// The function of a formula call `name(...)`: the C library's functions by their C names
/// ([`Func::name`]; `ln` is `log`), the constants excluded (`pi` is a name, not a call).
fn formula_function(name: &str) -> Option<Func> {
    let name = if name == "ln" { "log" } else { name };
    Func::from_name(name).filter(|f| f.arity() > 0)
}

/// The names [`formula_function`] accepts.
fn formula_function_names() -> Vec<&'static str> {
    let mut names: Vec<&'static str> = Func::ALL
        .iter()
        .filter(|f| f.arity() > 0)
        .map(|f| f.name())
        .collect();
    names.push("ln");
    names
}

/// The names [`formula_function`] accepts, comma-separated (for error messages).
fn formula_functions() -> String {
    formula_function_names().join(", ")
}

/// The left-to-right chain of a sum's terms or a product's factors (`empty` when there are
/// none): `first` makes the node of the first item from its operator, `op` the operation of each
/// later one.
fn compile_chain<O>(
    items: &[(O, Expr)],
    vars: &mut Vars,
    empty: Rational,
    first: impl Fn(&O, Node) -> Node,
    op: impl Fn(&O) -> ChainOp,
) -> Result<Node, CompileError> {
    let Some(((o, x), rest)) = items.split_first() else {
        return Ok(Node::Const(empty));
    };
    let head = first(o, compile(x, vars)?);
    let mut ops = Vec::with_capacity(rest.len());
    for (o, x) in rest {
        ops.push((op(o), compile(x, vars)?));
    }
    Ok(chain(head, ops))
}

/// `first op1 b1 op2 b2 ...` from the left: `first` alone, one binary node, or a
/// [`Node::Chain`] for two operations or more.
fn chain(first: Node, mut ops: Vec<(ChainOp, Node)>) -> Node {
    if ops.len() != 1 {
        return if ops.is_empty() {
            first
        } else {
            Node::Chain(Box::new(first), ops)
        };
    }
    let (op, b) = ops.pop().expect("one operation");
    let (a, b) = (Box::new(first), Box::new(b));
    match op {
        ChainOp::Add => Node::Add(a, b),
        ChainOp::Sub => Node::Sub(a, b),
        ChainOp::Mul => Node::Mul(a, b),
        ChainOp::Div => Node::Div(a, b),
    }
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

#[cfg(test)]
#[path = "language_tests.rs"]
mod language_tests;
