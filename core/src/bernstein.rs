//! Polynomials in Bernstein form, written once and generic over the scalar.
//!
//! A [`Bernstein`] polynomial of degree `n` is `p(t) = sum_i c_i B_i^n(t)` with the Bernstein
//! polynomials `B_i^n(t) = C(n,i) t^i (1-t)^(n-i)`. Everything that needs only `+ - *`
//! (evaluation by de Casteljau, subdivision, the derivative, the power-basis coefficients, the
//! product rule in scaled form) asks for a [`Ring`]; what divides by integers (degree elevation,
//! the product rule `B_i^m B_j^n = phi(m,n,i,j) B_{i+j}^{m+n}` with `phi` a fraction, conversion
//! from the power basis) asks for a [`Field`].
//!
//! # The scaled basis: division-free products
//!
//! The coefficients of a product of Bernstein polynomials have the denominators `C(m+n,k)`, which
//! a ring (a polynomial ring, in a symbolic proof) does not have. The *scaled* coefficients
//! `e_k = C(n,k) c_k` are the coefficients of the same polynomial in the basis
//! `t^k (1-t)^(n-k)` (the monomials of the homogeneous form in `(1-t, t)`); in that basis the
//! product is the plain convolution, so [`Bernstein::mul_scaled`] returns
//! `e_k = sum_{i+j=k} C(m,i) C(n,j) a_i b_j`, which is `C(m+n,k)` times the `k`-th Bernstein
//! coefficient of the product ([`Bernstein::mul`]). [`Bernstein::to_scaled`] and
//! [`Bernstein::from_scaled`] convert; a claim printed with `phi` is checked division-free by
//! multiplying both sides by `C(m+n,k)`.
//!
//! Likewise [`Bernstein::elevate_scaled`] returns `(n+1)` times the elevated coefficients: a
//! uniform factor, harmless wherever only the projective class matters (rational curves).
//!
//! # Integers in a field
//! The `Field` methods divide by degrees and binomial coefficients. They panic in a field whose
//! characteristic divides such an integer — never in characteristic 0 (rationals, square-root
//! extensions, `f64`) nor modulo a prime larger than the degrees involved. Binomial coefficients
//! are computed by [`binomial`](crate::scalar::binomial), which limits degrees to 67.

use crate::scalar::{binom, from_u64, Field, OrderedField, Ring, Sign};
use crate::vector::{Hom4, Vec3};

/// A malformed list of coefficients or control points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShapeError {
    /// The list is empty: a Bernstein form needs at least one coefficient (degree 0).
    Empty,
    /// Two lists that must have the same length (weights and points, coordinates of one curve,
    /// summands of one degree) do not.
    LengthMismatch {
        /// The length of the first list.
        expected: usize,
        /// The length of the list that differs from it.
        found: usize,
    },
    /// A row of a control net has a different length from the first row.
    Ragged {
        /// The index of the offending row.
        row: usize,
        /// The length of row 0.
        expected: usize,
        /// The length of the offending row.
        found: usize,
    },
}

impl core::fmt::Display for ShapeError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            ShapeError::Empty => f.write_str("empty list of coefficients or control points"),
            ShapeError::LengthMismatch { expected, found } => {
                write!(
                    f,
                    "length mismatch: expected {expected} entries, found {found}"
                )
            }
            ShapeError::Ragged {
                row,
                expected,
                found,
            } => write!(
                f,
                "ragged control net: row {row} has {found} entries, row 0 has {expected}"
            ),
        }
    }
}

impl std::error::Error for ShapeError {}

/// `k * x` for a non-negative integer `k`, with no work when `k == 1`.
pub(crate) fn scale_u64<T: Ring>(x: &T, k: u64) -> T {
    if k == 1 {
        x.clone()
    } else if let Ok(v) = i64::try_from(k) {
        x.scale_i64(v)
    } else {
        x.mul_ref(&from_u64(k))
    }
}

/// `x / d` for a positive integer `d`, with no work when `d == 1`.
///
/// # Panics
/// When `d` is zero in the field (its characteristic divides `d`).
pub(crate) fn div_u64<T: Field>(x: &T, d: u64) -> T {
    if d == 1 {
        return x.clone();
    }
    x.checked_div(&from_u64(d))
        .unwrap_or_else(|_| panic!("the integer {d} is zero in this field"))
}

