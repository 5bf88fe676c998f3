//! The scalars the `solve` kinds compute in: [`Rational`], [`Radical`] and [`FieldElement`]
//! (exact; the last for problems whose values leave the square-root field, computed in one
//! number field `Q(theta)`) and `f64` (`--float`), behind one trait, [`Scalar`], with what the kinds need beyond a field: the
//! printed and approximate values, the exact decomposition used to find rational zeros exactly,
//! and root isolation in `[0, 1]`. The exact search for rational zeros ([`rational_zeros`],
//! [`unit_zeros`]) lives here too, because it is defined by that decomposition.
//!
//! The trait is the solve module's own (core stays free of number-type details); each method
//! has one implementation per scalar, so a kind is written once, generically, and runs in every
//! mode.

use exactcheck_core::roots::{self, IsolatedRoot, ZeroPolynomial};
use exactcheck_core::{Bernstein, OrderedField, Sign};
use exactcheck_exact::algebraic::FieldElement;
use exactcheck_exact::univariate::{isolate_real_roots_in, UPoly};
use exactcheck_exact::{Radical, Radicand, Rational};

/// Default width of the isolating intervals of irrational zeros (poles, cusps) and of the
/// enclosure of an irrational smallest radius: `2^-50`, so `approx` is good to about `1e-15`.
pub(crate) const DEFAULT_WIDTH_LOG2: u32 = 50;

/// A scalar a `solve` kind computes in: exact ([`Rational`], [`Radical`]) or `f64`.
pub(crate) trait Scalar: OrderedField + std::fmt::Debug + std::fmt::Display {
    /// Whether zero tests and comparisons are exact (decides the depth cut-offs and the
    /// exact-only fields).
    const EXACT: bool;
    /// The nearest f64 (`-0` as `0`).
    fn approx(&self) -> f64;
    /// The rational number as a scalar.
    fn from_rational(q: &Rational) -> Self;
    /// The rational number `q` in the structure `self` lives in: [`Scalar::from_rational`],
    /// except in a number field, where `q` is taken as an element of `self`'s field (so that,
    /// say, its square root is looked for there).
    fn rational_like(&self, q: &Rational) -> Self {
        Self::from_rational(q)
    }
    /// The rational components `p_k` of `p = sum_k sqrt(k) p_k` (power coefficients), or `None`
    /// when the scalar has no exact decomposition (f64).
    fn rational_components(p: &[Self]) -> Option<Vec<Vec<Rational>>>;
    /// The nearest integer, where the scalar can find it exactly (rationals), for the
    /// refinement's grid index (`roots::refine_isolating_with`).
    fn round(&self) -> Option<Self>;
    /// The distinct roots of `p` in `[0, 1]`, by Bernstein subdivision (over `Q` by the real-root
    /// isolator of `exactcheck_exact::univariate`, which returns every rational root exactly;
    /// subdivision finds exactly only the dyadic ones).
    ///
    /// # Errors
    /// [`ZeroPolynomial`] when `p` is identically zero.
    fn unit_roots(p: &Bernstein<Self>) -> Result<Vec<IsolatedRoot<Self>>, ZeroPolynomial> {
        roots::unit_roots(p)
    }
}

/// The nearest integer to a rational (halves round up).
fn round_rational(x: &Rational) -> Rational {
    let y = x.clone() + Rational::new(1, 2).expect("2 != 0");
    Rational::from(num_integer::Integer::div_floor(&y.numer(), &y.denom()))
}

impl Scalar for Rational {
    const EXACT: bool = true;
    fn approx(&self) -> f64 {
        self.to_f64() + 0.0
    }
    fn from_rational(q: &Rational) -> Self {
        q.clone()
    }
    fn rational_components(p: &[Self]) -> Option<Vec<Vec<Rational>>> {
        Some(vec![p.to_vec()])
    }
    fn round(&self) -> Option<Self> {
        Some(round_rational(self))
    }
    fn unit_roots(p: &Bernstein<Self>) -> Result<Vec<IsolatedRoot<Self>>, ZeroPolynomial> {
        let u = UPoly::from_coeffs(p.to_power());
        if u.is_zero() {
            return Err(ZeroPolynomial);
        }
        Ok(isolate_real_roots_in(&u, &Rational::ZERO, &Rational::ONE)
            .into_iter()
            .map(|ri| match ri.exact_value() {
                Some(t) => IsolatedRoot::Exact(t.clone()),
                None => IsolatedRoot::Between(ri.lo, ri.hi),
            })
            .collect())
    }
}

