//! Where a program's error comes from at one sample, from the exact values of its operations:
//! * **local error** ([`Program::local_errors`]): each rounding operation evaluated in f64 on
//!   the exact values of its operands rounded to doubles, against the exact value of the
//!   subexpression it computes, rounded. An operation fed (nearly) exact operands that still
//!   misses the true value is where the bits are lost: a subtraction of two close rounded
//!   square roots misses by the operands' rounding errors, amplified by the cancellation (a
//!   binary32 program: the operation in binary32 on the operands rounded to binary32);
//! * **conditioning** ([`Program::conditioning`]): the relative condition number
//!   `sum_i |x_i * df/dx_i / f|` of each output, the derivatives computed by forward-mode dual
//!   numbers over the exact reals of `real` (rationals, and enclosures refined like the value
//!   itself). A double result of an ill-conditioned function loses about `log2(cond)` bits
//!   whatever the algorithm; more than that is the algorithm's.
//!
//! Both are further domains of the one generic walk (`walk`), so they follow the evaluation
//! order, `let` and `if` of the float and exact sides. The derivatives are hand-written dual
//! numbers rather than a symbolic `diff` of the expression because a program is not always an
//! expression of the `prove` syntax (FPCore's `let`, `if`, `fmin`...), and forward mode
//! differentiates exactly what the walk evaluates.
use super::float::{call_f32, call_f64, pow_f32, pow_f64};
use super::real::{nearest_double, rounding_decided, ExactStop, Halt, Real, MAX_PRECISION, XV};
use super::walk::{eval_node, Evaluator};
use super::{CmpOp, Format, Func, PowStyle, Program, START_PRECISION};
use crate::rational::Rational;
use exactcheck_core::Ring;
use std::cmp::Ordering;
use std::rc::Rc;

/// Subexpression texts longer than this are cut (with `...`) in reports.
const MAX_TEXT: usize = 120;

/// One rounding operation at one sample, fed the exact values of its operands rounded to
/// doubles.
#[derive(Clone, Debug, PartialEq)]
pub struct LocalError {
    /// What the operation is: `addition`, `subtraction`, `multiplication`, `division`,
    /// `square root`, `fma`, `power`.
    pub operation: &'static str,
    /// The subexpression it computes, in infix (cut to about 120 characters).
    pub at: String,
    /// The operation in f64 on the exact operands rounded to doubles.
    pub float: f64,
    /// The exact value of the subexpression, rounded to the nearest double.
    pub exact: f64,
}

/// The relative conditioning of one output at one sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Conditioning {
    /// `sum_i |x_i * df/dx_i / f|`, to about 6 significant bits or better.
    Number(f64),
    /// The exact value is 0: relative conditioning is undefined there.
    ZeroValue,
    /// The function is not differentiable at the sample (`|a|`, `sqrt(a)`, `min`/`max` at a
    /// kink).
    NotDifferentiable,
}

/// A value with the text of the subexpression it came from.
#[derive(Clone, Debug)]
struct Tracked {
    x: XV,
    text: Rc<str>,
    /// Binding strength of the text's outermost operator: 0 sum, 1 product, 2 unary minus,
    /// 3 power, 4 atom.
    prec: u8,
}

fn cut(s: String) -> Rc<str> {
    if s.chars().count() <= MAX_TEXT {
        return s.into();
    }
    let head: String = s.chars().take(MAX_TEXT - 3).collect();
    format!("{head}...").into()
}

/// `t` as an operand that needs at least binding strength `min`.
fn operand(t: &Tracked, min: u8) -> String {
    if t.prec >= min {
        t.text.to_string()
    } else {
        format!("({})", t.text)
    }
}

/// The local-error domain: the exact walk of `real` that also records every rounding
/// operation.
struct Local<'a> {
    real: Real<'a>,
    format: Format,
    names: &'a [String],
    ops: Vec<LocalError>,
}

