//! Tests of the half-gcd: its invariants directly, and the subquadratic gcd against Lehmer's
//! (`gcd_lehmer`, the quadratic reference) on random and worst-case operands up to 10^6 bits.
//! Small tunings make the recursion run deep on small numbers, so that every branch of `hgcd`
//! (both recursive calls, the steps between them, the division steps) is exercised cheaply.

use super::*;
use crate::gcd::gcd_biguint;
use exactcheck_core::Rng;
use num_bigint::BigInt;
use proptest::prelude::*;

/// The measured tuning with the half-gcd path forced at every size (`gcd_biguint` takes it only
/// from `HGCD_GCD_THRESHOLD` limbs on).
const FORCED: HgcdTuning = HgcdTuning {
    gcd_lehmer_below: 2,
    ..HGCD_TUNING
};

/// Tunings exercised: the measured one (forced) and small ones that recurse deeply.
const TUNINGS: [HgcdTuning; 4] = [
    FORCED,
    HgcdTuning {
        hgcd_base: 2,
        gcd_lehmer_below: 3,
        split: 0,
    },
    HgcdTuning {
        hgcd_base: 3,
        gcd_lehmer_below: 4,
        split: 1,
    },
    HgcdTuning {
        hgcd_base: 8,
        gcd_lehmer_below: 10,
        split: 2,
    },
];

fn random_biguint(limbs: usize, st: &mut Rng) -> BigUint {
    let v: Vec<u64> = (0..limbs).map(|_| st.next_u64()).collect();
    from_limbs(&v)
}

/// A random number of exactly `bits` bits.
fn random_bits(bits: u64, st: &mut Rng) -> BigUint {
    let mut x = random_biguint(bits.div_ceil(64) as usize, st) >> (64 * bits.div_ceil(64) - bits);
    x.set_bit(bits - 1, true);
    x
}

/// `(F(k), F(k+1))` by fast doubling.
fn fibonacci_pair(k: u64) -> (BigUint, BigUint) {
    if k == 0 {
        return (BigUint::zero(), BigUint::one());
    }
    let (f, g) = fibonacci_pair(k / 2);
    // F(2j) = F(j) (2 F(j+1) - F(j)), F(2j+1) = F(j)^2 + F(j+1)^2.
    let even = &f * ((&g << 1u32) - &f);
    let odd = &f * &f + &g * &g;
    if k % 2 == 0 {
        (even, odd)
    } else {
        let next = &even + &odd;
        (odd, next)
    }
}

fn fibonacci(k: u64) -> BigUint {
    fibonacci_pair(k).0
}

/// Checks every promise of `half_gcd_tuned` on `(a, b)`; for `generic` operands (random, no
/// huge quotient at the reduction floor) also that the reduced pair has about half the size.
fn check_hgcd(a: &BigUint, b: &BigUint, t: HgcdTuning, generic: bool) {
    let n = nlimbs(a).max(nlimbs(b));
    let s = n / 2 + 1;
    let floor = BigUint::one() << (64 * s);
    let diff = |x: &BigUint, y: &BigUint| if x >= y { x - y } else { y - x };
    match half_gcd_tuned(a, b, t) {
        None => {
            // No step possible.
            assert!(
                a.min(b) < &floor || diff(a, b) < floor,
                "hgcd gave up on a reducible pair: {a:x}, {b:x}"
            );
        }
        Some(h) => {
            let [[m00, m01], [m10, m11]] = &h.matrix;
            let det = BigInt::from(m00 * m11) - BigInt::from(m01 * m10);
            assert_eq!(det, BigInt::from(h.det), "det M");
            assert!(h.det == 1 || h.det == -1);
            assert_eq!(
                &(m00 * &h.a + m01 * &h.b),
                a,
                "M (a', b') = (a, b), first row"
            );
            assert_eq!(
                &(m10 * &h.a + m11 * &h.b),
                b,
                "M (a', b') = (a, b), second row"
            );
            assert!(h.a >= floor && h.b >= floor, "a', b' >= B^s");
            assert!(diff(&h.a, &h.b) < floor, "|a' - b'| < B^s");
            let bound = BigUint::one() << (64 * (n - s));
            for m in [m00, m01, m10, m11] {
                assert!(m < &bound, "entries of M below B^(n-s)");
            }
            assert_ne!(
                (m00, m01, m10, m11),
                (
                    &BigUint::one(),
                    &BigUint::zero(),
                    &BigUint::zero(),
                    &BigUint::one()
                )
            );
            if generic {
                // Half the size: a', b' have at most s + 1 limbs.
                assert!(
                    nlimbs(&h.a).max(nlimbs(&h.b)) <= s + 1,
                    "reduced to about half"
                );
            }
        }
    }
}

