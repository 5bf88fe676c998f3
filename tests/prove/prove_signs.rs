//! `exactcheck prove` with square roots whose branch argument needs the sign of a factor on
//! the domains: a factor in one variable decided by its real roots against the interval, a
//! product by the signs of its factors. The sign facts a proof uses are named in its verdict;
//! the false twins (a sign flipped, the domain dropped) fail with an exact counter-example or
//! stay undecided, never proved.

use crate::timed;

use timed::{prove_verdict as verdict, run_text as run};

#[test]
fn a_root_of_a_fraction_uses_the_sign_of_its_denominator_on_the_interval() {
    let args = [
        "sqrt((1+x)/(1-x))",
        "sqrt(1-x^2)/(1-x)",
        "--where",
        "-1 < x < 1",
    ];
    let (code, v, j) = verdict(&args);
    assert_eq!((code, v.as_str()), (0, "proved"), "{j}");
    let used: Vec<&str> = j["hypotheses_used"]
        .as_array()
        .unwrap_or_else(|| panic!("{j}"))
        .iter()
        .filter_map(|u| u.as_str())
        .collect();
    assert!(used.contains(&"x - 1 < 0 on -1 < x < 1"), "{j}");
    let (code, out, _) = run(&["prove", args[0], args[1], args[2], args[3]]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("x - 1 < 0 on -1 < x < 1"), "{out}");
}

#[test]
fn the_sign_flipped_twin_fails_at_an_exact_point() {
    let (code, v, j) = verdict(&[
        "sqrt((1+x)/(1-x))",
        "sqrt(1-x^2)/(x-1)",
        "--where",
        "-1 < x < 1",
    ]);
    assert_eq!((code, v.as_str()), (1, "fails"), "{j}");
    assert_eq!(j["point"]["x"].as_str(), Some("0"), "{j}");
}

#[test]
fn a_domain_past_the_root_of_the_denominator_is_never_proved() {
    // For 1 < x < 2 the left side is undefined: nothing is claimed there, and the sign of
    // 1 - x is not known on the interval.
    let (code, v, j) = verdict(&[
        "sqrt((1+x)/(1-x))",
        "sqrt(1-x^2)/(1-x)",
        "--where",
        "-1 < x < 2",
    ]);
    assert_ne!(v, "proved", "{j}");
    assert_ne!(code, 0, "{j}");
}

#[test]
fn a_square_factor_leaves_the_root_with_the_sign_of_its_base() {
    let (code, v, j) = verdict(&["sqrt(x^2*(1+x))", "x*sqrt(1+x)", "--where", "x >= 0"]);
    assert_eq!((code, v.as_str()), (0, "proved"), "{j}");
    // Without the domain x = -1/2 is a counter-example: the root is |x| sqrt(1 + x).
    let (code, v, j) = verdict(&["sqrt(x^2*(1+x))", "x*sqrt(1+x)"]);
    assert_eq!((code, v.as_str()), (1, "fails"), "{j}");
    let x: exactcheck_exact::Rational = j["point"]["x"].as_str().unwrap().parse().unwrap();
    assert!(x < exactcheck_exact::Rational::ZERO, "{j}");
    // On x <= -1/2 the other branch holds.
    let (code, v, j) = verdict(&[
        "sqrt(x^2*(1+x))",
        "-x*sqrt(1+x)",
        "--where",
        "-1 <= x <= -1/2",
    ]);
    assert_eq!((code, v.as_str()), (0, "proved"), "{j}");
}

#[test]
fn a_constant_factor_of_the_radicand_comes_out() {
    let (code, v, j) = verdict(&["sqrt(4 - 4*t^2)", "2*sqrt(1-t^2)"]);
    assert_eq!((code, v.as_str()), (0, "proved"), "{j}");
    let (code, v, j) = verdict(&["sqrt(4 - 4*t^2)", "-2*sqrt(1-t^2)"]);
    assert_eq!((code, v.as_str()), (1, "fails"), "{j}");
}

#[test]
fn a_product_of_factors_of_known_signs_on_an_interval() {
    // sqrt((1 - t)^2 (2 + t)) = (1 - t) sqrt(2 + t) needs 1 - t >= 0 on 0 <= t <= 1.
    let (code, v, j) = verdict(&[
        "sqrt((1-t)^2*(2+t))",
        "(1-t)*sqrt(2+t)",
        "--where",
        "0 <= t <= 1",
    ]);
    assert_eq!((code, v.as_str()), (0, "proved"), "{j}");
    // Past t = 1 the sign of 1 - t flips: a counter-example there.
    let (code, v, j) = verdict(&[
        "sqrt((1-t)^2*(2+t))",
        "(1-t)*sqrt(2+t)",
        "--where",
        "0 <= t <= 3",
    ]);
    assert_eq!((code, v.as_str()), (1, "fails"), "{j}");
}
