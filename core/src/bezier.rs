//! Bezier curves and tensor-product patches with vector control points, generic over
//! the scalar.
//!
//! * [`BezierCurve`]: `x(t) = sum_i B_i^n(t) b_i` with points `b_i` in [`Vec3`].
//! * [`RationalBezierCurve`]: `C(t) = sum B_k w_k r_k / sum B_k w_k`, kept in homogeneous form:
//!   control vectors `(w_k, w_k r_k)` in [`Hom4`], so the curve is `t -> sum B_k (w_k, w_k r_k)`,
//!   a polynomial curve in projective 3-space. Everything but the passage to Cartesian points is
//!   division-free (a [`Ring`]); weights may be zero (control points at infinity) or negative.
//! * [`TensorPatch`]: `S(u,v) = sum_i sum_j B_i^m(u) B_j^n(v) b_ij` with `b_ij` in [`Hom4`], so
//!   polynomial and rational patches alike.
//!
//! The algorithms (de Casteljau, subdivision, elevation, the product rule, its scaled
//! division-free form) are those of [`crate::bernstein`], run on vector-valued control lists.
//!
//! A homogeneous curve multiplied by a common non-zero factor is the same projective curve: this
//! is why [`RationalBezierCurve::elevate_scaled`] — `(n+1)` times the elevated control vectors —
//! is a genuine, division-free degree elevation of a rational curve.

use crate::bernstein::{self, Bernstein, ShapeError};
use crate::scalar::{Field, Ring, ZeroDivisor};
use crate::vector::{Hom4, Vec3};

/// A polynomial Bezier curve `x(t) = sum_{i=0}^n B_i^n(t) b_i` with control points in [`Vec3`].
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BezierCurve<T> {
    points: Vec<Vec3<T>>,
}

impl<T> BezierCurve<T> {
    /// The curve with control points `b_0..b_n`.
    ///
    /// # Panics
    /// When `points` is empty; [`BezierCurve::try_new`] reports it instead.
    pub fn new(points: Vec<Vec3<T>>) -> Self {
        Self::try_new(points).expect("a Bezier curve needs at least one control point")
    }

    /// The curve with control points `b_0..b_n`.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when `points` is empty.
    ///
    /// ```
    /// use exactcheck_core::bernstein::ShapeError;
    /// use exactcheck_core::bezier::BezierCurve;
    /// assert_eq!(BezierCurve::<f64>::try_new(vec![]), Err(ShapeError::Empty));
    /// ```
    pub fn try_new(points: Vec<Vec3<T>>) -> Result<Self, ShapeError> {
        if points.is_empty() {
            Err(ShapeError::Empty)
        } else {
            Ok(BezierCurve { points })
        }
    }

    /// The control points `b_0..b_n`.
    pub fn control_points(&self) -> &[Vec3<T>] {
        &self.points
    }

    /// The control points `b_0..b_n`, by value.
    pub fn into_control_points(self) -> Vec<Vec3<T>> {
        self.points
    }

    /// The degree `n` of the representation.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }
}

impl<T: Ring> BezierCurve<T> {
    /// The curve whose coordinate functions are `x`, `y`, `z`.
    ///
    /// # Errors
    /// [`ShapeError::LengthMismatch`] when their degrees differ (elevate first).
    pub fn from_coordinates(
        x: &Bernstein<T>,
        y: &Bernstein<T>,
        z: &Bernstein<T>,
    ) -> Result<Self, ShapeError> {
        let len = x.coeffs().len();
        for c in [y, z] {
            if c.coeffs().len() != len {
                return Err(ShapeError::LengthMismatch {
                    expected: len,
                    found: c.coeffs().len(),
                });
            }
        }
        let points = (0..len)
            .map(|i| {
                Vec3::new(
                    x.coeffs()[i].clone(),
                    y.coeffs()[i].clone(),
                    z.coeffs()[i].clone(),
                )
            })
            .collect();
        Ok(BezierCurve { points })
    }

    /// `x(t)` by de Casteljau's algorithm.
    pub fn eval(&self, t: &T) -> Vec3<T> {
        bernstein::casteljau(&self.points, &(T::one() - t), t)
    }

    /// De Casteljau subdivision at `t`: the pieces over `[0, t]` and `[t, 1]`, each
    /// reparametrized to `[0, 1]` (`left(u) = x(t u)`, `right(u) = x(t + (1-t) u)`).
    pub fn split(&self, t: &T) -> (Self, Self) {
        let (l, r) = bernstein::subdivide(&self.points, &(T::one() - t), t);
        (BezierCurve { points: l }, BezierCurve { points: r })
    }

    /// The hodograph `x'(t)`, a curve of degree `n - 1` with control vectors
    /// `n (b_{i+1} - b_i)`; for degree 0 the zero vector (degree 0).
    pub fn hodograph(&self) -> Self {
        BezierCurve {
            points: bernstein::differences(&self.points),
        }
    }

