//! Unit tests of the polynomial module.

use super::reduce::divide;
use super::*;
use crate::Rational;

type P = Poly<Rational>;

fn q(n: i64) -> Rational {
    Rational::from_integer(n)
}

fn x(i: Var) -> P {
    P::var(i)
}

#[test]
fn constants_need_no_variables() {
    assert!(P::zero().is_zero());
    assert_eq!(P::one().len(), 1);
    assert_eq!(P::from_i64(0), P::zero());
    assert_eq!(P::from_i64(3) * P::from_i64(4), P::from_i64(12));
    assert!(P::one().is_one());
    assert!(P::from_i64(-2).is_constant());
}

#[test]
fn order_is_lex_with_higher_index_larger() {
    let p = x(0).pow(5) + x(1);
    assert_eq!(p.leading_term().unwrap().0.exponents(), vec![(1, 1)]);
    let p = x(0) * x(2) + x(1) * x(1) * x(0);
    assert_eq!(
        p.leading_term().unwrap().0.exponents(),
        vec![(0, 1), (2, 1)]
    );
    assert!(p.is_canonical());
}

#[test]
fn binomial_expansion() {
    let p = (x(0) + x(1)).pow(5);
    assert_eq!(p.len(), 6);
    assert_eq!(p.coefficient(&[(0, 2), (1, 3)]), q(10));
    assert_eq!(p.coefficient(&[(0, 7)]), q(0));
    assert!(p.is_canonical());
    let sq = (x(0) - x(1) + P::one()).square();
    assert_eq!(sq, (x(0) - x(1) + P::one()) * (x(0) - x(1) + P::one()));
}

#[test]
fn field_width_grows_on_demand() {
    let p = (x(0) + P::one()).pow(100);
    assert_eq!(p.degree_in(0), 100);
    let r = p.square();
    assert_eq!(r.degree_in(0), 200);
    assert!(r.is_canonical());
    assert_eq!(r.shape.bits, 16);
    let big = x(3).pow(70_000) * x(3).pow(70_000);
    assert_eq!(big.degree_in(3), 140_000);
    assert!(big.is_canonical());
    let huge = x(1).pow(u32::MAX / 2) * x(1).pow(u32::MAX / 2);
    assert_eq!(huge.degree_in(1), u32::MAX - 1);
    // Mixed widths add up correctly.
    let s = big.clone() + x(3) - big;
    assert_eq!(s, x(3));
}

#[test]
fn many_variables_span_words() {
    let p: P = (0..40).map(x).fold(P::zero(), |a, b| a + b);
    let sq = p.square();
    assert_eq!(sq.len(), 40 * 41 / 2);
    assert_eq!(sq.coefficient(&[(3, 1), (39, 1)]), q(2));
    assert_eq!(sq.coefficient(&[(17, 2)]), q(1));
    assert_eq!(sq.variables().len(), 40);
    assert_eq!(sq.total_degree(), 2);
    assert!(sq.is_canonical());
}

#[test]
fn unit_circle_reduction() {
    // c = x0, s = x1: s^2 -> 1 - c^2.
    let (c, s, t) = (x(0), x(1), x(2));
    let rel = unit_circle_relation::<Rational>(0, 1);
    let f = c.square() * t.pow(3) + s.square() * t.pow(3) - t.clone();
    assert_eq!(f.reduce(std::slice::from_ref(&rel)), t.pow(3) - t);
    let g = s.pow(5);
    let want = s.clone() * (P::one() - c.square()).pow(2);
    assert_eq!(g.reduce_unit_circle(&[(0, 1)]), want);
    // The general division agrees with the closed form.
    let h = s.pow(4) * c.clone() + s.pow(3) + P::from_i64(2);
    let shape = h.widened_shape(8, 2);
    let by_division = divide(&h, &[&rel], shape).ok().unwrap();
    assert_eq!(by_division, h.reduce(&[rel]));
}

#[test]
fn small_groebner_by_hand() {
    // x = x1 > y = x0. <x^2 - y, x y - 1> has the reduced lex basis {y^3 - 1, x - y^2}.
    let (y, xx) = (x(0), x(1));
    let g = groebner(&[xx.square() - y.clone(), xx.clone() * &y - P::one()]).unwrap();
    assert_eq!(g, vec![y.pow(3) - P::one(), xx.clone() - y.square()]);
    // Normal forms modulo the basis.
    assert_eq!(xx.pow(3).reduce(&g), P::one());
    assert!((xx.square() - y.clone()).reduce(&g).is_zero());
    assert_eq!(
        groebner(&[xx.clone(), P::one() + xx.clone()]).unwrap(),
        vec![P::one()]
    );
}

