//! Claims of Spaeth's cylinder/sphere paper.
//!
//! The printed equations (4), (5), (7), (9), (10), (11) are kept as text (ASCII transliterations
//! of the printed formulas: `cb, sb` for cos/sin beta, `cg, sg` for gamma, `ct, st` for t) and
//! checked against the derivation in `exactcheck_core::cylinder_sphere`, symbolically modulo
//! `cos^2 + sin^2 = 1` for each angle. Where a printed formula does not match, the claim fails
//! with an exact counter-example (rational angles), and a corrected text — itself proved equal to
//! the derivation — is reported.
//!
//! `spaeth.eq7` ((5) substituted into (6) is (7)), `spaeth.eq8` ((7) is monic quadratic in `u`)
//! and `spaeth.eq11` (the roots (11) of the quadratic (8)) state printed formulas alone and are
//! decided by the claims-file engine from the embedded `claims.toml` (`Claim::printed`). The others
//! stay Rust, because the claims format cannot say what they check:
//! * `eq5`, `eq9`, `eq10` — each printed formula against the derivation of
//!   `exactcheck_core::cylinder_sphere` (the product of the rotation matrices of (4); (9) and
//!   (10) also against the core's `A(t)`, `B(t)`), inside the geometric domains, with the
//!   corrected text proved equal to the derivation and named in the erratum;
//! * `sampling` — the f64 sampling rule run on a configuration found by isolating the real
//!   roots of the discriminant (module `examples`);
//! * `example1` to `example3` — the worked examples solved by the core with the roots isolated
//!   exactly and compared with the printed numbers and figures.
//!
//! The same claims written as a claims file are `examples/spaeth.toml` (decided by the file
//! engine, comparing formulas of its own); a test checks that both give the same verdicts.

use super::engine::{prove_all_in, Symbols};
use super::{Claim, Equation, Outcome, Verdict};
use exactcheck_core::cylinder_sphere::{Angle, CylinderSphere};
use exactcheck_core::{Ring, Vec3};
use exactcheck_exact::poly::{unit_circle_relation, Poly, Var};
use exactcheck_exact::prove::VarDomain;
use exactcheck_exact::Rational;

type P = Poly<Rational>;

const VARS: [&str; 15] = [
    "a", "b", "r", "d", "e", "f", "R", "u", "ct", "st", "cb", "sb", "cg", "sg", "D",
];

/// (5) as printed.
const EQ5: [&str; 3] = [
    "cb*(a + r*ct) + u*sb",
    "cg*(b + r*st) + sg*(-sb*(a + r*ct) + u*cb)",
    "-sg*(b + r*st) + cg*(-sb*(a + r*ct) + u*cb)",
];
/// (4) multiplied out, as the corrected (5) would have to read for the product order printed in (4).
const EQ5_CORRECTED: [&str; 3] = [
    "cb*(a + r*ct) + sb*(-sg*(b + r*st) + cg*u)",
    "cg*(b + r*st) + sg*u",
    "-sb*(a + r*ct) + cb*(-sg*(b + r*st) + cg*u)",
];
/// (7) as printed.
const EQ7: &str = "(cb*(a + r*ct) + u*sb - d)^2 + (cg*(b + r*st) + sg*(-sb*(a + r*ct) + u*cb) - e)^2 + (-sg*(b + r*st) + cg*(-sb*(a + r*ct) + u*cb) - f)^2 - R^2";
/// (9) as printed.
const EQ9: &str = "sb*(cb*(a + r*ct) - d) + sg*cb*(cg*(b + r*st) - sg*sb*(a + r*ct) - e) + cg*cb*(sg*(b + r*st) + cg*sb*(a + r*ct) + f)";
/// (9) with the sign of the last term corrected.
const EQ9_CORRECTED: &str = "sb*(cb*(a + r*ct) - d) + sg*cb*(cg*(b + r*st) - sg*sb*(a + r*ct) - e) - cg*cb*(sg*(b + r*st) + cg*sb*(a + r*ct) + f)";
/// (10) as printed.
const EQ10: &str = "(cb*(a + r*ct) - d)^2 + (cg*(b + r*st) - sg*sb*(a + r*ct) - e)^2 + (sg*(b + r*st) + cg*sb*(a + r*ct) + f)^2";
/// (10) with the missing `- R^2`.
const EQ10_CORRECTED: &str = "(cb*(a + r*ct) - d)^2 + (cg*(b + r*st) - sg*sb*(a + r*ct) - e)^2 + (sg*(b + r*st) + cg*sb*(a + r*ct) + f)^2 - R^2";