/// A value linear over the scalar: a scalar, a [`Vec3`] or a [`Hom4`]. The generic algorithms
/// below (de Casteljau, subdivision, elevation, products, differences) run on control lists of
/// any of them, so curves and scalar polynomials share one implementation.
pub(crate) trait Linear<T: Ring>: Clone {
    /// Applies `f` to every coordinate.
    fn map_coeffs(&self, f: impl FnMut(&T) -> T) -> Self;
    /// Combines corresponding coordinates with `f`.
    fn zip_coeffs(&self, other: &Self, f: impl FnMut(&T, &T) -> T) -> Self;
}

impl<T: Ring> Linear<T> for T {
    fn map_coeffs(&self, mut f: impl FnMut(&T) -> T) -> Self {
        f(self)
    }
    fn zip_coeffs(&self, other: &Self, mut f: impl FnMut(&T, &T) -> T) -> Self {
        f(self, other)
    }
}

impl<T: Ring> Linear<T> for Vec3<T> {
    fn map_coeffs(&self, f: impl FnMut(&T) -> T) -> Self {
        self.map(f)
    }
    fn zip_coeffs(&self, other: &Self, mut f: impl FnMut(&T, &T) -> T) -> Self {
        Vec3::new(
            f(&self.x, &other.x),
            f(&self.y, &other.y),
            f(&self.z, &other.z),
        )
    }
}

impl<T: Ring> Linear<T> for Hom4<T> {
    fn map_coeffs(&self, mut f: impl FnMut(&T) -> T) -> Self {
        Hom4(core::array::from_fn(|i| f(&self.0[i])))
    }
    fn zip_coeffs(&self, other: &Self, mut f: impl FnMut(&T, &T) -> T) -> Self {
        Hom4(core::array::from_fn(|i| f(&self.0[i], &other.0[i])))
    }
}

/// `s a + t b`.
fn lin<T: Ring, V: Linear<T>>(a: &V, s: &T, b: &V, t: &T) -> V {
    a.zip_coeffs(b, |x, y| x.mul_ref(s) + y.mul_ref(t))
}

/// `a + b`.
pub(crate) fn plus<T: Ring, V: Linear<T>>(a: &V, b: &V) -> V {
    a.zip_coeffs(b, |x, y| x.add_ref(y))
}

/// The zero of the kind of `v`.
fn zero_like<T: Ring, V: Linear<T>>(v: &V) -> V {
    v.map_coeffs(|_| T::zero())
}

/// De Casteljau's algorithm at the homogeneous parameter `(s, t)`:
/// `sum_i C(n,i) s^(n-i) t^i c_i` (with `s = 1 - t` the value at `t`). `ctrl` is not empty.
pub(crate) fn casteljau<T: Ring, V: Linear<T>>(ctrl: &[V], s: &T, t: &T) -> V {
    let mut b = ctrl.to_vec();
    let len = b.len();
    for r in 1..len {
        for i in 0..len - r {
            b[i] = lin(&b[i], s, &b[i + 1], t);
        }
    }
    b.truncate(1);
    b.pop().expect("a control list is never empty")
}

/// De Casteljau subdivision at `(s, t)` (with `s = 1 - t`: the pieces over `[0, t]` and `[t, 1]`,
/// each reparametrized to `[0, 1]`). `ctrl` is not empty.
pub(crate) fn subdivide<T: Ring, V: Linear<T>>(ctrl: &[V], s: &T, t: &T) -> (Vec<V>, Vec<V>) {
    let mut b = ctrl.to_vec();
    let len = b.len();
    let mut left = Vec::with_capacity(len);
    let mut right = Vec::with_capacity(len);
    left.push(b[0].clone());
    right.push(b[len - 1].clone());
    for r in 1..len {
        for i in 0..len - r {
            b[i] = lin(&b[i], s, &b[i + 1], t);
        }
        left.push(b[0].clone());
        right.push(b[len - 1 - r].clone());
    }
    right.reverse();
    (left, right)
}

/// `(n+1)` times the control list of the degree elevation `n -> n+1`:
/// `e_i = i c_{i-1} + (n+1-i) c_i`.
pub(crate) fn elevate_scaled<T: Ring, V: Linear<T>>(ctrl: &[V]) -> Vec<V> {
    let n1 = ctrl.len() as u64; // n + 1
    let mut out = Vec::with_capacity(ctrl.len() + 1);
    out.push(ctrl[0].map_coeffs(|x| scale_u64(x, n1)));
    for i in 1..ctrl.len() {
        let a = ctrl[i - 1].map_coeffs(|x| scale_u64(x, i as u64));
        let b = ctrl[i].map_coeffs(|x| scale_u64(x, n1 - i as u64));
        out.push(plus(&a, &b));
    }
    out.push(ctrl[ctrl.len() - 1].map_coeffs(|x| scale_u64(x, n1)));
    out
}

