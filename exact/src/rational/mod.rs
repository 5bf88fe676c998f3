//! `Rational`: the fast exact rational field.
//!
//! # Representation
//! A rational is kept in canonical form, always: denominator positive, numerator and denominator
//! coprime, zero as `0/1`. Two tiers hold it:
//!
//! * **inline** — numerator and denominator as `i128` (both of magnitude below `2^127`), no heap;
//! * **big** — numerator `BigInt`, denominator `BigUint` (num-bigint), used only when a value does
//!   not fit inline. Results that fit inline again are moved back ("demoted"), so the tier is
//!   itself canonical and `==` compares representations.
//!
//! # Algorithms
//! Addition and multiplication follow Henrici and Knuth (TAOCP vol. 2, 4.5.1), as GMP's `mpq`
//! does: instead of multiplying out and reducing by one big gcd, they take gcds of the
//! denominators (addition) or of crossed numerator/denominator pairs (multiplication) and divide
//! them out first, so every gcd is taken of operands at most as large as the inputs, the common
//! cases (an integer operand, equal denominators, coprime denominators) take no gcd at all, and
//! the result needs no final reduction. The gcds themselves come from [`crate::gcd`]: word-size
//! binary gcds inline, and for big operands a division step then Lehmer's algorithm, never
//! num-integer's bit-by-bit binary gcd. Inline operands whose four parts all fit an `i64` (the
//! usual polynomial coefficient) take the kernels of `word`, which need no overflow checks.
//!
//! Everything converts to and from num-rational's `BigRational` ([`Rational::to_big_rational`],
//! `From<BigRational>`), which stays the public big-number base. The conversions, printing and
//! parsing are in `convert`.

use crate::bigint;
use crate::gcd::{gcd_biguint, gcd_u128, gcd_u64};
use exactcheck_core::{Field, OrderedField, Ring, Sign, ZeroDivisor};
use num_bigint::{BigInt, BigUint, Sign as BigSign};
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::borrow::Cow;
use std::cmp::Ordering;

mod convert;
#[cfg(test)]
mod tests;
mod word;

/// An exact rational number, always in canonical form (see the module documentation).
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Rational(Repr);

#[derive(Clone, PartialEq, Eq, Hash)]
enum Repr {
    /// `num / den` with `0 < den <= i128::MAX`, `|num| <= i128::MAX`, `gcd(|num|, den) = 1`.
    Small(i128, i128),
    /// `num / den`, coprime, `den > 0`, and not representable as `Small`.
    Big(Box<BigParts>),
}

#[derive(Clone, PartialEq, Eq, Hash)]
struct BigParts {
    num: BigInt,
    den: BigUint,
}

/// Whether `|x|` is small enough for the inline tier (`i128::MIN` is excluded so that negation
/// never overflows).
#[inline]
fn fits(x: i128) -> bool {
    x != i128::MIN
}

impl Rational {
    /// Zero.
    pub const ZERO: Rational = Rational(Repr::Small(0, 1));
    /// One.
    pub const ONE: Rational = Rational(Repr::Small(1, 1));

    /// The integer `n`.
    #[inline]
    pub fn from_integer(n: i64) -> Rational {
        Rational(Repr::Small(n as i128, 1))
    }

    /// `num / den` reduced to canonical form, or [`ZeroDivisor`] when `den == 0`.
    pub fn new(num: i64, den: i64) -> Result<Rational, ZeroDivisor> {
        if den == 0 {
            return Err(ZeroDivisor);
        }
        Ok(Self::reduce_small(num as i128, den as i128))
    }

    /// `num / 2^exp` in lowest terms (the common factors of two cancelled; no gcd).
    pub fn from_dyadic(num: &BigInt, exp: u64) -> Rational {
        let Some(tz) = num.trailing_zeros() else {
            return Rational::ZERO;
        };
        let shift = tz.min(exp);
        let e = exp - shift;
        if e <= 125 {
            if let Some(n) = num.to_i128() {
                return Rational(Repr::Small(n >> shift, 1i128 << e));
            }
        }
        Rational::from_coprime(num >> shift, BigUint::one() << e)
    }

    /// `num / den` for `i128` parts, canonicalised.
    ///
    /// # Errors
    /// [`ZeroDivisor`] when `den == 0`.
    pub fn from_i128_ratio(num: i128, den: i128) -> Result<Rational, ZeroDivisor> {
        if den == 0 {
            return Err(ZeroDivisor);
        }
        if fits(num) && fits(den) {
            Ok(Self::reduce_small(num, den))
        } else {
            Ok(Self::from_big_parts(BigInt::from(num), BigInt::from(den)))
        }
    }

