//! Polynomials and coefficients back to expression trees ([`Expr`]), so that derived polynomials
//! and exact values print as formulas (text, LaTeX, MathML) with the printers of this module.
//! The conversion lives with the formulas, not with the polynomials, so that polynomials do not
//! depend on formulas.
//!
//! A coefficient type says how one value reads as an expression ([`CoeffExpr`]): a
//! [`Rational`] is a number (a negative one the negation of its magnitude), a [`Radical`] the sum
//! of its terms `c sqrt(m)` by increasing radicand (`c` as `n sqrt(m) / d`), a
//! [`ComplexRadical`] `re + im i`. A polynomial ([`Poly::to_expr`]) is the sum of its terms in
//! the polynomial's order (decreasing monomials), each the coefficient times the powers of the
//! variables by increasing index; a coefficient `1` or `-1` is omitted, a negative coefficient
//! becomes a `-` of the sum, and the zero polynomial is the number 0.

use super::trig::{angles, Angle, Trig};
use super::{AddOp, Expr, ExprKind, MulOp};
use crate::poly::{Poly, Var, Vars};
use crate::radical::{ComplexRadical, Radical};
use crate::ratfun::RatFun;
use crate::rational::Rational;
use exactcheck_core::{Field, Ring, Sign};
use num_bigint::BigInt;

/// A coefficient that reads as an expression tree.
pub trait CoeffExpr {
    /// The value as an expression (module documentation).
    fn to_expr(&self) -> Expr;
}

fn num(n: BigInt) -> Expr {
    Expr::new(ExprKind::Number(Rational::from(n)))
}

impl CoeffExpr for Rational {
    fn to_expr(&self) -> Expr {
        Expr::number(self.clone())
    }
}

/// `|c| sqrt(m)` as `n sqrt(m) / d` (factors `1` and `sqrt(1)` left out).
fn radical_term(m: &crate::radical::Radicand, c: &Rational) -> Expr {
    let (n, d) = (c.numer().magnitude().clone(), c.denom());
    if m.is_one() {
        return Expr::new(ExprKind::Number(
            Rational::from(BigInt::from(n)) / Rational::from(d),
        ));
    }
    let mut items = Vec::new();
    if n != 1u32.into() {
        items.push((MulOp::Times, num(BigInt::from(n))));
    }
    items.push((
        MulOp::Times,
        Expr::new(ExprKind::Sqrt(Box::new(num(BigInt::from(m.to_biguint()))))),
    ));
    if d != 1.into() {
        items.push((MulOp::Divide, num(d)));
    }
    if items.len() == 1 {
        items.pop().expect("one factor").1
    } else {
        Expr::new(ExprKind::Product(items))
    }
}

impl CoeffExpr for Radical {
    fn to_expr(&self) -> Expr {
        let terms = self.terms();
        match terms {
            [] => Expr::new(ExprKind::Number(Rational::ZERO)),
            [(m, c)] => {
                let t = radical_term(m, c);
                if c.signum() == Sign::Negative {
                    Expr::new(ExprKind::Neg(Box::new(t)))
                } else {
                    t
                }
            }
            _ => Expr::new(ExprKind::Sum(
                terms
                    .iter()
                    .map(|(m, c)| {
                        let op = if c.signum() == Sign::Negative {
                            AddOp::Minus
                        } else {
                            AddOp::Plus
                        };
                        (op, radical_term(m, c))
                    })
                    .collect(),
            )),
        }
    }
}

