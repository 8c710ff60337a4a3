"""The typed API: Cnc, its results as dataclasses, and Batch."""

from __future__ import annotations

import ctypes
import datetime
import enum
import math
import struct
import time
from ctypes import byref, c_int16, c_int32, c_uint16, sizeof
from dataclasses import dataclass, field
from decimal import Decimal
from typing import Any, Callable, Dict, Generic, List, Optional, Tuple, TypeVar, Union

from . import _ffi
from ._errors import FocasError
from ._ffi import (ALL_AXES, IODBPRM, IODBPSD, MAX_AXIS, ODBALMMSG2, ODBERR, ODBM, ODBPOS,
                   ODBST, ODBSYS, PRGDIR3)

__all__ = [
    "DEFAULT_PORT", "Mode", "Run", "Motion", "Emergency", "AlarmState", "Unit",
    "Status", "SysInfo", "AxisPosition", "Alarm", "Param", "ProgramEntry",
    "AlarmHistoryEntry", "OperationRecord", "Cnc", "Batch", "Pending",
]

DEFAULT_PORT = 8193
"""FOCAS2's TCP port."""

EW_OK, EW_BUFFER, EW_RESET, EW_SOCKET = 0, 10, -2, -16
EW_LENGTH, EW_NUMBER, EW_ATTRIB, EW_DATA = 2, 3, 4, 5

T = TypeVar("T")
Value = Union[int, Decimal]
"""One parameter or diagnosis value: an int (bit, byte, word, 2-word) or a Decimal (real)."""


class Mode(enum.IntEnum):
    """The CNC's mode (ODBST.aut)."""
    MDI = 0
    MEM = 1
    NO_SELECTION = 2
    EDIT = 3
    HANDLE = 4
    JOG = 5
    TEACH_JOG = 6
    TEACH_HANDLE = 7
    INCREMENTAL = 8
    REFERENCE = 9
    REMOTE = 10


class Run(enum.IntEnum):
    """Automatic operation state (ODBST.run)."""
    RESET = 0
    STOP = 1
    HOLD = 2
    START = 3
    MSTR = 4


class Motion(enum.IntEnum):
    """Axis motion (ODBST.motion)."""
    IDLE = 0
    MOVING = 1
    DWELL = 2


class Emergency(enum.IntEnum):
    """Emergency stop state (ODBST.emergency)."""
    CLEAR = 0
    EMERGENCY = 1
    RESET = 2


class AlarmState(enum.IntEnum):
    """Alarm state (ODBST.alarm)."""
    CLEAR = 0
    ALARM = 1
    BATTERY_LOW = 2


class Unit(enum.IntEnum):
    """The unit of an axis's positions (POSELM.unit)."""
    MM = 0
    INCH = 1
    DEGREE = 2


def _table(e: Any) -> Dict[int, Any]:
    return {m.value: m for m in e}


_MODE, _RUN, _MOTION = _table(Mode), _table(Run), _table(Motion)
_EMG, _ALM, _UNIT = _table(Emergency), _table(AlarmState), _table(Unit)


@dataclass
class Status:
    """The CNC's status words (cnc_statinfo). A code without an enum member
    stays a plain int."""
    mode: Union[Mode, int]
    run: Union[Run, int]
    motion: Union[Motion, int]
    mstb: int
    emergency: Union[Emergency, int]
    alarm: Union[AlarmState, int]
    edit: int
    tmmode: int


@dataclass
class SysInfo:
    """System information (cnc_sysinfo): "31", " M", "G421", "08.0", 3 axes ..."""
    cnc_type: str
    mt_type: str
    series: str
    version: str
    axes: int
    max_axes: int
    addinfo: int


@dataclass
class AxisPosition:
    """The positions of one axis (cnc_rdposition), exact, in its unit."""
    name: str
    absolute: Decimal
    machine: Decimal
    relative: Decimal
    distance: Decimal
    unit: Union[Unit, int]


_PREFIXES = ["SW", "PW", "IO", "PS", "OT", "OH", "SV", "SR", "MC", "SP", "DS", "IE", "BG",
             "SN", "", "EX"]


def _shown(kind: int, number: int) -> str:
    p = "PC" if kind == 19 else (_PREFIXES[kind] if 0 <= kind < len(_PREFIXES) else "")
    return f"{p}{number:04d}" if p else f"{number} (type {kind})"


@dataclass
class Alarm:
    """An active alarm (cnc_rdalmmsg2)."""
    number: int
    type: int
    """The alarm type (group): 4 OT, 6 SV, 19 PC ..."""
    axis: int
    """The axis it concerns (1..), 0 for none."""
    message: str

    @property
    def code(self) -> str:
        """The number as the CNC shows it: "OT0500" (or "500 (type 21)")."""
        return _shown(self.type, self.number)


@dataclass
class Param:
    """A parameter or diagnosis item with its kind."""
    number: int
    kind: str
    """"bit", "byte", "word", "2word" or "real"."""
    per_axis: bool
    values: List[Value] = field(default_factory=list)
    """One value, or one per axis (axis 1 first) of a per-axis item read
    whole. Bits as an int 0..255 (bit n is 1 << n), reals as Decimal."""


