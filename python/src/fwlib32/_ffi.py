"""The bundled libfwlib32.so.1 through ctypes: structures and signatures.

The structures copy fwlib32-rs's include/fwlib32.h. FANUC's header spells
many fields `long`; FANUC's Linux library and ours read and write them as
32 bits, so they are c_int32 here, never c_long (8 bytes on 64-bit Linux).
A `long *` argument points at 4 bytes per element; a `long` passed by value
is c_long. Text fields are c_ubyte arrays (C char is unsigned on aarch64).

ctypes releases the GIL for the duration of every foreign call, so threads
polling different CNCs run their network exchanges in parallel.
"""

from __future__ import annotations

import ctypes
import os
from typing import TYPE_CHECKING, Any, Optional
from ctypes import POINTER, Structure, Union, sizeof
from ctypes import c_char_p, c_int, c_int16, c_int32, c_long, c_ubyte, c_uint16

MAX_AXIS = 32
ALL_AXES = -1


def library_path() -> str:
    """The path of the bundled libfwlib32.so.1 (the C library itself).

    A ctypes program written for FANUC's library loads ours by this path
    unchanged: ``ctypes.CDLL(fwlib32.library_path())``.
    """
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "libfwlib32.so.1")


class ODBSYS(Structure):
    """include/fwlib32.h's ODBSYS."""
    _fields_ = [("addinfo", c_int16), ("max_axis", c_int16),
                ("cnc_type", c_ubyte * 2), ("mt_type", c_ubyte * 2),
                ("series", c_ubyte * 4), ("version", c_ubyte * 4),
                ("axes", c_ubyte * 2)]


class ODBST(Structure):
    """include/fwlib32.h's ODBST."""
    _fields_ = [(n, c_int16) for n in ("hdck", "tmmode", "aut", "run", "motion",
                                        "mstb", "emergency", "alarm", "edit")]


class ODBERR(Structure):
    """include/fwlib32.h's ODBERR."""
    _fields_ = [("err_no", c_int16), ("err_dtno", c_int16)]


class POSELM(Structure):
    """include/fwlib32.h's POSELM."""
    _fields_ = [("data", c_int32), ("dec", c_int16), ("unit", c_int16),
                ("disp", c_int16), ("name", c_ubyte), ("suff", c_ubyte)]


class ODBPOS(Structure):
    """include/fwlib32.h's ODBPOS."""
    _fields_ = [("abs", POSELM), ("mach", POSELM), ("rel", POSELM), ("dist", POSELM)]


class ODBALMMSG2(Structure):
    """include/fwlib32.h's ODBALMMSG2."""
    _fields_ = [("alm_no", c_int32), ("type", c_int16), ("axis", c_int16),
                ("dummy", c_int16), ("msg_len", c_int16), ("alm_msg", c_ubyte * 64)]


class REALPRM(Structure):
    """include/fwlib32.h's REALPRM."""
    _fields_ = [("prm_val", c_int32), ("dec_val", c_int32)]


class IODBPSD_u(Union):
    """include/fwlib32.h's IODBPSD_u."""
    _fields_ = [("cdata", c_ubyte), ("idata", c_int16), ("ldata", c_int32),
                ("rdata", REALPRM), ("cdatas", c_ubyte * MAX_AXIS),
                ("idatas", c_int16 * MAX_AXIS), ("ldatas", c_int32 * MAX_AXIS),
                ("rdatas", REALPRM * MAX_AXIS)]


class IODBPSD(Structure):
    """cnc_rdparam's IODBPSD; cnc_diagnoss's ODBDGN has the same layout."""
    _fields_ = [("datano", c_int16), ("type", c_int16), ("u", IODBPSD_u)]


class IODBPRM_data(Structure):
    """include/fwlib32.h's IODBPRM_data."""
    _fields_ = [("prm_val", c_int32), ("dec_val", c_int32)]


class IODBPRM(Structure):
    """include/fwlib32.h's IODBPRM."""
    _fields_ = [("datano", c_int32), ("type", c_int16), ("axis", c_int16),
                ("info", c_int16), ("unit", c_int16), ("data", IODBPRM_data * MAX_AXIS)]


class ODBM(Structure):
    """include/fwlib32.h's ODBM."""
    _fields_ = [("datano", c_int16), ("dummy", c_int16), ("mcr_val", c_int32),
                ("dec_val", c_int16)]


class PRGDIR3_date(Structure):
    """include/fwlib32.h's PRGDIR3_date."""
    _fields_ = [(n, c_int16) for n in ("year", "month", "day", "hour", "minute", "dummy")]


