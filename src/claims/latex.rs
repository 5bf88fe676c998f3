//! `verify --latex`: the errata of the checked claims as LaTeX math, one line per equation.
//!
//! For every claim whose outcome carries an [`Erratum`], each non-empty part gets a comment line
//! `% <id> (<verdict>): <role>` followed by one line of LaTeX math per equation (no `$`; every
//! line parses alone, e.g. in KaTeX). The correction in words, when there is one, is a comment
//! line `% <id>: correction: ...`. The LaTeX comes from the expression trees
//! ([`exactcheck_exact::expr::to_latex`]) with the erratum's notation.

use super::{Checked, Erratum};

/// The erratum's parts as `(role, LaTeX)` pairs, in the order printed, corrected,
/// counter-example, residual (one pair per equation).
pub fn erratum_latex(e: &Erratum) -> Vec<(String, String)> {
    let n = e.notation();
    e.parts()
        .into_iter()
        .flat_map(|(role, eqs)| eqs.iter().map(move |q| (role.to_string(), q)))
        .map(|(role, q)| (role, q.latex(&n)))
        .collect()
}

/// The text of `verify --latex` (module documentation); empty when no row has an erratum.
pub fn document(rows: &[Checked]) -> String {
    let mut out = String::new();
    for r in rows {
        let Ok(o) = &r.outcome else { continue };
        let Some(e) = &o.erratum else { continue };
        if !e.correction.is_empty() {
            out += &format!(
                "% {}: correction: {}\n",
                r.id,
                e.correction.replace('\n', " ")
            );
        }
        let mut last_role = String::new();
        for (role, latex) in erratum_latex(e) {
            if role != last_role {
                out += &format!("% {} ({}): {role}\n", r.id, o.verdict);
                last_role = role;
            }
            out += &latex;
            out.push('\n');
        }
    }
    out
}
