"""Batch IK across worker processes (the solving itself: :mod:`app.kinematics.ik.batch`).

A batch whose targets all start from the same seed (``chain_seeds: false``) is a set of
independent solves, so it can be spread over worker processes (the solve is mostly Python:
threads would share one core). :class:`BatchPool` (one per app, made by its lifespan,
:mod:`app.api.state`) keeps a warm :class:`~concurrent.futures.ProcessPoolExecutor`
(forkserver; made on first use) whose workers (:mod:`app.workers.batch_worker`) rebuild
each robot from what its :class:`~app.kinematics.models.RobotModel` was built from (URDF
text, package directories, SRDF, end effector; cached per robot id and a digest of those, so
a replaced robot is rebuilt) and solve chunks of consecutive targets; the results are
assembled in target order.

Determinism: a worker solves a chunk with :func:`~app.kinematics.ik.batch.solve_into`,
target ``i`` with the generator of its index in the batch, so an answer never depends on the
number of processes or on the chunking (:mod:`app.kinematics.ik.batch`). Collision-aware
batches run in the pool too: obstacles are plain data, and each worker builds (and caches,
per robot) its own collision model.

Shared arrays, not pickled answers: the caller puts the batch's target matrices, room for
its answer columns (:class:`~app.kinematics.ik.batch.BatchAnswers`), the robot's pickled
recipe and the batch's control block (:mod:`app.workers.chunk_claims`) in one shared memory
segment (:mod:`app.workers.shared_segment`, unlinked when the batch ends, however it ends).
Workers write their answers in place and return only the rows' failure notes and their CPU
time; the recipe (the robot's URDF text, ~15–20 kB) is read by a worker only when it has not
built that robot yet.

Chunks claimed, not submitted: the caller submits one *drain* per worker
(:func:`~app.workers.batch_worker.drain_chunks`), which claims the next chunk from the
control block, solves it and claims again until none is left. Handing out a chunk then costs
a claim under a lock (a few µs) instead of a round trip through the executor (~0.3 ms of the
caller's CPU and ~0.15 ms of a worker's, measured before, docs/benchmarks.md), and chunks
still go to whichever worker is free first. The caller writes the targets chunk by chunk as
the first drains start (a drain that claims a chunk not yet written waits for it).

Chunks by measured cost: the pool keeps each robot's (and frame's) solve time per target,
measured by the workers' CPU clocks (a moving average over drains: the work's cost, whatever
else the machine runs; a drain that built the robot is not a measure), and cuts a batch into
chunks of decreasing size (guided scheduling: each about a ``GUIDE × processes``-th of what is
left (:data:`GUIDE`), of :data:`CHUNK_MIN_MS` to :data:`CHUNK_MAX_MS` of measured work), so
that the workers run out of work together.

Cancellation: the caller's ``cancel`` event is checked while it waits; once set, the batch is
withdrawn in its control block (no drain claims another chunk), the outcomes of the chunks
already solved are recorded and :class:`~app.kinematics.errors.Cancelled` is raised (a chunk
being solved in a worker is finished, writing to memory only that worker still maps: at most
:data:`CHUNK_BUDGET_MS` of budget, usually :data:`CHUNK_MAX_MS`). :meth:`BatchPool.shutdown`
withdraws every running batch the same way (they fail with a 503). A worker that dies
(killed, out of memory) breaks the pool: the batch fails with
:class:`~app.kinematics.errors.UnavailableError` (503) and the next batch gets a fresh pool.
Workers end with the process that started them (:func:`app.workers.procwatch.watch_parent`).
"""

from __future__ import annotations

import math
import multiprocessing
import multiprocessing.forkserver
import pickle
import queue
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_COMPLETED, CancelledError, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from multiprocessing import shared_memory

import numpy as np
import pinocchio as pin

