//! The C structures of `fwlib32.h` (default variant), with FANUC's names.
//!
//! Fields FANUC's header spells `long` are 32-bit here (`LONG`/`ULONG`):
//! FANUC's x86-64 library reads and writes them as 4 bytes, and so do we
//! (the `l32` layouts of layouts.json, checked by tests/abi.rs).

#![allow(non_camel_case_types)]

use std::os::raw::{c_char, c_short};

/// FANUC's LONG: 32 bits on every platform, as its Linux documentation defines it.
pub type LONG = i32;
/// FANUC's ULONG: 32 bits on every platform.
pub type ULONG = u32;

/// Maximum number of axes (Linux Ethernet build).
pub const MAX_AXIS: usize = 32;
/// Maximum number of spindles.
pub const MAX_SPINDLE: usize = 8;

/// cnc_sysinfo: CNC system information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSYS {
    pub addinfo: c_short,
    pub max_axis: c_short,
    pub cnc_type: [c_char; 2],
    pub mt_type: [c_char; 2],
    pub series: [c_char; 4],
    pub version: [c_char; 4],
    pub axes: [c_char; 2],
}

/// cnc_statinfo: CNC status information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBST {
    pub hdck: c_short,
    pub tmmode: c_short,
    pub aut: c_short,
    pub run: c_short,
    pub motion: c_short,
    pub mstb: c_short,
    pub emergency: c_short,
    pub alarm: c_short,
    pub edit: c_short,
}

/// cnc_statinfo2: CNC status information 2.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBST2 {
    pub hdck: c_short,
    pub tmmode: c_short,
    pub aut: c_short,
    pub run: c_short,
    pub motion: c_short,
    pub mstb: c_short,
    pub emergency: c_short,
    pub alarm: c_short,
    pub edit: c_short,
    pub warning: c_short,
    pub o3dchk: c_short,
    pub ext_opt: c_short,
    pub restart: c_short,
}

/// cnc_getdtailerr: detail of the last error.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBERR {
    pub err_no: c_short,
    pub err_dtno: c_short,
}

/// Copies wire characters into a C char array.
pub(crate) fn chars<const N: usize>(b: [u8; N]) -> [c_char; N] {
    b.map(|x| x as c_char)
}
