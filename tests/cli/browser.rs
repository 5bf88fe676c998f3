//! The report in a real browser: Debian's Chromium, headless, driven by playwright-core from
//! `tests/browser/check.mjs` (which also renders `verify --latex` with KaTeX).
//!
//! Needs `/usr/bin/chromium` (or `$CHROMIUM`), `node`, and `npm ci` run in `tests/browser`.
//! When one is missing the test prints why and passes, unless `EXACTCHECK_BROWSER=1` (as
//! `.ci/run` sets after installing them): then a missing piece fails the test.

use crate::common;

use exactcheck::claims::Verdict;
use exactcheck::papers::catalogue;
use std::path::{Path, PathBuf};
use std::process::Command;

/// What is missing to run the browser check, if anything.
fn missing(dir: &Path, chromium: &Path) -> Option<String> {
    if !chromium.exists() {
        return Some(format!("{} is absent", chromium.display()));
    }
    for module in ["playwright-core", "katex"] {
        if !dir.join("node_modules").join(module).exists() {
            return Some(format!(
                "{}/node_modules/{module} is absent (run `npm ci` there)",
                dir.display()
            ));
        }
    }
    match Command::new("node").arg("--version").output() {
        Ok(o) if o.status.success() => None,
        _ => Some("node is not runnable".into()),
    }
}

#[test]
fn the_report_renders_in_chromium() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/browser");
    let chromium = PathBuf::from(std::env::var("CHROMIUM").unwrap_or("/usr/bin/chromium".into()));
    if let Some(why) = missing(&dir, &chromium) {
        if std::env::var("EXACTCHECK_BROWSER").is_ok_and(|v| v == "1") {
            panic!("EXACTCHECK_BROWSER=1 but {why}");
        }
        eprintln!("browser test skipped: {why} (set EXACTCHECK_BROWSER=1 to make this a failure)");
        return;
    }
    let work = Path::new(env!("CARGO_TARGET_TMPDIR")).join("browser");
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).unwrap();

    let out_dir = work.join("out");
    let report = common::exactcheck()
        .args(["report", "-o"])
        .arg(&out_dir)
        .args(["--samples", "200", "--quiet"])
        .output()
        .unwrap();
    assert!(
        report.status.success(),
        "{}",
        String::from_utf8_lossy(&report.stderr)
    );

    let latex = work.join("verify.tex");
    let verify = common::exactcheck()
        .args(["verify", "--latex"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&verify.stderr);
    assert!(
        verify.status.code() == Some(0),
        "verify --latex: {:?} {stderr}",
        verify.status
    );
    assert!(
        verify.stdout.iter().filter(|&&b| b == b'\n').count() >= 20,
        "verify --latex printed too little"
    );
    std::fs::write(&latex, &verify.stdout).unwrap();

    let claims = catalogue();
    let failing: Vec<&str> = claims
        .iter()
        .filter(|c| c.expected == Verdict::Fails)
        .map(|c| c.id)
        .collect();
    let figures = exactcheck::papers::figures().unwrap().len();
    let screenshot = work.join("report.png");
    let top = work.join("report-top.png");
    let check = Command::new("node")
        .current_dir(&dir)
        .env("CHROMIUM", &chromium)
        .arg("check.mjs")
        .arg("--report")
        .arg(out_dir.join("index.html"))
        .arg("--latex")
        .arg(&latex)
        .arg("--screenshot")
        .arg(&screenshot)
        .arg("--top")
        .arg(&top)
        .args(["--claims", &claims.len().to_string()])
        .args(["--failing", &failing.join(",")])
        .args(["--figures", &figures.to_string()])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&check.stdout);
    let stderr = String::from_utf8_lossy(&check.stderr);
    assert!(check.status.success(), "{stdout}{stderr}");
    eprintln!("{}", stdout.trim());
    let size = std::fs::metadata(&screenshot).unwrap().len();
    assert!(size > 10_000, "a {size}-byte screenshot is not the page");
    eprintln!(
        "screenshots: {} (full page), {} (top, as docs/report.png; -errata.png and -figures.png beside it)",
        screenshot.display(),
        top.display()
    );
}
