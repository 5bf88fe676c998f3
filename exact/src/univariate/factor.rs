//! Factorisation of univariate polynomials over Z (equivalently over Q) into irreducible factors.
//!
//! # Algorithm (Zassenhaus)
//! 1. The content and Yun's square-free decomposition ([`UPoly::square_free_decomposition`])
//!    split the polynomial into square-free, primitive parts; each part is factored alone.
//! 2. A prime `p` not dividing the leading coefficient, modulo which the part stays square-free,
//!    is chosen among a few candidates (the one giving the fewest factors wins; a single factor
//!    modulo `p` proves irreducibility at once). Factorisation over `F_p`: distinct-degree
//!    factorisation (`gcd(x^(p^d) - x, f)`), then Cantor–Zassenhaus equal-degree splitting with
//!    random polynomials from the workspace's seeded [`Rng`] (so every run is reproducible).
//! 3. Hensel lifting of `f = lc * u_1 ... u_r (mod p)` to `mod p^(2^k)` past twice Mignotte's
//!    bound `|lc| 2^n ||f||_2` on the coefficients of `lc` times any factor: quadratic two-factor
//!    lifting (von zur Gathen and Gerhard, *Modern Computer Algebra*, Algorithm 15.10), one
//!    lifted factor split off after the other.
//! 4. Recombination: subsets of the lifted factors by increasing size, `lc * prod` reduced
//!    symmetrically modulo `p^(2^k)` and made primitive, tested by exact division over Z (a cheap
//!    divisibility test of the constant terms first). A factor found leaves the pool; what is
//!    left at the end is irreducible.
//!
//! **Degree pruning.** The degree of a true factor is a sum of degrees of modular factors for
//! *every* prime, so the distinct-degree patterns of all the primes tried give the set of
//! possible factor degrees (the intersection of their subset sums). A set with no degree
//! strictly between 0 and `n` proves irreducibility without recombination (`x^4 + 1` splits
//! into quadratics or linear factors modulo every prime, but a polynomial whose patterns are
//! `{1, 3}` and `{2, 2}` is irreducible), and recombination skips every subset whose degree is
//! not possible before any multiplication.
//!
//! Recombination stays exponential in the number of modular factors in the worst case
//! (polynomials with many factors modulo every prime, such as those with a Galois group of
//! exponent 2: the Swinnerton-Dyer polynomials). The subsets tested in one factorisation are
//! bounded by the `factor-combinations` limit ([`limits::FACTOR_COMBINATIONS`]), past which
//! [`UPoly::factor`] answers the [`LimitError`] instead of any factorisation: a product of
//! factors that may be reducible is never returned as irreducible, since a non-minimal
//! "minimal polynomial" would make a number field a ring with zero divisors. Degrees up to a
//! few dozen with a handful of modular factors are the target; van Hoeij's lattice
//! recombination would remove the exponential case.
//!
//! Hand-written because no maintained Rust crate factors integer polynomials on the
//! `num-bigint` integers the workspace uses (the FLINT bindings need a C library, and the pure
//! Rust computer-algebra crates bring their own integer types); the mod-`p` arithmetic is the
//! workspace's [`PrimeField`].

use super::UPoly;
use crate::modp::{is_prime_u64, PrimeField};
use crate::Rational;
use exactcheck_core::limits::{self, LimitError};
use exactcheck_core::{Ring, Rng};
use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// `content * prod f^e` ([`UPoly::factor`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Factorisation {
    /// The rational constant factor (negative when the polynomial's leading coefficient is).
    pub content: Rational,
    /// The irreducible factors with their multiplicities: each primitive with integer
    /// coefficients and a positive leading coefficient, of positive degree; sorted by degree,
    /// then coefficients.
    pub factors: Vec<(UPoly, u32)>,
}

impl Factorisation {
    /// The product `content * prod f^e`, expanded.
    pub fn expand(&self) -> UPoly {
        let mut p = UPoly::constant(self.content.clone());
        for (f, e) in &self.factors {
            for _ in 0..*e {
                p = p.mul_ref(f);
            }
        }
        p
    }
}

/// Candidate primes tried for one square-free part (the fewest modular factors wins).
const PRIMES_TRIED: usize = 5;

/// The first prime candidate; primes are taken upwards from here.
const FIRST_PRIME: u64 = 1 << 15;

