//! Certified enclosures of the elementary functions ([`Func`]) for the exact side (`real`):
//! exact values where the value is rational ([`special`]: `sin(0) = 0`, `log(1) = 0`,
//! `pow(4, 1/2) = 2`, `cbrt(27) = 3`, ...) and otherwise a rigorous dyadic enclosure
//! ([`enclose`]) of the value at an enclosure of the argument, which `real` refines (doubling the
//! working precision) until the correct rounding is decided: Ziv's strategy.
//!
//! # How an enclosure is certified
//! Every step is an operation of `interval` (endpoints rounded outward), so an enclosure of
//! the argument gives an enclosure of each intermediate; the truncation of a series is covered
//! by widening the sum by a proven bound of its tail. The kernels:
//! * `ln 2 = 2 atanh(1/3)` by the odd series below, and pi from [`crate::pi::enclosure`]
//!   (Machin's `pi = 16 atan(1/5) - 4 atan(1/239)`); the odd series
//!   `atanh z = sum z^(2k+1)/(2k+1)` and `atan z = sum (-1)^k z^(2k+1)/(2k+1)`: for `|z| <= 1/2`
//!   the tail after the terms up to `z^(2k-1)` is at most `|z|^(2k+1) / (1 - z^2) <=
//!   2 |z|^(2k+1)`. Both constants are cached at the largest precision computed so far.
//! * `exp x = 2^k exp(r)` with `k` the integer nearest `x / ln 2` and `r = x - k ln 2`; `exp r`
//!   is `(exp(r / 2^10))^(2^10)` and `exp(s)` for `|s| < 2^-9` is its Taylor sum, whose tail after
//!   the term `s^j / j!` is at most that term.
//! * `log x = e ln 2 + 2 atanh((m - 1)/(m + 1))` with `x = 2^e m`, `m` in `[1/2, 1)` (and
//!   `e = 0` for `x` in `[1/2, 2)`, so that values near 1 keep their relative accuracy).
//! * `sin`, `cos`: `x = k pi/2 + r` with `k` the nearest integer (pi at the precision plus the
//!   bits of `x`), then the Taylor sums of `sin r` and `cos r` (`|r| <= 1`: alternating, the tail
//!   at most the first omitted term) and the quadrant `k mod 4`.
//! * `atan x`: halved by `atan x = 2 atan(x / (1 + sqrt(1 + x^2)))` until `|x| < 2^-4`, then the
//!   series; `asin x = 2 atan(x / (1 + sqrt(1 - x^2)))`, `acos x = pi/2 - asin x`.
//! * the rest by identities: `tan = sin / cos`, `sinh`, `cosh`, `tanh` from `exp`, `asinh`,
//!   `acosh`, `atanh` from `log`, `pow(x, y) = exp(y log x)` for `x > 0`, `hypot` as
//!   `sqrt(x^2 + y^2)`, `cbrt` by the integer cube root of the mantissa (floor for the lower
//!   end, ceiling for the upper).
//!
//! An argument enclosure too wide for a kernel's reduction, or one straddling the boundary of
//! the function's domain, answers [`TStop::Ambiguous`] (refine); one lying entirely outside the
//! domain answers [`TStop::Outside`].
//!
//! # Why hand-written
//! No crate on num-bigint gives certified, correctly rounded enclosures of the elementary
//! functions: the arbitrary-precision float crates either bind MPFR/Arb (a C library) or round
//! their results without a proven error bound. The kernels above are a few textbook series on
//! top of the interval arithmetic this module's parent already has.
use super::interval::{Dir, Dy, Iv};
use super::Func;
use crate::expr::Coefficient;
use crate::rational::Rational;
use exactcheck_core::limits;
use exactcheck_core::{Ring, Sign};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cell::RefCell;
use std::cmp::Ordering;

/// Why an enclosure or an exact value cannot be given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum TStop {
    /// Exactly outside the function's domain.
    Outside,
    /// The argument's enclosure is too wide or straddles a domain boundary: refine.
    Ambiguous,
    /// The value would exceed the `constant-bits` limit.
    TooLarge,
}

