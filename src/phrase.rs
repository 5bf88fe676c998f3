//! Verdicts ([`Verdict`]) and the one formatter of identity verdicts: `prove`, claims files
//! (`identity` claims) and the built-in catalogue decide identities by the identity engine
//! ([`exactcheck_exact::prove::decide_identity`]) and word its [`IdentityReport`] here — the
//! verdict, the method, the evidence line, the erratum's correction line, the error messages
//! and `prove --json`'s object — so that one identity reads the same from each of them.
//!
//! What differs between front ends is data, not wording: a statement given as two sides is
//! spoken of as `LHS - RHS`, a residual the catalogue names (`q . n1`) by its name; the
//! components of a vector or matrix identity are named by their place (`in component 2 (y): `).
//! Three cases the engine's report does not settle alone are worded here too: a counter-example
//! with the constant `pi` (its value is a polynomial in pi, non-zero because pi is
//! transcendental), angles of `sin`/`cos`/`tan` (a point gives the angle, not its cosine and
//! sine apart) and a counter-example found at the generator of a number field of algebraic
//! constants (`prove_cmd::constants::settle`).
//!
//! Randomized tests (`prove --random`, a claims file's `instances` with `random`) are worded
//! by [`random`].
//!
//! The formatter lives in the application, not in `exactcheck-exact`: every caller is here, and
//! its JSON is the application's.

mod errors;
pub mod random;
mod text;

pub use random::{phrase_random, RandomOptions, RandomPhrased};
pub use text::{abbreviate, grouped, SHOWN_CHARS};

use exactcheck_exact::expr::library::Shape;
use exactcheck_exact::expr::{constant_base, describe_point, lindemann_weierstrass, Angle};
use exactcheck_exact::poly::{Poly, Var, Vars};
use exactcheck_exact::prove::{
    factored, real_zero_free, where_clause, AlgebraicConstants, ConstantPoint, ConstantValue,
    CoordinateOutcome, CorrectionVerdict, FractionIdentity, IdentityReport, IdentitySpec,
    IdentityVerdict, PointField, RadicalPoint, SquareRoot, Statement, UsedHypothesis,
};
use serde_json::{json, Value};
use std::fmt::{self, Display};

/// The verdict on a claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// True for all inputs: the residual expanded to zero.
    Proved,
    /// True on every exact instance and random evaluation tried (error bound stated).
    Holds,
    /// False: an exact counter-example was found.
    Fails,
    /// Not decided: the computation found neither a proof nor a counter-example (the evidence
    /// says what was tried). Never an expected verdict of the catalogue.
    Undecided,
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Verdict::Proved => "proved",
            Verdict::Holds => "holds",
            Verdict::Fails => "fails",
            Verdict::Undecided => "undecided",
        })
    }
}

const CLEARED: &str = " with the denominators cleared";

/// What the formatter needs besides the engine's report: names and texts as the user wrote
/// them. [`Phrasing::new`] gives the empty phrasing of `vars`; the front ends fill in what
/// their statement has.
pub struct Phrasing<'a> {
    /// The variable names of the report's polynomials.
    pub vars: &'a Vars,
    /// The relations as the user wrote them (joined after "modulo"; a counter-example then
    /// satisfies them: "where the relations hold").
    pub relations: Vec<String>,
    /// The unit circles `cos(x)^2 + sin(x)^2 = 1` of the angles (joined after the relations).
    pub circles: Vec<String>,
    /// The domains as the user wrote them (joined after "for").
    pub domains: Vec<String>,
    /// The name of each component of a vector or matrix identity (`component 2 (y)`,
    /// `entry (1, 2)`); empty for a scalar identity.
    pub labels: Vec<String>,
    /// The name of each residual of a statement given as residuals (the catalogue's `q . n1`);
    /// empty for a statement given as sides, whose residual is `LHS - RHS`.
    pub residuals: Vec<String>,
    /// The corrected form as written, one per component (claims files).
    pub corrected: Vec<String>,
    /// The hypotheses `!= 0` as the user wrote them, keyed by the polynomial printed with
    /// `vars` (a used hypothesis not found here is printed as `p != 0`).
    pub nonzero_texts: Vec<(String, String)>,
    /// The domains as the user wrote them, keyed by the variable's name (a used domain not
    /// found here is a square root's sign condition, printed `y >= 0`).
    pub domain_texts: Vec<(String, String)>,
    /// The square roots that became variables: name, where the root is defined, and whether
    /// that is everywhere.
    pub roots: Vec<(String, String, bool)>,
    /// The variable of the constant pi, when the statement has it.
    pub pi: Option<Var>,
    /// The statement's algebraic constants, when they were put in one number field.
    pub constants: Option<&'a AlgebraicConstants>,
    /// The exact counter-example found at the generator of the constants' field.
    pub constant_point: Option<ConstantPoint>,
    /// The constant angle (`1` of `sin(1)`), when the statement has one: its cosine and sine are
    /// no coordinates of a counter-example, and a value in them is non-zero by
    /// Lindemann–Weierstrass.
    pub constant_angle: Option<Angle>,
}

