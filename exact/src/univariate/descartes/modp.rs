//! The square-free part of an integer polynomial: the modular certificate (word-size primes,
//! Euclid without inverses) and the exact fallback by the primitive remainder sequence (step 1
//! of the parent module's documentation).
//!
//! The first prime is the Mersenne prime `2^31 - 1` ([`P31`]): a product of two residues plus
//! another such product is below `2^63`, so each step of Euclid's algorithm is two 64-bit
//! multiplications and one Mersenne fold, with no 128-bit arithmetic (about a third of the
//! instructions of the 61-bit primes). It fails only when it divides the leading coefficient
//! or the resultant `Res(q, q')` of a square-free `q`; the three 61/62-bit [`PRIMES`] follow.

use super::*;

/// The Mersenne prime `2^31 - 1`, the first prime of the modular square-freeness test.
pub(super) const P31: u64 = (1 << 31) - 1;

/// Three primes below `2^62` for the modular square-freeness test, after [`P31`].
pub(super) const PRIMES: [u64; 3] = [
    (1 << 61) - 1,
    4_611_686_018_427_387_847,
    4_611_686_018_427_387_817,
];

/// Multiplication modulo one of the [`PRIMES`]: Mersenne folding for `2^61 - 1`
/// ([`ModP`](crate::modp::ModP)), a `u128` remainder for the others.
#[inline]
pub(super) fn mul_mod(a: u64, b: u64, p: u64) -> u64 {
    reduce_u128(u128::from(a) * u128::from(b), p)
}

/// `x mod p` for one of the [`PRIMES`]: Mersenne folding for `2^61 - 1`, a `u128` remainder
/// for the others.
#[inline]
fn reduce_u128(x: u128, p: u64) -> u64 {
    if p == crate::modp::P {
        crate::modp::ModP::from_u128(x).value()
    } else {
        (x % u128::from(p)) as u64
    }
}

/// `x mod (2^31 - 1)` for `x < 2^63`: two Mersenne folds (below `2^33`, then below
/// `2^31 + 4`) and one conditional subtraction.
#[inline]
pub(super) fn fold31(x: u64) -> u64 {
    debug_assert!(x < 1 << 63);
    let x = (x & P31) + (x >> 31);
    let x = (x & P31) + (x >> 31);
    if x >= P31 {
        x - P31
    } else {
        x
    }
}

/// `x mod p` for an integer `x` (non-negative result).
pub(super) fn big_mod(x: &BigInt, p: u64) -> u64 {
    if p == crate::modp::P {
        return crate::modp::ModP::from_bigint(x).value();
    }
    if p == P31 {
        // Horner over the 64-bit limbs, most significant first: 2^64 = 2^(2 * 31 + 2) = 4.
        let r = x.magnitude().iter_u64_digits().rev().fold(0u64, |r, limb| {
            fold31((r << 2) + fold31(limb >> 1) * 2 + (limb & 1))
        });
        return if x.is_negative() && r != 0 {
            P31 - r
        } else {
            r
        };
    }
    let r = rem_small(x, p);
    if x.is_negative() && r != 0 {
        p - r
    } else {
        r
    }
}

/// The arithmetic of one prime for [`gcd_degree`].
trait Modulus: Copy {
    /// `a b mod p` (`a, b < p`).
    fn mul(self, a: u64, b: u64) -> u64;
    /// `x l + f b mod p` (all below `p`).
    fn mul_add(self, x: u64, l: u64, f: u64, b: u64) -> u64;
    fn p(self) -> u64;
}

/// One of the [`PRIMES`]: products in `u128`.
#[derive(Clone, Copy)]
struct Wide(u64);

impl Modulus for Wide {
    #[inline]
    fn mul(self, a: u64, b: u64) -> u64 {
        mul_mod(a, b, self.0)
    }
    #[inline]
    fn mul_add(self, x: u64, l: u64, f: u64, b: u64) -> u64 {
        // One reduction of a sum below 2^125.
        reduce_u128(
            u128::from(x) * u128::from(l) + u128::from(f) * u128::from(b),
            self.0,
        )
    }
    fn p(self) -> u64 {
        self.0
    }
}

/// [`P31`]: products in `u64` (two products of residues sum to less than `2^63`).
#[derive(Clone, Copy)]
struct Mersenne31;

impl Modulus for Mersenne31 {
    #[inline]
    fn mul(self, a: u64, b: u64) -> u64 {
        fold31(a * b)
    }
    #[inline]
    fn mul_add(self, x: u64, l: u64, f: u64, b: u64) -> u64 {
        fold31(x * l + f * b)
    }
    fn p(self) -> u64 {
        P31
    }
}

/// The degree of `gcd(a, b)` over `F_p` for one of the [`PRIMES`] (both non-zero, residues
/// below `p`; see [`gcd_degree`]).
pub(super) fn gcd_degree_mod_p(a: Vec<u64>, b: Vec<u64>, p: u64) -> usize {
    gcd_degree(a, b, Wide(p))
}

