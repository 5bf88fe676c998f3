//! Helpers shared by the claim modules: printed formulas (kept as text, as printed) turned into
//! polynomials, and identities decided by the identity engine of `exactcheck-exact`
//! (`prove::decide_identity`), worded by the formatter `prove` and claims files use
//! ([`crate::phrase`]), each residual named by its label.

use super::{Equation, Erratum, Outcome, Verdict};
use crate::phrase::Phrasing;
use exactcheck_core::{Hom4, Ring};
use exactcheck_exact::expr::CoeffExpr;
use exactcheck_exact::expr::{parse_expr, parse_poly, Coefficient, Expr};
use exactcheck_exact::poly::{Poly, Var, Vars};
use exactcheck_exact::prove::{
    decide_identity, factored, EngineError, IdentitySpec, IdentityVerdict, Part, PointField,
    Statement, VarDomain,
};
use exactcheck_exact::ratfun::RatFun;
use exactcheck_exact::Rational;
use std::fmt::Display;

/// A polynomial context: named variables and the polynomials of the printed formulas.
pub struct Symbols {
    /// The variable names.
    pub vars: Vars,
}

impl Symbols {
    /// A context with these variables declared first (so their indices are 0, 1, ...).
    pub fn new(names: &[&str]) -> Self {
        Symbols {
            vars: Vars::from_names(names.iter().copied()),
        }
    }

    /// The polynomial of a printed formula.
    pub fn parse<C: Coefficient>(&mut self, printed: &str) -> Result<Poly<C>, String> {
        parse_poly::<C>(printed, &mut self.vars)
            .map_err(|e| format!("printed formula {printed:?}: {e}"))
    }

    /// A homogeneous 4-vector of printed coordinates.
    pub fn hom4<C: Coefficient>(&mut self, printed: [&str; 4]) -> Result<Hom4<Poly<C>>, String> {
        Ok(Hom4::new(
            self.parse(printed[0])?,
            self.parse(printed[1])?,
            self.parse(printed[2])?,
            self.parse(printed[3])?,
        ))
    }

    /// The variables `name0 .. name3` as a homogeneous 4-vector.
    pub fn hom4_vars<C: Coefficient>(&mut self, name: &str) -> Hom4<Poly<C>> {
        let v = |i: usize, vars: &mut Vars| vars.poly::<C>(&format!("{name}{i}"));
        Hom4::new(
            v(0, &mut self.vars),
            v(1, &mut self.vars),
            v(2, &mut self.vars),
            v(3, &mut self.vars),
        )
    }
}

/// Decides that every residual is zero (modulo `relations`): `proved` when all expand to zero,
/// `fails` with the counter-example of the first that does not, `undecided` when the engine
/// finds neither (or the relations are inconsistent). [`prove_all_in`] without domains.
pub fn prove_all<C: PointField + Display + CoeffExpr>(
    sym: &Symbols,
    residuals: &[(&str, Poly<C>)],
    relations: &[Poly<C>],
    method: &str,
) -> Outcome
where
    C::Value: CoeffExpr,
{
    prove_all_in(sym, residuals, &[], relations, &[], method)
}

