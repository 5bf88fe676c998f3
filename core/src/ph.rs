//! Planar Pythagorean-hodograph (PH) curves, their rotated normal field and their offsets as
//! exact rational Bezier curves (Chiang, "PH curves"), written once and generic
//! over the scalar.
//!
//! # The construction
//! Two polynomials `u(t), v(t)` of degree `k` in Bernstein form define the hodograph
//! `B'(t) = (X'(t), Y'(t)) = (u^2 - v^2, 2 u v)` of degree `2k`, whose length is the polynomial
//! `sigma = u^2 + v^2` (the parametric speed): `X'^2 + Y'^2 = sigma^2`. Integrating from the
//! start point `p_0` gives the PH curve `B` of degree `n = 2k + 1` with control points
//! `p_{i+1} = p_i + h_i / n` (`h_i` the hodograph's Bernstein coefficients). The curve lies in the
//! plane `z = p_0z`.
//!
//! The *rotated normal field* is `V(t) = (-Y', X', sigma)`, degree `n - 1`: the left unit normal
//! `(-Y', X') / sigma` lifted to 45 degrees. The ruled surface `B(t) + s V(t)` cut by the plane
//! `z = p_0z + r` is, by Chiang's theorem ([`crate::ruled`]), a rational Bezier curve of degree
//! `m + n = 2n - 1` with weight polynomial `sigma` (degree-elevated) and
//! `C(t) = B(t) + (r / sigma(t)) V(t)`: the point at distance `r` from `B(t)` along the left normal
//! (lifted by `r`). Its projection is the offset curve at signed distance `r` (`r > 0` left).
//!
//! # Curvature, cusps, smallest radius
//! `X' Y'' - Y' X'' = 2 sigma (u v' - u' v)`, so the signed curvature is `kappa = 2 w / sigma^2`
//! with `w = u v' - u' v` ([`PhCurve::curvature_numerator`]) and the signed radius of curvature is
//! `rho = sigma^2 / (2 w)`. The offset `O = B + r n` has `O' = B' (1 - r kappa)` (Frenet:
//! `n' = -kappa B'`), so where `sigma != 0` it is singular (a cusp) exactly where
//! `sigma^2 - 2 r w = 0` ([`PhCurve::cusp_polynomial`]), i.e. where `r` equals the signed radius.
//!
//! The smallest radius on the left side (`w > 0`) is `rho_min = inf { m > 0 : sigma^2 - 2 m w`
//! has a zero in `[0, 1] }`: for `m > 0` the polynomial `f_m = sigma^2 - 2 m w` is positive
//! where `w <= 0`, and it decreases in `m` where `w > 0`, so "f_m has a zero in [0, 1]" is
//! monotone in `m`. [`PhCurve::min_radius`] decides it with exact root isolation only — no
//! trigonometry, no floats: a candidate `m` (at an end point, or at an exactly known critical
//! point of `rho`, a zero of `2 sigma' w - sigma w'`) *is* the minimum exactly when `f_m >= 0` on
//! `[0, 1]` and vanishes somewhere ([`PhCurve::is_min_radius`]); otherwise the minimum is
//! enclosed to any width: `rho` at a parameter near the isolated critical point is an upper bound
//! within about the square of the distance (rho is flat there); dyadic bisection brackets it by
//! comparisons, and one exact test of "f_m <= 0 somewhere" (Bernstein subdivision, root isolation
//! only for a touching zero) certifies the lower end — bisection on `m` with an exact test per
//! step is the fallback. The right side (`w < 0`, negative `r`) is the same
//! with `-w`.
//!
//! Preconditions are checked, not assumed: `u = v = 0` is refused by [`PhCurve::new`]; where
//! `sigma` vanishes in `[0, 1]` (the base curve itself is singular) the offset has a pole and
//! the radius questions are answered with [`PhError::SpeedVanishes`].