from app.kinematics.errors import Cancelled, UnavailableError
from app.kinematics.ik.batch import BatchAnswers, BatchTask, solve_targets
from app.kinematics.models import RobotModel
from app.workers import shared_segment
from app.workers.batch_worker import (
    ROBOTS_MAX,
    Drained,
    RobotRecipe,
    Rows,
    worker_drain,
    worker_init,
)
from app.workers.chunk_claims import ControlBlock, Lock

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
#: ends (a chunk costs a claim under a lock, a few µs, :mod:`app.workers.chunk_claims`).
CHUNK_MIN_MS = 1.0
#: Guided scheduling's share: each chunk about ``1 / (GUIDE × processes)`` of the targets
#: left (the classic guided self-scheduling's 1). With chunks claimed from the batch's
#: control block, a chunk costs a few µs, so the smaller chunks of 2 buy a closer finish:
#: on 4000 UR5 targets 1.81× → 1.85× the calling thread (docs/benchmarks.md).
GUIDE = 2
#: Solve time per target (µs) assumed for a robot and frame not measured yet.
DEFAULT_COST_US = 100.0
#: Weight of a chunk's measurement in the moving average of the cost per target.
COST_WEIGHT = 0.3
#: Batches with fewer targets than this are solved in the calling thread (no process hop).
MIN_PARALLEL = 32
#: How often (s) the caller's cancel event is checked while waiting for a chunk.
POLL_S = 0.05


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
        #: The lock of the control blocks, shared with the executor's workers.
        self._claims: Lock | None = None
        self._lock = threading.Lock()
        #: Measured solve time per target (µs) by (recipe key, frame, collision-aware).
        self._cost: dict[tuple[str, str, bool], float] = {}
        #: Pickled recipes by key (put in each batch's segment for workers that lack one).
        self._pickled: dict[str, bytes] = {}
        #: The control blocks of the batches running now (withdrawn by :meth:`shutdown`).
        self._running: set[ControlBlock] = set()

    def _pool(self) -> ProcessPoolExecutor:
        return self._pool_and_claims()[0]

    def _pool_and_claims(self) -> tuple[ProcessPoolExecutor, Lock]:
        """The executor (started on first use) and the claim lock its workers were given."""
        with self._lock:
            ctx = multiprocessing.get_context("forkserver")
            ctx.set_forkserver_preload(
                ["app.workers.forkserver_init", "app.workers.ik_batch", "app.workers.batch_worker"]
            )
            ensure_forkserver()  # the workers fork from it as they start, on submit
            if self._executor is None or self._claims is None:
                self._claims = ctx.Lock()
                self._executor = ProcessPoolExecutor(
                    self.processes,
                    mp_context=ctx,
                    initializer=worker_init,
                    initargs=(self._claims,),
                )
            return self._executor, self._claims

    def _discard(self, executor: ProcessPoolExecutor) -> None:
        """Drop a broken pool: the next batch starts a fresh one."""
        with self._lock:
            if self._executor is executor:
                self._executor = self._claims = None
        executor.shutdown(wait=False, cancel_futures=True)

    def shutdown(self) -> None:
        """Stop the workers: running batches are withdrawn (their drains stop claiming
        chunks; a chunk being solved finishes, at most :data:`CHUNK_BUDGET_MS` of budget),
        drains not started are dropped and the workers are joined."""
        with self._lock:
            executor, self._executor, self._claims = self._executor, None, None
            for block in self._running:
                block.cancel()
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
            while len(self._pickled) > ROBOTS_MAX:
                self._pickled.pop(next(iter(self._pickled)))
        dof = len(robot.joint_names)
        sizes = chunk_sizes(n, self.processes, self.cost_us(robot, task), task.options.timeout_ms)
        drains = min(self.processes, len(sizes))
        at = BatchAnswers.nbytes(n, dof)
        block_at = -(-(at + len(pickled)) // 8) * 8
        size = block_at + ControlBlock.nbytes(len(sizes), drains)
        with shared_segment.create(size) as segment:
            segment.buf[at : at + len(pickled)] = pickled
            rows = (segment.name, n, dof, (at, len(pickled)), recipe.key, block_at, len(sizes),
                    drains)  # fmt: skip
            return self._solve_shared(robot, targets, task, segment, rows, sizes, cancel, record)

    def _solve_shared(
        self,
        robot: RobotModel,
        targets: Sequence[pin.SE3],
        task: BatchTask,
        segment: shared_memory.SharedMemory,
        rows: Rows,
        sizes: list[int],
        cancel: threading.Event | None,
        record: Callable[[bool], None] | None,
    ) -> BatchAnswers:
        """The batch through ``segment``: targets written, drains run, answers copied out
        (no view on the segment outlives this call)."""
        matrices, answers = BatchAnswers.on_buffer(
            segment.buf, len(targets), len(robot.joint_names)
        )
        executor, claims = self._pool_and_claims()
        block = ControlBlock(segment.buf, rows[5], rows[6], rows[7], claims)
        try:
            block.lay_out(sizes)
            try:
                self._run(robot, rows, targets, matrices, answers, block, executor, task, cancel)
            except Cancelled:
                if record is not None:  # the outcomes of the chunks solved before, in order
                    _, _, done = block.progress()
                    bounds = block.bounds().tolist()
                    for k in np.flatnonzero(done).tolist():
                        for success in answers.success[bounds[k] : bounds[k + 1]].tolist():
                            record(success)
                raise
            out = answers.copy()
        finally:
            block.release()
        if record is not None:
            for success in out.success.tolist():
                record(success)
        return out

    def _run(
        self,
        robot: RobotModel,
        rows: Rows,
        targets: Sequence[pin.SE3],
        matrices: np.ndarray,
        answers: BatchAnswers,
        block: ControlBlock,
        executor: ProcessPoolExecutor,
        task: BatchTask,
        cancel: threading.Event | None,
    ) -> None:
        """Write each chunk's targets into ``matrices`` and publish it, submitting the
        batch's drains as the first chunks are written (the workers solve them while the
        later ones are written: the writing, ~1 µs a target, is then no longer all before
        the first solve); wait until every row is solved and every drain that took work has
        answered, and collect their notes and timings."""
        n, chunks, drains = len(answers), rows[6], rows[7]
        bounds = block.bounds().tolist()
        futures: list[Future[Drained | None]] = []
        with self._lock:
            self._running.add(block)
        try:
            for k in range(chunks):
                a, b = bounds[k], bounds[k + 1]
                matrices[a:b] = np.array([T.homogeneous for T in targets[a:b]])
                block.publish(k + 1)
                if len(futures) < drains:
                    try:
                        futures.append(executor.submit(worker_drain, rows, len(futures), task))
                    except BrokenProcessPool:
                        raise
                    except RuntimeError:  # "cannot schedule new futures after shutdown"
                        raise CancelledError() from None
            key = self._cost_key(robot, task)
            for notes, seconds, count in self._collect(block, futures, n, cancel):
                answers.notes.update(notes)
                if count:
                    self._measured(key, count, seconds)
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
            with self._lock:
                self._running.discard(block)
            block.cancel()  # however it ends, no drain claims a chunk of it any more
            for fut in futures:
                fut.cancel()

    @staticmethod
    def _collect(
        block: ControlBlock,
        futures: list[Future[Drained | None]],
        n: int,
        cancel: threading.Event | None,
    ) -> list[Drained]:
        """Wait for the batch: every row solved and every drain that claimed work answered
        (a drain still queued behind another batch claims nothing once every chunk is
        claimed: it is not waited for); their answers. A dead worker raises
        ``BrokenProcessPool``; the pool stopping (drains ended with rows unsolved, or
        dropped) raises ``CancelledError``. (No view on the segment in this frame: an
        exception's frames may outlive the segment.)"""
        while True:
            if cancel is not None and cancel.is_set():
                raise Cancelled()
            solved, started, _ = block.progress()
            for fut in futures:
                if fut.done() and not fut.cancelled() and fut.exception() is not None:
                    raise fut.exception()  # type: ignore[misc]
            waiting = [
                f for i, f in enumerate(futures) if not f.done() and (started[i] or solved < n)
            ]
            if not waiting:
                break
            wait(waiting, timeout=POLL_S, return_when=FIRST_COMPLETED)
        if solved < n:  # every drain ended, rows unsolved: the batch was withdrawn
            raise CancelledError()
        out = []
        for i, fut in enumerate(futures):
            if started[i]:
                done = fut.result()
                if done is None:  # the segment is there until this returns: never seen
                    raise UnavailableError("a batch IK worker lost the batch", "targets")
                out.append(done)
        return out
