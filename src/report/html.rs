//! The HTML page of the report, written as text: one self-contained document (inline style
//! sheet, one small inline script for the filters, the figures as inline SVG, a content
//! security policy that forbids every network load). Every text from a claim, a figure or a
//! regression is escaped ([`crate::plot::escape`]).
//!
//! The page works without JavaScript: every row is shown, and the filter controls stay hidden
//! (the script unhides them).

use super::inline_svg::isolate;
use super::meta::Meta;
use super::regress::{Summary, Table};
use crate::claims::{Checked, Equation, Verdict};
use crate::plot::{escape, Figure};
use crate::Error;
use exactcheck_exact::expr::{equation_to_mathml, Notation};
use std::fmt::Write as _;

/// Everything the page shows.
pub struct Page<'a> {
    /// What was checked (the built-in catalogue, or the claims file).
    pub subject: String,
    /// The header's facts.
    pub meta: &'a Meta,
    /// Every checked claim, in order.
    pub rows: &'a [Checked],
    /// The figures (the built-in catalogue's; none for a claims file).
    pub figures: &'a [Figure],
    /// The regression summaries.
    pub regressions: &'a [Summary],
    /// Why figures and regressions are absent, when they are (a claims file).
    pub note: Option<String>,
}

/// Whether a checked claim belongs in the errata: its check ran and found the printed
/// statement false.
pub fn is_erratum(row: &Checked) -> bool {
    matches!(&row.outcome, Ok(o) if o.verdict == Verdict::Fails)
}

/// The verdict's word, `error` when the check could not run.
fn verdict_word(row: &Checked) -> String {
    match &row.outcome {
        Ok(o) => o.verdict.to_string(),
        Err(_) => "error".into(),
    }
}

/// An HTML id made of letters, digits and `-` only (usable as a CSS `#id` selector as is).
pub fn css_id(prefix: &str, name: &str) -> String {
    let body: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
        .collect();
    format!("{prefix}-{body}")
}

/// The page.
///
/// # Errors
/// [`Error::Input`] when a figure cannot be inlined (see [`isolate`]).
pub fn page(p: &Page<'_>) -> Result<String, Error> {
    let mut s = String::with_capacity(1 << 20);
    let title = format!("exactcheck report: {}", p.subject);
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'; img-src data:\">\n\
         <title>{}</title>\n<style>{CSS}</style>\n</head>\n<body>\n",
        escape(&title)
    );
    header(&mut s, p);
    s.push_str("<main>\n");
    verdict_table(&mut s, p.rows);
    errata(&mut s, p.rows);
    figures(&mut s, p.figures, p.note.as_deref())?;
    regressions(&mut s, p.regressions, p.note.as_deref());
    s.push_str("</main>\n");
    let _ = write!(
        s,
        "<footer>Written by exactcheck {} — every verdict is the result of an exact computation; see the evidence of each claim.</footer>\n<script>{SCRIPT}</script>\n</body>\n</html>\n",
        escape(&p.meta.version)
    );
    Ok(s)
}

fn header(s: &mut String, p: &Page<'_>) {
    let m = p.meta;
    let _ = write!(
        s,
        "<header>\n<h1>exactcheck report</h1>\n<p class=\"subject\">{}</p>\n<dl class=\"meta\">\n",
        escape(&p.subject)
    );
    let commit = m
        .commit
        .clone()
        .unwrap_or_else(|| "not built from a git checkout".into());
    for (k, v, code) in [
        ("command", m.command.as_str(), true),
        ("date", m.date.as_str(), false),
        ("exactcheck", m.version.as_str(), false),
        ("git commit", commit.as_str(), true),
        ("rustc", m.rustc.as_str(), false),
        ("num-bigint", m.num_bigint.as_str(), false),
        ("num-rational", m.num_rational.as_str(), false),
        ("machine", m.machine.as_str(), false),
    ] {
        let v = escape(v);
        let v = if code { format!("<code>{v}</code>") } else { v };
        let _ = writeln!(s, "<dt>{k}</dt><dd>{v}</dd>");
    }
    s.push_str("</dl>\n");
    let total = p.rows.len();
    let ok = p.rows.iter().filter(|r| r.as_expected()).count();
    let mut counts = Vec::new();
    for v in ["proved", "holds", "fails", "undecided", "error"] {
        let n = p.rows.iter().filter(|r| verdict_word(r) == v).count();
        if n > 0 {
            counts.push(format!("<span class=\"v v-{v}\">{n} {v}</span>"));
        }
    }
    let errata = p.rows.iter().filter(|r| is_erratum(r)).count();
    let _ = write!(
        s,
        "<p class=\"totals\">{total} claims: {}; {ok} of {total} as expected; {errata} errata.</p>\n\
         <nav><a href=\"#claims\">verdicts</a> · <a href=\"#errata\">errata</a> · <a href=\"#figures\">figures</a> · <a href=\"#regressions\">float against exact</a></nav>\n</header>\n",
        counts.join(" ")
    );
}

