//! The arithmetic kernels: sorted merges for sums, and for products a heap merge of the rows
//! `f_i * g` over packed keys (specialised for 1 to 4 key words), a dense accumulator when the
//! exponent box is small, and a squaring heap that visits each unordered pair once.

use super::words::*;
use super::*;
use exactcheck_core::Ring;
use std::cmp::Ordering;

/// Calls `$f::<C, K>` with the key width as a constant for 1 to 4 words, `K = 0` (run time)
/// otherwise.
macro_rules! with_key_words {
    ($k:expr, $f:ident::<$c:ty>($($arg:expr),*)) => {
        match $k {
            1 => $f::<$c, 1>($($arg),*),
            2 => $f::<$c, 2>($($arg),*),
            3 => $f::<$c, 3>($($arg),*),
            4 => $f::<$c, 4>($($arg),*),
            _ => $f::<$c, 0>($($arg),*),
        }
    };
}

impl<C: Ring> Poly<C> {
    /// `self + rhs` (or `self - rhs` when `negate`), borrowing both.
    pub(super) fn add_impl(&self, rhs: &Self, negate: bool) -> Self {
        if rhs.is_empty() {
            return self.clone();
        }
        if self.is_empty() {
            return if negate { rhs.neg_impl() } else { rhs.clone() };
        }
        let shape = self.common_shape(rhs);
        merge(
            shape,
            &self.exps_in(shape),
            self.coeffs.iter().cloned(),
            &rhs.exps_in(shape),
            rhs.coeffs.iter().cloned(),
            negate,
        )
    }

    /// `self + rhs` (or `self - rhs` when `negate`), consuming both.
    pub(super) fn add_owned(self, rhs: Self, negate: bool) -> Self {
        if rhs.is_empty() {
            return self;
        }
        if self.is_empty() {
            return if negate { rhs.neg_owned() } else { rhs };
        }
        let shape = self.common_shape(&rhs);
        let (ae, ac) = self.into_parts(shape);
        let (be, bc) = rhs.into_parts(shape);
        merge(shape, &ae, ac.into_iter(), &be, bc.into_iter(), negate)
    }

    /// The packed monomials in shape `to` and the coefficients, without copying when the shape
    /// is already right.
    pub(super) fn into_parts(self, to: Shape) -> (Vec<u64>, Vec<C>) {
        let exps = if to == self.shape {
            self.exps
        } else {
            repack(&self.exps, self.coeffs.len(), self.shape, to)
        };
        (exps, self.coeffs)
    }

    /// `self + rhs` (or `self - rhs` when `negate`), consuming `self` only.
    pub(super) fn add_left_owned(self, rhs: &Self, negate: bool) -> Self {
        if rhs.is_empty() {
            return self;
        }
        if self.is_empty() {
            return if negate { rhs.neg_impl() } else { rhs.clone() };
        }
        let shape = self.common_shape(rhs);
        let be = rhs.exps_in(shape);
        let (ae, ac) = self.into_parts(shape);
        merge(
            shape,
            &ae,
            ac.into_iter(),
            &be,
            rhs.coeffs.iter().cloned(),
            negate,
        )
    }

    pub(super) fn neg_impl(&self) -> Self {
        Poly {
            shape: self.shape,
            exps: self.exps.clone(),
            coeffs: self.coeffs.iter().map(Ring::neg_ref).collect(),
        }
    }

    pub(super) fn neg_owned(mut self) -> Self {
        for c in &mut self.coeffs {
            let v = std::mem::replace(c, C::zero());
            *c = -v;
        }
        self
    }