// ------------------------------------------------------------------ exact values

/// The exact value of `f` at rational arguments when it is rational (`None` when it is
/// irrational, or not known to be rational here); `Err` when the arguments are outside the
/// domain or the value is too large.
pub(crate) fn special(
    f: Func,
    a: Option<&Rational>,
    b: Option<&Rational>,
) -> Option<Result<Rational, TStop>> {
    let zero = Rational::ZERO;
    let one = Rational::ONE;
    let x = a?;
    let out = |q: Rational| Some(Ok(q));
    let outside = Some(Err(TStop::Outside));
    let abs_le_one = || x.abs_cmp_one() != Ordering::Greater;
    match f {
        Func::Pi | Func::E => None,
        Func::Exp | Func::Cos | Func::Cosh if x.is_zero() => out(one),
        Func::Expm1
        | Func::Sin
        | Func::Tan
        | Func::Atan
        | Func::Sinh
        | Func::Tanh
        | Func::Asinh
            if x.is_zero() =>
        {
            out(zero)
        }
        Func::Exp2 if x.is_integer() => {
            let n = x.numer().to_i64()?;
            if n.unsigned_abs() > limits::CONSTANT_BITS.get() {
                return Some(Err(TStop::TooLarge));
            }
            let p = BigInt::one() << n.unsigned_abs();
            out(if n >= 0 {
                Rational::from(p)
            } else {
                Rational::from(BigRational::new(BigInt::one(), p))
            })
        }
        Func::Log | Func::Log2 | Func::Log10 => {
            if x.signum() != Sign::Positive {
                return outside;
            }
            let base = match f {
                Func::Log => return (x == &one).then_some(Ok(zero)),
                Func::Log2 => 2u32,
                _ => 10,
            };
            exact_log(x, base).map(Ok)
        }
        Func::Log1p => {
            if x <= &-one {
                outside
            } else if x.is_zero() {
                out(zero)
            } else {
                None
            }
        }
        Func::Asin | Func::Acos => {
            if !abs_le_one() {
                outside
            } else if (f == Func::Asin && x.is_zero()) || (f == Func::Acos && x == &one) {
                out(zero)
            } else {
                None
            }
        }
        Func::Acosh => {
            if x < &one {
                outside
            } else if x == &one {
                out(zero)
            } else {
                None
            }
        }
        Func::Atanh => {
            if x.abs_cmp_one() != Ordering::Less {
                outside
            } else if x.is_zero() {
                out(zero)
            } else {
                None
            }
        }
        Func::Atan2 => {
            let xx = b?;
            match (x.signum(), xx.signum()) {
                (Sign::Zero, Sign::Zero) => outside,
                (Sign::Zero, Sign::Positive) => out(zero),
                _ => None,
            }
        }
        Func::Pow => exact_pow(x, b?),
        Func::Hypot => {
            let y = b?;
            let s = x * x + y * y;
            if s.bits() > limits::CONSTANT_BITS.get() {
                return Some(Err(TStop::TooLarge));
            }
            s.try_sqrt().map(Ok)
        }
        Func::Cbrt => exact_root(x, 3).map(Ok),
        _ => None,
    }
}

trait AbsCmpOne {
    fn abs_cmp_one(&self) -> Ordering;
}

impl AbsCmpOne for Rational {
    /// `|self|` compared with 1.
    fn abs_cmp_one(&self) -> Ordering {
        let n = self.numer();
        n.magnitude().cmp(self.denom().magnitude())
    }
}

/// `k` when `x = base^k` for an integer `k`.
fn exact_log(x: &Rational, base: u32) -> Option<Rational> {
    let (n, d) = (x.numer(), x.denom());
    let (big, negate) = if n >= d { (n, false) } else { (d, true) };
    let small = if negate { x.numer() } else { x.denom() };
    if !small.is_one() {
        return None;
    }
    let mut m = big;
    let mut k: i64 = 0;
    let b = BigInt::from(base);
    while !m.is_one() {
        let (q, r) = m.div_rem(&b);
        if !r.is_zero() {
            return None;
        }
        m = q;
        k += 1;
    }
    Some(Rational::from_integer(if negate { -k } else { k }))
}

