//! Status, alarms, macros and program data beyond status.rs and program.rs.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, MAX_AXIS, REALPRM, ULONG};
use std::os::raw::{c_char, c_short, c_ushort};

/// One element of `ALMINFO2_u_alm1.alm`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ALMINFO2_u_alm1_alm {
    pub axis: c_short,
    pub alm_no: c_short,
}

/// The `alm1` member of `ALMINFO2_u`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ALMINFO2_u_alm1 {
    pub alm: [ALMINFO2_u_alm1_alm; 5],
    pub data_end: c_short,
}

/// One element of `ALMINFO2_u_alm2.alm`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ALMINFO2_u_alm2_alm {
    pub axis: c_short,
    pub alm_no: c_short,
    pub msg_len: c_short,
    pub alm_msg: [c_char; 34],
}

/// The `alm2` member of `ALMINFO2_u`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ALMINFO2_u_alm2 {
    pub alm: [ALMINFO2_u_alm2_alm; 5],
    pub data_end: c_short,
}

/// The `u` member of `ALMINFO2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ALMINFO2_u {
    pub alm1: ALMINFO2_u_alm1,
    pub alm2: ALMINFO2_u_alm2,
}

/// `cnc_rdalminfo2`: read alarm information.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ALMINFO2 {
    pub u: ALMINFO2_u,
}

/// Data of `cnc_read_cexeinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CEXEINFO {
    pub cond: LONG,
    pub cycle: LONG,
    pub count: LONG,
    pub time: LONG,
    pub dummy1: LONG,
    pub dummy2: LONG,
    pub dummy3: LONG,
    pub dummy4: LONG,
}

/// The `u` member of `IODBBOOK`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBBOOK_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub rdata: REALPRM,
}

/// `cnc_preset_prm`: parameter preset.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBBOOK {
    pub param_no: c_short,
    pub axis: c_char,
    pub r#type: c_char,
    pub u: IODBBOOK_u,
}

/// Data of `cnc_srcsrdidinfo`, `cnc_srcswridinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBIDINF {
    pub id_no: LONG,
    pub drv_no: c_short,
    pub acc_element: c_short,
    pub err_general: c_short,
    pub err_id_no: c_short,
    pub err_id_name: c_short,
    pub err_attr: c_short,
    pub err_unit: c_short,
    pub err_min_val: c_short,
    pub err_max_val: c_short,
    pub id_name_len: c_short,
    pub id_name_max: c_short,
    pub id_name: [c_char; 60],
    pub attr: LONG,
    pub unit_len: c_short,
    pub unit_max: c_short,
    pub unit: [c_char; 12],
    pub min_val: LONG,
    pub max_val: LONG,
}

/// `cnc_rdmacror2_name`: read custom macro names(area specified).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IODBMRN {
    pub mcr_val: f64,
    pub name: [c_char; 16],
}

/// `cnc_rdmacror4`: read custom macro names(area specified).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IODBMRN4 {
    pub mcr_val: f64,
    pub name: [c_char; 64],
}

/// `cnc_rdactpt_w`: read execution pointer of program for FS160is/180is-WB.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBACTPTW {
    pub mprgno: LONG,
    pub mblkno: LONG,
    pub sprgno: LONG,
    pub sblkno: LONG,
}

/// One element of `ODBAHIS3.alm_his`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS3_alm_his {
    pub alm_grp: c_short,
    pub alm_no: c_short,
    pub axis_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub len_msg: c_short,
    pub pth_no: c_short,
    pub dummy: c_short,
    pub alm_msg: [c_char; 32],
}

/// `cnc_rdalmhistry3`: read alarm history data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS3 {
    pub s_no: c_ushort,
    pub e_no: c_ushort,
    pub alm_his: [ODBAHIS3_alm_his; 10],
}

/// One element of `ODBDLLVERSION.dll`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBDLLVERSION_dll {
    pub Name: [c_char; 260],
    pub FileVersion: [c_char; 32],
    pub ProductVersion: [c_char; 32],
}

/// Data of `cnc_getdllversion`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBDLLVERSION {
    pub dll: [ODBDLLVERSION_dll; 2],
}

