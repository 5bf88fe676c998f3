//! Elements of a number field `Q(theta)` as an ordered field: the scalar a computation runs in
//! when its constants leave the square-root field ([`crate::Radical`]) but lie in one field
//! `Q(theta)` built from them ([`super::primitive_element`]).
//!
//! # Representation
//! A [`FieldElement`] is a polynomial in `theta` of degree below the field's degree, reduced
//! modulo the minimal polynomial, together with the field (`Arc<NumberField>`, shared by every
//! element of one computation). A rational number needs no field: it carries `None` and a
//! constant polynomial, so `zero()`, `one()` and `from_i64` (which the ordered-field traits
//! create without a context) promote to any field when they meet an element that has one.
//! Combining elements of two different fields is a logic error and panics; one computation uses
//! one field.
//!
//! # Exactness
//! * Field operations are polynomial operations modulo the minimal polynomial; the inverse is
//!   the extended Euclidean algorithm against it ([`NumberField::inverse`]).
//! * Zero test: the reduced polynomial is zero. This is exact because the minimal polynomial is
//!   irreducible, so `p(theta) = 0` holds only for `p = 0 (mod m)`.
//! * Sign and order: a non-zero element is a non-zero real number, so evaluating its polynomial
//!   by interval arithmetic at ever narrower isolating intervals of `theta` separates it from 0
//!   in finitely many steps; no floating-point number is consulted.
//! * Square roots ([`FieldElement::sqrt_in_field`]): the non-negative root of the element's value
//!   as an [`Algebraic`] number, expressed in `theta` when it lies in the field — decided by the
//!   certified primitive-element step (the generator stays `theta` only when the root is a
//!   polynomial in it, with a linear gcd as certificate).
//! * Printing: the value as an [`Algebraic`] number where its display finds radicals, computed
//!   exactly by [`NumberField::value`]; otherwise a polynomial in the values the user wrote
//!   when the field has names ([`NumberField::with_names`]: `1/2 + 3/4*cos(pi/8)`,
//!   `sqrt(2)*cos(2*pi/7)`), and `Root(minimal polynomial, isolating interval)` only when no
//!   names exist. The element's minimal polynomial, found by linear algebra in the field,
//!   decides whether a radical form is possible at all, so a value printed in names is never
//!   isolated as a root.
//!
//! Hand-written for the same reason as the rest of this module: no crate of the dependency set
//! has number fields.

use super::arith::{iv_add, iv_mul, Iv};
use super::display::may_print_as_radical;
use super::{primitive_element, Algebraic, NumberField};
use crate::univariate::UPoly;
use crate::Rational;
use exactcheck_core::{Field, OrderedField, Ring, Sign, Sqrt, ZeroDivisor};
use std::cmp::Ordering;
use std::fmt;
use std::sync::Arc;

/// An element of a number field `Q(theta)`, or a rational number: see the module
/// documentation of `exact/src/algebraic/element.rs`.
#[derive(Clone)]
pub struct FieldElement {
    /// The field; `None` for a rational number (then `poly` is constant).
    field: Option<Arc<NumberField>>,
    /// The element as a polynomial in the generator, reduced modulo the minimal polynomial.
    poly: UPoly,
}

impl FieldElement {
    /// The rational number `q` (in no field).
    pub fn rational(q: Rational) -> FieldElement {
        FieldElement {
            field: None,
            poly: UPoly::constant(q),
        }
    }

    /// The element `p(theta)` of `field`, reduced; a constant `p` stays in the field too.
    pub fn new(field: &Arc<NumberField>, p: &UPoly) -> FieldElement {
        FieldElement {
            field: Some(Arc::clone(field)),
            poly: field.reduce(p),
        }
    }

    /// The generator `theta` of `field`.
    pub fn generator(field: &Arc<NumberField>) -> FieldElement {
        FieldElement::new(field, &UPoly::x())
    }

    /// The field, `None` for a rational number built without one.
    pub fn field(&self) -> Option<&Arc<NumberField>> {
        self.field.as_ref()
    }

    /// The element as a polynomial in the generator (degree below the field's degree).
    pub fn poly(&self) -> &UPoly {
        &self.poly
    }

