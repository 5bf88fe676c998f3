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
//! quintic PH curves, 88 to 44). The distinct roots `rho_1 < ... < rho_m` in `[0, 1]` are then
//! isolated by bisection of `[0, 1]`, each by a rational interval `I_k` (open, ends not roots)
//! or exactly when a bisection point hits it. The bisection is driven by Descartes' rule of
//! signs when the candidate polynomial is certified square-free modulo a prime (the usual case,
//! no remainder sequence needed), else by Sturm sequences of its square-free part
//! (`isolate_candidates` explains the certificate).
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
//!     (Descartes or Sturm, as for the isolation) that each side of `P` holds no root of `R`
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

use crate::univariate::{sign_variations, RootInterval, UPoly};
use crate::{ModP, Rational};
use exactcheck_core::bernstein::Bernstein;
use exactcheck_core::bezier::RationalBezierCurve;
use exactcheck_core::{Field, Ring, Sign};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

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
    if let Some(root) = unit_roots_exact(w).into_iter().next() {
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
    let (sqf, counter, roots) = isolate_candidates(&candidates);
    let w_free = w.square_free_part();
    let mut search = Search {
        f,
        g,
        w_sturm: w_free.sturm_sequence(),
        w_free,
        counter,
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
    let roots = unit_roots_exact(&g);
    (g.primitive_part(), roots)
}

/// `P = R / (w^a S^b) * S` with `a`, `b` as large as the divisions are exact (`S` from
/// [`stationary_points`]; the factor `S` put back once when `S` is not constant).
///
/// `R` is in practice far from square-free: a root `t0` of `w` (a point of the curve at
/// infinity) makes `F(., t0)` and `G(., t0)` both multiples of `w(s) / (s - t0)`, and a zero of
/// `C'` is a multiple root of `R`, so `R = A w^a S^b` with large `a`, `b` (for the offsets of
/// cubic PH curves, `deg R = 20` with `w^4` and `S^2`; of quintic ones 88, with `w^9` and
/// `S^2`). Dividing them out before the Sturm sequence, whose cost grows steeply with the
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

/// How root counts of the square-free candidate polynomial are certified.
enum Counter {
    /// By its Sturm sequence.
    Sturm(Vec<UPoly>),
    /// By Descartes' rule of signs on its Bernstein coefficients over the interval.
    Descartes,
}

/// The square-free part of the candidate polynomial `p`, how to count its roots, and its roots
/// in `[0, 1]`.
///
/// The usual case is a square-free `p`, which is certified cheaply modulo the prime
/// `2^61 - 1`: if the prime divides neither a denominator nor the leading coefficient, then
/// `deg gcd(p, p') <= deg gcd(p mod q, p' mod q)`, so a constant gcd modulo the prime proves `p`
/// square-free over Q. Then the roots are isolated by bisection with Descartes' rule
/// ([`descartes_count`]) and counted the same way, with no Sturm sequence (whose remainder sequence dominated the run time for offsets of degree 13:
/// 30 of 40 seconds). Otherwise the square-free part comes from the primitive remainder sequence,
/// and roots are isolated and counted by Sturm sequences.
fn isolate_candidates(p: &UPoly) -> (UPoly, Counter, Vec<RootInterval>) {
    if p.is_constant() {
        return (p.clone(), Counter::Descartes, Vec::new());
    }
    if square_free_mod_prime(p) {
        let sqf = p.primitive_part();
        let roots = unit_roots_descartes(&sqf);
        return (sqf, Counter::Descartes, roots);
    }
    // The Sturm sequence of p ends in gcd(p, p').
    let chain = p.sturm_sequence();
    let repeated = chain.last().expect("p is not zero");
    let (sqf, sturm) = if repeated.is_constant() {
        (p.primitive_part(), chain)
    } else {
        let (quotient, rest) = p.div_rem(repeated);
        debug_assert!(rest.is_zero(), "gcd(p, p') divides p");
        let sqf = quotient.primitive_part();
        let sturm = sqf.sturm_sequence();
        (sqf, sturm)
    };
    let roots = unit_roots_sturm(&sqf, &sturm);
    (sqf, Counter::Sturm(sturm), roots)
}

/// Whether `p` (not constant) is certified square-free by a constant `gcd(p, p')` modulo
/// `2^61 - 1` (see [`isolate_candidates`]); `false` also when the prime is unlucky.
fn square_free_mod_prime(p: &UPoly) -> bool {
    let Ok(mut a) = p
        .coeffs()
        .iter()
        .map(ModP::from_rational)
        .collect::<Result<Vec<ModP>, _>>()
    else {
        return false;
    };
    if a.last().is_none_or(|lc| lc.is_zero()) {
        return false;
    }
    let mut b: Vec<ModP> = a
        .iter()
        .enumerate()
        .skip(1)
        .map(|(k, c)| *c * ModP::from_i64(k as i64))
        .collect();
    trim_mod(&mut b);
    // Euclid over the field of residues.
    while !b.is_empty() {
        let inv = b
            .last()
            .expect("not empty")
            .inv()
            .expect("trimmed: not zero");
        while a.len() >= b.len() {
            let factor = *a.last().expect("not shorter than b") * inv;
            let shift = a.len() - b.len();
            for (k, c) in b.iter().enumerate() {
                a[shift + k] -= factor * *c;
            }
            a.pop();
            trim_mod(&mut a);
            if a.len() < b.len() {
                break;
            }
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len() == 1
}

fn trim_mod(v: &mut Vec<ModP>) {
    while v.last().is_some_and(|c| c.is_zero()) {
        v.pop();
    }
}

/// Descartes' bound for the open interval `(lo, hi)`, `lo < hi`: the sign variations of the
/// coefficients of `(x + 1)^n p((lo x + hi) / (x + 1))` (the same, up to positive factors, as
/// the Bernstein coefficients of `p` on `[lo, hi]`, but computed by two compositions, with no
/// binomial coefficients, so for any degree). It bounds the number of roots in `(lo, hi)`
/// counted with multiplicity and has the same parity; 0 or 1 is exact.
fn descartes_count(p: &UPoly, lo: &Rational, hi: &Rational) -> usize {
    let n = p.degree();
    // Roots in (lo, hi) -> roots of q in (0, 1).
    let q = p.compose(&UPoly::from_coeffs(vec![lo.clone(), hi.sub_ref(lo)]));
    // y^n q(1/y): roots in (1, inf); then x = y - 1: roots in (0, inf).
    let mut reversed = padded(&q, n);
    reversed.reverse();
    let shifted = UPoly::from_coeffs(reversed).compose(&poly_x_plus_one());
    let signs: Vec<Sign> = shifted
        .coeffs()
        .iter()
        .map(Rational::signum)
        .filter(|s| *s != Sign::Zero)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

fn poly_x_plus_one() -> UPoly {
    UPoly::from_coeffs(vec![Rational::ONE, Rational::ONE])
}

/// Whether the square-free `p` has exactly one root in `[lo, hi]`, none at the ends
/// ([`descartes_count`]).
fn descartes_one(p: &UPoly, lo: &Rational, hi: &Rational) -> bool {
    p.sign_at(lo) != Sign::Zero && p.sign_at(hi) != Sign::Zero && descartes_count(p, lo, hi) == 1
}

/// The distinct roots in `[0, 1]` of the square-free, primitive (integer) `sqf`, increasing:
/// bisection driven by Descartes' rule (which reaches 0 or 1 on small enough intervals around
/// simple roots, so the bisection ends), a bisection point that is a root recorded exactly.
///
/// The classical integer form of the method (Collins-Akritas): the interval
/// `[c / 2^k, (c + 1) / 2^k]` carries an integer polynomial `q` with the roots of `sqf` there
/// mapped to `(0, 1)`; its halves carry `2^n q(x / 2)` and that shifted by 1, and Descartes'
/// bound is the sign variations of `(x + 1)^n q(1 / (x + 1))` (reversal, shift by 1). Only
/// integer additions and shifts, no rational normalisation: several times faster than
/// [`descartes_count`] on the high-degree candidate polynomials.
fn unit_roots_descartes(sqf: &UPoly) -> Vec<RootInterval> {
    let n = sqf.degree();
    let p: Vec<BigInt> = sqf
        .coeffs()
        .iter()
        .map(|c| {
            assert!(
                c.is_integer(),
                "a primitive polynomial has integer coefficients"
            );
            c.numer()
        })
        .collect();
    let dyadic = |c: &BigInt, k: u32| {
        Rational::from(c.clone()) * Rational::from(BigInt::one() << k).recip().expect("2^k")
    };
    let (zero, one) = (Rational::ZERO, Rational::ONE);
    let mut out: Vec<RootInterval> = [&zero, &one]
        .into_iter()
        .filter(|x| sqf.sign_at(x) == Sign::Zero)
        .map(|x| RootInterval::exact(x.clone()))
        .collect();
    let mut stack = vec![(BigInt::zero(), 0u32, p)];
    while let Some((c, k, q)) = stack.pop() {
        let mut rev = q.clone();
        rev.reverse();
        taylor_shift_one(&mut rev);
        let count = variations(&rev);
        if count == 0 {
            continue;
        }
        let ends_not_roots = !q[0].is_zero() && !q.iter().sum::<BigInt>().is_zero();
        if count == 1 && ends_not_roots {
            out.push(RootInterval {
                lo: dyadic(&c, k),
                hi: dyadic(&(&c + 1), k),
            });
            continue;
        }
        // 2^n q(x / 2), without the common power of two.
        let mut left: Vec<BigInt> = q.iter().enumerate().map(|(i, a)| a << (n - i)).collect();
        let twos = left
            .iter()
            .filter_map(BigInt::trailing_zeros)
            .min()
            .unwrap_or(0);
        for a in &mut left {
            *a >>= twos;
        }
        let mut right = left.clone();
        taylor_shift_one(&mut right);
        let mid = BigInt::from(2) * &c + 1;
        if right[0].is_zero() {
            out.push(RootInterval::exact(dyadic(&mid, k + 1)));
        }
        stack.push((mid, k + 1, right));
        stack.push((BigInt::from(2) * c, k + 1, left));
    }
    out.sort_by(|x, y| x.lo.cmp(&y.lo));
    out
}

/// `a(x) <- a(x + 1)` in place (coefficients from the constant term up).
fn taylor_shift_one(a: &mut [BigInt]) {
    let n = a.len();
    for i in 0..n.saturating_sub(1) {
        for j in (i..n - 1).rev() {
            let next = a[j + 1].clone();
            a[j] += next;
        }
    }
}

/// The sign variations of a coefficient sequence (zeros skipped).
fn variations(a: &[BigInt]) -> usize {
    let signs: Vec<bool> = a
        .iter()
        .filter(|c| !c.is_zero())
        .map(|c| c.sign() == num_bigint::Sign::Minus)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// The distinct roots in `[0, 1]` of the square-free `sqf` with the Sturm sequence `sturm`,
/// increasing: bisection of `[0, 1]` driven by Sturm counts (`V(a) - V(b)` distinct roots in
/// `(a, b]`), a bisection point that is a root recorded exactly (so roots are exact when a
/// dyadic bisection point or an end hits them, not whenever they are rational).
fn unit_roots_sturm(sqf: &UPoly, sturm: &[UPoly]) -> Vec<RootInterval> {
    let (zero, one) = (Rational::ZERO, Rational::ONE);
    if sqf.is_constant() {
        return Vec::new();
    }
    let is_root = |x: &Rational| sqf.sign_at(x) == Sign::Zero;
    let var = |x: &Rational| sign_variations(sturm, x);
    // The number of roots in the open interval (a, b).
    let open_count = |b: &Rational, va: usize, vb: usize| va - vb - usize::from(is_root(b));
    let mut out = Vec::new();
    if is_root(&zero) {
        out.push(RootInterval::exact(zero.clone()));
    }
    if is_root(&one) {
        out.push(RootInterval::exact(one.clone()));
    }
    let (v0, v1) = (var(&zero), var(&one));
    let count = open_count(&one, v0, v1);
    let mut stack = vec![(zero, one, v0, v1, count)];
    let half = Rational::new(1, 2).expect("2 is not zero");
    while let Some((a, b, va, vb, count)) = stack.pop() {
        if count == 0 {
            continue;
        }
        if count == 1 && !is_root(&a) && !is_root(&b) {
            out.push(RootInterval { lo: a, hi: b });
            continue;
        }
        let m = a.add_ref(&b) * &half;
        let vm = var(&m);
        if is_root(&m) {
            out.push(RootInterval::exact(m.clone()));
        }
        let right = open_count(&b, vm, vb);
        let left = open_count(&m, va, vm);
        stack.push((m.clone(), b, vm, vb, right));
        stack.push((a, m, va, vm, left));
    }
    out.sort_by(|x, y| x.lo.cmp(&y.lo));
    out
}

/// The distinct roots of the non-zero `p` in `[0, 1]`, increasing, isolated with the
/// [`RootInterval`] contract and exact **exactly when rational** ([`UPoly::isolate_roots`] on the
/// line, clipped to `[0, 1]`: an interval reaching past an end holds an irrational root, which
/// is compared with that end).
fn unit_roots_exact(p: &UPoly) -> Vec<RootInterval> {
    let (zero, one) = (Rational::ZERO, Rational::ONE);
    p.isolate_roots()
        .into_iter()
        .filter_map(|mut ri| {
            if ri.is_exact() {
                return (zero <= ri.lo && ri.lo <= one).then_some(ri);
            }
            if ri.hi <= zero || ri.lo >= one {
                return None;
            }
            if ri.lo < zero {
                // The root is irrational, so not 0: it is in [0, 1] iff 0 is below it.
                if p.compare_with_root(&ri, &zero) != std::cmp::Ordering::Less {
                    return None;
                }
                ri.lo = zero.clone();
            }
            if ri.hi > one {
                if p.compare_with_root(&ri, &one) != std::cmp::Ordering::Greater {
                    return None;
                }
                ri.hi = one.clone();
            }
            Some(ri)
        })
        .collect()
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
/// resultant with its Sturm sequence, and the current isolating intervals of its roots in
/// `[0, 1]` (shared by all pairs, so a bisection made for one pair helps the others).
struct Search {
    f: Dense,
    g: Dense,
    /// The square-free part of `w` and its Sturm sequence (roots of `w` are roots of `R` that
    /// [`candidate_polynomial`] removed).
    w_free: UPoly,
    w_sturm: Vec<UPoly>,
    sqf: UPoly,
    counter: Counter,
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
        let count = |p: &UPoly, chain: &[UPoly]| {
            (p.sign_at(lo) != Sign::Zero && p.sign_at(hi) != Sign::Zero)
                .then(|| sign_variations(chain, lo) - sign_variations(chain, hi))
        };
        let one = match &self.counter {
            Counter::Sturm(sturm) => count(&self.sqf, sturm) == Some(1),
            Counter::Descartes => descartes_one(&self.sqf, lo, hi),
        };
        one && (self.w_free.is_constant() || count(&self.w_free, &self.w_sturm) == Some(0))
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
