//! The square-root field and the Gröbner bases under hostile input (issues 13 and 16): many
//! square roots, their inverses and denesting, square roots of huge numbers, relations whose
//! Gröbner basis explodes, high powers modulo a unit circle. Each case pins the old failure (an
//! abort allocating gigabytes, minutes of work, a misleading message) and asserts a correct
//! answer or one line naming the limit, exit status 2, within a generous kill timeout.

use crate::timed;

/// Runs exactcheck with `args` under the shared kill-timeout (a hang fails the test; no time is
/// asserted).
fn run(args: &[String]) -> timed::Run {
    let os: Vec<std::ffi::OsString> = args.iter().map(Into::into).collect();
    let r = timed::run(&os, None);
    assert!(!r.timed_out, "exactcheck {args:?}: {}", r.describe());
    r
}

fn args(a: &[&str]) -> Vec<String> {
    a.iter().map(|s| s.to_string()).collect()
}

/// Asserts exit 2 and exactly one line on stderr containing `needle`.
fn refused(a: &[String], needle: &str) -> String {
    let out = run(a);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status, Some(2), "{a:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{a:?}: {err}");
    assert!(err.contains(needle), "{a:?}: {err}");
    assert!(!err.contains("panicked"), "{err}");
    err
}

/// Asserts the exit status and returns stdout.
fn answered(a: &[String], code: i32) -> String {
    let out = run(a);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status, Some(code), "{a:?}: {err}");
    assert!(
        !err.contains("panicked") && !err.contains("exceeds the limit"),
        "{err}"
    );
    String::from_utf8_lossy(&out.stdout).to_string()
}

/// `sqrt(2) + sqrt(3) + ...` over the first `k` primes.
fn prime_roots(k: usize) -> String {
    (2u64..)
        .filter(|&n| (2..n).take_while(|d| d * d <= n).all(|d| n % d != 0))
        .take(k)
        .map(|p| format!("sqrt({p})"))
        .collect::<Vec<_>>()
        .join("+")
}

/// 25 primes: the 8th power aborted allocating 5.4 GB, the inverse asked for 2.2 TB; 12 primes:
/// the inverse took 10-16 s. Refused under the default `radicands = 10`.
#[test]
fn many_square_roots_are_refused() {
    let s25 = prime_roots(25);
    refused(
        &args(&["prove", &format!("({s25})^8"), "0"]),
        "the limit radicands = 10 (found 25;",
    );
    refused(
        &args(&["prove", &format!("1/({s25})"), "0"]),
        "the limit radicands = 10",
    );
    refused(
        &args(&["prove", &format!("1/({})", prime_roots(12)), "0"]),
        "the limit radicands = 10 (found 12;",
    );
}

/// At the default limit the work is done: the inverse of ten roots, checked by multiplying back.
#[test]
fn ten_square_roots_are_computed() {
    let s10 = prime_roots(10);
    let out = answered(&args(&["prove", &format!("({s10}) * (1/({s10}))"), "1"]), 0);
    assert!(out.starts_with("proved"), "{out}");
}

/// Denesting `sqrt((S10)^2)` took 3.4-14 s (every perfect-square norm ran the whole trial
/// division); S12 more than 20 s, now refused.
#[test]
fn denesting_squares_of_sums_of_roots() {
    let s10 = prime_roots(10);
    let out = answered(&args(&["prove", &format!("sqrt(({s10})^2)"), &s10]), 0);
    assert!(out.starts_with("proved"), "{out}");
    let s12 = prime_roots(12);
    refused(
        &args(&["prove", &format!("sqrt(({s12})^2)"), &s12]),
        "the limit radicands = 10",
    );
}

/// Square roots of numbers with a huge square part are extracted at once (a prime power is
/// divided out in O(log e) divisions); a factor beyond the trial division is named as such.
#[test]
fn square_roots_of_big_numbers() {
    let out = answered(
        &args(&["prove", "sqrt((2^1000)^10*3)", "2^5000*sqrt(3)"]),
        0,
    );
    assert!(out.starts_with("proved"), "{out}");
    let out = answered(
        &args(&["prove", "sqrt((2^1024)^100*2)", "(2^1024)^50*sqrt(2)"]),
        0,
    );
    assert!(out.starts_with("proved"), "{out}");
    // A radicand beyond the square-root field's factoring: decided as a real algebraic number.
    let out = answered(
        &args(&[
            "prove",
            "sqrt(1208925819614629174706189*1208925819614629174706193)",
            "0",
        ]),
        1,
    );
    assert!(out.starts_with("fails"), "{out}");
}

/// Three dense cubics in x, y, z as relations did not finish in 300 s: their lex Gröbner basis
/// reaches coefficients of 200,000 digits. Refused on the coefficient size.
#[test]
fn dense_cubic_relations_stop_on_a_limit() {
    let cubics = [
        "6 + 7*z + 7*z^2 - 7*z^3 + 9*y + 9*y*z - 5*y*z^2 - 2*y^2 + 6*y^2*z - 2*y^3 + x + 4*x*z - 5*x*z^2 + 4*x*y - 3*x*y*z + x*y^2 + 8*x^2 - 4*x^2*z - 9*x^2*y + 4*x^3 = 0",
        "-3 + z + 7*z^2 - 5*z^3 - 9*y - y*z + y*z^2 - 8*y^2 + y^2*z - 4*y^3 - x + 5*x*z + 6*x*z^2 - 7*x*y + 5*x*y*z - 4*x*y^2 + 5*x^2 - 7*x^2*z + 8*x^2*y - 8*x^3 = 0",
        "8 - 3*z - 3*z^2 + 9*z^3 - y + y*z - 3*y*z^2 + 3*y^2 - 4*y^2*z - 6*y^3 + 2*x + 9*x*z - 8*x*z^2 - 6*x*y - 7*x*y*z - 7*x*y^2 - 6*x^2 + x^2*z - 2*x^2*y + 5*x^3 = 0",
    ];
    let mut a = args(&["prove", "x", "0"]);
    for c in cubics {
        a.push("--where".into());
        a.push(c.into());
    }
    refused(&a, "--where: size of a Groebner basis coefficient exceeds the limit groebner-bits = 10000 bits");
}

/// 200 relations `vI = I` took more than 20 s (every pair re-ranked at every step).
#[test]
fn two_hundred_linear_relations() {
    let sum: Vec<String> = (0..200).map(|i| format!("v{i}")).collect();
    let mut a = args(&["prove", &sum.join("+"), "19900"]);
    for i in 0..200 {
        a.push("--where".into());
        a.push(format!("v{i} = {i}"));
    }
    let out = answered(&a, 0);
    assert!(out.starts_with("proved"), "{out}");
}

/// `s^10000` modulo `c^2 + s^2 = 1` took more than 3.2 GB (every binomial row up to 5000 was
/// built); three such powers are refused by the terms limit before the expansion.
#[test]
fn high_powers_modulo_unit_circles() {
    let out = answered(&args(&["prove", "s^10000", "0", "--where", "c^2+s^2=1"]), 1);
    assert!(out.starts_with("fails"), "{out}");
    refused(
        &args(&[
            "prove",
            "s^10000*t^10000*u^10000",
            "0",
            "--where",
            "c^2+s^2=1",
            "--where",
            "d^2+t^2=1",
            "--where",
            "f^2+u^2=1",
        ]),
        "the limit terms = 1000000",
    );
}