/// The real `d`-th root of `x` (`d >= 2`) when it is rational.
fn exact_root(x: &Rational, d: u32) -> Option<Rational> {
    let neg = x.signum() == Sign::Negative;
    if neg && d % 2 == 0 {
        return None;
    }
    let root = |v: BigInt| -> Option<BigInt> {
        let v = v.abs();
        let r = v.nth_root(d);
        (num_traits::pow(r.clone(), d as usize) == v).then_some(r)
    };
    let n = root(x.numer())?;
    let den = root(x.denom())?;
    let q = Rational::from(BigRational::new(if neg { -n } else { n }, den));
    Some(q)
}

/// `x^y` when rational; `Err(Outside)` for `0^y` with `y < 0` and for a negative `x` with a
/// non-integer `y` (C's `pow` is NaN there).
fn exact_pow(x: &Rational, y: &Rational) -> Option<Result<Rational, TStop>> {
    if y.is_zero() || x == &Rational::ONE {
        return Some(Ok(Rational::ONE));
    }
    match x.signum() {
        Sign::Zero => {
            return Some(if y.signum() == Sign::Positive {
                Ok(Rational::ZERO)
            } else {
                Err(TStop::Outside)
            })
        }
        Sign::Negative if !y.is_integer() => return Some(Err(TStop::Outside)),
        _ => {}
    }
    let base = if y.is_integer() {
        x.clone()
    } else {
        let d = y.denom().to_u32().filter(|&d| d <= 64)?;
        exact_root(x, d)?
    };
    let n = y.numer();
    let n = match n.to_i32() {
        Some(n)
            if base.size_bits().saturating_mul(u64::from(n.unsigned_abs()))
                <= limits::CONSTANT_BITS.get() =>
        {
            n
        }
        _ if base.is_integer() && base.numer().magnitude().is_one() => {
            // (+-1)^n.
            return Some(Ok(if base.signum() == Sign::Negative && n.is_odd() {
                -Rational::ONE
            } else {
                Rational::ONE
            }));
        }
        _ => return Some(Err(TStop::TooLarge)),
    };
    Some(base.powi(n).map_err(|_| TStop::Outside))
}

// ------------------------------------------------------------------ interval helpers

fn int(n: i64) -> Iv {
    let d = Dy {
        m: BigInt::from(n),
        e: 0,
    };
    Iv {
        lo: d.clone(),
        hi: d,
    }
}

fn big(n: BigInt) -> Iv {
    let d = Dy { m: n, e: 0 };
    Iv {
        lo: d.clone(),
        hi: d,
    }
}

/// `a * 2^k`, exact.
fn shift(a: &Iv, k: i64) -> Iv {
    Iv {
        lo: Dy {
            m: a.lo.m.clone(),
            e: a.lo.e + k,
        },
        hi: Dy {
            m: a.hi.m.clone(),
            e: a.hi.e + k,
        },
    }
}

/// An upper bound of `|v|` over the enclosure.
fn mag(a: &Iv) -> Dy {
    let l = a.lo.m.abs();
    let h = a.hi.m.abs();
    let (lo, hi) = (Dy { m: l, e: a.lo.e }, Dy { m: h, e: a.hi.e });
    if Dy::cmp(&lo, &hi) == Ordering::Greater {
        lo
    } else {
        hi
    }
}

/// `2 d`.
fn twice(d: &Dy) -> Dy {
    Dy {
        m: d.m.clone(),
        e: d.e + 1,
    }
}

/// `a` widened by `t >= 0` on both sides.
fn widen(a: &Iv, t: &Dy, p: u64) -> Iv {
    Iv {
        lo: Dy::add(&a.lo, &t.neg(), p, Dir::Down),
        hi: Dy::add(&a.hi, t, p, Dir::Up),
    }
}

/// Whether `|v| < 2^k` for every `v` of the enclosure (known from an upper bound).
fn below(a: &Iv, k: i64) -> bool {
    let m = mag(a);
    m.is_zero() || m.top() <= k
}

