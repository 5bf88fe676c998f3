//! What `regress --formula` / `--fpcore` says about where the error comes from:
//! * each worst case's [`Explanation`]: the operations losing the most bits when fed exact
//!   operands ([`Program::local_errors`]) and the relative condition number of the exact
//!   function there ([`Program::conditioning`]);
//! * `--bin EXPR`: the compared samples binned by the exact value of an expression over the
//!   inputs (decades of its magnitude, by sign), with the error in each bin ([`Bins`]);
//! * `--csv FILE`: one row per compared sample ([`Csv`]);
//! * `--html FILE`: the report with an error-vs-input plot per input ([`html`]).
use crate::Error;
use exactcheck_exact::program::{Conditioning, ExactStop, Program};
use exactcheck_exact::Rational;
use exactcheck_float::summary::herbie_bits_in;
use exactcheck_float::{Case, Explanation, Observed, OperationError, Report};
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// At most this many named operations per explanation.
const MAX_OPERATIONS: usize = 3;

/// The explanation of one case of `program`; `external`: the float side is the user's
/// program, whose operations are unknown (only the conditioning is given).
pub fn explain(program: &Program, case: &Case, external: bool) -> Option<Explanation> {
    let x: Vec<Rational> = case
        .inputs
        .iter()
        .map(|&v| exactcheck_float::ExactScalar::from_f64_exact(v))
        .collect::<Option<_>>()?;
    let output = (0..case.ulps_per_output.len())
        .max_by(|&a, &b| {
            case.ulps_per_output[a]
                .total_cmp(&case.ulps_per_output[b])
                .then(b.cmp(&a))
        })
        .unwrap_or(0);
    let bits = case
        .float_outputs
        .as_ref()
        .and_then(|f| f.get(output))
        .zip(case.exact_outputs_f64.get(output))
        .map_or(64.0, |(&f, &e)| herbie_bits_in(program.precision, f, e));
    let (operations, operations_note) = if external {
        (
            Vec::new(),
            Some("the float side is an external program, whose operations are not known".into()),
        )
    } else {
        match program.local_errors(&x) {
            Ok(list) => {
                let mut ops: Vec<OperationError> = list
                    .into_iter()
                    .map(|o| OperationError {
                        operation: o.operation.to_string(),
                        at: o.at,
                        bits: herbie_bits_in(program.precision, o.float, o.exact),
                    })
                    .filter(|o| o.bits > Explanation::DOMINANT_BITS)
                    .collect();
                ops.sort_by(|a, b| b.bits.total_cmp(&a.bits));
                ops.truncate(MAX_OPERATIONS);
                (ops, None)
            }
            Err(e) => (Vec::new(), Some(stop_text(e))),
        }
    };
    let (condition, condition_note) = match program.conditioning(&x) {
        Ok(c) => match c.get(output) {
            Some(Conditioning::Number(c)) => (Some(*c), None),
            Some(Conditioning::ZeroValue) => (None, Some("the exact value is 0".to_string())),
            Some(Conditioning::NotDifferentiable) => {
                (None, Some("not differentiable at the sample".to_string()))
            }
            None => (None, Some("no such output".to_string())),
        },
        Err(e) => (None, Some(stop_text(e))),
    };
    Some(Explanation {
        output,
        bits,
        operations,
        operations_note,
        condition,
        condition_note,
    })
}

fn stop_text(e: ExactStop) -> String {
    format!("an exact value is {e}")
}

/// Fills in the explanation of every worst case of `report`.
pub fn explain_report(program: &Program, report: &mut Report, external: bool) {
    for w in &mut report.worst {
        w.explanation = explain(program, &w.original, external);
    }
}

// ------------------------------------------------------------------ --bin

/// One bin: the samples whose binning value has this sign and decade.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Bin {
    /// Compared samples in the bin.
    pub samples: usize,
    /// Sum of their bits of error.
    pub bits_sum: f64,
    /// Largest bits of error.
    pub max_bits: f64,
    /// Largest error in ulps.
    pub max_ulps: f64,
}