impl Local<'_> {
    /// The value of the program's format nearest to an exact value; a refinement when an
    /// enclosure does not decide it.
    fn round(&self, v: &XV) -> Result<f64, Halt> {
        match (v, self.format) {
            (XV::Exact(q), Format::Binary64) => Ok(q.to_f64()),
            (XV::Approx(iv, _), Format::Binary64) if rounding_decided(iv) => {
                Ok(nearest_double(&iv.lo))
            }
            (XV::Exact(q), f) => Ok(f.round(&q.to_big_rational())),
            (XV::Approx(iv, _), f) => {
                let lo = f.round(&iv.lo.to_big_rational());
                if lo.to_bits() == f.round(&iv.hi.to_big_rational()).to_bits() {
                    Ok(lo)
                } else {
                    Err(Halt::Refine { ambiguous: false })
                }
            }
        }
    }

    /// A result of `+ - * /` or `sqrt` computed in doubles on operands of the format, rounded to
    /// the format: for binary32 operands that is the binary32 operation (a double holds the
    /// exact result to more than twice binary32's precision plus two bits, so the second
    /// rounding is innocuous).
    fn fl(&self, v: f64) -> f64 {
        match self.format {
            Format::Binary64 => v,
            Format::Binary32 => f64::from(v as f32),
        }
    }

    fn record(
        &mut self,
        operation: &'static str,
        x: XV,
        float: f64,
        text: String,
        prec: u8,
    ) -> Result<Tracked, Halt> {
        let exact = self.round(&x)?;
        let text = cut(text);
        self.ops.push(LocalError {
            operation,
            at: text.to_string(),
            float,
            exact,
        });
        Ok(Tracked { x, text, prec })
    }

    fn binary(&mut self, a: Tracked, b: Tracked, op: char) -> Result<Tracked, Halt> {
        let (fa, fb) = (self.round(&a.x)?, self.round(&b.x)?);
        let (name, prec, float) = match op {
            '+' => ("addition", 0, fa + fb),
            '-' => ("subtraction", 0, fa - fb),
            '*' => ("multiplication", 1, fa * fb),
            _ => ("division", 1, fa / fb),
        };
        let float = self.fl(float);
        let text = format!("{} {op} {}", operand(&a, prec), operand(&b, prec + 1));
        let x = match op {
            '+' => self.real.add(a.x, b.x)?,
            '-' => self.real.sub(a.x, b.x)?,
            '*' => self.real.mul(a.x, b.x)?,
            _ => self.real.div(a.x, b.x)?,
        };
        self.record(name, x, float, text, prec)
    }

    fn call(name: &str, args: &[&Tracked]) -> String {
        let inner: Vec<&str> = args.iter().map(|t| &*t.text).collect();
        format!("{name}({})", inner.join(", "))
    }
}

