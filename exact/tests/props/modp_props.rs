//! Property tests of `ModP`, the integers modulo the Mersenne prime 2^61 - 1 used for randomized
//! identity tests: the field laws, inverses, the Mersenne reduction against plain `u128` `%`, and
//! the map from the rationals as a ring homomorphism.

use exactcheck_core::Rng;
use exactcheck_core::{Field, Ring, ZeroDivisor};
use exactcheck_exact::modp::{schwartz_zippel_bound, ModP, P};
use exactcheck_exact::Rational;
use num_bigint::BigInt;
use proptest::prelude::*;

fn elem() -> impl Strategy<Value = ModP> {
    prop_oneof![
        any::<u64>().prop_map(ModP::new),
        (0u64..4).prop_map(|k| ModP::new(P - k)),
        (0u64..4).prop_map(ModP::new),
    ]
}

fn rational() -> impl Strategy<Value = Rational> {
    prop_oneof![
        (any::<i64>(), 1i64..=i64::MAX).prop_map(|(n, d)| Rational::new(n, d).unwrap()),
        (-100i64..100, 1i64..100).prop_map(|(n, d)| Rational::new(n, d).unwrap()),
        (any::<i128>(), 1i128..=i128::MAX)
            .prop_map(|(n, d)| Rational::from_i128_ratio(n, d).unwrap()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn field_laws(x in elem(), y in elem(), z in elem()) {
        prop_assert_eq!(x + y, y + x);
        prop_assert_eq!(x * y, y * x);
        prop_assert_eq!((x + y) + z, x + (y + z));
        prop_assert_eq!((x * y) * z, x * (y * z));
        prop_assert_eq!(x * (y + z), x * y + x * z);
        prop_assert_eq!(x - y + y, x);
        prop_assert_eq!(x + (-x), ModP::zero());
        prop_assert_eq!(x * ModP::one(), x);
        prop_assert!(x.value() < P && (x * y).value() < P && (x - y).value() < P);
        match x.inv() {
            Ok(ix) => {
                prop_assert_eq!(x * ix, ModP::one());
                prop_assert_eq!(y / x * x, y);
            }
            Err(ZeroDivisor) => prop_assert!(x.is_zero()),
        }
        prop_assert_eq!(x.pow(5), x * x * x * x * x);
    }

    #[test]
    fn reduction_matches_u128_rem(a in any::<u64>(), b in any::<u64>(), wide in any::<u128>()) {
        let p = P as u128;
        prop_assert_eq!(ModP::new(a).value() as u128, a as u128 % p);
        prop_assert_eq!(ModP::from_u128(wide).value() as u128, wide % p);
        let (x, y) = (ModP::new(a), ModP::new(b));
        prop_assert_eq!((x * y).value() as u128, (a as u128 % p) * (b as u128 % p) % p);
        prop_assert_eq!((x + y).value() as u128, (a as u128 + b as u128) % p);
        let n = a as i64;
        prop_assert_eq!(ModP::from_i64(n).value() as i128, (n as i128).rem_euclid(p as i128));
        let big = BigInt::from(wide) * BigInt::from(a) - BigInt::from(b);
        let expect = ((&big % BigInt::from(P)) + BigInt::from(P)) % BigInt::from(P);
        prop_assert_eq!(BigInt::from(ModP::from_bigint(&big).value()), expect);
    }

    #[test]
    fn rationals_map_homomorphically(a in rational(), b in rational()) {
        let (fa, fb) = (ModP::from_rational(&a).unwrap(), ModP::from_rational(&b).unwrap());
        prop_assert_eq!(ModP::from_rational(&(&a + &b)).unwrap(), fa + fb);
        prop_assert_eq!(ModP::from_rational(&(&a - &b)).unwrap(), fa - fb);
        prop_assert_eq!(ModP::from_rational(&(&a * &b)).unwrap(), fa * fb);
        prop_assert_eq!(ModP::from_rational(&(-&a)).unwrap(), -fa);
        if !b.is_zero() && !fb.is_zero() {
            prop_assert_eq!(ModP::from_rational(&(&a / &b)).unwrap(), fa / fb);
        }
    }

    #[test]
    fn random_elements_are_reduced(seed in any::<u64>()) {
        let mut g = Rng::new(seed);
        for _ in 0..16 {
            prop_assert!(ModP::random(&mut g).value() < P);
        }
    }
}

#[test]
fn zero_divisors_are_reported() {
    assert_eq!(ModP::zero().inv(), Err(ZeroDivisor));
    let q = Rational::from_i128_ratio(3, P as i128 * 5).unwrap();
    assert_eq!(ModP::from_rational(&q), Err(ZeroDivisor));
    assert_eq!(ModP::from_i64(P as i64), ModP::zero());
}

#[test]
fn schwartz_zippel() {
    assert_eq!(schwartz_zippel_bound(0, 3), 0.0);
    let one = schwartz_zippel_bound(12, 1);
    assert!((one - 12.0 / P as f64).abs() < 1e-30);
    assert!(schwartz_zippel_bound(12, 2) < 1e-34);
}
