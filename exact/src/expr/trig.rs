//! Angles: `sin`, `cos` and `tan` of a rational combination of angle variables plus a rational
//! number and a rational multiple of `pi`, converted exactly to polynomials in the cosine and
//! sine of base angles.
//!
//! Each part of an angle is an integer multiple of a base angle ([`super::angle_base`]): an
//! angle variable `x` of `x/L` (`L` the lcm of the denominators of its coefficients in what is
//! decided together; `x` itself when they are integers), the rational number part of the
//! constant angle `u`. A base angle `a` becomes two variables of the table, named `cos(a)` and
//! `sin(a)` (`cos(x)`, `cos(x/2)`, `cos(1)`: names no identifier can take, so they never collide
//! with a user's variable, and a printed polynomial in them reads back to the same polynomial).
//! The caller adds the relation `cos(a)^2 + sin(a)^2 = 1` for every angle of the table
//! ([`angles`]); modulo these relations the normal form that is linear in each `sin(a)` is
//! unique, so a trigonometric polynomial is identically zero exactly when its normal form is
//! (for the constant angle by Lindemann–Weierstrass: the circle is its only algebraic relation).
//!
//! * `k a` expands by the multiple-angle formulas: `cos(k a) = T_k(cos a)`,
//!   `sin(k a) = sin a U_{k-1}(cos a)` with the Chebyshev polynomials `T`, `U` (already reduced:
//!   linear in `sin a`); `|k|` is bounded by the `angle-multiple` limit
//!   ([`limits::ANGLE_MULTIPLE`]) before anything is expanded;
//! * sums expand by the addition formulas, as the product of the complex numbers
//!   `cos a + i sin a`;
//! * the constant part `(p/q) pi` takes its exact value from [`trig_constant`];
//! * `tan = sin/cos`, a fraction whose denominator is a side condition (converted by
//!   [`Expr::to_ratfun`]).
//!
//! Written here rather than taken from a computer-algebra crate: the formulas are a few lines
//! over the workspace's own polynomial type, which the proof engine and its limits already use.

use super::angle_base::{base_multiple, Base, Part};
use super::eval::size_error;
use super::*;
use crate::poly::{Poly, Var, Vars};
use crate::ratfun::RatFun;
use exactcheck_core::Field;
use num_traits::{ToPrimitive, Zero};

pub use crate::coefficient::{Trig, TrigRefusal};

/// The name of the variable standing for the cosine of the angle `angle`: `cos(x)`.
pub fn cos_name(angle: &str) -> String {
    format!("cos({angle})")
}

/// The name of the variable standing for the sine of the angle `angle`: `sin(x)`.
pub fn sin_name(angle: &str) -> String {
    format!("sin({angle})")
}

/// An angle variable of a table: its name and the variables of its cosine and sine.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Angle {
    /// The angle's name (`x`).
    pub name: String,
    /// The variable `cos(x)`.
    pub cos: Var,
    /// The variable `sin(x)`.
    pub sin: Var,
}

impl Angle {
    /// The relation `cos(x)^2 + sin(x)^2 - 1` (zero on the unit circle).
    pub fn relation<C: Ring>(&self) -> Poly<C> {
        Poly::from_terms([
            (vec![(self.cos, 2)], C::one()),
            (vec![(self.sin, 2)], C::one()),
            (vec![], C::one().neg_ref()),
        ])
    }
}

/// Every angle of the table (each `cos(x)` with its `sin(x)`, both made together by the
/// conversion), in the order of the table.
pub fn angles(vars: &Vars) -> Vec<Angle> {
    vars.names()
        .iter()
        .enumerate()
        .filter_map(|(i, n)| {
            let name = n.strip_prefix("cos(")?.strip_suffix(')')?;
            let sin = vars.get(&sin_name(name))?;
            Some(Angle {
                name: name.to_string(),
                cos: i as Var,
                sin,
            })
        })
        .collect()
}

/// The angle whose cosine or sine the variable named `var` is: `x` for `cos(x)` and `sin(x)`.
pub fn angle_of(var: &str) -> Option<(&str, Trig)> {
    let (f, rest) = var.split_once('(')?;
    let which = Trig::from_name(f).filter(|t| *t != Trig::Tan)?;
    Some((rest.strip_suffix(')')?, which))
}

/// A counter-example's values, `name = value`, with every angle's cosine and sine written as one
/// angle: `cos(x) = 3/5, sin(x) = 4/5` becomes `x = angle with cos x = 3/5, sin x = 4/5`, in the
/// place of its first variable, and `cos(x/2) = 3/5, sin(x/2) = 4/5` becomes
/// `x = angle with cos(x/2) = 3/5, sin(x/2) = 4/5`. The constant angle (`cos(1)`, `sin(1)`) is
/// no coordinate of a point: its values are left out.
pub fn describe_point(point: &[(String, String)]) -> Vec<String> {
    let mut out = Vec::new();
    let mut done = Vec::new();
    for (v, q) in point {
        match angle_of(v) {
            Some((a, _)) => {
                if done.contains(&a) {
                    continue;
                }
                done.push(a);
                let base = Base::of_name(a);
                let Some(x) = base.variable() else {
                    continue;
                };
                let find = |n: String| point.iter().find(|(w, _)| *w == n).map(|(_, x)| x);
                match (find(cos_name(a)), find(sin_name(a))) {
                    (Some(c), Some(s)) if base.unit().is_one() => {
                        out.push(format!("{a} = angle with cos {a} = {c}, sin {a} = {s}"))
                    }
                    (Some(c), Some(s)) => out.push(format!(
                        "{x} = angle with {} = {c}, {} = {s}",
                        cos_name(a),
                        sin_name(a)
                    )),
                    _ => out.push(format!("{v} = {q}")),
                }
            }
            None => out.push(format!("{v} = {q}")),
        }
    }
    out
}

