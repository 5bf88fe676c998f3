//! `exactcheck prove` on matrices and determinants typed as LaTeX: `pmatrix` and the other
//! matrix environments, `vmatrix`, bars around an `array`, `\det`; equations pasted from an
//! `align` (with `&`); malformed matrices refused in one line.

use crate::timed;

use timed::run_text as run;

#[test]
fn determinants_and_matrix_identities_in_latex_are_decided() {
    for args in [
        &["\\det\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix} = ad - bc"][..],
        // The Vandermonde determinant.
        &["\\begin{vmatrix} 1 & a & a^2 \\\\ 1 & b & b^2 \\\\ 1 & c & c^2 \\end{vmatrix} = (b-a)(c-a)(c-b)"],
        &["\\left|\\begin{array}{cc} a & b \\\\[2pt] c & d \\\\ \\end{array}\\right| = ad - bc"],
        // The product rule of determinants, and a matrix times a column vector.
        &["\\det\\left(\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix}\\begin{pmatrix} p & q \\\\ r & s \\end{pmatrix}\\right) = (ad-bc)(ps-qr)"],
        &["\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix}\\begin{pmatrix} x \\\\ y \\end{pmatrix} = \\begin{bmatrix} ax+by \\\\ cx+dy \\end{bmatrix}"],
        // An equation pasted from an `align` environment.
        &["$\\cos 2\\theta &= \\cos^2\\theta - \\sin^2\\theta$"],
    ] {
        let mut all = vec!["prove"];
        all.extend_from_slice(args);
        let (code, out, err) = run(&all);
        assert_eq!(code, 0, "{args:?}: {out}{err}");
        assert!(out.starts_with("proved"), "{args:?}: {out}");
    }
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
