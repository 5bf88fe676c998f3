//! Property tests of `UPoly` and exact real root isolation on polynomials whose roots are known:
//! products of `(x - r_i)^(m_i)` with random rational `r_i` (repeats included), irreducible
//! quadratics `(x - a)^2 + c` with `c > 0` (no real roots), optionally `(x^2 - 2)^m` (irrational
//! roots `+-sqrt 2`), times a random non-zero rational. Checked: root counts, isolating intervals
//! (each holds exactly its expected root, rational roots exactly), refinement, multiplicities,
//! the non-negative set and the sign chart against exact evaluation, and the algebra (division
//! identity, gcds, square-free parts and decompositions).

use exactcheck_core::{Ring, Sign};
use exactcheck_exact::univariate::{RootInterval, UPoly};
use exactcheck_exact::Rational;
use proptest::prelude::*;
use std::cmp::Ordering;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).unwrap()
}

fn two() -> Rational {
    Rational::from_integer(2)
}

/// A real root the test knows exactly.
#[derive(Clone, Debug)]
enum Known {
    Rat(Rational),
    /// `+sqrt 2` (false) or `-sqrt 2` (true).
    Sqrt2(bool),
}

/// `x` compared with `sqrt 2`, exactly.
fn cmp_sqrt2(x: &Rational) -> Ordering {
    if x.signum() != Sign::Positive {
        Ordering::Less
    } else {
        x.square().cmp(&two())
    }
}

/// `x` compared with the known root `k`.
fn cmp_known(x: &Rational, k: &Known) -> Ordering {
    match k {
        Known::Rat(r) => x.cmp(r),
        Known::Sqrt2(false) => cmp_sqrt2(x),
        Known::Sqrt2(true) => cmp_sqrt2(&x.neg_ref()).reverse(),
    }
}

/// Whether the isolating interval holds the known root (exactly, for rational roots).
fn holds(ri: &RootInterval, k: &Known) -> bool {
    match k {
        Known::Rat(r) => ri.exact_value() == Some(r),
        Known::Sqrt2(_) => {
            !ri.is_exact()
                && cmp_known(&ri.lo, k) == Ordering::Less
                && cmp_known(&ri.hi, k) == Ordering::Greater
        }
    }
}

/// The test case: the polynomial with its known distinct real roots (increasing, with
/// multiplicities) and its expected square-free part.
#[derive(Clone, Debug)]
struct Case {
    poly: UPoly,
    roots: Vec<(Known, u32)>,
    square_free: UPoly,
}

fn small_rational() -> impl Strategy<Value = Rational> {
    (-12i64..=12, 1i64..=5).prop_map(|(n, d)| q(n, d))
}

fn arb_point() -> impl Strategy<Value = Rational> {
    (-60i64..=60, 1i64..=7).prop_map(|(n, d)| q(n, d))
}

fn arb_case() -> impl Strategy<Value = Case> {
    (
        prop::collection::vec((small_rational(), 1u32..=3), 0..=4),
        prop::collection::vec((-3i64..=3, 1i64..=9, 1i64..=4), 0..=2),
        0u32..=2,
        (prop_oneof![-9i64..=-1, 1i64..=9], 1i64..=4),
    )
        .prop_map(|(lin, quads, sqrt2_mult, (sn, sd))| {
            let mut poly = UPoly::constant(q(sn, sd));
            let mut square_free = UPoly::one();
            // Rational roots, merged by value.
            let mut rats: Vec<(Rational, u32)> = Vec::new();
            for (r, m) in lin {
                poly *= Ring::pow(&UPoly::from_roots(std::slice::from_ref(&r)), m);
                match rats.iter_mut().find(|(s, _)| *s == r) {
                    Some((_, k)) => *k += m,
                    None => {
                        square_free *= UPoly::from_roots(std::slice::from_ref(&r));
                        rats.push((r, m));
                    }
                }
            }
            // (x - a)^2 + c = x^2 - 2a x + a^2 + c, c > 0.
            let mut seen: Vec<UPoly> = Vec::new();
            for (a, cn, cd) in quads {
                let a = Rational::from_integer(a);
                let f = UPoly::from_coeffs(vec![a.square() + q(cn, cd), -(&a + &a), Rational::ONE]);
                poly *= &f;
                if !seen.contains(&f) {
                    square_free *= &f;
                    seen.push(f);
                }
            }
            let mut roots: Vec<(Known, u32)> =
                rats.into_iter().map(|(r, m)| (Known::Rat(r), m)).collect();
            if sqrt2_mult > 0 {
                let f = UPoly::from_i64_coeffs(&[-2, 0, 1]);
                poly *= Ring::pow(&f, sqrt2_mult);
                square_free *= f;
                roots.push((Known::Sqrt2(false), sqrt2_mult));
                roots.push((Known::Sqrt2(true), sqrt2_mult));
            }
            roots.sort_by(|(a, _), (b, _)| match (a, b) {
                (Known::Rat(x), _) => cmp_known(x, b),
                (_, Known::Rat(y)) => cmp_known(y, a).reverse(),
                (Known::Sqrt2(x), Known::Sqrt2(y)) => y.cmp(x),
            });
            Case {
                poly,
                roots,
                square_free,
            }
        })
}

