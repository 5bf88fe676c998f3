//! Cosines, sines and tangents of rational multiples of pi as [`Algebraic`] numbers.
//!
//! `cos(2 pi a / n)` with `gcd(a, n) = 1` is a root of the minimal polynomial `Psi_n(2x)`, where
//! `Psi_n` is the minimal polynomial of `2 cos(2 pi / n)`: the cyclotomic polynomial
//! `Phi_n(z) = prod_{d | n} (z^d - 1)^mu(n/d)` is palindromic of even degree `phi(n)` (for
//! `n > 2`), so `z^(-phi(n)/2) Phi_n(z)` is a polynomial in `y = z + 1/z`, rewritten with the
//! Dickson polynomials `z^k + z^-k = D_k(y)` (`D_0 = 2`, `D_1 = y`, `D_k = y D_(k-1) - D_(k-2)`).
//! Its roots `2 cos(2 pi k / n)`, `k` prime to `n` and `0 < k < n/2`, decrease with `k`, so the
//! root wanted is picked by its rank among the isolated roots, without any approximation of pi.
//! `Psi_n` is irreducible of degree `phi(n)/2` (the real subfield of the cyclotomic field), so
//! the result carries its minimal polynomial.
//!
//! `sin(pi p/q) = cos(pi (q - 2p) / (2q))`, and `tan(pi p/q)` is the signed square root of
//! `(1 - cos(2 pi p/q)) / (1 + cos(2 pi p/q))`, a Moebius image of a cosine.

use super::Algebraic;
use crate::univariate::UPoly;
use crate::Rational;
use exactcheck_core::limits::{self, LimitError};
use exactcheck_core::{Ring, Sign};
use num_integer::Integer;

/// The error of the trigonometric constructors.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TrigError {
    /// The denominator of the multiple of pi is zero.
    #[error("the multiple of pi has denominator 0")]
    ZeroDenominator,
    /// The tangent of an odd multiple of pi/2 does not exist.
    #[error("tan(pi {p}/{q}) is undefined: the angle is an odd multiple of pi/2")]
    TanUndefined {
        /// The numerator as given.
        p: i64,
        /// The denominator as given.
        q: i64,
    },
    /// The degree `phi(n)/2` of the value exceeds the `algebraic-degree` limit.
    #[error("{0}")]
    Limit(LimitError),
}

/// Euler's totient of `n >= 1` by trial division (`n` is small: see [`Algebraic::cos_pi`]).
fn totient(mut n: u64) -> u64 {
    let mut result = n;
    let mut p = 2;
    while p * p <= n {
        if n % p == 0 {
            while n % p == 0 {
                n /= p;
            }
            result -= result / p;
        }
        p += 1;
    }
    if n > 1 {
        result -= result / n;
    }
    result
}

/// The Moebius function of `n >= 1`.
fn moebius(mut n: u64) -> i32 {
    let mut mu = 1;
    let mut p = 2;
    while p * p <= n {
        if n % p == 0 {
            n /= p;
            if n % p == 0 {
                return 0;
            }
            mu = -mu;
        }
        p += 1;
    }
    if n > 1 {
        mu = -mu;
    }
    mu
}

/// `z^d - 1`.
fn z_pow_minus_one(d: usize) -> UPoly {
    let mut c = vec![Rational::ZERO; d + 1];
    c[0] = -Rational::ONE;
    c[d] = Rational::ONE;
    UPoly::from_coeffs(c)
}

/// The cyclotomic polynomial `Phi_n` (`n >= 1`).
pub fn cyclotomic(n: u64) -> UPoly {
    let (mut num, mut den) = (UPoly::one(), UPoly::one());
    for d in 1..=n {
        if n % d == 0 {
            match moebius(n / d) {
                1 => num = num.mul_ref(&z_pow_minus_one(d as usize)),
                -1 => den = den.mul_ref(&z_pow_minus_one(d as usize)),
                _ => {}
            }
        }
    }
    num.div_rem(&den).0
}

/// The minimal polynomial `Psi_n` of `2 cos(2 pi / n)`, `n >= 3`, from the palindromic
/// cyclotomic polynomial (module documentation).
pub fn real_cyclotomic(n: u64) -> UPoly {
    let phi = cyclotomic(n);
    let m = phi.degree() / 2;
    // Dickson polynomials D_0..D_m.
    let y = UPoly::x();
    let mut dickson = vec![UPoly::constant(Rational::from_integer(2)), y.clone()];
    while dickson.len() <= m {
        let k = dickson.len();
        let next = y.mul_ref(&dickson[k - 1]).sub_ref(&dickson[k - 2]);
        dickson.push(next);
    }
    let mut psi = UPoly::constant(phi.coeff(m));
    for (k, d) in dickson.iter().enumerate().take(m + 1).skip(1) {
        psi = psi.add_ref(&(d * &phi.coeff(m + k)));
    }
    psi
}

