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

/// The refused benchmarks (file, name) and why: the integer and binary80 precisions. Every
/// benchmark in binary64, binary32 or both (`intro-example-mixed`), with an elementary function
/// (`exp`, `log`, `sin`, `pow`, `atan2`, ...) or a loop runs.
const REFUSED: &[(&str, &str, &str)] = &[
    (
        "precimonious.fpcore",
        "arclength of a wiggly function",
        "not supported: precision integer",
    ),
    (
        "precimonious.fpcore",
        "arclength of a wiggly function (old version)",
        "not supported: precision binary80",
    ),
];

/// The accepted benchmarks that compare no sample, and why: FPBench's `while TRUE` loops never
/// end, Rocket Trajectory's counts to two million (every sample stops at the `loop-iterations`
/// limit; the exact side learns that from the counter alone), and Sine Newton's iterates shrink
/// doubly exponentially towards 0, cancelling more bits than the precision cap, so the exact
/// test decides them, where its exact iterates pass the `loop-value-bits` limit.
const NOTHING_COMPARED: &[(&str, &str, &str)] = &[
    ("apron.fpcore", "Euler Oscillator", "limit_stops"),
    ("apron.fpcore", "Filter", "limit_stops"),
    ("apron.fpcore", "Circle", "limit_stops"),
    ("rosa.fpcore", "Sine Newton", "limit_stops"),
    ("salsa.fpcore", "Rocket Trajectory", "limit_stops"),
    // binary32 benchmarks without a `:pre` sampled over all binary32 values: the samples leave
    // the domain, or their diverging loops' exact values are undecided or run past the limit.
    ("salsa.fpcore", "Odometry", "other"),
    ("salsa.fpcore", "Eigenvalue Computation", "other"),
    ("salsa.fpcore", "Iterative Gram-Schmidt Method", "other"),
];

/// The exit status of each file's run (at the default limits): 2 where a benchmark stopped at a
/// limit in every sample it did not compare and compared none (after the report; the one stderr
/// line names the limit), else 0.
fn expected_status(file: &str) -> i32 {
    match file {
        "apron.fpcore" | "salsa.fpcore" | "rosa.fpcore" => 2,
        _ => 0,
    }
}

/// The limit that stopped the samples of a benchmark of `file` that compared none: its name
/// and value as the report's `limit_stop` lists it, and as it prints.
fn stop_limit(file: &str) -> Value {
    if file == "rosa.fpcore" {
        serde_json::json!([{"limit": "loop-value-bits", "value": 16384}])
    } else {
        serde_json::json!([{"limit": "loop-iterations", "value": 10000}])
    }
}

/// [`stop_limit`] as the stderr line writes it.
fn stop_text(file: &str) -> &'static str {
    if file == "rosa.fpcore" {
        "loop-value-bits = 16384"
    } else {
        "loop-iterations = 10000"
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
            let first = match *file {
                "apron.fpcore" => "'Euler Oscillator' and of 2 other entries",
                "rosa.fpcore" => "'Sine Newton'",
                _ => "'Rocket Trajectory' and of 1 other entry",
            };
            assert!(
                stderr.contains(&format!("the limit {}", stop_text(file)))
                    && stderr.contains(first),
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
                        assert_eq!(e["limit_stop"], stop_limit(file), "{name}");
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

/// Runs `exactcheck regress ARGS --json` and returns the exit status and the first entry.
fn first_entry(args: &[&str]) -> (Option<i32>, Value) {
    let o = Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .arg("regress")
        .args(args)
        .args(["--json", "--quiet"])
        .output()
        .expect("the binary runs");
    let doc: Value = serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&o.stderr)));
    (o.status.code(), doc["entries"][0].clone())
}

