//! The four kinds of claims: reading their keys into a [`Check`] (formulas resolved) and
//! deciding it with the engines the rest of the tool uses — `exactcheck_exact::prove::decide_in`
//! (as `prove`), `prove::random_identity_test` (as `prove --random`), [`crate::claims::printed`]
//! (printed decimals) and [`crate::solve::solve`] (the exact solvers).

use super::defs::{self, Defs};
use super::name_expr;
use super::read::{present_keys, RawClaim};
use crate::claims::{printed, Equation, Erratum, Outcome, Verdict};
use crate::prove_cmd::{parse_where_with, Where};
use crate::Error;
use exactcheck_core::Ring;
use exactcheck_exact::expr::{parse_expr, AddOp, Coefficient, Expr, ExprKind};
use exactcheck_exact::poly::{Poly, Var, Vars};
use exactcheck_exact::prove::{
    counter_example, decide_fraction, decide_in, random_identity_test, unit_circle_pairs,
    where_clause, DecideError, Decision, Domain, FractionIdentity, PointField, RandomDecision,
    Seed, HOLDS_THRESHOLD_LOG2, MAX_RANDOM_TRIALS,
};
use exactcheck_exact::ratfun::RatFun;
use exactcheck_exact::{Radical, Rational};
use rayon::prelude::*;
use serde_json::Value;
use std::cell::RefCell;
use std::fmt::Display;

