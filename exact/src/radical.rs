//! `Radical`: the multi-quadratic numbers, exact sums `sum_m c_m sqrt(m)` over Q; and
//! `ComplexRadical`, the same with `i = sqrt(-1)` adjoined.
//!
//! # Where they are used
//! * SPEC.md §4 (Chiang, seed 004): Example 4 has control vectors with `sqrt 2` and `sqrt 6`, and
//!   Table 1 (the conic sections of the cone) has weights `1/sqrt 2`, `1 + sqrt 2` and planes with
//!   normal `(1, 1, sqrt 2)`; the ruled-surface formulas run over [`Radical`] to reproduce them
//!   exactly. Roots of quadratics (poles, parameters `t = 1/sqrt 2`) are exact [`Radical`]s too,
//!   through [`Sqrt`].
//! * SPEC.md §1 (Juttler, Satz 5): the complex focal lines `xi (1,0,0,i) + zeta (0,1,-i,0)` of
//!   the elliptic linear congruence need `i`; they are checked over [`ComplexRadical`].
//! * DESIGN.md, "Numbers in JSON": input strings such as `"1/sqrt(2)"` or `"(2+sqrt(2))/3"` are
//!   parsed by [`Radical`]'s `FromStr`, and answers are printed by its `Display` in the same syntax
//!   (the output parses back to the same value).
//!
//! # Canonical form
//! A [`Radical`] is a list of terms `(m, c_m)` meaning `c_m sqrt(m)`, where
//! * each radicand `m` ([`Radicand`]) is a positive **square-free** integer, `m = 1` standing for
//!   the rational part;
//! * the list is **sorted by strictly increasing `m`**;
//! * **no coefficient is zero** (zero is the empty list), and every coefficient is a canonical
//!   [`Rational`].
//!
//! The square roots of distinct square-free integers are linearly independent over Q
//! (Besicovitch 1940), so this representation is unique: `==` is equality of numbers and the
//! derived `Hash` is consistent with it. No context (no fixed field `Q(sqrt d)`) is needed: the
//! product rule `sqrt(m1) sqrt(m2) = g sqrt((m1/g)(m2/g))`, `g = gcd(m1, m2)`, keeps the basis
//! closed, so numbers built from any radicals combine freely (`Q(sqrt 2, sqrt 6) = Q(sqrt 2,
//! sqrt 3)` needs no declaration).
//!
//! # Algorithms
//! Field operations split a number along one radical: choose an integer `q > 1` that divides or is
//! coprime to every radicand present (a "coprime-basis" element; found by gcd refinement, no
//! factoring) and write `x = a + b sqrt(q)` with `a`, `b` free of `sqrt(q)`. Since `q` is coprime
//! to the radicands of `a` and `b`, `sqrt(q)` is not in the field they generate (Kummer theory),
//! so `a^2 - q b^2 != 0` for `x != 0`. Then
//! * **inverse**: `x^-1 = (a - b sqrt q) / (a^2 - q b^2)`, recursing on the norm, which has one
//!   radical fewer, until it is rational;
//! * **sign** (exact): if `sign a` and `sign b` agree or one is zero, that is the sign; otherwise it
//!   is `sign(a) sign(a^2 - q b^2)`, the norm's sign being decided recursively. A floating-point
//!   filter with a rigorous error bound answers first when the value is clearly away from zero
//!   (as CGAL's filtered predicates do); [`Radical::sign_exact`] skips it;
//! * **square root**: of a rational `n/d`, `sqrt(n d)/d` after extracting the square part of `n`
//!   and `d` (trial division, then Miller–Rabin and Pollard's rho for 64-bit cofactors); of
//!   `x = a + b sqrt q`, denesting: if the norm `a^2 - q b^2` has a square root `n` in the field of
//!   `a` and `b`, then `sqrt x = sqrt((a + n)/2) + sign(b) sqrt((a - n)/2)`, recursively; otherwise
//!   `sqrt x` is not multi-quadratic at all. Every root is verified (`y >= 0`, `y^2 == x`)
//!   before it is returned.
//!
//! Costs grow with the number `k` of independent radicals (the recursions branch up to three ways
//! per level), which is tiny in this workspace (`k <= 3`).

use crate::gcd::{gcd_biguint_u64, gcd_u64};
use crate::rational::Rational;
use exactcheck_core::{Field, OrderedField, Ring, Sign, Sqrt, ZeroDivisor};
use num_bigint::{BigInt, BigUint, Sign as BigSign};
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::str::FromStr;

// ====================================================================== radicands

/// A positive square-free integer, the `m` of a basis element `sqrt(m)` of a [`Radical`]
/// (`1` for the rational part).
///
/// Held inline when it fits a `u64`. Larger radicands (products of several large ones) are held
/// as a big integer together with a list of pairwise coprime, square-free 64-bit factors, so that
/// no operation overflows and every radicand can be printed in a form that parses back
/// (`sqrt(a)*sqrt(b)` with 64-bit `a`, `b`). The order is the numeric order.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Radicand(Rd);

/// Invariant: `Small` exactly when the value fits a `u64`; the derived order of the variants
/// (`Small` first) is then the numeric order.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
enum Rd {
    Small(u64),
    Big(Box<BigKey>),
}

/// A radicand beyond 64 bits: its value and a factorization into pairwise coprime, square-free
/// 64-bit factors (not unique, so equality, hashing and order look at the value only).
#[derive(Clone)]
struct BigKey {
    value: BigUint,
    factors: Vec<u64>,
}

impl PartialEq for BigKey {
    fn eq(&self, other: &Self) -> bool {
        self.value == other.value
    }
}

impl Eq for BigKey {}

impl std::hash::Hash for BigKey {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.value.hash(state);
    }
}

impl PartialOrd for BigKey {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for BigKey {
    fn cmp(&self, other: &Self) -> Ordering {
        self.value.cmp(&other.value)
    }
}

impl Radicand {
    /// The radicand 1 (the rational part).
    pub const ONE: Radicand = Radicand(Rd::Small(1));

    /// The value, if it fits in a `u64`.
    pub fn as_u64(&self) -> Option<u64> {
        match &self.0 {
            Rd::Small(v) => Some(*v),
            Rd::Big(_) => None,
        }
    }

    /// The value as a big integer.
    pub fn to_biguint(&self) -> BigUint {
        match &self.0 {
            Rd::Small(v) => BigUint::from(*v),
            Rd::Big(b) => b.value.clone(),
        }
    }

    /// Whether this is the radicand 1 (the rational part).
    pub fn is_one(&self) -> bool {
        matches!(self.0, Rd::Small(1))
    }

    /// Pairwise coprime square-free factors whose product is the value.
    fn factors(&self) -> &[u64] {
        match &self.0 {
            Rd::Small(v) => std::slice::from_ref(v),
            Rd::Big(b) => &b.factors,
        }
    }

    /// The product of pairwise coprime, square-free factors.
    fn from_factors(mut factors: Vec<u64>) -> Radicand {
        factors.retain(|&f| f > 1);
        let value = factors
            .iter()
            .fold(BigUint::one(), |acc, &f| acc * BigUint::from(f));
        match value.to_u64() {
            Some(v) => Radicand(Rd::Small(v)),
            None => Radicand(Rd::Big(Box::new(BigKey { value, factors }))),
        }
    }

    fn gcd(&self, o: &Radicand) -> Radicand {
        if let (Rd::Small(a), Rd::Small(b)) = (&self.0, &o.0) {
            return Radicand(Rd::Small(gcd_u64(*a, *b)));
        }
        // Both factor lists are pairwise coprime: gcd(prod a_i, prod b_j) = prod gcd(a_i, b_j).
        let mut g = Vec::new();
        for &a in self.factors() {
            for &b in o.factors() {
                g.push(gcd_u64(a, b));
            }
        }
        Radicand::from_factors(g)
    }

    /// `self / o` for a divisor `o` of `self`.
    fn div_exact(&self, o: &Radicand) -> Radicand {
        if let (Rd::Small(a), Rd::Small(b)) = (&self.0, &o.0) {
            return Radicand(Rd::Small(a / b));
        }
        let quotient = self
            .factors()
            .iter()
            .map(|&a| o.factors().iter().fold(a, |x, &g| x / gcd_u64(x, g)))
            .collect();
        Radicand::from_factors(quotient)
    }

