//! `exactcheck regress ruled-plane`: the f64 instantiation of Chiang's Theorem 1 (the plane
//! section of a ruled surface, [`RuledSurface::plane_section`]) against the exact one.
//!
//! # What is compared
//! The code under test is the generic theorem of `exactcheck-core`, instantiated at `f64`; the
//! reference is the same code at an exact rational type, on the same inputs converted exactly
//! from the doubles (the harness `exactcheck_float::regress`), so every difference is rounding
//! error of the f64 run. Two formulas per surface shape `(m, n)`:
//! * [`Part::Weights`]: the weights `w_0..w_{m+n}` (always defined);
//! * [`Part::Points`]: the control points `r_k = (w_k r_k) / w_k`, defined where every `w_k != 0`
//!   exactly (a sample with an exactly zero weight is counted "outside the exact domain").
//!
//! # Inputs
//! An input vector is `p_0..p_n` (3 coordinates each), `q_0..q_m`, then the plane `a, b, c, d`
//! ([`arity`]). Two regimes:
//! * **random** ([`random_gen`]): coordinates uniform in `[-10, 10]`, plane coefficients
//!   uniform in `[-1, 1]` and `d` in `[-10, 10]`;
//! * **near-degenerate** ([`near_degenerate_gen`]): an exactly degenerate configuration
//!   ([`DegenerateRuled`]) perturbed by relative `2^[-50, -20]` with
//!   [`exactcheck_float::NearDegenerate`]. The degenerate configurations are built with dyadic
//!   coordinates (multiples of 1/8 in `[-4, 4]`) so that the degeneracy holds *exactly in f64*:
//!   either the normal is orthogonal to one scaled control vector
//!   `Q_k = sum_{i+j=k} C(m,i) C(n,j) q_i` of the elevated direction field (the weight `w_k` is
//!   zero: the theorem's sum cancels), or orthogonal to the ruling direction `V(t0)` at
//!   `t0 in {1/4, 1/2, 3/4}` (the weight polynomial `N.V` has a root, a pole of the section,
//!   inside `[0, 1]`). After perturbation the weight is tiny and the float sum cancels
//!   catastrophically: the errors grow like the condition number `sum |terms| / |sum|`.
//!
//! Every worst case is reproducible: sample `i` of a run is
//! `exactcheck_float::sample_inputs(gen, seed, i)` with the generator of its row.

use crate::Error;
use exactcheck_core::ruled::{Plane, RuledSurface};
use exactcheck_core::{binomial, OrderedField, Ring, Vec3, ZeroDivisor};
use exactcheck_float::{
    regress, ExactScalar, Formula, GenError, InputGen, NearDegenerate, Options, RegressError,
    Report, Rng, UniformBox,
};
use serde_json::{json, Value};
use std::fmt::Write as _;

/// The surface shapes `(m, n)` the command regresses: direction field of degree `m`, base curve
/// of degree `n`.
pub const SHAPES: [(usize, usize); 3] = [(1, 2), (2, 3), (3, 5)];

/// The number of inputs for shape `(m, n)`: `3 (n + 1) + 3 (m + 1) + 4`.
pub fn arity(m: usize, n: usize) -> usize {
    3 * (n + 1) + 3 * (m + 1) + 4
}

/// The surface and plane encoded by an input vector of length [`arity`]`(m, n)`.
///
/// # Panics
/// When `x` is shorter than [`arity`]`(m, n)` (the harness only calls with that length).
pub fn decode<T: Ring>(m: usize, n: usize, x: &[T]) -> (RuledSurface<T>, Plane<T>) {
    let v = |i: usize| Vec3::new(x[3 * i].clone(), x[3 * i + 1].clone(), x[3 * i + 2].clone());
    let base: Vec<Vec3<T>> = (0..=n).map(v).collect();
    let dirs: Vec<Vec3<T>> = (n + 1..=n + 1 + m).map(v).collect();
    let o = 3 * (n + m + 2);
    let plane = Plane::new(
        x[o].clone(),
        x[o + 1].clone(),
        x[o + 2].clone(),
        x[o + 3].clone(),
    );
    let surface = RuledSurface::from_control(base, dirs)
        .expect("n + 1 >= 1 control points and m + 1 >= 1 control vectors");
    (surface, plane)
}