    /// Reduces `num / den` (`den != 0`, neither `i128::MIN`) to canonical form.
    fn reduce_small(num: i128, den: i128) -> Rational {
        debug_assert!(den != 0 && fits(num) && fits(den));
        let (num, den) = if den < 0 { (-num, -den) } else { (num, den) };
        if num == 0 {
            return Rational::ZERO;
        }
        if let (Ok(n), Ok(d)) = (i64::try_from(num), i64::try_from(den)) {
            // Both in one word (the common case of the polynomial kernels' output terms): a
            // 64-bit gcd and two 64-bit divisions instead of 128-bit ones. `g <= d < 2^63`.
            let g = gcd_u64(n.unsigned_abs(), d as u64) as i64;
            if g == 1 {
                return Rational(Repr::Small(num, den));
            }
            return Rational(Repr::Small((n / g) as i128, (d / g) as i128));
        }
        let g = gcd_u128(num.unsigned_abs(), den as u128) as i128;
        if g == 1 {
            return Rational(Repr::Small(num, den));
        }
        Rational(Repr::Small(div_small(num, g), div_small(den, g)))
    }

    /// Canonical form of `num / den` from big parts with `den != 0` (reduces by their gcd).
    fn from_big_parts(num: BigInt, den: BigInt) -> Rational {
        debug_assert!(!den.is_zero());
        let (sign, den_mag) = match den.sign() {
            BigSign::Minus => (-1, den.into_parts().1),
            _ => (1, den.into_parts().1),
        };
        let num = if sign < 0 { -num } else { num };
        if num.is_zero() {
            return Rational::ZERO;
        }
        let g = gcd_biguint(num.magnitude(), &den_mag);
        if g.is_one() {
            Self::from_coprime(num, den_mag)
        } else {
            let num = num / BigInt::from_biguint(BigSign::Plus, g.clone());
            Self::from_coprime(num, den_mag / g)
        }
    }

    /// Wraps coprime parts (`den > 0`), choosing the inline tier when they fit.
    fn from_coprime(num: BigInt, den: BigUint) -> Rational {
        debug_assert!(!den.is_zero());
        if den.bits() <= 127 && num.magnitude().bits() <= 127 {
            // Both fit: |x| < 2^127, so the conversions cannot fail.
            let n = num.to_i128().expect("|num| < 2^127 fits in i128");
            let d = den.to_i128().expect("den < 2^127 fits in i128");
            Rational(Repr::Small(n, d))
        } else {
            Rational(Repr::Big(Box::new(BigParts { num, den })))
        }
    }

    /// Whether the value is held inline (no heap); exposed for tests and benchmarks.
    pub fn is_inline(&self) -> bool {
        matches!(self.0, Repr::Small(..))
    }

    /// The canonical numerator and denominator when the value is held inline (both of magnitude
    /// below `2^127`, denominator positive, coprime), without allocating; `None` for the big tier.
    /// For kernels with machine-word fast paths (e.g. integer coefficients of polynomials).
    #[inline]
    pub fn inline_parts(&self) -> Option<(i128, i128)> {
        match self.0 {
            Repr::Small(n, d) => Some((n, d)),
            Repr::Big(_) => None,
        }
    }

    /// The double nearest to the value (ties to even, gradual underflow, overflow to `±inf`):
    /// the workspace's one correctly rounded conversion, [`crate::to_f64::rational_to_f64`],
    /// with a fast path where numerator and denominator are exact doubles (then one IEEE
    /// division is the correctly rounded quotient).
    pub fn to_f64(&self) -> f64 {
        const EXACT: i128 = 1 << 53;
        match &self.0 {
            // Both exact in f64 (converted from i64: one instruction each, not the i128 routine).
            Repr::Small(n, d) if n.abs() <= EXACT && *d <= EXACT => {
                (*n as i64) as f64 / (*d as i64) as f64
            }
            _ => crate::to_f64::rational_to_f64(&self.to_big_rational()),
        }
    }

    /// The size in bits: of the numerator's magnitude plus of the denominator (0 for zero counts
    /// as 0 + 1). Computed without allocating, for size limits checked after every operation.
    pub fn bits(&self) -> u64 {
        match &self.0 {
            Repr::Small(n, d) => {
                u64::from(128 - n.unsigned_abs().leading_zeros())
                    + u64::from(128 - (*d as u128).leading_zeros())
            }
            Repr::Big(b) => b.num.magnitude().bits() + b.den.bits(),
        }
    }

    /// The numerator (sign carrier) as a `BigInt`.
    pub fn numer(&self) -> BigInt {
        match &self.0 {
            Repr::Small(n, _) => BigInt::from(*n),
            Repr::Big(b) => b.num.clone(),
        }
    }

    /// The (positive) denominator as a `BigInt`.
    pub fn denom(&self) -> BigInt {
        match &self.0 {
            Repr::Small(_, d) => BigInt::from(*d),
            Repr::Big(b) => BigInt::from_biguint(BigSign::Plus, b.den.clone()),
        }
    }

