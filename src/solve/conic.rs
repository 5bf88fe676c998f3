//! `solve` kind `conic` (Chiang, "Conic table"): the section of the cone
//! `x^2 + y^2 = z^2` by any plane, as the two rational quadratic Bezier pieces of the cone's
//! ruled surfaces `V+` / `V-`, with the section type decided two independent ways.
//!
//! # The answer
//! The computation is [`exactcheck_core::conic::ConeSection`]: the cone is the pair of ruled
//! surfaces `s V(t)` (apex at the origin, `V` a quadratic direction field with control vectors
//! `q_k`, printed per piece as `directions`), and Chiang's theorem gives for the plane
//! `N . x + d = 0` the homogeneous control vectors `w_k = N . q_k`, `w_k r_k = -d q_k` of each
//! piece. A zero weight is a point at infinity (`points[k] = null`); `weighted_points[k]` is
//! always defined. The poles of a piece are the zeros in `[0, 1]` of its weight polynomial
//! `w0 (1-t)^2 + 2 w1 t(1-t) + w2 t^2` (rulings parallel to the plane), isolated exactly as in
//! `ruled_plane` (rational zeros and zeros of a linear square-free part exact, the others as
//! intervals `[lo, hi]` refined to `precision`), with their multiplicity.
//!
//! # The type, twice
//! `type_by_angle_rule` is the paper's rule on the angle between the normal and the cone's axis
//! ([`exactcheck_core::conic::angle_rule`]: the signs of `a^2 + b^2` and `c^2 - (a^2 + b^2)`); `type_by_bezier` is read
//! from each piece's own weights and points ([`exactcheck_core::conic::bezier_type`]: the sign of `w1^2 - w0 w2`, the
//! circle test on the control polygon). In exact mode both are exact and must agree; if they
//! ever did not, that would be a bug in this program, and the answer is an error saying so
//! rather than a silent pick of one of them. `type` is the common verdict.
//!
//! # Planes through the apex
//! With `d = 0` every weighted point is zero and the section is degenerate: the apex alone
//! (`point`), one ruling counted twice (`double_line`) or two rulings (`line_pair`). The rulings
//! lying in the plane are computed directly from the normal: a direction `(cos p, sin p, 1)` of
//! the cone lies in the plane iff `a cos p + b sin p + c = 0`, which gives, with
//! `D = a^2 + b^2 - c^2`,
//!
//! ```text
//!     direction = (-a c + e b sqrt(D), -b c - e a sqrt(D), a^2 + b^2),   e = +1 or -1
//! ```
//!
//! (`D < 0`: none; `D = 0`: one; `D > 0`: two). `sqrt(D)` is exact when it lies in the radical
//! field (always for rational input); otherwise the direction is given by its f64 `approx` only
//! and `direction` is `null`. The rulings are also the poles of the pieces: each pole `t0` is
//! assigned to its ruling exactly by the sign of `g(t0)`, `g(t) = b V_x(t) - a V_y(t)`, which is
//! `e sqrt(D) (a^2 + b^2)` times a positive factor on the ruling `e`. The sign of `g` at an
//! irrational pole is certified by refining the pole's interval until
//! `|g(lo)| > max |g'| (hi - lo)` (`g'` is linear, so its maximum is at an end).
//!
//! # Float mode
//! `--float` runs the same generic code in f64 with `1/sqrt 2 = 0.5f64.sqrt()`. The type is then
//! decided on rounded values, so a boundary case (a circle, a parabola, a plane through the
//! apex) is typically reported as a neighbouring type, and the two rules may disagree; the answer
//! says so in `type_note` instead of failing. Poles come from the same subdivision, which stops
//! where f64 cannot halve an interval.

use super::number::{Coords, ExactNumber, FieldNumber, FloatNumber};
use super::scalar::{unit_zeros, Scalar, DEFAULT_WIDTH_LOG2};
use super::{parse, FloatKind, Kind, Problem};
use crate::Error;
use exactcheck_core::conic::{cone_surface, ConeSection, DegenerateConic, SectionType};
use exactcheck_core::roots::{self, IsolatedRoot};
use exactcheck_core::ruled::Plane;
use exactcheck_core::{Bernstein, OrderedField, Sign, Sqrt, Vec3};
use exactcheck_exact::{Radical, Rational};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

