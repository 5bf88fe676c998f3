//! Unit tests of the Bernstein toolkit.

use super::*;
use crate::test_support::{ints, rational, Poly, Rng, Q};

const CASES: usize = 300;

fn qpoly(c: &[i64]) -> Bernstein<Q> {
    Bernstein::new(c.iter().map(|&x| Q::int(x)).collect())
}

fn fpoly(c: &[i64]) -> Bernstein<f64> {
    Bernstein::new(c.iter().map(|&x| x as f64).collect())
}

/// `sum_i c_i B_i^n(t)` summed directly, with the basis from its definition.
fn direct<T: Ring>(p: &Bernstein<T>, t: &T) -> T {
    let n = p.degree();
    let s = T::one() - t;
    let mut acc = T::zero();
    for (i, c) in p.coeffs().iter().enumerate() {
        let b = from_u64::<T>(binom(n, i)) * t.pow(i as u32) * s.pow((n - i) as u32);
        acc += b * c;
    }
    acc
}

/// `sum_k a_k t^k` by Horner's rule.
fn horner<T: Ring>(a: &[T], t: &T) -> T {
    a.iter().rev().fold(T::zero(), |acc, c| acc * t + c)
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

#[test]
fn empty_is_rejected() {
    assert_eq!(Bernstein::<Q>::try_new(vec![]), Err(ShapeError::Empty));
    assert_eq!(Bernstein::<Q>::from_power(&[]), Err(ShapeError::Empty));
    assert_eq!(Bernstein::<Q>::from_scaled(&[]), Err(ShapeError::Empty));
    assert_eq!(
        ShapeError::Empty.to_string(),
        "empty list of coefficients or control points"
    );
}

#[test]
#[should_panic(expected = "at least one coefficient")]
fn new_panics_on_empty() {
    let _ = Bernstein::<f64>::new(vec![]);
}

#[test]
fn casteljau_matches_direct_sum_f64_dyadic() {
    // Small integers at t = k/16: every intermediate is a short dyadic, so `==` is exact.
    let mut rng = Rng::new(1);
    for _ in 0..CASES {
        let n = rng.below(7);
        let p = fpoly(&ints(&mut rng, n + 1, 8));
        let t = rng.int(-8, 24) as f64 / 16.0;
        assert_eq!(p.eval(&t), direct(&p, &t), "{p:?} at {t}");
    }
}

#[test]
fn casteljau_matches_direct_sum_exact() {
    let mut rng = Rng::new(2);
    for _ in 0..CASES {
        let n = rng.below(7);
        let p = qpoly(&ints(&mut rng, n + 1, 9));
        let t = rational(&mut rng, 7, 5);
        assert_eq!(p.eval(&t), direct(&p, &t));
    }
}

#[test]
fn endpoints_are_end_coefficients() {
    let p = Bernstein::new(vec![0.1, 0.7, -0.3, 0.9]);
    assert_eq!(p.eval(&0.0), 0.1);
    assert_eq!(p.eval(&1.0), 0.9);
}

#[test]
fn homogeneous_evaluation_clears_denominators() {
    let mut rng = Rng::new(3);
    for _ in 0..CASES {
        let n = rng.below(6);
        let p = qpoly(&ints(&mut rng, n + 1, 9));
        let (num, den) = (rng.int(-6, 6), rng.int(1, 6));
        let (qn, qd) = (Q::int(num), Q::int(den));
        let hom = p.eval_homogeneous(&(qd - qn), &qn);
        assert_eq!(hom, qd.pow(n as u32) * p.eval(&(qn / qd)));
    }
}

#[test]
fn elevation_preserves_values() {
    let mut rng = Rng::new(4);
    for _ in 0..CASES {
        let n = rng.below(6);
        let p = qpoly(&ints(&mut rng, n + 1, 9));
        let r = rng.below(4);
        let e = p.elevate();
        let er = p.elevate_by(r);
        assert_eq!(e.degree(), n + 1);
        assert_eq!(er.degree(), n + r);
        // The one-step elevation agrees with repeated single steps.
        let mut rep = p.clone();
        for _ in 0..r {
            rep = rep.elevate();
        }
        assert_eq!(er, rep);
        // The Ring versions are uniform multiples.
        assert_eq!(p.elevate_scaled(), e.scale(&Q::int(n as i64 + 1)));
        let factor: i64 = (n + 1..=n + r).map(|k| k as i64).product();
        assert_eq!(p.elevate_by_scaled(r), er.scale(&Q::int(factor)));
        for _ in 0..4 {
            let t = rational(&mut rng, 7, 5);
            assert_eq!(e.eval(&t), p.eval(&t));
            assert_eq!(er.eval(&t), p.eval(&t));
        }
    }
}

#[test]
fn elevation_f64_tolerance() {
    let mut rng = Rng::new(5);
    for _ in 0..CASES {
        let n = rng.below(7);
        let p = fpoly(&ints(&mut rng, n + 1, 100));
        let e = p.elevate_by(1 + rng.below(3));
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            assert!(close(e.eval(&t), p.eval(&t)));
        }
    }
}

