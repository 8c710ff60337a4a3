//! Our own extensions, beyond FANUC's API: named `fwlib_*` and declared in
//! `include/fwlib32_ext.h` only (build.rs generates it from this file and
//! keeps these functions out of `fwlib32.h`).

use super::{ffi_boundary, nonnull};
use crate::client::batch::{Batch, Limits, default_limits};
use crate::client::handles;
use crate::error::Error;
use crate::ew::{EW_BUSY, EW_LENGTH};
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

/// From now on the read calls on `FlibHndl` are queued instead of sent:
/// each checks its arguments at once (a local error is returned at once and
/// the call is not queued) and returns EW_OK; the caller keeps its output
/// buffers alive until fwlib_batch_end, which sends them all and fills
/// them. Calls that cannot join a batch (writes, program transfers,
/// anything on connection 1, reads that need an earlier answer to form
/// their next request; the README lists the batchable ones) return
/// EW_REJECT (13) without traffic meanwhile. A second fwlib_batch_begin is
/// EW_BUSY (-1).
#[unsafe(no_mangle)]
pub extern "C" fn fwlib_batch_begin(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("fwlib_batch_begin", {
        let h = handles::lookup(FlibHndl)?;
        let mut s = h.state.lock();
        if s.batch.is_some() {
            return Err(Error::local(EW_BUSY, "a batch is already begun"));
        }
        let limits = s
            .batch_limits
            .unwrap_or(default_limits(h.pair.info.open.class()));
        s.batch = Some(Box::new(Batch::new(limits)));
        h.set_batching(true);
        Ok(())
    })
}

/// Sends the calls queued since fwlib_batch_begin in as few request frames
/// as the limits allow, fills every caller's outputs as the calls made
/// alone would, writes each call's own return code into `results` in
/// queue order, and ends the batch. `count` must be at least the number of
/// queued calls (else EW_LENGTH, nothing sent, the batch goes on); a
/// connection that fails is every affected call's result, not this
/// function's. Without a batch: EW_FUNC (1).
///
/// # Safety
/// `results` must point to `count` writable shorts (NULL with no call queued).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fwlib_batch_end(
    FlibHndl: c_ushort,
    results: *mut c_short,
    count: c_int,
) -> c_short {
    ffi_boundary!("fwlib_batch_end", {
        let h = handles::lookup(FlibHndl)?;
        let queued = h.state.lock().batch.as_ref().map_or(0, |b| b.len());
        if (count.max(0) as usize) < queued {
            return Err(Error::local(
                EW_LENGTH,
                "results has room for fewer calls than are queued",
            ));
        }
        let out = if queued > 0 {
            Some(nonnull(results)?)
        } else {
            None
        };
        let codes = h.end_batch(super::finish);
        h.state.lock().batch = None;
        h.set_batching(false);
        let codes = codes?;
        if let Some(out) = out {
            // SAFETY: `count` (≥ the codes) shorts at `results`, the caller's contract.
            unsafe { std::slice::from_raw_parts_mut(out, codes.len()) }.copy_from_slice(&codes);
        }
        Ok(())
    })
}

/// Sets the most one request frame of this handle's batches may carry:
/// `max_subpackets` subpackets (1..=255) and a body of `max_body` bytes
/// (30..=65525). The defaults are the most FANUC's library puts in one
/// frame for the CNC's class. A call larger than the limits is sent alone.
#[unsafe(no_mangle)]
pub extern "C" fn fwlib_batch_limits(
    FlibHndl: c_ushort,
    max_subpackets: c_int,
    max_body: c_int,
) -> c_short {
    ffi_boundary!("fwlib_batch_limits", {
        let h = handles::lookup(FlibHndl)?;
        if !(1..=255).contains(&max_subpackets) || !(30..=65525).contains(&max_body) {
            return Err(Error::local(EW_LENGTH, "limits out of range"));
        }
        let limits = Limits {
            subpackets: max_subpackets as usize,
            body: max_body as usize,
        };
        let mut s = h.state.lock();
        match s.batch.as_mut() {
            Some(b) => b.limits = limits,
            None => s.batch_limits = Some(limits),
        }
        Ok(())
    })
}
