use super::*;
use crate::sample_sphere::tests::workload_configuration;
use crate::sample_sphere::Sweep;
use exactcheck_core::cylinder_sphere::{Angle, CylinderSphere};
use exactcheck_core::rng::splitmix64;
use exactcheck_core::Vec3;
use exactcheck_float::convert::fsum;
use proptest::prelude::*;
use std::f64::consts::TAU;

/// Grid sizes: tiny, odd, around the lane, block and chunk boundaries, up to 10^6.
const GRIDS: &[usize] = &[
    1,
    2,
    3,
    5,
    7,
    8,
    9,
    17,
    100,
    BLOCK - 1,
    BLOCK,
    BLOCK + 1,
    BLOCK + LANES - 1,
    1000,
    2 * BLOCK + 3,
    4099,
    CHUNK - 1,
    CHUNK,
    CHUNK + 1,
    2 * CHUNK + BLOCK + 5,
    99_991,
    262_147,
    1_000_003,
];

#[test]
fn an_empty_grid_is_the_empty_summary_as_in_the_reference() {
    let s = DiscSampler::new(&workload_configuration());
    assert_eq!(s.sweep_addition(0), s.sweep(0));
    assert_eq!(s.sweep_addition_serial(0), s.sweep(0));
    assert_eq!(s.sweep(0).count_nonneg, 0);
}

/// Random configurations (axis point, radii, angles from Pythagorean triples, centre) from
/// seeded SplitMix64, with the workload's first.
fn configurations() -> Vec<CylinderSphere<f64>> {
    let mut out = vec![workload_configuration()];
    out.extend((0..4).map(|k| configuration(14 + k, k as usize)));
    out
}

/// A random configuration from the seed, at the scale `[1, 10, 0.01, 1000][k]`.
fn configuration(seed: u64, k: usize) -> CylinderSphere<f64> {
    let mut state = seed;
    let mut uniform = |lo: f64, hi: f64| {
        lo + (hi - lo) * (splitmix64(&mut state) >> 11) as f64 / (1u64 << 53) as f64
    };
    let angle = |t: f64| Angle {
        cos: (1.0 - t * t) / (1.0 + t * t),
        sin: 2.0 * t / (1.0 + t * t),
    };
    let scale = [1.0, 10.0, 0.01, 1000.0][k];
    CylinderSphere {
        a: uniform(-1.0, 1.0) * scale,
        b: uniform(-1.0, 1.0) * scale,
        r: uniform(0.5, 3.0) * scale,
        beta: angle(uniform(-2.0, 2.0)),
        gamma: angle(uniform(-2.0, 2.0)),
        center: Vec3::new(
            uniform(-2.0, 2.0) * scale,
            uniform(-2.0, 2.0) * scale,
            uniform(-2.0, 2.0) * scale,
        ),
        radius: uniform(1.0, 4.0) * scale,
    }
}

