//! Program execution: numbers, names, blocks, modal data, timers, upload.

#[allow(unused_imports)]
use super::{LONG, ULONG};
