//! The wording of randomized identity tests (`prove --random`, the random part of a claims
//! file's `instances` claim): one test per component, each modulo its own prime
//! ([`exactcheck_exact::prove::random_identity_test`]); the verdict shown is the first failing
//! component's, else the first undecided one's, else the component with the weakest bound (a
//! false identity has a false component, which passes with at most its own bound).

use super::Verdict;
use exactcheck_exact::expr::library::Shape;
use exactcheck_exact::prove::{RandomDecision, RandomReport, Seed, HOLDS_THRESHOLD_LOG2};
use serde_json::{json, Map, Value};

/// How a front end names its options in the advice of an evidence line.
pub struct RandomOptions {
    /// How to ask for a fresh seed: `run without --seed`, `remove \`seed\``.
    pub fresh_seed: &'static str,
    /// The option of the number of points: `--random`, `random`.
    pub points: &'static str,
    /// The other way to decide, appended to "use more points (...)": ` or exact mode (no
    /// --random)`, or empty.
    pub otherwise: &'static str,
    /// Appended to a failure: how to get an exact counter-example, or empty.
    pub exact_counter_example: &'static str,
}

/// A randomized test worded.
pub struct RandomPhrased {
    /// The verdict.
    pub verdict: Verdict,
    /// The verdict as shown: `holds (reproduced)` for a run with a chosen seed.
    pub verdict_text: &'static str,
    /// The component whose result is shown.
    pub shown: usize,
    /// `evaluation at K random points modulo ...`.
    pub method: String,
    /// The evidence line.
    pub evidence: String,
    /// log2 of the error bound shown, when the verdict has one.
    pub log2_bound: Option<f64>,
}

/// The run of a decision.
pub fn report_of(d: &RandomDecision) -> &RandomReport {
    match d {
        RandomDecision::Holds { report, .. }
        | RandomDecision::Reproduced { report }
        | RandomDecision::Undecided { report, .. }
        | RandomDecision::Fails { report, .. }
        | RandomDecision::Refuted { report, .. }
        | RandomDecision::Unconfirmed { report, .. } => report,
    }
}

/// The verdict of one component as `prove --json` lists it, with its bound.
pub fn component_verdict(d: &RandomDecision) -> (&'static str, Option<f64>) {
    match d {
        RandomDecision::Holds { log2_bound, .. } => ("holds", Some(*log2_bound)),
        RandomDecision::Reproduced { .. } => ("holds (reproduced)", None),
        RandomDecision::Undecided { log2_bound, .. } => ("undecided", Some(*log2_bound)),
        RandomDecision::Fails { .. } | RandomDecision::Refuted { .. } => ("fails", None),
        RandomDecision::Unconfirmed { .. } => ("undecided", None),
    }
}

/// A bound `2^l`, rounded up (so the printed bound is still a bound); `0` for no chance.
fn show(l: f64) -> String {
    if l == f64::NEG_INFINITY {
        "0".to_string()
    } else {
        format!("2^{:.1}", (l * 10.0).ceil() / 10.0)
    }
}

/// What the sides were rewritten with, for the evidence: the constants' field, the angles and
/// the square roots of expressions (` (with c = sqrt(2), c^2 - 2 = 0 in F_p[c]/(c^2 - 2); angle
/// x on its unit circle; sqrt(1 + t^2) as w with w^2 = the radicand, either sign)`), empty for
/// an identity over Q.
fn notes(report: &RandomReport) -> String {
    let mut parts = Vec::new();
    if let Some(k) = &report.constants {
        parts.push(format!(
            "{k}; values in F_p[c]/(m), m the minimal polynomial of c"
        ));
    }
    if !report.angles.is_empty() {
        let many = report.angles.len() > 1;
        parts.push(format!(
            "{} {} on {} unit circle{} (cos^2 + sin^2 = 1){}",
            if many { "angles" } else { "angle" },
            report.angles.join(", "),
            if many { "their" } else { "its" },
            if many { "s" } else { "" },
            if report.tan {
                ", points where the cosine of a tan vanishes skipped"
            } else {
                ""
            }
        ));
    }
    if !report.roots.is_empty() {
        parts.push(format!(
            "{} as w with w^2 = the radicand, either sign",
            report.roots.join(", ")
        ));
    }
    if parts.is_empty() {
        String::new()
    } else {
        format!(" ({})", parts.join("; "))
    }
}

