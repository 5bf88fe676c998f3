//! `solve ph_offset` on random PH curves, checked independently of `core::ph` where possible:
//! the answer's exact strings are parsed back, the hodograph is recomputed from `u`, `v` of the
//! problem (as rational polynomials) and from the answered control points (differences), and at
//! many rational parameters every offset point is at distance exactly `|r|` from the base point,
//! along the normal (dot product with the tangent zero), on the left for `r > 0`
//! (`B' x (C - B) = r sigma`), in the plane `z = r`. The weights are sigma degree-elevated; each
//! cusp interval holds exactly one zero of `sigma^2 - 2 r w` (Sturm count) and there are no
//! others; the smallest radius is exact and proved (`is_min_radius`, and no sampled radius is
//! smaller) or its enclosure brackets the appearance of cusps. Degenerate input gets a named
//! outcome or a one-line refusal (exit 2), never a panic.

use crate::common;

use common::{bernstein_upoly as upoly, binom, refused, solve_stdin};
use exactcheck::solve::{solve, Mode};
use exactcheck_core::ph::{PhCurve, Side};
use exactcheck_core::{Bernstein, OrderedField, Ring, Rng, Sign, Vec3};
use exactcheck_exact::univariate::UPoly;
use exactcheck_exact::Rational;
use serde_json::Value;

fn q(s: &str) -> Rational {
    s.parse()
        .unwrap_or_else(|e| panic!("{s:?} does not parse back: {e}"))
}

fn num(v: &Value) -> Rational {
    match v {
        Value::String(s) => q(s),
        Value::Number(n) => q(&n.to_string()),
        other => panic!("not a number: {other}"),
    }
}

fn nums(v: &Value) -> Vec<Rational> {
    v.as_array().expect("an array").iter().map(num).collect()
}

/// sum c_i C(n, i) t^i (1 - t)^(n - i), evaluated directly.
fn bern_eval(c: &[Rational], t: &Rational) -> Rational {
    let n = c.len() - 1;
    let s = Rational::ONE - t.clone();
    let mut acc = Rational::ZERO;
    for (i, ci) in c.iter().enumerate() {
        let mut term = ci.clone() * binom(n, i);
        for _ in 0..i {
            term *= t.clone();
        }
        for _ in 0..n - i {
            term *= s.clone();
        }
        acc += term;
    }
    acc
}

/// Distinct zeros of `p` in `[0, 1]` (Sturm).
fn zeros_in_unit(p: &UPoly) -> usize {
    p.count_roots(&Rational::ZERO, &Rational::ONE) + usize::from(p.eval(&Rational::ZERO).is_zero())
}

/// A random small rational `a/b`, `|a| <= m`.
fn small(rng: &mut Rng, m: u64) -> Rational {
    let a = rng.below(2 * m + 1) as i64 - m as i64;
    let b = rng.below(4) as i64 + 1;
    Rational::new(a, b).expect("b >= 1")
}

fn text(v: &[Rational]) -> String {
    let items: Vec<String> = v.iter().map(|x| format!("\"{x}\"")).collect();
    format!("[{}]", items.join(","))
}

/// The signed radius of curvature `sigma^2 / (2 w)` of `side` at `t` (`None` where that side
/// does not bend).
fn side_radius(sigma: &UPoly, w: &UPoly, side: Side, t: &Rational) -> Option<Rational> {
    let wt = match side {
        Side::Left => w.eval(t),
        Side::Right => -w.eval(t),
    };
    (wt.sign() == Sign::Positive).then(|| {
        let s = sigma.eval(t);
        s.clone() * s / (Rational::from(2) * wt)
    })
}

