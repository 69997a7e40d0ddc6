"""Batch IK over worker processes through shared arrays: the answers of 2 processes are the
calling thread's, field by field; chunks follow the measured cost; the shared segments are
unlinked whatever ends the batch.

Budgets are iteration caps with time limits generous enough never to bind (fixed seeds), so
every field but the solve time is deterministic.
"""

from __future__ import annotations

import pickle
import threading

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics import ik
from app.kinematics.errors import UnavailableError
from app.kinematics.ik.batch import (
    BYTE_COLUMNS,
    FLOAT_COLUMNS,
    INT_COLUMNS,
    BatchAnswers,
    BatchTask,
    solve_targets,
    target_rng,
)
from app.kinematics.ik.problem import IKOptions
from app.workers import ik_batch, shared_segment
from tests.api.ik_batch_segments import leftover_segments

#: Every column compared exactly; the solve time is a clock reading.
EXACT = ("q", *FLOAT_COLUMNS[:2], *INT_COLUMNS, *BYTE_COLUMNS)


def _targets(robot, frame: str, n: int, seed: int) -> list[pin.SE3]:
    """FK of ``n − 3`` configurations uniform within the limits, and 3 beyond reach."""
    rng = np.random.default_rng(seed)
    lo, hi = np.clip(robot.lower, -np.pi, np.pi), np.clip(robot.upper, -np.pi, np.pi)
    model, data = robot.model, robot.model.createData()
    out = []
    for _ in range(n - 3):
        pin.forwardKinematics(model, data, robot.to_pin(rng.uniform(lo, hi)))
        out.append(pin.updateFramePlacement(model, data, robot.frame_id(frame)).copy())
    far = pin.SE3(np.eye(3), np.array([0.0, 1.5, 0.3]))
    return out[:100] + [far] + out[100:] + [far, far]


@pytest.fixture(scope="module")
def pool():
    made = ik_batch.BatchPool(2)
    yield made
    made.shutdown()
    assert not leftover_segments()


@pytest.mark.parametrize(
    ("robot_id", "frame", "random_seed"),
    [("ur5", "tool0", 7), ("panda", "panda_link8", None)],
)
def test_two_processes_answer_as_one_field_by_field(
    pool, registry, robot_id, frame, random_seed
) -> None:
    """300 targets (3 unreachable: failure notes) in 2 worker processes against the calling
    thread: every column equal bit for bit, the notes equal, the segment gone."""
    robot = registry.get(robot_id)
    targets = _targets(robot, frame, 300, seed=11)
    options = IKOptions(frame=frame, timeout_ms=1000.0, max_iterations=400)
    task = BatchTask(robot.mid_range(), options, random_seed=random_seed)
    here = solve_targets(robot, targets, task)
    seen: list[bool] = []
    there = pool.solve(robot, targets, task, record=seen.append)
    assert len(there) == len(here) == 300 and there.solved >= 290
    for name in EXACT:
        assert np.array_equal(getattr(there, name), getattr(here, name)), name
    assert there.notes == here.notes and len(here.notes) >= 3
    assert seen == here.success.tolist()  # recorded in target order
    for i, T in enumerate(targets):  # and the calling thread's columns are the single solves
        res = ik.solve(robot, T, options, seed=task.seed, rng=target_rng(random_seed, i))
        row = {name: getattr(here, name)[i] for name in EXACT}
        assert row["q"].tolist() == res.q.tolist(), i
        assert (row["position_error"], row["orientation_error"]) == (
            res.position_error,
            res.orientation_error,
        )
        assert (row["iterations"], row["restarts"]) == (res.iterations, res.restarts)
        assert (bool(row["success"]), here.statuses()[i]) == (res.success, res.status)
        assert here.notes.get(i, (None, None)) == (res.reason, res.detail)
    assert pool.cost_us(robot, task) > 1.0  # measured by the workers
    assert not leftover_segments()


