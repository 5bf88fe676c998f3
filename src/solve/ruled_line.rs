//! `solve` kind `ruled_line`: where a line `P + lambda D` meets the ruled surface
//! `S(s,t) = B(t) + s V(t)` (Chiang, seed 004, section II.B; SPEC §4).
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
//! When `f` is identically zero every ruling meets or is parallel to the line: if `W` is
//! identically zero too, every ruling is parallel to the line (`parallel_to_every_ruling`; the
//! line is itself the ruling at the common roots of `U`, listed), otherwise all but finitely many
//! rulings cross the line, so a segment of the line lies on the surface (`line_on_surface`, with
//! `lambda` at the ends `t = 0, 1` where defined).
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

use super::number::{Coords, ExactNumber, FloatNumber};
use super::{by_mode, parse, Kind, Mode, Printable};
use crate::Error;
use exactcheck_core::roots::{
    gcd, multiplicity, refine, square_free, unit_roots, IsolatedRoot, ZeroPolynomial,
};
use exactcheck_core::ruled::RuledSurface;
use exactcheck_core::{Bernstein, Field, OrderedField, Ring, Sign, Vec3};
use exactcheck_exact::univariate::UPoly;
use exactcheck_exact::{Radical, Rational};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use serde_json::Value;

/// The largest `m + n` answered (module doc, "Limits").
pub const MAX_DEGREE: usize = 60;

/// The problem, with numbers of type `N` ([`ExactNumber`] in exact mode, [`FloatNumber`] with
/// `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "ruled_line",
    description = "A ruled surface S(s,t) = B(t) + s V(t) (Bezier base curve B of degree n, Bezier direction field V of degree m) and a line P + lambda D (Chiang, SPEC §4): the parameters t in [0,1] whose ruling meets the line (roots of det(B(t) - P, V(t), D), degree m+n <= 60), with s, lambda and the point; degenerate cases as typed outcomes."
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

/// A scalar the answer is computed in: exact (`Rational`, `Radical`) or `f64`, with its root
/// isolation in `[0, 1]`.
trait Scalar: OrderedField {
    fn text(&self) -> String;
    fn approx(&self) -> f64;
    /// The distinct roots of `p` in `[0, 1]`.
    fn roots(p: &Bernstein<Self>) -> Result<Vec<IsolatedRoot<Self>>, ZeroPolynomial> {
        unit_roots(p)
    }
}

impl Scalar for Radical {
    fn text(&self) -> String {
        self.to_string()
    }
    fn approx(&self) -> f64 {
        Printable::approx(self)
    }
}

/// Over `Q` the Sturm isolation of `exactcheck_exact::univariate` is used: it returns every
/// rational root exactly (Bernstein subdivision finds exactly only the dyadic ones), so a line
/// through `S(s, t)` with rational `t` gets its point exactly.
impl Scalar for Rational {
    fn text(&self) -> String {
        self.to_string()
    }
    fn approx(&self) -> f64 {
        Printable::approx(self)
    }
    fn roots(p: &Bernstein<Self>) -> Result<Vec<IsolatedRoot<Self>>, ZeroPolynomial> {
        use std::cmp::Ordering;
        let u = UPoly::from_coeffs(p.to_power());
        if u.is_zero() {
            return Err(ZeroPolynomial);
        }
        Ok(u.isolate_roots()
            .into_iter()
            .filter(|ri| {
                u.compare_with_root(ri, &Rational::ZERO) != Ordering::Greater
                    && u.compare_with_root(ri, &Rational::ONE) != Ordering::Less
            })
            .map(|ri| match ri.exact_value() {
                Some(t) => IsolatedRoot::Exact(t.clone()),
                None => IsolatedRoot::Between(ri.lo, ri.hi),
            })
            .collect())
    }
}

impl Scalar for f64 {
    fn text(&self) -> String {
        format!("{self:?}")
    }
    fn approx(&self) -> f64 {
        *self + 0.0
    }
}

/// What happens at one root of the line polynomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Status {
    /// The ruling crosses the line at one point.
    Point,
    /// The ruling is parallel to the line and is the line itself.
    RulingOnLine,
    /// The ruling is parallel to the line and apart from it: no point.
    RulingParallel,
    /// `V(t) = 0`: the ruling is the point `B(t)`, which lies on the line (`s` arbitrary).
    DegenerateRulingOnLine,
    /// `V(t) = 0` and `B(t)` is not on the line: no point.
    DegenerateRulingOffLine,
}

