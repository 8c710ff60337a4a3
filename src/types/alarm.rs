//! Alarms, alarm messages and operator messages (the histories: history.rs).

use super::LONG;
use std::os::raw::{c_char, c_short};

// --- alarm ---

/// cnc_alarm: alarm status bits (low 16 bits).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBALM {
    pub dummy: [c_short; 2],
    pub data: c_short,
}

/// cnc_rdalmmsg: one alarm with a 32-character message.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBALMMSG {
    pub alm_no: LONG,
    pub r#type: c_short,
    pub axis: c_short,
    pub dummy: c_short,
    pub msg_len: c_short,
    pub alm_msg: [c_char; 32],
}

/// cnc_rdalmmsg2: one alarm with a 64-character message.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBALMMSG2 {
    pub alm_no: LONG,
    pub r#type: c_short,
    pub axis: c_short,
    pub dummy: c_short,
    pub msg_len: c_short,
    pub alm_msg: [c_char; 64],
}

impl Default for ODBALMMSG2 {
    fn default() -> Self {
        ODBALMMSG2 {
            alm_no: 0,
            r#type: 0,
            axis: 0,
            dummy: 0,
            msg_len: 0,
            alm_msg: [0; 64],
        }
    }
}

/// cnc_rdalmmsg3: one alarm with a 256-character message (declared for
/// programs that call it; no FANUC Ethernet library implements it).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBALMMSG3 {
    pub alm_no: LONG,
    pub r#type: c_short,
    pub axis: c_short,
    pub dummy: c_short,
    pub msg_len: c_short,
    pub alm_msg: [c_char; 256],
}

/// ALMINFO type 0 record: axis bits and alarm number.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ALMINFO_alm1_rec {
    pub axis: LONG,
    pub alm_no: c_short,
}

/// ALMINFO type 0: up to 5 alarms without messages.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ALMINFO_alm1 {
    pub alm: [ALMINFO_alm1_rec; 5],
    pub data_end: LONG,
}

/// ALMINFO type 1 record: axis bits, alarm number and message.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ALMINFO_alm2_rec {
    pub axis: LONG,
    pub alm_no: c_short,
    pub msg_len: c_short,
    pub alm_msg: [c_char; 32],
}

/// ALMINFO type 1: up to 5 alarms with messages.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ALMINFO_alm2 {
    pub alm: [ALMINFO_alm2_rec; 5],
    pub data_end: LONG,
}

/// The union of ALMINFO.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ALMINFO_u {
    pub alm1: ALMINFO_alm1,
    pub alm2: ALMINFO_alm2,
}

impl Default for ALMINFO_u {
    fn default() -> Self {
        ALMINFO_u {
            alm2: ALMINFO_alm2::default(),
        }
    }
}

impl std::fmt::Debug for ALMINFO_u {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ALMINFO_u")
            .field("alm2", unsafe { &self.alm2 })
            .finish()
    }
}

/// cnc_rdalminfo: alarm information (5 alarms; the caller's `length` says how many fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ALMINFO {
    pub u: ALMINFO_u,
}

/// cnc_rdopmsg: one operator message (256-character variant).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OPMSG {
    pub datano: c_short,
    pub r#type: c_short,
    pub char_num: c_short,
    pub data: [c_char; 256],
}

impl Default for OPMSG {
    fn default() -> Self {
        OPMSG {
            datano: 0,
            r#type: 0,
            char_num: 0,
            data: [0; 256],
        }
    }
}

/// cnc_rdopmsg3: one operator message (256-character variant).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OPMSG3 {
    pub datano: c_short,
    pub r#type: c_short,
    pub char_num: c_short,
    pub data: [c_char; 256],
}

impl Default for OPMSG3 {
    fn default() -> Self {
        OPMSG3 {
            datano: 0,
            r#type: 0,
            char_num: 0,
            data: [0; 256],
        }
    }
}
