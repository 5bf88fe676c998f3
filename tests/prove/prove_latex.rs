//! `exactcheck prove` on formulas typed as the LaTeX source of a paper prints them: one
//! argument `LHS = RHS`, `\frac`, `\sqrt`, `\sum`, `\int`, `\frac{d}{dx}`, Greek letters, functions
//! without parentheses; bars `|x|` and factorials `n!` (in plain text too); the refusals are one
//! line naming what is wrong; a claims file reads LaTeX in its formula fields.

use crate::timed;

use timed::run_text as run;

/// `exactcheck prove ARGS` says "proved" with exit status 0 for each argument list.
pub(crate) fn each_is_proved(cases: &[&[&str]]) {
    each_gives(cases, 0, "proved");
}

/// `exactcheck prove ARGS` is refused with exit status 2 and one line containing the needle,
/// for each arguments and needle.
pub(crate) fn each_is_refused(cases: &[(&[&str], &str)]) {
    for (args, needle) in cases {
        let mut all = vec!["prove"];
        all.extend_from_slice(args);
        let (code, out, err) = run(&all);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

/// Runs `prove` with each list of arguments and checks the exit status and the verdict.
pub(crate) fn each_gives(cases: &[&[&str]], status: i32, verdict: &str) {
    for args in cases {
        let mut all = vec!["prove"];
        all.extend_from_slice(args);
        let (code, out, err) = run(&all);
        assert_eq!(code, status, "{args:?}: {out}{err}");
        assert!(out.starts_with(verdict), "{args:?}: {out}");
    }
}

#[test]
fn formulas_as_typed_in_latex_are_decided() {
    each_is_proved(&[
        &["\\frac{1}{2}", "0.5"][..],
        &["θ", "theta"],
        &["x^2-1 = (x-1)(x+1)"],
        &[
            "$\\sin\\theta = \\frac{2t}{1+t^2}$",
            "--where",
            "t = \\tan\\frac{\\theta}{2}",
        ],
        &["\\sum_{i=0}^{3}\\binom{3}{i}t^i(1-t)^{3-i} = 1"],
        &["\\int_0^1 t^2\\,dt = \\frac13"],
        &["$(a^2+b^2+c^2+d^2)^2 = (a^2+b^2-c^2-d^2)^2 + (2ac+2bd)^2 + (2ad-2bc)^2$"],
        &["\\sin^2\\theta + \\cos^2\\theta = 1"],
        &["\\frac{\\mathrm{d}}{\\mathrm{d}x} x^3 = 3x^2"],
        &["\\frac{\\partial}{\\partial x}\\left(x^2 y\\right) = 2xy"],
        &["\\frac{n(n+1)}{2} = \\frac{n^2 + n}{2}"],
        &["\\cos 2\\theta = \\cos^2\\theta - \\sin^2\\theta"],
        &["\\left(\\frac{1+\\sqrt5}{2}\\right)^2 = \\frac{1+\\sqrt5}{2} + 1"],
        &["\\int_{0}^{\\pi} \\sin t\\,dt = 2"],
        &["\\sin 30^\\circ = \\frac12"],
        &["\\left| a b \\right| = \\lvert a \\rvert \\lvert b \\rvert"],
        &["\\left| x \\right| = x", "--where", "x >= 0"],
        // Bars and factorials, in plain text as in LaTeX.
        &["|x|^2", "x^2"],
        &["|a|*|b|", "|a b|"],
        &["||x| - 1|^2", "(abs(x) - 1)^2"],
        &["5!", "120"],
        &["10!/(3!*7!)", "binomial(10, 3)"],
        &["$\\frac{6!}{2!\\,(6-2)!}$", "15"],
        &["sum(k, 0, 4, 4!/(k! (4 - k)!))", "16"],
    ]);
    // A misprint typed the same way fails at an exact point.
    let (code, out, err) = run(&[
        "prove",
        "\\sum_{i=0}^{3}\\binom{3}{i}t^{i+1}(1-t)^{3-i} = 1",
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("fails: at t = "), "{out}");
    let (code, out, err) = run(&["prove", "|x|", "x"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("fails: at x = -"), "{out}");
}

#[test]
fn latex_refusals_are_one_line_naming_the_problem() {
    each_is_refused(&[
        (&["\\log x", "1"][..], "\\log"),
        (&["\\left| x = x"], "not closed"),
        (&["\\sqrt[t]{8} = 2"], "an integer constant of at least 2"),
        (&["\\sin x^2 = 1"], "ambiguous"),
        (&["\\sin^{-1} x = 1"], "ambiguous"),
        (&["\\int_0^1 t^2 = 1"], "differential"),
        (&["a = b = c"], "unexpected character '='"),
        (&["|a|b|c|", "1"], "ambiguous"),
        (&["|x", "1"], "not closed"),
        (&["3!!", "720"], "double factorial"),
        (&["n!/(n-1)!", "n"], "integer constant, not n"),
        (
            &["diff(sum(k, 1, n, k^2), k)", "0"],
            "k is not a free variable",
        ),
        (
            &["diff(integrate(t^2, t, 0, x), t)", "0"],
            "t is not a free variable",
        ),
    ]);
}

#[test]
fn a_claims_file_reads_latex() {
    let root = env!("CARGO_MANIFEST_DIR");
    let file = format!("{root}/examples/latex.toml");
    let (code, out, err) = run(&["verify", &file]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("3 claims, 3 as expected"), "{out}");
}

#[test]
fn adjacent_letters_outside_latex_are_one_name_and_a_hint_says_so() {
    // Plain text: `2ac` is 2 times the variable `ac`, so Lebesgue's identity typed that way fails,
    // and a hint names the joined names.
    let (code, out, err) = run(&[
        "prove",
        "(a^2+b^2+c^2+d^2)^2 = (a^2+b^2-c^2-d^2)^2 + (2ac+2bd)^2 + (2ad-2bc)^2",
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        err.contains("hint: 'ac', 'bd', 'ad', 'bc' are each one variable") && err.contains("'a*c'"),
        "{err}"
    );
    // No hint where no name is spelled by one-letter variables.
    let (code, out, err) = run(&["prove", "ab + c = c + ab"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(!err.contains("hint"), "{err}");
}

#[test]
fn a_plain_side_beside_a_latex_side_is_read_as_latex_when_its_letters_say_so() {
    // `2uv` beside LaTeX with `u` and `v`: the product, and a note says so.
    for (lhs, rhs) in [
        ("\\frac{\\partial}{\\partial u}(u^2 v)", "2uv"),
        ("2uv", "\\frac{\\partial}{\\partial u}(u^2 v)"),
        (
            "\\det\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix}",
            "ad-bc",
        ),
    ] {
        let (code, out, err) = run(&["prove", lhs, rhs]);
        assert_eq!(code, 0, "{lhs} = {rhs}: {out}{err}");
        assert!(out.starts_with("proved"), "{out}");
        assert!(
            err.contains("is read as LaTeX, like the other side"),
            "{err}"
        );
    }
    // The LaTeX reading is only taken when it adds letters of the LaTeX side: `x1` is not
    // LaTeX, and `alphabeta` beside `\alpha \beta` reads `a`, `l`, ... that the LaTeX side lacks.
    for (lhs, rhs) in [("\\frac{a}{2}", "x1/2"), ("\\alpha \\beta", "alphabeta")] {
        let (code, out, err) = run(&["prove", lhs, rhs]);
        assert_eq!(code, 1, "{lhs} = {rhs}: {out}{err}");
        assert!(out.starts_with("fails"), "{out}");
        assert!(!err.contains("read as LaTeX"), "{err}");
    }
    // Both sides plain: names of several letters stay names.
    let (code, out, err) = run(&["prove", "2uv", "2*u*v"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(!err.contains("read as LaTeX"), "{err}");
}
