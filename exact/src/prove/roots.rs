//! Square roots of expressions in identities: `sqrt(E)` of a non-constant `E` is the
//! non-negative real root, defined where `E >= 0`. The conversion ([`crate::expr`]) names each
//! distinct radicand by a variable `y`; here `y` gets its meaning: the relation `y^2 = E`
//! (passed to the decision with the other relations, so ideal membership proves what holds for
//! both roots `±sqrt(E)`; for a radicand that is a fraction `N/D` the relation is cleared to
//! `y^2 D - N = 0` and `D != 0` joins the hypotheses, as for any relation between fractions) and
//! the sign condition `y >= 0` (a [`VarDomain`], which the counter-example search respects — it
//! takes the non-negative root — and which the proof uses where the branch matters, see
//! `hypotheses`). `abs(E)` is the root of `E^2`.

use super::{real_zero_free, PointField, VarDomain};
use crate::expr::{Expr, ExprError, ExprKind};
use crate::poly::{Poly, Var, Vars};
use crate::ratfun::RatFun;
use crate::Radical;
use crate::Rational;
use exactcheck_core::Ring;

/// The square root `sqrt(E)` named by the variable `var`.
#[derive(Clone, Debug)]
pub struct SquareRoot<C: Ring> {
    /// The variable standing for the root.
    pub var: Var,
    /// `E`, expanded: a polynomial, or a fraction in lowest terms with the divisors of `E` as
    /// its conditions.
    pub radicand: RatFun<C>,
    /// `E` as written.
    pub text: String,
    /// Whether `E` is written as an even power (`E = F^2`, the radicand of `abs(F)`): then it
    /// is never negative.
    pub square: bool,
}

impl<C: PointField> SquareRoot<C> {
    /// The relation `y^2 = E` as two sides: for a fraction `E` the identity engine clears it to
    /// `y^2 D - N = 0` and adds the divisors of `E` to the hypotheses.
    pub fn relation(&self) -> (RatFun<C>, RatFun<C>) {
        let y = Poly::var(self.var);
        (RatFun::from_poly(y.mul_ref(&y)), self.radicand.clone())
    }

    /// The relation cleared of the denominator `D` of `E = N/D`: `y^2 D - N`, zero exactly when
    /// `y = ±sqrt(E)` where `D != 0`.
    pub fn cleared_relation(&self) -> Poly<C> {
        let y = Poly::var(self.var);
        y.mul_ref(&y)
            .mul_ref(self.radicand.denominator())
            .sub_ref(self.radicand.numerator())
    }

    /// `N D` for the radicand `E = N/D`: the sign of `E` wherever it is defined.
    fn sign_polynomial(&self) -> Poly<C> {
        self.radicand
            .numerator()
            .mul_ref(self.radicand.denominator())
    }

    /// The sign condition `y >= 0` (the root is the non-negative one).
    pub fn domain() -> VarDomain {
        VarDomain {
            lower: Some((Rational::ZERO, false)),
            upper: None,
            integer: false,
        }
    }

    /// Whether `E >= 0` at every real point where it is defined, shown by the sufficient sign
    /// test of the proofs on `N D` (`x^2 + y^2`, `1/(1 + t^2)`): the root is then defined
    /// wherever its radicand is.
    pub fn defined_everywhere(&self) -> bool {
        self.square || super::hypotheses::non_negative(&self.sign_polynomial(), &[])
    }

    /// The side condition under which the root is defined, `E >= 0`, printed.
    pub fn condition(&self) -> String {
        format!("{} >= 0", self.text)
    }
}

/// The square roots of non-constant expressions recorded in `vars` by the conversions (after
/// [`Vars::allow_roots`]), each with its radicand expanded over `C`. Converting a radicand
/// again finds the inner roots it contains already in the table, so no new variable appears.
///
/// # Errors
/// The conversion's [`ExprError`]s, and [`ExprError::NegativeRadicand`] for a radicand that is
/// negative at every real point (`sqrt(-1 - x^2)`, `sqrt(-1/(1 + x^2))`): a root defined
/// nowhere.
pub fn square_roots<C: PointField>(vars: &mut Vars) -> Result<Vec<SquareRoot<C>>, ExprError> {
    let entries = vars.roots().to_vec();
    let mut out = Vec::with_capacity(entries.len());
    for entry in entries {
        let written = entry.radicand_expr();
        let radicand = written.to_ratfun::<C>(vars)?;
        let root = SquareRoot {
            var: entry.var,
            radicand,
            text: written.to_string(),
            square: is_even_power(written),
        };
        if surely_negative(&root.sign_polynomial()) {
            return Err(ExprError::NegativeRadicand {
                pos: written.pos,
                arg: written.to_string(),
            });
        }
        out.push(root);
    }
    Ok(out)
}

/// Whether `e` is written as a power with an even constant exponent.
fn is_even_power(e: &Expr) -> bool {
    let ExprKind::Pow(_, k) = &e.kind else {
        return false;
    };
    k.eval_constant::<Rational>()
        .is_ok_and(|k| k.is_integer() && (k / Rational::from_integer(2)).is_integer())
}

/// Whether `p` (`N D` for a radicand `N/D`) is negative at every real point, by the sufficient test of
/// [`real_zero_free`] applied to `-p` and the sign of its constant term (a zero-free
/// polynomial with a negative value at the origin is negative everywhere).
fn surely_negative<C: PointField>(p: &Poly<C>) -> bool {
    let constant = p.coefficient(&[]);
    let negative_at_origin = constant.to_radical().is_some_and(|c| c < Radical::zero());
    negative_at_origin && real_zero_free(p) == Some(true)
}