impl Evaluator for Local<'_> {
    type V = Tracked;
    type Stop = Halt;

    fn input(&mut self, i: usize) -> Tracked {
        Tracked {
            x: self.real.input(i),
            text: self.names[i].as_str().into(),
            prec: 4,
        }
    }
    fn constant(&mut self, q: &Rational) -> Result<Tracked, Halt> {
        let text = q.to_string();
        let prec = if text.starts_with('-') {
            2
        } else if text.contains('/') {
            1
        } else {
            4
        };
        Ok(Tracked {
            x: self.real.constant(q)?,
            text: text.into(),
            prec,
        })
    }
    fn neg(&mut self, a: Tracked) -> Result<Tracked, Halt> {
        let text = cut(format!("-{}", operand(&a, 3)));
        Ok(Tracked {
            x: self.real.neg(a.x)?,
            text,
            prec: 2,
        })
    }
    fn add(&mut self, a: Tracked, b: Tracked) -> Result<Tracked, Halt> {
        self.binary(a, b, '+')
    }
    fn sub(&mut self, a: Tracked, b: Tracked) -> Result<Tracked, Halt> {
        self.binary(a, b, '-')
    }
    fn mul(&mut self, a: Tracked, b: Tracked) -> Result<Tracked, Halt> {
        self.binary(a, b, '*')
    }
    fn div(&mut self, a: Tracked, b: Tracked) -> Result<Tracked, Halt> {
        self.binary(a, b, '/')
    }
    fn sqrt(&mut self, a: Tracked) -> Result<Tracked, Halt> {
        let float = self.fl(self.round(&a.x)?.sqrt());
        let text = Self::call("sqrt", &[&a]);
        let x = self.real.sqrt(a.x)?;
        self.record("square root", x, float, text, 4)
    }
    fn abs(&mut self, a: Tracked) -> Result<Tracked, Halt> {
        let text = cut(Self::call("fabs", &[&a]));
        Ok(Tracked {
            x: self.real.abs(a.x)?,
            text,
            prec: 4,
        })
    }
    fn fma(&mut self, a: Tracked, b: Tracked, c: Tracked) -> Result<Tracked, Halt> {
        let (fa, fb, fc) = (self.round(&a.x)?, self.round(&b.x)?, self.round(&c.x)?);
        let float = match self.format {
            Format::Binary64 => fa.mul_add(fb, fc),
            Format::Binary32 => f64::from((fa as f32).mul_add(fb as f32, fc as f32)),
        };
        let text = Self::call("fma", &[&a, &b, &c]);
        let x = self.real.fma(a.x, b.x, c.x)?;
        self.record("fma", x, float, text, 4)
    }
    fn min(&mut self, a: Tracked, b: Tracked) -> Result<Tracked, Halt> {
        let text = cut(Self::call("fmin", &[&a, &b]));
        Ok(Tracked {
            x: self.real.min(a.x, b.x)?,
            text,
            prec: 4,
        })
    }
    fn max(&mut self, a: Tracked, b: Tracked) -> Result<Tracked, Halt> {
        let text = cut(Self::call("fmax", &[&a, &b]));
        Ok(Tracked {
            x: self.real.max(a.x, b.x)?,
            text,
            prec: 4,
        })
    }
    fn pow(&mut self, a: Tracked, n: i32, style: PowStyle) -> Result<Tracked, Halt> {
        let fa = self.round(&a.x)?;
        let float = match self.format {
            Format::Binary64 => pow_f64(fa, n, style),
            Format::Binary32 => f64::from(pow_f32(fa as f32, n, style)),
        };
        let text = match style {
            PowStyle::Multiply => format!("{}^{n}", operand(&a, 4)),
            PowStyle::Libm => format!("pow({}, {n})", a.text),
        };
        let x = self.real.pow(a.x, n, style)?;
        self.record("power", x, float, text, 3)
    }
    fn call(&mut self, f: Func, a: Option<Tracked>, b: Option<Tracked>) -> Result<Tracked, Halt> {
        let fa = a.as_ref().map(|t| self.round(&t.x)).transpose()?;
        let fb = b.as_ref().map(|t| self.round(&t.x)).transpose()?;
        let (fa, fb) = (fa.unwrap_or(0.0), fb.unwrap_or(0.0));
        let float = match self.format {
            Format::Binary64 => call_f64(f, fa, fb),
            Format::Binary32 => f64::from(call_f32(f, fa as f32, fb as f32)),
        };
        let args: Vec<&Tracked> = a.iter().chain(b.iter()).collect();
        let text = if args.is_empty() {
            f.name().to_string()
        } else {
            Self::call(f.name(), &args)
        };
        let x = self.real.call(f, a.map(|t| t.x), b.map(|t| t.x))?;
        // a constant's rounding is an operation too (PI is not a double)
        self.record(f.name(), x, float, text, 4)
    }
    fn compare(&mut self, op: CmpOp, a: &Tracked, b: &Tracked) -> Result<bool, Halt> {
        self.real.compare(op, &a.x, &b.x)
    }
    fn iterate(&mut self) -> Result<(), Halt> {
        self.real.iterate()
    }
    /// In a program that mixes precisions each operation is measured in its own: its operands'
    /// exact values rounded to it, the operation in it, against its exact value rounded to it.
    fn set_format(&mut self, f: Format) -> Result<Format, Halt> {
        Ok(std::mem::replace(&mut self.format, f))
    }
    fn carry(&mut self, v: Tracked) -> Result<Tracked, Halt> {
        Ok(Tracked {
            x: self.real.carry(v.x)?,
            ..v
        })
    }
}

/// Why a dual-number pass stops.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum DualStop {
    Halt(Halt),
    /// A kink or an infinite derivative at the sample.
    NotDifferentiable,
}

impl From<Halt> for DualStop {
    fn from(h: Halt) -> DualStop {
        DualStop::Halt(h)
    }
}

/// A value and its gradient with respect to the inputs.
#[derive(Clone, Debug)]
struct DualValue {
    x: XV,
    d: Vec<XV>,
}

/// Forward-mode dual numbers over the exact reals of `real`.
struct Dual<'a> {
    real: Real<'a>,
}

fn zero() -> XV {
    XV::Exact(Rational::ZERO)
}

fn is_zero(v: &XV) -> bool {
    matches!(v, XV::Exact(q) if q.is_zero())
}

impl Dual<'_> {
    /// `a * b`, skipping exact zeros (most partial derivatives are).
    fn times(&mut self, a: &XV, b: &XV) -> Result<XV, Halt> {
        if is_zero(a) || is_zero(b) {
            return Ok(zero());
        }
        self.real.mul(a.clone(), b.clone())
    }

    /// `k * d_i` for every partial.
    fn scale(&mut self, k: &XV, d: &[XV]) -> Result<Vec<XV>, Halt> {
        d.iter().map(|di| self.times(k, di)).collect()
    }

    fn sum(&mut self, a: Vec<XV>, b: Vec<XV>, subtract: bool) -> Result<Vec<XV>, Halt> {
        a.into_iter()
            .zip(b)
            .map(|(p, q)| match (is_zero(&p), is_zero(&q)) {
                (_, true) => Ok(p),
                (true, false) if subtract => self.real.neg(q),
                (true, false) => Ok(q),
                _ if subtract => self.real.sub(p, q),
                _ => self.real.add(p, q),
            })
            .collect()
    }
}

