//! Five-axis and volumetric compensation, tilted working planes, 3-D interference
//! check shapes and learning control.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::LONG;
use std::os::raw::{c_char, c_short, c_uchar, c_ushort};

/// Data of `cnc_twp_rdfmt_mtrx`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IDBTWPFORM {
    pub euler: IDBTWP_EULER_FMT,
    pub rpy: IDBTWP_RPY_FMT,
    pub p3: IDBTWP_3P_FMT,
    pub vct2: IDBTWP_2VCT_FMT,
    pub pjct: IDBTWP_PJCT_FMT,
}

/// `cnc_wrrotvolc2`: write rotate volumetric compensation data (2).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBROTVOLC {
    pub lin: [LONG; 3],
    pub rot: [LONG; 3],
}

/// `cnc_rd5dmacmov`, `cnc_rd5dtooltip`: read tip of 5 axis manufacture send handle.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODB5DHDL {
    pub name: [c_char; 4],
    pub data: LONG,
    pub dec: c_short,
    pub flag: c_short,
    pub axis: c_short,
}

/// `cnc_rd5dpulse`: read pulse of 5 axis manufacture send handle.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODB5DPLS {
    pub name: [c_char; 3],
    pub data: LONG,
    pub dec: c_short,
}

/// `cnc_rdtdicubeinfo`: read cube infomation.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCBI {
    pub cb_no: c_ushort,
    pub nme_set: ODBNME,
    pub shp_no: c_uchar,
    pub cd_form: c_char,
}

/// `cnc_rdtdicubedata`, `cnc_wrtdicubedata`: read cube data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCUB {
    pub ref_vtx: [LONG; 3],
    pub adj_vtx1: [LONG; 3],
    pub adj_vtx2: [LONG; 3],
    pub adj_vtx3: [LONG; 3],
    pub n_unit: c_uchar,
    pub cb_form: c_char,
}

/// `cnc_rdtdicylinderdata`, `cnc_wrtdicylinderdata`: read cylinder data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCYL {
    pub sta_pnt: [LONG; 3],
    pub end_pnt: [LONG; 3],
    pub radius: LONG,
    pub n_unit: c_uchar,
    pub cb_form: c_char,
}

/// `cnc_rdfixoffs`, `cnc_wrfixoffs`: read rotary table dynamic fixture offset.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBFOFS {
    pub mcrval: LONG,
    pub decval: c_short,
}

/// Data of `cnc_twp_rdfmt_mtrx`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBFTRMTX {
    pub orgn: [f64; 3],
    pub rot: [[f64; 3]; 3],
}

/// `cnc_rdlrninfo`: read Parts Learning Data.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBLRNINFO {
    pub name: [c_char; 33],
    pub dummy1: [c_char; 3],
    pub axis: [[c_char; 4]; 4],
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub comment: [c_char; 33],
    pub dummy2: [c_char; 3],
}

/// `cnc_rdlrninfo2`: read Parts Learning Data.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBLRNINFO2 {
    pub name: [c_char; 33],
    pub dummy1: [c_char; 3],
    pub axis: [[c_char; 4]; 20],
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub comment: [c_char; 33],
    pub dummy2: [c_char; 3],
}

/// `cnc_rdlrninfol`: read Learning Data.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBLRNINFOL {
    pub axis: [c_char; 4],
    pub name: [c_char; 33],
    pub comment: [c_char; 33],
    pub path: c_char,
    pub dummy1: c_char,
}

/// `cnc_rdlrnprfcmnt`: read Profile Data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBLRNPRF {
    pub status: c_char,
    pub comment: [c_char; 17],
    pub path: c_char,
    pub dummy1: c_char,
}

/// `cnc_rdtdiplanedata`, `cnc_wrtdiplanedata`: read plane data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPLN {
    pub point: [LONG; 3],
    pub vect: [LONG; 3],
    pub n_unit: c_uchar,
    pub cb_form: c_char,
}

/// Data of `cnc_rdplutosmpl`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBRENPLT {
    pub delay_time: c_short,
    pub data_flag: c_ushort,
    pub pos_data: [c_short; 6],
}

/// Data of `cnc_rdsuo_prm_name`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSUODATA {
    pub data_name: [c_char; 4],
    pub prm_val: LONG,
    pub frc_dgt: LONG,
}

/// Data of `cnc_rdnutatortofs_vect`, `cnc_rdsuofs_vect`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSUOVECT {
    pub vect_val: LONG,
    pub frc_dgt: LONG,
}

/// `cnc_rdlrntrnsdata`: read Transfer Data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTRNS {
    pub status: c_short,
    pub pct: c_short,
    pub r#type: c_short,
    pub dummy: [c_char; 2],
}

/// Data of `cnc_rdtdicubeinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBNME {
    pub ob_type: c_short,
    pub obj_no: c_ushort,
    pub nme_no: c_ushort,
    pub suffix: c_ushort,
    pub name: [c_char; 12],
}

/// Data of `cnc_twp_rdfmt_mtrx`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IDBTWP_PJCT_FMT {
    pub orign: [f64; 3],
    pub i: f64,
    pub j: f64,
    pub k: f64,
    pub reserve: [LONG; 24],
}

/// Data of `cnc_twp_rdfmt_mtrx`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IDBTWP_2VCT_FMT {
    pub orign: [f64; 3],
    pub vtr1: [f64; 3],
    pub vtr2: [f64; 3],
    pub reserve: [LONG; 18],
}

/// Data of `cnc_twp_rdfmt_mtrx`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IDBTWP_3P_FMT {
    pub p1: [f64; 3],
    pub p2: [f64; 3],
    pub p3: [f64; 3],
    pub sft: [f64; 3],
    pub rot: f64,
    pub reserve: [LONG; 10],
}

/// Data of `cnc_twp_rdfmt_mtrx`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IDBTWP_RPY_FMT {
    pub orign: [f64; 3],
    pub i: f64,
    pub j: f64,
    pub k: f64,
    pub turn: c_short,
    pub reserve0: c_short,
    pub reserve: [LONG; 23],
}

/// Data of `cnc_twp_rdfmt_mtrx`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IDBTWP_EULER_FMT {
    pub orign: [f64; 3],
    pub i: f64,
    pub j: f64,
    pub k: f64,
    pub reserve: [LONG; 24],
}