// ------------------------------------------------------------------ input

/// The problem, with numbers of type `N` ([`ExactNumber`] in exact mode, [`FloatNumber`] with
/// `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "conic",
    description = "The section of the cone x^2 + y^2 = z^2 (Chiang's two ruled surfaces V+ and V-) by a plane, given either as `normal` and `point` (the plane through the point) or as `plane` [a, b, c, d] (a x + b y + c z + d = 0) — exactly one of the two forms: both pieces as rational quadratic Bezier curves (weights, points, poles in [0,1]), the type (circle, ellipse, parabola, hyperbola; point, double_line, line_pair for a plane through the apex) decided by the paper's angle rule and by the pieces' weights, and the rulings in the plane for a plane through the apex. Exact mode reads exact numbers (sqrt allowed); --float any finite number.",
    extend("oneOf" = [{"required": ["normal", "point"]}, {"required": ["plane"]}])
)]
pub struct Input<N> {
    /// `"conic"`.
    #[schemars(extend("const" = "conic"))]
    pub kind: String,
    /// The plane's normal `[a, b, c]`, not zero (with `point`).
    pub normal: Option<Coords<N, 3>>,
    /// A point of the plane (with `normal`).
    pub point: Option<Coords<N, 3>>,
    /// The plane `[a, b, c, d]`: `a x + b y + c z + d = 0`, `(a, b, c) != 0` (instead of
    /// `normal` and `point`).
    pub plane: Option<Coords<N, 4>>,
    /// The width to which the isolating intervals of irrational poles are refined (positive;
    /// default 2^-50, so `approx` is good to about 1e-15).
    pub precision: Option<N>,
}

/// The plane and the width, checked.
fn problem<N, T: Scalar + Sqrt>(
    input: &Input<N>,
    num: impl Fn(&N) -> T,
) -> Result<(Plane<T>, T), Error> {
    let vec3 = |Coords([x, y, z]): &Coords<N, 3>| Vec3::new(num(x), num(y), num(z));
    let plane = match (&input.normal, &input.point, &input.plane) {
        (Some(n), Some(p), None) => {
            let normal = vec3(n);
            if normal.is_zero() {
                return Err(Error::Input(
                    "normal: the zero vector is not the normal of a plane".into(),
                ));
            }
            let d = normal.dot(&vec3(p)).neg_ref();
            let Vec3 { x, y, z } = normal;
            Plane::new(x, y, z, d)
        }
        (None, None, Some(Coords([a, b, c, d]))) => {
            let plane = Plane::new(num(a), num(b), num(c), num(d));
            if plane.normal.is_zero() {
                return Err(Error::Input(
                    "plane: the normal (a, b, c) is the zero vector: there is no plane".into(),
                ));
            }
            plane
        }
        (_, _, Some(_)) => {
            return Err(Error::Input(
                "plane: give either `plane` [a, b, c, d] or `normal` and `point`, not both".into(),
            ))
        }
        (Some(_), None, None) => {
            return Err(Error::Input(
                "point: missing (the plane is the one through `point` with normal `normal`)".into(),
            ))
        }
        (None, Some(_), None) => {
            return Err(Error::Input(
                "normal: missing (the plane is the one through `point` with normal `normal`)"
                    .into(),
            ))
        }
        (None, None, None) => {
            return Err(Error::Input(
                "missing the plane: give `normal` and `point`, or `plane` [a, b, c, d]".into(),
            ))
        }
    };
    let width = match &input.precision {
        None => T::one()
            .checked_div(&T::from_i64(2).pow(DEFAULT_WIDTH_LOG2))
            .expect("2^50 != 0"),
        Some(w) => {
            let w = num(w);
            if w.sign() != Sign::Positive {
                return Err(Error::Input("precision: must be positive".into()));
            }
            super::number::check_precision(&w)?;
            w
        }
    };
    Ok((plane, width))
}

// ------------------------------------------------------------------ scalars

/// `1/sqrt 2` in a scalar with square roots: `sqrt(1/2)` ([`Radical`] holds it exactly; in f64
/// it is `0.5f64.sqrt()`).
///
/// `like` is a number of the computation: in a number field, `1/2` is taken in its field, to
/// which the problem's reading adjoined `sqrt(2)` ([`ConicKind`]'s `compute_in_field`).
fn inv_sqrt2<T: Scalar + Sqrt>(like: &T) -> T {
    like.rational_like(&Rational::new(1, 2).expect("2 != 0"))
        .sqrt()
        .expect("1/2 has a square root in the scalars with square roots (Radical, f64, a number field with sqrt 2)")
}

