//! Cell points of the counter-example search: rational points between the real roots of the
//! polynomials that decide where a residual can change sign, one variable at a time.
//!
//! A false identity may be false only on a narrow region (`sqrt((t^2 - 2)^2) = 2 - t^2` fails
//! exactly for `|t| > sqrt(2)`), which neither small rationals nor random ones need meet. The
//! search samples the cells of the sign charts of a few polynomials ([`cell_polynomials`]):
//! * each square-root variable `y` (a relation `a y^2 - E`) is eliminated from the residual, the
//!   other relations and the non-zero polynomials by writing each as `A + B y` (`y^2` replaced
//!   by `E / a`, the inner roots last); `A`, `B`, the radicand `E / a` and the norm
//!   `A^2 - B^2 E / a` are kept: where none of them changes sign, `A + B sqrt(E / a)` does not
//!   either (it vanishes only where the norm does);
//! * the polynomials without square roots are kept as they are.
//!
//! Along one variable `v`, the others fixed at rational values ([`cell_values`]) — at a point,
//! and at the ends of their domains (the faces of the box, where a region that reaches the
//! boundary shows itself) — each of them is a univariate polynomial with rational
//! coefficients; their real roots are isolated exactly ([`crate::univariate`]) and every open
//! gap between consecutive roots (and each rational root) that meets `v`'s domain gives one
//! value: the rational of least height in it ([`simplest_between`]). The search then checks the
//! point exactly like any other; nothing here is a verdict.

use super::hypotheses::{split, square_of};
use super::{PointField, VarDomain, CELL_ATTEMPTS};
use crate::poly::{Poly, Var};
use crate::univariate::{RootInterval, UPoly};
use crate::Rational;
use exactcheck_core::{Ring, Sign};
use num_integer::Integer;
use std::cmp::Ordering;
use std::collections::{HashSet, VecDeque};

/// The most polynomials [`cell_polynomials`] keeps (the residual's parts come first).
const MAX_CELL_POLYNOMIALS: usize = 32;

/// The highest degree of the product whose roots [`cell_values`] isolates along one variable
/// (factors past it are left out, the residual's parts come first).
const MAX_CELL_DEGREE: usize = 48;

/// The polynomials whose sign charts bound the cells (module documentation), and for every
/// variable whether it is a square-root variable (eliminated, so never sampled).
pub(super) fn cell_polynomials<C: PointField>(
    residual: &Poly<C>,
    relations: &[Poly<C>],
    nonzero: &[Poly<C>],
    nvars: usize,
) -> (Vec<Poly<C>>, Vec<bool>) {
    let roots: Vec<(Var, Poly<C>)> = (0..nvars as Var)
        .filter_map(|y| square_of(relations, y).map(|e| (y, e)))
        .collect();
    let mut is_root = vec![false; nvars];
    for (y, _) in &roots {
        is_root[*y as usize] = true;
    }
    let mut polys: Vec<Poly<C>> = std::iter::once(residual)
        .chain(nonzero)
        .chain(
            relations
                .iter()
                .filter(|r| !r.variables().iter().any(|&v| is_root[v as usize])),
        )
        .cloned()
        .collect();
    // The outer roots first: a radicand holds only roots of lower index.
    for (y, square) in roots.iter().rev() {
        let mut next = Vec::with_capacity(polys.len() + 2);
        for p in polys {
            if p.degree_in(*y) == 0 {
                next.push(p);
                continue;
            }
            if let Some((a, b)) = split(&p, *y, square, &Poly::one()) {
                let norm = (|| {
                    let b2 = b.try_mul(&b).ok()?.try_mul(square).ok()?;
                    Some(a.try_mul(&a).ok()?.sub_ref(&b2))
                })();
                next.extend(
                    [Some(a), Some(b), norm]
                        .into_iter()
                        .flatten()
                        .filter(|q| !q.is_constant()),
                );
            }
        }
        if !square.is_constant() {
            next.push(square.clone());
        }
        polys = next;
    }
    let mut kept: Vec<Poly<C>> = Vec::new();
    for p in polys {
        if kept.len() < MAX_CELL_POLYNOMIALS && !p.is_constant() && !kept.contains(&p) {
            kept.push(p);
        }
    }
    (kept, is_root)
}

