//! Machine-word coefficient kernels: the hook that lets the generic product kernels multiply
//! `Rational` and `ModP` coefficients as `i64` and accumulate them in `i64`, `i128` or 192 bits.
//!
//! # The hook
//! [`WordCoefficients`] is implemented by the coefficient types that have a machine-word image:
//! [`WordCoefficients::to_words`] writes a coefficient list as integers `n_i` of at most 63 bits
//! over one common denominator `d` (`c_i = n_i / d`; for a rational list `d` is the lcm of the
//! denominators, so a polynomial with a small rational content rides along as FLINT's
//! `fmpq_mpoly` stores it, content times an integer polynomial), and
//! [`WordCoefficients::from_word_sum`] turns an exact integer sum `n` (at most 192 bits) over a
//! denominator back into a coefficient, once per output term. `Poly<C>` stays generic over
//! `C: Ring`; the kernels ask [`word_hooks`] for the hooks of `C`, which recognises the
//! implementing types by their `TypeId` (every `Ring` is `'static`) and hands back plain function
//! pointers, so there is no `unsafe`, no specialisation, and other coefficient types (radicals,
//! polynomials) take the generic path unchanged. The number-type details stay in `exact`.
//!
//! # The accumulators
//! Every output coefficient of `f g` is a sum of at most `min(#f, #g)` term products, with at
//! most one term product per term of either factor, so the smallest of
//! `max|F| max|G| min(#f, #g)`, `sum|F| max|G|` and `max|F| sum|G|` is a bound `B` on every
//! partial sum. With `B < 2^31` the kernels sum in `i32` ([`W32`]: half the memory of `i64`
//! cells, so a dense slab twice as large stays in the first-level cache), with `B < 2^63` in
//! `i64` ([`W64`]), with `B < 2^127` in `i128` ([`W128`]), and otherwise in a signed 192-bit
//! `(hi: i64, lo: u128)` pair ([`W192`], the three-limb accumulation of FLINT's `mpoly`
//! kernels): each product of two 63-bit words is below `2^126`, and at most `2^64` of them sum
//! below `2^190`. No accumulator can overflow, so the kernels never check. Coefficients that do
//! not fit (a numerator or the common denominator beyond 63 bits) send the whole product to the
//! generic path on the coefficient type itself.
//!
//! Why hand-written: the coefficient kernels are the inner loops of every expansion; a generic
//! big-number type cannot know that a bound keeps all sums in one or two machine words.

use crate::gcd::gcd_u64;
use crate::{ModP, Rational};
use exactcheck_core::{Field, Ring};
use num_bigint::BigInt;
use std::any::Any;
use std::marker::PhantomData;

/// A signed integer of 192 bits, `hi * 2^128 + lo` (`lo` read unsigned): the exact value of a
/// word kernel's accumulator.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WordSum {
    /// The high part (signed).
    pub hi: i64,
    /// The low 128 bits.
    pub lo: u128,
}

impl WordSum {
    /// The value `x`.
    #[inline]
    pub fn from_i128(x: i128) -> WordSum {
        WordSum {
            hi: if x < 0 { -1 } else { 0 },
            lo: x as u128,
        }
    }

    /// The value as an `i128`, if it fits.
    #[inline]
    pub fn to_i128(self) -> Option<i128> {
        let x = self.lo as i128;
        ((self.hi == 0 && x >= 0) || (self.hi == -1 && x < 0)).then_some(x)
    }

    /// The value as a big integer.
    pub fn to_bigint(self) -> BigInt {
        (BigInt::from(self.hi) << 128) + BigInt::from(self.lo)
    }

    /// `self += p`.
    #[inline(always)]
    fn add_i128(&mut self, p: i128) {
        // lo + (p as u128) = lo + p + 2^128 [p < 0]; a carry out adds 2^128.
        let (s, carry) = self.lo.overflowing_add(p as u128);
        self.lo = s;
        self.hi = self.hi.wrapping_add(carry as i64 - (p < 0) as i64);
    }

