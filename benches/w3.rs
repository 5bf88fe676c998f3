//! Criterion benchmark of workload W3 (f64 sampling of the Spaeth discriminant): the sampler
//! with precomputed trigonometric coefficients (all cores and one thread) beside a plain
//! per-sample evaluation of the derived formulas with `sin_cos`.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use exactcheck::w2::problem;
use exactcheck_float::sampler::{sweep_direct, DiscSampler};

fn bench(c: &mut Criterion) {
    let n = 1 << 20;
    let cs = problem::<f64>();
    let sampler = DiscSampler::new(&cs);
    let mut g = c.benchmark_group("w3");
    g.sample_size(20);
    g.throughput(Throughput::Elements(n as u64));
    g.bench_function("coef_parallel", |b| b.iter(|| sampler.sweep(n)));
    g.bench_function("coef_serial", |b| b.iter(|| sampler.sweep_serial(n)));
    g.bench_function("direct_serial", |b| b.iter(|| sweep_direct(&cs, n)));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
