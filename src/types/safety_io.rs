//! Safety I/O signal history (`cnc_*_sfsg_*`).
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::LONG;
use std::os::raw::c_short;

/// Data of `cnc_rd_sfsg_disp_stat`, `cnc_wr_sfsg_disp_stat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBSFSGDSPSTAT {
    pub extract: c_short,
    pub symbol: c_short,
    pub extend: c_short,
}

/// Data of `cnc_rd_sfsg_sighis`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBSFSGSIGHIS {
    pub sno_sig: c_short,
    pub len_sig: c_short,
    pub sno_sig_his: c_short,
    pub len_sig_his: c_short,
    pub extract: c_short,
}

/// Data of `cnc_rd_sfsg_search`, `cnc_rd_sfsg_siginf`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBSFSGSIGINF {
    pub unittype: LONG,
    pub number: LONG,
    pub adr_type: c_short,
    pub bit: c_short,
}

/// Data of `cnc_rd_sfsg_loginf`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSFSGLOGINF {
    pub signal_num: c_short,
    pub sig_his_period: c_short,
    pub sig_his_count: c_short,
    pub sig_his_after: c_short,
    pub alm_detect_time: [c_short; 3],
    pub dummy: c_short,
    pub sfsg_alm: ODBSFSGALM,
    pub sfsg_alm_time: ODBSFSGALMTIME,
}

/// Data of `cnc_rd_sfsg_siginf`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSFSGSIGINFEX {
    pub sfsg_siginf: IODBSFSGSIGINF,
    pub select: c_short,
    pub reserve: c_short,
}

/// Data of `cnc_rd_sfsg_signal_num`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSFSGSIGNALNUM {
    pub signal_num_default: c_short,
    pub signal_num_extract: c_short,
}

/// Data of `cnc_rd_sfsg_loginf`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSFSGALMTIME {
    pub year: c_short,
    pub month: c_short,
    pub date: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
}

/// Data of `cnc_rd_sfsg_loginf`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSFSGALM {
    pub alm_type: c_short,
    pub alm_no: c_short,
}
