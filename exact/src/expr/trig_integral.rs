//! Antiderivatives of trigonometric polynomials: polynomials in `t`, `cos(t)` and `sin(t)` whose
//! coefficients are free of `t`, the integrands of `integrate(E, t, a, b)`.
//!
//! Each product `cos(t)^p sin(t)^q` is written as a finite Fourier sum
//! `sum_k alpha_k cos(k t) + beta_k sin(k t)` with rational `alpha`, `beta`, `k <= p + q`, by the
//! binomial expansion of `((z + 1/z)/2)^p ((z - 1/z)/(2i))^q` with `z = e^{it}` ([`fourier`]).
//! Then `t^m cos(k t)` and `t^m sin(k t)` are integrated in closed form by repeated
//! integration by parts, `int t^m e^{ikt} dt = e^{ikt} sum_j (-1)^j m!/(m-j)! t^{m-j} / (ik)^{j+1}`
//! (real and imaginary part; `k = 0` gives `t^{m+1}/(m+1)`). The antiderivative is kept as
//! [`Antiderivative`]: for each wave `cos(k t)` or `sin(k t)` its coefficients by power of `t`,
//! which the caller evaluates at the bounds by building `cos(k b)`, `sin(k b)` as expression
//! trees and converting them like any other angle.
//!
//! Written here rather than taken from a computer-algebra crate: the formulas are a few lines
//! of exact rational arithmetic over the workspace's own polynomial type, and must honour its
//! limits (`degree`, `angle-multiple`, `constant-bits`) before any work is done.

use super::eval::check_constant;
use super::trig::{cos_name, sin_name, Trig};
use super::*;
use crate::poly::{Poly, Var, Vars};
use num_traits::{One, Zero};
use std::collections::BTreeMap;

/// A wave `cos(k t)` (`Cos`, `k = 0` is the constant 1) or `sin(k t)` (`Sin`, `k >= 1`).
pub(super) type Wave = (u32, Trig);

/// An antiderivative `sum_wave wave(t) * sum_j parts[j] t^j`, the parts free of `t`, `cos(t)`,
/// `sin(t)`; the waves in increasing order, each once.
pub(super) type Antiderivative<C> = Vec<(Wave, Vec<Poly<C>>)>;

/// Terms of a polynomial as their exponents and coefficients.
pub(super) type TermList<C> = Vec<(Vec<(Var, u32)>, C)>;

/// A Gaussian rational `re + i im`.
type Gauss = (Rational, Rational);

/// `(-i)^n`.
fn minus_i_pow(n: u32) -> Gauss {
    let (one, zero) = (Rational::one(), Rational::zero());
    match n % 4 {
        0 => (one, zero),
        1 => (zero, -one),
        2 => (-one, zero),
        _ => (zero, one),
    }
}

/// The binomial coefficients `C(n, 0..=n)`.
pub(super) fn binomials(n: u32) -> Vec<BigInt> {
    let mut row = vec![BigInt::one()];
    for k in 0..n {
        let next = row[k as usize].clone() * (n - k) / (k + 1);
        row.push(next);
    }
    row
}

/// `cos(t)^p sin(t)^q` as `sum_k alpha_k cos(k t) + beta_k sin(k t)`: the pairs
/// `(alpha_k, beta_k)` for `k = 0..=p+q` (`beta_0 = 0`).
pub(super) fn fourier(p: u32, q: u32) -> Vec<(Rational, Rational)> {
    let n = p + q;
    // r[n + e]: the coefficient of z^e in 2^{p+q} (z + 1/z)^p ((z - 1/z))^q / ... before i^{-q}.
    let mut r = vec![BigInt::zero(); 2 * n as usize + 1];
    let (bp, bq) = (binomials(p), binomials(q));
    for (a, ca) in bp.iter().enumerate() {
        for (b, cb) in bq.iter().enumerate() {
            let e = 2 * (a + b) as i64 - i64::from(n);
            let term = ca * cb;
            let slot = &mut r[(e + i64::from(n)) as usize];
            if (q as usize - b) % 2 == 0 {
                *slot += term;
            } else {
                *slot -= term;
            }
        }
    }
    // (2i)^{-q} 2^{-p} = 2^{-(p+q)} (-i)^q.
    let (rho, iota) = minus_i_pow(q);
    let scale = Rational::from(BigInt::one() << n);
    let mut out = vec![(Rational::zero(), Rational::zero()); n as usize + 1];
    for (index, c) in r.into_iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        let e = index as i64 - i64::from(n);
        let c = Rational::from(c) / scale.clone();
        let (re, im) = (c.clone() * rho.clone(), c * iota.clone());
        // Re(A z^e) = re cos(e t) - im sin(e t), sin(e t) = sign(e) sin(|e| t).
        let slot = &mut out[e.unsigned_abs() as usize];
        slot.0 += re;
        if e != 0 {
            let sign = if e > 0 {
                Rational::one()
            } else {
                -Rational::one()
            };
            slot.1 -= im * sign;
        }
    }
    out
}

