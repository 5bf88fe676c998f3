//! The furniture both figures share: the style sheet, the title block, the legend and its
//! symbols.

use super::scene::Scene;
use super::svg::{Points, Svg, N};

pub(super) const STYLE: &str = "
.title{font-size:20px;font-weight:bold;fill:#222}
.sub{font-size:12.5px;fill:#444}
.tick{font-size:12px;fill:#333}
.axlabel{font-size:14px;fill:#222}
.legend{font-size:12.5px;fill:#222}
.mark{font-size:10.5px;fill:#333}
.frame{fill:none;stroke:#444;stroke-width:1}
.grid{stroke:#e4e4e4;stroke-width:1}
.taxis{stroke:#777;stroke-width:1.2}
.real{fill:#eef6e8}
.curve{fill:none;stroke-linejoin:round;stroke-linecap:round}
.u1{stroke:#1f5fbf;stroke-width:2.4}
.u2{stroke:#e0620d;stroke-width:2.4}
.hidden{stroke-width:1.8;stroke-opacity:0.7;stroke-dasharray:5 4}
.dot{fill:#222;stroke:#fff;stroke-width:0.8}
.hollow{fill:#fff;stroke:#222;stroke-width:1.2}
.end{stroke:#111;stroke-width:2}
.guide{stroke:#999;stroke-width:0.8;stroke-dasharray:2 3}
.tangent{fill:#8e24aa;stroke:#fff;stroke-width:0.8}
.cyl{fill:none;stroke:#8a8a8a;stroke-width:0.9}
.cyl-back{fill:none;stroke:#c4c4c4;stroke-width:0.8;stroke-dasharray:4 3}
.cyl-sil{fill:none;stroke:#555;stroke-width:1.5}
.sph{fill:none;stroke:#5b93c9;stroke-width:0.8}
.sph-back{fill:none;stroke:#a9c8e6;stroke-width:0.7;stroke-dasharray:3 3}
.sph-disc{fill:#d3e5f6;fill-opacity:0.5;stroke:#2f6da3;stroke-width:1.5}
.axis3{stroke:#333;stroke-width:1.3}
";

/// The title, subtitle lines and style of a figure; returns the y below them.
pub(super) fn header(svg: &mut Svg, title: &str, lines: &[String]) -> f64 {
    svg.open("style", &[]);
    svg.buf.push_str(STYLE);
    svg.close();
    svg.leaf(
        "rect",
        &[("width", &"100%"), ("height", &"100%"), ("fill", &"#fff")],
    );
    svg.text(24.0, 34.0, title, &[("class", &"title")]);
    let mut y = 34.0;
    for l in lines {
        y += 18.0;
        svg.text(24.0, y, l, &[("class", &"sub")]);
    }
    y + 14.0
}

pub(super) fn subtitle_lines(scene: &Scene, extra: &str, what: [&str; 2]) -> Vec<String> {
    let mut lines = vec![format!("{}{extra}", scene.config)];
    let parts: Vec<String> = [(what[0], &scene.note_float), (what[1], &scene.note_exact)]
        .iter()
        .filter_map(|(w, n)| n.as_ref().map(|n| format!("{w}: {n}")))
        .collect();
    if !parts.is_empty() {
        lines.push(parts.join("; "));
    }
    lines.push(match &scene.exact {
        Ok(e) => e.summary.clone(),
        Err(why) => why.clone(),
    });
    lines
}

/// A legend symbol.
#[derive(Clone, Copy)]
pub(super) enum Sym {
    /// A short line of the class.
    Line(&'static str),
    /// A dot (circle) of the class.
    Dot(&'static str),
    /// The exact interval end.
    Tick,
    /// The touching point.
    Diamond,
    /// The shading of the real t-range.
    Band,
    /// The sphere.
    Disc,
}

/// A legend box at `(x, y)` with one row per entry, and notes below it.
pub(super) fn legend(svg: &mut Svg, x: f64, y: f64, rows: &[(String, Sym)], notes: &[String]) {
    svg.leaf(
        "rect",
        &[
            ("x", &N(x - 10.0)),
            ("y", &N(y - 8.0)),
            ("width", &N(220.0)),
            ("height", &N(rows.len() as f64 * 24.0 + 34.0)),
            ("fill", &"#fafafa"),
            ("stroke", &"#bbb"),
            ("rx", &4),
        ],
    );
    svg.text(
        x,
        y + 10.0,
        "Legend",
        &[("class", &"legend"), ("font-weight", &"bold")],
    );
    let mut ry = y + 34.0;
    for (label, sym) in rows {
        let sx = x + 14.0;
        match *sym {
            Sym::Line(class) => svg.line((sx - 12.0, ry), (sx + 12.0, ry), &[("class", &class)]),
            Sym::Dot(class) => circle(svg, sx, ry, 3.4, class),
            Sym::Tick => svg.line((sx, ry - 8.0), (sx, ry + 8.0), &[("class", &"end")]),
            Sym::Diamond => diamond(svg, sx, ry, 6.0, "tangent"),
            Sym::Band => svg.leaf(
                "rect",
                &[
                    ("class", &"real"),
                    ("x", &N(sx - 12.0)),
                    ("y", &N(ry - 7.0)),
                    ("width", &24),
                    ("height", &14),
                    ("stroke", &"#cde3bd"),
                ],
            ),
            Sym::Disc => circle(svg, sx, ry, 8.0, "sph-disc"),
        }
        svg.text(x + 36.0, ry + 4.5, label, &[("class", &"legend")]);
        ry += 24.0;
    }
    for (i, l) in notes.iter().enumerate() {
        svg.text(
            x - 10.0,
            ry + 14.0 + 16.0 * i as f64,
            l,
            &[("class", &"mark")],
        );
    }
}

pub(super) fn diamond(svg: &mut Svg, x: f64, y: f64, r: f64, class: &str) {
    let pts = [(x, y - r), (x + r, y), (x, y + r), (x - r, y)];
    svg.leaf("polygon", &[("class", &class), ("points", &Points(&pts))]);
}

pub(super) fn circle(svg: &mut Svg, x: f64, y: f64, r: f64, class: &str) {
    svg.leaf(
        "circle",
        &[
            ("class", &class),
            ("cx", &N(x)),
            ("cy", &N(y)),
            ("r", &N(r)),
        ],
    );
}