#[test]
fn substitute_and_eval() {
    let p = x(0).square() * x(1) + x(1) - P::from_i64(3);
    let r = p.substitute(0, &(x(1) + P::one()));
    assert_eq!(r, (x(1) + P::one()).square() * x(1) + x(1) - P::from_i64(3));
    let v = p.eval(&[q(2), q(5)], Clone::clone);
    assert_eq!(v, q(22));
}

#[test]
fn printing() {
    let vars = Vars::from_names(["c", "s", "x"]);
    let p = unit_circle_relation::<Rational>(0, 1);
    assert_eq!(p.display(&vars).to_string(), "s^2 + c^2 - 1");
    let h = Rational::new(-3, 4).unwrap();
    let p = P::monomial(h, &[(2, 2), (0, 1)]) - x(1) + P::constant(Rational::new(1, 2).unwrap());
    assert_eq!(p.display(&vars).to_string(), "-3/4*c*x^2 - s + 1/2");
    assert_eq!(P::zero().display(&vars).to_string(), "0");
    assert_eq!(format!("{:?}", x(4)), "_x4");
}

#[test]
fn eval_takes_high_powers_by_squaring() {
    // Old: the evaluation tabulated x, x^2, ..., x^d (for x^100000 at 1/2, 625 MB); now the
    // distinct exponents only, each from the previous one by binary powering of the gap.
    let half = Rational::new(1, 2).unwrap();
    let p = P::monomial(q(3), &[(0, 100_000)]);
    let want = Rational::from(num_rational::BigRational::new(
        num_bigint::BigInt::from(3),
        num_bigint::BigInt::from(1u32) << 100_000u32,
    ));
    assert_eq!(p.eval(std::slice::from_ref(&half), Clone::clone), want);
    // Agrees with the term-by-term value on a polynomial with gaps, repeats and several
    // variables (the balanced sum of the terms changes nothing).
    let p = x(0).pow(7) * x(1).pow(3) + x(0).pow(3) - x(1).pow(10).scale_i64(5) + x(0).pow(12)
        - P::from_i64(2);
    let (a, b) = (Rational::new(-3, 2).unwrap(), Rational::new(5, 7).unwrap());
    let naive = a.pow(7) * b.pow(3) + a.pow(3) - b.pow(10).scale_i64(5) + a.pow(12) - q(2);
    assert_eq!(p.eval(&[a, b], Clone::clone), naive);
    assert_eq!(P::zero().eval(&[half], Clone::clone), Rational::ZERO);
}

#[test]
fn capped_products_stop_past_the_cap() {
    // (a0 + ... + a9)(b0 + ... + b9) has 100 terms: within a cap of 100, refused at 99, in
    // the heap kernel, in the dense kernel and in the squaring kernel alike.
    let f = P::sum((0..10).map(x).collect());
    let g = P::sum((10..20).map(x).collect());
    assert_eq!(f.mul_capped(&g, |_| 100).unwrap(), f.clone() * g.clone());
    assert!(f.mul_capped(&g, |_| 99).is_none());
    let (u, v) = (x(0) + P::one(), x(0).pow(10) - P::one());
    assert_eq!(u.pow(9).mul_capped(&v, |_| 20).unwrap().len(), 20);
    assert!(u.pow(9).mul_capped(&v, |_| 19).is_none());
    let sq = f.square_capped(|_| 55).unwrap();
    assert_eq!(sq, f.clone() * f.clone());
    assert!(f.square_capped(|_| 54).is_none());
    // A term times a polynomial.
    assert!(x(3).mul_capped(&f, |_| 9).is_none());
    // try_mul and try_pow under the default limits agree with the operators.
    assert_eq!(f.try_mul(&g).unwrap(), f.clone() * g.clone());
    assert_eq!(u.try_pow(20).unwrap(), u.pow(20));
    assert_eq!(
        x(0).try_pow(u32::MAX).unwrap_err(),
        SizeError::Limit(exactcheck_core::limits::DEGREE.exceeded(u32::MAX.to_string()))
    );
}

#[test]
fn unit_term_times_polynomial_of_fewer_and_more_words() {
    // The term's coefficient is 1: the coefficients are copied and the monomials added, also
    // when the factors have different numbers of words (x20 needs three words at 8 bits).
    let half = Rational::new(1, 2).unwrap();
    let p = P::constant(half.clone()) * x(20) + P::constant(q(-3)) * x(1) * x(1) + P::from_i64(7);
    let expected = P::from_terms([
        (vec![(0, 1), (20, 1)], half.clone()),
        (vec![(0, 1), (1, 2)], q(-3)),
        (vec![(0, 1)], q(7)),
    ]);
    assert_eq!(x(0) * p.clone(), expected);
    assert_eq!(p.clone() * x(0), expected);
    let big = P::monomial(q(1), &[(30, 2)]);
    let product = &big * &p;
    assert!(product.is_canonical());
    assert_eq!(product.coefficients(), &[half, q(-3), q(7)][..]);
    assert_eq!(product.degree_in(30), 2);
}
