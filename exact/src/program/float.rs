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
//! The evaluation never fails and allocates nothing per node (a `while` loop's parallel update
//! excepted): it is the generic walk of `walk` over the `Copy` type `f64`, with the `let` slots in a stack array (a heap vector only for
//! programs with more than [`STACK_SLOTS`] slots).
use super::walk::{count_iteration, eval_node, Evaluator};
use super::{CmpOp, Format, Func, PowStyle, Program};
use crate::rational::Rational;

/// Programs with at most this many `let` slots keep them on the stack during a float evaluation.
pub const STACK_SLOTS: usize = 32;

/// The IEEE double domain over borrowed inputs, with the loop iterations done so far.
struct F64<'a> {
    x: &'a [f64],
    iterations: u64,
}

/// The float evaluation stopped: its loops ran past the `loop-iterations` limit.
pub(super) struct LoopStop;

impl Evaluator for F64<'_> {
    type V = f64;
    type Stop = LoopStop;

    #[inline]
    fn input(&mut self, i: usize) -> f64 {
        self.x[i]
    }
    #[inline]
    fn constant(&mut self, q: &Rational) -> Result<f64, LoopStop> {
        Ok(q.to_f64())
    }
    #[inline]
    fn neg(&mut self, a: f64) -> Result<f64, LoopStop> {
        Ok(-a)
    }
    #[inline]
    fn add(&mut self, a: f64, b: f64) -> Result<f64, LoopStop> {
        Ok(a + b)
    }
    #[inline]
    fn sub(&mut self, a: f64, b: f64) -> Result<f64, LoopStop> {
        Ok(a - b)
    }
    #[inline]
    fn mul(&mut self, a: f64, b: f64) -> Result<f64, LoopStop> {
        Ok(a * b)
    }
    #[inline]
    fn div(&mut self, a: f64, b: f64) -> Result<f64, LoopStop> {
        Ok(a / b)
    }
    #[inline]
    fn sqrt(&mut self, a: f64) -> Result<f64, LoopStop> {
        Ok(a.sqrt())
    }
    #[inline]
    fn abs(&mut self, a: f64) -> Result<f64, LoopStop> {
        Ok(a.abs())
    }
    #[inline]
    fn fma(&mut self, a: f64, b: f64, c: f64) -> Result<f64, LoopStop> {
        Ok(a.mul_add(b, c))
    }
    #[inline]
    fn min(&mut self, a: f64, b: f64) -> Result<f64, LoopStop> {
        Ok(a.min(b))
    }
    #[inline]
    fn max(&mut self, a: f64, b: f64) -> Result<f64, LoopStop> {
        Ok(a.max(b))
    }
    #[inline]
    fn pow(&mut self, a: f64, n: i32, style: PowStyle) -> Result<f64, LoopStop> {
        Ok(pow_f64(a, n, style))
    }
    #[inline]
    fn call(&mut self, f: Func, a: Option<f64>, b: Option<f64>) -> Result<f64, LoopStop> {
        Ok(call_f64(f, a.unwrap_or(f64::NAN), b.unwrap_or(f64::NAN)))
    }
    #[inline]
    fn compare(&mut self, op: CmpOp, a: &f64, b: &f64) -> Result<bool, LoopStop> {
        Ok(match op {
            CmpOp::Lt => a < b,
            CmpOp::Le => a <= b,
            CmpOp::Gt => a > b,
            CmpOp::Ge => a >= b,
            CmpOp::Eq => a == b,
            CmpOp::Ne => a != b,
        })
    }
    #[inline]
    fn iterate(&mut self) -> Result<(), LoopStop> {
        if count_iteration(&mut self.iterations) {
            Ok(())
        } else {
            Err(LoopStop)
        }
    }
}

/// The binary32 domain over borrowed inputs (each taken as binary32), with the loop iterations.
struct F32<'a> {
    x: &'a [f64],
    iterations: u64,
}