/// `(n+1)(n+2)...(n+r)` times the control list of the elevation `n -> n+r` (repeated
/// [`elevate_scaled`]).
pub(crate) fn elevate_by_scaled<T: Ring, V: Linear<T>>(ctrl: &[V], r: usize) -> Vec<V> {
    let mut out = ctrl.to_vec();
    for _ in 0..r {
        out = elevate_scaled(&out);
    }
    out
}

/// The product rule in the scaled basis: `e_k = sum_{i+j=k} C(m,i) C(n,j) a_i b_j` for the
/// scalar list `a` (degree m) and the list `b` (degree n). Neither list is empty.
pub(crate) fn product_scaled<T: Ring, V: Linear<T>>(a: &[T], b: &[V]) -> Vec<V> {
    let (m, n) = (a.len() - 1, b.len() - 1);
    let a: Vec<T> = a
        .iter()
        .enumerate()
        .map(|(i, x)| scale_u64(x, binom(m, i)))
        .collect();
    let b: Vec<V> = b
        .iter()
        .enumerate()
        .map(|(j, v)| v.map_coeffs(|x| scale_u64(x, binom(n, j))))
        .collect();
    let mut out = vec![zero_like(&b[0]); m + n + 1];
    for (i, ai) in a.iter().enumerate() {
        if ai.is_zero() {
            continue;
        }
        for (j, bj) in b.iter().enumerate() {
            out[i + j] = out[i + j].zip_coeffs(bj, |acc, y| acc.add_ref(&ai.mul_ref(y)));
        }
    }
    out
}

/// The scaled-basis coefficients `C(n,k) c_k`.
pub(crate) fn to_scaled<T: Ring, V: Linear<T>>(ctrl: &[V]) -> Vec<V> {
    let n = ctrl.len() - 1;
    ctrl.iter()
        .enumerate()
        .map(|(k, v)| v.map_coeffs(|x| scale_u64(x, binom(n, k))))
        .collect()
}

/// The Bernstein coefficients `e_k / C(n,k)` of scaled-basis coefficients.
pub(crate) fn from_scaled<T: Field, V: Linear<T>>(e: &[V]) -> Vec<V> {
    let n = e.len() - 1;
    e.iter()
        .enumerate()
        .map(|(k, v)| v.map_coeffs(|x| div_u64(x, binom(n, k))))
        .collect()
}

/// The control list of the derivative: `n (c_{i+1} - c_i)`, of degree `n - 1`; for degree 0 the
/// zero polynomial of degree 0.
pub(crate) fn differences<T: Ring, V: Linear<T>>(ctrl: &[V]) -> Vec<V> {
    let n = ctrl.len() - 1;
    if n == 0 {
        return vec![zero_like(&ctrl[0])];
    }
    ctrl.windows(2)
        .map(|w| w[1].zip_coeffs(&w[0], |x, y| scale_u64(&x.sub_ref(y), n as u64)))
        .collect()
}

/// Divides every coordinate of every entry of `ctrl` by `d`.
pub(crate) fn div_all<T: Field, V: Linear<T>>(ctrl: &[V], d: u64) -> Vec<V> {
    ctrl.iter()
        .map(|v| v.map_coeffs(|x| div_u64(x, d)))
        .collect()
}

/// The Field form of [`product_scaled`]: the Bernstein coefficients of the product.
pub(crate) fn product<T: Field, V: Linear<T>>(a: &[T], b: &[V]) -> Vec<V> {
    from_scaled(&product_scaled(a, b))
}

/// The Field form of elevation `n -> n+r` by the product with the constant 1 of degree r, one
/// division per coordinate: `c'_k = sum_{i+j=k} C(n,i) C(r,j) c_i / C(n+r,k)`.
pub(crate) fn elevate_by<T: Field, V: Linear<T>>(ctrl: &[V], r: usize) -> Vec<V> {
    if r == 0 {
        return ctrl.to_vec();
    }
    let ones = vec![T::one(); r + 1];
    // product_scaled(a, b) with a the scalar list: multiply the ones by the control list.
    let mut scaled = product_scaled(&ones, ctrl);
    let n = ctrl.len() - 1;
    for (k, v) in scaled.iter_mut().enumerate() {
        *v = v.map_coeffs(|x| div_u64(x, binom(n + r, k)));
    }
    scaled
}

