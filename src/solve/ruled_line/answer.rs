//! The answer of `ruled_line`: the analysis rendered with exact strings or f64 numbers.

use super::analysis::{Analysis, Outcome, Status};
use super::covered::{Covered, End, COMPARE_STEPS};
use crate::solve::scalar::Scalar;
use exactcheck_core::roots::IsolatedRoot;
use exactcheck_core::Vec3;
use serde::Serialize;

/// A root parameter: exact value or isolating interval, with an approximation.
#[derive(Debug, Serialize)]
pub(super) struct ParamOut<S> {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) value: Option<S>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) interval: Option<[S; 2]>,
    pub(super) approx: f64,
}

#[derive(Debug, Serialize)]
pub(super) struct RootOut<S> {
    pub(super) t: ParamOut<S>,
    pub(super) multiplicity: usize,
    pub(super) status: &'static str,
    /// Whether `s`, `lambda` and `point` are exact (else approximations at the midpoint of
    /// the isolating interval of width <= 2^-60).
    pub(super) exact: bool,
    pub(super) s: Option<S>,
    pub(super) lambda: Option<S>,
    pub(super) point: Option<[S; 3]>,
    pub(super) approx: PointApprox,
}

#[derive(Debug, Serialize)]
pub(super) struct PointApprox {
    pub(super) s: Option<f64>,
    pub(super) lambda: Option<f64>,
    pub(super) point: Option<[f64; 3]>,
}

#[derive(Debug, Serialize)]
pub(crate) struct AnswerOut<S> {
    pub(super) kind: &'static str,
    pub(super) mode: &'static str,
    pub(super) m: usize,
    pub(super) n: usize,
    pub(super) degree: usize,
    /// The Bernstein coefficients of `det(B(t) - P, V(t), D)`, degree `m + n`.
    pub(super) polynomial: Vec<S>,
    pub(super) outcome: &'static str,
    pub(super) points: Vec<RootOut<S>>,
    /// `parallel_to_every_ruling`: the roots `t` whose ruling is the line (`null`: every ruling).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) rulings_on_line: Option<Option<Vec<ParamOut<S>>>>,
    /// The covered part of the line when every ruling meets the line or a ruling is the line:
    /// disjoint intervals of `lambda`, increasing (`null` ends are unbounded).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) covered: Option<Vec<PieceOut<S>>>,
    /// The least and the largest `lambda` of `covered` (`null`: unbounded).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) lambda_at_ends: Option<[Option<EndOut<S>>; 2]>,
    /// `undecided`: what was tried.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) note: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) float: Option<Box<AnswerOut<f64>>>,
}

/// An end of a covered interval: `lambda` exactly (`value`) or enclosed (`interval`, at an
/// irrational parameter), whether it is covered itself (`closed`), and the parameter `t` of the
/// ruling through it or whose neighbours' meeting points tend to it.
#[derive(Debug, Serialize)]
pub(super) struct EndOut<S> {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) value: Option<S>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) interval: Option<[S; 2]>,
    pub(super) approx: f64,
    pub(super) closed: bool,
    pub(super) t: ParamOut<S>,
}

#[derive(Debug, Serialize)]
pub(super) struct PieceOut<S> {
    pub(super) from: Option<EndOut<S>>,
    pub(super) to: Option<EndOut<S>>,
}

pub(super) fn end_out<T: Scalar, S>(end: &End<T>, out: &impl Fn(&T) -> S) -> Option<EndOut<S>> {
    let mut e = end.clone()?;
    let exact = e.exact();
    let (value, interval) = match exact {
        Some(x) => (Some(x), None),
        None => {
            // Narrow the parameter until lambda is enclosed to 2^-50 (relative to 1 + |lambda|).
            let mut enclosure = e.enclosure();
            for _ in 0..200 {
                if let Some((lo, hi)) = &enclosure {
                    let scale = T::one() + lo.abs() + hi.abs();
                    if hi.sub_ref(lo) <= scale / T::from_ratio(1 << 50, 1).expect("not zero") {
                        break;
                    }
                }
                if !e.narrow() {
                    break;
                }
                enclosure = e.enclosure();
            }
            (None, enclosure)
        }
    };
    let approx = match (&value, &interval) {
        (Some(x), _) => x.approx(),
        (None, Some((lo, hi))) => (lo.add_ref(hi) / T::from_i64(2)).approx(),
        (None, None) => e.approx_value().map_or(0.0, |x| x.approx()),
    };
    Some(EndOut {
        value: value.map(|x| out(&x)),
        interval: interval.map(|(lo, hi)| [out(&lo), out(&hi)]),
        approx,
        closed: e.closed,
        t: param(&e.t, out),
    })
}

