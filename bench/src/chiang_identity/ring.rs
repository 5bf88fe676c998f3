//! Chiang's ruled-surface / plane theorem as a polynomial identity, built with the [`Ring`] API
//! ([`ring_residuals`]).
//!
//! With Bézier curves `B(t)` of degree `n` (control points `p_j`) and `V(t)` of degree `m`
//! (control points `q_i`), a plane `N.x + d = 0` with `N = (a, b, c)`, and Bernstein polynomials
//! `B_k^deg(t) = C(deg, k) t^k (1 - t)^(deg - k)`, the theorem states
//!
//! ```text
//! (N.V) B_x - (N.B + d) V_x = sum_k B_k^{m+n}(t) sum_{i+j=k} phi(i, j) ((N.q_i) p_jx - (N.p_j + d) q_ix)
//! N.V                        = sum_k B_k^{m+n}(t) sum_{i+j=k} phi(i, j) (N.q_i)
//! ```
//!
//! with `phi(i, j) = C(m, i) C(n, j) / C(m + n, k)`: the x component and the weight of the
//! rational Bézier form of the intersection. [`ring_residuals`] builds both sides exactly as
//! `bench/scripts/anchors/chiang_identity.py`'s flint backend does (Bernstein forms expanded, products
//! over the ring) and returns `LHS - RHS` of each; both are zero. With `negative`, `phi(0, 0)`
//! becomes `1 + 1/7` (as `chiang_identity.py --negative`), and both residuals are non-zero.

use exactcheck_core::{binomial, Ring};
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::Rational;

/// The residuals `(x component, weight)` of the identity at degrees `(m, n)`, built with the [`Ring`] API
/// (see the module documentation); both are zero unless `negative`.
///
/// # Panics
/// When `m + n > 62` (binomial coefficients beyond `i64`).
pub fn ring_residuals(m: u32, n: u32, negative: bool) -> (Poly<Rational>, Poly<Rational>) {
    let w = ring_identity(m, n, negative);
    (w.x_residual, w.weight_residual)
}

/// The identity built with the [`Ring`] API: both residuals and the size of the expanded left-hand side
/// (the `lhs_x_terms` check value of `bench/scripts/anchors/chiang_identity.py`).
#[derive(Clone, Debug)]
pub struct RingIdentity {
    /// `LHS - RHS` of the x component (zero unless `negative`).
    pub x_residual: Poly<Rational>,
    /// `LHS - RHS` of the weight (zero unless `negative`).
    pub weight_residual: Poly<Rational>,
    /// The number of terms of the expanded x-component left-hand side.
    pub lhs_x_terms: usize,
    /// The number of variables (`5 + 3 (m + 1) + 3 (n + 1)`).
    pub variables: usize,
}

/// [`ring_residuals`] with the anchors' other check values (see [`RingIdentity`]).
///
/// # Panics
/// When `m + n > 62` (binomial coefficients beyond `i64`).
pub fn ring_identity(m: u32, n: u32, negative: bool) -> RingIdentity {
    type P = Poly<Rational>;
    let mut vars = Vars::new();
    let mut v = |name: String| -> P { vars.poly(&name) };
    let (t, a, b, c, d) = (
        v("t".into()),
        v("a".into()),
        v("b".into()),
        v("c".into()),
        v("d".into()),
    );
    let mut seq = |s: &str, k: u32| (0..=k).map(|j| v(format!("{s}{j}"))).collect::<Vec<P>>();
    let (px, py, pz) = (seq("px", n), seq("py", n), seq("pz", n));
    let (qx, qy, qz) = (seq("qx", m), seq("qy", m), seq("qz", m));
    let int = |x: u64| i64::try_from(x).expect("binomial coefficient fits in i64 (m + n <= 62)");
    let one = P::one();
    let bern =
        |deg: u32, k: u32| P::from_i64(int(binomial(deg, k))) * t.pow(k) * (&one - &t).pow(deg - k);
    let bez =
        |deg: u32, cp: &[P]| P::sum((0..=deg).map(|j| bern(deg, j) * &cp[j as usize]).collect());
    let (bx, by, bz) = (bez(n, &px), bez(n, &py), bez(n, &pz));
    let (vx, vy, vz) = (bez(m, &qx), bez(m, &qy), bez(m, &qz));
    let nv = &a * &vx + &b * &vy + &c * &vz;
    let nb = &a * &bx + &b * &by + &c * &bz;
    let p_lhs = &nv * &bx - (nb + &d) * &vx;
    let nq: Vec<P> = (0..=m as usize)
        .map(|i| &a * &qx[i] + &b * &qy[i] + &c * &qz[i])
        .collect();
    let np: Vec<P> = (0..=n as usize)
        .map(|j| &a * &px[j] + &b * &py[j] + &c * &pz[j])
        .collect();
    let (mut p_rhs, mut q_rhs) = (Vec::new(), Vec::new());
    for k in 0..=m + n {
        let (mut pt, mut wt) = (Vec::new(), Vec::new());
        for i in k.saturating_sub(n)..=k.min(m) {
            let j = k - i;
            let mut phi = Rational::new(
                int(binomial(m, i) * binomial(n, j)),
                int(binomial(m + n, k)),
            )
            .expect("C(m + n, k) is not zero");
            if negative && i == 0 && j == 0 {
                phi += Rational::new(1, 7).expect("7 is not zero");
            }
            let phi = P::constant(phi);
            let (i, j) = (i as usize, j as usize);
            pt.push(&phi * &(&nq[i] * &px[j] - (&np[j] + &d) * &qx[i]));
            wt.push(&phi * &nq[i]);
        }
        p_rhs.push(bern(m + n, k) * P::sum(pt));
        q_rhs.push(bern(m + n, k) * P::sum(wt));
    }
    let lhs_x_terms = p_lhs.len();
    RingIdentity {
        x_residual: p_lhs - P::sum(p_rhs),
        weight_residual: nv - P::sum(q_rhs),
        lhs_x_terms,
        variables: vars.len(),
    }
}
