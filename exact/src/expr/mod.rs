//! Expressions: the one grammar for every textual number or polynomial in the workspace. A parser
//! to an AST with positions, the conversion of the AST to a [`Poly`](crate::poly::Poly) over any coefficient type
//! implementing [`Coefficient`], the exact evaluation of constant expressions
//! ([`Expr::eval_constant`]) and a printer.
//!
//! Every entry point reads text through [`parse_expr`]: `prove` and the claim catalogue (via
//! [`parse_poly`]), and the `FromStr` of [`Rational`], [`crate::Radical`] and
//! [`crate::ComplexRadical`] (every number string of `solve`), which parse and then evaluate the
//! constant expression exactly in their type. So `"2 sqrt(4)"`, `"1e3"` and `"(2+sqrt(2))/3"` mean
//! the same everywhere, and the limits below hold for every input. The parser is hand-written
//! recursive descent: the grammar is small, and positions, the juxtaposition rule, the lexing of
//! scientific notation and the error messages are easier to control than with a generator.
//!
//! # Syntax
//! ```text
//! sum      := product (('+' | '-') product)*
//! product  := unary (('*' | '/') unary | implicit)*
//! implicit := power                          (juxtaposition, not starting with a number)
//! unary    := ('-' | '+') unary | power
//! power    := atom '°'? '!'? ('^' exponent)?   ('°': degrees, `atom * pi/180`; '!': factorial)
//! exponent := ('-' | '+') exponent | atom ('^' exponent)?   (right-associative)
//! atom     := number | variable | 'sqrt' '(' sum ')' | call | '(' sum ')' | '|' sum '|' | list
//! list     := '[' sum (',' sum)* ']'           (with calls only: vectors and matrices, see [`library`])
//! call     := 'diff' '(' sum ',' variable (',' sum)? ')'
//!           | 'integrate' '(' sum ',' variable ',' sum ',' sum ')'
//!           | 'sum' '(' variable ',' sum ',' sum ',' sum ')'
//!           | 'binomial' '(' sum ',' sum ')' | 'factorial' '(' sum ')'
//! number   := [0-9]+ ('.' [0-9]+)? ([eE] [+-]? [0-9]+)?
//! variable := [A-Za-z_][A-Za-z0-9_]*          (not followed by '('; not the word sqrt)
//! ```
//! White space may appear between tokens.
//!
//! The notation of typeset mathematics, as text copied from a paper has it, reads as the ASCII
//! it stands for: `−` (U+2212) is `-`; `∗` is `*`; `·`, `⋅` and `×` are the products
//! [`MulOp::Dot`] and [`MulOp::Cross`] (`*` between scalars); `÷`, `∕` are `/`; `π` is `pi`
//! (a token of its own, so `2πr` is `2*pi*r`); superscripts are exponents (`x²` is `x^2`, `x⁻¹`
//! is `x^-1`); `√` is the square root of the atom after it (`√2`, `√(x² + y²)`, `√2 x` is
//! `sqrt(2)*x`). `√x²` is refused: it is printed for both `√(x²)` and `(√x)²`.
//!
//! * **Numbers are exact**: a decimal is the fraction it denotes (`0.1 = 1/10`), and scientific
//!   notation is read exactly (`1e3 = 1000`, `2.5e-3 = 1/400`, `1E+5`, `5e0`). The exponent
//!   belongs to the number only when `e`/`E` follows the digits directly and is followed by an
//!   optional sign and at least one digit; otherwise `2e` is the product `2*e` of the number 2
//!   and the variable `e`, and `2e+x` is `2*e + x`.
//! * **Juxtaposition multiplies**, binding like `*`: `2x`, `2 sqrt(2)`, `x y`, `(a+b)(a-b)`,
//!   `c^2 x^3`. A juxtaposed factor takes no sign of its own (`x -y` is a difference) and may not
//!   start with a number (`2 3` and `x 2` are errors: write `*`).
//! * **Functions**: `sqrt`, `abs`, `diff`, `integrate`, `sum`, `binomial`, `factorial` ([`FUNCTIONS`]).
//!   `abs(E)` is `|E| = sqrt(E^2)`: the root variable of `E^2`, or the absolute value of a constant. A name followed directly by `(` is a function
//!   call, so `sn(x)` is the error `unknown function 'sn'` rather than the product `sn*(x)`;
//!   write the `*` for a product (`x*(y+1)`), or a space as printed: `t (1 - t)` is a product
//!   unless the name is a function (`sqrt (x)` is still `sqrt(x)`). `diff(E, t)` is the exact derivative of `E` in the
//!   variable `t` (the second argument must be a variable name), `diff(E, t, k)` the `k`-th, `k`
//!   a non-negative integer constant within the `diff-order` limit ([`limits::DIFF_ORDER`]); of a
//!   fraction by the quotient rule ([`crate::ratfun::RatFun::derivative`]).
//!   `integrate(E, t, a, b)` is the definite integral of a polynomial in `t` (coefficients may
//!   be fractions free of `t`; the bounds any expressions), `sum(k, a, b, E)` the sum over the
//!   integers `k` from `a` to `b` (integer constants: at most `sum-terms` terms,
//!   [`limits::SUM_TERMS`]; or polynomials with integer coefficients in other variables, for
//!   a polynomial `E` in `k`, summed in closed form), `binomial(n, k)` and `factorial(n)` exact integers of integer
//!   constants (held to `constant-bits`). The index of a sum and the variable of an integral
//!   are bound ([`Expr::collect_variables`] skips them). In an exponent, a name that is not a
//!   function followed by `(` is the exponent, and the `(` starts the next juxtaposed factor
//!   (`t^i (1-t)^(3-i)`).
//! * `^` binds tighter than unary minus (`-x^2 = -(x^2)`) and is right-associative
//!   (`x^2^3 = x^8`). Its exponent must evaluate to an integer constant with absolute value at
//!   most the `exponent` limit ([`limits::EXPONENT`]); it may carry a sign (`2^-3 = 1/8`), but a negative exponent needs a
//!   non-zero constant base in [`Expr::to_poly`]. Likewise [`Expr::to_poly`] divides only by an
//!   expression that evaluates to a non-zero constant (`3/4*x`). [`Expr::to_ratfun`] divides by
//!   (and takes negative powers of) any expression that is not identically zero: the result is
//!   a rational function ([`crate::ratfun::RatFun`]) in lowest terms with the divisors met, and
//!   an expression without such a division converts by [`Expr::to_poly`] alone.
//! * **Absolute value**: `|E|` is `abs(E)`. A `|` where an operand is expected opens an
//!   absolute value; a `|` after an operand closes the innermost one open at that level of
//!   parentheses, or, when none is open there, opens one as a juxtaposed factor. So
//!   `||x| - 1|` nests, `|a|*|b|` and `2|x|` are products, and a bar never closes one opened
//!   outside the parentheses it is in. A closing bar followed by a factor without an operator,
//!   with at least two bars after it at that level beyond those the open ones need, is refused
//!   as ambiguous, naming its position: `|a|b|c|` is both `|a|*b*|c|` and `|a*|b|*c|`.
//! * **Factorial**: `!` after an atom is `factorial(atom)`: `5!`, `n!`, `(n - k)!`; `n!^2` is
//!   `(n!)^2`. `n!!` (the double factorial) and a `!` in an exponent (`2^3!`) are refused.
//! * **Degrees**: `°` after an atom multiplies it by `pi/180`, so `cos(45°)` is `cos(pi/4)` and
//!   `(a + b)°` the angle `a + b` in degrees.
//! * `sqrt(E)` of a non-constant `E` is a variable standing for the non-negative root, one per
//!   distinct expanded radicand (a rational function in [`Expr::to_ratfun`], with the radicand's
//!   divisors as conditions), when the variable table allows it
//!   ([`crate::poly::Vars::allow_roots`]; its relation and sign condition come from
//!   [`crate::prove::square_roots`]), else [`ExprError::NonConstantSqrt`].
//! * `sqrt(...)` of a constant needs a coefficient type that has the root (over
//!   [`Rational`], only of perfect squares; [`crate::Radical`] denests; [`crate::ComplexRadical`]
//!   takes the principal root).
//! * A variable in a constant context ([`Expr::eval_constant`]) is an error naming it, except
//!   the names the target type defines ([`Coefficient::named_constant`]: `i` for
//!   [`crate::ComplexRadical`]).
//!
//! # Limits
//! No input makes the parser, the conversion or the evaluation panic or allocate without bound.
//! Every bound is a named limit of the one registry [`exactcheck_core::limits`] (raised on the
//! command line with `--limit NAME=VALUE`), read where it is checked, and exceeding it is the one
//! error [`ExprError::Limit`] with the position:
//! * `depth`: nesting of parentheses, signs and exponents;
//! * `digits`: the digits written in a number plus the absolute value of its decimal exponent
//!   (`1e5000` counts 5001: the value has that many digits);
//! * `exponent`: `|k|` of a `^` exponent; a variable's exponent must also fit in `u32`;
//! * `constant-bits`: every constant (a number, a folded constant, a polynomial coefficient).
//!   Powers are **predicted** before they are computed (the size of `c^k` is at least `k` times
//!   that of `c`, [`Coefficient::size_bits`]), and every product and power is checked after it
//!   is computed, so no intermediate result exceeds about twice the limit:
//!   `((2^10000)^10000)^10000` is refused at once;
//! * `variables`: the index of a new variable (the packed monomials are dense in the index, so
//!   the index, not only the count, sets the memory of every term);
//! * `degree`: the total degree of a product or power, predicted (the degrees add, a power
//!   multiplies) before it is expanded;
//! * `terms`: the terms of every polynomial, counted as a product's terms are produced
//!   ([`Poly::try_mul`](crate::poly::Poly::try_mul)), so an expansion stops at the limit
//!   instead of first allocating the whole result; a product whose terms would take more than
//!   a quarter of the `memory` limit (many variables make every term large) stops there too.
//!
//! # Conversion
//! [`Expr::to_poly`] expands bottom-up with the fast polynomial arithmetic of [`crate::poly`]:
//! sums are added pairwise (balanced), the factors of a product multiplied smallest first with
//! the constant factors folded into one scalar, powers by binary powering. Variables are looked
//! up (and added) in a [`Vars`](crate::poly::Vars) table, in order of first appearance. [`Expr::eval_constant`]
//! evaluates a constant expression in any [`Coefficient`] type with the same rules and limits.
//!
//! # Layout
//! Here: the limits, the AST and the errors (the [`Coefficient`] trait is re-exported from its
//! leaf module [`crate::coefficient`]); `numbers`: `FromStr` of the exact number types; `parse`: the lexer and
//! the parser; `eval`: the conversion to polynomials and the constant evaluator with the size
//! limits; `fraction`: the conversion to rational functions and the arguments of `diff`;
//! `calculus`: `integrate`, `sum`, `binomial` and `factorial`; `symbolic_sum`: the closed form
//! of a sum whose bound has a variable; [`library`]: definitions,
//! functions with parameters, vectors, matrices and the vector/Bezier functions, resolved to
//! core trees; [`lower`]: the core calls rewritten as plain arithmetic for the front ends that
//! evaluate a tree operation by operation; `map`: the one rebuild of a node from its mapped children ([`Expr::map_children`]) and the positions of built trees; `print`: the printer; `latex`: LaTeX ([`to_latex`]) with a [`Notation`] for names, from
//! a layout shared with `mathml` ([`to_mathml`]).
//!
//! # Errors
//! Every error is an [`ExprError`] with the byte position of the offending token or
//! sub-expression, e.g. `unexpected ')' at 14: expected a number, a variable or '('`.
use crate::rational::Rational;
use exactcheck_core::limits::{self, LimitError};
use exactcheck_core::Ring;
use num_bigint::BigInt;
use num_traits::Signed;

