//! Machining conditions, high-speed and HPCC settings, laser work data, smart adaptive
//! control.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, MAX_AXIS, REALPRM};
use std::os::raw::{c_char, c_short, c_uchar, c_ushort};

/// Data of `cnc_rdhsparam`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union HSPDATA {
    pub cdata: [c_char; MAX_AXIS],
    pub idata: [c_short; MAX_AXIS],
    pub ldata: [LONG; MAX_AXIS],
    pub rdata: [REALPRM; MAX_AXIS],
}

/// Data of `cnc_rdhsparamm`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union HSPDATAM {
    pub cdata: [c_char; 32],
    pub idata: [c_short; 32],
    pub ldata: [LONG; 32],
    pub rdata: [REALPRM; 32],
}

/// `cnc_rdhsparam`, `cnc_rdhsparamm`, `cnc_rdhsprminfo`: read the information for function cnc_rdhsparam().
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct HSPINFO {
    pub prminfo: [[c_char; 16]; 8],
}

/// `cnc_wrlswork`: white laser work data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBLSWORK {
    pub slct: c_short,
    pub skeyinf: c_short,
    pub reserve: [c_short; 14],
}

/// The `data` member of `IODBCTPR`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBCTPR_data {
    pub acc_bipl: [LONG; MAX_AXIS],
    pub acc_chg_time: LONG,
    pub jerk_acc_diff: [LONG; MAX_AXIS],
    pub jerk_acc_diff_lin: [LONG; MAX_AXIS],
    pub jerk_acc_ratio: c_char,
    pub max_acc: [LONG; MAX_AXIS],
    pub t_con_aipl: [c_short; MAX_AXIS],
    pub corner_feed_diff: [LONG; MAX_AXIS],
    pub max_cut_fdrate: [LONG; MAX_AXIS],
}

/// The `u` member of `IODBCTPR_prm`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBCTPR_prm_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub cdatas: [c_char; MAX_AXIS],
    pub idatas: [c_short; MAX_AXIS],
    pub ldatas: [LONG; MAX_AXIS],
}

/// One element of `IODBCTPR.prm`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBCTPR_prm {
    pub datano: c_short,
    pub r#type: c_short,
    pub u: IODBCTPR_prm_u,
}

/// `cnc_rdcdslctprm`: read the machining condition parameters.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBCTPR {
    pub data: IODBCTPR_data,
    pub prm: [IODBCTPR_prm; 2],
}

/// The `data_160` member of `IODBCTPRM_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBCTPRM_data_data_160 {
    pub acc_bipl: [LONG; 8],
    pub acc_chg_time: LONG,
    pub jerk_acc_diff: [LONG; 8],
    pub jerk_acc_diff_lin: [LONG; 8],
    pub jerk_acc_ratio: c_char,
    pub max_acc: [LONG; 8],
    pub t_con_aipl: [c_short; 8],
    pub corner_feed_diff: [LONG; 8],
    pub max_cut_fdrate: [LONG; 8],
}

/// The `data_30i` member of `IODBCTPRM_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBCTPRM_data_data_30i {
    pub acc_bipl: [REALPRM; 32],
    pub acc_chg_time: REALPRM,
    pub jerk_acc_diff: [REALPRM; 32],
    pub jerk_acc_diff_lin: [REALPRM; 32],
    pub jerk_acc_ratio: c_char,
    pub max_acc: [REALPRM; 32],
    pub t_con_aipl: [c_short; 32],
    pub corner_feed_diff: [REALPRM; 32],
    pub max_cut_fdrate: [REALPRM; 32],
}

/// The `data` member of `IODBCTPRM`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBCTPRM_data {
    pub data_160: IODBCTPRM_data_data_160,
    pub data_30i: IODBCTPRM_data_data_30i,
}

/// The `u` member of `IODBCTPRM_prm`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBCTPRM_prm_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub rdata: REALPRM,
    pub cdatas: [c_char; 32],
    pub idatas: [c_short; 32],
    pub ldatas: [LONG; 32],
    pub rdatas: [REALPRM; 32],
}

/// One element of `IODBCTPRM.prm`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBCTPRM_prm {
    pub datano: c_short,
    pub r#type: c_short,
    pub u: IODBCTPRM_prm_u,
}

/// `cnc_rdcdslctprmm`: read the machining condition parameters.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBCTPRM {
    pub data: IODBCTPRM_data,
    pub prm: [IODBCTPRM_prm; 2],
}

/// One element of `IODBHPAC.tune`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBHPAC_tune {
    pub slct: c_short,
    pub diff: c_short,
    pub fine: c_short,
    pub acc_lv: c_short,
    pub bipl: LONG,
    pub aipl: c_short,
    pub corner: LONG,
    pub clamp: LONG,
    pub c_acc: LONG,
    pub foward: LONG,
    pub reserve: [LONG; 8],
}

/// `cnc_rdhpcctuac`, `cnc_wrhpcctuac`: read hpcc tuning data ( acc input ).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBHPAC {
    pub tune: [IODBHPAC_tune; 3],
}

/// One element of `IODBHPPR.tune`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBHPPR_tune {
    pub slct: c_short,
    pub diff: c_short,
    pub fine: c_short,
    pub acc_lv: c_short,
    pub max_f: LONG,
    pub bipl: c_short,
    pub aipl: c_short,
    pub corner: LONG,
    pub clamp: c_short,
    pub radius: LONG,
    pub max_cf: LONG,
    pub min_cf: LONG,
    pub foward: LONG,
    pub reserve: [LONG; 5],
}