    /// `self · o` for `o` coprime to `self` (the product is then square-free).
    fn mul_coprime(&self, o: &Radicand) -> Radicand {
        if let (Rd::Small(a), Rd::Small(b)) = (&self.0, &o.0) {
            if let Some(p) = a.checked_mul(*b) {
                return Radicand(Rd::Small(p));
            }
        }
        let mut f = self.factors().to_vec();
        f.extend_from_slice(o.factors());
        Radicand::from_factors(f)
    }

    /// Whether `self` divides `o`.
    fn divides(&self, o: &Radicand) -> bool {
        match (&self.0, &o.0) {
            (Rd::Small(a), Rd::Small(b)) => b % a == 0,
            (Rd::Small(a), Rd::Big(b)) => gcd_biguint_u64(&b.value, *a) == Some(*a),
            (Rd::Big(_), Rd::Small(_)) => false,
            (Rd::Big(a), Rd::Big(b)) => (&b.value % &a.value).is_zero(),
        }
    }

    /// The value as a rational integer.
    fn to_rational(&self) -> Rational {
        match &self.0 {
            Rd::Small(v) => integer_u64(*v),
            Rd::Big(b) => Rational::from(BigInt::from_biguint(BigSign::Plus, b.value.clone())),
        }
    }

    /// The value as an `f64` (correctly rounded), `None` from 2^1000 on.
    fn to_f64_checked(&self) -> Option<f64> {
        match &self.0 {
            Rd::Small(v) => Some(*v as f64),
            Rd::Big(b) if b.value.bits() < 1000 => b.value.to_f64(),
            Rd::Big(_) => None,
        }
    }

    /// Whether the value is square-free and the representation consistent (certified by complete
    /// factorization of the 64-bit value or factors).
    fn is_square_free(&self) -> bool {
        match &self.0 {
            Rd::Small(v) => *v >= 1 && square_free_u64(*v).0 == 1,
            Rd::Big(b) => {
                let f = &b.factors;
                b.value.bits() > 64
                    && f.iter().all(|&x| x > 1 && square_free_u64(x).0 == 1)
                    && f.iter()
                        .enumerate()
                        .all(|(i, &x)| f[i + 1..].iter().all(|&y| gcd_u64(x, y) == 1))
                    && f.iter()
                        .fold(BigUint::one(), |acc, &x| acc * BigUint::from(x))
                        == b.value
            }
        }
    }

    /// Writes `sqrt(m)`; a radicand beyond 64 bits as a product `sqrt(a)*sqrt(b)*...` of 64-bit
    /// radicands, so that the parser (which factors 64-bit numbers completely) reads it back.
    fn write_sqrt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Rd::Big(b) = &self.0 else {
            return write!(f, "sqrt({self})");
        };
        let mut groups = Vec::new();
        let mut current = 1u64;
        for &x in &b.factors {
            match current.checked_mul(x) {
                Some(p) => current = p,
                None => {
                    groups.push(current);
                    current = x;
                }
            }
        }
        groups.push(current);
        for (i, g) in groups.iter().enumerate() {
            if i > 0 {
                f.write_str("*")?;
            }
            write!(f, "sqrt({g})")?;
        }
        Ok(())
    }
}

impl fmt::Display for Radicand {
    /// The decimal value.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Rd::Small(v) => write!(f, "{v}"),
            Rd::Big(b) => write!(f, "{}", b.value),
        }
    }
}

impl fmt::Debug for Radicand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

/// `sqrt(a) sqrt(b) = g sqrt(m)`: returns `(g, m)`, `g = gcd(a, b)`, `m = (a/g)(b/g)` (square-free
/// when `a` and `b` are).
fn mul_keys(a: &Radicand, b: &Radicand) -> (Radicand, Radicand) {
    if a.is_one() {
        return (Radicand::ONE, b.clone());
    }
    if b.is_one() {
        return (Radicand::ONE, a.clone());
    }
    let g = a.gcd(b);
    let m = a.div_exact(&g).mul_coprime(&b.div_exact(&g));
    (g, m)
}

/// The integer `v` as a rational.
fn integer_u64(v: u64) -> Rational {
    match i64::try_from(v) {
        Ok(s) => Rational::from_integer(s),
        Err(_) => Rational::from(BigInt::from(v)),
    }
}

// ====================================================================== number theory

/// `a b mod m`.
#[inline]
fn mul_mod(a: u64, b: u64, m: u64) -> u64 {
    ((a as u128 * b as u128) % m as u128) as u64
}

fn pow_mod(mut a: u64, mut e: u64, m: u64) -> u64 {
    let mut acc = 1 % m;
    a %= m;
    while e > 0 {
        if e & 1 == 1 {
            acc = mul_mod(acc, a, m);
        }
        a = mul_mod(a, a, m);
        e >>= 1;
    }
    acc
}

