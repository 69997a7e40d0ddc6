"""Inverse kinematics against independent references.

Solutions are checked with yourdfpy's forward kinematics (not Pinocchio's), joint limits
with the URDF's numbers, and the planar 2-link arm against the textbook closed form.
Budgets are generous (tests run on loaded machines); speed is measured in bench/.
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.kinematics import ik
from app.kinematics.analytic_ik.planar2 import into_limits, planar2_geometry, planar2_solutions
from app.kinematics.errors import InvalidInputError, UnknownNameError
from app.kinematics.ik.parameters import DEFAULT_PARAMETERS
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.ik.problem import IKOptions, IKProblem
from app.kinematics.ik.search import Search
from app.kinematics.models import RobotModel
from app.kinematics.rotations import quaternion_to_matrix
from tests.kinematics.reference import (
    TOL,
    pose_error,
    random_q,
    reference_pose,
    se3,
    within_limits,
)

BUDGET_MS = 500.0

# (robot id, frame, closed forms allowed): the benchmark chains and a DH robot.
CHAINS = [
    ("panda", "panda_link8", True),
    ("ur5", "tool0", True),
    ("ur5", "tool0", False),
    ("puma560", "tool", True),
]


@pytest.mark.parametrize("angle", [1e-13, 3e-9, 0.5, 3.0])
def test_pose_error_resolves_tiny_angles(angle: float) -> None:
    """The reference error itself: exact angles from 1e-13 rad up to nearly π."""
    axis = np.array([1.0, -2.0, 0.5]) / math.sqrt(5.25)
    R0 = pin.exp3(np.array([0.3, -0.7, 1.1]))
    T, target = np.eye(4), np.eye(4)
    T[:3, :3] = R0 @ pin.exp3(axis * angle)
    target[:3, :3] = R0
    assert pose_error(T, target)[1] == pytest.approx(angle, rel=1e-6, abs=1e-15)


@pytest.mark.parametrize(("robot_id", "frame", "analytic"), CHAINS)
@settings(
    max_examples=12,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(seed=st.integers(0, 2**32 - 1))
def test_reachable_targets_are_solved(
    registry, robot_id: str, frame: str, analytic: bool, seed: int
) -> None:
    """FK(IK(FK(q))) matches the target within tolerance, inside the limits (property)."""
    robot = registry.get(robot_id)
    q_true = random_q(robot, np.random.default_rng(seed))
    target = reference_pose(robot, q_true, frame)
    res = ik.solve(
        robot, se3(target), IKOptions(frame=frame, timeout_ms=BUDGET_MS, analytic=analytic)
    )
    assert res.method == ("analytic" if analytic and robot_id == "ur5" else "numeric")
    assert res.success, (res.status, res.position_error, res.orientation_error)
    assert res.status == "converged"
    for sol in res.solutions:
        assert within_limits(robot, sol.q)
        dp, dr = pose_error(reference_pose(robot, sol.q, frame), target)
        assert dp <= TOL and dr <= TOL
        assert sol.position_error == pytest.approx(dp, abs=1e-8)
    # Joints that do not support the frame keep their seed (Panda's fingers).
    still = np.setdiff1d(np.arange(robot.n), robot.supporting_joints(frame))
    np.testing.assert_array_equal(res.q[still], robot.mid_range()[still])


@pytest.mark.parametrize(
    "offset",
    [
        np.full(6, 0.05),
        # a seed whose L∞ and L2 orders of the solutions differ (the 3rd is nearer in L2)
        np.array([1.07, -1.4, 0.69, -0.97, 1.09, 0.12]),
    ],
)
def test_several_distinct_solutions_sorted_by_seed_distance(registry, offset) -> None:
    robot = registry.get("ur5")
    q_true = np.array([0.4, -1.1, 1.3, -0.6, 1.2, 0.3])
    target = reference_pose(robot, q_true, "tool0")
    seed = q_true + offset
    res = ik.solve(
        robot, se3(target), IKOptions(frame="tool0", num_solutions=4, timeout_ms=2000), seed=seed
    )
    assert res.success and len(res.solutions) >= 2
    # The solver ranks by the largest single-joint move from the seed (L∞; continuous joints
    # around the circle), ties broken by the Euclidean distance (ranking.py), not by L2 alone.
    cont = np.array([j.continuous for j in robot.joints])
    orders = []
    for sol in res.solutions:
        d = sol.q - seed
        d[cont] = np.angle(np.exp(1j * d[cont]))  # around the circle, independently of the code
        orders.append((float(np.abs(d).max()), float(np.linalg.norm(d))))
        assert sol.seed_distance == pytest.approx(np.abs(d).max(), abs=1e-12)
    assert orders == sorted(orders)
    for a in range(len(res.solutions)):
        for b in range(a):
            assert (
                np.abs(res.solutions[a].q - res.solutions[b].q).max() > DEFAULT_PARAMETERS.distinct
            )
        dp, dr = pose_error(reference_pose(robot, res.solutions[a].q, "tool0"), target)
        assert dp <= TOL and dr <= TOL


# ------------------------------------------------------------------------ UR-type closed form
@pytest.mark.parametrize(
    ("robot_id", "frame"), [("ur5", "tool0"), ("ur10", "tool0"), ("ur5_dh", "tool")]
)
def test_ur_closed_form_finds_all_branches(registry, robot_id: str, frame: str) -> None:
    """A generic UR pose has 8 IK branches; each is exact (yourdfpy) and within limits."""
    robot = registry.get(robot_id)
    q_true = np.array([0.4, -1.1, 1.3, -0.6, 1.2, 0.3])
    target = reference_pose(robot, q_true, frame)
    res = ik.solve(
        robot, se3(target), IKOptions(frame=frame, num_solutions=8, timeout_ms=BUDGET_MS)
    )
    assert res.method == "analytic" and len(res.solutions) == 8
    assert any(np.allclose(s.q, q_true, atol=1e-9) for s in res.solutions)
    for s in res.solutions:
        assert within_limits(robot, s.q)
        dp, dr = pose_error(reference_pose(robot, s.q, frame), target)
        assert dp <= 1e-10 and dr <= 1e-9
    # Shoulder, elbow and wrist signs: the 8 branches are pairwise distinct.
    branches = {
        (round(math.remainder(s.q[0] - res.solutions[0].q[0], 2 * math.pi), 6),
         round(s.q[2], 6), round(math.remainder(s.q[4], 2 * math.pi), 6))
        for s in res.solutions
    }  # fmt: skip
    assert len(branches) == 8


def test_ur_closed_form_on_z1_respects_narrow_limits(registry) -> None:
    """Z1 has the UR axis pattern but narrow limits: only in-limit branches are returned."""
    robot = registry.get("z1")
    frame = robot.ee_frame
    rng = np.random.default_rng(5)
    for _ in range(5):
        q_true = random_q(robot, rng)
        target = reference_pose(robot, q_true, frame)
        res = ik.solve(
            robot, se3(target), IKOptions(frame=frame, num_solutions=2, timeout_ms=100.0)
        )
        assert res.success and res.method.startswith("analytic")
        for s in res.solutions:
            assert within_limits(robot, s.q)
            dp, dr = pose_error(reference_pose(robot, s.q, frame), target)
            assert dp <= TOL and dr <= TOL


def test_ur_geometry_is_detected_only_where_it_applies(registry) -> None:
    from app.kinematics.analytic_ik.ur import ur_geometry

    cases = [("ur5", True), ("ur5_dh", True), ("z1", True), ("puma560", False), ("panda", False)]
    for rid, expected in cases:
        robot = registry.get(rid)
        frame = "panda_link8" if rid == "panda" else robot.ee_frame
        ch = ik_chain(robot, frame)
        assert (ur_geometry(robot, ch.active, ch.frame_id) is not None) == expected, rid


# ------------------------------------------------------------------ planar 2-link closed form
def _planar_closed_form(l1: float, l2: float, x: float, y: float) -> set[tuple[float, float]]:
    """Textbook closed form: c2 = (x² + y² − l1² − l2²)/(2 l1 l2), θ2 = ±acos c2."""
    c2 = (x * x + y * y - l1 * l1 - l2 * l2) / (2 * l1 * l2)
    out = set()
    for t2 in (math.acos(c2), -math.acos(c2)):
        t1 = math.atan2(y, x) - math.atan2(l2 * math.sin(t2), l1 + l2 * math.cos(t2))
        out.add((round(into_limits(t1, -math.pi, math.pi, 0.0), 9), round(t2, 9)))
    return out


@pytest.mark.parametrize(("x", "y"), [(1.2, 0.7), (-0.4, 1.1), (0.3, -0.9), (1.75, 0.1)])
def test_planar2_returns_both_elbow_solutions(registry, x: float, y: float) -> None:
    robot = registry.get("planar2")  # DH: l1 = 1.0, l2 = 0.8, frame tool at the tip
    target = pin.SE3(np.eye(3), np.array([x, y, 0.0]))
    res = ik.solve(robot, target, IKOptions(frame=robot.ee_frame, mode="position", num_solutions=2))
    assert res.success and len(res.solutions) == 2
    got = {(round(s.q[0], 9), round(s.q[1], 9)) for s in res.solutions}
    assert got == _planar_closed_form(1.0, 0.8, x, y)
    assert res.method == "analytic"


@pytest.mark.parametrize(("x", "y"), [(1.2, 0.7), (-0.4, 1.1)])
def test_numeric_search_reports_each_solution_once(registry, x: float, y: float) -> None:
    """The 2-link arm has exactly two solutions: the numeric search (restarts converging to
    them again and again) asked for three reports those two, each once."""
    robot = registry.get("planar2")
    target = pin.SE3(np.eye(3), np.array([x, y, 0.0]))
    options = IKOptions(
        frame=robot.ee_frame, mode="position", num_solutions=3, analytic=False,
        tolerance=(1e-9, 1e-9), timeout_ms=60_000, max_iterations=400,
    )  # fmt: skip
    res = ik.solve(robot, target, options)
    assert res.success and res.status == "converged" and res.method == "numeric"
    assert len(res.solutions) == 2
    got = {(round(s.q[0], 6), round(s.q[1], 6)) for s in res.solutions}
    assert got == {(round(a, 6), round(b, 6)) for a, b in _planar_closed_form(1.0, 0.8, x, y)}


def _tilted_planar_urdf() -> str:
    """A planar 2-link arm whose axes are world y, lifted and offset, with a tool offset."""
    return """<?xml version="1.0"?>
