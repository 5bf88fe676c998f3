//! Unit tests of the radicand factoring, the field and parsing into it.

use super::radicand::{remove_prime_power, square_free_big, square_free_u64};
use super::*;
use crate::expr::ExprError;
use crate::modp::is_prime_u64;
use crate::radical::radicand::integer_u64;
use exactcheck_core::{OrderedField, Ring, Sign};
use num_bigint::{BigInt, BigUint};
use num_traits::One;

fn r(s: &str) -> Radical {
    s.parse().unwrap_or_else(|e| panic!("{s:?}: {e}"))
}

#[test]
fn factorization() {
    assert_eq!(square_free_u64(1), (1, 1));
    assert_eq!(square_free_u64(12), (2, 3));
    assert_eq!(square_free_u64(72), (6, 2));
    let p = 4_294_967_311u64; // prime above 2^32
    assert!(is_prime_u64(p));
    assert_eq!(square_free_u64(p), (1, p));
    let q = 1_000_000_007u64;
    assert_eq!(square_free_u64(q * q), (q, 1));
    assert_eq!(square_free_u64(q * 1_000_000_009), (1, q * 1_000_000_009));
    assert_eq!(
        square_free_u64(9 * 1_048_583 * 1_048_583),
        (3 * 1_048_583, 1)
    );
    assert!(!is_prime_u64(3_215_031_751)); // strong pseudoprime to bases 2, 3, 5, 7
    assert!(is_prime_u64(u64::MAX - 58)); // the largest 64-bit prime
}

#[test]
fn big_radicands() {
    // (2^61 - 1)^2 * 3: beyond u64, square part found by trial division then rho.
    let p = BigUint::from((1u64 << 61) - 1);
    let n = &p * &p * 3u32;
    let (s, f) = square_free_big(&n).expect("certified");
    assert_eq!(s, p);
    assert_eq!(f.as_u64(), Some(3));
    // A product of two 64-bit primes: beyond reach, and not a square.
    let a = BigUint::from(u64::MAX - 58);
    assert!(is_prime_u64(18_446_744_073_709_551_533));
    let b = BigUint::from(18_446_744_073_709_551_533u64);
    assert!(square_free_big(&(&a * &b)).is_none());
    assert!(square_free_big(&(&a * &a)).is_some());
}

#[test]
fn products_of_big_radicands_do_not_overflow() {
    let p = Radical::sqrt_of(u64::MAX - 58);
    let q = Radical::sqrt_of(18_446_744_073_709_551_533);
    let pq = &p * &q;
    assert!(pq.terms()[0].0.as_u64().is_none());
    assert!(pq.is_canonical());
    let back = &pq * &p;
    assert_eq!(back, q.scale(&integer_u64(u64::MAX - 58)));
    assert!((&pq * &pq).to_rational().is_some());
    assert_eq!(pq.inv().unwrap() * &pq, Radical::one());
    // Printed as sqrt(a)*sqrt(b) with 64-bit factors, so it parses back.
    assert_eq!(pq.to_string().parse::<Radical>(), Ok(pq.clone()));
    assert!(pq.to_string().contains("*sqrt("));
}

#[test]
fn printing() {
    assert_eq!(
        r("1/2 + 3*sqrt(2) - sqrt(6)/3").to_string(),
        "1/2 + 3*sqrt(2) - sqrt(6)/3"
    );
    assert_eq!(r("-sqrt(8)").to_string(), "-2*sqrt(2)");
    assert_eq!(r("0").to_string(), "0");
    assert_eq!(r("-2/3*sqrt(5)").to_string(), "-2*sqrt(5)/3");
}

#[test]
fn denesting() {
    assert_eq!(r("sqrt(2 + sqrt(3))"), r("(sqrt(2) + sqrt(6))/2"));
    assert_eq!(r("sqrt(5 + 2*sqrt(6))"), r("sqrt(2) + sqrt(3)"));
    assert_eq!(r("sqrt(9 + 6*sqrt(2))"), r("sqrt(3) + sqrt(6)"));
    assert!(r("sqrt(2)").sqrt().is_none());
    assert!(r("1 + sqrt(2)").sqrt().is_none());
    assert!(r("1 - sqrt(2)").sqrt().is_none());
}

#[test]
fn filter_agrees_with_exact() {
    let x = r("sqrt(2) + sqrt(3)");
    let close: Rational = "3.1462643699419726".parse().unwrap();
    let d = &x - &Radical::from(close);
    assert_eq!(d.sign_filter(), None);
    assert_eq!(d.sign(), d.sign_exact());
    assert_eq!(r("sqrt(2) - 1").sign_filter(), Some(Sign::Positive));
}

