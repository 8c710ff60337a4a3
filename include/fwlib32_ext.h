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
