//! Square roots of expressions in the randomized identity test (`sqrt(1 + t^2)`, the derivative
//! of a root after lowering): each distinct root becomes a generator `w` of a ring with
//! `w^2 = R`, its radicand evaluated at the point.
//!
//! # The rewriting
//! Every `sqrt(R)` whose radicand has a variable, and every `abs(E)` as the root of `R = E^2`,
//! is replaced by a fresh variable `w_i`, inner
//! roots first, so that the radicand `R_i` of `w_i` mentions only the variables and the earlier
//! `w_j` ([`abstract_roots`]). Two roots share one `w` when their radicands expand to the same
//! rational function. A radicand with a square root of a constant or a trigonometric call is
//! refused (it would need the constants' field or the circles inside the tower); the number of
//! roots is held to the `radicands` limit (the ring has dimension `2^r`).
//!
//! # The evaluation
//! At a point, the radicands are evaluated in turn and the ring is the tower
//! `A = B[w_1, ..., w_r]/(w_i^2 - R_i(point))` over the base ring `B` of the test (`F_p` or
//! `F_p[c]/(m)`), an element a vector of `2^r` elements of `B` in the basis of the products
//! `w^S` ([`Tower`]). `(a + b w)(c + d w) = (ac + bd R) + (ad + bc) w`, and `a + b w` is a
//! unit exactly when its norm `a^2 - b^2 R` is one (then its inverse is `(a - b w)/(a^2 - b^2 R)`):
//! a divisor that is not a unit at the point is a pole, skipped like any other.
//!
//! # The bound
//! Write a radicand as `F_i / D_i` by the structural rules, and `w_i = w'_i / D_i` with
//! `w'_i^2 = F_i D_i`. The tree is then a fraction in the variables and the `w'_i`, and the
//! structural rules hold with the leaf `w_i` bounded by `log2 ||F||_1 <= ceil((L_i + L_Di)/2)`,
//! `L_D = L_Di`, `d = ceil((d_i + e_i)/2)`, `e = e_i` ([`leaf_bound`]): with the weights
//! `W_i = 2^{ceil((L_i + L_Di)/2)}`, the norm `||a + b w'_i|| = ||a|| + W_i ||b||` of the
//! quotient by `w'_i^2 - F_i D_i` is submultiplicative (`W_i^2 >= ||F_i D_i||_1`), and so is the
//! degree with `w'_i` of degree `ceil((d_i + e_i)/2)`. Reduced modulo the relations
//! `w'_i^2 = F_i D_i`, the numerator of `LHS - RHS` is `sum_S A_S w'^S` with integer polynomials
//! `A_S` of 1-norm at most `2^L` and degree at most `d`, and it evaluates to zero in `A`
//! exactly when every `A_S` vanishes at the point (`w'_i = D_i w_i` is a change of basis where
//! `D_i` is a unit). So the theorem of [`super`] holds with `G` one of the `A_S`, and with the
//! poles counted by the norm of the denominator over the tower, of degree at most `2^r` times
//! that of `D`: the per-point term is `d' / (2^62 - 2k - n 2^r e')`.
//!
//! What it proves: `holds` says that `LHS - RHS` vanishes modulo the relations `w^2 = R` (the
//! probability of the bound), hence wherever the roots are defined, for either sign of each
//! root. The converse does not hold: `sqrt(x) sqrt(y) = sqrt(x y)` holds for the non-negative
//! roots but not for every choice of signs, so a point where the sides differ proves nothing,
//! and the answer is `undecided` (run without `--random`, which uses the signs).
//!
//! Written here rather than taken from a crate: the ring is two recursive formulas over the
//! test's own base rings, whose moduli are drawn at run time.

use super::ring::{eval, EvalError, Values};
use super::{size_bound_in, BoundError, SizeBound};
use crate::expr::library::has_sqrt;
use crate::expr::{abs_radicand, has_trig, Expr, ExprKind, ABS, PI};
use crate::poly::Vars;
use crate::Rational;
use exactcheck_core::limits;
use std::collections::HashMap;

