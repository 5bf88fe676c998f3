//! End-to-end tests of the `exactcheck-bench` binary: every workload prints the check values of
//! its anchors, and bad sizes are one line naming the flag and the limit with exit status 2.
//! No test measures time.

use exactcheck_exact::univariate::bench_instances;
use exactcheck_exact::Rational;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn bench(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_exactcheck-bench"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn rational_sum_json_gives_the_anchor_check_values() {
    // N = 2000 sequential: the values gmpy2 prints for `rational_sum.py gmpy2 seq 2000`.
    let o = bench(&["rational-sum", "--n", "2000", "--mode", "seq", "--json"]);
    assert!(o.status.success());
    let s = stdout(&o);
    for needle in [
        "\"count_nonneg\": 0",
        "\"sum_num_digits\": 12783",
        "\"sum_den_digits\": 12779",
        "\"sum_num_mod_p\": 288945042",
        "\"sum_den_mod_p\": 303592070",
        "\"sum_approx\": -59720.84632400675",
    ] {
        assert!(s.contains(needle), "{needle} not in {s}");
    }
}

#[test]
fn chiang_identity_json_gives_the_anchor_check_values() {
    // The values every tool of `chiang_identity.py` prints: variables, terms of the expanded
    // x-component left side, and both residuals zero (not zero with `--negative`).
    for (m, n, nvars, terms) in [("2", "3", 26, 174), ("8", "13", 74, 5841)] {
        for negative in [false, true] {
            let mut args = vec!["chiang-identity", "--m", m, "--n", n, "--json"];
            if negative {
                args.push("--negative");
            }
            let o = bench(&args);
            assert!(o.status.success());
            let s = stdout(&o);
            let zero = !negative;
            for needle in [
                format!("\"nvars\": {nvars}"),
                format!("\"lhs_x_terms\": {terms}"),
                format!("\"x_identity_zero\": {zero}"),
                format!("\"weight_identity_zero\": {zero}"),
                format!("\"negative\": {negative}"),
            ] {
                assert!(s.contains(&needle), "{needle} not in {s}");
            }
        }
    }
}

#[test]
fn rational_sum_full_size_check_values() {
    // The check values at N = 100,000 (tree mode), exact sum of all discriminants.
    let o = bench(&["rational-sum", "--mode", "tree"]);
    assert!(o.status.success());
    let s = stdout(&o);
    for needle in [
        "parameters with disc >= 0: 3005",
        "numerator 215019 digits, denominator 215013 digits",
        "numerator mod 1e9+7 = 550882728, denominator mod 1e9+7 = 512952170",
        "value ~ -2760950.50203799",
    ] {
        assert!(s.contains(needle), "{needle} not in {s}");
    }
}

