"""Reachability builds over worker processes (the building itself:
:mod:`app.kinematics.reachability.build`).

With ``processes`` > 1 (and enough samples, see :func:`build_map`) worker processes
(forkserver; each builds its own model from the URDF) take chunks from a queue, fold them
into a partial map of their own (``np.maximum.at``) and, when the queue is empty, send it to
the parent, which merges the partial maps by maximum; otherwise the chunks run in the
calling thread. A cancelled build stops at once (worker processes are terminated). Worker
processes die with the process that started the build (:mod:`app.workers.procwatch`,
:mod:`app.workers.forkserver_init`).
"""

from __future__ import annotations

import multiprocessing
import queue
import time
from dataclasses import asdict
from typing import Any

import numpy as np

from app.kinematics.errors import Cancelled
from app.kinematics.models import RobotModel
from app.kinematics.reachability import build as here
from app.kinematics.reachability.build import CHUNK, UNREACHED, MapBuilder, Progress, chunks
from app.kinematics.reachability.spec import MapSpec
from app.workers.procwatch import kill_self, set_parent_death_signal, watch_parent

#: Fewer samples than this per worker process are not worth the process's start-up.
MIN_SAMPLES_PER_PROCESS = 1_000_000


def _worker_main(
    robot_args: dict[str, Any], spec_args: dict[str, Any], tasks: Any, results: Any
) -> None:
    """A build process: take chunks from ``tasks`` until ``None``, fold them into a partial
    map of its own (max per cell), report each chunk's size, then send the partial map
    (reached cells and their values) and exit.

    It dies with the process that started the build (however that one ends, SIGKILL
    included) and with its forkserver: nothing else would end it once its queues are gone.
    """
    set_parent_death_signal()  # the forkserver (see app.workers.forkserver_init)
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
    :class:`~app.kinematics.errors.Cancelled` when ``progress.cancel`` is set (checked after
    every chunk, or every 0.1 s while worker processes run).
    """
    if min_samples_per_process is None:
        min_samples_per_process = MIN_SAMPLES_PER_PROCESS
        if spec.self_collision != "ignore":
            min_samples_per_process //= 100
    parts = chunks(spec.samples, CHUNK)
    processes = max(1, min(processes, len(parts), spec.samples // max(1, min_samples_per_process)))
    if processes == 1:
        return here.build_map(robot, spec, progress)
    progress = progress or Progress(spec.samples)
    best = np.full(spec.cells, UNREACHED, dtype=np.float32)
    progress.started = time.monotonic()
    _build_in_processes(robot, spec, progress, processes, parts, best)
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
    ctx.set_forkserver_preload(["app.workers.forkserver_init", "app.workers.map_build"])
    return ctx