// ------------------------------------------------------------------ the computation

/// A pole of one piece, computed.
pub(crate) struct PoleData<T> {
    /// The zero of the weight polynomial.
    pub zero: IsolatedRoot<T>,
    /// Its multiplicity (exact scalars only).
    pub multiplicity: Option<usize>,
}

/// One piece, computed.
pub(crate) struct PieceData<T> {
    /// The cone's control vectors `q_k` of this piece.
    pub directions: Vec<Vec3<T>>,
    /// The section piece (curve; its own poles unrefined).
    pub curve: exactcheck_core::RationalBezierCurve<T>,
    /// The poles, refined.
    pub poles: Vec<PoleData<T>>,
    /// The type from this piece's weights and points.
    pub bezier: Option<SectionType>,
}

/// A ruling lying in a plane through the apex.
pub(crate) struct RulingData<T> {
    /// The direction, `None` where `sqrt(D)` is not in the field.
    pub direction: Option<Vec3<T>>,
    /// Its f64 approximation.
    pub approx: [f64; 3],
    /// `(piece index, pole index)` of the poles on this ruling.
    pub poles: Vec<(usize, usize)>,
}

/// The section, computed in `T`.
pub(crate) struct Computed<T> {
    /// The plane.
    pub plane: Plane<T>,
    /// `+` and `-`.
    pub pieces: [PieceData<T>; 2],
    /// The type by the angle rule.
    pub angle: SectionType,
    /// The rulings in the plane (`d = 0` only).
    pub rulings: Option<Vec<RulingData<T>>>,
}

fn three_approx<T: Scalar>(v: &Vec3<T>) -> [f64; 3] {
    [v.x.approx(), v.y.approx(), v.z.approx()]
}

/// The sign of `g` at the zero `root` of `w` (where `g` does not vanish), certified by
/// refining the interval (module doc). For f64 the refinement stops at f64 resolution and the
/// sign at the midpoint is taken.
fn sign_at_root<T: Scalar + Sqrt>(
    g: &Bernstein<T>,
    w: &Bernstein<T>,
    root: &IsolatedRoot<T>,
) -> Result<Sign, Error> {
    let dg = g.derivative();
    let mut root = root.clone();
    for _ in 0..4000 {
        let (lo, hi) = match &root {
            IsolatedRoot::Exact(t) => return Ok(g.eval(t).sign()),
            IsolatedRoot::Between(lo, hi) => (lo.clone(), hi.clone()),
        };
        let width = hi.sub_ref(&lo);
        let slope = dg.eval(&lo).abs().max_of(&dg.eval(&hi).abs());
        let at_lo = g.eval(&lo);
        if at_lo.abs() > slope.mul_ref(&width) {
            return Ok(at_lo.sign());
        }
        let half = width.checked_div(&T::from_i64(2)).expect("2 is not zero");
        let next = roots::refine(w, &root, &half);
        if !T::EXACT && next == root {
            return Ok(g.eval(&root.midpoint()).sign());
        }
        root = next;
    }
    Err(Error::Input(
        "internal error: the ruling of a pole could not be decided after 4000 refinements; please report this plane".into(),
    ))
}

/// `max(self, other)` for an ordered field.
trait MaxOf {
    fn max_of(&self, other: &Self) -> Self;
}

impl<T: OrderedField> MaxOf for T {
    fn max_of(&self, other: &Self) -> Self {
        if self >= other {
            self.clone()
        } else {
            other.clone()
        }
    }
}

