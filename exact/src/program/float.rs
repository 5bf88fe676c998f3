//! The float side: a [`Program`] evaluated in IEEE binary64 arithmetic, one rounding per node in
//! the order of the tree, as a C program compiled without `-ffast-math` computes it.
//!
//! * `+ - * /` and `sqrt` are the correctly rounded IEEE operations (`x/0 = ±inf`,
//!   `sqrt(-1) = NaN`); `fma` is `f64::mul_add` (one rounding); `fmin`/`fmax` are `f64::min`/
//!   `f64::max` (C's `fmin`/`fmax`: a NaN operand is ignored); `fabs` clears the sign.
//! * A literal is the double nearest to the exact rational ([`Rational::to_f64`], the workspace's
//!   one correctly rounded conversion: ties to even, subnormals, overflow to `±inf`).
//! * `x^n` follows its [`PowStyle`]: `Multiply` is `n - 1` multiplications from the left and for
//!   `n < 0` one division `1 / x^|n|` after them; `Libm` is the C library's `pow(x, n)`
//!   (`f64::powf`).
//! * The functions of [`Func`] are the C library's ([`call_f64`]: Rust's `f64` methods).
//! * A comparison involving NaN is false, except `!=`, which is true (IEEE 754).
//! * The precondition is **not** evaluated here: it is a property of the exact inputs, decided by
//!   the exact side.
//!
//! * A loop runs as written; past the `loop-iterations` limit (all loops of one evaluation
//!   together) the evaluation stops and every output is NaN, a float failure (a program whose
//!   exact loops also run that long is not compared at all).
//!
//! * A program of [`Format::Binary32`] runs the same walk over `f32`: every operation is the
//!   binary32 one (`f32` arithmetic, `f32::sqrt`, `f32::mul_add`), a literal is the binary32
//!   value nearest to it ([`crate::to_f64::rational_to_f32`], decided from the exact rational,
//!   not through a double), the functions are the C library's `f32` functions (`sinf`, `expf`,
//!   `powf`, ...: [`call_f32`]), an input is taken as binary32 (the harness samples binary32
//!   values) and the outputs are returned as the doubles holding them exactly.
//!
//! * An input of its own precision ([`Program::input_format`]: FPCore's
//!   `(! :precision binary32 x)` argument of a binary64 benchmark, or the reverse) is taken as
//!   the value of that precision it holds; the operations on it round to the precision in scope.
//!   A binary32 input of a binary64 program is a double like any other; a binary64 input of a
//!   binary32 program makes the whole evaluation the mixed one below.
//!
//! * A program that mixes precisions (FPCore's `(! :precision binary64 ...)` inside a binary32
//!   program, or the reverse, and `cast`: [`super::Node::Precision`], [`super::Node::Cast`])
//!   computes each operation in the precision in scope: its exact result on its operands,
//!   whatever their precisions, rounded once to that precision (a binary32 operation on binary64
//!   operands rounds the double result to odd, from its exact error, before rounding it to
//!   binary32, which is then correctly rounded); a literal is rounded to the precision in scope,
//!   `cast` rounds its operand's value to it, and the functions are the C library's of that
//!   precision (on binary64 arguments in binary32: the double function, rounded).
//!
//! The evaluation never fails and allocates nothing per node (a `while` loop's parallel update
//! excepted): it is the generic walk of `walk` over the `Copy` types `f64` and `f32` (one
//! generic domain, `Ieee`), with the `let` slots in a stack array (a heap vector only for
//! programs with more than [`STACK_SLOTS`] slots). A program that mixes precisions is noticed at
//! its first operation of another precision and evaluated again in the mixed domain (values in
//! doubles, slots in a vector).
use super::walk::{count_iteration, eval_node, Evaluator};
use super::{CmpOp, Format, Func, PowStyle, Program};
use crate::rational::Rational;
use num_traits::FromPrimitive;
use std::cmp::Ordering;

/// Programs with at most this many `let` slots keep them on the stack during a float evaluation.
pub const STACK_SLOTS: usize = 32;

/// Why a float evaluation stops.
pub(super) enum FloatStop {
    /// The loops ran past the `loop-iterations` limit.
    Loop,
    /// A uniform domain met a precision other than its own: the program mixes precisions and
    /// is evaluated again in [`Mixed`].
    Mixed,
}

