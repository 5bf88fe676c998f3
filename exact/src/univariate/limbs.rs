//! Fixed-width two's complement integer vectors for the Descartes subdivision
//! (`descartes.rs`): the `n + 1` integer Bernstein coefficients of one node stored in one flat
//! `Vec<u64>`, every coefficient in the same number `w` of 64-bit limbs, little-endian.
//!
//! de Casteljau's scheme at `1/2` on integers is `n(n+1)/2` additions of neighbours followed by
//! shifts (see the module documentation of `descartes`). With one `BigInt` per coefficient every
//! addition allocates and normalises; here an addition is a carry chain over `w` limbs in place,
//! with `w` fixed per node from the largest coefficient: the children's coefficients are at most
//! `n` bits longer than the parent's (each entry of the triangle is a sum of at most `2^n`
//! parent coefficients, and the shifts add `n - i` bits to an entry of `i` additions), so `w`
//! is chosen once, for `max bits + n + 1` (sign) bits, and no addition can overflow. After the
//! split the common power of two is divided out and `w` shrunk to the children's size.
//!
//! Hand-written because num-bigint has no fixed-width vector type; the operations are the four
//! used by the subdivision (add, shift left, arithmetic shift right, sign). The `BigInt`
//! version (`descartes::split_half`) is the reference of the tests.

use num_bigint::BigInt;

/// The coefficients of one node: `len` numbers of `w` limbs each, two's complement.
#[derive(Clone, Debug)]
pub(super) struct Limbs {
    w: usize,
    d: Vec<u64>,
}

/// `a += b` over equal-length limb slices (two's complement, the carry out dropped).
#[inline]
fn add_assign(a: &mut [u64], b: &[u64]) {
    let mut carry = false;
    for (x, &y) in a.iter_mut().zip(b) {
        let (s1, c1) = x.overflowing_add(y);
        let (s2, c2) = s1.overflowing_add(carry as u64);
        *x = s2;
        carry = c1 | c2;
    }
}

/// [`Limbs::taylor_shift_1`] on numbers of exactly `W` limbs.
fn taylor_shift_fixed<const W: usize>(d: &mut [u64]) {
    debug_assert_eq!(d.len() % W, 0);
    // On a copy as W-limb arrays (values, so the loop indexes without aliasing questions).
    let mut a: Vec<[u64; W]> = d
        .chunks_exact(W)
        .map(|c| c.try_into().expect("W limbs"))
        .collect();
    let n = a.len() - 1;
    for i in 0..n {
        // a_j += a_(j+1) from the top down: the new a_(j+1) is the previous step's x.
        let mut y = a[n];
        for x in a[i..n].iter_mut().rev() {
            add_assign(x, &y);
            y = *x;
        }
    }
    for (c, x) in d.chunks_exact_mut(W).zip(&a) {
        c.copy_from_slice(x);
    }
}

/// `dst = src << s` (same length, the bits above dropped).
#[inline]
fn shl_into(dst: &mut [u64], src: &[u64], s: usize) {
    let (q, r) = (s / 64, s % 64);
    let w = dst.len();
    for t in (0..w).rev() {
        let hi = if t >= q { src[t - q] } else { 0 };
        let lo = if t > q { src[t - q - 1] } else { 0 };
        dst[t] = if r == 0 {
            hi
        } else {
            (hi << r) | (lo >> (64 - r))
        };
    }
}

/// `x >>= s` arithmetically (sign-filled).
#[inline]
fn sar_in_place(x: &mut [u64], s: usize) {
    let w = x.len();
    let fill = if (x[w - 1] as i64) < 0 { u64::MAX } else { 0 };
    let (q, r) = (s / 64, s % 64);
    let get = |x: &[u64], t: usize| if t < w { x[t] } else { fill };
    for t in 0..w {
        let lo = get(x, t + q);
        let hi = get(x, t + q + 1);
        x[t] = if r == 0 {
            lo
        } else {
            (lo >> r) | (hi << (64 - r))
        };
    }
}