impl Status {
    fn name(self) -> &'static str {
        match self {
            Status::Point => "point",
            Status::RulingOnLine => "ruling_on_line",
            Status::RulingParallel => "ruling_parallel",
            Status::DegenerateRulingOnLine => "degenerate_ruling_on_line",
            Status::DegenerateRulingOffLine => "degenerate_ruling_off_line",
        }
    }
}

/// One root with what was computed there (exact when `exact`, else at the refined midpoint).
struct RootReport<T> {
    root: IsolatedRoot<T>,
    multiplicity: usize,
    status: Status,
    /// Whether `s`, `lambda` and the point are exact.
    exact: bool,
    s: Option<T>,
    lambda: Option<T>,
    point: Option<Vec3<T>>,
}

enum Outcome<T> {
    /// `f` is not identically zero: its roots in [0, 1].
    Roots(Vec<RootReport<T>>),
    /// `f = 0` and `W = 0`: every ruling is parallel to the line; the line is the ruling at
    /// these roots of `U` (all `t` when `U = 0` too, `None`).
    ParallelToEveryRuling(Option<Vec<IsolatedRoot<T>>>),
    /// `f = 0`, `W != 0`: a segment of the line lies on the surface; `lambda` at `t = 0, 1`
    /// (`None` where the ruling there is parallel to the line).
    LineOnSurface([Option<T>; 2]),
}

struct Analysis<T> {
    m: usize,
    n: usize,
    polynomial: Bernstein<T>,
    outcome: Outcome<T>,
}

fn dot3<T: Ring>(a: &[Bernstein<T>; 3], d: &Vec3<T>) -> [Bernstein<T>; 3] {
    // a x d, componentwise polynomials.
    let comb = |p: &Bernstein<T>, s: &T, q: &Bernstein<T>, r: &T| {
        Bernstein::new(
            p.coeffs()
                .iter()
                .zip(q.coeffs())
                .map(|(x, y)| x.mul_ref(s) - y.mul_ref(r))
                .collect(),
        )
    };
    [
        comb(&a[1], &d.z, &a[2], &d.y),
        comb(&a[2], &d.x, &a[0], &d.z),
        comb(&a[0], &d.y, &a[1], &d.x),
    ]
}

/// Whether every polynomial of `others` vanishes at the root `root` of `p` (`p` not zero).
fn vanishes_at<T: OrderedField>(
    p: &Bernstein<T>,
    others: &[Bernstein<T>],
    root: &IsolatedRoot<T>,
) -> bool {
    if others.iter().all(Bernstein::is_zero) {
        return true;
    }
    match root {
        IsolatedRoot::Exact(t) => others.iter().all(|q| q.eval(t).is_zero()),
        IsolatedRoot::Between(lo, hi) => {
            let mut all = vec![p.clone()];
            all.extend(others.iter().cloned());
            let g = gcd(&all).expect("p is not identically zero");
            if g.degree() == 0 {
                return false;
            }
            let q = square_free(&g).expect("a gcd of non-zero polynomials is not zero");
            let (a, b) = (q.eval(lo).sign(), q.eval(hi).sign());
            a != b && a != Sign::Zero && b != Sign::Zero
        }
    }
}

