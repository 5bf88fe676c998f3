//! The float-vs-exact regression summaries of the report: the four built-in kernels of
//! `exactcheck regress` run on seeded samples and summarised as tables.
//!
//! * `cylinder-sphere` and `bezier-cubic`: one harness sweep each (the inputs of
//!   [`crate::regress::generator`]), plus, for the cylinder/sphere, the roots' errors and the
//!   signs of the discriminant near tangency ([`crate::regress::root_errors`],
//!   [`crate::regress::sign_errors`]);
//! * `plane-plane`: the published JavaScript port against the exact construction, binned by
//!   the angle between the normals ([`crate::regress::planes::run`]);
//! * `ruled-plane`: Chiang's plane section, weights and points, for each shape on random and
//!   near-degenerate inputs ([`crate::regress::ruled::rows`]).
//!
//! Each becomes a [`Summary`]: tables of plain text cells the HTML writer prints as they are.

use crate::regress::planes::{self, cell};
use crate::regress::{self as regress_cmd, ruled, BezierCubicKernel, CylinderSphereKernel, Kernel};
use crate::Error;
use exactcheck_exact::Rational;
use exactcheck_float::{Options, Report};
use std::time::Instant;

/// A table: a caption, the column heads and rows of cells (plain text).
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// What the table shows.
    pub caption: String,
    /// The column heads.
    pub head: Vec<String>,
    /// The rows, each as long as `head`.
    pub rows: Vec<Vec<String>>,
}

/// The summary of one kernel's regression.
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// The kernel's name as `regress` takes it (`cylinder-sphere`), or the name of a saved
    /// run's formula or benchmark; also the anchor.
    pub kernel: String,
    /// What is regressed against what.
    pub title: String,
    /// The command that reproduces it in full.
    pub command: String,
    /// Seconds it took.
    pub seconds: f64,
    /// The tables.
    pub tables: Vec<Table>,
}

/// The kernels in report order.
pub const KERNELS: [&str; 4] = [
    "cylinder-sphere",
    "bezier-cubic",
    "plane-plane",
    "ruled-plane",
];

