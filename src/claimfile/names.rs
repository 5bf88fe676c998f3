//! Strict names: a free variable of a claim that is neither defined, nor declared (`variables =
//! [...]`, per file or per claim), nor used consistently gets a warning naming its near misses
//! (`Aa` vs `A`; `a` vs `A`), since a typo in a claims file otherwise silently makes a new
//! variable and the claim is decided about a different formula.
//!
//! * With a declaration (the file's `variables` and the claim's), every free variable outside it
//!   is warned about, with its near misses if any.
//! * Without one, a free variable that no other claim uses is warned about when it has a near
//!   miss among the defined names and the variables of the other claims.
//!
//! A near miss differs only in case, or by one edit (insert, delete, substitute, swap two
//! neighbours) in names of two or more characters, except a change of one digit for another
//! (`x0` and `x1` are an indexed family, not a typo). The distance is written out here: it is a
//! dozen lines on names of a few characters, not worth a dependency.

use std::collections::HashMap;

pub use exactcheck_exact::expr::library::is_name;

/// The optimal-string-alignment distance (Levenshtein with adjacent swaps) of two short names.
fn distance(a: &[char], b: &[char]) -> usize {
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut best = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                best = best.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = best;
        }
    }
    d[a.len()][b.len()]
}

/// Whether `a` and `b` (different names) are near misses of each other.
pub fn near(a: &str, b: &str) -> bool {
    if a == b {
        return false;
    }
    if a.eq_ignore_ascii_case(b) {
        return true;
    }
    let (x, y): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    if x.len().max(y.len()) < 2 || distance(&x, &y) != 1 {
        return false;
    }
    // Single letters with one index (`w0`, `B0`): different letters are different symbols, as
    // `x` and `y` are.
    let stem = |c: &[char]| -> usize { c.iter().take_while(|ch| !ch.is_ascii_digit()).count() };
    if stem(&x) <= 1 && stem(&y) <= 1 && x.first() != y.first() {
        return false;
    }
    // One digit for another at the same place: an index, not a typo.
    let digit_swap = x.len() == y.len()
        && x.iter()
            .zip(&y)
            .filter(|(p, q)| p != q)
            .all(|(p, q)| p.is_ascii_digit() && q.is_ascii_digit());
    !digit_swap
}

/// One claim as the check sees it: its label for messages (`p.toml:12: claim "a"`), its free
/// variables, and its own declared variables.
pub struct ClaimNames<'a> {
    /// The label.
    pub label: String,
    /// The free variables of its formulas (after definitions are substituted).
    pub free: Vec<String>,
    /// Its `variables`, if given.
    pub declared: Option<&'a [String]>,
}

/// The warnings of a file: see the module documentation. `defined` are the names of `[define]`,
/// `file_declared` the file's `variables`.
pub fn warnings(
    claims: &[ClaimNames<'_>],
    defined: &[String],
    file_declared: Option<&[String]>,
) -> Vec<String> {
    let mut users: HashMap<&str, usize> = HashMap::new();
    for c in claims {
        for n in &c.free {
            *users.entry(n.as_str()).or_default() += 1;
        }
    }
    let mut out = Vec::new();
    for c in claims {
        let declared: Vec<&String> = file_declared
            .into_iter()
            .flatten()
            .chain(c.declared.into_iter().flatten())
            .collect();
        let strict = file_declared.is_some() || c.declared.is_some();
        for n in &c.free {
            if declared.contains(&n) {
                continue;
            }
            // Candidates: defined names, declared variables, variables of other claims.
            let mut misses: Vec<String> = Vec::new();
            let mut push = |m: &str, what: &str| {
                let text = format!("{m} ({what})");
                if near(n, m) && !misses.contains(&text) {
                    misses.push(text);
                }
            };
            for d in defined {
                push(d, "defined");
            }
            for d in &declared {
                push(d, "a declared variable");
            }
            for (m, k) in &users {
                let own = usize::from(c.free.iter().any(|f| f == m));
                if *k > own {
                    push(m, "a variable of another claim");
                }
            }
            misses.sort();
            let hint = if misses.is_empty() {
                String::new()
            } else {
                format!("; did you mean {}?", misses.join(" or "))
            };
            if strict {
                out.push(format!(
                    "{}: {n} is neither defined nor a declared variable{}",
                    c.label,
                    if hint.is_empty() {
                        " (add it to variables)".to_string()
                    } else {
                        hint
                    }
                ));
            } else if users.get(n.as_str()) == Some(&1) && !hint.is_empty() {
                out.push(format!(
                    "{}: {n} is not defined, not declared and used by no other claim{hint}",
                    c.label
                ));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn claim<'a>(label: &str, free: &[&str], declared: Option<&'a [String]>) -> ClaimNames<'a> {
        ClaimNames {
            label: label.into(),
            free: free.iter().map(|s| s.to_string()).collect(),
            declared,
        }
    }

    #[test]
    fn near_misses() {
        assert!(near("Aa", "A") && near("a", "A") && near("rho", "rh0"));
        assert!(near("ab", "ba") && near("theta", "thetaa"));
        assert!(
            !near("x", "y"),
            "single letters are not typos of each other"
        );
        assert!(!near("x0", "x1"), "an index is not a typo");
        assert!(
            !near("w0", "B0"),
            "indexed single letters are different symbols"
        );
        assert!(!near("ab", "xy") && !near("A", "A"));
        assert!(is_name("A_1") && !is_name("1a") && !is_name("a-b") && !is_name(""));
    }

    #[test]
    fn an_undeclared_near_miss_of_a_definition_is_warned_about() {
        let defined = vec!["A".to_string()];
        let w = warnings(
            &[claim("p.toml:3: claim \"c\"", &["Aa", "t"], None)],
            &defined,
            None,
        );
        assert_eq!(
            w,
            ["p.toml:3: claim \"c\": Aa is not defined, not declared and used by no other claim; did you mean A (defined)?"]
        );
        // Used by two claims: consistent, no warning.
        let w = warnings(
            &[claim("c1", &["Aa"], None), claim("c2", &["Aa"], None)],
            &defined,
            None,
        );
        assert!(w.is_empty(), "{w:?}");
    }

    #[test]
    fn declared_variables_make_every_other_name_a_warning() {
        let vars = vec!["x".to_string(), "theta".to_string()];
        let w = warnings(&[claim("c", &["x", "thetaa", "q"], None)], &[], Some(&vars));
        assert_eq!(
            w,
            [
                "c: thetaa is neither defined nor a declared variable; did you mean theta (a declared variable)?",
                "c: q is neither defined nor a declared variable (add it to variables)",
            ]
        );
        let own = vec!["q".to_string()];
        let w = warnings(&[claim("c", &["x", "q"], Some(&own))], &[], Some(&vars));
        assert!(w.is_empty(), "{w:?}");
    }

    #[test]
    fn a_typo_of_another_claims_variable_is_named() {
        let w = warnings(
            &[
                claim("c1", &["radius"], None),
                claim("c2", &["radius"], None),
                claim("c3", &["raduis"], None),
            ],
            &[],
            None,
        );
        assert_eq!(
            w,
            ["c3: raduis is not defined, not declared and used by no other claim; did you mean radius (a variable of another claim)?"]
        );
    }
}
