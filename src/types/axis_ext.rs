//! Axis data beyond position.rs: graphic positions, indexing, distances, overstore.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, MAX_AXIS, MAX_CNCPATH, ULONG};
use std::os::raw::{c_char, c_int, c_short, c_uchar, c_ushort};

/// Data of `cnc_nextdistance`, `cnc_nextdistance_bg`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBAXIS {
    pub axnum: c_int,
    pub data: [LONG; MAX_AXIS],
    pub dp: [LONG; MAX_AXIS],
}

/// Data of `cnc_rdindexdata`, `cnc_wrindexdata`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBINDEXDAT {
    pub pos: LONG,
    pub inp_width: LONG,
    pub speed: c_ushort,
    pub f_flg: c_char,
    pub dummy: c_char,
}

/// Data of `cnc_rdindexposdata`, `cnc_wrindexposdata`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBINDEXPOSDAT {
    pub min_value: LONG,
    pub max_value: LONG,
    pub setting: c_char,
    pub dummy: [c_char; 3],
}

/// Data of `cnc_rdindexprm`, `cnc_wrindexprm`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBINDEXPRM {
    pub ofs_limit: LONG,
    pub detect_width: LONG,
    pub jog_clamp: [c_ushort; 3],
    pub matrix_single: c_char,
    pub torque_ovr: c_uchar,
    pub ofs_adjust: c_char,
    pub dummy: [c_char; 3],
}

/// `cnc_rdmovrlapm`: read manual overlapped motion value.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBOVLM {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [[LONG; 32]; 2],
}

/// `cnc_rdoverstore`, `cnc_wroverstore`: read overstore command.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBOVSTR {
    pub mcode: IODBOVMST,
    pub scode: IODBOVMST,
    pub tcode: IODBOVMST,
    pub bcode: IODBOVMST,
}

/// Data of `cnc_rdpalaxis`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPALAX {
    pub max_pal: LONG,
    pub data: [LONG; MAX_AXIS],
}

/// One element of `IODBPITCHBLK.pginf`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPITCHBLK_pginf {
    pub s_no: LONG,
    pub e_no: LONG,
    pub attr: c_short,
}

/// `cnc_rdpitchblkinfo`: read pitch compensation data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPITCHBLK {
    pub group_num: c_short,
    pub pginf: [IODBPITCHBLK_pginf; 8],
}

/// One element of `ODBAHDCK.info`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHDCK_info {
    pub stat: c_short,
    pub data: c_short,
}

/// Data of `cnc_hdck_nochange_info`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHDCK {
    pub dat_path: c_short,
    pub info: [ODBAHDCK_info; MAX_CNCPATH],
}

/// Data of `cnc_machine3_ex`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAXIS_EX {
    pub counter: c_short,
    pub r#type: c_short,
    pub data: [LONG; MAX_AXIS],
}

/// Data of `cnc_rdaxisstatus_bg`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAXSTS_BG {
    pub flag: LONG,
}

/// Data of `cnc_cannedcycle`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBCANCMD {
    pub p_data: CMNDDATA,
    pub q_data: CMNDDATA,
    pub r_data: CMNDDATA,
    pub z_data: CMNDDATA,
}

/// Data of `cnc_rdchopping`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCHOPPING {
    pub cur_pos: REALNUM,
    pub cur_speed: REALNUM,
    pub real_udp: REALNUM,
    pub real_ldp: REALNUM,
    pub stroke_cnt: ULONG,
}

/// Data of `cnc_rd_grpaxisinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBGRPAXIS {
    pub path_num: c_short,
    pub draw_num: c_short,
}

/// Data of `cnc_rd_grppos`, `cnc_rd_grppos3`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBGRPPOS {
    pub abs: POSVAL,
    pub mcn: POSVAL,
    pub feed_type: c_short,
    pub reserved: c_short,
}

/// Data of `cnc_rdindexinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBINDEXINFO {
    pub mode: c_ushort,
    pub nc_ax: c_short,
    pub inpos_point: c_short,
    pub ofs_edit_signal: c_short,
}

/// Data of `cnc_rdipltp`, `cnc_rdipltp_bg`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBIPL {
    pub outpt: c_uchar,
    pub ipltp: c_uchar,
    pub mv: c_uchar,
    pub inp: c_uchar,
}

/// Data of `cnc_rdpmcaxisinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMCAXISINFO {
    pub datastatus: c_uchar,
    pub axisstatus: c_uchar,
    pub commandsignal: c_uchar,
    pub statussignal: c_uchar,
    pub dummy: c_uchar,
    pub instruction: c_uchar,
    pub speedsignal: c_ushort,
    pub axisctrldata: ULONG,
    pub subinstnum: c_ushort,
    pub subinstlength: c_ushort,
    pub subinstdata1: ULONG,
    pub subinstdata2: ULONG,
    pub subinstdata3: ULONG,
    pub subinstdata4: ULONG,
    pub subinstdata5: ULONG,
    pub subinstdata6: ULONG,
    pub subinstdata7: ULONG,
}

/// `cnc_rdposfig`: read position and decimal figure.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPOSFIG {
    pub val: LONG,
    pub dec: LONG,
}

/// Data of `cnc_rdactpos_w`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBWACT {
    pub data: [LONG; 6],
}

/// `cnc_rd_grppos`, `cnc_rd_grppos3`: read graphic position.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct POSVAL {
    pub data: LONG,
    pub dec: LONG,
}

/// Data of `cnc_rdchopping`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct REALNUM {
    pub val: LONG,
    pub dec: LONG,
}

/// `cnc_cannedcycle`: read canned command data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CMNDDATA {
    pub val: f64,
    pub dec: LONG,
    pub dummy: LONG,
}

/// `cnc_rdoverstore`, `cnc_wroverstore`: read overstore command.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBOVMST {
    pub adrs: c_char,
    pub num: LONG,
}