/// The `faxis` member of `ODBDY3_pos`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDY3_pos_faxis {
    pub absolute: [LONG; MAX_AXIS],
    pub machine: [LONG; MAX_AXIS],
    pub relative: [LONG; MAX_AXIS],
    pub distance: [LONG; MAX_AXIS],
}

/// The `oaxis` member of `ODBDY3_pos`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDY3_pos_oaxis {
    pub absolute: LONG,
    pub machine: LONG,
    pub relative: LONG,
    pub distance: LONG,
}

/// The `pos` member of `ODBDY3`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBDY3_pos {
    pub faxis: ODBDY3_pos_faxis,
    pub oaxis: ODBDY3_pos_oaxis,
}

/// `cnc_rddynamic3`: read all dynamic data(3).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBDY3 {
    pub dummy: c_short,
    pub axis: c_short,
    pub alarm: LONG,
    pub prgnum: LONG,
    pub prgmnum: LONG,
    pub seqnum: LONG,
    pub actf: LONG,
    pub acts: LONG,
    pub pos: ODBDY3_pos,
}

/// The `faxis` member of `ODBDY3M_pos`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDY3M_pos_faxis {
    pub absolute: [LONG; 32],
    pub machine: [LONG; 32],
    pub relative: [LONG; 32],
    pub distance: [LONG; 32],
}

/// The `oaxis` member of `ODBDY3M_pos`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDY3M_pos_oaxis {
    pub absolute: LONG,
    pub machine: LONG,
    pub relative: LONG,
    pub distance: LONG,
}

/// The `pos` member of `ODBDY3M`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBDY3M_pos {
    pub faxis: ODBDY3M_pos_faxis,
    pub oaxis: ODBDY3M_pos_oaxis,
}

/// `cnc_rddynamic3m`: read all dynamic data(3m).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBDY3M {
    pub dummy: c_short,
    pub axis: c_short,
    pub alarm: LONG,
    pub prgnum: LONG,
    pub prgmnum: LONG,
    pub seqnum: LONG,
    pub actf: LONG,
    pub acts: LONG,
    pub pos: ODBDY3M_pos,
}

/// Data of `cnc_rdexecprog3`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBEXEPRGINFO {
    pub before_buffering: EXEPRG,
    pub after_buffering: EXEPRG,
}

/// One element of `ODBLALMHIS.alm_his`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBLALMHIS_alm_his {
    pub lalm_wrg: c_short,
    pub alm_grp: c_short,
    pub alm_wrg_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub len_msg: c_short,
    pub alm_msg: [c_char; 64],
    pub reserve: [c_short; 4],
}

/// Data of `cnc_rdlalmhistry`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBLALMHIS {
    pub s_no: c_ushort,
    pub e_no: c_ushort,
    pub alm_his: [ODBLALMHIS_alm_his; 50],
}

/// `cnc_rdmacro3`: read custom macro variable (3).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBM3 {
    pub datano: LONG,
    pub mcr_val: LONG,
    pub dec_val: c_short,
}

/// `cnc_rdmdlconfig`: read CNC module configuration information.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBMDLC {
    pub from: c_short,
    pub dram: c_short,
    pub sram: c_short,
    pub pmc: c_short,
    pub crtc: c_short,
    pub servo12: c_short,
    pub servo34: c_short,
    pub servo56: c_short,
    pub servo78: c_short,
    pub sic: c_short,
    pub pos_lsi: c_short,
    pub hi_aio: c_short,
    pub reserve: [c_short; 12],
    pub drmmrc: c_short,
    pub drmarc: c_short,
    pub pmcmrc: c_short,
    pub dmaarc: c_short,
    pub iopt: c_short,
    pub hdiio: c_short,
    pub gm2gr1: c_short,
    pub crtgr2: c_short,
    pub gm1gr2: c_short,
    pub gm2gr2: c_short,
    pub cmmrb: c_short,
    pub sv5axs: c_short,
    pub sv7axs: c_short,
    pub sicaxs: c_short,
    pub posaxs: c_short,
    pub hamaxs: c_short,
    pub romr64: c_short,
    pub srmr64: c_short,
    pub dr1r64: c_short,
    pub dr2r64: c_short,
    pub iopio2: c_short,
    pub hdiio2: c_short,
    pub cmmrb2: c_short,
    pub romfap: c_short,
    pub srmfap: c_short,
    pub drmfap: c_short,
    pub drmare: c_short,
    pub pmcmre: c_short,
    pub dmaare: c_short,
    pub frmbgg: c_short,
    pub drmbgg: c_short,
    pub asrbgg: c_short,
    pub edtpsc: c_short,
    pub slcpsc: c_short,
    pub reserve2: [c_short; 34],
}

