//! The paper registry: every source the built-in catalogue checks, as one unit each — its
//! claims (`crate::claims::<unit>`) and its figures (drawn by `crate::plot`). `verify`, the
//! report and `plot` read the papers from here, so adding a paper is one module under
//! `src/claims/` (with an embedded `claims.toml` for the claims that state printed formulas
//! alone), its figures (if any) in `src/plot/` (with its name in [`plot::FIGURE_NAMES`]), and
//! one entry of [`PAPERS`]. The catalogue is run from here
//! ([`verify`]): the registry sits above the claims and the figures, which never refer back.
//!
//! Several units can share one source document and claim-id prefix: Chiang's paper is four
//! units (`chiang`: ruled surfaces cut by planes; `chiang_conic`: the cone's conics;
//! `chiang_line`: lines and the vicinity test; `chiang_ph`: offsets of PH curves), all
//! `chiang.*` ids on one page.

use crate::claims::{self, Check, Checked, Claim, Outcome};
use crate::plot::{self, Figure};
use crate::Error;
use embedded::Embedded;
use rayon::prelude::*;
use serde_json::{Map, Value};
use std::time::Instant;

pub mod embedded;

/// Juettler's claims that state printed formulas alone.
static JUTTLER_PRINTED: Embedded = Embedded::new(
    "src/claims/juttler/claims.toml",
    include_str!("claims/juttler/claims.toml"),
);

/// Spaeth's claims that state printed formulas alone.
static SPAETH_PRINTED: Embedded = Embedded::new(
    "src/claims/spaeth/claims.toml",
    include_str!("claims/spaeth/claims.toml"),
);

/// One unit of the catalogue.
pub struct Paper {
    /// The module under `src/claims/` (`spaeth`, `chiang_conic`).
    pub unit: &'static str,
    /// The claim-id prefix of its claims, before the first `.` (`spaeth`, `chiang`).
    pub source: &'static str,
    /// The page of `docs/papers/` that states its claims.
    pub page: &'static str,
    /// Its claims, in the order of the papers' claim list: those its Rust code computes and
    /// those of its embedded claims file, taken by id.
    pub claims: fn() -> Vec<Claim>,
    /// Its embedded claims file (`src/claims/<unit>/claims.toml`): the claims that state the
    /// paper's printed formulas alone, decided by the claims-file engine.
    pub printed: Option<&'static Embedded>,
    /// Its figures, in the report's order (none for most).
    pub figures: fn() -> Result<Vec<Figure>, Error>,
    /// The name `exactcheck plot NAME` draws its figures by, if it has figures.
    pub plot: Option<&'static str>,
}

fn no_figures() -> Result<Vec<Figure>, Error> {
    Ok(Vec::new())
}

fn spaeth_claims() -> Vec<Claim> {
    let mut all = claims::spaeth::claims();
    all.extend(claims::spaeth::example_claims());
    all
}

/// Every unit, in catalogue order (the order of the claim list in `docs/papers/README.md`).
pub const PAPERS: [Paper; 7] = [
    Paper {
        unit: "juttler",
        source: "juttler",
        page: "docs/papers/juttler.md",
        claims: claims::juttler::claims,
        printed: Some(&JUTTLER_PRINTED),
        figures: no_figures,
        plot: None,
    },
    Paper {
        unit: "spaeth",
        source: "spaeth",
        page: "docs/papers/spaeth.md",
        claims: spaeth_claims,
        printed: Some(&SPAETH_PRINTED),
        figures: plot::spaeth_figures,
        plot: Some("spaeth"),
    },
    Paper {
        unit: "planes",
        source: "planes",
        page: "docs/papers/wabis.md",
        claims: claims::planes::claims,
        printed: None,
        figures: no_figures,
        plot: None,
    },
    Paper {
        unit: "chiang",
        source: "chiang",
        page: "docs/papers/chiang.md",
        claims: claims::chiang::claims,
        printed: None,
        figures: plot::chiang_figures,
        plot: Some("chiang"),
    },
    Paper {
        unit: "chiang_conic",
        source: "chiang",
        page: "docs/papers/chiang.md",
        claims: claims::chiang_conic::claims,
        printed: None,
        figures: plot::conic_figures,
        plot: Some("conics"),
    },
    Paper {
        unit: "chiang_line",
        source: "chiang",
        page: "docs/papers/chiang.md",
        claims: claims::chiang_line::claims,
        printed: None,
        figures: no_figures,
        plot: None,
    },
    Paper {
        unit: "chiang_ph",
        source: "chiang",
        page: "docs/papers/chiang.md",
        claims: claims::chiang_ph::claims,
        printed: None,
        figures: plot::ph_figures,
        plot: Some("ph"),
    },
];

/// Every figure of the catalogue, in registry order (the report shows them in this order).
///
/// # Errors
/// When a figure cannot be drawn (an internal error of the catalogue's data).
pub fn figures() -> Result<Vec<Figure>, Error> {
    let mut out = Vec::new();
    for p in &PAPERS {
        out.extend((p.figures)()?);
    }
    Ok(out)
}

impl Paper {
    /// Its claims, in the order of the papers' claim list, those of its embedded claims file
    /// with their statement and expected verdict as the file gives them.
    pub fn claims(&self) -> Vec<Claim> {
        let mut claims = (self.claims)();
        for c in &mut claims {
            if let (Check::Printed, Some(file)) = (&c.check, self.printed) {
                (c.statement, c.expected) = file.statement_and_expected(c.id);
            }
        }
        claims
    }

