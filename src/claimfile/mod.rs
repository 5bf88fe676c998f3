//! Claims files: a paper's claims as data (TOML or JSON), checked by `exactcheck verify FILE`
//! with the engines the built-in catalogue uses, and reported like the catalogue's claims.
//!
//! # The format
//! ```toml
//! [paper]                        # optional
//! name = "mypaper"               # the report's source (default: the file name without extension)
//! title = "..."                  # optional
//! reference = "..."              # optional
//!
//! [define]                       # optional: the paper's notation, typed once
//! X = "a + r*ct"                 # a scalar
//! v = ["X", "b + r*st", "u"]     # a vector (one formula per coordinate)
//! F = "norm2(v - vec(d, h, f)) - R^2"
//!
//! [latex]                        # optional: LaTeX of names for the report (`ct = '\cos t'`)
//!
//! [[claim]]
//! id = "mypaper.eq3"             # unique
//! statement = "..."              # as printed (optional)
//! kind = "identity"              # identity | value | instances | solve
//! expect = "fails"               # optional: proved | holds | fails
//! latex = { c = '\cos t' }       # optional: this claim's notation
//! ...                            # the kind's keys
//! ```
//! JSON files have the same shape (`{"paper": {...}, "define": {...}, "claim": [{...}]}`); the
//! format is chosen by the extension (`.toml`, `.json`), else by the content. Unknown keys, a key
//! a kind does not take, a missing key, a duplicate id, an unknown kind, a bad formula, an unknown
//! function, a wrong number of arguments and a vector where a scalar is needed are errors of one
//! line naming the file, the line, the claim and the key.
//!
//! # Formulas and definitions
//! Formulas use the expression syntax of `exactcheck_exact::expr` plus function calls; defined
//! names are replaced by their values and the functions (`vec`, `dot`, `cross`, `norm2`, `x`,
//! `y`, `z`, `at`, `bernstein`, `bezier`, `subs`) are evaluated by rewriting the tree before it
//! is expanded: see [`defs`]. Where a formula may be a vector (`lhs`, `rhs`, `corrected`), an
//! identity between vectors is one identity per coordinate.
//!
//! # Kinds
//! * `identity` — `lhs`, `rhs` (default `0`), `where` (relations `A = B` such as
//!   `c^2 + s^2 = 1`, and domains such as `r > 0`, exactly as `prove --where`), `domains`
//!   (domains only), `field` (`rational` or `radical`; default: radical when a formula has `sqrt`),
//!   `name` (what the printed `lhs` defines, e.g. `A`, one per coordinate), `corrected`. Decided
//!   by `exactcheck_exact::prove::decide_in` exactly as `prove`: **proved** (the residual reduces
//!   to zero), **fails** (an exact counter-example inside the domains, the residual there) or
//!   **undecided**. Write the printed formula as `lhs` and the derivation as `rhs`. When the
//!   claim fails and the file gives `corrected` (what the printed `lhs` should have been), the
//!   check *proves* `corrected = rhs` under the same relations and domains; only a proved
//!   correction enters the erratum (`name = corrected`, or `corrected = rhs` without `name`).
//! * `value` — `expr` (exact; `sqrt` allowed) and `printed` (a decimal or a list): each printed
//!   digit string is judged exactly ([`crate::claims::printed`]): **proved** when every printed
//!   value is the exact value, **holds** when each is it or its correct rounding (a tie counts as
//!   correct), else **fails** with the correct rounding to the same places and the deviation.
//! * `instances` — `lhs`, `rhs`, `where` (relations; for `random` only unit circles), `random`
//!   (K points modulo a random prime, `prove --random K`, with its proved error bound), `seed`
//!   (default: fresh per run, printed), `at` (exact instances: a list of tables `{x = "1/2"}`,
//!   every variable given, the relations must hold there). **fails** at a non-zero instance
//!   (exact counter-example) or point modulo p; **holds** when every instance is zero and the
//!   random test (if asked for) holds; **undecided** when its bound is too weak.
//! * `solve` — `problem` (an inline table, or a string of JSON: a `solve` problem of any kind)
//!   and `expect_fields` (path -> expected value; a path is dotted, `parametrization.real_at_t_pi`,
//!   with numbers indexing arrays, or a JSON pointer starting with `/`). Numbers compare exactly
//!   (`0` equals `"0"`, `"1/2"` equals `"2/4"`). A solve claim is a statement about one
//!   configuration checked exactly on it: **holds** when every field matches (not *proved*,
//!   which the catalogue keeps for statements about all inputs), else **fails** naming each
//!   mismatch.
//!
//! Without `expect`, proved and holds count as expected and fails and undecided do not; with
//! it, the verdict must equal it. An `identity` whose `corrected` form is not proved equal to
//! its `rhs` is not as expected, whatever its verdict. `verify FILE` exits 0 iff every claim is
//! as expected.
//!
//! # Bad claims and names
//! A claim that cannot be built (a bad formula or key) or decided (inconsistent relations, an
//! instance off its relations) gets the verdict `error` with its one-line message; the other
//! claims are decided and reported, and `verify` exits with status 2. A file with no claim that
//! can be decided is refused with the first claim's message (one line, status 2).
//!
//! `pi`, `e` and `i` are constants, never free variables: a formula using one as a variable is
//! a bad claim. `variables = ["x", "t"]` (at the top of the file, for every claim, and in a
//! claim, for that claim) declares the variables; any other free name then gets a warning on
//! standard error, with its near misses (`Aa` for the defined `A`, see the module `names`). Without a
//! declaration, a name used by one claim only that is a near miss of a defined name or of
//! another claim's variable gets that warning.

