//! The exact side: the true real value of a [`Program`] at rational inputs, as a
//! [`Reference`] with a guaranteed accuracy, or the reason there is none ([`ExactStop`]).
//!
//! # Contract
//! * `exact == true`: `value` **is** the true value.
//! * `exact == false`: the true value is not zero, `|value - true| <= 2^-REL_BITS * |true|`
//!   ([`REL_BITS`] = 80) and `value` rounds to the same double as the true value (round to
//!   nearest, ties to even) and, in a program of [`Format::Binary32`], to the same binary32
//!   value (decided on its own: a double can be a binary32 tie). That gives the error of a double in ulps to far better than
//!   `2^-10` ulps, the relative error to `2^-80` of itself, and the correctly rounded double of
//!   the true value, at any magnitude: a value of `1e-463` is refined relatively like one of 1.
//!   The correct rounding is decided, never assumed: an enclosure that contains the midpoint of
//!   two doubles (a tie: a dyadic number, which an irrational value never is) is refined until
//!   it lies on one side, and a value exactly at the midpoint is recognised by the exact zero
//!   test below (then it is rational and exact).
//! * [`ExactStop::OutsideDomain`]: exact division by zero, the exact square root of a negative
//!   number, exact `0^n` with `n < 0`, or a precondition that is exactly false.
//! * [`ExactStop::Undecided`]: a decision (a comparison of an `if` or of the precondition, the
//!   sign of a divisor or of a square root's argument) or the output's accuracy could not be
//!   settled up to [`MAX_PRECISION`] bits, and the exact zero test could not decide. Never a
//!   guess.
//! * [`ExactStop::LoopLimit`]: the program's loops ran past the `loop-iterations` limit
//!   ([`exactcheck_core::limits::LOOP_ITERATIONS`]). A loop's condition is decided on the exact
//!   values like an `if`'s (refined, never guessed), so the iterations are those of the true
//!   real computation. The variables that decide a loop's condition are run alone first
//!   (`walk`): when they alone pass the limit, the sample stops there without computing the
//!   loop's other variables (a loop counting to two million stops at once, not after ten
//!   thousand iterations of its whole state).
//! * [`ExactStop::LoopValueLimit`]: in the exact zero test (below), which keeps every value
//!   exact, a loop variable's value grew past the `loop-value-bits` limit
//!   ([`exactcheck_core::limits::LOOP_VALUE_BITS`]): a diverging loop's exact values grow every
//!   iteration, and at thousands of iterations each would cost minutes.
//! * [`ExactStop::TooLarge`]: an exact intermediate value would exceed
//!   the `constant-bits` limit ([`exactcheck_core::limits::CONSTANT_BITS`]) in bits (or an
//!   approximate one a binary exponent of that size), the limit every constant of the workspace
//!   obeys.
//!
//! # Algorithm
//! 1. **Rationals while possible** (the fast path): values are exact [`Rational`]s (the
//!    workspace's fast rationals, inline `i128` parts when they fit) as long as no irrational
//!    square root is involved; the square root of a rational that is the square of a rational
//!    stays exact ([`Coefficient::try_sqrt`]). A program without irrational roots never leaves
//!    this path and its results are exact.
//! 2. **Intervals**: an irrational root becomes an enclosure with dyadic endpoints at working
//!    precision `p` bits (`interval`, rounded outward); interval arithmetic propagates it, and
//!    rational operands join it as enclosures of themselves. An operation that needs a decision
//!    the enclosure cannot give (a divisor or a root's argument straddling zero, a comparison of
//!    overlapping enclosures) stops the pass, as does an output enclosure not narrow enough for
//!    the contract (not of one sign, not within `2^-REL_BITS` relative, or its ends rounding to
//!    different doubles); the sample is then evaluated again from the start at `2p` bits, from
//!    [`START_PRECISION`] up to [`MAX_PRECISION`] (the bound on the work of one sample: a value
//!    that cancels more than about `MAX_PRECISION` bits is `Undecided`).
//! 3. **Exact zero test**: intervals can never prove that a quantity is zero. The first time a
//!    pass is stopped by an undecidable decision (or by an output enclosure around zero or
//!    around a rounding boundary of the doubles), the whole program is evaluated in the multi-quadratic field [`crate::Radical`] (exact sums of
//!    `c sqrt(m)`, whose sign is decidable and whose square roots denest or fail): if every
//!    root is representable there, every decision is exact and each output is either rational
//!    (exact) or an irrational radical, refined with intervals until it meets the contract.
//!    Otherwise refinement goes on, and at the cap the answer is `Undecided`.
//! 4. **Equal calls**: the enclosure of a function at exact (rational) arguments carries the
//!    call, the function and those arguments ([`CallKey`]). Two values of the same call are the
//!    same real number: their difference is exactly 0, their quotient exactly 1 and they
//!    compare equal, at once (`sin(x + e) - sin(x)` at `e = 0`), where intervals would refine
//!    to the cap. A value computed from such an enclosure (`-sin(x)`, `2 sin(x)`) carries no
//!    call.
//!
//! The walk itself is the one generic walk (`walk`) shared with the float side and the radical
//! fallback.
use super::interval::Iv;
use super::transc::{self, TStop};
use super::walk::{count_iteration, eval_cond, eval_node, Evaluator};
use super::{CmpOp, Format, Func, PowStyle, Program};
use crate::expr::Coefficient;
use crate::radical::Radical;
use crate::rational::Rational;
use exactcheck_core::limits;
use exactcheck_core::{Field, OrderedField, Ring, Sign};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use std::cmp::Ordering;
use std::rc::Rc;

