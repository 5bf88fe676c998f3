//! The one formatter of the identity engine's verdicts: the method, the evidence, the erratum's
//! correction line and the error messages of an [`IdentityReport`], in the voice of the front
//! end that asked ([`Voice`]). The voices differ only where their readers do: `prove` speaks of
//! one identity and shortens huge values, a claims file numbers the coordinates of a vector
//! identity and names its corrected form, the catalogue names each residual by its label.

use super::identity::{
    CoordinateOutcome, CorrectionVerdict, EngineError, IdentityReport, IdentityVerdict,
    UsedHypothesis,
};
use super::{where_clause, DecideError, PointField};
use crate::poly::{Var, Vars};
use std::fmt::Display;

/// Who phrases the verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Voice {
    /// `exactcheck prove`: one identity, long values shortened (the JSON has them in full).
    Prove,
    /// A claims file's `identity` claim: coordinates numbered, corrected form named.
    ClaimsFile,
    /// The built-in catalogue: residuals named by their labels.
    Catalogue,
}

/// The longest value or polynomial the `prove` voice prints in full.
pub const SHOWN_CHARS: usize = 2_000;

/// `text` in full up to [`SHOWN_CHARS`] characters, else its beginning and its length (a
/// counter-example of `(x+y)^5000` is a number of 3,500 digits).
pub fn abbreviate(text: String) -> String {
    if text.len() <= SHOWN_CHARS {
        return text;
    }
    let mut cut = SHOWN_CHARS / 2;
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    format!(
        "{}... [{} characters in all; --json shows it in full]",
        &text[..cut],
        text.len()
    )
}

/// What a front end tells the formatter besides the report.
pub struct Phrasing<'a> {
    /// The voice.
    pub voice: Voice,
    /// The variable names of the report's polynomials.
    pub vars: &'a Vars,
    /// The relations as the user wrote them (joined after "modulo").
    pub relations: Vec<String>,
    /// The domains as the user wrote them (joined after "for").
    pub domains: Vec<String>,
    /// The catalogue's label of each residual; in the other voices the name of each component
    /// of a vector or matrix identity (`component 2 (y)`, `entry (1, 2)`), empty for a scalar
    /// identity.
    pub labels: Vec<String>,
    /// The corrected form as written, one per coordinate (claims files).
    pub corrected: Vec<String>,
    /// The hypotheses `!= 0` as the user wrote them, keyed by the polynomial printed with
    /// `vars` (a used hypothesis not found here is printed as `p != 0`).
    pub nonzero_texts: Vec<(String, String)>,
    /// The domains as the user wrote them, keyed by the variable's name (a used domain not
    /// found here is a square root's sign condition, printed `y >= 0`).
    pub domain_texts: Vec<(String, String)>,
    /// Appended to the evidence of `prove` and claims files (e.g. where square roots are
    /// defined); empty for none.
    pub suffix: String,
}

const CLEARED: &str = " with the denominators cleared";

