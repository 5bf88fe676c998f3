//! Identities with real algebraic constants outside the coefficient fields (`x + cos(pi/5)`,
//! `sin(x + pi/7)`, `sqrt(2 + sqrt(2)) x`), decided over Q with one more variable.
//!
//! The constants of the statement ([`crate::expr::abstract_constants`]) generate a number field
//! `Q(theta)`; `theta` is a *primitive element* ([`crate::algebraic::primitive_element`]) and
//! every constant is a polynomial in it, so the statement becomes one over Q in the variables
//! and a fresh variable `c` standing for `theta`, with the relation `m(c) = 0` for the minimal
//! polynomial `m` of `theta` ([`AlgebraicConstants`]). Then:
//! * **proved** when the residual reduces to zero modulo the relations with `m(c)` among them: it
//!   vanishes wherever they hold, in particular at `c = theta`;
//! * a non-zero reduction with `m` as the only relation is a non-zero element of
//!   `Q(theta)[vars]` (`m` is irreducible, so `Q[c]/(m)` is the field), so the identity fails at
//!   some rational point: [`AlgebraicConstants::counter_example`] finds one and evaluates the
//!   difference there exactly, as an element of `Q(theta)` (zero exactly when its reduction
//!   modulo `m` is) and then as an [`Algebraic`] number. Unit circles of angles take their
//!   rational points; other relations (a user's, those of square roots of expressions) leave
//!   the search to the engine, which is told the isolating interval of `theta` as the domain of
//!   `c`, so that any root of `m` it picks is `theta` itself.
//!
//! Taking all constants together matters: minimal polynomials over Q of two constants taken
//! separately do not describe their field when they are dependent (`cos(pi/5)` and `sqrt(5)`),
//! and a non-zero reduction would then prove nothing.

use super::{small_height_rationals, unit_circle_pairs, Domain};
use crate::algebraic::{primitive_element, FieldError, NumberField};
use crate::expr::{fill_constants, upoly_expr, ConstantLeaf, Expr};
use crate::poly::{Poly, Var};
use crate::ratfun::RatFun;
use crate::univariate::UPoly;
use crate::{Algebraic, Radical, Rational};
use exactcheck_core::{Ring, Rng};

/// The constants of a statement as polynomials in one primitive element `c`: see the
/// [module documentation](self).
#[derive(Clone, Debug)]
pub struct AlgebraicConstants {
    /// The name of the variable standing for the primitive element (`c`, or the first of `c1`,
    /// `c2`, ... that the statement does not use).
    pub name: String,
    /// The field `Q(theta)`.
    pub field: NumberField,
    /// The constants, in the order of their placeholders.
    pub leaves: Vec<ConstantLeaf>,
    /// Each constant as a polynomial in `theta`.
    pub polys: Vec<UPoly>,
    /// `theta` as an integer combination of the constants.
    pub combination: Vec<i64>,
}

/// A counter-example in rational values of the variables, with `c = theta`.
#[derive(Clone, Debug)]
pub struct ConstantPoint {
    /// The value of every variable of the statement but `c`.
    pub values: Vec<(Var, Rational)>,
    /// `LHS - RHS` there, exactly (not zero).
    pub value: Algebraic,
}

/// The most points [`AlgebraicConstants::counter_example`] tries.
pub const CONSTANT_ATTEMPTS: usize = 300;

impl AlgebraicConstants {
    /// The field of the irrational constants `leaves` (found by
    /// [`crate::expr::abstract_constants`]), its generator named apart from `taken` (the
    /// statement's variables); `None` without constants.
    ///
    /// # Errors
    /// [`FieldError`]: the `algebraic-degree` limit on the field's degree, a minimal polynomial
    /// factoring gave up on.
    pub fn new(
        leaves: Vec<ConstantLeaf>,
        taken: &[String],
    ) -> Result<Option<AlgebraicConstants>, FieldError> {
        if leaves.is_empty() {
            return Ok(None);
        }
        // The constant of the highest degree first: the generator is then often that constant.
        let mut order: Vec<usize> = (0..leaves.len()).collect();
        order.sort_by_key(|&i| std::cmp::Reverse(leaves[i].value.degree()));
        let sorted: Vec<Algebraic> = order.iter().map(|&i| leaves[i].value.clone()).collect();
        let pe = primitive_element(&sorted)?;
        let mut polys = vec![UPoly::zero(); leaves.len()];
        let mut combination = vec![0; leaves.len()];
        for (k, &i) in order.iter().enumerate() {
            polys[i] = pe.polys[k].clone();
            combination[i] = pe.combination[k];
        }
        let name = std::iter::once("c".to_string())
            .chain((1..).map(|i| format!("c{i}")))
            .find(|n| !taken.contains(n))
            .expect("some name is free");
        Ok(Some(AlgebraicConstants {
            name,
            field: pe.field,
            leaves,
            polys,
            combination,
        }))
    }

