//! Input domains: one exact [`Range`] per input, and the generator [`SampleDomain`] that samples
//! doubles inside them — the domain of an FPCore benchmark (from its `:pre`) or of
//! `regress --formula ... --domain 'x in [-1, 1], y >= 0'` ([`parse_domain`]).
//!
//! # Sampling
//! Each coordinate is drawn independently from the one [`Rng`]:
//! * **both bounds given**: uniform on the reals between the nearest doubles inside the bounds
//!   (exactly as [`crate::UniformBox`] draws: [`Rng::uniform`]);
//! * **a bound missing** (one-sided, or no bound at all): uniform over the *finite doubles* in
//!   range, i.e. over their ordinal index — the doubles ordered and numbered, `-0` and `+0`
//!   counted once — as Herbie samples. Every double is equally likely, so every binade
//!   (`[2^e, 2^(e+1))` holds 2^52 doubles whatever `e`) is equally likely: for `x >= 0` the
//!   median sample has a binary exponent near the middle of the exponent range (about 2^0),
//!   not near 1e308 as uniform-on-the-reals sampling would give.
//!
//! [`SampleDomain::with_sampling`] makes one rule apply to every coordinate ([`Sampling`]): all
//! uniform over the doubles of their ranges, bounded ones too (as Herbie samples every input),
//! or all uniform on the reals (every range then needs both bounds).
//!
//! # Binary32
//! [`SampleDomain::with_format`] with [`Format::Binary32`] samples binary32 values (held exactly by the
//! doubles returned): the ranges are those of the binary32 values inside the bounds (an
//! unbounded side stops at `±f32::MAX`), "uniform over the doubles" becomes uniform over the
//! binary32 values (their ordinal indices), and a uniform draw on the reals is rounded to the
//! nearest binary32 value (which stays in the range: its ends are binary32 values).
//!
//! # Exact bounds
//! Bounds are rationals. The sampled range of a coordinate is from the smallest double that
//! satisfies the lower bound (rounding `1/3` up; for an open bound, strictly above it) to the
//! largest double satisfying the upper bound, decided by exact comparison, so every sample
//! satisfies its bounds exactly. A range without any double (`(0, 5e-324)`, `[1/3, 1/3]`,
//! `x >= 1e400`) is a [`GenError`] naming the coordinate.
use crate::convert::f64_to_rational;
use crate::gen::{GenError, InputGen};
use exactcheck_core::Rng;
use exactcheck_exact::to_f64::Format;
use exactcheck_exact::Rational;

pub use exactcheck_exact::program::fpcore::{Bound, Range};

/// The ordinal index of a double: order-preserving, consecutive for adjacent doubles, `0` for
/// both zeros.
fn ordinal(x: f64) -> i64 {
    let bits = x.abs().to_bits() as i64;
    if x.is_sign_negative() {
        -bits
    } else {
        bits
    }
}

/// The double of ordinal index `k` (the inverse of [`ordinal`], `+0` for `0`).
fn from_ordinal(k: i64) -> f64 {
    let mag = f64::from_bits(k.unsigned_abs());
    if k < 0 {
        -mag
    } else {
        mag
    }
}

/// The ordinal index of a value of `format` ([`ordinal`] for doubles; binary32 values numbered
/// among themselves).
fn ordinal_in(format: Format, x: f64) -> i64 {
    match format {
        Format::Binary64 => ordinal(x),
        Format::Binary32 => {
            let bits = i64::from((x.abs() as f32).to_bits());
            if x.is_sign_negative() {
                -bits
            } else {
                bits
            }
        }
    }
}

/// The value of `format` of ordinal index `k` (the inverse of [`ordinal_in`]).
fn from_ordinal_in(format: Format, k: i64) -> f64 {
    match format {
        Format::Binary64 => from_ordinal(k),
        Format::Binary32 => {
            let mag = f64::from(f32::from_bits(
                u32::try_from(k.unsigned_abs()).unwrap_or(u32::MAX),
            ));
            if k < 0 {
                -mag
            } else {
                mag
            }
        }
    }
}

fn exact(x: f64) -> Rational {
    Rational::from(f64_to_rational(x).expect("a finite double"))
}