use crate::bernstein::Bernstein;
use crate::bezier::{BezierCurve, RationalBezierCurve};
use crate::roots::{
    common_unit_roots, multiplicity, restrict, sign_at_root, unit_roots, IsolatedRoot, Refiner,
};
use crate::ruled::{Plane, RuledSurface};
use crate::scalar::{binom, Field, OrderedField, QAlgebra, Ring, Sign};
use crate::vector::{Hom4, Vec3};
use std::fmt;

/// Why a PH curve or a question about it is refused.
#[derive(Clone, Debug, PartialEq)]
pub enum PhError<T> {
    /// `u` and `v` must have the same number of Bernstein coefficients.
    DegreeMismatch {
        /// Coefficients of `u`.
        u: usize,
        /// Coefficients of `v`.
        v: usize,
    },
    /// `u` and `v` are both identically zero: the hodograph vanishes, there is no curve.
    ZeroPreimage,
    /// The speed `sigma = u^2 + v^2` vanishes at these parameters of `[0, 1]` (common zeros of
    /// `u` and `v`): the base curve is singular there and the offset has a pole.
    SpeedVanishes(Vec<IsolatedRoot<T>>),
}

impl<T: fmt::Debug> fmt::Display for PhError<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PhError::DegreeMismatch { u, v } => write!(
                f,
                "u has {u} Bernstein coefficients and v has {v}: they must have the same degree"
            ),
            PhError::ZeroPreimage => {
                f.write_str("u and v are both zero: the hodograph vanishes, there is no curve")
            }
            PhError::SpeedVanishes(at) => write!(
                f,
                "the parametric speed u^2 + v^2 vanishes in [0, 1] (at {} parameter(s)): the base curve is singular there",
                at.len()
            ),
        }
    }
}

impl<T: fmt::Debug> std::error::Error for PhError<T> {}

/// Which side of the curve an offset or a radius question is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// The left normal `(-Y', X')`: positive offset distances, where `w > 0` is concave.
    Left,
    /// The right normal: negative offset distances.
    Right,
}

/// The smallest radius of curvature on one side, exactly or enclosed.
#[derive(Clone, Debug, PartialEq)]
pub enum RadiusBound<T> {
    /// The exact value.
    Exact(T),
    /// `lo < rho_min <= hi` (certified exactly: Bernstein enclosures of the radius at isolated
    /// critical points, or exact root isolation).
    Within(T, T),
}

/// The smallest radius of curvature on one side and where it is attained.
#[derive(Clone, Debug, PartialEq)]
pub struct MinRadius<T> {
    /// The value.
    pub value: RadiusBound<T>,
    /// For an exact value: the parameters in `[0, 1]` where `rho = rho_min` (the zeros of
    /// `sigma^2 - 2 rho_min w`). For an enclosure `(lo, hi]`: isolating intervals of the
    /// critical points of `rho` (zeros of `2 sigma' w - sigma w'` with `w > 0`) whose enclosure
    /// of `rho` reaches down to `hi`; the minimum is attained at one of them (or, for an
    /// inexact scalar that falls back to bisection on the radius, the zeros of
    /// `sigma^2 - 2 hi w`).
    pub attained: Vec<IsolatedRoot<T>>,
}

/// A zero of the offset's derivative: a cusp (or, at a multiple zero, a higher singularity).
#[derive(Clone, Debug, PartialEq)]
pub struct Cusp<T> {
    /// The parameter, isolated in `[0, 1]`.
    pub t: IsolatedRoot<T>,
    /// Its multiplicity as a zero of `sigma^2 - 2 r w` (2 at `r = rho_min`: the two cusps of a
    /// larger `r` merged).
    pub multiplicity: usize,
}

/// A planar PH curve: `u`, `v` in Bernstein form and the start point `p_0`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct PhCurve<T> {
    u: Bernstein<T>,
    v: Bernstein<T>,
    start: Vec3<T>,
}

impl<T> PhCurve<T> {
    /// `u` (Bernstein coefficients).
    pub fn u(&self) -> &Bernstein<T> {
        &self.u
    }

