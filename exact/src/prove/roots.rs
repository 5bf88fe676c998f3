//! Square roots of expressions in identities: `sqrt(E)` of a non-constant `E` is the
//! non-negative real root, defined where `E >= 0`. The conversion ([`crate::expr`]) names each
//! distinct radicand by a variable `y`; here `y` gets its meaning: the relation `y^2 - E = 0`
//! (passed to the decision with the other relations, so ideal membership proves what holds for
//! both roots `±sqrt(E)`) and the sign condition `y >= 0` (a [`VarDomain`], which the counter-example
//! search respects — it takes the non-negative root — and which the proof uses where the branch
//! matters, see `hypotheses`).

use super::{real_zero_free, PointField, VarDomain};
use crate::expr::ExprError;
use crate::poly::{Poly, Var, Vars};
use crate::Radical;
use crate::Rational;
use exactcheck_core::Ring;

/// The square root `sqrt(E)` named by the variable `var`.
#[derive(Clone, Debug)]
pub struct SquareRoot<C: Ring> {
    /// The variable standing for the root.
    pub var: Var,
    /// `E`, expanded.
    pub radicand: Poly<C>,
    /// `E` as written.
    pub text: String,
}

impl<C: Ring> SquareRoot<C> {
    /// `y^2 - E`: zero exactly when `y = ±sqrt(E)`.
    pub fn relation(&self) -> Poly<C> {
        Poly::var(self.var)
            .mul_ref(&Poly::var(self.var))
            .sub_ref(&self.radicand)
    }

    /// The sign condition `y >= 0` (the root is the non-negative one).
    pub fn domain() -> VarDomain {
        VarDomain {
            lower: Some((Rational::ZERO, false)),
            upper: None,
            integer: false,
        }
    }

    /// Whether `E >= 0` at every real point, shown by the sufficient sign test of the proofs
    /// (`x^2 + y^2`): the root is then defined everywhere.
    pub fn defined_everywhere(&self) -> bool
    where
        C: PointField,
    {
        super::hypotheses::non_negative(&self.radicand, &[])
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
/// negative at every real point (`sqrt(-1 - x^2)`): a root defined nowhere.
pub fn square_roots<C: PointField>(vars: &mut Vars) -> Result<Vec<SquareRoot<C>>, ExprError> {
    let entries = vars.roots().to_vec();
    let mut out = Vec::with_capacity(entries.len());
    for entry in entries {
        let written = entry.radicand_expr();
        let radicand = written.to_poly::<C>(vars)?;
        if surely_negative(&radicand) {
            return Err(ExprError::NegativeRadicand {
                pos: written.pos,
                arg: written.to_string(),
            });
        }
        out.push(SquareRoot {
            var: entry.var,
            radicand,
            text: written.to_string(),
        });
    }
    Ok(out)
}

/// Whether `p` is negative at every real point, by the sufficient test of
/// [`real_zero_free`] applied to `-p` and the sign of its constant term (a zero-free
/// polynomial with a negative value at the origin is negative everywhere).
fn surely_negative<C: PointField>(p: &Poly<C>) -> bool {
    let constant = p.coefficient(&[]);
    let negative_at_origin = constant.to_radical().is_some_and(|c| c < Radical::zero());
    negative_at_origin && real_zero_free(p) == Some(true)
}