mod angle_base;
mod calculus;
#[cfg(test)]
mod calculus_tests;
mod constants;
mod derivative;
mod eval;
mod fraction;
mod from_poly;
mod latex;
pub mod library;
mod lower;
mod map;
mod mathml;
mod numbers;
mod parse;
mod print;
mod roots;
mod symbolic_sum;
#[cfg(test)]
mod tests;
mod trig;
mod trig_integral;

pub use constants::{
    abstract_constants, fill_constants, needs_algebraic, upoly_expr, ConstantLeaf,
};
pub use fraction::ratfun_sides;
pub use from_poly::CoeffExpr;
pub use latex::{equation_to_latex, to_latex, Notation};
pub use lower::{eval_lowered, lower};
pub use mathml::{equation_to_mathml, to_mathml};
pub use numbers::{ParseRadicalError, ParseRationalError};
pub use parse::{is_latex, parse_expr, parse_expr_with_calls, parse_poly, split_equation, LIST};
pub use roots::{abs_radicand, ABS};
pub use symbolic_sum::symbolic_sum_ranges;

/// The functions written `name(arg, ...)` in every grammar (besides `sqrt`): `diff(E, t)` and
/// `diff(E, t, k)`, the exact derivative of `E` in the variable `t` (`k` times);
/// `integrate(E, t, a, b)`, the definite integral of a polynomial in `t`; `sum(k, a, b, E)`,
/// the sum of `E` over the integers `k` from `a` to `b`; `binomial(n, k)` and `factorial(n)`
/// of integer constants; the trigonometric functions [`TRIG_FUNCTIONS`]; `abs(E)`, the absolute
/// value `|E| = sqrt(E^2)` ([`ABS`]).
pub const FUNCTIONS: &[&str] = &[
    "abs",
    "diff",
    "integrate",
    "sum",
    "binomial",
    "factorial",
    "sin",
    "cos",
    "tan",
];

