//! Sparse multivariate polynomials over a coefficient ring: the scalar that turns generic formula
//! code into a symbolic proof.
//!
//! [`Poly<C>`] implements [`Ring`], so every formula written against `Ring` (DESIGN.md, "The scalar
//! traits") runs over polynomials: instantiate it with `Poly<Rational>` variables and an identity
//! is **proved** when its residual expands to the zero polynomial. Because the representation is
//! canonical, that test is `residual.is_zero()`.
//!
//! # Variables
//! A variable is an index ([`Var`], a `u32`); polynomials store no names. The [`Vars`] table maps
//! names to indices for the parser ([`crate::expr`]) and the printer ([`Poly::display`]).
//! `zero()`, `one()` and `from_i64()` need no variables at all. The monomial representation is
//! dense in the variable index (see below), so indices should be small and consecutive, as
//! [`Vars`] hands them out.
//!
//! # The monomial order
//! Terms are kept in **lexicographic order with the variables ranked by index, the highest index
//! largest** (`x_0 < x_1 < x_2 < ...`, so `x_1 > x_0^k` for every `k`), sorted by decreasing
//! monomial, without zero coefficients and without repeated monomials. The first term is the
//! leading term. This one order is used for the canonical form, for printing, and for
//! [`Poly::reduce`] and [`groebner`]. It is chosen so that [`unit_circle_relation`]`(c, s)` with
//! `c` declared before `s` has the leading monomial `s^2`: reduction then rewrites
//! `s^2 -> 1 - c^2` (declare the cosine before the sine).
//!
//! # Representation
//! Exponent vectors are packed into `u64` words, `64 / bits` variables per word, with a field
//! width `bits` of 8, 16, 32 or 64 chosen per polynomial (as in FLINT's `mpoly`): variable `v`
//! lives in word `v / (64 / bits)`, and within a word the higher variables take the higher bits,
//! so comparing the words as one multi-word unsigned integer, most significant word last, is the
//! monomial order, and multiplying monomials is adding words. The top bit of every field is a
//! guard bit that stays clear (exponents below `2^(bits-1)`), which makes divisibility one
//! subtraction per word. A polynomial uses as many words as its highest variable needs; operands
//! of different layouts are repacked to a common one. Before a product is formed, a bound on its
//! exponents (from the OR of all exponent words) picks a field width in which no field can
//! overflow, so the kernels never check. Exponents are limited to `u32::MAX` (the operators
//! panic beyond; [`Poly::checked_mul`] and [`Poly::checked_pow`] report it).
//!
//! # Algorithms
//! * Addition and subtraction merge the two sorted term lists (monomials of up to 16 words are
//!   compared and copied as fixed-size arrays). Sums of many large polynomials ([`Poly::sum`])
//!   are one k-way heap merge.
//! * Multiplication by a single term shifts and scales (the order is a monoid order, so the
//!   result is still sorted). Otherwise the exponents of the two operands are first re-packed
//!   into **compact keys**: each variable gets just the bits its largest exponent in the product
//!   needs (a Kronecker substitution that keeps the order). Then:
//!   - when the box of possible product exponents is small (at most 4 cells per term product,
//!     and `2^22` cells), products are accumulated in a dense array indexed by mixed radix, and
//!     the touched cells sorted once (dense few-variable products);
//!   - otherwise by Johnson's heap algorithm with the chained stream insertion of Monagan and
//!     Pearce ("Sparse polynomial division using a heap", 2011): a heap of at most
//!     `min(#f, #g)` streams yields the products in decreasing order, equal monomials are
//!     accumulated as they leave the heap, and the result is born sorted, with no per-term
//!     allocation. With one-word keys (W1: 74 variables in 10 words become one key word) the
//!     heap holds the keys themselves. Squaring runs the heap over the pairs `i <= j` only.
//!
//!   Full monomials are formed once per output term.
//! * Powers by binary powering (squarings and multiplications); a single term is raised directly.
//! * Normal forms ([`Poly::reduce`]) by multivariate division with a heap of pending monomials
//!   and a hash map of their coefficients: every monomial leaves the heap once, already final. For
//!   independent unit-circle relations `c_i^2 + s_i^2 - 1` (a Gröbner basis in any order) there
//!   is a closed form, `s^(2h+r) = s^r (1 - c^2)^h`, applied term by term
//!   ([`Poly::reduce_unit_circle`]); `reduce` recognises such relation sets and takes it.
//! * Gröbner bases ([`groebner`]) by Buchberger's algorithm with both of Buchberger's criteria
//!   (coprime leading monomials; the chain criterion), the normal pair selection strategy, and a
//!   final inter-reduction: the result is the unique reduced Gröbner basis, so [`Poly::reduce`]
//!   against it is a canonical normal form.
//!
//! # Performance
//! W1 (SPEC §4 at `(m, n) = (8, 13)`: a 9.5 kB expression pair over 74 variables, 5,841 terms)
//! parses, expands and compares in about 5 ms on the project machine, python-flint's
//! `fmpq_mpoly` takes 7.4 ms, SymPy 3.3 s (`exact/benches/poly.rs`). A large share of the time
//! is coefficient arithmetic in [`crate::Rational`].

use exactcheck_core::{Field, Ring};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};
use std::fmt;
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A variable: an index into a [`Vars`] table (or any numbering the caller chooses).
pub type Var = u32;

/// The largest supported exponent.
const MAX_EXP: u64 = u32::MAX as u64;

// ------------------------------------------------------------------------------------ layout

/// How the exponent vectors of one polynomial are packed: the field width and the number of
/// words per monomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Shape {
    bits: u32,
    words: usize,
}