    /// The shape of the product of `self` and `rhs`: a field width in which no exponent of the
    /// product overflows.
    ///
    /// # Panics
    /// When an exponent of the product exceeds `u32::MAX`.
    pub(super) fn product_shape(&self, rhs: &Self) -> Shape {
        let mut bits = self.shape.bits.max(rhs.shape.bits);
        let need = self.exp_bound() + rhs.exp_bound();
        if need >= 1 << (bits - 1) {
            // The cheap bound does not fit: take the exact largest sum per variable.
            let (a, b) = (self.max_exponents(), rhs.max_exponents());
            let exact = (0..a.len().max(b.len()))
                .map(|v| a.get(v).copied().unwrap_or(0) + b.get(v).copied().unwrap_or(0))
                .max()
                .unwrap_or(0);
            let need_bits = bits_for(exact).expect("exponent overflow: above u32::MAX");
            bits = bits.max(need_bits);
        }
        if bits == self.shape.bits && bits == rhs.shape.bits {
            Shape {
                bits,
                words: self.shape.words.max(rhs.shape.words),
            }
        } else {
            let nv = self.nvars_used().max(rhs.nvars_used());
            Shape {
                bits,
                words: Shape::words_for(bits, nv),
            }
        }
    }

    pub(super) fn mul_impl(&self, rhs: &Self) -> Self {
        self.mul_capped(rhs, |_| usize::MAX)
            .expect("a product without a cap on its terms always completes")
    }

    /// `self * rhs`, or `None` as soon as the product has more than `max(words)` terms (`words`
    /// being the words of one packed monomial of the product): the kernels count the terms as
    /// they produce them, so a product past the cap stops there instead of finishing.
    pub(super) fn mul_capped(&self, rhs: &Self, max: impl Fn(usize) -> usize) -> Option<Self> {
        if self.is_empty() || rhs.is_empty() {
            return Some(Poly::zero());
        }
        let shape = self.product_shape(rhs);
        let max = max(shape.words);
        let (ae, be) = (self.exps_in(shape), rhs.exps_in(shape));
        let w = shape.words;
        let (exps, coeffs) = if self.len() == 1 {
            mul_term(w, &be, &rhs.coeffs, &ae, &self.coeffs[0], max)
        } else if rhs.len() == 1 {
            mul_term(w, &ae, &self.coeffs, &be, &rhs.coeffs[0], max)
        } else {
            let (small, large) = if self.len() <= rhs.len() {
                ((&ae[..], self), (&be[..], rhs))
            } else {
                ((&be[..], rhs), (&ae[..], self))
            };
            let plan =
                ProductPlan::new(shape, small.0, small.1.len(), Some(large.0), large.1.len());
            plan.run_coeffs(&small.1.coeffs, &large.1.coeffs, max)
        }?;
        Some(Poly {
            shape,
            exps,
            coeffs,
        })
    }

    pub(super) fn square_impl(&self) -> Self {
        self.square_capped(|_| usize::MAX)
            .expect("a square without a cap on its terms always completes")
    }

    /// `self^2`, or `None` past `max(words)` terms (as [`Poly::mul_capped`]).
    pub(super) fn square_capped(&self, max: impl Fn(usize) -> usize) -> Option<Self> {
        if self.len() <= 1 {
            return Some(self.pow_term(2));
        }
        let shape = self.product_shape(self);
        let max = max(shape.words);
        let e = self.exps_in(shape);
        let plan = ProductPlan::new(shape, &e, self.len(), None, self.len());
        let (exps, coeffs) = plan.run_coeffs(&self.coeffs, &self.coeffs, max)?;
        Some(Poly {
            shape,
            exps,
            coeffs,
        })
    }

    /// The reference product: the kernels on the coefficient type's own arithmetic, never the
    /// machine-word kernels of [`super::words`] (for tests against them).
    #[cfg(test)]
    pub(super) fn mul_reference(&self, rhs: &Self) -> Self {
        if self.len() <= 1 || rhs.len() <= 1 {
            return self.mul_impl(rhs);
        }
        let shape = self.product_shape(rhs);
        let (ae, be) = (self.exps_in(shape), rhs.exps_in(shape));
        let (small, large) = if self.len() <= rhs.len() {
            ((&ae[..], self), (&be[..], rhs))
        } else {
            ((&be[..], rhs), (&ae[..], self))
        };
        let plan = ProductPlan::new(shape, small.0, small.1.len(), Some(large.0), large.1.len());
        let (exps, coeffs) = plan
            .run::<Generic<C>>(&small.1.coeffs, &large.1.coeffs, usize::MAX)
            .expect("no cap");
        Poly {
            shape,
            exps,
            coeffs,
        }
    }

