//! `regress --formula`, `--fpcore`, `--program`, `--shard` and `merge`, end to end through the
//! binary: the acceptance cases at test size.

use serde_json::Value;
use std::path::PathBuf;
use std::process::{Command, Output};

fn exactcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn json_of(o: &Output) -> Value {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("JSON on stdout")
}

fn data(name: &str) -> String {
    format!("{}/tests/regress/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// The first entry's report of a `regress --json` document.
fn report(doc: &Value) -> &Value {
    &doc["entries"][0]
}

fn refused(args: &[&str], needles: &[&str]) -> String {
    let o = exactcheck(args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: {err:?} lacks {n:?}");
    }
    err
}

const CANCEL: &str = "sqrt(x + 1) - sqrt(x)";
const RATIONALIZED: &str = "1/(sqrt(x + 1) + sqrt(x))";

#[test]
fn cancellation_is_found_and_the_rationalized_form_is_accurate() {
    let run = |f: &str| {
        json_of(&exactcheck(&[
            "regress",
            "--formula",
            f,
            "--domain",
            "x in [1, 1e15]",
            "--samples",
            "2000",
            "--json",
        ]))
    };
    let bad = run(CANCEL);
    let r = report(&bad);
    assert_eq!(r["name"], CANCEL);
    assert_eq!(r["compared"], 2000);
    assert_eq!(r["refined"], 2000, "irrational references");
    assert!(r["max_ulps"].as_f64().unwrap() > 1e6, "{r}");
    assert!(r["bits_of_error"].as_f64().unwrap() > 10.0, "{r}");
    let good = run(RATIONALIZED);
    let r = report(&good);
    assert!(r["max_ulps"].as_f64().unwrap() < 4.0, "{r}");
    assert!(r["bits_of_error"].as_f64().unwrap() < 2.0, "{r}");
}

#[test]
fn division_by_zero_is_outside_the_domain() {
    // Every sample outside the domain: nothing compared, exit status 1.
    let o = exactcheck(&[
        "regress",
        "--formula",
        "1/(x - y) + 1/x",
        "--vars",
        "x,y",
        "--domain",
        "x in [0, 0], y in [-1, 1]",
        "--samples",
        "50",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(1), "{o:?}");
    let doc: Value = serde_json::from_slice(&o.stdout).expect("JSON on stdout");
    let r = report(&doc);
    assert_eq!(r["domain_errors"], 50, "{r}");
    assert_eq!(r["compared"], 0, "{r}");
}

#[test]
fn four_shards_merge_into_the_single_run() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("regress_shards");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let base = [
        "regress",
        "--formula",
        "x*y - x*z + 1/(y - z)",
        "--vars",
        "x,y,z",
        "--domain",
        "x in [-1, 1], y in [-1, 1], z in [-1, 1]",
        "--samples",
        "20000",
        "--seed",
        "5",
    ];
    let whole = json_of(&exactcheck(&[&base[..], &["--json"]].concat()));
    let mut files = Vec::new();
    for i in [3, 1, 4, 2] {
        let shard = format!("{i}/4");
        let o = exactcheck(&[&base[..], &["--shard", &shard]].concat());
        let doc = json_of(&o);
        assert_eq!(report(&doc)["shard"], shard.as_str());
        let path = dir.join(format!("shard{i}.json"));
        std::fs::write(&path, &o.stdout).expect("write shard");
        files.push(path.to_string_lossy().into_owned());
    }
    let mut args = vec!["merge", "--json"];
    args.extend(files.iter().map(String::as_str));
    let merged = json_of(&exactcheck(&args));
    assert_eq!(merged, whole);
    // Text too.
    let text = |o: Output| String::from_utf8_lossy(&o.stdout).into_owned();
    let mut targs = vec!["merge"];
    targs.extend(files.iter().map(String::as_str));
    assert_eq!(text(exactcheck(&targs)), text(exactcheck(&base)));
    // A missing shard is named.
    refused(
        &["merge", &files[0], &files[1], &files[2]],
        &["missing", "2/4"],
    );
}

#[test]
fn fpcore_suites_print_one_table() {
    let o = exactcheck(&[
        "regress",
        "--fpcore",
        &data("suite.fpcore"),
        "--samples",
        "500",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = String::from_utf8_lossy(&o.stdout);
    let head = s.lines().next().expect("a table");
    for col in [
        "name",
        "samples",
        "max ulps",
        "median ulps",
        "bits",
        "worst input",
    ] {
        assert!(head.contains(col), "{head}");
    }
    assert!(s.contains("not supported: sin"), "{s}");
    let doc = json_of(&exactcheck(&[
        "regress",
        "--fpcore",
        &data("suite.fpcore"),
        "--samples",
        "500",
        "--json",
    ]));
    let entries = doc["entries"].as_array().expect("entries");
    assert_eq!(entries.len(), 5);
    let by = |n: &str| entries.iter().find(|e| e["name"] == n).expect(n);
    assert!(by("sqrt-cancel")["max_ulps"].as_f64().unwrap() > 1e6);
    assert!(by("sqrt-rationalized")["max_ulps"].as_f64().unwrap() < 4.0);
    assert_eq!(by("uses-sin")["not_supported"], "not supported: sin");
    assert_eq!(by("quadratic-root")["compared"], 500);
    // The same benchmark through --fpcore and --formula: the same sweep.
    let one = json_of(&exactcheck(&[
        "regress",
        "--fpcore",
        &data("suite.fpcore"),
        "--name",
        "sqrt-cancel",
        "--samples",
        "300",
        "--json",
    ]));
    let f = cancel_run("300", &[]);
    for key in [
        "max_ulps",
        "median_ulps",
        "bits_of_error",
        "compared",
        "worst",
    ] {
        assert_eq!(report(&one)[key], report(&f)[key], "{key}");
    }
    refused(
        &[
            "regress",
            "--fpcore",
            &data("suite.fpcore"),
            "--name",
            "nope",
        ],
        &["no FPCore named 'nope'", "sqrt-cancel"],
    );
}

/// The user's program as the float side computes what the formula's f64 side computes, so the
/// two reports are the same.
fn program_matches_builtin(cmd: &str) {
    let builtin = cancel_run("1500", &[]);
    let external = cancel_run("1500", &["--program", cmd]);
    assert_eq!(external, builtin, "{cmd}");
}

/// `regress --formula 'sqrt(x + 1) - sqrt(x)' --domain 'x in [1, 1e15]' --json` with `samples`.
fn cancel_run(samples: &str, extra: &[&str]) -> Value {
    let base = [
        "regress",
        "--formula",
        CANCEL,
        "--domain",
        "x in [1, 1e15]",
        "--samples",
        samples,
        "--json",
    ];
    json_of(&exactcheck(&[&base[..], extra].concat()))
}

fn compiled_c() -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("regress_c");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let exe = dir.join("cancel");
    let st = Command::new("gcc")
        .args(["-O2", "-o"])
        .arg(&exe)
        .arg(data("cancel.c"))
        .arg("-lm")
        .status()
        .expect("gcc runs");
    assert!(st.success(), "gcc failed");
    exe.to_string_lossy().into_owned()
}

#[test]
fn a_c_program_regresses_end_to_end() {
    program_matches_builtin(&compiled_c());
}

#[test]
fn a_python_program_regresses_end_to_end() {
    program_matches_builtin(&format!("python3 {}", data("cancel.py")));
}

#[test]
fn failing_programs_are_one_line_errors() {
    let base = |cmd: &str, timeout: &str| {
        let args = [
            "regress",
            "--formula",
            CANCEL,
            "--domain",
            "x in [1, 1e15]",
            "--samples",
            "100",
            "--program",
            cmd,
            "--program-timeout",
            timeout,
        ];
        args.map(String::from)
    };
    let run = |cmd: &str, needles: &[&str]| {
        let a = base(cmd, "2");
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        refused(&a, needles)
    };
    // Crashes at its fourth sample (index 3).
    run(
        "python3 -c 'import sys\nfor i, l in enumerate(sys.stdin):\n    assert i < 3\n    print(0.5, flush=True)'",
        &["sample 3"],
    );
    run(
        "python3 -c 'import time; time.sleep(60)'",
        &["sample 0", "2"],
    );
    run(
        "python3 -c 'import sys\nfor l in sys.stdin: print(\"hello\", flush=True)'",
        &["sample 0", "hello"],
    );
    run(
        "python3 -c 'import sys\nfor l in sys.stdin: print(1, 2, flush=True)'",
        &["sample 0", "2"],
    );
    run("/no/such/program", &["/no/such/program"]);
}

#[test]
fn bad_formulas_and_domains_are_one_line_errors() {
    refused(
        &["regress", "--formula", "sqrt(x +", "--samples", "10"],
        &["--formula"],
    );
    refused(
        &[
            "regress",
            "--formula",
            "x + y",
            "--vars",
            "x",
            "--samples",
            "10",
        ],
        &["--formula", "y"],
    );
    refused(
        &[
            "regress",
            "--formula",
            "x",
            "--domain",
            "x in [2, 1]",
            "--samples",
            "10",
        ],
        &["--domain"],
    );
    refused(
        &[
            "regress",
            "--formula",
            "x",
            "--domain",
            "q in [0, 1]",
            "--samples",
            "10",
        ],
        &["--domain", "q"],
    );
    // A usage error of the command line: one line and a hint.
    let o = exactcheck(&["regress"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    let first = err.lines().next().unwrap_or_default();
    for n in ["KERNEL", "--formula", "--fpcore"] {
        assert!(first.contains(n), "{err}");
    }
    refused(
        &["regress", "bezier-cubic", "--program", "cat"],
        &["--program"],
    );
    refused(&["regress", "plane-plane", "--shard", "1/2"], &["--shard"]);
    // Sample limits: per run, and in all with shards.
    refused(
        &["regress", "--formula", "x", "--samples", "200000000"],
        &["--samples must be between 1 and 100000000 in one run"],
    );
    refused(
        &[
            "regress",
            "--formula",
            "x",
            "--samples",
            "200000000",
            "--shard",
            "1/1",
        ],
        &["shard 1/1", "use more shards"],
    );
}

/// The README's FPCore table is this run's output, verbatim.
#[test]
fn readme_fpcore_table_is_measured() {
    let o = exactcheck(&[
        "regress",
        "--fpcore",
        &data("suite.fpcore"),
        "--samples",
        "2000",
    ]);
    assert!(o.status.success());
    let out = String::from_utf8_lossy(&o.stdout);
    let table: String = out.lines().take(7).map(|l| format!("{l}\n")).collect();
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).expect("README");
    assert!(readme.contains(&table), "README lacks\n{table}");
}

/// The README's program examples are the files the tests run, verbatim.
#[test]
fn readme_program_examples_are_the_tested_files() {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).expect("README");
    for file in ["cancel.c", "cancel.py"] {
        let text = std::fs::read_to_string(data(file)).expect("example");
        assert!(readme.contains(&text), "README lacks {file} verbatim");
    }
}
