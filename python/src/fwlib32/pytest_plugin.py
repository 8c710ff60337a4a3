"""pytest fixtures over fwlib32.testing, registered by the package's
`pytest11` entry point:

    def test_parts(focas_sim):
        with fwlib32.Cnc(focas_sim.host, focas_sim.port) as cnc:
            assert cnc.param(6711) == 1234

focas_sim: one simulator with the built-in profile, for the test.
focas_sim_factory: a function taking simulator()'s arguments, each
simulator it starts stopped after the test.
"""

from __future__ import annotations

from typing import Any, Callable, Iterator, List

import pytest

from .testing import Simulator, start


@pytest.fixture
def focas_sim() -> Iterator[Simulator]:
    """A focas-sim with the built-in profile on a free loopback port."""
    sim = start()
    try:
        yield sim
    finally:
        sim.stop()


@pytest.fixture
def focas_sim_factory() -> Iterator[Callable[..., Simulator]]:
    """Starts simulators (arguments of fwlib32.testing.simulator); all are
    stopped when the test ends."""
    started: List[Simulator] = []

    def make(*args: Any, **kwargs: Any) -> Simulator:
        sim = start(*args, **kwargs)
        started.append(sim)
        return sim

    try:
        yield make
    finally:
        for sim in started:
            sim.stop()