// ------------------------------------------------------------------------------ constants

/// `cos(n pi/12)` for `n = 0..=12`: sums of `num/den sqrt(radicand)`.
const COS_TWELFTHS: [&[(i64, i64, u32)]; 13] = [
    &[(1, 1, 1)],
    &[(1, 4, 6), (1, 4, 2)],
    &[(1, 2, 3)],
    &[(1, 2, 2)],
    &[(1, 2, 1)],
    &[(1, 4, 6), (-1, 4, 2)],
    &[],
    &[(-1, 4, 6), (1, 4, 2)],
    &[(-1, 2, 1)],
    &[(-1, 2, 2)],
    &[(-1, 2, 3)],
    &[(-1, 4, 6), (-1, 4, 2)],
    &[(-1, 1, 1)],
];

/// The denominators `q` of the angles `(p/q) pi` whose sine and cosine [`trig_constant`] gives.
pub const TRIG_DENOMINATORS: &[u32] = &[1, 2, 3, 4, 6, 12];

/// The exact value of `sin`, `cos` or `tan` at the angle `r pi` (`r` rational), in `C`: for `r`
/// with a denominator in [`TRIG_DENOMINATORS`] the value lies in `Q(sqrt 2, sqrt 3)` (`cos(pi/4)
/// = sqrt(2)/2`, `cos(pi/12) = (sqrt 6 + sqrt 2)/4`) and is built from that table, the fast path
/// of every coefficient type with those square roots; a type that computes every multiple,
/// [`crate::Algebraic`] (`cos(2*pi/7)` is a cubic irrationality), gives its own value through
/// [`Coefficient::trig_of_pi`], and the other types refuse other denominators with the reason,
/// as they refuse `tan` where the cosine is zero.
///
/// ```
/// use exactcheck_exact::expr::{trig_constant, Trig};
/// use exactcheck_exact::{Algebraic, Radical, Rational};
///
/// let c: Radical = trig_constant(&Rational::new(1, 4).unwrap(), Trig::Cos).unwrap();
/// assert_eq!(c.to_string(), "sqrt(2)/2");
/// let t: Radical = trig_constant(&Rational::new(1, 12).unwrap(), Trig::Tan).unwrap();
/// assert_eq!(t, "2 - sqrt(3)".parse().unwrap());
/// assert!(trig_constant::<Radical>(&Rational::new(1, 2).unwrap(), Trig::Tan).is_err());
/// assert!(trig_constant::<Radical>(&Rational::new(1, 5).unwrap(), Trig::Cos).is_err());
/// let c: Algebraic = trig_constant(&Rational::new(1, 5).unwrap(), Trig::Cos).unwrap();
/// assert_eq!(c.to_string(), "(1 + sqrt(5))/4");
/// ```
///
/// # Errors
/// [`TrigRefusal::Limit`] for a value past a limit (the degree of `cos(2*pi/1009)`);
/// [`TrigRefusal::Why`] with the reason in words: a denominator outside [`TRIG_DENOMINATORS`],
/// `tan` at a zero of the cosine, a square root `C` does not have (over [`Rational`],
/// `cos(pi/4)`).
pub fn trig_constant<C: Coefficient>(r: &Rational, which: Trig) -> Result<C, TrigRefusal> {
    if let Some(v) = C::trig_of_pi(r, which) {
        return v;
    }
    table_constant(r, which).map_err(TrigRefusal::Why)
}

/// The error of the call `name` at `pos` whose constant angle has no value: a limit stays a
/// limit ([`ExprError::CallLimit`]), every other reason is a bad call.
fn refused_call(pos: usize, name: &str, refusal: TrigRefusal) -> ExprError {
    match refusal {
        TrigRefusal::Limit(error) => ExprError::CallLimit {
            pos,
            name: name.to_string(),
            error,
        },
        TrigRefusal::Why(why) => ExprError::BadCall {
            pos,
            name: name.to_string(),
            why,
        },
    }
}

/// [`trig_constant`] from the built-in table of angles `(p/q) pi`, `q` in [`TRIG_DENOMINATORS`].
fn table_constant<C: Coefficient>(r: &Rational, which: Trig) -> Result<C, String> {
    let shown = angle_text(r);
    let twelfths = r * &Rational::from_integer(12);
    if !twelfths.is_integer() {
        return Err(format!(
            "{}({shown}) is not supported next to variables: exact values are built in for angles \
             (p/q)*pi with q in {}, not q = {} (every q is exact in an identity between constants)",
            which.name(),
            TRIG_DENOMINATORS
                .iter()
                .map(u32::to_string)
                .collect::<Vec<_>>()
                .join(", "),
            r.denom()
        ));
    }
    let n = (twelfths.numer() % 24i32)
        .to_i64()
        .expect("reduced modulo 24") as i32;
    let n = n.rem_euclid(24);
    let cos_at = |n: i32| -> Result<C, String> {
        let n = n.rem_euclid(24);
        let k = if n > 12 { 24 - n } else { n } as usize;
        let mut acc = C::zero();
        for &(num, den, d) in COS_TWELFTHS[k] {
            let q = Rational::new(num, den).expect("the table's denominators are not zero");
            let mut term = C::from_rational(&q)
                .ok_or_else(|| format!("{q} has no image in the coefficient ring"))?;
            if d != 1 {
                let root = C::from_rational(&Rational::from_integer(i64::from(d)))
                    .and_then(|x| x.try_sqrt())
                    .ok_or_else(|| {
                        format!(
                            "the value of {}({shown}) has sqrt({d}), which does not lie in the \
                             coefficient field{}",
                            which.name(),
                            C::sqrt_hint()
                        )
                    })?;
                term = term.mul_ref(&root);
            }
            acc += term;
        }
        Ok(acc)
    };
    match which {
        Trig::Cos => cos_at(n),
        Trig::Sin => cos_at(6 - n),
        Trig::Tan => {
            let c = cos_at(n)?;
            let inv = c
                .try_inverse()
                .ok_or_else(|| format!("tan({shown}) is undefined: cos({shown}) = 0"))?;
            Ok(cos_at(6 - n)?.mul_ref(&inv))
        }
    }
}

