//! `solve` kind `ruled_plane` (Chiang's Theorem 1): the section of the ruled surface
//! `S(s,t) = B(t) + s V(t)` by the plane `N.x + d = 0` as a rational Bezier curve of degree
//! `m + n`, with its degenerate cases as typed outcomes and its poles isolated exactly.
//!
//! # The answer
//! The homogeneous control vectors `(w_k, w_k r_k)` are Chiang's sums
//! ([`exactcheck_core::ruled::RuledSurface::plane_section`], division-free), so a zero weight is
//! a point at infinity (`points[k] = null`) and `weighted_points[k] = w_k r_k` is always defined.
//! The outcome is decided exactly ([`exactcheck_core::ruled::RuledSurface::classify_plane`]):
//!
//! * `curve`: the weight polynomial `N.V(t)` (degree `m`) is not identically zero. Its zeros in
//!   `[0, 1]` are the *poles* (rulings parallel to the plane): each is given by an interval
//!   `[lo, hi]` of rationals isolating it (`lo = hi` and `exact` when the pole is rational), its
//!   multiplicity as a zero of `N.V`, `ruling_in_plane` (the offset `N.B + d` vanishes there too:
//!   the whole ruling lies in the plane) and `removable` (the factor `(t - t0)^mult` divides all
//!   four homogeneous coordinates, so the curve stays finite at `t0`).
//! * `parallel_rulings`: `N.V = 0` identically, `N.B + d` not: every ruling is parallel to the
//!   plane; the section is the set of rulings at the zeros of `N.B + d` in `[0, 1]`
//!   (`rulings_in_plane`, each with `s` free), possibly none.
//! * `surface_in_plane`: both vanish identically.
//! * `degenerate_no_rulings`: every direction vector is zero (`V = 0`), so there are no rulings
//!   and the "surface" is the base curve `B` (checked before the two cases above, which it would
//!   otherwise be called): `base_curve_in_plane` says whether `N.B + d` vanishes identically,
//!   and if not, `base_points_in_plane` gives the zeros of `N.B + d` in `[0, 1]` (the parameters
//!   of the points where `B` meets the plane), possibly none.
//!
//! `ruling_parameter` gives `s(t) = -(N.B(t) + d) / (N.V(t))` as Bernstein coefficients of its
//! numerator (degree `n`) and denominator (degree `m`): the section point at `t` is `S(s(t), t)`.
//!
//! # Root isolation
//! The zeros in `[0, 1]` are isolated by the workspace's generic Bernstein–Descartes subdivision
//! on the square-free part ([`exactcheck_core::roots`], any ordered field, so radical
//! coefficients too), refined to `precision`. Rational zeros are then made exact: writing the
//! coefficients in the basis `sqrt(k)` of the radical field, `p = sum_k sqrt(k) p_k(t)` with
//! rational `p_k`, a rational `t0` is a zero of `p` iff it is a common zero of all `p_k`, i.e. a
//! zero of the rational polynomial `G = gcd_k p_k`, whose rational zeros the real-root isolator
//! (`isolate_real_roots_in`) returns exactly; each is placed in the one isolating interval that
//! contains it. "How often does `f` vanish at the zero `t0` of `p` isolated by `(lo, hi)`" is
//! decided exactly on `g = gcd(p, f)`: its zeros are zeros of `p`, so `(lo, hi)` isolates at most
//! `t0` among them, and the multiplicity of `t0` in `g` is `min(mult_p, mult_f)`
//! ([`exactcheck_core::roots::multiplicity`]).
//!
//! # Float mode
//! `--float` runs the same generic code in `f64`: the classification's zero tests are exact
//! comparisons with `0.0`, and the poles come from the same subdivision, which stops where f64
//! cannot halve an interval (such an interval is reported as one pole). That is a heuristic: it
//! can miss a double pole perturbed off the axis or report a cluster as one; `ruling_in_plane`,
//! `multiplicity` and `removable` need exact gcds and are given in exact mode only.
//!
//! # Limits
//! `m + n <= 60` ([`MAX_DEGREE`]): the product rule uses binomial coefficients `C(m+n, k)` in
//! 64-bit integers, which overflow beyond `m + n = 67`.