/// Which outputs of the section a kernel compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The weights `w_0..w_{m+n}`.
    Weights,
    /// The control points `r_0..r_{m+n}` (x, y, z each), defined where all `w_k != 0`.
    Points,
}

/// The section of a ruled surface of shape `(m, n)` by a plane, as a harness [`Formula`]
/// calling the generic [`RuledSurface::plane_section`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RuledPlaneKernel {
    /// Degree of the direction field.
    pub m: usize,
    /// Degree of the base curve.
    pub n: usize,
    /// The outputs compared.
    pub part: Part,
}

impl Formula for RuledPlaneKernel {
    fn name(&self) -> String {
        let what = match self.part {
            Part::Weights => "weights w_k",
            Part::Points => "points r_k",
        };
        format!(
            "ruled_plane (m, n) = ({}, {}): Chiang Theorem 1, {what}",
            self.m, self.n
        )
    }
    fn arity(&self) -> usize {
        arity(self.m, self.n)
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        let (surface, plane) = decode(self.m, self.n, x);
        let section = surface.plane_section(&plane);
        match self.part {
            Part::Weights => Ok(section.weights()),
            Part::Points => {
                let mut out = Vec::with_capacity(3 * section.control().len());
                for c in section.control() {
                    out.extend(c.to_point()?.into_array());
                }
                Ok(out)
            }
        }
    }
}

/// Random inputs of shape `(m, n)` (module doc).
///
/// # Errors
/// Never for the built-in bounds; the generator's validation error otherwise.
pub fn random_gen(m: usize, n: usize) -> Result<UniformBox, GenError> {
    let k = 3 * (n + m + 2);
    let mut lo = vec![-10.0; k];
    let mut hi = vec![10.0; k];
    lo.extend([-1.0, -1.0, -1.0, -10.0]);
    hi.extend([1.0, 1.0, 1.0, 10.0]);
    UniformBox::new(lo, hi)
}

/// Exactly degenerate configurations of shape `(m, n)`, in dyadic coordinates so the degeneracy
/// holds exactly in f64 (module doc): the base points of [`near_degenerate_gen`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DegenerateRuled {
    /// Degree of the direction field.
    pub m: usize,
    /// Degree of the base curve.
    pub n: usize,
}

/// A multiple of 1/8 in `[-4, 4]`.
fn dyadic(rng: &mut Rng) -> f64 {
    (rng.uniform(-32.0, 32.0)).round() / 8.0
}

impl InputGen for DegenerateRuled {
    fn arity(&self) -> usize {
        arity(self.m, self.n)
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        let (m, n) = (self.m, self.n);
        let mut x: Vec<f64> = (0..3 * (n + m + 2)).map(|_| dyadic(rng)).collect();
        let vec_at = |x: &[f64], i: usize| Vec3::new(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
        let q: Vec<Vec3<f64>> = (n + 1..=n + 1 + m).map(|i| vec_at(&x, i)).collect();
        let zero_weight = rng.chance(0.5);
        let k = rng.below((m + n + 1) as u64) as usize;
        let t0 = [0.25, 0.5, 0.75][rng.below(3) as usize];
        // The direction the normal must be orthogonal to. Both are exact in f64: small integer
        // multiples of dyadic vectors with few bits.
        let target = if zero_weight {
            let mut s = Vec3::new(0.0, 0.0, 0.0);
            for (i, qi) in q.iter().enumerate() {
                if k >= i && k - i <= n {
                    let c = binomial(m as u32, i as u32) * binomial(n as u32, (k - i) as u32);
                    s = s.add_scaled(&(c as f64), qi);
                }
            }
            s
        } else {
            exactcheck_core::BezierCurve::new(q).eval(&t0)
        };
        let u = Vec3::new(dyadic(rng), dyadic(rng), dyadic(rng));
        let normal = target.cross(&u);
        x.extend([normal.x, normal.y, normal.z, dyadic(rng)]);
        x
    }
    fn describe(&self) -> String {
        format!(
            "ruled_plane (m, n) = ({}, {}) degenerate: dyadic surface, normal orthogonal to a scaled elevated control vector (w_k = 0) or to V(t0), t0 in {{1/4, 1/2, 3/4}}",
            self.m, self.n
        )
    }
}

/// Near-degenerate inputs of shape `(m, n)`: [`DegenerateRuled`] perturbed by relative
/// `2^[-50, -20]` (each coordinate kept exact with probability 1/4).
///
/// # Errors
/// Never for the built-in exponents.
pub fn near_degenerate_gen(
    m: usize,
    n: usize,
) -> Result<NearDegenerate<DegenerateRuled>, GenError> {
    NearDegenerate::new(DegenerateRuled { m, n }, -50, -20)
}

/// The input regime of a row.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Regime {
    /// [`random_gen`].
    Random,
    /// [`near_degenerate_gen`].
    NearDegenerate,
}

