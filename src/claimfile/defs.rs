//! The definitions of a claims file: the `[define]` table read into
//! [`exactcheck_exact::expr::library::Defs`], which resolves names, functions with parameters,
//! vectors, matrices and the library functions (`dot`, `cross`, `det`, `bezier`, ...) for every
//! formula of the file, as `prove` resolves its sides.

pub use exactcheck_exact::expr::library::{has_sqrt, substitute, DefText, Defs, Val};
