//! `exactcheck prove` on formulas pasted from a typeset page: superscripts, `·`, `−`, `π`, `√`
//! decide as their ASCII spelling does, and a square root written as a half-integer power of a
//! constant takes the square-root field as `sqrt` does.

use crate::timed;

use timed::run_text as run;

#[test]
fn typeset_formulas_get_the_verdicts_of_their_ascii_spelling() {
    for (lhs, rhs) in [
        ("(1 − t²)² + (2t)²", "(1 + t²)²"),
        ("√2·√8", "4"),
        ("cos(π/4)", "√2/2"),
        ("2^(1/2)·8^(1/2)", "4"),
        ("(x + 1)^(1/2)·(x + 1)^(1/2)", "x + 1"),
        ("√(x² + y²)²", "x² + y²"),
    ] {
        let (code, out, err) = run(&["prove", lhs, rhs]);
        assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
        assert!(out.starts_with("proved"), "{lhs} = {rhs}: {out}");
    }
    // A misprint pasted the same way fails with an exact point.
    let (code, out, err) = run(&["prove", "(1 − t²)² + (2t)²", "(1 + t)²"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("fails: at t = "), "{out}");
    // The ambiguous `√x²` is one line naming both readings.
    let (code, _, err) = run(&["prove", "√x²", "x"]);
    assert_eq!(code, 2, "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("√(x²) or (√x)²"), "{err}");
}