use super::number::{Coords, ExactNumber, FieldNumber, FloatNumber};
use super::scalar::{unit_zeros, Scalar, DEFAULT_WIDTH_LOG2};
use super::{FloatKind, Kind, Problem};
use crate::Error;
use exactcheck_core::roots::{self, IsolatedRoot};
use exactcheck_core::ruled::{Plane, PlaneSection, RuledSurface};
use exactcheck_core::{Bernstein, OrderedField, RationalBezierCurve, Sign, Vec3};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// The largest `m + n` (degree of the section) accepted.
pub const MAX_DEGREE: usize = 60;

// ------------------------------------------------------------------ input

/// The problem, with numbers of type `N` ([`ExactNumber`] in exact mode, [`FloatNumber`] with
/// `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "ruled_plane",
    description = "Chiang's Theorem 1: the section of the ruled surface S(s,t) = B(t) + s V(t) (B a Bezier curve of degree n, V a Bezier direction field of degree m, m + n <= 60) by the plane a x + b y + c z + d = 0, as a rational Bezier curve of degree m + n, with the degenerate cases (parallel rulings, surface in the plane) and the poles in [0,1] decided exactly. Exact mode reads exact numbers (sqrt allowed); --float any finite number."
)]
pub struct Input<N> {
    /// `"ruled_plane"`.
    #[schemars(extend("const" = "ruled_plane"))]
    pub kind: String,
    /// The control points `p_0..p_n` of the base curve `B` (at least one).
    pub base: Vec<Coords<N, 3>>,
    /// The control vectors `q_0..q_m` of the direction field `V` (at least one).
    pub directions: Vec<Coords<N, 3>>,
    /// The plane `[a, b, c, d]`: `a x + b y + c z + d = 0`, `(a, b, c) != 0`.
    pub plane: Coords<N, 4>,
    /// The width to which the isolating intervals of irrational poles and rulings are refined
    /// (positive; default 2^-50, so `approx` is good to about 1e-15).
    pub precision: Option<N>,
}

/// The surface, the plane and the width, checked.
fn problem<N, T: OrderedField>(
    input: &Input<N>,
    num: impl Fn(&N) -> T,
) -> Result<(RuledSurface<T>, Plane<T>, T), Error> {
    let points = |list: &[Coords<N, 3>]| -> Vec<Vec3<T>> {
        list.iter()
            .map(|Coords([x, y, z])| Vec3::new(num(x), num(y), num(z)))
            .collect()
    };
    if input.base.is_empty() {
        return Err(Error::Input(
            "base: at least one control point is needed (n + 1 points for degree n)".into(),
        ));
    }
    if input.directions.is_empty() {
        return Err(Error::Input(
            "directions: at least one control vector is needed (m + 1 vectors for degree m)".into(),
        ));
    }
    let (n, m) = (input.base.len() - 1, input.directions.len() - 1);
    if m + n > MAX_DEGREE {
        return Err(Error::Input(format!(
            "base, directions: degree m + n = {m} + {n} = {} exceeds the limit {MAX_DEGREE}",
            m + n
        )));
    }
    let Coords([a, b, c, d]) = &input.plane;
    let plane = Plane::new(num(a), num(b), num(c), num(d));
    if plane.normal.is_zero() {
        return Err(Error::Input("plane: normal (a, b, c) is zero".into()));
    }
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
    let surface = RuledSurface::from_control(points(&input.base), points(&input.directions))
        .expect("both lists were checked non-empty");
    Ok((surface, plane, width))
}

// ------------------------------------------------------------------ isolation