/// The product-rule factor `phi(m,n,i,j) = C(m,i) C(n,j) / C(m+n,i+j)` of
/// `B_i^m B_j^n = phi(m,n,i,j) B_{i+j}^{m+n}`, as a reduced fraction
/// `(numerator, denominator)`; `(0, 1)` when `i > m` or `j > n`.
///
/// By Vandermonde's identity `phi <= 1`, so both parts fit in a `u64`.
///
/// # Panics
/// When `C(m+n, i+j)` overflows a `u64` (not before `m + n = 67`).
pub fn phi(m: usize, n: usize, i: usize, j: usize) -> (u64, u64) {
    if i > m || j > n {
        return (0, 1);
    }
    let num = u128::from(binom(m, i)) * u128::from(binom(n, j));
    let den = u128::from(binom(m + n, i + j));
    let g = gcd_u128(num, den);
    // num / g <= den / g <= den < 2^64.
    ((num / g) as u64, (den / g) as u64)
}

/// The product-rule factor [`phi`] as an element of the field.
///
/// # Panics
/// As [`phi`], and when the denominator is zero in the field.
pub fn phi_value<T: Field>(m: usize, n: usize, i: usize, j: usize) -> T {
    let (num, den) = phi(m, n, i, j);
    div_u64(&from_u64(num), den)
}

fn gcd_u128(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// A polynomial `p(t) = sum_{i=0}^n c_i B_i^n(t)` in Bernstein form of degree `n`.
///
/// The degree is that of the representation (the number of coefficients minus one), not
/// necessarily the exact degree of the polynomial: `elevate` raises it without changing `p`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Bernstein<T> {
    coeffs: Vec<T>,
}

impl<T> Bernstein<T> {
    /// The polynomial with Bernstein coefficients `c_0..c_n`.
    ///
    /// # Panics
    /// When `coeffs` is empty; [`Bernstein::try_new`] reports it instead.
    pub fn new(coeffs: Vec<T>) -> Self {
        Self::try_new(coeffs).expect("a Bernstein polynomial needs at least one coefficient")
    }

    /// The polynomial with Bernstein coefficients `c_0..c_n`.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when `coeffs` is empty.
    ///
    /// ```
    /// use exactcheck_core::bernstein::{Bernstein, ShapeError};
    /// assert_eq!(Bernstein::<f64>::try_new(vec![]), Err(ShapeError::Empty));
    /// assert_eq!(Bernstein::try_new(vec![1.0, 2.0]).unwrap().degree(), 1);
    /// ```
    pub fn try_new(coeffs: Vec<T>) -> Result<Self, ShapeError> {
        if coeffs.is_empty() {
            Err(ShapeError::Empty)
        } else {
            Ok(Bernstein { coeffs })
        }
    }

    /// The coefficients `c_0..c_n`.
    pub fn coeffs(&self) -> &[T] {
        &self.coeffs
    }

    /// The coefficients `c_0..c_n`, by value.
    pub fn into_coeffs(self) -> Vec<T> {
        self.coeffs
    }

    /// The degree `n` of the representation.
    pub fn degree(&self) -> usize {
        self.coeffs.len() - 1
    }

    /// The polynomial with coefficients `f(c_i)` (same degree).
    pub fn map<U>(&self, f: impl FnMut(&T) -> U) -> Bernstein<U> {
        Bernstein {
            coeffs: self.coeffs.iter().map(f).collect(),
        }
    }
}

impl<T: Ring> Bernstein<T> {
    /// The constant `c` written in degree `degree` (every coefficient is `c`, since
    /// `sum_i B_i^n = 1`).
    pub fn constant(c: T, degree: usize) -> Self {
        Bernstein {
            coeffs: vec![c; degree + 1],
        }
    }

    /// The basis polynomial `B_i^n` (coefficient 1 at `i`, 0 elsewhere).
    ///
    /// # Panics
    /// When `i > n`.
    pub fn basis(n: usize, i: usize) -> Self {
        assert!(i <= n, "basis index {i} exceeds the degree {n}");
        let mut coeffs = vec![T::zero(); n + 1];
        coeffs[i] = T::one();
        Bernstein { coeffs }
    }