fn analyse<T: Scalar>(
    surface: &RuledSurface<T>,
    point: &Vec3<T>,
    direction: &Vec3<T>,
) -> Analysis<T> {
    let (m, n) = surface.degrees();
    let f = surface.line_polynomial(point, direction);
    let v = surface.directions().coordinates();
    let b = surface.base().coordinates();
    let shifted = [
        shift(&b[0], &point.x),
        shift(&b[1], &point.y),
        shift(&b[2], &point.z),
    ];
    let w = dot3(&v, direction);
    let u = dot3(&shifted, direction);
    let dd = direction.norm_squared();
    let lambda_of = |x: &Vec3<T>| {
        x.add_scaled(&T::from_i64(-1), point)
            .dot(direction)
            .checked_div(&dd)
            .expect("the direction was checked to be non-zero")
    };
    let outcome = match T::roots(&f) {
        Err(_) => {
            if w.iter().all(Bernstein::is_zero) {
                Outcome::ParallelToEveryRuling(exactcheck_core::roots::common_unit_roots(&u).ok())
            } else {
                let at = |t: T| meeting(surface, point, direction, &t).map(|x| lambda_of(&x));
                Outcome::LineOnSurface([at(T::zero()), at(T::one())])
            }
        }
        Ok(roots) => {
            let width = T::from_ratio(1, 1 << 60).expect("2^60 is not zero");
            let mut reports = Vec::new();
            for root in roots {
                let root = refine(&f, &root, &width);
                let parallel = vanishes_at(&f, &w, &root);
                let zero_v = parallel && vanishes_at(&f, &v, &root);
                let on_line = parallel && vanishes_at(&f, &u, &root);
                let status = match (parallel, zero_v, on_line) {
                    (false, _, _) => Status::Point,
                    (true, false, true) => Status::RulingOnLine,
                    (true, false, false) => Status::RulingParallel,
                    (true, true, true) => Status::DegenerateRulingOnLine,
                    (true, true, false) => Status::DegenerateRulingOffLine,
                };
                let t = root.midpoint();
                let (s, lambda, x) = match status {
                    Status::Point => {
                        let s = ruling_parameter(surface, point, direction, &t);
                        match s {
                            Some(s) => {
                                let x = surface.eval(&s, &t);
                                (Some(s), Some(lambda_of(&x)), Some(x))
                            }
                            // Only at an interval midpoint of a root whose W is tiny in f64.
                            None => (None, None, None),
                        }
                    }
                    Status::DegenerateRulingOnLine => {
                        let x = surface.base().eval(&t);
                        (None, Some(lambda_of(&x)), Some(x))
                    }
                    _ => (None, None, None),
                };
                reports.push(RootReport {
                    multiplicity: multiplicity(&f, &root),
                    exact: root.exact().is_some(),
                    root,
                    status,
                    s,
                    lambda,
                    point: x,
                });
            }
            Outcome::Roots(reports)
        }
    };
    Analysis {
        m,
        n,
        polynomial: f,
        outcome,
    }
}

fn shift<T: Ring>(p: &Bernstein<T>, c: &T) -> Bernstein<T> {
    Bernstein::new(p.coeffs().iter().map(|x| x.sub_ref(c)).collect())
}

/// `s = -((B - P) x D) . (V x D) / |V x D|^2` at `t`: the ruling parameter of the meeting point;
/// `None` when `V(t) x D = 0` at this `t`.
fn ruling_parameter<T: Field>(
    surface: &RuledSurface<T>,
    point: &Vec3<T>,
    direction: &Vec3<T>,
    t: &T,
) -> Option<T> {
    let w = surface.directions().eval(t).cross(direction);
    let u = surface
        .base()
        .eval(t)
        .add_scaled(&T::from_i64(-1), point)
        .cross(direction);
    u.dot(&w).neg_ref().checked_div(&w.norm_squared()).ok()
}

