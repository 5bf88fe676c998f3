//! `exactcheck prove` with roots of index 3 and higher of constants, as printed:
//! `\sqrt[3]{2 + \sqrt5}`, `2^(1/3)`, `8^(2/3)`. They are real algebraic numbers (an odd index
//! keeps the sign, an even one takes the non-negative root of a non-negative number), so
//! Cardano's formula is proved exactly; its false twins fail with the exact difference; a root
//! of a non-constant, a negative number under an even index and an index that is not an
//! integer are refused in one line.

use crate::prove_latex::each_is_proved;
use crate::timed;

use timed::run_text as run;

#[test]
fn roots_of_constants_are_decided_exactly() {
    each_is_proved(&[
        // Cardano's solution of x^3 + 3x - 4 = 0 is x = 1.
        &["\\sqrt[3]{2+\\sqrt5} + \\sqrt[3]{2-\\sqrt5}", "1"][..],
        &["\\sqrt[3]{\\sqrt5+2} - \\sqrt[3]{\\sqrt5-2}", "1"],
        &["8^(1/3)", "2"],
        &["(-8)^(1/3)", "-2"],
        &["\\sqrt[4]{16}", "2"],
        &["27^(-1/3)", "1/3"],
        &["8^(2/3) x", "4 x"],
        &["(1 + 2^(1/3))^3", "3 + 3*2^(1/3) + 3*2^(2/3)"],
        &["2^(1/3) * 2^(2/3)", "2"],
        &["(-2)^(1/3)", "-2^(1/3)"],
        &["diff(2^(1/3) x^2, x)", "2*2^(1/3) x"],
    ]);
    let (code, out, err) = run(&["prove", "(2^(1/3))^3", "2", "--random", "5"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.starts_with("holds") && out.contains("c^3 - 2 = 0"),
        "{out}"
    );
}

#[test]
fn false_twins_fail_with_the_exact_difference() {
    for (lhs, rhs, shows) in [
        ("2^(1/3)", "1.26", "c = 2^(1/3), c^3 - 2 = 0"),
        (
            "\\sqrt[3]{2+\\sqrt5} + \\sqrt[3]{2-\\sqrt5}",
            "2",
            "LHS - RHS",
        ),
        // 1/(c - 1) = c^2 + c + 1 for c = 2^(1/3): the sides differ by c^2.
        (
            "(2^(1/3)+1)/(2^(1/3)-1)",
            "3+2*2^(1/3)+2^(2/3)",
            "Root(x^3 - 4",
        ),
    ] {
        let (code, out, err) = run(&["prove", lhs, rhs]);
        assert_eq!(code, 1, "{lhs} = {rhs}: {out}{err}");
        assert!(out.starts_with("fails"), "{out}");
        assert!(out.contains(shows), "{out}");
    }
}

#[test]
fn roots_that_are_not_taken_are_one_line_naming_the_problem() {
    for (lhs, expected) in [
        ("x^(1/3)", "found 1/3 of the non-constant x"),
        ("\\sqrt[3]{x}", "found 1/3 of the non-constant x"),
        (
            "(-16)^(1/4)",
            "a negative number has no real root of even index",
        ),
        (
            "\\sqrt[n]{2}",
            "the index of the root must be an integer constant of at least 2",
        ),
        (
            "\\sqrt[2.5]{2}",
            "the index of the root must be an integer constant of at least 2",
        ),
        ("2^(1/1000)", "algebraic-degree"),
    ] {
        let (code, out, err) = run(&["prove", lhs, "1"]);
        assert_eq!(code, 2, "{lhs}: {out}{err}");
        assert!(err.contains(expected), "{lhs}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
}