impl Evaluator for F32<'_> {
    type V = f32;
    type Stop = LoopStop;

    #[inline]
    fn input(&mut self, i: usize) -> f32 {
        self.x[i] as f32
    }
    fn constant(&mut self, q: &Rational) -> Result<f32, LoopStop> {
        // Exact: the binary32 value is held exactly by the double.
        Ok(crate::to_f64::rational_to_f32(&q.to_big_rational()) as f32)
    }
    #[inline]
    fn neg(&mut self, a: f32) -> Result<f32, LoopStop> {
        Ok(-a)
    }
    #[inline]
    fn add(&mut self, a: f32, b: f32) -> Result<f32, LoopStop> {
        Ok(a + b)
    }
    #[inline]
    fn sub(&mut self, a: f32, b: f32) -> Result<f32, LoopStop> {
        Ok(a - b)
    }
    #[inline]
    fn mul(&mut self, a: f32, b: f32) -> Result<f32, LoopStop> {
        Ok(a * b)
    }
    #[inline]
    fn div(&mut self, a: f32, b: f32) -> Result<f32, LoopStop> {
        Ok(a / b)
    }
    #[inline]
    fn sqrt(&mut self, a: f32) -> Result<f32, LoopStop> {
        Ok(a.sqrt())
    }
    #[inline]
    fn abs(&mut self, a: f32) -> Result<f32, LoopStop> {
        Ok(a.abs())
    }
    #[inline]
    fn fma(&mut self, a: f32, b: f32, c: f32) -> Result<f32, LoopStop> {
        Ok(a.mul_add(b, c))
    }
    #[inline]
    fn min(&mut self, a: f32, b: f32) -> Result<f32, LoopStop> {
        Ok(a.min(b))
    }
    #[inline]
    fn max(&mut self, a: f32, b: f32) -> Result<f32, LoopStop> {
        Ok(a.max(b))
    }
    #[inline]
    fn pow(&mut self, a: f32, n: i32, style: PowStyle) -> Result<f32, LoopStop> {
        Ok(pow_f32(a, n, style))
    }
    #[inline]
    fn call(&mut self, f: Func, a: Option<f32>, b: Option<f32>) -> Result<f32, LoopStop> {
        Ok(call_f32(f, a.unwrap_or(f32::NAN), b.unwrap_or(f32::NAN)))
    }
    #[inline]
    fn compare(&mut self, op: CmpOp, a: &f32, b: &f32) -> Result<bool, LoopStop> {
        Ok(match op {
            CmpOp::Lt => a < b,
            CmpOp::Le => a <= b,
            CmpOp::Gt => a > b,
            CmpOp::Ge => a >= b,
            CmpOp::Eq => a == b,
            CmpOp::Ne => a != b,
        })
    }
    #[inline]
    fn iterate(&mut self) -> Result<(), LoopStop> {
        if count_iteration(&mut self.iterations) {
            Ok(())
        } else {
            Err(LoopStop)
        }
    }
}

/// `a^n` in binary32, per [`PowStyle`] (`Libm`: C's `powf(a, (float)n)`).
pub fn pow_f32(a: f32, n: i32, style: PowStyle) -> f32 {
    match style {
        PowStyle::Libm => a.powf(n as f32),
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

/// The function `f` in binary32: the C library's `f32` functions (Rust's `f32` methods call
/// `expf`, `logf`, `sinf`, `powf`, `hypotf`, `cbrtf`, ...; the inverse hyperbolic functions are
/// declared directly), and the binary32 values nearest to pi and e.
pub fn call_f32(f: Func, a: f32, b: f32) -> f32 {
    match f {
        Func::Pi => std::f32::consts::PI,
        Func::E => std::f32::consts::E,
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
        Func::Asinh => cmath::asinhf(a),
        Func::Acosh => cmath::acoshf(a),
        Func::Atanh => cmath::atanhf(a),
        Func::Pow => a.powf(b),
        Func::Hypot => a.hypot(b),
        Func::Cbrt => a.cbrt(),
    }
}

/// `a^n` in doubles, per [`PowStyle`].
pub fn pow_f64(a: f64, n: i32, style: PowStyle) -> f64 {
    match style {
        PowStyle::Libm => a.powf(f64::from(n)),
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

/// The function `f` in doubles: the platform's C library (Rust's `f64` methods call it for
/// `exp`, `log`, `sin`, `pow`, `hypot`, `cbrt`, ...; the inverse hyperbolic functions are
/// declared directly); `b` is the second argument of the two-argument functions
/// (`atan2(a, b)` is `atan2(y = a, x = b)`), ignored otherwise.
pub fn call_f64(f: Func, a: f64, b: f64) -> f64 {
    match f {
        Func::Pi => std::f64::consts::PI,
        Func::E => std::f64::consts::E,
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
        Func::Asinh => cmath::asinh(a),
        Func::Acosh => cmath::acosh(a),
        Func::Atanh => cmath::atanh(a),
        Func::Pow => a.powf(b),
        Func::Hypot => a.hypot(b),
        Func::Cbrt => a.cbrt(),
    }
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
    /// the capacity, for programs with at most [`STACK_SLOTS`] slots.
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
        if self.precision == Format::Binary32 {
            self.eval_f32_into(x, out);
            return;
        }
        let mut d = F64 { x, iterations: 0 };
        let mut stack = [0.0f64; STACK_SLOTS];
        let mut heap;
        let slots: &mut [f64] = if self.slots <= STACK_SLOTS {
            &mut stack[..self.slots]
        } else {
            heap = vec![0.0; self.slots];
            &mut heap
        };
        for node in &self.outputs {
            match eval_node(&mut d, node, slots) {
                Ok(v) => out.push(v),
                Err(LoopStop) => {
                    // Loops past the limit: no output has a value.
                    out.clear();
                    out.resize(self.outputs.len(), f64::NAN);
                    return;
                }
            }
        }
    }

    /// The binary32 walk of [`Program::eval_f64_into`] (`out` is empty).
    fn eval_f32_into(&self, x: &[f64], out: &mut Vec<f64>) {
        let mut d = F32 { x, iterations: 0 };
        let mut stack = [0.0f32; STACK_SLOTS];
        let mut heap;
        let slots: &mut [f32] = if self.slots <= STACK_SLOTS {
            &mut stack[..self.slots]
        } else {
            heap = vec![0.0; self.slots];
            &mut heap
        };
        for node in &self.outputs {
            match eval_node(&mut d, node, slots) {
                Ok(v) => out.push(f64::from(v)),
                Err(LoopStop) => {
                    out.clear();
                    out.resize(self.outputs.len(), f64::NAN);
                    return;
                }
            }
        }
    }
}
