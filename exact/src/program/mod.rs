//! Float programs: the one intermediate form of every formula regressed from text — a
//! `--formula` in the `prove` syntax and an FPCore benchmark — evaluated two ways on the same
//! inputs:
//! * **in f64, as written**: each node is one IEEE double operation in the order of the tree
//!   (literals rounded to the nearest double, `fma` fused, `sqrt` correctly rounded), or one
//!   binary32 operation for a program of [`Format::Binary32`];
//! * **exactly**: the true real value of the tree at the (exact, dyadic) inputs. Without an
//!   irrational square root that is a rational computed exactly; with one, it is refined to as
//!   many bits as the comparison with the double needs (never a float `sqrt`).
//!
//! A [`Program`] has inputs (by index), optional `let` slots, an optional precondition (a
//! [`Cond`] the inputs must satisfy: FPCore's `:pre` beyond interval bounds) and one or more
//! output trees. It is built by the compilers (`prove` syntax: [`Program::from_expr`]; FPCore: the
//! FPCore reader) and evaluated by the evaluators of this module's children.
//!
//! # Layout
//! * `compile`: the `prove` syntax to a [`Program`] ([`Program::from_expr`], [`Program::parse`]);
//! * `walk`: the one tree walk, generic over the arithmetic (an `Evaluator`);
//! * `float`: the IEEE double side ([`Program::eval_f64`], [`Program::eval_f64_into`]);
//! * `real`: the exact side ([`Program::eval_exact`], [`Reference`], [`ExactStop`], the accuracy
//!   contract [`REL_BITS`] and the precision schedule [`START_PRECISION`] to
//!   [`MAX_PRECISION`]), with `interval`, its dyadic interval arithmetic;
//! * `explain`: where the error comes from at one sample ([`Program::local_errors`],
//!   [`Program::conditioning`]).
use crate::rational::Rational;
pub use crate::to_f64::Format;

#[cfg(test)]
mod binary32_tests;
mod compile;
mod explain;
mod float;
pub mod fpcore;
mod interval;
#[cfg(test)]
mod mixed_tests;
mod real;
#[cfg(test)]
mod tests;
mod transc;
#[cfg(test)]
mod transc_tests;
mod walk;

pub use compile::CompileError;
pub use explain::{Conditioning, LocalError};
pub use float::{call_f32, call_f64, pow_f32, pow_f64, STACK_SLOTS};
pub use real::{ExactStop, Reference, MAX_PRECISION, REL_BITS, START_PRECISION};

/// How an integer power is evaluated on the float side.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PowStyle {
    /// `x^n` of the `prove` syntax: `n - 1` multiplications from the left (`(x*x)*x`), and for a
    /// negative `n` one division `1 / x^|n|` after them; `x^0 = 1`.
    Multiply,
    /// FPCore's `pow` with an integer exponent: the C library's `pow(x, n)` (Rust's
    /// `f64::powf`), as a compiled C program would compute it.
    Libm,
}

/// A comparison operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CmpOp {
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `==`
    Eq,
    /// `!=`
    Ne,
}

/// An operation of a [`Node::Chain`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ChainOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
}

