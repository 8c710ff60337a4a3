//! Program restart points and operation path history (`cnc_rstrt_*`, `cnc_rdpthis_*`).
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::LONG;
use std::os::raw::{c_char, c_short};

/// Data of `cnc_rstrt_rdpnt`, `cnc_rstrt_wrpnt`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBRSTINFO {
    pub seq_no: LONG,
    pub c_blck_cnt: LONG,
    pub t_blck_cnt: LONG,
    pub call_from_no: LONG,
    pub call_from_blck: LONG,
    pub prg_rep: c_short,
    pub seq_rep: c_short,
    pub c_blck_rep: c_short,
    pub nest_lv: c_short,
    pub prg_name: [c_char; 246],
    pub dummy1: [c_char; 2],
    pub call_from_prg: [c_char; 246],
    pub dummy2: [c_char; 2],
    pub edit_flag: c_char,
    pub reserve: c_char,
    pub repeat: c_short,
    pub wait_m_code: LONG,
}

/// Data of `cnc_rstrt_rdpnt2`, `cnc_rstrt_wrpnt2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBRSTINFO2 {
    pub seq_no: LONG,
    pub c_blck_cnt: LONG,
    pub t_blck_cnt: LONG,
    pub call_from_no: LONG,
    pub call_from_blck: LONG,
    pub prg_rep: c_short,
    pub seq_rep: c_short,
    pub c_blck_rep: c_short,
    pub nest_lv: c_short,
    pub prg_name: [c_char; 246],
    pub dummy1: [c_char; 2],
    pub call_from_prg: [c_char; 246],
    pub dummy2: [c_char; 2],
    pub edit_flag: c_char,
    pub reserve: c_char,
    pub repeat: c_short,
    pub wait_m_code: LONG,
    pub time_s: c_char,
    pub time_m: c_char,
    pub time_h: c_char,
    pub time_d: c_char,
    pub id_no: LONG,
    pub reserve2: [LONG; 3],
}

/// Data of `cnc_rdgcodem`, `cnc_rstrt_rdmodal`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBGCD {
    pub group: c_short,
    pub flag: c_short,
    pub code: [c_char; 8],
}

/// Data of `cnc_rdprstrinfom`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPRSM {
    pub datano: c_short,
    pub r#type: c_short,
    pub data_info: [c_short; 5],
    pub rstr_bc: LONG,
    pub rstr_m: [LONG; 35],
    pub rstr_t: [LONG; 2],
    pub rstr_s: LONG,
    pub rstr_b: LONG,
    pub dest: [LONG; 32],
    pub dist: [LONG; 32],
}

/// Data of `cnc_rdpthis_aux`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBPTHIS_AUX {
    pub l_value: f64,
    pub l_value_e: f64,
    pub l_value_sub: f64,
    pub l_value_e_sub: f64,
    pub repeat_sub: LONG,
    pub repeat_e_sub: LONG,
    pub m_code: [LONG; 3],
    pub info1: LONG,
    pub number: c_short,
    pub number_sub: c_short,
    pub table_kind: c_short,
    pub m_count: c_char,
    pub master_indx_no_pt: c_char,
    pub master_indx_no_rel: c_char,
    pub l_frac: c_char,
    pub reserve1: [c_char; 6],
}

/// Data of `cnc_rdpthis_ax`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBPTHIS_AX {
    pub l_value: f64,
    pub l_value_e: f64,
    pub pos_value: f64,
    pub pos_value_e: f64,
    pub l_value_sub: f64,
    pub l_value_e_sub: f64,
    pub l_value_cycle: f64,
    pub l_value_e_cycle: f64,
    pub repeat_sub: LONG,
    pub repeat_e_sub: LONG,
    pub info1: LONG,
    pub number: c_short,
    pub number_sub: c_short,
    pub number_cycle: c_short,
    pub table_kind: c_short,
    pub name: [c_char; 4],
    pub cs_spdl_idx_pt: c_char,
    pub cs_spdl_idx_rel: c_char,
    pub master_indx_no_pt: c_char,
    pub master_indx_no_rel: c_char,
    pub pos_frac: c_char,
    pub l_frac: c_char,
    pub l_frac_cycle: c_char,
    pub reserve1: c_char,
}

/// The `date` member of `ODBPTHIS_GB`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPTHIS_GB_date {
    pub year: c_short,
    pub mon: c_char,
    pub day: c_char,
    pub hour: c_char,
    pub min: c_char,
    pub sec: c_char,
}

/// Data of `cnc_rdpthis_gb`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPTHIS_GB {
    pub date: ODBPTHIS_GB_date,
    pub reserve1: c_char,
    pub info1: LONG,
    pub path_num: c_char,
    pub reserve2: [c_char; 3],
}

/// Data of `cnc_rdpthis_log`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPTHIS_LOG {
    pub issub: c_char,
    pub kind: c_char,
    pub number: c_short,
}

/// Data of `cnc_rdpthis_pt`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBPTHIS_PT {
    pub time: f64,
    pub dist_err: c_short,
    pub ov_time: c_short,
    pub info1: LONG,
    pub alarm_no: c_short,
    pub alarm_type: c_char,
    pub alarm_axis: c_char,
    pub path_axis_num: c_char,
    pub path_spdl_num: c_char,
    pub time_frac: c_char,
    pub reserve1: c_char,
}

/// Data of `cnc_rdpthis_sp`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBPTHIS_SP {
    pub l_value: f64,
    pub l_value_e: f64,
    pub pos_value: f64,
    pub pos_value_e: f64,
    pub l_value_sub: f64,
    pub l_value_e_sub: f64,
    pub repeat_sub: LONG,
    pub repeat_e_sub: LONG,
    pub srpm: LONG,
    pub rrpm: LONG,
    pub sspm: LONG,
    pub smax: LONG,
    pub info1: LONG,
    pub number: c_short,
    pub number_sub: c_short,
    pub table_kind: c_short,
    pub sp_mode: c_char,
    pub name: [c_char; 4],
    pub ov_sp: c_char,
    pub reserve1: c_char,
    pub cs_axis_idx_pt: c_char,
    pub cs_axis_idx_rel: c_char,
    pub pos_frac: c_char,
    pub l_frac: c_char,
    pub reserve2: [c_char; 3],
}

/// Data of `cnc_rstrt_rdpntlist`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBRSTLIST {
    pub prg_name: [c_char; 246],
    pub dummy: [c_char; 2],
    pub seq_no: LONG,
    pub c_blck_cnt: LONG,
}

/// Data of `cnc_rstrt_rdpntlist2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBRSTLIST2 {
    pub prg_name: [c_char; 246],
    pub status: c_char,
    pub dummy: c_char,
    pub seq_no: LONG,
    pub wait_m_code: LONG,
    pub c_blck_cnt: LONG,
    pub time_s: c_char,
    pub time_m: c_char,
    pub time_h: c_char,
    pub time_d: c_char,
    pub id_no: LONG,
    pub reserve: [LONG; 3],
}

/// Data of `cnc_rstrt_rdlpmppnt`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBRSTMPINFO {
    pub u_block_num: LONG,
    pub mltpiece_all: LONG,
    pub mltpiece_exe: LONG,
    pub u_file_name: [c_char; 246],
}