/// Whether `name` is a constant of mathematics that a formula may never use as a free variable
/// (`e`, `i`): the one-line reason, or `None` for any other name. `prove` and claims files
/// refuse such a variable rather than treat `e*r` as a polynomial in a variable `e`. `pi` is not
/// refused here: the expression language gives it its meaning ([`PI`]), and the callers decide
/// identities in it as the transcendental constant.
pub fn reserved_constant(name: &str) -> Option<&'static str> {
    match name {
        "e" => Some(
            "e is the constant e (Euler's number), not a variable; name the variable differently (e.g. e1)",
        ),
        "i" => Some(
            "i is the imaginary unit, not a variable; name the variable differently (e.g. k)",
        ),
        _ => None,
    }
}

/// The first free variable of `exprs` that is a [`reserved_constant`], with its reason.
pub fn first_reserved<'a>(exprs: impl IntoIterator<Item = &'a Expr>) -> Option<&'static str> {
    let mut names = Vec::new();
    for e in exprs {
        e.collect_variables(&mut names);
    }
    names.iter().find_map(|n| reserved_constant(n))
}
pub use angle_base::{
    angle_variable, constant_base, lindemann_weierstrass, register_angle_bases, variable_base, Base,
};
pub use trig::{
    angle_of, angles, cos_name, describe_point, expand_angles, expand_angles_in,
    has_constant_angle, has_trig, sin_name, trig_constant, Angle, Trig, TrigRefusal,
    TRIG_DENOMINATORS,
};

