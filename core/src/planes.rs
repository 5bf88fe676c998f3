//! The intersection line of two planes, exactly and without unit normals.
//!
//! # The planes
//! A plane in normal form is a normal `n != 0` and a point `P`: the points `x` with
//! `n . x = d`, `d = n . P` (stored as [`Plane`]'s `normal . x + d' = 0` with `d' = -d`). The normal need not have length 1; every formula here is a
//! polynomial (or a quotient of polynomials) in the coordinates, so it runs over the rationals,
//! the square-root field, polynomials and `f64` alike.
//!
//! # The line
//! Two planes `n1 . x = d1`, `n2 . x = d2` meet in a line exactly when `q = n1 x n2 != 0`; `q` is
//! orthogonal to both normals, so it is the line's direction. This module's orientation is
//! **`q = n1 x n2`**; the published JavaScript (`float::wabis`) uses `n2 x n1 = -q`, which
//! describes the same line.
//!
//! # The point nearest the origin
//! Look for the point in the plane through the origin spanned by the normals,
//! `Q = s1 n1 + s2 n2`. Substituting into the two plane equations gives the linear system
//! ```text
//! s1 |n1|^2   + s2 (n1.n2) = d1
//! s1 (n1.n2)  + s2 |n2|^2  = d2
//! ```
//! whose Gram determinant is `G = |n1|^2 |n2|^2 - (n1.n2)^2 = |n1 x n2|^2` (Lagrange's
//! identity), non-zero exactly when the planes are not parallel. Cramer's rule gives
//! ```text
//! Q = [ (d1 |n2|^2 - d2 (n1.n2)) n1 + (d2 |n1|^2 - d1 (n1.n2)) n2 ] / |n1 x n2|^2.
//! ```
//! `Q` lies on both planes by construction (it solves the system). It lies in `span(n1, n2)`,
//! the plane through the origin orthogonal to `q`, so `Q . q = 0`; for any point `Q + lambda q`
//! of the line, `|Q + lambda q|^2 = |Q|^2 + lambda^2 |q|^2 >= |Q|^2`: `Q` is the point of the
//! line nearest the origin, and the unique one.
//!
//! With unit normals and `r = n1.n2` the formula becomes the published one,
//! `s1 = (d1 - r d2)/(1 - r^2)`, `s2 = (d2 - r d1)/(1 - r^2)`; without unit normals the published
//! one is wrong (the claim `planes.wabis` proves both statements).
//!
//! # Forms
//! * [`nearest_point_hom`]: the division-free homogeneous form `(numerator, G)` for any
//!   [`Ring`], so that the construction can be proved over polynomials;
//! * [`intersect`]: the divided form for an [`OrderedField`], with the cases decided exactly (for
//!   exact fields): [`PlanePair::Line`], [`PlanePair::Parallel`], [`PlanePair::Coincident`],
//!   [`PlanePair::ZeroNormal`].
//!
//! Hand-written because it is three lines of vector algebra whose derivation is the point; no
//! geometry crate computes it over exact or symbolic scalars.

use crate::scalar::{OrderedField, Ring};
use crate::vector::Vec3;

/// A plane `normal . x + d = 0`, the one plane type of the workspace: built from its
/// coefficients ([`Plane::new`], `a x + b y + c z + d = 0`, as the ruled surfaces and cone
/// sections use it) or from a normal and a point ([`Plane::through`], `d = -normal . point`, as
/// the plane-plane intersection takes it).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Plane<T> {
    /// The normal `N = (a, b, c)` (any length; zero is rejected by [`intersect`]).
    pub normal: Vec3<T>,
    /// The constant `d`.
    pub d: T,
}

impl<T: Ring> Plane<T> {
    /// The plane `a x + b y + c z + d = 0`.
    pub fn new(a: T, b: T, c: T, d: T) -> Self {
        Plane {
            normal: Vec3::new(a, b, c),
            d,
        }
    }

    /// The plane through `point` with normal `normal`: `d = -normal . point`.
    pub fn through(normal: Vec3<T>, point: &Vec3<T>) -> Self {
        let d = normal.dot(point).neg_ref();
        Plane { normal, d }
    }

    /// The plane `z = 0`.
    pub fn z0() -> Self {
        Plane::new(T::zero(), T::zero(), T::one(), T::zero())
    }

    /// The right-hand side `-d` of the plane equation written `normal . x = -d`.
    pub fn offset(&self) -> T {
        self.d.neg_ref()
    }

    /// `N . x + d`: zero exactly when `x` lies on the plane.
    pub fn value(&self, x: &Vec3<T>) -> T {
        self.normal.dot(x) + &self.d
    }

    /// The value at a homogeneous point `numerator / denominator`, multiplied by the
    /// denominator: `N . numerator + d denominator`.
    pub fn value_hom(&self, numerator: &Vec3<T>, denominator: &T) -> T {
        self.normal.dot(numerator) + &self.d.mul_ref(denominator)
    }
}

/// The direction `n1 x n2` of the intersection line (this module's orientation; the published
/// JavaScript uses `n2 x n1`).
pub fn direction<T: Ring>(p1: &Plane<T>, p2: &Plane<T>) -> Vec3<T> {
    p1.normal.cross(&p2.normal)
}