fn verdict_table(s: &mut String, rows: &[Checked]) {
    let mut sources: Vec<&str> = Vec::new();
    for r in rows {
        if !sources.contains(&r.source.as_str()) {
            sources.push(&r.source);
        }
    }
    s.push_str("<section id=\"claims\">\n<h2>Verdicts</h2>\n");
    s.push_str("<div id=\"filters\" hidden>\n<label>source <select id=\"filter-source\">\n<option value=\"\">all</option>\n");
    for src in &sources {
        let n = rows.iter().filter(|r| r.source == *src).count();
        let _ = writeln!(s, "<option value=\"{0}\">{0} ({n})</option>", escape(src));
    }
    s.push_str("</select></label>\n<label>verdict <select id=\"filter-verdict\">\n<option value=\"\">all</option>\n");
    for v in ["proved", "holds", "fails", "undecided", "error"] {
        let _ = writeln!(s, "<option value=\"{v}\">{v}</option>");
    }
    s.push_str("</select></label>\n<span id=\"filter-count\"></span>\n</div>\n");
    s.push_str(
        "<table id=\"verdicts\">\n<thead><tr><th>id</th><th>source</th><th>verdict</th><th>expected</th><th>as expected</th><th>method</th><th>evidence</th><th>seconds</th></tr></thead>\n<tbody>\n",
    );
    for r in rows {
        let verdict = verdict_word(r);
        let (method, evidence) = match &r.outcome {
            Ok(o) => (o.method.as_str(), o.evidence.as_str()),
            Err(e) => ("", e.as_str()),
        };
        let mark = if r.as_expected() {
            "<td class=\"ok\">✓</td>"
        } else {
            "<td class=\"bad\">✗</td>"
        };
        let id_cell = if is_erratum(r) {
            format!(
                "<a href=\"#{}\"><code>{}</code></a>",
                escape(&css_id("erratum", &r.id)),
                escape(&r.id)
            )
        } else {
            format!("<code>{}</code>", escape(&r.id))
        };
        let _ = writeln!(
            s,
            "<tr id=\"{}\" data-source=\"{}\" data-verdict=\"{verdict}\"><td>{id_cell}</td><td>{}</td><td class=\"v v-{verdict}\">{verdict}</td><td>{}</td>{mark}<td>{}</td><td>{}</td><td class=\"num\">{:.3}</td></tr>",
            escape(&css_id("claim", &r.id)),
            escape(&r.source),
            escape(&r.source),
            r.expected,
            escape(method),
            long_text(evidence),
            r.seconds
        );
    }
    s.push_str("</tbody>\n</table>\n</section>\n");
}

/// Short one-line text as is; longer text collapsed under its first line.
fn long_text(text: &str) -> String {
    let first = text.lines().next().unwrap_or("");
    if text.len() <= 160 && !text.contains('\n') {
        return escape(text);
    }
    let summary: String = if first.chars().count() > 120 {
        first.chars().take(120).collect::<String>() + "…"
    } else {
        first.to_string()
    };
    format!(
        "<details><summary>{}</summary><pre>{}</pre></details>",
        escape(&summary),
        escape(text)
    )
}

/// `lhs = rhs` of an erratum's equation: MathML (rendered by the browser, no script or font),
/// then the LaTeX to paste into an erratum, both printed from the expression trees.
fn equation(e: &Equation, notation: &Notation) -> String {
    format!(
        "{}<code class=\"tex\" title=\"LaTeX\">{}</code>",
        equation_to_mathml(&e.lhs, &e.rhs, notation),
        escape(&e.latex(notation))
    )
}

fn equations(s: &mut String, label: &str, eqs: &[Equation], notation: &Notation) {
    if eqs.is_empty() {
        return;
    }
    let _ = write!(s, "<dt>{label}</dt><dd><ul class=\"eqs\">");
    for e in eqs {
        let _ = write!(s, "<li>{}</li>", equation(e, notation));
    }
    s.push_str("</ul></dd>\n");
}

