//! The arithmetic kernels: sorted merges for sums, and for products a heap merge of the rows
//! `f_i * g` over packed keys (specialised for 1 to 4 key words), a dense accumulator when the
//! exponent box is small, and a squaring heap that visits each unordered pair once. The heap
//! merges are in `heap`, the dense accumulators in `dense`.

use super::words::*;
use super::*;
use exactcheck_core::Ring;
use std::borrow::Cow;
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

mod dense;
mod heap;

pub(super) use dense::*;
pub(super) use heap::*;

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
        if self.len() == 1 || rhs.len() == 1 {
            let (term, p) = if self.len() == 1 {
                (self, rhs)
            } else {
                (rhs, self)
            };
            // The many-term factor keeps its packing when only words are missing (they are
            // zero): no repacked copy of it.
            let (pe, pw) = if p.shape.bits == shape.bits && p.shape.words <= shape.words {
                (Cow::Borrowed(&p.exps[..]), p.shape.words)
            } else {
                (p.exps_in(shape), shape.words)
            };
            // The term's monomial, on the stack when it has the product's field width.
            let mut one = [0u64; 16];
            let m = if term.shape.bits == shape.bits
                && term.shape.words <= shape.words
                && shape.words <= one.len()
            {
                one[..term.shape.words].copy_from_slice(&term.exps);
                Cow::Borrowed(&one[..shape.words])
            } else {
                term.exps_in(shape)
            };
            let (exps, coeffs) = mul_term((&pe, pw), &p.coeffs, &m, &term.coeffs[0], max)?;
            return Some(Poly {
                shape,
                exps,
                coeffs,
            });
        }
        let (ae, be) = (self.exps_in(shape), rhs.exps_in(shape));
        let (exps, coeffs) = if self.len() * rhs.len() <= SMALL_PRODUCT {
            mul_small(shape, (&ae, &self.coeffs), (&be, &rhs.coeffs), max)
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
        let (exps, coeffs) = if self.len() * self.len() <= SMALL_PRODUCT {
            mul_small(shape, (&e, &self.coeffs), (&e, &self.coeffs), max)?
        } else {
            let plan = ProductPlan::new(shape, &e, self.len(), None, self.len());
            plan.run_coeffs(&self.coeffs, &self.coeffs, max)?
        };
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
        let products = (nf as u64).saturating_mul(ng as u64);
        let limit = DENSE_MAX_CELLS.min(products.saturating_mul(4));
        // The field-wise OR of the exponents bounds every largest exponent `m` by
        // `2^(b - 1) <= m <= or` (`b` the bit length of `or`): when even the lower bounds make
        // the box too large for a dense product, the upper bounds serve for the heap's keys
        // (they need at most one more bit per variable) and the exact maxima are not needed.
        let sum_of =
            |a: &[u64], b: &[u64]| -> Vec<u64> { a.iter().zip(b).map(|(x, y)| x + y).collect() };
        let oa = or_exps(shape, fe, nf, cap);
        let ob = ge.map(|ge| or_exps(shape, ge, ng, cap));
        let low = |v: &[u64]| -> Vec<u64> {
            v.iter()
                .map(|&x| {
                    if x == 0 {
                        0
                    } else {
                        1 << (63 - x.leading_zeros())
                    }
                })
                .collect()
        };
        let low_need = sum_of(&low(&oa), &low(ob.as_ref().unwrap_or(&oa)));
        let need: Vec<u64> = if dense_strides(&low_need, limit).is_none() {
            sum_of(&oa, ob.as_ref().unwrap_or(&oa))
        } else {
            let ma = max_exps(shape, fe, nf, cap);
            match ge {
                Some(ge) => sum_of(&ma, &max_exps(shape, ge, ng, cap)),
                None => ma.iter().map(|m| 2 * m).collect(),
            }
        };
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
                return match accumulator_for(&fw, gw) {
                    0 => self.run_words::<W32, C>(&fw, gw, max, d, h),
                    1 => self.run_words::<W64, C>(&fw, gw, max, d, h),
                    2 => self.run_words::<W128, C>(&fw, gw, max, d, h),
                    _ => self.run_words::<W192, C>(&fw, gw, max, d, h),
                };
            }
        }
        self.run::<Generic<C>>(fc, gc, max)
    }

    /// The product in word arithmetic `A`, its sums converted back over the denominator `d`
    /// by the hooks `h`.
    fn run_words<A: WordArith, C>(
        &self,
        fc: &[i64],
        gc: &[i64],
        max: usize,
        d: i128,
        h: WordHooks<C>,
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
        Some((exps, A::to_coeffs(sums, d, h)))
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
    if c.is_one() {
        return C::one();
    }
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
    // The iterators yield exactly `na` and `nb` coefficients.
    fn next<C: Ring>(it: &mut impl Iterator<Item = C>) -> C {
        it.next().unwrap_or_else(C::zero)
    }
    let (mut i, mut j) = (0, 0);
    while i < na && j < nb {
        let (ma, mb) = (&ae[i * w..(i + 1) * w], &be[j * w..(j + 1) * w]);
        match cmp_mono(ma, mb) {
            Ordering::Greater => {
                exps.extend_from_slice(ma);
                coeffs.push(next(&mut ac));
                i += 1;
            }
            Ordering::Less => {
                exps.extend_from_slice(mb);
                let b = next(&mut bc);
                coeffs.push(if negate { -b } else { b });
                j += 1;
            }
            Ordering::Equal => {
                let (a, b) = (next(&mut ac), next(&mut bc));
                let s = if negate { a - b } else { a + b };
                if !s.is_zero() {
                    exps.extend_from_slice(ma);
                    coeffs.push(s);
                }
                i += 1;
                j += 1;
            }
        }
    }
    // One list is used up: the rest of the other is copied as it is.
    exps.extend_from_slice(&ae[i * w..na * w]);
    coeffs.extend(ac);
    exps.extend_from_slice(&be[j * w..nb * w]);
    if negate {
        coeffs.extend(bc.map(|b| -b));
    } else {
        coeffs.extend(bc);
    }
    (exps, coeffs)
}

