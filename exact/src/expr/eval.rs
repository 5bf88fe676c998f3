//! The conversion of an [`Expr`] to a [`Poly`] and the exact evaluation of constant expressions,
//! with the size limits of the module documentation.

use super::*;
use crate::poly::{Poly, SizeError, Vars};
use num_traits::ToPrimitive;

// ------------------------------------------------------------------------------ conversion

impl Expr {
    /// The polynomial this expression denotes, over `C`; variables are looked up (and added) in
    /// `vars`.
    ///
    /// # Errors
    /// Division by a non-constant expression or by zero, exponents that are not integer
    /// constants (or overflow, or are negative on a non-constant base), `sqrt` of a
    /// non-constant or of a constant whose root is not in `C`, numbers with no image in `C`,
    /// and [`ExprError::Limit`] past the `exponent`, `constant-bits`, `variables`, `degree` or
    /// `terms` limit (see the module documentation).
    pub fn to_poly<C: Coefficient>(&self, vars: &mut Vars) -> Result<Poly<C>, ExprError> {
        match &self.kind {
            ExprKind::Number(q) => {
                C::from_rational(q)
                    .map(Poly::constant)
                    .ok_or_else(|| ExprError::Unrepresentable {
                        pos: self.pos,
                        number: q.to_string(),
                    })
            }
            ExprKind::Var(name) => {
                let v = vars.var(name);
                limits::VARIABLES
                    .check(u64::from(v) + 1)
                    .map_err(|error| ExprError::Limit {
                        pos: self.pos,
                        error,
                    })?;
                Ok(Poly::var(v))
            }
            ExprKind::Neg(x) => Ok(-x.to_poly::<C>(vars)?),
            ExprKind::Sum(items) => {
                let mut parts = Vec::with_capacity(items.len());
                for (op, x) in items {
                    let p = x.to_poly::<C>(vars)?;
                    parts.push(match op {
                        AddOp::Plus => p,
                        AddOp::Minus => -p,
                    });
                }
                let p = Poly::sum(parts);
                check_terms(&p, self.pos)?;
                check_coefficients(&p, self.pos)?;
                Ok(p)
            }
            ExprKind::Product(items) => {
                let (a, b) = product_pair(items, self.pos, vars)?;
                let p = a.try_mul(&b).map_err(|e| size_error(e, self.pos))?;
                check_coefficients(&p, self.pos)?;
                Ok(p)
            }
            ExprKind::Pow(base, exp) => {
                if let Some(c) = fractional_power(self, exp) {
                    return Ok(Poly::constant(c?));
                }
                let k = exponent_value(exp)?;
                let b = base.to_poly::<C>(vars)?;
                if let Some(c) = b.constant_value() {
                    return Ok(Poly::constant(constant_power(c, k, self.pos, exp.pos)?));
                }
                let k =
                    u32::try_from(k).map_err(|_| ExprError::NegativeExponent { pos: exp.pos })?;
                // The coefficient of a vertex monomial of the Newton polytope of b^k is the k-th
                // power of b's, so predict with the largest coefficient before expanding.
                let largest = b.coefficients().iter().map(C::size_bits).max();
                let predicted = largest.unwrap_or(0).saturating_mul(u64::from(k));
                limits::CONSTANT_BITS
                    .check(predicted)
                    .map_err(|_| ExprError::Limit {
                        pos: self.pos,
                        error: limits::CONSTANT_BITS.exceeded(format!("at least {predicted}")),
                    })?;
                let p = match binomial_power(&b, k).map_err(|e| size_error(e, self.pos))? {
                    Some(p) => p,
                    None => b.try_pow(k).map_err(|e| size_error(e, self.pos))?,
                };
                check_coefficients(&p, self.pos)?;
                Ok(p)
            }
            ExprKind::Sqrt(arg) => super::roots::sqrt_poly(self, arg, vars),
            ExprKind::Call(name, args) if name == super::ABS => {
                super::roots::abs_poly(self, args, vars)
            }
            ExprKind::Call(name, args) if super::calculus::CALCULUS.contains(&name.as_str()) => {
                super::calculus::call_poly(self, name, args, vars)
            }
            ExprKind::Call(name, args) => match super::trig::Trig::from_name(name) {
                Some(which) => super::trig::trig_poly(self, which, args, vars),
                None => super::fraction::diff_poly(self, args, vars),
            },
        }
    }