impl Phrasing<'_> {
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
        }
    }

    /// `" modulo A = B, C = D"`, or `""` without relations.
    pub fn modulo(&self) -> String {
        if self.relations.is_empty() {
            String::new()
        } else {
            format!(" modulo {}", self.relations.join(", "))
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
            "symbolic expansion over {}[{}]{}{}",
            C::field_name(),
            self.vars.names().join(","),
            self.modulo(),
            self.within()
        )
    }

    fn name(&self, v: Var) -> &str {
        self.vars
            .name(v)
            .expect("the engine reports only variables of the table")
    }

    fn shown(&self, text: String) -> String {
        if self.voice == Voice::Prove {
            abbreviate(text)
        } else {
            text
        }
    }

    /// `in component 2 (y): ` (the component's name from [`Phrasing::labels`]), or for a
    /// claims file without names `coordinate 2: `; empty for a scalar identity.
    fn coordinate(&self, k: usize, n: usize) -> String {
        match self.labels.get(k) {
            Some(label) if self.voice != Voice::Catalogue && !label.is_empty() => {
                format!("in {label}: ")
            }
            _ if self.voice == Voice::ClaimsFile && n > 1 => format!("coordinate {}: ", k + 1),
            _ => String::new(),
        }
    }

    /// `" (also undecided: component 3 (z))"` when coordinates besides `k` are undecided.
    fn also_undecided<C: PointField>(&self, r: &IdentityReport<C>, k: usize) -> String {
        let others: Vec<String> = r
            .coordinates_with(CoordinateOutcome::Undecided)
            .into_iter()
            .filter(|&j| j != k)
            .map(|j| match self.labels.get(j) {
                Some(l) if self.voice != Voice::Catalogue && !l.is_empty() => l.clone(),
                _ => format!("coordinate {}", j + 1),
            })
            .collect();
        if others.is_empty() {
            String::new()
        } else {
            format!(" (also undecided: {})", others.join(", "))
        }
    }

    fn label(&self, k: usize) -> &str {
        self.labels.get(k).map_or("LHS - RHS", String::as_str)
    }

    /// The evidence of the verdict (one line).
    pub fn evidence<C: PointField + Display>(&self, r: &IdentityReport<C>) -> String {
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
        let rel = if r.has_relations {
            " (where the relations hold)"
        } else {
            ""
        };
        let mut text = match &r.verdict {
            IdentityVerdict::Proved { expanded_terms, .. } if self.voice == Voice::Catalogue => {
                let extra = if n > 1 {
                    format!(" ({n} residuals in all)")
                } else {
                    String::new()
                };
                if *expanded_terms == 0 {
                    format!("{} expands to 0{extra}", self.label(0))
                } else {
                    format!(
                        "{} reduces to 0 ({expanded_terms} terms before reduction){extra}",
                        self.label(0)
                    )
                }
            }
            IdentityVerdict::Proved {
                expanded_terms,
                used,
            } if !used.is_empty() => {
                let texts: Vec<String> = used.iter().map(|u| self.used_text(u)).collect();
                let coords = if n > 1 {
                    format!(" in the {n} components")
                } else {
                    String::new()
                };
                format!(
                    "LHS - RHS{cleared_any} expands to {expanded_terms} terms{coords}, which vanish{modulo}, using the hypotheses {}{where_nonzero}",
                    texts.join(", ")
                )
            }
            IdentityVerdict::Proved { expanded_terms, .. } => match (*expanded_terms, n) {
                (0, 1) => format!("LHS - RHS{cleared_any} expands to 0{where_nonzero}"),
                (0, n) => format!(
                    "LHS - RHS{cleared_any} expands to 0 in each of the {n} components{where_nonzero}"
                ),
                (t, 1) => format!(
                    "LHS - RHS{cleared_any} expands to {t} terms, which reduce to 0{modulo}{where_nonzero}"
                ),
                (t, n) => format!(
                    "LHS - RHS{cleared_any} expands to {t} terms in the {n} components, which reduce to 0{modulo}{where_nonzero}"
                ),
            },
            IdentityVerdict::Fails {
                coordinate: k,
                normal_form,
                point,
                value,
            } => {
                let at: Vec<String> = point
                    .iter()
                    .map(|(v, q)| format!("{} = {q}", self.name(*v)))
                    .collect();
                let at = at.join(", ");
                let value = self.shown(value.to_string());
                let nf = self.shown(super::factored(normal_form, self.vars));
                match self.voice {
                    Voice::Catalogue => format!(
                        "{} is not zero: at {at} it is {value}; it reduces to {nf}",
                        self.label(*k)
                    ),
                    Voice::ClaimsFile => format!(
                        "{}{}{rel} LHS - RHS = {value}; LHS - RHS{} reduces{modulo} to {nf}{where_nonzero}",
                        self.coordinate(*k, n),
                        if at.is_empty() {
                            "everywhere".to_string()
                        } else {
                            format!("at {at}")
                        },
                        cleared(*k),
                    ),
                    Voice::Prove if r.cleared[*k] => format!(
                        "{}at {}{rel} LHS - RHS = {value}; LHS - RHS{CLEARED} reduces{modulo} to {nf}, not zero{where_nonzero}",
                        self.coordinate(*k, n),
                        abbreviate(at)
                    ),
                    // No variable: the identity is between constants, and their difference is
                    // the counter-example.
                    Voice::Prove if at.is_empty() => format!(
                        "{}LHS - RHS = {value}, a non-zero constant{rel}, so LHS = RHS + ({nf})",
                        self.coordinate(*k, n),
                    ),
                    Voice::Prove => format!(
                        "{}at {}{rel} LHS - RHS = {value}; LHS - RHS reduces{modulo} to {nf}, so LHS = RHS + ({nf})",
                        self.coordinate(*k, n),
                        abbreviate(at)
                    ),
                }
            }
            IdentityVerdict::Undecided {
                coordinate: k,
                normal_form,
                searched,
            } => {
                let nf = self.shown(super::factored(normal_form, self.vars));
                match self.voice {
                    Voice::Catalogue => format!(
                        "{} reduces to {nf} (not in the ideal of the relations), but no real counter-example was found: {searched}",
                        self.label(*k)
                    ),
                    _ => format!(
                        "{}LHS - RHS{} reduces{modulo} to {nf} (not zero), but no point{within} where it is non-zero was found{where_nonzero}: {searched}{}",
                        self.coordinate(*k, n),
                        cleared(*k),
                        self.also_undecided(r, *k)
                    ),
                }
            }
        };
        if self.voice != Voice::Catalogue {
            text += &self.suffix;
        }
        let fails = matches!(r.verdict, IdentityVerdict::Fails { .. });
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
                self.coordinate(*coordinate, n)
            ),
            CorrectionVerdict::Undecided {
                coordinate,
                normal_form,
            } => format!(
                "{}corrected - RHS reduces to {} (undecided)",
                self.coordinate(*coordinate, n),
                normal_form.display(self.vars)
            ),
        }
    }

    /// The correction line of a failing identity's erratum: what the sides differ by, or that the
    /// corrected form is proved.
    pub fn erratum_correction<C: PointField + Display>(&self, r: &IdentityReport<C>) -> String {
        let IdentityVerdict::Fails {
            coordinate,
            normal_form,
            ..
        } = &r.verdict
        else {
            return String::new();
        };
        let modulo = self.modulo();
        let nf = super::factored(normal_form, self.vars);
        if matches!(r.correction, Some(CorrectionVerdict::Proved)) {
            format!("the corrected form is proved equal to RHS{modulo}; the printed LHS differs from RHS by {nf}")
        } else if r.cleared[*coordinate] {
            format!("LHS - RHS{CLEARED} reduces{modulo} to {nf}")
        } else {
            format!("LHS - RHS reduces{modulo} to {nf}, so LHS = RHS + ({nf})")
        }
    }

    /// The message of an engine error (without the front end's prefix naming the input).
    pub fn error(&self, e: &EngineError) -> String {
        match e {
            EngineError::Size(_, e) => e.to_string(),
            EngineError::Decide(_, DecideError::Inconsistent) => match self.voice {
                Voice::Prove => format!(
                    "the relations {} are inconsistent (their Groebner basis contains a non-zero constant): no point satisfies them, so nothing can be proved from them",
                    self.relations.join(", ")
                ),
                Voice::ClaimsFile => format!(
                    "the relations{} are inconsistent (no point satisfies them, so nothing can be proved from them)",
                    self.modulo()
                ),
                Voice::Catalogue => DecideError::Inconsistent.to_string(),
            },
            EngineError::Decide(_, DecideError::EmptyDomain(v)) => {
                format!("the domain of {} is empty", self.name(*v))
            }
            EngineError::Decide(_, DecideError::DuplicateDomain(v)) => {
                format!("{} has two domains", self.name(*v))
            }
            EngineError::Decide(_, e) => e.to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr;
    use crate::prove::{decide_identity, IdentitySpec, Statement};
    use crate::Rational;

    fn report(l: &str, r: &str) -> (IdentityReport<Rational>, Vars) {
        let mut vars = Vars::new();
        let l = parse_expr(l).unwrap().to_ratfun(&mut vars).unwrap();
        let r = parse_expr(r).unwrap().to_ratfun(&mut vars).unwrap();
        let spec = IdentitySpec::new(vars, vec![Statement::Sides(l, r)]);
        (decide_identity(&spec).unwrap(), spec.vars)
    }

    fn phrasing(voice: Voice, vars: &Vars) -> Phrasing<'_> {
        Phrasing {
            voice,
            vars,
            relations: Vec::new(),
            domains: Vec::new(),
            // The catalogue names its residuals; a scalar identity of the other voices has no
            // component names.
            labels: if voice == Voice::Catalogue {
                vec!["the residual".into()]
            } else {
                Vec::new()
            },
            corrected: Vec::new(),
            nonzero_texts: Vec::new(),
            domain_texts: Vec::new(),
            suffix: String::new(),
        }
    }

    #[test]
    fn each_voice_phrases_the_same_report() {
        let (r, vars) = report("(a+b)^3", "a^3 + 3*a^2*b + 3*a*b^2");
        assert_eq!(
            phrasing(Voice::Prove, &vars).evidence(&r),
            "at a = 0, b = 1 LHS - RHS = 1; LHS - RHS reduces to b^3, so LHS = RHS + (b^3)"
        );
        assert_eq!(
            phrasing(Voice::ClaimsFile, &vars).evidence(&r),
            "at a = 0, b = 1 LHS - RHS = 1; LHS - RHS reduces to b^3"
        );
        assert_eq!(
            phrasing(Voice::Catalogue, &vars).evidence(&r),
            "the residual is not zero: at a = 0, b = 1 it is 1; it reduces to b^3"
        );
        assert_eq!(
            phrasing(Voice::Prove, &vars).method::<Rational>(),
            "symbolic expansion over Q[a,b]"
        );
    }

    #[test]
    fn components_are_named_in_the_prove_and_claims_voices() {
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
        let mut p = phrasing(Voice::Prove, &spec.vars);
        p.labels = vec!["component 1 (x)".into(), "component 2 (y)".into()];
        assert!(
            p.evidence(&r).starts_with("in component 2 (y): at "),
            "{}",
            p.evidence(&r)
        );
        p.voice = Voice::ClaimsFile;
        assert!(p.evidence(&r).starts_with("in component 2 (y): at "));
        p.labels.clear();
        assert!(p.evidence(&r).starts_with("coordinate 2: at "));
    }

    #[test]
    fn fractions_carry_their_side_conditions() {
        let (r, vars) = report("(x^2-1)/(x-1)", "x+1");
        assert_eq!(
            phrasing(Voice::Prove, &vars).evidence(&r),
            "LHS - RHS with the denominators cleared expands to 0, where x != 1"
        );
    }

    #[test]
    fn long_texts_are_shortened_in_the_prove_voice_only() {
        let long = "7".repeat(3 * SHOWN_CHARS);
        let short = abbreviate(long.clone());
        assert!(short.len() < long.len() && short.ends_with("--json shows it in full]"));
        assert_eq!(abbreviate("x".into()), "x");
    }
}
