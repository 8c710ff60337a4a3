//! Program upload.

use std::os::raw::{c_char, c_short};

/// cnc_upload / cnc_cupload: a piece of program text (`data` holds up to
/// `*length` characters, not NUL-terminated; `dummy` is not written).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBUP {
    pub dummy: [c_short; 2],
    pub data: [c_char; 256],
}

impl Default for ODBUP {
    fn default() -> Self {
        ODBUP {
            dummy: [0; 2],
            data: [0; 256],
        }
    }
}
