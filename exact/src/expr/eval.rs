//! The conversion of an [`Expr`] to a [`Poly`] and the exact evaluation of constant expressions,
//! with the size limits of the module documentation.

use super::*;
use crate::poly::{Poly, Vars};
use num_traits::ToPrimitive;

// ------------------------------------------------------------------------------ conversion

impl Expr {
    /// The polynomial this expression denotes, over `C`; variables are looked up (and added) in
    /// `vars`.
    ///
    /// # Errors
    /// Division by a non-constant expression or by zero, exponents that are not integer
    /// constants (or exceed [`MAX_EXPONENT`], or overflow, or are negative on a non-constant
    /// base), `sqrt` of a non-constant or of a constant whose root is not in `C`, numbers with no
    /// image in `C`, coefficients beyond [`MAX_CONSTANT_BITS`].
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
            ExprKind::Var(name) => Ok(Poly::var(vars.var(name))),
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
                check_coefficients(&p, self.pos)?;
                Ok(p)
            }
            ExprKind::Product(items) => {
                let (a, b) = product_pair(items, self.pos, vars)?;
                let p = a
                    .checked_mul(&b)
                    .ok_or(ExprError::ExponentOverflow { pos: self.pos })?;
                check_coefficients(&p, self.pos)?;
                Ok(p)
            }
            ExprKind::Pow(base, exp) => {
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
                if largest.unwrap_or(0).saturating_mul(u64::from(k)) > MAX_CONSTANT_BITS {
                    return Err(ExprError::ConstantTooLarge {
                        pos: self.pos,
                        max: MAX_CONSTANT_BITS,
                    });
                }
                let p = b
                    .checked_pow(k)
                    .ok_or(ExprError::ExponentOverflow { pos: self.pos })?;
                check_coefficients(&p, self.pos)?;
                Ok(p)
            }
            ExprKind::Sqrt(arg) => {
                let p = arg.to_poly::<C>(vars)?;
                let c = p
                    .constant_value()
                    .ok_or(ExprError::NonConstantSqrt { pos: arg.pos })?;
                sqrt_of(c, self.pos, arg).map(Poly::constant)
            }
            ExprKind::Call(name, _) => Err(ExprError::UnknownFunction {
                pos: self.pos,
                name: name.clone(),
            }),
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
    /// image in `C`, a constant beyond [`MAX_CONSTANT_BITS`].
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
                        MulOp::Times => acc *= v,
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
                let k = exponent_value(exp)?;
                let b = base.eval_constant::<C>()?;
                constant_power(b, k, self.pos, exp.pos)
            }
            ExprKind::Sqrt(arg) => sqrt_of(arg.eval_constant::<C>()?, self.pos, arg),
            ExprKind::Call(name, _) => Err(ExprError::UnknownFunction {
                pos: self.pos,
                name: name.clone(),
            }),
        }
    }
}

/// The square root of the constant `c` (the value of `arg`, in `sqrt` at `pos`).
fn sqrt_of<C: Coefficient>(c: C, pos: usize, arg: &Expr) -> Result<C, ExprError> {
    c.try_sqrt().ok_or_else(|| ExprError::NoSqrt {
        pos,
        arg: arg.to_string(),
        hint: c.sqrt_hint_for(),
    })
}

/// `c^k` for a constant `c` and `|k| <= MAX_EXPONENT`, by binary powering with the size limit:
/// refused at once when `k * size_bits(c)` exceeds [`MAX_CONSTANT_BITS`] (a lower bound of the
/// result's size), and checked after every multiplication, so no intermediate value exceeds
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
    if base.size_bits().saturating_mul(e) > MAX_CONSTANT_BITS {
        return Err(ExprError::ConstantTooLarge {
            pos,
            max: MAX_CONSTANT_BITS,
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

/// `Err(ConstantTooLarge)` when a coefficient of `p` exceeds [`MAX_CONSTANT_BITS`].
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
            (MulOp::Times, Some(c)) => scalar *= c,
            (MulOp::Times, None) => factors.push(p),
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
        a = a
            .checked_mul(&f)
            .ok_or(ExprError::ExponentOverflow { pos })?;
        check_coefficients(&a, pos)?;
    }
    Ok((a, b))
}

/// The value of an exponent expression: an integer constant with `|k| <= MAX_EXPONENT`.
fn exponent_value(e: &Expr) -> Result<i64, ExprError> {
    let bad = |found: String| ExprError::BadExponent { pos: e.pos, found };
    let q: Rational = match e.eval_constant() {
        Ok(q) => q,
        Err(ExprError::NotConstant { .. }) => return Err(bad(e.to_string())),
        Err(err) => return Err(err),
    };
    if !q.is_integer() {
        return Err(bad(q.to_string()));
    }
    match q.numer().to_i64() {
        Some(k) if k.unsigned_abs() <= u64::from(MAX_EXPONENT) => Ok(k),
        _ => Err(ExprError::ExponentTooLarge {
            pos: e.pos,
            exponent: q.to_string(),
            max: MAX_EXPONENT,
        }),
    }
}

/// `Err(ConstantTooLarge)` when `c` has more than [`MAX_CONSTANT_BITS`] bits.
pub(super) fn check_constant<C: Coefficient>(c: &C, pos: usize) -> Result<(), ExprError> {
    c.check_limits()
        .map_err(|error| ExprError::Limit { pos, error })?;
    if !c.size_within(MAX_CONSTANT_BITS) {
        Err(ExprError::ConstantTooLarge {
            pos,
            max: MAX_CONSTANT_BITS,
        })
    } else {
        Ok(())
    }
}
