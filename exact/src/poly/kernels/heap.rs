//! The heap merges of the product kernels: Johnson's multiplication with chained stream
//! insertion over packed keys (specialised for 1 to 4 key words) and the squaring heap that
//! visits each unordered pair once.

use super::super::words::*;
use super::*;
use std::cmp::Ordering;

/// A binary max-heap of stream indices, keyed by the monomials in `slots` (`w` words each).
pub(in crate::poly) struct Heap {
    pub(in crate::poly) h: Vec<u32>,
}

impl Heap {
    pub(in crate::poly) fn with_capacity(n: usize) -> Self {
        Heap {
            h: Vec::with_capacity(n),
        }
    }

    #[inline(always)]
    pub(in crate::poly) fn gt(slots: &[u64], w: usize, a: u32, b: u32) -> bool {
        let (a, b) = (a as usize, b as usize);
        cmp_mono(&slots[a * w..(a + 1) * w], &slots[b * w..(b + 1) * w]) == Ordering::Greater
    }

    #[inline]
    pub(in crate::poly) fn peek(&self) -> Option<u32> {
        self.h.first().copied()
    }

    #[inline(always)]
    pub(in crate::poly) fn push(&mut self, x: u32, slots: &[u64], w: usize) {
        let mut pos = self.h.len();
        self.h.push(x);
        while pos > 0 {
            let parent = (pos - 1) / 2;
            if Self::gt(slots, w, x, self.h[parent]) {
                self.h[pos] = self.h[parent];
                pos = parent;
            } else {
                break;
            }
        }
        self.h[pos] = x;
    }

    /// Pops the top stream when its key equals `key`: the next term of the current monomial.
    #[inline(always)]
    pub(in crate::poly) fn pop_if_key(
        &mut self,
        slots: &[u64],
        w: usize,
        key: &[u64],
    ) -> Option<usize> {
        let t = self.peek()? as usize;
        if cmp_mono(&slots[t * w..(t + 1) * w], key) != Ordering::Equal {
            return None;
        }
        self.pop(slots, w);
        Some(t)
    }

    #[inline(always)]
    pub(in crate::poly) fn pop(&mut self, slots: &[u64], w: usize) -> Option<u32> {
        let top = *self.h.first()?;
        let last = self.h.pop()?;
        let n = self.h.len();
        if n == 0 {
            return Some(top);
        }
        let mut pos = 0;
        loop {
            let l = 2 * pos + 1;
            if l >= n {
                break;
            }
            let r = l + 1;
            let c = if r < n && Self::gt(slots, w, self.h[r], self.h[l]) {
                r
            } else {
                l
            };
            if Self::gt(slots, w, self.h[c], last) {
                self.h[pos] = self.h[c];
                pos = c;
            } else {
                break;
            }
        }
        self.h[pos] = last;
        Some(top)
    }
}

/// The state of a heap merge over `n` streams `f_i * g` with `k`-word keys: the streams' current
/// keys (`slots`), their positions in `g` (`js`), and the heap, holding stream 0 at `f_0 g_0`.
fn start_streams(n: usize, k: usize, fk: &[u64], gk: &[u64]) -> (Vec<u64>, Vec<usize>, Heap) {
    let mut slots = vec![0u64; n * k];
    let mut heap = Heap::with_capacity(n);
    push_product(&mut heap, &mut slots, k, fk, 0, gk, 0);
    (slots, vec![0usize; n], heap)
}

/// Sets stream `i`'s slot to the key of the term product `f_i g_j` (keys `k` words wide in
/// `fk`, `gk`) and pushes the stream on the heap.
#[inline(always)]
fn push_product(
    heap: &mut Heap,
    slots: &mut [u64],
    k: usize,
    fk: &[u64],
    i: usize,
    gk: &[u64],
    j: usize,
) {
    add_mono(
        &mut slots[i * k..(i + 1) * k],
        &fk[i * k..(i + 1) * k],
        &gk[j * k..(j + 1) * k],
    );
    heap.push(i as u32, slots, k);
}

