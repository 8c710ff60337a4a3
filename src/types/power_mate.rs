//! Power Mate manager (`cnc_pmm*`) and the Power Mate D/H axis movement calls.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::LONG;
use std::os::raw::{c_char, c_short, c_uchar, c_ushort};

/// Data of `cnc_pmmgetstart`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBPMMGTI {
    pub top: LONG,
    pub num: LONG,
}

/// Data of `cnc_rdpmmprmtp`, `cnc_wrpmmprmtp`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IDBPMMPRP {
    pub chanl: LONG,
    pub group: LONG,
    pub folder: [c_char; 130],
    pub warn: LONG,
}

/// Data of `cnc_pmmget`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPMMGET {
    pub pos: LONG,
    pub feed: LONG,
    pub data: [LONG; 20],
    pub number: [LONG; 20],
    pub axis: [c_short; 20],
    pub r#type: [c_short; 20],
    pub alaxis: [c_char; 40],
    pub alnumber: [c_ushort; 40],
    pub chanl: LONG,
    pub group: LONG,
}

/// Data of `cnc_pmmiochanl`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMMIO {
    pub chanlnum: LONG,
}

/// Data of `cnc_pmmprmpage`, `cnc_wrpmmprm`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMMPRP {
    pub data: LONG,
    pub number: c_ushort,
    pub axis: c_uchar,
    pub r#type: c_uchar,
}

/// Data of `cnc_pmminit`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMMSLV {
    pub slvnum: LONG,
    pub group: [LONG; 8],
}

/// Data of `cnc_pmmsysdt`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMMSYD {
    pub system: [c_char; 2],
    pub model: [c_char; 2],
    pub series: [c_char; 4],
    pub edition: [c_char; 4],
}

// --- Power Mate D/H axis movement (FANUC's header declares these under
// `#if defined (PMD)`: not in the default variant, so not in layouts.json;
// their l32 layouts are checked by hand in tests/artifacts/abi.rs) ---

/// `cnc_opdi`: the axis and a signal value of one of three widths.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ODBOPDI {
    pub axis: c_short,
    pub u: ODBOPDI_u,
}

/// The `u` member of `ODBOPDI`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBOPDI_u {
    pub cdata: c_char,
    pub idata: c_short,
    pub ldata: LONG,
}

/// `cnc_refpoint`, `cnc_abspoint` … `cnc_exebufstat`: the execution state of each path.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBEXEC {
    pub dummy: c_short,
    pub cdata: [[c_char; 8]; 2],
}

/// `cnc_finstate`, `cnc_setfin`: the completion flags of each path.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBFIN {
    pub dummy: c_short,
    pub cdata: [c_char; 8],
}
