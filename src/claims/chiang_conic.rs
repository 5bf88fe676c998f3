//! The conic claims of Chiang ("Conic table"): `chiang.conic_table` (Table 1,
//! every printed entry against the exact derivation) and `chiang.conic_type` (the paper's angle
//! rule against the conic's own invariants, on Table 1 and on thousands of random planes).
//!
//! # The table
//! Table 1 is kept **as printed data** ([`TABLE1`]): the restoration of the OCR'd scan (square
//! roots restored, signs as printed), plus the plane equations as the OCR reads them (the
//! restoration leaves those out) and, in [`OCR_READINGS`], the OCR's literal reading of every
//! entry where it differs from the restoration. Each column is derived exactly over [`Radical`] (`Q(sqrt 2)`
//! here): the plane through `(1, 1, 1)` with the printed normal `N` is `N . x = N . (1,1,1)`, and
//! [`ConeSection::new`] cuts the cone's two ruled surfaces with it (Chiang's theorem with apex
//! `B = 0`: `w_k = N . q_k`, `w_k r_k = -d q_k`). Entries are judged one by one:
//! * a weight is *equal*, or *equal up to the common weight scale* (the three printed weights of
//!   the piece are the derived ones times one non-zero factor `lambda`, which leaves the curve
//!   unchanged; the factor is reported), or *different* (both values shown);
//! * a control point is equal or different (points are invariant under weight scaling);
//! * the poles `C-(t) = inf`: every printed parameter is a zero of the derived weight polynomial
//!   in `[0, 1]` (exact evaluation at the printed radical), and every derived pole (an isolating
//!   interval from `exactcheck_core::roots`, narrowed to width `<= 1/1024`, or the exact root)
//!   holds exactly one printed value.
//!   `C+` has no printed poles: its derived poles are reported, not judged;
//! * the normal: the printed control points `r0+, r1+, r2+` span a plane with this normal;
//! * the plane equation: it is the plane through `(1, 1, 1)` with the printed normal (the
//!   coefficient vectors `(a, b, c, rhs)` are proportional).
//!
//! Where the OCR's literal reading differs from the restoration the evidence says, computed,
//! which of the two the derivation supports.
//!
//! # The type
//! [`check_section`] decides the type of a section three ways and requires them to agree: the
//! paper's angle rule ([`angle_rule`]: exact comparisons of `c^2` with `a^2 + b^2`, no
//! trigonometry), the weight discriminant and circle test of **each** piece
//! ([`exactcheck_core::conic::bezier_type`]), and the number of rulings parallel to the plane —
//! the distinct zeros of the weight polynomials of the two pieces (which together run once
//! around the circle of directions; their shared end directions `(1,0,1)` and `(0,1,1)` counted
//! once): 0 for an ellipse, a circle or the apex alone, 1 for a parabola or a double line, 2 for
//! a hyperbola or a line pair. Every section's curve points at several exact rational parameters
//! are then substituted into the plane and into `x^2 + y^2 - z^2`. The random planes
//! ([`random_plane`], seeded workspace [`Rng`]) come from generators aimed at the boundaries:
//! `theta = pi/4` exactly (Pythagorean normals and radical ones `(a, b, sqrt(a^2 + b^2))`), circles
//! (`a = b = 0`), `c = 0`, planes through the apex (`d = 0`), pieces with `w1 = 0`
//! (`a + b + c = 0`) and normals with radical entries (`q + q' sqrt k`).
//!
//! Nothing here is hand-written mathematics beyond the bookkeeping: the sections, poles and types
//! are `exactcheck_core::conic`'s, computed over the exact field.

use super::{Claim, Outcome, Verdict};
use exactcheck_core::bezier::RationalBezierCurve;
use exactcheck_core::conic::{
    angle_rule, bezier_type, ConePiece, ConeSection, ConicType, DegenerateConic, SectionPiece,
    SectionType,
};
use exactcheck_core::roots::{IsolatedRoot, Refiner};
use exactcheck_core::ruled::Plane;
use exactcheck_core::{Field, Hom4, Ring, Rng, Vec3};
use exactcheck_exact::{Radical, Rational};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// The `chiang.conic_*` claims, statements as printed.
pub fn claims() -> Vec<Claim> {
    vec![
        claim!("chiang.conic_table", Holds, "Table 1 (cone K = V+ quarter, control vectors (1,0,1), (1/sqrt2)(1,1,1), (0,1,1), and V- three-quarter, (0,1,1), -(1/sqrt2)(1,1,1), (1,0,1); planes I through (1,1,1)): normal (0,0,1) circle: z - 1 = 0, w+ = 1, 1/sqrt2, 1, r+ = (1,0,1), (1,1,1), (0,1,1), w- = 1, -1/sqrt2, 1, r- = the + points reversed, C-(t) = inf: none; (1,1,3) ellipse: x + y + 3z = 4, w+ = 4, 5/sqrt2, 4, r+ = (5/4,0,5/4), (1,1,1), (0,5/4,5/4), w- = 4, -5/sqrt2, 4, C-: none; (1,1,sqrt2) parabola: x + y + sqrt2 z = 2 - sqrt2 (OCR), w+ = 1+sqrt2 (all three), r+ = (sqrt2,0,sqrt2), (1,1,1), (0,sqrt2,sqrt2), w- = 1+sqrt2, -sqrt2-1, 1+sqrt2, C-: t = 1/2; (1,1,0) hyperbola: x + y = 2, w+ = 1, sqrt2, 1, r+ = (2,0,2), (1,1,1), (0,2,2), w- = 1, -sqrt2, 1, C-: t = 1/sqrt2, t = 1 - 1/sqrt2", conic_table_claim),
        claim!("chiang.conic_type", Holds, "The intersection of the plane I with the cone K is a circle, an ellipse, a parabola or a hyperbola as the angle theta between the normal of I and the axis of K is 0, between 0 and pi/4, pi/4, or between pi/4 and pi/2 (Table 1: (0,0,1) circle, (1,1,3) ellipse, (1,1,sqrt2) parabola, (1,1,0) hyperbola)", conic_type_claim),
    ]
}

fn conic_table_claim() -> Result<Outcome, String> {
    check_table(&TABLE1)
}

fn conic_type_claim() -> Result<Outcome, String> {
    check_types(TYPE_SEED, TYPE_PLANES)
}

// ------------------------------------------------------------------------------ the data