    /// The value, if it is rational (the reduced polynomial is constant: exact, as the powers
    /// `1, theta, ..., theta^(n-1)` are linearly independent over Q).
    pub fn to_rational(&self) -> Option<Rational> {
        (self.poly.degree() == 0 || self.poly.is_zero()).then(|| self.poly.coeff(0))
    }

    /// Whether the value is rational.
    pub fn is_rational(&self) -> bool {
        self.to_rational().is_some()
    }

    /// The value as a real algebraic number, exactly.
    pub fn to_algebraic(&self) -> Algebraic {
        match (&self.field, self.to_rational()) {
            (_, Some(q)) => Algebraic::from_rational(q),
            (Some(f), None) => f.value(&self.poly),
            (None, None) => unreachable!("an element without a field is a constant"),
        }
    }

    /// An interval of width at most about `2^-bits` times the field's scale containing the
    /// value: the interval Horner evaluation of the polynomial at an enclosure of `theta` of
    /// width `2^-bits`.
    pub fn enclosure(&self, bits: u32) -> Iv {
        let x = match (&self.field, self.poly.degree()) {
            (Some(f), d) if d > 0 => f.generator().enclosure(bits),
            _ => {
                let c = self.poly.coeff(0);
                return (c.clone(), c);
            }
        };
        let mut acc: Iv = (Rational::ZERO, Rational::ZERO);
        for c in self.poly.coeffs().iter().rev() {
            acc = iv_add(&iv_mul(&acc, &x), &(c.clone(), c.clone()));
        }
        acc
    }

    /// The sign, exactly: see the module documentation of `exact/src/algebraic/element.rs`.
    pub fn signum(&self) -> Sign {
        if let Some(q) = self.to_rational() {
            return q.signum();
        }
        super::sign_by_refinement(16, |bits| self.enclosure(bits))
    }

    /// The nearest f64 (to within a relative `2^-60` before rounding).
    pub fn to_f64(&self) -> f64 {
        if let Some(q) = self.to_rational() {
            return q.to_f64();
        }
        let mut bits = 64;
        loop {
            let (lo, hi) = self.enclosure(bits);
            let width = hi.sub_ref(&lo);
            let scale = lo.abs().min(hi.abs());
            // Zero is excluded once lo and hi have one sign; then the width is checked
            // relative to the smaller end.
            if lo.signum() == hi.signum()
                && width.mul_ref(&Rational::from_integer(1i64 << 60)) <= scale
            {
                let mid = lo.add_ref(&hi) * Rational::new(1, 2).expect("2 != 0");
                return mid.to_f64();
            }
            bits *= 2;
        }
    }

    /// The field both operands live in (either one's, when the other is rational).
    ///
    /// # Panics
    /// When the operands belong to two different fields.
    fn common_field(&self, other: &FieldElement) -> Option<Arc<NumberField>> {
        match (&self.field, &other.field) {
            (Some(a), Some(b)) => {
                assert!(
                    Arc::ptr_eq(a, b)
                        || a.modulus() == b.modulus() && a.generator() == b.generator(),
                    "FieldElement: elements of two different number fields"
                );
                Some(Arc::clone(a))
            }
            (Some(a), None) | (None, Some(a)) => Some(Arc::clone(a)),
            (None, None) => None,
        }
    }

    fn add_impl(&self, rhs: &FieldElement) -> FieldElement {
        FieldElement {
            field: self.common_field(rhs),
            poly: self.poly.add_ref(&rhs.poly),
        }
    }

    fn sub_impl(&self, rhs: &FieldElement) -> FieldElement {
        FieldElement {
            field: self.common_field(rhs),
            poly: self.poly.sub_ref(&rhs.poly),
        }
    }

    fn mul_impl(&self, rhs: &FieldElement) -> FieldElement {
        let field = self.common_field(rhs);
        let poly = match &field {
            Some(f) => f.mul(&self.poly, &rhs.poly),
            None => self.poly.mul_ref(&rhs.poly),
        };
        FieldElement { field, poly }
    }

