//! Claims of Juettler's paper on rational curves and surfaces on quadrics.
//!
//! The paper is in German and numbers its theorems "Satz 1" to "Satz 11" (Satz: theorem) and
//! its lemmas "Lemma 4" and "Lemma 10" in one sequence; the claim ids keep that numbering
//! (`juttler.satz3` is the paper's Theorem 3), and so do the functions and modules named after
//! them (`satz3`, [`geometry::satz7`]).
//!
//! Printed formulas are kept as text exactly as the paper prints them and parsed; the maps of
//! `exactcheck_core::quadric` are the independent derivation they are compared against, and the
//! properties are proved by expanding residuals over polynomial rings.
//!
//! Three claims state printed formulas alone and are decided by the claims-file engine from
//! the embedded `claims.toml` (`Claim::printed`): `juttler.satz5` (the line (12) and the focal lines
//! (13) meet at lambda = 1, mu = +-i), `juttler.focal_absolute` ((13) on (14)) and
//! `juttler.satz11` (the line (18) meets the real focal lines). The others stay Rust, because
//! the claims format cannot say what they check:
//! * `lebesgue`, `dietz` — the printed maps (7), (8) against `quadric::lebesgue` and
//!   `quadric::dietz`, and the converses on exact instances drawn by the seeded generator;
//! * `satz1` — the product rule for control points against `quadric` on Bezier curves and
//!   patches of every degree tried;
//! * `satz2`, `sigma_inverse`, `satz3`, `satz8`, `satz9` — the printed sigma, sigma^-1, theta,
//!   tau, alpha against the `quadric` maps they restrict or factor;
//! * `lemma4`, `lemma10` — the preimage lines through `quadric::theta_preimage_point` and
//!   `alpha_preimage_point`;
//! * `circle_preimage`, `line_preimage`, `line_image`, `plane_lines` ([`geometry`]) — the
//!   quadrics and circles through the `quadric` maps, with the classification of their forms;
//! * `interpolation`, `interpolation_degree` — a nullspace of an exact linear system on seeded
//!   instances, and the degree count;
//! * `satz7` — Miquel's configuration on seeded random patches.

use super::engine::{prove_all, Rng, Symbols};
use super::{Claim, Outcome, Verdict};
use geometry::{circle_preimage, line_image, line_preimage, plane_lines, satz7};

mod converse;
pub mod geometry;
mod interpolation;

use converse::{converse_h, converse_k};
use exactcheck_core::quadric::{
    alpha, alpha_preimage_point, dietz, lebesgue, paraboloid_form, psi, sigma, sigma_inverse,
    sphere_form, tau, theta, theta_preimage_point,
};
use exactcheck_core::{Hom4, Ring};
use exactcheck_exact::poly::Poly;
use exactcheck_exact::Rational;
use interpolation::{interpolation, interpolation_degree};

type P = Poly<Rational>;

/// (7) as printed.
const LEBESGUE_PRINTED: [&str; 4] = [
    "p0^2+p1^2+p2^2+p3^2",
    "2*p0*p1 - 2*p2*p3",
    "2*p0*p2 + 2*p1*p3",
    "p1^2+p2^2-p0^2-p3^2",
];
/// (8) as printed.
const DIETZ_PRINTED: [&str; 4] = ["q0*q3", "q1*q3", "q0*q2", "q1*q2"];
/// (10) as printed.
const SIGMA_PRINTED: [&str; 4] = ["p0^2+p1^2+p2^2", "2*p0*p1", "2*p0*p2", "p1^2+p2^2-p0^2"];
/// sigma^-1 as printed.
const SIGMA_INV_PRINTED: [&str; 4] = ["k0 - k3", "k1", "k2", "0"];
/// (11) as printed.
const THETA_PRINTED: [&str; 4] = ["p0^2+p3^2", "p0*p1 - p2*p3", "p0*p2 + p1*p3", "0"];
/// (16) as printed.
const TAU_PRINTED: [&str; 4] = ["q0^2", "q0*q1", "q0*q2", "q1*q2"];
/// (17) as printed.
const ALPHA_PRINTED: [&str; 4] = ["q0*q3", "q1*q3", "q0*q2", "q0*q3"];

