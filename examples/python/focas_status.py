#!/usr/bin/env python3
"""Read a CNC's status, positions, alarms and parameters through libfwlib32.

Uses only the standard library (ctypes) on the installed FOCAS2 library:

    python3 focas_status.py HOST [PORT] [--lib PATH]

The library is PATH, else $FWLIB32, else what ctypes.util.find_library
finds for "fwlib32" (libfwlib32.so.1 from `make install`). Output is one
`key=value` per line. Exit status 0 on success, 1 when a call fails (the
failing function and its EW_* code are printed on stderr), 2 on bad usage.

The structures are those of fwlib32-rs's include/fwlib32.h: FANUC's `long`
fields are 32-bit (LONG = int32_t) on every platform, so they are c_int32
here, never c_long.
"""

import argparse
import ctypes
import ctypes.util
import os
import sys
from ctypes import POINTER, Structure, Union, byref, sizeof
from ctypes import c_char_p, c_int16, c_int32, c_long, c_ubyte, c_uint16

MAX_AXIS = 32
ALL_AXES = -1

EW_NAMES = {
    -17: "EW_PROTOCOL", -16: "EW_SOCKET", -15: "EW_NODLL", -8: "EW_HANDLE",
    -7: "EW_VERSION", -6: "EW_UNEXP", -2: "EW_RESET", -1: "EW_BUSY", 0: "EW_OK",
    1: "EW_FUNC", 2: "EW_LENGTH", 3: "EW_NUMBER", 4: "EW_ATTRIB", 5: "EW_DATA",
    6: "EW_NOOPT", 7: "EW_PROT", 9: "EW_PARAM", 10: "EW_BUFFER", 11: "EW_PATH",
    12: "EW_MODE", 13: "EW_REJECT", 15: "EW_ALARM", 16: "EW_STOP",
    17: "EW_PASSWD",
}

MODES = ["MDI", "MEM", "****", "EDIT", "HND", "JOG", "TJOG", "THND", "INC",
         "REF", "RMT"]
RUN_STATES = ["RESET", "STOP", "HOLD", "START", "MSTR"]


# --- Structures (include/fwlib32.h) ------------------------------------------

class ODBSYS(Structure):
    _fields_ = [("addinfo", c_int16), ("max_axis", c_int16),
                ("cnc_type", c_ubyte * 2), ("mt_type", c_ubyte * 2),
                ("series", c_ubyte * 4), ("version", c_ubyte * 4),
                ("axes", c_ubyte * 2)]


class ODBST(Structure):
    _fields_ = [(name, c_int16) for name in
                ("hdck", "tmmode", "aut", "run", "motion", "mstb",
                 "emergency", "alarm", "edit")]


class ODBAXISNAME(Structure):
    _fields_ = [("name", c_ubyte), ("suff", c_ubyte)]


class ODBDY_FAXIS(Structure):
    _fields_ = [("absolute", c_int32 * MAX_AXIS),
                ("machine", c_int32 * MAX_AXIS),
                ("relative", c_int32 * MAX_AXIS),
                ("distance", c_int32 * MAX_AXIS)]


class ODBDY_OAXIS(Structure):
    _fields_ = [("absolute", c_int32), ("machine", c_int32),
                ("relative", c_int32), ("distance", c_int32)]


class ODBDY_POS(Union):
    _fields_ = [("faxis", ODBDY_FAXIS), ("oaxis", ODBDY_OAXIS)]


class ODBDY2(Structure):
    _fields_ = [("dummy", c_int16), ("axis", c_int16),
                ("alarm", c_int32), ("prgnum", c_int32), ("prgmnum", c_int32),
                ("seqnum", c_int32), ("actf", c_int32), ("acts", c_int32),
                ("pos", ODBDY_POS)]


class ODBALMMSG2(Structure):
    _fields_ = [("alm_no", c_int32), ("type", c_int16), ("axis", c_int16),
                ("dummy", c_int16), ("msg_len", c_int16),
                ("alm_msg", c_ubyte * 64)]


class REALPRM(Structure):
    _fields_ = [("prm_val", c_int32), ("dec_val", c_int32)]