impl<'a> Phrasing<'a> {
    /// The texts of the variables' domains (`(name, "x > 0")` from the domain list's name and
    /// text), then each algebraic constant's isolating interval.
    pub fn domain_texts<'d>(
        domains: impl IntoIterator<Item = (&'d String, &'d String)>,
        constants: Option<&AlgebraicConstants>,
    ) -> Vec<(String, String)> {
        domains
            .into_iter()
            .map(|(n, t)| (n.clone(), t.trim().to_string()))
            .chain(constants.map(|k| {
                (
                    k.name.clone(),
                    format!("{} in its isolating interval {}", k.name, k.domain()),
                )
            }))
            .collect()
    }

    /// Each square root's variable name, its side condition `E >= 0` and whether it holds
    /// everywhere.
    pub fn root_texts<C: PointField>(
        roots: &[SquareRoot<C>],
        vars: &Vars,
    ) -> Vec<(String, String, bool)> {
        roots
            .iter()
            .map(|r| {
                let name = vars.name(r.var).unwrap_or("?").to_string();
                (name, r.condition(), r.defined_everywhere())
            })
            .collect()
    }

    /// The relations' and circles' texts, in that order.
    fn all_relations(&self) -> Vec<&str> {
        self.relations
            .iter()
            .chain(&self.circles)
            .map(String::as_str)
            .collect()
    }

    /// The phrasing of a statement in `vars` with nothing besides its report.
    pub fn new(vars: &'a Vars) -> Self {
        Phrasing {
            vars,
            relations: Vec::new(),
            circles: Vec::new(),
            domains: Vec::new(),
            labels: Vec::new(),
            residuals: Vec::new(),
            corrected: Vec::new(),
            nonzero_texts: Vec::new(),
            domain_texts: Vec::new(),
            roots: Vec::new(),
            pi: None,
            constants: None,
            constant_point: None,
            constant_angle: constant_base(vars).map(|(a, _)| a),
        }
    }

    /// The verdict: a report left undecided becomes `fails` when a counter-example was found at
    /// the constants' generator.
    pub fn verdict<C: PointField>(&self, r: &IdentityReport<C>) -> Verdict {
        match &r.verdict {
            _ if self.constant_point.is_some() => Verdict::Fails,
            IdentityVerdict::Proved { .. } => Verdict::Proved,
            IdentityVerdict::Fails { .. } => Verdict::Fails,
            IdentityVerdict::Undecided { .. } => Verdict::Undecided,
        }
    }

    /// A used hypothesis as the user wrote it.
    pub fn used_text<C: PointField + Display>(&self, u: &UsedHypothesis<C>) -> String {
        match u {
            UsedHypothesis::NonZero(p) => {
                let shown = p.display(self.vars).to_string();
                self.nonzero_texts
                    .iter()
                    .find(|(k, _)| *k == shown)
                    .map_or_else(|| format!("{shown} != 0"), |(_, t)| t.clone())
            }
            UsedHypothesis::Domain(v) => {
                let name = self.vars.name(*v).unwrap_or("?").to_string();
                self.domain_texts
                    .iter()
                    .find(|(k, _)| *k == name)
                    .map_or_else(|| format!("{name} >= 0"), |(_, t)| t.clone())
            }
            UsedHypothesis::Sign(f) => {
                let on: Vec<String> = f
                    .vars
                    .iter()
                    .map(|&v| self.used_text(&UsedHypothesis::<C>::Domain(v)))
                    .collect();
                let on = if on.is_empty() {
                    String::new()
                } else {
                    format!(" on {}", on.join(", "))
                };
                format!("{} {}{on}", f.poly.display(self.vars), f.sign.relation())
            }
        }
    }

    /// `" modulo A = B, C = D"`, or `""` without relations.
    pub fn modulo(&self) -> String {
        if self.relations.is_empty() && self.circles.is_empty() {
            String::new()
        } else {
            format!(" modulo {}", self.all_relations().join(", "))
        }
    }

    /// `" for r > 0, 0 <= t <= 1"`, or `""` without domains.
    pub fn within(&self) -> String {
        if self.domains.is_empty() {
            String::new()
        } else {
            format!(" for {}", self.domains.join(", "))
        }
    }

    /// The method: `symbolic expansion over Q[x,y] modulo ... for ...`, the field named by
    /// [`PointField::field_name`].
    pub fn method<C: PointField>(&self) -> String {
        format!(
            "symbolic expansion over {}[{}]{}{}{}",
            C::field_name(),
            self.vars.names().join(","),
            self.modulo(),
            self.within(),
            if self.pi.is_some() {
                " (pi an indeterminate: it is transcendental)"
            } else {
                ""
            }
        )
    }

    /// The suffix of every evidence line: where the square roots are defined and which
    /// constants the statement has; empty for neither.
    fn suffix(&self) -> String {
        let mut text = String::new();
        // `abs(E)` is a root the user did not write as one: it is defined everywhere.
        let abs = format!("{}(", exactcheck_exact::expr::ABS);
        let written: Vec<&(String, String, bool)> = self
            .roots
            .iter()
            .filter(|(name, _, _)| !name.starts_with(&abs))
            .collect();
        if !written.is_empty() {
            let c: Vec<&str> = written
                .iter()
                .filter(|(_, _, everywhere)| !everywhere)
                .map(|(_, c, _)| c.as_str())
                .collect();
            text = if c.is_empty() {
                " (the square roots are defined everywhere)".to_string()
            } else {
                format!(" (the square roots are defined where {})", c.join(", "))
            };
        }
        if let Some(k) = self.constants {
            text += &format!(" ({})", k.description());
        }
        text
    }

    fn name(&self, v: Var) -> &str {
        self.vars
            .name(v)
            .expect("the engine reports only variables of the table")
    }

    /// What component `k` of `n` is called at the head of a line: `in component 2 (y): `, or
    /// `coordinate 2: ` for an unnamed component of a statement given as sides; empty for a
    /// scalar identity and for a named residual (its name is the line's subject).
    fn place(&self, k: usize, n: usize) -> String {
        match self.labels.get(k) {
            Some(label) if !label.is_empty() => format!("in {label}: "),
            _ if n > 1 && self.residuals.is_empty() => format!("coordinate {}: ", k + 1),
            _ => String::new(),
        }
    }

    /// The residual of component `k`: `LHS - RHS`, or the catalogue's name of it.
    fn subject(&self, k: usize) -> &str {
        self.residuals.get(k).map_or("LHS - RHS", String::as_str)
    }

    /// The residuals of all `n` components at once.
    fn subjects(&self, n: usize) -> String {
        match self.residuals.as_slice() {
            [] => "LHS - RHS".to_string(),
            [one] => one.clone(),
            [first, ..] => format!("each of the {n} residuals ({first}, ...)"),
        }
    }

    /// `" (also undecided: component 3 (z))"` when components besides `k` are undecided.
    fn also_undecided<C: PointField>(&self, r: &IdentityReport<C>, k: usize) -> String {
        let others: Vec<String> = r
            .coordinates_with(CoordinateOutcome::Undecided)
            .into_iter()
            .filter(|&j| j != k)
            .map(|j| match (self.labels.get(j), self.residuals.get(j)) {
                (Some(l), _) if !l.is_empty() => l.clone(),
                (_, Some(name)) => name.clone(),
                _ => format!("coordinate {}", j + 1),
            })
            .collect();
        if others.is_empty() {
            String::new()
        } else {
            format!(" (also undecided: {})", others.join(", "))
        }
    }

    /// The counter-example's values by name, pi left out (it is the constant), each angle's
    /// cosine and sine written as one angle.
    fn shown_point(&self, point: &RadicalPoint) -> String {
        let named: Vec<(String, String)> = point
            .iter()
            .filter(|(v, _)| Some(*v) != self.pi)
            .map(|(v, q)| (self.name(*v).to_string(), q.to_string()))
            .collect();
        abbreviate(describe_point(&named).join(", "))
    }

    /// `" (where the relations hold)"` when the user gave relations.
    fn relations_hold(&self) -> &'static str {
        if self.relations.is_empty() {
            ""
        } else {
            " (where the relations hold)"
        }
    }

    /// The value of a failing component at its counter-example as a polynomial in pi, when the
    /// statement has pi and is given as sides.
    fn value_in_pi<C: PointField + Display>(
        &self,
        spec: &IdentitySpec<C>,
        k: usize,
        point: &RadicalPoint,
    ) -> Option<String> {
        let pi = self.pi?;
        let residual = residual(spec, k)?;
        Some(
            in_pi::<C>(&residual, point, pi)
                .display(self.vars)
                .to_string(),
        )
    }

    /// The value of a failing component at its counter-example as a polynomial in the cosine
    /// and sine of the constant angle, reduced modulo their circle, and the sentence that says
    /// why it is not zero, when the statement has a constant angle.
    fn value_in_constant_angle<C: PointField + Display>(
        &self,
        spec: &IdentitySpec<C>,
        k: usize,
        point: &RadicalPoint,
    ) -> Option<(String, String)> {
        let angle = self.constant_angle.as_ref()?;
        let q = in_constant_angle(spec, k, point, angle, self.pi)?;
        if q.degree_in(angle.cos) == 0 && q.degree_in(angle.sin) == 0 {
            return None;
        }
        Some((
            q.display(self.vars).to_string(),
            lindemann_weierstrass(&angle.name),
        ))
    }

    /// The evidence of the verdict (one line).
    pub fn evidence<C: PointField + Display>(
        &self,
        spec: &IdentitySpec<C>,
        r: &IdentityReport<C>,
    ) -> String {
        let n = r.cleared.len();
        let modulo = self.modulo();
        let within = self.within();
        let where_nonzero = where_clause(&r.conditions, self.vars);
        let cleared = |k: usize| {
            if r.cleared.get(k) == Some(&true) {
                CLEARED
            } else {
                ""
            }
        };
        let cleared_any = if r.cleared_any() { CLEARED } else { "" };
        let rel = self.relations_hold();
        let sides = self.residuals.is_empty();
        let mut text = match &r.verdict {
            IdentityVerdict::Undecided {
                coordinate: k,
                normal_form,
                ..
            } if self.constant_point.is_some() => {
                let (p, constants) = (
                    self.constant_point.as_ref().expect("matched"),
                    self.constants.expect("a constant point has its constants"),
                );
                let at = describe_point(&named_point(p, self.vars));
                let at = if at.is_empty() {
                    String::new()
                } else {
                    format!("at {}{rel}: ", at.join(", "))
                };
                format!(
                    "{}{at}{} = {}{}; {}{} reduces{modulo} to {}, not zero",
                    self.place(*k, n),
                    self.subject(*k),
                    shown_value(constants, p, self.vars),
                    why_not_zero(p),
                    self.subject(*k),
                    cleared(*k),
                    abbreviate(factored(normal_form, self.vars)),
                )
            }
            IdentityVerdict::Proved {
                expanded_terms,
                used,
            } if !used.is_empty() => {
                let texts: Vec<String> = used.iter().map(|u| self.used_text(u)).collect();
                let coords = match (n, sides) {
                    (1, _) => String::new(),
                    (_, true) => format!(" in the {n} components"),
                    (_, false) => String::new(),
                };
                format!(
                    "{}{cleared_any} expands to {expanded_terms} terms{coords}, which vanish{modulo}, using the hypotheses {}{where_nonzero}",
                    self.subjects(n),
                    texts.join(", ")
                )
            }
            IdentityVerdict::Proved { expanded_terms, .. } => {
                let each = if n > 1 && sides {
                    format!(" in each of the {n} components")
                } else {
                    String::new()
                };
                let terms_each = if n > 1 && sides {
                    format!(" in the {n} components")
                } else {
                    String::new()
                };
                match *expanded_terms {
                    0 => format!(
                        "{}{cleared_any} expands to 0{each}{where_nonzero}",
                        self.subjects(n)
                    ),
                    t => format!(
                        "{}{cleared_any} expands to {t} terms{terms_each}, which reduce to 0{modulo}{where_nonzero}",
                        self.subjects(n)
                    ),
                }
            }
            IdentityVerdict::Fails {
                coordinate: k,
                normal_form,
                point,
                value,
            } => {
                let k = *k;
                let place = self.place(k, n);
                let s = self.subject(k);
                let at = self.shown_point(point);
                let nf = abbreviate(factored(normal_form, self.vars));
                let at_rel = if at.is_empty() {
                    String::new()
                } else {
                    format!("at {at}{rel}: ")
                };
                if let Some((in_angle, why)) = self.value_in_constant_angle(spec, k, point) {
                    format!(
                        "{place}{at_rel}{s}{} = {in_angle}, {why}; {s}{} reduces{modulo} to {nf}",
                        cleared(k),
                        cleared(k)
                    )
                } else {
                    match self.value_in_pi(spec, k, point) {
                    Some(in_pi) => format!(
                        "{place}{at_rel}{s}{} = {in_pi}, a non-zero polynomial in pi, and pi is transcendental, so it is not zero; {s}{} reduces{modulo} to {nf}",
                        cleared(k),
                        cleared(k)
                    ),
                    None => {
                        let value = abbreviate(value.to_string());
                        if r.cleared[k] {
                            format!("{place}{at_rel}{s} = {value}; {s}{CLEARED} reduces{modulo} to {nf}, not zero{where_nonzero}")
                        } else if !sides {
                            format!("{place}{at_rel}{s} = {value}; it reduces{modulo} to {nf}")
                        } else if at.is_empty() {
                            // No variable: the identity is between constants, and their
                            // difference is the counter-example.
                            format!("{place}{s} = {value}, a non-zero constant{rel}, so LHS = RHS + {}", grouped(&nf))
                        } else {
                            format!("{place}{at_rel}{s} = {value}; {s} reduces{modulo} to {nf}, so LHS = RHS + {}", grouped(&nf))
                        }
                    }
                }
                }
            }
            IdentityVerdict::Undecided {
                coordinate: k,
                normal_form,
                searched,
            } => {
                let nf = abbreviate(factored(normal_form, self.vars));
                format!(
                    "{}{}{} reduces{modulo} to {nf} (not zero), but no point{within} where it is non-zero was found{where_nonzero}: {searched}{}",
                    self.place(*k, n),
                    self.subject(*k),
                    cleared(*k),
                    self.also_undecided(r, *k)
                )
            }
        };
        text += &self.suffix();
        if r.no_point_found && self.verdict(r) == Verdict::Proved {
            text += " (no point satisfying the hypotheses was found: the claim may be vacuous)";
        }
        let fails = self.verdict(r) == Verdict::Fails;
        match &r.correction {
            None => {}
            Some(CorrectionVerdict::Proved) if fails => {
                text += &format!(
                    ". Corrected form (proved equal to RHS{modulo}{within}): {}",
                    self.corrected.join(", ")
                );
            }
            Some(CorrectionVerdict::Proved) => {}
            Some(c) => {
                let why = self.correction_failure(c, n);
                if fails {
                    text += &format!(". (The given correction does not match RHS either: {why})");
                } else {
                    text += &format!(". (The given correction does not match RHS: {why})");
                }
            }
        }
        text
    }

    /// Why the corrected form was not proved equal to the right side (`None` when it was, or
    /// when the report has no corrected form).
    pub fn correction_problem<C: PointField + Display>(
        &self,
        r: &IdentityReport<C>,
    ) -> Option<String> {
        match &r.correction {
            None | Some(CorrectionVerdict::Proved) => None,
            Some(c) => Some(self.correction_failure(c, r.cleared.len())),
        }
    }

    fn correction_failure<C: PointField + Display>(
        &self,
        c: &CorrectionVerdict<C>,
        n: usize,
    ) -> String {
        match c {
            CorrectionVerdict::Proved => String::new(),
            CorrectionVerdict::Differs { coordinate, value } => format!(
                "{}it differs from RHS by {value} at a point",
                self.place(*coordinate, n)
            ),
            CorrectionVerdict::Undecided {
                coordinate,
                normal_form,
            } => format!(
                "{}corrected - RHS reduces to {} (undecided)",
                self.place(*coordinate, n),
                normal_form.display(self.vars)
            ),
        }
    }

    /// The correction line of a failing identity's erratum: what the sides differ by, or that the
    /// corrected form is proved.
    pub fn erratum_correction<C: PointField + Display>(&self, r: &IdentityReport<C>) -> String {
        if let (Some(p), Some(k)) = (&self.constant_point, self.constants) {
            return format!(
                "LHS - RHS = {} at the counter-example",
                shown_value(k, p, self.vars)
            );
        }
        let IdentityVerdict::Fails {
            coordinate,
            normal_form,
            ..
        } = &r.verdict
        else {
            return String::new();
        };
        let modulo = self.modulo();
        let nf = factored(normal_form, self.vars);
        if matches!(r.correction, Some(CorrectionVerdict::Proved)) {
            format!("the corrected form is proved equal to RHS{modulo}; the printed LHS differs from RHS by {nf}")
        } else if r.cleared[*coordinate] {
            format!("LHS - RHS{CLEARED} reduces{modulo} to {nf}")
        } else {
            format!(
                "LHS - RHS reduces{modulo} to {nf}, so LHS = RHS + {}",
                grouped(&nf)
            )
        }
    }

    /// The report as `prove --json` prints it: verdict, method, evidence and the number of
    /// residual terms; per component of a vector or matrix identity its verdict; the hypotheses
    /// used, the square roots, the side conditions, the constants; for a failure the point,
    /// the value there and the normal form.
    pub fn json<C: PointField + Display>(
        &self,
        spec: &IdentitySpec<C>,
        r: &IdentityReport<C>,
        shape: Shape,
    ) -> Value {
        let mut obj = serde_json::Map::new();
        obj.insert("verdict".into(), json!(self.verdict(r).to_string()));
        obj.insert("method".into(), json!(self.method::<C>()));
        obj.insert("evidence".into(), json!(self.evidence(spec, r)));
        obj.extend(self.fields(spec, r, shape));
        obj.into()
    }

    /// The typed fields of [`Phrasing::json`] besides the verdict, the method and the evidence
    /// (which a front end may word for itself): the number of residual terms, the components,
    /// the hypotheses used, the square roots, the side conditions, the constants; for a failure
    /// the point, the value there and the normal form. A claims file's JSON row carries them.
    pub fn fields<C: PointField + Display>(
        &self,
        spec: &IdentitySpec<C>,
        r: &IdentityReport<C>,
        shape: Shape,
    ) -> serde_json::Map<String, Value> {
        let vars = self.vars;
        let mut obj = json!({
            "residual_terms": r.residual_terms.iter().sum::<usize>(),
        });
        if shape != Shape::Scalar {
            obj["shape"] = json!(shape.to_string());
            obj["components"] = r
                .outcomes
                .iter()
                .enumerate()
                .map(|(k, o)| {
                    json!({
                        "component": shape.component(k),
                        "verdict": match o {
                            CoordinateOutcome::Proved => "proved",
                            CoordinateOutcome::Fails => "fails",
                            CoordinateOutcome::Undecided => "undecided",
                        },
                        "residual_terms": r.residual_terms[k],
                    })
                })
                .collect::<Vec<_>>()
                .into();
        }
        if let IdentityVerdict::Proved { used, .. } = &r.verdict {
            if !used.is_empty() {
                obj["hypotheses_used"] =
                    json!(used.iter().map(|u| self.used_text(u)).collect::<Vec<_>>());
            }
        }
        if !self.roots.is_empty() {
            obj["square_roots"] = self
                .roots
                .iter()
                .map(|(n, c, _)| json!({"root": n, "defined_where": c}))
                .collect::<Vec<_>>()
                .into();
        }
        if r.cleared_any() {
            obj["conditions"] = r
                .conditions
                .iter()
                .map(|p| json!({"nonzero": p.display(vars).to_string(), "real_zero_free": real_zero_free(p) == Some(true)}))
                .collect::<Vec<_>>()
                .into();
        }
        if let (
            Some(p),
            Some(k),
            IdentityVerdict::Undecided {
                normal_form,
                coordinate,
                ..
            },
        ) = (&self.constant_point, self.constants, &r.verdict)
        {
            if shape != Shape::Scalar {
                obj["failing_component"] = json!(shape.component(*coordinate));
            }
            obj["point"] = named_point(p, vars)
                .into_iter()
                .map(|(n, q)| (n, json!(q)))
                .collect::<serde_json::Map<_, _>>()
                .into();
            obj["value"] = json!(shown_value(k, p, vars));
            obj["normal_form"] = json!(normal_form.display(vars).to_string());
        }
        if let Some(k) = self.constants {
            obj["constants"] = json!(k.description());
        }
        if let IdentityVerdict::Fails {
            coordinate,
            point,
            value,
            normal_form,
        } = &r.verdict
        {
            let angle = self.constant_angle.as_ref();
            obj["point"] = point
                .iter()
                .filter(|(v, _)| Some(*v) != self.pi)
                .filter(|(v, _)| !angle.is_some_and(|a| [a.cos, a.sin].contains(v)))
                .map(|(v, q)| (self.name(*v).to_string(), json!(q.to_string())))
                .collect::<serde_json::Map<_, _>>()
                .into();
            if shape != Shape::Scalar {
                obj["failing_component"] = json!(shape.component(*coordinate));
            }
            obj["value"] = match (
                self.value_in_constant_angle(spec, *coordinate, point),
                self.value_in_pi(spec, *coordinate, point),
            ) {
                (Some((v, _)), _) | (None, Some(v)) => json!(v),
                (None, None) => json!(value.to_string()),
            };
            obj["normal_form"] = json!(normal_form.display(vars).to_string());
        }
        match obj {
            Value::Object(map) => map,
            _ => unreachable!("built as an object"),
        }
    }
}

