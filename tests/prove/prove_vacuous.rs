//! Claims whose conditions leave no real point: the domains, the relations, the hypotheses and
//! the conditions under which the square roots and the fractions are defined. `prove` refuses
//! them as bad input naming the conditions, claims files report them undecided, and a proof
//! under conditions of several variables where no point was found says that it may be vacuous.

use crate::common::verify_json;
use crate::timed;

use timed::run_text as run;

/// `prove ARGS`: its exit status, standard output and standard error.
fn prove(args: &[&str]) -> (i32, String, String) {
    let mut all = vec!["prove"];
    all.extend(args);
    run(&all)
}

#[test]
fn a_root_with_a_negative_radicand_everywhere_in_the_domain_is_refused() {
    for (args, conditions) in [
        (
            &["sqrt(x)*sqrt(x)", "x", "--where", "x < 0"][..],
            "no x satisfies x < 0 where the square roots are defined (x >= 0)",
        ),
        (
            &["sqrt(x)", "1", "--where", "x < 0"][..],
            "no x satisfies x < 0 where the square roots are defined (x >= 0)",
        ),
        (
            &["sqrt(x-1)*sqrt(1-x)", "0", "--where", "x > 2"][..],
            "no x satisfies x > 2 where the square roots are defined (x - 1 >= 0, 1 - x >= 0)",
        ),
        // An irrational end: 2 - x^2 >= 0 stops at sqrt(2) < 3/2.
        (
            &["sqrt(2 - x^2)^2", "2 - x^2", "--where", "x >= 3/2"][..],
            "no x satisfies x >= 3/2 where the square roots are defined (2 - x^2 >= 0)",
        ),
    ] {
        let (code, out, err) = prove(args);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert_eq!(
            err.trim_end(),
            format!("exactcheck: error: --where: {conditions}: the claim is vacuous"),
            "{args:?}"
        );
    }
}

#[test]
fn relations_and_denominators_without_a_real_point_are_refused() {
    // x^2 = 2 has no point above 2.
    let (code, _, err) = prove(&["x^2", "2", "--where", "x^2 = 2", "--where", "x > 2"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("no x satisfies x > 2, x^2 = 2 where the sides are defined"),
        "{err}"
    );
    // Relations alone are read over the complex numbers (s^2 = -1 for the imaginary unit), as
    // their consistency is: proved modulo them, without a warning.
    let (code, out, err) = prove(&["s^4", "1", "--where", "s^2 = -1"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.starts_with("proved: ") && !out.contains("vacuous"),
        "{out}"
    );
    // The sides are not defined at the only point of the relation.
    let (code, _, err) = prove(&["(x^2 - 1)/(x - 1)", "x + 1", "--where", "x = 1"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("no x satisfies x = 1 where the sides are defined"),
        "{err}"
    );
    // Inconsistent relations keep their own message.
    let (code, _, err) = prove(&["x", "1", "--where", "x = 1", "--where", "x = 2"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("are inconsistent"), "{err}");
}

#[test]
fn claims_with_a_point_stay_proved_without_a_warning() {
    for args in [
        &["sqrt(x)*sqrt(x)", "x", "--where", "x > 0"][..],
        &["sqrt(x)*sqrt(x)", "x", "--where", "x >= 0"][..],
        &["sqrt(x)*sqrt(x)", "x"][..],
        // Only the point 0 is left, and it is a point.
        &["sqrt(x)*sqrt(x)", "x", "--where", "x <= 0"][..],
        // Several variables: the search finds a point of the circle.
        &["x^2 + y^2", "1", "--where", "x^2 + y^2 = 1"][..],
        &["sqrt(x)*sqrt(y)", "sqrt(x*y)", "--where", "x > 0, y > 0"][..],
    ] {
        let (code, out, err) = prove(args);
        assert_eq!(code, 0, "{args:?}: {out}{err}");
        assert!(out.starts_with("proved: "), "{args:?}: {out}");
        assert!(!out.contains("vacuous"), "{args:?}: {out}");
    }
}

#[test]
fn a_proof_where_no_point_was_found_says_it_may_be_vacuous() {
    // x y - 1 >= 0 has no point with x < 0 < y; emptiness in two variables is not decided,
    // and the search finds no point.
    let (code, out, err) = prove(&["sqrt(x*y - 1)^2", "x*y - 1", "--where", "x < 0, y > 0"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.trim_end()
            .ends_with("(no point satisfying the hypotheses was found: the claim may be vacuous)"),
        "{out}"
    );
}

#[test]
fn an_absolute_value_is_no_square_root_in_the_sentence() {
    let (code, out, err) = prove(&["abs(x)^2", "x^2"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(!out.contains("square root"), "{out}");
    // A root the user wrote is still named.
    let (_, out, _) = prove(&["abs(x)*sqrt(x)^2", "abs(x)*x"]);
    assert!(
        out.contains("(the square roots are defined where x >= 0)"),
        "{out}"
    );
}

#[test]
fn claims_files_report_vacuous_claims_undecided() {
    let rows = verify_json("tests/claims_file/vacuous.toml", 1);
    assert_eq!(rows.verdicts(), ["undecided", "undecided", "proved"]);
    assert_eq!(
        rows.evidence("vacuous.root"),
        "no x satisfies x < 0 where the square roots are defined (x >= 0): the claim is vacuous"
    );
    assert!(
        rows.evidence("vacuous.two_roots")
            .contains("the claim is vacuous"),
        "{:?}",
        rows.rows
    );
}
