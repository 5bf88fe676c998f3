//! Tests of `prove` and of the exact fields behind it: fractions, the function library, square
//! roots, trigonometry, robustness against hostile expressions, the scalars' agreement and the
//! real-root isolation. One test binary; each module is one area, the helpers come from
//! `tests/common`.

#[path = "../common/mod.rs"]
mod common;
#[path = "../common/timed.rs"]
mod timed;

mod prove_angle_domains;
mod prove_angles_as_printed;
mod prove_calculus_roots;
mod prove_differential_findings;
mod prove_fractions;
mod prove_higher_roots;
mod prove_integral_constant_angles;
mod prove_latex;
mod prove_latex_matrices;
mod prove_latex_vectors;
mod prove_library;
mod prove_random;
mod prove_rational_roots;
mod prove_signs;
mod prove_sqrt;
mod prove_symbolic_sums;
mod prove_trig;
mod prove_typeset;
mod prove_vacuous;
mod prove_witness_cells;
mod real_roots;
mod robust_field;
mod robust_prove;
mod scalars_agree;