/// The cell phase of the counter-example search over one statement.
pub(super) struct Search<'a, C: PointField> {
    /// The residual.
    pub residual: &'a Poly<C>,
    /// The relations.
    pub relations: &'a [Poly<C>],
    /// The polynomials declared non-zero.
    pub nonzero: &'a [Poly<C>],
    /// The domain of every variable.
    pub dom: &'a [VarDomain],
    /// Whether each variable occurs in the statement.
    pub active: &'a [bool],
    /// Whether a variable is a coordinate of a unit circle (set by its parameter, not sampled).
    pub circle: &'a dyn Fn(Var) -> bool,
}

impl<C: PointField> Search<'_, C> {
    /// Calls `attempt` at the cell points of each sampled variable (active, neither a square
    /// root nor on a circle), the others first at the points `bases`, then at the points tried
    /// (one more variable moved each round), each point once, at most [`CELL_ATTEMPTS`] of them:
    /// the first answer of `attempt`, or the number of points tried.
    pub fn run<T>(
        &self,
        bases: Vec<Vec<Rational>>,
        attempt: &mut dyn FnMut(Vec<Rational>) -> Option<T>,
    ) -> Result<T, usize> {
        let nvars = self.dom.len();
        let (polys, is_root) = cell_polynomials(self.residual, self.relations, self.nonzero, nvars);
        let sampled: Vec<Var> = (0..nvars as Var)
            .filter(|&v| self.active[v as usize] && !is_root[v as usize] && !(self.circle)(v))
            .collect();
        if polys.is_empty() || sampled.is_empty() {
            return Err(0);
        }
        let mut tried = 0;
        let mut queue: VecDeque<(Vec<Rational>, usize)> =
            bases.into_iter().map(|b| (b, 0)).collect();
        let mut seen = HashSet::new();
        while let Some((base, depth)) = queue.pop_front() {
            for &v in &sampled {
                // The line through the point, and the lines on the faces of the box where
                // another variable is at an end of its domain: a region that meets a face
                // (`x^2 + y^2 > 1` in `0 < x, y < 3/4`) has a cell there.
                let mut lines = vec![base.clone()];
                for &u in sampled.iter().filter(|&&u| u != v) {
                    let d = &self.dom[u as usize];
                    for (end, _) in [&d.lower, &d.upper].into_iter().flatten() {
                        let mut line = base.clone();
                        line[u as usize] = end.clone();
                        lines.push(line);
                    }
                }
                for x in cell_values(&polys, &is_root, v, &lines, &self.dom[v as usize]) {
                    let mut point = base.clone();
                    point[v as usize] = x;
                    if !seen.insert(point.clone()) {
                        continue;
                    }
                    if tried >= CELL_ATTEMPTS {
                        return Err(tried);
                    }
                    tried += 1;
                    if let Some(found) = attempt(point.clone()) {
                        return Ok(found);
                    }
                    if depth + 1 < sampled.len() {
                        queue.push_back((point, depth + 1));
                    }
                }
            }
        }
        Err(tried)
    }
}

/// `p` with every variable but `v` fixed at `base`, as a polynomial in `v`; `None` when a
/// coefficient is not rational or a square-root variable is left.
fn restrict<C: PointField>(
    p: &Poly<C>,
    v: Var,
    base: &[Rational],
    is_root: &[bool],
) -> Option<UPoly> {
    let deg = p.degree_in(v) as usize;
    if deg == 0 || deg > MAX_CELL_DEGREE {
        return None;
    }
    let mut coeffs = vec![Rational::ZERO; deg + 1];
    for (m, c) in p.terms() {
        let mut value = c.to_radical()?.to_rational()?;
        let mut k = 0;
        for (w, e) in m.exponents() {
            if w == v {
                k = e as usize;
            } else if is_root[w as usize] {
                return None;
            } else {
                value *= &base[w as usize].powi(e as i32).ok()?;
            }
        }
        coeffs[k] = coeffs[k].add_ref(&value);
    }
    let u = UPoly::from_coeffs(coeffs);
    (!u.is_constant()).then(|| u.square_free_part().primitive_part())
}

