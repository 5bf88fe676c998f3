//! Tests of the worked example's internals.

use super::*;

#[test]
fn the_exact_r0_of_r_15_and_the_printed_digits() {
    let rows = ph_offsets_rows().unwrap();
    let x15 = rows
        .iter()
        .find(|r| r.r == "15" && r.name == "r0.x")
        .unwrap();
    assert_eq!(x15.exact, q(-300, 101));
    assert!(!x15.correctly_rounded);
    assert!(x15.reproduced_by.is_empty(), "{:?}", x15.reproduced_by);
    let x3 = rows
        .iter()
        .find(|r| r.r == "3" && r.name == "r0.x")
        .unwrap();
    assert_eq!(x3.exact, q(-60, 101));
    assert_eq!(
        x3.reproduced_by,
        vec!["the magnitude of the exact value correctly rounded (a lost minus sign)".to_string()]
    );
    assert!(rows
        .iter()
        .filter(|r| r.name == "w0")
        .all(|r| r.correctly_rounded));
}

#[test]
fn self_intersections_are_decided_exactly() {
    let (n, e) = self_intersections_of(&q(15, 1)).unwrap();
    assert_eq!(n, 1, "{e}");
    assert!(
        e.contains("2 cusps") && e.contains("1 self-intersection: C(s) = C(t)"),
        "{e}"
    );
    let (n, e) = self_intersections_of(&q(101, 8)).unwrap();
    assert_eq!(n, 0, "{e}");
    assert!(e.contains("1 cusp: t = 1/2 (multiplicity 2)"), "{e}");
    assert!(e.contains("no self-intersection (certified"), "{e}");
}