/// [`gcd_degree_mod_p`] modulo [`P31`] on 64-bit products.
pub(super) fn gcd_degree_mod_p31(a: Vec<u64>, b: Vec<u64>) -> usize {
    gcd_degree(a, b, Mersenne31)
}

/// The degree of `gcd(a, b)` over `F_p` (both non-zero, trailing zeros trimmed). Euclid's
/// algorithm without inverses: `a <- lc(b) a - lc(a) x^k b` cancels the leading term of `a`
/// and multiplies the gcd by the unit `lc(b)` only, so the degrees are those of the monic
/// remainder sequence.
fn gcd_degree<M: Modulus>(mut a: Vec<u64>, mut b: Vec<u64>, m: M) -> usize {
    fn trim(v: &mut Vec<u64>) {
        while v.last() == Some(&0) {
            v.pop();
        }
    }
    let p = m.p();
    trim(&mut a);
    trim(&mut b);
    if a.len() < b.len() {
        std::mem::swap(&mut a, &mut b);
    }
    while !b.is_empty() {
        // a <- a mod b (up to a unit factor)
        let db = b.len() - 1;
        let lb = b[db];
        while a.len() > db {
            let top = a.len() - 1;
            let f = a[top];
            let shift = top - db;
            for x in &mut a[..shift] {
                *x = m.mul(*x, lb);
            }
            // x lb - f b_j as x lb + (p - f) b_j.
            let nf = p - f;
            for (x, &bj) in a[shift..].iter_mut().zip(&b) {
                *x = m.mul_add(*x, lb, nf, bj);
            }
            debug_assert_eq!(a[top], 0);
            a.pop();
            trim(&mut a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().saturating_sub(1)
}

/// Whether `gcd(q mod p, q' mod p) = 1` over `F_p` for one of the primes ([`P31`], then the
/// [`PRIMES`]) keeping the degrees of `q` and `q'`: a proof that the integer polynomial `q`
/// (degree >= 1) is square-free (see the module documentation). `false` means "not proved",
/// not "not square-free".
pub(super) fn is_square_free_mod_p(q: &[BigInt]) -> bool {
    let n = q.len() - 1;
    let residues = |p: u64| -> Option<(Vec<u64>, Vec<u64>)> {
        let a: Vec<u64> = q.iter().map(|c| big_mod(c, p)).collect();
        let d: Vec<u64> = (1..=n)
            .map(|i| reduce_u128(u128::from(a[i]) * (i as u128 % u128::from(p)), p))
            .collect();
        (a[n] != 0 && d[n - 1] != 0).then_some((a, d))
    };
    if let Some((a, d)) = residues(P31) {
        if gcd_degree_mod_p31(a, d) == 0 {
            return true;
        }
    }
    PRIMES
        .iter()
        .any(|&p| residues(p).is_some_and(|(a, d)| gcd_degree_mod_p(a, d, p) == 0))
}

/// The gcd of the integers `q` (non-negative): each step reduces the next number modulo the
/// running gcd first (a word remainder while the gcd fits in a word), and stops at 1.
pub(super) fn content(q: &[BigInt]) -> BigInt {
    let mut g = BigInt::zero();
    for c in q {
        if g.is_one() {
            break;
        }
        if c.is_zero() {
            continue;
        }
        g = match g.to_u64() {
            Some(0) => c.abs(),
            Some(w) => BigInt::from(num_integer::Integer::gcd(&w, &rem_small(c, w))),
            None => num_integer::Integer::gcd(&g, &(c % &g)),
        };
    }
    g
}

/// The primitive square-free part with a positive leading coefficient, as integers.
pub(super) fn square_free_integer(coeffs: &[BigInt]) -> Vec<BigInt> {
    let g = content(coeffs);
    let mut q: Vec<BigInt> = match g.to_u64() {
        Some(1) => coeffs.to_vec(),
        // A word content (the usual case): exact division by a word, on `i128` when the
        // coefficient fits, by Jebelean's exact division on its limbs otherwise.
        Some(w) => coeffs
            .iter()
            .map(|c| match c.to_i128() {
                Some(v) => BigInt::from(v / i128::from(w)),
                None => {
                    let m = crate::bigint::divexact_1(&c.magnitude().to_u64_digits(), w);
                    let m = BigInt::from(crate::bigint::biguint_from_limbs(&m));
                    if c.is_negative() {
                        -m
                    } else {
                        m
                    }
                }
            })
            .collect(),
        None => coeffs.iter().map(|c| c / &g).collect(),
    };
    if q.last().is_some_and(|c| c.is_negative()) {
        for c in &mut q {
            *c = -std::mem::take(c);
        }
    }
    if q.len() <= 2 || is_square_free_mod_p(&q) {
        return q;
    }
    let u = UPoly::from_coeffs(q.iter().cloned().map(Rational::from).collect());
    let s = u.square_free_part().primitive_part();
    let mut out: Vec<BigInt> = s
        .coeffs()
        .iter()
        .map(|c| {
            debug_assert!(c.is_integer());
            c.numer()
        })
        .collect();
    if out.last().is_some_and(|c| c.is_negative()) {
        for c in &mut out {
            *c = -&*c;
        }
    }
    out
}
