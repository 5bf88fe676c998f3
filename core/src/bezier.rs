//! bezier (being written)