/// The rulings in a plane through the apex (module doc), each with the poles on it.
fn rulings<T: Scalar + Sqrt>(
    plane: &Plane<T>,
    pieces: &[PieceData<T>; 2],
) -> Result<Vec<RulingData<T>>, Error> {
    let n = &plane.normal;
    let (a, b, c) = (&n.x, &n.y, &n.z);
    let h = a.square().add_ref(&b.square());
    if h.is_zero() {
        return Ok(Vec::new());
    }
    let disc = h.sub_ref(&c.square());
    let base = |root: &T, e: i64| {
        let root = root.scale_i64(e);
        Vec3::new(
            a.mul_ref(c).neg_ref().add_ref(&b.mul_ref(&root)),
            b.mul_ref(c).neg_ref().sub_ref(&a.mul_ref(&root)),
            h.clone(),
        )
    };
    let all_poles = || {
        pieces
            .iter()
            .enumerate()
            .flat_map(|(i, p)| (0..p.poles.len()).map(move |k| (i, k)))
            .collect::<Vec<_>>()
    };
    match disc.sign() {
        Sign::Negative => Ok(Vec::new()),
        Sign::Zero => {
            let d = base(&T::zero(), 1);
            Ok(vec![RulingData {
                approx: three_approx(&d),
                direction: Some(d),
                poles: all_poles(),
            }])
        }
        Sign::Positive => {
            let exact_root = disc.sqrt();
            let approx_root = disc.approx().sqrt();
            let mut out: Vec<RulingData<T>> = [1i64, -1]
                .iter()
                .map(|&e| {
                    let d = exact_root.as_ref().map(|r| base(r, e));
                    // The twins of an exact direction are converted from it; only a direction
                    // outside the field is approximated in f64.
                    let approx = match &d {
                        Some(d) => three_approx(d),
                        None => {
                            let h = h.approx();
                            let (a, b, c) = (a.approx(), b.approx(), c.approx());
                            let e = e as f64;
                            [
                                -a * c + e * b * approx_root + 0.0,
                                -b * c - e * a * approx_root + 0.0,
                                h,
                            ]
                        }
                    };
                    RulingData {
                        direction: d,
                        approx,
                        poles: Vec::new(),
                    }
                })
                .collect();
            for (i, k) in all_poles() {
                let piece = &pieces[i];
                let v = cone_surface(
                    if i == 0 {
                        exactcheck_core::conic::ConePiece::Plus
                    } else {
                        exactcheck_core::conic::ConePiece::Minus
                    },
                    &inv_sqrt2(a),
                );
                let g = v
                    .directions()
                    .coordinate(0)
                    .scale(b)
                    .checked_sub(&v.directions().coordinate(1).scale(a));
                let g = g.expect("two quadratics");
                let w = piece.curve.weight_polynomial();
                match sign_at_root(&g, &w, &piece.poles[k].zero)? {
                    Sign::Positive => out[0].poles.push((i, k)),
                    Sign::Negative => out[1].poles.push((i, k)),
                    Sign::Zero => {
                        if T::EXACT {
                            return Err(Error::Input(
                                "internal error: a pole of a line-pair section lies on neither ruling; please report this plane".into(),
                            ));
                        }
                    }
                }
            }
            Ok(out)
        }
    }
}

/// The section by `plane`, computed in `T`, poles refined to `width`.
pub(crate) fn compute<T: Scalar + Sqrt>(plane: Plane<T>, width: &T) -> Result<Computed<T>, Error> {
    let inv_sqrt2 = inv_sqrt2(&plane.normal.x);
    let section = ConeSection::new(plane, &inv_sqrt2).map_err(|e| {
        // `problem` refuses a zero normal, so in f64 this is a non-zero normal whose squares
        // underflow to zero.
        Error::Input(if T::EXACT {
            format!("normal: {e}")
        } else {
            format!("normal: {}", super::F64_OUT_OF_RANGE)
        })
    })?;
    let check = section.check_types();
    let ConeSection { plane, pieces } = section;
    let piece = |k: usize, p: &exactcheck_core::conic::SectionPiece<T>| {
        let w = p.curve.weight_polynomial();
        let poles = unit_zeros(&w, width)
            .into_iter()
            .map(|zero| PoleData {
                multiplicity: T::EXACT.then(|| roots::multiplicity(&w, &zero)),
                zero,
            })
            .collect();
        PieceData {
            directions: cone_surface(p.piece, &inv_sqrt2)
                .directions()
                .control_points()
                .to_vec(),
            curve: p.curve.clone(),
            poles,
            bezier: check.bezier[k],
        }
    };
    let pieces = [piece(0, &pieces[0]), piece(1, &pieces[1])];
    let rulings = if plane.d.is_zero() {
        Some(rulings(&plane, &pieces)?)
    } else {
        None
    };
    Ok(Computed {
        angle: check.angle_rule,
        plane,
        pieces,
        rulings,
    })
}

