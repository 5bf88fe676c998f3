//! `exactcheck regress plane-plane`: the published JavaScript `InterctionLineOf2Areas`
//! (`exactcheck_float::wabis`, ported operation for operation) against the exact construction
//! of `exactcheck_core::planes`, as the planes approach parallel.
//!
//! # Inputs
//! Sample `i` of seed `s` is drawn from [`exactcheck_float::Rng::for_sample`]`(s, i)`, so every
//! case is reproducible from the seed and its index. A random direction `n1` (uniform in the
//! cube, rejected outside `0.1 <= |v| <= 1`) is normalised in f64 the JavaScript way
//! (`V3.Scale(v, 1/V3.Length(v))`); a random unit `w` orthogonal to it likewise; the nominal
//! angle `theta` is log-uniform from 90 degrees (`pi/2`) down to `1e-12` rad, and
//! `n2 = cos(theta) n1 + sin(theta) w`, normalised in f64. The points `P1, P2` are uniform in
//! `[-10, 10]^3`. The function requires unit normals, so it gets these f64 normals; the exact
//! construction gets **the same f64 values**, converted exactly to rationals (it does not need
//! unit length, so nothing is lost).
//!
//! # Measures
//! * **point**: `max_i |Q_f64,i - Q_i| / ulp(max_i |Q_i|)`, the error in ulps of the largest
//!   coordinate of the exact point `Q` (a per-coordinate ulps measure would blow up on a
//!   coordinate that happens to be near 0, which says nothing about the formula);
//! * **direction**: the published `q` is a unit vector along `n2 x n1`; the exact unit direction
//!   is `u = -(n1 x n2)/sqrt(G)`, `G = |n1 x n2|^2`, with `sqrt(G)` to 256 bits. The error is
//!   `max_i |q_i - u_i| / 2^-52`, in ulps of 1 (the length of both vectors); the angle between
//!   `q` and `u` is at most `sqrt(3)` times this many units of `2^-52`.
//!
//! Its own sweep rather than a `Subject` of the float harness: the report is binned by a derived
//! quantity (the angle between the normals), which the harness's flat statistics do not provide,
//! and both measures are taken relative to the whole vector (the largest coordinate, the unit
//! length), not per output as the harness measures. The harness's exact conversions and ulp
//! measure are reused.
//!
//! Each sample is binned by the exact angle between its f64 normals (`asin` of the square root
//! of `|n1 x n2|^2 / (|n1|^2 |n2|^2)`, computed exactly and rounded once), in decades. Each bin
//! reports the count, the max and median of both measures, and its worst case (by point error)
//! with the seed, the index and the inputs.

use super::sqrt_256;
use exactcheck_core::planes::{intersect, Plane, PlanePair};
use exactcheck_core::Vec3;
use exactcheck_exact::Rational;
use exactcheck_float::wabis::{interction_line_of_2_areas, length, scale, V3};
use exactcheck_float::{f64_to_rational, rational_to_f64, ulp, ExactScalar, Rng};
use num_rational::BigRational;
use num_traits::Signed;
use serde_json::{json, Value};
use std::fmt;

/// The largest angle (90 degrees) and the smallest nominal angle of the sweep.
pub const ANGLE_RANGE: (f64, f64) = (std::f64::consts::FRAC_PI_2, 1e-12);

/// The number of decade bins: `[0.1, pi/2]`, `[1e-2, 1e-1)`, ..., `[1e-11, 1e-10)`, and
/// `(0, 1e-11)` (the sweep's smallest angles, which the f64 normalisation may push a little
/// below 1e-12).
pub const BINS: usize = 12;

/// One input of the published function.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneCase {
    /// The first plane's point.
    pub p1: V3,
    /// The first plane's normal (unit in f64).
    pub n1: V3,
    /// The second plane's point.
    pub p2: V3,
    /// The second plane's normal (unit in f64).
    pub n2: V3,
}

fn random_unit(rng: &mut Rng) -> V3 {
    loop {
        let v = [
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
        ];
        let l = length(&v);
        if (0.1..=1.0).contains(&l) {
            return scale(&v, 1.0 / l);
        }
    }
}

fn f64_unit(v: &V3) -> V3 {
    scale(v, 1.0 / length(v))
}

