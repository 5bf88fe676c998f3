//! `solve conic` on 560 random planes (rational, radical, and the boundary families
//! `c^2 = a^2 + b^2`, `a = b = 0`, `d = 0`, `a + b + c = 0`) through the library entry, every
//! answer checked **independently of `core::conic`**: the cone's control vectors are the ones
//! the claim list prints, the weights are `N . q_k` of the printed vectors, the curve points at 13
//! rational parameters lie on the plane and on the cone exactly, the `type` equals the angle
//! rule computed here from the normal AND the weight-discriminant rule computed here from the
//! answered weights, the poles are zeros / sign changes of the answered weight polynomial and
//! give the right number of asymptotic directions, and the rulings of a plane through the apex
//! lie on the cone and in the plane. Bad input is a one-line error naming the field (exit 2).

use crate::common;

use common::{refused, solve_stdin};
use exactcheck::solve::{solve, Mode};
use exactcheck_core::{Bernstein, OrderedField, Ring, Rng, Sign, Vec3};
use exactcheck_exact::{Radical, Rational};
use serde_json::Value;

fn r(s: &str) -> Radical {
    s.parse()
        .unwrap_or_else(|e| panic!("{s:?} does not parse back: {e}"))
}

fn num(x: &Value) -> Radical {
    match x {
        Value::String(s) => r(s),
        Value::Number(n) => r(&n.to_string()),
        other => panic!("not a number: {other}"),
    }
}

fn radicals(v: &Value) -> Vec<Radical> {
    v.as_array().expect("an array").iter().map(num).collect()
}

fn vec3(v: &Value) -> Vec3<Radical> {
    let c = radicals(v);
    assert_eq!(c.len(), 3, "{v}");
    Vec3::new(c[0].clone(), c[1].clone(), c[2].clone())
}

fn on_cone(p: &Vec3<Radical>) -> bool {
    p.x.square() + p.y.square() == p.z.square()
}

/// the claim list's control vectors of V+ and V-.
fn spec_cone(piece: usize) -> Vec<Vec3<Radical>> {
    let s = r("1/sqrt(2)");
    let v =
        |x: i64, y: i64, z: i64| Vec3::new(Radical::from(x), Radical::from(y), Radical::from(z));
    let mid = |k: &Radical| Vec3::new(k.clone(), k.clone(), k.clone());
    if piece == 0 {
        vec![v(1, 0, 1), mid(&s), v(0, 1, 1)]
    } else {
        vec![v(0, 1, 1), mid(&s.neg_ref()), v(1, 0, 1)]
    }
}

/// Quadratic Bezier combination of three vectors at `t`.
fn bezier(ctrl: &[Vec3<Radical>], t: &Radical) -> Vec3<Radical> {
    let coord =
        |f: fn(&Vec3<Radical>) -> Radical| Bernstein::new(ctrl.iter().map(f).collect()).eval(t);
    Vec3::new(
        coord(|p| p.x.clone()),
        coord(|p| p.y.clone()),
        coord(|p| p.z.clone()),
    )
}

/// The paper's angle rule, decided here from the normal and `d` (theta in [0, pi/2]).
fn angle_rule(n: &Vec3<Radical>, d: &Radical) -> &'static str {
    let h = n.x.square() + n.y.square();
    let v = n.z.square();
    let conic = if h.is_zero() {
        "circle"
    } else {
        match v.sub_ref(&h).sign() {
            Sign::Positive => "ellipse",
            Sign::Zero => "parabola",
            Sign::Negative => "hyperbola",
        }
    };
    match (d.is_zero(), conic) {
        (false, c) => c,
        (true, "circle" | "ellipse") => "point",
        (true, "parabola") => "double_line",
        (true, _) => "line_pair",
    }
}

/// The number of distinct asymptotic directions (rulings parallel to the plane) each type has.
fn directions_at_infinity(t: &str) -> usize {
    match t {
        "circle" | "ellipse" | "point" => 0,
        "parabola" | "double_line" => 1,
        _ => 2,
    }
}

/// Where `t` of a pole is exact, its value; else the isolating interval.
fn pole_t(pole: &Value) -> Result<Radical, (Radical, Radical)> {
    match &pole["t"] {
        Value::Object(o) => {
            let i = radicals(&o["interval"]);
            Err((i[0].clone(), i[1].clone()))
        }
        t => Ok(num(t)),
    }
}