    /// `v` (Bernstein coefficients).
    pub fn v(&self) -> &Bernstein<T> {
        &self.v
    }

    /// The start point `p_0`.
    pub fn start(&self) -> &Vec3<T> {
        &self.start
    }

    /// `k`, the degree of `u` and `v`.
    pub fn preimage_degree(&self) -> usize {
        self.u.degree()
    }

    /// `n = 2k + 1`, the degree of the curve.
    pub fn degree(&self) -> usize {
        2 * self.u.degree() + 1
    }
}

/// `a b` in the Bernstein basis of degree `deg a + deg b` (the product rule divided by
/// `C(m+n, k)`, an integer inverse, so a [`QAlgebra`] suffices).
fn product<T: QAlgebra>(a: &Bernstein<T>, b: &Bernstein<T>) -> Bernstein<T> {
    let n = a.degree() + b.degree();
    let scaled = a.mul_scaled(b);
    Bernstein::new(
        scaled
            .iter()
            .enumerate()
            .map(|(k, e)| e.mul_ref(&inv_binom::<T>(n, k)))
            .collect(),
    )
}

fn inv_binom<T: QAlgebra>(n: usize, k: usize) -> T {
    T::inv_u64(binom(n, k)).expect("a binomial coefficient is invertible in a Q-algebra")
}

fn sub<T: Ring>(a: &Bernstein<T>, b: &Bernstein<T>) -> Bernstein<T> {
    a.checked_sub(b).expect("operands of equal degree")
}

fn add<T: Ring>(a: &Bernstein<T>, b: &Bernstein<T>) -> Bernstein<T> {
    a.checked_add(b).expect("operands of equal degree")
}

impl<T: QAlgebra> PhCurve<T> {
    /// The PH curve with preimage `u`, `v` (same degree) starting at `start`.
    ///
    /// # Errors
    /// [`PhError::DegreeMismatch`]; [`PhError::ZeroPreimage`] when `u = v = 0`.
    pub fn new(u: Bernstein<T>, v: Bernstein<T>, start: Vec3<T>) -> Result<Self, PhError<T>> {
        if u.coeffs().len() != v.coeffs().len() {
            return Err(PhError::DegreeMismatch {
                u: u.coeffs().len(),
                v: v.coeffs().len(),
            });
        }
        if u.is_zero() && v.is_zero() {
            return Err(PhError::ZeroPreimage);
        }
        Ok(PhCurve { u, v, start })
    }

    /// The hodograph `[X', Y'] = [u^2 - v^2, 2 u v]`, degree `2k`.
    pub fn hodograph(&self) -> [Bernstein<T>; 2] {
        let uu = product(&self.u, &self.u);
        let vv = product(&self.v, &self.v);
        let uv = product(&self.u, &self.v);
        [sub(&uu, &vv), add(&uv, &uv)]
    }

    /// The parametric speed `sigma = u^2 + v^2 = |B'|`, degree `2k`.
    pub fn speed(&self) -> Bernstein<T> {
        add(&product(&self.u, &self.u), &product(&self.v, &self.v))
    }

    /// The control points of `B` (degree `n = 2k + 1`): `p_{i+1} = p_i + h_i / n`.
    pub fn base(&self) -> BezierCurve<T> {
        let [hx, hy] = self.hodograph();
        integrate(&self.start, &hx, &hy)
    }

    /// The rotated normal field `V = (-Y', X', sigma)`, degree `n - 1 = 2k`.
    pub fn rotated_normal(&self) -> BezierCurve<T> {
        let [hx, hy] = self.hodograph();
        let sigma = self.speed();
        let mx = hy.map(Ring::neg_ref);
        BezierCurve::from_coordinates(&mx, &hx, &sigma).expect("three coordinates of degree 2k")
    }

