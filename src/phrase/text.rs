//! Texts in verdicts: long values shortened, differences parenthesized once.

/// The longest value or polynomial an evidence line prints in full.
pub const SHOWN_CHARS: usize = 2_000;

/// `text` in full up to [`SHOWN_CHARS`] characters, else its beginning and its length (a
/// counter-example of `(x+y)^5000` is a number of 3,500 digits).
pub fn abbreviate(text: String) -> String {
    if text.len() <= SHOWN_CHARS {
        return text;
    }
    let mut cut = SHOWN_CHARS / 2;
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    format!(
        "{}... [{} characters in all; --json shows it in full]",
        &text[..cut],
        text.len()
    )
}

/// `text` in parentheses, unless one pair of parentheses already encloses all of it.
pub fn grouped(text: &str) -> String {
    let enclosed = text.starts_with('(')
        && text
            .char_indices()
            .scan(0i64, |depth, (i, c)| {
                match c {
                    '(' => *depth += 1,
                    ')' => *depth -= 1,
                    _ => {}
                }
                Some((i, *depth))
            })
            .find(|&(_, depth)| depth == 0)
            .is_some_and(|(i, _)| i + 1 == text.len());
    if enclosed {
        text.to_string()
    } else {
        format!("({text})")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_texts_are_shortened() {
        let long = "7".repeat(3 * SHOWN_CHARS);
        let short = abbreviate(long.clone());
        assert!(short.len() < long.len() && short.ends_with("--json shows it in full]"));
        assert_eq!(abbreviate("x".into()), "x");
    }

    #[test]
    fn a_difference_is_parenthesized_once() {
        assert_eq!(grouped("(-sqrt(2) + sqrt(6))"), "(-sqrt(2) + sqrt(6))");
        assert_eq!(grouped("b^3"), "(b^3)");
        assert_eq!(grouped("(a + 1)*(b + 1)"), "((a + 1)*(b + 1))");
        assert_eq!(grouped("(a)"), "(a)");
    }
}
