//! The library functions computed on resolved values: vectors, matrices, Bernstein
//! polynomials and Bezier curves.

use super::*;

/// A library function applied to resolved arguments (`vals`: value and position).
pub(super) fn library_call(name: &str, vals: &[(Val, usize)], pos: usize) -> R<Val> {
    let node = |kind: ExprKind| Expr { kind, pos };
    let vector = |v: &(Val, usize), what: &str| -> R<Vec<Expr>> {
        match &v.0 {
            Val::Vector(xs) => Ok(xs.clone()),
            other => err(format!(
                "{} at {} where a vector is expected ({what} of {name})",
                other.shape(),
                v.1
            )),
        }
    };
    let matrix = |v: &(Val, usize)| -> R<Vec<Vec<Expr>>> {
        match &v.0 {
            Val::Matrix(rows) => Ok(rows.clone()),
            other => err(format!(
                "{} at {} where a matrix is expected (the argument of {name}; a matrix is [[a, b], [c, d]])",
                other.shape(),
                v.1
            )),
        }
    };
    let scalar = |v: &(Val, usize), what: &str| -> R<Expr> {
        match &v.0 {
            Val::Scalar(x) => Ok(x.clone()),
            other => err(format!(
                "{} at {} where a scalar is expected ({what} of {name})",
                other.shape(),
                v.1
            )),
        }
    };
    let int = |v: &(Val, usize), what: &str| -> R<u32> {
        let x = scalar(v, what)?;
        let q = x
            .eval_constant::<Rational>()
            .ok()
            .filter(|q| q.is_integer());
        match q.and_then(|q| q.to_string().parse::<u32>().ok()) {
            Some(k) => Ok(k),
            _ => err(format!(
                "{what} of {name} at {} must be a non-negative integer constant",
                v.1
            )),
        }
    };
    let same_length = |u: &[Expr], v: &[Expr]| -> R<()> {
        if u.len() == v.len() {
            Ok(())
        } else {
            err(format!(
                "{name} at {pos}: vectors of {} and {} coordinates",
                u.len(),
                v.len()
            ))
        }
    };
    let coordinate = |v: &(Val, usize), i: usize| -> R<Val> {
        let xs = vector(v, "the argument")?;
        match xs.get(i) {
            Some(x) => Ok(Val::Scalar(x.clone())),
            None => err(format!(
                "{name} at {pos}: coordinate {} of a vector of {}",
                i + 1,
                xs.len()
            )),
        }
    };
    Ok(match name {
        "vec" => Val::Vector(
            vals.iter()
                .map(|v| scalar(v, "a coordinate"))
                .collect::<R<_>>()?,
        ),
        "dot" => {
            let u = vector(&vals[0], "the first argument")?;
            let v = vector(&vals[1], "the second argument")?;
            same_length(&u, &v)?;
            Val::Scalar(inner(&u, &v, pos))
        }
        "norm2" => {
            let v = vector(&vals[0], "the argument")?;
            Val::Scalar(inner(&v, &v, pos))
        }
        "cross" => {
            let u = vector(&vals[0], "the first argument")?;
            let v = vector(&vals[1], "the second argument")?;
            let minus =
                |a: Expr, b: Expr| node(ExprKind::Sum(vec![(AddOp::Plus, a), (AddOp::Minus, b)]));
            let c = |i: usize, j: usize| {
                minus(
                    times(u[i].clone(), v[j].clone(), pos),
                    times(u[j].clone(), v[i].clone(), pos),
                )
            };
            match (u.len(), v.len()) {
                (2, 2) => Val::Scalar(c(0, 1)),
                (3, 3) => Val::Vector(vec![c(1, 2), c(2, 0), c(0, 1)]),
                (a, b) => {
                    return err(format!(
                        "cross at {pos} takes two 2-vectors or two 3-vectors, not vectors of {a} and {b}"
                    ))
                }
            }
        }
        "x" => coordinate(&vals[0], 0)?,
        "y" => coordinate(&vals[0], 1)?,
        "z" => coordinate(&vals[0], 2)?,
        "at" => {
            let i = int(&vals[1], "the index")?;
            if i == 0 {
                return err(format!(
                    "at at {pos}: coordinates count from 1 (at(v, 1) is the first)"
                ));
            }
            coordinate(&vals[0], i as usize - 1)?
        }
        "det" => {
            let m = matrix(&vals[0])?;
            let (r, c) = (m.len(), m[0].len());
            if r != c {
                return err(format!(
                    "det at {pos} takes a square matrix, not a {r}x{c} matrix"
                ));
            }
            let entry = m.iter().flatten().map(count_nodes).max().unwrap_or(1);
            if det_nodes(r, entry) > MAX_NODES {
                return err(format!(
                    "det at {pos} of a {r}x{r} matrix: {}",
                    too_many_nodes(pos)
                ));
            }
            let cols: Vec<usize> = (0..c).collect();
            Val::Scalar(det(&m, 0, &cols, pos))
        }
        "transpose" => Val::Matrix(transposed(&matrix(&vals[0])?)),
        "bernstein" => {
            let i = int(&vals[0], "i")?;
            let n = int(&vals[1], "n")?;
            limits::BERNSTEIN_DEGREE
                .check(u64::from(n))
                .map_err(|e| ResolveError {
                    def: None,
                    message: format!("bernstein at {pos}: {e}"),
                })?;
            if i > n {
                return err(format!("bernstein at {pos}: i = {i} > n = {n}"));
            }
            let t = scalar(&vals[2], "t")?;
            Val::Scalar(bernstein(i, n, &t, pos))
        }
        "bezier" => {
            let t = scalar(&vals[0], "t")?;
            let n = (vals.len() - 2) as u32;
            let points = &vals[1..];
            if points.iter().any(|(v, _)| matches!(v, Val::Matrix(_)))
                || points.iter().any(|(v, _)| !v.same_shape(&points[0].0))
            {
                return err(format!(
                    "bezier at {pos}: the control points must all be scalars or all vectors of one length"
                ));
            }
            let weights: Vec<Expr> = (0..=n).map(|i| bernstein(i, n, &t, pos)).collect();
            let split: Vec<Vec<&Expr>> = points.iter().map(|(v, _)| v.parts()).collect();
            let comb = |k: usize| {
                plus(
                    split
                        .iter()
                        .zip(&weights)
                        .map(|(xs, w)| {
                            // The weight of a degree-0 curve is 1: the point alone.
                            if matches!(&w.kind, ExprKind::Number(q) if *q == Rational::ONE) {
                                xs[k].clone()
                            } else {
                                times(w.clone(), xs[k].clone(), pos)
                            }
                        })
                        .collect(),
                    pos,
                )
            };
            match &points[0].0 {
                Val::Vector(xs) => Val::Vector((0..xs.len()).map(comb).collect()),
                _ => Val::Scalar(comb(0)),
            }
        }
        other => unreachable!("{other} is in LIBRARY and handled above"),
    })
}