/// Deterministic Miller–Rabin for 64-bit integers (the first twelve prime bases suffice below
/// 3.3 · 10^24).
fn is_prime_u64(n: u64) -> bool {
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    for p in BASES {
        if n % p == 0 {
            return n == p;
        }
    }
    let s = (n - 1).trailing_zeros();
    let d = (n - 1) >> s;
    'bases: for a in BASES {
        let mut x = pow_mod(a, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mul_mod(x, x, n);
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// A non-trivial factor of an odd composite `n` with no prime factor below 2^10, by Pollard's rho
/// with Brent's cycle detection and batched gcds.
fn pollard_brent(n: u64) -> u64 {
    let step = |x: u64, c: u64| ((x as u128 * x as u128 + c as u128) % n as u128) as u64;
    for c in 1u64.. {
        let (mut y, mut r, mut q, mut g) = (2u64, 1u64, 1u64, 1u64);
        let (mut x, mut ys) = (y, y);
        while g == 1 {
            x = y;
            for _ in 0..r {
                y = step(y, c);
            }
            let mut k = 0;
            while k < r && g == 1 {
                ys = y;
                for _ in 0..(128.min(r - k)) {
                    y = step(y, c);
                    q = mul_mod(q, x.abs_diff(y), n);
                }
                g = gcd_u64(q, n);
                k += 128;
            }
            r *= 2;
        }
        if g == n {
            // The batch overshot: redo it one step at a time.
            loop {
                ys = step(ys, c);
                g = gcd_u64(x.abs_diff(ys), n);
                if g > 1 {
                    break;
                }
            }
        }
        if g != n {
            return g;
        }
    }
    n
}

/// Appends the prime factors of `n` (with multiplicity, any order) to `out`; `n` has no prime
/// factor below 2^10 (or is 1).
fn factor_rho(n: u64, out: &mut Vec<u64>) {
    if n == 1 {
        return;
    }
    if is_prime_u64(n) {
        out.push(n);
        return;
    }
    let r = n.isqrt();
    if r * r == n {
        factor_rho(r, out);
        factor_rho(r, out);
        return;
    }
    let d = pollard_brent(n);
    factor_rho(d, out);
    factor_rho(n / d, out);
}

/// `n = s^2 f` with `f` square-free, for `n >= 1` (complete factorization: always succeeds).
fn square_free_u64(n: u64) -> (u64, u64) {
    let mut primes = Vec::new();
    let mut c = n;
    let mut p = 2u64;
    while p < 1024 && p * p <= c {
        while c % p == 0 {
            primes.push(p);
            c /= p;
        }
        p += if p == 2 { 1 } else { 2 };
    }
    if c > 1 {
        if p * p > c {
            primes.push(c);
        } else {
            factor_rho(c, &mut primes);
        }
    }
    primes.sort_unstable();
    let (mut s, mut f) = (1u64, 1u64);
    let mut i = 0;
    while i < primes.len() {
        let p = primes[i];
        let mut e = 0;
        while i < primes.len() && primes[i] == p {
            e += 1;
            i += 1;
        }
        s *= p.pow(e / 2);
        if e % 2 == 1 {
            f *= p;
        }
    }
    (s, f)
}

/// `n mod p` for a big `n` and a `p < 2^32`, without allocating.
fn rem_u64(n: &BigUint, p: u64) -> u64 {
    n.iter_u32_digits()
        .rev()
        .fold(0u64, |r, d| ((r << 32) | d as u64) % p)
}

/// Trial-division bound for radicands beyond 64 bits.
const TRIAL_BOUND: u64 = 1 << 20;

/// `n = s^2 f` with `f` square-free, for `n >= 1`; `None` when `f` cannot be certified square-free
/// (a cofactor beyond 64 bits, with no prime factor up to 2^20, that is not a perfect square).
fn square_free_big(n: &BigUint) -> Option<(BigUint, Radicand)> {
    if let Some(v) = n.to_u64() {
        let (s, f) = square_free_u64(v);
        return Some((BigUint::from(s), Radicand(Rd::Small(f))));
    }
    let r = n.sqrt();
    if &r * &r == *n {
        return Some((r, Radicand::ONE));
    }
    // Very long numbers get a shorter trial division (the cost is linear in their length).
    let bound = if n.bits() <= 512 {
        TRIAL_BOUND
    } else {
        1 << 14
    };
    let mut s = BigUint::one();
    let mut free_primes: Vec<u64> = Vec::new();
    let mut c = n.clone();
    let mut p = 2u64;
    let finish = |s: BigUint, mut free: Vec<u64>, c: u64| {
        let (s2, f2) = square_free_u64(c);
        free.push(f2);
        Some((s * s2, Radicand::from_factors(free)))
    };
    while p <= bound {
        if let Some(v) = c.to_u64() {
            return finish(s, free_primes, v);
        }
        if rem_u64(&c, p) == 0 {
            let mut e = 0u32;
            while rem_u64(&c, p) == 0 {
                c /= p;
                e += 1;
            }
            s *= BigUint::from(p).pow(e / 2);
            if e % 2 == 1 {
                free_primes.push(p);
            }
        }
        // 2, 3, then the numbers 6k +- 1.
        p = match p {
            2 => 3,
            3 => 5,
            _ if p % 6 == 5 => p + 2,
            _ => p + 4,
        };
    }
    if let Some(v) = c.to_u64() {
        return finish(s, free_primes, v);
    }
    let r = c.sqrt();
    if &r * &r == c {
        return Some((s * r, Radicand::from_factors(free_primes)));
    }
    None
}

// ====================================================================== the number type

/// A term `c sqrt(m)`.
type Term = (Radicand, Rational);

/// An exact multi-quadratic number `sum_m c_m sqrt(m)` (see the module documentation for the
/// canonical form). A real, totally ordered field with exact sign and square roots of the
/// elements whose roots are multi-quadratic.
///
/// ```
/// use exactcheck_core::{Field, Sqrt};
/// use exactcheck_exact::radical::Radical;
///
/// let x: Radical = "1/sqrt(2)".parse().unwrap();
/// assert_eq!(x.to_string(), "sqrt(2)/2");
/// let y: Radical = "sqrt(2) * sqrt(6)".parse().unwrap();
/// assert_eq!(y, Radical::sqrt_of(12));
/// let one_plus: Radical = "1 + sqrt(2)".parse().unwrap();
/// assert_eq!(one_plus.inv().unwrap().to_string(), "-1 + sqrt(2)");
/// let nested: Radical = "3 - 2*sqrt(2)".parse().unwrap();
/// assert_eq!(nested.sqrt().unwrap().to_string(), "-1 + sqrt(2)");
/// // An exact decision where f64 rounds both sides to the same double:
/// let s: Radical = "sqrt(2) + sqrt(3)".parse().unwrap();
/// assert!(s < "3.1462643699419726".parse().unwrap());
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Radical {
    terms: Vec<Term>,
}

impl Radical {
    /// `sqrt(m)` for a non-negative integer, in canonical form (`sqrt(12) = 2 sqrt(3)`,
    /// `sqrt(0) = 0`). Always succeeds: every `u64` is factored completely.
    pub fn sqrt_of(m: u64) -> Radical {
        if m == 0 {
            return Radical::default();
        }
        let (s, f) = square_free_u64(m);
        Radical {
            terms: vec![(Radicand(Rd::Small(f)), integer_u64(s))],
        }
    }

    /// The non-negative square root of a rational, `sqrt(n/d) = sqrt(n d)/d`.
    ///
    /// `None` for a negative argument, and when the square-free part of the numerator or the
    /// denominator cannot be certified: a cofactor above 2^64 with no prime factor below 2^20
    /// (2^14 beyond 512 bits) that is not a perfect square. Every 64-bit value is factored
    /// completely (Miller–Rabin and Pollard's rho).
    pub fn sqrt_rational(q: &Rational) -> Option<Radical> {
        match q.signum() {
            Sign::Negative => return None,
            Sign::Zero => return Some(Radical::default()),
            Sign::Positive => {}
        }
        let n = q.numer().into_parts().1;
        let d = q.denom().into_parts().1;
        let (sn, fnum) = square_free_big(&n)?;
        let (sd, fden) = if d.is_one() {
            (BigUint::one(), Radicand::ONE)
        } else {
            square_free_big(&d)?
        };
        // sqrt(n/d) = sn sqrt(fn) / (sd sqrt(fd)) = sn sqrt(fn fd) / (sd fd); fn, fd coprime.
        let den = sd * fden.to_biguint();
        let coef = Rational::from(BigRational::new_raw(
            BigInt::from_biguint(BigSign::Plus, sn),
            BigInt::from_biguint(BigSign::Plus, den),
        ));
        Some(Radical {
            terms: vec![(fnum.mul_coprime(&fden), coef)],
        })
    }

    /// The rational coefficient of `sqrt(1)` (zero if absent).
    pub fn rational_part(&self) -> Rational {
        match self.terms.first() {
            Some((m, c)) if m.is_one() => c.clone(),
            _ => Rational::ZERO,
        }
    }

    /// Whether the value is rational (no radical term).
    pub fn is_rational(&self) -> bool {
        match self.terms.as_slice() {
            [] => true,
            [(m, _)] => m.is_one(),
            _ => false,
        }
    }

    /// The value as a rational, if it is one.
    pub fn to_rational(&self) -> Option<Rational> {
        match self.terms.as_slice() {
            [] => Some(Rational::ZERO),
            [(m, c)] if m.is_one() => Some(c.clone()),
            _ => None,
        }
    }

    /// The non-zero rational value, borrowed, if the value is a non-zero rational.
    fn as_nonzero_rational(&self) -> Option<&Rational> {
        match self.terms.as_slice() {
            [(m, c)] if m.is_one() => Some(c),
            _ => None,
        }
    }

    /// The terms `(m, c_m)`, meaning `c_m sqrt(m)`, sorted by increasing `m`, no `c_m` zero.
    pub fn terms(&self) -> &[(Radicand, Rational)] {
        &self.terms
    }

    /// An `f64` approximation, for display only: each term is rounded and the rounded terms are
    /// summed, so the result may be far from correctly rounded (and even of the wrong sign) when
    /// terms cancel. Use [`OrderedField::sign`] and comparisons for decisions.
    pub fn to_f64(&self) -> f64 {
        self.terms
            .iter()
            .map(|(m, c)| {
                let cf = c.to_f64();
                if m.is_one() {
                    cf
                } else {
                    cf * m.to_f64_checked().unwrap_or(f64::INFINITY).sqrt()
                }
            })
            .sum()
    }

    /// `c · self` for a rational `c`.
    pub fn scale(&self, c: &Rational) -> Radical {
        if c.is_zero() {
            return Radical::default();
        }
        if c.is_one() {
            return self.clone();
        }
        Radical {
            terms: self.terms.iter().map(|(m, x)| (m.clone(), x * c)).collect(),
        }
    }

    /// Whether the representation is canonical: radicands strictly increasing and square-free
    /// (certified for radicands below 2^64), coefficients non-zero and canonical. Always true
    /// for values built through the public API; used by the property tests.
    pub fn is_canonical(&self) -> bool {
        self.terms.windows(2).all(|w| w[0].0 < w[1].0)
            && self
                .terms
                .iter()
                .all(|(m, c)| !c.is_zero() && c.is_canonical() && m.is_square_free())
    }

    /// The sign, decided exactly without the floating-point filter (for tests and benchmarks;
    /// [`OrderedField::sign`] gives the same answer, usually faster).
    pub fn sign_exact(&self) -> Sign {
        self.sign_rec(false)
    }

    // ------------------------------------------------------------------ kernels

    /// Canonical form of an unsorted list of terms (sorts, merges equal radicands, drops zeros).
    fn from_unsorted(mut v: Vec<Term>) -> Radical {
        v.sort_by(|a, b| a.0.cmp(&b.0));
        let mut out: Vec<Term> = Vec::with_capacity(v.len());
        for (m, c) in v {
            match out.last_mut() {
                Some((lm, lc)) if *lm == m => *lc += c,
                _ => out.push((m, c)),
            }
        }
        out.retain(|(_, c)| !c.is_zero());
        Radical { terms: out }
    }

    /// `lhs ± rhs` by merging the sorted term lists; `lhs` is consumed (its terms are moved).
    fn add_terms(lhs: Vec<Term>, rhs: &[Term], negate: bool) -> Radical {
        let signed = |c: &Rational| if negate { -c } else { c.clone() };
        if rhs.is_empty() {
            return Radical { terms: lhs };
        }
        let mut out = Vec::with_capacity(lhs.len() + rhs.len());
        let mut left = lhs.into_iter();
        let mut a = left.next();
        let mut j = 0;
        while let Some((am, ac)) = a.take() {
            let Some((bm, bc)) = rhs.get(j) else {
                out.push((am, ac));
                break;
            };
            match am.cmp(bm) {
                Ordering::Less => {
                    out.push((am, ac));
                    a = left.next();
                }
                Ordering::Greater => {
                    out.push((bm.clone(), signed(bc)));
                    j += 1;
                    a = Some((am, ac));
                }
                Ordering::Equal => {
                    let s = if negate { ac - bc } else { ac + bc };
                    if !s.is_zero() {
                        out.push((am, s));
                    }
                    j += 1;
                    a = left.next();
                }
            }
        }
        out.extend(left);
        out.extend(rhs[j..].iter().map(|(m, c)| (m.clone(), signed(c))));
        Radical { terms: out }
    }

    fn mul_impl(&self, rhs: &Radical) -> Radical {
        if self.terms.is_empty() || rhs.terms.is_empty() {
            return Radical::default();
        }
        if let Some(c) = rhs.as_nonzero_rational() {
            return self.scale(c);
        }
        if let Some(c) = self.as_nonzero_rational() {
            return rhs.scale(c);
        }
        let mut v = Vec::with_capacity(self.terms.len() * rhs.terms.len());
        for (m1, c1) in &self.terms {
            for (m2, c2) in &rhs.terms {
                let (g, m) = mul_keys(m1, m2);
                let c = c1 * c2;
                v.push((m, if g.is_one() { c } else { c * g.to_rational() }));
            }
        }
        Radical::from_unsorted(v)
    }

    fn square_impl(&self) -> Radical {
        if let Some(c) = self.as_nonzero_rational() {
            return Radical::from(c.square());
        }
        let t = &self.terms;
        let mut v = Vec::with_capacity(t.len() * (t.len() + 1) / 2);
        let two = Rational::from_integer(2);
        for (i, (m1, c1)) in t.iter().enumerate() {
            // (c sqrt m)^2 = c^2 m
            v.push((Radicand::ONE, c1.square() * m1.to_rational()));
            for (m2, c2) in &t[i + 1..] {
                let (g, m) = mul_keys(m1, m2);
                let c = c1 * c2 * &two;
                v.push((m, if g.is_one() { c } else { c * g.to_rational() }));
            }
        }
        Radical::from_unsorted(v)
    }

    /// An integer `q > 1` that divides or is coprime to every radicand present (`None` for a
    /// rational value). It divides at least one radicand.
    fn pick_generator(&self) -> Option<Radicand> {
        let mut q = self
            .terms
            .iter()
            .map(|t| &t.0)
            .find(|m| !m.is_one())?
            .clone();
        'refine: loop {
            for (m, _) in &self.terms {
                if m.is_one() {
                    continue;
                }
                let g = q.gcd(m);
                if !g.is_one() && g != q {
                    q = g;
                    continue 'refine;
                }
            }
            return Some(q);
        }
    }

    /// `self = a + b sqrt(q)` with `a`, `b` free of `sqrt(q)` (for `q` from `pick_generator`).
    fn split(&self, q: &Radicand) -> (Radical, Radical) {
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for (m, c) in &self.terms {
            if q.divides(m) {
                b.push((m.div_exact(q), c.clone()));
            } else {
                a.push((m.clone(), c.clone()));
            }
        }
        // Division by a common divisor keeps the order: both lists stay sorted.
        (Radical { terms: a }, Radical { terms: b })
    }

    /// `self · sqrt(q)` for a `self` whose radicands are all coprime to `q`.
    fn mul_sqrt_coprime(mut self, q: &Radicand) -> Radical {
        for (m, _) in &mut self.terms {
            *m = m.mul_coprime(q);
        }
        // Multiplication by a common factor keeps the order.
        self
    }

    /// The norm `a^2 - q b^2` of `a + b sqrt q`.
    fn norm(a: &Radical, b: &Radical, q: &Radicand) -> Radical {
        a.square_impl() - b.square_impl().scale(&q.to_rational())
    }

    fn inv_impl(&self) -> Result<Radical, ZeroDivisor> {
        match self.terms.as_slice() {
            [] => Err(ZeroDivisor),
            // 1/(c sqrt m) = sqrt(m) / (c m)
            [(m, c)] => Ok(Radical {
                terms: vec![(m.clone(), (c * m.to_rational()).recip()?)],
            }),
            _ => {
                let q = self.pick_generator().ok_or(ZeroDivisor)?;
                let (a, b) = self.split(&q);
                let n_inv = Radical::norm(&a, &b, &q).inv_impl()?;
                let conj = a - b.mul_sqrt_coprime(&q);
                Ok(conj.mul_impl(&n_inv))
            }
        }
    }

    /// A floating-point sign filter: `Some(sign)` when the f64 evaluation is farther from zero
    /// than a rigorous bound on its error, `None` when it cannot decide.
    ///
    /// Each term `c sqrt(m)` is evaluated from correctly rounded conversions of the numerator,
    /// denominator and radicand (all below 2^1000, so no overflow or underflow), then a
    /// division, a square root and a product: a relative error below `8 u` (`u = 2^-53`), bounded
    /// here by `2^-48`. Summing `k` terms adds at most `k u` times the sum of their magnitudes.
    /// The decision threshold `(2^-46 + k 2^-51) sum |t_i|` is four times larger than that.
    fn sign_filter(&self) -> Option<Sign> {
        let (mut sum, mut mag) = (0.0f64, 0.0f64);
        for (m, c) in &self.terms {
            // Correctly rounded (no allocation for inline values); a huge or tiny value is
            // rejected below as not normal.
            let cf = c.to_f64();
            let t = if m.is_one() {
                cf
            } else {
                cf * m.to_f64_checked()?.sqrt()
            };
            if !t.is_normal() {
                return None;
            }
            sum += t;
            mag += t.abs();
        }
        let k = self.terms.len() as f64;
        let err = (2f64.powi(-46) + k * 2f64.powi(-51)) * mag;
        if sum > err {
            Some(Sign::Positive)
        } else if sum < -err {
            Some(Sign::Negative)
        } else {
            None
        }
    }

    fn sign_rec(&self, filtered: bool) -> Sign {
        let first = match self.terms.as_slice() {
            [] => return Sign::Zero,
            [(_, c)] => return c.signum(),
            [(_, c), ..] => c.signum(),
        };
        if self.terms.iter().all(|(_, c)| c.signum() == first) {
            return first;
        }
        if filtered {
            if let Some(s) = self.sign_filter() {
                return s;
            }
        }
        let Some(q) = self.pick_generator() else {
            return first; // unreachable: two or more terms include an irrational one
        };
        let (a, b) = self.split(&q);
        let (sa, sb) = (a.sign_rec(filtered), b.sign_rec(filtered));
        match (sa, sb) {
            (_, Sign::Zero) => sa,
            (Sign::Zero, _) => sb,
            _ if sa == sb => sa,
            // a and b sqrt q of opposite signs: |a| vs |b| sqrt q is decided by a^2 vs q b^2.
            _ => Radical::norm(&a, &b, &q).sign_rec(filtered) * sa,
        }
    }

    fn sqrt_impl(&self) -> Option<Radical> {
        if self.terms.is_empty() {
            return Some(Radical::default());
        }
        if let Some(c) = self.as_nonzero_rational() {
            return Radical::sqrt_rational(c);
        }
        if self.sign_rec(true) != Sign::Positive {
            return None;
        }
        let q = self.pick_generator()?;
        let (a, b) = self.split(&q);
        let n = Radical::norm(&a, &b, &q).sqrt_impl()?;
        // The root of the norm must lie in the field of a and b (radicands built from their
        // primes only); otherwise sqrt(self) is not multi-quadratic (see the module docs).
        let mut l = Radicand::ONE;
        for (m, _) in a.terms.iter().chain(b.terms.iter()) {
            let g = l.gcd(m);
            l = l.mul_coprime(&m.div_exact(&g));
        }
        if !n.terms.iter().all(|(k, _)| k.divides(&l)) {
            return None;
        }
        let half = Rational::new(1, 2).ok()?;
        let u = (&a + &n).scale(&half).sqrt_impl()?;
        let v = (&a - &n).scale(&half).sqrt_impl()?;
        let y = if b.sign_rec(true) == Sign::Negative {
            u - v
        } else {
            u + v
        };
        (y.sign_rec(true) != Sign::Negative && y.square_impl() == *self).then_some(y)
    }

    // ------------------------------------------------------------------ operator bodies

    fn add_owned(self, rhs: &Radical) -> Radical {
        Radical::add_terms(self.terms, &rhs.terms, false)
    }
    fn add_borrowed(&self, rhs: &Radical) -> Radical {
        if self.terms.len() < rhs.terms.len() {
            Radical::add_terms(rhs.terms.clone(), &self.terms, false)
        } else {
            Radical::add_terms(self.terms.clone(), &rhs.terms, false)
        }
    }
    fn sub_owned(self, rhs: &Radical) -> Radical {
        Radical::add_terms(self.terms, &rhs.terms, true)
    }
    fn sub_borrowed(&self, rhs: &Radical) -> Radical {
        Radical::add_terms(self.terms.clone(), &rhs.terms, true)
    }
    fn mul_owned(self, rhs: &Radical) -> Radical {
        self.mul_impl(rhs)
    }
    fn mul_borrowed(&self, rhs: &Radical) -> Radical {
        self.mul_impl(rhs)
    }
    fn div_owned(self, rhs: &Radical) -> Radical {
        self.div_borrowed(rhs)
    }
    fn div_borrowed(&self, rhs: &Radical) -> Radical {
        match rhs.inv_impl() {
            Ok(r) => self.mul_impl(&r),
            Err(_) => panic!("Radical division by zero (use Field::checked_div to handle it)"),
        }
    }
    fn neg_borrowed(&self) -> Radical {
        Radical {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), -c)).collect(),
        }
    }
    fn neg_in_place(mut self) -> Radical {
        for (_, c) in &mut self.terms {
            *c = -std::mem::take(c);
        }
        self
    }
}