/// The LaTeX of the transliterated names, for the errata.
pub const NOTATION: [(&str, &str); 6] = [
    ("cb", "\\cos\\beta"),
    ("sb", "\\sin\\beta"),
    ("cg", "\\cos\\gamma"),
    ("sg", "\\sin\\gamma"),
    ("ct", "\\cos t"),
    ("st", "\\sin t"),
];

/// The symbolic `spaeth.*` claims.
pub fn claims() -> Vec<Claim> {
    vec![
        claim!("spaeth.eq5", Fails, "(4) (x,y,z) = Ry(beta) Rx(gamma) (a + r cos t, b + r sin t, u), multiplied out, is (5): x = cos b (a + r cos t) + u sin b, y = cos g (b + r sin t) + sin g (-sin b (a + r cos t) + u cos b), z = -sin g (b + r sin t) + cos g (-sin b (a + r cos t) + u cos b)", eq5),
        Claim::printed("spaeth.eq7"),
        Claim::printed("spaeth.eq8"),
        claim!("spaeth.eq9", Fails, "(9) A(t) = sin b [cos b (a + r cos t) - d] + sin g cos b [cos g (b + r sin t) - sin g sin b (a + r cos t) - e] + cos g cos b [sin g (b + r sin t) + cos g sin b (a + r cos t) + f]", eq9),
        claim!("spaeth.eq10", Fails, "(10) B(t) = [cos b (a + r cos t) - d]^2 + [cos g (b + r sin t) - sin g sin b (a + r cos t) - e]^2 + [sin g (b + r sin t) + cos g sin b (a + r cos t) + f]^2", eq10),
        Claim::printed("spaeth.eq11"),
    ]
}

const METHOD: &str = "symbolic expansion modulo cos^2 + sin^2 = 1 (t, beta, gamma)";

/// The domain of one variable of the printed formulas, as data: the engine's
/// [`VarDomain`] (bounds, strict or not) with the variable's name and the geometric reason.
#[derive(Clone, Debug, PartialEq)]
pub struct DomainDecl {
    /// The variable's name (one of the declared variables).
    pub var: &'static str,
    /// The bounds, as the proof engine takes them.
    pub domain: VarDomain,
    /// Why (the geometry).
    pub why: &'static str,
}

impl DomainDecl {
    /// The domain as text, e.g. `r > 0`.
    pub fn text(&self) -> String {
        let mut parts = Vec::new();
        if let Some((l, strict)) = &self.domain.lower {
            parts.push(format!(
                "{} {} {l}",
                self.var,
                if *strict { ">" } else { ">=" }
            ));
        }
        if let Some((u, strict)) = &self.domain.upper {
            parts.push(format!(
                "{} {} {u}",
                self.var,
                if *strict { "<" } else { "<=" }
            ));
        }
        parts.join(", ")
    }
}

/// The geometric domains of the variables of (4)-(11): the radii are positive. (The angles are
/// points of the unit circle through the relations `cos^2 + sin^2 = 1`; the offsets `a, b`, the
/// centre `d, e, f` and the height `u` are unrestricted; the paper restricts no parameter to
/// [0, 1].)
pub fn domains() -> Vec<DomainDecl> {
    let positive = || VarDomain {
        lower: Some((Rational::ZERO, true)),
        upper: None,
        integer: false,
    };
    vec![
        DomainDecl {
            var: "r",
            domain: positive(),
            why: "the cylinder radius",
        },
        DomainDecl {
            var: "R",
            domain: positive(),
            why: "the sphere radius",
        },
    ]
}

struct Setup {
    sym: Symbols,
    relations: Vec<P>,
    /// The declared domains with their variables.
    domains: Vec<(Var, VarDomain)>,
    cs: CylinderSphere<P>,
    ct: P,
    st: P,
    u: P,
}