/// An enclosed smallest radius `(lo, hi]`: every listed parameter interval holds a minimiser of
/// the radius, checked independently of the answer's own polynomials: the derivative of the
/// radius (sign of `(2 sigma' w - sigma w')`, negated on the right) goes from negative to
/// positive across it (so the radius inside is below the radius at the interval's ends), and the
/// radius at its midpoint is above `lo`, at most the radius at `t = 0` and `t = 1`, and within
/// the enclosure's width of `hi`.
fn check_minimisers(
    problem: &str,
    sigma: &UPoly,
    w: &UPoly,
    side: Side,
    enclosure: &[Rational],
    at: &Value,
) {
    let (lo, hi) = (&enclosure[0], &enclosure[1]);
    let crit = UPoly::constant(Rational::from(2))
        .mul_ref(&sigma.derivative())
        .mul_ref(w)
        .sub_ref(&sigma.mul_ref(&w.derivative()));
    let slope = |t: &Rational| match side {
        Side::Left => crit.eval(t).sign(),
        Side::Right => (-crit.eval(t)).sign(),
    };
    let at = at.as_array().expect("at is a list");
    assert!(!at.is_empty(), "{problem}: no minimiser listed");
    for entry in at {
        let iv = nums(&entry["interval"]);
        assert!(
            iv[0] < iv[1],
            "{problem}: an irrational minimiser is an interval"
        );
        assert_eq!(
            slope(&iv[0]),
            Sign::Negative,
            "{problem}: rho' at {}",
            iv[0]
        );
        assert_eq!(
            slope(&iv[1]),
            Sign::Positive,
            "{problem}: rho' at {}",
            iv[1]
        );
        let mid = (iv[0].clone() + iv[1].clone()) / Rational::from(2);
        let at_mid = side_radius(sigma, w, side, &mid).expect("the side bends at its minimum");
        assert!(at_mid > *lo, "{problem}: rho({mid}) <= lo");
        assert!(
            at_mid.clone() - hi.clone() <= hi.clone() - lo.clone(),
            "{problem}: rho({mid}) far above hi"
        );
        for t in [&Rational::ZERO, &Rational::ONE] {
            if let Some(r) = side_radius(sigma, w, side, t) {
                assert!(at_mid <= r, "{problem}: rho({mid}) > rho({t})");
            }
        }
    }
}

struct Checked {
    regular: usize,
    exact_radius: usize,
    enclosed_radius: usize,
    cusps: usize,
    points: usize,
}

