//! Unit tests of the Descartes isolator against the Sturm isolator and the reference options.

use super::*;
use exactcheck_core::bernstein::Bernstein;
use exactcheck_core::Rng;
use exactcheck_core::Sign;

fn bigs(c: &[i64]) -> Vec<BigInt> {
    c.iter().map(|&x| BigInt::from(x)).collect()
}

fn rationals(c: &[BigInt]) -> Vec<Rational> {
    c.iter().cloned().map(Rational::from).collect()
}

/// `a` is a positive multiple of `b` (coefficientwise, zeros included).
fn positive_multiple(a: &[BigInt], b: &[Rational]) {
    assert_eq!(a.len(), b.len());
    let mut ratio: Option<Rational> = None;
    for (x, y) in a.iter().zip(b) {
        assert_eq!(x.is_zero(), y.is_zero(), "{a:?} vs {b:?}");
        if !y.is_zero() {
            let r = Rational::from(x.clone()) / y.clone();
            assert_eq!(r.signum(), Sign::Positive);
            if let Some(q) = &ratio {
                assert_eq!(&r, q);
            }
            ratio = Some(r);
        }
    }
}

fn random_poly(rng: &mut Rng, n: usize) -> Vec<BigInt> {
    let mut c: Vec<BigInt> = (0..=n)
        .map(|_| BigInt::from(rng.below(2001) as i64 - 1000))
        .collect();
    if c[n].is_zero() {
        c[n] = BigInt::one();
    }
    c
}

#[test]
fn integer_bernstein_form_and_split_match_the_rational_ones() {
    let mut rng = Rng::new(14);
    for n in 1..=12 {
        let p = random_poly(&mut rng, n);
        let b = to_bernstein_integer(&p);
        let exact = Bernstein::from_power(&rationals(&p)).expect("non-empty");
        positive_multiple(&b, exact.coeffs());
        let (l, r) = split_half(&b);
        // The fixed-width kernel is the BigInt one exactly, twice over.
        let (ll, lr) = Limbs::from_bigints(&b).split_half();
        assert_eq!(ll.to_bigints(), l);
        assert_eq!(lr.to_bigints(), r);
        let (lll, llr) = ll.split_half();
        assert_eq!((lll.to_bigints(), llr.to_bigints()), split_half(&l));
        let (el, er) = exact.split(&half());
        positive_multiple(&l, el.coeffs());
        positive_multiple(&r, er.coeffs());
    }
}

#[test]
fn limb_kernel_matches_bigint_kernel_on_wide_numbers() {
    let mut rng = Rng::new(4141);
    for n in [1usize, 2, 5, 20, 41, 70] {
        for bits in [3u32, 63, 64, 65, 130, 400] {
            let p: Vec<BigInt> = (0..=n)
                .map(|_| {
                    let x = (BigInt::from(rng.below(1 << 62)) << (bits.saturating_sub(62)))
                        + BigInt::from(rng.below(1 << 20));
                    if rng.below(2) == 0 {
                        -x
                    } else {
                        x
                    }
                })
                .collect();
            let b = to_bernstein_integer(&p);
            let mut big = b.clone();
            let mut limbs = Limbs::from_bigints(&b);
            assert_eq!(limbs.to_bigints(), b);
            // Down one path of ten levels, alternating sides.
            for level in 0..10 {
                let (bl, br) = split_half(&big);
                let (ll, lr) = limbs.split_half();
                assert_eq!(ll.to_bigints(), bl, "n {n}, bits {bits}, level {level}");
                assert_eq!(lr.to_bigints(), br, "n {n}, bits {bits}, level {level}");
                (big, limbs) = if level % 2 == 0 { (bl, ll) } else { (br, lr) };
                for (i, c) in big.iter().enumerate() {
                    assert_eq!(limbs.sign_at(i), sign_of(c));
                }
            }
        }
    }
    // The f64 images of the limbs and of the BigInts agree up to a common power of two.
    for bits in [5u32, 64, 200] {
        let b: Vec<BigInt> = (0..9)
            .map(|i| (BigInt::from(i * 7919 - 30000) << bits) - BigInt::from(i))
            .collect();
        let (x, y) = (Limbs::from_bigints(&b).scaled_f64s(), b.scaled_f64s());
        let ratio = x[0] / y[0];
        assert_eq!(ratio, ratio.log2().round().exp2(), "a power of two");
        for (u, v) in x.iter().zip(&y) {
            assert!(
                (u - v * ratio).abs() <= 1e-15 * u.abs().max(1e-300),
                "{u} {v}"
            );
        }
    }
    // The Taylor shift on limbs is the BigInt one (widths 1, 2, 3, 4 and 6 limbs: the
    // fixed-width kernels and the general loop).
    let mut widths = Vec::new();
    for n in [8usize, 20, 40, 57, 90] {
        let c: Vec<BigInt> = (0..=n)
            .map(|i| (BigInt::from(i as i64 * 977 - 20_000) << (i * 3)) - 5)
            .collect();
        let mut reference = c.clone();
        taylor_shift_1(&mut reference);
        let mut l = Limbs::from_bigints_with_room(&c, n + 1);
        let w = l.width();
        l.taylor_shift_1();
        assert_eq!(l.to_bigints(), reference, "width {w}");
        widths.push(w);
    }
    assert_eq!(widths, [1, 2, 3, 4, 6]);
    // The multipliers L / C(n, i) by the recurrence equal the lcm of the binomials over
    // each binomial.
    for n in [1usize, 6, 30, 61] {
        let p: Vec<BigInt> = (0..=n).map(|i| BigInt::from(i as i64 - 3)).collect();
        let mut binom = vec![BigInt::one(); n + 1];
        for i in 1..=n {
            binom[i] = &binom[i - 1] * BigInt::from(n - i + 1) / BigInt::from(i);
        }
        let l = binom
            .iter()
            .fold(BigInt::one(), |l, b| num_integer::Integer::lcm(&l, b));
        let mut c: Vec<BigInt> = p.iter().rev().cloned().collect();
        taylor_shift_1(&mut c);
        let expect: Vec<BigInt> = (0..=n).map(|i| &c[n - i] * (&l / &binom[i])).collect();
        assert_eq!(to_bernstein_integer(&p), expect);
    }
}

