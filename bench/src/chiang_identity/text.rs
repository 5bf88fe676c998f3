//! The identity as text, for the whole `exactcheck prove` path and for other systems.

use exactcheck_core::binomial;

/// The identity as text: Chiang's ruled-surface / plane theorem, x component, as the two
/// sides of a polynomial identity in `t, a, b, c, d, px0.., py0.., pz0.., qx0.., qy0.., qz0..`,
/// exactly as `bench/scripts/anchors/chiang_text.py M N` prints them:
///
/// * LHS `(N.V(t)) Bx(t) - (N.B(t) + d) Vx(t)` with the Bernstein forms written unexpanded,
///   `C(n,j)*t^j*(1-t)^(n-j)`;
/// * RHS `sum_k B_k^{m+n}(t) P_kx` with the theorem's `P_k` and `phi(m,n,i,j)` as reduced
///   fractions `p/q`.
///
/// For `(m, n) = (8, 13)` the pair is about 9.5 kB over 74 variables, and both sides expand to
/// 5,841 terms.
///
/// # Panics
/// When `m + n > 67` (binomial coefficients beyond `u64`).
pub fn identity_text(m: u32, n: u32) -> (String, String) {
    let bern = |deg: u32, i: u32| format!("{}*t^{}*(1-t)^{}", binomial(deg, i), i, deg - i);
    let dot_q = |i: u32| format!("(a*qx{i}+b*qy{i}+c*qz{i})");
    let dot_p = |j: u32| format!("(a*px{j}+b*py{j}+c*pz{j}+d)");
    let join = |v: Vec<String>| v.join("+");
    let nv = format!(
        "({})",
        join(
            (0..=m)
                .map(|i| format!("{}*{}", bern(m, i), dot_q(i)))
                .collect()
        )
    );
    let bx = format!(
        "({})",
        join((0..=n).map(|j| format!("{}*px{j}", bern(n, j))).collect())
    );
    let nb = format!(
        "({})",
        join(
            (0..=n)
                .map(|j| format!("{}*{}", bern(n, j), dot_p(j)))
                .collect()
        )
    );
    let vx = format!(
        "({})",
        join((0..=m).map(|i| format!("{}*qx{i}", bern(m, i))).collect())
    );
    let lhs = format!("{nv}*{bx}-{nb}*{vx}");
    let mut terms = Vec::new();
    for k in 0..=m + n {
        let mut inner = Vec::new();
        for i in k.saturating_sub(n)..=k.min(m) {
            let j = k - i;
            let (num, den) = (binomial(m, i) * binomial(n, j), binomial(m + n, k));
            let g = num_integer::gcd(num, den);
            inner.push(format!(
                "{}/{}*({}*px{j}-{}*qx{i})",
                num / g,
                den / g,
                dot_q(i),
                dot_p(j)
            ));
        }
        terms.push(format!("{}*({})", bern(m + n, k), join(inner)));
    }
    (lhs, join(terms))
}
