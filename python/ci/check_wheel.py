#!/usr/bin/env python3
"""Checks a built fwlib32 wheel (CI, .ci/run): it holds exactly the
package's own files (the Python modules, py.typed, our libfwlib32.so.1,
focas-sim, focas, and the wheel's metadata), so nothing of FANUC's (its
library, its header) can be in it; the library is ours (it exports the
fwlib_* extensions FANUC's lacks); the programs keep their executable bit.
Prints the wheel's size and its tag.

    python check_wheel.py dist/fwlib32-1.0.0-py3-none-linux_x86_64.whl
"""

import os
import re
import sys
import zipfile

ALLOWED = re.compile(
    r"^(fwlib32/[A-Za-z_]+\.py"
    r"|fwlib32/py\.typed"
    r"|fwlib32/libfwlib32\.so\.1"
    r"|fwlib32/bin/(focas-sim|focas)"
    r"|fwlib32-[0-9.]+\.dist-info/(METADATA|WHEEL|RECORD|entry_points\.txt|top_level\.txt"
    r"|licenses/.*|LICENSE.*))$")
NEEDED = {"fwlib32/__init__.py", "fwlib32/py.typed", "fwlib32/libfwlib32.so.1",
          "fwlib32/bin/focas-sim", "fwlib32/bin/focas"}


def main() -> int:
    path = sys.argv[1]
    bad = []
    with zipfile.ZipFile(path) as z:
        infos = z.infolist()
        names = {i.filename for i in infos}
        for i in infos:
            if not ALLOWED.match(i.filename):
                bad.append(f"not one of the package's files: {i.filename}")
            # FANUC's Windows DLLs, its header, and its Linux builds
            # (libfwlib32-<platform>.so.1.0.N): never ours.
            if re.search(r"fanuc|\.dll$|\.h$|fwlib(e1|e64|0dn|30i|64)|libfwlib32-[a-z0-9]|"
                         r"\.so\.1\.0\.", i.filename, re.I):
                bad.append(f"a FANUC name: {i.filename}")
        for n in sorted(NEEDED - names):
            bad.append(f"missing: {n}")
        if "fwlib32/libfwlib32.so.1" in names:
            lib = z.read("fwlib32/libfwlib32.so.1")
            if not lib.startswith(b"\x7fELF") or b"fwlib_batch_begin" not in lib:
                bad.append("fwlib32/libfwlib32.so.1 is not fwlib32-rs's library")
        for n in ("fwlib32/bin/focas-sim", "fwlib32/bin/focas", "fwlib32/libfwlib32.so.1"):
            if n in names and not (z.getinfo(n).external_attr >> 16) & 0o111:
                bad.append(f"not executable: {n}")
        sizes = {i.filename: (i.file_size, i.compress_size) for i in infos}
    for b in bad:
        print(f"check_wheel: {b}", file=sys.stderr)
    if bad:
        return 1
    print(f"wheel: {os.path.basename(path)}: {os.path.getsize(path)} bytes, {len(names)} files")
    for n in ("fwlib32/libfwlib32.so.1", "fwlib32/bin/focas-sim", "fwlib32/bin/focas"):
        size, packed = sizes[n]
        print(f"  {n}: {size} bytes ({packed} compressed)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
