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
/// `i128` or 192 bits, and the result is the exact sum.
#[test]
fn accumulators_hold_extreme_sums() {
    let x = |i: Var| P::var(i);
    for (c, n) in [
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
        prop_assert_eq!(fast, slow);
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
