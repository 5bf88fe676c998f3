//! The workspace's one seeded random number generator: xoshiro256** seeded through SplitMix64.
//!
//! Every crate draws from this type (the regression harness, the catalogue's exact instances, the
//! counter-example search and the evaluation points of randomized identity tests); it lives in
//! `core` because it knows no number type.
//!
//! Written here rather than taken from a crate so that a regression report stays reproducible
//! from its seed forever: the stream is fixed by this file (and pinned by known-answer tests),
//! not by a dependency's version. Not for cryptography.
//!
//! Each sample of a regression run draws from its own stream, [`Rng::for_sample`]`(seed, index)`,
//! so a single worst case can be regenerated from `(seed, index)` without replaying the run.

/// One step of SplitMix64 (Steele, Lea, Flood 2014): advances `state` and returns the next output.
pub fn splitmix64(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The xoshiro256** generator (Blackman, Vigna 2018).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rng {
    s: [u64; 4],
}

impl Rng {
    /// A generator whose state is four SplitMix64 outputs from `seed`.
    pub fn new(seed: u64) -> Rng {
        let mut sm = seed;
        let s = [
            splitmix64(&mut sm),
            splitmix64(&mut sm),
            splitmix64(&mut sm),
            splitmix64(&mut sm),
        ];
        Rng::from_state(s)
    }

    /// A generator with the given raw state (an all-zero state, the one fixed point of
    /// xoshiro, is replaced by the state of `Rng::new(0)`).
    pub fn from_state(s: [u64; 4]) -> Rng {
        if s == [0; 4] {
            Rng::new(0)
        } else {
            Rng { s }
        }
    }

    /// The independent stream of sample `index` of a run with seed `seed`.
    pub fn for_sample(seed: u64, index: u64) -> Rng {
        let mut a = seed;
        let mut b = index ^ 0xD1B5_4A32_D192_ED03;
        let mixed = splitmix64(&mut a) ^ splitmix64(&mut b).rotate_left(17);
        Rng::new(mixed)
    }

    /// The stream of a run with seed `seed` on the input `bytes`: [`Rng::for_sample`] with the
    /// index a SplitMix64 fold of the bytes (8 at a time, little-endian, then the length), so
    /// that one seed gives unrelated streams for different inputs. Not a cryptographic hash.
    pub fn for_input(seed: u64, bytes: &[u8]) -> Rng {
        let mut h = 0x243F_6A88_85A3_08D3u64;
        for chunk in bytes.chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            h ^= u64::from_le_bytes(word);
            h = splitmix64(&mut h);
        }
        h ^= bytes.len() as u64;
        Rng::for_sample(seed, splitmix64(&mut h))
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        let result = self.s[1].wrapping_mul(5).rotate_left(7).wrapping_mul(9);
        let t = self.s[1] << 17;
        self.s[2] ^= self.s[0];
        self.s[3] ^= self.s[1];
        self.s[1] ^= self.s[2];
        self.s[0] ^= self.s[3];
        self.s[2] ^= t;
        self.s[3] = self.s[3].rotate_left(45);
        result
    }

    /// A uniform double in `[0, 1)` with 53 random bits.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// A uniform double in `[lo, hi]` (for finite `lo <= hi`; the result is clamped into the
    /// interval, so it is finite even for the widest intervals).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let t = self.next_f64();
        let x = lo * (1.0 - t) + hi * t;
        if x.is_nan() {
            lo
        } else {
            x.clamp(lo.min(hi), hi.max(lo))
        }
    }

    /// A uniform integer in `[0, n)` (Lemire's multiply-shift with rejection); `0` when `n == 0`.
    pub fn below(&mut self, n: u64) -> u64 {
        if n == 0 {
            return 0;
        }
        let threshold = n.wrapping_neg() % n;
        loop {
            let m = u128::from(self.next_u64()) * u128::from(n);
            if (m as u64) >= threshold {
                return (m >> 64) as u64;
            }
        }
    }

    /// `true` with probability `p` (clamped to `[0, 1]`).
    pub fn chance(&mut self, p: f64) -> bool {
        self.next_f64() < p
    }

    /// `1.0` or `-1.0` with equal probability.
    pub fn sign(&mut self) -> f64 {
        if self.next_u64() >> 63 == 0 {
            1.0
        } else {
            -1.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix_known_answer() {
        // The reference implementation's first outputs from seed 0.
        let mut s = 0u64;
        assert_eq!(splitmix64(&mut s), 0xE220_A839_7B1D_CDAF);
        assert_eq!(splitmix64(&mut s), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn input_streams_differ_by_input_and_repeat_by_seed() {
        let draw = |seed, text: &str| Rng::for_input(seed, text.as_bytes()).next_u64();
        assert_eq!(draw(7, "x"), draw(7, "x"));
        assert_ne!(draw(7, "x"), draw(7, "2*x"));
        assert_ne!(draw(7, "x"), draw(8, "x"));
        // The length is part of the input: trailing zero bytes change the stream.
        assert_ne!(draw(7, "x"), draw(7, "x\0"));
    }

    #[test]
    fn xoshiro_known_answer() {
        // The reference implementation from the state [1, 2, 3, 4].
        let mut r = Rng::from_state([1, 2, 3, 4]);
        assert_eq!(r.next_u64(), 11520);
        assert_eq!(r.next_u64(), 0);
        assert_eq!(r.next_u64(), 1509978240);
        assert_eq!(r.next_u64(), 1215971899390074240);
    }

    #[test]
    fn ranges() {
        let mut r = Rng::new(7);
        for _ in 0..1000 {
            let x = r.next_f64();
            assert!((0.0..1.0).contains(&x));
            let y = r.uniform(-2.0, 3.0);
            assert!((-2.0..=3.0).contains(&y));
            assert!(r.below(10) < 10);
            let z = r.uniform(-f64::MAX, f64::MAX);
            assert!(z.is_finite());
        }
        assert_eq!(r.below(0), 0);
        assert_eq!(r.uniform(1.0, 1.0), 1.0);
    }

    #[test]
    fn streams_are_reproducible_and_distinct() {
        let a: Vec<u64> = (0..4).map(|_| Rng::for_sample(5, 9).next_u64()).collect();
        assert!(a.iter().all(|&x| x == a[0]));
        assert_ne!(
            Rng::for_sample(5, 9).next_u64(),
            Rng::for_sample(5, 10).next_u64()
        );
        assert_ne!(
            Rng::for_sample(5, 9).next_u64(),
            Rng::for_sample(6, 9).next_u64()
        );
    }
}
