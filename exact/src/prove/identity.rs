//! The identity engine: one spec in ([`IdentitySpec`]: the identity's coordinates as sides or
//! residuals, relations, domains, hypotheses `!= 0`, a corrected form, the variable names), one
//! typed report out ([`IdentityReport`]: verdict, normal form, side conditions, counter-example,
//! what was tried, the corrected form's own verdict). `prove`, claims files and the catalogue all
//! decide identities here, and the command-line tool words the report with one formatter.
//!
//! The steps are those of the module [`super`]: relations between fractions are cleared of their
//! denominators (which become hypotheses); a coordinate between polynomials (and no hypothesis)
//! is decided as the polynomial `lhs - rhs` ([`super::decide_in`]), anything else with the
//! denominators cleared ([`super::decide_fraction`]), a residual given as such with the
//! hypotheses as non-zero conditions ([`super::decide_where`]). Every coordinate is decided
//! (the report lists each one's verdict, [`IdentityReport::outcomes`]); the first that fails
//! decides the claim, else the first undecided one, else it is proved.

use super::{
    consistent_basis, counter_example, decide_fraction, decide_in, decide_where, domain_table,
    points, unit_circle_pairs, witness, DecideError, Decision, FractionIdentity, Hypothesis,
    PointField, Points, RadicalPoint, VarDomain,
};
use crate::poly::{Poly, SizeError, Var, Vars};
use crate::ratfun::RatFun;

/// One coordinate of an identity.
// An identity has a few coordinates, built once and never stored in bulk: boxing the sides
// would only add an allocation and noise at every construction.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum Statement<C: PointField> {
    /// `lhs = rhs`, each a rational function.
    Sides(RatFun<C>, RatFun<C>),
    /// `residual = 0`, a polynomial built by the caller (the catalogue's minors and residuals).
    Residual(Poly<C>),
}

/// What is to be decided.
#[derive(Clone, Debug)]
pub struct IdentitySpec<C: PointField> {
    /// The variable names (the polynomials below index them).
    pub vars: Vars,
    /// The coordinates of the identity (one for a scalar identity).
    pub coordinates: Vec<Statement<C>>,
    /// Relations `a = b` the variables satisfy.
    pub relations: Vec<(RatFun<C>, RatFun<C>)>,
    /// Domains of variables (counter-examples are searched inside them).
    pub domains: Vec<(Var, VarDomain)>,
    /// Polynomials assumed non-zero: the proof does not use them, a counter-example avoids their
    /// zeros (the denominators of relations between fractions join them).
    pub hypotheses: Vec<Poly<C>>,
    /// A corrected left side per coordinate (for [`Statement::Sides`]), to be proved equal to the
    /// right side under the same relations, domains and hypotheses.
    pub corrected: Option<Vec<RatFun<C>>>,
    /// Further polynomials of the statement whose variables a counter-example names (the
    /// catalogue's printed sides, when it decides residuals built from them).
    pub context: Vec<Poly<C>>,
}

impl<C: PointField> IdentitySpec<C> {
    /// A spec without relations, domains, hypotheses, correction or context.
    pub fn new(vars: Vars, coordinates: Vec<Statement<C>>) -> Self {
        IdentitySpec {
            vars,
            coordinates,
            relations: Vec::new(),
            domains: Vec::new(),
            hypotheses: Vec::new(),
            corrected: None,
            context: Vec::new(),
        }
    }
}

/// A hypothesis a proof used: a polynomial declared non-zero (by the user, or a denominator),
/// or the domain of a variable (its sign, or the sign condition of a square root).
#[derive(Clone, Debug, PartialEq)]
pub enum UsedHypothesis<C: exactcheck_core::Ring> {
    /// `p != 0`.
    NonZero(Poly<C>),
    /// The domain of the variable.
    Domain(Var),
    /// A sign shown on the domains of its variables (`1 - x > 0` on `-1 < x < 1`).
    Sign(super::SignFact<C>),
}

