//! The mergeable counts and summaries of a sweep, folded sample by sample in sample order and
//! turned into the [`Report`].

use super::{Evaluated, Options, Subject, Sweep};
use crate::report::{Report, Summary, ThresholdCount, WorstCase};
use crate::summary::{BitsSum, Distribution};
use crate::CaseError;

/// The mergeable counts and summaries of a sweep.
pub(super) struct Accumulator {
    thresholds: Vec<f64>,
    above: Vec<usize>,
    ulps: Distribution,
    rel: Distribution,
    bits: BitsSum,
    max_bits: f64,
    max_ulps: f64,
    max_rel: f64,
    max_per_output: Vec<f64>,
    compared: usize,
    domain_errors: usize,
    invalid_inputs: usize,
    undecided: usize,
    limit_stops: usize,
    limit_stop: Vec<crate::report::LimitStop>,
    refined: usize,
    float_failures: usize,
}

impl Accumulator {
    pub(super) fn new(options: &Options) -> Accumulator {
        Accumulator {
            thresholds: options.thresholds.clone(),
            above: vec![0; options.thresholds.len()],
            ulps: Distribution::new(),
            rel: Distribution::new(),
            bits: BitsSum::default(),
            max_bits: 0.0,
            max_ulps: 0.0,
            max_rel: 0.0,
            max_per_output: Vec::new(),
            compared: 0,
            domain_errors: 0,
            invalid_inputs: 0,
            undecided: 0,
            limit_stops: 0,
            limit_stop: Vec::new(),
            refined: 0,
            float_failures: 0,
        }
    }

    pub(super) fn skip(&mut self, e: CaseError) {
        match e {
            CaseError::InvalidInputs => self.invalid_inputs += 1,
            CaseError::OutsideDomain => self.domain_errors += 1,
            CaseError::Undecided => self.undecided += 1,
            CaseError::LimitExceeded { limit, value } => {
                self.limit_stops += 1;
                let stop = crate::report::LimitStop {
                    limit: limit.to_string(),
                    value,
                };
                crate::report::note_limit_stop(&mut self.limit_stop, &stop);
            }
        }
    }

    pub(super) fn add(&mut self, ev: &Evaluated) {
        self.compared += 1;
        if ev.failure {
            self.float_failures += 1;
        }
        if ev.exact.iter().any(|v| !v.exact) {
            self.refined += 1;
        }
        if self.max_per_output.len() < ev.ulps.len() {
            self.max_per_output.resize(ev.ulps.len(), 0.0);
        }
        for (m, &u) in self.max_per_output.iter_mut().zip(&ev.ulps) {
            *m = m.max(u);
        }
        for (c, &t) in self.above.iter_mut().zip(&self.thresholds) {
            if ev.max_ulps > t {
                *c += 1;
            }
        }
        self.max_ulps = self.max_ulps.max(ev.max_ulps);
        self.max_rel = self.max_rel.max(ev.max_rel);
        self.ulps.push(ev.max_ulps);
        self.rel.push(ev.max_rel);
        self.bits.push(ev.bits);
        self.max_bits = self.max_bits.max(ev.bits);
    }

    pub(super) fn report(
        self,
        subject: &(impl Subject + ?Sized),
        generator: String,
        sweep: Sweep,
        options: &Options,
        worst: Vec<WorstCase>,
    ) -> Report {
        let range = sweep
            .shard
            .map_or(0..sweep.samples, |s| s.range(sweep.samples));
        let mut r = Report {
            formula: subject.name(),
            float_side: subject.float_side(),
            generator,
            precision: subject.format().name().to_string(),
            arity: subject.arity(),
            samples: sweep.samples,
            seed: sweep.seed,
            shard: sweep.shard,
            first_sample: range.start,
            end_sample: range.end,
            keep: options.worst,
            compared: self.compared,
            domain_errors: self.domain_errors,
            invalid_inputs: self.invalid_inputs,
            undecided: self.undecided,
            limit_stops: self.limit_stops,
            limit_stop: self.limit_stop,
            refined: self.refined,
            float_failures: self.float_failures,
            max_ulps: self.max_ulps,
            median_ulps: 0.0,
            mean_ulps: 0.0,
            max_rel: self.max_rel,
            median_rel: 0.0,
            bits_of_error: 0.0,
            max_bits: self.max_bits,
            max_ulps_per_output: self.max_per_output,
            above: self
                .thresholds
                .iter()
                .zip(&self.above)
                .map(|(&ulps, &count)| ThresholdCount { ulps, count })
                .collect(),
            worst,
            summary: Summary {
                ulps: self.ulps,
                rel: self.rel,
                bits: self.bits,
            },
        };
        r.refresh_statistics();
        r
    }
}