fn errata(s: &mut String, rows: &[Checked]) {
    let failing: Vec<&Checked> = rows.iter().filter(|r| is_erratum(r)).collect();
    // Counted, not assumed: a failing claim without a structured counter-example (e.g. a
    // `solve` claim of a file whose field differs) is shown with its evidence.
    let with_point = failing
        .iter()
        .filter(|r| {
            matches!(&r.outcome, Ok(o) if o.erratum.as_ref().is_some_and(|e| !e.counter_example.is_empty()))
        })
        .count();
    let _ = write!(
        s,
        "<section id=\"errata\">\n<h2>Errata</h2>\n<p>{} printed statement{} found false, {} of them with an exact counter-example below.</p>\n",
        failing.len(),
        if failing.len() == 1 { "" } else { "s" },
        with_point
    );
    for r in failing {
        let Ok(o) = &r.outcome else {
            unreachable!("is_erratum keeps only claims whose check ran")
        };
        let _ = write!(
            s,
            "<article class=\"erratum\" id=\"{}\" data-claim=\"{}\">\n<h3><a href=\"#{}\"><code>{}</code></a> <span class=\"v v-fails\">fails</span></h3>\n<p class=\"statement\"><span class=\"label\">as printed:</span> {}</p>\n",
            escape(&css_id("erratum", &r.id)),
            escape(&r.id),
            escape(&css_id("claim", &r.id)),
            escape(&r.id),
            escape(&r.statement)
        );
        match &o.erratum {
            Some(e) => {
                let notation = e.notation();
                s.push_str("<dl class=\"erratum-forms\">\n");
                equations(s, "printed form", &e.printed, &notation);
                equations(s, "correct form", &e.corrected, &notation);
                if !e.correction.is_empty() {
                    let _ = writeln!(
                        s,
                        "<dt>correct statement</dt><dd>{}</dd>",
                        escape(&e.correction)
                    );
                }
                equations(s, "counter-example", &e.counter_example, &notation);
                equations(s, "residual there", &e.residual, &notation);
                s.push_str("</dl>\n");
                let _ = writeln!(
                    s,
                    "<details><summary>evidence ({})</summary><pre>{}</pre></details>",
                    escape(&o.method),
                    escape(&o.evidence)
                );
            }
            None => {
                let _ = writeln!(
                    s,
                    "<p class=\"evidence\"><span class=\"label\">evidence ({}):</span></p><pre>{}</pre>",
                    escape(&o.method),
                    escape(&o.evidence)
                );
            }
        }
        s.push_str("</article>\n");
    }
    s.push_str("</section>\n");
}

fn figures(s: &mut String, figs: &[Figure], note: Option<&str>) -> Result<(), Error> {
    s.push_str("<section id=\"figures\">\n<h2>Figures</h2>\n");
    if figs.is_empty() {
        let _ = writeln!(s, "<p>{}</p>", escape(note.unwrap_or("No figures.")));
    }
    let mut used: Vec<String> = Vec::new();
    for (i, f) in figs.iter().enumerate() {
        let mut id = css_id("fig", &f.id);
        if used.contains(&id) {
            id = format!("{id}-{i}");
        }
        used.push(id.clone());
        let svg = isolate(&f.svg, &id, &id)?;
        let _ = write!(
            s,
            "<figure id=\"{id}\" data-source=\"{}\" data-figure=\"{}\">\n<div class=\"svg\">{svg}</div>\n<figcaption><code>{}</code> {}</figcaption>\n</figure>\n",
            escape(f.source),
            escape(&f.id),
            escape(&f.id),
            escape(&f.title)
        );
    }
    s.push_str("</section>\n");
    Ok(())
}

