//! Radicands and square-free factoring: the positive square-free integers `m` of the basis
//! elements `sqrt(m)`, and the number theory that extracts the square part of an integer (trial
//! division, Miller–Rabin, Pollard–Brent rho for 64-bit cofactors). Hand-written because no
//! dependency of the workspace factors integers, and the sizes here (64-bit factors) are served
//! well by these textbook algorithms.

use crate::gcd::{gcd_biguint_u64, gcd_u64};
use crate::modp::is_prime_u64;
use crate::rational::Rational;
use num_bigint::{BigInt, BigUint, Sign as BigSign};
use num_integer::Integer;
use num_traits::{One, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;

// ====================================================================== radicands

/// A positive square-free integer, the `m` of a basis element `sqrt(m)` of a [`Radical`](super::Radical)
/// (`1` for the rational part).
///
/// Held inline when it fits a `u64`. Larger radicands (products of several large ones) are held
/// as a big integer together with a list of pairwise coprime, square-free 64-bit factors, so that
/// no operation overflows and every radicand can be printed in a form that parses back
/// (`sqrt(a)*sqrt(b)` with 64-bit `a`, `b`). The order is the numeric order.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Radicand(pub(super) Rd);

/// Invariant: `Small` exactly when the value fits a `u64`; the derived order of the variants
/// (`Small` first) is then the numeric order.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(super) enum Rd {
    Small(u64),
    Big(Box<BigKey>),
}

/// A radicand beyond 64 bits: its value and a factorization into pairwise coprime, square-free
/// 64-bit factors (not unique, so equality, hashing and order look at the value only).
#[derive(Clone)]
pub(super) struct BigKey {
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
    pub(super) fn factors(&self) -> &[u64] {
        match &self.0 {
            Rd::Small(v) => std::slice::from_ref(v),
            Rd::Big(b) => &b.factors,
        }
    }

    /// The product of pairwise coprime, square-free factors.
    pub(super) fn from_factors(mut factors: Vec<u64>) -> Radicand {
        factors.retain(|&f| f > 1);
        let value = factors
            .iter()
            .fold(BigUint::one(), |acc, &f| acc * BigUint::from(f));
        match value.to_u64() {
            Some(v) => Radicand(Rd::Small(v)),
            None => Radicand(Rd::Big(Box::new(BigKey { value, factors }))),
        }
    }

