//! `juttler.plane_lines`: every plane contains exactly one projecting line, and its lines map
//! to the circles through one point (the mathematics is in the doc of [`plane_lines`]).

use super::*;

const PLANES: usize = 200;
const LINES_PER_PLANE: usize = 5;
const SPECIAL_PLANES: usize = 20;

/// `juttler.plane_lines`: every plane contains exactly one projecting line, and the lines of
/// the plane map to the circles through one fixed point, the image of that projecting line.
///
/// The line (12) of `p = (p0, p1, p2)` lies in `u . x = 0` iff `u . A(p) = u . B(p) = 0`, two
/// linear equations in `p` with rows `(u0, u1, u2)`, `(u3, -u2, u1)`. Symbolically over `Q[u]`
/// their cross product `p(u)` solves them and has `p0(u) = u1^2 + u2^2`: rank 2 (one line)
/// unless `u1 = u2 = 0`; then (the planes `u0 x0 + u3 x3 = 0`, horizontal planes and the plane
/// at infinity) every solution has `p0 = 0` and gives the one line `x0 = x3 = 0`. A line `XY`
/// of a plane through the projecting line meets it in `Z = gamma' X - gamma Y`, and
/// `delta(Z) ~ sigma(p)` symbolically; on random planes and lines the image circle's plane
/// contains `sigma(p)`.
///
/// # Errors
/// When a symbolic computation cannot be set up.
pub fn plane_lines() -> Result<Outcome, String> {
    run(plane_lines_inner)
}

