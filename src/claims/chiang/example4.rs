//! `chiang.example4`: every printed decimal of Example 4 against the exact curve in
//! `Q(sqrt 2, sqrt 6)`.
//!
//! The curve is `RuledSurface::plane_section` of `surface_and_plane(sqrt 2, sqrt 6)` over
//! [`Radical`] (exact). A printed decimal with `d` digits after the point is *correctly rounded*
//! when the exact value lies in `[printed - 10^-d / 2, printed + 10^-d / 2]`; the two comparisons
//! are exact (the ordered field [`Radical`]). The exact decimal shown is itself certified: the
//! integer nearest to `x 10^p` is checked by exact comparisons with its half-integer neighbours.
//!
//! For a printed value that is not correctly rounded, candidate explanations are *computed*
//! (each gives a value; the printed digits are then tested against it, rounded or truncated
//! toward zero, exactly as above):
//! * the exact value, truncated instead of rounded;
//! * the theorem's formulas evaluated with `sqrt 2 = 1.41`, `sqrt 6 = 2.45` (the printed weights),
//!   or with `sqrt 2 = 1.414`, `sqrt 6 = 2.449`, in exact rational arithmetic;
//! * the exact value's radical form `a + b sqrt 2 + c sqrt 3 + e sqrt 6` evaluated with
//!   `sqrt 2 = 1.41`, `sqrt 3 = 1.73`, `sqrt 6 = 2.45` (e.g. `r0 = -sqrt(2)/2 = -1.41/2`);
//! * the weighted points `w_k r_k` (exact, or with `sqrt 2 = 1.41`, `sqrt 6 = 2.45`) divided by
//!   the printed, rounded weight.

use super::{Outcome, Verdict};
use crate::claims::printed::{
    decimal, deviation_text, places, radical, rational, rounds_to, truncates_to,
};
use crate::claims::{Equation, Erratum};
use exactcheck_core::ruled::{Plane, RuledSurface};
use exactcheck_core::{Field, Ring, Vec3};
use exactcheck_exact::expr::CoeffExpr;
use exactcheck_exact::expr::{AddOp, Expr, ExprKind};
use exactcheck_exact::{Radical, Rational};

/// Chiang's Example 4 (the claim list, square roots restored from the text): `m = 1`, `n = 2`,
/// `p0 = (0,0,-1), p1 = (1,1,-1), p2 = (0,2,-1)`, `q0 = (-1, 1, sqrt 2)`, `q1 = (-1, -1, sqrt 6)`,
/// and the plane `z = 0`. The square roots are arguments, so any scalar that has them (an exact
/// square-root field, `f64`) instantiates the example; the one home of its data (the claim, `plot chiang`).
pub fn surface_and_plane<T: Ring>(sqrt2: T, sqrt6: T) -> (RuledSurface<T>, Plane<T>) {
    let i = |x: i64| T::from_i64(x);
    let surface = RuledSurface::from_control(
        vec![
            Vec3::new(i(0), i(0), i(-1)),
            Vec3::new(i(1), i(1), i(-1)),
            Vec3::new(i(0), i(2), i(-1)),
        ],
        vec![
            Vec3::new(i(-1), i(1), sqrt2),
            Vec3::new(i(-1), i(-1), sqrt6),
        ],
    )
    .expect("three control points and two control vectors");
    (surface, Plane::z0())
}

/// The printed weights `w0..w3`.
pub const PRINTED_WEIGHTS: [&str; 4] = ["1.41", "1.76", "2.10", "2.45"];
/// The printed points `r0..r3`.
pub const PRINTED_POINTS: [[&str; 3]; 4] = [
    ["-0.705", "0.705", "0"],
    ["-0.0341", "0.721", "0"],
    ["0.3", "1.07", "0"],
    ["-0.409", "1.60", "0"],
];

/// One printed value against the exact one.
#[derive(Clone, Debug)]
pub struct Example4Row {
    /// `w0`, ..., `r3.z`.
    pub name: String,
    /// The printed digits.
    pub printed: String,
    /// The exact value.
    pub exact: Radical,
    /// The exact value over a common denominator, e.g. `(2*sqrt(2) + sqrt(6))/3`.
    pub exact_text: String,
    /// The exact value correctly rounded to 6 places (certified).
    pub exact_decimal: String,
    /// `printed - exact`, to about 3 significant digits (certified rounding).
    pub deviation: String,
    /// Whether the printed digits are the exact value correctly rounded.
    pub correctly_rounded: bool,
    /// For a wrong value: the computed hypotheses (module doc) that reproduce the printed digits.
    pub reproduced_by: Vec<String>,
}

/// The 16 values `w0..w3, r0.x, r0.y, r0.z, ..., r3.z` of a curve (a point `None` where the
/// weight is zero).
fn values<T: Field>(weights: &[T], points: &[Option<Vec3<T>>]) -> Vec<Option<T>> {
    let mut out: Vec<Option<T>> = weights.iter().cloned().map(Some).collect();
    for p in points {
        match p {
            Some(v) => out.extend([Some(v.x.clone()), Some(v.y.clone()), Some(v.z.clone())]),
            None => out.extend([None, None, None]),
        }
    }
    out
}

