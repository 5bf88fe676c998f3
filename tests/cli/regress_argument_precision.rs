//! FPCore arguments of another precision than their benchmark's, end to end through the binary
//! (`tests/regress/argument_precision.fpcore`): sampled among the values of their own precision
//! (also the shrunk worst inputs and `--sample floats`), computed as FPCore 2.0 says, named in
//! the reports; and an array of loop results computed by one run of the loop.

use serde_json::Value;
use std::process::{Command, Output};

const FILE: &str = "tests/regress/argument_precision.fpcore";

fn exactcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// The report of benchmark `name` of [`FILE`], run with `extra` arguments.
fn entry(name: &str, extra: &[&str]) -> Value {
    let mut args = vec![
        "regress",
        "--fpcore",
        FILE,
        "--name",
        name,
        "--samples",
        "300",
        "--json",
    ];
    args.extend_from_slice(extra);
    let o = exactcheck(&args);
    assert!(
        o.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc: Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
    doc["entries"][0].clone()
}

fn is_binary32(v: f64) -> bool {
    f64::from(v as f32) == v
}

/// Input `i` of every worst case, as sampled and as shrunk.
fn worst_inputs(r: &Value, i: usize) -> Vec<f64> {
    let mut out = Vec::new();
    for w in r["worst"].as_array().expect("worst cases") {
        for case in [&w["original"], &w["shrunk"]] {
            if let Some(x) = case["inputs"].get(i) {
                out.push(x.as_f64().expect("a number"));
            }
        }
    }
    assert!(!out.is_empty(), "{r}");
    out
}

#[test]
fn a_binary32_argument_of_a_binary64_benchmark() {
    let r = entry("binary32 x of a binary64 benchmark", &[]);
    assert_eq!(r["precision"], "binary64");
    assert_eq!(
        r["generator"],
        "x in [1, 1000] (uniform, rounded to binary32), y in [-1, 1] (uniform)"
    );
    assert_eq!(r["compared"], 300);
    // x + y - x in doubles loses the bits of y below x's ulp: many ulps.
    assert!(r["max_ulps"].as_f64().unwrap() > 100.0, "{r}");
    // Sampled and shrunk among the binary32 values, and inside the domain.
    for x in worst_inputs(&r, 0) {
        assert!(is_binary32(x) && (1.0..=1000.0).contains(&x), "{x}");
    }
    assert!(worst_inputs(&r, 1).iter().any(|&y| !is_binary32(y)));
}

#[test]
fn a_binary64_argument_of_a_binary32_benchmark() {
    let r = entry("binary64 x of a binary32 benchmark", &[]);
    assert_eq!(r["precision"], "binary32");
    assert_eq!(r["generator"], "x in [1, 2] (uniform, binary64)");
    // `x - 1` rounds its exact value once to binary32: at most half an ulp. Taking x as a
    // binary32 value first would lose up to a whole one.
    assert_eq!(r["compared"], 300);
    assert!(r["max_ulps"].as_f64().unwrap() <= 0.5, "{r}");
    assert!(worst_inputs(&r, 0).iter().any(|&x| !is_binary32(x)));
}

#[test]
fn sampling_over_the_floats_and_the_csv_columns_follow_the_argument() {
    let dir = std::env::temp_dir().join(format!("exactcheck-argprec-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary directory");
    let csv = dir.join("samples.csv");
    let r = entry(
        "binary32 x of a binary64 benchmark",
        &[
            "--sample",
            "floats",
            "--csv",
            csv.to_str().expect("UTF-8 path"),
        ],
    );
    assert_eq!(
        r["generator"],
        "x in [1, 1000] (uniform over the binary32 values), y in [-1, 1] (uniform over the doubles)"
    );
    let text = std::fs::read_to_string(&csv).expect("the CSV is written");
    let mut lines = text.lines();
    let header = lines.next().expect("a header");
    assert!(
        header.starts_with("sample,x [binary32],y,float,"),
        "{header}"
    );
    let mut rows = 0;
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        let x: f64 = cells[1].parse().expect("a number");
        assert!(is_binary32(x) && (1.0..=1000.0).contains(&x), "{line}");
        rows += 1;
    }
    assert_eq!(rows, 300);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn an_array_of_loop_results_runs_the_loop_once() {
    // The loop runs 6,000 iterations: once within the limit of 10,000, twice past it.
    let r = entry(
        "two results of one loop",
        &["--limit", "loop-iterations=10000"],
    );
    assert_eq!(r["compared"], 300);
    assert!(r.get("limit_stops").is_none(), "{r}");
    let per_output = r["max_ulps_per_output"].as_array().expect("two outputs");
    assert_eq!(per_output.len(), 2);
    // The counter is exact; the sum of 6,000 doubles is not.
    assert_eq!(per_output[0].as_f64(), Some(0.0));
    assert!(per_output[1].as_f64().unwrap() > 1.0, "{r}");
    for w in r["worst"].as_array().expect("worst cases") {
        assert_eq!(w["original"]["exact_outputs_f64"][0].as_f64(), Some(6000.0));
    }
    // Below the one run's 6,000 iterations, no sample is compared and the limit is named.
    let o = exactcheck(&[
        "regress",
        "--fpcore",
        FILE,
        "--name",
        "two results of one loop",
        "--samples",
        "5",
        "--limit",
        "loop-iterations=5999",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("loop-iterations = 5999"), "{err}");
}

#[test]
fn an_argument_precision_that_is_no_fpcore_precision_is_refused() {
    let dir = std::env::temp_dir().join(format!("exactcheck-argprec-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary directory");
    let path = dir.join("bad.fpcore");
    std::fs::write(&path, "(FPCore ((! :precision binary65 x)) (+ x 1))\n").expect("written");
    let o = exactcheck(&[
        "regress",
        "--fpcore",
        path.to_str().expect("UTF-8 path"),
        "--samples",
        "5",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("1:24: unknown precision `binary65` of the argument `x`"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