    /// `self += x`.
    #[inline(always)]
    fn add(&mut self, x: WordSum) {
        let (s, carry) = self.lo.overflowing_add(x.lo);
        self.lo = s;
        self.hi = self.hi.wrapping_add(x.hi).wrapping_add(carry as i64);
    }
}

/// Coefficient types with a machine-word image, for the product kernels (see the module
/// documentation).
pub trait WordCoefficients: Ring {
    /// The coefficients as integers `n_i` over one common denominator `d >= 1`
    /// (`c_i = n_i / d`), every `|n_i| < 2^63` (`i64::MIN` excluded) and `d < 2^63`; `None` when
    /// that is not possible (the product then takes the generic path).
    fn to_words(coeffs: &[Self]) -> Option<(Vec<i64>, i64)>;

    /// The coefficient `n / d` (`d >= 1`, a product of two denominators of
    /// [`WordCoefficients::to_words`]).
    fn from_word_sum(n: WordSum, d: i128) -> Self;

    /// The coefficients `n_i / d` of sums of one word each, as [`WordCoefficients::from_word_sum`]
    /// on every `n_i` (one loop for a whole product instead of one call per coefficient).
    fn from_small_sums<T: Copy + Into<i64>>(n: &[T], d: i128) -> Vec<Self> {
        n.iter()
            .map(|&x| Self::from_word_sum(WordSum::from_i128(i128::from(x.into())), d))
            .collect()
    }
}

impl WordCoefficients for Rational {
    fn to_words(coeffs: &[Rational]) -> Option<(Vec<i64>, i64)> {
        let mut l: i64 = 1;
        for c in coeffs {
            let (_, d) = c.inline_parts()?;
            if d != 1 {
                let d = i64::try_from(d).ok()?;
                let g = gcd_u64(l as u64, d as u64) as i64;
                l = (l / g).checked_mul(d)?;
            }
        }
        let mut out = Vec::with_capacity(coeffs.len());
        for c in coeffs {
            let (n, d) = c.inline_parts()?;
            // Every denominator divides `l < 2^63`; the scaled numerator must fit a word, so the
            // product is formed in `i64` (a native multiply; an `i128` one is a library call).
            let n = i64::try_from(n).ok()?;
            let scaled = if l == 1 {
                n
            } else {
                n.checked_mul(l / d as i64)?
            };
            out.push(Some(scaled).filter(|&x| x != i64::MIN)?);
        }
        Some((out, l))
    }

    fn from_small_sums<T: Copy + Into<i64>>(n: &[T], d: i128) -> Vec<Rational> {
        if d == 1 {
            n.iter()
                .map(|&x| Rational::from_integer(x.into()))
                .collect()
        } else {
            n.iter()
                .map(|&x| {
                    Rational::from_i128_ratio(i128::from(x.into()), d)
                        .expect("word denominators are >= 1")
                })
                .collect()
        }
    }

    fn from_word_sum(n: WordSum, d: i128) -> Rational {
        match n.to_i128() {
            Some(x) if d == 1 => match i64::try_from(x) {
                Ok(s) => Rational::from_integer(s),
                Err(_) => Rational::from_i128_ratio(x, 1).expect("1 is not zero"),
            },
            Some(x) => Rational::from_i128_ratio(x, d).expect("word denominators are >= 1"),
            None => {
                let q = Rational::from(n.to_bigint());
                if d == 1 {
                    q
                } else {
                    let d = Rational::from_i128_ratio(d, 1).expect("1 is not zero");
                    q.checked_div(&d).expect("word denominators are >= 1")
                }
            }
        }
    }
}

impl WordCoefficients for ModP {
    fn to_words(coeffs: &[ModP]) -> Option<(Vec<i64>, i64)> {
        // Residues are below 2^61.
        Some((coeffs.iter().map(|c| c.value() as i64).collect(), 1))
    }

