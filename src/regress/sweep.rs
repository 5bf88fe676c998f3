//! What every harness sweep of `regress` shares: the progress bar, the JSON document of a run
//! (one entry per formula or FPCore benchmark, each a full harness report or the reason it was
//! not run), the text output with its summary table, and `exactcheck merge`.
//!
//! # The JSON document
//! ```text
//! { "exactcheck": "regress", "version": "0.1.0",
//!   "entries": [ { "name": ..., "line": 3 | null, <every field of the harness Report> },
//!                { "name": ..., "line": 9, "not_supported": "sin" }, ... ] }
//! ```
//! A shard's document has the same shape (each report carries `"shard": "I/N"`); `merge`
//! reads the documents of all shards and merges entry by entry ([`exactcheck_float::merge`]).

use crate::Error;
use exactcheck_float::Report;
use serde_json::{json, Value};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// One formula or benchmark of a run: its report, or why it was not run.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// The name (FPCore `:name`, or the formula text).
    pub name: String,
    /// The line of an FPCore benchmark in its file.
    pub line: Option<usize>,
    /// The report, or the reason it was not run (`not supported: OP`).
    pub outcome: Result<Report, String>,
    /// The error binned by `--bin`, when asked.
    pub bins: Option<super::explain::Bins>,
    /// The sign errors of `--predicate`, when asked.
    pub predicate: Option<super::predicate::Predicate>,
}

impl Entry {
    /// The entry as JSON: the report's fields plus `name` and `line`, or `not_supported`.
    pub fn to_json(&self) -> Value {
        let mut v = match &self.outcome {
            Ok(r) => r.to_json(),
            Err(why) => json!({ "not_supported": why }),
        };
        let obj = v.as_object_mut().expect("a report is a JSON object");
        obj.insert("name".into(), json!(self.name));
        obj.insert("line".into(), json!(self.line));
        if let Some(b) = &self.bins {
            obj.insert("bins".into(), b.to_json());
        }
        if let Some(p) = &self.predicate {
            obj.insert("predicate".into(), p.to_json());
        }
        // `name` and `line` first, for readers.
        let mut ordered = serde_json::Map::new();
        for key in ["name", "line"] {
            if let Some(x) = obj.remove(key) {
                ordered.insert(key.into(), x);
            }
        }
        ordered.append(obj);
        Value::Object(ordered)
    }

    /// Reads an entry back.
    fn from_json(mut v: Value, what: &str) -> Result<Entry, String> {
        let obj = v
            .as_object_mut()
            .ok_or_else(|| format!("{what} is not a JSON object"))?;
        let name = match obj.remove("name") {
            Some(Value::String(s)) => s,
            _ => return Err(format!("{what} has no \"name\" string")),
        };
        let line = match obj.remove("line") {
            None | Some(Value::Null) => None,
            Some(l) => Some(
                l.as_u64()
                    .and_then(|l| usize::try_from(l).ok())
                    .ok_or_else(|| format!("{what}: \"line\" is not a line number"))?,
            ),
        };
        let outcome = match obj.remove("not_supported") {
            Some(Value::String(why)) => Err(why),
            Some(_) => return Err(format!("{what}: \"not_supported\" is not a string")),
            None => Ok(serde_json::from_value::<Report>(v)
                .map_err(|e| format!("{what} is not a regress report: {e}"))?),
        };
        Ok(Entry {
            name,
            line,
            outcome,
            bins: None,
            predicate: None,
        })
    }
}

/// The JSON document of a run.
pub fn document(entries: &[Entry]) -> Value {
    json!({
        "exactcheck": "regress",
        "version": env!("CARGO_PKG_VERSION"),
        "entries": entries.iter().map(Entry::to_json).collect::<Vec<_>>(),
    })
}

