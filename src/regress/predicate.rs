//! `regress --predicate`: the formula is a geometric predicate (orient2d, incircle), used by
//! its sign; what matters is how often the float sign is wrong, not the error in ulps.
//!
//! Every compared sample's float sign (of the double result: `+`, `-` or `0`) is set against the
//! exact sign of the true value (exact for a rational formula; for a refined value, the sign the
//! exact side decided before refining: never a float). The counts are:
//! * **wrong sign**: both nonzero and opposite;
//! * **zero vs nonzero**: the float result is 0 where the true value is not, or the float result
//!   is nonzero where the true value is exactly 0 (a degenerate input the float code misses);
//! * **float failures**: a NaN, an infinity or no result: no sign at all.
//!
//! The worst examples are the samples of a wrong sign first, then of zero vs nonzero, each by
//! the size of the float result relative to its error (the ulps error of the sample), with the
//! inputs printed exactly (shortest round-trip doubles and the exact rationals they are).

use exactcheck_float::Observed;
use num_traits::Signed;
use serde_json::{json, Value};
use std::cmp::Ordering;

/// How one sample's float sign relates to the exact sign.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Verdict {
    /// Both nonzero and opposite.
    WrongSign,
    /// One is zero, the other not.
    ZeroVsNonzero,
    /// No float sign (NaN, infinity, no result).
    Failure,
    /// The same sign.
    Right,
}

/// One mis-signed sample, for the report.
#[derive(Clone, Debug, PartialEq)]
pub struct Example {
    /// The sample index.
    pub index: usize,
    /// What went wrong.
    pub verdict: Verdict,
    /// The inputs.
    pub inputs: Vec<f64>,
    /// The float result (`None`: no result).
    pub float: Option<f64>,
    /// The exact sign.
    pub exact: Ordering,
    /// The exact value, as the report prints it (`n/d`, or `~` and digits when refined).
    pub exact_text: String,
    /// The sample's error in ulps (how the examples are ranked).
    pub ulps: f64,
}

/// The sign errors of a sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Predicate {
    /// Samples compared.
    pub compared: usize,
    /// Samples of each [`Verdict`] but `Right`.
    pub wrong_sign: usize,
    /// Float 0 where the exact value is not.
    pub float_zero: usize,
    /// Float nonzero where the exact value is 0.
    pub float_nonzero: usize,
    /// Float failures.
    pub failures: usize,
    /// Samples whose exact value is 0.
    pub exact_zero: usize,
    /// The worst examples, worst first.
    pub worst: Vec<Example>,
    keep: usize,
    /// How the inputs were drawn (the `--near` set, if any).
    pub near: Option<String>,
}

fn sign_of(x: f64) -> Option<Ordering> {
    x.is_finite().then(|| x.partial_cmp(&0.0).expect("finite"))
}

impl Predicate {
    /// No sample yet; `keep` worst examples are kept.
    pub fn new(keep: usize, near: Option<String>) -> Predicate {
        Predicate {
            compared: 0,
            wrong_sign: 0,
            float_zero: 0,
            float_nonzero: 0,
            failures: 0,
            exact_zero: 0,
            worst: Vec::new(),
            keep,
            near,
        }
    }

    /// Counts one compared sample (of a one-output formula).
    pub fn add(&mut self, s: &Observed<'_>) {
        self.compared += 1;
        let exact_value = &s.exact[0].value;
        let exact = if exact_value.is_positive() {
            Ordering::Greater
        } else if exact_value.is_negative() {
            Ordering::Less
        } else {
            Ordering::Equal
        };
        if exact == Ordering::Equal {
            self.exact_zero += 1;
        }
        let float = s.float.and_then(|f| f.first().copied());
        let verdict = match float.and_then(sign_of) {
            None => Verdict::Failure,
            Some(f) if f == exact => Verdict::Right,
            Some(f) if f == Ordering::Equal || exact == Ordering::Equal => Verdict::ZeroVsNonzero,
            Some(_) => Verdict::WrongSign,
        };
        match verdict {
            Verdict::Right => return,
            Verdict::Failure => self.failures += 1,
            Verdict::WrongSign => self.wrong_sign += 1,
            Verdict::ZeroVsNonzero if exact == Ordering::Equal => self.float_nonzero += 1,
            Verdict::ZeroVsNonzero => self.float_zero += 1,
        }
        if self.keep == 0 {
            return;
        }
        let example = Example {
            index: s.index,
            verdict,
            inputs: s.inputs.to_vec(),
            float,
            exact,
            exact_text: if s.exact[0].exact {
                exact_value.to_string()
            } else {
                format!(
                    "~{}",
                    exactcheck_float::convert::decimal_digits(exact_value, 17)
                )
            },
            ulps: s.max_ulps,
        };
        let key = |e: &Example| (e.verdict, std::cmp::Reverse(OrdF64(e.ulps)), e.index);
        let pos = self.worst.partition_point(|e| key(e) < key(&example));
        if pos < self.keep {
            self.worst.insert(pos, example);
            self.worst.truncate(self.keep);
        }
    }

    /// The number of samples with any sign error.
    pub fn errors(&self) -> usize {
        self.wrong_sign + self.float_zero + self.float_nonzero + self.failures
    }

