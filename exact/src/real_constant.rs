//! The exact value of a constant expression as printed in a paper: a number of the square-root
//! field ([`Radical`]), a real algebraic number ([`Algebraic`]: nested radicals, `cos(pi/8)`,
//! `cos(2 pi/7)`), or a rational function of pi with real algebraic coefficients (`pi`,
//! `2*pi/3`, `pi^2 - sqrt(2)`).
//!
//! Every comparison with a rational number is decided exactly: in the two number types by
//! their own exact order; for a value in pi by refining the certified enclosure of pi
//! ([`crate::pi::enclosure`]) and interval evaluation until the rational lies outside. That
//! refinement always ends for a value that is not constant in pi: pi is transcendental, so a
//! non-constant rational function of it with algebraic coefficients equals no rational number.
//! Functions of pi that are not rational functions (`sqrt(pi)`, `cos(1)`, `cos(pi^2)`) are
//! refused with the reason, never approximated.

use crate::expr::{Expr, ExprError, PI};
use crate::poly::{Poly, Vars};
use crate::ratfun::RatFun;
use crate::{Algebraic, Radical, Rational};
use exactcheck_core::limits;
use exactcheck_core::{Ring, Sign};
use std::cmp::Ordering;
use std::fmt;

/// The exact value of a constant expression: see the [module documentation](self).
#[derive(Clone, Debug)]
pub enum RealConstant {
    /// A number of the square-root field: rationals, `sqrt(2)/2`, `cos(pi/12)`.
    Radical(Radical),
    /// A real algebraic number outside the square-root field (or a value the field refused).
    Algebraic(Algebraic),
    /// `num(pi) / den(pi)`, coefficients from the constant term up, not both constant, `den`
    /// not the zero polynomial, no common factor of positive degree.
    Pi {
        /// The numerator's coefficients, constant term first.
        num: Vec<Algebraic>,
        /// The denominator's coefficients, constant term first.
        den: Vec<Algebraic>,
    },
}

/// Why a constant expression has no exact value here.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RealConstantError {
    /// The expression language's own error (a variable, a division by zero, a negative
    /// radicand, `tan(pi/2)`, a limit).
    #[error("{0}")]
    Expr(#[from] ExprError),
    /// pi enters other than through sums, products, quotients and integer powers.
    #[error(
        "{0}; a value may use pi only in sums, products, quotients and integer powers (a rational function of pi), and angles only as rational multiples of pi"
    )]
    NotRationalInPi(String),
    /// A comparison needed pi to more bits than the `pi-bits` limit allows.
    #[error("{0}")]
    Limit(#[from] limits::LimitError),
    /// A square root of a negative number: the value is not a real number.
    #[error(
        "sqrt({arg}) at {pos}: square root of a negative number {value}: the value is not real"
    )]
    NotReal {
        /// Byte position of the `sqrt`.
        pos: usize,
        /// The radicand as written.
        arg: String,
        /// The radicand's exact value (negative).
        value: String,
    },
}

/// The exact value of the radicand `arg` (as printed by the expression printer, so it reads
/// back) when it is negative, printed.
fn negative_radicand(arg: &str) -> Option<String> {
    let v: Algebraic = crate::expr::parse_expr(arg).ok()?.eval_constant().ok()?;
    (v.sign() == exactcheck_core::Sign::Negative).then(|| v.to_string())
}

