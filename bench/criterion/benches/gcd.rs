//! `gcd_biguint` against num-integer's `Integer::gcd` (Stein's binary algorithm) on pairs of
//! pseudo-random numbers with a common factor, at 2 to 6000 64-bit limbs; the half-gcd against
//! Lehmer's algorithm at 10^3 to 10^6 bits and around their crossover (which sets
//! `HGCD_GCD_THRESHOLD`), and the half-gcd's own size parameters.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode};
use exactcheck_core::Rng;
use exactcheck_exact::bigint::rem_1;
use exactcheck_exact::gcd::{
    gcd_biguint, gcd_hgcd_tuned, gcd_lehmer, gcd_u128, gcd_u64, HgcdTuning, HGCD_GCD_THRESHOLD,
    HGCD_TUNING,
};
use num_bigint::BigUint;
use num_integer::Integer;

fn random_biguint(limbs: usize, state: &mut Rng) -> BigUint {
    let digits: Vec<u32> = (0..2 * limbs).map(|_| state.next_u64() as u32).collect();
    BigUint::new(digits)
}

/// Two numbers of about `limbs` limbs sharing a random common factor of about a quarter of
/// that size.
fn pair(limbs: usize, seed: u64) -> (BigUint, BigUint) {
    let mut st = Rng::new(seed);
    let lg = (limbs / 4).max(1);
    let lx = limbs.saturating_sub(lg).max(1);
    let g = random_biguint(lg, &mut st);
    let x = random_biguint(lx, &mut st);
    let y = random_biguint(lx, &mut st);
    (x * &g, y * &g)
}

fn bench_gcd(c: &mut Criterion) {
    let mut group = c.benchmark_group("gcd");
    for &limbs in &[2usize, 16, 128, 1024, 6000] {
        let (a, b) = pair(limbs, 0x1234_5678 ^ limbs as u64);
        assert_eq!(gcd_biguint(&a, &b), {
            if limbs <= 1024 {
                a.gcd(&b)
            } else {
                gcd_biguint(&a, &b)
            }
        });
        if limbs >= 128 {
            group.sample_size(10);
            group.sampling_mode(SamplingMode::Flat);
            group.warm_up_time(Duration::from_millis(500));
            group.measurement_time(Duration::from_secs(3));
        } else {
            group.sample_size(50);
            group.sampling_mode(SamplingMode::Auto);
            group.warm_up_time(Duration::from_millis(500));
            group.measurement_time(Duration::from_secs(2));
        }
        group.bench_with_input(
            BenchmarkId::new("exactcheck", limbs),
            &(&a, &b),
            |bch, (a, b)| bch.iter(|| gcd_biguint(black_box(a), black_box(b))),
        );
        // num-integer is quadratic with a large constant: time one call first and skip it
        // above 1024 limbs when a single call takes more than 2 s.
        let start = Instant::now();
        let expected = a.gcd(&b);
        let once = start.elapsed();
        assert_eq!(expected, gcd_biguint(&a, &b));
        if limbs > 1024 && once > Duration::from_secs(2) {
            eprintln!("gcd/num-integer/{limbs}: skipped, one call took {once:?}");
            continue;
        }
        if limbs > 1024 {
            group.measurement_time(once * 12);
        }
        group.bench_with_input(
            BenchmarkId::new("num-integer", limbs),
            &(&a, &b),
            |bch, (a, b)| bch.iter(|| black_box(a).gcd(black_box(b))),
        );
    }
    group.finish();
}

/// A random number of exactly `bits` bits.
fn random_bits(bits: u64, st: &mut Rng) -> BigUint {
    let limbs = bits.div_ceil(64) as usize;
    let mut x = random_biguint(limbs, st) >> (64 * limbs as u64 - bits);
    x.set_bit(bits - 1, true);
    x
}

/// Two `bits`-bit numbers with a planted common factor of `bits / 8` bits, and their gcd by
/// Lehmer's algorithm, checked to be a multiple of the factor.
fn planted_pair(bits: u64, seed: u64) -> (BigUint, BigUint, BigUint) {
    let mut st = Rng::new(seed);
    let g = random_bits(bits / 8, &mut st);
    let a = random_bits(bits - bits / 8, &mut st) * &g;
    let b = random_bits(bits - bits / 8 - 3, &mut st) * &g;
    let d = gcd_lehmer(&a, &b);
    assert!(
        (&d % &g) == BigUint::from(0u32),
        "the planted factor divides the gcd"
    );
    (a, b, d)
}