/// The subquadratic gcd against Lehmer, both orders, every tuning.
fn check_gcd(a: &BigUint, b: &BigUint) -> BigUint {
    let expected = gcd_lehmer(a, b);
    for t in TUNINGS {
        assert_eq!(gcd_hgcd_tuned(a, b, t), expected, "{t:?}");
        assert_eq!(gcd_hgcd_tuned(b, a, t), expected, "{t:?}");
    }
    assert_eq!(gcd_biguint(a, b), expected);
    expected
}

#[test]
fn hgcd_invariants_random() {
    let mut st = Rng::new(0x4ec0);
    for limbs in [1usize, 2, 3, 4, 5, 7, 10, 16, 33, 64, 100, 257, 600] {
        for _ in 0..3 {
            let a = random_biguint(limbs, &mut st);
            let b = random_biguint(limbs, &mut st) >> (st.next_u64() % 200);
            for t in TUNINGS {
                check_hgcd(&a, &b, t, true);
                check_hgcd(&b, &a, t, true);
            }
        }
    }
}

#[test]
fn hgcd_invariants_special() {
    let mut st = Rng::new(0x5eca1);
    let one = BigUint::one();
    for t in TUNINGS {
        // Equal operands, zero, tiny b, close operands: irreducible.
        let x = random_biguint(40, &mut st);
        assert!(half_gcd_tuned(&x, &x, t).is_none());
        assert!(half_gcd_tuned(&x, &BigUint::zero(), t).is_none());
        assert!(half_gcd_tuned(&x, &BigUint::from(7u32), t).is_none());
        assert!(half_gcd_tuned(&x, &(&x + 12345u32), t).is_none());
        // Consecutive Fibonacci numbers, a multiple, a huge quotient, powers of two.
        let (f, g) = fibonacci_pair(20_000);
        check_hgcd(&g, &f, t, true);
        check_hgcd(&f, &g, t, true);
        check_hgcd(&(&x * random_biguint(30, &mut st)), &x, t, false);
        let b = random_biguint(30, &mut st);
        let q = random_biguint(25, &mut st);
        check_hgcd(&(&b * &q + random_biguint(20, &mut st)), &b, t, false);
        check_hgcd(
            &((&one << 3000u32) * 3u32),
            &((&one << 2900u32) * 5u32),
            t,
            false,
        );
    }
}

#[test]
fn hgcd_reduces_along_the_euclidean_remainders() {
    // The reduced pair lies on the Euclidean remainder sequence r_0 = a, r_1 = b, ..., r_{j+1}
    // = r_{j-1} mod r_j: with a' >= b' it is (r_j, r_{j+1}), or (r_j + r_{j+1}, r_j) when the
    // last quotient was cut short by one to stay above B^s.
    let mut st = Rng::new(0xe0c1);
    for (la, lb) in [(300usize, 300usize), (200, 199), (120, 90)] {
        let a = random_biguint(la, &mut st);
        let b = random_biguint(lb, &mut st);
        for t in TUNINGS {
            let h = half_gcd_tuned(&a, &b, t).expect("random operands are reducible");
            let (hi, lo) = if h.a >= h.b {
                (&h.a, &h.b)
            } else {
                (&h.b, &h.a)
            };
            let (mut r0, mut r1) = if a >= b {
                (a.clone(), b.clone())
            } else {
                (b.clone(), a.clone())
            };
            let found = loop {
                if (&r0, &r1) == (hi, lo) || (&(&r0 + &r1), &r0) == (hi, lo) {
                    break true;
                }
                if r1.is_zero() || &r0 < lo {
                    break false;
                }
                let r2 = &r0 % &r1;
                r0 = mem::replace(&mut r1, r2);
            };
            assert!(found, "reduced pair off the remainder sequence ({t:?})");
            assert_eq!(gcd_lehmer(&h.a, &h.b), gcd_lehmer(&a, &b));
        }
    }
}

