//! Shards: equal parts of a sweep by sample index, run separately and merged.

/// Part `index` (1-based) of `count` equal parts of a sweep, by sample index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// Which part, `1..=count`.
    pub index: usize,
    /// How many parts.
    pub count: usize,
}

impl Shard {
    /// The sample indices of this part of a sweep of `samples`: `[(i-1) S / N, i S / N)`.
    pub fn range(&self, samples: usize) -> std::ops::Range<usize> {
        let at = |k: usize| (k as u128 * samples as u128 / self.count as u128) as usize;
        at(self.index - 1)..at(self.index)
    }
}

impl std::str::FromStr for Shard {
    type Err = String;
    /// `I/N` with `1 <= I <= N`.
    fn from_str(s: &str) -> Result<Shard, String> {
        let bad = || format!("shard '{s}' is not I/N with 1 <= I <= N (e.g. 2/4)");
        let (i, n) = s.split_once('/').ok_or_else(bad)?;
        let (index, count) = (
            i.trim().parse::<usize>().map_err(|_| bad())?,
            n.trim().parse::<usize>().map_err(|_| bad())?,
        );
        if index == 0 || index > count {
            return Err(bad());
        }
        Ok(Shard { index, count })
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// A sweep: how many samples, the seed, and which shard of it to run (all when `None`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sweep {
    /// The number of samples of the whole sweep.
    pub samples: usize,
    /// The seed: sample `i` draws from `Rng::for_sample(seed, i)`.
    pub seed: u64,
    /// The part to run.
    pub shard: Option<Shard>,
}
