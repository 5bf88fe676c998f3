//! `while` and `while*`: the binding orders, arrays ending a loop, the iteration limit, and a
//! benchmark of the vendored suite against an independent exact computation.
use super::*;
use crate::program::{ExactStop, REL_BITS};
use exactcheck_core::limits::LOOP_ITERATIONS;
use num_rational::BigRational;
use num_traits::{FromPrimitive, Signed, ToPrimitive};

fn exact_of(v: f64) -> Rational {
    Rational::from(BigRational::from_f64(v).expect("finite"))
}

fn exact_values(p: &Program, x: &[f64]) -> Vec<BigRational> {
    let xs: Vec<Rational> = x.iter().map(|&v| exact_of(v)).collect();
    p.eval_exact(&xs)
        .unwrap_or_else(|e| panic!("{e}"))
        .into_iter()
        .map(|r| {
            assert!(r.exact, "a rational loop has an exact value");
            r.value
        })
        .collect()
}

fn big(n: i64, d: i64) -> BigRational {
    q(n, d).to_big_rational()
}

#[test]
fn while_updates_in_parallel_and_while_star_in_sequence() {
    // One swap: `while` reads the old values (a, b) = (2, 1); `while*` updates a first, and
    // b then reads the new a: (2, 2).
    let par = program("(FPCore () (while (< i 1) ([a 1 b] [b 2 a] [i 0 (+ i 1)]) (array a b)))");
    let seq = program("(FPCore () (while* (< i 1) ([a 1 b] [b 2 a] [i 0 (+ i 1)]) (array a b)))");
    assert_eq!(exact_values(&par, &[]), vec![big(2, 1), big(1, 1)]);
    assert_eq!(exact_values(&seq, &[]), vec![big(2, 1), big(2, 1)]);
    assert_eq!(par.eval_f64(&[]), vec![2.0, 1.0]);
    assert_eq!(seq.eval_f64(&[]), vec![2.0, 2.0]);
    // The initial values: `while` evaluates them in the outer scope (`b` starts from the
    // argument `a`), `while*` sees the variables before (`b` starts from the loop's `a`).
    let par = program("(FPCore (a) (while FALSE ([a 5 a] [b a b]) b))");
    let seq = program("(FPCore (a) (while* FALSE ([a 5 a] [b a b]) b))");
    assert_eq!(exact_values(&par, &[3.0]), vec![big(3, 1)]);
    assert_eq!(exact_values(&seq, &[3.0]), vec![big(5, 1)]);
}

#[test]
fn a_loop_condition_is_decided_on_the_exact_values() {
    // 0.1 added ten times: exactly 1 after ten iterations, so the loop runs 10 times exactly;
    // in doubles the sum is 0.9999999999999999 after ten and it runs an eleventh time.
    let p = program("(FPCore () (while (< s 1) ([s 0 (+ s 1/10)] [n 0 (+ n 1)]) n))");
    assert_eq!(exact_values(&p, &[]), vec![big(10, 1)]);
    assert_eq!(p.eval_f64(&[]), vec![11.0]);
}

#[test]
fn a_loop_past_the_iteration_limit_stops_on_both_sides() {
    let p = program("(FPCore (x) (while TRUE ([x x (+ x 1)]) x))");
    assert_eq!(
        p.eval_exact(&[Rational::ONE]).unwrap_err(),
        ExactStop::LoopLimit
    );
    assert!(p.eval_f64(&[1.0])[0].is_nan());
    let msg = ExactStop::LoopLimit.to_string();
    assert!(msg.contains("the limit loop-iterations = "), "{msg}");
    // Exactly at the limit is within it.
    let at = format!(
        "(FPCore () (while (< i {}) ([i 0 (+ i 1)]) i))",
        LOOP_ITERATIONS.get()
    );
    let p = program(&at);
    assert_eq!(
        exact_values(&p, &[]),
        vec![BigRational::from_integer(LOOP_ITERATIONS.get().into())]
    );
    let past = format!(
        "(FPCore () (while (<= i {}) ([i 0 (+ i 1)]) i))",
        LOOP_ITERATIONS.get()
    );
    assert_eq!(
        program(&past).eval_exact(&[]).unwrap_err(),
        ExactStop::LoopLimit
    );
}

