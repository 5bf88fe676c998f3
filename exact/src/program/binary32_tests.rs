//! Tests of binary32 programs: the float side in f32, the exact reference's rounding decided in
//! binary32 (a double that is a binary32 tie is not enough), the local errors in binary32.
use super::*;
use crate::to_f64::rational_to_f32;
use num_bigint::BigInt;
use num_rational::BigRational;

fn prog32(text: &str) -> Program {
    let mut p = Program::parse(text, None).unwrap();
    p.precision = Format::Binary32;
    p
}

fn dyadic(m: i64, e: i32) -> Rational {
    let m = BigRational::from_integer(BigInt::from(m));
    let p = BigRational::from_integer(BigInt::from(1) << e.unsigned_abs() as usize);
    Rational::from(if e >= 0 { m * p } else { m / p })
}

#[test]
fn the_float_side_rounds_every_operation_and_literal_to_binary32() {
    // (x + y) - x: y below half an ulp of x vanishes in f32, not in f64.
    let p = prog32("(x + y) - x");
    let y = f64::powi(2.0, -30);
    assert_eq!(p.eval_f64(&[1.0, y]), vec![0.0]);
    let mut p64 = p.clone();
    p64.precision = Format::Binary64;
    assert_eq!(p64.eval_f64(&[1.0, y]), vec![y]);
    // A literal is the binary32 value nearest to it.
    assert_eq!(prog32("x * 0.1").eval_f64(&[1.0]), vec![f64::from(0.1f32)]);
    // sqrt and the library functions are the f32 ones.
    assert_eq!(
        prog32("sqrt(x)").eval_f64(&[2.0]),
        vec![f64::from(2.0f32.sqrt())]
    );
    let mut sin = p.clone();
    sin.outputs = vec![Node::Fun(Func::Sin, vec![Node::Input(0)])];
    assert_eq!(sin.eval_f64(&[0.5, 0.0]), vec![f64::from(0.5f32.sin())]);
    // An f32 overflow is an infinity where doubles are finite.
    assert_eq!(prog32("x * x").eval_f64(&[1e30]), vec![f64::INFINITY]);
}

#[test]
fn the_reference_decides_the_binary32_rounding_not_the_double_one() {
    // m = 1 + 2^-24 is the binary32 tie between 1 and 1 + 2^-23 (a double). sqrt(m^2 + d) is
    // m + d/(2m) nearly: for |d| = 2^-100 it rounds to the double m, whose binary32 rounding
    // is 1 (to even) whichever side of m the true value lies.
    let m = dyadic((1 << 24) + 1, -24);
    let p = prog32("sqrt(x)");
    for (d, want) in [(1, 1.0 + f64::powi(2.0, -23)), (-1, 1.0)] {
        let x = &(&m * &m) + &dyadic(d, -100);
        let r = p.eval_exact(&[x]).unwrap().remove(0);
        assert!(!r.exact);
        assert_eq!(
            crate::to_f64::rational_to_f64(&r.value),
            1.0 + f64::powi(2.0, -24)
        );
        assert_eq!(rational_to_f32(&r.value), want, "d = {d}");
    }
    // Exactly at the tie: a rational, exact, rounded to even.
    let r = p.eval_exact(&[&m * &m]).unwrap().remove(0);
    assert!(r.exact);
    assert_eq!(rational_to_f32(&r.value), 1.0);
}

#[test]
fn local_errors_are_binary32_operations() {
    // x + y at x = 1, y = 2^-30 in binary32: the addition rounds to 1.
    let p = prog32("(x + y) - x");
    let ops = p
        .local_errors(&[dyadic(1, 0), dyadic(1, -30)])
        .expect("rational");
    assert_eq!(ops[0].operation, "addition");
    assert_eq!(ops[0].float, 1.0);
    assert_eq!(ops[0].exact, 1.0);
    // The subtraction of the exact operands rounded to binary32 (1 - 1 = 0), against 2^-30.
    assert_eq!(ops[1].float, 0.0);
    assert_eq!(ops[1].exact, f64::powi(2.0, -30));
}

/// The powers of both formats: `Multiply` rounds every product in its own type; `Libm` converts
/// the exponent to the type first (`(float)n` rounds 2^24 + 1 to 2^24, `(double)n` is exact).
#[test]
fn powers_round_in_their_own_format() {
    use super::float::{pow_f32, pow_f64};
    assert_eq!(pow_f32(2.0, -3, PowStyle::Multiply), 0.125);
    assert_eq!(pow_f64(2.0, -3, PowStyle::Multiply), 0.125);
    assert_eq!(pow_f32(7.0, 0, PowStyle::Multiply), 1.0);
    // 1.1^3 by two rounded products, in each format.
    let a32 = 1.1f32;
    assert_eq!(pow_f32(a32, 3, PowStyle::Multiply), a32 * a32 * a32);
    assert_eq!(pow_f64(1.1, 3, PowStyle::Multiply), 1.1 * 1.1 * 1.1);
    let n = (1 << 24) + 1;
    assert_eq!(
        pow_f32(-1.0, n, PowStyle::Libm),
        (-1.0f32).powf(16_777_216.0)
    );
    assert_eq!(pow_f64(-1.0, n, PowStyle::Libm), -1.0);
}