/// The index of a declared variable; a misspelled name is an error (it used to become
/// variable 0, `a`, silently).
fn declared(sym: &Symbols, name: &str) -> Result<Var, String> {
    sym.vars.get(name).ok_or_else(|| {
        format!(
            "variable {name:?} is not declared (declared: {})",
            VARS.join(", ")
        )
    })
}

fn setup() -> Result<Setup, String> {
    let sym = Symbols::new(&VARS);
    let v = |n: &str| declared(&sym, n).map(P::var);
    let cs = CylinderSphere {
        a: v("a")?,
        b: v("b")?,
        r: v("r")?,
        beta: Angle {
            cos: v("cb")?,
            sin: v("sb")?,
        },
        gamma: Angle {
            cos: v("cg")?,
            sin: v("sg")?,
        },
        center: Vec3::new(v("d")?, v("e")?, v("f")?),
        radius: v("R")?,
    };
    let (ct, st, u) = (v("ct")?, v("st")?, v("u")?);
    let var = |n: &str| declared(&sym, n);
    let relations = vec![
        unit_circle_relation(var("ct")?, var("st")?),
        unit_circle_relation(var("cb")?, var("sb")?),
        unit_circle_relation(var("cg")?, var("sg")?),
    ];
    let domains = domains()
        .into_iter()
        .map(|d| Ok((var(d.var)?, d.domain)))
        .collect::<Result<_, String>>()?;
    Ok(Setup {
        sym,
        relations,
        domains,
        cs,
        ct,
        st,
        u,
    })
}

/// F's coefficients in u: `(F(0), F(1), F(-1))` give `F2 = (F(1) + F(-1))/2 - F(0)`,
/// `F1 = (F(1) - F(-1))/2`.
fn coefficients_in_u(s: &mut Setup, f: &P) -> Result<(P, P, P), String> {
    let u = s.sym.vars.get("u").ok_or("no u")?;
    if f.degree_in(u) > 2 {
        return Err("F has degree > 2 in u".into());
    }
    let at = |x: i64| f.substitute(u, &P::from_i64(x));
    let half = P::constant(Rational::new(1, 2).map_err(|e| e.to_string())?);
    let (f0, fp, fm) = (at(0), at(1), at(-1));
    let f2 = (fp.clone() + &fm) * &half - &f0;
    let f1 = (fp - fm) * &half;
    Ok((f2, f1, f0))
}

fn residuals_of(label: &str, a: &[P], b: &[P]) -> Vec<(String, P)> {
    a.iter()
        .zip(b)
        .enumerate()
        .map(|(i, (x, y))| (format!("{label}, coordinate {i}"), x.clone() - y))
        .collect()
}

/// Decides the residuals; a counter-example lies in the declared domains (the radii are
/// positive) as well as on the unit circles.
/// `sides`: the polynomials the residuals are differences of (a counter-example gives each of
/// their variables).
fn run(s: &Setup, residuals: &[(String, P)], sides: &[&P]) -> Result<Outcome, String> {
    let r: Vec<(&str, P)> = residuals
        .iter()
        .map(|(w, p)| (w.as_str(), p.clone()))
        .collect();
    Ok(prove_all_in(
        &s.sym,
        &r,
        sides,
        &s.relations,
        &s.domains,
        METHOD,
    ))
}

/// A printed or corrected formula of an erratum: the name it defines and its text.
type Form<'a> = (&'a str, &'a str);