/// The cell values of variable `v` in its domain `dom`, the other variables at each point of
/// `lines` in turn (module documentation): one rational in every open gap between consecutive
/// real roots of the polynomials restricted to `v` on these lines that meets the domain, and
/// every rational root in it, in increasing order. Empty when no polynomial depends on `v`.
pub(super) fn cell_values<C: PointField>(
    polys: &[Poly<C>],
    is_root: &[bool],
    v: Var,
    lines: &[Vec<Rational>],
    dom: &VarDomain,
) -> Vec<Rational> {
    let mut product = UPoly::one();
    let mut factors: Vec<UPoly> = Vec::new();
    for base in lines {
        for p in polys {
            let Some(u) = restrict(p, v, base, is_root) else {
                continue;
            };
            if factors.contains(&u) || product.degree() + u.degree() > MAX_CELL_DEGREE {
                continue;
            }
            product = &product * &u;
            factors.push(u);
        }
    }
    if factors.is_empty() {
        return Vec::new();
    }
    let lower = dom.lower.clone();
    let upper = dom.upper.clone();
    let ends: Vec<Rational> = [&lower, &upper]
        .into_iter()
        .flatten()
        .map(|(x, _)| x.clone())
        .collect();
    // Narrow intervals, so that the value of a gap is the simplest of the true gap (or close).
    let refined = Rational::new(1, 1024).expect("1024 is not zero");
    let mut roots: Vec<RootInterval> = product
        .isolate_roots()
        .into_iter()
        .map(|r| clear_of(&product, product.refine(&r, &refined), &ends))
        .collect();
    roots.sort_by(|a, b| a.lo.cmp(&b.lo));
    let mut out = Vec::new();
    // The gap above the previous root (its upper end, strict when the root is exact) and below
    // the next one, cut to the domain.
    let mut below: Option<(Rational, bool)> = None;
    for r in roots.iter().map(Some).chain(std::iter::once(None)) {
        let above = r.map(|r| (r.lo.clone(), r.is_exact()));
        let lo = tighter(below.clone(), lower.clone(), true);
        let hi = tighter(above, upper.clone(), false);
        if let Some(x) = simplest_between(lo.as_ref(), hi.as_ref()) {
            out.push(x);
        }
        if let Some(r) = r {
            if let Some(x) = r.exact_value() {
                if dom.contains(&crate::Radical::from(x)) {
                    out.push(x.clone());
                }
            }
            below = Some((r.hi.clone(), r.is_exact()));
        }
    }
    out.dedup();
    out
}

/// The isolating interval `r` of a root of `p` bisected until no point of `ends` lies in it
/// (closed), so that a gap cut at a domain's end is empty exactly when the true gap misses the
/// domain. A non-exact interval holds an irrational root, which no rational end equals.
fn clear_of(p: &UPoly, mut r: RootInterval, ends: &[Rational]) -> RootInterval {
    for x in ends {
        while !r.is_exact() && r.lo <= *x && *x <= r.hi {
            let mid = r.midpoint();
            match p.compare_with_root(&r, &mid) {
                Ordering::Less => r.lo = mid,
                Ordering::Greater => r.hi = mid,
                Ordering::Equal => return RootInterval::exact(mid),
            }
        }
    }
    r
}

