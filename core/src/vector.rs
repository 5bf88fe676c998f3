//! Generic vectors: Cartesian 3-vectors with dot and cross products, and homogeneous 4-vectors
//! (points of projective 3-space) with projective equality.

use crate::scalar::{Field, Ring};
use core::ops::{Add, Index, Neg, Sub};

/// A 3-vector `(x, y, z)` over a ring.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Default)]
pub struct Vec3<T> {
    /// First coordinate.
    pub x: T,
    /// Second coordinate.
    pub y: T,
    /// Third coordinate.
    pub z: T,
}

impl<T> Vec3<T> {
    /// The vector `(x, y, z)`.
    pub const fn new(x: T, y: T, z: T) -> Self {
        Vec3 { x, y, z }
    }
    /// The coordinates as an array.
    pub fn into_array(self) -> [T; 3] {
        [self.x, self.y, self.z]
    }
    /// Applies `f` to each coordinate.
    pub fn map<U>(&self, mut f: impl FnMut(&T) -> U) -> Vec3<U> {
        Vec3::new(f(&self.x), f(&self.y), f(&self.z))
    }
}

impl<T: Ring> Vec3<T> {
    /// The zero vector.
    pub fn zero() -> Self {
        Vec3::new(T::zero(), T::zero(), T::zero())
    }
    /// The vector of three integers.
    pub fn from_i64(x: i64, y: i64, z: i64) -> Self {
        Vec3::new(T::from_i64(x), T::from_i64(y), T::from_i64(z))
    }
    /// The dot product `self . rhs`.
    pub fn dot(&self, rhs: &Self) -> T {
        self.x.mul_ref(&rhs.x) + self.y.mul_ref(&rhs.y) + self.z.mul_ref(&rhs.z)
    }
    /// The cross product `self x rhs`.
    pub fn cross(&self, rhs: &Self) -> Self {
        Vec3::new(
            self.y.mul_ref(&rhs.z) - self.z.mul_ref(&rhs.y),
            self.z.mul_ref(&rhs.x) - self.x.mul_ref(&rhs.z),
            self.x.mul_ref(&rhs.y) - self.y.mul_ref(&rhs.x),
        )
    }
    /// `|self|^2`.
    pub fn norm_squared(&self) -> T {
        self.dot(self)
    }
    /// `k * self`.
    pub fn scale(&self, k: &T) -> Self {
        self.map(|c| c.mul_ref(k))
    }
    /// Whether every coordinate is zero.
    pub fn is_zero(&self) -> bool {
        self.x.is_zero() && self.y.is_zero() && self.z.is_zero()
    }
    /// `self + k * rhs`, the workhorse of linear combinations.
    pub fn add_scaled(&self, k: &T, rhs: &Self) -> Self {
        Vec3::new(
            self.x.add_ref(&k.mul_ref(&rhs.x)),
            self.y.add_ref(&k.mul_ref(&rhs.y)),
            self.z.add_ref(&k.mul_ref(&rhs.z)),
        )
    }
}

impl<T: Field> Vec3<T> {
    /// `self / k`, or the zero-divisor error.
    pub fn div_scalar(&self, k: &T) -> Result<Self, crate::scalar::ZeroDivisor> {
        let inv = k.inv()?;
        Ok(self.scale(&inv))
    }
}

impl<T: Ring> Add for &Vec3<T> {
    type Output = Vec3<T>;
    fn add(self, rhs: Self) -> Vec3<T> {
        Vec3::new(
            self.x.add_ref(&rhs.x),
            self.y.add_ref(&rhs.y),
            self.z.add_ref(&rhs.z),
        )
    }
}

impl<T: Ring> Sub for &Vec3<T> {
    type Output = Vec3<T>;
    fn sub(self, rhs: Self) -> Vec3<T> {
        Vec3::new(
            self.x.sub_ref(&rhs.x),
            self.y.sub_ref(&rhs.y),
            self.z.sub_ref(&rhs.z),
        )
    }
}

impl<T: Ring> Add for Vec3<T> {
    type Output = Vec3<T>;
    fn add(self, rhs: Self) -> Vec3<T> {
        &self + &rhs
    }
}