/// A node of a float program.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// Input number `i` (0-based, in the order of [`Program::inputs`]).
    Input(usize),
    /// The value bound to `let` slot `i` by an enclosing [`Node::Let`].
    Slot(usize),
    /// A literal, exact (`0.1` is `1/10`); the float side rounds it to the nearest double.
    Const(Rational),
    /// `-a` (exact on both sides).
    Neg(Box<Node>),
    /// `a + b`.
    Add(Box<Node>, Box<Node>),
    /// `a - b`.
    Sub(Box<Node>, Box<Node>),
    /// `a * b`.
    Mul(Box<Node>, Box<Node>),
    /// `a / b`; exact division by zero puts the sample outside the domain.
    Div(Box<Node>, Box<Node>),
    /// `a op1 b1 op2 b2 ...` from the left, `((a op1 b1) op2 b2) ...`: the same operations as
    /// the nested binary nodes, kept flat so that a sum or product of thousands of terms is
    /// walked, cloned and dropped without a level of recursion per term.
    Chain(Box<Node>, Vec<(ChainOp, Node)>),
    /// `sqrt(a)`; the exact root of a negative value puts the sample outside the domain.
    Sqrt(Box<Node>),
    /// `|a|`.
    Abs(Box<Node>),
    /// `a * b + c`, fused (one rounding) on the float side.
    Fma(Box<Node>, Box<Node>, Box<Node>),
    /// `min(a, b)` (C's `fmin`; the exact side has no NaN).
    Min(Box<Node>, Box<Node>),
    /// `max(a, b)` (C's `fmax`).
    Max(Box<Node>, Box<Node>),
    /// `a^n` for an integer `n` (see [`PowStyle`]); exact `0^n` with `n < 0` is outside the
    /// domain.
    Pow(Box<Node>, i32, PowStyle),
    /// Bind each `(slot, value)` in order (a later value may read an earlier slot: `let*`; for
    /// FPCore's parallel `let` the compiler renames), then evaluate the body.
    Let(Vec<(usize, Node)>, Box<Node>),
    /// `if cond then a else b`; the exact side decides `cond` exactly.
    If(Box<Cond>, Box<Node>, Box<Node>),
    /// A mathematical function or constant applied to [`Func::arity`] arguments: the C library
    /// function on the float side, a certified enclosure on the exact side (`transc`).
    Fun(Func, Vec<Node>),
    /// A loop (FPCore's `while` and `while*`), see [`Loop`].
    While(Box<Loop>),
    /// The operations of the subtree round to this precision (FPCore's `(! :precision F e)`
    /// inside a program of another precision); the exact side ignores it.
    Precision(Format, Box<Node>),
    /// The value rounded to the precision in scope (FPCore's `cast`, in a program that mixes
    /// precisions); the exact side ignores it.
    Cast(Box<Node>),
}

/// A loop: bind each variable's slot to its initial value, then, while `cond` holds, give each
/// variable its updated value; the loop's value is `body` evaluated after the last iteration.
///
/// `sequential` (`while*`): the initial values and the updates are evaluated one after
/// another, each seeing the variables bound (or updated) before it. Otherwise (`while`) every
/// initial value is evaluated before any variable is bound and every update reads the values of
/// the previous iteration. Every evaluation of a program counts its iterations (of all its
/// loops together) against the `loop-iterations` limit
/// ([`exactcheck_core::limits::LOOP_ITERATIONS`]): past it the evaluation stops, on the exact
/// side with [`ExactStop::LoopLimit`], on the float side with NaN outputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Loop {
    /// `while*` (true) or `while` (false).
    pub sequential: bool,
    /// `(slot, initial value, update)` per loop variable.
    pub vars: Vec<(usize, Node, Node)>,
    /// The condition checked before each iteration.
    pub cond: Cond,
    /// The value after the loop.
    pub body: Node,
}

