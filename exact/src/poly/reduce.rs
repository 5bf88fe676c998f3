//! Normal forms: the closed-form reduction modulo unit-circle relations, multivariate division
//! by a list of relations, and reduced Gröbner bases by Buchberger's algorithm.

use super::*;
use exactcheck_core::{Field, Ring};
use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};

impl<C: Ring> Poly<C> {
    /// The normal form modulo the unit-circle relations `c^2 + s^2 - 1` of the pairs `(c, s)`:
    /// every `s^2` is rewritten as `1 - c^2`, so that no term keeps an `s` exponent above 1.
    ///
    /// This is the normal form with respect to any monomial order in which `s^2 > c^2` for every
    /// pair (in this crate's order: `s > c`, i.e. `s` declared after `c`); the relations of
    /// independent pairs always form a Gröbner basis, so an identity holds for all angles iff
    /// the normal form of its residual is zero. Needs no division: any coefficient ring.
    ///
    /// # Panics
    /// When a variable occurs in two pairs, or `c == s` in a pair.
    pub fn reduce_unit_circle(&self, pairs: &[(Var, Var)]) -> Poly<C> {
        let mut seen = std::collections::HashSet::new();
        for &(c, s) in pairs {
            assert!(
                c != s && seen.insert(c) && seen.insert(s),
                "reduce_unit_circle: the pairs (cos, sin) must use distinct variables"
            );
        }
        let pairs: Vec<(usize, usize)> = pairs
            .iter()
            .map(|&(c, s)| (c as usize, s as usize))
            .collect();
        // Nothing to do unless some term has s^2.
        let reducible = |m: &[u64], sh: Shape| pairs.iter().any(|&(_, s)| sh.get(m, s) >= 2);
        if !(0..self.len()).any(|i| reducible(self.mono(i), self.shape)) {
            return self.clone();
        }
        // Room for c and for exponents up to e_c + e_s.
        let nv = pairs.iter().map(|&(c, s)| c.max(s) + 1).max().unwrap_or(0);
        let need = self.exp_bound().saturating_mul(2);
        let bits = bits_for(need.min(MAX_EXP)).unwrap_or(64);
        let shape = self.widened_shape(bits, nv);
        let exps = self.exps_in(shape);
        let mono = |i: usize| &exps[i * shape.words..(i + 1) * shape.words];
        // (1 - c^2)^h = sum_k binom(h, k) (-1)^k c^(2k): signed Pascal rows in C.
        let hmax = (0..self.len())
            .flat_map(|i| pairs.iter().map(move |&(_, s)| shape.get(mono(i), s) / 2))
            .max()
            .unwrap_or(0) as usize;
        let mut rows: Vec<Vec<C>> = vec![vec![C::one()]];
        for h in 1..=hmax {
            let prev = &rows[h - 1];
            let row: Vec<C> = (0..=h)
                .map(|k| {
                    // signed: r[h][k] = r[h-1][k] - r[h-1][k-1]
                    let a = prev.get(k).cloned().unwrap_or_else(C::zero);
                    match k.checked_sub(1).and_then(|j| prev.get(j)) {
                        Some(b) => a - b,
                        None => a,
                    }
                })
                .collect();
            rows.push(row);
        }
        let mut out_e: Vec<u64> = Vec::with_capacity(exps.len() * 2);
        let mut out_c: Vec<C> = Vec::with_capacity(self.len() * 2);
        let mut base = vec![0u64; shape.words];
        let mut hs: Vec<(usize, usize, usize)> = Vec::new(); // (c, h, k)
        for i in 0..self.len() {
            let m = mono(i);
            base.copy_from_slice(m);
            hs.clear();
            for &(c, s) in &pairs {
                let e = shape.get(m, s);
                if e >= 2 {
                    shape.set(&mut base, s, e & 1);
                    hs.push((c, (e / 2) as usize, 0));
                }
            }
            if hs.is_empty() {
                out_e.extend_from_slice(m);
                out_c.push(self.coeffs[i].clone());
                continue;
            }
            // Enumerate k_j in 0..=h_j for every rewritten pair (odometer).
            loop {
                let start = out_e.len();
                out_e.extend_from_slice(&base);
                let mut coeff = self.coeffs[i].clone();
                for &(c, h, k) in &hs {
                    shape.add(&mut out_e[start..], c, 2 * k as u64);
                    coeff *= &rows[h][k];
                }
                out_c.push(coeff);
                let mut j = 0;
                while j < hs.len() {
                    if hs[j].2 < hs[j].1 {
                        hs[j].2 += 1;
                        break;
                    }
                    hs[j].2 = 0;
                    j += 1;
                }
                if j == hs.len() {
                    break;
                }
            }
        }
        Poly::from_unsorted(shape, out_e, out_c)
    }
}