@dataclass
class ProgramEntry:
    """A program in the CNC's memory (cnc_rdprogdir3)."""
    number: int
    length: int
    comment: str
    modified: Optional[datetime.datetime]


@dataclass
class AlarmHistoryEntry:
    """An entry of the alarm history (cnc_rdalmhistry), newest first."""
    number: int
    type: int
    axis: int
    time: datetime.datetime
    """By the CNC's clock (the library gives the year modulo 100; 20yy here)."""
    message: str

    @property
    def code(self) -> str:
        """The number as the CNC shows it: "OT0500"."""
        return _shown(self.type, self.number)


@dataclass
class OperationRecord:
    """An operation history record (cnc_rdophistry), newest first.

    `kind` says which fields are set: "mdi" (key), "signal" (signal_area,
    signal_number, old, new), "alarm" (alarm_type, alarm_number, axis),
    "date" (date, power_on), "time" (time, power_on), "other" (rec_type only).
    """
    kind: str
    rec_type: int
    key: Optional[int] = None
    signal_area: Optional[int] = None
    """The PMC address type of a signal: 0 G, 1 F, 2 Y, 3 X ..."""
    signal_number: Optional[int] = None
    old: Optional[int] = None
    new: Optional[int] = None
    alarm_type: Optional[int] = None
    alarm_number: Optional[int] = None
    axis: Optional[int] = None
    date: Optional[datetime.date] = None
    time: Optional[datetime.time] = None
    power_on: Optional[bool] = None


# Parameter kinds by the answer's type word (low byte); diagnosis data
# numbers its types differently.
_PARAM_KINDS = {0: "bit", 1: "byte", 2: "word", 3: "2word", 4: "real"}
_DIAG_KINDS = {0: "byte", 1: "word", 2: "2word", 3: "bit", 4: "bit", 5: "real"}
_SIZES = {"bit": 1, "byte": 1, "word": 2, "2word": 4, "real": 8}

_PMC_AREAS = {a: i for i, a in enumerate("GFYXARTKCDMNEZ")}
# type: (data_type code, size, struct format)
_PMC_TYPES = {"byte": (0, 1, "b"), "word": (1, 2, "h"), "long": (2, 4, "i"),
              "float": (4, 4, "f"), "double": (5, 8, "d")}
PMC_CHUNK = 1400
"""The most PMC bytes one pmc_rdpmcrng exchange carries here (a longer read is split)."""


def _text(chars: Any, length: Optional[int] = None) -> str:
    b = bytes(chars if length is None else chars[:max(0, length)])
    return b.split(b"\0", 1)[0].decode("latin-1").strip()


def _dec(value: int, decimals: int) -> Decimal:
    return Decimal(value).scaleb(-decimals) if decimals > 0 else Decimal(value)


def _sbyte(v: int) -> int:
    return v - 256 if v > 127 else v


def _values(kind: str, u: Any, count: int) -> List[Value]:
    if kind == "bit":
        return [u.cdatas[i] for i in range(count)]
    if kind == "byte":
        return [_sbyte(u.cdatas[i]) for i in range(count)]
    if kind == "word":
        return [u.idatas[i] for i in range(count)]
    if kind == "2word":
        return [u.ldatas[i] for i in range(count)]
    return [_dec(u.rdatas[i].prm_val, u.rdatas[i].dec_val) for i in range(count)]


def _check_axis(call: str, axis: Optional[int]) -> None:
    if axis is not None and not 1 <= axis <= MAX_AXIS:
        raise FocasError(call, EW_ATTRIB, message=f"axes are numbered 1..{MAX_AXIS}")


def _pmc_spec(area: Union[str, int], start: int, end: Optional[int],
              type: str) -> Tuple[int, int, int, str, int]:
    """(area code, data type, size, format, count), or FocasError."""
    call = "pmc_rdpmcrng"
    if isinstance(area, str):
        if area.upper() not in _PMC_AREAS:
            raise FocasError(call, EW_ATTRIB, message=f"no PMC area {area!r} (G F Y X A R T K C D M N E Z)")
        code = _PMC_AREAS[area.upper()]
    else:
        code = int(area)
    if type not in _PMC_TYPES:
        raise FocasError(call, EW_ATTRIB, message=f"type {type!r}: byte, word, long, float or double")
    dtype, size, fmt = _PMC_TYPES[type]
    end = start if end is None else end
    if not 0 <= start <= end <= 65535:
        raise FocasError(call, EW_NUMBER, message=f"addresses {start}..{end}: not a range")
    return code, dtype, size, fmt, (end - start) // size + 1


