//! `solve` kind `cylinder_sphere` (Spaeth): decision, touching points or circle,
//! coefficients of A and B, parametrization and sample points of the intersection curve.
//!
//! Exact mode works over Q with rational angles `{cos, sin}` (checked on the unit circle;
//! `{radians}` is approximated by a nearby rational point and the answer says so), and over the
//! problem's number field when its values leave the square-root field (`"cos(pi/8)"`, module
//! `field`); sample points are computed in the square-root field (or in `Q[w]/(w^2 - D)` when the radicand cannot be
//! certified square-free), so each lies exactly on both surfaces (checked and reported). The
//! touching points are the multiple roots of the discriminant (module doc of
//! `exactcheck_core::cylinder_sphere`), each checked exactly on both surfaces; an identically
//! vanishing discriminant is reported as the touching circle (centre, radius, normal), checked
//! exactly at four of its points. Float mode evaluates the same generic formulas in f64 and
//! refuses non-finite input and overflowing coefficients.

use super::number::{FieldNumber, FloatNumber, RationalOrFieldNumber};
use super::scalar::Scalar;
use super::{FloatKind, Kind, Problem};
use crate::Error;
use exactcheck_core::cylinder_sphere::{Contact, CylinderSphere};
use exactcheck_core::{OrderedField, Vec3};

pub use answer::ExactAnswer;
pub use float::FloatAnswer;
pub use input::{
    configurations, AngleInput, AngleNote, Configurations, CylinderInput, Input, SphereInput,
};

mod answer;
mod exact;
mod field;
mod float;
mod input;
#[cfg(test)]
mod tests;

/// The kind.
pub struct CylinderSphereKind;

impl Kind for CylinderSphereKind {
    const NAME: &'static str = "cylinder_sphere";
    type Input = Input<RationalOrFieldNumber>;
    type Answer = ExactAnswer;

    fn compute(input: Self::Input) -> Result<ExactAnswer, Error> {
        exact::exact(input)
    }

    const RATIONAL_OR_FIELD: bool = true;

    fn compute_in_field(problem: &Problem) -> Result<ExactAnswer, Error> {
        let input: Input<FieldNumber> = problem.input_in_field(&[])?;
        field::exact_in_field(input)
    }
}

impl FloatKind for CylinderSphereKind {
    type FloatInput = Input<FloatNumber>;
    type FloatAnswer = FloatAnswer;

    fn compute_float(input: Self::FloatInput) -> Result<FloatAnswer, Error> {
        float::float_answer(input)
    }
}

impl super::Attach<FloatAnswer> for ExactAnswer {
    fn attach(&mut self, float: Result<FloatAnswer, Error>) -> Result<(), Error> {
        self.float = Some(float?);
        Ok(())
    }
}

/// The name of a contact in the answer.
pub(super) fn contact_name(c: Contact) -> &'static str {
    match c {
        Contact::Disjoint => "disjoint",
        Contact::Tangent => "tangent",
        Contact::Crossing => "crossing",
    }
}

pub(super) fn strings<T: ToString>(v: &Vec3<T>) -> [String; 3] {
    [v.x.to_string(), v.y.to_string(), v.z.to_string()]
}

/// The f64 approximations of a point's coordinates (`-0` as `0`).
pub(super) fn approx3<T: Scalar>(v: &Vec3<T>) -> [f64; 3] {
    [v.x.approx(), v.y.approx(), v.z.approx()]
}

/// Whether `x` lies on the sphere and on the cylinder of `cs`, exactly.
pub(super) fn on_both<T: OrderedField>(cs: &CylinderSphere<T>, x: &Vec3<T>) -> bool {
    let (axis_q, axis_d) = cs.axis();
    let sphere = (x - &cs.center).norm_squared() == cs.radius.square();
    let cyl = (x - &axis_q).cross(&axis_d).norm_squared() == cs.r.square();
    sphere && cyl
}