/// Relative accuracy of an inexact [`Reference`]: `|value - true| <= 2^-REL_BITS |true|`.
pub const REL_BITS: u32 = 80;
/// The working precision (bits) of the first interval pass.
pub const START_PRECISION: u64 = 128;
/// The largest working precision (bits); beyond it an undecided sample is [`ExactStop::Undecided`].
pub const MAX_PRECISION: u64 = 1 << 14;

/// The exact value of an output, or an approximation meeting the contract of `program::real`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Reference {
    /// The value (exact, or within `2^-REL_BITS` relative and rounding to the true value's
    /// double).
    pub value: BigRational,
    /// Whether `value` is the true value.
    pub exact: bool,
}

/// Why a sample has no exact reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, thiserror::Error)]
pub enum ExactStop {
    /// The inputs are outside the program's domain (exact division by zero, root of a negative
    /// number, `0^n` with `n < 0`, or a false precondition).
    #[error("outside the domain")]
    OutsideDomain,
    /// A decision could not be made up to the precision cap (`MAX_PRECISION` bits).
    #[error("undecided up to the precision cap of {MAX_PRECISION} bits")]
    Undecided,
    /// An intermediate value exceeds the `constant-bits` limit.
    #[error("{}", limits::CONSTANT_BITS.exceeded(format!("more than {} in an intermediate value", limits::CONSTANT_BITS.get())))]
    TooLarge,
    /// The program's loops ran past the `loop-iterations` limit.
    #[error("{}", limits::LOOP_ITERATIONS.exceeded(format!("more than {}", limits::LOOP_ITERATIONS.get())))]
    LoopLimit,
    /// A loop variable's exact value grew past the `loop-value-bits` limit.
    #[error("{}", limits::LOOP_VALUE_BITS.exceeded(format!("more than {} in a loop variable", limits::LOOP_VALUE_BITS.get())))]
    LoopValueLimit,
}

impl ExactStop {
    /// The limit that stopped the evaluation, for the stops at a limit on the work of one
    /// sample (`loop-iterations`, `loop-value-bits`); `None` otherwise.
    pub fn limit(self) -> Option<&'static limits::Limit> {
        match self {
            ExactStop::LoopLimit => Some(&limits::LOOP_ITERATIONS),
            ExactStop::LoopValueLimit => Some(&limits::LOOP_VALUE_BITS),
            ExactStop::OutsideDomain | ExactStop::Undecided | ExactStop::TooLarge => None,
        }
    }
}

/// A value of the exact evaluation: a rational, or an enclosure of an irrational number with,
/// for the value of a function at exact arguments, that call ([`CallKey`]).
#[derive(Clone, Debug)]
pub(super) enum XV {
    Exact(Rational),
    Approx(Box<Iv>, Option<Rc<CallKey>>),
}

