"""Batch IK across worker processes (the solving itself: :mod:`app.kinematics.ik.batch`).

A batch whose targets all start from the same seed (``chain_seeds: false``) is a set of
independent solves, so it can be spread over worker processes (the solve is mostly Python:
threads would share one core). :class:`BatchPool` (one per app, made by its lifespan,
:mod:`app.api.state`) keeps a warm :class:`~concurrent.futures.ProcessPoolExecutor`
(forkserver; made on first use) whose
workers rebuild each robot from what its :class:`~app.kinematics.models.RobotModel` was built
from (URDF text, package directories, SRDF, end effector; cached per robot id and a digest
of those, so a replaced robot is rebuilt) and solve chunks of consecutive targets; the
results are assembled in target order.

Determinism: a worker solves its chunk with :func:`~app.kinematics.ik.batch.solve_into`,
target ``i`` with the generator of its index in the batch, so an answer never depends on the
number of processes or on the chunking (:mod:`app.kinematics.ik.batch`). Collision-aware
batches run in the pool too: obstacles are plain data, and each worker builds (and caches,
per robot) its own collision model.

Shared arrays, not pickled answers: the caller puts the batch's target matrices, room for
its answer columns (:class:`~app.kinematics.ik.batch.BatchAnswers`) and the robot's pickled
recipe in one shared memory segment (:mod:`app.workers.shared_segment`, unlinked when the
batch ends, however it ends); a chunk is a range of rows plus the task, and a worker writes
its answers in place and returns only the rows' failure notes and its CPU time. Per target
this costs ~1.2 µs in the worker and ~1 µs in the caller (entries of the answer included),
where building, pickling and unpickling one answer object cost ~9–12 µs in the worker and
~7 µs in the caller (docs/benchmarks.md); the recipe (the robot's URDF text, ~15–20 kB) is
read by a worker only when it has not built that robot yet, instead of travelling with
every chunk.

Chunks by measured cost: the pool keeps each robot's (and frame's) solve time per target,
measured by the workers' CPU clocks (a moving average: the work's cost, whatever else the
machine runs), and cuts a batch into chunks of decreasing size (guided scheduling: each
about a ``processes``-th of what is left (:data:`GUIDE`), of :data:`CHUNK_MIN_MS` to
:data:`CHUNK_MAX_MS` of measured work), so that the chunks cost little to hand out and the
workers run out of work together.

Cancellation: the caller's ``cancel`` event is checked while waiting for each chunk; once
set, chunks not yet started are withdrawn and :class:`~app.kinematics.errors.Cancelled` is
raised (a chunk already running in a worker finishes it, writing to memory only that
worker still maps: at most :data:`CHUNK_BUDGET_MS` of budget, usually
:data:`CHUNK_MAX_MS`). A worker that dies (killed, out of memory) breaks the pool: the batch
fails with :class:`~app.kinematics.errors.UnavailableError` (503) and the next batch gets a
fresh pool. Workers end with the process that started them
(:func:`app.workers.procwatch.watch_parent`).

"""

from __future__ import annotations

import contextlib
import hashlib
import math
import mmap
import multiprocessing
import multiprocessing.forkserver
import pickle
import queue
import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_COMPLETED, CancelledError, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from multiprocessing import shared_memory

import numpy as np
import pinocchio as pin

from app.kinematics.errors import Cancelled, UnavailableError
from app.kinematics.ik.batch import BatchAnswers, BatchTask, solve_into, solve_targets
from app.kinematics.ik.warmup import warm_up
from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel
from app.workers import shared_segment
from app.workers.procwatch import kill_self, watch_parent

