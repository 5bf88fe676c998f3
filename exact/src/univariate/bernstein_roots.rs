//! Real roots in `[0, 1]`: the Bernstein form of a [`UPoly`] on the unit interval, and two exact
//! isolation methods with one default, [`UPoly::unit_roots`].
//!
//! # The two methods
//! * [`UnitRootMethod::Sturm`]: bisection of `[0, 1]` driven by Sturm counts, as
//!   [`UPoly::isolate_roots`] does on the whole line. The number of distinct roots in the open
//!   interval `(a, b)` is `V(a) - V(b)`, minus one when `b` itself is a root (`V` ignores the
//!   zero at a root, so `V(a) - V(b)` counts `(a, b]`). Every count evaluates the whole Sturm
//!   chain, `O(n)` polynomials of degree up to `n`.
//! * [`UnitRootMethod::BernsteinDescartes`]: the square-free part (primitive remainder
//!   sequence, [`UPoly::square_free_part`]) in Bernstein form on `[0, 1]`, then Descartes' rule
//!   of signs on the Bernstein coefficients with de Casteljau subdivision at `1/2`
//!   ([`exactcheck_core::roots`], which documents the algorithm and its termination). One
//!   subdivision costs `O(n^2)` additions and halvings, and the sign count is free.
//!
//! Both return isolating intervals with the [`RootInterval`] contract (an exact root, or an open
//! interval holding exactly one root whose ends are not roots); a root is exact when a
//! bisection point or an end point hits it, not necessarily whenever it is rational (unlike
//! [`UPoly::isolate_roots`], which tests every interval for a rational root; refine with
//! [`UPoly::refine`] if needed). The default is the faster of the two as measured by the
//! criterion bench `benches/roots.rs` (table in docs/benchmarks.md): Sturm. Bernstein–Descartes over
//! `Rational` is faster on random polynomials with few roots in `[0, 1]` but up to 3x slower on
//! many clustered roots (degree 40), where the denominators of the halved de Casteljau
//! coefficients grow by `2^n` per level.
//!
//! # Conversions
//! [`UPoly::to_bernstein`] and [`UPoly::from_bernstein`] convert between the power basis and
//! the Bernstein basis on `[0, 1]` ([`Bernstein::from_power`], [`Bernstein::to_power`]).

use super::isolate::SquareFree;
use super::*;
use exactcheck_core::bernstein::Bernstein;
use exactcheck_core::roots::{unit_roots_square_free, IsolatedRoot, ZeroPolynomial};

/// The isolation method of [`UPoly::unit_roots_with`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UnitRootMethod {
    /// Bisection driven by Sturm sequences.
    Sturm,
    /// Descartes' rule of signs on Bernstein coefficients with de Casteljau subdivision.
    BernsteinDescartes,
}

impl UnitRootMethod {
    /// The default of [`UPoly::unit_roots`]: the faster method in `benches/roots.rs`.
    pub const DEFAULT: UnitRootMethod = UnitRootMethod::Sturm;
}

impl From<IsolatedRoot<Rational>> for RootInterval {
    fn from(r: IsolatedRoot<Rational>) -> RootInterval {
        match r {
            IsolatedRoot::Exact(x) => RootInterval::exact(x),
            IsolatedRoot::Between(lo, hi) => RootInterval { lo, hi },
        }
    }
}

impl From<RootInterval> for IsolatedRoot<Rational> {
    fn from(r: RootInterval) -> IsolatedRoot<Rational> {
        if r.is_exact() {
            IsolatedRoot::Exact(r.lo)
        } else {
            IsolatedRoot::Between(r.lo, r.hi)
        }
    }
}

impl UPoly {
    /// The Bernstein form on `[0, 1]` of degree `max(deg, 0)` (the zero polynomial is the
    /// constant 0 of degree 0).
    pub fn to_bernstein(&self) -> Bernstein<Rational> {
        if self.is_zero() {
            return Bernstein::new(vec![Rational::ZERO]);
        }
        Bernstein::from_power(&self.coeffs).expect("a non-zero polynomial has coefficients")
    }

    /// The polynomial with the Bernstein form `b` on `[0, 1]`.
    pub fn from_bernstein(b: &Bernstein<Rational>) -> UPoly {
        UPoly::from_coeffs(b.to_power())
    }

