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
//! [`SampleDomain::with_formats`] gives each input its own format (an FPCore argument of
//! another precision than its benchmark's): each coordinate is drawn as its format says.
//!
//! # Exact bounds
//! Bounds are rationals. The sampled range of a coordinate is from the smallest double that
//! satisfies the lower bound (rounding `1/3` up; for an open bound, strictly above it) to the
//! largest double satisfying the upper bound, decided by exact comparison, so every sample
//! satisfies its bounds exactly. A range without any double (`(0, 5e-324)`, `[1/3, 1/3]`,
//! `x >= 1e400`) is a [`GenError`] naming the coordinate.
use crate::gen::{GenError, InputGen};
use exactcheck_core::Rng;
use exactcheck_exact::to_f64::Format;

pub use exactcheck_exact::program::fpcore::{Bound, Range};
pub use text::parse_domain;
use text::{show_interval, show_value};
use values::{from_ordinal_in, highest_value, lowest_value, ordinal, ordinal_in, values_word};

mod text;
mod values;

#[cfg(test)]
mod tests;

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
    /// The format of each coordinate's values.
    formats: Vec<Format>,
    /// The format the sampled program computes in: a coordinate of another format is named
    /// as such by [`InputGen::describe`].
    base: Format,
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
        let formats = vec![Format::Binary64; intervals.len()];
        SampleDomain::named_in(intervals, names, formats, Format::Binary64)
    }

    /// The same domain sampling the values of `format` (see the module doc; draw rules are
    /// reset to [`Sampling::Mixed`]: apply [`SampleDomain::with_sampling`] after this).
    ///
    /// # Errors
    /// When an interval contains no finite value of `format`, naming the input.
    pub fn with_format(self, format: Format) -> Result<SampleDomain, GenError> {
        let formats = vec![format; self.intervals.len()];
        SampleDomain::named_in(self.intervals, &self.names, formats, format)
    }

    /// The same domain with input `i` sampling the values of `formats[i]` (FPCore's arguments
    /// of their own precision; see the module doc; draw rules are reset to
    /// [`Sampling::Mixed`]: apply [`SampleDomain::with_sampling`] after this), for a program
    /// computing in `base` ([`InputGen::describe`] names the format of an input of another).
    ///
    /// # Errors
    /// When the number of formats is not the number of inputs, or an interval contains no
    /// finite value of its input's format, naming the input.
    pub fn with_formats(self, base: Format, formats: &[Format]) -> Result<SampleDomain, GenError> {
        if formats.len() != self.intervals.len() {
            return Err(GenError(format!(
                "{} formats for a domain of {} inputs",
                formats.len(),
                self.intervals.len()
            )));
        }
        SampleDomain::named_in(self.intervals, &self.names, formats.to_vec(), base)
    }

    fn named_in(
        intervals: Vec<Range>,
        names: &[String],
        formats: Vec<Format>,
        base: Format,
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
            let format = formats[i];
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
            formats,
            base,
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
        for (i, (iv, draw)) in self.intervals.iter().zip(&mut self.draws).enumerate() {
            let format = self.formats[i];
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
        self.draws
            .iter()
            .zip(&self.formats)
            .map(|(d, &format)| match *d {
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
        x.len() == self.draws.len()
            && x.iter()
                .zip(&self.draws)
                .zip(&self.formats)
                .all(|((&v, d), &format)| {
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
        let parts: Vec<String> = self
            .intervals
            .iter()
            .zip(&self.names)
            .zip(&self.draws)
            .zip(&self.formats)
            .map(|(((iv, name), draw), &format)| (iv, name, draw, format))
            .map(|(iv, name, draw, format)| match (&iv.lo, &iv.hi) {
                (Bound::Unbounded, Bound::Unbounded) => {
                    format!("{name} in all finite {}", values_word(format))
                }
                (lo, Bound::Unbounded) => one_sided(name, values_word(format), '>', lo),
                (Bound::Unbounded, hi) => one_sided(name, values_word(format), '<', hi),
                _ => match draw {
                    Draw::Uniform { .. } => match format {
                        // A binary64 input of a binary32 program.
                        Format::Binary64 if self.base != format => {
                            format!("{name} in {} (uniform, binary64)", show_interval(iv))
                        }
                        Format::Binary64 => format!("{name} in {} (uniform)", show_interval(iv)),
                        Format::Binary32 => format!(
                            "{name} in {} (uniform, rounded to binary32)",
                            show_interval(iv)
                        ),
                    },
                    Draw::Ordinal { .. } => format!(
                        "{name} in {} (uniform over the {})",
                        show_interval(iv),
                        values_word(format)
                    ),
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

/// `NAME in WORD > b` (`>=` for a closed bound; `<`, `<=` likewise) for a one-sided range.
fn one_sided(name: &str, word: &str, op: char, b: &Bound) -> String {
    let eq = if matches!(b, Bound::Open(_)) { "" } else { "=" };
    format!(
        "{name} in {word} {op}{eq} {}",
        show_value(b.value().expect("bounded"))
    )
}
