"""The bundled CNC simulator for tests: ``simulator()`` starts focas-sim on
a free loopback port and stops it again.

    from fwlib32 import Cnc
    from fwlib32.testing import simulator

    with simulator() as sim, Cnc(sim.host, sim.port) as cnc:
        assert cnc.param(6711) == 1234

With pytest, the `focas_sim` fixture is the same (fwlib32.pytest_plugin,
registered when the package is installed).
"""

from __future__ import annotations

import contextlib
import os
import selectors
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass, field
from typing import Iterator, List, Optional, Sequence, Tuple, Union

from ._bin import path as _bin_path

__all__ = ["Simulator", "simulator", "START_TIMEOUT"]

START_TIMEOUT = 30.0
"""Seconds focas-sim has to print its listening lines."""

PathLike = Union[str, "os.PathLike[str]"]


@dataclass
class Simulator:
    """A running focas-sim: where it listens, and its process."""
    host: str
    """The address to connect to ("127.0.0.1")."""
    port: int
    """Its port (the first machine's, with a fleet)."""
    process: "subprocess.Popen[bytes]"
    addrs: List[Tuple[str, int]] = field(default_factory=list)
    """(host, port) of every machine, in order (one without a fleet)."""

    @property
    def pid(self) -> int:
        """The simulator's process id."""
        return self.process.pid

    @property
    def addr(self) -> str:
        """"HOST:PORT" of the first machine."""
        return f"{self.host}:{self.port}"

    def stop(self) -> None:
        """Kills the simulator (by its PID) and reaps it; stopping twice does nothing."""
        if self.process.poll() is None:
            try:
                os.kill(self.process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        self.process.wait()
        if self.process.stdout is not None:
            self.process.stdout.close()


def _listening(line: bytes) -> Tuple[str, int]:
    text = line.decode("utf-8", "replace").strip()
    prefix = "listening on "
    if not text.startswith(prefix):
        raise RuntimeError(f"focas-sim: unexpected first line {text!r}")
    host, _, port = text[len(prefix):].rpartition(":")
    return host.strip("[]"), int(port)


def start(profile: Optional[PathLike] = None, *, profile_text: Optional[str] = None,
          args: Sequence[str] = (), fleet: Optional[int] = None,
          host: str = "127.0.0.1") -> Simulator:
    """Starts focas-sim on `host` port 0 (a free port) and returns it once it
    listens; the caller stops it (Simulator.stop). See simulator()."""
    cmd = [_bin_path("focas-sim"), "--listen", f"{host}:0"]
    tmp = None
    if profile_text is not None:
        fd, tmp = tempfile.mkstemp(prefix="focas-sim-", suffix=".toml")
        with os.fdopen(fd, "w") as f:
            f.write(profile_text)
        cmd += ["--profile", tmp]
    if profile is not None:
        cmd += ["--profile", os.fspath(profile)]
    if fleet is not None:
        cmd += ["--fleet", str(fleet)]
    cmd += list(args)
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    sim = Simulator(host, 0, proc)
    try:
        assert proc.stdout is not None and proc.stderr is not None
        want = fleet or 1
        lines = _read_lines(proc, want)
        if len(lines) < want:
            err = proc.stderr.read().decode("utf-8", "replace").strip() if proc.poll() is not None else ""
            raise RuntimeError(f"focas-sim did not start: {err or 'no listening line'} ({' '.join(cmd)})")
        sim.addrs = [_listening(line) for line in lines]
        sim.host, sim.port = sim.addrs[0]
        # The profile is read at the start: its temporary file can go.
        if tmp is not None:
            os.unlink(tmp)
            tmp = None
        proc.stderr.close()
        return sim
    except BaseException:
        sim.stop()
        raise
    finally:
        if tmp is not None:
            os.unlink(tmp)


def _read_lines(proc: "subprocess.Popen[bytes]", want: int) -> List[bytes]:
    """Up to `want` lines of stdout, waiting at most START_TIMEOUT for them."""
    assert proc.stdout is not None
    fd = proc.stdout.fileno()
    deadline = time.monotonic() + START_TIMEOUT
    buf, lines = b"", []  # type: Tuple[bytes, List[bytes]]
    with selectors.DefaultSelector() as sel:
        sel.register(fd, selectors.EVENT_READ)
        while len(lines) < want:
            left = deadline - time.monotonic()
            if left <= 0 or not sel.select(left):
                break
            chunk = os.read(fd, 4096)
            if not chunk:
                break
            buf += chunk
            *done, buf = buf.split(b"\n")
            lines += done
    return lines[:want]


@contextlib.contextmanager
def simulator(profile: Optional[PathLike] = None, *, profile_text: Optional[str] = None,
              args: Sequence[str] = (), fleet: Optional[int] = None,
              host: str = "127.0.0.1") -> Iterator[Simulator]:
    """Runs the bundled focas-sim for the `with` block and yields a
    Simulator (host, port, addrs, pid); on exit it is killed by its PID.

    profile: a machine profile file (TOML; default the built-in 3-axis
        mill, `python -m fwlib32.sim --print-profile` prints it);
    profile_text: the same as text (written to a temporary file);
    args: more focas-sim options, e.g. ["--fault", "refuse"];
    fleet: serve that many machines, each on its own port (addrs).
    """
    sim = start(profile, profile_text=profile_text, args=args, fleet=fleet, host=host)
    try:
        yield sim
    finally:
        sim.stop()
