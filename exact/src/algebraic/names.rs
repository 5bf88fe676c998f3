//! Elements of a number field `Q(theta)` printed as polynomials in values the user wrote.
//!
//! The generator `theta` of a field built from several numbers is a combination such as
//! `cos(pi/8) + cos(2*pi/7)` that nobody wrote, so an element is printed in the written values
//! `g_1, ..., g_k` instead (each given as a polynomial in `theta`), with rational coefficients:
//! `1/2 + cos(pi/8)*cos(2*pi/7)`.
//!
//! # The basis
//! The monomials `g_1^e_1 ... g_k^e_k` are visited in graded order (by total degree, and within
//! one degree lexicographically with higher powers of the earlier-written value first:
//! `1, a, b, a^2, a*b, b^2, ...`), and a monomial is kept when its coordinates in `theta` are
//! linearly independent of those of the monomials kept before it (exact linear algebra over Q).
//! The written values need not be independent: with `sqrt(2)` and `sqrt(8)` the second and
//! every product with it are dropped, with `sqrt(2)`, `sqrt(3)`, `sqrt(6)` the basis is
//! `1, sqrt(2), sqrt(3), sqrt(6)`. Only monomials of degree `t` that are a written value times a
//! monomial of degree `t - 1` kept are visited: every other monomial of degree `t` is a value
//! times a monomial that was dropped, which is a combination of kept monomials of degree below
//! `t` and of earlier ones of degree `t - 1`, so the product lies in the span of the visited
//! ones. That bounds the work by `k n^2` candidates for a field of degree `n`; exponents stay
//! below each value's degree (`g^d` is a combination of lower powers of `g`). The search ends
//! when `n` monomials are kept (they span the field) or when no monomial of one degree is kept:
//! the span is then closed under multiplication by every written value, so it is the field the
//! values generate, and when that is smaller than `Q(theta)` (a value needed to generate the
//! field was not written) there is no naming.
//!
//! # Coordinates
//! Once per field the matrix whose columns are the kept monomials' coordinates in `theta` is
//! inverted (Gauss-Jordan elimination by [`Matrix::rref`]); an element is then expressed by one
//! matrix-vector product, its one expression in the basis.
//!
//! Hand-written with the rest of the number-field code: no crate of the dependency set has
//! number fields, and the linear algebra is the workspace's own ([`exactcheck_core::linalg`]).

use super::NumberField;
use crate::univariate::UPoly;
use crate::Rational;
use exactcheck_core::linalg::Matrix;
use exactcheck_core::{Ring, Sign};
use std::cmp::Ordering;

/// Written values of a field and the basis of monomials in them that elements are printed in:
/// see the [module documentation](self).
#[derive(Clone, Debug)]
pub(super) struct Naming {
    /// The names as factors of a product (`cos(pi/8)`, `(1 + sqrt(2))`).
    names: Vec<String>,
    /// The kept monomials, as exponent vectors (one exponent per name), in graded order.
    basis: Vec<Vec<u32>>,
    /// Row `i` holds the coefficients of basis monomial `i` in terms of `1, theta, ...`,
    /// `theta^(n-1)`: the inverse of the matrix whose columns are the monomials' coordinates.
    to_basis: Matrix<Rational>,
}

/// `text` as a factor of a product: itself when it is a name, a number or one call
/// (`cos(pi/8)`), else in parentheses (`(1 + sqrt(2))`).
pub(super) fn as_factor(text: &str) -> String {
    let t = text.trim();
    let word = |s: &str| {
        !s.is_empty()
            && s.chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.')
    };
    let call = t.find('(').is_some_and(|open| {
        word(&t[..open]) && t.ends_with(')') && {
            // The parenthesis opened after the name closes at the end.
            let mut depth = 0i32;
            t[open..].char_indices().all(|(i, c)| {
                match c {
                    '(' => depth += 1,
                    ')' => depth -= 1,
                    _ => {}
                }
                depth > 0 || open + i == t.len() - 1
            })
        }
    });
    if word(t) || call {
        t.to_string()
    } else {
        format!("({t})")
    }
}

/// The coordinates of `p` (of degree below `n`) in `1, theta, ..., theta^(n-1)`.
fn coordinates(p: &UPoly, n: usize) -> Vec<Rational> {
    (0..n).map(|i| p.coeff(i)).collect()
}

/// The graded order of exponent vectors: by total degree, then lexicographically with the
/// higher exponent of an earlier value first.
fn graded(a: &[u32], b: &[u32]) -> Ordering {
    let total = |e: &[u32]| e.iter().map(|&x| u64::from(x)).sum::<u64>();
    total(a).cmp(&total(b)).then_with(|| b.cmp(a))
}