    /// The report's text.
    pub fn text(&self) -> String {
        let rate = |n: usize| {
            if self.compared == 0 {
                "-".to_string()
            } else {
                format!("{:.4}%", 100.0 * n as f64 / self.compared as f64)
            }
        };
        let mut out = format!(
            "predicate: the float sign against the exact sign on {} compared samples{}\n",
            self.compared,
            self.near
                .as_ref()
                .map_or(String::new(), |n| format!(" near {n}"))
        );
        out.push_str(&format!(
            "  wrong sign (opposite signs):             {} ({})\n",
            self.wrong_sign,
            rate(self.wrong_sign)
        ));
        out.push_str(&format!(
            "  zero vs nonzero:                         {} ({}): float 0 where exact is not {}, float nonzero where exact is 0 {}\n",
            self.float_zero + self.float_nonzero,
            rate(self.float_zero + self.float_nonzero),
            self.float_zero,
            self.float_nonzero
        ));
        out.push_str(&format!(
            "  no float sign (NaN, infinity):           {} ({})\n",
            self.failures,
            rate(self.failures)
        ));
        out.push_str(&format!(
            "  exactly zero (degenerate inputs):        {} ({})\n",
            self.exact_zero,
            rate(self.exact_zero)
        ));
        if !self.worst.is_empty() {
            out.push_str(
                "  worst examples (inputs exactly: doubles, then the rationals they are):\n",
            );
        }
        for e in &self.worst {
            let what = match e.verdict {
                Verdict::WrongSign => "wrong sign",
                Verdict::ZeroVsNonzero => "zero vs nonzero",
                Verdict::Failure => "no float sign",
                Verdict::Right => "right",
            };
            let float = e.float.map_or("none".to_string(), |f| format!("{f:?}"));
            out.push_str(&format!(
                "    sample {}: {what}: float {float}, exact {} ({})\n      inputs [{}]\n      exactly [{}]\n",
                e.index,
                sign_word(e.exact),
                e.exact_text,
                e.inputs
                    .iter()
                    .map(|x| format!("{x:?}"))
                    .collect::<Vec<_>>()
                    .join(", "),
                e.inputs
                    .iter()
                    .map(|&x| exactcheck_float::f64_to_rational(x)
                        .map_or_else(|| "NaN".into(), |q| q.to_string()))
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
        out
    }

    /// The JSON of the counts and examples.
    pub fn to_json(&self) -> Value {
        json!({
            "compared": self.compared,
            "near": self.near,
            "wrong_sign": self.wrong_sign,
            "float_zero_exact_nonzero": self.float_zero,
            "float_nonzero_exact_zero": self.float_nonzero,
            "no_float_sign": self.failures,
            "exact_zero": self.exact_zero,
            "worst": self.worst.iter().map(|e| json!({
                "sample": e.index,
                "verdict": format!("{:?}", e.verdict),
                "inputs": e.inputs,
                "inputs_exact": e.inputs.iter().map(|&x| exactcheck_float::f64_to_rational(x)
                    .map_or_else(|| "NaN".into(), |q| q.to_string())).collect::<Vec<String>>(),
                "float": e.float,
                "exact_sign": sign_word(e.exact),
                "exact": e.exact_text,
            })).collect::<Vec<_>>(),
        })
    }
}

fn sign_word(o: Ordering) -> &'static str {
    match o {
        Ordering::Less => "negative",
        Ordering::Equal => "zero",
        Ordering::Greater => "positive",
    }
}

/// A total order on doubles for ranking.
#[derive(Clone, Copy, Debug, PartialEq)]
struct OrdF64(f64);

impl Eq for OrdF64 {}

impl PartialOrd for OrdF64 {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for OrdF64 {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_float::ExactValue;
    use num_rational::BigRational;

    fn observe(p: &mut Predicate, index: usize, exact: i64, float: Option<f64>) {
        let e = [ExactValue::exact(BigRational::from_integer(exact.into()))];
        let f = float.map(|v| vec![v]);
        p.add(&Observed {
            index,
            inputs: &[index as f64],
            exact: &e,
            float: f.as_deref(),
            ulps: &[1.0],
            max_ulps: index as f64,
            bits: 0.0,
        });
    }

    #[test]
    fn signs_are_classified_and_the_worst_kept() {
        let mut p = Predicate::new(2, None);
        observe(&mut p, 1, 3, Some(2.0)); // right
        observe(&mut p, 2, -3, Some(0.5)); // wrong sign
        observe(&mut p, 3, 3, Some(0.0)); // float zero
        observe(&mut p, 4, 0, Some(-1e-300)); // float nonzero, exact zero
        observe(&mut p, 5, 0, Some(0.0)); // right, exactly zero
        observe(&mut p, 6, 1, Some(f64::NAN)); // no float sign
        observe(&mut p, 7, 1, None); // no float result
        observe(&mut p, 8, 2, Some(-0.0)); // -0 is zero
        assert_eq!(
            (
                p.compared,
                p.wrong_sign,
                p.float_zero,
                p.float_nonzero,
                p.failures,
                p.exact_zero
            ),
            (8, 1, 2, 1, 2, 2)
        );
        assert_eq!(p.errors(), 6);
        // Wrong signs first, then zero vs nonzero by the larger error.
        let kept: Vec<(usize, Verdict)> = p.worst.iter().map(|e| (e.index, e.verdict)).collect();
        assert_eq!(
            kept,
            vec![(2, Verdict::WrongSign), (8, Verdict::ZeroVsNonzero)]
        );
        let text = p.text();
        assert!(
            text.contains("wrong sign (opposite signs):             1 (12.5000%)"),
            "{text}"
        );
        assert!(
            text.contains("sample 2: wrong sign: float 0.5, exact negative (-3)"),
            "{text}"
        );
        assert!(text.contains("exactly [2]"), "{text}");
        assert_eq!(p.to_json()["float_nonzero_exact_zero"], 1);
    }
}
