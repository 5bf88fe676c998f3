use super::*;
use crate::test_support::Q;

fn q(n: i128, d: i128) -> Q {
    Q::new(n, d)
}

/// `prod (t - r)` in the power basis.
fn power_from_roots<T: Field>(roots: &[T]) -> Vec<T> {
    let mut a = vec![T::one()];
    for r in roots {
        let mut next = vec![T::zero(); a.len() + 1];
        for (k, c) in a.iter().enumerate() {
            next[k + 1] += c;
            next[k] -= c.mul_ref(r);
        }
        a = next;
    }
    a
}

fn bern<T: Field>(roots: &[T]) -> Bernstein<T> {
    Bernstein::from_power(&power_from_roots(roots)).unwrap()
}

/// Whether the isolated root holds `x` (equal when exact, strictly inside otherwise).
fn holds(r: &IsolatedRoot<Q>, x: &Q) -> bool {
    match r {
        IsolatedRoot::Exact(v) => v == x,
        IsolatedRoot::Between(lo, hi) => lo < x && x < hi,
    }
}

#[test]
fn dyadic_roots_and_end_points_are_exact() {
    let p = bern(&[q(0, 1), q(1, 2), q(1, 1), q(1, 4), q(3, 8)]);
    assert_eq!(
        unit_roots(&p).unwrap(),
        vec![
            IsolatedRoot::Exact(q(0, 1)),
            IsolatedRoot::Exact(q(1, 4)),
            IsolatedRoot::Exact(q(3, 8)),
            IsolatedRoot::Exact(q(1, 2)),
            IsolatedRoot::Exact(q(1, 1)),
        ]
    );
}

#[test]
fn non_dyadic_roots_are_isolated_with_sign_change() {
    let roots = [q(1, 3), q(2, 3), q(5, 7)];
    let p = bern(&roots);
    let found = unit_roots(&p).unwrap();
    assert_eq!(found.len(), 3);
    for (r, x) in found.iter().zip(&roots) {
        assert!(holds(r, x), "{r:?} should hold {x:?}");
        if let IsolatedRoot::Between(lo, hi) = r {
            assert!(lo < hi);
            assert_eq!(p.eval(lo).sign() * p.eval(hi).sign(), Sign::Negative);
        }
        assert_eq!(multiplicity(&p, r), 1);
    }
    // increasing and disjoint
    for w in found.windows(2) {
        assert!(w[0].hi() <= w[1].lo());
    }
}

#[test]
fn refine_narrows_and_keeps_the_root() {
    let p = bern(&[q(1, 3), q(4, 5)]);
    let width = q(1, 1000);
    for (r, x) in unit_roots(&p).unwrap().iter().zip([q(1, 3), q(4, 5)]) {
        let fine = refine(&p, r, &width);
        assert!(fine.width() <= width);
        assert!(holds(&fine, &x));
        assert!(fine.lo() >= r.lo() && fine.hi() <= r.hi());
    }
    // An exact midpoint hit becomes Exact: the root 3/4 with a first interval around it.
    let p = bern(&[q(3, 4), q(1, 3)]);
    let between = IsolatedRoot::Between(q(1, 2), q(1, 1));
    assert_eq!(
        refine(&p, &between, &q(1, 100)),
        IsolatedRoot::Exact(q(3, 4))
    );
}

#[test]
fn double_and_triple_roots_are_reported_once_with_multiplicity() {
    // (t - 1/3)^2 (t - 3/4) (t - 1)^2 t^3
    let p = bern(&[
        q(1, 3),
        q(1, 3),
        q(3, 4),
        q(1, 1),
        q(1, 1),
        q(0, 1),
        q(0, 1),
        q(0, 1),
    ]);
    let found = unit_roots(&p).unwrap();
    assert_eq!(found.len(), 4, "{found:?}");
    assert_eq!(found[0], IsolatedRoot::Exact(q(0, 1)));
    assert!(holds(&found[1], &q(1, 3)));
    assert_eq!(found[2], IsolatedRoot::Exact(q(3, 4)));
    assert_eq!(found[3], IsolatedRoot::Exact(q(1, 1)));
    let mult: Vec<usize> = found.iter().map(|r| multiplicity(&p, r)).collect();
    assert_eq!(mult, vec![3, 2, 1, 2]);
    // a triple irrational-interval root
    let p = bern(&[q(1, 3), q(1, 3), q(1, 3)]);
    let found = unit_roots(&p).unwrap();
    assert_eq!(found.len(), 1);
    assert_eq!(multiplicity(&p, &found[0]), 3);
    // not a root at all
    assert_eq!(multiplicity(&p, &IsolatedRoot::Exact(q(1, 2))), 0);
}