/// The sign of the two's complement number `x` and its magnitude (`x` itself, or its negation
/// in `scratch`, of the same length).
fn magnitude<'a>(x: &'a [u64], scratch: &'a mut [u64]) -> (bool, &'a [u64]) {
    if (x[x.len() - 1] as i64) < 0 {
        scratch.copy_from_slice(x);
        crate::bigint::negate_twos_complement(scratch);
        (true, scratch)
    } else {
        (false, x)
    }
}

/// The number of bits of `x` as a two's complement number without its redundant sign bits
/// (the sign bit included): `x` fits in this many bits.
fn signed_bits(x: &[u64]) -> usize {
    let neg = (x[x.len() - 1] as i64) < 0;
    for t in (0..x.len()).rev() {
        let v = if neg { !x[t] } else { x[t] };
        if v != 0 {
            return t * 64 + (64 - v.leading_zeros() as usize) + 1;
        }
    }
    1
}

impl Limbs {
    /// The numbers `b`, each in the least common number of limbs.
    pub(super) fn from_bigints(b: &[BigInt]) -> Limbs {
        Limbs::from_bigints_with_room(b, 0)
    }

    /// The numbers `b` in a common number of limbs with room for `extra` more bits.
    pub(super) fn from_bigints_with_room(b: &[BigInt], extra: usize) -> Limbs {
        Limbs::from_bigints_ordered(b, extra, false)
    }

    /// [`Limbs::from_bigints_with_room`] of `b` in reverse order (the reversal of a
    /// polynomial), without cloning the numbers.
    pub(super) fn from_bigints_reversed_with_room(b: &[BigInt], extra: usize) -> Limbs {
        Limbs::from_bigints_ordered(b, extra, true)
    }

    fn from_bigints_ordered(b: &[BigInt], extra: usize, reversed: bool) -> Limbs {
        let bits = b.iter().map(|c| c.bits() as usize + 1).max().unwrap_or(1) + extra;
        let w = bits.div_ceil(64).max(1);
        let mut d = vec![0u64; w * b.len()];
        let last = b.len().saturating_sub(1);
        for (i, x) in d.chunks_mut(w).enumerate() {
            let c = &b[if reversed { last - i } else { i }];
            for (limb, digit) in x.iter_mut().zip(c.magnitude().iter_u64_digits()) {
                *limb = digit;
            }
            if c.sign() == num_bigint::Sign::Minus {
                crate::bigint::negate_twos_complement(x);
            }
        }
        Limbs { w, d }
    }

    /// The numbers as `BigInt`s.
    pub(super) fn to_bigints(&self) -> Vec<BigInt> {
        let mut mag = vec![0u64; self.w];
        self.d
            .chunks(self.w)
            .map(|x| {
                let neg = (x[self.w - 1] as i64) < 0;
                mag.copy_from_slice(x);
                if neg {
                    crate::bigint::negate_twos_complement(&mut mag);
                }
                let m = BigInt::from(crate::bigint::biguint_from_limbs(&mag));
                if neg {
                    -m
                } else {
                    m
                }
            })
            .collect()
    }

    /// The limbs per number.
    #[cfg(test)]
    pub(super) fn width(&self) -> usize {
        self.w
    }

    /// How many numbers.
    pub(super) fn len(&self) -> usize {
        self.d.len() / self.w
    }

    fn get(&self, i: usize) -> &[u64] {
        &self.d[i * self.w..(i + 1) * self.w]
    }

    /// The sign of number `i`: -1, 0 or 1.
    pub(super) fn sign(&self, i: usize) -> i8 {
        let x = self.get(i);
        if (x[self.w - 1] as i64) < 0 {
            -1
        } else if x.iter().all(|&l| l == 0) {
            0
        } else {
            1
        }
    }

    /// The same numbers in `w` limbs (`w` at least the bits they need).
    fn resized(&self, w: usize) -> Limbs {
        let mut d = Vec::with_capacity(w * self.len());
        for x in self.d.chunks(self.w) {
            let fill = if (x[self.w - 1] as i64) < 0 {
                u64::MAX
            } else {
                0
            };
            let keep = w.min(self.w);
            d.extend_from_slice(&x[..keep]);
            d.resize(d.len() + (w - keep), fill);
        }
        Limbs { w, d }
    }