pub mod defs;
mod kinds;
mod names;
mod read;

use crate::claims::{Checked, Outcome, Verdict};
use crate::Error;
use exactcheck_exact::expr::{parse_expr_with_calls, Expr};
use kinds::{Check, Fault};
use rayon::prelude::*;
use read::Format;
use serde_json::{Map, Value};
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::Path;
use std::time::Instant;

/// A claims file, read and resolved: every formula is parsed and its definitions substituted.
pub struct ClaimsFile {
    /// The file's name as given (for messages).
    pub path: String,
    /// The paper.
    pub paper: Paper,
    /// The file's notation (`[latex]`): name -> LaTeX.
    pub notation: Vec<(String, String)>,
    /// The claims in file order.
    pub claims: Vec<FileClaim>,
    /// Warnings about names (a free variable that may be a typo, see the module `names`), one line each.
    pub warnings: Vec<String>,
}

/// `[paper]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Paper {
    /// The source name of the claims (`[paper] name`, else the file name without extension).
    pub name: String,
    /// The title, if given.
    pub title: Option<String>,
    /// The reference, if given.
    pub reference: Option<String>,
}

/// One claim of a file.
pub struct FileClaim {
    /// The id.
    pub id: String,
    /// The statement as printed (empty if not given).
    pub statement: String,
    /// The kind (`identity`, `value`, `instances`, `solve`).
    pub kind: String,
    /// The expected verdict, if the file gives one.
    pub expect: Option<Verdict>,
    /// The claim's notation merged over the file's.
    pub notation: Vec<(String, String)>,
    /// The line of the claim's `id`.
    pub line: usize,
    /// The line of each key of the claim.
    key_lines: HashMap<String, usize>,
    /// The check, or the one-line error (`FILE:LINE: claim "ID": key KEY: WHAT`) of a claim
    /// that cannot be built: that claim gets the verdict `error`, the others are decided.
    check: Result<Check, String>,
}