/// The trigonometric functions (`sin`, `cos`, `tan` of an angle: a rational combination of angle
/// variables plus a rational number and a rational multiple of [`PI`]); see [`Trig`].
pub const TRIG_FUNCTIONS: &[&str] = &["sin", "cos", "tan"];

/// The name of the constant pi. It is never a free variable: in a constant it has no exact
/// value (it is transcendental) except inside [`TRIG_FUNCTIONS`]; a polynomial conversion keeps
/// it as an indeterminate of that name, which a caller deciding an identity treats as the
/// transcendental constant (an identity in pi holds iff it holds with pi indeterminate).
pub const PI: &str = "pi";

// ------------------------------------------------------------------------------ coefficients

pub(crate) use crate::coefficient::log2_floor;
pub use crate::coefficient::Coefficient;

// ------------------------------------------------------------------------------ AST

/// `+` or `-` in a sum.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AddOp {
    /// Addition.
    Plus,
    /// Subtraction.
    Minus,
}

/// `*` or `/` in a product.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MulOp {
    /// Multiplication.
    Times,
    /// Division (by a non-zero constant, or by a non-zero polynomial in [`Expr::to_ratfun`]).
    Divide,
    /// A product written `\cdot` in LaTeX (`·`, `⋅` in text): the dot product between two
    /// vectors ([`library`] resolves it by shape), else [`MulOp::Times`].
    Dot,
    /// A product written `\times` in LaTeX (`×` in text): the cross product between two
    /// vectors ([`library`]), else [`MulOp::Times`].
    Cross,
}