/// The smallest finite value of `format` satisfying the lower bound `b` (`-max` when
/// unbounded), or `None` when no finite value does.
fn lowest_value(b: &Bound, format: Format) -> Option<f64> {
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
fn highest_value(b: &Bound, format: Format) -> Option<f64> {
    let neg = |b: &Bound| match b {
        Bound::Unbounded => Bound::Unbounded,
        Bound::Closed(q) => Bound::Closed(-q.clone()),
        Bound::Open(q) => Bound::Open(-q.clone()),
    };
    lowest_value(&neg(b), format).map(|d| -d)
}

/// What the values of `format` are called in messages and descriptions.
fn values_word(format: Format) -> &'static str {
    match format {
        Format::Binary64 => "doubles",
        Format::Binary32 => "binary32 values",
    }
}

/// Which distribution the coordinates are drawn from (see the module doc).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Sampling {
    /// Uniform on the reals where both bounds are given, over the doubles otherwise.
    #[default]
    Mixed,
    /// Every coordinate uniform on the reals of its range (both bounds needed).
    Reals,
    /// Every coordinate uniform over the doubles of its range, as Herbie samples.
    Floats,
}

/// How one coordinate is drawn.
#[derive(Clone, Debug, PartialEq)]
enum Draw {
    /// Uniform on the reals in `[lo, hi]`.
    Uniform { lo: f64, hi: f64 },
    /// Uniform over the doubles of ordinal indices `lo..=hi`.
    Ordinal { lo: i64, hi: i64 },
}

/// A generator sampling each input inside its [`Range`] (see the module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct SampleDomain {
    intervals: Vec<Range>,
    draws: Vec<Draw>,
    names: Vec<String>,
    format: Format,
}

impl SampleDomain {
    /// The generator of these intervals, one per input. Inputs are named `x0`, `x1`, ... in
    /// errors and in [`InputGen::describe`] ([`SampleDomain::named`] names them).
    ///
    /// # Errors
    /// When an interval contains no finite double, naming the coordinate.
    pub fn new(intervals: Vec<Range>) -> Result<SampleDomain, GenError> {
        let names: Vec<String> = (0..intervals.len()).map(|i| format!("x{i}")).collect();
        SampleDomain::named(intervals, &names)
    }

    /// The generator of these intervals, one per input, with the inputs' names (for errors and
    /// [`InputGen::describe`]).
    ///
    /// # Errors
    /// When the number of names is not the number of intervals, or when an interval contains
    /// no finite double, naming the input.
    pub fn named(intervals: Vec<Range>, names: &[String]) -> Result<SampleDomain, GenError> {
        SampleDomain::named_in(intervals, names, Format::Binary64)
    }

    /// The same domain sampling the values of `format` (see the module doc; draw rules are
    /// reset to [`Sampling::Mixed`]: apply [`SampleDomain::with_sampling`] after this).
    ///
    /// # Errors
    /// When an interval contains no finite value of `format`, naming the input.
    pub fn with_format(self, format: Format) -> Result<SampleDomain, GenError> {
        SampleDomain::named_in(self.intervals, &self.names, format)
    }

    fn named_in(
        intervals: Vec<Range>,
        names: &[String],
        format: Format,
    ) -> Result<SampleDomain, GenError> {
        if names.len() != intervals.len() {
            return Err(GenError(format!(
                "{} names for a domain of {} inputs",
                names.len(),
                intervals.len()
            )));
        }
        let names = names.to_vec();
        let mut draws = Vec::with_capacity(intervals.len());
        for (i, iv) in intervals.iter().enumerate() {
            let empty = || {
                GenError(format!(
                    "input {i} ({}) has no finite {} in {}",
                    names[i],
                    match format {
                        Format::Binary64 => "double",
                        Format::Binary32 => "binary32 value",
                    },
                    show_interval(iv)
                ))
            };
            let lo = lowest_value(&iv.lo, format).ok_or_else(empty)?;
            let hi = highest_value(&iv.hi, format).ok_or_else(empty)?;
            if ordinal(lo) > ordinal(hi) {
                return Err(empty());
            }
            let bounded = iv.lo != Bound::Unbounded && iv.hi != Bound::Unbounded;
            draws.push(if bounded {
                Draw::Uniform { lo, hi }
            } else {
                Draw::Ordinal {
                    lo: ordinal_in(format, lo),
                    hi: ordinal_in(format, hi),
                }
            });
        }
        Ok(SampleDomain {
            intervals,
            draws,
            names,
            format,
        })
    }

