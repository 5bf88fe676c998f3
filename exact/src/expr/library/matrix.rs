//! Trees of sums and products, matrix products and determinants for the library functions.

use super::*;

pub(super) fn too_many_nodes(pos: usize) -> String {
    format!(
        "the expression at {pos} expands to more than {MAX_NODES} nodes (MAX_NODES) after substituting the definitions"
    )
}

pub(super) fn times(a: Expr, b: Expr, pos: usize) -> Expr {
    Expr {
        kind: ExprKind::Product(vec![(MulOp::Times, a), (MulOp::Times, b)]),
        pos,
    }
}

pub(super) fn plus(xs: Vec<Expr>, pos: usize) -> Expr {
    Expr {
        kind: ExprKind::Sum(xs.into_iter().map(|x| (AddOp::Plus, x)).collect()),
        pos,
    }
}

/// `sum a_i b_i`.
pub(super) fn inner(a: &[Expr], b: &[Expr], pos: usize) -> Expr {
    plus(
        a.iter()
            .zip(b)
            .map(|(x, y)| times(x.clone(), y.clone(), pos))
            .collect(),
        pos,
    )
}

pub(super) fn transposed(rows: &[Vec<Expr>]) -> Vec<Vec<Expr>> {
    (0..rows[0].len())
        .map(|j| rows.iter().map(|r| r[j].clone()).collect())
        .collect()
}

/// The product of two non-scalar values (`left` at `lp`, `right` at `rp`): matrix times
/// vector or matrix.
pub(super) fn multiply(left: Val, right: Val, lp: usize, rp: usize) -> R<Val> {
    let mismatch = |l: &Val, r: &Val| {
        err(format!(
            "a product of {} at {lp} and {} at {rp}: the sizes do not match",
            l.shape(),
            r.shape()
        ))
    };
    match (&left, &right) {
        (Val::Vector(_), Val::Vector(_)) => err(format!(
            "a product of two vectors at {rp}: write dot(u, v) or cross(u, v)"
        )),
        (Val::Vector(_), Val::Matrix(_)) => err(format!(
            "a product of {} at {lp} and {} at {rp}: a vector multiplies no matrix from the left (write transpose(M)*v)",
            left.shape(),
            right.shape()
        )),
        (Val::Matrix(m), Val::Vector(v)) => {
            if m[0].len() != v.len() {
                return mismatch(&left, &right);
            }
            Ok(Val::Vector(m.iter().map(|r| inner(r, v, lp)).collect()))
        }
        (Val::Matrix(a), Val::Matrix(b)) => {
            if a[0].len() != b.len() {
                return mismatch(&left, &right);
            }
            let cols = transposed(b);
            Ok(Val::Matrix(
                a.iter()
                    .map(|r| cols.iter().map(|c| inner(r, c, lp)).collect())
                    .collect(),
            ))
        }
        _ => unreachable!("multiply() is called for vectors and matrices"),
    }
}

/// Whether `e` is the literal number 0.
pub(super) fn is_zero(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Number(q) if *q == Rational::ZERO)
}

/// An upper bound of the nodes of the cofactor expansion of an `n x n` matrix whose entries have
/// at most `entry` nodes (saturating).
pub(super) fn det_nodes(n: usize, entry: usize) -> usize {
    let mut nodes = entry;
    for k in 2..=n {
        // A sum of k signed products of an entry and a minor's expansion.
        nodes = k
            .saturating_mul(entry.saturating_add(nodes).saturating_add(2))
            .saturating_add(1);
    }
    nodes
}

/// The determinant by cofactor expansion along the first row (literal zero entries skipped).
/// `cols` are the columns of the minor, `row` its first row.
pub(super) fn det(m: &[Vec<Expr>], row: usize, cols: &[usize], pos: usize) -> Expr {
    if cols.len() == 1 {
        return m[row][cols[0]].clone();
    }
    let mut terms = Vec::new();
    for (k, &c) in cols.iter().enumerate() {
        let a = &m[row][c];
        if is_zero(a) {
            continue;
        }
        let rest: Vec<usize> = cols.iter().copied().filter(|&x| x != c).collect();
        let op = if k % 2 == 0 {
            AddOp::Plus
        } else {
            AddOp::Minus
        };
        terms.push((op, times(a.clone(), det(m, row + 1, &rest, pos), pos)));
    }
    if terms.is_empty() {
        return Expr {
            kind: ExprKind::Number(Rational::ZERO),
            pos,
        };
    }
    Expr {
        kind: ExprKind::Sum(terms),
        pos,
    }
}