/// The exact value of `LHS - RHS` at a counter-example: a number, a `Root(...)` written in a
/// variable of none of the statement's names (`x` when it has none but `c`), or a polynomial in
/// pi and `c` (a fraction of two when pi divides).
pub fn shown_value(k: &AlgebraicConstants, p: &ConstantPoint, vars: &Vars) -> String {
    match &p.value {
        ConstantValue::Number(a) => {
            let names: Vec<&String> = vars.names().iter().filter(|n| **n != k.name).collect();
            a.display_in(&exactcheck_exact::algebraic::root_variable(&names))
        }
        ConstantValue::InPi {
            numerator,
            denominator,
        } if exactcheck_core::Ring::is_one(denominator) => numerator.display(vars).to_string(),
        ConstantValue::InPi {
            numerator,
            denominator,
        } => format!(
            "({})/({})",
            numerator.display(vars),
            denominator.display(vars)
        ),
    }
}

/// `, a non-zero polynomial in pi, ...` after a value in pi at a counter-example (why it is not
/// zero: pi is transcendental over the algebraic numbers), nothing after a number.
fn why_not_zero(p: &ConstantPoint) -> &'static str {
    match &p.value {
        ConstantValue::Number(_) => "",
        ConstantValue::InPi { denominator, .. } if exactcheck_core::Ring::is_one(denominator) => {
            ", a non-zero polynomial in pi with coefficients in the field of the constants, and pi is transcendental, so it is not zero"
        }
        ConstantValue::InPi { .. } => {
            ", a quotient of non-zero polynomials in pi with coefficients in the field of the constants, and pi is transcendental, so it is not zero"
        }
    }
}

