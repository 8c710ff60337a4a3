//! Eco mode and power consumption monitor (`cnc_powc_*`, `cnc_pwcm_*`).
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, MAX_AXIS, MAX_SPINDLE, ULONG};
use std::os::raw::{c_char, c_short, c_uchar, c_ushort};

/// Data of `cnc_powc_rd_cycle_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPOWCCYC {
    pub cycletime: ULONG,
    pub powc_axis: ULONG,
    pub powc_spindle: ULONG,
    pub powc_outer: ULONG,
}

/// Data of `cnc_powc_rd_history`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPOWCHISALL {
    pub powchis: [ODBPOWCHIS; 30],
}

/// Data of `cnc_powc_rd_outer_set`, `cnc_powc_wr_outer_set`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPOWCOUTER {
    pub ave_pow: [ULONG; 8],
    pub ref_ofs: c_ushort,
    pub ref_adrs: c_char,
    pub ref_path: c_uchar,
}

/// Data of `cnc_pwcm_rd_consump`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPWCMDAT {
    pub time: ULONG,
    pub axis_num: c_short,
    pub spindle_num: c_short,
    pub all: ODBPWCM,
    pub axis: [ODBPWCM; MAX_AXIS],
    pub spindle: [ODBPWCM; MAX_SPINDLE],
}

/// `cnc_pwcm_rd_consump`: read power consumption.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPWCM {
    pub consump: LONG,
    pub regen: LONG,
    pub net: LONG,
    pub present: LONG,
}

/// Data of `cnc_powc_rd_history`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPOWCHIS {
    pub get_time: ULONG,
    pub powc_axis: ULONG,
    pub powc_spindle: ULONG,
    pub powc_outer: ULONG,
}