#[test]
fn product_matches_pointwise_product() {
    let mut rng = Rng::new(6);
    for _ in 0..CASES {
        let (m, n) = (rng.below(5), rng.below(5));
        let a = qpoly(&ints(&mut rng, m + 1, 9));
        let b = qpoly(&ints(&mut rng, n + 1, 9));
        let ab = a.mul(&b);
        assert_eq!(ab.degree(), m + n);
        // The scaled product is the convolution of the scaled forms.
        let (sa, sb) = (a.to_scaled(), b.to_scaled());
        let mut conv = vec![Q::zero(); m + n + 1];
        for (i, x) in sa.iter().enumerate() {
            for (j, y) in sb.iter().enumerate() {
                conv[i + j] += *x * y;
            }
        }
        assert_eq!(a.mul_scaled(&b), conv);
        assert_eq!(Bernstein::from_scaled(&conv).unwrap(), ab);
        assert_eq!(ab.to_scaled(), conv);
        for _ in 0..4 {
            let t = rational(&mut rng, 5, 4);
            assert_eq!(ab.eval(&t), a.eval(&t) * b.eval(&t));
        }
    }
}

#[test]
fn product_f64_tolerance() {
    let mut rng = Rng::new(7);
    for _ in 0..CASES {
        let (m, n) = (rng.below(6), rng.below(6));
        let a = fpoly(&ints(&mut rng, m + 1, 50));
        let b = fpoly(&ints(&mut rng, n + 1, 50));
        let ab = a.mul(&b);
        for k in 0..=8 {
            let t = k as f64 / 8.0;
            assert!(close(ab.eval(&t), a.eval(&t) * b.eval(&t)));
        }
    }
}

#[test]
fn phi_is_the_product_rule() {
    assert_eq!(phi(1, 2, 0, 1), (2, 3));
    assert_eq!(phi(2, 2, 1, 1), (2, 3));
    assert_eq!(phi(3, 0, 2, 0), (1, 1));
    assert_eq!(phi(1, 1, 2, 0), (0, 1));
    assert_eq!(phi_value::<Q>(1, 2, 1, 2), Q::new(1, 1));
    assert_eq!(phi_value::<Q>(2, 2, 0, 2), Q::new(1, 6));
    assert_eq!(phi_value::<f64>(1, 2, 0, 0), 1.0);
    // Large degrees stay within u64 and reduce.
    let (num, den) = phi(33, 33, 16, 17);
    assert!(num <= den && den > 1);
    for m in 0..5 {
        for n in 0..5 {
            for i in 0..=m {
                for j in 0..=n {
                    let lhs = Bernstein::<Q>::basis(m, i).mul(&Bernstein::basis(n, j));
                    let rhs = Bernstein::basis(m + n, i + j).scale(&phi_value(m, n, i, j));
                    assert_eq!(lhs, rhs);
                    let mut scaled = vec![Q::zero(); m + n + 1];
                    scaled[i + j] = Q::int((binom(m, i) * binom(n, j)) as i64);
                    assert_eq!(
                        Bernstein::<Q>::basis(m, i).mul_scaled(&Bernstein::basis(n, j)),
                        scaled
                    );
                }
            }
            // Vandermonde: sum_{i+j=k} phi = 1, so the constant 1 times 1 is 1.
            for k in 0..=m + n {
                let s = (0..=k).fold(Q::zero(), |acc, i| acc + phi_value::<Q>(m, n, i, k - i));
                assert_eq!(s, Q::one());
            }
        }
    }
}

