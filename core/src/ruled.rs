//! Ruled surfaces `S(s,t) = B(t) + s V(t)` and their intersections with a plane, a line and a
//! point (Chiang), written once and generic over the scalar.
//!
//! `B` is a Bezier curve of degree `n` (control points `p_j`), `V` a Bezier *direction field* of
//! degree `m` (control vectors `q_i`). The plane is `N . x + d = 0`, `N = (a, b, c)`.
//!
//! # The plane section (Chiang's Theorem 1)
//! Substituting `S(s,t)` into the plane gives `(N.B(t) + d) + s (N.V(t)) = 0`, so where
//! `N.V(t) != 0` the section is
//!
//! ```text
//!     C(t) = [ (N.V(t)) B(t) - (N.B(t) + d) V(t) ] / (N.V(t)),
//! ```
//!
//! a rational curve of degree `m + n`. Writing the numerator and the denominator (degree-elevated
//! from `m` to `m + n`) in the Bernstein basis of degree `m + n` by the product rule
//! `B_i^m B_j^n = phi(m,n,i,j) B_{i+j}^{m+n}` gives the theorem's weights and control points
//!
//! ```text
//!     w_k     = N . sum_{i+j=k} phi(m,n,i,j) q_i,
//!     w_k r_k = sum_{i+j=k} phi(m,n,i,j) [ (N.q_i) p_j - (N.p_j + d) q_i ],   k = 0..m+n.
//! ```
//!
//! [`RuledSurface::plane_section`] evaluates exactly these printed sums (homogeneous control
//! vectors `(w_k, w_k r_k)`, no division by `w_k`, so a zero weight is a point at infinity and
//! nothing fails); [`RuledSurface::plane_section_scaled`] is the division-free form for a
//! [`Ring`] (each sum multiplied by `C(m+n, k)`, so `phi` becomes the integer `C(m,i) C(n,j)`),
//! which is what lets a polynomial ring instantiate the theorem and the catalogue prove it. The
//! substitution itself (numerator and denominator as Bernstein products) is
//! [`RuledSurface::substitution`]: the claim `chiang.theorem` compares the two.
//!
//! Corollary 1 is the plane `z = 0` (`N = (0,0,1)`, `d = 0`), Corollary 2 the case `m = 0` (a
//! cylinder over `B`, all weights `q_0z`), Corollary 5 the case `m = 1, n = 2` with `z = 0`.
//!
//! # Degenerate cases (ignored by the paper, decided here)
//! [`RuledSurface::classify_plane`] tells them apart exactly (it needs exact zero tests, so it
//! means what it says only for exact scalars): a direction field `V` identically zero has no
//! rulings at all — the "surface" is the base curve `B`, and the section is the points of `B` at
//! the zeros of `N.B + d` (or all of `B`); else the weight polynomial `N.V` identically zero (every
//! ruling parallel to the plane) splits into *the whole surface in the plane* (`N.B + d` is zero
//! too) and *no curve* (then the section is the rulings at the zeros of `N.B + d`, each lying in
//! the plane); otherwise the section is a curve, whose poles are the zeros of `N.V` in `[0, 1]`
//! (isolated by the exact layer) — a common zero of `N.V` and `N.B + d` is a ruling lying in the
//! plane.
//!
//! # Line and point (the vicinity test)
//! A line `P + lambda D` meets `S` at parameter `t` iff `B(t) - P`, `V(t)` and `D` are linearly
//! dependent: `det(B(t) - P, V(t), D) = 0`, a polynomial of degree `m + n`
//! ([`RuledSurface::line_polynomial`]). Moving the line onto the x axis (`P = 0`, `D = (1,0,0)`)
//! gives Chiang's `B_y V_z - B_z V_y`. A point `P` lies on a ruling `t` iff `B(t) - P` and `V(t)`
//! are parallel: `(B(t) - P) x V(t) = 0`, three polynomials of degree `m + n`
//! ([`RuledSurface::vicinity_polynomials`]); Chiang's vicinity test uses two of them.

