//! Criterion benchmark of deciding an identity between rational functions against deciding its
//! cleared numerator as a polynomial identity: `P/D = Q/D` with `P = (x + y + z + 1)^k` as
//! written, `Q` its expansion and `D = 1 + x^2 + y^2`, against `P D = Q D`. Both paths start
//! from the parsed expressions: the rational one converts each side to a fraction in lowest
//! terms (gcds with `D`), clears the denominators and decides the cleared numerator off the
//! zeros of `D`; the polynomial one expands both sides and decides their difference. The
//! cleared numerator `P D - Q D` has `3 C(k + 3, 3)` terms before it cancels: 105, 495 and
//! 1,365 at `k = 4, 8, 12`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use exactcheck_exact::expr::{parse_expr, Expr};
use exactcheck_exact::poly::Vars;
use exactcheck_exact::prove::{decide_fraction, decide_in, Decision, FractionIdentity};
use exactcheck_exact::Rational;
use std::time::Duration;

const D: &str = "(1 + x^2 + y^2)";

/// The two sides of the rational identity and of the polynomial one at `k`.
fn sides(k: u32) -> ((Expr, Expr), (Expr, Expr)) {
    let p = format!("(x + y + z + 1)^{k}");
    let mut vars = Vars::new();
    let q = parse_expr(&p)
        .unwrap()
        .to_poly::<Rational>(&mut vars)
        .unwrap()
        .display(&vars)
        .to_string();
    let e = |s: String| parse_expr(&s).unwrap();
    (
        (e(format!("{p}/{D}")), e(format!("({q})/{D}"))),
        (e(format!("{p}*{D}")), e(format!("({q})*{D}"))),
    )
}

fn rational(l: &Expr, r: &Expr) -> bool {
    let mut vars = Vars::new();
    let l = l.to_ratfun::<Rational>(&mut vars).unwrap();
    let r = r.to_ratfun::<Rational>(&mut vars).unwrap();
    let f = FractionIdentity::new(&l, &r).unwrap();
    matches!(
        decide_fraction(&f, &[], &[], &[], vars.len()).unwrap(),
        Decision::Proved { .. }
    )
}

fn polynomial(l: &Expr, r: &Expr) -> bool {
    let mut vars = Vars::new();
    let l = l.to_poly::<Rational>(&mut vars).unwrap();
    let r = r.to_poly::<Rational>(&mut vars).unwrap();
    matches!(
        decide_in(&(l - r), &[], &[], vars.len()).unwrap(),
        Decision::Proved { .. }
    )
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("fraction_vs_numerator");
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(300));
    g.measurement_time(Duration::from_secs(2));
    for k in [4u32, 8, 12] {
        let ((rl, rr), (pl, pr)) = sides(k);
        // Both must be proved before they are timed.
        assert!(rational(&rl, &rr), "the rational identity at k = {k}");
        assert!(polynomial(&pl, &pr), "the polynomial identity at k = {k}");
        g.bench_with_input(BenchmarkId::new("rational", k), &k, |b, _| {
            b.iter(|| rational(&rl, &rr))
        });
        g.bench_with_input(BenchmarkId::new("numerator", k), &k, |b, _| {
            b.iter(|| polynomial(&pl, &pr))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