#: Most targets in one chunk (the unit of work of a worker process).
CHUNK_MAX = 1024
#: A chunk's total budget, targets × ``timeout_ms``, is kept under this (ms) when possible,
#: so that a cancelled batch frees its workers soon: a worst case, every target spending its
#: whole budget.
CHUNK_BUDGET_MS = 2000.0
#: Measured work (ms) of the largest chunk: what a cancelled batch's running chunk usually
#: still takes, and the grain of the first chunks.
CHUNK_MAX_MS = 50.0
#: Measured work (ms) of the smallest chunk: the last chunks, which even out the workers'
#: ends (a chunk costs the caller ~0.1–0.4 ms of CPU: submission, its round trip, waiting).
CHUNK_MIN_MS = 4.0
#: Guided scheduling's share: each chunk about ``1 / (GUIDE × processes)`` of the targets
#: left (the classic guided self-scheduling's 1; 2 made ~1/3 more chunks, each of them
#: ~0.3 ms of the caller's CPU and ~0.15 ms of a worker's, docs/benchmarks.md).
GUIDE = 1
#: Solve time per target (µs) assumed for a robot and frame not measured yet.
DEFAULT_COST_US = 100.0
#: Weight of a chunk's measurement in the moving average of the cost per target.
COST_WEIGHT = 0.3
#: Batches with fewer targets than this are solved in the calling thread (no process hop).
MIN_PARALLEL = 32
#: How often (s) the caller's cancel event is checked while waiting for a chunk.
POLL_S = 0.05


@dataclass(frozen=True)
class RobotRecipe:
    """What a worker needs to rebuild a robot; ``key`` (id and a digest of the rest) names
    the robot's version in the workers' caches."""

    robot_id: str
    urdf_text: str
    package_dirs: tuple[str, ...]
    srdf_text: str | None
    ee_frame: str | None
    key: str

    @classmethod
    def of(cls, robot: RobotModel) -> RobotRecipe:
        """The recipe of ``robot`` (computed once, kept in the model's lazy cache)."""
        return robot.lazy(RECIPE_KEY, cls._of)

    @classmethod
    def _of(cls, robot: RobotModel) -> RobotRecipe:
        """The recipe of ``robot``, computed."""
        h = hashlib.sha256()
        for part in (
            robot.urdf_text,
            "\0".join(robot.package_dirs),
            robot.srdf_text or "",
            robot.ee_frame or "",
        ):
            h.update(part.encode())
            h.update(b"\1")
        return cls(
            robot.id,
            robot.urdf_text,
            tuple(robot.package_dirs),
            robot.srdf_text,
            robot.ee_frame,
            f"{robot.id}:{h.hexdigest()}",
        )

    def build(self) -> RobotModel:
        return RobotModel(
            self.robot_id,
            self.urdf_text,
            package_dirs=self.package_dirs,
            srdf_text=self.srdf_text,
            ee_frame=self.ee_frame,
        )


#: Row → (reason, detail) of a batch's failures.
Notes = dict[int, tuple[str | None, str | None]]

#: The model's lazy-cache key of its batch recipe (:meth:`RobotRecipe.of`).
RECIPE_KEY: LazyKey[RobotRecipe] = LazyKey("ik_batch_recipe", RobotRecipe)


#: A worker's robots by recipe key (a replaced robot gets a new key; few robots are used).
_ROBOTS: dict[str, RobotModel] = {}
_ROBOTS_MAX = 16


def _worker_init() -> None:
    """A worker process ends with the process that started the pool, however that ends;
    it loads the compiled solver kernels before its first chunk."""
    watch_parent(kill_self, name="ik-batch-parent-watch")
    warm_up()


def _worker_robot(key: str, buffer: memoryview, recipe_at: int, recipe_len: int) -> RobotModel:
    """The robot of recipe ``key``: cached, or built from the recipe pickled at
    ``recipe_at`` in the batch's segment (sent once per batch, not once per chunk)."""
    robot = _ROBOTS.get(key)
    if robot is None:
        recipe = pickle.loads(buffer[recipe_at : recipe_at + recipe_len])
        if len(_ROBOTS) >= _ROBOTS_MAX:
            _ROBOTS.pop(next(iter(_ROBOTS)))
        robot = _ROBOTS[key] = recipe.build()
    return robot


#: What a chunk's rows need besides the task: segment name, targets in the batch, joints,
#: (offset, length) of the pickled recipe in the segment, recipe key, first and end row.
Rows = tuple[str, int, int, tuple[int, int], str, int, int]


