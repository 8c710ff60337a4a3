//! Custom macro variables.