impl Dual<'_> {
    fn q(v: i64) -> XV {
        XV::Exact(Rational::from_integer(v))
    }

    /// `1 / v`, or not differentiable where `v` is 0.
    fn recip(&mut self, v: XV) -> Result<XV, DualStop> {
        if self.real.sign(&v)? == Ordering::Equal {
            return Err(DualStop::NotDifferentiable);
        }
        Ok(self.real.div(Self::q(1), v)?)
    }

    fn f(&mut self, f: Func, a: &XV) -> Result<XV, DualStop> {
        Ok(self.real.call(f, Some(a.clone()), None)?)
    }

    /// The partial derivatives `(df/da, df/db)` of the function `f` at `(a, b)`, its value
    /// being `fx` (the textbook derivatives, evaluated exactly).
    fn partials(
        &mut self,
        f: Func,
        a: Option<&XV>,
        b: Option<&XV>,
        fx: &XV,
    ) -> Result<(Option<XV>, Option<XV>), DualStop> {
        let Some(a) = a else {
            return Ok((None, None));
        };
        let one = Self::q(1);
        let sq = |d: &mut Self, v: &XV| d.real.mul(v.clone(), v.clone());
        let da = match f {
            Func::Pi | Func::E => return Ok((None, None)),
            Func::Exp => fx.clone(),
            Func::Expm1 => self.real.add(fx.clone(), one)?,
            Func::Exp2 => {
                let ln2 = self.f(Func::Log, &Self::q(2))?;
                self.real.mul(fx.clone(), ln2)?
            }
            Func::Log => self.recip(a.clone())?,
            Func::Log2 | Func::Log10 => {
                let base = Self::q(if f == Func::Log2 { 2 } else { 10 });
                let ln = self.f(Func::Log, &base)?;
                let t = self.real.mul(a.clone(), ln)?;
                self.recip(t)?
            }
            Func::Log1p => {
                let t = self.real.add(one, a.clone())?;
                self.recip(t)?
            }
            Func::Sin => self.f(Func::Cos, a)?,
            Func::Cos => {
                let s = self.f(Func::Sin, a)?;
                self.real.neg(s)?
            }
            Func::Tan => {
                let t2 = sq(self, fx)?;
                self.real.add(one, t2)?
            }
            Func::Asin | Func::Acos => {
                let a2 = sq(self, a)?;
                let r = self.real.sub(one, a2)?;
                let r = self.real.sqrt(r)?;
                let k = self.recip(r)?;
                if f == Func::Acos {
                    self.real.neg(k)?
                } else {
                    k
                }
            }
            Func::Atan => {
                let a2 = sq(self, a)?;
                let t = self.real.add(one, a2)?;
                self.recip(t)?
            }
            Func::Sinh => self.f(Func::Cosh, a)?,
            Func::Cosh => self.f(Func::Sinh, a)?,
            Func::Tanh => {
                let t2 = sq(self, fx)?;
                self.real.sub(one, t2)?
            }
            Func::Asinh | Func::Acosh => {
                let a2 = sq(self, a)?;
                let r = if f == Func::Asinh {
                    self.real.add(a2, one)?
                } else {
                    self.real.sub(a2, one)?
                };
                let r = self.real.sqrt(r)?;
                self.recip(r)?
            }
            Func::Atanh => {
                let a2 = sq(self, a)?;
                let t = self.real.sub(one, a2)?;
                self.recip(t)?
            }
            Func::Cbrt => {
                let c2 = sq(self, fx)?;
                let t = self.real.mul(Self::q(3), c2)?;
                self.recip(t)?
            }
            Func::Atan2 | Func::Pow | Func::Hypot => {
                let Some(b) = b else {
                    return Ok((None, None));
                };
                return self.partials2(f, a, b, fx);
            }
        };
        Ok((Some(da), None))
    }

    /// The partials of the two-argument functions `atan2(a, b)`, `pow(a, b)`, `hypot(a, b)`.
    fn partials2(
        &mut self,
        f: Func,
        a: &XV,
        b: &XV,
        fx: &XV,
    ) -> Result<(Option<XV>, Option<XV>), DualStop> {
        Ok(match f {
            Func::Atan2 => {
                // atan2(y, x): d/dy = x / (x^2 + y^2), d/dx = -y / (x^2 + y^2)
                let a2 = self.real.mul(a.clone(), a.clone())?;
                let b2 = self.real.mul(b.clone(), b.clone())?;
                let r = self.real.add(a2, b2)?;
                let inv = self.recip(r)?;
                let dy = self.real.mul(b.clone(), inv.clone())?;
                let na = self.real.neg(a.clone())?;
                let dx = self.real.mul(na, inv)?;
                (Some(dy), Some(dx))
            }
            Func::Hypot => {
                let inv = self.recip(fx.clone())?;
                let da = self.real.mul(a.clone(), inv.clone())?;
                let db = self.real.mul(b.clone(), inv)?;
                (Some(da), Some(db))
            }
            _ => {
                // pow(a, b) = a^b: d/da = b a^b / a, d/db = ln(a) a^b (a > 0)
                if self.real.sign(a)? != Ordering::Greater {
                    return Err(DualStop::NotDifferentiable);
                }
                let inv = self.recip(a.clone())?;
                let t = self.real.mul(b.clone(), fx.clone())?;
                let da = self.real.mul(t, inv)?;
                let ln = self.f(Func::Log, a)?;
                let db = self.real.mul(ln, fx.clone())?;
                (Some(da), Some(db))
            }
        })
    }
}

