//! Conics as plane sections of the cone `x^2 + y^2 = z^2` (Chiang, "Conic
//! table"), written once and generic over the scalar.
//!
//! # The cone as two ruled surfaces
//! With apex `B(t) = 0` (`n = 0`) the cone is swept by the rulings `s V(t)`, where `V` is a
//! quadratic direction field (`m = 2`) whose control vectors are the homogeneous control points
//! of a rational quarter circle:
//!
//! ```text
//!     V+ : (1,0,1),  (1/sqrt2)(1,1,1),  (0,1,1)     the quarter x, y >= 0
//!     V- : (0,1,1), -(1/sqrt2)(1,1,1),  (1,0,1)     the other three quarters
//! ```
//!
//! (`V(t)_x^2 + V(t)_y^2 = V(t)_z^2` identically; the negative middle weight of `V-` gives the
//! complementary arc). Each piece, with `t` running over all of `R`, parametrizes the whole
//! circle of directions, so each alone already knows the whole conic.
//!
//! # The section
//! For the plane `N . x + d = 0` Chiang's theorem ([`crate::ruled`]) with `p_0 = 0` gives a
//! rational quadratic Bezier curve per piece: `w_k = N . q_k`, `w_k r_k = -d q_k`. Its poles are
//! the zeros of the weight polynomial in `[0, 1]` (rulings parallel to the plane). A plane through
//! the apex (`d = 0`) has every weighted point zero: the section is degenerate — the apex alone,
//! a double line or a line pair, the rulings at the real zeros of the weight polynomial.
//!
//! # The type, two independent ways
//! * [`angle_rule`] — the paper's rule on the angle `theta` between the normal and the cone's
//!   axis: `theta = 0` circle, `0 < theta < pi/4` ellipse, `theta = pi/4` parabola, otherwise
//!   hyperbola. Decided without trigonometry: `theta = 0` iff `a = b = 0`, and `theta` against
//!   `pi/4` is `cos^2 theta = c^2 / |N|^2` against `1/2`, i.e. the sign of `c^2 - (a^2 + b^2)`.
//!   (`theta` is taken in `[0, pi/2]`: a normal and its negative are the same plane.)
//! * [`bezier_type`] — from one section piece's own data: the weight polynomial
//!   `w0 (1-t)^2 + 2 w1 t(1-t) + w2 t^2` has `(w1^2 - w0 w2)`'s sign as its discriminant, so the
//!   conic has no, one (double) or two real points at infinity: ellipse, parabola, hyperbola
//!   (projective invariant: unchanged by reparametrization and weight scaling). An ellipse is a
//!   circle iff its control polygon is isosceles, `|r1 - r0| = |r2 - r1|`, and
//!   `w1^2 / (w0 w2) = cos^2 alpha`, `alpha` the angle at `r0` between the chord and the leg
//!   (all squared: exact comparisons in the field). With `d = 0` the same discriminant counts the
//!   rulings in the plane: none (the apex alone), one double, two.
//!
//! [`ConeSection::check_types`] compares them; the claim `chiang.conic_type` runs it on Table 1
//! and on thousands of random planes. The cone needs `1/sqrt 2`, so the tests live with an exact
//! scalar that has it (`tests/solve/conic_core.rs`, over `exactcheck_exact::Radical`).

use crate::bernstein::Bernstein;
use crate::bezier::{BezierCurve, RationalBezierCurve};
use crate::roots::{unit_roots, IsolatedRoot};
use crate::ruled::{Plane, RuledSurface};
use crate::scalar::{OrderedField, Ring, Sign};
use crate::vector::Vec3;
use std::fmt;

/// The two ruled surfaces of the cone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ConePiece {
    /// `V+`, the quarter cone over `x, y >= 0`.
    Plus,
    /// `V-`, the three-quarter cone.
    Minus,
}

impl ConePiece {
    /// Both pieces, `+` first.
    pub const BOTH: [ConePiece; 2] = [ConePiece::Plus, ConePiece::Minus];

    /// `"+"` or `"-"`.
    pub fn sign(self) -> &'static str {
        match self {
            ConePiece::Plus => "+",
            ConePiece::Minus => "-",
        }
    }
}

/// The type of a non-degenerate conic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ConicType {
    /// A circle.
    Circle,
    /// An ellipse that is not a circle.
    Ellipse,
    /// A parabola.
    Parabola,
    /// A hyperbola.
    Hyperbola,
}

/// A degenerate section (plane through the apex).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DegenerateConic {
    /// The apex alone (a steep plane).
    Point,
    /// One ruling, counted twice (a tangent plane).
    DoubleLine,
    /// Two rulings.
    LinePair,
}

/// What a plane cuts from the cone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SectionType {
    /// A proper conic.
    Conic(ConicType),
    /// A plane through the apex.
    Degenerate(DegenerateConic),
}