/// The kernel's discriminants written out plainly: the polynomial's coefficients, the block's
/// start angle and every table angle by their own `sin_cos`, then the per-sample formula.
fn plain_discs(s: &DiscSampler, n: usize, i0: usize, len: usize) -> Vec<f64> {
    let ([a0, a1, a2], [b0, b1, b2, b3, b4, b5]) = s.coefficients();
    let d0 = a0 * a0 + 0.5 * (a1 * a1 + a2 * a2) - b0 - 0.5 * (b3 + b5);
    let (d1, d2) = (2.0 * a0 * a1 - b1, 2.0 * a0 * a2 - b2);
    let (d3, d4) = (
        0.5 * (a1 * a1 - a2 * a2) - 0.5 * (b3 - b5),
        a1 * a2 - 0.5 * b4,
    );
    let dt = TAU / n as f64;
    let a = i0 as f64 * dt;
    let (s1, c1) = a.sin_cos();
    let (c2, s2) = (c1 * c1 - s1 * s1, 2.0 * s1 * c1);
    let (e1, e2) = (d1 * c1 + d2 * s1, d2 * c1 - d1 * s1);
    let (e3, e4) = (d3 * c2 + d4 * s2, d4 * c2 - d3 * s2);
    (0..len)
        .map(|j| {
            let theta = j as f64 * dt;
            let ((sj, cj), (s2j, c2j)) = (theta.sin_cos(), (2.0 * theta).sin_cos());
            d0 + e1 * cj + e2 * sj + e3 * c2j + e4 * s2j
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The kernel's first pass is the plain formula bit for bit, and its count the number of
    /// nonnegative values, for random configurations, grids and block starts.
    #[test]
    fn the_kernel_is_the_plain_formula(seed in any::<u64>(), k in 0usize..4, n in 1usize..3_000_000, start in 0.0f64..1.0) {
        let s = DiscSampler::new(&configuration(seed, k));
        let table = AngleTable::new(n);
        let i0 = ((start * n as f64) as usize).min(n - 1);
        let len = BLOCK.min(n - i0);
        let mut d = vec![0.0; len];
        let count = table.discs(&Trig2::new(&s), i0, &mut d);
        let want = plain_discs(&s, n, i0, len);
        prop_assert_eq!(count, want.iter().filter(|&&x| x >= 0.0).count());
        for (got, want) in d.iter().zip(&want) {
            prop_assert_eq!(got.to_bits(), want.to_bits());
        }
    }

    /// Against the straightforward implementation (`A^2 - B` at `sin_cos` per sample): every
    /// sample of a block at a random start of a random grid, for random configurations, is
    /// within the stated bound, which is within 66 u of the discriminant's scale.
    #[test]
    fn the_kernel_is_within_the_bound_of_the_straightforward_evaluation(seed in any::<u64>(), k in 0usize..4, n in 1usize..20_000_000, start in 0.0f64..1.0) {
        let s = DiscSampler::new(&configuration(seed, k));
        let bound = s.addition_disc_error();
        prop_assert!(s.addition_disc_error_scaled() < 66.0);
        let table = AngleTable::new(n);
        let i0 = ((start * n as f64) as usize).min(n - 1);
        let mut d = vec![0.0; BLOCK.min(n - i0)];
        table.discs(&Trig2::new(&s), i0, &mut d);
        for (j, &x) in d.iter().enumerate() {
            let reference = s.discriminant((i0 + j) as f64 * table.dt());
            prop_assert!((x - reference).abs() <= bound, "i = {}: {} vs {}", i0 + j, x, reference);
        }
    }

    /// The trigonometric polynomial is the discriminant: at random angles its plain evaluation
    /// agrees with `A^2 - B` within the bound.
    #[test]
    fn the_polynomial_is_the_discriminant(seed in any::<u64>(), k in 0usize..4, t in -10.0f64..10.0) {
        let s = DiscSampler::new(&configuration(seed, k));
        let p = Trig2::new(&s);
        prop_assert!((p.at(t) - s.discriminant(t)).abs() <= s.addition_disc_error());
    }
}

#[test]
fn blocks_may_start_anywhere_within_the_bound() {
    // The bound does not use i0 mod BLOCK: starts at odd places of a 10^7 grid, the
    // largest angles of the grid included.
    let n = 10_000_000;
    let s = workload_sampler();
    let bound = s.addition_disc_error();
    let table = AngleTable::new(n);
    let p = Trig2::new(&s);
    let mut d = [0.0; BLOCK];
    let mut state = 3;
    let mut starts: Vec<usize> = (0..200)
        .map(|_| (splitmix64(&mut state) % (n - BLOCK) as u64) as usize)
        .collect();
    starts.push(n - BLOCK);
    for i0 in starts {
        table.discs(&p, i0, &mut d);
        for (j, &x) in d.iter().enumerate() {
            let reference = s.discriminant((i0 + j) as f64 * table.dt());
            assert!((x - reference).abs() <= bound, "i = {}", i0 + j);
        }
    }
}

#[test]
fn every_samples_discriminant_is_within_the_stated_bound() {
    for cs in configurations() {
        let sampler = DiscSampler::new(&cs);
        let d = sampler.addition_disc_error();
        assert!(d > 0.0 && sampler.addition_disc_error_scaled() < 66.0);
        let p = Trig2::new(&sampler);
        let mut worst: f64 = 0.0;
        for &n in GRIDS {
            let table = AngleTable::new(n);
            let mut buf = [0.0; BLOCK];
            for i0 in (0..n).step_by(BLOCK) {
                let len = BLOCK.min(n - i0);
                let count = table.discs(&p, i0, &mut buf[..len]);
                assert_eq!(count, buf[..len].iter().filter(|&&x| x >= 0.0).count());
                for (j, &kernel) in buf[..len].iter().enumerate() {
                    let i = i0 + j;
                    let reference = sampler.discriminant(i as f64 * table.dt());
                    assert!((kernel - reference).abs() <= d, "n = {n}, i = {i}");
                    worst = worst.max((kernel - reference).abs() / d);
                }
            }
        }
        // The largest difference seen, as a fraction of the bound (printed with --nocapture).
        println!("largest |kernel - reference| / D: {worst}");
    }
}

#[test]
fn the_workloads_discriminant_bound_is_as_stated() {
    let s = DiscSampler::new(&workload_configuration());
    let d = s.addition_disc_error();
    let scaled = s.addition_disc_error_scaled();
    println!("workload: D = {d:e}, {scaled} u of the scale");
    assert!(d > 3.3e-13 && d < 3.4e-13, "{d:e}");
    assert!(scaled > 28.0 && scaled < 30.0, "{scaled}");
}

#[test]
fn count_and_sum_agree_with_the_reference_within_the_stated_bounds() {
    for (k, cs) in configurations().into_iter().enumerate() {
        let sampler = DiscSampler::new(&cs);
        let d = sampler.addition_disc_error();
        for &n in GRIDS {
            if k > 0 && n > 300_000 {
                continue;
            }
            let dt = TAU / n as f64;
            let discs: Vec<f64> = (0..n)
                .map(|i| sampler.discriminant(i as f64 * dt))
                .collect();
            let sure = discs.iter().filter(|&&x| x > d).count();
            let near_zero = discs.iter().filter(|&&x| x.abs() <= d).count();
            let roots: Vec<f64> = discs
                .iter()
                .filter(|&&x| x >= 0.0)
                .map(|x| x.sqrt())
                .collect();
            let got = sampler.sweep_addition(n);
            assert!(
                sure <= got.count_nonneg && got.count_nonneg <= sure + near_zero,
                "config {k}, n = {n}: {} not in {sure}..={}",
                got.count_nonneg,
                sure + near_zero
            );
            if near_zero == 0 {
                assert_eq!(got.count_nonneg, roots.len(), "config {k}, n = {n}");
            }
            let exact = fsum(&roots);
            let bound = sum_error_bound(n, got.sum_sqrt, &discs, d);
            assert!(
                (got.sum_sqrt - exact).abs() <= bound,
                "config {k}, n = {n}: {} vs {exact}, bound {bound:e}",
                got.sum_sqrt
            );
        }
    }
}

#[test]
fn paths_and_thread_counts_give_identical_bits() {
    let paths = [KernelPath::Portable, KernelPath::Avx2, KernelPath::Avx512];
    for cs in configurations() {
        let s = DiscSampler::new(&cs);
        for &n in GRIDS.iter().filter(|&&n| n <= 300_000) {
            let serial = s.sweep_addition_serial(n);
            assert_eq!(serial, s.sweep_addition(n), "n = {n}");
            for path in paths.into_iter().filter(|p| p.is_available()) {
                for parallel in [false, true] {
                    assert_eq!(s.sweep_addition_with(n, path, parallel), Some(serial));
                }
            }
        }
    }
    assert!(KernelPath::Portable.is_available());
    assert!(KernelPath::detect().is_available());
    for path in paths.into_iter().filter(|p| !p.is_available()) {
        assert_eq!(
            workload_sampler().sweep_addition_with(10, path, false),
            None
        );
    }
}

#[test]
fn the_detected_path_is_the_widest_this_cpu_runs() {
    let widest = [KernelPath::Avx512, KernelPath::Avx2, KernelPath::Portable]
        .into_iter()
        .find(|p| p.is_available());
    assert_eq!(Some(KernelPath::detect()), widest);
    #[cfg(target_arch = "x86_64")]
    {
        assert_eq!(
            KernelPath::Avx2.is_available(),
            is_x86_feature_detected!("avx2")
        );
        // AVX-512 exactly when the CPU has it and the compiler compiles for it (1.89 and newer).
        assert_eq!(
            KernelPath::Avx512.is_available(),
            rustversion::cfg!(since(1.89)) && is_x86_feature_detected!("avx512f")
        );
    }
}

/// The kernel's reduction written out plainly, sample by sample: lane `j mod LANES` of
/// block-relative index `j`, no block skipped, lanes added pairwise, chunks in order.
fn plain_lanes(s: &DiscSampler, n: usize) -> GridSummary {
    let table = AngleTable::new(n);
    let mut total = GridSummary {
        count_nonneg: 0,
        sum_sqrt: 0.0,
    };
    for lo in (0..n).step_by(CHUNK) {
        let (mut sum, mut count) = ([0.0f64; LANES], 0);
        for i0 in (lo..(lo + CHUNK).min(n)).step_by(BLOCK) {
            let mut d = vec![0.0; BLOCK.min(n - i0)];
            table.discs(&Trig2::new(s), i0, &mut d);
            for (j, &x) in d.iter().enumerate() {
                if x >= 0.0 {
                    count += 1;
                    sum[j % LANES] += x.sqrt();
                } else {
                    sum[j % LANES] += 0.0;
                }
            }
        }
        let l: Vec<f64> = (0..LANES / 2)
            .map(|k| sum[k] + sum[k + LANES / 2])
            .collect();
        let l: Vec<f64> = (0..LANES / 4).map(|k| l[k] + l[k + LANES / 4]).collect();
        total.count_nonneg += count;
        total.sum_sqrt += l[0] + l[1];
    }
    total
}

#[test]
fn the_reduction_is_the_plain_lane_sum_bit_for_bit() {
    assert_eq!(LANES, 8, "plain_lanes spells out three levels");
    for cs in configurations() {
        let s = DiscSampler::new(&cs);
        for &n in GRIDS.iter().filter(|&&n| n <= 300_000) {
            let got = s.sweep_addition(n);
            let want = plain_lanes(&s, n);
            assert_eq!(got.count_nonneg, want.count_nonneg, "n = {n}");
            assert_eq!(got.sum_sqrt.to_bits(), want.sum_sqrt.to_bits(), "n = {n}");
        }
    }
}

fn workload_sampler() -> DiscSampler {
    DiscSampler::new(&workload_configuration())
}

#[test]
fn the_summation_depth_is_lanes_blocks_and_chunks() {
    assert_eq!(sum_depth(10_000_000), CHUNK / LANES + 3 + 611);
    assert_eq!(sum_depth(1), CHUNK / LANES + 3 + 1);
}

/// The check values of `sample_sphere_numpy.py` at N = 10^7 on every path: count exactly, sum to 1e-12
/// relative; and the reference sweep's sum (exact sum of its square roots) within the bound.
#[test]
#[cfg_attr(debug_assertions, ignore = "release-mode test: 10^7 samples per path")]
fn check_values_at_ten_million() {
    let n = 10_000_000;
    let s = workload_sampler();
    let numpy = 13229714.773764007;
    for path in [KernelPath::Portable, KernelPath::Avx2, KernelPath::Avx512] {
        let Some(got) = s.sweep_addition_with(n, path, true) else {
            continue;
        };
        assert_eq!(got.count_nonneg, 3_415_478, "{path:?}");
        assert!(
            (got.sum_sqrt - numpy).abs() <= 1e-12 * numpy,
            "{path:?}: {:?}",
            got.sum_sqrt
        );
    }
    let dt = TAU / n as f64;
    let discs: Vec<f64> = (0..n).map(|i| s.discriminant(i as f64 * dt)).collect();
    let roots: Vec<f64> = discs
        .iter()
        .filter(|&&x| x >= 0.0)
        .map(|x| x.sqrt())
        .collect();
    assert_eq!(roots.len(), 3_415_478);
    let got = s.sweep_addition(n);
    let d = s.addition_disc_error();
    assert_eq!(discs.iter().filter(|&&x| x.abs() <= d).count(), 0);
    let bound = sum_error_bound(n, got.sum_sqrt, &discs, d);
    println!("sum bound at 10^7: {:e} relative", bound / got.sum_sqrt);
    assert!(bound < 3.4e-13 * numpy, "{bound:e}");
    assert!((got.sum_sqrt - fsum(&roots)).abs() <= bound);
}
