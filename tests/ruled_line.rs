//! `solve` kind `ruled_line`: random exact lines built through known surface points (rational
//! and radical coordinates, several (m, n)) are answered with points that lie on both, checked
//! by exact substitution; the degenerate outcomes are typed; bad input is one line naming the
//! field, exit status 2.

use exactcheck::solve::{solve, Mode};
use exactcheck_core::ruled::RuledSurface;
use exactcheck_core::{Ring, Rng, Vec3};
use exactcheck_exact::Radical;
use serde_json::Value;
use std::path::Path;
mod common;

fn rad(s: &str) -> Radical {
    s.parse().unwrap_or_else(|e| panic!("{s}: {e}"))
}

fn json_rad(v: &Value) -> Radical {
    rad(v.as_str().expect("an exact number as a string"))
}

/// A small rational, or with `radical`, sometimes `a + b sqrt(k)`.
fn number(rng: &mut Rng, radical: bool) -> String {
    let a = rng.below(13) as i64 - 6;
    let d = rng.below(4) as i64 + 1;
    if radical && rng.chance(0.4) {
        let b = rng.below(5) as i64 - 2;
        let k = [2, 3, 6][rng.below(3) as usize];
        format!("{a}/{d} + ({b})*sqrt({k})")
    } else {
        format!("{a}/{d}")
    }
}

fn coords(v: &Vec3<String>) -> String {
    format!("[\"{}\",\"{}\",\"{}\"]", v.x, v.y, v.z)
}

fn show(v: &Vec3<Radical>) -> Vec3<String> {
    v.map(ToString::to_string)
}

struct Instance {
    problem: String,
    surface: RuledSurface<Radical>,
    point: Vec3<Radical>,
    direction: Vec3<Radical>,
    /// The parameters of the chosen surface points on the line.
    known: Vec<Radical>,
}

fn instance(rng: &mut Rng, m: usize, n: usize, radical: bool) -> Option<Instance> {
    let vec = |rng: &mut Rng| {
        Vec3::new(
            number(rng, radical),
            number(rng, radical),
            number(rng, radical),
        )
    };
    let base: Vec<Vec3<String>> = (0..=n).map(|_| vec(rng)).collect();
    let dirs: Vec<Vec3<String>> = (0..=m).map(|_| vec(rng)).collect();
    let surface = RuledSurface::from_control(
        base.iter().map(|p| p.map(|x| rad(x))).collect(),
        dirs.iter().map(|p| p.map(|x| rad(x))).collect(),
    )
    .unwrap();
    let t1 = rad(&format!("{}/{}", rng.below(13), 12));
    let t2 = rad(&format!("{}/{}", rng.below(11), 10));
    let s1 = rad(&number(rng, false));
    let s2 = rad(&number(rng, false));
    let x1 = surface.eval(&s1, &t1);
    let x2 = surface.eval(&s2, &t2);
    let direction = x2.add_scaled(&Radical::from_i64(-1), &x1);
    if direction.is_zero() {
        return None;
    }
    let point = x1.add_scaled(&Radical::from_i64(-2), &direction);
    let problem = format!(
        r#"{{"kind":"ruled_line","base":[{}],"directions":[{}],"line":{{"point":{},"direction":{}}}}}"#,
        base.iter().map(coords).collect::<Vec<_>>().join(","),
        dirs.iter().map(coords).collect::<Vec<_>>().join(","),
        coords(&show(&point)),
        coords(&show(&direction)),
    );
    Some(Instance {
        problem,
        surface,
        point,
        direction,
        known: vec![t1, t2],
    })
}

/// Checks one answer: the known parameters are among the roots; every exact point lies on the
/// surface at its (t, s) and on the line at its lambda, exactly. Returns the number of exact
/// points checked.
fn check(inst: &Instance, a: &Value) -> usize {
    assert_eq!(a["kind"], "ruled_line");
    let (m, n) = inst.surface.degrees();
    assert_eq!(a["degree"], m + n);
    if a["outcome"] != "points" && a["outcome"] != "no_points" {
        // The line on the surface, or parallel to every ruling: no finite root list.
        return 0;
    }
    let roots = a["points"].as_array().unwrap();
    for t in &inst.known {
        let found = roots
            .iter()
            .any(|r| match (&r["t"]["value"], &r["t"]["interval"]) {
                (Value::String(v), _) => rad(v) == *t,
                (_, Value::Array(iv)) => json_rad(&iv[0]) <= *t && *t <= json_rad(&iv[1]),
                _ => panic!("a root without value or interval: {r}"),
            });
        assert!(found, "t = {t} not found in {a}\n{}", inst.problem);
    }
    let mut exact = 0;
    for r in roots {
        if r["status"] != "point" || r["exact"] != true {
            continue;
        }
        let t = json_rad(&r["t"]["value"]);
        let s = json_rad(&r["s"]);
        let lambda = json_rad(&r["lambda"]);
        let p = &r["point"];
        let x = Vec3::new(json_rad(&p[0]), json_rad(&p[1]), json_rad(&p[2]));
        assert_eq!(inst.surface.eval(&s, &t), x, "{}", inst.problem);
        assert_eq!(
            inst.point.add_scaled(&lambda, &inst.direction),
            x,
            "{}",
            inst.problem
        );
        exact += 1;
    }
    exact
}