/// The verdict of the engine.
#[derive(Clone, Debug)]
pub enum IdentityVerdict<C: PointField> {
    /// Every coordinate is zero (modulo the relations, off the conditions).
    Proved {
        /// Terms of the expanded residuals before reduction, summed over the coordinates (0 when
        /// each expanded to zero outright).
        expanded_terms: usize,
        /// The hypotheses the proof used (empty when the relations alone prove it).
        used: Vec<UsedHypothesis<C>>,
    },
    /// A verified exact counter-example to coordinate `coordinate`.
    Fails {
        /// The coordinate (0-based).
        coordinate: usize,
        /// Its normal form modulo the relations (what the two sides differ by).
        normal_form: Poly<C>,
        /// The point, restricted to the variables of the statement, in index order.
        point: RadicalPoint,
        /// `lhs - rhs` there (for a residual: the residual).
        value: C::Value,
    },
    /// Coordinate `coordinate` has a non-zero normal form but no counter-example was found.
    Undecided {
        /// The coordinate (0-based).
        coordinate: usize,
        /// Its normal form.
        normal_form: Poly<C>,
        /// What the search tried, in words.
        searched: String,
    },
}

/// The verdict on one coordinate of an identity.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoordinateOutcome {
    /// The coordinate's two sides are equal.
    Proved,
    /// A verified counter-example to the coordinate was found.
    Fails,
    /// Its normal form is not zero, but no counter-example was found.
    Undecided,
}

/// The verdict on a corrected form (proved equal to the right side, or not).
#[derive(Clone, Debug)]
pub enum CorrectionVerdict<C: PointField> {
    /// Every coordinate of the corrected form is proved equal to its right side.
    Proved,
    /// Coordinate `coordinate` differs from its right side by `value` at a point.
    Differs {
        /// The coordinate (0-based).
        coordinate: usize,
        /// `corrected - rhs` at the counter-example.
        value: C::Value,
    },
    /// Coordinate `coordinate` reduces to a non-zero normal form, no counter-example found.
    Undecided {
        /// The coordinate (0-based).
        coordinate: usize,
        /// `corrected - rhs` reduced.
        normal_form: Poly<C>,
    },
}

/// What the engine found.
#[derive(Clone, Debug)]
pub struct IdentityReport<C: PointField> {
    /// The verdict.
    pub verdict: IdentityVerdict<C>,
    /// Per coordinate: whether it was decided with the denominators cleared.
    pub cleared: Vec<bool>,
    /// Per coordinate: its verdict.
    pub outcomes: Vec<CoordinateOutcome>,
    /// Per coordinate: the terms of its residual (polynomial or cleared) before reduction.
    pub residual_terms: Vec<usize>,
    /// The side conditions: every divisor of the sides, of the relations and every hypothesis,
    /// each once (the points where one vanishes are excluded).
    pub conditions: Vec<Poly<C>>,
    /// Whether the spec had relations.
    pub has_relations: bool,
    /// The corrected form's verdict, when the spec has one.
    pub correction: Option<CorrectionVerdict<C>>,
    /// For a proof under conditions (domains, relations, hypotheses, square roots): `true`
    /// when no real point satisfying them all was found and their emptiness was not decided
    /// either, so the claim may be vacuous. `false` otherwise.
    pub no_point_found: bool,
}

impl<C: PointField> IdentityReport<C> {
    /// Whether any coordinate was decided with the denominators cleared.
    pub fn cleared_any(&self) -> bool {
        self.cleared.iter().any(|c| *c)
    }

    /// The coordinates (0-based) whose verdict is `outcome`.
    pub fn coordinates_with(&self, outcome: CoordinateOutcome) -> Vec<usize> {
        (0..self.outcomes.len())
            .filter(|&k| self.outcomes[k] == outcome)
            .collect()
    }
}

/// Which part of the spec an error belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// Relation `#i` (0-based).
    Relation(usize),
    /// Coordinate `#i` of the identity (0-based).
    Coordinate(usize),
    /// Coordinate `#i` of the corrected form (0-based).
    Corrected(usize),
}

/// Why the engine gave no report.
#[derive(Clone, Debug)]
pub enum EngineError {
    /// Clearing denominators of `part` exceeded a size limit.
    Size(Part, SizeError),
    /// The decision on `part` failed: inconsistent relations, a bad domain, a limit.
    Decide(Part, DecideError),
}