/// `b - (b . n1) n1`: the part of `b` orthogonal to the unit vector `n1` (f64).
fn orthogonal_part(b: &V3, n1: &V3) -> V3 {
    let k = b[0] * n1[0] + b[1] * n1[1] + b[2] * n1[2];
    [b[0] - k * n1[0], b[1] - k * n1[1], b[2] - k * n1[2]]
}

/// The unit normal at the angle `theta` from the unit normal `n1`, turned towards `b` (which must
/// not be parallel to `n1`): `unit(cos(theta) n1 + sin(theta) w)` with `w` the normalised part of
/// `b` orthogonal to `n1`, all in f64 (the sweep's and the tests' one construction).
pub fn normal_at_angle(n1: &V3, b: &V3, theta: f64) -> V3 {
    let w = f64_unit(&orthogonal_part(b, n1));
    let (c, s) = (theta.cos(), theta.sin());
    f64_unit(&[
        c * n1[0] + s * w[0],
        c * n1[1] + s * w[1],
        c * n1[2] + s * w[2],
    ])
}

/// Sample `index` of the sweep with this seed (module documentation).
pub fn sample_case(seed: u64, index: usize) -> PlaneCase {
    let mut rng = Rng::for_sample(seed, index as u64);
    let n1 = random_unit(&mut rng);
    let v = loop {
        let v = random_unit(&mut rng);
        if length(&orthogonal_part(&v, &n1)) > 0.1 {
            break v;
        }
    };
    let (hi, lo) = (ANGLE_RANGE.0.log10(), ANGLE_RANGE.1.log10());
    let theta = 10f64.powf(rng.uniform(lo, hi));
    let n2 = normal_at_angle(&n1, &v, theta);
    let mut point = || {
        [
            rng.uniform(-10.0, 10.0),
            rng.uniform(-10.0, 10.0),
            rng.uniform(-10.0, 10.0),
        ]
    };
    let (p1, p2) = (point(), point());
    PlaneCase { p1, n1, p2, n2 }
}

/// The errors of one case.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    /// The exact angle between the normals, in radians (rounded once).
    pub angle: f64,
    /// The point's error in ulps of its largest coordinate (`inf` when the function returned
    /// `null` or a non-finite point).
    pub point_ulps: f64,
    /// The unit direction's error in ulps of 1 (`inf` when the function returned `null`).
    pub direction_ulps: f64,
    /// The function returned `null` (its test `ql == 0` fired) although the planes meet in a line.
    pub null: bool,
    /// The function returned a point with a non-finite coordinate (`1 - r*r` evaluated to 0 or
    /// the quotient overflowed) although the planes meet in a line.
    pub non_finite: bool,
}

fn exact_vec(v: &V3) -> Option<Vec3<Rational>> {
    let r = |x: f64| Rational::from_f64_exact(x);
    Some(Vec3::new(r(v[0])?, r(v[1])?, r(v[2])?))
}

/// The published function against the exact construction on one case; `None` when an input is
/// not finite or the exact planes are not a line (parallel, coincident, zero normal).
pub fn measure(case: &PlaneCase) -> Option<Measured> {
    let plane = |n: &V3, p: &V3| Some(Plane::through(exact_vec(n)?, &exact_vec(p)?));
    let (a, b) = (plane(&case.n1, &case.p1)?, plane(&case.n2, &case.p2)?);
    let PlanePair::Line { point, direction } = intersect(&a, &b) else {
        return None;
    };
    let big = |v: &Vec3<Rational>| v.map(Rational::to_big_rational).into_array();
    let (q_exact, c) = (big(&point), big(&direction));
    let g = direction.norm_squared().to_big_rational();
    let sin2 = &g / (a.normal.norm_squared() * b.normal.norm_squared()).to_big_rational();
    let angle = rational_to_f64(&sin2).clamp(0.0, 1.0).sqrt().asin();
    let Some((q_point, q_dir)) = interction_line_of_2_areas(&case.p1, &case.n1, &case.p2, &case.n2)
    else {
        return Some(Measured {
            angle,
            point_ulps: f64::INFINITY,
            direction_ulps: f64::INFINITY,
            null: true,
            non_finite: false,
        });
    };
    let largest = q_exact
        .iter()
        .map(|x| rational_to_f64(&x.abs()))
        .fold(0.0, f64::max);
    let point_ulps = max_scaled_error(&q_point, &q_exact, ulp(largest));
    let root = sqrt_256(&g);
    let unit: Vec<BigRational> = c.iter().map(|ci| -(ci / &root)).collect();
    let direction_ulps = max_scaled_error(&q_dir, &unit, ulp(1.0));
    Some(Measured {
        angle,
        point_ulps,
        direction_ulps,
        null: false,
        non_finite: !q_point.iter().all(|x| x.is_finite()),
    })
}

