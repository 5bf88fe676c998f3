//! Polynomial expressions: parser and printer (being written).
