//! Teach programs, touch panel, keys and screens.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, ULONG};
use std::os::raw::{c_char, c_int, c_short, c_uchar};

/// One element of `IDBTPCMD.val`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBTPCMD_val {
    pub val: LONG,
    pub dec: LONG,
}

/// Data of `cnc_tprog_editcmd`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IDBTPCMD {
    pub cmd_id: LONG,
    pub integer: [LONG; 4],
    pub val: [IDBTPCMD_val; 4],
    pub text: [c_char; 64],
}

/// Data of `cnc_tprog_wrinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IDBTPINFO {
    pub prg_name: [c_char; 36],
    pub comment: [c_char; 20],
    pub axis: ULONG,
    pub out_nc_prg: [c_char; 36],
    pub reserve: [LONG; 2],
}

/// Data of `cnc_rd_scrlwaitmcode`, `cnc_wr_scrlwaitmcode`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBWAITMCODE {
    pub mcode: LONG,
    pub pathnum: LONG,
}

/// Data of `cnc_rd_hm_progstat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBHMPROGSTAT {
    pub run: c_short,
    pub disp: c_short,
    pub alm_no: c_short,
    pub reserve: c_short,
    pub prog_no: LONG,
    pub block_no: LONG,
}

/// `cnc_sendkey`: Send MDI key information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBKEYINFO {
    pub key: [ULONG; 2],
}

/// The `create` member of `ODBTPAPRG`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTPAPRG_create {
    pub year: c_short,
    pub mon: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
}

/// The `edit` member of `ODBTPAPRG`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTPAPRG_edit {
    pub year: c_short,
    pub mon: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
}

/// The `convert` member of `ODBTPAPRG`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTPAPRG_convert {
    pub year: c_short,
    pub mon: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
}

/// Data of `cnc_tprog_rdprg_by_name`, `cnc_tprog_rdprg_by_num`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBTPAPRG {
    pub format_version: c_short,
    pub func_version: c_short,
    pub size: LONG,
    pub create: ODBTPAPRG_create,
    pub edit: ODBTPAPRG_edit,
    pub convert: ODBTPAPRG_convert,
    pub attr: ULONG,
    pub name_copy: [c_char; 36],
    pub prg_name: [c_char; 36],
    pub comment: [c_char; 20],
    pub axis: ULONG,
    pub out_nc_prg: [c_char; 36],
    pub reserve: [LONG; 2],
}

/// Data of `cnc_tprog_rdcmd`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTPEDTCMD {
    pub cmd_num: c_char,
    pub cmd: [c_char; 31],
    pub word_num: c_char,
    pub word: [c_char; 31],
}

/// Data of `cnc_tpl_read`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTPNLINTF {
    pub status: c_uchar,
    pub dummy: [c_uchar; 3],
    pub coord_x: c_short,
    pub coord_y: c_short,
}

/// Data of `cnc_statinfo_dmg`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct OUT_STATINF_DMG {
    pub dummy: [c_short; 1],
    pub dmg: c_short,
    pub dummy1: [c_short; 7],
}

/// Data of `cnc_pmclad_screen`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PMCLAD_MESSAGE {
    pub message: *mut c_char,
    pub lines: c_int,
    pub color_fg: c_int,
    pub color_bg: c_int,
}