/// A claim decided by the claims-file engine.
pub struct Decision {
    /// The outcome.
    pub outcome: Outcome,
    /// Why the claim's corrected form is not proved equal to its `rhs` (if so).
    pub problem: Option<String>,
    /// The typed fields of the engine's report, as `prove --json` prints them for the same
    /// identity ([`crate::phrase::Phrasing::fields`], [`crate::phrase::random::random_fields`]):
    /// for `identity` claims and the random part of `instances` claims; empty for the others.
    pub report: Map<String, Value>,
}

/// The result of deciding one claim: the [`Decision`], or the error's one-line message and
/// whether it is the claim's bad input (not a failure of the check itself).
pub type Run = Result<Decision, (String, bool)>;

impl FileClaim {
    /// Decides the claim of the file `path` (named in the messages of bad input).
    pub fn decide(&self, path: &str) -> Run {
        match &self.check {
            Err(m) => Err((m.clone(), true)),
            Ok(check) => kinds::run(check, &self.notation).map_err(|f| match f {
                Fault::Internal(m) => (m, false),
                Fault::Input(key, m) => {
                    let line = self.key_lines.get(key).copied().unwrap_or(self.line);
                    (
                        format!("{path}:{line}: claim {:?}: key {key}: {m}", self.id),
                        true,
                    )
                }
            }),
        }
    }

    /// The verdict the claim is expected to have before it is decided: `expect`, else the
    /// kind's own (proved for `identity`, holds for the others).
    pub fn expected_before(&self) -> Verdict {
        self.expected(None)
    }

    /// The verdict the claim is compared with: `expect`, else the verdict itself when it is
    /// proved or holds, else the kind's own (proved for `identity`, holds for the others).
    fn expected(&self, verdict: Option<Verdict>) -> Verdict {
        if let Some(e) = self.expect {
            return e;
        }
        match verdict {
            Some(v @ (Verdict::Proved | Verdict::Holds)) => v,
            _ if self.kind == "identity" => Verdict::Proved,
            _ => Verdict::Holds,
        }
    }
}

/// Reads and resolves a claims file.
///
/// # Errors
/// [`Error::Io`] when it cannot be read; [`Error::Input`] with one line
/// `FILE:LINE: claim "ID": key KEY: WHAT` for anything wrong in it.
pub fn load(path: &Path) -> Result<ClaimsFile, Error> {
    let shown = path.display().to_string();
    let text = crate::solve::read_problem(Some(&shown))?;
    let stem = path
        .file_stem()
        .map_or_else(|| shown.clone(), |s| s.to_string_lossy().into_owned());
    parse(&text, &shown, &stem)
}

