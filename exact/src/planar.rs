//! Exact self-intersections of rational planar curves.
//!
//! A rational curve `C(t) = (x(t) / w(t), y(t) / w(t))`, `t` in `[0, 1]`, with `x, y, w` in
//! `Q[t]` and `w != 0` on `[0, 1]`, crosses itself where `C(s) = C(t)` for some `s < t`.
//! [`self_intersections`] finds **all** such pairs, each certified to exist, and certifies that
//! there are no others (or says why it could not decide, never guessing).
//!
//! # The equations
//! Since `w != 0`, `C(s) = C(t)` is `X(s, t) = x(s) w(t) - x(t) w(s) = 0` and the same with `y`.
//! Both vanish on the diagonal `s = t`, and both are antisymmetric, so they are divisible by
//! `s - t`:
//!
//! `F(s, t) = (x(s) w(t) - x(t) w(s)) / (s - t)`,  `G(s, t) = (y(s) w(t) - y(t) w(s)) / (s - t)`,
//!
//! symmetric polynomials (computed without division: for `i > j`,
//! `(s^i t^j - s^j t^i) / (s - t) = (s t)^j sum_{k < i-j} s^k t^(i-j-1-k)`). The
//! self-intersections are the real zeros of `(F, G)` in `[0, 1]^2` off the diagonal. On the
//! diagonal, `F(t, t) = x' w - x w'` and `G(t, t) = y' w - y w'`: common zeros there are the
//! parameters where `C'(t) = 0` (cusps, typically); they are reported separately
//! ([`SelfIntersections::stationary`]) and are not self-intersections.
//!
//! # Elimination
//! `R(t) = Res_s(F, G)`, the Sylvester resultant with respect to `s` (formal degrees), vanishes at
//! every `t` for which `F(., t)` and `G(., t)` have a common root, so the `t` of every solution is
//! a root of `R`, and by the symmetry of `F` and `G` so is its `s`. `R` is computed exactly by
//! evaluation and interpolation modulo word-size primes and the Chinese remainder theorem
//! (`resultant`): `F` and `G` scaled to integer coefficients, the Sylvester determinant at
//! `N + 1` points, `N` the degree bound `deg_s(G) deg_t(F) + deg_s(F) deg_t(G)` of the
//! determinant, interpolated modulo each prime until the product of the primes exceeds twice a
//! bound on the coefficients, then the scale divided out. If `R` vanishes identically, `F` and `G` share a
//! factor of positive degree in `s` (the curve lies on a line, or the parametrization is not
//! proper, or it retraces itself): the solution set may be a curve, and the error
//! [`PlanarError::CommonComponent`] says so rather than deciding.
//!
//! # Candidate parameters
//! `R` is far from square-free: it is divisible by high powers of `w` (points at infinity) and
//! of `S = gcd(x' w - x w', y' w - y w')` (stationary points). These are divided out and `S` put
//! back once (`candidate_polynomial`), which leaves the roots in `[0, 1]` unchanged and cuts the
//! degree about in half before the expensive step, the root isolation (for the offsets of
//! quintic PH curves, 88 to 44). Its square-free part (certified square-free modulo word-size
//! primes in the usual case, so no remainder sequence is needed:
//! [`UPoly::primitive_square_free_part`]) has the distinct roots `rho_1 < ... < rho_m` in
//! `[0, 1]`, isolated by the workspace's real-root isolator ([`isolate_real_roots_in`], Descartes'
//! rule of signs), each by a rational interval `I_k` (open, ends not roots), or exactly when it is
//! rational.
//! Every self-intersection `s < t` is `(rho_i, rho_j)` for some `i < j`, and, conversely, the box
//! `I_i x I_j` contains no solution but possibly `(rho_i, rho_j)`: any solution in it has both
//! coordinates roots of `R`, and `I_i`, `I_j` hold one each. So each pair `i < j` is decided on
//! its own:
//! * **both roots rational**: evaluate `F` and `G` at the point exactly;
//! * **one rational**, say `s = a`: the solutions in the box are the common roots of the
//!   univariate `F(a, t)` and `G(a, t)` in `I_j`, i.e. the roots of their gcd there (Sturm
//!   count; the ends of `I_j` are not roots of `R`, hence not of the gcd);
//! * **both irrational**: repeat, bisecting `I_i` and `I_j` (on the sign of the square-free part
//!   of `R`) after every failed attempt, until the budget ([`Budget`]) is spent:
//!   - *exclusion*: the tensor Bernstein coefficients of `F` or of `G` on the closed box
//!     `I_i x I_j` (the polynomial in power form composed with the affine maps of `[0, 1]` onto
//!     the box sides, then converted to the Bernstein basis in each variable) are all of one
//!     strict sign, so that polynomial has no zero in the box;
//!   - *certification* (Poincare-Miranda): with `c` the midpoints and `d` the widths of `I_i`,
//!     `I_j`, take the box `P = [c_i - d_i, c_i + d_i] x [c_j - d_j, c_j + d_j]`, which contains
//!     `(rho_i, rho_j)` at distance at least `d/2` from its sides; check by root counts
//!     (Descartes' bound for the candidates, Sturm for `w`) that each side of `P` holds no root of `R`
//!     but `rho_i` (resp. `rho_j`) and that its ends are not roots (`P` may reach outside
//!     `[0, 1]`, so the count is of the candidate polynomial and of `w`, whose roots together
//!     are those of `R`). Precondition with `A = J^{-1}`, `J` the exact Jacobian of `(F, G)` at
//!     the centre: `(H1, H2) = A (F, G)` has the same zeros and is close to the identity map
//!     around the root. If `H1` has one strict sign on the left side of `P` and the opposite strict sign
//!     on the right side, and `H2` likewise on the bottom and top sides (each side's restriction
//!     is a univariate polynomial whose Bernstein coefficients on the side are checked), the
//!     Poincare-Miranda theorem gives a zero of `(H1, H2)`, hence of `(F, G)`, in `P`. By the
//!     root counts that zero is `(rho_i, rho_j)`: the self-intersection exists, it is the only
//!     solution in `P` (uniqueness per box), and `rho_i != rho_j`.
//!
//! Exclusion converges for pairs that are not solutions (the Bernstein coefficients on a box
//! converge to the value at the point). Certification converges at transversal crossings: there
//! the Jacobian of `(F, G)` is, up to the non-zero factor `1 / (s - t)`, that of
//! `(x(s) w(t) - x(t) w(s), y(s) w(t) - y(t) w(s))`, non-singular exactly when the tangents
//! `C'(s)` and `C'(t)` are not parallel. A tangential self-contact with irrational parameters is
//! never certified: the budget runs out and [`PlanarError::Undecided`] names the box.
//!
//! # Cost
//! Measured in release builds on this machine (shared): the offsets of Chiang's cubic example,
//! a few milliseconds each; offsets of random quintic PH curves (degree 9, `deg R` about 88),
//! 0.1 to 0.3 s; of septic ones (degree 13, `deg R` about 204, candidates of degree about 108),
//! 2 to 3 s typically and 29 s for one with 18 candidate parameters in `[0, 1]` (153 pairs).
//! The time goes into the resultant (evaluation at about 290 points of 24 x 24 determinants) and
//! the isolation of the candidates.
//!
//! # Why a dense bivariate type here
//! `F` and `G` are dense (every `s^i t^j` up to the degree occurs), the procedure needs their
//! coefficient grid (partial evaluation in one variable, composition with affine maps per
//! variable, the tensor Bernstein form) and nothing of a general multivariate engine, so the
//! module keeps a small dense `(deg_s + 1) x (deg_t + 1)` coefficient array instead of the
//! sparse [`crate::poly::Poly`].

