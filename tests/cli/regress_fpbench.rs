//! Every vendored FPBench benchmark (`tests/regress/fpbench/`) regressed at a small sample count:
//! the benchmarks refused are exactly the listed ones, each with its one-line reason, and every
//! other one compares samples against a certified exact reference.

use serde_json::Value;
use std::collections::BTreeMap;
use std::process::Command;

const FILES: &[&str] = &[
    "apron.fpcore",
    "daisy.fpcore",
    "fptaylor-extra.fpcore",
    "fptaylor-real2float.fpcore",
    "fptaylor-tests.fpcore",
    "graphics.fpcore",
    "hamming-ch3.fpcore",
    "herbie.fpcore",
    "precimonious.fpcore",
    "rosa.fpcore",
    "rump.fpcore",
    "salsa.fpcore",
];

/// The refused benchmarks (file, name) and why: binary32 and integer precision. Every benchmark
/// with an elementary function (`exp`, `log`, `sin`, `pow`, `atan2`, ...) or a loop runs.
const REFUSED: &[(&str, &str, &str)] = &[
    (
        "fptaylor-extra.fpcore",
        "intro-example-mixed",
        "not supported: precision binary32",
    ),
    (
        "fptaylor-extra.fpcore",
        "exp1x_32",
        "not supported: precision binary32",
    ),
    (
        "fptaylor-extra.fpcore",
        "x_by_xy",
        "not supported: precision binary32",
    ),
    (
        "fptaylor-extra.fpcore",
        "hypot32",
        "not supported: precision binary32",
    ),
    (
        "fptaylor-extra.fpcore",
        "i4",
        "not supported: precision binary32",
    ),
    (
        "fptaylor-extra.fpcore",
        "i6",
        "not supported: precision binary32",
    ),
    (
        "fptaylor-tests.fpcore",
        "test01_sum3",
        "not supported: precision binary32",
    ),
    (
        "fptaylor-tests.fpcore",
        "test06_sums4, sum1",
        "not supported: precision binary32",
    ),
    (
        "fptaylor-tests.fpcore",
        "test06_sums4, sum2",
        "not supported: precision binary32",
    ),
    (
        "precimonious.fpcore",
        "arclength of a wiggly function",
        "not supported: precision integer",
    ),
    (
        "precimonious.fpcore",
        "arclength of a wiggly function (old version)",
        "not supported: precision binary32",
    ),
    (
        "salsa.fpcore",
        "Odometry",
        "not supported: precision binary32",
    ),
    (
        "salsa.fpcore",
        "Runge-Kutta 4",
        "not supported: precision binary32",
    ),
    (
        "salsa.fpcore",
        "Lead-lag System",
        "not supported: precision binary32",
    ),
    (
        "salsa.fpcore",
        "Rocket Trajectory",
        "not supported: precision binary32",
    ),
    (
        "salsa.fpcore",
        "Jacobi's Method",
        "not supported: precision binary32",
    ),
    (
        "salsa.fpcore",
        "Newton-Raphson's Method",
        "not supported: precision binary32",
    ),
    (
        "salsa.fpcore",
        "Eigenvalue Computation",
        "not supported: precision binary32",
    ),
    (
        "salsa.fpcore",
        "Iterative Gram-Schmidt Method",
        "not supported: precision binary32",
    ),
];

/// The accepted benchmarks that compare no sample, and why: FPBench's `while TRUE` loops never
/// end (every sample stops at the `loop-iterations` limit), and Sine Newton's iterates shrink
/// doubly exponentially towards 0, cancelling more bits than the precision cap (undecided).
const NOTHING_COMPARED: &[(&str, &str, &str)] = &[
    ("apron.fpcore", "Euler Oscillator", "limit_stops"),
    ("apron.fpcore", "Filter", "limit_stops"),
    ("apron.fpcore", "Circle", "limit_stops"),
    ("rosa.fpcore", "Sine Newton", "undecided"),
];

/// The exit status of each file's run: 2 where a benchmark stopped at the loop limit in every
/// sample (after the report; the one stderr line names the limit), 1 where one compared no
/// sample otherwise, else 0.
fn expected_status(file: &str) -> i32 {
    match file {
        "apron.fpcore" => 2,
        "rosa.fpcore" => 1,
        _ => 0,
    }
}

#[test]
fn every_fpbench_benchmark_runs_or_is_refused_with_its_reason() {
    let mut refused: BTreeMap<(String, String), String> = BTreeMap::new();
    let mut nothing: BTreeMap<(String, String), String> = BTreeMap::new();
    let mut total = 0;
    let mut compared = 0;
    for file in FILES {
        let path = format!(
            "{}/tests/regress/fpbench/{file}",
            env!("CARGO_MANIFEST_DIR")
        );
        let o = Command::new(env!("CARGO_BIN_EXE_exactcheck"))
            .args(["regress", "--fpcore", &path, "--samples", "8", "--json"])
            .output()
            .expect("the binary runs");
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(
            o.status.code(),
            Some(expected_status(file)),
            "{file}: {stderr}"
        );
        if expected_status(file) == 2 {
            assert_eq!(stderr.lines().count(), 1, "{stderr}");
            assert!(
                stderr.contains("the limit loop-iterations = 10000")
                    && stderr.contains("'Euler Oscillator' and of 2 other entries"),
                "{stderr}"
            );
        }
        let doc: Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
        for e in doc["entries"].as_array().expect("entries") {
            total += 1;
            let name = e["name"].as_str().expect("a name").to_string();
            let key = (file.to_string(), name.clone());
            match e["not_supported"].as_str() {
                Some(why) => {
                    assert_eq!(why.lines().count(), 1, "{name}: {why}");
                    refused.insert(key, why.to_string());
                }
                None if e["compared"].as_u64() == Some(0) => {
                    // Every sample is accounted for by the one reason.
                    let why = ["limit_stops", "undecided"]
                        .into_iter()
                        .find(|k| e[*k].as_u64() == Some(8))
                        .unwrap_or("other");
                    if why == "limit_stops" {
                        assert_eq!(e["limit_stop"], "loop-iterations = 10000", "{name}");
                    }
                    nothing.insert(key, why.to_string());
                }
                None => compared += 1,
            }
        }
    }
    assert_eq!(total, 136, "the vendored suite has 136 benchmarks");
    let want = |list: &[(&str, &str, &str)]| -> BTreeMap<(String, String), String> {
        list.iter()
            .map(|(f, n, w)| ((f.to_string(), n.to_string()), w.to_string()))
            .collect()
    };
    assert_eq!(refused, want(REFUSED));
    assert_eq!(nothing, want(NOTHING_COMPARED));
    // Every other benchmark compares samples against its exact reference.
    assert_eq!(
        compared + refused.len() + nothing.len(),
        total,
        "{compared} of {total} compared"
    );
}
