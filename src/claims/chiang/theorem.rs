//! `chiang.theorem`: the printed sums against the proof's substitution.
//!
//! **Symbolic, `m <= 4`, `n <= 6`.** Over `Q[p_jx..q_iz, a, b, c, d, t]` two independent
//! computations are compared:
//! 1. the theorem's sums, division-free: `H_k = sum_{i+j=k} C(m,i) C(n,j) (N.q_i, (N.q_i) p_j -
//!    (N.p_j + d) q_i)` (`RuledSurface::plane_section_scaled`, the printed `(w_k, w_k r_k)` times
//!    `C(m+n, k)`), against `RuledSurface::substitution`, the proof's numerator
//!    `(N.V) B - (N.B + d) V` and denominator `N.V` formed by Bernstein products (the product rule
//!    applied to the coefficient lists of `N.V`, `B`, `N.B + d`, `V`, never to the theorem's sums),
//!    coefficient by coefficient;
//! 2. as an identity in `t`: `sum_k H_k t^k (1-t)^(m+n-k)` (that is `sum_k w_k B_k^{m+n}(t)` and
//!    `sum_k w_k r_k B_k^{m+n}(t)`) against `N.V(t)` and `(N.V(t)) B(t) - (N.B(t) + d) V(t)` with
//!    `B(t)`, `V(t)` evaluated by de Casteljau's algorithm at the symbolic `t` — the proof's
//!    formula itself, with no Bernstein algebra at all.
//!
//! Both residuals expand to the zero polynomial: the theorem holds for every plane and every
//! surface of these degrees (the rational curve `H / w` is then `C(t)` wherever `N.V(t) != 0`).
//!
//! **Exact instances up to `(12, 20)`.** Random rational control points, vectors and planes;
//! the curve of `plane_section` evaluated at 20 rational parameters lies exactly on the plane and
//! equals `S(s(t), t)` with `s(t) = -(N.B(t) + d) / (N.V(t))` (`section_parameter`); a pole
//! (`N.V(t) = 0`) must be a pole of both.

use super::{symbolic_surface, Outcome, Verdict, P};
use crate::claims::engine::{Rng, Symbols};
use exactcheck_core::ruled::{Plane, RuledSurface};
use exactcheck_core::{Ring, Vec3};
use exactcheck_exact::Rational;
use rayon::prelude::*;
use std::time::Instant;

/// The symbolic range: every `m <= SYMBOLIC_MAX.0`, `n <= SYMBOLIC_MAX.1` (the theorem is stated
/// for every `m`, `n`; the evidence says which sizes the symbolic proof covers).
pub const SYMBOLIC_MAX: (usize, usize) = (4, 6);

/// The sizes `(m, n)` of the random exact instances (three each).
pub const RANDOM_SIZES: [(usize, usize); 8] = [
    (0, 3),
    (1, 2),
    (2, 5),
    (4, 6),
    (5, 8),
    (7, 11),
    (9, 16),
    (12, 20),
];

const INSTANCES_PER_SIZE: usize = 3;

/// What the symbolic check of one size measured.
#[derive(Clone, Debug)]
pub struct SizeReport {
    /// `(m, n)`.
    pub size: (usize, usize),
    /// `None` when both residuals are the zero polynomial, else the first non-zero one.
    pub failure: Option<String>,
    /// Terms of the theorem's sums (all `k`, the four homogeneous coordinates).
    pub sum_terms: usize,
    /// Terms of the sums expanded in `t` (`sum_k H_k t^k (1-t)^(m+n-k)`, four coordinates).
    pub t_terms: usize,
    /// Wall time of the check of this size, in milliseconds.
    pub millis: f64,
}