    /// The reference square (as [`Poly::mul_reference`]).
    #[cfg(test)]
    pub(super) fn square_reference(&self) -> Self {
        if self.len() <= 1 {
            return self.pow_term(2);
        }
        let shape = self.product_shape(self);
        let e = self.exps_in(shape);
        let plan = ProductPlan::new(shape, &e, self.len(), None, self.len());
        let (exps, coeffs) = plan
            .run::<Generic<C>>(&self.coeffs, &self.coeffs, usize::MAX)
            .expect("no cap");
        Poly {
            shape,
            exps,
            coeffs,
        }
    }
}

/// How a product of two polynomials of at least two terms each (or a square) is formed: the
/// packed monomials, and either the mixed-radix indices of a dense product or the compact keys
/// of a heap product. The coefficients come separately, in the kernels' arithmetic.
pub(super) struct ProductPlan<'a> {
    shape: Shape,
    /// The shorter factor's monomials.
    fe: &'a [u64],
    /// The longer factor's monomials (`None`: a square).
    ge: Option<&'a [u64]>,
    /// The largest exponent of every variable in the product.
    need: Vec<u64>,
    how: How,
}

enum How {
    /// A dense box of `cells` cells, the strides, and the factors' cell indices.
    Dense {
        cells: u64,
        strides: Vec<u64>,
        fi: Vec<u64>,
        gi: Vec<u64>,
    },
    /// A heap over keys of `k` words.
    Heap {
        k: usize,
        fk: Vec<u64>,
        gk: Vec<u64>,
    },
}

/// The largest dense box the word kernels accumulate in directly (bytes of accumulators; one
/// slab of it is in use at a time).
const DIRECT_MAX_BYTES: usize = 1 << 25;

impl<'a> ProductPlan<'a> {
    /// The plan for `f g` (`ge = Some`, `f` the shorter) or `f^2` (`ge = None`).
    fn new(shape: Shape, fe: &'a [u64], nf: usize, ge: Option<&'a [u64]>, ng: usize) -> Self {
        let cap = shape.words * shape.per_word();
        let ma = max_exps(shape, fe, nf, cap);
        let need: Vec<u64> = match ge {
            Some(ge) => {
                let mb = max_exps(shape, ge, ng, cap);
                ma.iter().zip(&mb).map(|(x, y)| x + y).collect()
            }
            None => ma.iter().map(|m| 2 * m).collect(),
        };
        let products = (nf as u64).saturating_mul(ng as u64);
        let limit = DENSE_MAX_CELLS.min(products.saturating_mul(4));
        let how = if let Some((cells, strides)) = dense_strides(&need, limit) {
            let fi = dense_indices(shape, fe, nf, &strides);
            let gi = match ge {
                Some(ge) => dense_indices(shape, ge, ng, &strides),
                None => Vec::new(),
            };
            How::Dense {
                cells,
                strides,
                fi,
                gi,
            }
        } else {
            let (k, place) = key_layout(&need);
            let fk = make_keys(shape, fe, nf, k, &place);
            let gk = match ge {
                Some(ge) => make_keys(shape, ge, ng, k, &place),
                None => Vec::new(),
            };
            How::Heap { k, fk, gk }
        };
        ProductPlan {
            shape,
            fe,
            ge,
            need,
            how,
        }
    }