/// Runs the kernel named `kernel` (one of [`KERNELS`]) on `samples` samples of seed `seed`.
///
/// # Errors
/// [`Error::Usage`] for an unknown kernel or options the harness refuses.
pub fn summary(kernel: &'static str, samples: usize, seed: u64) -> Result<Summary, Error> {
    let start = Instant::now();
    let options = Options {
        worst: 1,
        ..Options::default()
    };
    let command = format!("exactcheck regress {kernel} --samples {samples} --seed {seed}");
    let usage = |e: &dyn std::fmt::Display| Error::Usage(format!("regress {kernel}: {e}"));
    let (title, tables) = match kernel {
        "cylinder-sphere" => {
            let gen = regress_cmd::generator(Kernel::CylinderSphere)?;
            let report = exactcheck_float::regress::<Rational>(
                &CylinderSphereKernel,
                &gen,
                samples,
                seed,
                &options,
            )
            .map_err(|e| usage(&e))?;
            let roots = regress_cmd::root_errors(&gen, samples, seed);
            let signs = regress_cmd::sign_errors(samples, seed);
            let extra = Table {
                caption: "the roots u = -A ± sqrt(A² - B) in f64 against the exact roots, and the sign of A² - B near tangency".into(),
                head: vec!["measure".into(), "samples".into(), "result".into(), "worst inputs".into()],
                rows: vec![
                    vec![
                        "roots: max / median ulps".into(),
                        roots.compared.to_string(),
                        format!("{} / {}", cell(roots.max_ulps), cell(roots.median_ulps)),
                        inputs(&roots.worst),
                    ],
                    vec![
                        "signs near tangency: f64 real where exact none / f64 none where exact real / exactly zero".into(),
                        signs.samples.to_string(),
                        format!("{} / {} / {}", signs.false_real, signs.false_empty, signs.exact_zero),
                        String::new(),
                    ],
                ],
            };
            (
                "Spaeth's cylinder/sphere coefficients A(t), B(t) and A² - B, f64 against exact"
                    .to_string(),
                vec![
                    harness_table("A(t), B(t), A² - B", &[("all", &report)]),
                    extra,
                ],
            )
        }
        "bezier-cubic" => {
            let gen = regress_cmd::generator(Kernel::BezierCubic)?;
            let report = exactcheck_float::regress::<Rational>(
                &BezierCubicKernel,
                &gen,
                samples,
                seed,
                &options,
            )
            .map_err(|e| usage(&e))?;
            (
                "de Casteljau evaluation of a cubic Bézier curve in space, f64 against exact"
                    .to_string(),
                vec![harness_table("the point B(t)", &[("all", &report)])],
            )
        }
        "plane-plane" => {
            let r = planes::run(samples, seed, 1);
            let bins = Table {
                caption: format!(
                    "{} cases measured, {} skipped, {} null results and {} non-finite points where the planes meet in a line; errors in ulps, binned by the angle between the normals",
                    r.measured, r.skipped, r.null_results, r.non_finite_results
                ),
                head: [
                    "angle (rad)",
                    "cases",
                    "non-finite points",
                    "point: max ulps",
                    "point: median",
                    "direction: max ulps",
                    "direction: median",
                    "worst inputs (p1, n1, p2, n2)",
                ]
                .map(String::from)
                .to_vec(),
                rows: r
                    .bins
                    .iter()
                    .filter(|b| b.count > 0)
                    .map(|b| {
                        vec![
                            if b.lo == 0.0 {
                                format!("(0, {:.0e})", b.hi)
                            } else {
                                format!("[{:.0e}, {:.3})", b.lo, b.hi)
                            },
                            b.count.to_string(),
                            b.non_finite.to_string(),
                            cell(b.point_max),
                            cell(b.point_median),
                            cell(b.direction_max),
                            cell(b.direction_median),
                            b.worst.map_or_else(String::new, |(i, c)| {
                                format!(
                                    "sample {i}: {}, {}, {}, {}",
                                    inputs(&c.p1),
                                    inputs(&c.n1),
                                    inputs(&c.p2),
                                    inputs(&c.n2)
                                )
                            }),
                        ]
                    })
                    .collect(),
            };
            (
                "the published JavaScript InterctionLineOf2Areas (ported to f64) against the exact two-plane construction".to_string(),
                vec![bins],
            )
        }
        "ruled-plane" => {
            let rows = ruled::rows::<Rational>(samples, seed, &options)?;
            let labels: Vec<(String, String)> = rows
                .iter()
                .map(|r| {
                    let shape = format!("({}, {}) {}", r.m, r.n, r.regime.label());
                    (format!("{shape}: weights"), format!("{shape}: points"))
                })
                .collect();
            let named: Vec<(&str, &Report)> = rows
                .iter()
                .zip(&labels)
                .flat_map(|(r, (w, p))| [(w.as_str(), &r.weights), (p.as_str(), &r.points)])
                .collect();
            (
                "Chiang's plane section of a ruled surface (Theorem 1: weights and control points), f64 against exact".to_string(),
                vec![harness_table(
                    "each shape (m, n) on random and near-degenerate surfaces",
                    &named,
                )],
            )
        }
        other => {
            return Err(Error::Usage(format!(
                "no regression kernel {other:?} (kernels: {})",
                KERNELS.join(", ")
            )))
        }
    };
    Ok(Summary {
        kernel: kernel.to_string(),
        title,
        command,
        seconds: start.elapsed().as_secs_f64(),
        tables,
    })
}

/// The table of harness reports: samples, compared, skipped, failures, max/median ulps,
/// Herbie's bits, the worst input.
fn harness_table(caption: &str, reports: &[(&str, &Report)]) -> Table {
    Table {
        caption: caption.to_string(),
        head: [
            "outputs",
            "samples",
            "compared",
            "undecided",
            "outside the domain",
            "float failures",
            "max ulps",
            "median ulps",
            "bits of error: mean",
            "bits: max",
            "worst input",
        ]
        .map(String::from)
        .to_vec(),
        rows: reports
            .iter()
            .map(|(name, r)| {
                let worst = r.worst.first().map_or_else(String::new, |w| {
                    let o = &w.original;
                    match &w.shrunk {
                        Some(sh) if sh.inputs != o.inputs => format!(
                            "sample {} ({} ulps), shrunk to {} ({} ulps)",
                            w.index,
                            cell(o.ulps),
                            inputs(&sh.inputs),
                            cell(sh.ulps)
                        ),
                        _ => format!(
                            "sample {}: {} ulps at {}",
                            w.index,
                            cell(o.ulps),
                            inputs(&o.inputs)
                        ),
                    }
                });
                vec![
                    (*name).to_string(),
                    r.samples.to_string(),
                    r.compared.to_string(),
                    r.undecided.to_string(),
                    r.domain_errors.to_string(),
                    r.float_failures.to_string(),
                    cell(r.max_ulps),
                    cell(r.median_ulps),
                    format!("{:.2}", r.bits_of_error),
                    format!("{:.2}", r.max_bits),
                    worst,
                ]
            })
            .collect(),
    }
}