/// The field's part of the bound: `, m of degree 2 with log2 ||m||_1 <= 2`.
fn field_text(report: &RandomReport) -> String {
    match &report.field {
        Some(f) => format!(
            ", m of degree {} with log2 ||m||_1 <= {}",
            f.degree, f.modulus_bits
        ),
        None => String::new(),
    }
}

/// Words the decisions of the components (`labels` names them; empty for a scalar identity)
/// of a test at `trials` points from `seed`.
pub fn phrase_random(
    decisions: &[RandomDecision],
    labels: &[String],
    trials: u32,
    seed: Seed,
    options: &RandomOptions,
) -> RandomPhrased {
    let rank = |d: &RandomDecision| match d {
        RandomDecision::Fails { .. } | RandomDecision::Refuted { .. } => (3, 0.0),
        RandomDecision::Undecided { log2_bound, .. } => (2, *log2_bound),
        RandomDecision::Unconfirmed { .. } => (2, 0.0),
        RandomDecision::Holds { log2_bound, .. } => (1, *log2_bound),
        RandomDecision::Reproduced { .. } => (0, 0.0),
    };
    let shown = (0..decisions.len())
        .max_by(|&a, &b| {
            let (ra, la) = rank(&decisions[a]);
            let (rb, lb) = rank(&decisions[b]);
            // The first of equals: a later component wins only when strictly worse.
            ra.cmp(&rb).then(la.total_cmp(&lb)).then(b.cmp(&a))
        })
        .expect("an identity has at least one component");
    let decision = &decisions[shown];
    let report = report_of(decision);
    let chosen = matches!(seed, Seed::Chosen(_));
    let (prime_text, prefix) = if labels.is_empty() {
        (
            format!("the random prime p = {}", report.prime),
            String::new(),
        )
    } else {
        let primes: Vec<String> = decisions
            .iter()
            .map(|d| report_of(d).prime.to_string())
            .collect();
        let undecided: Vec<&str> = (0..decisions.len())
            .filter(|&k| {
                matches!(
                    decisions[k],
                    RandomDecision::Undecided { .. } | RandomDecision::Unconfirmed { .. }
                )
            })
            .map(|k| labels[k].as_str())
            .collect();
        (
            format!(
                "random primes, one per component ({}; p = {} in {})",
                primes.join(", "),
                report.prime,
                labels[shown]
            ),
            match decision {
                RandomDecision::Fails { .. } | RandomDecision::Refuted { .. } => {
                    format!("in {}: ", labels[shown])
                }
                RandomDecision::Undecided { .. } | RandomDecision::Unconfirmed { .. } => {
                    format!("undecided in {}: ", undecided.join(", "))
                }
                _ => format!("in each of the {} components: ", labels.len()),
            },
        )
    };
    let method = format!(
        "evaluation at {trials} random points modulo {prime_text} (seed {}{}{}{})",
        seed.value(),
        if chosen { ", chosen" } else { "" },
        if report.redrawn > 0 {
            format!(", {} primes dividing a divisor redrawn", report.redrawn)
        } else {
            String::new()
        },
        if report.poles > 0 {
            format!(", {} points where a divisor vanishes skipped", report.poles)
        } else {
            String::new()
        }
    );
    let notes = notes(report);
    let (verdict, verdict_text, log2_bound, evidence) = match decision {
        RandomDecision::Holds {
            bound, log2_bound, ..
        } => (
            Verdict::Holds,
            "holds",
            Some(*log2_bound),
            format!(
                "LHS - RHS vanishes at all {trials} points{notes}; with LHS - RHS = F/D ({bound}{}), a false identity passes with probability <= {} (below the threshold 2^{HOLDS_THRESHOLD_LOG2})",
                field_text(report),
                show(*log2_bound)
            ),
        ),
        RandomDecision::Reproduced { .. } => (
            Verdict::Holds,
            "holds (reproduced)",
            None,
            format!(
                "LHS - RHS vanishes at all {trials} points{notes} modulo the prime drawn from the chosen seed {} and the identity; a chosen seed gives no probability bound (it need not be independent of the identity): {} for a fresh seed and the proved bound",
                seed.value(),
                options.fresh_seed
            ),
        ),
        RandomDecision::Undecided {
            bound, log2_bound, ..
        } => {
            let why = match bound {
                Some(b) => format!(
                    "with LHS - RHS = F/D ({b}{}) the error bound{} is {}, not below the threshold 2^{HOLDS_THRESHOLD_LOG2}",
                    field_text(report),
                    if chosen { " a fresh seed would give" } else { "" },
                    show(*log2_bound)
                ),
                None => "the size and degree bounds of LHS - RHS do not fit in 64 bits, so no error bound can be given".to_string(),
            };
            (
                Verdict::Undecided,
                "undecided",
                Some(*log2_bound),
                format!(
                    "LHS - RHS vanishes at all {trials} points{notes}, but {why}; use more points ({} up to {}){}",
                    options.points,
                    exactcheck_exact::prove::MAX_RANDOM_TRIALS,
                    options.otherwise
                ),
            )
        }
        RandomDecision::Fails { point, value, .. } => (
            Verdict::Fails,
            "fails",
            None,
            format!(
                "LHS - RHS = {value} (mod p) at {}, so it is not zero{}",
                point
                    .iter()
                    .map(|(v, x)| format!("{v} = {x}"))
                    .collect::<Vec<_>>()
                    .join(", "),
                options.exact_counter_example
            ),
        ),
        RandomDecision::Refuted { exact, .. } => (
            Verdict::Fails,
            "fails",
            None,
            format!(
                "{}LHS - RHS = {}, not zero: evaluated exactly after LHS - RHS was non-zero at a random point modulo p{notes}",
                if exact.point.is_empty() {
                    String::new()
                } else {
                    format!("at {}: ", exact.point.join(", "))
                },
                exact.value
            ),
        ),
        RandomDecision::Unconfirmed { point, why, .. } => (
            Verdict::Undecided,
            "undecided",
            None,
            format!(
                "LHS - RHS is non-zero modulo p at {}{notes}, but no exact counter-example confirms it: {why}",
                point
                    .iter()
                    .map(|(v, x)| format!("{v} = {x}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        ),
    };
    RandomPhrased {
        verdict,
        verdict_text,
        shown,
        method,
        evidence: format!("{prefix}{evidence}"),
        log2_bound,
    }
}

/// The typed fields of a randomized test as `prove --random --json` prints them after the
/// verdict, the method and the evidence: the seed, the prime of the shown component, for a
/// vector or matrix identity (`shape`) each component's verdict and prime, and log2 of the
/// error bound (`null` for a bound that is not finite). A claims file's `instances` row with
/// `random` carries them too.
pub fn random_fields(
    phrased: &RandomPhrased,
    decisions: &[RandomDecision],
    shape: Shape,
    seed: Seed,
) -> Map<String, Value> {
    let bound = |l: f64| if l.is_finite() { json!(l) } else { json!(null) };
    let mut obj = Map::new();
    obj.insert("seed".into(), json!(seed.value()));
    obj.insert(
        "prime".into(),
        json!(report_of(&decisions[phrased.shown]).prime),
    );
    if shape != Shape::Scalar {
        obj.insert("shape".into(), json!(shape.to_string()));
        let components: Vec<Value> = decisions
            .iter()
            .enumerate()
            .map(|(k, d)| {
                let (verdict, log2) = component_verdict(d);
                let mut c = json!({"component": shape.component(k), "verdict": verdict,
                    "prime": report_of(d).prime});
                if let Some(l) = log2 {
                    c["log2_error_bound"] = bound(l);
                }
                c
            })
            .collect();
        obj.insert("components".into(), components.into());
    }
    if let RandomDecision::Refuted { exact, .. } = &decisions[phrased.shown] {
        obj.insert("counter_example".into(), json!(exact.point));
        obj.insert("value".into(), json!(exact.value));
    }
    if let Some(l) = phrased.log2_bound {
        obj.insert("log2_error_bound".into(), bound(l));
    }
    obj
}