/// `max_i |approx_i - exact_i| / unit`, computed exactly and rounded once; `inf` for a
/// non-finite approximation.
fn max_scaled_error(approx: &V3, exact: &[BigRational], unit: f64) -> f64 {
    let unit = f64_to_rational(unit).expect("an ulp of a finite double is finite");
    approx
        .iter()
        .zip(exact)
        .map(|(a, e)| match f64_to_rational(*a) {
            Some(a) => rational_to_f64(&((a - e).abs() / &unit)),
            None => f64::INFINITY,
        })
        .fold(0.0, f64::max)
}

/// The decade bin of an angle: 0 for `[0.1, pi/2]`, `k` for `[10^-(k+1), 10^-k)`, the last bin
/// taking everything below `1e-11`.
pub fn bin_of(angle: f64) -> usize {
    if angle >= 0.1 {
        return 0;
    }
    if angle <= 0.0 {
        return BINS - 1;
    }
    let k = (-angle.log10()).floor();
    (k as usize).clamp(1, BINS - 1)
}

/// The statistics of one bin.
#[derive(Clone, Debug, PartialEq)]
pub struct Bin {
    /// The smallest angle of the bin (radians).
    pub lo: f64,
    /// The largest angle of the bin.
    pub hi: f64,
    /// Cases in the bin.
    pub count: usize,
    /// Cases whose published point has a non-finite coordinate.
    pub non_finite: usize,
    /// Largest point error (ulps of the largest coordinate).
    pub point_max: f64,
    /// Median point error.
    pub point_median: f64,
    /// Largest direction error (ulps of 1).
    pub direction_max: f64,
    /// Median direction error.
    pub direction_median: f64,
    /// The case with the largest point error: its index and inputs.
    pub worst: Option<(usize, PlaneCase)>,
}

/// The report of `regress plane-plane`.
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneReport {
    /// The seed (cases are `sample_case(seed, index)`; planted cases carry their own index).
    pub seed: u64,
    /// Cases measured.
    pub measured: usize,
    /// Cases skipped (not a line exactly, or a non-finite input).
    pub skipped: usize,
    /// Cases where the published function returned `null` although the planes meet in a line.
    pub null_results: usize,
    /// Cases where it returned a non-finite point although the planes meet in a line.
    pub non_finite_results: usize,
    /// The decade bins, widest angles first.
    pub bins: Vec<Bin>,
    /// The worst cases overall (largest point error, then largest direction error, then the
    /// earlier index), at most the number asked for.
    pub worst: Vec<(usize, PlaneCase, Measured)>,
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    }
}

