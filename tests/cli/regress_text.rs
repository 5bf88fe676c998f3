//! `regress --formula`, `--fpcore`, `--program`, `--shard` and `merge`, end to end through the
//! binary: the acceptance cases at test size.

use crate::common;

use serde_json::Value;
use std::path::PathBuf;
use std::process::{Command, Output};

fn exactcheck(args: &[&str]) -> Output {
    common::exactcheck()
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
    assert!(s.contains("not supported: erf"), "{s}");
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
    assert_eq!(by("uses-erf")["not_supported"], "not supported: erf");
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
    let mut builtin = cancel_run("1500", &[]);
    let mut external = cancel_run("1500", &["--program", cmd]);
    // Only the float side each report records differs, and with it the local errors (the
    // operations of an external program are not known; the conditioning is the same).
    let side = |doc: &mut Value| doc["entries"][0]["float_side"].take();
    assert_eq!(side(&mut builtin), format!("formula {CANCEL}").as_str());
    assert_eq!(side(&mut external), format!("program {cmd}").as_str());
    let local = |doc: &mut Value| {
        for w in doc["entries"][0]["worst"].as_array_mut().unwrap() {
            let e = w["explanation"].as_object_mut().unwrap();
            e.remove("operations_note");
            e.insert("operations".into(), Value::Array(vec![]));
        }
    };
    local(&mut builtin);
    local(&mut external);
    assert_eq!(external, builtin, "{cmd}");
}

/// `regress --formula 'sqrt(x + 1) - sqrt(x)' --domain 'x in [1, 1e15]'` with `samples` and
/// `extra` arguments.
fn cancel_args(samples: &str, extra: &[&str]) -> Vec<String> {
    let base = [
        "regress",
        "--formula",
        CANCEL,
        "--domain",
        "x in [1, 1e15]",
        "--samples",
        samples,
    ];
    base.iter().chain(extra).map(|s| s.to_string()).collect()
}