/// The tighter of two bounds `(value, strict)`, lower ones when `is_lower`.
fn tighter(
    a: Option<(Rational, bool)>,
    b: Option<(Rational, bool)>,
    is_lower: bool,
) -> Option<(Rational, bool)> {
    match (a, b) {
        (None, x) | (x, None) => x,
        (Some(a), Some(b)) => {
            let a_inside = if is_lower { a.0 > b.0 } else { a.0 < b.0 };
            Some(if a.0 == b.0 {
                (a.0, a.1 || b.1)
            } else if a_inside {
                a
            } else {
                b
            })
        }
    }
}

/// The rational of least height (numerator and denominator both least) `x` with
/// `lo < x` (`lo <= x` when the bound is not strict) and `x < hi` (or `<=`), each bound
/// `(value, strict)` and `None` for none; `None` when no number satisfies both.
pub(super) fn simplest_between(
    lo: Option<&(Rational, bool)>,
    hi: Option<&(Rational, bool)>,
) -> Option<Rational> {
    match (lo, hi) {
        (None, None) => Some(Rational::ZERO),
        (Some((a, strict)), None) => Some(
            if a.signum() == Sign::Negative || (a.is_zero() && !strict) {
                Rational::ZERO
            } else {
                next_integer(a, *strict)
            },
        ),
        (None, Some((b, strict))) => {
            simplest_between(Some(&(b.neg_ref(), *strict)), None).map(|x| x.neg_ref())
        }
        (Some((a, sa)), Some((b, sb))) => {
            if a > b || (a == b && (*sa || *sb)) {
                return None;
            }
            if a == b {
                return Some(a.clone());
            }
            // The least height in the open interval, or a closed end of smaller height.
            let mut best = simplest_open(a, b);
            for (end, strict) in [(a, sa), (b, sb)] {
                if !strict && height_less(end, &best) {
                    best = end.clone();
                }
            }
            Some(best)
        }
    }
}

/// Whether `x` has a smaller height `max(|n|, d)` than `y` (ties: the smaller absolute value).
fn height_less(x: &Rational, y: &Rational) -> bool {
    let h = |q: &Rational| {
        let n = q.numer().magnitude().clone();
        let d = q.denom().magnitude().clone();
        n.max(d)
    };
    let abs = |q: &Rational| {
        if q.signum() == Sign::Negative {
            q.neg_ref()
        } else {
            q.clone()
        }
    };
    (h(x), abs(x)) < (h(y), abs(y))
}

/// The least integer above `a` (`>= a` when not `strict`), for `a >= 0`.
fn next_integer(a: &Rational, strict: bool) -> Rational {
    let f = Rational::from(a.numer().div_floor(&a.denom()));
    if !strict && f == *a {
        f
    } else {
        f + Rational::ONE
    }
}

