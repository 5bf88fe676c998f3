//! The machine-word kernels ([`super::words`]) against the generic kernels on the coefficient
//! type's own arithmetic ([`Poly::mul_reference`], [`Poly::square_reference`]): random sparse
//! and dense polynomials with small, large (beyond 2^63 and 2^127) and rational coefficients, so
//! that every accumulator (`i64`, `i128`, 192 bits) and the fallback to the generic path are
//! taken; and content extraction in powers.

use super::*;
use crate::expr::parse_poly;
use crate::{ModP, Rational};
use num_bigint::BigInt;
use proptest::prelude::*;

type P = Poly<Rational>;

/// A coefficient of one of several size classes.
fn arb_coeff() -> impl Strategy<Value = Rational> {
    prop_oneof![
        (-9i64..=9).prop_map(Rational::from_integer),
        (-9i64..=9).prop_map(|x| Rational::from_integer(x * ((1 << 31) + 11))),
        any::<i64>()
            .prop_filter("not MIN", |&x| x != i64::MIN)
            .prop_map(Rational::from_integer),
        // Beyond 2^63 (inline tier, no i64 word).
        (any::<i64>(), 1u32..60).prop_map(|(x, s)| Rational::from_i128_ratio(
            ((x as i128) << s) | 1,
            1
        )
        .expect("1 is not zero")),
        // Beyond 2^127 (big tier).
        (any::<i64>(), 64u32..100).prop_map(|(x, s)| Rational::from((BigInt::from(x) << s) + 1)),
        // Small rationals (a common denominator in words).
        (-50i64..=50, 1i64..=12).prop_map(|(n, d)| Rational::new(n, d).expect("d >= 1")),
        // A rational with a big denominator.
        (-50i64..=50, 1u32..80).prop_map(|(n, s)| Rational::from(BigInt::from(n))
            / Rational::from((BigInt::from(1) << (s + 63)) + 3)),
    ]
}

/// A polynomial in up to `nvars` variables with exponents up to `emax` and coefficients drawn
/// from `coeff`.
fn arb_poly_with(
    nvars: u32,
    emax: u32,
    terms: usize,
    coeff: impl Strategy<Value = Rational>,
) -> impl Strategy<Value = P> {
    let term = (prop::collection::vec(0..=emax, nvars as usize), coeff);
    prop::collection::vec(term, 1..=terms).prop_map(|ts| {
        P::from_terms(ts.into_iter().map(|(es, c)| {
            let m: Vec<(Var, u32)> = es
                .into_iter()
                .enumerate()
                .map(|(v, e)| (v as Var, e))
                .collect();
            (m, c)
        }))
    })
}

/// The coefficients all of one size class or mixed.
fn arb_poly(nvars: u32, emax: u32, terms: usize) -> impl Strategy<Value = P> {
    arb_poly_with(nvars, emax, terms, arb_coeff())
}

/// Small integer coefficients only (every product in the word kernels).
fn arb_int_poly(nvars: u32, emax: u32, terms: usize, cmax: i64) -> impl Strategy<Value = P> {
    arb_poly_with(
        nvars,
        emax,
        terms,
        (-cmax..=cmax).prop_map(Rational::from_integer),
    )
}

fn check_product(f: &P, g: &P) -> Result<(), TestCaseError> {
    let fast = f * g;
    prop_assert!(fast.is_canonical());
    prop_assert_eq!(&fast, &f.mul_reference(g));
    let sq = f.square();
    prop_assert!(sq.is_canonical());
    prop_assert_eq!(&sq, &f.square_reference());
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn dense_products_agree(f in arb_poly(3, 3, 20), g in arb_poly(3, 3, 20)) {
        check_product(&f, &g)?;
    }

    #[test]
    fn sparse_products_agree(f in arb_poly(6, 40, 15), g in arb_poly(6, 40, 15)) {
        check_product(&f, &g)?;
    }

    #[test]
    fn many_variable_products_agree(f in arb_poly(20, 2, 12), g in arb_poly(20, 2, 12)) {
        // Several key words: the multi-word heap kernels.
        check_product(&f, &g)?;
    }

    #[test]
    fn integer_products_agree(
        f in arb_int_poly(4, 5, 40, 1 << 40),
        g in arb_int_poly(4, 5, 40, 1 << 40),
    ) {
        check_product(&f, &g)?;
    }

    #[test]
    fn powers_agree(f in arb_poly(3, 2, 5), k in 0u32..6) {
        let mut reference = P::one();
        for _ in 0..k {
            reference = reference.mul_reference(&f);
        }
        let p = f.pow(k);
        prop_assert!(p.is_canonical());
        prop_assert_eq!(&p, &reference);
        prop_assert_eq!(&f.try_pow(k).expect("small"), &reference);
    }

    #[test]
    fn modp_products_agree(
        f in arb_int_poly(3, 4, 20, 1 << 62),
        g in arb_int_poly(3, 4, 20, 1 << 62),
    ) {
        let to_modp = |p: &P| p.map_coeffs(|c| ModP::from_rational(c).expect("integer"));
        let (fm, gm) = (to_modp(&f), to_modp(&g));
        prop_assert_eq!(&fm * &gm, fm.mul_reference(&gm));
        prop_assert_eq!(fm.square(), fm.square_reference());
        prop_assert_eq!(&fm * &gm, to_modp(&(&f * &g)));
    }
}