/// Measures the given cases `(index, case)`, bins them and keeps the `worst` worst.
pub fn report(
    seed: u64,
    cases: impl IntoIterator<Item = (usize, PlaneCase)>,
    worst: usize,
) -> PlaneReport {
    use rayon::prelude::*;
    let mut per_bin: Vec<Vec<(usize, PlaneCase, Measured)>> = vec![Vec::new(); BINS];
    let (mut skipped, mut null_results) = (0, 0);
    // Each case is measured on its own (exactly): in parallel, then binned in the given order,
    // so the report does not depend on the number of threads.
    let cases: Vec<(usize, PlaneCase)> = cases.into_iter().collect();
    let measured: Vec<Option<Measured>> = cases.par_iter().map(|(_, c)| measure(c)).collect();
    for ((i, case), m) in cases.into_iter().zip(measured) {
        match m {
            None => skipped += 1,
            Some(m) => {
                null_results += usize::from(m.null);
                per_bin[bin_of(m.angle)].push((i, case, m));
            }
        }
    }
    let measured = per_bin.iter().map(Vec::len).sum();
    let mut all: Vec<(usize, PlaneCase, Measured)> = per_bin.iter().flatten().copied().collect();
    all.sort_by(|a, b| {
        b.2.point_ulps
            .total_cmp(&a.2.point_ulps)
            .then(b.2.direction_ulps.total_cmp(&a.2.direction_ulps))
            .then(a.0.cmp(&b.0))
    });
    all.truncate(worst);
    let bins: Vec<Bin> = per_bin
        .into_iter()
        .enumerate()
        .map(|(k, cases)| {
            let mut points: Vec<f64> = cases.iter().map(|c| c.2.point_ulps).collect();
            let mut dirs: Vec<f64> = cases.iter().map(|c| c.2.direction_ulps).collect();
            let worst = cases
                .iter()
                .max_by(|a, b| {
                    a.2.point_ulps
                        .total_cmp(&b.2.point_ulps)
                        .then(b.0.cmp(&a.0))
                })
                .map(|c| (c.0, c.1));
            Bin {
                lo: if k == BINS - 1 {
                    0.0
                } else {
                    10f64.powi(-(k as i32) - 1)
                },
                hi: if k == 0 {
                    ANGLE_RANGE.0
                } else {
                    10f64.powi(-(k as i32))
                },
                count: cases.len(),
                non_finite: cases.iter().filter(|c| c.2.non_finite).count(),
                point_max: points.iter().copied().fold(0.0, f64::max),
                point_median: median(&mut points),
                direction_max: dirs.iter().copied().fold(0.0, f64::max),
                direction_median: median(&mut dirs),
                worst,
            }
        })
        .collect();
    let non_finite_results = bins.iter().map(|b: &Bin| b.non_finite).sum();
    PlaneReport {
        seed,
        measured,
        skipped,
        null_results,
        non_finite_results,
        bins,
        worst: all,
    }
}

/// `samples` cases of the sweep with this seed, measured and binned, with the `worst` worst.
pub fn run(samples: usize, seed: u64, worst: usize) -> PlaneReport {
    report(seed, (0..samples).map(|i| (i, sample_case(seed, i))), worst)
}

impl PlaneReport {
    /// The non-empty bin with the largest point error.
    pub fn worst_bin(&self) -> Option<&Bin> {
        self.bins
            .iter()
            .filter(|b| b.count > 0)
            .max_by(|a, b| a.point_max.total_cmp(&b.point_max))
    }

    /// The report as JSON.
    pub fn to_json(&self) -> Value {
        let case = |c: &PlaneCase| json!({"p1": c.p1, "n1": c.n1, "p2": c.p2, "n2": c.n2});
        json!({
            "kernel": "plane-plane",
            "code_under_test": "InterctionLineOf2Areas (published JavaScript, ported to f64 operation for operation)",
            "reference": "exact construction (exactcheck_core::planes) on the same f64 inputs converted exactly",
            "point_measure": "max_i |Q_f64,i - Q_i| / ulp(max_i |Q_i|)",
            "direction_measure": "max_i |q_i - u_i| / 2^-52, u the exact unit direction of n2 x n1",
            "seed": self.seed,
            "measured": self.measured,
            "skipped": self.skipped,
            "null_results": self.null_results,
            "non_finite_results": self.non_finite_results,
            "bins": self.bins.iter().map(|b| json!({
                "angle_lo": b.lo,
                "angle_hi": b.hi,
                "count": b.count,
                "non_finite_points": b.non_finite,
                "point_max_ulps": finite_or_null(b.point_max),
                "point_median_ulps": finite_or_null(b.point_median),
                "direction_max_ulps": finite_or_null(b.direction_max),
                "direction_median_ulps": finite_or_null(b.direction_median),
                "worst": b.worst.map(|(i, c)| json!({"index": i, "inputs": case(&c)})),
            })).collect::<Vec<_>>(),
            "worst": self.worst.iter().map(|(i, c, m)| json!({
                "index": i,
                "angle": m.angle,
                "point_ulps": finite_or_null(m.point_ulps),
                "direction_ulps": finite_or_null(m.direction_ulps),
                "inputs": case(c),
            })).collect::<Vec<_>>(),
        })
    }
}

fn finite_or_null(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        json!("inf")
    }
}

