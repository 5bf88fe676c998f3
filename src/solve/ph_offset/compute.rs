//! The computation of `ph_offset`: cusps, the smallest radius of curvature on each side and
//! overall (exact or certified enclosures), and the offsets themselves.

use super::Problem;
use crate::solve::scalar::{rational_zeros, unit_zeros, Scalar};
use exactcheck_core::ph::{MinRadius, PhCurve, RadiusBound, Side};
use exactcheck_core::roots::{self, IsolatedRoot};
use exactcheck_core::{RationalBezierCurve, Ring, Sign};
use exactcheck_exact::Rational;

/// Which sides attain the overall smallest radius.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Sides {
    Left,
    Right,
    Both,
    /// Two overlapping enclosures: not decided at this precision.
    Undecided,
}

impl Sides {
    pub(super) fn of(side: Side) -> Self {
        match side {
            Side::Left => Sides::Left,
            Side::Right => Sides::Right,
        }
    }

    pub(super) fn name(self) -> &'static str {
        match self {
            Sides::Left => "left",
            Sides::Right => "right",
            Sides::Both => "both",
            Sides::Undecided => "left_or_right",
        }
    }
}

/// A smallest radius with the side(s) attaining it.
#[derive(Clone, Debug)]
pub(super) struct Radius<T> {
    pub(super) value: RadiusBound<T>,
    pub(super) sides: Sides,
    pub(super) at: Vec<IsolatedRoot<T>>,
}

pub(super) fn signed<T: Ring>(side: Side, m: &T) -> T {
    match side {
        Side::Left => m.clone(),
        Side::Right => m.neg_ref(),
    }
}

/// The parameters where `sigma^2 - 2 r w` vanishes, rational ones exact, the others refined.
pub(super) fn cusp_zeros<T: Scalar>(curve: &PhCurve<T>, r: &T, width: &T) -> Vec<IsolatedRoot<T>> {
    unit_zeros(&curve.cusp_polynomial(r), width)
}

/// One side's smallest radius, upgraded to exact at a rational critical point (module doc).
pub(super) fn side_radius<T: Scalar>(
    curve: &PhCurve<T>,
    side: Side,
    tolerance: &T,
    width: &T,
) -> Option<Radius<T>> {
    let MinRadius { value, .. } = curve
        .min_radius(side, tolerance)
        .expect("called only when sigma has no zero in [0, 1]")?;
    let value = match value {
        RadiusBound::Within(lo, hi) if T::EXACT => {
            let crit = curve.radius_critical_polynomial();
            let exact = if crit.is_zero() {
                None
            } else {
                rational_zeros(&crit.to_power()).into_iter().find_map(|t| {
                    let m = signed(side, &curve.radius_at(&t)?);
                    (m > lo
                        && m <= hi
                        && curve
                            .is_min_radius(&m, side)
                            .expect("sigma has no zero in [0, 1]"))
                    .then_some(m)
                })
            };
            match exact {
                Some(m) => RadiusBound::Exact(m),
                None => RadiusBound::Within(lo, hi),
            }
        }
        other => other,
    };
    let at = match &value {
        RadiusBound::Exact(m) => cusp_zeros(curve, &signed(side, m), width),
        RadiusBound::Within(_, hi) => minimisers(curve, side, hi, width),
    };
    Some(Radius {
        at,
        value,
        sides: Sides::of(side),
    })
}

/// Where `side`'s radius `rho` attains its minimum when only an enclosure `(lo, hi]` of the
/// minimum is known (module doc): the zeros in `[0, 1]` of the critical polynomial
/// `2 sigma' w - sigma w'` (isolated by [`unit_zeros`], rational ones exact, the others refined
/// to `width`) that are local minima of `rho` with `rho <= hi` there. The minimum is attained
/// at an interior critical point, so it is attained among them. A local minimum is a zero
/// where the critical polynomial, signed for the side, changes sign from negative to positive
/// (`rho'` has the sign of `sigma (2 sigma' w - sigma w')` on the left, the opposite on the
/// right); `rho <= hi` is the sign of `sigma^2 - 2 hi w` there, decided exactly
/// ([`roots::sign_at_root`]). An exact zero is kept when [`PhCurve::is_min_radius`] proves
/// its radius the minimum.
pub(super) fn minimisers<T: Scalar>(
    curve: &PhCurve<T>,
    side: Side,
    hi: &T,
    width: &T,
) -> Vec<IsolatedRoot<T>> {
    let crit = curve.radius_critical_polynomial();
    if crit.is_zero() {
        return Vec::new();
    }
    let crit_side = match side {
        Side::Left => crit.clone(),
        Side::Right => crit.map(Ring::neg_ref),
    };
    let below = curve.cusp_polynomial(&signed(side, hi));
    unit_zeros(&crit, width)
        .into_iter()
        .filter(|c| match c {
            IsolatedRoot::Exact(t) => curve.radius_at(t).is_some_and(|r| {
                let m = signed(side, &r);
                m.sign() == Sign::Positive
                    && curve
                        .is_min_radius(&m, side)
                        .expect("sigma has no zero in [0, 1]")
            }),
            IsolatedRoot::Between(a, b) => {
                crit_side.eval(a).sign() == Sign::Negative
                    && crit_side.eval(b).sign() == Sign::Positive
                    && roots::sign_at_root(&below, &crit, c) != Sign::Positive
            }
        })
        .collect()
}

/// Whether the offset at `side`'s distance `m > 0` has a cusp: `m >= rho_min(side)`.
pub(super) fn reaches<T: Scalar>(curve: &PhCurve<T>, side: Side, m: &T) -> bool {
    !curve
        .offset_cusps(&signed(side, m))
        .expect("sigma has no zero in [0, 1]")
        .is_empty()
}