    /// The coordinate function `axis` (0 = x, 1 = y, 2 = z) as a Bernstein polynomial.
    ///
    /// # Panics
    /// When `axis > 2`.
    pub fn coordinate(&self, axis: usize) -> Bernstein<T> {
        Bernstein::new(self.points.iter().map(|p| p[axis].clone()).collect())
    }

    /// The three coordinate functions.
    pub fn coordinates(&self) -> [Bernstein<T>; 3] {
        [self.coordinate(0), self.coordinate(1), self.coordinate(2)]
    }

    /// The scalar polynomial `a . x(t)` (coefficients `a . b_i`), e.g. `N . V(t)` in the claim list.
    pub fn dot(&self, a: &Vec3<T>) -> Bernstein<T> {
        Bernstein::new(self.points.iter().map(|p| a.dot(p)).collect())
    }

    /// The same curve as a rational curve with all weights 1 (control vectors `(1, b_i)`).
    pub fn to_rational(&self) -> RationalBezierCurve<T> {
        RationalBezierCurve {
            control: self.points.iter().map(Hom4::from_point).collect(),
        }
    }
}

impl<T: Field> BezierCurve<T> {
    /// Degree elevation `n -> n+1` (the same curve):
    /// `b'_i = (i b_{i-1} + (n+1-i) b_i) / (n+1)`.
    pub fn elevate(&self) -> Self {
        let n1 = self.points.len() as u64;
        BezierCurve {
            points: bernstein::div_all(&bernstein::elevate_scaled(&self.points), n1),
        }
    }

    /// Degree elevation `n -> n+r` (the same curve), in one step.
    pub fn elevate_by(&self, r: usize) -> Self {
        BezierCurve {
            points: bernstein::elevate_by(&self.points, r),
        }
    }
}

/// A rational Bezier curve in homogeneous form: control vectors `(w_k, w_k r_k)` in [`Hom4`], the
/// curve `t -> sum_k B_k^n(t) (w_k, w_k r_k)` of projective 3-space, whose Cartesian form is
/// `C(t) = sum B_k w_k r_k / sum B_k w_k`.
///
/// A control vector with `w_k = 0` is a point at infinity (a direction), allowed.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RationalBezierCurve<T> {
    control: Vec<Hom4<T>>,
}

impl<T> RationalBezierCurve<T> {
    /// The curve with homogeneous control vectors `(w_k, w_k r_k)`, k = 0..n.
    ///
    /// # Panics
    /// When `control` is empty; [`RationalBezierCurve::try_new`] reports it instead.
    pub fn new(control: Vec<Hom4<T>>) -> Self {
        Self::try_new(control).expect("a rational Bezier curve needs at least one control vector")
    }

    /// The curve with homogeneous control vectors `(w_k, w_k r_k)`, k = 0..n.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when `control` is empty.
    ///
    /// ```
    /// use exactcheck_core::bernstein::ShapeError;
    /// use exactcheck_core::bezier::RationalBezierCurve;
    /// assert_eq!(RationalBezierCurve::<f64>::try_new(vec![]), Err(ShapeError::Empty));
    /// ```
    pub fn try_new(control: Vec<Hom4<T>>) -> Result<Self, ShapeError> {
        if control.is_empty() {
            Err(ShapeError::Empty)
        } else {
            Ok(RationalBezierCurve { control })
        }
    }

    /// The homogeneous control vectors `(w_k, w_k r_k)`.
    pub fn control(&self) -> &[Hom4<T>] {
        &self.control
    }

    /// The homogeneous control vectors, by value.
    pub fn into_control(self) -> Vec<Hom4<T>> {
        self.control
    }

    /// The degree `n` of the representation.
    pub fn degree(&self) -> usize {
        self.control.len() - 1
    }
}

impl<T: Ring> RationalBezierCurve<T> {
    /// The curve with weights `w_k` and control points `r_k`: control vectors `(w_k, w_k r_k)`.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when there are no weights, [`ShapeError::LengthMismatch`] when the
    /// numbers of weights and points differ.
    ///
    /// ```
    /// use exactcheck_core::bernstein::ShapeError;
    /// use exactcheck_core::bezier::RationalBezierCurve;
    /// use exactcheck_core::Vec3;
    /// let r = RationalBezierCurve::from_weights_points(&[1.0, 2.0], &[Vec3::from_i64(1, 0, 0)]);
    /// assert_eq!(r, Err(ShapeError::LengthMismatch { expected: 2, found: 1 }));
    /// ```
    pub fn from_weights_points(weights: &[T], points: &[Vec3<T>]) -> Result<Self, ShapeError> {
        if weights.len() != points.len() {
            return Err(ShapeError::LengthMismatch {
                expected: weights.len(),
                found: points.len(),
            });
        }
        Self::try_new(
            weights
                .iter()
                .zip(points)
                .map(|(w, p)| Hom4::from_weighted(w, p))
                .collect(),
        )
    }