/// The meeting point of ruling `t` with the line (when not parallel).
fn meeting<T: Field>(
    surface: &RuledSurface<T>,
    point: &Vec3<T>,
    direction: &Vec3<T>,
    t: &T,
) -> Option<Vec3<T>> {
    ruling_parameter(surface, point, direction, t).map(|s| surface.eval(&s, t))
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

// ------------------------------------------------------------------ answers

/// A root parameter: exact value or isolating interval, with an approximation.
#[derive(Debug, Serialize)]
struct ParamOut<S> {
    #[serde(skip_serializing_if = "Option::is_none")]
    value: Option<S>,
    #[serde(skip_serializing_if = "Option::is_none")]
    interval: Option<[S; 2]>,
    approx: f64,
}

#[derive(Debug, Serialize)]
struct RootOut<S> {
    t: ParamOut<S>,
    multiplicity: usize,
    status: &'static str,
    /// Whether `s`, `lambda` and `point` are exact (else approximations at the midpoint of
    /// the isolating interval of width <= 2^-60).
    exact: bool,
    s: Option<S>,
    lambda: Option<S>,
    point: Option<[S; 3]>,
    approx: PointApprox,
}

#[derive(Debug, Serialize)]
struct PointApprox {
    s: Option<f64>,
    lambda: Option<f64>,
    point: Option<[f64; 3]>,
}

#[derive(Debug, Serialize)]
struct AnswerOut<S> {
    kind: &'static str,
    mode: &'static str,
    m: usize,
    n: usize,
    degree: usize,
    /// The Bernstein coefficients of `det(B(t) - P, V(t), D)`, degree `m + n`.
    polynomial: Vec<S>,
    outcome: &'static str,
    points: Vec<RootOut<S>>,
    /// `parallel_to_every_ruling`: the roots `t` whose ruling is the line (`null`: every ruling).
    #[serde(skip_serializing_if = "Option::is_none")]
    rulings_on_line: Option<Option<Vec<ParamOut<S>>>>,
    /// `line_on_surface`: `lambda` of the meeting points of the rulings `t = 0` and `t = 1`
    /// (`null` at an end whose ruling is parallel to the line, so meets it nowhere or everywhere).
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_at_ends: Option<[Option<S>; 2]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<Box<AnswerOut<f64>>>,
}

fn param<T: Scalar, S>(r: &IsolatedRoot<T>, out: &impl Fn(&T) -> S) -> ParamOut<S> {
    match r {
        IsolatedRoot::Exact(t) => ParamOut {
            value: Some(out(t)),
            interval: None,
            approx: t.approx(),
        },
        IsolatedRoot::Between(lo, hi) => ParamOut {
            value: None,
            interval: Some([out(lo), out(hi)]),
            approx: r.midpoint().approx(),
        },
    }
}

fn render<T: Scalar, S>(
    a: &Analysis<T>,
    mode: &'static str,
    out: impl Fn(&T) -> S,
) -> AnswerOut<S> {
    let v3 = |x: &Vec3<T>| [out(&x.x), out(&x.y), out(&x.z)];
    let a3 = |x: &Vec3<T>| [x.x.approx(), x.y.approx(), x.z.approx()];
    let mut answer = AnswerOut {
        kind: "ruled_line",
        mode,
        m: a.m,
        n: a.n,
        degree: a.m + a.n,
        polynomial: a.polynomial.coeffs().iter().map(&out).collect(),
        outcome: "",
        points: Vec::new(),
        rulings_on_line: None,
        lambda_at_ends: None,
        float: None,
    };
    match &a.outcome {
        Outcome::Roots(reports) => {
            answer.outcome = if reports.iter().any(|r| r.point.is_some()) {
                "points"
            } else {
                "no_points"
            };
            answer.points = reports
                .iter()
                .map(|r| RootOut {
                    t: param(&r.root, &out),
                    multiplicity: r.multiplicity,
                    status: r.status.name(),
                    exact: r.exact,
                    s: r.s.as_ref().filter(|_| r.exact).map(&out),
                    lambda: r.lambda.as_ref().filter(|_| r.exact).map(&out),
                    point: r.point.as_ref().filter(|_| r.exact).map(v3),
                    approx: PointApprox {
                        s: r.s.as_ref().map(Scalar::approx),
                        lambda: r.lambda.as_ref().map(Scalar::approx),
                        point: r.point.as_ref().map(a3),
                    },
                })
                .collect();
        }
        Outcome::ParallelToEveryRuling(roots) => {
            answer.outcome = "parallel_to_every_ruling";
            answer.rulings_on_line = Some(
                roots
                    .as_ref()
                    .map(|rs| rs.iter().map(|r| param(r, &out)).collect()),
            );
        }
        Outcome::LineOnSurface(ends) => {
            answer.outcome = "line_on_surface";
            answer.lambda_at_ends = Some([ends[0].as_ref().map(&out), ends[1].as_ref().map(&out)]);
        }
    }
    answer
}

fn exact_answer(text: &str) -> Result<AnswerOut<String>, Error> {
    let input: Input<ExactNumber> = parse(text)?;
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
        exactcheck_core::limits::RULED_WORK
            .check(work)
            .map_err(|e| {
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
        Ok(render(&a, "exact", Scalar::text))
    } else {
        let p = build(&input, |x: &ExactNumber| x.0.clone())?;
        let a: Analysis<Radical> = analyse(&p.surface, &p.point, &p.direction);
        Ok(render(&a, "exact", Scalar::text))
    }
}

fn float_answer(text: &str) -> Result<AnswerOut<f64>, Error> {
    let input: Input<FloatNumber> = parse(text)?;
    let p = build(&input, |x: &FloatNumber| x.0)?;
    let a: Analysis<f64> = analyse(&p.surface, &p.point, &p.direction);
    Ok(render(&a, "float", |x: &f64| *x + 0.0))
}

/// The kind.
pub struct RuledLine;

impl Kind for RuledLine {
    const NAME: &'static str = "ruled_line";
    type Input = Input<ExactNumber>;

    fn answer(text: &str, mode: Mode) -> Result<Value, Error> {
        by_mode(text, mode, exact_answer, float_answer, |e, f| {
            e.float = Some(Box::new(f))
        })
    }
}
