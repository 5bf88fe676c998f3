//! [`ExactScalar`]: what the regression harness needs of an exact number type.
//!
//! The harness evaluates a formula twice on the same inputs: in `f64` and in an exact ordered
//! field. The exact side must take every finite double exactly (each is a dyadic rational) and
//! hand its results back as a `BigRational`, on which the error measures of [`crate::convert`]
//! are computed. Every [`RationalScalar`] of the exact crate is one.

use crate::convert::{f64_to_rational, rational_to_f64};
use exactcheck_exact::RationalScalar;

/// An exact ordered field that contains every finite double: every [`RationalScalar`] (the fast
/// `exactcheck_exact::Rational` and the baseline [`exactcheck_exact::PlainRational`]) is one.
///
/// # Laws
/// * `from_f64_exact(x)` is `Some` exactly for finite `x`, and
///   `from_f64_exact(x)?.to_big_rational()` equals `x` as a rational.
/// * `to_big_rational` is a field homomorphism on the values it is applied to: the harness
///   computes `a + b` in `Self` and compares `to_big_rational(a + b)` with float results.
pub trait ExactScalar: RationalScalar {
    /// The exact value of a finite double; `None` for NaN and infinities.
    fn from_f64_exact(x: f64) -> Option<Self>;

    /// The double nearest to the exact value (ties to even, overflow to `±inf`).
    fn to_f64_nearest(&self) -> f64 {
        rational_to_f64(&self.to_big_rational())
    }
}

impl<T: RationalScalar> ExactScalar for T {
    fn from_f64_exact(x: f64) -> Option<Self> {
        f64_to_rational(x).map(|q| T::from_big_rational(&q))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Ring;
    use exactcheck_exact::{PlainRational, Rational};

    fn round_trips<E: ExactScalar>() {
        for x in [0.0, -0.0, 1.0, -0.1, 1e-310, f64::MAX, f64::MIN_POSITIVE] {
            let e = E::from_f64_exact(x).expect("finite");
            assert_eq!(e.to_f64_nearest(), x);
            assert_eq!(Some(e.to_big_rational()), f64_to_rational(x));
        }
        assert!(E::from_f64_exact(f64::NAN).is_none());
        assert!(E::from_f64_exact(f64::INFINITY).is_none());
    }

    #[test]
    fn exact_scalars_round_trip() {
        round_trips::<PlainRational>();
        round_trips::<Rational>();
    }

    #[test]
    fn exact_arithmetic_on_converted_doubles() {
        // The doubles 0.1 + 0.2 sum exactly to 10808639105689191·2^-55, a tie between two
        // doubles; IEEE addition rounds it correctly (to even), so it matches the float sum,
        // while neither double equals the exact sum.
        let a = PlainRational::from_f64_exact(0.1).expect("finite");
        let b = PlainRational::from_f64_exact(0.2).expect("finite");
        let s = a.add_ref(&b);
        assert_eq!(s.to_f64_nearest(), 0.1 + 0.2);
        assert_ne!(Some(s.to_big_rational()), f64_to_rational(0.1 + 0.2));
        assert_ne!(Some(s.to_big_rational()), f64_to_rational(0.3));
    }
}