/// Solves one random problem and checks everything the module doc lists.
fn check_curve(
    u: &[Rational],
    v: &[Rational],
    start: [Rational; 2],
    radii: &[Rational],
    c: &mut Checked,
) {
    let problem = format!(
        r#"{{"kind":"ph_offset","u":{},"v":{},"start":{},"r":{},"precision":"1/1048576"}}"#,
        text(u),
        text(v),
        text(&start),
        text(radii)
    );
    let a = solve(&problem, Mode::Exact).unwrap_or_else(|e| panic!("{problem}: {e}"));
    let k = u.len() - 1;
    let n = 2 * k + 1;
    assert_eq!(a["kind"], "ph_offset");
    assert_eq!(a["base_degree"], n);
    assert_eq!(a["degree"], 2 * n - 1, "{problem}");

    // Independent polynomials from the problem itself.
    let (up, vp) = (upoly(u), upoly(v));
    let sigma_p = up.mul_ref(&up).add_ref(&vp.mul_ref(&vp));
    let w_p = up
        .mul_ref(&vp.derivative())
        .sub_ref(&up.derivative().mul_ref(&vp));
    let singular = !sigma_p.is_zero() && zeros_in_unit(&sigma_p) > 0;
    let offsets = a["offsets"].as_array().expect("r was an array");
    assert_eq!(offsets.len(), radii.len());
    if singular {
        assert_eq!(a["outcome"], "singular_base", "{problem}");
        assert!(a["min_radius_of_curvature"].is_null());
        assert!(!a["poles"].as_array().unwrap().is_empty());
        for o in offsets {
            assert!(o["cusps"].is_null());
        }
        return;
    }
    c.regular += 1;
    assert_eq!(a["outcome"], "offsets", "{problem}");

    // The base: starts at `start`; differences of its control points are the hodograph / n,
    // and the hodograph is (u^2 - v^2, 2uv) of the problem.
    let base: Vec<[Rational; 2]> = a["base"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            let c = nums(p);
            [c[0].clone(), c[1].clone()]
        })
        .collect();
    assert_eq!(base.len(), n + 1);
    assert_eq!(base[0], start);
    let nq = Rational::from(n as i64);
    let dx: Vec<Rational> = base
        .windows(2)
        .map(|w| (w[1][0].clone() - w[0][0].clone()) * nq.clone())
        .collect();
    let dy: Vec<Rational> = base
        .windows(2)
        .map(|w| (w[1][1].clone() - w[0][1].clone()) * nq.clone())
        .collect();
    let speed = nums(&a["speed"]);
    assert_eq!(speed.len(), 2 * k + 1);

    // The weights: sigma elevated from degree 2k to 2n - 1 = 4k + 1, by the elevation formula.
    let mut elevated = speed.clone();
    while elevated.len() < 2 * n {
        let m = elevated.len(); // new degree
        let mut next = Vec::with_capacity(m + 1);
        for i in 0..=m {
            let f = Rational::new(i as i64, m as i64).unwrap();
            let left = if i > 0 {
                elevated[i - 1].clone() * f.clone()
            } else {
                Rational::ZERO
            };
            let right = if i < m {
                elevated[i].clone() * (Rational::ONE - f)
            } else {
                Rational::ZERO
            };
            next.push(left + right);
        }
        elevated = next;
    }

    let samples: Vec<Rational> = (0..=32)
        .map(|j| Rational::new(j, 32).unwrap())
        .chain([q("1/3"), q("2/7"), q("5/9")])
        .collect();
    for t in &samples {
        let (xd, yd) = (bern_eval(&dx, t), bern_eval(&dy, t));
        let (ut, vt) = (bern_eval(u, t), bern_eval(v, t));
        assert_eq!(
            xd,
            ut.clone() * ut.clone() - vt.clone() * vt.clone(),
            "{problem} X'({t})"
        );
        assert_eq!(
            yd,
            Rational::from(2) * ut.clone() * vt.clone(),
            "{problem} Y'({t})"
        );
        assert_eq!(
            bern_eval(&speed, t),
            ut.clone() * ut + vt.clone() * vt,
            "{problem} sigma({t})"
        );
    }

    let curve = PhCurve::new(
        Bernstein::new(u.to_vec()),
        Bernstein::new(v.to_vec()),
        Vec3::new(start[0].clone(), start[1].clone(), Rational::ZERO),
    )
    .expect("a curve");

    for (o, r) in offsets.iter().zip(radii) {
        assert_eq!(num(&o["r"]), *r);
        assert_eq!(o["outcome"], if r.is_zero() { "r_zero" } else { "offset" });
        let weights = nums(&o["weights"]);
        assert_eq!(weights, elevated, "{problem}: weights = sigma elevated");
        let wp: Vec<Vec<Rational>> = o["weighted_points"]
            .as_array()
            .unwrap()
            .iter()
            .map(nums)
            .collect();
        assert_eq!(wp.len(), 2 * n);
        for (k, p) in o["points"].as_array().unwrap().iter().enumerate() {
            if weights[k].is_zero() {
                assert!(p.is_null());
            } else {
                let p = nums(p);
                assert_eq!(p[2], *r, "control point z = r");
                for i in 0..3 {
                    assert_eq!(p[i].clone() * weights[k].clone(), wp[k][i]);
                }
            }
        }
        let coord = |i: usize| -> Vec<Rational> { wp.iter().map(|p| p[i].clone()).collect() };
        let (cx, cy, cz) = (coord(0), coord(1), coord(2));
        let bx: Vec<Rational> = base.iter().map(|p| p[0].clone()).collect();
        let by: Vec<Rational> = base.iter().map(|p| p[1].clone()).collect();
        for t in &samples {
            let wt = bern_eval(&weights, t);
            let (x, y, z) = (
                bern_eval(&cx, t) / wt.clone(),
                bern_eval(&cy, t) / wt.clone(),
                bern_eval(&cz, t) / wt,
            );
            let (ddx, ddy) = (x - bern_eval(&bx, t), y - bern_eval(&by, t));
            let (xd, yd) = (bern_eval(&dx, t), bern_eval(&dy, t));
            assert_eq!(z, *r, "{problem}: z = r at {t}");
            assert_eq!(
                ddx.clone() * ddx.clone() + ddy.clone() * ddy.clone(),
                r.clone() * r.clone(),
                "{problem}: |C - B| = |r| at {t}"
            );
            assert_eq!(
                ddx.clone() * xd.clone() + ddy.clone() * yd.clone(),
                Rational::ZERO,
                "{problem}: along the normal at {t}"
            );
            // B' x (C - B) = r sigma: on the left for r > 0, the right for r < 0.
            assert_eq!(
                xd * ddy - yd * ddx,
                r.clone() * bern_eval(&speed, t),
                "{problem}: side at {t}"
            );
            c.points += 1;
        }

        // Cusps: exactly the zeros of sigma^2 - 2 r w in [0, 1], each isolated.
        let f = sigma_p
            .mul_ref(&sigma_p)
            .sub_ref(&w_p.scale(&(Rational::from(2) * r.clone())));
        let cusps = o["cusps"]
            .as_array()
            .expect("a regular base has cusps listed");
        assert_eq!(cusps.len(), zeros_in_unit(&f), "{problem}: r = {r}");
        for cusp in cusps {
            let t = &cusp["t"];
            let mult = cusp["multiplicity"].as_u64().expect("exact mode gives it");
            if t["exact"].is_string() {
                let t0 = num(&t["exact"]);
                let mut d = f.clone();
                let mut m = 0;
                while d.eval(&t0).is_zero() {
                    m += 1;
                    d = d.derivative();
                }
                assert_eq!(m, mult, "{problem}: multiplicity at {t0}");
                let p = nums(&cusp["point"]);
                assert_eq!(p[2], *r);
            } else {
                let iv = nums(&t["interval"]);
                assert!(iv[0] < iv[1] && iv[0] >= Rational::ZERO && iv[1] <= Rational::ONE);
                assert!(!f.eval(&iv[0]).is_zero());
                assert_eq!(
                    f.count_roots(&iv[0], &iv[1]),
                    1,
                    "{problem}: one zero in {iv:?}"
                );
                if mult == 1 {
                    assert!(f.eval(&iv[0]).sign() != f.eval(&iv[1]).sign());
                }
                assert!(iv[1].clone() - iv[0].clone() <= q("1/1048576"));
            }
            c.cusps += 1;
        }
    }

    // The smallest radius, side by side.
    let by_side = &a["min_radius_by_side"];
    for (name, side) in [("left", Side::Left), ("right", Side::Right)] {
        let m = &by_side[name];
        // The side bends somewhere iff its w has that sign somewhere in [0, 1].
        if m.is_null() {
            for t in &samples {
                let wt = w_p.eval(t);
                assert!(
                    match side {
                        Side::Left => wt.sign() != Sign::Positive,
                        Side::Right => wt.sign() != Sign::Negative,
                    },
                    "{problem}: {name} bends at {t} but has no radius"
                );
            }
            continue;
        }
        let signed = |x: &Rational| match side {
            Side::Left => x.clone(),
            Side::Right => -x.clone(),
        };
        let cusp_count = |x: &Rational| {
            let f = sigma_p
                .mul_ref(&sigma_p)
                .sub_ref(&w_p.scale(&(Rational::from(2) * signed(x))));
            zeros_in_unit(&f)
        };
        if m["exact"].is_string() {
            let value = num(&m["exact"]);
            assert!(
                curve.is_min_radius(&value, side).unwrap(),
                "{problem}: {name} {value}"
            );
            // No sampled radius on this side is smaller.
            for t in &samples {
                let wt = signed(&w_p.eval(t));
                if wt.sign() == Sign::Positive {
                    let s = sigma_p.eval(t);
                    assert!(
                        s.clone() * s / (Rational::from(2) * wt) >= value,
                        "{problem}: rho({t}) < {value}"
                    );
                }
            }
            for at in m["at"].as_array().unwrap() {
                if at["exact"].is_string() {
                    let t = num(&at["exact"]);
                    assert_eq!(signed(&curve.radius_at(&t).unwrap()), value);
                }
            }
            assert!(cusp_count(&value) > 0);
            c.exact_radius += 1;
        } else {
            let iv = nums(&m["interval"]);
            assert!(iv[0] < iv[1]);
            assert!(
                curve.offset_cusps(&signed(&iv[0])).unwrap().is_empty(),
                "{problem}"
            );
            assert!(
                !curve.offset_cusps(&signed(&iv[1])).unwrap().is_empty(),
                "{problem}"
            );
            assert_eq!(
                cusp_count(&iv[0]),
                0,
                "{problem}: no cusp below the enclosure"
            );
            assert!(cusp_count(&iv[1]) > 0, "{problem}: a cusp at its top");
            assert!(iv[1].clone() - iv[0].clone() <= q("1/1048576"));
            check_minimisers(&problem, &sigma_p, &w_p, side, &iv, &m["at"]);
            c.enclosed_radius += 1;
        }
    }
    // The overall minimum is the smaller side.
    let overall = &a["min_radius_of_curvature"];
    match overall["side"].as_str() {
        None => assert!(by_side["left"].is_null() && by_side["right"].is_null()),
        Some("left") | Some("right") => {
            let s = overall["side"].as_str().unwrap();
            assert_eq!(overall["exact"], by_side[s]["exact"], "{problem}");
            let other = if s == "left" { "right" } else { "left" };
            if let (Some(x), Some(y)) =
                (overall["exact"].as_str(), by_side[other]["exact"].as_str())
            {
                assert!(q(x) < q(y));
            }
        }
        Some("both") => assert_eq!(by_side["left"]["exact"], by_side["right"]["exact"]),
        Some(other) => assert_eq!(other, "left_or_right"),
    }
}