/// `a^2`, its lower end at least zero.
fn square(a: &Iv, p: u64) -> Iv {
    let s = Iv::mul(a, a, p);
    if s.lo.sign() == Ordering::Less {
        Iv {
            lo: Dy::zero(),
            hi: s.hi,
        }
    } else {
        s
    }
}

fn add(a: &Iv, b: &Iv, p: u64) -> Iv {
    Iv::add(a, b, p)
}
fn sub(a: &Iv, b: &Iv, p: u64) -> Iv {
    Iv::sub(a, b, p)
}
fn mul(a: &Iv, b: &Iv, p: u64) -> Iv {
    Iv::mul(a, b, p)
}

/// `a / b`, or `Ambiguous` when `b` straddles zero.
fn div(a: &Iv, b: &Iv, p: u64) -> Result<Iv, TStop> {
    match b.sign() {
        Some(Ordering::Less | Ordering::Greater) => Ok(Iv::div(a, b, p)),
        _ => Err(TStop::Ambiguous),
    }
}

/// `sqrt(max(a, 0))`: for an argument known to be non-negative whose enclosure may reach below
/// zero by rounding.
fn sqrt_clamped(a: &Iv, p: u64) -> Iv {
    let clamp = |d: &Dy| {
        if d.sign() == Ordering::Less {
            Dy::zero()
        } else {
            d.clone()
        }
    };
    Iv::sqrt(
        &Iv {
            lo: clamp(&a.lo),
            hi: clamp(&a.hi),
        },
        p,
    )
}

/// An approximation of a dyadic number as a double (not rounded with care: used to choose
/// reduction multiples, never as a value).
fn rough_f64(d: &Dy) -> f64 {
    let bits = d.m.bits();
    let s = bits.saturating_sub(60);
    let m = (&d.m >> s).to_f64().unwrap_or(0.0);
    let e = d.e + s as i64;
    m * 2f64.powi(e.clamp(-2000, 2000) as i32)
}

/// The integer nearest to the lower end of `a` (ties up).
fn nearest_integer(a: &Iv) -> BigInt {
    let d = &a.lo;
    if d.e >= 0 {
        return &d.m << d.e as u64;
    }
    let s = (-d.e) as u64;
    (&d.m + (BigInt::one() << (s - 1))) >> s
}

// ------------------------------------------------------------------ series and constants

/// `sum_k (+-1)^k z^(2k+1) / (2k+1)` (alternating: `atan`; else `atanh`) for `|z| <= 1/2`,
/// with the tail bound `2 |z|^(2k+1)`.
fn odd_series(z: &Iv, alternating: bool, p: u64) -> Iv {
    debug_assert!(below(z, -1) || mag(z).top() <= 0);
    let z2 = mul(z, z, p);
    let mut pw = z.clone();
    let mut sum = int(0);
    let mut k: i64 = 0;
    loop {
        let term = Iv::div(&pw, &int(2 * k + 1), p);
        sum = if alternating && k % 2 == 1 {
            sub(&sum, &term, p)
        } else {
            add(&sum, &term, p)
        };
        pw = mul(&pw, &z2, p);
        k += 1;
        let m = mag(&pw);
        if m.is_zero() || m.top() < -(p as i64) - 2 {
            return widen(&sum, &twice(&m), p);
        }
    }
}

thread_local! {
    static LN2: RefCell<Option<(u64, Iv)>> = const { RefCell::new(None) };
    static PI: RefCell<Option<(u64, Iv)>> = const { RefCell::new(None) };
}

fn cached(
    cell: &'static std::thread::LocalKey<RefCell<Option<(u64, Iv)>>>,
    p: u64,
    f: impl Fn(u64) -> Iv,
) -> Iv {
    if let Some(iv) = cell.with(|c| {
        c.borrow()
            .as_ref()
            .filter(|(q, _)| *q >= p)
            .map(|(_, iv)| iv.clone())
    }) {
        return iv;
    }
    let iv = f(p);
    cell.with(|c| *c.borrow_mut() = Some((p, iv.clone())));
    iv
}

