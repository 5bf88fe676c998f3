//! The proof engine's verdicts: randomized identity testing modulo a random prime (sound for
//! coefficients and exponents that defeat a fixed prime), inconsistent relations, real
//! counter-examples on relations, and domains.

use exactcheck_core::{Ring, Rng};
use exactcheck_exact::expr::{parse_expr, parse_poly};
use exactcheck_exact::modp::{is_prime_u64, ModP, PrimeField};
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::prove::{
    decide, decide_in, random_identity_test, DecideError, Decision, Hypothesis, RandomDecision,
    Seed, VarDomain, MAX_RANDOM_TRIALS,
};
use exactcheck_exact::{Radical, Rational};

const M61: &str = "2305843009213693951"; // 2^61 - 1, the old fixed modulus

fn random(lhs: &str, rhs: &str, trials: u32, seed: u64) -> RandomDecision {
    let (l, r) = (parse_expr(lhs).unwrap(), parse_expr(rhs).unwrap());
    let mut names = Vec::new();
    for n in ["x", "y", "c", "s"] {
        if lhs.contains(n) || rhs.contains(n) {
            names.push(n.to_string());
        }
    }
    random_identity_test(&l, &r, &names, &[], trials, Seed::Fresh(seed)).unwrap()
}

#[test]
fn the_old_fixed_prime_was_blind_to_its_multiples() {
    // The old wrong answer: modulo 2^61 - 1 the coefficient vanishes, so every point gave zero
    // and `prove '2305843009213693951*x' 0 --random 5` said "holds".
    let m = ModP::from_rational(&M61.parse::<Rational>().unwrap()).unwrap();
    let mut rng = Rng::new(1);
    assert!((m * ModP::random(&mut rng)).is_zero());
    // x^p = x modulo p (Fermat): the old test said `x^(2^61-1) = x` "holds".
    let x = ModP::random(&mut rng);
    assert_eq!(x.pow_u64(ModP::from_i64(-1).value() + 1), x);
    // With a random prime from [2^62, 2^63) every one of them fails, for many seeds.
    for seed in 0..20 {
        for (lhs, rhs) in [
            (format!("{M61}*x"), "0".to_string()),
            (format!("x + {M61}"), "x".to_string()),
            (format!("x^{M61}"), "x".to_string()),
        ] {
            assert!(
                matches!(random(&lhs, &rhs, 20, seed), RandomDecision::Fails { .. }),
                "{lhs} = {rhs}, seed {seed}"
            );
        }
    }
}

#[test]
fn products_of_primes_of_the_sampled_range_fail() {
    // Four primes just above 2^62 (the range the prime is drawn from), and three 61-bit primes.
    let big = "4611686018427388039*4611686018427388073*4611686018427388081*4611686018427388091*x";
    let small = "2305843009213693951*2305843009213693921*2305843009213693907*x";
    for p in [
        4611686018427388039u64,
        4611686018427388073,
        4611686018427388081,
        4611686018427388091,
        2305843009213693921,
        2305843009213693907,
    ] {
        assert!(is_prime_u64(p));
    }
    for seed in 0..20 {
        assert!(matches!(
            random(big, "0", 3, seed),
            RandomDecision::Fails { .. }
        ));
        assert!(matches!(
            random(small, "0", 3, seed),
            RandomDecision::Fails { .. }
        ));
    }
}

#[test]
fn true_identities_hold_with_a_bound_below_the_threshold() {
    match random(
        "(x + y)^5",
        "x^5 + 5 x^4 y + 10 x^3 y^2 + 10 x^2 y^3 + 5 x y^4 + y^5",
        4,
        9,
    ) {
        RandomDecision::Holds {
            log2_bound, report, ..
        } => {
            assert!(log2_bound < -30.0);
            assert!(report.prime >= 1 << 62 && is_prime_u64(report.prime));
            assert_eq!(report.seed, Seed::Fresh(9));
        }
        other => panic!("{other:?}"),
    }
    // Same seed, same prime and verdict.
    assert_eq!(
        random("x/3", "x*(1/3)", 2, 5),
        random("x/3", "x*(1/3)", 2, 5)
    );
}