impl Evaluator for Dual<'_> {
    type V = DualValue;
    type Stop = DualStop;

    fn input(&mut self, i: usize) -> DualValue {
        let n = self.real.x.len();
        let mut d = vec![zero(); n];
        d[i] = XV::Exact(Rational::ONE);
        DualValue {
            x: self.real.input(i),
            d,
        }
    }
    fn constant(&mut self, q: &Rational) -> Result<DualValue, DualStop> {
        Ok(DualValue {
            x: self.real.constant(q)?,
            d: vec![zero(); self.real.x.len()],
        })
    }
    fn neg(&mut self, a: DualValue) -> Result<DualValue, DualStop> {
        let d =
            a.d.into_iter()
                .map(|v| self.real.neg(v))
                .collect::<Result<_, _>>()?;
        Ok(DualValue {
            x: self.real.neg(a.x)?,
            d,
        })
    }
    fn add(&mut self, a: DualValue, b: DualValue) -> Result<DualValue, DualStop> {
        Ok(DualValue {
            x: self.real.add(a.x, b.x)?,
            d: self.sum(a.d, b.d, false)?,
        })
    }
    fn sub(&mut self, a: DualValue, b: DualValue) -> Result<DualValue, DualStop> {
        Ok(DualValue {
            x: self.real.sub(a.x, b.x)?,
            d: self.sum(a.d, b.d, true)?,
        })
    }
    fn mul(&mut self, a: DualValue, b: DualValue) -> Result<DualValue, DualStop> {
        let left = self.scale(&b.x, &a.d)?;
        let right = self.scale(&a.x, &b.d)?;
        Ok(DualValue {
            x: self.real.mul(a.x, b.x)?,
            d: self.sum(left, right, false)?,
        })
    }
    fn div(&mut self, a: DualValue, b: DualValue) -> Result<DualValue, DualStop> {
        // (a/b)' = (a' - (a/b) b') / b.
        let x = self.real.div(a.x, b.x.clone())?;
        let xb = self.scale(&x, &b.d)?;
        let num = self.sum(a.d, xb, true)?;
        let d = num
            .into_iter()
            .map(|v| {
                if is_zero(&v) {
                    Ok(v)
                } else {
                    self.real.div(v, b.x.clone())
                }
            })
            .collect::<Result<_, _>>()?;
        Ok(DualValue { x, d })
    }
    fn sqrt(&mut self, a: DualValue) -> Result<DualValue, DualStop> {
        let x = self.real.sqrt(a.x)?;
        if a.d.iter().all(is_zero) {
            return Ok(DualValue { x, d: a.d });
        }
        if self.real.sign(&x)? == Ordering::Equal {
            return Err(DualStop::NotDifferentiable);
        }
        // sqrt(a)' = a' / (2 sqrt(a)).
        let two_x = self.real.add(x.clone(), x.clone())?;
        let d =
            a.d.into_iter()
                .map(|v| {
                    if is_zero(&v) {
                        Ok(v)
                    } else {
                        self.real.div(v, two_x.clone())
                    }
                })
                .collect::<Result<_, _>>()?;
        Ok(DualValue { x, d })
    }
    fn abs(&mut self, a: DualValue) -> Result<DualValue, DualStop> {
        match self.real.sign(&a.x)? {
            Ordering::Less => self.neg(a),
            Ordering::Greater => Ok(a),
            Ordering::Equal if a.d.iter().all(is_zero) => Ok(a),
            Ordering::Equal => Err(DualStop::NotDifferentiable),
        }
    }
    fn fma(&mut self, a: DualValue, b: DualValue, c: DualValue) -> Result<DualValue, DualStop> {
        let ab = self.mul(a, b)?;
        self.add(ab, c)
    }
    fn min(&mut self, a: DualValue, b: DualValue) -> Result<DualValue, DualStop> {
        let less = self.real.compare(CmpOp::Lt, &a.x, &b.x)?;
        let greater = self.real.compare(CmpOp::Gt, &a.x, &b.x)?;
        match (less, greater) {
            (true, _) => Ok(a),
            (_, true) => Ok(b),
            _ => self.tie(a, b),
        }
    }
    fn max(&mut self, a: DualValue, b: DualValue) -> Result<DualValue, DualStop> {
        let less = self.real.compare(CmpOp::Lt, &a.x, &b.x)?;
        let greater = self.real.compare(CmpOp::Gt, &a.x, &b.x)?;
        match (less, greater) {
            (_, true) => Ok(a),
            (true, _) => Ok(b),
            _ => self.tie(a, b),
        }
    }
    fn pow(&mut self, a: DualValue, n: i32, style: PowStyle) -> Result<DualValue, DualStop> {
        if n == 0 {
            return self.constant(&Rational::ONE);
        }
        let x = self.real.pow(a.x.clone(), n, style)?;
        // (a^n)' = n a^(n-1) a'.
        let lower = self.real.pow(a.x, n - 1, style)?;
        let k = self
            .real
            .mul(XV::Exact(Rational::from(i64::from(n))), lower)?;
        let d = self.scale(&k, &a.d)?;
        Ok(DualValue { x, d })
    }
    fn call(
        &mut self,
        f: Func,
        a: Option<DualValue>,
        b: Option<DualValue>,
    ) -> Result<DualValue, DualStop> {
        let n = self.real.x.len();
        let x = self.real.call(
            f,
            a.as_ref().map(|v| v.x.clone()),
            b.as_ref().map(|v| v.x.clone()),
        )?;
        let constant = |v: &Option<DualValue>| v.as_ref().is_none_or(|v| v.d.iter().all(is_zero));
        if constant(&a) && constant(&b) {
            return Ok(DualValue {
                x,
                d: vec![zero(); n],
            });
        }
        // the partial derivatives of f with respect to its arguments, at the sample
        let (da, db) = self.partials(f, a.as_ref().map(|v| &v.x), b.as_ref().map(|v| &v.x), &x)?;
        let mut d = vec![zero(); n];
        if let (Some(a), Some(k)) = (&a, &da) {
            let t = self.scale(k, &a.d)?;
            d = self.sum(d, t, false)?;
        }
        if let (Some(b), Some(k)) = (&b, &db) {
            let t = self.scale(k, &b.d)?;
            d = self.sum(d, t, false)?;
        }
        Ok(DualValue { x, d })
    }
    fn compare(&mut self, op: CmpOp, a: &DualValue, b: &DualValue) -> Result<bool, DualStop> {
        Ok(self.real.compare(op, &a.x, &b.x)?)
    }
    fn iterate(&mut self) -> Result<(), DualStop> {
        Ok(self.real.iterate()?)
    }
    fn carry(&mut self, v: DualValue) -> Result<DualValue, DualStop> {
        let d =
            v.d.into_iter()
                .map(|q| self.real.carry(q))
                .collect::<Result<_, _>>()?;
        Ok(DualValue {
            x: self.real.carry(v.x)?,
            d,
        })
    }
}

