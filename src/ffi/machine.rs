//! Machine data (issue 11): the spindle control signals.

use super::{ffi_read, nonnull, put};
use crate::client::handles;
use crate::proto::machine::CtrlSignals;
use crate::types::{ODBSPDI, ODBSPDO};
use std::os::raw::{c_short, c_ushort};

/// The first signal word of the answer into the caller's 4 bytes (FANUC's
/// library writes one word per two bytes of the answer, up to the CNC's
/// maximum spindles, past the 4-byte struct; ours writes the struct only).
fn signals(FlibHndl: c_ushort, out: *mut u8, output: bool) -> crate::error::Result<()> {
    let h = handles::get(FlibHndl)?;
    let words = h.call(&CtrlSignals { output })?;
    if let Some(w) = words.first() {
        // SAFETY: `out` points to the caller's 4-byte struct.
        unsafe { put(out.cast::<i32>(), *w) };
    }
    Ok(())
}

/// Reads the spindle control input signals (four bytes, `sgnl1` the low
/// byte of the CNC's first signal word).
///
/// # Safety
/// `spdi` must point to a writable ODBSPDI.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdctrldi(FlibHndl: c_ushort, spdi: *mut ODBSPDI) -> c_short {
    ffi_read!("cnc_rdctrldi", {
        let out = nonnull(spdi)?.cast::<u8>();
        signals(FlibHndl, out, false)
    })
}

/// Reads the spindle control output signals (four bytes, as cnc_rdctrldi).
///
/// # Safety
/// `spdo` must point to a writable ODBSPDO.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdctrldo(FlibHndl: c_ushort, spdo: *mut ODBSPDO) -> c_short {
    ffi_read!("cnc_rdctrldo", {
        let out = nonnull(spdo)?.cast::<u8>();
        signals(FlibHndl, out, true)
    })
}