    /// The same domain with input names for [`InputGen::describe`].
    ///
    /// # Errors
    /// When the number of names is not the number of intervals.
    pub fn with_names(mut self, names: &[String]) -> Result<SampleDomain, GenError> {
        if names.len() != self.intervals.len() {
            return Err(GenError(format!(
                "{} names for a domain of {} inputs",
                names.len(),
                self.intervals.len()
            )));
        }
        self.names = names.to_vec();
        Ok(self)
    }

    /// The same domain drawn by `sampling` ([`Sampling::Mixed`] is how [`SampleDomain::named`]
    /// draws).
    ///
    /// # Errors
    /// [`Sampling::Reals`] with a range that lacks a bound, naming the input.
    pub fn with_sampling(mut self, sampling: Sampling) -> Result<SampleDomain, GenError> {
        let format = self.format;
        for (i, (iv, draw)) in self.intervals.iter().zip(&mut self.draws).enumerate() {
            let bounded = iv.lo != Bound::Unbounded && iv.hi != Bound::Unbounded;
            let (lo, hi) = match *draw {
                Draw::Uniform { lo, hi } => (lo, hi),
                Draw::Ordinal { lo, hi } => {
                    (from_ordinal_in(format, lo), from_ordinal_in(format, hi))
                }
            };
            *draw = match sampling {
                Sampling::Mixed if bounded => Draw::Uniform { lo, hi },
                Sampling::Reals if bounded => Draw::Uniform { lo, hi },
                Sampling::Reals => {
                    return Err(GenError(format!(
                        "input {i} ({}) in {} has no uniform distribution on the reals: give both bounds, or sample the {}",
                        self.names[i],
                        show_interval(iv),
                        values_word(format)
                    )))
                }
                Sampling::Mixed | Sampling::Floats => Draw::Ordinal {
                    lo: ordinal_in(format, lo),
                    hi: ordinal_in(format, hi),
                },
            };
        }
        Ok(self)
    }

    /// The intervals, one per input.
    pub fn intervals(&self) -> &[Range] {
        &self.intervals
    }
}

impl InputGen for SampleDomain {
    fn arity(&self) -> usize {
        self.draws.len()
    }

    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        let format = self.format;
        self.draws
            .iter()
            .map(|d| match *d {
                Draw::Uniform { lo, hi } => match format {
                    Format::Binary64 => rng.uniform(lo, hi),
                    Format::Binary32 => f64::from(rng.uniform(lo, hi) as f32),
                },
                Draw::Ordinal { lo, hi } => {
                    // At most 2 * 0x7FEF_FFFF_FFFF_FFFF + 1 < 2^64 values.
                    let n = hi.abs_diff(lo) + 1;
                    let k = lo.wrapping_add(rng.below(n) as i64);
                    from_ordinal_in(format, k)
                }
            })
            .collect()
    }

    fn contains(&self, x: &[f64]) -> bool {
        let format = self.format;
        x.len() == self.draws.len()
            && x.iter().zip(&self.draws).all(|(&v, d)| {
                format.holds(v)
                    && match *d {
                        Draw::Uniform { lo, hi } => lo <= v && v <= hi,
                        Draw::Ordinal { lo, hi } => {
                            v.is_finite() && (lo..=hi).contains(&ordinal_in(format, v))
                        }
                    }
            })
    }

    fn describe(&self) -> String {
        let word = values_word(self.format);
        let parts: Vec<String> = self
            .intervals
            .iter()
            .zip(&self.names)
            .zip(&self.draws)
            .map(|((iv, name), draw)| match (&iv.lo, &iv.hi) {
                (Bound::Unbounded, Bound::Unbounded) => format!("{name} in all finite {word}"),
                (lo, Bound::Unbounded) => format!(
                    "{name} in {word} {} {}",
                    if matches!(lo, Bound::Open(_)) {
                        ">"
                    } else {
                        ">="
                    },
                    show_value(lo.value().expect("bounded"))
                ),
                (Bound::Unbounded, hi) => format!(
                    "{name} in {word} {} {}",
                    if matches!(hi, Bound::Open(_)) {
                        "<"
                    } else {
                        "<="
                    },
                    show_value(hi.value().expect("bounded"))
                ),
                _ => match draw {
                    Draw::Uniform { .. } => match self.format {
                        Format::Binary64 => format!("{name} in {} (uniform)", show_interval(iv)),
                        Format::Binary32 => format!(
                            "{name} in {} (uniform, rounded to binary32)",
                            show_interval(iv)
                        ),
                    },
                    Draw::Ordinal { .. } => {
                        format!("{name} in {} (uniform over the {word})", show_interval(iv))
                    }
                },
            })
            .collect();
        if parts.is_empty() {
            "no inputs".to_string()
        } else {
            parts.join(", ")
        }
    }
}