/// `int t^m wave(k t) dt` as `(power, wave, coefficient)` terms, `k >= 1` (`wave` `Cos` or
/// `Sin`), each coefficient checked against `constant-bits` as it is built.
fn integrate_wave(
    m: u32,
    k: u32,
    which: Trig,
    pos: usize,
) -> Result<Vec<(u32, Wave, Rational)>, ExprError> {
    let mut out = Vec::new();
    // c_j = (-1)^j m!/(m-j)! (-i)^{j+1} / k^{j+1}: magnitude f_j = m!/(m-j)!/k^{j+1}.
    let mut f = Rational::one() / Rational::from(BigInt::from(k));
    for j in 0..=m {
        if j > 0 {
            f = f * Rational::from(BigInt::from(m - j + 1)) / Rational::from(BigInt::from(k));
        }
        check_constant(&f, pos)?;
        let f_signed = if j % 2 == 0 { f.clone() } else { -f.clone() };
        let (a, b) = minus_i_pow(j + 1);
        let (u, v) = (f_signed.clone() * a, f_signed * b);
        let power = m - j;
        // Re(c e^{ikt}) = u cos - v sin (for cos); Im(c e^{ikt}) = v cos + u sin (for sin).
        let (cos_part, sin_part) = match which {
            Trig::Sin => (v, u),
            _ => (u, -v),
        };
        if !cos_part.is_zero() {
            out.push((power, (k, Trig::Cos), cos_part));
        }
        if !sin_part.is_zero() {
            out.push((power, (k, Trig::Sin), sin_part));
        }
    }
    Ok(out)
}

/// The antiderivative in `t` of `p`, a polynomial in the variables `t`, `cos(t)`, `sin(t)` of
/// `vars` (any of them may be absent) with coefficients free of them. The `degree` limit
/// bounds `p`'s total degree plus one, the `angle-multiple` limit the largest `p + q` of a
/// product `cos(t)^p sin(t)^q`, both checked before anything is expanded.
pub(super) fn antiderivative<C: Coefficient>(
    call: &Expr,
    p: &Poly<C>,
    t: &str,
    vars: &Vars,
) -> Result<Antiderivative<C>, ExprError> {
    let pos = call.pos;
    let limit = |error| ExprError::Limit { pos, error };
    limits::DEGREE
        .check(p.total_degree().saturating_add(1))
        .map_err(limit)?;
    let tv = vars.get(t);
    let cv = vars.get(&cos_name(t));
    let sv = vars.get(&sin_name(t));
    let exponent = |m: &crate::poly::Monomial<'_>, v: Option<Var>| v.map_or(0, |v| m.exponent(v));
    let multiple = p
        .terms()
        .map(|(m, _)| u64::from(exponent(&m, cv)) + u64::from(exponent(&m, sv)))
        .max()
        .unwrap_or(0);
    limits::ANGLE_MULTIPLE.check(multiple).map_err(limit)?;
    let coefficient = |r: &Rational| {
        C::from_rational(r).ok_or_else(|| ExprError::Unrepresentable {
            pos,
            number: r.to_string(),
        })
    };
    let mut series: BTreeMap<(u32, u32), Vec<(Rational, Rational)>> = BTreeMap::new();
    // Keyed by (k, is sine) (`Trig` has no order).
    let mut pieces: BTreeMap<(u32, bool), BTreeMap<u32, TermList<C>>> = BTreeMap::new();
    for (m, c) in p.terms() {
        let (e_t, e_c, e_s) = (exponent(&m, tv), exponent(&m, cv), exponent(&m, sv));
        let rest: Vec<(Var, u32)> = m
            .exponents()
            .into_iter()
            .filter(|&(w, _)| Some(w) != tv && Some(w) != cv && Some(w) != sv)
            .collect();
        let waves = series
            .entry((e_c, e_s))
            .or_insert_with(|| fourier(e_c, e_s));
        for (k, (alpha, beta)) in waves.iter().enumerate() {
            let k = k as u32;
            let mut terms = Vec::new();
            if k == 0 {
                if !alpha.is_zero() {
                    let inv = Rational::from(BigInt::from(e_t) + 1u32);
                    terms.push((e_t + 1, (0, Trig::Cos), alpha.clone() / inv));
                }
            } else {
                for (amount, which) in [(alpha, Trig::Cos), (beta, Trig::Sin)] {
                    if amount.is_zero() {
                        continue;
                    }
                    for (power, wave, r) in integrate_wave(e_t, k, which, pos)? {
                        terms.push((power, wave, r * amount.clone()));
                    }
                }
            }
            for (power, wave, r) in terms {
                let value = c.mul_ref(&coefficient(&r)?);
                check_constant(&value, pos)?;
                pieces
                    .entry((wave.0, wave.1 == Trig::Sin))
                    .or_default()
                    .entry(power)
                    .or_default()
                    .push((rest.clone(), value));
            }
        }
    }
    Ok(pieces
        .into_iter()
        .map(|((k, is_sin), by_power)| {
            let wave = (k, if is_sin { Trig::Sin } else { Trig::Cos });
            let top = by_power.keys().next_back().copied().unwrap_or(0);
            let mut parts = vec![Poly::zero(); top as usize + 1];
            for (power, terms) in by_power {
                parts[power as usize] = Poly::from_terms(terms);
            }
            (wave, parts)
        })
        .filter(|(_, parts)| parts.iter().any(|p| !p.is_zero()))
        .collect())
}

