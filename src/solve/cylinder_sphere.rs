//! `solve` kind `cylinder_sphere` (Spaeth): decision, touching points or circle,
//! coefficients of A and B, parametrization and sample points of the intersection curve.
//!
//! Exact mode works over Q with rational angles `{cos, sin}` (checked on the unit circle;
//! `{radians}` is approximated by a nearby rational point and the answer says so); sample points
//! are computed in the square-root field (or in `Q[w]/(w^2 - D)` when the radicand cannot be
//! certified square-free), so each lies exactly on both surfaces (checked and reported). The
//! touching points are the multiple roots of the discriminant (module doc of
//! `exactcheck_core::cylinder_sphere`), each checked exactly on both surfaces; an identically
//! vanishing discriminant is reported as the touching circle (centre, radius, normal), checked
//! exactly at four of its points. Float mode evaluates the same generic formulas in f64 and
//! refuses non-finite input and overflowing coefficients.

use super::number::{Coords, FloatNumber, Radians, RationalNumber};
use super::{parse, FloatKind, Kind};
use crate::Error;
use exactcheck_core::cylinder_sphere::{
    unit_circle_point, Angle, Contact, CylinderSphere, TrigCoefficients,
};
use exactcheck_core::{OrderedField, Ring, Sign, Vec3};
use exactcheck_exact::cylinder_sphere::analyze;
use exactcheck_exact::univariate::{Bound, RootInterval};
use exactcheck_exact::{Radical, Rational};
use num_rational::BigRational;
use num_traits::One;
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::{Deserialize, Serialize};
use std::borrow::Cow;

// ------------------------------------------------------------------ input

/// The problem, with numbers of type `N` ([`RationalNumber`] in exact mode, [`FloatNumber`]
/// with `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "cylinder_sphere",
    description = "A cylinder and a sphere (Spaeth): decide whether and how they meet, the touching points or circle, A(t) and B(t), the parametrization and sample points of the intersection curve. Exact mode needs rational numbers; --float reads any finite number."
)]
pub struct Input<N> {
    /// `"cylinder_sphere"`.
    #[schemars(extend("const" = "cylinder_sphere"))]
    pub kind: String,
    /// The cylinder.
    pub cylinder: CylinderInput<N>,
    /// The sphere.
    pub sphere: SphereInput<N>,
    /// Number of sample angles (at least 1, at most the `samples` limit; default 12).
    #[schemars(range(min = 1))]
    pub samples: Option<u64>,
    /// The width to which irrational ends of the real tau-intervals are isolated (positive).
    pub precision: Option<N>,
}

/// The cylinder: radius `r` about the z axis through `(a, b, 0)`, rotated by `beta` (x-z plane)
/// then `gamma` (y-z plane).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CylinderInput<N> {
    /// `[a, b]`.
    pub axis_point: Coords<N, 2>,
    /// `r > 0`.
    pub radius: N,
    /// The rotation in the x-z plane.
    pub beta: AngleInput<N>,
    /// The rotation in the y-z plane.
    pub gamma: AngleInput<N>,
}

/// The sphere.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SphereInput<N> {
    /// `[d, e, f]`.
    pub center: Coords<N, 3>,
    /// `R > 0`.
    pub radius: N,
}

/// An angle: `{cos, sin}` (a point of the unit circle) or `{radians}`, not both.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AngleInput<N> {
    /// The cosine.
    pub cos: Option<N>,
    /// The sine.
    pub sin: Option<N>,
    /// The angle in radians.
    pub radians: Option<Radians>,
}

impl<N: JsonSchema> JsonSchema for AngleInput<N> {
    fn schema_name() -> Cow<'static, str> {
        format!("Angle_{}", N::schema_name()).into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let n = generator.subschema_for::<N>();
        let radians = generator.subschema_for::<Radians>();
        json_schema!({
            "description": "An angle: a point {cos, sin} of the unit circle (exact mode: rational, cos^2 + sin^2 = 1 exactly), or {radians} (exact mode takes the nearest rational point with tan(theta/2) of denominator <= 10^6 and reports it under approximated_angles); not both.",
            "oneOf": [
                {
                    "type": "object",
                    "properties": {"cos": n, "sin": n},
                    "required": ["cos", "sin"],
                    "additionalProperties": false
                },
                {
                    "type": "object",
                    "properties": {"radians": radians},
                    "required": ["radians"],
                    "additionalProperties": false
                }
            ]
        })
    }
}