/// An enclosure of `ln 2` at about `p` bits.
fn ln2(p: u64) -> Iv {
    cached(&LN2, p, |p| {
        let w = p + 8;
        let third = Iv::div(&int(1), &int(3), w);
        shift(&odd_series(&third, false, w), 1)
    })
}

/// An enclosure of pi at about `p` bits.
pub(crate) fn pi(p: u64) -> Iv {
    cached(&PI, p, |p| {
        // the crate's one certified enclosure of pi (Machin), rounded outward to `p + 8` bits
        let w = p + 8;
        let (lo, hi) = crate::pi::enclosure(u32::try_from(w).unwrap_or(u32::MAX));
        Iv {
            lo: Dy::from_rational(&lo, w, Dir::Down),
            hi: Dy::from_rational(&hi, w, Dir::Up),
        }
    })
}

// ------------------------------------------------------------------ kernels

/// `exp(x)`.
fn exp(x: &Iv, p: u64) -> Result<Iv, TStop> {
    if !below(x, 40) {
        return Err(TStop::TooLarge);
    }
    let w = p + 24;
    let k = (rough_f64(&x.lo) / std::f64::consts::LN_2).round() as i64;
    let r = sub(x, &mul(&int(k), &ln2(w + 48), w + 48), w);
    if !below(&r, 0) {
        return Err(TStop::Ambiguous);
    }
    const HALVINGS: i64 = 10;
    let s = shift(&r, -HALVINGS);
    let mut sum = int(1);
    let mut term = int(1);
    let mut j: i64 = 1;
    loop {
        term = Iv::div(&mul(&term, &s, w), &int(j), w);
        let m = mag(&term);
        if m.is_zero() || m.top() < -(w as i64) - 4 {
            // The tail from this term on is below |term| / (1 - |s|) < 2 |term|.
            sum = widen(&sum, &twice(&m), w);
            break;
        }
        sum = add(&sum, &term, w);
        j += 1;
    }
    for _ in 0..HALVINGS {
        sum = mul(&sum, &sum, w);
    }
    Ok(shift(&sum, k))
}

/// `log(x)` for `x > 0` (the caller checks the domain).
fn log(x: &Iv, p: u64) -> Result<Iv, TStop> {
    let w = p + 16;
    let top = x.lo.top();
    let e = if top == 0 || top == 1 { 0 } else { top };
    let m = shift(x, -e);
    let z = div(&sub(&m, &int(1), w), &add(&m, &int(1), w), w)?;
    if !below(&z, -1) {
        return Err(TStop::Ambiguous);
    }
    let l = shift(&odd_series(&z, false, w), 1);
    if e == 0 {
        return Ok(l);
    }
    let bits = 64 - e.unsigned_abs().leading_zeros() as u64;
    Ok(add(&l, &mul(&int(e), &ln2(w + bits), w + bits), w))
}

/// `(sin x, cos x)`.
fn sin_cos(x: &Iv, p: u64) -> Result<(Iv, Iv), TStop> {
    let top = mag(x).top().max(0) as u64;
    if top > limits::CONSTANT_BITS.get() {
        return Err(TStop::TooLarge);
    }
    let w = p + 16;
    let wx = w + top + 16;
    let half_pi = shift(&pi(wx), -1);
    let k = nearest_integer(&Iv::div(x, &half_pi, 64.max(top + 8)));
    let r = sub(x, &mul(&big(k.clone()), &half_pi, wx), wx);
    if !below(&r, 1) {
        return Err(TStop::Ambiguous);
    }
    let r2 = mul(&r, &r, w);
    // sin r = r - r^3/3! + ..., cos r = 1 - r^2/2! + ...
    let series = |first: Iv, start: i64| {
        let mut sum = first.clone();
        let mut term = first;
        let mut j = start;
        loop {
            term = Iv::div(&mul(&term, &r2, w), &int((j + 1) * (j + 2)), w).neg();
            j += 2;
            let m = mag(&term);
            if m.is_zero() || m.top() < -(w as i64) - 4 {
                // Alternating with decreasing terms from here on: the tail is at most this term.
                return widen(&sum, &twice(&m), w);
            }
            sum = add(&sum, &term, w);
        }
    };
    let s = series(r.clone(), 1);
    let c = series(int(1), 0);
    Ok(match k.mod_floor(&BigInt::from(4)).to_u8().unwrap_or(0) {
        0 => (s, c),
        1 => (c, s.neg()),
        2 => (s.neg(), c.neg()),
        _ => (c.neg(), s),
    })
}