    fn neg_impl(&self) -> FieldElement {
        FieldElement {
            field: self.field.clone(),
            poly: self.poly.neg_ref(),
        }
    }

    /// The inverse, or [`ZeroDivisor`] for zero.
    pub fn inverse(&self) -> Result<FieldElement, ZeroDivisor> {
        if self.poly.is_zero() {
            return Err(ZeroDivisor);
        }
        let poly = match (&self.field, self.to_rational()) {
            (_, Some(q)) => UPoly::constant(q.recip()?),
            (Some(f), None) => f.inverse(&self.poly).ok_or(ZeroDivisor)?,
            (None, None) => unreachable!("an element without a field is a constant"),
        };
        Ok(FieldElement {
            field: self.field.clone(),
            poly,
        })
    }

    /// The non-negative square root when it lies in the element's field (or is rational);
    /// `None` for a negative element and for a root outside the field. A root whose membership
    /// cannot be certified (a minimal polynomial that factoring gave up on, a degree past the
    /// `algebraic-degree` limit) is reported as outside: `None`.
    pub fn sqrt_in_field(&self) -> Option<FieldElement> {
        match self.signum() {
            Sign::Negative => return None,
            Sign::Zero => return Some(self.clone()),
            Sign::Positive => {}
        }
        if let (Some(field), None) = (&self.field, self.to_rational()) {
            if not_a_square_mod_primes(field, &self.poly) {
                return None;
            }
        }
        let root = self.to_algebraic().sqrt()?;
        if let Some(q) = root.to_rational() {
            return Some(FieldElement {
                field: self.field.clone(),
                poly: UPoly::constant(q.clone()),
            });
        }
        let field = self.field.as_ref()?;
        if field.degree() % root.degree() != 0 {
            return None;
        }
        // The gcd over the field of the root's minimal polynomial g and y^2 - self: when it is
        // linear, y - h, then h is a common root in the field, so h = +root or -root, and as
        // -root is not a second common root (the gcd would have degree 2), h = root. When it has
        // degree 2 (it divides y^2 - self) and g(-y) is not +-g(y), -root is no root of g, so
        // y^2 - self has no linear factor over the field (it would be y - root, making the gcd
        // linear): the root is outside. Both are decided by one gcd of degree-2 polynomials
        // over the field, where the primitive element below needs a resultant of degree
        // deg(field) * deg(root), whose root isolation dominates for fields of degree 12.
        let g = root.checked_minimal_polynomial().ok()?;
        let y2 = [self.poly.neg_ref(), UPoly::zero(), UPoly::one()];
        if let Some(h) = field.common_root(&g, &y2) {
            return Some(FieldElement::new(field, &h));
        }
        let mirrored = g.compose(&UPoly::x().neg_ref());
        if mirrored != g && mirrored != g.neg_ref() {
            return None;
        }
        let pe = primitive_element(&[field.generator().clone(), root]).ok()?;
        // The generator is kept (coefficient 0 for the root) exactly when the root was
        // certified to be a polynomial in it.
        (pe.combination == [1, 0]).then(|| FieldElement::new(field, &pe.polys[1]))
    }
}