fn arb_poly() -> impl Strategy<Value = UPoly> {
    prop::collection::vec((-9i64..=9, 1i64..=4), 0..=7)
        .prop_map(|c| UPoly::from_coeffs(c.into_iter().map(|(n, d)| q(n, d)).collect()))
}

/// A rational strictly inside every gap of the sign chart, in order (one per gap).
fn gap_points(p: &UPoly, intervals: &[RootInterval]) -> Vec<Rational> {
    let w = q(1, 1 << 40);
    let refined: Vec<RootInterval> = intervals.iter().map(|ri| p.refine(ri, &w)).collect();
    let mut pts = Vec::new();
    match refined.first() {
        None => pts.push(Rational::ZERO),
        Some(first) => pts.push(&first.lo - Rational::ONE),
    }
    for pair in refined.windows(2) {
        assert!(
            pair[0].hi < pair[1].lo,
            "roots closer than the test assumes"
        );
        pts.push((&pair[0].hi + &pair[1].lo) * q(1, 2));
    }
    if let Some(last) = refined.last() {
        pts.push(&last.hi + Rational::ONE);
    }
    pts
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn roots_are_counted_and_isolated(case in arb_case()) {
        let p = &case.poly;
        prop_assert_eq!(p.count_real_roots(), case.roots.len());
        let isolated = p.isolate_roots();
        prop_assert_eq!(isolated.len(), case.roots.len());
        for (ri, (k, _)) in isolated.iter().zip(&case.roots) {
            prop_assert!(ri.lo <= ri.hi);
            prop_assert!(holds(ri, k), "{:?} does not hold {:?} in {}", ri, k, p);
            if !ri.is_exact() {
                prop_assert!(p.sign_at(&ri.lo) != Sign::Zero && p.sign_at(&ri.hi) != Sign::Zero);
            }
        }
        // Sorted and disjoint (open intervals may share an end; an exact root may be the end of
        // its neighbour's open interval).
        for pair in isolated.windows(2) {
            prop_assert!(pair[0].hi <= pair[1].lo);
            prop_assert!(pair[0].lo < pair[1].hi);
        }
        // Multiplicities.
        let roots = p.roots();
        prop_assert_eq!(roots.len(), case.roots.len());
        for (r, (_, m)) in roots.iter().zip(&case.roots) {
            prop_assert_eq!(r.multiplicity, *m);
            prop_assert_eq!(p.multiplicity(&r.interval), *m);
        }
    }

    #[test]
    fn refinement_keeps_the_root_and_meets_the_width(case in arb_case(), k in 1u32..80, odd in 1i64..=9) {
        let width = q(odd, 1) * Rational::ONE.checked_div(&Rational::from_integer(2).pow(k)).unwrap();
        let p = &case.poly;
        for (ri, (known, _)) in p.isolate_roots().iter().zip(&case.roots) {
            let r = p.refine(ri, &width);
            prop_assert!(r.width() <= width || r.is_exact());
            prop_assert!(r.lo >= ri.lo && r.hi <= ri.hi);
            prop_assert!(holds(&r, known));
            prop_assert_eq!(p.refine(&r, &width), r.clone());
        }
    }

    #[test]
    fn sturm_counts_on_half_open_intervals(case in arb_case(), a in arb_point(), b in arb_point()) {
        let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
        let expected = case
            .roots
            .iter()
            .filter(|(k, _)| cmp_known(&lo, k) == Ordering::Less && cmp_known(&hi, k) != Ordering::Less)
            .count();
        prop_assert_eq!(case.poly.count_roots(&lo, &hi), expected);
        // Endpoints at rational roots: (r, r'] counts r' but not r.
        let rats: Vec<&Rational> = case
            .roots
            .iter()
            .filter_map(|(k, _)| match k { Known::Rat(r) => Some(r), _ => None })
            .collect();
        if rats.len() >= 2 {
            let (r0, r1) = (rats[0], rats[rats.len() - 1]);
            let inside = case
                .roots
                .iter()
                .filter(|(k, _)| cmp_known(r0, k) == Ordering::Less && cmp_known(r1, k) != Ordering::Less)
                .count();
            prop_assert_eq!(case.poly.count_roots(r0, r1), inside);
        }
    }

    #[test]
    fn nonnegative_set_agrees_with_evaluation(
        case in arb_case(),
        points in prop::collection::vec(arb_point(), 1..12),
    ) {
        let p = &case.poly;
        let set = p.nonnegative_set();
        let mut pts = points;
        for (k, _) in &case.roots {
            if let Known::Rat(r) = k {
                pts.push(r.clone());
                pts.push(r + q(1, 1000));
                pts.push(r - q(1, 1000));
            }
        }
        pts.extend([q(141, 100), q(142, 100), q(-141, 100), q(-142, 100)]);
        for x in &pts {
            let in_set = set.iter().filter(|iv| iv.contains(p, x)).count();
            prop_assert!(in_set <= 1, "intervals overlap at {}", x);
            prop_assert_eq!(in_set == 1, p.sign_at(x) != Sign::Negative, "at {} for {}", x, p);
        }
        // The sign chart against evaluation strictly inside every gap; the summaries against it.
        let chart = p.sign_chart();
        let intervals: Vec<RootInterval> = chart.roots.iter().map(|r| r.interval.clone()).collect();
        let samples = gap_points(p, &intervals);
        prop_assert_eq!(samples.len(), chart.gaps.len());
        for (x, s) in samples.iter().zip(&chart.gaps) {
            prop_assert_eq!(p.sign_at(x), *s);
        }
        let positive = chart.gaps.contains(&Sign::Positive);
        prop_assert_eq!(p.positive_somewhere(), positive);
        prop_assert_eq!(p.nonnegative_somewhere(), positive || !chart.roots.is_empty());
        // Touching points: exactly the roots of even multiplicity where p < 0 on both sides.
        let touching = p.touching_points();
        for t in &touching {
            prop_assert!(t.multiplicity % 2 == 0);
            prop_assert!(set.iter().any(|iv| iv.is_point() && iv.lo == exactcheck_exact::univariate::Bound::Root(t.interval.clone())));
        }
        prop_assert_eq!(touching.len(), set.iter().filter(|iv| iv.is_point()).count());
    }

    #[test]
    fn square_free_parts_and_decompositions(case in arb_case()) {
        let p = &case.poly;
        let sqf = p.square_free_part();
        prop_assert_eq!(&sqf, &case.square_free);
        prop_assert!(sqf.gcd(&sqf.derivative()).is_constant());
        prop_assert!(p.is_divisible_by(&sqf));
        let dec = p.square_free_decomposition();
        let mut rebuilt = UPoly::constant(p.leading_coefficient());
        for (f, i) in &dec {
            prop_assert!(!f.is_constant());
            prop_assert!(f.leading_coefficient().is_one());
            prop_assert!(f.gcd(&f.derivative()).is_constant());
            rebuilt *= Ring::pow(f, *i);
        }
        prop_assert_eq!(&rebuilt, p);
    }

    #[test]
    fn division_identity(a in arb_poly(), b in arb_poly()) {
        prop_assume!(!b.is_zero());
        let (quo, r) = a.div_rem(&b);
        prop_assert_eq!(&(&quo * &b) + &r, a.clone());
        prop_assert!(r.is_zero() || r.degree() < b.degree());
    }

    #[test]
    fn gcd_divides_both(a in arb_poly(), b in arb_poly(), c in arb_poly()) {
        let (ac, bc) = (&a * &c, &b * &c);
        let g = ac.gcd(&bc);
        prop_assert!(ac.is_divisible_by(&g));
        prop_assert!(bc.is_divisible_by(&g));
        if g.is_zero() {
            prop_assert!(ac.is_zero() && bc.is_zero());
        } else {
            prop_assert!(g.leading_coefficient().is_one());
            prop_assert!(g.is_divisible_by(&c.monic()));
            // The cofactors are coprime.
            let (ca, cb) = (ac.div_rem(&g).0, bc.div_rem(&g).0);
            prop_assert!(ca.gcd(&cb).is_constant() || ca.is_zero() || cb.is_zero());
        }
    }

    #[test]
    fn arithmetic_agrees_with_evaluation(a in arb_poly(), b in arb_poly(), x in arb_point()) {
        prop_assert_eq!((&a + &b).eval(&x), a.eval(&x) + b.eval(&x));
        prop_assert_eq!((&a - &b).eval(&x), a.eval(&x) - b.eval(&x));
        prop_assert_eq!((&a * &b).eval(&x), a.eval(&x) * b.eval(&x));
        prop_assert_eq!(a.compose(&b).eval(&x), a.eval(&b.eval(&x)));
        prop_assert_eq!(&a.primitive_part().scale(&a.content()), &a);
        let printed = a.display("t").to_string();
        let mut vars = exactcheck_exact::poly::Vars::new();
        let parsed: exactcheck_exact::poly::Poly<Rational> =
            exactcheck_exact::expr::parse_poly(&printed, &mut vars).unwrap();
        let var = vars.get("t").unwrap_or(0);
        prop_assert_eq!(UPoly::from_poly(&parsed, var).unwrap(), a);
    }
}

