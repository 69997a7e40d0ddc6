"""The fast path of :func:`app.kinematics.paths.follow.follow`: the warm-started local solve
(app/kinematics/paths/local.py) is never trusted, and the whole call is bounded by its
``deadline``.

Every point is checked against yourdfpy's forward kinematics (``check_points``), not the
code's own errors. The deadline is tested with a deadline already past and with a fake
clock, never a wall-clock race.
"""

from __future__ import annotations

import time

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.ik.search import joint_distance
from app.kinematics.paths import point_kernel
from app.kinematics.paths.follow import PathOptions, follow
from app.kinematics.paths.local import LocalSolver
from app.kinematics.paths.segments import CartesianPath, Line
from bench._lines import random_lines
from tests.kinematics.path_checks import check_points, ik_options

ARMS = [("ur5", "tool0"), ("panda", "panda_hand")]
OPTIONS = PathOptions(max_step=(0.01, 0.05), max_joint_step=0.1)


def _line(registry, robot_id: str, frame: str, seed: int = 11):
    robot = registry.get(robot_id)
    line = random_lines(robot, frame, 1, seed=seed, checks=6)[0]
    return robot, line, CartesianPath.from_segments(line.start, [Line(line.end)])


def _complete_line(registry, robot_id: str, frame: str):
    """The first random line (seeds 11, 12, ...) that ``follow`` completes."""
    for seed in range(11, 41):
        robot, line, path = _line(registry, robot_id, frame, seed)
        res = follow(robot, line.q0, path, ik_options(frame), OPTIONS)
        if res.failure is None and len(res.points) > 10:
            return robot, line, path, res
    raise AssertionError("no completed line in 30 draws")


# ----------------------------------------------------------------- the local solve
@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_local_solver_applies_and_is_used(registry, robot_id: str, frame: str) -> None:
    """On a full-pose line the compiled local points answer most points (else the speed-up
    is gone), one call per point or by runs in the compiled walk, and the answer is the
    verified path."""
    robot, line, path, _ = _complete_line(registry, robot_id, frame)
    calls = {"accepted": 0}
    original, original_walk = LocalSolver.point, LocalSolver.walk

    def counting(self, *args):
        out = original(self, *args)
        calls["accepted"] += out[0] == point_kernel.OK
        return out

    def counting_walk(self, *args):
        out = original_walk(self, *args)
        calls["accepted"] += out[0]
        return out

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(LocalSolver, "point", counting)
        mp.setattr(LocalSolver, "walk", counting_walk)
        res = follow(robot, line.q0, path, ik_options(frame), OPTIONS)
    assert res.failure is None
    check_points(robot, frame, line.q0, path, res, OPTIONS)
    assert calls["accepted"] >= 0.9 * (len(res.points) - 1)


def _lie(solver: LocalSolver, q_prev: np.ndarray, kind: str) -> np.ndarray:
    """A wrong configuration claimed as converged."""
    q = q_prev.copy()
    a = solver.ch.active
    if kind == "unconverged":  # a small step off the pose (0.01 rad on joint 1)
        q[a[1]] += 0.01
    elif kind == "outside_limits":
        q[a[0]] = solver.robot.upper[a[0]] + 0.5
    elif kind == "jump":  # far beyond max_joint_step
        q[a[0]] += 1.0
    elif kind == "nan":
        q[a[2]] = np.nan
    return q


def _lying(kind: str, calls: list[int]):
    """A LocalSolver.attempt (the Python path) that claims convergence on a wrong
    configuration (counting its calls in ``calls``)."""

    def attempt(self, q_prev, target):
        calls.append(1)
        return _lie(self, q_prev, kind), 3

    return attempt


def _lying_point(kind: str, calls: list[int]):
    """A LocalSolver.point (the compiled path) whose attempt claims convergence on a wrong
    configuration: the compiled checks alone (LocalSolver.check) judge it."""

    def point(self, q_prev, R, p, middle):
        calls.append(1)
        status, q, ep, er = self.check(q_prev, _lie(self, q_prev, kind), pin.SE3(R, p))
        assert status != point_kernel.OK
        return status, None, 0.0, 0.0, 3, 0.0, 0.0

    return point