    /// The distinct real roots in the closed interval `[0, 1]`, increasing, isolated by the
    /// default method ([`UnitRootMethod::DEFAULT`]; see the module documentation).
    ///
    /// # Errors
    /// [`ZeroPolynomial`] for the zero polynomial (every `t` is a root).
    ///
    /// ```
    /// use exactcheck_exact::univariate::{RootInterval, UPoly};
    /// use exactcheck_exact::Rational;
    /// let r = |n, d| Rational::new(n, d).unwrap();
    /// let p = UPoly::from_roots(&[r(-1, 3), r(1, 2), r(1, 2), r(1, 1), r(3, 2)]);
    /// let roots = p.unit_roots().unwrap();
    /// assert_eq!(roots, vec![RootInterval::exact(r(1, 2)), RootInterval::exact(r(1, 1))]);
    /// ```
    pub fn unit_roots(&self) -> Result<Vec<RootInterval>, ZeroPolynomial> {
        self.unit_roots_with(UnitRootMethod::DEFAULT)
    }

    /// [`UPoly::unit_roots`] by the given method.
    ///
    /// # Errors
    /// [`ZeroPolynomial`] for the zero polynomial.
    pub fn unit_roots_with(
        &self,
        method: UnitRootMethod,
    ) -> Result<Vec<RootInterval>, ZeroPolynomial> {
        if self.is_zero() {
            return Err(ZeroPolynomial);
        }
        if self.is_constant() {
            return Ok(Vec::new());
        }
        Ok(match method {
            UnitRootMethod::Sturm => sturm_unit_roots(&SquareFree::new(self)),
            UnitRootMethod::BernsteinDescartes => {
                let sqf = self.square_free_part().primitive_part();
                unit_roots_square_free(&sqf.to_bernstein())
                    .into_iter()
                    .map(RootInterval::from)
                    .collect()
            }
        })
    }
}

