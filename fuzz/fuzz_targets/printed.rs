//! The printed-decimal judge of value claims (`exactcheck::claims::printed`): an exact value and
//! a printed decimal of any length.
//!
//! From the input: `EXPR\nPRINTED` (an element of the square-root field and the printed text).
//! Checked: the certified decimal `decimal(v, p)` has `p` places and is a correct rounding of
//! `v` (`rounds_to`); a printed decimal that is a correct rounding and not a tie is that decimal;
//! a truncation that is not a rounding lies on the other side of `v` from the correct one; the
//! deviation text has the sign of `printed - v`. Never a panic.
#![no_main]
use exactcheck::claims::printed;
use exactcheck_core::scalar::{OrderedField, Ring, Sign};
use exactcheck_exact::expr::ExprError;
use exactcheck_exact::{Radical, Rational};
use exactcheck_fuzz::{small_limits, text};
use libfuzzer_sys::fuzz_target;

/// Places judged at most: a few hundred digits keep one run in milliseconds.
const MAX_PLACES: u32 = 300;

fuzz_target!(|data: &[u8]| {
    small_limits();
    let Some((expr, shown)) = text(data).split_once('\n') else {
        return;
    };
    let Ok(v) = expr.parse::<Radical>() else {
        return;
    };
    let Ok(q) = printed::rational(shown) else {
        return;
    };
    let p = printed::places(shown);
    if p > MAX_PLACES {
        return;
    }
    let correct = printed::decimal(&v, p);
    // A decimal longer than the fuzzer's small `digits` limit is not read back.
    let c: Rational = match correct.parse() {
        Ok(c) => c,
        Err(ExprError::Limit { .. }) => return,
        Err(e) => panic!("the certified decimal {correct} does not parse: {e}"),
    };
    assert_eq!(printed::places(&correct), p, "{correct} for {p} places");
    assert!(
        printed::rounds_to(&v, &c, p),
        "{correct} is not a rounding of {v} to {p} places"
    );
    // A printed multiple of 10^-p that rounds correctly and is not a tie is the certified one.
    let on_grid = q.mul_ref(&printed::pow10(p)).is_integer();
    if on_grid && printed::rounds_to(&v, &q, p) && !printed::ties(&v, &q, p) {
        assert_eq!(q, c, "{shown} and {correct} both round {v} to {p} places");
    }
    let dev = printed::radical(&q).sub_ref(&v);
    let text = printed::deviation_text(&dev);
    // A deviation longer than the fuzzer's small `digits` limit is not read back.
    let shown_dev: Rational = match text.trim_start_matches('+').parse() {
        Ok(d) => d,
        Err(ExprError::Limit { .. }) => return,
        Err(e) => panic!("the deviation {text} does not parse: {e}"),
    };
    let sign = |x: &Rational| x.signum();
    match dev.sign() {
        Sign::Zero => assert_eq!(text, "0"),
        s => {
            assert_eq!(sign(&shown_dev), s, "{text} for {dev}");
        }
    }
});