impl Regime {
    /// `random` / `near-degenerate`.
    pub fn label(self) -> &'static str {
        match self {
            Regime::Random => "random",
            Regime::NearDegenerate => "near-degenerate",
        }
    }
}

/// One row of the table: a shape and a regime, with the reports of weights and points.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Degree of the direction field.
    pub m: usize,
    /// Degree of the base curve.
    pub n: usize,
    /// The input regime.
    pub regime: Regime,
    /// The weights' report.
    pub weights: Report,
    /// The points' report.
    pub points: Report,
}

/// Regresses weights and points of shape `(m, n)` on inputs from `gen`.
///
/// # Errors
/// As [`exactcheck_float::regress`] (an arity mismatch or invalid options).
pub fn regress_shape<E: ExactScalar>(
    m: usize,
    n: usize,
    gen: &(impl InputGen + ?Sized),
    samples: usize,
    seed: u64,
    options: &Options,
) -> Result<(Report, Report), RegressError> {
    let kernel = |part| RuledPlaneKernel { m, n, part };
    Ok((
        regress::<E>(&kernel(Part::Weights), gen, samples, seed, options)?,
        regress::<E>(&kernel(Part::Points), gen, samples, seed, options)?,
    ))
}

/// Every row: each shape of [`SHAPES`] on random and near-degenerate inputs.
///
/// # Errors
/// [`Error::Usage`] when the harness refuses the options.
pub fn rows<E: ExactScalar>(
    samples: usize,
    seed: u64,
    options: &Options,
) -> Result<Vec<Row>, Error> {
    let usage = |e: &dyn std::fmt::Display| Error::Usage(e.to_string());
    let mut out = Vec::new();
    for (m, n) in SHAPES {
        for regime in [Regime::Random, Regime::NearDegenerate] {
            let (weights, points) = match regime {
                Regime::Random => {
                    let gen = random_gen(m, n).map_err(|e| usage(&e))?;
                    regress_shape::<E>(m, n, &gen, samples, seed, options)
                }
                Regime::NearDegenerate => {
                    let gen = near_degenerate_gen(m, n).map_err(|e| usage(&e))?;
                    regress_shape::<E>(m, n, &gen, samples, seed, options)
                }
            }
            .map_err(|e| usage(&e))?;
            out.push(Row {
                m,
                n,
                regime,
                weights,
                points,
            });
        }
    }
    Ok(out)
}

fn measure(v: f64) -> String {
    if v.is_infinite() {
        "inf".into()
    } else if v == 0.0 {
        "0".into()
    } else if (1e-2..1e5).contains(&v) {
        let s = format!("{v:.2}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.2e}")
    }
}

/// The table of the rows (Markdown), max and median errors in ulps.
pub fn table(rows: &[Row]) -> String {
    let mut s = String::from(
        "| (m, n) | inputs | compared (weights / points) | weights: max ulps | weights: median | points: max ulps | points: median | points > 1000 ulps | exact w_k = 0 (skipped) |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let big = r
            .points
            .above
            .iter()
            .find(|t| t.ulps == 1e3)
            .map_or_else(|| "-".into(), |t| t.count.to_string());
        let _ = writeln!(
            s,
            "| ({}, {}) | {} | {} / {} | {} | {} | {} | {} | {} | {} |",
            r.m,
            r.n,
            r.regime.label(),
            r.weights.compared,
            r.points.compared,
            measure(r.weights.max_ulps),
            measure(r.weights.median_ulps),
            measure(r.points.max_ulps),
            measure(r.points.median_ulps),
            big,
            r.points.domain_errors
        );
    }
    s
}

