"""The bundled programs (fwlib32/bin/focas-sim, fwlib32/bin/focas) and the
console entry points that run them."""

from __future__ import annotations

import os
import sys
from typing import List, NoReturn, Optional

_NAMES = ("focas-sim", "focas")


def path(name: str) -> str:
    """The path of bundled program `name` ("focas-sim" or "focas")."""
    if name not in _NAMES:
        raise ValueError(f"no bundled program {name!r} (focas-sim, focas)")
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin", name)


def run(name: str, args: Optional[List[str]] = None) -> NoReturn:
    """Replaces this process with bundled program `name` and `args`
    (default: this process's arguments)."""
    args = sys.argv[1:] if args is None else args
    exe = path(name)
    sys.stdout.flush()
    sys.stderr.flush()
    os.execv(exe, [name, *args])


def focas() -> NoReturn:
    """The `focas` command: the bundled command-line client."""
    run("focas")


def focas_sim() -> NoReturn:
    """The `focas-sim` command: the bundled CNC simulator."""
    run("focas-sim")