    /// The ruled surface `B(t) + s V(t)` (Chiang's cyclographic image of the curve).
    pub fn surface(&self) -> RuledSurface<T> {
        RuledSurface::new(self.base(), self.rotated_normal())
    }

    /// The plane `z = p_0z + r` whose section is the `r`-offset.
    pub fn offset_plane(&self, r: &T) -> Plane<T> {
        Plane::new(
            T::zero(),
            T::zero(),
            T::one(),
            self.start.z.add_ref(r).neg_ref(),
        )
    }

    /// The `r`-offset's homogeneous control vectors `(w_k, w_k r_k)`, `k = 0..2n-1`: Chiang's
    /// theorem ([`RuledSurface::plane_section_scaled`]) for [`PhCurve::surface`] and
    /// [`PhCurve::offset_plane`], each sum divided by `C(2n-1, k)`.
    pub fn offset_control(&self, r: &T) -> Vec<Hom4<T>> {
        let scaled = self.surface().plane_section_scaled(&self.offset_plane(r));
        let d = scaled.len() - 1;
        scaled
            .into_iter()
            .enumerate()
            .map(|(k, h)| {
                let c = inv_binom::<T>(d, k);
                Hom4(h.0.map(|x| x.mul_ref(&c)))
            })
            .collect()
    }

    /// `w = u v' - u' v` in the Bernstein basis of degree `max(2k - 1, 0)`: the signed curvature
    /// is `2 w / sigma^2`. Zero for `k = 0` (a straight line).
    pub fn curvature_numerator(&self) -> Bernstein<T> {
        if self.u.degree() == 0 {
            return Bernstein::constant(T::zero(), 0);
        }
        let a = product(&self.u, &self.v.derivative());
        let b = product(&self.u.derivative(), &self.v);
        sub(&a, &b)
    }

    /// `sigma^2 - 2 r w` (degree `4k`, `w` elevated): where `sigma != 0`, the offset at signed
    /// distance `r` is singular exactly at its zeros.
    pub fn cusp_polynomial(&self, r: &T) -> Bernstein<T> {
        let sigma = self.speed();
        let s2 = product(&sigma, &sigma);
        let w = self.curvature_numerator();
        let deg = s2.degree();
        let w_up = elevate_to(&w, deg);
        let two_r = r.add_ref(r);
        sub(&s2, &w_up.scale(&two_r))
    }

    /// `2 sigma' w - sigma w'` (degree `4k - 2`): the radius of curvature `sigma^2 / (2 w)` has
    /// derivative `sigma (2 sigma' w - sigma w') / (2 w^2)`, so its critical points (where
    /// `sigma != 0`) are the zeros of this polynomial (for `k = 1`, `w` is a constant and it is
    /// `2 sigma' w`). Zero for `k = 0` (a line).
    pub fn radius_critical_polynomial(&self) -> Bernstein<T> {
        let sigma = self.speed();
        let w = self.curvature_numerator();
        if self.u.degree() == 0 {
            return Bernstein::constant(T::zero(), 0);
        }
        let a = product(&sigma.derivative(), &w);
        let a = add(&a, &a);
        let b = product(&sigma, &w.derivative());
        let deg = a.degree().max(b.degree());
        sub(&elevate_to(&a, deg), &elevate_to(&b, deg))
    }
}

/// The planar Bezier curve (in the plane `z = start.z`) whose hodograph has the Bernstein
/// coefficients `(hx_i, hy_i)`, `i = 0..n-1`, starting at `start`: `p_{i+1} = p_i + h_i / n`.
/// For any hodograph, PH or not (the claims integrate deliberately wrong ones too).
///
/// # Panics
/// When `hx` and `hy` have different degrees.
pub fn integrate<T: QAlgebra>(
    start: &Vec3<T>,
    hx: &Bernstein<T>,
    hy: &Bernstein<T>,
) -> BezierCurve<T> {
    assert_eq!(
        hx.degree(),
        hy.degree(),
        "integrate: hodograph coordinates of one degree"
    );
    let inv_n = T::inv_u64(hx.degree() as u64 + 1).expect("n >= 1 is invertible");
    let mut points = vec![start.clone()];
    for (x, y) in hx.coeffs().iter().zip(hy.coeffs()) {
        let last = points.last().expect("starts with p_0");
        let next = Vec3::new(
            last.x.add_ref(&x.mul_ref(&inv_n)),
            last.y.add_ref(&y.mul_ref(&inv_n)),
            last.z.clone(),
        );
        points.push(next);
    }
    BezierCurve::new(points)
}

