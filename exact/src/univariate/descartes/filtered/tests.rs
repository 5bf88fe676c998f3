//! The filtered subdivision against the exact one and against Sturm counts.

use super::super::super::bench_instances;
use super::super::super::sturm::SquareFree;
use super::*;
use exactcheck_core::{OrderedField, Rng};
use proptest::prelude::*;

fn bigs(c: &[i64]) -> Vec<BigInt> {
    c.iter().map(|&x| BigInt::from(x)).collect()
}

fn upoly_of(q: &[BigInt]) -> UPoly {
    UPoly::from_coeffs(q.iter().cloned().map(Rational::from).collect())
}

/// The integer polynomial with these rational roots `(num, den)` times `rest`.
fn product(roots: &[(BigInt, BigInt)], rest: &[i64]) -> Vec<BigInt> {
    let mut p = UPoly::from_i64_coeffs(rest);
    for (num, den) in roots {
        p *= UPoly::from_coeffs(vec![
            Rational::from(-num.clone()),
            Rational::from(den.clone()),
        ]);
    }
    p.integer_coefficients()
}

fn small(roots: &[(i64, i64)]) -> Vec<(BigInt, BigInt)> {
    roots
        .iter()
        .map(|&(u, v)| (BigInt::from(u), BigInt::from(v)))
        .collect()
}

/// The four unit problems of the primitive square-free part of `c` (as `isolate_square_free`).
fn unit_problems(c: &[BigInt]) -> Vec<Vec<BigInt>> {
    let q = prepare(c).expect("not zero").expect("not constant");
    let neg: Vec<BigInt> = q
        .iter()
        .enumerate()
        .map(|(i, c)| if i % 2 == 1 { -c } else { c.clone() })
        .collect();
    let rev: Vec<BigInt> = q.iter().rev().cloned().collect();
    let rev_neg: Vec<BigInt> = neg.iter().rev().cloned().collect();
    vec![q, rev, neg, rev_neg]
}

/// `(lo, hi)` of a unit root.
fn ends(r: &UnitRoot) -> (Rational, Rational) {
    match r {
        UnitRoot::Exact(c, j) => (dyadic(c, *j), dyadic(c, *j)),
        UnitRoot::Open { a, b, .. } => (a.clone(), b.clone()),
    }
}

/// Checks `found` as the roots of the square-free `p` in `(0, 1)`: `count` of them, exact ones
/// roots, open ones inside `[0, 1]` with end values of opposite non-zero signs, all pairwise
/// disjoint. Each holds a root and they are disjoint, so with the right count each holds
/// exactly one.
fn check_unit(p: &[BigInt], found: &[UnitRoot], count: usize) {
    assert_eq!(found.len(), count, "{p:?}");
    let mut spans: Vec<(Rational, Rational)> = found.iter().map(ends).collect();
    spans.sort();
    for w in spans.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        assert!(
            a.1 <= b.0 && (a.0 != a.1 || b.0 != b.1 || a.0 != b.0),
            "{a:?} and {b:?} overlap, {p:?}"
        );
        // A point is not inside an open interval.
        if b.0 == b.1 {
            assert!(a.1 <= b.0);
        }
    }
    for r in found {
        let (lo, hi) = ends(r);
        assert!(lo >= Rational::ZERO && hi <= Rational::ONE, "{lo} {hi}");
        if lo == hi {
            assert!(lo > Rational::ZERO && lo < Rational::ONE);
            assert_eq!(sign_at_rational(p, &lo), Sign::Zero, "{lo} of {p:?}");
        } else {
            let (a, b) = (sign_at_rational(p, &lo), sign_at_rational(p, &hi));
            assert!(
                a != Sign::Zero && b != Sign::Zero && a != b,
                "({lo}, {hi}) of {p:?}"
            );
        }
    }
}

/// The number of roots of the square-free `p` in `(0, 1)` by Sturm's theorem.
fn sturm_unit_count(p: &[BigInt]) -> usize {
    let sf = SquareFree::new(&upoly_of(p));
    let in_half_open = sf.count(&Rational::ZERO, &Rational::ONE);
    in_half_open - usize::from(sign_at_rational(p, &Rational::ONE) == Sign::Zero)
}

