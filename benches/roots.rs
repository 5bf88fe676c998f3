//! Criterion benchmark of exact root isolation in [0, 1] (`UPoly::unit_roots_with`): Sturm
//! bisection against Bernstein–Descartes subdivision, at degrees 10, 20 and 40, on products of
//! `(t - k/(d+1))` (d roots in [0, 1], close together at degree 40) and on seeded random integer
//! polynomials (coefficients in [-100, 100], few roots in [0, 1]). The faster method is the
//! default of `UPoly::unit_roots`; the measured table is in docs/benchmarks.md.
//!
//! The group `w4` times W4 at the six comparison sizes (`w4::solve`: all real roots
//! isolated by Descartes' rule and refined to width 2^-53), each root count asserted first.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use exactcheck_core::Rng;
use exactcheck_exact::univariate::w4;
use exactcheck_exact::univariate::{UPoly, UnitRootMethod};
use exactcheck_exact::Rational;
use std::time::Duration;

fn spaced(d: i64) -> UPoly {
    let roots: Vec<Rational> = (1..=d)
        .map(|k| Rational::new(k, d + 1).expect("d + 1 > 0"))
        .collect();
    UPoly::from_roots(&roots)
}

fn random(d: usize, seed: u64) -> UPoly {
    let mut rng = Rng::new(seed);
    let mut c: Vec<i64> = (0..=d).map(|_| rng.below(201) as i64 - 100).collect();
    if c[d] == 0 {
        c[d] = 1;
    }
    UPoly::from_i64_coeffs(&c)
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("unit_roots");
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(300));
    g.measurement_time(Duration::from_secs(2));
    for d in [10usize, 20, 40] {
        let cases = [
            ("spaced", spaced(d as i64)),
            ("random", random(d, 0x5eed + d as u64)),
        ];
        for (name, p) in &cases {
            for (label, m) in [
                ("sturm", UnitRootMethod::Sturm),
                ("bernstein", UnitRootMethod::BernsteinDescartes),
            ] {
                // Both methods must agree on the number of roots before being timed.
                assert_eq!(
                    p.unit_roots_with(m).expect("non-zero").len(),
                    p.unit_roots_with(UnitRootMethod::Sturm)
                        .expect("non-zero")
                        .len()
                );
                g.bench_with_input(BenchmarkId::new(format!("{name}/{label}"), d), p, |b, p| {
                    b.iter(|| p.unit_roots_with(m).expect("non-zero"))
                });
            }
        }
    }
    g.finish();
}

fn bench_w4(c: &mut Criterion) {
    let mut g = c.benchmark_group("w4");
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(300));
    g.measurement_time(Duration::from_secs(2));
    for (family, degree, count) in w4::COMPARISON {
        let coeffs = family.polynomial(degree);
        // The check value (the same count in python-flint and SymPy) before timing.
        assert_eq!(w4::solve(&coeffs).len(), count, "{family:?} {degree}");
        g.bench_with_input(
            BenchmarkId::new(family.name(), degree),
            &coeffs,
            |b, coeffs| b.iter(|| w4::solve(coeffs)),
        );
    }
    g.finish();
}

criterion_group!(benches, bench, bench_w4);
criterion_main!(benches);
