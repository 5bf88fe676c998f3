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
        let bits = b.iter().map(|c| c.bits() as usize + 1).max().unwrap_or(1) + extra;
        let w = bits.div_ceil(64).max(1);
        let mut d = Vec::with_capacity(w * b.len());
        for c in b {
            let bytes = c.to_signed_bytes_le();
            let fill = if c.sign() == num_bigint::Sign::Minus {
                0xff
            } else {
                0
            };
            for t in 0..w {
                let mut limb = [fill; 8];
                for (k, byte) in limb.iter_mut().enumerate() {
                    if let Some(&v) = bytes.get(t * 8 + k) {
                        *byte = v;
                    }
                }
                d.push(u64::from_le_bytes(limb));
            }
        }
        Limbs { w, d }
    }

    /// The numbers as `BigInt`s.
    pub(super) fn to_bigints(&self) -> Vec<BigInt> {
        self.d
            .chunks(self.w)
            .map(|x| {
                let bytes: Vec<u8> = x.iter().flat_map(|l| l.to_le_bytes()).collect();
                BigInt::from_signed_bytes_le(&bytes)
            })
            .collect()
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
            d.extend(x.iter().copied().chain(std::iter::repeat(fill)).take(w));
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
        let w = self.w;
        let n = self.len() - 1;
        for i in 0..n {
            for j in (i..n).rev() {
                let (lo, hi) = self.d.split_at_mut((j + 1) * w);
                add_assign(&mut lo[j * w..], &hi[..w]);
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
            let neg = (x[w - 1] as i64) < 0;
            let m: &[u64] = if neg {
                let mut carry = true;
                for (d, &l) in scratch.iter_mut().zip(x) {
                    let (v, c) = (!l).overflowing_add(carry as u64);
                    *d = v;
                    carry = c;
                }
                &scratch
            } else {
                x
            };
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
            let neg = (x[w - 1] as i64) < 0;
            let m: &[u64] = if neg {
                let mut carry = true;
                for (d, &l) in scratch.iter_mut().zip(x) {
                    let (v, c) = (!l).overflowing_add(carry as u64);
                    *d = v;
                    carry = c;
                }
                &scratch
            } else {
                x
            };
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
                let x = v * (64.0 * (t as f64 - top as f64) - 64.0).exp2();
                if neg {
                    -x
                } else {
                    x
                }
            })
            .collect()
    }
}