fn exact_unit_roots(p: &[BigInt], pairs: bool) -> Vec<UnitRoot> {
    let opts = Options {
        pairs,
        filtered: false,
        ..Options::FAST
    };
    unit_roots(p, opts)
}

fn filtered_unit_roots(p: &[BigInt], pairs: bool) -> (Vec<UnitRoot>, FilterStats) {
    unit_roots_filtered(p, pairs)
}

/// Runs the filtered and the exact subdivision on every unit problem of `c` (with and without
/// the close pairs), checks both, the count from the exact path (and from Sturm with `sturm`);
/// returns the summed statistics of the filtered runs with pairs.
fn compare(c: &[BigInt], sturm: bool) -> FilterStats {
    let mut total = FilterStats::default();
    for p in unit_problems(c) {
        let exact = exact_unit_roots(&p, true);
        let count = exact.len();
        if sturm {
            assert_eq!(count, sturm_unit_count(&p), "{p:?}");
        }
        check_unit(&p, &exact, count);
        for pairs in [true, false] {
            let (found, stats) = filtered_unit_roots(&p, pairs);
            check_unit(&p, &found, count);
            if pairs {
                total.splits += stats.splits;
                total.exact_midpoints += stats.exact_midpoints;
                total.anchors += stats.anchors;
                total.fallbacks += stats.fallbacks;
            }
        }
    }
    total
}

#[test]
fn wilkinson_products_agree_without_the_exact_subdivision() {
    for n in 1..=60 {
        let stats = compare(&bench_instances::wilkinson(n), n <= 24);
        assert_eq!(stats.fallbacks, 0, "wilkinson({n}): {stats:?}");
    }
}

#[test]
fn random_benchmark_polynomials_agree() {
    for d in 2..=120 {
        compare(&bench_instances::random(d), d <= 30);
    }
}

#[test]
fn mignotte_polynomials_agree() {
    for n in 3..=60 {
        compare(&bench_instances::mignotte(n), n <= 30);
    }
}

#[test]
fn dyadic_roots_and_roots_at_zero_and_one() {
    // (2x - 1)(4x - 1)(8x - 3)(16x - 5)(32x - 7)...: every root a subdivision point.
    let dyadics: Vec<(i64, i64)> = vec![(1, 2), (1, 4), (3, 8), (5, 16), (7, 32), (9, 64), (-3, 4)];
    let c = product(&small(&dyadics), &[1]);
    compare(&c, true);
    let mut roots = dyadics.clone();
    roots.extend([(0, 1), (1, 1), (-1, 1), (3, 1), (-5, 4)]);
    let c = product(&small(&roots), &[1]);
    compare(&c, true);
    // Exact roots reported as such by the filtered path.
    let q = product(&small(&[(1, 2), (1, 4), (3, 8)]), &[1]);
    let (found, _) = filtered_unit_roots(&q, true);
    let exact = found
        .iter()
        .filter(|r| matches!(r, UnitRoot::Exact(..)))
        .count();
    assert_eq!(exact, 3);
}

#[test]
fn close_clusters() {
    let third = (BigInt::one() << 200u32) / 3u32;
    let mut roots = Vec::new();
    for e in [30u32, 45, 60, 90] {
        // The root third / 2^200 and one 2^-e above it, and a pair near 5/7.
        roots.push((
            third.clone() + (BigInt::one() << (200 - e)),
            BigInt::one() << 200u32,
        ));
    }
    roots.push((third, BigInt::one() << 200u32));
    roots.extend(small(&[(5, 7), (-5, 7)]));
    roots.push((
        BigInt::from(5) * (BigInt::one() << 70u32) + 1,
        BigInt::from(7) * (BigInt::one() << 70u32),
    ));
    let c = product(&roots, &[1, 0, 1]);
    compare(&c, true);
}

