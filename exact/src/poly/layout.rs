//! The packed monomial layout: exponent vectors in fixed-width fields of `u64` words, the
//! monomial order on them, and repacking between widths.

use super::*;
use std::cmp::Ordering;

/// How the exponent vectors of one polynomial are packed: the field width and the number of
/// words per monomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Shape {
    pub(super) bits: u32,
    pub(super) words: usize,
}

/// The guard bits (top bit of every field) for a field width.
#[inline]
pub(super) const fn guard_mask(bits: u32) -> u64 {
    match bits {
        8 => 0x8080_8080_8080_8080,
        16 => 0x8000_8000_8000_8000,
        32 => 0x8000_0000_8000_0000,
        _ => 0x8000_0000_0000_0000,
    }
}

/// The smallest field width whose fields hold `e` below their guard bit, `None` beyond
/// [`MAX_EXP`].
#[inline]
pub(super) fn bits_for(e: u64) -> Option<u32> {
    Some(if e < 1 << 7 {
        8
    } else if e < 1 << 15 {
        16
    } else if e < 1 << 31 {
        32
    } else if e <= MAX_EXP {
        64
    } else {
        return None;
    })
}

impl Shape {
    /// The shape of constants: no words at all.
    pub(super) const CONST: Shape = Shape { bits: 8, words: 0 };

    #[inline]
    pub(super) fn per_word(self) -> usize {
        (64 / self.bits) as usize
    }
    #[inline]
    pub(super) fn mask(self) -> u64 {
        if self.bits == 64 {
            u64::MAX
        } else {
            (1u64 << self.bits) - 1
        }
    }
    #[inline]
    pub(super) fn guard(self) -> u64 {
        guard_mask(self.bits)
    }
    /// The number of words needed for `nvars` variables at this width.
    #[inline]
    pub(super) fn words_for(bits: u32, nvars: usize) -> usize {
        nvars.div_ceil((64 / bits) as usize)
    }
    /// The exponent of `var` in the packed monomial `m`.
    #[inline]
    pub(super) fn get(self, m: &[u64], var: usize) -> u64 {
        let pw = self.per_word();
        match m.get(var / pw) {
            Some(w) => (w >> ((var % pw) as u32 * self.bits)) & self.mask(),
            None => 0,
        }
    }
    /// Adds `e` to the exponent of `var` (the caller guarantees there is room).
    #[inline]
    pub(super) fn add(self, m: &mut [u64], var: usize, e: u64) {
        let pw = self.per_word();
        m[var / pw] += e << ((var % pw) as u32 * self.bits);
    }
    /// Sets the exponent of `var` to `e` (the caller guarantees there is room).
    #[inline]
    pub(super) fn set(self, m: &mut [u64], var: usize, e: u64) {
        let pw = self.per_word();
        let sh = (var % pw) as u32 * self.bits;
        let w = &mut m[var / pw];
        *w = (*w & !(self.mask() << sh)) | (e << sh);
    }
    /// The largest field value in a word.
    #[inline]
    pub(super) fn max_field(self, mut w: u64) -> u64 {
        let mut best = 0;
        while w != 0 {
            best = best.max(w & self.mask());
            w = if self.bits == 64 { 0 } else { w >> self.bits };
        }
        best
    }
    /// Calls `f(var, exponent)` for every non-zero exponent of `m`, by increasing variable.
    #[inline]
    pub(super) fn for_each(self, m: &[u64], mut f: impl FnMut(usize, u64)) {
        let pw = self.per_word();
        for (k, &word) in m.iter().enumerate() {
            let mut x = word;
            while x != 0 {
                let field = (x.trailing_zeros() / self.bits) as usize;
                let sh = field as u32 * self.bits;
                f(k * pw + field, (x >> sh) & self.mask());
                x &= !(self.mask() << sh);
            }
        }
    }
}

/// The monomial order on packed monomials of equal length: the most significant word is last.
#[inline(always)]
pub(super) fn cmp_mono(a: &[u64], b: &[u64]) -> Ordering {
    debug_assert_eq!(a.len(), b.len());
    for k in (0..a.len()).rev() {
        match a[k].cmp(&b[k]) {
            Ordering::Equal => continue,
            o => return o,
        }
    }
    Ordering::Equal
}

/// `out = a + b` word by word (the caller guarantees that no field overflows).
#[inline(always)]
pub(super) fn add_mono(out: &mut [u64], a: &[u64], b: &[u64]) {
    for ((o, x), y) in out.iter_mut().zip(a).zip(b) {
        *o = x.wrapping_add(*y);
    }
}

/// Whether monomial `d` divides `m` (both with clear guard bits).
#[inline]
pub(super) fn divides(d: &[u64], m: &[u64], guard: u64) -> bool {
    d.iter()
        .zip(m)
        .all(|(&d, &m)| ((m | guard).wrapping_sub(d)) & guard == guard)
}

/// Appends the monomial `m` padded with zero words to `w` words (`m.len() <= w`), a word at a
/// time: the monomials are a few words long, where a bulk copy costs more than the words.
#[inline(always)]
pub(super) fn push_padded(out: &mut Vec<u64>, m: &[u64], w: usize) {
    for &x in m {
        out.push(x);
    }
    for _ in m.len()..w {
        out.push(0);
    }
}

/// Appends the product `a b` of two monomials of the same field width, `b` of `w = b.len()`
/// words and `a` of at most `w` (its missing words are zero).
#[inline(always)]
pub(super) fn push_product_padded(out: &mut Vec<u64>, a: &[u64], b: &[u64]) {
    for (x, y) in a.iter().zip(b) {
        out.push(x.wrapping_add(*y));
    }
    for &y in &b[a.len()..] {
        out.push(y);
    }
}

/// Repacks `n` monomials from one shape to another that has room for all their variables.
pub(super) fn repack(exps: &[u64], n: usize, from: Shape, to: Shape) -> Vec<u64> {
    if from.bits == to.bits && from.words > 0 {
        // The same fields: every monomial copied and padded with zero words, written once (no
        // zeroed buffer first).
        let w = from.words.min(to.words);
        let mut out = Vec::with_capacity(n * to.words);
        for m in exps[..n * from.words].chunks_exact(from.words) {
            push_padded(&mut out, &m[..w], to.words);
        }
        return out;
    }
    let mut out = vec![0u64; n * to.words];
    if from.bits != to.bits {
        for i in 0..n {
            let dst = &mut out[i * to.words..(i + 1) * to.words];
            from.for_each(&exps[i * from.words..(i + 1) * from.words], |v, e| {
                to.set(dst, v, e)
            });
        }
    }
    out
}
