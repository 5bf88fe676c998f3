//! `solve` kind `ruled_line`: where a line `P + lambda D` meets the ruled surface
//! `S(s,t) = B(t) + s V(t)` (Chiang, section II.B).
//!
//! # Method
//! The ruling `t` meets the line iff `B(t) - P`, `V(t)` and `D` are linearly dependent:
//! `f(t) = det(B(t) - P, V(t), D) = 0`, a polynomial of degree `m + n`
//! ([`RuledSurface::line_polynomial`]; Chiang's `B_y V_z - B_z V_y` after moving the line onto
//! the x axis, claim `chiang.line`). Its distinct real roots in `[0, 1]` are isolated exactly by
//! Bernstein–Descartes subdivision ([`exactcheck_core::roots`]): a rational root (in the field of
//! the input) is found `Exact`, any other is an isolating interval refined to width `2^-60`.
//! At each root, with `W(t) = V(t) x D` and `U(t) = (B(t) - P) x D`:
//! * `W(t) != 0` (the ruling is not parallel to the line): one point, with
//!   `s = -((B - P) x D) . W / |W|^2` and `lambda = (X - P) . D / |D|^2` — exact at an exact
//!   root, approximations (computed at the midpoint of the refined interval) at an interval root;
//! * `W(t) = 0`, `V(t) != 0` (the ruling is parallel to the line, so `f(t) = 0` without a
//!   meeting point): the whole ruling is the line when `U(t) = 0`, otherwise no point;
//! * `V(t) = 0` (the ruling degenerates to the point `B(t)`): the point `B(t)` when it lies on
//!   the line (`U(t) = 0`; `s` is arbitrary), otherwise no point.
//!
//! At an interval root "`W(t) = 0`" is decided exactly: `gcd(f, W_x, W_y, W_z)` divides `f`, so
//! it can vanish in the isolating interval only at `f`'s one root there, and it does iff its
//! square-free part changes sign across the interval. Nothing divides by a quantity that may be
//! zero.
//!
//! A root with status `ruling_on_line` puts the whole line on the surface: the outcome is then
//! `line_on_surface`; otherwise `points` when some root gives a point, else `no_points`.
//!
//! # The covered part (when `f` is identically zero)
//! Then every ruling meets the line or is parallel to it, possibly all at one point (a cone
//! whose apex is on the line). The answer is the set of `lambda` covered by the rulings
//! `t` in `[0, 1]` (`covered`: disjoint intervals, increasing, each end exact or enclosed at an
//! irrational parameter, `closed` when covered itself, `null` when unbounded; `lambda_at_ends`
//! its least and largest end), decided exactly:
//! * If `W` is identically zero too, every ruling is parallel to the line
//!   (`parallel_to_every_ruling`): at a common zero `z` of `U` the ruling is the line when
//!   `V(z) != 0` (listed in `rulings_on_line`; the whole line is covered), and only the point
//!   `B(z)` when `V(z) = 0`.
//! * Otherwise, off the zeros of `W`, the ruling `t` meets the line at
//!   `lambda(t) = N / Q`, `N = -((B - P) x V) . W`, `Q = |W|^2`, reduced by `gcd(N, Q)` to
//!   `N1 / Q1`. At a zero `z` of `W` the ruling is the line (`V(z) != 0`, `U(z) = 0`: the whole
//!   line), the point `B(z)` (`V(z) = 0`, `U(z) = 0`), or nothing. The breakpoints are the
//!   zeros in `[0, 1]` of `c1 = N1' Q1 - N1 Q1'` and of `W` (one polynomial, isolated exactly),
//!   and `0`, `1`; between two of them `lambda` is continuous and strictly monotone (the sign of
//!   `c1` at a point between them), so each stretch covers the interval between its end values:
//!   `lambda` itself at a breakpoint off the zeros of `W` (covered), its limit `N1 / Q1` at a
//!   zero of `W` (not covered by that stretch), unbounded at a pole (`Q1 = 0`). If `c1` is zero,
//!   `lambda` is one constant. The stretches and the points `B(z)` are merged into disjoint
//!   intervals; end values are compared exactly (equal at one breakpoint; at one zero of `W` by
//!   the sign of the cross-multiplied difference there; otherwise by enclosures from the
//!   Bernstein coefficients of `N1`, `Q1` on the parameter's interval, narrowed until they
//!   separate). Two irrational end values still not ordered after `COMPARE_STEPS` halvings
//!   give the outcome `undecided` with a note.
//!
//! The outcome then names the covered part: `line_on_surface` (all of the line),
//! `line_segment_on_surface` (an interval of positive length, possibly unbounded, possibly
//! several), `single_point`, `isolated_points`.
//!
//! # Limits and modes
//! `m + n <= 60` ([`MAX_DEGREE`]): the Bernstein conversions use binomials `C(m+n, k)` as `u64`,
//! exact only up to `C(67, 33)`, and the exact subdivision grows quickly beyond that degree.
//! Exact mode is further held to the `ruled-work` limit, checked before any work: `m + n` times
//! the dimension `2^k` of the square-root field of the input's numbers (the subdivision's cost
//! grows about as the sixth power of the degree and several-fold per square root).
//! Exact mode reads [`ExactNumber`]s and runs over `Q` when every number is rational, over the
//! radical field otherwise. `--float` runs the same generic code over `f64`; there the zero
//! tests and the root isolation are heuristics (f64 rounding), and the answer says `mode: float`.
//!
//! Hand-written because it is the workspace's own construction (the generic surface and the
//! generic root isolation); no crate solves it exactly.