    /// Whether every coefficient is zero (the zero polynomial).
    pub fn is_zero(&self) -> bool {
        self.coeffs.iter().all(Ring::is_zero)
    }

    /// `p(t)` by de Casteljau's algorithm (convex combinations `(1-t) b_i + t b_{i+1}`, exact at
    /// `t = 0` and `t = 1` also in floating point).
    pub fn eval(&self, t: &T) -> T {
        casteljau(&self.coeffs, &(T::one() - t), t)
    }

    /// The homogeneous form `sum_i c_i C(n,i) t^i s^(n-i)` at `(s, t)`; `eval(t)` is the case
    /// `s = 1 - t`. At a rational parameter `p/q` this is `q^n p(p/q)` for `(s, t) = (q-p, p)`,
    /// without division.
    pub fn eval_homogeneous(&self, s: &T, t: &T) -> T {
        casteljau(&self.coeffs, s, t)
    }

    /// De Casteljau subdivision at `t`: the pieces of `p` over `[0, t]` and `[t, 1]`, each
    /// reparametrized to `[0, 1]` (`left(u) = p(t u)`, `right(u) = p(t + (1-t) u)`).
    pub fn split(&self, t: &T) -> (Self, Self) {
        let (l, r) = subdivide(&self.coeffs, &(T::one() - t), t);
        (Bernstein { coeffs: l }, Bernstein { coeffs: r })
    }

    /// `(n+1)` times the degree elevation `n -> n+1` ([`Bernstein::elevate`]), division-free:
    /// coefficients `i c_{i-1} + (n+1-i) c_i`, so the result is the polynomial `(n+1) p`.
    pub fn elevate_scaled(&self) -> Self {
        Bernstein {
            coeffs: elevate_scaled(&self.coeffs),
        }
    }

    /// `r` times [`Bernstein::elevate_scaled`]: the polynomial `(n+1)(n+2)...(n+r) p` in
    /// degree `n + r`.
    pub fn elevate_by_scaled(&self, r: usize) -> Self {
        Bernstein {
            coeffs: elevate_by_scaled(&self.coeffs, r),
        }
    }

    /// The product rule division-free: `e_k = sum_{i+j=k} C(m,i) C(n,j) a_i b_j`, k = 0..m+n,
    /// the coefficients of `self * other` in the scaled basis `t^k (1-t)^(m+n-k)`; each is
    /// `C(m+n,k)` times the Bernstein coefficient of [`Bernstein::mul`].
    pub fn mul_scaled(&self, other: &Self) -> Vec<T> {
        product_scaled(&self.coeffs, &other.coeffs)
    }

    /// The scaled-basis coefficients `C(n,k) c_k`: `p(t) = sum_k e_k t^k (1-t)^(n-k)`.
    pub fn to_scaled(&self) -> Vec<T> {
        to_scaled(&self.coeffs)
    }

    /// The derivative `p'`, of degree `n - 1`, with coefficients `n (c_{i+1} - c_i)`; for
    /// degree 0 the zero polynomial of degree 0.
    pub fn derivative(&self) -> Self {
        Bernstein {
            coeffs: differences(&self.coeffs),
        }
    }

    /// The power-basis coefficients `a_0..a_n` of `p(t) = sum_k a_k t^k`:
    /// `a_k = C(n,k) sum_{i<=k} (-1)^(k-i) C(k,i) c_i = C(n,k) Delta^k c_0` (by a difference
    /// table: subtractions only, then one integer scaling per coefficient).
    pub fn to_power(&self) -> Vec<T> {
        let n = self.degree();
        let mut d = self.coeffs.clone();
        let mut a = Vec::with_capacity(n + 1);
        for k in 0..=n {
            a.push(scale_u64(&d[0], binom(n, k)));
            for i in 0..d.len() - 1 {
                d[i] = d[i + 1].sub_ref(&d[i]);
            }
            d.pop();
        }
        a
    }

    /// `k p`.
    pub fn scale(&self, k: &T) -> Self {
        self.map(|c| c.mul_ref(k))
    }

    /// `p + q` for two representations of the same degree.
    ///
    /// # Errors
    /// [`ShapeError::LengthMismatch`] when the degrees differ (elevate the lower one first).
    pub fn checked_add(&self, other: &Self) -> Result<Self, ShapeError> {
        self.zip_same_degree(other, |x, y| x.add_ref(y))
    }

