//! The small-height points of the counter-example search: the rationals by increasing height
//! and the tuples of them, ordered so that the first counter-example found is a simple one.

use super::VarDomain;
use crate::{Radical, Rational};
use exactcheck_core::{Ring, Rng};

/// The largest height of the small-height values of one variable.
const SMALL_HEIGHT: i64 = 12;

/// The most small-height values of one variable (those in its domain, by increasing height).
const SMALL_VALUES: usize = 24;

/// The rationals `n/d` of height `max(|n|, d)` at most `max_height`, in the order of the
/// counter-example search: by height, the non-negative ones first, then by absolute value
/// (`0, 1, -1, 1/2, 2, -1/2, -2, 1/3, 2/3, 3/2, 3, ...`).
pub fn small_height_rationals(max_height: i64) -> Vec<Rational> {
    // (height, negative, |q|) and the sign applied after sorting.
    let mut out: Vec<(i64, bool, Rational)> = Vec::new();
    for h in 1..=max_height {
        for d in 1..=h {
            for n in 0..=h {
                if n.max(d) != h || num_integer::gcd(n, d) != 1 {
                    continue;
                }
                let q = Rational::new(n, d).expect("d >= 1");
                if n > 0 {
                    out.push((h, true, q.clone()));
                }
                out.push((h, false, q));
            }
        }
    }
    out.sort();
    out.into_iter()
        .map(|(_, negative, q)| if negative { q.neg_ref() } else { q })
        .collect()
}

/// The points of the small-height phase of the search, at most `budget` of them: each active
/// variable runs through the first [`SMALL_VALUES`] small-height rationals of its domain (an
/// inactive one keeps its first), the tuples of positions ordered by their largest position, then
/// by their sum, then lexicographically. A variable whose domain holds no rational of height up
/// to [`SMALL_HEIGHT`] takes the domain's own samples (seeded).
pub(super) fn small_points(
    dom: &[VarDomain],
    active: &[bool],
    budget: usize,
) -> Vec<Vec<Rational>> {
    let heights = small_height_rationals(SMALL_HEIGHT);
    let mut rng = Rng::new(0x5EED_0002);
    let lists: Vec<Vec<Rational>> = dom
        .iter()
        .enumerate()
        .map(|(v, d)| {
            let mut l: Vec<Rational> = heights
                .iter()
                .filter(|q| d.contains(&Radical::from(*q)))
                .take(if active[v] { SMALL_VALUES } else { 1 })
                .cloned()
                .collect();
            if l.is_empty() {
                let k = if active[v] { SMALL_VALUES } else { 1 };
                for _ in 0..k {
                    let x = d.sample(&mut rng);
                    if !l.contains(&x) {
                        l.push(x);
                    }
                }
            }
            l
        })
        .collect();
    let lens: Vec<usize> = lists.iter().map(Vec::len).collect();
    let mut out = Vec::new();
    let top = lens.iter().copied().max().unwrap_or(1).max(1) - 1;
    let n = lens.len();
    'levels: for level in 0..=top {
        for sum in level..=level * n.max(1) {
            let mut tuple = vec![0usize; n];
            tuples(&lens, level, sum, 0, &mut tuple, &mut |t| {
                if out.len() < budget {
                    out.push(t.iter().zip(&lists).map(|(&i, l)| l[i].clone()).collect());
                }
                out.len() < budget
            });
            if out.len() >= budget {
                break 'levels;
            }
        }
    }
    out
}

/// Calls `emit` with every tuple `t` (`t[i] < lens[i]`, `t[i] <= level`) of largest entry
/// `level` and entry sum `sum`, positions `from..` still free, in lexicographic order; stops when
/// `emit` answers `false` (and answers `false` then).
fn tuples(
    lens: &[usize],
    level: usize,
    sum: usize,
    from: usize,
    t: &mut Vec<usize>,
    emit: &mut dyn FnMut(&[usize]) -> bool,
) -> bool {
    if from == lens.len() {
        if sum == 0 && (t.is_empty() || t.contains(&level)) {
            return emit(t);
        }
        return true;
    }
    let room: usize = lens[from + 1..]
        .iter()
        .map(|&l| l.min(level + 1).saturating_sub(1))
        .sum();
    let hi = (lens[from].min(level + 1)).saturating_sub(1).min(sum);
    for x in 0..=hi {
        if sum - x > room {
            continue;
        }
        t[from] = x;
        if !tuples(lens, level, sum - x, from + 1, t, emit) {
            return false;
        }
    }
    t[from] = 0;
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_heights_are_ordered_by_height() {
        let r = |n: i64, d: i64| Rational::new(n, d).unwrap();
        let q = small_height_rationals(3);
        assert_eq!(
            q[..7],
            [
                r(0, 1),
                r(1, 1),
                r(-1, 1),
                r(1, 2),
                r(2, 1),
                r(-1, 2),
                r(-2, 1)
            ]
        );
        // Every rational of height at most 3 once: 0, +-1, +-1/2, +-2, +-1/3, +-2/3, +-3/2, +-3.
        assert_eq!(q.len(), 15);
        let mut sorted = q.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), 15);
    }
}
