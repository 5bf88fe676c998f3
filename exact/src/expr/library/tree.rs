//! Walking and rewriting expression trees: visiting, substituting (with the binders of
//! `diff`, `integrate` and `sum` respected), positions and sizes.

use super::*;
pub(super) use crate::expr::map::at_pos;

/// Appends the names of the calls in `e` to `out` (each once).
pub(super) fn collect_calls(e: &Expr, out: &mut Vec<String>) {
    map_tree(e, &mut |x| {
        if let ExprKind::Call(n, _) = &x.kind {
            if !out.contains(n) {
                out.push(n.clone());
            }
        }
    });
}

/// Visits every node of `e` (children first).
pub(crate) fn map_tree(e: &Expr, f: &mut dyn FnMut(&Expr)) {
    match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => {}
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => map_tree(x, f),
        ExprKind::Pow(x, k) => {
            map_tree(x, f);
            map_tree(k, f);
        }
        ExprKind::Sum(ts) => ts.iter().for_each(|(_, t)| map_tree(t, f)),
        ExprKind::Product(fs) => fs.iter().for_each(|(_, t)| map_tree(t, f)),
        ExprKind::Call(_, args) => args.iter().for_each(|a| map_tree(a, f)),
    }
    f(e);
}

/// `e` with the variable `v` replaced by `value`, binders ignored: for renaming a bound
/// variable and for values that cannot be captured (integration bounds); every front end
/// substitutes with [`substitute_free`].
pub fn substitute(e: &Expr, v: &str, value: &Expr) -> Expr {
    rebuild(e, &|x| match &x.kind {
        ExprKind::Var(n) if n == v => at_pos(value, x.pos),
        _ => x,
    })
}

/// `e` with the free occurrences of the variable `v` replaced by `value`, as `subs` means it:
/// the substitution comes after every construct inside. A `diff` in `v` (or in a variable
/// `value` mentions) is differentiated first, so `subs(diff(E, t), t, 0)` is `E'(0)`; the
/// bound variable of `integrate` and `sum` is not replaced (only the bounds are), and is
/// renamed when `value` mentions it, so that no variable of `value` is captured.
///
/// # Errors
/// The one-line reason when a `diff` to take first cannot be taken exactly.
pub fn substitute_free(e: &Expr, v: &str, value: &Expr) -> Result<Expr, String> {
    let sub = |x: &Expr| substitute_free(x, v, value);
    let mentions = |name: &str| {
        let mut found = false;
        map_tree(value, &mut |x| {
            found |= matches!(&x.kind, ExprKind::Var(n) if n == name);
        });
        found
    };
    let kind = match &e.kind {
        ExprKind::Var(n) if n == v => return Ok(at_pos(value, e.pos)),
        ExprKind::Call(name, args) => {
            let var_at = |i: usize| match args.get(i).map(|a| &a.kind) {
                Some(ExprKind::Var(n)) => Some(n.as_str()),
                _ => None,
            };
            // (argument index of the variable, indices of the arguments where it is bound).
            let binder: Option<(usize, &[usize])> = match (name.as_str(), args.len()) {
                ("diff", 2 | 3) => Some((1, &[0, 1])),
                ("integrate", 4) => Some((1, &[0, 1])),
                ("sum", 4) => Some((0, &[0, 3])),
                _ => None,
            };
            match binder.and_then(|(i, bound)| Some((var_at(i)?, bound))) {
                Some((t, _)) if name == "diff" && (t == v || mentions(t)) => {
                    return sub(&derivative_first(e)?);
                }
                Some((t, bound)) if t == v || mentions(t) => {
                    // Only the bounds see the substitution; the bound variable is renamed
                    // apart from `value` (and from `v`) when `value` mentions it.
                    let args = if t == v || !mentions(t) {
                        args.clone()
                    } else {
                        let fresh = fresh_name(t, e, value);
                        let renamed = Expr {
                            kind: ExprKind::Var(fresh),
                            pos: e.pos,
                        };
                        args.iter()
                            .enumerate()
                            .map(|(j, a)| {
                                if bound.contains(&j) {
                                    substitute(a, t, &renamed)
                                } else {
                                    a.clone()
                                }
                            })
                            .collect()
                    };
                    let keep_bound = t == v;
                    ExprKind::Call(
                        name.clone(),
                        args.iter()
                            .enumerate()
                            .map(|(j, a)| {
                                if keep_bound && bound.contains(&j) {
                                    Ok(a.clone())
                                } else {
                                    sub(a)
                                }
                            })
                            .collect::<Result<_, String>>()?,
                    )
                }
                Some((_, _)) if name == "diff" => ExprKind::Call(
                    name.clone(),
                    args.iter()
                        .enumerate()
                        .map(|(j, a)| if j == 1 { Ok(a.clone()) } else { sub(a) })
                        .collect::<Result<_, String>>()?,
                ),
                _ => return e.try_map_children(sub),
            }
        }
        _ => return e.try_map_children(sub),
    };
    Ok(Expr { kind, pos: e.pos })
}