#[test]
fn huge_coefficients_tiny_and_huge_roots() {
    let one = BigInt::one();
    // Coefficients above 2^1100: a root near 1 with a 1100-bit denominator, roots 2^-300 and
    // 2^300 (the latter through the reciprocal unit problems), -2^-300 and -2^300.
    let roots = vec![
        ((&one << 1100u32) - 1, &one << 1100u32),
        (one.clone(), &one << 300u32),
        (&one << 300u32, one.clone()),
        (-one.clone(), &one << 300u32),
        (-(&one << 300u32), one.clone()),
        (BigInt::from(2), BigInt::from(3)),
    ];
    let c = product(&roots, &[1]);
    assert!(c.iter().any(|x| x.bits() > 1100));
    compare(&c, true);
    // Random 1200-bit coefficients.
    let mut rng = Rng::new(1100);
    for n in [3usize, 8, 17] {
        let c: Vec<BigInt> = (0..=n)
            .map(|_| {
                let mut x = BigInt::from(rng.below(1 << 30) as i64 - (1 << 29));
                for _ in 0..40 {
                    x = (x << 30u32) + BigInt::from(rng.below(1 << 30));
                }
                x
            })
            .collect();
        compare(&c, true);
    }
}

#[test]
fn anchors_restore_precision_where_the_root_conversion_runs_out() {
    // Wilkinson 40: the Bernstein coefficients on [0, 1] span far more than f64 resolves in
    // the middle of the interval; the f64 coefficients are recomputed from exact ones there.
    let p = &unit_problems(&bench_instances::wilkinson(40))[0];
    let count = exact_unit_roots(p, true).len();
    assert_eq!(count, 39);
    let (found, stats) = filtered_unit_roots(p, true);
    assert!(stats.anchors > 0, "{stats:?}");
    assert_eq!(stats.fallbacks, 0, "{stats:?}");
    check_unit(p, &found, count);
}

#[test]
fn the_exact_fallback_is_taken_below_the_depth_cap_and_is_correct() {
    // Roots 1/3 and 1/3 + 2^-80 (times x^2 + 1), without the pair splitter: separated at depth
    // about 80, below the cap of 20 handed to the exact subdivision.
    let a = (BigInt::one() << 200u32) / 3u32;
    let b = &a + (BigInt::one() << 120u32);
    let den = BigInt::one() << 200u32;
    let c = product(&[(a, den.clone()), (b, den)], &[1, 0, 1]);
    let p = &unit_problems(&c)[0];
    let (found, stats) = subdivide(p, false, 20);
    assert!(stats.fallbacks > 0, "{stats:?}");
    check_unit(p, &found, 2);
    // The default cap: f64 (re-anchored) separates the pair.
    let (found, stats) = filtered_unit_roots(p, false);
    assert_eq!(stats.fallbacks, 0, "{stats:?}");
    check_unit(p, &found, 2);
    // Mignotte 40 (pair 1.4e-21 apart) without pairs: the same, both caps.
    let p = &unit_problems(&bench_instances::mignotte(40))[0];
    let count = exact_unit_roots(p, false).len();
    let (found, stats) = subdivide(p, false, 20);
    assert!(stats.fallbacks > 0, "{stats:?}");
    check_unit(p, &found, count);
    let (found, _) = filtered_unit_roots(p, false);
    check_unit(p, &found, count);
    // With the pair splitter the pair is separated early, without the exact subdivision.
    let (found, stats) = filtered_unit_roots(p, true);
    assert_eq!(stats.fallbacks, 0, "{stats:?}");
    check_unit(p, &found, count);
}

#[test]
fn uncertain_midpoints_are_decided_exactly() {
    // Wilkinson 20: the roots 1/4, 1/2, 3/4 are split points; their f64 values are rounding
    // noise, so the exact evaluation decides them (zero: exact roots).
    let p = &unit_problems(&bench_instances::wilkinson(20))[0];
    let (found, stats) = filtered_unit_roots(p, true);
    assert!(stats.exact_midpoints >= 3, "{stats:?}");
    let exact: Vec<Rational> = found
        .iter()
        .filter_map(|r| match r {
            UnitRoot::Exact(c, j) => Some(dyadic(c, *j)),
            UnitRoot::Open { .. } => None,
        })
        .collect();
    for k in 1..=3 {
        assert!(
            exact.contains(&Rational::new(k, 4).expect("4")),
            "{exact:?}"
        );
    }
}