    /// The curve whose four homogeneous coordinate functions are `coords`
    /// (`coords[0]` is the weight polynomial).
    ///
    /// # Errors
    /// [`ShapeError::LengthMismatch`] when their degrees differ (elevate first).
    pub fn from_hom_coordinates(coords: &[Bernstein<T>; 4]) -> Result<Self, ShapeError> {
        let len = coords[0].coeffs().len();
        for c in &coords[1..] {
            if c.coeffs().len() != len {
                return Err(ShapeError::LengthMismatch {
                    expected: len,
                    found: c.coeffs().len(),
                });
            }
        }
        let control = (0..len)
            .map(|k| Hom4(core::array::from_fn(|a| coords[a].coeffs()[k].clone())))
            .collect();
        Ok(RationalBezierCurve { control })
    }

    /// The homogeneous point `sum_k B_k^n(t) (w_k, w_k r_k)` by de Casteljau's algorithm.
    pub fn eval_hom(&self, t: &T) -> Hom4<T> {
        bernstein::casteljau(&self.control, &(T::one() - t), t)
    }

    /// The weights `w_k` (first coordinates of the control vectors).
    pub fn weights(&self) -> Vec<T> {
        self.control.iter().map(|c| c.0[0].clone()).collect()
    }

    /// The weight polynomial `w(t) = sum_k B_k^n(t) w_k`, the denominator of `C(t)`.
    pub fn weight_polynomial(&self) -> Bernstein<T> {
        self.hom_coordinate(0)
    }

    /// The homogeneous coordinate function `a` (0 = weight, 1..=3 = weighted x, y, z).
    ///
    /// # Panics
    /// When `a > 3`.
    pub fn hom_coordinate(&self, a: usize) -> Bernstein<T> {
        Bernstein::new(self.control.iter().map(|c| c.0[a].clone()).collect())
    }

    /// The four homogeneous coordinate functions.
    pub fn hom_coordinates(&self) -> [Bernstein<T>; 4] {
        core::array::from_fn(|a| self.hom_coordinate(a))
    }

    /// De Casteljau subdivision at `t`: the pieces over `[0, t]` and `[t, 1]`, each
    /// reparametrized to `[0, 1]`.
    pub fn split(&self, t: &T) -> (Self, Self) {
        let (l, r) = bernstein::subdivide(&self.control, &(T::one() - t), t);
        (
            RationalBezierCurve { control: l },
            RationalBezierCurve { control: r },
        )
    }

    /// Division-free degree elevation `n -> n+1`: `(n+1)` times the control vectors of
    /// [`RationalBezierCurve::elevate`], which is the same projective curve (all homogeneous
    /// points scaled by `n+1`), with weights `(n+1)` times as large.
    pub fn elevate_scaled(&self) -> Self {
        RationalBezierCurve {
            control: bernstein::elevate_scaled(&self.control),
        }
    }

    /// [`RationalBezierCurve::elevate_scaled`] `r` times: the same projective curve in degree
    /// `n + r`, homogeneous points scaled by `(n+1)(n+2)...(n+r)`.
    pub fn elevate_by_scaled(&self, r: usize) -> Self {
        RationalBezierCurve {
            control: bernstein::elevate_by_scaled(&self.control, r),
        }
    }

    /// The product `p(t) * (homogeneous curve)(t)` division-free, in the scaled basis:
    /// `e_k = sum_{i+j=k} C(m,i) C(n,j) p_i (w_j, w_j r_j)`, k = 0..m+n, which is `C(m+n,k)` times
    /// the control vector `k` of [`RationalBezierCurve::mul_bernstein`] (see
    /// [`crate::bernstein`] on the scaled basis).
    pub fn mul_bernstein_scaled(&self, p: &Bernstein<T>) -> Vec<Hom4<T>> {
        bernstein::product_scaled(p.coeffs(), &self.control)
    }

    /// The control vectors in the scaled basis: `C(n,k) (w_k, w_k r_k)`.
    pub fn to_scaled(&self) -> Vec<Hom4<T>> {
        bernstein::to_scaled(&self.control)
    }
}

impl<T: Field> RationalBezierCurve<T> {
    /// The Cartesian point `C(t) = sum B_k w_k r_k / sum B_k w_k`.
    ///
    /// # Errors
    /// [`ZeroDivisor`] where the weight polynomial vanishes (a point at infinity).
    pub fn eval(&self, t: &T) -> Result<Vec3<T>, ZeroDivisor> {
        self.eval_hom(t).to_point()
    }

    /// The control points `r_k = (w_k r_k) / w_k`; `None` where `w_k = 0`.
    pub fn points(&self) -> Vec<Option<Vec3<T>>> {
        self.control.iter().map(|c| c.to_point().ok()).collect()
    }

    /// Degree elevation `n -> n+1`, the same homogeneous curve (weights included):
    /// `(i c_{i-1} + (n+1-i) c_i) / (n+1)` on the control vectors.
    pub fn elevate(&self) -> Self {
        let n1 = self.control.len() as u64;
        RationalBezierCurve {
            control: bernstein::div_all(&bernstein::elevate_scaled(&self.control), n1),
        }
    }