impl RealConstant {
    /// The exact value of `e`: in the square-root field when it lies there, else as a real
    /// algebraic number, else as a rational function of pi.
    ///
    /// ```
    /// use exactcheck_exact::expr::parse_expr;
    /// use exactcheck_exact::real_constant::RealConstant;
    ///
    /// let v = |s: &str| RealConstant::from_expr(&parse_expr(s).unwrap()).unwrap().to_string();
    /// assert_eq!(v("tan(pi/12)"), "2 - sqrt(3)");
    /// assert_eq!(v("cos(pi/8)"), "sqrt(2 + sqrt(2))/2");
    /// assert_eq!(v("2*pi/3"), "2/3*pi");
    /// assert!(RealConstant::from_expr(&parse_expr("sqrt(pi)").unwrap()).is_err());
    /// ```
    ///
    /// # Errors
    /// [`RealConstantError::Expr`] for a variable or an undefined value,
    /// [`RealConstantError::NotRationalInPi`] for pi under a square root or in a
    /// non-rational angle.
    pub fn from_expr(e: &Expr) -> Result<RealConstant, RealConstantError> {
        let radical_error = match e.eval_constant::<Radical>() {
            Ok(r) => return Ok(RealConstant::Radical(r)),
            Err(err) => err,
        };
        match e.eval_constant::<Algebraic>() {
            Ok(a) => return Ok(RealConstant::Algebraic(a)),
            Err(ExprError::NotConstant { name, .. }) if name == PI => {}
            // A limit of the square-root field (`radicands`) is no reason to refuse a value
            // the algebraic numbers have; any other error is reported as the field found it.
            Err(err @ (ExprError::Limit { .. } | ExprError::CallLimit { .. })) => {
                return Err(err.into())
            }
            Err(ExprError::NoSqrt { pos, arg, .. }) => {
                if let Some(value) = negative_radicand(&arg) {
                    return Err(RealConstantError::NotReal { pos, arg, value });
                }
                return Err(radical_error.into());
            }
            Err(_) => return Err(radical_error.into()),
        }
        let mut names = Vec::new();
        e.collect_variables(&mut names);
        if let Some(other) = names.iter().find(|n| n.as_str() != PI) {
            // The error of the evaluator, which names the variable and its position.
            return Err(match e.eval_constant::<Algebraic>() {
                Err(err) => err.into(),
                Ok(_) => RealConstantError::NotRationalInPi(format!("variable {other}")),
            });
        }
        let mut vars = Vars::new();
        let f: RatFun<Algebraic> = e
            .to_ratfun(&mut vars)
            .map_err(|err| RealConstantError::NotRationalInPi(err.to_string()))?;
        let Some(pi) = vars.get(PI) else {
            return Err(RealConstantError::NotRationalInPi(
                "pi does not reduce to a constant".into(),
            ));
        };
        let coefficients = |p: &Poly<Algebraic>| {
            let mut c = vec![Algebraic::zero(); p.degree_in(pi) as usize + 1];
            for (m, a) in p.terms() {
                c[m.exponent(pi) as usize] = a.clone();
            }
            c
        };
        let (num, den) = (coefficients(f.numerator()), coefficients(f.denominator()));
        if num.len() == 1 && den.len() == 1 {
            // The pi cancelled (`pi/pi`): an algebraic number after all.
            let q = num[0].clone()
                * den[0]
                    .inverse()
                    .map_err(|_| ExprError::DivisionByZero { pos: e.pos })?;
            return Ok(RealConstant::Algebraic(q));
        }
        Ok(RealConstant::Pi { num, den })
    }

    /// Whether the value involves pi (and so is transcendental).
    pub fn is_transcendental(&self) -> bool {
        matches!(self, RealConstant::Pi { .. })
    }

    /// The rational number, if the value is one.
    pub fn to_rational(&self) -> Option<Rational> {
        match self {
            RealConstant::Radical(r) => r.to_rational(),
            RealConstant::Algebraic(a) => a.to_rational().cloned(),
            RealConstant::Pi { .. } => None,
        }
    }

    /// An interval `[lo, hi]` containing the value, of width at most `2^-bits` when the value
    /// is a number of the two exact types, and shrinking to the value as `bits` grows for a
    /// value in pi; `None` when a denominator's enclosure still contains zero at this precision.
    pub fn enclosure(&self, bits: u32) -> Option<(Rational, Rational)> {
        match self {
            RealConstant::Radical(r) => Some(radical_enclosure(r, bits)),
            RealConstant::Algebraic(a) => Some(a.enclosure(bits)),
            RealConstant::Pi { num, den } => {
                // Horner on intervals: the errors of the coefficients and of pi add up to
                // about (degree + |value|) 2^-bits each; the extra bits cover them.
                let extra = 8 + 2 * (num.len() + den.len()) as u32;
                let pi = crate::pi::enclosure(bits + extra);
                let n = horner(num, &pi, bits + extra);
                let d = horner(den, &pi, bits + extra);
                interval_div(&n, &d)
            }
        }
    }

    /// The exact comparison of the value with `q`.
    ///
    /// # Errors
    /// [`RealConstantError::Limit`] of `pi-bits` when a value in pi is so close to `q` that
    /// pi to the limit's number of bits does not separate them.
    pub fn cmp_rational(&self, q: &Rational) -> Result<Ordering, RealConstantError> {
        match self {
            RealConstant::Radical(r) => Ok(r
                .partial_cmp(&Radical::from(q.clone()))
                .expect("the square-root field is ordered")),
            RealConstant::Algebraic(a) => Ok(a.compare(&Algebraic::from_rational(q.clone()))),
            RealConstant::Pi { .. } => {
                let mut bits = 64u32;
                loop {
                    if let Some((lo, hi)) = self.enclosure(bits) {
                        if &hi < q {
                            return Ok(Ordering::Less);
                        }
                        if &lo > q {
                            return Ok(Ordering::Greater);
                        }
                    }
                    let max = limits::PI_BITS.get();
                    if u64::from(bits) >= max {
                        return Err(limits::PI_BITS.exceeded(format!("more than {max}")).into());
                    }
                    bits = u32::try_from((u64::from(bits) * 2).min(max)).unwrap_or(u32::MAX);
                }
            }
        }
    }