#[test]
fn approx_is_the_top_64_bits() {
    let mut rng = Rng::new(7);
    for bits in [1u64, 2, 63, 64, 65, 127, 128, 129, 191, 192, 193, 500] {
        for _ in 0..20 {
            let x: BigInt = (0..bits.div_ceil(64)).fold(BigInt::zero(), |acc, _| {
                (acc << 64) + BigInt::from(rng.next_u64())
            }) >> (bits.div_ceil(64) * 64 - bits);
            let x = x | (BigInt::one() << (bits - 1));
            for v in [x.clone(), -x.clone()] {
                let shift = v.bits().saturating_sub(64);
                let top = (v.magnitude() >> shift).to_u64().expect("64 bits");
                let m = if v.is_negative() {
                    -(top as f64)
                } else {
                    top as f64
                };
                assert_eq!(approx(&v), Some((m, shift as i64)), "{v}");
            }
        }
    }
    assert_eq!(approx(&BigInt::zero()), None);
}

#[test]
fn word_contents_divide_out_of_big_coefficients() {
    // 3 (x - 2^100) (x + 5): coefficients beyond i128 and a word content of 3 and 6.
    let big: BigInt = BigInt::one() << 100u32;
    for k in [3i64, -6] {
        let k = BigInt::from(k);
        let five = BigInt::from(5);
        let p = [-(&big * &five) * &k, (&five - &big) * &k, k.clone()];
        let q = square_free_integer(&p);
        assert_eq!(q, vec![-(&big * &five), &five - &big, BigInt::one()]);
    }
}

#[test]
fn content_is_the_gcd() {
    let mut rng = Rng::new(99);
    for _ in 0..50 {
        let k = BigInt::from(rng.below(1 << 40) + 1) * BigInt::from(rng.below(1 << 40) + 1);
        let c: Vec<BigInt> = (0..6)
            .map(|_| &k * BigInt::from(rng.below(2001) as i64 - 1000))
            .collect();
        let expect = c
            .iter()
            .fold(BigInt::zero(), |g, x| num_integer::Integer::gcd(&g, x));
        assert_eq!(content(&c), expect);
    }
    assert_eq!(content(&bigs(&[0, 0])), BigInt::zero());
    assert_eq!(content(&bigs(&[0, -6, 0, 9])), BigInt::from(3));
}

#[test]
fn modular_square_free_test() {
    // (x - 1)^2 (x + 2) is not square-free: never "proved".
    assert!(!is_square_free_mod_p(&bigs(&[2, -3, 0, 1])));
    assert!(is_square_free_mod_p(&bigs(&[1, 0, 1])));
    assert!(is_square_free_mod_p(
        &super::super::bench_instances::wilkinson(30)
    ));
    // The square-free part of (x - 1)^2 (x + 2) is x^2 + x - 2.
    assert_eq!(
        square_free_integer(&bigs(&[-4, 6, 0, -2])),
        bigs(&[-2, 1, 1])
    );
}

#[test]
fn the_filter_never_contradicts_the_exact_sign() {
    let mut rng = Rng::new(53);
    let polys = [
        super::super::bench_instances::wilkinson(20),
        super::super::bench_instances::mignotte(30),
        super::super::bench_instances::random(40),
        random_poly(&mut rng, 25),
    ];
    let mut decided = 0;
    for q in &polys {
        let r = Refiner::new(q);
        for _ in 0..400 {
            let exp = rng.below(60);
            let num = BigInt::from(rng.below(1 << 62) as i64 - (1 << 61)) >> (62 - exp.min(62));
            let x = Dyadic { num, exp };
            let (p, _) = r.eval_exact(&x);
            if let Some(s) = r.filtered_sign(&x) {
                decided += 1;
                assert_eq!(s, sign_of(&p), "{x:?}");
            }
            let xr = x.to_rational();
            let v = upoly_of(q).eval(&xr);
            assert_eq!(sign_of(&p), v.signum());
        }
    }
    assert!(decided > 100, "the filter decided only {decided} signs");
}