/// An angle field, checked for exactly one of its two forms.
enum AngleForm<'a, N> {
    Point(&'a N, &'a N),
    Radians(f64),
}

fn angle_form<'a, N>(a: &'a AngleInput<N>, path: &str) -> Result<AngleForm<'a, N>, Error> {
    match (&a.cos, &a.sin, &a.radians) {
        (Some(c), Some(s), None) => Ok(AngleForm::Point(c, s)),
        (None, None, Some(r)) => Ok(AngleForm::Radians(r.0)),
        (_, _, Some(_)) => Err(Error::Input(format!(
            "{path}: give either {{cos, sin}} or {{radians}}, not both"
        ))),
        (Some(_), None, None) => Err(Error::Input(format!("missing field \"{path}.sin\""))),
        (None, Some(_), None) => Err(Error::Input(format!("missing field \"{path}.cos\""))),
        (None, None, None) => Err(Error::Input(format!(
            "{path}: an angle is {{cos, sin}} (a point of the unit circle) or {{radians}}"
        ))),
    }
}

/// A `{radians}` angle taken as a nearby rational point, as reported in the answer.
#[derive(Clone, Debug, Serialize)]
pub struct AngleNote {
    /// The field (`cylinder.beta`).
    pub field: String,
    /// The given angle.
    pub radians: f64,
    /// The rational `tau = tan(theta'/2)` taken.
    pub rational_tau: String,
    /// Its cosine, exact.
    pub cos: String,
    /// Its sine, exact.
    pub sin: String,
    /// `theta' - theta`.
    pub deviation_radians: f64,
}

fn exact_angle(
    a: &AngleInput<RationalNumber>,
    path: &str,
    notes: &mut Vec<AngleNote>,
) -> Result<Angle<Rational>, Error> {
    match angle_form(a, path)? {
        AngleForm::Radians(theta) => {
            let (angle, tau, dev) =
                exactcheck_exact::cylinder_sphere::rational_angle(theta, 1_000_000);
            notes.push(AngleNote {
                field: path.into(),
                radians: theta,
                rational_tau: tau.to_string(),
                cos: angle.cos.to_string(),
                sin: angle.sin.to_string(),
                deviation_radians: dev,
            });
            Ok(angle)
        }
        AngleForm::Point(c, s) => {
            let norm = c.0.square() + s.0.square();
            if norm != Rational::ONE {
                return Err(Error::Input(format!("{path}: cos^2 + sin^2 = {norm} != 1")));
            }
            Ok(Angle {
                cos: c.0.clone(),
                sin: s.0.clone(),
            })
        }
    }
}

fn float_angle(a: &AngleInput<FloatNumber>, path: &str) -> Result<Angle<f64>, Error> {
    match angle_form(a, path)? {
        AngleForm::Radians(t) => Ok(Angle {
            cos: t.cos(),
            sin: t.sin(),
        }),
        AngleForm::Point(c, s) => {
            let (c, s) = (c.0, s.0);
            if ((c * c + s * s) - 1.0).abs() > 1e-9 {
                return Err(Error::Input(format!(
                    "{path}: cos^2 + sin^2 = {} is not 1",
                    c * c + s * s
                )));
            }
            Ok(Angle { cos: c, sin: s })
        }
    }
}

