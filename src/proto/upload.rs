//! Program upload over connection 1.
