//! The definitions of a claims file: the `[define]` table read into
//! [`exactcheck_exact::expr::library::Defs`], which resolves names, functions with parameters,
//! vectors, matrices and the library functions (`dot`, `cross`, `det`, `bezier`, ...) for every
//! formula of the file, as `prove` resolves its sides.

pub use exactcheck_exact::expr::library::{has_sqrt, substitute_free, DefText, Defs, Val};

use serde_json::{Map, Value};

/// The `[define]` table: each entry a formula (a string or a number) or a vector (an array of
/// formulas), its key a name or a function head (`"f(t)"`, `"cross2(u, v)"`).
///
/// # Errors
/// `(path, message)` with the path of the entry at fault (`define.NAME`).
pub fn read(define: Option<&Map<String, Value>>) -> Result<Defs, (String, String)> {
    let mut entries = Vec::new();
    for (name, v) in define.into_iter().flatten() {
        let path = format!("define.{name}");
        let scalar = |v: &Value| match v {
            Value::String(s) => Some(s.clone()),
            Value::Number(n) => Some(n.to_string()),
            _ => None,
        };
        let text = match v {
            Value::Array(xs) => DefText::Vector(
                xs.iter()
                    .map(|x| {
                        scalar(x).ok_or_else(|| {
                            (
                                path.clone(),
                                "a coordinate must be a formula (a string) or an integer".into(),
                            )
                        })
                    })
                    .collect::<Result<_, _>>()?,
            ),
            v => DefText::Scalar(scalar(v).ok_or_else(|| {
                (
                    path.clone(),
                    "a definition is a formula (a string), a number or a vector (an array of formulas)"
                        .to_string(),
                )
            })?),
        };
        entries.push((name.clone(), text));
    }
    Defs::new(entries).map_err(|(name, m)| (format!("define.{name}"), m))
}