impl Dual<'_> {
    /// `min`/`max` of equal values: differentiable only when both gradients agree.
    fn tie(&mut self, a: DualValue, b: DualValue) -> Result<DualValue, DualStop> {
        for (p, q) in a.d.iter().zip(&b.d) {
            if self.real.compare(CmpOp::Ne, p, q)? {
                return Err(DualStop::NotDifferentiable);
            }
        }
        Ok(a)
    }

    /// `sum_i |x_i d_i| / |f|` as a double, or a refinement when the enclosure is too wide.
    fn condition(&mut self, f: &DualValue) -> Result<Conditioning, Halt> {
        match self.real.sign(&f.x)? {
            Ordering::Equal => return Ok(Conditioning::ZeroValue),
            Ordering::Less | Ordering::Greater => {}
        }
        let mut num = zero();
        for (i, di) in f.d.iter().enumerate() {
            let xi = XV::Exact(self.real.x[i].clone());
            let term = self.times(&xi, di)?;
            if !is_zero(&term) {
                let t = self.real.abs(term)?;
                num = self.real.add(num, t)?;
            }
        }
        if is_zero(&num) {
            return Ok(Conditioning::Number(0.0));
        }
        let fx = self.real.abs(f.x.clone())?;
        match self.real.div(num, fx)? {
            XV::Exact(q) => Ok(Conditioning::Number(q.to_f64())),
            XV::Approx(iv, _) if iv.narrow(6) => Ok(Conditioning::Number(
                crate::to_f64::rational_to_f64(&iv.midpoint()),
            )),
            XV::Approx(..) => Err(Halt::Refine { ambiguous: false }),
        }
    }
}

