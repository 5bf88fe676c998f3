//! The dense product kernels: an accumulator over the exponent box when it is small, and the
//! slab-by-slab direct product in word arithmetic.

use super::super::words::*;
use super::*;
use std::ops::Range;

/// The largest exponent box a dense product may use (cells of 4 bytes).
pub(in crate::poly) const DENSE_MAX_CELLS: u64 = 1 << 22;

/// Mixed-radix indices for a dense product: variable `v` gets radix `need[v] + 1`, the lowest
/// variable the smallest stride, so indices order like the monomials. `None` when the box
/// (the product of the radices) exceeds `limit`.
pub(in crate::poly) fn dense_strides(need: &[u64], limit: u64) -> Option<(u64, Vec<u64>)> {
    let mut stride = 1u64;
    let mut strides = vec![0u64; need.len()];
    for (v, &n) in need.iter().enumerate() {
        if n == 0 {
            continue;
        }
        strides[v] = stride;
        stride = stride.checked_mul(n + 1).filter(|&b| b <= limit)?;
    }
    Some((stride, strides))
}

/// The mixed-radix index of every monomial.
pub(in crate::poly) fn dense_indices(
    shape: Shape,
    e: &[u64],
    n: usize,
    strides: &[u64],
) -> Vec<u64> {
    let w = shape.words;
    (0..n)
        .map(|i| {
            let mut idx = 0;
            shape.for_each(&e[i * w..(i + 1) * w], |v, x| idx += x * strides[v]);
            idx
        })
        .collect()
}

/// Multiplication by accumulation in a dense box of exponents (for products whose exponent box
/// is not much larger than the number of term products, as in dense few-variable products):
/// each product goes to its cell by mixed-radix index, the touched cells are sorted once.
pub(in crate::poly) fn mul_dense<A: Arith>(
    w: usize,
    cells: usize,
    (fe, fi, fc): (&[u64], &[u64], &[A::In]),
    (ge, gi, gc): (&[u64], &[u64], &[A::In]),
    max: usize,
) -> Option<(Vec<u64>, Vec<A::Acc>)> {
    let mut cell = vec![0u32; cells];
    // (index, i, j, coefficient) of every distinct product monomial.
    let mut touched: Vec<(u64, u32, u32, A::Acc)> = Vec::with_capacity((fc.len() + gc.len()) * 4);
    for (i, (a, ia)) in fc.iter().zip(fi).enumerate() {
        for (j, (b, ib)) in gc.iter().zip(gi).enumerate() {
            let idx = ia + ib;
            match cell[idx as usize] {
                0 => {
                    // Cancellation can leave fewer terms, but not more: a dense product is
                    // small (its box at most DENSE_MAX_CELLS), so counting touched cells is
                    // the cheap prediction.
                    if touched.len() >= max {
                        return None;
                    }
                    touched.push((idx, i as u32, j as u32, A::mul(a, b)));
                    cell[idx as usize] = touched.len() as u32;
                }
                t => A::add_mul(&mut touched[t as usize - 1].3, a, b),
            }
        }
    }
    touched.sort_unstable_by_key(|x| std::cmp::Reverse(x.0));
    let mut out_e = Vec::with_capacity(touched.len() * w);
    let mut out_c = Vec::with_capacity(touched.len());
    for (_, i, j, c) in touched {
        if !A::is_zero(&c) {
            let (i, j) = (i as usize, j as usize);
            push_sum(&mut out_e, &fe[i * w..(i + 1) * w], &ge[j * w..(j + 1) * w]);
            out_c.push(c);
        }
    }
    Some((out_e, out_c))
}

/// The terms of one factor of a direct dense product grouped by the top variable's exponent.
struct Groups {
    /// Every term's slab-local cell index with its coefficient, in the factor's order.
    terms: Vec<(usize, i64)>,
    /// For every top exponent with terms, by decreasing exponent: the exponent, its terms (a
    /// range of `terms`) and the largest slab-local index among them.
    groups: Vec<(usize, Range<usize>, usize)>,
}