#[test]
fn random_lines_through_surface_points() {
    let mut rng = Rng::new(0x9ed1);
    let shapes = [(0, 1), (1, 1), (1, 2), (2, 2), (0, 3), (3, 1), (2, 4)];
    let (mut instances, mut radical_instances, mut exact_points) = (0, 0, 0);
    while instances < 120 {
        let (m, n) = shapes[instances % shapes.len()];
        let radical = instances % 3 == 2;
        let Some(inst) = instance(&mut rng, m, n, radical) else {
            continue;
        };
        let a =
            solve(&inst.problem, Mode::Exact).unwrap_or_else(|e| panic!("{}: {e}", inst.problem));
        exact_points += check(&inst, &a);
        instances += 1;
        radical_instances += usize::from(radical);
    }
    assert!(radical_instances >= 40);
    // Rational instances have their chosen parameters as exact roots (two per instance,
    // fewer when t1 = t2).
    assert!(exact_points >= 140, "{exact_points}");
}

fn answer(problem: &str) -> Value {
    solve(problem, Mode::Exact).unwrap_or_else(|e| panic!("{problem}: {e}"))
}

#[test]
fn degenerate_outcomes_are_typed() {
    // The plane z = 0 (B = (t,0,0), V = (0,1,0)) and a line in it, across the rulings.
    let plane = r#""base":[[0,0,0],[1,0,0]],"directions":[[0,1,0]]"#;
    let a = answer(&format!(
        r#"{{"kind":"ruled_line",{plane},"line":{{"point":[0,0,0],"direction":[1,1,0]}}}}"#
    ));
    assert_eq!(a["outcome"], "line_on_surface");
    assert_eq!(a["lambda_at_ends"], serde_json::json!(["0", "1"]));
    // A line parallel to the rulings in the plane: it is the ruling t = 1/2.
    let a = answer(&format!(
        r#"{{"kind":"ruled_line",{plane},"line":{{"point":["1/2",0,0],"direction":[0,1,0]}}}}"#
    ));
    assert_eq!(a["outcome"], "parallel_to_every_ruling");
    assert_eq!(a["rulings_on_line"][0]["value"], "1/2");
    // Parallel to the rulings, above the plane: no ruling is the line.
    let a = answer(&format!(
        r#"{{"kind":"ruled_line",{plane},"line":{{"point":[0,0,1],"direction":[0,1,0]}}}}"#
    ));
    assert_eq!(a["outcome"], "parallel_to_every_ruling");
    assert_eq!(a["rulings_on_line"], serde_json::json!([]));
    // The root t = 0 of det = -t is a ruling parallel to the line: no point, no division.
    let a = answer(
        r#"{"kind":"ruled_line","base":[[0,0,1]],"directions":[[1,0,0],[0,1,0]],"line":{"point":[0,0,0],"direction":[1,0,0]}}"#,
    );
    assert_eq!(a["outcome"], "no_points");
    assert_eq!(a["points"][0]["status"], "ruling_parallel");
    assert_eq!(a["points"][0]["point"], Value::Null);
    // V(0) = 0: the ruling is the point B(0) = (1,0,0), off the y axis.
    let a = answer(
        r#"{"kind":"ruled_line","base":[[1,0,0]],"directions":[[0,0,0],[1,1,1]],"line":{"point":[0,0,0],"direction":[0,1,0]}}"#,
    );
    assert_eq!(a["points"][0]["status"], "degenerate_ruling_off_line");
}