/// An IEEE format as a Rust type: the operations of [`Ieee`] in it.
trait IeeeFloat:
    Copy
    + PartialOrd
    + std::ops::Neg<Output = Self>
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<Output = Self>
    + std::ops::Div<Output = Self>
{
    const FORMAT: Format;
    const ZERO: Self;
    /// An input, taken in this format.
    fn input(x: f64) -> Self;
    /// The value of this format nearest to `q`.
    fn constant(q: &Rational) -> Self;
    /// The double holding the value exactly.
    fn widen(self) -> f64;
    fn sqrt(self) -> Self;
    fn abs(self) -> Self;
    fn mul_add(self, b: Self, c: Self) -> Self;
    fn min(self, b: Self) -> Self;
    fn max(self, b: Self) -> Self;
    fn pow(self, n: i32, style: PowStyle) -> Self;
    fn call(f: Func, a: Option<Self>, b: Option<Self>) -> Self;
}

macro_rules! ieee_float {
    ($t:ty, $format:expr, $input:expr, $constant:expr, $pow:ident, $call:ident) => {
        impl IeeeFloat for $t {
            const FORMAT: Format = $format;
            const ZERO: $t = 0.0;
            #[inline]
            fn input(x: f64) -> $t {
                $input(x)
            }
            #[inline]
            fn constant(q: &Rational) -> $t {
                $constant(q)
            }
            #[inline]
            fn widen(self) -> f64 {
                f64::from(self)
            }
            #[inline]
            fn sqrt(self) -> $t {
                <$t>::sqrt(self)
            }
            #[inline]
            fn abs(self) -> $t {
                <$t>::abs(self)
            }
            #[inline]
            fn mul_add(self, b: $t, c: $t) -> $t {
                <$t>::mul_add(self, b, c)
            }
            #[inline]
            fn min(self, b: $t) -> $t {
                <$t>::min(self, b)
            }
            #[inline]
            fn max(self, b: $t) -> $t {
                <$t>::max(self, b)
            }
            #[inline]
            fn pow(self, n: i32, style: PowStyle) -> $t {
                $pow(self, n, style)
            }
            #[inline]
            fn call(f: Func, a: Option<$t>, b: Option<$t>) -> $t {
                $call(f, a.unwrap_or(<$t>::NAN), b.unwrap_or(<$t>::NAN))
            }
        }
    };
}

ieee_float!(
    f64,
    Format::Binary64,
    |x| x,
    Rational::to_f64,
    pow_f64,
    call_f64
);
// A binary32 literal is decided from the exact rational (the double returned holds it exactly).
ieee_float!(
    f32,
    Format::Binary32,
    |x: f64| x as f32,
    |q: &Rational| crate::to_f64::rational_to_f32(&q.to_big_rational()) as f32,
    pow_f32,
    call_f32
);

/// The IEEE domain of one format over borrowed inputs, with the loop iterations done so far.
struct Ieee<'a, T> {
    x: &'a [f64],
    iterations: u64,
    format: std::marker::PhantomData<T>,
}

/// The truth of `a op b` in IEEE arithmetic (false on NaN, except `!=`).
#[inline]
fn ieee_compare<T: PartialOrd>(op: CmpOp, a: &T, b: &T) -> bool {
    match op {
        CmpOp::Lt => a < b,
        CmpOp::Le => a <= b,
        CmpOp::Gt => a > b,
        CmpOp::Ge => a >= b,
        CmpOp::Eq => a == b,
        CmpOp::Ne => a != b,
    }
}

