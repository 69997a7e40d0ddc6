"""Batch IK from one seed, in this thread: targets solved independently.

A batch whose targets all start from the same seed (``chain_seeds: false``) is a set of
independent solves; :func:`solve_targets` solves a run of them here, and
:mod:`app.workers.ik_batch` spreads runs over worker processes with the same function.

Determinism: an answer never depends on the number of processes or on the chunking. Each
target is solved from the same seed with the same options, and with a ``random_seed`` each
target has a generator of its own, ``default_rng(SeedSequence(random_seed,
spawn_key=(index,)))`` (the ``index``-th child of ``SeedSequence(random_seed).spawn``), in
this thread and in a worker alike. Without ``random_seed`` the restarts come from the
chain's fixed table, as for a single IK. Only the time budget (``timeout_ms``) can make two
runs differ, on a loaded machine; ``max_iterations`` with a generous budget does not.

Collision-aware batches are plain data too: obstacles travel to a worker, which builds (and
caches, per robot) its own collision model.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics import ik
from app.kinematics.collision import collision_filter
from app.kinematics.ik.problem import IKOptions
from app.kinematics.models import RobotModel
from app.kinematics.obstacles import Obstacle

#: (obstacles in the root frame, margin m, collision geometry ``mesh`` or ``convex``).
Collisions = tuple[tuple[Obstacle, ...], float, str]


@dataclass(frozen=True)
class BatchTask:
    """What every target of a batch shares: the seed (wire order), the options, the
    collisions to avoid and the ``random_seed`` of the per-target generators."""

    seed: np.ndarray
    options: IKOptions
    collisions: Collisions | None = None
    random_seed: int | None = None


def target_rng(random_seed: int | None, index: int) -> np.random.Generator | None:
    """Target ``index``'s restart generator: the ``index``-th child of
    ``SeedSequence(random_seed)`` (None without a seed: the chain's fixed restart table)."""
    if random_seed is None:
        return None
    return np.random.default_rng(np.random.SeedSequence(random_seed, spawn_key=(index,)))


def collision_accept(
    robot: RobotModel, collisions: Collisions | None
) -> Callable[[np.ndarray], bool] | None:
    """The collision-free predicate of collision-aware IK, or None without collisions."""
    if collisions is None:
        return None
    obstacles, margin, geometry = collisions
    return collision_filter(robot, obstacles, margin=margin, mode=geometry)


def solve_targets(
    robot: RobotModel,
    targets: Sequence[pin.SE3],
    task: BatchTask,
    *,
    start: int = 0,
    cancel: threading.Event | None = None,
    record: Callable[[bool], None] | None = None,
) -> list[ik.IKResult]:
    """Solve each target from ``task.seed`` in this thread; target ``i`` is target
    ``start + i`` of its batch (it picks the generator, :func:`target_rng`). ``record`` is
    called with each outcome as it comes. The results are plain data (they cross process
    boundaries, :mod:`app.workers.ik_batch`); the API writes their wire form."""
    accept = collision_accept(robot, task.collisions)
    out = []
    for i, T in enumerate(targets):
        res = ik.solve(
            robot,
            T,
            task.options,
            seed=task.seed,
            accept=accept,
            rng=target_rng(task.random_seed, start + i),
            cancel=cancel,
        )
        if record is not None:
            record(res.success)
        out.append(res)
    return out