/// A function and its exact arguments: two enclosures with equal keys enclose the same real
/// number, whatever their widths. So `sin(x + e) - sin(x)` at `e = 0` is exactly 0 at once and
/// `f(x) == f(x)` is decided true, where intervals alone could never show that a difference is
/// zero and would refine to the precision cap.
pub(super) type CallKey = (Func, Option<Rational>, Option<Rational>);

/// The call both `a` and `b` are the value of, if they are the values of one call.
fn same_call(a: &XV, b: &XV) -> bool {
    matches!((a, b), (XV::Approx(_, Some(x)), XV::Approx(_, Some(y))) if x == y)
}

/// Why an interval pass stops.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Halt {
    Outside,
    TooLarge,
    /// Past the `loop-iterations` limit (at any precision: the loop's exact decisions do not
    /// depend on it).
    LoopLimit,
    /// Try again at a higher precision; `ambiguous`: a decision (not just accuracy) was missing.
    Refine {
        ambiguous: bool,
    },
}

/// The exact domain at working precision `p`, with the loop iterations done so far.
pub(super) struct Real<'a> {
    pub(super) x: &'a [Rational],
    pub(super) p: u64,
    pub(super) iterations: u64,
}

impl<'a> Real<'a> {
    /// The domain at inputs `x` and precision `p`, no iteration done.
    pub(super) fn new(x: &'a [Rational], p: u64) -> Real<'a> {
        Real {
            x,
            p,
            iterations: 0,
        }
    }
}

/// `q` if its numerator and denominator have at most `constant-bits` bits together.
fn checked(q: Rational) -> Result<XV, Halt> {
    if q.bits() <= limits::CONSTANT_BITS.get() {
        Ok(XV::Exact(q))
    } else {
        Err(Halt::TooLarge)
    }
}

fn approx(iv: Iv) -> Result<XV, Halt> {
    if iv.max_exponent() > limits::CONSTANT_BITS.get() {
        Err(Halt::TooLarge)
    } else {
        Ok(XV::Approx(Box::new(iv), None))
    }
}

const AMBIGUOUS: Halt = Halt::Refine { ambiguous: true };

impl Real<'_> {
    fn iv(&self, v: &XV) -> Iv {
        match v {
            XV::Exact(q) => Iv::from_rational(q, self.p),
            XV::Approx(iv, _) => (**iv).clone(),
        }
    }

    /// The sign of `v`; `Err(AMBIGUOUS)` if its enclosure straddles zero.
    pub(super) fn sign(&self, v: &XV) -> Result<Ordering, Halt> {
        match v {
            XV::Exact(q) => Ok(q.cmp(&Rational::ZERO)),
            XV::Approx(iv, _) => iv.sign().ok_or(AMBIGUOUS),
        }
    }
}

