//! Workload W1 (Chiang's ruled-surface / plane theorem, SPEC §4, as a polynomial identity) at
//! `(m, n) = (2, 3), (4, 6), (8, 13)`:
//!
//! * `w1_text`: parse both sides of `w1_text(m, n)` (the text of `shared/anchors/w1_text.py`),
//!   expand them and compare — the whole `exactcheck prove` path;
//! * `w1_ring`: the identity built with the `Ring` API as `shared/anchors/w1_identity.py`'s flint
//!   backend builds it (x component and weight), residuals checked for zero;
//! * `fateman`: a generic dense multiplication, `f * (f + 1)` with `f = (1 + x + y + z + w)^8`
//!   (495 terms each, 245,025 term products), for comparison with other systems.
//!
//! Anchors on the same machine: `w1_identity.py flint 8 13` and `... sympy 8 13`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use exactcheck_core::{binomial, Ring};
use exactcheck_exact::expr::{parse_poly, w1_text};
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::Rational;

type P = Poly<Rational>;

const SIZES: [(u32, u32); 3] = [(2, 3), (4, 6), (8, 13)];

/// W1 from text: parse, expand, compare.
fn w1_text_proves(lhs: &str, rhs: &str) -> bool {
    let mut vars = Vars::new();
    let l: P = parse_poly(lhs, &mut vars).expect("LHS parses");
    let r: P = parse_poly(rhs, &mut vars).expect("RHS parses");
    l == r
}

/// W1 with the Ring API (as the flint backend of `w1_identity.py`): whether the x-component and
/// the weight residuals are both zero.
fn w1_ring_proves(m: u32, n: u32) -> bool {
    let mut vars = Vars::new();
    let mut v = |name: String| -> P { vars.poly(&name) };
    let (t, a, b, c, d) = (
        v("t".into()),
        v("a".into()),
        v("b".into()),
        v("c".into()),
        v("d".into()),
    );
    let mut seq = |s: &str, k: u32| (0..=k).map(|j| v(format!("{s}{j}"))).collect::<Vec<P>>();
    let (px, py, pz) = (seq("px", n), seq("py", n), seq("pz", n));
    let (qx, qy, qz) = (seq("qx", m), seq("qy", m), seq("qz", m));
    let one = P::one();
    let bern = |deg: u32, k: u32| {
        P::from_i64(binomial(deg, k) as i64) * t.pow(k) * (&one - &t).pow(deg - k)
    };
    let bez =
        |deg: u32, cp: &[P]| P::sum((0..=deg).map(|j| bern(deg, j) * &cp[j as usize]).collect());
    let (bx, by, bz) = (bez(n, &px), bez(n, &py), bez(n, &pz));
    let (vx, vy, vz) = (bez(m, &qx), bez(m, &qy), bez(m, &qz));
    let nv = &a * &vx + &b * &vy + &c * &vz;
    let nb = &a * &bx + &b * &by + &c * &bz;
    let p_lhs = &nv * &bx - (nb + &d) * &vx;
    let nq: Vec<P> = (0..=m as usize)
        .map(|i| &a * &qx[i] + &b * &qy[i] + &c * &qz[i])
        .collect();
    let np: Vec<P> = (0..=n as usize)
        .map(|j| &a * &px[j] + &b * &py[j] + &c * &pz[j])
        .collect();
    let (mut p_rhs, mut q_rhs) = (Vec::new(), Vec::new());
    for k in 0..=m + n {
        let (mut pt, mut wt) = (Vec::new(), Vec::new());
        for i in k.saturating_sub(n)..=k.min(m) {
            let j = k - i;
            let phi = P::constant(
                Rational::new(
                    (binomial(m, i) * binomial(n, j)) as i64,
                    binomial(m + n, k) as i64,
                )
                .expect("non-zero binomial"),
            );
            let (i, j) = (i as usize, j as usize);
            pt.push(&phi * &(&nq[i] * &px[j] - (&np[j] + &d) * &qx[i]));
            wt.push(&phi * &nq[i]);
        }
        p_rhs.push(bern(m + n, k) * P::sum(pt));
        q_rhs.push(bern(m + n, k) * P::sum(wt));
    }
    (p_lhs - P::sum(p_rhs)).is_zero() && (nv - P::sum(q_rhs)).is_zero()
}

fn bench_w1(c: &mut Criterion) {
    let mut group = c.benchmark_group("w1_text");
    group.measurement_time(Duration::from_secs(4));
    for (m, n) in SIZES {
        let (lhs, rhs) = w1_text(m, n);
        assert!(w1_text_proves(&lhs, &rhs));
        group.bench_with_input(
            BenchmarkId::from_parameter(format!("{m}x{n}")),
            &(lhs, rhs),
            |bch, (l, r)| bch.iter(|| black_box(w1_text_proves(black_box(l), black_box(r)))),
        );
    }
    group.finish();

    let mut group = c.benchmark_group("w1_ring");
    group.measurement_time(Duration::from_secs(4));
    for (m, n) in SIZES {
        assert!(w1_ring_proves(m, n));
        group.bench_with_input(
            BenchmarkId::from_parameter(format!("{m}x{n}")),
            &(m, n),
            |bch, &(m, n)| bch.iter(|| black_box(w1_ring_proves(black_box(m), black_box(n)))),
        );
    }
    group.finish();
}

fn bench_fateman(c: &mut Criterion) {
    let mut vars = Vars::new();
    let mut f: P = P::one();
    for name in ["x", "y", "z", "w"] {
        f += vars.poly::<Rational>(name);
    }
    let f = f.pow(8);
    let g = &f + &P::one();
    assert_eq!(f.len(), 495);
    let mut group = c.benchmark_group("fateman");
    group.sample_size(20);
    group.bench_function("8", |bch| {
        bch.iter(|| black_box(black_box(&f) * black_box(&g)).len())
    });
    group.finish();
}

criterion_group!(benches, bench_w1, bench_fateman);
criterion_main!(benches);