/// Reads a claims file from text (`file` names it in messages and chooses the format by its
/// extension; `default_name` is the paper's name when `[paper] name` is absent).
///
/// # Errors
/// As [`load`].
pub fn parse(text: &str, file: &str, default_name: &str) -> Result<ClaimsFile, Error> {
    let format: Format = read::format_of(file, text);
    let (raw, index) = read::read(text, format)
        .map_err(|e| Error::Input(format!("{file}:{}: {}", e.line, e.message)))?;
    let ids: Vec<Option<String>> = raw.claim.iter().map(|c| Some(c.id.clone())).collect();
    let fail = |path: &str, message: String| {
        let segs: Vec<String> = path.split('.').map(str::to_string).collect();
        Error::Input(format!(
            "{file}:{}: {}: {message}",
            index.line(path),
            read::where_key(&segs, &ids)
        ))
    };
    if raw.claim.is_empty() {
        return Err(Error::Input(format!(
            "{file}:1: the file has no claims (add a [[claim]] table, or \"claim\": [...] in JSON)"
        )));
    }
    let paper = match &raw.paper {
        Some(p) => Paper {
            name: p.name.clone().unwrap_or_else(|| default_name.to_string()),
            title: p.title.clone(),
            reference: p.reference.clone(),
        },
        None => Paper {
            name: default_name.to_string(),
            title: None,
            reference: None,
        },
    };
    let notation = notation_of(raw.latex.as_ref(), "latex", &fail)?;
    // Definitions.
    let mut defs = defs::read(raw.define.as_ref()).map_err(|(path, m)| fail(&path, m))?;
    defs.resolve_all().map_err(|e| {
        let name = e.def.clone().unwrap_or_default();
        let head = defs.head(&name).unwrap_or(&name);
        fail(&format!("define.{head}"), e.message)
    })?;
    // Declared variables: names of the syntax, not defined, not a constant.
    let declared_ok = |list: &[String], defs: &defs::Defs| -> Result<(), String> {
        for v in list {
            if !names::is_name(v) {
                return Err(format!("{v:?} is not a variable name"));
            }
            if let Some(why) = exactcheck_exact::expr::reserved_constant(v) {
                return Err(why.to_string());
            }
            if defs.is_defined(v) {
                return Err(format!("{v} is a defined name, not a variable"));
            }
        }
        Ok(())
    };
    if let Some(list) = &raw.variables {
        declared_ok(list, &defs).map_err(|m| fail("variables", m))?;
    }
    let defs = RefCell::new(defs);
    let mut claims: Vec<FileClaim> = Vec::new();
    // Each id and the line of its claim, to find a duplicate without a scan per claim.
    let mut first_line: HashMap<&str, usize> = HashMap::new();
    for (i, c) in raw.claim.iter().enumerate() {
        let base = format!("claim.{i}");
        if c.id.trim().is_empty() {
            return Err(fail(&format!("{base}.id"), "the id is empty".into()));
        }
        if let Some(first) = first_line.get(c.id.as_str()) {
            return Err(fail(
                &format!("{base}.id"),
                format!("duplicate id (first at line {first})"),
            ));
        }
        let key_fail = |key: &str, m: String| fail(&format!("{base}.{key}"), m);
        let expect = match c.expect.as_deref() {
            None => None,
            Some("proved") => Some(Verdict::Proved),
            Some("holds") => Some(Verdict::Holds),
            Some("fails") => Some(Verdict::Fails),
            Some("undecided") => {
                return Err(key_fail(
                    "expect",
                    "undecided is never an expected verdict (it means nothing was decided)".into(),
                ))
            }
            Some(other) => {
                return Err(key_fail(
                    "expect",
                    format!("unknown verdict {other:?} (proved, holds, fails)"),
                ))
            }
        };
        let mut claim_notation = notation.clone();
        // A claim that cannot be built (bad notation, formula, key) keeps its error; the rest
        // of the file is still decided.
        let check = notation_of(c.latex.as_ref(), &format!("{base}.latex"), &fail)
            .and_then(|own| {
                for (k, v) in own {
                    claim_notation.retain(|(n, _)| *n != k);
                    claim_notation.push((k, v));
                }
                if let Some(list) = &c.variables {
                    declared_ok(list, &defs.borrow()).map_err(|m| key_fail("variables", m))?;
                }
                kinds::build(c, &defs).map_err(|(key, m)| key_fail(key, m))
            })
            .map_err(|e| match e {
                Error::Input(m) => m,
                other => other.to_string(),
            });
        let mut key_lines = HashMap::new();
        for key in read::present_keys(c) {
            key_lines.insert(key.to_string(), index.line(&format!("{base}.{key}")));
        }
        let line = index.line(&format!("{base}.id"));
        first_line.insert(&c.id, line);
        claims.push(FileClaim {
            id: c.id.clone(),
            statement: c.statement.clone().unwrap_or_default(),
            kind: c.kind.clone(),
            expect,
            notation: claim_notation,
            line,
            key_lines,
            check,
        });
    }
    let named: Vec<names::ClaimNames<'_>> = claims
        .iter()
        .zip(&raw.claim)
        .filter_map(|(c, r)| {
            let check = c.check.as_ref().ok()?;
            let mut free = Vec::new();
            for e in check.formulas() {
                e.collect_variables(&mut free);
            }
            Some(names::ClaimNames {
                label: format!("{file}:{}: claim {:?}", c.line, c.id),
                free,
                declared: r.variables.as_deref(),
            })
        })
        .collect();
    let warnings = names::warnings(&named, &defs.borrow().names(), raw.variables.as_deref());
    Ok(ClaimsFile {
        path: file.to_string(),
        paper,
        notation,
        claims,
        warnings,
    })
}