use crate::bernstein::{Bernstein, ShapeError};
use crate::bezier::{BezierCurve, RationalBezierCurve};
use crate::scalar::{binom, from_u64, Field, Ring};
use crate::vector::{Hom4, Vec3};

pub use crate::planes::Plane;

/// The ruled surface `S(s,t) = B(t) + s V(t)`: base curve `B` of degree `n`, direction field `V`
/// of degree `m`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RuledSurface<T> {
    base: BezierCurve<T>,
    directions: BezierCurve<T>,
}

/// How a plane meets a ruled surface (module doc, "Degenerate cases").
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum PlaneSection<T> {
    /// A rational curve of degree `m + n` (the weight polynomial `N.V` is not identically zero;
    /// it may still vanish at finitely many parameters: the poles).
    Curve(RationalBezierCurve<T>),
    /// Every ruling is parallel to the plane (`N.V = 0` identically) and the surface is not in
    /// the plane: the section is the set of rulings at the zeros of `offset` (`N.B + d`), possibly
    /// empty.
    ParallelRulings {
        /// `N.B(t) + d`, degree `n`; not identically zero.
        offset: Bernstein<T>,
    },
    /// `N.V` and `N.B + d` both vanish identically: the whole surface lies in the plane.
    SurfaceInPlane,
    /// `V = 0` identically: there are no rulings, the surface is the base curve `B`, and the
    /// section is the points of `B` at the zeros of `offset` (`N.B + d`), or all of `B` when
    /// `offset` is zero.
    NoRulings {
        /// `N.B(t) + d`, degree `n` (zero when the base curve lies in the plane).
        offset: Bernstein<T>,
    },
}

impl<T> RuledSurface<T> {
    /// The surface with base curve `base` (degree `n`) and direction field `directions`
    /// (degree `m`).
    pub fn new(base: BezierCurve<T>, directions: BezierCurve<T>) -> Self {
        RuledSurface { base, directions }
    }

    /// The base curve `B`.
    pub fn base(&self) -> &BezierCurve<T> {
        &self.base
    }

    /// The direction field `V`.
    pub fn directions(&self) -> &BezierCurve<T> {
        &self.directions
    }

    /// `(m, n)`: the degrees of the direction field and of the base curve.
    pub fn degrees(&self) -> (usize, usize) {
        (self.directions.degree(), self.base.degree())
    }
}

impl<T: Ring> RuledSurface<T> {
    /// The surface from control points `p_0..p_n` and control vectors `q_0..q_m`.
    ///
    /// # Errors
    /// [`ShapeError::Empty`] when either list is empty.
    pub fn from_control(base: Vec<Vec3<T>>, directions: Vec<Vec3<T>>) -> Result<Self, ShapeError> {
        Ok(RuledSurface {
            base: BezierCurve::try_new(base)?,
            directions: BezierCurve::try_new(directions)?,
        })
    }

    /// The point `B(t) + s V(t)`.
    pub fn eval(&self, s: &T, t: &T) -> Vec3<T> {
        self.base.eval(t).add_scaled(s, &self.directions.eval(t))
    }

    /// The weight polynomial `N.V(t)` of degree `m` (before elevation): zero where the ruling is
    /// parallel to the plane.
    pub fn normal_component(&self, plane: &Plane<T>) -> Bernstein<T> {
        self.directions.dot(&plane.normal)
    }

    /// `N.B(t) + d` of degree `n`: zero where the base curve meets the plane.
    pub fn offset(&self, plane: &Plane<T>) -> Bernstein<T> {
        let nb = self.base.dot(&plane.normal);
        Bernstein::new(nb.coeffs().iter().map(|c| c.add_ref(&plane.d)).collect())
    }

