"""What this machine itself gives two processes: no pool, no IPC, no shared memory.

Printed by ``python -m bench batch`` beside the pool's speed-up, so that a pool short of
its target can be told from a machine that cannot reach it:

- **solver**: the batch's own loop (:func:`~app.kinematics.ik.batch.solve_targets`, the
  function a pool worker runs) over the pool's targets, in two independent processes
  started together, each with half the targets, its own robot and a warmed chain, against
  one process doing them all; wall time from the first start to the last end
  (``time.perf_counter``: CLOCK_MONOTONIC, one clock for every process);
- **compiled, 1 chain**: a Numba loop of one dependent floating-point recurrence held in
  registers (no memory traffic: what the cores scale when each is bound by its own
  latency), two units of work in one process against one unit in each of two;
- **compiled, 8 chains**: the same with eight independent recurrences interleaved, the
  same number of steps each (throughput-bound: two vCPUs that are hyperthreads of one
  physical core share its floating-point units and scale well below 2×, two real cores do
  not).

Each also with its CPU ratio, 2 × the CPU seconds of one process / the CPU seconds of the
two (``time.process_time`` in each): the speed-up two otherwise idle cores would give; on a
busy machine the wall times follow the other work's time slices, the CPU ratio much less
(it still moves with shared caches and hyperthread siblings).

The processes are started once (``spawn``: nothing inherited) and kept for every round;
rounds alternate one process and two, so that load from elsewhere hits both alike.
"""

from __future__ import annotations

import multiprocessing
import time
from typing import Any

import numpy as np

#: Iterations of one unit of the compiled loops (~0.2–0.4 s on the 2-core machine).
SPIN_ITERATIONS = 100_000_000


def _spin_kernels() -> tuple[Any, Any]:
    """The two compiled loops (compiled in the calling process, not cached)."""
    from numba import njit

    @njit(cache=False)
    def one_chain(n: int) -> float:
        x = 0.5
        for _ in range(n):
            x = x * 0.999999 + 1e-7
        return x

    @njit(cache=False)
    def eight_chains(n: int) -> float:
        a = b = c = d = e = f = g = h = 0.5
        for _ in range(n):
            a = a * 0.999999 + 1e-7
            b = b * 0.999998 + 2e-7
            c = c * 0.999997 + 3e-7
            d = d * 0.999996 + 4e-7
            e = e * 0.999995 + 5e-7
            f = f * 0.999994 + 6e-7
            g = g * 0.999993 + 7e-7
            h = h * 0.999992 + 8e-7
        return a + b + c + d + e + f + g + h

    one_chain(10)
    eight_chains(10)
    return one_chain, eight_chains


def _child(robots: dict[str, tuple[str, int]], commands: Any, results: Any) -> None:
    """A process of its own: build each robot and its targets, warm the solver on them,
    compile the loops, say ready, then run what it is told, reporting (start, end)."""
    from app.kinematics.ik.batch import BatchTask, solve_targets
    from app.kinematics.ik.problem import IKOptions
    from app.kinematics.ik.warmup import warm_up
    from app.robots.registry import Registry
    from bench.bench_ik import BUDGET_MS, targets

    warm_up()
    reg = Registry()
    work = {}
    for rid, (frame, n) in robots.items():
        robot = reg.get(rid)
        goals = targets(robot, frame, n, seed=21)
        task = BatchTask(robot.mid_range(), IKOptions(frame=frame, timeout_ms=BUDGET_MS))
        solve_targets(robot, goals[:200], task)  # chain built, kernels and caches warm
        work[rid] = (robot, goals, task)
    kernels = dict(zip(("compiled, 1 chain", "compiled, 8 chains"), _spin_kernels(), strict=True))
    results.put("ready")
    while True:
        command = commands.get()
        if command is None:
            return
        what, a, b = command
        c0, t0 = time.process_time(), time.perf_counter()
        if what in kernels:
            kernels[what]((b - a) * SPIN_ITERATIONS)
        else:
            robot, goals, task = work[what]
            solve_targets(robot, goals[a:b], task)
        results.put((t0, time.perf_counter(), time.process_time() - c0))


def ceilings(
    robots: dict[str, tuple[str, int]], rounds: int
) -> list[tuple[str, float, float, float]]:
    """Rows (work, median wall s of 1 process, of 2 processes, median CPU ratio) for each
    robot's solver loop (``robots``: id → (frame, targets)) and the two compiled loops."""
    ctx = multiprocessing.get_context("spawn")
    procs, queues = [], []
    results = ctx.Queue()
    try:
        for _ in range(3):  # one alone, two together
            q = ctx.Queue()
            p = ctx.Process(target=_child, args=(robots, q, results), daemon=True)
            p.start()
            procs.append(p)
            queues.append(q)
        for _ in procs:
            if results.get(timeout=600) != "ready":
                raise RuntimeError("a ceiling process failed to start")
        works = [*((rid, n) for rid, (_, n) in robots.items())]
        works += [("compiled, 1 chain", 2), ("compiled, 8 chains", 2)]
        rows = []
        for what, n in works:
            walls: dict[int, list[float]] = {1: [], 2: []}
            cpu: list[float] = []
            for _ in range(rounds):
                queues[0].put((what, 0, n))
                alone = results.get(timeout=600)
                walls[1].append(_wall([alone]))
                half = n // 2
                queues[1].put((what, 0, half))
                queues[2].put((what, half, n))
                pair = [results.get(timeout=600) for _ in range(2)]
                walls[2].append(_wall(pair))
                cpu.append(2 * alone[2] / (pair[0][2] + pair[1][2]))
            rows.append(
                (
                    what,
                    float(np.median(walls[1])),
                    float(np.median(walls[2])),
                    float(np.median(cpu)),
                )
            )
        return rows
    finally:
        for q in queues:
            q.put(None)
        for p in procs:
            p.join(timeout=30)
            if p.is_alive():
                p.kill()


def _wall(reports: list[tuple[float, float, float]]) -> float:
    """From the first start to the last end (s)."""
    return max(r[1] for r in reports) - min(r[0] for r in reports)