#[test]
fn gcd_random_sizes_against_lehmer() {
    // Small tunings on 10^3-bit and larger operands, with and without a planted factor, equal
    // and unequal sizes.
    let mut st = Rng::new(0x9cd);
    for bits in [1_000u64, 3_000, 10_000] {
        let (a, b) = (random_bits(bits, &mut st), random_bits(bits, &mut st));
        check_gcd(&a, &b);
        let g = random_bits(bits / 3, &mut st);
        let (x, y) = (random_bits(bits, &mut st), random_bits(bits - 100, &mut st));
        let d = check_gcd(&(&x * &g), &(&y * &g));
        assert!((&d % &g).is_zero());
        let small = random_bits(bits / 2, &mut st);
        check_gcd(&(&x * &g), &(&small * &g));
        check_gcd(&x, &random_bits(2 * bits, &mut st));
    }
}

#[test]
fn gcd_1e4_and_1e5_bits_against_lehmer() {
    // The measured tuning, forced, on 10^4 and 10^5 bits; planted factors of several sizes.
    let mut st = Rng::new(0x1e5);
    for bits in [10_000u64, 100_000] {
        let (a, b) = (random_bits(bits, &mut st), random_bits(bits, &mut st));
        assert_eq!(gcd_hgcd_tuned(&a, &b, FORCED), gcd_lehmer(&a, &b));
        for gbits in [64u64, bits / 10, bits / 2, 9 * bits / 10] {
            let g = random_bits(gbits, &mut st);
            let x = random_bits(bits - gbits, &mut st);
            let y = random_bits(bits - gbits - 17, &mut st);
            let (a, b) = (&x * &g, &y * &g);
            let d = gcd_hgcd_tuned(&a, &b, FORCED);
            assert_eq!(d, gcd_lehmer(&a, &b));
            assert!((&d % &g).is_zero());
        }
    }
    // Unequal sizes: 10^5 against 6 * 10^4 bits.
    let g = random_bits(5_000, &mut st);
    let (a, b) = (
        random_bits(95_000, &mut st) * &g,
        random_bits(55_000, &mut st) * &g,
    );
    assert_eq!(gcd_hgcd_tuned(&a, &b, FORCED), gcd_lehmer(&a, &b));
}

#[test]
fn gcd_1e6_bits_against_lehmer() {
    // 10^6 bits (gcd_biguint takes the half-gcd path): one random pair and one with a planted
    // 300,000-bit factor.
    let mut st = Rng::new(0x1e6);
    let (a, b) = (
        random_bits(1_000_000, &mut st),
        random_bits(1_000_000, &mut st),
    );
    assert_eq!(gcd_biguint(&a, &b), gcd_lehmer(&a, &b));
    let g = random_bits(300_000, &mut st);
    let (x, y) = (random_bits(700_000, &mut st), random_bits(699_950, &mut st));
    let (a, b) = (&x * &g, &y * &g);
    let d = gcd_biguint(&a, &b);
    assert_eq!(d, gcd_lehmer(&a, &b));
    assert!((&d % &g).is_zero());
}

#[test]
fn gcd_fibonacci_worst_case() {
    // All quotients 1: consecutive Fibonacci numbers are coprime, and gcd(F(m), F(n)) =
    // F(gcd(m, n)). F(300000) has about 208,000 bits.
    let one = BigUint::one();
    let gcd = |a: &BigUint, b: &BigUint| gcd_hgcd_tuned(a, b, FORCED);
    let (f, g) = fibonacci_pair(300_000);
    assert_eq!(gcd(&f, &g), one);
    assert_eq!(gcd(&g, &f), one);
    assert_eq!(
        gcd(&fibonacci(300_000), &fibonacci(240_000)),
        fibonacci(60_000)
    );
    assert_eq!(gcd(&fibonacci(299_997), &fibonacci(200_000)), fibonacci(1));
    // Above the threshold: F(500000) has about 347,000 bits.
    let (f, g) = fibonacci_pair(500_000);
    assert!(f.bits() > 64 * crate::gcd::HGCD_GCD_THRESHOLD as u64);
    assert_eq!(gcd_biguint(&f, &g), one);
    let (f, g) = fibonacci_pair(9_000);
    assert_eq!(check_gcd(&f, &g), one);
    assert_eq!(
        check_gcd(&fibonacci(9_000), &fibonacci(6_000)),
        fibonacci(3_000)
    );
}