/// `p` degree-elevated to `deg >= p.degree()` (exact in a Q-algebra: the elevation formula
/// divides by the new degree).
fn elevate_to<T: QAlgebra>(p: &Bernstein<T>, deg: usize) -> Bernstein<T> {
    let r = deg - p.degree();
    if r == 0 {
        return p.clone();
    }
    // p * 1, with 1 of degree r, is p elevated by r.
    product(p, &Bernstein::new(vec![T::one(); r + 1]))
}

impl<T: Field> PhCurve<T> {
    /// The `r`-offset as a rational Bezier curve of degree `2n - 1` (the section of
    /// [`PhCurve::surface`] by [`PhCurve::offset_plane`], Chiang's theorem as printed).
    pub fn offset(&self, r: &T) -> RationalBezierCurve<T> {
        self.surface().plane_section(&self.offset_plane(r))
    }

    /// The signed radius of curvature `sigma(t)^2 / (2 w(t))`, `None` where `w(t) = 0`
    /// (an inflection or a straight line: infinite radius).
    pub fn radius_at(&self, t: &T) -> Option<T> {
        let w = self.curvature_numerator().eval(t);
        let s = self.speed().eval(t);
        s.square().checked_div(&w.add_ref(&w)).ok()
    }
}

fn side_sign<T: Ring>(side: Side, x: T) -> T {
    match side {
        Side::Left => x,
        Side::Right => x.neg_ref(),
    }
}

/// Parameters of `[0, 1]` at which the sign of a non-zero `p` is sampled so that every interval
/// of constant non-zero sign is represented: both ends, both ends of every isolating interval and
/// the midpoint of every gap between roots.
fn sign_samples<T: OrderedField>(roots: &[IsolatedRoot<T>]) -> Vec<T> {
    let two = T::from_i64(2);
    let mid = |a: &T, b: &T| a.add_ref(b) / two.clone();
    let mut samples = vec![T::zero(), T::one()];
    let mut left = T::zero();
    for root in roots {
        samples.push(mid(&left, root.lo()));
        if let IsolatedRoot::Between(lo, hi) = root {
            samples.push(lo.clone());
            samples.push(hi.clone());
        }
        left = root.hi().clone();
    }
    samples.push(mid(&left, &T::one()));
    samples
}

/// Whether `p <= 0` somewhere on `[0, 1]`, by Bernstein subdivision: a piece whose
/// coefficients are all positive is positive (convex hull property); a non-positive end
/// coefficient is a non-positive value; other pieces are halved. `None` when `MAX_DEPTH` levels
/// or `MAX_PIECES` pieces do not decide it — only a zero where `p` touches 0 without changing
/// sign defeats it (then the control polygon never becomes positive and no sample is negative).
fn nonpositive_somewhere<T: OrderedField>(p: &Bernstein<T>) -> Option<bool> {
    const MAX_DEPTH: usize = 80;
    const MAX_PIECES: usize = 4096;
    let half = T::one() / T::from_i64(2);
    let mut stack = vec![(p.clone(), 0usize)];
    let mut pieces = 0;
    while let Some((q, depth)) = stack.pop() {
        let c = q.coeffs();
        let ends = [&c[0], &c[c.len() - 1]];
        if ends.iter().any(|e| e.sign() != Sign::Positive) {
            return Some(true);
        }
        if c.iter().all(|x| x.sign() == Sign::Positive) {
            continue;
        }
        pieces += 1;
        if depth >= MAX_DEPTH || pieces > MAX_PIECES {
            return None;
        }
        let (a, b) = q.split(&half);
        stack.push((b, depth + 1));
        stack.push((a, depth + 1));
    }
    Some(false)
}