/// Reads a document written by [`document`] (`what` names it in errors).
pub fn read_document(text: &str, what: &str) -> Result<Vec<Entry>, Error> {
    let v: Value = crate::solve::depth::parse_json(text)
        .map_err(|(pos, mut e)| {
            e.actual = format!("{what}: {} at byte {pos}", e.actual);
            Error::Limit(e)
        })?
        .map_err(|e| Error::Input(format!("{what}: not JSON: {e}")))?;
    if v.get("exactcheck") != Some(&json!("regress")) {
        return Err(Error::Input(format!(
            "{what} is not a regress report (no \"exactcheck\": \"regress\"; write shards with regress --shard I/N)"
        )));
    }
    let Some(Value::Array(entries)) = v.get("entries") else {
        return Err(Error::Input(format!("{what} has no \"entries\" list")));
    };
    entries
        .iter()
        .enumerate()
        .map(|(k, e)| Entry::from_json(e.clone(), &format!("{what}, entry {}", k + 1)))
        .collect::<Result<_, String>>()
        .map_err(Error::Input)
}

/// Shortest round-trip text of a double.
fn num(x: f64) -> String {
    format!("{x:?}")
}

/// The summary table of several entries: name, samples, max and median ulps, Herbie's bits of
/// error, the worst input.
pub fn table(entries: &[Entry]) -> String {
    let mut rows = vec![[
        "name".to_string(),
        "samples".into(),
        "compared".into(),
        "max ulps".into(),
        "median ulps".into(),
        "bits (mean)".into(),
        "worst input".into(),
    ]];
    for e in entries {
        match &e.outcome {
            Ok(r) if r.compared == 0 => rows.push([
                e.name.clone(),
                (r.end_sample - r.first_sample).to_string(),
                "0".into(),
                "-".into(),
                "-".into(),
                "-".into(),
                "no sample compared".into(),
            ]),
            Ok(r) => rows.push([
                // A precision other than binary64 is named with the entry: its ulps and bits
                // are that format's.
                if r.precision == "binary64" {
                    e.name.clone()
                } else {
                    format!("{} [{}]", e.name, r.precision)
                },
                (r.end_sample - r.first_sample).to_string(),
                r.compared.to_string(),
                super::planes::cell(r.max_ulps),
                super::planes::cell(r.median_ulps),
                format!("{:.2}", r.bits_of_error),
                r.worst.first().map_or("-".into(), |w| {
                    let c = w.shrunk.as_ref().unwrap_or(&w.original);
                    format!(
                        "[{}]",
                        c.inputs
                            .iter()
                            .map(|&x| num(x))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                }),
            ]),
            Err(why) => rows.push([
                e.name.clone(),
                "-".into(),
                "-".into(),
                "-".into(),
                "-".into(),
                "-".into(),
                why.clone(),
            ]),
        }
    }
    let widths: Vec<usize> = (0..7)
        .map(|c| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(0))
        .collect();
    let mut out = String::new();
    for (k, r) in rows.iter().enumerate() {
        let cells: Vec<String> = r
            .iter()
            .zip(&widths)
            .enumerate()
            .map(|(c, (s, &w))| {
                if c == 0 || c == 6 {
                    format!("{s:<w$}")
                } else {
                    format!("{s:>w$}")
                }
            })
            .collect();
        out.push_str(cells.join("  ").trim_end());
        out.push('\n');
        if k == 0 {
            let rule: Vec<String> = widths.iter().map(|&w| "-".repeat(w)).collect();
            out.push_str(&rule.join("  "));
            out.push('\n');
        }
    }
    out
}

/// Prints the entries: the JSON document, or each report (one) / the table then each report,
/// in one write.
pub fn print(entries: &[Entry], as_json: bool) -> Result<(), Error> {
    if as_json {
        return crate::output::println(format_args!("{:#}", document(entries)));
    }
    let mut text = crate::output::Text::new();
    if entries.len() > 1 {
        text.line(table(entries));
    }
    for e in entries {
        match &e.outcome {
            Ok(r) => {
                text.line(r);
                if let Some(b) = &e.bins {
                    text.line(b.text());
                }
                if let Some(p) = &e.predicate {
                    text.line(p.text());
                }
            }
            Err(why) => text.line(format_args!("{}: {why}\n", e.name)),
        }
    }
    text.print()
}

/// A progress bar on standard error for a sweep: drawn only when standard error is a terminal,
/// not `--quiet`, and the sweep has run for more than a second.
pub struct Progress {
    bar: Option<indicatif::ProgressBar>,
    started: Instant,
    total: usize,
    label: String,
}

impl Progress {
    /// A bar for `total` samples of `label`; `quiet` (or a non-terminal stderr) hides it.
    pub fn new(total: usize, label: &str, quiet: bool) -> Progress {
        let visible = !quiet && std::io::stderr().is_terminal();
        Progress {
            bar: visible.then(|| {
                indicatif::ProgressBar::with_draw_target(
                    Some(total as u64),
                    indicatif::ProgressDrawTarget::hidden(),
                )
            }),
            started: Instant::now(),
            total,
            label: label.chars().take(40).collect(),
        }
    }

    /// Samples done so far.
    pub fn update(&self, done: usize) {
        let Some(bar) = &self.bar else { return };
        if bar.is_hidden() && self.started.elapsed() > Duration::from_secs(1) && done < self.total {
            bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{msg} [{bar:30}] {pos}/{len} samples, {per_sec}, eta {eta}",
            ) {
                bar.set_style(style.progress_chars("=> "));
            }
            bar.set_message(self.label.clone());
        }
        bar.set_position(done as u64);
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

/// Arguments of `exactcheck merge`.
#[derive(Debug, clap::Args)]
pub struct MergeArgs {
    /// The shard reports (`regress ... --shard I/N` writes one each), in any order.
    #[arg(required = true, value_name = "SHARD")]
    pub files: Vec<String>,
    /// Print the merged report as JSON (the document a single run prints with --json).
    #[arg(long)]
    pub json: bool,
}

/// Runs `exactcheck merge`.
///
/// # Errors
/// A file that cannot be read or is not a shard report, shards of different sweeps, a shard
/// missing or given twice: one line naming the file or shard.
pub fn merge_cmd(args: &MergeArgs) -> Result<std::process::ExitCode, Error> {
    let mut docs = Vec::new();
    for path in &args.files {
        let text = crate::solve::read_problem(Some(path))?;
        docs.push(read_document(&text, path)?);
    }
    let first = &docs[0];
    for (doc, path) in docs.iter().zip(&args.files) {
        if doc.len() != first.len() {
            return Err(Error::Input(format!(
                "{path} has {} entries, {} has {}",
                doc.len(),
                args.files[0],
                first.len()
            )));
        }
    }
    let mut merged = Vec::new();
    for (k, entry) in first.iter().enumerate() {
        let mut reports = Vec::new();
        for (doc, path) in docs.iter().zip(&args.files) {
            let e = &doc[k];
            if e.name != entry.name || e.line != entry.line {
                return Err(Error::Input(format!(
                    "{path}: entry {} is '{}', in {} it is '{}'",
                    k + 1,
                    e.name,
                    args.files[0],
                    entry.name
                )));
            }
            if let Ok(r) = &e.outcome {
                reports.push(r.clone());
            }
        }
        let outcome = match &entry.outcome {
            Err(why) => Err(why.clone()),
            Ok(_) => {
                if reports.len() != docs.len() {
                    return Err(Error::Input(format!(
                        "entry '{}' is run in some shards and not supported in others",
                        entry.name
                    )));
                }
                Ok(exactcheck_float::merge(&reports)
                    .map_err(|e| Error::Input(format!("'{}': {e}", entry.name)))?)
            }
        };
        merged.push(Entry {
            name: entry.name.clone(),
            line: entry.line,
            outcome,
            bins: None,
            predicate: None,
        });
    }
    print(&merged, args.json)?;
    Ok(exit_code(&merged))
}

/// The exit status of a finished sweep: 1 when an entry compared no sample (a precondition never
/// true, a domain the exact side refuses: nothing was measured, as an undecided verdict), else 0.
pub fn exit_code(entries: &[Entry]) -> std::process::ExitCode {
    if entries
        .iter()
        .any(|e| matches!(&e.outcome, Ok(r) if r.compared == 0))
    {
        std::process::ExitCode::from(1)
    } else {
        std::process::ExitCode::SUCCESS
    }
}
