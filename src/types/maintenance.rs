//! Periodic maintenance.

use super::LONG;
use std::os::raw::c_char;

/// cnc_rdpm_item / cnc_wrpm_item: one maintenance item.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBPMAINTE {
    /// Name (not terminated when 62 characters long).
    pub name: [c_char; 62],
    /// Life count type.
    pub r#type: LONG,
    /// Life, in minutes.
    pub total: LONG,
    /// Life left.
    pub remain: LONG,
    /// Life state.
    pub stat: LONG,
}

impl Default for IODBPMAINTE {
    fn default() -> Self {
        IODBPMAINTE {
            name: [0; 62],
            r#type: 0,
            total: 0,
            remain: 0,
            stat: 0,
        }
    }
}
