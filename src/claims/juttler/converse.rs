//! The converses of (7) and (8): every rational point of K (of H) has a preimage under delta
//! (psi). The points are drawn *independently* of the maps — inverse stereographic images of
//! random rationals and Pythagorean quadruples found by search on K; `h3 = h1 h2 / h0` and the
//! points with `h0 = 0` on H — so the check is not circular; the preimages are constructed
//! (K: on the projecting line (12) through `sigma^-1(k)`, Lemma 4; H: read off (8), whose
//! matrix `[[h0, h2], [h1, h3]] = (q0, q1)^T (q3, q2)` has rank 1) and verified exactly.

use super::*;

/// A rational point of K by inverse stereographic projection of the rational point `(x, y)` of
/// the plane: `(1 + x^2 + y^2, 2x, 2y, x^2 + y^2 - 1)` (on K identically; `k0 > 0`, `k0 != k3`).
pub(super) fn stereographic_point(x: &Rational, y: &Rational) -> Hom4<Rational> {
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
}
