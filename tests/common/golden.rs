//! Golden files: committed outputs that tests compare with, and the one variable that rewrites
//! them all. With `EXACTCHECK_BLESS=1` every golden test writes what the code now produces
//! before comparing (the malformed corpus's `.expect` files, `tests/solve_golden/`, the JSON
//! Schemas in `docs/schema/`, the figures in `docs/`); review the change with `git diff`.

use std::path::Path;

/// Whether this run rewrites the golden files (`EXACTCHECK_BLESS=1`).
#[allow(dead_code)] // not every test crate that includes this module has golden files
pub fn blessing() -> bool {
    std::env::var_os("EXACTCHECK_BLESS").is_some_and(|v| v == "1")
}

/// Asserts that the committed file at `path` (relative to the repository root) holds exactly
/// `want`; when blessing, writes `want` there first.
#[allow(dead_code)] // not every test crate that includes this module compares whole files
pub fn assert_golden(path: &str, want: &str) {
    let full = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    if blessing() {
        if let Some(dir) = full.parent() {
            std::fs::create_dir_all(dir)
                .unwrap_or_else(|e| panic!("create {path}'s directory: {e}"));
        }
        std::fs::write(&full, want).unwrap_or_else(|e| panic!("write {path}: {e}"));
    }
    let have = std::fs::read_to_string(&full).unwrap_or_default();
    assert!(
        have == want,
        "{path} is stale: rerun the test with EXACTCHECK_BLESS=1 and review `git diff {path}`"
    );
}
