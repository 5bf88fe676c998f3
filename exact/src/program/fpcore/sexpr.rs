//! The s-expression layer of the FPCore reader: characters -> tokens -> trees, every tree node
//! carrying the line and column where it starts.
//!
//! Tokens (FPCore 2.0, "Syntax"): `(` `)` `[` `]` (brackets are parentheses that must close
//! with their own kind), strings `"..."` with the escapes `\"` and `\\` (plus the C escapes
//! `\n`, `\t`, `\r`; any other backslash pair is kept as written), comments from `;` to the end
//! of the line, and atoms: maximal runs of the remaining characters. An atom is a number when
//! it matches one of the three number forms of the standard — rational
//! `[+-]?[0-9]+/[0-9]*[1-9][0-9]*`, decimal `[-+]?([0-9]+(\.[0-9]+)?|\.[0-9]+)(e[-+]?[0-9]+)?`
//! and hexadecimal `[+-]?0x([0-9a-f]+(\.[0-9a-f]+)?|\.[0-9a-f]+)(p[-+]?[0-9]+)?`
//! (case-insensitive) — and is read into the exact [`Rational`] it denotes; otherwise it must
//! be a symbol (`[a-zA-Z~!@$%^&*_\-+=<>.?/:][a-zA-Z0-9~!@$%^&*_\-+=<>.?/:]*`, letters also
//! non-ASCII). An atom that starts like a number but is not one (`1.2.3`, `12abc`) is a syntax
//! error rather than a symbol. Lists nest at most the `depth` limit deep
//! ([`exactcheck_core::limits::DEPTH`]): the parser and the compiler recurse once per level.
use super::FpCoreError;
use crate::rational::Rational;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

/// The largest decimal, binary or `digits` exponent a literal may have: a literal is expanded
/// into an exact fraction, and `1e1000000000` would not fit in memory. Doubles need `|e| <= 1100`
/// (decimal: 10^±330, binary: 2^±1100), so this leaves room for any sensible literal.
pub(crate) const MAX_LITERAL_EXPONENT: i64 = 100_000;

/// A position in the source: 1-based line and column (columns count characters).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Pos {
    pub line: usize,
    pub col: usize,
}

/// One s-expression.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum SExpr {
    /// A number literal, exact.
    Num(Rational, Pos),
    /// A symbol (including properties `:name`).
    Sym(String, Pos),
    /// A string literal (escapes resolved).
    Str(String, Pos),
    /// A parenthesized (or bracketed) list.
    List(Vec<SExpr>, Pos),
}

impl SExpr {
    pub(crate) fn pos(&self) -> Pos {
        match self {
            SExpr::Num(_, p) | SExpr::Sym(_, p) | SExpr::Str(_, p) | SExpr::List(_, p) => *p,
        }
    }

    /// The symbol's name, if this is a symbol.
    pub(crate) fn sym(&self) -> Option<&str> {
        match self {
            SExpr::Sym(s, _) => Some(s),
            _ => None,
        }
    }

    /// A short description for error messages.
    pub(crate) fn describe(&self) -> String {
        match self {
            SExpr::Num(q, _) => format!("the number {q}"),
            SExpr::Sym(s, _) => format!("`{s}`"),
            SExpr::Str(s, _) => format!("the string {s:?}"),
            SExpr::List(items, _) => match items.first().and_then(SExpr::sym) {
                Some(head) => format!("a `({head} ...)` list"),
                None => "a list".to_string(),
            },
        }
    }
}

struct Lexer<'a> {
    chars: std::iter::Peekable<std::str::Chars<'a>>,
    line: usize,
    col: usize,
}

impl Lexer<'_> {
    fn pos(&self) -> Pos {
        Pos {
            line: self.line,
            col: self.col,
        }
    }

    fn peek(&mut self) -> Option<char> {
        self.chars.peek().copied()
    }

    fn bump(&mut self) -> Option<char> {
        let c = self.chars.next()?;
        if c == '\n' {
            self.line += 1;
            self.col = 1;
        } else {
            self.col += 1;
        }
        Some(c)
    }

    /// Skips white space and comments.
    fn skip_blank(&mut self) {
        while let Some(c) = self.peek() {
            if c.is_whitespace() {
                self.bump();
            } else if c == ';' {
                while let Some(c) = self.bump() {
                    if c == '\n' {
                        break;
                    }
                }
            } else {
                break;
            }
        }
    }
}

fn error(pos: Pos, message: impl Into<String>) -> FpCoreError {
    FpCoreError {
        line: pos.line,
        col: pos.col,
        message: message.into(),
    }
}

fn is_delimiter(c: char) -> bool {
    c.is_whitespace() || matches!(c, '(' | ')' | '[' | ']' | '"' | ';')
}