#[test]
fn huge_degrees_and_overflow_are_undecided_not_holds() {
    // Zero everywhere, but the degree bound 2^61 makes each point worth only one bit: 10 points
    // give 2^-10, above the threshold.
    let l = format!("0*x^{M61}");
    match random(&l, "0", 10, 3) {
        RandomDecision::Undecided { log2_bound, .. } => assert!(log2_bound > -30.0),
        other => panic!("{other:?}"),
    }
    // Bounds beyond 64 bits: undecided without a bound, never wrapped into a small one.
    let l = "0*((x^4294967296)^4294967296)^4294967296";
    assert!(matches!(
        random(l, "0", 3, 3),
        RandomDecision::Undecided { bound: None, .. }
    ));
}

#[test]
fn random_mode_refuses_what_it_cannot_bound() {
    let e = |t: &str| parse_expr(t).unwrap();
    let vars = ["x".to_string()];
    let one = Seed::Fresh(1);
    // A square root of an expression is a root w with w^2 = R: a point where the sides differ
    // does not refute (the roots take either sign). One whose radicand has a root of a constant
    // is refused; constants have a bound, but not undefined ones.
    assert!(matches!(
        random_identity_test(&e("sqrt(x) x"), &e("0"), &vars, &[], 3, one),
        Ok(RandomDecision::Unconfirmed { .. })
    ));
    assert!(random_identity_test(&e("sqrt(x + sqrt(2))"), &e("0"), &vars, &[], 3, one).is_err());
    assert!(random_identity_test(&e("tan(pi/2) x"), &e("0"), &vars, &[], 3, one).is_err());
    assert!(random_identity_test(&e("sqrt(2) x"), &e("0"), &vars, &[], 3, one).is_ok());
    // A divisor that is zero in the constants' field is not a unit modulo any prime.
    assert!(random_identity_test(&e("x/(sqrt(2)^2 - 2)"), &e("0"), &vars, &[], 3, one).is_err());
    assert!(random_identity_test(&e("x"), &e("x"), &vars, &[], 0, one).is_err());
    assert!(
        random_identity_test(&e("x"), &e("x"), &vars, &[], MAX_RANDOM_TRIALS + 1, one).is_err()
    );
    // A divisor that is zero is an error (redrawing the prime cannot help), not a verdict.
    assert!(random_identity_test(&e("x/(2-2)"), &e("0"), &vars, &[], 3, one).is_err());
}