impl std::fmt::Display for EngineError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EngineError::Size(_, e) => write!(f, "{e}"),
            EngineError::Decide(_, e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for EngineError {}

/// A coordinate ready to decide: its residual and, with fractions, the cleared identity.
struct Prepared<C: PointField> {
    residual: Poly<C>,
    fraction: Option<FractionIdentity<C>>,
}

/// Decides the identity of `spec`; see the module documentation.
///
/// # Errors
/// [`EngineError`] when clearing a denominator exceeds a limit, or a decision fails
/// (inconsistent relations, an empty or duplicate domain, a limit of the Gröbner basis).
pub fn decide_identity<C: PointField>(
    spec: &IdentitySpec<C>,
) -> Result<IdentityReport<C>, EngineError> {
    let nvars = spec.vars.len();
    // Relations between fractions are cleared of their denominators, which become hypotheses.
    let mut rels = Vec::new();
    let mut hypotheses: Vec<Poly<C>> = spec.hypotheses.clone();
    let mut relation_conditions = Vec::new();
    for (i, (a, b)) in spec.relations.iter().enumerate() {
        if a.is_polynomial() && b.is_polynomial() {
            rels.push(a.numerator().clone() - b.numerator());
        } else {
            let cleared =
                FractionIdentity::new(a, b).map_err(|e| EngineError::Size(Part::Relation(i), e))?;
            rels.push(cleared.residual);
            relation_conditions.extend(cleared.conditions);
        }
    }
    hypotheses.extend(relation_conditions);
    let prepare = |st: &Statement<C>, part: Part| -> Result<Prepared<C>, EngineError> {
        match st {
            Statement::Residual(p) => Ok(Prepared {
                residual: p.clone(),
                fraction: None,
            }),
            Statement::Sides(l, r)
                if l.is_polynomial() && r.is_polynomial() && hypotheses.is_empty() =>
            {
                Ok(Prepared {
                    residual: l.numerator().clone() - r.numerator(),
                    fraction: None,
                })
            }
            Statement::Sides(l, r) => {
                let f = FractionIdentity::new(l, r).map_err(|e| EngineError::Size(part, e))?;
                Ok(Prepared {
                    residual: f.residual.clone(),
                    fraction: Some(f),
                })
            }
        }
    };
    let decide = |p: &Prepared<C>, part: Part| -> Result<Decision<C>, EngineError> {
        match &p.fraction {
            None if hypotheses.is_empty() => decide_in(&p.residual, &rels, &spec.domains, nvars),
            None => decide_where(&p.residual, &rels, &hypotheses, &spec.domains, nvars),
            Some(f) => decide_fraction(f, &rels, &hypotheses, &spec.domains, nvars),
        }
        .map_err(|e| EngineError::Decide(part, e))
    };
    let prepared = spec
        .coordinates
        .iter()
        .enumerate()
        .map(|(k, st)| prepare(st, Part::Coordinate(k)))
        .collect::<Result<Vec<_>, _>>()?;
    let mut conditions: Vec<Poly<C>> = Vec::new();
    for p in prepared
        .iter()
        .filter_map(|p| p.fraction.as_ref())
        .flat_map(|f| &f.conditions)
        .chain(&hypotheses)
    {
        if !conditions.contains(p) {
            conditions.push(p.clone());
        }
    }
    // A counter-example names every variable of the sides (numerators and denominators, all
    // coordinates), the residuals, the relations, the conditions and the context; domains name
    // only those.
    let mut statement: Vec<&Poly<C>> = Vec::new();
    for st in &spec.coordinates {
        match st {
            Statement::Sides(l, r) => statement.extend([
                l.numerator(),
                l.denominator(),
                r.numerator(),
                r.denominator(),
            ]),
            Statement::Residual(p) => statement.push(p),
        }
    }
    statement.extend(&rels);
    statement.extend(&conditions);
    statement.extend(&spec.context);
    // Conditions without a common real point are refused before anything is decided on them
    // (after the errors of the domains and the relations, which come first).
    let vacuous = |e: DecideError| EngineError::Decide(Part::Coordinate(0), e);
    let dom = domain_table(&spec.domains, nvars).map_err(vacuous)?;
    let found = points(&rels, &conditions, &dom);
    if let Points::Empty(v) = found {
        consistent_basis(&rels, &unit_circle_pairs(&rels).1).map_err(vacuous)?;
        return Err(vacuous(DecideError::Vacuous(v)));
    }
    let mut expanded = 0;
    let mut used = Vec::new();
    let mut verdict = None;
    let mut undecided = None;
    let mut outcomes = Vec::new();
    for (k, p) in prepared.iter().enumerate() {
        match decide(p, Part::Coordinate(k))? {
            Decision::Proved {
                expanded_terms,
                hypotheses: indices,
                signs,
            } => {
                outcomes.push(CoordinateOutcome::Proved);
                expanded += expanded_terms;
                // The indices count the fraction's own conditions first, then the hypotheses,
                // as the decision was given them.
                let nonzero: Vec<&Poly<C>> = match &p.fraction {
                    None => hypotheses.iter().collect(),
                    Some(f) => f.conditions.iter().chain(&hypotheses).collect(),
                };
                for h in indices {
                    let u = match h {
                        Hypothesis::NonZero(i) => UsedHypothesis::NonZero(nonzero[i].clone()),
                        Hypothesis::Domain(v) => UsedHypothesis::Domain(v),
                    };
                    if !used.contains(&u) {
                        used.push(u);
                    }
                }
                for f in signs {
                    let u = UsedHypothesis::Sign(f);
                    if !used.contains(&u) {
                        used.push(u);
                    }
                }
            }
            Decision::Fails {
                normal_form,
                point,
                value,
            } => {
                outcomes.push(CoordinateOutcome::Fails);
                verdict.get_or_insert(IdentityVerdict::Fails {
                    coordinate: k,
                    normal_form,
                    point: counter_example(&point, &statement),
                    value,
                });
            }
            Decision::Undecided {
                normal_form,
                searched,
            } => {
                outcomes.push(CoordinateOutcome::Undecided);
                undecided.get_or_insert(IdentityVerdict::Undecided {
                    coordinate: k,
                    normal_form,
                    searched,
                });
            }
        }
    }
    let correction = match &spec.corrected {
        None => None,
        Some(forms) => {
            let mut found = CorrectionVerdict::Proved;
            for (j, (c, st)) in forms.iter().zip(&spec.coordinates).enumerate() {
                let Statement::Sides(_, r) = st else {
                    continue;
                };
                let p = prepare(&Statement::Sides(c.clone(), r.clone()), Part::Corrected(j))?;
                match decide(&p, Part::Corrected(j))? {
                    Decision::Proved { .. } => {}
                    Decision::Fails { value, .. } => {
                        found = CorrectionVerdict::Differs {
                            coordinate: j,
                            value,
                        };
                        break;
                    }
                    Decision::Undecided { normal_form, .. } => {
                        found = CorrectionVerdict::Undecided {
                            coordinate: j,
                            normal_form,
                        };
                        break;
                    }
                }
            }
            Some(found)
        }
    };
    let verdict = verdict.or(undecided).unwrap_or(IdentityVerdict::Proved {
        used,
        expanded_terms: expanded,
    });
    // Relations alone are read over the complex numbers: the warning needs a real condition.
    let real_conditions = !conditions.is_empty() || dom.iter().any(|d| *d != VarDomain::all());
    let no_point_found = matches!(verdict, IdentityVerdict::Proved { .. })
        && real_conditions
        && found == Points::Unknown
        && !witness(&rels, &conditions, &dom);
    Ok(IdentityReport {
        verdict,
        no_point_found,
        outcomes,
        cleared: prepared.iter().map(|p| p.fraction.is_some()).collect(),
        residual_terms: prepared.iter().map(|p| p.residual.len()).collect(),
        conditions,
        has_relations: !spec.relations.is_empty(),
        correction,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr;
    use crate::{Radical, Rational};
    use exactcheck_core::Ring;

    fn ratfun(text: &str, vars: &mut Vars) -> RatFun<Rational> {
        parse_expr(text).unwrap().to_ratfun(vars).unwrap()
    }

    fn spec(pairs: &[(&str, &str)], relations: &[(&str, &str)]) -> IdentitySpec<Rational> {
        let mut vars = Vars::new();
        let coordinates = pairs
            .iter()
            .map(|(l, r)| Statement::Sides(ratfun(l, &mut vars), ratfun(r, &mut vars)))
            .collect();
        let relations = relations
            .iter()
            .map(|(a, b)| (ratfun(a, &mut vars), ratfun(b, &mut vars)))
            .collect();
        IdentitySpec {
            relations,
            ..IdentitySpec::new(vars, coordinates)
        }
    }

    #[test]
    fn polynomial_identity_is_proved_without_conditions() {
        let r = decide_identity(&spec(&[("(x+1)^2", "x^2 + 2*x + 1")], &[])).unwrap();
        assert!(matches!(
            r.verdict,
            IdentityVerdict::Proved {
                expanded_terms: 0,
                ..
            }
        ));
        assert_eq!(r.cleared, [false]);
        assert!(r.conditions.is_empty() && r.correction.is_none() && !r.has_relations);
    }

    #[test]
    fn fractions_report_their_side_conditions() {
        let s = spec(&[("(x^2-1)/(x-1)", "x+1")], &[]);
        let r = decide_identity(&s).unwrap();
        assert!(matches!(r.verdict, IdentityVerdict::Proved { .. }));
        assert_eq!(r.cleared, [true]);
        let shown: Vec<String> = r
            .conditions
            .iter()
            .map(|p| p.display(&s.vars).to_string())
            .collect();
        assert_eq!(shown, ["x - 1"]);
    }

    #[test]
    fn a_false_coordinate_gives_a_verified_counter_example() {
        let s = spec(&[("x*y", "y*x"), ("(a+b)^2", "a^2 + b^2")], &[]);
        let r = decide_identity(&s).unwrap();
        let IdentityVerdict::Fails {
            coordinate,
            normal_form,
            point,
            value,
        } = r.verdict
        else {
            panic!("expected fails, got {:?}", r.verdict)
        };
        assert_eq!(coordinate, 1);
        assert_eq!(
            r.outcomes,
            [CoordinateOutcome::Proved, CoordinateOutcome::Fails]
        );
        assert_eq!(normal_form.display(&s.vars).to_string(), "2*a*b");
        // The value is 2ab at the reported point, recomputed independently.
        let at = |name: &str| {
            let v = s.vars.get(name).unwrap();
            point.iter().find(|(w, _)| *w == v).unwrap().1.clone()
        };
        let two_ab = Radical::from(2) * at("a") * at("b");
        assert_eq!(value, two_ab);
        assert!(!value.is_zero());
    }

    #[test]
    fn every_coordinate_is_decided_and_a_failure_outranks_an_undecided_one() {
        // x^2 + y^2 = 0 has the single real point 0, where x is zero: undecided; a + 1 = a
        // fails everywhere; the last coordinate is proved after both.
        let s = spec(
            &[("x", "0"), ("a + 1", "a"), ("b", "b")],
            &[("x^2 + y^2", "0")],
        );
        let r = decide_identity(&s).unwrap();
        assert_eq!(
            r.outcomes,
            [
                CoordinateOutcome::Undecided,
                CoordinateOutcome::Fails,
                CoordinateOutcome::Proved
            ]
        );
        assert!(matches!(
            r.verdict,
            IdentityVerdict::Fails { coordinate: 1, .. }
        ));
        assert_eq!(r.coordinates_with(CoordinateOutcome::Undecided), [0]);
    }

    #[test]
    fn relations_decide_modulo_and_corrections_get_their_own_verdict() {
        let mut s = spec(&[("c^2*x + s^2*x", "x + 1")], &[("c^2 + s^2", "1")]);
        let mut vars = s.vars.clone();
        s.corrected = Some(vec![ratfun("c^2*x + s^2*x + 1", &mut vars)]);
        s.vars = vars;
        let r = decide_identity(&s).unwrap();
        assert!(matches!(r.verdict, IdentityVerdict::Fails { .. }));
        assert!(matches!(r.correction, Some(CorrectionVerdict::Proved)));
        let mut vars = s.vars.clone();
        s.corrected = Some(vec![ratfun("x + 2", &mut vars)]);
        s.vars = vars;
        let r = decide_identity(&s).unwrap();
        assert!(matches!(
            r.correction,
            Some(CorrectionVerdict::Differs { coordinate: 0, .. })
        ));
    }

    #[test]
    fn inconsistent_relations_are_an_error_of_the_coordinate() {
        let s = spec(&[("x", "1")], &[("x", "1"), ("x", "2")]);
        let e = decide_identity(&s).unwrap_err();
        assert!(matches!(
            e,
            EngineError::Decide(Part::Coordinate(0), DecideError::Inconsistent)
        ));
    }

    #[test]
    fn residuals_and_hypotheses() {
        let mut vars = Vars::new();
        let p = parse_expr("x^2 - x")
            .unwrap()
            .to_poly::<Rational>(&mut vars)
            .unwrap();
        let h = parse_expr("x")
            .unwrap()
            .to_poly::<Rational>(&mut vars)
            .unwrap();
        let mut s = IdentitySpec::new(vars, vec![Statement::Residual(p)]);
        s.hypotheses = vec![h];
        let r = decide_identity(&s).unwrap();
        // x (x - 1) is non-zero off x = 0 except at x = 1: the counter-example avoids x = 0.
        let IdentityVerdict::Fails { point, .. } = &r.verdict else {
            panic!("expected fails")
        };
        assert!(!point[0].1.is_zero());
        assert_eq!(r.conditions.len(), 1);
    }
}