/// The standard's symbol characters: "letters, digits, or characters from the set
/// `~!@$%^&*_-+=<>.?/:`" — letters taken in the Unicode sense (some published benchmarks use
/// Greek names), the standard's regular expression being its ASCII form.
fn is_symbol_char(c: char) -> bool {
    c.is_alphanumeric() || "~!@$%^&*_-+=<>.?/:".contains(c)
}

/// Parses the whole text into its top-level s-expressions.
pub(crate) fn parse_all(text: &str) -> Result<Vec<SExpr>, FpCoreError> {
    let mut lx = Lexer {
        chars: text.chars().peekable(),
        line: 1,
        col: 1,
    };
    let mut out = Vec::new();
    loop {
        lx.skip_blank();
        if lx.peek().is_none() {
            return Ok(out);
        }
        out.push(parse_one(&mut lx, 0)?);
    }
}

fn parse_one(lx: &mut Lexer<'_>, depth: usize) -> Result<SExpr, FpCoreError> {
    lx.skip_blank();
    let pos = lx.pos();
    if let Err(e) = exactcheck_core::limits::DEPTH.check_usize(depth) {
        return Err(error(pos, e.to_string()));
    }
    match lx.peek() {
        None => Err(error(
            pos,
            "expected an expression, found the end of the input",
        )),
        Some(open @ ('(' | '[')) => {
            lx.bump();
            let close = if open == '(' { ')' } else { ']' };
            let mut items = Vec::new();
            loop {
                lx.skip_blank();
                match lx.peek() {
                    None => {
                        return Err(error(
                            lx.pos(),
                            format!(
                                "expected `{close}` to close the `{open}` at {}:{}, found the end of the input",
                                pos.line, pos.col
                            ),
                        ))
                    }
                    Some(c) if c == close => {
                        lx.bump();
                        return Ok(SExpr::List(items, pos));
                    }
                    Some(c @ (')' | ']')) => {
                        return Err(error(
                            lx.pos(),
                            format!(
                                "expected `{close}` to close the `{open}` at {}:{}, found `{c}`",
                                pos.line, pos.col
                            ),
                        ))
                    }
                    Some(_) => items.push(parse_one(lx, depth + 1)?),
                }
            }
        }
        Some(c @ (')' | ']')) => Err(error(pos, format!("unexpected `{c}`"))),
        Some('"') => {
            lx.bump();
            let mut s = String::new();
            loop {
                match lx.bump() {
                    None => {
                        return Err(error(
                            lx.pos(),
                            format!(
                            "expected `\"` to end the string at {}:{}, found the end of the input",
                            pos.line, pos.col
                        ),
                        ))
                    }
                    Some('"') => return Ok(SExpr::Str(s, pos)),
                    Some('\\') => match lx.bump() {
                        Some('"') => s.push('"'),
                        Some('\\') => s.push('\\'),
                        Some('n') => s.push('\n'),
                        Some('t') => s.push('\t'),
                        Some('r') => s.push('\r'),
                        Some(other) => {
                            s.push('\\');
                            s.push(other);
                        }
                        None => return Err(error(
                            lx.pos(),
                            "expected an escaped character after `\\`, found the end of the input",
                        )),
                    },
                    Some(c) => s.push(c),
                }
            }
        }
        Some(_) => {
            let mut atom = String::new();
            while let Some(c) = lx.peek() {
                if is_delimiter(c) {
                    break;
                }
                atom.push(c);
                lx.bump();
            }
            classify_atom(&atom, pos)
        }
    }
}

fn classify_atom(atom: &str, pos: Pos) -> Result<SExpr, FpCoreError> {
    match parse_number(atom) {
        Ok(Some(q)) => return Ok(SExpr::Num(q, pos)),
        Ok(None) => {}
        Err(msg) => return Err(error(pos, msg)),
    }
    let first = atom.chars().next().expect("atoms are non-empty");
    let numeric_start = first.is_ascii_digit()
        || (matches!(first, '+' | '-' | '.')
            && atom[1..].starts_with(|c: char| c.is_ascii_digit()));
    if numeric_start {
        return Err(error(
            pos,
            format!("expected a number (decimal, rational `n/d` or hexadecimal), found `{atom}`"),
        ));
    }
    if let Some(bad) = atom.chars().find(|&c| !is_symbol_char(c)) {
        return Err(error(
            pos,
            format!("expected a symbol, found `{atom}` (the character `{bad}` is not allowed)"),
        ));
    }
    Ok(SExpr::Sym(atom.to_string(), pos))
}