#[test]
fn a_chosen_seed_reveals_no_prime_of_another_identity_and_gives_no_bound() {
    // With a chosen seed, `x = 0` fails at a point and prints its prime p. The identity
    // `p x = 0` under the same seed is evaluated modulo another prime (the prime depends on the
    // identity too), so it fails as well; with the prime of the seed alone it passed every
    // point and was reported `holds` with a bound of 2^-55.9.
    let e = |t: &str| parse_expr(t).unwrap();
    let vars = ["x".to_string()];
    let seed = Seed::Chosen(7);
    let first = match random_identity_test(&e("x"), &e("0"), &vars, &[], 5, seed).unwrap() {
        RandomDecision::Fails { report, .. } => report.prime,
        other => panic!("{other:?}"),
    };
    let crafted = e(&format!("{first}*x"));
    match random_identity_test(&crafted, &e("0"), &vars, &[], 5, seed).unwrap() {
        RandomDecision::Fails { report, .. } => {
            assert_ne!(report.prime, first);
            assert_eq!(report.seed, seed);
        }
        other => panic!("{other:?}"),
    }
    // A true identity under a chosen seed is reproduced, never `Holds` with a bound; the same
    // seed drawn fresh gives the bound, with the same prime (the run is reproduced exactly).
    let (l, r) = (e("(x + 1)^2"), e("x^2 + 2 x + 1"));
    let chosen = random_identity_test(&l, &r, &vars, &[], 5, seed).unwrap();
    let fresh = random_identity_test(&l, &r, &vars, &[], 5, Seed::Fresh(7)).unwrap();
    match (chosen, fresh) {
        (RandomDecision::Reproduced { report: a }, RandomDecision::Holds { report: b, .. }) => {
            assert_eq!(a.prime, b.prime)
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn random_primes_are_uniformish_and_prime() {
    let mut rng = Rng::new(77);
    let mut seen = std::collections::HashSet::new();
    for _ in 0..50 {
        let f = PrimeField::random_62(&mut rng);
        let p = f.modulus();
        assert!((1u64 << 62..1u64 << 63).contains(&p) && is_prime_u64(p));
        seen.insert(p);
    }
    assert_eq!(seen.len(), 50);
}

fn polys(texts: &[&str], vars: &mut Vars) -> Vec<Poly<Rational>> {
    texts.iter().map(|t| parse_poly(t, vars).unwrap()).collect()
}

#[test]
fn inconsistent_relations_are_an_error_not_proved() {
    // The old wrong answer: `prove x 0 --where '1 = 2'` said "proved" (Groebner basis {1}).
    let mut vars = Vars::new();
    let x = parse_poly::<Rational>("x", &mut vars).unwrap();
    let one_is_two = polys(&["1 - 2"], &mut vars);
    assert_eq!(
        decide(&x, &one_is_two, 1).unwrap_err(),
        DecideError::Inconsistent
    );
    let two_values = polys(&["x - 1", "x - 2"], &mut vars);
    assert_eq!(
        decide(&x, &two_values, 1).unwrap_err(),
        DecideError::Inconsistent
    );
}

fn check_point(
    residual: &Poly<Rational>,
    relations: &[Poly<Rational>],
    d: &Decision<Rational>,
) -> Vec<Radical> {
    let Decision::Fails { point, value, .. } = d else {
        panic!("expected fails, got {d:?}")
    };
    let values: Vec<Radical> = point.iter().map(|(_, x)| x.clone()).collect();
    for r in relations {
        assert!(r.eval(&values, |c| Radical::from(c)).is_zero());
    }
    assert_eq!(residual.eval(&values, |c| Radical::from(c)), *value);
    assert!(!value.is_zero());
    values
}

#[test]
fn non_zero_normal_forms_fail_at_a_real_point_of_the_relations() {
    // The old answers: `undecided` for both.
    let mut vars = Vars::new();
    let res = parse_poly::<Rational>("c^2 + s^2 - 1", &mut vars).unwrap();
    let rels = polys(&["c^2 + s^2 - 2"], &mut vars);
    let d = decide(&res, &rels, vars.len()).unwrap();
    check_point(&res, &rels, &d);

    let mut vars = Vars::new();
    let res = parse_poly::<Rational>("x - 1", &mut vars).unwrap();
    let rels = polys(&["x - 2"], &mut vars);
    let d = decide(&res, &rels, vars.len()).unwrap();
    assert_eq!(check_point(&res, &rels, &d), vec![Radical::from(2)]);

    // An irrational point: x^2 = 2, x y = 1, residual y - 1.
    let mut vars = Vars::new();
    let res = parse_poly::<Rational>("y - 1", &mut vars).unwrap();
    let rels = polys(&["x^2 - 2", "x*y - 1"], &mut vars);
    let d = decide(&res, &rels, vars.len()).unwrap();
    let pt = check_point(&res, &rels, &d);
    assert!(!pt[1].is_rational());

    // x^2 + y^2 = 0 has only the real point 0, where x vanishes: undecided, never fails.
    let mut vars = Vars::new();
    let res = parse_poly::<Rational>("x", &mut vars).unwrap();
    let rels = polys(&["x^2 + y^2"], &mut vars);
    assert!(matches!(
        decide(&res, &rels, vars.len()).unwrap(),
        Decision::Undecided { .. }
    ));
}

#[test]
fn counter_examples_stay_in_the_domains() {
    let positive = VarDomain {
        lower: Some((Rational::ZERO, true)),
        upper: None,
        integer: false,
    };
    let half_up = VarDomain {
        lower: Some((Rational::new(1, 2).unwrap(), false)),
        upper: None,
        integer: false,
    };
    let mut vars = Vars::new();
    let res = parse_poly::<Rational>("r + R", &mut vars).unwrap();
    for _ in 0..3 {
        let d = decide_in(&res, &[], &[(0, positive.clone()), (1, half_up.clone())], 2).unwrap();
        let pt = check_point(&res, &[], &d);
        assert!(
            positive.contains(&pt[0]) && half_up.contains(&pt[1]),
            "{pt:?}"
        );
    }
    // On the unit circle with c > 1/2 the residual c - 1 is non-zero: the point obeys both.
    let mut vars = Vars::new();
    let res = parse_poly::<Rational>("c - 1", &mut vars).unwrap();
    let rels = polys(&["c^2 + s^2 - 1"], &mut vars);
    let c_dom = VarDomain {
        lower: Some((Rational::new(1, 2).unwrap(), true)),
        upper: Some((Rational::ONE, true)),
        integer: false,
    };
    let d = decide_in(&res, &rels, &[(0, c_dom.clone())], 2).unwrap();
    let pt = check_point(&res, &rels, &d);
    assert!(c_dom.contains(&pt[0]));
    // x^2 = 4 with x < 0: the root -2, not 2.
    let mut vars = Vars::new();
    let res = parse_poly::<Rational>("x - 2", &mut vars).unwrap();
    let rels = polys(&["x^2 - 4"], &mut vars);
    let neg = VarDomain {
        lower: None,
        upper: Some((Rational::ZERO, true)),
        integer: false,
    };
    let d = decide_in(&res, &rels, &[(0, neg)], 1).unwrap();
    assert_eq!(check_point(&res, &rels, &d), vec![Radical::from(-2)]);
    // x^2 = 4 with x > 3 has no point. x = 2 follows from the sign (the non-negative root of
    // x^2 = 4 is 2), so it is proved using the domain; x = -2 does not, and no point is found:
    // undecided.
    let big = VarDomain {
        lower: Some((Rational::from_integer(3), true)),
        upper: None,
        integer: false,
    };
    assert!(matches!(
        decide_in(&res, &rels, &[(0, big.clone())], 1).unwrap(),
        Decision::Proved { hypotheses, .. } if hypotheses == vec![Hypothesis::Domain(0)]
    ));
    let res = parse_poly::<Rational>("x + 2", &mut vars).unwrap();
    assert!(matches!(
        decide_in(&res, &rels, &[(0, big)], 1).unwrap(),
        Decision::Undecided { .. }
    ));
}

#[test]
fn malformed_domains_are_errors() {
    let mut vars = Vars::new();
    let res = parse_poly::<Rational>("x", &mut vars).unwrap();
    let empty = VarDomain {
        lower: Some((Rational::ONE, false)),
        upper: Some((Rational::ZERO, false)),
        integer: false,
    };
    assert_eq!(
        decide_in(&res, &[], &[(0, empty)], 1).unwrap_err(),
        DecideError::EmptyDomain(0)
    );
    let d = VarDomain::all();
    assert_eq!(
        decide_in(&res, &[], &[(0, d.clone()), (0, d.clone())], 1).unwrap_err(),
        DecideError::DuplicateDomain(0)
    );
    assert_eq!(
        decide_in(&res, &[], &[(3, d)], 1).unwrap_err(),
        DecideError::UnknownVariable(3)
    );
}

#[test]
fn square_roots_of_expressions_hold_by_their_squares_alone() {
    for (l, r) in [
        ("diff(sqrt(1 + x^2), x)", "x/sqrt(x^2 + 1)"),
        ("sqrt(x)^2", "x"),
        ("1/(sqrt(x) - 1)", "(sqrt(x) + 1)/(x - 1)"),
        ("sqrt(1 + sqrt(x))^2 - sqrt(x)", "1"),
        ("sqrt(y/x)*x", "sqrt(y/x)*x"),
        ("(x + sqrt(2))*sqrt(x*y)", "x*sqrt(x*y) + sqrt(2)*sqrt(y*x)"),
    ] {
        let d = random(l, r, 20, 7);
        let RandomDecision::Holds { log2_bound, .. } = d else {
            panic!("{l} = {r}: {d:?}")
        };
        assert!(log2_bound < -30.0, "{l} = {r}: {log2_bound}");
    }
    // False by the squares alone (a wrong sign, a wrong derivative, a sign relation between
    // roots): a difference, never a refutation.
    for (l, r) in [
        ("diff(sqrt(1 + x^2), x)", "-x/sqrt(x^2 + 1)"),
        ("sqrt(x)^3", "x"),
        ("sqrt(x)*sqrt(y)", "sqrt(x*y)"),
    ] {
        let d = random(l, r, 20, 7);
        assert!(
            matches!(&d, RandomDecision::Unconfirmed { why, .. } if why.contains("either sign")),
            "{l} = {r}: {d:?}"
        );
    }
}
