"""The worker side of batch IK across processes (:mod:`app.workers.ik_batch` is the caller's):
how a worker rebuilds a robot (:class:`RobotRecipe`, cached per recipe key), what it keeps
from the pool (the claim lock, :func:`worker_init`), and a batch's *drain*: chunks of rows
claimed from the batch's control block (:mod:`app.workers.chunk_claims`) and solved in place
in its shared segment (:func:`worker_drain`, :func:`drain_chunks`).
"""

from __future__ import annotations

import contextlib
import hashlib
import pickle
import time
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.ik.batch import BatchAnswers, BatchTask, solve_into
from app.kinematics.ik.warmup import warm_up
from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel
from app.workers import shared_segment
from app.workers.chunk_claims import ControlBlock, Lock
from app.workers.procwatch import kill_self, watch_parent


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
ROBOTS_MAX = 16


#: The lock of the batches' control blocks (:mod:`app.workers.chunk_claims`), shared with
#: the process that made the pool; given to each worker as it starts.
_CLAIMS: Lock | None = None


def worker_init(claims: Lock) -> None:
    """A worker process ends with the process that started the pool, however that ends;
    it keeps the pool's claim lock and loads the compiled solver kernels before its first
    drain."""
    global _CLAIMS
    _CLAIMS = claims
    watch_parent(kill_self, name="ik-batch-parent-watch")
    warm_up()


def _worker_robot(key: str, buffer: memoryview, recipe_at: int, recipe_len: int) -> RobotModel:
    """The robot of recipe ``key``: cached, or built from the recipe pickled at
    ``recipe_at`` in the batch's segment (sent once per batch, not once per chunk)."""
    robot = _ROBOTS.get(key)
    if robot is None:
        recipe = pickle.loads(buffer[recipe_at : recipe_at + recipe_len])
        if len(_ROBOTS) >= ROBOTS_MAX:
            _ROBOTS.pop(next(iter(_ROBOTS)))
        robot = _ROBOTS[key] = recipe.build()
    return robot


#: What a drain needs besides its index and the task: segment name, targets in the batch,
#: joints, (offset, length) of the pickled recipe in the segment, recipe key, offset of the
#: control block, chunks, drains.
Rows = tuple[str, int, int, tuple[int, int], str, int, int, int]

#: A drain's answer: the failure notes of its rows, the CPU seconds it spent (this process's
#: clock: the measured cost is the work's, whatever else the machine runs) and the rows
#: they were spent on (0 when the drain built the robot: not a measure of its solves).
Drained = tuple[Notes, float, int]


def worker_drain(rows: Rows, drain: int, task: BatchTask) -> Drained | None:
    """Drain ``drain`` of the batch in the shared segment ``rows[0]``, in a worker: chunks
    claimed and solved until none is left (:func:`drain_chunks`); None when the segment is
    gone (the batch ended before this drain started). The segment is mapped for the drain
    and unmapped after it."""
    try:
        mapped = shared_segment.map_segment(rows[0])
    except FileNotFoundError:
        return None
    try:
        return drain_chunks(memoryview(mapped), rows, drain, task, _CLAIMS)
    finally:
        with contextlib.suppress(BufferError):  # a view still exported: freed when collected
            mapped.close()


def drain_chunks(
    buffer: memoryview, rows: Rows, drain: int, task: BatchTask, claims: Lock | None
) -> Drained:
    """Claim the batch's next chunk from its control block, solve its targets
    (:func:`~app.kinematics.ik.batch.solve_into`, each with its row's generator), write
    their answers in place, mark the chunk done, and again, until every chunk is claimed or
    the batch is withdrawn. No view on ``buffer`` outlives this call."""
    t0 = time.process_time()
    _, n, dof, (recipe_at, recipe_len), key, block_at, chunks, drains = rows
    if claims is None:
        raise RuntimeError("a batch drain outside a pool worker needs the pool's claim lock")
    block = ControlBlock(buffer, block_at, chunks, drains, claims)
    try:
        if not block.start(drain):
            return {}, time.process_time() - t0, 0
        fresh = key not in _ROBOTS  # built now: its first solves build its chain's caches
        robot = _worker_robot(key, buffer, recipe_at, recipe_len)
        matrices, answers = BatchAnswers.on_buffer(buffer, n, dof)
        bounds = block.bounds()
        solved = 0
        while (k := block.claim()) is not None:
            start, stop = int(bounds[k]), int(bounds[k + 1])
            solve_into(robot, placements(matrices[start:stop]), task, answers, start=start)
            block.finish(k)
            solved += stop - start
        return answers.notes, time.process_time() - t0, 0 if fresh else solved
    finally:
        block.release()


_IDENTITY = pin.SE3.Identity()


def placements(matrices: np.ndarray) -> list[pin.SE3]:
    """The (k, 4, 4) homogeneous matrices as ``pin.SE3`` placements, each exactly its
    matrix: a copy of the identity given the rows' rotation and translation as contiguous
    arrays, ~1.0 µs each where ``pin.SE3(matrix)`` of a row takes ~2.0 µs."""
    rotations = np.ascontiguousarray(matrices[:, :3, :3])
    translations = np.ascontiguousarray(matrices[:, :3, 3])
    out = []
    for R, p in zip(rotations, translations, strict=True):
        T = _IDENTITY.copy()
        T.rotation = R
        T.translation = p
        out.append(T)
    return out
