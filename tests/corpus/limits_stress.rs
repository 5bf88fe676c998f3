//! The limits stress test("a stress test in the test suite runs every limit at and
//! just past its value").
//!
//! Every limit of the registry (`exactcheck::limits::all()`) has a file
//! `tests/stress/<name>.toml`:
//!
//! ```toml
//! value = 100                        # every case runs `exactcheck --limit terms=100 ARGS...`
//! [[case]]
//! args = ["prove", "(x+1)^99", "0"]  # paths are relative to the repository root
//! # stdin = "..."                    # optional standard input
//! # env = { RAYON_NUM_THREADS = "4" } # optional environment variables
//! outcome = "within"                 # exit status 0 or 1, no "panicked", no "exceeds the limit"
//! [[case]]
//! args = ["prove", "(x+1)^100", "0"]
//! outcome = "past"                   # exit 2, one line on stderr naming "the limit terms = 100"
//! ```
//!
//! with at least one case within the limit (at the value, where the measure allows) and one just
//! past it. The cases of all files run in parallel, each under a 20 s kill-timeout. The
//! `--timeout` watchdog is not a limit of the registry; its test is here too.

use crate::timed;

use serde::Deserialize;
use std::collections::BTreeSet;
use std::ffi::OsString;
use timed::{parallel_map, root, run, run_with_env, Run};

/// The stress directory, relative to the repository root.
const DIR: &str = "tests/stress";

/// One `tests/stress/<limit>.toml`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct StressFile {
    /// The value every case sets with `--limit NAME=VALUE`.
    value: u64,
    /// The runs.
    case: Vec<StressCase>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct StressCase {
    /// The command line after `exactcheck --limit NAME=VALUE`.
    args: Vec<String>,
    /// Standard input, if any.
    stdin: Option<String>,
    /// Environment variables of the run.
    #[serde(default)]
    env: std::collections::BTreeMap<String, String>,
    /// `within` or `past`.
    outcome: Outcome,
}

#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
enum Outcome {
    /// Exit status 0 or 1, nothing about a limit, no panic.
    Within,
    /// Exit status 2 and one line naming the limit and its value.
    Past,
}

fn registry() -> Vec<&'static str> {
    exactcheck::limits::all().iter().map(|l| l.name()).collect()
}

fn stress_path(name: &str) -> std::path::PathBuf {
    root().join(DIR).join(format!("{name}.toml"))
}

/// The stress files present: limit name -> parsed file (a malformed file fails the test).
fn stress_files() -> Vec<(&'static str, StressFile)> {
    registry()
        .into_iter()
        .filter(|name| stress_path(name).exists())
        .map(|name| {
            let path = stress_path(name);
            let text = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            let file: StressFile =
                toml::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            (name, file)
        })
        .collect()
}