impl UPoly {
    /// The factorisation into irreducible factors over Q (module documentation).
    ///
    /// ```
    /// use exactcheck_exact::univariate::UPoly;
    /// // 2 x^4 - 2 = 2 (x - 1) (x + 1) (x^2 + 1)
    /// let f = UPoly::from_i64_coeffs(&[-2, 0, 0, 0, 2]).factor().unwrap();
    /// assert_eq!(f.factors.len(), 3);
    /// assert_eq!(f.expand(), UPoly::from_i64_coeffs(&[-2, 0, 0, 0, 2]));
    /// ```
    ///
    /// # Errors
    /// The `factor-combinations` [`LimitError`] when recombination would test more subsets of
    /// modular factors than the limit allows.
    ///
    /// # Panics
    /// For the zero polynomial.
    pub fn factor(&self) -> Result<Factorisation, LimitError> {
        assert!(!self.is_zero(), "the zero polynomial has no factorisation");
        let mut factors = Vec::new();
        let mut budget = limits::FACTOR_COMBINATIONS.get();
        let mut product = UPoly::one();
        for (part, e) in self.square_free_decomposition() {
            for g in factor_square_free(&integer_coeffs(&part), &mut budget)? {
                let g = from_integers(&g);
                for _ in 0..e {
                    product = product.mul_ref(&g);
                }
                factors.push((g, e));
            }
        }
        factors.sort_by(|(a, _), (b, _)| {
            a.degree()
                .cmp(&b.degree())
                .then_with(|| a.coeffs().cmp(b.coeffs()))
        });
        let content = self
            .leading_coefficient()
            .checked_div(&product.leading_coefficient())
            .expect("a product of non-zero polynomials is not zero");
        Ok(Factorisation { content, factors })
    }

    /// The irreducible factors of a square-free polynomial of positive degree (primitive,
    /// positive leading coefficients, in no particular order).
    ///
    /// # Errors
    /// As [`UPoly::factor`].
    pub fn irreducible_factors(&self) -> Result<Vec<UPoly>, LimitError> {
        let mut budget = limits::FACTOR_COMBINATIONS.get();
        Ok(
            factor_square_free(&integer_coeffs(&self.primitive_part()), &mut budget)?
                .iter()
                .map(|g| from_integers(g))
                .collect(),
        )
    }
}

/// The integer coefficients of the primitive part with a positive leading coefficient.
fn integer_coeffs(p: &UPoly) -> Vec<BigInt> {
    let mut c = p.integer_coefficients();
    if c.last().is_some_and(Signed::is_negative) {
        c.iter_mut().for_each(|x| *x = -&*x);
    }
    c
}

fn from_integers(c: &[BigInt]) -> UPoly {
    UPoly::from_coeffs(c.iter().cloned().map(Rational::from).collect())
}

// ------------------------------------------------------------------------------ over Z

fn trim_z(a: &mut Vec<BigInt>) {
    while a.last().is_some_and(Zero::is_zero) {
        a.pop();
    }
}