/// A plane equation `a x + b y + c z = rhs` as printed.
#[derive(Clone, Copy, Debug)]
pub struct PrintedPlane {
    /// The equation, square roots restored as in the rest of the table.
    pub text: &'static str,
    /// The OCR's literal tokens (the seed's reading order).
    pub ocr: &'static str,
    /// `a, b, c, rhs`.
    pub coefficients: [&'static str; 4],
}

/// One column of Table 1, as printed (numbers in the workspace's number syntax).
#[derive(Clone, Copy, Debug)]
pub struct PrintedColumn {
    /// The column's heading: `circle`, `ellipse`, `parabola`, `hyperbola`.
    pub name: &'static str,
    /// The normal of the plane I.
    pub normal: [&'static str; 3],
    /// The plane equation (OCR'd; the restoration leaves it out).
    pub plane: PrintedPlane,
    /// `w0+ w1+ w2+`.
    pub weights_plus: [&'static str; 3],
    /// `r0+ r1+ r2+`.
    pub points_plus: [[&'static str; 3]; 3],
    /// `w0- w1- w2-`.
    pub weights_minus: [&'static str; 3],
    /// `r0- r1- r2-` ("the + points in reverse order", written out).
    pub points_minus: [[&'static str; 3]; 3],
    /// The row `C-(t) = inf` (empty: "none").
    pub poles_minus: &'static [&'static str],
}

/// Table 1 as the claim list restores it (plane equations as the OCR reads them).
pub const TABLE1: [PrintedColumn; 4] = [
    PrintedColumn {
        name: "circle",
        normal: ["0", "0", "1"],
        plane: PrintedPlane {
            text: "z - 1 = 0",
            ocr: "01 =−z",
            coefficients: ["0", "0", "1", "1"],
        },
        weights_plus: ["1", "1/sqrt(2)", "1"],
        points_plus: [["1", "0", "1"], ["1", "1", "1"], ["0", "1", "1"]],
        weights_minus: ["1", "-1/sqrt(2)", "1"],
        points_minus: [["0", "1", "1"], ["1", "1", "1"], ["1", "0", "1"]],
        poles_minus: &[],
    },
    PrintedColumn {
        name: "ellipse",
        normal: ["1", "1", "3"],
        plane: PrintedPlane {
            text: "x + y + 3z = 4",
            ocr: "43 =++ zyx",
            coefficients: ["1", "1", "3", "4"],
        },
        weights_plus: ["4", "5/sqrt(2)", "4"],
        points_plus: [["5/4", "0", "5/4"], ["1", "1", "1"], ["0", "5/4", "5/4"]],
        weights_minus: ["4", "-5/sqrt(2)", "4"],
        points_minus: [["0", "5/4", "5/4"], ["1", "1", "1"], ["5/4", "0", "5/4"]],
        poles_minus: &[],
    },
    PrintedColumn {
        name: "parabola",
        normal: ["1", "1", "sqrt(2)"],
        plane: PrintedPlane {
            text: "x + y + sqrt2 z = 2 - sqrt2",
            ocr: "222 −=++ zyx",
            coefficients: ["1", "1", "sqrt(2)", "2 - sqrt(2)"],
        },
        weights_plus: ["1 + sqrt(2)", "1 + sqrt(2)", "1 + sqrt(2)"],
        points_plus: [
            ["sqrt(2)", "0", "sqrt(2)"],
            ["1", "1", "1"],
            ["0", "sqrt(2)", "sqrt(2)"],
        ],
        weights_minus: ["1 + sqrt(2)", "-sqrt(2) - 1", "1 + sqrt(2)"],
        points_minus: [
            ["0", "sqrt(2)", "sqrt(2)"],
            ["1", "1", "1"],
            ["sqrt(2)", "0", "sqrt(2)"],
        ],
        poles_minus: &["1/2"],
    },
    PrintedColumn {
        name: "hyperbola",
        normal: ["1", "1", "0"],
        plane: PrintedPlane {
            text: "x + y = 2",
            ocr: "2=+ yx",
            coefficients: ["1", "1", "0", "2"],
        },
        weights_plus: ["1", "sqrt(2)", "1"],
        points_plus: [["2", "0", "2"], ["1", "1", "1"], ["0", "2", "2"]],
        weights_minus: ["1", "-sqrt(2)", "1"],
        points_minus: [["0", "2", "2"], ["1", "1", "1"], ["2", "0", "2"]],
        poles_minus: &["1/sqrt(2)", "1 - 1/sqrt(2)"],
    },
];

/// The OCR's literal reading of an entry where it differs from the restoration.
#[derive(Clone, Copy, Debug)]
pub struct OcrReading {
    /// The column (`circle`, ...).
    pub column: &'static str,
    /// The entry (`w1+`, `r0-`, `C-(t) = inf`).
    pub entry: &'static str,
    /// The seed's characters.
    pub ocr: &'static str,
    /// What they literally say: one number (weight), three (point) or the pole parameters.
    pub reading: &'static [&'static str],
}

/// Every entry of the scanned Table 1 whose OCR differs from the restoration (lost square
/// roots: `2 1` is `1/2` literally, restored as `1/sqrt2`).
pub const OCR_READINGS: [OcrReading; 17] = [
    ocr("circle", "w1+", "2 1", &["1/2"]),
    ocr("circle", "w1-", "2 1 −", &["-1/2"]),
    ocr("ellipse", "w1+", "2 5", &["5/2"]),
    ocr("ellipse", "w1-", "2 5 −", &["-5/2"]),
    ocr("parabola", "w0+", "21+", &["1 + 2"]),
    ocr("parabola", "w1+", "21+", &["1 + 2"]),
    ocr("parabola", "w2+", "21+", &["1 + 2"]),
    ocr("parabola", "w0-", "21+", &["1 + 2"]),
    ocr("parabola", "w1-", "21−−", &["-2 - 1"]),
    ocr("parabola", "w2-", "21+", &["1 + 2"]),
    ocr("parabola", "r0+", ")2,0,2(", &["2", "0", "2"]),
    ocr("parabola", "r2+", ")2,2,0(", &["0", "2", "2"]),
    ocr("parabola", "r0-", ")2,2,0(", &["0", "2", "2"]),
    ocr("parabola", "r2-", ")2,0,2(", &["2", "0", "2"]),
    ocr("hyperbola", "w1+", "2", &["2"]),
    ocr("hyperbola", "w1-", "2−", &["-2"]),
    ocr(
        "hyperbola",
        "C-(t) = inf",
        "2 1=t 2 11, 2 1 −== tt",
        &["1/2", "1 - 1/2"],
    ),
];

const fn ocr(
    column: &'static str,
    entry: &'static str,
    ocr: &'static str,
    reading: &'static [&'static str],
) -> OcrReading {
    OcrReading {
        column,
        entry,
        ocr,
        reading,
    }
}

// ------------------------------------------------------------------------ the judgement

/// How a printed entry compares with the derived one.
#[derive(Clone, Debug, PartialEq)]
pub enum Judgement {
    /// Equal.
    Equal,
    /// A weight equal to the derived one times the piece's common factor `lambda`
    /// (`printed = lambda * derived` for all three weights of the piece; points unchanged).
    Scaled(Radical),
    /// Different (both values are in the row).
    Different,
    /// Not printed: the derived value is reported only.
    NotPrinted,
}

impl Judgement {
    /// Whether the entry is right (equal, or equal up to the weight scale).
    pub fn is_right(&self) -> bool {
        matches!(self, Judgement::Equal | Judgement::Scaled(_))
    }

    fn text(&self) -> String {
        match self {
            Judgement::Equal => "equal".into(),
            Judgement::Scaled(l) => {
                format!("equal up to the common weight scale (printed = {l} x derived)")
            }
            Judgement::Different => "**different**".into(),
            Judgement::NotPrinted => "not printed (derived only)".into(),
        }
    }
}

/// One entry of Table 1: printed against derived.
#[derive(Clone, Debug)]
pub struct TableRow {
    /// The column (`circle`, ...).
    pub column: &'static str,
    /// The entry (`normal`, `plane`, `w0+`, `r1-`, `C-(t) = inf`, `C+(t) = inf`).
    pub entry: String,
    /// As printed.
    pub printed: String,
    /// As derived.
    pub derived: String,
    /// The judgement.
    pub judgement: Judgement,
    /// The derived value (one number for a weight, three for a point or a normal; empty for
    /// the other rows).
    pub derived_value: Vec<Radical>,
    /// Computed remarks: the OCR's reading and which reading the derivation supports.
    pub notes: Vec<String>,
}

fn num(text: &str) -> Result<Radical, String> {
    text.parse::<Radical>()
        .map_err(|e| format!("printed number {text:?}: {e}"))
}

fn vec3(texts: &[&str]) -> Result<Vec3<Radical>, String> {
    match texts {
        [x, y, z] => Ok(Vec3::new(num(x)?, num(y)?, num(z)?)),
        _ => Err(format!("a point needs three coordinates, got {texts:?}")),
    }
}

fn point_text(p: &Vec3<Radical>) -> String {
    format!("({}, {}, {})", p.x, p.y, p.z)
}

fn printed_point_text(p: &[&str; 3]) -> String {
    format!("({}, {}, {})", p[0], p[1], p[2])
}

/// `a x + b y + c z = rhs`, zero terms left out.
fn equation_text(n: &Vec3<Radical>, rhs: &Radical) -> String {
    let mut s = String::new();
    for (c, v) in [(&n.x, "x"), (&n.y, "y"), (&n.z, "z")] {
        if c.is_zero() {
            continue;
        }
        let text = c.to_string();
        let (neg, abs) = match text.strip_prefix('-') {
            Some(a) if !a.contains(['+', '-']) => (true, a.to_string()),
            _ => (false, text.clone()),
        };
        let coef = if abs == "1" {
            String::new()
        } else if abs.contains(['+', '-']) {
            format!("({abs}) ")
        } else {
            format!("{abs} ")
        };
        match (s.is_empty(), neg) {
            (true, true) => s.push('-'),
            (true, false) => {}
            (false, true) => s.push_str(" - "),
            (false, false) => s.push_str(" + "),
        }
        s.push_str(&coef);
        s.push_str(v);
    }
    format!("{s} = {rhs}")
}

fn poles_text(poles: &[IsolatedRoot<Radical>]) -> String {
    if poles.is_empty() {
        return "none".into();
    }
    poles
        .iter()
        .map(|p| match p {
            IsolatedRoot::Exact(t) => format!("t = {t}"),
            IsolatedRoot::Between(lo, hi) => format!("t in ({lo}, {hi})"),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn printed_poles_text(poles: &[&str]) -> String {
    if poles.is_empty() {
        "none".into()
    } else {
        poles
            .iter()
            .map(|t| format!("t = {t}"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// All 2x2 minors of the pair vanish: the vectors are proportional (or one is zero).
fn proportional(u: &[Radical], v: &[Radical]) -> bool {
    (0..u.len()).all(|i| (i + 1..u.len()).all(|j| u[i].mul_ref(&v[j]) == u[j].mul_ref(&v[i])))
}

/// The printed poles against the derived ones (module doc): the problems found (none: equal).
fn judge_poles(
    printed: &[Radical],
    printed_text: &[&str],
    derived: &[IsolatedRoot<Radical>],
    weight: &exactcheck_core::Bernstein<Radical>,
) -> Vec<String> {
    let mut problems = Vec::new();
    let (zero, one) = (Radical::zero(), Radical::one());
    for (t, text) in printed.iter().zip(printed_text) {
        let w = weight.eval(t);
        if !w.is_zero() {
            problems.push(format!("w-({text}) = {w}, not 0"));
        } else if *t < zero || *t > one {
            problems.push(format!("t = {text} is outside [0, 1]"));
        }
    }
    for pole in derived {
        let inside = printed
            .iter()
            .filter(|t| match pole {
                IsolatedRoot::Exact(x) => *t == x,
                IsolatedRoot::Between(lo, hi) => lo < *t && *t < hi,
            })
            .count();
        if inside != 1 {
            problems.push(format!(
                "the derived pole {} holds {inside} printed values",
                poles_text(std::slice::from_ref(pole))
            ));
        }
    }
    if printed.len() != derived.len() {
        problems.push(format!(
            "{} printed poles, {} derived",
            printed.len(),
            derived.len()
        ));
    }
    problems
}

/// The isolating intervals narrowed to width `<= 1/1024` (for the reader; the matching with the
/// printed values is exact either way).
fn refined_poles(
    weight: &exactcheck_core::Bernstein<Radical>,
    poles: &[IsolatedRoot<Radical>],
) -> Vec<IsolatedRoot<Radical>> {
    let width = Radical::from_ratio(1, 1024).expect("1024 != 0");
    let refiner = Refiner::new(weight);
    poles.iter().map(|p| refiner.refine(p, &width)).collect()
}

/// The rows of one piece: weights (with the common-scale test) and points.
fn piece_rows(
    column: &'static str,
    sign: &str,
    printed_w: &[&'static str; 3],
    printed_r: &[[&'static str; 3]; 3],
    derived_w: &[Radical],
    derived_r: &[Option<Vec3<Radical>>],
) -> Result<Vec<TableRow>, String> {
    let pw = printed_w
        .iter()
        .map(|t| num(t))
        .collect::<Result<Vec<_>, _>>()?;
    // printed = lambda * derived for one lambda != 0
    let lambda = if pw.iter().any(Ring::is_zero) || derived_w.iter().any(Ring::is_zero) {
        None
    } else {
        let l = pw[0]
            .checked_div(&derived_w[0])
            .expect("the derived weight is non-zero");
        pw.iter()
            .zip(derived_w)
            .all(|(p, d)| *p == l.mul_ref(d))
            .then_some(l)
    };
    let mut rows = Vec::new();
    for k in 0..3 {
        let judgement = if pw[k] == derived_w[k] {
            Judgement::Equal
        } else if let Some(l) = &lambda {
            Judgement::Scaled(l.clone())
        } else {
            Judgement::Different
        };
        rows.push(TableRow {
            column,
            entry: format!("w{k}{sign}"),
            printed: printed_w[k].to_string(),
            derived: derived_w[k].to_string(),
            judgement,
            derived_value: vec![derived_w[k].clone()],
            notes: Vec::new(),
        });
    }
    for k in 0..3 {
        let p = vec3(&printed_r[k])?;
        let (derived, judgement, derived_value) = match &derived_r[k] {
            Some(d) => (
                point_text(d),
                if *d == p {
                    Judgement::Equal
                } else {
                    Judgement::Different
                },
                d.clone().into_array().to_vec(),
            ),
            None => (
                "at infinity (w = 0)".to_string(),
                Judgement::Different,
                Vec::new(),
            ),
        };
        rows.push(TableRow {
            column,
            entry: format!("r{k}{sign}"),
            printed: printed_point_text(&printed_r[k]),
            derived,
            judgement,
            derived_value,
            notes: Vec::new(),
        });
    }
    Ok(rows)
}

/// `1/sqrt 2` in [`Radical`].
pub fn inv_sqrt2() -> Radical {
    Radical::sqrt_of(2)
        .checked_div(&Radical::from(2))
        .expect("2 != 0")
}

/// Every entry of `table` against the derivation (module doc), column by column, then the OCR
/// notes of [`OCR_READINGS`] attached to their rows.
///
/// # Errors
/// A printed number that does not parse, a zero printed normal (data errors).
pub fn table_rows(table: &[PrintedColumn]) -> Result<Vec<TableRow>, String> {
    let mut rows = Vec::new();
    let through = Vec3::new(Radical::one(), Radical::one(), Radical::one());
    for col in table {
        let n = vec3(&col.normal)?;
        let rhs = n.dot(&through);
        let plane = Plane::new(n.x.clone(), n.y.clone(), n.z.clone(), rhs.neg_ref());
        let section = ConeSection::new(plane, &inv_sqrt2())
            .map_err(|e| format!("{}: the printed normal: {e}", col.name))?;
        // the normal against the plane of the printed points r+
        let r: Vec<Vec3<Radical>> = col
            .points_plus
            .iter()
            .map(|p| vec3(p))
            .collect::<Result<_, _>>()?;
        let minus = Radical::from(-1);
        let spanned = r[1]
            .add_scaled(&minus, &r[0])
            .cross(&r[2].add_scaled(&minus, &r[0]));
        let normal_ok = !spanned.is_zero()
            && proportional(&n.clone().into_array(), &spanned.clone().into_array());
        rows.push(TableRow {
            column: col.name,
            entry: "normal".into(),
            printed: printed_point_text(&col.normal),
            derived: format!(
                "(r1+ - r0+) x (r2+ - r0+) = {} (of the printed points)",
                point_text(&spanned)
            ),
            judgement: if normal_ok {
                Judgement::Equal
            } else {
                Judgement::Different
            },
            derived_value: spanned.clone().into_array().to_vec(),
            notes: Vec::new(),
        });
        // the plane equation
        let pc = col
            .plane
            .coefficients
            .iter()
            .map(|t| num(t))
            .collect::<Result<Vec<_>, _>>()?;
        let derived_plane = [n.x.clone(), n.y.clone(), n.z.clone(), rhs.clone()];
        let plane_ok = pc.iter().any(|c| !c.is_zero()) && proportional(&pc, &derived_plane);
        let mut notes = vec![format!(
            "the OCR reads `{}` (the restoration leaves out the plane equations)",
            col.plane.ocr
        )];
        if !plane_ok {
            let at = pc[0].add_ref(&pc[1]).add_ref(&pc[2]);
            notes.push(format!(
                "the printed left side at (1, 1, 1) is {at}, the printed right side {}: the printed plane misses (1, 1, 1){}",
                pc[3],
                if proportional(&pc[..3], &derived_plane[..3]) {
                    "; its normal is the printed one"
                } else {
                    "; its normal is not the printed one"
                }
            ));
        }
        rows.push(TableRow {
            column: col.name,
            entry: "plane".into(),
            printed: col.plane.text.into(),
            derived: equation_text(&n, &rhs),
            judgement: if plane_ok {
                Judgement::Equal
            } else {
                Judgement::Different
            },
            derived_value: derived_plane.to_vec(),
            notes,
        });
        let [plus, minus_piece] = &section.pieces;
        rows.extend(piece_rows(
            col.name,
            "+",
            &col.weights_plus,
            &col.points_plus,
            &plus.curve.weights(),
            &plus.curve.points(),
        )?);
        rows.extend(piece_rows(
            col.name,
            "-",
            &col.weights_minus,
            &col.points_minus,
            &minus_piece.curve.weights(),
            &minus_piece.curve.points(),
        )?);
        let printed_poles = col
            .poles_minus
            .iter()
            .map(|t| num(t))
            .collect::<Result<Vec<_>, _>>()?;
        let weight = minus_piece.curve.weight_polynomial();
        let derived_minus = refined_poles(&weight, &minus_piece.poles);
        let problems = judge_poles(&printed_poles, col.poles_minus, &derived_minus, &weight);
        let mut notes = vec![format!(
            "w-(t) = ({}) (1-t)^2 + 2 ({}) t(1-t) + ({}) t^2",
            weight.coeffs()[0],
            weight.coeffs()[1],
            weight.coeffs()[2]
        )];
        if problems.is_empty() && !printed_poles.is_empty() {
            notes.push(
                "every printed t is an exact zero of w-(t) in [0, 1] and lies in its own derived isolating interval"
                    .into(),
            );
        }
        notes.extend(problems.iter().cloned());
        rows.push(TableRow {
            column: col.name,
            entry: "C-(t) = inf".into(),
            printed: printed_poles_text(col.poles_minus),
            derived: poles_text(&derived_minus),
            judgement: if problems.is_empty() {
                Judgement::Equal
            } else {
                Judgement::Different
            },
            derived_value: Vec::new(),
            notes,
        });
        rows.push(TableRow {
            column: col.name,
            entry: "C+(t) = inf".into(),
            printed: "(not printed)".into(),
            derived: poles_text(&refined_poles(&plus.curve.weight_polynomial(), &plus.poles)),
            judgement: Judgement::NotPrinted,
            derived_value: Vec::new(),
            notes: Vec::new(),
        });
    }
    attach_ocr_notes(table, &mut rows)?;
    Ok(rows)
}

/// For every [`OCR_READINGS`] entry: is the OCR's literal value the derived one? (computed)
fn attach_ocr_notes(table: &[PrintedColumn], rows: &mut [TableRow]) -> Result<(), String> {
    for reading in OCR_READINGS {
        let Some(col) = table.iter().find(|c| c.name == reading.column) else {
            continue;
        };
        let Some(row) = rows
            .iter_mut()
            .find(|r| r.column == reading.column && r.entry == reading.entry)
        else {
            return Err(format!(
                "OCR reading for {} {}: no such entry",
                reading.column, reading.entry
            ));
        };
        let literal = reading.reading.join(", ");
        let ocr_right = if reading.entry.starts_with('C') {
            let n = vec3(&col.normal)?;
            let rhs = n.dot(&Vec3::new(Radical::one(), Radical::one(), Radical::one()));
            let section = ConeSection::new(Plane::new(n.x, n.y, n.z, rhs.neg_ref()), &inv_sqrt2())
                .map_err(|e| format!("{}: {e}", col.name))?;
            let piece = &section.pieces[1];
            let ts = reading
                .reading
                .iter()
                .map(|t| num(t))
                .collect::<Result<Vec<_>, _>>()?;
            let weight = piece.curve.weight_polynomial();
            let values: Vec<String> = ts
                .iter()
                .zip(reading.reading)
                .map(|(t, text)| format!("w-({text}) = {}", weight.eval(t)))
                .collect();
            row.notes.push(format!(
                "OCR `{}` literally `{literal}`: {}",
                reading.ocr,
                values.join(", ")
            ));
            judge_poles(&ts, reading.reading, &piece.poles, &weight).is_empty()
        } else {
            let lit = reading
                .reading
                .iter()
                .map(|t| num(t))
                .collect::<Result<Vec<_>, _>>()?;
            let value = lit
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ");
            row.notes.push(format!(
                "OCR `{}` literally `{literal}` = {value}",
                reading.ocr
            ));
            lit == row.derived_value
        };
        let spec_right = row.judgement.is_right();
        row.notes.push(
            match (ocr_right, spec_right) {
                (true, true) => "both readings are the derived value",
                (true, false) => {
                    "the derivation supports the OCR's literal reading, not the restoration"
                }
                (false, true) => {
                    "the derivation supports the restoration, not the OCR's literal reading"
                }
                (false, false) => "the derivation supports neither reading",
            }
            .into(),
        );
    }
    Ok(())
}

/// The claim over a given table (the printed one is [`TABLE1`]; tests plant misprints).
///
/// # Errors
/// Data errors of [`table_rows`].
pub fn check_table(table: &[PrintedColumn]) -> Result<Outcome, String> {
    let rows = table_rows(table)?;
    let judged: Vec<&TableRow> = rows
        .iter()
        .filter(|r| r.judgement != Judgement::NotPrinted)
        .collect();
    let equal = judged
        .iter()
        .filter(|r| r.judgement == Judgement::Equal)
        .count();
    let scaled: Vec<String> = judged
        .iter()
        .filter_map(|r| match &r.judgement {
            Judgement::Scaled(l) => Some(format!("{} {} (factor {l})", r.column, r.entry)),
            _ => None,
        })
        .collect();
    // The plane equations are the OCR's reading only (the claim list restores normals, weights, points
    // and poles, not the equations): a mismatch there is reported, but the verdict is decided by
    // the restored entries.
    let describe = |r: &&TableRow| {
        format!(
            "{} {}: printed {}, derived {}{}",
            r.column,
            r.entry,
            r.printed,
            r.derived,
            if r.notes.is_empty() {
                String::new()
            } else {
                format!(" ({})", r.notes.join("; "))
            }
        )
    };
    let different: Vec<String> = judged
        .iter()
        .filter(|r| !r.judgement.is_right() && r.entry != "plane")
        .map(describe)
        .collect();
    let ocr_planes: Vec<String> = judged
        .iter()
        .filter(|r| !r.judgement.is_right() && r.entry == "plane")
        .map(describe)
        .collect();
    let mut evidence = format!(
        "{} columns x {} judged entries (normal, plane, 3 weights and 3 points per piece, C-(t) = inf): {equal} equal",
        table.len(),
        judged.len() / table.len().max(1)
    );
    if !scaled.is_empty() {
        let _ = write!(
            evidence,
            ", {} equal up to the common weight scale ({})",
            scaled.len(),
            scaled.join(", ")
        );
    }
    if different.is_empty() {
        evidence.push_str(", none of the restored entries different.");
    } else {
        let _ = write!(
            evidence,
            ", {} different: {}.",
            different.len(),
            different.join("; ")
        );
    }
    if !ocr_planes.is_empty() {
        let _ = write!(
            evidence,
            " Plane equations as the OCR reads them (not restored, so not part of the verdict; if the paper prints them so, they are misprints): {} of {} miss the plane through (1,1,1): {}.",
            ocr_planes.len(),
            table.len(),
            ocr_planes.join("; ")
        );
    }
    let ocr: Vec<String> = rows
        .iter()
        .filter(|r| r.notes.iter().any(|n| n.starts_with("OCR `")))
        .map(|r| format!("{} {}: {}", r.column, r.entry, r.notes.join(", ")))
        .collect();
    if !ocr.is_empty() {
        let _ = write!(
            evidence,
            " OCR against the restoration, computed: {}.",
            ocr.join("; ")
        );
    }
    let plus_poles: Vec<String> = rows
        .iter()
        .filter(|r| r.judgement == Judgement::NotPrinted)
        .map(|r| format!("{}: {}", r.column, r.derived))
        .collect();
    let _ = write!(
        evidence,
        " C+(t) = inf (not printed), derived: {}.",
        plus_poles.join("; ")
    );
    let _ = write!(
        evidence,
        " Table (entry: printed | derived | judgement): {}",
        rows.iter()
            .map(|r| format!(
                "{} {}: {} | {} | {}",
                r.column,
                r.entry,
                r.printed,
                r.derived,
                r.judgement.text()
            ))
            .collect::<Vec<_>>()
            .join("; ")
    );
    Ok(Outcome {
        verdict: if different.is_empty() {
            Verdict::Holds
        } else {
            Verdict::Fails
        },
        method: "exact derivation in Q(sqrt 2) (Radical): ConeSection of the plane through (1,1,1) with the printed normal; entries compared exactly, weights up to a common factor, poles by exact evaluation and root isolation".into(),
        evidence, erratum: None, })
}

/// Table 1 as Markdown for docs/papers/chiang.md: printed | derived | judgement, with the
/// computed notes.
///
/// # Errors
/// Data errors of [`table_rows`].
pub fn conic_table_markdown() -> Result<String, String> {
    let rows = table_rows(&TABLE1)?;
    let mut s = String::from(
        "| column | entry | printed | derived | judgement |\n| --- | --- | --- | --- | --- |\n",
    );
    for r in &rows {
        let mut j = r.judgement.text();
        if !r.notes.is_empty() {
            j = format!("{j}; {}", r.notes.join("; "));
        }
        let _ = writeln!(
            s,
            "| {} | {} | `{}` | `{}` | {} |",
            r.column,
            r.entry,
            r.printed,
            r.derived,
            j.replace('|', "\\|")
        );
    }
    Ok(s)
}

// ------------------------------------------------------------------------------ the type

/// The seed of `chiang.conic_type`'s random planes.
pub const TYPE_SEED: u64 = 2026;
/// How many random planes `chiang.conic_type` checks.
pub const TYPE_PLANES: usize = 3500;

/// The parameters at which every section's points are checked (exact).
pub const SAMPLE_T: [(i64, i64); 7] = [(0, 1), (1, 4), (1, 3), (1, 2), (3, 4), (1, 1), (-2, 3)];

/// A generator of random planes (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum PlaneKind {
    /// Small rational `a, b, c, d`.
    Generic,
    /// `theta = pi/4` with a Pythagorean normal `k (m^2 - n^2, 2mn, +-(m^2 + n^2))` (coordinates
    /// shuffled between `a` and `b`).
    Pythagorean,
    /// `theta = pi/4` with a radical `c = +-sqrt(a^2 + b^2)`.
    RadicalQuarter,
    /// `a = b = 0`.
    Circle,
    /// `c = 0`.
    Vertical,
    /// `a + b + c = 0`: both pieces have `w1 = 0`.
    ZeroMiddleWeight,
    /// Normal entries `q + q' sqrt k`, `k` in 2, 3, 5.
    RadicalNormal,
}

impl PlaneKind {
    /// Every generator.
    pub const ALL: [PlaneKind; 7] = [
        PlaneKind::Generic,
        PlaneKind::Pythagorean,
        PlaneKind::RadicalQuarter,
        PlaneKind::Circle,
        PlaneKind::Vertical,
        PlaneKind::ZeroMiddleWeight,
        PlaneKind::RadicalNormal,
    ];

    /// A short name for the evidence.
    pub fn name(self) -> &'static str {
        match self {
            PlaneKind::Generic => "generic",
            PlaneKind::Pythagorean => "theta=pi/4 Pythagorean",
            PlaneKind::RadicalQuarter => "theta=pi/4 radical",
            PlaneKind::Circle => "a=b=0",
            PlaneKind::Vertical => "c=0",
            PlaneKind::ZeroMiddleWeight => "a+b+c=0 (w1=0)",
            PlaneKind::RadicalNormal => "radical normal",
        }
    }
}

fn small_rational(rng: &mut Rng) -> Rational {
    let n = rng.below(19) as i64 - 9;
    let d = rng.below(5) as i64 + 1;
    Rational::new(n, d).expect("d >= 1")
}

fn nonzero_rational(rng: &mut Rng) -> Rational {
    loop {
        let q = small_rational(rng);
        if !q.is_zero() {
            return q;
        }
    }
}

/// A random plane of the given kind (through the apex when `through_apex`, otherwise with a
/// non-zero `d`); the normal is never zero.
pub fn random_plane(rng: &mut Rng, kind: PlaneKind, through_apex: bool) -> Plane<Radical> {
    let q = |rng: &mut Rng| Radical::from(small_rational(rng));
    let nz = |rng: &mut Rng| Radical::from(nonzero_rational(rng));
    let sign = |rng: &mut Rng, x: Radical| if rng.below(2) == 0 { x } else { x.neg_ref() };
    let (a, b, c) = match kind {
        PlaneKind::Generic => loop {
            let (a, b, c) = (q(rng), q(rng), q(rng));
            if !(a.is_zero() && b.is_zero() && c.is_zero()) {
                break (a, b, c);
            }
        },
        PlaneKind::Pythagorean => {
            let m = rng.below(6) as i64 + 1;
            let n = rng.below(m as u64) as i64; // 0 <= n < m
            let k = nz(rng);
            let (x, y, h) = (m * m - n * n, 2 * m * n, m * m + n * n);
            let (x, y) = if rng.below(2) == 0 { (x, y) } else { (y, x) };
            let s = |rng: &mut Rng, v: i64| sign(rng, k.mul_ref(&Radical::from(v)));
            (s(rng, x), s(rng, y), s(rng, h))
        }
        PlaneKind::RadicalQuarter => {
            let (a, b) = loop {
                let (a, b) = (small_rational(rng), small_rational(rng));
                if !(a.is_zero() && b.is_zero()) {
                    break (a, b);
                }
            };
            let c = Radical::sqrt_rational(&a.mul_ref(&a).add_ref(&b.mul_ref(&b)))
                .expect("a^2 + b^2 >= 0 has a real square root");
            (Radical::from(a), Radical::from(b), sign(rng, c))
        }
        PlaneKind::Circle => (Radical::zero(), Radical::zero(), nz(rng)),
        PlaneKind::Vertical => loop {
            let (a, b) = (q(rng), q(rng));
            if !(a.is_zero() && b.is_zero()) {
                break (a, b, Radical::zero());
            }
        },
        PlaneKind::ZeroMiddleWeight => loop {
            let (a, b) = (q(rng), q(rng));
            let c = a.add_ref(&b).neg_ref();
            if !(a.is_zero() && b.is_zero()) {
                break (a, b, c);
            }
        },
        PlaneKind::RadicalNormal => loop {
            let entry = |rng: &mut Rng| {
                let k = [2u64, 3, 5][rng.below(3) as usize];
                q(rng).add_ref(&Radical::sqrt_of(k).scale(&small_rational(rng)))
            };
            let (a, b, c) = (entry(rng), entry(rng), entry(rng));
            if !(a.is_zero() && b.is_zero() && c.is_zero()) {
                break (a, b, c);
            }
        },
    };
    let d = if through_apex {
        Radical::zero()
    } else {
        nz(rng)
    };
    Plane::new(a, b, c, d)
}

/// What [`check_section`] found for one plane.
#[derive(Clone, Debug, PartialEq)]
pub struct SectionReport {
    /// The type by the angle rule.
    pub angle_rule: SectionType,
    /// The type by each piece's weights and points.
    pub bezier: [Option<SectionType>; 2],
    /// Distinct rulings parallel to the plane (zeros of both weight polynomials, shared end
    /// directions once).
    pub rulings_at_infinity: usize,
    /// Curve points substituted into the plane and the cone.
    pub points_checked: usize,
    /// Points found off the plane or off the cone (parameter and point), if any.
    pub off: Vec<String>,
}

impl SectionReport {
    /// The three type decisions agree and every sampled point is on plane and cone.
    pub fn agrees(&self) -> bool {
        self.bezier.iter().all(|b| *b == Some(self.angle_rule))
            && self.rulings_at_infinity == expected_rulings(self.angle_rule)
            && self.off.is_empty()
    }
}

/// Rulings parallel to the plane of a section of this type: points at infinity of a conic, or
/// the rulings contained in a plane through the apex.
pub fn expected_rulings(t: SectionType) -> usize {
    match t {
        SectionType::Conic(ConicType::Circle | ConicType::Ellipse)
        | SectionType::Degenerate(DegenerateConic::Point) => 0,
        SectionType::Conic(ConicType::Parabola)
        | SectionType::Degenerate(DegenerateConic::DoubleLine) => 1,
        SectionType::Conic(ConicType::Hyperbola)
        | SectionType::Degenerate(DegenerateConic::LinePair) => 2,
    }
}

/// The section of `plane` decided three ways, and its points checked at [`SAMPLE_T`] (module
/// doc).
///
/// The points are checked in homogeneous coordinates: at `t = n/d` the curve's homogeneous point
/// times `d^deg` is `H = sum_k C(deg, k) n^k (d - n)^(deg - k) c_k` (integer multiples of the
/// control vectors `c_k = (w_k, w_k r_k)`, no product of two radicals), a pole where its weight
/// `W` is zero, and the point `(X, Y, Z) / W` is on the plane and on the cone exactly when
/// `N . (X, Y, Z) + d W = 0` and `X^2 + Y^2 - Z^2 = 0` (`W != 0`). This avoids the inverse of a
/// radical weight per point, the slow part of [`check_section_reference`] (the affine
/// substitution, kept as the reference the tests compare with); the point is made affine only
/// to be printed when it is off.
///
/// # Errors
/// The zero normal.
pub fn check_section(plane: &Plane<Radical>) -> Result<SectionReport, String> {
    check_section_with(plane, |piece, plane, n, d| {
        let h = scaled_hom(&piece.curve, n, d);
        let [w, x, y, z] = &h.0;
        if w.is_zero() {
            return None; // a pole
        }
        let on_plane = plane
            .normal
            .dot(&Vec3::new(x.clone(), y.clone(), z.clone()))
            .add_ref(&plane.d.mul_ref(w))
            .is_zero();
        let on_cone = x.square().add_ref(&y.square()) == z.square();
        Some((on_plane, on_cone))
    })
}

/// The reference for [`check_section`]: each curve point made affine (`C(t) = (X, Y, Z) / W`)
/// and substituted into the plane and into `x^2 + y^2 - z^2`, as the claim's evidence words it.
///
/// # Errors
/// The zero normal.
pub fn check_section_reference(plane: &Plane<Radical>) -> Result<SectionReport, String> {
    check_section_with(plane, |piece, plane, n, d| {
        let t = Radical::from_ratio(n, d).expect("d != 0");
        let p = piece.curve.eval(&t).ok()?; // None at a pole
        let on_plane = plane.value(&p).is_zero();
        let on_cone = p.x.square().add_ref(&p.y.square()) == p.z.square();
        Some((on_plane, on_cone))
    })
}

/// `d^deg` times the homogeneous point of `curve` at `t = n / d` (`d > 0`): the Bernstein sum
/// with the integer factors `C(deg, k) n^k (d - n)^(deg - k)`.
fn scaled_hom(curve: &RationalBezierCurve<Radical>, n: i64, d: i64) -> Hom4<Radical> {
    let control = curve.control();
    let deg = control.len() - 1;
    let (n, m) = (Rational::from_integer(n), Rational::from_integer(d - n));
    let mut h: Hom4<Radical> = Hom4(core::array::from_fn(|_| Radical::zero()));
    let mut binom: i64 = 1;
    for (k, c) in control.iter().enumerate() {
        let factor = Rational::from_integer(binom)
            .mul_ref(&n.pow(k as u32))
            .mul_ref(&m.pow((deg - k) as u32));
        for (slot, x) in h.0.iter_mut().zip(&c.0) {
            *slot = slot.add_ref(&x.scale(&factor));
        }
        // C(deg, k + 1) = C(deg, k) (deg - k) / (k + 1), exact in integers.
        binom = binom * (deg - k) as i64 / (k as i64 + 1);
    }
    h
}

/// A point test: `(on plane, on cone)` of a piece's point at `t = n / d`, `None` at a pole.
type PointTest = fn(&SectionPiece<Radical>, &Plane<Radical>, i64, i64) -> Option<(bool, bool)>;

/// [`check_section`] with the point test given.
fn check_section_with(plane: &Plane<Radical>, test: PointTest) -> Result<SectionReport, String> {
    let section = ConeSection::new(plane.clone(), &inv_sqrt2()).map_err(|e| e.to_string())?;
    let rule = angle_rule(plane).map_err(|e| e.to_string())?;
    let bezier = [
        bezier_type(&section.pieces[0].curve),
        bezier_type(&section.pieces[1].curve),
    ];
    debug_assert_eq!(section.pieces[0].piece, ConePiece::Plus);
    let plus = &section.pieces[0].poles;
    // V+(0) = V-(1) = (1,0,1), V+(1) = V-(0) = (0,1,1): a zero at an end of the + piece is a
    // zero at the other end of the - piece (end-point roots are found exactly).
    let shared = plus
        .iter()
        .filter(|p| matches!(p.exact(), Some(t) if t.is_zero() || *t == Radical::one()))
        .count();
    let rulings_at_infinity = plus.len() + section.pieces[1].poles.len() - shared;
    let mut points_checked = 0;
    let mut off = Vec::new();
    for piece in &section.pieces {
        for (n, d) in SAMPLE_T {
            let Some((on_plane, on_cone)) = test(piece, plane, n, d) else {
                continue; // a pole
            };
            points_checked += 1;
            if !(on_plane && on_cone) {
                let t = Radical::from_ratio(n, d).expect("d != 0");
                let p = piece
                    .curve
                    .eval(&t)
                    .expect("the point test found a non-zero weight");
                off.push(format!(
                    "C{}({n}/{d}) = {} is {}",
                    piece.piece.sign(),
                    point_text(&p),
                    if on_plane {
                        "off the cone"
                    } else {
                        "off the plane"
                    }
                ));
            }
        }
    }
    Ok(SectionReport {
        angle_rule: rule,
        bezier,
        rulings_at_infinity,
        points_checked,
        off,
    })
}

fn plane_text(p: &Plane<Radical>) -> String {
    format!(
        "({}) x + ({}) y + ({}) z + ({}) = 0",
        p.normal.x, p.normal.y, p.normal.z, p.d
    )
}

fn report_text(r: &SectionReport) -> String {
    let b = |x: &Option<SectionType>| x.map_or("not a conic piece".to_string(), |t| t.to_string());
    format!(
        "angle rule {}, C+ invariants {}, C- invariants {}, {} rulings parallel to the plane (expected {}){}",
        r.angle_rule,
        b(&r.bezier[0]),
        b(&r.bezier[1]),
        r.rulings_at_infinity,
        expected_rulings(r.angle_rule),
        if r.off.is_empty() {
            String::new()
        } else {
            format!(", {}", r.off.join(", "))
        }
    )
}

/// `chiang.conic_type`: Table 1's four planes, then `count` random planes from `seed`, cycling
/// through the generators of [`PlaneKind`], every fourth plane of each through the apex.
///
/// # Errors
/// Data errors of [`TABLE1`].
pub fn check_types(seed: u64, count: usize) -> Result<Outcome, String> {
    let mut disagreements = Vec::new();
    let mut table_text = Vec::new();
    let through = Vec3::new(Radical::one(), Radical::one(), Radical::one());
    let mut table_planes = Vec::new();
    for col in &TABLE1 {
        let n = vec3(&col.normal)?;
        let d = n.dot(&through).neg_ref();
        table_planes.push(Plane::new(n.x, n.y, n.z, d));
    }
    // The planes are drawn in order from the one generator, then checked in parallel (each
    // section is independent); the reports are read in order, so the evidence and the first
    // error do not depend on the number of threads.
    let mut rng = Rng::new(seed);
    let random: Vec<(PlaneKind, Plane<Radical>)> = (0..count)
        .map(|i| {
            let kind = PlaneKind::ALL[i % PlaneKind::ALL.len()];
            let apex = (i / PlaneKind::ALL.len()) % 4 == 3;
            (kind, random_plane(&mut rng, kind, apex))
        })
        .collect();
    let reports: Vec<Result<SectionReport, String>> = table_planes
        .par_iter()
        .chain(random.par_iter().map(|(_, p)| p))
        .map(check_section)
        .collect();
    let mut reports = reports.into_iter();
    for (col, plane) in TABLE1.iter().zip(&table_planes) {
        let r = reports.next().expect("one report per plane")?;
        let named = r.angle_rule.to_string() == col.name;
        table_text.push(format!(
            "{} {}: {}",
            col.name,
            printed_point_text(&col.normal),
            report_text(&r)
        ));
        if !r.agrees() || !named {
            disagreements.push(format!(
                "Table 1 column {} (plane {}): {}",
                col.name,
                plane_text(plane),
                report_text(&r)
            ));
        }
    }
    let mut per_type: BTreeMap<&'static str, usize> = BTreeMap::new();
    let mut per_kind: BTreeMap<PlaneKind, usize> = BTreeMap::new();
    let (mut agreeing, mut points) = (0usize, 0usize);
    for ((kind, plane), r) in random.iter().zip(reports) {
        let kind = *kind;
        let r = r?;
        *per_type.entry(r.angle_rule.name()).or_default() += 1;
        *per_kind.entry(kind).or_default() += 1;
        points += r.points_checked;
        if r.agrees() {
            agreeing += 1;
        } else {
            disagreements.push(format!(
                "random plane {} ({}): {}",
                plane_text(plane),
                kind.name(),
                report_text(&r)
            ));
        }
    }
    let counts = |m: Vec<(String, usize)>| {
        m.into_iter()
            .map(|(k, v)| format!("{k} {v}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let type_counts = counts(
        SectionType::ALL
            .iter()
            .map(|t| {
                (
                    t.name().to_string(),
                    per_type.get(t.name()).copied().unwrap_or(0),
                )
            })
            .collect(),
    );
    let kind_counts = counts(
        per_kind
            .iter()
            .map(|(k, v)| (k.name().to_string(), *v))
            .collect(),
    );
    let summary = format!(
        "Table 1: {}. Random planes (workspace Rng, seed {seed}): {count}, by generator: {kind_counts}; every fourth plane of each generator through the apex (d = 0). By type (angle rule): {type_counts}. Type decided three ways (angle rule; weight discriminant and circle test of C+ and of C-; rulings parallel to the plane = zeros of the weight polynomials): {agreeing} of {count} agree; {points} curve points at t in {{0, 1/4, 1/3, 1/2, 3/4, 1, -2/3}} substituted exactly into the plane and x^2 + y^2 - z^2",
        table_text.join("; ")
    );
    Ok(if disagreements.is_empty() {
        Outcome {
            verdict: Verdict::Holds,
            method: format!("exact sections in Q(sqrt 2, ...) (Radical) of Table 1's planes and {count} seeded random planes"),
            evidence: format!("{summary}: all on plane and cone. All agree, and each Table 1 column is the type its heading names."), erratum: None, }
    } else {
        Outcome {
            verdict: Verdict::Fails,
            method: format!("exact sections in Q(sqrt 2, ...) (Radical) of Table 1's planes and {count} seeded random planes"),
            evidence: format!(
                "{summary}. {} counter-example(s): {}",
                disagreements.len(),
                disagreements.join("; ")
            ), erratum: None, }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The homogeneous point test against the affine reference, on Table 1 and on planes of
    /// every generator (through the apex and not), and on planes the curves do not lie in.
    #[test]
    fn homogeneous_points_agree_with_the_affine_reference() {
        let mut rng = Rng::new(7);
        let through = Vec3::new(Radical::one(), Radical::one(), Radical::one());
        let mut planes: Vec<Plane<Radical>> = TABLE1
            .iter()
            .map(|col| {
                let n = vec3(&col.normal).expect("Table 1 parses");
                let d = n.dot(&through).neg_ref();
                Plane::new(n.x, n.y, n.z, d)
            })
            .collect();
        for i in 0..140 {
            let kind = PlaneKind::ALL[i % PlaneKind::ALL.len()];
            planes.push(random_plane(&mut rng, kind, i % 4 == 3));
        }
        for plane in &planes {
            let fast = check_section(plane).expect("non-zero normal");
            let reference = check_section_reference(plane).expect("non-zero normal");
            assert_eq!(fast, reference, "{}", plane_text(plane));
        }
    }

    #[test]
    fn scaled_hom_is_d_to_the_degree_times_the_point() {
        let mut rng = Rng::new(11);
        for i in 0..30 {
            let plane = random_plane(&mut rng, PlaneKind::ALL[i % 7], false);
            let section = ConeSection::new(plane, &inv_sqrt2()).expect("non-zero normal");
            for piece in &section.pieces {
                let deg = piece.curve.control().len() as u32 - 1;
                for (n, d) in SAMPLE_T {
                    let t = Radical::from_ratio(n, d).expect("d != 0");
                    let scale = Radical::from(Rational::from_integer(d).pow(deg));
                    let expected = Hom4(piece.curve.eval_hom(&t).0.map(|x| x.mul_ref(&scale)));
                    assert_eq!(scaled_hom(&piece.curve, n, d), expected, "t = {n}/{d}");
                }
            }
        }
    }

    /// A point test that finds every point off reports the affine point, as the reference
    /// would print it (the failure text is made from `eval`, not from the scaled point).
    #[test]
    fn off_points_are_printed_affine() {
        let plane = Plane::new(
            Radical::zero(),
            Radical::zero(),
            Radical::one(),
            Radical::from(-1i64),
        );
        let r = check_section_with(&plane, |_, _, _, _| Some((true, false))).unwrap();
        assert_eq!(r.off.len(), r.points_checked);
        assert!(
            r.off[0].starts_with("C+(0/1) = (1, 0, 1) is off the cone"),
            "{}",
            r.off[0]
        );
        assert!(!r.agrees());
    }
}
