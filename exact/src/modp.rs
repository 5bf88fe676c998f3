//! `ModP`: the integers modulo the Mersenne prime `p = 2^61 - 1`, for randomized identity tests.
//!
//! # Why
//! The proof engine's "holds" verdict (method "finite-field random
//! evaluation") evaluates a claim's residual — a polynomial in the
//! inputs, written once and generic over [`Ring`] — at random points of `Z/pZ`. By the
//! Schwartz–Zippel lemma a non-zero polynomial of total degree `d` vanishes at a uniformly random
//! point with probability at most `d / p`, so `k` independent evaluations that all give zero
//! leave an error probability of at most `(d / p)^k` ([`schwartz_zippel_bound`]). With
//! `p ≈ 2.3 · 10^18` a single evaluation of a degree-100 residual is already wrong with
//! probability below `5 · 10^-17`.
//!
//! # Representation
//! A residue is a `u64` in `0..P`, always reduced, so `==` is equality in the field. Products are
//! formed in `u128` and reduced by the Mersenne folding `x = hi · 2^61 + lo ≡ hi + lo (mod p)`,
//! with no division. Rationals map in by `n · d^-1` ([`ModP::from_rational`]), which is a ring
//! homomorphism on the rationals whose denominator is prime to `p`.
//!
//! Random points come from the workspace's one seeded generator, [`exactcheck_core::Rng`], so
//! that every randomized verdict is reproducible from its seed.
//!
//! # A prime chosen at random: [`PrimeField`]
//! A fixed modulus is unsound for `prove --random`: `(2^61 - 1) x` is zero modulo `2^61 - 1`
//! although it is not zero over Q. [`PrimeField`] is `Z/pZ` for a modulus chosen at run time,
//! [`PrimeField::random_62`] draws it uniformly from the primes in `[2^62, 2^63)` (uniform
//! candidates, rejected unless prime: the accepted value is uniform over the primes), and
//! [`is_prime_u64`] is a deterministic Miller–Rabin test (the first twelve primes as bases are a
//! proof of primality for every `n < 3.3 · 10^24`, Sorenson and Webster 2015). Elements are plain
//! `u64` residues in `0..p`, and the arithmetic lives on the context value (`field.mul(a, b)`):
//! with `p < 2^63` a sum of two residues fits in a `u64` and a product in a `u128`. It is written
//! here rather than taken from a crate because the workspace needs only these few operations and
//! must control the sampling to state its error bound (see `prove::random`).

use crate::rational::Rational;
use exactcheck_core::{Field, Ring, Rng, ZeroDivisor};
use num_bigint::{BigInt, Sign as BigSign};
use std::fmt;

/// The modulus, the Mersenne prime `2^61 - 1`.
pub const P: u64 = (1u64 << 61) - 1;

/// An element of `Z/pZ` with `p = 2^61 - 1` ([`P`]); the wrapped residue is always in `0..P`.
///
/// ```
/// use exactcheck_core::Ring;
/// use exactcheck_core::Rng;
/// use exactcheck_exact::modp::{schwartz_zippel_bound, ModP};
///
/// // (x + y)^2 - (x^2 + 2xy + y^2) vanishes at 20 random points: if it were a non-zero
/// // polynomial (of degree 2), that would happen with probability at most (2/p)^20.
/// let mut rng = Rng::new(7);
/// for _ in 0..20 {
///     let (x, y) = (ModP::random(&mut rng), ModP::random(&mut rng));
///     let residual = (x + y).square() - (x * x + ModP::from_i64(2) * x * y + y * y);
///     assert!(residual.is_zero());
/// }
/// assert!(schwartz_zippel_bound(2, 20) < 1e-300);
/// ```
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct ModP(u64);

/// Reduces `x < 2^124` (any product of two residues, and any once-folded `u128`) modulo [`P`].
#[inline]
fn reduce_small_u128(x: u128) -> u64 {
    // x = hi 2^61 + lo ≡ hi + lo; hi < 2^63, lo < 2^61, so the fold fits in a u64.
    let folded = ((x >> 61) as u64) + ((x as u64) & P);
    let r = (folded >> 61) + (folded & P);
    if r >= P {
        r - P
    } else {
        r
    }
}

impl ModP {
    /// Zero.
    pub const ZERO: ModP = ModP(0);
    /// One.
    pub const ONE: ModP = ModP(1);

