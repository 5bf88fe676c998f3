//! The acceptance list of `regress` that explains its errors, one test per point the other
//! regress tests leave open: exactly-zero values, rounding ties reached through different square
//! roots, a program whose answers shift by a numeric banner, Herbie's count of infinities, and
//! each explaining feature (local error, conditioning, `--bin`, `--csv`, `--html`, `--near`,
//! several outputs, `--predicate`, transcendental functions, binary32, loops) run on a benchmark
//! of the vendored FPBench suite (`tests/regress/fpbench/`), not on a formula written for the
//! test.

use crate::common;
use serde_json::Value;
use std::path::PathBuf;
use std::process::Output;

fn exactcheck(args: &[&str]) -> Output {
    common::exactcheck()
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

fn json_of(o: &Output) -> Value {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("JSON on stdout")
}

/// The first entry of `regress ARGS --json`.
fn entry(args: &[&str]) -> Value {
    let args = [&["regress"][..], args, &["--json"]].concat();
    json_of(&exactcheck(&args))["entries"][0].clone()
}

/// The path of a vendored FPBench file.
fn fpbench(file: &str) -> String {
    format!(
        "{}/tests/regress/fpbench/{file}",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// A fresh scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("done_when_{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

/// The worst case's `original` record of an entry.
fn worst(e: &Value) -> &Value {
    &e["worst"][0]["original"]
}

/// An expression that is exactly zero behind square roots has the exact value 0 (not a tiny
/// approximation), every sample is compared, and a non-zero float result is infinitely wrong
/// relatively.
#[test]
fn exactly_zero_expressions_are_decided_zero() {
    for formula in [
        "sqrt(x)*sqrt(x) - x",
        "(sqrt(x) + 1)*(sqrt(x) - 1) - (x - 1)",
    ] {
        let e = entry(&[
            "--formula",
            formula,
            "--domain",
            "x in [1, 2]",
            "--samples",
            "40",
            "--worst",
            "1",
        ]);
        assert_eq!(
            (e["compared"].as_u64(), e["undecided"].as_u64()),
            (Some(40), Some(0)),
            "{formula}: {e}"
        );
        let w = worst(&e);
        assert_eq!(w["exact_outputs"][0], "0", "{formula}: {w}");
        assert_eq!(w["exact_outputs_f64"][0], 0.0, "{formula}: {w}");
        assert_ne!(w["float_outputs"][0], 0.0, "{formula}: {w}");
        assert_eq!(e["max_rel"], "inf", "{formula}: {e}");
    }
}

/// Ties reached through square roots of different radicands, and a tie whose even neighbour is
/// the upper one: the exact value is the midpoint itself and rounds to even.
#[test]
fn ties_through_different_square_roots_round_to_even() {
    for (formula, exact, nearest) in [
        (
            "sqrt(2*(x + 2^-53)) * sqrt((x + 2^-53)/2)",
            "9007199254740993/9007199254740992",
            1.0,
        ),
        (
            "sqrt(3*(x + 3*2^-53)) * sqrt(3*(x + 3*2^-53)) / 3",
            "9007199254740995/9007199254740992",
            1.0 + f64::powi(2.0, -51),
        ),
    ] {
        let e = entry(&[
            "--formula",
            formula,
            "--domain",
            "x in [1, 1]",
            "--samples",
            "3",
            "--worst",
            "1",
        ]);
        assert_eq!(e["compared"], 3, "{formula}: {e}");
        let w = worst(&e);
        assert_eq!(w["exact_outputs"][0], exact, "{formula}: {w}");
        assert_eq!(w["exact_outputs_f64"][0], nearest, "{formula}: {w}");
        // Half an ulp off at most: the tie is the exact value, not a value near it.
        assert!(e["max_ulps"].as_f64().unwrap() <= 0.5, "{formula}: {e}");
    }
}

/// A banner that reads as a number shifts every answer by one sample: the plain protocol
/// notices the line left over, the numbered one the first answer; both stop with one line.
#[test]
fn a_numeric_banner_is_a_protocol_error() {
    let answer = "awk \"BEGIN { printf \\\"%.17g\\n\\\", sqrt($x + 1) - sqrt($x) }\"";
    for (cmd, extra, needle) in [
        (
            format!("sh -c 'echo 0; while read -r x; do x=${{x#[}}; x=${{x%]}}; {answer}; done'"),
            None,
            "protocol error",
        ),
        (
            format!(
                "sh -c 'echo 0 0; while read -r i x; do x=${{x#[}}; x=${{x%]}}; printf \"%s \" $i; {answer}; done'"
            ),
            Some("--program-echo-index"),
            "does not start with the index 1",
        ),
    ] {
        let mut args = vec![
            "regress",
            "--formula",
            "sqrt(x + 1) - sqrt(x)",
            "--domain",
            "x in [1, 1e15]",
            "--samples",
            "50",
            "--quiet",
            "--program",
            &cmd,
        ];
        args.extend(extra);
        let o = exactcheck(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{cmd}: {err}");
        assert_eq!(err.lines().count(), 1, "{cmd}: {err}");
        assert!(err.contains(needle), "{cmd}: {err}");
        assert!(o.stdout.is_empty(), "{cmd}");
    }
}

/// Herbie's bits count the infinities as the doubles past `±MAX`: a correctly rounded overflow
/// to `+inf` is 0 bits (it is still a float failure in ulps), a spurious one almost 64.
#[test]
fn a_correctly_rounded_infinity_is_zero_bits() {
    let e = entry(&[
        "--formula",
        "x*x",
        "--domain",
        "x in [1e300, 1e301]",
        "--samples",
        "50",
    ]);
    assert_eq!(e["compared"], 50, "{e}");
    assert_eq!(e["float_failures"], 50, "{e}");
    assert_eq!(
        (e["bits_of_error"].as_f64(), e["max_bits"].as_f64()),
        (Some(0.0), Some(0.0))
    );
    assert_eq!(worst(&e)["exact_outputs_f64"][0], "inf", "{e}");
    let e = entry(&[
        "--formula",
        "x*x/x",
        "--domain",
        "x in [1e200, 1e300]",
        "--samples",
        "50",
    ]);
    assert_eq!(e["float_failures"], 50, "{e}");
    // About 2^57 doubles lie between the exact values near 1e250 and +inf.
    assert!(e["bits_of_error"].as_f64().unwrap() > 50.0, "{e}");
    assert!(e["max_bits"].as_f64().unwrap() <= 64.0, "{e}");
}

/// Local error on FPBench's NMSE example 3.1: the subtraction loses the bits, and the problem is
/// well-conditioned there (the loss is the algorithm's).
#[test]
fn nmse_3_1_names_the_subtraction_and_its_bits() {
    let e = entry(&[
        "--fpcore",
        &fpbench("hamming-ch3.fpcore"),
        "--name",
        "NMSE example 3.1",
        "--samples",
        "300",
        "--worst",
        "1",
    ]);
    let x = &e["worst"][0]["explanation"];
    let top = &x["operations"][0];
    assert_eq!(top["operation"], "subtraction", "{x}");
    assert_eq!(top["at"], "sqrt(x + 1) - sqrt(x)", "{x}");
    assert!(top["bits"].as_f64().unwrap() > 30.0, "{x}");
    assert_eq!(x["operations"].as_array().unwrap().len(), 1, "{x}");
    assert!((x["condition"].as_f64().unwrap() - 0.5).abs() < 1e-3, "{x}");
}

/// The condition number separates FPBench's 3x3 determinant, ill-conditioned where it loses
/// bits (its loss is within what the condition number predicts), from NMSE example 3.1,
/// well-conditioned and still losing most of its bits.
#[test]
fn conditioning_separates_the_determinant_from_nmse_3_1() {
    let run = |file: &str, name: &str| {
        let o = exactcheck(&[
            "regress",
            "--fpcore",
            &fpbench(file),
            "--name",
            name,
            "--samples",
            "300",
            "--worst",
            "1",
            "--quiet",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let e = entry(&[
            "--fpcore",
            &fpbench(file),
            "--name",
            name,
            "--samples",
            "300",
            "--worst",
            "1",
        ]);
        (
            String::from_utf8(o.stdout).unwrap(),
            e["worst"][0]["explanation"].clone(),
        )
    };
    let (text, x) = run("daisy.fpcore", "matrixDeterminant");
    let (cond, bits) = (
        x["condition"].as_f64().unwrap(),
        x["bits"].as_f64().unwrap(),
    );
    assert!(cond > 16.0 && bits <= cond.log2() + 3.0, "{x}");
    assert!(
        text.contains("ill-conditioned here") && text.contains("the loss is the problem's"),
        "{text}"
    );
    let (text, x) = run("hamming-ch3.fpcore", "NMSE example 3.1");
    let (cond, bits) = (
        x["condition"].as_f64().unwrap(),
        x["bits"].as_f64().unwrap(),
    );
    assert!(cond < 1.0 && bits > 30.0, "{x}");
    assert!(
        text.contains("well-conditioned (cond 0.5): the algorithm loses"),
        "{text}"
    );
}

/// `--bin`, `--csv` and `--html` on Rosa's `triangle1` (Heron's formula): every compared sample
/// in one bin of `a + b - c`, one CSV row each with the benchmark's inputs as columns, and a
/// plot of the error against each input.
#[test]
fn triangle1_is_binned_exported_and_plotted() {
    let dir = scratch("triangle1");
    let csv = dir.join("samples.csv");
    let html = dir.join("report.html");
    let e = entry(&[
        "--fpcore",
        &fpbench("rosa.fpcore"),
        "--name",
        "triangle1",
        "--samples",
        "400",
        "--worst",
        "1",
        "--bin",
        "a + b - c",
        "--csv",
        csv.to_str().unwrap(),
        "--html",
        html.to_str().unwrap(),
    ]);
    let compared = e["compared"].as_u64().unwrap();
    assert!(compared > 100, "{e}");
    assert_eq!(e["bins"]["expr"], "a + b - c");
    let bins = e["bins"]["bins"].as_array().unwrap();
    let total: u64 = bins.iter().map(|b| b["samples"].as_u64().unwrap()).sum();
    assert_eq!(total, compared);
    // The precondition keeps a + b - c above 0.1 and below 17.
    for b in bins {
        let label = b["bin"].as_str().unwrap();
        assert!(
            ["[1e-1, 1e0)", "[1e0, 1e1)", "[1e1, 1e2)"].contains(&label),
            "{label}"
        );
    }
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("sample,a,b,c,float,exact_rounded,ulps,max_ulps,bits")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len() as u64, compared);
    for r in &rows {
        let (a, b, c) = (r[1], r[2], r[3]);
        assert!(
            a + b > c + 0.1 && a + c > b + 0.1 && b + c > a + 0.1,
            "{r:?}"
        );
        let s = (a + b + c) / 2.0;
        assert_eq!(r[4], (s * (s - a) * (s - b) * (s - c)).sqrt(), "{r:?}");
    }
    let page = std::fs::read_to_string(&html).unwrap();
    assert_eq!(page.matches("<svg").count(), 3);
    for v in ["a", "b", "c"] {
        assert!(page.contains(&format!("bits of error against {v}")), "{v}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--near` on Rosa's `triangle1`: drawn near the edge of its precondition `a + b > c + 0.1`
/// (nearly degenerate triangles), the median error is far above the uniform sweep's.
#[test]
fn triangle1_near_its_degenerate_edge_loses_more() {
    let file = fpbench("rosa.fpcore");
    let run = |extra: &[&str]| {
        let args = [
            &["--fpcore", &file, "--name", "triangle1", "--samples", "400"][..],
            extra,
        ]
        .concat();
        entry(&args)
    };
    let uniform = run(&[]);
    let near = run(&["--near", "a + b = c + 0.1"]);
    assert!(
        near["generator"]
            .as_str()
            .unwrap()
            .starts_with("near a + b = c + 0.1: "),
        "{near}"
    );
    assert!(near["compared"].as_u64().unwrap() > 100, "{near}");
    let median = |e: &Value| e["median_ulps"].as_f64().unwrap();
    assert!(median(&near) > 4.0 * median(&uniform), "{near} {uniform}");
}

/// Several outputs from real benchmarks: Daisy's two polar-to-Cartesian benchmarks as one
/// FPCore `array`, each output reported, the worst of the two the sample's error.
#[test]
fn daisy_polar_to_cartesian_as_an_array_reports_both_outputs() {
    let dir = scratch("polar");
    let path = dir.join("polar.fpcore");
    std::fs::write(
        &path,
        "(FPCore (radius theta) :name \"polarToCarthesian\" :pre (and (<= 1 radius 10) (<= 0 theta 360))\n  (let* ([pi 3.14159265359] [radiant (* theta (/ pi 180.0))])\n    (array (* radius (cos radiant)) (* radius (sin radiant)))))\n",
    )
    .unwrap();
    let both = entry(&["--fpcore", path.to_str().unwrap(), "--samples", "300"]);
    let one = |name: &str| {
        entry(&[
            "--fpcore",
            &fpbench("daisy.fpcore"),
            "--name",
            name,
            "--samples",
            "300",
        ])
    };
    let (x, y) = (one("polarToCarthesian, x"), one("polarToCarthesian, y"));
    let per = both["max_ulps_per_output"].as_array().unwrap();
    assert_eq!(per.len(), 2, "{both}");
    assert_eq!(per[0], x["max_ulps"], "{both} {x}");
    assert_eq!(per[1], y["max_ulps"], "{both} {y}");
    assert_eq!(
        both["max_ulps"].as_f64().unwrap(),
        per[0].as_f64().unwrap().max(per[1].as_f64().unwrap())
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--predicate` on Daisy's `matrixDeterminant` (a 3x3 determinant, the orientation test in
/// three dimensions): on well-spread entries in [-10, 10] no sign is wrong; drawn near the
/// singular matrices (`--near det = 0`, its inputs `e` and `i` written `e0` and `i0`, since `e`
/// and `i` are constants in the formula syntax) float signs are wrong or zero.
#[test]
fn the_determinant_benchmark_counts_sign_errors() {
    let file = fpbench("daisy.fpcore");
    let run = |extra: &[&str]| {
        let args = [
            &[
                "--fpcore",
                &file,
                "--name",
                "matrixDeterminant",
                "--samples",
                "2000",
                "--predicate",
            ][..],
            extra,
        ]
        .concat();
        entry(&args)["predicate"].clone()
    };
    let uniform = run(&[]);
    assert_eq!(uniform["compared"], 2000, "{uniform}");
    for k in [
        "wrong_sign",
        "float_zero_exact_nonzero",
        "float_nonzero_exact_zero",
        "no_float_sign",
    ] {
        assert_eq!(uniform[k], 0, "{k}: {uniform}");
    }
    let near = run(&[
        "--near",
        "a*e0*i0 + b*f*g + c*d*h = c*e0*g + b*d*i0 + a*f*h",
    ]);
    assert!(near["compared"].as_u64().unwrap() > 1000, "{near}");
    assert!(near["wrong_sign"].as_u64().unwrap() > 0, "{near}");
    assert!(
        near["float_zero_exact_nonzero"].as_u64().unwrap() > 0,
        "{near}"
    );
    // Naming the constant e where the benchmark has an input e is refused in one line.
    let o = exactcheck(&[
        "regress",
        "--fpcore",
        &file,
        "--name",
        "matrixDeterminant",
        "--samples",
        "10",
        "--bin",
        "a*e",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(
        err.trim_end(),
        "exactcheck: error: --bin: 'e' in 'a*e' is a constant in the formula syntax, not the input e of this benchmark: write e0 for that input"
    );
}

/// Transcendental references on FPTaylor's `exp1x`, `(exp(x) - 1) / x`: every sample compared
/// against a decided reference, the error a few ulps, and the cancelling subtraction after `exp`
/// named as where they are lost.
#[test]
fn exp1x_is_regressed_against_a_decided_exponential() {
    let e = entry(&[
        "--fpcore",
        &fpbench("fptaylor-extra.fpcore"),
        "--name",
        "exp1x",
        "--samples",
        "300",
        "--worst",
        "1",
    ]);
    assert_eq!(
        (e["compared"].as_u64(), e["undecided"].as_u64()),
        (Some(300), Some(0))
    );
    let max = e["max_ulps"].as_f64().unwrap();
    assert!(max > 1.0 && max < 1000.0, "{e}");
    let x = &e["worst"][0]["explanation"];
    assert_eq!(x["operations"][0]["operation"], "subtraction", "{x}");
    assert_eq!(x["operations"][0]["at"], "exp(x) - 1", "{x}");
}

/// binary32 on FPTaylor's `hypot32`: inputs are binary32 values, errors in binary32 ulps, and a
/// square root of a sum of two squares is within two of them.
#[test]
fn hypot32_is_measured_in_binary32() {
    let e = entry(&[
        "--fpcore",
        &fpbench("fptaylor-extra.fpcore"),
        "--name",
        "hypot32",
        "--samples",
        "300",
    ]);
    assert_eq!(e["precision"], "binary32");
    assert_eq!(e["compared"], 300, "{e}");
    let max = e["max_ulps"].as_f64().unwrap();
    assert!(max > 0.0 && max <= 2.0, "{e}");
    for w in e["worst"].as_array().unwrap() {
        for x in w["original"]["inputs"].as_array().unwrap() {
            let x = x.as_f64().unwrap();
            assert_eq!(f64::from(x as f32), x, "{x} is not a binary32 value");
        }
    }
}

/// A `while*` loop on Salsa's Newton-Raphson benchmark (binary32): every sample's loop runs to
/// its exit on the exact side too, and every sample is compared.
#[test]
fn newton_raphson_loops_to_a_compared_result() {
    let e = entry(&[
        "--fpcore",
        &fpbench("salsa.fpcore"),
        "--name",
        "Newton-Raphson's Method",
        "--samples",
        "100",
    ]);
    assert_eq!(e["precision"], "binary32");
    assert_eq!(
        (
            e["compared"].as_u64(),
            e["undecided"].as_u64(),
            e["limit_stops"].as_u64().unwrap_or(0)
        ),
        (Some(100), Some(0), 0),
        "{e}"
    );
}

/// The README's regress section shows the explained worst input of `sqrt(x + 1) - sqrt(x)` and
/// of the naive quadratic formula: each `$ exactcheck ...` command of that block prints every
/// line the README shows after it (the `...` stands for the lines left out).
#[test]
fn the_readme_shows_what_regress_explains() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("README.md");
    let start = readme
        .find("```console\n$ exactcheck regress --formula 'sqrt(x + 1) - sqrt(x)'")
        .expect("the README's regress console block");
    let block = &readme[start + "```console\n".len()..];
    let block = &block[..block.find("```").expect("the block ends")];
    let mut commands: Vec<(String, Vec<&str>)> = Vec::new();
    let mut continued = false;
    for line in block.lines() {
        if let Some(command) = line.strip_prefix("$ ") {
            commands.push((command.trim_end_matches('\\').to_string(), Vec::new()));
            continued = line.ends_with('\\');
        } else if continued {
            let last = commands.last_mut().expect("a command first");
            last.0.push_str(line.trim_end_matches('\\'));
            continued = line.ends_with('\\');
        } else if line != "..." {
            commands.last_mut().expect("a command first").1.push(line);
        }
    }
    assert_eq!(commands.len(), 2, "{block}");
    for (command, shown) in &commands {
        // The commands quote with single quotes only; split the words as a shell would.
        let mut words = Vec::new();
        let mut rest = command.trim_start_matches("exactcheck ").trim();
        while !rest.is_empty() {
            if let Some(quoted) = rest.strip_prefix('\'') {
                let end = quoted.find('\'').expect("a closed quote");
                words.push(quoted[..end].to_string());
                rest = quoted[end + 1..].trim_start();
            } else {
                let end = rest.find(' ').unwrap_or(rest.len());
                words.push(rest[..end].to_string());
                rest = rest[end..].trim_start();
            }
        }
        let args: Vec<&str> = words.iter().map(String::as_str).collect();
        let out = exactcheck(&args);
        assert!(out.status.success(), "{command}");
        let text = String::from_utf8_lossy(&out.stdout);
        for line in shown {
            assert!(
                text.lines().any(|l| l == *line),
                "README: `{command}` does not print {line:?}; it prints\n{text}"
            );
        }
    }
}
