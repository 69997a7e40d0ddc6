"""Building a reachability map: sampling, the per-process builder and the process pool.

Joint space is sampled within the limits of the joints that move the frame (the others do
not change the frame's pose and stay at their neutral values); continuous joints over
[−π, π). ``random``: uniform samples, the block of :data:`BLOCK` samples starting at sample
s drawn from ``default_rng([seed, s])``, so a map depends on the seed only, not on the
number of processes. ``grid``: g = round(samples^(1/k)) values per joint, g^k samples in
all, end points included (a range that is a full turn [−π, π] leaves out the duplicate +π).
FK and the Jacobian are vectorised over a block in NumPy
(:class:`app.kinematics.chain.SerialChain`; chains with other joint kinds fall back to
Pinocchio in a loop). Chunks of :data:`CHUNK` samples are the unit of work: with
``processes`` > 1 (and enough samples, see :func:`build_map`) worker processes (forkserver;
each builds its own model from the URDF) take chunks from a queue, fold them into a partial
map of their own (``np.maximum.at``) and, when the queue is empty, send it to the parent,
which merges the partial maps by maximum; otherwise the chunks run in the calling thread.
Progress advances per chunk; a cancelled build stops within a chunk (in the calling thread)
or at once (worker processes are terminated). Worker processes die with the process that
started the build (:mod:`app.kinematics.procwatch`, :mod:`app.kinematics.forkserver_init`).
"""

from __future__ import annotations

import math
import multiprocessing
import os
import queue
import threading
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

from app.kinematics.analysis import yoshikawa_components
from app.kinematics.chain import chain_for
from app.kinematics.errors import InvalidInputError
from app.kinematics.models import RobotModel
from app.kinematics.procwatch import kill_self, set_parent_death_signal, watch_parent
from app.kinematics.reachability.bins import orientation_bin_from_rotation
from app.kinematics.reachability.spec import MapSpec, self_collision_check, voxel_index

#: Samples per chunk (one unit of work for a process; progress advances per chunk).
CHUNK = 32_768
#: Samples evaluated at once inside a chunk (small enough for the CPU caches); random
#: samples are drawn per block, so a map does not depend on CHUNK or the process count.
BLOCK = 2_048
UNREACHED = np.float32(-1.0)
#: Fewer samples than this per process and a build runs in the calling thread instead.
MIN_SAMPLES_PER_PROCESS = 1_000_000


def chunk_samples(spec: MapSpec, start: int, stop: int) -> np.ndarray:
    """Samples [start, stop) of the build (one column per chain joint). Random samples come
    in blocks of :data:`BLOCK`: the block starting at sample b is drawn from a generator
    seeded with (seed, b), so any range gives the samples the build used."""
    lo = np.asarray(spec.chain_lower)
    hi = np.asarray(spec.chain_upper)
    n = stop - start
    if spec.sampling == "random":
        first = start - start % BLOCK
        blocks = [
            np.random.default_rng([spec.seed, b]).random((BLOCK, lo.size))
            for b in range(first, stop, BLOCK)
        ]
        u = np.concatenate(blocks)[start - first : start - first + n]
        return lo + (hi - lo) * u
    g = spec.grid_per_joint
    cont = np.isclose(hi - lo, 2 * math.pi) & np.isclose(lo, -math.pi)
    idx = np.unravel_index(np.arange(start, stop), (g,) * lo.size)
    out = np.empty((n, lo.size))
    for j in range(lo.size):
        step = (hi[j] - lo[j]) / (g if cont[j] else g - 1)
        out[:, j] = lo[j] + step * idx[j]
    return out