    /// The residue of a `u64`.
    #[inline]
    pub fn new(x: u64) -> ModP {
        let r = (x >> 61) + (x & P);
        ModP(if r >= P { r - P } else { r })
    }

    /// The residue of a `u128`, by Mersenne folding (no division).
    #[inline]
    pub fn from_u128(x: u128) -> ModP {
        // One fold brings any u128 below 2^68, which the product reduction handles.
        ModP(reduce_small_u128((x >> 61) + (x & P as u128)))
    }

    /// The residue of a signed integer.
    #[inline]
    pub fn from_i64(n: i64) -> ModP {
        let r = ModP::new(n.unsigned_abs());
        if n < 0 {
            -r
        } else {
            r
        }
    }

    /// The residue of a big integer.
    pub fn from_bigint(n: &BigInt) -> ModP {
        // Horner over the 64-bit limbs, most significant first: r = r 2^64 + limb.
        let shift = ModP::new(1u64 << 63) * ModP::new(2); // 2^64 mod p
        let mut r = ModP::ZERO;
        for limb in n.magnitude().iter_u64_digits().rev() {
            r = r * shift + ModP::new(limb);
        }
        if n.sign() == BigSign::Minus {
            -r
        } else {
            r
        }
    }

    /// The image `n · d^-1` of the rational `n / d`.
    ///
    /// This is a ring homomorphism from the rationals whose denominator is prime to `p`:
    /// `from_rational(a + b) = from_rational(a) + from_rational(b)`, likewise for `*`.
    ///
    /// # Errors
    /// [`ZeroDivisor`] when `p` divides the denominator (the rational has no image).
    pub fn from_rational(q: &Rational) -> Result<ModP, ZeroDivisor> {
        if let Some((n, d)) = q.inline_parts() {
            // The inline tier: no big integers (the denominator is positive).
            let n = match ModP::from_u128(n.unsigned_abs()) {
                r if n < 0 => -r,
                r => r,
            };
            if d == 1 {
                return Ok(n);
            }
            return Ok(n * ModP::from_u128(d.unsigned_abs()).inv_impl()?);
        }
        let n = ModP::from_bigint(&q.numer());
        if q.is_integer() {
            return Ok(n);
        }
        let d = ModP::from_bigint(&q.denom());
        Ok(n * d.inv_impl()?)
    }

    /// The residue, in `0..P`.
    #[inline]
    pub fn value(self) -> u64 {
        self.0
    }

    /// A uniformly random element drawn from `rng`.
    pub fn random(rng: &mut Rng) -> ModP {
        // Rejection sampling on 61 bits: only the value P itself (probability 2^-61) is redrawn.
        loop {
            let x = rng.next_u64() >> 3;
            if x < P {
                return ModP(x);
            }
        }
    }

    /// `self^e` for a 64-bit exponent (`self^0 = 1`).
    pub fn pow_u64(self, mut e: u64) -> ModP {
        let mut acc = ModP::ONE;
        let mut base = self;
        while e > 0 {
            if e & 1 == 1 {
                acc *= base;
            }
            base = base * base;
            e >>= 1;
        }
        acc
    }

    /// The inverse by the extended Euclidean algorithm, or [`ZeroDivisor`] for zero.
    fn inv_impl(self) -> Result<ModP, ZeroDivisor> {
        if self.0 == 0 {
            return Err(ZeroDivisor);
        }
        // Invariant: r_i ≡ t_i · self (mod p); all quantities fit in i64 since p < 2^61.
        let (mut r0, mut r1) = (P as i64, self.0 as i64);
        let (mut t0, mut t1) = (0i64, 1i64);
        while r1 != 0 {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            (t0, t1) = (t1, t0 - q * t1);
        }
        debug_assert_eq!(r0, 1);
        Ok(ModP::from_i64(t0))
    }

    #[inline]
    fn add_impl(self, rhs: ModP) -> ModP {
        let s = self.0 + rhs.0;
        ModP(if s >= P { s - P } else { s })
    }

    #[inline]
    fn sub_impl(self, rhs: ModP) -> ModP {
        ModP(if self.0 >= rhs.0 {
            self.0 - rhs.0
        } else {
            self.0 + P - rhs.0
        })
    }

    #[inline]
    fn mul_impl(self, rhs: ModP) -> ModP {
        ModP(reduce_small_u128(self.0 as u128 * rhs.0 as u128))
    }
}

