//! The claim catalogue: statements of the source papers with their printed form (as data), the
//! check that decides each, and the verdict the catalogue expects.
//!
//! Coverage of the papers' claim list: every `juttler.*` id and every `spaeth.*` id
//! is implemented, plus `juttler.interpolation_degree`, the degree comparison
//! split off from the sentence of `juttler.interpolation` (it is not an id of the list), the `planes.*`
//! id and the `chiang.*` ids of the ruled-surface half of Chiang's paper (`chiang.theorem`,
//! `chiang.corollary1/2/5`, `chiang.example4`, `chiang.line`, `chiang.vicinity`), the conic ids
//! `chiang.conic_table`, `chiang.conic_type` ([`chiang_conic`]) and the offset and PH ids
//! (`chiang.offset`, `chiang.ph_*`, [`chiang_ph`]): every id of the list.
//!
//! A verdict is only ever the result of a computation:
//! * **proved** — the residual expanded to zero over polynomials (modulo the declared relations);
//! * **holds** — zero on exact instances and/or random evaluations modulo a prime, with the
//!   error bound stated in the evidence;
//! * **fails** — an exact counter-example, the residual's value there, and the corrected form;
//! * **undecided** — neither (e.g. a non-zero normal form modulo relations without a real point
//!   found): reported as such, never counted as expected.
//!
//! One directory per unit of the paper registry ([`crate::papers`], which also runs the
//! catalogue: `papers::verify`): the claims of a paper, its printed data and fixtures. A claim
//! that states the paper's printed formulas alone (an identity of printed formulas, a printed
//! value against its exact value) is written in the unit's embedded claims file
//! (`src/claims/<unit>/claims.toml`, held by the paper registry) and decided by the claims-file engine, as a
//! user's own file is. The others are Rust, because the claims format cannot say what they
//! check: they compare the printed text with an independent derivation of the workspace
//! (`exactcheck_core::quadric`, `cylinder_sphere`, `ruled`, `conic`, `ph`), or decide on exact
//! instances, seeded random configurations and root isolation, and name each residual in their
//! evidence; each unit's module documentation says which claims are which and why.

/// A catalogue entry: `claim!(id, ExpectedVerdict, "statement as printed", check_fn)`.
macro_rules! claim {
    ($id:literal, $expected:ident, $statement:literal, $check:ident) => {
        Claim {
            id: $id,
            statement: $statement,
            expected: Verdict::$expected,
            check: $crate::claims::Check::Computed($check),
        }
    };
}

pub mod chiang;
pub mod chiang_conic;
pub mod chiang_line;
pub mod chiang_ph;
pub mod engine;
pub mod juttler;
pub mod latex;
pub mod planes;
pub mod printed;
pub mod spaeth;

use exactcheck_exact::expr::{equation_to_latex, parse_expr, Expr, Notation};
use serde_json::{json, Value};

pub use crate::phrase::Verdict;

/// What a check found.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// The verdict.
    pub verdict: Verdict,
    /// How it was decided (e.g. "symbolic expansion over Q[p0..p3]").
    pub method: String,
    /// The evidence: term counts, instance counts and error bounds, or the counter-example, the
    /// residual there and the corrected form.
    pub evidence: String,
    /// For a failing printed statement: the printed and the derived correct form, the exact
    /// counter-example and the residual there, as expression trees (the report's errata and
    /// `verify --latex`). `None` for the other verdicts.
    pub erratum: Option<Box<Erratum>>,
}

/// An equation `lhs = rhs` of an erratum, both sides expression trees (printed as text or
/// LaTeX from the tree).
#[derive(Clone, Debug, PartialEq)]
pub struct Equation {
    /// The left side (often a name: `x`, `A(t)` is written as the variable `A`).
    pub lhs: Expr,
    /// The right side.
    pub rhs: Expr,
}

impl Equation {
    /// `lhs = rhs`.
    pub fn new(lhs: Expr, rhs: Expr) -> Self {
        Equation { lhs, rhs }
    }

    /// The equation of two printed (or derived) texts in the expression syntax.
    ///
    /// # Errors
    /// A text that does not parse (named in the message).
    pub fn parse(lhs: &str, rhs: &str) -> Result<Self, String> {
        let p = |t: &str| parse_expr(t).map_err(|e| format!("formula {t:?}: {e}"));
        Ok(Equation::new(p(lhs)?, p(rhs)?))
    }

    /// The variable `name` equal to the expression `rhs`.
    pub fn named(name: &str, rhs: Expr) -> Self {
        Equation::new(Expr::var(name), rhs)
    }

    /// `lhs = rhs` in the expression syntax.
    pub fn text(&self) -> String {
        format!("{} = {}", self.lhs, self.rhs)
    }

    /// `lhs = rhs` as LaTeX math.
    pub fn latex(&self, notation: &Notation) -> String {
        equation_to_latex(&self.lhs, &self.rhs, notation)
    }

    /// `{ "text": .., "latex": .. }` for `verify --json`.
    pub fn to_json(&self, notation: &Notation) -> Value {
        json!({ "text": self.text(), "latex": self.latex(notation) })
    }
}