fn names() -> Vec<String> {
    let mut n: Vec<String> = (0..4).map(|k| format!("w{k}")).collect();
    for k in 0..4 {
        for a in ["x", "y", "z"] {
            n.push(format!("r{k}.{a}"));
        }
    }
    n
}

fn printed_texts() -> Vec<&'static str> {
    let mut t: Vec<&str> = PRINTED_WEIGHTS.to_vec();
    for p in PRINTED_POINTS {
        t.extend(p);
    }
    t
}

/// A computed explanation: a name and the 16 values it gives (`None`: not applicable).
struct Hypothesis {
    name: String,
    values: Vec<Option<Radical>>,
}

fn with_rounded_roots(s2: &str, s6: &str) -> Result<Hypothesis, String> {
    let (surface, plane) = surface_and_plane(rational(s2)?, rational(s6)?);
    let curve = surface.plane_section(&plane);
    Ok(Hypothesis {
        name: format!("the formulas with sqrt 2 = {s2}, sqrt 6 = {s6}"),
        values: values(&curve.weights(), &curve.points())
            .into_iter()
            .map(|v| v.map(|q| radical(&q)))
            .collect(),
    })
}

/// `w_k r_k` divided by the printed weight.
fn over_printed_weights<T: Field>(
    name: &str,
    control: &[exactcheck_core::Hom4<T>],
    lift: impl Fn(&T) -> Radical,
) -> Result<Hypothesis, String> {
    let mut values = vec![None; 4];
    for (k, h) in control.iter().enumerate() {
        let w = radical(&rational(PRINTED_WEIGHTS[k])?);
        for a in 1..4 {
            values.push(Some(
                lift(&h.0[a])
                    .checked_div(&w)
                    .map_err(|_| "a printed weight is zero".to_string())?,
            ));
        }
    }
    Ok(Hypothesis {
        name: name.into(),
        values,
    })
}

/// The exact radical form evaluated with `sqrt 2 = 1.41`, `sqrt 3 = 1.73`, `sqrt 6 = 2.45`.
fn radical_form_rounded(x: &Radical) -> Option<Radical> {
    let mut sum = Rational::ZERO;
    for (m, c) in x.terms() {
        let root = match m.as_u64()? {
            1 => Rational::from_integer(1),
            2 => rational("1.41").ok()?,
            3 => rational("1.73").ok()?,
            6 => rational("2.45").ok()?,
            _ => return None,
        };
        sum = sum.add_ref(&c.mul_ref(&root));
    }
    Some(radical(&sum))
}

/// The table of Example 4: every printed value against the exact one (module doc).
///
/// # Errors
/// A printed decimal that does not parse (data error), a zero weight.
pub fn example4_table() -> Result<Vec<Example4Row>, String> {
    let (surface, plane) = surface_and_plane(Radical::sqrt_of(2), Radical::sqrt_of(6));
    let curve = surface.plane_section(&plane);
    let exact = values(&curve.weights(), &curve.points());
    let (rs, rp) = surface_and_plane(rational("1.41")?, rational("2.45")?);
    let rounded_control = rs.plane_section(&rp).into_control();
    let hypotheses = vec![
        Hypothesis {
            name: "the exact value".into(),
            values: exact.clone(),
        },
        with_rounded_roots("1.41", "2.45")?,
        with_rounded_roots("1.414", "2.449")?,
        Hypothesis {
            name: "the exact radical form with sqrt 2 = 1.41, sqrt 3 = 1.73, sqrt 6 = 2.45".into(),
            values: exact
                .iter()
                .map(|v| v.as_ref().and_then(radical_form_rounded))
                .collect(),
        },
        over_printed_weights(
            "w_k r_k (exact) divided by the printed w_k",
            curve.control(),
            Radical::clone,
        )?,
        over_printed_weights(
            "w_k r_k with sqrt 2 = 1.41, sqrt 6 = 2.45 divided by the printed w_k",
            &rounded_control,
            radical,
        )?,
    ];
    let mut rows = Vec::new();
    for (i, (name, text)) in names().into_iter().zip(printed_texts()).enumerate() {
        let x = exact[i]
            .clone()
            .ok_or_else(|| format!("{name}: the exact weight is zero"))?;
        let printed = rational(text)?;
        let p = places(text);
        let correctly_rounded = rounds_to(&x, &printed, p);
        let mut reproduced_by = Vec::new();
        if !correctly_rounded {
            for h in &hypotheses {
                let Some(v) = &h.values[i] else { continue };
                if h.name != "the exact value" && rounds_to(v, &printed, p) {
                    reproduced_by.push(format!("{} (rounded)", h.name));
                }
                if truncates_to(v, &printed, p) {
                    reproduced_by.push(format!("{} (truncated)", h.name));
                }
            }
        }
        rows.push(Example4Row {
            name,
            printed: text.into(),
            exact_text: x.to_string_over_common_denominator(),
            exact_decimal: decimal(&x, 6),
            deviation: deviation_text(&radical(&printed).sub_ref(&x)),
            correctly_rounded,
            reproduced_by,
            exact: x,
        });
    }
    Ok(rows)
}

