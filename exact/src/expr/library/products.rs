//! Products and powers as printed: `\cdot` and `\times` between vectors (the dot and cross
//! products), powers of square matrices, bold names (`\mathbf{v}`) and the length `|v|` of a
//! vector.

use super::*;
use exactcheck_core::Sign;

/// The product of two non-scalar values written with `op` between them: `\cdot` is the dot
/// product of two vectors, `\times` their cross product; two matrices with `\cdot` are refused
/// (the matrix product or the sum of the entrywise products); everything else is [`multiply`].
fn written_product(op: MulOp, left: Val, right: Val, lp: usize, rp: usize) -> R<Val> {
    match (op, &left, &right) {
        (MulOp::Dot, Val::Vector(_), Val::Vector(_)) => {
            library_call("dot", &[(left, lp), (right, rp)], rp)
        }
        (MulOp::Cross, Val::Vector(_), Val::Vector(_)) => {
            library_call("cross", &[(left, lp), (right, rp)], rp)
        }
        (MulOp::Dot, Val::Matrix(_), Val::Matrix(_)) => err(format!(
            "\\cdot between {} at {lp} and {} at {rp} is ambiguous (the matrix product or the sum of the entrywise products): write M N or M*N for the matrix product",
            left.shape(),
            right.shape()
        )),
        _ => multiply(left, right, lp, rp),
    }
}

impl Defs {
    /// A product: the scalar factors multiplied, the vectors and matrices combined from the
    /// left by the product written between them (`*` or juxtaposition, `\cdot`, `\times`, with
    /// any scalar factors between). A product chain that takes a dot product of two vectors and
    /// then joins a vector or matrix by `\cdot` or `\times` (`a \cdot b \times c`) is refused as
    /// ambiguous.
    pub(super) fn product(
        &mut self,
        factors: &[(MulOp, Expr)],
        pos: usize,
        stack: &mut Vec<String>,
    ) -> R<Val> {
        let mut scalars = Vec::new();
        let mut other: Option<(Val, usize)> = None;
        // The product written (`\cdot`, `\times`) since the last vector or matrix.
        let mut written: Option<(MulOp, usize)> = None;
        // Where a product of two vectors gave a scalar, and where a cross product gave a vector,
        // in this chain.
        let mut scalar_from: Option<usize> = None;
        let mut cross_from: Option<usize> = None;
        for (op, f) in factors {
            if matches!(op, MulOp::Dot | MulOp::Cross) {
                match written {
                    Some((w, p)) if w != *op && other.is_some() => {
                        return err(format!(
                            "\\cdot and \\times at {p} and {} between the same two vectors or matrices: write parentheses",
                            f.pos
                        ))
                    }
                    _ => written = Some((*op, f.pos)),
                }
            }
            let v = self.resolve(f, stack)?;
            if let Val::Scalar(x) = v {
                let op = if op.divides() {
                    MulOp::Divide
                } else {
                    MulOp::Times
                };
                scalars.push((op, x));
                continue;
            }
            if op.divides() {
                return err(format!("division by {} at {}", v.shape(), f.pos));
            }
            let written_op = written.take();
            match other.take() {
                None => {
                    if let (Some(at), Some((_, p))) = (scalar_from, written_op) {
                        return err(format!(
                            "the product at {at} of two vectors is a scalar, then {} at {p}: ambiguous; write parentheses, e.g. a \\cdot (b \\times c)",
                            v.shape()
                        ));
                    }
                    other = Some((v, f.pos));
                }
                Some((left, p)) => {
                    let op = written_op.map_or(MulOp::Times, |(w, _)| w);
                    if let (MulOp::Cross, Some(at)) = (op, cross_from) {
                        return err(format!(
                            "the cross product at {at} then \\times at {}: ambiguous (the cross product is not associative); write parentheses, e.g. a \\times (b \\times c)",
                            f.pos
                        ));
                    }
                    if op == MulOp::Cross && matches!((&left, &v), (Val::Vector(_), Val::Vector(_)))
                    {
                        cross_from = Some(f.pos);
                    }
                    match written_product(op, left, v, p, f.pos)? {
                        Val::Scalar(x) => {
                            scalar_from = Some(f.pos);
                            scalars.push((MulOp::Times, x));
                        }
                        v => other = Some((v, p)),
                    }
                }
            }
        }
        let with = |x: Option<Expr>| {
            let mut fs = scalars.clone();
            if let Some(x) = x {
                fs.insert(0, (MulOp::Times, x));
            }
            Expr {
                kind: ExprKind::Product(fs),
                pos,
            }
        };
        Ok(match other {
            None => Val::Scalar(with(None)),
            Some((v, _)) if scalars.is_empty() => v,
            Some((v, _)) => v.map(|x| with(Some(x))),
        })
    }