// ====================================================================== operator plumbing

macro_rules! binop {
    ($t:ty, $tr:ident, $m:ident, $atr:ident, $am:ident, $own:ident, $borrow:ident) => {
        impl<'b> $tr<&'b $t> for $t {
            type Output = $t;
            fn $m(self, rhs: &'b $t) -> $t {
                <$t>::$own(self, rhs)
            }
        }
        impl $tr<$t> for $t {
            type Output = $t;
            fn $m(self, rhs: $t) -> $t {
                <$t>::$own(self, &rhs)
            }
        }
        impl<'a, 'b> $tr<&'b $t> for &'a $t {
            type Output = $t;
            fn $m(self, rhs: &'b $t) -> $t {
                <$t>::$borrow(self, rhs)
            }
        }
        impl<'a> $tr<$t> for &'a $t {
            type Output = $t;
            fn $m(self, rhs: $t) -> $t {
                <$t>::$borrow(self, &rhs)
            }
        }
        impl<'b> $atr<&'b $t> for $t {
            fn $am(&mut self, rhs: &'b $t) {
                *self = <$t>::$own(std::mem::take(self), rhs);
            }
        }
        impl $atr<$t> for $t {
            fn $am(&mut self, rhs: $t) {
                *self = <$t>::$own(std::mem::take(self), &rhs);
            }
        }
    };
}