/// The table as Markdown (what docs/papers/chiang.md shows; `tests/solve/chiang.rs` checks it is there verbatim).
pub fn example4_markdown(rows: &[Example4Row]) -> String {
    let mut s = String::from(
        "| value | printed | exact | exact decimal | deviation (printed - exact) | correctly rounded? |\n| --- | --- | --- | --- | --- | --- |\n",
    );
    for r in rows {
        let verdict = if r.correctly_rounded {
            "yes".to_string()
        } else if r.reproduced_by.is_empty() {
            "**no** (no tested hypothesis reproduces it)".to_string()
        } else {
            format!("**no**; reproduced by {}", r.reproduced_by.join("; "))
        };
        s.push_str(&format!(
            "| {} | {} | `{}` | {} | {} | {} |\n",
            r.name, r.printed, r.exact_text, r.exact_decimal, r.deviation, verdict
        ));
    }
    s
}

/// The claim `chiang.example4`.
pub fn check() -> Result<Outcome, String> {
    let rows = example4_table()?;
    let wrong: Vec<&Example4Row> = rows.iter().filter(|r| !r.correctly_rounded).collect();
    let row_text = |r: &Example4Row| {
        format!(
            "{}: printed {}, exact {} = {}, deviation {}",
            r.name, r.printed, r.exact_text, r.exact_decimal, r.deviation
        )
    };
    let table: Vec<String> = rows
        .iter()
        .map(|r| {
            format!(
                "{} [{}]",
                row_text(r),
                if r.correctly_rounded {
                    "correctly rounded"
                } else {
                    "not correctly rounded"
                }
            )
        })
        .collect();
    let evidence = if wrong.is_empty() {
        format!(
            "all {} printed values are the exact values correctly rounded. Table: {}",
            rows.len(),
            table.join("; ")
        )
    } else {
        let explained: Vec<String> = wrong
            .iter()
            .map(|r| {
                format!(
                    "{} — {}",
                    row_text(r),
                    if r.reproduced_by.is_empty() {
                        "reproduced by none of the tested hypotheses".to_string()
                    } else {
                        format!("reproduced by {}", r.reproduced_by.join(" and by "))
                    }
                )
            })
            .collect();
        format!(
            "{} of {} printed values are not the exact value correctly rounded to the printed digits: {}. Table: {}",
            wrong.len(),
            rows.len(),
            explained.join("; "),
            table.join("; ")
        )
    };
    Ok(Outcome {
        verdict: if wrong.is_empty() {
            Verdict::Holds
        } else {
            Verdict::Fails
        },
        method: "exact arithmetic in Q(sqrt 2, sqrt 6) (Radical); each printed decimal compared exactly with its rounding interval; explanations computed (exact rational arithmetic with rounded roots, truncation, division by the printed weights)".into(),
        erratum: (!wrong.is_empty()).then(|| Box::new(example4_erratum(&wrong))),
        evidence,
    })
}

/// The erratum of `chiang.example4`: each wrong printed value (its rational value) and the exact
/// value, the example's data (control points and vectors, exact), and `printed - exact` for each.
fn example4_erratum(wrong: &[&Example4Row]) -> Erratum {
    let var = |r: &Example4Row| r.name.replace('.', "_");
    let (surface, _) = surface_and_plane(Radical::sqrt_of(2), Radical::sqrt_of(6));
    let tuple = |v: &Vec3<Radical>| Expr::tuple(vec![v.x.to_expr(), v.y.to_expr(), v.z.to_expr()]);
    let mut counter_example: Vec<Equation> = surface
        .base()
        .control_points()
        .iter()
        .enumerate()
        .map(|(j, p)| Equation::named(&format!("p{j}"), tuple(p)))
        .collect();
    counter_example.extend(
        surface
            .directions()
            .control_points()
            .iter()
            .enumerate()
            .map(|(i, q)| Equation::named(&format!("q{i}"), tuple(q))),
    );
    let printed = |r: &Example4Row| {
        rational(&r.printed).expect("the printed digits were read as a rational by the table")
    };
    Erratum {
        printed: wrong
            .iter()
            .map(|r| Equation::named(&var(r), printed(r).to_expr()))
            .collect(),
        corrected: wrong
            .iter()
            .map(|r| Equation::named(&var(r), r.exact.to_expr()))
            .collect(),
        correction: {
            let parts: Vec<String> = wrong
                .iter()
                .map(|r| format!("{} = {} (printed {})", r.name, r.exact_decimal, r.printed))
                .collect();
            format!(
                "the exact values correctly rounded to 6 places: {}",
                parts.join(", ")
            )
        },
        counter_example,
        residual: wrong
            .iter()
            .map(|r| {
                let p = radical(&printed(r));
                Equation::new(
                    Expr::new(ExprKind::Sum(vec![
                        (AddOp::Plus, p.to_expr()),
                        (AddOp::Minus, Expr::var(&var(r))),
                    ])),
                    p.sub_ref(&r.exact).to_expr(),
                )
            })
            .collect(),
        notation: Vec::new(),
    }
}