#[test]
fn a_loop_value_past_its_size_limit_stops_the_exact_test() {
    // `sqrt(2) y - sqrt(2) y` is an enclosure around zero, so the exact test decides it, with
    // `y` exact there; squaring 3/2 doubles its size every iteration (3^(2^n) / 2^(2^n)).
    let text = |n: u64| {
        format!(
            "(FPCore (x) (while (< i {n}) ([y x (* y y)] [i 0 (+ i 1)]) (- (* (sqrt 2) y) (* (sqrt 2) y))))"
        )
    };
    assert_eq!(exact_values(&program(&text(8)), &[1.5]), vec![big(0, 1)]);
    let stop = program(&text(20)).eval_exact(&[exact_of(1.5)]).unwrap_err();
    assert_eq!(stop, ExactStop::LoopValueLimit);
    assert_eq!(stop.limit().map(|l| l.name()), Some("loop-value-bits"));
    assert_eq!(
        ExactStop::LoopLimit.limit().map(|l| l.name()),
        Some("loop-iterations")
    );
    assert_eq!(ExactStop::Undecided.limit().map(|l| l.name()), None);
    let msg = stop.to_string();
    assert!(msg.contains("the limit loop-value-bits = "), "{msg}");
}

#[test]
fn arrays_end_a_loop_and_loops_nest_in_lets() {
    let p = program(
        "(FPCore (x) (let ([h 1/2]) (while* (< i 2) ([y x (* y h)] [i 0 (+ i 1)]) (array y i))))",
    );
    assert_eq!(p.outputs.len(), 2);
    assert_eq!(exact_values(&p, &[3.0]), vec![big(3, 4), big(2, 1)]);
    // Misuse is a syntax error with its position, never a panic.
    for bad in [
        "(FPCore (x) (while (< x 1) ([x x]) x))",
        "(FPCore (x) (while (< x 1) ([y 0 y] [y 1 y]) x))",
        "(FPCore (x) (while (< x 1) x))",
        "(FPCore (x) (while (< x 1) ([y 0 y])))",
    ] {
        assert!(parse_file(bad).is_err(), "{bad}");
    }
}

/// The reals of a rational, as an f64 (for messages).
fn show(v: &BigRational) -> f64 {
    v.to_f64().unwrap_or(f64::NAN)
}

#[test]
fn a_nonlinear_loop_is_refined_through_enclosures() {
    // Newton's iteration for sqrt(2): the exact rationals double in size every step, so the
    // loop carries them as enclosures; the independent computation here keeps them exact.
    let p = program("(FPCore (x) (while (< i 12) ([y x (/ (+ y (/ 2 y)) 2)] [i 0 (+ i 1)]) y))");
    let r = p.eval_exact(&[Rational::ONE]).expect("defined");
    let mut y = BigRational::from_integer(1.into());
    let two = BigRational::from_integer(2.into());
    for _ in 0..12 {
        y = (&y + &two / &y) / &two;
    }
    let rel = ((&r[0].value - &y) / &y).abs();
    assert!(
        rel <= BigRational::new(1.into(), num_bigint::BigInt::from(1) << REL_BITS),
        "{} against {}",
        show(&r[0].value),
        show(&y)
    );
    assert_eq!(
        crate::to_f64::rational_to_f64(&r[0].value),
        crate::to_f64::rational_to_f64(&y)
    );
}