macro_rules! field_ops {
    ($t:ty) => {
        binop!($t, Add, add, AddAssign, add_assign, add_owned, add_borrowed);
        binop!($t, Sub, sub, SubAssign, sub_assign, sub_owned, sub_borrowed);
        binop!($t, Mul, mul, MulAssign, mul_assign, mul_owned, mul_borrowed);
        binop!($t, Div, div, DivAssign, div_assign, div_owned, div_borrowed);
        impl Neg for $t {
            type Output = $t;
            fn neg(self) -> $t {
                self.neg_in_place()
            }
        }
        impl Neg for &$t {
            type Output = $t;
            fn neg(self) -> $t {
                self.neg_borrowed()
            }
        }
    };
}

field_ops!(Radical);
field_ops!(ComplexRadical);

// ====================================================================== scalar traits

impl Ring for Radical {
    fn zero() -> Self {
        Radical::default()
    }
    fn one() -> Self {
        Radical::from(Rational::ONE)
    }
    fn from_i64(n: i64) -> Self {
        Radical::from(Rational::from_integer(n))
    }
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
    fn is_one(&self) -> bool {
        self.as_nonzero_rational().is_some_and(|c| c.is_one())
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_borrowed(rhs)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.sub_borrowed(rhs)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(rhs)
    }
    fn neg_ref(&self) -> Self {
        -self
    }
    fn square(&self) -> Self {
        self.square_impl()
    }
}

impl Field for Radical {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        self.inv_impl()
    }
    fn checked_div(&self, rhs: &Self) -> Result<Self, ZeroDivisor> {
        Ok(self.mul_impl(&rhs.inv_impl()?))
    }
}

impl OrderedField for Radical {
    fn sign(&self) -> Sign {
        self.sign_rec(true)
    }
}

impl PartialOrd for Radical {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Radical {
    /// The exact numeric order (the sign of the difference).
    fn cmp(&self, other: &Self) -> Ordering {
        if let (Some(a), Some(b)) = (self.to_rational(), other.to_rational()) {
            return a.cmp(&b);
        }
        match self.sub_borrowed(other).sign_rec(true) {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        }
    }
}

impl Sqrt for Radical {
    /// The non-negative square root when it is multi-quadratic: `sqrt(8) = 2 sqrt(2)`,
    /// `sqrt(3 - 2 sqrt(2)) = sqrt(2) - 1`, `sqrt(2 + sqrt(3)) = (sqrt(2) + sqrt(6))/2`; `None`
    /// for negative values, for values such as `sqrt(2)` whose root is not multi-quadratic, and
    /// for rationals whose factorization is out of reach (see [`Radical::sqrt_rational`]).
    fn sqrt(&self) -> Option<Self> {
        self.sqrt_impl()
    }
}

impl From<Rational> for Radical {
    fn from(q: Rational) -> Self {
        if q.is_zero() {
            Radical::default()
        } else {
            Radical {
                terms: vec![(Radicand::ONE, q)],
            }
        }
    }
}

impl From<&Rational> for Radical {
    fn from(q: &Rational) -> Self {
        Radical::from(q.clone())
    }
}

impl From<i64> for Radical {
    fn from(n: i64) -> Self {
        Radical::from(Rational::from_integer(n))
    }
}

// ====================================================================== printing

/// Writes `|c| sqrt(m)` as `n`, `n/d`, `sqrt(m)`, `n*sqrt(m)`, `sqrt(m)/d` or `n*sqrt(m)/d`.
fn write_abs_term(f: &mut fmt::Formatter<'_>, m: &Radicand, c: &Rational) -> fmt::Result {
    let n = c.numer().into_parts().1;
    let d = c.denom().into_parts().1;
    if m.is_one() {
        write!(f, "{n}")?;
    } else {
        if !n.is_one() {
            write!(f, "{n}*")?;
        }
        m.write_sqrt(f)?;
    }
    if !d.is_one() {
        write!(f, "/{d}")?;
    }
    Ok(())
}

impl fmt::Display for Radical {
    /// The number syntax of DESIGN.md, terms by increasing radicand:
    /// `1/2 + 3*sqrt(2) - sqrt(6)/3`; `0` for zero. [`FromStr`] reads it back.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return f.write_str("0");
        }
        for (i, (m, c)) in self.terms.iter().enumerate() {
            let negative = c.signum() == Sign::Negative;
            match (i, negative) {
                (0, true) => f.write_str("-")?,
                (0, false) => {}
                (_, true) => f.write_str(" - ")?,
                (_, false) => f.write_str(" + ")?,
            }
            write_abs_term(f, m, c)?;
        }
        Ok(())
    }
}

impl fmt::Debug for Radical {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

// ====================================================================== complex radicals

/// A Gaussian multi-quadratic number `re + im i` (`i = sqrt(-1)`), for the conjugate-imaginary
/// focal lines of Juttler's Satz 5 (SPEC.md §1). A field, not ordered. Canonical whenever its
/// parts are, so `==` is equality.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct ComplexRadical {
    /// The real part.
    pub re: Radical,
    /// The imaginary part.
    pub im: Radical,
}

impl ComplexRadical {
    /// `re + im i`.
    pub fn new(re: Radical, im: Radical) -> ComplexRadical {
        ComplexRadical { re, im }
    }