    /// Decides one of its claims: computed by its Rust code, or by the claims-file engine from
    /// its embedded file. The catalogue's claims are not the user's input: an error is the
    /// claim's, never bad input.
    fn decide(&self, c: &Claim) -> (Result<Outcome, String>, Option<String>, Map<String, Value>) {
        match (&c.check, self.printed) {
            (Check::Computed(f), _) => (f(), None, Map::new()),
            (Check::Printed, Some(file)) => match file.decide(c.id) {
                Ok(d) => (Ok(d.outcome), d.problem, d.report),
                Err((m, _)) => (Err(m), None, Map::new()),
            },
            (Check::Printed, None) => (
                Err(format!(
                    "{}: the unit {} has no claims file",
                    c.id, self.unit
                )),
                None,
                Map::new(),
            ),
        }
    }
}

/// The whole catalogue in the order of the papers' claim list (docs/papers/README.md): the
/// claims of every unit of [`PAPERS`].
pub fn catalogue() -> Vec<Claim> {
    PAPERS.iter().flat_map(Paper::claims).collect()
}

/// Checks every claim whose id starts with `prefix` (all when `None`).
///
/// # Errors
/// When a prefix is given and no claim id starts with it.
pub fn verify(prefix: Option<&str>) -> Result<Vec<Checked>, Error> {
    verify_with(prefix, true)
}

/// [`verify`], showing a progress bar on standard error unless `quiet` (or it is not a
/// terminal).
///
/// The claims run in parallel on rayon's global pool (`RAYON_NUM_THREADS` sets its size); the
/// rows come back in catalogue order whatever the number of threads. The workers read the same
/// process-wide `--limit` values (atomics of `exactcheck_core::limits`) and allocate through the
/// same counting allocator as the main thread.
///
/// # Errors
/// As [`verify`].
pub fn verify_with(prefix: Option<&str>, quiet: bool) -> Result<Vec<Checked>, Error> {
    let claims: Vec<(&Paper, Claim)> = PAPERS
        .iter()
        .flat_map(|p| p.claims().into_iter().map(move |c| (p, c)))
        .filter(|(_, c)| prefix.is_none_or(|p| c.id.starts_with(p)))
        .collect();
    if claims.is_empty() {
        let known: Vec<&str> = catalogue().iter().map(|c| c.id).collect();
        return Err(Error::Usage(format!(
            "no claim id starts with {:?} (claims: {})",
            prefix.unwrap_or(""),
            known.join(", ")
        )));
    }
    let steps = crate::output::Steps::new(claims.len() as u64, quiet);
    // The claims are independent: each is a task of rayon's pool (`with_max_len(1)`: one claim
    // per task, so a long claim never holds a queue of short ones). `collect` keeps catalogue
    // order, so the rows, and every output made from them, do not depend on the thread count.
    Ok(claims
        .par_iter()
        .with_max_len(1)
        .map(|(paper, c)| {
            steps.start(c.id);
            let start = Instant::now();
            let (outcome, problem, report) = paper.decide(c);
            steps.done();
            Checked {
                id: c.id.to_string(),
                source: c.id.split('.').next().unwrap_or(c.id).to_string(),
                statement: c.statement.to_string(),
                expected: c.expected,
                outcome,
                seconds: start.elapsed().as_secs_f64(),
                problem,
                bad_input: false,
                report,
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_are_claim_modules_and_prefixes_match() {
        for p in &PAPERS {
            let claims = p.claims();
            assert!(!claims.is_empty(), "{}", p.unit);
            assert!(p.unit.starts_with(p.source), "{}", p.unit);
            for c in claims {
                assert_eq!(c.id.split('.').next(), Some(p.source), "{}", c.id);
            }
            let page = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(p.page);
            assert!(page.is_file(), "{}", p.page);
        }
    }

    /// Every embedded claims file parses, names its paper's source, gives every claim an
    /// expected verdict, and each of its claims is in its unit's list exactly once.
    #[test]
    fn embedded_claims_files_are_the_units_printed_claims() {
        for p in &PAPERS {
            let Some(e) = p.printed else { continue };
            let file = e.file().unwrap_or_else(|m| panic!("{}: {m}", e.path));
            assert_eq!(file.paper.name, p.source, "{}", e.path);
            assert!(file.warnings.is_empty(), "{}: {:?}", e.path, file.warnings);
            assert!(!file.claims.is_empty(), "{}", e.path);
            let claims = p.claims();
            for c in &file.claims {
                assert!(c.expect.is_some(), "{}: {} has no expect", e.path, c.id);
                let uses = claims
                    .iter()
                    .filter(|k| matches!(k.check, Check::Printed) && k.id == c.id)
                    .count();
                assert_eq!(uses, 1, "{}: {} is taken {uses} times", e.path, c.id);
            }
            for k in claims.iter().filter(|k| matches!(k.check, Check::Printed)) {
                assert!(!k.statement.is_empty(), "{}: not in {}", k.id, e.path);
            }
        }
        // A unit without a file has no claim that needs one.
        for p in PAPERS.iter().filter(|p| p.printed.is_none()) {
            assert!(p
                .claims()
                .iter()
                .all(|k| matches!(k.check, Check::Computed(_))));
        }
    }

    #[test]
    fn plot_names_are_distinct() {
        let names: Vec<&str> = PAPERS.iter().filter_map(|p| p.plot).collect();
        let mut unique = names.clone();
        unique.dedup();
        assert_eq!(names, unique);
        // `plot` dispatches on its own list of names: the same set as the registry's.
        let mut sorted = names.clone();
        sorted.sort_unstable();
        let mut drawn = plot::FIGURE_NAMES.to_vec();
        drawn.sort_unstable();
        assert_eq!(sorted, drawn);
    }

    #[test]
    fn no_claim_expects_undecided() {
        assert!(catalogue()
            .iter()
            .all(|c| c.expected != claims::Verdict::Undecided));
    }
}