#[test]
fn parse_errors() {
    use ExprError as E;
    let err = |s: &str| s.parse::<Radical>().unwrap_err();
    assert!(matches!(err("1/0"), E::DivisionByZero { pos: 2 }));
    assert!(matches!(err("sqrt(-1)"), E::NoSqrt { pos: 0, .. }));
    assert!(matches!(err("i"), E::NotConstant { pos: 0, .. }));
    assert!(matches!(err("2 +"), E::Unexpected { pos: 3, .. }));
    assert!(matches!(err("2 3"), E::Unexpected { pos: 2, .. }));
    assert!(matches!(err("1."), E::Unexpected { pos: 1, .. }));
    assert!(matches!(err("(1"), E::Unexpected { pos: 2, .. }));
    assert!(
        matches!(err("2^20000"), E::Limit { ref error, .. } if error.limit.name() == "exponent")
    );
    assert!(matches!(err("0^-1"), E::DivisionByZero { pos: 2 }));
    let deep = "(".repeat(500) + "1" + &")".repeat(500);
    assert!(matches!(err(&deep), E::Limit { ref error, .. } if error.limit.name() == "depth"));
    assert!(matches!(err(""), E::Unexpected { pos: 0, .. }));
    assert!(matches!(err("sqrt 2"), E::Unexpected { pos: 5, .. }));
    assert!(matches!(err("é"), E::Unexpected { pos: 0, .. }));
    assert_eq!(
        err("i").to_string(),
        "variable 'i' at 0 where a constant number is expected (the imaginary unit i exists \
         only for complex numbers)"
    );
}

#[test]
fn one_grammar_regressions() {
    // Rejected by the old second parser, which had no juxtaposition and no exponents.
    assert_eq!(r("2 sqrt(4)"), Radical::from_i64(4));
    assert_eq!(r("2sqrt(2)"), r("sqrt(8)"));
    assert_eq!(r("5e0"), Radical::from_i64(5));
    assert_eq!(r("2.5e-3 sqrt(2)"), r("sqrt(2)/400"));
    assert_eq!(r("2^-2"), r("1/4"));
    // Powers up to the exponent limit (the old parser stopped at 1024), within the size limit.
    assert_eq!(r("(sqrt(2))^2000"), r("2^1000"));
    // Regression: `"((2^1024)^1024)^1024"` ran for 13 s and aborted; now refused at once.
    assert_eq!(
        "((2^1024)^1024)^1024"
            .parse::<Radical>()
            .unwrap_err()
            .to_string(),
        "at 0: size of a constant exceeds the limit constant-bits = 1000000 bits (found at least \
         1048576; raise it with --limit constant-bits=N)"
    );
    assert!(matches!(
        "sqrt((2^1024)^1024*2)/1000".parse::<Radical>(),
        Err(ExprError::Limit { ref error, .. }) if error.limit.name() == "constant-bits"
    ));
}

#[test]
fn big_prime_powers_are_removed_in_few_passes() {
    let mut c = BigUint::from(3u32).pow(1001) * 7u32;
    assert_eq!(remove_prime_power(&mut c, 3), 1001);
    assert_eq!(c, BigUint::from(7u32));
    let mut c = BigUint::from(5u32);
    assert_eq!(remove_prime_power(&mut c, 5), 1);
    assert_eq!(c, BigUint::one());
    // Regression: `sqrt(2^999000 * 3)` divided by 2 once per pass (a million passes over a
    // million bits) and never finished; the square part is now found at once.
    let n = (BigUint::one() << 999_000u32) * 3u32;
    let (s, f) = square_free_big(&n).expect("certified");
    assert_eq!(s, BigUint::one() << 499_500u32);
    assert_eq!(f.as_u64(), Some(3));
    let x: Radical = "sqrt((2^1000)^999*3)/(2^500)^999".parse().unwrap();
    assert_eq!(x, Radical::sqrt_of(3));
}

#[test]
fn common_denominator_printing() {
    let w1 = r("(2*sqrt(2) + sqrt(6))/3");
    assert_eq!(w1.to_string(), "2*sqrt(2)/3 + sqrt(6)/3");
    assert_eq!(
        w1.to_string_over_common_denominator(),
        "(2*sqrt(2) + sqrt(6))/3"
    );
    let x = r("-1/2 + sqrt(2)/3");
    assert_eq!(x.to_string_over_common_denominator(), "(-3 + 2*sqrt(2))/6");
    assert_eq!(r(&x.to_string_over_common_denominator()), x);
    assert_eq!(
        r("-sqrt(2)/2").to_string_over_common_denominator(),
        "-sqrt(2)/2"
    );
    assert_eq!(
        r("1 + sqrt(2)").to_string_over_common_denominator(),
        "1 + sqrt(2)"
    );
}

/// The sum of the square roots of the first `k` primes.
fn prime_root_sum(k: usize) -> String {
    let primes: Vec<u64> = (2u64..)
        .filter(|&n| (2..n).take_while(|d| d * d <= n).all(|d| n % d != 0))
        .take(k)
        .collect();
    primes
        .iter()
        .map(|p| format!("sqrt({p})"))
        .collect::<Vec<_>>()
        .join(" + ")
}

