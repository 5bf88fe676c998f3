//! `chiang.conic_type`: the angle rule against the conics' own invariants and the rulings
//! parallel to the plane, on Table 1 and on seeded random planes (module doc of [`super`]).

use super::*;

/// The seed of `chiang.conic_type`'s random planes.
pub const TYPE_SEED: u64 = 2026;
/// How many random planes `chiang.conic_type` checks.
pub const TYPE_PLANES: usize = 3500;

/// The parameters at which every section's points are checked (exact).
pub const SAMPLE_T: [(i64, i64); 7] = [(0, 1), (1, 4), (1, 3), (1, 2), (3, 4), (1, 1), (-2, 3)];

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
pub(super) fn scaled_hom(curve: &RationalBezierCurve<Radical>, n: i64, d: i64) -> Hom4<Radical> {
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
pub(super) type PointTest =
    fn(&SectionPiece<Radical>, &Plane<Radical>, i64, i64) -> Option<(bool, bool)>;

/// [`check_section`] with the point test given.
pub(super) fn check_section_with(
    plane: &Plane<Radical>,
    test: PointTest,
) -> Result<SectionReport, String> {
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

pub(super) fn plane_text(p: &Plane<Radical>) -> String {
    format!(
        "({}) x + ({}) y + ({}) z + ({}) = 0",
        p.normal.x, p.normal.y, p.normal.z, p.d
    )
}

pub(super) fn report_text(r: &SectionReport) -> String {
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