impl Evaluator for Real<'_> {
    type V = XV;
    type Stop = Halt;

    fn input(&mut self, i: usize) -> XV {
        XV::Exact(self.x[i].clone())
    }
    fn constant(&mut self, q: &Rational) -> Result<XV, Halt> {
        Ok(XV::Exact(q.clone()))
    }
    fn neg(&mut self, a: XV) -> Result<XV, Halt> {
        Ok(match a {
            XV::Exact(q) => XV::Exact(-q),
            XV::Approx(iv, _) => XV::Approx(Box::new(iv.neg()), None),
        })
    }
    fn add(&mut self, a: XV, b: XV) -> Result<XV, Halt> {
        match (&a, &b) {
            (XV::Exact(x), XV::Exact(y)) => checked(x + y),
            _ => approx(Iv::add(&self.iv(&a), &self.iv(&b), self.p)),
        }
    }
    fn sub(&mut self, a: XV, b: XV) -> Result<XV, Halt> {
        if same_call(&a, &b) {
            return Ok(XV::Exact(Rational::ZERO));
        }
        match (&a, &b) {
            (XV::Exact(x), XV::Exact(y)) => checked(x - y),
            _ => approx(Iv::sub(&self.iv(&a), &self.iv(&b), self.p)),
        }
    }
    fn mul(&mut self, a: XV, b: XV) -> Result<XV, Halt> {
        match (&a, &b) {
            (XV::Exact(x), XV::Exact(y)) => checked(x * y),
            (XV::Exact(z), _) | (_, XV::Exact(z)) if z.is_zero() => Ok(XV::Exact(Rational::ZERO)),
            _ => approx(Iv::mul(&self.iv(&a), &self.iv(&b), self.p)),
        }
    }
    fn div(&mut self, a: XV, b: XV) -> Result<XV, Halt> {
        match self.sign(&b)? {
            Ordering::Equal => return Err(Halt::Outside),
            Ordering::Less | Ordering::Greater => {}
        }
        if same_call(&a, &b) {
            return Ok(XV::Exact(Rational::ONE));
        }
        match (&a, &b) {
            (XV::Exact(x), XV::Exact(y)) => {
                checked(x.checked_div(y).expect("the divisor's sign is not zero"))
            }
            (XV::Exact(z), _) if z.is_zero() => Ok(XV::Exact(Rational::ZERO)),
            _ => approx(Iv::div(&self.iv(&a), &self.iv(&b), self.p)),
        }
    }
    fn sqrt(&mut self, a: XV) -> Result<XV, Halt> {
        match a {
            XV::Exact(q) => {
                if q.signum() == Sign::Negative {
                    return Err(Halt::Outside);
                }
                match q.try_sqrt() {
                    Some(r) => Ok(XV::Exact(r)),
                    None => approx(Iv::sqrt(&Iv::from_rational(&q, self.p), self.p)),
                }
            }
            XV::Approx(iv, _) => {
                if iv.hi.sign() == Ordering::Less {
                    Err(Halt::Outside)
                } else if iv.lo.sign() == Ordering::Less {
                    Err(AMBIGUOUS)
                } else {
                    approx(Iv::sqrt(&iv, self.p))
                }
            }
        }
    }
    fn abs(&mut self, a: XV) -> Result<XV, Halt> {
        Ok(match a {
            XV::Exact(q) => XV::Exact(if q.signum() == Sign::Negative { -q } else { q }),
            XV::Approx(iv, _) => XV::Approx(Box::new(iv.abs()), None),
        })
    }
    fn fma(&mut self, a: XV, b: XV, c: XV) -> Result<XV, Halt> {
        let ab = self.mul(a, b)?;
        self.add(ab, c)
    }
    fn min(&mut self, a: XV, b: XV) -> Result<XV, Halt> {
        match (&a, &b) {
            (XV::Exact(x), XV::Exact(y)) => Ok(XV::Exact(x.min(y).clone())),
            _ => approx(Iv::min(&self.iv(&a), &self.iv(&b))),
        }
    }
    fn max(&mut self, a: XV, b: XV) -> Result<XV, Halt> {
        match (&a, &b) {
            (XV::Exact(x), XV::Exact(y)) => Ok(XV::Exact(x.max(y).clone())),
            _ => approx(Iv::max(&self.iv(&a), &self.iv(&b))),
        }
    }
    fn pow(&mut self, a: XV, n: i32, _style: PowStyle) -> Result<XV, Halt> {
        match a {
            XV::Exact(q) => {
                if q.is_zero() && n < 0 {
                    return Err(Halt::Outside);
                }
                // size_bits(q^k) >= k size_bits(q): refuse before computing.
                if q.size_bits().saturating_mul(u64::from(n.unsigned_abs()))
                    > limits::CONSTANT_BITS.get()
                {
                    return Err(Halt::TooLarge);
                }
                checked(q.powi(n).expect("0^n with n < 0 is excluded above"))
            }
            XV::Approx(iv, _) => {
                // Binary powering of the enclosure, then one division for n < 0.
                let mut e = n.unsigned_abs();
                let mut acc = XV::Exact(Rational::ONE);
                let mut sq = XV::Approx(iv, None);
                while e > 0 {
                    if e & 1 == 1 {
                        acc = self.mul(acc, sq.clone())?;
                    }
                    e >>= 1;
                    if e > 0 {
                        sq = self.mul(sq.clone(), sq)?;
                    }
                }
                if n < 0 {
                    self.div(XV::Exact(Rational::ONE), acc)
                } else {
                    Ok(acc)
                }
            }
        }
    }
    fn call(&mut self, f: Func, a: Option<XV>, b: Option<XV>) -> Result<XV, Halt> {
        let exact = |v: &Option<XV>| match v {
            Some(XV::Exact(q)) => Some(q.clone()),
            _ => None,
        };
        let (qa, qb) = (exact(&a), exact(&b));
        if qa.is_some() == a.is_some() && qb.is_some() == b.is_some() {
            if let Some(r) = transc::special(f, qa.as_ref(), qb.as_ref()) {
                return r.map_err(halt).and_then(checked);
            }
        }
        match (f, &a, &b) {
            (Func::Pow, Some(x), Some(y)) => {
                if let Some(n) = qb
                    .as_ref()
                    .filter(|q| q.is_integer())
                    .and_then(|q| q.numer().to_i32())
                {
                    return self.pow(x.clone(), n, PowStyle::Libm);
                }
                match self.sign(x)? {
                    // A negative base: C's pow is NaN unless the exponent is an integer, which
                    // only an exact exponent shows.
                    Ordering::Less if qb.is_some() => return Err(Halt::Outside),
                    Ordering::Less => return Err(AMBIGUOUS),
                    Ordering::Equal => {
                        return match self.sign(y)? {
                            Ordering::Greater => Ok(XV::Exact(Rational::ZERO)),
                            Ordering::Less => Err(Halt::Outside),
                            Ordering::Equal => Ok(XV::Exact(Rational::ONE)),
                        }
                    }
                    Ordering::Greater => {}
                }
            }
            // atan2(y, 0): pi/2 times the sign of y; undefined at the origin.
            (Func::Atan2, Some(y), Some(x)) if self.sign(x)? == Ordering::Equal => {
                let half_pi = transc::enclose(Func::Pi, None, None, self.p)
                    .map_err(halt)?
                    .half();
                return match self.sign(y)? {
                    Ordering::Greater => approx(half_pi),
                    Ordering::Less => approx(half_pi.neg()),
                    Ordering::Equal => Err(Halt::Outside),
                };
            }
            _ => {}
        }
        let ia = a.as_ref().map(|v| self.iv(v));
        let ib = b.as_ref().map(|v| self.iv(v));
        let v = transc::enclose(f, ia.as_ref(), ib.as_ref(), self.p)
            .map_err(halt)
            .and_then(approx)?;
        // At exact arguments the value is that call's, and says so.
        Ok(match v {
            XV::Approx(iv, None) if qa.is_some() == a.is_some() && qb.is_some() == b.is_some() => {
                XV::Approx(iv, Some(Rc::new((f, qa, qb))))
            }
            v => v,
        })
    }
    fn compare(&mut self, op: CmpOp, a: &XV, b: &XV) -> Result<bool, Halt> {
        let ord = match (a, b) {
            (XV::Exact(x), XV::Exact(y)) => x.cmp(y),
            _ if same_call(a, b) => Ordering::Equal,
            _ => Iv::sub(&self.iv(a), &self.iv(b), self.p)
                .sign()
                .ok_or(AMBIGUOUS)?,
        };
        Ok(holds(op, ord))
    }
    fn iterate(&mut self) -> Result<(), Halt> {
        if count_iteration(&mut self.iterations) {
            Ok(())
        } else {
            Err(Halt::LoopLimit)
        }
    }
    /// An exact iteration can cost thousands of big-number operations: loops count ahead.
    fn iteration_count(&mut self) -> Option<&mut u64> {
        Some(&mut self.iterations)
    }
    /// A rational loop variable of more than `4p` bits becomes its enclosure at precision `p`:
    /// a loop's exact rationals can double in size every iteration (`x <- x*x + c`), an
    /// enclosure's cost stays that of the precision, and the refinement of `p` still reaches
    /// the contract (the exact rationals come back at the precision where they fit).
    fn carry(&mut self, v: XV) -> Result<XV, Halt> {
        match v {
            XV::Exact(q) if q.bits() > self.p.saturating_mul(4) => {
                approx(Iv::from_rational(&q, self.p))
            }
            v => Ok(v),
        }
    }
}