    /// Whether the value is an integer (denominator 1).
    pub fn is_integer(&self) -> bool {
        match &self.0 {
            Repr::Small(_, d) => *d == 1,
            Repr::Big(b) => b.den.is_one(),
        }
    }

    /// The value as num-rational's `BigRational`.
    pub fn to_big_rational(&self) -> BigRational {
        BigRational::new_raw(self.numer(), self.denom())
    }

    /// Whether the internal representation is canonical (coprime parts, positive denominator,
    /// inline exactly when it fits). Always true for values built through the public API; used
    /// by the property tests after every operation.
    pub fn is_canonical(&self) -> bool {
        match &self.0 {
            Repr::Small(n, d) => {
                *d > 0
                    && fits(*n)
                    && fits(*d)
                    && (if *n == 0 {
                        *d == 1
                    } else {
                        gcd_u128(n.unsigned_abs(), *d as u128) == 1
                    })
            }
            Repr::Big(b) => {
                !b.den.is_zero()
                    && !b.num.is_zero()
                    && (b.den.bits() > 127 || b.num.magnitude().bits() > 127)
                    && gcd_biguint(b.num.magnitude(), &b.den).is_one()
            }
        }
    }

    /// The numerator and denominator as big integers, borrowed where possible.
    fn big_parts(&self) -> (Cow<'_, BigInt>, Cow<'_, BigUint>) {
        match &self.0 {
            Repr::Small(n, d) => (
                Cow::Owned(BigInt::from(*n)),
                Cow::Owned(BigUint::from(*d as u128)),
            ),
            Repr::Big(b) => (Cow::Borrowed(&b.num), Cow::Borrowed(&b.den)),
        }
    }

    /// The sign.
    pub fn signum(&self) -> Sign {
        let positive = match &self.0 {
            Repr::Small(n, _) => match n.cmp(&0) {
                Ordering::Equal => return Sign::Zero,
                o => o == Ordering::Greater,
            },
            Repr::Big(b) => b.num.is_positive(),
        };
        if positive {
            Sign::Positive
        } else {
            Sign::Negative
        }
    }

    /// `1 / self`, or [`ZeroDivisor`].
    pub fn recip(&self) -> Result<Rational, ZeroDivisor> {
        match &self.0 {
            Repr::Small(0, _) => Err(ZeroDivisor),
            Repr::Small(n, d) => Ok(if *n < 0 {
                Rational(Repr::Small(-*d, -*n))
            } else {
                Rational(Repr::Small(*d, *n))
            }),
            Repr::Big(b) => {
                let (sign, mag) = (b.num.sign(), b.num.magnitude().clone());
                let num = BigInt::from_biguint(sign, b.den.clone());
                Ok(Self::from_coprime(num, mag))
            }
        }
    }

    // ------------------------------------------------------------------ arithmetic kernels

    /// `self + rhs`, or `self - rhs` when `sub`: subtraction directly, not as `self + (-rhs)`,
    /// which would copy a big `rhs` to negate it.
    #[inline]
    fn add_impl(&self, rhs: &Rational, sub: bool) -> Rational {
        if let (Repr::Small(a, b), Repr::Small(c, d)) = (&self.0, &rhs.0) {
            if let Some((a, b, c, d)) = word::words(*a, *b, *c, *d) {
                // `-c` of a word `c` fits `i64` except for `i64::MIN`, left to the general path.
                if let Some(c) = if sub { c.checked_neg() } else { Some(c) } {
                    return word::add_words(a, b, c, d);
                }
            }
            // `fits` excludes i128::MIN, so `-c` cannot overflow.
            if let Some(r) = add_small(*a, *b, if sub { -*c } else { *c }, *d) {
                return r;
            }
        }
        if rhs.is_zero_value() {
            return self.clone();
        }
        if self.is_zero_value() {
            return if sub { rhs.neg_impl() } else { rhs.clone() };
        }
        // A big operand and a word-sized one (the running sum of rational-sum `seq`): limb kernels.
        match (&self.0, &rhs.0) {
            (Repr::Big(x), Repr::Small(c, d)) => {
                if let Some(r) = add_big_word(&x.num, &x.den, if sub { -*c } else { *c }, *d) {
                    return r;
                }
            }
            (Repr::Small(c, d), Repr::Big(y)) => {
                // x + y, or x - y = -(y - x).
                if let Some(mut r) = add_big_word(&y.num, &y.den, if sub { -*c } else { *c }, *d) {
                    if sub {
                        r.neg_in_place();
                    }
                    return r;
                }
            }
            _ => {}
        }
        let (a, b) = self.big_parts();
        let (c, d) = rhs.big_parts();
        add_big(&a, &b, &c, &d, sub)
    }