// ------------------------------------------------------------------------------ the real-root API

use exactcheck_exact::univariate::{
    isolate_real_roots, isolate_real_roots_in, isolate_real_roots_sturm,
    isolate_real_roots_sturm_in, refine_real_root, sign_at_real_root,
};

/// The fast isolator's answer checked against the Sturm reference for the same polynomial: the
/// same number of roots, the same exact (rational) roots, every other interval isolating with
/// non-root ends at which the square-free part changes sign, and the i-th intervals of both
/// overlapping (they hold the same root).
fn agrees_with_sturm(
    p: &UPoly,
    fast: &[RootInterval],
    sturm: &[RootInterval],
) -> Result<(), String> {
    if fast.len() != sturm.len() {
        return Err(format!(
            "{} roots, Sturm {} for {p}",
            fast.len(),
            sturm.len()
        ));
    }
    let sqf = p.square_free_part();
    for (f, s) in fast.iter().zip(sturm) {
        if f.exact_value() != s.exact_value() {
            return Err(format!("{f:?} vs Sturm {s:?} for {p}"));
        }
        if !f.is_exact() {
            if sqf.sign_at(&f.lo) * sqf.sign_at(&f.hi) != Sign::Negative {
                return Err(format!("{f:?} does not isolate a root of {p}"));
            }
            if f.hi <= s.lo || s.hi <= f.lo {
                return Err(format!("{f:?} and Sturm {s:?} hold different roots of {p}"));
            }
        }
    }
    for pair in fast.windows(2) {
        if pair[0].hi > pair[1].lo || pair[0].lo >= pair[1].hi {
            return Err(format!("not sorted and disjoint: {:?}", pair));
        }
    }
    Ok(())
}

