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

Answers are columns (:class:`BatchAnswers`): one NumPy array per numeric field of a batch
answer (``q`` in wire order, rad or m; errors in m and rad; counts; the solve time in ms;
``success`` and a ``status`` code) and, for the few targets that have them, ``reason`` and
``detail`` by index. The columns can live in any buffer (:meth:`BatchAnswers.on_buffer`), so
a worker process writes its chunk's answers straight into memory shared with the caller
instead of building, pickling and unpickling one object per target. A column holds exactly
the value of the solver's answer (float64, int64), so an answer read from the columns is
the single solve's, bit for bit.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import get_args

import numpy as np
import pinocchio as pin

from app.kinematics import ik
from app.kinematics.collision import collision_filter
from app.kinematics.ik.problem import IKOptions, Status
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


#: The statuses of an answer, by their code in :attr:`BatchAnswers.status`.
STATUSES: tuple[Status, ...] = get_args(Status)
_STATUS_CODE = {s: i for i, s in enumerate(STATUSES)}
#: The float64 columns of one value per target (after ``q``, which has one per joint).
FLOAT_COLUMNS = ("position_error", "orientation_error", "solve_time_ms")
#: The int64 columns.
INT_COLUMNS = ("iterations", "restarts")
#: The one-byte columns: ``success`` (bool) and ``status`` (code into :data:`STATUSES`).
BYTE_COLUMNS = ("success", "status")


class BatchAnswers:
    """The answers of a batch (or of a worker's rows of it) as columns, row ``i`` for
    target ``i`` of the batch.

    Attributes
    ----------
    q
        (n, dof) best configurations, wire order (rad or m).
    position_error, orientation_error
        (n,) errors of ``q`` against the target (m, rad).
    solve_time_ms
        (n,) each target's solve time (ms).
    iterations, restarts
        (n,) int64 counts of :class:`~app.kinematics.ik.IKResult`.
    success
        (n,) bool.
    status
        (n,) int8, the index of the status in :data:`STATUSES`.
    notes
        Row → (``reason``, ``detail``) of the rows where either is not None (failures);
        plain data, not in the buffer.
    """

    __slots__ = ("q", *FLOAT_COLUMNS, *INT_COLUMNS, *BYTE_COLUMNS, "notes")

    q: np.ndarray
    position_error: np.ndarray
    orientation_error: np.ndarray
    solve_time_ms: np.ndarray
    iterations: np.ndarray
    restarts: np.ndarray
    success: np.ndarray
    status: np.ndarray
    notes: dict[int, tuple[str | None, str | None]]

    def __init__(self, columns: dict[str, np.ndarray]) -> None:
        for name, column in columns.items():
            setattr(self, name, column)
        self.notes = {}

    @staticmethod
    def nbytes(n: int, dof: int) -> int:
        """Bytes of the buffer of :meth:`on_buffer`: ``n`` targets (4 × 4 float64 each)
        and their answers, ``dof`` joints."""
        return n * (8 * (16 + dof + len(FLOAT_COLUMNS) + len(INT_COLUMNS)) + len(BYTE_COLUMNS))

    @classmethod
    def on_buffer(cls, buffer: memoryview, n: int, dof: int) -> tuple[np.ndarray, BatchAnswers]:
        """Views on ``buffer`` (at least :meth:`nbytes` long): the (n, 4, 4) float64 target
        matrices (root frame, m) and the answer columns, laid out one after the other in
        this order: targets, ``q``, :data:`FLOAT_COLUMNS`, :data:`INT_COLUMNS`,
        :data:`BYTE_COLUMNS` (every column 8-byte aligned but the last ones). Two processes
        that map the same memory see the same arrays."""
        offset = 0

        def take(dtype: type, count: int, shape: tuple[int, ...]) -> np.ndarray:
            nonlocal offset
            view = np.frombuffer(buffer, dtype=dtype, count=count, offset=offset)
            offset += view.nbytes
            return view.reshape(shape)

        targets = take(np.float64, 16 * n, (n, 4, 4))
        columns = {"q": take(np.float64, n * dof, (n, dof))}
        for name in FLOAT_COLUMNS:
            columns[name] = take(np.float64, n, (n,))
        for name in INT_COLUMNS:
            columns[name] = take(np.int64, n, (n,))
        columns["success"] = take(np.bool_, n, (n,))
        columns["status"] = take(np.int8, n, (n,))
        return targets, cls(columns)

    @classmethod
    def allocate(cls, n: int, dof: int) -> BatchAnswers:
        """Columns of ``n`` answers in this process's own memory (zeros)."""
        return cls.on_buffer(memoryview(bytearray(cls.nbytes(n, dof))), n, dof)[1]

    def copy(self) -> BatchAnswers:
        """The same answers in this process's own memory (no view on the buffer left)."""
        out = BatchAnswers({k: getattr(self, k).copy() for k in self.__slots__[:-1]})
        out.notes = dict(self.notes)
        return out

    def __len__(self) -> int:
        return len(self.success)

    @property
    def solved(self) -> int:
        """How many targets were solved."""
        return int(np.count_nonzero(self.success))

    def put(self, i: int, res: ik.IKResult) -> None:
        """Write ``res`` as row ``i`` (its value exactly)."""
        self.q[i] = res.q
        self.position_error[i] = res.position_error
        self.orientation_error[i] = res.orientation_error
        self.solve_time_ms[i] = res.solve_time_ms
        self.iterations[i] = res.iterations
        self.restarts[i] = res.restarts
        self.success[i] = res.success
        self.status[i] = _STATUS_CODE[res.status]
        if res.reason is not None or res.detail is not None:
            self.notes[i] = (res.reason, res.detail)

    def statuses(self) -> list[Status]:
        """The status of every row."""
        return [STATUSES[c] for c in self.status.tolist()]


def solve_into(
    robot: RobotModel,
    targets: Sequence[pin.SE3],
    task: BatchTask,
    out: BatchAnswers,
    *,
    start: int = 0,
    cancel: threading.Event | None = None,
    record: Callable[[bool], None] | None = None,
) -> None:
    """Solve each target from ``task.seed`` in this thread; target ``i`` is target
    ``start + i`` of its batch (it picks the generator, :func:`target_rng`) and its answer
    is row ``start + i`` of ``out``. ``record`` is called with each outcome as it comes."""
    accept = collision_accept(robot, task.collisions)
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
        out.put(start + i, res)


def solve_targets(
    robot: RobotModel,
    targets: Sequence[pin.SE3],
    task: BatchTask,
    *,
    cancel: threading.Event | None = None,
    record: Callable[[bool], None] | None = None,
) -> BatchAnswers:
    """Every target of a batch solved from ``task.seed`` in this thread (:func:`solve_into`),
    as columns in this process's memory; the API writes their wire form."""
    out = BatchAnswers.allocate(len(targets), len(robot.joint_names))
    solve_into(robot, targets, task, out, cancel=cancel, record=record)
    return out