#[test]
fn random_ph_curves_have_exact_offsets_cusps_and_radii() {
    let mut rng = Rng::new(20261123);
    let mut c = Checked {
        regular: 0,
        exact_radius: 0,
        enclosed_radius: 0,
        cusps: 0,
        points: 0,
    };
    let mut degrees = [0usize; 3];
    for i in 0..108 {
        let k = 1 + i % 3;
        let (u, v) = loop {
            let u: Vec<Rational> = (0..=k).map(|_| small(&mut rng, 6)).collect();
            let v: Vec<Rational> = (0..=k).map(|_| small(&mut rng, 6)).collect();
            if u.iter().chain(&v).any(|x| !x.is_zero()) {
                break (u, v);
            }
        };
        let start = [small(&mut rng, 5), small(&mut rng, 5)];
        // Small, large and negative distances, and sometimes 0.
        let mut radii = vec![
            small(&mut rng, 3),
            small(&mut rng, 40),
            -small(&mut rng, 40).abs(),
        ];
        if i % 9 == 0 {
            radii.push(Rational::ZERO);
        }
        check_curve(&u, &v, start, &radii, &mut c);
        degrees[k - 1] += 1;
    }
    assert!(c.regular >= 100, "{} regular curves", c.regular);
    assert_eq!(degrees, [36, 36, 36]);
    // The checks were not vacuous.
    assert!(
        c.exact_radius > 10 && c.enclosed_radius > 10,
        "{} exact, {} enclosed",
        c.exact_radius,
        c.enclosed_radius
    );
    assert!(c.cusps > 50, "{} cusps", c.cusps);
    assert!(c.points > 10_000, "{} points", c.points);
    eprintln!(
        "{} regular curves, {} exact and {} enclosed radii, {} cusps, {} offset points checked",
        c.regular, c.exact_radius, c.enclosed_radius, c.cusps, c.points
    );
}