/// The configuration and the sample count, from a problem whose numbers are read by `num` and
/// angles by `angle`.
fn configuration<N, T: OrderedField>(
    input: &Input<N>,
    num: impl Fn(&N) -> T,
    mut angle: impl FnMut(&AngleInput<N>, &str) -> Result<Angle<T>, Error>,
) -> Result<(CylinderSphere<T>, usize), Error> {
    let cyl = &input.cylinder;
    let [a, b] = &cyl.axis_point.0;
    let [d, e, f] = &input.sphere.center.0;
    let cs = CylinderSphere {
        a: num(a),
        b: num(b),
        r: num(&cyl.radius),
        beta: angle(&cyl.beta, "cylinder.beta")?,
        gamma: angle(&cyl.gamma, "cylinder.gamma")?,
        center: Vec3::new(num(d), num(e), num(f)),
        radius: num(&input.sphere.radius),
    };
    if cs.r.sign() != Sign::Positive {
        return Err(Error::Input("cylinder.radius must be positive".into()));
    }
    if cs.radius.sign() != Sign::Positive {
        return Err(Error::Input("sphere.radius must be positive".into()));
    }
    let samples = match input.samples {
        None => 12,
        Some(0) => return Err(Error::Input("samples must be at least 1".into())),
        Some(n) => {
            crate::limits::SAMPLES.check(n)?;
            usize::try_from(n).expect("within the samples limit, which fits memory")
        }
    };
    Ok((cs, samples))
}

/// The configurations of a `cylinder_sphere` problem for drawing it: in f64 (the problem must
/// be valid in `--float` mode) and, when the problem is exact input, exactly.
pub struct Configurations {
    /// The f64 configuration.
    pub float: CylinderSphere<f64>,
    /// The exact configuration, or why there is none (e.g. floating literals, irrational input).
    pub exact: Result<CylinderSphere<Rational>, Error>,
    /// The `{radians}` angles taken as rational points in `exact`.
    pub approximated_angles: Vec<AngleNote>,
}

/// Reads a `cylinder_sphere` problem as `solve` does, both ways (the kind is not checked).
///
/// # Errors
/// [`Error::Input`] when the problem is not valid in `--float` mode.
pub fn configurations(text: &str) -> Result<Configurations, Error> {
    let finput: Input<FloatNumber> = parse(text)?;
    let (float, _) = configuration(&finput, |x| x.0, float_angle)?;
    let mut notes = Vec::new();
    let exact = parse::<Input<RationalNumber>>(text).and_then(|input| {
        configuration(
            &input,
            |x| x.0.clone(),
            |a, p| exact_angle(a, p, &mut notes),
        )
        .map(|(cs, _)| cs)
    });
    Ok(Configurations {
        float,
        exact,
        approximated_angles: notes,
    })
}

// ------------------------------------------------------------------ answers

/// A trigonometric polynomial: its basis and coefficients.
#[derive(Debug, Serialize)]
struct TrigPoly<T> {
    basis: &'static [&'static str],
    coefficients: Vec<T>,
}

/// A and B of `u^2 + 2 A u + B = 0`.
#[derive(Debug, Serialize)]
struct Coefficients<T> {
    #[serde(rename = "A")]
    a: TrigPoly<T>,
    #[serde(rename = "B")]
    b: TrigPoly<T>,
}

impl<T> Coefficients<T> {
    fn new<S>(c: &TrigCoefficients<S>, f: impl Fn(&S) -> T) -> Self {
        Coefficients {
            a: TrigPoly {
                basis: &["1", "cos t", "sin t"],
                coefficients: c.a.iter().map(&f).collect(),
            },
            b: TrigPoly {
                basis: &["1", "cos t", "sin t", "cos^2 t", "cos t sin t", "sin^2 t"],
                coefficients: c.b.iter().map(&f).collect(),
            },
        }
    }
}

/// A touching point.
#[derive(Debug, Serialize)]
#[serde(untagged)]
enum TangentPoint {
    /// At a rational tau (or t = pi), with the point exactly.
    Exact {
        tau: String,
        point: [String; 3],
        approx: [f64; 3],
        on_both_surfaces: bool,
    },
    /// At an irrational tau, given by an isolating interval.
    Isolated {
        tau_interval: [String; 2],
        approx: TauApprox,
    },
}

#[derive(Debug, Serialize)]
struct TauApprox {
    tau: f64,
}

