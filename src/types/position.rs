//! Axes and spindles: names, positions, speeds, loads, dynamic data, figures.

#[allow(unused_imports)]
use super::{LONG, ULONG};