/// The multiplicity of the zero `z` of `p` (isolated for `p`) as a zero of `f`, capped at its
/// multiplicity in `p`: its multiplicity in `gcd(p, f)` (module doc). Exact scalars only.
fn common_multiplicity<T: Scalar>(
    p: &Bernstein<T>,
    f: &Bernstein<T>,
    z: &IsolatedRoot<T>,
) -> usize {
    if f.is_zero() {
        return roots::multiplicity(p, z);
    }
    let g = roots::gcd(&[p.clone(), f.clone()]).expect("f is not zero");
    roots::multiplicity(&g, z)
}

// ------------------------------------------------------------------ the computation

/// A pole, computed.
struct PoleData<T> {
    zero: IsolatedRoot<T>,
    /// `(multiplicity, ruling_in_plane, removable)`, exact scalars only.
    exact: Option<(usize, bool, bool)>,
}

/// The section, computed in `T`.
struct Section<T> {
    m: usize,
    n: usize,
    outcome: &'static str,
    curve: RationalBezierCurve<T>,
    weight: Bernstein<T>,
    offset: Bernstein<T>,
    poles: Option<Vec<PoleData<T>>>,
    rulings: Option<Vec<IsolatedRoot<T>>>,
    /// With no rulings: whether the base curve lies in the plane, else its points there.
    base: Option<(bool, Vec<IsolatedRoot<T>>)>,
}

fn compute<T: Scalar>(surface: &RuledSurface<T>, plane: &Plane<T>, width: &T) -> Section<T> {
    let (m, n) = surface.degrees();
    let weight = surface.normal_component(plane);
    let offset = surface.offset(plane);
    let curve = surface.plane_section(plane);
    let mut base = None;
    let (outcome, poles, rulings) = match surface.classify_plane(plane) {
        PlaneSection::Curve(_) => {
            let coords: Vec<Bernstein<T>> = (1..4).map(|a| curve.hom_coordinate(a)).collect();
            let poles = unit_zeros(&weight, width)
                .into_iter()
                .map(|zero| {
                    let exact = T::EXACT.then(|| {
                        let mult = roots::multiplicity(&weight, &zero);
                        let in_plane = common_multiplicity(&weight, &offset, &zero) > 0;
                        let removable = coords
                            .iter()
                            .all(|x| common_multiplicity(&weight, x, &zero) >= mult);
                        (mult, in_plane, removable)
                    });
                    PoleData { zero, exact }
                })
                .collect();
            ("curve", Some(poles), None)
        }
        PlaneSection::ParallelRulings { offset } => {
            ("parallel_rulings", None, Some(unit_zeros(&offset, width)))
        }
        PlaneSection::SurfaceInPlane => ("surface_in_plane", None, None),
        PlaneSection::NoRulings { offset } => {
            base = Some(if offset.is_zero() {
                (true, Vec::new())
            } else {
                (false, unit_zeros(&offset, width))
            });
            ("degenerate_no_rulings", None, None)
        }
    };
    Section {
        m,
        n,
        outcome,
        curve,
        weight,
        offset,
        poles,
        rulings,
        base,
    }
}

// ------------------------------------------------------------------ answers

/// A parameter in `[0, 1]`: an isolating interval, its midpoint, and the value when exact.
#[derive(Debug, Serialize)]
struct Parameter<V> {
    interval: [V; 2],
    approx: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    exact: Option<V>,
}

/// A pole of the curve.
#[derive(Debug, Serialize)]
struct Pole<V> {
    #[serde(flatten)]
    t: Parameter<V>,
    #[serde(skip_serializing_if = "Option::is_none")]
    multiplicity: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ruling_in_plane: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    removable: Option<bool>,
}

/// `s(t) = -(N.B(t) + d) / (N.V(t))` in Bernstein form.
#[derive(Debug, Serialize)]
struct RulingParameter<V> {
    formula: &'static str,
    basis: &'static str,
    numerator: Vec<V>,
    denominator: Vec<V>,
}

