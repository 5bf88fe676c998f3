//! Tests of `plot`: every figure is well-formed SVG with the expected elements. One test
//! binary; each module is one family of figures, the helpers come from
//! `tests/common/plot_support.rs`.

#[path = "../common/plot_support.rs"]
mod plot_support;

mod plot;
mod plot_chiang;
mod plot_conics;
mod plot_ph;