    /// `self + rhs` (`self - rhs` when `sub`) reusing `self`'s storage: a big `self` plus a
    /// word-sized `rhs` (the running sum `s += x`) is updated in place
    /// ([`add_big_word_in_place`]); everything else is [`Rational::add_impl`].
    fn add_owned(mut self, rhs: &Rational, sub: bool) -> Rational {
        if let (Repr::Big(x), Repr::Small(c, d)) = (&mut self.0, &rhs.0) {
            match add_big_word_in_place(x, if sub { -*c } else { *c }, *d) {
                InPlace::Done => return self,
                InPlace::Replaced(r) => return r,
                InPlace::NotWords => {}
            }
        }
        self.add_impl(rhs, sub)
    }

    fn mul_impl(&self, rhs: &Rational) -> Rational {
        if let (Repr::Small(a, b), Repr::Small(c, d)) = (&self.0, &rhs.0) {
            if let Some((a, b, c, d)) = word::words(*a, *b, *c, *d) {
                return word::mul_words(a, b, c, d);
            }
            return mul_small(*a, *b, *c, *d);
        }
        if self.is_zero_value() || rhs.is_zero_value() {
            return Rational::ZERO;
        }
        let (a, b) = self.big_parts();
        let (c, d) = rhs.big_parts();
        mul_big(&a, &b, &c, &d)
    }

    fn neg_impl(&self) -> Rational {
        match &self.0 {
            Repr::Small(n, d) => Rational(Repr::Small(-*n, *d)),
            Repr::Big(b) => Rational(Repr::Big(Box::new(BigParts {
                num: -&b.num,
                den: b.den.clone(),
            }))),
        }
    }

    fn neg_in_place(&mut self) {
        match &mut self.0 {
            Repr::Small(n, _) => *n = -*n,
            Repr::Big(b) => {
                let num = std::mem::take(&mut b.num);
                b.num = -num;
            }
        }
    }

    fn is_zero_value(&self) -> bool {
        matches!(self.0, Repr::Small(0, _))
    }

    /// `self / rhs`, or [`ZeroDivisor`].
    pub fn checked_div(&self, rhs: &Rational) -> Result<Rational, ZeroDivisor> {
        Ok(self.mul_impl(&rhs.recip()?))
    }

    fn cmp_impl(&self, rhs: &Rational) -> Ordering {
        let (sa, sb) = (self.signum(), rhs.signum());
        if sa != sb {
            return sa.cmp(&sb);
        }
        if let (Repr::Small(a, b), Repr::Small(c, d)) = (&self.0, &rhs.0) {
            // Word-sized parts (the common case): the products fit `i128` without a check.
            let word = |x: i128| i128::from(x as i64) == x;
            if word(*a) && word(*b) && word(*c) && word(*d) {
                return (a * d).cmp(&(c * b));
            }
            if let (Some(l), Some(r)) = (a.checked_mul(*d), c.checked_mul(*b)) {
                return l.cmp(&r);
            }
        }
        let (a, b) = self.big_parts();
        let (c, d) = rhs.big_parts();
        let l = a.as_ref() * BigInt::from_biguint(BigSign::Plus, d.into_owned());
        let r = c.as_ref() * BigInt::from_biguint(BigSign::Plus, b.into_owned());
        l.cmp(&r)
    }

    /// `self^e` for an integer exponent (negative exponents invert).
    ///
    /// # Errors
    /// [`ZeroDivisor`] for `0^e` with `e < 0`.
    pub fn powi(&self, e: i32) -> Result<Rational, ZeroDivisor> {
        let p = Ring::pow(self, e.unsigned_abs());
        if e < 0 {
            p.recip()
        } else {
            Ok(p)
        }
    }
}