/// Checks the theorem symbolically for one `(m, n)` (module doc).
pub fn check_size(m: usize, n: usize) -> SizeReport {
    let start = Instant::now();
    let mut sym = Symbols::new(&["a", "b", "c", "d", "t"]);
    let surface = symbolic_surface(&mut sym, m, n);
    let v = |sym: &mut Symbols, name: &str| sym.vars.poly::<Rational>(name);
    let plane = Plane::new(
        v(&mut sym, "a"),
        v(&mut sym, "b"),
        v(&mut sym, "c"),
        v(&mut sym, "d"),
    );
    let t = v(&mut sym, "t");
    let sums = surface.plane_section_scaled(&plane);
    let substitution = surface.substitution(&plane);
    let sum_terms = sums
        .iter()
        .map(|h| h.0.iter().map(P::len).sum::<usize>())
        .sum();
    let coordinate = ["w", "w r_x", "w r_y", "w r_z"];
    let mut failure = None;
    'coefficients: for (k, h) in sums.iter().enumerate() {
        for (a, name) in coordinate.iter().enumerate() {
            let r = h.0[a].sub_ref(&substitution[a][k]);
            if !r.is_zero() {
                failure = Some(format!(
                    "(m, n) = ({m}, {n}), k = {k}: the sum for {name} minus the substitution's coefficient is {}",
                    r.display(&sym.vars)
                ));
                break 'coefficients;
            }
        }
    }
    // The identity in t.
    let one_minus_t = <P as Ring>::one().sub_ref(&t);
    let degree = m + n;
    let mut t_terms = 0;
    if failure.is_none() {
        let mut lhs = [P::zero(), P::zero(), P::zero(), P::zero()];
        for (k, h) in sums.iter().enumerate() {
            let basis = t
                .pow(k as u32)
                .mul_ref(&one_minus_t.pow((degree - k) as u32));
            for (a, slot) in lhs.iter_mut().enumerate() {
                *slot += &h.0[a].mul_ref(&basis);
            }
        }
        t_terms = lhs.iter().map(P::len).sum();
        let b = surface.base().eval(&t);
        let dir = surface.directions().eval(&t);
        let nv = plane.normal.dot(&dir);
        let offset = plane.value(&b);
        let numerator = b.scale(&nv).add_scaled(&offset.neg_ref(), &dir);
        let rhs = [nv, numerator.x, numerator.y, numerator.z];
        for (a, name) in coordinate.iter().enumerate() {
            let r = lhs[a].sub_ref(&rhs[a]);
            if !r.is_zero() {
                failure = Some(format!(
                    "(m, n) = ({m}, {n}): sum_k ({name})_k B_k(t) minus the substitution at symbolic t is {}",
                    r.display(&sym.vars)
                ));
                break;
            }
        }
    }
    SizeReport {
        size: (m, n),
        failure,
        sum_terms,
        t_terms,
        millis: start.elapsed().as_secs_f64() * 1000.0,
    }
}

/// What the random exact instances found.
struct InstanceReport {
    instances: usize,
    points: usize,
    poles: usize,
}

fn random_surface(rng: &mut Rng, m: usize, n: usize) -> (RuledSurface<Rational>, Plane<Rational>) {
    let point =
        |rng: &mut Rng| Vec3::new(rng.rational(9, 4), rng.rational(9, 4), rng.rational(9, 4));
    let base = (0..=n).map(|_| point(rng)).collect();
    let directions = (0..=m).map(|_| point(rng)).collect();
    let surface = RuledSurface::from_control(base, directions)
        .expect("n + 1 >= 1 points, m + 1 >= 1 vectors");
    let normal = loop {
        let v = Vec3::new(
            Rational::from_integer(rng.int(-5, 5)),
            Rational::from_integer(rng.int(-5, 5)),
            Rational::from_integer(rng.int(-5, 5)),
        );
        if !(v.x.is_zero() && v.y.is_zero() && v.z.is_zero()) {
            break v;
        }
    };
    let d = rng.rational(9, 4);
    (surface, Plane::new(normal.x, normal.y, normal.z, d))
}

/// The parameters: `i/17` for `i = 0..=17`, and `1/3`, `5/7`.
fn parameters() -> Vec<Rational> {
    let mut ts: Vec<Rational> = (0..=17)
        .map(|i| Rational::new(i, 17).expect("17 != 0"))
        .collect();
    ts.push(Rational::new(1, 3).expect("3 != 0"));
    ts.push(Rational::new(5, 7).expect("7 != 0"));
    ts
}

/// One drawn instance: `(m, n)`, its index among the instances of that size, surface and plane.
type Drawn = (usize, usize, usize, RuledSurface<Rational>, Plane<Rational>);

fn random_instances() -> Result<InstanceReport, String> {
    let mut rng = Rng::new(0x00C4_1A46);
    let ts = parameters();
    // Drawn in order from the one generator, checked in parallel, read in order (the first
    // failure in drawing order is the one reported).
    let drawn: Vec<Drawn> = RANDOM_SIZES
        .iter()
        .flat_map(|&(m, n)| (0..INSTANCES_PER_SIZE).map(move |i| (m, n, i)))
        .map(|(m, n, instance)| {
            let (surface, plane) = random_surface(&mut rng, m, n);
            (m, n, instance, surface, plane)
        })
        .collect();
    let counts: Vec<Result<(usize, usize), String>> = drawn
        .par_iter()
        .with_max_len(1)
        .map(|(m, n, instance, surface, plane)| {
            instance_points(*m, *n, *instance, surface, plane, &ts)
        })
        .collect();
    let mut report = InstanceReport {
        instances: 0,
        points: 0,
        poles: 0,
    };
    for c in counts {
        let (points, poles) = c?;
        report.points += points;
        report.poles += poles;
        report.instances += 1;
    }
    Ok(report)
}

