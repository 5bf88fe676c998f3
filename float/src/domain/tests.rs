//! Tests of the sampling domains: exact bounds, the ordinal indices, binary32 ranges and the
//! domain text.
use super::text::*;
use super::values::*;
use super::*;
use crate::convert::{binary_exponent, f64_to_rational};
use exactcheck_exact::Rational;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).expect("nonzero denominator")
}

fn names(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

fn lowest_double(b: &Bound) -> Option<f64> {
    lowest_value(b, Format::Binary64)
}

fn highest_double(b: &Bound) -> Option<f64> {
    highest_value(b, Format::Binary64)
}

#[test]
fn binary32_domains_sample_binary32_values_inside_the_bounds() {
    let names = names(&["x", "y"]);
    let d = SampleDomain::named(
        vec![iv(Bound::Open(q(1, 3)), cl(2)), iv(cl(0), Bound::Unbounded)],
        &names,
    )
    .and_then(|d| d.with_format(Format::Binary32))
    .expect("non-empty");
    // 1/3 is excluded: the lowest binary32 value above it.
    let third = f64::from(1.0f32 / 3.0);
    let lo = if third > 1.0 / 3.0 {
        third
    } else {
        f64::from((1.0f32 / 3.0).next_up())
    };
    assert_eq!(d.draws[0], Draw::Uniform { lo, hi: 2.0 });
    assert_eq!(
        d.draws[1],
        Draw::Ordinal {
            lo: 0,
            hi: i64::from(f32::MAX.to_bits())
        }
    );
    for sampling in [Sampling::Mixed, Sampling::Floats] {
        let d = d.clone().with_sampling(sampling).expect("valid");
        let mut rng = Rng::new(3);
        for _ in 0..2000 {
            let s = d.sample(&mut rng);
            assert!(d.contains(&s), "{s:?}");
            for &v in &s {
                assert_eq!(f64::from(v as f32), v);
            }
            assert!(lo <= s[0] && s[0] <= 2.0 && s[1] >= 0.0);
        }
    }
    // A double that is not a binary32 value is outside; so is a range without one.
    assert!(!d.contains(&[0.1, 1.0]));
    assert!(d.contains(&[f64::from(0.5f32), 1.0]));
    // From 1 (closed or open) to 1 + 2^-40: only 1 itself is a binary32 value.
    let near_one = q(1, 1)
        + Rational::from(num_rational::BigRational::new(
            1.into(),
            (1u64 << 40).into(),
        ));
    let binary32_domain = |lo: Bound, hi: Bound| {
        SampleDomain::named(vec![iv(lo, hi)], &names[..1])
            .and_then(|d| d.with_format(Format::Binary32))
    };
    let empty = binary32_domain(cl(1), Bound::Closed(near_one.clone()));
    assert!(empty.is_ok(), "1 itself is a binary32 value");
    let none = binary32_domain(Bound::Open(q(1, 1)), Bound::Open(near_one));
    assert_eq!(
        none.map(|_| ()).unwrap_err().0,
        "input 0 (x) has no finite binary32 value in (1, 1.0000000000009095)"
    );
    // Uniform over the binary32 values: each binade of [1, 2^20] equally likely.
    let d = SampleDomain::named(vec![iv(cl(1), cl(1 << 20))], &names[..1])
        .and_then(|d| d.with_format(Format::Binary32))
        .and_then(|d| d.with_sampling(Sampling::Floats))
        .expect("valid");
    let mut rng = Rng::new(5);
    let below = (0..10_000)
        .filter(|_| d.sample(&mut rng)[0] < 1024.0)
        .count();
    assert!((below as f64 / 10_000.0 - 0.5).abs() < 0.03, "{below}");
    assert_eq!(
        d.describe(),
        "x in [1, 1.048576e6] (uniform over the binary32 values)"
    );
}

fn iv(lo: Bound, hi: Bound) -> Range {
    Range { lo, hi }
}

fn cl(n: i64) -> Bound {
    Bound::Closed(Rational::from_integer(n))
}

#[test]
fn ordinals_are_consecutive_and_invertible() {
    for x in [
        0.0,
        5e-324,
        1.0,
        f64::MAX,
        -5e-324,
        -1.0,
        -f64::MAX,
        1.5e-310,
    ] {
        assert_eq!(from_ordinal(ordinal(x)), x);
    }
    assert_eq!(ordinal(-0.0), 0);
    assert_eq!(ordinal(5e-324), 1);
    assert_eq!(ordinal(-5e-324), -1);
    assert_eq!(from_ordinal(ordinal(1.0) + 1), 1.0 + f64::EPSILON);
}

#[test]
fn bounds_round_inward_exactly() {
    let third = q(1, 3);
    let lo = lowest_double(&Bound::Closed(third.clone())).expect("a double");
    let hi = highest_double(&Bound::Closed(third.clone())).expect("a double");
    assert!(exact(lo) > third && exact(hi) < third);
    assert_eq!(from_ordinal(ordinal(hi) + 1), lo);
    assert_eq!(lowest_double(&cl(1)), Some(1.0));
    assert_eq!(
        lowest_double(&Bound::Open(Rational::ONE)),
        Some(1.0 + f64::EPSILON)
    );
    assert_eq!(highest_double(&Bound::Open(Rational::ZERO)), Some(-5e-324));
    assert_eq!(lowest_double(&Bound::Open(Rational::ZERO)), Some(5e-324));
    let huge: Rational = "10^400".parse().expect("a number");
    assert_eq!(lowest_double(&Bound::Closed(huge.clone())), None);
    assert_eq!(highest_double(&Bound::Closed(huge.clone())), Some(f64::MAX));
    assert_eq!(lowest_double(&Bound::Closed(-huge)), Some(-f64::MAX));
    assert_eq!(
        lowest_double(&Bound::Closed(Rational::from(
            f64_to_rational(f64::MAX).expect("finite")
        ))),
        Some(f64::MAX)
    );
    assert_eq!(
        lowest_double(&Bound::Open(Rational::from(
            f64_to_rational(f64::MAX).expect("finite")
        ))),
        None
    );
}

#[test]
fn samples_stay_inside_their_bounds() {
    let d = SampleDomain::new(vec![
        iv(Bound::Closed(q(1, 3)), Bound::Closed(q(2, 3))),
        iv(Bound::Open(Rational::ZERO), Bound::Unbounded),
        iv(Bound::Unbounded, Bound::Open(q(-1, 10))),
        iv(Bound::Unbounded, Bound::Unbounded),
        iv(cl(2), cl(2)),
        iv(Bound::Open(Rational::ZERO), Bound::Open(q(1, 1_000_000))),
    ])
    .expect("non-empty");
    let mut rng = Rng::new(5);
    for _ in 0..20_000 {
        let s = d.sample(&mut rng);
        assert_eq!(s.len(), 6);
        assert!(s.iter().all(|v| v.is_finite()));
        assert!(exact(s[0]) >= q(1, 3) && exact(s[0]) <= q(2, 3), "{}", s[0]);
        assert!(s[1] > 0.0);
        assert!(exact(s[2]) < q(-1, 10), "{}", s[2]);
        assert_eq!(s[4], 2.0);
        assert!(s[5] > 0.0 && exact(s[5]) < q(1, 1_000_000));
    }
}

#[test]
fn one_sided_bounds_sample_every_binade_alike() {
    let d = SampleDomain::new(vec![iv(cl(0), Bound::Unbounded)]).expect("non-empty");
    let mut rng = Rng::new(9);
    let mut exps: Vec<i32> = (0..4001)
        .map(|_| {
            let x = d.sample(&mut rng)[0];
            assert!(x >= 0.0);
            binary_exponent(x).unwrap_or(-1075)
        })
        .collect();
    exps.sort_unstable();
    let median = exps[exps.len() / 2];
    // Uniform over the doubles in [0, MAX]: the exponents are uniform over the 2046 normal
    // binades -1022..=1023 (the subnormals are one binade's worth), so the median is near
    // 0 and the deciles near ±818; uniform on the reals would put nearly every sample at
    // exponent 1020 or more.
    assert!((-60..=60).contains(&median), "median exponent {median}");
    let (d1, d9) = (exps[exps.len() / 10], exps[exps.len() * 9 / 10]);
    assert!(
        (-900..-700).contains(&d1) && (700..900).contains(&d9),
        "{d1} {d9}"
    );
    // Both signs when unbounded.
    let all = SampleDomain::new(vec![Range::UNBOUNDED]).expect("non-empty");
    let neg = (0..1000).filter(|_| all.sample(&mut rng)[0] < 0.0).count();
    assert!((400..600).contains(&neg), "{neg}");
}

#[test]
fn bounded_intervals_sample_uniformly_on_the_reals() {
    let d = SampleDomain::new(vec![iv(
        cl(1),
        Bound::Closed("1e15".parse().expect("number")),
    )])
    .expect("non-empty");
    let mut rng = Rng::new(3);
    let big = (0..1000).filter(|_| d.sample(&mut rng)[0] > 1e14).count();
    assert!(big > 850, "{big}");
}

#[test]
fn empty_ranges_are_errors_naming_the_coordinate() {
    let e = SampleDomain::new(vec![
        Range::UNBOUNDED,
        iv(Bound::Closed(q(1, 3)), Bound::Closed(q(1, 3))),
    ])
    .expect_err("1/3 is not a double");
    assert!(e.0.contains("input 1 (x1)"), "{e}");
    let e = SampleDomain::named(
        vec![Range::UNBOUNDED, iv(cl(3), cl(2))],
        &names(&["x", "y"]),
    )
    .expect_err("3 > 2");
    assert!(
        e.0.contains("input 1 (y) has no finite double in [3, 2]"),
        "{e}"
    );
    assert!(SampleDomain::named(vec![Range::UNBOUNDED], &names(&["x", "y"])).is_err());
    assert!(SampleDomain::new(vec![iv(
        Bound::Open(Rational::ZERO),
        Bound::Open(Rational::ZERO)
    )])
    .is_err());
    assert!(SampleDomain::new(vec![iv(cl(2), cl(1))]).is_err());
    assert!(SampleDomain::new(vec![iv(
        Bound::Closed("10^400".parse().expect("n")),
        Bound::Unbounded
    )])
    .is_err());
    let d = SampleDomain::new(vec![Range::UNBOUNDED]).expect("non-empty");
    assert!(d.with_names(&names(&["a", "b"])).is_err());
}

#[test]
fn describe_is_readable() {
    let d = SampleDomain::new(vec![
        iv(cl(1), Bound::Closed("1e15".parse().expect("number"))),
        iv(cl(0), Bound::Unbounded),
        iv(Bound::Open(q(1, 3)), Bound::Closed(q(1, 2))),
        iv(Bound::Unbounded, Bound::Open(Rational::ONE)),
        Range::UNBOUNDED,
    ])
    .expect("non-empty")
    .with_names(&names(&["x", "y", "z", "w", "v"]))
    .expect("five names");
    assert_eq!(
        d.describe(),
        "x in [1, 1e15] (uniform), y in doubles >= 0, z in (1/3, 0.5] (uniform), \
         w in doubles < 1, v in all finite doubles"
    );
}

#[test]
fn parse_domain_reads_every_form() {
    let vars = names(&["x", "y", "z", "w", "u", "v"]);
    let d = parse_domain(
        "x in [-1, 1], y in [0, 1e15], z in (0, inf), w >= 1/3, w < 2^60, u in (-inf, -2^60]",
        &vars,
    )
    .expect("valid");
    let p2_60 = Rational::from_integer(1 << 60);
    assert_eq!(
        d,
        vec![
            iv(cl(-1), cl(1)),
            iv(cl(0), Bound::Closed("1e15".parse().expect("n"))),
            iv(Bound::Open(Rational::ZERO), Bound::Unbounded),
            iv(Bound::Closed(q(1, 3)), Bound::Open(p2_60.clone())),
            iv(Bound::Unbounded, Bound::Closed(-p2_60)),
            Range::UNBOUNDED,
        ]
    );
    assert_eq!(
        parse_domain("", &vars).expect("empty"),
        vec![Range::UNBOUNDED; 6]
    );
    assert_eq!(
        parse_domain(" x in [0.1 , 1/2) ", &vars).expect("valid")[0],
        iv(Bound::Closed(q(1, 10)), Bound::Open(q(1, 2)))
    );
}

#[test]
fn parse_domain_errors_name_the_part() {
    let vars = names(&["x", "y"]);
    let cases = [
        ("q in [0, 1]", "\"q in [0, 1]\": unknown variable `q`"),
        (
            "x in [0, 1], x in [2, 3]",
            "\"x in [2, 3]\": `x` is bounded twice",
        ),
        ("x >= 0, x > 1", "\"x > 1\": `x` has two lower bounds"),
        ("x in [0, 1", "\"x in [0, 1\": expected the interval to end"),
        ("x in 0, 1]", "expected `[` or `(` after `in`"),
        ("x in [0 1]", "expected two bounds"),
        ("x in [a, 1]", "`a` is not a number"),
        ("x in [2, 1]", "the interval of `x` is empty"),
        ("x in [1, 1)", "the interval of `x` is empty"),
        ("x in [inf, 1]", "the lower bound cannot be +inf"),
        ("x in [0, -inf]", "the upper bound cannot be -inf"),
        ("x = 3", "expected `in [a, b]` or a comparison"),
        ("x >= inf", "a one-sided bound must be a finite number"),
        ("x in [0, 1],, y >= 0", "an empty part between commas"),
        ("[0, 1]", "expected a variable name"),
    ];
    for (text, want) in cases {
        let e = parse_domain(text, &vars).expect_err(text);
        assert!(e.contains(want), "{text}: {e}");
        assert!(!e.contains('\n'));
    }
}

#[test]
fn sampling_floats_or_reals_applies_to_every_coordinate() {
    let names = names(&["x", "y"]);
    let base = || {
        SampleDomain::named(
            vec![iv(cl(1), cl(1 << 20)), iv(cl(0), Bound::Unbounded)],
            &names,
        )
        .expect("non-empty")
    };
    let below_2_10 = |d: &SampleDomain| {
        let mut rng = Rng::new(9);
        let n = 20_000;
        let k = (0..n)
            .filter(|_| {
                let s = d.sample(&mut rng);
                assert!(d.contains(&s), "{s:?}");
                s[0] < 1024.0
            })
            .count();
        k as f64 / n as f64
    };
    // Over the doubles each binade of [1, 2^20] is as likely: half the samples below 2^10;
    // on the reals about 2^-10 of them.
    let floats = base().with_sampling(Sampling::Floats).expect("valid");
    assert!((below_2_10(&floats) - 0.5).abs() < 0.02);
    assert!(below_2_10(&base()) < 0.01);
    assert_eq!(
        floats.describe(),
        "x in [1, 1.048576e6] (uniform over the doubles), y in doubles >= 0"
    );
    assert_eq!(
        base().with_sampling(Sampling::Mixed).expect("valid"),
        base()
    );
    let e = base()
        .with_sampling(Sampling::Reals)
        .expect_err("y has no upper bound");
    assert!(e.to_string().contains("input 1 (y)"), "{e}");
    let reals = SampleDomain::named(vec![iv(cl(1), cl(2)), iv(cl(-3), cl(3))], &names)
        .and_then(|d| d.with_sampling(Sampling::Reals))
        .expect("both bounded");
    assert_eq!(
        reals.describe(),
        "x in [1, 2] (uniform), y in [-3, 3] (uniform)"
    );
}

/// A domain whose `x` is a binary32 argument and `y` a binary64 one, of a program computing in
/// `base`, drawn by `sampling`.
fn mixed_formats(base: Format, sampling: Sampling, bounded: bool) -> SampleDomain {
    let x = if bounded {
        iv(Bound::Open(q(1, 3)), cl(1000))
    } else {
        iv(Bound::Unbounded, Bound::Unbounded)
    };
    SampleDomain::named(vec![x, iv(cl(-2), cl(5))], &names(&["x", "y"]))
        .and_then(|d| d.with_formats(base, &[Format::Binary32, Format::Binary64]))
        .and_then(|d| d.with_sampling(sampling))
        .expect("non-empty")
}

#[test]
fn inputs_of_their_own_format_are_drawn_and_described_as_such() {
    let d = mixed_formats(Format::Binary64, Sampling::Mixed, true);
    assert_eq!(
        d.describe(),
        "x in (1/3, 1000] (uniform, rounded to binary32), y in [-2, 5] (uniform)"
    );
    // Some y is not a binary32 value: only x is rounded.
    let mut rng = Rng::new(3);
    let samples: Vec<Vec<f64>> = (0..200).map(|_| d.sample(&mut rng)).collect();
    assert!(samples.iter().any(|s| !Format::Binary32.holds(s[1])));
    // Shrinking stays among the binary32 values of x.
    assert!(d.contains(&[1.5, 0.1]));
    assert!(!d.contains(&[0.1, 1.5]));
    let d = mixed_formats(Format::Binary32, Sampling::Floats, false);
    assert_eq!(
        d.describe(),
        "x in all finite binary32 values, y in [-2, 5] (uniform over the doubles)"
    );
    let d = mixed_formats(Format::Binary32, Sampling::Reals, true);
    assert_eq!(
        d.describe(),
        "x in (1/3, 1000] (uniform, rounded to binary32), y in [-2, 5] (uniform, binary64)"
    );
    let e = SampleDomain::named(vec![iv(cl(0), cl(1))], &names(&["x"]))
        .and_then(|d| d.with_formats(Format::Binary64, &[]))
        .expect_err("one format per input");
    assert!(
        e.to_string().contains("0 formats for a domain of 1 inputs"),
        "{e}"
    );
}

proptest::proptest! {
    /// Every sampled value of a binary32 input is a binary32 value inside its bounds, whatever
    /// the sampling rule and the other inputs' format.
    #[test]
    fn a_binary32_input_samples_binary32_values(
        seed in 0u64..u64::MAX,
        base_is_32 in proptest::bool::ANY,
        rule in 0usize..3,
        bounded in proptest::bool::ANY,
    ) {
        let base = if base_is_32 { Format::Binary32 } else { Format::Binary64 };
        let sampling = [Sampling::Mixed, Sampling::Floats, Sampling::Reals][rule];
        let bounded = bounded || sampling == Sampling::Reals;
        let d = mixed_formats(base, sampling, bounded);
        let mut rng = Rng::new(seed);
        for _ in 0..64 {
            let s = d.sample(&mut rng);
            proptest::prop_assert!(Format::Binary32.holds(s[0]) && s[0].is_finite(), "{s:?}");
            proptest::prop_assert!(!bounded || (s[0] > 1.0 / 3.0 && s[0] <= 1000.0), "{s:?}");
            proptest::prop_assert!((-2.0..=5.0).contains(&s[1]), "{s:?}");
            proptest::prop_assert!(d.contains(&s), "{s:?}");
        }
    }
}