fn table(s: &mut String, t: &Table) {
    let _ = write!(
        s,
        "<table class=\"regress\">\n<caption>{}</caption>\n<thead><tr>",
        escape(&t.caption)
    );
    for h in &t.head {
        let _ = write!(s, "<th>{}</th>", escape(h));
    }
    s.push_str("</tr></thead>\n<tbody>\n");
    for row in &t.rows {
        s.push_str("<tr>");
        for c in row {
            let _ = write!(s, "<td>{}</td>", escape(c));
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody>\n</table>\n");
}

fn regressions(s: &mut String, summaries: &[Summary], note: Option<&str>) {
    s.push_str("<section id=\"regressions\">\n<h2>Float against exact</h2>\n");
    if summaries.is_empty() {
        let _ = writeln!(
            s,
            "<p>{}</p>",
            escape(note.unwrap_or("No regressions were run."))
        );
    } else {
        s.push_str("<p>The built-in kernels of <code>exactcheck regress</code> (and the saved runs given with <code>--regress</code>), run in f64 and exactly on the same seeded inputs. Errors in ulps of the exact value; bits of error as Herbie measures them (log2 of 1 + the doubles between the f64 result and the correctly rounded exact value).</p>\n");
        if summaries
            .iter()
            .any(|r| r.command.starts_with("exactcheck regress "))
        {
            let _ = writeln!(s, "<p>{}</p>", escape(super::regress::KERNEL_NOT_EXPLAINED));
        }
    }
    for r in summaries {
        let _ = write!(
            s,
            "<article class=\"regression\" id=\"{}\">\n<h3>{}</h3>\n<p>{} — <code>{}</code> ({:.1} s)</p>\n",
            escape(&css_id("regress", &r.kernel)),
            escape(&r.kernel),
            escape(&r.title),
            escape(&r.command),
            r.seconds
        );
        for t in &r.tables {
            table(s, t);
        }
        s.push_str("</article>\n");
    }
    s.push_str("</section>\n");
}

/// The page's style sheet: the system font stack, no web font.
const CSS: &str = r#"
:root{--fg:#1d232a;--muted:#5b6570;--line:#d8dde3;--bg:#fff;--head:#f3f5f7}
*{box-sizing:border-box}
body{margin:0;font:15px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,"Helvetica Neue",Arial,"Noto Sans",sans-serif;color:var(--fg);background:var(--bg)}
header,main,footer{max-width:1400px;margin:0 auto;padding:0 24px}
header{padding-top:16px;border-bottom:1px solid var(--line)}
h1{margin:0 0 4px;font-size:26px}
h2{margin:28px 0 10px;font-size:21px;border-bottom:2px solid var(--line);padding-bottom:4px}
h3{margin:18px 0 6px;font-size:17px}
code,pre{font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,"DejaVu Sans Mono",monospace;font-size:13px}
pre{white-space:pre-wrap;word-break:break-word;background:var(--head);padding:6px 8px;margin:4px 0}
.subject{font-size:17px;margin:0 0 8px}
dl.meta{display:grid;grid-template-columns:max-content 1fr;gap:2px 14px;margin:0 0 8px;font-size:13.5px}
dl.meta dt{color:var(--muted)}
dl.meta dd{margin:0}
.totals{font-weight:600}
nav{margin:0 0 12px}
nav a{color:#0b5cad}
table{border-collapse:collapse;width:100%;font-size:13.5px;margin:6px 0 14px}
th,td{border:1px solid var(--line);padding:3px 6px;text-align:left;vertical-align:top}
thead th{background:var(--head);position:sticky;top:0}
caption{caption-side:top;text-align:left;color:var(--muted);padding:2px 0 4px}
td.num{text-align:right;font-variant-numeric:tabular-nums}
td details summary{cursor:pointer}
.v{font-weight:600;white-space:nowrap}
td.v,span.v{border-radius:3px}
span.v{padding:0 5px}
.v-proved{background:#d7f2dc;color:#11552a}
.v-holds{background:#dcecfb;color:#0d3f73}
.v-fails{background:#fbdada;color:#8a1111}
.v-undecided{background:#fdf0c6;color:#6b4d00}
.v-error{background:#e6dcf5;color:#4b2380}
td.ok{color:#11552a;text-align:center}
td.bad{color:#8a1111;text-align:center;font-weight:700}
#filters{margin:4px 0 8px;display:flex;gap:18px;align-items:center}
#filters[hidden]{display:none}
#filter-count{color:var(--muted)}
tr[hidden]{display:none}
article.erratum{border:1px solid var(--line);border-left:4px solid #c62828;padding:4px 14px 10px;margin:12px 0}
.erratum .statement{margin:4px 0}
.label{color:var(--muted)}
dl.erratum-forms{display:grid;grid-template-columns:max-content 1fr;gap:4px 14px;margin:6px 0}
dl.erratum-forms dt{color:var(--muted)}
dl.erratum-forms dd{margin:0}
ul.eqs{margin:0;padding:0;list-style:none}
ul.eqs li{margin:4px 0}
ul.eqs math{display:block;text-align:left;margin:2px 0;font-size:1.1em}
code.tex{display:block;color:#555;font-size:.85em;white-space:pre-wrap;overflow-wrap:anywhere}
figure{margin:16px 0;border:1px solid var(--line);padding:8px}
figure .svg svg{max-width:100%;height:auto;display:block;margin:0 auto}
figcaption{color:var(--muted);margin-top:6px}
footer{color:var(--muted);font-size:13px;padding:24px;border-top:1px solid var(--line);margin-top:24px}
@media print{#filters{display:none}thead th{position:static}}
"#;

/// The filters: source and verdict `<select>`s hide the rows that do not match.
const SCRIPT: &str = r#"
(function () {
  var table = document.getElementById('verdicts');
  var source = document.getElementById('filter-source');
  var verdict = document.getElementById('filter-verdict');
  var count = document.getElementById('filter-count');
  var rows = table.tBodies[0].rows;
  function apply() {
    var shown = 0;
    for (var i = 0; i < rows.length; i++) {
      var r = rows[i];
      var keep = (!source.value || r.getAttribute('data-source') === source.value) &&
                 (!verdict.value || r.getAttribute('data-verdict') === verdict.value);
      r.hidden = !keep;
      if (keep) shown++;
    }
    count.textContent = shown + ' of ' + rows.length + ' claims shown';
  }
  source.addEventListener('change', apply);
  verdict.addEventListener('change', apply);
  document.getElementById('filters').hidden = false;
  apply();
})();
"#;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::{Erratum, Outcome};
    use exactcheck_exact::expr::parse_expr;

    fn meta() -> Meta {
        Meta {
            command: "exactcheck report -o out".into(),
            date: "2026-01-02 03:04:05 UTC".into(),
            version: "0.1.0".into(),
            commit: None,
            rustc: "rustc 1.95.0".into(),
            num_bigint: "0.4.6".into(),
            num_rational: "0.4.2".into(),
            machine: "2 logical cores, linux x86_64".into(),
        }
    }

    fn row(id: &str, verdict: Verdict, erratum: Option<Erratum>) -> Checked {
        Checked {
            id: id.into(),
            source: id.split('.').next().unwrap().into(),
            statement: format!("statement of {id} <with markup & quotes\">"),
            expected: verdict,
            outcome: Ok(Outcome {
                verdict,
                method: "m".into(),
                evidence: "line one\nline two".into(),
                erratum: erratum.map(Box::new),
            }),
            seconds: 0.5,
            problem: None,
            bad_input: false,
            report: Default::default(),
        }
    }

    #[test]
    fn rows_errata_and_escaping() {
        let eq = |l: &str, r: &str| Equation {
            lhs: parse_expr(l).unwrap(),
            rhs: parse_expr(r).unwrap(),
        };
        let erratum = Erratum {
            printed: vec![eq("y", "x^2 + 1")],
            corrected: vec![eq("y", "x^2 - 1")],
            counter_example: vec![eq("x", "3")],
            residual: vec![eq("r", "2")],
            ..Erratum::default()
        };
        let rows = vec![
            row("a.one", Verdict::Proved, None),
            row("a.two", Verdict::Fails, Some(erratum)),
            row("b.three", Verdict::Fails, None),
            Checked {
                outcome: Err("could not run".into()),
                ..row("b.four", Verdict::Holds, None)
            },
        ];
        let m = meta();
        let html = page(&Page {
            subject: "test".into(),
            meta: &m,
            rows: &rows,
            figures: &[],
            regressions: &[],
            note: Some("none here".into()),
        })
        .unwrap();
        assert_eq!(html.matches("<tr id=\"claim-").count(), 4);
        assert!(html.contains("data-source=\"b\" data-verdict=\"error\""));
        // Both failing claims are errata, the one without an erratum with its evidence.
        assert_eq!(html.matches("<article class=\"erratum\"").count(), 2);
        assert!(html.contains("id=\"erratum-b-three\""));
        // The erratum's equation as MathML (from the tree) with its LaTeX under it.
        assert!(
            html.contains("<math display=\"block\"><mrow><mi>y</mi><mo>=</mo>"),
            "{html}"
        );
        assert!(
            html.contains("<code class=\"tex\" title=\"LaTeX\">y = x^{2} - 1</code>"),
            "{html}"
        );
        assert!(html.contains("&lt;with markup &amp; quotes&quot;&gt;"));
        assert!(!html.contains("<with markup"));
        assert!(html.contains("<details><summary>line one</summary>"));
        assert!(html.contains("3 of 4 as expected; 2 errata."), "{html}");
    }

    #[test]
    fn ids_are_css_safe() {
        assert_eq!(
            css_id("fig", "spaeth.example1.tu"),
            "fig-spaeth-example1-tu"
        );
    }
}
