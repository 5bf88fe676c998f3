//! Arithmetic of the square-root field `Radical` (Q adjoined square roots of the primes 2, 3, 5
//! and 7: every radicand is a product of a subset of them times a square) against itself and
//! against f64.
//!
//! From the input: two elements `a`, `b` of up to four terms `c sqrt(m)` each (c = n/d with
//! small n, d). Checked: canonical forms; `a + b - b = a`, `a * b = b * a`, `(a * b) / b = a`,
//! `a * a^-1 = 1`, `(a - b) + b = a`; `sqrt(a^2) = |a|` (the root of a square of the field is in
//! the field) and `sqrt(a)^2 = a` whenever a root is returned; the exact sign agrees with the
//! f64 value where that is well-conditioned (|value| above 1e-9 of the sum of the terms'
//! magnitudes), and products and quotients agree with f64 to 1e-9 relative. Never a panic.
#![no_main]
use exactcheck_core::scalar::{Field, OrderedField, Ring, Sign, Sqrt};
use exactcheck_exact::{Radical, Rational};
use exactcheck_fuzz::small_limits;
use libfuzzer_sys::fuzz_target;

/// A radicand from one byte: the product of the primes whose bit is set (bits 0..4 of 2, 3, 5,
/// 7) times the square of (the high nibble + 1).
fn radicand(byte: u8) -> u64 {
    let primes = [2u64, 3, 5, 7];
    let core: u64 = primes
        .iter()
        .enumerate()
        .filter(|(i, _)| byte & (1 << i) != 0)
        .map(|(_, p)| p)
        .product();
    let k = u64::from(byte >> 4) + 1;
    core * k * k
}

/// An element from up to four (radicand, numerator, denominator) triples.
fn element(bytes: &[u8]) -> (Radical, f64) {
    let mut x = Radical::zero();
    let mut size = 0.0f64;
    for t in bytes.chunks_exact(3).take(4) {
        let m = radicand(t[0]);
        let n = i64::from(t[1] as i8);
        let d = i64::from(t[2] % 16) + 1;
        let c = Rational::new(n, d).expect("d >= 1");
        let term = Radical::sqrt_of(m).scale(&c);
        size += term.to_f64().abs();
        x = x.add_ref(&term);
    }
    (x, size)
}

/// The sign an f64 value shows when it is clearly away from zero relative to `size`.
fn clear_sign(v: f64, size: f64) -> Option<Sign> {
    if v.abs() <= 1e-9 * size || !v.is_finite() {
        None
    } else if v > 0.0 {
        Some(Sign::Positive)
    } else {
        Some(Sign::Negative)
    }
}

fn check_sign(x: &Radical, size: f64, what: &str) {
    assert!(x.is_canonical(), "{what} = {x:?} is not canonical");
    let exact = x.sign();
    assert_eq!(
        exact,
        x.sign_exact(),
        "sign and sign_exact differ for {what} = {x:?}"
    );
    assert_eq!(exact == Sign::Zero, x.is_zero(), "{what} = {x:?}");
    if let Some(s) = clear_sign(x.to_f64(), size) {
        assert_eq!(exact, s, "{what} = {x:?}: exact sign vs f64 {}", x.to_f64());
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(f64::MIN_POSITIVE)
}

fuzz_target!(|data: &[u8]| {
    small_limits();
    let Some((&split, rest)) = data.split_first() else {
        return;
    };
    let cut = (usize::from(split % 5) * 3).min(rest.len());
    let (a, sa) = element(&rest[..cut]);
    let (b, sb) = element(&rest[cut..]);
    check_sign(&a, sa, "a");
    check_sign(&b, sb, "b");

    let sum = a.add_ref(&b);
    check_sign(&sum, sa + sb, "a + b");
    assert_eq!(sum.sub_ref(&b), a, "a + b - b");
    let diff = a.sub_ref(&b);
    check_sign(&diff, sa + sb, "a - b");
    assert_eq!(diff.add_ref(&b), a, "(a - b) + b");
    assert_eq!(
        a.cmp(&b),
        match diff.sign() {
            Sign::Negative => std::cmp::Ordering::Less,
            Sign::Zero => std::cmp::Ordering::Equal,
            Sign::Positive => std::cmp::Ordering::Greater,
        },
        "cmp vs sign of a - b"
    );

    let prod = a.mul_ref(&b);
    assert_eq!(prod, b.mul_ref(&a), "a * b = b * a");
    check_sign(&prod, sa * sb, "a * b");
    let (fa, fb) = (a.to_f64(), b.to_f64());
    if clear_sign(fa, sa).is_some() && clear_sign(fb, sb).is_some() {
        assert!(
            close(prod.to_f64(), fa * fb),
            "a * b = {} vs f64 {}",
            prod.to_f64(),
            fa * fb
        );
    }
    assert_eq!(a.square(), a.mul_ref(&a), "square");

    match b.inv() {
        Err(_) => assert!(b.is_zero(), "b = {b:?} has no inverse"),
        Ok(inv) => {
            assert!(!b.is_zero());
            assert!(b.mul_ref(&inv).is_one(), "b * b^-1 for b = {b:?}");
            let q = a.checked_div(&b).expect("b is not zero");
            assert_eq!(q.mul_ref(&b), a, "(a / b) * b");
            assert_eq!(
                prod.checked_div(&b).expect("b is not zero"),
                a,
                "(a * b) / b"
            );
            if clear_sign(fa, sa).is_some() && clear_sign(fb, sb).is_some() {
                assert!(
                    close(q.to_f64(), fa / fb),
                    "a / b = {} vs f64 {}",
                    q.to_f64(),
                    fa / fb
                );
            }
        }
    }

    // sqrt(a^2) = |a|.
    let root = a.square().sqrt();
    let abs = if a.sign() == Sign::Negative {
        a.neg_ref()
    } else {
        a.clone()
    };
    assert_eq!(root.as_ref(), Some(&abs), "sqrt(a^2) for a = {a:?}");
    match a.sqrt() {
        Some(r) => {
            assert_ne!(r.sign(), Sign::Negative, "sqrt(a) < 0 for a = {a:?}");
            assert_eq!(r.square(), a, "sqrt(a)^2 for a = {a:?}");
        }
        None => assert_ne!(a.sign(), Sign::Zero, "sqrt(0) refused"),
    }
});