    /// The theorem's sums multiplied by `C(m+n, k)`, division-free: the homogeneous vectors
    /// `sum_{i+j=k} C(m,i) C(n,j) ( N.q_i, (N.q_i) p_j - (N.p_j + d) q_i )`, k = 0..m+n.
    /// They are the coefficients of the section in the scaled basis `t^k (1-t)^(m+n-k)`
    /// (module doc of [`crate::bernstein`]); [`RationalBezierCurve::from_scaled`] turns them
    /// into the Bernstein control vectors in a field.
    pub fn plane_section_scaled(&self, plane: &Plane<T>) -> Vec<Hom4<T>> {
        let (m, n) = self.degrees();
        let q = self.directions.control_points();
        let p = self.base.control_points();
        let nq: Vec<T> = q.iter().map(|qi| plane.normal.dot(qi)).collect();
        let np: Vec<T> = p.iter().map(|pj| plane.value(pj)).collect();
        let mut out = vec![Hom4([T::zero(), T::zero(), T::zero(), T::zero()]); m + n + 1];
        for (i, qi) in q.iter().enumerate() {
            for (j, pj) in p.iter().enumerate() {
                let c = from_u64::<T>(binom(m, i) * binom(n, j));
                let w = nq[i].mul_ref(&c);
                let point = pj.scale(&nq[i]).add_scaled(&np[j].neg_ref(), qi).scale(&c);
                let slot = &mut out[i + j];
                slot.0[0] += &w;
                slot.0[1] += &point.x;
                slot.0[2] += &point.y;
                slot.0[3] += &point.z;
            }
        }
        out
    }

    /// The substitution of the theorem's proof, as Bernstein polynomials of degree `m + n` in
    /// the scaled basis: `[denominator, numerator x, y, z]` with denominator `N.V` (elevated by
    /// the product with the constant 1 of degree `n`) and numerator `(N.V) B - (N.B + d) V`.
    /// Computed by Bernstein products, independently of the theorem's sums; equal to
    /// [`RuledSurface::plane_section_scaled`] exactly when the theorem is right.
    pub fn substitution(&self, plane: &Plane<T>) -> [Vec<T>; 4] {
        let (_, n) = self.degrees();
        let nv = self.normal_component(plane);
        let off = self.offset(plane);
        let ones = Bernstein::new(vec![T::one(); n + 1]);
        let b = self.base.coordinates();
        let v = self.directions.coordinates();
        let denominator = nv.mul_scaled(&ones);
        let coord = |a: usize| {
            let first = nv.mul_scaled(&b[a]);
            let second = v[a].mul_scaled(&off);
            first
                .iter()
                .zip(&second)
                .map(|(x, y)| x.sub_ref(y))
                .collect::<Vec<T>>()
        };
        [denominator, coord(0), coord(1), coord(2)]
    }

    /// `det(B(t) - P, V(t), D)` of degree `m + n`, division-free: its coefficients in the scaled
    /// basis `t^k (1-t)^(m+n-k)` ([`RuledSurface::line_polynomial`] converts in a field). Zero
    /// exactly at the parameters whose ruling meets the line `P + lambda D` or is parallel to it.
    pub fn line_polynomial_scaled(&self, point: &Vec3<T>, direction: &Vec3<T>) -> Vec<T> {
        let [bx, by, bz] = self.shifted_base(point);
        let [vx, vy, vz] = self.directions.coordinates();
        let (dx, dy, dz) = (&direction.x, &direction.y, &direction.z);
        // det(b, v, d) = b . (v x d) = bx (vy dz - vz dy) + by (vz dx - vx dz) + bz (vx dy - vy dx)
        let cx = combine(&vy, dz, &vz, dy);
        let cy = combine(&vz, dx, &vx, dz);
        let cz = combine(&vx, dy, &vy, dx);
        add3(bx.mul_scaled(&cx), by.mul_scaled(&cy), bz.mul_scaled(&cz))
    }