/// Runs `pass` at working precision `START_PRECISION`, `2x`, ... up to `MAX_PRECISION`, while
/// it asks for refinement.
fn refine<T>(mut pass: impl FnMut(u64) -> Result<T, Halt>) -> Result<T, ExactStop> {
    let mut p = START_PRECISION;
    loop {
        match pass(p) {
            Ok(v) => return Ok(v),
            Err(Halt::Outside) => return Err(ExactStop::OutsideDomain),
            Err(Halt::TooLarge) => return Err(ExactStop::TooLarge),
            Err(Halt::LoopLimit) => return Err(ExactStop::LoopLimit),
            Err(Halt::Refine { .. }) if p >= MAX_PRECISION => return Err(ExactStop::Undecided),
            Err(Halt::Refine { .. }) => p *= 2,
        }
    }
}

impl Program {
    /// Every rounding operation of the outputs at the exact inputs `x` (one per input), in
    /// evaluation order: the operation in f64 on the exact values of its operands rounded to
    /// doubles, and the exact value of its subexpression rounded (see the module documentation
    /// of `program::explain`). Negation, `fabs`, `fmin` and `fmax` never round and are not
    /// listed. The precondition is not evaluated: `x` is a sample already inside the domain.
    ///
    /// # Errors
    /// [`ExactStop`] as [`Program::eval_exact`]; [`ExactStop::Undecided`] also when a
    /// subexpression's rounding to a double cannot be decided up to the precision cap.
    ///
    /// # Panics
    /// When `x.len()` is not [`Program::arity`].
    pub fn local_errors(&self, x: &[Rational]) -> Result<Vec<LocalError>, ExactStop> {
        assert_eq!(x.len(), self.inputs.len(), "Program::local_errors: arity");
        refine(|p| {
            let mut d = Local {
                real: Real::new(x, p),
                format: self.precision,
                names: &self.inputs,
                ops: Vec::new(),
            };
            let mut slots = vec![
                Tracked {
                    x: zero(),
                    text: "".into(),
                    prec: 4,
                };
                self.slots
            ];
            for node in &self.outputs {
                eval_node(&mut d, node, &mut slots)?;
            }
            Ok(d.ops)
        })
    }