use crate::univariate::{
    compare_simple, descartes_bound, isolate_real_roots_in, RootInterval, UPoly,
};
use crate::Rational;
use exactcheck_core::bernstein::Bernstein;
use exactcheck_core::bezier::RationalBezierCurve;
use exactcheck_core::{Field, Ring, Sign};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::One;
use std::cmp::Ordering;

mod resultant;
#[cfg(test)]
mod tests;

use resultant::resultant_s;

/// How much work [`self_intersections`] may spend on one candidate pair before it gives up.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Budget {
    /// The number of bisections of the two parameter intervals of a candidate pair (each
    /// halves both widths) after which an undecided pair ends the computation with
    /// [`PlanarError::Undecided`].
    pub max_bisections: u32,
}

impl Default for Budget {
    /// 96 bisections: far more than a transversal crossing or a non-solution needs with the
    /// coefficient sizes of the workspace's curves (typically fewer than 20).
    fn default() -> Budget {
        Budget { max_bisections: 96 }
    }
}

/// How a [`Crossing`] was certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Certificate {
    /// Both parameters are rational and `F`, `G` vanish there exactly.
    Exact,
    /// One parameter is rational; the other is a root of the gcd of the univariate restrictions
    /// of `F` and `G`, counted in its interval by a Sturm sequence.
    RationalParameter,
    /// Poincare-Miranda on a rational box after preconditioning (module documentation).
    PoincareMiranda,
}