    /// `e` (rewritten by [`crate::expr::abstract_constants`] with this statement's leaves) with
    /// every constant replaced by its polynomial in `c`.
    pub fn fill(&self, e: &Expr) -> Expr {
        let values: Vec<Expr> = self
            .polys
            .iter()
            .map(|p| upoly_expr(p, &self.name))
            .collect();
        fill_constants(e, &values)
    }

    /// The minimal polynomial of `theta` with integer coefficients.
    fn minimal(&self) -> UPoly {
        self.field.modulus().primitive_part()
    }

    /// The relation `m(c)` (zero at `c = theta`), as an expression.
    pub fn relation(&self) -> Expr {
        upoly_expr(&self.minimal(), &self.name)
    }

    /// The relation as text: `4*c^2 - 2*c - 1 = 0`.
    pub fn relation_text(&self) -> String {
        format!("{} = 0", self.minimal().display(&self.name))
    }

    /// The isolating interval of `theta` among the real roots of `m`, as the domain of `c`.
    pub fn domain(&self) -> Domain {
        let iv = self.field.generator().interval();
        Domain {
            lower: Some((iv.lo.clone(), true)),
            upper: Some((iv.hi.clone(), true)),
        }
    }

    /// What `c` is: `c = cos(pi/5)`, or for several constants the combination and each
    /// constant in `c` (`c = cos(pi/5) + sin(pi/5), cos(pi/5) = ..., sin(pi/5) = ...`).
    pub fn definition(&self) -> String {
        let c = &self.name;
        let single = self.polys.iter().position(|p| *p == UPoly::x());
        match single {
            Some(i) if self.leaves.len() == 1 => format!("{c} = {}", self.leaves[i].text),
            _ => {
                let mut theta = String::new();
                for (l, k) in self.leaves.iter().zip(&self.combination) {
                    let term = match k.unsigned_abs() {
                        0 => continue,
                        1 => l.text.clone(),
                        n => format!("{n}*{}", l.text),
                    };
                    theta += &match (theta.is_empty(), *k < 0) {
                        (true, false) => term,
                        (true, true) => format!("-{term}"),
                        (false, false) => format!(" + {term}"),
                        (false, true) => format!(" - {term}"),
                    };
                }
                let each: Vec<String> = self
                    .leaves
                    .iter()
                    .zip(&self.polys)
                    .filter(|(_, p)| **p != UPoly::x())
                    .map(|(l, p)| format!("{} = {}", l.text, p.display(c)))
                    .collect();
                format!("{c} = {theta}, {}", each.join(", "))
            }
        }
    }

    /// `with c = cos(pi/5), 4*c^2 - 2*c - 1 = 0`: the constants introduced, for a verdict.
    pub fn description(&self) -> String {
        let degree = self.field.degree();
        format!(
            "with {}, {} (its minimal polynomial, degree {degree})",
            self.definition(),
            self.relation_text()
        )
    }