#[test]
fn derivative_commutes_with_power_form() {
    // Ring-only operations on small integers: exact in f64 as well.
    let mut rng = Rng::new(8);
    for _ in 0..CASES {
        let n = rng.below(8);
        let p = fpoly(&ints(&mut rng, n + 1, 20));
        let dp = p.derivative();
        assert_eq!(dp.degree(), n.saturating_sub(1));
        let a = p.to_power();
        let mut da: Vec<f64> = (1..a.len()).map(|k| k as f64 * a[k]).collect();
        if da.is_empty() {
            da.push(0.0);
        }
        assert_eq!(dp.to_power(), da);
    }
    assert!(Bernstein::new(vec![5.0]).derivative().is_zero());
}

#[test]
fn power_form_round_trip() {
    let mut rng = Rng::new(9);
    for _ in 0..CASES {
        let n = rng.below(8);
        let p = qpoly(&ints(&mut rng, n + 1, 20));
        let a = p.to_power();
        assert_eq!(Bernstein::from_power(&a).unwrap(), p);
        let t = rational(&mut rng, 9, 7);
        assert_eq!(horner(&a, &t), p.eval(&t));
        // And the other way round.
        let a2: Vec<Q> = ints(&mut rng, n + 1, 20).into_iter().map(Q::int).collect();
        assert_eq!(Bernstein::from_power(&a2).unwrap().to_power(), a2);
    }
    let mut rng = Rng::new(10);
    for _ in 0..CASES {
        let n = rng.below(8);
        let p = fpoly(&ints(&mut rng, n + 1, 20));
        let back = Bernstein::from_power(&p.to_power()).unwrap();
        for (x, y) in back.coeffs().iter().zip(p.coeffs()) {
            assert!(close(*x, *y));
        }
    }
}

#[test]
fn symbolic_evaluation_is_the_power_form() {
    // Over Z[x] (a ring, no division): de Casteljau at t = x expands p into the power basis.
    let mut rng = Rng::new(11);
    for _ in 0..CASES {
        let n = rng.below(8);
        let c = ints(&mut rng, n + 1, 20);
        let symbolic = Bernstein::new(c.iter().map(|&x| Poly::constant(x as i128)).collect());
        let expanded = symbolic.eval(&Poly::x());
        let mut power: Vec<i128> = qpoly(&c)
            .to_power()
            .iter()
            .map(|q| {
                assert_eq!(q.1, 1);
                q.0
            })
            .collect();
        while power.last() == Some(&0) {
            power.pop();
        }
        assert_eq!(expanded, Poly(power));
        // The Ring-only product and derivative run symbolically too.
        let sq = symbolic.mul_scaled(&symbolic);
        assert_eq!(sq.len(), 2 * n + 1);
        let _ = symbolic.derivative().to_power();
    }
}

#[test]
fn split_reparametrizes() {
    let mut rng = Rng::new(12);
    for _ in 0..CASES {
        let n = rng.below(7);
        let p = qpoly(&ints(&mut rng, n + 1, 9));
        let t = rational(&mut rng, 5, 5);
        let (l, r) = p.split(&t);
        assert_eq!(l.degree(), n);
        assert_eq!(r.degree(), n);
        let u = rational(&mut rng, 5, 4);
        assert_eq!(l.eval(&u), p.eval(&(t * u)));
        assert_eq!(r.eval(&u), p.eval(&(t + (Q::one() - t) * u)));
    }
}

#[test]
fn sums_and_sign_changes() {
    let a = qpoly(&[1, -2, 3]);
    let b = qpoly(&[0, 1, 1]);
    assert_eq!(a.checked_add(&b).unwrap(), qpoly(&[1, -1, 4]));
    assert_eq!(a.checked_sub(&b).unwrap(), qpoly(&[1, -3, 2]));
    assert_eq!(
        a.checked_add(&qpoly(&[1])),
        Err(ShapeError::LengthMismatch {
            expected: 3,
            found: 1
        })
    );
    assert_eq!(a.sign_changes(), 2);
    assert_eq!(qpoly(&[1, 0, 0, 2]).sign_changes(), 0);
    assert_eq!(qpoly(&[-1, 0, 0, 2]).sign_changes(), 1);
    assert_eq!(Bernstein::constant(Q::int(3), 2), qpoly(&[3, 3, 3]));
}

#[test]
fn integers_beyond_i64() {
    let big = u64::MAX - 4;
    let q: Q = from_u64(big);
    assert_eq!(q, Q::new(big as i128, 1));
    assert_eq!(scale_u64(&Q::int(2), big), Q::new(2 * big as i128, 1));
}
