//! Servo sampling, tuning and feedback; real-time I/O and PMC signal monitoring.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, MAX_AXIS, ULONG};
use std::os::raw::{c_char, c_short, c_uchar, c_ushort, c_void};

/// Data of `cnc_sdtsetchnl2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBSDTCHAN2 {
    pub r#type: c_short,
    pub chno: c_char,
    pub axis: c_char,
    pub shift: c_ushort,
    pub io: [PMC_DATA; 16],
}

/// `cnc_wrtrqlimit`: Set torque limit data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBTRQ {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [c_ushort; MAX_AXIS],
}

/// `pmc_rdpmcrng_ext`: read PMC data.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBPMCEXT {
    pub type_a: c_short,
    pub type_d: c_short,
    pub datano_s: c_short,
    pub datano_e: c_short,
    pub err_code: c_short,
    pub reserved: c_short,
    pub data: *mut c_void,
}

/// Data of `cnc_rdrtmiowrenbl`, `cnc_rdrtmiowrenblbit`, `cnc_wrrtmiowrenbl` ….
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRTMIO {
    pub adr_type: c_short,
    pub dummy: c_short,
    pub no: ULONG,
    pub bit: c_char,
}

/// Data of `cnc_getrtmioinfo`, `cnc_rdrtmiowrenblrng`, `cnc_wrrtmiowrenblrng`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRTMIOR {
    pub adr_type: c_short,
    pub adr_attr: LONG,
    pub sno: ULONG,
    pub eno: ULONG,
}

/// One element of `IODBSIG2.data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBSIG2_data {
    pub ent_no: c_short,
    pub sig_no: c_short,
    pub sig_name: c_char,
    pub mask_pat: c_char,
}

/// `cnc_rdhissgnl2`, `cnc_wrhissgnl2`: read signals related operation history 2.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBSIG2 {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [IODBSIG2_data; 45],
}

/// Data of `cnc_msr_rdhis_pmc_ex`, `cnc_msr_rdmon_pmcinf_ex`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBEXPMCSGNL {
    pub inf: [ODBEXPMCSGNLINF; 2],
    pub exsgnlterm: [[ODBEXPMCSGNLTERM; 32]; 2],
}

/// `pmc_rdpmcaddr`: read PMC address information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMCADR {
    pub pmc_adr: c_ushort,
    pub adr_attr: c_ushort,
    pub adr: ULONG,
    pub top: ULONG,
    pub num: ULONG,
}

/// `cnc_rdftrq_info`: Get setting information of "Fine toruqe sensing function".
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBP_FTRQ_PRM_INF {
    pub smpl_enbl: c_char,
    pub cycle: c_char,
    pub axis_num: c_char,
    pub dummy1: c_char,
}

/// Data of `cnc_sdtreadsmpl2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBSD {
    pub chadata: *mut c_ushort,
    pub count: *mut LONG,
}

/// `cnc_rdsvfeedback`: Read Servo feedback multiplication data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSVFBACK {
    pub dummy: c_short,
    pub dtype: c_short,
    pub fback: [LONG; MAX_AXIS],
    pub afback: [LONG; MAX_AXIS],
}

/// One element of `ODBTUNREQ.stat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTUNREQ_stat {
    pub status: c_short,
    pub dummy: c_short,
}

/// Data of `cnc_reqsvgtung`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTUNREQ {
    pub stat: [ODBTUNREQ_stat; MAX_AXIS],
}

/// One element of `ODBTUNSTAT.stat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTUNSTAT_stat {
    pub status: c_short,
    pub dummy: c_short,
}

/// Data of `cnc_rdsvgtungstat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTUNSTAT {
    pub stat: [ODBTUNSTAT_stat; MAX_AXIS],
}

/// The `w` member of `ODBWVDT2_u`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBWVDT2_u_w {
    pub axis: c_short,
    pub kind: c_char,
}

/// The `io` member of `ODBWVDT2_u`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBWVDT2_u_io {
    pub no: c_short,
    pub adr: c_char,
    pub bit: c_char,
}

/// The `u` member of `ODBWVDT2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBWVDT2_u {
    pub w: ODBWVDT2_u_w,
    pub io: ODBWVDT2_u_io,
}

/// The `start` member of `ODBWVDT2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBWVDT2_start {
    pub year: c_char,
    pub month: c_char,
    pub day: c_char,
    pub hour: c_char,
    pub minute: c_char,
    pub second: c_char,
}

/// The `stop` member of `ODBWVDT2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBWVDT2_stop {
    pub year: c_char,
    pub month: c_char,
    pub day: c_char,
    pub hour: c_char,
    pub minute: c_char,
    pub second: c_char,
}

/// Data of `cnc_rdwavedata2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBWVDT2 {
    pub channel: c_short,
    pub u: ODBWVDT2_u,
    pub start: ODBWVDT2_start,
    pub stop: ODBWVDT2_stop,
    pub t_cycle: c_short,
    pub adjust: c_short,
    pub data: [c_short; 8192],
}

/// Data of `cnc_sdtstartsmpl2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TRG_DATA {
    pub seq_no: LONG,
    pub pmc_trg: PMC_DATA,
}

/// Data of `cnc_sdtsetchnl2`, `cnc_sdtstartsmpl2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PMC_DATA {
    pub unittype: c_short,
    pub adr: c_char,
    pub bit: c_uchar,
    pub no: c_ushort,
}

/// Data of `cnc_msr_rdhis_pmc_ex`, `cnc_msr_rdmon_pmcinf_ex`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBEXPMCSGNLTERM {
    pub data: c_char,
    pub dummy: c_char,
}

/// Data of `cnc_msr_rdhis_pmc_ex`, `cnc_msr_rdmon_pmcinf_ex`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBEXPMCSGNLINF {
    pub pmc_no: c_char,
    pub kind: c_char,
    pub length: c_char,
    pub dummy: c_char,
    pub top_adrs: LONG,
}
