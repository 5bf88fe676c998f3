//! The messages of the identity engine's errors in the user's words: inconsistent relations,
//! empty and duplicate domains, and conditions without a common real point (a vacuous claim).

use super::Phrasing;
use exactcheck_exact::poly::Var;
use exactcheck_exact::prove::{DecideError, EngineError};

impl Phrasing<'_> {
    /// The message of an engine error (without the front end's prefix naming the input).
    pub fn error(&self, e: &EngineError) -> String {
        match e {
            EngineError::Size(_, e) => e.to_string(),
            EngineError::Decide(_, DecideError::Inconsistent) => {
                let all = self.all_relations();
                let which = if all.is_empty() {
                    String::new()
                } else {
                    format!(" {}", all.join(", "))
                };
                format!(
                    "the relations{which} are inconsistent (their Groebner basis contains a non-zero constant): no point satisfies them, so nothing can be proved from them"
                )
            }
            EngineError::Decide(_, DecideError::EmptyDomain(v)) => {
                format!("the domain of {} is empty", self.name(*v))
            }
            EngineError::Decide(_, DecideError::Vacuous(v)) => self.vacuous(*v),
            EngineError::Decide(_, DecideError::DuplicateDomain(v)) => {
                format!("{} has two domains", self.name(*v))
            }
            EngineError::Decide(_, e) => e.to_string(),
        }
    }

    /// Why no value of `v` is left ([`DecideError::Vacuous`]), in the user's words: the
    /// hypotheses that name `v` and the conditions of the square roots that do.
    fn vacuous(&self, v: Var) -> String {
        let name = self.name(v);
        let names_it = |text: &str| {
            text.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                .any(|w| w == name)
        };
        let given: Vec<&str> = self
            .domain_texts
            .iter()
            .map(|(_, t)| t)
            .chain(&self.relations)
            .chain(self.nonzero_texts.iter().map(|(_, t)| t))
            .map(String::as_str)
            .filter(|t| names_it(t))
            .collect();
        let roots: Vec<&str> = self
            .roots
            .iter()
            .filter(|(_, c, everywhere)| !everywhere && names_it(c))
            .map(|(_, c, _)| c.as_str())
            .collect();
        let hypotheses = if given.is_empty() {
            String::new()
        } else {
            format!(" {}", given.join(", "))
        };
        let defined = if roots.is_empty() {
            " where the sides are defined".to_string()
        } else {
            format!(" where the square roots are defined ({})", roots.join(", "))
        };
        format!("no {name} satisfies{hypotheses}{defined}: the claim is vacuous")
    }
}