impl MulOp {
    /// Whether the operator divides (every other one multiplies scalars).
    pub fn divides(self) -> bool {
        self == MulOp::Divide
    }
}

/// A parsed expression: a node and the byte position where it starts in the source.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What the node is.
    pub kind: ExprKind,
    /// The byte offset of its first token in the source (0 for built nodes, if one likes).
    pub pos: usize,
}

/// The kinds of [`Expr`] nodes. Sums and products are n-ary, so long chains stay shallow.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A number (the parser produces non-negative integers and decimals).
    Number(Rational),
    /// A variable by name.
    Var(String),
    /// Unary minus.
    Neg(Box<Expr>),
    /// `t_0 op_1 t_1 op_2 t_2 ...`; the first operator applies to the first term (the parser
    /// always gives `Plus` there).
    Sum(Vec<(AddOp, Expr)>),
    /// `f_0 op_1 f_1 ...`; the first operator applies to the first factor (`Divide` there means
    /// `1 / f_0`; the parser always gives `Times`).
    Product(Vec<(MulOp, Expr)>),
    /// `base ^ exponent`.
    Pow(Box<Expr>, Box<Expr>),
    /// `sqrt(arg)`.
    Sqrt(Box<Expr>),
    /// `name(arg, ...)`: a function call. The functions of the language ([`FUNCTIONS`]: `diff`)
    /// are converted; any other name is produced only by [`parse_expr_with_calls`] and resolved
    /// by its caller, and the conversions to polynomials and constants refuse it
    /// ([`ExprError::UnknownFunction`]). With the empty name it is a tuple `(a, b, ...)`
    /// ([`Expr::tuple`]: a vector in an erratum), printed but never parsed.
    Call(String, Vec<Expr>),
}

impl Expr {
    /// A node at position 0 (for building expressions in code).
    pub fn new(kind: ExprKind) -> Self {
        Expr { kind, pos: 0 }
    }

    /// Appends the variables of the tree to `out`, in order of first appearance, each once
    /// (names already in `out` are not repeated): the one walk `prove` and the claims files use
    /// to name the variables of their sides. The index of a `sum` and the variable of an
    /// `integrate` are bound in their body and not collected from it.
    pub fn collect_variables(&self, out: &mut Vec<String>) {
        match &self.kind {
            ExprKind::Number(_) => {}
            ExprKind::Var(v) => {
                if !out.contains(v) {
                    out.push(v.clone());
                }
            }
            ExprKind::Neg(x) | ExprKind::Sqrt(x) => x.collect_variables(out),
            ExprKind::Pow(a, b) => {
                a.collect_variables(out);
                b.collect_variables(out);
            }
            ExprKind::Sum(ts) => ts.iter().for_each(|(_, t)| t.collect_variables(out)),
            ExprKind::Product(fs) => fs.iter().for_each(|(_, f)| f.collect_variables(out)),
            ExprKind::Call(name, args) => calculus::collect_call_variables(name, args, out),
        }
    }

    /// The variable `name`.
    pub fn var(name: &str) -> Self {
        Expr::new(ExprKind::Var(name.to_string()))
    }

    /// The number `q` (a negative `q` is built as the negation of `|q|`, as the parser would).
    pub fn number(q: Rational) -> Self {
        if q.signum() == exactcheck_core::Sign::Negative {
            Expr::new(ExprKind::Neg(Box::new(Expr::new(ExprKind::Number(-q)))))
        } else {
            Expr::new(ExprKind::Number(q))
        }
    }

    /// The tuple `(items...)`: a call with the empty name (a vector, e.g. a control point).
    pub fn tuple(items: Vec<Expr>) -> Self {
        Expr::new(ExprKind::Call(String::new(), items))
    }

