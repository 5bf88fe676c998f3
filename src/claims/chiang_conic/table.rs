//! `chiang.conic_table`: every printed entry of Table 1 judged against the exact derivation
//! (module doc of [`super`]).

use super::*;

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

pub(super) fn num(text: &str) -> Result<Radical, String> {
    text.parse::<Radical>()
        .map_err(|e| format!("printed number {text:?}: {e}"))
}

pub(super) fn vec3(texts: &[&str]) -> Result<Vec3<Radical>, String> {
    match texts {
        [x, y, z] => Ok(Vec3::new(num(x)?, num(y)?, num(z)?)),
        _ => Err(format!("a point needs three coordinates, got {texts:?}")),
    }
}

pub(super) fn point_text(p: &Vec3<Radical>) -> String {
    format!("({}, {}, {})", p.x, p.y, p.z)
}

pub(super) fn printed_point_text(p: &[&str; 3]) -> String {
    format!("({}, {}, {})", p[0], p[1], p[2])
}

/// `a x + b y + c z = rhs`, zero terms left out.
pub(super) fn equation_text(n: &Vec3<Radical>, rhs: &Radical) -> String {
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

pub(super) fn poles_text(poles: &[IsolatedRoot<Radical>]) -> String {
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

pub(super) fn printed_poles_text(poles: &[&str]) -> String {
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

/// The printed poles against the derived ones (module doc): the problems found (none: equal).
pub(super) fn judge_poles(
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
pub(super) fn refined_poles(
    weight: &exactcheck_core::Bernstein<Radical>,
    poles: &[IsolatedRoot<Radical>],
) -> Vec<IsolatedRoot<Radical>> {
    let width = Radical::from_ratio(1, 1024).expect("1024 != 0");
    let refiner = Refiner::new(weight);
    poles.iter().map(|p| refiner.refine(p, &width)).collect()
}

/// The rows of one piece: weights (with the common-scale test) and points.
pub(super) fn piece_rows(
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
pub(super) fn attach_ocr_notes(
    table: &[PrintedColumn],
    rows: &mut [TableRow],
) -> Result<(), String> {
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
