//! The one timer of the benchmark workloads: wall-clock time and the process's CPU time of the
//! same region, so that `bench/scripts/compare.py` can compare tools by CPU time (the measure that a
//! shared machine disturbs least) and still show wall time beside it.

use std::time::Instant;

/// A running measurement of wall-clock and process CPU time.
#[derive(Clone, Copy, Debug)]
pub struct Stopwatch {
    wall: Instant,
    cpu: f64,
}

/// What a [`Stopwatch`] measured, in seconds.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Elapsed {
    /// Wall-clock seconds.
    pub wall: f64,
    /// CPU seconds of the whole process (all threads) in the region.
    pub cpu: f64,
}

impl Stopwatch {
    /// Starts measuring now.
    pub fn start() -> Self {
        Stopwatch {
            wall: Instant::now(),
            cpu: process_cpu_seconds(),
        }
    }

    /// The time since [`Stopwatch::start`].
    pub fn elapsed(&self) -> Elapsed {
        Elapsed {
            wall: self.wall.elapsed().as_secs_f64(),
            cpu: process_cpu_seconds() - self.cpu,
        }
    }
}

/// The CPU time the process has used so far (`CLOCK_PROCESS_CPUTIME_ID`: every thread, user and
/// system), in seconds; 0 where the clock is unavailable.
pub fn process_cpu_seconds() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec for the duration of the call.
    let ok = unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut ts) } == 0;
    if ok {
        ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cpu_time_grows_with_work_and_wall_time_is_not_negative() {
        let w = Stopwatch::start();
        let mut x = 0u64;
        for i in 0..5_000_000u64 {
            x = x.wrapping_mul(6364136223846793005).wrapping_add(i);
        }
        std::hint::black_box(x);
        let e = w.elapsed();
        assert!(e.cpu > 0.0, "{e:?}");
        assert!(e.wall >= 0.0, "{e:?}");
    }
}
