//! The conic claims of Chiang ("Conic table"): `chiang.conic_table` (Table 1,
//! every printed entry against the exact derivation) and `chiang.conic_type` (the paper's angle
//! rule against the conic's own invariants, on Table 1 and on thousands of random planes).
//!
//! # The table
//! Table 1 is kept **as printed data** ([`TABLE1`]): the restoration of the OCR'd scan (square
//! roots restored, signs as printed), plus the plane equations as the OCR reads them (the
//! restoration leaves those out) and, in [`OCR_READINGS`], the OCR's literal reading of every
//! entry where it differs from the restoration. Each column is derived exactly over [`Radical`] (`Q(sqrt 2)`
//! here): the plane through `(1, 1, 1)` with the printed normal `N` is `N . x = N . (1,1,1)`, and
//! [`ConeSection::new`] cuts the cone's two ruled surfaces with it (Chiang's theorem with apex
//! `B = 0`: `w_k = N . q_k`, `w_k r_k = -d q_k`). Entries are judged one by one:
//! * a weight is *equal*, or *equal up to the common weight scale* (the three printed weights of
//!   the piece are the derived ones times one non-zero factor `lambda`, which leaves the curve
//!   unchanged; the factor is reported), or *different* (both values shown);
//! * a control point is equal or different (points are invariant under weight scaling);
//! * the poles `C-(t) = inf`: every printed parameter is a zero of the derived weight polynomial
//!   in `[0, 1]` (exact evaluation at the printed radical), and every derived pole (an isolating
//!   interval from `exactcheck_core::roots`, narrowed to width `<= 1/1024`, or the exact root)
//!   holds exactly one printed value.
//!   `C+` has no printed poles: its derived poles are reported, not judged;
//! * the normal: the printed control points `r0+, r1+, r2+` span a plane with this normal;
//! * the plane equation: it is the plane through `(1, 1, 1)` with the printed normal (the
//!   coefficient vectors `(a, b, c, rhs)` are proportional).
//!
//! Where the OCR's literal reading differs from the restoration the evidence says, computed,
//! which of the two the derivation supports.
//!
//! # The type
//! [`check_section`] decides the type of a section three ways and requires them to agree: the
//! paper's angle rule ([`angle_rule`]: exact comparisons of `c^2` with `a^2 + b^2`, no
//! trigonometry), the weight discriminant and circle test of **each** piece
//! ([`exactcheck_core::conic::bezier_type`]), and the number of rulings parallel to the plane —
//! the distinct zeros of the weight polynomials of the two pieces (which together run once
//! around the circle of directions; their shared end directions `(1,0,1)` and `(0,1,1)` counted
//! once): 0 for an ellipse, a circle or the apex alone, 1 for a parabola or a double line, 2 for
//! a hyperbola or a line pair. Every section's curve points at several exact rational parameters
//! are then substituted into the plane and into `x^2 + y^2 - z^2`. The random planes
//! (`exactcheck_exact::random_plane`, seeded workspace [`Rng`]) come from generators aimed at the boundaries:
//! `theta = pi/4` exactly (Pythagorean normals and radical ones `(a, b, sqrt(a^2 + b^2))`), circles
//! (`a = b = 0`), `c = 0`, planes through the apex (`d = 0`), pieces with `w1 = 0`
//! (`a + b + c = 0`) and normals with radical entries (`q + q' sqrt k`).
//!
//! Nothing here is hand-written mathematics beyond the bookkeeping: the sections, poles and types
//! are `exactcheck_core::conic`'s, computed over the exact field.
//!
//! Rust, not an embedded claims file: Table 1 is judged entry by entry (weights up to a
//! common factor, poles by root isolation, the OCR's readings), and the type rule on thousands of
//! seeded random planes; a claims file has no such judgements.

use super::{Claim, Outcome, Verdict};
use exactcheck_core::bezier::RationalBezierCurve;
use exactcheck_core::conic::{
    angle_rule, bezier_type, ConePiece, ConeSection, ConicType, DegenerateConic, SectionPiece,
    SectionType,
};
use exactcheck_core::roots::{IsolatedRoot, Refiner};
use exactcheck_core::ruled::Plane;
use exactcheck_core::{proportional, Field, Hom4, Ring, Rng, Vec3};
use exactcheck_exact::random_plane::{random_plane, PlaneKind};
use exactcheck_exact::{Radical, Rational};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// The `chiang.conic_*` claims, statements as printed.
pub fn claims() -> Vec<Claim> {
    vec![
        claim!("chiang.conic_table", Holds, "Table 1 (cone K = V+ quarter, control vectors (1,0,1), (1/sqrt2)(1,1,1), (0,1,1), and V- three-quarter, (0,1,1), -(1/sqrt2)(1,1,1), (1,0,1); planes I through (1,1,1)): normal (0,0,1) circle: z - 1 = 0, w+ = 1, 1/sqrt2, 1, r+ = (1,0,1), (1,1,1), (0,1,1), w- = 1, -1/sqrt2, 1, r- = the + points reversed, C-(t) = inf: none; (1,1,3) ellipse: x + y + 3z = 4, w+ = 4, 5/sqrt2, 4, r+ = (5/4,0,5/4), (1,1,1), (0,5/4,5/4), w- = 4, -5/sqrt2, 4, C-: none; (1,1,sqrt2) parabola: x + y + sqrt2 z = 2 - sqrt2 (OCR), w+ = 1+sqrt2 (all three), r+ = (sqrt2,0,sqrt2), (1,1,1), (0,sqrt2,sqrt2), w- = 1+sqrt2, -sqrt2-1, 1+sqrt2, C-: t = 1/2; (1,1,0) hyperbola: x + y = 2, w+ = 1, sqrt2, 1, r+ = (2,0,2), (1,1,1), (0,2,2), w- = 1, -sqrt2, 1, C-: t = 1/sqrt2, t = 1 - 1/sqrt2", conic_table_claim),
        claim!("chiang.conic_type", Holds, "The intersection of the plane I with the cone K is a circle, an ellipse, a parabola or a hyperbola as the angle theta between the normal of I and the axis of K is 0, between 0 and pi/4, pi/4, or between pi/4 and pi/2 (Table 1: (0,0,1) circle, (1,1,3) ellipse, (1,1,sqrt2) parabola, (1,1,0) hyperbola)", conic_type_claim),
    ]
}

fn conic_table_claim() -> Result<Outcome, String> {
    check_table(&TABLE1)
}

fn conic_type_claim() -> Result<Outcome, String> {
    check_types(TYPE_SEED, TYPE_PLANES)
}

mod data;
mod table;
#[cfg(test)]
mod tests;
mod types;

pub use data::*;
pub use table::*;
pub use types::*;
