"""The compiled whole search (app.kinematics.ik.search_kernel, driven by ik.compiled): it
cannot make the solver report a wrong answer (every converged iterate is verified by
Pinocchio, checked here against yourdfpy), it takes the Python loop's iterates on the paths
that resume it (rejected solutions, several solutions, random restarts), and its budget is
read between chunks of attempts from a clock the tests control."""

from __future__ import annotations

import threading
from dataclasses import replace

import numpy as np
import pytest

from app.kinematics import ik, jit
from app.kinematics.errors import Cancelled
from app.kinematics.ik import kernel, search_kernel
from app.kinematics.ik.parameters import DEFAULT_PARAMETERS
from app.kinematics.ik.problem import IKOptions
from tests.kinematics.reference import TOL, pose_error, random_q, reference_pose, se3

pytestmark = pytest.mark.skipif(not jit.available(), reason="Numba not installed")

#: A budget no machine runs out of: the iteration cap ends every search.
NO_DEADLINE_MS = 60_000
#: Tolerances no iterate meets (rounding alone is larger): a search that never converges
#: on a reachable target, so that the budget or the cap ends it.
UNMET = (1e-300, 1e-300)


#: The same solver on the Python loop only.
PYTHON_LOOP = replace(DEFAULT_PARAMETERS, compiled=False)


@pytest.mark.parametrize(("robot_id", "frame"), [("panda", "panda_link8"), ("ur5", "tool0")])
def test_a_kernel_that_lies_about_convergence_is_not_believed(
    registry, monkeypatch, robot_id: str, frame: str
) -> None:
    """The kernel reports CONVERGED with a configuration 0.01 rad off on the first joint:
    the verification refuses every one, so no success, and the best iterate reported has
    its true error (yourdfpy's FK), not the kernel's."""
    robot = registry.get(robot_id)
    real = search_kernel.search

    def lying(state, *args):
        outcome = real(state, *args)
        qa = state.qa
        if outcome == kernel.CONVERGED:
            qa[0] += 0.01 if qa[0] < 0.0 else -0.01
        return outcome

    monkeypatch.setattr(search_kernel, "search", lying)
    # the general driver (ik.compiled); the fast path's lying kernel: test_ik_single
    monkeypatch.setattr(ik, "applies", lambda *a: False)
    rng = np.random.default_rng(3)
    options = IKOptions(frame=frame, timeout_ms=NO_DEADLINE_MS, max_iterations=200, analytic=False)
    for _ in range(5):
        target = reference_pose(robot, random_q(robot, rng), frame)
        res = ik.solve(robot, se3(target), options)
        assert not res.success and res.solutions == []
        dp, dr = pose_error(reference_pose(robot, res.q, frame), target)
        assert res.position_error == pytest.approx(dp, abs=1e-9)
        assert res.orientation_error == pytest.approx(dr, abs=1e-9)
        assert dp > TOL or dr > TOL


@pytest.mark.parametrize(("robot_id", "frame"), [("panda", "panda_link8"), ("ur5", "tool0")])
def test_fast_path_answers_reach_the_target_by_yourdfpy(registry, robot_id, frame) -> None:
    """The benchmark's case (mid-range seed, one solution, numeric only): every answer is
    within the tolerances by an independent FK and within the limits."""
    robot = registry.get(robot_id)
    rng = np.random.default_rng(17)
    options = IKOptions(frame=frame, timeout_ms=NO_DEADLINE_MS, max_iterations=2000,
                        analytic=False)  # fmt: skip
    for _ in range(40):
        target = reference_pose(robot, random_q(robot, rng), frame)
        res = ik.solve(robot, se3(target), options)
        assert res.success
        assert np.all(res.q >= robot.lower) and np.all(res.q <= robot.upper)
        dp, dr = pose_error(reference_pose(robot, res.q, frame), target)
        assert dp <= TOL and dr <= TOL


@pytest.mark.parametrize("case", ["reject_first", "three_solutions", "random_restarts"])
def test_resumed_searches_take_the_python_loops_iterates(registry, case: str) -> None:
    """Searches that return to Python mid-way (a converged iterate refused by ``accept``,
    several solutions wanted, random restarts drawn by the caller) take the same iterates
    as the Python loop: same counts, same solutions."""
    robot = registry.get("panda")
    frame = "panda_link8"
    options = IKOptions(
        frame=frame,
        timeout_ms=NO_DEADLINE_MS,
        max_iterations=400,
        analytic=False,
        num_solutions=3 if case == "three_solutions" else 1,
    )
    rng = np.random.default_rng(11)
    most_restarts = 0
    for _ in range(4):
        target = se3(reference_pose(robot, random_q(robot, rng), frame))
        seed = random_q(robot, rng)
        if case == "random_restarts":  # mostly out of reach (within the reach bound)
            target.translation = target.translation * 1.4
        answers = []
        for parameters in (DEFAULT_PARAMETERS, PYTHON_LOOP):
            seen: list[int] = []

            def accept(q: np.ndarray, seen: list[int] = seen) -> bool:
                seen.append(1)
                return len(seen) > 2  # the first two converged iterates are refused

            kwargs: dict = {"seed": seed}
            if case == "reject_first":
                kwargs["accept"] = accept
            if case == "random_restarts":
                kwargs["rng"] = np.random.default_rng(5)
            answers.append(ik.solve(robot, target, options, parameters=parameters, **kwargs))
        a, b = answers
        assert (a.success, a.status, a.iterations, a.restarts) == (
            b.success, b.status, b.iterations, b.restarts,
        )  # fmt: skip
        assert len(a.solutions) == len(b.solutions)
        for sa, sb in zip(a.solutions, b.solutions, strict=True):
            np.testing.assert_allclose(sa.q, sb.q, rtol=0, atol=1e-8)
        np.testing.assert_allclose(a.q, b.q, rtol=0, atol=1e-8)
        most_restarts = max(most_restarts, a.restarts)
    if case == "random_restarts":
        assert most_restarts > 40  # past the nearest table samples: drawn from rng