/// `a/b + c/d` on the inline tier by Henrici's method; `None` on overflow.
#[inline]
fn add_small(a: i128, b: i128, c: i128, d: i128) -> Option<Rational> {
    if b == 1 && d == 1 {
        let s = a.checked_add(c)?;
        return fits(s).then_some(Rational(Repr::Small(s, 1)));
    }
    if a == 0 {
        return Some(Rational(Repr::Small(c, d)));
    }
    if c == 0 {
        return Some(Rational(Repr::Small(a, b)));
    }
    if b == d {
        // Same denominator: one gcd of the sum against it.
        let s = a.checked_add(c)?;
        if s == 0 {
            return Some(Rational::ZERO);
        }
        if !fits(s) {
            return None;
        }
        let g = gcd_u128(s.unsigned_abs(), b as u128) as i128;
        return Some(Rational(Repr::Small(div_small(s, g), div_small(b, g))));
    }
    if d == 1 {
        // a/b + c = (a + c b)/b, already reduced.
        let n = c.checked_mul(b)?.checked_add(a)?;
        return fits(n).then_some(Rational(Repr::Small(n, b)));
    }
    if b == 1 {
        let n = a.checked_mul(d)?.checked_add(c)?;
        return fits(n).then_some(Rational(Repr::Small(n, d)));
    }
    let g = gcd_u128(b as u128, d as u128) as i128;
    if g == 1 {
        let n = a.checked_mul(d)?.checked_add(c.checked_mul(b)?)?;
        let den = b.checked_mul(d)?;
        if n == 0 {
            return Some(Rational::ZERO);
        }
        return (fits(n) && fits(den)).then_some(Rational(Repr::Small(n, den)));
    }
    let (b1, d1) = (div_small(b, g), div_small(d, g));
    let t = a.checked_mul(d1)?.checked_add(c.checked_mul(b1)?)?;
    if t == 0 {
        return Some(Rational::ZERO);
    }
    if !fits(t) {
        return None;
    }
    let g2 = gcd_u128(t.unsigned_abs(), g as u128) as i128;
    let den = b1.checked_mul(div_small(d, g2))?;
    fits(den).then_some(Rational(Repr::Small(div_small(t, g2), den)))
}

/// `x / y` (truncated) for `y > 0`: one 64-bit division when `|x|` and `y` fit a word (the
/// parts of most inline rationals), the `i128` division (a library call) otherwise.
#[inline]
fn div_small(x: i128, y: i128) -> i128 {
    debug_assert!(y > 0);
    let m = x.unsigned_abs();
    if (m | y as u128) >> 64 == 0 {
        let q = i128::from((m as u64) / (y as u64));
        if x < 0 {
            -q
        } else {
            q
        }
    } else {
        x / y
    }
}

/// `(a/b) (c/d)` for inline operands by Henrici's method: the crossed gcds are cancelled on
/// the inline parts, and products that overflow `i128` are formed as 256-bit products straight
/// into the big tier (no second normalisation).
#[inline]
fn mul_small(a: i128, b: i128, c: i128, d: i128) -> Rational {
    if a == 0 || c == 0 {
        return Rational::ZERO;
    }
    let g1 = if d == 1 {
        1
    } else {
        gcd_u128(a.unsigned_abs(), d as u128) as i128
    };
    let g2 = if b == 1 {
        1
    } else {
        gcd_u128(c.unsigned_abs(), b as u128) as i128
    };
    // Divide only where a factor cancels: i128 division is the expensive part.
    let (a, d) = if g1 == 1 {
        (a, d)
    } else {
        (div_small(a, g1), div_small(d, g1))
    };
    let (c, b) = if g2 == 1 {
        (c, b)
    } else {
        (div_small(c, g2), div_small(b, g2))
    };
    if let (Some(n), Some(den)) = (a.checked_mul(c), b.checked_mul(d)) {
        if fits(n) && fits(den) {
            return Rational(Repr::Small(n, den));
        }
    }
    let sign = if (a < 0) == (c < 0) {
        BigSign::Plus
    } else {
        BigSign::Minus
    };
    let num = BigInt::from_biguint(sign, wide_mul(a.unsigned_abs(), c.unsigned_abs()));
    Rational::from_coprime(num, wide_mul(b as u128, d as u128))
}

/// The full 256-bit product `x y` as a [`BigUint`].
fn wide_mul(x: u128, y: u128) -> BigUint {
    let (x0, x1) = (x as u64 as u128, x >> 64);
    let (y0, y1) = (y as u64 as u128, y >> 64);
    let (p00, p01, p10, p11) = (x0 * y0, x0 * y1, x1 * y0, x1 * y1);
    // Middle column: the high half of p00 plus the low halves of p01 and p10 (< 3 * 2^64).
    let mid = (p00 >> 64) + (p01 as u64 as u128) + (p10 as u64 as u128);
    let high = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    bigint::biguint_from_limbs(&[p00 as u64, mid as u64, high as u64, (high >> 64) as u64])
}

/// `x / g` for a `g` dividing `x`: a shift when `g` is a power of two (the denominators of
/// doubles), otherwise num-bigint's division.
fn div_exact(x: &BigUint, g: &BigUint) -> BigUint {
    match g.trailing_zeros() {
        Some(t) if g.bits() == t + 1 => x >> t,
        _ => x / g,
    }
}

/// `x / g` for a signed `x` and a `g` dividing it ([`div_exact`] on the magnitude).
fn div_exact_signed(x: &BigInt, g: &BigUint) -> BigInt {
    BigInt::from_biguint(x.sign(), div_exact(x.magnitude(), g))
}

/// `x * y` for a signed `x` and an unsigned `y`, without copying `y` into a `BigInt`.
fn mul_signed(x: &BigInt, y: &BigUint) -> BigInt {
    BigInt::from_biguint(x.sign(), x.magnitude() * y)
}