    /// `q - self`, exactly.
    pub fn rational_minus(&self, q: &Rational) -> RealConstant {
        match self {
            RealConstant::Radical(r) => RealConstant::Radical(Radical::from(q.clone()).sub_ref(r)),
            RealConstant::Algebraic(a) => {
                RealConstant::Algebraic(Algebraic::from_rational(q.clone()) - a.clone())
            }
            RealConstant::Pi { num, den } => {
                // (q den - num) / den.
                let qa = Algebraic::from_rational(q.clone());
                let len = num.len().max(den.len());
                let at =
                    |c: &[Algebraic], i: usize| c.get(i).cloned().unwrap_or_else(Algebraic::zero);
                let mut n: Vec<Algebraic> = (0..len)
                    .map(|i| qa.clone() * at(den, i) - at(num, i))
                    .collect();
                while n.len() > 1 && n.last().is_some_and(Ring::is_zero) {
                    n.pop();
                }
                RealConstant::Pi {
                    num: n,
                    den: den.clone(),
                }
            }
        }
    }

    /// `q * self`, exactly.
    pub fn scale(&self, q: &Rational) -> RealConstant {
        let qa = Algebraic::from_rational(q.clone());
        match self {
            RealConstant::Radical(r) => RealConstant::Radical(r.scale(q)),
            RealConstant::Algebraic(a) => RealConstant::Algebraic(qa * a.clone()),
            RealConstant::Pi { num, den } => RealConstant::Pi {
                num: num.iter().map(|c| qa.clone() * c.clone()).collect(),
                den: den.clone(),
            },
        }
    }

    /// The sign, exactly.
    ///
    /// # Errors
    /// As [`RealConstant::cmp_rational`].
    pub fn sign(&self) -> Result<Sign, RealConstantError> {
        Ok(match self.cmp_rational(&Rational::ZERO)? {
            Ordering::Less => Sign::Negative,
            Ordering::Equal => Sign::Zero,
            Ordering::Greater => Sign::Positive,
        })
    }
}

/// An enclosure of a number of the square-root field, of width at most `2^-bits`: each term
/// `c sqrt(m)` from the integer square root of `m 4^k`.
fn radical_enclosure(r: &Radical, bits: u32) -> (Rational, Rational) {
    if let Some(q) = r.to_rational() {
        return (q.clone(), q);
    }
    let terms = r.terms();
    let n = terms.len() as u64;
    // Each term within |c| 2^-k; k large enough that the sum is within 2^-bits / 2.
    let mut lo = Rational::ZERO;
    let mut hi = Rational::ZERO;
    for (m, c) in terms {
        let c_bits = c.numer().bits().saturating_sub(c.denom().bits()) + 1;
        let k = u64::from(bits) + 2 + c_bits + 64 - n.leading_zeros() as u64;
        let root = (m.to_biguint() << (2 * k)).sqrt();
        let below = Rational::from_dyadic(&num_bigint::BigInt::from(root.clone()), k);
        let above = Rational::from_dyadic(&num_bigint::BigInt::from(root + 1u32), k);
        let (a, b) = (c * &below, c * &above);
        if a <= b {
            lo = &lo + &a;
            hi = &hi + &b;
        } else {
            lo = &lo + &b;
            hi = &hi + &a;
        }
    }
    (lo, hi)
}

fn interval_add(a: &(Rational, Rational), b: &(Rational, Rational)) -> (Rational, Rational) {
    (&a.0 + &b.0, &a.1 + &b.1)
}

fn interval_mul(a: &(Rational, Rational), b: &(Rational, Rational)) -> (Rational, Rational) {
    let p = [&a.0 * &b.0, &a.0 * &b.1, &a.1 * &b.0, &a.1 * &b.1];
    let lo = p.iter().min().expect("four products").clone();
    let hi = p.iter().max().expect("four products").clone();
    (lo, hi)
}