    fn from_word_sum(n: WordSum, d: i128) -> ModP {
        // 2^128 = 2^(2*61 + 6) = 2^6 modulo 2^61 - 1.
        let v = ModP::from_u128(n.lo) + ModP::from_i64(n.hi) * ModP::new(64);
        if d == 1 {
            v
        } else {
            let d = ModP::from_u128(d as u128);
            v * d
                .inv()
                .expect("the modulus divides no word denominator (ModP's are all 1)")
        }
    }
}

/// [`WordCoefficients::to_words`] as a function pointer.
type ToWords<C> = fn(&[C]) -> Option<(Vec<i64>, i64)>;
/// A content split (see [`content_of`]) as a function pointer.
type ContentSplit<C> = fn(&[C]) -> Option<(C, Vec<C>)>;

/// The word hooks of one coefficient type, as plain function pointers.
pub(super) struct WordHooks<C> {
    pub(super) to_words: ToWords<C>,
    pub(super) from_word_sum: fn(WordSum, i128) -> C,
    pub(super) from_i32_sums: fn(&[i32], i128) -> Vec<C>,
    pub(super) from_i64_sums: fn(&[i64], i128) -> Vec<C>,
}

impl<C> Clone for WordHooks<C> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<C> Copy for WordHooks<C> {}

/// `t` as a `U` when `T` and `U` are the same type.
pub(super) fn cast<T: 'static, U: 'static>(t: T) -> Option<U> {
    let mut slot = Some(t);
    (&mut slot as &mut dyn Any)
        .downcast_mut::<Option<U>>()
        .and_then(Option::take)
}

/// The word hooks of `C` when it implements [`WordCoefficients`] (`Rational`, `ModP`), `None`
/// for every other coefficient type.
pub(super) fn word_hooks<C: Ring>() -> Option<WordHooks<C>> {
    fn of<W: WordCoefficients>() -> WordHooks<W> {
        WordHooks {
            to_words: W::to_words,
            from_word_sum: W::from_word_sum,
            from_i32_sums: W::from_small_sums::<i32>,
            from_i64_sums: W::from_small_sums::<i64>,
        }
    }
    cast::<WordHooks<Rational>, WordHooks<C>>(of::<Rational>())
        .or_else(|| cast::<WordHooks<ModP>, WordHooks<C>>(of::<ModP>()))
}

/// The content of a polynomial with rational coefficients, for powers: `c = gcd(numerators) /
/// lcm(denominators)` (positive) and the primitive integer coefficients `c_i / c`; `None` when
/// `c = 1` or `C` is not `Rational`.
pub(super) fn content_of<C: Ring>(coeffs: &[C]) -> Option<(C, Vec<C>)> {
    let split: ContentSplit<Rational> = rational_content_impl;
    cast::<ContentSplit<Rational>, ContentSplit<C>>(split)?(coeffs)
}

/// Whether the rationals are all integers of the inline tier whose gcd is 1 (content 1, the
/// common case), decided in machine words without building a big integer; `false` also when
/// the list needs the general computation.
fn unit_integer_content(q: &[Rational]) -> bool {
    let mut g = 0u128;
    for c in q {
        match c.inline_parts() {
            // Once the gcd is 1 it stays 1; the rest must still be integers.
            Some((n, 1)) if g != 1 => g = crate::gcd::gcd_u128(g, n.unsigned_abs()),
            Some((_, 1)) => {}
            _ => return false,
        }
    }
    g == 1
}

fn rational_content_impl(q: &[Rational]) -> Option<(Rational, Vec<Rational>)> {
    use num_integer::Integer;
    use num_traits::{One, Zero};
    if q.is_empty() {
        return None;
    }
    if unit_integer_content(q) {
        return None;
    }
    let mut g = BigInt::zero();
    let mut l = BigInt::one();
    for c in q {
        g = g.gcd(&c.numer());
        if !c.is_integer() {
            l = l.lcm(&c.denom());
        }
    }
    let content = Rational::from(g) / Rational::from(l);
    if content.is_one() {
        return None;
    }
    let prim = q
        .iter()
        .map(|c| {
            c.checked_div(&content)
                .expect("the content of a non-zero list is not zero")
        })
        .collect();
    Some((content, prim))
}