/// Checks one exact answer; returns the number of (piece, parameter) points checked.
fn check(problem: &str, a: &Value) -> usize {
    let input: Value = serde_json::from_str(problem).unwrap();
    let (normal, d) = if input["plane"].is_array() {
        let p = radicals(&input["plane"]);
        (
            Vec3::new(p[0].clone(), p[1].clone(), p[2].clone()),
            p[3].clone(),
        )
    } else {
        let n = vec3(&input["normal"]);
        let d = n.dot(&vec3(&input["point"])).neg_ref();
        (n, d)
    };
    assert_eq!(a["kind"], "conic");
    assert_eq!(a["mode"], "exact");
    let plane = radicals(&a["plane"]);
    assert_eq!(
        plane,
        vec![
            normal.x.clone(),
            normal.y.clone(),
            normal.z.clone(),
            d.clone()
        ]
    );
    let want = angle_rule(&normal, &d);
    assert_eq!(a["type"], want, "{problem}");
    assert_eq!(a["type_by_angle_rule"], want, "{problem}");
    assert_eq!(a["type_by_bezier"], want, "{problem}");
    let pieces = a["pieces"].as_array().unwrap();
    assert_eq!(pieces.len(), 2);
    let mut checked = 0;
    let mut pole_count = 0;
    for (i, piece) in pieces.iter().enumerate() {
        assert_eq!(piece["cone"], ["+", "-"][i]);
        let q: Vec<Vec3<Radical>> = piece["directions"]
            .as_array()
            .unwrap()
            .iter()
            .map(vec3)
            .collect();
        assert_eq!(q, spec_cone(i), "{problem}: the cone's control vectors");
        let w = radicals(&piece["weights"]);
        let weighted: Vec<Vec3<Radical>> = piece["weighted_points"]
            .as_array()
            .unwrap()
            .iter()
            .map(vec3)
            .collect();
        for k in 0..3 {
            assert_eq!(w[k], normal.dot(&q[k]), "{problem}: w{k} = N.q{k}");
            assert_eq!(
                weighted[k],
                q[k].scale(&d.neg_ref()),
                "{problem}: w{k} r{k}"
            );
            let p = &piece["points"][k];
            if w[k].is_zero() {
                assert!(p.is_null(), "{problem}: points[{k}]");
            } else {
                assert_eq!(vec3(p).scale(&w[k]), weighted[k], "{problem}: points[{k}]");
            }
        }
        // The weight-discriminant rule, computed here from the answered weights.
        let disc = w[1].square().sub_ref(&w[0].mul_ref(&w[2]));
        let by_weights = match (d.is_zero(), disc.sign()) {
            (true, Sign::Negative) => "point",
            (true, Sign::Zero) => "double_line",
            (true, Sign::Positive) => "line_pair",
            (false, Sign::Positive) => "hyperbola",
            (false, Sign::Zero) => "parabola",
            (false, Sign::Negative) => "ellipse or circle",
        };
        if by_weights == "ellipse or circle" {
            assert!(want == "ellipse" || want == "circle", "{problem}: {want}");
        } else {
            assert_eq!(by_weights, want, "{problem}: the weight discriminant");
        }
        assert_eq!(piece["type_by_bezier"], want, "{problem}");
        // Points on the plane and on the cone; a circle's points all at one height and one
        // distance from the axis, an ellipse's not.
        let wp = Bernstein::new(w.clone());
        let mut radii = Vec::new();
        for k in 0..=12 {
            let t = Radical::from(Rational::new(k, 12).unwrap());
            let wt = wp.eval(&t);
            if wt.is_zero() {
                continue;
            }
            let x = bezier(&weighted, &t).div_scalar(&wt).unwrap();
            assert!(
                normal.dot(&x).add_ref(&d).is_zero(),
                "{problem}: off the plane at {k}/12"
            );
            assert!(on_cone(&x), "{problem}: off the cone at {k}/12");
            radii.push((x.x.square() + x.y.square(), x.z.clone()));
            checked += 1;
        }
        if want == "circle" || want == "ellipse" {
            let same = radii.windows(2).all(|p| p[0] == p[1]);
            assert_eq!(
                same,
                want == "circle",
                "{problem}: circle test on the points"
            );
        }
        // Poles: zeros (exact) or sign changes (interval) of the answered weight polynomial.
        let poles = piece["poles"].as_array().unwrap();
        let mut last = Radical::from(-1);
        for pole in poles {
            match pole_t(pole) {
                Ok(t) => {
                    assert!(Radical::zero() <= t && t <= Radical::one());
                    assert!(wp.eval(&t).is_zero(), "{problem}: exact pole {t}");
                    assert!(t > last, "{problem}: poles increasing");
                    last = t.clone();
                    if i == 0 && (t.is_zero() || t.is_one()) {
                        // V+(0) = V-(1), V+(1) = V-(0): the same direction, counted once.
                        pole_count -= 1;
                    }
                }
                Err((lo, hi)) => {
                    assert!(Radical::zero() <= lo && lo < hi && hi <= Radical::one());
                    let (s0, s1) = (wp.eval(&lo).sign(), wp.eval(&hi).sign());
                    assert!(
                        s0 != Sign::Zero && s1 != Sign::Zero && s0 != s1,
                        "{problem}: no sign change on [{lo}, {hi}]"
                    );
                    assert!(lo > last, "{problem}: poles increasing");
                    last = hi.clone();
                    let mid = lo.add_ref(&hi).to_f64() / 2.0;
                    let approx = pole["approx"].as_f64().unwrap();
                    assert!((mid - approx).abs() < 1e-12, "{problem}");
                }
            }
            pole_count += 1;
        }
    }
    assert_eq!(
        pole_count,
        directions_at_infinity(want),
        "{problem}: the number of directions at infinity"
    );
    // Planes through the apex: the rulings.
    let degenerate = &a["degenerate"];
    if d.is_zero() {
        let rulings = degenerate["rulings"].as_array().unwrap();
        let expected = match want {
            "point" => 0,
            "double_line" => 1,
            _ => 2,
        };
        assert_eq!(rulings.len(), expected, "{problem}: rulings");
        assert_eq!(vec3(&degenerate["apex"]), Vec3::zero());
        let mut on_rulings = 0;
        for ruling in rulings {
            let approx: Vec<f64> = ruling["approx"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            let cone = approx[0] * approx[0] + approx[1] * approx[1] - approx[2] * approx[2];
            assert!(
                cone.abs() < 1e-9 * approx[2] * approx[2],
                "{problem}: approx off the cone"
            );
            if ruling["direction"].is_null() {
                // sqrt(a^2 + b^2 - c^2) outside the radical field: said so, approx only.
                assert!(degenerate["note"].is_string(), "{problem}");
                on_rulings += ruling["parameters"].as_array().unwrap().len();
                continue;
            }
            let dir = vec3(&ruling["direction"]);
            let da = dir.map(Radical::to_f64);
            assert!(
                (da.x - approx[0]).abs() + (da.y - approx[1]).abs() < 1e-9 * (1.0 + da.z.abs())
            );
            assert!(
                !dir.is_zero() && on_cone(&dir),
                "{problem}: ruling not on the cone"
            );
            assert!(
                normal.dot(&dir).is_zero(),
                "{problem}: ruling not in the plane"
            );
            for p in ruling["parameters"].as_array().unwrap() {
                let i = if p["cone"] == "+" { 0 } else { 1 };
                match pole_t(p) {
                    Ok(t) => {
                        let v = bezier(&spec_cone(i), &t);
                        assert!(
                            v.cross(&dir).is_zero(),
                            "{problem}: V({t}) not on the ruling"
                        );
                    }
                    Err((lo, hi)) => {
                        let t = lo.add_ref(&hi).to_f64() / 2.0;
                        let v = bezier(
                            &spec_cone(i),
                            &Radical::from(
                                Rational::new((t * 1e12).round() as i64, 1_000_000_000_000)
                                    .unwrap(),
                            ),
                        );
                        let (v, dr) = (v.map(Radical::to_f64), dir.map(Radical::to_f64));
                        let c = [
                            v.y * dr.z - v.z * dr.y,
                            v.z * dr.x - v.x * dr.z,
                            v.x * dr.y - v.y * dr.x,
                        ];
                        let scale = (v.x * v.x + v.y * v.y + v.z * v.z).sqrt()
                            * (dr.x * dr.x + dr.y * dr.y + dr.z * dr.z).sqrt();
                        assert!(
                            c.iter().all(|x| x.abs() < 1e-9 * scale),
                            "{problem}: pole {t} not on its ruling"
                        );
                    }
                }
                on_rulings += 1;
            }
        }
        let poles: usize = pieces
            .iter()
            .map(|p| p["poles"].as_array().unwrap().len())
            .sum();
        assert_eq!(on_rulings, poles, "{problem}: every pole is on one ruling");
    } else {
        assert!(degenerate.is_null(), "{problem}");
    }
    checked
}

/// A small rational as text.
fn rational(rng: &mut Rng) -> String {
    let a = rng.below(13) as i64 - 6;
    let b = rng.below(4) + 1;
    format!("{a}/{b}")
}

/// A small number with `sqrt(2)` or `sqrt(3)`.
fn radical(rng: &mut Rng) -> String {
    let a = rng.below(9) as i64 - 4;
    let c = rng.below(5) as i64 - 2;
    let k = if rng.chance(0.5) { 2 } else { 3 };
    format!("{a}/2 + ({c})*sqrt({k})")
}

fn triple(v: [String; 3]) -> String {
    format!("[\"{}\",\"{}\",\"{}\"]", v[0], v[1], v[2])
}

/// A random plane of family `i % 8` (module doc), as a problem.
fn random_problem(rng: &mut Rng, i: usize) -> String {
    let point = |rng: &mut Rng| triple([rational(rng), rational(rng), rational(rng)]);
    let normal_point =
        |n: String, p: String| format!(r#"{{"kind":"conic","normal":{n},"point":{p}}}"#);
    match i % 8 {
        0 => normal_point(
            triple([rational(rng), rational(rng), rational(rng)]),
            point(rng),
        ),
        1 => {
            // c^2 = a^2 + b^2 from Pythagorean triples, signs and a scale
            let triples = [
                (3, 4, 5),
                (1, 0, 1),
                (0, 1, 1),
                (5, 12, 13),
                (8, 15, 17),
                (4, 3, 5),
            ];
            let (a, b, c) = triples[rng.below(triples.len() as u64) as usize];
            let k = rng.below(3) as i64 + 1;
            let s = |rng: &mut Rng| if rng.chance(0.5) { 1 } else { -1 };
            let n = [a * k * s(rng), b * k * s(rng), c * k * s(rng)].map(|x| x.to_string());
            normal_point(triple(n), point(rng))
        }
        2 => {
            let c = rng.below(7) as i64 - 3;
            normal_point(
                triple(["0".into(), "0".into(), format!("{c}/2")]),
                point(rng),
            )
        }
        3 => {
            let n = triple([rational(rng), rational(rng), rational(rng)]);
            if rng.chance(0.5) {
                normal_point(n, triple(["0".into(), "0".into(), "0".into()]))
            } else {
                let n: Vec<Value> = serde_json::from_str::<Vec<Value>>(&n).unwrap();
                format!(
                    r#"{{"kind":"conic","plane":[{},{},{},0]}}"#,
                    n[0], n[1], n[2]
                )
            }
        }
        4 => {
            let (a, b) = (rational(rng), rational(rng));
            let c = format!("-({a}) - ({b})");
            normal_point(triple([a, b, c]), point(rng))
        }
        5 => normal_point(
            triple([radical(rng), radical(rng), radical(rng)]),
            triple([radical(rng), rational(rng), radical(rng)]),
        ),
        6 => format!(
            r#"{{"kind":"conic","plane":["{}","{}","{}","{}"]}}"#,
            rational(rng),
            rational(rng),
            rational(rng),
            rational(rng)
        ),
        _ => {
            // parabolas and double lines with radical normals: c^2 = a^2 + b^2
            let (a, b, c) = [
                ("1", "1", "sqrt(2)"),
                ("1", "sqrt(3)", "-2"),
                ("sqrt(2)", "sqrt(2)", "2"),
            ][rng.below(3) as usize];
            let p = if rng.chance(0.25) {
                triple(["0".into(), "0".into(), "0".into()])
            } else {
                point(rng)
            };
            normal_point(triple([a.into(), b.into(), c.into()]), p)
        }
    }
}

#[test]
fn random_planes_give_points_on_plane_and_cone_and_the_same_type_both_ways() {
    let mut rng = Rng::new(0xC0_41C5);
    let mut answered = 0;
    let mut refused_zero = 0;
    let mut points = 0;
    let mut types = std::collections::BTreeMap::new();
    for i in 0..560 {
        let p = random_problem(&mut rng, i);
        match solve(&p, Mode::Exact) {
            Ok(a) => {
                points += check(&p, &a);
                *types
                    .entry(a["type"].as_str().unwrap().to_string())
                    .or_insert(0) += 1;
                answered += 1;
            }
            Err(e) => {
                let e = e.to_string();
                assert!(
                    e.starts_with("normal: the zero vector")
                        || e.starts_with("plane: the normal (a, b, c) is the zero vector"),
                    "{p}: {e}"
                );
                assert_eq!(e.lines().count(), 1);
                refused_zero += 1;
            }
        }
    }
    assert!(
        answered >= 500,
        "{answered} answered, {refused_zero} zero normals"
    );
    assert!(points >= 500 * 13, "{points}");
    // Every type occurs, so each branch of both rules was exercised.
    for t in [
        "circle",
        "ellipse",
        "parabola",
        "hyperbola",
        "point",
        "double_line",
        "line_pair",
    ] {
        assert!(types.get(t).copied().unwrap_or(0) >= 3, "{t}: {types:?}");
    }
}

#[test]
fn table1_columns_are_reproduced() {
    // the claim list Table 1 (square roots restored): the + weights and the C- poles.
    let cases = [
        ("[0,0,1]", "circle", ["1", "1/sqrt(2)", "1"], 0),
        ("[1,1,3]", "ellipse", ["4", "5/sqrt(2)", "4"], 0),
        (
            "[1,1,\"sqrt(2)\"]",
            "parabola",
            ["1+sqrt(2)", "1+sqrt(2)", "1+sqrt(2)"],
            1,
        ),
        ("[1,1,0]", "hyperbola", ["1", "sqrt(2)", "1"], 2),
    ];
    for (normal, ty, w, minus_poles) in cases {
        let p = format!(r#"{{"kind":"conic","normal":{normal},"point":[1,1,1]}}"#);
        let a = solve(&p, Mode::Exact).unwrap();
        check(&p, &a);
        assert_eq!(a["type"], ty);
        assert_eq!(
            radicals(&a["pieces"][0]["weights"]),
            w.map(r).to_vec(),
            "{ty}"
        );
        assert!(a["pieces"][0]["poles"].as_array().unwrap().is_empty());
        assert_eq!(
            a["pieces"][1]["poles"].as_array().unwrap().len(),
            minus_poles
        );
    }
    // The parabola's pole is t = 1/2 exactly (a double zero); the hyperbola's are isolated
    // around 1 - 1/sqrt 2 and 1/sqrt 2.
    let a = solve(
        r#"{"kind":"conic","normal":[1,1,"sqrt(2)"],"point":[1,1,1]}"#,
        Mode::Exact,
    )
    .unwrap();
    assert_eq!(a["pieces"][1]["poles"][0]["t"], "1/2");
    assert_eq!(a["pieces"][1]["poles"][0]["multiplicity"], 2);
    let a = solve(
        r#"{"kind":"conic","normal":[1,1,0],"point":[1,1,1]}"#,
        Mode::Exact,
    )
    .unwrap();
    for (pole, want) in a["pieces"][1]["poles"]
        .as_array()
        .unwrap()
        .iter()
        .zip(["1 - 1/sqrt(2)", "1/sqrt(2)"])
    {
        let (lo, hi) = pole_t(pole).unwrap_err();
        let want = r(want);
        assert!(lo < want && want < hi, "{pole}");
    }
}

#[test]
fn float_mode_runs_the_same_code_and_says_the_type_is_rounded() {
    let mut rng = Rng::new(7);
    for i in 0..40 {
        let p = random_problem(&mut rng, i);
        let o = solve_stdin(p.as_bytes(), &["--float"]);
        if o.status.code() == Some(2) {
            let err = String::from_utf8_lossy(&o.stderr);
            assert!(err.contains("zero vector"), "{p}: {err}");
            continue;
        }
        assert!(
            o.status.success(),
            "{p}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let a: Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(a["mode"], "float");
        assert!(a["type_note"].as_str().unwrap().contains("f64-rounded"));
        let exact = solve(&p, Mode::Exact).unwrap();
        // Away from the boundary cases the float type is the exact one.
        if ["ellipse", "hyperbola"].contains(&exact["type"].as_str().unwrap()) {
            assert_eq!(a["type"], exact["type"], "{p}");
        }
        for (fp, ep) in a["pieces"]
            .as_array()
            .unwrap()
            .iter()
            .zip(exact["pieces"].as_array().unwrap())
        {
            for (fw, ew) in fp["weights"]
                .as_array()
                .unwrap()
                .iter()
                .zip(radicals(&ep["weights"]))
            {
                assert!(
                    (fw.as_f64().unwrap() - ew.to_f64()).abs() <= 1e-12 * (1.0 + ew.to_f64().abs())
                );
            }
        }
    }
    // The parabola of Table 1 in f64: the rules disagree on rounded values; no type is picked.
    let o = solve_stdin(
        br#"{"kind":"conic","normal":[1,1,"sqrt(2)"],"point":[1,1,1]}"#,
        &["--float"],
    );
    let a: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(a["type"].is_null(), "{a}");
    assert!(a["type_note"].as_str().unwrap().contains("disagree"));
    // --both attaches the float answer to the exact one.
    let o = solve_stdin(br#"{"kind":"conic","plane":[1,1,3,-5]}"#, &["--both"]);
    let a: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(a["mode"], "exact");
    assert_eq!(a["float"]["mode"], "float");
    assert_eq!(a["float"]["type"], "ellipse");
}

#[test]
fn degenerate_and_malformed_input_is_one_line_naming_the_field() {
    refused(
        r#"{"kind":"conic","normal":[0,0,0],"point":[1,2,3]}"#,
        &[],
        &["normal", "zero vector"],
    );
    refused(
        r#"{"kind":"conic","normal":["sqrt(2)-sqrt(2)",0,0],"point":[1,2,3]}"#,
        &[],
        &["normal", "zero vector"],
    );
    refused(
        r#"{"kind":"conic","plane":[0,0,0,1]}"#,
        &[],
        &["plane", "zero vector"],
    );
    refused(
        r#"{"kind":"conic","normal":[0,0,0],"point":[1,2,3]}"#,
        &["--float"],
        &["normal", "zero vector"],
    );
    refused(
        r#"{"kind":"conic","normal":[0,0,1]}"#,
        &[],
        &["point: missing"],
    );
    refused(
        r#"{"kind":"conic","point":[0,0,1]}"#,
        &[],
        &["normal: missing"],
    );
    refused(r#"{"kind":"conic"}"#, &[], &["missing the plane"]);
    refused(
        r#"{"kind":"conic","normal":[0,0,1],"point":[1,1,1],"plane":[0,0,1,-1]}"#,
        &[],
        &["plane", "not both"],
    );
    refused(r#"{"kind":"conic","plane":[0,0,1]}"#, &[], &["plane", "4"]);
    refused(
        r#"{"kind":"conic","normal":[0,0,1,2],"point":[1,1,1]}"#,
        &[],
        &["normal", "3"],
    );
    refused(
        r#"{"kind":"conic","normal":[0,0,0.5],"point":[1,1,1]}"#,
        &[],
        &["normal[2]"],
    );
    refused(
        r#"{"kind":"conic","normal":[0,0,"1/0"],"point":[1,1,1]}"#,
        &[],
        &["normal[2]"],
    );
    refused(
        r#"{"kind":"conic","normal":[0,0,1],"point":[1,1,1],"cone":2}"#,
        &[],
        &["unknown field `cone`"],
    );
    refused(
        r#"{"kind":"conic","plane":[1,1,0,-2],"precision":0}"#,
        &[],
        &["precision"],
    );
    refused(
        r#"{"kind":"conic","plane":[1,1,0,"1e400"]}"#,
        &["--float"],
        &["plane[3]"],
    );
    // Planes through the apex are named outcomes, not errors.
    for (plane, ty) in [
        ("[0,0,1,0]", "point"),
        ("[3,4,5,0]", "double_line"),
        ("[1,1,0,0]", "line_pair"),
    ] {
        let p = format!(r#"{{"kind":"conic","plane":{plane}}}"#);
        let a = solve(&p, Mode::Exact).unwrap();
        assert_eq!(a["type"], ty);
        check(&p, &a);
    }
}
