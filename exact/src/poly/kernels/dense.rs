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

/// The mixed-radix index of every monomial: the fields of the variables with a stride (the
/// others are zero in both factors), each read by one shift and mask.
pub(in crate::poly) fn dense_indices(
    shape: Shape,
    e: &[u64],
    n: usize,
    strides: &[u64],
) -> Vec<u64> {
    let w = shape.words;
    let (pw, mask) = (shape.per_word(), shape.mask());
    let fields: Vec<(usize, u32, u64)> = strides
        .iter()
        .enumerate()
        .filter(|&(_, &s)| s != 0)
        .map(|(v, &s)| (v / pw, (v % pw) as u32 * shape.bits, s))
        .collect();
    if w == 1 {
        return e[..n]
            .iter()
            .map(|&m| {
                fields
                    .iter()
                    .map(|&(_, sh, s)| ((m >> sh) & mask) * s)
                    .sum()
            })
            .collect();
    }
    (0..n)
        .map(|i| {
            let m = &e[i * w..(i + 1) * w];
            fields
                .iter()
                .map(|&(k, sh, s)| ((m[k] >> sh) & mask) * s)
                .sum()
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

    /// Reorders every group's terms by their cell modulo [`BLOCK`] (decreasing within each
    /// class): a block times consecutive terms then adds to disjoint cells, so no
    /// multiply-add waits for the store of the one before it.
    fn spread(&mut self) {
        let mut buf = Vec::new();
        for (_, r, _) in &self.groups {
            let terms = &mut self.terms[r.clone()];
            buf.clear();
            for class in 0..BLOCK {
                buf.extend(terms.iter().filter(|t| t.0 % BLOCK == class));
            }
            terms.copy_from_slice(&buf);
        }
    }
}

/// The longest block of consecutive cells the direct kernel multiplies as one.
const BLOCK: usize = 4;

/// The terms of the other factor of a direct dense product, grouped by the top variable's
/// exponent as in [`Groups`], and within a group cut into blocks of up to [`BLOCK`] terms on
/// consecutive cells (a run of the lowest variable's exponents). A block times one term of the
/// other factor adds to consecutive cells: one bounds check and one load of that term serve up
/// to four products, whose coefficients stay in registers.
struct Blocks {
    /// The blocks: the lowest slab-local cell and the coefficients by increasing cell (zeros
    /// past the block's length). Within a group, the blocks of length 4, then 3, 2 and 1.
    blocks: Vec<(usize, [i64; BLOCK])>,
    /// For every top exponent with terms, by decreasing exponent: the exponent, the range of
    /// `blocks` of each length (`ranges[p - 1]`: length `p`) and the largest slab-local index.
    groups: Vec<(usize, [Range<usize>; BLOCK], usize)>,
}

impl Blocks {
    /// The blocks of a factor's groups (without `cut`: every term its own block).
    fn new(grouped: &Groups, cut: bool) -> Blocks {
        let mut blocks = Vec::with_capacity(grouped.terms.len());
        let mut groups = Vec::with_capacity(grouped.groups.len());
        // Per length, the blocks of the current group.
        let mut by_len: [Vec<(usize, [i64; BLOCK])>; BLOCK] = Default::default();
        for (top, range, high) in grouped.groups.iter().cloned() {
            let terms = &grouped.terms[range];
            let mut k = 0;
            while k < terms.len() {
                // A run of consecutive cells, from the highest down.
                let mut run = 1;
                while cut && k + run < terms.len() && terms[k + run].0 + run == terms[k].0 {
                    run += 1;
                }
                // Cut BLOCK at a time, the last five as three and two (a single term is the
                // dearest block).
                let mut rest = run;
                while rest > 0 {
                    let p = if rest == BLOCK + 1 {
                        BLOCK - 1
                    } else {
                        rest.min(BLOCK)
                    };
                    let low = terms[k + p - 1].0;
                    let mut a = [0i64; BLOCK];
                    for (i, &(_, ci)) in terms[k..k + p].iter().rev().enumerate() {
                        a[i] = ci;
                    }
                    by_len[p - 1].push((low, a));
                    k += p;
                    rest -= p;
                }
            }
            let mut ranges: [Range<usize>; BLOCK] = Default::default();
            for p in (0..BLOCK).rev() {
                let first = blocks.len();
                blocks.append(&mut by_len[p]);
                ranges[p] = first..blocks.len();
            }
            groups.push((top, ranges, high));
        }
        Blocks { blocks, groups }
    }
}

/// Multiplication in word arithmetic directly in dense arrays of accumulators over the
/// exponent box (for boxes of at most [`DIRECT_MAX_BYTES`]), one slab at a time: the output is
/// formed for each exponent `t` of the top variable (the one with the largest stride) from the
/// highest down, from the pairs of term groups whose top exponents add up to `t` (the factors
/// are sorted, so each group is a stretch of terms). The first factor comes in blocks of
/// consecutive cells ([`Blocks`]): each block times a term of the second is a multiply-add into
/// up to four consecutive cells of the slab (`stride` cells, small enough to stay in cache).
/// The slab is then read from the top, row by row of the lowest variable (a row whose cells are
/// all zero is skipped with one test), which yields the result sorted; each output monomial is
/// its row's packed monomial (kept by counting the row's mixed-radix digits down) plus the
/// lowest variable's exponent. The inner loops divide nothing, and cells that cancel to zero
/// are skipped like untouched ones.
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
    let f_terms = Groups::new(fi, fc, slab);
    let f = Blocks::new(&f_terms, A::BLOCKS);
    let mut g = Groups::new(gi, gc, slab);
    if A::BLOCKS {
        g.spread();
    }
    let slab = slab as usize;
    let mut g_of: Vec<Option<(Range<usize>, usize)>> = vec![None; top_radix as usize];
    for (t, r, high) in &g.groups {
        g_of[*t] = Some((r.clone(), *high));
    }
    let w = shape.words;
    let pw = shape.per_word();
    // The word of a variable's field and the packed unit of that field.
    let unit = |v: usize| (v / pw, 1u64 << ((v % pw) as u32 * shape.bits));
    let low_radices = &radices[..radices.len() - 1];
    // A row: the cells of the lowest variable (stride 1) for fixed other exponents; the other
    // variables below the top one are the row index's mixed-radix digits.
    let (row_len, low_word, low_unit) = match low_radices.first() {
        Some(&(v, _, radix)) => {
            let (k, u) = unit(v);
            (radix as usize, k, u)
        }
        None => (1, 0, 0),
    };
    let row_digits: Vec<(usize, u64, u64)> = low_radices
        .iter()
        .skip(1)
        .map(|&(v, _, radix)| {
            let (k, u) = unit(v);
            (k, u, radix)
        })
        .collect();
    let mut digits = vec![0u64; row_digits.len()];
    let mut acc = vec![A::ZERO; slab];
    let (nf, ng) = (fc.len(), gc.len());
    let cap = (top_radix as usize * slab)
        .min(nf.saturating_mul(ng))
        .min(8 * (nf + ng) + 1024)
        .min(max.saturating_add(1));
    let mut out_e = Vec::with_capacity(cap * w);
    let mut out_c = Vec::with_capacity(cap);
    let mut m = vec![0u64; w];
    let (top_word, top_unit) = unit(top_var);
    for t in (0..top_radix as usize).rev() {
        // One past the highest cell written in this slab (0: none).
        let mut end = 0;
        for (ta, franges, fhigh) in &f.groups {
            let Some(Some((gr, ghigh))) = t.checked_sub(*ta).map(|tb| &g_of[tb]) else {
                continue;
            };
            // Every cell written below is at most `fhigh + ghigh < slab`.
            end = end.max(fhigh + ghigh + 1);
            let gterms = &g.terms[gr.clone()];
            let row = &mut acc[..end];
            for &(la, a) in &f.blocks[franges[3].clone()] {
                add_mul_block::<A, 4>(&mut row[la..], &a, gterms);
            }
            for &(la, a) in &f.blocks[franges[2].clone()] {
                add_mul_block::<A, 3>(&mut row[la..], &a, gterms);
            }
            for &(la, a) in &f.blocks[franges[1].clone()] {
                add_mul_block::<A, 2>(&mut row[la..], &a, gterms);
            }
            if A::BLOCKS {
                for &(la, a) in &f.blocks[franges[0].clone()] {
                    add_mul_block::<A, 1>(&mut row[la..], &a, gterms);
                }
            } else {
                for &(la, a) in &f.blocks[franges[0].clone()] {
                    add_mul_row::<A>(&mut row[la..], a[0], gterms);
                }
            }
        }
        if end == 0 {
            continue;
        }
        // The packed monomial of the first cell of the highest row written, with exponent `t`
        // of the top variable; then row by row downwards.
        let top_row = (end - 1) / row_len;
        m.fill(0);
        m[top_word] += t as u64 * top_unit;
        let mut r = top_row as u64;
        for (d, &(k, u, radix)) in digits.iter_mut().zip(&row_digits) {
            *d = r % radix;
            r /= radix;
            m[k] += *d * u;
        }
        for row in (0..=top_row).rev() {
            let start = row * row_len;
            let cells = &mut acc[start..(start + row_len).min(end)];
            if !A::all_zero(cells) {
                for (x, c) in cells.iter_mut().enumerate().rev() {
                    if A::is_zero(c) {
                        continue;
                    }
                    if out_c.len() >= max {
                        return None;
                    }
                    let low = x as u64 * low_unit;
                    if w == 1 {
                        out_e.push(m[0] + low);
                    } else {
                        let base = out_e.len();
                        out_e.extend_from_slice(&m);
                        out_e[base + low_word] += low;
                    }
                    out_c.push(*c);
                    *c = A::ZERO;
                }
            }
            if row > 0 {
                // The next row down: decrement the lowest digit, borrowing upwards.
                for (d, &(k, u, radix)) in digits.iter_mut().zip(&row_digits) {
                    if *d > 0 {
                        *d -= 1;
                        m[k] -= u;
                        break;
                    }
                    *d = radix - 1;
                    m[k] += (radix - 1) * u;
                }
            }
        }
    }
    Some((out_e, out_c))
}

/// `cells[lb + i] += a[i] * b` for `i < P` and every term `(lb, b)` of one group of the other
/// factor (every `lb + P <= cells.len()`): the block's `P` coefficients stay in registers, and
/// one bounds check and one load of `(lb, b)` serve `P` products.
#[inline(always)]
fn add_mul_block<A: WordArith, const P: usize>(
    cells: &mut [A::Acc],
    a: &[i64; BLOCK],
    terms: &[(usize, i64)],
) where
    A::Acc: Copy,
{
    let a: [i64; P] = std::array::from_fn(|i| a[i]);
    for &(lb, b) in terms {
        let run = &mut cells[lb..lb + P];
        for i in 0..P {
            A::add_mul(&mut run[i], &a[i], &b);
        }
    }
}

/// `row[lb] += a * b` for the terms `(lb, b)` of one group (every `lb < row.len()`), unrolled
/// by four so that the loop's own bookkeeping is shared by four products (the accumulators
/// without blocks).
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs of one group cut into blocks: nine cells as 4 + 3 + 2, five as 3 + 2, and the
    /// coefficients of a block by increasing cell.
    #[test]
    fn blocks_cut_runs_of_consecutive_cells() {
        // One group (slab 100): cells 20..=12 (a run of 9), 10, 8..=7, 5..=1 (a run of 5).
        let idx: Vec<u64> = (12..=20)
            .rev()
            .chain([10, 8, 7])
            .chain((1..=5).rev())
            .collect();
        let c: Vec<i64> = idx.iter().map(|&i| 100 + i as i64).collect();
        let b = Blocks::new(&Groups::new(&idx, &c, 100), true);
        let single = Blocks::new(&Groups::new(&idx, &c, 100), false);
        assert_eq!(single.blocks.len(), idx.len());
        assert_eq!(single.groups[0].1[0], 0..idx.len());
        assert_eq!(b.groups.len(), 1);
        let (top, ranges, high) = &b.groups[0];
        assert_eq!((*top, *high), (0, 20));
        let lows = |p: usize| -> Vec<usize> {
            b.blocks[ranges[p - 1].clone()]
                .iter()
                .map(|x| x.0)
                .collect()
        };
        assert_eq!(lows(4), vec![17]);
        assert_eq!(lows(3), vec![14, 3]);
        assert_eq!(lows(2), vec![12, 7, 1]);
        assert_eq!(lows(1), vec![10]);
        // Every term once, each block's coefficients by increasing cell, zeros past its length.
        let mut seen = Vec::new();
        for p in 1..=BLOCK {
            for &(low, a) in &b.blocks[ranges[p - 1].clone()] {
                for (i, &ai) in a.iter().enumerate() {
                    if i < p {
                        assert_eq!(ai, 100 + (low + i) as i64);
                        seen.push(low + i);
                    } else {
                        assert_eq!(ai, 0);
                    }
                }
            }
        }
        seen.sort_unstable();
        let mut all: Vec<usize> = idx.iter().map(|&i| i as usize).collect();
        all.sort_unstable();
        assert_eq!(seen, all);
    }

    /// Groups by the top exponent, then spread: within a group the terms come by their cell
    /// modulo BLOCK, so consecutive terms of one class are at least BLOCK cells apart.
    #[test]
    fn spread_groups_by_cell_class() {
        // Slab 10: top exponent 1 holds cells 9..=2 (indices 19..=12), top 0 cells 3, 1.
        let idx: Vec<u64> = (12..=19).rev().chain([3, 1]).collect();
        let c: Vec<i64> = (0..idx.len() as i64).collect();
        let mut g = Groups::new(&idx, &c, 10);
        assert_eq!(g.groups.len(), 2);
        assert_eq!((g.groups[0].0, g.groups[0].2), (1, 9));
        assert_eq!((g.groups[1].0, g.groups[1].2), (0, 3));
        g.spread();
        let cells: Vec<usize> = g.terms.iter().map(|t| t.0).collect();
        assert_eq!(cells, vec![8, 4, 9, 5, 6, 2, 7, 3, 1, 3]);
        // The coefficients moved with their cells.
        for &(cell, coeff) in &g.terms[..8] {
            assert_eq!(coeff, 9 - cell as i64);
        }
    }
}