/// The half-gcd path forced at every size.
const FORCED: HgcdTuning = HgcdTuning {
    gcd_lehmer_below: 2,
    ..HGCD_TUNING
};

fn slow_group_settings(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
) {
    group.sample_size(10);
    group.sampling_mode(SamplingMode::Flat);
    group.warm_up_time(Duration::from_millis(300));
    group.measurement_time(Duration::from_secs(3));
}

/// Lehmer's algorithm (`gcd_lehmer`) against the half-gcd (`gcd_hgcd_tuned` with the measured
/// tuning, forced at every size) and the dispatching `gcd_biguint`, at 10^3 to 10^6 bits, on
/// pairs with a planted common factor; every result is checked against Lehmer's before timing.
fn bench_hgcd_vs_lehmer(c: &mut Criterion) {
    let mut group = c.benchmark_group("hgcd_vs_lehmer");
    slow_group_settings(&mut group);
    for bits in [1_000u64, 10_000, 100_000, 1_000_000] {
        let (a, b, d) = planted_pair(bits, 0x4ec0 ^ bits);
        assert_eq!(gcd_hgcd_tuned(&a, &b, FORCED), d);
        assert_eq!(gcd_biguint(&a, &b), d);
        lehmer_and_half_gcd(&mut group, bits, &a, &b);
        group.bench_with_input(
            BenchmarkId::new("gcd_biguint", bits),
            &(&a, &b),
            |bch, (a, b)| bch.iter(|| gcd_biguint(black_box(a), black_box(b))),
        );
    }
    group.finish();
}

/// Lehmer against the forced half-gcd on one pair, in `group` under `bits`.
fn lehmer_and_half_gcd(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    bits: u64,
    a: &BigUint,
    b: &BigUint,
) {
    group.bench_with_input(BenchmarkId::new("lehmer", bits), &(a, b), |bch, (a, b)| {
        bch.iter(|| gcd_lehmer(black_box(a), black_box(b)))
    });
    group.bench_with_input(
        BenchmarkId::new("half-gcd", bits),
        &(a, b),
        |bch, (a, b)| bch.iter(|| gcd_hgcd_tuned(black_box(a), black_box(b), FORCED)),
    );
}

/// Around the crossover: random pairs (no planted factor, the full descent) from 150,000 to
/// 500,000 bits, Lehmer against the forced half-gcd; `HGCD_GCD_THRESHOLD` is where they meet.
fn bench_hgcd_crossover(c: &mut Criterion) {
    let mut group = c.benchmark_group("hgcd_crossover");
    slow_group_settings(&mut group);
    eprintln!("HGCD_GCD_THRESHOLD = {HGCD_GCD_THRESHOLD} limbs");
    let mut st = Rng::new(0xc805);
    for bits in [150_000u64, 200_000, 300_000, 400_000, 500_000] {
        let (a, b) = (random_bits(bits, &mut st), random_bits(bits, &mut st));
        assert_eq!(gcd_hgcd_tuned(&a, &b, FORCED), gcd_lehmer(&a, &b));
        lehmer_and_half_gcd(&mut group, bits, &a, &b);
    }
    group.finish();
}

/// The half-gcd's own parameters at 300,000 bits: the base-case size (`hgcd_base`, limbs) and
/// the split of the gcd's outer loop (`split`: hgcd on the leading `n - floor(n split / 3)`
/// limbs).
fn bench_hgcd_tuning(c: &mut Criterion) {
    let mut group = c.benchmark_group("hgcd_tuning");
    slow_group_settings(&mut group);
    let (a, b, d) = planted_pair(300_000, 0x7e4e);
    for hgcd_base in [40usize, 100, 150, 250] {
        for split in [0usize, 1, 2] {
            let t = HgcdTuning {
                hgcd_base,
                gcd_lehmer_below: 2,
                split,
            };
            assert_eq!(gcd_hgcd_tuned(&a, &b, t), d);
            let id = format!("base{hgcd_base}/split{split}");
            group.bench_with_input(BenchmarkId::new("half-gcd", id), &t, |bch, &t| {
                bch.iter(|| gcd_hgcd_tuned(black_box(&a), black_box(&b), t))
            });
        }
    }
    group.finish();
}