/// A sum of `n` equal largest products lands in one monomial: the accumulator bound picks
/// `i32`, `i64`, `i128` or 192 bits, and the result is the exact sum.
#[test]
fn accumulators_hold_extreme_sums() {
    let x = |i: Var| P::var(i);
    for (c, n) in [
        // n c^2 just below 2^31 (i32 cells) and just above it (i64).
        (18918, 6),
        (-18918, 6),
        (18919, 6),
        (i64::MAX, 10),
        (-i64::MAX, 10),
        (1i64 << 40, 40),
        ((1 << 62) + 1, 200),
    ] {
        let c = Rational::from_integer(c);
        // f = c (1 + y x + y^2 x^2 + ...), g = c (x^(n-1) + y x^(n-2) + ...): every term of
        // f_i g_j with i + j = n - 1 is c^2 x^(n-1) y^i.
        let f = P::sum((0..n).map(|i| x(0).pow(i) * x(1).pow(i)).collect()).scale(&c);
        let g = P::sum((0..n).map(|i| x(0).pow(n - 1 - i)).collect()).scale(&c);
        let fast = &f * &g;
        assert_eq!(fast, f.mul_reference(&g));
        let sq = g.square();
        assert_eq!(sq, g.square_reference());
        assert_eq!(&g * &g, sq);
        // The top coefficient of g^2 is n c^2.
        let top = sq.coefficient(&[(0, 2 * (n - 1))]);
        assert_eq!(top, c.square());
        let mid = sq.coefficient(&[(0, n - 1)]);
        assert_eq!(mid, Rational::from_integer(n as i64) * c.square());
    }
}

/// The fuzz input `(2*5e-070(a+b)*(a-2))^52` (which took 10 s when its rational content rode
/// through the expansion) equals `c^52 ((a+b)(a-2))^52` computed the reference way.
#[test]
fn power_with_a_big_rational_content() {
    let mut vars = Vars::new();
    let p: P = parse_poly("(2*5e-070(a+b)*(a-2))^52", &mut vars).expect("parses");
    let (a, b) = (
        P::var(vars.get("a").unwrap()),
        P::var(vars.get("b").unwrap()),
    );
    let base = (&a + &b) * (&a - P::from_i64(2));
    let mut reference = P::one();
    for _ in 0..52 {
        reference = reference.mul_reference(&base);
    }
    let c = Rational::new(1, 10).unwrap().powi(69).unwrap();
    let reference = reference.scale(&super::kernels::pow_coeff(&c, 52));
    assert!(p.is_canonical());
    assert_eq!(p, reference);
    // And through the Ring API.
    let q = (base.scale(&c)).pow(52);
    assert_eq!(q, reference);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// The field-wise (SWAR) maximum of the packed exponents against a per-variable scan.
    #[test]
    fn max_exps_matches_a_scan(f in arb_poly(12, 300, 10)) {
        let cap = f.shape.words * f.shape.per_word();
        let fast = max_exps(f.shape, &f.exps, f.len(), cap);
        let mut slow = vec![0u64; cap];
        for (m, _) in f.terms() {
            for (v, e) in m.exponents() {
                slow[v as usize] = slow[v as usize].max(u64::from(e));
            }
        }
        // The OR bound: at least the maximum, of the same bit length.
        let or = or_exps(f.shape, &f.exps, f.len(), cap);
        for (o, m) in or.iter().zip(&slow) {
            prop_assert!(o >= m && o.leading_zeros() == m.leading_zeros());
        }
        prop_assert_eq!(fast, slow);
    }

    /// Compact keys at every field width (8, 16, 32 and 64 bits) against keys assembled from
    /// the exponents one variable at a time; and compared as multi-word integers (most
    /// significant word last) they keep the terms' decreasing order.
    #[test]
    fn keys_match_a_scan(
        f in prop_oneof![
            arb_poly(12, 3, 12),
            arb_poly(12, 300, 12),
            arb_poly(12, 70_000, 12),
            arb_poly(5, u32::MAX, 8),
        ],
    ) {
        let cap = f.shape.words * f.shape.per_word();
        let need = max_exps(f.shape, &f.exps, f.len(), cap);
        let (k, place) = key_layout(&need);
        let fast = make_keys(f.shape, &f.exps, f.len(), k, &place);
        let mut slow = vec![0u64; f.len() * k];
        for (i, (m, _)) in f.terms().enumerate() {
            for (v, e) in m.exponents() {
                let (kw, sh) = place[v as usize];
                slow[i * k + kw] |= u64::from(e) << sh;
            }
        }
        prop_assert_eq!(&fast, &slow);
        for pair in fast.chunks_exact(k).collect::<Vec<_>>().windows(2) {
            prop_assert!(pair[0].iter().rev().cmp(pair[1].iter().rev()).is_gt());
        }
    }

    /// Dense products of several slabs (top exponents up to 7) with cancellation.
    #[test]
    fn slab_products_agree(
        f in arb_int_poly(3, 7, 60, 3),
        g in arb_int_poly(3, 7, 60, 3),
    ) {
        check_product(&f, &g)?;
        let h = &f * &(-&g);
        prop_assert_eq!(&h + &(&f * &g), P::zero());
    }
}