    /// Divides every number by the common power of two of the non-zero ones and shrinks the
    /// limb count to the largest.
    fn normalise(mut self) -> Limbs {
        let w = self.w;
        let tz = self
            .d
            .chunks(w)
            .filter_map(|x| {
                x.iter()
                    .position(|&l| l != 0)
                    .map(|t| t * 64 + x[t].trailing_zeros() as usize)
            })
            .min()
            .unwrap_or(0);
        if tz > 0 {
            for x in self.d.chunks_mut(w) {
                sar_in_place(x, tz);
            }
        }
        let bits = self.d.chunks(w).map(signed_bits).max().unwrap_or(1);
        let need = bits.div_ceil(64).max(1);
        if need < w {
            self.resized(need)
        } else {
            self
        }
    }

    /// `a(x + 1)` in place for the polynomial with these coefficients (constant term first),
    /// `n(n+1)/2` additions; the caller leaves room for `n` more bits
    /// ([`Limbs::from_bigints_with_room`]).
    pub(super) fn taylor_shift_1(&mut self) {
        // The usual widths with the limb count known to the compiler (carry chains unrolled).
        match self.w {
            1 => taylor_shift_fixed::<1>(&mut self.d),
            2 => taylor_shift_fixed::<2>(&mut self.d),
            3 => taylor_shift_fixed::<3>(&mut self.d),
            4 => taylor_shift_fixed::<4>(&mut self.d),
            w => {
                let n = self.len() - 1;
                for i in 0..n {
                    for j in (i..n).rev() {
                        let (lo, hi) = self.d.split_at_mut((j + 1) * w);
                        add_assign(&mut lo[j * w..], &hi[..w]);
                    }
                }
            }
        }
    }

    /// de Casteljau at `1/2` without the halvings: the two halves, each `2^n` times the true
    /// Bernstein coefficients, over their common power of two (as `descartes::split_half`).
    pub(super) fn split_half(&self) -> (Limbs, Limbs) {
        let len = self.len();
        let n = len - 1;
        let bits = self.d.chunks(self.w).map(signed_bits).max().unwrap_or(1);
        let w = (bits + n + 1).div_ceil(64);
        let mut work = self.resized(w).d;
        let mut left = vec![0u64; len * w];
        let mut right = vec![0u64; len * w];
        shl_into(&mut left[..w], &work[..w], n);
        shl_into(&mut right[n * w..], &work[n * w..], n);
        for k in 1..=n {
            for i in 0..=n - k {
                let (lo, hi) = work.split_at_mut((i + 1) * w);
                add_assign(&mut lo[i * w..], &hi[..w]);
            }
            shl_into(&mut left[k * w..(k + 1) * w], &work[..w], n - k);
            shl_into(
                &mut right[(n - k) * w..(n - k + 1) * w],
                &work[(n - k) * w..(n - k + 1) * w],
                n - k,
            );
        }
        (
            Limbs { w, d: left }.normalise(),
            Limbs { w, d: right }.normalise(),
        )
    }
}

impl Limbs {
    /// For every number `x` (in order): its sign (`true` when negative), the 64 leading bits
    /// `t` of `|x|` and their position `s`, so that `|x| = t 2^s + r` with `0 <= r < 2^s`, and
    /// `t >= 2^63` whenever `s > 0` (`t = |x|`, `s = 0` when `|x| < 2^64`). The exact input of a
    /// correctly bounded conversion to `f64` (`descartes::filtered`).
    pub(super) fn leading_bits(&self, mut f: impl FnMut(bool, u64, u64)) {
        let w = self.w;
        let mut scratch = vec![0u64; w];
        for x in self.d.chunks(w) {
            let (neg, m) = magnitude(x, &mut scratch);
            match m.iter().rposition(|&l| l != 0) {
                None => f(false, 0, 0),
                Some(0) => f(neg, m[0], 0),
                Some(t) => {
                    let z = m[t].leading_zeros();
                    let top = if z == 0 {
                        m[t]
                    } else {
                        (m[t] << z) | (m[t - 1] >> (64 - z))
                    };
                    f(neg, top, 64 * t as u64 - u64::from(z))
                }
            }
        }
    }

