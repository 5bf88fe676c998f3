//! Criterion benchmark of deciding an identity between rational functions against deciding its
//! cleared numerator as a polynomial identity: `P/D = Q/D` with `P = (x + y + z + 1)^k` as
//! written, `Q` its expansion and `D = 1 + x^2 + y^2`, against `P D = Q D`. Both paths start
//! from the parsed expressions: the rational one converts the two sides as `prove` does
//! (`ratfun_sides`: cross-multiplied once over the factored denominators, then only the smaller
//! side reduced to lowest terms), clears the denominators and decides the cleared numerator
//! off the zeros of `D`; the polynomial one expands both sides and decides their difference.
//! A third line, `reduced`, converts each side to lowest terms on its own (`to_ratfun`, the
//! route taken when the identity does not hold), for comparison. The
//! cleared numerator `P D - Q D` has `3 C(k + 3, 3)` terms before it cancels: 105, 495 and
//! 1,365 at `k = 4, 8, 12`.
//!
//! Two realistic families go the same way. The curvature numerator of a rational Bezier curve
//! of degree `n` with symbolic weights, `x' y'' - y' x''` written from the derivatives of
//! `x = X/W`, `y = Y/W` (`diff` of the fractions), against its homogeneous form
//! `det[[W, X, Y], [W', X', Y'], [W'', X'', Y'']] / W^3`; the polynomial side is the
//! numerator cleared by hand, `W ((X'W - XW')(Y''W - YW'') - (Y'W - YW')(X''W - XW''))` against
//! `det W^2`. And the rational unit circle family `((p^2 - q^2)/(p^2 + q^2))^2 +
//! (2pq/(p^2 + q^2))^2 = 1` with `p = (t + s + 1)^k`, `q = (t - 2s)^k`, against
//! `(p^2 - q^2)^2 + (2pq)^2 = (p^2 + q^2)^2`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use exactcheck_exact::expr::library::{resolve, Val};
use exactcheck_exact::expr::{parse_expr, ratfun_sides, Expr};
use exactcheck_exact::poly::Vars;
use exactcheck_exact::prove::{decide_fraction, decide_in, Decision, FractionIdentity};
use exactcheck_exact::ratfun::RatFun;
use exactcheck_exact::Rational;
use std::time::Duration;

const D: &str = "(1 + x^2 + y^2)";

/// The two sides of the rational identity and of the polynomial one at `k`.
fn sides(k: u32) -> ((Expr, Expr), (Expr, Expr)) {
    let p = format!("(x + y + z + 1)^{k}");
    let mut vars = Vars::new();
    let q = parse_expr(&p)
        .unwrap()
        .to_poly::<Rational>(&mut vars)
        .unwrap()
        .display(&vars)
        .to_string();
    let e = |s: String| parse_expr(&s).unwrap();
    (
        (e(format!("{p}/{D}")), e(format!("({q})/{D}"))),
        (e(format!("{p}*{D}")), e(format!("({q})*{D}"))),
    )
}

fn rational(l: &Expr, r: &Expr) -> bool {
    let mut vars = Vars::new();
    let (l, r) = ratfun_sides::<Rational>(l, r, &mut vars).unwrap();
    decide_sides(&l, &r, vars.len())
}

fn reduced(l: &Expr, r: &Expr) -> bool {
    let mut vars = Vars::new();
    let l = l.to_ratfun::<Rational>(&mut vars).unwrap();
    let r = r.to_ratfun::<Rational>(&mut vars).unwrap();
    decide_sides(&l, &r, vars.len())
}

fn decide_sides(l: &RatFun<Rational>, r: &RatFun<Rational>, nvars: usize) -> bool {
    let f = FractionIdentity::new(l, r).unwrap();
    matches!(
        decide_fraction(&f, &[], &[], &[], nvars).unwrap(),
        Decision::Proved { .. }
    )
}

fn polynomial(l: &Expr, r: &Expr) -> bool {
    let mut vars = Vars::new();
    let l = l.to_poly::<Rational>(&mut vars).unwrap();
    let r = r.to_poly::<Rational>(&mut vars).unwrap();
    matches!(
        decide_in(&(l - r), &[], &[], vars.len()).unwrap(),
        Decision::Proved { .. }
    )
}

/// The two sides of a rational identity, then those of its cleared numerator.
type Pair = ((Expr, Expr), (Expr, Expr));

/// `bezier(t, c_0, ..., c_n)` with `c_i = f(i)`.
fn bezier(n: usize, f: impl Fn(usize) -> String) -> String {
    let pts: Vec<String> = (0..=n).map(f).collect();
    format!("bezier(t, {})", pts.join(", "))
}

