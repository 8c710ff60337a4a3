//! Parameters and diagnostics.