/// What a failing claim's printed statement should have said, computed by its check: the
/// report's errata section and `verify --latex` are made from it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Erratum {
    /// The printed formulas that are wrong, as printed (empty when the statement is prose).
    pub printed: Vec<Equation>,
    /// The derived correct formulas (proved or computed exactly by the check).
    pub corrected: Vec<Equation>,
    /// The correct statement in words, when it is not (only) a formula.
    pub correction: String,
    /// The exact counter-example: one `variable = value` per coordinate.
    pub counter_example: Vec<Equation>,
    /// The residual at the counter-example (e.g. `printed - derived = 22626/51701`).
    pub residual: Vec<Equation>,
    /// LaTeX for variable names (`cb` -> `\\cos\\beta`); names not listed are printed by the
    /// LaTeX printer's default rules.
    pub notation: Vec<(String, String)>,
}

impl Erratum {
    /// The notation of the erratum's names for the printers.
    ///
    /// # Panics
    /// When an entry is outside the LaTeX subset of [`Notation::set`]: the entries are written
    /// by the claim modules, and a test checks every erratum of the catalogue.
    pub fn notation(&self) -> Notation {
        Notation::from_pairs(self.notation.iter().map(|(a, b)| (a, b)))
            .expect("the claim modules write notation entries in the accepted LaTeX subset")
    }

    /// The erratum's parts: role and equations (`printed`, `corrected`, `counter-example`,
    /// `residual`), the empty ones left out.
    pub fn parts(&self) -> Vec<(&'static str, &[Equation])> {
        [
            ("printed", &self.printed[..]),
            ("corrected", &self.corrected[..]),
            ("counter-example", &self.counter_example[..]),
            ("residual", &self.residual[..]),
        ]
        .into_iter()
        .filter(|(_, e)| !e.is_empty())
        .collect()
    }

    /// The JSON object of `verify --json`: `printed`, `corrected`, `counter_example`,
    /// `residual` (arrays of `{ "text", "latex" }`) and `correction`.
    pub fn to_json(&self) -> Value {
        let n = self.notation();
        let eqs = |v: &[Equation]| Value::Array(v.iter().map(|e| e.to_json(&n)).collect());
        json!({
            "printed": eqs(&self.printed),
            "corrected": eqs(&self.corrected),
            "counter_example": eqs(&self.counter_example),
            "residual": eqs(&self.residual),
            "correction": self.correction,
        })
    }
}

/// How a claim of the catalogue is decided.
pub enum Check {
    /// By the unit's Rust code (an independent derivation, root isolation, seeded instances).
    Computed(fn() -> Result<Outcome, String>),
    /// By the claims-file engine: the claim of the same id in the unit's embedded claims file
    /// (the paper registry, `crate::papers`, holds the file, gives the claim its statement and
    /// expected verdict from it and decides it).
    Printed,
}

/// A claim of the catalogue.
pub struct Claim {
    /// The stable identifier of the claim list.
    pub id: &'static str,
    /// The statement as printed in the source (data, never "fixed" silently).
    pub statement: &'static str,
    /// The verdict the catalogue expects (what `verify` compares against).
    pub expected: Verdict,
    /// The computation that decides the claim.
    pub check: Check,
}

impl Claim {
    /// The claim `id` of the unit's embedded claims file (statement and expected verdict filled
    /// in by the paper registry).
    pub fn printed(id: &'static str) -> Claim {
        Claim {
            id,
            statement: "",
            expected: Verdict::Proved,
            check: Check::Printed,
        }
    }

    /// Decides a claim the unit's Rust code computes.
    ///
    /// # Errors
    /// Why the claim could not be decided; for a claim of the embedded claims file, that the
    /// paper registry decides it (`crate::papers::verify`).
    pub fn run(&self) -> Result<Outcome, String> {
        match &self.check {
            Check::Computed(f) => f(),
            Check::Printed => Err(format!(
                "{} is a claim of its paper's embedded claims file, decided by the paper registry",
                self.id
            )),
        }
    }
}

/// A checked claim (of the built-in catalogue or of a claims file).
pub struct Checked {
    /// The claim's id.
    pub id: String,
    /// The source it belongs to (the report filters by it): the id's prefix before the first
    /// `.` for the catalogue (`spaeth`), the file's paper name for a claims file.
    pub source: String,
    /// The printed statement.
    pub statement: String,
    /// The expected verdict.
    pub expected: Verdict,
    /// What the check found, or why it could not run.
    pub outcome: Result<Outcome, String>,
    /// Seconds the check took.
    pub seconds: f64,
    /// Why the claim is not as expected whatever its verdict (a claims file's `corrected` form
    /// not proved equal to its `rhs`), if so.
    pub problem: Option<String>,
    /// Whether the error of `outcome` is the claim's bad input (a formula that cannot be parsed
    /// or built), not a failure of the check: `verify` then exits with status 2.
    pub bad_input: bool,
    /// The typed fields of the identity engine's report as `prove --json` prints them (claims
    /// decided by the claims-file engine: `identity`, and `instances` with `random`), added to
    /// the JSON row; empty for the others.
    pub report: serde_json::Map<String, Value>,
}

