/*
 * fwlib32_ext.h: extensions of fwlib32-rs beyond FANUC's FOCAS2 interface.
 *
 * FANUC's functions are declared in fwlib32.h (included here) under FANUC's
 * names. Functions of our own, which FANUC's library does not have, are named
 * fwlib_* and are declared in this header only: a program that includes just
 * fwlib32.h stays buildable against FANUC's library, and one that uses an
 * extension says so by including fwlib32_ext.h.
 *
 * There are no extensions yet, so this header declares nothing beyond
 * fwlib32.h. (When the first fwlib_* function is exported, build.rs is to
 * generate this header with cbindgen from src/, as it generates fwlib32.h.)
 */

#ifndef _FWLIB32_EXT_H
#define _FWLIB32_EXT_H

#include "fwlib32.h"

#ifdef __cplusplus
extern "C" {
#endif  /* __cplusplus */

/* fwlib_* declarations go here. */

#ifdef __cplusplus
}  /* extern "C" */
#endif  /* __cplusplus */

#endif  /* _FWLIB32_EXT_H */