impl CoeffExpr for ComplexRadical {
    fn to_expr(&self) -> Expr {
        if self.im.is_zero() {
            return self.re.to_expr();
        }
        let i = Expr::var("i");
        let im = self.im.to_expr();
        let (negative, mag) = match im.kind {
            ExprKind::Neg(x) => (true, *x),
            other => (false, Expr::new(other)),
        };
        let is_one = matches!(&mag.kind, ExprKind::Number(q) if *q == Rational::from_integer(1));
        let im_term = if is_one {
            i
        } else {
            Expr::new(ExprKind::Product(vec![
                (MulOp::Times, mag),
                (MulOp::Times, i),
            ]))
        };
        let op = if negative { AddOp::Minus } else { AddOp::Plus };
        if self.re.is_zero() {
            if negative {
                Expr::new(ExprKind::Neg(Box::new(im_term)))
            } else {
                im_term
            }
        } else {
            Expr::new(ExprKind::Sum(vec![
                (AddOp::Plus, self.re.to_expr()),
                (op, im_term),
            ]))
        }
    }
}

impl<C: CoeffExpr> Poly<C> {
    /// The polynomial as an expression (module documentation), variables named by `vars`
    /// (a variable without a name in the table is `_x<index>`, as [`Poly::display`] writes).
    pub fn to_expr(&self, vars: &Vars) -> Expr {
        let name = |v: Var| {
            vars.name(v)
                .map_or_else(|| crate::poly::fallback_name(v as usize), str::to_string)
        };
        let mut sum = Vec::new();
        for (mono, c) in self.terms() {
            let coeff = c.to_expr();
            let (negative, mag) = match coeff.kind {
                ExprKind::Neg(x) => (true, *x),
                other => (false, Expr::new(other)),
            };
            let mut factors = Vec::new();
            let is_one =
                matches!(&mag.kind, ExprKind::Number(q) if *q == Rational::from_integer(1));
            let powers = mono.exponents();
            if !is_one || powers.is_empty() {
                factors.push((MulOp::Times, mag));
            }
            for (v, e) in powers {
                let x = Expr::var(&name(v));
                factors.push((
                    MulOp::Times,
                    if e == 1 {
                        x
                    } else {
                        Expr::new(ExprKind::Pow(Box::new(x), Box::new(num(BigInt::from(e)))))
                    },
                ));
            }
            let term = if factors.len() == 1 {
                factors.pop().expect("one factor").1
            } else {
                Expr::new(ExprKind::Product(factors))
            };
            sum.push((if negative { AddOp::Minus } else { AddOp::Plus }, term));
        }
        match sum.len() {
            0 => Expr::new(ExprKind::Number(Rational::ZERO)),
            1 if sum[0].0 == AddOp::Plus => sum.pop().expect("one term").1,
            1 => Expr::new(ExprKind::Neg(Box::new(sum.pop().expect("one term").1))),
            _ => Expr::new(ExprKind::Sum(sum)),
        }
    }
}

/// A rational function as an expression: the numerator, or numerator `/` denominator, each a
/// polynomial as [`Poly::to_expr`] writes it, and every variable of `vars` that stands for a
/// function turned back into the call: a square root of an expression ([`Vars::roots`]) into
/// `sqrt` of its radicand as written, the cosine and sine of an angle variable `x` (named
/// `cos(x)`, `sin(x)`, [`super::trig::angles`]) into the calls `cos(x)` and `sin(x)`. The tree
/// then means the same function without the table.
pub(crate) fn ratfun_to_expr<C: CoeffExpr + Field>(f: &RatFun<C>, vars: &Vars) -> Expr {
    let num = f.numerator().to_expr(vars);
    let tree = if f.denominator().is_one() {
        num
    } else {
        Expr::new(ExprKind::Product(vec![
            (MulOp::Times, num),
            (MulOp::Divide, f.denominator().to_expr(vars)),
        ]))
    };
    let angles = angles(vars);
    with_calls(&tree, vars, &angles)
}