use super::number::{Coords, ExactNumber, FieldNumber, FloatNumber};
use super::{FloatKind, Kind};
use crate::Error;
use exactcheck_core::ruled::RuledSurface;
use exactcheck_core::{OrderedField, Vec3};
use exactcheck_exact::algebraic::FieldElement;
use exactcheck_exact::{Radical, Rational};
use schemars::JsonSchema;
use serde::Deserialize;

mod analysis;
mod answer;
mod covered;

use analysis::{analyse, Analysis};
use answer::{render, AnswerOut};

/// The largest `m + n` answered (module doc, "Limits").
pub const MAX_DEGREE: usize = 60;

/// The problem, with numbers of type `N` ([`ExactNumber`] in exact mode, [`FloatNumber`] with
/// `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "ruled_line",
    description = "A ruled surface S(s,t) = B(t) + s V(t) (Bezier base curve B of degree n, Bezier direction field V of degree m) and a line P + lambda D (Chiang): the parameters t in [0,1] whose ruling meets the line (roots of det(B(t) - P, V(t), D), degree m+n <= 60), with s, lambda and the point. Outcomes: points, no_points, line_on_surface (a ruling is the line, or the rulings cover all of it), line_segment_on_surface / single_point / isolated_points (det vanishes identically: the covered part of the line, decided exactly, in `covered` and `lambda_at_ends`), parallel_to_every_ruling, undecided (with a note)."
)]
pub struct Input<N> {
    /// `"ruled_line"`.
    #[schemars(extend("const" = "ruled_line"))]
    pub kind: String,
    /// The control points `p_0..p_n` of the base curve `B` (at least one).
    pub base: Vec<Coords<N, 3>>,
    /// The control vectors `q_0..q_m` of the direction field `V` (at least one).
    pub directions: Vec<Coords<N, 3>>,
    /// The line.
    pub line: LineInput<N>,
}

/// The line `point + lambda direction`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LineInput<N> {
    /// A point `P` of the line.
    pub point: Coords<N, 3>,
    /// The direction `D` (not zero).
    pub direction: Coords<N, 3>,
}

// ------------------------------------------------------------------ input checks

struct Problem<T> {
    surface: RuledSurface<T>,
    point: Vec3<T>,
    direction: Vec3<T>,
}

fn vec3<N: Clone, T>(c: &Coords<N, 3>, f: impl Fn(&N) -> T) -> Vec3<T> {
    let [x, y, z] = &c.0;
    Vec3::new(f(x), f(y), f(z))
}

fn build<N: Clone, T: OrderedField>(
    input: &Input<N>,
    f: impl Fn(&N) -> T + Copy,
) -> Result<Problem<T>, Error> {
    if input.base.is_empty() {
        return Err(Error::Input(
            "base: at least one control point is required".into(),
        ));
    }
    if input.directions.is_empty() {
        return Err(Error::Input(
            "directions: at least one control vector is required".into(),
        ));
    }
    let (n, m) = (input.base.len() - 1, input.directions.len() - 1);
    if m + n > MAX_DEGREE {
        return Err(Error::Input(format!(
            "base, directions: the degree m + n = {m} + {n} = {} exceeds the limit {MAX_DEGREE}",
            m + n
        )));
    }
    let direction = vec3(&input.line.direction, f);
    if direction.is_zero() {
        return Err(Error::Input(
            "line.direction: the zero vector gives no line".into(),
        ));
    }
    let base: Vec<Vec3<T>> = input.base.iter().map(|c| vec3(c, f)).collect();
    let dirs: Vec<Vec3<T>> = input.directions.iter().map(|c| vec3(c, f)).collect();
    if dirs.iter().all(Vec3::is_zero) {
        return Err(Error::Input(
            "directions: every control vector is zero, so the surface is the curve B, not a ruled surface".into(),
        ));
    }
    let surface =
        RuledSurface::from_control(base, dirs).expect("both lists were checked to be non-empty");
    Ok(Problem {
        surface,
        point: vec3(&input.line.point, f),
        direction,
    })
}