    /// An exact counter-example to `lhs = rhs` with `c = theta` (the variable `c`): rational
    /// values of the other variables (small heights first, inside `domains`; an angle's cosine
    /// and sine at a rational point of its unit circle), where no condition vanishes and
    /// `LHS - RHS` is a non-zero element of `Q(theta)`. `relations` are those besides `m(c)`;
    /// only unit circles are supported, and `excluded` variables (pi, an indeterminate with no
    /// rational value) may not occur.
    ///
    /// # Errors
    /// Why no point was found, in words.
    #[allow(clippy::too_many_arguments)]
    pub fn counter_example(
        &self,
        c: Var,
        lhs: &RatFun<Rational>,
        rhs: &RatFun<Rational>,
        relations: &[Poly<Rational>],
        conditions: &[Poly<Rational>],
        domains: &[(Var, Domain)],
        excluded: &[Var],
    ) -> Result<ConstantPoint, String> {
        let (pairs, others) = unit_circle_pairs(relations);
        if !others.is_empty() {
            return Err(
                "the search for a counter-example with algebraic constants takes unit circles as its only relations"
                    .into(),
            );
        }
        let polys: Vec<&Poly<Rational>> = [
            lhs.numerator(),
            lhs.denominator(),
            rhs.numerator(),
            rhs.denominator(),
        ]
        .into_iter()
        .chain(conditions)
        .collect();
        let mut vars: Vec<Var> = Vec::new();
        for p in &polys {
            for v in p.variables() {
                if v != c && !vars.contains(&v) {
                    vars.push(v);
                }
            }
        }
        vars.sort_unstable();
        if let Some(v) = vars.iter().find(|v| excluded.contains(v)) {
            return Err(format!(
                "variable #{v} has no rational value to give it (pi is transcendental)"
            ));
        }
        let heights = small_height_rationals(12);
        // Each slot: a free variable (its values) or a circle (values of tau).
        let in_circle = |v: Var| pairs.iter().any(|&(a, b)| a == v || b == v);
        let mut slots: Vec<(Vec<Var>, Vec<Rational>)> = Vec::new();
        for &(a, b) in &pairs {
            slots.push((vec![a, b], heights.iter().take(24).cloned().collect()));
        }
        for &v in vars.iter().filter(|v| !in_circle(**v)) {
            let dom = domains
                .iter()
                .find(|(w, _)| *w == v)
                .map(|(_, d)| d.clone())
                .unwrap_or_default();
            let list: Vec<Rational> = heights
                .iter()
                .filter(|q| dom.contains(&Radical::from(*q)))
                .take(24)
                .cloned()
                .collect();
            if list.is_empty() {
                return Err(format!(
                    "the domain of variable #{v} has no rational of small height"
                ));
            }
            slots.push((vec![v], list));
        }
        let mut rng = Rng::new(0x5EED_00C0);
        for attempt in 0..CONSTANT_ATTEMPTS {
            let mut values: Vec<(Var, Rational)> = Vec::new();
            for (vs, list) in &slots {
                let reach = list.len().min(2 + attempt / 8);
                let q = if attempt == 0 {
                    list[0].clone()
                } else {
                    list[rng.below(reach as u64) as usize].clone()
                };
                match vs.as_slice() {
                    [cv, sv] => {
                        let t2 = q.square();
                        let den = (Rational::ONE + &t2)
                            .recip()
                            .expect("1 + tau^2 >= 1 is not zero");
                        values.push((*cv, (Rational::ONE - &t2) * &den));
                        values.push((*sv, q.scale_i64(2) * &den));
                    }
                    _ => values.push((vs[0], q)),
                }
            }
            if let Some(value) = self.difference_at(c, lhs, rhs, conditions, &values) {
                values.sort_by_key(|(v, _)| *v);
                return Ok(ConstantPoint { values, value });
            }
        }
        Err(format!(
            "no rational point among {CONSTANT_ATTEMPTS} tried makes LHS - RHS non-zero off the conditions"
        ))
    }

    /// `p` at the point, as an element of `Q(theta)` (a polynomial in `c`, reduced).
    fn at(&self, c: Var, p: &Poly<Rational>, values: &[(Var, Rational)]) -> UPoly {
        let mut q = p.clone();
        for (v, x) in values {
            q = q.substitute(*v, &Poly::constant(x.clone()));
        }
        let u = UPoly::from_poly(&q, c).expect("every variable but c has a value");
        self.field.reduce(&u)
    }

    /// `LHS - RHS` at the point when it is defined (no condition vanishes) and not zero.
    fn difference_at(
        &self,
        c: Var,
        lhs: &RatFun<Rational>,
        rhs: &RatFun<Rational>,
        conditions: &[Poly<Rational>],
        values: &[(Var, Rational)],
    ) -> Option<Algebraic> {
        if conditions.iter().any(|p| self.at(c, p, values).is_zero()) {
            return None;
        }
        let (ln, ld) = (
            self.at(c, lhs.numerator(), values),
            self.at(c, lhs.denominator(), values),
        );
        let (rn, rd) = (
            self.at(c, rhs.numerator(), values),
            self.at(c, rhs.denominator(), values),
        );
        let num = self
            .field
            .reduce(&ln.mul_ref(&rd).sub_ref(&rn.mul_ref(&ld)));
        if num.is_zero() {
            return None;
        }
        let inv = self.field.inverse(&self.field.mul(&ld, &rd))?;
        Some(self.field.value(&self.field.mul(&num, &inv)))
    }
}