    /// The relative condition number of each output at the exact inputs `x`:
    /// `sum_i |x_i * df/dx_i / f|`, the derivatives exact (forward-mode dual numbers over the
    /// exact reals). The precondition is not evaluated.
    ///
    /// # Errors
    /// [`ExactStop`] as [`Program::eval_exact`].
    ///
    /// # Panics
    /// When `x.len()` is not [`Program::arity`].
    pub fn conditioning(&self, x: &[Rational]) -> Result<Vec<Conditioning>, ExactStop> {
        assert_eq!(x.len(), self.inputs.len(), "Program::conditioning: arity");
        refine(|p| {
            let mut d = Dual {
                real: Real::new(x, p),
            };
            let mut slots = vec![
                DualValue {
                    x: zero(),
                    d: vec![zero(); x.len()],
                };
                self.slots
            ];
            let mut out = Vec::with_capacity(self.outputs.len());
            for node in &self.outputs {
                match eval_node(&mut d, node, &mut slots) {
                    Ok(f) => out.push(d.condition(&f)?),
                    Err(DualStop::NotDifferentiable) => out.push(Conditioning::NotDifferentiable),
                    Err(DualStop::Halt(h)) => return Err(h),
                }
            }
            Ok(out)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(v: f64) -> Rational {
        Rational::from(num_rational::BigRational::from_float(v).expect("finite"))
    }

    fn bits(a: f64, b: f64) -> f64 {
        // Ordinal distance of two positive doubles, as bits.
        ((a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs() as f64 + 1.0).log2()
    }

    #[test]
    fn the_subtraction_loses_the_bits_of_sqrt_x_plus_1_minus_sqrt_x() {
        let p = Program::parse("sqrt(x + 1) - sqrt(x)", None).unwrap();
        let ops = p.local_errors(&[q(1e15)]).unwrap();
        let names: Vec<(&str, &str)> = ops.iter().map(|o| (o.operation, &*o.at)).collect();
        assert_eq!(
            names,
            [
                ("addition", "x + 1"),
                ("square root", "sqrt(x + 1)"),
                ("square root", "sqrt(x)"),
                ("subtraction", "sqrt(x + 1) - sqrt(x)"),
            ]
        );
        let sub = &ops[3];
        assert!(bits(sub.float, sub.exact) > 20.0, "{sub:?}");
        for o in &ops[..3] {
            assert!(bits(o.float, o.exact) <= 1.0, "{o:?}");
        }
        // Well-conditioned: cond = x / (2 sqrt(x (x + 1))), about 1/2.
        let c = p.conditioning(&[q(1e15)]).unwrap();
        let Conditioning::Number(c) = c[0] else {
            panic!("{c:?}")
        };
        assert!((c - 0.5).abs() < 1e-3, "{c}");
    }

    #[test]
    fn condition_numbers_of_rational_functions_are_exact() {
        // x - y at (1, 1 - 2^-20): cond = (|x| + |y|) / |x - y| = (2 - 2^-20) 2^20.
        let p = Program::parse("x - y", None).unwrap();
        let y = 1.0 - 2f64.powi(-20);
        let c = p.conditioning(&[q(1.0), q(y)]).unwrap();
        assert_eq!(c, [Conditioning::Number((1.0 + y) * 2f64.powi(20))]);
        // x * y / z: cond 3 anywhere.
        let p = Program::parse("x * y / z", None).unwrap();
        let c = p.conditioning(&[q(3.5), q(-2.0), q(0.1)]).unwrap();
        assert_eq!(c, [Conditioning::Number(3.0)]);
        // x^3: cond 3; x - x is zero.
        let p = Program::parse("x^3", None).unwrap();
        assert_eq!(
            p.conditioning(&[q(7.0)]).unwrap(),
            [Conditioning::Number(3.0)]
        );
        let p = Program::parse("x - x", None).unwrap();
        assert_eq!(
            p.conditioning(&[q(7.0)]).unwrap(),
            [Conditioning::ZeroValue]
        );
        // sqrt at 0 has no derivative.
        let p = Program::parse("sqrt(x)", None).unwrap();
        assert_eq!(
            p.conditioning(&[q(0.0)]).unwrap(),
            [Conditioning::NotDifferentiable]
        );
    }

    #[test]
    fn functions_have_their_textbook_condition_numbers_and_local_errors() {
        let close = |c: &[Conditioning], want: f64| match c {
            [Conditioning::Number(v)] => (v - want).abs() <= 1e-6 * want,
            _ => false,
        };
        // exp: cond |x|; log: cond 1/|log x|; sin at pi/4-ish: |x cos x / sin x|.
        let p = Program::parse("exp(x)", None).unwrap();
        assert!(close(&p.conditioning(&[q(3.0)]).unwrap(), 3.0));
        let p = Program::parse("log(x)", None).unwrap();
        let c = p.conditioning(&[q(2.0)]).unwrap();
        assert!(close(&c, 1.0 / 2f64.ln()), "{c:?}");
        let p = Program::parse("sin(x)", None).unwrap();
        let x = 0.75f64;
        let c = p.conditioning(&[q(x)]).unwrap();
        assert!(close(&c, x * x.cos() / x.sin()), "{c:?}");
        // pow(x, y) at (2, 3): d/dx = 12, d/dy = 8 ln 2, f = 8: cond = 3 + 3 ln 2
        let p = Program::parse("pow(x, y)", None).unwrap();
        let c = p.conditioning(&[q(2.0), q(3.0)]).unwrap();
        assert!(close(&c, 3.0 + 3.0 * 2f64.ln()), "{c:?}");
        // asin at 1 has no derivative
        let p = Program::parse("asin(x)", None).unwrap();
        assert_eq!(
            p.conditioning(&[q(1.0)]).unwrap(),
            [Conditioning::NotDifferentiable]
        );
        // 1 - cos(x) at small x: the subtraction loses the bits, cos itself is accurate
        let p = Program::parse("1 - cos(x)", None).unwrap();
        let ops = p.local_errors(&[q(1e-5)]).unwrap();
        let op = |name: &str| ops.iter().find(|o| o.operation == name).expect(name);
        assert_eq!(op("cos").float, op("cos").exact, "{ops:?}");
        let sub = op("subtraction");
        assert!(
            ((sub.float - sub.exact) / sub.exact).abs() > 1e-8,
            "{ops:?}"
        );
    }

    #[test]
    fn texts_keep_the_needed_parentheses() {
        let p = Program::parse("(a - b) * (c + d) / h - (f - g)^2", None).unwrap();
        let x: Vec<Rational> = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0].map(q).to_vec();
        let ops = p.local_errors(&x).unwrap();
        let last = ops.last().unwrap();
        assert_eq!(last.at, "(a - b) * (c + d) / h - (f - g)^2");
        assert!(ops.iter().all(|o| bits(o.float, o.exact) <= 1.0), "{ops:?}");
    }
}
