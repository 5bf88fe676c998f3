//! LaTeX matrices and determinants, read as the list syntax of the plain language.
//!
//! * `\begin{pmatrix} a & b \\ c & d \end{pmatrix}` (also `bmatrix`, `Bmatrix`, `matrix`,
//!   `smallmatrix`, and `array` with its column specification) is the matrix `[[a, b], [c, d]]`;
//!   a single column is the vector `[a, c]` (the printed form of a point or a direction);
//! * `\begin{vmatrix} .. \end{vmatrix}`, and a matrix between absolute-value bars (`|..|`,
//!   `\left| \begin{array}{cc} .. \end{array} \right|`), is its determinant `det(..)`;
//! * `\det` applies to the atom that follows (`\det\begin{pmatrix}..\end{pmatrix}`,
//!   `\det(M)`, `\det{M}`).
//!
//! Entries are separated by `&` and rows by `\\` (an optional spacing `\\[2pt]` is skipped); a
//! final `\\` before `\end` is allowed. Rows of different lengths, an environment closed by
//! another's `\end`, and `Vmatrix` (a norm) are refused, naming what is wrong.

use super::*;

/// The environments that are matrices, and whether each is a determinant.
const MATRIX_ENVIRONMENTS: &[(&str, bool)] = &[
    ("pmatrix", false),
    ("bmatrix", false),
    ("Bmatrix", false),
    ("matrix", false),
    ("smallmatrix", false),
    ("array", false),
    ("vmatrix", true),
];

/// The environment named by a `\begin{..}` or `\end{..}` token's text (the first group).
pub(super) fn environment(text: &str) -> &str {
    let Some(open) = text.find('{') else {
        return "";
    };
    let rest = &text[open + 1..];
    rest[..rest.find('}').unwrap_or(rest.len())].trim()
}

/// Blanks the alignment marks `&` outside every environment (`x &= \frac{1}{2}` pasted from
/// an `align`): there they only place the line, while inside a matrix they separate entries.
pub(super) fn blank_alignment(s: &mut String) {
    let mut depth = 0usize;
    let mut marks = Vec::new();
    let mut at = 0;
    while let Some(c) = s[at..].chars().next() {
        if c == '\\' {
            let word = word_at(s, at + 1);
            match word {
                "begin" => depth += 1,
                "end" => depth = depth.saturating_sub(1),
                _ => {}
            }
            // A command's word, or the one character after the backslash (`\&`, `\\`).
            at += 1 + if word.is_empty() {
                s[at + 1..].chars().next().map_or(0, char::len_utf8)
            } else {
                word.len()
            };
            continue;
        }
        if c == '&' && depth == 0 {
            marks.push(at);
        }
        at += c.len_utf8();
    }
    for m in marks {
        s.replace_range(m..m + 1, " ");
    }
}

/// The end of `\begin{..}` or `\end{..}` at `at` (the backslash), with `array`'s column
/// specification `{cc}` included; `None` when the braces are not there.
pub(super) fn environment_end(src: &str, at: usize) -> Option<usize> {
    let word = word_at(src, at + 1);
    let open = at + 1 + word.len();
    if !src[open..].starts_with('{') {
        return None;
    }
    let end = group_end(src, open)?;
    if word == "begin" && environment(&src[at..end]) == "array" && src[end..].starts_with('{') {
        return group_end(src, end);
    }
    Some(end)
}