/// One instance of [`random_instances`]: `(points, poles)` at the parameters `ts`, or the
/// failure.
fn instance_points(
    m: usize,
    n: usize,
    instance: usize,
    surface: &RuledSurface<Rational>,
    plane: &Plane<Rational>,
    ts: &[Rational],
) -> Result<(usize, usize), String> {
    let (mut points, mut poles) = (0, 0);
    let curve = surface.plane_section(plane);
    if curve.degree() != m + n {
        return Err(format!(
            "(m, n) = ({m}, {n}): the section has degree {}",
            curve.degree()
        ));
    }
    for t in ts {
        match (curve.eval(t), surface.section_parameter(plane, t)) {
            (Ok(x), Ok(s)) => {
                let on_plane = plane.value(&x);
                let on_surface = surface.eval(&s, t);
                if !on_plane.is_zero() || on_surface != x {
                    return Err(format!(
                        "(m, n) = ({m}, {n}), instance {instance}, t = {t}: the curve point {x:?} has plane value {on_plane} and the surface point there is {on_surface:?}"
                    ));
                }
                points += 1;
            }
            (Err(_), Err(_)) => poles += 1,
            (c, s) => {
                return Err(format!(
                    "(m, n) = ({m}, {n}), instance {instance}, t = {t}: the curve is {} there but the surface parameter is {}",
                    if c.is_ok() { "finite" } else { "at infinity" },
                    if s.is_ok() { "finite" } else { "undefined" }
                ))
            }
        }
    }
    Ok((points, poles))
}

fn size_text(r: &SizeReport) -> String {
    format!(
        "({}, {}): {} terms in the sums, {} terms in t, {:.1} ms",
        r.size.0, r.size.1, r.sum_terms, r.t_terms, r.millis
    )
}

/// The claim `chiang.theorem`.
pub fn check() -> Result<Outcome, String> {
    let method = format!(
        "symbolic expansion over Q[p_j, q_i, a, b, c, d, t] for m <= {}, n <= {} (sums vs Bernstein-product substitution, and the identity in t against de Casteljau at symbolic t); exact rational instances up to {:?}",
        SYMBOLIC_MAX.0,
        SYMBOLIC_MAX.1,
        RANDOM_SIZES[RANDOM_SIZES.len() - 1]
    );
    // The sizes are independent: checked in parallel (the next size and the exact instances
    // alongside), then read in order, so the first failure reported is the first in (m, n)
    // order whatever the number of threads.
    let sizes: Vec<(usize, usize)> = (0..=SYMBOLIC_MAX.0)
        .flat_map(|m| (0..=SYMBOLIC_MAX.1).map(move |n| (m, n)))
        .collect();
    let ((reports, symbolic_ms), (next, instances)) = rayon::join(
        || {
            let start = Instant::now();
            let reports: Vec<SizeReport> = sizes
                .par_iter()
                .with_max_len(1)
                .map(|&(m, n)| check_size(m, n))
                .collect();
            (reports, start.elapsed().as_secs_f64() * 1000.0)
        },
        || {
            rayon::join(
                || check_size(SYMBOLIC_MAX.0 + 1, SYMBOLIC_MAX.1 + 1),
                random_instances,
            )
        },
    );
    let mut last = None;
    let mut sizes = 0;
    // The largest m and n the symbolic pass expanded (the range actually run).
    let mut covered = (0, 0);
    for r in reports {
        if let Some(f) = r.failure {
            return Ok(Outcome {
                verdict: Verdict::Fails,
                method: method.clone(),
                evidence: f,
                erratum: None,
            });
        }
        sizes += 1;
        covered = (covered.0.max(r.size.0), covered.1.max(r.size.1));
        last = Some(r);
    }
    let last = last.expect("at least one size");
    if let Some(f) = next.failure {
        return Ok(Outcome {
            verdict: Verdict::Fails,
            method: method.clone(),
            evidence: f,
            erratum: None,
        });
    }
    // The two sizes the evidence compares are timed again, one after the other on this thread:
    // in the parallel pass above each ran beside other sizes, so their time ratio mixed in
    // contention (9.3x was seen for a growth of about 1.7x). Both expanded to zero above; the
    // re-runs are the same deterministic expansions and are used for their times only.
    let last = check_size(last.size.0, last.size.1);
    let next = check_size(next.size.0, next.size.1);
    let instances = match instances {
        Ok(r) => r,
        Err(e) => {
            return Ok(Outcome {
                verdict: Verdict::Fails,
                method: method.clone(),
                evidence: e,
                erratum: None,
            })
        }
    };
    Ok(Outcome {
        verdict: Verdict::Proved,
        method,
        evidence: format!(
            "both residuals expand to 0 for all {sizes} sizes (m, n) with m <= {}, n <= {} ({symbolic_ms:.0} ms in all); at {}; the next size, {} (also 0), grows by {:.1}x in t-terms and {:.1}x in time. The symbolic proof covers m <= {}, n <= {} and ({}, {}) only; the theorem is stated for every m, n, and the other sizes are checked only on the exact instances below. Exact instances: {} random rational surfaces and planes at (m, n) in {:?}, {} parameters each: {} curve points exactly on the plane and equal to S(s(t), t), {} poles (N.V(t) = 0) at which curve and surface parameter are both undefined",
            covered.0,
            covered.1,
            size_text(&last),
            size_text(&next),
            next.t_terms as f64 / last.t_terms as f64,
            next.millis / last.millis,
            covered.0,
            covered.1,
            next.size.0,
            next.size.1,
            instances.instances,
            RANDOM_SIZES,
            parameters().len(),
            instances.points,
            instances.poles,
        ), erratum: None, })
}
