//! The workspace's real-root API for polynomials with rational coefficients.
//!
//! Every answer is a list of [`RootInterval`]s, increasing and pairwise disjoint, one per
//! **distinct** real root: a rational root is the exact point `[r, r]`, an irrational one an open
//! interval with rational ends that holds it and no other root (its ends are not roots), which
//! [`refine_real_root`] narrows to any width and [`sign_at_real_root`] uses to decide the sign of
//! another polynomial at the root.
//!
//! * [`isolate_real_roots`] is the production isolator: Descartes' rule of signs on the primitive
//!   square-free part (module `descartes`: Bernstein subdivision on integers, filtered by `f64`
//!   with a rigorous error bound, close pairs separated by Newton steps), then every interval
//!   that is not already exact is tested for a rational root (the rational root theorem on the
//!   narrowed interval), so an interval is exact **exactly when the root is rational**.
//! * [`isolate_real_roots_sturm`] is the reference: bisection driven by Sturm counts, with the
//!   same promise on rational roots. The tests compare the two. [`UPoly::isolate_roots`] gives
//!   the reference's intervals from the Descartes isolator's roots (module `isolate`).
//! * [`isolate_real_roots_in`] restricts either answer to a closed interval `[lo, hi]` (for
//!   example `[0, 1]`, the parameter range of Bezier curves): an interval reaching past an end
//!   holds an irrational root, which is compared with that end exactly.
//! * [`descartes_bound`] is the sign-variation bound on an interval, for callers that only need
//!   to certify that an interval holds exactly one root.
//!
//! Degrees above [`MAX_DESCARTES_DEGREE`] (where the integer subdivision would be far too slow)
//! are isolated by the Sturm path.

use super::descartes::{integer_real_roots_rational_exact, unit_descartes_bound};
use super::*;
use std::cmp::Ordering;

/// Isolating intervals of the distinct real roots of `p`, increasing (module documentation):
/// exact exactly when the root is rational. Empty for constants and for the zero polynomial.
pub fn isolate_real_roots(p: &UPoly) -> Vec<RootInterval> {
    if p.is_constant() {
        return Vec::new();
    }
    if p.degree() > MAX_DESCARTES_DEGREE {
        return isolate_real_roots_sturm(p);
    }
    integer_real_roots_rational_exact(&p.integer_coefficients()).expect("not the zero polynomial")
}

/// The reference isolator: bisection driven by Sturm counts (module `sturm`), with the same
/// contract as [`isolate_real_roots`] (the intervals themselves may differ) and the same
/// intervals as [`UPoly::isolate_roots`]. Production uses it only beyond
/// [`MAX_DESCARTES_DEGREE`].
pub fn isolate_real_roots_sturm(p: &UPoly) -> Vec<RootInterval> {
    if p.is_constant() {
        return Vec::new();
    }
    sturm::SquareFree::new(p).isolate()
}

/// The distinct real roots of `p` in the closed interval `[lo, hi]` (`lo <= hi`), increasing,
/// from [`isolate_real_roots`]: the exact roots in `[lo, hi]`, and the isolating intervals
/// clipped to `[lo, hi]` (an irrational root is never an end, so a clipped interval still
/// isolates it). Empty for constants and for the zero polynomial.
///
/// # Panics
/// When `lo > hi`.
pub fn isolate_real_roots_in(p: &UPoly, lo: &Rational, hi: &Rational) -> Vec<RootInterval> {
    assert!(lo <= hi, "isolate_real_roots_in: {lo} > {hi}");
    let roots = isolate_real_roots(p);
    clip_roots(p, roots, lo, hi)
}

/// The common real roots of `ps` in `[lo, hi]`: the roots of their gcd there
/// ([`isolate_real_roots_in`]), zero polynomials ignored. `None` when every polynomial is zero
/// (every point is a common root).
///
/// # Panics
/// When `lo > hi`.
pub fn common_real_roots_in(
    ps: &[UPoly],
    lo: &Rational,
    hi: &Rational,
) -> Option<Vec<RootInterval>> {
    let mut nonzero = ps.iter().filter(|p| !p.is_zero());
    let first = nonzero.next()?.clone();
    let g = nonzero.fold(first, |g, p| g.gcd(p));
    Some(isolate_real_roots_in(&g, lo, hi))
}

/// [`isolate_real_roots_in`] on the Sturm path ([`isolate_real_roots_sturm`]), the reference
/// of the tests.
///
/// # Panics
/// When `lo > hi`.
pub fn isolate_real_roots_sturm_in(p: &UPoly, lo: &Rational, hi: &Rational) -> Vec<RootInterval> {
    assert!(lo <= hi, "isolate_real_roots_sturm_in: {lo} > {hi}");
    let roots = isolate_real_roots_sturm(p);
    clip_roots(p, roots, lo, hi)
}