/// Why a check could not give a verdict.
pub enum Fault {
    /// The file is at fault: the key and what is wrong.
    Input(&'static str, String),
    /// The check itself failed (reported as the claim's error, not as a bad file).
    Internal(String),
}

type Built<T> = Result<T, (&'static str, String)>;

/// Relations and domains of `where` / `domains`.
#[derive(Default)]
pub struct Conditions {
    relations: Vec<(Expr, Expr)>,
    relation_texts: Vec<String>,
    domains: Vec<(String, Domain, String)>,
}

/// A claim ready to be decided.
pub enum Check {
    /// `identity`.
    Identity {
        lhs: Vec<Expr>,
        rhs: Vec<Expr>,
        names: Vec<Expr>,
        conditions: Conditions,
        radical: bool,
        corrected: Option<Vec<Expr>>,
    },
    /// `value`.
    Value {
        expr: Expr,
        name: Option<Expr>,
        printed: Vec<String>,
    },
    /// `instances`.
    Instances {
        lhs: Vec<Expr>,
        rhs: Vec<Expr>,
        conditions: Conditions,
        random: Option<u32>,
        seed: Option<u64>,
        at: Vec<Vec<(String, Expr)>>,
    },
    /// `solve`.
    Solve {
        problem: String,
        fields: Vec<(String, Value)>,
    },
}

const IDENTITY_KEYS: [&str; 7] = [
    "name",
    "lhs",
    "rhs",
    "where",
    "domains",
    "field",
    "corrected",
];
const VALUE_KEYS: [&str; 3] = ["name", "expr", "printed"];
const INSTANCES_KEYS: [&str; 6] = ["lhs", "rhs", "where", "random", "seed", "at"];
const SOLVE_KEYS: [&str; 2] = ["problem", "expect_fields"];

fn key_name(k: &str) -> &'static str {
    IDENTITY_KEYS
        .iter()
        .chain(&VALUE_KEYS)
        .chain(&INSTANCES_KEYS)
        .chain(&SOLVE_KEYS)
        .chain(&["kind"])
        .find(|x| **x == k)
        .copied()
        .unwrap_or("kind")
}

/// Reads a claim's keys for its kind.
pub fn build(c: &RawClaim, defs: &RefCell<Defs>) -> Built<Check> {
    let allowed: &[&str] = match c.kind.as_str() {
        "identity" => &IDENTITY_KEYS,
        "value" => &VALUE_KEYS,
        "instances" => &INSTANCES_KEYS,
        "solve" => &SOLVE_KEYS,
        other => {
            return Err((
                "kind",
                format!("unknown kind {other:?} (identity, value, instances, solve)"),
            ))
        }
    };
    if let Some(k) = present_keys(c).into_iter().find(|k| !allowed.contains(k)) {
        return Err((
            key_name(k),
            format!(
                "kind {} does not take this key (its keys: {})",
                c.kind,
                allowed.join(", ")
            ),
        ));
    }
    let resolve = |key: &'static str, text: &str| -> Built<Vec<Expr>> {
        defs.borrow_mut()
            .resolve_text(text)
            .map(|v| v.components())
            .map_err(|e| (key, e.message))
    };
    let required = |key: &'static str, v: &Option<String>| -> Built<String> {
        v.clone()
            .ok_or((key, format!("missing (kind {} needs it)", c.kind)))
    };
    let same_shape = |key: &'static str, a: &[Expr], b: &[Expr], what: &str| -> Built<()> {
        if a.len() == b.len() {
            Ok(())
        } else {
            let shape = |n: usize| {
                if n == 1 {
                    "a scalar".to_string()
                } else {
                    format!("a vector of {n}")
                }
            };
            Err((
                key,
                format!("{} but {what} is {}", shape(b.len()), shape(a.len())),
            ))
        }
    };
    let names = |n: usize| -> Built<Vec<Expr>> {
        let list = c.name.as_ref().map(|n| n.list()).unwrap_or_default();
        if !list.is_empty() && list.len() != n {
            return Err(("name", format!("{} names for {n} coordinates", list.len())));
        }
        list.iter()
            .map(|t| name_expr(t).map_err(|e| ("name", e)))
            .collect()
    };
    Ok(match c.kind.as_str() {
        "identity" | "instances" => {
            let lhs = resolve("lhs", &required("lhs", &c.lhs)?)?;
            let rhs = resolve("rhs", c.rhs.as_deref().unwrap_or("0"))?;
            same_shape("rhs", &lhs, &rhs, "lhs")?;
            let conditions = conditions(c, defs)?;
            if c.kind == "identity" {
                let corrected = match &c.corrected {
                    Some(t) => {
                        let x = resolve("corrected", t)?;
                        same_shape("corrected", &lhs, &x, "lhs")?;
                        Some(x)
                    }
                    None => None,
                };
                let radical = match c.field.as_deref() {
                    Some("rational") => false,
                    Some("radical") => true,
                    None => lhs
                        .iter()
                        .chain(&rhs)
                        .chain(corrected.iter().flatten())
                        .chain(conditions.relations.iter().flat_map(|(a, b)| [a, b]))
                        .any(|e| defs::has_sqrt(e) || exactcheck_exact::expr::has_trig(e)),
                    Some(o) => {
                        return Err(("field", format!("unknown field {o:?} (rational, radical)")))
                    }
                };
                Check::Identity {
                    names: names(lhs.len())?,
                    lhs,
                    rhs,
                    conditions,
                    radical,
                    corrected,
                }
            } else {
                if !conditions.domains.is_empty() {
                    return Err((
                        "where",
                        "instances take relations only (no domains such as 'r > 0')".into(),
                    ));
                }
                let random = match c.random {
                    None => None,
                    Some(k) => match u32::try_from(k) {
                        Ok(k) if (1..=MAX_RANDOM_TRIALS).contains(&k) => Some(k),
                        _ => {
                            return Err((
                                "random",
                                format!("takes 1 to {MAX_RANDOM_TRIALS} points, not {k}"),
                            ))
                        }
                    },
                };
                if c.seed.is_some() && random.is_none() {
                    return Err(("seed", "a seed needs random = K".into()));
                }
                let mut at = Vec::new();
                for (k, point) in c.at.iter().flatten().enumerate() {
                    let mut values = Vec::new();
                    for (var, v) in point {
                        if defs.borrow().is_defined(var) {
                            return Err((
                                "at",
                                format!(
                                    "instance {}: {var} is a defined name, not a variable (give the variables its definition uses)",
                                    k + 1
                                ),
                            ));
                        }
                        let text = match v {
                            Value::String(s) => s.clone(),
                            Value::Number(n) => n.to_string(),
                            _ => {
                                return Err((
                                    "at",
                                    format!(
                                        "instance {}: {var} must be a number or a string",
                                        k + 1
                                    ),
                                ))
                            }
                        };
                        let e = defs.borrow_mut().resolve_scalar(&text).map_err(|e| {
                            ("at", format!("instance {}: {var}: {}", k + 1, e.message))
                        })?;
                        values.push((var.clone(), e));
                    }
                    at.push(values);
                }
                if random.is_none() && at.is_empty() {
                    return Err((
                        "lhs",
                        "an instances claim needs random = K or at = [...] (or both)".into(),
                    ));
                }
                Check::Instances {
                    lhs,
                    rhs,
                    conditions,
                    random,
                    seed: c.seed,
                    at,
                }
            }
        }
        "value" => {
            let expr = defs
                .borrow_mut()
                .resolve_scalar(&required("expr", &c.expr)?)
                .map_err(|e| ("expr", e.message))?;
            let printed = c
                .printed
                .as_ref()
                .ok_or(("printed", "missing (kind value needs it)".to_string()))?
                .list();
            if printed.is_empty() {
                return Err(("printed", "give at least one printed decimal".into()));
            }
            for p in &printed {
                printed::rational(p).map_err(|e| ("printed", e))?;
            }
            Check::Value {
                expr,
                name: names(1)?.pop(),
                printed,
            }
        }
        "solve" => {
            let problem = match c
                .problem
                .as_ref()
                .ok_or(("problem", "missing (kind solve needs it)".to_string()))?
            {
                Value::String(s) => s.clone(),
                v @ Value::Object(_) => v.to_string(),
                _ => {
                    return Err((
                        "problem",
                        "a problem is a table (an object) or a string of JSON".into(),
                    ))
                }
            };
            crate::solve::problem_kind(&problem).map_err(|e| ("problem", e.to_string()))?;
            let fields: Vec<(String, Value)> = c
                .expect_fields
                .as_ref()
                .ok_or(("expect_fields", "missing (kind solve needs it)".to_string()))?
                .iter()
                .map(|(k, v)| (k.clone(), v.clone()))
                .collect();
            if fields.is_empty() {
                return Err(("expect_fields", "give at least one expected field".into()));
            }
            Check::Solve { problem, fields }
        }
        _ => unreachable!("the kind was checked above"),
    })
}