fn upoly_of(q: &[BigInt]) -> UPoly {
    UPoly::from_coeffs(rationals(q))
}

/// Checks `found` (refined to width `w`) against the Sturm isolation of `c`: the same count,
/// sorted and disjoint closed intervals, each of width at most `w` and overlapping exactly
/// one Sturm interval, each exact one a root, each open one with end values of opposite
/// non-zero signs of the square-free part.
fn check_refined_against_sturm(c: &[BigInt], found: &[RootInterval], w: &Rational) {
    check_against_sturm_with(c, found, w, true);
}

/// `strict`: the closed intervals are disjoint (refined); otherwise they may share an end
/// (isolating intervals).
fn check_against_sturm_with(c: &[BigInt], found: &[RootInterval], w: &Rational, strict: bool) {
    let p = upoly_of(c);
    let sturm = isolate_real_roots_sturm(&p);
    assert_eq!(found.len(), sturm.len(), "{p}: {found:?} vs {sturm:?}");
    let sqf = p.square_free_part();
    for pair in found.windows(2) {
        assert!(
            pair[0].hi < pair[1].lo || (!strict && pair[0].hi == pair[1].lo),
            "{pair:?} of {p}"
        );
    }
    for (f, s) in found.iter().zip(&sturm) {
        assert!(f.width() <= *w, "{f:?} of {p} wider than {w}");
        if f.is_exact() {
            assert!(p.eval(&f.lo).is_zero(), "{f:?} is not a root of {p}");
            assert!(s.lo <= f.lo && f.lo <= s.hi, "{f:?} vs {s:?} of {p}");
        } else {
            let (a, b) = (sqf.sign_at(&f.lo), sqf.sign_at(&f.hi));
            assert!(a != Sign::Zero && b != Sign::Zero && a != b, "{f:?} of {p}");
            let lo = f.lo.clone().max(s.lo.clone());
            let hi = f.hi.clone().min(s.hi.clone());
            assert!(lo <= hi, "{f:?} vs {s:?} of {p}");
        }
    }
}

fn product(factors: &[(i64, i64)], rest: &[i64]) -> Vec<BigInt> {
    let mut p = UPoly::from_i64_coeffs(rest);
    for &(q, r) in factors {
        p *= UPoly::from_i64_coeffs(&[-r, q]);
    }
    p.integer_coefficients()
}

/// Runs the fast and the reference isolator, checks both against Sturm, returns the fast
/// answer.
fn both(c: &[BigInt], w: &Rational) -> Vec<RootInterval> {
    let fast = real_roots_to_with(c, w, Options::FAST).expect("non-zero");
    let reference = real_roots_to_with(c, w, Options::REFERENCE).expect("non-zero");
    check_refined_against_sturm(c, &fast, w);
    check_refined_against_sturm(c, &reference, w);
    let coarse = integer_real_roots(c).expect("non-zero");
    check_against_sturm_with(c, &coarse, &Rational::from(BigInt::one() << 4000u32), false);
    fast
}

#[test]
fn rational_roots_are_recognised_exactly() {
    let w = super::super::bench_instances::target_width();
    let mut rng = Rng::new(1414);
    for round in 0..24 {
        // Distinct rational roots r / q with denominators up to 60, some dividing a small
        // leading coefficient, some dyadic, some at 0 and +-1, times an irreducible
        // quadratic (x^2 + 2 or x^2 - 3: irrational or complex roots).
        let k = 1 + rng.below(9) as usize;
        let mut roots: Vec<(i64, i64)> = Vec::new();
        while roots.len() < k {
            let q = 1 + rng.below(if round % 2 == 0 { 60 } else { 8 }) as i64;
            let r = rng.below(8 * q as u64 + 1) as i64 - 4 * q;
            let g = num_integer::Integer::gcd(&r, &q);
            let (r, q) = (r / g.max(1), q / g.max(1));
            if !roots.contains(&(q, r)) {
                roots.push((q, r));
            }
        }
        let rest: &[i64] = if round % 3 == 0 {
            &[-3, 0, 1]
        } else {
            &[2, 0, 1]
        };
        let c = product(&roots, rest);
        let fast = both(&c, &w);
        let exact = fast.iter().filter(|r| r.is_exact()).count();
        assert_eq!(exact, roots.len(), "{roots:?}: {fast:?}");
    }
    // The Wilkinson products: every root exact.
    for n in [5usize, 20, 40] {
        let fast = both(&super::super::bench_instances::wilkinson(n), &w);
        assert!(fast.iter().all(RootInterval::is_exact), "wilkinson({n})");
    }
}

