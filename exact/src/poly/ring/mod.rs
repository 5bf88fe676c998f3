//! The [`Poly`] type: its terms, constructors, evaluation and substitution, powers, and the
//! ring operations (forwarded to the kernels in `kernels`). The products and powers within the
//! limits are in `limited`, the standard traits in `traits`.

use super::*;
use exactcheck_core::limits::{self, LimitError};
use exactcheck_core::Ring;
use std::borrow::Cow;
use std::cmp::Ordering;
use std::collections::HashMap;
use std::fmt;

mod limited;
mod traits;

pub use limited::SizeError;

// ------------------------------------------------------------------------------------ Poly

/// A sparse multivariate polynomial with coefficients in `C`, in canonical form (see the module
/// documentation): `==` is equality of polynomials.
#[derive(Clone)]
pub struct Poly<C> {
    pub(super) shape: Shape,
    /// `len * shape.words` words: the packed monomials, strictly decreasing.
    pub(super) exps: Vec<u64>,
    /// The coefficients, none zero.
    pub(super) coeffs: Vec<C>,
}

/// A borrowed monomial (exponent vector) of a [`Poly`].
#[derive(Clone, Copy)]
pub struct Monomial<'a> {
    pub(super) words: &'a [u64],
    pub(super) shape: Shape,
}

impl Monomial<'_> {
    /// The exponent of `var`.
    pub fn exponent(&self, var: Var) -> u32 {
        self.shape.get(self.words, var as usize) as u32
    }

    /// The non-zero exponents `(var, exponent)`, by increasing variable.
    pub fn exponents(&self) -> Vec<(Var, u32)> {
        let mut v = Vec::new();
        self.shape
            .for_each(self.words, |var, e| v.push((var as Var, e as u32)));
        v
    }

    /// The total degree (sum of the exponents).
    pub fn total_degree(&self) -> u64 {
        let mut d = 0;
        self.shape.for_each(self.words, |_, e| d += e);
        d
    }

    /// Whether this is the monomial `1` (all exponents zero).
    pub fn is_one(&self) -> bool {
        self.words.iter().all(|&w| w == 0)
    }
}

impl PartialEq for Monomial<'_> {
    fn eq(&self, other: &Self) -> bool {
        if self.shape == other.shape {
            self.words == other.words
        } else {
            self.exponents() == other.exponents()
        }
    }
}

impl fmt::Debug for Monomial<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.exponents()).finish()
    }
}

/// The iterator of [`Poly::terms`]: `(monomial, coefficient)` by decreasing monomial.
pub struct Terms<'a, C> {
    pub(super) poly: &'a Poly<C>,
    pub(super) next: usize,
}

impl<'a, C> Iterator for Terms<'a, C> {
    type Item = (Monomial<'a>, &'a C);
    fn next(&mut self) -> Option<Self::Item> {
        let i = self.next;
        let c = self.poly.coeffs.get(i)?;
        self.next += 1;
        Some((self.poly.monomial_at(i), c))
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        let r = self.poly.coeffs.len() - self.next;
        (r, Some(r))
    }
}

impl<C> ExactSizeIterator for Terms<'_, C> {}

impl<C> Poly<C> {
    #[inline]
    pub(super) fn mono(&self, i: usize) -> &[u64] {
        let w = self.shape.words;
        &self.exps[i * w..(i + 1) * w]
    }