/// The `juttler.*` claims.
pub fn claims() -> Vec<Claim> {
    vec![
        claim!("juttler.lebesgue", Proved, "(7) k0 = p0^2+p1^2+p2^2+p3^2, k1 = 2p0p1 - 2p2p3, k2 = 2p0p2 + 2p1p3, k3 = p1^2+p2^2-p0^2-p3^2 satisfies (5) k0^2 = k1^2 + k2^2 + k3^2 for all p", lebesgue_claim),
        claim!("juttler.dietz", Proved, "(8) h0 = q0q3, h1 = q1q3, h2 = q0q2, h3 = q1q2 satisfies (6) h0 h3 = h1 h2 for all q", dietz_claim),
        claim!("juttler.satz1", Proved, "Satz 1: delta maps a rational Bezier curve of degree n to one of degree 2n on K (control points by the product rule), a patch of degree (m,n) to one of degree (2m,2n)", satz1),
        claim!("juttler.satz2", Proved, "Satz 2: delta restricted to p3 = 0 equals sigma (10) = (p0^2+p1^2+p2^2, 2p0p1, 2p0p2, p1^2+p2^2-p0^2)", satz2),
        claim!("juttler.sigma_inverse", Proved, "sigma^-1(k) = (k0 - k3, k1, k2, 0) inverts sigma (projectively)", sigma_inverse_claim),
        claim!("juttler.satz3", Proved, "Satz 3: delta = sigma o theta with theta (11) = (p0^2+p3^2, p0p1 - p2p3, p0p2 + p1p3, 0)", satz3),
        claim!("juttler.lemma4", Proved, "Lemma 4: the theta-preimage of p = (p0,p1,p2,0) is the line lambda (p0,p1,p2,0) + mu (0,p2,-p1,p0) (12)", lemma4),
        Claim::printed("juttler.satz5"),
        Claim::printed("juttler.focal_absolute"),
        claim!("juttler.circle_preimage", Proved, "the preimage of a circle of P under theta (so the delta-preimage of a circle of K not through z) is a hyperboloid of one sheet", circle_preimage),
        claim!("juttler.line_preimage", Proved, "the preimage of a line of P under theta (so the delta-preimage of a circle of K through z) is a hyperbolic paraboloid", line_preimage),
        claim!("juttler.line_image", Proved, "the theta-image of a non-projecting line is a circle or a line of P; its delta-image is a circle on K", line_image),
        claim!("juttler.plane_lines", Proved, "every plane contains exactly one projecting line (12); the lines of the plane map (theta, delta) to the circles through one fixed point, the image of that projecting line", plane_lines),
        claim!("juttler.satz8", Proved, "Satz 8: psi restricted to the plane q3 = q0 equals tau (16) = (q0^2, q0q1, q0q2, q1q2)", satz8),
        claim!("juttler.satz9", Proved, "Satz 9: psi = tau o alpha with alpha (17) = (q0q3, q1q3, q0q2, q0q3)", satz9),
        claim!("juttler.lemma10", Proved, "Lemma 10: the alpha-preimage of q = (q0,q1,q2,q0) is the line lambda (q0,q1,q2,q0) + mu (q0,q1,0,0) (18)", lemma10),
        claim!("juttler.interpolation", Holds, "interpolation on K by rational curves reduces to a homogeneous linear system (and works)", interpolation),
        claim!("juttler.interpolation_degree", Fails, "the interpolating curves on K need fewer degrees than with plain stereographic projection", interpolation_degree),
        claim!("juttler.satz7", Holds, "Satz 7 (Dietz): if a biquadratic Bezier patch y(u,v) lies on K, with boundary circles y(0,v), y(u,0), y(1,v), y(u,1) meeting at the corners p_i and second points q_i, then p1, q2, p3, q4 lie on a circle (and q1, p2, q3, p4) — Miquel's theorem", satz7),
        Claim::printed("juttler.satz11"),
    ]
}