    /// The exact value of a constant expression in `C`: numbers, `sqrt`, `+ - * /` and integer
    /// powers, with the limits of the module documentation. A name is looked up with
    /// [`Coefficient::named_constant`] (`i` for [`crate::ComplexRadical`]); any other variable
    /// is an error naming it and its position.
    ///
    /// ```
    /// use exactcheck_exact::{expr::parse_expr, Radical, Rational};
    ///
    /// let q: Rational = parse_expr("2.5e-3 + 1/2^2").unwrap().eval_constant().unwrap();
    /// assert_eq!(q, Rational::new(101, 400).unwrap());
    /// let r: Radical = parse_expr("2 sqrt(8)").unwrap().eval_constant().unwrap();
    /// assert_eq!(r.to_string(), "4*sqrt(2)");
    /// let e = parse_expr("1 + x").unwrap().eval_constant::<Rational>().unwrap_err();
    /// assert_eq!(e.to_string(), "variable 'x' at 4 where a constant number is expected");
    /// ```
    ///
    /// # Errors
    /// A variable, division by zero, a bad exponent, a square root not in `C`, a number with no
    /// image in `C`, [`ExprError::Limit`] past the `exponent` or `constant-bits` limit.
    pub fn eval_constant<C: Coefficient>(&self) -> Result<C, ExprError> {
        match &self.kind {
            ExprKind::Number(q) => C::from_rational(q).ok_or_else(|| ExprError::Unrepresentable {
                pos: self.pos,
                number: q.to_string(),
            }),
            ExprKind::Var(name) => C::named_constant(name).ok_or_else(|| ExprError::NotConstant {
                pos: self.pos,
                name: name.clone(),
                hint: if name == "i" {
                    " (the imaginary unit i exists only for complex numbers)"
                } else if name == PI {
                    " (pi is transcendental, so it has no exact value here; sin, cos and tan of \
                     rational multiples of pi do)"
                } else {
                    ""
                },
            }),
            ExprKind::Neg(x) => Ok(-x.eval_constant::<C>()?),
            ExprKind::Sum(items) => {
                let mut acc = C::zero();
                for (op, x) in items {
                    let v = x.eval_constant::<C>()?;
                    match op {
                        AddOp::Plus => acc += v,
                        AddOp::Minus => acc -= v,
                    }
                    check_constant(&acc, self.pos)?;
                }
                Ok(acc)
            }
            ExprKind::Product(items) => {
                let mut acc = C::one();
                for (op, x) in items {
                    let v = x.eval_constant::<C>()?;
                    match op {
                        MulOp::Times | MulOp::Dot | MulOp::Cross => acc *= v,
                        MulOp::Divide => match v.try_inverse() {
                            Some(inv) => acc *= inv,
                            None => return Err(ExprError::DivisionByZero { pos: x.pos }),
                        },
                    }
                    check_constant(&acc, self.pos)?;
                }
                Ok(acc)
            }
            ExprKind::Pow(base, exp) => {
                // The exponent is evaluated once: in a tower `a^b^c` every level evaluates
                // the exponent above it.
                match exponent_of(exp)? {
                    Exponent::Integer(k) => {
                        let b = base.eval_constant::<C>()?;
                        constant_power(b, k, self.pos, exp.pos)
                    }
                    Exponent::Fraction(k, n) => root_power(base, k, n, self.pos, exp.pos),
                }
            }
            ExprKind::Sqrt(arg) => sqrt_of(arg.eval_constant::<C>()?, self.pos, arg),
            ExprKind::Call(name, args) if name == super::ABS => {
                super::roots::abs_constant(self, args)
            }
            ExprKind::Call(name, args) if super::calculus::CALCULUS.contains(&name.as_str()) => {
                super::calculus::call_constant(self, name, args)
            }
            ExprKind::Call(name, args) if super::trig::Trig::from_name(name).is_some() => {
                let which = super::trig::Trig::from_name(name).expect("matched above");
                super::trig::trig_value(self, which, args)
            }
            // The derivative of a constant is 0.
            ExprKind::Call(_, args) => {
                let (e, _, k) = super::fraction::diff_arguments(self, args)?;
                let c = e.eval_constant::<C>()?;
                Ok(if k == 0 { c } else { C::zero() })
            }
        }
    }
}