/// The guard bits (top bit of every field) for a field width.
#[inline]
const fn guard_mask(bits: u32) -> u64 {
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
fn bits_for(e: u64) -> Option<u32> {
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
    const CONST: Shape = Shape { bits: 8, words: 0 };

    #[inline]
    fn per_word(self) -> usize {
        (64 / self.bits) as usize
    }
    #[inline]
    fn mask(self) -> u64 {
        if self.bits == 64 {
            u64::MAX
        } else {
            (1u64 << self.bits) - 1
        }
    }
    #[inline]
    fn guard(self) -> u64 {
        guard_mask(self.bits)
    }
    /// The number of words needed for `nvars` variables at this width.
    #[inline]
    fn words_for(bits: u32, nvars: usize) -> usize {
        nvars.div_ceil((64 / bits) as usize)
    }
    /// The exponent of `var` in the packed monomial `m`.
    #[inline]
    fn get(self, m: &[u64], var: usize) -> u64 {
        let pw = self.per_word();
        match m.get(var / pw) {
            Some(w) => (w >> ((var % pw) as u32 * self.bits)) & self.mask(),
            None => 0,
        }
    }
    /// Adds `e` to the exponent of `var` (the caller guarantees there is room).
    #[inline]
    fn add(self, m: &mut [u64], var: usize, e: u64) {
        let pw = self.per_word();
        m[var / pw] += e << ((var % pw) as u32 * self.bits);
    }
    /// Sets the exponent of `var` to `e` (the caller guarantees there is room).
    #[inline]
    fn set(self, m: &mut [u64], var: usize, e: u64) {
        let pw = self.per_word();
        let sh = (var % pw) as u32 * self.bits;
        let w = &mut m[var / pw];
        *w = (*w & !(self.mask() << sh)) | (e << sh);
    }
    /// The largest field value in a word.
    #[inline]
    fn max_field(self, mut w: u64) -> u64 {
        let mut best = 0;
        while w != 0 {
            best = best.max(w & self.mask());
            w = if self.bits == 64 { 0 } else { w >> self.bits };
        }
        best
    }
    /// Calls `f(var, exponent)` for every non-zero exponent of `m`, by increasing variable.
    #[inline]
    fn for_each(self, m: &[u64], mut f: impl FnMut(usize, u64)) {
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
fn cmp_mono(a: &[u64], b: &[u64]) -> Ordering {
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
fn add_mono(out: &mut [u64], a: &[u64], b: &[u64]) {
    for ((o, x), y) in out.iter_mut().zip(a).zip(b) {
        *o = x.wrapping_add(*y);
    }
}

/// Whether monomial `d` divides `m` (both with clear guard bits).
#[inline]
fn divides(d: &[u64], m: &[u64], guard: u64) -> bool {
    d.iter()
        .zip(m)
        .all(|(&d, &m)| ((m | guard).wrapping_sub(d)) & guard == guard)
}

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

/// Repacks `n` monomials from one shape to another that has room for all their variables.
fn repack(exps: &[u64], n: usize, from: Shape, to: Shape) -> Vec<u64> {
    let mut out = vec![0u64; n * to.words];
    if from.bits == to.bits {
        let w = from.words.min(to.words);
        for i in 0..n {
            out[i * to.words..i * to.words + w]
                .copy_from_slice(&exps[i * from.words..i * from.words + w]);
        }
    } else {
        for i in 0..n {
            let dst = &mut out[i * to.words..(i + 1) * to.words];
            from.for_each(&exps[i * from.words..(i + 1) * from.words], |v, e| {
                to.set(dst, v, e)
            });
        }
    }
    out
}

// ------------------------------------------------------------------------------------ Vars

/// A table of variable names: name <-> index. Indices are handed out consecutively from 0 in the
/// order names are first seen.
///
/// Names should be identifiers (`[A-Za-z_][A-Za-z0-9_]*`, not `sqrt`) for printed polynomials to
/// parse back ([`crate::expr`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Vars {
    names: Vec<String>,
    index: HashMap<String, Var>,
}

impl Vars {
    /// An empty table.
    pub fn new() -> Self {
        Self::default()
    }

    /// A table with these names, numbered in order (repeated names keep their first index).
    pub fn from_names<S: AsRef<str>>(names: impl IntoIterator<Item = S>) -> Self {
        let mut v = Vars::new();
        for n in names {
            v.var(n.as_ref());
        }
        v
    }

    /// The index of `name`, adding it to the table if it is new.
    ///
    /// # Panics
    /// When the table already holds `u32::MAX` names.
    pub fn var(&mut self, name: &str) -> Var {
        if let Some(&i) = self.index.get(name) {
            return i;
        }
        let i = Var::try_from(self.names.len()).expect("too many variables");
        self.names.push(name.to_string());
        self.index.insert(name.to_string(), i);
        i
    }

    /// The polynomial of the variable `name` (added to the table if new).
    pub fn poly<C: Ring>(&mut self, name: &str) -> Poly<C> {
        Poly::var(self.var(name))
    }

    /// The index of `name`, if it is in the table.
    pub fn get(&self, name: &str) -> Option<Var> {
        self.index.get(name).copied()
    }

    /// The name of variable `var`, if it is in the table.
    pub fn name(&self, var: Var) -> Option<&str> {
        self.names.get(var as usize).map(String::as_str)
    }

    /// The names, by index.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The number of names.
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// Whether the table is empty.
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }
}

// ------------------------------------------------------------------------------------ Poly

/// A sparse multivariate polynomial with coefficients in `C`, in canonical form (see the module
/// documentation): `==` is equality of polynomials.
#[derive(Clone)]
pub struct Poly<C> {
    shape: Shape,
    /// `len * shape.words` words: the packed monomials, strictly decreasing.
    exps: Vec<u64>,
    /// The coefficients, none zero.
    coeffs: Vec<C>,
}

/// A borrowed monomial (exponent vector) of a [`Poly`].
#[derive(Clone, Copy)]
pub struct Monomial<'a> {
    words: &'a [u64],
    shape: Shape,
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
    poly: &'a Poly<C>,
    next: usize,
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
    fn mono(&self, i: usize) -> &[u64] {
        let w = self.shape.words;
        &self.exps[i * w..(i + 1) * w]
    }

    #[inline]
    fn monomial_at(&self, i: usize) -> Monomial<'_> {
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
    fn nvars_used(&self) -> usize {
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
    fn exp_bound(&self) -> u64 {
        let or = self.exps.iter().fold(0u64, |a, &x| a | x);
        let m = self.shape.max_field(or);
        if m == 0 {
            0
        } else {
            (1u64 << (64 - m.leading_zeros())) - 1
        }
    }

    /// The largest exponent of every variable, indexed by variable.
    fn max_exponents(&self) -> Vec<u64> {
        let mut v = vec![0u64; self.nvars_used()];
        for i in 0..self.len() {
            self.shape.for_each(self.mono(i), |var, e| {
                v[var] = v[var].max(e);
            });
        }
        v
    }

    /// The packed monomials in shape `to` (which must have room for all variables).
    fn exps_in(&self, to: Shape) -> Cow<'_, [u64]> {
        if to == self.shape {
            Cow::Borrowed(&self.exps)
        } else {
            Cow::Owned(repack(&self.exps, self.len(), self.shape, to))
        }
    }

    /// A common shape for two polynomials (for merging; no exponent grows).
    fn common_shape(&self, other: &Self) -> Shape {
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
    fn widened_shape(&self, bits: u32, nvars: usize) -> Shape {
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
    fn from_unsorted(shape: Shape, exps: Vec<u64>, mut coeffs: Vec<C>) -> Self {
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
        // Powers of each variable, computed once up to the degree needed.
        let degs = self.max_exponents();
        let powers: Vec<Vec<R>> = degs
            .iter()
            .enumerate()
            .map(|(v, &d)| {
                let mut p = Vec::with_capacity(d as usize);
                if d > 0 {
                    let x = point.get(v).unwrap_or_else(|| {
                        panic!(
                            "eval: no value for variable {v} (point has {})",
                            point.len()
                        )
                    });
                    p.push(x.clone());
                    for k in 1..d as usize {
                        let next = p[k - 1].mul_ref(x);
                        p.push(next);
                    }
                }
                p
            })
            .collect();
        let mut acc = R::zero();
        for i in 0..self.len() {
            let mut t = coeff(&self.coeffs[i]);
            self.shape.for_each(self.mono(i), |v, e| {
                t *= &powers[v][e as usize - 1];
            });
            acc += t;
        }
        acc
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
    /// on compact one-word keys (as in multiplication) that writes every term once.
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
        let mut need = vec![0u64; cap];
        for p in &polys {
            let e = p.exps_in(shape);
            for (n, m) in need.iter_mut().zip(max_exps(shape, &e, p.len(), cap)) {
                *n = (*n).max(m);
            }
        }
        let (k, place) = key_layout(&need);
        if k > 1 {
            return Poly::sum_pairwise(polys);
        }
        let total: usize = polys.iter().map(Poly::len).sum();
        let mut exps_of = Vec::with_capacity(polys.len());
        let mut keys_of = Vec::with_capacity(polys.len());
        let mut coeffs_of = Vec::with_capacity(polys.len());
        for p in polys {
            let n = p.len();
            let (e, c) = p.into_parts(shape);
            keys_of.push(make_keys(shape, &e, n, 1, &place));
            exps_of.push(e);
            coeffs_of.push(c.into_iter());
        }
        let w = words;
        let mut pos = vec![0usize; keys_of.len()];
        let mut heap: Vec<(u64, u32)> = Vec::with_capacity(keys_of.len());
        for (p, keys) in keys_of.iter().enumerate() {
            push1(&mut heap, (keys[0], p as u32));
        }
        let mut out_e: Vec<u64> = Vec::with_capacity(total * w);
        let mut out_c: Vec<C> = Vec::with_capacity(total);
        // Takes the root's next coefficient and moves its summand on.
        let mut step = |heap: &mut Vec<(u64, u32)>, pos: &mut Vec<usize>| -> C {
            let p = heap[0].1 as usize;
            let c = coeffs_of[p].next().unwrap_or_else(C::zero);
            pos[p] += 1;
            match keys_of[p].get(pos[p]) {
                Some(&key) => heap[0].0 = key,
                None => {
                    let last = heap.pop().unwrap_or((0, 0));
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
                out_e.extend_from_slice(&exps_of[p][i * w..(i + 1) * w]);
                out_c.push(acc);
            }
        }
        Poly {
            shape,
            exps: out_e,
            coeffs: out_c,
        }
    }

    /// The sum of many polynomials, added pairwise (balanced), which keeps the merges of similar
    /// sizes.
    fn sum_pairwise(mut polys: Vec<Poly<C>>) -> Poly<C> {
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
        if self.exp_bound() + rhs.exp_bound() > MAX_EXP {
            let (a, b) = (self.max_exponents(), rhs.max_exponents());
            let worst = (0..a.len().min(b.len()))
                .map(|v| a[v] + b[v])
                .max()
                .unwrap_or(0);
            if worst > MAX_EXP && !self.is_empty() && !rhs.is_empty() {
                return None;
            }
        }
        Some(self.mul_impl(rhs))
    }

    /// `self^e`, or `None` when an exponent of the power would exceed `u32::MAX` (where
    /// [`Ring::pow`] panics).
    pub fn checked_pow(&self, e: u32) -> Option<Self> {
        if e > 1 && self.max_exponent() as u64 * e as u64 > MAX_EXP {
            return None;
        }
        Some(self.pow_u64(e as u64))
    }

    /// `self^e` for a 64-bit exponent.
    fn pow_u64(&self, mut e: u64) -> Self {
        if e == 0 {
            return Poly::one();
        }
        if self.len() <= 1 {
            return self.pow_term(e);
        }
        let mut acc = Poly::one();
        let mut base = self.clone();
        loop {
            if e & 1 == 1 {
                acc = acc.mul_ref(&base);
            }
            e >>= 1;
            if e == 0 {
                return acc;
            }
            base = base.square_impl();
        }
    }

    /// `self^e` for zero or a single term.
    fn pow_term(&self, e: u64) -> Self {
        if self.is_empty() {
            return Poly::zero();
        }
        let c = pow_coeff(&self.coeffs[0], e);
        if c.is_zero() {
            return Poly::zero();
        }
        let need = self.exp_bound().saturating_mul(e);
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

    // -------------------------------------------------------------------------- arithmetic

    /// `self + rhs` (or `self - rhs` when `negate`), borrowing both.
    fn add_impl(&self, rhs: &Self, negate: bool) -> Self {
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
    fn add_owned(self, rhs: Self, negate: bool) -> Self {
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
    fn into_parts(self, to: Shape) -> (Vec<u64>, Vec<C>) {
        let exps = if to == self.shape {
            self.exps
        } else {
            repack(&self.exps, self.coeffs.len(), self.shape, to)
        };
        (exps, self.coeffs)
    }

    /// `self + rhs` (or `self - rhs` when `negate`), consuming `self` only.
    fn add_left_owned(self, rhs: &Self, negate: bool) -> Self {
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

    fn neg_impl(&self) -> Self {
        Poly {
            shape: self.shape,
            exps: self.exps.clone(),
            coeffs: self.coeffs.iter().map(Ring::neg_ref).collect(),
        }
    }

    fn neg_owned(mut self) -> Self {
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
    fn product_shape(&self, rhs: &Self) -> Shape {
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

    fn mul_impl(&self, rhs: &Self) -> Self {
        if self.is_empty() || rhs.is_empty() {
            return Poly::zero();
        }
        let shape = self.product_shape(rhs);
        let (ae, be) = (self.exps_in(shape), rhs.exps_in(shape));
        let w = shape.words;
        let (exps, coeffs) = if self.len() == 1 {
            mul_term(w, &be, &rhs.coeffs, &ae, &self.coeffs[0])
        } else if rhs.len() == 1 {
            mul_term(w, &ae, &self.coeffs, &be, &rhs.coeffs[0])
        } else {
            let cap = w * shape.per_word();
            let (ma, mb) = (
                max_exps(shape, &ae, self.len(), cap),
                max_exps(shape, &be, rhs.len(), cap),
            );
            let need: Vec<u64> = ma.iter().zip(&mb).map(|(x, y)| x + y).collect();
            let (small, large) = if self.len() <= rhs.len() {
                ((&ae[..], &self.coeffs[..]), (&be[..], &rhs.coeffs[..]))
            } else {
                ((&be[..], &rhs.coeffs[..]), (&ae[..], &self.coeffs[..]))
            };
            let products = (self.len() as u64).saturating_mul(rhs.len() as u64);
            let limit = DENSE_MAX_CELLS.min(products.saturating_mul(4));
            if let Some((cells, strides)) = dense_strides(&need, limit) {
                let fi = dense_indices(shape, small.0, small.1.len(), &strides);
                let gi = dense_indices(shape, large.0, large.1.len(), &strides);
                mul_dense(
                    w,
                    cells as usize,
                    (small.0, &fi, small.1),
                    (large.0, &gi, large.1),
                )
            } else {
                let (k, place) = key_layout(&need);
                let fk = make_keys(shape, small.0, small.1.len(), k, &place);
                let gk = make_keys(shape, large.0, large.1.len(), k, &place);
                let f = (small.0, &fk[..], small.1);
                let g = (large.0, &gk[..], large.1);
                if k == 1 {
                    mul_heap1(w, f, g)
                } else {
                    with_key_words!(k, mul_heap::<C>(k, w, f, g))
                }
            }
        };
        Poly {
            shape,
            exps,
            coeffs,
        }
    }

    fn square_impl(&self) -> Self {
        if self.len() <= 1 {
            return self.pow_term(2);
        }
        let shape = self.product_shape(self);
        let e = self.exps_in(shape);
        let cap = shape.words * shape.per_word();
        let need: Vec<u64> = max_exps(shape, &e, self.len(), cap)
            .iter()
            .map(|m| 2 * m)
            .collect();
        let n = self.len() as u64;
        let (exps, coeffs) = match dense_strides(&need, DENSE_MAX_CELLS.min(n * n * 4)) {
            Some((cells, strides)) => {
                let idx = dense_indices(shape, &e, self.len(), &strides);
                let f = (&e[..], &idx[..], &self.coeffs[..]);
                mul_dense(shape.words, cells as usize, f, f)
            }
            None => {
                let (k, place) = key_layout(&need);
                let keys = make_keys(shape, &e, self.len(), k, &place);
                let f = (&e[..], &keys[..], &self.coeffs[..]);
                with_key_words!(k, square_heap::<C>(k, shape.words, f))
            }
        };
        Poly {
            shape,
            exps,
            coeffs,
        }
    }

    // ------------------------------------------------------------------- unit-circle relations

    /// The normal form modulo the unit-circle relations `c^2 + s^2 - 1` of the pairs `(c, s)`:
    /// every `s^2` is rewritten as `1 - c^2`, so that no term keeps an `s` exponent above 1.
    ///
    /// This is the normal form with respect to any monomial order in which `s^2 > c^2` for every
    /// pair (in this crate's order: `s > c`, i.e. `s` declared after `c`); the relations of
    /// independent pairs always form a Gröbner basis, so an identity holds for all angles iff
    /// the normal form of its residual is zero. Needs no division: any coefficient ring.
    ///
    /// # Panics
    /// When a variable occurs in two pairs, or `c == s` in a pair.
    pub fn reduce_unit_circle(&self, pairs: &[(Var, Var)]) -> Poly<C> {
        let mut seen = std::collections::HashSet::new();
        for &(c, s) in pairs {
            assert!(
                c != s && seen.insert(c) && seen.insert(s),
                "reduce_unit_circle: the pairs (cos, sin) must use distinct variables"
            );
        }
        let pairs: Vec<(usize, usize)> = pairs
            .iter()
            .map(|&(c, s)| (c as usize, s as usize))
            .collect();
        // Nothing to do unless some term has s^2.
        let reducible = |m: &[u64], sh: Shape| pairs.iter().any(|&(_, s)| sh.get(m, s) >= 2);
        if !(0..self.len()).any(|i| reducible(self.mono(i), self.shape)) {
            return self.clone();
        }
        // Room for c and for exponents up to e_c + e_s.
        let nv = pairs.iter().map(|&(c, s)| c.max(s) + 1).max().unwrap_or(0);
        let need = self.exp_bound().saturating_mul(2);
        let bits = bits_for(need.min(MAX_EXP)).unwrap_or(64);
        let shape = self.widened_shape(bits, nv);
        let exps = self.exps_in(shape);
        let mono = |i: usize| &exps[i * shape.words..(i + 1) * shape.words];
        // (1 - c^2)^h = sum_k binom(h, k) (-1)^k c^(2k): signed Pascal rows in C.
        let hmax = (0..self.len())
            .flat_map(|i| pairs.iter().map(move |&(_, s)| shape.get(mono(i), s) / 2))
            .max()
            .unwrap_or(0) as usize;
        let mut rows: Vec<Vec<C>> = vec![vec![C::one()]];
        for h in 1..=hmax {
            let prev = &rows[h - 1];
            let row: Vec<C> = (0..=h)
                .map(|k| {
                    // signed: r[h][k] = r[h-1][k] - r[h-1][k-1]
                    let a = prev.get(k).cloned().unwrap_or_else(C::zero);
                    match k.checked_sub(1).and_then(|j| prev.get(j)) {
                        Some(b) => a - b,
                        None => a,
                    }
                })
                .collect();
            rows.push(row);
        }
        let mut out_e: Vec<u64> = Vec::with_capacity(exps.len() * 2);
        let mut out_c: Vec<C> = Vec::with_capacity(self.len() * 2);
        let mut base = vec![0u64; shape.words];
        let mut hs: Vec<(usize, usize, usize)> = Vec::new(); // (c, h, k)
        for i in 0..self.len() {
            let m = mono(i);
            base.copy_from_slice(m);
            hs.clear();
            for &(c, s) in &pairs {
                let e = shape.get(m, s);
                if e >= 2 {
                    shape.set(&mut base, s, e & 1);
                    hs.push((c, (e / 2) as usize, 0));
                }
            }
            if hs.is_empty() {
                out_e.extend_from_slice(m);
                out_c.push(self.coeffs[i].clone());
                continue;
            }
            // Enumerate k_j in 0..=h_j for every rewritten pair (odometer).
            loop {
                let start = out_e.len();
                out_e.extend_from_slice(&base);
                let mut coeff = self.coeffs[i].clone();
                for &(c, h, k) in &hs {
                    shape.add(&mut out_e[start..], c, 2 * k as u64);
                    coeff *= &rows[h][k];
                }
                out_c.push(coeff);
                let mut j = 0;
                while j < hs.len() {
                    if hs[j].2 < hs[j].1 {
                        hs[j].2 += 1;
                        break;
                    }
                    hs[j].2 = 0;
                    j += 1;
                }
                if j == hs.len() {
                    break;
                }
            }
        }
        Poly::from_unsorted(shape, out_e, out_c)
    }
}

/// `c^e` by binary powering.
fn pow_coeff<C: Ring>(c: &C, mut e: u64) -> C {
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
fn merge<C: Ring>(
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
fn merge_words<C: Ring, const W: usize>(
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
fn mul_term<C: Ring>(w: usize, ge: &[u64], gc: &[C], m: &[u64], c: &C) -> (Vec<u64>, Vec<C>) {
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
    (exps, coeffs)
}

/// A binary max-heap of stream indices, keyed by the monomials in `slots` (`w` words each).
struct Heap {
    h: Vec<u32>,
}

impl Heap {
    fn with_capacity(n: usize) -> Self {
        Heap {
            h: Vec::with_capacity(n),
        }
    }

    #[inline(always)]
    fn gt(slots: &[u64], w: usize, a: u32, b: u32) -> bool {
        let (a, b) = (a as usize, b as usize);
        cmp_mono(&slots[a * w..(a + 1) * w], &slots[b * w..(b + 1) * w]) == Ordering::Greater
    }

    #[inline]
    fn peek(&self) -> Option<u32> {
        self.h.first().copied()
    }

    #[inline(always)]
    fn push(&mut self, x: u32, slots: &[u64], w: usize) {
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

    #[inline(always)]
    fn pop(&mut self, slots: &[u64], w: usize) -> Option<u32> {
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

/// The largest exponent of every variable over `n` monomials (`cap` variables).
fn max_exps(shape: Shape, e: &[u64], n: usize, cap: usize) -> Vec<u64> {
    let w = shape.words;
    let mut m = vec![0u64; cap];
    for i in 0..n {
        shape.for_each(&e[i * w..(i + 1) * w], |v, x| m[v] = m[v].max(x));
    }
    m
}

/// Compact keys for the monomials of a product: every variable gets just the bits that its
/// largest exponent in the product needs (`need[v]`, a Kronecker substitution), packed from the
/// lowest variable up without crossing word boundaries, so that comparing keys as multi-word
/// integers (most significant word last) is still the monomial order and adding keys never
/// carries. When the operands have few low-degree variables (W1: 74 variables in 10 words) the
/// keys take one or two words, and the heap compares those instead of whole monomials.
///
/// Returns the number of key words and the place `(word, shift)` of every variable.
fn key_layout(need: &[u64]) -> (usize, Vec<(usize, u32)>) {
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
fn make_keys(shape: Shape, e: &[u64], n: usize, k: usize, place: &[(usize, u32)]) -> Vec<u64> {
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
fn push_sum(out: &mut Vec<u64>, a: &[u64], b: &[u64]) {
    out.extend(a.iter().zip(b).map(|(x, y)| x.wrapping_add(*y)));
}

/// Johnson's heap multiplication of two sorted term lists (`f` the shorter, both with at least
/// two terms), with Monagan–Pearce chained stream insertion: stream `i` is `f_i * g_j` for
/// increasing `j`, and stream `i + 1` enters the heap when stream `i` leaves its first term; the
/// heap thus holds at most one entry per stream and yields the products in decreasing order,
/// equal monomials are accumulated as they leave it, and the result is born sorted. The heap
/// orders the compact keys of [`key_layout`] (`k` words, `K` if non-zero); the full monomials
/// (`w` words) are formed once per output term.
fn mul_heap<C: Ring, const K: usize>(
    k: usize,
    w: usize,
    (fe, fk, fc): (&[u64], &[u64], &[C]),
    (ge, gk, gc): (&[u64], &[u64], &[C]),
) -> (Vec<u64>, Vec<C>) {
    let k = if K == 0 { k } else { K };
    let (nf, ng) = (fc.len(), gc.len());
    let mut slots = vec![0u64; nf * k];
    let mut js = vec![0usize; nf];
    let mut heap = Heap::with_capacity(nf);
    let cap = (nf * ng).min(4 * (nf + ng) + 1024);
    let mut out_e: Vec<u64> = Vec::with_capacity(cap * w);
    let mut out_c: Vec<C> = Vec::with_capacity(cap);
    let mut cur = vec![0u64; k];
    add_mono(&mut slots[0..k], &fk[0..k], &gk[0..k]);
    heap.push(0, &slots, k);

    // Moves stream i past its current term and (re)inserts what follows.
    let advance = |i: usize, slots: &mut Vec<u64>, js: &mut Vec<usize>, heap: &mut Heap| {
        let j = js[i];
        if j == 0 && i + 1 < nf {
            let n = i + 1;
            js[n] = 0;
            add_mono(
                &mut slots[n * k..(n + 1) * k],
                &fk[n * k..(n + 1) * k],
                &gk[0..k],
            );
            heap.push(n as u32, slots, k);
        }
        if j + 1 < ng {
            js[i] = j + 1;
            add_mono(
                &mut slots[i * k..(i + 1) * k],
                &fk[i * k..(i + 1) * k],
                &gk[(j + 1) * k..(j + 2) * k],
            );
            heap.push(i as u32, slots, k);
        }
    };

    while let Some(i) = heap.pop(&slots, k) {
        let i = i as usize;
        let j = js[i];
        cur.copy_from_slice(&slots[i * k..(i + 1) * k]);
        let mut acc = fc[i].mul_ref(&gc[j]);
        advance(i, &mut slots, &mut js, &mut heap);
        while let Some(top) = heap.peek() {
            let t = top as usize;
            if slots[t * k..(t + 1) * k] != cur[..] {
                break;
            }
            heap.pop(&slots, k);
            acc += fc[t].mul_ref(&gc[js[t]]);
            advance(t, &mut slots, &mut js, &mut heap);
        }
        if !acc.is_zero() {
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &ge[j * w..(j + 1) * w]);
            out_c.push(acc);
        }
    }
    (out_e, out_c)
}

/// [`mul_heap`] for one-word keys, the common case: the heap holds `(key, stream)` pairs, so
/// comparisons touch no other memory, and a stream that continues replaces the root in place
/// (one sift instead of a pop and a push).
fn mul_heap1<C: Ring>(
    w: usize,
    (fe, fk, fc): (&[u64], &[u64], &[C]),
    (ge, gk, gc): (&[u64], &[u64], &[C]),
) -> (Vec<u64>, Vec<C>) {
    let (nf, ng) = (fc.len(), gc.len());
    let mut js = vec![0u32; nf];
    let mut heap: Vec<(u64, u32)> = Vec::with_capacity(nf);
    let cap = (nf * ng).min(4 * (nf + ng) + 1024);
    let mut out_e: Vec<u64> = Vec::with_capacity(cap * w);
    let mut out_c: Vec<C> = Vec::with_capacity(cap);
    heap.push((fk[0].wrapping_add(gk[0]), 0));

    // Takes the root's product and moves its stream on; returns the product.
    let step = |heap: &mut Vec<(u64, u32)>, js: &mut Vec<u32>| -> C {
        let (_, s) = heap[0];
        let i = s as usize;
        let j = js[i] as usize;
        let p = fc[i].mul_ref(&gc[j]);
        if j + 1 < ng {
            js[i] = (j + 1) as u32;
            heap[0] = (fk[i].wrapping_add(gk[j + 1]), s);
            sift_down1(heap);
        } else {
            let last = heap.pop().unwrap_or((0, 0));
            if !heap.is_empty() {
                heap[0] = last;
                sift_down1(heap);
            }
        }
        if j == 0 && i + 1 < nf {
            push1(heap, (fk[i + 1].wrapping_add(gk[0]), (i + 1) as u32));
        }
        p
    };

    while let Some(&(key, s)) = heap.first() {
        let (i, j) = (s as usize, js[s as usize] as usize);
        let mut acc = step(&mut heap, &mut js);
        while heap.first().is_some_and(|t| t.0 == key) {
            acc += step(&mut heap, &mut js);
        }
        if !acc.is_zero() {
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &ge[j * w..(j + 1) * w]);
            out_c.push(acc);
        }
    }
    (out_e, out_c)
}

/// Restores the max-heap order below the root.
#[inline(always)]
fn sift_down1(h: &mut [(u64, u32)]) {
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
fn push1(h: &mut Vec<(u64, u32)>, x: (u64, u32)) {
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
const DENSE_MAX_CELLS: u64 = 1 << 22;

/// Mixed-radix indices for a dense product: variable `v` gets radix `need[v] + 1`, the lowest
/// variable the smallest stride, so indices order like the monomials. `None` when the box
/// (the product of the radices) exceeds `limit`.
fn dense_strides(need: &[u64], limit: u64) -> Option<(u64, Vec<u64>)> {
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
fn dense_indices(shape: Shape, e: &[u64], n: usize, strides: &[u64]) -> Vec<u64> {
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
fn mul_dense<C: Ring>(
    w: usize,
    cells: usize,
    (fe, fi, fc): (&[u64], &[u64], &[C]),
    (ge, gi, gc): (&[u64], &[u64], &[C]),
) -> (Vec<u64>, Vec<C>) {
    let mut cell = vec![0u32; cells];
    // (index, i, j, coefficient) of every distinct product monomial.
    let mut touched: Vec<(u64, u32, u32, C)> = Vec::with_capacity((fc.len() + gc.len()) * 4);
    for (i, (a, ia)) in fc.iter().zip(fi).enumerate() {
        for (j, (b, ib)) in gc.iter().zip(gi).enumerate() {
            let idx = ia + ib;
            let p = a.mul_ref(b);
            match cell[idx as usize] {
                0 => {
                    touched.push((idx, i as u32, j as u32, p));
                    cell[idx as usize] = touched.len() as u32;
                }
                t => touched[t as usize - 1].3 += p,
            }
        }
    }
    touched.sort_unstable_by_key(|x| std::cmp::Reverse(x.0));
    let mut out_e = Vec::with_capacity(touched.len() * w);
    let mut out_c = Vec::with_capacity(touched.len());
    for (_, i, j, c) in touched {
        if !c.is_zero() {
            let (i, j) = (i as usize, j as usize);
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &ge[j * w..(j + 1) * w]);
            out_c.push(c);
        }
    }
    (out_e, out_c)
}

/// Squaring with the heap over the pairs `i <= j` (at least two terms): stream `i` is
/// `f_i * f_j` for `j = i, i+1, ...`; stream `i + 1` enters when `(i, i + 1)` leaves. Products
/// with `i < j` count twice. Keys as in [`mul_heap`].
fn square_heap<C: Ring, const K: usize>(
    k: usize,
    w: usize,
    (fe, fk, fc): (&[u64], &[u64], &[C]),
) -> (Vec<u64>, Vec<C>) {
    let k = if K == 0 { k } else { K };
    let n = fc.len();
    let mut slots = vec![0u64; n * k];
    let mut js = vec![0usize; n];
    let mut heap = Heap::with_capacity(n);
    let cap = (n * n).min(8 * n + 1024);
    let mut out_e: Vec<u64> = Vec::with_capacity(cap * w);
    let mut out_c: Vec<C> = Vec::with_capacity(cap);
    let mut cur = vec![0u64; k];
    add_mono(&mut slots[0..k], &fk[0..k], &fk[0..k]);
    heap.push(0, &slots, k);

    let advance = |i: usize, slots: &mut Vec<u64>, js: &mut Vec<usize>, heap: &mut Heap| {
        let j = js[i];
        if j == i + 1 && i + 1 < n {
            let m = i + 1;
            js[m] = m;
            add_mono(
                &mut slots[m * k..(m + 1) * k],
                &fk[m * k..(m + 1) * k],
                &fk[m * k..(m + 1) * k],
            );
            heap.push(m as u32, slots, k);
        }
        if j + 1 < n {
            js[i] = j + 1;
            add_mono(
                &mut slots[i * k..(i + 1) * k],
                &fk[i * k..(i + 1) * k],
                &fk[(j + 1) * k..(j + 2) * k],
            );
            heap.push(i as u32, slots, k);
        }
    };
    // Diagonal products go to `diag`, off-diagonal ones (to be doubled) to `off`.
    let take = |i: usize, j: usize, diag: &mut Option<C>, off: &mut Option<C>| {
        let (slot, p) = if i == j {
            (diag, fc[i].square())
        } else {
            (off, fc[i].mul_ref(&fc[j]))
        };
        match slot {
            Some(a) => *a += p,
            None => *slot = Some(p),
        }
    };

    while let Some(i) = heap.pop(&slots, k) {
        let i = i as usize;
        let j = js[i];
        cur.copy_from_slice(&slots[i * k..(i + 1) * k]);
        let mut diag: Option<C> = None;
        let mut off: Option<C> = None;
        take(i, j, &mut diag, &mut off);
        advance(i, &mut slots, &mut js, &mut heap);
        while let Some(top) = heap.peek() {
            let t = top as usize;
            if slots[t * k..(t + 1) * k] != cur[..] {
                break;
            }
            heap.pop(&slots, k);
            take(t, js[t], &mut diag, &mut off);
            advance(t, &mut slots, &mut js, &mut heap);
        }
        let acc = match (diag, off) {
            (Some(d), Some(o)) => d + o.add_ref(&o),
            (Some(d), None) => d,
            (None, Some(o)) => o.add_ref(&o),
            (None, None) => continue,
        };
        if !acc.is_zero() {
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &fe[j * w..(j + 1) * w]);
            out_c.push(acc);
        }
    }
    (out_e, out_c)
}

// ------------------------------------------------------------------------------ normal forms

/// The relation `c^2 + s^2 - 1` of an angle given by its cosine `c` and sine `s`.
///
/// In this crate's order its leading monomial is the square of the higher variable: declare the
/// cosine first (`c < s`) and reduction rewrites `s^2 -> 1 - c^2`. Relations of independent
/// pairs form a Gröbner basis; [`Poly::reduce`] recognises them and uses the closed form of
/// [`Poly::reduce_unit_circle`].
pub fn unit_circle_relation<C: Ring>(c: Var, s: Var) -> Poly<C> {
    Poly::from_terms([
        (vec![(c, 2)], C::one()),
        (vec![(s, 2)], C::one()),
        (vec![], -C::one()),
    ])
}

/// Exponents overflowed the current field width during a division: retry wider.
struct Overflow;

/// A rewriting rule `lm -> tail` from a monic relation `lm - tail`.
struct Rule<C> {
    lm: Vec<u64>,
    tail_e: Vec<u64>,
    tail_c: Vec<C>,
}

/// A monomial key ordered by the monomial order (for `BinaryHeap`).
#[derive(PartialEq, Eq)]
struct Key(Box<[u64]>);

impl Ord for Key {
    fn cmp(&self, other: &Self) -> Ordering {
        cmp_mono(&self.0, &other.0)
    }
}

impl PartialOrd for Key {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<C: Field> Poly<C> {
    /// The polynomial divided by its leading coefficient (zero stays zero).
    pub fn make_monic(&self) -> Poly<C> {
        match self.coeffs.first() {
            None => Poly::zero(),
            Some(lc) if lc.is_one() => self.clone(),
            Some(lc) => match lc.inv() {
                Ok(inv) => self.scale(&inv),
                // A field has no non-zero zero divisors; keep the polynomial as it is.
                Err(_) => self.clone(),
            },
        }
    }

    /// The remainder of `self` on multivariate division by `relations`, in the monomial order of
    /// the module documentation (lex, higher variable index larger): no term of the result is
    /// divisible by the leading monomial of a relation. At each step the first relation (in the
    /// given order) whose leading monomial divides the current term is used.
    ///
    /// Against a Gröbner basis (from [`groebner`]) the remainder is the **canonical normal form**
    /// of `self` modulo the ideal of the relations: a polynomial identity holds on the variety
    /// of the relations (more exactly, modulo their ideal) iff the normal form of its residual is
    /// zero. Against other relation sets it is only *a* remainder. Independent unit-circle
    /// relations ([`unit_circle_relation`]) are recognised and reduced in closed form.
    ///
    /// # Panics
    /// When an exponent would exceed `u32::MAX`.
    pub fn reduce(&self, relations: &[Poly<C>]) -> Poly<C> {
        let rels: Vec<&Poly<C>> = relations.iter().filter(|g| !g.is_empty()).collect();
        if rels.is_empty() || self.is_empty() {
            return self.clone();
        }
        if rels.iter().any(|g| g.is_constant()) {
            return Poly::zero();
        }
        if let Some(pairs) = unit_circle_pairs(&rels) {
            return self.reduce_unit_circle(&pairs);
        }
        let mut bits = rels
            .iter()
            .map(|g| g.shape.bits)
            .fold(self.shape.bits, u32::max);
        loop {
            let nv = rels
                .iter()
                .map(|g| g.nvars_used())
                .fold(self.nvars_used(), usize::max);
            let shape = Shape {
                bits,
                words: Shape::words_for(bits, nv),
            };
            match divide(self, &rels, shape) {
                Ok(r) => return r,
                Err(Overflow) => {
                    bits *= 2;
                    assert!(bits <= 64, "exponent overflow: above u32::MAX");
                }
            }
        }
    }
}

/// The pairs `(c, s)` (with `s` the leading variable) if every relation is a multiple of
/// `c^2 + s^2 - 1` and the pairs are independent.
fn unit_circle_pairs<C: Ring>(rels: &[&Poly<C>]) -> Option<Vec<(Var, Var)>> {
    let mut pairs = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for g in rels {
        if g.len() != 3 {
            return None;
        }
        let t: Vec<Vec<(Var, u32)>> = g.terms().map(|(m, _)| m.exponents()).collect();
        let (s, c) = match (&t[0][..], &t[1][..], &t[2][..]) {
            ([(s, 2)], [(c, 2)], []) => (*s, *c),
            _ => return None,
        };
        let k = &g.coeffs;
        if k[0] != k[1] || k[2] != k[0].neg_ref() || !seen.insert(s) || !seen.insert(c) {
            return None;
        }
        pairs.push((c, s));
    }
    Some(pairs)
}

/// Division with a heap of pending monomials (all in `shape`): every monomial leaves the heap
/// once, with its final coefficient, because rewriting only produces smaller monomials.
fn divide<C: Field>(f: &Poly<C>, rels: &[&Poly<C>], shape: Shape) -> Result<Poly<C>, Overflow> {
    let w = shape.words;
    let guard = shape.guard();
    let rules: Vec<Rule<C>> = rels
        .iter()
        .map(|g| {
            let g = g.make_monic();
            let e = g.exps_in(shape).into_owned();
            Rule {
                lm: e[..w].to_vec(),
                tail_e: e[w..].to_vec(),
                tail_c: g.coeffs[1..].iter().map(Ring::neg_ref).collect(),
            }
        })
        .collect();
    let fe = f.exps_in(shape);
    let mut pending: HashMap<Box<[u64]>, C> = HashMap::with_capacity(f.len() * 2);
    let mut heap: BinaryHeap<Key> = BinaryHeap::with_capacity(f.len() * 2);
    for (i, c) in f.coeffs.iter().enumerate() {
        let m: Box<[u64]> = fe[i * w..(i + 1) * w].into();
        pending.insert(m.clone(), c.clone());
        heap.push(Key(m));
    }
    let mut out_e = Vec::new();
    let mut out_c = Vec::new();
    let mut u = vec![0u64; w];
    let mut nm = vec![0u64; w];
    while let Some(Key(m)) = heap.pop() {
        let Some(c) = pending.remove(&m) else {
            continue;
        };
        if c.is_zero() {
            continue;
        }
        match rules.iter().find(|r| divides(&r.lm, &m, guard)) {
            None => {
                out_e.extend_from_slice(&m);
                out_c.push(c);
            }
            Some(r) => {
                for k in 0..w {
                    u[k] = m[k] - r.lm[k];
                }
                for (t, d) in r.tail_c.iter().enumerate() {
                    add_mono(&mut nm, &u, &r.tail_e[t * w..(t + 1) * w]);
                    if nm.iter().any(|x| x & guard != 0) {
                        return Err(Overflow);
                    }
                    let v = c.mul_ref(d);
                    match pending.get_mut(&nm[..]) {
                        Some(acc) => *acc += v,
                        None => {
                            let key: Box<[u64]> = nm.as_slice().into();
                            pending.insert(key.clone(), v);
                            heap.push(Key(key));
                        }
                    }
                }
            }
        }
    }
    Ok(Poly {
        shape,
        exps: out_e,
        coeffs: out_c,
    })
}

/// The least common multiple of two monomials (exponent lists).
fn lcm_exponents(a: &[(Var, u32)], b: &[(Var, u32)]) -> Vec<(Var, u32)> {
    let mut m: std::collections::BTreeMap<Var, u32> = a.iter().copied().collect();
    for &(v, e) in b {
        let x = m.entry(v).or_insert(0);
        *x = (*x).max(e);
    }
    m.into_iter().collect()
}

/// `num / den` for monomials (exponent lists) with `den | num`.
fn quotient_exponents(num: &[(Var, u32)], den: &[(Var, u32)]) -> Vec<(Var, u32)> {
    let d: HashMap<Var, u32> = den.iter().copied().collect();
    num.iter()
        .map(|&(v, e)| (v, e - d.get(&v).copied().unwrap_or(0)))
        .filter(|&(_, e)| e > 0)
        .collect()
}

/// Whether monomial `d` divides `m` (exponent lists).
fn divides_exponents(d: &[(Var, u32)], m: &[(Var, u32)]) -> bool {
    let mm: HashMap<Var, u32> = m.iter().copied().collect();
    d.iter().all(|(v, e)| mm.get(v).is_some_and(|x| x >= e))
}

/// The reduced Gröbner basis of the ideal generated by `relations`, in the monomial order of the
/// module documentation (lex, higher variable index larger), by Buchberger's algorithm.
///
/// The result is monic, inter-reduced and sorted by increasing leading monomial; it is unique
/// for the ideal, and [`Poly::reduce`] against it is a canonical normal form. `[1]` means the
/// relations are inconsistent; the empty list means they are all zero. Meant for a handful of
/// small relations (lex bases can grow quickly).
///
/// # Panics
/// When an exponent would exceed `u32::MAX`.
pub fn groebner<C: Field>(relations: &[Poly<C>]) -> Vec<Poly<C>> {
    let mut g: Vec<Poly<C>> = relations
        .iter()
        .filter(|p| !p.is_empty())
        .map(Poly::make_monic)
        .collect();
    if g.iter().any(Poly::is_constant) {
        return vec![Poly::one()];
    }
    let lm = |p: &Poly<C>| {
        p.leading_term()
            .map(|(m, _)| m.exponents())
            .unwrap_or_default()
    };
    let mut lms: Vec<Vec<(Var, u32)>> = g.iter().map(lm).collect();
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    for j in 0..g.len() {
        for i in 0..j {
            pairs.push((i, j));
        }
    }
    while !pairs.is_empty() {
        // Normal strategy: the pair with the smallest lcm (total degree, then the order).
        let keyed: Vec<(u64, Poly<C>)> = pairs
            .iter()
            .map(|&(i, j)| {
                let l = lcm_exponents(&lms[i], &lms[j]);
                let deg = l.iter().map(|&(_, e)| e as u64).sum();
                (deg, Poly::<C>::monomial(C::one(), &l))
            })
            .collect();
        let best = (0..pairs.len())
            .min_by(|&a, &b| {
                let ((da, ma), (db, mb)) = (&keyed[a], &keyed[b]);
                da.cmp(db).then_with(|| {
                    let s = ma.common_shape(mb);
                    cmp_mono(&ma.exps_in(s), &mb.exps_in(s))
                })
            })
            .unwrap_or(0);
        let (i, j) = pairs.swap_remove(best);
        let l = lcm_exponents(&lms[i], &lms[j]);
        // Criterion 1: coprime leading monomials reduce to zero.
        let deg_l: u32 = l.iter().map(|p| p.1).sum();
        let deg_sum: u32 = lms[i].iter().chain(&lms[j]).map(|p| p.1).sum();
        if deg_l == deg_sum {
            continue;
        }
        // Criterion 2 (chain): some g_k with lm(g_k) | lcm whose pairs with i and j are done.
        let chain = (0..g.len()).any(|k| {
            k != i
                && k != j
                && divides_exponents(&lms[k], &l)
                && !pairs.contains(&(i.min(k), i.max(k)))
                && !pairs.contains(&(j.min(k), j.max(k)))
        });
        if chain {
            continue;
        }
        let si = Poly::monomial(C::one(), &quotient_exponents(&l, &lms[i]));
        let sj = Poly::monomial(C::one(), &quotient_exponents(&l, &lms[j]));
        let s = si * &g[i] - sj * &g[j];
        let r = s.reduce(&g).make_monic();
        if r.is_empty() {
            continue;
        }
        if r.is_constant() {
            return vec![Poly::one()];
        }
        let k = g.len();
        lms.push(lm(&r));
        g.push(r);
        for i in 0..k {
            pairs.push((i, k));
        }
    }
    // Minimal basis: drop elements whose leading monomial another one divides (of equal ones,
    // keep the first).
    let mut keep: Vec<usize> = Vec::new();
    for i in 0..g.len() {
        let redundant = (0..g.len())
            .any(|j| j != i && divides_exponents(&lms[j], &lms[i]) && (lms[j] != lms[i] || j < i));
        if !redundant {
            keep.push(i);
        }
    }
    let mut basis: Vec<Poly<C>> = keep.iter().map(|&i| g[i].clone()).collect();
    // Inter-reduce: every element reduced by the others (leading terms stay).
    for i in 0..basis.len() {
        let others: Vec<Poly<C>> = basis
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, p)| p.clone())
            .collect();
        basis[i] = basis[i].reduce(&others).make_monic();
    }
    basis.sort_by(|a, b| {
        let (ma, mb) = (a.leading_monomial_poly(), b.leading_monomial_poly());
        let s = ma.common_shape(&mb);
        cmp_mono(&ma.exps_in(s), &mb.exps_in(s))
    });
    basis
}

impl<C: Ring> Poly<C> {
    /// The leading monomial as a polynomial with coefficient one (zero for zero).
    fn leading_monomial_poly(&self) -> Poly<C> {
        match self.leading_term() {
            None => Poly::zero(),
            Some(_) => Poly {
                shape: self.shape,
                exps: self.mono(0).to_vec(),
                coeffs: vec![C::one()],
            },
        }
    }
}

// ------------------------------------------------------------------------------ traits

impl<C: Ring> PartialEq for Poly<C> {
    fn eq(&self, other: &Self) -> bool {
        if self.len() != other.len() || self.coeffs != other.coeffs {
            return false;
        }
        if self.shape == other.shape {
            return self.exps == other.exps;
        }
        let s = self.common_shape(other);
        self.exps_in(s) == other.exps_in(s)
    }
}

impl<C: Ring + Eq> Eq for Poly<C> {}

impl<C: Ring> Default for Poly<C> {
    fn default() -> Self {
        Poly::zero()
    }
}

impl<C: Ring> From<C> for Poly<C> {
    fn from(c: C) -> Self {
        Poly::constant(c)
    }
}

impl<C: Ring> Ring for Poly<C> {
    fn zero() -> Self {
        Poly::zero()
    }
    fn one() -> Self {
        Poly::constant(C::one())
    }
    fn from_i64(n: i64) -> Self {
        Poly::constant(C::from_i64(n))
    }
    fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }
    fn is_one(&self) -> bool {
        self.is_constant() && self.coeffs.first().is_some_and(Ring::is_one)
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs, false)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs, true)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(rhs)
    }
    fn neg_ref(&self) -> Self {
        self.neg_impl()
    }
    fn square(&self) -> Self {
        self.square_impl()
    }
    fn pow(&self, e: u32) -> Self {
        self.pow_u64(e as u64)
    }
    fn scale_i64(&self, n: i64) -> Self {
        self.scale(&C::from_i64(n))
    }
}

impl<C: Ring> Neg for Poly<C> {
    type Output = Poly<C>;
    fn neg(self) -> Poly<C> {
        self.neg_owned()
    }
}

impl<C: Ring> Neg for &Poly<C> {
    type Output = Poly<C>;
    fn neg(self) -> Poly<C> {
        self.neg_impl()
    }
}

macro_rules! poly_binop {
    ($tr:ident, $m:ident, $atr:ident, $am:ident, |$a:ident, $b:ident|
        owned: $owned:expr, left_owned: $left:expr, borrowed: $borrowed:expr) => {
        impl<C: Ring> $tr<Poly<C>> for Poly<C> {
            type Output = Poly<C>;
            fn $m(self, rhs: Poly<C>) -> Poly<C> {
                let ($a, $b) = (self, rhs);
                $owned
            }
        }
        impl<C: Ring> $tr<&Poly<C>> for Poly<C> {
            type Output = Poly<C>;
            fn $m(self, rhs: &Poly<C>) -> Poly<C> {
                let ($a, $b) = (self, rhs);
                $left
            }
        }
        impl<C: Ring> $tr<&Poly<C>> for &Poly<C> {
            type Output = Poly<C>;
            fn $m(self, rhs: &Poly<C>) -> Poly<C> {
                let ($a, $b) = (self, rhs);
                $borrowed
            }
        }
        impl<C: Ring> $tr<Poly<C>> for &Poly<C> {
            type Output = Poly<C>;
            fn $m(self, rhs: Poly<C>) -> Poly<C> {
                let ($a, $b) = (self, &rhs);
                $borrowed
            }
        }
        impl<C: Ring> $atr<Poly<C>> for Poly<C> {
            fn $am(&mut self, rhs: Poly<C>) {
                let lhs = std::mem::take(self);
                *self = $tr::$m(lhs, rhs);
            }
        }
        impl<C: Ring> $atr<&Poly<C>> for Poly<C> {
            fn $am(&mut self, rhs: &Poly<C>) {
                let lhs = std::mem::take(self);
                *self = $tr::$m(lhs, rhs);
            }
        }
    };
}

poly_binop!(Add, add, AddAssign, add_assign, |a, b|
    owned: a.add_owned(b, false), left_owned: a.add_left_owned(b, false), borrowed: a.add_impl(b, false));
poly_binop!(Sub, sub, SubAssign, sub_assign, |a, b|
    owned: a.add_owned(b, true), left_owned: a.add_left_owned(b, true), borrowed: a.add_impl(b, true));
poly_binop!(Mul, mul, MulAssign, mul_assign, |a, b|
    owned: a.mul_impl(&b), left_owned: a.mul_impl(b), borrowed: a.mul_impl(b));

// ------------------------------------------------------------------------------ printing

/// The name printed for a variable that has none in the table.
fn fallback_name(v: usize) -> String {
    format!("_x{v}")
}

/// Whether a printed coefficient needs parentheses as a factor (it has a top-level `+` or `-`
/// after its first character).
fn needs_parens(s: &str) -> bool {
    let mut depth = 0i32;
    for (i, ch) in s.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            '+' | '-' if depth == 0 && i > 0 => return true,
            _ => {}
        }
    }
    false
}

/// Writes a polynomial in the expression syntax of [`crate::expr`], with coefficients printed by
/// `coeff` and variables named by `name`.
fn write_poly<C>(
    p: &Poly<C>,
    f: &mut fmt::Formatter<'_>,
    coeff: impl Fn(&C) -> String,
    name: impl Fn(usize) -> String,
) -> fmt::Result {
    if p.is_empty() {
        return f.write_str("0");
    }
    for i in 0..p.len() {
        let s = coeff(&p.coeffs[i]);
        let (negative, mag) = match s.strip_prefix('-') {
            Some(rest) if !needs_parens(rest) => (true, rest.to_string()),
            _ => (false, s),
        };
        let mag = if needs_parens(&mag) {
            format!("({mag})")
        } else {
            mag
        };
        match (i, negative) {
            (0, true) => f.write_str("-")?,
            (0, false) => {}
            (_, true) => f.write_str(" - ")?,
            (_, false) => f.write_str(" + ")?,
        }
        let mut factors: Vec<String> = Vec::new();
        p.shape.for_each(p.mono(i), |v, e| {
            factors.push(if e == 1 {
                name(v)
            } else {
                format!("{}^{e}", name(v))
            })
        });
        if factors.is_empty() {
            f.write_str(&mag)?;
        } else {
            if mag != "1" {
                write!(f, "{mag}*")?;
            }
            f.write_str(&factors.join("*"))?;
        }
    }
    Ok(())
}

/// A polynomial with its variable names, for printing ([`Poly::display`]).
pub struct PolyDisplay<'a, C> {
    poly: &'a Poly<C>,
    vars: &'a Vars,
}

impl<C: Ring + fmt::Display> fmt::Display for PolyDisplay<'_, C> {
    /// The expression syntax of [`crate::expr`]: terms by decreasing monomial, e.g.
    /// `s^2 + c^2 - 1` or `3/4*x^2*y - x + 1/2`; it parses back to the same polynomial.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_poly(
            self.poly,
            f,
            |c| c.to_string(),
            |v| {
                self.vars
                    .name(v as Var)
                    .map_or_else(|| fallback_name(v), str::to_string)
            },
        )
    }
}

impl<C> Poly<C> {
    /// The polynomial printed with the names of `vars` (variables without a name print as
    /// `_x<index>`). The output parses back ([`crate::expr::parse_poly`]) to the same polynomial
    /// when the coefficients print in the expression syntax (as [`crate::Rational`] does).
    pub fn display<'a>(&'a self, vars: &'a Vars) -> PolyDisplay<'a, C> {
        PolyDisplay { poly: self, vars }
    }
}

impl<C: fmt::Debug> fmt::Debug for Poly<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_poly(self, f, |c| format!("{c:?}"), fallback_name)
    }
}

// ------------------------------------------------------------------------------ tests

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;

    type P = Poly<Rational>;

    fn q(n: i64) -> Rational {
        Rational::from_integer(n)
    }

    fn x(i: Var) -> P {
        P::var(i)
    }

    #[test]
    fn constants_need_no_variables() {
        assert!(P::zero().is_zero());
        assert_eq!(P::one().len(), 1);
        assert_eq!(P::from_i64(0), P::zero());
        assert_eq!(P::from_i64(3) * P::from_i64(4), P::from_i64(12));
        assert!(P::one().is_one());
        assert!(P::from_i64(-2).is_constant());
    }

    #[test]
    fn order_is_lex_with_higher_index_larger() {
        let p = x(0).pow(5) + x(1);
        assert_eq!(p.leading_term().unwrap().0.exponents(), vec![(1, 1)]);
        let p = x(0) * x(2) + x(1) * x(1) * x(0);
        assert_eq!(
            p.leading_term().unwrap().0.exponents(),
            vec![(0, 1), (2, 1)]
        );
        assert!(p.is_canonical());
    }

    #[test]
    fn binomial_expansion() {
        let p = (x(0) + x(1)).pow(5);
        assert_eq!(p.len(), 6);
        assert_eq!(p.coefficient(&[(0, 2), (1, 3)]), q(10));
        assert_eq!(p.coefficient(&[(0, 7)]), q(0));
        assert!(p.is_canonical());
        let sq = (x(0) - x(1) + P::one()).square();
        assert_eq!(sq, (x(0) - x(1) + P::one()) * (x(0) - x(1) + P::one()));
    }

    #[test]
    fn field_width_grows_on_demand() {
        let p = (x(0) + P::one()).pow(100);
        assert_eq!(p.degree_in(0), 100);
        let r = p.square();
        assert_eq!(r.degree_in(0), 200);
        assert!(r.is_canonical());
        assert_eq!(r.shape.bits, 16);
        let big = x(3).pow(70_000) * x(3).pow(70_000);
        assert_eq!(big.degree_in(3), 140_000);
        assert!(big.is_canonical());
        let huge = x(1).pow(u32::MAX / 2) * x(1).pow(u32::MAX / 2);
        assert_eq!(huge.degree_in(1), u32::MAX - 1);
        // Mixed widths add up correctly.
        let s = big.clone() + x(3) - big;
        assert_eq!(s, x(3));
    }

    #[test]
    fn many_variables_span_words() {
        let p: P = (0..40).map(x).fold(P::zero(), |a, b| a + b);
        let sq = p.square();
        assert_eq!(sq.len(), 40 * 41 / 2);
        assert_eq!(sq.coefficient(&[(3, 1), (39, 1)]), q(2));
        assert_eq!(sq.coefficient(&[(17, 2)]), q(1));
        assert_eq!(sq.variables().len(), 40);
        assert_eq!(sq.total_degree(), 2);
        assert!(sq.is_canonical());
    }

    /// The product by all pairwise term products, sorted and combined by `from_terms`.
    fn naive_mul(a: &P, b: &P) -> P {
        let mut terms = Vec::new();
        for (ma, ca) in a.terms() {
            for (mb, cb) in b.terms() {
                let mut m = ma.exponents();
                m.extend(mb.exponents());
                terms.push((m, ca.mul_ref(cb)));
            }
        }
        P::from_terms(terms)
    }

    /// A pseudo-random sparse polynomial: `n` terms over `nvars` variables, `per` variables per
    /// term with exponents below `emax`.
    fn sparse(seed: u64, n: usize, nvars: u32, per: usize, emax: u32) -> P {
        let mut st = seed;
        let mut next = move || {
            st = st
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (st >> 33) as u32
        };
        let terms: Vec<(Vec<(Var, u32)>, Rational)> = (0..n)
            .map(|_| {
                let m = (0..per).map(|_| (next() % nvars, next() % emax)).collect();
                (m, q(next() as i64 % 19 - 9))
            })
            .collect();
        P::from_terms(terms)
    }

    #[test]
    fn every_multiplication_kernel_agrees_with_the_naive_product() {
        let dense = (x(0) + x(1) + P::from_i64(2)).pow(5);
        let cases = [
            // Dense box.
            (dense.clone(), (x(0) - x(1) + P::one()).pow(4)),
            // Sparse, one-word keys.
            (sparse(1, 30, 40, 3, 2), sparse(2, 25, 40, 3, 2)),
            // Two-word keys.
            (sparse(3, 30, 40, 4, 4), sparse(4, 30, 40, 4, 4)),
            // Many key words (run-time width).
            (sparse(5, 20, 60, 8, 60), sparse(6, 20, 60, 8, 60)),
            // 16-bit fields.
            (sparse(7, 10, 9, 3, 300), sparse(8, 12, 9, 3, 300)),
        ];
        for (a, b) in &cases {
            let fast = a * b;
            assert!(fast.is_canonical());
            assert_eq!(fast, naive_mul(a, b));
            assert_eq!(a.square(), naive_mul(a, a));
            assert_eq!(a.square(), a * a);
        }
    }

    #[test]
    fn large_sums_agree_with_repeated_addition() {
        for (nvars, per, emax) in [(40, 3, 2), (60, 8, 60)] {
            let parts: Vec<P> = (0..7).map(|i| sparse(i, 80, nvars, per, emax)).collect();
            let folded = parts.iter().fold(P::zero(), |a, b| a + b);
            let mut with_cancellation = parts.clone();
            with_cancellation.push(-parts[3].clone());
            let s = P::sum(parts);
            assert!(s.is_canonical());
            assert_eq!(s, folded);
            let c = P::sum(with_cancellation);
            assert!(c.is_canonical());
            assert_eq!(c, &folded - &sparse(3, 80, nvars, per, emax));
        }
    }

    #[test]
    fn unit_circle_reduction() {
        // c = x0, s = x1: s^2 -> 1 - c^2.
        let (c, s, t) = (x(0), x(1), x(2));
        let rel = unit_circle_relation::<Rational>(0, 1);
        let f = c.square() * t.pow(3) + s.square() * t.pow(3) - t.clone();
        assert_eq!(f.reduce(std::slice::from_ref(&rel)), t.pow(3) - t);
        let g = s.pow(5);
        let want = s.clone() * (P::one() - c.square()).pow(2);
        assert_eq!(g.reduce_unit_circle(&[(0, 1)]), want);
        // The general division agrees with the closed form.
        let h = s.pow(4) * c.clone() + s.pow(3) + P::from_i64(2);
        let shape = h.widened_shape(8, 2);
        let by_division = divide(&h, &[&rel], shape).ok().unwrap();
        assert_eq!(by_division, h.reduce(&[rel]));
    }

    #[test]
    fn small_groebner_by_hand() {
        // x = x1 > y = x0. <x^2 - y, x y - 1> has the reduced lex basis {y^3 - 1, x - y^2}.
        let (y, xx) = (x(0), x(1));
        let g = groebner(&[xx.square() - y.clone(), xx.clone() * &y - P::one()]);
        assert_eq!(g, vec![y.pow(3) - P::one(), xx.clone() - y.square()]);
        // Normal forms modulo the basis.
        assert_eq!(xx.pow(3).reduce(&g), P::one());
        assert!((xx.square() - y.clone()).reduce(&g).is_zero());
        assert_eq!(
            groebner(&[xx.clone(), P::one() + xx.clone()]),
            vec![P::one()]
        );
    }

    #[test]
    fn substitute_and_eval() {
        let p = x(0).square() * x(1) + x(1) - P::from_i64(3);
        let r = p.substitute(0, &(x(1) + P::one()));
        assert_eq!(r, (x(1) + P::one()).square() * x(1) + x(1) - P::from_i64(3));
        let v = p.eval(&[q(2), q(5)], Clone::clone);
        assert_eq!(v, q(22));
    }

    #[test]
    fn printing() {
        let vars = Vars::from_names(["c", "s", "x"]);
        let p = unit_circle_relation::<Rational>(0, 1);
        assert_eq!(p.display(&vars).to_string(), "s^2 + c^2 - 1");
        let h = Rational::new(-3, 4).unwrap();
        let p =
            P::monomial(h, &[(2, 2), (0, 1)]) - x(1) + P::constant(Rational::new(1, 2).unwrap());
        assert_eq!(p.display(&vars).to_string(), "-3/4*c*x^2 - s + 1/2");
        assert_eq!(P::zero().display(&vars).to_string(), "0");
        assert_eq!(format!("{:?}", x(4)), "_x4");
    }
}
