//! A sweep run as shards and merged is the single run: same counts, maxima, worst cases (shrunk
//! the same way), medians and bits of error, whatever the order of the shard reports; and the
//! JSON form of a shard report reads back to the same report. A shard that disagrees with itself
//! (an edited count, a summary emptied, a maximum out of its summary) or that measured another
//! float side is refused.

use exactcheck_core::{OrderedField, ZeroDivisor};
use exactcheck_exact::Rational;
use exactcheck_float::{
    check_consistent, merge, run, CaseError, FloatSideError, Formula, LimitStop, Options, Report,
    Shard, Subject, Sweep, UniformBox,
};

/// `(x + y) - x` (cancellation) and `x / (y - x)` (outside the domain where `y == x`).
struct Mixed;

impl Formula for Mixed {
    fn name(&self) -> String {
        "(x + y) - x, x / (y - x)".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        let d = x[1].sub_ref(&x[0]);
        Ok(vec![
            x[0].add_ref(&x[1]).sub_ref(&x[0]),
            x[0].checked_div(&d)?,
        ])
    }
}

fn sweep(samples: usize, shard: Option<Shard>) -> Report {
    let gen = UniformBox::cube(2, -1e3, 1e3).expect("valid box");
    let options = Options {
        worst: 4,
        ..Options::default()
    };
    let sweep = Sweep {
        samples,
        seed: 11,
        shard,
    };
    run(
        &exactcheck_float::Generic::<_, Rational>::new(&Mixed),
        &gen,
        sweep,
        &options,
        &|_| {},
    )
    .expect("runs")
}

#[test]
fn four_shards_merge_into_the_single_run() {
    let samples = 20_000;
    let whole = sweep(samples, None);
    assert!(whole.compared > 0 && whole.max_ulps > 1.0, "{whole}");
    let mut shards: Vec<Report> = (1..=4)
        .map(|index| sweep(samples, Some(Shard { index, count: 4 })))
        .collect();
    assert_eq!(
        shards
            .iter()
            .map(|r| r.end_sample - r.first_sample)
            .sum::<usize>(),
        samples
    );
    // Through JSON, as the CLI's shard files are.
    shards = shards
        .iter()
        .map(|r| serde_json::from_value(r.to_json()).expect("reads back"))
        .collect();
    shards.reverse();
    let merged = merge(&shards).expect("merges");
    assert_eq!(merged, whole);
    assert_eq!(merged.to_string(), whole.to_string());
}

#[test]
fn bad_merges_are_refused() {
    let a = sweep(1000, Some(Shard { index: 1, count: 2 }));
    let b = sweep(1000, Some(Shard { index: 2, count: 2 }));
    let msg = |r: Result<Report, exactcheck_float::MergeError>| r.expect_err("refused").0;
    assert_eq!(
        msg(merge(std::slice::from_ref(&a))),
        "shard(s) missing: 2/2"
    );
    assert_eq!(
        msg(merge(&[a.clone(), a.clone()])),
        "shard 1/2 is given twice"
    );
    let other = sweep(999, Some(Shard { index: 2, count: 2 }));
    assert!(msg(merge(&[a.clone(), other])).contains("samples 999"));
    let whole = sweep(1000, None);
    assert!(msg(merge(&[whole])).contains("not a shard report"));
    assert!(merge(&[b, a]).is_ok());
    assert!(msg(merge(&[])).contains("no shard"));
}

#[test]
fn shard_syntax() {
    assert_eq!("2/4".parse::<Shard>(), Ok(Shard { index: 2, count: 4 }));
    for bad in ["0/4", "5/4", "1", "a/b", "1/0"] {
        assert!(bad.parse::<Shard>().is_err(), "{bad}");
    }
    let s = Shard { index: 3, count: 3 };
    assert_eq!(s.range(10), 6..10);
    assert_eq!(Shard { index: 1, count: 3 }.range(10), 0..3);
}

/// `x * y`, whose float side fails (a zero divisor) where `x < -900`: float failures, infinite
/// errors and 64 bits in the summaries.
struct Failing;

impl Formula for Failing {
    fn name(&self) -> String {
        "x * y, failing below -900".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        Ok(vec![x[0].mul_ref(&x[1])])
    }
    fn eval_f64(&self, x: &[f64]) -> Result<Vec<f64>, ZeroDivisor> {
        if x[0] < -900.0 {
            return Err(ZeroDivisor);
        }
        Ok(vec![x[0] * x[1] * (1.0 + f64::EPSILON)])
    }
}

fn failing_sweep(samples: usize, shard: Option<Shard>) -> Report {
    let gen = UniformBox::cube(2, -1e3, 1e3).expect("valid box");
    let sweep = Sweep {
        samples,
        seed: 5,
        shard,
    };
    run(
        &exactcheck_float::Generic::<_, Rational>::new(&Failing),
        &gen,
        sweep,
        &Options::default(),
        &|_| {},
    )
    .expect("runs")
}