/// Machine-word gcds on 4096 pairs with a random common factor (about a quarter of the bits);
/// many distinct pairs, so that the branch predictor cannot learn them.
fn bench_words(c: &mut Criterion) {
    let mut st = Rng::new(0xabcd_ef01_u64);
    let p64: Vec<(u64, u64)> = (0..4096)
        .map(|_| {
            let g = st.next_u64() >> 48;
            ((st.next_u64() >> 16) * g, (st.next_u64() >> 16) * g)
        })
        .collect();
    let p128: Vec<(u128, u128)> = (0..4096)
        .map(|_| {
            let g = u128::from(st.next_u64() >> 32);
            let x = u128::from(st.next_u64()) << 32 | u128::from(st.next_u64() >> 32);
            let y = u128::from(st.next_u64()) << 32 | u128::from(st.next_u64() >> 32);
            (x * g, y * g)
        })
        .collect();
    let mut group = c.benchmark_group("gcd_words_x4096");
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
    group.bench_function("u64/exactcheck", |bch| {
        bch.iter(|| {
            p64.iter()
                .fold(0, |acc, &(a, b)| acc ^ gcd_u64(black_box(a), b))
        })
    });
    group.bench_function("u64/num-integer", |bch| {
        bch.iter(|| {
            p64.iter()
                .fold(0, |acc, &(a, b)| acc ^ black_box(a).gcd(&b))
        })
    });
    group.bench_function("u128/exactcheck", |bch| {
        bch.iter(|| {
            p128.iter()
                .fold(0, |acc, &(a, b)| acc ^ gcd_u128(black_box(a), b))
        })
    });
    group.bench_function("u128/num-integer", |bch| {
        bch.iter(|| {
            p128.iter()
                .fold(0, |acc, &(a, b)| acc ^ black_box(a).gcd(&b))
        })
    });
    group.finish();
}

/// Two random 350,000-bit numbers (no planted common factor: the full Euclidean descent).
fn bench_350k_bits(c: &mut Criterion) {
    let mut st = Rng::new(0x350_000);
    let limbs = 5469; // 350,016 bits, minus 16
    let mut a = random_biguint(limbs, &mut st) >> 16u32;
    let mut b = random_biguint(limbs, &mut st) >> 16u32;
    a.set_bit(349_999, true);
    b.set_bit(349_999, true);
    assert_eq!(a.bits(), 350_000);
    let mut group = c.benchmark_group("gcd_350000_bits");
    group.sample_size(10);
    group.sampling_mode(SamplingMode::Flat);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(3));
    group.bench_function("exactcheck", |bch| {
        bch.iter(|| gcd_biguint(black_box(&a), black_box(&b)))
    });
    group.finish();
}

/// Remainder of a big number by one limb (the step that starts every big-by-word gcd and the
/// addition of a word-sized rational to a big one): the folding kernel `bigint::rem_1`
/// against num-bigint's `&BigUint % u64`, at 10^4, 10^5 and 10^6 bits, for a 48-bit divisor
/// (the size of the rational-sum workload's denominators) and a full 64-bit one.
fn bench_rem_1(c: &mut Criterion) {
    let mut group = c.benchmark_group("rem_1");
    group.warm_up_time(Duration::from_millis(300));
    group.measurement_time(Duration::from_secs(2));
    let mut st = Rng::new(0x4e3);
    for bits in [10_000usize, 100_000, 1_000_000] {
        let x = random_biguint(bits.div_ceil(64), &mut st);
        let limbs = x.to_u64_digits();
        for d in [0xb7e1_5162_8aed_u64, 0xf3a9_52c1_0d7b_4e65] {
            assert_eq!(BigUint::from(rem_1(&limbs, d)), &x % d);
            let id = format!("{bits}/{}bit", 64 - d.leading_zeros());
            group.bench_with_input(BenchmarkId::new("exactcheck", &id), &d, |bch, &d| {
                bch.iter(|| rem_1(black_box(&limbs), d))
            });
            group.bench_with_input(BenchmarkId::new("num-bigint", &id), &d, |bch, &d| {
                bch.iter(|| black_box(&x) % d)
            });
        }
    }
    group.finish();
}

criterion_group!(
    benches,
    bench_gcd,
    bench_words,
    bench_350k_bits,
    bench_rem_1,
    bench_hgcd_vs_lehmer,
    bench_hgcd_crossover,
    bench_hgcd_tuning
);
criterion_main!(benches);
