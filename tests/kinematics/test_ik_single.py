"""The single-answer fast path of :func:`app.kinematics.ik.solve` (:mod:`app.kinematics.ik.single`,
:mod:`app.kinematics.ik.query_kernel`) against the general path (forced by making
``ik.applies`` refuse every query): the same answers on hundreds of random targets of four
arms, on unreachable targets and on searches a fake clock ends; a kernel that lies is caught
by Pinocchio's check (answers held against yourdfpy); and the first attempt runs even when
the budget is already spent, in the compiled and the Python loop."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from app.kinematics import ik, jit
from app.kinematics.ik import single
from app.kinematics.ik.kernel import CONVERGED
from app.kinematics.ik.parameters import DEFAULT_PARAMETERS
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.ik.problem import IKOptions
from app.kinematics.ik.query_kernel import ANALYTIC
from tests.kinematics.reference import TOL, pose_error, reference_pose, se3

pytestmark = pytest.mark.skipif(not jit.available(), reason="Numba not installed")

#: (robot, frame): redundant 7-DoF, UR type (closed form), spherical wrist, prismatic joint.
ARMS = [
    ("panda", "panda_link8"),
    ("ur5", "tool0"),
    ("ur5_dh", None),
    ("puma560", None),
    ("stanford_arm", None),
]
TARGETS = 150


def _ticking(step: float):
    """A fake clock (s) advancing by ``step`` at each read (the same reads give the same
    times on both paths)."""
    reads = [0]

    def clock() -> float:
        reads[0] += 1
        return reads[0] * step

    return clock


def _both(monkeypatch, robot, target, options, step: float = 1e-4, **kw):
    """(fast path's result, general path's result) of one query, each on a fresh fake clock;
    asserts which path answered."""
    answered = []
    real = single.solve_single

    def spy(*a, **k):
        res = real(*a, **k)
        answered.append(res is not None)
        return res

    monkeypatch.setattr(ik, "solve_single", spy)
    fast = ik.solve(robot, target, options, clock=_ticking(step), **kw)
    with monkeypatch.context() as m:
        m.setattr(ik, "applies", lambda *a: False)
        general = ik.solve(robot, target, options, clock=_ticking(step), **kw)
    return fast, general, answered


def _assert_same(a: ik.IKResult, b: ik.IKResult, same_reads: bool = True) -> None:
    assert (a.success, a.status, a.reason, a.detail, a.method) == (
        b.success, b.status, b.reason, b.detail, b.method,
    )  # fmt: skip
    assert (a.iterations, a.restarts) == (b.iterations, b.restarts)
    if same_reads:
        assert a.solve_time_ms == b.solve_time_ms  # the same clock reads
    np.testing.assert_allclose(a.q, b.q, rtol=0, atol=1e-12)
    assert abs(a.position_error - b.position_error) <= 1e-12
    assert abs(a.orientation_error - b.orientation_error) <= 1e-12
    assert len(a.solutions) == len(b.solutions)
    for sa, sb in zip(a.solutions, b.solutions, strict=True):
        np.testing.assert_allclose(sa.q, sb.q, rtol=0, atol=1e-12)
        assert sa.branch == sb.branch
        assert sa.seed_distance == pytest.approx(sb.seed_distance, abs=1e-12)
        if sb.manipulability is None:
            assert sa.manipulability is None
        else:
            assert abs(sa.manipulability - sb.manipulability) <= 1e-12
        assert sa.clearance == sb.clearance


def _targets(robot, ch, n: int, seed: int) -> list:
    """Poses (yourdfpy) of configurations uniform within the chain's sampling box."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        q = robot.mid_range()
        q[ch.active] = rng.uniform(ch.sample_lo, ch.sample_hi)
        out.append(se3(reference_pose(robot, q, ch.frame)))
    return out


@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
@pytest.mark.parametrize("annotate", [True, False])
def test_fast_path_gives_the_general_answers(
    registry, monkeypatch, robot_id: str, frame: str | None, annotate: bool
) -> None:
    """Random targets (closed form on for the UR5, off for every arm on a second half): the
    fast path answers every one, with the general path's configuration, counts, errors,
    label and manipulability; every success is within tolerance by yourdfpy."""
    robot = registry.get(robot_id)
    options = IKOptions(frame=frame, tolerance=(TOL, TOL), timeout_ms=5.0)
    ch = ik_chain(robot, ik.frame_name(robot, options.frame or _frame(robot)))
    goals = _targets(robot, ch, TARGETS, seed=29)
    for i, target in enumerate(goals):
        opts = options if i % 2 else replace(options, analytic=False)
        fast, general, answered = _both(monkeypatch, robot, target, opts, annotate=annotate)
        assert answered == [True]
        _assert_same(fast, general)
        if fast.success:
            dp, dr = pose_error(reference_pose(robot, fast.q, ch.frame), target.homogeneous)
            assert dp <= TOL and dr <= TOL


