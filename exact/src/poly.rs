//! Sparse multivariate polynomials (being written).
