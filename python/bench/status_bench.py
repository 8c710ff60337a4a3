#!/usr/bin/env python3
"""Reading the status 1,000 times: the typed API against raw ctypes on the
same library against a plain-socket floor, in one run, on the bundled
simulator (loopback). Prints the times and the ratios (never asserts them).

    python bench/status_bench.py [--calls 1000] [--rounds 15]

- typed: fwlib32.Cnc.status() (a Status dataclass with enums);
- ctypes: cnc_statinfo(handle, byref(ODBST())) on fwlib32.library_path(),
  declared as a ctypes program written for FANUC's library declares it;
- floor: a plain Python socket sending the very request frame the library
  sends for cnc_statinfo (captured through a loopback relay) on a session it
  opened with the library's own open frame, reading each answer whole.

The three run in turn, `--rounds` times, on the same simulator; the times
are medians over the rounds, each ratio the median of the rounds' ratios.
"""

import argparse
import ctypes
import socket
import statistics
import sys
import threading
import time
from ctypes import POINTER, Structure, byref, c_char_p, c_int16, c_long, c_uint16

import fwlib32
from fwlib32.testing import simulator

HEADER = 10  # a0 a0 a0 a0, version, type, body length (big-endian words)


class ODBST(Structure):
    _fields_ = [(n, c_int16) for n in ("hdck", "tmmode", "aut", "run", "motion",
                                        "mstb", "emergency", "alarm", "edit")]


def read_frame(sock: socket.socket, buf: bytearray) -> bytes:
    """One whole frame from `sock` (header, then its body)."""
    view = memoryview(buf)
    got = 0
    while got < HEADER:
        n = sock.recv_into(view[got:])
        if n == 0:
            raise ConnectionError("closed")
        got += n
    need = HEADER + int.from_bytes(buf[8:10], "big")
    while got < need:
        n = sock.recv_into(view[got:])
        if n == 0:
            raise ConnectionError("closed")
        got += n
    return bytes(buf[:need])


class Relay:
    """A loopback relay that keeps the frames each client connection sent,
    to capture the library's own open and status request frames."""

    def __init__(self, target):
        self.target = target
        self.server = socket.create_server(("127.0.0.1", 0))
        self.port = self.server.getsockname()[1]
        self.sent = []  # per connection: the frames the client sent
        self.lock = threading.Lock()
        self.threads = []
        threading.Thread(target=self._accept, daemon=True).start()

    def _accept(self):
        while True:
            try:
                client, _ = self.server.accept()
            except OSError:
                return
            up = socket.create_connection(self.target)
            frames = []
            with self.lock:
                self.sent.append(frames)
            for a, b, keep in ((client, up, frames), (up, client, None)):
                t = threading.Thread(target=self._pump, args=(a, b, keep), daemon=True)
                t.start()
                self.threads.append(t)

    @staticmethod
    def _pump(src, dst, keep):
        buf = bytearray(1 << 16)
        try:
            while True:
                f = read_frame(src, buf)
                if keep is not None:
                    keep.append(f)
                dst.sendall(f)
        except OSError:
            pass
        finally:
            for s in (src, dst):
                try:
                    s.shutdown(socket.SHUT_RDWR)
                except OSError:
                    pass

    def close(self):
        self.server.close()


def capture(host, port):
    """(open frame, status request frame) the library sends, on one connection."""
    relay = Relay((host, port))
    cnc = fwlib32.Cnc("127.0.0.1", relay.port, timeout=10)
    with relay.lock:
        before = [len(f) for f in relay.sent]
    cnc.status()
    with relay.lock:
        after = [list(f) for f in relay.sent]
    cnc.close()
    relay.close()
    for i, frames in enumerate(after):
        new = frames[before[i] if i < len(before) else 0:]
        if new:
            assert len(new) == 1, "cnc_statinfo sent more than one frame"
            return frames[0], new[0]
    raise RuntimeError("no status frame captured")


def timed(fn, calls):
    start = time.perf_counter()
    for _ in range(calls):
        fn()
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--calls", type=int, default=1000)
    ap.add_argument("--rounds", type=int, default=15)
    args = ap.parse_args()

    with simulator() as sim:
        open_frame, status_frame = capture(sim.host, sim.port)

        # The floor: our own session, the captured frames.
        sock = socket.create_connection((sim.host, sim.port))
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        buf = bytearray(1 << 16)
        sock.sendall(open_frame)
        read_frame(sock, buf)

        def floor():
            sock.sendall(status_frame)
            read_frame(sock, buf)

        # Raw ctypes, as legacy code declares it.
        lib = ctypes.CDLL(fwlib32.library_path())
        lib.cnc_allclibhndl3.argtypes = [c_char_p, c_uint16, c_long, POINTER(c_uint16)]
        lib.cnc_statinfo.argtypes = [c_uint16, POINTER(ODBST)]
        lib.cnc_allclibhndl3.restype = lib.cnc_statinfo.restype = c_int16
        h = c_uint16(0)
        assert lib.cnc_allclibhndl3(sim.host.encode(), sim.port, 10, byref(h)) == 0
        statinfo = lib.cnc_statinfo

        def raw():
            st = ODBST()
            if statinfo(h, byref(st)) != 0:
                raise RuntimeError("cnc_statinfo failed")

        cnc = fwlib32.Cnc(sim.host, sim.port, timeout=10)
        assert cnc.status().mode == fwlib32.Mode.MEM

        names = ["typed", "ctypes", "floor"]
        fns = {"typed": cnc.status, "ctypes": raw, "floor": floor}
        results = {k: [] for k in names}
        for name in names:  # warm up
            timed(fns[name], 50)
        for r in range(args.rounds):
            # The order turns each round: no one goes first every time.
            for name in names[r % 3:] + names[:r % 3]:
                results[name].append(timed(fns[name], args.calls))
        cnc.close()
        lib.cnc_freelibhndl(h)
        sock.close()

    def ratio(a, b):
        # The median of the rounds' own ratios: each compares runs made
        # moments apart, so a load that comes and goes cancels out.
        return statistics.median(x / y for x, y in zip(results[a], results[b]))

    med = {k: statistics.median(v) for k, v in results.items()}
    print(f"status read {args.calls} times, median of {args.rounds} rounds "
          f"(Python {sys.version.split()[0]}):")
    for k in names:
        print(f"  {k:7s} {med[k] * 1e3:8.1f} ms  {med[k] / args.calls * 1e6:7.1f} us/call")
    print(f"  typed / ctypes = {ratio('typed', 'ctypes'):.3f}")
    print(f"  ctypes / floor = {ratio('ctypes', 'floor'):.3f}")
    print(f"  typed / floor  = {ratio('typed', 'floor'):.3f}")


if __name__ == "__main__":
    main()