    #[inline]
    pub(super) fn monomial_at(&self, i: usize) -> Monomial<'_> {
        Monomial {
            words: self.mono(i),
            shape: self.shape,
        }
    }

    /// The number of terms.
    pub fn len(&self) -> usize {
        self.coeffs.len()
    }

    /// Whether there are no terms (the zero polynomial).
    pub fn is_empty(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// The terms `(monomial, coefficient)`, by decreasing monomial.
    pub fn terms(&self) -> Terms<'_, C> {
        Terms {
            poly: self,
            next: 0,
        }
    }

    /// The coefficients, in the order of [`Poly::terms`].
    pub fn coefficients(&self) -> &[C] {
        &self.coeffs
    }

    /// The leading term (largest monomial in the order of the module documentation), `None` for
    /// the zero polynomial.
    pub fn leading_term(&self) -> Option<(Monomial<'_>, &C)> {
        self.terms().next()
    }

    /// The largest exponent of `var` (0 for the zero polynomial).
    pub fn degree_in(&self, var: Var) -> u32 {
        (0..self.len())
            .map(|i| self.shape.get(self.mono(i), var as usize))
            .max()
            .unwrap_or(0) as u32
    }

    /// The total degree: the largest sum of exponents of a term (0 for the zero polynomial).
    pub fn total_degree(&self) -> u64 {
        self.terms()
            .map(|(m, _)| m.total_degree())
            .max()
            .unwrap_or(0)
    }

    /// The variables that occur, increasing.
    pub fn variables(&self) -> Vec<Var> {
        let mut or = vec![0u64; self.shape.words];
        for i in 0..self.len() {
            for (o, w) in or.iter_mut().zip(self.mono(i)) {
                *o |= w;
            }
        }
        let mut v = Vec::new();
        self.shape.for_each(&or, |var, _| v.push(var as Var));
        v
    }

    /// Whether there is no variable (zero or a non-zero constant).
    pub fn is_constant(&self) -> bool {
        self.is_empty() || (self.len() == 1 && self.mono(0).iter().all(|&w| w == 0))
    }

    /// The number of variables the packed monomials have room for up to the highest one that
    /// occurs (one more than the highest variable index, 0 without variables).
    pub(super) fn nvars_used(&self) -> usize {
        let w = self.shape.words;
        let mut or = vec![0u64; w];
        for i in 0..self.len() {
            for (o, x) in or.iter_mut().zip(self.mono(i)) {
                *o |= x;
            }
        }
        match or.iter().rposition(|&x| x != 0) {
            None => 0,
            Some(k) => {
                let top = 63 - or[k].leading_zeros();
                k * self.shape.per_word() + (top / self.shape.bits) as usize + 1
            }
        }
    }

    /// An upper bound `2^b - 1` on every exponent (0 without variables).
    pub(super) fn exp_bound(&self) -> u64 {
        let or = self.exps.iter().fold(0u64, |a, &x| a | x);
        let m = self.shape.max_field(or);
        if m == 0 {
            0
        } else {
            (1u64 << (64 - m.leading_zeros())) - 1
        }
    }

    /// The largest exponent of every variable, indexed by variable.
    pub(super) fn max_exponents(&self) -> Vec<u64> {
        let mut v = vec![0u64; self.nvars_used()];
        for i in 0..self.len() {
            self.shape.for_each(self.mono(i), |var, e| {
                v[var] = v[var].max(e);
            });
        }
        v
    }

    /// The packed monomials in shape `to` (which must have room for all variables).
    pub(super) fn exps_in(&self, to: Shape) -> Cow<'_, [u64]> {
        if to == self.shape {
            Cow::Borrowed(&self.exps)
        } else {
            Cow::Owned(repack(&self.exps, self.len(), self.shape, to))
        }
    }

    /// A common shape for two polynomials (for merging; no exponent grows).
    pub(super) fn common_shape(&self, other: &Self) -> Shape {
        let bits = self.shape.bits.max(other.shape.bits);
        if self.shape.bits == other.shape.bits {
            Shape {
                bits,
                words: self.shape.words.max(other.shape.words),
            }
        } else {
            let nv = self.nvars_used().max(other.nvars_used());
            Shape {
                bits,
                words: Shape::words_for(bits, nv),
            }
        }
    }

    /// A shape of width at least `bits` with room for `nvars` variables and for the variables of
    /// `self`.
    pub(super) fn widened_shape(&self, bits: u32, nvars: usize) -> Shape {
        let bits = bits.max(self.shape.bits);
        let nv = nvars.max(if bits == self.shape.bits {
            self.shape.words * self.shape.per_word()
        } else {
            self.nvars_used()
        });
        Shape {
            bits,
            words: Shape::words_for(bits, nv),
        }
    }

    /// Whether the representation is canonical: every monomial well formed, strictly
    /// decreasing, no zero coefficient. Always true for values built through the public API;
    /// used by the property tests.
    pub fn is_canonical(&self) -> bool
    where
        C: Ring,
    {
        let s = self.shape;
        if ![8, 16, 32, 64].contains(&s.bits)
            || self.exps.len() != self.coeffs.len() * s.words
            || self.coeffs.iter().any(Ring::is_zero)
            || self.exps.iter().any(|w| w & s.guard() != 0)
        {
            return false;
        }
        let mut ok = true;
        for i in 0..self.len() {
            s.for_each(self.mono(i), |_, e| ok &= e <= MAX_EXP);
        }
        ok && (1..self.len()).all(|i| cmp_mono(self.mono(i - 1), self.mono(i)) == Ordering::Greater)
    }
}

