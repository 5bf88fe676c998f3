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

/// The refused benchmarks (file, name) and why.
const REFUSED: &[(&str, &str, &str)] = &[];

#[test]
fn every_fpbench_benchmark_runs_or_is_refused_with_its_reason() {
    let mut refused: BTreeMap<(String, String), String> = BTreeMap::new();
    let mut total = 0;
    let mut compared = 0;
    for file in FILES {
        let path = format!("{}/tests/regress/fpbench/{file}", env!("CARGO_MANIFEST_DIR"));
        let o = Command::new(env!("CARGO_BIN_EXE_exactcheck"))
            .args(["regress", "--fpcore", &path, "--samples", "8", "--json"])
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
    // Every accepted benchmark but a few whose samples all leave the domain or stay undecided
    // compares samples.
    assert!(compared + refused.len() + 8 >= total, "{compared} of {total} compared");
}
