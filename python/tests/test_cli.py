"""The bundled programs: `python -m fwlib32.sim`, the `focas` entry point,
and the pytest fixture the package registers."""

import json
import os
import subprocess
import sys
import sysconfig

from fwlib32 import Cnc


def test_python_m_fwlib32_sim():
    out = subprocess.run([sys.executable, "-m", "fwlib32.sim", "--print-profile"],
                         check=True, capture_output=True, text=True).stdout
    assert "[cnc]" in out and 'class = "30i"' in out
    usage = subprocess.run([sys.executable, "-m", "fwlib32.sim", "--help"],
                           check=True, capture_output=True, text=True).stdout
    assert "listening on ADDR" in usage


def scripts_dir() -> str:
    return sysconfig.get_paths()["scripts"]


def test_the_focas_command(machine):
    focas = os.path.join(scripts_dir(), "focas")
    assert os.access(focas, os.X_OK), focas
    out = subprocess.run([focas, "--host", machine.host, "--port", str(machine.port),
                          "--json", "status"], check=True, capture_output=True, text=True).stdout
    st = json.loads(out)
    assert st["mode"]["name"] == "EDIT" and st["run"]["name"] == "STOP"
    # A failure: one line on stderr, exit status 1.
    bad = subprocess.run([focas, "--host", "127.0.0.1", "--port", "1", "status"],
                         capture_output=True, text=True)
    assert bad.returncode == 1 and "EW_SOCKET" in bad.stderr


def test_python_m_fwlib32(machine):
    out = subprocess.run([sys.executable, "-m", "fwlib32", "--host", machine.host, "--port",
                          str(machine.port), "param", "6711"],
                         check=True, capture_output=True, text=True).stdout
    assert "987654" in out


def test_the_focas_sim_command():
    sim = os.path.join(scripts_dir(), "focas-sim")
    out = subprocess.run([sim, "--help"], check=True, capture_output=True, text=True).stdout
    assert "--fleet" in out


def test_the_pytest_fixture(focas_sim):
    # The built-in profile (a 31i-B mill): part counter 1234.
    with Cnc(focas_sim.host, focas_sim.port) as cnc:
        assert cnc.param(6711) == 1234
        assert cnc.sysinfo().mt_type == " M"
    assert focas_sim.process.poll() is None


def test_a_fleet(focas_sim_factory):
    sim = focas_sim_factory(fleet=3)
    assert len(sim.addrs) == 3 and len({p for _, p in sim.addrs}) == 3
    for host, port in sim.addrs:
        with Cnc(host, port) as cnc:
            assert cnc.sysinfo().series == "G421"
