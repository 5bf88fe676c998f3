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

use super::{small_height_rationals, unit_circle_pairs, VarDomain};
use crate::algebraic::{primitive_element, FieldError, NumberField};
use crate::expr::{fill_constants, upoly_expr, ConstantLeaf, Expr};
use crate::poly::{Poly, Var};
use crate::ratfun::RatFun;
use crate::univariate::UPoly;
use crate::{Algebraic, Radical, Rational};
use exactcheck_core::{Ring, Rng};

/// The constants of a statement as polynomials in one primitive element `c`: see the module
/// documentation of `exact/src/prove/constants.rs`.
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
    /// The value of every variable of the statement but `c` and pi.
    pub values: Vec<(Var, Rational)>,
    /// `LHS - RHS` there, exactly (not zero).
    pub value: ConstantValue,
}

/// The value of `LHS - RHS` at a [`ConstantPoint`].
#[derive(Clone, Debug, PartialEq)]
pub enum ConstantValue {
    /// A non-zero element of `Q(theta)`.
    Number(Algebraic),
    /// With pi in the statement: `numerator / denominator`, polynomials in pi and `c` whose
    /// coefficients (polynomials in `c`) are reduced modulo the minimal polynomial of `theta`,
    /// the numerator of positive degree in pi or the denominator not constant. Pi is
    /// transcendental over the algebraic numbers, so a polynomial in pi with coefficients in
    /// `Q(theta)` is zero at pi only when every coefficient is: the value is not zero.
    InPi {
        /// Not zero.
        numerator: Poly<Rational>,
        /// Not zero; 1 when free of pi (its inverse in `Q(theta)` is in the numerator).
        denominator: Poly<Rational>,
    },
}