#[test]
fn recognition_needs_the_divisibility_and_the_exact_test() {
    // x^2 - 2 (roots +-sqrt 2): the convergents 3/2, 7/5, 17/12, ... of sqrt 2 pass
    // neither p | 2 with q | 1 nor the exact test: nothing is recognised.
    let c = bigs(&[-2, 0, 1]);
    let lo = Rational::from_integer(1);
    let hi = Rational::from_integer(2);
    assert_eq!(
        recognise_rational(&c, std::f64::consts::SQRT_2, &lo, &hi),
        None
    );
    // 3 x^2 - 2 x - 1 = (3 x + 1)(x - 1): an estimate near -1/3 finds it, one near 1 too.
    let c = bigs(&[-1, -2, 3]);
    let third = Rational::new(-1, 3).expect("3");
    assert_eq!(
        recognise_rational(
            &c,
            -0.333_333_3,
            &Rational::from_integer(-1),
            &Rational::ZERO
        ),
        Some(third)
    );
    // A candidate outside the interval is not returned.
    assert_eq!(
        recognise_rational(
            &c,
            -0.333_333_3,
            &Rational::ZERO,
            &Rational::from_integer(2)
        ),
        None
    );
    assert!(linear_factor_divides(&c, -1, 3));
    assert!(linear_factor_divides(&c, 1, 1));
    assert!(!linear_factor_divides(&c, 1, 3));
    assert_eq!(
        convergents(0.75).collect::<Vec<_>>(),
        vec![(0, 1), (1, 1), (3, 4)]
    );
    assert_eq!(convergents(f64::NAN).count(), 0);
    assert_eq!(convergents(2.0).collect::<Vec<_>>(), vec![(2, 1)]);
}

/// The Bernstein form from the shifted limbs equals the `BigInt` one, with word
/// multipliers (degree up to 44) and with big ones (above).
#[test]
fn bernstein_from_shifted_limbs_agrees() {
    let mut rng = Rng::new(77);
    for n in [1usize, 2, 8, 20, 44, 45, 60, 90] {
        let p: Vec<BigInt> = (0..=n)
            .map(|_| BigInt::from(rng.next_u64() as i64) << (rng.below(90) as u32))
            .collect();
        let rev: Vec<BigInt> = p.iter().rev().cloned().collect();
        let mut shifted = Limbs::from_bigints_with_room(&rev, n + 1);
        shifted.taylor_shift_1();
        assert_eq!(
            bernstein_from_shifted(&shifted).to_bigints(),
            to_bernstein_integer(&p),
            "degree {n}"
        );
    }
}

/// `BigInt`s through limbs and back: signs, zero, `-2^(64k)`, `2^(64k) - 1`, with room.
#[test]
fn limbs_round_trip() {
    let mut cs: Vec<BigInt> = vec![BigInt::zero(), BigInt::one(), -BigInt::one()];
    for k in [1u32, 2, 3] {
        let p = BigInt::one() << (64 * k);
        cs.extend([p.clone(), -p.clone(), &p - 1, 1 - &p, -(&p >> 1u32)]);
    }
    for extra in [0, 1, 63, 64, 200] {
        let l = Limbs::from_bigints_with_room(&cs, extra);
        assert_eq!(l.to_bigints(), cs, "room {extra}");
    }
    assert_eq!(Limbs::from_bigints_width(&cs, 6).to_bigints(), cs);
}

/// The limb synthetic division ([`Limbs::divide_by_linear`]) against the `BigInt` one:
/// products `(q x - p) g` with random `g` (coefficients up to 200 bits, both parities of
/// `q` and `p`, signs, words near 2^63) give the quotient `g`, and other linear factors
/// are refused exactly when the reference refuses them.
/// A random case for the divisions by a linear factor `q x - p`: `g` of degree 1 to
/// `max_degree` with coefficients of `bits` bits and random signs (`None` when its leading
/// coefficient came out zero), and `p / q` in lowest terms, `q > 0`, with words drawn from small
/// values (up to `small`), 20-bit ones, full 63-bit ones and words next to `i64::MAX`.
pub(super) fn random_linear_factor_case(
    rng: &mut Rng,
    max_degree: u64,
    bits: u32,
    small: u64,
) -> Option<(Vec<BigInt>, i64, i64)> {
    let word = |rng: &mut Rng| -> i64 {
        match rng.below(4) {
            0 => 1 + rng.below(small) as i64,
            1 => 1 + rng.below(1 << 20) as i64,
            2 => (rng.next_u64() >> 1) as i64,
            _ => i64::MAX - rng.below(5) as i64,
        }
    };
    let deg = 1 + rng.below(max_degree) as usize;
    let g: Vec<BigInt> = (0..=deg)
        .map(|_| {
            let mut x = BigInt::from(rng.next_u64());
            for _ in 0..bits / 64 {
                x = (x << 64u32) + BigInt::from(rng.next_u64());
            }
            x >>= (64 - bits % 64) % 64;
            if rng.below(2) == 0 {
                -x
            } else {
                x
            }
        })
        .collect();
    if g[deg].is_zero() {
        return None;
    }
    let (mut p, mut q) = (word(rng), word(rng));
    let gc = num_integer::Integer::gcd(&p, &q);
    (p, q) = (p / gc, q / gc);
    if rng.below(2) == 0 {
        p = -p;
    }
    Some((g, p, q))
}

