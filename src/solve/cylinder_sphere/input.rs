//! The input of `cylinder_sphere`: its types (and their JSON Schema), the angles in their two
//! forms, and the configuration read from them exactly or in f64.

use crate::solve::number::{Coords, FloatNumber, Radians, RationalNumber};
use crate::solve::parse;
use crate::Error;
use exactcheck_core::cylinder_sphere::{Angle, CylinderSphere};
use exactcheck_core::{OrderedField, Sign, Vec3};
use exactcheck_exact::Rational;
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::{Deserialize, Serialize};
use std::borrow::Cow;

/// The problem, with numbers of type `N` (in exact mode
/// [`RationalOrFieldNumber`](crate::solve::number::RationalOrFieldNumber), or
/// [`RationalNumber`] where only rational input is wanted, and
/// [`FieldNumber`](crate::solve::number::FieldNumber) in the number field; [`FloatNumber`] with
/// `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "cylinder_sphere",
    description = "A cylinder and a sphere (Spaeth): decide whether and how they meet, the touching points or circle, A(t) and B(t), the parametrization and sample points of the intersection curve. Exact mode reads exact numbers: rational ones, or algebraic values such as \"cos(pi/8)\" and \"sqrt(2 + sqrt(3))\" when one of the problem's values leaves the square-root field (the problem is then computed in its number field); --float reads any finite number."
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
    /// The width to which irrational ends of the real tau-intervals are isolated (a positive
    /// rational number).
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
            "description": "An angle: a point {cos, sin} of the unit circle (exact mode: cos^2 + sin^2 = 1 exactly), or {radians} (exact mode takes the nearest rational point with tan(theta/2) of denominator <= 10^6 and reports it under approximated_angles); not both.",
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

/// An angle read exactly: `{cos, sin}` read by `num` and checked on the unit circle exactly;
/// `{radians}` taken as a nearby rational point (noted in `notes`) and lifted by `lift`.
pub(super) fn exact_angle<N, T: OrderedField + std::fmt::Display>(
    a: &AngleInput<N>,
    path: &str,
    notes: &mut Vec<AngleNote>,
    num: impl Fn(&N) -> T,
    lift: impl Fn(&Rational) -> T,
) -> Result<Angle<T>, Error> {
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
            Ok(Angle {
                cos: lift(&angle.cos),
                sin: lift(&angle.sin),
            })
        }
        AngleForm::Point(c, s) => {
            let (c, s) = (num(c), num(s));
            let norm = c.square() + s.square();
            if norm != T::one() {
                return Err(Error::Input(format!("{path}: cos^2 + sin^2 = {norm} != 1")));
            }
            Ok(Angle { cos: c, sin: s })
        }
    }
}

pub(super) fn float_angle(a: &AngleInput<FloatNumber>, path: &str) -> Result<Angle<f64>, Error> {
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
pub(super) fn configuration<N, T: OrderedField>(
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
            |a, p| exact_angle(a, p, &mut notes, |x| x.0.clone(), Rational::clone),
        )
        .map(|(cs, _)| cs)
    });
    Ok(Configurations {
        float,
        exact,
        approximated_angles: notes,
    })
}
