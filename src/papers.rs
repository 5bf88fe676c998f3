//! The paper registry: every source the built-in catalogue checks, as one unit each — its
//! claims (`crate::claims::<unit>`) and its figures (drawn by `crate::plot`). `verify`, the
//! report and `plot` read the papers from here, so adding a paper is one module under
//! `src/claims/`, its figures (if any) in `src/plot/`, and one entry of [`PAPERS`].
//!
//! Several units can share one source document and claim-id prefix: Chiang's paper is four
//! units (`chiang`: ruled surfaces cut by planes; `chiang_conic`: the cone's conics;
//! `chiang_line`: lines and the vicinity test; `chiang_ph`: offsets of PH curves), all
//! `chiang.*` ids on one page.

use crate::claims::{self, Claim};
use crate::plot::{self, Figure};
use crate::Error;

/// One unit of the catalogue.
pub struct Paper {
    /// The module under `src/claims/` (`spaeth`, `chiang_conic`).
    pub unit: &'static str,
    /// The claim-id prefix of its claims, before the first `.` (`spaeth`, `chiang`).
    pub source: &'static str,
    /// The page of `docs/papers/` that states its claims.
    pub page: &'static str,
    /// Its claims, in the order of the papers' claim list.
    pub claims: fn() -> Vec<Claim>,
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
        figures: no_figures,
        plot: None,
    },
    Paper {
        unit: "spaeth",
        source: "spaeth",
        page: "docs/papers/spaeth.md",
        claims: spaeth_claims,
        figures: plot::spaeth_figures,
        plot: Some("spaeth"),
    },
    Paper {
        unit: "planes",
        source: "planes",
        page: "docs/papers/wabis.md",
        claims: claims::planes::claims,
        figures: no_figures,
        plot: None,
    },
    Paper {
        unit: "chiang",
        source: "chiang",
        page: "docs/papers/chiang.md",
        claims: claims::chiang::claims,
        figures: plot::chiang_figures,
        plot: Some("chiang"),
    },
    Paper {
        unit: "chiang_conic",
        source: "chiang",
        page: "docs/papers/chiang.md",
        claims: claims::chiang_conic::claims,
        figures: plot::conic_figures,
        plot: Some("conics"),
    },
    Paper {
        unit: "chiang_line",
        source: "chiang",
        page: "docs/papers/chiang.md",
        claims: claims::chiang_line::claims,
        figures: no_figures,
        plot: None,
    },
    Paper {
        unit: "chiang_ph",
        source: "chiang",
        page: "docs/papers/chiang.md",
        claims: claims::chiang_ph::claims,
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

/// Whether `name` is the `plot` name of a paper's figures (not a problem file).
pub fn is_plot_name(name: &str) -> bool {
    PAPERS.iter().any(|p| p.plot == Some(name))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_are_claim_modules_and_prefixes_match() {
        for p in &PAPERS {
            let claims = (p.claims)();
            assert!(!claims.is_empty(), "{}", p.unit);
            assert!(p.unit.starts_with(p.source), "{}", p.unit);
            for c in claims {
                assert_eq!(c.id.split('.').next(), Some(p.source), "{}", c.id);
            }
            let page = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(p.page);
            assert!(page.is_file(), "{}", p.page);
        }
    }

    #[test]
    fn plot_names_are_distinct() {
        let names: Vec<&str> = PAPERS.iter().filter_map(|p| p.plot).collect();
        let mut unique = names.clone();
        unique.dedup();
        assert_eq!(names, unique);
        assert!(is_plot_name("conics") && !is_plot_name("problem.json"));
    }
}