/// `atan(x)`.
fn atan(x: &Iv, p: u64) -> Result<Iv, TStop> {
    let w = p + 16;
    let mut y = x.clone();
    let mut halvings = 0i64;
    while !below(&y, -4) {
        if halvings > 12 {
            return Err(TStop::Ambiguous);
        }
        let root = Iv::sqrt(&add(&int(1), &square(&y, w), w), w);
        y = Iv::div(&y, &add(&int(1), &root, w), w);
        halvings += 1;
    }
    Ok(shift(&odd_series(&y, true, w), halvings))
}

/// `asin(x)` for `|x| <= 1` (the caller checks the domain).
fn asin(x: &Iv, p: u64) -> Result<Iv, TStop> {
    let w = p + 16;
    let root = sqrt_clamped(&sub(&int(1), &square(x, w), w), w);
    let y = Iv::div(x, &add(&int(1), &root, w), w);
    Ok(shift(&atan(&y, w)?, 1))
}

/// The cube root, each end rounded outward.
fn cbrt(x: &Iv, p: u64) -> Iv {
    Iv {
        lo: cbrt_dy(&x.lo, p, Dir::Down),
        hi: cbrt_dy(&x.hi, p, Dir::Up),
    }
}

fn cbrt_dy(a: &Dy, p: u64, dir: Dir) -> Dy {
    if a.is_zero() {
        return Dy::zero();
    }
    if a.m.is_negative() {
        let flipped = match dir {
            Dir::Down => Dir::Up,
            Dir::Up => Dir::Down,
        };
        return cbrt_dy(&a.neg(), p, flipped).neg();
    }
    let mut s = (3 * p + 3).saturating_sub(a.m.bits());
    while (a.e - s as i64).rem_euclid(3) != 0 {
        s += 1;
    }
    let m = &a.m << s;
    let mut r = m.cbrt();
    if dir == Dir::Up && &r * &r * &r != m {
        r += 1u32;
    }
    Dy::rounded(r, (a.e - s as i64) / 3, p, dir)
}

/// Whether every point of `a` is `> c` (`Some(true)`), every point `<= c` (`Some(false)`), or
/// neither is known (`None`); with `strict == false` the first case is `>= c`.
fn above(a: &Iv, c: i64, strict: bool) -> Option<bool> {
    let c = Dy {
        m: BigInt::from(c),
        e: 0,
    };
    let lo = Dy::cmp(&a.lo, &c);
    let hi = Dy::cmp(&a.hi, &c);
    if lo == Ordering::Greater || (!strict && lo == Ordering::Equal) {
        Some(true)
    } else if hi == Ordering::Less || (strict && hi == Ordering::Equal) {
        Some(false)
    } else {
        None
    }
}

/// The domain check of an enclosure: `Ok` when every point is inside, `Outside` when none is.
fn domain(inside: Option<bool>) -> Result<(), TStop> {
    match inside {
        Some(true) => Ok(()),
        Some(false) => Err(TStop::Outside),
        None => Err(TStop::Ambiguous),
    }
}

