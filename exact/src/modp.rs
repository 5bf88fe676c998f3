//! Integers modulo 2^61 - 1 (being written).