impl<T: Ring> Sub for Vec3<T> {
    type Output = Vec3<T>;
    fn sub(self, rhs: Self) -> Vec3<T> {
        &self - &rhs
    }
}

impl<T: Ring> Neg for &Vec3<T> {
    type Output = Vec3<T>;
    fn neg(self) -> Vec3<T> {
        self.map(|c| c.neg_ref())
    }
}

impl<T> Index<usize> for Vec3<T> {
    type Output = T;
    fn index(&self, i: usize) -> &T {
        match i {
            0 => &self.x,
            1 => &self.y,
            2 => &self.z,
            _ => panic!("Vec3 index {i} out of range 0..3"),
        }
    }
}

/// A homogeneous 4-vector `(p0, p1, p2, p3)`: the point `(p1, p2, p3) / p0` of projective 3-space
/// when `p0 != 0`, a point at infinity when `p0 = 0`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Hom4<T>(pub [T; 4]);

impl<T: Ring> Hom4<T> {
    /// The vector `(p0, p1, p2, p3)`.
    pub fn new(p0: T, p1: T, p2: T, p3: T) -> Self {
        Hom4([p0, p1, p2, p3])
    }
    /// The homogeneous form `(1, x, y, z)` of a Cartesian point.
    pub fn from_point(p: &Vec3<T>) -> Self {
        Hom4([T::one(), p.x.clone(), p.y.clone(), p.z.clone()])
    }
    /// The homogeneous form `(w, w x, w y, w z)` of a weighted point.
    pub fn from_weighted(w: &T, p: &Vec3<T>) -> Self {
        Hom4([w.clone(), w.mul_ref(&p.x), w.mul_ref(&p.y), w.mul_ref(&p.z)])
    }
    /// Whether all four coordinates are zero (no projective point).
    pub fn is_zero(&self) -> bool {
        self.0.iter().all(Ring::is_zero)
    }
    /// The six 2x2 minors `a_i b_j - a_j b_i` (i < j) of the pair `(self, rhs)`.
    pub fn minors(&self, rhs: &Self) -> [T; 6] {
        let (a, b) = (&self.0, &rhs.0);
        let m = |i: usize, j: usize| a[i].mul_ref(&b[j]) - a[j].mul_ref(&b[i]);
        [m(0, 1), m(0, 2), m(0, 3), m(1, 2), m(1, 3), m(2, 3)]
    }
    /// Projective equality: all 2x2 minors vanish and neither vector is zero.
    pub fn proj_eq(&self, rhs: &Self) -> bool {
        !self.is_zero() && !rhs.is_zero() && self.minors(rhs).iter().all(Ring::is_zero)
    }
    /// `k * self`.
    pub fn scale(&self, k: &T) -> Self {
        Hom4(core::array::from_fn(|i| self.0[i].mul_ref(k)))
    }
    /// The bilinear form `sum_i a_i b_i` (the Euclidean one on coordinates).
    pub fn dot(&self, rhs: &Self) -> T {
        let mut acc = T::zero();
        for i in 0..4 {
            acc += self.0[i].mul_ref(&rhs.0[i]);
        }
        acc
    }
    /// `self + rhs`.
    pub fn add(&self, rhs: &Self) -> Self {
        Hom4(core::array::from_fn(|i| self.0[i].add_ref(&rhs.0[i])))
    }
}

impl<T: Field> Hom4<T> {
    /// The Cartesian point `(p1, p2, p3) / p0`, or the zero-divisor error at infinity.
    pub fn to_point(&self) -> Result<Vec3<T>, crate::scalar::ZeroDivisor> {
        let inv = self.0[0].inv()?;
        Ok(Vec3::new(
            self.0[1].mul_ref(&inv),
            self.0[2].mul_ref(&inv),
            self.0[3].mul_ref(&inv),
        ))
    }
}

/// The determinant of the 4x4 matrix with these rows ([`crate::linalg::det`]), over any
/// [`Ring`]. Two lines of projective 3-space spanned by `a, b` and `c, d` meet exactly when
/// `det4(a, b, c, d) = 0`.
pub fn det4<T: Ring>(a: &Hom4<T>, b: &Hom4<T>, c: &Hom4<T>, d: &Hom4<T>) -> T {
    crate::linalg::det(&[a, b, c, d].map(|r| r.0.to_vec()))
}

