//! Base angles: the angles whose cosine and sine are the variables of a table, of which every
//! angle of a statement is an integer combination (plus a rational multiple of pi).
//!
//! * An angle variable `x` whose coefficients across the statement have the denominators
//!   `q_1, ..., q_n` has the base angle `x/L`, `L = lcm(q_i)`: the variables `cos(x/L)` and
//!   `sin(x/L)` (`cos(x)`, `sin(x)` for `L = 1`), and `(p/q) x` is the multiple `pL/q` of it.
//!   Deciding over the base angle is sound and complete: `x` ranges over the reals exactly when
//!   `x/L` does.
//! * The rational constant parts `r_1, ..., r_n` of the angles (radians, `sin(1)`,
//!   `cos(2 + pi/3)`) are the integer multiples of one constant angle `u`, their rational gcd
//!   (`u = g/L`, `L` the lcm of their denominators, `g` the gcd of the integers `L r_i`): the
//!   variables `cos(u)` and `sin(u)` with the circle relation like an angle variable's. By
//!   Lindemann–Weierstrass `e^{iu}` is transcendental, so the only algebraic relation over the
//!   algebraic numbers between `cos(u)` and `sin(u)` is `cos(u)^2 + sin(u)^2 = 1`: a polynomial
//!   in them with algebraic coefficients is zero exactly when it is zero modulo the circle.
//!
//! The names (`cos(x/2)`, `cos(1/2)`) are names no identifier can take, and a printed polynomial
//! in them reads back to the same polynomial when its table has the same bases. Everything
//! decided together must share its bases: [`register_angle_bases`] enters them in the table
//! before anything is converted; the conversion of a single expression finds them there (or
//! enters the base of its own angle when there is none yet).

use super::trig::{angles, cos_name, linear_angle, sin_name, Angle, Trig};
use super::*;
use crate::poly::{Var, Vars};
use exactcheck_core::Sign;
use num_integer::Integer;
use num_traits::{One, ToPrimitive, Zero};

/// What the angle of a table's `cos(...)`, `sin(...)` pair stands for.
#[derive(Clone, Debug, PartialEq)]
pub enum Base {
    /// The angle variable `name` times `unit` (`unit = 1/L`): `x/L`.
    Variable {
        /// The angle variable (`x`).
        name: String,
        /// `1/L`.
        unit: Rational,
    },
    /// The constant angle `u` (radians, positive), of which every rational constant part of
    /// an angle is an integer multiple.
    Constant(Rational),
}

impl Base {
    /// The base of the angle named `angle` in a table (`x`, `x/2`, `1`, `1/2`).
    pub fn of_name(angle: &str) -> Base {
        if let Ok(u) = angle.parse::<Rational>() {
            return Base::Constant(u);
        }
        if let Some((x, l)) = angle.rsplit_once('/') {
            if let Ok(l) = l.parse::<BigInt>() {
                if l > BigInt::one() {
                    let unit = reciprocal(l);
                    return Base::Variable {
                        name: x.to_string(),
                        unit,
                    };
                }
            }
        }
        Base::Variable {
            name: angle.to_string(),
            unit: Rational::ONE,
        }
    }

    /// The angle's name: `x`, `x/2`, `1`, `1/2`.
    pub fn name(&self) -> String {
        match self {
            Base::Variable { name, unit } if unit.is_one() => name.clone(),
            Base::Variable { name, unit } => format!("{name}/{}", unit.denom()),
            Base::Constant(u) => u.to_string(),
        }
    }

    /// The angle variable of a variable base.
    pub fn variable(&self) -> Option<&str> {
        match self {
            Base::Variable { name, .. } => Some(name),
            Base::Constant(_) => None,
        }
    }

    /// The base's step: `1/L` of a variable, `u` of the constant.
    pub fn unit(&self) -> &Rational {
        match self {
            Base::Variable { unit, .. } => unit,
            Base::Constant(u) => u,
        }
    }
}

/// The angle variable of the angle named `angle` (`x` of `x/2`), `None` for the constant angle.
pub fn angle_variable(angle: &str) -> Option<String> {
    Base::of_name(angle).variable().map(str::to_string)
}