impl Scalar for Radical {
    const EXACT: bool = true;
    fn approx(&self) -> f64 {
        self.to_f64() + 0.0
    }
    fn from_rational(q: &Rational) -> Self {
        Radical::from(q)
    }
    fn rational_components(p: &[Self]) -> Option<Vec<Vec<Rational>>> {
        let mut parts: Vec<(Radicand, Vec<Rational>)> = Vec::new();
        for (i, c) in p.iter().enumerate() {
            for (radicand, q) in c.terms() {
                let slot = match parts.iter().position(|(r, _)| r == radicand) {
                    Some(k) => k,
                    None => {
                        parts.push((radicand.clone(), vec![Rational::ZERO; p.len()]));
                        parts.len() - 1
                    }
                };
                parts[slot].1[i] = q.clone();
            }
        }
        Some(parts.into_iter().map(|(_, v)| v).collect())
    }
    fn round(&self) -> Option<Self> {
        self.to_rational()
            .map(|q| Radical::from(&round_rational(&q)))
    }
}

/// Elements of the problem's number field `Q(theta)` of degree `n`. The decomposition is the
/// power basis `1, theta, ..., theta^(n-1)`, a basis of the field over `Q`: `p = sum_k theta^k
/// p_k(t)` with rational `p_k`, so a rational `t0` is a zero of `p` iff it is a zero of every
/// `p_k`. Roots in `[0, 1]` are isolated by the Bernstein subdivision of the trait's default
/// (`exactcheck_core::roots::unit_roots`), which needs only exact signs: the field decides
/// them exactly (interval evaluation at `theta`, zero by the reduced polynomial), so every
/// isolating interval holds exactly one root, as for [`Radical`].
impl Scalar for FieldElement {
    const EXACT: bool = true;
    fn approx(&self) -> f64 {
        self.to_f64() + 0.0
    }
    fn from_rational(q: &Rational) -> Self {
        FieldElement::rational(q.clone())
    }
    fn rational_like(&self, q: &Rational) -> Self {
        match self.field() {
            Some(f) => FieldElement::new(f, &UPoly::constant(q.clone())),
            None => FieldElement::rational(q.clone()),
        }
    }
    fn rational_components(p: &[Self]) -> Option<Vec<Vec<Rational>>> {
        let n = p.iter().map(|c| c.poly().degree() + 1).max().unwrap_or(1);
        Some(
            (0..n)
                .map(|k| p.iter().map(|c| c.poly().coeff(k)).collect())
                .collect(),
        )
    }
    fn round(&self) -> Option<Self> {
        self.to_rational()
            .map(|q| FieldElement::rational(round_rational(&q)))
    }
}

impl Scalar for f64 {
    const EXACT: bool = false;
    fn approx(&self) -> f64 {
        self + 0.0
    }
    fn from_rational(q: &Rational) -> Self {
        q.to_f64()
    }
    fn rational_components(_: &[Self]) -> Option<Vec<Vec<Rational>>> {
        None
    }
    fn round(&self) -> Option<Self> {
        None
    }
}

/// The rational zeros in `[0, 1]` of `p` (power coefficients), exactly: writing the coefficients
/// in the basis `sqrt(k)` of the radical field, `p = sum_k sqrt(k) p_k(t)` with rational `p_k`, a
/// rational `t0` is a zero of `p` iff it is a common zero of all `p_k`, i.e. a zero of the
/// rational polynomial `G = gcd_k p_k`, whose rational zeros in `[0, 1]` the real-root isolator
/// (`isolate_real_roots_in`) returns exactly. Empty for `f64` (no exact decomposition). Used by
/// `ruled_plane` (exact poles) and `ph_offset` (exact cusps and critical points of the radius).
pub(crate) fn rational_zeros<T: Scalar>(p: &[T]) -> Vec<T> {
    let Some(parts) = T::rational_components(p) else {
        return Vec::new();
    };
    let mut g = UPoly::zero();
    for part in parts {
        g = g.gcd(&UPoly::from_coeffs(part));
    }
    isolate_real_roots_in(&g, &Rational::ZERO, &Rational::ONE)
        .into_iter()
        .filter_map(|ri| ri.exact_value().map(T::from_rational))
        .collect()
}