/// Whether two coordinate vectors of the same length are proportional: every 2x2 minor
/// `u_i v_j - u_j v_i` vanishes (so also when either is zero). Vectors of different lengths are
/// not.
pub fn proportional<T: Ring>(u: &[T], v: &[T]) -> bool {
    u.len() == v.len()
        && (0..u.len())
            .all(|i| (i + 1..u.len()).all(|j| u[i].mul_ref(&v[j]) == u[j].mul_ref(&v[i])))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn proportional_vectors_by_their_minors() {
        let v = |xs: &[i32]| xs.iter().map(|&x| f64::from(x)).collect::<Vec<f64>>();
        assert!(proportional(&v(&[1, 2, 3]), &v(&[-2, -4, -6])));
        assert!(proportional(&v(&[0, 0, 0]), &v(&[1, 5, 7])));
        assert!(!proportional(&v(&[1, 2, 3]), &v(&[1, 2, 4])));
        assert!(!proportional(&v(&[1, 2]), &v(&[1, 2, 0])));
    }

    #[test]
    fn cross_is_orthogonal() {
        let a = Vec3::<f64>::from_i64(1, 2, 3);
        let b = Vec3::<f64>::from_i64(-4, 0, 5);
        let c = a.cross(&b);
        assert_eq!(c, Vec3::from_i64(10, -17, 8));
        assert_eq!(c.dot(&a), 0.0);
        assert_eq!(c.dot(&b), 0.0);
    }

    #[test]
    fn determinant_of_four_rows() {
        let e = |i: usize| {
            let mut v = [0.0; 4];
            v[i] = 1.0;
            Hom4(v)
        };
        assert_eq!(det4(&e(0), &e(1), &e(2), &e(3)), 1.0);
        assert_eq!(det4(&e(1), &e(0), &e(2), &e(3)), -1.0);
        let a = Hom4([2.0, 1.0, 0.0, 3.0]);
        let b = Hom4([1.0, -1.0, 4.0, 0.0]);
        let c = Hom4([0.0, 2.0, 1.0, 1.0]);
        let d = Hom4([5.0, 0.0, -2.0, 1.0]);
        // Checked against the Leibniz formula.
        let m = [a.0, b.0, c.0, d.0];
        let mut leibniz = 0.0;
        let perms = [
            [0, 1, 2, 3],
            [0, 1, 3, 2],
            [0, 2, 1, 3],
            [0, 2, 3, 1],
            [0, 3, 1, 2],
            [0, 3, 2, 1],
            [1, 0, 2, 3],
            [1, 0, 3, 2],
            [1, 2, 0, 3],
            [1, 2, 3, 0],
            [1, 3, 0, 2],
            [1, 3, 2, 0],
            [2, 0, 1, 3],
            [2, 0, 3, 1],
            [2, 1, 0, 3],
            [2, 1, 3, 0],
            [2, 3, 0, 1],
            [2, 3, 1, 0],
            [3, 0, 1, 2],
            [3, 0, 2, 1],
            [3, 1, 0, 2],
            [3, 1, 2, 0],
            [3, 2, 0, 1],
            [3, 2, 1, 0],
        ];
        for p in perms {
            let inversions = (0..4)
                .flat_map(|i| (i + 1..4).map(move |j| (i, j)))
                .filter(|&(i, j)| p[i] > p[j])
                .count();
            let sign = if inversions % 2 == 0 { 1.0 } else { -1.0 };
            leibniz += sign * m[0][p[0]] * m[1][p[1]] * m[2][p[2]] * m[3][p[3]];
        }
        assert_eq!(det4(&a, &b, &c, &d), leibniz);
    }

    #[test]
    fn projective_equality() {
        let p = Hom4::new(1.0, 2.0, 3.0, 4.0);
        assert!(p.proj_eq(&p.scale(&-3.0)));
        assert!(!p.proj_eq(&Hom4::new(1.0, 2.0, 3.0, 5.0)));
        let z = Hom4::new(0.0, 0.0, 0.0, 0.0);
        assert!(!z.proj_eq(&z));
        assert!(!p.proj_eq(&z));
    }
}