/// The Schwartz–Zippel bound: the probability that a non-zero polynomial of total degree
/// `total_degree` over `Z/pZ` vanishes at each of `trials` independent, uniformly random points.
///
/// It is `(d / p)^trials` (Schwartz 1980, Zippel 1979: at most `d / p` per point), capped at 1
/// (a degree `d >= p` gives no information). A constant non-zero polynomial (`d = 0`) never
/// vanishes, so the bound is 0 for `trials >= 1`; with `trials = 0` nothing was tested and the
/// bound is 1. For many trials the value underflows to `0.0`; [`schwartz_zippel_log2_bound`]
/// gives its base-2 logarithm instead.
pub fn schwartz_zippel_bound(total_degree: u64, trials: u32) -> f64 {
    let per_point = (total_degree as f64 / P as f64).min(1.0);
    per_point.powf(trials as f64)
}

/// The base-2 logarithm of [`schwartz_zippel_bound`] (`trials · log2(d / p)`, at most 0), which
/// does not underflow; `-inf` for `d = 0` and `trials >= 1`.
pub fn schwartz_zippel_log2_bound(total_degree: u64, trials: u32) -> f64 {
    if trials == 0 {
        return 0.0;
    }
    let per_point = (total_degree as f64 / P as f64).min(1.0);
    trials as f64 * per_point.log2()
}

// ---------------------------------------------------------------------- operator plumbing

impl ModP {
    #[inline]
    fn div_impl(self, rhs: ModP) -> ModP {
        match rhs.inv_impl() {
            Ok(r) => self.mul_impl(r),
            Err(_) => panic!("ModP division by zero (use Field::checked_div to handle it)"),
        }
    }
}

exactcheck_core::ring_ops! {
    impl[] ModP;
    Neg::neg: |a| ModP(if a.0 == 0 { 0 } else { P - a.0 });
    Add::add, AddAssign::add_assign: |a, b| a.add_impl(*b);
    Sub::sub, SubAssign::sub_assign: |a, b| a.sub_impl(*b);
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_impl(*b);
    Div::div, DivAssign::div_assign: |a, b| a.div_impl(*b);
}

impl Ring for ModP {
    #[inline]
    fn zero() -> Self {
        ModP::ZERO
    }
    #[inline]
    fn one() -> Self {
        ModP::ONE
    }
    #[inline]
    fn from_i64(n: i64) -> Self {
        ModP::from_i64(n)
    }
    #[inline]
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
    #[inline]
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_impl(*rhs)
    }
    #[inline]
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.sub_impl(*rhs)
    }
    #[inline]
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(*rhs)
    }
    #[inline]
    fn neg_ref(&self) -> Self {
        -*self
    }
    fn pow(&self, e: u32) -> Self {
        self.pow_u64(e as u64)
    }
}

impl Field for ModP {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        self.inv_impl()
    }
}

impl From<u64> for ModP {
    fn from(x: u64) -> Self {
        ModP::new(x)
    }
}

impl From<i64> for ModP {
    fn from(n: i64) -> Self {
        ModP::from_i64(n)
    }
}

impl TryFrom<&Rational> for ModP {
    type Error = ZeroDivisor;
    fn try_from(q: &Rational) -> Result<Self, ZeroDivisor> {
        ModP::from_rational(q)
    }
}

impl fmt::Display for ModP {
    /// The residue in `0..P`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl fmt::Debug for ModP {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} (mod 2^61-1)", self.0)
    }
}

// ------------------------------------------------------------------ runtime prime modulus

/// `n` is prime (deterministic for every `u64`: Miller–Rabin to the bases 2, 3, ..., 37).
pub fn is_prime_u64(n: u64) -> bool {
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    for p in BASES {
        if n % p == 0 {
            return n == p;
        }
    }
    let mulm = |a: u64, b: u64| (a as u128 * b as u128 % n as u128) as u64;
    let powm = |mut b: u64, mut e: u64| {
        let mut acc = 1u64;
        while e > 0 {
            if e & 1 == 1 {
                acc = mulm(acc, b);
            }
            b = mulm(b, b);
            e >>= 1;
        }
        acc
    };
    let s = (n - 1).trailing_zeros();
    let d = (n - 1) >> s;
    'bases: for a in BASES {
        let mut x = powm(a, d);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mulm(x, x);
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// The prime field `Z/pZ` for a modulus `p` chosen at run time (an odd prime below `2^63`).
/// Elements are `u64` residues in `0..p`; the operations are methods of the field value.
///
/// ```
/// use exactcheck_exact::modp::PrimeField;
/// let f = PrimeField::new(1_000_000_007).unwrap();
/// let x = f.from_i64(-3);
/// assert_eq!(f.mul(x, f.inv(x).unwrap()), 1);
/// assert!(PrimeField::new(1_000_000_008).is_none());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrimeField {
    p: u64,
}