/// The functions and constants of [`Node::Fun`]. Outside its domain (`log` of a non-positive
/// number, `asin` beyond `[-1, 1]`, `pow` of a negative number to a non-integer power, ...) the
/// exact side puts the sample outside the domain, as for a division by zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Func {
    /// The constant pi.
    Pi,
    /// The constant e.
    E,
    /// `e^x`.
    Exp,
    /// `2^x`.
    Exp2,
    /// `e^x - 1`.
    Expm1,
    /// The natural logarithm.
    Log,
    /// The base-2 logarithm.
    Log2,
    /// The base-10 logarithm.
    Log10,
    /// `log(1 + x)`.
    Log1p,
    /// Sine (radians).
    Sin,
    /// Cosine.
    Cos,
    /// Tangent.
    Tan,
    /// Arcsine, in `[-pi/2, pi/2]`.
    Asin,
    /// Arccosine, in `[0, pi]`.
    Acos,
    /// Arctangent, in `(-pi/2, pi/2)`.
    Atan,
    /// `atan2(y, x)`: the angle of the point `(x, y)`, in `(-pi, pi]`; undefined at the origin.
    Atan2,
    /// Hyperbolic sine.
    Sinh,
    /// Hyperbolic cosine.
    Cosh,
    /// Hyperbolic tangent.
    Tanh,
    /// Inverse hyperbolic sine.
    Asinh,
    /// Inverse hyperbolic cosine (`x >= 1`).
    Acosh,
    /// Inverse hyperbolic tangent (`|x| < 1`).
    Atanh,
    /// `x^y` for a real exponent (C's `pow`; an integer literal exponent is [`Node::Pow`]).
    Pow,
    /// `sqrt(x^2 + y^2)` (C's `hypot` on the float side).
    Hypot,
    /// The real cube root.
    Cbrt,
}

impl Func {
    /// Every function, in declaration order.
    pub const ALL: [Func; 25] = [
        Func::Pi,
        Func::E,
        Func::Exp,
        Func::Exp2,
        Func::Expm1,
        Func::Log,
        Func::Log2,
        Func::Log10,
        Func::Log1p,
        Func::Sin,
        Func::Cos,
        Func::Tan,
        Func::Asin,
        Func::Acos,
        Func::Atan,
        Func::Atan2,
        Func::Sinh,
        Func::Cosh,
        Func::Tanh,
        Func::Asinh,
        Func::Acosh,
        Func::Atanh,
        Func::Pow,
        Func::Hypot,
        Func::Cbrt,
    ];

    /// The number of arguments.
    pub fn arity(self) -> usize {
        match self {
            Func::Pi | Func::E => 0,
            Func::Atan2 | Func::Pow | Func::Hypot => 2,
            _ => 1,
        }
    }

    /// The FPCore (and C) name: `PI` and `E` for the constants, `exp`, `atan2`, ... otherwise.
    pub fn name(self) -> &'static str {
        match self {
            Func::Pi => "PI",
            Func::E => "E",
            Func::Exp => "exp",
            Func::Exp2 => "exp2",
            Func::Expm1 => "expm1",
            Func::Log => "log",
            Func::Log2 => "log2",
            Func::Log10 => "log10",
            Func::Log1p => "log1p",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Asin => "asin",
            Func::Acos => "acos",
            Func::Atan => "atan",
            Func::Atan2 => "atan2",
            Func::Sinh => "sinh",
            Func::Cosh => "cosh",
            Func::Tanh => "tanh",
            Func::Asinh => "asinh",
            Func::Acosh => "acosh",
            Func::Atanh => "atanh",
            Func::Pow => "pow",
            Func::Hypot => "hypot",
            Func::Cbrt => "cbrt",
        }
    }

    /// The function called `name` ([`Func::name`]).
    pub fn from_name(name: &str) -> Option<Func> {
        Func::ALL.iter().copied().find(|f| f.name() == name)
    }
}

/// A condition of an [`Node::If`] or a precondition.
#[derive(Clone, Debug, PartialEq)]
pub enum Cond {
    /// A constant truth value.
    Bool(bool),
    /// `a op b`.
    Cmp(CmpOp, Node, Node),
    /// All of them (true when empty).
    And(Vec<Cond>),
    /// Any of them (false when empty).
    Or(Vec<Cond>),
    /// The negation.
    Not(Box<Cond>),
}

