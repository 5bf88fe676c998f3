//! `:pre`: the `let`s of a precondition inlined, its conjuncts, and the interval bounds among
//! them that become the sampling domain (see the parent module's documentation).
use super::super::sexpr::SExpr;
use super::super::{Bound, FpCoreError, Range};
use super::{list_items, literal};
use crate::program::CmpOp;
use crate::rational::Rational;

/// Whether `e` may be substituted for a name bound to it without changing any meaning: a
/// literal or a symbol (FPCore expressions have no side effects; these cost nothing twice).
fn inlinable(e: &SExpr) -> bool {
    match e {
        SExpr::Sym(s, _) => !s.starts_with(':'),
        _ => matches!(literal(e), Ok(Some(_))),
    }
}

/// `e` with every `let` / `let*` whose bound values are all literals or names replaced by its
/// body with those values substituted, innermost first (a `let` binding anything else stays).
/// Used on `:pre` only, so that interval bounds written through a `let` are seen as bounds.
pub(super) fn inline_lets(e: &SExpr) -> SExpr {
    let SExpr::List(items, pos) = e else {
        return e.clone();
    };
    let items: Vec<SExpr> = items.iter().map(inline_lets).collect();
    let head = items.first().and_then(SExpr::sym);
    if let (Some(kind @ ("let" | "let*")), [_, bindings, body]) = (head, &items[..]) {
        let pairs: Option<Vec<(&str, &SExpr)>> = list_items(bindings).and_then(|bs| {
            bs.iter()
                .map(|b| match list_items(b) {
                    Some([SExpr::Sym(n, _), v]) if inlinable(v) => Some((n.as_str(), v)),
                    _ => None,
                })
                .collect()
        });
        if let Some(pairs) = pairs {
            let sequential = kind == "let*";
            let distinct = sequential
                || pairs
                    .iter()
                    .enumerate()
                    .all(|(i, (n, _))| pairs[..i].iter().all(|(m, _)| m != n));
            if distinct {
                // `let*`: each value sees the bindings before it; `let`: none of them.
                let mut map: Vec<(&str, SExpr)> = Vec::new();
                for (n, v) in pairs {
                    let v = if sequential {
                        substitute(v, &map)
                    } else {
                        Some(v.clone())
                    };
                    let Some(v) = v else { break };
                    map.push((n, v));
                }
                if map.len() == list_items(bindings).map_or(0, <[SExpr]>::len) {
                    if let Some(inlined) = substitute(body, &map) {
                        return inlined;
                    }
                }
            }
        }
    }
    SExpr::List(items, *pos)
}

/// `e` with the names of `map` (innermost binding last) replaced by their values; `None` when a
/// binding form inside would capture a substituted name, or is one this does not scope (loops,
/// tensors): the caller then keeps its `let`.
fn substitute(e: &SExpr, map: &[(&str, SExpr)]) -> Option<SExpr> {
    match e {
        SExpr::Sym(s, _) => Some(
            map.iter()
                .rev()
                .find(|(n, _)| n == s)
                .map_or_else(|| e.clone(), |(_, v)| v.clone()),
        ),
        SExpr::Num(..) | SExpr::Str(..) => Some(e.clone()),
        SExpr::List(items, pos) => {
            let head = items.first().and_then(SExpr::sym);
            match (head, &items[..]) {
                (Some(kind @ ("let" | "let*")), [h, bindings, body]) => {
                    let bs = list_items(bindings)?;
                    let mut inner: Vec<(&str, SExpr)> = map.to_vec();
                    let mut new_bs = Vec::with_capacity(bs.len());
                    let mut bound: Vec<&str> = Vec::new();
                    for b in bs {
                        let [SExpr::Sym(n, npos), v] = list_items(b)? else {
                            return None;
                        };
                        let scope = if kind == "let*" { &inner[..] } else { map };
                        new_bs.push(SExpr::List(
                            vec![SExpr::Sym(n.clone(), *npos), substitute(v, scope)?],
                            b.pos(),
                        ));
                        bound.push(n);
                        if kind == "let*" {
                            inner.retain(|(m, _)| m != n);
                        }
                    }
                    // A substituted value naming a variable this form rebinds would be captured.
                    let captures = map
                        .iter()
                        .any(|(_, v)| v.sym().is_some_and(|s| bound.contains(&s)));
                    if captures {
                        return None;
                    }
                    inner.retain(|(m, _)| !bound.contains(m));
                    Some(SExpr::List(
                        vec![
                            h.clone(),
                            SExpr::List(new_bs, bindings.pos()),
                            substitute(body, &inner)?,
                        ],
                        *pos,
                    ))
                }
                (Some(h), _)
                    if h.starts_with("while")
                        || h.starts_with("for")
                        || h.starts_with("tensor") =>
                {
                    None
                }
                _ => {
                    // The operator in head position is not a variable.
                    let mut out = Vec::with_capacity(items.len());
                    for (i, it) in items.iter().enumerate() {
                        out.push(if i == 0 && it.sym().is_some() {
                            it.clone()
                        } else {
                            substitute(it, map)?
                        });
                    }
                    Some(SExpr::List(out, *pos))
                }
            }
        }
    }
}