impl<C: Ring> Poly<C> {
    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly {
            shape: Shape::CONST,
            exps: Vec::new(),
            coeffs: Vec::new(),
        }
    }

    /// The constant `c`.
    pub fn constant(c: C) -> Self {
        if c.is_zero() {
            return Self::zero();
        }
        Poly {
            shape: Shape::CONST,
            exps: Vec::new(),
            coeffs: vec![c],
        }
    }

    /// The variable `x_var`.
    ///
    /// Monomials are dense in the variable index: a polynomial in `x_var` takes `var / 8 + 1`
    /// words per term.
    pub fn var(var: Var) -> Self {
        let shape = Shape {
            bits: 8,
            words: Shape::words_for(8, var as usize + 1),
        };
        let mut exps = vec![0u64; shape.words];
        shape.set(&mut exps, var as usize, 1);
        Poly {
            shape,
            exps,
            coeffs: vec![C::one()],
        }
    }

    /// The term `c * prod x_v^e` for the pairs `(v, e)` (a variable may repeat: exponents add).
    ///
    /// # Panics
    /// When an exponent exceeds `u32::MAX`.
    pub fn monomial(c: C, exponents: &[(Var, u32)]) -> Self {
        Self::from_terms([(exponents, c)])
    }

    /// The polynomial `sum c * prod x_v^e` of the terms `(exponents, c)`, in any order, with
    /// repeated monomials and zero coefficients allowed (they are combined and dropped).
    ///
    /// # Panics
    /// When an exponent exceeds `u32::MAX`.
    pub fn from_terms<M: AsRef<[(Var, u32)]>>(terms: impl IntoIterator<Item = (M, C)>) -> Self {
        let terms: Vec<(M, C)> = terms.into_iter().collect();
        let mut max_var = None::<usize>;
        let mut max_exp = 0u64;
        for (m, _) in &terms {
            // The sum of a term's exponents bounds each of its (possibly repeated) variables.
            let mut sum = 0u64;
            for &(v, e) in m.as_ref() {
                max_var = max_var.max(Some(v as usize));
                sum += e as u64;
            }
            max_exp = max_exp.max(sum);
        }
        let bits = bits_for(max_exp.min(MAX_EXP)).unwrap_or(64);
        let shape = Shape {
            bits,
            words: max_var.map_or(0, |v| Shape::words_for(bits, v + 1)),
        };
        let n = terms.len();
        let mut exps = vec![0u64; n * shape.words];
        let mut coeffs = Vec::with_capacity(n);
        for (i, (m, c)) in terms.into_iter().enumerate() {
            let dst = &mut exps[i * shape.words..(i + 1) * shape.words];
            for &(v, e) in m.as_ref() {
                let total = shape.get(dst, v as usize) + e as u64;
                assert!(total <= MAX_EXP, "exponent overflow: above u32::MAX");
                shape.set(dst, v as usize, total);
            }
            coeffs.push(c);
        }
        Self::from_unsorted(shape, exps, coeffs)
    }

    /// Sorts and combines terms given in any order.
    pub(super) fn from_unsorted(shape: Shape, exps: Vec<u64>, mut coeffs: Vec<C>) -> Self {
        let n = coeffs.len();
        let w = shape.words;
        let mut idx: Vec<u32> = (0..n as u32).collect();
        let key = |i: u32| &exps[i as usize * w..(i as usize + 1) * w];
        idx.sort_unstable_by(|&a, &b| cmp_mono(key(b), key(a)));
        let mut out_e = Vec::with_capacity(n * w);
        let mut out_c = Vec::with_capacity(n);
        let mut k = 0;
        while k < n {
            let i = idx[k] as usize;
            let m = key(i as u32);
            let mut acc = std::mem::replace(&mut coeffs[i], C::zero());
            k += 1;
            while k < n && key(idx[k]) == m {
                acc += std::mem::replace(&mut coeffs[idx[k] as usize], C::zero());
                k += 1;
            }
            if !acc.is_zero() {
                out_e.extend_from_slice(m);
                out_c.push(acc);
            }
        }
        Poly {
            shape,
            exps: out_e,
            coeffs: out_c,
        }
    }

    /// The coefficient of the monomial `prod x_v^e` for the pairs `(v, e)` (zero if absent; a
    /// variable may repeat: exponents add).
    pub fn coefficient(&self, exponents: &[(Var, u32)]) -> C {
        let mut m: std::collections::BTreeMap<usize, u64> = std::collections::BTreeMap::new();
        for &(v, e) in exponents {
            *m.entry(v as usize).or_insert(0) += e as u64;
        }
        // Pack it in our shape (if it does not fit, it is not a monomial of ours).
        let mut key = vec![0u64; self.shape.words];
        for (v, e) in m {
            if e == 0 {
                continue;
            }
            if v >= self.shape.words * self.shape.per_word() || e >= 1 << (self.shape.bits - 1) {
                return C::zero();
            }
            self.shape.set(&mut key, v, e);
        }
        // Binary search in the decreasing list.
        let (mut lo, mut hi) = (0, self.len());
        while lo < hi {
            let mid = (lo + hi) / 2;
            match cmp_mono(self.mono(mid), &key) {
                Ordering::Equal => return self.coeffs[mid].clone(),
                Ordering::Greater => lo = mid + 1,
                Ordering::Less => hi = mid,
            }
        }
        C::zero()
    }

    /// The constant value, if the polynomial is a constant (`Some(zero)` for zero).
    pub fn constant_value(&self) -> Option<C> {
        if self.is_empty() {
            Some(C::zero())
        } else if self.is_constant() {
            Some(self.coeffs[0].clone())
        } else {
            None
        }
    }

    /// `c * self`.
    pub fn scale(&self, c: &C) -> Self {
        if c.is_zero() {
            return Self::zero();
        }
        let mut exps = Vec::with_capacity(self.exps.len());
        let mut coeffs = Vec::with_capacity(self.len());
        for i in 0..self.len() {
            let p = self.coeffs[i].mul_ref(c);
            if !p.is_zero() {
                exps.extend_from_slice(self.mono(i));
                coeffs.push(p);
            }
        }
        Poly {
            shape: self.shape,
            exps,
            coeffs,
        }
    }

    /// The polynomial with every coefficient mapped by `f` (terms mapped to zero are dropped).
    pub fn map_coeffs<D: Ring>(&self, mut f: impl FnMut(&C) -> D) -> Poly<D> {
        let mut exps = Vec::with_capacity(self.exps.len());
        let mut coeffs = Vec::with_capacity(self.len());
        for i in 0..self.len() {
            let d = f(&self.coeffs[i]);
            if !d.is_zero() {
                exps.extend_from_slice(self.mono(i));
                coeffs.push(d);
            }
        }
        Poly {
            shape: self.shape,
            exps,
            coeffs,
        }
    }

    /// The value at `point` (`point[v]` for variable `v`), with coefficients mapped by `coeff`.
    ///
    /// # Panics
    /// When a variable of the polynomial has no entry in `point`.
    pub fn eval<R: Ring>(&self, point: &[R], coeff: impl Fn(&C) -> R) -> R {
        // The powers of each variable that occur, computed once: the distinct exponents in
        // increasing order, each from the previous one times the gap's power by binary powering.
        // So `x^100000` costs 17 squarings and keeps one value, not a table of every power up
        // to the degree (which for `x^100000` at 1/2 alone holds 625 MB).
        let mut used: Vec<Vec<u64>> = Vec::new();
        for i in 0..self.len() {
            self.shape.for_each(self.mono(i), |v, e| {
                if used.len() <= v {
                    used.resize_with(v + 1, Vec::new);
                }
                used[v].push(e);
            });
        }
        let powers: Vec<Vec<(u64, R)>> = used
            .into_iter()
            .enumerate()
            .map(|(v, mut es)| {
                es.sort_unstable();
                es.dedup();
                if es.is_empty() {
                    return Vec::new();
                }
                let x = point.get(v).unwrap_or_else(|| {
                    panic!(
                        "eval: no value for variable {v} (point has {})",
                        point.len()
                    )
                });
                let mut out: Vec<(u64, R)> = Vec::with_capacity(es.len());
                for e in es {
                    let next = match out.last() {
                        None => power_of(x, e),
                        Some((prev, p)) if e - prev == 1 => p.mul_ref(x),
                        Some((prev, p)) => p.mul_ref(&power_of(x, e - prev)),
                    };
                    out.push((e, next));
                }
                out
            })
            .collect();
        // The terms are summed as a balanced tree (a binary counter of partial sums): adding
        // exact values costs with their size, and a running sum would be full size from the
        // start (for rationals, a gcd of the full size per term).
        let mut partial: Vec<(u32, R)> = Vec::new();
        for i in 0..self.len() {
            let mut t = coeff(&self.coeffs[i]);
            self.shape.for_each(self.mono(i), |v, e| {
                let k = powers[v]
                    .binary_search_by_key(&e, |(f, _)| *f)
                    .expect("every exponent that occurs was tabulated above");
                t *= &powers[v][k].1;
            });
            let mut level = 0;
            while partial.last().is_some_and(|(l, _)| *l == level) {
                let (_, s) = partial.pop().expect("checked to be non-empty");
                t = s + t;
                level += 1;
            }
            partial.push((level, t));
        }
        partial
            .into_iter()
            .rev()
            .fold(R::zero(), |acc, (_, t)| t + acc)
    }

    /// The polynomial with `var` replaced by `value`.
    ///
    /// # Panics
    /// When an exponent of the result would exceed `u32::MAX`.
    pub fn substitute(&self, var: Var, value: &Poly<C>) -> Poly<C> {
        let v = var as usize;
        // Split self = sum_k x^k P_k; removing x^k keeps each P_k sorted.
        let mut parts: Vec<(u64, Vec<u64>, Vec<C>)> = Vec::new();
        let mut slot: HashMap<u64, usize> = HashMap::new();
        for i in 0..self.len() {
            let k = self.shape.get(self.mono(i), v);
            let j = *slot.entry(k).or_insert_with(|| {
                parts.push((k, Vec::new(), Vec::new()));
                parts.len() - 1
            });
            let start = parts[j].1.len();
            parts[j].1.extend_from_slice(self.mono(i));
            if k > 0 {
                self.shape.set(&mut parts[j].1[start..], v, 0);
            }
            parts[j].2.push(self.coeffs[i].clone());
        }
        parts.sort_unstable_by_key(|p| p.0);
        let mut power = Poly::one();
        let mut have = 0u64;
        let mut sums = Vec::with_capacity(parts.len());
        for (k, exps, coeffs) in parts {
            let pk = Poly {
                shape: self.shape,
                exps,
                coeffs,
            };
            if k > have {
                power = power.mul_ref(&value.pow_u64(k - have));
                have = k;
            }
            sums.push(pk.mul_ref(&power));
        }
        Poly::sum(sums)
    }

    /// The sum of many polynomials. Few or small summands are added pairwise (balanced, which
    /// keeps the merges of similar sizes); many large ones in one pass, a k-way merge by a heap
    /// on compact keys of one or two words (as in multiplication) that writes every term once.
    pub fn sum(polys: Vec<Poly<C>>) -> Poly<C> {
        let mut polys: Vec<Poly<C>> = polys.into_iter().filter(|p| !p.is_empty()).collect();
        match polys.len() {
            0 => return Poly::zero(),
            1 => return polys.pop().unwrap_or_else(Poly::zero),
            n if n <= 4 || polys.iter().map(Poly::len).sum::<usize>() < 256 => {
                return Poly::sum_pairwise(polys)
            }
            _ => {}
        }
        let bits = polys.iter().map(|p| p.shape.bits).max().unwrap_or(8);
        let words = if polys.iter().all(|p| p.shape.bits == bits) {
            polys.iter().map(|p| p.shape.words).max().unwrap_or(0)
        } else {
            Shape::words_for(bits, polys.iter().map(Poly::nvars_used).max().unwrap_or(0))
        };
        let shape = Shape { bits, words };
        let cap = words * shape.per_word();
        // The keys only need every variable's bit length: the OR of the exponents has the
        // bit length of their maximum, at one OR per word.
        // Every summand is read in its own packing (the variables it has room for are below
        // `cap`); only one of another field width is repacked, for the output.
        let mut need = vec![0u64; cap];
        for p in &polys {
            for (n, m) in need.iter_mut().zip(or_exps(p.shape, &p.exps, p.len(), cap)) {
                *n |= m;
            }
        }
        let (k, place) = key_layout(&need);
        if k > 2 {
            return Poly::sum_pairwise(polys);
        }
        let total: usize = polys.iter().map(Poly::len).sum();
        let mut exps_of = Vec::with_capacity(polys.len());
        let mut words_of = Vec::with_capacity(polys.len());
        let mut keys_of = Vec::with_capacity(polys.len());
        let mut coeffs_of = Vec::with_capacity(polys.len());
        for p in polys {
            let n = p.len();
            keys_of.push(make_keys(p.shape, &p.exps, n, k, &place));
            let own = p.shape.bits == bits && p.shape.words <= words;
            words_of.push(if own { p.shape.words } else { words });
            let (e, c) = if own {
                (p.exps, p.coeffs)
            } else {
                p.into_parts(shape)
            };
            exps_of.push(e);
            coeffs_of.push(c.into_iter());
        }
        let terms = Summands {
            exps: exps_of,
            words: words_of,
            coeffs: coeffs_of,
            total,
        };
        if k == 1 {
            sum_heap(shape, keys_of, terms)
        } else {
            // Two key words as one u128 (most significant word last), as in the products.
            let wide = keys_of
                .iter()
                .map(|keys| {
                    keys.chunks_exact(2)
                        .map(|p| (u128::from(p[1]) << 64) | u128::from(p[0]))
                        .collect()
                })
                .collect();
            sum_heap(shape, wide, terms)
        }
    }

    /// The sum of many polynomials, added pairwise (balanced), which keeps the merges of similar
    /// sizes.
    pub(super) fn sum_pairwise(mut polys: Vec<Poly<C>>) -> Poly<C> {
        while polys.len() > 1 {
            let mut next = Vec::with_capacity(polys.len().div_ceil(2));
            let mut it = polys.into_iter();
            while let Some(a) = it.next() {
                match it.next() {
                    Some(b) => next.push(a + b),
                    None => next.push(a),
                }
            }
            polys = next;
        }
        polys.pop().unwrap_or_else(Poly::zero)
    }

    /// The largest exponent of any variable (0 without variables).
    pub fn max_exponent(&self) -> u32 {
        self.max_exponents().into_iter().max().unwrap_or(0) as u32
    }

    /// `self * rhs`, or `None` when an exponent of the product would exceed `u32::MAX` (where
    /// `*` panics).
    pub fn checked_mul(&self, rhs: &Self) -> Option<Self> {
        if self.product_exponent_overflows(rhs) {
            return None;
        }
        Some(self.mul_impl(rhs))
    }

    /// Whether an exponent of `self * rhs` would exceed `u32::MAX` (neither factor zero).
    fn product_exponent_overflows(&self, rhs: &Self) -> bool {
        if self.is_empty() || rhs.is_empty() || self.exp_bound() + rhs.exp_bound() <= MAX_EXP {
            return false;
        }
        let (a, b) = (self.max_exponents(), rhs.max_exponents());
        let worst = (0..a.len().min(b.len()))
            .map(|v| a[v] + b[v])
            .max()
            .unwrap_or(0);
        worst > MAX_EXP
    }

    /// `self^e`, or `None` when an exponent of the power would exceed `u32::MAX` (where
    /// [`Ring::pow`] panics).
    pub fn checked_pow(&self, e: u32) -> Option<Self> {
        if e > 1 && self.max_exponent() as u64 * e as u64 > MAX_EXP {
            return None;
        }
        Some(self.pow_u64(e as u64))
    }

    /// `self^e` for a 64-bit exponent: a single term directly, the content split off, then the
    /// power recurrence or binary powering as the cost model of `power` chooses.
    pub(super) fn pow_u64(&self, e: u64) -> Self {
        if e == 0 {
            return Poly::one();
        }
        if self.len() <= 1 {
            return self.pow_term(e);
        }
        if let Some((c, prim)) = self.split_content() {
            return prim.pow_u64(e).scale(&pow_coeff(&c, e));
        }
        if let Some(p) = self.pow_by_recurrence(e, |_| usize::MAX) {
            return p.expect("a power without a cap on its terms always completes");
        }
        binary_power(self, e, |a, b| a.mul_ref(b), Poly::square_impl)
    }

    /// `self = c * P` with a primitive integer `P` when the coefficients are rationals whose
    /// content `c` is not 1 (see [`super::words`]); `None` otherwise. Powers expand `P^e` and
    /// scale by `c^e` once, so a big rational content never rides through the expansion.
    pub(super) fn split_content(&self) -> Option<(C, Self)> {
        let (c, coeffs) = super::words::content_of(&self.coeffs)?;
        Some((
            c,
            Poly {
                shape: self.shape,
                exps: self.exps.clone(),
                coeffs,
            },
        ))
    }

    /// `self^e` for zero or a single term.
    pub(super) fn pow_term(&self, e: u64) -> Self {
        if self.is_empty() {
            return Poly::zero();
        }
        let c = pow_coeff(&self.coeffs[0], e);
        if c.is_zero() {
            return Poly::zero();
        }
        let need = self.exp_bound().saturating_mul(e);
        if need < 1 << (self.shape.bits - 1) {
            // Every exponent times `e` stays below the guard bit of its field: the words
            // multiply without carries between fields.
            return Poly {
                shape: self.shape,
                exps: self.mono(0).iter().map(|w| w * e).collect(),
                coeffs: vec![c],
            };
        }
        let mut exps = Vec::new();
        let shape = if need <= MAX_EXP {
            let sh = self.widened_shape(bits_for(need).unwrap_or(64), 0);
            let mut m = vec![0u64; sh.words];
            self.shape
                .for_each(self.mono(0), |v, x| sh.set(&mut m, v, x * e));
            exps.extend_from_slice(&m);
            sh
        } else {
            let mut pairs = Vec::new();
            self.shape.for_each(self.mono(0), |v, x| {
                let t = x.checked_mul(e).filter(|&t| t <= MAX_EXP);
                pairs.push((
                    v as Var,
                    t.expect("exponent overflow: above u32::MAX") as u32,
                ));
            });
            return Poly::monomial(c, &pairs);
        };
        Poly {
            shape,
            exps,
            coeffs: vec![c],
        }
    }
}

