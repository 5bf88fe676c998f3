//! Criterion benchmark of exact root isolation in [0, 1] (`isolate_real_roots_in`, Descartes'
//! rule with every rational root exact, against the Sturm reference `isolate_real_roots_sturm_in`),
//! at degrees 10, 20 and 40, on products of `(t - k/(d+1))` (d rational roots in [0, 1], close
//! together at degree 40) and on seeded random integer polynomials (coefficients in [-100, 100],
//! few roots in [0, 1]).
//!
//! The group `real_roots` times the real-roots workload at the six comparison sizes (`bench_instances::solve`: all real roots
//! isolated by Descartes' rule and refined to width 2^-53), each root count asserted first.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use exactcheck_core::Rng;
use exactcheck_exact::univariate::bench_instances;
use exactcheck_exact::univariate::{
    isolate_real_roots_in, isolate_real_roots_sturm_in, RootInterval, UPoly,
};
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

/// An isolator of the roots in `[lo, hi]`.
type Method = fn(&UPoly, &Rational, &Rational) -> Vec<RootInterval>;

/// The roots of `p` in `[0, 1]` by `m`.
fn unit(p: &UPoly, m: Method) -> Vec<RootInterval> {
    m(p, &Rational::ZERO, &Rational::ONE)
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
            let methods: [(&str, Method); 2] = [
                ("descartes", isolate_real_roots_in),
                ("sturm", isolate_real_roots_sturm_in),
            ];
            for (label, m) in methods {
                // Both isolators must agree on the number of roots before being timed.
                assert_eq!(unit(p, m).len(), unit(p, isolate_real_roots_sturm_in).len());
                g.bench_with_input(BenchmarkId::new(format!("{name}/{label}"), d), p, |b, p| {
                    b.iter(|| unit(p, m))
                });
            }
        }
    }
    g.finish();
}

fn bench_real_roots(c: &mut Criterion) {
    let mut g = c.benchmark_group("real_roots");
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(300));
    g.measurement_time(Duration::from_secs(2));
    for (family, degree, count) in bench_instances::COMPARISON {
        let coeffs = family.polynomial(degree);
        // The check value (the same count in python-flint and SymPy) before timing.
        assert_eq!(
            bench_instances::solve(&coeffs).len(),
            count,
            "{family:?} {degree}"
        );
        g.bench_with_input(
            BenchmarkId::new(family.name(), degree),
            &coeffs,
            |b, coeffs| b.iter(|| bench_instances::solve(coeffs)),
        );
    }
    g.finish();
}

criterion_group!(benches, bench, bench_real_roots);
criterion_main!(benches);
