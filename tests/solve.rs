//! `exactcheck solve` end to end: the JSON answers of the existing kinds stay what they were
//! before the contract became types (golden files), and every class of bad input is one line
//! naming the field, exit status 2.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn solve(problem: &[u8], extra: &[&str]) -> Output {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .arg("solve")
        .args(extra)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the binary runs");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(problem)
        .expect("write");
    child.wait_with_output().expect("finishes")
}

fn golden_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/solve_golden")
}

/// Fields added to the answers after the golden files were saved (each documented in the
/// README); everything else must be exactly as before.
const ADDED_FIELDS: [&str; 0] = [];

fn without_added(mut v: serde_json::Value) -> serde_json::Value {
    if let Some(o) = v.as_object_mut() {
        for k in ADDED_FIELDS {
            o.remove(k);
        }
        if let Some(f) = o.get_mut("float").and_then(|f| f.as_object_mut()) {
            for k in ADDED_FIELDS {
                f.remove(k);
            }
        }
    }
    v
}

/// The answers saved from the hand-walked implementation (tests/solve_golden/NAME.MODE.out)
/// are reproduced field for field, in the same order.
#[test]
fn answers_of_the_existing_kinds_are_unchanged() {
    let mut checked = 0;
    let mut entries: Vec<_> = std::fs::read_dir(golden_dir())
        .expect("golden dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "out"))
        .collect();
    entries.sort();
    for out in entries {
        let stem = out.file_stem().unwrap().to_string_lossy().into_owned();
        let (name, mode) = stem.rsplit_once('.').expect("NAME.MODE.out");
        let problem = std::fs::read(golden_dir().join(format!("{name}.json"))).expect("input");
        let flag = match mode {
            "exact" => vec![],
            "float" => vec!["--float"],
            "both" => vec!["--both"],
            other => panic!("unknown mode {other}"),
        };
        let o = solve(&problem, &flag);
        assert!(
            o.status.success(),
            "{stem}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let got: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON answer");
        let want: serde_json::Value =
            serde_json::from_slice(&std::fs::read(&out).expect("golden")).expect("golden JSON");
        let got = without_added(got);
        assert_eq!(
            got.as_object().map(|o| o.keys().cloned().collect::<Vec<_>>()),
            want.as_object().map(|o| o.keys().cloned().collect::<Vec<_>>()),
            "{stem}: field order"
        );
        assert_eq!(got, want, "{stem}");
        checked += 1;
    }
    assert_eq!(checked, 13, "every golden answer was compared");
}