    /// `p - q` for two representations of the same degree.
    ///
    /// # Errors
    /// [`ShapeError::LengthMismatch`] when the degrees differ (elevate the lower one first).
    pub fn checked_sub(&self, other: &Self) -> Result<Self, ShapeError> {
        self.zip_same_degree(other, |x, y| x.sub_ref(y))
    }

    fn zip_same_degree(
        &self,
        other: &Self,
        mut f: impl FnMut(&T, &T) -> T,
    ) -> Result<Self, ShapeError> {
        if self.coeffs.len() != other.coeffs.len() {
            return Err(ShapeError::LengthMismatch {
                expected: self.coeffs.len(),
                found: other.coeffs.len(),
            });
        }
        Ok(Bernstein {
            coeffs: self
                .coeffs
                .iter()
                .zip(&other.coeffs)
                .map(|(x, y)| f(x, y))
                .collect(),
        })
    }
}

impl<T: Field> Bernstein<T> {
    /// Degree elevation `n -> n+1` (the same polynomial):
    /// `c'_i = (i c_{i-1} + (n+1-i) c_i) / (n+1)`.
    pub fn elevate(&self) -> Self {
        Bernstein {
            coeffs: div_all(&elevate_scaled(&self.coeffs), self.coeffs.len() as u64),
        }
    }

    /// Degree elevation `n -> n+r` (the same polynomial), in one step:
    /// `c'_k = sum_{i+j=k} C(n,i) C(r,j) c_i / C(n+r,k)`.
    pub fn elevate_by(&self, r: usize) -> Self {
        Bernstein {
            coeffs: elevate_by(&self.coeffs, r),
        }
    }

    /// The product `p q` in degree `m + n` by the product rule:
    /// `d_k = sum_{i+j=k} phi(m,n,i,j) a_i b_j`.
    pub fn mul(&self, other: &Self) -> Self {
        Bernstein {
            coeffs: product(&self.coeffs, &other.coeffs),
        }
    }

    /// The polynomial `sum_k a_k t^k` in Bernstein form of degree `n = a.len() - 1`:
    /// `c_i = sum_{k<=i} C(i,k) / C(n,k) a_k`.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when `a` is empty.
    pub fn from_power(a: &[T]) -> Result<Self, ShapeError> {
        if a.is_empty() {
            return Err(ShapeError::Empty);
        }
        let n = a.len() - 1;
        // b_k = a_k / C(n,k) = Delta^k c_0; rebuild the difference table from its left edge.
        let b: Vec<T> = a
            .iter()
            .enumerate()
            .map(|(k, x)| div_u64(x, binom(n, k)))
            .collect();
        let mut row = vec![b[n].clone()];
        for k in (0..n).rev() {
            let mut next = Vec::with_capacity(row.len() + 1);
            next.push(b[k].clone());
            for (i, r) in row.iter().enumerate() {
                let v = next[i].add_ref(r);
                next.push(v);
            }
            row = next;
        }
        Ok(Bernstein { coeffs: row })
    }

    /// The polynomial `sum_k e_k t^k (1-t)^(n-k)` (scaled-basis coefficients, as returned by
    /// [`Bernstein::mul_scaled`] and [`Bernstein::to_scaled`]) in Bernstein form:
    /// `c_k = e_k / C(n,k)`.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when `e` is empty.
    pub fn from_scaled(e: &[T]) -> Result<Self, ShapeError> {
        if e.is_empty() {
            return Err(ShapeError::Empty);
        }
        Ok(Bernstein {
            coeffs: from_scaled(e),
        })
    }
}

impl<T: OrderedField> Bernstein<T> {
    /// The number of sign changes in `c_0..c_n`, zeros skipped: an upper bound on the number of
    /// roots in the open interval `(0, 1)` with the same parity (Descartes' rule in Bernstein
    /// form); 0 proves there is none, 1 that there is exactly one.
    pub fn sign_changes(&self) -> usize {
        let mut last = Sign::Zero;
        let mut changes = 0;
        for c in &self.coeffs {
            let s = c.sign();
            if s == Sign::Zero {
                continue;
            }
            if last != Sign::Zero && s != last {
                changes += 1;
            }
            last = s;
        }
        changes
    }
}

#[cfg(test)]
mod tests;
