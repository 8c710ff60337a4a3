//! Tool numbers, tool life and counters.

#[allow(unused_imports)]
use super::{LONG, ULONG};
use std::os::raw::{c_char, c_short};

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