    /// The three coordinates of `(B(t) - P) x V(t)`, each of degree `m + n`, division-free (scaled
    /// basis, as [`RuledSurface::line_polynomial_scaled`]): all three vanish at `t` exactly when
    /// `P` lies on the line of the ruling `t` (or `V(t) = 0`).
    pub fn vicinity_polynomials_scaled(&self, point: &Vec3<T>) -> [Vec<T>; 3] {
        let [bx, by, bz] = self.shifted_base(point);
        let [vx, vy, vz] = self.directions.coordinates();
        let cross = |a: &Bernstein<T>, b: &Bernstein<T>, c: &Bernstein<T>, d: &Bernstein<T>| {
            // a b - c d
            let l = a.mul_scaled(b);
            let r = c.mul_scaled(d);
            l.iter()
                .zip(&r)
                .map(|(x, y)| x.sub_ref(y))
                .collect::<Vec<T>>()
        };
        [
            cross(&by, &vz, &bz, &vy),
            cross(&bz, &vx, &bx, &vz),
            cross(&bx, &vy, &by, &vx),
        ]
    }

    fn shifted_base(&self, point: &Vec3<T>) -> [Bernstein<T>; 3] {
        let [bx, by, bz] = self.base.coordinates();
        let shift = |b: Bernstein<T>, c: &T| {
            Bernstein::new(b.coeffs().iter().map(|x| x.sub_ref(c)).collect())
        };
        [
            shift(bx, &point.x),
            shift(by, &point.y),
            shift(bz, &point.z),
        ]
    }
}

/// `a * s - b * t` for polynomials `a, b` and scalars `s, t`.
fn combine<T: Ring>(a: &Bernstein<T>, s: &T, b: &Bernstein<T>, t: &T) -> Bernstein<T> {
    Bernstein::new(
        a.coeffs()
            .iter()
            .zip(b.coeffs())
            .map(|(x, y)| x.mul_ref(s) - y.mul_ref(t))
            .collect(),
    )
}

fn add3<T: Ring>(a: Vec<T>, b: Vec<T>, c: Vec<T>) -> Vec<T> {
    a.into_iter()
        .zip(b)
        .zip(c)
        .map(|((x, y), z)| x + y + z)
        .collect()
}

impl<T: Field> RuledSurface<T> {
    /// Chiang's Theorem 1 as printed: the homogeneous control vectors `(w_k, w_k r_k)` of the
    /// section, `w_k = N . sum phi(m,n,i,j) q_i`, `w_k r_k = sum phi(m,n,i,j) [(N.q_i) p_j -
    /// (N.p_j + d) q_i]`. No division by a weight: a zero weight gives a point at infinity.
    pub fn plane_section(&self, plane: &Plane<T>) -> RationalBezierCurve<T> {
        RationalBezierCurve::from_scaled(&self.plane_section_scaled(plane))
            .expect("m + n + 1 >= 1 control vectors")
    }

    /// Decides the case of the section by exact zero tests on `N.V` and `N.B + d` (module doc).
    pub fn classify_plane(&self, plane: &Plane<T>) -> PlaneSection<T> {
        if !self.normal_component(plane).is_zero() {
            return PlaneSection::Curve(self.plane_section(plane));
        }
        let offset = self.offset(plane);
        if self.directions.control_points().iter().all(Vec3::is_zero) {
            return PlaneSection::NoRulings { offset };
        }
        if offset.is_zero() {
            PlaneSection::SurfaceInPlane
        } else {
            PlaneSection::ParallelRulings { offset }
        }
    }

    /// `det(B(t) - P, V(t), D)` in Bernstein form of degree `m + n` (module doc).
    pub fn line_polynomial(&self, point: &Vec3<T>, direction: &Vec3<T>) -> Bernstein<T> {
        from_scaled_poly(&self.line_polynomial_scaled(point, direction))
    }

    /// The coordinates of `(B(t) - P) x V(t)` in Bernstein form of degree `m + n`.
    pub fn vicinity_polynomials(&self, point: &Vec3<T>) -> [Bernstein<T>; 3] {
        self.vicinity_polynomials_scaled(point)
            .map(|p| from_scaled_poly(&p))
    }

