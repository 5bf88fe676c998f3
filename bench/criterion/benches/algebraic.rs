//! Real algebraic numbers: the minimal polynomials of `cos(2 pi / n)` for `n <= 60`, a sum of
//! nested radicals (resultant, root selection) and an exact comparison of two close numbers.
//! `bench/scripts/compare_algebraic.py` times the same workloads against python-flint and SymPy.

use criterion::{criterion_group, criterion_main, Criterion};
use exactcheck_exact::algebraic::Algebraic;
use std::hint::black_box;

fn bench_algebraic(c: &mut Criterion) {
    let mut group = c.benchmark_group("algebraic");
    group.sample_size(10);
    group.bench_function("cos_2pi_over_n_up_to_60", |b| {
        b.iter(|| {
            for n in 1..=60 {
                black_box(Algebraic::cos_pi(2, n).expect("small degree"));
            }
        })
    });
    let x: Algebraic = "sqrt(2 + sqrt(2))".parse().expect("constant");
    let y: Algebraic = "sqrt(3 + sqrt(3))".parse().expect("constant");
    group.bench_function("sum_of_two_nested_radicals", |b| {
        b.iter(|| black_box(x.clone() + y.clone()))
    });
    // sqrt(2) + sqrt(3) against 3.1462643699419726 (2e-17 apart): refinement decides.
    let s: Algebraic = "sqrt(2) + sqrt(3)".parse().expect("constant");
    let q: Algebraic = "3.1462643699419726".parse().expect("constant");
    group.bench_function("compare_close", |b| b.iter(|| black_box(s.compare(&q))));
    group.finish();
}

criterion_group!(benches, bench_algebraic);
criterion_main!(benches);