/// The base angle of the angle variable `x` in the table, with its base.
pub fn variable_base(vars: &Vars, x: &str) -> Option<(Angle, Base)> {
    angles(vars).into_iter().find_map(|a| {
        let base = Base::of_name(&a.name);
        (base.variable() == Some(x)).then_some((a, base))
    })
}

/// The constant angle of the table, with its base.
pub fn constant_base(vars: &Vars) -> Option<(Angle, Base)> {
    angles(vars).into_iter().find_map(|a| {
        let base = Base::of_name(&a.name);
        matches!(base, Base::Constant(_)).then_some((a, base))
    })
}

/// Which base an angle's term needs: that of an angle variable, or the constant angle.
#[derive(Clone, Copy, Debug)]
pub(super) enum Part<'a> {
    /// The term `c x` of the angle variable `x`.
    Variable(&'a str),
    /// The rational constant part.
    Constant,
}

/// The cosine and sine variables of the base of `part` and the multiple `coefficient` is of it,
/// entering the base in `vars` when it has none (`x/q` for the coefficient `p/q` of `x`, `|r|`
/// for the constant part `r`), checked against the `angle-multiple` limit.
///
/// # Errors
/// A multiple past the `angle-multiple` limit; a coefficient that is not a multiple of the base
/// already in the table (a statement whose parts were converted without
/// [`register_angle_bases`]).
pub(super) fn base_multiple(
    vars: &mut Vars,
    part: Part<'_>,
    coefficient: &Rational,
    arg: &Expr,
    name: &str,
) -> Result<(Var, Var, i64), ExprError> {
    let found = match part {
        Part::Variable(x) => variable_base(vars, x),
        Part::Constant => constant_base(vars),
    };
    let (angle, base) = match found {
        Some(f) => f,
        None => {
            let base = match part {
                Part::Variable(x) => Base::Variable {
                    name: x.to_string(),
                    unit: reciprocal(coefficient.denom()),
                },
                Part::Constant if coefficient.signum() == Sign::Negative => {
                    Base::Constant(coefficient.neg_ref())
                }
                Part::Constant => Base::Constant(coefficient.clone()),
            };
            (enter(vars, &base, arg.pos)?, base)
        }
    };
    let k = coefficient
        .checked_div(base.unit())
        .expect("a base angle is not zero");
    if !k.is_integer() {
        return Err(ExprError::BadCall {
            pos: arg.pos,
            name: name.to_string(),
            why: format!(
                "the angle {arg} is not an integer multiple of the base angle {} of the \
                 expressions converted before it (convert the expressions decided together with \
                 their angles registered first)",
                base.name()
            ),
        });
    }
    let k = k.numer();
    let limit = |found: String| ExprError::Limit {
        pos: arg.pos,
        error: limits::ANGLE_MULTIPLE.exceeded(found),
    };
    let k = match k.to_i64() {
        Some(k) => k,
        None => return Err(limit(format!("an integer of {} bits", k.bits()))),
    };
    limits::ANGLE_MULTIPLE
        .check(k.unsigned_abs())
        .map_err(|_| {
            limit(match base {
                Base::Variable { unit, .. } if unit.is_one() => k.unsigned_abs().to_string(),
                _ => format!("{} times the base angle {}", k.unsigned_abs(), base.name()),
            })
        })?;
    Ok((angle.cos, angle.sin, k))
}

/// Why a non-zero polynomial in the cosine and sine of the constant angle `angle` (modulo their
/// circle) is not zero.
pub fn lindemann_weierstrass(angle: &str) -> String {
    let u = Base::of_name(angle);
    let exp = match u.unit() {
        r if r.is_one() => "e^i".to_string(),
        r if r.is_integer() => format!("e^({r} i)"),
        r => format!("e^({} i/{})", r.numer(), r.denom()),
    };
    format!(
        "a non-zero polynomial in cos({angle}), sin({angle}) modulo cos({angle})^2 + \
         sin({angle})^2 = 1, and cos({angle}) + i sin({angle}) = {exp} is transcendental \
         (Lindemann–Weierstrass), so it is not zero"
    )
}