/// `a/b + c/d` (`a/b - c/d` when `sub`) on big parts by Knuth's method (TAOCP 4.5.1): gcds only
/// of the denominators and of the new numerator against their (usually small) common factor.
/// Borrows every operand; only the result's parts are allocated.
fn add_big(a: &BigInt, b: &BigUint, c: &BigInt, d: &BigUint, sub: bool) -> Rational {
    let combine = |x: BigInt, y: BigInt| if sub { x - y } else { x + y };
    if let Some(r) = add_dyadic(a, b, c, d, sub) {
        return r;
    }
    if b == d {
        let s = if sub { a - c } else { a + c };
        if s.is_zero() {
            return Rational::ZERO;
        }
        let g = gcd_biguint(s.magnitude(), b);
        return if g.is_one() {
            Rational::from_coprime(s, b.clone())
        } else {
            Rational::from_coprime(div_exact_signed(&s, &g), div_exact(b, &g))
        };
    }
    let g = gcd_biguint(b, d);
    if g.is_one() {
        let n = combine(mul_signed(a, d), mul_signed(c, b));
        if n.is_zero() {
            return Rational::ZERO;
        }
        return Rational::from_coprime(n, b * d);
    }
    let b1 = div_exact(b, &g);
    let d1 = div_exact(d, &g);
    let t = combine(mul_signed(a, &d1), mul_signed(c, &b1));
    if t.is_zero() {
        return Rational::ZERO;
    }
    let g2 = gcd_biguint(t.magnitude(), &g);
    if g2.is_one() {
        Rational::from_coprime(t, b1 * d)
    } else {
        let den = b1 * div_exact(d, &g2);
        Rational::from_coprime(div_exact_signed(&t, &g2), den)
    }
}

/// [`add_big`] when `b` or `d` is a power of two (a double, or a value built from doubles by
/// ring operations, against anything): every gcd of Knuth's method is then a power of two
/// found from trailing zeros, every division by it a shift, and the multiplication by the
/// power-of-two cofactor a shift too. `None` when neither denominator is a power of two.
fn add_dyadic(a: &BigInt, b: &BigUint, c: &BigInt, d: &BigUint, sub: bool) -> Option<Rational> {
    let (tb, td) = (b.trailing_zeros()?, d.trailing_zeros()?);
    let (pb, pd) = (b.bits() == tb + 1, d.bits() == td + 1);
    if !pb && !pd {
        return None;
    }
    // g = gcd(b, d) = 2^m; t = a (d/g) + c (b/g).
    let m = tb.min(td);
    let term = |x: &BigInt, y: &BigUint, ty: u64, py: bool| {
        if py {
            x << (ty - m)
        } else {
            mul_signed(x, &(y >> m))
        }
    };
    let (x, y) = (term(a, d, td, pd), term(c, b, tb, pb));
    let t = if sub { x - y } else { x + y };
    let Some(tz) = t.trailing_zeros() else {
        return Some(Rational::ZERO);
    };
    // g2 = gcd(t, g) = 2^s; the result is (t/g2) / ((b/g)(d/g2)).
    let s = tz.min(m);
    let den = match (pb, pd) {
        (true, true) => BigUint::one() << (tb - m + td - s),
        (true, false) => (d >> s) << (tb - m),
        (false, _) => (b >> m) << (td - s),
    };
    Some(Rational::from_coprime(t >> s, den))
}