#[test]
fn every_limit_has_a_stress_file() {
    let names = registry();
    let mut problems = Vec::new();
    let missing: Vec<&str> = names
        .iter()
        .copied()
        .filter(|n| !stress_path(n).exists())
        .collect();
    if !missing.is_empty() {
        problems.push(format!(
            "no tests/stress/<name>.toml for the limit(s): {}",
            missing.join(", ")
        ));
    }
    // A file for no limit is a misspelt or renamed limit.
    for entry in std::fs::read_dir(root().join(DIR)).expect("read tests/stress") {
        let path = entry.expect("entry").path();
        let stem = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        if path.extension().is_some_and(|e| e == "toml") && !names.contains(&stem.as_str()) {
            problems.push(format!("{}: no limit of that name", path.display()));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// Whether a run meets `outcome` for the limit `name` at `value`; `Err` says how not.
fn judge(name: &str, value: u64, outcome: Outcome, r: &Run) -> Result<(), String> {
    if r.timed_out {
        return Err(format!("no answer: {}", r.describe()));
    }
    if r.panicked() {
        return Err(format!("\"panicked\" in the output: {}", r.describe()));
    }
    match outcome {
        Outcome::Within => {
            if !matches!(r.status, Some(0 | 1)) {
                return Err(format!("within the limit but {}", r.describe()));
            }
            if r.stdout_text().contains("exceeds the limit")
                || r.stderr_text().contains("exceeds the limit")
            {
                return Err(format!(
                    "within the limit but a limit is named: {}",
                    r.describe()
                ));
            }
        }
        Outcome::Past => {
            if r.status != Some(2) {
                return Err(format!("past the limit but {}", r.describe()));
            }
            let needle = format!("the limit {name} = {value}");
            match r.one_stderr_line() {
                Some(line) if line.contains(&needle) => {}
                _ => {
                    return Err(format!(
                        "past the limit but stderr is not one line naming {needle:?}: {}",
                        r.describe()
                    ))
                }
            }
        }
    }
    Ok(())
}

#[test]
fn every_limit_holds_at_its_value_and_refuses_just_past_it() {
    let files = stress_files();
    let mut problems = Vec::new();
    let mut runs = Vec::new();
    for (name, file) in &files {
        for outcome in [Outcome::Within, Outcome::Past] {
            if !file.case.iter().any(|c| c.outcome == outcome) {
                problems.push(format!(
                    "tests/stress/{name}.toml: no case with outcome = \"{}\"",
                    if outcome == Outcome::Within {
                        "within"
                    } else {
                        "past"
                    }
                ));
            }
        }
        for (i, case) in file.case.iter().enumerate() {
            runs.push((*name, file.value, i, case));
        }
    }
    let results = parallel_map(&runs, |(name, value, _, case)| {
        let mut args: Vec<OsString> = vec!["--limit".into(), format!("{name}={value}").into()];
        args.extend(case.args.iter().map(OsString::from));
        let env: Vec<(String, String)> = case.env.clone().into_iter().collect();
        let r = run_with_env(&args, case.stdin.as_deref().map(str::as_bytes), &env);
        judge(name, *value, case.outcome, &r)
    });
    for ((name, _, i, case), result) in runs.iter().zip(results) {
        if let Err(why) = result {
            problems.push(format!(
                "tests/stress/{name}.toml case #{} {:?}: {why}",
                i + 1,
                case.args
            ));
        }
    }
    eprintln!(
        "{} stress files, {} runs, {} problems",
        files.len(),
        runs.len(),
        problems.len()
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn every_stress_file_is_for_a_limit_and_well_formed() {
    // Parsing is the check (deny_unknown_fields, the outcome enum); a missing directory is not.
    let files = stress_files();
    let names: BTreeSet<&str> = registry().into_iter().collect();
    for (name, file) in &files {
        assert!(names.contains(name));
        assert!(
            !file.case.is_empty(),
            "tests/stress/{name}.toml has no [[case]]"
        );
        for case in &file.case {
            assert!(
                !case.args.is_empty(),
                "tests/stress/{name}.toml: a case without args"
            );
            assert!(
                !case.args.iter().any(|a| a == "--limit"),
                "tests/stress/{name}.toml: the harness sets --limit {name}={}; a case may not",
                file.value
            );
        }
    }
}

/// `--timeout` (the wall-clock watchdog of src/budget.rs) on a run needing far more than a
/// second ends it with exit status 2 and one line naming the timeout; on a fast run it changes
/// nothing.
#[test]
fn timeout_ends_a_long_run_with_one_line_and_changes_nothing_on_a_fast_one() {
    let os = |args: &[&str]| -> Vec<OsString> { args.iter().map(OsString::from).collect() };
    // (x+y+z)^100 (x-y+2z)^100: two powers of 5,151 terms each (fast, by the power recurrence)
    // and their product, 26 million products of coefficients of about 200 bits: 17 s here.
    // ((x+y+z)^200 alone, 30 s by binary powering, takes 0.2 s since the recurrence.)
    let slow = os(&["--timeout", "1", "prove", "(x+y+z)^100*(x-y+2z)^100", "0"]);
    let fast = ["prove", "(x+y)^3", "x^3 + 3x^2 y + 3x y^2 + y^3"];
    let mut fast_timed = os(&fast);
    fast_timed.extend(os(&["--timeout", "1"]));
    let runs = [slow, os(&fast), fast_timed];
    let results = parallel_map(&runs, |args| run(args, None));
    let (slow, fast, fast_timed) = (&results[0], &results[1], &results[2]);
    assert!(
        !slow.timed_out,
        "--timeout 1 did not end the run: {}",
        slow.describe()
    );
    assert_eq!(slow.status, Some(2), "{}", slow.describe());
    assert!(!slow.panicked(), "{}", slow.describe());
    let line = slow
        .one_stderr_line()
        .unwrap_or_else(|| panic!("not one line: {}", slow.describe()));
    assert!(line.contains("--timeout 1"), "{line}");
    assert!(slow.stdout.is_empty(), "{}", slow.stdout_text());
    // The fast run: the same answer with and without the watchdog.
    assert_eq!(fast.status, Some(0), "{}", fast.describe());
    assert_eq!(fast_timed.status, fast.status, "{}", fast_timed.describe());
    assert_eq!(fast_timed.stdout, fast.stdout);
    assert_eq!(fast_timed.stderr, fast.stderr);
    assert!(
        fast.stdout_text().starts_with("proved"),
        "{}",
        fast.stdout_text()
    );
}
