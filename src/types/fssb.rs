//! FSSB (servo serial bus) of the 30i-B: amplifiers, units and maintenance data.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::LONG;
use std::os::raw::{c_char, c_short, c_uchar, c_ushort};

/// Data of `cnc_rdifsb_as_sv_axis`, `cnc_wrifsb_as_sv_axis`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBIFSBAXIS {
    pub axis_num: c_short,
    pub axis_name: [c_char; 4],
    pub line: c_short,
    pub amp_name: [c_char; 8],
    pub pm: [c_short; 8],
    pub cs: c_short,
    pub tndm: c_short,
}

/// Data of `cnc_rdifsb_comstatdtl`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBCOMSTATDTL {
    pub error_inf: LONG,
    pub jitter_inf: LONG,
    pub n_warning: c_char,
    pub j_warning: c_char,
    pub reserve: [c_char; 2],
}

/// Data of `cnc_rdifsb_fssbunt`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBFSSBUNT {
    pub slv_unt_num: c_short,
    pub fssb_unt_num: c_short,
    pub name: [c_char; 4],
}

/// Data of `cnc_rdifsb_info`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBINFO {
    pub fssb_line_mnt_st: c_uchar,
    pub reserve: c_uchar,
    pub card_num: c_ushort,
    pub line_info: [ODBIFSBLINE; 4],
}

/// Data of `cnc_rdifsb_mainte_sp`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBMNTSP {
    pub spdl_num: c_short,
    pub spdl_name: [c_char; 4],
    pub line: c_short,
    pub amp_name: [c_char; 8],
    pub amp_series: [c_char; 12],
    pub amp_pwr: [c_char; 8],
    pub amp_edt: [c_char; 8],
    pub amp_spdl_num: c_short,
    pub amp_spec_num: [c_char; 23],
    pub amp_serial_num: [c_char; 13],
}

/// Data of `cnc_rdifsb_mainte_sv`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBMNTSV {
    pub axis_num: c_short,
    pub axis_name: [c_char; 4],
    pub line: c_short,
    pub amp_name: [c_char; 8],
    pub amp_series: [c_char; 12],
    pub amp_cur: [c_char; 8],
    pub amp_edt: [c_char; 8],
    pub amp_axis_num: c_short,
    pub amp_spec_num: [c_char; 23],
    pub amp_serial_num: [c_char; 13],
}

/// Data of `cnc_rdifsb_as_plsmod`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBPLSMDL {
    pub slave_num: c_short,
    pub name: [c_char; 8],
    pub r#type: [c_char; 8],
    pub pcb_id: c_ushort,
    pub info: [c_char; 24],
}

/// Data of `cnc_rdifsb_slu_pm`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBSLUPM {
    pub slave_num: c_short,
    pub axis_num: [c_short; 8],
    pub axis_name: [[c_char; 4]; 8],
}

/// Data of `cnc_rdifsb_slu_sp`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBSLUSP {
    pub slave_num: c_short,
    pub spdl_num: c_short,
    pub spdl_name: [c_char; 4],
}

/// Data of `cnc_rdifsb_slu_sv`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBSLUSV {
    pub slave_num: c_short,
    pub axis_num: c_short,
    pub axis_name: [c_char; 4],
    pub tndm: c_char,
    pub reserve: [c_char; 3],
}

/// Data of `cnc_rdifsb_slvunt`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBSLVUNT {
    pub slv_unt_num: c_short,
    pub kind: c_char,
    pub attrb: c_char,
}

/// Data of `cnc_rdifsb_as_amp_sp`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBSPAMP {
    pub slave_num: c_short,
    pub name: [c_char; 8],
    pub series: [c_char; 12],
    pub pwr: [c_char; 8],
    pub as_spdl_num: c_short,
    pub as_spdl_name: [c_char; 4],
}

/// Data of `cnc_rdifsb_as_amp_sv`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBSVAMP {
    pub slave_num: c_short,
    pub name: [c_char; 8],
    pub series: [c_char; 12],
    pub cur: [c_char; 8],
    pub as_axis_num: c_short,
    pub as_axis_name: [c_char; 4],
}

/// Data of `cnc_rdifsb_sysalm`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBIFSBSYSALM {
    pub num_sys_alm: LONG,
    pub error_line: c_short,
    pub error_slvnum1: c_short,
    pub error_slvnum2: c_short,
    pub year: c_short,
    pub mon: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
    pub alarm_cause: [c_char; 100],
}

/// Data of `cnc_rdifsb_warnhst_msg`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBWARNHSTMSG {
    pub year: c_short,
    pub month: c_char,
    pub day: c_char,
    pub hour: c_char,
    pub minute: c_char,
    pub second: c_char,
    pub dummy: c_char,
    pub msg_dat: ODBIFSBWARNINGMSG,
}

/// Data of `cnc_rdifsb_warnhst_msg`, `cnc_rdifsb_warning_msg`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBWARNINGMSG {
    pub line: c_short,
    pub slv_src: c_short,
    pub slv_dst: c_short,
    pub r#type: c_short,
    pub wm_typ: [c_char; 32],
    pub wm_pnt: [c_char; 32],
}

/// Data of `cnc_rdifsb_info`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIFSBLINE {
    pub hrv_ln: c_ushort,
    pub ax_num_ln: c_ushort,
    pub sp_num_ln: c_ushort,
    pub pm_num_ln: c_ushort,
}