/// Checks a failing printed formula: the failure (with its counter-example) from the printed
/// residuals, plus the proof that the corrected text matches the derivation. The erratum gets the
/// printed forms, and the corrected forms when they are proved.
fn with_correction(
    s: &Setup,
    printed: &[(String, P)],
    corrected: &[(String, P)],
    correction: &str,
    forms: (&[Form], &[Form]),
    sides: &[&P],
) -> Result<Outcome, String> {
    let mut out = run(s, printed, sides)?;
    if out.verdict == Verdict::Fails {
        let fixed = run(s, corrected, &[])?;
        let equations = |f: &[Form]| {
            f.iter()
                .map(|(lhs, rhs)| Equation::parse(lhs, rhs))
                .collect::<Result<Vec<_>, _>>()
        };
        let erratum = out.erratum.get_or_insert_with(Default::default);
        erratum.printed = equations(forms.0)?;
        erratum.notation = NOTATION
            .iter()
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .collect();
        out.evidence = if fixed.verdict == Verdict::Proved {
            erratum.corrected = equations(forms.1)?;
            erratum.correction = correction.to_string();
            let text: Vec<String> = erratum.corrected.iter().map(Equation::text).collect();
            format!(
                "{}. Corrected form (proved equal to the derivation): {} ({correction})",
                out.evidence,
                text.join(", ")
            )
        } else {
            erratum.correction = format!(
                "the candidate correction does not match the derivation either: {}",
                fixed.evidence
            );
            format!(
                "{}. (The candidate correction does not match either: {})",
                out.evidence, fixed.evidence
            )
        };
    }
    Ok(out)
}

