//! Polynomials in Bernstein form (SPEC §0), written once and generic over the scalar.
//!
//! A [`Bernstein`] polynomial of degree `n` is `p(t) = sum_i c_i B_i^n(t)` with the Bernstein
//! polynomials `B_i^n(t) = C(n,i) t^i (1-t)^(n-i)` (SPEC §0). Everything that needs only `+ - *`
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
//! are computed by [`binomial`], which limits degrees to 67.

use crate::scalar::{binomial, Field, OrderedField, Ring, Sign};
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

/// `C(n, k)` for `usize` arguments (0 when `k > n`).
pub(crate) fn binom(n: usize, k: usize) -> u64 {
    if k > n {
        return 0;
    }
    let n = u32::try_from(n).expect("degree does not fit in u32");
    binomial(n, k as u32)
}

/// The image of a non-negative integer in the ring (exact for the whole `u64` range).
pub(crate) fn from_u64<T: Ring>(n: u64) -> T {
    match i64::try_from(n) {
        Ok(v) => T::from_i64(v),
        // n < 2^64, so n >> 1 fits in an i64.
        Err(_) => T::from_i64((n >> 1) as i64).scale_i64(2) + T::from_i64((n & 1) as i64),
    }
}

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
/// `B_i^m B_j^n = phi(m,n,i,j) B_{i+j}^{m+n}` (SPEC §0), as a reduced fraction
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

/// A polynomial `p(t) = sum_{i=0}^n c_i B_i^n(t)` in Bernstein form of degree `n` (SPEC §0).
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

    /// The product `p q` in degree `m + n` by the product rule (SPEC §0):
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

/// Exact test scalars shared by the tests of this module and of [`crate::bezier`]: rationals
/// over `i128` (a field), polynomials over `i128` in one variable (a ring: a symbolic check), and
/// a deterministic pseudo-random generator.
#[cfg(test)]
pub(crate) mod test_support {
    use crate::scalar::{Field, Ring, ZeroDivisor};

    /// The workspace's seeded generator, with the two draws these tests use.
    pub struct Rng(crate::rng::Rng);