    /// Degree elevation `n -> n+r`, the same homogeneous curve, in one step.
    pub fn elevate_by(&self, r: usize) -> Self {
        RationalBezierCurve {
            control: bernstein::elevate_by(&self.control, r),
        }
    }

    /// The homogeneous curve multiplied by the scalar polynomial `p` (degree m), of degree `m + n`
    /// by the product rule: control vectors
    /// `sum_{i+j=k} phi(m,n,i,j) p_i (w_j, w_j r_j)`. Where `p(t) != 0` it is the same
    /// projective point; the zeros of `p` become common zeros of all coordinates (base points).
    pub fn mul_bernstein(&self, p: &Bernstein<T>) -> Self {
        RationalBezierCurve {
            control: bernstein::product(p.coeffs(), &self.control),
        }
    }

    /// The curve from scaled-basis control vectors `e_k` (as returned by
    /// [`RationalBezierCurve::mul_bernstein_scaled`]): control vectors `e_k / C(n,k)`.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when `e` is empty.
    pub fn from_scaled(e: &[Hom4<T>]) -> Result<Self, ShapeError> {
        if e.is_empty() {
            return Err(ShapeError::Empty);
        }
        Ok(RationalBezierCurve {
            control: bernstein::from_scaled(e),
        })
    }
}

/// A tensor-product Bezier patch of degree `(m, n)` with homogeneous control vectors:
/// `S(u,v) = sum_{i=0}^m sum_{j=0}^n B_i^m(u) B_j^n(v) b_ij`, `b_ij` in [`Hom4`] (so rational
/// patches, with `b_ij = (w_ij, w_ij r_ij)`, and polynomial ones, with all weights 1).
///
/// The net is given by rows: row `i` holds `b_i0..b_in` (fixed `i`, the `v` direction).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TensorPatch<T> {
    cols: usize,
    net: Vec<Hom4<T>>,
}

impl<T> TensorPatch<T> {
    /// The patch with control net `net[i][j] = b_ij`.
    ///
    /// # Panics
    /// When the net is empty or ragged; [`TensorPatch::try_new`] reports it instead.
    pub fn new(net: Vec<Vec<Hom4<T>>>) -> Self {
        match Self::try_new(net) {
            Ok(p) => p,
            Err(e) => panic!("invalid control net: {e}"),
        }
    }

    /// The patch with control net `net[i][j] = b_ij`.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when there is no row or row 0 is empty, [`ShapeError::Ragged`]
    /// when a row's length differs from row 0's.
    ///
    /// ```
    /// use exactcheck_core::bernstein::ShapeError;
    /// use exactcheck_core::bezier::TensorPatch;
    /// use exactcheck_core::Hom4;
    /// let p = Hom4::new(1.0, 0.0, 0.0, 0.0);
    /// let net = vec![vec![p.clone(), p.clone()], vec![p]];
    /// assert_eq!(
    ///     TensorPatch::try_new(net),
    ///     Err(ShapeError::Ragged { row: 1, expected: 2, found: 1 })
    /// );
    /// ```
    pub fn try_new(net: Vec<Vec<Hom4<T>>>) -> Result<Self, ShapeError> {
        let cols = net.first().map_or(0, Vec::len);
        if cols == 0 {
            return Err(ShapeError::Empty);
        }
        if let Some((row, r)) = net.iter().enumerate().find(|(_, r)| r.len() != cols) {
            return Err(ShapeError::Ragged {
                row,
                expected: cols,
                found: r.len(),
            });
        }
        Ok(TensorPatch {
            cols,
            net: net.into_iter().flatten().collect(),
        })
    }

    /// The degrees `(m, n)`: `m` in `u` (rows), `n` in `v` (columns).
    pub fn degrees(&self) -> (usize, usize) {
        (self.net.len() / self.cols - 1, self.cols - 1)
    }

    /// The control vector `b_ij`.
    ///
    /// # Panics
    /// When `i > m` or `j > n`.
    pub fn control(&self, i: usize, j: usize) -> &Hom4<T> {
        assert!(j < self.cols, "column {j} out of range");
        &self.net[i * self.cols + j]
    }

    /// Row `i` of the net, `b_i0..b_in`: the control vectors of the curve `v -> S(u_i, v)`
    /// (of the boundary `S(0, v)` for `i = 0`, `S(1, v)` for `i = m`).
    ///
    /// # Panics
    /// When `i > m`.
    pub fn row(&self, i: usize) -> &[Hom4<T>] {
        &self.net[i * self.cols..(i + 1) * self.cols]
    }

    /// The four corner control vectors, which are the corner points:
    /// `[S(0,0), S(1,0), S(1,1), S(0,1)]` (counter-clockwise in the `(u, v)` square).
    pub fn corners(&self) -> [&Hom4<T>; 4] {
        let (m, n) = self.degrees();
        [
            self.control(0, 0),
            self.control(m, 0),
            self.control(m, n),
            self.control(0, n),
        ]
    }