fn eq5() -> Result<Outcome, String> {
    let mut s = setup()?;
    let printed: Vec<P> = EQ5
        .iter()
        .map(|t| s.sym.parse(t))
        .collect::<Result<_, _>>()?;
    let corrected: Vec<P> = EQ5_CORRECTED
        .iter()
        .map(|t| s.sym.parse(t))
        .collect::<Result<_, _>>()?;
    let product = s.cs.point_printed_order(&s.ct, &s.st, &s.u).into_array();
    let reversed = s.cs.point(&s.ct, &s.st, &s.u).into_array();
    let printed_res = residuals_of("(5) as printed - Ry(beta) Rx(gamma) v", &printed, &product);
    let corrected_res = residuals_of("corrected (5) - Ry(beta) Rx(gamma) v", &corrected, &product);
    let names = ["x", "y", "z"];
    let forms = |f: [&'static str; 3]| -> Vec<Form<'static>> { names.into_iter().zip(f).collect() };
    let sides: Vec<&P> = printed.iter().chain(&product).collect();
    let mut out = with_correction(
        &s,
        &printed_res,
        &corrected_res,
        "(5) is (4) multiplied out in the order printed in (4), Ry(beta) Rx(gamma) v",
        (&forms(EQ5), &forms(EQ5_CORRECTED)),
        &sides,
    )?;
    // What (5) is instead: the product in the other order.
    let other = run(
        &s,
        &residuals_of("(5) - Rx(gamma) Ry(beta) v", &printed, &reversed),
        &[],
    )?;
    if out.verdict == Verdict::Fails && other.verdict == Verdict::Proved {
        out.evidence += ". The printed (5) is exactly Rx(gamma) Ry(beta) v (proved): the matrices of (4) are multiplied in the opposite order; (7)-(11) follow (5)";
        if let Some(e) = out.erratum.as_mut() {
            e.correction += "; the printed (5) is exactly Rx(gamma) Ry(beta) v (proved): the matrices of (4) are multiplied in the opposite order";
        }
    }
    Ok(out)
}

fn eq9() -> Result<Outcome, String> {
    let mut s = setup()?;
    let f = s.sym.parse(EQ7)?;
    let (_, f1, _) = coefficients_in_u(&mut s, &f)?;
    let half = P::constant(Rational::new(1, 2).map_err(|e| e.to_string())?);
    let a_derived = f1 * &half;
    let printed = s.sym.parse(EQ9)?;
    let corrected = s.sym.parse(EQ9_CORRECTED)?;
    let core_a = s.cs.coefficients_at(&s.ct, &s.st).0;
    let residual = printed.clone() - &a_derived;
    with_correction(
        &s,
        &[(
            "(9) as printed - (half the u-coefficient of (7))".into(),
            residual,
        )],
        &[
            (
                "corrected (9) - (half the u-coefficient of (7))".into(),
                corrected - &a_derived,
            ),
            (
                "core A(t) - (half the u-coefficient of (7))".into(),
                core_a - &a_derived,
            ),
        ],
        "the last term's sign is -",
        (&[("A", EQ9)], &[("A", EQ9_CORRECTED)]),
        &[&printed, &a_derived],
    )
}

fn eq10() -> Result<Outcome, String> {
    let mut s = setup()?;
    let f = s.sym.parse(EQ7)?;
    let (_, _, f0) = coefficients_in_u(&mut s, &f)?;
    let printed = s.sym.parse(EQ10)?;
    let corrected = s.sym.parse(EQ10_CORRECTED)?;
    let core_b = s.cs.coefficients_at(&s.ct, &s.st).1;
    let residual = printed.clone() - &f0;
    with_correction(
        &s,
        &[(
            "(10) as printed - (the u-free term of (7))".into(),
            residual,
        )],
        &[
            (
                "corrected (10) - (the u-free term of (7))".into(),
                corrected - &f0,
            ),
            ("core B(t) - (the u-free term of (7))".into(), core_b - &f0),
        ],
        "the printed (10) lacks - R^2, which (8) needs",
        (&[("B", EQ10)], &[("B", EQ10_CORRECTED)]),
        &[&printed, &f0],
    )
}

mod examples;

pub use examples::{
    example_claims, sampling_config, SpaethExample, SPAETH_CYLINDER_RADIUS, SPAETH_EXAMPLES,
};

#[cfg(test)]
mod tests {
    use super::examples::q;
    use super::*;
    use exactcheck_exact::Radical;

    #[test]
    fn a_misspelled_variable_is_an_error() {
        // Old behaviour: `vars.get(n).unwrap_or_default()` made "cT" silently variable 0 (a).
        let sym = Symbols::new(&VARS);
        let e = declared(&sym, "cT").unwrap_err();
        assert!(e.contains("\"cT\" is not declared"), "{e}");
        assert_eq!(declared(&sym, "ct").unwrap(), sym.vars.get("ct").unwrap());
        assert_ne!(declared(&sym, "st").unwrap(), 0);
    }

    #[test]
    fn radii_are_positive() {
        let d = domains();
        let names: Vec<&str> = d.iter().map(|d| d.var).collect();
        assert_eq!(names, ["r", "R"]);
        for d in &d {
            assert!(VARS.contains(&d.var));
            assert!(d.domain.contains(&Radical::from(&q(1, 2))));
            assert!(!d.domain.contains(&Radical::zero()));
            assert!(!d.domain.contains(&Radical::from(&q(-1, 1))));
        }
        assert_eq!(d[0].text(), "r > 0");
    }

    /// Regression: without domains the counter-examples of eq5 and eq10 had r = -1 and
    /// R = -1/2, outside the geometry. The search now stays inside r > 0, R > 0.
    #[test]
    fn counter_examples_stay_inside_the_domains() {
        use exactcheck_exact::prove::{decide, decide_in, Decision};
        let s = setup().unwrap();
        let rv = declared(&s.sym, "r").unwrap();
        let r_of = |d: Decision<Rational>| match d {
            Decision::Fails { point, .. } => point.into_iter().find(|(v, _)| *v == rv).unwrap().1,
            _ => panic!("r + 1 is not identically zero"),
        };
        // r + 1 vanishes only at r = -1: with the domain, the point has r > 0.
        let residual = s.cs.r.clone() + P::from_i64(1);
        let free = r_of(decide(&residual, &s.relations, s.sym.vars.len()).unwrap());
        let inside =
            r_of(decide_in(&residual, &s.relations, &s.domains, s.sym.vars.len()).unwrap());
        assert!(inside > Radical::zero(), "{inside}");
        assert!(s
            .domains
            .iter()
            .all(|(v, d)| *v != rv || d.contains(&inside)));
        assert_ne!(
            free,
            Radical::from(&q(-1, 1)),
            "r = -1 is not a counter-example of r + 1"
        );
        for (f, name) in [(eq5 as fn() -> _, "r"), (eq10, "R")] {
            let e = f().unwrap().evidence;
            assert!(!e.contains(&format!("{name} = -")), "{e}");
        }
    }

    #[test]
    fn the_failing_equations_fail_inside_the_domains() {
        for f in [eq5, eq9, eq10] {
            assert_eq!(f().unwrap().verdict, Verdict::Fails);
        }
    }
}