class IODBPSD_u(Union):
    _fields_ = [("cdata", c_ubyte), ("idata", c_int16), ("ldata", c_int32),
                ("rdata", REALPRM),
                ("cdatas", c_ubyte * MAX_AXIS), ("idatas", c_int16 * MAX_AXIS),
                ("ldatas", c_int32 * MAX_AXIS), ("rdatas", REALPRM * MAX_AXIS)]


class IODBPSD(Structure):
    _fields_ = [("datano", c_int16), ("type", c_int16), ("u", IODBPSD_u)]


# The sizes C gives them: a layout mistake stops here, not in the CNC call.
for struct, size in ((ODBDY2, 540), (IODBPSD, 260), (ODBALMMSG2, 76), (ODBST, 18)):
    if sizeof(struct) != size:
        raise SystemExit(f"{struct.__name__} is {sizeof(struct)} bytes, not {size}")


# --- The library ---------------------------------------------------------------

class FocasError(Exception):
    def __init__(self, function, code):
        self.function, self.code = function, code
        name = EW_NAMES.get(code, "EW_?")
        super().__init__(f"{function} failed: {name} ({code})")


# name: argument types; every function returns a short (an EW_* code).
SIGNATURES = {
    "cnc_startupprocess": [c_long, c_char_p],
    "cnc_exitprocess": [],
    "cnc_allclibhndl3": [c_char_p, c_uint16, c_long, POINTER(c_uint16)],
    "cnc_freelibhndl": [c_uint16],
    "cnc_sysinfo": [c_uint16, POINTER(ODBSYS)],
    "cnc_statinfo": [c_uint16, POINTER(ODBST)],
    "cnc_rdaxisname": [c_uint16, POINTER(c_int16), POINTER(ODBAXISNAME)],
    "cnc_getfigure": [c_uint16, c_int16, POINTER(c_int16), POINTER(c_int16),
                      POINTER(c_int16)],
    "cnc_rddynamic2": [c_uint16, c_int16, c_int16, POINTER(ODBDY2)],
    "cnc_rdalmmsg2": [c_uint16, c_int16, POINTER(c_int16), POINTER(ODBALMMSG2)],
    "cnc_rdparam": [c_uint16, c_int16, c_int16, c_int16, POINTER(IODBPSD)],
}


def load_library(path=None):
    """Loads libfwlib32 and declares the functions this program calls."""
    path = path or os.environ.get("FWLIB32") or ctypes.util.find_library("fwlib32")
    if not path:
        raise OSError("not found: install it (make install), "
                      "or give its path with --lib or $FWLIB32")
    lib = ctypes.CDLL(path)
    for name, argtypes in SIGNATURES.items():
        fn = getattr(lib, name)
        fn.argtypes, fn.restype = argtypes, c_int16
    return lib, path


def call(lib, name, *args):
    """Calls a FOCAS function; raises FocasError unless it returns EW_OK."""
    ret = getattr(lib, name)(*args)
    if ret != 0:
        raise FocasError(name, ret)


def text(chars, length=None):
    """A fixed-size char field (not NUL-terminated) as a str."""
    return bytes(chars[:length] if length is not None else chars).decode("latin-1")


def fixed(value, decimals):
    """value * 10^-decimals with `decimals` places, exactly (no float)."""
    if decimals <= 0:
        return str(value * 10 ** -decimals)
    sign = "-" if value < 0 else ""
    whole, frac = divmod(abs(value), 10 ** decimals)
    return f"{sign}{whole}.{frac:0{decimals}d}"


# --- The program ---------------------------------------------------------------