/// An enclosure of `f` at the enclosures `a`, `b` of its arguments (as [`Func::arity`] says;
/// `Pow` with `b`'s value not an integer), at about `p` bits. The sign-dependent cases of
/// `atan2` and a `pow` of a non-positive base are decided by the caller, which passes only a
/// positive base to `Pow` and a non-zero `x` to `Atan2`.
pub(crate) fn enclose(f: Func, a: Option<&Iv>, b: Option<&Iv>, p: u64) -> Result<Iv, TStop> {
    let w = p + 16;
    let x = || a.expect("an argument");
    let y = || b.expect("a second argument");
    match f {
        Func::Pi => Ok(pi(p)),
        Func::E => exp(&int(1), p),
        Func::Exp => exp(x(), p),
        Func::Exp2 => exp(&mul(x(), &ln2(w + 8), w), p),
        Func::Expm1 => Ok(sub(&exp(x(), w)?, &int(1), w)),
        Func::Log | Func::Log2 | Func::Log10 => {
            domain(above(x(), 0, true))?;
            let l = log(x(), w)?;
            match f {
                Func::Log => Ok(l),
                Func::Log2 => div(&l, &ln2(w), w),
                _ => div(&l, &log(&int(10), w)?, w),
            }
        }
        Func::Log1p => {
            domain(above(x(), -1, true))?;
            log(&add(x(), &int(1), w), p)
        }
        Func::Sin => Ok(sin_cos(x(), p)?.0),
        Func::Cos => Ok(sin_cos(x(), p)?.1),
        Func::Tan => {
            let (s, c) = sin_cos(x(), w)?;
            div(&s, &c, w)
        }
        Func::Asin | Func::Acos => {
            domain(above(x(), -1, false))?;
            domain(above(x(), 1, true).map(|a| !a))?;
            let s = asin(x(), w)?;
            if f == Func::Asin {
                Ok(s)
            } else {
                Ok(sub(&shift(&pi(w), -1), &s, w))
            }
        }
        Func::Atan => atan(x(), p),
        Func::Atan2 => {
            // atan2(y, x) with y = a, x = b: atan(y / x), plus or minus pi for x < 0.
            let (yy, xx) = (x(), y());
            let q = atan(&div(yy, xx, w)?, w)?;
            match xx.sign() {
                Some(Ordering::Greater) => Ok(q),
                Some(Ordering::Less) => match yy.sign() {
                    Some(Ordering::Less) => Ok(sub(&q, &pi(w), w)),
                    Some(_) => Ok(add(&q, &pi(w), w)),
                    None => Err(TStop::Ambiguous),
                },
                _ => Err(TStop::Ambiguous),
            }
        }
        Func::Sinh | Func::Cosh => {
            let e = exp(x(), w)?;
            let inv = Iv::div(&int(1), &e, w);
            let s = if f == Func::Sinh {
                sub(&e, &inv, w)
            } else {
                add(&e, &inv, w)
            };
            Ok(shift(&s, -1))
        }
        Func::Tanh => {
            let e = exp(&shift(x(), 1), w)?;
            div(&sub(&e, &int(1), w), &add(&e, &int(1), w), w)
        }
        Func::Asinh => {
            // Odd: computed on |x| when the sign is known, which avoids a cancellation.
            let (v, negate) = match x().sign() {
                Some(Ordering::Less) => (x().neg(), true),
                _ => (x().clone(), false),
            };
            let root = Iv::sqrt(&add(&square(&v, w), &int(1), w), w);
            let l = log(&add(&v, &root, w), w)?;
            Ok(if negate { l.neg() } else { l })
        }
        Func::Acosh => {
            domain(above(x(), 1, false))?;
            let root = sqrt_clamped(&sub(&square(x(), w), &int(1), w), w);
            log(&add(x(), &root, w), w)
        }
        Func::Atanh => {
            domain(above(x(), -1, true))?;
            domain(above(x(), 1, false).map(|a| !a))?;
            let q = div(&add(&int(1), x(), w), &sub(&int(1), x(), w), w)?;
            Ok(shift(&log(&q, w)?, -1))
        }
        Func::Pow => {
            domain(above(x(), 0, true))?;
            exp(&mul(y(), &log(x(), w + 16)?, w + 16), w)
        }
        Func::Hypot => {
            let s = add(&square(x(), w), &square(y(), w), w);
            Ok(sqrt_clamped(&s, w))
        }
        Func::Cbrt => Ok(cbrt(x(), w)),
    }
}