#[test]
fn limb_division_agrees_with_the_bigint_reference() {
    let mut rng = Rng::new(2611);
    for round in 0..400 {
        let bits = [3u32, 64, 200][round % 3];
        let Some((g, p, q)) = random_linear_factor_case(&mut rng, 12, bits, 7) else {
            continue;
        };
        let deg = g.len() - 1;
        // a = (q x - p) g.
        let mut a = vec![BigInt::zero(); deg + 2];
        for (i, c) in g.iter().enumerate() {
            a[i + 1] += c * q;
            a[i] -= c * p;
        }
        let w = super::super::limbs::linear_factor_width(&a);
        let l = Limbs::from_bigints_width(&a, w);
        let got = l
            .divide_by_linear(p, q)
            .expect("a true factor is certified");
        assert_eq!(got.to_bigints(), g, "round {round}: ({q} x - {p})");
        // Other candidates: the reference decides.
        for (p2, q2) in [(p + 1, q), (p, q + 2), (p + q, q), (1, 1), (-1, 2)] {
            if p2 == 0 || q2 <= 0 || num_integer::Integer::gcd(&p2, &q2) != 1 {
                continue;
            }
            let expected = divide_by_linear_factor(&a, p2, q2);
            let got = l.divide_by_linear(p2, q2).map(|x| x.to_bigints());
            assert_eq!(got, expected, "round {round}: ({q2} x - {p2})");
        }
    }
}

#[test]
fn close_pairs_are_split_and_agree_with_the_reference() {
    let w = super::super::bench_instances::target_width();
    // Mignotte-type x^n - 2 (a x - 1)^2 with other parameters, and (x - a)(x - a - eps) g.
    for (n, a) in [(12usize, 7i64), (25, 10), (33, 3), (40, 13), (50, 10)] {
        let mut c = vec![BigInt::zero(); n + 1];
        c[n] += 1;
        c[2] -= 2 * a * a;
        c[1] += 4 * a;
        c[0] -= 2;
        // Both checked against Sturm (4 real roots for even n, 3 for odd n).
        let fast = both(&c, &w);
        assert_eq!(fast.len(), 4 - n % 2, "n {n}, a {a}");
    }
    for e in [20u32, 45, 70, 120] {
        let a = Rational::new(2, 7).expect("7");
        let eps = Rational::from(BigInt::one()) / Rational::from(BigInt::one() << e);
        let g = UPoly::from_i64_coeffs(&[5, -1, 0, 3, 0, 1]);
        let p = UPoly::from_roots(&[a.clone(), a + eps]) * g;
        let fast = both(&p.integer_coefficients(), &w);
        assert_eq!(fast.len(), 3, "eps 2^-{e}");
    }
}

#[test]
fn pair_splitter_verifies_its_point() {
    // x^2 - 2 (4 x - 1)^2 on the node (0, 1/2) at depth 1, ends negative... use the
    // Mignotte polynomial x^30 - 2 (10 x - 1)^2 on (1/16, 1/8): the split point has the
    // opposite sign and lies strictly inside.
    let p = super::super::bench_instances::mignotte(30);
    let s = PairSplitter::new(&p);
    let (x, delta) = s
        .split(&BigInt::from(1), 4, Sign::Negative)
        .expect("a pair");
    let xr = x.to_rational();
    assert!(xr > Rational::new(1, 16).expect("16") && xr < Rational::new(1, 8).expect("8"));
    assert_eq!(sign_at_rational(&p, &xr), Sign::Positive);
    let d = delta.expect("an estimate");
    assert!(d > 0.0 && d < 1e-10, "{d}");
    // x^2 + 1 shifted: (8x - 1)^2 + 1 has no real root; V may be 2 but no split point.
    let q = bigs(&[2, -16, 64]);
    let s = PairSplitter::new(&q);
    assert!(s.split(&BigInt::from(0), 2, Sign::Positive).is_none());
}

