"""IK branches, ranking and typed failures, against references.

Branch flags are checked against definitions computed independently of the code's triple
products: yourdfpy link frames, finite differences, the textbook joint-space signs (UR:
sin q5; planar arm: θ2), and the 8 closed-form solutions of a UR5 pose verified by yourdfpy
forward kinematics. Budgets are iteration caps with generous time limits.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics import ik
from app.kinematics.ik.branches import branch_form, branch_label
from app.kinematics.ik.failure import UNREACHABLE_ITERATIONS, reach_bound
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.ik.problem import IKOptions
from app.kinematics.ik.ranking import CLUSTER_THRESHOLD, Grouping
from app.kinematics.models import RobotModel
from tests.kinematics.chains import planar_2link
from tests.kinematics.reference import (
    TOL,
    _urdf,
    pose_error,
    random_q,
    reference_pose,
    se3,
    within_limits,
)

BUDGET_MS = 5000.0
#: A generic UR5 configuration (no joint near a singularity) and its pose.
UR5_Q = np.array([0.3, -1.1, 1.4, -0.6, 0.9, 0.2])


def _frames(robot: RobotModel, q: np.ndarray, links: list[str]) -> list[np.ndarray]:
    """World transforms of ``links`` by yourdfpy."""
    urdf = _urdf(robot)
    urdf.update_cfg(q)
    return [urdf.get_transform(link, urdf.base_link) for link in links]


# ----------------------------------------------------------------------------- UR5 flags
def _closest_point(p1: np.ndarray, w1: np.ndarray, p2: np.ndarray, w2: np.ndarray) -> np.ndarray:
    """The point of line (p1, w1) closest to line (p2, w2) (non-parallel lines)."""
    A = np.array([[w1 @ w1, -(w1 @ w2)], [w1 @ w2, -(w2 @ w2)]])
    t, _ = np.linalg.solve(A, np.array([(p2 - p1) @ w1, (p2 - p1) @ w2]))
    return p1 + t * w1


def _ur5_wrist_point(robot: RobotModel, q: np.ndarray) -> np.ndarray:
    """The common point of axes 5 and 6 (yourdfpy frames, URDF axes)."""
    T5, T6 = _frames(robot, q, ["wrist_2_link", "wrist_3_link"])
    p5, w5 = T5[:3, 3], T5[:3, :3] @ np.array(robot.joints[4].axis)
    p6, w6 = T6[:3, 3], T6[:3, :3] @ np.array(robot.joints[5].axis)
    return _closest_point(p5, w5, p6, w6)


def _ur5_reference_flags(robot: RobotModel, q: np.ndarray) -> tuple[str, str, str] | None:
    """The textbook flags of a UR5 configuration, or None near a branch boundary.

    shoulder: right when raising joint 2 raises the wrist point (finite difference, world z
    = axis 1); elbow: up when the turn from the upper arm (axis 2 → axis 3) to the forearm
    (axis 3 → axis 4) about axis 2, in the arm plane, has the opposite sign of that rise
    (for a right shoulder: a clockwise turn about axis 2); both change sign only at a
    singularity (the elbow stretched or folded, the wrist point above the shoulder);
    wrist: noflip when sin q5 > 0.
    """
    h = 1e-6
    dq = np.zeros(6)
    dq[1] = h
    dz = (_ur5_wrist_point(robot, q + dq) - _ur5_wrist_point(robot, q - dq))[2] / (2 * h)
    Ts, Te, Tt = _frames(robot, q, ["upper_arm_link", "forearm_link", "wrist_1_link"])
    n = Ts[:3, :3] @ np.array(robot.joints[1].axis)
    P = np.eye(3) - np.outer(n, n)
    s, e, t = P @ Ts[:3, 3], P @ Te[:3, 3], P @ Tt[:3, 3]
    turn = float(n @ np.cross(e - s, t - e))
    if abs(dz) < 1e-3 or abs(turn) < 1e-3 or abs(math.sin(q[4])) < 1e-3:
        return None
    return (
        "shoulder_right" if dz > 0 else "shoulder_left",
        "elbow_up" if turn * dz < 0 else "elbow_down",
        "wrist_noflip" if math.sin(q[4]) > 0 else "wrist_flip",
    )


def test_ur5_flags_match_the_textbook_definitions(registry) -> None:
    robot = registry.get("ur5")
    ch = ik_chain(robot, "tool0")
    rng = np.random.default_rng(13)
    checked = 0
    for _ in range(200):
        q = rng.uniform(-math.pi, math.pi, 6)
        ref = _ur5_reference_flags(robot, q)
        if ref is None:
            continue
        assert branch_label(robot, ch, q) == "/".join(ref), q
        checked += 1
    assert checked > 150


def test_ur5_flipping_q5_flips_only_the_wrist(registry) -> None:
    robot = registry.get("ur5")
    ch = ik_chain(robot, "tool0")
    a = branch_label(robot, ch, UR5_Q).split("/")
    q = UR5_Q.copy()
    q[4] = -q[4]
    b = branch_label(robot, ch, q).split("/")
    assert a[:2] == b[:2] and {a[2], b[2]} == {"wrist_flip", "wrist_noflip"}


def test_ur5_eight_closed_form_solutions_have_eight_labels(registry) -> None:
    robot = registry.get("ur5")
    target = reference_pose(robot, UR5_Q, "tool0")
    options = IKOptions(frame="tool0", num_solutions=8, timeout_ms=BUDGET_MS, max_iterations=2000)
    res = ik.solve(robot, se3(target), options, seed=UR5_Q)
    assert res.success and len(res.solutions) == 8
    labels = [s.branch for s in res.solutions]
    assert len(set(labels)) == 8
    assert set(labels) == {
        f"shoulder_{s}/elbow_{e}/wrist_{w}"
        for s, e, w in itertools.product(("left", "right"), ("up", "down"), ("flip", "noflip"))
    }
    for sol in res.solutions:
        assert within_limits(robot, sol.q)
        dp, dr = pose_error(reference_pose(robot, sol.q, "tool0"), target)
        assert dp <= TOL and dr <= TOL
        ref = _ur5_reference_flags(robot, sol.q)
        assert ref is None or sol.branch == "/".join(ref)
    # The seed's own configuration is one of them, at distance 0, answered first.
    assert res.solutions[0].seed_distance == pytest.approx(0.0, abs=1e-9)


# ------------------------------------------------------------------ other structures
def test_puma560_spherical_wrist_is_detected(registry) -> None:
    robot = registry.get("puma560")
    ch = ik_chain(robot, "tool")
    form = branch_form(robot, ch)
    assert form is not None and form.kind == "6r" and form.elbow and not form.tip_axis4
    # Independently: axes 4, 5, 6 meet in one point at random configurations (yourdfpy).
    rng = np.random.default_rng(4)
    for _ in range(5):
        q = random_q(robot, rng)
        T = _frames(robot, q, ["link_4", "link_5", "link_6"])
        p = [t[:3, 3] for t in T]
        w = [t[:3, :3] @ np.array(robot.joints[i].axis) for t, i in zip(T, (3, 4, 5), strict=True)]
        c = _closest_point(p[0], w[0], p[1], w[1])  # on axis 4, nearest axis 5
        for pi, wi in zip(p, w, strict=True):  # c lies on axes 4, 5 and 6
            assert np.linalg.norm(np.cross(c - pi, wi / np.linalg.norm(wi))) < 1e-9


def test_puma560_wrist_flip_solution_changes_only_the_wrist_flag(registry) -> None:
    """(q4 + π, −q5, q6 + π) reaches the same pose (yourdfpy): the other wrist branch."""
    robot = registry.get("puma560")
    ch = ik_chain(robot, "tool")
    q = np.array([0.3, 0.8, -0.9, 0.4, 0.7, 0.2])
    flipped = q + np.array([0, 0, 0, math.pi, 0, math.pi])
    flipped[4] = -q[4]
    dp, dr = pose_error(reference_pose(robot, flipped, "tool"), reference_pose(robot, q, "tool"))
    assert dp < 1e-12 and dr < 1e-9
    a, b = branch_label(robot, ch, q).split("/"), branch_label(robot, ch, flipped).split("/")
    assert a[:2] == b[:2] and a[2] != b[2]


def test_stanford_arm_has_no_elbow_flag_and_panda_no_flags(registry) -> None:
    stanford = registry.get("stanford_arm")
    label = branch_label(stanford, ik_chain(stanford, "tool"), stanford.mid_range())
    assert label is not None and label.startswith("shoulder_") and "elbow" not in label
    panda = registry.get("panda")
    ch = ik_chain(panda, "panda_link8")
    assert branch_form(panda, ch) is None and branch_label(panda, ch, panda.mid_range()) is None


def test_planar2_elbows_are_labelled_by_the_sign_of_theta2(registry) -> None:
    """elbow_up ⇔ θ2 ∈ (0, π) (the planar DH arm, l1 = 1, l2 = 0.8)."""
    robot = registry.get("planar2")
    ch = ik_chain(robot, robot.ee_frame)
    t1, t2 = 0.4, 1.1
    target = np.array(
        [math.cos(t1) + 0.8 * math.cos(t1 + t2), math.sin(t1) + 0.8 * math.sin(t1 + t2), 0]
    )
    options = IKOptions(
        frame=robot.ee_frame, mode="position", num_solutions=2, timeout_ms=BUDGET_MS,
        max_iterations=500,
    )  # fmt: skip
    res = ik.solve(robot, pin.SE3(np.eye(3), target), options)
    assert res.success and len(res.solutions) == 2
    for sol in res.solutions:
        assert sol.branch == ("elbow_up" if math.sin(sol.q[1]) > 0 else "elbow_down")
        assert np.linalg.norm(reference_pose(robot, sol.q, robot.ee_frame)[:3, 3] - target) < TOL
    assert {s.branch for s in res.solutions} == {"elbow_up", "elbow_down"}
    for theta2 in (0.3, 2.0, -0.3, -2.0):
        expected = "elbow_up" if theta2 > 0 else "elbow_down"
        assert branch_label(robot, ch, np.array([0.7, theta2])) == expected


# ------------------------------------------------------------------------------ clusters
def test_clusters_are_single_linkage_at_the_threshold(registry) -> None:
    robot = registry.get("panda")
    g = Grouping(robot, ik_chain(robot, "panda_link8"))
    base = robot.mid_range()
    step = np.zeros(robot.n)
    step[2] = 0.8 * CLUSTER_THRESHOLD
    g.add(base)
    g.add(base + step)  # linked to the first
    assert g.count == 1
    g.add(base + 2 * step)  # 1.6 × threshold from the first, linked through the second
    assert g.count == 1
    far = base.copy()
    far[0] += 1.01 * CLUSTER_THRESHOLD
    g.add(far)
    assert g.count == 2
    keys = g.keys()
    assert keys[0] == keys[1] == keys[2] != keys[3]


def test_panda_solutions_are_distinct_clusters_nearest_the_seed_first(registry) -> None:
    robot = registry.get("panda")
    seed = robot.mid_range()
    q_true = np.array([0.5, 0.3, -0.2, -1.8, 0.1, 2.0, 0.4] + [0.0] * (robot.n - 7))
    target = reference_pose(robot, q_true, "panda_link8")
    options = IKOptions(
        frame="panda_link8", num_solutions=5, timeout_ms=BUDGET_MS, max_iterations=4000
    )
    res = ik.solve(robot, se3(target), options, seed=seed, rng=np.random.default_rng(3))
    assert res.success and len(res.solutions) >= 2
    assert [s.branch for s in res.solutions] == [f"cluster_{k}" for k in range(len(res.solutions))]
    moves = [float(np.abs(s.q - seed).max()) for s in res.solutions]
    assert [s.seed_distance for s in res.solutions] == pytest.approx(moves, abs=1e-12)
    assert moves == sorted(moves)
    for a, b in itertools.combinations(res.solutions, 2):
        assert np.abs(a.q - b.q).max() > CLUSTER_THRESHOLD
    for sol in res.solutions:
        dp, dr = pose_error(reference_pose(robot, sol.q, "panda_link8"), target)
        assert dp <= TOL and dr <= TOL


# ----------------------------------------------------------------------------- ranking
def _yoshikawa_fd(robot: RobotModel, q: np.ndarray, frame: str) -> float:
    """|det J| of a 6-joint arm, J by central differences of yourdfpy poses (world axes)."""
    h = 1e-6
    J = np.zeros((6, 6))
    for i in range(6):
        dq = np.zeros(robot.n)
        dq[i] = h
        Tp, Tm = reference_pose(robot, q + dq, frame), reference_pose(robot, q - dq, frame)
        J[:3, i] = (Tp[:3, 3] - Tm[:3, 3]) / (2 * h)
        J[3:, i] = pin.log3(Tp[:3, :3] @ Tm[:3, :3].T) / (2 * h)
    return abs(float(np.linalg.det(J)))


def test_rank_by_manipulability_orders_by_yoshikawa(registry) -> None:
    robot = registry.get("ur5")
    target = reference_pose(robot, UR5_Q, "tool0")
    options = IKOptions(
        frame="tool0", num_solutions=8, timeout_ms=BUDGET_MS, max_iterations=2000,
        rank_by="manipulability",
    )  # fmt: skip
    res = ik.solve(robot, se3(target), options, seed=UR5_Q)
    assert len(res.solutions) == 8
    w = [s.manipulability for s in res.solutions]
    assert w == sorted(w, reverse=True)
    for sol in res.solutions:
        assert sol.manipulability == pytest.approx(_yoshikawa_fd(robot, sol.q, "tool0"), rel=1e-5)
    assert res.q.tolist() == res.solutions[0].q.tolist()


# ----------------------------------------------------------------------------- failures
def test_reach_bound_holds_for_random_configurations(registry) -> None:
    """|p(q) − b| ≤ R (yourdfpy FK) on arms with offsets, prismatic joints and a tool."""
    rng = np.random.default_rng(21)
    for robot_id in ("ur5", "panda", "puma560", "stanford_arm", "rrp"):
        robot = registry.get(robot_id)
        ch = ik_chain(robot, robot.ee_frame)
        b, reach = reach_bound(robot, ch, robot.mid_range())
        for _ in range(200):
            q = random_q(robot, rng)
            d = np.linalg.norm(reference_pose(robot, q, robot.ee_frame)[:3, 3] - b)
            assert d <= reach + 1e-12, (robot_id, d, reach)


def test_unreachable_target_is_answered_without_a_search(registry) -> None:
    robot = registry.get("ur5")
    target = pin.SE3(np.eye(3), np.array([10.0, 0.0, 0.0]))
    res = ik.solve(robot, target, IKOptions(frame="tool0", timeout_ms=BUDGET_MS))
    assert not res.success and res.reason == "unreachable"
    assert res.iterations <= UNREACHABLE_ITERATIONS and res.restarts <= UNREACHABLE_ITERATIONS
    assert "10" in res.detail and "m" in res.detail
    # Orientation mode has no position to bound: no short cut, no unreachable.
    res = ik.solve(
        robot,
        target,
        IKOptions(frame="tool0", mode="orientation", timeout_ms=BUDGET_MS, max_iterations=200),
    )
    assert res.success and res.reason is None and res.detail is None


def test_joint_limits_reason_closed_form_and_numeric() -> None:
    """A planar arm whose joints stop at ±0.5 rad: the target needs θ2 = ±1.2."""
    robot = RobotModel("tight2", planar_2link(1.0, 0.7, limit=0.5), ee_frame="tip")
    t1, t2 = 0.2, 1.2
    target = np.array(
        [math.cos(t1) + 0.7 * math.cos(t1 + t2), math.sin(t1) + 0.7 * math.sin(t1 + t2), 0]
    )
    for analytic in (True, False):
        options = IKOptions(
            frame="tip", mode="position", timeout_ms=BUDGET_MS, max_iterations=300,
            analytic=analytic,
        )  # fmt: skip
        res = ik.solve(robot, pin.SE3(np.eye(3), target), options)
        assert not res.success and res.reason == "joint_limits", (analytic, res.detail)
        assert "j2" in res.detail
        assert within_limits(robot, res.q)


def test_singular_reason_at_a_stretched_arm() -> None:
    """A 2-link arm whose forearm is lifted 0.5 m: its reach bound (1.92 m) exceeds its reach
    in the plane (1.8 m); a target 1.85 m out is searched and the best configuration is the
    stretched arm, where the two columns of the position Jacobian are parallel."""
    urdf = planar_2link(1.0, 0.8, name="lifted2").replace(
        '<origin xyz="1.0 0 0" rpy="0 0 0"/>', '<origin xyz="1.0 0 0.5" rpy="0 0 0"/>'
    )
    robot = RobotModel("lifted2", urdf, ee_frame="tip")
    options = IKOptions(frame="tip", mode="position", timeout_ms=BUDGET_MS, max_iterations=300)
    target = pin.SE3(np.eye(3), np.array([1.85 * math.cos(0.6), 1.85 * math.sin(0.6), 0.5]))
    res = ik.solve(robot, target, options, seed=np.array([0.3, 0.9]))
    assert not res.success and res.reason == "singular", res.detail
    assert res.position_error == pytest.approx(0.05, abs=1e-3)  # 1.85 − 1.8
    assert abs(math.sin(res.q[1])) < 0.05  # (nearly) stretched


def test_collision_reason_when_accept_rejects_every_solution(registry) -> None:
    robot = registry.get("ur5")
    target = reference_pose(robot, UR5_Q, "tool0")
    options = IKOptions(frame="tool0", timeout_ms=BUDGET_MS, max_iterations=300)
    res = ik.solve(robot, se3(target), options, accept=lambda q: False)
    assert not res.success and res.reason == "collision" and "collide" in res.detail


def test_timeout_reason_names_the_iteration_cap(registry) -> None:
    robot = registry.get("ur5")
    seed = UR5_Q
    target = reference_pose(robot, np.array([1.0, -1.5, 1.0, 0.6, -0.9, 1.2]), "tool0")
    options = IKOptions(frame="tool0", timeout_ms=BUDGET_MS, max_iterations=2, analytic=False)
    res = ik.solve(robot, se3(target), options, seed=seed)
    assert not res.success and res.reason == "timeout"
    assert "max_iterations = 2" in res.detail
    assert res.status == "not_converged"


def test_success_has_no_reason(registry) -> None:
    robot = registry.get("ur5")
    res = ik.solve(robot, se3(reference_pose(robot, UR5_Q, "tool0")), IKOptions(frame="tool0"))
    assert res.success and res.reason is None and res.detail is None


@pytest.mark.parametrize("robot_id", ["ur5", "puma560"])
def test_labels_change_only_at_singularities(registry, robot_id) -> None:
    """Along short joint-space segments sampled finely, the label changes only where the
    frame Jacobian's smallest singular value dips near 0 in between: a path that keeps away
    from singularities keeps its whole label (the UR5 configuration is where an elbow flag
    taken on the side of axis 4, not of the wrist point, flipped at σ_min ≈ 0.03)."""
    robot = registry.get(robot_id)
    frame = robot.ee_frame
    ch = ik_chain(robot, frame)
    rng = np.random.default_rng(5)
    starts = [np.array([-2.006, 2.530, -2.049, 1.993, -3.717, -0.736])] if robot_id == "ur5" else []
    starts += [random_q(robot, rng) for _ in range(60)]
    fid = robot.frame_id(frame)
    data = robot.model.createData()
    changes = 0
    for q0 in starts:
        q1 = np.clip(q0 + rng.uniform(-0.4, 0.4, 6), robot.lower, robot.upper)
        labels, sigmas = [], []
        for u in np.linspace(0.0, 1.0, 81):
            q = q0 + u * (q1 - q0)
            labels.append(branch_label(robot, ch, q))
            J = pin.computeFrameJacobian(
                robot.model, data, robot.to_pin(q), fid, pin.LOCAL_WORLD_ALIGNED
            )
            sigmas.append(np.linalg.svd(J, compute_uv=False)[-1])
        for i in range(len(labels) - 1):
            if labels[i] != labels[i + 1]:
                changes += 1
                assert min(sigmas[max(0, i - 1) : i + 3]) < 0.02, (q0, q1, i, labels[i : i + 2])
    assert changes > 0  # the segments do cross branch boundaries (the test can fail)
