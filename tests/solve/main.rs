//! Tests of `solve` and of the geometry behind its kinds: the command's contract, ranges and
//! limits, the property tests, conics, planes, ruled surfaces, PH curves and offsets, and the
//! checks of Chiang's papers. One test binary; each module is one area, the helpers come from
//! `tests/common`.

#[path = "../common/mod.rs"]
mod common;

mod chiang;
mod chiang_conic;
mod chiang_ph;
mod conic;
mod conic_core;
mod cylinder_sphere_field;
mod ph_core;
mod ph_offset;
mod planes;
mod ruled_float;
mod ruled_line;
mod ruled_plane;
mod solve;
mod solve_f64_range;
mod solve_limits;
mod solve_props;