impl Algebraic {
    /// `cos(pi p / q)`, exactly, with its minimal polynomial (of degree `phi(n)/2` where `n` is
    /// the denominator of `p / (2q)` in lowest terms, for `n > 2`).
    ///
    /// ```
    /// use exactcheck_exact::algebraic::Algebraic;
    /// let c = Algebraic::cos_pi(1, 5).unwrap();
    /// assert_eq!(c.to_string(), "(1 + sqrt(5))/4");
    /// ```
    ///
    /// # Errors
    /// [`TrigError::ZeroDenominator`] for `q = 0`; [`TrigError::Limit`] when the degree would
    /// exceed the `algebraic-degree` limit.
    pub fn cos_pi(p: i64, q: i64) -> Result<Algebraic, TrigError> {
        Algebraic::cos_pi_wide(i128::from(p), i128::from(q))
    }

    /// [`Algebraic::cos_pi`] for arguments with `|q| < 2^100`.
    fn cos_pi_wide(p: i128, q: i128) -> Result<Algebraic, TrigError> {
        if q == 0 {
            return Err(TrigError::ZeroDenominator);
        }
        // p/q pi = 2 pi a/n with a/n = p/(2q) in lowest terms, n > 0.
        let (mut a, mut n) = (p, 2 * q);
        if n < 0 {
            a = -a;
            n = -n;
        }
        let g = a.gcd(&n);
        a /= g;
        n /= g;
        // phi(n) >= sqrt(n/2): refuse large n before factoring it.
        let max = limits::ALGEBRAIC_DEGREE.get().min(1 << 20);
        if n > i128::from(8 * (max + 1) * (max + 1) + 8) {
            return Err(TrigError::Limit(
                limits::ALGEBRAIC_DEGREE.exceeded(format!("more than {max}")),
            ));
        }
        let a = a.rem_euclid(n);
        let n = n as u64; // below 2^44 after the check above
        let mut a = a as u64;
        if 2 * a > n {
            a = n - a;
        }
        match n {
            1 => return Ok(Algebraic::one()),
            2 => return Ok(Algebraic::from_integer(-1)),
            _ => {}
        }
        let degree = totient(n) / 2;
        limits::ALGEBRAIC_DEGREE
            .check(degree)
            .map_err(TrigError::Limit)?;
        // Psi_n(2x): the roots cos(2 pi k/n), increasing as k decreases.
        let psi = real_cyclotomic(n);
        let two_x = UPoly::from_coeffs(vec![Rational::ZERO, Rational::from_integer(2)]);
        let f = psi.compose(&two_x).primitive_part();
        let roots = f.isolate_roots();
        let rank = (a + 1..n.div_ceil(2))
            .filter(|k| k.gcd(&n) == 1 && 2 * k < n)
            .count();
        let ri = roots[rank].clone();
        Ok(Algebraic::from_isolated(f, ri, &roots, true))
    }

    /// `sin(pi p / q) = cos(pi (q - 2p) / (2q))`, exactly.
    ///
    /// # Errors
    /// As [`Algebraic::cos_pi`].
    pub fn sin_pi(p: i64, q: i64) -> Result<Algebraic, TrigError> {
        if q == 0 {
            return Err(TrigError::ZeroDenominator);
        }
        let (p, q) = (i128::from(p), i128::from(q));
        Algebraic::cos_pi_wide(q - 2 * p, 2 * q)
    }

    /// `tan(pi p / q)`, exactly: `sign * sqrt((1 - c) / (1 + c))` with `c = cos(2 pi p / q)`
    /// and the sign of `sin * cos`.
    ///
    /// # Errors
    /// [`TrigError::TanUndefined`] at odd multiples of pi/2, otherwise as [`Algebraic::cos_pi`].
    pub fn tan_pi(p: i64, q: i64) -> Result<Algebraic, TrigError> {
        let cos = Algebraic::cos_pi(p, q)?;
        if cos.is_zero() {
            return Err(TrigError::TanUndefined { p, q });
        }
        let sin = Algebraic::sin_pi(p, q)?;
        let c2 = Algebraic::cos_pi_wide(2 * i128::from(p), i128::from(q))?;
        if c2 == Algebraic::from_integer(-1) {
            // Unreachable: cos(2x) = -1 means cos(x) = 0.
            return Err(TrigError::TanUndefined { p, q });
        }
        let one = Rational::ONE;
        let w = c2.mobius(&-one.clone(), &one, &one, &one);
        let t = w.sqrt().expect("tan^2 is not negative");
        Ok(match sin.sign() * cos.sign() {
            Sign::Negative => -t,
            _ => t,
        })
    }
}