// ------------------------------------------------------------------ answers

/// A pole's parameter: exact, or an isolating interval with its midpoint.
#[derive(Debug, Serialize)]
#[serde(untagged)]
enum PoleT<V> {
    Exact(V),
    Isolated { interval: [V; 2], approx: f64 },
}

/// A pole of a piece.
#[derive(Debug, Serialize)]
struct Pole<V> {
    t: PoleT<V>,
    approx: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    multiplicity: Option<usize>,
}

#[derive(Debug, Serialize)]
struct PieceApprox {
    weights: Vec<f64>,
    points: Vec<Option<[f64; 3]>>,
}

/// One piece of the answer.
#[derive(Debug, Serialize)]
struct Piece<V> {
    cone: &'static str,
    directions: Vec<[V; 3]>,
    weights: Vec<V>,
    points: Vec<Option<[V; 3]>>,
    weighted_points: Vec<[V; 3]>,
    poles: Vec<Pole<V>>,
    type_by_bezier: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    approx: Option<PieceApprox>,
}

/// Where a ruling meets a piece: the piece and the pole's parameter.
#[derive(Debug, Serialize)]
struct RulingParameter<V> {
    cone: &'static str,
    t: PoleT<V>,
    approx: f64,
}

/// A ruling in a plane through the apex.
#[derive(Debug, Serialize)]
struct Ruling<V> {
    direction: Option<[V; 3]>,
    approx: [f64; 3],
    parameters: Vec<RulingParameter<V>>,
}

/// The degenerate section of a plane through the apex.
#[derive(Debug, Serialize)]
struct Degenerate<V> {
    apex: [V; 3],
    rulings: Vec<Ruling<V>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    note: Option<&'static str>,
}

/// The answer, with numbers of type `V` (exact strings, or f64 with `--float`).
#[derive(Debug, Serialize)]
pub(crate) struct Answer<V> {
    kind: &'static str,
    mode: &'static str,
    plane: [V; 4],
    #[serde(rename = "type")]
    type_: Option<&'static str>,
    type_by_angle_rule: &'static str,
    type_by_bezier: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    type_note: Option<String>,
    pieces: Vec<Piece<V>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    degenerate: Option<Degenerate<V>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<Box<Answer<f64>>>,
}

fn three<T, V>(p: &Vec3<T>, v: &impl Fn(&T) -> V) -> [V; 3] {
    [v(&p.x), v(&p.y), v(&p.z)]
}

fn pole_t<T: Scalar, V>(z: &IsolatedRoot<T>, v: &impl Fn(&T) -> V) -> PoleT<V> {
    match z {
        IsolatedRoot::Exact(t) => PoleT::Exact(v(t)),
        IsolatedRoot::Between(lo, hi) => PoleT::Isolated {
            interval: [v(lo), v(hi)],
            approx: z.midpoint().approx(),
        },
    }
}

/// The common type of the pieces' Bezier verdicts, `None` when they differ or are undecided.
fn common_bezier(c: &Computed<impl Sized>) -> Option<SectionType> {
    match (c.pieces[0].bezier, c.pieces[1].bezier) {
        (Some(x), Some(y)) if x == y => Some(x),
        _ => None,
    }
}