impl Checked {
    /// Whether the verdict is the one the catalogue expects (and nothing else is wrong with
    /// the claim, see [`Checked::problem`]).
    pub fn as_expected(&self) -> bool {
        self.problem.is_none()
            && matches!(&self.outcome, Ok(o) if o.verdict == self.expected && o.verdict != Verdict::Undecided)
    }

    /// The JSON object of a verdict (`id`, `verdict`, `method`, `evidence`, plus more), with
    /// `erratum` ([`Erratum::to_json`]) when the check filled one, then the fields of
    /// [`Checked::report`] the row does not have already.
    pub fn to_json(&self) -> Value {
        match &self.outcome {
            Ok(o) => {
                let mut v = json!({
                    "id": self.id,
                    "verdict": o.verdict.to_string(),
                    "method": o.method,
                    "evidence": o.evidence,
                    "expected": self.expected.to_string(),
                    "as_expected": self.as_expected(),
                    "statement": self.statement,
                    "seconds": self.seconds,
                });
                if let Some(e) = &o.erratum {
                    v["erratum"] = e.to_json();
                }
                if let Some(p) = &self.problem {
                    v["problem"] = json!(p);
                }
                if let Value::Object(row) = &mut v {
                    for (key, value) in &self.report {
                        row.entry(key.clone()).or_insert_with(|| value.clone());
                    }
                }
                v
            }
            Err(e) => json!({
                "id": self.id,
                "verdict": "error",
                "method": "",
                "evidence": e,
                "expected": self.expected.to_string(),
                "as_expected": false,
                "statement": self.statement,
                "seconds": self.seconds,
            }),
        }
    }
}

/// The readable table of `verify`: id, verdict, method, evidence (wrapped), and a summary line.
pub fn table(rows: &[Checked]) -> String {
    let idw = rows.iter().map(|r| r.id.len()).max().unwrap_or(2).max(2);
    let mut s = format!(
        "{:idw$}  {:8}  {:38}  evidence\n",
        "id", "verdict", "method"
    );
    for r in rows {
        let (verdict, method, evidence) = match &r.outcome {
            Ok(o) => (o.verdict.to_string(), o.method.clone(), o.evidence.clone()),
            Err(e) => ("error".to_string(), String::new(), e.clone()),
        };
        let mark = match &r.problem {
            Some(p) => format!("  << not as expected: {p}"),
            None if r.as_expected() => String::new(),
            None => format!("  << expected {}", r.expected),
        };
        let mut lines = evidence.lines();
        s += &format!(
            "{:idw$}  {:8}  {:38}  {}{mark}\n",
            r.id,
            verdict,
            method,
            lines.next().unwrap_or(""),
        );
        for l in lines {
            s += &format!("{:idw$}  {:8}  {:38}  {}\n", "", "", "", l);
        }
    }
    let ok = rows.iter().filter(|r| r.as_expected()).count();
    s += &format!("{} claims, {} as expected", rows.len(), ok);
    for v in [
        Verdict::Proved,
        Verdict::Holds,
        Verdict::Fails,
        Verdict::Undecided,
    ] {
        let n = rows
            .iter()
            .filter(|r| matches!(&r.outcome, Ok(o) if o.verdict == v))
            .count();
        s += &format!(", {n} {v}");
    }
    // claims that could not be built or decided (verdict `error`), named only when present
    let errors = rows.iter().filter(|r| r.outcome.is_err()).count();
    if errors > 0 {
        s += &format!(", {errors} error");
    }
    s
}

#[cfg(test)]
mod verdict_tests {
    use super::engine::{prove_all, Symbols};
    use super::*;
    use exactcheck_exact::poly::Poly;
    use exactcheck_exact::Rational;

    #[test]
    fn undecided_is_its_own_verdict_and_never_as_expected() {
        // Old wrong answer: the engine's Undecided became `fails`.
        let mut sym = Symbols::new(&["x", "y"]);
        let x: Poly<Rational> = sym.parse("x").unwrap();
        let rel: Poly<Rational> = sym.parse("x^2 + y^2").unwrap();
        let o = prove_all(&sym, &[("x", x.clone())], &[rel], "test");
        assert_eq!(o.verdict, Verdict::Undecided, "{}", o.evidence);
        assert_eq!(o.verdict.to_string(), "undecided");
        let checked = Checked {
            id: "t".into(),
            source: "t".into(),
            statement: String::new(),
            expected: Verdict::Undecided,
            outcome: Ok(o),
            seconds: 0.0,
            problem: None,
            bad_input: false,
            report: Default::default(),
        };
        assert!(!checked.as_expected());
        assert_eq!(checked.to_json()["verdict"], "undecided");
        assert!(table(&[checked]).ends_with("1 undecided"));
        // Inconsistent relations are undecided too, never proved.
        let one: Poly<Rational> = sym.parse("1").unwrap();
        let o = prove_all(&sym, &[("x", x)], &[one], "test");
        assert_eq!(o.verdict, Verdict::Undecided);
        assert!(o.evidence.contains("inconsistent"));
    }
}