class Pending(Generic[T]):
    """The result of one read in a Batch: `value` after the batch was sent."""

    __slots__ = ("call", "_value", "_error", "_done")

    def __init__(self, call: str) -> None:
        self.call = call
        self._value: Any = None
        self._error: Optional[FocasError] = None
        self._done = False

    @property
    def value(self) -> T:
        """The value read; raises this read's FocasError if it failed (or
        EW_FUNC if the batch was not sent)."""
        if not self._done:
            raise FocasError(self.call, 1, message="the batch has not been sent")
        if self._error is not None:
            raise self._error
        value: T = self._value
        return value

    @property
    def error(self) -> Optional[FocasError]:
        """This read's error, None if it succeeded."""
        return self._error

    def _set(self, value: Any = None, error: Optional[FocasError] = None) -> None:
        self._value, self._error, self._done = value, error, True


class Cnc:
    """A connection to one CNC (a FOCAS library handle), as a context manager.

        with Cnc("10.0.0.5", timeout=5) as cnc:
            print(cnc.status().mode, cnc.positions()[0].absolute)

    `timeout` is in seconds (whole seconds on the wire, rounded up; 0 waits
    for ever); every call returns or raises within it. Every failure raises
    FocasError. Calls release the GIL while they wait on the network: one
    Cnc per thread polls several CNCs in parallel. A Cnc is one handle:
    share it between threads only under a lock of your own.
    """

    def __init__(self, host: str, port: int = DEFAULT_PORT, timeout: float = 10.0) -> None:
        lib = _ffi.lib()
        self._lib = lib
        self.host = host
        self.port = port
        self.timeout = timeout
        self._kinds: Dict[Tuple[str, int], str] = {}
        self._axes: Optional[int] = None
        self._h: Optional[int] = None
        secs = 0 if timeout <= 0 else max(1, math.ceil(timeout))
        h = c_uint16(0)
        rc = lib.cnc_allclibhndl3(host.encode(), port, secs, byref(h))
        if rc != EW_OK:
            raise FocasError("cnc_allclibhndl3", rc, message=f"{host}:{port}")
        self._h = h.value

    # --- life ---------------------------------------------------------------

    @property
    def handle(self) -> int:
        """The library handle (for calls of your own through ctypes on
        library_path()); FocasError EW_HANDLE once closed."""
        if self._h is None:
            raise FocasError("cnc_freelibhndl", -8, message="the Cnc is closed")
        return self._h

    def close(self) -> None:
        """Frees the handle (cnc_freelibhndl); the connection closes with the
        last handle to the CNC. Closing twice does nothing."""
        h, self._h = self._h, None
        if h is not None:
            self._lib.cnc_freelibhndl(h)

    def __enter__(self) -> "Cnc":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:
            pass

    def __repr__(self) -> str:
        state = "closed" if self._h is None else f"handle {self._h}"
        return f"Cnc({self.host!r}, {self.port}, {state})"

    def _fail(self, call: str, rc: int, message: str = "") -> FocasError:
        """The FocasError of `call`'s `rc`, with the handle's detail words."""
        err = ODBERR()
        detail: Optional[Tuple[int, int]] = None
        if self._h is not None:
            get = self._lib.pmc_getdtailerr if call.startswith("pmc_") else self._lib.cnc_getdtailerr
            if get(self._h, byref(err)) == EW_OK:
                detail = (err.err_no, err.err_dtno)
        return FocasError(call, rc, detail, message)

    def set_path(self, path: int) -> None:
        """Selects the path (1..) later calls on this Cnc address (cnc_setpath)."""
        rc = self._lib.cnc_setpath(self.handle, path)
        if rc:
            raise self._fail("cnc_setpath", rc)
        self._axes = None

    def set_reconnect(self, on: bool = True) -> None:
        """With reconnection on, a call after the CNC dropped off the network
        first connects again (fwlib_set_reconnect) instead of failing with
        EW_SOCKET until the Cnc is closed. Nothing is ever sent twice."""
        rc = self._lib.fwlib_set_reconnect(self.handle, 1 if on else 0)
        if rc:
            raise self._fail("fwlib_set_reconnect", rc)

    # --- status ------------------------------------------------------------

    def status(self) -> Status:
        """The status words (cnc_statinfo): mode, run state, motion ..."""
        st = ODBST()
        h = self._h
        rc = self._lib.cnc_statinfo(self.handle if h is None else h, st)
        if rc:
            raise self._fail("cnc_statinfo", rc)
        return _status(st)

    def sysinfo(self) -> SysInfo:
        """System information (cnc_sysinfo)."""
        s = ODBSYS()
        rc = self._lib.cnc_sysinfo(self.handle, s)
        if rc:
            raise self._fail("cnc_sysinfo", rc)
        return _sysinfo(s)

    def positions(self) -> List[AxisPosition]:
        """Absolute, machine, relative positions and distance to go of every
        axis of the path, with names, decimals and units, in one exchange
        (cnc_rdposition, a function of the 30i class: 30i/31i/32i/0i-F)."""
        buf, num = (ODBPOS * MAX_AXIS)(), c_int16(MAX_AXIS)
        rc = self._lib.cnc_rdposition(self.handle, -1, byref(num), buf)
        if rc:
            raise self._fail("cnc_rdposition", rc)
        return _positions(buf, num)

    def alarms(self) -> List[Alarm]:
        """The active alarms of the path with their messages (cnc_rdalmmsg2,
        all types); no alarm: an empty list."""
        buf, num = (ODBALMMSG2 * _ALARMS)(), c_int16(_ALARMS)
        rc = self._lib.cnc_rdalmmsg2(self.handle, -1, byref(num), buf)
        if rc:
            raise self._fail("cnc_rdalmmsg2", rc)
        return _alarms(buf, num)

    # --- parameters and diagnosis ----------------------------------------------

    def _kind(self, table: str, number: int) -> Optional[str]:
        """The kind of parameter (table "p") or diagnosis item ("d") `number`,
        read once (cnc_rdparam_ext / cnc_rddiag_ext) and kept; None when the
        CNC does not know the number."""
        key = (table, number)
        if key in self._kinds:
            return self._kinds[key]
        call = "cnc_rdparam_ext" if table == "p" else "cnc_rddiag_ext"
        if not -32768 <= number <= 32767:
            raise FocasError(call, EW_NUMBER, message=f"number {number} out of range")
        nos, rec = (c_int32 * 1)(number), IODBPRM()
        rc = getattr(self._lib, call)(self.handle, nos, 1, byref(rec))
        if rc:
            raise self._fail(call, rc)
        if rec.type == -1:
            return None
        kinds = _PARAM_KINDS if table == "p" else _DIAG_KINDS
        kind = kinds.get(rec.type & 0xFF)
        if kind is None:
            raise FocasError(call, EW_ATTRIB, message=f"item {number} has type {rec.type}")
        self._kinds[key] = kind
        return kind

    def _path_axes(self) -> int:
        if self._axes is None:
            self._axes = self.sysinfo().axes
        return self._axes

    def _read(self, table: str, number: int, word: int) -> Param:
        call = "cnc_rdparam" if table == "p" else "cnc_diagnoss"
        kind = self._kind(table, number) or "real"  # unknown: the CNC says so below
        axes = self._path_axes() if word < 0 else 1
        buf = IODBPSD()
        rc = getattr(self._lib, call)(self.handle, number, word, sizeof(IODBPSD), byref(buf))
        if rc:
            raise self._fail(call, rc)
        return _param(number, kind, buf, axes)

    def param_values(self, number: int, axis: Optional[int] = None) -> Param:
        """Parameter `number` with its kind: the whole parameter (`axis`
        None: its one value, or one per axis of the path) or the value of
        axis `axis` (1..) alone."""
        _check_axis("cnc_rdparam", axis)
        return self._read("p", number, -1 if axis is None else axis)

    def param(self, number: int, axis: Optional[int] = None) -> Value:
        """One value of parameter `number` (cnc_rdparam): of the path (`axis`
        None) or of axis `axis` (1..). An int (bits as 0..255), a Decimal for
        a real parameter. A per-axis parameter without an axis: EW_ATTRIB."""
        _check_axis("cnc_rdparam", axis)
        return _one("cnc_rdparam", self._read("p", number, 0 if axis is None else axis))

    def diag_values(self, number: int, axis: Optional[int] = None) -> Param:
        """Diagnosis item `number` with its kind, as param_values."""
        _check_axis("cnc_diagnoss", axis)
        return self._read("d", number, -1 if axis is None else axis)

    def diag(self, number: int, axis: Optional[int] = None) -> Value:
        """One value of diagnosis item `number` (cnc_diagnoss), as param."""
        _check_axis("cnc_diagnoss", axis)
        return _one("cnc_diagnoss", self._read("d", number, 0 if axis is None else axis))

    def set_param(self, number: int, value: Union[Value, float, str], axis: Optional[int] = None) -> None:
        """Writes one value of parameter `number` (cnc_wrparam): of the path
        (`axis` None) or of axis `axis`. The CNC checks it as for its own
        panel: parameter write enable and MDI mode, else EW_PASSWD."""
        call = "cnc_wrparam"
        _check_axis(call, axis)
        kind = self._kind("p", number)
        if kind is None:
            raise FocasError(call, EW_NUMBER, message=f"no parameter {number}")
        buf = IODBPSD(datano=number, type=0 if axis is None else axis)
        if kind == "real":
            mant, dec = _fixed(call, value)
            buf.u.rdata.prm_val, buf.u.rdata.dec_val = mant, dec
        else:
            v = int(value)
            if kind in ("bit", "byte"):
                buf.u.cdata = v & 0xFF
            elif kind == "word":
                buf.u.idata = v
            else:
                buf.u.ldata = v
        rc = self._lib.cnc_wrparam(self.handle, 4 + _SIZES[kind], byref(buf))
        if rc:
            raise self._fail(call, rc)

    # --- macro variables -----------------------------------------------------

    def macro(self, number: int) -> Optional[Decimal]:
        """Custom macro variable `number` (cnc_rdmacro), exact; None when vacant."""
        m = ODBM()
        rc = self._lib.cnc_rdmacro(self.handle, number, 10, byref(m))
        if rc:
            raise self._fail("cnc_rdmacro", rc)
        return _macro(m)

    def set_macro(self, number: int, value: Union[Decimal, int, float, str, None]) -> None:
        """Writes custom macro variable `number` (cnc_wrmacro); None makes it
        vacant. The value is sent exactly (digits and decimal places)."""
        mant, dec = (0, -1) if value is None else _fixed("cnc_wrmacro", value)
        rc = self._lib.cnc_wrmacro(self.handle, number, 10, mant, dec)
        if rc:
            raise self._fail("cnc_wrmacro", rc)

    # --- PMC -----------------------------------------------------------------

    def pmc(self, area: Union[str, int], start: int, end: Optional[int] = None,
            type: str = "byte") -> List[Union[int, float]]:
        """PMC data (pmc_rdpmcrng): the elements of `type` ("byte", "word",
        "long", "float", "double") of `area` ("G", "F", "Y", "X", "R", "D" ...)
        starting at byte address `start`, one every size bytes, up to the
        one starting at `end` (default: `start`, one element).
        ``cnc.pmc("D", 100, 120, "word")`` reads D100, D102 ... D120."""
        code, dtype, size, fmt, n = _pmc_spec(area, start, end, type)
        out: List[Union[int, float]] = []
        per = PMC_CHUNK // size
        while len(out) < n:
            k = min(n - len(out), per)
            s = start + len(out) * size
            buf = ctypes.create_string_buffer(8 + k * size)
            rc = self._lib.pmc_rdpmcrng(self.handle, code, dtype, s, s + k * size - 1,
                                        len(buf), buf)
            if rc:
                raise self._fail("pmc_rdpmcrng", rc)
            out.extend(struct.unpack_from(f"={k}{fmt}", buf, 8))
        return out

    def set_pmc(self, area: Union[str, int], start: int, values: List[Union[int, float]],
                type: str = "byte") -> None:
        """Writes `values` as elements of `type` from byte address `start` of
        `area` (pmc_wrpmcrng). The CNC refuses X, F and Y (EW_PMC / EW_DATA)."""
        if not values:
            return
        code, dtype, size, fmt, _ = _pmc_spec(area, start, start, type)
        n = len(values)
        e = start + n * size - 1
        buf = ctypes.create_string_buffer(8 + n * size)
        try:
            struct.pack_into(f"=hhHH{n}{fmt}", buf, 0, code, dtype, start, e, *values)
        except struct.error as ex:
            raise FocasError("pmc_wrpmcrng", EW_DATA, message=str(ex)) from None
        rc = self._lib.pmc_wrpmcrng(self.handle, len(buf), buf)
        if rc:
            raise self._fail("pmc_wrpmcrng", rc)

    # --- programs --------------------------------------------------------------

    def programs(self) -> List[ProgramEntry]:
        """The programs in memory with size, comment and modification date
        (cnc_rdprogdir3 type 2), by number."""
        out: List[ProgramEntry] = []
        top = 0
        while True:
            buf, top_c, num = (PRGDIR3 * 64)(), c_int32(top), c_int16(64)
            rc = self._lib.cnc_rdprogdir3(self.handle, 2, byref(top_c), byref(num), buf)
            if rc:
                raise self._fail("cnc_rdprogdir3", rc)
            for p in buf[:num.value]:
                d = p.mdate
                try:
                    when: Optional[datetime.datetime] = datetime.datetime(
                        d.year, d.month, d.day, d.hour, d.minute)
                except ValueError:
                    when = None
                out.append(ProgramEntry(p.number, p.length, _text(p.comment).strip("()"), when))
            if num.value < 64 or not out:
                return out
            top = out[-1].number + 1

    def program(self, number: int) -> str:
        """Uploads program `number` (cnc_upstart3 ... cnc_upend3): its text
        in punch format ("%", one block a line, "%")."""
        h = self.handle
        rc = self._lib.cnc_upstart3(h, 0, number, number)
        if rc:
            raise self._fail("cnc_upstart3", rc)
        chunks: List[bytes] = []
        buf = ctypes.create_string_buffer(4096)
        n = c_int32(0)
        last = time.monotonic()
        while True:
            n.value = len(buf)
            rc = self._lib.cnc_upload3(h, byref(n), buf)
            if rc == EW_OK:
                chunks.append(buf.raw[:n.value])
                last = time.monotonic()
            elif rc == EW_RESET:
                break
            elif rc == EW_BUFFER and (self.timeout <= 0 or time.monotonic() - last < self.timeout):
                time.sleep(0.001)  # nothing has arrived yet: as FANUC's cnc_upload, every ms
            else:
                err = self._fail("cnc_upload3", rc, "" if rc != EW_BUFFER else "no text within the timeout")
                self._lib.cnc_upend3(h)
                raise err
        rc = self._lib.cnc_upend3(h)
        if rc:
            raise self._fail("cnc_upend3", rc)
        return b"".join(chunks).decode("latin-1")

    def put_program(self, text: Union[str, bytes]) -> None:
        """Downloads program text in punch format ("%", "O<number>" block,
        blocks, "%") into memory (cnc_dwnstart3 ... cnc_dwnend3). The CNC's
        refusal (number in use EW_DATA, memory full EW_OVRFLOW ...) is raised;
        a refused program is not stored."""
        data = text.encode("latin-1") if isinstance(text, str) else bytes(text)
        h = self.handle
        rc = self._lib.cnc_dwnstart3(h, 0)
        if rc:
            raise self._fail("cnc_dwnstart3", rc)
        step = 1280 * 8
        for i in range(0, len(data), step):
            chunk = data[i:i + step]
            n = c_int32(len(chunk))
            rc = self._lib.cnc_download3(h, byref(n), chunk)
            if rc:
                err = self._fail("cnc_download3", rc)
                self._lib.cnc_dwnend3(h)
                raise err
        rc = self._lib.cnc_dwnend3(h)
        if rc:
            raise self._fail("cnc_dwnend3", rc)

    def delete_program(self, number: int) -> None:
        """Deletes program `number` (cnc_delete): EW_DATA when there is none,
        EW_PROT when protected, EW_BUSY when running or selected."""
        rc = self._lib.cnc_delete(self.handle, number)
        if rc:
            raise self._fail("cnc_delete", rc)

    # --- histories -------------------------------------------------------------

    def alarm_history(self) -> List[AlarmHistoryEntry]:
        """The alarm history, newest first (cnc_rdalmhisno, cnc_rdalmhistry).
        Not on a Series 15 (EW_FUNC)."""
        count = c_uint16(0)
        rc = self._lib.cnc_rdalmhisno(self.handle, byref(count))
        if rc:
            raise self._fail("cnc_rdalmhisno", rc)
        out: List[AlarmHistoryEntry] = []
        per = 20
        for s in range(1, count.value + 1, per):
            e = min(count.value, s + per - 1)
            buf = ctypes.create_string_buffer(6 + 48 * per)
            rc = self._lib.cnc_rdalmhistry(self.handle, s, e, len(buf), buf)
            if rc:
                raise self._fail("cnc_rdalmhistry", rc)
            s_no, _, e_no = struct.unpack_from("=HhH", buf, 0)
            for i in range(max(0, e_no - s_no + 1) if e_no >= s_no else 0):
                (_, grp, no, axis, yy, mo, dd, hh, mi, ss, _, ln,
                 msg) = struct.unpack_from("=hhhBBBBBBBBh32s", buf, 6 + 48 * i)
                try:
                    when = datetime.datetime(2000 + yy, mo, dd, hh, mi, ss)
                except ValueError:
                    continue
                out.append(AlarmHistoryEntry(no, grp, axis, when, _text(msg, ln)))
        return out

    def operation_history(self) -> List[OperationRecord]:
        """The operation history, newest first (cnc_rdophisno, cnc_rdophistry):
        MDI keys, signal changes, alarms, dates and times."""
        count = c_uint16(0)
        rc = self._lib.cnc_rdophisno(self.handle, byref(count))
        if rc:
            raise self._fail("cnc_rdophisno", rc)
        out: List[OperationRecord] = []
        per = 80
        for s in range(1, count.value + 1, per):
            e = min(count.value, s + per - 1)
            buf = ctypes.create_string_buffer(6 + 8 * per)
            rc = self._lib.cnc_rdophistry(self.handle, s, e, len(buf), buf)
            if rc:
                raise self._fail("cnc_rdophistry", rc)
            s_no, _, e_no = struct.unpack_from("=HhH", buf, 0)
            for i in range(e_no - s_no + 1 if e_no >= s_no else 0):
                out.append(_op_record(bytes(buf.raw[6 + 8 * i:14 + 8 * i])))
        return out

    # --- batch -----------------------------------------------------------------

    def batch(self) -> "Batch":
        """A batch of reads sent together in as few request frames as fit
        (fwlib_batch_begin ... fwlib_batch_end):

            with cnc.batch() as b:
                st, parts = b.status(), b.param(6711)
            print(st.value.mode, parts.value)
        """
        return Batch(self)