#: The segment this worker keeps mapped between the chunks of one batch: (name, mapping).
_MAPPED: tuple[str, mmap.mmap] | None = None


def _worker_chunk(rows: Rows, task: BatchTask) -> tuple[Notes, float] | None:
    """Targets ``start`` … ``stop − 1`` of a batch of ``n`` in the shared ``segment``
    (:meth:`BatchAnswers.on_buffer`), solved in a worker, their answers written in place.
    Returns the rows' failure notes and the CPU seconds spent on them (this process's
    clock: the measured cost is the work's, whatever else the machine runs); None when the
    segment is gone (the batch was withdrawn before this chunk started).

    The worker keeps the batch's segment mapped from its first chunk to the first chunk of
    another batch (:func:`app.workers.shared_segment.still_there` checks, per chunk, that the
    caller has not unlinked it), instead of mapping and unmapping it for every chunk
    (~80 µs a chunk measured, docs/benchmarks.md); at most one batch's segment (unlinked by
    then: its memory is freed when the mapping goes) stays mapped in an idle worker."""
    global _MAPPED
    segment = rows[0]
    if _MAPPED is not None and _MAPPED[0] != segment:
        _drop_mapping()
    if _MAPPED is None:
        try:
            _MAPPED = (segment, shared_segment.map_segment(segment))
        except FileNotFoundError:
            return None
    elif not shared_segment.still_there(segment):
        _drop_mapping()
        return None
    return _solve_rows(memoryview(_MAPPED[1]), rows, task)


def _drop_mapping() -> None:
    """Unmap the kept segment (its views are gone: none outlives :func:`_solve_rows`)."""
    global _MAPPED
    if _MAPPED is not None:
        _, mapped = _MAPPED
        _MAPPED = None
        with contextlib.suppress(BufferError):  # a view still exported: freed when collected
            mapped.close()


def _solve_rows(buffer: memoryview, rows: Rows, task: BatchTask) -> tuple[Notes, float]:
    """:func:`_worker_chunk` on the mapped segment (no view on it outlives this call)."""
    t0 = time.process_time()
    _, n, dof, (recipe_at, recipe_len), key, start, stop = rows
    robot = _worker_robot(key, buffer, recipe_at, recipe_len)
    matrices, answers = BatchAnswers.on_buffer(buffer, n, dof)
    targets = [pin.SE3(T) for T in matrices[start:stop]]
    solve_into(robot, targets, task, answers, start=start)
    return answers.notes, time.process_time() - t0


def chunk_sizes(n: int, processes: int, cost_us: float, timeout_ms: float) -> list[int]:
    """Sizes of consecutive chunks of ``n`` targets, decreasing (guided scheduling): each
    about ``1 / (GUIDE × processes)`` of the targets left, between :data:`CHUNK_MIN_MS` and
    :data:`CHUNK_MAX_MS` of work at ``cost_us`` per target, at most :data:`CHUNK_MAX`
    targets and a budget within :data:`CHUNK_BUDGET_MS` where possible."""
    most = min(CHUNK_MAX, math.floor(CHUNK_MAX_MS * 1e3 / cost_us))
    most = max(1, min(most, math.floor(CHUNK_BUDGET_MS / timeout_ms)))
    least = min(math.ceil(CHUNK_MIN_MS * 1e3 / cost_us), math.ceil(n / processes))
    least = max(1, min(most, least))  # a small batch is still shared by the processes
    sizes = []
    left = n
    while left > 0:
        size = min(left, most, max(least, math.ceil(left / (GUIDE * processes))))
        if 2 * (left - size) < least and left <= most:  # no crumb after the last chunk
            size = left
        sizes.append(size)
        left -= size
    return sizes


_STARTER: queue.SimpleQueue[Future[None]] | None = None
_STARTER_LOCK = threading.Lock()


def _starter(requests: queue.SimpleQueue[Future[None]]) -> None:
    while True:
        done = requests.get()
        try:
            multiprocessing.forkserver.ensure_running()
        except BaseException as exc:  # noqa: BLE001 - handed to the caller
            done.set_exception(exc)
        else:
            done.set_result(None)


