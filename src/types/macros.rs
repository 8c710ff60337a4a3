//! Custom macro variables.

#[allow(unused_imports)]
use super::{LONG, ULONG};
use std::os::raw::c_short;

/// cnc_rdmacro: one custom macro variable. The value is
/// `mcr_val · 10^-dec_val`; a vacant variable reads as mcr_val 0, dec_val -1.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBM {
    /// Variable number.
    pub datano: c_short,
    pub dummy: c_short,
    /// Value digits.
    pub mcr_val: LONG,
    /// Decimal places (-1: vacant).
    pub dec_val: c_short,
}

/// One variable of IODBMR.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBMR_data {
    /// Value digits.
    pub mcr_val: LONG,
    /// Decimal places (-1: vacant).
    pub dec_val: c_short,
}

/// cnc_rdmacror / cnc_wrmacror: a range of custom macro variables. FANUC's
/// header declares 5 records; callers pass larger buffers for more
/// (`length` = 8 + 8 · count).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBMR {
    /// First variable number.
    pub datano_s: c_short,
    pub dummy: c_short,
    /// Last variable number.
    pub datano_e: c_short,
    pub data: [IODBMR_data; 5],
}

/// cnc_rdmacroinfo: custom macro variable information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBMVINF {
    pub use_no1: c_short,
    pub use_no2: c_short,
}

/// cnc_rdpmacroinfo: the P-code macro variables' information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMINF {
    /// Variables #10000.. the CNC has.
    pub use_no1: c_short,
    /// Variables #20000.. (extended P-code variables).
    pub use_no2: c_short,
    /// Type of the extended variables.
    pub v2_type: c_short,
}

/// cnc_rdpmacro: one P-code macro variable. The value is
/// `mcr_val · 10^-dec_val`; a vacant variable reads as mcr_val 0, dec_val -1.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPM {
    /// Variable number.
    pub datano: LONG,
    pub dummy: c_short,
    /// Value digits.
    pub mcr_val: LONG,
    /// Decimal places (-1: vacant).
    pub dec_val: c_short,
}

/// cnc_rdpmacroinfo2: the P-code macro variables' information (2).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPMINF2 {
    /// Variables #10000.. the CNC has.
    pub use_no1: LONG,
    /// Extended variables #20000..
    pub use_no2: LONG,
    /// Extended variables #200000..
    pub use_no20: LONG,
    /// Type of the variables #10000..
    pub v1_type: c_short,
    /// Type of the extended variables #20000..
    pub v2_type: c_short,
    /// Type of the extended variables #200000..
    pub v20_type: c_short,
}

/// One variable of IODBPR.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPR_data {
    /// Value digits.
    pub mcr_val: LONG,
    /// Decimal places (-1: vacant).
    pub dec_val: c_short,
}

/// cnc_rdpmacror / cnc_wrpmacror: a range of P-code macro variables.
/// FANUC's header declares 5 records; callers pass larger buffers for more
/// (`length` = 12 + 8 · count).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPR {
    /// First variable number.
    pub datano_s: LONG,
    pub dummy: c_short,
    /// Last variable number.
    pub datano_e: LONG,
    pub data: [IODBPR_data; 5],
}
