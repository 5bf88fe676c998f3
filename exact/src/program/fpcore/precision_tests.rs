//! Arguments of another precision than their benchmark's (`(! :precision binary32 x)` in a
//! binary64 benchmark and the reverse), the refused argument precisions, and an array of loop
//! results computed by one run of the loop.
use super::parse_file;
use crate::program::{ExactStop, Format};
use crate::rational::Rational;
use crate::to_f64::rational_to_f32;
use exactcheck_core::limits::LOOP_ITERATIONS;
use proptest::prelude::*;

use crate::program::mixed_tests::{exact, fpcore as program};

#[test]
fn arguments_keep_their_own_precision() {
    let p = program("(FPCore ((! :precision binary32 x) y) (+ x y))");
    assert_eq!(p.precision, Format::Binary64);
    assert_eq!(p.input_format(0), Format::Binary32);
    assert_eq!(p.input_format(1), Format::Binary64);
    assert!(p.mixes_input_precisions());
    let p = program("(FPCore ((! :precision binary64 x) y) :precision binary32 (+ x y))");
    assert_eq!(p.precision, Format::Binary32);
    assert_eq!(
        [p.input_format(0), p.input_format(1)],
        [Format::Binary64, Format::Binary32]
    );
    // An annotation of the benchmark's own precision changes nothing.
    let p = program("(FPCore ((! :precision binary64 x)) (+ x 1))");
    assert!(p.input_precision.is_empty());
    assert!(!p.mixes_input_precisions());
}

#[test]
fn a_binary64_argument_of_a_binary32_benchmark_is_rounded_once_by_the_operation() {
    // x = 1 + 2^-24 + 2^-50 is no binary32 value. `x - 1` in binary32 rounds the exact
    // 2^-24 + 2^-50 once, to 2^-24; taking x as binary32 first (1 + 2^-23) would give 2^-23.
    let x = 1.0 + f64::powi(2.0, -24) + f64::powi(2.0, -50);
    let p = program("(FPCore ((! :precision binary64 x)) :precision binary32 (- x 1))");
    assert_eq!(p.eval_f64(&[x]), vec![f64::powi(2.0, -24)]);
    let r = p.eval_exact(&[exact(x)]).unwrap();
    assert_eq!(r[0].value, (&exact(x) - &Rational::ONE).to_big_rational());
    // The same in a binary32 benchmark whose argument is binary32: its value is taken as one.
    let q = program("(FPCore (x) :precision binary32 (- x 1))");
    assert_eq!(q.eval_f64(&[x]), vec![f64::powi(2.0, -23)]);
}

#[test]
fn a_binary32_argument_of_a_binary64_benchmark_feeds_double_operations() {
    let p = program("(FPCore ((! :precision binary32 x) y) (- (+ x y) y))");
    let x = f64::from(1.1f32);
    let y = 1e-9;
    assert_eq!(p.eval_f64(&[x, y]), vec![(x + y) - y]);
    let r = p.eval_exact(&[exact(x), exact(y)]).unwrap();
    assert_eq!(r[0].value, exact(x).to_big_rational());
}

#[test]
fn argument_precisions_outside_binary64_and_binary32() {
    for (text, op) in [
        (
            "(FPCore ((! :precision binary80 x)) (+ x 1))",
            "precision binary80",
        ),
        (
            "(FPCore ((! :precision integer n)) (+ n 1))",
            "precision integer",
        ),
        (
            "(FPCore ((! :precision (float 8 16) x)) x)",
            "precision (float 8 16)",
        ),
        ("(FPCore ((! :round toZero x)) x)", "round toZero"),
    ] {
        let b = parse_file(text).expect("parses");
        assert_eq!(b[0].program.clone().unwrap_err().op, op, "{text}");
    }
    // A name that is no FPCore precision is an error of the file, with its position.
    let e = parse_file("(FPCore ((! :precision binary65 x)) x)").unwrap_err();
    assert_eq!((e.line, e.col), (1, 24));
    assert!(
        e.message
            .starts_with("unknown precision `binary65` of the argument `x`"),
        "{e}"
    );
}

#[test]
fn an_array_of_loop_results_runs_the_loop_once() {
    // The loop runs exactly `loop-iterations` times: within the limit once, past it twice.
    let limit = LOOP_ITERATIONS.get();
    let text = format!(
        "(FPCore () (while (< i {limit}) ([i 0 (+ i 1)] [s 0 (+ s 2)]) (array i s (- s i))))"
    );
    let p = program(&text);
    assert_eq!(p.outputs.len(), 3);
    let n = limit as f64;
    assert_eq!(p.eval_f64(&[]), vec![n, 2.0 * n, n]);
    let r = p.eval_exact(&[]).expect("within the limit");
    let values: Vec<_> = r.iter().map(|r| r.value.clone()).collect();
    let big = |k: u64| num_rational::BigRational::from_integer(k.into());
    assert_eq!(values, vec![big(limit), big(2 * limit), big(limit)]);
    // The elements are the loop's: under a `let` and an `if` too, and in both branches.
    let p = program(
        "(FPCore (x) (let ([a (* x 2)]) (if (< x 0) (while (< i 3) ([i 0 (+ i 1)]) (array i a)) (array a x))))",
    );
    assert_eq!(p.eval_f64(&[-1.0]), vec![3.0, -2.0]);
    assert_eq!(p.eval_f64(&[5.0]), vec![10.0, 5.0]);
    let r = p.eval_exact(&[exact(-1.0)]).unwrap();
    assert_eq!(r[1].value, exact(-2.0).to_big_rational());
    // Past the limit, the whole evaluation stops once.
    let past = format!("(FPCore () (while (<= i {limit}) ([i 0 (+ i 1)]) (array i i)))");
    let p = program(&past);
    assert_eq!(p.eval_exact(&[]).unwrap_err(), ExactStop::LoopLimit);
    assert!(p.eval_f64(&[]).iter().all(|v| v.is_nan()));
}

proptest! {
    /// A binary32 operation of a binary32 benchmark on a binary64 argument is the exact result
    /// rounded once to binary32.
    #[test]
    fn binary64_arguments_round_once(x in -1e6f64..1e6, y in -1e6f32..1e6) {
        let p = program("(FPCore ((! :precision binary64 x) y) :precision binary32 (* x y))");
        let want = rational_to_f32(&(&exact(x) * &exact(f64::from(y))).to_big_rational());
        prop_assert_eq!(p.eval_f64(&[x, f64::from(y)]), vec![want]);
    }
}