/// Terms of a polynomial as their exponents and coefficients.
type TermList = Vec<(Vec<(Var, u32)>, Rational)>;

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
    pub fn domain(&self) -> VarDomain {
        let iv = self.field.generator().interval();
        VarDomain {
            lower: Some((iv.lo.clone(), true)),
            upper: Some((iv.hi.clone(), true)),
            integer: false,
        }
    }

    /// `theta` as written: the constant, or the integer combination of the constants.
    fn generator_text(&self) -> String {
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
        theta
    }

    /// `with c = cos(pi/5), 4*c^2 - 2*c - 1 = 0`: the constant introduced and its minimal
    /// polynomial, then every other constant as a polynomial in `c`
    /// (`with c = sin(pi/5), 16*c^4 - 20*c^2 + 5 = 0, cos(pi/5) = -2*c^2 + 3/2`).
    pub fn description(&self) -> String {
        let c = &self.name;
        let mut text = format!(
            "with {c} = {}, {}",
            self.generator_text(),
            self.relation_text()
        );
        for (l, p) in self.leaves.iter().zip(&self.polys) {
            if *p != UPoly::x() {
                text += &format!(", {} = {}", l.text, p.display(c));
            }
        }
        text
    }

    /// An exact counter-example to `lhs = rhs` with `c = theta` (the variable `c`): rational
    /// values of the other variables (small heights first, inside `domains`; an angle's cosine
    /// and sine at a rational point of its unit circle), where no condition vanishes and
    /// `LHS - RHS` is a non-zero element of `Q(theta)`. `relations` are those besides `m(c)`;
    /// only unit circles are supported. The variable `pi` (when the statement has pi) gets no
    /// value: `LHS - RHS` is then a polynomial in pi with coefficients in `Q(theta)`, and it is
    /// not zero at pi exactly when one of its coefficients is not zero (pi is transcendental);
    /// a condition vanishes there only when all of its coefficients do.
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
        domains: &[(Var, VarDomain)],
        pi: Option<Var>,
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
                if v != c && Some(v) != pi && !vars.contains(&v) {
                    vars.push(v);
                }
            }
        }
        vars.sort_unstable();
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
            if let Some(value) = self.difference_at(c, pi, lhs, rhs, conditions, &values) {
                values.sort_by_key(|(v, _)| *v);
                return Ok(ConstantPoint { values, value });
            }
        }
        Err(format!(
            "no rational point among {CONSTANT_ATTEMPTS} tried makes LHS - RHS non-zero off the conditions"
        ))
    }

    /// `p` at the point, by powers of pi (one entry without pi): each coefficient an element of
    /// `Q(theta)`, a polynomial in `c` reduced modulo the minimal polynomial.
    fn at(
        &self,
        c: Var,
        pi: Option<Var>,
        p: &Poly<Rational>,
        values: &[(Var, Rational)],
    ) -> Vec<UPoly> {
        let mut q = p.clone();
        for (v, x) in values {
            q = q.substitute(*v, &Poly::constant(x.clone()));
        }
        let degree = pi.map_or(0, |pi| q.degree_in(pi));
        let mut by_power: Vec<TermList> = vec![Vec::new(); degree as usize + 1];
        for (m, coefficient) in q.terms() {
            let k = pi.map_or(0, |pi| m.exponent(pi));
            let rest: Vec<(Var, u32)> = m
                .exponents()
                .into_iter()
                .filter(|(v, _)| Some(*v) != pi)
                .collect();
            by_power[k as usize].push((rest, coefficient.clone()));
        }
        let mut out: Vec<UPoly> = by_power
            .into_iter()
            .map(|terms| {
                let u = UPoly::from_poly(&Poly::from_terms(terms), c)
                    .expect("every variable but c and pi has a value");
                self.field.reduce(&u)
            })
            .collect();
        while out.len() > 1 && out.last().is_some_and(UPoly::is_zero) {
            out.pop();
        }
        out
    }

    /// A polynomial in pi with coefficients in `Q(theta)` (by powers of pi) as a polynomial in
    /// `c` and pi.
    fn in_pi(c: Var, pi: Option<Var>, coefficients: &[UPoly]) -> Poly<Rational> {
        let mut total = Poly::zero();
        for (k, u) in coefficients.iter().enumerate() {
            let power = match pi {
                Some(pi) if k > 0 => Poly::monomial(Rational::ONE, &[(pi, k as u32)]),
                _ => Poly::constant(Rational::ONE),
            };
            total += u.to_poly(c) * power;
        }
        total
    }

    /// `LHS - RHS` at the point when it is defined (no condition vanishes) and not zero.
    fn difference_at(
        &self,
        c: Var,
        pi: Option<Var>,
        lhs: &RatFun<Rational>,
        rhs: &RatFun<Rational>,
        conditions: &[Poly<Rational>],
        values: &[(Var, Rational)],
    ) -> Option<ConstantValue> {
        let zero = |p: &[UPoly]| p.iter().all(UPoly::is_zero);
        if conditions.iter().any(|p| zero(&self.at(c, pi, p, values))) {
            return None;
        }
        let cross = lhs.numerator().clone() * rhs.denominator()
            - rhs.numerator().clone() * lhs.denominator();
        let num = self.at(c, pi, &cross, values);
        let den = self.at(
            c,
            pi,
            &(lhs.denominator().clone() * rhs.denominator()),
            values,
        );
        if zero(&num) || zero(&den) {
            return None;
        }
        match (num.as_slice(), den.as_slice()) {
            ([n], [d]) => {
                let inv = self.field.inverse(d)?;
                Some(ConstantValue::Number(
                    self.field.value(&self.field.mul(n, &inv)),
                ))
            }
            (_, [d]) => {
                let inv = self.field.inverse(d)?;
                let scaled: Vec<UPoly> = num.iter().map(|n| self.field.mul(n, &inv)).collect();
                Some(ConstantValue::InPi {
                    numerator: Self::in_pi(c, pi, &scaled),
                    denominator: Poly::constant(Rational::ONE),
                })
            }
            _ => Some(ConstantValue::InPi {
                numerator: Self::in_pi(c, pi, &num),
                denominator: Self::in_pi(c, pi, &den),
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::{abstract_constants, angles, parse_expr, Angle};
    use crate::poly::Vars;
    use crate::prove::{decide_identity, IdentitySpec, IdentityVerdict, Statement};
    use proptest::prelude::*;

    /// The outcome of `lhs = rhs` decided as `prove` decides it: proved, or the counter-example.
    enum Outcome {
        Proved,
        Fails(Box<(Vars, ConstantPoint)>),
        Undecided,
    }

    fn decide(lhs: &str, rhs: &str) -> (Outcome, AlgebraicConstants) {
        let mut leaves = Vec::new();
        let l = abstract_constants(&parse_expr(lhs).unwrap(), &mut leaves).unwrap();
        let r = abstract_constants(&parse_expr(rhs).unwrap(), &mut leaves).unwrap();
        let k = AlgebraicConstants::new(leaves, &["x".to_string()])
            .unwrap()
            .expect("the statement has constants");
        let mut vars = Vars::new();
        let l: RatFun<Rational> = k.fill(&l).to_ratfun(&mut vars).unwrap();
        let r: RatFun<Rational> = k.fill(&r).to_ratfun(&mut vars).unwrap();
        let m: Poly<Rational> = k.relation().to_poly(&mut vars).unwrap();
        let c = vars.get(&k.name).unwrap();
        let circles: Vec<Poly<Rational>> = angles(&vars).iter().map(Angle::relation).collect();
        let one = |p: &Poly<Rational>| {
            (
                RatFun::from_poly(p.clone()),
                RatFun::from_poly(Poly::zero()),
            )
        };
        let mut spec =
            IdentitySpec::new(vars.clone(), vec![Statement::Sides(l.clone(), r.clone())]);
        spec.relations = circles.iter().chain([&m]).map(one).collect();
        spec.domains = vec![(c, k.domain())];
        let report = decide_identity(&spec).unwrap();
        let outcome = match &report.verdict {
            IdentityVerdict::Proved { .. } => Outcome::Proved,
            // The engine's own counter-example (a quadratic m, solved in the square-root
            // field) or none: the search at c = theta is checked either way.
            IdentityVerdict::Fails { .. } | IdentityVerdict::Undecided { .. } => {
                let pi = vars.get(crate::expr::PI);
                match k.counter_example(c, &l, &r, &circles, &report.conditions, &spec.domains, pi)
                {
                    Ok(p) => Outcome::Fails(Box::new((vars, p))),
                    Err(_) => Outcome::Undecided,
                }
            }
        };
        (outcome, k)
    }

    /// The cosine and sine of `x` at the point, as floats.
    fn angle_at(vars: &Vars, p: &ConstantPoint) -> f64 {
        let get = |name: &str| {
            let v = vars.get(name).unwrap();
            p.values.iter().find(|(w, _)| *w == v).unwrap().1.to_f64()
        };
        get("sin(x)").atan2(get("cos(x)"))
    }

    #[test]
    fn constants_next_to_variables() {
        assert!(matches!(
            decide("x*cos(2*pi/7)", "x*(2*cos(pi/7)^2 - 1)").0,
            Outcome::Proved
        ));
        assert!(matches!(
            decide("x + cos(pi/5)", "x + (1 + sqrt(5))/4").0,
            Outcome::Proved
        ));
        assert!(matches!(
            decide("x*sqrt(2 + sqrt(2))", "2*x*cos(pi/8)").0,
            Outcome::Proved
        ));
        let (o, k) = decide("x*cos(2*pi/7)", "x/2");
        assert_eq!(
            k.description(),
            "with c = cos(2*pi/7), 8*c^3 + 4*c^2 - 4*c - 1 = 0"
        );
        let Outcome::Fails(found) = o else {
            panic!("expected a counter-example")
        };
        let p = found.1;
        // At x = 1: cos(2 pi/7) - 1/2, checked against the number computed on its own.
        let want: Algebraic = "cos(2*pi/7) - 1/2".parse().unwrap();
        assert_eq!(p.value, ConstantValue::Number(want));
        let (_, k) = decide("x*cos(pi/5)", "x*sqrt(5)");
        assert_eq!(k.field.degree(), 2);
        assert!(
            k.description().contains("sqrt(5) = 4*c - 1"),
            "{}",
            k.description()
        );
    }

    #[test]
    fn pi_stays_pi_in_the_counter_example() {
        // c + pi: not zero, as pi is transcendental over Q(sin(pi/7)).
        let (o, _) = decide("x + pi + sin(pi/7)", "x");
        let Outcome::Fails(found) = o else {
            panic!("expected a counter-example")
        };
        let (vars, p) = *found;
        let ConstantValue::InPi {
            numerator,
            denominator,
        } = &p.value
        else {
            panic!("expected a value in pi, got {:?}", p.value)
        };
        assert_eq!(numerator.display(&vars).to_string(), "c + pi");
        assert!(Ring::is_one(denominator));
        assert!(p.values.iter().all(|(v, _)| vars.name(*v) == Some("x")));
        // Pi divides: the value is a fraction of polynomials in pi and c.
        let (o, _) = decide("x + cos(pi/7)/pi", "x");
        let Outcome::Fails(found) = o else {
            panic!("expected a counter-example")
        };
        let ConstantValue::InPi { denominator, .. } = &found.1.value else {
            panic!("expected a value in pi")
        };
        assert_eq!(denominator.display(&found.0).to_string(), "pi");
        // Pi that cancels leaves a number.
        let (o, _) = decide("x*pi + sin(pi/7)", "pi*x");
        let Outcome::Fails(found) = o else {
            panic!("expected a counter-example")
        };
        assert!(matches!(found.1.value, ConstantValue::Number(_)));
        assert!(matches!(
            decide("pi*sin(pi/7) + x", "x + sin(pi/7)*pi").0,
            Outcome::Proved
        ));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        /// The addition formula with a constant angle `(p/q) pi`, `q` in 5, 7, 8, 10, is proved;
        /// perturbed by a rational it fails with LHS - RHS exactly minus the perturbation; with
        /// the wrong constant angle it fails with the value the floating-point evaluation of
        /// the two sides at the counter-example gives.
        #[test]
        fn addition_formulas_with_constant_angles(
            qi in 0usize..4, p in 1i64..10, sine in any::<bool>(), n in -5i64..=5, d in 1i64..=4,
        ) {
            let q = [5i64, 7, 8, 10][qi];
            let p = p % (2 * q);
            prop_assume!(p % q != 0 && 2 * p % q != 0);
            let a = format!("{p}*pi/{q}");
            let (lhs, rhs) = if sine {
                (format!("sin(x + {a})"), format!("sin(x)*cos({a}) + cos(x)*sin({a})"))
            } else {
                (format!("cos(x + {a})"), format!("cos(x)*cos({a}) - sin(x)*sin({a})"))
            };
            prop_assert!(matches!(decide(&lhs, &rhs).0, Outcome::Proved));
            let shift = Rational::new(n, d).unwrap();
            prop_assume!(!shift.is_zero());
            let (o, _) = decide(&lhs, &format!("{rhs} + ({shift})"));
            let Outcome::Fails(found) = o else { panic!("{lhs} = {rhs} + {shift}: no counter-example") };
            let pt = found.1;
            prop_assert_eq!(pt.value, ConstantValue::Number(Algebraic::from_rational(-shift)));
            // The wrong angle: (p + 1) pi/q in the right side.
            let b = format!("{}*pi/{q}", p + 1);
            let wrong = rhs.replace(&a, &b);
            let (o, _) = decide(&lhs, &wrong);
            let Outcome::Fails(found) = o else { panic!("{lhs} = {wrong}: no counter-example") };
            let (vars, pt) = *found;
            let x = angle_at(&vars, &pt);
            let (ta, tb) = (
                p as f64 * std::f64::consts::PI / q as f64,
                (p + 1) as f64 * std::f64::consts::PI / q as f64,
            );
            let float = if sine {
                (x + ta).sin() - (x.sin() * tb.cos() + x.cos() * tb.sin())
            } else {
                (x + ta).cos() - (x.cos() * tb.cos() - x.sin() * tb.sin())
            };
            let ConstantValue::Number(value) = &pt.value else { panic!("no pi in {lhs} = {wrong}") };
            let (lo, hi) = value.enclosure(60);
            prop_assert!(float.abs() > 1e-9);
            prop_assert!((lo.to_f64() - float).abs() < 1e-9 && (hi.to_f64() - float).abs() < 1e-9);
        }
    }
}
