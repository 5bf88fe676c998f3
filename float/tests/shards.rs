//! A sweep run as shards and merged is the single run: same counts, maxima, worst cases (shrunk
//! the same way), medians and bits of error, whatever the order of the shard reports; and the
//! JSON form of a shard report reads back to the same report.

use exactcheck_core::{OrderedField, ZeroDivisor};
use exactcheck_exact::Rational;
use exactcheck_float::{merge, run, Formula, Options, Report, Shard, Sweep, UniformBox};

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
