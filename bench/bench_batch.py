"""Batch IK across processes: targets per second with 1 and 2 worker processes.

What ``POST /robots/{id}/ik/batch`` with ``chain_seeds: false`` runs
(:class:`app.workers.ik_batch.BatchPool`): the same targets (TRAC-IK's protocol: uniform
within the limits, seed at mid-range, 5 ms per target) solved in the calling thread
(1 process) and by a warm pool of 2 worker processes, alternating round by round so that
load hits both alike; and, as the ceiling of the pool on this machine, the same two workers
given one chunk (half the targets) each, so that the pool's per-chunk overhead is gone and
only the machine's own scaling over two cores remains. Reported: targets/s (wall clock: the
work spans processes) per round, the best and the median round, and the speed-up of the
medians. Worth reading only with the machine otherwise idle: other work on the two cores
takes from the pool first.

Environment: ``DENAVIT_BENCH_BATCH_N`` (targets per robot, default 4000),
``DENAVIT_BENCH_BATCH_ROUNDS`` (rounds of each, default 3).
"""

from __future__ import annotations

import contextlib
import math
import os
import time
from collections.abc import Iterator

import numpy as np

from app.kinematics.ik.batch import BatchTask
from app.kinematics.ik.problem import IKOptions
from app.robots.registry import Registry
from app.workers import default_processes, ik_batch
from app.workers.ik_batch import BatchPool
from bench.bench_ik import BUDGET_MS, targets

#: The pool's own overhead apart: the same 2 workers given one chunk each (half the targets),
#: so that only the machine's scaling over two cores remains (its ceiling).
CEILING = "2, one chunk each"


@contextlib.contextmanager
def _one_chunk_per_process() -> Iterator[None]:
    saved = ik_batch.chunk_size
    ik_batch.chunk_size = lambda n, processes, timeout_ms: math.ceil(n / processes)
    try:
        yield
    finally:
        ik_batch.chunk_size = saved


def rates(n: int, rounds: int) -> list[tuple]:
    """Rows: robot, processes, targets/s of every round, solved."""
    reg = Registry()
    pools: dict[int | str, BatchPool] = {1: BatchPool(1), 2: BatchPool(2), CEILING: BatchPool(2)}
    rows = []
    try:
        for rid, frame in (("panda", "panda_link8"), ("ur5", "tool0")):
            robot = reg.get(rid)
            goals = targets(robot, frame, n, seed=21)
            task = BatchTask(robot.mid_range(), IKOptions(frame=frame, timeout_ms=BUDGET_MS))
            for pool in pools.values():  # warm: workers started, robot built, kernels loaded
                pool.solve(robot, goals[:200], task)
            speed: dict[int | str, list[float]] = {p: [] for p in pools}
            solved = dict.fromkeys(pools, 0)
            for _ in range(rounds):
                for p, pool in pools.items():
                    chunks = _one_chunk_per_process() if p == CEILING else contextlib.nullcontext()
                    with chunks:
                        t0 = time.perf_counter()
                        out = pool.solve(robot, goals, task)
                        speed[p].append(n / (time.perf_counter() - t0))
                    solved[p] = sum(r.success for r in out)
            for p in pools:
                rows.append((rid, p, speed[p], solved[p]))
    finally:
        for pool in pools.values():
            pool.shutdown()
    return rows


def main() -> None:
    n = int(os.environ.get("DENAVIT_BENCH_BATCH_N", "4000"))
    rounds = int(os.environ.get("DENAVIT_BENCH_BATCH_ROUNDS", "3"))
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(
        f"machine: {default_processes()} cores usable; load average {load:.1f} at start; "
        f"{n} targets per robot, 5 ms each, {rounds} alternating rounds"
    )
    print("\n| robot | processes | targets/s per round | best | median | solved "
          "| speed-up (medians) |")  # fmt: skip
    print("|---|---|---|---|---|---|---|")
    base: dict[str, float] = {}
    for rid, p, speed, solved in rates(n, rounds):
        med = float(np.median(speed))
        base.setdefault(rid, med)
        per_round = ", ".join(f"{s:.0f}" for s in speed)
        print(f"| {rid} | {p} | {per_round} | {max(speed):.0f} | {med:.0f} | {solved}/{n} "
              f"| {med / base[rid]:.2f}× |")  # fmt: skip
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"\nload average at the end: {load:.1f}")


if __name__ == "__main__":
    main()
