//! Helpers shared by the CLI end-to-end tests (each test binary `tests/GROUP/main.rs` includes
//! this module with `#[path = "../common/mod.rs"] mod common;`, its modules `use crate::common`).

// Each test crate uses a different part of this module.
#![allow(dead_code)]

use std::process::{Output, Stdio};

mod exe;
pub mod golden;
#[allow(unused_imports)]
pub use exe::{exactcheck, EXACTCHECK};

/// Runs `exactcheck solve EXTRA...` with `problem` on standard input.
pub fn solve_stdin(problem: impl AsRef<[u8]>, extra: &[&str]) -> Output {
    use std::io::Write;
    let mut child = exactcheck()
        .arg("solve")
        .args(extra)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(problem.as_ref())
        .expect("write");
    child.wait_with_output().expect("finishes")
}

/// Runs `exactcheck solve EXTRA...` on `problem` and asserts the refusal contract: exit status 2,
/// nothing on standard output, one line on standard error containing every needle; returns it.
#[allow(dead_code)] // each test crate includes this module; not all of them test refusals
pub fn refused(problem: &str, extra: &[&str], needles: &[&str]) -> String {
    let o = solve_stdin(problem.as_bytes(), extra);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{problem}: {err}");
    assert_eq!(err.lines().count(), 1, "{problem}: {err}");
    assert!(o.stdout.is_empty(), "{problem}");
    for n in needles {
        assert!(err.contains(n), "{problem}: {err:?} lacks {n:?}");
    }
    err
}

/// Whether the JSON holds a `null` inside an array that has numbers: a NaN or infinity that
/// serde_json wrote as `null` (answers are refused before that; see `solve::finite`).
/// `ruled_line`'s `lambda_at_ends` is exempt: there `null` is the contract's unbounded end of
/// the covered part of the line beside the other end (found by `solve_props` on
/// `base [[-1,-3,2]]`, directions `[[-2,-1,-1],[2,-1,1]]`, line direction `(-2,-1,-1)`).
/// The `approx` paths an exact answer lists in `approx_out_of_range` (f64 twins of exact values
/// beyond f64's range, written as `null` on purpose) are exempt as well; a listed path that is
/// not `null` in the answer counts as a finding.
#[allow(dead_code)] // not every test crate that includes this module reads answers
pub fn has_null_number(v: &serde_json::Value) -> bool {
    let mut v = v.clone();
    if let Some(listed) = v.get("approx_out_of_range").cloned() {
        for path in listed.as_array().into_iter().flatten() {
            match path.as_str().and_then(|p| pointer_mut(&mut v, p)) {
                Some(x) if x.is_null() => *x = serde_json::Value::from(0),
                _ => return true,
            }
        }
    }
    null_beside_number(&v)
}

#[allow(dead_code)]
/// The value at a path as `solve::finite` writes it (`approx.point[0]`, `poles[1].approx`).
fn pointer_mut<'a>(v: &'a mut serde_json::Value, path: &str) -> Option<&'a mut serde_json::Value> {
    let mut cur = v;
    for part in path.split('.') {
        let (key, rest) = part.split_at(part.find('[').unwrap_or(part.len()));
        if !key.is_empty() {
            cur = cur.get_mut(key)?;
        }
        for index in rest.split(['[', ']']).filter(|s| !s.is_empty()) {
            cur = cur.get_mut(index.parse::<usize>().ok()?)?;
        }
    }
    Some(cur)
}

#[allow(dead_code)]
fn null_beside_number(v: &serde_json::Value) -> bool {
    use serde_json::Value;
    match v {
        Value::Array(a) => {
            let numbers = a.iter().any(Value::is_number);
            a.iter()
                .any(|x| (numbers && x.is_null()) || null_beside_number(x))
        }
        Value::Object(o) => o
            .iter()
            .any(|(k, x)| k != "lambda_at_ends" && null_beside_number(x)),
        _ => false,
    }
}

/// `C(n, k)` as an exact rational.
#[allow(dead_code)] // not every test crate that includes this module uses it
pub fn binom(n: usize, k: usize) -> exactcheck_exact::Rational {
    use exactcheck_exact::Rational;
    let mut c = Rational::ONE;
    for i in 0..k {
        c = c * Rational::from((n - i) as i64) / Rational::from((i + 1) as i64);
    }
    c
}

/// The Bernstein polynomial `sum c_i C(n, i) t^i (1 - t)^(n - i)` as a power-basis polynomial,
/// built from `(1 - t)` and `t` (independently of the workspace's basis conversions).
#[allow(dead_code)]
pub fn bernstein_upoly(c: &[exactcheck_exact::Rational]) -> exactcheck_exact::univariate::UPoly {
    use exactcheck_core::Ring;
    use exactcheck_exact::univariate::UPoly;
    let n = c.len() - 1;
    let t = UPoly::x();
    let s = UPoly::one().sub_ref(&t);
    let mut acc = UPoly::zero();
    for (i, ci) in c.iter().enumerate() {
        let mut term = UPoly::constant(ci.clone() * binom(n, i));
        for _ in 0..i {
            term = term.mul_ref(&t);
        }
        for _ in 0..n - i {
            term = term.mul_ref(&s);
        }
        acc = acc.add_ref(&term);
    }
    acc
}

/// The rows of `exactcheck verify FILE --json` (a claims file), see [`verify_json`].
#[allow(dead_code)] // not every test crate that includes this module checks claims files
pub struct VerifyRows {
    /// The JSON rows, in file order.
    pub rows: Vec<serde_json::Value>,
    /// Standard error.
    pub stderr: String,
}

#[allow(dead_code)]
impl VerifyRows {
    /// The row of claim `id` (panics naming the id and the rows when there is none).
    pub fn row(&self, id: &str) -> &serde_json::Value {
        self.rows
            .iter()
            .find(|r| r["id"] == id)
            .unwrap_or_else(|| panic!("{id} in {:?}", self.rows))
    }

    /// The verdict of every row, in order.
    pub fn verdicts(&self) -> Vec<&str> {
        self.rows
            .iter()
            .map(|r| r["verdict"].as_str().expect("a verdict"))
            .collect()
    }

    /// The evidence of claim `id`.
    pub fn evidence(&self, id: &str) -> &str {
        self.row(id)["evidence"].as_str().expect("evidence")
    }
}

/// Runs `exactcheck verify FILE --json` in the workspace root (`file` relative to it), asserts
/// its exit status and returns its rows.
#[allow(dead_code)]
pub fn verify_json(file: &str, status: i32) -> VerifyRows {
    let out = exactcheck()
        .args(["verify", file, "--json"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    assert_eq!(out.status.code(), Some(status), "{file}: {out:?}");
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("{file}: not JSON rows ({e}): {out:?}"));
    VerifyRows {
        rows: rows.as_array().expect("an array of rows").clone(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}