    /// The numbers times `2^-s` in `f64`, `s` common (the largest lands near `2^64`), from the
    /// two leading limbs of each magnitude: a relative error below `2^-52` each; for estimates
    /// only (nothing is decided on them).
    pub(super) fn scaled_f64s(&self) -> Vec<f64> {
        let w = self.w;
        let mut scratch = vec![0u64; w];
        let mut mags: Vec<(bool, f64, usize)> = Vec::with_capacity(self.len());
        for x in self.d.chunks(w) {
            let (neg, m) = magnitude(x, &mut scratch);
            match m.iter().rposition(|&l| l != 0) {
                None => mags.push((false, 0.0, 0)),
                Some(t) => {
                    let lo = if t > 0 { m[t - 1] } else { 0 };
                    let v = m[t] as f64 * 18446744073709551616.0 + lo as f64;
                    mags.push((neg, v, t));
                }
            }
        }
        let top = mags.iter().map(|&(_, _, t)| t).max().unwrap_or(0);
        mags.into_iter()
            .map(|(neg, v, t)| {
                let x = v * super::pow2f(64 * (t as i64 - top as i64) - 64);
                if neg {
                    -x
                } else {
                    x
                }
            })
            .collect()
    }
}

impl Limbs {
    /// The numbers `x_(n-i) m_i` for `i = 0..=n` (reversed, each times its word), one limb
    /// wider.
    pub(super) fn reversed_times_words(&self, m: &[u64]) -> Limbs {
        let (w, len) = (self.w, self.len());
        assert_eq!(m.len(), len, "one multiplier per number");
        let wide = self.resized(w + 1);
        let mut d = vec![0u64; len * (w + 1)];
        for (i, out) in d.chunks_mut(w + 1).enumerate() {
            crate::bigint::mul_1_add_in_place(out, wide.get(len - 1 - i), m[i], false);
        }
        Limbs { w: w + 1, d }
    }
}

impl Limbs {
    /// The sign (-1, 0, 1) of `sum_i a_i m^i 2^(k (n - i))` for the polynomial `a` with these
    /// coefficients (`n = len - 1`) and a word `0 < m < 2^k`: `2^(k n) a(m / 2^k)`, the sign of
    /// `a` at the dyadic point `m / 2^k`. Horner's scheme in a fixed width that holds every
    /// partial sum: `|sum_(l >= i) a_l m^(l - i) 2^(k (n - l))| < (n + 1) 2^(A + k (n - i))`,
    /// `A` the coefficients' bit length, so `A + k n + log2(n + 1) + 2` bits suffice.
    pub(super) fn sign_at_dyadic(&self, m: u64, k: u64) -> i8 {
        let len = self.len();
        let n = len - 1;
        debug_assert!(m > 0 && (k >= 64 || m < 1u64 << k));
        let a_bits = self.d.chunks(self.w).map(signed_bits).max().unwrap_or(1);
        let bits = a_bits + (k as usize) * n + (usize::BITS - len.leading_zeros()) as usize + 2;
        let w = bits.div_ceil(64);
        let wide = self.resized(w);
        let mut acc = vec![0u64; w];
        let mut term = vec![0u64; w];
        for i in (0..=n).rev() {
            // acc = acc m + a_i 2^(k (n - i))
            let mut carry = 0u64;
            for x in acc.iter_mut() {
                let p = u128::from(*x) * u128::from(m) + u128::from(carry);
                *x = p as u64;
                carry = (p >> 64) as u64;
            }
            shl_into(&mut term, wide.get(i), (k as usize) * (n - i));
            add_assign(&mut acc, &term);
        }
        if (acc[w - 1] as i64) < 0 {
            -1
        } else if acc.iter().all(|&l| l == 0) {
            0
        } else {
            1
        }
    }
}

// ------------------------------------------------------------------------ linear factors

