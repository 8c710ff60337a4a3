#!/usr/bin/env python3
"""Runs a wheel's own focas-sim and focas against each other (CI, .ci/run,
for a wheel of another architecture, under its runner):

    python run_programs.py WHEEL [RUNNER ...]      e.g. qemu-aarch64 -L /

The simulator listens on 127.0.0.1:0; `focas --json` reads its status and
parameter 6711 (the built-in profile's 1234); the simulator is killed by
its PID at the end. Exit status 0 when every answer is right.
"""

import json
import os
import select
import signal
import subprocess
import sys
import tempfile
import zipfile


def main() -> int:
    wheel, runner = sys.argv[1], sys.argv[2:]
    with tempfile.TemporaryDirectory() as tmp:
        with zipfile.ZipFile(wheel) as z:
            for name in ("focas-sim", "focas"):
                dest = os.path.join(tmp, name)
                with open(dest, "wb") as f:
                    f.write(z.read(f"fwlib32/bin/{name}"))
                os.chmod(dest, 0o755)
        sim = subprocess.Popen([*runner, os.path.join(tmp, "focas-sim"), "--listen",
                                "127.0.0.1:0"], stdout=subprocess.PIPE, stdin=subprocess.DEVNULL)
        try:
            assert sim.stdout is not None
            if not select.select([sim.stdout], [], [], 120)[0]:
                print("run_programs: focas-sim printed nothing in 120 s", file=sys.stderr)
                return 1
            line = sim.stdout.readline().decode().strip()
            if not line.startswith("listening on "):
                print(f"run_programs: focas-sim printed {line!r}", file=sys.stderr)
                return 1
            port = line.rsplit(":", 1)[1]
            focas = [*runner, os.path.join(tmp, "focas"), "--host", "127.0.0.1", "--port", port,
                     "--json"]
            def focas_json(*args: str):
                out = subprocess.run(focas + list(args), check=True, capture_output=True,
                                     text=True, timeout=120).stdout
                return json.loads(out)
            st, parts = focas_json("status"), focas_json("param", "6711")
            ok = st["mode"]["name"] == "MEM" and parts["values"] == [1234]
            print(f"run_programs: {os.path.basename(wheel)}: focas-sim and focas ran "
                  f"({' '.join(runner) or 'natively'}): mode {st['mode']['name']}, "
                  f"param 6711 {parts['values']}: {'ok' if ok else 'WRONG'}")
            return 0 if ok else 1
        finally:
            os.kill(sim.pid, signal.SIGKILL)
            sim.wait()


if __name__ == "__main__":
    sys.exit(main())