/// One certified self-intersection: `C(s) = C(t)` with `s < t`, the unique such pair with `s` in
/// `s_interval` and `t` in `t_interval`.
#[derive(Clone, Debug, PartialEq)]
pub struct Crossing {
    /// An isolating interval of `s`, a root of [`SelfIntersections::resultant`] (exact when
    /// `lo == hi`).
    pub s_interval: RootInterval,
    /// An isolating interval of `t`, likewise, disjoint from `s_interval` and above it.
    pub t_interval: RootInterval,
    /// How the existence was proved.
    pub certificate: Certificate,
    /// `s`, approximately (the midpoint of `s_interval`, refined to width `2^-64`).
    pub s: f64,
    /// `t`, approximately.
    pub t: f64,
    /// The crossing point `C(s)`, approximately (evaluated exactly at the midpoint of
    /// `s_interval`, then rounded).
    pub point: [f64; 2],
}

/// The result of [`self_intersections`]: every self-intersection, certified, and nothing else.
#[derive(Clone, Debug, PartialEq)]
pub struct SelfIntersections {
    /// The self-intersections, sorted by `s` (empty: the curve is certified simple on
    /// `[0, 1]`, apart from the stationary points).
    pub crossings: Vec<Crossing>,
    /// The parameters in `[0, 1]` where `C'(t) = 0` (cusps, typically): the roots of
    /// `gcd(x' w - x w', y' w - y w')`, isolated. They are diagonal solutions, not crossings.
    pub stationary: Vec<RootInterval>,
    /// `Res_s(F, G)`, whose roots in `[0, 1]` are the candidate parameters.
    pub resultant: UPoly,
    /// The number of candidate pairs `(rho_i, rho_j)`, `i < j`, excluded (no crossing).
    pub excluded_pairs: usize,
}

/// Why [`self_intersections`] gave no answer.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PlanarError {
    /// The weight vanishes on `[0, 1]` (the precondition), at the root isolated here.
    #[error("the weight w vanishes on [0, 1] (at a root in {0})")]
    WeightVanishes(RootInterval),
    /// The weight is the zero polynomial.
    #[error("the weight w is the zero polynomial")]
    ZeroWeight,
    /// `Res_s(F, G)` vanishes identically: `F` and `G` share a factor (the curve is a point or
    /// lies on a line, or its parametrization is not proper); the solution set may be a curve.
    #[error(
        "the self-intersection equations share a factor (the curve lies on a line, is a point, or \
         its parametrization is not proper): not decided"
    )]
    CommonComponent,
    /// The budget ran out on a candidate pair that was neither excluded nor certified (a
    /// tangential self-contact or a singular point, or just too little budget).
    #[error(
        "undecided: the candidate box s in {s}, t in {t} was neither excluded nor certified after \
         {bisections} bisections (tangential self-contact or singular point?)"
    )]
    Undecided {
        /// The last interval of `s` (boxed to keep the error small).
        s: Box<RootInterval>,
        /// The last interval of `t`.
        t: Box<RootInterval>,
        /// The bisections spent.
        bisections: u32,
    },
}

