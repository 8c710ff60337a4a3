//! The functions FANUC's header declares but none of its Ethernet
//! libraries implements, exported so that programs calling them link and
//! load. Each answers as FANUC's library does on an Ethernet handle:
//! `EW_VERSION` for the rows of src/spec/table/absent/ (build.rs writes
//! their exports into `$OUT_DIR/absent.rs`, included here), `EW_MMCSYS`
//! for cnc_allclibhndl (no HSSB driver).

use super::ffi_boundary;
use crate::client::handles;
use crate::error::Error;
use crate::ew::EW_VERSION;
#[allow(unused_imports)]
use crate::types::*;
#[allow(unused_imports)]
use std::os::raw::{c_char, c_int, c_long, c_short, c_uchar, c_uint, c_ulong, c_ushort, c_void};

/// The body of every export of src/spec/table/absent/, given an address
/// inside the export (its name is the dynamic symbol there): `EW_VERSION`
/// once the handle is checked, without traffic, writing nothing.
extern "C" fn not_on_ethernet(h: c_ushort, at: *const c_void) -> c_short {
    // SAFETY: dladdr reads the loaded objects' symbol tables; the name it
    // gives is the export's, in the library's string table, as long as the
    // library is loaded (this call).
    let name = unsafe {
        let mut info: libc::Dl_info = std::mem::zeroed();
        match libc::dladdr(at, &mut info) != 0 && !info.dli_sname.is_null() {
            true => std::ffi::CStr::from_ptr(info.dli_sname).to_str().ok(),
            false => None,
        }
    };
    super::boundary(name.unwrap_or("a function not on Ethernet"), &mut || {
        handles::get(h)?;
        Err(Error::local(
            EW_VERSION,
            "not in FANUC's Ethernet libraries",
        ))
    })
}

/// An export's body on x86-64 and aarch64: an address inside it as the
/// second argument, then a jump to [`not_on_ethernet`] (the handle stays
/// the first).
#[cfg(target_arch = "x86_64")]
macro_rules! jump {
    () => {
        core::arch::naked_asm!("lea rsi, [rip]", "jmp {f}", f = sym super::not_on_ethernet)
    };
}
#[cfg(target_arch = "aarch64")]
macro_rules! jump {
    () => {
        core::arch::naked_asm!("adr x1, .", "b {f}", f = sym super::not_on_ethernet)
    };
}

#[allow(unused_variables, clippy::too_many_arguments)]
mod rows {
    use super::*;
    include!(concat!(env!("OUT_DIR"), "/absent.rs"));
}
pub use rows::*;

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