/// The circle along which the surfaces touch (discriminant identically zero).
#[derive(Debug, Serialize)]
struct TangentCircle {
    /// Its centre (the sphere's centre, on the axis).
    center: [String; 3],
    /// Its radius (the cylinder's).
    radius: String,
    /// The normal of its plane (the axis direction).
    normal: [String; 3],
    /// Its cylinder coordinate `u = -A(t)` (constant).
    u: String,
    /// Exact check at `t = 0, pi/2, pi, 3 pi/2`: the points `x(t, u)` lie on both surfaces, at
    /// distance `radius` from `center`, in the plane through `center` normal to `normal`.
    on_both_surfaces: bool,
    approx: CircleApprox,
}

#[derive(Debug, Serialize)]
struct CircleApprox {
    center: [f64; 3],
    radius: f64,
}

/// An end of a real tau-interval.
#[derive(Debug, Serialize)]
#[serde(untagged)]
enum End {
    Exact(String),
    Isolated { interval: [String; 2], approx: f64 },
}

#[derive(Debug, Serialize)]
struct Parametrization {
    angle: &'static str,
    u: &'static str,
    #[serde(rename = "P")]
    p: String,
    point: &'static str,
    real_for_tau_in: Vec<[End; 2]>,
    real_at_t_pi: bool,
}

#[derive(Debug, Serialize)]
struct Sample {
    tau: String,
    cos: String,
    sin: String,
    t_degrees: f64,
    u: Vec<String>,
    points: Vec<[String; 3]>,
}

/// A point exactly as text, and its f64 approximation.
type PointText = ([String; 3], [f64; 3]);

#[derive(Debug, Serialize)]
struct CurvePoint {
    exact: [String; 3],
    approx: [f64; 3],
}

/// The exact answer.
#[derive(Debug, Serialize)]
pub(crate) struct ExactAnswer {
    kind: &'static str,
    mode: &'static str,
    intersects: bool,
    contact: &'static str,
    contact_by_axis_distance: &'static str,
    methods_agree: bool,
    components: usize,
    tangent_points: Vec<TangentPoint>,
    tangent_circle: Option<TangentCircle>,
    coefficients: Coefficients<String>,
    parametrization: Parametrization,
    samples: Vec<Sample>,
    points: Vec<CurvePoint>,
    all_points_on_both_surfaces: bool,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    approximated_angles: Vec<AngleNote>,
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<FloatAnswer>,
}

#[derive(Debug, Serialize)]
struct FloatSample {
    t: f64,
    cos: f64,
    sin: f64,
    u: Vec<f64>,
    points: Vec<[f64; 3]>,
}

/// The `--float` answer.
#[derive(Debug, Serialize)]
pub(crate) struct FloatAnswer {
    kind: &'static str,
    mode: &'static str,
    intersects: bool,
    contact_by_axis_distance: &'static str,
    coefficients: Coefficients<f64>,
    samples: Vec<FloatSample>,
}

/// The kind.
pub struct CylinderSphereKind;

impl Kind for CylinderSphereKind {
    const NAME: &'static str = "cylinder_sphere";
    type Input = Input<RationalNumber>;
    type Answer = ExactAnswer;

    fn compute(input: Self::Input) -> Result<ExactAnswer, Error> {
        exact(input)
    }
}

impl FloatKind for CylinderSphereKind {
    type FloatInput = Input<FloatNumber>;
    type FloatAnswer = FloatAnswer;

    fn compute_float(input: Self::FloatInput) -> Result<FloatAnswer, Error> {
        float_answer(input)
    }
}

impl super::Attach<FloatAnswer> for ExactAnswer {
    fn attach(&mut self, float: Result<FloatAnswer, Error>) -> Result<(), Error> {
        self.float = Some(float?);
        Ok(())
    }
}

/// The name of a contact in the answer.
fn contact_name(c: Contact) -> &'static str {
    match c {
        Contact::Disjoint => "disjoint",
        Contact::Tangent => "tangent",
        Contact::Crossing => "crossing",
    }
}

fn strings<T: ToString>(v: &Vec3<T>) -> [String; 3] {
    [v.x.to_string(), v.y.to_string(), v.z.to_string()]
}