class _FakeClock:
    """A clock that stands still for ``reads`` reads, then jumps past any deadline; it can
    set an event on the jump instead."""

    def __init__(self, reads: int, cancel: threading.Event | None = None) -> None:
        self.reads, self.count, self.cancel = reads, 0, cancel

    def __call__(self) -> float:
        self.count += 1
        if self.count <= self.reads:
            return 0.0
        if self.cancel is not None:
            self.cancel.set()
            return 0.0
        return float("inf")


@pytest.mark.parametrize("reads", [0, 1, 3])
def test_deadline_is_read_between_chunks_of_attempts(registry, reads) -> None:
    """A search that never converges and has no iteration cap: the search ends when the clock says
    the deadline passed, after one chunk of attempts per clock read in time."""
    robot = registry.get("panda")
    clock = _FakeClock(reads + 1)  # the budget's start stands still too
    target = se3(reference_pose(robot, robot.mid_range(), "panda_link8"))
    options = IKOptions(frame="panda_link8", timeout_ms=1e9, analytic=False, tolerance=UNMET)
    res = ik.solve(robot, target, options, clock=clock)
    assert not res.success and res.status == "timeout"
    # the budget's start, the first read before any attempt, one read after each chunk,
    # then the answer's solve time (two reads on a failure)
    assert clock.count == 1 + max(reads, 1) + 1 + 2
    chunk = DEFAULT_PARAMETERS.chunk_attempts
    # a budget spent at the first read still runs the first attempt (one chunk of one)
    attempts = max(reads * chunk, 1)
    assert attempts <= res.iterations <= 1 + attempts * DEFAULT_PARAMETERS.attempt_cap


def test_cancel_is_read_between_chunks(registry) -> None:
    """A cancel set while the search runs stops it at the next chunk boundary."""
    robot = registry.get("panda")
    cancel = threading.Event()
    clock = _FakeClock(3, cancel)
    target = se3(reference_pose(robot, robot.mid_range(), "panda_link8"))
    options = IKOptions(frame="panda_link8", timeout_ms=1e9, analytic=False, tolerance=UNMET)
    with pytest.raises(Cancelled):
        ik.solve(robot, target, options, cancel=cancel, clock=clock)
    assert clock.count == 4  # the budget's start, then three reads


@pytest.mark.parametrize("path", ["general", "fast"])
@pytest.mark.parametrize(("robot_id", "frame"), [("panda", "panda_link8"), ("ur5", "tool0")])
def test_a_reused_search_state_gives_the_answers_of_a_fresh_one(
    registry, monkeypatch, robot_id: str, frame: str, path: str
) -> None:
    """Queries on one thread reuse the chain's idle search state (ik.compiled, and the fast
    path's, ik.single): each answer (q, iterations, restarts, errors) is the one of a search
    from freshly allocated arrays, whatever the queries before it (reachable,
    unreachable-in-budget, other seeds)."""
    robot = registry.get(robot_id)
    ch = ik.precompute.ik_chain(robot, frame)
    if path == "general":
        monkeypatch.setattr(ik, "applies", lambda *a: False)
    idle = ch.idle_states if path == "general" else ch.idle_query_states
    rng = np.random.default_rng(31)
    opts = IKOptions(frame=frame, timeout_ms=NO_DEADLINE_MS, max_iterations=400, analytic=False)
    queries = []
    for _ in range(12):
        q = random_q(robot, rng)
        target = se3(reference_pose(robot, q, frame))
        # the default seed (far: a jump to the table), and a near one (tracking: the attempt
        # from the seed, with its null-space pull towards it on the redundant arm)
        queries += [(target, None), (target, q + rng.normal(0.0, 0.05, q.shape))]
    starved = replace(opts, max_iterations=3)  # stops mid-search: the state is left used
    answers = {}
    for fresh in (True, False):
        out = []
        for i, (target, seed) in enumerate(queries):
            if fresh:
                idle.clear()
            o = starved if i % 5 in (3, 4) else opts  # a near seed starved, then a far one
            r = ik.solve(robot, target, o, seed=seed)
            out.append((r.success, r.q.tolist(), r.iterations, r.restarts, r.position_error))
        answers[fresh] = out
    assert answers[False] == answers[True]
    assert idle  # the state was kept for reuse