/// `a/b + c/d` for a big `a/b` and a word-sized `c/d` (`|c| < 2^64`, `0 < d < 2^64`, both
/// canonical) by Henrici's method on the limb kernels of [`crate::bigint`]; `None` when `c/d`
/// is not word-sized. With `g = gcd(b, d) = gcd(d, b mod d)`:
///
/// * `g = 1`: `(a d + c b) / (b d)`, already reduced;
/// * otherwise, `t = a (d/g) + c (b/g)`, `g2 = gcd(t, g) = gcd(g, t mod g)`, and the result is
///   `(t/g2) / ((b/g)(d/g2))` (TAOCP 4.5.1).
///
/// The big operands are copied out as limbs once; then one folding remainder pass for `g`, one fused
/// pass ([`bigint::add_word_pass`]) for `t` and `b (d/g)`, one remainder pass over `t` when
/// `g > 1`, and, only when `g2 > 1`, one pass dividing `t` and the denominator by `g2` at once. [`add_big`] is the reference it
/// replaces (tested against it).
fn add_big_word(a: &BigInt, b: &BigUint, c: i128, d: i128) -> Option<Rational> {
    let cm = u64::try_from(c.unsigned_abs()).ok()?;
    let d = u64::try_from(d).ok()?;
    debug_assert!(d > 0);
    let (an, cn) = (a.sign() == BigSign::Minus, c < 0);
    // Copied at the lengths the pass works on (n limbs and n + 1).
    let n = a
        .magnitude()
        .iter_u64_digits()
        .len()
        .max(b.iter_u64_digits().len());
    let (al, bl) = (
        bigint::limbs_of(a.magnitude(), n),
        bigint::limbs_of(b, n + 1),
    );
    let g = gcd_u64(d, bigint::rem_1(&bl, d));
    let (t, tn, den) = bigint::add_word_pass(al, an, bl, cn, cm, d, g);
    if t.is_empty() {
        return Some(Rational::ZERO);
    }
    // t = a (d/g) + c (b/g) and den = b (d/g) = (b/g) d; with g2 = gcd(t, g) (which divides d)
    // the result is (t/g2) / ((b/g)(d/g2)).
    let g2 = if g == 1 {
        1
    } else {
        gcd_u64(g, bigint::rem_1(&t, g))
    };
    let (mut t, mut den) = (t, den);
    if g2 != 1 {
        bigint::divexact_1_pair_in_place(&mut t, &mut den, g2);
    }
    if t.is_empty() {
        return Some(Rational::ZERO);
    }
    let sign = if tn { BigSign::Minus } else { BigSign::Plus };
    let num = BigInt::from_biguint(sign, bigint::biguint_from_limbs(&t));
    Some(Rational::from_coprime(
        num,
        bigint::biguint_from_limbs(&den),
    ))
}

/// The outcome of [`add_big_word_in_place`].
enum InPlace {
    /// The big value was updated and is still big.
    Done,
    /// The result, which is zero or fits the inline tier.
    Replaced(Rational),
    /// The word operand does not fit 64 bits: nothing was done.
    NotWords,
}

/// The limb buffers of [`add_big_word_in_place`], reused from call to call on each thread so
/// that a running sum allocates nothing per addition (buffers above [`SCRATCH_KEPT_LIMBS`]
/// are released after use).
#[derive(Default)]
struct AddScratch {
    a: Vec<u64>,
    b: Vec<u64>,
    out: (Vec<u64>, Vec<u64>),
    digits: Vec<u32>,
}

/// The largest scratch buffer kept between calls, in limbs (8 MB).
const SCRATCH_KEPT_LIMBS: usize = 1 << 20;

thread_local! {
    static ADD_SCRATCH: std::cell::RefCell<AddScratch> = std::cell::RefCell::new(AddScratch::default());
}

/// `x + c/d` (`c/d` canonical, `d > 0`) written over `x` itself: [`add_big_word`]'s passes on
/// the thread's reused limb buffers, the result stored back into `x`'s own allocations through
/// num-bigint's `assign_from_slice`, so no number is allocated or freed per addition.
fn add_big_word_in_place(x: &mut BigParts, c: i128, d: i128) -> InPlace {
    let (Ok(cm), Ok(d)) = (u64::try_from(c.unsigned_abs()), u64::try_from(d)) else {
        return InPlace::NotWords;
    };
    if cm == 0 {
        return InPlace::Done;
    }
    ADD_SCRATCH.with(|cell| {
        let mut guard = cell.borrow_mut();
        let s = &mut *guard;
        let an = x.num.sign() == BigSign::Minus;
        let n = x
            .num
            .magnitude()
            .iter_u64_digits()
            .len()
            .max(x.den.iter_u64_digits().len());
        bigint::limbs_into(x.num.magnitude(), n, &mut s.a);
        bigint::limbs_into(&x.den, n + 1, &mut s.b);
        let g = gcd_u64(d, bigint::rem_1(&s.b, d));
        let tn = bigint::add_word_pass_into(&mut s.a, an, &mut s.b, (c < 0, cm, d), g, &mut s.out);
        let (t, den) = (&mut s.out.0, &mut s.out.1);
        let result = if t.is_empty() {
            InPlace::Replaced(Rational::ZERO)
        } else {
            // As in `add_big_word`: the result is (t/g2) / den/g2, g2 = gcd(t, g).
            let g2 = if g == 1 {
                1
            } else {
                gcd_u64(g, bigint::rem_1(t, g))
            };
            if g2 != 1 {
                bigint::divexact_1_pair_in_place(t, den, g2);
            }
            let sign = if tn { BigSign::Minus } else { BigSign::Plus };
            if t.len() <= 2 && den.len() <= 2 {
                // Perhaps inline now.
                InPlace::Replaced(Rational::from_coprime(
                    BigInt::from_biguint(sign, bigint::biguint_from_limbs(t)),
                    bigint::biguint_from_limbs(den),
                ))
            } else {
                bigint::u32_digits_into(t, &mut s.digits);
                x.num.assign_from_slice(sign, &s.digits);
                bigint::u32_digits_into(den, &mut s.digits);
                x.den.assign_from_slice(&s.digits);
                InPlace::Done
            }
        };
        if s.a.capacity() > SCRATCH_KEPT_LIMBS {
            *s = AddScratch::default();
        }
        result
    })
}

