//! The IEEE double versions (`*64`) of parameters, offsets and positions.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, MAX_AXIS};
use std::os::raw::{c_char, c_short};

/// `cnc_prstwkcd64`: preset work coordinate.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IDBWRA64 {
    pub datano: c_short,
    pub r#type: c_short,
    pub dummy: [c_short; 2],
    pub data: [REALDATA; MAX_AXIS],
}

/// `cnc_wrrelpos64`: set origin / preset relative axis position.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IDBWRR64 {
    pub datano: c_short,
    pub r#type: c_short,
    pub dummy: [c_short; 2],
    pub data: [REALDATA; MAX_AXIS],
}

/// The `u` member of `IODBPSD64`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBPSD64_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub rdata: REALDATA,
    pub cdatas: [c_char; MAX_AXIS],
    pub idatas: [c_short; MAX_AXIS],
    pub ldatas: [LONG; MAX_AXIS],
    pub rdatas: [REALDATA; MAX_AXIS],
}

/// `cnc_rdparam64`, `cnc_wrparam64`: read  parameter (IEEE double version).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBPSD64 {
    pub datano: c_short,
    pub r#type: c_short,
    pub axis: c_short,
    pub dummy: c_short,
    pub u: IODBPSD64_u,
}

/// `cnc_rdwkcdsfms64`, `cnc_rdwkcdshft64`, `cnc_wrwkcdsfms64` …: read  work coordinate shift.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IODBWCSF64 {
    pub dummy1: c_short,
    pub r#type: c_short,
    pub dummy2: [c_short; 2],
    pub data: [REALDATA; MAX_AXIS],
}

/// `cnc_wrzofs64`: write work zero offset value.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct IODBZOFS64 {
    pub datano: c_short,
    pub r#type: c_short,
    pub dummy: [c_short; 2],
    pub data: [REALDATA; MAX_AXIS],
}

/// `cnc_rdzofsr64`: read work zero offset value(area specified).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IODBZOR64 {
    pub datano_s: c_short,
    pub r#type: c_short,
    pub datano_e: c_short,
    pub dummy: c_short,
    pub data: [REALDATA; 256],
}

/// `cnc_rdaxisdata64`: read various axis data(IEEE double version).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBAXDT64 {
    pub name: [c_char; 4],
    pub dummy: [c_char; 4],
    pub data: f64,
    pub dec: c_short,
    pub unit: c_short,
    pub flag: c_short,
    pub reserve: c_short,
}

/// `cnc_rdcommand64`: read command value.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBCMD64 {
    pub adrs: c_char,
    pub num: c_char,
    pub flag: c_short,
    pub dec_val: LONG,
    pub cmd_val: f64,
}

/// `cnc_wksft_rnge64`, `cnc_zofs_rnge64`: read validity of work zero offset.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBDATRNG64 {
    pub data_min: f64,
    pub data_max: f64,
    pub dec: LONG,
    pub status: LONG,
}

/// The `u` member of `ODBDGN64`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBDGN64_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub rdata: REALDATA,
    pub cdatas: [c_char; MAX_AXIS],
    pub idatas: [c_short; MAX_AXIS],
    pub ldatas: [LONG; MAX_AXIS],
    pub rdatas: [REALDATA; MAX_AXIS],
}

/// Data of `cnc_diagnoss64`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBDGN64 {
    pub datano: c_short,
    pub r#type: c_short,
    pub axis: c_short,
    pub dummy: c_short,
    pub u: ODBDGN64_u,
}

/// Data of `cnc_rdholmes64`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBHOLDATA64 {
    pub mes_val1: [f64; 2],
    pub mes_dp1: [LONG; 2],
    pub mes_val2: [f64; 2],
    pub mes_dp2: [LONG; 2],
    pub mes_val3: [f64; 2],
    pub mes_dp3: [LONG; 2],
    pub mes_axis: [c_char; 2],
    pub mes_parl: [c_char; 2],
}

/// Data of `cnc_diagnoss64`, `cnc_prstwkcd64`, `cnc_rdblkdist` ….
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct REALDATA {
    pub val: f64,
    pub dec: LONG,
    pub dummy: LONG,
}

/// Data of `cnc_wrtofsdrctinp64`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct REALMES64 {
    pub mes_val: f64,
    pub dec_val: LONG,
    pub dummy: LONG,
}