/// The halt of a function's stop.
fn halt(s: TStop) -> Halt {
    match s {
        TStop::Outside => Halt::Outside,
        TStop::Ambiguous => AMBIGUOUS,
        TStop::TooLarge => Halt::TooLarge,
    }
}

/// Whether `a op b` holds when `a` compares to `b` as `ord`.
fn holds(op: CmpOp, ord: Ordering) -> bool {
    match op {
        CmpOp::Lt => ord == Ordering::Less,
        CmpOp::Le => ord != Ordering::Greater,
        CmpOp::Gt => ord == Ordering::Greater,
        CmpOp::Ge => ord != Ordering::Less,
        CmpOp::Eq => ord == Ordering::Equal,
        CmpOp::Ne => ord != Ordering::Equal,
    }
}

/// The double nearest to `d` (ties to even; beyond the range, an infinity).
pub(super) fn nearest_double(d: &super::interval::Dy) -> f64 {
    crate::to_f64::rational_to_f64(&d.to_big_rational())
}

/// Whether both ends of `iv` round to the same double: then so does every point of it (rounding
/// is monotone), the true value and the midpoint included.
pub(super) fn rounding_decided(iv: &Iv) -> bool {
    nearest_double(&iv.lo).to_bits() == nearest_double(&iv.hi).to_bits()
}

