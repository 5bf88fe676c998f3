//! Claims of Juettler's paper on rational curves and surfaces on quadrics (seed 002, SPEC §1).
//!
//! Printed formulas are kept as text exactly as the paper prints them and parsed; the maps of
//! `exactcheck_core::quadric` are the independent derivation they are compared against, and the
//! properties are proved by expanding residuals over polynomial rings.

use super::engine::{prove_all, Rng, Symbols};
use super::juttler_geometry::{circle_preimage, line_image, line_preimage, plane_lines, satz7};
use super::{Claim, Outcome, Verdict};
use exactcheck_core::quadric::{
    alpha, alpha_preimage_point, dietz, lebesgue, paraboloid_form, psi, sigma, sigma_inverse,
    sphere_form, tau, theta, theta_preimage_point,
};
use exactcheck_core::{det4, Hom4, Ring};
use exactcheck_exact::expr::Coefficient;
use exactcheck_exact::poly::Poly;
use exactcheck_exact::{ComplexRadical, Rational};

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
        claim!("juttler.satz5", Proved, "Satz 5: every line (12) meets both focal lines xi (1,0,0,i) + zeta (0,1,-i,0) and xi (1,0,0,-i) + zeta (0,1,i,0) (13); lambda = 1, mu = +-i gives the meeting points", satz5),
        claim!("juttler.focal_absolute", Proved, "the focal lines (13) lie on the absolute quadric x0^2+x1^2+x2^2+x3^2 = 0 (14)", focal_absolute),
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
        claim!("juttler.satz11", Proved, "Satz 11: every line (18) meets both real focal lines (1,lambda,0,0) and (0,0,1,mu)", satz11),
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
fn proportional<C: Ring>(
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

fn decide<C: exactcheck_core::Field + Coefficient + std::fmt::Display>(
    sym: &Symbols,
    residuals: &[(String, Poly<C>)],
    relations: &[Poly<C>],
    method: &str,
) -> Outcome {
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
    res.extend(proportional(
        "sigma^-1(sigma(p)) ~ p",
        &sigma_inverse(&sigma(&p)),
        &p,
    )?);
    // sigma(sigma^-1(k)) ~ k for k on K: modulo k0^2 - k1^2 - k2^2 - k3^2.
    res.extend(proportional(
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
    res.extend(proportional(
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
    let mut res = proportional(
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

fn satz5() -> Result<Outcome, String> {
    type C = Poly<ComplexRadical>;
    let mut sym = Symbols::new(&["p0", "p1", "p2"]);
    let i = C::constant(ComplexRadical::i());
    let (p0, p1, p2) = (
        sym.vars.poly::<ComplexRadical>("p0"),
        sym.vars.poly("p1"),
        sym.vars.poly("p2"),
    );
    let a = Hom4::new(p0.clone(), p1.clone(), p2.clone(), C::zero());
    let b = Hom4::new(C::zero(), p2.clone(), -p1.clone(), p0.clone());
    let (o, z) = (C::one(), C::zero());
    let mut res = Vec::new();
    for (sign, label) in [(i.clone(), "+i"), (-i.clone(), "-i")] {
        // The focal line xi (1,0,0,s) + zeta (0,1,-s,0) with s = +-i.
        let f1 = Hom4::new(o.clone(), z.clone(), z.clone(), sign.clone());
        let f2 = Hom4::new(z.clone(), o.clone(), -sign.clone(), z.clone());
        res.push((
            format!("det(line (12), focal line {label})"),
            det4(&a, &b, &f1, &f2),
        ));
        // The printed meeting point: lambda = 1, mu = s lies on the focal line.
        let x = Hom4::new(
            a.0[0].clone() + sign.clone() * &b.0[0],
            a.0[1].clone() + sign.clone() * &b.0[1],
            a.0[2].clone() + sign.clone() * &b.0[2],
            a.0[3].clone() + sign.clone() * &b.0[3],
        );
        let on = x
            .add(&f1.scale(&p0.neg_ref()))
            .add(&f2.scale(&(p1.clone() + sign.clone() * &p2).neg_ref()));
        for (c, r) in on.0.into_iter().enumerate() {
            res.push((format!("point lambda = 1, mu = {label} minus p0 f1 + (p1 {label} p2) f2, coordinate {c}"), r));
        }
    }
    Ok(decide(
        &sym,
        &res,
        &[],
        "symbolic expansion over Q(i)[p0,p1,p2]",
    ))
}

fn focal_absolute() -> Result<Outcome, String> {
    type C = Poly<ComplexRadical>;
    let mut sym = Symbols::new(&["xi", "zeta"]);
    let i = C::constant(ComplexRadical::i());
    let (xi, zeta) = (
        sym.vars.poly::<ComplexRadical>("xi"),
        sym.vars.poly::<ComplexRadical>("zeta"),
    );
    let mut res = Vec::new();
    for (s, label) in [(i.clone(), "+i"), (-i, "-i")] {
        let x = Hom4::new(xi.clone(), zeta.clone(), -(s.clone() * &zeta), s * &xi);
        res.push((
            format!("x0^2+x1^2+x2^2+x3^2 on the focal line ({label})"),
            x.dot(&x),
        ));
    }
    Ok(decide(
        &sym,
        &res,
        &[],
        "symbolic expansion over Q(i)[xi,zeta]",
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
    res.extend(proportional(
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
    let mut res = proportional(
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

fn satz11() -> Result<Outcome, String> {
    let mut sym = Symbols::new(&["q0", "q1", "q2"]);
    let (q0, q1, q2) = (
        sym.vars.poly::<Rational>("q0"),
        sym.vars.poly("q1"),
        sym.vars.poly("q2"),
    );
    let a = Hom4::new(q0.clone(), q1.clone(), q2, q0.clone());
    let b = Hom4::new(q0, q1, P::zero(), P::zero());
    let e = |i: usize| {
        let mut v = [P::zero(), P::zero(), P::zero(), P::zero()];
        v[i] = P::one();
        Hom4(v)
    };
    let res = vec![
        (
            "det(line (18), focal line (1,lambda,0,0))".to_string(),
            det4(&a, &b, &e(0), &e(1)),
        ),
        (
            "det(line (18), focal line (0,0,1,mu))".to_string(),
            det4(&a, &b, &e(2), &e(3)),
        ),
    ];
    Ok(decide(
        &sym,
        &res,
        &[],
        "symbolic expansion over Q[q0,q1,q2]",
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

// ------------------------------------------------------------------- rational points of K, H

/// A rational point of K by inverse stereographic projection of the rational point `(x, y)` of
/// the plane: `(1 + x^2 + y^2, 2x, 2y, x^2 + y^2 - 1)` (on K identically; `k0 > 0`, `k0 != k3`).
fn stereographic_point(x: &Rational, y: &Rational) -> Hom4<Rational> {
    let s = x.square() + y.square();
    Hom4::new(
        Rational::ONE + &s,
        x.clone() + x,
        y.clone() + y,
        s - Rational::ONE,
    )
}

/// A Pythagorean quadruple `k1^2 + k2^2 + k3^2 = k0^2` found by search over random integer
/// triples in `-r..=r` (the square root is taken exactly); `None` after `tries` misses.
fn pythagorean_point(rng: &mut Rng, r: i64, tries: usize) -> Option<Hom4<Rational>> {
    for _ in 0..tries {
        let k = [rng.int(-r, r), rng.int(-r, r), rng.int(-r, r)];
        let s: i64 = k.iter().map(|x| x * x).sum();
        if s == 0 {
            continue;
        }
        // Exact integer square root (s <= 3 r^2 is small): the f64 estimate, corrected.
        let mut k0 = (s as f64).sqrt() as i64;
        while k0 * k0 > s {
            k0 -= 1;
        }
        while (k0 + 1) * (k0 + 1) <= s {
            k0 += 1;
        }
        if k0 * k0 == s {
            let q = Rational::from_integer;
            return Some(Hom4::new(q(k0), q(k[0]), q(k[1]), q(k[2])));
        }
    }
    None
}

/// Where the rational points of K of the converse check come from.
struct SpherePoints {
    points: Vec<Hom4<Rational>>,
    stereographic: usize,
    pythagorean: usize,
    special: usize,
}

/// Rational points of K drawn without delta: inverse stereographic images of random rationals,
/// Pythagorean quadruples found by search, and the special points — the centre `z = (1,0,0,1)`
/// (preimage line `x0 = x3 = 0`) and points with `k1 = k2 = 0` (`k0 = +-k3`).
fn sphere_points(rng: &mut Rng, count: usize) -> SpherePoints {
    let mut points = vec![
        Hom4::new(Rational::ONE, Rational::ZERO, Rational::ZERO, Rational::ONE),
        Hom4::new(
            Rational::ONE,
            Rational::ZERO,
            Rational::ZERO,
            -Rational::ONE,
        ),
    ];
    let special = points.len();
    let (mut stereographic, mut pythagorean) = (0, 0);
    while stereographic + pythagorean < count {
        if (stereographic + pythagorean) % 2 == 0 {
            let (x, y) = (rng.rational(9, 7), rng.rational(9, 7));
            points.push(stereographic_point(&x, &y));
            stereographic += 1;
        } else if let Some(k) = pythagorean_point(rng, 30, 1000) {
            points.push(k);
            pythagorean += 1;
        }
    }
    SpherePoints {
        points,
        stereographic,
        pythagorean,
        special,
    }
}

/// A delta-preimage of the point `k` of K: a point `p` of its projecting line (12) (through
/// `sigma^-1(k)`, Lemma 4; the line `x0 = x3 = 0` for the centre) with `delta(p) ~ k`, checked
/// exactly. `Err` when `k` is not on K or no point of the line tried maps to `k`.
fn delta_preimage(k: &Hom4<Rational>, rng: &mut Rng) -> Result<Hom4<Rational>, String> {
    if k.is_zero() || !sphere_form(k).is_zero() {
        return Err(format!("{k:?} is not a point of K"));
    }
    let line = exactcheck_core::sphere_interpolation::preimage_line(k);
    for _ in 0..20 {
        let (l, m) = (rng.rational(5, 3), rng.rational(5, 3));
        let p = line[0].scale(&l).add(&line[1].scale(&m));
        let image = lebesgue(&p);
        if !p.is_zero() && !image.is_zero() && image.proj_eq(k) {
            return Ok(p);
        }
    }
    Err(format!(
        "no point of the projecting line of {k:?} maps to it"
    ))
}

/// A psi-preimage of the point `h` of H from (8): `[[h0, h2], [h1, h3]] = (q0, q1)^T (q3, q2)`
/// has rank 1, so `(q0, q1)` is a non-zero column and `(q3, q2)` a non-zero row; checked exactly.
fn psi_preimage(h: &Hom4<Rational>) -> Result<Hom4<Rational>, String> {
    if h.is_zero() || !paraboloid_form(h).is_zero() {
        return Err(format!("{h:?} is not a point of H"));
    }
    let [h0, h1, h2, h3] = &h.0;
    let (q0, q1) = if h0.is_zero() && h1.is_zero() {
        (h2.clone(), h3.clone())
    } else {
        (h0.clone(), h1.clone())
    };
    let (q3, q2) = if h0.is_zero() && h2.is_zero() {
        (h1.clone(), h3.clone())
    } else {
        (h0.clone(), h2.clone())
    };
    let q = Hom4::new(q0, q1, q2, q3);
    let image = psi(&q);
    if image.is_zero() || !image.proj_eq(h) {
        return Err(format!("psi({q:?}) is not {h:?}"));
    }
    Ok(q)
}

/// Points of H drawn without psi: `h3 = h1 h2 / h0` for random rationals `h0 != 0`, `h1`, `h2`,
/// and the points with `h0 = 0` (then `h1 h2 = 0`: `(0, h1, 0, h3)` and `(0, 0, h2, h3)`).
fn paraboloid_points(rng: &mut Rng, count: usize) -> (Vec<Hom4<Rational>>, usize) {
    let mut points = Vec::new();
    for _ in 0..count {
        let (h0, h1, h2) = (rng.nonzero(9, 7), rng.rational(9, 7), rng.rational(9, 7));
        let h3 = (h1.clone() * &h2)
            .checked_div(&h0)
            .expect("h0 is drawn non-zero");
        points.push(Hom4::new(h0, h1, h2, h3));
    }
    let at_infinity = count / 10;
    for i in 0..at_infinity {
        let (a, b) = (rng.nonzero(9, 7), rng.rational(9, 7));
        points.push(if i % 2 == 0 {
            Hom4::new(Rational::ZERO, a, Rational::ZERO, b)
        } else {
            Hom4::new(Rational::ZERO, Rational::ZERO, a, b)
        });
    }
    (points, at_infinity)
}

const CONVERSE_POINTS: usize = 200;

/// The converse of (7): every rational point of K — drawn independently of delta — has a
/// delta-preimage, found on its projecting line and checked exactly.
pub(super) fn converse_k() -> Result<String, String> {
    let mut rng = Rng::new(0xC0);
    let pts = sphere_points(&mut rng, CONVERSE_POINTS);
    for k in &pts.points {
        delta_preimage(k, &mut rng)?;
    }
    Ok(format!(
        "converse: all {} rational points of K drawn without delta ({} inverse stereographic images of random rationals, {} Pythagorean quadruples found by search, {} special: z = (1,0,0,1) and (1,0,0,-1)) have a delta-preimage on their projecting line (12), checked exactly",
        pts.points.len(),
        pts.stereographic,
        pts.pythagorean,
        pts.special
    ))
}

/// The converse of (8): every rational point of H — drawn independently of psi — has a
/// psi-preimage (from (8)), checked exactly; for `h0 != 0` also every point of its line (18).
pub(super) fn converse_h() -> Result<String, String> {
    let mut rng = Rng::new(0xC1);
    let (points, at_infinity) = paraboloid_points(&mut rng, CONVERSE_POINTS);
    let mut on_line = 0;
    for h in &points {
        psi_preimage(h)?;
        if !h.0[0].is_zero() {
            let q = Hom4::new(
                h.0[0].clone(),
                h.0[1].clone(),
                h.0[2].clone(),
                h.0[0].clone(),
            );
            let (l, m) = (rng.nonzero(5, 3), rng.rational(5, 3));
            let p = alpha_preimage_point(&q, &l, &m);
            if !p.is_zero() && !psi(&p).is_zero() {
                if !psi(&p).proj_eq(h) {
                    return Err(format!(
                        "a point of the line (18) of {h:?} does not map to it"
                    ));
                }
                on_line += 1;
            }
        }
    }
    Ok(format!(
        "converse: all {} rational points of H drawn without psi (h3 = h1 h2 / h0 for random rationals, {at_infinity} with h0 = 0) have a psi-preimage read off (8), checked exactly; {on_line} random points of the lines (18) map onto their point",
        points.len()
    ))
}

// ----------------------------------------------------------------------------- interpolation

/// The numbers of points `N` and the point sets per `N` of the interpolation claims.
const INTERPOLATION_N: core::ops::RangeInclusive<usize> = 2..=8;
const INTERPOLATION_SETS: usize = 4;

/// One interpolation instance: the degrees each construction needs.
#[derive(Clone, Debug, PartialEq)]
struct DegreeRow {
    /// The number of points.
    n: usize,
    /// The image degree 2n of the delta-construction (least preimage degree n that works).
    delta: usize,
    /// The least image degree of a rational plane curve mapped by sigma, by the same linear
    /// method (`sphere_interpolation::sigma_degree`).
    sigma_rational: Option<usize>,
    /// The image degree 2m of plain stereographic projection: the least-degree polynomial
    /// interpolant of the points `sigma^-1(k_j)` of the plane, mapped by sigma.
    sigma_polynomial: usize,
}

/// The image degree of plain stereographic projection: the least `m` for which a polynomial
/// curve `(x(t), y(t))` of degree `m` passes through the affine points `sigma^-1(k_j)` at the
/// parameters `t_j` (Vandermonde systems solved exactly), and `2m`, the degree of its sigma-image
/// `(1 + x^2 + y^2, 2x, 2y, x^2 + y^2 - 1)`: exactly 2m, since by minimality the leading
/// coefficients `(a_m, b_m)` are not both zero (checked), so `1 + x^2 + y^2` has the leading
/// coefficient `a_m^2 + b_m^2 > 0`, and the coordinates have no common root (`x = y = 0` makes
/// the first one 1). The image is checked to pass through every `k_j`.
fn plain_sigma_degree(points: &[Hom4<Rational>], params: &[Rational]) -> Result<usize, String> {
    use exactcheck_core::linalg::Matrix;
    let mut xs = Vec::new();
    let mut ys = Vec::new();
    for k in points {
        let p = sigma_inverse(k);
        let (x, y) = (p.0[1].checked_div(&p.0[0]), p.0[2].checked_div(&p.0[0]));
        let (Ok(x), Ok(y)) = (x, y) else {
            return Err(format!(
                "{k:?} is the centre's fibre (sigma^-1 at infinity)"
            ));
        };
        xs.push(x);
        ys.push(y);
    }
    let eval =
        |c: &[Rational], t: &Rational| c.iter().rev().fold(Rational::ZERO, |acc, a| acc * t + a);
    for m in 0..points.len() {
        let v = Matrix::from_rows(
            params
                .iter()
                .map(|t| (0..=m).map(|i| t.pow(i as u32)).collect())
                .collect(),
        )
        .map_err(|e| e.to_string())?;
        let (Some(cx), Some(cy)) = (
            v.solve(&xs).map_err(|e| e.to_string())?,
            v.solve(&ys).map_err(|e| e.to_string())?,
        ) else {
            continue;
        };
        if m > 0 && cx[m].is_zero() && cy[m].is_zero() {
            return Err(format!("degree {m} solution of lower degree (not minimal)"));
        }
        for (k, t) in points.iter().zip(params) {
            let image = sigma(&Hom4::new(
                Rational::ONE,
                eval(&cx, t),
                eval(&cy, t),
                Rational::ZERO,
            ));
            if !image.proj_eq(k) {
                return Err(format!(
                    "the plane interpolant's image misses {k:?} at t = {t}"
                ));
            }
        }
        return Ok(2 * m);
    }
    Err("no polynomial interpolant below degree N (parameters not distinct?)".into())
}

/// Runs the interpolation instances: for each `N` several point sets of K (inverse
/// stereographic images of random rationals, so `k0 != k3`) at random distinct parameters.
/// `Ok(Err(evidence))` when a curve misses a point or leaves K.
fn interpolation_rows() -> Result<Result<Vec<DegreeRow>, String>, String> {
    use exactcheck_core::sphere_interpolation::interpolate;
    let mut rng = Rng::new(0x1A7E);
    let mut rows = Vec::new();
    for n in INTERPOLATION_N {
        for _ in 0..INTERPOLATION_SETS {
            let points: Vec<Hom4<Rational>> = (0..n)
                .map(|_| stereographic_point(&rng.rational(9, 7), &rng.rational(9, 7)))
                .collect();
            let mut params: Vec<Rational> = Vec::new();
            while params.len() < n {
                let t = Rational::new(rng.int(-50, 50), 50).expect("50 is a non-zero denominator");
                if !params.contains(&t) {
                    params.push(t);
                }
            }
            let r = interpolate(&points, &params).map_err(|e| format!("{n} points: {e}"))?;
            for (k, t) in points.iter().zip(&params) {
                if !r.curve.eval_hom(t).proj_eq(k) {
                    return Ok(Err(format!(
                        "the curve for {n} points misses {k:?} at t = {t}"
                    )));
                }
            }
            let c = r.curve.hom_coordinates();
            let form = c[0]
                .mul(&c[0])
                .checked_sub(&c[1].mul(&c[1]))
                .and_then(|f| f.checked_sub(&c[2].mul(&c[2])))
                .and_then(|f| f.checked_sub(&c[3].mul(&c[3])))
                .map_err(|e| e.to_string())?;
            if form.coeffs().iter().any(|x| !x.is_zero()) {
                return Ok(Err(format!("the curve for {n} points leaves K")));
            }
            rows.push(DegreeRow {
                n,
                delta: r.degree,
                sigma_rational: r.sigma_degree,
                sigma_polynomial: plain_sigma_degree(&points, &params)?,
            });
        }
    }
    Ok(Ok(rows))
}

/// `2` or `2..4`: the values of a column over the instances of one N.
fn span_text(values: impl Iterator<Item = usize>) -> String {
    let v: Vec<usize> = values.collect();
    match (v.iter().min(), v.iter().max()) {
        (Some(a), Some(b)) if a == b => a.to_string(),
        (Some(a), Some(b)) => format!("{a}..{b}"),
        _ => "none".into(),
    }
}

/// `juttler.interpolation`: interpolation on K is a homogeneous linear problem and works: on
/// every instance the nullspace gives a curve through every point at its parameter that lies on
/// K identically (exact).
pub(super) fn interpolation() -> Result<Outcome, String> {
    const METHOD: &str = "exact linear algebra over Q (nullspace), exact checks";
    let rows = match interpolation_rows()? {
        Ok(r) => r,
        Err(evidence) => {
            return Ok(Outcome {
                verdict: Verdict::Fails,
                method: METHOD.into(),
                evidence,
            })
        }
    };
    let degrees: Vec<String> = INTERPOLATION_N
        .map(|n| {
            format!(
                "N={n}: {}",
                span_text(rows.iter().filter(|r| r.n == n).map(|r| r.delta))
            )
        })
        .collect();
    Ok(Outcome {
        verdict: Verdict::Holds,
        method: METHOD.into(),
        evidence: format!(
            "{} random instances ({} point sets of K for each N = {}..{}, random distinct parameters): each curve from the nullspace passes through every point at its parameter and lies on K identically; image degrees found: {}",
            rows.len(),
            INTERPOLATION_SETS,
            INTERPOLATION_N.start(),
            INTERPOLATION_N.end(),
            degrees.join(", ")
        ),
    })
}

/// The verdict on "fewer degrees than plain stereographic projection" from the computed rows:
/// it holds for N when the delta-construction's degree is below plain stereographic
/// projection's on every instance with N points; the printed statement (no restriction on N)
/// fails if some N has an instance where it is not. The comparison with the rational plane
/// curves (sigma of the same linear method) is reported alongside.
fn degree_verdict(rows: &[DegreeRow]) -> Outcome {
    let ns: Vec<usize> = {
        let mut v: Vec<usize> = rows.iter().map(|r| r.n).collect();
        v.dedup();
        v
    };
    let fewer = |n: usize, other: &dyn Fn(&DegreeRow) -> Option<usize>| {
        rows.iter()
            .filter(|r| r.n == n)
            .all(|r| other(r).is_some_and(|o| r.delta < o))
    };
    let plain = |r: &DegreeRow| Some(r.sigma_polynomial);
    let rational = |r: &DegreeRow| r.sigma_rational;
    let list = |f: &dyn Fn(usize) -> bool| {
        let v: Vec<String> = ns
            .iter()
            .filter(|&&n| f(n))
            .map(|n| n.to_string())
            .collect();
        if v.is_empty() {
            "none".to_string()
        } else {
            v.join(", ")
        }
    };
    let table: Vec<String> = ns
        .iter()
        .map(|&n| {
            let of = |f: &dyn Fn(&DegreeRow) -> Option<usize>| {
                span_text(rows.iter().filter(|r| r.n == n).filter_map(f))
            };
            format!(
                "N={n}: delta {}, plain sigma {}, rational sigma {}",
                of(&|r| Some(r.delta)),
                of(&plain),
                of(&rational)
            )
        })
        .collect();
    let counter = rows.iter().find(|r| r.delta >= r.sigma_polynomial);
    let summary = format!(
        "image degrees computed on {} instances: {}. Fewer than plain stereographic projection (polynomial interpolant in the plane, mapped by sigma) for N in {{{}}}; fewer than rational plane curves mapped by sigma (same linear method) for N in {{{}}}",
        rows.len(),
        table.join("; "),
        list(&|n| fewer(n, &plain)),
        list(&|n| fewer(n, &rational)),
    );
    match counter {
        Some(r) => Outcome {
            verdict: Verdict::Fails,
            method: "exact interpolation by both constructions, degrees compared".into(),
            evidence: format!(
                "counter-example: N = {} points, the delta-construction needs image degree {} and plain stereographic projection {} (not fewer). {summary}. Corrected claim: fewer degrees than plain stereographic projection only for the N listed first",
                r.n, r.delta, r.sigma_polynomial
            ),
        },
        None => Outcome {
            verdict: Verdict::Holds,
            method: "exact interpolation by both constructions, degrees compared".into(),
            evidence: summary,
        },
    }
}

/// `juttler.interpolation_degree`: the delta-construction needs fewer degrees than plain
/// stereographic projection — decided per N from computed degrees ([`degree_verdict`]).
pub(super) fn interpolation_degree() -> Result<Outcome, String> {
    match interpolation_rows()? {
        Ok(rows) => Ok(degree_verdict(&rows)),
        Err(evidence) => Err(format!("an interpolation instance failed: {evidence}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_points_are_drawn_without_delta_and_include_special_points() {
        let mut rng = Rng::new(7);
        let pts = sphere_points(&mut rng, 40);
        assert_eq!(pts.points.len(), 42);
        assert!(pts.stereographic > 0 && pts.pythagorean > 0 && pts.special == 2);
        for k in &pts.points {
            assert!(sphere_form(k).is_zero() && !k.is_zero());
            let p = delta_preimage(k, &mut rng).expect("every point of K has a preimage");
            assert!(lebesgue(&p).proj_eq(k));
        }
        // The centre's fibre is the line x0 = x3 = 0.
        let z = &pts.points[0];
        let p = delta_preimage(z, &mut rng).unwrap();
        assert!(p.0[0].is_zero() && p.0[3].is_zero());
        // A point off K is refused, not "inverted".
        let off = Hom4::new(Rational::ONE, Rational::ONE, Rational::ONE, Rational::ONE);
        assert!(delta_preimage(&off, &mut rng).is_err());
    }

    #[test]
    fn pythagorean_search_is_exact() {
        let mut rng = Rng::new(3);
        for _ in 0..20 {
            let k = pythagorean_point(&mut rng, 30, 1000).expect("found");
            assert!(sphere_form(&k).is_zero());
            assert!(k.0[0] > Rational::ZERO);
        }
    }

    #[test]
    fn points_of_h_with_h0_zero_have_preimages() {
        // The old check skipped h0 = 0; (8) gives preimages there too.
        let q = Rational::from_integer;
        for h in [
            Hom4::new(q(0), q(3), q(0), q(5)),
            Hom4::new(q(0), q(0), q(2), q(-7)),
            Hom4::new(q(0), q(0), q(0), q(1)),
            Hom4::new(q(2), q(3), q(4), q(6)),
        ] {
            let p = psi_preimage(&h).expect("a preimage");
            assert!(psi(&p).proj_eq(&h));
        }
        assert!(psi_preimage(&Hom4::new(q(1), q(1), q(1), q(2))).is_err());
        let mut rng = Rng::new(5);
        let (pts, inf) = paraboloid_points(&mut rng, 50);
        assert_eq!((pts.len(), inf), (55, 5));
        assert!(pts.iter().all(|h| paraboloid_form(h).is_zero()));
    }

    #[test]
    fn plain_sigma_needs_degree_two_n_minus_two() {
        let q = |n: i64, d: i64| Rational::new(n, d).unwrap();
        let pts: Vec<Hom4<Rational>> = [(1, 2), (3, -1), (0, 5), (-2, 1)]
            .iter()
            .map(|&(x, y)| stereographic_point(&q(x, 3), &q(y, 2)))
            .collect();
        let ts = [q(0, 1), q(1, 3), q(2, 3), q(1, 1)];
        for n in 1..=4 {
            assert_eq!(
                plain_sigma_degree(&pts[..n], &ts[..n]).unwrap(),
                2 * (n - 1)
            );
        }
        // Collinear, equally spaced points: a line (degree 1) suffices, image degree 2.
        let line: Vec<Hom4<Rational>> = (0..4)
            .map(|i| stereographic_point(&q(i, 1), &q(2 * i, 1)))
            .collect();
        assert_eq!(plain_sigma_degree(&line, &ts).unwrap(), 2);
    }

    #[test]
    fn the_degree_claim_is_decided_by_the_comparison() {
        let row = |n, delta, rat, poly| DegreeRow {
            n,
            delta,
            sigma_rational: Some(rat),
            sigma_polynomial: poly,
        };
        // Old behaviour: "holds" although N = 2 and N = 4 print equal degrees.
        let o = degree_verdict(&[row(2, 2, 2, 2), row(3, 2, 4, 4), row(4, 4, 4, 6)]);
        assert_eq!(o.verdict, Verdict::Fails);
        assert!(o.evidence.contains("N = 2 points"), "{}", o.evidence);
        assert!(o.evidence.contains("plain stereographic projection (polynomial interpolant in the plane, mapped by sigma) for N in {3, 4}"), "{}", o.evidence);
        assert!(
            o.evidence.contains("same linear method) for N in {3}"),
            "{}",
            o.evidence
        );
        let o = degree_verdict(&[row(3, 2, 4, 4), row(5, 4, 6, 8)]);
        assert_eq!(o.verdict, Verdict::Holds);
    }

    #[test]
    fn interpolation_degrees_are_computed() {
        let rows = interpolation_rows().unwrap().unwrap();
        assert_eq!(rows.len(), INTERPOLATION_N.count() * INTERPOLATION_SETS);
        for r in &rows {
            // Random points in general position: the polynomial interpolant has degree N - 1.
            assert_eq!(r.sigma_polynomial, 2 * (r.n - 1), "{r:?}");
            // The delta-construction solves 2N conditions with 4(n+1) - 1 projective unknowns.
            assert_eq!(r.delta, 2 * ((2 * r.n + 1).div_ceil(4) - 1), "{r:?}");
        }
        let o = interpolation_degree().unwrap();
        assert_eq!(o.verdict, Verdict::Fails, "{}", o.evidence);
    }
}