/// Random integer polynomials with repeated factors: products of up to three random factors of
/// degree 1 to 4, each to a power 1 to 3.
fn arb_repeated() -> impl Strategy<Value = UPoly> {
    prop::collection::vec((prop::collection::vec(-20i64..=20, 2..=5), 1u32..=3), 1..=3).prop_map(
        |factors| {
            let mut p = UPoly::one();
            for (c, m) in factors {
                let f = UPoly::from_i64_coeffs(&c);
                if !f.is_zero() {
                    p *= Ring::pow(&f, m);
                }
            }
            p
        },
    )
}

/// Clustered roots: `c + k / 2^e` for a few `k` (rational, denominators up to `2^40`), times
/// `(x - c)^2 - 2^-(2e+1)` (an irrational pair in the same cluster) and a random quadratic.
fn arb_clustered() -> impl Strategy<Value = UPoly> {
    (
        -3i64..=3,
        8u32..=40,
        prop::collection::btree_set(1i64..=6, 1..=3),
        prop::collection::vec(-9i64..=9, 3),
    )
        .prop_map(|(c, e, ks, quad)| {
            let c = Rational::from_integer(c);
            let step = Rational::ONE.checked_div(&two().pow(e)).unwrap();
            let roots: Vec<Rational> = ks
                .into_iter()
                .map(|k| &c + &(Rational::from_integer(k) * &step))
                .collect();
            let pair = UPoly::from_coeffs(vec![
                c.square() - step.square() * q(1, 2),
                -(&c + &c),
                Rational::ONE,
            ]);
            let mut p = UPoly::from_roots(&roots) * pair;
            let quad = UPoly::from_i64_coeffs(&quad);
            if !quad.is_zero() {
                p *= quad;
            }
            p
        })
}

