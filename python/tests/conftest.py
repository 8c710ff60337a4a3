"""Fixtures of the fwlib32 package's own tests: the installed package (never
a source tree) against its bundled simulator serving data/machine.toml."""

from pathlib import Path
from typing import Iterator

import pytest

import fwlib32
from fwlib32 import Cnc
from fwlib32.testing import Simulator, simulator

DATA = Path(__file__).resolve().parent / "data"


@pytest.fixture(scope="session")
def machine() -> Iterator[Simulator]:
    """One simulator serving data/machine.toml for the session (tests that
    write restore what they change, or use their own simulator)."""
    with simulator(DATA / "machine.toml") as sim:
        yield sim


@pytest.fixture
def cnc(machine: Simulator) -> Iterator[Cnc]:
    """A connection to `machine`, closed after the test."""
    with Cnc(machine.host, machine.port, timeout=10) as c:
        yield c