/// The point of a counter-example by name (`c` is the constant, not a coordinate).
pub fn named_point(point: &ConstantPoint, vars: &Vars) -> Vec<(String, String)> {
    point
        .values
        .iter()
        .map(|(v, q)| (vars.name(*v).unwrap_or("?").to_string(), q.to_string()))
        .collect()
}

/// The residual of component `k` (`LHS - RHS` with the denominators cleared).
pub fn residual<C: PointField>(spec: &IdentitySpec<C>, k: usize) -> Option<Poly<C>> {
    Some(match spec.coordinates.get(k)? {
        Statement::Sides(l, r) if l.is_polynomial() && r.is_polynomial() => {
            l.numerator().clone() - r.numerator()
        }
        Statement::Sides(l, r) => FractionIdentity::new(l, r).ok()?.residual,
        Statement::Residual(p) => p.clone(),
    })
}

/// The residual of component `k` at a counter-example with every variable fixed but pi and the
/// cosine and sine of the constant angle, reduced modulo the angle's circle (`sin(u)^2 = 1 -
/// cos(u)^2`). It is not zero: its value at the point's rational values of `cos(u)`, `sin(u)`
/// (on the circle) and pi is the engine's non-zero value; so, without pi, it is a non-zero
/// polynomial in `cos(u)`, `sin(u)` modulo the circle, non-zero at the angle `u` by
/// Lindemann–Weierstrass.
pub fn in_constant_angle<C: PointField>(
    spec: &IdentitySpec<C>,
    k: usize,
    point: &RadicalPoint,
    angle: &Angle,
    pi: Option<Var>,
) -> Option<Poly<C::Value>> {
    let mut q = residual(spec, k)?.map_coeffs(C::lift);
    for (v, x) in point {
        if Some(*v) != pi && *v != angle.cos && *v != angle.sin {
            q = q.substitute(*v, &Poly::constant(C::lift_radical(x)));
        }
    }
    Some(reduce_circle(&q, angle.cos, angle.sin))
}