/// All self-intersections of `C = (x / w, y / w)` on `[0, 1]` (see the module documentation).
///
/// # Errors
/// [`PlanarError::ZeroWeight`] / [`PlanarError::WeightVanishes`] when the precondition
/// `w != 0` on `[0, 1]` fails; [`PlanarError::CommonComponent`] when the equations are
/// degenerate; [`PlanarError::Undecided`] when the budget runs out.
///
/// ```
/// use exactcheck_exact::planar::{self_intersections, Budget};
/// use exactcheck_exact::univariate::UPoly;
/// use exactcheck_exact::Rational;
/// // The nodal cubic (t^2 - 1, t^3 - t) with t = 4u - 2: the node is at u = 1/4 and u = 3/4.
/// let t = UPoly::from_i64_coeffs(&[-2, 4]);
/// let x = UPoly::from_i64_coeffs(&[-1, 0, 1]).compose(&t);
/// let y = UPoly::from_i64_coeffs(&[0, -1, 0, 1]).compose(&t);
/// let found = self_intersections(&x, &y, &UPoly::one(), Budget::default()).unwrap();
/// assert_eq!(found.crossings.len(), 1);
/// let c = &found.crossings[0];
/// assert_eq!(c.s_interval.exact_value(), Some(&Rational::new(1, 4).unwrap()));
/// assert_eq!(c.t_interval.exact_value(), Some(&Rational::new(3, 4).unwrap()));
/// ```
pub fn self_intersections(
    x: &UPoly,
    y: &UPoly,
    w: &UPoly,
    budget: Budget,
) -> Result<SelfIntersections, PlanarError> {
    if w.is_zero() {
        return Err(PlanarError::ZeroWeight);
    }
    if let Some(root) = unit_roots(w).into_iter().next() {
        return Err(PlanarError::WeightVanishes(root));
    }
    // A common factor of x, y, w does not change the curve on [0, 1] (it does not vanish there,
    // since w does not) but would be a common factor of F and G: divide it out.
    let common = x.gcd(w).gcd(y);
    let (x, y, w) = if common.is_constant() {
        (x.clone(), y.clone(), w.clone())
    } else {
        let exact = |p: &UPoly| {
            let (quotient, rest) = p.div_rem(&common);
            debug_assert!(rest.is_zero(), "the gcd divides");
            quotient
        };
        (exact(x), exact(y), exact(w))
    };
    let (x, y, w) = (&x, &y, &w);
    let f = Dense::divided_difference(x, w);
    let g = Dense::divided_difference(y, w);
    let resultant = resultant_s(&f, &g);
    if resultant.is_zero() {
        return Err(PlanarError::CommonComponent);
    }
    let (stationary_poly, stationary) = stationary_points(x, y, w);
    let candidates = candidate_polynomial(&resultant, w, &stationary_poly);
    let sqf = candidates.primitive_square_free_part();
    let roots = unit_roots(&sqf);
    let w_free = w.square_free_part();
    let mut search = Search {
        f,
        g,
        w_roots: w_free.isolate_roots(),
        w_free,
        sqf,
        roots,
    };
    let m = search.roots.len();
    let mut found = Vec::new();
    let mut excluded_pairs = 0;
    for i in 0..m {
        for j in i + 1..m {
            match search.decide(i, j, budget)? {
                Some(certificate) => found.push((i, j, certificate)),
                None => excluded_pairs += 1,
            }
        }
    }
    let precision = Rational::new(1, 1 << 62).expect("not zero") * Rational::new(1, 4).expect("4");
    let crossings = found
        .into_iter()
        .map(|(i, j, certificate)| {
            let s_interval = search.narrow(i, &precision);
            let t_interval = search.narrow(j, &precision);
            let s_mid = s_interval.midpoint();
            let wm = w.eval(&s_mid);
            let point = [
                (x.eval(&s_mid) / &wm).to_f64(),
                (y.eval(&s_mid) / &wm).to_f64(),
            ];
            Crossing {
                s: s_mid.to_f64(),
                t: t_interval.midpoint().to_f64(),
                s_interval,
                t_interval,
                certificate,
                point,
            }
        })
        .collect();
    Ok(SelfIntersections {
        crossings,
        stationary,
        resultant,
        excluded_pairs,
    })
}

/// [`self_intersections`] of the curve with homogeneous coordinates `[W, WX, WY]` in Bernstein
/// form on `[0, 1]` (the first three of [`RationalBezierCurve::hom_coordinates`]).
///
/// # Errors
/// As [`self_intersections`].
pub fn self_intersections_hom(
    hom: &[Bernstein<Rational>; 3],
    budget: Budget,
) -> Result<SelfIntersections, PlanarError> {
    let [w, x, y] = hom.each_ref().map(UPoly::from_bernstein);
    self_intersections(&x, &y, &w, budget)
}

/// [`self_intersections`] of the projection of a rational Bezier curve onto the `xy`-plane (the
/// curve itself when it lies in a plane `z = const`, as the offsets of
/// `exactcheck_core::ph::PhCurve::offset` do).
///
/// # Errors
/// As [`self_intersections`].
pub fn self_intersections_xy(
    curve: &RationalBezierCurve<Rational>,
    budget: Budget,
) -> Result<SelfIntersections, PlanarError> {
    let [w, x, y, _] = curve.hom_coordinates();
    self_intersections_hom(&[w, x, y], budget)
}

