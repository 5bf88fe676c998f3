//! The hostile `solve` cases and the limits that `solve` enforces, pinned: each
//! answers correctly or refuses with one line naming the limit (exit 2). Before the fixes these
//! ran for tens of seconds (refinement by bisection, isolation of roots of polynomials with
//! thousand-digit coefficients, sphere interpolation of many points), printed `null` for
//! non-finite numbers, or named no limit (JSON nesting). No test asserts a time.

use crate::common;

use common::{refused, solve_stdin};
use serde_json::Value;

const CS_RADIANS: &str = r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0,0],"radius":5,"beta":{"radians":1},"gamma":{"radians":-1}},"sphere":{"center":[1,2,4],"radius":5},"samples":2,"precision":PREC}"#;

fn exactcheck(args: &[&str]) -> std::process::Output {
    common::exactcheck()
        .args(args)
        .output()
        .expect("the binary runs")
}

fn answer(problem: &str, extra: &[&str]) -> Value {
    let o = solve_stdin(problem.as_bytes(), extra);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    serde_json::from_slice(&o.stdout).expect("JSON")
}

#[test]
fn a_fine_precision_is_refined_quickly_or_refused_by_the_precision_bits_limit() {
    // 1/(2^1024)^10 asks 10,240 bits: past the default precision-bits limit of 1,024.
    let p = CS_RADIANS.replace("PREC", r#""1/(2^1024)^10""#);
    refused(&p, &[], &["the limit precision-bits = 1024"]);
    // Raised, it is answered (quadratic interval refinement: it took 10 s of bisection), and
    // every irrational end is an interval of width <= 2^-10240 around the root.
    let v = answer(&p, &["--limit", "precision-bits=10240"]);
    let intervals = v["parametrization"]["real_for_tau_in"]
        .as_array()
        .expect("intervals");
    let mut checked = 0;
    for iv in intervals {
        for end in iv.as_array().expect("two ends") {
            if let Some(pair) = end.get("interval") {
                let lo: exactcheck_exact::Rational = pair[0].as_str().unwrap().parse().unwrap();
                let hi: exactcheck_exact::Rational = pair[1].as_str().unwrap().parse().unwrap();
                let w: exactcheck_exact::Rational = "1/(2^1024)^10".parse().unwrap();
                assert!(lo < hi && hi - lo <= w);
                checked += 1;
            }
        }
    }
    assert!(checked > 0, "{v}");
}

#[test]
fn the_bisection_limit_is_checked_before_refining() {
    let p = CS_RADIANS.replace("PREC", r#""2^-200""#);
    refused(
        &p,
        &["--limit", "bisection=100"],
        &["the limit bisection = 100"],
    );
}

#[test]
fn thousand_digit_coordinates_are_answered_exactly() {
    // Isolating the discriminant's roots bisected log2(leading coefficient) times to make a
    // rational root exact (28 s at 1,000 digits); the samples' square roots factored the
    // radicand. Now both are quick and the points are still checked exactly.
    let k = 1000;
    let sevens = "7".repeat(k);
    let scale = format!("1{}", "0".repeat(k - 2));
    let p = format!(
        r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":"{}/{scale}","beta":{{"cos":1,"sin":0}},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":["{sevens}/{scale}",0,0],"radius":"{}8/{scale}"}},"samples":1}}"#,
        "4".repeat(k),
        "7".repeat(k - 1)
    );
    let v = answer(&p, &[]);
    assert_eq!(v["all_points_on_both_surfaces"], true, "{v}");
    assert_eq!(v["intersects"], true);
}

#[test]
fn json_integers_past_the_digits_limit_are_refused() {
    let big = "7".repeat(30_000);
    let p = format!(
        r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":5,"beta":{{"cos":1,"sin":0}},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":[{big},0,0],"radius":7}}}}"#
    );
    refused(
        &p,
        &[],
        &[
            "sphere.center[0]",
            "the limit digits = 10000",
            "found 30000",
        ],
    );
    let p = format!(
        r#"{{"kind":"sphere_interpolation","points":[[1,0,0],[0,0,1]],"params":[{},0]}}"#,
        "9".repeat(100_000)
    );
    refused(&p, &[], &["params[0]", "the limit digits"]);
    // A floating literal's mantissa counts too (in --float mode it is read).
    let p = format!(
        r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":5,"beta":{{"cos":1,"sin":0}},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":[1.{},0,0],"radius":7}}}}"#,
        "5".repeat(10_001)
    );
    refused(&p, &["--float"], &["the limit digits"]);
}

