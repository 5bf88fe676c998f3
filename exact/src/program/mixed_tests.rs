//! Tests of programs that mix precisions: each operation rounds once to the precision in scope,
//! on both sides of the independent checks (exact rationals rounded by `rational_to_f32`, the
//! native `f32` operations), and FPBench's mixed benchmark.
use super::fpcore::parse_file;
use super::*;
use crate::to_f64::rational_to_f32;
use num_traits::FromPrimitive;
use proptest::prelude::*;

/// The first benchmark of an FPCore text, compiled.
pub(super) fn fpcore(text: &str) -> Program {
    parse_file(text).unwrap()[0]
        .program
        .clone()
        .unwrap_or_else(|e| panic!("{e}"))
}

/// The exact value of a double.
pub(super) fn exact(v: f64) -> Rational {
    Rational::from(num_rational::BigRational::from_f64(v).expect("finite"))
}

#[test]
fn a_binary32_operation_on_doubles_rounds_once() {
    // 1 + 2^-24 is a binary32 tie; 2^-60 above it the sum rounds up, below it down. Rounding
    // the double sum (which drops 2^-60) to binary32 would give 1 both times.
    let p = fpcore("(FPCore (a b) (! :precision binary32 (+ a b)))");
    let a = 1.0 + f64::powi(2.0, -24);
    let b = f64::powi(2.0, -60);
    assert_eq!(p.eval_f64(&[a, b]), vec![1.0 + f64::powi(2.0, -23)]);
    assert_eq!(p.eval_f64(&[a, -b]), vec![1.0]);
    // The exact side ignores the precisions: the real sum.
    let r = p.eval_exact(&[exact(a), exact(b)]).unwrap();
    assert_eq!(r[0].value, (&exact(a) + &exact(b)).to_big_rational());
    // A literal is rounded to the precision in scope, `cast` rounds to it.
    let p =
        fpcore("(FPCore (x) :precision binary32 (cast (! :precision binary64 (- (+ x 1e-10) x))))");
    let want = f64::from(((1.0f64 + 1e-10) - 1.0) as f32);
    assert_eq!(p.eval_f64(&[1.0]), vec![want]);
    assert_ne!(want, 0.0);
    assert_eq!(
        fpcore("(FPCore (x) :precision binary32 (- (+ x 1e-10) x))").eval_f64(&[1.0]),
        vec![0.0]
    );
}

#[test]
fn intro_example_mixed_runs_in_both_precisions() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/regress/fpbench/fptaylor-extra.fpcore"
    ))
    .unwrap();
    let b = parse_file(&text)
        .unwrap()
        .into_iter()
        .find(|b| b.name.as_deref() == Some("intro-example-mixed"))
        .unwrap();
    let p = b.program.unwrap();
    assert_eq!(p.precision, Format::Binary32);
    for t in [1.0f32, 3.0, 7.1, 100.3, 998.9] {
        // t + 1 in binary32, t / (t + 1) in binary64, the quotient cast to binary32.
        let s = t + 1.0;
        let want = (f64::from(t) / f64::from(s)) as f32;
        assert_eq!(p.eval_f64(&[f64::from(t)]), vec![f64::from(want)], "{t}");
        // The exact value t / (t + 1), its rounding decided in binary32.
        let x = exact(f64::from(t));
        let r = p.eval_exact(std::slice::from_ref(&x)).unwrap();
        let q = x.checked_div(&(&x + &Rational::ONE)).unwrap();
        assert_eq!(r[0].value, q.to_big_rational());
    }
}

#[test]
fn the_standard_examples_of_rounding_with_cast() {
    // FPCore 2.0's examples: a precision annotation does not round a variable (cast 1 is
    // cast 2), `cast` does (cast 3 and cast 4 round x to binary32); lexical scoping rounds
    // `x - 1` to binary32 and adds 1 in binary64.
    let spec = parse_file(include_str!("../../tests/fpcore/spec_examples.fpcore")).unwrap();
    let run = |name: &str, x: f64| {
        let b = spec
            .iter()
            .find(|b| b.name.as_deref() == Some(name))
            .unwrap();
        b.program.as_ref().unwrap().eval_f64(&[x])
    };
    let x = 0.1;
    let x32 = f64::from(0.1f32);
    assert_ne!(x, x32);
    assert_eq!(run("cast 1", x), vec![x]);
    assert_eq!(run("cast 2", x), vec![x]);
    assert_eq!(run("cast 3", x), vec![x32]);
    assert_eq!(run("cast 4", x), vec![x32]);
    assert_eq!(
        run("rounding: lexical scoping", x),
        vec![f64::from((x - 1.0) as f32) + 1.0]
    );
}

proptest! {
    #[test]
    fn binary32_operations_on_doubles_are_correctly_rounded(
        ma in 1u64..(1 << 53), mb in 1u64..(1 << 53), ea in -40i32..40, eb in -40i32..40,
        neg in any::<bool>(),
    ) {
        let a = ma as f64 * f64::powi(2.0, ea - 52);
        let b = if neg { -1.0 } else { 1.0 } * mb as f64 * f64::powi(2.0, eb - 52);
        for (op, f) in [("+", 0), ("-", 1), ("*", 2), ("/", 3)] {
            let p = fpcore(&format!("(FPCore (a b) (! :precision binary32 ({op} a b)))"));
            let (qa, qb) = (exact(a), exact(b));
            let q = match f {
                0 => &qa + &qb,
                1 => &qa - &qb,
                2 => &qa * &qb,
                _ => qa.checked_div(&qb).unwrap(),
            };
            prop_assert_eq!(p.eval_f64(&[a, b]), vec![rational_to_f32(&q.to_big_rational())], "{} {} {}", a, op, b);
        }
    }

    #[test]
    fn binary32_operations_on_binary32_values_are_the_f32_ones(
        a in -1e6f32..1e6, b in -1e6f32..1e6, c in 1e-3f32..1e3,
    ) {
        // A binary32 scope inside a binary64 program runs in the mixed domain; the same
        // expression in a binary32 program runs in f32.
        let body = "(/ (- (* a b) (sqrt c)) (+ c (fma a b c)))";
        let mixed = fpcore(&format!("(FPCore (a b c) (! :precision binary32 {body}))"));
        let f32p = fpcore(&format!("(FPCore (a b c) :precision binary32 {body})"));
        let x = [f64::from(a), f64::from(b), f64::from(c)];
        let want = ((a * b) - c.sqrt()) / (c + a.mul_add(b, c));
        prop_assert_eq!(f32p.eval_f64(&x), vec![f64::from(want)]);
        prop_assert_eq!(mixed.eval_f64(&x), vec![f64::from(want)]);
    }
}