/// A measure as JSON: a number, or the string `"inf"` (JSON has no infinity).
/// The rows as one JSON document.
pub fn rows_json(rows: &[Row]) -> Value {
    json!({
        "kernel": "ruled-plane",
        "rows": rows.iter().map(|r| json!({
            "m": r.m,
            "n": r.n,
            "inputs": r.regime.label(),
            "weights": r.weights.to_json(),
            "points": r.points.to_json(),
        })).collect::<Vec<_>>(),
    })
}

/// The text output: the table, then each report (worst cases with their sample index).
pub fn text(rows: &[Row], seed: u64) -> String {
    let mut s = format!(
        "regress ruled-plane: Chiang Theorem 1 in f64 vs exact, seed {seed} (sample i of a row: sample_inputs(row generator, {seed}, i))\n\n"
    );
    s.push_str(&table(rows));
    for r in rows {
        let _ = write!(
            s,
            "\n## ({}, {}) {}\n{}\n{}",
            r.m,
            r.n,
            r.regime.label(),
            r.weights,
            r.points
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_exact::Rational;

    #[test]
    fn degenerate_base_points_are_exactly_degenerate() {
        // The dyadic construction must make a weight, or N.V(t0), exactly zero.
        for (m, n) in SHAPES {
            let gen = DegenerateRuled { m, n };
            let mut rng = Rng::new(5);
            for _ in 0..200 {
                let x = gen.sample(&mut rng);
                let q: Vec<Rational> = x
                    .iter()
                    .map(|&v| Rational::from_f64_exact(v).unwrap())
                    .collect();
                let (s, plane) = decode(m, n, &q);
                let nv = s.normal_component(&plane);
                let weights = s.plane_section(&plane).weights();
                let pole = [(1, 4), (1, 2), (3, 4)]
                    .iter()
                    .any(|&(a, b)| nv.eval(&Rational::new(a, b).unwrap()).is_zero());
                assert!(
                    pole || weights.iter().any(Ring::is_zero),
                    "{x:?} is not degenerate"
                );
            }
        }
    }

    #[test]
    fn kernel_outputs_match_the_theorem_and_the_domain_excludes_zero_weights() {
        let x = exactcheck_float::sample_inputs(&random_gen(1, 2).unwrap(), 9, 0);
        let k = |part| RuledPlaneKernel { m: 1, n: 2, part };
        let w = k(Part::Weights).eval::<f64>(&x).unwrap();
        let p = k(Part::Points).eval::<f64>(&x).unwrap();
        assert_eq!((w.len(), p.len()), (4, 12));
        // w_0 = N.q_0.
        let o = 3 * 5;
        let w0 = x[o] * x[9] + x[o + 1] * x[10] + x[o + 2] * x[11];
        assert!((w[0] - w0).abs() <= 1e-12 * w0.abs().max(1.0));
        // q_0 in the plane's direction space: w_0 = 0, the points are undefined.
        let mut y = x.clone();
        let normal = [y[10], -y[9], 0.0];
        y[o..o + 3].copy_from_slice(&normal);
        let yq: Vec<Rational> = y
            .iter()
            .map(|&v| Rational::from_f64_exact(v).unwrap())
            .collect();
        assert_eq!(k(Part::Points).eval(&yq), Err(ZeroDivisor));
    }

    #[test]
    fn rows_are_deterministic_and_degenerate_inputs_are_worse() {
        let options = Options {
            worst: 1,
            ..Options::default()
        };
        let a = rows::<Rational>(300, 4, &options).unwrap();
        assert_eq!(a, rows::<Rational>(300, 4, &options).unwrap());
        assert_eq!(a.len(), 2 * SHAPES.len());
        for pair in a.chunks(2) {
            let (random, near) = (&pair[0], &pair[1]);
            assert!(random.points.compared > 250, "{}", table(&a));
            assert!(near.points.max_ulps > 1e3 * random.points.max_ulps.max(1.0));
        }
        let t = table(&a);
        assert_eq!(t.lines().count(), 2 + a.len());
        let j = rows_json(&a);
        assert_eq!(j["rows"].as_array().unwrap().len(), a.len());
    }
}