#[derive(Debug, Serialize)]
struct Approx {
    weights: Vec<f64>,
    points: Vec<Option<[f64; 3]>>,
    weighted_points: Vec<[f64; 3]>,
}

/// The answer, with numbers of type `V` (exact strings, or f64 with `--float`).
#[derive(Debug, Serialize)]
pub(crate) struct Answer<V> {
    kind: &'static str,
    mode: &'static str,
    outcome: &'static str,
    m: usize,
    n: usize,
    degree: usize,
    weights: Vec<V>,
    points: Vec<Option<[V; 3]>>,
    weighted_points: Vec<[V; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    poles: Option<Vec<Pole<V>>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    rulings_in_plane: Option<Vec<Parameter<V>>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    base_curve_in_plane: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    base_points_in_plane: Option<Vec<Parameter<V>>>,
    ruling_parameter: RulingParameter<V>,
    #[serde(skip_serializing_if = "Option::is_none")]
    approx: Option<Approx>,
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<Box<Answer<f64>>>,
}

fn parameter<T: Scalar, V>(z: &IsolatedRoot<T>, v: &impl Fn(&T) -> V) -> Parameter<V> {
    match z {
        IsolatedRoot::Exact(t) => Parameter {
            interval: [v(t), v(t)],
            approx: t.approx(),
            exact: Some(v(t)),
        },
        IsolatedRoot::Between(lo, hi) => Parameter {
            interval: [v(lo), v(hi)],
            approx: z.midpoint().approx(),
            exact: None,
        },
    }
}

fn three<T, V>(p: &Vec3<T>, v: &impl Fn(&T) -> V) -> [V; 3] {
    [v(&p.x), v(&p.y), v(&p.z)]
}

fn render<T: Scalar, V>(s: &Section<T>, mode: &'static str, v: impl Fn(&T) -> V) -> Answer<V> {
    let weights = s.curve.weights();
    let points = s.curve.points();
    let weighted: Vec<Vec3<T>> = s
        .curve
        .control()
        .iter()
        .map(|h| Vec3::new(h.0[1].clone(), h.0[2].clone(), h.0[3].clone()))
        .collect();
    let approx = T::EXACT.then(|| Approx {
        weights: weights.iter().map(Scalar::approx).collect(),
        points: points
            .iter()
            .map(|p| p.as_ref().map(|p| three(p, &Scalar::approx)))
            .collect(),
        weighted_points: weighted.iter().map(|p| three(p, &Scalar::approx)).collect(),
    });
    Answer {
        kind: "ruled_plane",
        mode,
        outcome: s.outcome,
        m: s.m,
        n: s.n,
        degree: s.m + s.n,
        weights: weights.iter().map(&v).collect(),
        points: points
            .iter()
            .map(|p| p.as_ref().map(|p| three(p, &v)))
            .collect(),
        weighted_points: weighted.iter().map(|p| three(p, &v)).collect(),
        poles: s.poles.as_ref().map(|poles| {
            poles
                .iter()
                .map(|p| Pole {
                    t: parameter(&p.zero, &v),
                    multiplicity: p.exact.map(|e| e.0),
                    ruling_in_plane: p.exact.map(|e| e.1),
                    removable: p.exact.map(|e| e.2),
                })
                .collect()
        }),
        rulings_in_plane: s
            .rulings
            .as_ref()
            .map(|r| r.iter().map(|z| parameter(z, &v)).collect()),
        base_curve_in_plane: s.base.as_ref().map(|(all, _)| *all),
        base_points_in_plane: s
            .base
            .as_ref()
            .filter(|(all, _)| !all)
            .map(|(_, zs)| zs.iter().map(|z| parameter(z, &v)).collect()),
        ruling_parameter: RulingParameter {
            formula: "s(t) = -(N.B(t) + d) / (N.V(t)) = numerator(t) / denominator(t)",
            basis: "Bernstein on [0, 1]: numerator of degree n, denominator of degree m",
            numerator: s.offset.coeffs().iter().map(|c| v(&c.neg_ref())).collect(),
            denominator: s.weight.coeffs().iter().map(&v).collect(),
        },
        approx,
        float: None,
    }
}

fn exact_answer<N, T: Scalar>(
    input: &Input<N>,
    lift: impl Fn(&N) -> T,
) -> Result<Answer<String>, Error> {
    let (surface, plane, width) = problem(input, lift)?;
    let s = compute(&surface, &plane, &width);
    Ok(render(&s, "exact", ToString::to_string))
}

fn exact(input: Input<ExactNumber>) -> Result<Answer<String>, Error> {
    let all = input
        .base
        .iter()
        .chain(&input.directions)
        .flat_map(|c| c.0.iter())
        .chain(input.plane.0.iter())
        .chain(input.precision.iter());
    // Rational input runs over the (faster) rationals; radicals over the radical field.
    if all.into_iter().all(|x| x.0.is_rational()) {
        exact_answer(&input, |x: &ExactNumber| {
            x.0.to_rational()
                .expect("is_rational was checked for every number")
        })
    } else {
        exact_answer(&input, |x: &ExactNumber| x.0.clone())
    }
}

fn float_answer(input: Input<FloatNumber>) -> Result<Answer<f64>, Error> {
    let (surface, plane, width) = problem(&input, |x| x.0)?;
    let s = compute(&surface, &plane, &width);
    let answer = render(&s, "float", |x: &f64| *x + 0.0);
    let finite = answer
        .weighted_points
        .iter()
        .flatten()
        .all(|x| x.is_finite())
        && answer.weights.iter().all(|x| x.is_finite());
    if !finite {
        return Err(Error::Input(
            "the f64 computation overflows for these numbers; use exact mode".into(),
        ));
    }
    Ok(answer)
}

/// The kind.
pub struct RuledPlane;

impl Kind for RuledPlane {
    const NAME: &'static str = "ruled_plane";
    type Input = Input<ExactNumber>;
    type Answer = Answer<String>;

