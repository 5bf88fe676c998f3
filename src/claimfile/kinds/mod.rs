//! The four kinds of claims: reading their keys into a [`Check`] (formulas resolved) and
//! deciding it with the engines the rest of the tool uses — `exactcheck_exact::prove::decide_in`
//! (as `prove`), `prove::random_identity_test` (as `prove --random`), [`crate::claims::printed`]
//! (printed decimals) and [`crate::solve::solve`] (the exact solvers).
//!
//! This module reads the keys; each kind is decided in its own submodule: [`identity`],
//! [`value`], [`instances`], [`solve`].

mod identity;
mod instances;
mod solve;
mod value;

use identity::identity_claim;
use instances::instances;
use solve::solve;
use value::{printed_tuple, values};

use super::defs::{self, Defs};
use super::read::{present_keys, RawClaim};
use super::{name_expr, Decision};
use crate::claims::{printed, Equation, Erratum, Outcome, Verdict};
use crate::phrase::Phrasing;
use crate::prove_cmd::{parse_where_with, split_where, Domain, Where};
use crate::Error;
use exactcheck_core::Ring;
use exactcheck_exact::expr::library::Shape;
use exactcheck_exact::expr::{
    first_reserved, is_decimal_name, parse_expr, AddOp, Coefficient, Expr, ExprKind,
};
use exactcheck_exact::poly::{Poly, Var, Vars};
use exactcheck_exact::prove::{
    decide_identity, random_identity_test, square_roots, unit_circle_pairs, CorrectionVerdict,
    DecideError, EngineError, FractionIdentity, IdentitySpec, IdentityVerdict, Part, PointField,
    RandomDecision, Seed, SquareRoot, Statement, VarDomain, MAX_RANDOM_TRIALS,
};
use exactcheck_exact::ratfun::RatFun;
use exactcheck_exact::real_constant::RealConstant;
use exactcheck_exact::{Radical, Rational};
use rayon::prelude::*;
use serde_json::{Map, Value};
use std::cell::RefCell;
use std::cmp::Ordering;
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
    domains: Vec<Domain>,
    /// Hypotheses `A != B` and their texts.
    nonzero: Vec<(Expr, Expr, String)>,
}