/// `a / b`, `None` when `b` contains zero.
fn interval_div(
    a: &(Rational, Rational),
    b: &(Rational, Rational),
) -> Option<(Rational, Rational)> {
    if b.0 <= Rational::ZERO && b.1 >= Rational::ZERO {
        return None;
    }
    let inv = (b.1.recip().ok()?, b.0.recip().ok()?);
    Some(interval_mul(a, &inv))
}

/// The polynomial with coefficients `c` (constant first) at the interval `x`.
fn horner(c: &[Algebraic], x: &(Rational, Rational), bits: u32) -> (Rational, Rational) {
    let mut acc = (Rational::ZERO, Rational::ZERO);
    for a in c.iter().rev() {
        acc = interval_add(&interval_mul(&acc, x), &a.enclosure(bits));
    }
    acc
}

/// A coefficient as a factor: rationals bare (`2/3`), others parenthesised.
fn factor_text(a: &Algebraic) -> String {
    match a.to_rational() {
        Some(q) => q.to_string(),
        None => format!("({a})"),
    }
}

/// A polynomial in pi in the expression syntax, highest power first.
fn poly_text(c: &[Algebraic]) -> String {
    let mut out = String::new();
    for (k, a) in c.iter().enumerate().rev() {
        if a.is_zero() {
            continue;
        }
        let negative = a.sign() == Sign::Negative;
        let mag = if negative { -a.clone() } else { a.clone() };
        let power = match k {
            0 => String::new(),
            1 => "pi".to_string(),
            _ => format!("pi^{k}"),
        };
        let term = if k == 0 {
            factor_text(&mag)
        } else if mag.to_rational().is_some_and(|q| *q == Rational::ONE) {
            power
        } else {
            format!("{}*{power}", factor_text(&mag))
        };
        if out.is_empty() {
            out = if negative { format!("-{term}") } else { term };
        } else {
            out.push_str(if negative { " - " } else { " + " });
            out.push_str(&term);
        }
    }
    if out.is_empty() {
        "0".into()
    } else {
        out
    }
}