/// A `latex` table as pairs.
fn notation_of(
    table: Option<&serde_json::Map<String, Value>>,
    path: &str,
    fail: &dyn Fn(&str, String) -> Error,
) -> Result<Vec<(String, String)>, Error> {
    let mut out = Vec::new();
    for (k, v) in table.into_iter().flatten() {
        match v.as_str() {
            // Checked here, so the erratum's notation is known to be valid when it is printed.
            Some(s) => match exactcheck_exact::expr::Notation::new().set(k, s) {
                Ok(()) => out.push((k.clone(), s.to_string())),
                Err(e) => return Err(fail(&format!("{path}.{k}"), e)),
            },
            None => {
                return Err(fail(
                    &format!("{path}.{k}"),
                    "LaTeX must be a string".into(),
                ))
            }
        }
    }
    Ok(out)
}

/// Checks the claims whose id starts with `only` (all when `None`).
///
/// # Errors
/// [`Error::Usage`] when no id starts with `only`; [`Error::Input`] (one line with file, line,
/// claim and key) when no chosen claim can be built or decided (a bad formula; inconsistent
/// relations, an instance off the relations or missing a variable, a `solve` problem the solver
/// refuses). When some can, the others are rows with the verdict `error` and
/// [`Checked::bad_input`] set.
pub fn check(file: &ClaimsFile, only: Option<&str>) -> Result<Vec<Checked>, Error> {
    check_with(file, only, true)
}

/// [`check`], showing a progress bar on standard error unless `quiet` (or it is not a
/// terminal).
///
/// # Errors
/// As [`check`].
pub fn check_with(
    file: &ClaimsFile,
    only: Option<&str>,
    quiet: bool,
) -> Result<Vec<Checked>, Error> {
    let chosen: Vec<&FileClaim> = file
        .claims
        .iter()
        .filter(|c| only.is_none_or(|p| c.id.starts_with(p)))
        .collect();
    if chosen.is_empty() {
        let ids: Vec<&str> = file.claims.iter().map(|c| c.id.as_str()).collect();
        return Err(Error::Usage(format!(
            "no claim id of {} starts with {:?} (claims: {})",
            file.path,
            only.unwrap_or(""),
            ids.join(", ")
        )));
    }
    let steps = crate::output::Steps::new(chosen.len() as u64, quiet);
    // The claims are independent: checked in parallel on rayon's pool, then read in file order.
    // A claim that cannot be built or decided (a bad formula; inconsistent relations, an
    // instance off its relations, a problem the solver refuses) gets the verdict `error` with
    // its one-line message, and the others are decided.
    let runs: Vec<(Run, f64)> = chosen
        .par_iter()
        .with_max_len(1)
        .map(|c| {
            steps.start(&c.id);
            let start = Instant::now();
            let run = c.decide(&file.path);
            steps.done();
            (run, start.elapsed().as_secs_f64())
        })
        .collect();
    // Nothing decidable at all: the file is bad input, reported as one line (the first claim's
    // error).
    if runs.iter().all(|(r, _)| matches!(r, Err((_, true)))) {
        if let Some((Err((m, _)), _)) = runs.into_iter().next() {
            return Err(Error::Input(m));
        }
        unreachable!("at least one claim was chosen");
    }
    let mut rows = Vec::new();
    for (c, (run, seconds)) in chosen.iter().zip(runs) {
        let (outcome, problem, report, bad_input) = match run {
            Ok(d) => (Ok(d.outcome), d.problem, d.report, false),
            Err((m, bad)) => (Err(m), None, Map::new(), bad),
        };
        let verdict = outcome.as_ref().ok().map(|o| o.verdict);
        rows.push(Checked {
            id: c.id.clone(),
            source: file.paper.name.clone(),
            statement: c.statement.clone(),
            expected: c.expected(verdict),
            outcome,
            seconds,
            problem,
            bad_input,
            report,
        });
    }
    Ok(rows)
}

