//! `exactcheck solve` end to end: the JSON answers of the existing kinds stay what they were
//! before the contract became types (golden files), and every class of bad input is one line
//! naming the field, exit status 2.

use crate::common;
use std::path::{Path, PathBuf};

use common::golden::blessing;
use common::refused;
use common::solve_stdin as solve;

fn golden_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/solve_golden")
}

/// The committed answers (tests/solve_golden/NAME.MODE.out) are reproduced field for field, in
/// the same order; `EXACTCHECK_BLESS=1` rewrites them from this run.
#[test]
fn answers_of_the_existing_kinds_are_unchanged() {
    let mut checked = 0;
    let mut entries: Vec<_> = std::fs::read_dir(golden_dir())
        .expect("golden dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "out"))
        .collect();
    entries.sort();
    for out in entries {
        let stem = out.file_stem().unwrap().to_string_lossy().into_owned();
        let (name, mode) = stem.rsplit_once('.').expect("NAME.MODE.out");
        let problem = std::fs::read(golden_dir().join(format!("{name}.json"))).expect("input");
        let flag = match mode {
            "exact" => vec![],
            "float" => vec!["--float"],
            "both" => vec!["--both"],
            other => panic!("unknown mode {other}"),
        };
        let o = solve(&problem, &flag);
        assert!(
            o.status.success(),
            "{stem}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let got: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON answer");
        if blessing() {
            std::fs::write(&out, &o.stdout).expect("bless the golden answer");
        }
        let want: serde_json::Value =
            serde_json::from_slice(&std::fs::read(&out).expect("golden")).expect("golden JSON");
        assert_eq!(
            got.as_object()
                .map(|o| o.keys().cloned().collect::<Vec<_>>()),
            want.as_object()
                .map(|o| o.keys().cloned().collect::<Vec<_>>()),
            "{stem}: field order"
        );
        assert_eq!(got, want, "{stem}");
        checked += 1;
    }
    assert_eq!(checked, 43, "every golden answer was compared");
}

fn cylinder_sphere(beta: &str, center: &str, radius: &str, extra: &str) -> String {
    format!(
        r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":5,"beta":{beta},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":{center},"radius":{radius}}}{extra}}}"#
    )
}

const ZERO: &str = r#"{"cos":1,"sin":0}"#;