class PRGDIR3(Structure):
    """include/fwlib32.h's PRGDIR3."""
    _fields_ = [("number", c_int32), ("length", c_int32), ("page", c_int32),
                ("comment", c_ubyte * 52), ("mdate", PRGDIR3_date), ("cdate", PRGDIR3_date)]


# The sizes C gives them: a layout mistake stops the import, not a call.
for _s, _n in ((ODBSYS, 18), (ODBST, 18), (ODBERR, 4), (ODBPOS, 48), (ODBALMMSG2, 76),
               (IODBPSD, 260), (IODBPRM, 268), (ODBM, 12), (PRGDIR3, 88)):
    if sizeof(_s) != _n:
        raise ImportError(f"fwlib32: {_s.__name__} is {sizeof(_s)} bytes, not {_n}")

_u16p = POINTER(c_uint16)
_i16p = POINTER(c_int16)
_i32p = POINTER(c_int32)
_vp = ctypes.c_void_p

# name: argument types; every function returns a short (an EW_* code).
SIGNATURES = {
    "cnc_allclibhndl3": [c_char_p, c_uint16, c_long, _u16p],
    "cnc_freelibhndl": [c_uint16],
    "cnc_setpath": [c_uint16, c_int16],
    "cnc_getdtailerr": [c_uint16, POINTER(ODBERR)],
    "pmc_getdtailerr": [c_uint16, POINTER(ODBERR)],
    "cnc_sysinfo": [c_uint16, POINTER(ODBSYS)],
    "cnc_statinfo": [c_uint16, POINTER(ODBST)],
    "cnc_rdposition": [c_uint16, c_int16, _i16p, POINTER(ODBPOS)],
    "cnc_rdalmmsg2": [c_uint16, c_int16, _i16p, POINTER(ODBALMMSG2)],
    "cnc_rdparam": [c_uint16, c_int16, c_int16, c_int16, POINTER(IODBPSD)],
    "cnc_diagnoss": [c_uint16, c_int16, c_int16, c_int16, POINTER(IODBPSD)],
    "cnc_rdparam_ext": [c_uint16, _i32p, c_int16, POINTER(IODBPRM)],
    "cnc_rddiag_ext": [c_uint16, _i32p, c_int16, POINTER(IODBPRM)],
    "cnc_wrparam": [c_uint16, c_int16, POINTER(IODBPSD)],
    "cnc_rdmacro": [c_uint16, c_int16, c_int16, POINTER(ODBM)],
    "cnc_wrmacro": [c_uint16, c_int16, c_int16, c_long, c_int16],
    "pmc_rdpmcrng": [c_uint16, c_int16, c_int16, c_uint16, c_uint16, c_uint16, _vp],
    "pmc_wrpmcrng": [c_uint16, c_uint16, _vp],
    "cnc_rdprogdir3": [c_uint16, c_int16, _i32p, _i16p, POINTER(PRGDIR3)],
    "cnc_upstart3": [c_uint16, c_int16, c_long, c_long],
    "cnc_upload3": [c_uint16, _i32p, _vp],
    "cnc_upend3": [c_uint16],
    "cnc_dwnstart3": [c_uint16, c_int16],
    "cnc_download3": [c_uint16, _i32p, c_char_p],
    "cnc_dwnend3": [c_uint16],
    "cnc_delete": [c_uint16, c_int16],
    "cnc_rdalmhisno": [c_uint16, _u16p],
    "cnc_rdalmhistry": [c_uint16, c_uint16, c_uint16, c_uint16, _vp],
    "cnc_rdophisno": [c_uint16, _u16p],
    "cnc_rdophistry": [c_uint16, c_uint16, c_uint16, c_uint16, _vp],
    "fwlib_batch_begin": [c_uint16],
    "fwlib_batch_end": [c_uint16, _i16p, c_int],
    "fwlib_set_reconnect": [c_uint16, c_int],
}


class _Lib:
    """The loaded library, its functions declared (attributes by name)."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.dll = ctypes.CDLL(path)
        for name, argtypes in SIGNATURES.items():
            fn = getattr(self.dll, name)
            fn.argtypes, fn.restype = argtypes, c_int16
            setattr(self, name, fn)

    if TYPE_CHECKING:
        def __getattr__(self, name: str) -> Any: ...


_lib: Optional[_Lib] = None


def lib() -> _Lib:
    """The bundled library, loaded at the first use."""
    global _lib
    if _lib is None:
        _lib = _Lib(library_path())
    return _lib
