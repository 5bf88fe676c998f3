//! `regress` that explains its errors, end to end through the binary: local error per
//! operation, conditioning against the algorithm, `--bin`, `--csv`, `--html`, and the page
//! docs/regress-explain.md, whose shown output must be what the tool prints.

use crate::common;
use serde_json::Value;
use std::process::Output;

fn exactcheck(args: &[&str]) -> Output {
    common::exactcheck()
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

/// `exactcheck regress --formula FORMULA [--vars VARS] --domain DOMAIN --samples SAMPLES
/// EXTRA...` (`vars` empty: the variables as the formula names them).
fn regress(formula: &str, vars: &str, domain: &str, samples: &str, extra: &[&str]) -> Output {
    let mut args = vec!["regress", "--formula", formula];
    if !vars.is_empty() {
        args.extend(["--vars", vars]);
    }
    args.extend(["--domain", domain, "--samples", samples]);
    args.extend_from_slice(extra);
    exactcheck(&args)
}

/// A fresh scratch directory for one test.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir =
        std::env::temp_dir().join(format!("exactcheck-explain-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn json_of(o: &Output) -> Value {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("JSON on stdout")
}

const CANCEL: &str = "sqrt(x + 1) - sqrt(x)";
const QUADRATIC: &str = "(-b + sqrt(b*b - 4*a*c)) / (2*a)";
const QUADRATIC_DOMAIN: &str = "a in [1, 2], b in [1e3, 1e8], c in [1, 2]";

/// The explanation of the worst case of a `--json` run of 1000 samples.
fn explanation(formula: &str, vars: &str, domain: &str, extra: &[&str]) -> Value {
    let extra = [&["--worst", "1", "--json"][..], extra].concat();
    let doc = json_of(&regress(formula, vars, domain, "1000", &extra));
    doc["entries"][0]["worst"][0]["explanation"].clone()
}

#[test]
fn the_subtraction_of_sqrt_x_plus_1_minus_sqrt_x_loses_the_bits_of_a_well_conditioned_problem() {
    let e = explanation(CANCEL, "", "x in [1, 1e15]", &[]);
    let top = &e["operations"][0];
    assert_eq!(top["operation"], "subtraction", "{e}");
    assert_eq!(top["at"], CANCEL, "{e}");
    assert!(top["bits"].as_f64().unwrap() > 30.0, "{e}");
    // Only the subtraction loses more than rounding.
    assert_eq!(e["operations"].as_array().unwrap().len(), 1, "{e}");
    // cond = x / (2 sqrt(x (x + 1))): one half.
    let cond = e["condition"].as_f64().unwrap();
    assert!((cond - 0.5).abs() < 1e-3, "{e}");
    assert!(e["bits"].as_f64().unwrap() > 30.0, "{e}");

    let o = regress(
        CANCEL,
        "",
        "x in [1, 1e15]",
        "500",
        &["--worst", "1", "--quiet"],
    );
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains("local error: the subtraction in sqrt(x + 1) - sqrt(x) loses"),
        "{text}"
    );
    assert!(
        text.contains("conditioning: well-conditioned (cond 0.5): the algorithm loses"),
        "{text}"
    );
}

#[test]
fn the_naive_quadratic_formula_loses_its_bits_in_the_cancelling_addition() {
    let e = explanation(QUADRATIC, "a,b,c", QUADRATIC_DOMAIN, &[]);
    let top = &e["operations"][0];
    assert_eq!(top["operation"], "addition", "{e}");
    assert_eq!(top["at"], "-b + sqrt(b * b - 4 * a * c)", "{e}");
    assert!(top["bits"].as_f64().unwrap() > 30.0, "{e}");
    // The small root -c/b is well-conditioned: the loss is the algorithm's.
    let cond = e["condition"].as_f64().unwrap();
    assert!(cond < 4.0, "{e}");
    assert!(e["bits"].as_f64().unwrap() > 30.0, "{e}");
}

#[test]
fn a_stable_formula_reports_no_dominant_loss() {
    let e = explanation("1/(sqrt(x + 1) + sqrt(x))", "", "x in [1, 1e15]", &[]);
    assert_eq!(e["operations"], Value::Array(vec![]), "{e}");
    assert!(e["bits"].as_f64().unwrap() <= 2.0, "{e}");
    let o = regress(
        "1/(sqrt(x + 1) + sqrt(x))",
        "",
        "x in [1, 1e15]",
        "300",
        &["--worst", "1", "--quiet"],
    );
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("local error: no dominant loss"), "{text}");
    assert!(
        text.contains("well-conditioned (cond 0.5) and accurate here"),
        "{text}"
    );
}

#[test]
fn an_ill_conditioned_difference_of_squares_is_the_problems_loss() {
    let e = explanation("x*x - y*y", "x,y", "x in [1, 2], y in [1, 2]", &[]);
    let cond = e["condition"].as_f64().unwrap();
    let bits = e["bits"].as_f64().unwrap();
    assert!(cond > 100.0, "{e}");
    assert!(bits <= cond.log2() + 3.0, "{e}");
}

#[test]
fn an_external_program_gets_conditioning_but_no_local_error() {
    let e = explanation(
        CANCEL,
        "",
        "x in [1, 1e6]",
        &["--program", "python3 tests/regress/cancel.py"],
    );
    if e.is_null() {
        // No python3 here: nothing to check.
        return;
    }
    assert!(
        e["operations_note"].as_str().unwrap().contains("external"),
        "{e}"
    );
    assert!(e["condition"].as_f64().is_some(), "{e}");
}