_ALARMS = 32


_ODBST = struct.Struct("=9h")


def _status(st: ODBST) -> Status:
    # One unpack of the nine words: the fastest read of a ctypes structure.
    _, tmmode, aut, run, motion, mstb, emg, alarm, edit = _ODBST.unpack(st)
    return Status(_MODE.get(aut, aut), _RUN.get(run, run), _MOTION.get(motion, motion), mstb,
                  _EMG.get(emg, emg), _ALM.get(alarm, alarm), edit, tmmode)


def _sysinfo(s: ODBSYS) -> SysInfo:
    axes = _text(s.axes)
    return SysInfo(_text(s.cnc_type), bytes(s.mt_type).decode("latin-1"), _text(s.series),
                   _text(s.version), int(axes) if axes.isdigit() else 0, s.max_axis, s.addinfo)


def _positions(buf: Any, num: c_int16) -> List[AxisPosition]:
    out = []
    for p in buf[:max(0, num.value)]:
        a = p.abs
        if a.name == 0:
            continue
        name = chr(a.name) + (chr(a.suff) if 32 < a.suff < 127 else "")
        out.append(AxisPosition(name, _dec(a.data, a.dec), _dec(p.mach.data, p.mach.dec),
                                _dec(p.rel.data, p.rel.dec), _dec(p.dist.data, p.dist.dec),
                                _UNIT.get(a.unit, a.unit)))
    return out


