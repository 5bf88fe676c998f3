//! The one rebuild of an expression node from its mapped children. Every rewrite of a tree in
//! `expr` (positions, substitution, angle expansion, constant leaves, lowering) handles the node
//! kinds it changes and hands every other node to [`Expr::try_map_children`] or
//! [`Expr::map_children`], so the list of node kinds and their children is written once.

use super::{Expr, ExprKind};
use std::convert::Infallible;

impl Expr {
    /// This node with every child replaced by `f(child)`, in order (a power's base before its
    /// exponent), its position kept; a number or a variable is cloned. The first error of `f`
    /// stops the rebuild.
    ///
    /// # Errors
    /// The first error of `f`.
    pub(crate) fn try_map_children<E>(
        &self,
        mut f: impl FnMut(&Expr) -> Result<Expr, E>,
    ) -> Result<Expr, E> {
        let kind = match &self.kind {
            ExprKind::Number(_) | ExprKind::Var(_) => self.kind.clone(),
            ExprKind::Neg(x) => ExprKind::Neg(Box::new(f(x)?)),
            ExprKind::Sqrt(x) => ExprKind::Sqrt(Box::new(f(x)?)),
            ExprKind::Pow(a, k) => {
                let a = f(a)?;
                ExprKind::Pow(Box::new(a), Box::new(f(k)?))
            }
            ExprKind::Sum(ts) => ExprKind::Sum(
                ts.iter()
                    .map(|(op, t)| Ok((*op, f(t)?)))
                    .collect::<Result<_, E>>()?,
            ),
            ExprKind::Product(fs) => ExprKind::Product(
                fs.iter()
                    .map(|(op, x)| Ok((*op, f(x)?)))
                    .collect::<Result<_, E>>()?,
            ),
            ExprKind::Call(name, args) => {
                ExprKind::Call(name.clone(), args.iter().map(f).collect::<Result<_, E>>()?)
            }
        };
        Ok(Expr {
            kind,
            pos: self.pos,
        })
    }

    /// This node with every child replaced by `f(child)`, its position kept (the infallible
    /// [`Expr::try_map_children`]).
    pub(crate) fn map_children(&self, mut f: impl FnMut(&Expr) -> Expr) -> Expr {
        match self.try_map_children(|x| Ok::<_, Infallible>(f(x))) {
            Ok(e) => e,
            Err(never) => match never {},
        }
    }
}

/// `e` with every position set to `pos`: a tree built from text or computed for the node at
/// `pos` takes its position.
pub(crate) fn at_pos(e: &Expr, pos: usize) -> Expr {
    let mut x = e.map_children(|c| at_pos(c, pos));
    x.pos = pos;
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr;

    fn positions(e: &Expr, out: &mut Vec<usize>) {
        out.push(e.pos);
        e.map_children(|c| {
            positions(c, out);
            c.clone()
        });
    }

    #[test]
    fn map_children_keeps_the_node_and_maps_every_child_in_order() {
        for text in [
            "-x",
            "sqrt(2 + y)",
            "a^b",
            "x - y + 3",
            "x*y/z",
            "diff(x^2 + y, x)",
            "7",
            "t",
        ] {
            let e = parse_expr(text).unwrap();
            // The identity map rebuilds the same tree.
            assert_eq!(e.map_children(Clone::clone), e, "{text}");
            // Children are visited left to right.
            let mut seen = Vec::new();
            e.map_children(|c| {
                seen.push(c.to_string());
                c.clone()
            });
            let want: Vec<String> = match &e.kind {
                ExprKind::Number(_) | ExprKind::Var(_) => vec![],
                ExprKind::Neg(x) | ExprKind::Sqrt(x) => vec![x.to_string()],
                ExprKind::Pow(a, k) => vec![a.to_string(), k.to_string()],
                ExprKind::Sum(ts) => ts.iter().map(|(_, t)| t.to_string()).collect(),
                ExprKind::Product(fs) => fs.iter().map(|(_, t)| t.to_string()).collect(),
                ExprKind::Call(_, args) => args.iter().map(ToString::to_string).collect(),
            };
            assert_eq!(seen, want, "{text}");
        }
    }

    #[test]
    fn try_map_children_stops_at_the_first_error() {
        let e = parse_expr("a + b + c").unwrap();
        let mut calls = 0;
        let r: Result<Expr, String> = e.try_map_children(|c| {
            calls += 1;
            if c.to_string() == "b" {
                Err("b".into())
            } else {
                Ok(c.clone())
            }
        });
        assert_eq!(r, Err("b".to_string()));
        assert_eq!(calls, 2);
    }

    #[test]
    fn at_pos_sets_every_position() {
        let e = parse_expr("-(x + 2^y) * sqrt(z)").unwrap();
        let moved = at_pos(&e, 42);
        let mut ps = Vec::new();
        positions(&moved, &mut ps);
        assert!(ps.len() > 5 && ps.iter().all(|&p| p == 42), "{ps:?}");
        assert_eq!(moved.to_string(), e.to_string());
    }
}