#[test]
fn binary32_benchmarks_measure_binary32_ulps() {
    // FPTaylor's x / (x + y) on [1, 4]^2 in binary32: two roundings, at most 1.5 binary32 ulps,
    // every worst input a binary32 value.
    let path = format!(
        "{}/tests/regress/fpbench/fptaylor-extra.fpcore",
        env!("CARGO_MANIFEST_DIR")
    );
    let (status, e) = first_entry(&["--fpcore", &path, "--name", "x_by_xy", "--samples", "300"]);
    assert_eq!(status, Some(0), "{e}");
    assert_eq!(e["precision"], "binary32");
    assert_eq!(e["compared"], 300);
    let max = e["max_ulps"].as_f64().expect("max ulps");
    assert!(max > 0.25 && max <= 1.5, "{max}");
    for w in e["worst"].as_array().expect("worst") {
        for x in w["original"]["inputs"].as_array().expect("inputs") {
            let x = x.as_f64().expect("a number");
            assert_eq!(f64::from(x as f32), x, "{x} is not a binary32 value");
            assert!((1.0..=4.0).contains(&x));
        }
    }

    // (x + y) - x with y far below half a binary32 ulp of x: in binary32 the sum is x and the
    // result 0 (relative error exactly 1: y / ulp32(y) in [2^23, 2^24) ulps, 24 bits or more);
    // in binary64 the sum keeps y to within 2^-53, a relative error below 2^-23.
    let formula = [
        "--formula",
        "(x + y) - x",
        "--domain",
        "x in [1, 2], y in [1e-9, 2e-9]",
        "--samples",
        "200",
    ];
    let (status, e32) = first_entry(&[&formula[..], &["--precision", "binary32"]].concat());
    assert_eq!(status, Some(0), "{e32}");
    assert_eq!(e32["precision"], "binary32");
    assert_eq!(e32["max_rel"], 1.0);
    assert_eq!(e32["median_rel"], 1.0);
    let (lo, hi) = (f64::powi(2.0, 23), f64::powi(2.0, 24));
    for k in ["max_ulps", "median_ulps"] {
        let u = e32[k].as_f64().expect("ulps");
        assert!(lo <= u && u < hi, "{k} = {u}");
    }
    assert!(e32["bits_of_error"].as_f64().expect("bits") > 23.0);
    let (status, e64) = first_entry(&formula);
    assert_eq!(status, Some(0), "{e64}");
    assert_eq!(e64["precision"], "binary64");
    assert!(e64["max_rel"].as_f64().expect("rel") < f64::powi(2.0, -23));

    // The text table names the precision with the entry.
    let o = Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .args(["regress", "--fpcore", &path, "--samples", "20", "--quiet"])
        .output()
        .expect("the binary runs");
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("x_by_xy [binary32]"), "{text}");
    assert!(
        text.contains("in binary32: errors in binary32 ulps"),
        "{text}"
    );
}

#[test]
fn sine_newton_says_why_no_sample_was_compared() {
    // Ten Newton steps on sin's Taylor polynomial converge to 0 cubically: the exact iterate
    // ends at about 2^-34000 from 0.5 (the exponent triples every step), and each step cancels
    // about twice its bits, far beyond the precision cap; the exact test, which keeps the
    // iterates exact, stops when they pass the `loop-value-bits` limit.
    let path = format!(
        "{}/tests/regress/fpbench/rosa.fpcore",
        env!("CARGO_MANIFEST_DIR")
    );
    let o = Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .args([
            "regress",
            "--fpcore",
            &path,
            "--name",
            "Sine Newton",
            "--samples",
            "3",
        ])
        .arg("--quiet")
        .output()
        .expect("the binary runs");
    assert_eq!(o.status.code(), Some(2));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("3 stopped by the limit loop-value-bits = 16384"),
        "{text}"
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        stderr.contains("the limit loop-value-bits = 16384 bits")
            && stderr.contains("'Sine Newton'"),
        "{stderr}"
    );
}

#[test]
fn jacobi_runs_at_the_default_limits() {
    // Over all binary32 inputs Jacobi's iteration mostly diverges: its exact values grow every
    // iteration. The candidates of the shrinking phase that reach the exact zero test stop at the
    // `loop-value-bits` limit instead of growing rationals up to `constant-bits` for minutes;
    // the diverging samples stop at the iteration limit and are counted as such.
    let (status, e) = benchmark_entry("salsa.fpcore", "Jacobi's Method", "8");
    assert_eq!(status, Some(0), "{e}");
    assert_eq!(e["compared"], 4, "{e}");
    assert_eq!(e["limit_stops"], 4, "{e}");
    assert_eq!(
        e["limit_stop"],
        serde_json::json!([{"limit": "loop-iterations", "value": 10000}]),
        "{e}"
    );
}

#[test]
fn intro_example_mixed_is_regressed_in_its_two_precisions() {
    let (status, e) = benchmark_entry("fptaylor-extra.fpcore", "intro-example-mixed", "200");
    assert_eq!(status, Some(0), "{e}");
    assert_eq!(e["precision"], "binary32");
    assert_eq!(e["compared"], 200, "{e}");
    // t + 1 rounds in binary32, the quotient in binary64 and its cast to binary32: within 1.5
    // binary32 ulps of t / (t + 1) (at most half an ulp on 200 samples), and not always exact.
    let max = e["max_ulps"].as_f64().expect("max ulps");
    assert!(max > 0.0 && max < 1.51, "{max}");
}

/// [`first_entry`] of the benchmark `name` of a vendored FPBench file at `samples` samples.
fn benchmark_entry(file: &str, name: &str, samples: &str) -> (Option<i32>, Value) {
    let path = format!(
        "{}/tests/regress/fpbench/{file}",
        env!("CARGO_MANIFEST_DIR")
    );
    first_entry(&["--fpcore", &path, "--name", name, "--samples", samples])
}
