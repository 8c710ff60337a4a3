/*
 * fwlib32_ext.h: extensions of fwlib32-rs beyond FANUC's FOCAS2 interface.
 *
 * GENERATED FILE: do not edit. build.rs writes it with cbindgen from
 * src/ffi/ext.rs; refresh the committed copy with
 *     FWLIB32_UPDATE_HEADER=1 cargo build
 *
 * FANUC's functions are declared in fwlib32.h (included here) under FANUC's
 * names. Functions of our own, which FANUC's library does not have, are named
 * fwlib_* and are declared in this header only: a program that includes just
 * fwlib32.h stays buildable against FANUC's library, and one that uses an
 * extension says so by including fwlib32_ext.h.
 */

#ifndef _FWLIB32_EXT_H
#define _FWLIB32_EXT_H

#include "fwlib32.h"

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

/*
 From now on the read calls on `FlibHndl` are queued instead of sent:
 each checks its arguments at once (a local error is returned at once and
 the call is not queued) and returns EW_OK; the caller keeps its output
 buffers alive until fwlib_batch_end, which sends them all and fills
 them. Calls that cannot join a batch (writes, program transfers,
 anything on connection 1, reads that need an earlier answer to form
 their next request; the README lists the batchable ones) return
 EW_REJECT (13) without traffic meanwhile. A second fwlib_batch_begin is
 EW_BUSY (-1).
 */
short fwlib_batch_begin(unsigned short FlibHndl);

/*
 Sends the calls queued since fwlib_batch_begin in as few request frames
 as the limits allow, fills every caller's outputs as the calls made
 alone would, writes each call's own return code into `results` in
 queue order, and ends the batch. `count` must be at least the number of
 queued calls (else EW_LENGTH, nothing sent, the batch goes on); a
 connection that fails is every affected call's result, not this
 function's. Without a batch: EW_FUNC (1).

 # Safety
 `results` must point to `count` writable shorts (NULL with no call queued).
 */
short fwlib_batch_end(unsigned short FlibHndl, short *results, int count);

/*
 Sets the most one request frame of this handle's batches may carry:
 `max_subpackets` subpackets (1..=255) and a body of `max_body` bytes
 (30..=65525). The defaults are the most FANUC's library puts in one
 frame for the CNC's class. A call larger than the limits is sent alone.
 */
short fwlib_batch_limits(unsigned short FlibHndl, int max_subpackets, int max_body);

/*
 Turns reconnection on (`on` not 0) or off (0, the default, as FANUC's
 library behaves) for handle `FlibHndl`.

 When a CNC drops off the network, the calls of every handle to it fail
 with EW_SOCKET (-16), and by default keep failing until every such handle
 is freed and allocated again. With reconnection on, a call on this handle
 after such a failure first reopens the connections (the open and the
 start-up exchanges, as `cnc_allclibhndl3` makes them), within the call's
 timeout, then goes ahead; if the CNC is still away the call returns
 EW_SOCKET again, and the next call tries again. The other handles to the
 same CNC share the reopened connections. Nothing is ever sent twice: the
 call that failed returned its error, and only a new call from the
 program sends a write again.
 */
short fwlib_set_reconnect(unsigned short FlibHndl, int on);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* _FWLIB32_EXT_H */