/// `b^k` for a binomial `b = c1 m1 + c2 m2` by the binomial theorem:
/// `sum_i binom(k, i) c1^i c2^(k-i) m1^i m2^(k-i)`, `k + 1` distinct terms, each binomial from
/// the previous one by an exact integer ratio. Binary powering would square `b^(k/2)`, about
/// `k^2/8` products of large coefficients: `(x+y)^5000` took 10 to 25 s that way, a fraction
/// of a second here. `None` (nothing computed) when `b` is not a binomial, `k < 2`, or a
/// binomial coefficient has no image in `C`; the limits are those of [`Poly::try_pow`].
fn binomial_power<C: Coefficient>(b: &Poly<C>, k: u32) -> Result<Option<Poly<C>>, SizeError> {
    if b.len() != 2 || k < 2 {
        return Ok(None);
    }
    let k64 = u64::from(k);
    limits::DEGREE.check(b.total_degree().saturating_mul(k64))?;
    if u64::from(b.max_exponent()) * k64 > u64::from(u32::MAX) {
        return Err(SizeError::ExponentOverflow);
    }
    limits::TERMS.check(k64 + 1)?;
    let terms: Vec<(Vec<(crate::poly::Var, u32)>, &C)> =
        b.terms().map(|(m, c)| (m.exponents(), c)).collect();
    // The coefficients take about (k + 1) (k (s1 + s2) / 2 + k) bits in all (term i has
    // i s1 + (k - i) s2 bits and a binomial of at most k bits), and so do the powers of c2
    // kept: predicted against a quarter of the memory limit before any work.
    let (s1, s2) = (terms[0].1.size_bits(), terms[1].1.size_bits());
    let bits = (k64 + 1).saturating_mul(k64.saturating_mul(s1.saturating_add(s2)) / 2 + k64);
    let budget_bits = limits::MEMORY
        .get()
        .saturating_mul(1 << 20)
        .saturating_mul(8)
        / 4;
    if bits.saturating_mul(2) > budget_bits {
        return Err(SizeError::Limit(limits::MEMORY.exceeded(format!(
            "a power of {} MB of coefficients, over a quarter of the limit",
            (bits.saturating_mul(2) / 8) >> 20
        ))));
    }
    let (e1, c1) = (&terms[0].0, terms[0].1);
    let (e2, c2) = (&terms[1].0, terms[1].1);
    // c2^j for j = 0..=k, so that term i takes c2^(k-i).
    let mut pow2 = Vec::with_capacity(k as usize + 1);
    pow2.push(C::one());
    for j in 1..=k as usize {
        let next = pow2[j - 1].mul_ref(c2);
        pow2.push(next);
    }
    let mut binom = BigInt::from(1u32);
    let mut pow1 = C::one();
    let mut out = Vec::with_capacity(k as usize + 1);
    for i in 0..=k {
        let Some(bc) = C::from_rational(&Rational::from(binom.clone())) else {
            return Ok(None);
        };
        let c = bc.mul_ref(&pow1).mul_ref(&pow2[(k - i) as usize]);
        let mut m: Vec<(crate::poly::Var, u32)> = Vec::with_capacity(e1.len() + e2.len());
        m.extend(e1.iter().map(|&(v, e)| (v, e * i)));
        m.extend(e2.iter().map(|&(v, e)| (v, e * (k - i))));
        out.push((m, c));
        if i < k {
            binom = binom * (k - i) / (i + 1);
            pow1 = pow1.mul_ref(c1);
        }
    }
    Ok(Some(Poly::from_terms(out)))
}

/// The square root of the constant `c` (the value of `arg`, in `sqrt` at `pos`).
pub(super) fn sqrt_of<C: Coefficient>(c: C, pos: usize, arg: &Expr) -> Result<C, ExprError> {
    c.try_sqrt().ok_or_else(|| ExprError::NoSqrt {
        pos,
        arg: arg.to_string(),
        hint: c.sqrt_hint_for(),
    })
}

/// `c^k` for a constant `c` and `|k|` within the `exponent` limit, by binary powering with the
/// size limit: refused at once when `k * size_bits(c)` exceeds `constant-bits` (a lower bound of
/// the result's size), and checked after every multiplication, so no intermediate value exceeds
/// about twice the limit. `pos` is the power's position, `exp_pos` its exponent's.
fn constant_power<C: Coefficient>(
    c: C,
    k: i64,
    pos: usize,
    exp_pos: usize,
) -> Result<C, ExprError> {
    let base = if k < 0 {
        c.try_inverse()
            .ok_or(ExprError::DivisionByZero { pos: exp_pos })?
    } else {
        c
    };
    let mut e = k.unsigned_abs();
    let predicted = base.size_bits().saturating_mul(e);
    if predicted > limits::CONSTANT_BITS.get() {
        return Err(ExprError::Limit {
            pos,
            error: limits::CONSTANT_BITS.exceeded(format!("at least {predicted}")),
        });
    }
    let mut acc = C::one();
    let mut sq = base;
    while e > 0 {
        if e & 1 == 1 {
            acc = acc.mul_ref(&sq);
            check_constant(&acc, pos)?;
        }
        e >>= 1;
        if e > 0 {
            sq = sq.square();
            check_constant(&sq, pos)?;
        }
    }
    Ok(acc)
}