/// Sturm bisection of `[0, 1]` for a non-constant square-free polynomial.
fn sturm_unit_roots(sf: &SquareFree) -> Vec<RootInterval> {
    let p = sf.poly();
    let (zero, one) = (Rational::ZERO, Rational::ONE);
    let is_root = |x: &Rational| p.sign_at(x) == Sign::Zero;
    // The number of roots in the open interval (a, b), from V(a), V(b).
    let open_count = |b: &Rational, va: usize, vb: usize| va - vb - usize::from(is_root(b));
    let mut out = Vec::new();
    if is_root(&zero) {
        out.push(RootInterval::exact(zero.clone()));
    }
    let (v0, v1) = (sf.var_at(&zero), sf.var_at(&one));
    let c = open_count(&one, v0, v1);
    let mut stack = vec![(zero, one.clone(), v0, v1, c)];
    while let Some((a, b, va, vb, count)) = stack.pop() {
        if count == 0 {
            continue;
        }
        if count == 1 && !is_root(&a) && !is_root(&b) {
            out.push(RootInterval { lo: a, hi: b });
            continue;
        }
        let m = midpoint(&a, &b);
        let vm = sf.var_at(&m);
        if is_root(&m) {
            out.push(RootInterval::exact(m.clone()));
        }
        let right_count = open_count(&b, vm, vb);
        let left_count = open_count(&m, va, vm);
        stack.push((m.clone(), b, vm, vb, right_count));
        stack.push((a, m, va, vm, left_count));
    }
    if is_root(&one) {
        out.push(RootInterval::exact(one));
    }
    out.sort_by(|x, y| x.lo.cmp(&y.lo).then_with(|| x.hi.cmp(&y.hi)));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Radical;
    use exactcheck_core::roots::{refine, unit_roots};
    use exactcheck_core::OrderedField;
    use proptest::prelude::*;

    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n, d).unwrap()
    }

    const METHODS: [UnitRootMethod; 2] =
        [UnitRootMethod::Sturm, UnitRootMethod::BernsteinDescartes];

    /// Whether the isolated root is `x` (equal when exact, strictly inside otherwise).
    fn holds(ri: &RootInterval, x: &Rational) -> bool {
        if ri.is_exact() {
            ri.lo == *x
        } else {
            ri.lo < *x && *x < ri.hi
        }
    }

    /// Checks `found` against the sorted distinct expected roots, one by one.
    fn check(p: &UPoly, found: &[RootInterval], expected: &[Rational]) {
        assert_eq!(found.len(), expected.len(), "{found:?} vs {expected:?}");
        for (ri, x) in found.iter().zip(expected) {
            assert!(holds(ri, x), "{ri:?} should hold {x}");
            if !ri.is_exact() {
                let s = p.square_free_part();
                assert_eq!(s.sign_at(&ri.lo) * s.sign_at(&ri.hi), Sign::Negative);
                assert_ne!(s.sign_at(&ri.lo), Sign::Zero);
            }
        }
    }

    #[test]
    fn bernstein_conversion_round_trips() {
        let p = UPoly::from_i64_coeffs(&[3, -1, 0, 7, -2]);
        let b = p.to_bernstein();
        assert_eq!(b.degree(), 4);
        assert_eq!(UPoly::from_bernstein(&b), p);
        for x in [r(0, 1), r(1, 3), r(1, 1), r(5, 7)] {
            assert_eq!(b.eval(&x), p.eval(&x));
        }
        assert_eq!(
            UPoly::zero().to_bernstein(),
            Bernstein::new(vec![Rational::ZERO])
        );
        assert_eq!(
            UPoly::from_bernstein(&Bernstein::constant(r(0, 1), 3)),
            UPoly::zero()
        );
    }

    #[test]
    fn equally_spaced_roots_degree_20_and_40() {
        for d in [20i64, 40] {
            let expected: Vec<Rational> = (1..=d).map(|k| r(k, d + 1)).collect();
            let p = UPoly::from_roots(&expected);
            for m in METHODS {
                check(&p, &p.unit_roots_with(m).unwrap(), &expected);
            }
        }
    }

    #[test]
    fn roots_outside_end_points_and_multiplicities() {
        // roots -1/100, 0, 1/3 (double), 1/2, 99/100, 1 (triple), 101/100, 2
        let all = [
            r(-1, 100),
            r(0, 1),
            r(1, 3),
            r(1, 3),
            r(1, 2),
            r(99, 100),
            r(1, 1),
            r(1, 1),
            r(1, 1),
            r(101, 100),
            r(2, 1),
        ];
        let p = UPoly::from_roots(&all);
        let expected = [r(0, 1), r(1, 3), r(1, 2), r(99, 100), r(1, 1)];
        for m in METHODS {
            let found = p.unit_roots_with(m).unwrap();
            check(&p, &found, &expected);
            let mult: Vec<u32> = found.iter().map(|ri| p.multiplicity(ri)).collect();
            assert_eq!(mult, vec![1, 2, 1, 1, 3]);
        }
        assert_eq!(p.unit_roots(), p.unit_roots_with(UnitRootMethod::DEFAULT));
    }

    #[test]
    fn irrational_roots_refine_through_upoly() {
        // t^2 - 1/2 and t^2 - t + 1/10: roots 1/sqrt 2 and (1 -+ sqrt(3/5)) / 2, all in (0, 1)
        let p = UPoly::from_coeffs(vec![r(-1, 2), r(0, 1), r(1, 1)])
            * UPoly::from_coeffs(vec![r(1, 10), r(-1, 1), r(1, 1)]);
        let s = 0.6f64.sqrt();
        let expected = [(1.0 - s) / 2.0, 0.5f64.sqrt(), (1.0 + s) / 2.0];
        for m in METHODS {
            let found = p.unit_roots_with(m).unwrap();
            assert_eq!(found.len(), 3, "{found:?}");
            for (ri, x) in found.iter().zip(expected) {
                assert!(!ri.is_exact());
                let fine = p.refine(ri, &r(1, 1_000_000));
                assert!(fine.width() <= r(1, 1_000_000));
                assert!((fine.to_f64() - x).abs() < 1e-5, "{fine:?} vs {x}");
            }
        }
    }

    #[test]
    fn zero_and_constant() {
        for m in METHODS {
            assert_eq!(UPoly::zero().unit_roots_with(m), Err(ZeroPolynomial));
            assert_eq!(UPoly::constant(r(-3, 1)).unit_roots_with(m), Ok(vec![]));
        }
    }

    fn rad(n: i64, d: i64) -> Radical {
        Radical::from_i64(n) / Radical::from_i64(d)
    }

    /// `prod (t - x)` in Bernstein form, over any field.
    fn bern_from_roots<T: OrderedField>(roots: &[T]) -> Bernstein<T> {
        roots.iter().fold(Bernstein::new(vec![T::one()]), |acc, x| {
            acc.mul(&Bernstein::new(vec![x.neg_ref(), T::one() - x]))
        })
    }

    #[test]
    fn radical_inverse_sqrt_two() {
        // t^2 - 1/2 has the root 1/sqrt 2 in (0, 1) (and -1/sqrt 2 outside).
        let p = Bernstein::from_power(&[rad(-1, 2), rad(0, 1), rad(1, 1)]).unwrap();
        let root = Radical::sqrt_of(2) / Radical::from_i64(2);
        let found = unit_roots(&p).unwrap();
        assert_eq!(found.len(), 1);
        assert!(found[0].lo() < &root && &root < found[0].hi(), "{found:?}");
        let fine = refine(&p, &found[0], &rad(1, 1000));
        assert!(fine.width() <= rad(1, 1000));
        assert!(fine.lo() < &root && &root < fine.hi());
    }

    #[test]
    fn radical_coefficients_with_rational_roots() {
        let s2 = Radical::sqrt_of(2);
        let s6 = Radical::sqrt_of(6);
        // (t - 1/2)(t - sqrt2/2)(t - sqrt6): V = 2 on [0, 1], the split point 1/2 is a root.
        let p = bern_from_roots(&[rad(1, 2), s2.clone() / rad(2, 1), s6.clone()]);
        assert!(p.coeffs().iter().any(|c| !c.is_rational()));
        let found = unit_roots(&p).unwrap();
        assert_eq!(found.len(), 2, "{found:?}");
        let sqrt2_half = s2 / rad(2, 1);
        assert!(found[0].lo() < &sqrt2_half || found[1].lo() < &sqrt2_half);
        assert!(found.contains(&IsolatedRoot::Exact(rad(1, 2))));
        // (t - 3/8)(t - sqrt6/4): 3/8 isolated in (0, 1/2), made exact by refinement.
        let p = bern_from_roots(&[rad(3, 8), s6.clone() / rad(4, 1)]);
        let found = unit_roots(&p).unwrap();
        assert_eq!(found.len(), 2, "{found:?}");
        assert_eq!(
            refine(&p, &found[0], &rad(1, 100)),
            IsolatedRoot::Exact(rad(3, 8))
        );
        let sqrt6_quarter = s6 / rad(4, 1);
        assert!(found[1].lo() < &sqrt6_quarter && &sqrt6_quarter < found[1].hi());
        // A double radical root is reported once with multiplicity 2.
        let p = bern_from_roots(&[sqrt6_quarter.clone(), sqrt6_quarter.clone(), rad(1, 5)]);
        let found = unit_roots(&p).unwrap();
        assert_eq!(found.len(), 2, "{found:?}");
        assert_eq!(exactcheck_core::roots::multiplicity(&p, &found[1]), 2);
        assert_eq!(exactcheck_core::roots::multiplicity(&p, &found[0]), 1);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Products of linear factors with rational roots in and out of [0, 1]: exactly the
        /// ones in [0, 1] are found, in order, by both methods, and the number agrees with
        /// Sturm's count.
        #[test]
        fn finds_exactly_the_roots_in_unit_interval(
            roots in proptest::collection::vec((-8i64..=20, 1i64..=12), 1..9)
        ) {
            let roots: Vec<Rational> = roots.iter().map(|&(n, d)| r(n, d)).collect();
            let p = UPoly::from_roots(&roots);
            let mut inside: Vec<Rational> = roots
                .iter()
                .filter(|x| **x >= Rational::ZERO && **x <= Rational::ONE)
                .cloned()
                .collect();
            inside.sort();
            inside.dedup();
            // Sturm's count of distinct roots in [0, 1] = (0, 1] plus the root at 0.
            let zero = Rational::ZERO;
            let sturm = p.count_roots(&zero, &Rational::ONE)
                + usize::from(p.sign_at(&zero) == Sign::Zero);
            prop_assert_eq!(sturm, inside.len());
            for m in METHODS {
                let found = p.unit_roots_with(m).unwrap();
                prop_assert_eq!(found.len(), inside.len());
                for (ri, x) in found.iter().zip(&inside) {
                    prop_assert!(holds(ri, x), "{:?} should hold {}", ri, x);
                }
            }
        }
    }
}