    /// The imaginary unit `i`.
    pub fn i() -> ComplexRadical {
        ComplexRadical {
            re: Radical::default(),
            im: Radical::one(),
        }
    }

    /// The complex conjugate `re - im i`.
    pub fn conj(&self) -> ComplexRadical {
        ComplexRadical {
            re: self.re.clone(),
            im: -&self.im,
        }
    }

    /// The squared modulus `re^2 + im^2` (a non-negative [`Radical`], zero only for zero).
    pub fn norm_sqr(&self) -> Radical {
        self.re.square_impl() + self.im.square_impl()
    }

    /// Whether the imaginary part is zero.
    pub fn is_real(&self) -> bool {
        self.im.is_zero()
    }

    /// The principal square root (real part positive, or zero with a non-negative imaginary
    /// part) when it is a Gaussian multi-quadratic number: `sqrt(-2) = sqrt(2) i`,
    /// `sqrt(2 i) = 1 + i`. `None` otherwise.
    pub fn principal_sqrt(&self) -> Option<ComplexRadical> {
        if self.im.is_zero() {
            return Some(if self.re.sign() == Sign::Negative {
                ComplexRadical::new(Radical::default(), (-&self.re).sqrt_impl()?)
            } else {
                ComplexRadical::from(self.re.sqrt_impl()?)
            });
        }
        let modulus = self.norm_sqr().sqrt_impl()?;
        let half = Rational::new(1, 2).ok()?;
        let u = (&modulus + &self.re).scale(&half).sqrt_impl()?;
        let v = (&modulus - &self.re).scale(&half).sqrt_impl()?;
        let v = if self.im.sign() == Sign::Negative {
            -v
        } else {
            v
        };
        let y = ComplexRadical::new(u, v);
        (y.square() == *self).then_some(y)
    }

    fn mul_borrowed(&self, rhs: &ComplexRadical) -> ComplexRadical {
        let re = self.re.mul_impl(&rhs.re) - self.im.mul_impl(&rhs.im);
        let im = self.re.mul_impl(&rhs.im) + self.im.mul_impl(&rhs.re);
        ComplexRadical { re, im }
    }
    fn mul_owned(self, rhs: &ComplexRadical) -> ComplexRadical {
        self.mul_borrowed(rhs)
    }
    fn add_owned(self, rhs: &ComplexRadical) -> ComplexRadical {
        ComplexRadical {
            re: self.re + &rhs.re,
            im: self.im + &rhs.im,
        }
    }
    fn add_borrowed(&self, rhs: &ComplexRadical) -> ComplexRadical {
        self.clone().add_owned(rhs)
    }
    fn sub_owned(self, rhs: &ComplexRadical) -> ComplexRadical {
        ComplexRadical {
            re: self.re - &rhs.re,
            im: self.im - &rhs.im,
        }
    }
    fn sub_borrowed(&self, rhs: &ComplexRadical) -> ComplexRadical {
        self.clone().sub_owned(rhs)
    }
    fn inv_impl(&self) -> Result<ComplexRadical, ZeroDivisor> {
        let n = self.norm_sqr().inv_impl()?;
        Ok(ComplexRadical {
            re: self.re.mul_impl(&n),
            im: -self.im.mul_impl(&n),
        })
    }
    fn div_borrowed(&self, rhs: &ComplexRadical) -> ComplexRadical {
        match rhs.inv_impl() {
            Ok(r) => self.mul_borrowed(&r),
            Err(_) => {
                panic!("ComplexRadical division by zero (use Field::checked_div to handle it)")
            }
        }
    }
    fn div_owned(self, rhs: &ComplexRadical) -> ComplexRadical {
        self.div_borrowed(rhs)
    }
    fn neg_borrowed(&self) -> ComplexRadical {
        ComplexRadical {
            re: self.re.neg_borrowed(),
            im: self.im.neg_borrowed(),
        }
    }
    fn neg_in_place(self) -> ComplexRadical {
        ComplexRadical {
            re: -self.re,
            im: -self.im,
        }
    }
}

impl Ring for ComplexRadical {
    fn zero() -> Self {
        ComplexRadical::default()
    }
    fn one() -> Self {
        ComplexRadical::from(Radical::one())
    }
    fn from_i64(n: i64) -> Self {
        ComplexRadical::from(Radical::from(n))
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_borrowed(rhs)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.sub_borrowed(rhs)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_borrowed(rhs)
    }
    fn neg_ref(&self) -> Self {
        -self
    }
    fn square(&self) -> Self {
        // (a + b i)^2 = a^2 - b^2 + 2ab i
        let ab = self.re.mul_impl(&self.im);
        ComplexRadical {
            re: self.re.square_impl() - self.im.square_impl(),
            im: ab.scale(&Rational::from_integer(2)),
        }
    }
}

impl Field for ComplexRadical {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        self.inv_impl()
    }
    fn checked_div(&self, rhs: &Self) -> Result<Self, ZeroDivisor> {
        Ok(self.mul_borrowed(&rhs.inv_impl()?))
    }
}

impl Sqrt for ComplexRadical {
    /// The principal square root, see [`ComplexRadical::principal_sqrt`].
    fn sqrt(&self) -> Option<Self> {
        self.principal_sqrt()
    }
}

impl From<Radical> for ComplexRadical {
    fn from(re: Radical) -> Self {
        ComplexRadical {
            re,
            im: Radical::default(),
        }
    }
}

impl From<Rational> for ComplexRadical {
    fn from(q: Rational) -> Self {
        ComplexRadical::from(Radical::from(q))
    }
}

impl fmt::Display for ComplexRadical {
    /// `re + im*i` in the number syntax: `1/2 - sqrt(3)/2*i`, `(1 + sqrt(2))*i`, `i`, `-i`; a
    /// real value prints as a [`Radical`]. [`FromStr`] reads it back.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.im.is_zero() {
            return fmt::Display::fmt(&self.re, f);
        }
        let has_re = !self.re.is_zero();
        if has_re {
            fmt::Display::fmt(&self.re, f)?;
        }
        match self.im.terms.as_slice() {
            [(m, c)] => {
                let negative = c.signum() == Sign::Negative;
                f.write_str(match (has_re, negative) {
                    (true, true) => " - ",
                    (true, false) => " + ",
                    (false, true) => "-",
                    (false, false) => "",
                })?;
                if m.is_one() && (c.is_one() || (-c).is_one()) {
                    f.write_str("i")
                } else {
                    write_abs_term(f, m, c)?;
                    f.write_str("*i")
                }
            }
            _ => {
                if has_re {
                    f.write_str(" + ")?;
                }
                write!(f, "({})*i", self.im)
            }
        }
    }
}