<robot name="tilted2">
  <link name="base"/><link name="l1"/><link name="l2"/><link name="tool"/>
  <joint name="a" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0.1 0.2 0.5" rpy="0 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-3.2" upper="3.2" velocity="1" effort="1"/></joint>
  <joint name="b" type="revolute"><parent link="l1"/><child link="l2"/>
    <origin xyz="0.6 0.05 0" rpy="0 0 0"/><axis xyz="0 -1 0"/>
    <limit lower="-3.2" upper="3.2" velocity="1" effort="1"/></joint>
  <joint name="t" type="fixed"><parent link="l2"/><child link="tool"/>
    <origin xyz="0.4 0 0.1" rpy="0 0 0"/></joint>
</robot>"""


def test_planar2_closed_form_in_a_general_placement() -> None:
    """Parallel axes along ±y, offsets and a tool: two exact solutions, checked by yourdfpy."""
    robot = RobotModel("tilted2", _tilted_planar_urdf(), ee_frame="tool")
    q_true = np.array([0.7, -1.2])
    target = reference_pose(robot, q_true, "tool")
    res = ik.solve(robot, se3(target), IKOptions(frame="tool", mode="position", num_solutions=2))
    assert res.method == "analytic" and len(res.solutions) == 2
    assert any(np.allclose(s.q, q_true, atol=1e-9) for s in res.solutions)
    for s in res.solutions:
        assert np.linalg.norm(reference_pose(robot, s.q, "tool")[:3, 3] - target[:3, 3]) < 1e-12


def test_planar2_solutions_unreachable_is_empty(registry) -> None:
    robot = registry.get("planar2")
    ee = robot.ee_frame
    geo = planar2_geometry(robot, robot.supporting_joints(ee), robot.frame_id(ee))
    assert geo is not None and geo.l1 == pytest.approx(1.0) and geo.l2 == pytest.approx(0.8)
    assert planar2_solutions(geo, np.array([2.5, 0.0, 0.0])) == []
    assert planar2_solutions(geo, np.array([0.1, 0.0, 0.0])) == []  # inside |l1 − l2|


def test_into_limits() -> None:
    assert into_limits(3.0 * math.pi / 2, -math.pi, math.pi, 0.0) == pytest.approx(-math.pi / 2)
    assert into_limits(0.5, -2 * math.pi, 2 * math.pi, -5.0) == pytest.approx(0.5 - 2 * math.pi)
    assert into_limits(0.5, -2 * math.pi, 2 * math.pi, 1.0) == pytest.approx(0.5)
    assert into_limits(4.0, -math.inf, math.inf, 0.0) == pytest.approx(4.0 - 2 * math.pi)


# ------------------------------------------------------------------------- failures, modes
def test_target_outside_workspace_returns_best_effort(registry) -> None:
    robot = registry.get("ur5")
    target = pin.SE3(np.eye(3), np.array([3.0, 0.0, 0.5]))  # UR5 reach is ~0.85 m
    res = ik.solve(robot, target, IKOptions(frame="tool0", timeout_ms=20.0))
    assert not res.success and res.solutions == []
    # Beyond the reach bound: no search to time out, a short best-effort descent instead.
    assert res.status == "not_converged" and res.reason == "unreachable"
    assert within_limits(robot, res.q)
    dp, _ = pose_error(reference_pose(robot, res.q, "tool0"), target.homogeneous)
    assert res.position_error == pytest.approx(dp, abs=1e-9)
    assert res.position_error > 2.0


def test_iteration_cap_reports_not_converged(registry) -> None:
    robot = registry.get("ur5")
    target = pin.SE3(np.eye(3), np.array([3.0, 0.0, 0.5]))
    res = ik.solve(robot, target, IKOptions(frame="tool0", timeout_ms=1000.0, max_iterations=25))
    assert not res.success and res.status == "not_converged" and res.iterations == 25


def test_planar2_unreachable_is_not_a_success(registry) -> None:
    robot = registry.get("planar2")
    target = pin.SE3(np.eye(3), np.array([2.5, 0.0, 0.0]))
    res = ik.solve(robot, target, IKOptions(frame=robot.ee_frame, mode="position", timeout_ms=10.0))
    assert not res.success
    # The best effort stretches towards the target: distance = 2.5 − (l1 + l2).
    assert res.position_error == pytest.approx(0.7, abs=1e-3)


@pytest.mark.parametrize("robot_id", ["rrp", "planar3r"])
def test_position_mode_on_a_three_joint_arm(registry, robot_id: str) -> None:
    robot = registry.get(robot_id)
    rng = np.random.default_rng(7)
    for _ in range(5):
        q_true = random_q(robot, rng)
        target = reference_pose(robot, q_true, robot.ee_frame)
        goal = pin.SE3(np.eye(3), target[:3, 3].copy())  # orientation ignored
        res = ik.solve(
            robot, goal, IKOptions(frame=robot.ee_frame, mode="position", timeout_ms=BUDGET_MS)
        )
        assert res.success
        T = reference_pose(robot, res.q, robot.ee_frame)
        assert np.linalg.norm(T[:3, 3] - target[:3, 3]) <= TOL
        assert within_limits(robot, res.q)


def test_orientation_mode(registry) -> None:
    robot = registry.get("ur5")
    target = reference_pose(robot, np.array([0.1, -0.8, 1.0, 0.3, -0.7, 2.0]), "tool0")
    goal = pin.SE3(target[:3, :3].copy(), np.array([9.0, 9.0, 9.0]))  # position ignored
    res = ik.solve(robot, goal, IKOptions(frame="tool0", mode="orientation", timeout_ms=BUDGET_MS))
    assert res.success
    _, dr = pose_error(reference_pose(robot, res.q, "tool0"), target)
    assert dr <= TOL


def test_zero_weight_frees_a_component(registry) -> None:
    """Weight 0 on ωz: any rotation about world z of the target is accepted."""
    robot = registry.get("ur5")
    target = reference_pose(robot, np.array([0.2, -1.0, 1.1, -0.4, 1.3, 0.0]), "tool0")
    Rz = pin.rpy.rpyToMatrix(0.0, 0.0, 0.3)
    goal = pin.SE3(Rz @ target[:3, :3], target[:3, 3].copy())
    w = np.array([1, 1, 1, 1, 1, 0.0])
    res = ik.solve(robot, goal, IKOptions(frame="tool0", weights=tuple(w), timeout_ms=BUDGET_MS))
    assert res.success
    T = reference_pose(robot, res.q, "tool0")
    assert np.linalg.norm(T[:3, 3] - target[:3, 3]) <= TOL
    # The tool z axis is world-z-rotation invariant only up to the free angle: check the
    # constrained rotation components, log3(R R_tᵀ)[0:2] ≈ 0.
    assert np.abs(pin.log3(T[:3, :3] @ goal.rotation.T)[:2]).max() <= TOL


def test_continuous_joints_use_wire_angles(registry) -> None:
    """Kinova: continuous joints come back as one angle in (−π, π], FK-verified."""
    robot = registry.get("kinova")
    frame = robot.ee_frame
    cont = [j.index for j in robot.joints if j.continuous]
    assert cont
    rng = np.random.default_rng(3)
    for _ in range(4):
        q_true = random_q(robot, rng)
        q_true[cont] += 2 * np.pi  # the same pose with angles beyond π
        target = reference_pose(robot, q_true, frame)
        res = ik.solve(robot, se3(target), IKOptions(frame=frame, timeout_ms=BUDGET_MS))
        assert res.success
        assert res.q.shape == (robot.n,)
        assert np.all(np.abs(res.q[cont]) <= np.pi + 1e-12)
        dp, dr = pose_error(reference_pose(robot, res.q, frame), target)
        assert dp <= TOL and dr <= TOL


def test_accept_predicate_rejects_solutions(registry) -> None:
    """A rejecting predicate makes the solver look for another branch (shoulder sign)."""
    robot = registry.get("ur5")
    q_true = np.array([0.4, -1.1, 1.3, -0.6, 1.2, 0.3])
    target = se3(reference_pose(robot, q_true, "tool0"))
    calls: list[np.ndarray] = []

    def accept(q: np.ndarray) -> bool:
        calls.append(q.copy())
        return q[2] < 0.0  # elbow on the other side than q_true

    res = ik.solve(
        robot, target, IKOptions(frame="tool0", timeout_ms=2000), seed=q_true, accept=accept
    )
    assert calls and res.success and res.q[2] < 0.0
    dp, dr = pose_error(reference_pose(robot, res.q, "tool0"), target.homogeneous)
    assert dp <= TOL and dr <= TOL
    # every solution refused: the search ends when its budget does (a fake clock, 1 ms a read)
    never = ik.solve(
        robot,
        target,
        IKOptions(frame="tool0", timeout_ms=10.0),
        accept=lambda q: False,
        clock=_ticking(1e-3),
    )
    assert not never.success and never.solutions == []
    assert never.status == "timeout"


def _ticking(step: float):
    """A fake clock (s) advancing by ``step`` at each read."""
    reads = [0]

    def clock() -> float:
        reads[0] += 1
        return reads[0] * step

    return clock


@pytest.mark.parametrize("mode", ["pose", "position"])  # the compiled loop, the Python loop
def test_budget_exhausted_by_a_fake_clock_reports_timeout(registry, mode: str) -> None:
    """A reachable target, tolerances no iterate meets, a clock advancing 1 ms per read and
    a 10 ms budget: ``timeout`` after a bounded number of reads, whatever the machine's load
    (real time plays no part)."""
    robot = registry.get("panda")
    target = se3(reference_pose(robot, np.array(PANDA_Q), "panda_link8"))
    options = IKOptions(
        frame="panda_link8", mode=mode, tolerance=(1e-300, 1e-300), timeout_ms=10.0,
        analytic=False,
    )  # fmt: skip
    res = ik.solve(robot, target, options, clock=_ticking(1e-3))
    assert not res.success and res.status == "timeout"
    assert res.solve_time_ms >= 10.0  # measured on the fake clock: past the budget
    assert 0 < res.iterations <= 10 * 4 * DEFAULT_PARAMETERS.attempt_cap


PANDA_Q = [0.3, 0.2, -0.2, -1.8, 0.1, 1.9, 0.5, 0.03]


def panda_two_solutions(robot: RobotModel) -> tuple[np.ndarray, np.ndarray, pin.SE3]:
    """Two configurations 0.5 rad apart (elbow swung about the shoulder–wrist line, other
    finger opening) that both place panda_link8 at one pose, checked by yourdfpy."""
    q_a = np.array(PANDA_Q)
    T = reference_pose(robot, q_a, "panda_link8")
    start = q_a + [0.6, 0.0, -0.6, 0.0, 0.0, 0.0, 0.0, -0.02]
    options = IKOptions(frame="panda_link8", tolerance=(1e-10, 1e-10), timeout_ms=BUDGET_MS)
    q_b = ik.solve(robot, se3(T), options, seed=start).q
    dp, dr = pose_error(reference_pose(robot, q_b, "panda_link8"), T)
    assert dp <= 1e-9 and dr <= 1e-9 and within_limits(robot, q_b)
    assert np.abs(q_b - q_a).max() > 0.5
    return q_a, q_b, se3(T)


@pytest.mark.parametrize("mode", ["pose", "position"])  # compiled and Python loops
def test_a_seed_that_solves_the_target_is_the_answer(registry, mode: str) -> None:
    """Each of two different solutions, given as the seed, comes back unchanged after one
    evaluation (the finger, which does not move the frame, keeps its seed value too)."""
    robot = registry.get("panda")
    options = IKOptions(frame="panda_link8", mode=mode, timeout_ms=BUDGET_MS)
    q_a, q_b, target = panda_two_solutions(robot)
    for q in (q_a, q_b):
        res = ik.solve(robot, target, options, seed=q)
        assert res.success and res.iterations <= 1 and res.restarts == 0
        np.testing.assert_array_equal(res.q, q)


def test_redundant_arm_answers_near_its_own_seed(registry) -> None:
    """Seeds near two different solutions of one pose: each answer stays by its own seed."""
    robot = registry.get("panda")
    q_a, q_b, target = panda_two_solutions(robot)
    options = IKOptions(frame="panda_link8", timeout_ms=BUDGET_MS)
    nudge = np.array([0.03, -0.02, 0.03, 0.02, -0.03, 0.02, 0.03, 0.0])
    for q in (q_a, q_b):
        res = ik.solve(robot, target, options, seed=q + nudge)
        assert res.success and res.restarts == 0
        assert np.abs(res.q - q).max() < 0.1


def test_closed_form_branch_nearest_the_seed_comes_first(registry) -> None:
    """UR5: every closed-form branch, given as the seed, is the answer."""
    robot = registry.get("ur5")
    target = reference_pose(robot, np.array([0.4, -1.1, 1.3, -0.6, 1.2, 0.3]), "tool0")
    branches = ik.solve(robot, se3(target), IKOptions(frame="tool0", num_solutions=8)).solutions
    assert len(branches) == 8
    for b in branches:
        res = ik.solve(robot, se3(target), IKOptions(frame="tool0"), seed=b.q)
        assert res.method == "analytic"
        np.testing.assert_allclose(res.q, b.q, atol=1e-12)
        dp, dr = pose_error(reference_pose(robot, res.q, "tool0"), target)
        assert dp <= TOL and dr <= TOL


@pytest.mark.parametrize(
    ("weights", "axis", "accepted"),
    [
        (None, (1.0, 0.0, 0.0), False),
        (None, (0.0, 0.0, 1.0), False),
        ((1, 1, 1, 1, 1, 0), (1.0, 0.0, 0.0), False),
        ((1, 1, 1, 1, 1, 0), (0.0, 0.0, 1.0), True),  # the error lies on a freed component
    ],
)
def test_offer_refuses_a_candidate_outside_the_orientation_tolerance(
    registry, weights, axis, accepted: bool
) -> None:
    """A candidate at the target position but 0.01 rad off in orientation (world axis
    ``axis``) is not a solution unless that rotation component is freed."""
    robot = registry.get("ur5")
    q = np.array([0.4, -1.1, 1.3, -0.6, 1.2, 0.3])
    T = reference_pose(robot, q, "tool0")
    # R R_tᵀ = exp(0.01·axis): the frame is rotated 0.01 rad about ``axis`` (world) from it.
    target = pin.SE3(pin.exp3(-0.01 * np.array(axis)) @ T[:3, :3], T[:3, 3].copy())
    options = IKOptions(frame="tool0", weights=weights)
    ch = ik_chain(robot, "tool0")
    search = Search(IKProblem(robot, ch, target, q, options, options.task()))
    dp, dr = pose_error(T, target.homogeneous)
    assert dp <= 1e-12 and dr == pytest.approx(0.01)  # meets position, not orientation
    assert search.offer(q[ch.active]) is accepted
    assert len(search.solutions) == accepted


@pytest.mark.parametrize(("mode", "accepted"), [("pose", False), ("orientation", True)])
def test_offer_refuses_a_candidate_outside_the_position_tolerance(
    registry, mode: str, accepted: bool
) -> None:
    """A candidate at the target orientation but 1 mm away is a solution only when the
    position is free."""
    robot = registry.get("ur5")
    q = np.array([0.4, -1.1, 1.3, -0.6, 1.2, 0.3])
    T = reference_pose(robot, q, "tool0")
    target = pin.SE3(T[:3, :3].copy(), T[:3, 3] + [0.0, 1e-3, 0.0])
    options = IKOptions(frame="tool0", mode=mode)
    ch = ik_chain(robot, "tool0")
    search = Search(IKProblem(robot, ch, target, q, options, options.task()))
    assert search.offer(q[ch.active]) is accepted
    assert len(search.solutions) == accepted


def test_quaternion_target_matches_matrix(registry) -> None:
    robot = registry.get("ur5")
    quat = np.array([0.1, 0.7, -0.2, 0.67])
    quat /= np.linalg.norm(quat)
    R = quaternion_to_matrix(quat)
    target = pin.SE3(R, np.array([0.3, 0.2, 0.4]))
    res = ik.solve(robot, target, IKOptions(frame="tool0", timeout_ms=BUDGET_MS))
    assert res.success
    dp, dr = pose_error(reference_pose(robot, res.q, "tool0"), target.homogeneous)
    assert dp <= TOL and dr <= TOL


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"mode": "twist"}, "mode"),
        ({"num_solutions": 0}, "num_solutions"),
        ({"timeout_ms": -1.0}, "timeout_ms"),
        ({"max_iterations": 0}, "max_iterations"),
        ({"tolerance": (0.0, 1e-5)}, "tolerance"),
        ({"weights": (1, 1, 1, 1, 1, -1.0)}, "weights"),
        ({"weights": (0.0,) * 6}, "weights"),
    ],
)
def test_bad_options(kwargs: dict, field: str) -> None:
    with pytest.raises(InvalidInputError) as err:
        IKOptions(frame="tool0", **kwargs)
    assert err.value.field == field


def test_bad_seed(registry) -> None:
    with pytest.raises(InvalidInputError) as err:
        ik.solve(
            registry.get("ur5"), pin.SE3.Identity(), IKOptions(frame="tool0"), seed=np.zeros(3)
        )
    assert err.value.field == "seed"


def test_unknown_frame(registry) -> None:
    with pytest.raises(UnknownNameError):
        ik.solve(registry.get("ur5"), pin.SE3.Identity(), IKOptions(frame="tool9"))


def test_error_jacobian_and_step_equivalence(registry) -> None:
    """J_e = [J_v; Jlog3(R_e)ᵀ J_ω] matches finite differences of e = [p − p_t; log3(R R_tᵀ)],
    and J_e·Δq = −e has the same minimum-norm solution as J·Δq = −e (Jlog3ᵀ φ = φ)."""
    robot = registry.get("panda")
    fid = robot.frame_id("panda_link8")
    q0 = robot.mid_range()
    q0[:7] = [0.3, -0.4, 0.2, -2.0, 0.1, 1.5, 0.4]
    target = pin.SE3(pin.rpy.rpyToMatrix(0.4, -0.3, 1.1), np.array([0.4, 0.1, 0.5]))

    def err(q: np.ndarray) -> np.ndarray:
        T = reference_pose(robot, q, "panda_link8")
        return np.concatenate(
            [T[:3, 3] - target.translation, pin.log3(T[:3, :3] @ target.rotation.T)]
        )

    pin.computeJointJacobians(robot.model, robot.data, robot.to_pin(q0))
    T = pin.updateFramePlacement(robot.model, robot.data, fid)
    J = pin.getFrameJacobian(robot.model, robot.data, fid, pin.LOCAL_WORLD_ALIGNED)[:, :7]
    Re = T.rotation @ target.rotation.T
    Je = np.vstack([J[:3], pin.Jlog3(Re).T @ J[3:]])
    h = 1e-6
    fd = np.array(
        [(err(q0 + h * np.eye(robot.n)[i]) - err(q0 - h * np.eye(robot.n)[i])) / (2 * h)
         for i in range(7)]
    ).T  # fmt: skip
    np.testing.assert_allclose(Je, fd, atol=1e-6)
    e = err(q0)
    np.testing.assert_allclose(np.linalg.pinv(Je) @ e, np.linalg.pinv(J) @ e, rtol=1e-9, atol=1e-12)
