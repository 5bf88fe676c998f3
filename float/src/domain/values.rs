//! The values of a format as the sampler sees them: their ordinal indices (consecutive for
//! adjacent values, as Herbie numbers the doubles) and the extreme values inside a bound.
use crate::convert::f64_to_rational;
use exactcheck_exact::program::fpcore::Bound;
use exactcheck_exact::to_f64::Format;
use exactcheck_exact::Rational;
/// The ordinal index of a double: order-preserving, consecutive for adjacent doubles, `0` for
/// both zeros.
pub(super) fn ordinal(x: f64) -> i64 {
    ordinal_in(Format::Binary64, x)
}

/// The double of ordinal index `k` (the inverse of [`ordinal`], `+0` for `0`).
#[cfg(test)]
pub(super) fn from_ordinal(k: i64) -> f64 {
    from_ordinal_in(Format::Binary64, k)
}

/// The ordinal index of a value of `format` ([`ordinal`] for doubles; binary32 values numbered
/// among themselves): the bits of its magnitude, with its sign.
pub(super) fn ordinal_in(format: Format, x: f64) -> i64 {
    let bits = match format {
        Format::Binary64 => x.abs().to_bits() as i64,
        Format::Binary32 => i64::from((x.abs() as f32).to_bits()),
    };
    if x.is_sign_negative() {
        -bits
    } else {
        bits
    }
}

/// The value of `format` of ordinal index `k` (the inverse of [`ordinal_in`]).
pub(super) fn from_ordinal_in(format: Format, k: i64) -> f64 {
    let mag = match format {
        Format::Binary64 => f64::from_bits(k.unsigned_abs()),
        Format::Binary32 => f64::from(f32::from_bits(
            u32::try_from(k.unsigned_abs()).unwrap_or(u32::MAX),
        )),
    };
    if k < 0 {
        -mag
    } else {
        mag
    }
}

pub(super) fn exact(x: f64) -> Rational {
    Rational::from(f64_to_rational(x).expect("a finite double"))
}

/// The smallest finite value of `format` satisfying the lower bound `b` (`-max` when
/// unbounded), or `None` when no finite value does.
pub(super) fn lowest_value(b: &Bound, format: Format) -> Option<f64> {
    let (q, strict) = match b {
        Bound::Unbounded => return Some(-format.max()),
        Bound::Closed(q) => (q, false),
        Bound::Open(q) => (q, true),
    };
    let d = match format {
        Format::Binary64 => q.to_f64(),
        Format::Binary32 => format.round(&q.to_big_rational()),
    };
    let d = if d == f64::INFINITY {
        return None;
    } else if d == f64::NEG_INFINITY {
        -format.max()
    } else {
        d
    };
    let e = exact(d);
    let ok = if strict { &e > q } else { &e >= q };
    let d = if ok {
        d
    } else {
        from_ordinal_in(format, ordinal_in(format, d) + 1)
    };
    d.is_finite().then_some(d)
}

/// The largest finite value of `format` satisfying the upper bound `b` (`max` when
/// unbounded), or `None` when no finite value does.
pub(super) fn highest_value(b: &Bound, format: Format) -> Option<f64> {
    let neg = |b: &Bound| match b {
        Bound::Unbounded => Bound::Unbounded,
        Bound::Closed(q) => Bound::Closed(-q.clone()),
        Bound::Open(q) => Bound::Open(-q.clone()),
    };
    lowest_value(&neg(b), format).map(|d| -d)
}

/// What the values of `format` are called in messages and descriptions.
pub(super) fn values_word(format: Format) -> &'static str {
    match format {
        Format::Binary64 => "doubles",
        Format::Binary32 => "binary32 values",
    }
}