fn approx3(v: &Vec3<Radical>) -> [f64; 3] {
    [v.x.to_f64() + 0.0, v.y.to_f64() + 0.0, v.z.to_f64() + 0.0]
}

/// Whether `x` lies on the sphere and on the cylinder of `cs`, exactly.
fn on_both<T: OrderedField>(cs: &CylinderSphere<T>, x: &Vec3<T>) -> bool {
    let (axis_q, axis_d) = cs.axis();
    let sphere = (x - &cs.center).norm_squared() == cs.radius.square();
    let cyl = (x - &axis_q).cross(&axis_d).norm_squared() == cs.r.square();
    sphere && cyl
}

fn exact(input: Input<RationalNumber>) -> Result<ExactAnswer, Error> {
    let mut notes = Vec::new();
    let (cs, n_samples) = configuration(
        &input,
        |x| x.0.clone(),
        |a, p| exact_angle(a, p, &mut notes),
    )?;
    let width = match &input.precision {
        None => None,
        Some(RationalNumber(w)) => {
            if w.sign() != Sign::Positive {
                return Err(Error::Input("precision must be positive".into()));
            }
            super::number::check_precision(w)?;
            Some(w.clone())
        }
    };
    let analysis = analyze(&cs);
    let by_distance = cs.contact_by_distance();
    let coeffs = cs.trig_coefficients();
    let p = &analysis.discriminant;
    let half = Rational::new(1, 2).expect("2 != 0");
    // Sample parameters: rational tau on a grid of angles, plus one inside every interval, kept
    // where the discriminant is >= 0.
    let mut taus: Vec<Rational> = Vec::new();
    for k in 0..n_samples {
        let t = std::f64::consts::TAU * k as f64 / n_samples as f64;
        if (t - std::f64::consts::PI).abs() > 1e-9 {
            let (_, tau, _) = exactcheck_exact::cylinder_sphere::rational_angle(t, 1000);
            taus.push(tau);
        }
    }
    for iv in &analysis.nonnegative {
        let mid = match (&iv.lo, &iv.hi) {
            (Bound::Root(a), Bound::Root(b)) => (a.midpoint() + b.midpoint()) * &half,
            (Bound::NegInf, Bound::Root(b)) => b.lo.clone() - Rational::ONE,
            (Bound::Root(a), Bound::PosInf) => a.hi.clone() + Rational::ONE,
            // The whole line (an interval never starts at +inf or ends at -inf).
            _ => Rational::ZERO,
        };
        taus.push(mid);
    }
    taus.sort();
    taus.dedup();
    let lift = |q: &Rational| Radical::from(q);
    let rcs = cs.map(lift);
    let mut samples = Vec::new();
    let mut points = Vec::new();
    let mut all_on_both = true;
    for tau in &taus {
        if p.sign_at(tau) == Sign::Negative {
            continue;
        }
        let angle = unit_circle_point(tau).expect("1 + tau^2 > 0 for rational tau");
        let (a, b) = cs.coefficients_at(&angle.cos, &angle.sin);
        let disc = a.square() - &b;
        // u and the points: in the radical field, or in Q(w), w^2 = disc, when the radicand
        // cannot be certified square-free or is too big to factor quickly (the square-free
        // part needs a factorization: a few hundred digits already take seconds).
        let small =
            disc.numer().bits() <= MAX_FACTORED_BITS && disc.denom().bits() <= MAX_FACTORED_BITS;
        let root = if small {
            Radical::sqrt_rational(&disc)
        } else {
            None
        };
        let (us, pts): (Vec<String>, Vec<PointText>) = match root {
            None => {
                let (pts, ok) = quadratic_points(&cs, &angle, &a, &disc);
                all_on_both &= ok;
                let minus_a = a.neg_ref();
                (
                    vec![
                        format!("{minus_a} - sqrt({disc})"),
                        format!("{minus_a} + sqrt({disc})"),
                    ],
                    pts,
                )
            }
            Some(root) => {
                let (c, s) = (lift(&angle.cos), lift(&angle.sin));
                let minus_a = lift(&a).neg_ref();
                let us: Vec<Radical> = if disc.is_zero() {
                    vec![minus_a]
                } else {
                    vec![minus_a.sub_ref(&root), minus_a.add_ref(&root)]
                };
                let pts: Vec<Vec3<Radical>> = us.iter().map(|u| rcs.point(&c, &s, u)).collect();
                all_on_both &= pts.iter().all(|x| on_both(&rcs, x));
                (
                    us.iter().map(ToString::to_string).collect(),
                    pts.iter().map(|x| (strings(x), approx3(x))).collect(),
                )
            }
        };
        samples.push(Sample {
            tau: tau.to_string(),
            cos: angle.cos.to_string(),
            sin: angle.sin.to_string(),
            t_degrees: 2.0 * tau.to_f64().atan().to_degrees(),
            u: us,
            points: pts.iter().map(|p| p.0.clone()).collect(),
        });
        points.extend(
            pts.into_iter()
                .map(|(exact, approx)| CurvePoint { exact, approx }),
        );
    }
    // Touching points: every multiple root of the discriminant.
    let mut tangent_points = Vec::new();
    for tp in &analysis.tangent_params {
        let (angle, tau_text) = match tp {
            None => (
                Angle {
                    cos: Rational::from_integer(-1),
                    sin: Rational::ZERO,
                },
                "infinity (t = pi)".to_string(),
            ),
            Some(ri) => match ri.exact_value() {
                Some(v) => (
                    unit_circle_point(v).expect("1 + tau^2 > 0 for rational tau"),
                    v.to_string(),
                ),
                None => {
                    let w = Rational::new(1, 1 << 40).expect("2^40 != 0");
                    let refined = p.try_refine(ri, &w)?;
                    tangent_points.push(TangentPoint::Isolated {
                        tau_interval: [refined.lo.to_string(), refined.hi.to_string()],
                        approx: TauApprox {
                            tau: refined.to_f64(),
                        },
                    });
                    continue;
                }
            },
        };
        let (a, _) = cs.coefficients_at(&angle.cos, &angle.sin);
        let x = cs.point(&angle.cos, &angle.sin, &a.neg_ref());
        let ok = on_both(&cs, &x);
        all_on_both &= ok;
        let xr = x.map(lift);
        tangent_points.push(TangentPoint::Exact {
            tau: tau_text,
            point: strings(&x),
            approx: approx3(&xr),
            on_both_surfaces: ok,
        });
    }
    let tangent_circle = analysis.touching_circle.then(|| tangent_circle(&cs));
    if let Some(c) = &tangent_circle {
        all_on_both &= c.on_both_surfaces;
    }
    // Interval ends to the requested precision.
    let refine = |r: &RootInterval| match &width {
        Some(w) if !r.is_exact() => p.try_refine(r, w),
        _ => Ok(r.clone()),
    };
    let end = |x: &Bound| -> Result<End, Error> {
        Ok(match x {
            Bound::NegInf => End::Exact("-inf".into()),
            Bound::PosInf => End::Exact("+inf".into()),
            Bound::Root(r) => match r.exact_value() {
                Some(v) => End::Exact(v.to_string()),
                None => {
                    let r = refine(r)?;
                    End::Isolated {
                        interval: [r.lo.to_string(), r.hi.to_string()],
                        approx: r.to_f64(),
                    }
                }
            },
        })
    };
    let intervals = analysis
        .nonnegative
        .iter()
        .map(|iv| Ok([end(&iv.lo)?, end(&iv.hi)?]))
        .collect::<Result<_, Error>>()?;
    Ok(ExactAnswer {
        kind: "cylinder_sphere",
        mode: "exact",
        intersects: analysis.contact != Contact::Disjoint,
        contact: contact_name(analysis.contact),
        contact_by_axis_distance: contact_name(by_distance),
        methods_agree: analysis.contact == by_distance
            && analysis.touching() == Some(cs.touching_by_distance()),
        components: analysis.components,
        tangent_points,
        tangent_circle,
        coefficients: Coefficients::new(&coeffs, ToString::to_string),
        parametrization: Parametrization {
            angle: "cos t = (1 - tau^2)/(1 + tau^2), sin t = 2*tau/(1 + tau^2) (tau = infinity at t = pi)",
            u: "-A(t) +- sqrt(P(tau))/(1 + tau^2)",
            p: p.display("tau").to_string(),
            point: "Rx(gamma) Ry(beta) (a + r cos t, b + r sin t, u)",
            real_for_tau_in: intervals,
            real_at_t_pi: analysis.sign_at_pi != Sign::Negative,
        },
        samples,
        points,
        all_points_on_both_surfaces: all_on_both,
        approximated_angles: notes,
        float: None,
    })
}

