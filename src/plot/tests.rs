//! Unit tests of the plot modules.

use super::*;

#[test]
fn escaping() {
    assert_eq!(
        escape(r#"a < b && c > "d" 'e'"#),
        "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &apos;e&apos;"
    );
    assert_eq!(escape("plain °√ text"), "plain °√ text");
    assert_eq!(escape("bell\u{7}tab\t"), "bell\u{FFFD}tab\t");
    let mut svg = Svg::new(10.0, 10.0, "<T&>");
    svg.text(1.0, 2.0, "x<y", &[("class", &"a\"b")]);
    let out = svg.finish();
    assert!(out.contains("<title>&lt;T&amp;&gt;</title>"), "{out}");
    assert!(
        out.contains(r#"<text x="1" y="2" class="a&quot;b">x&lt;y</text>"#),
        "{out}"
    );
    assert!(out.trim_end().ends_with("</svg>"));
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