def ensure_forkserver() -> None:
    """Start this process's forkserver, if it is not running, from a thread that lives as
    long as the process.

    The forkserver dies with the *thread* that started it: :mod:`app.workers.forkserver_init`
    sets ``PR_SET_PDEATHSIG``, whose "parent" is the starting thread. Started by a thread of
    an app's compute pool (the thread that submits a batch), it would die when that app's
    lifespan stops its pool, and a later pool of the process (another app, a restarted
    lifespan) would find it gone.
    """
    global _STARTER
    with _STARTER_LOCK:
        if _STARTER is None:
            _STARTER = queue.SimpleQueue()
            threading.Thread(
                target=_starter, args=(_STARTER,), name="forkserver-starter", daemon=True
            ).start()
        requests = _STARTER
    done: Future[None] = Future()
    requests.put(done)
    done.result()


class BatchPool:
    """Worker processes for batch IK; ``processes`` = 1 solves in the calling thread."""

    def __init__(self, processes: int) -> None:
        if processes < 1:
            raise ValueError("processes must be at least 1")
        self.processes = processes
        self._executor: ProcessPoolExecutor | None = None
        self._lock = threading.Lock()
        #: Measured solve time per target (µs) by (recipe key, frame, collision-aware).
        self._cost: dict[tuple[str, str, bool], float] = {}
        #: Pickled recipes by key (put in each batch's segment for workers that lack one).
        self._pickled: dict[str, bytes] = {}

    def _pool(self) -> ProcessPoolExecutor:
        with self._lock:
            ctx = multiprocessing.get_context("forkserver")
            ctx.set_forkserver_preload(["app.workers.forkserver_init", "app.workers.ik_batch"])
            ensure_forkserver()  # the workers fork from it as they start, on submit
            if self._executor is None:
                self._executor = ProcessPoolExecutor(
                    self.processes, mp_context=ctx, initializer=_worker_init
                )
            return self._executor

    def _discard(self, executor: ProcessPoolExecutor) -> None:
        """Drop a broken pool: the next batch starts a fresh one."""
        with self._lock:
            if self._executor is executor:
                self._executor = None
        executor.shutdown(wait=False, cancel_futures=True)

    def shutdown(self) -> None:
        """Stop the workers: pending chunks are withdrawn, running ones finish (at most
        :data:`CHUNK_BUDGET_MS` of budget each) and the workers are joined."""
        with self._lock:
            executor, self._executor = self._executor, None
        if executor is not None:
            executor.shutdown(wait=True, cancel_futures=True)

    def cost_us(self, robot: RobotModel, task: BatchTask) -> float:
        """The measured solve time per target (µs) of ``task``'s kind on ``robot`` (a moving
        average over the workers' chunks; :data:`DEFAULT_COST_US` before any)."""
        return self._cost.get(self._cost_key(robot, task), DEFAULT_COST_US)

    @staticmethod
    def _cost_key(robot: RobotModel, task: BatchTask) -> tuple[str, str, bool]:
        return (RobotRecipe.of(robot).key, task.options.frame, task.collisions is not None)

    def _measured(self, key: tuple[str, str, bool], targets: int, seconds: float) -> None:
        """Fold one chunk's solve time into the cost per target of ``key``."""
        us = max(seconds * 1e6 / targets, 1.0)
        old = self._cost.get(key)
        self._cost[key] = us if old is None else old + COST_WEIGHT * (us - old)

    def solve(
        self,
        robot: RobotModel,
        targets: Sequence[pin.SE3],
        task: BatchTask,
        *,
        cancel: threading.Event | None = None,
        record: Callable[[bool], None] | None = None,
    ) -> BatchAnswers:
        """Every target solved from ``task.seed``, in order (as :func:`solve_targets`): in the
        workers when there are several and at least :data:`MIN_PARALLEL` targets, else here.

        Raises
        ------
        Cancelled
            ``cancel`` was set while the batch ran.
        UnavailableError
            A worker process died during the batch (field ``targets``).
        """
        n = len(targets)
        if self.processes == 1 or n < MIN_PARALLEL:
            return solve_targets(robot, targets, task, cancel=cancel, record=record)
        recipe = RobotRecipe.of(robot)
        pickled = self._pickled.get(recipe.key)
        if pickled is None:
            pickled = self._pickled[recipe.key] = pickle.dumps(recipe, pickle.HIGHEST_PROTOCOL)
            while len(self._pickled) > _ROBOTS_MAX:
                self._pickled.pop(next(iter(self._pickled)))
        at = BatchAnswers.nbytes(n, len(robot.joint_names))
        with shared_segment.create(at + len(pickled)) as segment:
            segment.buf[at : at + len(pickled)] = pickled
            rows = (segment.name, n, len(robot.joint_names), (at, len(pickled)), recipe.key)
            return self._solve_shared(robot, targets, task, segment, rows, cancel, record)

    def _solve_shared(
        self,
        robot: RobotModel,
        targets: Sequence[pin.SE3],
        task: BatchTask,
        segment: shared_memory.SharedMemory,
        rows: tuple[str, int, int, tuple[int, int], str],
        cancel: threading.Event | None,
        record: Callable[[bool], None] | None,
    ) -> BatchAnswers:
        """The batch through ``segment``: targets written, chunks run, answers copied out
        (no view on the segment outlives this call)."""
        matrices, answers = BatchAnswers.on_buffer(
            segment.buf, len(targets), len(robot.joint_names)
        )
        self._run(robot, rows, targets, matrices, answers, task, cancel, record)
        return answers.copy()

    def _run(
        self,
        robot: RobotModel,
        rows: tuple[str, int, int, tuple[int, int], str],
        targets: Sequence[pin.SE3],
        matrices: np.ndarray,
        answers: BatchAnswers,
        task: BatchTask,
        cancel: threading.Event | None,
        record: Callable[[bool], None] | None,
    ) -> None:
        """Hand the rows of ``answers`` (in the segment of ``rows``) out in chunks, wait for
        each in order and collect the rows' notes and timings. A chunk's targets are
        written into ``matrices`` just before it is submitted, so the workers solve the
        first chunks while the later ones are written (the writing, ~1 µs a target, is
        then no longer all before the first solve)."""
        n = len(answers)
        key = self._cost_key(robot, task)
        sizes = chunk_sizes(n, self.processes, self.cost_us(robot, task), task.options.timeout_ms)
        executor = self._pool()
        futures: list[tuple[int, int, Future]] = []
        try:
            start = 0
            for size in sizes:
                stop = start + size
                matrices[start:stop] = np.array([T.homogeneous for T in targets[start:stop]])
                try:
                    fut = executor.submit(_worker_chunk, (*rows, start, start + size), task)
                except BrokenProcessPool:
                    raise
                except RuntimeError:  # "cannot schedule new futures after shutdown"
                    raise CancelledError() from None
                futures.append((start, start + size, fut))
                start += size
            for start, stop, fut in futures:
                while True:
                    if cancel is not None and cancel.is_set():
                        raise Cancelled()
                    if fut.done():
                        break
                    wait([fut], timeout=POLL_S, return_when=FIRST_COMPLETED)
                done = fut.result()
                if done is None:  # the segment is there until this returns: never seen
                    raise UnavailableError("a batch IK worker lost the batch", "targets")
                notes, seconds = done
                answers.notes.update(notes)
                self._measured(key, stop - start, seconds)
                if record is not None:
                    for success in answers.success[start:stop].tolist():
                        record(success)
        except BrokenProcessPool:
            self._discard(executor)
            raise UnavailableError(
                "a batch IK worker process died during the batch; send it again",
                "targets",
            ) from None
        except CancelledError:  # the pool was shut down (application shutdown) meanwhile
            raise UnavailableError(
                "the batch IK workers were stopped during the batch; send it again", "targets"
            ) from None
        finally:
            for _, _, fut in futures:
                fut.cancel()