#[test]
fn root_conversion_is_within_its_bound() {
    let mut rng = Rng::new(52);
    for round in 0..200 {
        let n = 1 + rng.below(12) as usize;
        let bits = [1u32, 20, 63, 64, 65, 200, 1500][round % 7];
        let b: Vec<BigInt> = (0..=n)
            .map(|i| {
                // Some entries much smaller than the largest (deep underflow below 2^-1074).
                let own = if i % 3 == 2 { 1 } else { bits };
                let mut x = BigInt::from(rng.below(3) as i64 - 1);
                for _ in 0..own.div_ceil(16) {
                    x = (x << 16u32) + BigInt::from(rng.below(1 << 16));
                }
                x
            })
            .collect();
        // Pushed after an existing block (the leading bits read off the two's complement).
        let mut g = vec![7.0];
        let e = f64_coefficients_limbs(&Limbs::from_bigints(&b), &mut g);
        let g = g.split_off(1);
        let k = b.iter().map(BigInt::bits).max().unwrap_or(0);
        let m = max_abs(&g);
        if m == 0.0 {
            continue;
        }
        assert!((0.5..=1.0).contains(&m), "{m}");
        let e = rational_of_f64(e).expect("finite");
        for (x, gi) in b.iter().zip(&g) {
            let exact = Rational::from(x.clone()) / pow2(k);
            let err = (rational_of_f64(*gi).expect("finite") - exact).abs();
            assert!(err <= e, "{x} -> {gi}");
        }
    }
}

#[test]
fn root_node_is_within_its_bound() {
    let mut rng = Rng::new(53);
    let mut cases: Vec<Vec<BigInt>> = vec![
        bench_instances::wilkinson(40),
        bench_instances::mignotte(60),
        bench_instances::random(120),
        product(&small(&[(1, 3), (2, 3)]), &[1]),
    ];
    for n in [1usize, 2, 5, 13, 40] {
        for bits in [3u32, 64, 300, 1200] {
            cases.push(
                (0..=n)
                    .map(|_| {
                        let mut x = BigInt::from(rng.below(3) as i64 - 1);
                        for _ in 0..bits.div_ceil(16) {
                            x = (x << 16u32) + BigInt::from(rng.below(1 << 16));
                        }
                        x
                    })
                    .collect(),
            );
        }
    }
    for p in cases {
        if p.iter().skip(1).all(Zero::is_zero) {
            continue;
        }
        let n = p.len() - 1;
        let mut g = Vec::new();
        let (root, scale) = root_f64_coefficients(&p, &binomials_f64(n), &mut g);
        // The exact values 2^scale c_(n-i) / C(n, i), c by the BigInt Taylor shift.
        let mut c: Vec<BigInt> = p.iter().rev().cloned().collect();
        taylor_shift_1(&mut c);
        let e = rational_of_f64(root.e).expect("finite");
        let two_scale = if scale >= 0 {
            pow2(scale as u64)
        } else {
            Rational::ONE / pow2((-scale) as u64)
        };
        let mut binom = BigInt::one();
        for i in 0..=n {
            let exact = Rational::from(c[n - i].clone()) * two_scale.clone()
                / Rational::from(binom.clone());
            let err = (rational_of_f64(g[i]).expect("finite") - exact).abs();
            assert!(err <= e, "coefficient {i} of {p:?}");
            binom = binom * BigInt::from(n - i) / BigInt::from(i + 1);
        }
        assert!((0.5..1.0 + 1e-12).contains(&max_abs(&g)));
        assert_eq!(root.lo, sign_of(&c[n]));
        assert_eq!(root.hi, sign_of(&c[0]));
    }
}

/// The exact de Casteljau halves of `g` (taken as exact rationals).
fn exact_halves(g: &[f64]) -> (Vec<Rational>, Vec<Rational>) {
    let n = g.len() - 1;
    let mut work: Vec<Rational> = g
        .iter()
        .map(|&x| rational_of_f64(x).expect("finite"))
        .collect();
    let mut left = vec![work[0].clone()];
    let mut right = vec![Rational::ZERO; n + 1];
    right[n] = work[n].clone();
    let half = Rational::new(1, 2).expect("2");
    for k in 1..=n {
        for i in 0..=n - k {
            work[i] = (work[i].clone() + work[i + 1].clone()) * half.clone();
        }
        left.push(work[0].clone());
        right[n - k] = work[n - k].clone();
    }
    (left, right)
}

