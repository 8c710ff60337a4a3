"""The typed API on every area, against data/machine.toml."""

import datetime
import os
import sysconfig
from decimal import Decimal

import pytest

import fwlib32
from fwlib32 import (AlarmState, Cnc, Emergency, FocasError, Mode, Motion, Param, Run, Unit)
from fwlib32.testing import simulator


def test_the_package_under_test_is_the_installed_one():
    # CI installs the wheel into a fresh venv and runs these tests from a
    # folder outside the repository: the package must come from there.
    purelib = os.path.realpath(sysconfig.get_paths()["purelib"])
    assert os.path.realpath(fwlib32.__file__).startswith(purelib + os.sep), fwlib32.__file__
    assert os.path.isfile(fwlib32.library_path())
    assert os.path.basename(fwlib32.library_path()) == "libfwlib32.so.1"
    for name in ("focas-sim", "focas"):
        assert os.access(fwlib32.bin_path(name), os.X_OK)
    assert os.path.isfile(os.path.join(os.path.dirname(fwlib32.__file__), "py.typed"))


def test_status(cnc):
    st = cnc.status()
    assert (st.mode, st.run, st.motion) == (Mode.EDIT, Run.STOP, Motion.IDLE)
    assert (st.emergency, st.alarm, st.mstb, st.edit) == (Emergency.EMERGENCY, AlarmState.ALARM, 0, 0)


def test_sysinfo(cnc):
    s = cnc.sysinfo()
    assert (s.cnc_type, s.mt_type, s.series, s.version) == ("31", " T", "G4T1", "12.5")
    assert (s.axes, s.max_axes) == (3, 32)


def test_positions(cnc):
    axes = cnc.positions()
    assert [a.name for a in axes] == ["X", "Z", "C"]
    x, z, c = axes
    assert (x.absolute, x.machine, x.relative, x.distance) == (
        Decimal("52.250"), Decimal("152.250"), Decimal("-1.500"), Decimal("0.250"))
    assert str(z.absolute) == "-123.4567" and str(z.machine) == "200.0000"
    assert (x.unit, z.unit, c.unit) == (Unit.MM, Unit.MM, Unit.DEGREE)
    assert c.absolute == Decimal("270.000")


def test_alarms(cnc):
    alarms = cnc.alarms()
    assert len(alarms) == 1
    a = alarms[0]
    assert (a.number, a.type, a.axis, a.message) == (1001, 19, 0, "HYDRAULIC PRESSURE LOW")
    assert a.code == "PC1001"


def test_params_of_every_kind(cnc):
    assert cnc.param(0) == 0b10000001
    assert cnc.param_values(0) == Param(0, "bit", False, [129])
    assert cnc.param(20) == -5
    assert cnc.param_values(20).kind == "byte"
    assert cnc.param(1825, 2) == -3001
    assert cnc.param_values(1825) == Param(1825, "word", True, [3000, -3001, 3002])
    assert cnc.param(6711) == 987654
    assert cnc.param_values(6711).kind == "2word"
    assert cnc.param(1320, 1) == Decimal("800.000")
    p = cnc.param_values(1320)
    assert p.kind == "real" and p.per_axis
    assert p.values == [Decimal("800.000"), Decimal("-0.500"), Decimal("0.001")]
    assert cnc.param_values(1320, 3) == Param(1320, "real", True, [Decimal("0.001")])


def test_param_errors(cnc):
    with pytest.raises(FocasError) as e:
        cnc.param(9999)
    assert (e.value.function, e.value.code, e.value.name) == ("cnc_rdparam", 3, "EW_NUMBER")
    # A per-axis parameter read without an axis: the CNC's EW_ATTRIB.
    with pytest.raises(FocasError) as e:
        cnc.param(1320)
    assert e.value.name == "EW_ATTRIB"
    with pytest.raises(FocasError) as e:
        cnc.param(1320, 0)
    assert e.value.code == 4


def test_diagnosis(cnc):
    assert cnc.diag_values(308) == Param(308, "byte", True, [38, 36, 41])
    assert cnc.diag(308, 3) == 41
    assert cnc.diag(411) == -21
    assert cnc.diag(4901) == Decimal("23.5")
    with pytest.raises(FocasError) as e:
        cnc.diag(9998)
    assert (e.value.function, e.value.name) == ("cnc_diagnoss", "EW_NUMBER")


