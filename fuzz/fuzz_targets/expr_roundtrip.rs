//! The expression parser and printer: whatever parses prints to text that parses again, to an
//! expression whose printed form is a fixed point from the second round on and which expands to
//! the same polynomial (over Q, or over Q(sqrt) when it has square roots); `parse_poly` agrees
//! with `parse_expr` + `to_poly`. Errors are fine; panics are not.
#![no_main]
use exactcheck_exact::expr::{parse_expr, parse_expr_with_calls, parse_poly, Expr};
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::{Radical, Rational};
use exactcheck_fuzz::{small_limits, text, with_raised_limits};
use libfuzzer_sys::fuzz_target;

fn same_poly<C>(a: &Expr, b: &Expr, source: &str)
where
    C: exactcheck_exact::expr::Coefficient + PartialEq + std::fmt::Debug,
    Poly<C>: PartialEq + std::fmt::Debug,
{
    let mut vars = Vars::new();
    let Ok(p) = a.to_poly::<C>(&mut vars) else {
        return;
    };
    let via_text = parse_poly::<C>(source, &mut vars);
    assert_eq!(
        via_text.as_ref(),
        Ok(&p),
        "parse_poly disagrees with to_poly on {source:?}"
    );
    let q = with_raised_limits(|| b.to_poly::<C>(&mut vars));
    assert_eq!(
        q.as_ref(),
        Ok(&p),
        "{source:?} printed as {b} expands differently"
    );
}

fuzz_target!(|data: &[u8]| {
    small_limits();
    let source = text(data);
    let _ = parse_expr_with_calls(source).map(|e| e.to_string());
    let Ok(e) = parse_expr(source) else {
        return;
    };
    let printed = e.to_string();
    let again = with_raised_limits(|| parse_expr(&printed))
        .unwrap_or_else(|err| panic!("{source:?} printed as {printed:?} does not parse: {err}"));
    // A decimal `0.5` is the number 1/2 and prints as `(1/2)`, which parses as a quotient: the
    // printed form settles after the first round.
    let printed2 = again.to_string();
    let third = with_raised_limits(|| parse_expr(&printed2))
        .unwrap_or_else(|err| panic!("{source:?} printed as {printed2:?} does not parse: {err}"));
    assert_eq!(
        printed2,
        third.to_string(),
        "printing {source:?} does not settle"
    );
    if source.contains("sqrt") {
        same_poly::<Radical>(&e, &again, source);
    } else {
        same_poly::<Rational>(&e, &again, source);
    }
});
