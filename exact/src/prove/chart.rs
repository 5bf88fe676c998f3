//! The sign chart of a univariate polynomial with rational coefficients on an interval domain:
//! the real roots of the polynomial inside the interval, isolated exactly, and one rational
//! sample point in each open gap between them that meets the interval, with the polynomial's
//! sign on that gap. Roots are compared with the interval's rational ends exactly, so that a
//! root at a closed end is in the chart and a root at an open end is not; an irrational root is
//! never an end.
//!
//! The domain is read as a real interval (an integer domain's flag is ignored: the chart covers
//! the real points between its ends).

use super::{PointField, VarDomain};
use crate::poly::{Poly, Var};
use crate::univariate::{compare_with_real_root, RootInterval, UPoly};
use crate::Rational;
use exactcheck_core::Sign;
use std::cmp::Ordering;

/// One cell of a chart, in increasing order along the domain.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Cell {
    /// A real root of the polynomial inside the domain.
    Root(RootInterval),
    /// The part of an open gap between roots that lies in the domain: a rational point of it
    /// and the polynomial's sign there (the same on the whole gap).
    Gap {
        /// A rational point of the gap inside the domain.
        sample: Rational,
        /// The polynomial's sign on the gap.
        sign: Sign,
    },
}

/// An end of a gap: a root of the polynomial or an end of the domain.
enum End<'a> {
    Root(&'a RootInterval),
    Value(&'a Rational),
}

/// The chart of `u` on `d` (module documentation): empty when `d` holds no real point; for a
/// single-point domain `[a, a]` the root `a` or one gap with the sample `a`. The zero
/// polynomial has one gap of sign zero.
pub fn chart(u: &UPoly, d: &VarDomain) -> Vec<Cell> {
    let lower = d.lower.as_ref();
    let upper = d.upper.as_ref();
    if let (Some((a, sa)), Some((b, sb))) = (lower, upper) {
        match a.cmp(b) {
            Ordering::Greater => return Vec::new(),
            Ordering::Equal if *sa || *sb => return Vec::new(),
            Ordering::Equal => {
                let sign = u.sign_at(a);
                return vec![if sign == Sign::Zero && !u.is_zero() {
                    Cell::Root(RootInterval::exact(a.clone()))
                } else {
                    Cell::Gap {
                        sample: a.clone(),
                        sign,
                    }
                }];
            }
            Ordering::Less => {}
        }
    }
    let signs = u.sign_chart();
    let roots: Vec<&RootInterval> = signs.roots.iter().map(|r| &r.interval).collect();
    let mut cells = Vec::new();
    for (i, sign) in signs.gaps.iter().enumerate() {
        let left = i.checked_sub(1).map(|k| roots[k]);
        let right = roots.get(i).copied();
        // The gap's part in the domain runs from the larger of its lower ends to the smaller
        // of its upper ends; it is not empty when the first lies below the second.
        let from = inner_end(u, left, lower.map(|(a, _)| a), Ordering::Less);
        let to = inner_end(u, right, upper.map(|(b, _)| b), Ordering::Greater);
        if let Some(sample) = sample_between(u, from, to) {
            cells.push(Cell::Gap {
                sample,
                sign: *sign,
            });
        }
        if let Some(r) = right {
            if root_in(u, r, d) {
                cells.push(Cell::Root(r.clone()));
            }
        }
    }
    cells
}

/// The polynomial with rational coefficients, when it has them.
pub fn rational<C: PointField>(p: &Poly<C>) -> Option<Poly<Rational>> {
    let cs: Vec<Rational> = p
        .coefficients()
        .iter()
        .map(|c| c.to_radical().and_then(|r| r.to_rational()))
        .collect::<Option<_>>()?;
    let mut it = cs.into_iter();
    Some(p.map_coeffs(|_| it.next().expect("one coefficient each")))
}

/// `p` as a univariate polynomial in `v` with rational coefficients, when it is one.
pub fn univariate<C: PointField>(p: &Poly<C>, v: Var) -> Option<UPoly> {
    UPoly::from_poly(&rational(p)?, v).ok()
}

/// The root `r` of `u` compared with the rational `x`: `Less` when the root is below `x`.
fn root_vs(u: &UPoly, r: &RootInterval, x: &Rational) -> Ordering {
    compare_with_real_root(u, r, x).reverse()
}

/// Whether the root of `u` in `r` lies in `d` (its ends compared exactly).
fn root_in(u: &UPoly, r: &RootInterval, d: &VarDomain) -> bool {
    let meets = |end: &Option<(Rational, bool)>, outside: Ordering| {
        end.as_ref()
            .is_none_or(|(x, strict)| match root_vs(u, r, x) {
                Ordering::Equal => !strict,
                o => o != outside,
            })
    };
    meets(&d.lower, Ordering::Less) && meets(&d.upper, Ordering::Greater)
}

/// The end of a gap's part in the domain on one side: of the gap's root and the domain's end
/// on that side (`None`: an infinity), the inner one. `outward` is the side's direction:
/// `Less` for the lower ends (the larger is kept), `Greater` for the upper ends.
fn inner_end<'a>(
    u: &UPoly,
    root: Option<&'a RootInterval>,
    end: Option<&'a Rational>,
    outward: Ordering,
) -> Option<End<'a>> {
    match (root, end) {
        (Some(r), Some(x)) if root_vs(u, r, x) == outward.reverse() => Some(End::Root(r)),
        (_, Some(x)) => Some(End::Value(x)),
        (Some(r), None) => Some(End::Root(r)),
        (None, None) => None,
    }
}

