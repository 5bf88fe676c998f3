//! Normal forms: the closed-form reduction modulo unit-circle relations, multivariate division
//! by a list of relations, and reduced Gröbner bases by Buchberger's algorithm.

use super::*;
use crate::coefficient::Coefficient;
use exactcheck_core::limits::{self, LimitError};
use exactcheck_core::{Field, Ring};
use num_bigint::BigUint;
use num_traits::One;
use std::cmp::Ordering;
use std::collections::{BTreeSet, BinaryHeap, HashMap, HashSet};

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
        self.reduce_unit_circle_within(pairs, u64::MAX)
            .expect("no bound on the number of terms")
    }

    /// [`Poly::reduce_unit_circle`] for polynomials from the input: the number of terms of the
    /// result, before like terms merge (`sum over the terms of prod_j (e_j / 2 + 1)` for the
    /// exponents `e_j` of the sines), is predicted first and checked against
    /// [`limits::TERMS`], so `s1^10000 s2^10000 s3^10000` is refused before anything is
    /// allocated.
    ///
    /// # Errors
    /// A [`LimitError`] naming the `terms` limit.
    ///
    /// # Panics
    /// As [`Poly::reduce_unit_circle`].
    pub fn try_reduce_unit_circle(&self, pairs: &[(Var, Var)]) -> Result<Poly<C>, LimitError> {
        self.reduce_unit_circle_within(pairs, limits::TERMS.get())
    }

    fn reduce_unit_circle_within(
        &self,
        pairs: &[(Var, Var)],
        max_terms: u64,
    ) -> Result<Poly<C>, LimitError> {
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
            return Ok(self.clone());
        }
        // The size of the result before merging, predicted before any work.
        let mut predicted: u64 = 0;
        for i in 0..self.len() {
            let m = self.mono(i);
            let n = pairs
                .iter()
                .map(|&(_, s)| self.shape.get(m, s) / 2 + 1)
                .fold(1u64, u64::saturating_mul);
            predicted = predicted.saturating_add(n);
            if predicted > max_terms {
                return Err(limits::TERMS.exceeded(format!("more than {max_terms}")));
            }
        }
        // Room for c and for exponents up to e_c + e_s.
        let nv = pairs.iter().map(|&(c, s)| c.max(s) + 1).max().unwrap_or(0);
        let need = self.exp_bound().saturating_mul(2);
        let bits = bits_for(need.min(MAX_EXP)).unwrap_or(64);
        let shape = self.widened_shape(bits, nv);
        let exps = self.exps_in(shape);
        let mono = |i: usize| &exps[i * shape.words..(i + 1) * shape.words];
        // (1 - c^2)^h = sum_k binom(h, k) (-1)^k c^(2k): the signed binomial rows, only for the
        // h that occur (building every row up to the largest h took 3.2 GB for s^10000).
        let mut rows: HashMap<usize, Vec<C>> = HashMap::new();
        for i in 0..self.len() {
            for &(_, s) in &pairs {
                let h = (shape.get(mono(i), s) / 2) as usize;
                if h > 0 {
                    rows.entry(h).or_insert_with(|| signed_binomial_row(h));
                }
            }
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
                    coeff *= &rows[&h][k];
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
        Ok(Poly::from_unsorted(shape, out_e, out_c))
    }
}

/// `binom(h, k) (-1)^k` for `k = 0..=h`, in any ring: each binomial by the multiplicative
/// formula in big integers (`O(h)` small multiplications and exact divisions), then mapped into
/// the ring by [`ring_from_biguint`].
fn signed_binomial_row<C: Ring>(h: usize) -> Vec<C> {
    let mut b = BigUint::one();
    let mut row = Vec::with_capacity(h + 1);
    for k in 0..=h {
        let c: C = ring_from_biguint(&b);
        row.push(if k % 2 == 1 { -c } else { c });
        b = b * BigUint::from(h - k) / BigUint::from(k + 1);
    }
    row
}