/// Why the worst cases of a built-in kernel are not explained.
pub const KERNEL_NOT_EXPLAINED: &str = "Local errors per operation and conditioning are not shown for the built-in kernels: they are compiled Rust code, not a float program whose operations can be fed exact operands one by one; a formula or FPCore benchmark (regress --formula, --fpcore, saved with --json and given to report --regress) is explained.";

/// The summary of one entry of a saved `regress --json` run (or of a `merge`d one): the harness
/// table and its worst cases with where their error comes from (the local error of each
/// operation and the conditioning, as the run computed them), or why that is not known.
pub fn saved_summary(entry: &crate::regress::sweep::Entry, file: &str) -> Summary {
    let command = format!("saved in {file}");
    let Ok(r) = &entry.outcome else {
        let why = entry.outcome.as_ref().err().cloned().unwrap_or_default();
        return Summary {
            kernel: entry.name.clone(),
            title: format!("{}: not run", entry.name),
            command,
            seconds: 0.0,
            tables: vec![Table {
                caption: "why the benchmark was not run".into(),
                head: vec!["reason".into()],
                rows: vec![vec![why]],
            }],
        };
    };
    let built_in = r.float_side.starts_with("built-in ");
    let rows = r
        .worst
        .iter()
        .map(|w| {
            let case = w.shrunk.as_ref().unwrap_or(&w.original);
            let (bits, local, conditioning) = match &w.explanation {
                Some(e) => (format!("{:.1}", e.bits), e.local(), e.verdict()),
                None if built_in => (
                    format!("{:.1}", w.original.bits),
                    "not available: a built-in kernel is compiled code, not a float program".into(),
                    "not available (no float program to differentiate)".into(),
                ),
                None => (
                    format!("{:.1}", w.original.bits),
                    "not available: the saved run carries no explanation of this case".into(),
                    "not available".into(),
                ),
            };
            vec![
                w.index.to_string(),
                inputs(&w.original.inputs),
                cell(w.original.ulps),
                inputs(&case.inputs),
                bits,
                local,
                conditioning,
            ]
        })
        .collect();
    Summary {
        kernel: entry.name.clone(),
        title: if r.precision == "binary64" {
            format!(
                "saved run: {} against the exact value ({}, seed {})",
                r.float_side, r.generator, r.seed
            )
        } else {
            format!(
                "saved run: {} in {} against the exact value ({}, seed {}; errors in {} ulps)",
                r.float_side, r.precision, r.generator, r.seed, r.precision
            )
        },
        command,
        seconds: 0.0,
        tables: vec![
            harness_table("the saved run", &[("all", r)]),
            Table {
                caption: "the worst samples explained: the operations that lose the bits (each fed exact operands) and the conditioning of the exact function there".into(),
                head: [
                    "sample",
                    "inputs",
                    "ulps",
                    "shrunk to",
                    "bits lost",
                    "local error",
                    "conditioning",
                ]
                .map(String::from)
                .to_vec(),
                rows,
            },
        ],
    }
}

/// Inputs as `[a, b, ...]`, each double printed so it reads back exactly.
fn inputs(x: &[f64]) -> String {
    let cells: Vec<String> = x.iter().map(|v| format!("{v:?}")).collect();
    format!("[{}]", cells.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kernel_summarises_deterministically() {
        for kernel in KERNELS {
            let a = summary(kernel, 40, 3).unwrap();
            assert!(!a.tables.is_empty(), "{kernel}");
            for t in &a.tables {
                assert!(!t.rows.is_empty(), "{kernel}: {}", t.caption);
                assert!(t.rows.iter().all(|r| r.len() == t.head.len()), "{kernel}");
            }
            let b = summary(kernel, 40, 3).unwrap();
            assert_eq!(a.tables, b.tables, "{kernel}");
        }
        assert!(summary("nope", 10, 1).is_err());
    }

    #[test]
    fn harness_rows_carry_the_report() {
        let s = summary("bezier-cubic", 50, 1).unwrap();
        let row = &s.tables[0].rows[0];
        assert_eq!(row[1], "50");
        assert_eq!(
            row[2], "50",
            "every de Casteljau sample is compared: {row:?}"
        );
        assert!(row[10].starts_with("sample "), "{row:?}");
    }
}
