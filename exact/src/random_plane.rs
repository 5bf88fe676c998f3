//! Random planes `a x + b y + c z + d = 0` over `Q(sqrt 2, sqrt 3, sqrt 5)` ([`Radical`]) for
//! testing sections of the cone `x^2 + y^2 = z^2`, from generators aimed at the boundaries
//! between the section types: `theta = pi/4` exactly (Pythagorean normals and radical ones
//! `(a, b, sqrt(a^2 + b^2))`), circles (`a = b = 0`), `c = 0`, planes through the apex
//! (`d = 0`), normals with `a + b + c = 0` (a middle weight zero) and normals with radical
//! entries (`q + q' sqrt k`). Every draw comes from the workspace's seeded [`Rng`], so a seed
//! gives the same planes on every run.

use crate::{Radical, Rational};
use exactcheck_core::ruled::Plane;
use exactcheck_core::{Ring, Rng};

/// A generator of random planes, each aimed at a boundary of the section types.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum PlaneKind {
    /// Small rational `a, b, c, d`.
    Generic,
    /// `theta = pi/4` with a Pythagorean normal `k (m^2 - n^2, 2mn, +-(m^2 + n^2))` (coordinates
    /// shuffled between `a` and `b`).
    Pythagorean,
    /// `theta = pi/4` with a radical `c = +-sqrt(a^2 + b^2)`.
    RadicalQuarter,
    /// `a = b = 0`.
    Circle,
    /// `c = 0`.
    Vertical,
    /// `a + b + c = 0`: both pieces have `w1 = 0`.
    ZeroMiddleWeight,
    /// Normal entries `q + q' sqrt k`, `k` in 2, 3, 5.
    RadicalNormal,
}

impl PlaneKind {
    /// Every generator.
    pub const ALL: [PlaneKind; 7] = [
        PlaneKind::Generic,
        PlaneKind::Pythagorean,
        PlaneKind::RadicalQuarter,
        PlaneKind::Circle,
        PlaneKind::Vertical,
        PlaneKind::ZeroMiddleWeight,
        PlaneKind::RadicalNormal,
    ];

    /// A short name for the evidence.
    pub fn name(self) -> &'static str {
        match self {
            PlaneKind::Generic => "generic",
            PlaneKind::Pythagorean => "theta=pi/4 Pythagorean",
            PlaneKind::RadicalQuarter => "theta=pi/4 radical",
            PlaneKind::Circle => "a=b=0",
            PlaneKind::Vertical => "c=0",
            PlaneKind::ZeroMiddleWeight => "a+b+c=0 (w1=0)",
            PlaneKind::RadicalNormal => "radical normal",
        }
    }
}

fn small_rational(rng: &mut Rng) -> Rational {
    let n = rng.below(19) as i64 - 9;
    let d = rng.below(5) as i64 + 1;
    Rational::new(n, d).expect("d >= 1")
}

fn nonzero_rational(rng: &mut Rng) -> Rational {
    loop {
        let q = small_rational(rng);
        if !q.is_zero() {
            return q;
        }
    }
}

/// A random plane of the given kind (through the apex when `through_apex`, otherwise with a
/// non-zero `d`); the normal is never zero.
pub fn random_plane(rng: &mut Rng, kind: PlaneKind, through_apex: bool) -> Plane<Radical> {
    let q = |rng: &mut Rng| Radical::from(small_rational(rng));
    let nz = |rng: &mut Rng| Radical::from(nonzero_rational(rng));
    let sign = |rng: &mut Rng, x: Radical| if rng.below(2) == 0 { x } else { x.neg_ref() };
    let (a, b, c) = match kind {
        PlaneKind::Generic => loop {
            let (a, b, c) = (q(rng), q(rng), q(rng));
            if !(a.is_zero() && b.is_zero() && c.is_zero()) {
                break (a, b, c);
            }
        },
        PlaneKind::Pythagorean => {
            let m = rng.below(6) as i64 + 1;
            let n = rng.below(m as u64) as i64; // 0 <= n < m
            let k = nz(rng);
            let (x, y, h) = (m * m - n * n, 2 * m * n, m * m + n * n);
            let (x, y) = if rng.below(2) == 0 { (x, y) } else { (y, x) };
            let s = |rng: &mut Rng, v: i64| sign(rng, k.mul_ref(&Radical::from(v)));
            (s(rng, x), s(rng, y), s(rng, h))
        }
        PlaneKind::RadicalQuarter => {
            let (a, b) = loop {
                let (a, b) = (small_rational(rng), small_rational(rng));
                if !(a.is_zero() && b.is_zero()) {
                    break (a, b);
                }
            };
            let c = Radical::sqrt_rational(&a.mul_ref(&a).add_ref(&b.mul_ref(&b)))
                .expect("a^2 + b^2 >= 0 has a real square root");
            (Radical::from(a), Radical::from(b), sign(rng, c))
        }
        PlaneKind::Circle => (Radical::zero(), Radical::zero(), nz(rng)),
        PlaneKind::Vertical => loop {
            let (a, b) = (q(rng), q(rng));
            if !(a.is_zero() && b.is_zero()) {
                break (a, b, Radical::zero());
            }
        },
        PlaneKind::ZeroMiddleWeight => loop {
            let (a, b) = (q(rng), q(rng));
            let c = a.add_ref(&b).neg_ref();
            if !(a.is_zero() && b.is_zero()) {
                break (a, b, c);
            }
        },
        PlaneKind::RadicalNormal => loop {
            let entry = |rng: &mut Rng| {
                let k = [2u64, 3, 5][rng.below(3) as usize];
                q(rng).add_ref(&Radical::sqrt_of(k).scale(&small_rational(rng)))
            };
            let (a, b, c) = (entry(rng), entry(rng), entry(rng));
            if !(a.is_zero() && b.is_zero() && c.is_zero()) {
                break (a, b, c);
            }
        },
    };
    let d = if through_apex {
        Radical::zero()
    } else {
        nz(rng)
    };
    Plane::new(a, b, c, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_gives_a_nonzero_normal_and_its_boundary() {
        let mut rng = Rng::new(11);
        for kind in PlaneKind::ALL {
            for through_apex in [false, true] {
                for _ in 0..50 {
                    let p = random_plane(&mut rng, kind, through_apex);
                    let n = &p.normal;
                    assert!(!n.is_zero(), "{kind:?}");
                    assert_eq!(p.d.is_zero(), through_apex, "{kind:?}");
                    let (a, b, c) = (&n.x, &n.y, &n.z);
                    let quarter = c.mul_ref(c) == a.mul_ref(a).add_ref(&b.mul_ref(b));
                    match kind {
                        PlaneKind::Pythagorean | PlaneKind::RadicalQuarter => assert!(quarter),
                        PlaneKind::Circle => assert!(a.is_zero() && b.is_zero()),
                        PlaneKind::Vertical => assert!(c.is_zero()),
                        PlaneKind::ZeroMiddleWeight => {
                            assert!(a.add_ref(b).add_ref(c).is_zero());
                        }
                        PlaneKind::Generic | PlaneKind::RadicalNormal => {}
                    }
                }
            }
        }
    }

    #[test]
    fn a_seed_gives_the_same_planes() {
        let draw = |seed| {
            let mut rng = Rng::new(seed);
            (0..20)
                .map(|i| random_plane(&mut rng, PlaneKind::ALL[i % 7], i % 2 == 0))
                .collect::<Vec<_>>()
        };
        assert_eq!(draw(5), draw(5));
    }
}