/// `S = gcd(x' w - x w', y' w - y w')` (primitive) and its roots in `[0, 1]`: where
/// `(x/w, y/w)' = 0`.
fn stationary_points(x: &UPoly, y: &UPoly, w: &UPoly) -> (UPoly, Vec<RootInterval>) {
    let wd = w.derivative();
    let fx = x.derivative() * w.clone() - x.clone() * wd.clone();
    let fy = y.derivative() * w.clone() - y.clone() * wd;
    let g = fx.gcd(&fy);
    assert!(
        !g.is_zero(),
        "a constant curve is rejected as a common component first"
    );
    let roots = unit_roots(&g);
    (g.primitive_part(), roots)
}

/// `P = R / (w^a S^b) * S` with `a`, `b` as large as the divisions are exact (`S` from
/// [`stationary_points`]; the factor `S` put back once when `S` is not constant).
///
/// `R` is in practice far from square-free: a root `t0` of `w` (a point of the curve at
/// infinity) makes `F(., t0)` and `G(., t0)` both multiples of `w(s) / (s - t0)`, and a zero of
/// `C'` is a multiple root of `R`, so `R = A w^a S^b` with large `a`, `b` (for the offsets of
/// cubic PH curves, `deg R = 20` with `w^4` and `S^2`; of quintic ones 88, with `w^9` and
/// `S^2`). Dividing them out before the root isolation, whose cost grows steeply with the
/// degree, makes the isolation several times faster. Nothing is lost in `[0, 1]`: `w` has no
/// root there, and the roots of `S` are kept. The roots of `w` outside `[0, 1]` are still roots
/// of `R`, which the Poincare-Miranda step accounts for ([`Search::isolates_one`]).
fn candidate_polynomial(resultant: &UPoly, w: &UPoly, stationary: &UPoly) -> UPoly {
    let mut p = resultant.clone();
    for d in [w, stationary] {
        if d.is_constant() {
            continue;
        }
        loop {
            let (quotient, rest) = p.div_rem(d);
            if !rest.is_zero() {
                break;
            }
            p = quotient;
        }
    }
    if stationary.is_constant() {
        p
    } else {
        p * stationary.clone()
    }
}

/// The distinct roots of the non-zero `p` in `[0, 1]`, increasing, isolated with the
/// [`RootInterval`] contract and exact exactly when rational ([`isolate_real_roots_in`]).
fn unit_roots(p: &UPoly) -> Vec<RootInterval> {
    isolate_real_roots_in(p, &Rational::ZERO, &Rational::ONE)
}

/// Whether the square-free `p` has exactly one root in `[lo, hi]`, none at the ends: both ends
/// are not roots and Descartes' bound ([`descartes_bound`]) is 1.
fn descartes_one(p: &UPoly, lo: &Rational, hi: &Rational) -> bool {
    p.sign_at(lo) != Sign::Zero && p.sign_at(hi) != Sign::Zero && descartes_bound(p, lo, hi) == 1
}

// ------------------------------------------------------------------------------ dense bivariate

/// A dense polynomial in `s, t` over Q: `c[i][j]` is the coefficient of `s^i t^j`; every row
/// has the same length.
#[derive(Clone, Debug, PartialEq)]
struct Dense {
    c: Vec<Vec<Rational>>,
}

impl Dense {
    fn zero(ds: usize, dt: usize) -> Dense {
        Dense {
            c: vec![vec![Rational::ZERO; dt + 1]; ds + 1],
        }
    }

    /// `(p(s) w(t) - p(t) w(s)) / (s - t)` (module documentation).
    fn divided_difference(p: &UPoly, w: &UPoly) -> Dense {
        let d = p.degree().max(w.degree());
        let mut out = Dense::zero(d.saturating_sub(1), d.saturating_sub(1));
        for i in 0..=d {
            for j in 0..i {
                // The coefficient of s^i t^j - s^j t^i in p(s) w(t) - p(t) w(s).
                let a = p.coeff(i) * w.coeff(j) - p.coeff(j) * w.coeff(i);
                if a.is_zero() {
                    continue;
                }
                for k in 0..i - j {
                    out.c[j + k][j + (i - j - 1 - k)] += &a;
                }
            }
        }
        out.trim()
    }

    /// Drops zero rows and columns at the top ends (keeping at least one of each).
    fn trim(mut self) -> Dense {
        while self.c.len() > 1
            && self
                .c
                .last()
                .is_some_and(|r| r.iter().all(Rational::is_zero))
        {
            self.c.pop();
        }
        let cols = (0..self.c[0].len())
            .rev()
            .find(|&j| self.c.iter().any(|r| !r[j].is_zero()))
            .map_or(1, |j| j + 1);
        for r in &mut self.c {
            r.truncate(cols);
        }
        self
    }

