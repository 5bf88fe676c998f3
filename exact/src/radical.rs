//! Square-root extensions of Q (being written).
