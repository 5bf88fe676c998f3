//! Printing an [`Expr`] in the syntax it was parsed from, with the parentheses it needs.

use super::*;
use std::fmt;

// ------------------------------------------------------------------------------ printing

/// Binding strength of a node when printed (higher binds tighter).
fn precedence(e: &Expr) -> u8 {
    match e.kind {
        ExprKind::Sum(_) => 1,
        ExprKind::Product(_) => 2,
        ExprKind::Neg(_) => 3,
        ExprKind::Pow(..) => 4,
        ExprKind::Number(_) | ExprKind::Var(_) | ExprKind::Sqrt(_) | ExprKind::Call(..) => 5,
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

impl Expr {
    /// A lower bound on the nesting depth the parser counts for any text that parses to this
    /// tree (each parenthesised group counts two levels: the group and its first factor; each
    /// sign, exponent and call one), taken on the printed form, which has the fewest
    /// parentheses. So a tree built by substitution can be held to the `depth` limit the parser
    /// applies without refusing any tree the parser accepts.
    pub fn nesting(&self) -> usize {
        let wrapped = |x: &Expr, min: u8| x.nesting() + if precedence(x) < min { 2 } else { 0 };
        match &self.kind {
            ExprKind::Number(_) | ExprKind::Var(_) => 0,
            ExprKind::Neg(x) => 1 + wrapped(x, 3),
            ExprKind::Sum(items) => items.iter().map(|(_, x)| wrapped(x, 2)).max().unwrap_or(0),
            ExprKind::Product(items) => items.iter().map(|(_, x)| wrapped(x, 3)).max().unwrap_or(0),
            ExprKind::Pow(base, exp) => {
                let e = match exp.kind {
                    ExprKind::Pow(..) => exp.nesting(),
                    _ => wrapped(exp, 5),
                };
                wrapped(base, 5).max(1 + e)
            }
            ExprKind::Sqrt(x) => 1 + x.nesting(),
            ExprKind::Call(_, args) => 1 + args.iter().map(Expr::nesting).max().unwrap_or(0),
        }
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
                        (0, MulOp::Times | MulOp::Dot | MulOp::Cross) => {}
                        (0, MulOp::Divide) => f.write_str("1/")?,
                        (_, MulOp::Times) => f.write_str("*")?,
                        (_, MulOp::Divide) => f.write_str("/")?,
                        // The product as written, which reads back as it (a dot or cross
                        // product between vectors).
                        (_, MulOp::Dot) => f.write_str(" \u{b7} ")?,
                        (_, MulOp::Cross) => f.write_str(" \u{d7} ")?,
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
            ExprKind::Call(name, args) if args.is_empty() && is_decimal_name(name) => {
                f.write_str(name)
            }
            ExprKind::Call(name, args) => {
                // A list `[a, b]` is printed as written.
                let list = name == super::parse::LIST;
                if list {
                    f.write_str("[")?;
                } else {
                    write!(f, "{name}(")?;
                }
                for (k, a) in args.iter().enumerate() {
                    if k > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{a}")?;
                }
                f.write_str(if list { "]" } else { ")" })
            }
        }
    }
}
