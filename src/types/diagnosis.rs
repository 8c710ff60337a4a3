//! Trouble diagnosis (`cnc_mdg_*`) and modification detection (`cnc_mdd_*`).
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, MAX_AXIS, ULONG};
use std::os::raw::{c_char, c_short, c_uchar, c_ushort};

/// Data of `cnc_mdd_getexceptparam`, `cnc_mdd_setexceptparam`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBMDDEXCEPTPRM {
    pub sno: LONG,
    pub eno: LONG,
}

/// Data of `cnc_mdg_rdalminfo`, `cnc_mdg_rdcontinfo`, `cnc_mdg_rddtmsg` ….
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBMDGINFO {
    pub alm_no: LONG,
    pub r#type: c_short,
    pub axis: c_short,
    pub path: c_short,
    pub reserved: c_short,
}

/// Data of `cnc_mdg_rdheatsimlt`, `cnc_mdg_rdloadlvl`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBLOAD {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [c_short; MAX_AXIS],
}

/// Data of `cnc_mdd_rdinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBMDDINFO {
    pub status: c_short,
    pub prot: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
    pub reg_code: ULONG,
    pub cur_code: ULONG,
    pub modulate: c_short,
}

/// Data of `cnc_mdg_rddtmsg`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBMDGDTMSG {
    pub message: [c_char; 1600],
    pub imgid: ULONG,
}

/// Data of `cnc_mdg_rdflow`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBMDGFLOW {
    pub msgidx: c_short,
    pub yesidx: c_short,
    pub noidx: c_short,
    pub reserved: c_short,
    pub message: [c_char; 400],
    pub detail: c_short,
    pub operate: c_short,
}

/// Data of `cnc_mdg_rdmsg`, `cnc_mdg_rdmsgordr`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBMDGMSG {
    pub alm_no: LONG,
    pub msgidx: c_short,
    pub reserved: c_short,
    pub r#type: [c_char; 4],
    pub part: [c_char; 4],
    pub level: [c_char; 4],
    pub add_inf: [c_char; 4],
    pub mark: [c_char; 20],
    pub message: [c_char; 100],
    pub cause: [c_char; 300],
}