impl<T: IeeeFloat> Evaluator for Ieee<'_, T> {
    type V = T;
    type Stop = FloatStop;

    #[inline]
    fn input(&mut self, i: usize) -> T {
        T::input(self.x[i])
    }
    #[inline]
    fn constant(&mut self, q: &Rational) -> Result<T, FloatStop> {
        Ok(T::constant(q))
    }
    #[inline]
    fn neg(&mut self, a: T) -> Result<T, FloatStop> {
        Ok(-a)
    }
    #[inline]
    fn add(&mut self, a: T, b: T) -> Result<T, FloatStop> {
        Ok(a + b)
    }
    #[inline]
    fn sub(&mut self, a: T, b: T) -> Result<T, FloatStop> {
        Ok(a - b)
    }
    #[inline]
    fn mul(&mut self, a: T, b: T) -> Result<T, FloatStop> {
        Ok(a * b)
    }
    #[inline]
    fn div(&mut self, a: T, b: T) -> Result<T, FloatStop> {
        Ok(a / b)
    }
    #[inline]
    fn sqrt(&mut self, a: T) -> Result<T, FloatStop> {
        Ok(a.sqrt())
    }
    #[inline]
    fn abs(&mut self, a: T) -> Result<T, FloatStop> {
        Ok(a.abs())
    }
    #[inline]
    fn fma(&mut self, a: T, b: T, c: T) -> Result<T, FloatStop> {
        Ok(a.mul_add(b, c))
    }
    #[inline]
    fn min(&mut self, a: T, b: T) -> Result<T, FloatStop> {
        Ok(a.min(b))
    }
    #[inline]
    fn max(&mut self, a: T, b: T) -> Result<T, FloatStop> {
        Ok(a.max(b))
    }
    #[inline]
    fn pow(&mut self, a: T, n: i32, style: PowStyle) -> Result<T, FloatStop> {
        Ok(a.pow(n, style))
    }
    #[inline]
    fn call(&mut self, f: Func, a: Option<T>, b: Option<T>) -> Result<T, FloatStop> {
        Ok(T::call(f, a, b))
    }
    #[inline]
    fn compare(&mut self, op: CmpOp, a: &T, b: &T) -> Result<bool, FloatStop> {
        Ok(ieee_compare(op, a, b))
    }
    #[inline]
    fn iterate(&mut self) -> Result<(), FloatStop> {
        if count_iteration(&mut self.iterations) {
            Ok(())
        } else {
            Err(FloatStop::Loop)
        }
    }
    /// The program's own precision changes nothing; another one is a mixed program.
    #[inline]
    fn set_format(&mut self, f: Format) -> Result<Format, FloatStop> {
        if f == T::FORMAT {
            Ok(f)
        } else {
            Err(FloatStop::Mixed)
        }
    }
    // `cast`: every value of a program of one precision already is a value of it (the default).
}

/// The mixed-precision domain: a program whose operations round to different precisions
/// (FPCore's `:precision` on sub-expressions and `cast`). Values are doubles (a binary32 value
/// is held exactly); every operation rounds its exact result once, to the precision in scope,
/// whatever the precisions of its operands.
struct Mixed<'a> {
    x: &'a [f64],
    iterations: u64,
    format: Format,
}

/// The binary32 value nearest to a real number `t`, given the double `r` nearest to it and the
/// sign of `t - r` (`Equal`: `r` is `t`). `r` is first made the round-to-odd double of `t` (the
/// odd neighbour on the side of `t` when `r` is inexact and even), which rounds to binary32 as
/// `t` itself does: a double has more than binary32's precision plus two bits.
fn round32(r: f64, rest: Ordering) -> f64 {
    if !r.is_finite() || r == 0.0 || rest == Ordering::Equal || r.to_bits() & 1 == 1 {
        return f64::from(r as f32);
    }
    let away = (rest == Ordering::Greater) == (r > 0.0);
    let odd = f64::from_bits(if away {
        r.to_bits() + 1
    } else {
        r.to_bits() - 1
    });
    f64::from(odd as f32)
}

/// The sign of `v` (`Equal` for zero and NaN).
fn sign(v: f64) -> Ordering {
    v.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
}

/// Whether `v` is a binary32 value (or not finite).
fn is_f32(v: f64) -> bool {
    !v.is_finite() || f64::from(v as f32) == v
}

impl Mixed<'_> {
    /// A result that is exact in doubles (negation, `fabs`, `fmin`, `fmax`, `cast`), rounded to
    /// the precision in scope.
    fn exact(&self, v: f64) -> f64 {
        match self.format {
            Format::Binary64 => v,
            Format::Binary32 => f64::from(v as f32),
        }
    }

    /// `r`, the double nearest to an operation's exact result `r + e` (`e` the sign of the
    /// exact remainder), rounded to the precision in scope.
    fn rounded(&self, r: f64, rest: impl FnOnce() -> Ordering) -> f64 {
        match self.format {
            Format::Binary64 => r,
            Format::Binary32 => round32(
                r,
                if r.is_finite() {
                    rest()
                } else {
                    Ordering::Equal
                },
            ),
        }
    }
}