/// What `run` writes passes the check: float failures, and summaries past the exact size that
/// collapse to buckets.
#[test]
fn shards_as_written_are_consistent() {
    let samples = 140_000;
    let shards: Vec<Report> = (1..=2)
        .map(|index| failing_sweep(samples, Some(Shard { index, count: 2 })))
        .collect();
    for s in &shards {
        assert!(s.float_failures > 0 && s.summary.ulps.is_collapsed(), "{s}");
        assert_eq!(check_consistent(s), Ok(()));
    }
    let merged = merge(&shards).expect("merges");
    assert_eq!(merged, failing_sweep(samples, None));
    assert_eq!(check_consistent(&merged), Ok(()));
}

/// The second shard of a 1000-sample sweep, edited by `edit`, merged with the first: the
/// refusal's message.
fn refusal(edit: impl FnOnce(&mut Report)) -> String {
    let a = sweep(1000, Some(Shard { index: 1, count: 2 }));
    let mut b = sweep(1000, Some(Shard { index: 2, count: 2 }));
    assert!(merge(&[a.clone(), b.clone()]).is_ok());
    edit(&mut b);
    let e = merge(&[a, b]).expect_err("a tampered shard is refused").0;
    assert!(!e.contains('\n'), "{e}");
    e
}

#[test]
fn tampered_counts_are_refused() {
    let e = refusal(|b| b.compared = 1_000_000_000_000_000_000);
    assert!(
        e.starts_with("shard 2/2 is inconsistent: compared 1000000000000000000 + "),
        "{e}"
    );
    assert!(e.contains("is not the 500 samples it covers"), "{e}");
    let e = refusal(|b| b.undecided = usize::MAX);
    assert!(e.contains("is not the 500 samples it covers"), "{e}");
    // The outcomes still add up, but the summaries hold one sample fewer than `compared`.
    let e = refusal(|b| {
        b.compared -= 1;
        b.undecided += 1;
    });
    assert!(e.contains("ulps summary holds"), "{e}");
    let e = refusal(|b| b.float_failures = b.compared + 1);
    assert!(e.contains("float failures"), "{e}");
    let e = refusal(|b| b.float_failures += 1);
    assert!(e.contains("fewer infinite errors"), "{e}");
    let e = refusal(|b| b.above[0].count += 1);
    assert!(
        e.contains("samples above 1.0 ulps, but its summary has"),
        "{e}"
    );
}

#[test]
fn emptied_or_edited_summaries_are_refused() {
    let e = refusal(|b| b.summary = Default::default());
    assert!(e.contains("summary holds 0 samples"), "{e}");
    let e = refusal(|b| b.summary.bits.count += 1);
    assert!(e.contains("bits of error summary holds"), "{e}");
    let e = refusal(|b| b.median_ulps *= 2.0);
    assert!(e.contains("median_ulps"), "{e}");
    let e = refusal(|b| b.bits_of_error = 3.0);
    assert!(e.contains("bits_of_error 3.0 is not"), "{e}");
    let e = refusal(|b| b.max_bits = 70.0);
    assert!(e.contains("max_bits 70.0 does not"), "{e}");
}

#[test]
fn maxima_out_of_their_summary_are_refused() {
    let e = refusal(|b| b.max_ulps = 1e308);
    assert!(e.contains("max_ulps 1e308 is not the largest value"), "{e}");
    let e = refusal(|b| b.max_rel = f64::NAN);
    assert!(e.contains("max_rel NaN"), "{e}");
    let e = refusal(|b| b.max_ulps_per_output[0] = 1e308);
    assert!(e.contains("max_ulps_per_output holds 1e308"), "{e}");
}

#[test]
fn missing_or_edited_worst_cases_are_refused() {
    let e = refusal(|b| b.worst.clear());
    assert!(e.contains("0 worst cases, not 4"), "{e}");
    let e = refusal(|b| b.worst.swap(0, 1));
    assert!(e.contains("is not worse than the next"), "{e}");
    let e = refusal(|b| b.worst[1].index = 3);
    assert!(e.contains("is sample 3, outside 500..1000"), "{e}");
    // A case's float output edited: its recorded error no longer follows from its outputs.
    let e = refusal(|b| {
        let y = &mut b.worst[1]
            .original
            .float_outputs
            .as_mut()
            .expect("compared")[0];
        *y = f64::from_bits(y.to_bits() + 1);
    });
    assert!(e.contains("ulps from its exact value, not the"), "{e}");
}