/// A square root of an expression, abstracted as the variable `name`.
#[derive(Clone, Debug)]
pub(crate) struct Root {
    /// The variable standing for the root.
    pub name: String,
    /// The radicand, the earlier roots in it replaced by their variables.
    pub radicand: Expr,
    /// The root as written, for the evidence.
    pub written: String,
}

/// The sides with every square root of an expression replaced by a variable, and the roots,
/// inner first (module documentation). `taken` are the names the variables must avoid.
///
/// # Errors
/// A radicand with a square root of a constant or a trigonometric call; more roots than the
/// `radicands` limit.
pub(crate) fn abstract_roots(
    lhs: &Expr,
    rhs: &Expr,
    taken: &[String],
) -> Result<(Expr, Expr, Vec<Root>), String> {
    let mut state = Roots {
        roots: Vec::new(),
        keys: Vec::new(),
        vars: Vars::new(),
        taken: taken.to_vec(),
    };
    let l = state.rewrite(lhs)?;
    let r = state.rewrite(rhs)?;
    Ok((l, r, state.roots))
}

struct Roots {
    roots: Vec<Root>,
    /// The expanded radicand of each root, printed (equal radicands, one root).
    keys: Vec<String>,
    vars: Vars,
    taken: Vec<String>,
}

impl Roots {
    fn rewrite(&mut self, e: &Expr) -> Result<Expr, String> {
        // `abs(E)` is the root of `E^2`.
        let squared;
        let x = match &e.kind {
            ExprKind::Sqrt(x) => x.as_ref(),
            ExprKind::Call(name, args) if name == ABS && args.len() == 1 => {
                squared = abs_radicand(&args[0]);
                &squared
            }
            _ => return e.try_map_children(|c| self.rewrite(c)),
        };
        let radicand = self.rewrite(x)?;
        let mut names = Vec::new();
        radicand.collect_variables(&mut names);
        if names.iter().all(|n| n == PI) {
            return Ok(Expr {
                kind: ExprKind::Sqrt(Box::new(radicand)),
                pos: e.pos,
            });
        }
        if has_sqrt(&radicand) || has_trig(&radicand) {
            return Err(format!(
                "{e} takes the square root of an expression with a square root of a constant or \
                 sin, cos or tan, which --random does not evaluate (no error bound is proved for \
                 it modulo p); run without --random, which decides it exactly"
            ));
        }
        // Equal radicands written differently (`1 + t^2`, `t^2 + 1`) share a root.
        let key = match radicand.to_ratfun::<Rational>(&mut self.vars) {
            Ok(f) => format!("{f:?}"),
            Err(_) => radicand.to_string(),
        };
        let name = match self.keys.iter().position(|k| *k == key) {
            Some(i) => self.roots[i].name.clone(),
            None => {
                limits::RADICANDS
                    .check_usize(self.roots.len() + 1)
                    .map_err(|error| format!("at {}: {error}", e.pos))?;
                let name = (0u32..)
                    .map(|k| format!("_w{k}"))
                    .find(|n| !self.taken.contains(n))
                    .expect("finitely many names are taken");
                self.taken.push(name.clone());
                self.keys.push(key);
                self.roots.push(Root {
                    name: name.clone(),
                    radicand,
                    written: e.to_string(),
                });
                name
            }
        };
        Ok(Expr {
            kind: ExprKind::Var(name),
            pos: e.pos,
        })
    }
}

/// The bounds of each root's variable as a leaf of the structural rules (module
/// documentation), by name.
///
/// # Errors
/// As [`size_bound_in`] on a radicand.
pub(crate) fn leaf_bounds(roots: &[Root]) -> Result<HashMap<String, SizeBound>, BoundError> {
    let mut leaves = HashMap::new();
    for root in roots {
        let b = size_bound_in(&root.radicand, &leaves)?;
        leaves.insert(root.name.clone(), leaf_bound(&b)?);
    }
    Ok(leaves)
}