impl Naming {
    /// The naming of `field` by the values `generators` (name as written, polynomial in
    /// `theta`), `None` when the monomials in them do not span the field (or it is `Q`).
    pub(super) fn new(field: &NumberField, generators: &[(&str, &UPoly)]) -> Option<Naming> {
        let n = field.degree();
        if n < 2 || generators.is_empty() {
            return None;
        }
        let values: Vec<UPoly> = generators.iter().map(|(_, p)| field.reduce(p)).collect();
        let k = values.len();
        // The kept monomials with their polynomials in theta; those of the last degree visited
        // start at `last`.
        let mut kept: Vec<(Vec<u32>, UPoly)> = vec![(vec![0; k], UPoly::one())];
        let mut last = 0;
        while kept.len() < n {
            let mut candidates: Vec<(Vec<u32>, UPoly)> = Vec::new();
            for (e, p) in &kept[last..] {
                for (j, g) in values.iter().enumerate() {
                    let mut e2 = e.clone();
                    e2[j] += 1;
                    if candidates.iter().all(|(c, _)| *c != e2) {
                        candidates.push((e2, field.mul(p, g)));
                    }
                }
            }
            candidates.sort_by(|a, b| graded(&a.0, &b.0));
            // The pivot columns of the echelon form are the columns independent of those
            // before them: the kept monomials first (all pivots), then the candidates.
            let mut m = Matrix::zeros(n, kept.len() + candidates.len());
            for (j, (_, p)) in kept.iter().chain(&candidates).enumerate() {
                for (i, c) in coordinates(p, n).into_iter().enumerate() {
                    m.set(i, j, c);
                }
            }
            let (_, pivots) = m.rref();
            let before = kept.len();
            last = before;
            kept.extend(
                pivots
                    .into_iter()
                    .filter(|&j| j >= before)
                    .map(|j| candidates[j - before].clone()),
            );
            if kept.len() == before {
                return None;
            }
        }
        // Gauss-Jordan on [B | I]: the right half becomes B^-1.
        let mut aug = Matrix::zeros(n, 2 * n);
        for (j, (_, p)) in kept.iter().enumerate() {
            for (i, c) in coordinates(p, n).into_iter().enumerate() {
                aug.set(i, j, c);
            }
            aug.set(j, n + j, Rational::ONE);
        }
        let (r, pivots) = aug.rref();
        debug_assert_eq!(pivots, (0..n).collect::<Vec<_>>());
        let mut to_basis = Matrix::zeros(n, n);
        for i in 0..n {
            for j in 0..n {
                to_basis.set(i, j, r.get(i, n + j).clone());
            }
        }
        Some(Naming {
            names: generators.iter().map(|(t, _)| as_factor(t)).collect(),
            basis: kept.into_iter().map(|(e, _)| e).collect(),
            to_basis,
        })
    }

    /// The monomial with exponents `e` in the expression syntax (`cos(pi/8)^2*sqrt(3)`), empty
    /// for `1`.
    fn monomial(&self, e: &[u32]) -> String {
        let factors: Vec<String> = self
            .names
            .iter()
            .zip(e)
            .filter(|(_, &x)| x > 0)
            .map(|(name, &x)| match x {
                1 => name.clone(),
                _ => format!("{name}^{x}"),
            })
            .collect();
        factors.join("*")
    }

    /// The element whose coordinates in `theta` are `c` (length `n`), as a polynomial in the
    /// named values: `1/2 + 3/4*cos(pi/8) - cos(pi/8)^3`, in the expression syntax.
    pub(super) fn print(&self, c: &[Rational]) -> String {
        let mut out = String::new();
        for (i, e) in self.basis.iter().enumerate() {
            let di = self
                .to_basis
                .row(i)
                .iter()
                .zip(c)
                .fold(Rational::ZERO, |acc, (a, b)| acc.add_ref(&a.mul_ref(b)));
            if di.is_zero() {
                continue;
            }
            let negative = di.signum() == Sign::Negative;
            let magnitude = if negative { di.neg_ref() } else { di };
            let power = self.monomial(e);
            let term = match (power.is_empty(), magnitude.is_one()) {
                (true, _) => magnitude.to_string(),
                (false, true) => power,
                (false, false) => format!("{magnitude}*{power}"),
            };
            match (out.is_empty(), negative) {
                (true, false) => out.push_str(&term),
                (true, true) => out.push_str(&format!("-{term}")),
                (false, false) => out.push_str(&format!(" + {term}")),
                (false, true) => out.push_str(&format!(" - {term}")),
            }
        }
        if out.is_empty() {
            "0".to_string()
        } else {
            out
        }
    }

