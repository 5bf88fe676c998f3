//! Exact division of multivariate polynomials ([`div_exact`]) and partial derivatives
//! ([`poly_derivative`]): the steps of the gcd ([`super::gcd`]), of square-free factoring
//! ([`super::factor`]) and of the cancellation of rational functions.

use super::{Poly, Var};
use exactcheck_core::{Field, Ring};

/// The partial derivative of `p` in `v`.
pub fn poly_derivative<C: Ring>(p: &Poly<C>, v: Var) -> Poly<C> {
    Poly::from_terms(p.terms().filter_map(|(m, c)| {
        let e = m.exponent(v);
        (e > 0).then(|| {
            let exps: Vec<(Var, u32)> = m
                .exponents()
                .into_iter()
                .map(|(w, k)| (w, if w == v { k - 1 } else { k }))
                .filter(|&(_, k)| k > 0)
                .collect();
            (exps, c.scale_i64(i64::from(e)))
        })
    }))
}

/// One more than the highest variable index in `a` or `b` (0 when both are constants): the
/// number of variable slots the two need.
pub(crate) fn variable_span<C: Ring>(a: &Poly<C>, b: &Poly<C>) -> usize {
    a.variables()
        .iter()
        .chain(&b.variables())
        .map(|&v| v as usize + 1)
        .max()
        .unwrap_or(0)
}

/// `a / b` when `b` divides `a` exactly (`None` otherwise, or for `b = 0`): division by the
/// leading term in the monomial order until nothing is left. The remainder is kept in an
/// ordered map (exponents from the highest variable down, which is the order of
/// [`crate::poly`]), so each step costs the terms of `b` times a logarithm rather than a pass
/// over the whole remainder.
///
/// The keys of the map are the exponents packed into one `u128` when the degrees of `a` fit
/// (no allocation per term): in an exact division every term met has each exponent at most
/// the degree of `a` in that variable (the degrees of the quotient and of `b` add up to those
/// of `a`), so a quotient term beyond `deg(a) - deg(b)` proves that `b` does not divide `a`.
/// Otherwise the keys are vectors of exponents.
pub fn div_exact<C: Field>(a: &Poly<C>, b: &Poly<C>) -> Option<Poly<C>> {
    let (_, bc) = b.leading_term()?;
    let binv = bc.inv().ok()?;
    if a.is_zero() {
        return Some(Poly::zero());
    }
    let n = variable_span(a, b);
    let degrees: Vec<(u32, u32)> = (0..n as Var)
        .map(|v| (a.degree_in(v), b.degree_in(v)))
        .collect();
    if degrees.iter().any(|&(da, db)| db > da) {
        return None;
    }
    let widths: Vec<u32> = degrees
        .iter()
        .map(|&(da, _)| 32 - da.leading_zeros())
        .collect();
    if widths.iter().sum::<u32>() <= 128 {
        // Variable 0 in the lowest bits, so that the order of the keys is that of `crate::poly`.
        let shifts: Vec<u32> = widths
            .iter()
            .scan(0, |s, &w| {
                let at = *s;
                *s += w;
                Some(at)
            })
            .collect();
        let field = |k: u128, v: usize| {
            if widths[v] == 0 {
                0
            } else {
                ((k >> shifts[v]) & ((1u128 << widths[v]) - 1)) as u32
            }
        };
        return divide_keys(
            a,
            b,
            &binv,
            |exps| {
                exps.iter()
                    .map(|&(v, e)| u128::from(e) << shifts[v as usize])
                    .sum()
            },
            |m, lead| {
                (0..n).try_fold(0u128, |q, v| {
                    let e = field(*m, v).checked_sub(field(*lead, v))?;
                    let (da, db) = degrees[v];
                    match e {
                        0 => Some(q),
                        _ => (e <= da - db).then(|| q | (u128::from(e) << shifts[v])),
                    }
                })
            },
            |q, t| q + t,
            |q| {
                (0..n)
                    .filter_map(|v| Some((v as Var, field(*q, v))).filter(|&(_, e)| e > 0))
                    .collect()
            },
        );
    }
    divide_keys(
        a,
        b,
        &binv,
        |exps| {
            let mut k = vec![0u32; n];
            for &(v, e) in exps {
                k[n - 1 - v as usize] = e;
            }
            k
        },
        |m, lead| m.iter().zip(lead).map(|(x, y)| x.checked_sub(*y)).collect(),
        |q, t| q.iter().zip(t).map(|(x, y)| x + y).collect(),
        |q| {
            (0..n)
                .rev()
                .filter(|&i| q[i] > 0)
                .map(|i| ((n - 1 - i) as Var, q[i]))
                .collect()
        },
    )
}

/// The division of [`div_exact`] over keys of type `K` ordered like the monomials: `key` of a
/// term's exponents, `quotient` of a key by the leading key of `b` (`None` when it is not a
/// quotient term of an exact division), `add` of two keys (a product of monomials), and
/// `exponents` of a key.
fn divide_keys<C: Field, K: Ord + Clone>(
    a: &Poly<C>,
    b: &Poly<C>,
    binv: &C,
    key: impl Fn(&[(Var, u32)]) -> K,
    quotient: impl Fn(&K, &K) -> Option<K>,
    add: impl Fn(&K, &K) -> K,
    exponents: impl Fn(&K) -> Vec<(Var, u32)>,
) -> Option<Poly<C>> {
    let bterms: Vec<(K, C)> = b
        .terms()
        .map(|(m, c)| (key(&m.exponents()), c.clone()))
        .collect();
    let ((blead, _), brest) = bterms.split_first()?;
    let mut rest: std::collections::BTreeMap<K, C> = a
        .terms()
        .map(|(m, c)| (key(&m.exponents()), c.clone()))
        .collect();
    let mut terms = Vec::new();
    while let Some((m, c)) = rest.pop_last() {
        let q = quotient(&m, blead)?;
        let qc = if binv.is_one() { c } else { c.mul_ref(binv) };
        for (bm, bc) in brest {
            let t = qc.mul_ref(bc);
            match rest.entry(add(&q, bm)) {
                std::collections::btree_map::Entry::Occupied(mut o) => {
                    let v = o.get().sub_ref(&t);
                    if v.is_zero() {
                        o.remove();
                    } else {
                        *o.get_mut() = v;
                    }
                }
                std::collections::btree_map::Entry::Vacant(v) => {
                    v.insert(t.neg_ref());
                }
            }
        }
        terms.push((exponents(&q), qc));
    }
    Some(Poly::from_terms(terms))
}
