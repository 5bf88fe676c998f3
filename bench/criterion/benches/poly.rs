//! The workload chiang-identity (Chiang's ruled-surface / plane theorem, the claim list, as a polynomial identity) at
//! `(m, n) = (2, 3), (4, 6), (8, 13), (13, 21)`:
//!
//! * `identity_text`: parse both sides of `identity_text(m, n)` (the text of `bench/scripts/anchors/chiang_text.py`),
//!   expand them and compare — the whole `exactcheck prove` path;
//! * `identity_ring`: the identity built with the `Ring` API as `bench/scripts/anchors/chiang_identity.py`'s flint
//!   backend builds it (x component and weight, `exactcheck_bench::chiang_identity::ring_residuals`),
//!   residuals checked for zero;
//! * `fateman`: a generic dense multiplication, `f * (f + 1)` with `f = (1 + x + y + z + w)^k`
//!   for `k = 8, 12, 16` (at `k = 8` 495 terms each, 245,025 term products; `exactcheck-bench
//!   dense` and `bench/scripts/anchors/dense_product.py` time the same product), checked before timing.
//!
//! Anchors on the same machine: `chiang_identity.py flint 8 13` and `... sympy 8 13`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use exactcheck_bench::chiang_identity::{identity_text, ring_residuals};
use exactcheck_core::Ring;
use exactcheck_exact::expr::parse_poly;
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::Rational;

type P = Poly<Rational>;

const SIZES: [(u32, u32); 4] = [(2, 3), (4, 6), (8, 13), (13, 21)];

/// The identity from text: parse, expand, compare.
fn text_proves(lhs: &str, rhs: &str) -> bool {
    let mut vars = Vars::new();
    let l: P = parse_poly(lhs, &mut vars).expect("LHS parses");
    let r: P = parse_poly(rhs, &mut vars).expect("RHS parses");
    l == r
}

/// The identity with the Ring API: whether the x-component and the weight residuals are both zero.
fn ring_proves(m: u32, n: u32) -> bool {
    let (dp, dq) = ring_residuals(m, n, false);
    dp.is_zero() && dq.is_zero()
}

fn bench_identity(c: &mut Criterion) {
    let mut group = c.benchmark_group("identity_text");
    group.measurement_time(Duration::from_secs(4));
    for (m, n) in SIZES {
        let (lhs, rhs) = identity_text(m, n);
        assert!(text_proves(&lhs, &rhs));
        group.bench_with_input(
            BenchmarkId::from_parameter(format!("{m}x{n}")),
            &(lhs, rhs),
            |bch, (l, r)| bch.iter(|| black_box(text_proves(black_box(l), black_box(r)))),
        );
    }
    group.finish();

    let mut group = c.benchmark_group("identity_ring");
    group.measurement_time(Duration::from_secs(4));
    for (m, n) in SIZES {
        assert!(ring_proves(m, n));
        group.bench_with_input(
            BenchmarkId::from_parameter(format!("{m}x{n}")),
            &(m, n),
            |bch, &(m, n)| bch.iter(|| black_box(ring_proves(black_box(m), black_box(n)))),
        );
    }
    group.finish();
}

/// `f (f + 1)` with `f = (1 + x + y + z + w)^k`.
fn dense_factors(k: u32) -> (P, P) {
    let mut vars = Vars::new();
    let mut f: P = P::one();
    for name in ["x", "y", "z", "w"] {
        f += vars.poly::<Rational>(name);
    }
    let f = f.pow(k);
    let g = &f + &P::one();
    (f, g)
}

fn bench_fateman(c: &mut Criterion) {
    let mut group = c.benchmark_group("fateman");
    group.sample_size(20);
    for k in [8u32, 12, 16] {
        let (f, g) = dense_factors(k);
        // Check values before timing: C(2k + 4, 4) terms (every monomial of degree <= 2k in
        // four variables), and the coefficient sum f(1) (f(1) + 1) = 5^k (5^k + 1).
        let h = &f * &g;
        let terms = (1..=4u64).fold(1u64, |acc, i| acc * (2 * k as u64 + i) / i);
        assert_eq!(h.len() as u64, terms);
        let five = Rational::from_integer(5)
            .powi(k as i32)
            .expect("5 is not zero");
        let sum = h.coefficients().iter().fold(Rational::zero(), |s, c| s + c);
        assert_eq!(sum, five.mul_ref(&five.add_ref(&Rational::one())));
        group.bench_function(k.to_string(), |bch| {
            bch.iter(|| black_box(black_box(&f) * black_box(&g)).len())
        });
    }
    group.finish();
}

criterion_group!(benches, bench_identity, bench_fateman);
criterion_main!(benches);