    pub(super) fn gcd(&self, o: &Radicand) -> Radicand {
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
    pub(super) fn div_exact(&self, o: &Radicand) -> Radicand {
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
    pub(super) fn mul_coprime(&self, o: &Radicand) -> Radicand {
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
    pub(super) fn divides(&self, o: &Radicand) -> bool {
        match (&self.0, &o.0) {
            (Rd::Small(a), Rd::Small(b)) => b % a == 0,
            (Rd::Small(a), Rd::Big(b)) => gcd_biguint_u64(&b.value, *a) == Some(*a),
            (Rd::Big(_), Rd::Small(_)) => false,
            (Rd::Big(a), Rd::Big(b)) => (&b.value % &a.value).is_zero(),
        }
    }

    /// The value as a rational integer.
    pub(super) fn to_rational(&self) -> Rational {
        match &self.0 {
            Rd::Small(v) => integer_u64(*v),
            Rd::Big(b) => Rational::from(BigInt::from_biguint(BigSign::Plus, b.value.clone())),
        }
    }

    /// The value as an `f64` (correctly rounded), `None` from 2^1000 on.
    pub(super) fn to_f64_checked(&self) -> Option<f64> {
        match &self.0 {
            Rd::Small(v) => Some(*v as f64),
            Rd::Big(b) if b.value.bits() < 1000 => b.value.to_f64(),
            Rd::Big(_) => None,
        }
    }

    /// Whether the value is square-free and the representation consistent (certified by complete
    /// factorization of the 64-bit value or factors).
    pub(super) fn is_square_free(&self) -> bool {
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
    pub(super) fn write_sqrt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
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
pub(super) fn mul_keys(a: &Radicand, b: &Radicand) -> (Radicand, Radicand) {
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
pub(super) fn integer_u64(v: u64) -> Rational {
    match i64::try_from(v) {
        Ok(s) => Rational::from_integer(s),
        Err(_) => Rational::from(BigInt::from(v)),
    }
}

// ====================================================================== number theory
//
// Primality is `crate::modp::is_prime_u64` (deterministic Miller–Rabin), shared with the random
// primes of `prove --random`.

/// `a b mod m`.
#[inline]
pub(super) fn mul_mod(a: u64, b: u64, m: u64) -> u64 {
    ((a as u128 * b as u128) % m as u128) as u64
}

/// A non-trivial factor of an odd composite `n` with no prime factor below 2^10, by Pollard's rho
/// with Brent's cycle detection and batched gcds.
pub(super) fn pollard_brent(n: u64) -> u64 {
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
pub(super) fn factor_rho(n: u64, out: &mut Vec<u64>) {
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
pub(super) fn square_free_u64(n: u64) -> (u64, u64) {
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
pub(super) fn rem_u64(n: &BigUint, p: u64) -> u64 {
    n.iter_u32_digits()
        .rev()
        .fold(0u64, |r, d| ((r << 32) | d as u64) % p)
}

/// Divides the largest power of the prime `p` out of `c` (`c > 0`) and returns its exponent `e`,
/// with `O(log e)` big divisions: find the largest `J` with `p^(2^J) | c` by repeated squaring,
/// then divide by `p^(2^j)` for `j = J, J-1, ..., 0` where it still divides (each at most once,
/// since `e < 2^(J+1)`). Dividing by `p` once per factor would take `e` passes over `c`
/// (`2^999000 * 3` never finished).
pub(super) fn remove_prime_power(c: &mut BigUint, p: u64) -> u32 {
    let mut pows = vec![BigUint::from(p)];
    loop {
        let last = pows.last().expect("starts non-empty");
        if last.bits() * 2 > c.bits() + 1 {
            break;
        }
        let sq = last * last;
        if !(&*c % &sq).is_zero() {
            break;
        }
        pows.push(sq);
    }
    let mut e = 0u32;
    for (j, pj) in pows.iter().enumerate().rev() {
        let (q, r) = c.div_rem(pj);
        if r.is_zero() {
            *c = q;
            e += 1 << j;
        }
    }
    e
}

/// Trial-division bound for radicands beyond 64 bits.
pub(super) const TRIAL_BOUND: u64 = 1 << 20;

/// `n = s^2 f` with `f` square-free, for `n >= 1`; `None` when `f` cannot be certified square-free
/// (a cofactor beyond 64 bits, with no prime factor up to 2^20, that is not a perfect square).
pub(super) fn square_free_big(n: &BigUint) -> Option<(BigUint, Radicand)> {
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
            let e = remove_prime_power(&mut c, p);
            s *= BigUint::from(p).pow(e / 2);
            if e % 2 == 1 {
                free_primes.push(p);
            }
            // A cofactor that is now a perfect square ends the search: the common case of the
            // norms met in denesting, which would otherwise run the whole trial division.
            if c.bits() > 64 {
                let r = c.sqrt();
                if &r * &r == c {
                    return Some((s * r, Radicand::from_factors(free_primes)));
                }
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

// ====================================================================== independent radicals

/// The number of independent square roots among `radicands`: the rank `k` of the subgroup they
/// generate in `Q* / Q*^2`, so that `Q(sqrt m : m in radicands)` has dimension `2^k` over Q.
///
/// Computed without factoring: the 64-bit factors of the radicands are refined by gcds into a
/// coprime base `B` (pairwise coprime, square-free; every radicand is the product of the base
/// elements dividing it); distinct products of base elements are distinct square-free integers,
/// so the base elements are independent modulo squares and `k` is the rank over GF(2) of the
/// radicands' incidence vectors on `B` (Gaussian elimination on bit sets).
pub(super) fn independent_count<'a>(radicands: impl Iterator<Item = &'a Radicand>) -> usize {
    let radicands: Vec<&Radicand> = radicands.filter(|m| !m.is_one()).collect();
    let mut base: Vec<u64> = Vec::new();
    for m in &radicands {
        for &f in m.factors() {
            refine_base(&mut base, f);
        }
    }
    let words = base.len().div_ceil(64);
    // Reduced rows, each with its pivot bit (the lowest set bit).
    let mut rows: Vec<(usize, Vec<u64>)> = Vec::new();
    for m in &radicands {
        let mut v = vec![0u64; words];
        for (i, &b) in base.iter().enumerate() {
            if m.factors().iter().any(|&f| f % b == 0) {
                v[i / 64] |= 1 << (i % 64);
            }
        }
        for (pivot, row) in &rows {
            if v[pivot / 64] >> (pivot % 64) & 1 == 1 {
                for (x, y) in v.iter_mut().zip(row) {
                    *x ^= y;
                }
            }
        }
        let lowest = v
            .iter()
            .enumerate()
            .find(|(_, w)| **w != 0)
            .map(|(i, w)| i * 64 + w.trailing_zeros() as usize);
        if let Some(p) = lowest {
            // Keep the rows fully reduced: clear the new pivot from the earlier rows.
            for (_, row) in rows.iter_mut() {
                if row[p / 64] >> (p % 64) & 1 == 1 {
                    for (x, y) in row.iter_mut().zip(&v) {
                        *x ^= y;
                    }
                }
            }
            rows.push((p, v));
        }
    }
    rows.len()
}

/// Adds the square-free `x > 1` to the pairwise coprime, square-free `base`, splitting elements
/// that share a factor with it, so that `base` stays a coprime base of everything added.
fn refine_base(base: &mut Vec<u64>, mut x: u64) {
    let mut i = 0;
    while i < base.len() && x > 1 {
        let b = base[i];
        let g = gcd_u64(x, b);
        if g > 1 {
            // Square-free: g is coprime to b/g and to x/g, and both to every other element.
            if g < b {
                base[i] = g;
                base.push(b / g);
            }
            x /= g;
        }
        i += 1;
    }
    if x > 1 {
        base.push(x);
    }
}