#[test]
fn chiang_example_answers_and_a_singular_base() {
    let mut c = Checked {
        regular: 0,
        exact_radius: 0,
        enclosed_radius: 0,
        cusps: 0,
        points: 0,
    };
    let i = |x: i64| Rational::from(x);
    check_curve(
        &[i(10), i(-1)],
        &[i(1), i(10)],
        [i(0), i(0)],
        &[i(3), q("63/5"), i(15), i(-15)],
        &mut c,
    );
    assert_eq!(c.exact_radius, 1);
    assert_eq!(c.cusps, 2, "r = 15 has two cusps, 3 and 12.6 < 101/8 none");
    // u and v share the zero 1/2: singular base, offsets with their pole, no radius or cusps.
    check_curve(
        &[i(1), i(0), i(-1)],
        &[i(1), q("1/2"), i(-2)],
        [i(0), i(0)],
        &[i(2)],
        &mut c,
    );
}

#[test]
fn the_smallest_radius_of_the_worked_example_is_101_over_8_at_one_half() {
    let a = solve(
        r#"{"kind":"ph_offset","u":[10,-1],"v":[1,10],"start":[0,0],"r":"101/8"}"#,
        Mode::Exact,
    )
    .unwrap();
    let m = &a["min_radius_of_curvature"];
    assert_eq!(m["exact"], "101/8");
    assert_eq!(m["side"], "left");
    assert_eq!(m["at"][0]["exact"], "1/2");
    // At r = rho_min the two cusps have merged: one double zero at 1/2.
    let cusps = a["cusps"].as_array().unwrap();
    assert_eq!(cusps.len(), 1);
    assert_eq!(cusps[0]["t"]["exact"], "1/2");
    assert_eq!(cusps[0]["multiplicity"], 2);
}