/// The image of a non-negative integer in a ring, by binary splitting on its base-2^32 digits
/// (`n = hi 2^(32 m) + lo`), so that the cost is a few ring products of balanced sizes rather
/// than one small step per digit.
fn ring_from_biguint<C: Ring>(n: &BigUint) -> C {
    let digits: Vec<u32> = n.iter_u32_digits().collect();
    fn rec<C: Ring>(d: &[u32]) -> C {
        match d {
            [] => C::zero(),
            [x] => C::from_i64(i64::from(*x)),
            _ => {
                let m = d.len() / 2;
                let (lo, hi) = d.split_at(m);
                // 2^(32 m) by binary powering of 2^32.
                let mut p = C::one();
                let mut base = C::from_i64(1 << 32);
                let mut e = m;
                while e > 0 {
                    if e & 1 == 1 {
                        p = p.mul_ref(&base);
                    }
                    e >>= 1;
                    if e > 0 {
                        base = base.square();
                    }
                }
                rec::<C>(hi).mul_ref(&p).add_ref(&rec::<C>(lo))
            }
        }
    }
    rec(&digits)
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

/// A pending S-pair `(i, j)`, `i < j`, ranked for the normal selection strategy: the smallest
/// lcm of the leading monomials first (total degree, then the monomial order), ties by the
/// indices (so the order is total and the run deterministic).
#[derive(PartialEq, Eq, PartialOrd, Ord)]
struct PairKey {
    degree: u64,
    /// One more than the highest variable of the lcm (a higher variable makes a larger
    /// monomial), so that the vectors compared next have the same length.
    top: usize,
    /// The exponents of the lcm, highest variable first: for equal `top`, the lexicographic
    /// order of these vectors is the monomial order of the module documentation.
    lcm_desc: Vec<u32>,
    i: usize,
    j: usize,
}

impl PairKey {
    fn new(lms: &[Vec<(Var, u32)>], i: usize, j: usize) -> PairKey {
        let l = lcm_exponents(&lms[i], &lms[j]);
        let nv = l.iter().map(|&(v, _)| v as usize + 1).max().unwrap_or(0);
        let mut lcm_desc = vec![0u32; nv];
        for &(v, e) in &l {
            lcm_desc[nv - 1 - v as usize] = e;
        }
        PairKey {
            degree: l.iter().map(|&(_, e)| u64::from(e)).sum(),
            top: nv,
            lcm_desc,
            i,
            j,
        }
    }
}

/// The reduced Gröbner basis of the ideal generated by `relations`, in the monomial order of the
/// module documentation (lex, higher variable index larger), by Buchberger's algorithm with the
/// normal selection strategy and Buchberger's two criteria.
///
/// The result is monic, inter-reduced and sorted by increasing leading monomial; it is unique
/// for the ideal, and [`Poly::reduce`] against it is a canonical normal form. `[1]` means the
/// relations are inconsistent; the empty list means they are all zero. Meant for a handful of
/// small relations: lex bases can grow doubly exponentially, in the number of elements and in
/// the size of their coefficients (three dense cubics in x, y, z reach coefficients of 200,000
/// digits within 42 steps, each step slower than the last), so the run is bounded by three
/// named limits: [`limits::GROEBNER_STEPS`] (S-polynomials reduced, checked before each),
/// [`limits::GROEBNER_BASIS`] (elements of the basis, checked before one is added) and
/// [`limits::GROEBNER_BITS`] (the size [`Coefficient::size_bits`] of every coefficient of a new
/// element: the cost of the next reductions grows with it).
///
/// The pending pairs are kept in a priority queue (a `BTreeSet` ordered by `PairKey`), so
/// selecting the next pair costs `O(log n)`: ranking every pair at every step made 200 linear
/// relations take more than 20 s.
///
/// # Errors
/// A [`LimitError`] when the computation would exceed one of the two limits.
///
/// # Panics
/// When an exponent would exceed `u32::MAX`.
pub fn groebner<C: Field + Coefficient>(relations: &[Poly<C>]) -> Result<Vec<Poly<C>>, LimitError> {
    let mut g: Vec<Poly<C>> = relations
        .iter()
        .filter(|p| !p.is_empty())
        .map(Poly::make_monic)
        .collect();
    if g.iter().any(Poly::is_constant) {
        return Ok(vec![Poly::one()]);
    }
    limits::GROEBNER_BASIS.check_usize(g.len())?;
    let lm = |p: &Poly<C>| {
        p.leading_term()
            .map(|(m, _)| m.exponents())
            .unwrap_or_default()
    };
    let mut lms: Vec<Vec<(Var, u32)>> = g.iter().map(lm).collect();
    let mut queue: BTreeSet<PairKey> = BTreeSet::new();
    let mut pending: HashSet<(usize, usize)> = HashSet::new();
    for j in 0..g.len() {
        for i in 0..j {
            queue.insert(PairKey::new(&lms, i, j));
            pending.insert((i, j));
        }
    }
    let mut steps: u64 = 0;
    while let Some(PairKey { i, j, .. }) = queue.pop_first() {
        pending.remove(&(i, j));
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
                && !pending.contains(&(i.min(k), i.max(k)))
                && !pending.contains(&(j.min(k), j.max(k)))
        });
        if chain {
            continue;
        }
        steps += 1;
        limits::GROEBNER_STEPS.check(steps)?;
        let si = Poly::monomial(C::one(), &quotient_exponents(&l, &lms[i]));
        let sj = Poly::monomial(C::one(), &quotient_exponents(&l, &lms[j]));
        let s = si * &g[i] - sj * &g[j];
        let r = s.reduce(&g).make_monic();
        if let Some(bits) = r.coefficients().iter().map(C::size_bits).max() {
            limits::GROEBNER_BITS.check(bits)?;
        }
        if r.is_empty() {
            continue;
        }
        if r.is_constant() {
            return Ok(vec![Poly::one()]);
        }
        let k = g.len();
        limits::GROEBNER_BASIS.check_usize(k + 1)?;
        lms.push(lm(&r));
        g.push(r);
        for i in 0..k {
            queue.insert(PairKey::new(&lms, i, k));
            pending.insert((i, k));
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
    Ok(basis)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::poly::Vars;
    use crate::Rational;

    fn polys(texts: &[String], vars: &mut Vars) -> Vec<Poly<Rational>> {
        texts
            .iter()
            .map(|t| parse_poly::<Rational>(t, vars).expect("a polynomial"))
            .collect()
    }

    /// three dense cubics in x, y, z did not finish in 300 s (the coefficients of the
    /// lex basis grow past 200,000 digits); now the coefficient-size limit stops the run.
    #[test]
    fn dense_cubics_stop_on_the_coefficient_limit() {
        let mut vars = Vars::new();
        let rels = polys(&CUBICS.map(String::from), &mut vars);
        let e = groebner(&rels).unwrap_err();
        assert!(std::ptr::eq(e.limit, &limits::GROEBNER_BITS), "{e}");
        assert!(e.to_string().contains("groebner-bits = 10000 bits"), "{e}");
    }

    /// 200 relations `vI = I` took more than 20 s (every pair re-ranked at every
    /// step); with the pair queue they are immediate, and the basis is the relations.
    #[test]
    fn two_hundred_linear_relations() {
        let mut vars = Vars::new();
        let texts: Vec<String> = (0..200).map(|i| format!("v{i} - {i}")).collect();
        let rels = polys(&texts, &mut vars);
        let basis = groebner(&rels).unwrap();
        assert_eq!(basis.len(), 200);
        let sum = polys(
            &[(0..200)
                .map(|i| format!("v{i}"))
                .collect::<Vec<_>>()
                .join(" + ")],
            &mut vars,
        );
        assert_eq!(
            sum[0].reduce(&basis),
            Poly::constant(Rational::from_integer(19_900))
        );
    }

    /// The pair order is the monomial order: a higher variable beats any power of lower ones.
    #[test]
    fn pair_keys_follow_the_monomial_order() {
        let lms = vec![
            vec![(0, 5)],
            vec![(0, 1)],
            vec![(1, 1)],
            vec![(0, 2), (1, 2)],
        ];
        // lcm x0^5 (degree 5) vs lcm x0 x1 (degree 2): the smaller degree first.
        assert!(PairKey::new(&lms, 1, 2) < PairKey::new(&lms, 0, 1));
        let lms = vec![
            vec![(0, 3)],
            vec![(0, 1)],
            vec![(1, 2)],
            vec![(0, 1), (1, 1)],
        ];
        // lcm(x0^3, x0) = x0^3 and lcm(x1^2, x0 x1) = x0 x1^2: both degree 3, x1 is higher.
        assert!(PairKey::new(&lms, 0, 1) < PairKey::new(&lms, 2, 3));
    }

    /// `s^10000` modulo `c^2 + s^2 - 1` built every binomial row up to 5000 (3.2 GB); only the
    /// row used is built now, and the terms limit is checked before the expansion.
    #[test]
    fn high_powers_of_the_sine() {
        let mut vars = Vars::new();
        let c = vars.var("c");
        let s = vars.var("s");
        let p: Poly<Rational> = Poly::var(s).pow(10_000);
        let r = p.try_reduce_unit_circle(&[(c, s)]).unwrap();
        assert_eq!(r.len(), 5001);
        // (1 - c^2)^5000 at c = 0 is 1; the c^2 coefficient is -5000.
        assert_eq!(
            r.terms().last().map(|(_, k)| k.clone()),
            Some(Rational::ONE)
        );
        let three: Vec<String> = (0..3).map(|i| format!("s{i}^10000")).collect();
        let mut pairs = Vec::new();
        for i in 0..3 {
            pairs.push((vars.var(&format!("c{i}")), vars.var(&format!("s{i}"))));
        }
        let q = polys(&[three.join("*")], &mut vars).remove(0);
        let e = q.try_reduce_unit_circle(&pairs).unwrap_err();
        assert!(std::ptr::eq(e.limit, &limits::TERMS), "{e}");
        assert_eq!(
            ring_from_biguint::<Rational>(&(BigUint::one() << 200u32)),
            {
                let two: Rational = Rational::from_integer(2);
                two.pow(200)
            }
        );
    }

    const CUBICS: [&str; 3] = [
        "6 + 7*z + 7*z^2 - 7*z^3 + 9*y + 9*y*z - 5*y*z^2 - 2*y^2 + 6*y^2*z - 2*y^3 + x + 4*x*z - 5*x*z^2 + 4*x*y - 3*x*y*z + x*y^2 + 8*x^2 - 4*x^2*z - 9*x^2*y + 4*x^3",
        "-3 + z + 7*z^2 - 5*z^3 - 9*y - y*z + y*z^2 - 8*y^2 + y^2*z - 4*y^3 - x + 5*x*z + 6*x*z^2 - 7*x*y + 5*x*y*z - 4*x*y^2 + 5*x^2 - 7*x^2*z + 8*x^2*y - 8*x^3",
        "8 - 3*z - 3*z^2 + 9*z^3 - y + y*z - 3*y*z^2 + 3*y^2 - 4*y^2*z - 6*y^3 + 2*x + 9*x*z - 8*x*z^2 - 6*x*y - 7*x*y*z - 7*x*y^2 - 6*x^2 + x^2*z - 2*x^2*y + 5*x^3",
    ];
}
