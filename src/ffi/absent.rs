//! cnc_allclibhndl, declared by FANUC's header for its HSSB driver, which
//! none of its Ethernet libraries has: exported so that programs calling
//! it link and load, answering as FANUC's library does without the driver.
//! The functions that answer a code on a handle (`EW_VERSION`) are table
//! entries (src/spec/table/absent.rs).

use super::ffi_boundary;
use crate::error::Error;
use std::os::raw::{c_short, c_ushort};

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
        // The code src/ffi/exported.rs lists for it.
        let code = super::exported::ABSENT[0].1;
        Err(Error::local(code, "no HSSB driver: use cnc_allclibhndl3"))
    })
}