impl fmt::Debug for ComplexRadical {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

// ====================================================================== parsing

/// The error of parsing a [`Radical`] or [`ComplexRadical`] expression. Positions are 0-based
/// byte offsets into the input.
///
/// ```
/// use exactcheck_exact::radical::{ParseRadicalError as E, Radical};
///
/// let parse = |s: &str| s.parse::<Radical>().unwrap_err();
/// assert!(matches!(parse("2 * * 3"), E::Unexpected { pos: 4, .. }));
/// assert!(matches!(parse("(1 + 2"), E::UnexpectedEnd { pos: 6, .. }));
/// assert!(matches!(parse("cos(1)"), E::UnknownName { pos: 0, .. }));
/// assert!(matches!(parse("1/(2 - 2)"), E::DivisionByZero { pos: 1 }));
/// assert!(matches!(parse("sqrt(-2)"), E::NoSquareRoot { pos: 0, .. }));
/// assert!(matches!(parse("2^1.5"), E::Unexpected { .. }));
/// assert!(matches!(parse("2^99999"), E::BadExponent { pos: 2 }));
/// assert!(matches!(parse(&"-".repeat(200)), E::TooDeep { .. }));
/// assert_eq!(
///     parse("sqrt(-2)").to_string(),
///     "sqrt at position 0: -2 has no square root in this number type"
/// );
/// ```
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ParseRadicalError {
    /// A character that cannot continue the expression here.
    #[error("unexpected {found:?} at position {pos}: expected {expected}")]
    Unexpected {
        /// Where.
        pos: usize,
        /// The offending character.
        found: String,
        /// What would have been accepted.
        expected: &'static str,
    },
    /// The input ended too early.
    #[error("unexpected end of input at position {pos}: expected {expected}")]
    UnexpectedEnd {
        /// Where (the input's length).
        pos: usize,
        /// What would have been accepted.
        expected: &'static str,
    },
    /// A name other than `sqrt` (and `i` for complex numbers).
    #[error("unknown name {name:?} at position {pos}")]
    UnknownName {
        /// Where.
        pos: usize,
        /// The name.
        name: String,
    },
    /// A division by zero (or a negative power of zero).
    #[error("division by zero at position {pos}")]
    DivisionByZero {
        /// The position of the `/` or `^`.
        pos: usize,
    },
    /// `sqrt(k)` where the root of `k` is not in the number type (negative for a real type,
    /// not multi-quadratic, or with a radicand too large to factor).
    #[error("sqrt at position {pos}: {radicand} has no square root in this number type")]
    NoSquareRoot {
        /// The position of `sqrt`.
        pos: usize,
        /// The value under the root, printed.
        radicand: String,
    },
    /// An exponent beyond `±1024` or not an integer.
    #[error("exponent at position {pos} must be an integer in -1024..=1024")]
    BadExponent {
        /// Where the exponent starts.
        pos: usize,
    },
    /// Parentheses or unary signs nested more than 128 deep.
    #[error("expression nested too deeply at position {pos}")]
    TooDeep {
        /// Where the limit was hit.
        pos: usize,
    },
}

/// What the expression parser needs from a number type.
trait ParseTarget: Field + fmt::Display {
    fn from_rational(q: Rational) -> Self;
    fn root(&self) -> Option<Self>;
    fn imaginary_unit() -> Option<Self>;
}

impl ParseTarget for Radical {
    fn from_rational(q: Rational) -> Self {
        Radical::from(q)
    }
    fn root(&self) -> Option<Self> {
        self.sqrt_impl()
    }
    fn imaginary_unit() -> Option<Self> {
        None
    }
}

impl ParseTarget for ComplexRadical {
    fn from_rational(q: Rational) -> Self {
        ComplexRadical::from(q)
    }
    fn root(&self) -> Option<Self> {
        self.principal_sqrt()
    }
    fn imaginary_unit() -> Option<Self> {
        Some(ComplexRadical::i())
    }
}

const MAX_DEPTH: usize = 128;
const OPERAND: &str = "a number, sqrt(...), or '('";

/// Recursive-descent parser:
/// `expr = term (('+'|'-') term)*`, `term = unary (('*'|'/') unary)*`,
/// `unary = ('-'|'+') unary | power`, `power = atom ('^' integer)?`,
/// `atom = number | 'sqrt' '(' expr ')' | 'i' | '(' expr ')'`.
struct Parser<'s> {
    src: &'s str,
    pos: usize,
    depth: usize,
}

impl<'s> Parser<'s> {
    fn new(src: &'s str) -> Self {
        Parser {
            src,
            pos: 0,
            depth: 0,
        }
    }

    fn skip_ws(&mut self) {
        while let Some(c) = self.src[self.pos..].chars().next() {
            if !c.is_whitespace() {
                break;
            }
            self.pos += c.len_utf8();
        }
    }

    fn peek(&mut self) -> Option<char> {
        self.skip_ws();
        self.src[self.pos..].chars().next()
    }

    fn error_here(&self, expected: &'static str) -> ParseRadicalError {
        match self.src[self.pos..].chars().next() {
            Some(c) => ParseRadicalError::Unexpected {
                pos: self.pos,
                found: c.to_string(),
                expected,
            },
            None => ParseRadicalError::UnexpectedEnd {
                pos: self.pos,
                expected,
            },
        }
    }

    fn expect(&mut self, ch: char, expected: &'static str) -> Result<(), ParseRadicalError> {
        if self.peek() == Some(ch) {
            self.pos += 1;
            Ok(())
        } else {
            Err(self.error_here(expected))
        }
    }

    fn enter(&mut self) -> Result<(), ParseRadicalError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            Err(ParseRadicalError::TooDeep { pos: self.pos })
        } else {
            Ok(())
        }
    }

    fn parse_all<T: ParseTarget>(mut self) -> Result<T, ParseRadicalError> {
        let v = self.expr::<T>()?;
        if self.peek().is_some() {
            return Err(self.error_here("an operator or the end of the input"));
        }
        Ok(v)
    }

    fn expr<T: ParseTarget>(&mut self) -> Result<T, ParseRadicalError> {
        let mut acc = self.term::<T>()?;
        loop {
            match self.peek() {
                Some('+') => {
                    self.pos += 1;
                    acc += self.term::<T>()?;
                }
                Some('-') => {
                    self.pos += 1;
                    acc -= self.term::<T>()?;
                }
                _ => return Ok(acc),
            }
        }
    }

    fn term<T: ParseTarget>(&mut self) -> Result<T, ParseRadicalError> {
        let mut acc = self.unary::<T>()?;
        loop {
            match self.peek() {
                Some('*') => {
                    self.pos += 1;
                    acc *= self.unary::<T>()?;
                }
                Some('/') => {
                    let at = self.pos;
                    self.pos += 1;
                    let d = self.unary::<T>()?;
                    acc = acc
                        .checked_div(&d)
                        .map_err(|_| ParseRadicalError::DivisionByZero { pos: at })?;
                }
                _ => return Ok(acc),
            }
        }
    }

    fn unary<T: ParseTarget>(&mut self) -> Result<T, ParseRadicalError> {
        match self.peek() {
            Some(c @ ('-' | '+')) => {
                self.pos += 1;
                self.enter()?;
                let v = self.unary::<T>()?;
                self.depth -= 1;
                Ok(if c == '-' { -v } else { v })
            }
            _ => self.power::<T>(),
        }
    }

    fn power<T: ParseTarget>(&mut self) -> Result<T, ParseRadicalError> {
        let base = self.atom::<T>()?;
        if self.peek() != Some('^') {
            return Ok(base);
        }
        let at = self.pos;
        self.pos += 1;
        self.skip_ws();
        let start = self.pos;
        let negative = match self.peek() {
            Some('-') => {
                self.pos += 1;
                true
            }
            Some('+') => {
                self.pos += 1;
                false
            }
            _ => false,
        };
        self.skip_ws();
        let digits_start = self.pos;
        while self.src[self.pos..].starts_with(|c: char| c.is_ascii_digit()) {
            self.pos += 1;
        }
        let e: u32 = self.src[digits_start..self.pos]
            .parse()
            .ok()
            .filter(|e| *e <= 1024)
            .ok_or(ParseRadicalError::BadExponent { pos: start })?;
        let p = base.pow(e);
        if negative {
            p.inv()
                .map_err(|_| ParseRadicalError::DivisionByZero { pos: at })
        } else {
            Ok(p)
        }
    }

    fn atom<T: ParseTarget>(&mut self) -> Result<T, ParseRadicalError> {
        match self.peek() {
            Some('(') => {
                self.pos += 1;
                self.enter()?;
                let v = self.expr::<T>()?;
                self.expect(')', "')'")?;
                self.depth -= 1;
                Ok(v)
            }
            Some(c) if c.is_ascii_digit() => {
                let start = self.pos;
                let rest = &self.src[start..];
                let int_len = rest
                    .find(|c: char| !c.is_ascii_digit())
                    .unwrap_or(rest.len());
                let mut end = start + int_len;
                if self.src[end..].starts_with('.') {
                    let frac = &self.src[end + 1..];
                    let frac_len = frac
                        .find(|c: char| !c.is_ascii_digit())
                        .unwrap_or(frac.len());
                    if frac_len == 0 {
                        self.pos = end + 1;
                        return Err(self.error_here("digits after the decimal point"));
                    }
                    end += 1 + frac_len;
                }
                self.pos = end;
                let q: Rational = self.src[start..end]
                    .parse()
                    .map_err(|_| self.error_here("a number"))?;
                Ok(T::from_rational(q))
            }
            Some(c) if c.is_ascii_alphabetic() || c == '_' => {
                let start = self.pos;
                let rest = &self.src[start..];
                let len = rest
                    .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .unwrap_or(rest.len());
                let name = &rest[..len];
                self.pos = start + len;
                match name {
                    "sqrt" => {
                        self.expect('(', "'(' after sqrt")?;
                        self.enter()?;
                        let k = self.expr::<T>()?;
                        self.expect(')', "')'")?;
                        self.depth -= 1;
                        k.root().ok_or_else(|| ParseRadicalError::NoSquareRoot {
                            pos: start,
                            radicand: k.to_string(),
                        })
                    }
                    "i" => T::imaginary_unit().ok_or_else(|| ParseRadicalError::UnknownName {
                        pos: start,
                        name: name.to_string(),
                    }),
                    _ => Err(ParseRadicalError::UnknownName {
                        pos: start,
                        name: name.to_string(),
                    }),
                }
            }
            _ => Err(self.error_here(OPERAND)),
        }
    }
}

