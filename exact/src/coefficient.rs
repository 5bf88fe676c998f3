//! The coefficient types of the expression language: what a number type provides so that
//! formulas ([`crate::expr`]) can be converted into polynomials over it ([`Coefficient`]), and
//! the trigonometric functions a type may evaluate at rational multiples of pi ([`Trig`]).
//!
//! A leaf module below the number types ([`crate::rational`], [`crate::radical`],
//! [`crate::modp`], [`crate::algebraic`]) and the polynomials ([`crate::poly`]), which implement
//! or use the trait, and below [`crate::expr`], which converts with it and re-exports it
//! (`expr::Coefficient`, `expr::Trig`).

use crate::rational::Rational;
use exactcheck_core::limits::LimitError;
use exactcheck_core::Ring;
use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive};

/// A trigonometric function of the language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Trig {
    /// `sin`.
    Sin,
    /// `cos`.
    Cos,
    /// `tan = sin/cos`.
    Tan,
}

impl Trig {
    /// The function of this name ([`crate::expr::TRIG_FUNCTIONS`]).
    pub fn from_name(name: &str) -> Option<Trig> {
        match name {
            "sin" => Some(Trig::Sin),
            "cos" => Some(Trig::Cos),
            "tan" => Some(Trig::Tan),
            _ => None,
        }
    }

    /// The name, as written.
    pub fn name(self) -> &'static str {
        match self {
            Trig::Sin => "sin",
            Trig::Cos => "cos",
            Trig::Tan => "tan",
        }
    }
}

/// Why a coefficient type has no value for `sin`, `cos` or `tan` of a rational multiple of pi
/// ([`Coefficient::trig_of_pi`], [`crate::expr::trig_constant`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TrigRefusal {
    /// The value exists but is past a named limit (the degree of `cos(2*pi/1009)` past
    /// `algebraic-degree`): the limit's own error, so callers tell it from bad input by type.
    Limit(exactcheck_core::limits::LimitError),
    /// Anything else, in words: the value is undefined (`tan` where the cosine is zero) or not in
    /// the type (`cos(pi/5)` over the square-root field).
    Why(String),
}

impl std::fmt::Display for TrigRefusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TrigRefusal::Limit(e) => e.fmt(f),
            TrigRefusal::Why(why) => f.write_str(why),
        }
    }
}

impl From<String> for TrigRefusal {
    fn from(why: String) -> TrigRefusal {
        TrigRefusal::Why(why)
    }
}

/// What the conversion needs of a coefficient type: the image of a rational number, inverses (for
/// division by constants) and square roots (for `sqrt`).
///
/// Implemented here for [`Rational`]; a square-root field or a finite field implements it beside
/// its definition (`impl exactcheck_exact::expr::Coefficient for ...`).
pub trait Coefficient: Ring {
    /// The image of a rational number, `None` if it has none (e.g. a denominator divisible by the
    /// characteristic).
    fn from_rational(q: &Rational) -> Option<Self>;
    /// The inverse, `None` for zero (or any non-invertible element).
    fn try_inverse(&self) -> Option<Self>;
    /// A square root in the type, `None` if there is none.
    fn try_sqrt(&self) -> Option<Self>;
    /// The real root of index `n >= 2` in the type: for an odd `n` the one real root (of the
    /// sign of `self`), for an even `n` the non-negative root of a non-negative number; `None`
    /// when the type has none (the default has the square roots of [`Coefficient::try_sqrt`]
    /// only).
    ///
    /// # Errors
    /// A limit of the type (the `algebraic-degree` of a real algebraic number).
    fn try_nth_root(&self, n: u32) -> Result<Option<Self>, LimitError> {
        Ok(if n == 2 { self.try_sqrt() } else { None })
    }
    /// Why [`Coefficient::try_nth_root`] found no root of a higher index (appended to the
    /// error): by default, that such roots are taken in the real algebraic numbers.
    fn nth_root_hint() -> &'static str {
        " (roots of index 3 and higher of constants are taken in the real algebraic numbers)"
    }
    /// The absolute value `|c|` in the type, `None` if the type has none (the default: a type
    /// without an order, such as a finite field). For a real `c` it is `c` or `-c`, the one
    /// that is not negative; a complex number's is its modulus, when that root is in the type.
    fn try_abs(&self) -> Option<Self> {
        None
    }
    /// Appended to the error message when [`Coefficient::try_sqrt`] fails (e.g. which field
    /// would have the root); empty by default.
    fn sqrt_hint() -> &'static str {
        ""
    }
    /// The hint for this value's failed [`Coefficient::try_sqrt`] (e.g. that it is negative, or
    /// out of reach of factoring); [`Coefficient::sqrt_hint`] by default.
    fn sqrt_hint_for(&self) -> &'static str {
        Self::sqrt_hint()
    }
    /// A lower bound for the size in bits of the value that grows linearly under powers:
    /// `size_bits(x^k) >= k * size_bits(x)` (for a rational `n/d`,
    /// `floor(log2 |n|) + floor(log2 d)`; 0 for zero and units such as `±1`). The size limit
    /// `constant-bits` ([`exactcheck_core::limits::CONSTANT_BITS`]) predicts powers with it and checks results against it. The default,
    /// 0, suits types of fixed size (a finite field), which need no limit.
    fn size_bits(&self) -> u64 {
        0
    }
    /// Whether [`Coefficient::size_bits`] is at most `max`; a type may answer faster than by
    /// computing the size (every coefficient of every product is checked).
    fn size_within(&self, max: u64) -> bool {
        self.size_bits() <= max
    }
    /// The value of a name in a constant expression ([`crate::expr::Expr::eval_constant`]), `None` for a name
    /// the type does not define (the default: every name). [`crate::ComplexRadical`] defines `i`.
    fn named_constant(_name: &str) -> Option<Self> {
        None
    }
    /// `cos` (`which` [`Trig::Cos`]), `sin` or `tan` of the angle `r pi` when the type computes
    /// it for every rational `r` ([`crate::Algebraic`] does); `None`, the default, leaves it to
    /// the built-in table of [`crate::expr::trig_constant`], whose values lie in `Q(sqrt 2, sqrt 3)`.
    ///
    /// # Errors
    /// [`TrigRefusal::Limit`] for a value past a limit, [`TrigRefusal::Why`] with the reason in
    /// words (`tan` at a zero of the cosine).
    fn trig_of_pi(_r: &Rational, _which: Trig) -> Option<Result<Self, TrigRefusal>> {
        None
    }
    /// Checks the value against the named limits of its type (for
    /// [`crate::Radical`], the number of independent square roots,
    /// [`exactcheck_core::limits::RADICANDS`]); called on every folded constant and every
    /// coefficient of a sum or product, like [`Coefficient::size_within`]. `Ok` by default.
    ///
    /// # Errors
    /// The [`exactcheck_core::limits::LimitError`] of the limit exceeded.
    fn check_limits(&self) -> Result<(), exactcheck_core::limits::LimitError> {
        Ok(())
    }
}

