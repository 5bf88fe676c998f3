//! `Res_s(F, G)` of two bivariate polynomials as a polynomial in `t`, by the Chinese remainder
//! theorem over word-size primes.
//!
//! `F` and `G` are scaled to integer coefficients (`c_F F`, `c_G G`). The Sylvester determinant
//! with the formal degrees `m = deg_s F`, `n = deg_s G` is a polynomial in the entries, so its
//! image modulo a prime `p` is the determinant of the reduced matrix: for each prime the
//! determinant is evaluated at `N + 1` points `t = 0, 1, ..., N` (`N` the degree bound
//! `n deg_t F + m deg_t G`) by Gaussian elimination in `Z/pZ`, and interpolated. The integer
//! coefficients are recovered by the Chinese remainder theorem, in the symmetric range, once
//! the product of the primes exceeds twice the bound
//! `|coefficient of R| <= ||R||_1 <= ||F||_1^n ||G||_1^m`
//! (the determinant is a signed sum of products of one entry per row; `||a b||_1 <= ||a||_1
//! ||b||_1` for polynomials, and the entries of a row of the Sylvester matrix are the
//! coefficients of one of the two polynomials, so a row contributes at most that polynomial's
//! norm). Every step is exact: the primes only make the integer arithmetic word-sized.
//! Finally the scale `c_F^n c_G^m` is divided out.
//!
//! Written here rather than taken from a crate: the workspace's polynomials are its own types,
//! and the few operations (a determinant and an interpolation modulo a prime, and a CRT) are
//! short. The fraction-free Bareiss determinant at integer points is kept as the test
//! reference.

use super::Dense;
use crate::modp::{is_prime_u64, PrimeField};
use crate::univariate::UPoly;
use crate::Rational;
#[cfg(test)]
use exactcheck_core::Ring;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// `Res_s(f, g)` as a polynomial in `t` (module documentation).
pub(super) fn resultant_s(f: &Dense, g: &Dense) -> UPoly {
    if f.is_zero() || g.is_zero() {
        return UPoly::zero();
    }
    let (m, n) = (f.deg_s(), g.deg_s());
    let bound = n * f.deg_t() + m * g.deg_t();
    let (cf, fi) = f.to_integer();
    let (cg, gi) = g.to_integer();
    let norm_bits = |rows: &[Vec<BigInt>]| -> u64 {
        rows.iter()
            .flatten()
            .fold(BigInt::zero(), |acc, a| acc + a.abs())
            .bits()
    };
    // Bits of 2 ||F||_1^n ||G||_1^m, rounded up.
    let needed = n as u64 * norm_bits(&fi) + m as u64 * norm_bits(&gi) + 2;
    let mut modulus = BigInt::one();
    let mut coeffs: Vec<BigInt> = vec![BigInt::zero(); bound + 1];
    let mut primes = Primes::below_2_62();
    while modulus.bits() <= needed {
        let field = primes.next_field();
        let p = field.modulus();
        let residues = resultant_mod(&field, &fi, &gi, bound);
        // CRT: x = c + M ((r - c) M^-1 mod p), for every coefficient.
        let pb = BigInt::from(p);
        let m_mod_p = residue(&modulus, p);
        let m_inv = field
            .inv(m_mod_p)
            .expect("the primes are distinct, so M is invertible modulo the next one");
        for (c, r) in coeffs.iter_mut().zip(residues) {
            let c_mod_p = residue(c, p);
            let k = field.mul(field.sub(r, c_mod_p), m_inv);
            *c += &modulus * BigInt::from(k);
        }
        modulus *= pb;
    }
    // Symmetric range: the true coefficients lie in (-M/2, M/2).
    let half = &modulus >> 1;
    for c in &mut coeffs {
        if *c > half {
            *c -= &modulus;
        }
    }
    let scale = (0..n).fold(Rational::ONE, |acc, _| acc * &cf)
        * (0..m).fold(Rational::ONE, |acc, _| acc * &cg);
    let inv = scale.recip().expect("scales are not zero");
    UPoly::from_coeffs(
        coeffs
            .into_iter()
            .map(|c| Rational::from(c) * &inv)
            .collect(),
    )
}