class MapBuilder:
    """Computes the reached cells of sample ranges for one spec (one per process)."""

    def __init__(self, robot: RobotModel, spec: MapSpec) -> None:
        self.robot = robot
        self.spec = spec
        self.chain = chain_for(robot, spec.frame)
        self.rows = np.asarray(spec.rows, dtype=int)
        self.lower = np.asarray(spec.lower)
        self.shape = np.asarray(spec.shape, dtype=np.int64)
        self.collides: Callable[[np.ndarray], bool] | None = None
        if spec.self_collision != "ignore":
            make = self_collision_check()
            if make is None:
                raise InvalidInputError(
                    "self-collision checking is not available", "self_collision"
                )
            self.collides = make(robot, spec.self_collision)

    def cells(self, start: int, stop: int) -> tuple[np.ndarray, np.ndarray]:
        """Cell index and manipulability (float32) of each in-bounds sample of [start, stop).

        Cells may repeat: merging takes the maximum (``np.maximum.at``).
        """
        parts = [self._block(a, min(stop, a + BLOCK)) for a in range(start, stop, BLOCK)]
        if len(parts) == 1:
            return parts[0]
        return np.concatenate([c for c, _ in parts]), np.concatenate([w for _, w in parts])

    def _block(self, start: int, stop: int) -> tuple[np.ndarray, np.ndarray]:
        spec = self.spec
        Q = chunk_samples(spec, start, stop)
        if self.collides is not None:
            full = np.tile(self.robot.neutral(), (Q.shape[0], 1))
            full[:, spec.chain_wire] = Q
            keep = np.array([not self.collides(q) for q in full], dtype=bool)
            Q = Q[keep]
        if Q.shape[0] == 0:
            return np.empty(0, np.int64), np.empty(0, np.float32)
        Rt, P, J = self.chain.evaluate(Q)
        vox, ok = voxel_index(spec, self.lower, self.shape, P)
        w = yoshikawa_components(J[self.rows])
        cell = vox * spec.bins + orientation_bin_from_rotation(Rt, spec.orientation_divisions)
        return cell[ok], w[ok].astype(np.float32)


def _worker_main(
    robot_args: dict[str, Any], spec_args: dict[str, Any], tasks: Any, results: Any
) -> None:
    """A build process: take chunks from ``tasks`` until ``None``, fold them into a partial
    map of its own (max per cell), report each chunk's size, then send the partial map
    (reached cells and their values) and exit.

    It dies with the process that started the build (however that one ends, SIGKILL
    included) and with its forkserver: nothing else would end it once its queues are gone.
    """
    set_parent_death_signal()  # the forkserver (see app.kinematics.forkserver_init)
    watch_parent(kill_self)  # the process that started the build
    try:
        robot = RobotModel(**robot_args)
        spec = MapSpec(**spec_args)
        builder = MapBuilder(robot, spec)
        best = np.full(spec.cells, UNREACHED, dtype=np.float32)
        while (task := tasks.get()) is not None:
            a, b = task
            cells, vals = builder.cells(a, b)
            np.maximum.at(best, cells, vals)
            results.put(("n", b - a))
        idx = np.flatnonzero(best >= 0)
        results.put(("map", idx, best[idx]))
    except BaseException as exc:  # reported to the parent, which fails the build
        results.put(("error", f"{type(exc).__name__}: {exc}"))


@dataclass
class Progress:
    """Shared between a build and whoever watches it."""

    total: int
    done: int = 0
    started: float | None = None  # time.monotonic() when sampling began
    finished: float | None = None
    cancel: threading.Event = field(default_factory=threading.Event)

    def elapsed(self) -> float:
        """Seconds spent sampling so far (or in all, once finished)."""
        if self.started is None:
            return 0.0
        return (self.finished if self.finished is not None else time.monotonic()) - self.started

    def rate(self) -> float | None:
        """Samples per second so far."""
        dt = self.elapsed()
        return self.done / dt if self.done and dt > 0 else None

    def eta(self) -> float | None:
        """Seconds left at the current rate."""
        rate = self.rate()
        return (self.total - self.done) / rate if rate else None


class Cancelled(Exception):
    """The build was cancelled."""


def _chunks(total: int, size: int) -> list[tuple[int, int]]:
    return [(a, min(total, a + size)) for a in range(0, total, size)]


