//! Inlining standalone SVG documents into one HTML page without clashes.
//!
//! An inline `<svg>` shares the page's id space and style sheet: two figures that both define
//! `id="arrow"` would point their `url(#arrow)` at the first one, and a figure's
//! `<style>.title{...}</style>` would restyle every `.title` of the page, the other figures'
//! included. [`isolate`] therefore
//! * drops anything before the `<svg` element (an XML declaration, a doctype);
//! * renames every `id="X"` to `id="PREFIX-X"` and every reference to it (`url(#X)`,
//!   `href="#X"`, `xlink:href="#X"`);
//! * scopes every rule of every `<style>` element to the figure: each selector `S` becomes
//!   `#SCOPE S` (the figure element's id). The figures' style sheets are flat lists of rules;
//!   an at-rule or a nested block is refused with an error rather than leaked to the page.

use crate::Error;

/// `svg` ready to be inlined in an element with id `scope`: ids prefixed with `prefix`,
/// style rules scoped to `#scope`.
///
/// # Errors
/// [`Error::Input`] when the document has no `<svg` element or a style sheet this cannot
/// scope (an at-rule, unbalanced braces).
pub fn isolate(svg: &str, prefix: &str, scope: &str) -> Result<String, Error> {
    let start = svg
        .find("<svg")
        .ok_or_else(|| Error::Input(format!("figure {scope}: no <svg> element")))?;
    let mut out = svg[start..].trim_end().to_string();
    for id in ids(&out) {
        let new = format!("{prefix}-{id}");
        for (old, replacement) in [
            (format!("id=\"{id}\""), format!("id=\"{new}\"")),
            (format!("url(#{id})"), format!("url(#{new})")),
            (format!("href=\"#{id}\""), format!("href=\"#{new}\"")),
        ] {
            out = out.replace(&old, &replacement);
        }
    }
    scope_styles(&out, scope)
}

/// The values of the `id` attributes of `svg`, longest first (so renaming `a` cannot touch
/// the references of `ab`: every pattern ends in a quote or parenthesis anyway).
fn ids(svg: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find(" id=\"") {
        rest = &rest[i + 5..];
        if let Some(end) = rest.find('"') {
            let id = &rest[..end];
            if !id.is_empty() && !out.iter().any(|x| x == id) {
                out.push(id.to_string());
            }
        }
    }
    out.sort_by_key(|s| std::cmp::Reverse(s.len()));
    out
}

/// Rewrites the content of every `<style>` element of `svg` so its rules apply inside
/// `#scope` only.
fn scope_styles(svg: &str, scope: &str) -> Result<String, Error> {
    let mut out = String::with_capacity(svg.len() + 256);
    let mut rest = svg;
    while let Some(open) = rest.find("<style") {
        let body_start = rest[open..]
            .find('>')
            .map(|i| open + i + 1)
            .ok_or_else(|| Error::Input(format!("figure {scope}: unterminated <style>")))?;
        let body_end = rest[body_start..]
            .find("</style>")
            .map(|i| body_start + i)
            .ok_or_else(|| Error::Input(format!("figure {scope}: <style> without </style>")))?;
        out.push_str(&rest[..body_start]);
        out.push_str(&scope_css(&rest[body_start..body_end], scope)?);
        rest = &rest[body_end..];
        // Copy the closing tag so the next search starts after it.
        out.push_str("</style>");
        rest = &rest["</style>".len()..];
    }
    out.push_str(rest);
    Ok(out)
}

/// A flat style sheet (`selectors { declarations }` ...) with every selector prefixed by
/// `#scope `.
fn scope_css(css: &str, scope: &str) -> Result<String, Error> {
    let mut out = String::with_capacity(css.len() * 2);
    let mut rest = css;
    loop {
        let Some(open) = rest.find('{') else {
            if !rest.trim().is_empty() {
                return Err(Error::Input(format!(
                    "figure {scope}: style text outside a rule: {:?}",
                    rest.trim()
                )));
            }
            break;
        };
        let selectors = rest[..open].trim();
        let close = rest[open..]
            .find('}')
            .map(|i| open + i)
            .ok_or_else(|| Error::Input(format!("figure {scope}: unbalanced braces in <style>")))?;
        let body = &rest[open + 1..close];
        if selectors.starts_with('@') || body.contains('{') || selectors.is_empty() {
            return Err(Error::Input(format!(
                "figure {scope}: the report cannot scope the style rule {selectors:?}"
            )));
        }
        let scoped: Vec<String> = selectors
            .split(',')
            .map(|s| format!("#{scope} {}", s.trim()))
            .collect();
        out.push_str(&scoped.join(","));
        out.push('{');
        out.push_str(body);
        out.push_str("}\n");
        rest = &rest[close + 1..];
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const A: &str = "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"><style>\n.title{font-size:20px}\ntext, .sub {fill:#444}\n</style><defs><marker id=\"arrow\"/><marker id=\"arrow2\"/></defs><path marker-end=\"url(#arrow)\"/><use href=\"#arrow2\"/><text class=\"title\">t</text></svg>\n";

    #[test]
    fn ids_and_references_are_prefixed() {
        let s = isolate(A, "f1", "fig1").unwrap();
        assert!(s.starts_with("<svg"), "{s}");
        assert!(s.contains("id=\"f1-arrow\"") && s.contains("id=\"f1-arrow2\""));
        assert!(s.contains("url(#f1-arrow)") && s.contains("href=\"#f1-arrow2\""));
        assert!(!s.contains("\"arrow\"") && !s.contains("#arrow)"));
        // Two figures with the same ids no longer share any.
        let t = isolate(A, "f2", "fig2").unwrap();
        assert!(t.contains("id=\"f2-arrow\"") && !t.contains("f1-"));
    }

    #[test]
    fn style_rules_apply_inside_the_figure_only() {
        let s = isolate(A, "f1", "fig1").unwrap();
        assert!(s.contains("#fig1 .title{font-size:20px}"), "{s}");
        assert!(s.contains("#fig1 text,#fig1 .sub{fill:#444}"), "{s}");
        assert!(!s.contains("\n.title"));
    }

    #[test]
    fn what_cannot_be_scoped_is_an_error() {
        for bad in [
            "<svg><style>@media print{.a{fill:red}}</style></svg>",
            "<svg><style>.a{fill:red</style></svg>",
            "<svg><style>.a{fill:red} stray</style></svg>",
            "no svg here",
        ] {
            assert!(isolate(bad, "p", "s").is_err(), "{bad}");
        }
    }

    #[test]
    fn every_catalogue_figure_isolates() {
        for f in crate::papers::figures().unwrap() {
            let s = isolate(&f.svg, "p", "s").unwrap();
            assert!(s.starts_with("<svg") && s.ends_with("</svg>"), "{}", f.id);
        }
    }
}
