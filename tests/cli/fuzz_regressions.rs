//! Inputs found by the cargo-fuzz targets of fuzz/ (minimized), pinned in the normal test suite:
//! each test names what it pins, the old wrong behaviour and the right one.
use exactcheck::solve::{solve, Mode};

/// fuzz target `solve_json`: a JSON key with an escaped newline (`"li\ne"`) was quoted raw in
/// the unknown-field error, which then spanned two lines (the path and serde's message both
/// carry the key). Every error is one line: line breaks are escaped.
#[test]
fn unknown_json_key_with_a_newline_is_a_one_line_error() {
    let text = r#"{"kind":"ruled_line","base":[[0,0,0],[1,2,0],[2,0,0]],"directions":[[1,0,1],[0,0,1]],"li\ne":{"point":[1,"8/9",1],"direction":["-8/2","1/9",-2]}}"#;
    for mode in [Mode::Exact, Mode::Float, Mode::Both] {
        let message = solve(text, mode)
            .expect_err("an unknown field is refused")
            .to_string();
        assert!(!message.contains('\n'), "two lines: {message:?}");
        assert!(
            message.contains(r"unknown field `li\ne`"),
            "the key is named, escaped: {message:?}"
        );
    }
}

/// The same for the other line breaks and control characters a key may hold (`\r`, `\u2028`,
/// escape sequences of a terminal).
#[test]
fn unknown_json_keys_with_control_characters_are_one_line_errors() {
    for key in [r"a\rb", r"a\u2028b", r"a\u001b[2Jb", r"a\u0085b"] {
        let text = format!(r#"{{"kind":"conic","{key}":1}}"#);
        let message = solve(&text, Mode::Exact)
            .expect_err("an unknown field is refused")
            .to_string();
        assert!(
            !message.contains(['\n', '\r', '\u{2028}', '\u{1b}', '\u{85}']),
            "{key}: {message:?}"
        );
        assert!(message.contains("unknown field"), "{key}: {message:?}");
    }
}

/// fuzz target `prove`: a failing identity whose cleared residual (a 20th power plus two
/// fractions, coefficients of dozens of digits) took 28 s, nearly all in printing the residual
/// factored: the remainder sequences of its square-free factorization swelled in coefficient
/// size, which the work bound (counting terms only) did not see. The bound now weighs each
/// product by the sizes of its coefficients, so the factorization gives up early and the
/// expanded residual is printed; the verdict is the same `fails` with a counter-example.
#[test]
fn a_residual_with_swelling_gcds_prints_without_factoring_at_length() {
    let lhs = "(p ^2+p1^2^2+p3^2p4)^20+ (11+p++p^2*2^2+p3^2p4^2+p^- 2*p2*p4)^2 + (01+p^1/p1^2)^2";
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .args(["prove", lhs])
        .output()
        .expect("the binary runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.starts_with("fails: at "), "{text}");
    assert!(text.contains("where p != 0, p1 != 0"), "{text}");
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