// ------------------------------------------------------------------------------ arithmetic

/// The coefficient arithmetic of a product kernel: inputs `In`, exact partial sums `Acc`.
pub(super) trait Arith {
    type In;
    type Acc: Clone;
    fn mul(a: &Self::In, b: &Self::In) -> Self::Acc;
    fn add_mul(acc: &mut Self::Acc, a: &Self::In, b: &Self::In);
    fn add(acc: &mut Self::Acc, x: Self::Acc);
    fn double(x: Self::Acc) -> Self::Acc;
    fn is_zero(x: &Self::Acc) -> bool;
}

/// The generic arithmetic: the ring's own operations.
pub(super) struct Generic<C>(PhantomData<C>);

impl<C: Ring> Arith for Generic<C> {
    type In = C;
    type Acc = C;
    #[inline(always)]
    fn mul(a: &C, b: &C) -> C {
        a.mul_ref(b)
    }
    #[inline(always)]
    fn add_mul(acc: &mut C, a: &C, b: &C) {
        *acc += a.mul_ref(b);
    }
    #[inline(always)]
    fn add(acc: &mut C, x: C) {
        *acc += x;
    }
    #[inline(always)]
    fn double(x: C) -> C {
        x.add_ref(&x)
    }
    #[inline(always)]
    fn is_zero(x: &C) -> bool {
        x.is_zero()
    }
}

/// Word arithmetic: `i64` inputs, an accumulator of exact sums (at most a [`WordSum`]) and its zero.
pub(super) trait WordArith: Arith<In = i64, Acc: Copy> {
    const ZERO: Self::Acc;
    /// Whether the direct dense kernel multiplies blocks of consecutive cells (`i32` cells:
    /// a block of four is one vector multiply-add; wider products are not vector operations
    /// here, and for them the kernel keeps one product per term).
    const BLOCKS: bool;
    /// Whether every cell is zero.
    fn all_zero(cells: &[Self::Acc]) -> bool;
    /// The coefficients `n_i / d` of the exact sums `n_i`, by the hooks `h`: accumulators of
    /// one word convert the whole list in one call of the coefficient type's loop.
    fn to_coeffs<C>(sums: Vec<Self::Acc>, d: i128, h: WordHooks<C>) -> Vec<C>;
}

/// `i32` accumulators (every partial sum, so every term product, below `2^31`).
pub(super) struct W32;
/// `i64` accumulators (every partial sum below `2^63`).
pub(super) struct W64;
/// `i128` accumulators (every partial sum below `2^127`).
pub(super) struct W128;
/// 192-bit accumulators.
pub(super) struct W192;

/// The [`Arith`] and [`WordArith`] impls of a word accumulator: its type and zero, one
/// product widened to it, a product added to it, an accumulator added to it, the zero test of
/// a row of cells, and the conversion of the sums to coefficients. The four accumulators
/// differ only there.
macro_rules! word_arith {
    ($name:ident, $acc:ty, $zero:expr,
     mul: |$a:ident, $b:ident| $mul:expr,
     add_mul: |$u:ident, $c:ident, $d:ident| $add_mul:expr,
     add: |$x:ident, $y:ident| $add:expr,
     blocks: $blocks:expr,
     all_zero: |$z:ident| $all_zero:expr,
     to_coeffs: |$v:ident, $dd:ident, $h:ident| $to_coeffs:expr) => {
        impl Arith for $name {
            type In = i64;
            type Acc = $acc;
            #[inline(always)]
            fn mul($a: &i64, $b: &i64) -> $acc {
                $mul
            }
            #[inline(always)]
            fn add_mul($u: &mut $acc, $c: &i64, $d: &i64) {
                $add_mul
            }
            #[inline(always)]
            fn add($x: &mut $acc, $y: $acc) {
                $add
            }
            #[inline(always)]
            fn double(x: $acc) -> $acc {
                let mut y = x;
                Self::add(&mut y, x);
                y
            }
            #[inline(always)]
            fn is_zero(x: &$acc) -> bool {
                *x == $zero
            }
        }

        impl WordArith for $name {
            const ZERO: $acc = $zero;
            const BLOCKS: bool = $blocks;
            #[inline(always)]
            fn all_zero($z: &[$acc]) -> bool {
                $all_zero
            }
            fn to_coeffs<C>($v: Vec<$acc>, $dd: i128, $h: WordHooks<C>) -> Vec<C> {
                $to_coeffs
            }
        }
    };
}

