//! The worked example (section 3): `u = (10, -1)`, `v = (1, 10)`, `p0 = (0, 0, 0)`, a
//! cubic PH curve. Every printed number is data (strings as printed) and judged against the
//! exact value computed by [`exactcheck_core::ph`] over [`Rational`].
//!
//! * `chiang.ph_points` — `p1..p3` against the control points integrated from the hodograph
//!   (`p_{i+1} = p_i + h_i / 3`), entry by entry; the base curve's derivative is checked against
//!   `(u^2 - v^2, 2uv)` at rational parameters.
//! * `chiang.ph_normals` — `q0..q2` against `V = (-Y', X', sigma)`: per control vector equal?,
//!   horizontally perpendicular to the hodograph coefficient `h_i` (the derived `q_i` is
//!   `(-h_iy, h_ix, sigma_i)`, perpendicular by construction)?, at 45 degrees (`|xy| = z`; the
//!   45-degree property is one of `V(t)`, the derived middle vector is horizontal)? Then every
//!   sign pattern of the printed non-zero entries is tried against the left field
//!   `(-Y', X', sigma)` (the claim's `V`) and the right field `(Y', -X', sigma)`: the patterns
//!   that give each are reported.
//! * `chiang.ph_radius` — the smallest radius of curvature exactly
//!   ([`PhCurve::min_radius`]: a candidate certified by root isolation), the printed decimal
//!   judged (a tie is named), and the cusps at the printed radii counted exactly two
//!   independent ways: the zeros of `sigma^2 - 2 r w` with multiplicity
//!   ([`PhCurve::offset_cusps`]), and the common zeros of the quotient-rule numerators
//!   `W X' - X W'`, `W Y' - Y W'` of the rational offset curve itself (its derivative;
//!   [`common_unit_roots`]), whose monic gcd must equal the monic cusp polynomial. Each part of
//!   the printed sentence is decided as printed; a value strictly between the printed 12.6 and
//!   the exact minimum is a counter-example to "r > 12.6: two cusps".
//! * `chiang.ph_offsets` — every printed decimal of `r0` and `w0` against the exact value:
//!   fraction, certified decimal, deviation, and computed readings (the exact value or its
//!   magnitude — a lost minus sign — rounded or truncated to the printed digits).

use super::{example_curve, q};
use crate::claims::printed::{
    decimal, deviation_text, inv_pow10, places, radical, rational, rounds_to, ties, truncates_to,
};
use crate::claims::{Equation, Erratum, Outcome, Verdict};
use exactcheck_core::ph::{Cusp, PhCurve, RadiusBound, Side};
use exactcheck_core::roots::{common_unit_roots, gcd, refine, IsolatedRoot};
use exactcheck_core::{Bernstein, OrderedField, Ring, Vec3};
use exactcheck_exact::expr::CoeffExpr;
use exactcheck_exact::expr::{AddOp, Expr, ExprKind, MulOp};
use exactcheck_exact::planar::{self_intersections_xy, Budget};
use exactcheck_exact::Rational;

/// The printed control points `p1, p2, p3` (the paper: "p1 = (33, 20/3, 0), p2 = (79/3, 119/3,
/// 0), p3 = (-20/3, 33, 0)").
pub const PRINTED_POINTS: [[&str; 3]; 3] = [
    ["33", "20/3", "0"],
    ["79/3", "119/3", "0"],
    ["-20/3", "33", "0"],
];

/// The printed control vectors `q0, q1, q2` of the rotated normal field.
pub const PRINTED_NORMALS: [[&str; 3]; 3] =
    [["20", "99", "101"], ["99", "20", "0"], ["20", "99", "101"]];

/// The printed smallest radius of the osculating circle.
pub const PRINTED_MIN_RADIUS: &str = "12.6";

/// The printed offsets: `(r, r0)` for `r = 3, 12.6, 15`.
pub const PRINTED_OFFSETS: [(&str, [&str; 3]); 3] = [
    ("3", ["0.594", "2.94", "3"]),
    ("12.6", ["2.5", "12.4", "12.6"]),
    ("15", ["2.96", "14.7", "15"]),
];

/// The printed weight of `r0`, the same for every `r`.
pub const PRINTED_W0: &str = "101";

pub(super) const AXES: [&str; 3] = ["x", "y", "z"];

pub(super) fn coords(p: &Vec3<Rational>) -> [Rational; 3] {
    [p.x.clone(), p.y.clone(), p.z.clone()]
}

pub(super) fn triple(p: &[Rational; 3]) -> String {
    format!("({}, {}, {})", p[0], p[1], p[2])
}

pub(super) fn parse_triple(p: &[&str; 3]) -> Result<[Rational; 3], String> {
    Ok([rational(p[0])?, rational(p[1])?, rational(p[2])?])
}

mod offsets;
mod points;
mod radius;
#[cfg(test)]
mod tests;

pub use offsets::*;
pub use points::*;
pub use radius::*;