def test_chunks_by_measured_cost() -> None:
    """Guided chunks: they cover the batch, never grow, and each is within the measured-work
    bounds (and the budget bound)."""
    cases = [(4000, 65.0, 5.0), (4000, 100.0, 5.0), (33, 100.0, 5.0), (500, 3000.0, 5.0),
             (200, 65.0, 200.0), (61, 65.0, 5.0), (4000, 90.0, 5.0)]  # fmt: skip
    for n, cost, timeout in cases:
        sizes = ik_batch.chunk_sizes(n, 2, cost, timeout)
        assert sum(sizes) == n
        most = min(ik_batch.CHUNK_MAX_MS * 1e3 / cost, ik_batch.CHUNK_BUDGET_MS / timeout)
        assert max(sizes) <= max(1, most)
        least = min(most, ik_batch.CHUNK_MIN_MS * 1e3 / cost, n / 2)
        assert all(s >= least - 1 for s in sizes[:-1]) and sizes[-1] >= least / 2
        assert len(sizes) >= 2  # every batch here is shared by the 2 processes
        # never growing, but for the last chunk, which takes a crumb a smallest one would
        # leave after it (less than half a smallest chunk)
        assert all(a >= b for a, b in zip(sizes[:-1], sizes[1:-1], strict=False))
        assert len(sizes) == 1 or sizes[-1] < sizes[-2] + least
    sizes = ik_batch.chunk_sizes(4000, 2, 65.0, 5.0)
    most = min(int(ik_batch.CHUNK_MAX_MS * 1e3 / 65.0), int(ik_batch.CHUNK_BUDGET_MS / 5.0))
    assert sizes[0] == most and sizes[-1] < sizes[0] // 4
    # each a processes-th of what is left (guided self-scheduling), within the bounds: 4000
    # UR5-like targets (50 µs, 5 ms budget) in 12 chunks, the budget bound (400) first
    assert ik_batch.chunk_sizes(4000, 2, 50.0, 5.0) == [400] * 9 + [200, 100, 100]


def test_an_error_while_collecting_unlinks_the_segment(pool, registry) -> None:
    """An exception out of ``record`` (the caller's own code) mid-batch: it propagates, and
    the segment is unlinked all the same."""
    robot = registry.get("ur5")
    task = BatchTask(robot.mid_range(), IKOptions(frame="tool0", max_iterations=400))

    def record(success: bool) -> None:
        raise RuntimeError("caller failed")

    with pytest.raises(RuntimeError, match="caller failed"):
        pool.solve(robot, _targets(robot, "tool0", 120, seed=2), task, record=record)
    assert not leftover_segments()


def test_a_worker_finds_a_withdrawn_batch_gone(registry) -> None:
    """A chunk that starts after its batch's segment was unlinked does nothing (None)."""
    robot = registry.get("ur5")
    task = BatchTask(robot.mid_range(), IKOptions(frame="tool0"))
    recipe = ik_batch.RobotRecipe.of(robot)
    with shared_segment.create(BatchAnswers.nbytes(4, 6)) as segment:
        name = segment.name
    assert ik_batch._worker_chunk((name, 4, 6, (0, 0), recipe.key, 0, 4), task) is None


def _batch_segment(robot, targets: list[pin.SE3]):
    """A segment laid out as :meth:`BatchPool.solve` lays one out: the targets, room for the
    answers, the robot's pickled recipe after them; and the rows' first fields."""
    recipe = ik_batch.RobotRecipe.of(robot)
    pickled = pickle.dumps(recipe)
    n, dof = len(targets), len(robot.joint_names)
    at = BatchAnswers.nbytes(n, dof)
    made = shared_segment.create(at + len(pickled))
    segment = made.__enter__()
    segment.buf[at : at + len(pickled)] = pickled
    matrices, _ = BatchAnswers.on_buffer(segment.buf, n, dof)
    matrices[:] = np.array([T.homogeneous for T in targets])
    del matrices
    return made, segment, (segment.name, n, dof, (at, len(pickled)), recipe.key)