/// The samples binned by the exact value of an expression: by sign, then by the decade
/// `[10^k, 10^(k+1))` of the magnitude of the value rounded to a double (0 is its own bin).
#[derive(Clone, Debug, PartialEq)]
pub struct Bins {
    /// The expression.
    pub expr: String,
    program: Program,
    /// `(sign, decade)` to the bin; sign `-1`, `0` (the value 0, decade 0) or `1`.
    pub bins: BTreeMap<(i8, i32), Bin>,
}

impl Bins {
    /// Bins by `expr`, an expression over the inputs of `program`.
    ///
    /// # Errors
    /// [`Error::Input`]: the expression does not parse or names a variable that is not an
    /// input.
    pub fn new(expr: &str, program: &Program) -> Result<Bins, Error> {
        let inputs = super::near::expression_inputs("--bin", expr, &program.inputs)?;
        let bin =
            Program::parse(expr, Some(&inputs)).map_err(|e| Error::Input(format!("--bin: {e}")))?;
        if bin.outputs.len() != 1 {
            return Err(Error::Input("--bin needs one expression".into()));
        }
        Ok(Bins {
            expr: expr.to_string(),
            program: bin,
            bins: BTreeMap::new(),
        })
    }

    /// Adds one compared sample.
    ///
    /// # Errors
    /// The expression is undefined at the sample (or its value cannot be decided): one line
    /// naming the sample and its inputs.
    pub fn add(&mut self, s: &Observed<'_>) -> Result<(), String> {
        let x: Vec<Rational> = s
            .inputs
            .iter()
            .map(|&v| exactcheck_float::ExactScalar::from_f64_exact(v))
            .collect::<Option<_>>()
            .ok_or_else(|| format!("--bin: sample {} has a non-finite input", s.index))?;
        let value = match self.program.eval_exact(&x) {
            Ok(r) => exactcheck_float::convert::rational_to_f64(&r[0].value),
            Err(e) => {
                let inputs: Vec<String> = self
                    .program
                    .inputs
                    .iter()
                    .zip(s.inputs)
                    .map(|(n, v)| format!("{n} = {v:?}"))
                    .collect();
                let why = match e {
                    ExactStop::OutsideDomain => "undefined (outside its domain)".to_string(),
                    other => other.to_string(),
                };
                return Err(format!(
                    "--bin '{}' is {why} at sample {} ({})",
                    self.expr,
                    s.index,
                    inputs.join(", ")
                ));
            }
        };
        let key = if value == 0.0 {
            (0, 0)
        } else {
            let sign = if value < 0.0 { -1 } else { 1 };
            // The decade of a finite nonzero double is within [-324, 308].
            (sign, value.abs().log10().floor() as i32)
        };
        let b = self.bins.entry(key).or_default();
        b.samples += 1;
        b.bits_sum += s.bits;
        b.max_bits = b.max_bits.max(s.bits);
        b.max_ulps = b.max_ulps.max(s.max_ulps);
        Ok(())
    }

    /// The bins in increasing order of value.
    fn ordered(&self) -> Vec<((i8, i32), &Bin)> {
        let mut v: Vec<_> = self.bins.iter().map(|(k, b)| (*k, b)).collect();
        v.sort_by_key(|&((sign, d), _)| (sign, if sign < 0 { -d } else { d }));
        v
    }

    fn label((sign, d): (i8, i32)) -> String {
        match sign {
            0 => "0".to_string(),
            1 => format!("[1e{d}, 1e{})", d + 1),
            _ => format!("(-1e{}, -1e{d}]", d + 1),
        }
    }