impl Parser<'_> {
    /// Whether the current token ends a matrix entry: `&`, `\\` or an `\end{..}`.
    pub(in crate::expr::parse) fn ends_matrix_entry(&self) -> bool {
        self.cur.tok == Tok::Command && {
            let text = self.text(self.cur);
            text == "&" || text == "\\\\" || text.starts_with("\\end")
        }
    }

    /// The matrix environment whose `\begin{..}` is the current token.
    pub(super) fn parse_environment(&mut self) -> Result<Expr, ExprError> {
        let t = self.cur;
        let text = self.text(t);
        let env = environment(text);
        let Some(&(_, det)) = MATRIX_ENVIRONMENTS.iter().find(|(e, _)| *e == env) else {
            let why = if env == "Vmatrix" {
                "a norm (double bars) of a matrix is not supported".to_string()
            } else {
                format!(
                    "the environment '{env}' is not read (matrices: pmatrix, bmatrix, Bmatrix, matrix, smallmatrix, array; determinants: vmatrix)"
                )
            };
            return Err(self.refuse(t.start, "\\begin", why));
        };
        if !self.calls {
            return Err(self.refuse(t.start, "\\begin", "a matrix is not a number here"));
        }
        self.bump();
        let mut rows: Vec<Vec<Expr>> = vec![Vec::new()];
        loop {
            let at_end = self.cur.tok == Tok::Command && self.text(self.cur).starts_with("\\end");
            // A final `\\` leaves an empty last row before `\end`.
            let empty_last_row = at_end && rows.len() > 1 && rows.last().is_some_and(Vec::is_empty);
            if !(at_end && empty_last_row) {
                rows.last_mut().expect("a row").push(self.parse_sum()?);
            }
            if !self.ends_matrix_entry() {
                return Err(self.unexpected("an operator, '&', '\\\\' or \\end{..}"));
            }
            let sep = self.text(self.cur);
            if sep.starts_with("\\end") {
                if environment(sep) != env {
                    return Err(self.refuse(
                        self.cur.start,
                        "\\end",
                        format!(
                            "\\begin{{{env}}} is closed by \\end{{{}}}",
                            environment(sep)
                        ),
                    ));
                }
                self.bump();
                break;
            }
            self.bump();
            if sep == "\\\\" {
                self.skip_row_spacing();
                rows.push(Vec::new());
            }
        }
        if rows.last().is_some_and(Vec::is_empty) {
            rows.pop();
        }
        let width = rows[0].len();
        if let Some(r) = rows.iter().position(|r| r.len() != width) {
            return Err(self.refuse(
                t.start,
                "\\begin",
                format!(
                    "row {} of the {env} has {}, row 1 has {}",
                    r + 1,
                    entries(rows[r].len()),
                    entries(width)
                ),
            ));
        }
        let list = |items: Vec<Expr>| Expr {
            kind: ExprKind::Call(LIST.to_string(), items),
            pos: t.start,
        };
        let matrix = if width == 1 && rows.len() > 1 && !det {
            list(rows.into_iter().flatten().collect())
        } else {
            list(rows.into_iter().map(list).collect())
        };
        Ok(if det {
            determinant(matrix, t.start)
        } else {
            matrix
        })
    }

    /// Skips the optional spacing `[2pt]` after a row separator `\\`.
    fn skip_row_spacing(&mut self) {
        if self.cur.tok == Tok::LBracket {
            let mut at = self.cur.end;
            let src = self.src;
            if let Some(close) = src[at..].find(']') {
                let inside = &src[at..at + close];
                if inside
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | ' ' | '-'))
                {
                    at += close + 1;
                    self.cur = self.lex(at);
                }
            }
        }
    }

    /// `\det` and the atom that follows it.
    pub(super) fn parse_det(&mut self, pos: usize) -> Result<Expr, ExprError> {
        self.bump();
        let arg = self.parse_atom("a matrix after \\det")?;
        Ok(determinant(arg, pos))
    }
}

/// `n entries` (`1 entry`).
fn entries(n: usize) -> String {
    format!("{n} {}", if n == 1 { "entry" } else { "entries" })
}

/// `det(m)` at `pos`.
pub(in crate::expr::parse) fn determinant(m: Expr, pos: usize) -> Expr {
    Expr {
        kind: ExprKind::Call("det".to_string(), vec![m]),
        pos,
    }
}

/// Whether `e` is a matrix literal (a list of lists): between bars it is a determinant.
pub(in crate::expr::parse) fn is_matrix_literal(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Call(n, rows) if n == LIST
        && !rows.is_empty()
        && rows.iter().all(|r| matches!(&r.kind, ExprKind::Call(n, _) if n == LIST)))
}