impl Groups {
    /// The groups of a factor with cell indices `idx` (decreasing: the terms are sorted) and
    /// coefficients `c`, for slabs of `slab` cells: one division per group, none per term.
    fn new(idx: &[u64], c: &[i64], slab: u64) -> Groups {
        let mut terms = Vec::with_capacity(idx.len());
        let mut groups = Vec::new();
        let mut k = 0;
        while k < idx.len() {
            let top = idx[k] / slab;
            let floor = top * slab;
            let first = k;
            let mut high = 0;
            while k < idx.len() && idx[k] >= floor {
                let lo = (idx[k] - floor) as usize;
                high = high.max(lo);
                terms.push((lo, c[k]));
                k += 1;
            }
            groups.push((top as usize, first..k, high));
        }
        Groups { terms, groups }
    }
}

/// The packed monomials of the cells of one slab, by slab-local index, when that table is
/// small (at most this many words); larger slabs decode each output cell by division.
const DECODE_TABLE_WORDS: usize = 1 << 18;

/// Multiplication in word arithmetic directly in dense arrays of accumulators over the
/// exponent box (for boxes of at most [`DIRECT_MAX_BYTES`]), one slab at a time: the output is
/// formed for each exponent `t` of the top variable (the one with the largest stride) from the
/// highest down, from the pairs of term groups whose top exponents add up to `t` (the factors
/// are sorted, so each group is a stretch of terms). Every term product is one multiply-add
/// into the slab (`stride` cells, small enough to stay in cache), and scanning the slab from
/// the top yields the result sorted. Each output monomial is the packed monomial of its
/// slab-local index (from a table built once by counting in mixed radix, or by division for
/// slabs too large for the table) with the top exponent `t` set: the inner loops divide
/// nothing. Cells that cancel to zero are skipped like untouched ones.
pub(in crate::poly) fn mul_dense_direct<A: WordArith>(
    shape: Shape,
    strides: &[u64],
    need: &[u64],
    (fi, fc): (&[u64], &[i64]),
    (gi, gc): (&[u64], &[i64]),
    max: usize,
) -> Option<(Vec<u64>, Vec<A::Acc>)>
where
    A::Acc: Copy,
{
    let radices: Vec<(usize, u64, u64)> = need
        .iter()
        .enumerate()
        .filter(|&(_, &n)| n > 0)
        .map(|(v, &n)| (v, strides[v], n + 1))
        .collect();
    // The top variable: the largest stride (the last variable in use).
    let &(top_var, slab, top_radix) = radices
        .last()
        .expect("a product of two polynomials of two terms or more has a variable");
    let f = Groups::new(fi, fc, slab);
    let g = Groups::new(gi, gc, slab);
    let slab = slab as usize;
    let mut g_of: Vec<Option<(Range<usize>, usize)>> = vec![None; top_radix as usize];
    for (t, r, high) in &g.groups {
        g_of[*t] = Some((r.clone(), *high));
    }
    let w = shape.words;
    let low_radices = &radices[..radices.len() - 1];
    let table = (slab.saturating_mul(w) <= DECODE_TABLE_WORDS)
        .then(|| decode_table(shape, low_radices, slab));
    let mut acc = vec![A::ZERO; slab];
    let (nf, ng) = (fc.len(), gc.len());
    let cap = (top_radix as usize * slab)
        .min(nf.saturating_mul(ng))
        .min(8 * (nf + ng) + 1024)
        .min(max.saturating_add(1));
    let mut out_e = Vec::with_capacity(cap * w);
    let mut out_c = Vec::with_capacity(cap);
    let mut m = vec![0u64; w];
    // The top variable's field: its word and shift (clear in every decoded monomial).
    let (top_word, top_shift) = (
        top_var / shape.per_word(),
        (top_var % shape.per_word()) as u32 * shape.bits,
    );
    for t in (0..top_radix as usize).rev() {
        // One past the highest cell written in this slab (0: none).
        let mut end = 0;
        for (ta, fr, fhigh) in &f.groups {
            let Some(Some((gr, ghigh))) = t.checked_sub(*ta).map(|tb| &g_of[tb]) else {
                continue;
            };
            end = end.max(fhigh + ghigh + 1);
            let gterms = &g.terms[gr.clone()];
            for &(la, a) in &f.terms[fr.clone()] {
                // Every cell of this row is below `la + ghigh + 1 <= slab`.
                add_mul_row::<A>(&mut acc[la..la + ghigh + 1], a, gterms);
            }
        }
        for (lo, c) in acc[..end].iter_mut().enumerate().rev() {
            if A::is_zero(c) {
                continue;
            }
            if out_c.len() >= max {
                return None;
            }
            let top = (t as u64) << top_shift;
            match &table {
                // One word per monomial (up to 8 variables): no copy loop.
                Some(table) if w == 1 => out_e.push(table[lo] | top),
                Some(table) => {
                    let base = out_e.len();
                    out_e.extend_from_slice(&table[lo * w..(lo + 1) * w]);
                    out_e[base + top_word] |= top;
                }
                None => {
                    m.fill(0);
                    for &(v, stride, radix) in low_radices {
                        shape.set(&mut m, v, (lo as u64 / stride) % radix);
                    }
                    m[top_word] |= top;
                    out_e.extend_from_slice(&m);
                }
            }
            out_c.push(*c);
            *c = A::ZERO;
        }
    }
    Some((out_e, out_c))
}