/// The limb count with which [`Limbs::divide_by_linear`] can certify every linear factor of
/// the integer polynomial `a` (not zero, degree `n`): every factor `g` of `a` over `Z` has
/// `|g|_inf <= |g|_1 <= 2^(deg g) |a|_2 <= 2^n sqrt(n + 1) max |a_i|` (Mignotte's bound, the
/// leading coefficient of `g` dividing that of `a`), so its coefficients have at most
/// `B = bits(max |a_i|) + n + ceil(log2(n + 1) / 2)` bits; the division's certificate needs
/// 67 more, and a sign bit.
pub(super) fn linear_factor_width(a: &[BigInt]) -> usize {
    let n = a.len().saturating_sub(1);
    let bits = a.iter().map(|c| c.bits() as usize).max().unwrap_or(0);
    let log_half = (usize::BITS - n.leading_zeros()) as usize / 2 + 1;
    (bits + n + log_half + 67 + 1).div_ceil(64)
}

impl Limbs {
    /// The numbers `b` in exactly `w` limbs each.
    ///
    /// # Panics
    /// If a number needs more than `64 w` bits (sign included).
    pub(super) fn from_bigints_width(b: &[BigInt], w: usize) -> Limbs {
        let l = Limbs::from_bigints(b);
        assert!(
            l.w <= w,
            "from_bigints_width: a number needs more than {w} limbs"
        );
        l.resized(w)
    }

    /// The numbers `v` in exactly `w >= 2` limbs each (two's complement, sign-extended).
    pub(super) fn from_i128s(v: &[i128], w: usize) -> Limbs {
        assert!(w >= 2, "from_i128s: an i128 needs two limbs");
        let mut d = vec![0u64; w * v.len()];
        for (x, &c) in d.chunks_mut(w).zip(v) {
            let ext = if c < 0 { u64::MAX } else { 0 };
            x[0] = c as u64;
            x[1] = (c >> 64) as u64;
            x[2..].fill(ext);
        }
        Limbs { w, d }
    }

    /// The numbers as `i128`s, `None` when one of them does not fit.
    pub(super) fn to_i128s(&self) -> Option<Vec<i128>> {
        self.d
            .chunks(self.w)
            .map(|x| {
                if signed_bits(x) > 128 {
                    return None;
                }
                let hi = if self.w > 1 {
                    x[1]
                } else if (x[0] as i64) < 0 {
                    u64::MAX
                } else {
                    0
                };
                Some(((u128::from(hi) << 64) | u128::from(x[0])) as i128)
            })
            .collect()
    }