    /// The ruling parameter `s` of the section point at `t`: `-(N.B(t) + d) / (N.V(t))`.
    ///
    /// # Errors
    /// [`crate::ZeroDivisor`] at a pole (`N.V(t) = 0`).
    pub fn section_parameter(
        &self,
        plane: &Plane<T>,
        t: &T,
    ) -> Result<T, crate::scalar::ZeroDivisor> {
        let den = self.normal_component(plane).eval(t);
        self.offset(plane).eval(t).neg_ref().checked_div(&den)
    }
}

fn from_scaled_poly<T: Field>(p: &[T]) -> Bernstein<T> {
    Bernstein::from_scaled(p).expect("m + n + 1 >= 1 coefficients")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn surface() -> RuledSurface<f64> {
        RuledSurface::from_control(
            vec![
                Vec3::new(0.0, 0.0, -1.0),
                Vec3::new(1.0, 1.0, -1.0),
                Vec3::new(0.0, 2.0, -1.0),
            ],
            vec![Vec3::new(-1.0, 1.0, 1.5), Vec3::new(-1.0, -1.0, 2.5)],
        )
        .unwrap()
    }

    #[test]
    fn section_lies_on_plane_and_surface() {
        let s = surface();
        let plane = Plane::new(0.5, -0.25, 1.0, 0.75);
        let c = s.plane_section(&plane);
        assert_eq!(c.degree(), 3);
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            let x = c.eval(&t).unwrap();
            assert!(plane.value(&x).abs() < 1e-12);
            let sp = s.section_parameter(&plane, &t).unwrap();
            let y = s.eval(&sp, &t);
            assert!((&x - &y).norm_squared() < 1e-20);
        }
    }

    #[test]
    fn substitution_equals_theorem_sums() {
        let s = surface();
        let plane = Plane::new(2.0, -1.0, 3.0, 0.5);
        let sub = s.substitution(&plane);
        let thm = s.plane_section_scaled(&plane);
        for (k, h) in thm.iter().enumerate() {
            for (a, coordinate) in sub.iter().enumerate() {
                assert!((h.0[a] - coordinate[k]).abs() < 1e-12, "k={k} a={a}");
            }
        }
    }

    #[test]
    fn line_through_a_surface_point() {
        let s = surface();
        let x = s.eval(&0.7, &0.3);
        let d = Vec3::new(0.2, 1.0, -0.5);
        let p = x.add_scaled(&-2.0, &d);
        let f = s.line_polynomial(&p, &d);
        assert_eq!(f.degree(), 3);
        assert!(f.eval(&0.3).abs() < 1e-12);
        let [a, b, c] = s.vicinity_polynomials(&x);
        for g in [a, b, c] {
            assert!(g.eval(&0.3).abs() < 1e-12);
        }
    }

    #[test]
    fn classification() {
        // Horizontal rulings, plane z = 0: parallel rulings; base curve in z = 0: surface in plane.
        let flat = RuledSurface::from_control(
            vec![Vec3::new(0.0, 0.0, -1.0), Vec3::new(1.0, 0.0, 1.0)],
            vec![Vec3::new(0.0, 1.0, 0.0)],
        )
        .unwrap();
        match flat.classify_plane(&Plane::z0()) {
            PlaneSection::ParallelRulings { offset } => {
                assert_eq!(offset.coeffs(), &[-1.0, 1.0]);
            }
            other => panic!("{other:?}"),
        }
        let inplane = RuledSurface::from_control(
            vec![Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0)],
            vec![Vec3::new(0.0, 1.0, 0.0)],
        )
        .unwrap();
        assert_eq!(
            inplane.classify_plane(&Plane::z0()),
            PlaneSection::SurfaceInPlane
        );
        // No rulings at all (V = 0): the section is the base curve's points in the plane.
        let curve_only = RuledSurface::from_control(
            vec![Vec3::new(0.0, 0.0, -1.0), Vec3::new(1.0, 0.0, 1.0)],
            vec![Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 0.0)],
        )
        .unwrap();
        match curve_only.classify_plane(&Plane::z0()) {
            PlaneSection::NoRulings { offset } => assert_eq!(offset.coeffs(), &[-1.0, 1.0]),
            other => panic!("{other:?}"),
        }
    }
}