#[test]
fn a_split_stays_within_its_bound() {
    let mut rng = Rng::new(40);
    for round in 0..300 {
        let n = 1 + rng.below(40) as usize;
        let g: Vec<f64> = (0..=n)
            .map(|i| {
                let x = (rng.below(1 << 53) as f64) / (1u64 << 53) as f64 - 0.5;
                // Some entries tiny (subnormal after halvings).
                if round % 5 == 0 && i % 2 == 0 {
                    x * pow2f(-1060)
                } else {
                    x
                }
            })
            .collect();
        let m = max_abs(&g);
        let (mut left, mut right) = (vec![0.0; n + 1], g.clone());
        de_casteljau_half(&mut right, &mut left);
        let nf = (n + 1) as f64;
        // The parent exact (E = 0): the bound is the split's own error.
        let e = (nf * f64::EPSILON * m + nf * TINY) * SAFETY;
        let (l, r) = exact_halves(&g);
        for (half, exact) in [(&left, &l), (&right, &r)] {
            let bound = rational_of_f64(e).expect("finite");
            for (x, y) in half.iter().zip(exact) {
                let err = (rational_of_f64(*x).expect("finite") - y.clone()).abs();
                assert!(err <= bound, "{err} > {bound}");
            }
            // Renormalisation scales values and bound by one power of two, at least 1, and
            // leaves the largest value below 1.
            let mut scaled = half.clone();
            let (es, ms) = renormalise(&mut scaled, e);
            assert_eq!(ms, max_abs(&scaled));
            let Some(i) = half.iter().position(|&x| x != 0.0) else {
                continue;
            };
            let f = scaled[i] / half[i];
            assert!(f >= 1.0 && f.log2().fract() == 0.0, "{f}");
            assert_eq!(es, e * f);
            assert!(scaled.iter().zip(half.iter()).all(|(s, h)| *s == h * f));
            assert!(max_abs(&scaled) < 1.0);
        }
    }
}

#[test]
fn max_variations_is_the_maximum_over_all_sign_choices() {
    let mut rng = Rng::new(3);
    let signs = [Sign::Negative, Sign::Zero, Sign::Positive];
    for _ in 0..500 {
        let len = rng.below(7) as usize;
        let mid: Vec<f64> = (0..len)
            .map(|_| [-2.0, -0.5, 0.0, 0.5, 2.0][rng.below(5) as usize])
            .collect();
        let lo = signs[rng.below(3) as usize];
        let hi = signs[rng.below(3) as usize];
        let e = 1.0;
        // Brute force over every choice for the uncertain entries (|x| <= 1).
        let uncertain: Vec<usize> = (0..len).filter(|&i| mid[i].abs() <= e).collect();
        let mut best = 0;
        for choice in 0..3usize.pow(uncertain.len() as u32) {
            let mut seq = vec![lo];
            let mut ch = choice;
            for (i, &x) in mid.iter().enumerate() {
                if uncertain.contains(&i) {
                    seq.push(signs[ch % 3]);
                    ch /= 3;
                } else {
                    seq.push(sign_f64(x));
                }
            }
            seq.push(hi);
            best = best.max(isolate::count_variations(seq));
        }
        assert_eq!(
            max_variations(lo, &mid, e, hi),
            best,
            "{lo:?} {mid:?} {hi:?}"
        );
    }
}

#[test]
fn pow2f_is_exact() {
    for k in -1074i64..=1023 {
        let x = pow2f(k);
        let r = rational_of_f64(x).expect("finite");
        let expected = if k >= 0 {
            pow2(k as u64)
        } else {
            Rational::ONE / pow2((-k) as u64)
        };
        assert_eq!(r, expected, "2^{k}");
    }
    assert_eq!(pow2f(-1075), 0.0);
    assert_eq!(pow2f(1024), f64::INFINITY);
}