/// The tree `wave(k * bound)` (`cos` or `sin`), at the bound's position, for the conversion
/// of an antiderivative's value at a bound; `None` for the constant wave (`k = 0`).
pub(super) fn wave_at(wave: Wave, bound: &Expr) -> Option<Expr> {
    let (k, which) = wave;
    if k == 0 {
        return None;
    }
    let angle = if k == 1 {
        bound.clone()
    } else {
        Expr {
            kind: ExprKind::Product(vec![
                (MulOp::Times, Expr::number(Rational::from(BigInt::from(k)))),
                (MulOp::Times, bound.clone()),
            ]),
            pos: bound.pos,
        }
    };
    Some(Expr {
        kind: ExprKind::Call(which.name().to_string(), vec![angle]),
        pos: bound.pos,
    })
}

#[cfg(test)]
mod tests {
    use super::super::trig::tests::decide_trig;
    use super::*;
    use crate::expr::parse_expr;
    use crate::prove::Decision;
    use crate::Radical;
    use proptest::prelude::*;

    fn proved(lhs: &str, rhs: &str) -> bool {
        matches!(decide_trig(lhs, rhs), Decision::Proved { .. })
    }

    #[test]
    fn definite_integrals_of_trigonometric_polynomials() {
        for (l, r) in [
            ("integrate(sin(x), x, 0, pi)", "2"),
            ("integrate(cos(t)^2, t, 0, 2*pi)", "pi"),
            ("integrate(t*sin(t), t, 0, pi)", "pi"),
            ("integrate(cos(t), t, 0, x)", "sin(x)"),
            ("integrate(sin(t)^3, t, 0, x)", "2/3 - cos(x) + cos(x)^3/3"),
            ("integrate(t^2*cos(t), t, 0, pi)", "-2*pi"),
            ("integrate(sin(3*t)*sin(2*t), t, 0, pi)", "0"),
            ("integrate(sin(3*t)^2, t, 0, pi)", "pi/2"),
            (
                "integrate(cos(2*t + pi/3), t, 0, x)",
                "sin(2*x + pi/3)/2 - sin(pi/3)/2",
            ),
            (
                "integrate(y*t*cos(t), t, a, b)",
                "y*(b*sin(b) + cos(b) - a*sin(a) - cos(a))",
            ),
            ("integrate(cos(t)/y, t, 0, pi/2)", "1/y"),
            ("integrate(t, t, 0, sin(t))", "sin(t)^2/2"),
            ("integrate(cos(t), t, 0, t)", "sin(t)"),
        ] {
            assert!(proved(l, r), "{l} = {r}: {:?}", decide_trig(l, r));
        }
        assert!(matches!(
            decide_trig("integrate(sin(x), x, 0, pi)", "1"),
            Decision::Fails { .. }
        ));
        assert!(matches!(
            decide_trig("integrate(sin(t)^2, t, 0, x)", "x/2"),
            Decision::Fails { .. }
        ));
    }

