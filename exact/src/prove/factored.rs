//! Residuals and normal forms printed factored: the rational content, the monomial factor, then
//! the square-free factors ([`crate::poly::square_free`]), e.g. `-3 w0 w1^2 w2 t^2 (t - 1)^2`.

use super::PointField;
use crate::poly::{square_free, Poly, Var, Vars};
use crate::Rational;
use exactcheck_core::Sign;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::One;
use std::fmt::Display;

/// `p` printed factored over Q: the constant factor (an integer or a fraction, `-` alone for
/// `-1`), the square-free factors in parentheses with their multiplicities, then the monomial
/// factor, all juxtaposed, so the text parses back ([`crate::expr`]) to `p`:
/// `-3 w0 w1^2 w2 t^2 (1 - t)^2` prints `-3 (t - 1)^2 t^2 w0 w1^2 w2`. Each factor with rational
/// coefficients is a primitive integer polynomial with a positive leading coefficient (its
/// content moved into the constant); a factor with irrational coefficients is monic.
///
/// The expanded form ([`Poly::display`]) is printed instead when it is not longer, and when the
/// polynomial is too large to factor quickly ([`crate::poly::factor`]'s bounds).
pub fn factored<C: PointField + Display>(p: &Poly<C>, vars: &Vars) -> String {
    let expanded = p.display(vars).to_string();
    match factored_text(p, vars) {
        Some(f) if f.len() < expanded.len() => f,
        _ => expanded,
    }
}

/// A coefficient as a rational, when it is one.
fn rational<C: PointField>(c: &C) -> Option<Rational> {
    c.to_radical().and_then(|r| r.to_rational())
}

/// The factored text of [`factored`], `None` when not factored.
fn factored_text<C: PointField + Display>(p: &Poly<C>, vars: &Vars) -> Option<String> {
    let f = square_free(p)?;
    let mut unit = f.unit.clone();
    let mut parts: Vec<String> = Vec::new();
    let name = |v: Var| {
        vars.name(v)
            .map_or_else(|| format!("_x{v}"), str::to_string)
    };
    let power = |base: String, e: u32| {
        if e == 1 {
            base
        } else {
            format!("{base}^{e}")
        }
    };
    // The parenthesised factors come before the variables: a name followed by `(` would read
    // as a function call.
    for (factor, e) in &f.factors {
        let factor = match primitive_scale(factor) {
            Some(k) => {
                // factor = (k factor) / k, so the constant takes (1/k)^e.
                let inv = C::from_rational(&k.recip().ok()?)?;
                unit = unit.mul_ref(&inv.pow(*e));
                factor.scale(&C::from_rational(&k)?)
            }
            None => factor.clone(),
        };
        parts.push(power(format!("({})", factor.display(vars)), *e));
    }
    for &(v, e) in &f.monomial {
        parts.push(power(name(v), e));
    }
    let constant = match rational(&unit) {
        Some(q) => q.to_string(),
        None => format!("({unit})"),
    };
    let body = parts.join(" ");
    Some(if body.is_empty() {
        constant
    } else if constant == "1" {
        body
    } else if constant == "-1" {
        format!("-{body}")
    } else {
        format!("{constant} {body}")
    })
}

/// The positive rational `k` that makes `k f` a primitive polynomial with integer coefficients
/// (the lcm of the denominators over the gcd of the numerators), when every coefficient of `f`
/// is rational and `f` is monic (so `k f` has a positive leading coefficient).
fn primitive_scale<C: PointField>(f: &Poly<C>) -> Option<Rational> {
    let qs: Vec<Rational> = f
        .coefficients()
        .iter()
        .map(rational)
        .collect::<Option<_>>()?;
    let mut den = BigInt::one();
    let mut num = BigInt::from(0);
    for q in &qs {
        den = den.lcm(&q.denom());
        num = num.gcd(&q.numer());
    }
    if num == BigInt::from(0) || qs.first().map(Rational::signum) != Some(Sign::Positive) {
        return None;
    }
    Some(Rational::from(den) / Rational::from(num))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_poly;
    use crate::Radical;

    fn check(text: &str, names: &[&str], want: &str) {
        let mut vars = Vars::from_names(names);
        let p: Poly<Rational> = parse_poly(text, &mut vars).unwrap();
        let shown = factored(&p, &vars);
        assert_eq!(shown, want, "{text}");
        // The text parses back to the polynomial.
        assert_eq!(
            parse_poly::<Rational>(&shown, &mut vars).unwrap(),
            p,
            "{shown}"
        );
    }

    #[test]
    fn residuals_print_factored() {
        check(
            "-3 w0 w1^2 w2 t^2 (1-t)^2",
            &["t", "w0", "w1", "w2"],
            "-3 (t - 1)^2 t^2 w0 w1^2 w2",
        );
        check("6 x^3 - 6 x^2 - 6 x + 6", &["x"], "6 (x + 1) (x - 1)^2");
        // Not shorter than the expanded form: that is printed.
        check("6 x^2 - 6", &["x"], "6*x^2 - 6");
        check("-(x + y)^3 / 4", &["x", "y"], "-1/4 (y + x)^3");
        check("(x/2 + 1/3) (x + 1)^2", &["x"], "1/6 (3*x + 2) (x + 1)^2");
        // Nothing to gain: the expanded form.
        check("x^2 + y", &["x", "y"], "y + x^2");
        check("2 x + 1", &["x"], "2*x + 1");
        check("0", &["x"], "0");
        check("-5/3", &["x"], "-5/3");
    }

    #[test]
    fn irrational_coefficients_keep_a_monic_factor() {
        let mut vars = Vars::from_names(["x", "y"]);
        let p: Poly<Radical> = parse_poly("sqrt(2) x^2 (x + sqrt(3) y)^2", &mut vars).unwrap();
        let shown = factored(&p, &vars);
        // The factor is monic in the monomial order (y before x), its leading coefficient 3
        // moved into the constant.
        assert!(shown.starts_with("(3*sqrt(2)) (y + "), "{shown}");
        assert!(shown.ends_with(")^2 x^2"), "{shown}");
        assert_eq!(parse_poly::<Radical>(&shown, &mut vars).unwrap(), p);
    }
}
