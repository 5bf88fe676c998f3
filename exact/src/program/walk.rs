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
use super::{node_ops, ChainOp, CmpOp, Cond, Format, Func, Loop, Node, PowStyle};
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
    /// The loop iterations counted so far, for a domain that counts a loop's iterations ahead
    /// (see [`eval_loop`]); `None` (the default) for a domain where an iteration is cheap.
    fn iteration_count(&mut self) -> Option<&mut u64> {
        None
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
///
/// A domain that counts ahead ([`Evaluator::iteration_count`]) first runs the loop's *control*
/// variables alone ([`control_vars`]: those the condition reads, and those their values read,
/// when they are not all of them) on a copy of the slots. They are computed exactly as in the
/// whole loop, so the whole loop runs the same iterations: if they run past the
/// `loop-iterations` limit, the loop stops there, at the limit's stop, before any other variable
/// is computed (a loop counting `i` to two million does not compute its state ten thousand
/// times to learn that). Otherwise (they end within the limit, or stop for another reason) the
/// count is put back and the whole loop runs as written.
fn eval_loop<D: Evaluator>(d: &mut D, l: &Loop, slots: &mut [D::V]) -> Result<D::V, D::Stop> {
    if d.iteration_count().is_some() {
        if let Some(control) = control_vars(l) {
            count_ahead(d, l, &control, slots)?;
        }
    }
    run_loop(d, l, None, slots)?;
    eval_node(d, &l.body, slots)
}

/// Runs the loop `l` (its initial values, then the updates while its condition holds) on
/// `slots`, with only the variables `only` lists (indices into `l.vars`, in order) when given.
fn run_loop<D: Evaluator>(
    d: &mut D,
    l: &Loop,
    only: Option<&[usize]>,
    slots: &mut [D::V],
) -> Result<(), D::Stop> {
    let vars: Vec<&(usize, Node, Node)> = match only {
        Some(only) => only.iter().map(|&k| &l.vars[k]).collect(),
        None => l.vars.iter().collect(),
    };
    let step = |d: &mut D, slots: &mut [D::V], initial: bool| -> Result<(), D::Stop> {
        if l.sequential {
            for (s, init, update) in vars.iter().copied() {
                let x = eval_node(d, if initial { init } else { update }, slots)?;
                slots[*s] = d.carry(x)?;
            }
        } else {
            let mut values = Vec::with_capacity(vars.len());
            for (s, init, update) in vars.iter().copied() {
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
    Ok(())
}

/// Runs the control variables `control` of `l` alone on a copy of `slots`: the stop of the
/// `loop-iterations` limit if they run past it, `Ok` otherwise (the iteration count as it was).
/// Every other stop of theirs is left to the whole loop, which meets it too, unless one of the
/// other variables stops it earlier.
fn count_ahead<D: Evaluator>(
    d: &mut D,
    l: &Loop,
    control: &[usize],
    slots: &[D::V],
) -> Result<(), D::Stop> {
    let Some(&mut before) = d.iteration_count() else {
        return Ok(());
    };
    let mut copy = slots.to_vec();
    let outcome = run_loop(d, l, Some(control), &mut copy);
    let count = d.iteration_count().expect("the domain counts ahead");
    // Only `iterate` raises the count, and it stops exactly when the count passes the limit.
    // The count stays past the limit with the stop, as after `iterate`'s own stop.
    match outcome {
        Err(stop) if *count > exactcheck_core::limits::LOOP_ITERATIONS.get() => Err(stop),
        _ => {
            *count = before;
            Ok(())
        }
    }
}

/// The control variables of `l` (indices into `l.vars`, in order): every variable whose slot
/// the condition reads, and, repeatedly, every variable whose initial value or update writes a
/// slot that a control variable's initial value or update reads. `None` when their initial
/// values and updates are more than a quarter of the loop's operations (each variable counted
/// one more): counting ahead would then cost too much of a loop that ends within the limit.
pub(super) fn control_vars(l: &Loop) -> Option<Vec<usize>> {
    let mut read = Vec::new();
    cond_slots(&l.cond, &mut read);
    let written: Vec<Vec<usize>> = l
        .vars
        .iter()
        .map(|(s, init, update)| {
            let mut w = vec![*s];
            written_slots(init, &mut w);
            written_slots(update, &mut w);
            w
        })
        .collect();
    let mut control = vec![false; l.vars.len()];
    loop {
        let mut grew = false;
        for (k, w) in written.iter().enumerate() {
            if !control[k] && w.iter().any(|s| read.contains(s)) {
                control[k] = true;
                grew = true;
                let (_, init, update) = &l.vars[k];
                node_slots(init, &mut read);
                node_slots(update, &mut read);
            }
        }
        if !grew {
            break;
        }
    }
    // Counting ahead pays when the control variables are a small part of the loop's work.
    let ops = |k: usize| node_ops(&l.vars[k].1) + node_ops(&l.vars[k].2) + 1;
    let all: usize = (0..l.vars.len()).map(ops).sum();
    let part: usize = (0..l.vars.len()).filter(|&k| control[k]).map(ops).sum();
    if part.saturating_mul(4) > all {
        return None;
    }
    Some((0..l.vars.len()).filter(|&k| control[k]).collect())
}

/// Pushes onto `out` every slot `node` reads.
fn node_slots(node: &Node, out: &mut Vec<usize>) {
    visit(node, &mut |n| {
        if let Node::Slot(s) = n {
            out.push(*s);
        }
    });
}

/// Pushes onto `out` every slot `cond` reads.
fn cond_slots(cond: &Cond, out: &mut Vec<usize>) {
    visit_cond(cond, &mut |n| {
        if let Node::Slot(s) = n {
            out.push(*s);
        }
    });
}

/// Pushes onto `out` every slot `node` binds (its `let`s and loops).
fn written_slots(node: &Node, out: &mut Vec<usize>) {
    visit(node, &mut |n| match n {
        Node::Let(bindings, _) => out.extend(bindings.iter().map(|(s, _)| *s)),
        Node::While(l) => out.extend(l.vars.iter().map(|(s, _, _)| *s)),
        _ => {}
    });
}

/// Calls `f` on `node` and every node below it (conditions included).
fn visit(node: &Node, f: &mut impl FnMut(&Node)) {
    f(node);
    match node {
        Node::Input(_) | Node::Slot(_) | Node::Const(_) => {}
        Node::Neg(a)
        | Node::Sqrt(a)
        | Node::Abs(a)
        | Node::Pow(a, _, _)
        | Node::Precision(_, a)
        | Node::Cast(a) => visit(a, f),
        Node::Add(a, b)
        | Node::Sub(a, b)
        | Node::Mul(a, b)
        | Node::Div(a, b)
        | Node::Min(a, b)
        | Node::Max(a, b) => {
            visit(a, f);
            visit(b, f);
        }
        Node::Fma(a, b, c) => {
            visit(a, f);
            visit(b, f);
            visit(c, f);
        }
        Node::Chain(a, rest) => {
            visit(a, f);
            for (_, b) in rest {
                visit(b, f);
            }
        }
        Node::Let(bindings, body) => {
            for (_, v) in bindings {
                visit(v, f);
            }
            visit(body, f);
        }
        Node::If(c, a, b) => {
            visit_cond(c, f);
            visit(a, f);
            visit(b, f);
        }
        Node::Fun(_, args) => {
            for a in args {
                visit(a, f);
            }
        }
        Node::While(l) => {
            visit_cond(&l.cond, f);
            for (_, init, update) in &l.vars {
                visit(init, f);
                visit(update, f);
            }
            visit(&l.body, f);
        }
    }
}

/// Calls `f` on every node of `cond`.
fn visit_cond(cond: &Cond, f: &mut impl FnMut(&Node)) {
    match cond {
        Cond::Bool(_) => {}
        Cond::Cmp(_, a, b) => {
            visit(a, f);
            visit(b, f);
        }
        Cond::And(cs) | Cond::Or(cs) => {
            for c in cs {
                visit_cond(c, f);
            }
        }
        Cond::Not(c) => visit_cond(c, f),
    }
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
