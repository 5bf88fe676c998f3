//! Rational points of the unit circle near a given angle: how exact code takes an angle that a
//! paper prints in radians (exact code cannot hold `cos 1`, but it can hold a rational point of
//! the unit circle a few millionths of a radian away, and say how far away it is).
//!
//! Every rational point of the unit circle other than `(-1, 0)` is
//! `(cos, sin) = ((1 - tau^2)/(1 + tau^2), 2 tau/(1 + tau^2))` for the rational
//! `tau = tan(theta/2)` ([`crate::cylinder_sphere::unit_circle_point`]). So the nearest rational
//! points with bounded height come from the best rational approximations of `tan(theta/2)`:
//! its continued-fraction convergents `h_k / k_k`. We take the last convergent whose denominator
//! does not exceed `max_den`; by the theory of continued fractions it is a best approximation of
//! the second kind (no fraction with a smaller or equal denominator is closer), and
//! `|tau - h/k| < 1/(k k')` with `k'` the next denominator. The returned deviation
//! `2 atan(h/k) - theta` is computed in f64 and is for reporting only.
//!
//! Hand-written: a dozen lines of continued fractions, generic over the scalar field.

use crate::cylinder_sphere::{unit_circle_point, Angle};
use crate::scalar::Field;

/// A rational point of the unit circle chosen near a printed angle.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalAngle<T> {
    /// The point `(cos, sin)`.
    pub angle: Angle<T>,
    /// Its parameter `tau = tan(angle/2)` as a fraction `num / den` (`den >= 1`).
    pub tau: (i64, i64),
    /// The parameter as a field element.
    pub tau_value: T,
    /// `2 atan(num/den) - theta` in radians, reduced modulo `2 pi` to `[-pi, pi]` (f64, for
    /// reporting).
    pub deviation: f64,
}

/// Why no rational angle was produced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RationalAngleError {
    /// The angle, or `tan(theta/2)`, is not a finite number (or too large for an `i64`
    /// numerator).
    OutOfRange(f64),
    /// `max_den` is below 1.
    BadDenominatorBound(i64),
}

impl core::fmt::Display for RationalAngleError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            RationalAngleError::OutOfRange(t) => {
                write!(f, "angle {t} has no finite rational parameter tan(theta/2)")
            }
            RationalAngleError::BadDenominatorBound(d) => {
                write!(f, "denominator bound {d} is below 1")
            }
        }
    }
}

impl std::error::Error for RationalAngleError {}

/// The last continued-fraction convergent `h/k` of `x` with `1 <= k <= max_den`.
///
/// # Errors
/// When `x` is not finite or `max_den < 1`.
pub fn best_convergent(x: f64, max_den: i64) -> Result<(i64, i64), RationalAngleError> {
    if !x.is_finite() {
        return Err(RationalAngleError::OutOfRange(x));
    }
    if max_den < 1 {
        return Err(RationalAngleError::BadDenominatorBound(max_den));
    }
    let (mut h0, mut h1, mut k0, mut k1) = (0i64, 1i64, 1i64, 0i64);
    let mut v = x;
    for _ in 0..64 {
        let a = v.floor();
        if a.abs() >= 9.0e18 {
            break;
        }
        let ai = a as i64;
        let next = ai
            .checked_mul(h1)
            .and_then(|p| p.checked_add(h0))
            .zip(ai.checked_mul(k1).and_then(|p| p.checked_add(k0)));
        let Some((h2, k2)) = next else { break };
        if k2 > max_den || k2 <= 0 {
            break;
        }
        (h0, h1, k0, k1) = (h1, h2, k1, k2);
        let frac = v - a;
        if frac.abs() < 1e-15 {
            break;
        }
        v = 1.0 / frac;
    }
    // The first convergent floor(x)/1 always fits (k = 1 <= max_den) unless floor(x) overflows.
    if k1 == 0 {
        return Err(RationalAngleError::OutOfRange(x));
    }
    Ok((h1, k1))
}