/// Sets `outcome`, `covered`, `lambda_at_ends` (and `note`) from the covered part of the line.
pub(super) fn describe<T: Scalar, S>(
    answer: &mut AnswerOut<S>,
    covered: &Covered<T>,
    out: &impl Fn(&T) -> S,
) {
    match covered {
        Covered::WholeLine => {
            answer.outcome = "line_on_surface";
            answer.covered = Some(vec![PieceOut {
                from: None,
                to: None,
            }]);
            answer.lambda_at_ends = Some([None, None]);
        }
        Covered::Undecided => {
            answer.outcome = "undecided";
            answer.note = Some(format!(
                "the rulings meet the line in a set of parameters or limits whose end values were compared exactly where possible; two irrational end values were still not ordered after {COMPARE_STEPS} halvings of their parameters (they may be equal)"
            ));
        }
        Covered::Pieces(pieces) => {
            let points = pieces.iter().all(|p| match (&p.from, &p.to) {
                (Some(a), Some(b)) => a.key == b.key,
                _ => false,
            });
            answer.outcome =
                if pieces.len() == 1 && pieces[0].from.is_none() && pieces[0].to.is_none() {
                    "line_on_surface"
                } else if pieces.is_empty() {
                    "no_points"
                } else if !points {
                    "line_segment_on_surface"
                } else if pieces.len() == 1 {
                    "single_point"
                } else {
                    "isolated_points"
                };
            let first = pieces.first().and_then(|p| end_out(&p.from, out));
            let last = pieces.last().and_then(|p| end_out(&p.to, out));
            answer.lambda_at_ends = Some([first, last]);
            answer.covered = Some(
                pieces
                    .iter()
                    .map(|p| PieceOut {
                        from: end_out(&p.from, out),
                        to: end_out(&p.to, out),
                    })
                    .collect(),
            );
        }
    }
}

pub(super) fn param<T: Scalar, S>(r: &IsolatedRoot<T>, out: &impl Fn(&T) -> S) -> ParamOut<S> {
    match r {
        IsolatedRoot::Exact(t) => ParamOut {
            value: Some(out(t)),
            interval: None,
            approx: t.approx(),
        },
        IsolatedRoot::Between(lo, hi) => ParamOut {
            value: None,
            interval: Some([out(lo), out(hi)]),
            approx: r.midpoint().approx(),
        },
    }
}

pub(super) fn render<T: Scalar, S>(
    a: &Analysis<T>,
    mode: &'static str,
    out: impl Fn(&T) -> S,
) -> AnswerOut<S> {
    let v3 = |x: &Vec3<T>| [out(&x.x), out(&x.y), out(&x.z)];
    let a3 = |x: &Vec3<T>| [x.x.approx(), x.y.approx(), x.z.approx()];
    let mut answer = AnswerOut {
        kind: "ruled_line",
        mode,
        m: a.m,
        n: a.n,
        degree: a.m + a.n,
        polynomial: a.polynomial.coeffs().iter().map(&out).collect(),
        outcome: "",
        points: Vec::new(),
        rulings_on_line: None,
        covered: None,
        lambda_at_ends: None,
        note: None,
        float: None,
    };
    match &a.outcome {
        Outcome::Roots(reports) => {
            answer.outcome = if reports.iter().any(|r| r.status == Status::RulingOnLine) {
                // A ruling is the line: the whole line lies on the surface.
                describe(&mut answer, &Covered::<T>::WholeLine, &out);
                answer.outcome
            } else if reports.iter().any(|r| r.point.is_some()) {
                "points"
            } else {
                "no_points"
            };
            answer.points = reports
                .iter()
                .map(|r| RootOut {
                    t: param(&r.root, &out),
                    multiplicity: r.multiplicity,
                    status: r.status.name(),
                    exact: r.exact,
                    s: r.s.as_ref().filter(|_| r.exact).map(&out),
                    lambda: r.lambda.as_ref().filter(|_| r.exact).map(&out),
                    point: r.point.as_ref().filter(|_| r.exact).map(v3),
                    approx: PointApprox {
                        s: r.s.as_ref().map(Scalar::approx),
                        lambda: r.lambda.as_ref().map(Scalar::approx),
                        point: r.point.as_ref().map(a3),
                    },
                })
                .collect();
        }
        Outcome::ParallelToEveryRuling(roots, covered) => {
            answer.rulings_on_line = Some(
                roots
                    .as_ref()
                    .map(|rs| rs.iter().map(|r| param(r, &out)).collect()),
            );
            describe(&mut answer, covered, &out);
            answer.outcome = "parallel_to_every_ruling";
        }
        Outcome::Covered(covered) => describe(&mut answer, covered, &out),
    }
    answer
}