// ------------------------------------------------------------------------------ normal forms

/// The relation `c^2 + s^2 - 1` of an angle given by its cosine `c` and sine `s`.
///
/// In this crate's order its leading monomial is the square of the higher variable: declare the
/// cosine first (`c < s`) and reduction rewrites `s^2 -> 1 - c^2`. Relations of independent
/// pairs form a Gröbner basis; [`Poly::reduce`] recognises them and uses the closed form of
/// [`Poly::reduce_unit_circle`].
pub fn unit_circle_relation<C: Ring>(c: Var, s: Var) -> Poly<C> {
    Poly::from_terms([
        (vec![(c, 2)], C::one()),
        (vec![(s, 2)], C::one()),
        (vec![], -C::one()),
    ])
}

/// Exponents overflowed the current field width during a division: retry wider.
pub(super) struct Overflow;

/// A rewriting rule `lm -> tail` from a monic relation `lm - tail`.
pub(super) struct Rule<C> {
    pub(super) lm: Vec<u64>,
    pub(super) tail_e: Vec<u64>,
    pub(super) tail_c: Vec<C>,
}

/// A monomial key ordered by the monomial order (for `BinaryHeap`).
#[derive(PartialEq, Eq)]
pub(super) struct Key(Box<[u64]>);

impl Ord for Key {
    fn cmp(&self, other: &Self) -> Ordering {
        cmp_mono(&self.0, &other.0)
    }
}

impl PartialOrd for Key {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<C: Field> Poly<C> {
    /// The polynomial divided by its leading coefficient (zero stays zero).
    pub fn make_monic(&self) -> Poly<C> {
        match self.coeffs.first() {
            None => Poly::zero(),
            Some(lc) if lc.is_one() => self.clone(),
            Some(lc) => match lc.inv() {
                Ok(inv) => self.scale(&inv),
                // A field has no non-zero zero divisors; keep the polynomial as it is.
                Err(_) => self.clone(),
            },
        }
    }