/// Residuals `printed_i - derived_i` (exact equality of coordinates).
fn equal_coordinates<C: Ring>(
    label: &str,
    printed: &Hom4<Poly<C>>,
    derived: &Hom4<Poly<C>>,
) -> Vec<(String, Poly<C>)>
where
    Poly<C>: Ring,
{
    (0..4)
        .map(|i| {
            (
                format!("{label}: coordinate {i}"),
                printed.0[i].clone() - &derived.0[i],
            )
        })
        .collect()
}

/// Residuals of projective equality: the six 2x2 minors (and neither side may be zero).
fn proportional_residuals<C: Ring>(
    label: &str,
    a: &Hom4<Poly<C>>,
    b: &Hom4<Poly<C>>,
) -> Result<Vec<(String, Poly<C>)>, String>
where
    Poly<C>: Ring,
{
    if a.is_zero() || b.is_zero() {
        return Err(format!("{label}: a side is the zero vector"));
    }
    Ok(a.minors(b)
        .into_iter()
        .enumerate()
        .map(|(i, m)| (format!("{label}: minor {i}"), m))
        .collect())
}

fn decide<
    C: exactcheck_exact::prove::PointField + std::fmt::Display + exactcheck_exact::expr::CoeffExpr,
>(
    sym: &Symbols,
    residuals: &[(String, Poly<C>)],
    relations: &[Poly<C>],
    method: &str,
) -> Outcome
where
    C::Value: exactcheck_exact::expr::CoeffExpr,
{
    let r: Vec<(&str, Poly<C>)> = residuals
        .iter()
        .map(|(w, p)| (w.as_str(), p.clone()))
        .collect();
    prove_all(sym, &r, relations, method)
}

fn lebesgue_claim() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["p0", "p1", "p2", "p3"]);
    let printed: Hom4<P> = sym.hom4(LEBESGUE_PRINTED)?;
    let derived = lebesgue(&sym.hom4_vars::<Rational>("p"));
    let mut res = vec![(
        "k0^2 - k1^2 - k2^2 - k3^2 with k as printed in (7)".to_string(),
        sphere_form(&printed),
    )];
    res.extend(equal_coordinates(
        "(7) as printed vs core::quadric::lebesgue",
        &printed,
        &derived,
    ));
    let mut out = decide(&sym, &res, &[], "symbolic expansion over Q[p0..p3]");
    out.evidence = format!("{}; {}", out.evidence, converse_k()?);
    Ok(out)
}

fn dietz_claim() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["q0", "q1", "q2", "q3"]);
    let printed: Hom4<P> = sym.hom4(DIETZ_PRINTED)?;
    let derived = dietz(&sym.hom4_vars::<Rational>("q"));
    let mut res = vec![(
        "h0 h3 - h1 h2 with h as printed in (8)".to_string(),
        paraboloid_form(&printed),
    )];
    res.extend(equal_coordinates(
        "(8) as printed vs core::quadric::dietz",
        &printed,
        &derived,
    ));
    let mut out = decide(&sym, &res, &[], "symbolic expansion over Q[q0..q3]");
    out.evidence = format!("{}; {}", out.evidence, converse_h()?);
    Ok(out)
}