pub(crate) use crate::coefficient::angle_text;

// ------------------------------------------------------------------------------ arguments

/// An angle `sum c_i x_i + r + s pi`: rational multiples of angle variables, a rational number
/// (radians) and a rational multiple of pi.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct LinearAngle {
    /// The angle variables and their multiples (non-zero), in order of appearance.
    pub terms: Vec<(String, Rational)>,
    /// The rational number part (`1` in `sin(x + 1)`).
    pub constant: Rational,
    /// The multiple of pi.
    pub pi: Rational,
}

/// What an angle may be, for the refusals.
pub(super) const ANGLE_FORM: &str = "angles are rational combinations of angle variables plus a \
     rational number and a rational multiple of pi, such as x/2 - y + 1 + pi/3";

/// The argument of the call `call` (`name(arg)`) as an angle, or why it is not one.
pub(super) fn linear_angle(
    call: &Expr,
    name: &str,
    args: &[Expr],
) -> Result<LinearAngle, ExprError> {
    let bad = |pos: usize, why: String| ExprError::BadCall {
        pos,
        name: name.to_string(),
        why,
    };
    let [arg] = args else {
        return Err(bad(
            call.pos,
            format!("takes one argument (an angle), not {}", args.len()),
        ));
    };
    let form = ANGLE_FORM;
    let mut scratch = Vars::new();
    let p: Poly<Rational> = match arg.to_poly(&mut scratch) {
        Ok(p) => p,
        Err(ExprError::NoSqrt { .. }) => {
            return Err(bad(
                arg.pos,
                format!(
                    "the angle {arg} is irrational (its sine has no exact value, and it is not \
                     an angle variable); {form}"
                ),
            ))
        }
        Err(e) => return Err(e),
    };
    if scratch.names().iter().any(|n| angle_of(n).is_some()) {
        return Err(bad(
            arg.pos,
            format!("the angle {arg} contains sin or cos; {form}"),
        ));
    }
    let mut terms = Vec::new();
    let mut constant = Rational::ZERO;
    let mut pi = Rational::ZERO;
    for (m, c) in p.terms() {
        match m.exponents().as_slice() {
            [] => constant = c.clone(),
            [(v, 1)] => {
                let var = scratch.name(*v).expect("a variable of the scratch table");
                if var == PI {
                    pi = c.clone();
                    continue;
                }
                terms.push((*v, var.to_string(), c.clone()));
            }
            _ => {
                return Err(bad(
                    arg.pos,
                    format!("the angle {arg} is not linear in its variables; {form}"),
                ))
            }
        }
    }
    // In order of appearance (the scratch table's order), so angles enter the caller's table
    // as they are written.
    terms.sort_by_key(|t| t.0);
    Ok(LinearAngle {
        terms: terms.into_iter().map(|(_, x, k)| (x, k)).collect(),
        constant,
        pi,
    })
}

// ------------------------------------------------------------------------------ expansion

/// The Chebyshev polynomials `T_k` and `U_{k-1}` (`k >= 1`) as integer coefficient vectors
/// (index = power of the cosine): `cos(k x) = T_k(cos x)`, `sin(k x) = sin x U_{k-1}(cos x)`.
fn chebyshev(k: usize) -> (Vec<BigInt>, Vec<BigInt>) {
    // t = [T_{n-1}, T_n], u = [U_{n-2}, U_{n-1}], from n = 1.
    let step = |prev: &[BigInt], cur: &[BigInt]| -> Vec<BigInt> {
        let mut next = vec![BigInt::zero(); cur.len() + 1];
        for (i, c) in cur.iter().enumerate() {
            next[i + 1] += c * 2;
        }
        for (i, c) in prev.iter().enumerate() {
            next[i] -= c;
        }
        next
    };
    let one = || vec![BigInt::from(1)];
    let (mut t0, mut t1) = (one(), vec![BigInt::zero(), BigInt::from(1)]);
    let (mut u0, mut u1) = (vec![BigInt::zero()], one());
    for _ in 1..k {
        let t2 = step(&t0, &t1);
        let u2 = step(&u0, &u1);
        (t0, t1) = (t1, t2);
        (u0, u1) = (u1, u2);
    }
    (t1, u1)
}

