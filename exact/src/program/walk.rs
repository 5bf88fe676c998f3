//! The one tree walk of a [`Program`](super::Program), generic over the arithmetic it is done in
//! ([`Evaluator`]): IEEE doubles (`float`), the exact reals of `real` (rationals and refined
//! intervals) and the multi-quadratic field [`crate::Radical`] (the exact zero test of `real`).
//!
//! The walk owns the evaluation order (the tree's, left operand first), the precision in scope
//! ([`Node::Precision`], which a float domain rounds to), `let` binding, loops
//! (their binding orders; the domain counts the iterations), `if`
//! (only the chosen branch is evaluated) and conditions (`and`/`or` short-circuit from the left,
//! as a compiled C program does); a domain supplies the operations and a possibly failing
//! decision of a comparison. Values are moved, not borrowed, so a domain of `Copy` numbers
//! (`f64`) compiles to straight-line float code with no allocation, and `Result<_, Infallible>`
//! costs nothing.
use super::{ChainOp, CmpOp, Cond, Format, Func, Loop, Node, PowStyle};
use crate::rational::Rational;

/// The arithmetic a program is evaluated in.
pub(crate) trait Evaluator {
    /// A value.
    type V: Clone;
    /// Why an evaluation stops (never for `f64`).
    type Stop;
    /// Input number `i`.
    fn input(&mut self, i: usize) -> Self::V;
    /// A literal.
    fn constant(&mut self, q: &Rational) -> Result<Self::V, Self::Stop>;
    /// `-a`.
    fn neg(&mut self, a: Self::V) -> Result<Self::V, Self::Stop>;
    /// `a + b`.
    fn add(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::Stop>;
    /// `a - b`.
    fn sub(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::Stop>;
    /// `a * b`.
    fn mul(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::Stop>;
    /// `a / b`.
    fn div(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::Stop>;
    /// `sqrt(a)`.
    fn sqrt(&mut self, a: Self::V) -> Result<Self::V, Self::Stop>;
    /// `|a|`.
    fn abs(&mut self, a: Self::V) -> Result<Self::V, Self::Stop>;
    /// `a * b + c` (fused where that means something).
    fn fma(&mut self, a: Self::V, b: Self::V, c: Self::V) -> Result<Self::V, Self::Stop>;
    /// `min(a, b)`.
    fn min(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::Stop>;
    /// `max(a, b)`.
    fn max(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::Stop>;
    /// `a^n`.
    fn pow(&mut self, a: Self::V, n: i32, style: PowStyle) -> Result<Self::V, Self::Stop>;
    /// The function `f` at its arguments (`a` and `b` present as [`Func::arity`] says).
    fn call(
        &mut self,
        f: Func,
        a: Option<Self::V>,
        b: Option<Self::V>,
    ) -> Result<Self::V, Self::Stop>;
    /// The truth of `a op b`.
    fn compare(&mut self, op: CmpOp, a: &Self::V, b: &Self::V) -> Result<bool, Self::Stop>;
    /// Counts one more loop iteration of this evaluation; the stop once the count exceeds the
    /// `loop-iterations` limit.
    fn iterate(&mut self) -> Result<(), Self::Stop>;
    /// A loop variable's new value as the loop keeps it (by default unchanged; the exact domain
    /// turns a rational grown too large for its working precision into an enclosure).
    fn carry(&mut self, v: Self::V) -> Result<Self::V, Self::Stop> {
        Ok(v)
    }
    /// Makes `f` the precision the operations round to, returning the one it replaces (by
    /// default nothing changes: the exact domains compute real numbers).
    fn set_format(&mut self, f: Format) -> Result<Format, Self::Stop> {
        Ok(f)
    }
    /// `v` rounded to the precision in scope (by default unchanged).
    fn cast(&mut self, v: Self::V) -> Result<Self::V, Self::Stop> {
        Ok(v)
    }
}

/// Counts one iteration into `count`; `false` once it exceeds the `loop-iterations` limit.
pub(crate) fn count_iteration(count: &mut u64) -> bool {
    *count += 1;
    *count <= exactcheck_core::limits::LOOP_ITERATIONS.get()
}

/// The value of `node`, with `let` slots in `slots`.
///
/// # Panics
/// On a slot or input index out of range (a malformed program: the compilers never build one).
pub(crate) fn eval_node<D: Evaluator>(
    d: &mut D,
    node: &Node,
    slots: &mut [D::V],
) -> Result<D::V, D::Stop> {
    Ok(match node {
        Node::Input(i) => d.input(*i),
        Node::Slot(i) => slots[*i].clone(),
        Node::Const(q) => d.constant(q)?,
        Node::Neg(a) => {
            let a = eval_node(d, a, slots)?;
            d.neg(a)?
        }
        Node::Add(a, b) => {
            let a = eval_node(d, a, slots)?;
            let b = eval_node(d, b, slots)?;
            d.add(a, b)?
        }
        Node::Sub(a, b) => {
            let a = eval_node(d, a, slots)?;
            let b = eval_node(d, b, slots)?;
            d.sub(a, b)?
        }
        Node::Mul(a, b) => {
            let a = eval_node(d, a, slots)?;
            let b = eval_node(d, b, slots)?;
            d.mul(a, b)?
        }
        Node::Div(a, b) => {
            let a = eval_node(d, a, slots)?;
            let b = eval_node(d, b, slots)?;
            d.div(a, b)?
        }
        Node::Chain(first, rest) => {
            let mut acc = eval_node(d, first, slots)?;
            for (op, b) in rest {
                let b = eval_node(d, b, slots)?;
                acc = match op {
                    ChainOp::Add => d.add(acc, b)?,
                    ChainOp::Sub => d.sub(acc, b)?,
                    ChainOp::Mul => d.mul(acc, b)?,
                    ChainOp::Div => d.div(acc, b)?,
                };
            }
            acc
        }
        Node::Sqrt(a) => {
            let a = eval_node(d, a, slots)?;
            d.sqrt(a)?
        }
        Node::Abs(a) => {
            let a = eval_node(d, a, slots)?;
            d.abs(a)?
        }
        Node::Fma(a, b, c) => {
            let a = eval_node(d, a, slots)?;
            let b = eval_node(d, b, slots)?;
            let c = eval_node(d, c, slots)?;
            d.fma(a, b, c)?
        }
        Node::Min(a, b) => {
            let a = eval_node(d, a, slots)?;
            let b = eval_node(d, b, slots)?;
            d.min(a, b)?
        }
        Node::Max(a, b) => {
            let a = eval_node(d, a, slots)?;
            let b = eval_node(d, b, slots)?;
            d.max(a, b)?
        }
        Node::Pow(a, n, style) => {
            let a = eval_node(d, a, slots)?;
            d.pow(a, *n, *style)?
        }
        Node::Let(bindings, body) => {
            for (slot, value) in bindings {
                let v = eval_node(d, value, slots)?;
                slots[*slot] = v;
            }
            eval_node(d, body, slots)?
        }
        Node::If(cond, then, otherwise) => {
            if eval_cond(d, cond, slots)? {
                eval_node(d, then, slots)?
            } else {
                eval_node(d, otherwise, slots)?
            }
        }
        Node::Fun(f, args) => {
            let a = match args.first() {
                Some(n) => Some(eval_node(d, n, slots)?),
                None => None,
            };
            let b = match args.get(1) {
                Some(n) => Some(eval_node(d, n, slots)?),
                None => None,
            };
            d.call(*f, a, b)?
        }
        Node::While(l) => eval_loop(d, l, slots)?,
        Node::Precision(f, a) => {
            let outer = d.set_format(*f)?;
            let v = eval_node(d, a, slots);
            d.set_format(outer)?;
            v?
        }
        Node::Cast(a) => {
            let a = eval_node(d, a, slots)?;
            d.cast(a)?
        }
    })
}

/// The value of a loop (see [`Loop`] for the two binding orders).
fn eval_loop<D: Evaluator>(d: &mut D, l: &Loop, slots: &mut [D::V]) -> Result<D::V, D::Stop> {
    let step = |d: &mut D, slots: &mut [D::V], initial: bool| -> Result<(), D::Stop> {
        if l.sequential {
            for (s, init, update) in &l.vars {
                let x = eval_node(d, if initial { init } else { update }, slots)?;
                slots[*s] = d.carry(x)?;
            }
        } else {
            let mut values = Vec::with_capacity(l.vars.len());
            for (s, init, update) in &l.vars {
                let x = eval_node(d, if initial { init } else { update }, slots)?;
                values.push((*s, d.carry(x)?));
            }
            for (s, x) in values {
                slots[s] = x;
            }
        }
        Ok(())
    };
    step(d, slots, true)?;
    while eval_cond(d, &l.cond, slots)? {
        d.iterate()?;
        step(d, slots, false)?;
    }
    eval_node(d, &l.body, slots)
}

/// The truth of `cond`.
pub(crate) fn eval_cond<D: Evaluator>(
    d: &mut D,
    cond: &Cond,
    slots: &mut [D::V],
) -> Result<bool, D::Stop> {
    Ok(match cond {
        Cond::Bool(b) => *b,
        Cond::Cmp(op, a, b) => {
            let a = eval_node(d, a, slots)?;
            let b = eval_node(d, b, slots)?;
            d.compare(*op, &a, &b)?
        }
        Cond::And(cs) => {
            for c in cs {
                if !eval_cond(d, c, slots)? {
                    return Ok(false);
                }
            }
            true
        }
        Cond::Or(cs) => {
            for c in cs {
                if eval_cond(d, c, slots)? {
                    return Ok(true);
                }
            }
            false
        }
        Cond::Not(c) => !eval_cond(d, c, slots)?,
    })
}