impl PrimeField {
    /// The field of an odd prime `p < 2^63`; `None` otherwise.
    pub fn new(p: u64) -> Option<PrimeField> {
        (p > 2 && p < 1 << 63 && is_prime_u64(p)).then_some(PrimeField { p })
    }

    /// A prime drawn uniformly from the primes in `[2^62, 2^63)`: uniform 62-bit offsets are
    /// drawn until one gives a prime, so every prime of the range is equally likely.
    pub fn random_62(rng: &mut Rng) -> PrimeField {
        loop {
            let candidate = (1u64 << 62) | (rng.next_u64() >> 2);
            if is_prime_u64(candidate) {
                return PrimeField { p: candidate };
            }
        }
    }

    /// The modulus `p`.
    pub fn modulus(&self) -> u64 {
        self.p
    }

    /// A uniformly random element.
    pub fn random(&self, rng: &mut Rng) -> u64 {
        rng.below(self.p)
    }

    /// `a + b`.
    #[inline]
    pub fn add(&self, a: u64, b: u64) -> u64 {
        let s = a + b; // < 2^64 since both are below p < 2^63
        if s >= self.p {
            s - self.p
        } else {
            s
        }
    }

    /// `a - b`.
    #[inline]
    pub fn sub(&self, a: u64, b: u64) -> u64 {
        if a >= b {
            a - b
        } else {
            a + (self.p - b)
        }
    }

    /// `-a`.
    #[inline]
    pub fn neg(&self, a: u64) -> u64 {
        if a == 0 {
            0
        } else {
            self.p - a
        }
    }

    /// `a b`.
    #[inline]
    pub fn mul(&self, a: u64, b: u64) -> u64 {
        (a as u128 * b as u128 % self.p as u128) as u64
    }