/// The curvature identity of a rational Bezier curve of degree `n` (rational sides, then the
/// cleared numerator's polynomial sides).
fn curvature(n: usize) -> Pair {
    let x = bezier(n, |i| format!("w{i}*x{i}"));
    let y = bezier(n, |i| format!("w{i}*y{i}"));
    let w = bezier(n, |i| format!("w{i}"));
    let d = |p: &str, k: u32| {
        if k == 1 {
            format!("diff({p}, t)")
        } else {
            format!("diff({p}, t, {k})")
        }
    };
    let (fx, fy) = (format!("({x})/({w})"), format!("({y})/({w})"));
    let lhs = format!("{}*{} - {}*{}", d(&fx, 1), d(&fy, 2), d(&fy, 1), d(&fx, 2));
    let det = format!(
        "({w})*({xd}*{yd2} - {yd}*{xd2}) - {wd}*(({x})*{yd2} - ({y})*{xd2}) + {wd2}*(({x})*{yd} - ({y})*{xd})",
        xd = d(&x, 1),
        yd = d(&y, 1),
        xd2 = d(&x, 2),
        yd2 = d(&y, 2),
        wd = d(&w, 1),
        wd2 = d(&w, 2),
    );
    let cleared = format!(
        "({w})*((({xd})*({w}) - ({x})*{wd})*(({yd2})*({w}) - ({y})*{wd2}) - (({yd})*({w}) - ({y})*{wd})*(({xd2})*({w}) - ({x})*{wd2}))",
        xd = d(&x, 1),
        yd = d(&y, 1),
        xd2 = d(&x, 2),
        yd2 = d(&y, 2),
        wd = d(&w, 1),
        wd2 = d(&w, 2),
    );
    let e = |s: String| match resolve(&s).unwrap() {
        Val::Scalar(x) => x,
        other => panic!("a scalar, not {other:?}"),
    };
    (
        (e(lhs), e(format!("({det})/({w})^3"))),
        (e(cleared), e(format!("({det})*({w})^2"))),
    )
}

/// The rational unit circle identity with `p = (t + s + 1)^k`, `q = (t - 2s)^k`.
fn circle(k: u32) -> Pair {
    // Parenthesised: `^` is right-associative, so `(t + s + 1)^4^2` would be a 16th power.
    let (p, q) = (format!("((t + s + 1)^{k})"), format!("((t - 2*s)^{k})"));
    let den = format!("({p}^2 + {q}^2)");
    let e = |s: String| parse_expr(&s).unwrap();
    (
        (
            e(format!("(({p}^2 - {q}^2)/{den})^2 + (2*{p}*{q}/{den})^2")),
            e("1".to_string()),
        ),
        (
            e(format!("({p}^2 - {q}^2)^2 + (2*{p}*{q})^2")),
            e(format!("{den}^2")),
        ),
    )
}

/// Benchmarks both sides of each identity of `cases` in group `name`.
fn pair_group(c: &mut Criterion, name: &str, cases: Vec<(u32, Pair)>) {
    let mut g = c.benchmark_group(name);
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(300));
    g.measurement_time(Duration::from_secs(2));
    for (k, ((rl, rr), (pl, pr))) in cases {
        assert!(rational(&rl, &rr), "the rational identity of {name} at {k}");
        assert!(reduced(&rl, &rr), "the reduced identity of {name} at {k}");
        assert!(
            polynomial(&pl, &pr),
            "the polynomial identity of {name} at {k}"
        );
        g.bench_with_input(BenchmarkId::new("rational", k), &k, |b, _| {
            b.iter(|| rational(&rl, &rr))
        });
        g.bench_with_input(BenchmarkId::new("numerator", k), &k, |b, _| {
            b.iter(|| polynomial(&pl, &pr))
        });
        g.bench_with_input(BenchmarkId::new("reduced", k), &k, |b, _| {
            b.iter(|| reduced(&rl, &rr))
        });
    }
    g.finish();
}

fn realistic(c: &mut Criterion) {
    let degrees = [2u32, 3, 4];
    let curves = degrees
        .iter()
        .map(|&n| (n, curvature(n as usize)))
        .collect();
    pair_group(c, "curvature_vs_numerator", curves);
    let circles = [2u32, 4, 6].iter().map(|&k| (k, circle(k))).collect();
    pair_group(c, "circle_vs_numerator", circles);
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("fraction_vs_numerator");
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(300));
    g.measurement_time(Duration::from_secs(2));
    for k in [4u32, 8, 12] {
        let ((rl, rr), (pl, pr)) = sides(k);
        // Both must be proved before they are timed.
        assert!(rational(&rl, &rr), "the rational identity at k = {k}");
        assert!(reduced(&rl, &rr), "the reduced identity at k = {k}");
        assert!(polynomial(&pl, &pr), "the polynomial identity at k = {k}");
        g.bench_with_input(BenchmarkId::new("rational", k), &k, |b, _| {
            b.iter(|| rational(&rl, &rr))
        });
        g.bench_with_input(BenchmarkId::new("numerator", k), &k, |b, _| {
            b.iter(|| polynomial(&pl, &pr))
        });
        g.bench_with_input(BenchmarkId::new("reduced", k), &k, |b, _| {
            b.iter(|| reduced(&rl, &rr))
        });
    }
    g.finish();
}

criterion_group!(benches, bench, realistic);
criterion_main!(benches);
