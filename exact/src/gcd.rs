//! Greatest common divisors for the exact rational type (being written).