    /// The product on coefficients of type `C`: in machine words when `C` has word hooks and
    /// both coefficient lists fit ([`super::words`]), else in `C`'s own arithmetic.
    fn run_coeffs<C: Ring>(&self, fc: &[C], gc: &[C], max: usize) -> Option<(Vec<u64>, Vec<C>)> {
        if let Some(h) = word_hooks::<C>() {
            if let Some((fw, fd)) = (h.to_words)(fc) {
                let g = if self.ge.is_none() {
                    None
                } else {
                    Some((h.to_words)(gc))
                };
                let (gw, gd) = match &g {
                    None => (&fw, fd),
                    Some(Some((gw, gd))) => (gw, *gd),
                    Some(None) => return self.run::<Generic<C>>(fc, gc, max),
                };
                let d = fd as i128 * gd as i128;
                let back = |x: WordSum| (h.from_word_sum)(x, d);
                return match accumulator_for(&fw, gw) {
                    0 => self.run_words::<W64, C>(&fw, gw, max, back),
                    1 => self.run_words::<W128, C>(&fw, gw, max, back),
                    _ => self.run_words::<W192, C>(&fw, gw, max, back),
                };
            }
        }
        self.run::<Generic<C>>(fc, gc, max)
    }

    /// The product in word arithmetic `A`, converted back by `back`.
    fn run_words<A: WordArith, C>(
        &self,
        fc: &[i64],
        gc: &[i64],
        max: usize,
        back: impl Fn(WordSum) -> C,
    ) -> Option<(Vec<u64>, Vec<C>)>
    where
        A::Acc: Copy,
    {
        let (exps, sums) = match &self.how {
            How::Dense {
                cells,
                strides,
                fi,
                gi,
            } if (*cells as usize).saturating_mul(std::mem::size_of::<A::Acc>())
                <= DIRECT_MAX_BYTES =>
            {
                let gi = if self.ge.is_some() { gi } else { fi };
                mul_dense_direct::<A>(self.shape, strides, &self.need, (fi, fc), (gi, gc), max)?
            }
            _ => self.run::<A>(fc, gc, max)?,
        };
        Some((exps, sums.into_iter().map(|x| back(A::sum(x))).collect()))
    }

    /// The product in arithmetic `A` by the planned kernel.
    pub(super) fn run<A: Arith>(
        &self,
        fc: &[A::In],
        gc: &[A::In],
        max: usize,
    ) -> Option<(Vec<u64>, Vec<A::Acc>)> {
        let w = self.shape.words;
        let ge = self.ge.unwrap_or(self.fe);
        match &self.how {
            How::Dense { cells, fi, gi, .. } => {
                let gi = if self.ge.is_some() { gi } else { fi };
                mul_dense::<A>(w, *cells as usize, (self.fe, fi, fc), (ge, gi, gc), max)
            }
            How::Heap { k, fk, gk } => {
                let f = (self.fe, &fk[..], fc);
                if self.ge.is_none() {
                    with_key_words!(*k, square_heap::<A>(*k, w, f, max))
                } else {
                    let g = (ge, &gk[..], gc);
                    if *k == 1 {
                        mul_heap1::<A, u64>(w, f, g, max)
                    } else if *k == 2 {
                        // Two key words as one u128 (most significant word last): adding keys
                        // never carries between words, so u128 addition and order agree.
                        let wide = |keys: &[u64]| -> Vec<u128> {
                            keys.chunks_exact(2)
                                .map(|p| (u128::from(p[1]) << 64) | u128::from(p[0]))
                                .collect()
                        };
                        let (fk2, gk2) = (wide(fk), wide(gk));
                        mul_heap1::<A, u128>(w, (f.0, &fk2[..], f.2), (ge, &gk2[..], gc), max)
                    } else {
                        with_key_words!(*k, mul_heap::<A>(*k, w, f, g, max))
                    }
                }
            }
        }
    }
}

/// `c^e` by binary powering.
pub(super) fn pow_coeff<C: Ring>(c: &C, mut e: u64) -> C {
    let mut acc = C::one();
    let mut base = c.clone();
    while e > 0 {
        if e & 1 == 1 {
            acc *= &base;
        }
        e >>= 1;
        if e > 0 {
            base = base.square();
        }
    }
    acc
}