def _alarms(buf: Any, num: c_int16) -> List[Alarm]:
    return [Alarm(a.alm_no, a.type, a.axis, _text(a.alm_msg, a.msg_len))
            for a in buf[:max(0, num.value)]]


def _param(number: int, kind: str, buf: IODBPSD, axes: int) -> Param:
    # The answer's axis word: negative all axes, n one axis, 0 none.
    word = buf.type
    count = min(axes, MAX_AXIS) if word < 0 else 1
    return Param(number, kind, word != 0, _values(kind, buf.u, count))


def _one(call: str, p: Param) -> Value:
    if len(p.values) != 1:
        raise FocasError(call, EW_ATTRIB, message=f"item {p.number} is per axis: give an axis")
    return p.values[0]


def _macro(m: ODBM) -> Optional[Decimal]:
    return None if m.dec_val == -1 else _dec(m.mcr_val, m.dec_val)


def _fixed(call: str, value: Union[Decimal, int, float, str]) -> Tuple[int, int]:
    """(digits, decimal places) of `value`, exactly; EW_DATA when it does not
    fit 32 bits."""
    try:
        d = Decimal(str(value)) if not isinstance(value, Decimal) else value
        sign, digits, exp = d.as_tuple()
    except Exception:
        raise FocasError(call, EW_DATA, message=f"{value!r} is not a number") from None
    if not isinstance(exp, int):
        raise FocasError(call, EW_DATA, message=f"{value!r} is not a finite number")
    mant = int("".join(map(str, digits)) or "0") * (-1 if sign else 1)
    dec = -exp
    while dec < 0:
        mant, dec = mant * 10, dec + 1
    if not -(2 ** 31) <= mant < 2 ** 31:
        raise FocasError(call, EW_DATA, message=f"{value!r} does not fit 32 bits")
    return mant, dec


