//! The roots of the line polynomial `f(t) = det(B(t) - P, V(t), D)` and what happens at each
//! (the module doc of `ruled_line`, "Method").

use super::covered::{covered, parallel_to_every_ruling, Covered};
use crate::solve::scalar::Scalar;
use exactcheck_core::roots::{multiplicity, refine, vanishes_at_root, IsolatedRoot};
use exactcheck_core::ruled::RuledSurface;
use exactcheck_core::{Bernstein, Field, Ring, Vec3};

/// What happens at one root of the line polynomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Status {
    /// The ruling crosses the line at one point.
    Point,
    /// The ruling is parallel to the line and is the line itself.
    RulingOnLine,
    /// The ruling is parallel to the line and apart from it: no point.
    RulingParallel,
    /// `V(t) = 0`: the ruling is the point `B(t)`, which lies on the line (`s` arbitrary).
    DegenerateRulingOnLine,
    /// `V(t) = 0` and `B(t)` is not on the line: no point.
    DegenerateRulingOffLine,
}

impl Status {
    pub(super) fn name(self) -> &'static str {
        match self {
            Status::Point => "point",
            Status::RulingOnLine => "ruling_on_line",
            Status::RulingParallel => "ruling_parallel",
            Status::DegenerateRulingOnLine => "degenerate_ruling_on_line",
            Status::DegenerateRulingOffLine => "degenerate_ruling_off_line",
        }
    }
}

/// One root with what was computed there (exact when `exact`, else at the refined midpoint).
pub(super) struct RootReport<T> {
    pub(super) root: IsolatedRoot<T>,
    pub(super) multiplicity: usize,
    pub(super) status: Status,
    /// Whether `s`, `lambda` and the point are exact.
    pub(super) exact: bool,
    pub(super) s: Option<T>,
    pub(super) lambda: Option<T>,
    pub(super) point: Option<Vec3<T>>,
}

pub(super) enum Outcome<T> {
    /// `f` is not identically zero: its roots in [0, 1].
    Roots(Vec<RootReport<T>>),
    /// `f = 0` and `W = 0`: every ruling is parallel to the line; the line is the ruling at
    /// these roots of `U` (all `t` when `U = 0` too, `None`).
    ParallelToEveryRuling(Option<Vec<IsolatedRoot<T>>>, Covered<T>),
    /// `f = 0`, `W != 0`: every ruling meets the line or is parallel to it; the part of the
    /// line they cover.
    Covered(Covered<T>),
}

pub(super) struct Analysis<T> {
    pub(super) m: usize,
    pub(super) n: usize,
    pub(super) polynomial: Bernstein<T>,
    pub(super) outcome: Outcome<T>,
}

pub(super) fn dot3<T: Ring>(a: &[Bernstein<T>; 3], d: &Vec3<T>) -> [Bernstein<T>; 3] {
    // a x d, componentwise polynomials.
    let comb = |p: &Bernstein<T>, s: &T, q: &Bernstein<T>, r: &T| {
        Bernstein::new(
            p.coeffs()
                .iter()
                .zip(q.coeffs())
                .map(|(x, y)| x.mul_ref(s) - y.mul_ref(r))
                .collect(),
        )
    };
    [
        comb(&a[1], &d.z, &a[2], &d.y),
        comb(&a[2], &d.x, &a[0], &d.z),
        comb(&a[0], &d.y, &a[1], &d.x),
    ]
}

pub(super) fn analyse<T: Scalar>(
    surface: &RuledSurface<T>,
    point: &Vec3<T>,
    direction: &Vec3<T>,
) -> Analysis<T> {
    let (m, n) = surface.degrees();
    let f = surface.line_polynomial(point, direction);
    let v = surface.directions().coordinates();
    let b = surface.base().coordinates();
    let shifted = [
        shift(&b[0], &point.x),
        shift(&b[1], &point.y),
        shift(&b[2], &point.z),
    ];
    let w = dot3(&v, direction);
    let u = dot3(&shifted, direction);
    let dd = direction.norm_squared();
    let lambda_of = |x: &Vec3<T>| {
        x.add_scaled(&T::from_i64(-1), point)
            .dot(direction)
            .checked_div(&dd)
            .expect("the direction was checked to be non-zero")
    };
    let outcome = match T::unit_roots(&f) {
        Err(_) => {
            if w.iter().all(Bernstein::is_zero) {
                parallel_to_every_ruling(direction, &shifted, &v, &u)
            } else {
                Outcome::Covered(covered(surface, direction, &shifted, &w, &u))
            }
        }
        Ok(roots) => {
            let width = T::from_ratio(1, 1 << 60).expect("2^60 is not zero");
            let mut reports = Vec::new();
            for root in roots {
                let root = refine(&f, &root, &width);
                let parallel = vanishes_at_root(&f, &w, &root);
                let zero_v = parallel && vanishes_at_root(&f, &v, &root);
                let on_line = parallel && vanishes_at_root(&f, &u, &root);
                let status = match (parallel, zero_v, on_line) {
                    (false, _, _) => Status::Point,
                    (true, false, true) => Status::RulingOnLine,
                    (true, false, false) => Status::RulingParallel,
                    (true, true, true) => Status::DegenerateRulingOnLine,
                    (true, true, false) => Status::DegenerateRulingOffLine,
                };
                let t = root.midpoint();
                let (s, lambda, x) = match status {
                    Status::Point => {
                        let s = ruling_parameter(surface, point, direction, &t);
                        match s {
                            Some(s) => {
                                let x = surface.eval(&s, &t);
                                (Some(s), Some(lambda_of(&x)), Some(x))
                            }
                            // Only at an interval midpoint of a root whose W is tiny in f64.
                            None => (None, None, None),
                        }
                    }
                    Status::DegenerateRulingOnLine => {
                        let x = surface.base().eval(&t);
                        (None, Some(lambda_of(&x)), Some(x))
                    }
                    _ => (None, None, None),
                };
                reports.push(RootReport {
                    multiplicity: multiplicity(&f, &root),
                    exact: root.exact().is_some(),
                    root,
                    status,
                    s,
                    lambda,
                    point: x,
                });
            }
            Outcome::Roots(reports)
        }
    };
    Analysis {
        m,
        n,
        polynomial: f,
        outcome,
    }
}

pub(super) fn shift<T: Ring>(p: &Bernstein<T>, c: &T) -> Bernstein<T> {
    Bernstein::new(p.coeffs().iter().map(|x| x.sub_ref(c)).collect())
}

/// `s = -((B - P) x D) . (V x D) / |V x D|^2` at `t`: the ruling parameter of the meeting point;
/// `None` when `V(t) x D = 0` at this `t`.
pub(super) fn ruling_parameter<T: Field>(
    surface: &RuledSurface<T>,
    point: &Vec3<T>,
    direction: &Vec3<T>,
    t: &T,
) -> Option<T> {
    let w = surface.directions().eval(t).cross(direction);
    let u = surface
        .base()
        .eval(t)
        .add_scaled(&T::from_i64(-1), point)
        .cross(direction);
    u.dot(&w).neg_ref().checked_div(&w.norm_squared()).ok()
}