#[test]
fn an_irrational_root_is_an_interval_with_approximations() {
    // det = t^2 - 1/2 up to a factor: the root 1/sqrt(2) is isolated, refined to 2^-60.
    let a = answer(
        r#"{"kind":"ruled_line","base":[[0,"-1/2",0],[0,"-1/2",0],[0,"1/2",0]],"directions":[[0,0,1]],"line":{"point":[0,0,0],"direction":[1,0,0]}}"#,
    );
    let r = &a["points"][0];
    assert_eq!(r["exact"], false);
    let iv = &r["t"]["interval"];
    let (lo, hi) = (json_rad(&iv[0]), json_rad(&iv[1]));
    let root = rad("1/sqrt(2)");
    assert!(lo < root && root < hi);
    assert!(hi - lo <= rad("2^-60"));
    assert!((r["approx"]["point"][1].as_f64().unwrap()).abs() < 1e-15);
}

#[test]
fn float_mode_finds_the_same_parameter() {
    let p = r#"{"kind":"ruled_line","base":[[0,0,0],[1,0,0],[2,1,0]],"directions":[[0,0,1],[0,1,1]],"line":{"point":[0,0,0.5],"direction":[1,0,0]}}"#;
    let a = solve(p, Mode::Float).unwrap();
    assert_eq!(a["mode"], "float");
    assert_eq!(a["points"][0]["t"]["value"], 0.0);
    assert_eq!(a["points"][0]["s"], 0.5);
}

/// Exit status 2 and one line on stderr naming the field.
fn refused(problem: &str, needles: &[&str]) {
    common::refused(problem, &[], needles);
}

#[test]
fn bad_input_is_one_line_naming_the_field() {
    let line = r#""line":{"point":[0,0,0],"direction":[1,0,0]}"#;
    refused(
        r#"{"kind":"ruled_line","base":[[0,0,0]],"directions":[[0,0,1]],"line":{"point":[0,0,0],"direction":[0,0,0]}}"#,
        &["line.direction", "zero"],
    );
    refused(
        &format!(r#"{{"kind":"ruled_line","base":[[0,0,0],[1,0]],"directions":[[0,0,1]],{line}}}"#),
        &["base[1]", "expected 3 coordinates, found 2"],
    );
    refused(
        &format!(r#"{{"kind":"ruled_line","base":[],"directions":[[0,0,1]],{line}}}"#),
        &["base", "at least one"],
    );
    refused(
        &format!(r#"{{"kind":"ruled_line","base":[[0,0,0]],"directions":[],{line}}}"#),
        &["directions", "at least one"],
    );
    refused(
        &format!(r#"{{"kind":"ruled_line","base":[[0,0,0]],"directions":[[0,0,0]],{line}}}"#),
        &["directions", "every control vector is zero"],
    );
    let many = vec!["[0,0,1]"; 62].join(",");
    refused(
        &format!(r#"{{"kind":"ruled_line","base":[[0,0,0]],"directions":[{many}],{line}}}"#),
        &["directions", "exceeds the limit 60"],
    );
    refused(
        &format!(r#"{{"kind":"ruled_line","base":[[0.5,0,0]],"directions":[[0,0,1]],{line}}}"#),
        &["base[0][0]", "floating-point"],
    );
}

/// The committed example answer (tests/solve_golden/ruled_line_two_points.*), also in the README.
#[test]
fn golden_answer_is_unchanged() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/solve_golden");
    let problem = std::fs::read_to_string(dir.join("ruled_line_two_points.json")).unwrap();
    let want: Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("ruled_line_two_points.exact.expected")).unwrap(),
    )
    .unwrap();
    assert_eq!(answer(&problem), want);
}

#[test]
fn a_high_degree_over_square_roots_is_refused_before_the_work() {
    // m + n = 60 with square roots ran past 150 s and 1.1 GB; over Q it ran past a minute.
    let line = r#""line":{"point":["1/3",0,0],"direction":[1,2,3]}"#;
    let point = |i: usize| format!("[{},{},{}]", i % 5, (i * 3) % 7, (i * 5) % 11);
    let base: Vec<String> = (0..31).map(point).collect();
    let mut dirs: Vec<String> = (0..30).map(|i| point(i + 40)).collect();
    let problem = |dirs: &[String]| {
        format!(
            r#"{{"kind":"ruled_line","base":[{}],"directions":[{}],{line}}}"#,
            base.join(","),
            dirs.join(",")
        )
    };
    dirs[0] = r#"["sqrt(2)",1,1]"#.into();
    refused(
        &problem(&dirs),
        &[
            "m + n = 59 with 1 independent square roots",
            "exceeds the limit ruled-work = 32",
        ],
    );
    dirs[0] = "[1,1,1]".into();
    refused(
        &problem(&dirs),
        &["m + n = 59 with 0 independent", "ruled-work = 32"],
    );
}
