//! Exact real root isolation: the Descartes isolator and its refinement against
//! the Sturm isolator (`isolate_real_roots_sturm`, the reference), on random integer polynomials with
//! repeated and rational roots, on the benchmark families at small degrees and on known roots; the
//! check values (root counts) of the comparison sizes (the `real-roots` benchmark's command is
//! tested in `bench/`).
//! No test measures time.

use exactcheck_core::Ring;
use exactcheck_exact::univariate::bench_instances::{self, Family};
use exactcheck_exact::univariate::{
    integer_real_roots, integer_real_roots_to, isolate_real_roots_sturm, RootInterval, UPoly,
};
use exactcheck_exact::Rational;
use num_bigint::BigInt;
use proptest::prelude::*;

fn rat(n: i64, d: i64) -> Rational {
    Rational::new(n, d).expect("non-zero denominator")
}

fn upoly(c: &[BigInt]) -> UPoly {
    UPoly::from_coeffs(c.iter().cloned().map(Rational::from).collect())
}

/// Checks `found` against the Sturm isolation of `p`: the same number of roots, the i-th Sturm
/// interval meeting the i-th found interval (closed), the found intervals sorted and disjoint,
/// each exact one a root, each open one with non-root ends of opposite signs of the square-free
/// part and exactly one root by Sturm's count. (The found intervals need not be nested in the
/// Sturm ones: a close pair is split at a point that is not dyadic of low order, so one Sturm
/// interval can meet two found intervals; matching by order is the right test.)
fn check_against_sturm(p: &UPoly, found: &[RootInterval]) {
    let sturm = isolate_real_roots_sturm(p);
    assert_eq!(
        found.len(),
        sturm.len(),
        "root count of {p}: {found:?} vs {sturm:?}"
    );
    for (s, f) in sturm.iter().zip(found) {
        assert!(
            s.lo.clone().max(f.lo.clone()) <= s.hi.clone().min(f.hi.clone()),
            "{s:?} and {f:?} of {p} do not meet"
        );
        if !f.is_exact() {
            assert_eq!(p.count_roots(&f.lo, &f.hi), 1, "{f:?} of {p}");
        }
    }
    for pair in found.windows(2) {
        assert!(
            pair[0].hi <= pair[1].lo,
            "not sorted/disjoint: {pair:?} for {p}"
        );
    }
    let sqf = p.square_free_part();
    for f in found {
        if f.is_exact() {
            assert!(p.eval(&f.lo).is_zero(), "{f:?} is not a root of {p}");
        } else {
            assert!(f.lo < f.hi);
            let (a, b) = (sqf.sign_at(&f.lo), sqf.sign_at(&f.hi));
            assert!(
                a != exactcheck_core::Sign::Zero && b != exactcheck_core::Sign::Zero && a != b,
                "{f:?} of {p}: end signs {a:?} {b:?}"
            );
        }
    }
}

/// Checks the refined intervals: as [`check_against_sturm`], each of width at most `w`, each
/// inside the matching unrefined interval.
fn check_refined(p: &UPoly, w: &Rational) {
    let coarse = p.real_roots_descartes();
    let fine = p.isolate_real_roots_to(w);
    check_against_sturm(p, &fine);
    assert!(
        fine.windows(2).all(|pair| pair[0].hi < pair[1].lo),
        "closed intervals meet: {fine:?}"
    );
    assert_eq!(coarse.len(), fine.len());
    for (c, f) in coarse.iter().zip(&fine) {
        assert!(f.width() <= *w, "{f:?} wider than {w}");
        assert!(c.lo <= f.lo && f.hi <= c.hi, "{f:?} not inside {c:?}");
    }
}

fn bigs(c: &[i64]) -> Vec<BigInt> {
    c.iter().map(|&x| BigInt::from(x)).collect()
}

// ------------------------------------------------------------------------------ known answers

#[test]
fn comparison_sizes_have_the_pinned_root_counts() {
    // The check values of the comparison: python-flint and SymPy find the same counts.
    for (family, degree, count) in bench_instances::COMPARISON {
        let roots = bench_instances::solve(&family.polynomial(degree));
        assert_eq!(roots.len(), count, "{family:?} {degree}");
        let w = bench_instances::target_width();
        assert!(roots.iter().all(|r| r.width() <= w));
        assert!(roots.windows(2).all(|p| p[0].hi < p[1].lo));
    }
}

#[test]
fn wilkinson_roots_lie_in_their_intervals() {
    for n in [20usize, 40] {
        let roots = bench_instances::solve(&bench_instances::wilkinson(n));
        assert_eq!(roots.len(), n);
        for (j, r) in roots.iter().enumerate() {
            let x = rat(j as i64 + 1, n as i64);
            assert!(
                r.lo <= x && x <= r.hi,
                "root {x} of wilkinson({n}) not in {r:?}"
            );
            assert!(r.is_exact() || (r.lo < x && x < r.hi));
        }
    }
}

