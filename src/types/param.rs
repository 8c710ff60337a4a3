//! Parameters and diagnostics.

#[allow(unused_imports)]
use super::{LONG, ULONG};