#[test]
fn roots_just_outside_the_unit_interval_are_not_reported() {
    let p = bern(&[q(-1, 20), q(21, 20), q(1, 2), q(2, 1)]);
    let found = unit_roots(&p).unwrap();
    assert_eq!(found.len(), 1);
    assert!(holds(&found[0], &q(1, 2)));
    // with a second root in [0, 1], V = 2 on [0, 1] and the split point 1/2 is hit exactly
    let p = bern(&[q(-1, 20), q(21, 20), q(1, 2), q(1, 3)]);
    let found = unit_roots(&p).unwrap();
    assert_eq!(found.len(), 2);
    assert!(holds(&found[0], &q(1, 3)));
    assert_eq!(found[1], IsolatedRoot::Exact(q(1, 2)));
    let p = bern(&[q(-1, 1000), q(1001, 1000), q(3, 1)]);
    assert_eq!(unit_roots(&p).unwrap(), vec![]);
    // t^2 + 1 has no real root at all (but V = 0 only after the square-free step is trivial)
    let p = Bernstein::from_power(&[q(1, 1), q(0, 1), q(1, 1)]).unwrap();
    assert_eq!(unit_roots(&p).unwrap(), vec![]);
    // a pair of complex roots close to 1/2: (t - 1/2)^2 + 1/10000 — V = 2 first, then 0
    let p = Bernstein::from_power(&[q(2501, 10000), q(-1, 1), q(1, 1)]).unwrap();
    assert_eq!(unit_roots(&p).unwrap(), vec![]);
}

#[test]
fn constant_and_zero_polynomials() {
    let c = Bernstein::constant(q(3, 1), 4);
    assert_eq!(unit_roots(&c).unwrap(), vec![]);
    let z = Bernstein::constant(q(0, 1), 3);
    assert_eq!(unit_roots(&z), Err(ZeroPolynomial));
    assert_eq!(square_free(&z), Err(ZeroPolynomial));
    assert_eq!(multiplicity(&z, &IsolatedRoot::Exact(q(1, 2))), 0);
    // A representation of higher degree than the polynomial (elevated) changes nothing.
    let p = bern(&[q(1, 3)]).elevate_by(4);
    let found = unit_roots(&p).unwrap();
    assert_eq!(found.len(), 1);
    assert!(holds(&found[0], &q(1, 3)));
}

#[test]
fn common_roots_via_gcd() {
    let p1 = bern(&[q(1, 3), q(1, 2), q(2, 1)]);
    let p2 = bern(&[q(3, 4), q(1, 3), q(3, 4)]);
    let p3 = bern(&[q(1, 3), q(1, 2)]).elevate();
    let zero = Bernstein::constant(q(0, 1), 2);
    let common = common_unit_roots(&[p1.clone(), zero.clone(), p2.clone(), p3]).unwrap();
    assert_eq!(common.len(), 1);
    assert!(holds(&common[0], &q(1, 3)));
    assert_eq!(
        common_unit_roots(&[p1.clone(), bern(&[q(1, 2), q(1, 5)])]).unwrap(),
        vec![IsolatedRoot::Exact(q(1, 2))]
    );
    assert_eq!(
        common_unit_roots(&[p1.clone(), bern(&[q(1, 5)])]).unwrap(),
        vec![]
    );
    assert_eq!(
        common_unit_roots(std::slice::from_ref(&zero)),
        Err(ZeroPolynomial)
    );
    assert_eq!(common_unit_roots::<Q>(&[]), Err(ZeroPolynomial));
    // The gcd itself: monic (t - 1/3) in degree 1.
    let g = gcd(&[p1, p2]).unwrap();
    assert_eq!(g.to_power(), vec![q(-1, 3), q(1, 1)]);
}

#[test]
fn degree_twenty_with_twenty_roots_in_f64() {
    // Roots (2k+1)/42, k = 0..19, none dyadic: f64 is the heuristic instantiation, here with
    // well separated roots.
    let roots: Vec<f64> = (0..20).map(|k| (2 * k + 1) as f64 / 42.0).collect();
    // Built as a product in Bernstein form (the power basis would perturb the roots by far
    // more than the tolerance: Wilkinson).
    let p = roots.iter().fold(Bernstein::new(vec![1.0]), |acc, r| {
        acc.mul(&Bernstein::new(vec![-r, 1.0 - r]))
    });
    assert_eq!(p.degree(), 20);
    let found = unit_roots(&p).unwrap();
    assert_eq!(found.len(), 20, "{found:?}");
    for (r, x) in found.iter().zip(&roots) {
        assert!(*r.lo() <= *x && *x <= *r.hi(), "{r:?} should hold {x}");
        let fine = refine(&p, r, &1e-9);
        assert!((fine.midpoint() - x).abs() < 1e-6, "{fine:?} vs {x}");
    }
}