/// Whether a prime certifies that the non-zero element `k` of `field` is no square in it: a
/// prime `p` (odd, below [`SQUARE_TEST_PRIMES_BELOW`]) at which the minimal polynomial `m` has
/// `p`-integral coefficients and `deg m` distinct roots `t_j` modulo `p` (so `p` does not divide
/// its discriminant, and the primes of the field above `p` are the `deg m` primes of degree one
/// `theta -> t_j`), `k` has `p`-integral coefficients, every `k(t_j)` is non-zero (`k` is a unit
/// above `p`) and some `k(t_j)` is not a square modulo `p`. Were `k = h^2` in the field, `h`
/// would be a unit above `p`, hence a polynomial in `theta` with `p`-integral coefficients, and
/// `h(t_j)^2 = k(t_j)` modulo `p`. `false` when no such prime is found among the first few
/// that qualify: the question stays open, for the certified test of the caller.
fn not_a_square_mod_primes(field: &NumberField, k: &UPoly) -> bool {
    let m = field.modulus();
    let n = m.degree() as u64;
    let mut qualified = 0;
    for p in (3..SQUARE_TEST_PRIMES_BELOW).step_by(2) {
        if p <= n || !crate::modp::is_prime_u64(p) {
            continue;
        }
        let fp = crate::modp::PrimeField::new(p).expect("p is prime");
        let reduce = |q: &UPoly| -> Option<Vec<u64>> {
            q.coeffs()
                .iter()
                .map(|c| fp.from_rational(c).ok())
                .collect()
        };
        let (Some(mc), Some(kc)) = (reduce(m), reduce(k)) else {
            continue;
        };
        let at = |c: &[u64], t: u64| c.iter().rev().fold(0, |acc, &x| fp.add(fp.mul(acc, t), x));
        let roots: Vec<u64> = (0..p).filter(|&t| at(&mc, t) == 0).collect();
        if roots.len() as u64 != n {
            continue;
        }
        let values: Vec<u64> = roots.iter().map(|&t| at(&kc, t)).collect();
        if values.contains(&0) {
            continue;
        }
        if values.iter().any(|&v| fp.pow(v, (p - 1) / 2) != 1) {
            return true;
        }
        qualified += 1;
        if qualified == SQUARE_TEST_PRIMES {
            return false;
        }
    }
    false
}

/// The primes searched by [`not_a_square_mod_primes`] lie below this bound (a search of a few
/// million evaluations of the minimal polynomial at most).
const SQUARE_TEST_PRIMES_BELOW: u64 = 4000;

/// How many qualifying primes [`not_a_square_mod_primes`] tries before leaving the question open.
const SQUARE_TEST_PRIMES: usize = 8;

impl PartialEq for FieldElement {
    fn eq(&self, other: &FieldElement) -> bool {
        self.common_field(other);
        self.poly == other.poly
    }
}

impl PartialOrd for FieldElement {
    fn partial_cmp(&self, other: &FieldElement) -> Option<Ordering> {
        Some(match self.sub_impl(other).signum() {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        })
    }
}

impl Default for FieldElement {
    fn default() -> FieldElement {
        FieldElement::rational(Rational::ZERO)
    }
}

impl From<Rational> for FieldElement {
    fn from(q: Rational) -> FieldElement {
        FieldElement::rational(q)
    }
}

impl fmt::Display for FieldElement {
    /// The value as an [`Algebraic`] number: a rational, a radical where the display of
    /// [`Algebraic`] finds one, else a polynomial in the field's named numbers when it has
    /// them ([`NumberField::named`]: `1/2 + 3/4*cos(pi/8)`), else `Root(f, lo, hi) ≈ decimal`.
    ///
    /// Whether a radical form is possible is decided first, by the element's minimal polynomial
    /// when its degree is at most 4 ([`NumberField::minimal_polynomial_of`], linear algebra);
    /// the number itself (a characteristic polynomial and a root isolation) is built only when
    /// that polynomial may give a radical, or when no name is there to print in.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (Some(field), None) = (&self.field, self.to_rational()) else {
            return write!(f, "{}", self.poly.coeff(0));
        };
        if let Some(minimal) = field
            .minimal_polynomial_of(&self.poly, 4)
            .filter(may_print_as_radical)
        {
            if let Some(text) = field.value_with(&self.poly, &minimal).radical_form() {
                return f.write_str(&text);
            }
        }
        match field.named(&self.poly) {
            Some(text) => f.write_str(&text),
            None => write!(f, "{}", field.value(&self.poly)),
        }
    }
}

impl fmt::Debug for FieldElement {
    /// The polynomial in `theta` and the field's minimal polynomial.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.field {
            Some(field) => write!(f, "FieldElement({} mod {})", self.poly, field.modulus()),
            None => write!(f, "FieldElement({})", self.poly),
        }
    }
}

exactcheck_core::ring_ops! {
    impl[] FieldElement;
    Neg::neg: |a| a.neg_impl();
    Add::add, AddAssign::add_assign: |a, b| a.add_impl(b);
    Sub::sub, SubAssign::sub_assign: |a, b| a.sub_impl(b);
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_impl(b);
    Div::div, DivAssign::div_assign: |a, b| a.mul_impl(&b.inverse().expect("division of a number-field element by zero"));
}