/// `x mod p` in `0..p`.
fn residue(x: &BigInt, p: u64) -> u64 {
    let r = x.mod_floor(&BigInt::from(p));
    let (_, digits) = r.to_u64_digits();
    digits.first().copied().unwrap_or(0)
}

/// The coefficients modulo `p` (of `t^0 .. t^bound`) of the Sylvester determinant of the
/// integer bivariate polynomials `f` and `g` (rows by powers of `s`, each a polynomial in `t`).
fn resultant_mod(
    field: &PrimeField,
    f: &[Vec<BigInt>],
    g: &[Vec<BigInt>],
    bound: usize,
) -> Vec<u64> {
    let p = field.modulus();
    let reduce = |rows: &[Vec<BigInt>]| -> Vec<Vec<u64>> {
        rows.iter()
            .map(|row| row.iter().map(|a| residue(a, p)).collect())
            .collect()
    };
    let (fp, gp) = (reduce(f), reduce(g));
    let at = |rows: &[Vec<u64>], t: u64| -> Vec<u64> {
        rows.iter()
            .map(|row| {
                row.iter()
                    .rev()
                    .fold(0, |acc, &a| field.add(field.mul(acc, t), a))
            })
            .collect()
    };
    let nodes: Vec<u64> = (0..=bound as u64).collect();
    let values: Vec<u64> = nodes
        .iter()
        .map(|&t| sylvester_det_mod(field, &at(&fp, t), &at(&gp, t)))
        .collect();
    interpolate_mod(field, &nodes, values)
}

/// The Sylvester determinant of `sum f_i s^i` and `sum g_i s^i` (formal degrees) modulo `p`, by
/// Gaussian elimination.
fn sylvester_det_mod(field: &PrimeField, f: &[u64], g: &[u64]) -> u64 {
    let (m, n) = (f.len() - 1, g.len() - 1);
    let size = m + n;
    if size == 0 {
        return 1;
    }
    let mut a = vec![vec![0u64; size]; size];
    for r in 0..n {
        for (k, &c) in f.iter().rev().enumerate() {
            a[r][r + k] = c;
        }
    }
    for r in 0..m {
        for (k, &c) in g.iter().rev().enumerate() {
            a[n + r][r + k] = c;
        }
    }
    let mut det = 1u64;
    for k in 0..size {
        let Some(piv) = (k..size).find(|&r| a[r][k] != 0) else {
            return 0;
        };
        if piv != k {
            a.swap(piv, k);
            det = field.neg(det);
        }
        det = field.mul(det, a[k][k]);
        let inv = field.inv(a[k][k]).expect("the pivot is not zero");
        let (top, bottom) = a.split_at_mut(k + 1);
        let pivot_row = &top[k];
        for row in bottom.iter_mut() {
            if row[k] == 0 {
                continue;
            }
            let factor = field.mul(row[k], inv);
            for j in k..size {
                row[j] = field.sub(row[j], field.mul(factor, pivot_row[j]));
            }
        }
    }
    det
}

/// The coefficients (low to high, `nodes.len()` of them) modulo `p` of the polynomial through
/// `(nodes[k], values[k])`, by Newton's divided differences.
fn interpolate_mod(field: &PrimeField, nodes: &[u64], mut dd: Vec<u64>) -> Vec<u64> {
    let n = nodes.len();
    for level in 1..n {
        for k in (level..n).rev() {
            let num = field.sub(dd[k], dd[k - 1]);
            let den = field.sub(nodes[k], nodes[k - level]);
            dd[k] = field.mul(num, field.inv(den).expect("the nodes are distinct"));
        }
    }
    // Horner on the Newton form: acc = acc (t - x_k) + dd_k.
    let mut acc: Vec<u64> = Vec::with_capacity(n);
    for k in (0..n).rev() {
        let mut next = vec![0u64; acc.len() + 1];
        for (i, &a) in acc.iter().enumerate() {
            next[i + 1] = field.add(next[i + 1], a);
            next[i] = field.sub(next[i], field.mul(a, nodes[k]));
        }
        next[0] = field.add(next[0], dd[k]);
        acc = next;
    }
    acc.truncate(n);
    acc
}

/// The primes below `2^62`, in decreasing order.
struct Primes {
    next: u64,
}

impl Primes {
    fn below_2_62() -> Primes {
        Primes {
            next: (1u64 << 62) - 1,
        }
    }