fn answer(problem: &str, extra: &[&str]) -> serde_json::Value {
    let o = solve(problem.as_bytes(), extra);
    assert!(
        o.status.success(),
        "{problem}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).expect("JSON answer")
}

#[test]
fn unknown_and_repeated_fields_are_refused_by_name() {
    // a misspelt field was silently ignored.
    refused(
        &cylinder_sphere(ZERO, "[1,0,0]", "7", r#","sampels":8"#),
        &[],
        &["unknown field `sampels`"],
    );
    refused(
        &cylinder_sphere(r#"{"cos":1,"sin":0,"deg":0}"#, "[1,0,0]", "7", ""),
        &[],
        &["cylinder.beta", "unknown field `deg`"],
    );
    refused(
        &cylinder_sphere(ZERO, "[1,0,0]", "7", r#","samples":8,"samples":9"#),
        &[],
        &["duplicate field `samples`"],
    );
    refused(
        r#"{"kind":"sphere_interpolation","points":[[1,0,0]],"params":[0],"weights":[1]}"#,
        &[],
        &["unknown field `weights`"],
    );
}

#[test]
fn conflicting_angle_keys_are_refused() {
    // {cos, sin, radians} together was accepted (radians won silently).
    for mode in [&[][..], &["--float"][..]] {
        refused(
            &cylinder_sphere(r#"{"cos":1,"sin":0,"radians":1}"#, "[1,0,0]", "7", ""),
            mode,
            &["cylinder.beta", "not both"],
        );
    }
    refused(
        &cylinder_sphere(r#"{"sin":0}"#, "[1,0,0]", "7", ""),
        &[],
        &["cylinder.beta.cos"],
    );
}

#[test]
fn big_json_integers_are_read_exactly() {
    // 10^23 was called a floating-point literal, a 400-digit integer "out of range".
    let big = format!("1{}", "0".repeat(23));
    let a = answer(
        &cylinder_sphere(ZERO, &format!("[{big},0,0]"), &big, ""),
        &[],
    );
    // delta = 10^23 = R: the centre is at distance R from the axis, r = 5 < R: crossing.
    assert_eq!(a["contact"], "crossing");
    assert_eq!(a["methods_agree"], true);
    let huge = format!("1{}", "0".repeat(400));
    let a = answer(
        &cylinder_sphere(ZERO, &format!("[{huge},0,0]"), "7", ""),
        &[],
    );
    assert_eq!(a["contact"], "disjoint");
    assert_eq!(a["contact_by_axis_distance"], "disjoint");
    // A radius one more than the distance minus r: exactly tangent from outside.
    let delta_minus_r = format!("{}5", "9".repeat(399));
    let a = answer(
        &cylinder_sphere(ZERO, &format!("[{huge},0,0]"), &delta_minus_r, ""),
        &[],
    );
    assert_eq!(a["contact"], "tangent");
    assert_eq!(a["tangent_points"][0]["point"][0], "5");
}

#[test]
fn a_byte_order_mark_is_skipped() {
    let plain = cylinder_sphere(ZERO, "[8,0,3]", "3", "");
    let with_bom = format!("\u{feff}{plain}");
    assert_eq!(answer(&with_bom, &[]), answer(&plain, &[]));
}

/// The suggested exact string in a float-literal refusal.
fn suggestion(err: &str) -> String {
    let start = err.find("as a string, \"").expect("a suggestion") + "as a string, \"".len();
    err[start..].split('"').next().unwrap().to_string()
}

#[test]
fn float_literals_are_refused_with_a_suggestion_that_parses() {
    for (literal, field) in [
        ("5.5", "sphere.radius"),
        ("1e+23", "sphere.radius"),
        ("2.5e-3", "sphere.radius"),
    ] {
        let problem = cylinder_sphere(ZERO, "[1,0,0]", literal, "");
        let err = refused(&problem, &[], &[field, literal, "--float"]);
        let s = suggestion(&err);
        assert!(s.parse::<exactcheck_exact::Radical>().is_ok(), "{s} parses");
        // Fed back, the suggestion is accepted and means the written decimal.
        let fixed = cylinder_sphere(ZERO, "[1,0,0]", &format!("\"{s}\""), "");
        answer(&fixed, &[]);
    }
    assert_eq!(
        suggestion(&refused(
            &cylinder_sphere(ZERO, "[1,0,0]", "1e+23", ""),
            &[],
            &[]
        )),
        "100000000000000000000000"
    );
    refused(
        r#"{"kind":"sphere_interpolation","points":[[0.6,0.8,0]],"params":[0]}"#,
        &[],
        &["points[0][0]", "\"0.6\""],
    );
}

#[test]
fn float_mode_refuses_non_finite_values() {
    // these printed null coefficients and a confident verdict, exit 0.
    refused(
        &cylinder_sphere(r#"{"radians":"10^400"}"#, "[1,0,0]", "7", ""),
        &["--float"],
        &["cylinder.beta.radians", "not a finite f64"],
    );
    refused(
        &cylinder_sphere(ZERO, "[1,0,0]", r#""10^400""#, ""),
        &["--float"],
        &["sphere.radius", "not a finite f64"],
    );
    refused(
        &cylinder_sphere(ZERO, "[1e400,0,0]", "7", ""),
        &["--float"],
        &["sphere.center[0]", "not a finite f64"],
    );
    // Finite input whose coefficients overflow.
    refused(
        &cylinder_sphere(ZERO, "[1,0,0]", "1e300", ""),
        &["--float"],
        &["overflow"],
    );
    // And --both refuses them too.
    refused(
        &cylinder_sphere(ZERO, "[1,0,0]", r#""10^400""#, ""),
        &["--both"],
        &["sphere.radius", "not a finite f64"],
    );
}

#[test]
fn errors_name_the_field_path() {
    refused(
        &cylinder_sphere(r#"{"cos":"1/0","sin":0}"#, "[1,0,0]", "7", ""),
        &[],
        &["cylinder.beta.cos"],
    );
    refused(
        &cylinder_sphere(ZERO, "[1,0,true]", "7", ""),
        &[],
        &["sphere.center[2]", "boolean"],
    );
    refused(
        &cylinder_sphere(ZERO, "[1,0,0]", "7", r#","samples":"many""#),
        &[],
        &["samples"],
    );
    refused(
        r#"{"kind":"cylinder_sphere"}"#,
        &[],
        &["missing field `cylinder`"],
    );
    refused(r#"[1,2]"#, &[], &["must be a JSON object"]);
}

#[test]
fn on_the_axis_with_equal_radii_the_surfaces_touch_along_a_circle() {
    // The reported example: the old answer was contact_by_axis_distance "crossing",
    // methods_agree false, and no touching reported.
    let a = answer(
        r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0,0],"radius":5,"beta":{"cos":1,"sin":0},"gamma":{"cos":1,"sin":0}},"sphere":{"center":[0,0,3],"radius":5}}"#,
        &[],
    );
    assert_eq!(a["contact"], "tangent");
    assert_ne!(a["contact_by_axis_distance"], "crossing");
    assert_eq!(a["contact_by_axis_distance"], "tangent");
    assert_eq!(a["methods_agree"], true);
    let c = &a["tangent_circle"];
    assert_eq!(c["center"], serde_json::json!(["0", "0", "3"]));
    assert_eq!(c["radius"], "5");
    assert_eq!(c["normal"], serde_json::json!(["0", "0", "1"]));
    assert_eq!(c["u"], "3");
    assert_eq!(c["on_both_surfaces"], true);
    assert_eq!(a["tangent_points"], serde_json::json!([]));
}

#[test]
fn the_figure_eight_reports_its_touching_point() {
    // centre (2,0,0), R = 7 = r + delta; tangent_points was empty.
    let a = answer(&cylinder_sphere(ZERO, "[2,0,0]", "7", ""), &[]);
    assert_eq!(a["contact"], "crossing");
    assert_eq!(a["methods_agree"], true);
    assert_eq!(a["components"], 1);
    let tp = a["tangent_points"].as_array().unwrap();
    assert_eq!(tp.len(), 1);
    assert_eq!(tp[0]["point"], serde_json::json!(["-5", "0", "0"]));
    assert_eq!(tp[0]["on_both_surfaces"], true);
    assert!(a["tangent_circle"].is_null());
}

/// Every `unit_direction` of a committed `plane_plane` answer reads back through the exact
/// parser as the unit vector it claims to be: its coordinates, parsed alone, are near the
/// printed approximations, their squares sum to exactly 1, and it is exactly parallel to the
/// printed `direction`.
#[test]
fn printed_unit_directions_parse_back_to_the_unit_vector() {
    use exactcheck_exact::Algebraic;
    let value = |text: &str| -> Algebraic {
        text.parse()
            .unwrap_or_else(|e| panic!("{text:?} does not parse back: {e}"))
    };
    let mut checked = 0;
    for entry in std::fs::read_dir(golden_dir()).expect("golden dir") {
        let path = entry.expect("entry").path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if !(name.starts_with("plane_plane") && name.ends_with(".out")) {
            continue;
        }
        let answer: serde_json::Value =
            serde_json::from_slice(&std::fs::read(&path).expect("golden")).expect("JSON");
        // Exact answers only (a `--float` answer prints numbers).
        let Some(unit) = answer["unit_direction"]
            .as_array()
            .filter(|u| u.iter().all(serde_json::Value::is_string))
        else {
            continue;
        };
        let u: Vec<&str> = unit.iter().map(|x| x.as_str().expect("text")).collect();
        // One generator at most: with two (a field of degree 12 under the square root) the
        // exact parse takes minutes; the printer is the same for every field.
        let generators: std::collections::HashSet<&str> = u
            .iter()
            .flat_map(|t| t.match_indices("cos(").map(|(i, _)| &t[i..]))
            .map(|rest| &rest[..rest.find(')').map_or(rest.len(), |j| j + 1)])
            .collect();
        if generators.len() > 1 {
            continue;
        }
        let d: Vec<&str> = answer["direction"]
            .as_array()
            .expect("a direction")
            .iter()
            .map(|x| x.as_str().expect("text"))
            .collect();
        for (i, text) in u.iter().enumerate() {
            let (lo, hi) = value(text).enclosure(64);
            let approx = answer["approx"]["unit_direction"][i]
                .as_f64()
                .expect("an approximation");
            let mid = (lo.to_f64() + hi.to_f64()) / 2.0;
            assert!(
                (mid - approx).abs() < 1e-12,
                "{name}: {text} = {mid}, not {approx}"
            );
        }
        let norm = format!("({})^2 + ({})^2 + ({})^2", u[0], u[1], u[2]);
        assert_eq!(value(&norm), value("1"), "{name}: |{u:?}| != 1");
        for (i, j) in [(0, 1), (1, 2), (0, 2)] {
            let cross = format!("({})*({}) - ({})*({})", u[i], d[j], u[j], d[i]);
            assert_eq!(value(&cross), value("0"), "{name}: {u:?} not along {d:?}");
        }
        checked += 1;
    }
    assert!(
        checked >= 4,
        "only {checked} plane_plane answers with a unit direction"
    );
}

/// `docs/schema/<kind>.json` is what the types generate (regenerate with
/// `EXACTCHECK_BLESS=1 cargo test --release --test solve solve::`); every kind of `solve` has one.
#[test]
fn committed_schemas_are_current() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/schema");
    let mut n = 0;
    for k in exactcheck::solve::kinds() {
        let path = dir.join(format!("{}.json", k.name));
        let want = exactcheck::solve::schema(k.name).expect("a schema");
        let schema: serde_json::Value = serde_json::from_str(&want).unwrap();
        assert_eq!(schema["title"], k.name);
        assert_eq!(schema["properties"]["kind"]["const"], k.name);
        assert_eq!(schema["additionalProperties"], false);
        if blessing() {
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(&path, &want).unwrap();
        }
        let have = std::fs::read_to_string(&path).unwrap_or_default();
        assert_eq!(
            have,
            want,
            "{} is stale: run EXACTCHECK_BLESS=1 cargo test --release --test solve solve::",
            path.display()
        );
        n += 1;
    }
    assert_eq!(n, exactcheck::solve::kinds().len());
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        n,
        "a schema file for every kind and no other"
    );
}

/// `solve --schema KIND` prints the committed schema file; an unknown kind is a one-line error.
#[test]
fn solve_schema_flag_prints_the_committed_schema() {
    let bin = common::EXACTCHECK;
    for kind in ["sphere_interpolation", "cylinder_sphere"] {
        let o = std::process::Command::new(bin)
            .args(["solve", "--schema", kind])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0), "{kind}");
        let committed = std::fs::read_to_string(format!(
            "{}/docs/schema/{kind}.json",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap();
        assert_eq!(String::from_utf8_lossy(&o.stdout), committed, "{kind}");
    }
    let o = std::process::Command::new(bin)
        .args(["solve", "--schema", "no_such_kind"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&o.stderr)
            .trim_end()
            .lines()
            .count(),
        1
    );
}

/// A plane-plane problem with the given normal of the second plane and point of the first.
fn planes(normal: &str, point: &str) -> String {
    format!(
        r#"{{"kind":"plane_plane","planes":[{{"normal":[0,0,1],"point":{point}}},{{"normal":{normal},"point":[1,0,0]}}]}}"#
    )
}

#[test]
fn number_strings_are_constant_formulas_of_the_language() {
    // det([[1, 2], [3, 4]]) = -2, binomial(5, 2)/5 = 2, norm2([3, 4]) = 25, sum = 6.
    let plain = answer(&planes("[-2, 0, 0]", "[0, 0, 2]"), &[]);
    let written = answer(
        &planes(
            r#"["det([[1, 2], [3, 4]])", "dot([1, 2], [0, 0])", 0]"#,
            r#"["factorial(0) - 1", 0, "binomial(5, 2)/5"]"#,
        ),
        &[],
    );
    assert_eq!(written, plain);
    let big = answer(&planes("[-2, 0, 0]", "[0, 0, 25]"), &[]);
    assert_eq!(
        answer(&planes("[-2, 0, 0]", r#"[0, 0, "norm2([3, 4])"]"#), &[]),
        big
    );
    assert_eq!(
        answer(
            &planes("[-2, 0, 0]", r#"[0, 0, "sum(k, 0, 3, k) + 19"]"#),
            &[]
        ),
        big
    );
    // The --float reading goes through the same parser.
    assert_eq!(
        answer(
            &planes("[-2, 0, 0]", r#"[0, 0, "factorial(4) + 1"]"#),
            &["--float"]
        ),
        answer(&planes("[-2, 0, 0]", "[0, 0, 25]"), &["--float"])
    );
}

#[test]
fn number_strings_that_are_not_constant_scalars_are_refused_by_field() {
    refused(
        &planes("[-2, 0, 0]", r#"[0, 0, "2 x"]"#),
        &[],
        &["planes[0].point[2]", "\"2 x\"", "variable 'x'"],
    );
    refused(
        &planes(r#"["[1, 2]", 0, 0]"#, "[0, 0, 1]"),
        &[],
        &[
            "planes[1].normal[0]",
            "a vector of 2 where a number is expected",
        ],
    );
    refused(
        &planes(r#"["det([[1, 2, 3]])", 0, 0]"#, "[0, 0, 1]"),
        &[],
        &["planes[1].normal[0]", "det"],
    );
}

/// The registry of kinds (`exactcheck::solve::kinds()`) is what the coverage tests read: every
/// registered kind has its schema file, a golden problem with at least one golden answer, and a
/// broken problem in the malformed corpus; every golden problem is of a registered kind.
#[test]
fn every_registered_kind_has_a_schema_a_golden_answer_and_a_malformed_case() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let names: Vec<&str> = exactcheck::solve::kinds().iter().map(|k| k.name).collect();
    let kind_of = |path: &Path| -> Option<String> {
        let text = std::fs::read_to_string(path).ok()?;
        let v: serde_json::Value =
            serde_json::from_str(text.trim_start_matches('\u{feff}')).ok()?;
        v.get("kind")?.as_str().map(String::from)
    };
    // Golden problems (NAME.json) and the modes answered (NAME.MODE.out).
    let files: Vec<String> = std::fs::read_dir(golden_dir())
        .expect("golden dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    let mut golden_kinds = Vec::new();
    for f in files.iter().filter(|f| f.ends_with(".json")) {
        let stem = f.trim_end_matches(".json");
        let kind = kind_of(&golden_dir().join(f)).unwrap_or_else(|| panic!("{f}: no kind"));
        assert!(
            names.contains(&kind.as_str()),
            "{f}: unregistered kind {kind:?}"
        );
        let answered = files
            .iter()
            .any(|o| o.starts_with(&format!("{stem}.")) && o.ends_with(".out"));
        assert!(answered, "{f}: no golden answer {stem}.MODE.out");
        golden_kinds.push(kind);
    }
    let malformed: Vec<String> = std::fs::read_dir(root.join("tests/malformed"))
        .expect("malformed dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            name.ends_with(".json")
                && !name.ends_with(".plot.json")
                && !name.ends_with(".shard.json")
                && !name.ends_with(".claims.json")
        })
        .filter_map(|p| std::fs::read(p).ok())
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .collect();
    for name in &names {
        assert!(
            root.join(format!("docs/schema/{name}.json")).is_file(),
            "{name}: no docs/schema/{name}.json"
        );
        assert!(
            golden_kinds.iter().any(|k| k == name),
            "{name}: no golden problem in tests/solve_golden"
        );
        assert!(
            malformed
                .iter()
                .any(|t| t.contains(&format!("\"kind\":\"{name}\""))
                    || t.contains(&format!("\"kind\": \"{name}\""))),
            "{name}: no solve case in tests/malformed"
        );
    }
}

/// A problem computed in a number field gives the answer the radical field gives for the same
/// numbers: `sqrt(2)/2` written as `2*cos(pi/8)^2 - 1` (which the radical field cannot evaluate,
/// so the problem is computed in `Q(cos(pi/8))`) against `sqrt(2)/2` itself. The exact values
/// are compared as real algebraic numbers, the twins as f64.
#[test]
fn a_number_field_problem_agrees_with_the_radical_field() {
    use exactcheck_exact::Algebraic;
    let problem = |x: &str| {
        format!(
            r#"{{"kind":"plane_plane","planes":[{{"normal":["{x}",2,3],"point":[0,0,1]}},{{"normal":[2,4,"{x}"],"point":[3,0,0]}}]}}"#
        )
    };
    let answer = |x: &str| {
        let o = solve(problem(x).as_bytes(), &[]);
        assert!(
            o.status.success(),
            "{x}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        serde_json::from_slice::<serde_json::Value>(&o.stdout).expect("JSON answer")
    };
    let (field, radical) = (answer("2*cos(pi/8)^2 - 1"), answer("sqrt(2)/2"));
    assert_eq!(field["outcome"], "line");
    for key in [
        "outcome",
        "on_both_planes",
        "nearest_to_origin",
        "unit_direction_in_field",
    ] {
        assert_eq!(field[key], radical[key], "{key}");
    }
    for key in ["point", "direction", "unit_direction"] {
        for i in 0..3 {
            let value = |a: &serde_json::Value| -> Algebraic {
                a[key][i]
                    .as_str()
                    .expect("a string")
                    .parse()
                    .expect("an exact value")
            };
            assert_eq!(value(&field), value(&radical), "{key}[{i}]");
            let (f, r) = (
                field["approx"][key][i].as_f64().unwrap(),
                radical["approx"][key][i].as_f64().unwrap(),
            );
            assert!(
                (f - r).abs() <= 1e-15 * r.abs().max(1.0),
                "{key}[{i}]: {f} vs {r}"
            );
        }
    }
}

/// Values of a problem whose field is generated by a value it wrote print as polynomials in
/// that string, not as `Root(...)`; each reads back (through the expression parser) as an exact
/// value equal to its f64 twin.
#[test]
fn number_field_values_print_in_the_generator_the_problem_named() {
    use exactcheck_exact::Algebraic;
    let text = r#"{"kind":"plane_plane","planes":[{"normal":["cos(pi/8)",2,3],"point":[0,0,1]},{"normal":[2,4,7],"point":[3,0,0]}]}"#;
    let o = solve(text.as_bytes(), &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let a: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON answer");
    assert_eq!(a["direction"][1], "6 - 7*cos(pi/8)");
    assert_eq!(a["direction"][2], "-4 + 4*cos(pi/8)");
    for key in ["point", "direction"] {
        for i in 0..3 {
            let s = a[key][i].as_str().expect("a string");
            assert!(!s.contains("Root("), "{key}[{i}]: {s}");
            let v: Algebraic = s.parse().expect("an exact value");
            let twin = a["approx"][key][i].as_f64().unwrap();
            let exact: f64 = v.to_decimal(17).parse().unwrap();
            assert!((exact - twin).abs() <= 1e-14, "{key}[{i}]: {s} vs {twin}");
        }
    }
}

/// Two unrelated values of degrees 4 and 3 span a field of degree 12, which no value generates
/// alone: the answer is exact (`Root(...)` values) and the unit direction's square root is
/// decided without the degree-144 primitive element.
#[test]
fn a_field_of_degree_twelve_is_answered() {
    let text = r#"{"kind":"plane_plane","planes":[{"normal":[1,0,"cos(pi/8)"],"point":[0,0,1]},{"normal":[0,1,"cos(2*pi/7)"],"point":[1,0,0]}]}"#;
    let o = solve(text.as_bytes(), &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let a: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON answer");
    assert_eq!(a["outcome"], "line");
    assert_eq!(a["on_both_planes"], true);
    assert_eq!(a["unit_direction_in_field"], false);
    // The direction n1 x n2 = (-cos(pi/8), -cos(2 pi/7), 1).
    let d: Vec<f64> = (0..3)
        .map(|i| a["approx"]["direction"][i].as_f64().unwrap())
        .collect();
    let (c8, c7) = (
        (std::f64::consts::PI / 8.0).cos(),
        (2.0 * std::f64::consts::PI / 7.0).cos(),
    );
    let scale = d[2];
    assert!(
        (d[0] + c8 * scale).abs() < 1e-12 && (d[1] + c7 * scale).abs() < 1e-12,
        "{d:?}"
    );
}
