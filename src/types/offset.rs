//! Tool and work offsets.

#[allow(unused_imports)]
use super::{LONG, ULONG};
