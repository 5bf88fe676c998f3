//! Prices the choice between the two ways `Poly` raises a polynomial to a power: binary powering
//! on the fast product kernels, and the power recurrence (`exact/src/poly/power.rs`). For each
//! base and exponent it prints the best of three timings of each method, their ratio and the
//! method the cost model picks, and asserts that both methods give the same polynomial. The
//! prices of the cost model (`WORD_NS` and the others in `power.rs`) were measured this way; run
//! it again on another machine to re-derive them:
//!
//! ```sh
//! cargo run --release -p exactcheck-bench --example power_calibration
//! ```
//!
//! It prints timings only; the tests check the results (`poly::word_tests`).

use exactcheck_core::Ring;
use exactcheck_exact::poly::Poly;
use exactcheck_exact::Rational;
use std::time::Instant;

type P = Poly<Rational>;

fn main() {
    let x = |i: u32| P::var(i);
    let c = |n: i64| P::from_i64(n);
    let fuzz = x(0) + x(1).pow(2) + x(2) + c(3) * x(1) * x(3);
    let dense4 = c(1) + x(0) + x(1) + x(2) + x(3);
    let sparse10 = P::sum(
        (0..10)
            .map(|i| x(i) * x((i + 3) % 10).pow(2) * c(i64::from(i) + 1))
            .collect(),
    );
    let uni = P::sum(
        (0..10)
            .map(|i| x(0).pow(i) * c(2 * i64::from(i) + 1))
            .collect(),
    );
    let tri = c(7) * x(0).pow(3) * x(1) + c(-5) * x(1).pow(2) + x(0) + c(2);
    let cases: Vec<(&str, &P, Vec<u64>)> = vec![
        ("fuzz", &fuzz, vec![10, 20, 37, 50]),
        ("dense4", &dense4, vec![2, 4, 8, 12, 16]),
        ("sparse10", &sparse10, vec![2, 3, 4, 6]),
        ("uni10", &uni, vec![2, 4, 10, 20, 40]),
        ("tri", &tri, vec![5, 20, 60]),
    ];
    for (name, f, es) in cases {
        for e in es {
            let time = |g: &dyn Fn() -> P| {
                let mut best = f64::MAX;
                let mut r = P::zero();
                for _ in 0..3 {
                    let s = Instant::now();
                    r = g();
                    best = best.min(s.elapsed().as_secs_f64());
                }
                (best, r)
            };
            let (tb, rb) = time(&|| f.pow_binary(e));
            let (tr, rr) = time(&|| f.pow_recurrence_forced(e).expect("a base of several terms"));
            assert_eq!(rb, rr, "{name}^{e}: the two methods disagree");
            println!(
                "{name:9} e={e:3} terms={:6} binary={:9.3} ms  recurrence={:9.3} ms  ratio b/r={:6.2}  model_prefers_rec={}",
                rb.len(),
                tb * 1e3,
                tr * 1e3,
                tb / tr,
                f.recurrence_is_preferred(e)
            );
        }
    }
}