/// Products of at most this many term products are formed by [`mul_small`]: for them, planning
/// a kernel (exponent bounds, keys or cell indices, word conversions) costs more than the
/// products themselves.
const SMALL_PRODUCT: usize = 32;

/// `f g` for small factors (`#f #g <= SMALL_PRODUCT`): the rows `f_i g` are sorted, so the
/// product is their merge, the largest row head found by a scan (the shorter factor has at
/// most five terms), its equals in the other rows summed in the coefficients' own arithmetic,
/// and every output monomial written once. The monomials are compared word by word as they are
/// formed, most significant word first. `None` past `max` terms.
pub(super) fn mul_small<C: Ring>(
    shape: Shape,
    f: (&[u64], &[C]),
    g: (&[u64], &[C]),
    max: usize,
) -> Option<(Vec<u64>, Vec<C>)> {
    let ((fe, fc), (ge, gc)) = if f.1.len() <= g.1.len() {
        (f, g)
    } else {
        (g, f)
    };
    let (w, nf, ng) = (shape.words, fc.len(), gc.len());
    assert!(
        nf * ng <= SMALL_PRODUCT && nf <= SMALL_ROWS,
        "mul_small of {nf} x {ng} terms"
    );
    // Words above the highest non-zero word of every monomial of both factors compare equal.
    let top = |e: &[u64]| {
        e.chunks_exact(w.max(1))
            .map(|m| m.iter().rposition(|&x| x != 0).map_or(0, |t| t + 1))
            .max()
            .unwrap_or(0)
    };
    let used = top(&fe[..nf * w]).max(top(&ge[..ng * w]));
    let cmp = |(i, j): (usize, usize), (k, l): (usize, usize)| -> Ordering {
        for t in (0..used).rev() {
            let x = fe[i * w + t].wrapping_add(ge[j * w + t]);
            let y = fe[k * w + t].wrapping_add(ge[l * w + t]);
            match x.cmp(&y) {
                Ordering::Equal => continue,
                o => return o,
            }
        }
        Ordering::Equal
    };
    // The next term of every row (`ng`: the row is done).
    let mut heads = [0usize; SMALL_ROWS];
    let mut exps = Vec::with_capacity(nf * ng * w);
    let mut coeffs = Vec::with_capacity(nf * ng);
    loop {
        let mut top: Option<usize> = None;
        for i in 0..nf {
            if heads[i] < ng
                && top.is_none_or(|b| cmp((i, heads[i]), (b, heads[b])) == Ordering::Greater)
            {
                top = Some(i);
            }
        }
        let Some(b) = top else { break };
        let jb = heads[b];
        let mut acc = fc[b].mul_ref(&gc[jb]);
        heads[b] += 1;
        // A row is strictly decreasing: at most its head equals the top.
        for i in b + 1..nf {
            if heads[i] < ng && cmp((i, heads[i]), (b, jb)) == Ordering::Equal {
                acc += fc[i].mul_ref(&gc[heads[i]]);
                heads[i] += 1;
            }
        }
        if !acc.is_zero() {
            push_sum(
                &mut exps,
                &fe[b * w..(b + 1) * w],
                &ge[jb * w..(jb + 1) * w],
            );
            coeffs.push(acc);
            if coeffs.len() > max {
                return None;
            }
        }
    }
    Some((exps, coeffs))
}