#[test]
fn random_polynomials_agree_with_the_reference() {
    let w = super::super::bench_instances::target_width();
    let mut rng = Rng::new(77);
    for n in [1usize, 2, 3, 7, 15, 31] {
        for _ in 0..4 {
            let c = random_poly(&mut rng, n);
            both(&c, &w);
        }
    }
    // Repeated roots (the square-free part), roots at 0 and +-1, huge and tiny coefficients.
    let cases = [
        product(&[(1, 0), (1, 1), (1, -1), (3, 1), (3, 1), (2, 1)], &[1]),
        product(&[(7, 3), (7, 3), (7, 3), (1, 5)], &[1, 1, 1]),
        product(&[(1, 1 << 40), (1 << 40, 1), (3, -(1 << 35))], &[1]),
        bigs(&[-(1 << 62), 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]),
        bigs(&[1, 0, 0, -(1 << 62)]),
    ];
    for c in &cases {
        both(c, &w);
    }
    for (family, degree, count) in super::super::bench_instances::COMPARISON {
        let c = family.polynomial(degree);
        let fast = real_roots_to_with(&c, &w, Options::FAST).expect("non-zero");
        assert_eq!(fast.len(), count);
        if degree <= 50 {
            check_refined_against_sturm(&c, &fast, &w);
        }
    }
}

/// One comparison instance through the fast path: the pinned count, width and order (one
/// test per instance, so each can be profiled alone: `valgrind --tool=callgrind
/// target/release/deps/exactcheck_exact-* --exact univariate::descartes::unit_tests::instance_wilkinson_20`).
fn comparison_instance(index: usize) {
    let (family, degree, count) = super::super::bench_instances::COMPARISON[index];
    let w = super::super::bench_instances::target_width();
    let roots = super::super::bench_instances::solve(&family.polynomial(degree));
    assert_eq!(roots.len(), count);
    assert!(roots.iter().all(|r| r.width() <= w));
    assert!(roots.windows(2).all(|p| p[0].hi < p[1].lo));
}

#[test]
fn instance_wilkinson_20() {
    comparison_instance(0);
}

#[test]
fn instance_wilkinson_40() {
    comparison_instance(1);
}

#[test]
fn instance_random_50() {
    comparison_instance(2);
}

#[test]
fn instance_random_100() {
    comparison_instance(3);
}

#[test]
fn instance_mignotte_20() {
    comparison_instance(4);
}

#[test]
fn instance_mignotte_40() {
    comparison_instance(5);
}

#[test]
fn refinement_brackets_roots_of_close_pairs() {
    // Roots 1/3 and 1/3 + 2^-40.
    let third = Rational::new(1, 3).expect("3");
    let p = UPoly::from_roots(&[
        Rational::new(1, 3).expect("3"),
        Rational::new(1, 3).expect("3")
            + Rational::from(BigInt::one()) / Rational::from(BigInt::one() << 40u32),
    ]);
    let w = super::super::bench_instances::target_width();
    let roots = p.isolate_real_roots_to(&w);
    assert_eq!(roots.len(), 2);
    assert!(roots[0].hi < roots[1].lo);
    for r in &roots {
        assert!(r.is_exact() || r.width() <= w);
    }
    assert!(roots[0].lo <= third && third <= roots[0].hi);
    assert!(roots[1].lo > third);
}

mod dyadic_horner {
    use super::*;
    use proptest::prelude::*;

    fn to_sign(s: i8) -> Sign {
        match s {
            -1 => Sign::Negative,
            0 => Sign::Zero,
            _ => Sign::Positive,
        }
    }

    /// The limb evaluation against the `BigInt` Horner schemes of the refinement and the
    /// close-pair splitter; numerators of 65 bits and more are refused.
    fn check(a: &[BigInt], num: BigInt, exp: u64) {
        let x = Dyadic { num, exp };
        let r = Refiner::new(a);
        let fast = DyadicHorner::new(a).eval(&x.num, exp, true);
        if x.num.bits() > 64 {
            assert!(fast.is_none());
            return;
        }
        let (v, d) = fast.expect("a word numerator");
        let (rv, rd) = r.eval_exact_bigint(&x);
        assert_eq!(v, rv, "value of {a:?} at {x:?}");
        assert_eq!(d, rd, "derivative of {a:?} at {x:?}");
        assert_eq!(v, PairSplitter::eval(a, &x));
        assert_eq!(r.eval_exact(&x), (rv.clone(), rd));
        assert_eq!(r.value_exact(&x), rv);
        if let Some(s) = DyadicHorner::new(a).sign_truncated(&x.num, exp) {
            assert_eq!(to_sign(s), sign_of(&rv), "{a:?} at {x:?}");
        }
        assert_eq!(r.sign_exact(&x), sign_of(&rv));
    }