    impl Rng {
        pub fn new(seed: u64) -> Self {
            Rng(crate::rng::Rng::new(seed))
        }
        /// Uniform in `lo..=hi`.
        pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
            lo + self.0.below((hi - lo + 1) as u64) as i64
        }
        pub fn below(&mut self, n: usize) -> usize {
            self.0.below(n as u64) as usize
        }
    }

    macro_rules! binop {
        ($t:ty, $tr:ident, $m:ident, $tra:ident, $ma:ident, $f:ident) => {
            impl core::ops::$tr for $t {
                type Output = $t;
                fn $m(self, r: $t) -> $t {
                    self.$f(&r)
                }
            }
            impl<'a> core::ops::$tr<&'a $t> for $t {
                type Output = $t;
                fn $m(self, r: &'a $t) -> $t {
                    self.$f(r)
                }
            }
            impl core::ops::$tra for $t {
                fn $ma(&mut self, r: $t) {
                    *self = self.$f(&r);
                }
            }
            impl<'a> core::ops::$tra<&'a $t> for $t {
                fn $ma(&mut self, r: &'a $t) {
                    *self = self.$f(r);
                }
            }
        };
    }

    fn gcd(mut a: i128, mut b: i128) -> i128 {
        a = a.abs();
        b = b.abs();
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    }

    /// An exact rational `n / d` in lowest terms with `d > 0` (overflow panics).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
    pub struct Q(pub i128, pub i128);

    impl Q {
        pub fn new(n: i128, d: i128) -> Q {
            assert!(d != 0, "zero denominator");
            let g = gcd(n, d).max(1);
            let s = if d < 0 { -1 } else { 1 };
            Q(s * n / g, s * d / g)
        }
        pub fn int(n: i64) -> Q {
            Q(n as i128, 1)
        }
        fn add_q(&self, r: &Q) -> Q {
            let g = gcd(self.1, r.1);
            let (a, b) = (self.1 / g, r.1 / g);
            let n = self
                .0
                .checked_mul(b)
                .and_then(|x| x.checked_add(r.0.checked_mul(a)?));
            Q::new(
                n.expect("Q overflow"),
                self.1.checked_mul(b).expect("Q overflow"),
            )
        }
        fn sub_q(&self, r: &Q) -> Q {
            self.add_q(&Q(-r.0, r.1))
        }
        fn mul_q(&self, r: &Q) -> Q {
            let g1 = gcd(self.0, r.1).max(1);
            let g2 = gcd(r.0, self.1).max(1);
            let n = (self.0 / g1).checked_mul(r.0 / g2).expect("Q overflow");
            let d = (self.1 / g2).checked_mul(r.1 / g1).expect("Q overflow");
            Q::new(n, d)
        }
        fn div_q(&self, r: &Q) -> Q {
            assert!(r.0 != 0, "division by zero");
            self.mul_q(&Q::new(r.1, r.0))
        }
    }

    binop!(Q, Add, add, AddAssign, add_assign, add_q);
    binop!(Q, Sub, sub, SubAssign, sub_assign, sub_q);
    binop!(Q, Mul, mul, MulAssign, mul_assign, mul_q);
    binop!(Q, Div, div, DivAssign, div_assign, div_q);

    impl core::ops::Neg for Q {
        type Output = Q;
        fn neg(self) -> Q {
            Q(-self.0, self.1)
        }
    }

    impl Ring for Q {
        fn zero() -> Self {
            Q(0, 1)
        }
        fn one() -> Self {
            Q(1, 1)
        }
        fn from_i64(n: i64) -> Self {
            Q::int(n)
        }
        fn is_zero(&self) -> bool {
            self.0 == 0
        }
    }

    impl Field for Q {
        fn inv(&self) -> Result<Self, ZeroDivisor> {
            if self.0 == 0 {
                Err(ZeroDivisor)
            } else {
                Ok(Q::new(self.1, self.0))
            }
        }
    }

    impl PartialOrd for Q {
        fn partial_cmp(&self, o: &Q) -> Option<core::cmp::Ordering> {
            (self.0 * o.1).partial_cmp(&(o.0 * self.1))
        }
    }

    impl crate::scalar::OrderedField for Q {}

    /// A polynomial `sum a_k x^k` over `i128` (no trailing zeros; overflow panics): a ring that
    /// is not a field, standing in for the symbolic scalars.
    #[derive(Clone, Debug, PartialEq, Eq, Hash)]
    pub struct Poly(pub Vec<i128>);

    impl Poly {
        pub fn x() -> Poly {
            Poly(vec![0, 1])
        }
        pub fn constant(c: i128) -> Poly {
            Poly(vec![c]).trim()
        }
        fn trim(mut self) -> Poly {
            while self.0.last() == Some(&0) {
                self.0.pop();
            }
            self
        }
        fn zip(&self, r: &Poly, f: impl Fn(i128, i128) -> i128) -> Poly {
            let len = self.0.len().max(r.0.len());
            let get = |p: &Poly, i: usize| p.0.get(i).copied().unwrap_or(0);
            Poly((0..len).map(|i| f(get(self, i), get(r, i))).collect()).trim()
        }
        fn add_p(&self, r: &Poly) -> Poly {
            self.zip(r, |a, b| a.checked_add(b).expect("Poly overflow"))
        }
        fn sub_p(&self, r: &Poly) -> Poly {
            self.zip(r, |a, b| a.checked_sub(b).expect("Poly overflow"))
        }
        fn mul_p(&self, r: &Poly) -> Poly {
            if self.0.is_empty() || r.0.is_empty() {
                return Poly(vec![]);
            }
            let mut out = vec![0i128; self.0.len() + r.0.len() - 1];
            for (i, a) in self.0.iter().enumerate() {
                for (j, b) in r.0.iter().enumerate() {
                    let p = a.checked_mul(*b).expect("Poly overflow");
                    out[i + j] = out[i + j].checked_add(p).expect("Poly overflow");
                }
            }
            Poly(out).trim()
        }
    }

    binop!(Poly, Add, add, AddAssign, add_assign, add_p);
    binop!(Poly, Sub, sub, SubAssign, sub_assign, sub_p);
    binop!(Poly, Mul, mul, MulAssign, mul_assign, mul_p);

    impl core::ops::Neg for Poly {
        type Output = Poly;
        fn neg(self) -> Poly {
            Poly(self.0.iter().map(|a| -a).collect())
        }
    }

    impl Ring for Poly {
        fn zero() -> Self {
            Poly(vec![])
        }
        fn one() -> Self {
            Poly(vec![1])
        }
        fn from_i64(n: i64) -> Self {
            Poly::constant(n as i128)
        }
        fn is_zero(&self) -> bool {
            self.0.is_empty()
        }
    }

    /// A random integer coefficient list of length `len` with entries in `-r..=r`.
    pub fn ints(rng: &mut Rng, len: usize, r: i64) -> Vec<i64> {
        (0..len).map(|_| rng.int(-r, r)).collect()
    }

    /// A random rational with numerator in `-r..=r` and denominator in `1..=d`.
    pub fn rational(rng: &mut Rng, r: i64, d: i64) -> Q {
        Q::new(rng.int(-r, r) as i128, rng.int(1, d) as i128)
    }
}

