//! The dense product kernels: an accumulator over the exponent box when it is small, and the
//! slab-by-slab direct product in word arithmetic.

use super::super::words::*;
use super::*;

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

/// Multiplication in word arithmetic directly in dense arrays of accumulators over the
/// exponent box (for boxes of at most [`DIRECT_MAX_BYTES`]), one slab at a time: the output is
/// formed for each exponent `t` of the top variable (the one with the largest stride) from the
/// highest down, from the pairs of term groups whose top exponents add up to `t` (the factors
/// are sorted, so each group is a run of terms). Every term product is one multiply-add into
/// the slab (`stride` cells, small enough to stay in cache), and scanning the slab from the top
/// yields the result sorted, each monomial decoded from its mixed-radix index (`strides`,
/// radices `need + 1`). Cells that cancel to zero are skipped like untouched ones.
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
    let &(_, slab, top_radix) = radices
        .last()
        .expect("a product of two polynomials of two terms or more has a variable");
    let slab = slab as usize;
    // Runs of equal top exponent: (top exponent, start, end), for f and by exponent for g.
    let runs = |idx: &[u64]| -> Vec<(usize, usize, usize)> {
        let mut out: Vec<(usize, usize, usize)> = Vec::new();
        for (k, &x) in idx.iter().enumerate() {
            let t = (x / slab as u64) as usize;
            match out.last_mut() {
                Some(r) if r.0 == t => r.2 = k + 1,
                _ => out.push((t, k, k + 1)),
            }
        }
        out
    };
    let low =
        |idx: &[u64]| -> Vec<usize> { idx.iter().map(|&x| (x % slab as u64) as usize).collect() };
    let (fr, gr) = (runs(fi), runs(gi));
    let (fl, gl) = (low(fi), low(gi));
    let mut g_of: Vec<Option<(usize, usize, usize)>> = vec![None; top_radix as usize];
    for &(t, a, b) in &gr {
        let top = gl[a..b].iter().copied().max().unwrap_or(0);
        g_of[t] = Some((a, b, top));
    }
    let mut acc = vec![A::ZERO; slab];
    let w = shape.words;
    let mut out_e = Vec::new();
    let mut out_c = Vec::new();
    let mut m = vec![0u64; w];
    for t in (0..top_radix as usize).rev() {
        let mut touched = false;
        for &(ta, fa, fb) in &fr {
            let Some(Some((ga, gb, gtop))) = t.checked_sub(ta).map(|tb| g_of[tb]) else {
                continue;
            };
            touched = true;
            let (gcs, gls) = (&gc[ga..gb], &gl[ga..gb]);
            for (a, &la) in fc[fa..fb].iter().zip(&fl[fa..fb]) {
                // Every cell of this row is below `la + gtop + 1 <= slab`.
                let row = &mut acc[la..la + gtop + 1];
                for (b, &lb) in gcs.iter().zip(gls) {
                    A::add_mul(&mut row[lb], a, b);
                }
            }
        }
        if !touched {
            continue;
        }
        for (lo, c) in acc.iter_mut().enumerate().rev() {
            if A::is_zero(c) {
                continue;
            }
            if out_c.len() >= max {
                return None;
            }
            let idx = (t * slab + lo) as u64;
            m.fill(0);
            for &(v, stride, radix) in &radices {
                shape.set(&mut m, v, (idx / stride) % radix);
            }
            out_e.extend_from_slice(&m);
            out_c.push(*c);
            *c = A::ZERO;
        }
    }
    Some((out_e, out_c))
}