    fn is_zero(&self) -> bool {
        self.c.iter().flatten().all(Rational::is_zero)
    }

    fn deg_s(&self) -> usize {
        self.c.len() - 1
    }

    fn deg_t(&self) -> usize {
        self.c[0].len() - 1
    }

    /// The coefficients in `s` (of `s^0, s^1, ...`) at `t = t0`.
    fn at_t(&self, t0: &Rational) -> Vec<Rational> {
        self.c.iter().map(|row| horner(row, t0)).collect()
    }

    /// The univariate polynomial `p(s0, t)` in `t`.
    fn at_s(&self, s0: &Rational) -> UPoly {
        let mut acc = vec![Rational::ZERO; self.deg_t() + 1];
        for row in self.c.iter().rev() {
            for (a, r) in acc.iter_mut().zip(row) {
                *a = a.mul_ref(s0) + r;
            }
        }
        UPoly::from_coeffs(acc)
    }

    /// `p(s0, t0)`.
    fn eval(&self, s0: &Rational, t0: &Rational) -> Rational {
        horner(&self.at_t(t0), s0)
    }

    /// `(c, c p)` with `c > 0` the least common multiple of the denominators, so that `c p` has
    /// integer coefficients (returned as integers).
    fn to_integer(&self) -> (Rational, Vec<Vec<BigInt>>) {
        let lcm = self
            .c
            .iter()
            .flatten()
            .fold(BigInt::one(), |acc, a| acc.lcm(&a.denom()));
        let c = Rational::from(lcm);
        let rows = self
            .c
            .iter()
            .map(|row| {
                row.iter()
                    .map(|a| {
                        let v = a.mul_ref(&c);
                        debug_assert!(v.is_integer());
                        v.numer()
                    })
                    .collect()
            })
            .collect();
        (c, rows)
    }

    /// `(dp/ds, dp/dt)` at `(s0, t0)`.
    fn gradient(&self, s0: &Rational, t0: &Rational) -> [Rational; 2] {
        let in_s = self.at_t(t0);
        let ds: Vec<Rational> = in_s
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, a)| a.mul_ref(&Rational::from_integer(i as i64)))
            .collect();
        let in_t = self.at_s(s0).derivative();
        [horner(&ds, s0), in_t.eval(t0)]
    }

    /// `a p + b q` (same shapes or not).
    fn combine(a: &Rational, p: &Dense, b: &Rational, q: &Dense) -> Dense {
        let ds = p.deg_s().max(q.deg_s());
        let dt = p.deg_t().max(q.deg_t());
        let mut out = Dense::zero(ds, dt);
        for (k, src) in [(a, p), (b, q)] {
            for (i, row) in src.c.iter().enumerate() {
                for (j, v) in row.iter().enumerate() {
                    out.c[i][j] += &k.mul_ref(v);
                }
            }
        }
        out
    }

    /// The strict sign of all tensor Bernstein coefficients on `[s0, s1] x [t0, t1]`, if they
    /// share one (then `p` has that sign on the whole closed box).
    fn box_sign(&self, s: (&Rational, &Rational), t: (&Rational, &Rational)) -> Option<Sign> {
        let (ds, dt) = (self.deg_s(), self.deg_t());
        let affine =
            |lo: &Rational, hi: &Rational| UPoly::from_coeffs(vec![lo.clone(), hi.sub_ref(lo)]);
        let (ms, mt) = (affine(s.0, s.1), affine(t.0, t.1));
        // Rows in s, each a polynomial in t mapped to the unit variable v, in power form.
        let rows: Vec<Vec<Rational>> = self
            .c
            .iter()
            .map(|row| padded(&UPoly::from_coeffs(row.clone()).compose(&mt), dt))
            .collect();
        // For each power of v, the polynomial in s mapped to u, in Bernstein form.
        let cols: Vec<Vec<Rational>> = (0..=dt)
            .map(|l| {
                let col = UPoly::from_coeffs(rows.iter().map(|r| r[l].clone()).collect());
                bernstein(&padded(&col.compose(&ms), ds))
            })
            .collect();
        // For each Bernstein index in u, the polynomial in v, in Bernstein form.
        let mut coeffs = Vec::with_capacity((ds + 1) * (dt + 1));
        for k in 0..=ds {
            let power: Vec<Rational> = cols.iter().map(|c| c[k].clone()).collect();
            coeffs.extend(bernstein(&power));
        }
        strict_sign(&coeffs)
    }
}

