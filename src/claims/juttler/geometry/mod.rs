//! The geometric properties of the net projection theta and of delta in Juettler's paper (the
//! list after Satz 5 — Theorem 5 in the paper's German numbering — and Satz 7): preimages of circles and lines of P, images of lines, the
//! projecting line of a plane, and Miquel's configuration of a biquadratic patch on K.
//!
//! Each check decides its claim by computation: symbolic identities expanded over polynomial
//! rings (via [`prove_all`]), signs of symbolic minors read off their terms, and exact instances
//! over [`Rational`] drawn by the workspace's seeded generator (deterministic).
//!
//! One file per claim; this module holds the plumbing they share (early stops with a decided
//! outcome, exact-matrix helpers). The reusable mathematics lives in
//! [`exactcheck_core::inertia`] (Laplace determinant, principal minors, Jacobi's rule,
//! polarization) and [`exactcheck_exact::symbolic`] (form matrices of polynomial quadrics,
//! definite signs, substitutions).

use crate::claims::engine::{prove_all, Rng, Symbols};
use crate::claims::{Outcome, Verdict};
use exactcheck_core::bernstein::Bernstein;
use exactcheck_core::inertia::{det, jacobi_inertia, principal};
use exactcheck_core::linalg::{Inertia, Matrix};
use exactcheck_core::miquel::{
    bilinear_patch, cross3, lebesgue_patch, miquel_configuration, MiquelConfiguration,
};
use exactcheck_core::quadric::{
    lebesgue, lebesgue_curve, sigma, sphere_form, theta, theta_preimage_point,
};
use exactcheck_core::{det4, Hom4, Ring, Sign, TensorPatch};
use exactcheck_exact::poly::{Poly, Var};
use exactcheck_exact::symbolic::{
    definite_sign, divide_by_var, form_matrix, quadratic, substitute_all, substitute_ints,
};
use exactcheck_exact::Rational;

type P = Poly<Rational>;
type Q = Rational;

mod circle_preimage;
mod line_image;
mod line_preimage;
mod plane_lines;
mod satz7;

pub use circle_preimage::circle_preimage;
pub use line_image::line_image;
pub use line_preimage::line_preimage;
pub use plane_lines::plane_lines;
pub use satz7::satz7;

// ---------------------------------------------------------------------------------- plumbing

/// Why a check stopped early: a decided outcome (a failed identity or instance) or an error.
enum Stop {
    Decided(Outcome),
    Error(String),
}

impl From<String> for Stop {
    fn from(e: String) -> Self {
        Stop::Error(e)
    }
}

fn run(f: impl FnOnce() -> Result<Outcome, Stop>) -> Result<Outcome, String> {
    match f() {
        Ok(o) | Err(Stop::Decided(o)) => Ok(o),
        Err(Stop::Error(e)) => Err(e),
    }
}

fn fails(method: &str, evidence: String) -> Stop {
    Stop::Decided(Outcome {
        verdict: Verdict::Fails,
        method: method.into(),
        evidence,
        erratum: None,
    })
}

/// Proves every residual (modulo `relations`) and returns how many; stops with the engine's
/// counter-example otherwise.
fn prove(
    sym: &Symbols,
    residuals: &[(String, P)],
    relations: &[P],
    method: &str,
) -> Result<usize, Stop> {
    let r: Vec<(&str, P)> = residuals
        .iter()
        .map(|(w, p)| (w.as_str(), p.clone()))
        .collect();
    let o = prove_all(sym, &r, relations, method);
    if o.verdict == Verdict::Proved {
        Ok(residuals.len())
    } else {
        Err(Stop::Decided(o))
    }
}

fn q(n: i64) -> Q {
    Q::from_integer(n)
}

fn inertia_text(i: &Inertia) -> String {
    format!("({}, {}, {})", i.positive, i.negative, i.zero)
}

fn fmt_hom(v: &Hom4<Q>) -> String {
    format!("({}, {}, {}, {})", v.0[0], v.0[1], v.0[2], v.0[3])
}

// ------------------------------------------------------------------------- exact helpers

fn matrix(rows: Vec<Vec<Q>>) -> Result<Matrix<Q>, Stop> {
    Matrix::from_rows(rows).map_err(|e| Stop::Error(e.to_string()))
}

fn inertia_of(rows: Vec<Vec<Q>>) -> Result<Inertia, Stop> {
    matrix(rows)?
        .inertia()
        .map_err(|e| Stop::Error(e.to_string()))
}