/// The `constant-bits` limit on every coefficient of `p`.
fn check_coefficients<C: Coefficient>(p: &Poly<C>, pos: usize) -> Result<(), ExprError> {
    p.coefficients()
        .iter()
        .try_for_each(|c| check_constant(c, pos))
}

/// A product's value as two factors `(a, b)`, `b` the largest factor and `a` the product of the
/// others (multiplied smallest first, with the constant factors folded into the smallest).
fn product_pair<C: Coefficient>(
    items: &[(MulOp, Expr)],
    pos: usize,
    vars: &mut Vars,
) -> Result<(Poly<C>, Poly<C>), ExprError> {
    let mut scalar = C::one();
    let mut factors: Vec<Poly<C>> = Vec::new();
    for (op, x) in items {
        let p = x.to_poly::<C>(vars)?;
        match (op, p.constant_value()) {
            (MulOp::Times | MulOp::Dot | MulOp::Cross, Some(c)) => scalar *= c,
            (MulOp::Times | MulOp::Dot | MulOp::Cross, None) => factors.push(p),
            (MulOp::Divide, None) => return Err(ExprError::NonConstantDivisor { pos: x.pos }),
            (MulOp::Divide, Some(c)) => match c.try_inverse() {
                Some(inv) => scalar *= inv,
                None => return Err(ExprError::DivisionByZero { pos: x.pos }),
            },
        }
        check_constant(&scalar, pos)?;
    }
    // Smallest first; the scalar goes into the smallest factor.
    factors.sort_by_key(Poly::len);
    let Some(b) = factors.pop() else {
        return Ok((Poly::constant(scalar), Poly::one()));
    };
    let mut it = factors.into_iter();
    let Some(first) = it.next() else {
        return Ok((Poly::constant(scalar), b));
    };
    let mut a = first.scale(&scalar);
    for f in it {
        a = a.try_mul(&f).map_err(|e| size_error(e, pos))?;
        check_coefficients(&a, pos)?;
    }
    Ok((a, b))
}

/// `base^(k/n)` for a constant `base` (`self` at `pos`, the exponent at `exp_pos`): the real
/// root of index `n` in `C` ([`Coefficient::try_nth_root`]; a rational root of a rational,
/// `8^(1/3)`, in every field), to the power `k`.
fn root_power<C: Coefficient>(
    base: &Expr,
    k: i64,
    n: u32,
    pos: usize,
    exp_pos: usize,
) -> Result<C, ExprError> {
    let b = base.eval_constant::<C>()?;
    let rational = || {
        let q = base.eval_constant::<Rational>().ok()?;
        let negative = q.signum() == exactcheck_core::Sign::Negative;
        match q.try_nth_root(n) {
            Ok(Some(r)) => C::from_rational(&r).map(Ok),
            _ if negative && n % 2 == 0 => {
                Some(Err(": a negative number has no real root of even index"))
            }
            _ => None,
        }
    };
    let root = match b.try_nth_root(n) {
        Ok(Some(r)) => r,
        Ok(None) => match rational() {
            Some(Ok(r)) => r,
            found => {
                return Err(ExprError::NoRoot {
                    pos,
                    index: n,
                    arg: base.to_string(),
                    hint: match found {
                        Some(Err(why)) => why,
                        _ => C::nth_root_hint(),
                    },
                })
            }
        },
        Err(error) => return Err(ExprError::Limit { pos, error }),
    };
    constant_power(root, k, pos, exp_pos)
}

/// The value of a constant exponent: an integer, or a fraction `k/n` that is not one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Exponent {
    /// An integer within the `exponent` limit.
    Integer(i64),
    /// `k/n` in lowest terms, `n >= 2` within the `algebraic-degree` limit, `|k|` within the
    /// `exponent` limit.
    Fraction(i64, u32),
}

