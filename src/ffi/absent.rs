//! Functions FANUC's header declares but none of its Ethernet libraries
//! implements. They are exported so that programs calling them link and
//! load, and they answer as FANUC's Windows library does on an Ethernet
//! handle: `EW_VERSION` (-7), without traffic, writing nothing. A bad handle
//! is `EW_HANDLE` (-8) first, as for every call.

use super::ffi_boundary;
use crate::client::handles;
use crate::error::{Error, Result};
use crate::types::{ODBALMMSG3, ODBSPDLNAME, PRGPNT};
use std::os::raw::{c_char, c_long, c_short, c_ulong, c_ushort, c_void};

/// The code function `name` answers (src/ffi/exported.rs).
fn code(name: &str) -> c_short {
    super::exported::ABSENT
        .iter()
        .find(|a| a.0 == name)
        .unwrap_or_else(|| panic!("{name} is not listed in src/ffi/exported.rs"))
        .1
}

/// The answer of function `name` (on a handle): the handle checked, then
/// its code.
fn not_on_ethernet(name: &str, h: c_ushort) -> Result<()> {
    handles::get(h)?;
    Err(Error::local(
        code(name),
        "not available on an Ethernet connection (as FANUC's library)",
    ))
}

/// Reads the execution pointer: HSSB only; `EW_VERSION` (-7) on Ethernet.
///
/// # Safety
/// Nothing is written through the pointers.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdexecpt(
    FlibHndl: c_ushort,
    pact: *mut PRGPNT,
    pnext: *mut PRGPNT,
) -> c_short {
    let _ = (pact, pnext);
    ffi_boundary!("cnc_rdexecpt", {
        not_on_ethernet("cnc_rdexecpt", FlibHndl)
    })
}

/// Reads program lines: HSSB only; `EW_VERSION` (-7) on Ethernet.
///
/// # Safety
/// Nothing is written through the pointers.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdprogline(
    FlibHndl: c_ushort,
    prog_no: c_long,
    line_no: c_ulong,
    prog_data: *mut c_char,
    line_len: *mut c_ulong,
    data_len: *mut c_ulong,
) -> c_short {
    let _ = (prog_no, line_no, prog_data, line_len, data_len);
    ffi_boundary!("cnc_rdprogline", {
        not_on_ethernet("cnc_rdprogline", FlibHndl)
    })
}

/// Starts reading servo data: HSSB only; `EW_VERSION` (-7) on Ethernet.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_svdtstartrd(FlibHndl: c_ushort, axis: c_short) -> c_short {
    let _ = axis;
    ffi_boundary!("cnc_svdtstartrd", {
        not_on_ethernet("cnc_svdtstartrd", FlibHndl)
    })
}

/// Reads servo data: HSSB only; `EW_VERSION` (-7) on Ethernet.
///
/// # Safety
/// Nothing is written through the pointers.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_svdtrddata(
    FlibHndl: c_ushort,
    stat: *mut c_short,
    length: *mut c_long,
    data: *mut c_void,
) -> c_short {
    let _ = (stat, length, data);
    ffi_boundary!("cnc_svdtrddata", {
        not_on_ethernet("cnc_svdtrddata", FlibHndl)
    })
}

/// Ends reading servo data: HSSB only; `EW_VERSION` (-7) on Ethernet.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_svdtendrd(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_svdtendrd", {
        not_on_ethernet("cnc_svdtendrd", FlibHndl)
    })
}

/// Reads spindle names (multi-path form): `EW_VERSION` (-7) on Ethernet.
///
/// # Safety
/// Nothing is written through the pointers.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdspdlnamem(
    FlibHndl: c_ushort,
    data_num: *mut c_short,
    spdlname: *mut ODBSPDLNAME,
) -> c_short {
    let _ = (data_num, spdlname);
    ffi_boundary!("cnc_rdspdlnamem", {
        not_on_ethernet("cnc_rdspdlnamem", FlibHndl)
    })
}

/// Reads alarm messages with 256-character texts: `EW_VERSION` (-7) on Ethernet.
///
/// # Safety
/// Nothing is written through the pointers.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmmsg3(
    FlibHndl: c_ushort,
    r#type: c_short,
    num: *mut c_short,
    almmsg: *mut ODBALMMSG3,
) -> c_short {
    let _ = (r#type, num, almmsg);
    ffi_boundary!("cnc_rdalmmsg3", {
        not_on_ethernet("cnc_rdalmmsg3", FlibHndl)
    })
}

/// Allocates a handle on FANUC's HSSB (optical fibre) driver, which an
/// Ethernet machine does not have: `EW_MMCSYS` (-3), as FANUC's library
/// answers without it. `*FlibHndl` is left as it was.
///
/// # Safety
/// Nothing is written through the pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_allclibhndl(FlibHndl: *mut c_ushort) -> c_short {
    let _ = FlibHndl;
    ffi_boundary!("cnc_allclibhndl", {
        Err(Error::local(
            code("cnc_allclibhndl"),
            "no HSSB driver: use cnc_allclibhndl3",
        ))
    })
}
