//! End-to-end tests of the `exactcheck` binary: output contracts and exit statuses.

use std::process::{Command, Output};

fn exactcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn bench_w2_json_gives_the_anchor_check_values() {
    // N = 2000 sequential: the values gmpy2 prints for `w2_rational.py gmpy2 seq 2000`.
    let o = exactcheck(&["bench", "w2", "--n", "2000", "--mode", "seq", "--json"]);
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
fn bench_w2_full_size_check_values() {
    // The check values at N = 100,000 (tree mode), exact sum of all discriminants.
    let o = exactcheck(&["bench", "w2", "--mode", "tree"]);
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
        let o = exactcheck(&[
            "bench", "w2", "--n", "300", "--mode", "tree", "--scalar", scalar,
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
fn regress_reports_worst_cases_reproducibly() {
    let args = [
        "regress",
        "bezier-cubic",
        "--samples",
        "300",
        "--seed",
        "9",
        "--worst",
        "1",
    ];
    let (a, b) = (exactcheck(&args), exactcheck(&args));
    assert!(a.status.success());
    let s = stdout(&a);
    assert!(s.contains("300 samples, seed 9"), "{s}");
    assert!(s.contains("error in ulps"), "{s}");
    assert_eq!(s, stdout(&b));
}

#[test]
fn bad_input_is_one_line_and_status_2() {
    for args in [
        &["regress", "cylinder-sphere", "--samples", "0"][..],
        &["regress", "no-such-kernel"][..],
        &["bench", "w2", "--mode", "fastest"][..],
        &["bench", "w2", "--n", "-3"][..],
        &["frobnicate"][..],
    ] {
        let o = exactcheck(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(err.contains("error"), "{args:?}: {err}");
    }
    let o = exactcheck(&["regress", "cylinder-sphere", "--samples", "0"]);
    assert_eq!(String::from_utf8_lossy(&o.stderr).lines().count(), 1);
}