fn satz2() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["p0", "p1", "p2", "p3"]);
    let printed_delta: Hom4<P> = sym.hom4(LEBESGUE_PRINTED)?;
    let printed_sigma: Hom4<P> = sym.hom4(SIGMA_PRINTED)?;
    let p3 = sym.vars.var("p3");
    let restricted = Hom4(printed_delta.0.map(|c| c.substitute(p3, &P::zero())));
    let mut res = equal_coordinates(
        "delta (7) at p3 = 0 vs sigma (10)",
        &restricted,
        &printed_sigma,
    );
    let p = sym.hom4_vars::<Rational>("p");
    res.extend(equal_coordinates(
        "(10) as printed vs core::quadric::sigma",
        &printed_sigma,
        &sigma(&p),
    ));
    Ok(decide(&sym, &res, &[], "symbolic expansion over Q[p0..p3]"))
}

fn sigma_inverse_claim() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["p0", "p1", "p2", "k0", "k1", "k2", "k3"]);
    let printed: Hom4<P> = sym.hom4(SIGMA_INV_PRINTED)?;
    let k = sym.hom4_vars::<Rational>("k");
    let mut res = equal_coordinates("sigma^-1 as printed vs core", &printed, &sigma_inverse(&k));
    let p = Hom4::new(
        sym.vars.poly("p0"),
        sym.vars.poly("p1"),
        sym.vars.poly("p2"),
        P::zero(),
    );
    // sigma^-1(sigma(p)) ~ p for p in P, for all p.
    res.extend(proportional_residuals(
        "sigma^-1(sigma(p)) ~ p",
        &sigma_inverse(&sigma(&p)),
        &p,
    )?);
    // sigma(sigma^-1(k)) ~ k for k on K: modulo k0^2 - k1^2 - k2^2 - k3^2.
    res.extend(proportional_residuals(
        "sigma(sigma^-1(k)) ~ k on K",
        &sigma(&sigma_inverse(&k)),
        &k,
    )?);
    Ok(decide(
        &sym,
        &res,
        &[sphere_form(&k)],
        "symbolic expansion modulo (5) k0^2 = k1^2+k2^2+k3^2",
    ))
}

fn satz3() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["p0", "p1", "p2", "p3"]);
    let printed: Hom4<P> = sym.hom4(THETA_PRINTED)?;
    let p = sym.hom4_vars::<Rational>("p");
    let mut res = equal_coordinates(
        "(11) as printed vs core::quadric::theta",
        &printed,
        &theta(&p),
    );
    res.extend(proportional_residuals(
        "delta(p) ~ sigma(theta(p))",
        &lebesgue(&p),
        &sigma(&printed),
    )?);
    Ok(decide(&sym, &res, &[], "symbolic expansion over Q[p0..p3]"))
}

/// The four 3x3 minors of the 3x4 matrix with rows `a, b, c`: all zero iff `a` lies in the span
/// of `b` and `c` (for independent `b`, `c`).
fn in_span<C: Ring>(
    label: &str,
    a: &Hom4<Poly<C>>,
    b: &Hom4<Poly<C>>,
    c: &Hom4<Poly<C>>,
) -> Vec<(String, Poly<C>)>
where
    Poly<C>: Ring,
{
    let cols = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];
    cols.iter()
        .map(|&[i, j, k]| {
            let m = |r: &Hom4<Poly<C>>, s: &Hom4<Poly<C>>, x: usize, y: usize| {
                r.0[x].mul_ref(&s.0[y]) - r.0[y].mul_ref(&s.0[x])
            };
            let det = a.0[i].mul_ref(&m(b, c, j, k)) - a.0[j].mul_ref(&m(b, c, i, k))
                + a.0[k].mul_ref(&m(b, c, i, j));
            (format!("{label}: 3x3 minor {i}{j}{k}"), det)
        })
        .collect()
}