#[test]
fn gcd_huge_quotients() {
    // a = q b + r with q of thousands of bits, at the start, in the middle and at the end of
    // the descent.
    let mut st = Rng::new(0x9b16);
    for (bbits, qbits) in [(20_000u64, 5_000u64), (40_000, 20_000), (5_000, 30_000)] {
        let b = random_bits(bbits, &mut st);
        let q = random_bits(qbits, &mut st);
        let r = random_bits(bbits - 1000, &mut st);
        let a = &q * &b + &r;
        check_gcd(&a, &b);
        // Continued fraction [.., 3, q, 5, ..]: the huge quotient in the middle.
        let c = &b * 5u32 + random_bits(bbits / 3, &mut st);
        let d = &q * &c + &b;
        let e = &d * 3u32 + &c;
        check_gcd(&e, &d);
        // A planted factor as well.
        let g = random_bits(3_000, &mut st);
        check_gcd(&(&e * &g), &(&d * &g));
    }
}

#[test]
fn gcd_special_operands() {
    let mut st = Rng::new(0x5bec);
    let one = BigUint::one();
    for bits in [2_000u64, 50_000] {
        let x = random_bits(bits, &mut st);
        // Equal operands, one a multiple of the other, zero.
        assert_eq!(check_gcd(&x, &x), x);
        assert_eq!(check_gcd(&(&x * random_bits(bits / 2, &mut st)), &x), x);
        assert_eq!(check_gcd(&(&x * 3u32), &x), x);
        assert_eq!(check_gcd(&x, &BigUint::zero()), x);
        // Powers of two times odd numbers: the gcd is the smaller power of two times the gcd
        // of the odd parts.
        let (u, v) = (
            random_bits(bits, &mut st) | &one,
            random_bits(bits, &mut st) | &one,
        );
        let g_odd = gcd_lehmer(&u, &v);
        for (i, j) in [(0u64, 5000u64), (4321, 64), (bits, bits + 1)] {
            let d = check_gcd(&(&u << i), &(&v << j));
            assert_eq!(d, &g_odd << i.min(j));
        }
        assert_eq!(
            check_gcd(&(&one << bits), &(&one << (bits / 2))),
            &one << (bits / 2)
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn prop_gcd_against_lehmer(
        la in 1usize..2500, lb in 1usize..2500, lg in 0usize..1500, seed in any::<u64>(),
        t in 0usize..TUNINGS.len()
    ) {
        let mut st = Rng::new(seed);
        let g = random_biguint(lg, &mut st) | BigUint::one();
        let (a, b) = (random_biguint(la, &mut st) * &g, random_biguint(lb, &mut st) * &g);
        prop_assert_eq!(gcd_hgcd_tuned(&a, &b, TUNINGS[t]), gcd_lehmer(&a, &b));
    }

    #[test]
    fn prop_hgcd_invariants(la in 1usize..400, shift in 0u64..3000, seed in any::<u64>(), t in 0usize..TUNINGS.len()) {
        let mut st = Rng::new(seed);
        let a = random_biguint(la, &mut st);
        let b = random_biguint(la, &mut st) >> shift;
        check_hgcd(&a, &b, TUNINGS[t], true);
    }
}

#[test]
fn simulate_min_keeps_the_floor() {
    // lehmer_simulate_min: certified quotients (as lehmer_simulate) and every returned
    // remainder at least `min`; with min = 0 it is lehmer_simulate.
    let mut st = Rng::new(0x51a);
    for _ in 0..3000 {
        let t1 = (u128::from(st.next_u64()) << 64 | u128::from(st.next_u64())) | 1 << 127;
        let t2 =
            (u128::from(st.next_u64()) << 64 | u128::from(st.next_u64())) >> (st.next_u64() % 8);
        let (t1, t2) = (t1.max(t2), t1.min(t2));
        assert_eq!(
            super::super::lehmer_simulate(t1, t2),
            lehmer_simulate_min(t1, t2, 0)
        );
        let min = 1u128 << (st.next_u64() % 126) | 1 << 63;
        if let Some(c) = lehmer_simulate_min(t1, t2, min) {
            let (ia, ib) = (BigInt::from(t1), BigInt::from(t2));
            let sgn = if c.odd { -1 } else { 1 };
            let na = (BigInt::from(c.x1) * &ia - BigInt::from(c.y1) * &ib) * sgn;
            let nb = (BigInt::from(c.y2) * &ib - BigInt::from(c.x2) * &ia) * sgn;
            assert!(nb >= BigInt::from(min) && na > nb, "{t1} {t2} {min} {c:?}");
            // A consecutive pair of the true remainder sequence of (t1, t2).
            let mut r = (BigInt::from(t1), BigInt::from(t2));
            while r.0 != na {
                assert!(r.1 > BigInt::zero());
                r = (r.1.clone(), &r.0 % &r.1);
            }
            assert_eq!(r.1, nb);
        }
    }
}
