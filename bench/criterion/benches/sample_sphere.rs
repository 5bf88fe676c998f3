//! Criterion benchmark of workload sample-sphere (f64 sampling of the Spaeth discriminant): the
//! angle-addition kernel (no libm call per sample; all cores and one thread on the detected path,
//! and one thread on every path this CPU runs: portable, AVX2, AVX-512) beside the sampler with precomputed trigonometric coefficients and
//! `sin_cos` per sample (all cores and one thread) and a plain per-sample evaluation of the
//! derived formulas.
//!
//! Before timing, every variant's check values at the bench's N are asserted against the slow
//! reference (`sin_cos` per sample, computed once): the count exactly (no sample of this grid has
//! a reference discriminant within the kernel's error bound of zero, asserted too) and the sum to
//! `1e-12` relative.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use exactcheck_bench::rational_sum::problem;
use exactcheck_bench::sample_sphere::{
    sweep_direct, AdditionSweep, GridSummary, KernelPath, Sweep,
};
use exactcheck_float::sampler::DiscSampler;

fn bench(c: &mut Criterion) {
    let n = 1 << 20;
    let cs = problem::<f64>();
    let sampler = DiscSampler::new(&cs);
    let reference = sweep_direct(&cs, n);
    let dt = std::f64::consts::TAU / n as f64;
    let bound = sampler.addition_disc_error();
    assert!(
        (0..n).all(|i| sampler.discriminant(i as f64 * dt).abs() > bound),
        "a reference discriminant within the kernel's bound of zero"
    );
    let check = |name: &str, got: GridSummary| {
        assert_eq!(got.count_nonneg, reference.count_nonneg, "{name}");
        assert!(
            (got.sum_sqrt - reference.sum_sqrt).abs() <= 1e-12 * reference.sum_sqrt,
            "{name}: {} vs {}",
            got.sum_sqrt,
            reference.sum_sqrt
        );
    };
    let paths: Vec<(&str, KernelPath)> = [
        ("portable", KernelPath::Portable),
        ("avx2", KernelPath::Avx2),
        ("avx512", KernelPath::Avx512),
    ]
    .into_iter()
    .filter(|(_, p)| p.is_available())
    .collect();
    let on = |path, parallel| {
        sampler
            .sweep_addition_with(n, path, parallel)
            .expect("only available paths are run")
    };
    check("addition", sampler.sweep_addition(n));
    check("addition_serial", sampler.sweep_addition_serial(n));
    for &(name, path) in &paths {
        check(&format!("addition_{name}"), on(path, true));
        check(&format!("addition_{name}_serial"), on(path, false));
    }
    check("coef", sampler.sweep(n));
    check("coef_serial", sampler.sweep_serial(n));

    let mut g = c.benchmark_group("sample_sphere");
    g.sample_size(20);
    g.throughput(Throughput::Elements(n as u64));
    g.bench_function("addition_parallel", |b| {
        b.iter(|| sampler.sweep_addition(n))
    });
    g.bench_function("addition_serial", |b| {
        b.iter(|| sampler.sweep_addition_serial(n))
    });
    for &(name, path) in &paths {
        g.bench_function(format!("addition_{name}_serial"), |b| {
            b.iter(|| on(path, false))
        });
    }
    g.bench_function("coef_parallel", |b| b.iter(|| sampler.sweep(n)));
    g.bench_function("coef_serial", |b| b.iter(|| sampler.sweep_serial(n)));
    g.bench_function("direct_serial", |b| b.iter(|| sweep_direct(&cs, n)));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