/// The packed monomial of every slab-local cell index `0..slab` (`w` words each) for the
/// variables below the top one (`(variable, stride, radix)`, increasing strides), by counting
/// in mixed radix instead of dividing.
fn decode_table(shape: Shape, low: &[(usize, u64, u64)], slab: usize) -> Vec<u64> {
    let w = shape.words;
    let pw = shape.per_word();
    let mut table = vec![0u64; slab * w];
    // Every digit's word and the packed unit of its field: stepping a digit is one addition.
    let units: Vec<(usize, u64, u64)> = low
        .iter()
        .map(|&(v, _, radix)| (v / pw, 1u64 << ((v % pw) as u32 * shape.bits), radix))
        .collect();
    let mut digits = vec![0u64; low.len()];
    let mut m = vec![0u64; w];
    for lo in 0..slab {
        if w == 1 {
            table[lo] = m[0];
        } else {
            table[lo * w..(lo + 1) * w].copy_from_slice(&m);
        }
        // The next index: increment the lowest digit, carrying upwards (a digit at its radix
        // goes back from `radix - 1` to 0).
        for (d, &(k, unit, radix)) in digits.iter_mut().zip(&units) {
            *d += 1;
            if *d < radix {
                m[k] += unit;
                break;
            }
            *d = 0;
            m[k] -= (radix - 1) * unit;
        }
    }
    table
}

/// `row[lb] += a * b` for the terms `(lb, b)` of one group (every `lb < row.len()`), unrolled
/// by four so that the loop's own bookkeeping is shared by four products.
#[inline(always)]
fn add_mul_row<A: WordArith>(row: &mut [A::Acc], a: i64, terms: &[(usize, i64)])
where
    A::Acc: Copy,
{
    let mut quads = terms.chunks_exact(4);
    for q in &mut quads {
        A::add_mul(&mut row[q[0].0], &a, &q[0].1);
        A::add_mul(&mut row[q[1].0], &a, &q[1].1);
        A::add_mul(&mut row[q[2].0], &a, &q[2].1);
        A::add_mul(&mut row[q[3].0], &a, &q[3].1);
    }
    for &(lb, b) in quads.remainder() {
        A::add_mul(&mut row[lb], &a, &b);
    }
}
