//! Tool and work offsets.

#[allow(unused_imports)]
use super::{LONG, MAX_AXIS, ULONG};
use std::os::raw::c_short;

/// cnc_rdtofs: one tool offset value.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTOFS {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: LONG,
}

/// A tool offset with its imaginary tip number and 1 value (IODBTO.u.m_ofs_at).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTO_TIP1 {
    pub tip: c_short,
    pub data: [LONG; 1],
}

/// A tool offset with its imaginary tip number and 2 values (IODBTO.u.m_ofs_bt).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTO_TIP2 {
    pub tip: c_short,
    pub data: [LONG; 2],
}

/// A tool offset with its imaginary tip number and 4 values (m_ofs_ct, t_ofs_a).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTO_TIP4 {
    pub tip: c_short,
    pub data: [LONG; 4],
}

/// A tool offset with its imaginary tip number and 8 values (t_ofs_b).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTO_TIP8 {
    pub tip: c_short,
    pub data: [LONG; 8],
}

/// Two values of the extended lathe offsets (t_ofs_ex).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTO_EX {
    pub data: [LONG; 2],
}

/// The value area of IODBTO: one view per offset memory type (180 bytes).
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBTO_U {
    pub m_ofs: [LONG; 5],
    pub m_ofs_a: [LONG; 5],
    pub m_ofs_b: [LONG; 10],
    pub m_ofs_c: [LONG; 20],
    pub m_ofs_at: [IODBTO_TIP1; 5],
    pub m_ofs_bt: [IODBTO_TIP2; 5],
    pub m_ofs_ct: [IODBTO_TIP4; 5],
    pub t_tip: [c_short; 5],
    pub t_ofs: [LONG; 5],
    pub t_ofs_a: [IODBTO_TIP4; 5],
    pub t_ofs_b: [IODBTO_TIP8; 5],
    pub t_ofs_2g: [LONG; 15],
    pub m_ofs_cnr: [LONG; 10],
    pub t_ofs_ex: [IODBTO_EX; 5],
}

impl std::fmt::Debug for IODBTO_U {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // Every view covers the same bytes; show them as 4-byte values.
        let all: [LONG; 45] = unsafe { std::mem::transmute_copy(self) };
        f.debug_struct("IODBTO_U").field("values", &all).finish()
    }
}

/// cnc_rdtofsr: tool offsets of a number range (5 values as declared; the
/// caller's `length` says how many really fit).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct IODBTO {
    pub datano_s: c_short,
    pub r#type: c_short,
    pub datano_e: c_short,
    pub u: IODBTO_U,
}

/// cnc_rdtofsinfo: tool offset memory type and number of offsets.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLINF {
    pub ofs_type: c_short,
    pub use_no: c_short,
}

/// cnc_rdzofs / cnc_wrzofs: one work zero offset, one axis or all axes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBZOFS {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [LONG; MAX_AXIS],
}

/// cnc_rdzofsr: work zero offsets of a number range (as declared, 8 offsets
/// of MAX_AXIS values; the caller's `length` says how many really fit).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct IODBZOR {
    pub datano_s: c_short,
    pub r#type: c_short,
    pub datano_e: c_short,
    pub data: [LONG; 256], // 8 * MAX_AXIS
}

/// cnc_rdtofsinfo2: tool offset memory type, number of offsets, and which
/// offsets are enabled.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLINF2 {
    pub ofs_type: c_short,
    pub use_no: c_short,
    pub ofs_enable: c_short,
}

/// cnc_rdwkcdshft / cnc_wrwkcdshft: the work coordinate shift of one or
/// all axes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBWCSF {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [LONG; MAX_AXIS],
}

/// cnc_rdbtofsinfo: the B-axis tool offsets' memory type, how many there
/// are and the sub function number of offset cancel.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBBTLINF {
    pub ofs_type: c_short,
    pub use_no: c_short,
    pub sub_no: c_short,
}

/// cnc_rdradofs: the cutter compensation mode, the plane's two axes and
/// the offset vector in it.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBROFS {
    pub mode: c_short,
    pub pln_axes: [c_short; 2],
    pub ofsvct: [LONG; 2],
}

/// cnc_rd3dtofs: the 3-D tool offset mode, its three axes and the offset
/// vector.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODB3DTO {
    pub mode: c_short,
    pub ofs_axes: [c_short; 3],
    pub ofsvct: [LONG; 3],
}

/// cnc_rdtldata: the work zero point measurement's TL value and its
/// decimals.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLDATA {
    pub tl: LONG,
    pub tl_dp: LONG,
}

/// cnc_rdtlmsinfo: the tool length measurement: T and M codes, the
/// measured length and its decimals, the offset number.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLMSINF {
    pub t: LONG,
    pub m: LONG,
    pub hm: LONG,
    pub hm_dp: LONG,
    pub tlofs_no: LONG,
}

/// cnc_tofs_rnge / cnc_zofs_rnge / cnc_wksft_rnge: the range an offset's
/// value may be set in, and whether it may be set.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDATRNG {
    pub data_min: LONG,
    pub data_max: LONG,
    pub status: LONG,
}

/// cnc_rdvolccomp: the volumetric compensation amount of each axis (5 as
/// declared).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBVOLCOMP {
    pub comp: [LONG; 5],
}