/// `1/l` for a positive integer `l`.
fn reciprocal(l: BigInt) -> Rational {
    Rational::ONE
        .checked_div(&Rational::from(l))
        .expect("a denominator is not zero")
}

/// Enters the cosine and sine variables of `base` in `vars`.
fn enter(vars: &mut Vars, base: &Base, pos: usize) -> Result<Angle, ExprError> {
    let name = base.name();
    let (cos, sin) = (vars.var(&cos_name(&name)), vars.var(&sin_name(&name)));
    limits::VARIABLES
        .check(u64::from(cos.max(sin)) + 1)
        .map_err(|error| ExprError::Limit { pos, error })?;
    Ok(Angle { name, cos, sin })
}

/// Enters in `vars` the base angles of the expressions decided together (module
/// documentation): for each angle variable with a non-integer coefficient, `x/L`; for the
/// rational constant parts, the constant angle `u`. Angle variables whose coefficients are all
/// integers keep the base `x`, entered by the conversion when it meets them. Malformed angles
/// are left to the conversion, which reports them.
///
/// # Errors
/// A base the table already has that does not divide the one needed (its expressions were
/// converted before these were registered); the `variables` limit.
pub fn register_angle_bases(exprs: &[&Expr], vars: &mut Vars) -> Result<(), ExprError> {
    let mut calls = Vec::new();
    for e in exprs {
        super::library::map_tree(e, &mut |x| {
            if matches!(&x.kind, ExprKind::Call(name, _) if Trig::from_name(name).is_some()) {
                calls.push(x.clone());
            }
        });
    }
    // Per angle variable (in order of appearance): the lcm of its denominators.
    let mut lcms: Vec<(String, BigInt, usize)> = Vec::new();
    let mut constants: Vec<(Rational, usize)> = Vec::new();
    for call in &calls {
        let ExprKind::Call(name, args) = &call.kind else {
            continue;
        };
        let Ok(angle) = linear_angle(call, name, args) else {
            continue;
        };
        for (x, c) in &angle.terms {
            match lcms.iter_mut().find(|(y, _, _)| y == x) {
                Some((_, l, _)) => *l = l.lcm(&c.denom()),
                None => lcms.push((x.clone(), c.denom(), args[0].pos)),
            }
        }
        if !angle.constant.is_zero() {
            constants.push((angle.constant.clone(), args[0].pos));
        }
    }
    let conflict = |pos: usize, needed: String, found: String| ExprError::BadCall {
        pos,
        name: "angle".into(),
        why: format!(
            "the angles need the base angle {needed}, but the table already has {found} (its \
             expressions were converted before the angles were registered)"
        ),
    };
    for (x, l, pos) in lcms {
        let unit = reciprocal(l.clone());
        match variable_base(vars, &x) {
            Some((_, old)) => {
                if !old.unit().denom().is_multiple_of(&l) {
                    let new = Base::Variable { name: x, unit };
                    return Err(conflict(pos, new.name(), old.name()));
                }
            }
            None if l.is_one() => {}
            None => {
                enter(vars, &Base::Variable { name: x, unit }, pos)?;
            }
        }
    }
    if let Some((_, pos)) = constants.first() {
        let l = constants
            .iter()
            .fold(BigInt::one(), |l, (r, _)| l.lcm(&r.denom()));
        let scale = Rational::from(l.clone());
        let g = constants
            .iter()
            .fold(BigInt::zero(), |g, (r, _)| g.gcd(&(r * &scale).numer()));
        let u = Rational::from(g)
            .checked_div(&scale)
            .expect("the lcm of denominators is not zero");
        match constant_base(vars) {
            Some((_, old)) => {
                let multiple =
                    |r: &Rational| r.checked_div(old.unit()).is_ok_and(|k| k.is_integer());
                if constants.iter().any(|(r, _)| !multiple(r)) {
                    return Err(conflict(*pos, u.to_string(), old.name()));
                }
            }
            None => {
                enter(vars, &Base::Constant(u), *pos)?;
            }
        }
    }
    Ok(())
}