    /// The basis monomials as printed, in order.
    #[cfg(test)]
    pub(super) fn basis_texts(&self) -> Vec<String> {
        self.basis.iter().map(|e| self.monomial(e)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebraic::{primitive_element, Algebraic, FieldElement};
    use proptest::prelude::*;
    use std::sync::Arc;

    /// The expression parser's value of a constant text: the independent path every printed
    /// element is checked against.
    fn alg(text: &str) -> Algebraic {
        text.parse()
            .unwrap_or_else(|e| panic!("{text} does not read back: {e}"))
    }

    /// The field of the written values `texts`, named by all of them, and each value's
    /// polynomial in the generator.
    fn named_field(texts: &[&str]) -> (Arc<NumberField>, Vec<UPoly>) {
        let numbers: Vec<Algebraic> = texts.iter().map(|t| alg(t)).collect();
        let pe = primitive_element(&numbers).unwrap();
        let names: Vec<(&str, &UPoly)> = texts.iter().copied().zip(&pe.polys).collect();
        let field = pe
            .field
            .clone()
            .with_names(&names)
            .expect("the values span");
        (Arc::new(field), pe.polys)
    }

    fn basis(field: &NumberField) -> Vec<String> {
        field.naming.as_ref().unwrap().basis_texts()
    }

    /// The product of the values `polys[j]` raised to `exps[j]`, in the field.
    fn monomial(field: &NumberField, polys: &[UPoly], exps: &[u32]) -> UPoly {
        let mut acc = UPoly::one();
        for (p, &e) in polys.iter().zip(exps) {
            for _ in 0..e {
                acc = field.mul(&acc, p);
            }
        }
        acc
    }

    /// `named(p)` reads back as the value of `p`.
    fn reads_back(field: &NumberField, p: &UPoly) -> Result<String, TestCaseError> {
        let text = field.named(p).unwrap();
        prop_assert_eq!(alg(&text), field.value(p), "{}", text);
        Ok(text)
    }

    #[test]
    fn bases_of_dependent_and_independent_values() {
        let (k, _) = named_field(&["sqrt(2)", "sqrt(3)"]);
        assert_eq!(basis(&k), ["", "sqrt(2)", "sqrt(3)", "sqrt(2)*sqrt(3)"]);
        // sqrt(8) = 2 sqrt(2) and every product with it are dropped.
        let (k, _) = named_field(&["sqrt(2)", "sqrt(8)"]);
        assert_eq!(basis(&k), ["", "sqrt(2)"]);
        let (k, _) = named_field(&["sqrt(2)", "sqrt(8)", "sqrt(3)"]);
        assert_eq!(basis(&k), ["", "sqrt(2)", "sqrt(3)", "sqrt(2)*sqrt(3)"]);
        let (k, _) = named_field(&["sqrt(2)", "sqrt(3)", "sqrt(6)"]);
        assert_eq!(basis(&k), ["", "sqrt(2)", "sqrt(3)", "sqrt(6)"]);
        // cos(pi/8) alone generates Q(sqrt 2, cos(pi/8)): the basis is its powers.
        let (k, _) = named_field(&["sqrt(2)", "cos(pi/8)"]);
        assert_eq!(basis(&k), ["", "sqrt(2)", "cos(pi/8)", "sqrt(2)*cos(pi/8)"]);
        let (k, _) = named_field(&["cos(pi/8)", "cos(2*pi/7)"]);
        assert_eq!(k.degree(), 12);
        assert_eq!(
            basis(&k),
            [
                "",
                "cos(pi/8)",
                "cos(2*pi/7)",
                "cos(pi/8)^2",
                "cos(pi/8)*cos(2*pi/7)",
                "cos(2*pi/7)^2",
                "cos(pi/8)^3",
                "cos(pi/8)^2*cos(2*pi/7)",
                "cos(pi/8)*cos(2*pi/7)^2",
                "cos(pi/8)^3*cos(2*pi/7)",
                "cos(pi/8)^2*cos(2*pi/7)^2",
                "cos(pi/8)^3*cos(2*pi/7)^2",
            ]
        );
    }

    #[test]
    fn values_that_do_not_generate_the_field_give_no_names() {
        let pe = primitive_element(&[alg("sqrt(2)"), alg("sqrt(3)")]).unwrap();
        let k = pe.field.clone();
        assert!(k.clone().with_names(&[("sqrt(2)", &pe.polys[0])]).is_none());
        let six = k.mul(&pe.polys[0], &pe.polys[1]);
        assert!(k.clone().with_names(&[("sqrt(6)", &six)]).is_none());
        assert!(k.clone().with_names(&[]).is_none());
        // sqrt(6) with sqrt(2) does generate it: sqrt(3) = sqrt(6)*sqrt(2)/2.
        let k = k.with_names(&[("sqrt(2)", &pe.polys[0]), ("sqrt(6)", &six)]);
        let k = k.expect("sqrt(2) and sqrt(6) generate Q(sqrt 2, sqrt 3)");
        assert_eq!(k.named(&pe.polys[1]).unwrap(), "1/2*sqrt(2)*sqrt(6)");
    }

    #[test]
    fn elements_print_with_signs_products_and_powers() {
        let (k, g) = named_field(&["cos(pi/8)", "cos(2*pi/7)"]);
        let (c8, c7) = (&g[0], &g[1]);
        let one = UPoly::one();
        let e = k
            .mul(c8, c7)
            .sub_ref(&(one.clone() * &Rational::from_integer(4)));
        assert_eq!(k.named(&e).unwrap(), "-4 + cos(pi/8)*cos(2*pi/7)");
        let sq = k.mul(c7, c7).neg_ref();
        assert_eq!(k.named(&sq).unwrap(), "-cos(2*pi/7)^2");
        let m = monomial(&k, &g, &[3, 2]) * &Rational::new(-3, 7).unwrap();
        assert_eq!(k.named(&m).unwrap(), "-3/7*cos(pi/8)^3*cos(2*pi/7)^2");
        assert_eq!(k.named(&UPoly::zero()).unwrap(), "0");
        assert_eq!(k.named(&one).unwrap(), "1");
        // cos(pi/8)^4 is no basis monomial: 4 c^4 = 4 c^2 - 1/2.
        let c4 = monomial(&k, &g, &[4, 0]);
        assert_eq!(k.named(&c4).unwrap(), "-1/8 + cos(pi/8)^2");
        // The element's printer prefers a radical form: 4 cos(pi/8)^2 - 2 = sqrt(2), then
        // names, and names are never Root(...).
        let s2 = FieldElement::new(&k, &monomial(&k, &g, &[2, 0])) * FieldElement::from_i64(4)
            - FieldElement::from_i64(2);
        assert_eq!(s2.to_string(), "sqrt(2)");
        assert_eq!(
            FieldElement::new(&k, &e).to_string(),
            "-4 + cos(pi/8)*cos(2*pi/7)"
        );
        for p in [e, sq, m, c4] {
            reads_back(&k, &p).unwrap();
        }
    }

    #[test]
    fn elements_of_quartic_fields_print_as_radicals_or_in_names() {
        let (k, g) = named_field(&["sqrt(2)", "sqrt(3)"]);
        let el = |p: &UPoly| FieldElement::new(&k, p).to_string();
        let one = UPoly::one();
        let six = k.mul(&g[0], &g[1]);
        // Quadratic and even quartic values keep their radical forms.
        assert_eq!(el(&one.add_ref(&six)), "1 + sqrt(6)");
        assert_eq!(el(&g[0].add_ref(&g[1])), "sqrt(2) + sqrt(3)");
        // Others print in the names.
        assert_eq!(
            el(&one.add_ref(&g[0]).add_ref(&g[1])),
            "1 + sqrt(2) + sqrt(3)"
        );
        let x = g[0].add_ref(&six) * &Rational::new(2, 3).unwrap();
        assert_eq!(
            el(&one.add_ref(&x)),
            "1 + 2/3*sqrt(2) + 2/3*sqrt(2)*sqrt(3)"
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// Random elements of quartic fields named by dependent and independent values.
        #[test]
        fn printed_elements_read_back_in_quartic_fields(
            which in 0usize..3,
            c in proptest::collection::vec(-6i64..7, 4),
            d in 1i64..5,
        ) {
            let texts: &[&str] = match which {
                0 => &["sqrt(2)", "sqrt(3)"],
                1 => &["sqrt(2)", "sqrt(8)", "sqrt(3)"],
                _ => &["sqrt(2)", "sqrt(3)", "sqrt(6)"],
            };
            let (k, _) = named_field(texts);
            let coeffs = c.iter().map(|&x| Rational::new(x, d).unwrap()).collect();
            let p = UPoly::from_coeffs(coeffs);
            reads_back(&k, &p)?;
        }
    }

    proptest! {
        // Reading a text back sums numbers of degree 12 by resultants: a few cases.
        #![proptest_config(ProptestConfig::with_cases(4))]

        /// Random sparse elements of the degree-12 field of cos(pi/8) and cos(2 pi/7): two
        /// products of powers of the values (the exponents may pass the basis), plus a rational.
        #[test]
        fn printed_elements_read_back_in_a_field_of_degree_twelve(
            a in -5i64..6, b in -5i64..6, c in -5i64..6, d in 1i64..4,
            e in proptest::collection::vec(0u32..5, 4),
        ) {
            let (k, g) = named_field(&["cos(pi/8)", "cos(2*pi/7)"]);
            let q = |x: i64| Rational::new(x, d).unwrap();
            let p = UPoly::constant(q(a))
                .add_ref(&(monomial(&k, &g, &e[..2]) * &q(b)))
                .add_ref(&(monomial(&k, &g, &e[2..]) * &q(c)));
            let p = k.reduce(&p);
            reads_back(&k, &p)?;
        }
    }
}