fn plane_lines_inner() -> Result<Outcome, Stop> {
    const METHOD: &str = "symbolic expansion over Q[u] + exact instances";
    let mut sym = Symbols::new(&[
        "u0", "u1", "u2", "u3", "p0", "p1", "p2", "W0", "W1", "W2", "W3", "alpha", "beta", "gamma",
        "alpha2", "beta2", "gamma2",
    ]);
    let u = sym.hom4_vars::<Rational>("u");
    let pv: Vec<Var> = (0..3).map(|i| sym.vars.var(&format!("p{i}"))).collect();
    let pp = Hom4::new(
        sym.vars.poly::<Rational>("p0"),
        sym.vars.poly("p1"),
        sym.vars.poly("p2"),
        P::zero(),
    );
    let ea = u.dot(&theta_preimage_point(&pp, &P::one(), &P::zero()));
    let eb = u.dot(&theta_preimage_point(&pp, &P::zero(), &P::one()));
    // The coefficient rows of the two linear equations in p, read off by substitution.
    let coeffs = |e: &P| -> Vec<P> {
        (0..3)
            .map(|i| {
                at(
                    e,
                    &pv,
                    &(0..3).map(|k| i64::from(k == i)).collect::<Vec<_>>(),
                )
            })
            .collect()
    };
    let (r1, r2) = (coeffs(&ea), coeffs(&eb));
    let cross = [
        r1[1].mul_ref(&r2[2]) - r1[2].mul_ref(&r2[1]),
        r1[2].mul_ref(&r2[0]) - r1[0].mul_ref(&r2[2]),
        r1[0].mul_ref(&r2[1]) - r1[1].mul_ref(&r2[0]),
    ];
    let p_of_u = Hom4::new(
        cross[0].clone(),
        cross[1].clone(),
        cross[2].clone(),
        P::zero(),
    );
    let mut res = vec![
        (
            "u . A(p) - (row 1) . p".to_string(),
            ea.clone()
                - (0..3)
                    .map(|i| r1[i].mul_ref(&pp.0[i]))
                    .fold(P::zero(), |s, t| s + t),
        ),
        (
            "u . B(p) - (row 2) . p".to_string(),
            eb.clone()
                - (0..3)
                    .map(|i| r2[i].mul_ref(&pp.0[i]))
                    .fold(P::zero(), |s, t| s + t),
        ),
        (
            "u . A(p(u))".to_string(),
            u.dot(&theta_preimage_point(&p_of_u, &P::one(), &P::zero())),
        ),
        (
            "u . B(p(u))".to_string(),
            u.dot(&theta_preimage_point(&p_of_u, &P::zero(), &P::one())),
        ),
    ];
    // Lines of a plane through the projecting line g of p: X, Y = combinations of A, B, W.
    let w = sym.hom4_vars::<Rational>("W");
    let (a_pt, b_pt) = (
        theta_preimage_point(&pp, &P::one(), &P::zero()),
        theta_preimage_point(&pp, &P::zero(), &P::one()),
    );
    let comb = |x: &P, y: &P, z: &P| a_pt.scale(x).add(&b_pt.scale(y)).add(&w.scale(z));
    let (al, be, ga) = (
        sym.vars.poly::<Rational>("alpha"),
        sym.vars.poly::<Rational>("beta"),
        sym.vars.poly::<Rational>("gamma"),
    );
    let (al2, be2, ga2) = (
        sym.vars.poly::<Rational>("alpha2"),
        sym.vars.poly::<Rational>("beta2"),
        sym.vars.poly::<Rational>("gamma2"),
    );
    let xx = comb(&al, &be, &ga);
    let yy = comb(&al2, &be2, &ga2);
    let z = xx.scale(&ga2).add(&yy.scale(&-ga.clone()));
    for (i, mnr) in lebesgue(&z).minors(&sigma(&pp)).into_iter().enumerate() {
        res.push((
            format!("delta(gamma2 X - gamma Y) ~ sigma(p): minor {i}"),
            mnr,
        ));
    }
    res.push((
        "det4(A, B, gamma2 X - gamma Y, W) (Z lies on the projecting line)".into(),
        det4(&a_pt, &b_pt, &z, &w),
    ));
    let proved = prove(&sym, &res, &[], METHOD)?;
    let (u1v, u2v) = (sym.vars.var("u1"), sym.vars.var("u2"));
    let p0_ok = matches!(
        definite_sign(&cross[0]),
        Some((Sign::Positive, ref v)) if v.iter().all(|&x| x == u1v || x == u2v)
    );
    // Exceptional planes u1 = u2 = 0: the p1, p2 columns of both rows vanish.
    let special: Vec<P> = [&r1[1], &r1[2], &r2[1], &r2[2]]
        .iter()
        .map(|c| at(c, &[u1v, u2v], &[0, 0]))
        .collect();
    let special_ok = special.iter().all(P::is_zero);
    if !p0_ok || !special_ok {
        return Err(fails(
            METHOD,
            format!(
                "p0(u) = {} is not positive off u1 = u2 = 0, or the exceptional rows do not reduce to the p0 column",
                cross[0].display(&sym.vars)
            ),
        ));
    }

    // Exact instances.
    let mut rng = Rng::new(0x0091_A4E5);
    let mut lines_checked = 0;
    let mut skipped = 0;
    let mut planes_done = 0;
    while planes_done < PLANES {
        let uu = rng.hom4(9);
        if uu.0[1].is_zero() && uu.0[2].is_zero() {
            skipped += 1;
            continue;
        }
        let eqs = matrix(vec![
            vec![uu.0[0].clone(), uu.0[1].clone(), uu.0[2].clone()],
            vec![uu.0[3].clone(), -uu.0[2].clone(), uu.0[1].clone()],
        ])?;
        let ns = eqs.nullspace();
        if ns.len() != 1 {
            return Err(fails(
                METHOD,
                format!(
                    "plane u = {}: {} projecting lines (nullspace dimension {})",
                    fmt_hom(&uu),
                    ns.len(),
                    ns.len()
                ),
            ));
        }
        let p = Hom4::new(
            ns[0][0].clone(),
            ns[0][1].clone(),
            ns[0][2].clone(),
            Q::ZERO,
        );
        let (ga, gb) = (
            theta_preimage_point(&p, &Q::ONE, &Q::ZERO),
            theta_preimage_point(&p, &Q::ZERO, &Q::ONE),
        );
        let s = sigma(&p);
        if !uu.dot(&ga).is_zero() || !uu.dot(&gb).is_zero() || p.0[0].is_zero() {
            return Err(fails(
                METHOD,
                format!(
                    "plane u = {}: the line (12) of p = {} is not in it",
                    fmt_hom(&uu),
                    fmt_hom(&p)
                ),
            ));
        }
        let in_plane = orthogonal(std::slice::from_ref(&uu))?;
        let mut done = 0;
        let mut tries = 0;
        while done < LINES_PER_PLANE && tries < 10 * LINES_PER_PLANE {
            tries += 1;
            let pick = |rng: &mut Rng| {
                let mut v = Hom4::new(Q::ZERO, Q::ZERO, Q::ZERO, Q::ZERO);
                for basis in &in_plane {
                    v = v.add(&basis.scale(&Q::from_integer(rng.int(-5, 5))));
                }
                v
            };
            let (x, y) = (pick(&mut rng), pick(&mut rng));
            if rank(&[x.clone(), y.clone()])? < 2 {
                continue;
            }
            let (c, on_k) = image_controls(&x, &y)?;
            if rank(&c)? < 3 {
                // The projecting line itself (or a draw on it): not a circle.
                continue;
            }
            let n = orthogonal(&c)?;
            // The meeting point Z of XY with the projecting line: (lambda, mu, -alpha, -beta)
            // in the nullspace of the columns X, Y, A, B.
            let cols = matrix(
                (0..4)
                    .map(|i| {
                        vec![
                            x.0[i].clone(),
                            y.0[i].clone(),
                            ga.0[i].clone(),
                            gb.0[i].clone(),
                        ]
                    })
                    .collect(),
            )?;
            let meet = cols.nullspace();
            let z_ok = meet.len() == 1 && {
                let z = x.scale(&meet[0][0]).add(&y.scale(&meet[0][1]));
                !z.is_zero() && lebesgue(&z).proj_eq(&s)
            };
            if !(on_k && n.len() == 1 && n[0].dot(&s).is_zero() && z_ok) {
                return Err(fails(
                    METHOD,
                    format!(
                        "plane u = {}, line through {} and {}: its image circle does not pass through sigma(p) = {}",
                        fmt_hom(&uu),
                        fmt_hom(&x),
                        fmt_hom(&y),
                        fmt_hom(&s)
                    ),
                ));
            }
            done += 1;
            lines_checked += 1;
        }
        planes_done += 1;
    }
    // The exceptional planes u0 x0 + u3 x3 = 0.
    for _ in 0..SPECIAL_PLANES {
        let (u0, u3) = loop {
            let t = (rng.int(-9, 9), rng.int(-9, 9));
            if t != (0, 0) {
                break t;
            }
        };
        let eqs = matrix(vec![vec![q(u0), q(0), q(0)], vec![q(u3), q(0), q(0)]])?;
        let ns = eqs.nullspace();
        let mut pts = Vec::new();
        for v in &ns {
            let p = Hom4::new(v[0].clone(), v[1].clone(), v[2].clone(), Q::ZERO);
            pts.push(theta_preimage_point(&p, &Q::ONE, &Q::ZERO));
            pts.push(theta_preimage_point(&p, &Q::ZERO, &Q::ONE));
        }
        let on_axis = pts.iter().all(|x| x.0[0].is_zero() && x.0[3].is_zero());
        if ns.len() != 2 || !on_axis || rank(&pts)? != 2 {
            return Err(fails(
                METHOD,
                format!(
                    "plane {u0} x0 + {u3} x3 = 0: the solutions p do not all give the line x0 = x3 = 0"
                ),
            ));
        }
    }
    Ok(Outcome {
        verdict: Verdict::Proved,
        method: format!(
            "symbolic expansion over Q[u,p,W,...] + exact instances ({PLANES} planes, {lines_checked} lines)"
        ),
        evidence: format!(
            "the line (12) of p lies in u.x = 0 iff (u0,u1,u2).p = 0 and (u3,-u2,u1).p = 0; their cross product p(u) = ({}, {}, {}) solves both, and p0(u) = {} > 0 unless u1 = u2 = 0: rank 2, exactly one projecting line (distinct p with p0 != 0 give distinct lines, theta maps each back to p; the member p0 = 0 of (12), the line x0 = x3 = 0 through e1, e2, lies in the plane only if u1 = u2 = 0). Exception u1 = u2 = 0 (planes u0 x0 + u3 x3 = 0: z = const and the plane at infinity): every solution has p0 = 0 and gives the same line x0 = x3 = 0 (the member p0 = 0 of (12), on which theta is undefined), so still exactly one. For a line XY of a plane through the projecting line g of p (X, Y = alpha A + beta B + gamma W), Z = gamma' X - gamma Y lies on g and delta(Z) ~ sigma(p): every image circle passes through sigma(p) = delta(g) ({proved} identities expanded to 0). Exact: {PLANES} random planes have a 1-dimensional solution space with p0 != 0 ({skipped} exceptional draws redrawn); {lines_checked} random non-projecting lines in them have image circles whose plane contains sigma(p), met at delta(XY ∩ g); {SPECIAL_PLANES} random exceptional planes give only x0 = x3 = 0",
            p_of_u.0[0].display(&sym.vars),
            p_of_u.0[1].display(&sym.vars),
            p_of_u.0[2].display(&sym.vars),
            cross[0].display(&sym.vars)
        ), erratum: None, })
}