/// The exact value of a number atom: `Ok(None)` when the atom is not a number at all,
/// `Err` when its exponent is beyond [`MAX_LITERAL_EXPONENT`].
fn parse_number(atom: &str) -> Result<Option<Rational>, String> {
    let (neg, body) = match atom.as_bytes().first() {
        Some(b'-') => (true, &atom[1..]),
        Some(b'+') => (false, &atom[1..]),
        _ => (false, atom),
    };
    let value = if let Some(hex) = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X")) {
        parse_positional(hex, 16, &['p', 'P'], 2)?
    } else if let Some((n, d)) = body.split_once('/') {
        if !all_digits(n, 10) || !all_digits(d, 10) {
            return Ok(None);
        }
        for part in [n, d] {
            let written = part.len() as u64;
            check_literal_size(
                &format!("the literal `{atom}`"),
                written * 3,
                Some(written),
                10,
                0,
            )?;
        }
        let d: BigInt = d.parse().expect("checked digits");
        if d.is_zero() {
            return Ok(None);
        }
        let n: BigInt = n.parse().expect("checked digits");
        Some(BigRational::new(n, d))
    } else {
        parse_positional(body, 10, &['e', 'E'], 10)?
    };
    Ok(value.map(|v| Rational::from(if neg { -v } else { v })))
}

fn all_digits(s: &str, radix: u32) -> bool {
    !s.is_empty() && s.chars().all(|c| c.is_digit(radix))
}

/// `digits[.digits][<marker>[+-]digits]` in `radix`, the exponent (decimal digits) scaling by
/// `exp_base`.
fn parse_positional(
    s: &str,
    radix: u32,
    markers: &[char],
    exp_base: u32,
) -> Result<Option<BigRational>, String> {
    let (mantissa, exponent) = match s.find(markers) {
        Some(i) => (&s[..i], Some(&s[i + 1..])),
        None => (s, None),
    };
    let (int_part, frac_part) = match mantissa.split_once('.') {
        Some((i, f)) => (i, f),
        None => (mantissa, ""),
    };
    let int_ok = int_part.is_empty() || all_digits(int_part, radix);
    let frac_ok = frac_part.is_empty() || all_digits(frac_part, radix);
    let has_digits = !int_part.is_empty() || !frac_part.is_empty();
    let dot_needs_digits = !mantissa.contains('.') || !frac_part.is_empty();
    if !(int_ok && frac_ok && has_digits && dot_needs_digits) {
        return Ok(None);
    }
    let exp: i64 = match exponent {
        None => 0,
        Some(e) => {
            let digits = e.strip_prefix(['+', '-']).unwrap_or(e);
            if !all_digits(digits, 10) {
                return Ok(None);
            }
            match e.parse::<i64>() {
                Ok(v) if v.abs() <= MAX_LITERAL_EXPONENT => v,
                _ => {
                    return Err(format!(
                        "the exponent of the literal `{s}` is beyond ±{MAX_LITERAL_EXPONENT}"
                    ))
                }
            }
        }
    };
    let written = (int_part.len() + frac_part.len()) as u64;
    check_literal_size(
        &format!("the literal `{s}`"),
        written.saturating_mul(u64::from(radix.ilog2())),
        Some(written).filter(|_| radix == 10),
        exp_base,
        exp,
    )?;
    let all: String = format!("{int_part}{frac_part}");
    let m = BigInt::parse_bytes(all.as_bytes(), radix).expect("checked digits");
    let frac_len = frac_part.len() as i64;
    // value = m * radix^(-frac_len) * exp_base^exp
    let radix_pow = BigInt::from(radix).pow(frac_len as u32);
    let mut q = BigRational::new(m, radix_pow);
    q *= pow_rational(exp_base, exp);
    Ok(Some(q))
}

/// Checks the size of the literal `m·base^e` (`m` of `m_bits` bits) before it is built: its
/// bits against the `constant-bits` limit, as every exact constant of the prove syntax is, and
/// for a decimal literal (`base` 10, `m` written in `m_digits` decimal digits) its digits plus
/// `|e|` against the `digits` limit, as the prove syntax counts them (`1e5000` has 5001).
///
/// # Errors
/// The limit's one-line message, naming the literal `what`.
pub(crate) fn check_literal_size(
    what: &str,
    m_bits: u64,
    m_digits: Option<u64>,
    base: u32,
    e: i64,
) -> Result<(), String> {
    use exactcheck_core::limits;
    let at = |error: exactcheck_core::limits::LimitError| format!("{what}: {error}");
    if let (Some(d), 10) = (m_digits, base) {
        limits::DIGITS
            .check(d.saturating_add(e.unsigned_abs()))
            .map_err(at)?;
    }
    // |e| times floor(log2(base)) bits at least: a lower bound, so no literal within the limit
    // is refused.
    let per = u64::from(base.ilog2());
    limits::CONSTANT_BITS
        .check(m_bits.saturating_add(e.unsigned_abs().saturating_mul(per)))
        .map_err(at)
}

/// `base^e` exactly, for `|e| <= MAX_LITERAL_EXPONENT` (checked by the callers).
pub(crate) fn pow_rational(base: u32, e: i64) -> BigRational {
    let p = BigInt::from(base).pow(e.unsigned_abs() as u32);
    if e >= 0 {
        BigRational::from_integer(p)
    } else {
        BigRational::new(BigInt::one(), p)
    }
}