#[test]
fn the_pid_benchmark_matches_an_independent_exact_loop() {
    let suite = include_str!("../../../../tests/regress/fpbench/salsa.fpcore");
    let all = parse_file(suite).expect("the suite parses");
    let pid = all
        .iter()
        .find(|b| b.name.as_deref() == Some("PID"))
        .expect("PID");
    let p = pid.program.as_ref().expect("PID compiles");
    let (m, kp, ki, kd, c) = (-5.0, 9.4514, 0.69006, 2.8454, 1.25);
    let r = p
        .eval_exact(&[m, kp, ki, kd, c].map(exact_of))
        .expect("defined");
    // The loop of the benchmark, written out in exact rationals.
    let e = |v: f64| exact_of(v).to_big_rational();
    let (mut m, kp, ki, kd, c) = (e(m), e(kp), e(ki), e(kd), e(c));
    let dt = big(1, 2);
    let invdt = big(2, 1);
    let (mut i, mut eold, mut t) = (big(0, 1), big(0, 1), big(0, 1));
    let hundredth = big(1, 100);
    while t < big(100, 1) {
        let err = &c - &m;
        let p = &kp * &err;
        i = &i + &ki * &dt * &err;
        let d = &kd * &invdt * (&err - &eold);
        let r = &p + &i + &d;
        m = &m + &hundredth * &r;
        eold = err;
        t = &t + &dt;
    }
    let rel = if m == big(0, 1) {
        r[0].value.abs()
    } else {
        ((&r[0].value - &m) / &m).abs()
    };
    assert!(
        rel <= BigRational::new(1.into(), num_bigint::BigInt::from(1) << REL_BITS),
        "{} against {}",
        show(&r[0].value),
        show(&m)
    );
    assert_eq!(
        crate::to_f64::rational_to_f64(&r[0].value),
        crate::to_f64::rational_to_f64(&m)
    );
}

/// A loop whose end only its counter `i` decides, run `n` times, with a state cheap in exact
/// rationals and larger than the counter: `a` alternates between `x` and `1 - x`, `b` between
/// 1 and -1, `s` sums `a b`, and `d` divides by `i - k`, which is zero at the `k`-th iteration.
fn counted_loop(n: u64, k: u64) -> Program {
    program(&format!(
        "(FPCore (x) (while* (< i {n}) ([i 0 (+ i 1)] [a x (- 1 a)] [b 1 (* b -1)] \
         [s 0 (+ s (* a b))] [d 1 (/ (* d 1/2) (- i {k}))]) s))"
    ))
}

#[test]
fn the_variables_that_end_a_loop_are_found() {
    let p = counted_loop(3, 100);
    let Node::While(l) = &p.outputs[0] else {
        panic!("a loop: {:?}", p.outputs[0])
    };
    assert_eq!(crate::program::walk::control_vars(l), Some(vec![0]));
    // Newton's loop: the counter is half of the loop's variables and its work is not small.
    let p = program("(FPCore (x) (while (< i 12) ([y x (/ (+ y (/ 2 y)) 2)] [i 0 (+ i 1)]) y))");
    let Node::While(l) = &p.outputs[0] else {
        panic!("a loop")
    };
    assert_eq!(crate::program::walk::control_vars(l), None);
    // A condition on `e`, which reads `y`: both control the loop, `t` does not.
    let p = program(
        "(FPCore (x) (while* (> e 0) ([y x (* y 1/2)] [e 1 (- y 1/1024)] [i 0 (+ i 1)] \
         [t 0 (+ (* t t) (* (* y y) (- (* 3 t) (* y (+ t 1)))))]) t))",
    );
    let Node::While(l) = &p.outputs[0] else {
        panic!("a loop")
    };
    assert_eq!(crate::program::walk::control_vars(l), None);
    let p = program(
        "(FPCore (x) (while* (> e 0) ([y x (* y 1/2)] [e 1 (- y 1/1024)] [i 0 (+ i 1)] \
         [t 0 (+ (* t t) (* (* y y) (- (* 3 t) (* y (+ t 1)))))] \
         [u 0 (+ (* u u) (* (* y y) (- (* 3 u) (* y (+ u 1)))))] \
         [v 0 (+ (* v v) (* (* y y) (- (* 3 v) (* y (+ v 1)))))]) t))",
    );
    let Node::While(l) = &p.outputs[0] else {
        panic!("a loop")
    };
    assert_eq!(crate::program::walk::control_vars(l), Some(vec![0, 1]));
}