    /// The remainder of `self` on multivariate division by `relations`, in the monomial order of
    /// the module documentation (lex, higher variable index larger): no term of the result is
    /// divisible by the leading monomial of a relation. At each step the first relation (in the
    /// given order) whose leading monomial divides the current term is used.
    ///
    /// Against a Gröbner basis (from [`groebner`]) the remainder is the **canonical normal form**
    /// of `self` modulo the ideal of the relations: a polynomial identity holds on the variety
    /// of the relations (more exactly, modulo their ideal) iff the normal form of its residual is
    /// zero. Against other relation sets it is only *a* remainder. Independent unit-circle
    /// relations ([`unit_circle_relation`]) are recognised and reduced in closed form.
    ///
    /// # Panics
    /// When an exponent would exceed `u32::MAX`.
    pub fn reduce(&self, relations: &[Poly<C>]) -> Poly<C> {
        let rels: Vec<&Poly<C>> = relations.iter().filter(|g| !g.is_empty()).collect();
        if rels.is_empty() || self.is_empty() {
            return self.clone();
        }
        if rels.iter().any(|g| g.is_constant()) {
            return Poly::zero();
        }
        if let Some(pairs) = unit_circle_pairs(&rels) {
            return self.reduce_unit_circle(&pairs);
        }
        let mut bits = rels
            .iter()
            .map(|g| g.shape.bits)
            .fold(self.shape.bits, u32::max);
        loop {
            let nv = rels
                .iter()
                .map(|g| g.nvars_used())
                .fold(self.nvars_used(), usize::max);
            let shape = Shape {
                bits,
                words: Shape::words_for(bits, nv),
            };
            match divide(self, &rels, shape) {
                Ok(r) => return r,
                Err(Overflow) => {
                    bits *= 2;
                    assert!(bits <= 64, "exponent overflow: above u32::MAX");
                }
            }
        }
    }
}

/// The pairs `(c, s)` (with `s` the leading variable) if every relation is a multiple of
/// `c^2 + s^2 - 1` and the pairs are independent.
pub(super) fn unit_circle_pairs<C: Ring>(rels: &[&Poly<C>]) -> Option<Vec<(Var, Var)>> {
    let mut pairs = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for g in rels {
        if g.len() != 3 {
            return None;
        }
        let t: Vec<Vec<(Var, u32)>> = g.terms().map(|(m, _)| m.exponents()).collect();
        let (s, c) = match (&t[0][..], &t[1][..], &t[2][..]) {
            ([(s, 2)], [(c, 2)], []) => (*s, *c),
            _ => return None,
        };
        let k = &g.coeffs;
        if k[0] != k[1] || k[2] != k[0].neg_ref() || !seen.insert(s) || !seen.insert(c) {
            return None;
        }
        pairs.push((c, s));
    }
    Some(pairs)
}

/// Division with a heap of pending monomials (all in `shape`): every monomial leaves the heap
/// once, with its final coefficient, because rewriting only produces smaller monomials.
pub(super) fn divide<C: Field>(
    f: &Poly<C>,
    rels: &[&Poly<C>],
    shape: Shape,
) -> Result<Poly<C>, Overflow> {
    let w = shape.words;
    let guard = shape.guard();
    let rules: Vec<Rule<C>> = rels
        .iter()
        .map(|g| {
            let g = g.make_monic();
            let e = g.exps_in(shape).into_owned();
            Rule {
                lm: e[..w].to_vec(),
                tail_e: e[w..].to_vec(),
                tail_c: g.coeffs[1..].iter().map(Ring::neg_ref).collect(),
            }
        })
        .collect();
    let fe = f.exps_in(shape);
    let mut pending: HashMap<Box<[u64]>, C> = HashMap::with_capacity(f.len() * 2);
    let mut heap: BinaryHeap<Key> = BinaryHeap::with_capacity(f.len() * 2);
    for (i, c) in f.coeffs.iter().enumerate() {
        let m: Box<[u64]> = fe[i * w..(i + 1) * w].into();
        pending.insert(m.clone(), c.clone());
        heap.push(Key(m));
    }
    let mut out_e = Vec::new();
    let mut out_c = Vec::new();
    let mut u = vec![0u64; w];
    let mut nm = vec![0u64; w];
    while let Some(Key(m)) = heap.pop() {
        let Some(c) = pending.remove(&m) else {
            continue;
        };
        if c.is_zero() {
            continue;
        }
        match rules.iter().find(|r| divides(&r.lm, &m, guard)) {
            None => {
                out_e.extend_from_slice(&m);
                out_c.push(c);
            }
            Some(r) => {
                for k in 0..w {
                    u[k] = m[k] - r.lm[k];
                }
                for (t, d) in r.tail_c.iter().enumerate() {
                    add_mono(&mut nm, &u, &r.tail_e[t * w..(t + 1) * w]);
                    if nm.iter().any(|x| x & guard != 0) {
                        return Err(Overflow);
                    }
                    let v = c.mul_ref(d);
                    match pending.get_mut(&nm[..]) {
                        Some(acc) => *acc += v,
                        None => {
                            let key: Box<[u64]> = nm.as_slice().into();
                            pending.insert(key.clone(), v);
                            heap.push(Key(key));
                        }
                    }
                }
            }
        }
    }
    Ok(Poly {
        shape,
        exps: out_e,
        coeffs: out_c,
    })
}

/// The least common multiple of two monomials (exponent lists).
pub(super) fn lcm_exponents(a: &[(Var, u32)], b: &[(Var, u32)]) -> Vec<(Var, u32)> {
    let mut m: std::collections::BTreeMap<Var, u32> = a.iter().copied().collect();
    for &(v, e) in b {
        let x = m.entry(v).or_insert(0);
        *x = (*x).max(e);
    }
    m.into_iter().collect()
}

/// `num / den` for monomials (exponent lists) with `den | num`.
pub(super) fn quotient_exponents(num: &[(Var, u32)], den: &[(Var, u32)]) -> Vec<(Var, u32)> {
    let d: HashMap<Var, u32> = den.iter().copied().collect();
    num.iter()
        .map(|&(v, e)| (v, e - d.get(&v).copied().unwrap_or(0)))
        .filter(|&(_, e)| e > 0)
        .collect()
}

/// Whether monomial `d` divides `m` (exponent lists).
pub(super) fn divides_exponents(d: &[(Var, u32)], m: &[(Var, u32)]) -> bool {
    let mm: HashMap<Var, u32> = m.iter().copied().collect();
    d.iter().all(|(v, e)| mm.get(v).is_some_and(|x| x >= e))
}

/// The reduced Gröbner basis of the ideal generated by `relations`, in the monomial order of the
/// module documentation (lex, higher variable index larger), by Buchberger's algorithm.
///
/// The result is monic, inter-reduced and sorted by increasing leading monomial; it is unique
/// for the ideal, and [`Poly::reduce`] against it is a canonical normal form. `[1]` means the
/// relations are inconsistent; the empty list means they are all zero. Meant for a handful of
/// small relations (lex bases can grow quickly).
///
/// # Panics
/// When an exponent would exceed `u32::MAX`.
pub fn groebner<C: Field>(relations: &[Poly<C>]) -> Vec<Poly<C>> {
    let mut g: Vec<Poly<C>> = relations
        .iter()
        .filter(|p| !p.is_empty())
        .map(Poly::make_monic)
        .collect();
    if g.iter().any(Poly::is_constant) {
        return vec![Poly::one()];
    }
    let lm = |p: &Poly<C>| {
        p.leading_term()
            .map(|(m, _)| m.exponents())
            .unwrap_or_default()
    };
    let mut lms: Vec<Vec<(Var, u32)>> = g.iter().map(lm).collect();
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    for j in 0..g.len() {
        for i in 0..j {
            pairs.push((i, j));
        }
    }
    while !pairs.is_empty() {
        // Normal strategy: the pair with the smallest lcm (total degree, then the order).
        let keyed: Vec<(u64, Poly<C>)> = pairs
            .iter()
            .map(|&(i, j)| {
                let l = lcm_exponents(&lms[i], &lms[j]);
                let deg = l.iter().map(|&(_, e)| e as u64).sum();
                (deg, Poly::<C>::monomial(C::one(), &l))
            })
            .collect();
        let best = (0..pairs.len())
            .min_by(|&a, &b| {
                let ((da, ma), (db, mb)) = (&keyed[a], &keyed[b]);
                da.cmp(db).then_with(|| {
                    let s = ma.common_shape(mb);
                    cmp_mono(&ma.exps_in(s), &mb.exps_in(s))
                })
            })
            .unwrap_or(0);
        let (i, j) = pairs.swap_remove(best);
        let l = lcm_exponents(&lms[i], &lms[j]);
        // Criterion 1: coprime leading monomials reduce to zero.
        let deg_l: u32 = l.iter().map(|p| p.1).sum();
        let deg_sum: u32 = lms[i].iter().chain(&lms[j]).map(|p| p.1).sum();
        if deg_l == deg_sum {
            continue;
        }
        // Criterion 2 (chain): some g_k with lm(g_k) | lcm whose pairs with i and j are done.
        let chain = (0..g.len()).any(|k| {
            k != i
                && k != j
                && divides_exponents(&lms[k], &l)
                && !pairs.contains(&(i.min(k), i.max(k)))
                && !pairs.contains(&(j.min(k), j.max(k)))
        });
        if chain {
            continue;
        }
        let si = Poly::monomial(C::one(), &quotient_exponents(&l, &lms[i]));
        let sj = Poly::monomial(C::one(), &quotient_exponents(&l, &lms[j]));
        let s = si * &g[i] - sj * &g[j];
        let r = s.reduce(&g).make_monic();
        if r.is_empty() {
            continue;
        }
        if r.is_constant() {
            return vec![Poly::one()];
        }
        let k = g.len();
        lms.push(lm(&r));
        g.push(r);
        for i in 0..k {
            pairs.push((i, k));
        }
    }
    // Minimal basis: drop elements whose leading monomial another one divides (of equal ones,
    // keep the first).
    let mut keep: Vec<usize> = Vec::new();
    for i in 0..g.len() {
        let redundant = (0..g.len())
            .any(|j| j != i && divides_exponents(&lms[j], &lms[i]) && (lms[j] != lms[i] || j < i));
        if !redundant {
            keep.push(i);
        }
    }
    let mut basis: Vec<Poly<C>> = keep.iter().map(|&i| g[i].clone()).collect();
    // Inter-reduce: every element reduced by the others (leading terms stay).
    for i in 0..basis.len() {
        let others: Vec<Poly<C>> = basis
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, p)| p.clone())
            .collect();
        basis[i] = basis[i].reduce(&others).make_monic();
    }
    basis.sort_by(|a, b| {
        let (ma, mb) = (a.leading_monomial_poly(), b.leading_monomial_poly());
        let s = ma.common_shape(&mb);
        cmp_mono(&ma.exps_in(s), &mb.exps_in(s))
    });
    basis
}

impl<C: Ring> Poly<C> {
    /// The leading monomial as a polynomial with coefficient one (zero for zero).
    pub(super) fn leading_monomial_poly(&self) -> Poly<C> {
        match self.leading_term() {
            None => Poly::zero(),
            Some(_) => Poly {
                shape: self.shape,
                exps: self.mono(0).to_vec(),
                coeffs: vec![C::one()],
            },
        }
    }
}