    /// `base ^ k`: a power of a scalar, or of a square matrix ([`matrix_power`]).
    pub(super) fn power(
        &mut self,
        base: &Expr,
        k: &Expr,
        pos: usize,
        stack: &mut Vec<String>,
    ) -> R<Val> {
        let b = self.resolve(base, stack)?;
        let k = self.scalar(k, stack, "an exponent")?;
        match b {
            Val::Scalar(b) => Ok(Val::Scalar(Expr {
                kind: ExprKind::Pow(Box::new(b), Box::new(k)),
                pos,
            })),
            Val::Matrix(m) => matrix_power(m, &k, base.pos),
            v => err(format!(
                "{} at {} where a scalar is expected (a power's base; for |v|^2 write norm2(v))",
                v.shape(),
                base.pos
            )),
        }
    }

    /// The bold name `bold(v)` (`\mathbf{v}`): the value `v` is defined as (or bound to as a
    /// parameter); an undefined bold name is refused, since a bold letter names a vector or a
    /// matrix and reading it as a scalar variable would decide another identity.
    pub(super) fn bold(&mut self, args: &[Expr], pos: usize, stack: &mut Vec<String>) -> R<Val> {
        let [arg] = args else {
            return err(format!(
                "{BOLD} at {pos} takes 1 argument, not {}",
                args.len()
            ));
        };
        let ExprKind::Var(name) = &arg.kind else {
            return err(format!("{BOLD} at {pos} takes a name, not {arg}"));
        };
        if !self.scope.contains_key(name) && !self.is_defined(name) {
            return err(format!(
                "the bold name {name} at {pos} is not defined: a bold letter names a vector or a matrix, so define it (prove: --define '{name} = [{name}1, {name}2, {name}3]'; a claims file: {name} = [\"{name}1\", \"{name}2\", \"{name}3\"] in [define])"
            ));
        }
        self.resolve(arg, stack)
    }
}

/// `|v|` of a vector: its length `sqrt(norm2(v))`; of a scalar the absolute value, of a matrix
/// refused (the determinant or a norm).
pub(super) fn absolute(arg: Val, arg_pos: usize, pos: usize) -> R<Val> {
    let node = |kind: ExprKind| Expr { kind, pos };
    match arg {
        Val::Scalar(x) => Ok(Val::Scalar(node(ExprKind::Call(
            crate::expr::ABS.to_string(),
            vec![x],
        )))),
        v @ Val::Vector(_) => match library_call("norm2", &[(v, arg_pos)], pos)? {
            Val::Scalar(n2) => Ok(Val::Scalar(node(ExprKind::Sqrt(Box::new(n2))))),
            _ => unreachable!("norm2 is a scalar"),
        },
        v => err(format!(
            "|..| of {} at {arg_pos} is ambiguous (its determinant or a norm): write det(M)",
            v.shape()
        )),
    }
}

/// `M^k` of a square matrix and a non-negative integer constant `k` (at most the
/// `matrix-power` limit; `M^0` is the identity), by repeated squaring; refused when the
/// entries' trees would exceed [`MAX_NODES`].
pub(super) fn matrix_power(m: Vec<Vec<Expr>>, k: &Expr, pos: usize) -> R<Val> {
    let n = m.len();
    if m[0].len() != n {
        return err(format!(
            "a power of {} at {pos}: only a square matrix has powers",
            Val::Matrix(m).shape()
        ));
    }
    let e = k
        .eval_constant::<Rational>()
        .ok()
        .filter(|q| q.is_integer() && q.signum() != Sign::Negative)
        .and_then(|q| q.to_string().parse::<usize>().ok());
    let Some(mut e) = e else {
        return err(format!(
            "the exponent {k} of the matrix power at {pos} must be a non-negative integer constant (M^0 is the identity; an inverse is not supported)"
        ));
    };
    limits::MATRIX_POWER
        .check_usize(e)
        .map_err(|error| ResolveError {
            def: None,
            message: format!("the matrix power at {pos}: {error}"),
        })?;
    let number = |i: i64| Expr {
        kind: ExprKind::Number(Rational::from_integer(i)),
        pos,
    };
    let mut result = Val::Matrix(
        (0..n)
            .map(|i| (0..n).map(|j| number(i64::from(i == j))).collect())
            .collect(),
    );
    let mut square = Val::Matrix(m);
    let check = |v: &Val| -> R<()> {
        let nodes: usize = v.parts().iter().map(|x| count_nodes(x)).sum();
        if nodes > MAX_NODES {
            return err(too_many_nodes(pos));
        }
        Ok(())
    };
    let mut first = true;
    while e > 0 {
        if e & 1 == 1 {
            result = if first {
                square.clone()
            } else {
                multiply(result, square.clone(), pos, pos)?
            };
            first = false;
            check(&result)?;
        }
        e >>= 1;
        if e > 0 {
            square = multiply(square.clone(), square, pos, pos)?;
            check(&square)?;
        }
    }
    Ok(result)
}

#[cfg(test)]
#[path = "products_tests.rs"]
mod tests;