/// The conjuncts of a precondition: nested `and`s flattened.
pub(super) fn conjuncts<'a>(e: &'a SExpr, out: &mut Vec<&'a SExpr>) {
    if let SExpr::List(items, _) = e {
        if items.first().and_then(SExpr::sym) == Some("and") {
            for c in &items[1..] {
                conjuncts(c, out);
            }
            return;
        }
    }
    out.push(e);
}

pub(super) fn cmp_op(s: &str) -> Option<CmpOp> {
    Some(match s {
        "<" => CmpOp::Lt,
        "<=" => CmpOp::Le,
        ">" => CmpOp::Gt,
        ">=" => CmpOp::Ge,
        "==" => CmpOp::Eq,
        "!=" => CmpOp::Ne,
        _ => return None,
    })
}

/// One adjacent pair of an ordered comparison chain of a `:pre` conjunct.
pub(super) enum PrePair<'a> {
    /// `arg op literal`, normalized with the argument on the left.
    Bound(usize, CmpOp, Rational),
    /// Anything else: a condition.
    Other(CmpOp, &'a SExpr, &'a SExpr),
}

/// The pairs of a comparison-chain conjunct (`None` for any other conjunct, and for `!=`, which
/// is never an interval bound).
pub(super) fn pre_pairs<'a>(
    e: &'a SExpr,
    args: &[String],
) -> Result<Option<Vec<PrePair<'a>>>, FpCoreError> {
    let Some(items) = list_items(e) else {
        return Ok(None);
    };
    let Some(op) = items.first().and_then(SExpr::sym).and_then(cmp_op) else {
        return Ok(None);
    };
    if op == CmpOp::Ne || items.len() < 3 {
        return Ok(None);
    }
    let arg = |x: &SExpr| x.sym().and_then(|s| args.iter().position(|a| a == s));
    let mut out = Vec::new();
    for w in items[1..].windows(2) {
        let (a, b) = (&w[0], &w[1]);
        let pair = match (arg(a), literal(b)?, literal(a)?, arg(b)) {
            (Some(i), Some(q), _, _) => PrePair::Bound(i, op, q),
            (_, _, Some(q), Some(i)) => PrePair::Bound(i, flip(op), q),
            _ => PrePair::Other(op, a, b),
        };
        out.push(pair);
    }
    Ok(Some(out))
}

/// `a op b` <=> `b flip(op) a`.
fn flip(op: CmpOp) -> CmpOp {
    match op {
        CmpOp::Lt => CmpOp::Gt,
        CmpOp::Le => CmpOp::Ge,
        CmpOp::Gt => CmpOp::Lt,
        CmpOp::Ge => CmpOp::Le,
        CmpOp::Eq => CmpOp::Eq,
        CmpOp::Ne => CmpOp::Ne,
    }
}

/// Is `new` a tighter lower bound than `old`?
fn tighter_lo(new: &Bound, old: &Bound) -> bool {
    match (new.value(), old.value()) {
        (None, _) => false,
        (Some(_), None) => true,
        (Some(n), Some(o)) => n > o || (n == o && matches!(new, Bound::Open(_))),
    }
}

/// Is `new` a tighter upper bound than `old`?
fn tighter_hi(new: &Bound, old: &Bound) -> bool {
    match (new.value(), old.value()) {
        (None, _) => false,
        (Some(_), None) => true,
        (Some(n), Some(o)) => n < o || (n == o && matches!(new, Bound::Open(_))),
    }
}

/// The sampling intervals given by the interval bounds of `:pre`.
pub(super) fn domain(pre: &SExpr, args: &[String]) -> Result<Vec<Range>, FpCoreError> {
    let mut dom = vec![Range::UNBOUNDED; args.len()];
    let mut cs = Vec::new();
    conjuncts(pre, &mut cs);
    for c in cs {
        for pair in pre_pairs(c, args)?.unwrap_or_default() {
            let PrePair::Bound(i, op, q) = pair else {
                continue;
            };
            let (lo, hi) = match op {
                CmpOp::Lt => (None, Some(Bound::Open(q))),
                CmpOp::Le => (None, Some(Bound::Closed(q))),
                CmpOp::Gt => (Some(Bound::Open(q)), None),
                CmpOp::Ge => (Some(Bound::Closed(q)), None),
                CmpOp::Eq => (Some(Bound::Closed(q.clone())), Some(Bound::Closed(q))),
                CmpOp::Ne => unreachable!("`!=` is never split into bounds"),
            };
            if let Some(lo) = lo {
                if tighter_lo(&lo, &dom[i].lo) {
                    dom[i].lo = lo;
                }
            }
            if let Some(hi) = hi {
                if tighter_hi(&hi, &dom[i].hi) {
                    dom[i].hi = hi;
                }
            }
        }
    }
    Ok(dom)
}