/// The roots among `roots` (isolating intervals of `p`, exact exactly for rational roots) that
/// lie in `[lo, hi]`, clipped to it.
fn clip_roots(
    p: &UPoly,
    roots: Vec<RootInterval>,
    lo: &Rational,
    hi: &Rational,
) -> Vec<RootInterval> {
    if roots.is_empty() {
        return roots;
    }
    let sqf = p.square_free_part();
    // `x` compared with the irrational root isolated by `ri` (`x` strictly inside it): the
    // square-free part changes sign across the root only.
    let below_root = |ri: &RootInterval, x: &Rational| sqf.sign_at(x) == sqf.sign_at(&ri.lo);
    roots
        .into_iter()
        .filter_map(|mut ri| {
            if ri.is_exact() {
                return (*lo <= ri.lo && ri.lo <= *hi).then_some(ri);
            }
            if ri.hi <= *lo || ri.lo >= *hi {
                return None;
            }
            if ri.lo < *lo {
                if !below_root(&ri, lo) {
                    return None;
                }
                ri.lo = lo.clone();
            }
            if ri.hi > *hi {
                if below_root(&ri, hi) {
                    return None;
                }
                ri.hi = hi.clone();
            }
            Some(ri)
        })
        .collect()
}

/// A refinement of `root` (an isolating interval of a root of `p`, as returned above) to width
/// at most `width`, holding the same root: [`UPoly::refine`] (quadratic interval refinement on
/// the sign of the square-free part).
///
/// # Panics
/// As [`UPoly::refine`]: when `root` is not exact and does not isolate a root of `p`, or when
/// `width <= 0`.
pub fn refine_real_root(p: &UPoly, root: &RootInterval, width: &Rational) -> RootInterval {
    p.refine(root, width)
}

/// The sign of `q` at the root of `p` isolated by `root` (as returned above), decided exactly:
/// an exact root is substituted; otherwise `q` vanishes at the root exactly when
/// `gcd(p, q)` changes sign across `root` (the gcd's square-free part has the root as a simple
/// root), and else `root` is halved (quadratic refinement on the primitive square-free part of
/// `p`) until Descartes' bound of `q` on it is 0 and `q` does not vanish at its lower end, where
/// the sign of `q` at the midpoint is the answer. The loop ends: `q` has no root at the root of
/// `p`, so once the interval is narrow enough the disc on it holds no complex root of `q` and
/// the bound is 0 (the one-circle theorem, see `exactcheck_core::roots`).
///
/// # Panics
/// When `p` is zero, or `root` is not exact and does not isolate a root of `p`.
pub fn sign_at_real_root(q: &UPoly, p: &UPoly, root: &RootInterval) -> Sign {
    if let Some(r) = root.exact_value() {
        return q.sign_at(r);
    }
    assert!(!p.is_zero(), "sign_at_real_root: the zero polynomial");
    if q.is_zero() {
        return Sign::Zero;
    }
    if q.is_constant() {
        return q.sign_at_pos_inf();
    }
    let g = p.gcd(q).square_free_part();
    if !g.is_constant() && g.sign_at(&root.lo) * g.sign_at(&root.hi) == Sign::Negative {
        return Sign::Zero;
    }
    let sqf = p.primitive_square_free_part();
    let mut ri = root.clone();
    loop {
        if q.sign_at(&ri.lo) != Sign::Zero && descartes_bound(q, &ri.lo, &ri.hi) == 0 {
            return q.sign_at(&ri.midpoint());
        }
        let half_width = ri.width() * half();
        ri = isolate::refine_simple(&sqf, &ri, &half_width);
        if let Some(r) = ri.exact_value() {
            return q.sign_at(r);
        }
    }
}

/// The rational `x` compared with the root of `p` isolated by `root`: `Less` when `x` is below
/// the root ([`UPoly::compare_with_root`]).
pub fn compare_with_real_root(p: &UPoly, root: &RootInterval, x: &Rational) -> Ordering {
    p.compare_with_root(root, x)
}

/// Descartes' bound for the open interval `(lo, hi)`, `lo < hi`: the sign variations of the
/// Bernstein coefficients of `p` on `[lo, hi]` (computed on integers, from `p` composed with
/// the affine map of `[0, 1]` onto `[lo, hi]`). It bounds the number of roots of `p` in
/// `(lo, hi)` counted with multiplicity and has the same parity, so 0 and 1 are exact. 0 for
/// non-zero constants.
///
/// # Panics
/// When `p` is zero or `lo >= hi`.
pub fn descartes_bound(p: &UPoly, lo: &Rational, hi: &Rational) -> usize {
    assert!(!p.is_zero(), "descartes_bound: the zero polynomial");
    assert!(lo < hi, "descartes_bound: {lo} >= {hi}");
    if p.is_constant() {
        return 0;
    }
    let on_unit = p.compose(&UPoly::from_coeffs(vec![lo.clone(), hi.sub_ref(lo)]));
    unit_descartes_bound(&on_unit.integer_coefficients())
}