/// The value of an exponent expression, evaluated once ([`Exponent`]).
///
/// # Errors
/// [`ExprError::BadExponent`] for an exponent that is not constant; a limit exceeded.
pub(super) fn exponent_of(e: &Expr) -> Result<Exponent, ExprError> {
    let q: Rational = match e.eval_constant() {
        Ok(q) => q,
        Err(ExprError::NotConstant { .. }) => {
            return Err(ExprError::BadExponent {
                pos: e.pos,
                found: e.to_string(),
            })
        }
        Err(err) => return Err(err),
    };
    let limit = |error| ExprError::Limit { pos: e.pos, error };
    let k = q.numer();
    let k = k
        .to_i64()
        .filter(|k| limits::EXPONENT.check(k.unsigned_abs()).is_ok())
        .ok_or_else(|| {
            limit(limits::EXPONENT.exceeded(match k.to_i64() {
                Some(k) => k.unsigned_abs().to_string(),
                None => format!("an integer of {} bits", k.bits()),
            }))
        })?;
    if q.is_integer() {
        return Ok(Exponent::Integer(k));
    }
    let n = q.denom();
    limits::ALGEBRAIC_DEGREE
        .check_usize(n.to_usize().unwrap_or(usize::MAX))
        .map_err(limit)?;
    Ok(Exponent::Fraction(
        k,
        n.to_u32().expect("within the algebraic-degree limit"),
    ))
}

/// The value of an exponent expression: an integer constant within the `exponent` limit.
pub(super) fn exponent_value(e: &Expr) -> Result<i64, ExprError> {
    match exponent_of(e)? {
        Exponent::Integer(k) => Ok(k),
        Exponent::Fraction(k, n) => Err(ExprError::BadExponent {
            pos: e.pos,
            found: format!("{k}/{n}"),
        }),
    }
}

/// The value of the power `e` when its exponent `exp` is a constant that is not an integer
/// (`2^(1/3)`): the constant power of [`Expr::eval_constant`], or the error of an exponent
/// that is not an integer (a non-constant base takes integer exponents only); `None` for an
/// integer exponent or one that is not constant.
pub(super) fn fractional_power<C: Coefficient>(
    e: &Expr,
    exp: &Expr,
) -> Option<Result<C, ExprError>> {
    match fractional_exponent(exp) {
        Ok(None) => None,
        Err(err) => Some(Err(err)),
        Ok(Some((k, n))) => Some(match e.eval_constant::<C>() {
            Err(ExprError::NotConstant { .. }) => Err(ExprError::BadExponent {
                pos: exp.pos,
                found: match &e.kind {
                    ExprKind::Pow(base, _) => format!("{k}/{n} of the non-constant {base}"),
                    _ => format!("{k}/{n}"),
                },
            }),
            value => value,
        }),
    }
}

/// A constant exponent `k/n` that is not an integer (`1/3`, `-2/5`) as `(k, n)`; `None` for any
/// other exponent (an integer, or not a constant: [`exponent_value`] judges those).
///
/// # Errors
/// A limit exceeded.
pub(super) fn fractional_exponent(e: &Expr) -> Result<Option<(i64, u32)>, ExprError> {
    match exponent_of(e) {
        Ok(Exponent::Fraction(k, n)) => Ok(Some((k, n))),
        Ok(Exponent::Integer(_)) | Err(ExprError::BadExponent { .. }) => Ok(None),
        Err(err) => Err(err),
    }
}

/// The `constant-bits` limit on the constant `c`.
pub(super) fn check_constant<C: Coefficient>(c: &C, pos: usize) -> Result<(), ExprError> {
    c.check_limits()
        .map_err(|error| ExprError::Limit { pos, error })?;
    let max = limits::CONSTANT_BITS.get();
    if !c.size_within(max) {
        Err(ExprError::Limit {
            pos,
            error: limits::CONSTANT_BITS.exceeded(format!("more than {max}")),
        })
    } else {
        Ok(())
    }
}

/// The `terms` limit on the terms of `p` (a sum: its terms were not counted as produced).
fn check_terms<C: Coefficient>(p: &Poly<C>, pos: usize) -> Result<(), ExprError> {
    limits::TERMS
        .check_usize(p.len())
        .map_err(|error| ExprError::Limit { pos, error })
}

/// A refused product or power as an error at `pos`.
pub(super) fn size_error(e: SizeError, pos: usize) -> ExprError {
    match e {
        SizeError::ExponentOverflow => ExprError::ExponentOverflow { pos },
        SizeError::Limit(error) => ExprError::Limit { pos, error },
    }
}