#[test]
fn r_zero_is_the_curve_itself() {
    let a = solve(
        r#"{"kind":"ph_offset","u":[1,"1/2",-1],"v":[0,1,"2/3"],"start":[1,-2],"r":0}"#,
        Mode::Exact,
    )
    .unwrap();
    assert_eq!(a["outcome"], "r_zero");
    let base: Vec<Vec<Rational>> = a["base"].as_array().unwrap().iter().map(nums).collect();
    let weights = nums(&a["weights"]);
    let wp: Vec<Vec<Rational>> = a["weighted_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(nums)
        .collect();
    for j in 0..=8 {
        let t = Rational::new(j, 8).unwrap();
        let wt = bern_eval(&weights, &t);
        for axis in 0..2 {
            let c: Vec<Rational> = wp.iter().map(|p| p[axis].clone()).collect();
            let b: Vec<Rational> = base.iter().map(|p| p[axis].clone()).collect();
            assert_eq!(bern_eval(&c, &t) / wt.clone(), bern_eval(&b, &t));
        }
    }
    assert!(a["cusps"].as_array().unwrap().is_empty());
}

#[test]
fn a_straight_line_has_no_radius() {
    // u = 2 v: w = u v' - u' v = 0, a line traversed non-uniformly.
    let a = solve(
        r#"{"kind":"ph_offset","u":[2,4],"v":[1,2],"start":[0,0],"r":[1,-1]}"#,
        Mode::Exact,
    )
    .unwrap();
    assert_eq!(a["outcome"], "offsets");
    assert!(a["min_radius_of_curvature"].is_null());
    assert!(a["note"].as_str().unwrap().contains("straight line"));
    for o in a["offsets"].as_array().unwrap() {
        assert!(o["cusps"].as_array().unwrap().is_empty());
    }
}

#[test]
fn radical_coefficients_are_answered_in_the_radical_field() {
    let a = solve(
        r#"{"kind":"ph_offset","u":["sqrt(2)",1],"v":[0,"sqrt(2)"],"start":[0,0],"r":"1/2"}"#,
        Mode::Exact,
    )
    .unwrap();
    assert_eq!(a["outcome"], "offset");
    assert!(a["speed"][0] == "2", "{}", a["speed"]);
    assert!(!a["min_radius_of_curvature"].is_null());
}

#[test]
fn float_mode_runs_the_same_code_and_agrees() {
    let p = r#"{"kind":"ph_offset","u":[10,-1],"v":[1,10],"start":[0,0],"r":[3,"63/5",15]}"#;
    let e = solve(p, Mode::Exact).unwrap();
    let f = solve(p, Mode::Float).unwrap();
    assert_eq!(f["mode"], "float");
    for (eo, fo) in e["offsets"]
        .as_array()
        .unwrap()
        .iter()
        .zip(f["offsets"].as_array().unwrap())
    {
        for (ep, fp) in eo["points"]
            .as_array()
            .unwrap()
            .iter()
            .zip(fo["points"].as_array().unwrap())
        {
            for (x, y) in nums(ep).iter().zip(fp.as_array().unwrap()) {
                assert!((x.to_f64() - y.as_f64().unwrap()).abs() < 1e-12);
            }
        }
        assert_eq!(
            eo["cusps"].as_array().unwrap().len(),
            fo["cusps"].as_array().unwrap().len()
        );
    }
    let m = f["min_radius_of_curvature"]["approx"].as_f64().unwrap();
    assert!((m - 12.625).abs() < 1e-6, "{m}");
    let b = solve(p, Mode::Both).unwrap();
    assert_eq!(b["mode"], "exact");
    assert_eq!(b["float"]["mode"], "float");
}

#[test]
fn degenerate_input_is_refused_in_one_line() {
    let p = |u: &str, v: &str, rest: &str| {
        format!(r#"{{"kind":"ph_offset","u":{u},"v":{v},"start":[0,0]{rest}}}"#)
    };
    refused(
        &p("[0,0]", "[0,\"0\"]", r#","r":1"#),
        &[],
        &["u, v", "zero"],
    );
    refused(&p("[1,2]", "[1]", r#","r":1"#), &[], &["v:", "same degree"]);
    refused(&p("[]", "[]", r#","r":1"#), &[], &["u:", "at least one"]);
    refused(&p("[1]", "[2]", r#","r":[]"#), &[], &["r:", "empty array"]);
    refused(
        &p("[1]", "[2]", r#","r":0.5"#),
        &[],
        &["r:", "floating-point"],
    );
    refused(
        &p("[1]", "[2]", r#","r":[1,0.5]"#),
        &[],
        &["r:", "element 1"],
    );
    refused(
        &p("[1.5]", "[2]", r#","r":1"#),
        &[],
        &["u", "floating-point"],
    );
    refused(&p("[1]", "[2]", r#","r":"x""#), &[], &["r:"]);
    refused(&p("[1]", "[2]", r#","r":true"#), &[], &["r:", "boolean"]);
    refused(&p("[1]", "[2]", ""), &[], &["missing field `r`"]);
    refused(
        &p("[1]", "[2]", r#","r":1,"precision":0"#),
        &[],
        &["precision"],
    );
    refused(&p("[1]", "[2]", r#","r":1,"extra":0"#), &[], &["extra"]);
    refused(
        r#"{"kind":"ph_offset","u":[1],"v":[2],"start":[0],"r":1}"#,
        &[],
        &["start", "2 coordinates"],
    );
    let many = format!("[{}]", vec!["1"; 17].join(","));
    refused(&p(&many, &many, r#","r":1"#), &[], &["u:", "at most 16"]);
    refused(&p("[\"1/0\"]", "[2]", r#","r":1"#), &[], &["u"]);
    // The float path refuses what f64 cannot hold.
    refused(
        &p("[\"10^200\"]", "[2]", r#","r":1"#),
        &["--float"],
        &["f64"],
    );
    // A singular base is a named outcome through the binary too, exit 0.
    let o = solve_stdin(p("[1,-1]", "[1,-1]", r#","r":2"#), &[]);
    assert!(o.status.success());
    let a: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(a["outcome"], "singular_base");
    assert_eq!(a["poles"][0]["exact"], "1/2");
}

/// The offset at the parameter `t` (f64), from the answer's exact weights and weighted points.
fn offset_at(offset: &Value, t: f64) -> [f64; 2] {
    let w: Vec<f64> = nums(&offset["weights"])
        .iter()
        .map(Rational::to_f64)
        .collect();
    let wp: Vec<Vec<f64>> = offset["weighted_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| nums(p).iter().map(Rational::to_f64).collect())
        .collect();
    let n = w.len() - 1;
    let basis = |i: usize| binom(n, i).to_f64() * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32);
    let (mut x, mut y, mut d) = (0.0, 0.0, 0.0);
    for i in 0..=n {
        x += basis(i) * wp[i][0];
        y += basis(i) * wp[i][1];
        d += basis(i) * w[i];
    }
    [x / d, y / d]
}

/// `self_intersections` (exact mode, rational input, base degree <= 5): Chiang's offsets have
/// none at r = 3 and 63/5 and one crossing at 15; every certified crossing is a pair of
/// parameters where the answered curve really meets itself (checked in f64 from the exact
/// control data); a septic gets a note, radical input no field.
#[test]
fn self_intersections_are_decided_exactly_for_low_degrees() {
    let a = solve(
        r#"{"kind":"ph_offset","u":[10,-1],"v":[1,10],"start":[0,0],"r":[3,"63/5",15]}"#,
        Mode::Exact,
    )
    .unwrap();
    let counts: Vec<u64> = a["offsets"]
        .as_array()
        .unwrap()
        .iter()
        .map(|o| {
            assert_eq!(o["self_intersections"]["decided"], true, "{o}");
            o["self_intersections"]["count"].as_u64().unwrap()
        })
        .collect();
    assert_eq!(counts, vec![0, 0, 1]);
    let mut rng = Rng::new(77);
    let mut crossings = 0;
    for _ in 0..12 {
        let u: Vec<Rational> = (0..2).map(|_| small(&mut rng, 9)).collect();
        let v: Vec<Rational> = (0..2).map(|_| small(&mut rng, 9)).collect();
        let problem = format!(
            r#"{{"kind":"ph_offset","u":{},"v":{},"start":[0,0],"r":[1,8,30,-30]}}"#,
            text(&u),
            text(&v)
        );
        let Ok(a) = solve(&problem, Mode::Exact) else {
            continue;
        };
        for o in a["offsets"].as_array().unwrap() {
            let si = &o["self_intersections"];
            if si["decided"] != true {
                continue;
            }
            for c in si["crossings"].as_array().unwrap() {
                let (s, t) = (
                    c["s"]["approx"].as_f64().unwrap(),
                    c["t"]["approx"].as_f64().unwrap(),
                );
                assert!(s < t && (0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&t));
                let (p, q) = (offset_at(o, s), offset_at(o, t));
                let scale = 1.0 + p[0].abs().max(p[1].abs());
                assert!(
                    (p[0] - q[0]).abs() < 1e-6 * scale && (p[1] - q[1]).abs() < 1e-6 * scale,
                    "{problem}: C({s}) = {p:?} but C({t}) = {q:?}"
                );
                crossings += 1;
            }
        }
    }
    assert!(crossings > 0, "some random offset crosses itself");
    let septic = solve(
        r#"{"kind":"ph_offset","u":[1,2,3,4],"v":[4,3,2,1],"start":[0,0],"r":1}"#,
        Mode::Exact,
    )
    .unwrap();
    assert_eq!(septic["self_intersections"]["decided"], false);
    let radical = solve(
        r#"{"kind":"ph_offset","u":["sqrt(2)",1],"v":[1,2],"start":[0,0],"r":1}"#,
        Mode::Exact,
    )
    .unwrap();
    assert!(radical.get("self_intersections").is_none());
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig {
        cases: 48,
        failure_persistence: None,
        ..proptest::prelude::ProptestConfig::default()
    })]

    /// Quintic and septic PH curves whose smallest radius is irrational (an enclosure): every
    /// listed parameter holds a minimiser of the radius ([`check_minimisers`]), on both sides.
    #[test]
    fn irrational_minimum_radius_is_attained_inside_the_listed_intervals(
        uv in proptest::collection::vec((-4i64..=4, -4i64..=4, 1i64..=3), 3..5),
    ) {
        let u: Vec<Rational> = uv.iter().map(|(a, _, d)| Rational::new(*a, *d).unwrap()).collect();
        let v: Vec<Rational> = uv.iter().map(|(_, b, d)| Rational::new(*b, *d).unwrap()).collect();
        let (up, vp) = (upoly(&u), upoly(&v));
        let sigma = up.mul_ref(&up).add_ref(&vp.mul_ref(&vp));
        proptest::prop_assume!(!sigma.is_zero() && zeros_in_unit(&sigma) == 0);
        let w = up.mul_ref(&vp.derivative()).sub_ref(&up.derivative().mul_ref(&vp));
        let problem = format!(
            r#"{{"kind":"ph_offset","u":{},"v":{},"start":[0,0],"r":1}}"#,
            text(&u),
            text(&v)
        );
        let a = solve(&problem, Mode::Exact).unwrap_or_else(|e| panic!("{problem}: {e}"));
        let by_side = &a["min_radius_by_side"];
        let mut enclosed = false;
        for (name, side) in [("left", Side::Left), ("right", Side::Right)] {
            let m = &by_side[name];
            if m["interval"].is_array() {
                enclosed = true;
                check_minimisers(&problem, &sigma, &w, side, &nums(&m["interval"]), &m["at"]);
            }
        }
        proptest::prop_assume!(enclosed);
        let overall = &a["min_radius_of_curvature"];
        if overall["interval"].is_array() && overall["side"] != "left_or_right" {
            let side = if overall["side"] == "left" { Side::Left } else { Side::Right };
            let interval = nums(&overall["interval"]);
            check_minimisers(&problem, &sigma, &w, side, &interval, &overall["at"]);
        }
    }
}

/// The committed quintic example has an irrational smallest radius: its `at` is the one
/// minimiser, not the two zeros of `sigma^2 - 2 hi w` on either side of it.
#[test]
fn the_quintic_example_lists_its_minimiser() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/solve_golden");
    let problem = std::fs::read_to_string(dir.join("ph_quintic.json")).unwrap();
    let a = solve(&problem, Mode::Exact).unwrap();
    let (up, vp) = (
        upoly(&[q("1"), q("1/2"), q("-1")]),
        upoly(&[q("0"), q("1"), q("2/3")]),
    );
    let sigma = up.mul_ref(&up).add_ref(&vp.mul_ref(&vp));
    let w = up
        .mul_ref(&vp.derivative())
        .sub_ref(&up.derivative().mul_ref(&vp));
    let m = &a["min_radius_of_curvature"];
    assert_eq!(m["side"], "left");
    assert_eq!(m["at"].as_array().unwrap().len(), 1);
    check_minimisers(
        &problem,
        &sigma,
        &w,
        Side::Left,
        &nums(&m["interval"]),
        &m["at"],
    );
}

#[test]
fn coefficients_of_thousands_of_digits_are_refused_before_the_work() {
    // Linear u, v with 9,999-digit coefficients ran for 144 s.
    let big = format!("1{}", "3".repeat(9998));
    let problem =
        format!(r#"{{"kind":"ph_offset","u":["{big}",-1],"v":[1,"{big}"],"start":[0,0],"r":3}}"#);
    common::refused(
        &problem,
        &[],
        &["u, v: ", "exceeds the limit ph-bits = 2048 bits"],
    );
}
