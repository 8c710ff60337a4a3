//! Main menu customisation (`cnc_*_mm_*`).
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, ULONG};
use std::os::raw::c_char;

/// Data of `cnc_rd_mm_ctgry_cstm_str_data`, `cnc_wr_mm_ctgry_cstm_str_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBMMCTGRYCSTMSTRING {
    pub string: [c_char; 13],
    pub reserve: [c_char; 3],
}

/// Data of `cnc_rd_mm_icn_cstm_str_data`, `cnc_wr_mm_icn_cstm_str_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBMMICONCSTMSTRING {
    pub scrninf: ODBMMSCRNINF,
    pub string: [c_char; 13],
    pub reserve: [c_char; 3],
}

/// Data of `cnc_rd_mm_mc_ctgry_def_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBMMMCCTGRYDEFDAT {
    pub cmsg_id: LONG,
}

/// Data of `cnc_rd_mm_mc_scrn_def_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBMMMCSCRNDEFDAT {
    pub scrninf: ODBMMSCRNINF,
    pub icn_id: LONG,
    pub msg_id: LONG,
}

/// Data of `cnc_rd_mm_icn_cstm_str_data`, `cnc_rd_mm_mc_dflt_scrn_inf`, `cnc_rd_mm_mc_scrn_def_data` ….
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBMMSCRNINF {
    pub scrn_id: ULONG,
}