#[test]
fn independent_radicals_is_the_rank_modulo_squares() {
    assert_eq!(r("3/4").independent_radicals(), 0);
    assert_eq!(r("sqrt(6)").independent_radicals(), 1);
    // One radicand with ten prime factors is one square root.
    assert_eq!(r("sqrt(6469693230)").independent_radicals(), 1);
    assert_eq!(
        r("1 + sqrt(2) + sqrt(3) + sqrt(6)").independent_radicals(),
        2
    );
    // sqrt(6) sqrt(10) = 2 sqrt(15): three radicands, two independent roots.
    assert_eq!(r("sqrt(6) + sqrt(10) + sqrt(15)").independent_radicals(), 2);
    assert_eq!(r(&prime_root_sum(7)).independent_radicals(), 7);
    // Radicands beyond 64 bits (products of 64-bit factors).
    let big = r("sqrt(18446744073709551557) * sqrt(18446744073709551533) + sqrt(2)");
    assert_eq!(big.independent_radicals(), 2);
}

/// `(sqrt(2) + ... + sqrt(97))^8` (25 primes) aborted allocating 5.4 GB and its
/// inverse asked for 2.2 TB; the sum is now refused, naming the limit, before any product.
#[test]
fn many_radicands_are_refused_with_the_limit() {
    let msg = |s: &str| s.parse::<Radical>().unwrap_err().to_string();
    let limit = exactcheck_core::limits::RADICANDS.get();
    assert_eq!(limit, 10, "the test assumes the default");
    let e = msg(&format!("({})^8", prime_root_sum(25)));
    assert!(e.contains("the limit radicands = 10 (found 11;"), "{e}");
    let e = msg(&format!("1/({})", prime_root_sum(12)));
    assert!(e.contains("the limit radicands = 10"), "{e}");
    // At the limit: computed.
    let s = r(&prime_root_sum(10));
    let inv = s.inv().unwrap();
    assert_eq!(inv.mul_ref(&s), Radical::one());
    assert_eq!(inv.independent_radicals(), 10);
}

/// `sqrt((S10)^2)` took 3.4-14 s (the trial division of every perfect-square norm ran
/// to its bound); the denesting now finds the root at once.
#[test]
fn denesting_a_square_of_ten_roots() {
    let s = prime_root_sum(10);
    let y = r(&format!("sqrt(({s})^2)"));
    assert_eq!(y, r(&s));
}

/// A cofactor out of reach of the trial division is named as such, not as negative or not
/// denestable.
#[test]
fn the_sqrt_message_says_why() {
    let msg = |s: &str| s.parse::<Radical>().unwrap_err().to_string();
    // Two primes near 2^80: no factor below the bound, not a square.
    let e = msg("sqrt(1208925819614629174706189*1208925819614629174706193)");
    assert!(e.contains("trial-division bound 2^20"), "{e}");
    assert!(!e.contains("negative"), "{e}");
    assert!(msg("sqrt(-2)").contains("it is negative"));
    assert!(msg("sqrt(sqrt(2))").contains("not denestable"));
    // A huge square part with a small square-free part is extracted (2^10000 * 3).
    assert_eq!(
        r("sqrt((2^1000)^10*3)"),
        Radical::sqrt_of(3).scale(&Rational::from(BigInt::from(2).pow(5000)))
    );
}

#[test]
fn to_f64_beyond_f64s_range_is_signed_infinity_or_zero_never_nan() {
    // Terms of opposite signs that each overflow: the difference of the rounded terms was
    // `inf - inf`, NaN; the value is `10^400 (sqrt(2) - 1)`, beyond f64's range, positive.
    assert_eq!(r("10^400*sqrt(2) - 10^400").to_f64(), f64::INFINITY);
    assert_eq!(r("10^400 - 10^400*sqrt(2)").to_f64(), f64::NEG_INFINITY);
    // The product P of the primes below 1000 (about 10^416, square-free) as a radicand beyond
    // 2^1000: with a coefficient that underflows f64 the term was `0 * inf`, NaN; with one in
    // range it was `inf`. The values are 10^-350 sqrt(P) and 10^-300 sqrt(P).
    let primes: Vec<u64> = (2..1000).filter(|&n| is_prime_u64(n)).collect();
    let product = primes.iter().fold(BigUint::one(), |acc, &p| acc * p);
    let root = Radical::sqrt_rational(&Rational::from(BigInt::from(product))).expect("square-free");
    let half_log10: f64 = primes.iter().map(|&p| (p as f64).log10()).sum::<f64>() / 2.0;
    for k in [350u32, 300] {
        let tiny = r(&format!("1/10^{k}")).to_rational().expect("rational");
        let got = root.scale(&tiny).to_f64();
        let want = 10f64.powf(half_log10 - f64::from(k));
        assert!((got / want - 1.0).abs() < 1e-9, "10^-{k}: {got} vs {want}");
    }
    // Tiny values round towards zero with their sign, in-range values as before.
    assert_eq!(r("10^-400*sqrt(2) - 10^-400").to_f64(), 0.0);
    assert_eq!(r("sqrt(2)").to_f64(), std::f64::consts::SQRT_2);
    assert_eq!(r("3/4").to_f64(), 0.75);
}