fn horner(coeffs: &[Rational], x: &Rational) -> Rational {
    coeffs
        .iter()
        .rev()
        .fold(Rational::ZERO, |acc, a| acc.mul_ref(x) + a)
}

/// The power coefficients of `p`, padded with zeros to `d + 1` entries.
fn padded(p: &UPoly, d: usize) -> Vec<Rational> {
    let mut v = p.coeffs().to_vec();
    debug_assert!(v.len() <= d + 1, "degree does not grow under affine maps");
    v.resize(d + 1, Rational::ZERO);
    v
}

/// Power coefficients (at least one) to Bernstein coefficients on `[0, 1]` of the same degree.
fn bernstein(power: &[Rational]) -> Vec<Rational> {
    Bernstein::from_power(power)
        .expect("at least one coefficient")
        .into_coeffs()
}

fn strict_sign(coeffs: &[Rational]) -> Option<Sign> {
    let first = coeffs.first()?.signum();
    (first != Sign::Zero && coeffs.iter().all(|c| c.signum() == first)).then_some(first)
}

/// The strict sign of the univariate `p` on `[lo, hi]` by its Bernstein coefficients there.
fn edge_sign(p: &UPoly, lo: &Rational, hi: &Rational) -> Option<Sign> {
    let mapped = p.compose(&UPoly::from_coeffs(vec![lo.clone(), hi.sub_ref(lo)]));
    strict_sign(&bernstein(&padded(&mapped, p.degree())))
}

// ------------------------------------------------------------------------------ resultant

// ------------------------------------------------------------------------------ the search

/// The state of the pair-by-pair decision: the equations, the square-free part of the
/// resultant, and the current isolating intervals of its roots in
/// `[0, 1]` (shared by all pairs, so a bisection made for one pair helps the others).
struct Search {
    f: Dense,
    g: Dense,
    /// The square-free part of `w` and its real roots, isolated once (roots of `w` are roots of
    /// `R` that [`candidate_polynomial`] removed).
    w_free: UPoly,
    w_roots: Vec<RootInterval>,
    sqf: UPoly,
    roots: Vec<RootInterval>,
}

impl Search {
    /// Decides the pair `(rho_i, rho_j)`, `i < j`: `Some(certificate)` for a crossing, `None`
    /// when excluded.
    fn decide(
        &mut self,
        i: usize,
        j: usize,
        budget: Budget,
    ) -> Result<Option<Certificate>, PlanarError> {
        let mut bisections = 0;
        loop {
            // A bisection may hit a root exactly; the exact cases need no budget.
            match (self.roots[i].is_exact(), self.roots[j].is_exact()) {
                (true, true) => {
                    let (s, t) = (&self.roots[i].lo, &self.roots[j].lo);
                    let zero = self.f.eval(s, t).is_zero() && self.g.eval(s, t).is_zero();
                    return Ok(zero.then_some(Certificate::Exact));
                }
                (true, false) => return self.one_rational(i, j),
                (false, true) => return self.one_rational(j, i),
                (false, false) => {}
            }
            let (si, tj) = (&self.roots[i], &self.roots[j]);
            let excluded = [&self.f, &self.g]
                .iter()
                .any(|p| p.box_sign((&si.lo, &si.hi), (&tj.lo, &tj.hi)).is_some());
            if excluded {
                return Ok(None);
            }
            if self.miranda(i, j) {
                return Ok(Some(Certificate::PoincareMiranda));
            }
            if bisections == budget.max_bisections {
                return Err(PlanarError::Undecided {
                    s: Box::new(si.clone()),
                    t: Box::new(tj.clone()),
                    bisections,
                });
            }
            self.bisect(i);
            self.bisect(j);
            bisections += 1;
        }
    }

    /// The pair with `rho_a` rational: a crossing iff the gcd of `F(rho_a, .)` and
    /// `G(rho_a, .)` has a root in `I_b` (module documentation; `F`, `G` are symmetric, so
    /// the order of the pair does not matter).
    fn one_rational(&self, a: usize, b: usize) -> Result<Option<Certificate>, PlanarError> {
        let s0 = &self.roots[a].lo;
        let h = self.f.at_s(s0).gcd(&self.g.at_s(s0));
        if h.is_zero() {
            // s - s0 divides F and G, so R = 0, which was ruled out; report rather than panic.
            return Err(PlanarError::CommonComponent);
        }
        let ib = &self.roots[b];
        let crossing = h.count_roots(&ib.lo, &ib.hi) > 0;
        Ok(crossing.then_some(Certificate::RationalParameter))
    }