impl FromStr for Radical {
    type Err = ParseRadicalError;

    /// Parses the number syntax of DESIGN.md: integers, decimals (`0.1` is exactly 1/10),
    /// `sqrt(...)` of any expression with a multi-quadratic root, `+ - * /`, unary signs,
    /// parentheses and integer powers `^k` (`|k| <= 1024`) — e.g. `"1/sqrt(2)"`,
    /// `"(2+sqrt(2))/3"`, `"sqrt(3 - 2*sqrt(2))"`, `"-3/4"`.
    ///
    /// # Errors
    /// A [`ParseRadicalError`] naming the problem and its position: malformed input, unknown
    /// names (including `i`: use [`ComplexRadical`]), division by zero, a square root not in the
    /// type (`sqrt(-1)`, `sqrt(sqrt(2))`).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Parser::new(s).parse_all::<Radical>()
    }
}

impl FromStr for ComplexRadical {
    type Err = ParseRadicalError;

    /// Parses the syntax of [`Radical`]'s `FromStr` with the imaginary unit as `i` or
    /// `sqrt(-1)`; `sqrt` takes the principal root (`sqrt(-4) = 2*i`).
    ///
    /// # Errors
    /// As for [`Radical`]; `sqrt(z)` fails when the principal root of `z` is not a Gaussian
    /// multi-quadratic number.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Parser::new(s).parse_all::<ComplexRadical>()
    }
}

// ====================================================================== unit tests

impl crate::expr::Coefficient for Radical {
    fn from_rational(q: &Rational) -> Option<Self> {
        Some(Radical::from(q))
    }
    fn try_inverse(&self) -> Option<Self> {
        self.inv().ok()
    }
    fn try_sqrt(&self) -> Option<Self> {
        Sqrt::sqrt(self)
    }
    fn sqrt_hint() -> &'static str {
        " (no square root in the square-root field: negative, or not denestable)"
    }
}

impl crate::expr::Coefficient for ComplexRadical {
    fn from_rational(q: &Rational) -> Option<Self> {
        Some(ComplexRadical::from(q.clone()))
    }
    fn try_inverse(&self) -> Option<Self> {
        self.inv().ok()
    }
    fn try_sqrt(&self) -> Option<Self> {
        self.principal_sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(s: &str) -> Radical {
        s.parse().unwrap_or_else(|e| panic!("{s:?}: {e}"))
    }

    #[test]
    fn factorization() {
        assert_eq!(square_free_u64(1), (1, 1));
        assert_eq!(square_free_u64(12), (2, 3));
        assert_eq!(square_free_u64(72), (6, 2));
        let p = 4_294_967_311u64; // prime above 2^32
        assert!(is_prime_u64(p));
        assert_eq!(square_free_u64(p), (1, p));
        let q = 1_000_000_007u64;
        assert_eq!(square_free_u64(q * q), (q, 1));
        assert_eq!(square_free_u64(q * 1_000_000_009), (1, q * 1_000_000_009));
        assert_eq!(
            square_free_u64(9 * 1_048_583 * 1_048_583),
            (3 * 1_048_583, 1)
        );
        assert!(!is_prime_u64(3_215_031_751)); // strong pseudoprime to bases 2, 3, 5, 7
        assert!(is_prime_u64(u64::MAX - 58)); // the largest 64-bit prime
    }

    #[test]
    fn big_radicands() {
        // (2^61 - 1)^2 * 3: beyond u64, square part found by trial division then rho.
        let p = BigUint::from((1u64 << 61) - 1);
        let n = &p * &p * 3u32;
        let (s, f) = square_free_big(&n).expect("certified");
        assert_eq!(s, p);
        assert_eq!(f.as_u64(), Some(3));
        // A product of two 64-bit primes: beyond reach, and not a square.
        let a = BigUint::from(u64::MAX - 58);
        assert!(is_prime_u64(18_446_744_073_709_551_533));
        let b = BigUint::from(18_446_744_073_709_551_533u64);
        assert!(square_free_big(&(&a * &b)).is_none());
        assert!(square_free_big(&(&a * &a)).is_some());
    }

    #[test]
    fn products_of_big_radicands_do_not_overflow() {
        let p = Radical::sqrt_of(u64::MAX - 58);
        let q = Radical::sqrt_of(18_446_744_073_709_551_533);
        let pq = &p * &q;
        assert!(pq.terms()[0].0.as_u64().is_none());
        assert!(pq.is_canonical());
        let back = &pq * &p;
        assert_eq!(back, q.scale(&integer_u64(u64::MAX - 58)));
        assert!((&pq * &pq).to_rational().is_some());
        assert_eq!(pq.inv().unwrap() * &pq, Radical::one());
        // Printed as sqrt(a)*sqrt(b) with 64-bit factors, so it parses back.
        assert_eq!(pq.to_string().parse::<Radical>(), Ok(pq.clone()));
        assert!(pq.to_string().contains("*sqrt("));
    }

    #[test]
    fn printing() {
        assert_eq!(
            r("1/2 + 3*sqrt(2) - sqrt(6)/3").to_string(),
            "1/2 + 3*sqrt(2) - sqrt(6)/3"
        );
        assert_eq!(r("-sqrt(8)").to_string(), "-2*sqrt(2)");
        assert_eq!(r("0").to_string(), "0");
        assert_eq!(r("-2/3*sqrt(5)").to_string(), "-2*sqrt(5)/3");
    }

    #[test]
    fn denesting() {
        assert_eq!(r("sqrt(2 + sqrt(3))"), r("(sqrt(2) + sqrt(6))/2"));
        assert_eq!(r("sqrt(5 + 2*sqrt(6))"), r("sqrt(2) + sqrt(3)"));
        assert_eq!(r("sqrt(9 + 6*sqrt(2))"), r("sqrt(3) + sqrt(6)"));
        assert!(r("sqrt(2)").sqrt().is_none());
        assert!(r("1 + sqrt(2)").sqrt().is_none());
        assert!(r("1 - sqrt(2)").sqrt().is_none());
    }

    #[test]
    fn filter_agrees_with_exact() {
        let x = r("sqrt(2) + sqrt(3)");
        let close: Rational = "3.1462643699419726".parse().unwrap();
        let d = &x - &Radical::from(close);
        assert_eq!(d.sign_filter(), None);
        assert_eq!(d.sign(), d.sign_exact());
        assert_eq!(r("sqrt(2) - 1").sign_filter(), Some(Sign::Positive));
    }

    #[test]
    fn parse_errors() {
        use ParseRadicalError as E;
        assert!(matches!(
            "1/0".parse::<Radical>(),
            Err(E::DivisionByZero { pos: 1 })
        ));
        assert!(matches!(
            "sqrt(-1)".parse::<Radical>(),
            Err(E::NoSquareRoot { pos: 0, .. })
        ));
        assert!(matches!("i".parse::<Radical>(), Err(E::UnknownName { .. })));
        assert!(matches!(
            "2 +".parse::<Radical>(),
            Err(E::UnexpectedEnd { pos: 3, .. })
        ));
        assert!(matches!(
            "2 3".parse::<Radical>(),
            Err(E::Unexpected { pos: 2, .. })
        ));
        assert!(matches!(
            "1.".parse::<Radical>(),
            Err(E::UnexpectedEnd { .. })
        ));
        assert!(matches!(
            "(1".parse::<Radical>(),
            Err(E::UnexpectedEnd { .. })
        ));
        assert!(matches!(
            "2^2000".parse::<Radical>(),
            Err(E::BadExponent { .. })
        ));
        assert!(matches!(
            "0^-1".parse::<Radical>(),
            Err(E::DivisionByZero { .. })
        ));
        let deep = "(".repeat(500) + "1" + &")".repeat(500);
        assert!(matches!(deep.parse::<Radical>(), Err(E::TooDeep { .. })));
        assert!(matches!(
            "".parse::<Radical>(),
            Err(E::UnexpectedEnd { pos: 0, .. })
        ));
        assert!(matches!(
            "sqrt 2".parse::<Radical>(),
            Err(E::Unexpected { .. })
        ));
        assert!(matches!("é".parse::<Radical>(), Err(E::Unexpected { .. })));
    }
}
