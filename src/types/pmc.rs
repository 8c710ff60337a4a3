//! PMC areas.

#[allow(unused_imports)]
use super::{LONG, ULONG};