/// The matrix of the quadratic function `f` in the vectors `basis` (by polarization,
/// [`exactcheck_core::inertia::polarized`]).
fn polarized(f: &dyn Fn(&Hom4<Q>) -> Q, basis: &[Hom4<Q>]) -> Result<Vec<Vec<Q>>, Stop> {
    exactcheck_core::inertia::polarized(f, basis)
        .map_err(|e| Stop::Error(format!("polarization: {e}")))
}

/// The symmetric matrix of the quadratic form `q` in `vars` ([`form_matrix`]).
fn form_matrix_of(q: &P, vars: &[Var]) -> Result<Vec<Vec<P>>, Stop> {
    form_matrix(q, vars).map_err(|e| Stop::Error(format!("form matrix: {e}")))
}

/// `p` with the variables `vars` replaced by the integers `vals`.
fn at(p: &P, vars: &[Var], vals: &[i64]) -> P {
    substitute_ints(p, vars, vals)
}

fn unit(i: usize) -> Hom4<Q> {
    Hom4(core::array::from_fn(|j| q(i64::from(j == i))))
}

/// The delta-image of the line `A + t (B - A)` (Bernstein control `A, B`): its three quadratic
/// control vectors (by [`lebesgue_curve`]) and whether the curve lies on K identically.
fn image_controls(a: &Hom4<Q>, b: &Hom4<Q>) -> Result<([Hom4<Q>; 3], bool), String> {
    let x: [Bernstein<Q>; 4] =
        core::array::from_fn(|i| Bernstein::new(vec![a.0[i].clone(), b.0[i].clone()]));
    let k = lebesgue_curve(&x);
    let sq = |i: usize| k[i].mul(&k[i]);
    let on_k = sq(0)
        .checked_sub(&sq(1))
        .and_then(|s| s.checked_sub(&sq(2)))
        .and_then(|s| s.checked_sub(&sq(3)))
        .map(|s| s.is_zero())
        .map_err(|e| format!("k0^2 - k1^2 - k2^2 - k3^2 of a line image: {e}"))?;
    let c = core::array::from_fn(|j| Hom4(core::array::from_fn(|i| k[i].coeffs()[j].clone())));
    Ok((c, on_k))
}

/// The rank of a list of 4-vectors.
fn rank(vs: &[Hom4<Q>]) -> Result<usize, Stop> {
    Ok(matrix(vs.iter().map(|v| v.0.to_vec()).collect())?.rank())
}

/// A basis of `{x : v . x = 0 for all v in vs}`.
fn orthogonal(vs: &[Hom4<Q>]) -> Result<Vec<Hom4<Q>>, Stop> {
    Ok(matrix(vs.iter().map(|v| v.0.to_vec()).collect())?
        .nullspace()
        .into_iter()
        .map(|n| Hom4(core::array::from_fn(|i| n[i].clone())))
        .collect())
}

/// The Plücker-linear plane `N(A, B)` of the delta-image circle of the line `AB`
/// (`m_ij = A_i B_j - A_j B_i`): `(m03 - m12, m02 - m13, -(m01 + m23), m03 + m12)`. The check
/// `line_image` proves `cross3(K20, K11, K02) = 4 G N` with `G = (m01 - m23)^2 + (m02 + m13)^2`.
fn image_plane<T: Ring>(a: &Hom4<T>, b: &Hom4<T>) -> Hom4<T> {
    let [m01, m02, m03, m12, m13, m23] = a.minors(b);
    Hom4::new(
        m03.sub_ref(&m12),
        m02.sub_ref(&m13),
        -(m01.add_ref(&m23)),
        m03 + m12,
    )
}

/// The two linear complexes of the congruence (12): `g1 = m01 - m23`, `g2 = m02 + m13`.
fn congruence_forms<T: Ring>(a: &Hom4<T>, b: &Hom4<T>) -> [T; 2] {
    let [m01, m02, _, _, m13, m23] = a.minors(b);
    [m01 - m23, m02 + m13]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn expect(o: Result<Outcome, String>, v: Verdict) -> Outcome {
        let o = o.expect("the check runs");
        assert_eq!(o.verdict, v, "{}", o.evidence);
        o
    }

    #[test]
    fn circle_preimage_is_proved() {
        let o = expect(circle_preimage(), Verdict::Proved);
        assert!(o.evidence.contains("(2, 2, 0)"), "{}", o.evidence);
    }

    #[test]
    fn line_preimage_is_proved() {
        expect(line_preimage(), Verdict::Proved);
    }

    #[test]
    fn line_image_is_proved() {
        expect(line_image(), Verdict::Proved);
    }

    #[test]
    fn plane_lines_is_proved() {
        expect(plane_lines(), Verdict::Proved);
    }
}