/// `e` with the variables of `vars` that stand for functions replaced by their calls
/// ([`ratfun_to_expr`]).
fn with_calls(e: &Expr, vars: &Vars, angles: &[Angle]) -> Expr {
    let ExprKind::Var(name) = &e.kind else {
        return e.map_children(|x| with_calls(x, vars, angles));
    };
    let Some(v) = vars.get(name) else {
        return e.clone();
    };
    if let Some(root) = vars.roots().iter().find(|r| r.var == v) {
        return Expr::new(ExprKind::Sqrt(Box::new(root.radicand_expr().clone())));
    }
    for a in angles {
        let which = if a.cos == v {
            Trig::Cos
        } else if a.sin == v {
            Trig::Sin
        } else {
            continue;
        };
        return Expr::new(ExprKind::Call(
            which.name().to_string(),
            vec![Expr::var(&a.name)],
        ));
    }
    e.clone()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::{parse_poly, to_latex, Notation};

    fn radical(s: &str) -> Radical {
        s.parse().expect("a radical")
    }

    #[test]
    fn rational_polynomials() {
        let mut vars = Vars::new();
        let p: Poly<Rational> = parse_poly("x^2*y - 3/4*x + 1 - y^3", &mut vars).unwrap();
        let e = p.to_expr(&vars);
        assert_eq!(e.to_string(), "-y^3 + x^2*y - (3/4)*x + 1");
        // It converts back to the same polynomial.
        let mut v2 = vars.clone();
        assert_eq!(parse_poly::<Rational>(&e.to_string(), &mut v2).unwrap(), p);
        assert_eq!(
            to_latex(&e, &Notation::new()),
            "-y^{3} + x^{2}\\,y - \\frac{3}{4}\\,x + 1"
        );
        let neg: Poly<Rational> = parse_poly("-x", &mut vars).unwrap();
        assert_eq!(neg.to_expr(&vars).to_string(), "-x");
        let c: Poly<Rational> = parse_poly("-5/2", &mut vars).unwrap();
        assert_eq!(
            to_latex(&c.to_expr(&vars), &Notation::new()),
            "-\\frac{5}{2}"
        );
        assert_eq!(Poly::<Rational>::zero().to_expr(&vars).to_string(), "0");
        let unnamed: Poly<Rational> = Poly::var(7);
        assert_eq!(unnamed.to_expr(&vars).to_string(), "_x7");
    }

    #[test]
    fn radicals() {
        let n = Notation::new();
        assert_eq!(
            to_latex(&radical("-sqrt(2)/2").to_expr(), &n),
            "-\\frac{\\sqrt{2}}{2}"
        );
        assert_eq!(
            to_latex(&radical("(2*sqrt(2) + sqrt(6))/3").to_expr(), &n),
            "\\frac{2\\,\\sqrt{2}}{3} + \\frac{\\sqrt{6}}{3}"
        );
        assert_eq!(
            to_latex(&radical("1 - 3 sqrt(5)").to_expr(), &n),
            "1 - 3\\,\\sqrt{5}"
        );
        assert_eq!(to_latex(&radical("0").to_expr(), &n), "0");
        for s in [
            "-sqrt(2)/2",
            "(8 - 6*sqrt(2) - 4*sqrt(3) + 3*sqrt(6))/2",
            "7/3",
            "-1 + sqrt(2)",
        ] {
            let r = radical(s);
            assert_eq!(radical(&r.to_expr().to_string()), r, "{s}");
        }
        // A radical coefficient with several terms is a factor in parentheses.
        let mut vars = Vars::from_names(["x"]);
        let p = Poly::var(0).scale(&radical("-1 + sqrt(2)")) - Poly::constant(radical("sqrt(3)"));
        vars.var("x");
        assert_eq!(
            to_latex(&p.to_expr(&vars), &n),
            "\\left(-1 + \\sqrt{2}\\right)\\,x - \\sqrt{3}"
        );
        let z = ComplexRadical::new(radical("1/2"), radical("-sqrt(3)/2"));
        assert_eq!(
            to_latex(&z.to_expr(), &n),
            "\\frac{1}{2} - \\frac{\\sqrt{3}}{2}\\,i"
        );
        let i = ComplexRadical::new(radical("0"), radical("1"));
        assert_eq!(i.to_expr().to_string(), "i");
    }
}