    /// The truncated scheme next to the roots, where it matters: at the ends of the refined
    /// intervals of the comparison instances (within `2^-53` of a root) it decides, and
    /// correctly, for the word-sized random and Mignotte coefficients.
    #[test]
    fn truncated_signs_next_to_roots() {
        use super::super::super::bench_instances as inst;
        let mut decided = 0;
        for (family, degree, _) in inst::COMPARISON {
            let a = family.polynomial(degree);
            let q = square_free_integer(&a);
            let h = DyadicHorner::new(&q);
            for ri in inst::solve(&a).iter().filter(|ri| !ri.is_exact()) {
                for end in [&ri.lo, &ri.hi] {
                    let exp = end.denom().bits() - 1;
                    if end.denom() != BigInt::one() << exp {
                        continue;
                    }
                    let x = Dyadic {
                        num: end.numer(),
                        exp,
                    };
                    let exact = sign_of(&PairSplitter::eval(&q, &x));
                    if let Some(s) = h.sign_truncated(&x.num, exp) {
                        decided += 1;
                        assert_eq!(to_sign(s), exact, "{family:?} {degree} at {end}");
                    }
                }
            }
        }
        assert!(decided >= 16, "decided only {decided}");
    }

    #[test]
    fn dyadic_horner_edge_cases() {
        let polys = [
            bigs(&[5]),
            bigs(&[0]),
            bigs(&[-1, 0, 1]),
            bigs(&[i64::MIN, i64::MAX, i64::MIN, -1]),
            super::super::super::bench_instances::wilkinson(20),
            super::super::super::bench_instances::random(50),
            super::super::super::bench_instances::mignotte(40),
        ];
        let nums = [
            BigInt::zero(),
            BigInt::one(),
            -BigInt::one(),
            BigInt::from(u64::MAX),
            -BigInt::from(u64::MAX),
            BigInt::from(i64::MIN),
            BigInt::one() << 64u32,
            -(BigInt::one() << 64u32),
        ];
        for a in &polys {
            for num in &nums {
                for exp in [0u64, 1, 55, 63, 64, 65, 130] {
                    check(a, num.clone(), exp);
                }
            }
        }
    }

    proptest! {
        #[test]
        fn dyadic_horner_matches_bigint_horner(
            coeffs in prop::collection::vec((any::<i64>(), 0u32..200), 1..40),
            m in any::<u64>(),
            negative in any::<bool>(),
            extra in 0u32..3,
            exp in 0u64..140,
        ) {
            let a: Vec<BigInt> = coeffs.iter().map(|&(c, s)| BigInt::from(c) << s).collect();
            // Numerators of 1 to 66 bits, of either sign.
            let mut num = BigInt::from(m) << extra;
            if negative {
                num = -num;
            }
            check(&a, num, exp);
        }
    }
}

/// The modular gcd degree (fused reduction steps) against the gcd over `Q`, on products with a
/// planted common factor, for each of the three primes.
#[test]
fn gcd_degree_mod_p_matches_rational_gcd() {
    let mut rng = Rng::new(61);
    for round in 0..60 {
        let h = random_poly(&mut rng, round % 7);
        let f = random_poly(&mut rng, 1 + round % 11);
        let g = random_poly(&mut rng, 1 + round % 13);
        let (hu, fu, gu) = (upoly_of(&h), upoly_of(&f), upoly_of(&g));
        let (a, b) = (fu.mul_impl(&hu), gu.mul_impl(&hu));
        let expected = a.gcd(&b).degree();
        let ints = |u: &UPoly| -> Vec<BigInt> { u.coeffs().iter().map(|c| c.numer()).collect() };
        for &p in &PRIMES {
            let (am, bm): (Vec<u64>, Vec<u64>) = (
                ints(&a).iter().map(|c| big_mod(c, p)).collect(),
                ints(&b).iter().map(|c| big_mod(c, p)).collect(),
            );
            assert_eq!(
                gcd_degree_mod_p(am, bm, p),
                expected,
                "{a} and {b} modulo {p}"
            );
        }
        // 2^31 - 1 on 64-bit products, against the same gcd and against the u128 kernel.
        let (am, bm): (Vec<u64>, Vec<u64>) = (
            ints(&a).iter().map(|c| big_mod(c, P31)).collect(),
            ints(&b).iter().map(|c| big_mod(c, P31)).collect(),
        );
        assert_eq!(
            gcd_degree_mod_p31(am.clone(), bm.clone()),
            gcd_degree_mod_p(am, bm, P31),
            "{a} and {b} modulo 2^31 - 1"
        );
    }
}

/// The residues modulo `2^31 - 1` (limb folding, `fold31`) against num-bigint's remainder, on
/// integers of up to five limbs of both signs, limbs at the extremes included.
#[test]
fn big_mod_p31_matches_bigint_remainder() {
    let mut rng = Rng::new(31);
    let p = BigInt::from(P31);
    let specials = [
        0u64,
        1,
        P31 - 1,
        P31,
        P31 + 1,
        u64::MAX,
        u64::MAX - 1,
        1 << 63,
    ];
    for round in 0..400 {
        let len = 1 + round % 5;
        let limbs: Vec<u64> = (0..len)
            .map(|i| {
                if (round + i) % 3 == 0 {
                    specials[(round + 7 * i) % specials.len()]
                } else {
                    rng.next_u64()
                }
            })
            .collect();
        let mut x = BigInt::from(crate::bigint::biguint_from_limbs(&limbs));
        if round % 2 == 1 {
            x = -x;
        }
        let expected = ((&x % &p) + &p) % &p;
        assert_eq!(BigInt::from(big_mod(&x, P31)), expected, "{x}");
    }
    for x in [0u64, 1, P31 - 1, P31, (1 << 62) + 12345, (1 << 63) - 1] {
        assert_eq!(fold31(x), x % P31, "{x}");
    }
}