/// `x^e` by binary powering (`e >= 1`).
fn power_of<R: Ring>(x: &R, e: u64) -> R {
    binary_power(x, e, R::mul_ref, R::square)
}

/// `x^e` for `e >= 1` by binary powering with the given product and square: the one loop of the
/// powers (of polynomials, their coefficients, and the generic reference of the tests).
pub(super) fn binary_power<T: Clone>(
    x: &T,
    mut e: u64,
    mul: impl Fn(&T, &T) -> T,
    square: impl Fn(&T) -> T,
) -> T {
    debug_assert!(e >= 1, "binary_power of the empty product");
    let mut acc: Option<T> = None;
    let mut sq = x.clone();
    loop {
        if e & 1 == 1 {
            acc = Some(match acc {
                None => sq.clone(),
                Some(a) => mul(&a, &sq),
            });
        }
        e >>= 1;
        if e == 0 {
            return acc.unwrap_or(sq);
        }
        sq = square(&sq);
    }
}

/// The summands of a k-way merge: every summand's packed monomials (of the sum's field width,
/// with at most its words: missing words are zero) and their words, the coefficients, and the
/// total number of terms.
struct Summands<C> {
    exps: Vec<Vec<u64>>,
    words: Vec<usize>,
    coeffs: Vec<std::vec::IntoIter<C>>,
    total: usize,
}

