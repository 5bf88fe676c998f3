//! Criterion benchmark of workload W2 (exact Spaeth discriminant; see `src/w2.rs`): the fast
//! `Rational` beside num-rational's plain `BigRational`, in the three modes, at sizes that keep a
//! run short. Whole-workload figures at the anchors' sizes come from `exactcheck bench w2` and
//! `scripts/compare_w2.sh`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use exactcheck::w2::{self, Mode};
use exactcheck_exact::{PlainRational, Rational};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("w2");
    g.sample_size(10);
    for (mode, n) in [(Mode::Eval, 10_000), (Mode::Tree, 10_000), (Mode::Seq, 500)] {
        let name = format!("{mode:?}").to_lowercase();
        g.bench_with_input(BenchmarkId::new(format!("{name}/fast"), n), &n, |b, &n| {
            b.iter(|| w2::run::<Rational>(n, mode).count_nonneg)
        });
        g.bench_with_input(BenchmarkId::new(format!("{name}/plain"), n), &n, |b, &n| {
            b.iter(|| w2::run::<PlainRational>(n, mode).count_nonneg)
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