/// The leaf `w = w'/D` for a radicand `F/D` bounded by `b`, `w'^2 = F D`.
fn leaf_bound(b: &SizeBound) -> Result<SizeBound, BoundError> {
    let half = |a: u64, c: u64| {
        a.checked_add(c)
            .map(|s| s.div_ceil(2))
            .ok_or(BoundError::Overflow)
    };
    Ok(SizeBound {
        num_bits: half(b.num_bits, b.den_bits)?,
        den_bits: b.den_bits,
        degree: half(b.degree, b.den_degree)?,
        den_degree: b.den_degree,
    })
}

/// Why a point where the sides differ is not a counter-example when the identity has square
/// roots of expressions (module documentation).
pub(crate) const NOT_A_REFUTATION: &str =
    "the square roots of expressions are tested as roots w with w^2 = R, for either sign: a \
     point where the sides differ shows that the identity does not follow from w^2 = R alone, \
     not that it is false for the non-negative roots (sqrt(x) sqrt(y) = sqrt(x y) holds only \
     for those); run without --random, which decides it with the signs";

/// The bounds with which the error bound of [`super`] holds with `r` roots: the degree of the
/// denominator times `2^r`, the degree of its norm over the tower (module documentation).
/// `None` when it overflows.
pub(crate) fn norm_bound(b: &SizeBound, r: usize) -> Option<SizeBound> {
    let factor = 1u64.checked_shl(u32::try_from(r).ok()?)?;
    Some(SizeBound {
        den_degree: b.den_degree.checked_mul(factor)?,
        ..*b
    })
}

/// The values of the variables at a point, by name.
type Point<V> = HashMap<String, V>;

/// A tower with the point lifted into it.
type Lifted<'a, R> = (Tower<'a, R>, Point<Vec<<R as Values>::V>>);

/// The ring `B[w_1, ..., w_r]/(w_i^2 - R_i)` of one point (module documentation): an element
/// is `2^r` elements of `B`, the coefficient of `w^S` at the index whose bits are `S`.
pub(crate) struct Tower<'a, R: Values> {
    base: &'a R,
    /// `R_i`, an element of the tower of the first `i` roots (`2^i` coefficients).
    radicands: Vec<Vec<R::V>>,
}

impl<'a, R: Values> Tower<'a, R> {
    /// The tower of the roots at the point `point` (values in `B`, without the roots): each
    /// radicand evaluated in the tower of the roots before it; the point lifted to the tower,
    /// with each root's variable its generator.
    ///
    /// # Errors
    /// The evaluation's errors on a radicand (a pole there is a pole of the point).
    pub(crate) fn at(
        base: &'a R,
        roots: &[Root],
        point: &Point<R::V>,
        constant: &dyn Fn(&str) -> bool,
        refused: &dyn Fn(&Expr) -> String,
    ) -> Result<Lifted<'a, R>, EvalError> {
        let mut tower = Tower {
            base,
            radicands: Vec::new(),
        };
        for root in roots {
            let lifted = tower.lift(roots, point);
            let r = eval(&root.radicand, &tower, &lifted, constant, refused)?;
            tower.radicands.push(r);
        }
        let lifted = tower.lift(roots, point);
        Ok((tower, lifted))
    }

    /// The point in the tower as built so far: the values of `B` as constants, the roots
    /// already adjoined as their generators.
    fn lift(&self, roots: &[Root], point: &Point<R::V>) -> Point<Vec<R::V>> {
        let size = 1usize << self.radicands.len();
        let zero = self.base.number(&Rational::ZERO).expect("0 maps");
        let one = self.base.number(&Rational::ONE).expect("1 maps");
        let mut out: HashMap<String, Vec<R::V>> = point
            .iter()
            .map(|(name, v)| {
                let mut x = vec![zero.clone(); size];
                x[0] = v.clone();
                (name.clone(), x)
            })
            .collect();
        for (i, root) in roots.iter().take(self.radicands.len()).enumerate() {
            let mut w = vec![zero.clone(); size];
            w[1 << i] = one.clone();
            out.insert(root.name.clone(), w);
        }
        out
    }

    fn zip(&self, a: &[R::V], b: &[R::V], f: impl Fn(&R::V, &R::V) -> R::V) -> Vec<R::V> {
        a.iter().zip(b).map(|(x, y)| f(x, y)).collect()
    }

    /// `a b` for elements of the tower of the first `log2 a.len()` roots.
    fn product(&self, a: &[R::V], b: &[R::V]) -> Vec<R::V> {
        if a.len() == 1 {
            return vec![self.base.mul(&a[0], &b[0])];
        }
        let h = a.len() / 2;
        let r = &self.radicands[h.trailing_zeros() as usize];
        let (a0, a1) = a.split_at(h);
        let (b0, b1) = b.split_at(h);
        let bd = self.product(a1, b1);
        let low = self.zip(&self.product(a0, b0), &self.product(&bd, r), |x, y| {
            self.base.add(x, y)
        });
        let high = self.zip(&self.product(a0, b1), &self.product(a1, b0), |x, y| {
            self.base.add(x, y)
        });
        [low, high].concat()
    }

    /// `a^-1` (module documentation), `None` when `a` is not a unit.
    fn inverse(&self, a: &[R::V]) -> Option<Vec<R::V>> {
        if a.len() == 1 {
            return self.base.inv(&a[0]).map(|x| vec![x]);
        }
        let h = a.len() / 2;
        let r = &self.radicands[h.trailing_zeros() as usize];
        let (a0, a1) = a.split_at(h);
        let norm = self.zip(
            &self.product(a0, a0),
            &self.product(&self.product(a1, a1), r),
            |x, y| self.base.sub(x, y),
        );
        let n = self.inverse(&norm)?;
        let low = self.product(a0, &n);
        let high: Vec<R::V> = self
            .product(a1, &n)
            .iter()
            .map(|x| self.base.neg(x))
            .collect();
        Some([low, high].concat())
    }
}