    /// `a^e`.
    pub fn pow(&self, mut a: u64, mut e: u64) -> u64 {
        let mut acc = 1 % self.p;
        while e > 0 {
            if e & 1 == 1 {
                acc = self.mul(acc, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        acc
    }

    /// The inverse, or [`ZeroDivisor`] for zero.
    pub fn inv(&self, a: u64) -> Result<u64, ZeroDivisor> {
        if a == 0 {
            return Err(ZeroDivisor);
        }
        // Extended Euclid; r_i ≡ t_i a (mod p), all magnitudes below p < 2^63.
        let (mut r0, mut r1) = (self.p as i128, a as i128);
        let (mut t0, mut t1) = (0i128, 1i128);
        while r1 != 0 {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            (t0, t1) = (t1, t0 - q * t1);
        }
        debug_assert_eq!(r0, 1);
        Ok(t0.rem_euclid(self.p as i128) as u64)
    }

    /// The residue of a signed integer.
    pub fn from_i64(&self, n: i64) -> u64 {
        let r = n.unsigned_abs() % self.p;
        if n < 0 {
            self.neg(r)
        } else {
            r
        }
    }

    /// The residue of a big integer.
    pub fn from_bigint(&self, n: &BigInt) -> u64 {
        let r = (n.magnitude() % self.p)
            .iter_u64_digits()
            .next()
            .unwrap_or(0);
        if n.sign() == BigSign::Minus {
            self.neg(r)
        } else {
            r
        }
    }

    /// The image `n d^-1` of `n / d`.
    ///
    /// # Errors
    /// [`ZeroDivisor`] when `p` divides the denominator.
    pub fn from_rational(&self, q: &Rational) -> Result<u64, ZeroDivisor> {
        let n = self.from_bigint(&q.numer());
        if q.is_integer() {
            return Ok(n);
        }
        Ok(self.mul(n, self.inv(self.from_bigint(&q.denom()))?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn miller_rabin_against_trial_division() {
        let trial = |n: u64| n >= 2 && (2..).take_while(|d| d * d <= n).all(|d| n % d != 0);
        for n in 0..5000u64 {
            assert_eq!(is_prime_u64(n), trial(n), "{n}");
        }
        assert!(is_prime_u64(P));
        assert!(is_prime_u64((1 << 62) + 135)); // the smallest prime above 2^62
        assert!(!is_prime_u64(3_215_031_751)); // strong pseudoprime to 2, 3, 5, 7
        assert!(!is_prime_u64(3_825_123_056_546_413_051)); // spsp to bases 2..23
        assert!(!is_prime_u64(P * 3));
    }

    #[test]
    fn prime_field_arithmetic() {
        let mut rng = Rng::new(5);
        let f = PrimeField::random_62(&mut rng);
        let p = f.modulus();
        assert!((1u64 << 62..1u64 << 63).contains(&p) && is_prime_u64(p));
        let a = p - 1;
        assert_eq!(f.mul(a, a), 1);
        assert_eq!(f.add(a, a), p - 2);
        assert_eq!(f.sub(1, 2), p - 1);
        assert_eq!(f.pow(3, p - 1), 1);
        let x = f.random(&mut rng);
        if x != 0 {
            assert_eq!(f.mul(x, f.inv(x).unwrap()), 1);
        }
        assert_eq!(f.inv(0), Err(ZeroDivisor));
        let big = BigInt::from(p) * BigInt::from(p) - 5;
        assert_eq!(f.from_bigint(&big), p - 5);
        assert_eq!(f.from_bigint(&-big), 5);
        assert_eq!(
            f.from_i64(i64::MIN),
            ((i64::MIN as i128).rem_euclid(p as i128)) as u64
        );
        let bad = Rational::from(num_rational::BigRational::new(1.into(), BigInt::from(p)));
        assert_eq!(f.from_rational(&bad), Err(ZeroDivisor));
        let half = Rational::new(1, 2).unwrap();
        assert_eq!(
            f.add(
                f.from_rational(&half).unwrap(),
                f.from_rational(&half).unwrap()
            ),
            1
        );
    }

    #[test]
    fn reduction_edges() {
        assert_eq!(ModP::new(P).value(), 0);
        assert_eq!(ModP::new(u64::MAX).value(), (u64::MAX % P));
        assert_eq!(
            ModP::from_u128(u128::MAX).value(),
            (u128::MAX % P as u128) as u64
        );
        let m = ModP::new(P - 1);
        assert_eq!((m * m).value(), 1);
        assert_eq!(ModP::from_i64(-1).value(), P - 1);
        assert_eq!(
            ModP::from_i64(i64::MIN).value(),
            ((i64::MIN as i128).rem_euclid(P as i128)) as u64
        );
    }

    #[test]
    fn inverse_and_division() {
        assert_eq!(ModP::ZERO.inv(), Err(ZeroDivisor));
        let x = ModP::new(123_456_789);
        assert_eq!(x * x.inv().unwrap(), ModP::ONE);
        assert_eq!(x.inv().unwrap(), x.pow_u64(P - 2));
        assert_eq!(ModP::new(6) / ModP::new(3), ModP::new(2));
    }

    #[test]
    fn rationals_map_in() {
        let half = Rational::new(1, 2).unwrap();
        let h = ModP::from_rational(&half).unwrap();
        assert_eq!(h + h, ModP::ONE);
        let bad = Rational::from_i128_ratio(1, P as i128).unwrap();
        assert_eq!(ModP::from_rational(&bad), Err(ZeroDivisor));
        let big: BigInt = BigInt::from(P) * BigInt::from(P) + 5;
        assert_eq!(ModP::from_bigint(&big), ModP::new(5));
        assert_eq!(ModP::from_bigint(&-big), -ModP::new(5));
    }

    #[test]
    fn bound() {
        assert_eq!(schwartz_zippel_bound(0, 1), 0.0);
        assert_eq!(schwartz_zippel_bound(5, 0), 1.0);
        let b = schwartz_zippel_bound(10, 2);
        assert!((b - (10.0 / P as f64).powi(2)).abs() < 1e-40);
        assert_eq!(schwartz_zippel_bound(u64::MAX, 3), 1.0);
        assert!((schwartz_zippel_log2_bound(1 << 20, 1) - (20.0 - (P as f64).log2())).abs() < 1e-9);
    }

    #[test]
    fn generator_is_reproducible() {
        let mut a = Rng::new(42);
        let mut b = Rng::new(42);
        for _ in 0..10 {
            let x = ModP::random(&mut a);
            assert_eq!(x, ModP::random(&mut b));
            assert!(x.value() < P);
        }
    }
}