/// The distinct zeros in `[0, 1]` of `p` (not identically zero), increasing, rational ones
/// exact ([`rational_zeros`]), irrational ones refined to width `<= width` by bisection.
pub(crate) fn unit_zeros<T: Scalar>(p: &Bernstein<T>, width: &T) -> Vec<IsolatedRoot<T>> {
    let found = roots::unit_roots(p).expect("unit_zeros: the caller passes a non-zero polynomial");
    let rational = rational_zeros::<T>(&p.to_power());
    let refiner = roots::Refiner::new(p);
    found
        .into_iter()
        .map(|z| match &z {
            IsolatedRoot::Between(lo, hi) => match rational.iter().find(|r| {
                r.sub_ref(lo).sign() == Sign::Positive && hi.sub_ref(r).sign() == Sign::Positive
            }) {
                Some(r) => IsolatedRoot::Exact(r.clone()),
                None => refiner.refine_with(&z, width, T::round),
            },
            IsolatedRoot::Exact(_) => z,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Ring;

    fn q(s: &str) -> Rational {
        s.parse().expect("a rational")
    }

    #[test]
    fn rational_roots_are_exact_over_q_and_dyadic_ones_in_every_field() {
        // (t - 1/3)(t - 1/2): over Q both roots are exact; the subdivision of the other
        // scalars finds the dyadic 1/2 exactly and encloses 1/3.
        let p = UPoly::from_roots(&[q("1/3"), q("1/2")]).to_bernstein();
        let over_q = Rational::unit_roots(&p).expect("not zero");
        assert_eq!(
            over_q,
            vec![IsolatedRoot::Exact(q("1/3")), IsolatedRoot::Exact(q("1/2"))]
        );
        let lift = Bernstein::new(p.coeffs().iter().map(Radical::from).collect());
        let over_radicals = Radical::unit_roots(&lift).expect("not zero");
        assert_eq!(over_radicals.len(), 2);
        assert!(matches!(over_radicals[0], IsolatedRoot::Between(..)));
        assert_eq!(
            over_radicals[1],
            IsolatedRoot::Exact(Radical::from(q("1/2")))
        );
        let zero = Bernstein::new(vec![Rational::ZERO; 3]);
        assert_eq!(Rational::unit_roots(&zero), Err(ZeroPolynomial));
    }

    #[test]
    fn components_round_and_approx_agree_across_scalars() {
        let s2 = Radical::sqrt_of(2);
        // 1 + sqrt(2) t: components 1 + 0 t (rational part) and 0 + t (sqrt 2 part).
        let p = vec![Radical::one(), s2.clone()];
        let parts = Radical::rational_components(&p).expect("exact");
        assert_eq!(parts.len(), 2);
        assert!(parts.contains(&vec![Rational::ONE, Rational::ZERO]));
        assert!(parts.contains(&vec![Rational::ZERO, Rational::ONE]));
        assert_eq!(f64::rational_components(&[1.0, 2.0]), None);
        for (x, want) in [("5/2", "3"), ("-5/2", "-2"), ("7/3", "2")] {
            assert_eq!(Scalar::round(&q(x)), Some(q(want)));
            assert_eq!(
                Scalar::round(&Radical::from(q(x))),
                Some(Radical::from(q(want)))
            );
        }
        assert_eq!(Scalar::round(&s2), None);
        assert_eq!(<f64 as Scalar>::round(&2.5), None);
        assert_eq!(Scalar::approx(&q("-0")), 0.0);
        assert!(Scalar::approx(&q("-0")).is_sign_positive());
        assert!(Scalar::approx(&-0.0f64).is_sign_positive());
        assert_eq!(Scalar::approx(&s2), std::f64::consts::SQRT_2);
    }

    #[test]
    fn zeros_at_the_ends_and_at_bisection_points() {
        // t (t - 1/2)(t - 1)(t - 3/4)(t - 2)
        let p = UPoly::from_roots(&[q("0"), q("1/2"), q("1"), q("3/4"), q("2")]);
        let z = unit_zeros(&p.to_bernstein(), &q("1/1024"));
        let want: Vec<IsolatedRoot<Rational>> = ["0", "1/2", "3/4", "1"]
            .iter()
            .map(|s| IsolatedRoot::Exact(q(s)))
            .collect();
        assert_eq!(z, want);
    }

    #[test]
    fn radical_coefficients_with_a_rational_zero() {
        // sqrt(2) (t - 2/5) (t + 1): the zero 2/5 is exact.
        let s2 = Radical::sqrt_of(2);
        let p: Vec<Radical> = [q("-2/5"), q("3/5"), q("1")]
            .iter()
            .map(|c| Radical::from(c).mul_ref(&s2))
            .collect();
        let z = unit_zeros(
            &Bernstein::from_power(&p).expect("three coefficients"),
            &Radical::from(q("1/1000")),
        );
        assert_eq!(z, vec![IsolatedRoot::Exact(Radical::from(q("2/5")))]);
    }
}