/// `where` and `domains`, parsed as `prove --where` parses them.
fn conditions(c: &RawClaim, defs: &RefCell<Defs>) -> Built<Conditions> {
    let mut out = Conditions::default();
    let parse = |text: &str, what: &str| -> Result<Expr, Error> {
        defs.borrow_mut()
            .resolve_scalar(text)
            .map_err(|e| Error::Input(format!("{what}: {}", e.message)))
    };
    let lists: [(&'static str, &Option<Vec<String>>); 2] =
        [("where", &c.where_), ("domains", &c.domains)];
    for (key, list) in lists {
        for (i, text) in list.iter().flatten().enumerate() {
            let what = format!("entry {}", i + 1);
            match parse_where_with(text, &what, &parse).map_err(|e| (key, e.to_string()))? {
                Where::Relation(a, b) => {
                    if key == "domains" {
                        return Err((
                            key,
                            format!(
                                "{what}: {text:?} is a relation, not a domain (put it under where)"
                            ),
                        ));
                    }
                    out.relations.push((a, b));
                    out.relation_texts.push(text.clone());
                }
                Where::Domain(v, d) => {
                    if d.is_empty() {
                        return Err((key, format!("{what}: the domain {text:?} is empty")));
                    }
                    if out.domains.iter().any(|(w, _, _)| *w == v) {
                        return Err((
                            key,
                            format!("{what}: {v} already has a domain (give both bounds in one, e.g. '0 <= {v} <= 1')"),
                        ));
                    }
                    out.domains.push((v, d, text.clone()));
                }
            }
        }
    }
    Ok(out)
}

/// Decides a claim.
pub fn run(check: &Check, notation: &[(String, String)]) -> Result<Outcome, Fault> {
    let mut out = match check {
        Check::Identity { radical: true, .. } => identity::<Radical>(check)?,
        Check::Identity { .. } => identity::<Rational>(check)?,
        Check::Value {
            expr,
            name,
            printed,
        } => value(expr, name.as_ref(), printed)?,
        Check::Instances { .. } => instances(check)?,
        Check::Solve { problem, fields } => solve(problem, fields)?,
    };
    if let Some(e) = out.erratum.as_mut() {
        e.notation = notation.to_vec();
    }
    Ok(out)
}

fn num(q: Rational) -> Expr {
    Expr::new(ExprKind::Number(q))
}

fn difference(a: &Expr, b: &Expr) -> Expr {
    Expr::new(ExprKind::Sum(vec![
        (AddOp::Plus, a.clone()),
        (AddOp::Minus, b.clone()),
    ]))
}

fn var(name: &str) -> Expr {
    Expr::new(ExprKind::Var(name.to_string()))
}

/// An exact value printed by its type, read back as an expression tree.
fn value_expr(v: &impl Display) -> Result<Expr, Fault> {
    let text = v.to_string();
    parse_expr(&text)
        .map_err(|e| Fault::Internal(format!("the exact value {text} does not read back: {e}")))
}

fn to_ratfun<C: Coefficient + exactcheck_core::Field>(
    e: &Expr,
    vars: &mut Vars,
    key: &'static str,
) -> Result<RatFun<C>, Fault> {
    e.to_ratfun::<C>(vars)
        .map_err(|err| Fault::Input(key, err.to_string()))
}

/// `a = b` with the denominators cleared (a product past a limit is the fault of `key`).
fn clear<C: exactcheck_core::Field>(
    a: &RatFun<C>,
    b: &RatFun<C>,
    key: &'static str,
) -> Result<FractionIdentity<C>, Fault> {
    FractionIdentity::new(a, b).map_err(|e| Fault::Input(key, e.to_string()))
}

fn to_poly<C: Coefficient>(e: &Expr, vars: &mut Vars, key: &'static str) -> Result<Poly<C>, Fault> {
    e.to_poly::<C>(vars)
        .map_err(|err| Fault::Input(key, err.to_string()))
}

fn identity<C: PointField + Display>(check: &Check) -> Result<Outcome, Fault> {
    let Check::Identity {
        lhs,
        rhs,
        names,
        conditions,
        corrected,
        ..
    } = check
    else {
        unreachable!("identity() is called for identity claims")
    };
    let mut vars = Vars::new();
    let mut sides = Vec::new();
    for (l, r) in lhs.iter().zip(rhs) {
        let l = to_ratfun::<C>(l, &mut vars, "lhs")?;
        let r = to_ratfun::<C>(r, &mut vars, "rhs")?;
        sides.push((l, r));
    }
    let corrected_fns = match corrected {
        Some(xs) => Some(
            xs.iter()
                .map(|x| to_ratfun::<C>(x, &mut vars, "corrected"))
                .collect::<Result<Vec<_>, _>>()?,
        ),
        None => None,
    };
    // Relations between fractions are cleared of their denominators, which become hypotheses
    // (non-zero).
    let mut rels = Vec::new();
    let mut hypotheses: Vec<Poly<C>> = Vec::new();
    for (a, b) in &conditions.relations {
        let a = to_ratfun::<C>(a, &mut vars, "where")?;
        let b = to_ratfun::<C>(b, &mut vars, "where")?;
        if a.is_polynomial() && b.is_polynomial() {
            rels.push(a.into_numerator() - b.into_numerator());
        } else {
            let cleared = clear(&a, &b, "where")?;
            rels.push(cleared.residual);
            hypotheses.extend(cleared.conditions);
        }
    }
    // Every angle `x` of sin, cos, tan: its cosine and sine lie on the unit circle. pi is the
    // transcendental constant: an indeterminate while deciding.
    let angle_list = exactcheck_exact::expr::angles(&vars);
    let user_relations = rels.len();
    for a in &angle_list {
        rels.push(a.relation());
    }
    let pi = vars.get(exactcheck_exact::expr::PI);
    let pi_in_relations =
        pi.is_some_and(|p| rels[..user_relations].iter().any(|r| r.degree_in(p) > 0));
    let mixed: Vec<&str> = angle_list
        .iter()
        .filter(|a| vars.get(&a.name).is_some())
        .map(|a| a.name.as_str())
        .collect();
    // `l = r`: a polynomial residual, or (with a fraction anywhere) the cleared identity.
    let pair =
        |l: &RatFun<C>, r: &RatFun<C>| -> Result<(Poly<C>, Option<FractionIdentity<C>>), Fault> {
            if l.is_polynomial() && r.is_polynomial() && hypotheses.is_empty() {
                Ok((l.numerator().clone() - r.numerator(), None))
            } else {
                let f = clear(l, r, "lhs")?;
                Ok((f.residual.clone(), Some(f)))
            }
        };
    let mut residuals = Vec::new();
    let mut fractions = Vec::new();
    for (l, r) in &sides {
        let (res, f) = pair(l, r)?;
        residuals.push(res);
        fractions.push(f);
    }
    let mut excluded: Vec<Poly<C>> = Vec::new();
    for p in fractions
        .iter()
        .flatten()
        .flat_map(|f| &f.conditions)
        .chain(&hypotheses)
    {
        if !excluded.contains(p) {
            excluded.push(p.clone());
        }
    }
    let where_nonzero = where_clause(&excluded, &vars);
    let mut doms: Vec<(Var, Domain)> = Vec::new();
    for (v, d, text) in &conditions.domains {
        let var = vars.get(v).ok_or_else(|| {
            Fault::Input(
                "where",
                format!("{text:?}: {v} does not occur in the identity or its relations"),
            )
        })?;
        doms.push((var, d.clone()));
    }
    let modulo = if rels.is_empty() {
        String::new()
    } else {
        let circles = angle_list
            .iter()
            .map(|a| format!("cos({0})^2 + sin({0})^2 = 1", a.name));
        let texts: Vec<String> = conditions
            .relation_texts
            .iter()
            .cloned()
            .chain(circles)
            .collect();
        format!(" modulo {}", texts.join(", "))
    };
    let within = if conditions.domains.is_empty() {
        String::new()
    } else {
        let d: Vec<&str> = conditions
            .domains
            .iter()
            .map(|(_, _, t)| t.as_str())
            .collect();
        format!(" for {}", d.join(", "))
    };
    let field = if std::any::type_name::<C>().contains("Radical") {
        "Q(sqrt)"
    } else {
        "Q"
    };
    let method = format!(
        "symbolic expansion over {field}[{}]{modulo}{within}",
        vars.names().join(",")
    );
    let decide = |p: &Poly<C>, f: Option<&FractionIdentity<C>>| -> Result<Decision<C>, Fault> {
        match f {
            None => decide_in(p, &rels, &doms, vars.len()),
            Some(f) => decide_fraction(f, &rels, &hypotheses, &doms, vars.len()),
        }
        .map(|d| crate::prove_cmd::sound_counter_example(d, pi_in_relations, &mixed))
        .map_err(|e| {
            Fault::Input(
                "where",
                match e {
                    DecideError::Inconsistent => format!(
                        "the relations{modulo} are inconsistent (no point satisfies them, so nothing can be proved from them)"
                    ),
                    other => other.to_string(),
                },
            )
        })
    };
    let name = |v: Var| {
        vars.name(v)
            .expect("the engine reports only variables of the table")
            .to_string()
    };
    let cleared = |k: usize| {
        if fractions.get(k).is_some_and(Option::is_some) {
            " with the denominators cleared"
        } else {
            ""
        }
    };
    let cleared_any = if fractions.iter().any(Option::is_some) {
        " with the denominators cleared"
    } else {
        ""
    };
    let coordinate = |k: usize| {
        if lhs.len() == 1 {
            String::new()
        } else {
            format!("coordinate {}: ", k + 1)
        }
    };
    let mut terms = 0;
    for (k, res) in residuals.iter().enumerate() {
        match decide(res, fractions[k].as_ref())? {
            Decision::Proved { expanded_terms } => terms += expanded_terms,
            Decision::Undecided {
                normal_form,
                searched,
            } => {
                return Ok(Outcome {
                    verdict: Verdict::Undecided,
                    method,
                    evidence: format!(
                        "{}LHS - RHS{} reduces{modulo} to {} (not zero), but no point{within} where it is non-zero was found{where_nonzero}: {searched}",
                        coordinate(k),
                        cleared(k),
                        normal_form.display(&vars)
                    ),
                    erratum: None,
                })
            }
            Decision::Fails {
                normal_form,
                point,
                value,
            } => {
                // Every variable of the sides (all coordinates, numerators and denominators),
                // the relations and the excluded denominators; domains name only those.
                let statement: Vec<&Poly<C>> = sides
                    .iter()
                    .flat_map(|(l, r)| {
                        [l.numerator(), l.denominator(), r.numerator(), r.denominator()]
                    })
                    .chain(&rels)
                    .chain(&excluded)
                    .collect();
                // pi is the constant: the value is a polynomial in it, the point leaves it out.
                let (value, note) = match pi {
                    Some(p) => (
                        crate::prove_cmd::in_pi::<C>(res, &point, p)
                            .display(&vars)
                            .to_string(),
                        ", a non-zero polynomial in pi, and pi is transcendental, so it is not zero",
                    ),
                    None => (value.to_string(), ""),
                };
                let point: Vec<(String, Radical)> = counter_example(&point, &statement)
                    .into_iter()
                    .filter(|(v, _)| Some(*v) != pi)
                    .map(|(v, q)| (name(v), q))
                    .collect();
                let named: Vec<(String, String)> =
                    point.iter().map(|(v, q)| (v.clone(), q.to_string())).collect();
                let at = exactcheck_exact::expr::describe_point(&named);
                let nf = normal_form.display(&vars).to_string();
                let mut evidence = format!(
                    "{}{}{} LHS - RHS = {value}{note}; LHS - RHS{} reduces{modulo} to {nf}{}",
                    coordinate(k),
                    if at.is_empty() {
                        "everywhere".to_string()
                    } else {
                        format!("at {}", at.join(", "))
                    },
                    if user_relations == 0 { "" } else { " (where the relations hold)" },
                    cleared(k),
                    where_nonzero,
                );
                let mut counter_example = Vec::new();
                for (v, q) in &point {
                    counter_example.push(Equation {
                        lhs: var(v),
                        rhs: value_expr(q)?,
                    });
                }
                let printed: Vec<Equation> = if names.is_empty() {
                    lhs.iter()
                        .zip(rhs)
                        .map(|(l, r)| Equation {
                            lhs: l.clone(),
                            rhs: r.clone(),
                        })
                        .collect()
                } else {
                    names
                        .iter()
                        .zip(lhs)
                        .map(|(n, l)| Equation {
                            lhs: n.clone(),
                            rhs: l.clone(),
                        })
                        .collect()
                };
                let mut erratum = Erratum {
                    printed,
                    correction: if fractions[k].is_some() {
                        format!("LHS - RHS{} reduces{modulo} to {nf}", cleared(k))
                    } else {
                        format!("LHS - RHS reduces{modulo} to {nf}, so LHS = RHS + ({nf})")
                    },
                    counter_example,
                    residual: vec![Equation {
                        lhs: difference(&lhs[k], &rhs[k]),
                        rhs: value_expr(&value)?,
                    }],
                    ..Erratum::default()
                };
                if let (Some(cp), Some(cx)) = (&corrected_fns, corrected) {
                    let mut failed = None;
                    for (j, (c, (_, r))) in cp.iter().zip(&sides).enumerate() {
                        let (res, f) = pair(c, r)?;
                        match decide(&res, f.as_ref())? {
                            Decision::Proved { .. } => {}
                            Decision::Fails { value, .. } => {
                                failed = Some(format!("{}it differs from RHS by {value} at a point", coordinate(j)));
                                break;
                            }
                            Decision::Undecided { normal_form, .. } => {
                                failed = Some(format!(
                                    "{}corrected - RHS reduces to {} (undecided)",
                                    coordinate(j),
                                    normal_form.display(&vars)
                                ));
                                break;
                            }
                        }
                    }
                    match failed {
                        None => {
                            let shown: Vec<String> = cx.iter().map(ToString::to_string).collect();
                            evidence += &format!(
                                ". Corrected form (proved equal to RHS{modulo}{within}): {}",
                                shown.join(", ")
                            );
                            erratum.corrected = cx
                                .iter()
                                .enumerate()
                                .map(|(j, x)| match names.get(j) {
                                    Some(n) => Equation {
                                        lhs: n.clone(),
                                        rhs: x.clone(),
                                    },
                                    None => Equation {
                                        lhs: x.clone(),
                                        rhs: rhs[j].clone(),
                                    },
                                })
                                .collect();
                            erratum.correction = format!(
                                "the corrected form is proved equal to RHS{modulo}; the printed LHS differs from RHS by {nf}"
                            );
                        }
                        Some(why) => {
                            evidence +=
                                &format!(". (The given correction does not match RHS either: {why})");
                        }
                    }
                }
                return Ok(Outcome {
                    verdict: Verdict::Fails,
                    method,
                    evidence,
                    erratum: Some(Box::new(erratum)),
                });
            }
        }
    }
    let n = residuals.len();
    Ok(Outcome {
        verdict: Verdict::Proved,
        method,
        evidence: match (terms, n) {
            (0, 1) => format!("LHS - RHS{} expands to 0{where_nonzero}", cleared_any),
            (0, n) => format!(
                "LHS - RHS{} expands to 0 in each of the {n} coordinates{where_nonzero}",
                cleared_any
            ),
            (t, 1) => format!(
                "LHS - RHS{} expands to {t} terms, which reduce to 0{modulo}{where_nonzero}",
                cleared_any
            ),
            (t, n) => format!(
                "LHS - RHS{} expands to {t} terms in the {n} coordinates, which reduce to 0{modulo}{where_nonzero}",
                cleared_any
            ),
        },
        erratum: None,
    })
}

fn value(expr: &Expr, name: Option<&Expr>, printed_list: &[String]) -> Result<Outcome, Fault> {
    let v: Radical = expr
        .eval_constant::<Radical>()
        .map_err(|e| Fault::Input("expr", e.to_string()))?;
    let mut notes = Vec::new();
    let mut all_exact = true;
    let mut wrong = Vec::new();
    let max_places = printed_list
        .iter()
        .map(|p| printed::places(p))
        .max()
        .unwrap_or(0);
    for p in printed_list {
        let q = printed::rational(p).map_err(|e| Fault::Input("printed", e))?;
        let places = printed::places(p);
        let qr = printed::radical(&q);
        if qr == v {
            notes.push(format!("{p} is the exact value"));
            continue;
        }
        all_exact = false;
        let correct = printed::decimal(&v, places);
        if printed::rounds_to(&v, &q, places) {
            notes.push(if printed::ties(&v, &q, places) {
                format!("{p}: a correct rounding to {places} places (a tie: both neighbours are)")
            } else {
                format!("{p}: correctly rounded to {places} places")
            });
        } else {
            let dev = qr.sub_ref(&v);
            let how = if printed::truncates_to(&v, &q, places) {
                " (truncated, not rounded)"
            } else {
                ""
            };
            notes.push(format!(
                "{p}: wrong{how}; correctly rounded to {places} places it is {correct} (printed - exact = {})",
                printed::deviation_text(&dev)
            ));
            wrong.push((p.clone(), q, correct, dev));
        }
    }
    let verdict = if !wrong.is_empty() {
        Verdict::Fails
    } else if all_exact {
        Verdict::Proved
    } else {
        Verdict::Holds
    };
    let shown = printed::decimal(&v, max_places + 4);
    let evidence = format!("exact value {v} = {shown}...; {}", notes.join("; "));
    let erratum = if wrong.is_empty() {
        None
    } else {
        let label = name.cloned().unwrap_or_else(|| expr.clone());
        let mut e = Erratum {
            correction: format!("the exact value is {v} = {shown}..."),
            ..Erratum::default()
        };
        for (_, q, correct, dev) in &wrong {
            e.printed.push(Equation {
                lhs: label.clone(),
                rhs: num(q.clone()),
            });
            let c = printed::rational(correct).map_err(Fault::Internal)?;
            e.corrected.push(Equation {
                lhs: label.clone(),
                rhs: num(c),
            });
            e.residual.push(Equation {
                lhs: difference(&num(q.clone()), &label),
                rhs: value_expr(dev)?,
            });
        }
        Some(Box::new(e))
    };
    Ok(Outcome {
        verdict,
        method: "exact evaluation in Q(sqrt); printed decimals judged exactly".into(),
        evidence,
        erratum,
    })
}

fn instances(check: &Check) -> Result<Outcome, Fault> {
    let Check::Instances {
        lhs,
        rhs,
        conditions,
        random,
        seed,
        at,
    } = check
    else {
        unreachable!("instances() is called for instances claims")
    };
    let mut names = Vec::new();
    for e in lhs.iter().chain(rhs) {
        e.collect_variables(&mut names);
    }
    for (a, b) in &conditions.relations {
        a.collect_variables(&mut names);
        b.collect_variables(&mut names);
    }
    // Exact instances: independent, so checked in parallel, then read in order (the first
    // instance with a fault of the file or a non-zero residual is the one reported, as when
    // they ran one after another).
    let instance = |k: usize, point: &Vec<(String, Expr)>| -> Result<Option<Outcome>, Fault> {
        let missing: Vec<&String> = names
            .iter()
            .filter(|n| !point.iter().any(|(v, _)| v == *n))
            .collect();
        if !missing.is_empty() {
            return Err(Fault::Input(
                "at",
                format!(
                    "instance {} gives no value to {}",
                    k + 1,
                    missing
                        .iter()
                        .map(|s| s.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            ));
        }
        let eval = |e: &Expr| -> Result<Radical, Fault> {
            let mut x = e.clone();
            for (v, val) in point {
                x = defs::substitute(&x, v, val);
            }
            x.eval_constant::<Radical>()
                .map_err(|err| Fault::Input("at", format!("instance {}: {err}", k + 1)))
        };
        for (i, (a, b)) in conditions.relations.iter().enumerate() {
            if eval(a)? != eval(b)? {
                return Err(Fault::Input(
                    "at",
                    format!(
                        "instance {} does not satisfy the relation {:?}",
                        k + 1,
                        conditions.relation_texts[i]
                    ),
                ));
            }
        }
        for (c, (l, r)) in lhs.iter().zip(rhs).enumerate() {
            let d = eval(l)?.sub_ref(&eval(r)?);
            if !d.is_zero() {
                let coords = if lhs.len() == 1 {
                    String::new()
                } else {
                    format!(" (coordinate {})", c + 1)
                };
                let shown: Vec<String> = point.iter().map(|(v, x)| format!("{v} = {x}")).collect();
                let erratum = Erratum {
                    printed: vec![Equation {
                        lhs: l.clone(),
                        rhs: r.clone(),
                    }],
                    correction: format!("LHS - RHS = {d} at instance {}", k + 1),
                    counter_example: point
                        .iter()
                        .map(|(v, x)| Equation {
                            lhs: var(v),
                            rhs: x.clone(),
                        })
                        .collect(),
                    residual: vec![Equation {
                        lhs: difference(l, r),
                        rhs: value_expr(&d)?,
                    }],
                    ..Erratum::default()
                };
                return Ok(Some(Outcome {
                    verdict: Verdict::Fails,
                    method: "exact evaluation at the given instances".into(),
                    evidence: format!(
                        "at instance {} ({}) LHS - RHS = {d}{coords}, not zero",
                        k + 1,
                        shown.join(", ")
                    ),
                    erratum: Some(Box::new(erratum)),
                }));
            }
        }
        Ok(None)
    };
    let found: Vec<Result<Option<Outcome>, Fault>> = at
        .par_iter()
        .enumerate()
        .map(|(k, point)| instance(k, point))
        .collect();
    for f in found {
        if let Some(outcome) = f? {
            return Ok(outcome);
        }
    }
    let exact_note = if at.is_empty() {
        String::new()
    } else {
        format!("LHS - RHS is exactly 0 at all {} given instances", at.len())
    };
    let Some(trials) = *random else {
        return Ok(Outcome {
            verdict: Verdict::Holds,
            method: "exact evaluation at the given instances".into(),
            evidence: exact_note,
            erratum: None,
        });
    };
    // Random evaluation modulo a random prime (prove --random).
    let mut vars = Vars::new();
    let mut rels = Vec::new();
    for (a, b) in &conditions.relations {
        rels.push(
            to_poly::<Rational>(a, &mut vars, "where")?
                - to_poly::<Rational>(b, &mut vars, "where")?,
        );
    }
    let (pairs, others) = unit_circle_pairs(&rels);
    if !others.is_empty() {
        return Err(Fault::Input(
            "where",
            "random evaluation supports only unit-circle relations 'c^2 + s^2 = 1'".into(),
        ));
    }
    let vname = |v: Var| {
        vars.name(v)
            .expect("relation variables are in the table")
            .to_string()
    };
    let circles: Vec<(String, String)> = pairs.iter().map(|&(c, s)| (vname(c), vname(s))).collect();
    let seed_of_run = match seed {
        Some(s) => Seed::Chosen(*s),
        None => Seed::Fresh(crate::prove_cmd::fresh_seed()),
    };
    let seed = seed_of_run.value();
    let chosen = if matches!(seed_of_run, Seed::Chosen(_)) {
        ", chosen"
    } else {
        ""
    };
    let show = |l: f64| {
        if l == f64::NEG_INFINITY {
            "0".to_string()
        } else {
            format!("2^{:.1}", (l * 10.0).ceil() / 10.0)
        }
    };
    let mut worst = f64::NEG_INFINITY;
    let mut primes = Vec::new();
    let mut undecided = None;
    let mut reproduced = false;
    // The coordinates are tested in parallel and read in order; each has its own prime (drawn
    // from the seed and the coordinate's identity).
    let decisions: Vec<Result<RandomDecision, String>> = lhs
        .par_iter()
        .zip(rhs.par_iter())
        .map(|(l, r)| random_identity_test(l, r, &names, &circles, trials, seed_of_run))
        .collect();
    for (c, ((l, r), d)) in lhs.iter().zip(rhs).zip(decisions).enumerate() {
        let d = d.map_err(|e| Fault::Input("lhs", e))?;
        let coords = if lhs.len() == 1 {
            String::new()
        } else {
            format!(" (coordinate {})", c + 1)
        };
        match d {
            RandomDecision::Holds {
                report, log2_bound, ..
            } => {
                primes.push(report.prime);
                worst = worst.max(log2_bound);
            }
            RandomDecision::Reproduced { report } => {
                primes.push(report.prime);
                reproduced = true;
            }
            RandomDecision::Undecided {
                report, log2_bound, ..
            } => {
                primes.push(report.prime);
                worst = worst.max(log2_bound);
                undecided.get_or_insert(coords);
            }
            RandomDecision::Fails {
                report,
                point,
                value,
            } => {
                let at: Vec<String> = point.iter().map(|(v, x)| format!("{v} = {x}")).collect();
                let erratum = Erratum {
                    printed: vec![Equation {
                        lhs: l.clone(),
                        rhs: r.clone(),
                    }],
                    correction: format!(
                        "LHS - RHS = {value} (mod p = {}) at {}: not zero modulo p, so not zero over Q",
                        report.prime,
                        at.join(", ")
                    ),
                    ..Erratum::default()
                };
                return Ok(Outcome {
                    verdict: Verdict::Fails,
                    method: format!(
                        "evaluation at {trials} random points modulo the random prime p = {} (seed {seed}{chosen})",
                        report.prime
                    ),
                    evidence: format!(
                        "LHS - RHS = {value} (mod p) at {}{coords}, so it is not zero{}",
                        at.join(", "),
                        if exact_note.is_empty() { String::new() } else { format!("; {exact_note}") }
                    ),
                    erratum: Some(Box::new(erratum)),
                });
            }
        }
    }
    let primes = match primes.as_slice() {
        [p] => format!("the random prime p = {p}"),
        many => format!(
            "random primes ({}, one per coordinate)",
            many.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    let method = format!(
        "evaluation at {trials} random points modulo {primes} (seed {seed}{chosen}){}",
        if at.is_empty() {
            ""
        } else {
            " and exact instances"
        }
    );
    let extra = if exact_note.is_empty() {
        String::new()
    } else {
        format!("; {exact_note}")
    };
    Ok(match undecided {
        None if reproduced => Outcome {
            verdict: Verdict::Holds,
            method,
            evidence: format!(
                "LHS - RHS vanishes at all {trials} points modulo the prime drawn from the chosen seed {seed} and the identity (a reproduced run); a chosen seed gives no probability bound (it need not be independent of the identity): remove `seed` for a fresh seed and the proved bound{extra}"
            ),
            erratum: None,
        },
        None => Outcome {
            verdict: Verdict::Holds,
            method,
            evidence: format!(
                "LHS - RHS vanishes at all {trials} points; a false identity passes with probability <= {} (proved bound, below the threshold 2^{HOLDS_THRESHOLD_LOG2}){extra}",
                show(worst)
            ),
            erratum: None,
        },
        Some(coords) => Outcome {
            verdict: Verdict::Undecided,
            method,
            evidence: format!(
                "LHS - RHS vanishes at all {trials} points, but the error bound{coords}{} is {}, not below 2^{HOLDS_THRESHOLD_LOG2}; use more points (random up to {MAX_RANDOM_TRIALS}){extra}",
                if chosen.is_empty() { "" } else { " a fresh seed would give" },
                show(worst)
            ),
            erratum: None,
        },
    })
}

/// A field of an answer: by JSON pointer (`/a/0`) or dotted path (`a.0`).
fn lookup<'a>(answer: &'a Value, path: &str) -> Option<&'a Value> {
    if path.starts_with('/') {
        return answer.pointer(path);
    }
    let mut v = answer;
    for seg in path.split('.') {
        v = match v {
            Value::Object(m) => m.get(seg)?,
            Value::Array(a) => a.get(seg.parse::<usize>().ok()?)?,
            _ => return None,
        };
    }
    Some(v)
}

/// An exact number of a JSON value (a number or a numeric string).
fn exact_number(v: &Value) -> Option<Radical> {
    match v {
        Value::Number(n) => n.to_string().parse().ok(),
        Value::String(s) => s.parse().ok(),
        _ => None,
    }
}

/// Whether an answer's value is the expected one: equal JSON, or equal exact numbers, or
/// arrays/objects equal element by element in that sense.
fn matches(expected: &Value, got: &Value) -> bool {
    match (expected, got) {
        (Value::Array(a), Value::Array(b)) => {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| matches(x, y))
        }
        (Value::Object(a), Value::Object(b)) => {
            a.len() == b.len()
                && a.iter()
                    .all(|(k, x)| b.get(k).is_some_and(|y| matches(x, y)))
        }
        _ if expected == got => true,
        _ => match (exact_number(expected), exact_number(got)) {
            (Some(x), Some(y)) => x == y,
            _ => false,
        },
    }
}

fn solve(problem: &str, fields: &[(String, Value)]) -> Result<Outcome, Fault> {
    let answer = crate::solve::solve(problem, crate::solve::Mode::Exact)
        .map_err(|e| Fault::Input("problem", e.to_string()))?;
    let kind = answer
        .get("kind")
        .and_then(Value::as_str)
        .unwrap_or("?")
        .to_string();
    let mut matched = Vec::new();
    let mut mismatched = Vec::new();
    let mut e = Erratum::default();
    for (path, expected) in fields {
        match lookup(&answer, path) {
            Some(got) if matches(expected, got) => matched.push(format!("{path} = {expected}")),
            Some(got) => {
                mismatched.push(format!("{path} is {got}, not {expected}"));
                if let (Some(x), Some(y)) = (exact_number(expected), exact_number(got)) {
                    let label = var(&path
                        .trim_start_matches('/')
                        .replace(|c: char| !c.is_ascii_alphanumeric(), "_"));
                    e.printed.push(Equation {
                        lhs: label.clone(),
                        rhs: value_expr(&x)?,
                    });
                    e.corrected.push(Equation {
                        lhs: label,
                        rhs: value_expr(&y)?,
                    });
                }
            }
            None => mismatched.push(format!("{path} is not in the answer (expected {expected})")),
        }
    }
    let method = format!("the exact solver (solve, kind {kind}) on the given configuration");
    if mismatched.is_empty() {
        return Ok(Outcome {
            verdict: Verdict::Holds,
            method,
            evidence: format!(
                "the exact answer has every expected field: {}",
                matched.join(", ")
            ),
            erratum: None,
        });
    }
    e.correction = format!("the exact solver finds: {}", mismatched.join("; "));
    Ok(Outcome {
        verdict: Verdict::Fails,
        method,
        evidence: format!(
            "{}{}",
            mismatched.join("; "),
            if matched.is_empty() {
                String::new()
            } else {
                format!(" (matched: {})", matched.join(", "))
            }
        ),
        erratum: Some(Box::new(e)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn answer_fields_compare_exactly() {
        let a = json!({"type": "parabola", "plane": ["1", "sqrt(2)"], "n": 3, "ok": false});
        assert!(matches(&json!("parabola"), lookup(&a, "type").unwrap()));
        assert!(matches(
            &json!([1, "2/sqrt(2)"]),
            lookup(&a, "plane").unwrap()
        ));
        assert!(matches(&json!("6/2"), lookup(&a, "/n").unwrap()));
        assert!(!matches(&json!(true), lookup(&a, "ok").unwrap()));
        assert!(matches(&json!(1), lookup(&a, "plane.0").unwrap()));
        assert!(lookup(&a, "plane.2").is_none());
    }
}