/// A dense polynomial with holes: every monomial of the box `0..=emax` in `nvars` variables
/// whose mask bit is set, with coefficients from `coeff` (runs of consecutive exponents of
/// every length, as the direct dense kernel cuts them).
fn arb_holey_dense(
    nvars: u32,
    emax: u32,
    coeff: impl Strategy<Value = i64>,
) -> impl Strategy<Value = P> {
    let cells = (emax as usize + 1).pow(nvars);
    prop::collection::vec((any::<bool>(), any::<bool>(), coeff), cells).prop_map(move |cs| {
        P::from_terms(
            cs.into_iter()
                .enumerate()
                .filter(|(_, (a, b, _))| *a || *b)
                .map(|(mut k, (_, _, c))| {
                    let m: Vec<(Var, u32)> = (0..nvars)
                        .map(|v| {
                            let e = (k % (emax as usize + 1)) as u32;
                            k /= emax as usize + 1;
                            (v as Var, e)
                        })
                        .collect();
                    (m, Rational::from_integer(c))
                }),
        )
    })
}

/// Coefficients of every word accumulator's range: small, near 2^31, and near 2^62.
fn arb_word_int() -> impl Strategy<Value = i64> {
    prop_oneof![
        -9i64..=9,
        (-9i64..=9).prop_map(|x| x * ((1 << 31) + 11)),
        (-(1i64 << 62)..(1i64 << 62)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 120, ..ProptestConfig::default() })]

    /// The direct dense kernel (runs of consecutive cells, the decode table) against the
    /// generic kernels, dense factors with holes in one to four variables, coefficients in
    /// every accumulator's range.
    #[test]
    fn run_products_agree(
        f1 in arb_holey_dense(1, 12, arb_word_int()),
        g1 in arb_holey_dense(1, 9, arb_word_int()),
        f2 in arb_holey_dense(2, 5, arb_word_int()),
        g2 in arb_holey_dense(2, 4, arb_word_int()),
        f3 in arb_holey_dense(3, 3, -5i64..=5),
        g3 in arb_holey_dense(3, 2, arb_word_int()),
        f4 in arb_holey_dense(4, 2, arb_word_int()),
        g4 in arb_holey_dense(4, 2, -1000i64..=1000),
    ) {
        check_product(&f1, &g1)?;
        check_product(&f2, &g2)?;
        check_product(&f3, &g3)?;
        check_product(&f4, &g4)?;
        // Factors in different variables: runs in one factor only.
        check_product(&f1, &f2)?;
        check_product(&g3, &f2)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// The direct dense kernel on monomials of two words (nine variables at eight bits: the
    /// top variable in the second word, the rows' variables in the first), against the generic
    /// kernels.
    #[test]
    fn two_word_dense_products_agree(
        f in arb_holey_dense(9, 1, -9i64..=9),
        g in arb_holey_dense(9, 1, arb_word_int()),
    ) {
        prop_assert_eq!(f.shape.words, 2);
        check_product(&f, &g)?;
    }
}