/// Whether the midpoint of an output enclosure meets the contract: one sign, `2^-REL_BITS`
/// relative accuracy, the correct rounding to a double decided and, for a binary32 program, the
/// rounding to binary32 too (a double can be a binary32 tie: deciding the double is not enough).
fn settled(iv: &Iv, format: Format) -> bool {
    iv.narrow(REL_BITS)
        && rounding_decided(iv)
        && (format == Format::Binary64
            || format.round(&iv.lo.to_big_rational()).to_bits()
                == format.round(&iv.hi.to_big_rational()).to_bits())
}

// ------------------------------------------------------------------ the radical fallback

/// Why the radical evaluation stops.
enum RadStop {
    /// Exactly outside the domain.
    Outside,
    /// A root that is not multi-quadratic (or not certifiable), or a value beyond the size
    /// limit: the radical field cannot decide this sample.
    Unrepresentable,
    /// Past the `loop-iterations` limit.
    LoopLimit,
    /// A loop variable past the `loop-value-bits` limit.
    LoopValueLimit,
}

/// The multi-quadratic field [`Radical`] as an exact domain, with the loop iterations done.
struct Rad<'a> {
    x: &'a [Rational],
    iterations: u64,
}

fn rad_checked(r: Radical) -> Result<Radical, RadStop> {
    if r.size_within(limits::CONSTANT_BITS.get()) {
        Ok(r)
    } else {
        Err(RadStop::Unrepresentable)
    }
}

