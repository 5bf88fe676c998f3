//! Printing: polynomials in the expression syntax of [`crate::expr`], with variable names from
//! a [`Vars`] table.

use super::*;
use exactcheck_core::Ring;
use std::fmt;

/// The name printed for a variable that has none in the table.
pub(crate) fn fallback_name(v: usize) -> String {
    format!("_x{v}")
}

/// Whether a printed coefficient needs parentheses as a factor (it has a top-level `+` or `-`
/// after its first character).
pub(super) fn needs_parens(s: &str) -> bool {
    let mut depth = 0i32;
    for (i, ch) in s.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            '+' | '-' if depth == 0 && i > 0 => return true,
            _ => {}
        }
    }
    false
}

/// Writes a polynomial in the expression syntax of [`crate::expr`], with coefficients printed by
/// `coeff` and variables named by `name`.
pub(super) fn write_poly<C>(
    p: &Poly<C>,
    f: &mut fmt::Formatter<'_>,
    coeff: impl Fn(&C) -> String,
    name: impl Fn(usize) -> String,
) -> fmt::Result {
    if p.is_empty() {
        return f.write_str("0");
    }
    for i in 0..p.len() {
        let s = coeff(&p.coeffs[i]);
        let (negative, mag) = match s.strip_prefix('-') {
            Some(rest) if !needs_parens(rest) => (true, rest.to_string()),
            _ => (false, s),
        };
        let mag = if needs_parens(&mag) {
            format!("({mag})")
        } else {
            mag
        };
        match (i, negative) {
            (0, true) => f.write_str("-")?,
            (0, false) => {}
            (_, true) => f.write_str(" - ")?,
            (_, false) => f.write_str(" + ")?,
        }
        let mut factors: Vec<String> = Vec::new();
        p.shape.for_each(p.mono(i), |v, e| {
            factors.push(if e == 1 {
                name(v)
            } else {
                format!("{}^{e}", name(v))
            })
        });
        if factors.is_empty() {
            f.write_str(&mag)?;
        } else {
            if mag != "1" {
                write!(f, "{mag}*")?;
            }
            f.write_str(&factors.join("*"))?;
        }
    }
    Ok(())
}

/// A polynomial with its variable names, for printing ([`Poly::display`]).
pub struct PolyDisplay<'a, C> {
    pub(super) poly: &'a Poly<C>,
    pub(super) vars: &'a Vars,
}

impl<C: Ring + fmt::Display> fmt::Display for PolyDisplay<'_, C> {
    /// The expression syntax of [`crate::expr`]: terms by decreasing monomial, e.g.
    /// `s^2 + c^2 - 1` or `3/4*x^2*y - x + 1/2`; it parses back to the same polynomial.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_poly(
            self.poly,
            f,
            |c| c.to_string(),
            |v| {
                self.vars
                    .name(v as Var)
                    .map_or_else(|| fallback_name(v), str::to_string)
            },
        )
    }
}

impl<C> Poly<C> {
    /// The polynomial printed with the names of `vars` (variables without a name print as
    /// `_x<index>`). The output parses back ([`crate::expr::parse_poly`]) to the same polynomial
    /// when the coefficients print in the expression syntax (as [`crate::Rational`] does).
    pub fn display<'a>(&'a self, vars: &'a Vars) -> PolyDisplay<'a, C> {
        PolyDisplay { poly: self, vars }
    }
}

impl<C: fmt::Debug> fmt::Debug for Poly<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_poly(self, f, |c| format!("{c:?}"), fallback_name)
    }
}