impl fmt::Display for RealConstant {
    /// In the expression syntax where possible (`2 - sqrt(3)`, `2/3*pi`, `(pi + 1)/(pi - 1)`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RealConstant::Radical(r) => write!(f, "{r}"),
            RealConstant::Algebraic(a) => write!(f, "{a}"),
            RealConstant::Pi { num, den } => {
                let n = poly_text(num);
                if den.len() == 1 && den[0].to_rational().is_some_and(|q| *q == Rational::ONE) {
                    return f.write_str(&n);
                }
                let d = poly_text(den);
                let wrap = |s: String, simple: bool| if simple { s } else { format!("({s})") };
                let n_simple = num.iter().filter(|a| !a.is_zero()).count() == 1;
                let d_simple = !d.contains([' ', '/', '*']);
                write!(f, "{}/{}", wrap(n, n_simple), wrap(d, d_simple))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr;

    fn value(s: &str) -> Result<RealConstant, RealConstantError> {
        RealConstant::from_expr(&parse_expr(s).unwrap())
    }

    fn q(s: &str) -> Rational {
        s.parse().unwrap()
    }

    #[test]
    fn each_value_lands_in_the_smallest_type() {
        assert!(matches!(
            value("cos(pi/4)").unwrap(),
            RealConstant::Radical(_)
        ));
        assert!(matches!(
            value("sqrt(3/4)").unwrap(),
            RealConstant::Radical(_)
        ));
        assert!(matches!(
            value("cos(pi/8)").unwrap(),
            RealConstant::Algebraic(_)
        ));
        assert!(matches!(
            value("sqrt(2 + sqrt(2))").unwrap(),
            RealConstant::Algebraic(_)
        ));
        assert!(matches!(
            value("cos(2*pi/7)").unwrap(),
            RealConstant::Algebraic(_)
        ));
        assert!(value("pi^2 - sqrt(2)").unwrap().is_transcendental());
        assert!(value("1/(pi - 3)").unwrap().is_transcendental());
        // pi cancels: an algebraic number after all.
        assert_eq!(value("2*pi/pi").unwrap().to_rational(), Some(q("2")));
        assert_eq!(value("cos(45°)").unwrap().to_string(), "sqrt(2)/2");
        assert_eq!(
            value("cos(22.5°)").unwrap().to_string(),
            "sqrt(2 + sqrt(2))/2"
        );
        assert_eq!(value("tan(pi/12)").unwrap().to_string(), "2 - sqrt(3)");
    }

    #[test]
    fn what_has_no_exact_value_is_refused() {
        for bad in [
            "sqrt(pi)",
            "cos(1)",
            "cos(pi^2)",
            "x + 1",
            "tan(pi/2)",
            "sqrt(1 - sqrt(2))",
            "1/(pi - pi)",
        ] {
            assert!(value(bad).is_err(), "{bad}");
        }
        let e = value("tan(3*pi/2)").unwrap_err().to_string();
        assert!(e.contains("tan(3*pi/2) is undefined"), "{e}");
    }

    #[test]
    fn comparisons_with_rationals_are_exact() {
        let pi = value("pi").unwrap();
        assert_eq!(pi.cmp_rational(&q("355/113")).unwrap(), Ordering::Less);
        assert_eq!(
            pi.cmp_rational(&q("103993/33102")).unwrap(),
            Ordering::Greater
        );
        let x = value("2*pi/3 - 2").unwrap();
        assert_eq!(x.cmp_rational(&q("0.0943951")).unwrap(), Ordering::Greater);
        assert_eq!(x.cmp_rational(&q("0.0943952")).unwrap(), Ordering::Less);
        // 1/(pi - 3) = 7.0625133...
        let y = value("1/(pi - 3)").unwrap();
        assert_eq!(y.cmp_rational(&q("7.0625133")).unwrap(), Ordering::Greater);
        assert_eq!(y.cmp_rational(&q("7.0625134")).unwrap(), Ordering::Less);
        // Exact equality in the algebraic numbers.
        let c = value("cos(pi/3)").unwrap();
        assert_eq!(c.cmp_rational(&q("1/2")).unwrap(), Ordering::Equal);
        let d = value("cos(pi/8)^2 - sqrt(2)/4").unwrap();
        assert_eq!(d.cmp_rational(&q("1/2")).unwrap(), Ordering::Equal);
        // q - x and q x.
        let r = pi.rational_minus(&q("3"));
        assert_eq!(r.sign().unwrap(), Sign::Negative);
        assert_eq!(pi.scale(&q("-1")).sign().unwrap(), Sign::Negative);
    }

    proptest::proptest! {
        /// The table of the square-root field and the algebraic numbers agree on every multiple
        /// of pi/12, and the enclosures contain the value.
        #[test]
        fn field_and_algebraic_trig_agree(p in -30i64..30, which in 0usize..3) {
            let f = ["cos", "sin", "tan"][which];
            let text = format!("{f}({p}*pi/12)");
            let e = parse_expr(&text).unwrap();
            let r = e.eval_constant::<Radical>();
            let a = e.eval_constant::<Algebraic>();
            proptest::prop_assert_eq!(r.is_ok(), a.is_ok(), "{}", text);
            if let (Ok(r), Ok(a)) = (r, a) {
                let ra: Algebraic = r.to_string().parse().unwrap();
                proptest::prop_assert!(ra == a, "{}: {} vs {}", text, r, a);
                let (lo, hi) = RealConstant::Radical(r.clone()).enclosure(30).unwrap();
                proptest::prop_assert!(lo <= hi);
                let v = RealConstant::Algebraic(a);
                proptest::prop_assert!(v.cmp_rational(&lo).unwrap() != Ordering::Less);
                proptest::prop_assert!(v.cmp_rational(&hi).unwrap() != Ordering::Greater);
            }
        }

        /// `n pi / d` against the fraction `m / k`: the verdict of the enclosure agrees with
        /// the sign of `n k pi - m d` decided by a rational bracket of pi.
        #[test]
        fn multiples_of_pi_compare_like_the_bracket(n in -50i64..50, d in 1i64..50, m in -200i64..200, k in 1i64..50) {
            proptest::prop_assume!(n != 0);
            let v = value(&format!("{n}*pi/{d}")).unwrap();
            let t = Rational::new(m, k).unwrap();
            let got = v.cmp_rational(&t).unwrap();
            // n pi/d < m/k  <=>  pi (n k) < m d (k, d > 0), decided when the bracket does.
            let want = {
                let (lo, hi) = crate::pi::enclosure(60);
                let a = Rational::new(n * k, 1).unwrap();
                let b = Rational::new(m * d, 1).unwrap();
                let (x, y) = (&a * &lo, &a * &hi);
                let (x, y) = if x <= y { (x, y) } else { (y, x) };
                if y < b { Ordering::Less } else if x > b { Ordering::Greater } else { return Ok(()) }
            };
            proptest::prop_assert_eq!(got, want);
        }
    }
}
