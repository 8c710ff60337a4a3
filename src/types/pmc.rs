//! PMC areas.

#[allow(unused_imports)]
use super::{LONG, ULONG};
use std::os::raw::{c_char, c_short, c_ushort};

/// The data of IODBPMC: bytes, words, longs (4 bytes each), floats or
/// doubles, by the request's data type.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBPMC_u {
    pub cdata: [c_char; 5],
    pub idata: [c_short; 5],
    pub ldata: [LONG; 5],
    pub fdata: [f32; 5],
    pub dfdata: [f64; 5],
}

impl Default for IODBPMC_u {
    fn default() -> Self {
        IODBPMC_u { dfdata: [0.0; 5] }
    }
}

impl std::fmt::Debug for IODBPMC_u {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // SAFETY: every bit pattern is a valid [u8; 40].
        let b: [u8; 40] = unsafe { std::mem::transmute(*self) };
        f.debug_struct("IODBPMC_u").field("bytes", &b).finish()
    }
}

/// pmc_rdpmcrng / pmc_wrpmcrng: a range of PMC addresses. FANUC's header
/// declares 5 elements; callers pass larger buffers for more
/// (`length` = 8 + bytes of data).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct IODBPMC {
    /// Address type: 0 G, 1 F, 2 Y, 3 X, 4 A, 5 R, 6 T, 7 K, 8 C, 9 D, ...
    pub type_a: c_short,
    /// Data type: 0 byte, 1 word, 2 long (4 bytes), 4 float, 5 double.
    pub type_d: c_short,
    /// First address (a byte address).
    pub datano_s: c_short,
    /// Last address (a byte address).
    pub datano_e: c_short,
    pub u: IODBPMC_u,
}

/// One area of ODBPMCINF.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMCINF_info {
    /// Address letter ('G', 'F', ...).
    pub pmc_adr: c_char,
    /// Attribute bits of the area, as the CNC reports them.
    pub adr_attr: c_char,
    /// First address.
    pub top_num: c_ushort,
    /// Last address.
    pub last_num: c_ushort,
}

/// pmc_rdpmcinfo: the PMC areas and their address ranges.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPMCINF {
    /// Number of areas in `info`.
    pub datano: c_short,
    pub info: [ODBPMCINF_info; 64],
}

impl Default for ODBPMCINF {
    fn default() -> Self {
        ODBPMCINF {
            datano: 0,
            info: [ODBPMCINF_info::default(); 64],
        }
    }
}

/// pmc_getdtailerr: detail of the last PMC error.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMCERR {
    pub err_no: c_short,
    pub err_dtno: c_short,
}

/// pmc_rdpmctitle: the PMC program's title data (texts, not terminated).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPMCTITLE {
    pub mtb: [c_char; 48],
    pub machine: [c_char; 48],
    pub r#type: [c_char; 48],
    pub prgno: [c_char; 8],
    pub prgvers: [c_char; 4],
    pub prgdraw: [c_char; 48],
    pub date: [c_char; 32],
    pub design: [c_char; 48],
    pub written: [c_char; 48],
    pub remarks: [c_char; 48],
}

/// pmc_rdalmmsg: one PMC alarm message (the caller passes an array of
/// them); text, zero-padded.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPMCALM {
    pub almmsg: [c_char; 128],
}

/// pmc_rdpmctitle2: the PMC program's title data, with longer program
/// number and version fields than ODBPMCTITLE's (texts, not terminated).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPMCTITLE2 {
    pub mtb: [c_char; 48],
    pub machine: [c_char; 48],
    pub r#type: [c_char; 48],
    pub prgno: [c_char; 16],
    pub prgvers: [c_char; 16],
    pub prgdraw: [c_char; 48],
    pub date: [c_char; 32],
    pub design: [c_char; 48],
    pub written: [c_char; 48],
    pub remarks: [c_char; 48],
}

/// pmc_read_seq_program_and_memory_type: the sequence program's type and
/// the PMC memory type, as codes (4 bytes each) and texts.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(non_snake_case)]
pub struct ODBPMCLADMEMTYPE {
    pub SystemType: ULONG,
    pub SystemAttribute: ULONG,
    pub TargetType: ULONG,
    pub TargetAttribute: ULONG,
    pub SystemTypeStr: [c_char; 32],
    pub TargetTypeStr: [c_char; 32],
}