impl Evaluator for Mixed<'_> {
    type V = f64;
    type Stop = FloatStop;

    fn input(&mut self, i: usize) -> f64 {
        self.x[i]
    }
    fn constant(&mut self, q: &Rational) -> Result<f64, FloatStop> {
        Ok(match self.format {
            Format::Binary64 => q.to_f64(),
            Format::Binary32 => crate::to_f64::rational_to_f32(&q.to_big_rational()),
        })
    }
    fn neg(&mut self, a: f64) -> Result<f64, FloatStop> {
        Ok(self.exact(-a))
    }
    fn add(&mut self, a: f64, b: f64) -> Result<f64, FloatStop> {
        let r = a + b;
        // The exact error of the sum (Knuth's TwoSum).
        Ok(self.rounded(r, || {
            let bb = r - a;
            sign((a - (r - bb)) + (b - bb))
        }))
    }
    fn sub(&mut self, a: f64, b: f64) -> Result<f64, FloatStop> {
        self.add(a, -b)
    }
    fn mul(&mut self, a: f64, b: f64) -> Result<f64, FloatStop> {
        let r = a * b;
        // The exact error of the product by one fused multiply-add.
        Ok(self.rounded(r, || sign(a.mul_add(b, -r))))
    }
    fn div(&mut self, a: f64, b: f64) -> Result<f64, FloatStop> {
        let r = a / b;
        // a/b - r = (a - r b) / b, the remainder exact by one fused multiply-add.
        Ok(self.rounded(r, || {
            let rem = sign((-r).mul_add(b, a));
            if b < 0.0 {
                rem.reverse()
            } else {
                rem
            }
        }))
    }
    fn sqrt(&mut self, a: f64) -> Result<f64, FloatStop> {
        let r = a.sqrt();
        // sqrt(a) - r has the sign of a - r^2.
        Ok(self.rounded(r, || sign((-r).mul_add(r, a))))
    }
    fn abs(&mut self, a: f64) -> Result<f64, FloatStop> {
        Ok(self.exact(a.abs()))
    }
    fn fma(&mut self, a: f64, b: f64, c: f64) -> Result<f64, FloatStop> {
        Ok(match self.format {
            Format::Binary64 => a.mul_add(b, c),
            Format::Binary32 if is_f32(a) && is_f32(b) && is_f32(c) => {
                f64::from((a as f32).mul_add(b as f32, c as f32))
            }
            // Wider operands: the exact `a b + c`, rounded once.
            Format::Binary32 => match [a, b, c]
                .map(|v| num_rational::BigRational::from_f64(v).map(Rational::from))
            {
                [Some(a), Some(b), Some(c)] => {
                    crate::to_f64::rational_to_f32(&(&(&a * &b) + &c).to_big_rational())
                }
                _ => f64::from(a.mul_add(b, c) as f32),
            },
        })
    }
    fn min(&mut self, a: f64, b: f64) -> Result<f64, FloatStop> {
        Ok(self.exact(a.min(b)))
    }
    fn max(&mut self, a: f64, b: f64) -> Result<f64, FloatStop> {
        Ok(self.exact(a.max(b)))
    }
    fn pow(&mut self, a: f64, n: i32, style: PowStyle) -> Result<f64, FloatStop> {
        match (style, self.format) {
            (PowStyle::Multiply, _) => {
                if n == 0 {
                    return Ok(1.0);
                }
                let mut acc = a;
                for _ in 1..n.unsigned_abs() {
                    acc = self.mul(acc, a)?;
                }
                if n < 0 {
                    self.div(1.0, acc)
                } else {
                    Ok(acc)
                }
            }
            (PowStyle::Libm, Format::Binary64) => Ok(pow_f64(a, n, style)),
            (PowStyle::Libm, Format::Binary32) if is_f32(a) => {
                Ok(f64::from(pow_f32(a as f32, n, style)))
            }
            (PowStyle::Libm, Format::Binary32) => Ok(f64::from(pow_f64(a, n, style) as f32)),
        }
    }
    /// The C library's function of the precision in scope (`sinf` on binary32 arguments); on
    /// wider arguments in binary32 the double function, rounded.
    fn call(&mut self, f: Func, a: Option<f64>, b: Option<f64>) -> Result<f64, FloatStop> {
        let (a, b) = (a.unwrap_or(f64::NAN), b.unwrap_or(f64::NAN));
        Ok(match self.format {
            Format::Binary64 => call_f64(f, a, b),
            Format::Binary32 if is_f32(a) && is_f32(b) => {
                f64::from(call_f32(f, a as f32, b as f32))
            }
            Format::Binary32 => f64::from(call_f64(f, a, b) as f32),
        })
    }
    fn compare(&mut self, op: CmpOp, a: &f64, b: &f64) -> Result<bool, FloatStop> {
        Ok(ieee_compare(op, a, b))
    }
    fn iterate(&mut self) -> Result<(), FloatStop> {
        if count_iteration(&mut self.iterations) {
            Ok(())
        } else {
            Err(FloatStop::Loop)
        }
    }
    fn set_format(&mut self, f: Format) -> Result<Format, FloatStop> {
        Ok(std::mem::replace(&mut self.format, f))
    }
    fn cast(&mut self, a: f64) -> Result<f64, FloatStop> {
        Ok(self.exact(a))
    }
}