/// The simplest rational (least numerator and denominator) in the open interval `(a, b)`,
/// `a < b`, by the continued fractions of the ends (the Stern–Brocot descent).
fn simplest_open(a: &Rational, b: &Rational) -> Rational {
    if a.signum() == Sign::Negative && b.signum() == Sign::Positive {
        return Rational::ZERO;
    }
    if b.signum() != Sign::Positive {
        return simplest_open(&b.neg_ref(), &a.neg_ref()).neg_ref();
    }
    // 0 <= a < b.
    let n = Rational::from(a.numer().div_floor(&a.denom()));
    let next = n.add_ref(&Rational::ONE);
    if next < *b {
        return next;
    }
    // (a, b) lies in [n, n + 1]: x = n + 1/z with z in (1/(b - n), 1/(a - n)).
    let (a1, b1) = (a.sub_ref(&n), b.sub_ref(&n));
    let low = b1.recip().expect("b > n");
    let z = if a1.is_zero() {
        next_integer(&low, true)
    } else {
        simplest_open(&low, &a1.recip().expect("a > n"))
    };
    n + z.recip().expect("z >= 1")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n, d).unwrap()
    }

    #[test]
    fn the_simplest_rational_between_two_bounds() {
        let open = |a: Rational, b: Rational| {
            simplest_between(Some(&(a, true)), Some(&(b, true))).unwrap()
        };
        assert_eq!(open(q(1, 3), q(1, 2)), q(2, 5));
        assert_eq!(open(q(-1, 1), q(3, 2)), q(0, 1));
        // Between sqrt(2) ~ 1.41421 (isolated in (1414/1000, 1415/1000)) and 3/2.
        assert_eq!(open(q(1415, 1000), q(3, 2)), q(10, 7));
        assert_eq!(open(q(-3, 2), q(-1415, 1000)), q(-10, 7));
        assert_eq!(open(q(0, 1), q(1, 100)), q(1, 101));
        assert_eq!(open(q(2, 1), q(3, 1)), q(5, 2));
        // Closed ends count when they are simpler.
        assert_eq!(
            simplest_between(Some(&(q(1, 1), false)), Some(&(q(3, 2), true))),
            Some(q(1, 1))
        );
        assert_eq!(
            simplest_between(Some(&(q(1, 1), true)), Some(&(q(1, 1), false))),
            None
        );
        assert_eq!(
            simplest_between(Some(&(q(7, 3), true)), None),
            Some(q(3, 1))
        );
        assert_eq!(
            simplest_between(None, Some(&(q(-2, 1), false))),
            Some(q(-2, 1))
        );
        // Every answer lies in its interval, and no rational of smaller denominator does.
        for (a, b) in [
            (q(13, 7), q(15, 8)),
            (q(-5, 3), q(-8, 5)),
            (q(1, 1000), q(1, 999)),
        ] {
            let x = open(a.clone(), b.clone());
            assert!(a < x && x < b, "{x}");
            // The least n/k above a, for every k below x's denominator, is not below b.
            let d = x.denom();
            let mut k = 1i64;
            while num_bigint::BigInt::from(k) < d {
                let ak = &a * &Rational::from_integer(k);
                let n = Rational::from(ak.numer().div_floor(&ak.denom())) + Rational::ONE;
                let least = n / Rational::from_integer(k);
                assert!(least >= b, "{x} against {least}");
                k += 1;
            }
        }
    }

    #[test]
    fn cells_of_a_narrow_branch_are_sampled() {
        // sqrt((t^2 - 2)^2) + t^2 - 2 with w = the root: the radicand's roots +-sqrt(2) bound
        // the cell (sqrt(2), 3/2) of -1 < t < 3/2, sampled at 10/7.
        let mut vars = Vars::from_names(["t", "w"]);
        let residual: Poly<Rational> = parse_poly("w + t^2 - 2", &mut vars).unwrap();
        let relation: Poly<Rational> = parse_poly("w^2 - (t^2 - 2)^2", &mut vars).unwrap();
        let (polys, is_root) = cell_polynomials(&residual, &[relation], &[], 2);
        assert_eq!(is_root, vec![false, true]);
        let dom = VarDomain {
            lower: Some((q(-1, 1), true)),
            upper: Some((q(3, 2), true)),
            integer: false,
        };
        let values = cell_values(&polys, &is_root, 0, &[vec![Rational::ZERO; 2]], &dom);
        assert_eq!(values, vec![q(0, 1), q(10, 7)]);
        // Without a domain every gap is sampled: below -sqrt(2), between, above.
        let all = cell_values(
            &polys,
            &is_root,
            0,
            &[vec![Rational::ZERO; 2]],
            &VarDomain::all(),
        );
        assert_eq!(all, vec![q(-2, 1), q(0, 1), q(2, 1)]);
        // Rational roots are points of their own.
        let mut vars = Vars::from_names(["x", "y"]);
        let p: Poly<Rational> = parse_poly("(x - 1/2) (x^2 + y^2 - 1)", &mut vars).unwrap();
        let (polys, is_root) = cell_polynomials(&p, &[], &[], 2);
        let values = cell_values(
            &polys,
            &is_root,
            0,
            &[vec![Rational::ZERO, q(1, 2)]],
            &VarDomain::all(),
        );
        assert_eq!(values, vec![q(-1, 1), q(0, 1), q(1, 2), q(2, 3), q(1, 1)]);
    }
}