/// The rational point of the unit circle whose parameter `tau` is the best convergent of
/// `tan(theta/2)` with denominator at most `max_den` (see the module documentation).
///
/// Any finite angle is accepted (angles differing by `2 pi` give the same point; near `pi`
/// the parameter is large and the point approaches `(-1, 0)`, which has no parameter).
///
/// # Errors
/// When `theta` is not finite, `tan(theta/2)` does not fit an `i64` numerator, or
/// `max_den < 1`.
pub fn rational_angle<T: Field>(
    theta: f64,
    max_den: i64,
) -> Result<RationalAngle<T>, RationalAngleError> {
    if !theta.is_finite() {
        return Err(RationalAngleError::OutOfRange(theta));
    }
    let (h, k) = best_convergent((theta / 2.0).tan(), max_den)?;
    let tau_value = T::from_ratio(h, k).map_err(|_| RationalAngleError::BadDenominatorBound(k))?;
    // 1 + tau^2 > 0 for real tau: unit_circle_point cannot divide by zero here.
    let angle = unit_circle_point(&tau_value).expect("1 + tau^2 is positive for a real tau");
    let raw = 2.0 * (h as f64 / k as f64).atan() - theta;
    let tau = core::f64::consts::TAU;
    let deviation = raw - tau * (raw / tau).round();
    Ok(RationalAngle {
        angle,
        tau: (h, k),
        tau_value,
        deviation,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn convergents_of_known_numbers() {
        assert_eq!(best_convergent(core::f64::consts::PI, 1000), Ok((355, 113)));
        assert_eq!(best_convergent(core::f64::consts::PI, 100), Ok((22, 7)));
        assert_eq!(best_convergent(0.5, 10), Ok((1, 2)));
        assert_eq!(best_convergent(-0.5, 10), Ok((-1, 2)));
        assert_eq!(best_convergent(3.0, 1), Ok((3, 1)));
        assert!(matches!(
            best_convergent(f64::NAN, 10),
            Err(RationalAngleError::OutOfRange(_))
        ));
        assert_eq!(
            best_convergent(1.0, 0),
            Err(RationalAngleError::BadDenominatorBound(0))
        );
    }

    #[test]
    fn one_radian_is_approximated_on_the_circle() {
        // tan(1/2) = 0.5463...; the convergent with denominator <= 1000 is 59/108.
        let r = rational_angle::<f64>(1.0, 1000).unwrap();
        assert_eq!(r.tau, (59, 108));
        let (c, s) = (r.angle.cos, r.angle.sin);
        assert!((c * c + s * s - 1.0).abs() < 1e-15);
        assert!((c - 1f64.cos()).abs() < 1e-4 && (s - 1f64.sin()).abs() < 1e-4);
        assert!(r.deviation.abs() < 1e-4 && r.deviation != 0.0);
        let m = rational_angle::<f64>(-1.0, 1000).unwrap();
        assert_eq!(m.tau, (-59, 108));
    }

    #[test]
    fn rejects_angles_without_a_finite_parameter_and_wraps_the_rest() {
        assert!(matches!(
            rational_angle::<f64>(f64::NAN, 10),
            Err(RationalAngleError::OutOfRange(_))
        ));
        // Angles beyond pi wrap around: 3 pi / 2 is -pi / 2 (tau = -1).
        let r = rational_angle::<f64>(1.5 * core::f64::consts::PI, 10).unwrap();
        assert_eq!(r.tau, (-1, 1));
        assert!(r.deviation.abs() < 1e-12);
        assert!((r.angle.cos - 0.0).abs() < 1e-15 && (r.angle.sin + 1.0).abs() < 1e-15);
        assert!(matches!(
            rational_angle::<f64>(f64::INFINITY, 10),
            Err(RationalAngleError::OutOfRange(_))
        ));
        assert_eq!(
            rational_angle::<f64>(0.3, 0),
            Err(RationalAngleError::BadDenominatorBound(0))
        );
    }
}