def test_a_worker_keeps_a_batch_mapped_between_its_chunks(registry, monkeypatch) -> None:
    """Chunks of one batch reuse one mapping of its segment; a chunk of another batch maps
    that batch's segment (its answers land there, not in the first); a chunk that comes
    after its batch's segment was unlinked finds it gone (None) even though the mapping
    was kept, and the mapping is dropped. Answers are the calling thread's."""
    monkeypatch.setattr(ik_batch, "_MAPPED", None)
    robot = registry.get("ur5")
    task = BatchTask(robot.mid_range(), IKOptions(frame="tool0", max_iterations=400))
    first = _targets(robot, "tool0", 8, seed=5)[:4]
    second = _targets(robot, "tool0", 9, seed=6)[:6]
    made_a, seg_a, rows_a = _batch_segment(robot, first)
    made_b, seg_b, rows_b = _batch_segment(robot, second)
    try:
        assert ik_batch._worker_chunk((*rows_a, 0, 2), task) is not None
        kept = ik_batch._MAPPED
        assert kept is not None and kept[0] == seg_a.name
        assert ik_batch._worker_chunk((*rows_a, 2, 4), task) is not None
        assert ik_batch._MAPPED is kept  # the same mapping, not a new one
        assert ik_batch._worker_chunk((*rows_b, 0, 6), task) is not None
        assert ik_batch._MAPPED is not None and ik_batch._MAPPED[0] == seg_b.name
        assert kept[1].closed  # the first batch's mapping was dropped
        for segment, targets in ((seg_a, first), (seg_b, second)):
            there = BatchAnswers.on_buffer(segment.buf, len(targets), 6)[1].copy()
            here = solve_targets(robot, targets, task)
            for name in EXACT:
                assert np.array_equal(getattr(there, name), getattr(here, name)), name
    finally:
        made_a.__exit__(None, None, None)
    try:  # the kept mapping of the first batch is gone; b is kept, then unlinked
        assert ik_batch._worker_chunk((*rows_a, 0, 2), task) is None
        assert ik_batch._MAPPED is None
        assert ik_batch._worker_chunk((*rows_b, 0, 1), task) is not None
    finally:
        made_b.__exit__(None, None, None)
    assert ik_batch._worker_chunk((*rows_b, 1, 2), task) is None  # kept, but unlinked
    assert ik_batch._MAPPED is None
    assert not leftover_segments()


def test_answers_on_a_buffer_are_shared_and_copied_out() -> None:
    """Two views of one buffer see each other's writes; a copy owns its memory."""
    buffer = memoryview(bytearray(BatchAnswers.nbytes(5, 7)))
    matrices, a = BatchAnswers.on_buffer(buffer, 5, 7)
    _, b = BatchAnswers.on_buffer(buffer, 5, 7)
    matrices[3] = np.eye(4)
    a.q[2] = np.arange(7.0)
    a.status[4], a.iterations[1], a.success[0] = 2, 17, True
    assert b.q[2].tolist() == list(range(7)) and b.iterations[1] == 17 and b.success[0]
    assert b.statuses()[4] == "timeout" and b.solved == 1
    assert np.frombuffer(buffer, np.float64, 16, 3 * 16 * 8).reshape(4, 4).tolist() == (
        np.eye(4).tolist()
    )
    c = a.copy()
    a.q[2] = 0.0
    assert c.q[2].tolist() == list(range(7))


def test_shutdown_during_a_batch_unlinks_the_segment(pool, registry, monkeypatch) -> None:
    """The pool stopped (application shutdown) while a batch of slow targets runs, in 128
    chunks of 2 (at most 5 start: 2 running, 3 queued; the rest are withdrawn): the batch
    fails with a 503 error naming ``targets`` and its segment is unlinked; the pool serves
    the next batch with fresh workers."""
    monkeypatch.setattr(ik_batch, "chunk_sizes", lambda n, *_: [2] * (n // 2))
    robot = registry.get("panda")
    # Beyond reach but inside the reach bound: each target searches its whole 50 ms budget
    # (1.0 m is outside the bound: classified unreachable in ~10 ms, and a batch of those
    # could end before a loaded machine's test thread sees its chunks queued). 256 of them
    # are ≥ 6 s of work on two workers; the shutdown waits for the two running chunks only.
    slow = [pin.SE3(np.eye(3), np.array([0.0, 0.95, 0.333]))] * 256
    options = IKOptions(frame="panda_link8", mode="position", timeout_ms=50.0)
    task = BatchTask(robot.mid_range(), options)
    failed: list[BaseException] = []

    def run() -> None:
        try:
            pool.solve(robot, slow, task)
        except UnavailableError as exc:
            failed.append(exc)

    thread = threading.Thread(target=run)
    thread.start()
    event = threading.Event()
    while thread.is_alive():  # until chunks of the batch are in the pool
        executor = pool._executor
        if executor is not None and executor._pending_work_items and leftover_segments():
            break
        event.wait(0.005)
    pool.shutdown()
    thread.join(timeout=60)
    assert not thread.is_alive() and len(failed) == 1 and failed[0].field == "targets"
    assert not leftover_segments()
    capped = IKOptions(frame="panda_link8", timeout_ms=1000.0, max_iterations=400)
    small = BatchTask(robot.mid_range(), capped)
    assert pool.solve(robot, _targets(robot, "panda_link8", 40, seed=3), small).solved >= 37