/// Merges two sorted term lists of the same shape.
pub(super) fn merge<C: Ring>(
    shape: Shape,
    ae: &[u64],
    ac: impl Iterator<Item = C>,
    be: &[u64],
    bc: impl Iterator<Item = C>,
    negate: bool,
) -> Poly<C> {
    macro_rules! by_words {
        ($($n:literal)*) => {
            match shape.words {
                $($n => merge_words::<C, $n>($n, ae, ac, be, bc, negate),)*
                w => merge_words::<C, 0>(w, ae, ac, be, bc, negate),
            }
        };
    }
    // Word counts as constants up to 16 (128 variables at 8 bits): compares and copies of
    // monomials then compile to straight-line code.
    let (exps, coeffs) = by_words!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16);
    Poly {
        shape,
        exps,
        coeffs,
    }
}

/// [`merge`] with `W` words per monomial (`W = 0`: `w`, at run time).
pub(super) fn merge_words<C: Ring, const W: usize>(
    w: usize,
    ae: &[u64],
    mut ac: impl Iterator<Item = C>,
    be: &[u64],
    mut bc: impl Iterator<Item = C>,
    negate: bool,
) -> (Vec<u64>, Vec<C>) {
    let w = if W == 0 { w } else { W };
    let (na, nb) = (ae.len() / w.max(1), be.len() / w.max(1));
    // With zero words both lists are single constants.
    let (na, nb) = if w == 0 { (1, 1) } else { (na, nb) };
    let mut exps = Vec::with_capacity(ae.len() + be.len());
    let mut coeffs = Vec::with_capacity(na + nb);
    let (mut i, mut j) = (0, 0);
    let mut a_next = ac.next();
    let mut b_next = bc.next();
    while let (Some(_), Some(_)) = (&a_next, &b_next) {
        let (ma, mb) = (&ae[i * w..(i + 1) * w], &be[j * w..(j + 1) * w]);
        match cmp_mono(ma, mb) {
            Ordering::Greater => {
                exps.extend_from_slice(ma);
                coeffs.extend(a_next.take());
                a_next = ac.next();
                i += 1;
            }
            Ordering::Less => {
                exps.extend_from_slice(mb);
                let b = b_next.take().unwrap_or_else(C::zero);
                coeffs.push(if negate { -b } else { b });
                b_next = bc.next();
                j += 1;
            }
            Ordering::Equal => {
                let a = a_next.take().unwrap_or_else(C::zero);
                let b = b_next.take().unwrap_or_else(C::zero);
                let s = if negate { a - b } else { a + b };
                if !s.is_zero() {
                    exps.extend_from_slice(ma);
                    coeffs.push(s);
                }
                a_next = ac.next();
                b_next = bc.next();
                i += 1;
                j += 1;
            }
        }
    }
    while let Some(a) = a_next {
        exps.extend_from_slice(&ae[i * w..(i + 1) * w]);
        coeffs.push(a);
        a_next = ac.next();
        i += 1;
    }
    while let Some(b) = b_next {
        exps.extend_from_slice(&be[j * w..(j + 1) * w]);
        coeffs.push(if negate { -b } else { b });
        b_next = bc.next();
        j += 1;
    }
    (exps, coeffs)
}

/// `g * (m, c)`: a term times a sorted list stays sorted.
pub(super) fn mul_term<C: Ring>(
    w: usize,
    ge: &[u64],
    gc: &[C],
    m: &[u64],
    c: &C,
    max: usize,
) -> Option<(Vec<u64>, Vec<C>)> {
    if gc.len() > max {
        return None;
    }
    let mut exps = Vec::with_capacity(ge.len());
    let mut coeffs = Vec::with_capacity(gc.len());
    let mut buf = vec![0u64; w];
    for (j, g) in gc.iter().enumerate() {
        let p = g.mul_ref(c);
        if !p.is_zero() {
            add_mono(&mut buf, &ge[j * w..(j + 1) * w], m);
            exps.extend_from_slice(&buf);
            coeffs.push(p);
        }
    }
    Some((exps, coeffs))
}

/// A binary max-heap of stream indices, keyed by the monomials in `slots` (`w` words each).
pub(super) struct Heap {
    pub(super) h: Vec<u32>,
}