fn exact_answer(input: Input<ExactNumber>) -> Result<AnswerOut<String>, Error> {
    let all_rational = input
        .base
        .iter()
        .chain(&input.directions)
        .chain([&input.line.point, &input.line.direction])
        .all(|c| c.0.iter().all(|x| x.0.is_rational()));
    let k = Radical::independent_radicals_together(
        input
            .base
            .iter()
            .chain(&input.directions)
            .chain([&input.line.point, &input.line.direction])
            .flat_map(|c| c.0.iter().map(|x| &x.0)),
    );
    // Checked before the work; an empty list or a degree past MAX_DEGREE is refused by `build`.
    let degree = (input.base.len() + input.directions.len()).saturating_sub(2);
    if !input.base.is_empty() && !input.directions.is_empty() && degree <= MAX_DEGREE {
        let work = (degree as u64).saturating_mul(1u64 << k.min(62));
        crate::limits::RULED_WORK.check(work).map_err(|e| {
            Error::Input(format!(
                "base, directions: m + n = {degree} with {k} independent square roots: {e}"
            ))
        })?;
    }
    if all_rational {
        let p = build(&input, |x: &ExactNumber| {
            x.0.to_rational().expect("is_rational was checked")
        })?;
        let a: Analysis<Rational> = analyse(&p.surface, &p.point, &p.direction);
        Ok(render(&a, "exact", ToString::to_string))
    } else {
        let p = build(&input, |x: &ExactNumber| x.0.clone())?;
        let a: Analysis<Radical> = analyse(&p.surface, &p.point, &p.direction);
        Ok(render(&a, "exact", ToString::to_string))
    }
}

fn float_answer(input: Input<FloatNumber>) -> Result<AnswerOut<f64>, Error> {
    let p = build(&input, |x: &FloatNumber| x.0)?;
    let a: Analysis<f64> = analyse(&p.surface, &p.point, &p.direction);
    Ok(render(&a, "float", |x: &f64| *x + 0.0))
}

/// The kind.
pub struct RuledLine;

impl Kind for RuledLine {
    const NAME: &'static str = "ruled_line";
    type Input = Input<ExactNumber>;
    type Answer = AnswerOut<String>;

    fn compute(input: Self::Input) -> Result<Self::Answer, Error> {
        exact_answer(input)
    }

    /// In the problem's number field of degree `d`, the work bound is `(m + n) d`, as it is
    /// `(m + n) 2^k` in the radical field of degree `2^k`.
    fn compute_in_field(problem: &super::Problem) -> Result<Self::Answer, Error> {
        let input: Input<FieldNumber> = problem.input_in_field(&[])?;
        let d = input
            .base
            .iter()
            .chain(&input.directions)
            .chain([&input.line.point, &input.line.direction])
            .flat_map(|c| c.0.iter())
            .find_map(|x| x.0.field().map(|f| f.degree()))
            .unwrap_or(1);
        let degree = (input.base.len() + input.directions.len()).saturating_sub(2);
        if !input.base.is_empty() && !input.directions.is_empty() && degree <= MAX_DEGREE {
            crate::limits::RULED_WORK
                .check((degree as u64).saturating_mul(d as u64))
                .map_err(|e| {
                    Error::Input(format!(
                        "base, directions: m + n = {degree} in a number field of degree {d}: {e}"
                    ))
                })?;
        }
        let p = build(&input, |x: &FieldNumber| x.0.clone())?;
        let a: Analysis<FieldElement> = analyse(&p.surface, &p.point, &p.direction);
        Ok(render(&a, "exact", ToString::to_string))
    }
}

impl FloatKind for RuledLine {
    type FloatInput = Input<FloatNumber>;
    type FloatAnswer = AnswerOut<f64>;

    fn compute_float(input: Self::FloatInput) -> Result<Self::FloatAnswer, Error> {
        float_answer(input)
    }
}

impl super::FloatSlot for AnswerOut<String> {
    type Float = AnswerOut<f64>;
    fn float_slot(&mut self) -> &mut Option<Box<AnswerOut<f64>>> {
        &mut self.float
    }
}