/// The largest numerator or denominator (in bits) of a sample's discriminant that is factored
/// to write its square root in the radical field; bigger ones use `Q[w]/(w^2 - D)`.
const MAX_FACTORED_BITS: u64 = 256;

/// The touching circle of a configuration whose discriminant vanishes identically: centre and
/// radius from the geometry (the sphere's centre on the axis, the cylinder's radius), `u` from
/// `A` at `t = 0`, and the exact check at four of its points.
fn tangent_circle(cs: &CylinderSphere<Rational>) -> TangentCircle {
    let (_, normal) = cs.axis();
    let (a0, _) = cs.coefficients_at(&Rational::ONE, &Rational::ZERO);
    let u = a0.neg_ref();
    let quarter_turns = [(1, 0), (0, 1), (-1, 0), (0, -1)];
    let ok = quarter_turns.iter().all(|&(c, s)| {
        let (c, s) = (Rational::from_integer(c), Rational::from_integer(s));
        let x = cs.point(&c, &s, &u);
        let rel = &x - &cs.center;
        on_both(cs, &x) && rel.norm_squared() == cs.r.square() && rel.dot(&normal).is_zero()
    });
    TangentCircle {
        center: strings(&cs.center),
        radius: cs.r.to_string(),
        normal: strings(&normal),
        u: u.to_string(),
        on_both_surfaces: ok,
        approx: CircleApprox {
            center: [
                cs.center.x.to_f64() + 0.0,
                cs.center.y.to_f64() + 0.0,
                cs.center.z.to_f64() + 0.0,
            ],
            radius: cs.r.to_f64(),
        },
    }
}