/// `(cos, sin)` of the angle of `call` as polynomials over `C` in the variables `cos(x)`, `sin(x)`
/// of its angle variables (added to `vars`, always in pairs).
pub(super) fn cos_sin<C: Coefficient>(
    call: &Expr,
    name: &str,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<(Poly<C>, Poly<C>), ExprError> {
    let angle = linear_angle(call, name, args)?;
    let constant = |which| {
        trig_constant::<C>(&angle.pi, which).map_err(|why| refused_call(call.pos, name, why))
    };
    let (c0, s0) = (constant(Trig::Cos)?, constant(Trig::Sin)?);
    let mut acc: Option<(Poly<C>, Poly<C>)> = None;
    let size = |e| size_error(e, call.pos);
    let int = |b: &BigInt| {
        C::from_rational(&Rational::from(b.clone())).ok_or_else(|| ExprError::Unrepresentable {
            pos: call.pos,
            number: b.to_string(),
        })
    };
    // Every part as a multiple of its base angle (`angle_base`): the variables' and the
    // rational constant's.
    let mut multiples = Vec::new();
    for (x, c) in &angle.terms {
        multiples.push(base_multiple(vars, Part::Variable(x), c, &args[0], name)?);
    }
    if !angle.constant.is_zero() {
        multiples.push(base_multiple(
            vars,
            Part::Constant,
            &angle.constant,
            &args[0],
            name,
        )?);
    }
    for (cv, sv, k) in &multiples {
        let (cv, sv) = (*cv, *sv);
        let (t, u) = chebyshev(k.unsigned_abs() as usize);
        let mut cos_terms = Vec::new();
        for (i, a) in t.iter().enumerate().filter(|(_, a)| !a.is_zero()) {
            cos_terms.push((vec![(cv, i as u32)], int(a)?));
        }
        let mut sin_terms = Vec::new();
        for (i, a) in u.iter().enumerate().filter(|(_, a)| !a.is_zero()) {
            let a = if *k < 0 { -a } else { a.clone() };
            sin_terms.push((vec![(cv, i as u32), (sv, 1)], int(&a)?));
        }
        let pair = (Poly::from_terms(cos_terms), Poly::from_terms(sin_terms));
        acc = Some(match acc {
            None => pair,
            Some((c, s)) => (
                c.try_mul(&pair.0)
                    .map_err(size)?
                    .sub_ref(&s.try_mul(&pair.1).map_err(size)?),
                c.try_mul(&pair.1)
                    .map_err(size)?
                    .add_ref(&s.try_mul(&pair.0).map_err(size)?),
            ),
        });
    }
    Ok(match acc {
        None => (Poly::constant(c0), Poly::constant(s0)),
        Some((c, s)) => (
            c.scale(&c0).sub_ref(&s.scale(&s0)),
            s.scale(&c0).add_ref(&c.scale(&s0)),
        ),
    })
}

/// `sin`, `cos` (or, when the cosine is a non-zero constant, `tan`) of the angle of `call` as a
/// polynomial over `C`. `tan` of a variable angle is a fraction: [`ExprError::NonConstantDivisor`]
/// here, converted by [`Expr::to_ratfun`].
pub(super) fn trig_poly<C: Coefficient>(
    call: &Expr,
    which: Trig,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<Poly<C>, ExprError> {
    let (c, s) = cos_sin::<C>(call, which.name(), args, vars)?;
    match which {
        Trig::Cos => Ok(c),
        Trig::Sin => Ok(s),
        Trig::Tan => match c.constant_value() {
            Some(k) => match k.try_inverse() {
                Some(inv) => Ok(s.scale(&inv)),
                None => Err(undefined_tan(call, args)),
            },
            None => Err(ExprError::NonConstantDivisor { pos: call.pos }),
        },
    }
}

/// `sin`, `cos` or `tan` of the angle of `call` as a rational function over `C` (`tan = sin/cos`,
/// the cosine a condition).
pub(super) fn trig_ratfun<C: Coefficient + Field>(
    call: &Expr,
    which: Trig,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<RatFun<C>, ExprError> {
    let (c, s) = cos_sin::<C>(call, which.name(), args, vars)?;
    match which {
        Trig::Cos => Ok(RatFun::from_poly(c)),
        Trig::Sin => Ok(RatFun::from_poly(s)),
        Trig::Tan => RatFun::from_poly(s)
            .div(&RatFun::from_poly(c))
            .map_err(|e| size_error(e, call.pos))?
            .ok_or_else(|| undefined_tan(call, args)),
    }
}

/// `e` with every `sin`, `cos` and `tan` replaced by its polynomial in the variables `cos(x)`,
/// `sin(x)` of its base angles (the expansion of the conversion, [`cos_sin`]; `cos(x/2)`,
/// `sin(x/2)` when `x` has a half, `cos(1)`, `sin(1)` for the constant angle) and `tan` by the
/// quotient `sin/cos`, the rest of the tree kept as written: for evaluators that work on the
/// tree (the randomized identity test), which then treat `cos(x)`, `sin(x)` as variables on the
/// unit circle ([`angles`] names them). The bases are `e`'s own
/// ([`super::register_angle_bases`]); [`expand_angles_in`] expands with a table's. The multiple
/// of pi of an angle must have a rational cosine and sine (callers split other multiples of pi
/// off first, [`super::abstract_constants`]).
///
/// ```
/// use exactcheck_exact::expr::{expand_angles, parse_expr};
/// let e = expand_angles(&parse_expr("sin(2*x) + tan(y)").unwrap()).unwrap();
/// assert_eq!(e.to_string(), "2*cos(x)*sin(x) + sin(y)/cos(y)");
/// let e = expand_angles(&parse_expr("sin(x) + cos(x/2)").unwrap()).unwrap();
/// assert_eq!(e.to_string(), "2*cos(x/2)*sin(x/2) + cos(x/2)");
/// ```
///
/// # Errors
/// The conversion's errors of a call: an angle that is not a rational combination of variables
/// plus a constant, an angle multiple past the `angle-multiple` limit, a multiple of pi whose
/// value is irrational, `tan` where the cosine is zero.
pub fn expand_angles(e: &Expr) -> Result<Expr, ExprError> {
    let mut vars = Vars::new();
    super::register_angle_bases(&[e], &mut vars)?;
    expand_angles_in(e, &mut vars)
}

/// [`expand_angles`] with the base angles of `vars` (entered by
/// [`super::register_angle_bases`] for everything expanded together).
///
/// # Errors
/// Those of [`expand_angles`].
pub fn expand_angles_in(e: &Expr, vars: &mut Vars) -> Result<Expr, ExprError> {
    if let ExprKind::Call(name, args) = &e.kind {
        if let Some(which) = Trig::from_name(name) {
            let (c, s) = cos_sin::<Rational>(e, name, args, vars)?;
            return Ok(match which {
                Trig::Cos => c.to_expr(vars),
                Trig::Sin => s.to_expr(vars),
                Trig::Tan => {
                    if c.is_zero() {
                        return Err(undefined_tan(e, args));
                    }
                    Expr::new(ExprKind::Product(vec![
                        (MulOp::Times, s.to_expr(vars)),
                        (MulOp::Divide, c.to_expr(vars)),
                    ]))
                }
            });
        }
    }
    e.try_map_children(|x| expand_angles_in(x, vars))
}

/// `tan` of an angle whose cosine is identically zero.
fn undefined_tan(call: &Expr, args: &[Expr]) -> ExprError {
    let arg = args.first().map(ToString::to_string).unwrap_or_default();
    ExprError::BadCall {
        pos: call.pos,
        name: "tan".into(),
        why: format!("tan({arg}) is undefined: cos({arg}) = 0"),
    }
}

/// The value of `sin`, `cos` or `tan` of a constant angle (`(p/q) pi`) in `C`.
pub(super) fn trig_value<C: Coefficient>(
    call: &Expr,
    which: Trig,
    args: &[Expr],
) -> Result<C, ExprError> {
    let angle = linear_angle(call, which.name(), args)?;
    if let Some((x, _)) = angle.terms.first() {
        return Err(ExprError::NotConstant {
            pos: args[0].pos,
            name: x.clone(),
            hint: "",
        });
    }
    if !angle.constant.is_zero() {
        return Err(transcendental_value(which.name(), args, &angle));
    }
    trig_constant::<C>(&angle.pi, which).map_err(|why| refused_call(call.pos, which.name(), why))
}

/// The refusal of an exact value for an angle with a rational constant part (`sin(1)`): by
/// Lindemann–Weierstrass its cosine and sine are transcendental.
fn transcendental_value(name: &str, args: &[Expr], angle: &LinearAngle) -> ExprError {
    let arg = &args[0];
    let what = if angle.pi.is_zero() {
        format!("the angle {arg}")
    } else {
        format!("the constant part {} of the angle {arg}", angle.constant)
    };
    ExprError::BadCall {
        pos: arg.pos,
        name: name.to_string(),
        why: format!(
            "{what} is not a rational multiple of pi (its sine is transcendental): it has no \
             exact value (an identity with it is still decided, by prove or an identity claim)"
        ),
    }
}

/// Whether the call `e` is `sin`, `cos` or `tan` of a constant angle with a rational part
/// (`sin(1)`, `cos(2 + pi/3)`): a constant without an exact value, decided as the cosine and
/// sine of the constant base angle ([`super::angle_base`]).
pub(super) fn is_transcendental_constant(e: &Expr) -> bool {
    let ExprKind::Call(name, args) = &e.kind else {
        return false;
    };
    Trig::from_name(name).is_some()
        && linear_angle(e, name, args).is_ok_and(|a| a.terms.is_empty() && !a.constant.is_zero())
}

/// Whether the tree has an angle with a rational number part (`sin(1)`, `cos(x + 1/2)`): its
/// statements are decided with the constant base angle ([`super::angle_base`]), not by value.
pub fn has_constant_angle(e: &Expr) -> bool {
    let mut found = false;
    super::library::map_tree(e, &mut |x| {
        if let ExprKind::Call(name, args) = &x.kind {
            found |= Trig::from_name(name).is_some()
                && linear_angle(x, name, args).is_ok_and(|a| !a.constant.is_zero());
        }
    });
    found
}

/// Whether the tree calls `sin`, `cos` or `tan`.
pub fn has_trig(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => false,
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => has_trig(x),
        ExprKind::Pow(a, b) => has_trig(a) || has_trig(b),
        ExprKind::Sum(ts) => ts.iter().any(|(_, t)| has_trig(t)),
        ExprKind::Product(fs) => fs.iter().any(|(_, f)| has_trig(f)),
        ExprKind::Call(name, args) => Trig::from_name(name).is_some() || args.iter().any(has_trig),
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::expr::parse_expr;
    use crate::prove::{decide, Decision};
    use crate::Radical;
    use proptest::prelude::*;

    fn radical_poly(text: &str, vars: &mut Vars) -> Poly<Radical> {
        parse_expr(text).unwrap().to_poly(vars).unwrap()
    }

    /// Decides `lhs = rhs` with the circles of the angles.
    pub(in crate::expr) fn decide_trig(lhs: &str, rhs: &str) -> Decision<Radical> {
        let mut vars = Vars::new();
        let (l, r) = (parse_expr(lhs).unwrap(), parse_expr(rhs).unwrap());
        crate::expr::register_angle_bases(&[&l, &r], &mut vars).unwrap();
        let l: RatFun<Radical> = l.to_ratfun(&mut vars).unwrap();
        let r: RatFun<Radical> = r.to_ratfun(&mut vars).unwrap();
        let res = l
            .numerator()
            .try_mul(r.denominator())
            .unwrap()
            .sub_ref(&r.numerator().try_mul(l.denominator()).unwrap());
        let rels: Vec<Poly<Radical>> = angles(&vars).iter().map(Angle::relation).collect();
        decide(&res, &rels, vars.len()).unwrap()
    }

    fn proved(lhs: &str, rhs: &str) -> bool {
        matches!(decide_trig(lhs, rhs), Decision::Proved { .. })
    }

    #[test]
    fn constants_agree_with_libm() {
        // An independent check of the table: every twelfth of pi against the floating-point
        // sine and cosine.
        for n in -30i64..30 {
            let r = Rational::new(n, 12).unwrap();
            let x = n as f64 * std::f64::consts::PI / 12.0;
            let c: Radical = trig_constant(&r, Trig::Cos).unwrap();
            let s: Radical = trig_constant(&r, Trig::Sin).unwrap();
            assert!((c.to_f64() - x.cos()).abs() < 1e-12, "cos({n} pi/12)");
            assert!((s.to_f64() - x.sin()).abs() < 1e-12, "sin({n} pi/12)");
            assert!((c.square() + s.square()).is_one());
            match trig_constant::<Radical>(&r, Trig::Tan) {
                Ok(t) => assert!((t.to_f64() - x.tan()).abs() < 1e-9, "tan({n} pi/12)"),
                Err(why) => {
                    assert!(
                        c.is_zero() && why.to_string().contains("undefined"),
                        "{why}"
                    );
                }
            }
        }
    }

    #[test]
    fn constants_refused_outside_the_field() {
        let e = trig_constant::<Radical>(&Rational::new(2, 5).unwrap(), Trig::Sin)
            .unwrap_err()
            .to_string();
        assert!(e.contains("q = 5"), "{e}");
        let e = trig_constant::<Rational>(&Rational::new(1, 4).unwrap(), Trig::Cos)
            .unwrap_err()
            .to_string();
        assert!(e.contains("sqrt(2)"), "{e}");
        let half: Rational = trig_constant(&Rational::new(1, 6).unwrap(), Trig::Sin).unwrap();
        assert_eq!(half, Rational::new(1, 2).unwrap());
    }

    #[test]
    fn chebyshev_polynomials() {
        let (t, u) = chebyshev(3);
        let ints = |v: &[i64]| v.iter().map(|&k| BigInt::from(k)).collect::<Vec<_>>();
        assert_eq!(t, ints(&[0, -3, 0, 4]));
        assert_eq!(u, ints(&[-1, 0, 4]));
        let (t, u) = chebyshev(1);
        assert_eq!((t, u), (ints(&[0, 1]), ints(&[1])));
    }

    #[test]
    fn identities_proved_and_false_ones_rejected() {
        assert!(proved("sin(x)^2 + cos(x)^2", "1"));
        assert!(proved("sin(3x)", "3 sin(x) - 4 sin(x)^3"));
        assert!(proved("cos(x + y)", "cos(x) cos(y) - sin(x) sin(y)"));
        assert!(proved("sin(x - y)", "sin(x) cos(y) - cos(x) sin(y)"));
        assert!(proved("cos(-5x)", "cos(5x)"));
        assert!(proved("sin(x + pi)", "-sin(x)"));
        assert!(proved("cos(x + pi/2)", "-sin(x)"));
        assert!(proved("sin(x + pi/4)", "sqrt(2)/2 (sin(x) + cos(x))"));
        assert!(proved("tan(x + pi/4)", "(1 + tan(x))/(1 - tan(x))"));
        assert!(proved("tan(2x)", "2 tan(x)/(1 - tan(x)^2)"));
        assert!(proved("cos(pi/12)", "(sqrt(6) + sqrt(2))/4"));
        // Every path has a false identity it rejects: the multiple angle, the sum, the
        // constant, the fraction.
        for (l, r) in [
            ("sin(3x)", "3 sin(x) - 3 sin(x)^3"),
            ("cos(x + y)", "cos(x) cos(y) + sin(x) sin(y)"),
            ("sin(x + pi/3)", "sin(x)/2 + cos(x)/2"),
            ("tan(2x)", "2 tan(x)/(1 + tan(x)^2)"),
            ("cos(2x)", "1"),
        ] {
            match decide_trig(l, r) {
                Decision::Fails { point, value, .. } => {
                    assert!(!value.is_zero());
                    assert!(!point.is_empty());
                }
                other => panic!("{l} = {r}: {other:?}"),
            }
        }
        assert!(matches!(
            decide_trig("cos(pi/3)", "sqrt(3)/2"),
            Decision::Fails { .. }
        ));
    }

    #[test]
    fn constant_values_and_errors() {
        let v = |t: &str| parse_expr(t).unwrap().eval_constant::<Radical>();
        assert_eq!(v("cos(pi/4)").unwrap(), v("sqrt(2)/2").unwrap());
        assert_eq!(v("tan(pi/12)").unwrap(), v("2 - sqrt(3)").unwrap());
        assert_eq!(v("sin(-7pi/6)").unwrap(), v("1/2").unwrap());
        assert_eq!(v("cos(2*pi/3/2)").unwrap(), v("1/2").unwrap());
        let err = |t: &str| v(t).unwrap_err().to_string();
        assert!(
            err("tan(pi/2)").contains("undefined"),
            "{}",
            err("tan(pi/2)")
        );
        assert!(err("sin(x)").contains("'x'"), "{}", err("sin(x)"));
        assert!(err("sin(1)").contains("not a rational multiple of pi"));
        assert!(err("cos(2 + pi/3)").contains("the constant part 2"));
        assert!(err("cos(pi/5)").contains("not supported"));
        assert!(err("pi").contains("transcendental"), "{}", err("pi"));
        let mut vars = Vars::new();
        let conv = |t: &str, vars: &mut Vars| {
            parse_expr(t)
                .unwrap()
                .to_poly::<Radical>(vars)
                .unwrap_err()
                .to_string()
        };
        assert!(conv("sin(x^2)", &mut vars).contains("not linear"));
        // An integrand with a fraction of the integration variable's angle is refused.
        let half = conv("integrate(sin(t/2), t, 0, x)", &mut Vars::new());
        assert!(half.contains("t/2"), "{half}");
        let irrational = conv("sin(sqrt(2))", &mut vars);
        assert!(irrational.contains("is irrational"), "{irrational}");
        assert!(conv("sin(x y)", &mut vars).contains("not linear"));
        assert!(conv("sin(sin(x))", &mut vars).contains("contains sin or cos"));
        assert!(conv("sin(x, y)", &mut vars).contains("one argument"));
        assert!(conv("sin(100000 x)", &mut vars).contains("angle-multiple"));
        assert!(conv("tan(x)", &mut vars).contains("non-constant"));
        assert!(conv("diff(x, pi)", &mut vars).contains("pi is a constant"));
    }

    /// `text` parsed, with a table holding its base angles.
    fn with_bases(text: &str) -> (Expr, Vars) {
        let e = parse_expr(text).unwrap();
        let mut vars = Vars::new();
        crate::expr::register_angle_bases(&[&e], &mut vars).unwrap();
        (e, vars)
    }

    fn fails(lhs: &str, rhs: &str) -> bool {
        matches!(decide_trig(lhs, rhs), Decision::Fails { value, .. } if !value.is_zero())
    }

    #[test]
    fn half_angles_and_rational_multiples() {
        // Weierstrass: t = tan(x/2).
        assert!(proved("sin(x)", "2 tan(x/2)/(1 + tan(x/2)^2)"));
        assert!(proved("cos(x)", "(1 - tan(x/2)^2)/(1 + tan(x/2)^2)"));
        assert!(proved("tan(x)", "2 tan(x/2)/(1 - tan(x/2)^2)"));
        assert!(proved("cos(x)", "1 - 2 sin(x/2)^2"));
        assert!(proved("sin(x/2)^2", "(1 - cos(x))/2"));
        assert!(proved("cos(3x/4)", "4 cos(x/4)^3 - 3 cos(x/4)"));
        assert!(proved("sin(x/2 + x/3)", "sin(5x/6)"));
        assert!(proved("cos(x/2 - y)", "cos(x/2) cos(y) + sin(x/2) sin(y)"));
        assert!(fails("sin(x)", "2 tan(x/2)/(1 - tan(x/2)^2)"));
        assert!(fails("cos(x)", "1 - 2 cos(x/2)^2"));
        assert!(fails("sin(x/2)", "sin(x)/2"));
        // The base angle's variables read back: x/6 for the denominators 2 and 3.
        let (e, mut vars) = with_bases("sin(x/2) + cos(2x/3)");
        let p: Poly<Rational> = e.to_poly(&mut vars).unwrap();
        assert_eq!(vars.names()[..2], ["cos(x/6)", "sin(x/6)"]);
        let again: Poly<Rational> = parse_expr(&p.display(&vars).to_string())
            .unwrap()
            .to_poly(&mut vars)
            .unwrap();
        assert_eq!(p, again);
        // The multiple in the base angle is what the limit bounds.
        let (e, mut vars) = with_bases("sin(x/1001) + sin(x)");
        let err = e.to_poly::<Rational>(&mut vars).unwrap_err().to_string();
        assert!(
            err.contains("angle-multiple") && err.contains("1001 times"),
            "{err}"
        );
        // Converted apart, the second expression finds a base it is no multiple of.
        let mut vars = Vars::new();
        radical_poly("sin(x)", &mut vars);
        let err = parse_expr("sin(x/2)")
            .unwrap()
            .to_poly::<Radical>(&mut vars)
            .unwrap_err()
            .to_string();
        assert!(err.contains("base angle x"), "{err}");
    }

    #[test]
    fn constant_angles_decided_by_lindemann_weierstrass() {
        assert!(proved("sin(2)", "2 sin(1) cos(1)"));
        assert!(proved("cos(1)^2 + sin(1)^2", "1"));
        assert!(proved("cos(1/2)^2", "(1 + cos(1))/2"));
        assert!(proved("sin(2 + pi/3)", "sin(2)/2 + sqrt(3)/2 cos(2)"));
        assert!(proved("tan(1)", "sin(1)/cos(1)"));
        assert!(proved("sin(x + 1)", "sin(x) cos(1) + cos(x) sin(1)"));
        assert!(proved("1/sin(1)", "sin(1)/(1 - cos(1)^2)"));
        // A constant bound of an integral is an angle too.
        assert!(proved("integrate(sin(t), t, 0, 1)", "1 - cos(1)"));
        assert!(fails("sin(1)", "0"));
        assert!(fails("sin(2)", "2 sin(1)"));
        assert!(fails("cos(2)", "1 - sin(1)^2"));
        // The constant angle is the rational gcd of the constant parts: 2/3 for 2 and 4/3.
        let (_, vars) = with_bases("sin(2) + cos(4/3)");
        assert_eq!(vars.names(), ["cos(2/3)", "sin(2/3)"]);
        assert_eq!(
            crate::expr::constant_base(&vars).map(|(_, b)| b),
            Some(Base::Constant(Rational::new(2, 3).unwrap()))
        );
        assert!(crate::expr::lindemann_weierstrass("2/3").contains("e^(2 i/3)"));
    }

    #[test]
    fn derivatives_by_the_chain_rule() {
        assert!(proved("diff(sin(x), x)", "cos(x)"));
        assert!(proved("diff(cos(3x), x)", "-3 sin(3x)"));
        assert!(proved("diff(x sin(x), x)", "sin(x) + x cos(x)"));
        assert!(proved("diff(tan(x), x)", "1/cos(x)^2"));
        assert!(proved("diff(sin(x), x, 4)", "sin(x)"));
        assert!(proved("diff(sin(y), x)", "0"));
        assert!(!proved("diff(sin(2x), x)", "cos(2x)"));
        assert!(proved("diff(sin(x/2), x)", "cos(x/2)/2"));
        assert!(proved("diff(tan(x/2), x)", "(1 + tan(x/2)^2)/2"));
        assert!(proved("diff(x cos(x/3), x)", "cos(x/3) - x sin(x/3)/3"));
        assert!(!proved("diff(sin(x/2), x)", "cos(x/2)"));
    }

    #[test]
    fn angles_of_a_table_and_points() {
        let mut vars = Vars::new();
        radical_poly("sin(2a + b) + x", &mut vars);
        let names: Vec<String> = angles(&vars).into_iter().map(|a| a.name).collect();
        assert_eq!(names, ["a", "b"]);
        let point = [
            ("cos(a)".to_string(), "3/5".to_string()),
            ("x".to_string(), "2".to_string()),
            ("sin(a)".to_string(), "4/5".to_string()),
        ];
        assert_eq!(
            describe_point(&point),
            ["a = angle with cos a = 3/5, sin a = 4/5", "x = 2"]
        );
        let point = [
            ("cos(1)".to_string(), "0".to_string()),
            ("sin(1)".to_string(), "1".to_string()),
            ("cos(a/2)".to_string(), "3/5".to_string()),
            ("sin(a/2)".to_string(), "4/5".to_string()),
        ];
        assert_eq!(
            describe_point(&point),
            ["a = angle with cos(a/2) = 3/5, sin(a/2) = 4/5"]
        );
    }

    /// `(cos, sin)` of `k` times the angle at the circle point of `u`, by repeated complex
    /// multiplication of the rational point (independent of the Chebyshev expansion).
    fn power_of_point(u: &Rational, k: i64) -> (Rational, Rational) {
        let den = (Rational::ONE + u.square()).inv().unwrap();
        let c = (Rational::ONE - u.square()) * &den;
        let s = u.scale_i64(2) * &den;
        let (mut pc, mut ps) = (Rational::ONE, Rational::ZERO);
        for _ in 0..k.unsigned_abs() {
            (pc, ps) = (&pc * &c - &ps * &s, &pc * &s + &ps * &c);
        }
        if k < 0 {
            ps = -ps;
        }
        (pc, ps)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// `sin` and `cos` of `a x + b y + (n/12) pi`, expanded, agree with the angle evaluated
        /// exactly at rational points of the two circles.
        #[test]
        fn expansion_matches_evaluation_at_circle_points(
            a in -12i64..=12, b in -12i64..=12, n in -24i64..=24,
            un in -9i64..=9, ud in 1i64..=5, vn in -9i64..=9, vd in 1i64..=5,
        ) {
            let text = format!("{a}*x + {b}*y + {n}*pi/12");
            let mut vars = Vars::new();
            let cp = radical_poly(&format!("cos({text})"), &mut vars);
            let sp = radical_poly(&format!("sin({text})"), &mut vars);
            let (u, v) = (Rational::new(un, ud).unwrap(), Rational::new(vn, vd).unwrap());
            let (xc, xs) = power_of_point(&u, 1);
            let (yc, ys) = power_of_point(&v, 1);
            let mut point = vec![Radical::zero(); vars.len()];
            for (name, val) in [("cos(x)", &xc), ("sin(x)", &xs), ("cos(y)", &yc), ("sin(y)", &ys)] {
                if let Some(i) = vars.get(name) {
                    point[i as usize] = Radical::from(val.clone());
                }
            }
            let got_c = cp.eval(&point, Radical::clone);
            let got_s = sp.eval(&point, Radical::clone);
            // cos and sin of the whole angle: (a x) (b y) (n pi/12) as complex products.
            let (ac, as_) = power_of_point(&u, a);
            let (bc, bs) = power_of_point(&v, b);
            let (c1, s1) = (&ac * &bc - &as_ * &bs, &ac * &bs + &as_ * &bc);
            let r = Rational::new(n, 12).unwrap();
            let k0: Radical = trig_constant(&r, Trig::Cos).unwrap();
            let s0: Radical = trig_constant(&r, Trig::Sin).unwrap();
            let (c1, s1) = (Radical::from(c1), Radical::from(s1));
            let want_c = &c1 * &k0 - &s1 * &s0;
            let want_s = &s1 * &k0 + &c1 * &s0;
            prop_assert_eq!(got_c, want_c);
            prop_assert_eq!(got_s, want_s);
        }

        /// The false identity `sin(a x) = a sin(x)` (for `|a| >= 2`) is rejected with a
        /// counter-example, the true `sin(a x)^2 + cos(a x)^2 = 1` proved.
        #[test]
        fn multiple_angles_decided(a in 2i64..=9) {
            let identity = format!("sin({a} x)^2 + cos({a} x)^2");
            prop_assert!(proved(&identity, "1"));
            let is_fails = matches!(
                decide_trig(&format!("sin({a} x)"), &format!("{a} sin(x)")),
                Decision::Fails { .. }
            );
            prop_assert!(is_fails);
        }
    }
}