/// Data of `cnc_mdg_rdwvdata`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBMDGWVDT {
    pub ldata: [LONG; 500],
    pub p_dec: c_ushort,
    pub num: c_ushort,
    pub channel: c_ushort,
    pub axis: c_ushort,
    pub kind: c_ushort,
    pub interval: c_ushort,
    pub t_cycle: c_ushort,
    pub unit: c_char,
    pub sw_alm: c_char,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBVIEWGRP2 {
    pub sv1: ODBSV2_GRP1,
    pub sv2: ODBSV2_GRP2,
    pub sv3: ODBSV2_GRP3,
    pub sv4: ODBSV2_GRP4,
    pub sv5: ODBSV2_GRP5,
    pub sv6: ODBSV2_GRP6,
    pub sv7: ODBSV2_GRP7,
    pub sp1: ODBSP2_GRP1,
    pub sp2: ODBSP2_GRP2,
    pub sp3: ODBSP2_GRP3,
    pub sp4: ODBSP2_GRP4,
    pub sp5: ODBSP2_GRP5,
    pub sp6: ODBSP2_GRP6,
    pub sp7: ODBSP2_GRP7,
    pub sp8: ODBSP2_GRP8,
    pub lat1: ODBLAT_GRP1,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBLAT_GRP1 {
    pub nnum: ULONG,
    pub prog: [c_char; 36],
    pub year: c_char,
    pub mon: c_char,
    pub day: c_char,
    pub hour: c_char,
    pub min: c_char,
    pub sec: c_char,
    pub reserved: [c_char; 2],
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSP2_GRP8 {
    pub isncr_intp: c_ushort,
    pub isncr_com: c_ushort,
    pub isncr_wrn: c_ushort,
    pub esncr_intp: c_ushort,
    pub esncr_com: c_ushort,
    pub esncr_wrn: c_ushort,
    pub sp_dat1: c_short,
    pub sp_dat2: c_short,
    pub sp_dat3: c_short,
    pub sp_dat4: c_short,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBSP2_GRP7 {
    pub iab_amplt: ODBMDGDT,
    pub eab_amplt: ODBMDGDT,
    pub iab_ofs_a: c_short,
    pub iab_ofs_b: c_short,
    pub iab_noise: c_short,
    pub eab_ofs_a: c_short,
    pub eab_ofs_b: c_short,
    pub eab_noise: c_short,
    pub iab_max_flt: c_ushort,
    pub eab_max_flt: c_ushort,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBMDGDT {
    pub dt: ODBMDGVAL,
    pub fp: c_short,
    pub reserved: c_short,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBMDGVAL {
    pub lval: LONG,
    pub ulval: ULONG,
    pub sval: c_short,
    pub usval: c_ushort,
    pub cval: c_char,
    pub ucval: c_uchar,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSP2_GRP6 {
    pub sp_up_err1: c_ushort,
    pub sp_up_err2: c_ushort,
    pub sp_lw_err1: c_ushort,
    pub sp_lw_err2: c_ushort,
    pub sp_up_jt1: c_ushort,
    pub sp_up_jt2: c_ushort,
    pub sp_lw_jt1: c_ushort,
    pub sp_lw_jt2: c_ushort,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSP2_GRP5 {
    pub ps_dgn: c_ushort,
    pub ps_sub_dgn: c_ushort,
    pub sp_dgn: c_ushort,
    pub ps_int_tmp: c_uchar,
    pub ps_sink_tmp: c_uchar,
    pub sp_int_tmp: c_uchar,
    pub sp_sink_tmp: c_uchar,
    pub amp_grp: c_uchar,
    pub amp_slv: c_uchar,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBSP2_GRP4 {
    pub resistance: ODBMDGDT,
    pub detect_res: c_uchar,
    pub reserved: [c_char; 7],
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBSP2_GRP3 {
    pub ps_vumb: ODBMDGDT,
    pub ps_vthd: ODBMDGDT,
    pub freq: ODBMDGDT,
    pub ps_vrms: c_ushort,
    pub ps_cur: c_ushort,
    pub dvolt: c_ushort,
    pub ps_statf: c_uchar,
    pub reserved: c_char,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBSP2_GRP2 {
    pub pos_err: LONG,
    pub syn_err: LONG,
    pub sp_spd: LONG,
    pub mt_spd: LONG,
    pub mt_cur: ODBMDGDT,
    pub ldmtr: c_ushort,
    pub trq_cmd: c_short,
    pub heat_mt: c_char,
    pub heat_amp: c_char,
    pub reserved: [c_char; 2],
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSP2_GRP1 {
    pub motion: LONG,
    pub cmd_spd: c_short,
    pub mode: c_char,
    pub gear: c_char,
    pub osel: c_char,
    pub reserved: [c_char; 3],
    pub sig_in: ODBSIGDIO,
    pub sig_out: ODBSIGDIO,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSIGDIO {
    pub sgnl1: c_char,
    pub sgnl2: c_char,
    pub sgnl3: c_char,
    pub sgnl4: c_char,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSV2_GRP7 {
    pub id_intp: c_ushort,
    pub id_com: c_ushort,
    pub id_wrn: c_ushort,
    pub ed_intp: c_ushort,
    pub ed_com: c_ushort,
    pub ed_wrn: c_ushort,
    pub sv_dat1: c_short,
    pub sv_dat2: c_short,
    pub sv_dat3: c_short,
    pub sv_dat4: c_short,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSV2_GRP6 {
    pub sv_up_err1: c_ushort,
    pub sv_up_err2: c_ushort,
    pub sv_lw_err1: c_ushort,
    pub sv_lw_err2: c_ushort,
    pub sv_up_jt1: c_ushort,
    pub sv_up_jt2: c_ushort,
    pub sv_lw_jt1: c_ushort,
    pub sv_lw_jt2: c_ushort,
    pub sdu_up_err1: c_ushort,
    pub sdu_up_err2: c_ushort,
    pub sdu_lw_err1: c_ushort,
    pub sdu_lw_err2: c_ushort,
    pub sdu_up_jt1: c_ushort,
    pub sdu_up_jt2: c_ushort,
    pub sdu_lw_jt1: c_ushort,
    pub sdu_lw_jt2: c_ushort,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSV2_GRP5 {
    pub ps_dgn: c_ushort,
    pub ps_sub_dgn: c_ushort,
    pub sv_dgn: c_ushort,
    pub ps_int_tmp: c_uchar,
    pub ps_sink_tmp: c_uchar,
    pub sv_int_tmp: c_uchar,
    pub sv_sink_tmp: c_uchar,
    pub amp_grp: c_uchar,
    pub amp_slv: c_uchar,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBSV2_GRP4 {
    pub resistance: ODBMDGDT,
    pub detect_res: c_uchar,
    pub reserved: [c_char; 7],
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBSV2_GRP3 {
    pub ps_vumb: ODBMDGDT,
    pub ps_vthd: ODBMDGDT,
    pub freq: ODBMDGDT,
    pub ps_vrms: c_ushort,
    pub ps_cur: c_ushort,
    pub dvolt: c_ushort,
    pub ps_statf: c_uchar,
    pub reserved: c_char,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBSV2_GRP2 {
    pub mt_cur: ODBMDGDT,
    pub trq_cmd: c_short,
    pub efc_cur: c_short,
    pub dlvl: c_ushort,
    pub heat: c_ushort,
    pub opt: c_short,
    pub opt2: c_short,
}

/// Data of `cnc_mdg_rdalminfoview2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBSV2_GRP1 {
    pub cmd_pls: LONG,
    pub fb_pls: LONG,
    pub refc: LONG,
    pub pos_err: LONG,
    pub act_spd: ODBMDGDT,
    pub amr: c_ushort,
    pub reserved: c_short,
}