/// The sign of `a + b sqrt 2`, exactly.
fn sign_with_sqrt2(a: &Rational, b: &Rational) -> Sign {
    let (sa, sb) = (a.signum(), b.signum());
    if sa == sb || sb == Sign::Zero {
        return sa;
    }
    if sa == Sign::Zero {
        return sb;
    }
    // Opposite signs: the larger of a^2 and 2 b^2 decides.
    match a.square().cmp(&(two() * b.square())) {
        Ordering::Greater => sa,
        Ordering::Less => sb,
        Ordering::Equal => Sign::Zero,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn fast_isolator_holds_the_known_roots(case in arb_case()) {
        let p = &case.poly;
        let fast = isolate_real_roots(p);
        prop_assert_eq!(fast.len(), case.roots.len());
        for (ri, (k, _)) in fast.iter().zip(&case.roots) {
            prop_assert!(holds(ri, k), "{:?} does not hold {:?} in {}", ri, k, p);
        }
        let sturm = isolate_real_roots_sturm(p);
        prop_assert_eq!(agrees_with_sturm(p, &fast, &sturm), Ok(()));
    }

    #[test]
    fn fast_isolator_agrees_with_sturm_on_repeated_factors(p in arb_repeated()) {
        let fast = isolate_real_roots(&p);
        prop_assert_eq!(agrees_with_sturm(&p, &fast, &isolate_real_roots_sturm(&p)), Ok(()));
    }

    #[test]
    fn fast_isolator_agrees_with_sturm_on_clustered_roots(p in arb_clustered()) {
        let fast = isolate_real_roots(&p);
        prop_assert_eq!(agrees_with_sturm(&p, &fast, &isolate_real_roots_sturm(&p)), Ok(()));
    }

    #[test]
    fn roots_in_an_interval_are_the_global_roots_filtered(
        p in prop_oneof![arb_repeated(), arb_clustered(), arb_case().prop_map(|c| c.poly)],
        a in arb_point(),
        b in arb_point(),
    ) {
        let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
        let inside = isolate_real_roots_in(&p, &lo, &hi);
        let reference = isolate_real_roots_sturm_in(&p, &lo, &hi);
        prop_assert_eq!(agrees_with_sturm(&p, &inside, &reference), Ok(()));
        // The count from the Sturm sequence: roots in (lo, hi], plus lo itself.
        let at_lo = usize::from(!p.is_zero() && p.sign_at(&lo) == Sign::Zero);
        prop_assert_eq!(inside.len(), p.count_roots(&lo, &hi) + at_lo);
        for ri in &inside {
            prop_assert!(lo <= ri.lo && ri.hi <= hi, "{:?} outside [{}, {}]", ri, lo, hi);
        }
        // The unit interval, the Bezier parameter range.
        let unit = isolate_real_roots_in(&p, &Rational::ZERO, &Rational::ONE);
        let unit_ref = isolate_real_roots_sturm_in(&p, &Rational::ZERO, &Rational::ONE);
        prop_assert_eq!(agrees_with_sturm(&p, &unit, &unit_ref), Ok(()));
    }

    #[test]
    fn refinement_and_signs_at_roots(case in arb_case(), other in arb_poly(), k in 1u32..60) {
        let p = &case.poly;
        let width = Rational::ONE.checked_div(&two().pow(k)).unwrap();
        let sqrt2_poly = UPoly::from_i64_coeffs(&[-2, 0, 1]);
        // `other` reduced modulo x^2 - 2 is a + b x: its sign at +-sqrt 2 is decided exactly.
        let reduced = other.rem(&sqrt2_poly);
        let (a, b) = (reduced.coeff(0), reduced.coeff(1));
        for (ri, (known, _)) in isolate_real_roots(p).iter().zip(&case.roots) {
            let r = refine_real_root(p, ri, &width);
            prop_assert!(r.is_exact() || r.width() <= width);
            prop_assert!(holds(&r, known));
            let expected = match known {
                Known::Rat(x) => other.sign_at(x),
                Known::Sqrt2(false) => sign_with_sqrt2(&a, &b),
                Known::Sqrt2(true) => sign_with_sqrt2(&a, &b.neg_ref()),
            };
            prop_assert_eq!(sign_at_real_root(&other, p, ri), expected);
            // A multiple of the root's own factor vanishes there.
            let vanishing = other.clone() * case.square_free.clone();
            prop_assert_eq!(sign_at_real_root(&vanishing, p, ri), Sign::Zero);
        }
    }
}