/// Johnson's heap multiplication of two sorted term lists (`f` the shorter, both with at least
/// two terms), with Monagan–Pearce chained stream insertion: stream `i` is `f_i * g_j` for
/// increasing `j`, and stream `i + 1` enters the heap when stream `i` leaves its first term; the
/// heap thus holds at most one entry per stream and yields the products in decreasing order,
/// equal monomials are accumulated as they leave it, and the result is born sorted. The heap
/// orders the compact keys of [`key_layout`] (`k` words, `K` if non-zero); the full monomials
/// (`w` words) are formed once per output term.
pub(in crate::poly) fn mul_heap<A: Arith, const K: usize>(
    k: usize,
    w: usize,
    (fe, fk, fc): (&[u64], &[u64], &[A::In]),
    (ge, gk, gc): (&[u64], &[u64], &[A::In]),
    max: usize,
) -> Option<(Vec<u64>, Vec<A::Acc>)> {
    let k = if K == 0 { k } else { K };
    let (nf, ng) = (fc.len(), gc.len());
    let (mut slots, mut js, mut heap) = start_streams(nf, k, fk, gk);
    let cap = (nf * ng)
        .min(4 * (nf + ng) + 1024)
        .min(max.saturating_add(1));
    let mut out_e: Vec<u64> = Vec::with_capacity(cap * w);
    let mut out_c: Vec<A::Acc> = Vec::with_capacity(cap);
    let mut cur = vec![0u64; k];

    // Moves stream i past its current term and (re)inserts what follows.
    let advance = |i: usize, slots: &mut Vec<u64>, js: &mut Vec<usize>, heap: &mut Heap| {
        let j = js[i];
        if j == 0 && i + 1 < nf {
            let n = i + 1;
            js[n] = 0;
            push_product(heap, slots, k, fk, n, gk, 0);
        }
        if j + 1 < ng {
            js[i] = j + 1;
            push_product(heap, slots, k, fk, i, gk, j + 1);
        }
    };

    while let Some(i) = heap.pop(&slots, k) {
        let i = i as usize;
        let j = js[i];
        cur.copy_from_slice(&slots[i * k..(i + 1) * k]);
        let mut acc = A::mul(&fc[i], &gc[j]);
        advance(i, &mut slots, &mut js, &mut heap);
        while let Some(t) = heap.pop_if_key(&slots, k, &cur) {
            A::add_mul(&mut acc, &fc[t], &gc[js[t]]);
            advance(t, &mut slots, &mut js, &mut heap);
        }
        if !A::is_zero(&acc) {
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &ge[j * w..(j + 1) * w]);
            out_c.push(acc);
            if out_c.len() > max {
                return None;
            }
        }
    }
    Some((out_e, out_c))
}

/// A heap key of one or two words held as one integer (`u64`, `u128`).
pub(in crate::poly) trait HeapKey: Copy + Ord {
    fn plus(self, other: Self) -> Self;
}
impl HeapKey for u64 {
    #[inline(always)]
    fn plus(self, other: u64) -> u64 {
        self.wrapping_add(other)
    }
}
impl HeapKey for u128 {
    #[inline(always)]
    fn plus(self, other: u128) -> u128 {
        self.wrapping_add(other)
    }
}

/// [`mul_heap`] for keys of one or two words, the common cases: the heap holds `(key, stream)`
/// pairs, so comparisons touch no other memory, and a stream that continues replaces the root
/// in place (one sift instead of a pop and a push).
pub(in crate::poly) fn mul_heap1<A: Arith, Key: HeapKey>(
    w: usize,
    (fe, fk, fc): (&[u64], &[Key], &[A::In]),
    (ge, gk, gc): (&[u64], &[Key], &[A::In]),
    max: usize,
) -> Option<(Vec<u64>, Vec<A::Acc>)> {
    let (nf, ng) = (fc.len(), gc.len());
    let mut js = vec![0u32; nf];
    let mut heap: Vec<(Key, u32)> = Vec::with_capacity(nf);
    let cap = (nf * ng)
        .min(4 * (nf + ng) + 1024)
        .min(max.saturating_add(1));
    let mut out_e: Vec<u64> = Vec::with_capacity(cap * w);
    let mut out_c: Vec<A::Acc> = Vec::with_capacity(cap);
    heap.push((fk[0].plus(gk[0]), 0));

    // Takes the root's term product `(i, j)` and moves its stream on; returns `(i, j)`.
    let step = |heap: &mut Vec<(Key, u32)>, js: &mut Vec<u32>| -> (usize, usize) {
        let (_, s) = heap[0];
        let i = s as usize;
        let j = js[i] as usize;
        if j + 1 < ng {
            js[i] = (j + 1) as u32;
            heap[0] = (fk[i].plus(gk[j + 1]), s);
            sift_down1(heap);
        } else {
            let last = heap.pop().expect("the root exists");
            if !heap.is_empty() {
                heap[0] = last;
                sift_down1(heap);
            }
        }
        if j == 0 && i + 1 < nf {
            push1(heap, (fk[i + 1].plus(gk[0]), (i + 1) as u32));
        }
        (i, j)
    };

    while let Some(&(key, _)) = heap.first() {
        let (i, j) = step(&mut heap, &mut js);
        let mut acc = A::mul(&fc[i], &gc[j]);
        while heap.first().is_some_and(|t| t.0 == key) {
            let (s, t) = step(&mut heap, &mut js);
            A::add_mul(&mut acc, &fc[s], &gc[t]);
        }
        if !A::is_zero(&acc) {
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &ge[j * w..(j + 1) * w]);
            out_c.push(acc);
            if out_c.len() > max {
                return None;
            }
        }
    }
    Some((out_e, out_c))
}

