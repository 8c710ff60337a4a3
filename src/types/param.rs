//! Parameters and diagnostics.

use super::{LONG, MAX_AXIS};
use std::os::raw::{c_char, c_short, c_ushort};

/// A real parameter value: `prm_val · 10^-dec_val`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct REALPRM {
    pub prm_val: LONG,
    pub dec_val: LONG,
}

/// A real diagnosis value: `dgn_val · 10^-dec_val`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct REALDGN {
    pub dgn_val: LONG,
    pub dec_val: LONG,
}

/// The value union of IODBPSD: which member is valid depends on the
/// parameter's type and on whether one axis or all axes were read.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBPSD_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub rdata: REALPRM,
    pub cdatas: [c_char; MAX_AXIS],
    pub idatas: [c_short; MAX_AXIS],
    pub ldatas: [LONG; MAX_AXIS],
    pub rdatas: [REALPRM; MAX_AXIS],
}

impl Default for IODBPSD_u {
    fn default() -> Self {
        IODBPSD_u {
            rdatas: [REALPRM::default(); MAX_AXIS],
        }
    }
}

impl std::fmt::Debug for IODBPSD_u {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // Every member is plain data, and the union is fully covered by rdatas.
        let v = unsafe { self.ldatas };
        f.debug_struct("IODBPSD_u").field("ldatas", &v).finish()
    }
}

/// cnc_rdparam / cnc_wrparam: one parameter (`type` = axis: 0 none, n, -1 all).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct IODBPSD {
    pub datano: c_short,
    pub r#type: c_short,
    pub u: IODBPSD_u,
}

/// The value union of ODBDGN.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBDGN_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
    pub rdata: REALDGN,
    pub cdatas: [c_char; MAX_AXIS],
    pub idatas: [c_short; MAX_AXIS],
    pub ldatas: [LONG; MAX_AXIS],
    pub rdatas: [REALDGN; MAX_AXIS],
}

impl Default for ODBDGN_u {
    fn default() -> Self {
        ODBDGN_u {
            rdatas: [REALDGN::default(); MAX_AXIS],
        }
    }
}

impl std::fmt::Debug for ODBDGN_u {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let v = unsafe { self.ldatas };
        f.debug_struct("ODBDGN_u").field("ldatas", &v).finish()
    }
}

/// cnc_diagnoss: one diagnosis data item (`type` = axis: 0 none, n, -1 all).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ODBDGN {
    pub datano: c_short,
    pub r#type: c_short,
    pub u: ODBDGN_u,
}

/// One value of IODBPRM.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPRM_data {
    pub prm_val: LONG,
    pub dec_val: LONG,
}

/// cnc_rdparam_ext / cnc_rddiag_ext: one parameter (or diagnosis) record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPRM {
    pub datano: LONG,
    pub r#type: c_short,
    pub axis: c_short,
    pub info: c_short,
    pub unit: c_short,
    pub data: [IODBPRM_data; 32],
}

/// One entry of ODBPARAIF.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPARAIF_info {
    pub prm_no: c_short,
    pub prm_type: c_short,
}

/// cnc_rdparainfo: parameter numbers and attributes (10 entries declared;
/// `read_no` entries may be used with a larger buffer).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPARAIF {
    pub info_no: c_ushort,
    pub prev_no: c_short,
    pub next_no: c_short,
    pub info: [ODBPARAIF_info; 10],
}

/// One entry of ODBDIAGIF.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDIAGIF_info {
    pub diag_no: c_short,
    pub diag_type: c_short,
}

/// cnc_rddiaginfo: diagnosis numbers and attributes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDIAGIF {
    pub info_no: c_ushort,
    pub prev_no: c_short,
    pub next_no: c_short,
    pub info: [ODBDIAGIF_info; 10],
}

/// cnc_rdparanum: smallest and largest parameter number, and how many exist.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPARANUM {
    pub para_min: c_ushort,
    pub para_max: c_ushort,
    pub total_no: c_ushort,
}

/// cnc_rdsetnum: smallest and largest setting data number, and how many
/// exist.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSETNUM {
    pub set_min: c_ushort,
    pub set_max: c_ushort,
    pub total_no: c_ushort,
}

/// cnc_rddiagnum: smallest and largest diagnosis number, and how many exist.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDIAGNUM {
    pub diag_min: c_ushort,
    pub diag_max: c_ushort,
    pub total_no: c_ushort,
}

/// cnc_rdparainfo3: the attributes of one parameter.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPARAIF2 {
    pub prm_no: c_short,
    pub size: c_short,
    pub array: c_short,
    pub unit: c_short,
    pub dim: c_short,
    pub input: c_short,
    pub display: c_short,
    pub others: c_short,
}