fn lemma4() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["p0", "p1", "p2", "lambda", "mu", "x0", "x1", "x2", "x3"]);
    let p = Hom4::new(
        sym.vars.poly("p0"),
        sym.vars.poly("p1"),
        sym.vars.poly("p2"),
        P::zero(),
    );
    let (l, m) = (
        sym.vars.poly::<Rational>("lambda"),
        sym.vars.poly::<Rational>("mu"),
    );
    // Every point of (12) maps to p (projectively) ...
    let mut res = proportional_residuals(
        "theta(lambda A + mu B) ~ p",
        &theta(&theta_preimage_point(&p, &l, &m)),
        &p,
    )?;
    // ... and every point x lies on the line (12) of its image theta(x): the preimage is the line.
    let x = sym.hom4_vars::<Rational>("x");
    let tx = theta(&x);
    let a = theta_preimage_point(&tx, &P::one(), &P::zero());
    let b = theta_preimage_point(&tx, &P::zero(), &P::one());
    res.extend(in_span("x on the line (12) of theta(x)", &x, &a, &b));
    Ok(decide(
        &sym,
        &res,
        &[],
        "symbolic expansion over Q[p, lambda, mu, x]",
    ))
}

fn satz8() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["q0", "q1", "q2"]);
    let printed: Hom4<P> = sym.hom4(TAU_PRINTED)?;
    let (q0, q1, q2) = (
        sym.vars.poly::<Rational>("q0"),
        sym.vars.poly("q1"),
        sym.vars.poly("q2"),
    );
    let q = Hom4::new(q0.clone(), q1, q2, q0);
    let mut res = equal_coordinates("psi at q3 = q0 vs tau (16) as printed", &psi(&q), &printed);
    res.extend(equal_coordinates(
        "(16) as printed vs core::quadric::tau",
        &printed,
        &tau(&q),
    ));
    Ok(decide(
        &sym,
        &res,
        &[],
        "symbolic expansion over Q[q0,q1,q2]",
    ))
}

fn satz9() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["q0", "q1", "q2", "q3"]);
    let printed: Hom4<P> = sym.hom4(ALPHA_PRINTED)?;
    let q = sym.hom4_vars::<Rational>("q");
    let mut res = equal_coordinates(
        "(17) as printed vs core::quadric::alpha",
        &printed,
        &alpha(&q),
    );
    res.extend(proportional_residuals(
        "psi(q) ~ tau(alpha(q))",
        &psi(&q),
        &tau(&printed),
    )?);
    Ok(decide(&sym, &res, &[], "symbolic expansion over Q[q0..q3]"))
}

fn lemma10() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["q0", "q1", "q2", "lambda", "mu", "x0", "x1", "x2", "x3"]);
    let (q0, q1, q2) = (
        sym.vars.poly::<Rational>("q0"),
        sym.vars.poly("q1"),
        sym.vars.poly("q2"),
    );
    let q = Hom4::new(q0.clone(), q1, q2, q0);
    let (l, m) = (
        sym.vars.poly::<Rational>("lambda"),
        sym.vars.poly::<Rational>("mu"),
    );
    // Every point of (18) maps to q (projectively) ...
    let mut res = proportional_residuals(
        "alpha(lambda A + mu B) ~ q",
        &alpha(&alpha_preimage_point(&q, &l, &m)),
        &q,
    )?;
    // ... and every point x lies on the line (18) of its image alpha(x).
    let x = sym.hom4_vars::<Rational>("x");
    let ax = alpha(&x);
    let a = alpha_preimage_point(&ax, &P::one(), &P::zero());
    let b = alpha_preimage_point(&ax, &P::zero(), &P::one());
    res.extend(in_span("x on the line (18) of alpha(x)", &x, &a, &b));
    Ok(decide(
        &sym,
        &res,
        &[],
        "symbolic expansion over Q[q, lambda, mu, x]",
    ))
}

