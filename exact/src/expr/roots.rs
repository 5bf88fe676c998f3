//! Square roots of non-constant expressions: `sqrt(E)` becomes a variable `y` of the table,
//! one per distinct expanded radicand, when the table allows it
//! ([`crate::poly::Vars::allow_roots`]). The relation `y^2 = E` and the sign condition `y >= 0`
//! that give the variable its meaning are built by [`crate::prove::square_roots`]; a caller that
//! does not add them must not allow roots (the variable alone would be a free unknown).

use super::{Expr, ExprError};
use crate::poly::{Poly, RootEntry, RootRadicand, Var, Vars};
use exactcheck_core::limits;
use std::any::Any;
use std::sync::Arc;

/// Expressions are compared structurally; the numbers in them are exact, so equality is an
/// equivalence (the table of roots, [`crate::poly::RootEntry`], needs `Eq`).
impl Eq for Expr {}

/// The radicand of a square-root variable is the formula as written.
impl RootRadicand for Expr {
    fn eq_radicand(&self, other: &dyn RootRadicand) -> bool {
        other.as_any().downcast_ref::<Expr>() == Some(self)
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
}

impl RootEntry {
    /// The radicand as written: every root of a table is recorded by the conversions of
    /// formulas (`root_variable`), with its formula.
    pub fn radicand_expr(&self) -> &Expr {
        self.radicand
            .as_any()
            .downcast_ref::<Expr>()
            .expect("the conversions of formulas record every root with its formula")
    }
}

/// The variable of `sqrt(arg)`, `radicand` being `arg` expanded (not a constant): the variable
/// already recorded for an equal radicand, else a new one named `sqrt(<arg as printed>)`.
///
/// # Errors
/// [`ExprError::NonConstantSqrt`] when the table does not allow roots; the `variables` limit.
pub(super) fn root_variable<C: super::Coefficient>(
    radicand: &Poly<C>,
    arg: &Expr,
    vars: &mut Vars,
) -> Result<Var, ExprError> {
    if !vars.roots_allowed() {
        return Err(ExprError::NonConstantSqrt { pos: arg.pos });
    }
    // The coefficient types print their values exactly in `Debug`, and the terms of a
    // polynomial are in a canonical order: equal radicands have equal keys.
    let key = format!("{radicand:?}");
    if let Some(v) = vars.root_by_key(&key) {
        return Ok(v);
    }
    let mut name = format!("sqrt({arg})");
    // A different radicand printed the same way (impossible for the printer's output, kept
    // apart all the same).
    while vars.get(&name).is_some() {
        name.push(' ');
    }
    limits::VARIABLES
        .check(vars.len() as u64 + 1)
        .map_err(|error| ExprError::Limit {
            pos: arg.pos,
            error,
        })?;
    Ok(vars.add_root(&name, Arc::new(arg.clone()), key))
}