/// Square-free polynomials on which `2^31 - 1` fails (it divides the discriminant, or the
/// leading coefficient) are still proved by the other primes; non-square-free ones never are.
#[test]
fn modular_square_free_test_past_p31() {
    let p = P31 as i64;
    // x (x - p): the two roots meet modulo p.
    assert!(is_square_free_mod_p(&bigs(&[0, -p, 1])));
    // p x^2 - 1: the leading coefficient vanishes modulo p.
    assert!(is_square_free_mod_p(&bigs(&[-1, 0, p])));
    // (x - 1)^2 (x - p): repeated over Z.
    assert!(!is_square_free_mod_p(&bigs(&[-p, 1 + 2 * p, -2 - p, 1])));
    assert_eq!(square_free_integer(&bigs(&[0, -p, 1])), bigs(&[0, -p, 1]));
}

/// The refinement's window signs (truncated limb scheme, exact limb fallback) against Sturm on
/// word-sized coefficients, where they decide: random polynomials of higher degree (roots near
/// and outside the unit circle, so `|x| > 1` at some windows), Mignotte-like pairs
/// `x^n - 2 (a x - 1)^2`, and clusters `(x - 1/3)(x - 1/3 - 2^-e) g` refined to `2^-53` and
/// far below it.
#[test]
fn word_sized_windows_agree_with_sturm() {
    let w = super::super::bench_instances::target_width();
    let fine = Rational::from(BigInt::one()) / Rational::from(BigInt::one() << 200u32);
    for d in [33usize, 47, 60] {
        both(&super::super::bench_instances::random(d), &w);
    }
    for (n, a) in [(8i64, 3i64), (13, 7), (21, 12), (30, 10)] {
        let mut c = vec![BigInt::zero(); n as usize + 1];
        c[n as usize] += 1;
        c[2] -= 2 * a * a;
        c[1] += 4 * a;
        c[0] -= 2;
        both(&c, &w);
        both(&c, &fine);
    }
    let mut rng = Rng::new(1933);
    for e in [20u32, 40, 60] {
        let third = UPoly::from_i64_coeffs(&[-1, 3]);
        let shifted = UPoly::from_coeffs(vec![
            -(Rational::new(1, 3).unwrap()
                + Rational::from(BigInt::one()) / Rational::from(BigInt::one() << e)),
            Rational::ONE,
        ]);
        let g = upoly_of(&random_poly(&mut rng, 9));
        let c = third.mul_impl(&shifted).mul_impl(&g).integer_coefficients();
        both(&c, &w);
        both(&c, &fine);
    }
}

proptest::proptest! {
    /// The signs of `p(1)` and `p(-1)` (in `i128` while they fit, else on `BigInt`s) against
    /// the `BigInt` sums, with coefficients around the `i128` boundary and sums that cancel.
    #[test]
    fn signs_of_sums_match_bigint_sums(
        coeffs in proptest::collection::vec((proptest::prelude::any::<i64>(), 0u32..130), 1..30),
        cancel in proptest::prelude::any::<bool>(),
    ) {
        let mut p: Vec<BigInt> = coeffs.iter().map(|&(c, s)| BigInt::from(c) << s).collect();
        if cancel {
            // Make p(1) = 0 exactly.
            let s: BigInt = p.iter().sum();
            p.push(-s);
        }
        let plus: BigInt = p.iter().sum();
        let minus: BigInt = p
            .iter()
            .enumerate()
            .map(|(i, c)| if i % 2 == 1 { -c } else { c.clone() })
            .sum();
        proptest::prop_assert_eq!(sign_of_sum(&p), sign_of(&plus));
        proptest::prop_assert_eq!(sign_of_sum_at(&p, true), sign_of(&minus));
    }

    /// The reversed conversion to limbs equals the conversion of the reversed numbers.
    #[test]
    fn reversed_limbs_match_limbs_of_the_reversal(
        coeffs in proptest::collection::vec((proptest::prelude::any::<i64>(), 0u32..200), 1..20),
        extra in 0usize..70,
    ) {
        let p: Vec<BigInt> = coeffs.iter().map(|&(c, s)| BigInt::from(c) << s).collect();
        let rev: Vec<BigInt> = p.iter().rev().cloned().collect();
        proptest::prop_assert_eq!(
            Limbs::from_bigints_reversed_with_room(&p, extra).to_bigints(),
            Limbs::from_bigints_with_room(&rev, extra).to_bigints()
        );
    }
}