/// A rational strictly between `from` and `to` (`None` ends are infinities), or `None` when
/// `from` is not below `to`. Root intervals are refined until a rational separates the ends.
fn sample_between(u: &UPoly, from: Option<End>, to: Option<End>) -> Option<Rational> {
    let one = Rational::ONE;
    let half = Rational::new(1, 2).expect("2 is not zero");
    // Whether `from < to`, exactly.
    let below = match (&from, &to) {
        (Some(End::Value(a)), Some(End::Value(b))) => a < b,
        (Some(End::Root(r)), Some(End::Value(b))) => root_vs(u, r, b) == Ordering::Less,
        (Some(End::Value(a)), Some(End::Root(r))) => root_vs(u, r, a) == Ordering::Greater,
        // Two roots of a gap's ends are consecutive, increasing.
        (Some(End::Root(a)), Some(End::Root(b))) => a != b,
        _ => true,
    };
    if !below {
        return None;
    }
    let mut lo = match from {
        None => None,
        Some(End::Value(a)) => Some(RootInterval::exact(a.clone())),
        Some(End::Root(r)) => Some(r.clone()),
    };
    let mut hi = match to {
        None => None,
        Some(End::Value(b)) => Some(RootInterval::exact(b.clone())),
        Some(End::Root(r)) => Some(r.clone()),
    };
    loop {
        match (&lo, &hi) {
            (None, None) => return Some(Rational::ZERO),
            (Some(l), None) => return Some(&l.hi + &one),
            (None, Some(h)) => return Some(&h.lo - &one),
            (Some(l), Some(h)) if l.hi < h.lo => return Some((&l.hi + &h.lo) * &half),
            // The ends are distinct: refining the inexact one(s) separates them.
            (Some(l), Some(h)) => {
                if !l.is_exact() {
                    lo = Some(u.refine(l, &(l.width() * &half)));
                }
                if !h.is_exact() {
                    hi = Some(u.refine(h, &(h.width() * &half)));
                }
            }
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;

    fn u(text: &str) -> UPoly {
        let mut vars = Vars::from_names(["x"]);
        let p = parse_poly::<Rational>(text, &mut vars).unwrap();
        UPoly::from_poly(&p, 0).unwrap()
    }

    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n, d).unwrap()
    }

    /// The real interval with the ends `lo` and `hi` (each with its strictness).
    pub(in crate::prove) fn dom(
        lo: Option<(Rational, bool)>,
        hi: Option<(Rational, bool)>,
    ) -> VarDomain {
        VarDomain {
            lower: lo,
            upper: hi,
            integer: false,
        }
    }

    /// The chart as text: roots as `0` (exact `r=...`), gaps as their sign; every sample
    /// checked to lie in the domain and to have the gap's sign.
    fn shape(p: &str, d: &VarDomain) -> Vec<String> {
        let q = u(p);
        let cells = chart(&q, d);
        cells
            .iter()
            .map(|c| match c {
                Cell::Root(ri) => match ri.exact_value() {
                    Some(t) => format!("root {t}"),
                    None => "root".to_string(),
                },
                Cell::Gap { sample, sign } => {
                    assert!(
                        d.contains(&crate::Radical::from(sample)),
                        "{sample} in {d:?}"
                    );
                    assert_eq!(q.sign_at(sample), *sign, "{p} at {sample}");
                    format!("{sign:?}")
                }
            })
            .collect()
    }

    #[test]
    fn roots_at_the_ends_are_in_the_chart_only_for_closed_ends() {
        let closed = dom(Some((r(-1, 1), false)), Some((r(1, 1), false)));
        let open = dom(Some((r(-1, 1), true)), Some((r(1, 1), true)));
        assert_eq!(shape("1 - x^2", &closed), ["root -1", "Positive", "root 1"]);
        assert_eq!(shape("1 - x^2", &open), ["Positive"]);
        // Half-open: the root at the closed end only.
        let half_open = dom(Some((r(-1, 1), true)), Some((r(1, 1), false)));
        assert_eq!(shape("x^2 - 1", &half_open), ["Negative", "root 1"]);
        // A root at an end and one inside.
        assert_eq!(
            shape(
                "x*(x - 1)",
                &dom(Some((r(0, 1), false)), Some((r(2, 1), true)))
            ),
            ["root 0", "Negative", "root 1", "Positive"]
        );
    }

    #[test]
    fn unbounded_sides_and_the_whole_line() {
        let all = VarDomain::all();
        assert_eq!(
            shape("x^2 - 1", &all),
            ["Positive", "root -1", "Negative", "root 1", "Positive"]
        );
        let above = dom(Some((r(0, 1), true)), None);
        assert_eq!(shape("x^2 - 1", &above), ["Negative", "root 1", "Positive"]);
        let below = dom(None, Some((r(-3, 1), false)));
        assert_eq!(shape("x^2 - 1", &below), ["Positive"]);
        assert_eq!(shape("x^2 + 1", &all), ["Positive"]);
    }

    #[test]
    fn irrational_roots_are_compared_with_rational_ends_exactly() {
        // sqrt(2) against 7/5 (below it) and 3/2 (above it).
        let to_7_5 = dom(Some((r(0, 1), false)), Some((r(7, 5), false)));
        let to_3_2 = dom(Some((r(0, 1), false)), Some((r(3, 2), false)));
        assert_eq!(shape("2 - x^2", &to_7_5), ["Positive"]);
        assert_eq!(shape("2 - x^2", &to_3_2), ["Positive", "root", "Negative"]);
        // An end very close above sqrt(2): the gap between is still sampled.
        let tight = dom(Some((r(14142136, 10000000), true)), None);
        assert_eq!(shape("2 - x^2", &tight), ["Negative"]);
        let tight_below = dom(Some((r(14142135, 10000000), true)), None);
        assert_eq!(
            shape("2 - x^2", &tight_below),
            ["Positive", "root", "Negative"]
        );
        // Two irrational roots close together (1 +- sqrt(2)/1000), no domain.
        assert_eq!(
            shape("x^2 - 2*x + 499999/500000", &VarDomain::all()),
            ["Positive", "root", "Negative", "root", "Positive"]
        );
    }

    #[test]
    fn constants_points_and_empty_domains() {
        let all = VarDomain::all();
        assert_eq!(shape("3", &all), ["Positive"]);
        assert_eq!(
            shape("-1/2", &dom(Some((r(5, 1), false)), None)),
            ["Negative"]
        );
        assert_eq!(shape("0", &all), ["Zero"]);
        let at = |a: i64| dom(Some((r(a, 1), false)), Some((r(a, 1), false)));
        assert_eq!(shape("x - 1", &at(1)), ["root 1"]);
        assert_eq!(shape("x - 1", &at(2)), ["Positive"]);
        let empty = dom(Some((r(1, 1), true)), Some((r(1, 1), false)));
        assert!(shape("x - 1", &empty).is_empty());
        let reversed = dom(Some((r(2, 1), false)), Some((r(1, 1), false)));
        assert!(shape("x", &reversed).is_empty());
    }
}
