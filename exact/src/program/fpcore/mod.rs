//! The FPCore reader: FPBench's benchmark format (FPCore 1.x and 2.0) compiled into
//! [`Program`]s, the one intermediate form that `regress` evaluates in f64 and exactly.
//!
//! # What is read
//! A file is a sequence of benchmarks `(FPCore name? (arg ...) :prop value ... body)`. Each one
//! becomes a [`Benchmark`]: its `:name`, its arguments, its sampling [`Range`]s (from
//! `:pre`) and either a [`Program`] or the reason it cannot be one ([`Unsupported`]).
//!
//! The supported subset, where "the exact value" is a rational, a rational refined through
//! square roots, or a certified enclosure of an elementary function refined until its rounding
//! is decided:
//! * numbers — decimal (`1.5e-3`), rational (`1/3`), hexadecimal (`0x1.8p3`) and
//!   `(digits m e b)` = `m·b^e` — all taken **exactly** into [`Node::Const`] (the float side
//!   rounds the literal to the nearest double, as FPCore's binary64 context does);
//! * `+ - * /` (binary; `-` with one argument is negation), `neg`, `sqrt`, `fabs`, `fma`,
//!   `fmin`, `fmax`, and `pow` with an integer literal exponent ([`PowStyle::Libm`]: C's `pow`);
//! * the C library's functions `exp`, `exp2`, `expm1`, `log`, `log2`, `log10`, `log1p`, `sin`,
//!   `cos`, `tan`, `asin`, `acos`, `atan`, `atan2`, `sinh`, `cosh`, `tanh`, `asinh`, `acosh`,
//!   `atanh`, `pow` with any other exponent, `hypot`, `cbrt`, and the constants `PI` and `E`
//!   ([`Node::Fun`]: the C function on the float side, a certified enclosure on the exact side);
//! * `let` (parallel: each bound value sees the outer scope; every binding gets a fresh slot,
//!   so evaluating the bindings one after another as [`Node::Let`] does is equivalent) and `let*`
//!   (sequential); boolean bindings are substituted into their uses;
//! * `if`, the comparisons `< > <= >= == !=` (variadic as the standard says: a chain of
//!   adjacent pairs for the ordered ones and `==`, all pairs distinct for `!=`), `and`, `or`,
//!   `not`, `TRUE`, `FALSE`;
//! * `while` and `while*` loops (FPCore 2.0: `while` binds its variables and updates them in
//!   parallel, `while*` one after another), [`crate::program::Loop`]; a loop's condition is
//!   decided exactly, like an `if`'s, and every evaluation counts its iterations against the
//!   `loop-iterations` limit;
//! * `(array e ...)` ending the body (as the whole body, or the body of its `let`s, loops and
//!   `if` branches): one output per element, each the whole body with that element taken;
//! * rounding contexts: `:precision binary64` (the default when absent) or `binary32` (the
//!   program's [`crate::program::Format`]: its float side computes in `f32`) and
//!   `:round nearestEven`, on the benchmark, in `!` annotations and on arguments. An argument
//!   of the other precision (`(! :precision binary32 x)` in a binary64 benchmark, or the
//!   reverse) holds values of its own precision: it is sampled among them
//!   ([`crate::program::Program::input_precision`]) and the operations on it round to the
//!   precision in scope, as for a value of an annotated sub-expression. An annotation of
//!   the other precision inside the body is a [`Node::Precision`] scope: its operations round
//!   to it (FPCore's lexical scoping); `(cast e)` rounds `e` to the precision in scope
//!   ([`Node::Cast`], only in a program that mixes precisions: otherwise it is `e`). Other
//!   properties (`:cite`, `:spec`, `:math-library`, ...) are metadata and ignored.
//!
//! Everything else is reported per benchmark as `not supported: OP`, never approximated:
//! the functions without a certified enclosure here (`erf`, `tgamma`, `fmod`, ...), the
//! derived and non-finite constants (`LN2`, `INFINITY`, ...), `for` loops, tensors,
//! the classification predicates (`isnan`, ...), calls of other named FPCores, any precision
//! other than binary64 and binary32 (on the benchmark, an annotation or an argument:
//! `precision integer`), and rounding other than nearestEven. A `:precision` of an argument
//! that names no FPCore precision at all is an error of the file.
//!
//! # `:pre` and the domain
//! The precondition is split into its conjuncts (`and`, nested). Each ordered comparison chain
//! (`(<= lo x hi)`, `(< 0 x)`, `(>= x 0)`, `(== x c)`) is split into adjacent pairs; a pair
//! between one argument and a number literal is an interval bound of that argument (the
//! tightest bound per side wins; at a tie the strict one). Every other pair and conjunct is kept
//! as a [`Cond`] in [`Program::pre`], checked exactly on each sample. Since the sampler draws
//! only doubles satisfying the interval bounds exactly, the bounds need not be re-checked.
//!
//! # Why hand-written
//! The grammar is tiny (atoms, strings, two kinds of brackets, comments), error messages must
//! carry line and column and say what was expected, and the number literals must be read
//! exactly into rationals — a parser-generator crate would add a dependency for less than 300
//! lines and still need all of that by hand.
use crate::program::Program;
use crate::rational::Rational;