    fn column(&self, j: usize) -> Vec<Hom4<T>>
    where
        T: Clone,
    {
        self.net
            .iter()
            .skip(j)
            .step_by(self.cols)
            .cloned()
            .collect()
    }
}

impl<T: Ring> TensorPatch<T> {
    /// The patch with weights `w_ij` and points `r_ij`: control vectors `(w_ij, w_ij r_ij)`.
    ///
    /// # Errors
    /// As [`TensorPatch::try_new`]; [`ShapeError::LengthMismatch`] when the numbers of rows
    /// differ, [`ShapeError::Ragged`] when a row of points is not as long as its row of weights.
    pub fn from_weights_points(
        weights: &[Vec<T>],
        points: &[Vec<Vec3<T>>],
    ) -> Result<Self, ShapeError> {
        if weights.len() != points.len() {
            return Err(ShapeError::LengthMismatch {
                expected: weights.len(),
                found: points.len(),
            });
        }
        let mut net = Vec::with_capacity(weights.len());
        for (row, (w, p)) in weights.iter().zip(points).enumerate() {
            if w.len() != p.len() {
                return Err(ShapeError::Ragged {
                    row,
                    expected: w.len(),
                    found: p.len(),
                });
            }
            net.push(
                w.iter()
                    .zip(p)
                    .map(|(w, p)| Hom4::from_weighted(w, p))
                    .collect(),
            );
        }
        Self::try_new(net)
    }

    /// The polynomial patch with control points `points[i][j]` (all weights 1).
    ///
    /// # Errors
    /// As [`TensorPatch::try_new`].
    pub fn from_points(points: &[Vec<Vec3<T>>]) -> Result<Self, ShapeError> {
        Self::try_new(
            points
                .iter()
                .map(|r| r.iter().map(Hom4::from_point).collect())
                .collect(),
        )
    }

    /// The homogeneous point `S(u, v)`: de Casteljau in `v` on every row, then in `u`.
    pub fn eval_hom(&self, u: &T, v: &T) -> Hom4<T> {
        self.v_curve(v).eval_hom(u)
    }

    /// The iso-curve at fixed `u`: the rational curve `v -> S(u, v)` of degree `n`
    /// (de Casteljau in `u` on every column).
    pub fn u_curve(&self, u: &T) -> RationalBezierCurve<T> {
        let s = T::one() - u;
        let control = (0..self.cols)
            .map(|j| bernstein::casteljau(&self.column(j), &s, u))
            .collect();
        RationalBezierCurve { control }
    }

    /// The iso-curve at fixed `v`: the rational curve `u -> S(u, v)` of degree `m`
    /// (de Casteljau in `v` on every row).
    pub fn v_curve(&self, v: &T) -> RationalBezierCurve<T> {
        let s = T::one() - v;
        let control = self
            .net
            .chunks(self.cols)
            .map(|r| bernstein::casteljau(r, &s, v))
            .collect();
        RationalBezierCurve { control }
    }

    /// The four boundary curves, read off the net without arithmetic, in the order
    /// `[u -> S(u,0), v -> S(1,v), u -> S(u,1), v -> S(0,v)]`: consecutive curves (cyclically)
    /// share the corners `S(1,0), S(1,1), S(0,1), S(0,0)`; each runs in its increasing parameter.
    pub fn boundary_curves(&self) -> [RationalBezierCurve<T>; 4] {
        let (m, n) = self.degrees();
        [
            RationalBezierCurve {
                control: self.column(0),
            },
            RationalBezierCurve {
                control: self.row(m).to_vec(),
            },
            RationalBezierCurve {
                control: self.column(n),
            },
            RationalBezierCurve {
                control: self.row(0).to_vec(),
            },
        ]
    }

    /// The same patch with the roles of `u` and `v` exchanged (`b'_ji = b_ij`).
    pub fn transpose(&self) -> Self {
        let net = (0..self.cols)
            .flat_map(|j| self.column(j))
            .collect::<Vec<_>>();
        TensorPatch {
            cols: self.net.len() / self.cols,
            net,
        }
    }
}

