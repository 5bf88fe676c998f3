//! Chiang ("Cyclographic maps / offsets" and "PH curves"): the offset theorem,
//! the corollary's degrees and the worked example of a cubic PH curve, printed number by printed
//! number — `chiang.offset`, `chiang.ph_degree`, `chiang.ph_points`, `chiang.ph_normals`,
//! `chiang.ph_radius`, `chiang.ph_offsets`.
//!
//! The construction lives in `exactcheck_core::ph` ([`PhCurve`], generic over a Q-algebra);
//! here it runs over the proof engine's polynomial ring `Q[u_i, v_i, s_x, s_y, r, t]` (symbolic
//! proofs: a residual "is zero" means it expanded to the zero polynomial), over [`Rational`]
//! (random exact instances and the worked example) and, for printed decimals, the comparisons
//! of `crate::claims::printed` (exact, in `Radical`).
//!
//! * `offset` — `chiang.offset` (restrictions (1)-(3) give the `r`-offset, every property as a
//!   polynomial identity in a symbolic `t`) and `chiang.ph_degree` (the corollary's degrees
//!   `n - 1` and `2n - 1`, attained: leading power coefficient and the gcd of the homogeneous
//!   coordinates).
//! * `example` — `chiang.ph_points`, `chiang.ph_normals` (with the search over sign patterns
//!   of the printed magnitudes), `chiang.ph_radius` (exact smallest radius, exact cusp counts
//!   two independent ways) and `chiang.ph_offsets` (every printed decimal of the offsets).
//!
//! Hand-written here: only the bookkeeping of the claims (the residual list, the enumeration of
//! the 2^8 sign patterns of the printed normals, the readings of printed decimals); the
//! mathematics is `exactcheck_core::ph`, the proofs are the engine's, the decimal judgements are
//! `crate::claims::printed`.
//!
//! Self-intersections of the offsets are decided exactly by `exactcheck_exact::planar` (the
//! resultant of the divided differences, each candidate pair excluded by tensor-Bernstein signs
//! or certified by Poincare-Miranda): [`self_intersections_of`].
//!
//! Rust, not an embedded claims file, claim by claim: `chiang.offset` and `chiang.ph_degree`
//! expand the offset theorem for families of degrees (a claims file states one formula of fixed
//! degree); `chiang.ph_points` and `chiang.ph_normals` judge the printed numbers against the
//! control points and normals `exactcheck_core::ph` derives (the normals under every sign
//! pattern and both orientations); `chiang.ph_radius` certifies the smallest radius by root
//! isolation and counts cusps two independent ways; `chiang.ph_offsets` judges every printed
//! decimal against the offsets the core computes, with the readings of a lost sign or a
//! truncation.

mod example;
mod offset;

pub use example::{
    ph_normals_with, ph_offsets_markdown, ph_offsets_rows, ph_points_with,
    self_intersection_evidence, self_intersections_of, weights_markdown, OffsetRow,
    PRINTED_MIN_RADIUS, PRINTED_NORMALS, PRINTED_OFFSETS, PRINTED_POINTS, PRINTED_W0,
};
pub use offset::{offset_proof, BaseForm, DEGREE_RANDOM_MAX_K, DEGREE_SYMBOLIC_MAX_K};

use super::{Claim, Outcome, Verdict};
use exactcheck_core::ph::PhCurve;
use exactcheck_core::{Bernstein, Vec3};
use exactcheck_exact::Rational;

/// The `chiang.offset` and `chiang.ph_*` claims, statements as printed.
pub fn claims() -> Vec<Claim> {
    vec![
        claim!("chiang.offset", Proved, "restrictions (1) base curve in a plane z = const, (2) ruling perpendicular to the xy-projection of the tangent B'(t), (3) ruling at 45 degrees to z = 0: a surface obeying all three, with base curve in z = -r, meets z = 0 in the r-offset of B", offset_claim),
        claim!("chiang.ph_degree", Proved, "Corollary: for a PH curve B(t) of degree n in the xy-plane, the rotated normal vector field V(t) has degree n-1; the r-offset, the intersection of the ruled surface gamma(B(t)) with the plane z - r = 0, is a rational Bezier curve of degree 2n-1", degree_claim),
        claim!("chiang.ph_points", Holds, "Example: u0=10, u1=-1, v0=1, v1=10, p0=(0,0,0); by Theorem 2 the other control points are p1=(33, 20/3, 0), p2=(79/3, 119/3, 0), p3=(-20/3, 33, 0)", points_claim),
        claim!("chiang.ph_normals", Fails, "Example: the rotated normal vector field V(t) of degree 2 has, by Theorem 1, the control points q0=(20,99,101), q1=(99,20,0), q2=(20,99,101)", normals_claim),
        claim!("chiang.ph_radius", Fails, "Example: the smallest osculating circle radius is 12.6; for r < 12.6 the r-offset has no self-intersection, for r = 12.6 it has exactly one cusp, for r > 12.6 it self-intersects and has two cusps", radius_claim),
        claim!("chiang.ph_offsets", Fails, "Example (Table 2): for r = 3, r0 = (0.594, 2.94, 3); for r = 12.6, r0 = (2.5, 12.4, 12.6); for r = 15, r0 = (2.96, 14.7, 15); the weight of the first control point r0 is w0 = 101 in every case", offsets_claim),
    ]
}

fn offset_claim() -> Result<Outcome, String> {
    offset::offset_check()
}

fn degree_claim() -> Result<Outcome, String> {
    offset::degree_check()
}

fn points_claim() -> Result<Outcome, String> {
    ph_points_with(&PRINTED_POINTS)
}

fn normals_claim() -> Result<Outcome, String> {
    ph_normals_with(&PRINTED_NORMALS)
}

fn radius_claim() -> Result<Outcome, String> {
    example::radius_check()
}

fn offsets_claim() -> Result<Outcome, String> {
    example::offsets_check()
}

/// The worked example over the rationals: `u = (10, -1)`, `v = (1, 10)` in Bernstein form,
/// starting at the origin.
pub fn example_curve() -> PhCurve<Rational> {
    let c = |k: i64| q(k, 1);
    PhCurve::new(
        Bernstein::new(vec![c(10), c(-1)]),
        Bernstein::new(vec![c(1), c(10)]),
        Vec3::new(c(0), c(0), c(0)),
    )
    .expect("same degree, not zero")
}

/// `n / d` (`d != 0`).
fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).expect("a non-zero denominator")
}