/// `a^n` in one float type per [`PowStyle`]: `$name(a, n, style)` in `$t` (`Libm`: the C
/// library's `pow` of the exponent converted to `$t`, as C's `pow(a, (double)n)` and
/// `powf(a, (float)n)`; `Multiply`: `n - 1` rounded products, then one reciprocal for `n < 0`).
macro_rules! libm_pow {
    ($(#[$doc:meta])* $name:ident, $t:ident) => {
        $(#[$doc])*
        pub fn $name(a: $t, n: i32, style: PowStyle) -> $t {
            match style {
                PowStyle::Libm => a.powf(n as $t),
                PowStyle::Multiply => {
                    if n == 0 {
                        return 1.0;
                    }
                    let mut acc = a;
                    for _ in 1..n.unsigned_abs() {
                        acc *= a;
                    }
                    if n < 0 {
                        1.0 / acc
                    } else {
                        acc
                    }
                }
            }
        }
    };
}

libm_pow! {
    /// `a^n` in binary32, per [`PowStyle`] (`Libm`: C's `powf(a, (float)n)`).
    pow_f32, f32
}

libm_pow! {
    /// `a^n` in doubles, per [`PowStyle`] (`Libm`: C's `pow(a, (double)n)`, the exponent exact).
    pow_f64, f64
}

/// The C-library call table of one float type: `$name(f, a, b)` in `$t` (its `consts` for pi
/// and e, Rust's methods, which call the C library, and the declared inverse hyperbolic
/// functions `$asinh`, `$acosh`, `$atanh`).
macro_rules! libm_calls {
    ($(#[$doc:meta])* $name:ident, $t:ident, $asinh:ident, $acosh:ident, $atanh:ident) => {
        $(#[$doc])*
        pub fn $name(f: Func, a: $t, b: $t) -> $t {
            match f {
                Func::Pi => std::$t::consts::PI,
                Func::E => std::$t::consts::E,
                Func::Exp => a.exp(),
                Func::Exp2 => a.exp2(),
                Func::Expm1 => a.exp_m1(),
                Func::Log => a.ln(),
                Func::Log2 => a.log2(),
                Func::Log10 => a.log10(),
                Func::Log1p => a.ln_1p(),
                Func::Sin => a.sin(),
                Func::Cos => a.cos(),
                Func::Tan => a.tan(),
                Func::Asin => a.asin(),
                Func::Acos => a.acos(),
                Func::Atan => a.atan(),
                Func::Atan2 => a.atan2(b),
                Func::Sinh => a.sinh(),
                Func::Cosh => a.cosh(),
                Func::Tanh => a.tanh(),
                Func::Asinh => cmath::$asinh(a),
                Func::Acosh => cmath::$acosh(a),
                Func::Atanh => cmath::$atanh(a),
                Func::Pow => a.powf(b),
                Func::Hypot => a.hypot(b),
                Func::Cbrt => a.cbrt(),
            }
        }
    };
}

libm_calls! {
    /// The function `f` in binary32: the C library's `f32` functions (Rust's `f32` methods call
    /// `expf`, `logf`, `sinf`, `powf`, `hypotf`, `cbrtf`, ...; the inverse hyperbolic functions are
    /// declared directly), and the binary32 values nearest to pi and e.
    call_f32, f32, asinhf, acoshf, atanhf
}

/// The inverse hyperbolic functions of the platform's C library. Rust's `f64::asinh`, `acosh`
/// and `atanh` are formulas in Rust (not the C functions) that lose several ulps near `|x| = 1`
/// and `x = 1`; a compiled C program calls these.
mod cmath {
    extern "C" {
        #[link_name = "asinh"]
        fn c_asinh(x: f64) -> f64;
        #[link_name = "acosh"]
        fn c_acosh(x: f64) -> f64;
        #[link_name = "atanh"]
        fn c_atanh(x: f64) -> f64;
        #[link_name = "asinhf"]
        fn c_asinhf(x: f32) -> f32;
        #[link_name = "acoshf"]
        fn c_acoshf(x: f32) -> f32;
        #[link_name = "atanhf"]
        fn c_atanhf(x: f32) -> f32;
    }

    pub(super) fn asinh(x: f64) -> f64 {
        // SAFETY: a pure C function of one double, defined for every double.
        unsafe { c_asinh(x) }
    }
    pub(super) fn acosh(x: f64) -> f64 {
        // SAFETY: as above.
        unsafe { c_acosh(x) }
    }
    pub(super) fn atanh(x: f64) -> f64 {
        // SAFETY: as above.
        unsafe { c_atanh(x) }
    }
    pub(super) fn asinhf(x: f32) -> f32 {
        // SAFETY: a pure C function of one float, defined for every float.
        unsafe { c_asinhf(x) }
    }
    pub(super) fn acoshf(x: f32) -> f32 {
        // SAFETY: as above.
        unsafe { c_acoshf(x) }
    }
    pub(super) fn atanhf(x: f32) -> f32 {
        // SAFETY: as above.
        unsafe { c_atanhf(x) }
    }
}

libm_calls! {
    /// The function `f` in doubles: the platform's C library (Rust's `f64` methods call it for
    /// `exp`, `log`, `sin`, `pow`, `hypot`, `cbrt`, ...; the inverse hyperbolic functions are
    /// declared directly); `b` is the second argument of the two-argument functions
    /// (`atan2(a, b)` is `atan2(y = a, x = b)`), ignored otherwise.
    call_f64, f64, asinh, acosh, atanh
}

impl Program {
    /// The outputs evaluated in IEEE doubles at `x` (one value per input), in the order of the
    /// tree; never fails (see the module documentation of `program::float`).
    ///
    /// # Panics
    /// When `x.len()` is not [`Program::arity`], or on a malformed program (a slot or input
    /// index out of range; the compilers never build one).
    pub fn eval_f64(&self, x: &[f64]) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.outputs.len());
        self.eval_f64_into(x, &mut out);
        out
    }

    /// [`Program::eval_f64`] into a reused vector (cleared first): no allocation once `out` has
    /// the capacity, for programs of one precision with at most [`STACK_SLOTS`] slots.
    ///
    /// # Panics
    /// As [`Program::eval_f64`].
    pub fn eval_f64_into(&self, x: &[f64], out: &mut Vec<f64>) {
        assert_eq!(
            x.len(),
            self.inputs.len(),
            "Program::eval_f64: {} values for {} inputs",
            x.len(),
            self.inputs.len()
        );
        out.clear();
        let uniform = match self.precision {
            Format::Binary64 => self.eval_ieee::<f64>(x, out),
            // A binary64 input of a binary32 program is not a binary32 operand: the operations
            // on it round its exact value once, in the mixed domain.
            Format::Binary32 if self.mixes_input_precisions() => Err(FloatStop::Mixed),
            Format::Binary32 => self.eval_ieee::<f32>(x, out),
        };
        let done = match uniform {
            Err(FloatStop::Mixed) => {
                out.clear();
                self.eval_mixed(x, out)
            }
            other => other,
        };
        if done.is_err() {
            // Loops past the limit: no output has a value.
            out.clear();
            out.resize(self.outputs.len(), f64::NAN);
        }
    }

    /// The walk in the IEEE format `T` (`out` is empty); [`FloatStop::Mixed`] at the first
    /// operation of another precision.
    fn eval_ieee<T: IeeeFloat>(&self, x: &[f64], out: &mut Vec<f64>) -> Result<(), FloatStop> {
        let mut d = Ieee::<T> {
            x,
            iterations: 0,
            format: std::marker::PhantomData,
        };
        let mut stack = [T::ZERO; STACK_SLOTS];
        let mut heap;
        let slots: &mut [T] = if self.slots <= STACK_SLOTS {
            &mut stack[..self.slots]
        } else {
            heap = vec![T::ZERO; self.slots];
            &mut heap
        };
        for node in &self.outputs {
            out.push(eval_node(&mut d, node, slots)?.widen());
        }
        Ok(())
    }

    /// The walk of a program that mixes precisions (`out` is empty).
    fn eval_mixed(&self, x: &[f64], out: &mut Vec<f64>) -> Result<(), FloatStop> {
        let mut d = Mixed {
            x,
            iterations: 0,
            format: self.precision,
        };
        let mut slots = vec![0.0; self.slots];
        for node in &self.outputs {
            out.push(eval_node(&mut d, node, &mut slots)?);
        }
        Ok(())
    }
}
