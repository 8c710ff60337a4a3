//! Axes, modes and settings (the long tail): positions with extra digits,
//! the tool interference check, the coordinate rotation.

use super::LONG;
use std::os::raw::c_short;

/// cnc_absolute2_exdgt & co.: one axis's position with extra digits.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ODBEXPOS {
    pub data: f64,
    pub dec: LONG,
    pub digit: LONG,
}

/// cnc_rdinterference: the two tools of the interference check.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLINTF {
    pub inf_tool: [c_short; 2],
}

/// cnc_rdcdrotate: the coordinate rotation in force: its mode, the plane's
/// axes, the center and the angle.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBROT {
    pub mode: c_short,
    pub pln_axes: [c_short; 2],
    pub center: [LONG; 2],
    pub angle: LONG,
}