/// The one-call conversion of word sums back to coefficients agrees with the conversion of
/// each sum, over the denominators 1 and beyond, for `Rational` and `ModP`.
#[test]
fn small_sums_convert_as_word_sums() {
    let wide: Vec<i64> = vec![0, 1, -1, 6, -35, i64::MAX, -i64::MAX, i64::MIN, 1 << 40];
    let narrow: Vec<i32> = vec![0, 1, -1, 6, -35, i32::MAX, i32::MIN];
    let each = |n: &[i64], d: i128| -> Vec<Rational> {
        n.iter()
            .map(|&x| Rational::from_word_sum(WordSum::from_i128(i128::from(x)), d))
            .collect()
    };
    for d in [1i128, 6, 35, (1 << 62) + 9, i128::from(i64::MAX) * 5] {
        assert_eq!(Rational::from_small_sums(&wide, d), each(&wide, d));
        let n32: Vec<i64> = narrow.iter().map(|&x| i64::from(x)).collect();
        assert_eq!(Rational::from_small_sums(&narrow, d), each(&n32, d));
    }
    assert_eq!(
        Rational::from_small_sums(&[12i64], 18),
        vec![Rational::new(2, 3).expect("3 is not zero")]
    );
    let modp: Vec<ModP> = wide
        .iter()
        .map(|&x| ModP::from_word_sum(WordSum::from_i128(i128::from(x)), 1))
        .collect();
    assert_eq!(ModP::from_small_sums(&wide, 1), modp);
    assert_eq!(ModP::from_small_sums(&[-1i64], 1), vec![ModP::from_i64(-1)]);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 100, ..ProptestConfig::default() })]

    /// Keys of two words (the `u128` heap) and of three (the slot heap).
    #[test]
    fn wide_key_products_agree(
        f in arb_poly(30, 6, 8),
        g in arb_poly(30, 6, 8),
        h in arb_poly(45, 6, 8),
    ) {
        check_product(&f, &g)?;
        check_product(&f, &h)?;
    }
}

// ------------------------------------------------------------------------------ powers

/// A base for powers: `terms` terms in up to `nvars` variables.
fn arb_base(nvars: u32, emax: u32, terms: usize) -> impl Strategy<Value = P> {
    arb_poly(nvars, emax, terms)
}

/// A small integer coefficient or a large one of up to 62 bits, either sign.
fn arb_word_coeff() -> impl Strategy<Value = Rational> {
    prop_oneof![
        (-9i64..=9).prop_map(Rational::from_integer),
        (-(1i64 << 62)..=(1i64 << 62)).prop_map(Rational::from_integer),
    ]
}

fn to_modp(p: &P) -> Poly<ModP> {
    p.map_coeffs(|c| ModP::from_rational(c).unwrap_or(ModP::ONE))
}

/// `f^k` by the reference (binary powering on the generic kernels), computed on the integer
/// polynomial `D f` and scaled by `1 / D^k` once, `D` a common multiple of the denominators of
/// `f`'s coefficients: the same kernels as `f.pow_reference(k)`, without reducing a product of
/// big denominators in each of the millions of coefficient products of the last squarings.
fn reference_power(f: &P, k: u32) -> P {
    let mut d = BigInt::from(1);
    for c in f.coefficients() {
        let den = c.denom();
        if &d % &den != BigInt::from(0) {
            d *= den;
        }
    }
    let d = Rational::from(d);
    let dk = (0..k).fold(Rational::from_integer(1), |acc, _| acc * &d);
    f.scale(&d)
        .pow_reference(u64::from(k))
        .scale(&(Rational::from_integer(1) / dk))
}

/// `f^k` every way there is against the reference (binary powering on the generic kernels).
fn check_power(f: &P, k: u32) -> Result<(), TestCaseError> {
    let reference = reference_power(f, k);
    let p = f.pow(k);
    prop_assert!(p.is_canonical());
    prop_assert_eq!(&p, &reference);
    prop_assert_eq!(&f.try_pow(k).expect("small"), &reference);
    if let Some(r) = f.pow_recurrence_forced(u64::from(k)) {
        prop_assert!(r.is_canonical());
        prop_assert_eq!(&r, &reference);
    }
    Ok(())
}

