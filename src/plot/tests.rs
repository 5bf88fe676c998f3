//! Unit tests of the plot modules.

use super::*;
use style::tick_label;

#[test]
fn escaping() {
    assert_eq!(
        escape(r#"a < b && c > "d" 'e'"#),
        "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &apos;e&apos;"
    );
    assert_eq!(escape("plain °√ text"), "plain °√ text");
    assert_eq!(escape("bell\u{7}tab\t"), "bell\u{FFFD}tab\t");
    // A page: the title escaped after the <svg> tag, text escaped and cleaned by plotters' writer.
    let out = style::render((10, 10), "<T&>", |root| {
        style::text(root, "x<y\u{1}", (1, 2), &style::font(10.0, style::INK))
    });
    assert!(
        out.starts_with("<svg width=\"10\" height=\"10\" viewBox=\"0 0 10 10\""),
        "{out}"
    );
    assert!(out.contains(">\n<title>&lt;T&amp;&gt;</title>\n"), "{out}");
    assert!(out.contains("x&lt;y\u{FFFD}"), "{out}");
    assert!(out.trim_end().ends_with("</svg>"));
}

/// The axis of fixed ticks: the key points are the ticks inside the range, the labels follow
/// the step, far-off values saturate instead of wrapping round.
#[test]
fn ticked_axis() {
    use plotters::coord::ranged1d::{Ranged, ValueFormatter};
    let a = style::Ticked::nice(-7.0, 7.0, 6);
    assert_eq!(a.range, (-8.0, 8.0));
    assert_eq!(
        a.key_points(100usize),
        vec![-8.0, -6.0, -4.0, -2.0, 0.0, 2.0, 4.0, 6.0, 8.0]
    );
    assert_eq!(a.map(&-8.0, (0, 160)), 0);
    assert_eq!(a.map(&2.0, (0, 160)), 100);
    assert_eq!(a.map(&1e300, (0, 160)), 1_000_000);
    assert_eq!(a.format_ext(&-6.0), "−6");
    let t = style::Ticked {
        range: (0.0, 360.0),
        ticks: vec![0.0, 30.0, 400.0],
        step: 30.0,
    };
    assert_eq!(t.key_points(5usize), vec![0.0, 30.0]);
}

#[test]
fn ticks() {
    let (t, step) = nice_ticks(-7.0, 7.0, 6);
    assert_eq!(step, 2.0);
    assert_eq!(t, vec![-8.0, -6.0, -4.0, -2.0, 0.0, 2.0, 4.0, 6.0, 8.0]);
    let (t, step) = nice_ticks(0.0, 9.0, 6);
    assert_eq!((t[0], *t.last().unwrap(), step), (0.0, 10.0, 2.0));
    let (t, step) = nice_ticks(0.0, 1.0, 5);
    assert!((step - 0.2).abs() < 1e-12);
    assert_eq!(t.len(), 6);
    assert_eq!(tick_label(t[3], step), "0.6");
    let (t, step) = nice_ticks(-3.0, 30.0, 6);
    assert_eq!(step, 5.0);
    assert_eq!((t[0], *t.last().unwrap()), (-5.0, 30.0));
    assert_eq!(tick_label(-5.0, step), "−5");
    // A degenerate range still gives ticks.
    assert!(nice_ticks(2.0, 2.0, 4).0.len() >= 2);
}

/// Ticks for any finite range: few, finite, increasing, covering the range, with a positive
/// step. Old: a subnormal range (a sphere radius of 1/10^323) gave a zero step and a range of
/// `i64::MIN..=i64::MAX` ticks, "capacity overflow".
#[test]
fn ticks_for_any_finite_range() {
    let tiny = 1e-323;
    let cases = [
        (-tiny, tiny),
        (0.0, tiny),
        (3.0, 3.0 + 4.0 * f64::EPSILON),
        (0.0, 0.0),
        (-0.0, 0.0),
        (tiny, tiny),
        (f64::MAX, f64::MAX),
        (-f64::MAX, f64::MAX),
        (0.0, f64::MAX),
        (-f64::MAX, -f64::MAX / 2.0),
        (1e300, 1e300 * (1.0 + 1e-15)),
        (-1e-300, 1e-300),
        (5.0, -5.0),
        (f64::MIN_POSITIVE, 2.0 * f64::MIN_POSITIVE),
    ];
    for (lo, hi) in cases {
        for target in [0, 1, 6, 1000, usize::MAX] {
            let (t, step) = nice_ticks(lo, hi, target);
            let what = format!("[{lo:e}, {hi:e}] target {target}: {t:?} step {step:e}");
            assert!(t.len() >= 2 && t.len() <= 4 * 1000 + 5, "{what}");
            assert!(step.is_finite() && step > 0.0, "{what}");
            assert!(t.iter().all(|x| x.is_finite()), "{what}");
            assert!(t.windows(2).all(|w| w[0] < w[1]), "{what}");
            assert!(t[0] <= lo.min(hi) && t[t.len() - 1] >= hi.max(lo), "{what}");
            assert!(t.iter().all(|&x| !tick_label(x, step).is_empty()), "{what}");
        }
    }
    // Non-finite bounds give no ticks rather than a loop or a panic.
    assert!(nice_ticks(f64::NAN, 1.0, 6).0.is_empty());
    assert!(nice_ticks(0.0, f64::INFINITY, 6).0.is_empty());
    // A subnormal range is drawn at the smallest width f64 resolves here, about its centre.
    let (t, step) = nice_ticks(-tiny, tiny, 6);
    assert!((1e-292..=1e-290).contains(&step), "{step:e}");
    assert!(t.len() <= 10, "{t:?}");
    assert_eq!(tick_label(2e-7, 1e-7), "2.000e−7");
}

#[test]
fn angles_from_tau() {
    assert_eq!(tau_degrees(0.0), 0.0);
    assert!((tau_degrees(1.0) - 90.0).abs() < 1e-12);
    assert!((tau_degrees(-1.0) - 270.0).abs() < 1e-12);
}

#[test]
fn exact_arcs_of_the_examples() {
    let e1 = spaeth_scene(1)
        .map(|s| s.exact.ok())
        .ok()
        .flatten()
        .expect("example 1");
    assert!(e1.everywhere && e1.arcs.is_empty());
    let e3 = spaeth_scene(3)
        .map(|s| s.exact.ok())
        .ok()
        .flatten()
        .expect("example 3");
    assert!(!e3.everywhere && e3.arcs.is_empty() && e3.tangents.is_empty());
    let e2 = spaeth_scene(2)
        .map(|s| s.exact.ok())
        .ok()
        .flatten()
        .expect("example 2");
    assert!(!e2.everywhere && !e2.arcs.is_empty());
    // The f64 sampler agrees with the exact arcs away from their ends.
    let s = spaeth_scene(2).expect("example 2");
    let sampler = DiscSampler::new(&s.float);
    for &(a, b) in &e2.arcs {
        let len = if a <= b { b - a } else { b + 360.0 - a };
        let mid = (a + len / 2.0) % 360.0;
        assert!(sampler.discriminant(mid.to_radians()) > 0.0, "{a} {b}");
    }
    assert!(spaeth_scene(4).is_err());
}

#[test]
fn runs_are_closed_at_the_boundary() {
    let s = spaeth_scene(2).expect("example 2");
    let sampler = DiscSampler::new(&s.float);
    let rs = runs(&sampler, 500);
    assert!(!rs.is_empty());
    for r in &rs {
        let first = r[0];
        let last = r[r.len() - 1];
        // Where a run starts or ends inside (0, 2 pi) the branches meet.
        if first[0] > 1e-9 {
            assert!((first[1] - first[2]).abs() < 1e-3, "{first:?}");
        }
        if last[0] < TAU - 1e-9 {
            assert!((last[1] - last[2]).abs() < 1e-3, "{last:?}");
        }
    }
}

/// Every figure of the catalogue (what the report inlines): unique ids, a caption naming the
/// paper's example, and an SVG document with a size, a viewBox and the caption as its title.
#[test]
fn catalogue_figures_are_documents() {
    let figs = crate::papers::figures().expect("the catalogue draws");
    let ids: Vec<&str> = figs.iter().map(|f| f.id.as_str()).collect();
    assert_eq!(
        ids,
        [
            "spaeth.example1.tu",
            "spaeth.example1.3d",
            "spaeth.example2.tu",
            "spaeth.example2.3d",
            "spaeth.example3.tu",
            "spaeth.example3.3d",
            "chiang.example4",
            "chiang.conic_table",
            "chiang.ph_offsets"
        ]
    );
    for f in &figs {
        let head = f.svg.lines().next().unwrap_or_default();
        assert!(head.starts_with("<svg width=\""), "{}: {head}", f.id);
        let size: Vec<&str> = head.split('"').collect();
        let (w, h) = (size[1], size[3]);
        assert!(w.parse::<u32>().is_ok_and(|w| w > 0), "{}", f.id);
        assert!(h.parse::<u32>().is_ok_and(|h| h > 0), "{}", f.id);
        assert!(
            head.contains(&format!("viewBox=\"0 0 {w} {h}\"")),
            "{}",
            f.id
        );
        assert!(f
            .svg
            .lines()
            .nth(1)
            .is_some_and(|l| l.starts_with("<title>")));
        assert!(f.svg.trim_end().ends_with("</svg>"), "{}", f.id);
        assert!(!f.svg.contains("NaN") && !f.svg.contains("inf"), "{}", f.id);
    }
}