/// `cnc_rdpmacroinfo3`: read P code macro variable information (3).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMINF3 {
    pub use_no1: c_short,
    pub use_no2: ULONG,
    pub v1_type: c_short,
    pub v2_type: c_short,
}

/// `cnc_rdpmacvalflag`: read P code macro variable flag.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMVALFLG {
    pub exe_type: c_short,
    pub aux_type: c_short,
    pub tlk_type: c_short,
}

/// `cnc_rdprotect2`: read protect status.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPRTCT2 {
    pub disp: c_short,
    pub edit: c_short,
    pub encd: c_short,
    pub lock: c_short,
    pub output: c_short,
    pub dummy: c_short,
}

/// Data of `cnc_rdproctime3`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPTIME3 {
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
    pub dummy: c_short,
}

/// Data of `cnc_srcsrdlayout`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSRCSLYT {
    pub spndl: [c_short; 4],
    pub servo: [c_short; 8],
    pub axis_name: [c_char; 8],
}

/// Data of `cnc_srcsrdexstat`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSRCSST {
    pub acc_element: c_short,
    pub err_general: c_short,
    pub err_id_no: c_short,
    pub err_attr: c_short,
    pub err_op_data: c_short,
}

/// Data of `cnc_sysconfig`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSYSC {
    pub slot_no_p: [c_char; 16],
    pub slot_no_l: [c_char; 16],
    pub mod_id: [c_short; 16],
    pub soft_id: [c_short; 16],
    pub s_series: [[c_char; 5]; 16],
    pub s_version: [[c_char; 5]; 16],
    pub dummy: [c_char; 16],
    pub m_rom: c_short,
    pub s_rom: c_short,
    pub svo_soft: [c_char; 8],
    pub pmc_soft: [c_char; 6],
    pub lad_soft: [c_char; 6],
    pub mcr_soft: [c_char; 8],
    pub spl1_soft: [c_char; 6],
    pub spl2_soft: [c_char; 6],
    pub frmmin: c_short,
    pub drmmin: c_short,
    pub srmmin: c_short,
    pub pmcmin: c_short,
    pub crtmin: c_short,
    pub sv1min: c_short,
    pub sv3min: c_short,
    pub sicmin: c_short,
    pub posmin: c_short,
    pub drmmrc: c_short,
    pub drmarc: c_short,
    pub pmcmrc: c_short,
    pub dmaarc: c_short,
    pub iopt: c_short,
    pub hdiio: c_short,
    pub frmsub: c_short,
    pub drmsub: c_short,
    pub srmsub: c_short,
    pub sv5sub: c_short,
    pub sv7sub: c_short,
    pub sicsub: c_short,
    pub possub: c_short,
    pub hamsub: c_short,
    pub gm2gr1: c_short,
    pub crtgr2: c_short,
    pub gm1gr2: c_short,
    pub gm2gr2: c_short,
    pub cmmrb: c_short,
    pub sv5axs: c_short,
    pub sv7axs: c_short,
    pub sicaxs: c_short,
    pub posaxs: c_short,
    pub hanaxs: c_short,
    pub romr64: c_short,
    pub srmr64: c_short,
    pub dr1r64: c_short,
    pub dr2r64: c_short,
    pub iopio2: c_short,
    pub hdiio2: c_short,
    pub cmmrb2: c_short,
    pub romfap: c_short,
    pub srmfap: c_short,
    pub drmfap: c_short,
}

/// `cnc_rdopmsgmps`: read operator message for MAPPS.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OPMSGMPS {
    pub datano: c_short,
    pub r#type: c_short,
    pub char_num: c_short,
    pub data: [c_char; 256],
}

/// `cnc_rdexecprog3`: read execute-program infomation.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EXEPRG {
    pub length: c_ushort,
    pub prep_blk: c_short,
    pub act_blk: c_short,
    pub dummy: c_short,
    pub data: [c_char; 512],
}