def test_macro_read_write(cnc):
    assert cnc.macro(100) == 42
    assert cnc.macro(500) == Decimal("-0.0625")
    assert str(cnc.macro(500)) == "-0.0625"
    assert cnc.macro(150) is None  # vacant
    try:
        cnc.set_macro(150, Decimal("12.345"))
        assert str(cnc.macro(150)) == "12.345"
        cnc.set_macro(150, -7)
        assert cnc.macro(150) == -7
    finally:
        cnc.set_macro(150, None)
    assert cnc.macro(150) is None
    with pytest.raises(FocasError) as e:
        cnc.macro(30000)
    assert (e.value.function, e.value.name) == ("cnc_rdmacro", "EW_NUMBER")


def test_pmc_read_write(cnc):
    assert cnc.pmc("D", 0, type="long") == [1000]
    assert cnc.pmc("d", 0, 3) == [0, 0, 3, -24]
    assert cnc.pmc("D", 10, 11) == [0x12, 0x34]
    assert cnc.pmc("R", 500, 501) == [127, -128]
    try:
        cnc.set_pmc("D", 100, [1, -2, 300], "word")
        assert cnc.pmc("D", 100, 104, "word") == [1, -2, 300]
        cnc.set_pmc("D", 200, [1.5], "double")
        assert cnc.pmc("D", 200, type="double") == [1.5]
    finally:
        cnc.set_pmc("D", 100, [0] * 6)
        cnc.set_pmc("D", 200, [0] * 8)
    # A range longer than one exchange is read in pieces.
    assert cnc.pmc("D", 0, 2999) == [0, 0, 3, -24] + [0] * 6 + [0x12, 0x34] + [0] * 2988
    with pytest.raises(FocasError) as e:
        cnc.pmc("Q", 0)
    assert e.value.name == "EW_ATTRIB"
    with pytest.raises(FocasError) as e:
        cnc.set_pmc("X", 0, [1])
    assert (e.value.function, e.value.name) == ("pmc_wrpmcrng", "EW_PROT")


def test_programs(cnc):
    entries = cnc.programs()
    assert [p.number for p in entries] == [10]
    p = entries[0]
    assert (p.comment, p.modified) == ("FACE", datetime.datetime(2025, 1, 2, 3, 4))
    assert p.length > 0
    # Punch format: "%", a block a line, "%" (no line end after it).
    assert cnc.program(10) == "%\nO0010 (FACE)\nN10 G50 S2000\nN20 M30\n%"

    text = "%\nO0777 (FROM PYTHON)\nN10 G00 X0.\nN20 M30\n%\n"
    cnc.put_program(text)
    try:
        assert [p.number for p in cnc.programs()] == [10, 777]
        assert cnc.program(777) == text.rstrip("\n")
        # The number is taken: the CNC refuses, nothing changes.
        with pytest.raises(FocasError) as e:
            cnc.put_program(text)
        assert e.value.code != 0
    finally:
        cnc.delete_program(777)
    assert [p.number for p in cnc.programs()] == [10]
    with pytest.raises(FocasError) as e:
        cnc.delete_program(777)
    assert (e.value.function, e.value.name) == ("cnc_delete", "EW_DATA")
    with pytest.raises(FocasError) as e:
        cnc.program(4242)
    assert (e.value.function, e.value.name) == ("cnc_upload3", "EW_DATA")


def test_program_text_of_several_frames(cnc):
    blocks = "".join(f"N{n} G01 X{n}.125 Y-{n}.5 F1000\n" for n in range(10, 3000, 10))
    text = f"%\nO0888 (LONG)\n{blocks}M30\n%\n"
    assert len(text) > 3 * 1450
    cnc.put_program(text)
    try:
        assert cnc.program(888) == text.rstrip("\n")
    finally:
        cnc.delete_program(888)


def test_alarm_history(cnc):
    h = cnc.alarm_history()
    # The alarm raised at the start comes first (by the simulator's clock),
    # then the profile's entries, newest first.
    assert [(e.number, e.type) for e in h] == [(1001, 19), (500, 4), (410, 6)]
    assert h[0].message == "HYDRAULIC PRESSURE LOW"
    assert (h[1].axis, h[1].time, h[1].message) == (
        2, datetime.datetime(2025, 3, 4, 5, 6, 7), "OVER TRAVEL ( +Z )")
    assert h[1].code == "OT0500"
    assert h[2].time == datetime.datetime(2024, 12, 31, 23, 59, 58)