    #[test]
    fn refusals_name_the_bound_or_the_integrand() {
        let err = |text: &str| {
            let mut vars = Vars::new();
            parse_expr(text)
                .unwrap()
                .to_ratfun::<Radical>(&mut vars)
                .unwrap_err()
                .to_string()
        };
        for (text, says) in [
            (
                "integrate(sin(t), t, 0, x^2)",
                "the bound x^2, which is not an angle",
            ),
            (
                "integrate(sin(t), t, 0, sqrt(2))",
                "the bound sqrt(2), which is not an angle",
            ),
            (
                "integrate(tan(t), t, 0, x)",
                "divides by an expression in t",
            ),
            ("integrate(cos(t)^1001, t, 0, x)", "angle-multiple"),
        ] {
            let got = err(text);
            assert!(got.contains(says), "{text}: {got}");
        }
    }

    fn q(n: i64, d: i64) -> Rational {
        Rational::from(BigInt::from(n)) / Rational::from(BigInt::from(d))
    }

    #[test]
    fn power_reduction_formulas() {
        // cos^2 = 1/2 + cos(2t)/2; sin^2 = 1/2 - cos(2t)/2; cos sin = sin(2t)/2.
        let z = Rational::zero;
        assert_eq!(
            fourier(2, 0),
            vec![(q(1, 2), z()), (z(), z()), (q(1, 2), z())]
        );
        assert_eq!(
            fourier(0, 2),
            vec![(q(1, 2), z()), (z(), z()), (q(-1, 2), z())]
        );
        assert_eq!(fourier(1, 1), vec![(z(), z()), (z(), z()), (z(), q(1, 2))]);
        // sin^3 = 3/4 sin t - 1/4 sin 3t.
        assert_eq!(
            fourier(0, 3),
            vec![(z(), z()), (z(), q(3, 4)), (z(), z()), (z(), q(-1, 4))]
        );
        assert_eq!(fourier(0, 0), vec![(Rational::one(), z())]);
    }

    /// A random trigonometric polynomial in `t`: terms `c t^m cos(t)^p sin(t)^q`, some with a
    /// multiple angle `cos(k t)`.
    fn trig_poly() -> impl Strategy<Value = String> {
        let term = (
            -5i64..=5,
            1i64..=3,
            0u32..=2,
            0u32..=3,
            0u32..=3,
            1u32..=3,
            any::<bool>(),
        )
            .prop_map(|(n, d, m, p, q, k, multiple)| {
                let angle = if multiple {
                    format!("cos({k}*t)")
                } else {
                    "1".into()
                };
                format!("({n}/{d})*t^{m}*cos(t)^{p}*sin(t)^{q}*{angle}")
            });
        proptest::collection::vec(term, 1..=3).prop_map(|ts| ts.join(" + "))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// The fundamental theorem: `diff(integrate(P(t), t, 0, x), x) = P(x)`, checked through
        /// `diff`'s chain rule on the expanded antiderivative, and a shifted right side fails.
        #[test]
        fn derivative_of_the_integral_is_the_integrand(p in trig_poly()) {
            let px = p.replace('t', "x");
            let lhs = format!("diff(integrate({p}, t, 0, x), x)");
            prop_assert!(proved(&lhs, &px), "{} = {}: {:?}", lhs, px, decide_trig(&lhs, &px));
            let shifted = format!("{px} + cos(x)^2 + sin(x)^2");
            let fails = matches!(decide_trig(&lhs, &shifted), Decision::Fails { .. });
            prop_assert!(fails);
            // The integral from x to x is zero.
            let empty = format!("integrate({p}, t, x, x)");
            prop_assert!(proved(&empty, "0"));
        }
    }
}