    /// The quotient `a / (q x - p)` of the polynomial `a` with these coefficients (constant
    /// term first, degree `n >= 1`) when `q x - p` divides it over `Z` (`q > 0`, `p != 0`,
    /// `gcd(p, q) = 1`), `None` otherwise; the quotient has `n` coefficients of the same
    /// width.
    ///
    /// Synthetic division in the ring `Z / 2^(64 w)`, where every step is a multiply-add by a
    /// word and a Hensel division, fused in one pass
    /// ([`crate::bigint::mul_1_add_hensel_in_place`]): by `q` from the
    /// top (`s_(n-1) = a_n / q`, `s_(k-1) = (a_k + p s_k) / q`, then `a_0 + p s_0 = 0` checked)
    /// when `q` is odd, else by `-p` from the bottom (`s_0 = a_0 / (-p)`,
    /// `s_k = (q s_(k-1) - a_k) / p`, then `q s_(n-1) = a_n` checked); `p` and `q` are coprime,
    /// so one of them is odd, hence invertible modulo `2^(64 w)`. The checks make
    /// `(q x - p) s = a` hold modulo `2^(64 w)`. **Certificate:** when moreover every `s_k`
    /// (read as two's complement) has at most `64 w - 66` bits, both sides of that congruence
    /// lie in `(-2^(64 w - 1), 2^(64 w - 1))` (`|q s_(k-1) - p s_k| < 2^(64 w - 3)`, and `a`'s
    /// coefficients fit in `w` limbs), so they are equal over `Z`. Conversely, when `q x - p`
    /// divides `a`, the ring quotient is the integer quotient (the division by an invertible
    /// element is unique), which fits when `w` is at least [`linear_factor_width`]`(a)`: no
    /// divisor is missed at that width.
    pub(super) fn divide_by_linear(&self, p: i64, q: i64) -> Option<Limbs> {
        use crate::bigint::{
            hensel_div_1_in_place, inverse_mod_2_64, mul_1_add_hensel_in_place, mul_1_add_in_place,
            negate_twos_complement,
        };
        let (w, len) = (self.w, self.len());
        assert!(
            q > 0 && p != 0 && len >= 2,
            "divide_by_linear: q > 0, p != 0, degree >= 1"
        );
        let n = len - 1;
        let (pm, qm) = (p.unsigned_abs(), q as u64);
        // The quotient's coefficients, each step one fused multiply-add and Hensel division.
        let mut s;
        if qm & 1 == 1 {
            let inv = inverse_mod_2_64(qm);
            // s_(k-1) = (a_k + p s_k) / q, s_n = 0 (s_(k-1) starts as a_k).
            s = self.d[w..].to_vec();
            hensel_div_1_in_place(&mut s[(n - 1) * w..], qm, inv);
            for k in (1..n).rev() {
                let (lo, hi) = s.split_at_mut(k * w);
                mul_1_add_hensel_in_place(&mut lo[(k - 1) * w..], &hi[..w], pm, p < 0, qm, inv);
            }
            let mut r = self.get(0).to_vec();
            mul_1_add_in_place(&mut r, &s[..w], pm, p < 0);
            if r.iter().any(|&l| l != 0) {
                return None;
            }
        } else {
            debug_assert!(pm & 1 == 1, "p and q are coprime");
            let inv = inverse_mod_2_64(pm);
            s = self.d[..n * w].to_vec();
            // s_k = (q s_(k-1) - a_k) / p, s_(-1) = 0: for p > 0 as (-a_k + q s_(k-1)) / p,
            // for p < 0 as (a_k - q s_(k-1)) / |p| (s_k starts as a_k, negated when p > 0).
            if p > 0 {
                for x in s.chunks_mut(w) {
                    negate_twos_complement(x);
                }
            }
            hensel_div_1_in_place(&mut s[..w], pm, inv);
            for k in 1..n {
                let (lo, hi) = s.split_at_mut(k * w);
                mul_1_add_hensel_in_place(&mut hi[..w], &lo[(k - 1) * w..], qm, p < 0, pm, inv);
            }
            let mut r = self.get(n).to_vec();
            mul_1_add_in_place(&mut r, &s[(n - 1) * w..], qm, true);
            if r.iter().any(|&l| l != 0) {
                return None;
            }
        }
        s.chunks(w)
            .all(|x| signed_bits(x) <= 64 * w - 66)
            .then_some(Limbs { w, d: s })
    }
}

// ------------------------------------------------------------------------ dyadic evaluation

/// An integer polynomial prepared for exact evaluation at dyadic points `m / 2^k` whose
/// numerator is a word (`|m| < 2^64`), the refinement's evaluation points: each coefficient's
/// sign and magnitude limbs, extracted once.
///
/// Horner's scheme runs on one two's complement limb vector per value, in place: a step is a
/// multiplication by the word `|m|` (one `u128` product per limb) and the addition of the
/// coefficient at its bit offset `k (n - i)` (a carry chain over its own limbs, propagated only
/// while it carries), where the `BigInt` scheme (`PairSplitter::eval`, the tests' reference)
/// allocates a shifted copy of every coefficient and a product per step. The vector grows with
/// the bound on the partial sums, so early steps touch few limbs.
pub(super) struct DyadicHorner {
    /// `(negative, magnitude limbs)` from the constant term up.
    coeffs: Vec<(bool, Vec<u64>)>,
    /// The largest coefficient bit length.
    a_bits: usize,
}

/// `v *= m` modulo `2^(64 len)` (exact for two's complement values that fit).
#[inline]
fn mul_word(v: &mut [u64], m: u64) {
    let mut carry = 0u64;
    for x in v.iter_mut() {
        let p = u128::from(*x) * u128::from(m) + u128::from(carry);
        *x = p as u64;
        carry = (p >> 64) as u64;
    }
}