#[test]
fn dyadic_sign_matches_rational_evaluation() {
    let p = bigs(&[-3, 7, 0, -11, 5]);
    for k in 0..12u64 {
        for m in 0..(1i64 << k.min(6)) {
            let x = dyadic(&BigInt::from(2 * m + 1), k + 1);
            assert_eq!(
                sign_at_dyadic(&p, &BigInt::from(2 * m + 1), k + 1),
                sign_at_rational(&p, &x)
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Random integer polynomials through the public isolator (filtered) against Sturm, and
    /// unit problem by unit problem against the exact subdivision.
    #[test]
    fn random_integer_polynomials(
        coeffs in proptest::collection::vec(-1000i64..=1000, 2..26),
        shift in 0u32..80,
    ) {
        let mut c: Vec<BigInt> = coeffs.iter().map(|&x| BigInt::from(x) << shift).collect();
        if c.iter().skip(1).all(Zero::is_zero) {
            c[1] = BigInt::one();
        }
        let p = upoly_of(&c);
        let sturm = isolate_real_roots_sturm(&p);
        let found = integer_real_roots(&c).expect("non-zero");
        prop_assert_eq!(found.len(), sturm.len());
        let sqf = p.square_free_part();
        for r in &found {
            if r.is_exact() {
                prop_assert!(p.eval(&r.lo).is_zero());
            } else {
                let (a, b) = (sqf.sign_at(&r.lo), sqf.sign_at(&r.hi));
                prop_assert!(a != Sign::Zero && b != Sign::Zero && a != b);
            }
        }
        for w in found.windows(2) {
            prop_assert!(w[0].hi <= w[1].lo);
        }
        compare(&c, false);
    }
}

/// The exact sign at a dyadic point on limbs equals the `BigInt` Horner's, on random
/// polynomials (coefficients up to 300 bits, both signs), at roots (`(2^k x - m) g`) and at
/// every odd numerator of small depths.
#[test]
fn sign_at_dyadic_on_limbs_agrees_with_bigint() {
    let mut rng = exactcheck_core::Rng::new(3141);
    for round in 0..300 {
        let n = 1 + rng.below(30) as usize;
        let mut p: Vec<BigInt> = (0..=n)
            .map(|_| BigInt::from(rng.next_u64() as i64) << (rng.below(240) as u32))
            .collect();
        let k = 1 + rng.below(63);
        let m = (rng.next_u64() >> (64 - k)) | 1;
        if round % 3 == 0 {
            // A root at m / 2^k: p (2^k x - m).
            let mut q = vec![BigInt::zero(); n + 2];
            for (i, c) in p.iter().enumerate() {
                q[i + 1] += c << k;
                q[i] -= c * BigInt::from(m);
            }
            p = q;
        }
        let limbs = Limbs::from_bigints(&p);
        let expected = sign_at_dyadic(&p, &BigInt::from(m), k);
        let got = match limbs.sign_at_dyadic(m, k) {
            -1 => Sign::Negative,
            0 => Sign::Zero,
            _ => Sign::Positive,
        };
        assert_eq!(got, expected, "round {round}: degree {n}, {m} / 2^{k}");
        if round % 3 == 0 {
            assert_eq!(got, Sign::Zero);
        }
    }
}

/// Both subdivisions list a unit problem's roots in increasing order, split points that are
/// roots included (so `isolate_square_free` needs no sort): dyadic roots at several depths,
/// Wilkinson's products, a random polynomial, a close pair.
#[test]
fn unit_roots_come_out_in_increasing_order() {
    let cases = [
        product(
            &small(&[(1, 2), (1, 4), (3, 4), (3, 8), (5, 16), (1, 3), (2, 3)]),
            &[1],
        ),
        bench_instances::wilkinson(20),
        bench_instances::wilkinson(24),
        bench_instances::random(30),
        bench_instances::mignotte(20),
    ];
    for c in &cases {
        for p in unit_problems(c) {
            let (filtered, _) = filtered_unit_roots(&p, true);
            for (name, found) in [
                ("filtered", filtered),
                ("exact", exact_unit_roots(&p, true)),
            ] {
                let e: Vec<(Rational, Rational)> = found.iter().map(ends).collect();
                assert!(
                    e.windows(2).all(|w| w[0].1 <= w[1].0 && w[0] < w[1]),
                    "{name}: {e:?}"
                );
            }
        }
    }
}

/// Whether the root's `f64` shift of `p` is accepted (not replaced by the exact shift).
fn f64_shift_accepted(p: &[BigInt]) -> bool {
    let n = p.len() - 1;
    let mut g = Vec::new();
    let (root, _) = root_f64_coefficients(p, &binomials_f64(n), &mut g);
    root.shifted.is_none()
}

#[test]
fn cancellation_is_predicted_where_the_f64_shift_is_rejected() {
    // The benchmark instances: Wilkinson's two positive unit problems cancel, every unit
    // problem of the random and Mignotte polynomials is accepted.
    for (family, degree, _) in bench_instances::COMPARISON {
        let problems = unit_problems(&family.polynomial(degree));
        for (i, p) in problems.iter().enumerate() {
            if variations(p) == 0 {
                continue;
            }
            let wilkinson = family == bench_instances::Family::Wilkinson;
            assert_eq!(
                shift_predicted_to_cancel(p),
                wilkinson && i < 2,
                "{family:?} {degree}, unit problem {i}"
            );
            assert_eq!(f64_shift_accepted(p), !(wilkinson && i < 2));
        }
    }
    // Products of linear factors with roots in (0, 1): n sign variations, and from about
    // degree 30 a cancellation the prediction sees (`sum |p_m| / |p_n|` is the product of the
    // `1 + r_j`, about `2^(0.56 n)`; the threshold is `2^15 / (3n + 8)`).
    let mut rng = Rng::new(33);
    for n in [31usize, 45, 60] {
        let roots: Vec<(i64, i64)> = (0..n).map(|_| (1 + rng.below(59) as i64, 60)).collect();
        let p = product(&small(&roots), &[1]);
        assert!(shift_predicted_to_cancel(&p), "degree {n}");
        assert!(!f64_shift_accepted(&p), "degree {n}");
    }
    // Random word coefficients (about n / 2 sign variations) are never predicted to cancel.
    for n in [2usize, 5, 20, 50, 100, 200, 400] {
        let p: Vec<BigInt> = (0..=n)
            .map(|_| BigInt::from(rng.next_u64() as i64))
            .collect();
        assert!(!shift_predicted_to_cancel(&p), "degree {n}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]
    /// The node indices' words against `BigInt`: a path of left and right children from the
    /// root down to depth 201 (one past the depth cap) gives `c` with `2 c` and `2 c + 1`.
    #[test]
    fn node_indices_follow_the_bigint_path(bits in proptest::collection::vec(any::<bool>(), 0..=201)) {
        let (mut c, mut big) = (NodeIndex::ZERO, BigInt::zero());
        for right in bits {
            prop_assert_eq!(c.is_odd(), big.bit(0));
            prop_assert_eq!(c.word(), big.to_u64());
            prop_assert_eq!(c.to_bigint(), big.clone());
            c = c.doubled();
            big <<= 1u32;
            if right {
                c = c.odd();
                big += 1u32;
            }
        }
        prop_assert_eq!(c.to_bigint(), big.clone());
        prop_assert_eq!(c.word(), big.to_u64());
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]
    /// With every entry certain, the branch-free count equals the general one.
    #[test]
    fn certain_variations_match_the_general_count(
        mid in proptest::collection::vec((0.5f64..4.0, any::<bool>()), 0..40),
        lo in 0usize..3,
        hi in 0usize..3,
    ) {
        let signs = [Sign::Negative, Sign::Zero, Sign::Positive];
        let mid: Vec<f64> = mid.into_iter().map(|(x, neg)| if neg { -x } else { x }).collect();
        let (lo, hi) = (signs[lo], signs[hi]);
        prop_assert_eq!(
            max_variations(lo, &mid, 0.25, hi),
            max_variations_uncertain(lo, &mid, 0.25, hi)
        );
        prop_assert_eq!(certain_variations(lo, &mid, hi), max_variations_uncertain(lo, &mid, 0.25, hi));
    }
}
