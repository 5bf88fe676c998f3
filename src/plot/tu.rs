//! The t-u diagram (the paper's Fig. 2 and 3): the branches over `t` in degrees, the paper's
//! 10-degree samples, and the exact ends of the real t-intervals and touching points.

use super::*;

/// Dense samples of the curves in the t-u diagram.
const TU_SAMPLES: usize = 2000;

/// The t-u diagram (the paper's Fig. 2 / 3).
pub(super) fn tu_diagram(scene: &Scene) -> String {
    let (width, height) = (980.0, 600.0);
    let title = format!(
        "{}: t-u diagram{}",
        scene.name,
        scene
            .figure
            .map(|f| format!(" (the paper's {f})"))
            .unwrap_or_default()
    );
    let mut svg = Svg::new(width, height, &title);
    let top = header(
        &mut svg,
        &title,
        &subtitle_lines(scene, "", ["curves and dots", "exact markers"]),
    ) + 18.0;
    let (x0, w) = (80.0, 640.0);
    let (y0, h) = (top, height - top - 70.0);
    let sampler = DiscSampler::new(&scene.float);
    let curves = runs(&sampler, TU_SAMPLES);
    // u-range: the sphere's extent along the axis (every curve point lies in it) and u = 0.
    let (lo, hi) = sphere_u_range(&scene.float);
    let (uticks, ustep) = nice_ticks(lo.min(0.0), hi.max(0.0), 6);
    let (umin, umax) = (uticks[0], uticks[uticks.len() - 1]);
    let px = |t_deg: f64| x0 + t_deg / 360.0 * w;
    let py = |u: f64| y0 + h - (u - umin) / (umax - umin) * h;

    // Real t-ranges (exact), grid, frame, the t axis.
    if let Ok(e) = &scene.exact {
        let band = |svg: &mut Svg, a: f64, b: f64| {
            svg.leaf(
                "rect",
                &[
                    ("class", &"real"),
                    ("x", &N(px(a))),
                    ("y", &N(y0)),
                    ("width", &N(px(b) - px(a))),
                    ("height", &N(h)),
                ],
            );
        };
        if e.everywhere {
            band(&mut svg, 0.0, 360.0);
        }
        for &(s, t) in &e.arcs {
            if s <= t {
                band(&mut svg, s, t);
            } else {
                band(&mut svg, s, 360.0);
                band(&mut svg, 0.0, t);
            }
        }
    }
    for k in 0..=12 {
        let x = px(k as f64 * 30.0);
        svg.line((x, y0), (x, y0 + h), &[("class", &"grid")]);
    }
    for &u in &uticks {
        svg.line((x0, py(u)), (x0 + w, py(u)), &[("class", &"grid")]);
    }
    svg.leaf(
        "rect",
        &[
            ("class", &"frame"),
            ("x", &N(x0)),
            ("y", &N(y0)),
            ("width", &N(w)),
            ("height", &N(h)),
        ],
    );
    svg.line((x0, py(0.0)), (x0 + w, py(0.0)), &[("class", &"taxis")]);
    for k in 0..=36 {
        let x = px(k as f64 * 10.0);
        let len = if k % 3 == 0 { 6.0 } else { 3.0 };
        svg.line((x, y0 + h), (x, y0 + h + len), &[("stroke", &"#444")]);
        if k % 3 == 0 {
            svg.text(
                x,
                y0 + h + 20.0,
                &format!("{}°", k * 10),
                &[("class", &"tick"), ("text-anchor", &"middle")],
            );
        }
    }
    for &u in &uticks {
        svg.line((x0 - 6.0, py(u)), (x0, py(u)), &[("stroke", &"#444")]);
        svg.text(
            x0 - 10.0,
            py(u) + 4.0,
            &tick_label(u, ustep),
            &[("class", &"tick"), ("text-anchor", &"end")],
        );
    }
    svg.text(
        x0 + w / 2.0,
        y0 + h + 44.0,
        "t (degrees)",
        &[("class", &"axlabel"), ("text-anchor", &"middle")],
    );
    let (lx, ly) = (x0 - 52.0, y0 + h / 2.0);
    svg.text(
        lx,
        ly,
        "u (along the cylinder axis)",
        &[
            ("class", &"axlabel"),
            ("text-anchor", &"middle"),
            ("transform", &format!("rotate(-90 {} {})", N(lx), N(ly))),
        ],
    );

    // The branches.
    for run in &curves {
        for (branch, class) in [(1, "curve u1"), (2, "curve u2")] {
            let pts: Vec<(f64, f64)> = run
                .iter()
                .map(|p| (px(p[0].to_degrees()), py(p[branch])))
                .collect();
            svg.leaf("polyline", &[("class", &class), ("points", &Points(&pts))]);
        }
    }
    if curves.is_empty() {
        svg.text(
            x0 + w / 2.0,
            y0 + 28.0,
            "A(t)² − B(t) < 0 for every sampled t: no real u, no curve",
            &[
                ("class", &"legend"),
                ("text-anchor", &"middle"),
                ("font-style", &"italic"),
            ],
        );
    }

    // The paper's 10-degree samples (under the exact markers).
    let mut sample_real = (0, 0);
    for k in 0..=36 {
        let t = k as f64 * 10.0;
        match sampler.roots(t.to_radians()) {
            Some((u1, u2)) => {
                sample_real.0 += 1;
                circle(&mut svg, px(t), py(u1), 3.4, "dot");
                circle(&mut svg, px(t), py(u2), 3.4, "dot");
            }
            None => {
                sample_real.1 += 1;
                circle(&mut svg, px(t), py(0.0), 3.4, "hollow");
            }
        }
    }

    // Exact ends of the real t-intervals and touching points.
    let mid_u = |t_deg: f64| {
        let p = eval(&sampler, t_deg.to_radians());
        0.5 * (p[1] + p[2])
    };
    let mut labelled: Vec<f64> = Vec::new();
    let mut label = |svg: &mut Svg, t: f64, text: String| {
        let x = px(t);
        svg.line((x, y0), (x, y0 + h), &[("class", &"guide")]);
        // Stagger labels that would overlap.
        let row = labelled
            .iter()
            .filter(|&&o| (px(o) - x).abs() < 44.0)
            .count();
        labelled.push(t);
        svg.text(
            x + 3.0,
            y0 + 13.0 + 12.0 * row as f64,
            &text,
            &[("class", &"mark")],
        );
    };
    if let Ok(e) = &scene.exact {
        for &(s, t) in &e.arcs {
            for end in [s, t] {
                let (x, y) = (px(end), py(mid_u(end)));
                label(&mut svg, end, format!("{}°", short(end, 2)));
                svg.line((x, y - 9.0), (x, y + 9.0), &[("class", &"end")]);
            }
        }
        for &t in &e.tangents {
            label(&mut svg, t, format!("{}° (touching)", short(t, 2)));
            diamond(&mut svg, px(t), py(mid_u(t)), 6.0, "tangent");
        }
    }

    // Legend: the entries that occur.
    let mut rows: Vec<(String, Sym)> = Vec::new();
    if !curves.is_empty() {
        rows.push(("u1 = −A − √(A² − B)".into(), Sym::Line("curve u1")));
        rows.push(("u2 = −A + √(A² − B)".into(), Sym::Line("curve u2")));
    }
    if sample_real.0 > 0 {
        rows.push(("10° sample: real u1, u2".into(), Sym::Dot("dot")));
    }
    if sample_real.1 > 0 {
        rows.push(("10° sample: not real".into(), Sym::Dot("hollow")));
    }
    let mut notes = vec![
        format!("curves: f64, {TU_SAMPLES} steps in t,"),
        "broken where A² − B < 0".to_string(),
    ];
    if let Ok(e) = &scene.exact {
        if e.everywhere || !e.arcs.is_empty() {
            rows.push(("A² − B ≥ 0 (exact)".into(), Sym::Band));
        }
        if !e.arcs.is_empty() {
            rows.push(("end of a real t-interval".into(), Sym::Tick));
        }
        if !e.tangents.is_empty() {
            rows.push(("touching point".into(), Sym::Diamond));
        }
        if e.everywhere || !e.arcs.is_empty() || !e.tangents.is_empty() {
            notes.push("shading, ends, touching points:".into());
            notes.push("exact (Sturm on the τ-quartic)".into());
        }
    }
    legend(&mut svg, x0 + w + 36.0, y0, &rows, &notes);
    svg.finish()
}
