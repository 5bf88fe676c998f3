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

/// The refused benchmarks (file, name) and why: loops, binary32 and integer precision. Every
/// benchmark with an elementary function (`exp`, `log`, `sin`, `pow`, `atan2`, ...) runs.
const REFUSED: &[(&str, &str, &str)] = &[
    ("apron.fpcore", "Arrow-Hurwicz", "not supported: while*"),
    ("apron.fpcore", "Euler Oscillator", "not supported: while"),
    ("apron.fpcore", "Filter", "not supported: while*"),
    (
        "apron.fpcore",
        "Symplectic Oscillator",
        "not supported: while*",
    ),
    ("apron.fpcore", "Circle", "not supported: while*"),
    ("apron.fpcore", "Flower", "not supported: while"),
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
        "not supported: while",
    ),
    ("rosa.fpcore", "N Body Simulation", "not supported: while"),
    ("rosa.fpcore", "Pendulum", "not supported: while"),
    ("rosa.fpcore", "Sine Newton", "not supported: while"),
    (
        "salsa.fpcore",
        "Odometry",
        "not supported: precision binary32",
    ),
    ("salsa.fpcore", "PID", "not supported: while*"),
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
    ("salsa.fpcore", "Trapeze", "not supported: while*"),
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

#[test]
fn every_fpbench_benchmark_runs_or_is_refused_with_its_reason() {
    let mut refused: BTreeMap<(String, String), String> = BTreeMap::new();
    let mut total = 0;
    let mut compared = 0;
    for file in FILES {
        let path = format!(
            "{}/tests/regress/fpbench/{file}",
            env!("CARGO_MANIFEST_DIR")
        );
        let o = Command::new(env!("CARGO_BIN_EXE_exactcheck"))
            // No shrinking of worst cases: a candidate input where two transcendental terms
            // cancel exactly (`sin(x + eps) - sin(x)` at `eps = 0`) is refined to the precision
            // cap before it counts as undecided, which makes shrinking slow.
            .args([
                "regress",
                "--fpcore",
                &path,
                "--samples",
                "8",
                "--worst",
                "0",
                "--json",
            ])
            .output()
            .expect("the binary runs");
        assert!(
            o.status.success(),
            "{file}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let doc: Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
        for e in doc["entries"].as_array().expect("entries") {
            total += 1;
            let name = e["name"].as_str().expect("a name").to_string();
            match e["not_supported"].as_str() {
                Some(why) => {
                    assert_eq!(why.lines().count(), 1, "{name}: {why}");
                    refused.insert((file.to_string(), name), why.to_string());
                }
                None => {
                    if e["compared"].as_u64().unwrap_or(0) > 0 {
                        compared += 1;
                    }
                }
            }
        }
    }
    assert_eq!(total, 136, "the vendored suite has 136 benchmarks");
    let want: BTreeMap<(String, String), String> = REFUSED
        .iter()
        .map(|(f, n, w)| ((f.to_string(), n.to_string()), w.to_string()))
        .collect();
    assert_eq!(refused, want);
    // Every accepted benchmark compares samples against its exact reference.
    assert_eq!(
        compared + refused.len(),
        total,
        "{compared} of {total} compared"
    );
}