// The bound keeps every product and partial sum inside `i32`, so the products are exact in
// `i64` and the narrowing loses nothing. Zero tests of a row OR its cells (one vector loop).
word_arith!(W32, i32, 0,
    mul: |a, b| a.wrapping_mul(*b) as i32,
    add_mul: |acc, a, b| *acc = acc.wrapping_add(a.wrapping_mul(*b) as i32),
    add: |x, y| *x = x.wrapping_add(y),
    blocks: true,
    all_zero: |cells| cells.iter().fold(0, |o, &x| o | x) == 0,
    to_coeffs: |sums, d, h| (h.from_i32_sums)(&sums, d));
word_arith!(W64, i64, 0,
    mul: |a, b| a * b,
    add_mul: |acc, a, b| *acc += a * b,
    add: |x, y| *x += y,
    blocks: false,
    all_zero: |cells| cells.iter().fold(0, |o, &x| o | x) == 0,
    to_coeffs: |sums, d, h| (h.from_i64_sums)(&sums, d));
word_arith!(W128, i128, 0,
    mul: |a, b| *a as i128 * *b as i128,
    add_mul: |acc, a, b| *acc += *a as i128 * *b as i128,
    add: |x, y| *x += y,
    blocks: false,
    all_zero: |cells| cells.iter().fold(0, |o, &x| o | x) == 0,
    to_coeffs: |sums, d, h| sums.into_iter().map(|x| (h.from_word_sum)(WordSum::from_i128(x), d)).collect());
// A product of two 63-bit words is below 2^126: an i128, added with a carry into the top.
word_arith!(W192, WordSum, WordSum { hi: 0, lo: 0 },
    mul: |a, b| WordSum::from_i128(*a as i128 * *b as i128),
    add_mul: |acc, a, b| acc.add_i128(*a as i128 * *b as i128),
    add: |x, y| x.add(y),
    blocks: false,
    all_zero: |cells| cells.iter().all(|x| x.hi == 0 && x.lo == 0),
    to_coeffs: |sums, d, h| sums.into_iter().map(|x| (h.from_word_sum)(x, d)).collect());

/// Which accumulator a product needs: the bound `B` of the module documentation; 0 for
/// `i32`, 1 for `i64`, 2 for `i128`, 3 for 192 bits.
pub(super) fn accumulator_for(f: &[i64], g: &[i64]) -> u8 {
    let max = |v: &[i64]| v.iter().map(|x| x.unsigned_abs()).max().unwrap_or(0) as u128;
    // At most 2^64 terms of at most 2^63 each: below 2^127.
    let sum = |v: &[i64]| v.iter().map(|x| x.unsigned_abs() as u128).sum::<u128>();
    let n = f.len().min(g.len()) as u128;
    let (mf, mg) = (max(f), max(g));
    let bound = [
        (mf * mg).checked_mul(n),
        sum(f).checked_mul(mg),
        mf.checked_mul(sum(g)),
    ]
    .into_iter()
    .flatten()
    .min();
    match bound {
        Some(b) if b < 1 << 31 => 0,
        Some(b) if b < 1 << 63 => 1,
        Some(b) if b < 1 << 127 => 2,
        _ => 3,
    }
}