/// `x / g`, borrowing `x` when `g` is one.
fn div_unless_one<'a>(x: &'a BigUint, g: &BigUint) -> Cow<'a, BigUint> {
    if g.is_one() {
        Cow::Borrowed(x)
    } else {
        Cow::Owned(div_exact(x, g))
    }
}

/// `(a/b)(c/d)` on big parts by Henrici's method: cancel `gcd(a, d)` and `gcd(c, b)` first. The
/// magnitudes are multiplied borrowed (no copy when a gcd is one) and the sign applied last.
fn mul_big(a: &BigInt, b: &BigUint, c: &BigInt, d: &BigUint) -> Rational {
    if b.is_one() && d.is_one() {
        // Integers (the coefficients of primitive polynomials): nothing to cancel.
        return Rational::from_coprime(a * c, b.clone());
    }
    let g1 = gcd_biguint(a.magnitude(), d);
    let g2 = gcd_biguint(c.magnitude(), b);
    let (a1, d1) = (div_unless_one(a.magnitude(), &g1), div_unless_one(d, &g1));
    let (c1, b1) = (div_unless_one(c.magnitude(), &g2), div_unless_one(b, &g2));
    let num = BigInt::from_biguint(a.sign() * c.sign(), a1.as_ref() * c1.as_ref());
    Rational::from_coprime(num, b1.as_ref() * d1.as_ref())
}

// ---------------------------------------------------------------------- operator plumbing

exactcheck_core::ring_ops! {
    impl[] Rational;
    Neg::neg: |x| x.neg_impl(), owned |x| {
        let mut x = x;
        x.neg_in_place();
        x
    };
    Add::add, AddAssign::add_assign: |x, y| x.add_impl(y, false), owned |x, y| x.add_owned(y, false);
    Sub::sub, SubAssign::sub_assign: |x, y| x.add_impl(y, true), owned |x, y| x.add_owned(y, true);
    Mul::mul, MulAssign::mul_assign: |x, y| x.mul_impl(y);
    Div::div, DivAssign::div_assign: |x, y| match x.checked_div(y) {
        Ok(q) => q,
        Err(_) => panic!("Rational division by zero (use Field::checked_div to handle it)"),
    };
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Self) -> Ordering {
        self.cmp_impl(other)
    }
}

impl Default for Rational {
    #[inline]
    fn default() -> Self {
        Rational::ZERO
    }
}

impl Ring for Rational {
    #[inline]
    fn zero() -> Self {
        Rational::ZERO
    }
    #[inline]
    fn one() -> Self {
        Rational::ONE
    }
    #[inline]
    fn from_i64(n: i64) -> Self {
        Rational::from_integer(n)
    }
    #[inline]
    fn is_zero(&self) -> bool {
        self.is_zero_value()
    }
    #[inline]
    fn is_one(&self) -> bool {
        matches!(self.0, Repr::Small(1, 1))
    }
    #[inline]
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs, false)
    }
    #[inline]
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs, true)
    }
    #[inline]
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(rhs)
    }
    #[inline]
    fn neg_ref(&self) -> Self {
        self.neg_impl()
    }
    fn square(&self) -> Self {
        // (n/d)^2 is already reduced: no gcd at all.
        match &self.0 {
            Repr::Small(n, d) => {
                if let (Ok(n), Ok(d)) = (i64::try_from(*n), i64::try_from(*d)) {
                    // Word parts: the squares are below 2^126.
                    let (n, d) = (i128::from(n), i128::from(d));
                    return Rational(Repr::Small(n * n, d * d));
                }
                if let (Some(nn), Some(dd)) = (n.checked_mul(*n), d.checked_mul(*d)) {
                    if fits(nn) && fits(dd) {
                        return Rational(Repr::Small(nn, dd));
                    }
                }
                let (n, d) = (BigInt::from(*n), BigUint::from(*d as u128));
                Rational::from_coprime(&n * &n, &d * &d)
            }
            Repr::Big(b) => Rational::from_coprime(&b.num * &b.num, &b.den * &b.den),
        }
    }
}

impl Field for Rational {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        self.recip()
    }
    fn checked_div(&self, rhs: &Self) -> Result<Self, ZeroDivisor> {
        Rational::checked_div(self, rhs)
    }
    fn from_ratio(num: i64, den: i64) -> Result<Self, ZeroDivisor> {
        Rational::new(num, den)
    }
}

impl OrderedField for Rational {
    fn sign(&self) -> Sign {
        self.signum()
    }
}