fn check_power_modp(f: &Poly<ModP>, k: u32) -> Result<(), TestCaseError> {
    let reference = f.pow_reference(u64::from(k));
    prop_assert_eq!(&f.pow(k), &reference);
    prop_assert_eq!(&f.try_pow(k).expect("small"), &reference);
    if let Some(r) = f.pow_recurrence_forced(u64::from(k)) {
        prop_assert!(r.is_canonical());
        prop_assert_eq!(&r, &reference);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Sparse bases of 2 to 4 terms in 1 to 6 variables, every coefficient class (big
    /// numerators and denominators, so contents split off too), exponents up to 40.
    #[test]
    fn sparse_powers_agree(nv in 1u32..=6, f in arb_base(6, 3, 4), k in 0u32..=40) {
        // Keep the variables below nv.
        let f = f.map_coeffs(Clone::clone);
        let f = (nv..6).fold(f, |f, v| f.substitute(v, &P::one()));
        check_power(&f, k)?;
    }

    /// Dense small bases (up to 9 terms in 1 to 3 variables), exponents up to 16.
    #[test]
    fn dense_powers_agree(f in arb_poly_with(3, 2, 9, arb_word_coeff()), k in 0u32..=16) {
        check_power(&f, k)?;
    }

    /// Integer bases whose coefficients pass 2^62 (two-limb multipliers in the recurrence,
    /// accumulators over several limbs) and negative leading coefficients.
    #[test]
    fn word_coefficient_powers_agree(f in arb_poly_with(4, 3, 4, arb_word_coeff()), k in 0u32..=25) {
        check_power(&f, k)?;
        check_power(&(-&f), k)?;
    }

    /// Powers modulo 2^61 - 1 against the reference.
    #[test]
    fn modp_powers_agree(f in arb_poly_with(5, 3, 5, arb_word_coeff()), k in 0u32..=40) {
        check_power_modp(&to_modp(&f), k)?;
    }
}

/// The fuzz input `16*(t+ 1*x^2+y+3*x*y_x)^74` (8.4 s by binary powering: its last steps
/// multiply powers of ~10,000 terms with coefficients beyond 63 bits) at exponent 23: the
/// parsed power (content split off, recurrence by the cost model) equals the reference.
#[test]
fn fuzz_power_shape_matches_the_reference() {
    let mut vars = Vars::new();
    let p: P = parse_poly("16*(t+ 1*x^2+y+3*x*y_x)^23", &mut vars).expect("parses");
    let v = |n: &str| P::var(vars.get(n).expect("a variable of the input"));
    let base =
        v("t") + v("x").pow(2) + v("y") + v("x") * v("y_x").scale(&Rational::from_integer(3));
    assert!(base.recurrence_is_preferred(74));
    assert!(base.recurrence_is_preferred(23));
    let reference = base.pow_reference(23).scale(&Rational::from_integer(16));
    assert!(p.is_canonical());
    assert_eq!(p.len(), 2600);
    assert_eq!(p, reference);
    // The leading coefficient 16 * 3^23 and the pure power of t.
    let lead = Rational::from(BigInt::from(3).pow(23u32) * 16);
    assert_eq!(p.coefficient(&[(3, 23), (1, 23)]), lead);
    assert_eq!(p.coefficient(&[(0, 23)]), Rational::from_integer(16));
}

/// The weight must separate the leading term when other terms share its top exponent
/// (`x y`, `y` and `x^3 y^0`: the degree in y ties, x breaks it), and several variables tie.
#[test]
fn recurrence_with_ties_in_the_top_variable() {
    let x = |i: Var| P::var(i);
    let c = |n: i64| P::from_i64(n);
    let bases = [
        x(0) * x(1) + x(1) + x(0).pow(3),
        x(0) * x(1) * x(2) - c(2) * x(1) * x(2) + c(5) * x(0) * x(2) + x(2) - c(7),
        c(-3) * x(0).pow(2) * x(1) + x(0) * x(1) - x(1) + c(4) * x(0).pow(5),
        x(2).pow(3) * x(0) + x(2).pow(3) * x(1) - x(2).pow(3) + x(1).pow(9) * x(0).pow(9),
    ];
    for f in &bases {
        for k in [2u64, 3, 7, 12] {
            let reference = f.pow_reference(k);
            let r = f
                .pow_recurrence_forced(k)
                .expect("integer word coefficients");
            assert_eq!(r, reference, "{k}");
            let m = to_modp(f);
            assert_eq!(
                m.pow_recurrence_forced(k).expect("ModP"),
                m.pow_reference(k),
                "{k}"
            );
        }
    }
}

/// The recurrence stops past its cap on the terms (what `try_pow` turns into the `terms` or
/// `memory` limit), and completes at the cap.
#[test]
fn recurrence_stops_past_the_cap() {
    let x = |i: Var| P::var(i);
    let f = x(0) + x(1) + x(2) + P::one();
    // (1 + x + y + z)^30 has C(33, 3) = 5456 terms.
    let reference = f.pow_reference(30);
    assert_eq!(reference.len(), 5456);
    assert!(matches!(f.pow_by_recurrence(30, |_| 5455), Some(None)));
    let at_cap = f
        .pow_by_recurrence(30, |_| 5456)
        .expect("chosen")
        .expect("within the cap");
    assert_eq!(at_cap, reference);
    // try_pow under the default limits.
    assert_eq!(f.try_pow(30).expect("within the limits"), reference);
}

/// The cost model keeps binary powering where it wins: the square of a many-term sparse base.
#[test]
fn cost_model_keeps_binary_powering_for_wide_squares() {
    let f = P::sum((0..12).map(|i| P::var(i) * P::var(i + 1)).collect());
    assert!(!f.recurrence_is_preferred(2));
    assert!(f.recurrence_is_preferred(30));
}

/// Fateman's dense product at a small size through the direct dense kernel, against the
/// generic kernels, and its check values (`(1 + x + y + z + w)^6`: 210 terms, the product 1820).
#[test]
fn fateman_product_matches_the_reference() {
    let mut vars = Vars::new();
    let f: P = parse_poly("1 + x + y + z + w", &mut vars)
        .expect("parses")
        .pow(6);
    let g = &f + &P::one();
    let h = &f * &g;
    assert_eq!(f.len(), 210);
    assert_eq!(h.len(), 1820);
    assert!(h.is_canonical());
    assert_eq!(h, f.mul_reference(&g));
    assert_eq!(f.square(), f.square_reference());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Products of at most `SMALL_PRODUCT` term products (sorted once, no planned kernel)
    /// against the reference, with the cap exactly at the size and one below it.
    #[test]
    fn small_products_agree(f in arb_poly(4, 3, 6), g in arb_poly(4, 3, 6)) {
        check_product(&f, &g)?;
        let h = f.mul_reference(&g);
        prop_assert_eq!(f.mul_capped(&g, |_| h.len()), Some(h.clone()));
        if !h.is_empty() {
            prop_assert!(f.mul_capped(&g, |_| h.len() - 1).is_none());
        }
    }

    /// Sums of many large summands whose compact keys take two words (twelve variables of
    /// ten bits) merged by the heap on `u128` keys, against the pairwise sums.
    #[test]
    fn two_word_key_sums_agree(
        polys in prop::collection::vec(arb_poly(12, 600, 60), 9..13),
        cancel in any::<bool>(),
    ) {
        let mut polys = polys;
        if cancel {
            // A summand that cancels another one exactly.
            let neg = -polys[0].clone();
            polys.push(neg);
        }
        let total: usize = polys.iter().map(Poly::len).sum();
        prop_assume!(total >= 256);
        let sum = P::sum(polys.clone());
        prop_assert!(sum.is_canonical());
        prop_assert_eq!(sum, P::sum_pairwise(polys));
    }
}

/// The content split: a list of integers with gcd 1 has content 1 (decided in machine words),
/// others keep their content, rationals included.
#[test]
fn content_of_word_lists() {
    let q = |n: i64, d: i64| Rational::new(n, d).expect("d >= 1");
    assert!(super::words::content_of(&[q(1, 1), q(-1, 1)]).is_none());
    assert!(super::words::content_of(&[q(6, 1), q(-10, 1), q(15, 1)]).is_none());
    let (c, prim) = super::words::content_of(&[q(4, 1), q(-6, 1)]).expect("content 2");
    assert_eq!((c, prim), (q(2, 1), vec![q(2, 1), q(-3, 1)]));
    // gcd 1 among the first integers, then a fraction: the content is 1/2, not 1.
    let (c, prim) = super::words::content_of(&[q(1, 1), q(3, 1), q(1, 2)]).expect("content 1/2");
    assert_eq!((c, prim), (q(1, 2), vec![q(2, 1), q(6, 1), q(1, 1)]));
}