/// A bound value: as a double when it is one (`1e15`, `0.5`), else as the exact rational.
fn show_value(q: &Rational) -> String {
    let d = q.to_f64();
    if d.is_finite() && &exact(d) == q {
        let a = d.abs();
        if a != 0.0 && !(1e-4..1e6).contains(&a) {
            format!("{d:e}")
        } else {
            format!("{d}")
        }
    } else {
        q.to_string()
    }
}

/// `[lo, hi]`, `(lo, inf)`, ...
fn show_interval(iv: &Range) -> String {
    let lo = match &iv.lo {
        Bound::Unbounded => "(-inf".to_string(),
        Bound::Closed(q) => format!("[{}", show_value(q)),
        Bound::Open(q) => format!("({}", show_value(q)),
    };
    let hi = match &iv.hi {
        Bound::Unbounded => "inf)".to_string(),
        Bound::Closed(q) => format!("{}]", show_value(q)),
        Bound::Open(q) => format!("{})", show_value(q)),
    };
    format!("{lo}, {hi}")
}

/// Which sides of an input a domain text has bounded so far.
#[derive(Clone, Copy, Default)]
struct Seen {
    lo: bool,
    hi: bool,
}

/// Parses a domain text into one [`Range`] per variable of `vars`.
///
/// The text is a comma-separated list of parts, each `NAME in [a, b]` (brackets: `[`/`]`
/// closed, `(`/`)` open; `inf`, `+inf`, `-inf` for a missing bound) or a one-sided
/// `NAME >= a`, `NAME > a`, `NAME <= b`, `NAME < b` (a lower and an upper one-sided part may
/// bound the same variable). Numbers are in the workspace's number syntax, parsed by
/// [`Rational`]'s `FromStr`: `1e15`, `-2^60`, `1/3`, `0.1` (exactly one tenth). A variable not
/// mentioned is unbounded on both sides; an empty text bounds nothing.
///
/// # Errors
/// A one-line message naming the part: an unknown variable, a variable bounded twice (on the
/// same side), an unparsable number, `lo > hi`, or garbage.
pub fn parse_domain(text: &str, vars: &[String]) -> Result<Vec<Range>, String> {
    let mut out = vec![Range::UNBOUNDED; vars.len()];
    let mut seen = vec![Seen::default(); vars.len()];
    for part in split_parts(text) {
        let part = part.trim();
        if part.is_empty() {
            if text.trim().is_empty() {
                continue;
            }
            return Err(format!("domain {text:?}: an empty part between commas"));
        }
        let bad = |why: &str| format!("domain part {part:?}: {why}");
        let name_end = part
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(part.len());
        let name = &part[..name_end];
        if name.is_empty() {
            return Err(bad("expected a variable name"));
        }
        let Some(i) = vars.iter().position(|v| v == name) else {
            return Err(bad(&format!(
                "unknown variable `{name}` (the variables are {})",
                vars.join(", ")
            )));
        };
        let rest = part[name_end..].trim_start();
        let (lo, hi) = if let Some(spec) = rest.strip_prefix("in") {
            let spec = spec.trim();
            let (lo, hi) = parse_bracketed(spec).map_err(|why| bad(&why))?;
            if seen[i].lo || seen[i].hi {
                return Err(bad(&format!("`{name}` is bounded twice")));
            }
            (Some(lo), Some(hi))
        } else {
            let (op, value) = [">=", "<=", ">", "<"]
                .iter()
                .find_map(|op| rest.strip_prefix(op).map(|v| (*op, v)))
                .ok_or_else(|| bad("expected `in [a, b]` or a comparison `>= a`, `< b`, ..."))?;
            let v = parse_number(value.trim()).map_err(|why| bad(&why))?;
            let Some(v) = v else {
                return Err(bad("a one-sided bound must be a finite number"));
            };
            match op {
                ">=" => (Some(Bound::Closed(v)), None),
                ">" => (Some(Bound::Open(v)), None),
                "<=" => (None, Some(Bound::Closed(v))),
                _ => (None, Some(Bound::Open(v))),
            }
        };
        if let Some(lo) = lo {
            if seen[i].lo {
                return Err(bad(&format!("`{name}` has two lower bounds")));
            }
            seen[i].lo = true;
            out[i].lo = lo;
        }
        if let Some(hi) = hi {
            if seen[i].hi {
                return Err(bad(&format!("`{name}` has two upper bounds")));
            }
            seen[i].hi = true;
            out[i].hi = hi;
        }
        if let (Some(l), Some(h)) = (out[i].lo.value(), out[i].hi.value()) {
            let open = matches!(out[i].lo, Bound::Open(_)) || matches!(out[i].hi, Bound::Open(_));
            if l > h || (l == h && open) {
                return Err(bad(&format!(
                    "the interval of `{name}` is empty: {}",
                    show_interval(&out[i])
                )));
            }
        }
    }
    Ok(out)
}