fn mul_z(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![BigInt::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// `a mod m` in `[0, m)` coefficient-wise, trimmed.
fn reduce(a: &[BigInt], m: &BigInt) -> Vec<BigInt> {
    let mut out: Vec<BigInt> = a.iter().map(|c| c.mod_floor(m)).collect();
    trim_z(&mut out);
    out
}

/// `a mod m` in `(-m/2, m/2]` coefficient-wise.
fn symmetric(a: &[BigInt], m: &BigInt) -> Vec<BigInt> {
    let half = m >> 1usize;
    let mut out: Vec<BigInt> = a
        .iter()
        .map(|c| {
            let r = c.mod_floor(m);
            if r > half {
                r - m
            } else {
                r
            }
        })
        .collect();
    trim_z(&mut out);
    out
}

fn sub_z(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    let n = a.len().max(b.len());
    let mut out: Vec<BigInt> = (0..n)
        .map(|i| a.get(i).cloned().unwrap_or_default() - b.get(i).cloned().unwrap_or_default())
        .collect();
    trim_z(&mut out);
    out
}

fn add_z(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    let n = a.len().max(b.len());
    let mut out: Vec<BigInt> = (0..n)
        .map(|i| a.get(i).cloned().unwrap_or_default() + b.get(i).cloned().unwrap_or_default())
        .collect();
    trim_z(&mut out);
    out
}

/// Division of `a` by the monic `b` modulo `m`: `(q, r)` with `a = q b + r (mod m)`,
/// `deg r < deg b`, both reduced to `[0, m)`.
fn divrem_monic_mod(a: &[BigInt], b: &[BigInt], m: &BigInt) -> (Vec<BigInt>, Vec<BigInt>) {
    let mut r = reduce(a, m);
    let db = b.len() - 1;
    if r.len() <= db {
        return (Vec::new(), r);
    }
    let mut q = vec![BigInt::zero(); r.len() - db];
    for k in (db..r.len()).rev() {
        let c = r[k].mod_floor(m);
        if c.is_zero() {
            continue;
        }
        for (j, bj) in b.iter().enumerate() {
            r[k - db + j] -= &c * bj;
        }
        q[k - db] = c;
    }
    r.truncate(db);
    (reduce(&q, m), reduce(&r, m))
}

/// `a / b` over Z when `b` divides `a` exactly, `None` otherwise (`b` non-zero).
fn divide_exact_z(a: &[BigInt], b: &[BigInt]) -> Option<Vec<BigInt>> {
    if a.len() < b.len() {
        return None;
    }
    let lb = b.last().expect("non-zero divisor");
    let db = b.len() - 1;
    let mut r = a.to_vec();
    let mut q = vec![BigInt::zero(); a.len() - db];
    for k in (db..a.len()).rev() {
        if r[k].is_zero() {
            continue;
        }
        let (c, rem) = r[k].div_rem(lb);
        if !rem.is_zero() {
            return None;
        }
        for (j, bj) in b.iter().enumerate() {
            r[k - db + j] -= &c * bj;
        }
        q[k - db] = c;
    }
    r.iter().all(Zero::is_zero).then_some(q)
}

fn primitive_z(a: &[BigInt]) -> Vec<BigInt> {
    let g = a.iter().fold(BigInt::zero(), |g, c| g.gcd(c));
    let mut out: Vec<BigInt> = if g.is_zero() || g.is_one() {
        a.to_vec()
    } else {
        a.iter().map(|c| c / &g).collect()
    };
    if out.last().is_some_and(Signed::is_negative) {
        out.iter_mut().for_each(|c| *c = -&*c);
    }
    out
}

// ------------------------------------------------------------------------------ over F_p

/// Polynomials over `F_p` as residue vectors from the constant term up, trimmed.
struct Fp(PrimeField);

impl Fp {
    fn trim(a: &mut Vec<u64>) {
        while a.last() == Some(&0) {
            a.pop();
        }
    }

    fn reduce_z(&self, a: &[BigInt]) -> Vec<u64> {
        let mut out: Vec<u64> = a.iter().map(|c| self.0.from_bigint(c)).collect();
        Fp::trim(&mut out);
        out
    }

    fn mul(&self, a: &[u64], b: &[u64]) -> Vec<u64> {
        if a.is_empty() || b.is_empty() {
            return Vec::new();
        }
        let mut out = vec![0; a.len() + b.len() - 1];
        for (i, &x) in a.iter().enumerate() {
            if x == 0 {
                continue;
            }
            for (j, &y) in b.iter().enumerate() {
                out[i + j] = self.0.add(out[i + j], self.0.mul(x, y));
            }
        }
        Fp::trim(&mut out);
        out
    }

    fn sub(&self, a: &[u64], b: &[u64]) -> Vec<u64> {
        let n = a.len().max(b.len());
        let mut out: Vec<u64> = (0..n)
            .map(|i| {
                self.0.sub(
                    a.get(i).copied().unwrap_or(0),
                    b.get(i).copied().unwrap_or(0),
                )
            })
            .collect();
        Fp::trim(&mut out);
        out
    }

    fn scale(&self, a: &[u64], c: u64) -> Vec<u64> {
        let mut out: Vec<u64> = a.iter().map(|&x| self.0.mul(x, c)).collect();
        Fp::trim(&mut out);
        out
    }

    fn monic(&self, a: &[u64]) -> Vec<u64> {
        match a.last() {
            Some(&l) if l != 1 => self.scale(a, self.0.inv(l).expect("non-zero")),
            _ => a.to_vec(),
        }
    }

    /// `(q, r)` with `a = q b + r`, `b` non-zero.
    fn divrem(&self, a: &[u64], b: &[u64]) -> (Vec<u64>, Vec<u64>) {
        let db = b.len() - 1;
        let mut r = a.to_vec();
        if r.len() <= db {
            return (Vec::new(), r);
        }
        let inv = self.0.inv(b[db]).expect("non-zero leading coefficient");
        let mut q = vec![0; r.len() - db];
        for k in (db..r.len()).rev() {
            let c = self.0.mul(r[k], inv);
            if c == 0 {
                continue;
            }
            for (j, &bj) in b.iter().enumerate() {
                r[k - db + j] = self.0.sub(r[k - db + j], self.0.mul(c, bj));
            }
            q[k - db] = c;
        }
        r.truncate(db);
        Fp::trim(&mut r);
        Fp::trim(&mut q);
        (q, r)
    }

    fn rem(&self, a: &[u64], b: &[u64]) -> Vec<u64> {
        self.divrem(a, b).1
    }

    /// The monic gcd.
    fn gcd(&self, a: &[u64], b: &[u64]) -> Vec<u64> {
        let (mut a, mut b) = (a.to_vec(), b.to_vec());
        while !b.is_empty() {
            let r = self.rem(&a, &b);
            a = b;
            b = r;
        }
        self.monic(&a)
    }

    /// `(s, t)` with `s a + t b = 1` for coprime `a`, `b`.
    fn bezout(&self, a: &[u64], b: &[u64]) -> (Vec<u64>, Vec<u64>) {
        let (mut r0, mut r1) = (a.to_vec(), b.to_vec());
        let (mut s0, mut s1) = (vec![1u64], Vec::new());
        let (mut t0, mut t1) = (Vec::new(), vec![1u64]);
        while !r1.is_empty() {
            let (q, r) = self.divrem(&r0, &r1);
            let s = self.sub(&s0, &self.mul(&q, &s1));
            let t = self.sub(&t0, &self.mul(&q, &t1));
            (r0, r1) = (r1, r);
            (s0, s1) = (s1, s);
            (t0, t1) = (t1, t);
        }
        // r0 is a non-zero constant.
        let inv = self.0.inv(r0[0]).expect("coprime polynomials");
        (self.scale(&s0, inv), self.scale(&t0, inv))
    }

    /// `a^e mod m`.
    fn pow_mod(&self, a: &[u64], e: &BigUint, m: &[u64]) -> Vec<u64> {
        let mut acc = vec![1u64];
        let base = self.rem(a, m);
        for i in (0..e.bits()).rev() {
            acc = self.rem(&self.mul(&acc, &acc), m);
            if e.bit(i) {
                acc = self.rem(&self.mul(&acc, &base), m);
            }
        }
        acc
    }

    fn derivative(&self, a: &[u64]) -> Vec<u64> {
        let mut out: Vec<u64> = a
            .iter()
            .enumerate()
            .skip(1)
            .map(|(k, &c)| self.0.mul(c, k as u64 % self.0.modulus()))
            .collect();
        Fp::trim(&mut out);
        out
    }

    /// The monic irreducible factors of the monic square-free `f`.
    fn factor(&self, f: &[u64], rng: &mut Rng) -> Vec<Vec<u64>> {
        let p = BigUint::from(self.0.modulus());
        let x = vec![0, 1];
        let mut out = Vec::new();
        let mut rest = f.to_vec();
        let mut h = x.clone();
        let mut d = 1;
        // Distinct-degree factorisation.
        while 2 * d < rest.len() {
            h = self.pow_mod(&h, &p, &rest);
            let g = self.gcd(&self.sub(&h, &x), &rest);
            if g.len() > 1 {
                self.split_equal_degree(&g, d, rng, &mut out);
                rest = self.divrem(&rest, &g).0;
                h = self.rem(&h, &rest);
            }
            d += 1;
        }
        if rest.len() > 1 {
            out.push(self.monic(&rest));
        }
        out
    }

    /// Cantor–Zassenhaus: splits the monic `g`, a product of irreducibles of degree `d`.
    fn split_equal_degree(&self, g: &[u64], d: usize, rng: &mut Rng, out: &mut Vec<Vec<u64>>) {
        let n = g.len() - 1;
        if n == d {
            out.push(g.to_vec());
            return;
        }
        let p = BigUint::from(self.0.modulus());
        let e = (p.pow(d as u32) - 1u32) >> 1usize;
        loop {
            let a: Vec<u64> = (0..n).map(|_| self.0.random(rng)).collect();
            let mut a = a;
            Fp::trim(&mut a);
            if a.len() < 2 {
                continue;
            }
            let b = self.sub(&self.pow_mod(&a, &e, g), &[1]);
            let c = self.gcd(&b, g);
            if c.len() > 1 && c.len() < g.len() {
                let other = self.divrem(g, &c).0;
                self.split_equal_degree(&c, d, rng, out);
                self.split_equal_degree(&self.monic(&other), d, rng, out);
                return;
            }
        }
    }
}

// ------------------------------------------------------------------------------ Hensel

/// One quadratic Hensel step (von zur Gathen–Gerhard 15.10): from `f = g h`, `s g + t h = 1`
/// modulo `m`, `h` monic, to the same modulo `m^2`.
#[allow(clippy::type_complexity)]
fn hensel_step(
    f: &[BigInt],
    g: &[BigInt],
    h: &[BigInt],
    s: &[BigInt],
    t: &[BigInt],
    m2: &BigInt,
) -> (Vec<BigInt>, Vec<BigInt>, Vec<BigInt>, Vec<BigInt>) {
    let e = reduce(&sub_z(f, &mul_z(g, h)), m2);
    let (q, r) = divrem_monic_mod(&mul_z(s, &e), h, m2);
    let g2 = reduce(&add_z(&add_z(g, &mul_z(t, &e)), &mul_z(&q, g)), m2);
    let h2 = reduce(&add_z(h, &r), m2);
    let b = reduce(
        &sub_z(&add_z(&mul_z(s, &g2), &mul_z(t, &h2)), &[BigInt::one()]),
        m2,
    );
    let (c, d) = divrem_monic_mod(&mul_z(s, &b), &h2, m2);
    let s2 = reduce(&sub_z(s, &d), m2);
    let t2 = reduce(&sub_z(&sub_z(t, &mul_z(t, &b)), &mul_z(&c, &g2)), m2);
    (g2, h2, s2, t2)
}

/// The monic factors `u` of `f = lc(f) prod u (mod p)` lifted to modulo `p^(2^k) >= target`;
/// returns the lifted factors (monic, in `[0, m)`) and the modulus `m`.
fn hensel_lift(
    fp: &Fp,
    f: &[BigInt],
    factors: &[Vec<u64>],
    target: &BigInt,
) -> (Vec<Vec<BigInt>>, BigInt) {
    let p = BigInt::from(fp.0.modulus());
    let mut moduli = vec![p.clone()];
    while moduli.last().expect("non-empty") <= target {
        let m = moduli.last().expect("non-empty");
        moduli.push(m * m);
    }
    let big_m = moduli.last().expect("non-empty").clone();
    let to_z = |a: &[u64]| -> Vec<BigInt> { a.iter().map(|&c| BigInt::from(c)).collect() };
    let lc = fp.0.from_bigint(f.last().expect("non-zero"));
    let mut out = Vec::new();
    let mut current = reduce(f, &big_m);
    for i in 0..factors.len() - 1 {
        let h0 = factors[i].clone();
        let g0 = factors[i + 1..]
            .iter()
            .fold(vec![lc], |acc, u| fp.mul(&acc, u));
        let (s0, t0) = fp.bezout(&g0, &h0);
        let (mut g, mut h, mut s, mut t) = (to_z(&g0), to_z(&h0), to_z(&s0), to_z(&t0));
        for m2 in &moduli[1..] {
            (g, h, s, t) = hensel_step(&current, &g, &h, &s, &t, m2);
        }
        out.push(h);
        current = g;
    }
    // The last factor: current = lc * u (mod M); make it monic.
    let lc_inv = current
        .last()
        .expect("non-zero")
        .modinv(&big_m)
        .expect("the leading coefficient is a unit modulo p^k");
    out.push(reduce(
        &current.iter().map(|c| c * &lc_inv).collect::<Vec<_>>(),
        &big_m,
    ));
    (out, big_m)
}

// ------------------------------------------------------------------------------ driver

/// The irreducible factors over Z of the square-free, primitive `f` with positive leading
/// coefficient (each primitive with positive leading coefficient).
fn factor_square_free(f: &[BigInt], budget: &mut u64) -> Result<Vec<Vec<BigInt>>, LimitError> {
    let n = f.len() - 1;
    if n <= 1 {
        return Ok(vec![f.to_vec()]);
    }
    let mut out = Vec::new();
    let mut f = f.to_vec();
    // The factor x, split off so that the constant-term test below applies.
    if f[0].is_zero() {
        out.push(vec![BigInt::zero(), BigInt::one()]);
        f.remove(0);
        if f.len() <= 2 {
            out.push(primitive_z(&f));
            return Ok(out);
        }
    }
    let mut rng = Rng::new(0x5eed_fac7 ^ f.len() as u64);
    let lc = f.last().expect("non-zero").clone();
    // The prime with the fewest modular factors among a few; the factor degrees all of them
    // allow.
    let mut best: Option<(Fp, Vec<Vec<u64>>)> = None;
    let mut possible = vec![true; f.len()];
    let mut tried = 0;
    let mut candidate = FIRST_PRIME;
    while tried < PRIMES_TRIED {
        candidate += 1;
        if !is_prime_u64(candidate) {
            continue;
        }
        let fp = Fp(PrimeField::new(candidate).expect("an odd prime"));
        if fp.0.from_bigint(&lc) == 0 {
            continue;
        }
        let a = fp.reduce_z(&f);
        if fp.gcd(&a, &fp.derivative(&a)).len() != 1 {
            continue;
        }
        tried += 1;
        let factors = fp.factor(&fp.monic(&a), &mut rng);
        if factors.len() == 1 {
            out.push(f);
            return Ok(out);
        }
        let sums = subset_degree_sums(&factors, f.len() - 1);
        for (p, s) in possible.iter_mut().zip(sums) {
            *p &= s;
        }
        if !possible[1..f.len() - 1].iter().any(|&p| p) {
            // No proper factor degree is a subset sum for every prime: irreducible.
            out.push(f);
            return Ok(out);
        }
        if best.as_ref().is_none_or(|(_, b)| factors.len() < b.len()) {
            best = Some((fp, factors));
        }
    }
    let (fp, factors) = best.expect("some prime keeps a square-free polynomial square-free");
    // Mignotte: every coefficient of lc * g, g | f, is at most |lc| 2^n ||f||_2.
    let norm2: BigInt = f.iter().map(|c| c * c).sum::<BigInt>().sqrt() + 1;
    let bound = (lc.abs() * norm2) << n;
    let (lifted, m) = hensel_lift(&fp, &f, &factors, &(bound << 1usize));
    recombine(f, lifted, &m, &possible, budget, &mut out)?;
    Ok(out)
}

/// `sums[k]`: some of the modular `factors` have degrees adding up to `k` (`0 <= k <= n`).
fn subset_degree_sums(factors: &[Vec<u64>], n: usize) -> Vec<bool> {
    let mut sums = vec![false; n + 1];
    sums[0] = true;
    for u in factors {
        let d = u.len() - 1;
        for k in (d..=n).rev() {
            sums[k] |= sums[k - d];
        }
    }
    sums
}

/// Zassenhaus recombination of the lifted factors of `f` modulo `m` (module documentation);
/// `possible[k]`: a factor of the original polynomial may have degree `k` (every factor of `f`
/// is one).
fn recombine(
    mut f: Vec<BigInt>,
    mut pool: Vec<Vec<BigInt>>,
    m: &BigInt,
    possible: &[bool],
    budget: &mut u64,
    out: &mut Vec<Vec<BigInt>>,
) -> Result<(), LimitError> {
    let mut size = 1;
    'sizes: while 2 * size <= pool.len() {
        let lc = f.last().expect("non-zero").clone();
        let mut subset: Vec<usize> = (0..size).collect();
        loop {
            // Every subset enumerated counts, the pruned ones too: the limit bounds the work.
            if *budget == 0 {
                let limit = &limits::FACTOR_COMBINATIONS;
                return Err(limit.exceeded(format!("more than {}", limit.get())));
            }
            *budget -= 1;
            let degree: usize = subset.iter().map(|&i| pool[i].len() - 1).sum();
            let plausible = possible.get(degree).copied().unwrap_or(false) && {
                // Constant terms first: lc * prod u(0) must divide lc * f(0) up to the content.
                let c0 = subset.iter().fold(lc.clone(), |acc, &i| {
                    (acc * pool[i].first().cloned().unwrap_or_default()).mod_floor(m)
                });
                let c0 = symmetric(&[c0], m).pop().unwrap_or_default();
                f[0].is_zero() || c0.is_zero() || (&lc * &f[0]) % &c0 == BigInt::zero()
            };
            if plausible {
                let g = subset.iter().fold(vec![lc.clone()], |acc, &i| {
                    reduce(&mul_z(&acc, &pool[i]), m)
                });
                let g = primitive_z(&symmetric(&g, m));
                if let Some(q) = divide_exact_z(&f, &g) {
                    out.push(g);
                    f = primitive_z(&q);
                    for &i in subset.iter().rev() {
                        pool.remove(i);
                    }
                    continue 'sizes;
                }
            }
            // The next subset of this size, in lexicographic order.
            let k = pool.len();
            let Some(pos) = (0..size).rev().find(|&j| subset[j] < k - size + j) else {
                size += 1;
                continue 'sizes;
            };
            subset[pos] += 1;
            for j in pos + 1..size {
                subset[j] = subset[j - 1] + 1;
            }
        }
    }
    out.push(f);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn up(c: &[i64]) -> UPoly {
        UPoly::from_i64_coeffs(c)
    }

    /// The degrees a factor of `g` over Z can have by the factorisation patterns modulo four
    /// primes (from 101 up, away from the primes the factoriser uses): the degree of a true
    /// factor is a sum of degrees of modular factors for every prime. `possible[k]` false for
    /// every `0 < k < deg g` proves `g` irreducible independently of recombination.
    fn possible_factor_degrees(g: &UPoly) -> Vec<bool> {
        let f = integer_coeffs(g);
        let n = f.len() - 1;
        let mut possible = vec![true; n + 1];
        let mut rng = exactcheck_core::Rng::new(3);
        let mut used = 0;
        let mut p = 100;
        while used < 4 {
            p += 1;
            let Some(field) = PrimeField::new(p) else {
                continue;
            };
            let fp = Fp(field);
            let a = fp.reduce_z(&f);
            if a.len() != f.len() || fp.gcd(&a, &fp.derivative(&a)).len() != 1 {
                continue;
            }
            used += 1;
            let mut sums = vec![false; n + 1];
            sums[0] = true;
            for u in fp.factor(&fp.monic(&a), &mut rng) {
                let d = u.len() - 1;
                for k in (d..=n).rev() {
                    sums[k] |= sums[k - d];
                }
            }
            for k in 0..=n {
                possible[k] &= sums[k];
            }
        }
        possible
    }

    /// The properties every factorisation must have.
    fn check(p: &UPoly, f: &Factorisation) {
        assert_eq!(&f.expand(), p, "the product of the factors is the input");
        for (g, e) in &f.factors {
            assert!(*e >= 1 && g.degree() >= 1);
            assert_eq!(g, &g.primitive_part());
            assert!(g.leading_coefficient() > Rational::ZERO);
        }
    }

    #[test]
    fn small_factorisations() {
        // x^4 - 1 = (x - 1)(x + 1)(x^2 + 1)
        let f = up(&[-1, 0, 0, 0, 1]).factor().unwrap();
        check(&up(&[-1, 0, 0, 0, 1]), &f);
        let gs: Vec<UPoly> = f.factors.iter().map(|(g, _)| g.clone()).collect();
        assert_eq!(gs, vec![up(&[-1, 1]), up(&[1, 1]), up(&[1, 0, 1])]);
        // -6 x^3 (2x + 1)^2 (x^2 - 2)
        let p = up(&[0, 0, 0, -6])
            .mul_ref(&up(&[1, 2]).mul_ref(&up(&[1, 2])))
            .mul_ref(&up(&[-2, 0, 1]));
        let f = p.factor().unwrap();
        check(&p, &f);
        assert_eq!(f.content, Rational::from_integer(-6));
        assert_eq!(
            f.factors,
            vec![(up(&[0, 1]), 3), (up(&[1, 2]), 2), (up(&[-2, 0, 1]), 1)]
        );
        // Rational coefficients: x^2/4 - 1/9 = 1/36 (3x - 2)(3x + 2)
        let q = UPoly::from_coeffs(vec![
            Rational::new(-1, 9).unwrap(),
            Rational::ZERO,
            Rational::new(1, 4).unwrap(),
        ]);
        let f = q.factor().unwrap();
        check(&q, &f);
        assert_eq!(f.content, Rational::new(1, 36).unwrap());
        // Constants.
        let f = up(&[-5]).factor().unwrap();
        assert!(f.factors.is_empty() && f.content == Rational::from_integer(-5));
    }

    #[test]
    fn swinnerton_dyer_and_cyclotomic() {
        // x^4 - 10 x^2 + 1 (minimal polynomial of sqrt 2 + sqrt 3) is irreducible although it
        // factors modulo every prime.
        let s = up(&[1, 0, -10, 0, 1]);
        assert_eq!(s.irreducible_factors().unwrap(), vec![s.clone()]);
        // x^n - 1 is the product of the cyclotomic polynomials of the divisors of n.
        for n in [12usize, 30, 36, 60] {
            let mut c = vec![0i64; n + 1];
            c[0] = -1;
            c[n] = 1;
            let p = up(&c);
            let f = p.factor().unwrap();
            check(&p, &f);
            // One factor of degree phi(d) per divisor d.
            let totient = |d: usize| (1..=d).filter(|k| num_integer::gcd(*k, d) == 1).count();
            let mut want: Vec<usize> = (1..=n).filter(|d| n % d == 0).map(totient).collect();
            let mut got: Vec<usize> = f.factors.iter().map(|(g, _)| g.degree()).collect();
            want.sort_unstable();
            got.sort_unstable();
            assert_eq!(got, want, "x^{n} - 1");
        }
        // x^4 - 14 x^2 + 1 = (x^2 - 4x + 1)(x^2 + 4x + 1) (roots +-2 +-sqrt 3), times s.
        let t = up(&[1, 0, -14, 0, 1]);
        let p = s.mul_ref(&t);
        let f = p.factor().unwrap();
        check(&p, &f);
        let gs: Vec<UPoly> = f.factors.iter().map(|(g, _)| g.clone()).collect();
        assert_eq!(gs, vec![up(&[1, -4, 1]), up(&[1, 4, 1]), s]);
    }

    /// The Swinnerton-Dyer polynomial of the square roots of `primes`: the product of
    /// `x - (+-sqrt p1 +- ... +- sqrt pk)` over all signs, built without factoring as
    /// `s_{k+1}(x) = s_k(x - sqrt p) s_k(x + sqrt p) = A^2 - p B^2` for `s_k(x - sqrt p) = A + sqrt(p) B`.
    fn swinnerton_dyer(primes: &[i64]) -> UPoly {
        let mut s = up(&[0, 1]);
        for &p in primes {
            let (mut a, mut b) = (UPoly::zero(), UPoly::zero());
            let (mut pa, mut pb) = (UPoly::one(), UPoly::zero());
            let pq = UPoly::constant(Rational::from_integer(p));
            for c in s.coeffs() {
                a = a.add_ref(&pa.mul_ref(&UPoly::constant(c.clone())));
                b = b.add_ref(&pb.mul_ref(&UPoly::constant(c.clone())));
                // (pa + sqrt(p) pb)(x - sqrt(p)) = (x pa - p pb) + sqrt(p)(x pb - pa).
                let next_a = pa.mul_ref(&UPoly::x()).sub_ref(&pb.mul_ref(&pq));
                let next_b = pb.mul_ref(&UPoly::x()).sub_ref(&pa);
                pa = next_a;
                pb = next_b;
            }
            s = a.mul_ref(&a).sub_ref(&pq.mul_ref(&b.mul_ref(&b)));
        }
        s
    }

    #[test]
    fn swinnerton_dyer_polynomials_are_irreducible_or_refused() {
        // Degrees 16 and 32: irreducible over Q, products of linear and quadratic factors modulo
        // every prime (2^8 and 2^16 subsets of modular factors).
        for primes in [&[2i64, 3, 5, 7][..], &[2, 3, 5, 7, 11]] {
            let s = swinnerton_dyer(primes);
            assert_eq!(s.degree(), 1 << primes.len());
            let f = s
                .factor()
                .expect("within the default factor-combinations limit");
            check(&s, &f);
            assert_eq!(
                f.factors,
                vec![(s.clone(), 1)],
                "SD{primes:?} is irreducible"
            );
        }
        // With too small a budget the answer is the limit's error, never a partial
        // factorisation.
        let s = swinnerton_dyer(&[2, 3, 5, 7]);
        let err = factor_square_free(&integer_coeffs(&s), &mut 20).unwrap_err();
        assert_eq!(err.limit.name(), "factor-combinations");
        assert!(
            err.to_string()
                .contains("exceeds the limit factor-combinations"),
            "{err}"
        );
        // A product of two of them is found as the two factors, whatever the budget leaves.
        let t = swinnerton_dyer(&[2, 3, 5]);
        let p = s.mul_ref(&t);
        let f = p.factor().unwrap();
        check(&p, &f);
        assert_eq!(f.factors, vec![(t, 1), (s, 1)]);
    }

    #[test]
    fn degree_patterns_prove_irreducibility() {
        // x^4 + x + 1 is irreducible; patterns {1, 3} and {2, 2} of two primes leave no proper
        // factor degree (1 and 3 are not sums of 2 and 2, and 2 is not a sum of 1 and 3).
        let g = up(&[1, 1, 0, 0, 1]);
        let f = g.factor().unwrap();
        assert_eq!(f.factors, vec![(g.clone(), 1)]);
        let sums = subset_degree_sums(&[vec![1, 1], vec![1, 0, 0, 1]], 4);
        assert_eq!(sums, vec![true, true, false, true, true]);
    }

    /// A random integer polynomial of degree `d` from drawn coefficients (leading one non-zero).
    fn poly_of(c: &[i64]) -> UPoly {
        up(c)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// Products of random factors are factored back: the product of the factors is the
        /// input, every factor found is irreducible by the degree patterns modulo four primes
        /// (or has no proper factor degree those patterns allow), and every drawn factor is a
        /// product of found factors.
        #[test]
        fn products_factor_back(
            fs in proptest::collection::vec(
                (proptest::collection::vec(-9i64..=9, 2..=6), 1u32..=2), 1..=4),
            unit in (-5i64..=5).prop_filter("non-zero", |u| *u != 0),
        ) {
            let mut p = up(&[unit]);
            let mut drawn = Vec::new();
            for (c, e) in &fs {
                let g = poly_of(c);
                if g.degree() == 0 {
                    continue;
                }
                drawn.push(g.clone());
                for _ in 0..*e {
                    p = p.mul_ref(&g);
                }
            }
            let f = p.factor().unwrap();
            check(&p, &f);
            // Every drawn factor divides into found factors.
            for g in &drawn {
                let mut rest = g.primitive_part();
                for (h, _) in &f.factors {
                    while rest.degree() >= h.degree() && rest.div_rem(h).1.is_zero() {
                        rest = rest.div_rem(h).0;
                    }
                }
                prop_assert!(rest.is_constant(), "{g:?} is not a product of found factors");
            }
            // Irreducibility: no degree strictly between 0 and deg g is possible for every
            // prime's pattern, or g is checked irreducible by the rational-root theorem.
            for (g, _) in &f.factors {
                let possible = possible_factor_degrees(g);
                let n = g.degree();
                let proper = (1..n).any(|k| possible[k]);
                if proper && n <= 3 {
                    // Degrees 2 and 3: irreducible iff no rational root.
                    prop_assert!(g.isolate_roots().iter().all(|r| !r.is_exact()));
                } else if proper {
                    // Exhaustive check of the small cases: the factorisation of g alone
                    // finds g again.
                    prop_assert_eq!(g.irreducible_factors().unwrap(), vec![g.clone()]);
                }
            }
        }

        /// The multiset of factors of a product of distinct random monic-ish irreducible
        /// quadratics and linear factors equals the drawn multiset up to sign.
        #[test]
        fn drawn_irreducibles_come_back(
            quads in proptest::collection::vec((1i64..=7, -7i64..=7, 1i64..=9), 1..=5),
            lins in proptest::collection::vec((1i64..=5, -9i64..=9), 0..=3),
        ) {
            let mut p = UPoly::one();
            let mut drawn: Vec<UPoly> = Vec::new();
            // a x^2 + b x + c with b^2 - 4ac < 0 is irreducible.
            for (a, b, c) in quads {
                let g = up(&[c, b, a]);
                if b * b - 4 * a * c >= 0 || drawn.contains(&g.primitive_part()) {
                    continue;
                }
                drawn.push(g.primitive_part());
                p = p.mul_ref(&g);
            }
            for (a, b) in lins {
                let g = up(&[b, a]).primitive_part();
                let g = if g.leading_coefficient() < Rational::ZERO { -g } else { g };
                if drawn.contains(&g) {
                    continue;
                }
                drawn.push(g.clone());
                p = p.mul_ref(&g);
            }
            prop_assume!(!drawn.is_empty());
            let f = p.factor().unwrap();
            check(&p, &f);
            let mut found: Vec<UPoly> = f.factors.iter().map(|(g, _)| g.clone()).collect();
            let key = |g: &UPoly| (g.degree(), g.coeffs().to_vec());
            found.sort_by_key(key);
            drawn.sort_by_key(key);
            prop_assert_eq!(found, drawn);
        }
    }
}