#[test]
fn a_loop_counted_past_the_limit_stops_before_its_state_is_computed() {
    let limit = LOOP_ITERATIONS.get();
    let x = [q(1, 3)];
    // Exactly at the limit the whole loop runs (the count ahead leaves the count as it was):
    // s sums a b = x - (1 - x) + x - ... over the limit's iterations.
    let r = exact_values(&counted_loop(limit, limit + 5), &[1.0 / 4.0]);
    let half = i64::try_from(limit / 2).expect("small");
    let want = if limit % 2 == 0 {
        // Pairs of (1 - x) - x, with x = 1/4: 1/2 each.
        big(half, 2)
    } else {
        big(half, 2) + big(3, 4)
    };
    // The first update gives a = 1 - x, b = -1: s = -(1 - x), then + x, ...
    assert_eq!(r, vec![-want]);
    // One more: the counter alone passes the limit, so the sample stops there, and `d`'s
    // division by zero at the fifth iteration is never reached; within the limit it is.
    assert_eq!(
        counted_loop(limit + 1, 5).eval_exact(&x).unwrap_err(),
        ExactStop::LoopLimit
    );
    assert_eq!(
        counted_loop(limit, 5).eval_exact(&x).unwrap_err(),
        ExactStop::OutsideDomain
    );
    // The float side runs as written: the limit's NaN.
    assert!(counted_loop(limit + 1, 5).eval_f64(&[0.25])[0].is_nan());
}

#[test]
fn nested_loops_count_their_iterations_together_when_counting_ahead() {
    // An outer loop of 2 iterations whose update of `s` runs an inner counted loop of m
    // iterations: 2 + 2 m iterations in all.
    let limit = LOOP_ITERATIONS.get();
    let text = |m: u64| {
        format!(
            "(FPCore (x) (while* (< k 2) ([k 0 (+ k 1)] [w x (* w 1/2)] [z x (* z -1)] \
             [s 0 (while* (< i {m}) ([i 0 (+ i 1)] [a x (- 1 a)] [b 1 (* b -1)] \
             [c 0 (+ c (* a b))] [d 0 (+ d (* c w))]) (+ s c))]) s))"
        )
    };
    let m = (limit - 2) / 2;
    // Each inner loop sums m terms a b, -1/2 per pair at x = 1/4 (as in `counted_loop`).
    let inner = -big(i64::try_from(m / 2).expect("small"), 2) - big(3 * (m % 2) as i64, 4);
    let r = exact_values(&program(&text(m)), &[0.25]);
    assert_eq!(r, vec![&inner + &inner]);
    assert_eq!(
        program(&text(m + 1)).eval_exact(&[q(1, 4)]).unwrap_err(),
        ExactStop::LoopLimit
    );
}

#[test]
fn rocket_trajectory_stops_at_the_iteration_limit_at_once() {
    // Its loop counts `i` from 1 to 2,000,000: past the default limit whatever the inputs, so
    // the exact side stops at the limit without computing the trajectory (ten thousand steps of
    // sines and cosines of enclosures) first.
    let suite = include_str!("../../../../tests/regress/fpbench/salsa.fpcore");
    let all = parse_file(suite).expect("the suite parses");
    let rocket = all
        .iter()
        .find(|b| b.name.as_deref() == Some("Rocket Trajectory"))
        .and_then(|b| b.program.as_ref().ok())
        .expect("Rocket Trajectory compiles");
    for (mf, a) in [(150_000.0, 140.0), (1.0e30, -3.5), (-2.0e-20, 7.0e12)] {
        assert_eq!(
            rocket.eval_exact(&[exact_of(mf), exact_of(a)]).unwrap_err(),
            ExactStop::LoopLimit
        );
    }
    let Node::Let(_, body) = &rocket.outputs[0] else {
        panic!("the constants are bound first: {:?}", rocket.outputs[0])
    };
    let Node::While(l) = &**body else {
        panic!("the loop follows the constants")
    };
    let control = crate::program::walk::control_vars(l).expect("the counter alone");
    assert_eq!(control.len(), 1);
    assert_eq!(l.vars[control[0]].0, l.vars[12].0, "the counter `i`");
}