fn render<T: Scalar + Sqrt, V>(
    c: &Computed<T>,
    mode: &'static str,
    v: impl Fn(&T) -> V,
) -> Answer<V> {
    let pieces = c
        .pieces
        .iter()
        .zip(["+", "-"])
        .map(|(p, cone)| {
            let weights = p.curve.weights();
            let points = p.curve.points();
            let weighted: Vec<Vec3<T>> = p
                .curve
                .control()
                .iter()
                .map(|h| Vec3::new(h.0[1].clone(), h.0[2].clone(), h.0[3].clone()))
                .collect();
            Piece {
                cone,
                directions: p.directions.iter().map(|q| three(q, &v)).collect(),
                weights: weights.iter().map(&v).collect(),
                points: points
                    .iter()
                    .map(|q| q.as_ref().map(|q| three(q, &v)))
                    .collect(),
                weighted_points: weighted.iter().map(|q| three(q, &v)).collect(),
                poles: p
                    .poles
                    .iter()
                    .map(|pole| Pole {
                        t: pole_t(&pole.zero, &v),
                        approx: pole.zero.midpoint().approx(),
                        multiplicity: pole.multiplicity,
                    })
                    .collect(),
                type_by_bezier: p.bezier.map(SectionType::name),
                approx: T::EXACT.then(|| PieceApprox {
                    weights: weights.iter().map(Scalar::approx).collect(),
                    points: points
                        .iter()
                        .map(|q| q.as_ref().map(three_approx))
                        .collect(),
                }),
            }
        })
        .collect();
    let degenerate = c.rulings.as_ref().map(|rulings| Degenerate {
        apex: three(&Vec3::zero(), &v),
        rulings: rulings
            .iter()
            .map(|r| Ruling {
                direction: r.direction.as_ref().map(|d| three(d, &v)),
                approx: r.approx,
                parameters: r
                    .poles
                    .iter()
                    .map(|&(i, k)| {
                        let z = &c.pieces[i].poles[k].zero;
                        RulingParameter {
                            cone: if i == 0 { "+" } else { "-" },
                            t: pole_t(z, &v),
                            approx: z.midpoint().approx(),
                        }
                    })
                    .collect(),
            })
            .collect(),
        note: rulings.iter().any(|r| r.direction.is_none()).then_some(
            "sqrt(a^2 + b^2 - c^2) is not in the radical field: the directions are given by their approx only",
        ),
    });
    let bezier = common_bezier(c);
    Answer {
        kind: "conic",
        mode,
        plane: [
            v(&c.plane.normal.x),
            v(&c.plane.normal.y),
            v(&c.plane.normal.z),
            v(&c.plane.d),
        ],
        type_: Some(c.angle.name()),
        type_by_angle_rule: c.angle.name(),
        type_by_bezier: bezier.map(SectionType::name),
        type_note: None,
        pieces,
        degenerate,
        float: None,
    }
}

fn exact<N, T: Scalar + Sqrt>(
    input: Input<N>,
    num: impl Fn(&N) -> T,
) -> Result<Answer<String>, Error> {
    let (plane, width) = problem(&input, num)?;
    let c = compute(plane, &width)?;
    let by_angle = c.angle;
    for (p, cone) in c.pieces.iter().zip(["+", "-"]) {
        if p.bezier != Some(by_angle) {
            return Err(Error::Input(format!(
                "internal error: the angle rule says {by_angle} but the weights of piece {cone} say {}; this is a bug, please report this plane",
                p.bezier.map_or("no conic", SectionType::name)
            )));
        }
    }
    if let Some(rulings) = &c.rulings {
        let want = match by_angle {
            SectionType::Degenerate(DegenerateConic::Point) => 0,
            SectionType::Degenerate(DegenerateConic::DoubleLine) => 1,
            SectionType::Degenerate(DegenerateConic::LinePair) => 2,
            SectionType::Conic(_) => usize::MAX,
        };
        if rulings.len() != want {
            return Err(Error::Input(format!(
                "internal error: a {by_angle} with {} rulings; this is a bug, please report this plane",
                rulings.len()
            )));
        }
    }
    Ok(render(&c, "exact", ToString::to_string))
}

fn float_answer(input: Input<FloatNumber>) -> Result<Answer<f64>, Error> {
    let (plane, width) = problem(&input, |x| x.0)?;
    // The classification compares `c^2` with `a^2 + b^2`: beyond f64's range (`inf - inf`) or
    // below it (both `0`) the comparison means nothing.
    if !plane.normal.norm_squared().is_finite() {
        return Err(Error::Input(format!("normal: {}", super::F64_OUT_OF_RANGE)));
    }
    let c = compute(plane, &width)?;
    let mut answer = render(&c, "float", |x: &f64| *x + 0.0);
    let finite = answer.plane.iter().all(|x| x.is_finite())
        && answer.pieces.iter().all(|p| {
            p.weights
                .iter()
                .chain(p.weighted_points.iter().flatten())
                .all(|x| x.is_finite())
        });
    if !finite {
        return Err(Error::Input(
            "the f64 computation overflows for these numbers; use exact mode".into(),
        ));
    }
    let agree = answer.type_by_bezier == Some(answer.type_by_angle_rule);
    answer.type_note = Some(if agree {
        "decided on f64-rounded values: a boundary case (circle, parabola, plane through the apex) can come out as a neighbouring type; exact mode decides exactly".into()
    } else {
        answer.type_ = None;
        format!(
            "decided on f64-rounded values, and the two rules disagree (angle rule: {}, weights: {} / {}): rounding near a boundary case; exact mode decides exactly",
            answer.type_by_angle_rule,
            answer.pieces[0].type_by_bezier.unwrap_or("undecided"),
            answer.pieces[1].type_by_bezier.unwrap_or("undecided"),
        )
    });
    Ok(answer)
}