def _frame(robot) -> str:
    from app.kinematics.groups import default_frame, group

    return default_frame(robot, group(robot, None), None)


@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_unreachable_targets_are_answered_by_the_general_path(
    registry, monkeypatch, robot_id: str, frame: str | None
) -> None:
    """A target far beyond the reach bound: the fast path hands it to the general path (its
    descent and reason), whose answer is unchanged."""
    robot = registry.get(robot_id)
    options = IKOptions(frame=frame, timeout_ms=5.0)
    T = np.eye(4)
    T[:3, 3] = [40.0, -3.0, 2.0]
    fast, general, answered = _both(monkeypatch, robot, se3(T), options)
    assert answered == [False]
    assert not fast.success and fast.reason == "unreachable"
    _assert_same(fast, general)


@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
@pytest.mark.parametrize("step", [1e-4, 1e-3])
def test_searches_ended_by_a_fake_clock_fail_alike(
    registry, monkeypatch, robot_id: str, frame: str | None, step: float
) -> None:
    """Tolerances no iterate meets and a fake clock: both paths time out after the same
    iterations, with the same best iterate, errors, reason and detail."""
    robot = registry.get(robot_id)
    options = IKOptions(frame=frame, tolerance=(1e-300, 1e-300), timeout_ms=5.0, analytic=False)
    ch = ik_chain(robot, ik.frame_name(robot, options.frame or _frame(robot)))
    for target in _targets(robot, ch, 3, seed=7):
        fast, general, answered = _both(monkeypatch, robot, target, options, step=step)
        assert answered == [True]
        assert fast.status == "timeout" and fast.iterations > 0
        _assert_same(fast, general)


@pytest.mark.parametrize(("robot_id", "frame"), [("panda", "panda_link8"), ("ur5", "tool0")])
def test_iteration_cap_fails_alike(registry, monkeypatch, robot_id: str, frame: str) -> None:
    """An iteration cap ends both searches at the same iterate (``not_converged``)."""
    robot = registry.get(robot_id)
    options = IKOptions(
        frame=frame, tolerance=(1e-300, 1e-300), timeout_ms=1e6, analytic=False,
        max_iterations=57,
    )  # fmt: skip
    ch = ik_chain(robot, frame)
    for target in _targets(robot, ch, 3, seed=8):
        fast, general, answered = _both(monkeypatch, robot, target, options)
        assert answered == [True]
        assert fast.status == "not_converged" and fast.iterations == 57
        _assert_same(fast, general)


@pytest.mark.parametrize(
    ("robot_id", "frame", "analytic"),
    [("panda", "panda_link8", False), ("ur5", "tool0", False), ("ur5", "tool0", True)],
)
@pytest.mark.parametrize("joint", [0, 2])
def test_a_lying_kernel_is_caught_by_pinocchio(
    registry, monkeypatch, robot_id: str, frame: str, analytic: bool, joint: int
) -> None:
    """The compiled query reports a converged iterate (or the UR closed form's candidate)
    0.01 rad off on one joint: Pinocchio's check refuses it, the fast path never answers it,
    and the query is answered by the general path (a verified solution, held against
    yourdfpy)."""
    robot = registry.get(robot_id)
    ch = ik_chain(robot, frame)
    k = ch.k
    real = single.entry()
    lies = []

    def lying(*args):
        outcome = real(*args)
        if outcome in (CONVERGED, ANALYTIC):
            args[5][joint] += 0.01  # sf[:k] holds the answer
            lies.append(args[5][:k].copy())
        return outcome

    monkeypatch.setattr(single, "entry", lambda: lying)
    options = IKOptions(frame=frame, tolerance=(TOL, TOL), analytic=analytic, timeout_ms=50.0)
    for target in _targets(robot, ch, 20, seed=3):
        fast, general, answered = _both(monkeypatch, robot, target, options)
        assert answered == [False]  # refused: the general path answered
        _assert_same(fast, general, same_reads=False)  # (one more read before it did)
        assert fast.success
        dp, dr = pose_error(reference_pose(robot, fast.q, frame), target.homogeneous)
        assert dp <= TOL and dr <= TOL
        # what the kernel claimed last is off the target, and not what was answered
        claimed = fast.q.copy()
        claimed[ch.active] = lies[-1]
        assert max(pose_error(reference_pose(robot, claimed, frame), target.homogeneous)) > TOL
    assert len(lies) >= 20