fn bin_label(b: &Bin) -> String {
    if b.lo == 0.0 {
        format!("(0, {:.0e})", b.hi)
    } else if b.hi == ANGLE_RANGE.0 {
        format!("[{:.0e}, pi/2]", b.lo)
    } else {
        format!("[{:.0e}, {:.0e})", b.lo, b.hi)
    }
}

/// An error measure in a table cell: `inf`, `0`, two decimals in a middle range, else
/// scientific with three (the tables of `regress plane-plane` and of an FPCore suite).
pub fn cell(v: f64) -> String {
    if v.is_infinite() {
        "inf".into()
    } else if v == 0.0 {
        "0".into()
    } else if (1e-2..1e6).contains(&v) {
        format!("{v:.2}")
    } else {
        format!("{v:.3e}")
    }
}

impl fmt::Display for PlaneReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "plane-plane: published InterctionLineOf2Areas (f64) vs the exact construction, seed {}",
            self.seed
        )?;
        writeln!(
            f,
            "  {} cases measured, {} skipped (not a line exactly); the planes meet in a line, yet the function returned null {} times and a non-finite point {} times",
            self.measured, self.skipped, self.null_results, self.non_finite_results
        )?;
        writeln!(
            f,
            "  point Q: ulps of its largest coordinate; direction q: ulps of 1 (exact unit vector, sqrt to 256 bits)"
        )?;
        writeln!(
            f,
            "  {:>18}  {:>6}  {:>12}  {:>11}  {:>11}  {:>11}  {:>11}",
            "angle n1, n2 (rad)", "cases", "Q not finite", "Q max", "Q median", "q max", "q median"
        )?;
        for b in &self.bins {
            writeln!(
                f,
                "  {:>18}  {:>6}  {:>12}  {:>11}  {:>11}  {:>11}  {:>11}",
                bin_label(b),
                b.count,
                b.non_finite,
                cell(b.point_max),
                cell(b.point_median),
                cell(b.direction_max),
                cell(b.direction_median)
            )?;
        }
        write!(
            f,
            "  worst cases (by point error, then direction error; reproduce with the seed {} and the sample index):",
            self.seed
        )?;
        for (i, c, m) in &self.worst {
            write!(
                f,
                "\n    sample {i}: angle {:.3e} rad, Q {} ulps, q {} ulps; P1 = {:?}, n1 = {:?}, P2 = {:?}, n2 = {:?}",
                m.angle,
                cell(m.point_ulps),
                cell(m.direction_ulps),
                c.p1,
                c.n1,
                c.p2,
                c.n2
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bins_are_decades() {
        assert_eq!(bin_of(1.5), 0);
        assert_eq!(bin_of(0.1), 0);
        assert_eq!(bin_of(0.099), 1);
        assert_eq!(bin_of(2e-11), 10);
        assert_eq!(bin_of(1e-12 * 0.9), 11);
        assert_eq!(bin_of(1e-20), 11);
    }

    #[test]
    fn cases_are_reproducible_and_unit() {
        let a = sample_case(7, 3);
        assert_eq!(a, sample_case(7, 3));
        assert!((length(&a.n1) - 1.0).abs() < 1e-15 && (length(&a.n2) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn worst_cases_are_reproducible_from_seed_and_index() {
        let r = run(300, 4, 2);
        assert_eq!(r.measured + r.skipped, 300);
        assert_eq!(r.worst.len(), 2);
        for (i, c, m) in &r.worst {
            assert_eq!(*c, sample_case(4, *i));
            assert_eq!(measure(c), Some(*m));
        }
        assert!(r.worst[0].2.point_ulps >= r.worst[1].2.point_ulps);
        assert_eq!(r, run(300, 4, 2));
    }

    #[test]
    fn orthogonal_unit_planes_are_exact() {
        let m = measure(&PlaneCase {
            p1: [1.0, 5.0, 7.0],
            n1: [1.0, 0.0, 0.0],
            p2: [3.0, 2.0, -1.0],
            n2: [0.0, 1.0, 0.0],
        })
        .unwrap();
        assert_eq!(m.point_ulps, 0.0);
        assert_eq!(m.direction_ulps, 0.0);
        assert!((m.angle - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    }
}