    /// A decimal shown as printed (`0.3330`, `-1.5`: the digits kept, trailing zeros too), for
    /// errata that quote a paper's decimals: a call without arguments whose name is the digits
    /// ([`is_decimal_name`]), printed as the digits in every notation (a negative one is the
    /// negation of its magnitude). Like a tuple it is printed, never converted; the text parses
    /// back to the number it denotes.
    pub fn decimal(text: &str) -> Self {
        match text.strip_prefix('-') {
            Some(magnitude) => Expr::new(ExprKind::Neg(Box::new(Expr::decimal(magnitude)))),
            None => Expr::new(ExprKind::Call(text.to_string(), Vec::new())),
        }
    }
}

/// Whether a call's name is the digits of an [`Expr::decimal`] (`[0-9]+(.[0-9]+)?`).
pub fn is_decimal_name(name: &str) -> bool {
    let mut parts = name.splitn(2, '.');
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    parts.next().is_some_and(digits) && parts.next().is_none_or(digits)
}

// ------------------------------------------------------------------------------ errors

/// An error of parsing or converting an expression, with the byte position it refers to.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ExprError {
    /// A token that does not fit the grammar.
    #[error("unexpected {found} at {pos}: expected {expected}")]
    Unexpected {
        /// Byte position of the token.
        pos: usize,
        /// The token, quoted (or `end of input`).
        found: String,
        /// What would have fitted.
        expected: &'static str,
    },
    /// Division by an expression that is not constant.
    #[error("division by a non-constant expression at {pos}")]
    NonConstantDivisor {
        /// Byte position of the divisor.
        pos: usize,
    },
    /// Division by an expression that evaluates to zero.
    #[error("division by zero at {pos}")]
    DivisionByZero {
        /// Byte position of the divisor.
        pos: usize,
    },
    /// Division by a polynomial expression that is identically zero (`1/(x-x)`).
    #[error("division by zero at {pos}: the divisor {divisor} is identically zero")]
    ZeroDivisor {
        /// Byte position of the divisor.
        pos: usize,
        /// The divisor, printed.
        divisor: String,
    },
    /// A call of a function of the language ([`FUNCTIONS`]) with wrong arguments.
    #[error("{name} at {pos}: {why}")]
    BadCall {
        /// Byte position of the argument at fault (or of the call).
        pos: usize,
        /// The function.
        name: String,
        /// What is wrong, in words.
        why: String,
    },
    /// An exponent that is not a non-negative integer constant.
    #[error(
        "exponent at {pos} must be a non-negative integer constant (or half of one: x^(1/2) is \
         sqrt(x); a constant takes any rational exponent: 2^(1/3)), found {found}"
    )]
    BadExponent {
        /// Byte position of the exponent.
        pos: usize,
        /// The exponent (its expression, or its value).
        found: String,
    },
    /// A negative exponent of a base that is not a non-zero constant.
    #[error(
        "negative exponent at {pos}: only a non-zero constant can be raised to a negative power"
    )]
    NegativeExponent {
        /// Byte position of the exponent.
        pos: usize,
    },
    /// A name followed by `(` that is not a known function.
    #[error(
        "unknown function '{name}' at {pos}: the functions are sqrt, {list} (write \
         '{name}*(...)' for a product)",
        list = FUNCTIONS.join(", ")
    )]
    UnknownFunction {
        /// Byte position of the name.
        pos: usize,
        /// The name.
        name: String,
    },
    /// A variable where a constant is required ([`Expr::eval_constant`]).
    #[error("variable '{name}' at {pos} where a constant number is expected{hint}")]
    NotConstant {
        /// Byte position of the variable.
        pos: usize,
        /// Its name.
        name: String,
        /// A hint for names that are constants elsewhere (`i`).
        hint: &'static str,
    },
    /// A power or product whose exponents would exceed `u32::MAX`.
    #[error("exponent overflow at {pos}: a variable's exponent would exceed {max}", max = u32::MAX)]
    ExponentOverflow {
        /// Byte position of the power or product.
        pos: usize,
    },
    /// `sqrt` of an expression that is not constant, where the conversion does not allow
    /// such roots ([`crate::poly::Vars::allow_roots`]).
    #[error("sqrt of a non-constant expression at {pos}")]
    NonConstantSqrt {
        /// Byte position of the argument.
        pos: usize,
    },
    /// `sqrt` of a constant whose root is not in the coefficient field.
    #[error("sqrt({arg}) at {pos} does not lie in the coefficient field{hint}")]
    NoSqrt {
        /// Byte position of the `sqrt`.
        pos: usize,
        /// The argument, printed.
        arg: String,
        /// The coefficient type's hint ([`Coefficient::sqrt_hint`]).
        hint: &'static str,
    },
    /// A root of index 3 or higher (`2^(1/3)`, `\sqrt[3]{2}`) of a constant that has none in the
    /// coefficient field.
    #[error(
        "the root of index {index} of {arg} at {pos} does not lie in the coefficient field{hint}"
    )]
    NoRoot {
        /// Byte position of the power.
        pos: usize,
        /// The index.
        index: u32,
        /// The radicand, printed.
        arg: String,
        /// The coefficient type's hint ([`Coefficient::nth_root_hint`]).
        hint: &'static str,
    },
    /// `sqrt(E)` of a non-constant `E` that is negative at every real point: the root is
    /// nowhere defined.
    #[error("sqrt({arg}) at {pos}: the radicand is negative for all real values, so the square root is defined nowhere")]
    NegativeRadicand {
        /// Byte position of the argument.
        pos: usize,
        /// The argument, printed.
        arg: String,
    },
    /// A number with no image in the coefficient ring.
    #[error("the number {number} at {pos} has no image in the coefficient ring")]
    Unrepresentable {
        /// Byte position of the number.
        pos: usize,
        /// The number.
        number: String,
    },
    /// A named limit of [`exactcheck_core::limits`] exceeded at `pos`: the nesting depth, the
    /// digits of a number, an exponent, the size of a constant, the number of variables, the
    /// terms or the degree of a polynomial, the radicands of a coefficient
    /// ([`Coefficient::check_limits`]). One line, e.g. `at 4: size of a constant exceeds the
    /// limit constant-bits = 1000000 bits (found more than 1000000; raise it with --limit
    /// constant-bits=N)`.
    #[error("at {pos}: {error}")]
    Limit {
        /// Byte position of the token, number, product or power.
        pos: usize,
        /// Which limit, its value and what was found.
        error: LimitError,
    },
    /// A named limit exceeded by the value of a function call: `cos(2*pi/1009)` has degree 504,
    /// past `algebraic-degree`. One line, e.g. `cos at 0: degree of an algebraic number exceeds
    /// the limit algebraic-degree = 64 (found 504; raise it with --limit algebraic-degree=N)`.
    #[error("{name} at {pos}: {error}")]
    CallLimit {
        /// Byte position of the call.
        pos: usize,
        /// The function.
        name: String,
        /// Which limit, its value and what was found.
        error: LimitError,
    },
}