/// `floor(log2 |n|)`, 0 for zero.
pub(crate) fn log2_floor(n: &BigInt) -> u64 {
    n.bits().saturating_sub(1)
}

impl Coefficient for Rational {
    fn from_rational(q: &Rational) -> Option<Self> {
        Some(q.clone())
    }
    fn try_inverse(&self) -> Option<Self> {
        self.recip().ok()
    }
    /// The non-negative root of a rational whose numerator and denominator are perfect squares.
    fn try_sqrt(&self) -> Option<Self> {
        let (n, d) = (self.numer(), self.denom());
        if n.is_negative() {
            return None;
        }
        let (rn, rd) = (n.sqrt(), d.sqrt());
        if &rn * &rn == n && &rd * &rd == d {
            Some(Rational::from(num_rational::BigRational::new(rn, rd)))
        } else {
            None
        }
    }
    /// The rational root of a rational whose numerator and denominator are perfect powers.
    fn try_nth_root(&self, n: u32) -> Result<Option<Self>, LimitError> {
        if n < 2 {
            return Ok((n == 1).then(|| self.clone()));
        }
        let (num, den) = (self.numer(), self.denom());
        if num.is_negative() && n % 2 == 0 {
            return Ok(None);
        }
        let root = |x: &BigInt| {
            let r = x.nth_root(n);
            (num_traits::Pow::pow(&r, n) == *x).then_some(r)
        };
        Ok(match (root(&num), root(&den)) {
            (Some(a), Some(b)) => Some(Rational::from(num_rational::BigRational::new(a, b))),
            _ => None,
        })
    }
    fn try_abs(&self) -> Option<Self> {
        Some(if self.signum() == exactcheck_core::Sign::Negative {
            self.neg_ref()
        } else {
            self.clone()
        })
    }
    fn sqrt_hint() -> &'static str {
        " (it is irrational: a radical coefficient field is needed)"
    }
    fn size_bits(&self) -> u64 {
        log2_floor(&self.numer()) + log2_floor(&self.denom())
    }
    /// Inline values (two machine words) are far below any limit used here.
    fn size_within(&self, max: u64) -> bool {
        (self.is_inline() && max >= 256) || self.size_bits() <= max
    }
}

/// `r pi` as written: `pi`, `-pi/2`, `3*pi/4`, `0`.
pub(crate) fn angle_text(r: &Rational) -> String {
    let (n, d) = (r.numer(), r.denom());
    let num = match n.to_i64() {
        Some(0) => return "0".into(),
        Some(1) => "pi".to_string(),
        Some(-1) => "-pi".to_string(),
        _ => format!("{n}*pi"),
    };
    if d == BigInt::from(1) {
        num
    } else {
        format!("{num}/{d}")
    }
}