/// A claim ready to be decided.
pub enum Check {
    /// `identity`: the sides component by component, of one shape.
    Identity {
        shape: Shape,
        lhs: Vec<Expr>,
        rhs: Vec<Expr>,
        names: Vec<Expr>,
        conditions: Conditions,
        radical: bool,
        corrected: Option<Vec<Expr>>,
    },
    /// `value`: one expression per component (one for a scalar; a vector's coordinates; a
    /// matrix's entries by rows), their names (none, or one per component) and the printed
    /// decimals of each.
    Value {
        exprs: Vec<Expr>,
        names: Vec<Expr>,
        printed: Vec<Vec<String>>,
    },
    /// `instances`.
    Instances {
        /// The one shape of both sides (to name the components).
        shape: Shape,
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

impl Check {
    /// The formulas of the claim after definitions are substituted (sides, corrected form,
    /// relations, value, instance values): what its free variables are read from.
    pub fn formulas(&self) -> Vec<&Expr> {
        fn relations(c: &Conditions) -> Vec<&Expr> {
            c.relations.iter().flat_map(|(a, b)| [a, b]).collect()
        }
        match self {
            Check::Identity {
                lhs,
                rhs,
                conditions,
                corrected,
                ..
            } => lhs
                .iter()
                .chain(rhs)
                .chain(corrected.iter().flatten())
                .chain(relations(conditions))
                .collect(),
            Check::Value { exprs, .. } => exprs.iter().collect(),
            Check::Instances {
                lhs,
                rhs,
                conditions,
                ..
            } => lhs.iter().chain(rhs).chain(relations(conditions)).collect(),
            Check::Solve { .. } => Vec::new(),
        }
    }
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
    let resolve_shaped = |key: &'static str, text: &str| -> Built<(Vec<Expr>, Shape)> {
        let v = defs
            .borrow_mut()
            .resolve_text(text)
            .map_err(|e| (key, e.message))?;
        let components = v.components();
        no_reserved(key, &components)?;
        Ok((components, v.dims()))
    };
    let required = |key: &'static str, v: &Option<String>| -> Built<String> {
        v.clone()
            .ok_or((key, format!("missing (kind {} needs it)", c.kind)))
    };
    let same_shape = |key: &'static str, a: Shape, b: Shape, what: &str| -> Built<()> {
        if a == b {
            Ok(())
        } else {
            Err((
                key,
                format!("{b} but {what} is {a}: the sides of an identity are compared component by component and must have one shape"),
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
            let (lhs, shape) = resolve_shaped("lhs", &required("lhs", &c.lhs)?)?;
            // A missing `rhs` is zero in every component.
            let (rhs, rhs_shape) = match c.rhs.as_deref() {
                Some(t) => resolve_shaped("rhs", t)?,
                None => (vec![Expr::number(Rational::ZERO); lhs.len()], shape),
            };
            same_shape("rhs", shape, rhs_shape, "lhs")?;
            let conditions = conditions(c, defs)?;
            if c.kind == "identity" {
                let corrected = match &c.corrected {
                    Some(t) => {
                        let (x, x_shape) = resolve_shaped("corrected", t)?;
                        same_shape("corrected", shape, x_shape, "lhs")?;
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
                    shape,
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
                    shape,
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
            let val = defs
                .borrow_mut()
                .resolve_text(&required("expr", &c.expr)?)
                .map_err(|e| ("expr", e.message))?;
            let given = c
                .printed
                .as_ref()
                .ok_or(("printed", "missing (kind value needs it)".to_string()))?
                .list();
            if given.is_empty() {
                return Err(("printed", "give at least one printed decimal".into()));
            }
            let exprs = val.components();
            no_reserved("expr", &exprs)?;
            // A scalar may be printed several times (each judged); a vector or matrix is
            // printed once, as a tuple or row ("(1/2, 0.7071)") or an array of its components.
            let printed: Vec<Vec<String>> = if matches!(val, defs::Val::Scalar(_)) {
                vec![given]
            } else {
                let items = if given.len() == 1 {
                    printed_tuple(&given[0])
                } else {
                    given
                };
                if items.len() != exprs.len() {
                    return Err((
                        "printed",
                        format!(
                            "{} printed value{} for {} (give one per component, e.g. \"(1/2, 0.7071)\")",
                            items.len(),
                            if items.len() == 1 { "" } else { "s" },
                            val.shape()
                        ),
                    ));
                }
                items.into_iter().map(|p| vec![p]).collect()
            };
            for p in printed.iter().flatten() {
                printed::rational(p).map_err(|e| ("printed", e))?;
            }
            Check::Value {
                names: names(exprs.len())?,
                exprs,
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

/// Refuses a free variable `pi`, `e` or `i` in the resolved formulas of `key`
/// ([`reserved_constant`](exactcheck_exact::expr::reserved_constant)).
fn no_reserved(key: &'static str, exprs: &[Expr]) -> Built<()> {
    match first_reserved(exprs) {
        Some(why) => Err((key, why.to_string())),
        None => Ok(()),
    }
}

/// `where` and `domains`, parsed as `prove --where` parses them.
fn conditions(c: &RawClaim, defs: &RefCell<Defs>) -> Built<Conditions> {
    let mut out = Conditions::default();
    let parse = |text: &str, what: &str| -> Result<Expr, Error> {
        let e = defs
            .borrow_mut()
            .resolve_scalar(text)
            .map_err(|e| Error::Input(format!("{what}: {}", e.message)))?;
        match first_reserved([&e]) {
            Some(why) => Err(Error::Input(format!("{what}: {why}"))),
            None => Ok(e),
        }
    };
    let lists: [(&'static str, &Option<Vec<String>>); 2] =
        [("where", &c.where_), ("domains", &c.domains)];
    for (key, list) in lists {
        let texts = list
            .iter()
            .flatten()
            .enumerate()
            .flat_map(|(i, t)| split_where(t).into_iter().map(move |t| (i, t)));
        for (i, text) in texts {
            let text = &text;
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
                Where::NonZero(a, b) => {
                    if key == "domains" {
                        return Err((
                            key,
                            format!("{what}: {text:?} is a hypothesis, not a domain (put it under where)"),
                        ));
                    }
                    out.nonzero.push((a, b, text.trim().to_string()));
                }
                Where::Domain(d) => {
                    let v = d.name.clone();
                    if d.bounds.is_empty() {
                        return Err((key, format!("{what}: the domain {text:?} is empty")));
                    }
                    if out.domains.iter().any(|w| w.name == v) {
                        return Err((
                            key,
                            format!("{what}: {v} already has a domain (give both bounds in one, e.g. '0 <= {v} <= 1')"),
                        ));
                    }
                    out.domains.push(d);
                }
            }
        }
    }
    Ok(out)
}

/// Decides a claim: its outcome; for an identity with a `corrected` form not proved equal to
/// its `rhs`, why (the claim is then not as expected, whatever its verdict); the typed fields
/// of the engine's report (identities, random instances).
pub fn run(check: &Check, notation: &[(String, String)]) -> Result<Decision, Fault> {
    let mut decided = match check {
        Check::Identity { .. } => identity_claim(check)?,
        Check::Value {
            exprs,
            names,
            printed,
        } => Decision::outcome(values(exprs, names, printed)?),
        Check::Instances { .. } => {
            let (outcome, report) = instances(check)?;
            Decision {
                report,
                ..Decision::outcome(outcome)
            }
        }
        Check::Solve { problem, fields } => Decision::outcome(solve(problem, fields)?),
    };
    if let Some(e) = decided.outcome.erratum.as_mut() {
        e.notation = notation.to_vec();
    }
    Ok(decided)
}

impl Decision {
    /// An outcome alone: no problem, no typed fields.
    fn outcome(outcome: Outcome) -> Self {
        Decision {
            outcome,
            problem: None,
            report: Map::new(),
        }
    }
}

/// A printed number as written when it is a plain decimal (`0.3330`, `-2.5`: [`Expr::decimal`]),
/// else (`1e-3`, `1/3`) the number `q` it denotes.
fn as_printed(text: &str, q: &Rational) -> Expr {
    let t = text.trim();
    if is_decimal_name(t.strip_prefix('-').unwrap_or(t)) {
        Expr::decimal(t)
    } else {
        Expr::number(q.clone())
    }
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

fn to_poly<C: Coefficient>(e: &Expr, vars: &mut Vars, key: &'static str) -> Result<Poly<C>, Fault> {
    e.to_poly::<C>(vars)
        .map_err(|err| Fault::Input(key, err.to_string()))
}