#[test]
fn many_interpolation_points_are_refused_by_the_points_limit() {
    let n = 1000;
    let points: Vec<&str> = (0..n).map(|_| "[1,0,0]").collect();
    let params: Vec<String> = (0..n).map(|i| i.to_string()).collect();
    let p = format!(
        r#"{{"kind":"sphere_interpolation","points":[{}],"params":[{}]}}"#,
        points.join(","),
        params.join(",")
    );
    refused(&p, &[], &["the limit points = 30", "found 1000"]);
}

#[test]
fn interpolation_skips_degrees_without_solutions_and_still_interpolates() {
    // 12 points in general position: the degrees below about N/2 have only the zero solution;
    // the answer is unchanged (the golden files pin the smaller cases) and verified.
    let pts = [
        ["9/11", "6/11", "-2/11"],
        ["1/3", "-2/3", "2/3"],
        ["0", "0", "1"],
        ["3/5", "4/5", "0"],
        ["2/3", "2/3", "1/3"],
        ["2/7", "3/7", "6/7"],
        ["-6/7", "2/7", "3/7"],
        ["4/9", "-4/9", "7/9"],
        ["1", "0", "0"],
        ["0", "-1", "0"],
        ["-2/3", "1/3", "-2/3"],
        ["12/13", "0", "5/13"],
    ];
    let points: Vec<String> = pts
        .iter()
        .map(|p| format!(r#"["{}","{}","{}"]"#, p[0], p[1], p[2]))
        .collect();
    let params: Vec<String> = (0..pts.len()).map(|i| format!("\"{i}/12\"")).collect();
    let p = format!(
        r#"{{"kind":"sphere_interpolation","points":[{}],"params":[{}]}}"#,
        points.join(","),
        params.join(",")
    );
    let v = answer(&p, &[]);
    assert_eq!(v["passes_through_all_points"], true);
    assert_eq!(v["degree"], 12, "{v}");
}

#[test]
fn deep_json_names_the_depth_limit_in_one_line() {
    // A million brackets: serde_json stopped at 128 levels naming no limit; a recursive reader
    // would overflow the stack.
    let deep = "[".repeat(1_000_000);
    refused(&deep, &[], &["the limit depth = 256"]);
    let p = format!(r#"{{"kind":"plane_plane","planes":{}}}"#, "[".repeat(300));
    refused(&p, &[], &["the limit depth = 256"]);
    // Within the limit (deeper than serde_json's own 128), the ordinary type error.
    let p = format!(
        r#"{{"kind":"plane_plane","planes":{}{}}}"#,
        "[".repeat(200),
        "]".repeat(200)
    );
    refused(&p, &[], &["planes"]);
}

#[test]
fn deep_claims_files_name_the_depth_limit_in_one_line() {
    let dir = std::env::temp_dir().join(format!("exactcheck-solve-limits-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    for (name, text) in [
        ("deep.toml", format!("a = {}\n", "[".repeat(1_000_000))),
        (
            "deep.json",
            format!("{{\"claim\": {}", "[".repeat(1_000_000)),
        ),
    ] {
        let path = dir.join(name);
        std::fs::write(&path, text).expect("write");
        let o = exactcheck(&["verify", path.to_str().expect("UTF-8 path")]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
        assert!(err.contains("the limit depth"), "{name}: {err}");
        assert!(
            !err.contains("panicked") && !err.contains("overflow"),
            "{err}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn samples_past_the_limit_are_refused() {
    let p = r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0,0],"radius":5,"beta":{"cos":1,"sin":0},"gamma":{"cos":1,"sin":0}},"sphere":{"center":[1,0,0],"radius":7},"samples":100001}"#;
    refused(p, &[], &["the limit samples = 100000"]);
    let o = exactcheck(&["regress", "bezier-cubic", "--samples", "100001"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("the limit samples = 100000"), "{err}");
}