#[test]
fn mignotte_pair_is_separated() {
    for n in [20usize, 40, 60] {
        let roots = bench_instances::solve(&bench_instances::mignotte(n));
        let near: Vec<&RootInterval> = roots
            .iter()
            .filter(|r| r.lo > rat(9, 100) && r.hi < rat(11, 100))
            .collect();
        assert_eq!(near.len(), 2, "mignotte({n}): {roots:?}");
        assert!(near[0].hi < near[1].lo);
        // The pair straddles 1/10 (the polynomial is x^n - 2 (10x - 1)^2, positive at 1/10).
        assert!(near[0].lo < rat(1, 10) && rat(1, 10) < near[1].hi);
        let p = upoly(&bench_instances::mignotte(n));
        check_against_sturm(&p, &roots);
    }
}

#[test]
fn random_family_reproduces_splitmix64() {
    // SplitMix64 from state 1: the first output is 0x910a2dec89025cc1 (as i64, negative).
    let c = bench_instances::random(1);
    assert_eq!(c[0], BigInt::from(0x910a_2dec_8902_5cc1u64 as i64));
    assert_eq!(c.len(), 2);
    assert_eq!(bench_instances::wilkinson(2), bigs(&[2, -6, 4]));
    assert_eq!(bench_instances::mignotte(3), bigs(&[-2, 40, -200, 1]));
}

#[test]
fn families_at_small_degrees_agree_with_sturm() {
    let w = bench_instances::target_width();
    for d in 1..=12 {
        for family in [Family::Wilkinson, Family::Random, Family::Mignotte] {
            let c = family.polynomial(d);
            let p = upoly(&c);
            let coarse = integer_real_roots(&c).expect("non-zero");
            check_against_sturm(&p, &coarse);
            let fine = integer_real_roots_to(&c, &w).expect("non-zero");
            check_against_sturm(&p, &fine);
            assert!(fine.iter().all(|r| r.width() <= w));
            assert!(fine.windows(2).all(|pair| pair[0].hi < pair[1].lo));
        }
    }
    for d in [20usize, 30] {
        check_refined(&upoly(&bench_instances::random(d)), &w);
        check_refined(&upoly(&bench_instances::mignotte(d)), &w);
    }
}

#[test]
fn special_points_and_widths() {
    // Roots at 0, 1, -1, dyadic and reciprocal-of-dyadic points, a double root, huge roots.
    let cases: Vec<UPoly> = vec![
        UPoly::from_roots(&[rat(0, 1), rat(1, 1), rat(-1, 1), rat(1, 2), rat(3, 1)]),
        UPoly::from_roots(&[rat(1, 3), rat(1, 3), rat(-2, 7), rat(4, 1), rat(-1, 4)]),
        UPoly::from_i64_coeffs(&[-2, 0, 1]),
        UPoly::from_i64_coeffs(&[1, 0, 1]),
        UPoly::from_i64_coeffs(&[-(1 << 62), 1]),
        UPoly::from_i64_coeffs(&[1, -(1 << 62)]),
        UPoly::from_i64_coeffs(&[-1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1 << 40]),
        UPoly::from_i64_coeffs(&[3, -1]),
    ];
    for p in &cases {
        check_against_sturm(p, &p.real_roots_descartes());
        for w in [
            rat(1, 1000),
            rat(3, 7),
            rat(5, 1),
            bench_instances::target_width(),
        ] {
            check_refined(p, &w);
        }
    }
    assert!(UPoly::from_i64_coeffs(&[5])
        .real_roots_descartes()
        .is_empty());
    assert!(integer_real_roots(&bigs(&[0, 0])).is_err());
}

// ------------------------------------------------------------------------------ properties

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 64,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    /// Products of random linear factors `a x - b` (repeated ones included) and a random
    /// integer polynomial, degree up to 30.
    #[test]
    fn descartes_agrees_with_sturm(
        factors in prop::collection::vec((1i64..12, -30i64..30, 1u32..3), 0..8),
        rest in prop::collection::vec(-1000i64..1000, 1..16),
        k in 10i64..80,
    ) {
        let mut p = UPoly::from_i64_coeffs(&rest);
        if p.is_zero() {
            p = UPoly::one();
        }
        for (a, b, m) in factors {
            for _ in 0..m {
                p *= UPoly::from_i64_coeffs(&[-b, a]);
            }
        }
        if p.degree() > 30 {
            return Ok(());
        }
        check_against_sturm(&p, &p.real_roots_descartes());
        let w = Rational::from(BigInt::from(1)) / Rational::from(BigInt::from(1) << k as u32);
        check_refined(&p, &w);
    }
}

// ------------------------------------------------------------------------------ the command
