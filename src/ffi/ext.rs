//! Our own extensions, beyond FANUC's API: named `fwlib_*` and declared in
//! `include/fwlib32_ext.h` only (build.rs generates it from this file and
//! keeps these functions out of `fwlib32.h`).

use super::ffi_boundary;
use crate::client::handles;
use std::os::raw::{c_int, c_short, c_ushort};

/// Turns reconnection on (`on` not 0) or off (0, the default, as FANUC's
/// library behaves) for handle `FlibHndl`.
///
/// When a CNC drops off the network, the calls of every handle to it fail
/// with EW_SOCKET (-16), and by default keep failing until every such handle
/// is freed and allocated again. With reconnection on, a call on this handle
/// after such a failure first reopens the connections (the open and the
/// start-up exchanges, as `cnc_allclibhndl3` makes them), within the call's
/// timeout, then goes ahead; if the CNC is still away the call returns
/// EW_SOCKET again, and the next call tries again. The other handles to the
/// same CNC share the reopened connections. Nothing is ever sent twice: the
/// call that failed returned its error, and only a new call from the
/// program sends a write again.
#[unsafe(no_mangle)]
pub extern "C" fn fwlib_set_reconnect(FlibHndl: c_ushort, on: c_int) -> c_short {
    ffi_boundary!("fwlib_set_reconnect", {
        handles::get(FlibHndl)?.state.lock().reconnect = on != 0;
        Ok(())
    })
}