/// The parts of a domain text: split at the commas outside brackets and parentheses.
fn split_parts(text: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in text.char_indices() {
        match c {
            '[' | '(' => depth += 1,
            ']' | ')' => depth -= 1,
            ',' if depth <= 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

/// `[a, b]`, `(a, b]`, ... into its two bounds.
fn parse_bracketed(spec: &str) -> Result<(Bound, Bound), String> {
    let open_lo = match spec.chars().next() {
        Some('[') => false,
        Some('(') => true,
        _ => return Err("expected `[` or `(` after `in`".to_string()),
    };
    let open_hi = match spec.chars().last() {
        Some(']') if spec.len() > 1 => false,
        Some(')') if spec.len() > 1 => true,
        _ => return Err("expected the interval to end with `]` or `)`".to_string()),
    };
    let inner = &spec[1..spec.len() - 1];
    // The comma between the bounds: the first one outside parentheses.
    let mut depth = 0i32;
    let comma = inner.char_indices().find_map(|(i, c)| {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ',' if depth == 0 => return Some(i),
            _ => {}
        }
        None
    });
    let Some(comma) = comma else {
        return Err("expected two bounds `a, b` in the interval".to_string());
    };
    let lo_text = inner[..comma].trim();
    let hi_text = inner[comma + 1..].trim();
    let lo = match parse_number(lo_text)? {
        Some(v) if open_lo => Bound::Open(v),
        Some(v) => Bound::Closed(v),
        None if is_minus_inf(lo_text) => Bound::Unbounded,
        None => return Err("the lower bound cannot be +inf".to_string()),
    };
    let hi = match parse_number(hi_text)? {
        Some(v) if open_hi => Bound::Open(v),
        Some(v) => Bound::Closed(v),
        None if !is_minus_inf(hi_text) => Bound::Unbounded,
        None => return Err("the upper bound cannot be -inf".to_string()),
    };
    Ok((lo, hi))
}

fn is_minus_inf(s: &str) -> bool {
    s.starts_with('-')
}

/// A bound: `Ok(None)` for `inf`, `+inf`, `-inf` (also `infinity`), else the exact number.
fn parse_number(s: &str) -> Result<Option<Rational>, String> {
    let unsigned = s.strip_prefix(['+', '-']).unwrap_or(s).trim();
    if unsigned.eq_ignore_ascii_case("inf") || unsigned.eq_ignore_ascii_case("infinity") {
        return Ok(None);
    }
    if s.is_empty() {
        return Err("expected a number".to_string());
    }
    s.parse::<Rational>()
        .map(Some)
        .map_err(|e| format!("`{s}` is not a number ({e})"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convert::binary_exponent;

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
        let empty = SampleDomain::named(
            vec![iv(
                cl(1),
                Bound::Closed(
                    q(1, 1)
                        + Rational::from(num_rational::BigRational::new(
                            1.into(),
                            (1u64 << 40).into(),
                        )),
                ),
            )],
            &names[..1],
        )
        .and_then(|d| d.with_format(Format::Binary32));
        assert!(empty.is_ok(), "1 itself is a binary32 value");
        let none = SampleDomain::named(
            vec![iv(
                Bound::Open(q(1, 1)),
                Bound::Open(
                    q(1, 1)
                        + Rational::from(num_rational::BigRational::new(
                            1.into(),
                            (1u64 << 40).into(),
                        )),
                ),
            )],
            &names[..1],
        )
        .and_then(|d| d.with_format(Format::Binary32));
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
}