/// Restores the max-heap order below the root.
#[inline(always)]
pub(in crate::poly) fn sift_down1<Key: Copy + Ord>(h: &mut [(Key, u32)]) {
    let n = h.len();
    let x = h[0];
    let mut pos = 0;
    loop {
        let l = 2 * pos + 1;
        if l >= n {
            break;
        }
        let c = if l + 1 < n && h[l + 1].0 > h[l].0 {
            l + 1
        } else {
            l
        };
        if h[c].0 > x.0 {
            h[pos] = h[c];
            pos = c;
        } else {
            break;
        }
    }
    h[pos] = x;
}

/// Inserts into the max-heap.
#[inline(always)]
pub(in crate::poly) fn push1<Key: Copy + Ord>(h: &mut Vec<(Key, u32)>, x: (Key, u32)) {
    let mut pos = h.len();
    h.push(x);
    while pos > 0 {
        let parent = (pos - 1) / 2;
        if x.0 > h[parent].0 {
            h[pos] = h[parent];
            pos = parent;
        } else {
            break;
        }
    }
    h[pos] = x;
}

/// Squaring with the heap over the pairs `i <= j` (at least two terms): stream `i` is
/// `f_i * f_j` for `j = i, i+1, ...`; stream `i + 1` enters when `(i, i + 1)` leaves. Products
/// with `i < j` count twice. Keys as in [`mul_heap`].
pub(in crate::poly) fn square_heap<A: Arith, const K: usize>(
    k: usize,
    w: usize,
    (fe, fk, fc): (&[u64], &[u64], &[A::In]),
    max: usize,
) -> Option<(Vec<u64>, Vec<A::Acc>)> {
    let k = if K == 0 { k } else { K };
    let n = fc.len();
    let (mut slots, mut js, mut heap) = start_streams(n, k, fk, fk);
    let cap = (n * n).min(8 * n + 1024).min(max.saturating_add(1));
    let mut out_e: Vec<u64> = Vec::with_capacity(cap * w);
    let mut out_c: Vec<A::Acc> = Vec::with_capacity(cap);
    let mut cur = vec![0u64; k];

    let advance = |i: usize, slots: &mut Vec<u64>, js: &mut Vec<usize>, heap: &mut Heap| {
        let j = js[i];
        if j == i + 1 && i + 1 < n {
            let m = i + 1;
            js[m] = m;
            push_product(heap, slots, k, fk, m, fk, m);
        }
        if j + 1 < n {
            js[i] = j + 1;
            push_product(heap, slots, k, fk, i, fk, j + 1);
        }
    };
    // Diagonal products go to `diag`, off-diagonal ones (to be doubled) to `off`.
    let take = |i: usize, j: usize, diag: &mut Option<A::Acc>, off: &mut Option<A::Acc>| {
        let slot = if i == j { diag } else { off };
        match slot {
            Some(a) => A::add_mul(a, &fc[i], &fc[j]),
            None => *slot = Some(A::mul(&fc[i], &fc[j])),
        }
    };

    while let Some(i) = heap.pop(&slots, k) {
        let i = i as usize;
        let j = js[i];
        cur.copy_from_slice(&slots[i * k..(i + 1) * k]);
        let mut diag: Option<A::Acc> = None;
        let mut off: Option<A::Acc> = None;
        take(i, j, &mut diag, &mut off);
        advance(i, &mut slots, &mut js, &mut heap);
        while let Some(t) = heap.pop_if_key(&slots, k, &cur) {
            take(t, js[t], &mut diag, &mut off);
            advance(t, &mut slots, &mut js, &mut heap);
        }
        let acc = match (diag, off) {
            (Some(mut d), Some(o)) => {
                A::add(&mut d, A::double(o));
                d
            }
            (Some(d), None) => d,
            (None, Some(o)) => A::double(o),
            (None, None) => continue,
        };
        if !A::is_zero(&acc) {
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &fe[j * w..(j + 1) * w]);
            out_c.push(acc);
            if out_c.len() > max {
                return None;
            }
        }
    }
    Some((out_e, out_c))
}