/// The smaller of the two sides' radii, compared exactly (module doc).
pub(super) fn overall<T: Scalar>(
    curve: &PhCurve<T>,
    left: Option<Radius<T>>,
    right: Option<Radius<T>>,
) -> Option<Radius<T>> {
    use RadiusBound::{Exact, Within};
    let (a, b) = match (left, right) {
        (None, x) | (x, None) => return x,
        (Some(a), Some(b)) => (a, b),
    };
    let both = |value: RadiusBound<T>, sides: Sides, a: &Radius<T>, b: &Radius<T>| {
        let mut at = a.at.clone();
        at.extend(b.at.iter().cloned());
        Radius { value, sides, at }
    };
    match (&a.value, &b.value) {
        (Exact(x), Exact(y)) => Some(if x < y {
            a
        } else if y < x {
            b
        } else {
            both(Exact(x.clone()), Sides::Both, &a, &b)
        }),
        (Exact(_), Within(..)) | (Within(..), Exact(_)) => {
            let (e, w) = if matches!(a.value, Exact(_)) {
                (a, b)
            } else {
                (b, a)
            };
            let (Exact(x), Within(lo, hi)) = (&e.value, &w.value) else {
                unreachable!("matched one exact and one enclosed value above")
            };
            let other = match w.sides {
                Sides::Left => Side::Left,
                _ => Side::Right,
            };
            Some(if x <= lo {
                e
            } else if x > hi {
                w
            } else if curve
                .is_min_radius(x, other)
                .expect("sigma has no zero in [0, 1]")
            {
                both(Exact(x.clone()), Sides::Both, &e, &w)
            } else if reaches(curve, other, x) {
                // rho_other < x <= hi: the enclosure shrinks to (lo, x).
                Radius {
                    value: Within(lo.clone(), x.clone()),
                    ..w
                }
            } else {
                e
            })
        }
        (Within(lo_a, hi_a), Within(lo_b, hi_b)) => Some(if hi_a <= lo_b {
            a
        } else if hi_b <= lo_a {
            b
        } else {
            let lo = if lo_a < lo_b { lo_a } else { lo_b }.clone();
            let hi = if hi_a < hi_b { hi_a } else { hi_b }.clone();
            both(Within(lo, hi), Sides::Undecided, &a, &b)
        }),
    }
}

/// One offset, computed.
pub(super) struct OffsetData<T> {
    pub(super) r: T,
    pub(super) outcome: &'static str,
    pub(super) curve: RationalBezierCurve<T>,
    /// `None` on a singular base.
    pub(super) cusps: Option<Vec<(IsolatedRoot<T>, usize)>>,
}

/// Everything the answer reports, in `T`.
pub(super) struct Computed<T> {
    pub(super) curve: PhCurve<T>,
    pub(super) singular: bool,
    pub(super) poles: Vec<IsolatedRoot<T>>,
    pub(super) line: bool,
    pub(super) left: Option<Radius<T>>,
    pub(super) right: Option<Radius<T>>,
    pub(super) min: Option<Radius<T>>,
    pub(super) offsets: Vec<OffsetData<T>>,
    pub(super) single: bool,
}

/// The tolerance of the radius bisection: `width` in exact arithmetic; in f64 at least `1e-9`
/// times the largest radius sampled where the curve bends (module doc, "Float mode").
pub(super) fn radius_tolerance<T: Scalar>(curve: &PhCurve<T>, width: &T) -> T {
    if T::EXACT {
        return width.clone();
    }
    let mut scale = T::one();
    for k in 0..=256 {
        let t = T::from_i64(k) / T::from_i64(256);
        if let Some(rho) = curve.radius_at(&t) {
            let a = rho.abs();
            if a > scale && a.approx().is_finite() {
                scale = a;
            }
        }
    }
    let rel =
        scale * T::from_rational(&Rational::new(1, 1_000_000_000).expect("a non-zero denominator"));
    if rel > *width {
        rel
    } else {
        width.clone()
    }
}

pub(super) fn compute<T: Scalar>(p: Problem<T>) -> Computed<T> {
    let Problem {
        curve,
        radii,
        single,
        width,
    } = p;
    let zeros = curve.speed_zeros();
    let singular = !zeros.is_empty();
    // Over the reals the zeros of sigma = u^2 + v^2 are exactly the common zeros of u and v;
    // exact mode gives them as sigma's zeros (rational ones exact, the others refined).
    let poles = if singular && T::EXACT {
        unit_zeros(&curve.speed(), &width)
    } else {
        zeros
    };
    let line = curve.curvature_numerator().is_zero();
    let (left, right, min) = if singular {
        (None, None, None)
    } else {
        let tol = radius_tolerance(&curve, &width);
        let left = side_radius(&curve, Side::Left, &tol, &width);
        let right = side_radius(&curve, Side::Right, &tol, &width);
        let min = overall(&curve, left.clone(), right.clone());
        (left, right, min)
    };
    let offsets = radii
        .into_iter()
        .map(|r| {
            let outcome = if singular {
                "singular_base"
            } else if r.is_zero() {
                "r_zero"
            } else {
                "offset"
            };
            let cusps = (!singular).then(|| {
                let poly = curve.cusp_polynomial(&r);
                cusp_zeros(&curve, &r, &width)
                    .into_iter()
                    .map(|t| {
                        let m = roots::multiplicity(&poly, &t);
                        (t, m)
                    })
                    .collect()
            });
            OffsetData {
                curve: curve.offset(&r),
                r,
                outcome,
                cusps,
            }
        })
        .collect();
    Computed {
        curve,
        singular,
        poles,
        line,
        left,
        right,
        min,
        offsets,
        single,
    }
}