/// `q` modulo `c^2 + s^2 - 1`: every `s^2` replaced by `1 - c^2`, so that `q` is linear in `s`
/// (the unique normal form of that relation).
fn reduce_circle<V: exactcheck_core::Ring>(q: &Poly<V>, c: Var, s: Var) -> Poly<V> {
    use exactcheck_core::Ring;
    let one_minus_c2 = Poly::from_terms([(vec![], V::one()), (vec![(c, 2)], V::one().neg_ref())]);
    let mut out = Poly::zero();
    for (m, a) in q.terms() {
        let mut exps = m.exponents();
        let e = exps.iter().find(|(v, _)| *v == s).map_or(0, |x| x.1);
        exps.retain(|(v, _)| *v != s);
        if e % 2 == 1 {
            exps.push((s, 1));
            exps.sort_unstable();
        }
        let mut t = Poly::from_terms([(exps, a.clone())]);
        for _ in 0..e / 2 {
            t *= one_minus_c2.clone();
        }
        out = out.add_ref(&t);
    }
    out
}

/// The residual at a counter-example with every variable but pi fixed: a polynomial in pi, not
/// zero (it is not zero at the value the search gave pi), so not zero at pi, which is
/// transcendental over the algebraic numbers of the point.
pub fn in_pi<C: PointField>(residual: &Poly<C>, point: &RadicalPoint, pi: Var) -> Poly<C::Value> {
    let mut q = residual.map_coeffs(C::lift);
    for (v, x) in point {
        if *v != pi {
            q = q.substitute(*v, &Poly::constant(C::lift_radical(x)));
        }
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_exact::expr::parse_expr;
    use exactcheck_exact::prove::decide_identity;
    use exactcheck_exact::Rational;

    fn spec(l: &str, r: &str) -> IdentitySpec<Rational> {
        let mut vars = Vars::new();
        let l = parse_expr(l).unwrap().to_ratfun(&mut vars).unwrap();
        let r = parse_expr(r).unwrap().to_ratfun(&mut vars).unwrap();
        IdentitySpec::new(vars, vec![Statement::Sides(l, r)])
    }

    /// A statement given as sides reads the same whoever asks; the catalogue's residual of
    /// the same difference is named by its name in the same sentence (its point gives the
    /// residual's variables: `a` cancels from `b^3`).
    #[test]
    fn sides_and_named_residuals_read_alike() {
        let s = spec("(a+b)^3", "a^3 + 3*a^2*b + 3*a*b^2");
        let r = decide_identity(&s).unwrap();
        let p = Phrasing::new(&s.vars);
        assert_eq!(
            p.evidence(&s, &r),
            "at a = 0, b = 1: LHS - RHS = 1; LHS - RHS reduces to b^3, so LHS = RHS + (b^3)"
        );
        assert_eq!(p.verdict(&r), Verdict::Fails);
        assert_eq!(p.method::<Rational>(), "symbolic expansion over Q[a,b]");
        let residual = match &s.coordinates[0] {
            Statement::Sides(l, rr) => l.numerator().clone() - rr.numerator(),
            Statement::Residual(p) => p.clone(),
        };
        let named = IdentitySpec::new(s.vars.clone(), vec![Statement::Residual(residual)]);
        let rn = decide_identity(&named).unwrap();
        let mut q = Phrasing::new(&named.vars);
        q.residuals = vec!["the residual".into()];
        assert_eq!(
            q.evidence(&named, &rn),
            "at b = 1: the residual = 1; it reduces to b^3"
        );
        let json = p.json(&s, &r, Shape::Scalar);
        assert_eq!(json["verdict"], "fails");
        assert_eq!(json["point"]["b"], "1");
        assert_eq!(json["normal_form"], "b^3");
    }

    #[test]
    fn components_are_named_by_their_place() {
        let mut vars = Vars::new();
        let mut side = |t: &str| {
            parse_expr(t)
                .unwrap()
                .to_ratfun::<Rational>(&mut vars)
                .unwrap()
        };
        let coordinates = vec![
            Statement::Sides(side("u"), side("u")),
            Statement::Sides(side("v"), side("2*v")),
        ];
        let spec = IdentitySpec::new(vars, coordinates);
        let r = decide_identity(&spec).unwrap();
        let mut p = Phrasing::new(&spec.vars);
        p.labels = vec!["component 1 (x)".into(), "component 2 (y)".into()];
        let e = p.evidence(&spec, &r);
        assert!(e.starts_with("in component 2 (y): at "), "{e}");
        p.labels.clear();
        assert!(p.evidence(&spec, &r).starts_with("coordinate 2: at "));
    }

    #[test]
    fn fractions_carry_their_side_conditions() {
        let s = spec("(x^2-1)/(x-1)", "x+1");
        let r = decide_identity(&s).unwrap();
        assert_eq!(
            Phrasing::new(&s.vars).evidence(&s, &r),
            "LHS - RHS with the denominators cleared expands to 0, where x != 1"
        );
    }
}