/// Parses a name or printed form of an erratum (`A`, `A(t)`).
fn name_expr(text: &str) -> Result<Expr, String> {
    parse_expr_with_calls(text).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reads and checks a file: a file whose every claim is broken is refused as one line.
    fn load_str(text: &str, file: &str) -> Result<ClaimsFile, String> {
        let f = parse(text, file, "t").map_err(|e| e.to_string())?;
        check(&f, None).map_err(|e| e.to_string())?;
        Ok(f)
    }

    #[test]
    fn the_issue_example_checks() {
        let f = load_str(
            r#"
[[claim]]
id = "mypaper.eq3"
statement = "cos^2 t x^3 + sin^2 t x^3 - x = x^3 - x"
kind = "identity"
lhs = "c^2 x^3 + s^2 x^3 - x"
rhs = "x^3 - x"
where = ["c^2 + s^2 = 1"]

[[claim]]
id = "mypaper.table1"
kind = "value"
expr = "(2*sqrt(2) + sqrt(6))/3"
printed = "1.76"
"#,
            "p.toml",
        )
        .unwrap();
        let rows = check(&f, None).unwrap();
        let v: Vec<String> = rows
            .iter()
            .map(|r| r.outcome.as_ref().unwrap().verdict.to_string())
            .collect();
        assert_eq!(v, ["proved", "holds"]);
        assert!(rows.iter().all(Checked::as_expected));
        assert_eq!(rows[0].source, "t");
    }

    #[test]
    fn errors_name_line_claim_and_key() {
        let text = "[[claim]]\nid = \"a.b\"\nkind = \"identity\"\nlhs = \"x +)\"\n";
        let e = load_str(text, "p.toml").err().expect("an error");
        assert!(
            e.starts_with("p.toml:4: claim \"a.b\": key lhs: unexpected ')' at 3"),
            "{e}"
        );
        let e = load_str(
            "[[claim]]\nid = \"a\"\nkind = \"identity\"\nlsh = \"x\"\n",
            "p.toml",
        )
        .err()
        .expect("an error");
        assert!(
            e.starts_with("p.toml:4: claim \"a\": key lsh: unknown field"),
            "{e}"
        );
        let json = "{\"claim\": [\n {\"id\": \"a\", \"kind\": \"value\",\n \"expr\": \"dot(1)\", \"printed\": \"1\"}]}";
        let e = load_str(json, "p.json").err().expect("an error");
        assert!(
            e.starts_with("p.json:3: claim \"a\": key expr: dot at 0 takes 2 arguments"),
            "{e}"
        );
        let json = "{\"claim\": [\n {\"id\": \"a\", \"kind\": \"value\",\n \"expr\": \"1\", \"expr\": \"2\", \"printed\": \"1\"}]}";
        let e = load_str(json, "p.json").err().expect("an error");
        assert!(e.contains("p.json:3:") && e.contains("key expr"), "{e}");
        assert!(e.contains("twice") || e.contains("duplicate"), "{e}");
        let text = "[define]\nA = \"x + 1\"\n\n[[claim]]\nid = \"i\"\nkind = \"instances\"\nlhs = \"A\"\nrhs = \"x + 1\"\nat = [{ A = 2 }]\n";
        let e = load_str(text, "p.toml").err().expect("an error");
        assert!(
            e.starts_with("p.toml:9: claim \"i\": key at: instance 1: A is a defined name"),
            "{e}"
        );
    }
}