#[cfg(test)]
mod tests {
    use super::test_support::{ints, rational, Poly, Rng, Q};
    use super::*;

    const CASES: usize = 300;

    fn qpoly(c: &[i64]) -> Bernstein<Q> {
        Bernstein::new(c.iter().map(|&x| Q::int(x)).collect())
    }

    fn fpoly(c: &[i64]) -> Bernstein<f64> {
        Bernstein::new(c.iter().map(|&x| x as f64).collect())
    }

    /// `sum_i c_i B_i^n(t)` summed directly, with the basis from its definition.
    fn direct<T: Ring>(p: &Bernstein<T>, t: &T) -> T {
        let n = p.degree();
        let s = T::one() - t;
        let mut acc = T::zero();
        for (i, c) in p.coeffs().iter().enumerate() {
            let b = from_u64::<T>(binom(n, i)) * t.pow(i as u32) * s.pow((n - i) as u32);
            acc += b * c;
        }
        acc
    }

    /// `sum_k a_k t^k` by Horner's rule.
    fn horner<T: Ring>(a: &[T], t: &T) -> T {
        a.iter().rev().fold(T::zero(), |acc, c| acc * t + c)
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn empty_is_rejected() {
        assert_eq!(Bernstein::<Q>::try_new(vec![]), Err(ShapeError::Empty));
        assert_eq!(Bernstein::<Q>::from_power(&[]), Err(ShapeError::Empty));
        assert_eq!(Bernstein::<Q>::from_scaled(&[]), Err(ShapeError::Empty));
        assert_eq!(
            ShapeError::Empty.to_string(),
            "empty list of coefficients or control points"
        );
    }

    #[test]
    #[should_panic(expected = "at least one coefficient")]
    fn new_panics_on_empty() {
        let _ = Bernstein::<f64>::new(vec![]);
    }

    #[test]
    fn casteljau_matches_direct_sum_f64_dyadic() {
        // Small integers at t = k/16: every intermediate is a short dyadic, so `==` is exact.
        let mut rng = Rng::new(1);
        for _ in 0..CASES {
            let n = rng.below(7);
            let p = fpoly(&ints(&mut rng, n + 1, 8));
            let t = rng.int(-8, 24) as f64 / 16.0;
            assert_eq!(p.eval(&t), direct(&p, &t), "{p:?} at {t}");
        }
    }

    #[test]
    fn casteljau_matches_direct_sum_exact() {
        let mut rng = Rng::new(2);
        for _ in 0..CASES {
            let n = rng.below(7);
            let p = qpoly(&ints(&mut rng, n + 1, 9));
            let t = rational(&mut rng, 7, 5);
            assert_eq!(p.eval(&t), direct(&p, &t));
        }
    }

    #[test]
    fn endpoints_are_end_coefficients() {
        let p = Bernstein::new(vec![0.1, 0.7, -0.3, 0.9]);
        assert_eq!(p.eval(&0.0), 0.1);
        assert_eq!(p.eval(&1.0), 0.9);
    }

    #[test]
    fn homogeneous_evaluation_clears_denominators() {
        let mut rng = Rng::new(3);
        for _ in 0..CASES {
            let n = rng.below(6);
            let p = qpoly(&ints(&mut rng, n + 1, 9));
            let (num, den) = (rng.int(-6, 6), rng.int(1, 6));
            let (qn, qd) = (Q::int(num), Q::int(den));
            let hom = p.eval_homogeneous(&(qd - qn), &qn);
            assert_eq!(hom, qd.pow(n as u32) * p.eval(&(qn / qd)));
        }
    }

    #[test]
    fn elevation_preserves_values() {
        let mut rng = Rng::new(4);
        for _ in 0..CASES {
            let n = rng.below(6);
            let p = qpoly(&ints(&mut rng, n + 1, 9));
            let r = rng.below(4);
            let e = p.elevate();
            let er = p.elevate_by(r);
            assert_eq!(e.degree(), n + 1);
            assert_eq!(er.degree(), n + r);
            // The one-step elevation agrees with repeated single steps.
            let mut rep = p.clone();
            for _ in 0..r {
                rep = rep.elevate();
            }
            assert_eq!(er, rep);
            // The Ring versions are uniform multiples.
            assert_eq!(p.elevate_scaled(), e.scale(&Q::int(n as i64 + 1)));
            let factor: i64 = (n + 1..=n + r).map(|k| k as i64).product();
            assert_eq!(p.elevate_by_scaled(r), er.scale(&Q::int(factor)));
            for _ in 0..4 {
                let t = rational(&mut rng, 7, 5);
                assert_eq!(e.eval(&t), p.eval(&t));
                assert_eq!(er.eval(&t), p.eval(&t));
            }
        }
    }

    #[test]
    fn elevation_f64_tolerance() {
        let mut rng = Rng::new(5);
        for _ in 0..CASES {
            let n = rng.below(7);
            let p = fpoly(&ints(&mut rng, n + 1, 100));
            let e = p.elevate_by(1 + rng.below(3));
            for k in 0..=10 {
                let t = k as f64 / 10.0;
                assert!(close(e.eval(&t), p.eval(&t)));
            }
        }
    }

    #[test]
    fn product_matches_pointwise_product() {
        let mut rng = Rng::new(6);
        for _ in 0..CASES {
            let (m, n) = (rng.below(5), rng.below(5));
            let a = qpoly(&ints(&mut rng, m + 1, 9));
            let b = qpoly(&ints(&mut rng, n + 1, 9));
            let ab = a.mul(&b);
            assert_eq!(ab.degree(), m + n);
            // The scaled product is the convolution of the scaled forms.
            let (sa, sb) = (a.to_scaled(), b.to_scaled());
            let mut conv = vec![Q::zero(); m + n + 1];
            for (i, x) in sa.iter().enumerate() {
                for (j, y) in sb.iter().enumerate() {
                    conv[i + j] += *x * y;
                }
            }
            assert_eq!(a.mul_scaled(&b), conv);
            assert_eq!(Bernstein::from_scaled(&conv).unwrap(), ab);
            assert_eq!(ab.to_scaled(), conv);
            for _ in 0..4 {
                let t = rational(&mut rng, 5, 4);
                assert_eq!(ab.eval(&t), a.eval(&t) * b.eval(&t));
            }
        }
    }

    #[test]
    fn product_f64_tolerance() {
        let mut rng = Rng::new(7);
        for _ in 0..CASES {
            let (m, n) = (rng.below(6), rng.below(6));
            let a = fpoly(&ints(&mut rng, m + 1, 50));
            let b = fpoly(&ints(&mut rng, n + 1, 50));
            let ab = a.mul(&b);
            for k in 0..=8 {
                let t = k as f64 / 8.0;
                assert!(close(ab.eval(&t), a.eval(&t) * b.eval(&t)));
            }
        }
    }

    #[test]
    fn phi_is_the_product_rule() {
        assert_eq!(phi(1, 2, 0, 1), (2, 3));
        assert_eq!(phi(2, 2, 1, 1), (2, 3));
        assert_eq!(phi(3, 0, 2, 0), (1, 1));
        assert_eq!(phi(1, 1, 2, 0), (0, 1));
        assert_eq!(phi_value::<Q>(1, 2, 1, 2), Q::new(1, 1));
        assert_eq!(phi_value::<Q>(2, 2, 0, 2), Q::new(1, 6));
        assert_eq!(phi_value::<f64>(1, 2, 0, 0), 1.0);
        // Large degrees stay within u64 and reduce.
        let (num, den) = phi(33, 33, 16, 17);
        assert!(num <= den && den > 1);
        for m in 0..5 {
            for n in 0..5 {
                for i in 0..=m {
                    for j in 0..=n {
                        let lhs = Bernstein::<Q>::basis(m, i).mul(&Bernstein::basis(n, j));
                        let rhs = Bernstein::basis(m + n, i + j).scale(&phi_value(m, n, i, j));
                        assert_eq!(lhs, rhs);
                        let mut scaled = vec![Q::zero(); m + n + 1];
                        scaled[i + j] = Q::int((binom(m, i) * binom(n, j)) as i64);
                        assert_eq!(
                            Bernstein::<Q>::basis(m, i).mul_scaled(&Bernstein::basis(n, j)),
                            scaled
                        );
                    }
                }
                // Vandermonde: sum_{i+j=k} phi = 1, so the constant 1 times 1 is 1.
                for k in 0..=m + n {
                    let s = (0..=k).fold(Q::zero(), |acc, i| acc + phi_value::<Q>(m, n, i, k - i));
                    assert_eq!(s, Q::one());
                }
            }
        }
    }

    #[test]
    fn derivative_commutes_with_power_form() {
        // Ring-only operations on small integers: exact in f64 as well.
        let mut rng = Rng::new(8);
        for _ in 0..CASES {
            let n = rng.below(8);
            let p = fpoly(&ints(&mut rng, n + 1, 20));
            let dp = p.derivative();
            assert_eq!(dp.degree(), n.saturating_sub(1));
            let a = p.to_power();
            let mut da: Vec<f64> = (1..a.len()).map(|k| k as f64 * a[k]).collect();
            if da.is_empty() {
                da.push(0.0);
            }
            assert_eq!(dp.to_power(), da);
        }
        assert!(Bernstein::new(vec![5.0]).derivative().is_zero());
    }

    #[test]
    fn power_form_round_trip() {
        let mut rng = Rng::new(9);
        for _ in 0..CASES {
            let n = rng.below(8);
            let p = qpoly(&ints(&mut rng, n + 1, 20));
            let a = p.to_power();
            assert_eq!(Bernstein::from_power(&a).unwrap(), p);
            let t = rational(&mut rng, 9, 7);
            assert_eq!(horner(&a, &t), p.eval(&t));
            // And the other way round.
            let a2: Vec<Q> = ints(&mut rng, n + 1, 20).into_iter().map(Q::int).collect();
            assert_eq!(Bernstein::from_power(&a2).unwrap().to_power(), a2);
        }
        let mut rng = Rng::new(10);
        for _ in 0..CASES {
            let n = rng.below(8);
            let p = fpoly(&ints(&mut rng, n + 1, 20));
            let back = Bernstein::from_power(&p.to_power()).unwrap();
            for (x, y) in back.coeffs().iter().zip(p.coeffs()) {
                assert!(close(*x, *y));
            }
        }
    }

    #[test]
    fn symbolic_evaluation_is_the_power_form() {
        // Over Z[x] (a ring, no division): de Casteljau at t = x expands p into the power basis.
        let mut rng = Rng::new(11);
        for _ in 0..CASES {
            let n = rng.below(8);
            let c = ints(&mut rng, n + 1, 20);
            let symbolic = Bernstein::new(c.iter().map(|&x| Poly::constant(x as i128)).collect());
            let expanded = symbolic.eval(&Poly::x());
            let mut power: Vec<i128> = qpoly(&c)
                .to_power()
                .iter()
                .map(|q| {
                    assert_eq!(q.1, 1);
                    q.0
                })
                .collect();
            while power.last() == Some(&0) {
                power.pop();
            }
            assert_eq!(expanded, Poly(power));
            // The Ring-only product and derivative run symbolically too.
            let sq = symbolic.mul_scaled(&symbolic);
            assert_eq!(sq.len(), 2 * n + 1);
            let _ = symbolic.derivative().to_power();
        }
    }

    #[test]
    fn split_reparametrizes() {
        let mut rng = Rng::new(12);
        for _ in 0..CASES {
            let n = rng.below(7);
            let p = qpoly(&ints(&mut rng, n + 1, 9));
            let t = rational(&mut rng, 5, 5);
            let (l, r) = p.split(&t);
            assert_eq!(l.degree(), n);
            assert_eq!(r.degree(), n);
            let u = rational(&mut rng, 5, 4);
            assert_eq!(l.eval(&u), p.eval(&(t * u)));
            assert_eq!(r.eval(&u), p.eval(&(t + (Q::one() - t) * u)));
        }
    }

    #[test]
    fn sums_and_sign_changes() {
        let a = qpoly(&[1, -2, 3]);
        let b = qpoly(&[0, 1, 1]);
        assert_eq!(a.checked_add(&b).unwrap(), qpoly(&[1, -1, 4]));
        assert_eq!(a.checked_sub(&b).unwrap(), qpoly(&[1, -3, 2]));
        assert_eq!(
            a.checked_add(&qpoly(&[1])),
            Err(ShapeError::LengthMismatch {
                expected: 3,
                found: 1
            })
        );
        assert_eq!(a.sign_changes(), 2);
        assert_eq!(qpoly(&[1, 0, 0, 2]).sign_changes(), 0);
        assert_eq!(qpoly(&[-1, 0, 0, 2]).sign_changes(), 1);
        assert_eq!(Bernstein::constant(Q::int(3), 2), qpoly(&[3, 3, 3]));
    }

    #[test]
    fn integers_beyond_i64() {
        let big = u64::MAX - 4;
        let q: Q = from_u64(big);
        assert_eq!(q, Q::new(big as i128, 1));
        assert_eq!(scale_u64(&Q::int(2), big), Q::new(2 * big as i128, 1));
    }
}
