"""FocasError: a closed port, a refusing simulator, CNC-side refusals, a
silent CNC within the timeout."""

import pickle
import socket
import time

import pytest

from fwlib32 import Cnc, FocasError, ew_name
from fwlib32.testing import simulator


def closed_port() -> int:
    """A loopback port nobody listens on (bound, read back, closed)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_a_closed_port():
    port = closed_port()
    with pytest.raises(FocasError) as e:
        Cnc("127.0.0.1", port, timeout=5)
    err = e.value
    assert (err.function, err.code, err.name) == ("cnc_allclibhndl3", -16, "EW_SOCKET")
    assert err.detail is None  # no handle to ask
    assert f"127.0.0.1:{port}" in str(err)
    assert str(err).startswith("cnc_allclibhndl3: EW_SOCKET (-16): socket error")


def test_a_refusing_simulator():
    # `refuse`: the CNC's FOCAS server not accepting (docs/simulator.md, faults).
    with simulator(args=["--fault", "refuse"]) as sim:
        with pytest.raises(FocasError) as e:
            Cnc(sim.host, sim.port, timeout=5)
    assert (e.value.function, e.value.name) == ("cnc_allclibhndl3", "EW_SOCKET")


def test_a_cnc_answering_an_error_code():
    spec = "error:functions=cnc_statinfo,code=EW_BUSY"
    with simulator(args=["--fault", spec]) as sim, Cnc(sim.host, sim.port) as cnc:
        with pytest.raises(FocasError) as e:
            cnc.status()
        assert (e.value.function, e.value.code, e.value.name) == ("cnc_statinfo", -1, "EW_BUSY")
        assert e.value.detail is not None  # cnc_getdtailerr answered
        # The other functions go on.
        assert cnc.sysinfo().axes == 3


def test_a_silent_cnc_ends_within_the_timeout():
    # Connected first, then the CNC stops answering (a pulled cable): the
    # call ends with EW_SOCKET after the handle's timeout, not never.
    with simulator(args=["--fault", "silent:at=0,duration=0"]) as sim:
        start = time.monotonic()
        with pytest.raises(FocasError) as e:
            Cnc(sim.host, sim.port, timeout=1)
        assert e.value.name == "EW_SOCKET"
        assert time.monotonic() - start < 30  # bounded: not a speed goal


def test_a_cnc_switched_off():
    # `off` from the start: connections reset at once, new ones refused.
    with simulator(args=["--fault", "off:at=0,duration=0"]) as sim:
        with pytest.raises(FocasError) as e:
            Cnc(sim.host, sim.port, timeout=5)
        assert (e.value.function, e.value.name) == ("cnc_allclibhndl3", "EW_SOCKET")


def test_the_error_object():
    e = FocasError("cnc_rdparam", 3, (3, 0), "extra words")
    assert (e.function, e.code, e.name, e.detail, e.message) == (
        "cnc_rdparam", 3, "EW_NUMBER", (3, 0), "extra words")
    assert e.meaning == "data number error: no such number"
    assert str(e) == "cnc_rdparam: EW_NUMBER (3): data number error: no such number: extra words [detail 3/0]"
    assert isinstance(e, Exception)
    back = pickle.loads(pickle.dumps(e))
    assert (back.function, back.code, back.detail, str(back)) == (e.function, e.code, e.detail, str(e))
    assert FocasError("f", 999).name == "EW_?"
    assert ew_name(-16) == "EW_SOCKET" and ew_name(1) == "EW_FUNC"