/// The point of the line nearest the origin in homogeneous, division-free form
/// `(numerator, denominator)` with
/// `numerator = (d1 |n2|^2 - d2 (n1.n2)) n1 + (d2 |n1|^2 - d1 (n1.n2)) n2` and
/// `denominator = |n1 x n2|^2` (module documentation). Valid over any ring; the point is
/// `numerator / denominator` when the denominator is invertible.
pub fn nearest_point_hom<T: Ring>(p1: &Plane<T>, p2: &Plane<T>) -> (Vec3<T>, T) {
    let (n1, n2) = (&p1.normal, &p2.normal);
    let (d1, d2) = (p1.offset(), p2.offset());
    let r = n1.dot(n2);
    let s1 = d1.mul_ref(&n2.norm_squared()) - d2.mul_ref(&r);
    let s2 = d2.mul_ref(&n1.norm_squared()) - d1.mul_ref(&r);
    let numerator = n1.scale(&s1).add_scaled(&s2, n2);
    (numerator, n1.cross(n2).norm_squared())
}

/// Which plane of a pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Which {
    /// The first plane.
    First,
    /// The second plane.
    Second,
}

impl Which {
    /// The index of the plane (0 or 1).
    pub fn index(self) -> usize {
        match self {
            Which::First => 0,
            Which::Second => 1,
        }
    }
}

/// How two planes meet.
#[derive(Clone, Debug, PartialEq)]
pub enum PlanePair<T> {
    /// In a line: `point + lambda direction`.
    Line {
        /// The point of the line nearest the origin.
        point: Vec3<T>,
        /// `n1 x n2`.
        direction: Vec3<T>,
    },
    /// Parallel and distinct: no common point.
    Parallel,
    /// The same plane.
    Coincident,
    /// A normal is the zero vector (not a plane); the first such one is named.
    ZeroNormal {
        /// The plane with the zero normal.
        which: Which,
    },
}

/// The intersection of two planes, every case decided by exact zero tests (for exact fields).
///
/// Parallel normals give [`PlanePair::Coincident`] when the two equations are proportional
/// (`d2 n1 = d1 n2`: with `n2 = k n1` this is `d2 = k d1`, and the second plane
/// `k (n1 . x) + d2 = 0` is then the first), else [`PlanePair::Parallel`]. The normals are parallel exactly when the
/// denominator `G = |n1 x n2|^2` is zero: in an ordered field a sum of squares vanishes only
/// when every term does. Deciding on `G` itself (rather than on `n1 x n2`) means the division
/// that follows can never meet a zero divisor, also in `f64` where `G` may underflow to 0 for a
/// tiny non-zero cross product (that case is then reported as parallel). Over fields that are
/// not ordered (integers modulo p) `G` can vanish for non-parallel normals, and the point
/// nearest the origin is not defined; hence the `OrderedField` bound.
pub fn intersect<T: OrderedField>(p1: &Plane<T>, p2: &Plane<T>) -> PlanePair<T> {
    if p1.normal.is_zero() {
        return PlanePair::ZeroNormal {
            which: Which::First,
        };
    }
    if p2.normal.is_zero() {
        return PlanePair::ZeroNormal {
            which: Which::Second,
        };
    }
    let (numerator, g) = nearest_point_hom(p1, p2);
    if g.is_zero() {
        return if p1.normal.scale(&p2.d) == p2.normal.scale(&p1.d) {
            PlanePair::Coincident
        } else {
            PlanePair::Parallel
        };
    }
    let point = numerator
        .div_scalar(&g)
        .expect("G = |n1 x n2|^2 was just tested to be non-zero");
    PlanePair::Line {
        point,
        direction: direction(p1, p2),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plane(n: [i64; 3], p: [i64; 3]) -> Plane<f64> {
        Plane::through(
            Vec3::from_i64(n[0], n[1], n[2]),
            &Vec3::from_i64(p[0], p[1], p[2]),
        )
    }

    #[test]
    fn non_unit_normals_give_the_nearest_point() {
        // x = 1 (normal 2 e_x) and x + y = 1: the line x = 1, y = 0, nearest the origin at (1, 0, 0).
        let a = plane([2, 0, 0], [1, 0, 0]);
        let b = plane([1, 1, 0], [0, 1, 0]);
        match intersect(&a, &b) {
            PlanePair::Line { point, direction } => {
                assert_eq!(point, Vec3::new(1.0, 0.0, 0.0));
                assert_eq!(direction, Vec3::new(0.0, 0.0, 2.0));
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn an_underflowing_gram_determinant_is_not_a_division_by_zero() {
        // n1 x n2 = (0, 0, 1e-170) is not zero in f64, but |n1 x n2|^2 = 1e-340 underflows to 0.
        // The old decision on n1 x n2 went on to divide by G = 0 and panicked in `expect`; the
        // decision on G reports the (numerically) parallel planes instead.
        let a = Plane::through(Vec3::new(1e-170, 0.0, 0.0), &Vec3::zero());
        let b = Plane::through(Vec3::new(0.0, 1.0, 0.0), &Vec3::zero());
        assert!(!direction(&a, &b).is_zero());
        assert_eq!(intersect(&a, &b), PlanePair::Coincident);
    }

    #[test]
    fn degenerate_cases_are_typed() {
        let a = plane([1, 2, 3], [0, 0, 1]);
        assert_eq!(
            intersect(&a, &plane([2, 4, 6], [3, 0, 0])),
            PlanePair::Coincident
        );
        assert_eq!(
            intersect(&a, &plane([-1, -2, -3], [0, 0, 0])),
            PlanePair::Parallel
        );
        assert_eq!(
            intersect(&plane([0, 0, 0], [1, 1, 1]), &a),
            PlanePair::ZeroNormal {
                which: Which::First
            }
        );
        assert_eq!(
            intersect(&a, &plane([0, 0, 0], [1, 1, 1])),
            PlanePair::ZeroNormal {
                which: Which::Second
            }
        );
    }
}
