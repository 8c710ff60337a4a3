//! Custom macro variables.

#[allow(unused_imports)]
use super::{LONG, ULONG};
