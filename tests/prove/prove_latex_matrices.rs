//! `exactcheck prove` on matrices and determinants typed as LaTeX: `pmatrix` and the other
//! matrix environments, `vmatrix`, bars around an `array`, `\det`; equations pasted from an
//! `align` (with `&`); malformed matrices refused in one line; and a claims file's failing
//! verdict naming the names of several letters spelled by one-letter variables (`2ac`).

use crate::timed;

use crate::prove_latex::each_is_proved;
use timed::run_text as run;

#[test]
fn determinants_and_matrix_identities_in_latex_are_decided() {
    each_is_proved(&[
        &["\\det\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix} = ad - bc"][..],
        // The Vandermonde determinant.
        &["\\begin{vmatrix} 1 & a & a^2 \\\\ 1 & b & b^2 \\\\ 1 & c & c^2 \\end{vmatrix} = (b-a)(c-a)(c-b)"],
        &["\\left|\\begin{array}{cc} a & b \\\\[2pt] c & d \\\\ \\end{array}\\right| = ad - bc"],
        // The product rule of determinants, and a matrix times a column vector.
        &["\\det\\left(\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix}\\begin{pmatrix} p & q \\\\ r & s \\end{pmatrix}\\right) = (ad-bc)(ps-qr)"],
        &["\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix}\\begin{pmatrix} x \\\\ y \\end{pmatrix} = \\begin{bmatrix} ax+by \\\\ cx+dy \\end{bmatrix}"],
        // An equation pasted from an `align` environment.
        &["$\\cos 2\\theta &= \\cos^2\\theta - \\sin^2\\theta$"],
    ]);
    // A misprinted entry fails at an exact point.
    let (code, out, err) = run(&[
        "prove",
        "\\begin{vmatrix} a & b \\\\ c & d \\end{vmatrix} = ad + bc",
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("fails: at "), "{out}");
}

#[test]
fn malformed_matrices_are_one_line_naming_the_problem() {
    for (text, needle) in [
        (
            "\\begin{pmatrix} a & b \\\\ c \\end{pmatrix} = 0",
            "row 2 of the pmatrix has 1 entry, row 1 has 2 entries",
        ),
        (
            "\\begin{vmatrix} a \\end{pmatrix} = 0",
            "is closed by \\end{pmatrix}",
        ),
        ("\\begin{cases} a \\end{cases} = 0", "'cases' is not read"),
        ("\\begin{pmatrix} a & b = 0", "expected an operator, '&'"),
        (
            "\\begin{pmatrix} a & b \\end{pmatrix} = 0",
            "LHS is a 1x2 matrix, RHS is a scalar",
        ),
    ] {
        let (code, out, err) = run(&["prove", text]);
        assert_eq!(code, 2, "{text}: {out}{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{text}: {err}");
    }
}

#[test]
fn a_claims_file_names_joined_names_in_a_failing_verdict() {
    let path = std::env::temp_dir().join(format!("exactcheck-joined-{}.toml", std::process::id()));
    std::fs::write(
        &path,
        r#"
[[claim]]
id = "plain"
kind = "identity"
lhs = "(a^2+b^2+c^2+d^2)^2"
rhs = "(a^2+b^2-c^2-d^2)^2 + (2ac+2bd)^2 + (2ad-2bc)^2"
expect = "fails"

[[claim]]
id = "latex"
kind = "identity"
lhs = "$(a^2+b^2+c^2+d^2)^2$"
rhs = "$(a^2+b^2-c^2-d^2)^2 + (2ac+2bd)^2 + (2ad-2bc)^2$"
"#,
    )
    .unwrap();
    let rows = crate::common::verify_json(path.to_str().unwrap(), 0);
    std::fs::remove_file(&path).ok();
    let plain = rows.row("plain");
    assert_eq!(plain["verdict"], "fails", "{plain}");
    let evidence = plain["evidence"].as_str().unwrap();
    assert!(
        evidence.contains("hint: 'ac', 'bd', 'ad', 'bc' are each one variable"),
        "{evidence}"
    );
    let latex = rows.row("latex");
    assert_eq!(latex["verdict"], "proved", "{latex}");
    assert!(
        !latex["evidence"].as_str().unwrap().contains("hint"),
        "{latex}"
    );
}
