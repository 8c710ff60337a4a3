//! Tool numbers, tool life and counters.

#[allow(unused_imports)]
use super::{LONG, ULONG};
use std::os::raw::{c_char, c_short, c_uchar, c_ushort};

/// cnc_rdlife / cnc_rdcount (and cnc_rdntool): one tool life value of a group.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLIFE3 {
    pub datano: c_short,
    pub dummy: c_short,
    pub data: LONG,
}

/// One tool of a tool life group (ODBTG.data).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTG_DATA {
    pub tuse_num: LONG,
    pub tool_num: LONG,
    pub length_num: LONG,
    pub radius_num: LONG,
    pub tinfo: LONG,
}

/// cnc_rdtoolgrp: a tool life group with its tools (5 as declared; the
/// caller's `length` says how many really fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTG {
    pub grp_num: c_short,
    pub dummy: [c_short; 2],
    pub ntool: LONG,
    pub life: LONG,
    pub count: LONG,
    pub data: [ODBTG_DATA; 5],
}

/// cnc_rdtlctldata: tool control data of a punch press.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLCTL {
    pub slct: c_short,
    pub used_tool: c_short,
    pub turret_indx: c_short,
    pub zero_tl_no: LONG,
    pub t_axis_move: LONG,
    pub total_punch: [LONG; 2],
    pub t_axis_dec: c_char,
    pub reserve: c_char,
    pub reserves: [c_short; 10],
}

/// cnc_rdngrp: the number of tool life groups.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLIFE2 {
    pub dummy: [c_short; 2],
    pub data: LONG,
}

/// cnc_rdgrpid: the tool life group of a tool number (`type` the tool
/// number asked for, `dummy` untouched).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLIFE1 {
    pub dummy: c_short,
    pub r#type: c_short,
    pub data: LONG,
}

/// cnc_rdgrpid2: the tool life group of a tool number.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLIFE5 {
    pub dummy: LONG,
    pub r#type: LONG,
    pub data: LONG,
}

/// cnc_instlifedt: the tool to insert.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBITD {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: LONG,
}

/// One group of IODBTGI.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTGI_DATA {
    pub n_tool: LONG,
    pub count_value: LONG,
    pub counter: LONG,
    pub count_type: LONG,
}

/// cnc_rdgrpinfo / cnc_wrgrpinfo: tool life groups `s_grp`..=`e_grp` (5 as
/// declared; the caller's `length` says how many really fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTGI {
    pub s_grp: c_short,
    pub dummy: c_short,
    pub e_grp: c_short,
    pub data: [IODBTGI_DATA; 5],
}

/// cnc_rdtlusegrp: the next, in-use and selected tool life groups.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBUSEGRP {
    pub next: LONG,
    pub r#use: LONG,
    pub slct: LONG,
    pub opt_next: LONG,
    pub opt_use: LONG,
    pub opt_slct: LONG,
}

/// cnc_rdtool: one tool of the tool management data.
#[allow(non_snake_case)]
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMNG {
    pub T_code: LONG,
    pub life_count: LONG,
    pub max_life: LONG,
    pub rest_life: LONG,
    pub life_stat: c_uchar,
    pub cust_bits: c_uchar,
    pub tool_info: c_ushort,
    pub H_code: c_short,
    pub D_code: c_short,
    pub spindle_speed: LONG,
    pub feedrate: LONG,
    pub magazine: c_short,
    pub pot: c_short,
    pub G_code: c_short,
    pub W_code: c_short,
    pub gno: c_short,
    pub grp: c_short,
    pub edge: c_short,
    pub org_magazine: c_short,
    pub org_pot: c_short,
    pub edge_num: c_uchar,
    pub reserve_c: c_char,
    pub reserved: [LONG; 2],
    pub custom1: LONG,
    pub custom2: LONG,
    pub custom3: LONG,
    pub custom4: LONG,
    pub custom5: LONG,
    pub custom6: LONG,
    pub custom7: LONG,
    pub custom8: LONG,
    pub custom9: LONG,
    pub custom10: LONG,
    pub custom11: LONG,
    pub custom12: LONG,
    pub custom13: LONG,
    pub custom14: LONG,
    pub custom15: LONG,
    pub custom16: LONG,
    pub custom17: LONG,
    pub custom18: LONG,
    pub custom19: LONG,
    pub custom20: LONG,
}

