//! Build facts the HTML report (`exactcheck report`) states in its header, read once at build
//! time so the binary reports what it was built from:
//! * `EXACTCHECK_GIT_COMMIT`: `git rev-parse --short HEAD`, or empty when not built from a git
//!   checkout (no git, or no repository: tolerated);
//! * `EXACTCHECK_RUSTC`: `$RUSTC --version`;
//! * `EXACTCHECK_NUM_BIGINT`, `EXACTCHECK_NUM_RATIONAL`: the versions `Cargo.lock` pins
//!   (several versions joined by ", "; empty without a lock file). Read from the lock file
//!   rather than `cargo metadata` so the build needs neither the network nor a second cargo.
//!
//! Rebuilds when `Cargo.lock` or the checked-out commit changes (the HEAD file and the branch's
//! ref, when they exist: a path that does not exist would make cargo rerun this on every
//! build).

use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    let dir = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let lock = dir.join("Cargo.lock");
    println!("cargo:rerun-if-changed=build.rs");
    if lock.exists() {
        println!("cargo:rerun-if-changed={}", lock.display());
    }
    let commit = git(&dir, &["rev-parse", "--short", "HEAD"]).unwrap_or_default();
    if !commit.is_empty() {
        for path in watched_git_files(&dir) {
            println!("cargo:rerun-if-changed={}", path.display());
        }
    }
    println!("cargo:rustc-env=EXACTCHECK_GIT_COMMIT={commit}");

    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let rustc_version = Command::new(&rustc)
        .arg("--version")
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default();
    println!("cargo:rustc-env=EXACTCHECK_RUSTC={rustc_version}");

    let lock_text = std::fs::read_to_string(&lock).unwrap_or_default();
    for (crate_name, var) in [
        ("num-bigint", "EXACTCHECK_NUM_BIGINT"),
        ("num-rational", "EXACTCHECK_NUM_RATIONAL"),
    ] {
        println!(
            "cargo:rustc-env={var}={}",
            locked_versions(&lock_text, crate_name).join(", ")
        );
    }
}

/// `git ARGS` in `dir`: its trimmed standard output, `None` when git is missing or fails.
fn git(dir: &Path, args: &[&str]) -> Option<String> {
    let out = Command::new("git")
        .args(args)
        .current_dir(dir)
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// The files whose change means a new commit is checked out: HEAD, the branch's ref (loose or
/// packed), each only when it exists.
fn watched_git_files(dir: &Path) -> Vec<PathBuf> {
    let mut paths = Vec::new();
    let mut git_path = |p: &str| {
        if let Some(path) = git(dir, &["rev-parse", "--git-path", p]) {
            let path = dir.join(path);
            if path.exists() {
                paths.push(path);
            }
        }
    };
    git_path("HEAD");
    git_path("packed-refs");
    if let Some(branch) = git(dir, &["symbolic-ref", "-q", "HEAD"]) {
        git_path(&branch);
    }
    paths
}

/// The versions of `name` in a `Cargo.lock` (its `[[package]]` entries).
fn locked_versions(lock: &str, name: &str) -> Vec<String> {
    let mut out = Vec::new();
    for entry in lock.split("[[package]]").skip(1) {
        let field = |key: &str| {
            entry.lines().find_map(|l| {
                l.trim()
                    .strip_prefix(key)
                    .and_then(|r| r.trim().strip_prefix('='))
                    .map(|v| v.trim().trim_matches('"').to_string())
            })
        };
        if field("name").as_deref() == Some(name) {
            if let Some(v) = field("version") {
                out.push(v);
            }
        }
    }
    out
}