def test_operation_history(cnc):
    h = cnc.operation_history()
    kinds = [r.kind for r in h]
    # The profile's three entries are the oldest; the start-up alarm and its
    # time stamp come before them.
    mdi, sig, date = h[-3:]
    assert (mdi.kind, mdi.key) == ("mdi", 0x52)
    assert (sig.kind, sig.signal_area, sig.signal_number, sig.old, sig.new) == ("signal", 0, 43, 1, 5)
    assert (date.kind, date.date) == ("date", datetime.date(2025, 3, 4))
    assert "alarm" in kinds[:-3]
    alarm = next(r for r in h if r.kind == "alarm")
    assert (alarm.alarm_number, alarm.alarm_type) == (1001, 19)


def test_batch(cnc):
    with cnc.batch() as b:
        st = b.status()
        pos = b.positions()
        alarms = b.alarms()
        parts = b.param(6711)
        limit = b.param(1320, 2)
        whole = b.param_values(1825)
        dgn = b.diag(4901)
        gauge = b.macro(500)
        d0 = b.pmc("D", 0, type="long")
        missing = b.param(9999)
        info = b.sysinfo()
        assert len(b) == 11
    assert st.value.mode == Mode.EDIT
    assert [a.name for a in pos.value] == ["X", "Z", "C"]
    assert alarms.value[0].number == 1001
    assert parts.value == 987654
    assert limit.value == Decimal("-0.500")
    assert whole.value.values == [3000, -3001, 3002]
    assert dgn.value == Decimal("23.5")
    assert gauge.value == Decimal("-0.0625")
    assert d0.value == [1000]
    assert info.value.series == "G4T1"
    assert missing.error is not None and missing.error.name == "EW_NUMBER"
    with pytest.raises(FocasError):
        missing.value
    # The batch gave what the calls give alone.
    assert st.value == cnc.status() and pos.value == cnc.positions()


def test_pending_before_send(cnc):
    b = cnc.batch()
    st = b.status()
    with pytest.raises(FocasError):
        st.value
    b.send()
    assert st.value.run == Run.STOP
    # After a batch, calls go out alone again.
    assert cnc.param(6711) == 987654


MDI_MACHINE = """
[cnc]
class = "{cls}"
max_axes = 8
[[path]]
machine = "mill"
[path.status]
aut = 0
[[path.axis]]
name = "X"
decimals = 3
[param]
param_write_enable = true
[[param.parameter]]
number = 6711
kind = "2word"
values = [5]
[[param.parameter]]
number = 1320
kind = "real"
axis = true
decimals = 3
values = [100000]
[[param.parameter]]
number = 20
kind = "byte"
values = [1]
"""


def test_parameter_writes():
    profile = MDI_MACHINE.format(cls="30i")
    with simulator(profile_text=profile) as sim, Cnc(sim.host, sim.port) as cnc:
        assert cnc.status().mode == Mode.MDI
        cnc.set_param(6711, 77)
        assert cnc.param(6711) == 77
        cnc.set_param(1320, "12.5", axis=1)
        assert cnc.param(1320, 1) == Decimal("12.500")
        cnc.set_param(20, -3)
        assert cnc.param(20) == -3


def test_a_16i_class_cnc():
    profile = MDI_MACHINE.format(cls="16i")
    with simulator(profile_text=profile) as sim, Cnc(sim.host, sim.port) as cnc:
        assert (cnc.sysinfo().axes, cnc.sysinfo().max_axes) == (1, 8)
        cnc.set_param(6711, 78)
        with cnc.batch() as b:
            p, st, whole = b.param(6711), b.status(), b.param_values(1320)
        assert p.value == 78 and st.value.mode == Mode.MDI
        assert whole.value.per_axis and len(whole.value.values) == 1


def test_a_refused_parameter_write_changes_nothing(cnc):
    # machine.toml is in EDIT mode: the CNC wants MDI for a parameter write.
    with pytest.raises(FocasError) as e:
        cnc.set_param(6711, 1)
    assert (e.value.function, e.value.name) == ("cnc_wrparam", "EW_PASSWD")
    assert cnc.param(6711) == 987654


def test_close_and_reuse(machine):
    cnc = Cnc(machine.host, machine.port)
    h = cnc.handle
    assert h > 0 and repr(cnc).endswith(f"handle {h})")
    cnc.close()
    cnc.close()
    with pytest.raises(FocasError) as e:
        cnc.status()
    assert e.value.name == "EW_HANDLE"