/// Satz 1: the delta-image of a degree-n curve is a degree-2n curve on K, with control points
/// from the product rule; of a bilinear patch, a biquadratic patch. Symbolic in the control
/// vectors and the parameters, for n = 1, 2, 3 and the (1,1) patch.
pub(super) fn satz1() -> Result<Outcome, String> {
    use exactcheck_core::quadric::{lebesgue_curve_scaled, lebesgue_patch_scaled};
    use exactcheck_core::{binomial, Bernstein, TensorPatch};
    let mut sym = Symbols::new(&["t", "u", "v"]);
    let mut res: Vec<(String, P)> = Vec::new();
    let inv_binom = |n: usize, k: usize| {
        let b = i64::try_from(binomial(n as u32, k as u32)).expect("C(6, k) fits in i64");
        P::constant(Rational::new(1, b).expect("a binomial coefficient is non-zero"))
    };
    for n in 1..=3usize {
        let x: [Bernstein<P>; 4] = std::array::from_fn(|a| {
            Bernstein::new(
                (0..=n)
                    .map(|i| sym.vars.poly::<Rational>(&format!("c{n}_{i}_{a}")))
                    .collect(),
            )
        });
        let t = sym.vars.poly::<Rational>("t");
        let scaled = lebesgue_curve_scaled(&x);
        let image: Vec<Bernstein<P>> = scaled
            .iter()
            .map(|e| {
                Bernstein::new(
                    e.iter()
                        .enumerate()
                        .map(|(k, c)| c.clone() * inv_binom(2 * n, k))
                        .collect(),
                )
            })
            .collect();
        if image.iter().any(|b| b.degree() != 2 * n) {
            return Err(format!("image of degree {n} is not of degree {}", 2 * n));
        }
        let at_t = Hom4::new(
            image[0].eval(&t),
            image[1].eval(&t),
            image[2].eval(&t),
            image[3].eval(&t),
        );
        let direct = lebesgue(&Hom4::new(
            x[0].eval(&t),
            x[1].eval(&t),
            x[2].eval(&t),
            x[3].eval(&t),
        ));
        res.extend(equal_coordinates(
            &format!("degree {n}: product-rule control points vs delta(x(t))"),
            &at_t,
            &direct,
        ));
        res.push((format!("degree {n}: image on K"), sphere_form(&at_t)));
    }
    // Bilinear patch -> biquadratic patch.
    let net: Vec<Vec<Hom4<P>>> = (0..2)
        .map(|i| {
            (0..2)
                .map(|j| {
                    Hom4(std::array::from_fn(|a| {
                        sym.vars.poly::<Rational>(&format!("n_{i}{j}_{a}"))
                    }))
                })
                .collect()
        })
        .collect();
    let (u, v) = (
        sym.vars.poly::<Rational>("u"),
        sym.vars.poly::<Rational>("v"),
    );
    let scaled = lebesgue_patch_scaled(&net);
    let image_net: Vec<Vec<Hom4<P>>> = scaled
        .iter()
        .enumerate()
        .map(|(k, row)| {
            row.iter()
                .enumerate()
                .map(|(l, h)| h.scale(&(inv_binom(2, k) * inv_binom(2, l))))
                .collect()
        })
        .collect();
    let image = TensorPatch::try_new(image_net).map_err(|e| e.to_string())?;
    if image.degrees() != (2, 2) {
        return Err("the image of the bilinear patch is not biquadratic".into());
    }
    let bilinear = TensorPatch::try_new(net).map_err(|e| e.to_string())?;
    let direct = lebesgue(&bilinear.eval_hom(&u, &v));
    let at_uv = image.eval_hom(&u, &v);
    res.extend(equal_coordinates(
        "patch: product-rule net vs delta(x(u,v))",
        &at_uv,
        &direct,
    ));
    res.push(("patch: image on K".into(), sphere_form(&at_uv)));
    let mut out = decide(
        &sym,
        &res,
        &[],
        "symbolic expansion over Q[control vectors, t, u, v]",
    );
    if out.verdict == Verdict::Proved {
        out.evidence = format!(
            "for n = 1, 2, 3 the product-rule control points of degree 2n give delta(x(t)) identically and lie on K; the bilinear patch maps to the biquadratic one ({} residuals expanded to 0)",
            res.len()
        );
    }
    Ok(out)
}