def _op_record(r: bytes) -> OperationRecord:
    t = struct.unpack_from("=h", r, 0)[0]
    if t == 0:
        return OperationRecord("mdi", t, key=r[2], power_on=bool(r[3]))
    if t == 1:
        return OperationRecord("signal", t, signal_area=r[2], old=r[3], new=r[4],
                               signal_number=struct.unpack_from("=h", r, 6)[0])
    if t == 2:
        grp, no = struct.unpack_from("=hh", r, 2)
        return OperationRecord("alarm", t, alarm_type=grp, alarm_number=no, axis=r[6])
    if t == 3:
        try:
            d: Optional[datetime.date] = datetime.date(2000 + r[2], r[3], r[4])
        except ValueError:
            d = None
        return OperationRecord("date", t, date=d, power_on=bool(r[5]))
    if t == 4:
        try:
            tm: Optional[datetime.time] = datetime.time(r[2], r[3], r[4])
        except ValueError:
            tm = None
        return OperationRecord("time", t, time=tm, power_on=bool(r[5]))
    return OperationRecord("other", t)


class Batch:
    """Reads gathered, then sent together (fwlib_batch_begin ...
    fwlib_batch_end): each method returns a Pending whose `value` is there
    once the batch is sent (on leaving the `with` block, or by send()). Each
    read's outputs and error are those of the same read made alone; an
    error of one read (its `Pending.value` raises it) leaves the others.
    Batched errors carry no detail words. Parameters and diagnosis items
    whose kind the Cnc has not yet seen cost one exchange each before the
    batch (the kind is kept for later batches).
    """

    def __init__(self, cnc: Cnc) -> None:
        self._cnc = cnc
        # (pending, queue: () -> rc, decode: () -> value); a read whose kind
        # must be known first has `learn` run before the batch begins.
        self._ops: List[Tuple[Pending[Any], Callable[[], int], Callable[[], Any]]] = []
        self._learn: List[Tuple[str, int]] = []
        self._sent = False

    def __enter__(self) -> "Batch":
        return self

    def __exit__(self, exc_type: Any, *exc: Any) -> None:
        if exc_type is None and not self._sent:
            self.send()

    def __len__(self) -> int:
        return len(self._ops)

    def _add(self, call: str, queue: Callable[[], int], decode: Callable[[], Any]) -> Pending[Any]:
        if self._sent:
            raise FocasError(call, EW_NUMBER, message="the batch was already sent")
        p: Pending[Any] = Pending(call)
        self._ops.append((p, queue, decode))
        return p

    def status(self) -> Pending[Status]:
        """Cnc.status in the batch."""
        c, st = self._cnc, ODBST()
        return self._add("cnc_statinfo", lambda: c._lib.cnc_statinfo(c.handle, st),
                         lambda: _status(st))

    def sysinfo(self) -> Pending[SysInfo]:
        """Cnc.sysinfo in the batch."""
        c, s = self._cnc, ODBSYS()
        return self._add("cnc_sysinfo", lambda: c._lib.cnc_sysinfo(c.handle, s),
                         lambda: _sysinfo(s))

    def positions(self) -> Pending[List[AxisPosition]]:
        """Cnc.positions in the batch."""
        c, buf, num = self._cnc, (ODBPOS * MAX_AXIS)(), c_int16(MAX_AXIS)
        return self._add("cnc_rdposition",
                         lambda: c._lib.cnc_rdposition(c.handle, -1, byref(num), buf),
                         lambda: _positions(buf, num))

    def alarms(self) -> Pending[List[Alarm]]:
        """Cnc.alarms in the batch."""
        c, buf, num = self._cnc, (ODBALMMSG2 * _ALARMS)(), c_int16(_ALARMS)
        return self._add("cnc_rdalmmsg2",
                         lambda: c._lib.cnc_rdalmmsg2(c.handle, -1, byref(num), buf),
                         lambda: _alarms(buf, num))

    def macro(self, number: int) -> Pending[Optional[Decimal]]:
        """Cnc.macro in the batch."""
        c, m = self._cnc, ODBM()
        return self._add("cnc_rdmacro", lambda: c._lib.cnc_rdmacro(c.handle, number, 10, byref(m)),
                         lambda: _macro(m))

    def _item(self, table: str, number: int, axis: Optional[int], whole: bool) -> Pending[Any]:
        call = "cnc_rdparam" if table == "p" else "cnc_diagnoss"
        c, buf = self._cnc, IODBPSD()
        word = (-1 if whole else 0) if axis is None else axis
        self._learn.append((table, number))

        def queue() -> int:
            _check_axis(call, axis)
            rc: int = getattr(c._lib, call)(c.handle, number, word, sizeof(IODBPSD), byref(buf))
            return rc

        def decode() -> Any:
            kind = c._kinds.get((table, number), "real")
            p = _param(number, kind, buf, c._path_axes() if word < 0 else 1)
            return p if whole else _one(call, p)
        return self._add(call, queue, decode)

    def param(self, number: int, axis: Optional[int] = None) -> Pending[Value]:
        """Cnc.param in the batch."""
        return self._item("p", number, axis, False)

    def param_values(self, number: int, axis: Optional[int] = None) -> Pending[Param]:
        """Cnc.param_values in the batch."""
        return self._item("p", number, axis, True)

    def diag(self, number: int, axis: Optional[int] = None) -> Pending[Value]:
        """Cnc.diag in the batch."""
        return self._item("d", number, axis, False)

    def diag_values(self, number: int, axis: Optional[int] = None) -> Pending[Param]:
        """Cnc.diag_values in the batch."""
        return self._item("d", number, axis, True)

    def pmc(self, area: Union[str, int], start: int, end: Optional[int] = None,
            type: str = "byte") -> Pending[List[Union[int, float]]]:
        """Cnc.pmc in the batch: at most PMC_CHUNK bytes."""
        c = self._cnc
        spec: List[Any] = []
        buf = ctypes.create_string_buffer(8 + PMC_CHUNK)

        def queue() -> int:
            code, dtype, size, fmt, n = _pmc_spec(area, start, end, type)
            if n * size > PMC_CHUNK:
                raise FocasError("pmc_rdpmcrng", EW_LENGTH,
                                 message=f"a batch reads at most {PMC_CHUNK} PMC bytes at once")
            spec[:] = [n, fmt]
            rc: int = c._lib.pmc_rdpmcrng(c.handle, code, dtype, start, start + n * size - 1,
                                          8 + n * size, buf)
            return rc

        return self._add("pmc_rdpmcrng", queue,
                         lambda: list(struct.unpack_from(f"={spec[0]}{spec[1]}", buf, 8)))

    def send(self) -> None:
        """Sends the gathered reads (once) and fills every Pending. A failure
        of the connection is every affected read's error."""
        if self._sent:
            return
        self._sent = True
        c = self._cnc
        for table, number in self._learn:
            try:
                c._kind(table, number)
            except FocasError:
                pass  # the read itself reports it
        if any(t == "p" or t == "d" for t, _ in self._learn):
            try:
                c._path_axes()
            except FocasError:
                pass
        h = c.handle
        rc = c._lib.fwlib_batch_begin(h)
        if rc:
            raise c._fail("fwlib_batch_begin", rc)
        queued: List[Tuple[Pending[Any], Callable[[], Any]]] = []
        try:
            for p, queue, decode in self._ops:
                try:
                    rc = queue()
                except FocasError as e:
                    p._set(error=e)
                    continue
                if rc:
                    p._set(error=FocasError(p.call, rc))
                else:
                    queued.append((p, decode))
        finally:
            results = (c_int16 * max(1, len(queued)))()
            rc = c._lib.fwlib_batch_end(h, results, len(queued))
        if rc:
            raise c._fail("fwlib_batch_end", rc)
        for (p, decode), r in zip(queued, results):
            if r:
                p._set(error=FocasError(p.call, r))
            else:
                try:
                    p._set(decode())
                except FocasError as e:
                    p._set(error=e)