#[test]
fn fast_and_plain_scalars_print_the_same_check_values() {
    let run = |scalar| {
        let o = bench(&[
            "rational-sum",
            "--n",
            "300",
            "--mode",
            "tree",
            "--scalar",
            scalar,
        ]);
        assert!(o.status.success());
        stdout(&o)
            .lines()
            .filter(|l| !l.contains("time") && !l.contains("scalar"))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(run("fast"), run("plain"));
}

#[test]
fn sample_sphere_matches_the_numpy_anchor() {
    // sample_sphere_numpy.py (all variants) prints count_nonneg 3415478 and sum_sqrt
    // 13229714.773764007 at N = 10,000,000; the sum depends on the last bits of each sqrt, so
    // compare to 1e-9.
    for variant in [
        "addition",
        "addition-serial",
        "coef",
        "coef-serial",
        "direct",
    ] {
        let o = bench(&["sample-sphere", "--variant", variant, "--json"]);
        assert!(o.status.success());
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
        assert_eq!(v["variant"], variant);
        assert_eq!(v["count_nonneg"], 3415478, "{variant}");
        let sum: f64 = v["sum_sqrt"].as_str().unwrap().parse().unwrap();
        assert!(
            (sum - 13229714.773764007).abs() < 1e-9 * sum,
            "{variant}: {sum}"
        );
    }
    // The default variant is the angle-addition kernel.
    let o = bench(&["sample-sphere", "--n", "1000", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["variant"], "addition");
}

/// `formula` evaluates the Python baseline's formula on the baseline's inputs: its check values
/// are those `scripts/regress_baseline.py` computed with `fractions.Fraction` (N = 100,000,
/// seed 1), so the throughput comparison is of the same work.
#[test]
fn formula_matches_the_python_baseline() {
    let o = bench(&["formula", "--n", "100000", "--seed", "1"]);
    assert!(o.status.success());
    let s = stdout(&o);
    assert!(
        s.contains(
            "sum_num_mod_p 1890083373366259320, sum_den_mod_p 473922923631408103, fsum 56.33278487489465"
        ),
        "{s}"
    );
}

#[test]
fn real_roots_json_line() {
    let o = bench(&[
        "real-roots",
        "--family",
        "wilkinson",
        "--degree",
        "8",
        "--json",
    ]);
    assert!(o.status.success());
    let s = stdout(&o);
    let v: serde_json::Value = serde_json::from_str(s.trim()).expect("one JSON line");
    assert_eq!(v["tool"], "exactcheck");
    assert_eq!(v["family"], "wilkinson");
    assert_eq!(v["degree"], 8);
    assert_eq!(v["real_roots"], 8);
    let roots = v["roots"].as_array().expect("a list");
    assert_eq!(roots.len(), 8);
    let w = bench_instances::target_width();
    for (j, r) in roots.iter().enumerate() {
        let lo: Rational = r[0].as_str().expect("a string").parse().expect("p/q");
        let hi: Rational = r[1].as_str().expect("a string").parse().expect("p/q");
        assert!(hi.clone() - lo.clone() <= w);
        let x = Rational::new(j as i64 + 1, 8).expect("non-zero denominator");
        assert!(lo <= x && x <= hi);
    }
    assert!(v["seconds"].as_f64().is_some());
}

#[test]
fn real_roots_text_and_bad_degrees() {
    let o = bench(&["real-roots", "--family", "mignotte", "--degree", "20"]);
    assert!(o.status.success());
    let s = stdout(&o);
    assert!(s.contains("4 real roots"), "{s}");
    assert!(s.contains("0.09999999999"), "{s}");
    for bad in ["0", "2001"] {
        let o = bench(&["real-roots", "--family", "random", "--degree", bad]);
        assert_eq!(o.status.code(), Some(2));
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(e.contains("--degree must be between 1 and 2000"), "{e}");
        assert_eq!(e.trim().lines().count(), 1, "{e}");
    }
}

#[test]
fn counts_out_of_range_are_one_line_naming_flag_and_limit() {
    for (args, message) in [
        (
            &["rational-sum", "--n", "0"][..],
            "--n must be between 1 and 10000000 with --mode eval (got 0)",
        ),
        (
            &["sample-sphere", "--n", "0"][..],
            "--n must be between 1 and 1000000000 (got 0)",
        ),
        (
            &[
                "rational-sum",
                "--n",
                "18446744073709551615",
                "--mode",
                "tree",
            ][..],
            "--n must be between 1 and 1000000 with --mode tree (got 18446744073709551615)",
        ),
        (
            &["sample-sphere", "--n", "100000000000000"][..],
            "--n must be between 1 and 1000000000 (got 100000000000000)",
        ),
        (
            &["rational-sum", "--n", "100000000", "--mode", "tree"][..],
            "--n must be between 1 and 1000000 with --mode tree (got 100000000)",
        ),
        (
            &["rational-sum", "--n", "1000000000000"][..],
            "--n must be between 1 and 10000000 with --mode eval (got 1000000000000)",
        ),
        (
            &["rational-sum", "--n", "100001", "--mode", "seq"][..],
            "--n must be between 1 and 100000 with --mode seq (got 100001)",
        ),
        (
            &["chiang-identity", "--m", "30", "--n", "30"][..],
            "--m 30 and --n 30: m + n must be at most 48",
        ),
        (
            &["dense-product", "--k", "31"][..],
            "--k must be between 1 and 30 (got 31)",
        ),
        (
            &["formula", "--n", "0"][..],
            "--n must be between 1 and 10000000 (got 0)",
        ),
    ] {
        let start = Instant::now();
        let o = bench(args);
        assert!(start.elapsed() < Duration::from_secs(10), "{args:?}");
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(
            String::from_utf8_lossy(&o.stderr),
            format!("exactcheck-bench: error: {message}\n"),
            "{args:?}"
        );
        assert!(o.stdout.is_empty());
    }
    // The limits themselves are accepted.
    let o = bench(&["rational-sum", "--n", "1", "--mode", "tree"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn usage_errors_are_one_line_plus_a_hint() {
    for args in [
        &[][..],
        &["frobnicate"][..],
        &["real-roots"][..],
        &["rational-sum", "--mode", "fastest"][..],
        &["rational-sum", "--n", "-3"][..],
        &["rational-sum", "--n", "18446744073709551616"][..],
        &["sample-sphere", "--variant", "gpu"][..],
    ] {
        let o = bench(args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        let lines: Vec<&str> = err.lines().collect();
        assert_eq!(lines.len(), 2, "{args:?}: {err}");
        assert!(
            lines[0].starts_with("exactcheck-bench: error: "),
            "{args:?}: {err}"
        );
        assert!(
            lines[1].starts_with("exactcheck-bench: hint: "),
            "{args:?}: {err}"
        );
        assert!(o.stdout.is_empty(), "{args:?}");
    }
    let o = bench(&["rational-sum", "--bogus"]);
    assert_eq!(
        String::from_utf8_lossy(&o.stderr).lines().next(),
        Some("exactcheck-bench: error: unexpected argument '--bogus' found")
    );
    // Help is not an error: standard output, status 0.
    let o = bench(&["--help"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).contains("rational-sum"));
}