/// The most terms of the shorter factor of a product of at most [`SMALL_PRODUCT`] term
/// products (`5 * 5 <= 32 < 6 * 6`).
const SMALL_ROWS: usize = 5;

/// `g * (m, c)`: a term times a sorted list stays sorted. The monomials of `g` take `wg` words
/// each, at most the `m.len()` words of the product and of the same field width (the missing
/// words are zero).
pub(super) fn mul_term<C: Ring>(
    (ge, wg): (&[u64], usize),
    gc: &[C],
    m: &[u64],
    c: &C,
    max: usize,
) -> Option<(Vec<u64>, Vec<C>)> {
    if gc.len() > max {
        return None;
    }
    let w = m.len();
    debug_assert!(wg <= w);
    let mut exps = Vec::with_capacity(gc.len() * w);
    if c.is_one() {
        // A unit coefficient (a variable or a monomial times a polynomial): the coefficients
        // are copied, none becomes zero, and no coefficient product is formed.
        for j in 0..gc.len() {
            push_product_padded(&mut exps, &ge[j * wg..(j + 1) * wg], m);
        }
        return Some((exps, gc.to_vec()));
    }
    let mut coeffs = Vec::with_capacity(gc.len());
    for (j, g) in gc.iter().enumerate() {
        let p = g.mul_ref(c);
        if !p.is_zero() {
            push_product_padded(&mut exps, &ge[j * wg..(j + 1) * wg], m);
            coeffs.push(p);
        }
    }
    Some((exps, coeffs))
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

/// The field-wise OR of the exponents of `n` monomials (`cap` variables): per variable at
/// least its largest exponent and of the same bit length, one OR per word.
pub(super) fn or_exps(shape: Shape, e: &[u64], n: usize, cap: usize) -> Vec<u64> {
    let w = shape.words;
    let mut acc = vec![0u64; w];
    if w > 0 {
        for m in e[..n * w].chunks_exact(w) {
            for (a, x) in acc.iter_mut().zip(m) {
                *a |= x;
            }
        }
    }
    let mut out = vec![0u64; cap];
    shape.for_each(&acc, |v, x| out[v] = x);
    out
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
    match shape.bits {
        8 => make_keys_in::<8>(shape.words, e, n, k, place),
        16 => make_keys_in::<16>(shape.words, e, n, k, place),
        32 => make_keys_in::<32>(shape.words, e, n, k, place),
        _ => make_keys_in::<64>(shape.words, e, n, k, place),
    }
}

/// [`make_keys`] with the field width `B` a constant: finding a field from its lowest set bit is
/// then a shift, not a division (the sums of chiang-identity key tens of thousands of monomials).
fn make_keys_in<const B: u32>(
    w: usize,
    e: &[u64],
    n: usize,
    k: usize,
    place: &[(usize, u32)],
) -> Vec<u64> {
    let per_word = (64 / B) as usize;
    let mask = if B == 64 { u64::MAX } else { (1u64 << B) - 1 };
    let mut keys = vec![0u64; n * k];
    if w == 0 {
        return keys;
    }
    for (key, m) in keys.chunks_exact_mut(k).zip(e.chunks_exact(w)) {
        for (j, &word) in m.iter().enumerate() {
            let mut x = word;
            while x != 0 {
                let field = x.trailing_zeros() / B;
                let sh = field * B;
                let (kw, at) = place[j * per_word + field as usize];
                key[kw] |= ((x >> sh) & mask) << at;
                x &= !(mask << sh);
            }
        }
    }
    keys
}

/// `out += a + b` for monomials of `w` words.
#[inline(always)]
pub(super) fn push_sum(out: &mut Vec<u64>, a: &[u64], b: &[u64]) {
    out.extend(a.iter().zip(b).map(|(x, y)| x.wrapping_add(*y)));
}