fn float_answer(input: Input<FloatNumber>) -> Result<FloatAnswer, Error> {
    let (cs, n) = configuration(&input, |x| x.0, float_angle)?;
    let coeffs = cs.trig_coefficients();
    if !coeffs
        .a
        .iter()
        .chain(coeffs.b.iter())
        .all(|x| x.is_finite())
    {
        return Err(Error::Input(
            "--float: the coefficients of A and B overflow f64 for this input; use exact mode"
                .into(),
        ));
    }
    let sampler = exactcheck_float::sampler::DiscSampler::new(&cs);
    let mut samples = Vec::new();
    for k in 0..n {
        let t = std::f64::consts::TAU * k as f64 / n as f64;
        let (s, c) = t.sin_cos();
        let u: Vec<f64> = sampler
            .roots(t)
            .map(|(a, b)| vec![a, b])
            .unwrap_or_default();
        let points: Vec<[f64; 3]> = u.iter().map(|u| cs.point(&c, &s, u).into_array()).collect();
        if !u
            .iter()
            .chain(points.iter().flatten())
            .all(|x| x.is_finite())
        {
            return Err(Error::Input(format!(
                "--float: the curve point at t = {t} overflows f64 for this input; use exact mode"
            )));
        }
        samples.push(FloatSample {
            t,
            cos: c,
            sin: s,
            u,
            points,
        });
    }
    let contact = cs.contact_by_distance();
    Ok(FloatAnswer {
        kind: "cylinder_sphere",
        mode: "float",
        intersects: contact != Contact::Disjoint,
        contact_by_axis_distance: contact_name(contact),
        coefficients: Coefficients::new(&coeffs, |x| *x),
        samples,
    })
}