/// The k-way merge of [`Poly::sum`] over compact keys of one or two words (`u64`, `u128`):
/// a heap of `(key, summand)` pairs, equal monomials accumulated as they leave it, every term
/// written once.
fn sum_heap<C: Ring, Key: HeapKey>(
    shape: Shape,
    keys_of: Vec<Vec<Key>>,
    s: Summands<C>,
) -> Poly<C> {
    let Summands {
        exps: exps_of,
        words: words_of,
        coeffs: mut coeffs_of,
        total,
    } = s;
    let w = shape.words;
    let mut pos = vec![0usize; keys_of.len()];
    let mut heap: Vec<(Key, u32)> = Vec::with_capacity(keys_of.len());
    for (p, keys) in keys_of.iter().enumerate() {
        push1(&mut heap, (keys[0], p as u32));
    }
    let mut out_e: Vec<u64> = Vec::with_capacity(total * w);
    let mut out_c: Vec<C> = Vec::with_capacity(total);
    // Takes the root's next coefficient and moves its summand on.
    let mut step = |heap: &mut Vec<(Key, u32)>, pos: &mut Vec<usize>| -> C {
        let p = heap[0].1 as usize;
        let c = coeffs_of[p].next().unwrap_or_else(C::zero);
        pos[p] += 1;
        match keys_of[p].get(pos[p]) {
            Some(&key) => heap[0].0 = key,
            None => {
                let last = heap.pop().expect("the root exists");
                if heap.is_empty() {
                    return c;
                }
                heap[0] = last;
            }
        }
        sift_down1(heap);
        c
    };
    while let Some(&(key, p)) = heap.first() {
        let (p, i) = (p as usize, pos[p as usize]);
        let mut acc = step(&mut heap, &mut pos);
        while heap.first().is_some_and(|t| t.0 == key) {
            acc += step(&mut heap, &mut pos);
        }
        if !acc.is_zero() {
            let wp = words_of[p];
            push_padded(&mut out_e, &exps_of[p][i * wp..(i + 1) * wp], w);
            out_c.push(acc);
        }
    }
    Poly {
        shape,
        exps: out_e,
        coeffs: out_c,
    }
}