/// The enclosure `[min a / 2 max b, max a / 2 min b]` of `a / 2b` on the interval where `a`
/// and `b` are given by Bernstein coefficients of one degree (`a >= 0` there), `None` unless
/// every coefficient of `b` is positive.
fn hull_ratio<T: OrderedField>(a: &Bernstein<T>, b: &Bernstein<T>) -> Option<(T, T)> {
    let extremes = |p: &Bernstein<T>| -> (T, T) {
        let c = p.coeffs();
        let (mut lo, mut hi) = (c[0].clone(), c[0].clone());
        for x in &c[1..] {
            if *x < lo {
                lo = x.clone();
            }
            if *x > hi {
                hi = x.clone();
            }
        }
        (lo, hi)
    };
    let (b_lo, b_hi) = extremes(b);
    if b_lo.sign() != Sign::Positive {
        return None;
    }
    let (a_lo, a_hi) = extremes(a);
    let a_lo = if a_lo.sign() == Sign::Negative {
        T::zero()
    } else {
        a_lo
    };
    Some((a_lo / b_hi.add_ref(&b_hi), a_hi / b_lo.add_ref(&b_lo)))
}

impl<T: OrderedField> PhCurve<T> {
    /// The parameters of `[0, 1]` where the speed `sigma` vanishes (common zeros of `u` and `v`).
    pub fn speed_zeros(&self) -> Vec<IsolatedRoot<T>> {
        common_unit_roots(&[self.u.clone(), self.v.clone()])
            .expect("new() refuses u = v = 0, so the gcd is not zero")
    }

    fn regular(&self) -> Result<(), PhError<T>> {
        let z = self.speed_zeros();
        if z.is_empty() {
            Ok(())
        } else {
            Err(PhError::SpeedVanishes(z))
        }
    }

    /// The singular points of the offset at signed distance `r` in `[0, 1]`: the zeros of
    /// [`PhCurve::cusp_polynomial`], with multiplicity.
    ///
    /// # Errors
    /// [`PhError::SpeedVanishes`] when the base curve is singular in `[0, 1]`.
    pub fn offset_cusps(&self, r: &T) -> Result<Vec<Cusp<T>>, PhError<T>> {
        self.regular()?;
        let f = self.cusp_polynomial(r);
        let roots = unit_roots(&f).expect("sigma^2 - 2 r w is not zero where sigma has no zero");
        Ok(roots
            .into_iter()
            .map(|t| {
                let multiplicity = multiplicity(&f, &t);
                Cusp { t, multiplicity }
            })
            .collect())
    }

    /// Whether `m > 0` is exactly the smallest radius of curvature on `side`: `sigma^2 - 2 m w`
    /// (with `-w` on the right) is `>= 0` on `[0, 1]` and vanishes somewhere (module doc).
    ///
    /// # Errors
    /// [`PhError::SpeedVanishes`].
    pub fn is_min_radius(&self, m: &T, side: Side) -> Result<bool, PhError<T>> {
        self.regular()?;
        if m.sign() != Sign::Positive {
            return Ok(false);
        }
        let f = self.cusp_polynomial(&side_sign(side, m.clone()));
        let roots = unit_roots(&f).expect("not zero where sigma has no zero");
        if roots.is_empty() {
            return Ok(false);
        }
        Ok(sign_samples(&roots)
            .iter()
            .all(|t| f.eval(t).sign() != Sign::Negative))
    }