/// A float program: named inputs, `let` slots, an optional precondition and the outputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// A short name for reports (the formula text, or FPCore's `:name`).
    pub name: String,
    /// The input names, in order: [`Node::Input`] indexes them, and the evaluators take one
    /// value per name.
    pub inputs: Vec<String>,
    /// The number of `let` slots the nodes use (slots are `0..slots`).
    pub slots: usize,
    /// A condition on the inputs beyond their sampling intervals (FPCore's `:pre`, less the
    /// interval bounds taken as the domain); a sample where it is exactly false is outside the
    /// domain.
    pub pre: Option<Cond>,
    /// The outputs (one or more).
    pub outputs: Vec<Node>,
    /// The format the float side computes in (every operation, literal and library function
    /// rounded to it, except inside a [`Node::Precision`]) and the exact reference's rounding is
    /// decided in: binary64 unless FPCore's `:precision` or `regress --precision` says binary32.
    pub precision: Format,
    /// The precision of each input's values where it is not [`Program::precision`] (FPCore's
    /// argument `(! :precision binary32 x)` in a binary64 benchmark, or the reverse): `None`, or
    /// an empty vector, for an input of the program's precision ([`Program::input_format`]).
    /// Such an input is sampled among the values of its own precision, and the operations on it
    /// round to the precision in scope.
    pub input_precision: Vec<Option<Format>>,
}

impl Program {
    /// The number of inputs.
    pub fn arity(&self) -> usize {
        self.inputs.len()
    }

    /// The precision of input `i`'s values: its own ([`Program::input_precision`]) or the
    /// program's.
    pub fn input_format(&self, i: usize) -> Format {
        self.input_precision
            .get(i)
            .copied()
            .flatten()
            .unwrap_or(self.precision)
    }

    /// Whether some input's values are of another precision than the program's.
    pub fn mixes_input_precisions(&self) -> bool {
        (0..self.inputs.len()).any(|i| self.input_format(i) != self.precision)
    }

    /// The number of operations: every node of the outputs, the `let` values and the
    /// precondition except inputs, slots, literals and the `let`/`if`/loop nodes themselves, plus
    /// one per comparison (`and`/`or`/`not` are free); a loop's condition and updates count once.
    /// A measure of the size of the program for reports.
    pub fn operation_count(&self) -> usize {
        self.outputs.iter().map(node_ops).sum::<usize>() + self.pre.as_ref().map_or(0, cond_ops)
    }
}

fn node_ops(n: &Node) -> usize {
    match n {
        Node::Input(_) | Node::Slot(_) | Node::Const(_) => 0,
        Node::Neg(a) | Node::Sqrt(a) | Node::Abs(a) | Node::Pow(a, _, _) | Node::Cast(a) => {
            1 + node_ops(a)
        }
        Node::Precision(_, a) => node_ops(a),
        Node::Add(a, b)
        | Node::Sub(a, b)
        | Node::Mul(a, b)
        | Node::Div(a, b)
        | Node::Min(a, b)
        | Node::Max(a, b) => 1 + node_ops(a) + node_ops(b),
        Node::Fma(a, b, c) => 1 + node_ops(a) + node_ops(b) + node_ops(c),
        Node::Chain(a, rest) => {
            node_ops(a) + rest.iter().map(|(_, b)| 1 + node_ops(b)).sum::<usize>()
        }
        Node::Let(bindings, body) => {
            bindings.iter().map(|(_, v)| node_ops(v)).sum::<usize>() + node_ops(body)
        }
        Node::If(c, a, b) => cond_ops(c) + node_ops(a) + node_ops(b),
        Node::Fun(f, args) => usize::from(f.arity() > 0) + args.iter().map(node_ops).sum::<usize>(),
        Node::While(l) => {
            cond_ops(&l.cond)
                + node_ops(&l.body)
                + l.vars
                    .iter()
                    .map(|(_, init, update)| node_ops(init) + node_ops(update))
                    .sum::<usize>()
        }
    }
}

fn cond_ops(c: &Cond) -> usize {
    match c {
        Cond::Bool(_) => 0,
        Cond::Cmp(_, a, b) => 1 + node_ops(a) + node_ops(b),
        Cond::And(cs) | Cond::Or(cs) => cs.iter().map(cond_ops).sum(),
        Cond::Not(c) => cond_ops(c),
    }
}