#[test]
fn bins_count_every_compared_sample() {
    let doc = json_of(&regress(
        QUADRATIC,
        "a,b,c",
        QUADRATIC_DOMAIN,
        "500",
        &["--worst", "1", "--bin", "b*b/(a*c)", "--json"],
    ));
    let entry = &doc["entries"][0];
    let bins = entry["bins"]["bins"].as_array().unwrap();
    let total: u64 = bins.iter().map(|b| b["samples"].as_u64().unwrap()).sum();
    assert_eq!(total, entry["compared"].as_u64().unwrap());
    // b^2/(ac) lies in [2.5e5, 1e16]: decades 5 to 15 only.
    for b in bins {
        let label = b["bin"].as_str().unwrap();
        let k: i32 = label[3..label.find(',').unwrap()].parse().unwrap();
        assert!((5..=15).contains(&k), "{label}");
    }
    // More cancellation (larger b^2/(ac)), more bits lost.
    let first = bins.first().unwrap()["mean_bits"].as_f64().unwrap();
    let last = bins.last().unwrap()["mean_bits"].as_f64().unwrap();
    assert!(last > first + 10.0, "{bins:?}");
    let o = regress(
        QUADRATIC,
        "a,b,c",
        QUADRATIC_DOMAIN,
        "200",
        &["--worst", "1", "--bin", "b*b/(a*c)", "--quiet"],
    );
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains("error by the value of --bin b*b/(a*c):"),
        "{text}"
    );
}

#[test]
fn csv_has_one_checked_row_per_compared_sample() {
    let dir = scratch("csv");
    let path = dir.join("samples.csv");
    let path = path.to_str().unwrap();
    let doc = json_of(&regress(
        "x*x - y*y",
        "x,y",
        "x in [1, 2], y in [1, 2]",
        "300",
        &["--csv", path, "--json"],
    ));
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("sample,x,y,float,exact_rounded,ulps,max_ulps,bits")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert_eq!(
        rows.len() as u64,
        doc["entries"][0]["compared"].as_u64().unwrap()
    );
    for r in &rows {
        let (x, y) = (r[1], r[2]);
        assert_eq!(r[3], x * x - y * y, "{r:?}");
        let xr = exactcheck_float::convert::f64_to_rational(x).unwrap();
        let yr = exactcheck_float::convert::f64_to_rational(y).unwrap();
        let exact = &xr * &xr - &yr * &yr;
        assert_eq!(
            r[4],
            exactcheck_float::convert::rational_to_f64(&exact),
            "{r:?}"
        );
        assert_eq!(r[5], r[6]);
        assert!((0.0..=64.0).contains(&r[7]), "{r:?}");
    }
    assert!(rows.iter().any(|r| r[7] > 1.0), "some sample loses bits");
    // No temporary file is left beside it.
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn html_has_the_explanation_and_one_plot_per_input() {
    let dir = scratch("html");
    let path = dir.join("report.html");
    let path = path.to_str().unwrap();
    let o = regress(
        QUADRATIC,
        "a,b,c",
        QUADRATIC_DOMAIN,
        "300",
        &["--worst", "1", "--quiet", "--html", path],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let page = std::fs::read_to_string(path).unwrap();
    assert_eq!(page.matches("<svg").count(), 3);
    assert!(page.contains("local error: the addition in -b + sqrt(b * b - 4 * a * c) loses"));
    assert!(page.contains("bits of error against b"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_explain_options_are_refused_in_one_line() {
    // The arguments after `regress`, separated by `|`.
    for (args, needle) in [
        (
            "--formula|x + y|--samples|10|--bin|1/(x - x)",
            "is undefined (outside its domain) at sample 0",
        ),
        (
            "--formula|x + y|--samples|10|--bin|z",
            "--bin: unknown variable 'z'",
        ),
        (
            "--formula|x|--samples|10|--csv|/no/such/dir/a.csv",
            "the directory /no/such/dir does not exist",
        ),
        (
            "cylinder-sphere|--samples|10|--bin|x",
            "--bin applies to --formula and --fpcore",
        ),
        (
            "--formula|x|--samples|10|--shard|1/2|--bin|x",
            "--bin needs the whole sweep",
        ),
    ] {
        let args: Vec<&str> = std::iter::once("regress").chain(args.split('|')).collect();
        let o = exactcheck(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(o.stdout.is_empty(), "{args:?}");
    }
}

/// The words of a shell command line: blanks separate, single quotes group.
fn words(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    let mut any = false;
    for ch in line.chars() {
        match ch {
            '\'' => {
                quoted = !quoted;
                any = true;
            }
            c if c.is_whitespace() && !quoted => {
                if any {
                    out.push(std::mem::take(&mut cur));
                    any = false;
                }
            }
            c => {
                cur.push(c);
                any = true;
            }
        }
    }
    if any {
        out.push(cur);
    }
    out
}

/// Every `console` block of docs/regress-explain.md is a command and what it prints, verbatim.
#[test]
fn the_explain_page_shows_current_output() {
    let page = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/docs/regress-explain.md"
    ))
    .expect("docs/regress-explain.md");
    let mut blocks = 0;
    let mut rest = page.as_str();
    while let Some(start) = rest.find("```console\n") {
        let body = &rest[start + "```console\n".len()..];
        let end = body.find("\n```").expect("a closed block");
        let block = &body[..end];
        rest = &body[end + 4..];
        let (command, shown) = block.split_once('\n').unwrap_or((block, ""));
        let args = words(
            command
                .strip_prefix("$ exactcheck ")
                .expect("$ exactcheck ..."),
        );
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = exactcheck(&args);
        let printed = String::from_utf8(o.stdout).unwrap();
        assert_eq!(
            printed.trim_end(),
            shown.trim_end(),
            "docs/regress-explain.md: `{command}` prints otherwise"
        );
        blocks += 1;
    }
    assert!(blocks >= 3, "the page shows {blocks} runs");
}
