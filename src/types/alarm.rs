//! Alarms, alarm messages, operator messages and the alarm history.

#[allow(unused_imports)]
use super::{LONG, ULONG};

// --- alarm history ---

/// One record of ODBAHIS (48 bytes).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS_ALM {
    pub dummy: std::os::raw::c_short,
    pub alm_grp: std::os::raw::c_short,
    pub alm_no: std::os::raw::c_short,
    pub axis_no: std::os::raw::c_char,
    pub year: std::os::raw::c_char,
    pub month: std::os::raw::c_char,
    pub day: std::os::raw::c_char,
    pub hour: std::os::raw::c_char,
    pub minute: std::os::raw::c_char,
    pub second: std::os::raw::c_char,
    pub dummy2: std::os::raw::c_char,
    pub len_msg: std::os::raw::c_short,
    pub alm_msg: [std::os::raw::c_char; 32],
}

/// cnc_rdalmhistry: alarm history (10 records as declared; the caller's
/// `length` says how many really fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS {
    pub s_no: std::os::raw::c_ushort,
    pub r#type: std::os::raw::c_short,
    pub e_no: std::os::raw::c_ushort,
    pub alm_his: [ODBAHIS_ALM; 10],
}

/// One record of ODBAHIS2 (52 bytes).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS2_ALM {
    pub alm_grp: std::os::raw::c_short,
    pub alm_no: std::os::raw::c_short,
    pub axis_no: std::os::raw::c_short,
    pub year: std::os::raw::c_short,
    pub month: std::os::raw::c_short,
    pub day: std::os::raw::c_short,
    pub hour: std::os::raw::c_short,
    pub minute: std::os::raw::c_short,
    pub second: std::os::raw::c_short,
    pub len_msg: std::os::raw::c_short,
    pub alm_msg: [std::os::raw::c_char; 32],
}

/// cnc_rdalmhistry2: alarm history, all fields as shorts.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS2 {
    pub s_no: std::os::raw::c_ushort,
    pub e_no: std::os::raw::c_ushort,
    pub alm_his: [ODBAHIS2_ALM; 10],
}