impl Evaluator for Rad<'_> {
    type V = Radical;
    type Stop = RadStop;

    fn input(&mut self, i: usize) -> Radical {
        Radical::from(&self.x[i])
    }
    fn constant(&mut self, q: &Rational) -> Result<Radical, RadStop> {
        Ok(Radical::from(q))
    }
    fn neg(&mut self, a: Radical) -> Result<Radical, RadStop> {
        Ok(-a)
    }
    fn add(&mut self, a: Radical, b: Radical) -> Result<Radical, RadStop> {
        rad_checked(a + b)
    }
    fn sub(&mut self, a: Radical, b: Radical) -> Result<Radical, RadStop> {
        rad_checked(a - b)
    }
    fn mul(&mut self, a: Radical, b: Radical) -> Result<Radical, RadStop> {
        rad_checked(a * b)
    }
    fn div(&mut self, a: Radical, b: Radical) -> Result<Radical, RadStop> {
        let inv = b.inv().map_err(|_| RadStop::Outside)?;
        rad_checked(a * inv)
    }
    fn sqrt(&mut self, a: Radical) -> Result<Radical, RadStop> {
        if a.sign() == Sign::Negative {
            return Err(RadStop::Outside);
        }
        a.try_sqrt().ok_or(RadStop::Unrepresentable)
    }
    fn abs(&mut self, a: Radical) -> Result<Radical, RadStop> {
        Ok(if a.sign() == Sign::Negative { -a } else { a })
    }
    fn fma(&mut self, a: Radical, b: Radical, c: Radical) -> Result<Radical, RadStop> {
        let ab = self.mul(a, b)?;
        self.add(ab, c)
    }
    fn min(&mut self, a: Radical, b: Radical) -> Result<Radical, RadStop> {
        Ok(a.min(b))
    }
    fn max(&mut self, a: Radical, b: Radical) -> Result<Radical, RadStop> {
        Ok(a.max(b))
    }
    fn pow(&mut self, a: Radical, n: i32, _style: PowStyle) -> Result<Radical, RadStop> {
        if a.is_zero() && n < 0 {
            return Err(RadStop::Outside);
        }
        if a.size_bits().saturating_mul(u64::from(n.unsigned_abs())) > limits::CONSTANT_BITS.get() {
            return Err(RadStop::Unrepresentable);
        }
        let p = rad_checked(Ring::pow(&a, n.unsigned_abs()))?;
        if n < 0 {
            p.inv().map_err(|_| RadStop::Outside)
        } else {
            Ok(p)
        }
    }
    fn call(
        &mut self,
        f: Func,
        a: Option<Radical>,
        b: Option<Radical>,
    ) -> Result<Radical, RadStop> {
        let qb = b.as_ref().and_then(Radical::to_rational);
        match (f, a, b) {
            (Func::Pow, Some(x), Some(_)) if qb.as_ref().is_some_and(Rational::is_integer) => {
                let n = qb
                    .and_then(|q| q.numer().to_i32())
                    .ok_or(RadStop::Unrepresentable)?;
                self.pow(x, n, PowStyle::Libm)
            }
            (Func::Hypot, Some(x), Some(y)) => {
                let xx = self.mul(x.clone(), x)?;
                let yy = self.mul(y.clone(), y)?;
                let s = self.add(xx, yy)?;
                self.sqrt(s)
            }
            (f, a, b) => {
                let qa = match &a {
                    Some(r) => Some(r.to_rational().ok_or(RadStop::Unrepresentable)?),
                    None => None,
                };
                let qb = match &b {
                    Some(r) => Some(r.to_rational().ok_or(RadStop::Unrepresentable)?),
                    None => None,
                };
                match transc::special(f, qa.as_ref(), qb.as_ref()) {
                    Some(Ok(q)) => Ok(Radical::from(&q)),
                    Some(Err(TStop::Outside)) => Err(RadStop::Outside),
                    _ => Err(RadStop::Unrepresentable),
                }
            }
        }
    }
    fn compare(&mut self, op: CmpOp, a: &Radical, b: &Radical) -> Result<bool, RadStop> {
        Ok(holds(op, a.cmp(b)))
    }
    fn iterate(&mut self) -> Result<(), RadStop> {
        if count_iteration(&mut self.iterations) {
            Ok(())
        } else {
            Err(RadStop::LoopLimit)
        }
    }
    /// Every value is exact here: loops count ahead.
    fn iteration_count(&mut self) -> Option<&mut u64> {
        Some(&mut self.iterations)
    }
    /// Every value here is exact: a loop variable past the `loop-value-bits` limit stops the
    /// sample (a diverging loop would grow its values up to `constant-bits`).
    fn carry(&mut self, v: Radical) -> Result<Radical, RadStop> {
        if v.size_within(limits::LOOP_VALUE_BITS.get()) {
            Ok(v)
        } else {
            Err(RadStop::LoopValueLimit)
        }
    }
}

/// An inexact reference to an irrational radical, by interval refinement (the value is neither
/// zero nor dyadic, so refinement reaches the relative contract and decides the rounding).
fn radical_reference(r: &Radical, format: Format) -> Result<Reference, ExactStop> {
    if let Some(q) = r.to_rational() {
        return Ok(Reference {
            value: q.to_big_rational(),
            exact: true,
        });
    }
    let mut p = START_PRECISION;
    loop {
        let mut sum: Option<Iv> = None;
        for (m, c) in r.terms() {
            let root = Iv::sqrt(
                &Iv::from_rational(&Rational::from(BigInt::from(m.to_biguint())), p),
                p,
            );
            let term = Iv::mul(&Iv::from_rational(c, p), &root, p);
            sum = Some(match sum {
                None => term,
                Some(s) => Iv::add(&s, &term, p),
            });
        }
        let iv = sum.expect("an irrational radical has terms");
        if settled(&iv, format) {
            return Ok(Reference {
                value: iv.midpoint(),
                exact: false,
            });
        }
        if p >= MAX_PRECISION {
            return Err(ExactStop::Undecided);
        }
        p *= 2;
    }
}

// ------------------------------------------------------------------ entry point

/// The outcome of one interval pass.
enum Pass {
    Done(Vec<Reference>),
    Refine { ambiguous: bool },
}