#[test]
fn eight_dyadic_roots_found_exactly() {
    // Roots j/8, j = 1..8: split points of the bisection (and the end point 1), all Exact.
    let distinct: Vec<Q> = (1..=8).map(|j| q(j, 8)).collect();
    let p = bern(&distinct);
    let found = unit_roots(&p).unwrap();
    let expected: Vec<IsolatedRoot<Q>> = distinct.iter().map(|x| IsolatedRoot::Exact(*x)).collect();
    assert_eq!(found, expected);
    assert!(found.iter().all(|r| multiplicity(&p, r) == 1));
}

#[test]
fn a_line_has_its_root_exact() {
    // V = 1 on [0, 1] already; a degree-1 square-free part gives the root by one division.
    let p = bern(&[q(2, 7)]);
    assert_eq!(unit_roots(&p).unwrap(), vec![IsolatedRoot::Exact(q(2, 7))]);
    // A double root with the line as square-free part, after refinement too.
    let p = bern(&[q(2, 7), q(2, 7)]);
    assert_eq!(unit_roots(&p).unwrap(), vec![IsolatedRoot::Exact(q(2, 7))]);
    assert_eq!(
        refine(&p, &IsolatedRoot::Between(q(0, 1), q(1, 1)), &q(1, 10)),
        IsolatedRoot::Exact(q(2, 7))
    );
    // Degree 2 square-free part: V = 1 on [0, 1] gives the whole interval, refined by bisection.
    let p = bern(&[q(2, 7), q(2, 7), q(5, 1)]);
    let whole = IsolatedRoot::Between(q(0, 1), q(1, 1));
    assert_eq!(unit_roots(&p).unwrap(), vec![whole.clone()]);
    let fine = refine(&p, &whole, &q(1, 10));
    assert!(
        fine.width() <= q(1, 10) && holds(&fine, &q(2, 7)),
        "{fine:?}"
    );
}

#[test]
fn square_free_entry_point_matches() {
    let p = bern(&[q(1, 3), q(1, 3), q(1, 2), q(5, 6)]);
    let sqf = square_free(&p).unwrap();
    assert_eq!(sqf.degree(), 3);
    assert_eq!(unit_roots_square_free(&sqf), unit_roots(&p).unwrap());
}

#[test]
#[should_panic(expected = "zero polynomial")]
fn square_free_entry_point_rejects_zero() {
    unit_roots_square_free(&Bernstein::constant(q(0, 1), 2));
}

/// Regression: two f64 roots closer than the spacing of doubles near 1/2 used to panic
/// ("the midpoint rounds to an end point"); they are now one `Between` cluster around 1/2.
#[test]
fn f64_inseparable_roots_are_a_cluster_not_a_panic() {
    let e = 2f64.powi(-60);
    // (t - 1/2)(t - 1/2 - e) in Bernstein form of degree 2 from its power coefficients.
    let p = Bernstein::from_power(&[0.5 * (0.5 + e), -(1.0 + e), 1.0]).unwrap();
    let roots = unit_roots(&p).unwrap();
    assert!(!roots.is_empty());
    for r in &roots {
        let (lo, hi) = match r {
            IsolatedRoot::Exact(x) => (*x, *x),
            IsolatedRoot::Between(a, b) => (*a, *b),
        };
        assert!(lo <= 0.5 + 1e-9 && hi >= 0.5 - 1e-9, "{r:?}");
    }
}

/// The quadratic shortcut of [`square_free`] (a discriminant test) gives the gcd's answer: on
/// every quadratic with small rational coefficients, including the double roots, the degree-2
/// Bernstein forms of lines and constants, and leading coefficients of either sign.
#[test]
fn square_free_of_a_quadratic_is_the_gcds() {
    let vals: Vec<Q> = [-3, -2, -1, 0, 1, 2, 4]
        .iter()
        .flat_map(|&n| [q(n, 1), q(n, 3)])
        .collect();
    let mut double = 0;
    for a in &vals {
        for b in &vals {
            for c in &vals {
                let power = [*a, *b, *c];
                let Ok(p) = Bernstein::from_power(&power) else {
                    continue;
                };
                let trimmed = trim(power.to_vec());
                if trimmed.is_empty() {
                    assert_eq!(square_free(&p), Err(ZeroPolynomial));
                    continue;
                }
                let reference = Bernstein::from_power(&square_free_of_power(&trimmed)).unwrap();
                let got = square_free(&p).unwrap();
                // The same polynomial up to a constant factor: the same monic power form.
                assert_eq!(
                    trim(got.to_power()).len(),
                    trim(reference.to_power()).len(),
                    "{power:?}"
                );
                assert_eq!(
                    monic(&trim(got.to_power())),
                    monic(&trim(reference.to_power())),
                    "{power:?}"
                );
                if trimmed.len() == 3 && got.degree() == 1 {
                    double += 1;
                }
            }
        }
    }
    assert!(double > 0, "the double roots were reached");
}