/// cnc_regtool_f2: one tool of the tool management data with 40 custom
/// data (IODBTLMNG's members, then custom21..custom40).
#[allow(non_snake_case)]
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMNG_F2 {
    pub T_code: LONG,
    pub life_count: LONG,
    pub max_life: LONG,
    pub rest_life: LONG,
    pub life_stat: c_uchar,
    pub cust_bits: c_uchar,
    pub tool_info: c_ushort,
    pub H_code: c_short,
    pub D_code: c_short,
    pub spindle_speed: LONG,
    pub feedrate: LONG,
    pub magazine: c_short,
    pub pot: c_short,
    pub G_code: c_short,
    pub W_code: c_short,
    pub gno: c_short,
    pub grp: c_short,
    pub edge: c_short,
    pub org_magazine: c_short,
    pub org_pot: c_short,
    pub edge_num: c_uchar,
    pub reserve_c: c_char,
    pub reserved: [LONG; 2],
    pub custom1: LONG,
    pub custom2: LONG,
    pub custom3: LONG,
    pub custom4: LONG,
    pub custom5: LONG,
    pub custom6: LONG,
    pub custom7: LONG,
    pub custom8: LONG,
    pub custom9: LONG,
    pub custom10: LONG,
    pub custom11: LONG,
    pub custom12: LONG,
    pub custom13: LONG,
    pub custom14: LONG,
    pub custom15: LONG,
    pub custom16: LONG,
    pub custom17: LONG,
    pub custom18: LONG,
    pub custom19: LONG,
    pub custom20: LONG,
    pub custom21: LONG,
    pub custom22: LONG,
    pub custom23: LONG,
    pub custom24: LONG,
    pub custom25: LONG,
    pub custom26: LONG,
    pub custom27: LONG,
    pub custom28: LONG,
    pub custom29: LONG,
    pub custom30: LONG,
    pub custom31: LONG,
    pub custom32: LONG,
    pub custom33: LONG,
    pub custom34: LONG,
    pub custom35: LONG,
    pub custom36: LONG,
    pub custom37: LONG,
    pub custom38: LONG,
    pub custom39: LONG,
    pub custom40: LONG,
}

/// cnc_rdmagazine, cnc_regmagazine: one pot of the magazine management
/// data and the tool management data number in it.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMAG {
    pub magazine: c_short,
    pub pot: c_short,
    pub tool_index: c_short,
}

/// cnc_delmagazine: one pot of the magazine management data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMAG2 {
    pub magazine: c_short,
    pub pot: c_short,
}

/// cnc_rdtooldata: the tool data of a punch press.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLDT {
    pub slct: c_short,
    pub tool_no: LONG,
    pub x_axis_ofs: LONG,
    pub y_axis_ofs: LONG,
    pub turret_pos: LONG,
    pub chg_tl_no: LONG,
    pub punch_count: LONG,
    pub tool_life: LONG,
    pub m_tl_radius: LONG,
    pub m_tl_angle: LONG,
    pub tl_shape: c_char,
    pub tl_size_i: LONG,
    pub tl_size_j: LONG,
    pub tl_angle: LONG,
    pub x_axis_dec: c_char,
    pub y_axis_dec: c_char,
    pub turret_dec: c_char,
    pub m_radius_dec: c_char,
    pub m_angle_dec: c_char,
    pub tl_size_i_dec: c_char,
    pub tl_size_j_dec: c_char,
    pub tl_angle_dec: c_char,
    pub reserve: [c_short; 2],
}

/// cnc_rdtoolinfo: the tool data sizes of a punch press.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPTLINF {
    pub tld_max: c_short,
    pub mlt_max: c_short,
    pub reserve: c_short,
    pub tld_size: [c_short; 16],
    pub mlt_size: [c_short; 16],
    pub reserves: [c_short; 16],
}

/// cnc_rdtlinfo: the tool life management's limits.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLINFO {
    pub max_group: LONG,
    pub max_tool: LONG,
    pub max_minute: LONG,
    pub max_cycle: LONG,
}

/// cnc_rdusegrpid: the next, in-use and selected tool life groups
/// (`datano` and `type` untouched).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBUSEGR {
    pub datano: c_short,
    pub r#type: c_short,
    pub next: LONG,
    pub r#use: LONG,
    pub slct: LONG,
}

/// cnc_rdmaxgrp / cnc_rdmaxtool: the most tool life groups, or tools in a
/// group (`datano` and `type` untouched).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBLFNO {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: c_short,
}

/// cnc_rd1tlifedata / cnc_rd2tlifedata: one tool of a tool life group:
/// its number, H and D codes and information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTD {
    pub datano: c_short,
    pub r#type: c_short,
    pub tool_num: LONG,
    pub h_code: LONG,
    pub d_code: LONG,
    pub tool_inf: LONG,
}

/// cnc_rd1tlifedat2: one tool of a tool life group by a long use number
/// (`dummy` and `type` untouched).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTD2 {
    pub datano: c_short,
    pub dummy: c_short,
    pub r#type: LONG,
    pub tool_num: LONG,
    pub h_code: LONG,
    pub d_code: LONG,
    pub tool_inf: LONG,
}

/// One group of IODBTR.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTR_DATA {
    pub ntool: LONG,
    pub life: LONG,
    pub count: LONG,
}

/// cnc_rdtoolrng: tool life groups `datano_s`..=`datano_e`: tools, life
/// and counter (5 as declared; the caller's `length` says how many fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTR {
    pub datano_s: c_short,
    pub dummy: c_short,
    pub datano_e: c_short,
    pub data: [IODBTR_DATA; 5],
}

/// cnc_rdusetlno: the use number of the tool in use of each tool life
/// group `s_grp`..=`e_grp` (5 as declared; `length` says how many fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLUSE {
    pub s_grp: c_short,
    pub dummy: c_short,
    pub e_grp: c_short,
    pub data: [LONG; 5],
}

/// cnc_rdtltool: one tool of a tool life group: its number, H and D codes
/// and information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLTOOL {
    pub tool_num: LONG,
    pub h_code: LONG,
    pub d_code: LONG,
    pub tool_inf: LONG,
}

/// cnc_rdexchgtgrp: a tool life group whose tools must be exchanged, and
/// its optional group number.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBEXGP {
    pub grp_no: LONG,
    pub opt_grpno: LONG,
}