impl Heap {
    pub(super) fn with_capacity(n: usize) -> Self {
        Heap {
            h: Vec::with_capacity(n),
        }
    }

    #[inline(always)]
    pub(super) fn gt(slots: &[u64], w: usize, a: u32, b: u32) -> bool {
        let (a, b) = (a as usize, b as usize);
        cmp_mono(&slots[a * w..(a + 1) * w], &slots[b * w..(b + 1) * w]) == Ordering::Greater
    }

    #[inline]
    pub(super) fn peek(&self) -> Option<u32> {
        self.h.first().copied()
    }

    #[inline(always)]
    pub(super) fn push(&mut self, x: u32, slots: &[u64], w: usize) {
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
    pub(super) fn pop_if_key(&mut self, slots: &[u64], w: usize, key: &[u64]) -> Option<usize> {
        let t = self.peek()? as usize;
        if cmp_mono(&slots[t * w..(t + 1) * w], key) != Ordering::Equal {
            return None;
        }
        self.pop(slots, w);
        Some(t)
    }

    #[inline(always)]
    pub(super) fn pop(&mut self, slots: &[u64], w: usize) -> Option<u32> {
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

/// The largest exponent of every variable over `n` monomials (`cap` variables): a field-wise
/// maximum of the packed words (SWAR: with the guard bits clear, `((x | H) - m) & H` marks the
/// fields where `x >= m` without borrows between fields), the fields read out once at the end.
pub(super) fn max_exps(shape: Shape, e: &[u64], n: usize, cap: usize) -> Vec<u64> {
    let w = shape.words;
    let h = shape.guard();
    let field = shape.mask();
    let mut acc = vec![0u64; w];
    for i in 0..n {
        for (m, &x) in acc.iter_mut().zip(&e[i * w..(i + 1) * w]) {
            let ge = ((x | h).wrapping_sub(*m)) & h;
            let mask = (ge >> (shape.bits - 1)).wrapping_mul(field);
            *m = (x & mask) | (*m & !mask);
        }
    }
    let mut m = vec![0u64; cap];
    shape.for_each(&acc, |v, x| m[v] = x);
    m
}

/// Compact keys for the monomials of a product: every variable gets just the bits that its
/// largest exponent in the product needs (`need[v]`, a Kronecker substitution), packed from the
/// lowest variable up without crossing word boundaries, so that comparing keys as multi-word
/// integers (most significant word last) is still the monomial order and adding keys never
/// carries. When the operands have few low-degree variables (chiang-identity: 74 variables in 10 words) the
/// keys take one or two words, and the heap compares those instead of whole monomials.
///
/// Returns the number of key words and the place `(word, shift)` of every variable.
pub(super) fn key_layout(need: &[u64]) -> (usize, Vec<(usize, u32)>) {
    let mut place = vec![(0usize, 0u32); need.len()];
    let (mut word, mut shift) = (0usize, 0u32);
    for (v, &s) in need.iter().enumerate() {
        if s == 0 {
            continue;
        }
        let width = 64 - s.leading_zeros();
        if shift + width > 64 {
            word += 1;
            shift = 0;
        }
        place[v] = (word, shift);
        shift += width;
    }
    (word + 1, place)
}

/// The keys (`k` words each) of `n` monomials in the layout `place`.
pub(super) fn make_keys(
    shape: Shape,
    e: &[u64],
    n: usize,
    k: usize,
    place: &[(usize, u32)],
) -> Vec<u64> {
    let w = shape.words;
    let mut keys = vec![0u64; n * k];
    for i in 0..n {
        let key = &mut keys[i * k..(i + 1) * k];
        shape.for_each(&e[i * w..(i + 1) * w], |v, x| {
            let (kw, sh) = place[v];
            key[kw] |= x << sh;
        });
    }
    keys
}

/// `out += a + b` for monomials of `w` words.
#[inline(always)]
pub(super) fn push_sum(out: &mut Vec<u64>, a: &[u64], b: &[u64]) {
    out.extend(a.iter().zip(b).map(|(x, y)| x.wrapping_add(*y)));
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
pub(super) fn mul_heap<A: Arith, const K: usize>(
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
pub(super) trait HeapKey: Copy + Ord {
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
pub(super) fn mul_heap1<A: Arith, Key: HeapKey>(
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
pub(super) fn sift_down1<Key: Copy + Ord>(h: &mut [(Key, u32)]) {
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
pub(super) fn push1<Key: Copy + Ord>(h: &mut Vec<(Key, u32)>, x: (Key, u32)) {
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

/// The largest exponent box a dense product may use (cells of 4 bytes).
pub(super) const DENSE_MAX_CELLS: u64 = 1 << 22;

/// Mixed-radix indices for a dense product: variable `v` gets radix `need[v] + 1`, the lowest
/// variable the smallest stride, so indices order like the monomials. `None` when the box
/// (the product of the radices) exceeds `limit`.
pub(super) fn dense_strides(need: &[u64], limit: u64) -> Option<(u64, Vec<u64>)> {
    let mut stride = 1u64;
    let mut strides = vec![0u64; need.len()];
    for (v, &n) in need.iter().enumerate() {
        if n == 0 {
            continue;
        }
        strides[v] = stride;
        stride = stride.checked_mul(n + 1).filter(|&b| b <= limit)?;
    }
    Some((stride, strides))
}

/// The mixed-radix index of every monomial.
pub(super) fn dense_indices(shape: Shape, e: &[u64], n: usize, strides: &[u64]) -> Vec<u64> {
    let w = shape.words;
    (0..n)
        .map(|i| {
            let mut idx = 0;
            shape.for_each(&e[i * w..(i + 1) * w], |v, x| idx += x * strides[v]);
            idx
        })
        .collect()
}

/// Multiplication by accumulation in a dense box of exponents (for products whose exponent box
/// is not much larger than the number of term products, as in dense few-variable products):
/// each product goes to its cell by mixed-radix index, the touched cells are sorted once.
pub(super) fn mul_dense<A: Arith>(
    w: usize,
    cells: usize,
    (fe, fi, fc): (&[u64], &[u64], &[A::In]),
    (ge, gi, gc): (&[u64], &[u64], &[A::In]),
    max: usize,
) -> Option<(Vec<u64>, Vec<A::Acc>)> {
    let mut cell = vec![0u32; cells];
    // (index, i, j, coefficient) of every distinct product monomial.
    let mut touched: Vec<(u64, u32, u32, A::Acc)> = Vec::with_capacity((fc.len() + gc.len()) * 4);
    for (i, (a, ia)) in fc.iter().zip(fi).enumerate() {
        for (j, (b, ib)) in gc.iter().zip(gi).enumerate() {
            let idx = ia + ib;
            match cell[idx as usize] {
                0 => {
                    // Cancellation can leave fewer terms, but not more: a dense product is
                    // small (its box at most DENSE_MAX_CELLS), so counting touched cells is
                    // the cheap prediction.
                    if touched.len() >= max {
                        return None;
                    }
                    touched.push((idx, i as u32, j as u32, A::mul(a, b)));
                    cell[idx as usize] = touched.len() as u32;
                }
                t => A::add_mul(&mut touched[t as usize - 1].3, a, b),
            }
        }
    }
    touched.sort_unstable_by_key(|x| std::cmp::Reverse(x.0));
    let mut out_e = Vec::with_capacity(touched.len() * w);
    let mut out_c = Vec::with_capacity(touched.len());
    for (_, i, j, c) in touched {
        if !A::is_zero(&c) {
            let (i, j) = (i as usize, j as usize);
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &ge[j * w..(j + 1) * w]);
            out_c.push(c);
        }
    }
    Some((out_e, out_c))
}

/// Squaring with the heap over the pairs `i <= j` (at least two terms): stream `i` is
/// `f_i * f_j` for `j = i, i+1, ...`; stream `i + 1` enters when `(i, i + 1)` leaves. Products
/// with `i < j` count twice. Keys as in [`mul_heap`].
pub(super) fn square_heap<A: Arith, const K: usize>(
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

/// Multiplication in word arithmetic directly in dense arrays of accumulators over the
/// exponent box (for boxes of at most [`DIRECT_MAX_BYTES`]), one slab at a time: the output is
/// formed for each exponent `t` of the top variable (the one with the largest stride) from the
/// highest down, from the pairs of term groups whose top exponents add up to `t` (the factors
/// are sorted, so each group is a run of terms). Every term product is one multiply-add into
/// the slab (`stride` cells, small enough to stay in cache), and scanning the slab from the top
/// yields the result sorted, each monomial decoded from its mixed-radix index (`strides`,
/// radices `need + 1`). Cells that cancel to zero are skipped like untouched ones.
pub(super) fn mul_dense_direct<A: WordArith>(
    shape: Shape,
    strides: &[u64],
    need: &[u64],
    (fi, fc): (&[u64], &[i64]),
    (gi, gc): (&[u64], &[i64]),
    max: usize,
) -> Option<(Vec<u64>, Vec<A::Acc>)>
where
    A::Acc: Copy,
{
    let radices: Vec<(usize, u64, u64)> = need
        .iter()
        .enumerate()
        .filter(|&(_, &n)| n > 0)
        .map(|(v, &n)| (v, strides[v], n + 1))
        .collect();
    // The top variable: the largest stride (the last variable in use).
    let &(_, slab, top_radix) = radices
        .last()
        .expect("a product of two polynomials of two terms or more has a variable");
    let slab = slab as usize;
    // Runs of equal top exponent: (top exponent, start, end), for f and by exponent for g.
    let runs = |idx: &[u64]| -> Vec<(usize, usize, usize)> {
        let mut out: Vec<(usize, usize, usize)> = Vec::new();
        for (k, &x) in idx.iter().enumerate() {
            let t = (x / slab as u64) as usize;
            match out.last_mut() {
                Some(r) if r.0 == t => r.2 = k + 1,
                _ => out.push((t, k, k + 1)),
            }
        }
        out
    };
    let low =
        |idx: &[u64]| -> Vec<usize> { idx.iter().map(|&x| (x % slab as u64) as usize).collect() };
    let (fr, gr) = (runs(fi), runs(gi));
    let (fl, gl) = (low(fi), low(gi));
    let mut g_of: Vec<Option<(usize, usize, usize)>> = vec![None; top_radix as usize];
    for &(t, a, b) in &gr {
        let top = gl[a..b].iter().copied().max().unwrap_or(0);
        g_of[t] = Some((a, b, top));
    }
    let mut acc = vec![A::ZERO; slab];
    let w = shape.words;
    let mut out_e = Vec::new();
    let mut out_c = Vec::new();
    let mut m = vec![0u64; w];
    for t in (0..top_radix as usize).rev() {
        let mut touched = false;
        for &(ta, fa, fb) in &fr {
            let Some(Some((ga, gb, gtop))) = t.checked_sub(ta).map(|tb| g_of[tb]) else {
                continue;
            };
            touched = true;
            let (gcs, gls) = (&gc[ga..gb], &gl[ga..gb]);
            for (a, &la) in fc[fa..fb].iter().zip(&fl[fa..fb]) {
                // Every cell of this row is below `la + gtop + 1 <= slab`.
                let row = &mut acc[la..la + gtop + 1];
                for (b, &lb) in gcs.iter().zip(gls) {
                    A::add_mul(&mut row[lb], a, b);
                }
            }
        }
        if !touched {
            continue;
        }
        for (lo, c) in acc.iter_mut().enumerate().rev() {
            if A::is_zero(c) {
                continue;
            }
            if out_c.len() >= max {
                return None;
            }
            let idx = (t * slab + lo) as u64;
            m.fill(0);
            for &(v, stride, radix) in &radices {
                shape.set(&mut m, v, (idx / stride) % radix);
            }
            out_e.extend_from_slice(&m);
            out_c.push(*c);
            *c = A::ZERO;
        }
    }
    Some((out_e, out_c))
}