    /// The table, one line per bin.
    pub fn text(&self) -> String {
        let mut rows = vec![[
            "value of bin".to_string(),
            "samples".into(),
            "bits (mean)".into(),
            "bits (max)".into(),
            "max ulps".into(),
        ]];
        for (k, b) in self.ordered() {
            rows.push([
                Self::label(k),
                b.samples.to_string(),
                format!("{:.2}", b.bits_sum / b.samples as f64),
                format!("{:.2}", b.max_bits),
                super::planes::cell(b.max_ulps),
            ]);
        }
        let widths: Vec<usize> = (0..5)
            .map(|c| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(0))
            .collect();
        let mut out = format!("  error by the value of --bin {}:\n", self.expr);
        for r in &rows {
            let cells: Vec<String> = r
                .iter()
                .zip(&widths)
                .enumerate()
                .map(|(c, (s, &w))| {
                    if c == 0 {
                        format!("{s:<w$}")
                    } else {
                        format!("{s:>w$}")
                    }
                })
                .collect();
            let _ = writeln!(out, "    {}", cells.join("  ").trim_end());
        }
        out
    }

    /// The bins as JSON.
    pub fn to_json(&self) -> Value {
        json!({
            "expr": self.expr,
            "bins": self.ordered().into_iter().map(|(k, b)| json!({
                "bin": Self::label(k),
                "samples": b.samples,
                "mean_bits": b.bits_sum / b.samples as f64,
                "max_bits": b.max_bits,
                "max_ulps": if b.max_ulps.is_finite() { json!(b.max_ulps) } else { json!("inf") },
            })).collect::<Vec<_>>(),
        })
    }
}

// ------------------------------------------------------------------ --csv

/// The per-sample export: a header, then one row per compared sample.
pub struct Csv {
    text: String,
}

/// A double for the CSV: round-trip digits, `inf`, `-inf`, `NaN`.
fn cell(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else {
        format!("{x:?}")
    }
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
fn field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

impl Csv {
    /// The header for `program`'s inputs and outputs.
    pub fn new(program: &Program) -> Csv {
        let mut cols = vec!["sample".to_string()];
        // An input of another precision than the program's says which.
        cols.extend(program.inputs.iter().enumerate().map(|(i, n)| {
            let f = program.input_format(i);
            if f == program.precision {
                field(n)
            } else {
                field(&format!("{n} [{}]", f.name()))
            }
        }));
        let n = program.outputs.len();
        for o in 0..n {
            let suffix = if n > 1 {
                format!("_{}", o + 1)
            } else {
                String::new()
            };
            for c in ["float", "exact_rounded", "ulps"] {
                cols.push(format!("{c}{suffix}"));
            }
        }
        cols.push("max_ulps".into());
        cols.push("bits".into());
        Csv {
            text: cols.join(",") + "\n",
        }
    }

    /// Adds one compared sample.
    pub fn add(&mut self, s: &Observed<'_>) {
        let mut row = vec![s.index.to_string()];
        row.extend(s.inputs.iter().map(|&x| cell(x)));
        for (o, e) in s.exact.iter().enumerate() {
            let f = s.float.and_then(|f| f.get(o)).copied().unwrap_or(f64::NAN);
            row.push(cell(f));
            row.push(cell(exactcheck_float::convert::rational_to_f64(&e.value)));
            row.push(cell(s.ulps.get(o).copied().unwrap_or(f64::INFINITY)));
        }
        row.push(cell(s.max_ulps));
        row.push(cell(s.bits));
        self.text.push_str(&row.join(","));
        self.text.push('\n');
    }

    /// The whole file.
    pub fn contents(&self) -> &str {
        &self.text
    }
}

/// Checks a `--csv` or `--html` output path before the sweep: a file name (not a directory)
/// whose directory exists.
///
/// # Errors
/// [`Error::Usage`] naming the option and the path.
pub fn check_output(option: &str, path: &str) -> Result<(), Error> {
    crate::output::check_output_file(path, &[])
        .map_err(|e| Error::Usage(format!("{option}: {e}")))?;
    let p = std::path::Path::new(path);
    let dir = match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => std::path::Path::new("."),
    };
    if !dir.is_dir() {
        return Err(Error::Usage(format!(
            "{option} {path}: the directory {} does not exist",
            dir.display()
        )));
    }
    Ok(())
}