/// `C(n, i) t^i (1 - t)^(n - i)` as a tree.
pub(super) fn bernstein(i: u32, n: u32, t: &Expr, pos: usize) -> Expr {
    let node = |kind: ExprKind| Expr { kind, pos };
    let num = |q: Rational| node(ExprKind::Number(q));
    let int = |k: u64| num(Rational::from_integer(k as i64));
    // C(n, i) exactly: C(n, k + 1) = C(n, k) (n - k) / (k + 1), an exact integer division.
    let mut c = num_bigint::BigInt::from(1u32);
    for k in 0..i {
        c = c * (n - k) / (k + 1);
    }
    let c = Rational::from(c);
    let one_minus_t = node(ExprKind::Sum(vec![
        (AddOp::Plus, int(1)),
        (AddOp::Minus, t.clone()),
    ]));
    // Factors 1, t^0 and (1 - t)^0 are left out and exponents 1 not written, so the tree
    // prints as a formula would be written (`3 t (1 - t)^2`, `t^3`).
    let mut factors = Vec::new();
    if c != Rational::ONE {
        factors.push(num(c));
    }
    for (base, k) in [(t.clone(), i), (one_minus_t, n - i)] {
        match k {
            0 => {}
            1 => factors.push(base),
            k => factors.push(node(ExprKind::Pow(
                Box::new(base),
                Box::new(int(u64::from(k))),
            ))),
        }
    }
    match factors.len() {
        0 => int(1),
        1 => factors.pop().expect("one factor"),
        _ => node(ExprKind::Product(
            factors.into_iter().map(|f| (MulOp::Times, f)).collect(),
        )),
    }
}