/// [`cancel_args`] with `--json`: the document.
fn cancel_run(samples: &str, extra: &[&str]) -> Value {
    let args = cancel_args(samples, &[&["--json"], extra].concat());
    json_of(&exactcheck(
        &args.iter().map(String::as_str).collect::<Vec<_>>(),
    ))
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

/// `regress --formula CANCEL` over 100 samples with `--program CMD` and `extra` arguments.
fn program_args(cmd: &str, extra: &[&str]) -> Vec<String> {
    cancel_args("100", &[&["--quiet", "--program", cmd], extra].concat())
}

/// A program that breaks the protocol ends the run with one line (exit status 2), never with an
/// accuracy figure; one that keeps it gives the same report as the formula's own f64 side.
#[test]
fn protocol_errors_are_one_line_errors() {
    let echo = |times: usize, numbered: bool, after: &str| {
        let (read, answer) = if numbered {
            ("read -r i x", "echo \"$i $x\"; ")
        } else {
            ("read -r x", "echo \"$x\"; ")
        };
        format!(
            "sh -c 'while {read}; do x=${{x#[}}; x=${{x%]}}; x=$(awk \"BEGIN {{ printf \\\"%.17g\\\", sqrt($x + 1) - sqrt($x) }}\"); {}done; {after}'",
            answer.repeat(times)
        )
    };
    let run = |cmd: &str, extra: &[&str], needles: &[&str]| {
        let a = program_args(cmd, extra);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        refused(&a, needles)
    };
    run(&echo(2, false, ""), &[], &["protocol error"]);
    run(
        &echo(2, true, ""),
        &["--program-echo-index"],
        &[
            "sample 1",
            "does not start with the index 1",
            "--program-echo-index",
        ],
    );
    run(
        &echo(1, false, "echo done"),
        &[],
        &["after its answer to sample", "\"done\""],
    );
    run(
        &echo(1, false, "exit 3"),
        &[],
        &["exit status 3 after its last answer"],
    );
    run(
        "sh -c 'echo ready; while read -r x; do echo 1; done'",
        &[],
        &["sample 0", "\"ready\""],
    );
    // The same loop keeping the protocol, numbered too, runs to its report.
    for extra in [&[][..], &["--program-echo-index"][..]] {
        let o = exactcheck(
            &program_args(&echo(1, !extra.is_empty(), ""), extra)
                .iter()
                .map(String::as_str)
                .collect::<Vec<_>>(),
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(String::from_utf8_lossy(&o.stdout).contains("100 compared"));
    }
}

/// Whether process `pid` is gone: no such process, or a zombie (killed, waiting to be reaped by
/// whichever process adopted it).
#[cfg(target_os = "linux")]
fn dead(pid: u32) -> bool {
    match std::fs::read_to_string(format!("/proc/{pid}/stat")) {
        Err(_) => true,
        Ok(stat) => stat
            .rsplit_once(") ")
            .is_some_and(|(_, rest)| rest.starts_with('Z') || rest.starts_with('X')),
    }
}

/// Waits up to 20 s for a file to hold a pid.
#[cfg(target_os = "linux")]
fn read_pid(path: &std::path::Path) -> u32 {
    let t = std::time::Instant::now();
    loop {
        if let Ok(Ok(pid)) = std::fs::read_to_string(path).map(|t| t.trim().parse()) {
            return pid;
        }
        assert!(t.elapsed().as_secs() < 20, "no pid in {path:?}");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

/// Waits up to 5 s for `pid` to be gone.
#[cfg(target_os = "linux")]
fn assert_dies(pid: u32, what: &str) {
    let t = std::time::Instant::now();
    while !dead(pid) && t.elapsed().as_secs() < 5 {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(
        dead(pid),
        "{what}: the program's child {pid} outlived exactcheck"
    );
}

/// A program that starts `sleep 1000` (its pid written to `pid_file`) and never answers.
#[cfg(target_os = "linux")]
fn hanging_parent(pid_file: &std::path::Path) -> String {
    let _ = std::fs::remove_file(pid_file);
    format!(
        "sh -c 'sleep 1000 & echo $! > \"{}\"; while read -r x; do :; done'",
        pid_file.display()
    )
}

/// exactcheck's `--timeout` and SIGTERM end it with the program's whole process group.
#[cfg(target_os = "linux")]
#[test]
fn timeout_and_sigterm_stop_what_the_program_started() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("program_group");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let pid_file = dir.join("sleep.pid");
    let cmd = hanging_parent(&pid_file);
    let mut args = vec!["--timeout".to_string(), "2".into()];
    args.extend(program_args(&cmd, &["--program-timeout", "600"]));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    refused(&args, &["did not finish within --timeout 2 s"]);
    assert_dies(read_pid(&pid_file), "--timeout");

    let args = program_args(&hanging_parent(&pid_file), &["--program-timeout", "600"]);
    let mut child = common::exactcheck()
        .args(&args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("the binary runs");
    let grandchild = read_pid(&pid_file);
    // SAFETY: `kill` takes plain integers.
    unsafe {
        libc::kill(child.id() as i32, libc::SIGTERM);
    }
    let status = child.wait().expect("exactcheck ends");
    use std::os::unix::process::ExitStatusExt;
    assert_eq!(status.signal(), Some(libc::SIGTERM), "{status:?}");
    assert_dies(grandchild, "SIGTERM");
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

/// The FPCore table of docs/regress.md is this run's output, verbatim.
#[test]
fn guide_fpcore_table_is_measured() {
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
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/regress.md"))
        .expect("docs/regress.md");
    assert!(readme.contains(&table), "docs/regress.md lacks\n{table}");
}

/// The program examples of docs/regress.md are the files the tests run, verbatim.
#[test]
fn guide_program_examples_are_the_tested_files() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/regress.md"))
        .expect("docs/regress.md");
    for file in ["cancel.c", "cancel.py"] {
        let text = std::fs::read_to_string(data(file)).expect("example");
        assert!(
            readme.contains(&text),
            "docs/regress.md lacks {file} verbatim"
        );
    }
}

#[test]
fn a_sum_of_thousands_of_terms_regresses_instead_of_overflowing_a_workers_stack() {
    // A left-deep tree of 5,000 additions overflowed a rayon worker's stack (exit status 134).
    let n = 5000;
    let sum = vec!["x"; n].join("+");
    let doc = json_of(&exactcheck(&[
        "regress",
        "--formula",
        &sum,
        "--domain",
        "x in [1, 2]",
        "--samples",
        "20",
        "--json",
    ]));
    let r = report(&doc);
    assert_eq!(r["compared"], 20, "{r}");
    assert_eq!(r["domain_errors"], 0, "{r}");
}

/// Writes `text` to a file of this test's temporary directory and returns its path.
fn temp_file(name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("regress_explains");
    std::fs::create_dir_all(&dir).expect("temporary directory");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("written");
    path.to_string_lossy().into_owned()
}

/// The shrunk inputs of every worst case of a report.
fn shrunk_inputs(r: &Value) -> Vec<Vec<f64>> {
    r["worst"]
        .as_array()
        .expect("worst cases")
        .iter()
        .map(|w| {
            let s = if w["shrunk"].is_null() {
                &w["original"]
            } else {
                &w["shrunk"]
            };
            s["inputs"]
                .as_array()
                .expect("inputs")
                .iter()
                .map(|v| v.as_f64().expect("a number"))
                .collect()
        })
        .collect()
}

/// A shrunk worst case stays inside the sampled domain (`--domain`, or the interval bounds of
/// an FPCore `:pre`) and inside the rest of `:pre`: `(x + y) - x` is as bad at `x = 512`, but
/// that is not a case of this sweep.
#[test]
fn shrunk_worst_inputs_stay_in_the_domain() {
    let in_domain = |x: &[f64]| {
        (1000.0..=1010.0).contains(&x[0]) && (1e-3..=2e-3).contains(&x[1]) && x[1] < x[0] / 1e5
    };
    let doc = json_of(&exactcheck(&[
        "regress",
        "--formula",
        "(x + y) - x",
        "--vars",
        "x,y",
        "--domain",
        "x in [1000, 1010], y in [1e-3, 2e-3]",
        "--samples",
        "2000",
        "--json",
    ]));
    let r = report(&doc);
    assert!(r["max_ulps"].as_f64().unwrap() > 1e3, "{r}");
    for x in shrunk_inputs(r) {
        assert!(
            (1000.0..=1010.0).contains(&x[0]) && (1e-3..=2e-3).contains(&x[1]),
            "{x:?}"
        );
    }
    assert!(r["worst"][0]["shrink_steps"].as_u64().unwrap() > 0, "{r}");
    let fpcore = temp_file(
        "absorb.fpcore",
        "(FPCore (x y) :name \"absorb\" :pre (and (<= 1000 x 1010) (<= 1/1000 y 2/1000) (< (* y 100000) x)) (- (+ x y) x))",
    );
    let doc = json_of(&exactcheck(&[
        "regress",
        "--fpcore",
        &fpcore,
        "--samples",
        "2000",
        "--json",
    ]));
    let r = report(&doc);
    assert!(r["max_ulps"].as_f64().unwrap() > 1e3, "{r}");
    for x in shrunk_inputs(r) {
        assert!(in_domain(&x), "{x:?}");
    }
}

/// NMSE example 3.6 (FPBench's `hamming-ch3`) has exact values down to about 1e-463 for the
/// largest doubles, where f64 returns 0: refined relatively, each of those samples has a
/// relative error of exactly 1 (an absolute cut-off at 2^-1280 made the exact values about 0
/// and the errors 0). A value that is exactly zero behind fourth roots, which no exact test
/// here decides, is undecided, never a tiny number.
#[test]
fn tiny_exact_values_keep_their_relative_error() {
    let fpcore = temp_file(
        "nmse36.fpcore",
        "(FPCore (x) :name \"NMSE example 3.6, x >= 1e300\" :pre (>= x 1e300) (- (/ 1 (sqrt x)) (/ 1 (sqrt (+ x 1)))))",
    );
    let doc = json_of(&exactcheck(&[
        "regress",
        "--fpcore",
        &fpcore,
        "--samples",
        "300",
        "--json",
    ]));
    let r = report(&doc);
    assert_eq!(
        (r["compared"].as_u64(), r["undecided"].as_u64()),
        (Some(300), Some(0)),
        "{r}"
    );
    assert_eq!(
        (r["median_rel"].as_f64(), r["max_rel"].as_f64()),
        (Some(1.0), Some(1.0)),
        "{r}"
    );
    let w = &r["worst"][0]["original"];
    let exact = w["exact_outputs"][0].as_str().expect("text");
    assert!(exact.starts_with('~') && exact.contains("e-4"), "{w}");
    assert_eq!(w["float_outputs"][0], 0.0);
    let o = exactcheck(&[
        "regress",
        "--formula",
        "sqrt(sqrt(x))*sqrt(sqrt(x)) - sqrt(x)",
        "--domain",
        "x in [1, 2]",
        "--samples",
        "20",
        "--quiet",
    ]);
    let text = String::from_utf8_lossy(&o.stdout);
    // Nothing compared: exit status 1, as for any sweep that measured nothing.
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        text.contains("0 compared") && text.contains("20 undecided"),
        "{text}"
    );
}

/// `sqrt(m) * sqrt(m)` with `m = 1 + 2^-53`, the midpoint of 1 and its successor: the exact
/// value is the tie itself, which rounds to even (1), and the f64 result 1 is 0 bits off.
#[test]
fn ties_reached_through_square_roots_round_to_even() {
    let doc = json_of(&exactcheck(&[
        "regress",
        "--formula",
        "sqrt(x + 2^-53) * sqrt(x + 2^-53)",
        "--domain",
        "x in [1, 1]",
        "--samples",
        "3",
        "--json",
    ]));
    let r = report(&doc);
    assert_eq!(r["bits_of_error"], 0.0, "{r}");
    let w = &r["worst"][0]["original"];
    assert_eq!(w["exact_outputs"][0], "9007199254740993/9007199254740992");
    assert_eq!(w["exact_outputs_f64"][0], 1.0);
}

/// `--sample floats` draws every input uniformly over the doubles of its range, as Herbie
/// does, and says so; `--sample reals` needs bounded ranges; a `:pre` written with `let` is
/// sampled as the same condition written directly.
#[test]
fn sampling_is_chosen_and_reported() {
    let run = |extra: &[&str]| cancel_run("500", extra);
    let mixed = run(&[]);
    let reals = run(&["--sample", "reals"]);
    let floats = run(&["--sample", "floats"]);
    assert_eq!(report(&mixed)["generator"], "x in [1, 1e15] (uniform)");
    assert_eq!(report(&reals)["generator"], report(&mixed)["generator"]);
    assert_eq!(report(&reals)["median_ulps"], report(&mixed)["median_ulps"]);
    assert_eq!(
        report(&floats)["generator"],
        "x in [1, 1e15] (uniform over the doubles)"
    );
    // Uniform over the doubles, the median input is near 2^25 (not near 5e14): smaller errors.
    assert!(
        report(&floats)["median_ulps"].as_f64().unwrap()
            < report(&mixed)["median_ulps"].as_f64().unwrap() / 100.0
    );
    refused(
        &[
            "regress",
            "--formula",
            "x",
            "--domain",
            "x in [1, inf)",
            "--sample",
            "reals",
        ],
        &["input 0 (x)", "both bounds"],
    );
    let direct = json_of(&exactcheck(&[
        "regress",
        "--fpcore",
        &data("suite.fpcore"),
        "--name",
        "sqrt-cancel",
        "--samples",
        "300",
        "--json",
    ]));
    let with_let = temp_file(
        "let_pre.fpcore",
        "(FPCore (x) :name \"sqrt-cancel\" :pre (let ([lo 1] [hi 1e15]) (<= lo x hi)) (- (sqrt (+ x 1)) (sqrt x)))",
    );
    let via_let = json_of(&exactcheck(&[
        "regress",
        "--fpcore",
        &with_let,
        "--samples",
        "300",
        "--json",
    ]));
    for key in ["generator", "compared", "max_ulps", "median_ulps", "worst"] {
        assert_eq!(report(&via_let)[key], report(&direct)[key], "{key}");
    }
}