// ------------------------------------------------------------------ --html

/// At most this many samples are plotted (every k-th compared sample, by index).
pub const PLOT_POINTS: usize = 2000;

/// The points of the error-vs-input plots: every `stride`-th sample's inputs and bits.
pub struct Points {
    stride: usize,
    /// `(inputs, bits)` of the kept samples.
    pub points: Vec<(Vec<f64>, f64)>,
}

impl Points {
    /// Keeps about [`PLOT_POINTS`] of `samples`.
    pub fn new(samples: usize) -> Points {
        Points {
            stride: samples.div_ceil(PLOT_POINTS).max(1),
            points: Vec::new(),
        }
    }

    /// Offers one compared sample.
    pub fn add(&mut self, s: &Observed<'_>) {
        if s.index % self.stride == 0 {
            self.points.push((s.inputs.to_vec(), s.bits.min(64.0)));
        }
    }
}

/// The SVG scatter plot of bits of error against input `i`.
fn plot(points: &[(Vec<f64>, f64)], i: usize, name: &str) -> Result<String, Error> {
    use plotters::prelude::*;
    let xs: Vec<f64> = points.iter().map(|(x, _)| x[i]).collect();
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    // A positive range over several decades is plotted against log10 of the input.
    let log = lo > 0.0 && hi / lo > 1e3;
    let map = |x: f64| if log { x.log10() } else { x };
    let (a, b) = if lo.is_finite() {
        let (a, b) = (map(lo), map(hi));
        if a == b {
            (a - 1.0, b + 1.0)
        } else {
            (a, b)
        }
    } else {
        (0.0, 1.0)
    };
    let mut svg = String::new();
    {
        let fail = |e: &dyn std::fmt::Display| Error::Input(format!("plot: {e}"));
        let root = SVGBackend::with_string(&mut svg, (640, 320)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(&e))?;
        let label = if log {
            format!("log10({name})")
        } else {
            name.to_string()
        };
        let mut chart = ChartBuilder::on(&root)
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(45)
            .build_cartesian_2d(a..b, 0.0..64.0)
            .map_err(|e| fail(&e))?;
        chart
            .configure_mesh()
            .x_desc(label)
            .y_desc("bits of error")
            .draw()
            .map_err(|e| fail(&e))?;
        chart
            .draw_series(
                points
                    .iter()
                    .map(|(x, bits)| Circle::new((map(x[i]), *bits), 2, BLUE.mix(0.5).filled())),
            )
            .map_err(|e| fail(&e))?;
        root.present().map_err(|e| fail(&e))?;
    }
    Ok(svg)
}

/// The HTML page of one regressed program: the text report, then one error-vs-input plot per
/// input.
///
/// # Errors
/// A plot cannot be drawn.
pub fn html(program: &Program, report_text: &str, points: &Points) -> Result<String, Error> {
    let esc = crate::plot::escape;
    let mut s = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head><meta charset=\"utf-8\"><title>regress {}</title>\n<style>body{{font-family:sans-serif;max-width:60rem;margin:auto}} pre{{background:#f6f6f6;padding:1em;overflow-x:auto}}</style></head>\n<body>\n<h1>regress <code>{}</code></h1>\n<pre>{}</pre>\n<h2>Error against each input</h2>\n<p>Bits of error (Herbie's measure) of {} compared samples (every sample whose index is a multiple of the stride that keeps at most {PLOT_POINTS}).</p>\n",
        esc(&program.name),
        esc(&program.name),
        esc(report_text),
        points.points.len()
    );
    for (i, name) in program.inputs.iter().enumerate() {
        let _ = writeln!(
            s,
            "<figure>\n{}\n<figcaption>bits of error against {}</figcaption>\n</figure>",
            plot(&points.points, i, name)?,
            esc(name)
        );
    }
    s.push_str("</body>\n</html>\n");
    Ok(s)
}