def report(lib, h):
    sysinfo = ODBSYS()
    call(lib, "cnc_sysinfo", h, byref(sysinfo))
    print(f"cnc_type={text(sysinfo.cnc_type)}")
    print(f"mt_type={text(sysinfo.mt_type)}")
    print(f"series={text(sysinfo.series)}")
    print(f"version={text(sysinfo.version)}")

    st = ODBST()
    call(lib, "cnc_statinfo", h, byref(st))
    mode = MODES[st.aut] if 0 <= st.aut < len(MODES) else "?"
    run = RUN_STATES[st.run] if 0 <= st.run < len(RUN_STATES) else "?"
    print(f"aut={st.aut} ({mode})")
    print(f"run={st.run} ({run})")
    for field in ("motion", "mstb", "emergency", "alarm", "edit"):
        print(f"{field}={getattr(st, field)}")

    # Axis names and decimal places, then every axis's positions in one call.
    names = (ODBAXISNAME * MAX_AXIS)()
    count = c_int16(MAX_AXIS)  # in: room, out: axes named
    call(lib, "cnc_rdaxisname", h, byref(count), names)
    naxes = count.value
    figures = c_int16(0)
    dec_in, dec_out = (c_int16 * MAX_AXIS)(), (c_int16 * MAX_AXIS)()
    call(lib, "cnc_getfigure", h, 0, byref(figures), dec_in, dec_out)
    dyn = ODBDY2()
    call(lib, "cnc_rddynamic2", h, ALL_AXES, sizeof(dyn), byref(dyn))
    print(f"program=O{dyn.prgnum}")
    print(f"sequence=N{dyn.seqnum}")
    print(f"feed={dyn.actf}")
    print(f"spindle_speed={dyn.acts}")
    print(f"axes={naxes}")
    pos = dyn.pos.faxis
    for i in range(naxes):
        name = chr(names[i].name) + (chr(names[i].suff) if names[i].suff else "")
        dec = dec_in[i] if i < figures.value else 0
        for kind in ("absolute", "machine", "relative", "distance"):
            print(f"{name}.{kind}={fixed(getattr(pos, kind)[i], dec)}")

    # Active alarms (type -1: all), up to 10.
    alarms = (ODBALMMSG2 * 10)()
    count = c_int16(len(alarms))  # in: room, out: alarms read
    call(lib, "cnc_rdalmmsg2", h, -1, byref(count), alarms)
    print(f"alarms={count.value}")
    for i, a in enumerate(alarms[:count.value], 1):
        message = text(a.alm_msg, a.msg_len)
        print(f"alarm{i}={a.alm_no} (type {a.type}, axis {a.axis}) {message}")

    # Parameter 6711, the part counter: one 2-word value (4 + 4 bytes).
    prm = IODBPSD()
    call(lib, "cnc_rdparam", h, 6711, 0, 4 + 4, byref(prm))
    print(f"param6711={prm.u.ldata}")

    # Parameter 1320, stored stroke limit +: one real value per axis.
    prm = IODBPSD()
    call(lib, "cnc_rdparam", h, 1320, ALL_AXES, 4 + sizeof(REALPRM) * MAX_AXIS,
         byref(prm))
    for i in range(naxes):
        r = prm.u.rdatas[i]
        print(f"param1320.{chr(names[i].name)}={fixed(r.prm_val, r.dec_val)}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("host", help="the CNC's address")
    parser.add_argument("port", nargs="?", type=int, default=8193,
                        help="its FOCAS port (8193)")
    parser.add_argument("--timeout", type=int, default=10, help="seconds")
    parser.add_argument("--lib", help="path of libfwlib32.so (else $FWLIB32, "
                        "else the installed one)")
    args = parser.parse_args()
    if not 0 < args.port < 65536:
        parser.error(f"port {args.port} out of range")

    try:
        lib, path = load_library(args.lib)
    except OSError as e:
        print(f"cannot load libfwlib32: {e}", file=sys.stderr)
        return 1
    print(f"library={path}")

    # FANUC's Linux library needs this call before any other; ours does not.
    lib.cnc_startupprocess(0, b"focas.log")
    handle = c_uint16(0)
    try:
        call(lib, "cnc_allclibhndl3", args.host.encode(), args.port,
             args.timeout, byref(handle))
    except FocasError as e:
        print(f"cannot connect to {args.host}:{args.port}: {e}", file=sys.stderr)
        lib.cnc_exitprocess()
        return 1
    print(f"connected={args.host}:{args.port}")

    status = 0
    try:
        report(lib, handle)
    except FocasError as e:
        print(e, file=sys.stderr)
        status = 1
    finally:
        ret = lib.cnc_freelibhndl(handle)
        if ret != 0:
            print(FocasError("cnc_freelibhndl", ret), file=sys.stderr)
            status = 1
        lib.cnc_exitprocess()
    return status


if __name__ == "__main__":
    sys.exit(main())