impl ExprError {
    /// The byte position the error refers to.
    pub fn position(&self) -> usize {
        match self {
            ExprError::Unexpected { pos, .. }
            | ExprError::NonConstantDivisor { pos }
            | ExprError::DivisionByZero { pos }
            | ExprError::ZeroDivisor { pos, .. }
            | ExprError::BadCall { pos, .. }
            | ExprError::BadExponent { pos, .. }
            | ExprError::ExponentOverflow { pos }
            | ExprError::NegativeExponent { pos }
            | ExprError::UnknownFunction { pos, .. }
            | ExprError::NotConstant { pos, .. }
            | ExprError::NonConstantSqrt { pos }
            | ExprError::NegativeRadicand { pos, .. }
            | ExprError::NoSqrt { pos, .. }
            | ExprError::NoRoot { pos, .. }
            | ExprError::Unrepresentable { pos, .. }
            | ExprError::Limit { pos, .. }
            | ExprError::CallLimit { pos, .. } => *pos,
        }
    }

    /// The limit exceeded, for [`ExprError::Limit`] and [`ExprError::CallLimit`]: callers tell
    /// a limit from bad input by this, not by the message.
    pub fn limit(&self) -> Option<&LimitError> {
        match self {
            ExprError::Limit { error, .. } | ExprError::CallLimit { error, .. } => Some(error),
            _ => None,
        }
    }
}