@pytest.mark.parametrize("checks", ["compiled", "python"])
@pytest.mark.parametrize("kind", ["unconverged", "outside_limits", "jump", "nan"])
@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_wrong_local_answers_are_never_accepted(
    registry, robot_id: str, frame: str, kind: str, checks: str
) -> None:
    """A local solve that returns an unconverged, out-of-limits, jumping or NaN
    configuration as converged: no such point is returned, by the compiled checks or by
    the Python ones (the compiled point switched off); the fallback (ik.solve) still
    follows the line, and every point is on the path by yourdfpy's FK."""
    robot, line, path, ref = _complete_line(registry, robot_id, frame)
    calls: list[int] = []
    with pytest.MonkeyPatch.context() as mp:
        if checks == "compiled":
            # every waypoint through the per-point call that lies (the compiled walk, which
            # takes the same compiled step and checks, is off: tests/kinematics/test_path_walk.py)
            mp.setattr(LocalSolver, "walk", lambda self, *args: (0, 0))
            mp.setattr(LocalSolver, "point", _lying_point(kind, calls))
        else:
            mp.setattr(LocalSolver, "prepare", lambda self, *args: False)
            mp.setattr(LocalSolver, "attempt", _lying(kind, calls))
        res = follow(robot, line.q0, path, ik_options(frame), OPTIONS)
    assert len(calls) >= len(res.points) - 1  # every point was offered the lie first
    check_points(robot, frame, line.q0, path, res, OPTIONS)
    assert res.failure is None
    for p in res.points:
        assert np.isfinite(p.q).all()
        assert (p.q >= robot.lower).all() and (p.q <= robot.upper).all()
    # The fallback answers the same path (not necessarily the same points: no local steps).
    assert res.fraction == ref.fraction == 1.0


@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_compiled_and_python_checks_answer_the_same_points(
    registry, robot_id: str, frame: str
) -> None:
    """The same lines followed with the compiled point and with the Python checks: the
    same points (configurations to 1e-12, s exactly), errors and failure."""
    robot = registry.get(robot_id)
    for line in random_lines(robot, frame, 8, seed=21, checks=4):
        path = CartesianPath.from_segments(line.start, [Line(line.end)])
        res = follow(robot, line.q0, path, ik_options(frame), OPTIONS)
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(LocalSolver, "prepare", lambda self, *args: False)
            ref = follow(robot, line.q0, path, ik_options(frame), OPTIONS)
        assert len(res.points) == len(ref.points)
        for p, r in zip(res.points, ref.points, strict=True):
            assert p.s == r.s
            np.testing.assert_allclose(p.q, r.q, rtol=0.0, atol=1e-12)
            assert p.position_error == pytest.approx(r.position_error, abs=1e-12)
            assert p.orientation_error == pytest.approx(r.orientation_error, abs=1e-12)
        assert (res.failure is None) == (ref.failure is None)
        if res.failure is not None:
            assert (res.failure.reason, res.failure.index) == (
                ref.failure.reason,
                ref.failure.index,
            )


# ------------------------------------------------------------------------ deadline
@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_deadline_already_past_stops_at_the_first_waypoint(
    registry, robot_id: str, frame: str
) -> None:
    robot, line, path = _line(registry, robot_id, frame)
    res = follow(
        robot, line.q0, path, ik_options(frame), OPTIONS, deadline=time.perf_counter() - 1.0
    )
    assert res.failure is not None
    assert res.failure.reason == "timeout" and res.failure.index == 1
    assert "time budget ran out" in res.failure.detail
    assert len(res.points) == 1 and res.fraction == 0.0
    np.testing.assert_array_equal(res.points[0].q, line.q0)
    np.testing.assert_array_equal(res.failure.q, line.q0)


@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_deadline_by_a_fake_clock_keeps_the_points_so_far(
    registry, robot_id: str, frame: str
) -> None:
    """A clock that advances one unit per reading, deadline 8: the walk stops with
    ``timeout`` at the first waypoint whose reading is ≥ 8, keeping the verified points
    before it (the same line completes without a deadline)."""
    robot, line, path, full = _complete_line(registry, robot_id, frame)
    readings: list[float] = []

    def clock() -> float:
        readings.append(float(len(readings)))
        return readings[-1]

    res = follow(robot, line.q0, path, ik_options(frame), OPTIONS, deadline=8.0, clock=clock)
    assert res.failure is not None and res.failure.reason == "timeout"
    assert readings[-1] == 8.0  # it stopped at the reading that passed the deadline
    poses, ss = path.sample(OPTIONS.max_step)
    k = res.failure.index
    assert 1 < k <= 9 < len(poses)
    assert res.failure.s == float(ss[k])
    check_points(robot, frame, line.q0, path, res, OPTIONS)
    # Every waypoint before k was reached, and the points are those of the full answer.
    assert res.fraction == pytest.approx(float(ss[k - 1]), abs=0.0)
    n = len(res.points)
    for p, q in zip(res.points, full.points[:n], strict=True):
        np.testing.assert_array_equal(p.q, q.q)
    assert joint_distance(robot, res.failure.q, res.points[-1].q).max() == 0.0
