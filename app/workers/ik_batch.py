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

Determinism: a worker solves its chunk with :func:`~app.kinematics.ik.batch.solve_targets`,
target ``i`` with the generator of its index in the batch, so an answer never depends on the
number of processes or on the chunking (:mod:`app.kinematics.ik.batch`). Collision-aware
batches run in the pool too: obstacles are plain data, and each worker builds (and caches,
per robot) its own collision model.

Cancellation: the caller's ``cancel`` event is checked while waiting for each chunk; once
set, chunks not yet started are withdrawn and :class:`~app.kinematics.errors.Cancelled` is
raised (a chunk already running in a worker finishes it: at most :data:`CHUNK_BUDGET_MS` of
budget). A worker that dies (killed, out of memory) breaks the pool: the batch fails with
:class:`~app.kinematics.errors.UnavailableError` (503) and the next batch gets a fresh
pool. Workers end with the process that started them
(:func:`app.workers.procwatch.watch_parent`).

"""

from __future__ import annotations

import hashlib
import math
import multiprocessing
import multiprocessing.forkserver
import queue
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_COMPLETED, CancelledError, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.errors import Cancelled, UnavailableError
from app.kinematics.ik import IKResult
from app.kinematics.ik.batch import BatchTask, solve_targets
from app.kinematics.ik.warmup import warm_up
from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel
from app.workers.procwatch import kill_self, watch_parent

#: Most targets in one chunk (the unit of work of a worker process). Each chunk costs the
#: caller a round trip through the pool and its answers' unpickling; at 64 the caller's share
#: was ~20 % of a core, at 256 about half that (Panda, 4 000 targets).
CHUNK_MAX = 256
#: A chunk's total budget, targets × ``timeout_ms``, is kept under this (ms) when possible,
#: so that a cancelled batch frees its workers soon: a worst case, every target spending its
#: whole budget; a solved target takes ~0.1 ms, so a chunk usually ends within ~30 ms.
CHUNK_BUDGET_MS = 2000.0
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


def _worker_robot(recipe: RobotRecipe) -> RobotModel:
    robot = _ROBOTS.get(recipe.key)
    if robot is None:
        if len(_ROBOTS) >= _ROBOTS_MAX:
            _ROBOTS.pop(next(iter(_ROBOTS)))
        robot = _ROBOTS[recipe.key] = recipe.build()
    return robot


def _worker_chunk(
    recipe: RobotRecipe, matrices: np.ndarray, start: int, task: BatchTask
) -> list[IKResult]:
    """Targets ``start`` … of a batch (homogeneous matrices, root frame) in a worker."""
    robot = _worker_robot(recipe)
    targets = [pin.SE3(np.ascontiguousarray(T)) for T in matrices]
    return solve_targets(robot, targets, task, start=start)


def chunk_size(n: int, processes: int, timeout_ms: float) -> int:
    """Targets per chunk: about four chunks per process (load balance), at most
    :data:`CHUNK_MAX`, and a chunk's budget within :data:`CHUNK_BUDGET_MS` where possible."""
    size = min(CHUNK_MAX, math.ceil(n / (4 * processes)))
    return max(1, min(size, math.floor(CHUNK_BUDGET_MS / timeout_ms)))


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

    def solve(
        self,
        robot: RobotModel,
        targets: Sequence[pin.SE3],
        task: BatchTask,
        *,
        cancel: threading.Event | None = None,
        record: Callable[[bool], None] | None = None,
    ) -> list[IKResult]:
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
        size = chunk_size(n, self.processes, task.options.timeout_ms)
        matrices = np.array([T.homogeneous for T in targets])
        executor = self._pool()
        futures: list[Future] = []
        try:
            for a in range(0, n, size):
                futures.append(
                    executor.submit(_worker_chunk, recipe, matrices[a : a + size], a, task)
                )
            out: list[IKResult] = []
            for fut in futures:
                while True:
                    if cancel is not None and cancel.is_set():
                        raise Cancelled()
                    if fut.done():
                        break
                    wait([fut], timeout=POLL_S, return_when=FIRST_COMPLETED)
                part = fut.result()
                if record is not None:
                    for res in part:
                        record(res.success)
                out.extend(part)
            return out
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
            for fut in futures:
                fut.cancel()