impl<R: Values> Values for Tower<'_, R> {
    type V = Vec<R::V>;
    fn number(&self, q: &Rational) -> Option<Vec<R::V>> {
        let zero = self.base.number(&Rational::ZERO).expect("0 maps");
        let mut x = vec![zero; 1 << self.radicands.len()];
        x[0] = self.base.number(q)?;
        Some(x)
    }
    fn add(&self, a: &Vec<R::V>, b: &Vec<R::V>) -> Vec<R::V> {
        self.zip(a, b, |x, y| self.base.add(x, y))
    }
    fn sub(&self, a: &Vec<R::V>, b: &Vec<R::V>) -> Vec<R::V> {
        self.zip(a, b, |x, y| self.base.sub(x, y))
    }
    fn mul(&self, a: &Vec<R::V>, b: &Vec<R::V>) -> Vec<R::V> {
        self.product(a, b)
    }
    fn neg(&self, a: &Vec<R::V>) -> Vec<R::V> {
        a.iter().map(|x| self.base.neg(x)).collect()
    }
    fn inv(&self, a: &Vec<R::V>) -> Option<Vec<R::V>> {
        self.inverse(a)
    }
    fn is_zero(&self, a: &Vec<R::V>) -> bool {
        a.iter().all(|x| self.base.is_zero(x))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr;
    use crate::modp::PrimeField;
    use exactcheck_core::Rng;

    fn roots_of(l: &str, r: &str) -> (Expr, Expr, Vec<Root>) {
        abstract_roots(&parse_expr(l).unwrap(), &parse_expr(r).unwrap(), &[]).unwrap()
    }

    #[test]
    fn equal_radicands_share_a_root_and_inner_roots_come_first() {
        let (l, r, roots) = roots_of("t/sqrt(1 + t^2)", "t*sqrt(t^2 + 1)/(1 + t^2)");
        assert_eq!(roots.len(), 1);
        assert_eq!(l.to_string(), "t/_w0");
        assert_eq!(r.to_string(), "t*_w0/(1 + t^2)");
        let (l, _, roots) = roots_of("sqrt(1 + sqrt(x)) + sqrt(2)", "0");
        assert_eq!(roots.len(), 2);
        assert_eq!(roots[0].radicand.to_string(), "x");
        assert_eq!(roots[1].radicand.to_string(), "1 + _w0");
        assert_eq!(l.to_string(), "_w1 + sqrt(2)");
        let err = abstract_roots(
            &parse_expr("sqrt(x + sqrt(2))").unwrap(),
            &parse_expr("0").unwrap(),
            &[],
        )
        .unwrap_err();
        assert!(err.contains("square root of a constant"), "{err}");
    }

    /// The tower against its definition: `w^2 = R`, products associative, inverses inverse.
    #[test]
    fn tower_arithmetic() {
        let mut rng = Rng::new(5);
        let f = PrimeField::random_62(&mut rng);
        let (_, _, roots) = roots_of("sqrt(x) + sqrt(1 + sqrt(x))", "0");
        let point: HashMap<String, u64> = [("x".to_string(), f.random(&mut rng))].into();
        let Ok((tower, lifted)) = Tower::at(&f, &roots, &point, &|_| false, &|_| String::new())
        else {
            panic!("no pole at a random point")
        };
        let w0 = &lifted["_w0"];
        let w1 = &lifted["_w1"];
        let x = &lifted["x"];
        assert_eq!(tower.mul(w0, w0), *x);
        let one = tower.number(&Rational::ONE).unwrap();
        assert_eq!(tower.mul(w1, w1), tower.add(&one, w0));
        let random = |rng: &mut Rng| -> Vec<u64> { (0..4).map(|_| f.random(rng)).collect() };
        for _ in 0..20 {
            let (a, b, c) = (random(&mut rng), random(&mut rng), random(&mut rng));
            assert_eq!(
                tower.mul(&tower.mul(&a, &b), &c),
                tower.mul(&a, &tower.mul(&b, &c))
            );
            let inv = tower.inv(&a).expect("a random element is a unit");
            assert_eq!(tower.mul(&a, &inv), one);
        }
        // Zero has no inverse.
        assert!(tower.inv(&tower.sub(w0, w0)).is_none());
    }

    #[test]
    fn a_root_leaf_is_half_its_radicand() {
        let (_, _, roots) = roots_of("sqrt((x^3 + 7)/(y + 1))", "0");
        let leaves = leaf_bounds(&roots).unwrap();
        let b = leaves["_w0"];
        // F = x^3 + 7 (3 bits + 1, degree 3), D = y + 1 (1 bit, degree 1).
        assert_eq!(b.degree, 2);
        assert_eq!(b.den_degree, 1);
        assert!(b.num_bits >= 2 && b.den_bits >= 1, "{b:?}");
    }

    fn test(l: &str, r: &str, seed: u64) -> super::super::RandomDecision {
        let names = ["x".to_string(), "y".to_string()];
        let (l, r) = (parse_expr(l).unwrap(), parse_expr(r).unwrap());
        super::super::random_identity_test(&l, &r, &names, &[], 8, super::super::Seed::Fresh(seed))
            .unwrap()
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(24))]
        /// `(a + b w)(a - b w) = a^2 - b^2 R` for a root `w` of `R`, and its inverse, hold; a
        /// perturbed right side differs, which is no refutation.
        #[test]
        fn conjugates_multiply_to_the_norm(
            a in -9i64..=9,
            b in 1i64..=9,
            c in 1i64..=9,
            seed in 0u64..1000,
        ) {
            let radicand = format!("x^2*y + {c}");
            let w = format!("sqrt({radicand})");
            let product = format!("({a} + {b}*{w})*({a} - {b}*{w})");
            let norm = format!("({a})^2 - ({b})^2*({radicand})");
            let holds = |d: &super::super::RandomDecision| {
                matches!(d, super::super::RandomDecision::Holds { .. })
            };
            let d = test(&product, &norm, seed);
            proptest::prop_assert!(holds(&d), "{product} = {norm}: {d:?}");
            let inverse = format!("1/({a} + {b}*{w})");
            let by_norm = format!("({a} - {b}*{w})/({norm})");
            let d = test(&inverse, &by_norm, seed);
            proptest::prop_assert!(holds(&d), "{inverse} = {by_norm}: {d:?}");
            let d = test(&product, &format!("{norm} + x"), seed);
            let unconfirmed = matches!(d, super::super::RandomDecision::Unconfirmed { .. });
            proptest::prop_assert!(unconfirmed, "{d:?}");
        }
    }
}
