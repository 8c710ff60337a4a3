"""8 threads polling 8 simulators at once (30i and 16i classes), each
through its own Cnc."""

import threading
import time
from decimal import Decimal

from fwlib32 import Cnc

PROFILE = """
[cnc]
class = "{cls}"
max_axes = 8
cnc_id = [1, 2, 3, {n}]
[[path]]
machine = "mill"
[[path.axis]]
name = "X"
decimals = 3
absolute = {n}000
[param]
[[param.parameter]]
number = 6711
kind = "2word"
values = [{n}]
"""

THREADS = 8
POLLS = 100


def test_eight_threads_poll_eight_simulators(focas_sim_factory):
    sims = [focas_sim_factory(profile_text=PROFILE.format(n=n, cls="30i" if n % 2 else "16i"))
            for n in range(1, THREADS + 1)]
    errors, counts = [], [0] * THREADS

    def poll(i: int) -> None:
        n = i + 1
        try:
            with Cnc(sims[i].host, sims[i].port, timeout=10) as cnc:
                for _ in range(POLLS):
                    assert cnc.param(6711) == n
                    if n % 2:  # cnc_rdposition: the 30i class
                        assert cnc.positions()[0].absolute == Decimal(n)
                    assert cnc.status().mode is not None
                    with cnc.batch() as b:
                        p, st = b.param(6711), b.status()
                    assert p.value == n and st.value == cnc.status()
                    counts[i] += 1
        except BaseException as e:  # reported by the main thread
            errors.append((n, e))

    threads = [threading.Thread(target=poll, args=(i,)) for i in range(THREADS)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    assert counts == [POLLS] * THREADS


def test_calls_wait_without_the_gil(focas_sim_factory):
    # Each simulator answers 300 ms late. Every thread notes when its call
    # starts and ends: had a call held the GIL while it waited, no other
    # thread could have started a call meanwhile, so no two intervals
    # could overlap. They all overlap one another.
    sims = [focas_sim_factory(args=["--delay-ms", "300"]) for _ in range(4)]
    cncs = [Cnc(s.host, s.port, timeout=10) for s in sims]
    spans = [(0.0, 0.0)] * len(cncs)
    barrier = threading.Barrier(len(cncs))

    def call(i: int) -> None:
        barrier.wait()
        start = time.monotonic()
        cncs[i].status()
        spans[i] = (start, time.monotonic())

    threads = [threading.Thread(target=call, args=(i,)) for i in range(len(cncs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for c in cncs:
        c.close()
    latest_start = max(s for s, _ in spans)
    earliest_end = min(e for _, e in spans)
    assert latest_start < earliest_end, spans