/// A variable name based on `base` that occurs in neither `e` nor `value`.
pub(super) fn fresh_name(base: &str, e: &Expr, value: &Expr) -> String {
    let mut taken = HashSet::new();
    for tree in [e, value] {
        map_tree(tree, &mut |x| {
            if let ExprKind::Var(n) = &x.kind {
                taken.insert(n.clone());
            }
        });
    }
    (1..)
        .map(|k| format!("{base}{k}"))
        .find(|n| !taken.contains(n))
        .expect("a finite tree leaves some name free")
}

/// The call `diff(E, t[, k])` taken: the derivative as an expression (numerator over
/// denominator, with rational coefficients), positioned at the call. A square root of an
/// expression is a variable of the conversion, written back as the root itself
/// ([`ratfun_to_expr`](crate::expr::from_poly::ratfun_to_expr)): `diff(sqrt(x), x)` is
/// `1/(2*sqrt(x))`.
pub(super) fn derivative_first(call: &Expr) -> Result<Expr, String> {
    let mut vars = crate::poly::Vars::new();
    vars.allow_roots();
    let f = call
        .to_ratfun::<Rational>(&mut vars)
        .map_err(|e| format!("the derivative {call} is taken first, and fails: {e}"))?;
    Ok(at_pos(
        &crate::expr::from_poly::ratfun_to_expr(&f, &vars),
        call.pos,
    ))
}

/// Rebuilds `e` bottom-up, handing every rebuilt node (its children done) to `f`.
pub(super) fn rebuild(e: &Expr, f: &dyn Fn(Expr) -> Expr) -> Expr {
    f(e.map_children(|x| rebuild(x, f)))
}

/// The number of nodes of a tree.
pub fn count_nodes(e: &Expr) -> usize {
    let mut n = 0;
    map_tree(e, &mut |_| n += 1);
    n
}

/// Whether the tree contains `sqrt` or a power that is not an integer (`2^(1/3)`): then the
/// radical coefficient field, or the algebraic numbers, are needed.
pub fn has_sqrt(e: &Expr) -> bool {
    let mut found = false;
    map_tree(e, &mut |x| {
        found |= match &x.kind {
            ExprKind::Sqrt(_) => true,
            ExprKind::Pow(_, exp) => exp
                .eval_constant::<crate::Rational>()
                .is_ok_and(|q| !q.is_integer()),
            _ => false,
        }
    });
    found
}

/// Why `diff` cannot be read in the presence of `relations`, or `None`: a `diff(E, t)` in
/// `sides` whose `E` has a variable `y` other than `t` that a relation ties to `t`. A relation
/// holds at points and does not make `y` a function of `t`: `diff(y, t)` is 0 with `y` and `t`
/// independent, which is not the derivative the relation `y = t^2` suggests. The caller refuses
/// such an identity instead of proving a statement about partial derivatives that may not be
/// the one meant.
pub fn diff_against_relations(sides: &[&Expr], relations: &[(&Expr, &Expr)]) -> Option<String> {
    let mut related: Vec<Vec<String>> = Vec::new();
    for (a, b) in relations {
        let mut vs = Vec::new();
        a.collect_variables(&mut vs);
        b.collect_variables(&mut vs);
        related.push(vs);
    }
    let mut found = None;
    for side in sides {
        map_tree(side, &mut |x| {
            let ExprKind::Call(name, args) = &x.kind else {
                return;
            };
            let (true, Some(body), Some(ExprKind::Var(t))) = (
                name == "diff" && found.is_none(),
                args.first(),
                args.get(1).map(|a| &a.kind),
            ) else {
                return;
            };
            let mut vs = Vec::new();
            body.collect_variables(&mut vs);
            for y in vs.iter().filter(|y| *y != t) {
                if related.iter().any(|r| r.contains(y) && r.contains(t)) {
                    found = Some(format!(
                        "{x} differentiates in {t} an expression with {y}, and a relation ties {y} to {t}: relations hold at points and do not make {y} a function of {t} (diff treats {y} as independent); substitute the relation into the expression first"
                    ));
                    return;
                }
            }
        });
    }
    found
}