impl SectionType {
    /// Every section type: the four conics, then the three degenerate sections.
    pub const ALL: [SectionType; 7] = [
        SectionType::Conic(ConicType::Circle),
        SectionType::Conic(ConicType::Ellipse),
        SectionType::Conic(ConicType::Parabola),
        SectionType::Conic(ConicType::Hyperbola),
        SectionType::Degenerate(DegenerateConic::Point),
        SectionType::Degenerate(DegenerateConic::DoubleLine),
        SectionType::Degenerate(DegenerateConic::LinePair),
    ];

    /// `circle`, `ellipse`, `parabola`, `hyperbola`, `point`, `double_line`, `line_pair`.
    pub fn name(self) -> &'static str {
        match self {
            SectionType::Conic(ConicType::Circle) => "circle",
            SectionType::Conic(ConicType::Ellipse) => "ellipse",
            SectionType::Conic(ConicType::Parabola) => "parabola",
            SectionType::Conic(ConicType::Hyperbola) => "hyperbola",
            SectionType::Degenerate(DegenerateConic::Point) => "point",
            SectionType::Degenerate(DegenerateConic::DoubleLine) => "double_line",
            SectionType::Degenerate(DegenerateConic::LinePair) => "line_pair",
        }
    }
}

impl fmt::Display for SectionType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The plane's normal is the zero vector (for a scalar whose squares can vanish, one whose
/// `a^2 + b^2` and `c^2` are both zero).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ZeroNormal;

impl fmt::Display for ZeroNormal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("the normal is the zero vector: there is no plane")
    }
}

impl std::error::Error for ZeroNormal {}

/// The cone's ruled surface `piece` (apex at the origin); `inv_sqrt2` is `1/sqrt 2` in `T`.
pub fn cone_surface<T: Ring>(piece: ConePiece, inv_sqrt2: &T) -> RuledSurface<T> {
    let v = |x: i64, y: i64, z: i64| Vec3::new(T::from_i64(x), T::from_i64(y), T::from_i64(z));
    let mid = |s: &T| Vec3::new(s.clone(), s.clone(), s.clone());
    let directions = match piece {
        ConePiece::Plus => vec![v(1, 0, 1), mid(inv_sqrt2), v(0, 1, 1)],
        ConePiece::Minus => vec![v(0, 1, 1), mid(&inv_sqrt2.neg_ref()), v(1, 0, 1)],
    };
    RuledSurface::new(
        BezierCurve::new(vec![v(0, 0, 0)]),
        BezierCurve::new(directions),
    )
}

/// The paper's classification by the angle between the normal and the axis (module doc):
/// for a plane through the apex the degenerate counterpart (ellipse or circle: the apex alone;
/// parabola: a double line; hyperbola: a line pair).
///
/// # Errors
/// [`ZeroNormal`].
pub fn angle_rule<T: OrderedField>(plane: &Plane<T>) -> Result<SectionType, ZeroNormal> {
    let n = &plane.normal;
    let horizontal = n.x.square() + n.y.square();
    let vertical = n.z.square();
    if horizontal.is_zero() && vertical.is_zero() {
        return Err(ZeroNormal);
    }
    let conic = if horizontal.is_zero() {
        ConicType::Circle
    } else {
        match vertical.sub_ref(&horizontal).sign() {
            Sign::Positive => ConicType::Ellipse,
            Sign::Zero => ConicType::Parabola,
            Sign::Negative => ConicType::Hyperbola,
        }
    };
    Ok(if plane.d.is_zero() {
        SectionType::Degenerate(degenerate_of(conic))
    } else {
        SectionType::Conic(conic)
    })
}

fn degenerate_of(conic: ConicType) -> DegenerateConic {
    match conic {
        ConicType::Circle | ConicType::Ellipse => DegenerateConic::Point,
        ConicType::Parabola => DegenerateConic::DoubleLine,
        ConicType::Hyperbola => DegenerateConic::LinePair,
    }
}

/// The type of a rational quadratic Bezier section piece from its own weights and points
/// (module doc); `None` when the piece is not a conic section of the cone as built here (not
/// quadratic, or control points that do not span a conic: collinear with non-zero weighted
/// points).
pub fn bezier_type<T: OrderedField>(piece: &RationalBezierCurve<T>) -> Option<SectionType> {
    if piece.degree() != 2 {
        return None;
    }
    let c = piece.control();
    let w = piece.weights();
    let disc = w[1].square().sub_ref(&w[0].mul_ref(&w[2]));
    let rank = disc.sign();
    let weighted_zero = c.iter().all(|h| h.0[1..].iter().all(Ring::is_zero));
    if weighted_zero {
        return Some(SectionType::Degenerate(match rank {
            Sign::Negative => DegenerateConic::Point,
            Sign::Zero => DegenerateConic::DoubleLine,
            Sign::Positive => DegenerateConic::LinePair,
        }));
    }
    let conic = match rank {
        Sign::Positive => ConicType::Hyperbola,
        Sign::Zero => ConicType::Parabola,
        Sign::Negative => {
            if is_circle(piece) {
                ConicType::Circle
            } else {
                ConicType::Ellipse
            }
        }
    };
    Some(SectionType::Conic(conic))
}

