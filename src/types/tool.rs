//! Tool numbers, tool life and counters.

#[allow(unused_imports)]
use super::{LONG, ULONG};
