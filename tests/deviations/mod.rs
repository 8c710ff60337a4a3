//! Where our library differs from FANUC's on purpose, for the oracle's
//! recorded cases (tests/vectors/): each entry names the cases and the
//! reason a user would accept. The shared golden set's table is in
//! tests/vectors.rs (DEVIATIONS); README.md lists both.

use super::common::Case;

pub struct Deviation {
    /// The vector file's function.
    pub function: &'static str,
    /// Case names: exact, or a prefix ending in `*`.
    pub cases: &'static [&'static str],
    pub reason: &'static str,
}

pub const ORACLE: &[Deviation] = &[];

fn matches(pat: &str, name: &str) -> bool {
    match pat.strip_suffix('*') {
        Some(p) => name.starts_with(p),
        None => pat == name,
    }
}

/// The deviation a recorded case is listed under, if any.
pub fn oracle(case: &Case) -> Option<&'static Deviation> {
    ORACLE
        .iter()
        .find(|d| d.function == case.function && d.cases.iter().any(|p| matches(p, &case.name)))
}