/// The two curve points at an angle where `u = -A +- sqrt(disc)` and `sqrt(disc)` is not
/// available in the radical field: coordinates `p + q sqrt(disc)` computed over `Q[w]` modulo
/// `w^2 - disc`, and the exact check that both lie on the sphere and the cylinder (the surface
/// equations reduce to 0 modulo `w^2 - disc`).
fn quadratic_points(
    cs: &CylinderSphere<Rational>,
    angle: &Angle<Rational>,
    a: &Rational,
    disc: &Rational,
) -> (Vec<PointText>, bool) {
    use exactcheck_exact::poly::Poly;
    type P = Poly<Rational>;
    let k = |q: &Rational| P::constant(q.clone());
    let w = P::var(0);
    let relation = [w.square() - k(disc)];
    let pcs = cs.map(k);
    let (axis_q, axis_d) = pcs.axis_polynomial();
    let mut ok = true;
    let mut pts = Vec::new();
    for sign in [-1i64, 1] {
        let u = k(&a.neg_ref()) + w.scale_i64(sign);
        let x = pcs.point(&k(&angle.cos), &k(&angle.sin), &u);
        let sphere = ((&x - &pcs.center).norm_squared() - pcs.radius.square()).reduce(&relation);
        let cyl = ((&x - &axis_q).cross(&axis_d).norm_squared() - pcs.r.square()).reduce(&relation);
        ok &= sphere.is_zero() && cyl.is_zero();
        let coord = |c: &P| {
            let p0 = c.coefficient(&[]);
            let p1 = c.coefficient(&[(0, 1)]);
            let text = if p1.is_zero() {
                p0.to_string()
            } else {
                format!("{p0} + {p1}*sqrt({disc})")
            };
            // The one conversion of sums of roots: finite and NaN-free where the terms alone
            // leave f64's range.
            let approx = exactcheck_exact::to_f64::sum_of_roots_to_f64(&[
                (p0.to_big_rational(), BigRational::one()),
                (p1.to_big_rational(), disc.to_big_rational()),
            ]);
            (text, approx + 0.0)
        };
        let (cx, cy, cz) = (coord(&x.x), coord(&x.y), coord(&x.z));
        pts.push(([cx.0, cy.0, cz.0], [cx.1, cy.1, cz.1]));
    }
    (pts, ok)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact(text: &str) -> Result<ExactAnswer, Error> {
        super::exact(parse(text)?)
    }

    fn problem(center: &str, radius: &str) -> String {
        format!(
            r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":5,"beta":{{"cos":1,"sin":0}},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":{center},"radius":{radius}}},"samples":4}}"#
        )
    }

    #[test]
    fn the_touching_circle_is_reported_and_checked() {
        // The reported example: centre (0,0,3) on the axis, R = r = 5.
        let a = exact(&problem("[0,0,3]", "5")).unwrap();
        assert_eq!(a.contact, "tangent");
        assert_eq!(a.contact_by_axis_distance, "tangent");
        assert!(a.methods_agree);
        assert!(a.tangent_points.is_empty());
        let c = a.tangent_circle.expect("a touching circle");
        assert_eq!(c.center, ["0", "0", "3"]);
        assert_eq!(c.radius, "5");
        assert_eq!(c.u, "3");
        assert!(c.on_both_surfaces);
        assert!(a.all_points_on_both_surfaces);
    }

    #[test]
    fn the_figure_eight_touches_at_its_crossing_point() {
        // centre (2,0,0), R = 7 = r + delta: touching at (-5, 0, 0), t = pi.
        let a = exact(&problem("[2,0,0]", "7")).unwrap();
        assert_eq!(a.contact, "crossing");
        assert!(a.methods_agree);
        assert!(a.tangent_circle.is_none());
        assert_eq!(a.tangent_points.len(), 1);
        match &a.tangent_points[0] {
            TangentPoint::Exact {
                tau,
                point,
                on_both_surfaces,
                ..
            } => {
                assert_eq!(tau, "infinity (t = pi)");
                assert_eq!(point, &["-5", "0", "0"]);
                assert!(on_both_surfaces);
            }
            other => panic!("{other:?}"),
        }
    }
}