impl<T: Field> TensorPatch<T> {
    /// The Cartesian point `S(u, v)`.
    ///
    /// # Errors
    /// [`ZeroDivisor`] where the weight vanishes (a point at infinity).
    pub fn eval(&self, u: &T, v: &T) -> Result<Vec3<T>, ZeroDivisor> {
        self.eval_hom(u, v).to_point()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{ints, rational, Rng, Q};

    const CASES: usize = 200;

    fn q(n: i64) -> Q {
        Q::int(n)
    }

    fn qvec(rng: &mut Rng, r: i64) -> Vec3<Q> {
        Vec3::new(q(rng.int(-r, r)), q(rng.int(-r, r)), q(rng.int(-r, r)))
    }

    fn qcurve(rng: &mut Rng, n: usize) -> BezierCurve<Q> {
        BezierCurve::new((0..=n).map(|_| qvec(rng, 9)).collect())
    }

    /// A random rational curve with non-zero weights.
    fn qrational(rng: &mut Rng, n: usize) -> (Vec<Q>, Vec<Vec3<Q>>) {
        let w = (0..=n)
            .map(|_| q(rng.int(1, 5) * if rng.int(0, 3) == 0 { -1 } else { 1 }))
            .collect();
        let p = (0..=n).map(|_| qvec(rng, 9)).collect();
        (w, p)
    }

    fn basis<T: Ring>(n: usize, i: usize, t: &T) -> T {
        crate::scalar::from_u64::<T>(crate::scalar::binom(n, i))
            * t.pow(i as u32)
            * (T::one() - t).pow((n - i) as u32)
    }

    #[test]
    fn curve_eval_matches_direct_sum_and_coordinates() {
        let mut rng = Rng::new(21);
        for _ in 0..CASES {
            let n = rng.below(6);
            let pts: Vec<Vec3<f64>> = (0..=n)
                .map(|_| Vec3::from_i64(rng.int(-8, 8), rng.int(-8, 8), rng.int(-8, 8)))
                .collect();
            let c = BezierCurve::new(pts.clone());
            let t = rng.int(-4, 20) as f64 / 16.0;
            let mut direct = Vec3::zero();
            for (i, p) in pts.iter().enumerate() {
                direct = direct.add_scaled(&basis(n, i, &t), p);
            }
            let x = c.eval(&t);
            assert_eq!(x, direct);
            let [cx, cy, cz] = c.coordinates();
            assert_eq!(x, Vec3::new(cx.eval(&t), cy.eval(&t), cz.eval(&t)));
            assert_eq!(BezierCurve::from_coordinates(&cx, &cy, &cz).unwrap(), c);
        }
    }

    #[test]
    fn curve_elevation_and_split() {
        let mut rng = Rng::new(22);
        for _ in 0..CASES {
            let n = rng.below(6);
            let c = qcurve(&mut rng, n);
            let e = c.elevate();
            let r = rng.below(4);
            let er = c.elevate_by(r);
            assert_eq!(e.degree(), n + 1);
            assert_eq!(er.degree(), n + r);
            let t = rational(&mut rng, 5, 5);
            let (l, rt) = c.split(&t);
            for _ in 0..3 {
                let u = rational(&mut rng, 6, 4);
                assert_eq!(e.eval(&u), c.eval(&u));
                assert_eq!(er.eval(&u), c.eval(&u));
                assert_eq!(l.eval(&u), c.eval(&(t * u)));
                assert_eq!(rt.eval(&u), c.eval(&(t + (Q::one() - t) * u)));
            }
            // Split pieces meet at C(t).
            assert_eq!(l.control_points()[n], rt.control_points()[0]);
            assert_eq!(l.control_points()[n], c.eval(&t));
        }
    }

    #[test]
    fn split_halves_f64_exact() {
        let mut rng = Rng::new(23);
        for _ in 0..CASES {
            let n = rng.below(6);
            let pts = (0..=n)
                .map(|_| Vec3::from_i64(rng.int(-8, 8), rng.int(-8, 8), rng.int(-8, 8)))
                .collect();
            let c: BezierCurve<f64> = BezierCurve::new(pts);
            let (l, r) = c.split(&0.5);
            for k in 0..=8 {
                let u = k as f64 / 8.0;
                assert_eq!(l.eval(&u), c.eval(&(u / 2.0)));
                assert_eq!(r.eval(&u), c.eval(&(0.5 + u / 2.0)));
            }
        }
    }

    #[test]
    fn hodograph_is_the_derivative() {
        let mut rng = Rng::new(24);
        for _ in 0..CASES {
            let n = rng.below(7);
            let c = qcurve(&mut rng, n);
            let h = c.hodograph();
            assert_eq!(h.degree(), n.saturating_sub(1));
            for (axis, coord) in c.coordinates().iter().enumerate() {
                assert_eq!(h.coordinate(axis), coord.derivative());
            }
            let a = qvec(&mut rng, 5);
            assert_eq!(c.dot(&a).eval(&q(3)), a.dot(&c.eval(&q(3))));
        }
        let point = BezierCurve::new(vec![Vec3::from_i64(1, 2, 3)]);
        assert_eq!(point.hodograph().control_points(), &[Vec3::<f64>::zero()]);
    }

    #[test]
    fn rational_eval_is_the_quotient() {
        let mut rng = Rng::new(25);
        for _ in 0..CASES {
            let n = rng.below(6);
            let (w, p) = qrational(&mut rng, n);
            let c = RationalBezierCurve::from_weights_points(&w, &p).unwrap();
            assert_eq!(c.weights(), w);
            assert_eq!(c.points(), p.iter().cloned().map(Some).collect::<Vec<_>>());
            let t = rational(&mut rng, 6, 5);
            let mut num = Vec3::zero();
            let mut den = Q::zero();
            for k in 0..=n {
                let bw = basis(n, k, &t) * w[k];
                num = num.add_scaled(&bw, &p[k]);
                den += bw;
            }
            let h = c.eval_hom(&t);
            assert_eq!(h.0[0], c.weight_polynomial().eval(&t));
            for a in 1..4 {
                assert_eq!(h.0[a], c.hom_coordinate(a).eval(&t));
            }
            match c.eval(&t) {
                Ok(x) => assert_eq!(x, num.div_scalar(&den).unwrap()),
                Err(ZeroDivisor) => assert!(den.is_zero()),
            }
            assert_eq!(
                RationalBezierCurve::from_hom_coordinates(&c.hom_coordinates()).unwrap(),
                c
            );
        }
    }

    #[test]
    fn rational_eval_f64_tolerance() {
        let mut rng = Rng::new(26);
        for _ in 0..CASES {
            let n = rng.below(6);
            let w: Vec<f64> = (0..=n).map(|_| rng.int(1, 9) as f64 / 3.0).collect();
            let p: Vec<Vec3<f64>> = (0..=n)
                .map(|_| Vec3::new(rng.int(-9, 9) as f64 / 7.0, rng.int(-9, 9) as f64, 0.1))
                .collect();
            let c = RationalBezierCurve::from_weights_points(&w, &p).unwrap();
            for k in 0..=10 {
                let t = k as f64 / 10.0;
                let (mut num, mut den) = (Vec3::zero(), 0.0);
                for i in 0..=n {
                    let bw = basis(n, i, &t) * w[i];
                    num = num.add_scaled(&bw, &p[i]);
                    den += bw;
                }
                let x = c.eval(&t).unwrap();
                let y = num.div_scalar(&den).unwrap();
                assert!((&x - &y).norm_squared() < 1e-20, "{x:?} vs {y:?}");
            }
        }
    }

    #[test]
    fn zero_weights_are_points_at_infinity() {
        // w = (1, -1): the weight polynomial 1 - 2t vanishes at t = 1/2.
        let c = RationalBezierCurve::from_weights_points(
            &[q(1), q(0), q(-1)],
            &[
                Vec3::from_i64(0, 0, 0),
                Vec3::from_i64(1, 1, 1),
                Vec3::from_i64(2, 0, 0),
            ],
        )
        .unwrap();
        assert_eq!(c.points()[1], None);
        assert_eq!(c.eval(&Q::new(1, 2)), Err(ZeroDivisor));
        assert_eq!(c.eval(&q(0)), Ok(Vec3::zero()));
        assert_eq!(c.eval(&q(1)), Ok(Vec3::from_i64(2, 0, 0)));
        assert_eq!(
            RationalBezierCurve::<Q>::from_weights_points(&[], &[]),
            Err(ShapeError::Empty)
        );
    }

    #[test]
    fn rational_elevation_split_and_scaling() {
        let mut rng = Rng::new(27);
        for _ in 0..CASES {
            let n = rng.below(5);
            let (w, p) = qrational(&mut rng, n);
            let c = RationalBezierCurve::from_weights_points(&w, &p).unwrap();
            let e = c.elevate();
            let es = c.elevate_scaled();
            let r = rng.below(3);
            let er = c.elevate_by(r);
            let ers = c.elevate_by_scaled(r);
            let t = rational(&mut rng, 5, 5);
            let (l, rt) = c.split(&t);
            for _ in 0..3 {
                let u = rational(&mut rng, 6, 4);
                let h = c.eval_hom(&u);
                assert_eq!(e.eval_hom(&u), h);
                assert_eq!(er.eval_hom(&u), h);
                if !h.is_zero() {
                    assert!(es.eval_hom(&u).proj_eq(&h));
                    assert!(ers.eval_hom(&u).proj_eq(&h));
                }
                assert_eq!(l.eval_hom(&u), c.eval_hom(&(t * u)));
                assert_eq!(rt.eval_hom(&u), c.eval_hom(&(t + (Q::one() - t) * u)));
            }
            assert_eq!(es.control()[0], c.control()[0].scale(&q(n as i64 + 1)));
        }
    }

    #[test]
    fn mul_bernstein_is_the_pointwise_product() {
        let mut rng = Rng::new(28);
        for _ in 0..CASES {
            let (m, n) = (rng.below(4), rng.below(4));
            let (w, pts) = qrational(&mut rng, n);
            let c = RationalBezierCurve::from_weights_points(&w, &pts).unwrap();
            let p = Bernstein::new(ints(&mut rng, m + 1, 6).into_iter().map(q).collect());
            let pc = c.mul_bernstein(&p);
            assert_eq!(pc.degree(), m + n);
            let scaled = c.mul_bernstein_scaled(&p);
            assert_eq!(RationalBezierCurve::from_scaled(&scaled).unwrap(), pc);
            assert_eq!(pc.to_scaled(), scaled);
            for _ in 0..3 {
                let t = rational(&mut rng, 5, 4);
                assert_eq!(pc.eval_hom(&t), c.eval_hom(&t).scale(&p.eval(&t)));
            }
            // Each coordinate is the scalar product rule.
            for a in 0..4 {
                assert_eq!(pc.hom_coordinate(a), p.mul(&c.hom_coordinate(a)));
            }
        }
    }

    fn qpatch(rng: &mut Rng, m: usize, n: usize) -> TensorPatch<Q> {
        let w: Vec<Vec<Q>> = (0..=m)
            .map(|_| (0..=n).map(|_| q(rng.int(1, 4))).collect())
            .collect();
        let p: Vec<Vec<Vec3<Q>>> = (0..=m)
            .map(|_| (0..=n).map(|_| qvec(rng, 9)).collect())
            .collect();
        TensorPatch::from_weights_points(&w, &p).unwrap()
    }

    #[test]
    fn patch_iso_curves_agree_with_eval() {
        let mut rng = Rng::new(29);
        for _ in 0..CASES {
            let (m, n) = (rng.below(4), rng.below(4));
            let s = qpatch(&mut rng, m, n);
            assert_eq!(s.degrees(), (m, n));
            let (u, v) = (rational(&mut rng, 5, 4), rational(&mut rng, 5, 4));
            let h = s.eval_hom(&u, &v);
            // Direct double sum.
            let mut direct = Hom4::new(q(0), q(0), q(0), q(0));
            for i in 0..=m {
                for j in 0..=n {
                    let b = basis(m, i, &u) * basis(n, j, &v);
                    direct = direct.add(&s.control(i, j).scale(&b));
                }
            }
            assert_eq!(h, direct);
            let uc = s.u_curve(&u);
            let vc = s.v_curve(&v);
            assert_eq!(uc.degree(), n);
            assert_eq!(vc.degree(), m);
            assert_eq!(uc.eval_hom(&v), h);
            assert_eq!(vc.eval_hom(&u), h);
            assert_eq!(s.transpose().eval_hom(&v, &u), h);
            assert_eq!(s.eval(&u, &v), h.to_point());
            // Boundary curves are the iso-curves at the edges.
            let [b0, b1, b2, b3] = s.boundary_curves();
            assert_eq!(b0, s.v_curve(&q(0)));
            assert_eq!(b1, s.u_curve(&q(1)));
            assert_eq!(b2, s.v_curve(&q(1)));
            assert_eq!(b3, s.u_curve(&q(0)));
            let corners = s.corners();
            assert_eq!(*corners[0], s.eval_hom(&q(0), &q(0)));
            assert_eq!(*corners[1], s.eval_hom(&q(1), &q(0)));
            assert_eq!(*corners[2], s.eval_hom(&q(1), &q(1)));
            assert_eq!(*corners[3], s.eval_hom(&q(0), &q(1)));
        }
    }

    #[test]
    fn patch_f64_polynomial() {
        // A bilinear patch of integer points at dyadic parameters: exact.
        let s = TensorPatch::from_points(&[
            vec![Vec3::from_i64(0, 0, 0), Vec3::from_i64(0, 4, 1)],
            vec![Vec3::from_i64(4, 0, 2), Vec3::from_i64(4, 4, -3)],
        ])
        .unwrap();
        let x = s.eval(&0.25, &0.5).unwrap();
        // z = (1-u)(v) + 2u(1-v) - 3uv at (1/4, 1/2).
        assert_eq!(x, Vec3::new(1.0, 2.0, 0.375 + 0.25 - 0.375));
    }

    #[test]
    fn malformed_nets_are_rejected() {
        let h = Hom4::new(q(1), q(0), q(0), q(0));
        assert_eq!(TensorPatch::<Q>::try_new(vec![]), Err(ShapeError::Empty));
        assert_eq!(
            TensorPatch::<Q>::try_new(vec![vec![]]),
            Err(ShapeError::Empty)
        );
        assert_eq!(
            TensorPatch::try_new(vec![vec![h.clone()], vec![h.clone(), h.clone()]]),
            Err(ShapeError::Ragged {
                row: 1,
                expected: 1,
                found: 2
            })
        );
        assert_eq!(
            TensorPatch::from_weights_points(&[vec![q(1)]], &[]),
            Err(ShapeError::LengthMismatch {
                expected: 1,
                found: 0
            })
        );
        assert_eq!(
            TensorPatch::from_weights_points(&[vec![q(1)]], &[vec![]]),
            Err(ShapeError::Ragged {
                row: 0,
                expected: 1,
                found: 0
            })
        );
        assert_eq!(BezierCurve::<Q>::try_new(vec![]), Err(ShapeError::Empty));
        let x = Bernstein::new(vec![q(1), q(2)]);
        assert_eq!(
            BezierCurve::from_coordinates(&x, &x, &Bernstein::new(vec![q(1)])),
            Err(ShapeError::LengthMismatch {
                expected: 2,
                found: 1
            })
        );
        assert_eq!(TensorPatch::new(vec![vec![h.clone()]]).degrees(), (0, 0));
    }
}