impl Program {
    /// The true values of the outputs at the exact inputs `x` (one per input), exact where
    /// rational and otherwise to the contract of `program::real` ([`REL_BITS`], the rounding
    /// to a double decided).
    ///
    /// # Errors
    /// [`ExactStop::OutsideDomain`], [`ExactStop::Undecided`], [`ExactStop::TooLarge`],
    /// [`ExactStop::LoopLimit`], [`ExactStop::LoopValueLimit`] as documented on [`ExactStop`].
    ///
    /// # Panics
    /// When `x.len()` is not [`Program::arity`], or on a malformed program (a slot or input
    /// index out of range; the compilers never build one).
    pub fn eval_exact(&self, x: &[Rational]) -> Result<Vec<Reference>, ExactStop> {
        assert_eq!(
            x.len(),
            self.inputs.len(),
            "Program::eval_exact: {} values for {} inputs",
            x.len(),
            self.inputs.len()
        );
        let mut p = START_PRECISION;
        let mut radical_tried = false;
        loop {
            let ambiguous = match self.interval_pass(x, p) {
                Ok(Pass::Done(refs)) => return Ok(refs),
                Ok(Pass::Refine { ambiguous }) | Err(Halt::Refine { ambiguous }) => ambiguous,
                Err(Halt::Outside) => return Err(ExactStop::OutsideDomain),
                Err(Halt::TooLarge) => return Err(ExactStop::TooLarge),
                Err(Halt::LoopLimit) => return Err(ExactStop::LoopLimit),
            };
            if ambiguous && !radical_tried {
                radical_tried = true;
                match self.radical_pass(x) {
                    Ok(values) => {
                        return values
                            .iter()
                            .map(|r| radical_reference(r, self.precision))
                            .collect()
                    }
                    Err(RadStop::Outside) => return Err(ExactStop::OutsideDomain),
                    Err(RadStop::LoopLimit) => return Err(ExactStop::LoopLimit),
                    Err(RadStop::LoopValueLimit) => return Err(ExactStop::LoopValueLimit),
                    Err(RadStop::Unrepresentable) => {}
                }
            }
            if p >= MAX_PRECISION {
                return Err(ExactStop::Undecided);
            }
            p *= 2;
        }
    }

    /// One evaluation at working precision `p`.
    fn interval_pass(&self, x: &[Rational], p: u64) -> Result<Pass, Halt> {
        let mut d = Real::new(x, p);
        let mut slots = vec![XV::Exact(Rational::ZERO); self.slots];
        if let Some(pre) = &self.pre {
            if !eval_cond(&mut d, pre, &mut slots)? {
                return Err(Halt::Outside);
            }
        }
        let mut refs = Vec::with_capacity(self.outputs.len());
        for node in &self.outputs {
            match eval_node(&mut d, node, &mut slots)? {
                XV::Exact(q) => refs.push(Reference {
                    value: q.to_big_rational(),
                    exact: true,
                }),
                XV::Approx(iv, _) => {
                    if iv.is_point() {
                        refs.push(Reference {
                            value: iv.lo.to_big_rational(),
                            exact: true,
                        });
                    } else if settled(&iv, self.precision) {
                        refs.push(Reference {
                            value: iv.midpoint(),
                            exact: false,
                        });
                    } else {
                        // Around zero, or narrow but around a rounding boundary (perhaps
                        // exactly at a tie): only the exact test can tell.
                        let ambiguous = match iv.sign() {
                            None => true,
                            Some(_) => iv.narrow(REL_BITS),
                        };
                        return Ok(Pass::Refine { ambiguous });
                    }
                }
            }
        }
        Ok(Pass::Done(refs))
    }

    /// The whole program in the radical field: exact values, or why not.
    fn radical_pass(&self, x: &[Rational]) -> Result<Vec<Radical>, RadStop> {
        let mut d = Rad { x, iterations: 0 };
        let mut slots = vec![Radical::default(); self.slots];
        if let Some(pre) = &self.pre {
            if !eval_cond(&mut d, pre, &mut slots)? {
                return Err(RadStop::Outside);
            }
        }
        self.outputs
            .iter()
            .map(|node| eval_node(&mut d, node, &mut slots))
            .collect()
    }
}