/// The kind.
pub struct ConicKind;

impl Kind for ConicKind {
    const NAME: &'static str = "conic";
    type Input = Input<ExactNumber>;
    type Answer = Answer<String>;

    fn compute(input: Self::Input) -> Result<Self::Answer, Error> {
        exact(input, |x: &ExactNumber| x.0.clone())
    }

    /// The cone `x^2 + y^2 = z^2` needs `1/sqrt(2)`: `sqrt(2)` is adjoined to the field.
    fn compute_in_field(problem: &Problem) -> Result<Self::Answer, Error> {
        let input: Input<FieldNumber> = problem.input_in_field(&["sqrt(2)"])?;
        exact(input, |x: &FieldNumber| x.0.clone())
    }
}

impl FloatKind for ConicKind {
    type FloatInput = Input<FloatNumber>;
    type FloatAnswer = Answer<f64>;

    fn compute_float(input: Self::FloatInput) -> Result<Self::FloatAnswer, Error> {
        float_answer(input)
    }
}

impl super::FloatSlot for Answer<String> {
    type Float = Answer<f64>;
    fn float_slot(&mut self) -> &mut Option<Box<Answer<f64>>> {
        &mut self.float
    }
}

/// The exact section of a `conic` problem (for `plot`): the computed data in `Q(sqrt 2, ...)`.
///
/// # Errors
/// As `solve`.
pub(crate) fn exact_section(text: &str) -> Result<Computed<Radical>, Error> {
    let input: Input<ExactNumber> = parse(text)?;
    let (plane, width) = problem(&input, |x| x.0.clone())?;
    compute(plane, &width)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn answer(text: &str) -> serde_json::Value {
        crate::solve::solve(text, crate::solve::Mode::Exact).expect("an answer")
    }

    #[test]
    fn inv_sqrt2_is_the_one_of_each_scalar() {
        use exactcheck_core::Field;
        assert_eq!(
            inv_sqrt2(&Radical::from(&Rational::ONE)),
            Radical::sqrt_of(2).inv().expect("sqrt 2 is not zero")
        );
        assert_eq!(
            inv_sqrt2(&Radical::from(&Rational::ONE)).to_string(),
            "sqrt(2)/2"
        );
        assert_eq!(inv_sqrt2(&1.0f64).to_bits(), 0.5f64.sqrt().to_bits());
    }

    #[test]
    fn the_two_plane_forms_give_the_same_answer() {
        let a = answer(r#"{"kind":"conic","normal":[1,1,3],"point":[1,1,1]}"#);
        let b = answer(r#"{"kind":"conic","plane":[1,1,3,-5]}"#);
        assert_eq!(a, b);
        assert_eq!(a["type"], "ellipse");
        assert_eq!(
            a["pieces"][0]["weights"],
            serde_json::json!(["4", "5*sqrt(2)/2", "4"])
        );
    }

    #[test]
    fn a_line_pair_assigns_each_pole_to_its_ruling() {
        // (1, 1, 1) through the apex: D = 1, rulings (-1 + 1, -1 - 1, 2) = (0, -2, 2) and
        // (-2, 0, 2): both in the three-quarter cone V-, so all poles are on piece -.
        let a = answer(r#"{"kind":"conic","plane":[1,1,1,0]}"#);
        assert_eq!(a["type"], "line_pair");
        let rulings = a["degenerate"]["rulings"].as_array().unwrap();
        assert_eq!(rulings.len(), 2);
        assert_eq!(rulings[0]["direction"], serde_json::json!(["0", "-2", "2"]));
        assert_eq!(rulings[1]["direction"], serde_json::json!(["-2", "0", "2"]));
        for r in rulings {
            let p = r["parameters"].as_array().unwrap();
            assert_eq!(p.len(), 1, "{r}");
            assert_eq!(p[0]["cone"], "-");
        }
    }
}