    /// Whether `sigma^2 - 2 m w` (side-signed) is `<= 0` somewhere in `[0, 1]`: `m >= rho_min`
    /// (monotone in `m`, as `f_m` decreases where `w > 0`). Decided by Bernstein subdivision
    /// ([`nonpositive_somewhere`], no gcds), and by exact root isolation when subdivision cannot
    /// (a touching zero, `m = rho_min` exactly).
    fn reaches(&self, m: &T, side: Side) -> bool {
        let f = self.cusp_polynomial(&side_sign(side, m.clone()));
        nonpositive_somewhere(&f).unwrap_or_else(|| {
            f.coeffs()[0].sign() != Sign::Positive
                || !unit_roots(&f)
                    .expect("not zero where sigma has no zero")
                    .is_empty()
        })
    }

    /// The smallest radius of curvature on `side`, exactly when it is attained at an end point
    /// or at an exactly isolated critical point, else enclosed in `(lo, hi]` with
    /// `hi - lo <= tolerance`; `None` when the side has no curvature (`w` never has the side's
    /// sign in `[0, 1]`: no finite radius there). Callers that can find further exact critical
    /// points (e.g. rational roots over Q) test them with [`PhCurve::is_min_radius`].
    ///
    /// # Errors
    /// [`PhError::SpeedVanishes`].
    ///
    /// # Panics
    /// When `tolerance` is not positive.
    pub fn min_radius(
        &self,
        side: Side,
        tolerance: &T,
    ) -> Result<Option<MinRadius<T>>, PhError<T>> {
        assert!(
            tolerance.sign() == Sign::Positive,
            "min_radius: the tolerance must be positive"
        );
        self.regular()?;
        let w = match side {
            Side::Left => self.curvature_numerator(),
            Side::Right => self.curvature_numerator().map(Ring::neg_ref),
        };
        if w.is_zero() {
            return Ok(None);
        }
        let w_roots = unit_roots(&w).expect("w is not zero");
        let sigma = self.speed();
        let rho = |t: &T| -> Option<T> {
            let wt = w.eval(t);
            (wt.sign() == Sign::Positive).then(|| sigma.eval(t).square() / wt.add_ref(&wt))
        };
        // Upper bounds: rho at the sign samples of w where w > 0 (there is one when w > 0
        // somewhere). Possible exact minima: those samples include both end points; add the
        // exactly isolated critical points of rho.
        let mut hi: Option<T> = None;
        let mut take = |m: T| {
            if hi.as_ref().is_none_or(|h| m < *h) {
                hi = Some(m);
            }
        };
        for t in sign_samples(&w_roots) {
            if let Some(m) = rho(&t) {
                take(m);
            }
        }
        let crit = self.radius_critical_polynomial();
        let crit_roots = if crit.is_zero() {
            Vec::new()
        } else {
            unit_roots(&crit).expect("not zero")
        };
        for c in &crit_roots {
            if let Some(m) = c.exact().and_then(&rho) {
                take(m);
            }
        }
        let Some(hi) = hi else {
            return Ok(None);
        };
        if self.is_min_radius(&hi, side)? {
            let f = self.cusp_polynomial(&side_sign(side, hi.clone()));
            let attained = unit_roots(&f).expect("not zero");
            return Ok(Some(MinRadius {
                value: RadiusBound::Exact(hi),
                attained,
            }));
        }
        // The minimum is not at an end point or an exact critical point, so it is at an
        // irrational critical point `c` of rho with `w(c) > 0` (rho -> infinity at the zeros of
        // w, and sigma has no zero). Each such `c` is enclosed by an isolating interval of the
        // critical polynomial, and rho(c) by the convex hulls of the Bernstein coefficients of
        // sigma^2 and w restricted to that interval: `[min sigma^2 / 2 max w, max sigma^2 / 2 min
        // w]`. Refining the interval (quadratic refinement of a simple root) shrinks the
        // enclosure to width <= tolerance / 4 after a few rounds, whatever the size of rho'':
        // no test on the near-double zeros of sigma^2 - 2 m w is needed.
        let two = T::from_i64(2);
        let sigma2 = self.cusp_polynomial(&T::zero());
        let w_up = elevate_to(&w, sigma2.degree());
        let quarter_tol = tolerance.clone() / T::from_i64(4);
        let refiner = Refiner::new(&crit);
        let mut enclosures: Vec<(T, T, IsolatedRoot<T>)> = Vec::new();
        for c in crit_roots.iter().filter(|c| c.exact().is_none()) {
            if sign_at_root(&w, &crit, c) != Sign::Positive {
                continue;
            }
            let mut root = c.clone();
            loop {
                let (a, b) = (root.lo().clone(), root.hi().clone());
                if let IsolatedRoot::Exact(t) = &root {
                    let m = rho(t).expect("w > 0 at the critical point");
                    enclosures.push((m.clone(), m, root));
                    break;
                }
                if let Some((l, h)) =
                    hull_ratio(&restrict(&sigma2, &a, &b), &restrict(&w_up, &a, &b))
                {
                    if h.sub_ref(&l) <= quarter_tol {
                        enclosures.push((l, h, root));
                        break;
                    }
                }
                let width = root.width() / T::from_i64(1 << 16);
                let next = refiner.refine(&root, &width);
                if next == root {
                    // No progress (only an inexact scalar stops shrinking): rho at the midpoint.
                    let m = rho(&root.midpoint()).unwrap_or_else(|| hi.clone());
                    enclosures.push((m.clone(), m, root));
                    break;
                }
                root = next;
            }
        }
        let least_lo = enclosures
            .iter()
            .map(|(l, _, _)| l)
            .min_by(|x, y| x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal));
        let Some(least_lo) = least_lo.cloned() else {
            // Not reached for exact scalars (the candidates cover every minimum); an inexact
            // scalar falls back to deciding `rho_min <= m` by bisection on m.
            return Ok(Some(self.min_radius_by_bisection(side, tolerance, hi)));
        };
        let mut least_hi = hi.clone();
        for (_, h, _) in &enclosures {
            if *h < least_hi {
                least_hi = h.clone();
            }
        }
        // Round outwards to the dyadic grid of `[0, hi]` with a step of at most tolerance / 4
        // (short numbers): `lo < least_lo <= rho_min <= least_hi <= hi`, and the width is at
        // most 3/4 of the tolerance (`least_hi - least_lo <= tolerance / 4`).
        let grid = |target: &T, strict: bool| -> (T, T) {
            let (mut a, mut c) = (T::zero(), hi.clone());
            while c.sub_ref(&a) > quarter_tol {
                let mid = a.add_ref(&c) / two.clone();
                if mid < *target || (!strict && mid == *target) {
                    a = mid;
                } else {
                    c = mid;
                }
            }
            (a, c)
        };
        let lo = grid(&least_lo, true).0;
        let hi = if least_hi < hi {
            grid(&least_hi, false).1
        } else {
            hi
        };
        let attained = enclosures
            .into_iter()
            .filter(|(l, _, _)| *l <= hi)
            .map(|(_, _, root)| root)
            .collect();
        Ok(Some(MinRadius {
            value: RadiusBound::Within(lo, hi),
            attained,
        }))
    }

    /// The enclosure `(lo, hi]` of the smallest radius on `side` by bisection on `m` with the
    /// exact test [`PhCurve::reaches`], from the upper bound `hi`.
    fn min_radius_by_bisection(&self, side: Side, tolerance: &T, mut hi: T) -> MinRadius<T> {
        let two = T::from_i64(2);
        let mut lo = T::zero();
        while hi.sub_ref(&lo) > *tolerance {
            let mid = lo.add_ref(&hi) / two.clone();
            if self.reaches(&mid, side) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        let f = self.cusp_polynomial(&side_sign(side, hi.clone()));
        let attained = unit_roots(&f).expect("not zero");
        MinRadius {
            value: RadiusBound::Within(lo, hi),
            attained,
        }
    }
}

#[cfg(test)]
mod tests;