mod array;
mod compile;
mod sexpr;

#[cfg(test)]
mod precision_tests;
#[cfg(test)]
mod tests;

pub use crate::program::{CmpOp, Cond, Func, Node, PowStyle};

/// One side of a sampling interval.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Bound {
    /// No bound on this side (all finite doubles).
    Unbounded,
    /// The end point is included.
    Closed(Rational),
    /// The end point is excluded.
    Open(Rational),
}

impl Bound {
    /// The end point, if there is one.
    pub fn value(&self) -> Option<&Rational> {
        match self {
            Bound::Unbounded => None,
            Bound::Closed(q) | Bound::Open(q) => Some(q),
        }
    }
}

/// The sampling interval of one input: `lo` below, `hi` above.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Range {
    /// The lower bound.
    pub lo: Bound,
    /// The upper bound.
    pub hi: Bound,
}

impl Range {
    /// All finite doubles.
    pub const UNBOUNDED: Range = Range {
        lo: Bound::Unbounded,
        hi: Bound::Unbounded,
    };
}

/// A syntax error (or an ill-formed benchmark) in an FPCore file: where, and what was expected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FpCoreError {
    /// 1-based line.
    pub line: usize,
    /// 1-based column (in characters).
    pub col: usize,
    /// What is wrong, one line.
    pub message: String,
}

impl std::fmt::Display for FpCoreError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "FPCore {}:{}: {}", self.line, self.col, self.message)
    }
}

impl std::error::Error for FpCoreError {}

/// A benchmark that uses something outside the supported subset (see the module doc).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unsupported {
    /// The operation, constant, construct or property (`sin`, `PI`, `while`,
    /// `precision binary32`, `pow with a non-integer exponent`, ...).
    pub op: String,
}

impl std::fmt::Display for Unsupported {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "not supported: {}", self.op)
    }
}

impl std::error::Error for Unsupported {}

/// One FPCore benchmark of a file.
#[derive(Clone, Debug, PartialEq)]
pub struct Benchmark {
    /// The `:name` property.
    pub name: Option<String>,
    /// The identifier of a named FPCore, `(FPCore ident (args) ...)`.
    pub ident: Option<String>,
    /// The line of the benchmark's opening `(FPCore`.
    pub line: usize,
    /// The argument names, in order.
    pub args: Vec<String>,
    /// The compiled program (inputs = `args`), or what is not supported.
    pub program: Result<Program, Unsupported>,
    /// The sampling interval of each argument, from the interval bounds of `:pre`
    /// ([`Range::UNBOUNDED`] for an argument without any).
    pub domain: Vec<Range>,
}

impl Benchmark {
    /// The name for reports: `:name`, else the identifier, else `FPCore at line N`.
    pub fn display_name(&self) -> String {
        self.name
            .clone()
            .or_else(|| self.ident.clone())
            .unwrap_or_else(|| format!("FPCore at line {}", self.line))
    }
}

/// Reads every benchmark of an FPCore file.
///
/// # Errors
/// The first syntax error (unbalanced brackets, a malformed number, a missing body, an
/// ill-formed `let`, a wrong number of operands, an unbound variable, ...) as one
/// [`FpCoreError`] with its line and column. An unsupported operation is not an error: it
/// marks only its own benchmark ([`Benchmark::program`]).
pub fn parse_file(text: &str) -> Result<Vec<Benchmark>, FpCoreError> {
    let trees = sexpr::parse_all(text)?;
    trees.iter().map(compile::benchmark).collect()
}
