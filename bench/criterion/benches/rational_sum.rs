//! Criterion benchmark of workload rational-sum (exact Spaeth discriminant; see `bench/src/rational_sum.rs`): the fast
//! `Rational` beside num-rational's plain `BigRational`, in the three modes at the anchors'
//! N = 2,000 and `seq` at N = 10,000 (fast scalar only). Before anything is timed, every
//! configuration's check values (`count_nonneg`, the sum's digit counts and residues mod
//! 1e9+7, as `bench/scripts/anchors/rational_sum.py` prints them, identical for gmpy2, FLINT and
//! Python's `Fraction`) are asserted. Whole-workload figures come from `exactcheck-bench rational-sum`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use exactcheck_bench::rational_sum::{self, Mode};
use exactcheck_exact::{PlainRational, Rational, RationalScalar};

/// `(count_nonneg, sum_num_digits, sum_den_digits, sum_num_mod_p, sum_den_mod_p)` printed by
/// the anchors (gmpy2 2.3.2 / GMP 6.3.0) for the sums at `n`.
fn expected_sum(n: usize) -> (usize, usize, usize, u64, u64) {
    match n {
        2_000 => (0, 12_783, 12_779, 288_945_042, 303_592_070),
        10_000 => (0, 56_276, 56_271, 988_689_208, 977_114_744),
        _ => panic!("no anchor check values recorded for N = {n}"),
    }
}

/// Runs the workload once and asserts the anchors' check values.
fn assert_check_values<T: RationalScalar>(n: usize, mode: Mode) {
    let out = rational_sum::run::<T>(n, mode);
    let (count, nd, dd, nm, dm) = expected_sum(n);
    assert_eq!(out.count_nonneg, count, "count_nonneg, {mode:?} N = {n}");
    match (mode, out.sum) {
        (Mode::Eval, None) => {}
        (Mode::Tree | Mode::Seq, Some(sum)) => {
            let cv = rational_sum::check_values(&sum);
            assert_eq!(
                (cv.num_digits, cv.den_digits, cv.num_mod_p, cv.den_mod_p),
                (nd, dd, nm, dm),
                "sum check values, {mode:?} N = {n}"
            );
        }
        (mode, sum) => panic!("{mode:?} returned sum {:?}", sum.is_some()),
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("rational_sum");
    g.sample_size(10);
    for (mode, n, plain) in [
        (Mode::Eval, 2_000, true),
        (Mode::Tree, 2_000, true),
        (Mode::Seq, 2_000, true),
        (Mode::Seq, 10_000, false),
    ] {
        assert_check_values::<Rational>(n, mode);
        if plain {
            assert_check_values::<PlainRational>(n, mode);
        }
        let name = format!("{mode:?}").to_lowercase();
        g.bench_with_input(BenchmarkId::new(format!("{name}/fast"), n), &n, |b, &n| {
            b.iter(|| rational_sum::run::<Rational>(n, mode).count_nonneg)
        });
        if plain {
            g.bench_with_input(BenchmarkId::new(format!("{name}/plain"), n), &n, |b, &n| {
                b.iter(|| rational_sum::run::<PlainRational>(n, mode).count_nonneg)
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
