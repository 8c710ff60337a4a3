"""Legacy ctypes code: a program written for FANUC's library loads ours by
fwlib32.library_path() and calls it unchanged."""

import json
import subprocess
import sys

import fwlib32

PROGRAM = r'''
import ctypes, json, sys
from ctypes import Structure, byref, c_char_p, c_int16, c_long, c_uint16, POINTER

class ODBST(Structure):
    _fields_ = [(n, c_int16) for n in ("hdck", "tmmode", "aut", "run", "motion",
                                        "mstb", "emergency", "alarm", "edit")]

lib = ctypes.CDLL(sys.argv[1])
lib.cnc_allclibhndl3.argtypes = [c_char_p, c_uint16, c_long, POINTER(c_uint16)]
lib.cnc_statinfo.argtypes = [c_uint16, POINTER(ODBST)]
lib.cnc_freelibhndl.argtypes = [c_uint16]
for f in (lib.cnc_allclibhndl3, lib.cnc_statinfo, lib.cnc_freelibhndl):
    f.restype = c_int16
h = c_uint16(0)
rc = lib.cnc_allclibhndl3(sys.argv[2].encode(), int(sys.argv[3]), 10, byref(h))
st = ODBST()
rc2 = lib.cnc_statinfo(h, byref(st)) if rc == 0 else None
lib.cnc_freelibhndl(h)
print(json.dumps({"connect": rc, "statinfo": rc2,
                  "words": [getattr(st, n) for n, _ in ODBST._fields_]}))
'''


def test_a_ctypes_program_loads_library_path(machine):
    out = subprocess.run([sys.executable, "-c", PROGRAM, fwlib32.library_path(),
                          machine.host, str(machine.port)],
                         check=True, capture_output=True, text=True).stdout
    r = json.loads(out)
    assert (r["connect"], r["statinfo"]) == (0, 0)
    # hdck tmmode aut run motion mstb emergency alarm edit: machine.toml's.
    assert r["words"][2:] == [3, 1, 0, 0, 1, 1, 0]


def test_the_same_library_in_process(machine):
    import ctypes
    lib = ctypes.CDLL(fwlib32.library_path())
    h = ctypes.c_uint16(0)
    lib.cnc_allclibhndl3.argtypes = [ctypes.c_char_p, ctypes.c_uint16, ctypes.c_long,
                                     ctypes.POINTER(ctypes.c_uint16)]
    assert lib.cnc_allclibhndl3(machine.host.encode(), machine.port, 10, ctypes.byref(h)) == 0
    try:
        # Its handle works with the typed API's library too: one library.
        sysinfo = (ctypes.c_ubyte * 18)()
        assert lib.cnc_sysinfo(h, sysinfo) == 0
        assert bytes(sysinfo[8:12]) == b"G4T1"
    finally:
        lib.cnc_freelibhndl(h)