#[cfg(test)]
mod tests {
    use super::super::tests::{refused, same};
    use crate::expr::{parse_expr_with_calls, split_equation, to_latex, to_mathml, Notation};

    #[test]
    fn matrix_environments_are_lists_of_rows() {
        same(
            "\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix}",
            "[[a, b], [c, d]]",
        );
        same("\\begin{bmatrix} 1 & 2 \\end{bmatrix}", "[[1, 2]]");
        same("\\begin{matrix} x \\\\ y \\\\ z \\end{matrix}", "[x, y, z]");
        // A final row separator and a row spacing are allowed.
        same(
            "\\begin{smallmatrix} a & b \\\\[2pt] c & d \\\\ \\end{smallmatrix}",
            "[[a, b], [c, d]]",
        );
        same(
            "\\begin{array}{cc} \\frac12 & x^2 \\\\ 2y & 0 \\end{array}",
            "[[1/2, x^2], [2*y, 0]]",
        );
    }

    #[test]
    fn determinants_by_vmatrix_bars_and_det() {
        same(
            "\\begin{vmatrix} a & b \\\\ c & d \\end{vmatrix}",
            "det([[a, b], [c, d]])",
        );
        same(
            "\\left| \\begin{array}{cc} a & b \\\\ c & d \\end{array} \\right|",
            "det([[a, b], [c, d]])",
        );
        same(
            "2\\det\\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix}",
            "2*det([[a, b], [c, d]])",
        );
        // A one-by-one determinant is its entry, not a vector.
        same("\\begin{vmatrix} x \\end{vmatrix}", "det([[x]])");
        same(
            "|\\begin{matrix} a & |b| \\\\ c & d \\end{matrix}|",
            "det([[a, abs(b)], [c, d]])",
        );
        // Bars around anything else are still the absolute value.
        same("\\left| x - 1 \\right|", "abs(x - 1)");
    }

    #[test]
    fn alignment_marks_outside_matrices_are_blank() {
        let (l, r) = split_equation("x &= \\frac{1}{2}").unwrap();
        same(&l, "x");
        same(&r, "1/2");
    }

    #[test]
    fn malformed_matrices_are_refused_naming_the_fault() {
        refused(
            "\\begin{pmatrix} a & b \\\\ c \\end{pmatrix}",
            "row 2 of the pmatrix has 1 entry, row 1 has 2 entries",
        );
        refused(
            "\\begin{vmatrix} a \\end{pmatrix}",
            "\\begin{vmatrix} is closed by \\end{pmatrix}",
        );
        refused("\\begin{Vmatrix} a \\end{Vmatrix}", "a norm");
        refused(
            "\\begin{cases} a \\end{cases}",
            "the environment 'cases' is not read",
        );
        refused("\\begin{pmatrix} a & b", "expected an operator, '&'");
        refused("a \\\\ b", "unexpected '\\\\'");
        refused("\\\\ b", "outside a matrix environment");
        refused("\\begin{pmatrix}", "unexpected end of input");
        refused("\\begin", "\\begin");
        refused("\\det", "a matrix after \\det");
    }

    #[test]
    fn printed_matrices_and_determinants_read_back() {
        for (ascii, printed) in [
            (
                "[[a, b], [c, d]]",
                "\\begin{pmatrix}a & b \\\\ c & d\\end{pmatrix}",
            ),
            ("[x, y^2]", "\\begin{pmatrix}x \\\\ y^{2}\\end{pmatrix}"),
            (
                "2*det([[1, a], [1, b]])",
                "2\\,\\begin{vmatrix}1 & a \\\\ 1 & b\\end{vmatrix}",
            ),
        ] {
            let e = parse_expr_with_calls(ascii).unwrap();
            let latex = to_latex(&e, &Notation::new());
            assert_eq!(latex, printed, "{ascii}");
            same(&latex, ascii);
        }
        let e = parse_expr_with_calls("det([[a, b], [c, d]])").unwrap();
        let m = to_mathml(&e, &Notation::new());
        assert!(m.contains("<mo>|</mo><mtable><mtr><mtd>"), "{m}");
    }
}
