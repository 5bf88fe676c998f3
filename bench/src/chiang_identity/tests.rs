//! The identity holds at every size the benchmarks use, from text and with the `Ring` API, its
//! perturbed form does not, and the text is the anchor's byte for byte.

use super::*;
use exactcheck_exact::expr::parse_poly;
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::Rational;

type P = Poly<Rational>;

fn poly(text: &str, vars: &mut Vars) -> P {
    parse_poly(text, vars).expect("the identity's text parses")
}

/// The identity from text: `(LHS, RHS, variables)`; `negative` perturbs `phi(0, 0)` as
/// `chiang_identity.py --negative` does (1 becomes 1 + 1/7).
fn from_text(m: u32, n: u32, negative: bool) -> (P, P, Vars) {
    let (lhs, mut rhs) = identity_text(m, n);
    if negative {
        assert!(rhs.contains("1/1*("));
        rhs = rhs.replacen("1/1*(", "8/7*(", 1);
    }
    let mut vars = Vars::new();
    let l = poly(&lhs, &mut vars);
    let r = poly(&rhs, &mut vars);
    (l, r, vars)
}

#[test]
fn the_text_is_the_anchors() {
    let (lhs, rhs) = identity_text(2, 3);
    assert_eq!(
        lhs,
        "(1*t^0*(1-t)^2*(a*qx0+b*qy0+c*qz0)+2*t^1*(1-t)^1*(a*qx1+b*qy1+c*qz1)+1*t^2*(1-t)^0*\
         (a*qx2+b*qy2+c*qz2))*(1*t^0*(1-t)^3*px0+3*t^1*(1-t)^2*px1+3*t^2*(1-t)^1*px2+1*t^3*\
         (1-t)^0*px3)-(1*t^0*(1-t)^3*(a*px0+b*py0+c*pz0+d)+3*t^1*(1-t)^2*(a*px1+b*py1+c*pz1+d)\
         +3*t^2*(1-t)^1*(a*px2+b*py2+c*pz2+d)+1*t^3*(1-t)^0*(a*px3+b*py3+c*pz3+d))*(1*t^0*\
         (1-t)^2*qx0+2*t^1*(1-t)^1*qx1+1*t^2*(1-t)^0*qx2)"
    );
    assert!(rhs.starts_with("1*t^0*(1-t)^5*(1/1*((a*qx0+b*qy0+c*qz0)*px0-(a*px0+b*py0+c*pz0+d)*qx0))+5*t^1*(1-t)^4*(3/5*("));
    let (l, r) = identity_text(8, 13);
    // `chiang_text.py 8 13 | wc -c` gives 9500: both lines and their newlines.
    assert_eq!(l.len() + r.len() + 2, 9500);
}

/// The app's `prove` test reads this size's text from a fixture: it is this text.
#[test]
fn the_apps_fixture_is_the_text() {
    let fixture = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/fixtures/chiang_identity_4_6.txt"
    ))
    .expect("the fixture");
    let (lhs, rhs) = identity_text(4, 6);
    assert_eq!(fixture, format!("{lhs}\n{rhs}\n"));
}

#[test]
fn the_identity_holds_from_text_and_its_perturbation_does_not() {
    for (m, n, terms, nvars) in [(2, 3, 174, 26), (4, 6, 855, 41), (8, 13, 5841, 74)] {
        let (l, r, vars) = from_text(m, n, false);
        assert_eq!(l.len(), terms, "({m},{n})");
        assert_eq!(vars.len(), nvars);
        assert_eq!(l, r, "({m},{n}) does not prove");
        let (l, r, _) = from_text(m, n, true);
        assert!(!(&l - &r).is_zero(), "({m},{n}) --negative proves");
    }
}

#[test]
fn the_expanded_side_prints_and_parses_back() {
    let (l, _, mut vars) = from_text(4, 6, false);
    let text = l.display(&vars).to_string();
    assert_eq!(poly(&text, &mut vars), l);
}

#[test]
fn the_identity_holds_with_the_ring_api_and_its_perturbation_does_not() {
    for (m, n) in [(2, 3), (4, 6), (8, 13)] {
        let (dp, dq) = ring_residuals(m, n, false);
        assert!(dp.is_zero() && dq.is_zero(), "({m},{n})");
        let (dp, dq) = ring_residuals(m, n, true);
        assert!(!dp.is_zero() && !dq.is_zero(), "({m},{n}) --negative");
    }
}

#[test]
fn the_workload_reports_proved_and_the_perturbation_not() {
    let text = run(2, 3, false, true).expect("valid sizes");
    assert!(text.contains("\"x_identity_zero\": true, \"weight_identity_zero\": true"));
    let text = run(2, 3, true, true).expect("valid sizes");
    assert!(text.contains("\"x_identity_zero\": false, \"weight_identity_zero\": false"));
    assert!(run(30, 30, false, true).is_err());
    assert!(run(0, 3, false, true).is_err());
}