/// `v += (-1)^neg mag 2^s` modulo `2^(64 len)`; the carry (borrow) stops as soon as it is 0.
#[inline]
fn add_shifted(v: &mut [u64], neg: bool, mag: &[u64], s: usize) {
    let (q, r) = (s / 64, s % 64);
    let len = v.len();
    let mut carry = false;
    let mut t = 0;
    while t <= mag.len() {
        let hi = mag.get(t).copied().unwrap_or(0);
        let lo = if t > 0 { mag[t - 1] } else { 0 };
        let limb = if r == 0 {
            hi
        } else {
            (hi << r) | (lo >> (64 - r))
        };
        let idx = q + t;
        if idx >= len {
            // A carry (borrow) out of the top limb is the wrap of two's complement arithmetic
            // modulo 2^(64 len) (a negative addend meeting a positive value), as in the tail
            // loop below; only a non-zero limb past the end would be an overflow.
            debug_assert!(limb == 0, "add_shifted: the value does not fit");
            return;
        }
        if neg {
            let (d1, b1) = v[idx].overflowing_sub(limb);
            let (d2, b2) = d1.overflowing_sub(u64::from(carry));
            v[idx] = d2;
            carry = b1 | b2;
        } else {
            let (s1, c1) = v[idx].overflowing_add(limb);
            let (s2, c2) = s1.overflowing_add(u64::from(carry));
            v[idx] = s2;
            carry = c1 | c2;
        }
        t += 1;
    }
    let mut idx = q + t;
    while carry && idx < len {
        if neg {
            let (d, b) = v[idx].overflowing_sub(1);
            v[idx] = d;
            carry = b;
        } else {
            let (s, c) = v[idx].overflowing_add(1);
            v[idx] = s;
            carry = c;
        }
        idx += 1;
    }
}

/// `v` extended to `len` limbs by its sign.
#[inline]
fn sign_extend(v: &mut Vec<u64>, len: usize) {
    if len > v.len() {
        let fill = if v.last().is_some_and(|&l| (l as i64) < 0) {
            u64::MAX
        } else {
            0
        };
        v.resize(len, fill);
    }
}

/// The two's complement number `v` as a `BigInt`.
fn twos_complement_to_bigint(mut v: Vec<u64>) -> BigInt {
    let neg = v.last().is_some_and(|&l| (l as i64) < 0);
    if neg {
        crate::bigint::negate_twos_complement(&mut v);
    }
    let m = BigInt::from(crate::bigint::biguint_from_limbs(&v));
    if neg {
        -m
    } else {
        m
    }
}

impl DyadicHorner {
    /// The polynomial with these coefficients (constant term first, at least one).
    pub(super) fn new(a: &[BigInt]) -> DyadicHorner {
        let coeffs = a
            .iter()
            .map(|c| {
                (
                    c.sign() == num_bigint::Sign::Minus,
                    c.magnitude().iter_u64_digits().collect(),
                )
            })
            .collect();
        let a_bits = a.iter().map(|c| c.bits() as usize).max().unwrap_or(0);
        DyadicHorner { coeffs, a_bits }
    }

