//! bernstein (being written)
