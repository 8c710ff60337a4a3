"""FOCAS2 for Python, without FANUC's library.

The package carries fwlib32-rs's libfwlib32.so.1 (the C ABI of FANUC's
fwlib32.h over its own FOCAS2 protocol), a typed API over it, the focas-sim
CNC simulator and the focas command-line client:

    from fwlib32 import Cnc

    with Cnc("10.0.0.5", timeout=5) as cnc:
        print(cnc.status().mode)                  # Mode.MEM
        for axis in cnc.positions():
            print(axis.name, axis.absolute)       # X 125.000

Every failure raises FocasError (code, name, detail). library_path() is the
bundled library for ctypes code written for FANUC's; fwlib32.testing starts
the simulator for tests.
"""

from ._api import (DEFAULT_PORT, Alarm, AlarmHistoryEntry, AlarmState, AxisPosition, Batch,
                   Cnc, Emergency, Mode, Motion, OperationRecord, Param, Pending,
                   ProgramEntry, Run, Status, SysInfo, Unit)
from ._errors import EW, FocasError, ew_name
from ._ffi import library_path

__version__ = "1.0.0"

__all__ = [
    "Cnc", "Batch", "Pending", "FocasError", "library_path", "ew_name", "EW", "DEFAULT_PORT",
    "Status", "SysInfo", "AxisPosition", "Alarm", "Param", "ProgramEntry",
    "AlarmHistoryEntry", "OperationRecord", "Mode", "Run", "Motion", "Emergency",
    "AlarmState", "Unit", "bin_path",
]


def bin_path(name: str) -> str:
    """The path of a bundled program: "focas-sim" or "focas"."""
    from ._bin import path
    return path(name)