/// The float side of a shard is recorded, and shards of different float sides do not merge.
#[test]
fn shards_of_another_float_side_are_refused() {
    let subject = exactcheck_float::Generic::<_, Rational>::new(&Mixed);
    assert_eq!(subject.float_side(), "built-in (x + y) - x, x / (y - x)");
    let b = sweep(1000, Some(Shard { index: 2, count: 2 }));
    assert_eq!(b.float_side, subject.float_side());
    let e = refusal(|b| b.float_side = "program ./mine".into());
    assert_eq!(
        e,
        "report 2 is of another sweep: float side program ./mine (report 1: built-in (x + y) - x, x / (y - x))"
    );
}

/// `x * y`, whose exact side stops at the limit `limit = value` where `x < 0` (as a loop past
/// its limit would): a stand-in for shards of one sweep run where different limits were met.
struct Stopping {
    limit: &'static str,
    value: u64,
}

impl Subject for Stopping {
    fn name(&self) -> String {
        "x * y".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn float_side(&self) -> String {
        "built-in x * y".into()
    }
    fn exact(&self, x: &[f64]) -> Result<Vec<exactcheck_float::ExactValue>, CaseError> {
        if x[0] < 0.0 {
            return Err(CaseError::LimitExceeded {
                limit: self.limit,
                value: self.value,
            });
        }
        let q = |v: f64| num_rational::BigRational::from_float(v).expect("finite");
        Ok(vec![exactcheck_float::ExactValue::exact(q(x[0]) * q(x[1]))])
    }
    fn float(&self, _index: usize, x: &[f64]) -> Result<Option<Vec<f64>>, FloatSideError> {
        Ok(Some(vec![x[0] * x[1]]))
    }
}

fn stopping_shard(limit: &'static str, value: u64, index: usize) -> Report {
    let gen = UniformBox::cube(2, -1.0, 1.0).expect("valid box");
    let sweep = Sweep {
        samples: 400,
        seed: 3,
        shard: Some(Shard { index, count: 2 }),
    };
    run(
        &Stopping { limit, value },
        &gen,
        sweep,
        &Options::default(),
        &|_| {},
    )
    .expect("runs")
}

/// The limits that stopped samples are a list, one per limit sorted by name, in shard and
/// merged reports alike (JSON: `[{"limit": NAME, "value": N}, ...]`); shards stopped at two values
/// of one limit do not merge.
#[test]
fn shards_stopped_by_different_limits_merge_into_the_list_of_both() {
    let a = stopping_shard("loop-value-bits", 64, 1);
    let b = stopping_shard("loop-iterations", 300, 2);
    let stop = |limit: &str, value| LimitStop {
        limit: limit.to_string(),
        value,
    };
    assert!(a.limit_stops > 0 && a.compared > 0, "{a}");
    assert_eq!(a.limit_stop, vec![stop("loop-value-bits", 64)]);
    let json = serde_json::to_value(&a).expect("JSON");
    assert_eq!(
        json["limit_stop"],
        serde_json::json!([{"limit": "loop-value-bits", "value": 64}])
    );
    let back: Report = serde_json::from_value(json).expect("reads back");
    assert_eq!(back, a);
    let merged = merge(&[b.clone(), a.clone()]).expect("merges");
    assert_eq!(merged.limit_stops, a.limit_stops + b.limit_stops);
    assert_eq!(
        merged.limit_stop,
        vec![stop("loop-iterations", 300), stop("loop-value-bits", 64)]
    );
    assert_eq!(check_consistent(&merged), Ok(()));
    assert_eq!(
        serde_json::to_value(&merged).expect("JSON")["limit_stop"],
        serde_json::json!([
            {"limit": "loop-iterations", "value": 300},
            {"limit": "loop-value-bits", "value": 64}
        ])
    );
    let text = merged.to_string();
    assert!(
        text.contains(&format!(
            ", {} stopped by the limits loop-iterations = 300, loop-value-bits = 64\n",
            merged.limit_stops
        )),
        "{text}"
    );
    assert!(a
        .to_string()
        .contains("stopped by the limit loop-value-bits = 64\n"));

    // One limit at two values: refused, the values named.
    let c = stopping_shard("loop-iterations", 10_000, 1);
    let e = merge(&[c, b.clone()])
        .expect_err("two values of one limit")
        .0;
    assert_eq!(
        e,
        "shards stopped at different values of the limit loop-iterations: 10000 and 300 (run every shard with the same --limit)"
    );
    // A shard whose stops and their limits disagree is inconsistent.
    let mut d = a.clone();
    d.limit_stop.clear();
    assert!(check_consistent(&d)
        .expect_err("stops without a limit")
        .contains("limit_stop lists 0 limits"));
    let mut d = a;
    d.limit_stop.push(stop("loop-iterations", 300));
    assert!(check_consistent(&d)
        .expect_err("unsorted")
        .contains("are not distinct limits sorted by name"));
}