    /// Poincare-Miranda on the box around `I_i x I_j` (module documentation).
    fn miranda(&self, i: usize, j: usize) -> bool {
        let widen = |r: &RootInterval| {
            let (c, d) = (r.midpoint(), r.width());
            (c.sub_ref(&d), c.add_ref(&d))
        };
        let (ps, pt) = (widen(&self.roots[i]), widen(&self.roots[j]));
        let (cs, ct) = (self.roots[i].midpoint(), self.roots[j].midpoint());
        let [fs, ft] = self.f.gradient(&cs, &ct);
        let [gs, gt] = self.g.gradient(&cs, &ct);
        let det = fs.mul_ref(&gt) - ft.mul_ref(&gs);
        let Ok(inv) = det.inv() else {
            return false;
        };
        // A = J^{-1} = [[gt, -ft], [-gs, fs]] / det.
        let h1 = Dense::combine(&(gt * &inv), &self.f, &-(ft * &inv), &self.g);
        let h2 = Dense::combine(&-(gs * &inv), &self.f, &(fs * &inv), &self.g);
        let opposite = |a: Option<Sign>, b: Option<Sign>| {
            matches!(
                (a, b),
                (Some(Sign::Negative), Some(Sign::Positive))
                    | (Some(Sign::Positive), Some(Sign::Negative))
            )
        };
        // H1 on the sides s = ps.0 and s = ps.1 (as polynomials in t over pt).
        let left = edge_sign(&h1.at_s(&ps.0), &pt.0, &pt.1);
        let right = edge_sign(&h1.at_s(&ps.1), &pt.0, &pt.1);
        if !opposite(left, right) {
            return false;
        }
        // H2 on the sides t = pt.0 and t = pt.1: by symmetry of the roles, restrict the
        // transposed polynomial.
        let h2t = h2.transpose();
        let bottom = edge_sign(&h2t.at_s(&pt.0), &ps.0, &ps.1);
        let top = edge_sign(&h2t.at_s(&pt.1), &ps.0, &ps.1);
        // Last, as the most expensive test (a root count of the candidate polynomial, of high
        // degree): no root of R in the sides of P but rho_i and rho_j.
        opposite(bottom, top) && self.isolates_one(&ps) && self.isolates_one(&pt)
    }

    /// Whether the closed interval `[lo, hi]` holds exactly one root of `R` and its ends none:
    /// one root of the candidate polynomial, no root of `w` (module documentation).
    fn isolates_one(&self, (lo, hi): &(Rational, Rational)) -> bool {
        // No root of `w` in `[lo, hi]`: neither end is one, and every isolated root lies below
        // `lo` or above `hi` (the square-free `w_free` changes sign across each of its roots).
        let w_free_in = || {
            let w = &self.w_free;
            w.sign_at(lo) != Sign::Zero
                && w.sign_at(hi) != Sign::Zero
                && self.w_roots.iter().all(|r| {
                    compare_simple(w, r, lo) == Ordering::Greater
                        || compare_simple(w, r, hi) == Ordering::Less
                })
        };
        descartes_one(&self.sqf, lo, hi) && (self.w_free.is_constant() || w_free_in())
    }

    /// Halves the interval of root `k` (exact when the midpoint is the root).
    fn bisect(&mut self, k: usize) {
        let r = &self.roots[k];
        if r.is_exact() {
            return;
        }
        let m = r.midpoint();
        let sm = self.sqf.sign_at(&m);
        self.roots[k] = if sm == Sign::Zero {
            RootInterval::exact(m)
        } else if sm == self.sqf.sign_at(&r.lo) {
            RootInterval {
                lo: m,
                hi: r.hi.clone(),
            }
        } else {
            RootInterval {
                lo: r.lo.clone(),
                hi: m,
            }
        };
    }

    /// Bisects root `k` until its interval is at most `width` wide; returns it.
    fn narrow(&mut self, k: usize, width: &Rational) -> RootInterval {
        while self.roots[k].width() > *width {
            self.bisect(k);
        }
        self.roots[k].clone()
    }
}

impl Dense {
    fn transpose(&self) -> Dense {
        let (ds, dt) = (self.deg_s(), self.deg_t());
        let mut out = Dense::zero(dt, ds);
        for (i, row) in self.c.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                out.c[j][i] = v.clone();
            }
        }
        out
    }
}