/// `cnc_rdhpcctupr`, `cnc_wrhpcctupr`: read hpcc tuning data ( parameter input ).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBHPPR {
    pub tune: [IODBHPPR_tune; 3],
}

/// `cnc_rdhpccset`, `cnc_wrhpccset`: read hpcc setting data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBHPST {
    pub slct: c_short,
    pub hpcc: c_short,
    pub multi: c_short,
    pub ovr1: c_short,
    pub ign_f: c_short,
    pub foward: c_short,
    pub max_f: LONG,
    pub ovr2: c_short,
    pub ovr3: c_short,
    pub ovr4: c_short,
    pub reserve: [LONG; 7],
}

/// `cnc_rdpscdproc2`, `cnc_wrpscdproc2`: read processing condition file (processing data).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPSCD2 {
    pub slct: LONG,
    pub feed: LONG,
    pub power: c_short,
    pub freq: c_short,
    pub duty: c_short,
    pub g_press: c_short,
    pub g_kind: c_short,
    pub g_ready_t: c_short,
    pub displace: c_short,
    pub supple: LONG,
    pub edge_slt: c_short,
    pub appr_slt: c_short,
    pub pwr_ctrl: c_short,
    pub displace2: LONG,
    pub gap_axis: c_char,
    pub feed_dec: c_char,
    pub supple_dec: c_char,
    pub dsp2_dec: c_char,
    pub pb_power: c_short,
    pub reserve: [c_short; 8],
}

/// Data of `cnc_rct_rdGrpName`, `cnc_rct_wrGrpName`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRCT_CSTMNAME {
    pub grp_num: c_ushort,
    pub dummy: c_ushort,
    pub grp_name: [c_char; 16],
    pub ptn_name: [[c_char; 16]; 3],
}

/// Data of `cnc_rct_rdPtnSlct`, `cnc_rct_wrPtnSlct`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRCT_GRPPTN {
    pub grp_num: c_ushort,
    pub ptn_num: c_ushort,
}

/// The `uParam` member of `IODBRCT_ITEM_ptn`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBRCT_ITEM_ptn_uParam {
    pub bdata: c_char,
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub rdata: REALPRM,
    pub bdatas: [c_char; MAX_AXIS],
    pub cdatas: [c_char; MAX_AXIS],
    pub idatas: [c_short; MAX_AXIS],
    pub ldatas: [LONG; MAX_AXIS],
    pub rdatas: [REALPRM; MAX_AXIS],
}

/// One element of `IODBRCT_ITEM.ptn`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBRCT_ITEM_ptn {
    pub enable: c_char,
    pub dummy2: [c_char; 3],
    pub attr2: LONG,
    pub uParam: IODBRCT_ITEM_ptn_uParam,
}

/// Data of `cnc_rct_rdItem`, `cnc_rct_wrItem`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBRCT_ITEM {
    pub item_num: c_ushort,
    pub r#type: c_uchar,
    pub axsp_num: c_char,
    pub ptn_num: c_char,
    pub dummy: c_uchar,
    pub attr: c_ushort,
    pub ptn: [IODBRCT_ITEM_ptn; 6],
}

/// The `u` member of `IODBSOCTLDAT`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBSOCTLDAT_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub rdata: REALPRM,
}

/// Data of `cnc_rdsoc_tldat`, `cnc_wrsoc_tldat`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBSOCTLDAT {
    pub u: IODBSOCTLDAT_u,
}

/// Data of `cnc_mcs_rdheader`, `cnc_mcs_wrheader`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBMCSHEAD {
    pub layout: c_char,
    pub string1: [c_char; 51],
    pub string2: [c_char; 51],
}

/// Data of `cnc_rdpressure`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPRESSURE {
    pub cmd_val: LONG,
    pub feedbak_val: LONG,
}

/// Data of `cnc_rct_rdslctptnname`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBRCT_SLCTPTNNAME {
    pub sl_ptrn_no: LONG,
    pub sl_nm_slct: c_short,
}

/// Data of `cnc_rdsoc_curdat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSOCCUR {
    pub mode: c_short,
    pub table: c_short,
    pub dummy: LONG,
    pub ovrr: CUROVRR,
    pub load: CURLOAD,
    pub temp: CURTEMP,
    pub rdtm: CURRDTM,
}

/// Data of `cnc_rdsoc_tlatrr`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSOCTLATTR {
    pub prm_no: c_short,
    pub r#type: c_char,
}

/// Data of `cnc_rdscdldat`, `cnc_wrscdldat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SCDL_1D {
    pub file_no: c_short,
    pub file_name: [c_char; 16],
    pub repeat_num: c_short,
    pub current_num: c_short,
    pub dummy: [c_char; 2],
}

/// Data of `cnc_rdsoc_curdat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CURRDTM {
    pub current: c_ushort,
    pub threshold: c_ushort,
    pub dummy: LONG,
}

/// Data of `cnc_rdsoc_curdat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CURTEMP {
    pub current: c_ushort,
    pub start: c_ushort,
    pub end: c_ushort,
    pub alarm: c_ushort,
    pub dummy: LONG,
}

/// Data of `cnc_rdsoc_curdat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CURLOAD {
    pub current: c_ushort,
    pub effect: c_ushort,
    pub target: c_ushort,
    pub irregular: c_ushort,
    pub dummy: LONG,
}

/// Data of `cnc_rdsoc_curdat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CUROVRR {
    pub current: c_ushort,
    pub minmum: c_ushort,
    pub maximum: c_ushort,
    pub dummy: c_short,
}