/// The circle test of an elliptic piece (`w0 w2 > w1^2 >= 0`, so the end points are finite;
/// module doc): isosceles control polygon and `w1^2 / (w0 w2) = cos^2 alpha`, compared
/// cross-multiplied. With `w1 = 0` the middle control vector is a direction `v` (a half
/// ellipse on the chord): a circle iff `v` is perpendicular to the chord and
/// `4 |v|^2 = w0 w2 |chord|^2`.
fn is_circle<T: OrderedField>(piece: &RationalBezierCurve<T>) -> bool {
    let c = piece.control();
    let w = piece.weights();
    let point = |k: usize| {
        c[k].to_point()
            .expect("an elliptic piece has non-zero end weights")
    };
    let (p0, p2) = (point(0), point(2));
    let minus = T::from_i64(-1);
    let chord = p2.add_scaled(&minus, &p0);
    let w02 = w[0].mul_ref(&w[2]);
    if w[1].is_zero() {
        let v = Vec3::new(c[1].0[1].clone(), c[1].0[2].clone(), c[1].0[3].clone());
        return v.dot(&chord).is_zero()
            && v.norm_squared().scale_i64(4) == w02.mul_ref(&chord.norm_squared());
    }
    let p1 = point(1);
    let leg0 = p1.add_scaled(&minus, &p0);
    let leg1 = p2.add_scaled(&minus, &p1);
    if leg0.norm_squared() != leg1.norm_squared() {
        return false;
    }
    // w1^2 |leg0|^2 |chord|^2 = w0 w2 (leg0 . chord)^2
    let lhs = w[1]
        .square()
        .mul_ref(&leg0.norm_squared())
        .mul_ref(&chord.norm_squared());
    let rhs = w02.mul_ref(&leg0.dot(&chord).square());
    lhs == rhs
}

/// One piece of a section: the rational quadratic Bezier curve and its poles.
#[derive(Clone, Debug, PartialEq)]
pub struct SectionPiece<T> {
    /// Which cone piece.
    pub piece: ConePiece,
    /// The curve (Chiang's theorem; all weighted points zero for a plane through the apex).
    pub curve: RationalBezierCurve<T>,
    /// The parameters in `[0, 1]` where the weight vanishes: points at infinity of a conic, or
    /// the rulings lying in a plane through the apex.
    pub poles: Vec<IsolatedRoot<T>>,
}

/// The section of the cone by a plane: both pieces.
#[derive(Clone, Debug, PartialEq)]
pub struct ConeSection<T> {
    /// The plane.
    pub plane: Plane<T>,
    /// `+` and `-`.
    pub pieces: [SectionPiece<T>; 2],
}

/// The type decided both ways, and whether they agree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TypeCheck {
    /// By the paper's angle rule.
    pub angle_rule: SectionType,
    /// By each piece's weights and points (`None`: not a conic piece).
    pub bezier: [Option<SectionType>; 2],
}

impl TypeCheck {
    /// All three verdicts equal.
    pub fn agree(&self) -> bool {
        self.bezier.iter().all(|b| *b == Some(self.angle_rule))
    }
}

impl<T: OrderedField> ConeSection<T> {
    /// The section of the cone by `plane`; `inv_sqrt2` is `1/sqrt 2` in `T`.
    ///
    /// # Errors
    /// [`ZeroNormal`].
    pub fn new(plane: Plane<T>, inv_sqrt2: &T) -> Result<Self, ZeroNormal> {
        // The angle rule's own test (`a^2 + b^2` and `c^2` both zero), so that `check_types`
        // cannot meet a zero normal: in a field the same as a zero vector, and in a scalar whose
        // squares can vanish for non-zero numbers, the refusal of such a normal.
        angle_rule(&plane)?;
        let piece = |piece: ConePiece| {
            let curve = cone_surface(piece, inv_sqrt2).plane_section(&plane);
            let weight: Bernstein<T> = curve.weight_polynomial();
            let poles = unit_roots(&weight)
                .expect("the weight polynomial N.V is not zero for a non-zero normal");
            SectionPiece {
                piece,
                curve,
                poles,
            }
        };
        let pieces = [piece(ConePiece::Plus), piece(ConePiece::Minus)];
        Ok(ConeSection { plane, pieces })
    }

    /// The type by the angle rule and by each piece's own data.
    pub fn check_types(&self) -> TypeCheck {
        TypeCheck {
            angle_rule: angle_rule(&self.plane).expect("new() refuses the zero normal"),
            bezier: [
                bezier_type(&self.pieces[0].curve),
                bezier_type(&self.pieces[1].curve),
            ],
        }
    }
}
