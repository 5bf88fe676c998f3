//! The variables of the bounds of sums with symbolic bounds (`sum(k, 1, n, k^2)`), which take
//! integer values, and the ranges `from <= to + 1` where the closed form of such a sum is the
//! sum ([`crate::expr::symbolic_sum_ranges`]). An identity with such sums is decided as an
//! identity of polynomials; its counter-example must give those variables integer values inside
//! every range: [`SumRanges::add_domains`] makes their domains integer (with the bound a range
//! in one variable gives, `n >= 0` for `sum(k, 1, n, E)`), and [`SumRanges::check`] turns a
//! failure whose point lies outside a range into `undecided`.

use super::identity::{IdentityReport, IdentityVerdict};
use super::{PointField, VarDomain};
use crate::expr::library::substitute;
use crate::expr::{symbolic_sum_ranges, Expr};
use crate::poly::{Poly, Var, Vars};
use crate::Rational;
use exactcheck_core::Sign;

/// The ranges of the symbolic sums of a statement.
#[derive(Clone, Debug, Default)]
pub struct SumRanges {
    ranges: Vec<(Expr, Expr)>,
}

impl SumRanges {
    /// The ranges of the symbolic sums of `exprs` (the sides, relations and hypotheses).
    pub fn of<'a>(exprs: impl IntoIterator<Item = &'a Expr>) -> SumRanges {
        SumRanges {
            ranges: exprs.into_iter().flat_map(symbolic_sum_ranges).collect(),
        }
    }

    /// Whether the statement has no symbolic sum.
    pub fn is_empty(&self) -> bool {
        self.ranges.is_empty()
    }

    /// The variables of the bounds, in order of first appearance.
    fn variables(&self) -> Vec<String> {
        let mut names = Vec::new();
        for (a, b) in &self.ranges {
            a.collect_variables(&mut names);
            b.collect_variables(&mut names);
        }
        names
    }

    /// Makes the domains of the bounds' variables integer in `doms` (adding a domain where
    /// there is none), with the bound `v >= c` or `v <= c` of a range whose length
    /// `to - from + 1` is `alpha v + beta` (constants `alpha != 0`, `beta`).
    pub fn add_domains(&self, vars: &Vars, doms: &mut Vec<(Var, VarDomain)>) {
        for name in self.variables() {
            let Some(v) = vars.get(&name) else { continue };
            let at = match doms.iter().position(|(w, _)| *w == v) {
                Some(i) => i,
                None => {
                    doms.push((v, VarDomain::all()));
                    doms.len() - 1
                }
            };
            let d = &mut doms[at].1;
            d.integer = true;
            for (a, b) in &self.ranges {
                let Some((alpha, beta)) = linear_length(a, b, &name) else {
                    continue;
                };
                let c = (-beta) * alpha.recip().expect("alpha is not zero");
                if alpha.signum() == Sign::Positive {
                    if d.lower.as_ref().is_none_or(|(lo, _)| *lo < c) {
                        d.lower = Some((c, false));
                    }
                } else if d.upper.as_ref().is_none_or(|(hi, _)| *hi > c) {
                    d.upper = Some((c, false));
                }
            }
        }
    }

    /// Turns a failure into `undecided` when its point gives a bound's variable a value that is
    /// not an integer or lies outside a range (`vars` names the point's variables).
    pub fn check<C: PointField>(&self, vars: &Vars, report: &mut IdentityReport<C>) {
        let IdentityVerdict::Fails {
            coordinate,
            normal_form,
            point,
            ..
        } = &report.verdict
        else {
            return;
        };
        let values: Vec<(String, Option<Rational>)> = point
            .iter()
            .filter_map(|(v, x)| Some((vars.name(*v)?.to_string(), x.to_rational())))
            .collect();
        let at = |e: &Expr| -> Option<Rational> {
            let mut e = e.clone();
            for (name, q) in &values {
                e = substitute(&e, name, &Expr::number(q.clone()?));
            }
            e.eval_constant::<Rational>().ok()
        };
        let outside = self.ranges.iter().find(|(a, b)| {
            !matches!((at(a), at(b)), (Some(lo), Some(hi))
                if lo.is_integer() && hi.is_integer() && lo <= &hi + &Rational::ONE)
        });
        if let Some((a, b)) = outside {
            report.verdict = IdentityVerdict::Undecided {
                coordinate: *coordinate,
                normal_form: normal_form.clone(),
                searched: format!(
                    "the sides differ as polynomials, but the point found is not an integer \
                     point where the range {a}..{b} of a sum holds ({a} <= {b} + 1), and none \
                     was found"
                ),
            };
        }
    }
}

/// `(alpha, beta)` when `to - from + 1 = alpha v + beta` for the variable `name` and rational
/// constants `alpha != 0`, `beta`.
fn linear_length(from: &Expr, to: &Expr, name: &str) -> Option<(Rational, Rational)> {
    let mut scratch = Vars::new();
    let v = scratch.var(name);
    let lo: Poly<Rational> = from.to_poly(&mut scratch).ok()?;
    let hi: Poly<Rational> = to.to_poly(&mut scratch).ok()?;
    let length = hi - lo + Poly::constant(Rational::ONE);
    if length.variables() != [v] || length.degree_in(v) != 1 {
        return None;
    }
    let alpha = length.coefficient(&[(v, 1)]);
    let beta = length.coefficient(&[]);
    Some((alpha, beta))
}