def _late_clock():
    """A clock whose first read starts the budget and whose every later read is past it."""
    reads = [0]

    def clock() -> float:
        reads[0] += 1
        return 0.0 if reads[0] == 1 else 1e6

    return clock


#: The same solver on the Python loop only.
PYTHON_LOOP = replace(DEFAULT_PARAMETERS, compiled=False)


@pytest.mark.parametrize("path", ["fast", "compiled", "python"])
@pytest.mark.parametrize(("robot_id", "frame"), [("panda", "panda_link8"), ("ur5", "tool0")])
def test_a_spent_budget_still_runs_the_first_attempt(
    registry, monkeypatch, robot_id: str, frame: str, path: str
) -> None:
    """The first query of a busy server may find its budget spent before the search starts:
    an easy target (a configuration 0.05 rad from the seed) is still solved by the first
    attempt (≥ 1 iteration), then the clock ends the search. Fast path, compiled general
    path and Python loop alike."""
    robot = registry.get(robot_id)
    ch = ik_chain(robot, frame)
    q = robot.mid_range()
    q[ch.active] += 0.05
    target = se3(reference_pose(robot, q, frame))
    options = IKOptions(frame=frame, tolerance=(TOL, TOL), analytic=False, timeout_ms=5.0)
    params = PYTHON_LOOP if path == "python" else DEFAULT_PARAMETERS
    if path != "fast":
        monkeypatch.setattr(ik, "applies", lambda *a: False)
    res = ik.solve(robot, target, options, parameters=params, clock=_late_clock())
    assert res.success and res.iterations >= 1
    dp, dr = pose_error(reference_pose(robot, res.q, frame), target.homogeneous)
    assert dp <= TOL and dr <= TOL
    # a target the first attempt cannot reach: a timeout after that attempt alone
    far = IKOptions(frame=frame, tolerance=(1e-300, 1e-300), analytic=False, timeout_ms=5.0)
    res = ik.solve(robot, target, far, parameters=params, clock=_late_clock())
    assert res.status == "timeout" and 1 <= res.iterations <= 1 + params.attempt_cap
    assert math.isfinite(res.position_error)


@pytest.mark.parametrize(("robot_id", "frame"), [("panda", "panda_link8"), ("ur5", "tool0")])
def test_a_poisoned_idle_state_gives_the_general_answers(
    registry, monkeypatch, robot_id: str, frame: str
) -> None:
    """The fast path resets its reused state at each query's start: an idle state filled
    with garbage (a best energy of 0, counters, distances) gives the general path's answers,
    on searches that end by their cap near the seed (the best iterate reported) and on ones
    that converge."""
    robot = registry.get(robot_id)
    ch = ik_chain(robot, frame)
    idle = ch.idle_query_states
    rng = np.random.default_rng(5)
    capped = IKOptions(frame=frame, tolerance=(1e-300, 1e-300), analytic=False, max_iterations=4,
                       timeout_ms=1e6)  # fmt: skip
    solved = IKOptions(frame=frame, tolerance=(TOL, TOL), analytic=False, timeout_ms=1e6)
    for _ in range(6):
        q = robot.mid_range()
        q[ch.active] = rng.uniform(ch.sample_lo, ch.sample_hi)
        target = se3(reference_pose(robot, q, frame))
        seed = q.copy()
        seed[ch.active] += rng.normal(0.0, 0.02, ch.k)  # near: no jump to the table
        for options, s in [(capped, seed), (solved, seed), (solved, None)]:
            ik.solve(robot, target, options, seed=s)  # (a state to poison)
            for state in idle.values():
                state.sf[:] = 0.0
                state.d[:] = -1.0
                state.si[:] = 3
            fast, general, answered = _both(monkeypatch, robot, target, options, seed=s)
            assert answered == [True]
            _assert_same(fast, general)


@pytest.mark.parametrize("x", [0.95, 1.0])
def test_a_closed_form_without_candidates_searches_alike(registry, monkeypatch, x: float) -> None:
    """A UR5 target inside the reach bound that the closed form proves out of reach (no
    candidate): both paths search on (``analytic+numeric``) and fail alike on a fake clock."""
    robot = registry.get("ur5")
    target = se3(np.block([[np.eye(3), np.array([[x], [0.0], [0.3]])], [np.zeros((1, 3)), 1.0]]))
    options = IKOptions(frame="tool0", timeout_ms=5.0)
    fast, general, answered = _both(monkeypatch, robot, target, options)
    assert answered == [True]
    assert fast.method == "analytic+numeric" and not fast.success
    _assert_same(fast, general)