def build_map(
    robot: RobotModel,
    spec: MapSpec,
    progress: Progress | None = None,
    processes: int = 1,
    min_samples_per_process: int | None = None,
) -> np.ndarray:
    """The map's float32 grid (shape + (bins,)): best manipulability per cell, −1 unreached.

    Up to ``processes`` worker processes, but no more than one per
    ``min_samples_per_process`` samples (default :data:`MIN_SAMPLES_PER_PROCESS`, less with
    self-collision checks): starting a process costs up to about a second. Raises
    :class:`Cancelled` when ``progress.cancel`` is set (checked after every chunk, or
    every 0.1 s while worker processes run).
    """
    progress = progress or Progress(spec.samples)
    best = np.full(spec.cells, UNREACHED, dtype=np.float32)
    chunks = _chunks(spec.samples, CHUNK)
    progress.started = time.monotonic()

    def merge(n: int, cells: np.ndarray, vals: np.ndarray) -> None:
        np.maximum.at(best, cells, vals)
        progress.done += n

    if min_samples_per_process is None:
        min_samples_per_process = MIN_SAMPLES_PER_PROCESS
        if spec.self_collision != "ignore":
            min_samples_per_process //= 100
    processes = max(1, min(processes, len(chunks), spec.samples // max(1, min_samples_per_process)))
    if processes == 1:
        builder = MapBuilder(robot, spec)
        for a, b in chunks:
            if progress.cancel.is_set():
                raise Cancelled
            merge(b - a, *builder.cells(a, b))
    else:
        _build_in_processes(robot, spec, progress, processes, chunks, best)
    return best.reshape(*spec.shape, spec.bins)


def _build_in_processes(
    robot: RobotModel,
    spec: MapSpec,
    progress: Progress,
    processes: int,
    chunks: list[tuple[int, int]],
    best: np.ndarray,
) -> None:
    """Run the chunks over worker processes (:func:`_worker_main`) and merge their partial
    maps into ``best`` by maximum. Cancelling terminates the workers at once."""
    robot_args = {
        "robot_id": robot.id,
        "urdf_text": robot.urdf_text,
        "package_dirs": robot.package_dirs,
        "srdf_text": robot.srdf_text,
        "ee_frame": robot.ee_frame,
    }
    ctx = _context()
    tasks = ctx.Queue()
    results = ctx.Queue()
    for c in chunks:
        tasks.put(c)
    for _ in range(processes):
        tasks.put(None)
    workers = [
        ctx.Process(
            target=_worker_main,
            args=(robot_args, asdict(spec), tasks, results),
            name=f"reachability-{i}",
            daemon=True,
        )
        for i in range(processes)
    ]
    for w in workers:
        w.start()
    finished = 0
    try:
        while finished < processes:
            if progress.cancel.is_set():
                raise Cancelled
            try:
                msg = results.get(timeout=0.1)
            except queue.Empty:
                dead = [w for w in workers if not w.is_alive() and w.exitcode != 0]
                if dead:
                    raise RuntimeError(
                        f"build process {dead[0].name} died (exit code {dead[0].exitcode})"
                    ) from None
                continue
            if msg[0] == "n":
                progress.done += msg[1]
            elif msg[0] == "map":
                _, idx, vals = msg
                best[idx] = np.maximum(best[idx], vals)
                finished += 1
            else:
                raise RuntimeError(f"build process failed: {msg[1]}")
        for w in workers:
            w.join()
    finally:
        for w in workers:
            if w.is_alive():
                w.terminate()
        for w in workers:
            w.join(timeout=5)
        for q in (tasks, results):
            q.cancel_join_thread()
            q.close()


def _context() -> multiprocessing.context.BaseContext:
    """Forkserver: workers fork from a clean server process, never from this threaded one.
    The forkserver dies with the process that started it (``forkserver_init``)."""
    ctx = multiprocessing.get_context("forkserver")
    ctx.set_forkserver_preload(
        ["app.kinematics.forkserver_init", "app.kinematics.reachability.build"]
    )
    return ctx


def default_processes() -> int:
    """Worker processes for a build: every core this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover
        return os.cpu_count() or 1