    fn next_field(&mut self) -> PrimeField {
        loop {
            let c = self.next;
            self.next -= 2;
            if is_prime_u64(c) {
                return PrimeField::new(c).expect("an odd prime below 2^63");
            }
        }
    }
}

/// The reference: the Sylvester determinant at the integers `t` centred on 0 by Bareiss'
/// fraction-free elimination, and Newton interpolation over Q.
#[cfg(test)]
pub(super) fn resultant_s_bareiss(f: &Dense, g: &Dense) -> UPoly {
    if f.is_zero() || g.is_zero() {
        return UPoly::zero();
    }
    let (m, n) = (f.deg_s(), g.deg_s());
    let bound = n * f.deg_t() + m * g.deg_t();
    let (cf, fi) = f.to_integer();
    let (cg, gi) = g.to_integer();
    let low = -((bound / 2) as i64);
    let nodes: Vec<BigInt> = (0..=bound as i64).map(|k| BigInt::from(low + k)).collect();
    let values: Vec<Rational> = nodes
        .iter()
        .map(|t0| {
            let at = |p: &[Vec<BigInt>]| -> Vec<BigInt> {
                p.iter()
                    .map(|row| row.iter().rev().fold(BigInt::zero(), |acc, a| acc * t0 + a))
                    .collect()
            };
            Rational::from(sylvester_det(&at(&fi), &at(&gi)))
        })
        .collect();
    let nodes: Vec<Rational> = nodes.into_iter().map(Rational::from).collect();
    let scale = (0..n).fold(Rational::ONE, |acc, _| acc * &cf)
        * (0..m).fold(Rational::ONE, |acc, _| acc * &cg);
    newton_interpolate(&nodes, values).scale(&scale.recip().expect("scales are not zero"))
}

#[cfg(test)]
fn sylvester_det(f: &[BigInt], g: &[BigInt]) -> BigInt {
    let (m, n) = (f.len() - 1, g.len() - 1);
    let size = m + n;
    let mut a: Vec<Vec<BigInt>> = vec![vec![BigInt::zero(); size]; size];
    for r in 0..n {
        for (k, c) in f.iter().rev().enumerate() {
            a[r][r + k] = c.clone();
        }
    }
    for r in 0..m {
        for (k, c) in g.iter().rev().enumerate() {
            a[n + r][r + k] = c.clone();
        }
    }
    bareiss(a)
}

/// The determinant of an integer matrix by Bareiss' fraction-free elimination: after step `k`
/// every entry is a `(k+1) x (k+1)` minor, so the division by the previous pivot is exact.
#[cfg(test)]
pub(super) fn bareiss(mut a: Vec<Vec<BigInt>>) -> BigInt {
    let size = a.len();
    if size == 0 {
        return BigInt::one();
    }
    let mut negate = false;
    let mut prev = BigInt::one();
    for k in 0..size - 1 {
        if a[k][k].is_zero() {
            let Some(p) = (k + 1..size).find(|&r| !a[r][k].is_zero()) else {
                return BigInt::zero();
            };
            a.swap(p, k);
            negate = !negate;
        }
        let (top, bottom) = a.split_at_mut(k + 1);
        let pivot_row = &top[k];
        for row in bottom.iter_mut() {
            for j in k + 1..size {
                let v = &row[j] * &pivot_row[k] - &row[k] * &pivot_row[j];
                row[j] = v / &prev;
            }
            row[k] = BigInt::zero();
        }
        prev = pivot_row[k].clone();
    }
    let det = a[size - 1][size - 1].clone();
    if negate {
        -det
    } else {
        det
    }
}

#[cfg(test)]
fn newton_interpolate(nodes: &[Rational], mut dd: Vec<Rational>) -> UPoly {
    let n = nodes.len();
    for level in 1..n {
        for k in (level..n).rev() {
            let num = dd[k].sub_ref(&dd[k - 1]);
            let den = nodes[k].sub_ref(&nodes[k - level]);
            dd[k] = num / &den;
        }
    }
    let mut acc = UPoly::zero();
    for k in (0..n).rev() {
        acc = acc * UPoly::from_coeffs(vec![-nodes[k].clone(), Rational::ONE])
            + UPoly::constant(dd[k].clone());
    }
    acc
}
