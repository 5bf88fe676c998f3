//! Integration tests of `exactcheck-exact` through its public API: property tests of the exact
//! scalars, the polynomial kernels, the parser, root isolation and the proof engine against
//! independent paths, and the self-intersections of planar curves. One test binary; each module
//! is one area (`cargo test --release -p exactcheck-exact --test props poly_props::`).

mod calculus_props;
mod cylinder_sphere_props;
mod modp_props;
mod parser_props;
mod planar;
mod poly_props;
mod prove_engine;
mod radical_props;
mod ratfun_props;
mod rational_props;
mod sqrt_props;
mod univariate_props;