    /// The sign (-1, 0, 1) of `a(m / 2^k)` from Horner's scheme with `P` fraction bits,
    /// truncated (floor) after every multiplication, when the error bound decides it; `None`
    /// when it does not or `|m| >= 2^64` (the caller evaluates exactly then).
    ///
    /// With `x = m / 2^k`, `|x| < 2^e`, the scheme computes `t_i = floor(t_(i+1) x) + a_i 2^P`
    /// from `t_n = a_n 2^P`; its error against `2^P` times the exact partial sum obeys
    /// `|err_i| <= 1 + |x| |err_(i+1)|`, so `|err_0| < (n + 1) 2^(e n)`, and a result of at
    /// least `2^(bits(n + 1) + e n)` in magnitude has the sign of `a(x)`. `P = 128 + e n +
    /// bits(n + 1)` leaves the filter undecided only where `|a(x)| < 2^-127` or so. The vector
    /// holds the partial sums (`(n + 1) 2^(A + e (n - i))` times `2^P`, plus the error) and
    /// the product before the shift (`k + e` bits more), so nothing overflows.
    pub(super) fn sign_truncated(&self, m: &BigInt, k: u64) -> Option<i8> {
        if m.bits() > 64 || k > 4096 {
            return None;
        }
        let neg_m = m.sign() == num_bigint::Sign::Minus;
        let mu = m.magnitude().iter_u64_digits().next().unwrap_or(0);
        let n = self.coeffs.len() - 1;
        let k = k as usize;
        let e = (64 - mu.leading_zeros() as usize).saturating_sub(k);
        let nb = (usize::BITS - (n + 1).leading_zeros()) as usize;
        let threshold = nb + e * n;
        let frac = 128 + threshold;
        let bits = frac + self.a_bits + e * n + nb + 2 + k + e + 1;
        let w = bits.div_ceil(64);
        let neg_at = |i: usize| self.coeffs[i].0 ^ (neg_m && i % 2 == 1);
        let mut t = vec![0u64; w];
        add_shifted(&mut t, neg_at(n), &self.coeffs[n].1, frac);
        for i in (0..n).rev() {
            mul_word(&mut t, mu);
            sar_in_place(&mut t, k);
            add_shifted(&mut t, neg_at(i), &self.coeffs[i].1, frac);
        }
        // |t| >= 2^threshold: a magnitude of more than `threshold` bits.
        if signed_bits(&t) > threshold + 1 {
            Some(if (t[w - 1] as i64) < 0 { -1 } else { 1 })
        } else {
            None
        }
    }

    /// `2^(k n) a(m / 2^k)` and, when `derivative`, `2^(k (n - 1)) a'(m / 2^k)` (else 0), both
    /// exact; `None` when `|m| >= 2^64` (the caller evaluates on `BigInt`s then).
    ///
    /// With `|m| < 2^B` and `2^k <= 2^B`, the partial sums of the value after the coefficient
    /// of degree `i` are `sum_(l >= i) a_l m^(l - i) 2^(k (n - l))`, below
    /// `(n + 1) 2^(A + B (n - i))` in magnitude (`A` the coefficients' bit length), and those
    /// of the derivative below `n (n + 1) 2^(A + B (n - i))`; the vectors hold
    /// `A + B (n - i) + 2 bits(n + 1) + 2` bits at that step, so nothing overflows. A negative
    /// `m` is evaluated as `a(-y)` at `y = |m| / 2^k` (odd coefficients negated), the
    /// derivative negated back.
    pub(super) fn eval(&self, m: &BigInt, k: u64, derivative: bool) -> Option<(BigInt, BigInt)> {
        if m.bits() > 64 {
            return None;
        }
        let neg_m = m.sign() == num_bigint::Sign::Minus;
        let mu = m.magnitude().iter_u64_digits().next().unwrap_or(0);
        let n = self.coeffs.len() - 1;
        let b = (64 - mu.leading_zeros() as usize).max(k as usize);
        let slack = 2 * (usize::BITS - (n + 1).leading_zeros()) as usize + 2;
        let limbs_at = |i: usize| (self.a_bits + b * (n - i) + slack).div_ceil(64);
        let neg_at = |i: usize| self.coeffs[i].0 ^ (neg_m && i % 2 == 1);
        let mut p: Vec<u64> = vec![0; limbs_at(n)];
        add_shifted(&mut p, neg_at(n), &self.coeffs[n].1, 0);
        let mut d: Vec<u64> = Vec::new();
        for i in (0..n).rev() {
            let len = limbs_at(i);
            sign_extend(&mut p, len);
            if derivative {
                // d = d m + p (before p's step)
                sign_extend(&mut d, len);
                mul_word(&mut d, mu);
                add_assign(&mut d, &p);
            }
            mul_word(&mut p, mu);
            add_shifted(&mut p, neg_at(i), &self.coeffs[i].1, (k as usize) * (n - i));
        }
        let value = twos_complement_to_bigint(p);
        let slope = if derivative && !d.is_empty() {
            let s = twos_complement_to_bigint(d);
            if neg_m {
                -s
            } else {
                s
            }
        } else {
            BigInt::from(0)
        };
        Some((value, slope))
    }
}