/// [`prove_all`] for the variables' values in `domains` (e.g. radii `> 0`): counter-examples are
/// searched inside the domains only.
///
/// On `fails` the outcome carries an [`Erratum`] with the exact counter-example (`name = value`
/// for every variable of the residuals, of `sides` and of the relations: `sides` are the
/// statement's two sides when the caller has them, so that a variable that cancels from every
/// residual is given too) and the residual there (its normal form
/// modulo the relations `= value`); the caller adds the printed and the corrected forms.
pub fn prove_all_in<C: PointField + Display + CoeffExpr>(
    sym: &Symbols,
    residuals: &[(&str, Poly<C>)],
    sides: &[&Poly<C>],
    relations: &[Poly<C>],
    domains: &[(Var, VarDomain)],
    method: &str,
) -> Outcome
where
    C::Value: CoeffExpr,
{
    let undecided = |evidence: String| Outcome {
        verdict: Verdict::Undecided,
        method: method.into(),
        evidence,
        erratum: None,
    };
    let spec = IdentitySpec {
        relations: relations
            .iter()
            .map(|r| {
                (
                    RatFun::from_poly(r.clone()),
                    RatFun::from_poly(Poly::zero()),
                )
            })
            .collect(),
        domains: domains.to_vec(),
        context: sides.iter().copied().cloned().collect(),
        ..IdentitySpec::new(
            sym.vars.clone(),
            residuals
                .iter()
                .map(|(_, r)| Statement::Residual(r.clone()))
                .collect(),
        )
    };
    let phrasing = Phrasing {
        residuals: residuals.iter().map(|(w, _)| w.to_string()).collect(),
        ..Phrasing::new(&sym.vars)
    };
    let report = match decide_identity(&spec) {
        Ok(r) => r,
        Err(e) => {
            let k = match &e {
                EngineError::Decide(Part::Coordinate(k), _) => *k,
                _ => 0,
            };
            return undecided(format!("{}: {}", residuals[k].0, phrasing.error(&e)));
        }
    };
    let evidence = phrasing.evidence(&spec, &report);
    match &report.verdict {
        IdentityVerdict::Proved { .. } => Outcome {
            verdict: Verdict::Proved,
            method: method.into(),
            evidence,
            erratum: None,
        },
        IdentityVerdict::Undecided { .. } => undecided(evidence),
        IdentityVerdict::Fails {
            normal_form,
            point,
            value,
            ..
        } => {
            let name = |v: Var| {
                sym.vars
                    .name(v)
                    .expect("the engine reports only variables of the context")
            };
            let erratum = Erratum {
                counter_example: point
                    .iter()
                    .map(|(v, q)| Equation::new(Expr::var(name(*v)), q.to_expr()))
                    .collect(),
                residual: vec![Equation::new(
                    // Factored when that is shorter; the text is the engine's own printing,
                    // so it parses back.
                    parse_expr(&factored(normal_form, &sym.vars))
                        .unwrap_or_else(|_| normal_form.to_expr(&sym.vars)),
                    value.to_expr(),
                )],
                ..Erratum::default()
            };
            Outcome {
                verdict: Verdict::Fails,
                method: method.into(),
                evidence,
                erratum: Some(Box::new(erratum)),
            }
        }
    }
}

/// The seeded generator of the catalogue's exact random instances: the workspace's one generator
/// ([`exactcheck_core::Rng`]) with helpers for small exact values.
pub struct Rng(exactcheck_core::Rng);

impl Rng {
    /// A generator started from `seed` (same seed, same instances).
    pub fn new(seed: u64) -> Rng {
        Rng(exactcheck_core::Rng::new(seed))
    }
    /// The next 64 pseudo-random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0.next_u64()
    }
    /// Uniform in `lo..=hi`.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.0.below((hi - lo + 1) as u64) as i64
    }
    /// `n / d` with `|n| <= r`, `1 <= d <= den`.
    pub fn rational(&mut self, r: i64, den: i64) -> Rational {
        let n = self.int(-r, r);
        let d = self.int(1, den);
        Rational::new(n, d).expect("the denominator d >= 1 is not zero")
    }
    /// A non-zero rational as [`Rng::rational`].
    pub fn nonzero(&mut self, r: i64, den: i64) -> Rational {
        loop {
            let q = self.rational(r, den);
            if !q.is_zero() {
                return q;
            }
        }
    }
    /// A homogeneous vector of integers in `-r..=r` (possibly zero).
    pub fn hom4(&mut self, r: i64) -> Hom4<Rational> {
        Hom4(core::array::from_fn(|_| {
            Rational::from_integer(self.int(-r, r))
        }))
    }
    /// A non-zero homogeneous vector of integers in `-r..=r`.
    pub fn nonzero_hom4(&mut self, r: i64) -> Hom4<Rational> {
        loop {
            let h = self.hom4(r);
            if !h.is_zero() {
                return h;
            }
        }
    }
}