    fn compute(input: Self::Input) -> Result<Self::Answer, Error> {
        exact(input)
    }

    fn compute_in_field(problem: &Problem) -> Result<Self::Answer, Error> {
        let input: Input<FieldNumber> = problem.input_in_field(&[])?;
        exact_answer(&input, |x: &FieldNumber| x.0.clone())
    }
}

impl FloatKind for RuledPlane {
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

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Ring;
    use exactcheck_exact::univariate::UPoly;
    use exactcheck_exact::Rational;

    fn q(s: &str) -> Rational {
        s.parse().expect("a rational")
    }

    #[test]
    fn rational_zeros_are_exact_and_irrational_ones_isolated() {
        // (t - 1/3)^2 (t^2 - 1/2): a double rational zero and 1/sqrt 2.
        let p = UPoly::from_roots(&[q("1/3"), q("1/3")]).mul_ref(&UPoly::from_coeffs(vec![
            q("-1/2"),
            Rational::ZERO,
            Rational::ONE,
        ]));
        let width = q("1/1000000");
        let z = unit_zeros(&p.to_bernstein(), &width);
        assert_eq!(z.len(), 2, "{z:?}");
        assert_eq!(z[0], IsolatedRoot::Exact(q("1/3")));
        match &z[1] {
            IsolatedRoot::Between(lo, hi) => {
                assert!(lo.square() < q("1/2") && hi.square() > q("1/2"));
                assert!(hi.sub_ref(lo) <= width);
            }
            other => panic!("{other:?}"),
        }
        let b = p.to_bernstein();
        assert_eq!(roots::multiplicity(&b, &z[0]), 2);
        assert_eq!(roots::multiplicity(&b, &z[1]), 1);
        assert_eq!(common_multiplicity(&b, &b.derivative(), &z[0]), 1);
        assert_eq!(common_multiplicity(&b, &b.derivative(), &z[1]), 0);
    }
}