ring_by_impls! {
    FieldElement;
    zero: FieldElement::rational(Rational::ZERO);
    one: FieldElement::rational(Rational::ONE);
    from_i64: |n| FieldElement::rational(Rational::from_integer(n));
    is_zero: |e| e.poly.is_zero();
}

impl Field for FieldElement {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        self.inverse()
    }
}

impl OrderedField for FieldElement {
    fn sign(&self) -> Sign {
        self.signum()
    }
}

impl Sqrt for FieldElement {
    /// [`FieldElement::sqrt_in_field`].
    fn sqrt(&self) -> Option<Self> {
        self.sqrt_in_field()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn alg(text: &str) -> Algebraic {
        text.parse().unwrap()
    }

    fn field(text: &str) -> Arc<NumberField> {
        Arc::new(NumberField::new(alg(text)).unwrap())
    }

    #[test]
    fn arithmetic_order_and_printing_in_a_quartic_field() {
        // theta = cos(pi/8) = sqrt(2 + sqrt 2)/2: theta^2 = (2 + sqrt 2)/4.
        let f = field("cos(pi/8)");
        let t = FieldElement::generator(&f);
        let four = FieldElement::from_i64(4);
        let s2 = t.square() * &four - FieldElement::from_i64(2);
        assert_eq!(s2.to_string(), "sqrt(2)");
        assert_eq!(s2.square(), FieldElement::from_i64(2));
        assert_eq!(t.to_string(), "sqrt(2 + sqrt(2))/2");
        assert!(t > FieldElement::from_i64(0) && t < FieldElement::one());
        assert_eq!(t.sign(), Sign::Positive);
        assert_eq!(t.neg_ref().sign(), Sign::Negative);
        let inv = t.inv().unwrap();
        assert!((inv.clone() * &t).is_one());
        assert!((inv.to_f64() - 1.0 / (std::f64::consts::PI / 8.0).cos()).abs() < 1e-15);
        assert_eq!(FieldElement::zero().inv(), Err(ZeroDivisor));
        // sqrt(2) has its square root in no quartic field containing only sqrt(2 + sqrt 2)...
        assert!(s2.sqrt_in_field().is_none());
        // ... while 2 + sqrt 2 = (2 theta)^2 has one, 2 theta.
        let x = FieldElement::from_i64(2) + &s2;
        assert_eq!(
            x.sqrt_in_field(),
            Some(t.clone() * FieldElement::from_i64(2))
        );
        assert_eq!(FieldElement::from_i64(-1).sqrt_in_field(), None);
        assert_eq!(
            FieldElement::from_i64(9).sqrt_in_field(),
            Some(FieldElement::from_i64(3))
        );
    }

    /// Square roots in the degree-12 field of cos(pi/8) and cos(2 pi/7): the prime test refutes
    /// non-squares, never a square, and the answers agree with the square roots of the values.
    #[test]
    fn square_roots_in_a_field_of_degree_twelve() {
        let pe = super::super::primitive_element(&[alg("cos(pi/8)"), alg("cos(2*pi/7)")]).unwrap();
        assert_eq!(pe.field.degree(), 12);
        let f = Arc::new(pe.field);
        let c8 = FieldElement::new(&f, &pe.polys[0]);
        let c7 = FieldElement::new(&f, &pe.polys[1]);
        // A sum of squares that is no square, as in plane_plane's unit direction.
        let six_minus = FieldElement::from_i64(6) - c8.clone() * FieldElement::from_i64(7);
        let k = FieldElement::from_i64(4) + six_minus.square() + c7.square();
        assert!(not_a_square_mod_primes(&f, &k.poly));
        assert_eq!(k.sqrt_in_field(), None);
        assert!(k.to_algebraic().sqrt().unwrap().degree() > 1);
        // 3 is no square (sqrt 3 is not in the field), 2 is (4 cos(pi/8)^2 - 2 = sqrt 2).
        let three = FieldElement::new(&f, &UPoly::constant(Rational::from_integer(3)));
        assert_eq!(three.sqrt_in_field(), None);
        let two = FieldElement::new(&f, &UPoly::constant(Rational::from_integer(2)));
        let s2 = c8.square() * FieldElement::from_i64(4) - FieldElement::from_i64(2);
        assert_eq!(two.sqrt_in_field(), Some(s2));
        // A square is never refuted, and its root is the positive one.
        let h = FieldElement::one() + &c8 - c7.clone() * FieldElement::from_i64(3);
        let h2 = h.square();
        assert!(!not_a_square_mod_primes(&f, &h2.poly));
        let root = h2.sqrt_in_field().expect("a square");
        assert_eq!(root.to_algebraic(), h2.to_algebraic().sqrt().unwrap());
        assert!(root == h || root == h.neg_ref());
    }

    #[test]
    fn a_cubic_field_prints_roots() {
        let f = field("cos(2*pi/7)");
        let t = FieldElement::generator(&f);
        let s = t.to_string();
        assert!(
            s.starts_with("Root(8*x^3 + 4*x^2 - 4*x - 1") || s.starts_with("Root("),
            "{s}"
        );
        assert!((t.to_f64() - (2.0 * std::f64::consts::PI / 7.0).cos()).abs() < 1e-15);
        assert!(format!("{t:?}").contains("mod"));
        // Rational results of field arithmetic are rational again: 2 cos(2pi/7) + 2 cos(4pi/7)
        // + 2 cos(6pi/7) = -1, with cos(4pi/7) = 2t^2 - 1 and cos(6pi/7) = 4t^3 - 3t.
        let two = FieldElement::from_i64(2);
        let c2 = two.clone() * t.square() - FieldElement::one();
        let c3 = FieldElement::from_i64(4) * t.pow(3) - FieldElement::from_i64(3) * &t;
        let sum = two.clone() * (t.clone() + &c2 + &c3);
        assert_eq!(sum.to_rational(), Some(Rational::from_integer(-1)));
        assert_eq!(sum.to_string(), "-1");
    }

    use proptest::prelude::*;

    /// A random element `a + b t + c t^2` of the cubic field `Q(cos(2 pi/7))` and the same
    /// number computed by [`Algebraic`] arithmetic (resultants), an independent path.
    fn both(f: &Arc<NumberField>, a: i64, b: i64, c: i64, d: i64) -> (FieldElement, Algebraic) {
        let q = |n: i64| Rational::new(n, d).unwrap();
        let p = UPoly::from_coeffs(vec![q(a), q(b), q(c)]);
        let t = f.generator().clone();
        let want = Algebraic::from_rational(q(a))
            + t.clone() * Algebraic::from_rational(q(b))
            + t.clone() * t * Algebraic::from_rational(q(c));
        (FieldElement::new(f, &p), want)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        #[test]
        fn field_arithmetic_and_order_agree_with_algebraic_numbers(
            a in -9i64..10, b in -9i64..10, c in -9i64..10, d in 1i64..6,
            e in -9i64..10, g in -9i64..10, h in -9i64..10, k in 1i64..6,
        ) {
            let f = field("cos(2*pi/7)");
            let (x, ax) = both(&f, a, b, c, d);
            let (y, ay) = both(&f, e, g, h, k);
            prop_assert_eq!(x.to_algebraic(), ax.clone());
            prop_assert_eq!((x.clone() + &y).to_algebraic(), ax.clone() + ay.clone());
            prop_assert_eq!((x.clone() * &y).to_algebraic(), ax.clone() * ay.clone());
            prop_assert_eq!(x.partial_cmp(&y), Some(ax.cmp(&ay)));
            prop_assert_eq!(x.sign(), ax.sign());
            prop_assert_eq!(x == y, ax == ay);
            if !y.is_zero() {
                prop_assert_eq!((x.clone() / &y).to_algebraic(), ax.clone() / ay.clone());
            }
            let (lo, hi) = x.enclosure(40);
            let v = x.to_f64();
            prop_assert!(lo.to_f64() <= v && v <= hi.to_f64());
        }
    }
}
