"""Mimic joints in the core: supports, Jacobians, IK, joint maps, map bounds.

References are independent of the code under test: a closed form for a planar robot whose
follower (multiplier −2, offset 0.1) sits on another branch than its leader, central finite
differences of yourdfpy's forward kinematics (which applies URDF ``<mimic>`` itself) for the
Panda's ``panda_rightfinger``, and yourdfpy poses for IK answers.
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics import ik
from app.kinematics.errors import InvalidInputError, UnknownNameError
from app.kinematics.ik.problem import IKOptions, seed_configuration
from app.kinematics.jacobian import frame_jacobian
from app.kinematics.models import RobotModel
from app.kinematics.reachability.spec import default_bounds
from app.kinematics.velocity import inverse_velocity
from tests.kinematics.reference import _urdf as reference_urdf
from tests.kinematics.reference import pose_error, random_configurations, reference_pose, se3

L1, L2, MULT, OFFSET = 0.8, 0.5, -2.0, 0.1

#: ``drive`` (revolute z at the base, its own leaf branch) is the leader of ``follow``
#: (revolute z at the end of link1, on the other branch: base → j1 → link1 → follow → link2
#: → tip). Pinocchio's support of ``tip`` is {j1, follow}: the leader is elsewhere. (Pinocchio
#: needs a leader parsed before its followers, sibling branches in joint-name order: drive < j1.)
PLANAR_MIMIC = f"""<?xml version="1.0"?>
<robot name="planar_mimic">
  <link name="base"/><link name="drive_link"/><link name="link1"/><link name="link2"/>
  <link name="tip"/>
  <joint name="drive" type="revolute">
    <parent link="base"/><child link="drive_link"/>
    <origin xyz="0 0.3 0"/><axis xyz="0 0 1"/>
    <limit lower="-1.5" upper="1.5" velocity="1" effort="1"/>
  </joint>
  <joint name="j1" type="revolute">
    <parent link="base"/><child link="link1"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" velocity="1" effort="1"/>
  </joint>
  <joint name="follow" type="revolute">
    <parent link="link1"/><child link="link2"/>
    <origin xyz="{L1} 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-4" upper="4" velocity="1" effort="1"/>
    <mimic joint="drive" multiplier="{MULT}" offset="{OFFSET}"/>
  </joint>
  <joint name="tip_joint" type="fixed">
    <parent link="link2"/><child link="tip"/><origin xyz="{L2} 0 0"/>
  </joint>
</robot>"""


def _closed_form(lead: float, q1: float) -> tuple[np.ndarray, float, np.ndarray]:
    """Tip position, heading and world Jacobian (6×2: lead, j1) of the planar robot."""
    a12 = q1 + MULT * lead + OFFSET
    p = np.array(
        [L1 * math.cos(q1) + L2 * math.cos(a12), L1 * math.sin(q1) + L2 * math.sin(a12), 0]
    )
    d_lead = MULT * np.array([-L2 * math.sin(a12), L2 * math.cos(a12), 0, 0, 0, 1])
    d_q1 = np.array([-p[1], p[0], 0, 0, 0, 1])
    return p, a12, np.column_stack([d_lead, d_q1])


@pytest.fixture(scope="module")
def planar() -> RobotModel:
    robot = RobotModel("planar_mimic", PLANAR_MIMIC)
    assert reference_urdf(robot).actuated_joint_names == robot.joint_names == ["drive", "j1"]
    return robot


@pytest.mark.parametrize(("lead", "q1"), [(0.0, 0.0), (0.3, -1.2), (-1.1, 2.5), (1.4, 0.7)])
def test_planar_mimic_fk_and_jacobian_match_the_closed_form(planar, lead, q1) -> None:
    follow = MULT * lead + OFFSET
    q = planar.configuration(joint_positions={"drive": lead, "j1": q1, "follow": follow})
    T = planar.model.createData()
    pin.framesForwardKinematics(planar.model, T, planar.to_pin(q))
    M = T.oMf[planar.frame_id("tip")]
    p, heading, J_ref = _closed_form(lead, q1)
    np.testing.assert_allclose(M.translation, p, atol=1e-12)
    np.testing.assert_allclose(M.rotation, pin.exp3(np.array([0, 0, heading])), atol=1e-12)
    cols = planar.supporting_joints("tip")
    assert [planar.joint_names[c] for c in cols] == ["drive", "j1"]
    J = frame_jacobian(planar, q, "tip")
    np.testing.assert_allclose(J[:, cols], J_ref, atol=1e-12)


def test_planar_mimic_inverse_velocity_uses_the_leader(planar) -> None:
    """A tip velocity only the leader can give (j1 fixed would need the other column)."""
    q = planar.configuration(joint_positions={"drive": 0.2, "j1": -0.4})
    _, _, J_ref = _closed_form(0.2, -0.4)
    twist = J_ref @ np.array([0.7, -0.3])
    res = inverse_velocity(planar, q, twist, "tip", "world")
    np.testing.assert_allclose(res.joint_velocities, [0.7, -0.3], atol=1e-9)


@pytest.mark.parametrize("mode", ["position", "pose"])
def test_planar_mimic_ik_moves_the_leader_without_a_wrong_closed_form(planar, mode) -> None:
    """The tip's moving joints (drive, j1) look like a planar 2R arm but are not one: no
    closed form is tried, and the numeric solver reaches every target (yourdfpy-checked)."""
    targets = random_configurations(planar, 50, seed=3)
    seeds = random_configurations(planar, 50, seed=4)
    options = IKOptions(frame="tip", mode=mode, timeout_ms=60_000.0, max_iterations=500)
    for q_t, seed in zip(targets, seeds, strict=True):
        T = reference_pose(planar, q_t, "tip")
        res = ik.solve(planar, se3(T), options, seed=seed)
        assert res.success and res.method == "numeric"
        dp, dr = pose_error(reference_pose(planar, res.q, "tip"), T)
        assert dp < 1e-5 and (mode == "position" or dr < 1e-5)


def _fd_jacobian(robot: RobotModel, q: np.ndarray, frame: str, h: float = 1e-6) -> np.ndarray:
    """Central differences of yourdfpy FK (world-aligned twist) over every wire joint."""
    J = np.zeros((6, robot.n))
    for i in range(robot.n):
        e = np.zeros(robot.n)
        e[i] = h
        Tp = reference_pose(robot, q + e, frame)
        Tm = reference_pose(robot, q - e, frame)
        J[:3, i] = (Tp[:3, 3] - Tm[:3, 3]) / (2 * h)
        J[3:, i] = pin.log3(Tp[:3, :3] @ Tm[:3, :3].T) / (2 * h)
    return J


def test_panda_rightfinger_jacobian_and_support_follow_the_leader(registry) -> None:
    """The leader's column of a link under a follower equals moving the leader in yourdfpy's
    FK (the follower following), and the leader is among the joints that move the link."""
    robot = registry.get("panda")
    assert reference_urdf(robot).actuated_joint_names == robot.joint_names  # same q order
    qs = random_configurations(robot, 5, seed=16)
    for q in qs:
        q[7] = min(q[7], 0.039)  # room for the +h step inside the finger's limits
        J_fd = _fd_jacobian(robot, q, "panda_rightfinger")
        J = frame_jacobian(robot, q, "panda_rightfinger")
        np.testing.assert_allclose(J, J_fd, atol=1e-7)
        moving = set(np.flatnonzero(np.abs(J_fd).max(axis=0) > 1e-6))
        assert moving == set(robot.supporting_joints("panda_rightfinger").tolist())
        assert 7 in moving


def test_ik_on_panda_rightfinger_moves_the_finger(registry) -> None:
    """Reachable targets (yourdfpy FK of random configurations) from seeds elsewhere: ≥ 99 %
    solved under an iteration cap, checked with yourdfpy, the finger leader moving."""
    robot = registry.get("panda")
    targets = random_configurations(robot, 200, seed=1)
    seeds = random_configurations(robot, 200, seed=2)
    options = IKOptions(frame="panda_rightfinger", timeout_ms=60_000.0, max_iterations=2000)
    solved = moved = 0
    for q_t, seed in zip(targets, seeds, strict=True):
        T = reference_pose(robot, q_t, "panda_rightfinger")
        res = ik.solve(robot, se3(T), options, seed=seed)
        if not res.success:
            continue
        dp, dr = pose_error(reference_pose(robot, res.q, "panda_rightfinger"), T)
        assert dp < 1e-5 and dr < 1e-5
        solved += 1
        moved += abs(res.q[7] - seed[7]) > 1e-6
    assert solved >= 198, solved
    assert moved >= 100, moved


def test_joint_map_accepts_consistent_followers(registry) -> None:
    robot = registry.get("panda")
    arm = dict(zip(robot.joint_names[:7], [0.1, -0.2, 0.3, -1.5, 0.4, 1.2, -0.5], strict=True))
    state = {**arm, "panda_finger_joint1": 0.021, "panda_finger_joint2": 0.021}
    expected = robot.configuration(joint_positions={**arm, "panda_finger_joint1": 0.021})
    np.testing.assert_array_equal(robot.configuration(joint_positions=state), expected)
    np.testing.assert_array_equal(seed_configuration(robot, state)[:8], expected)
    # within 1e-9 of multiplier × leader + offset: accepted
    robot.configuration(joint_positions={**state, "panda_finger_joint2": 0.021 + 5e-10})
    # the leader absent: checked against its default (0 for the Panda's finger)
    robot.configuration(joint_positions={"panda_finger_joint2": 0.0})


@pytest.mark.parametrize(
    ("values", "expected"),
    [
        ({"panda_finger_joint1": 0.02, "panda_finger_joint2": 0.03}, "0.02"),
        ({"panda_finger_joint1": 0.02, "panda_finger_joint2": 0.02 + 2e-9}, "0.02"),
        ({"panda_finger_joint2": 0.01}, "0.0"),
    ],
)
def test_joint_map_refuses_an_inconsistent_follower(registry, values, expected) -> None:
    robot = registry.get("panda")
    for build in (
        lambda: robot.configuration(joint_positions=values),
        lambda: seed_configuration(robot, values),
    ):
        with pytest.raises(InvalidInputError) as e:
            build()
        assert e.value.field.endswith(".panda_finger_joint2")
        assert (
            f"expected {expected}" in e.value.message and "panda_finger_joint1" in e.value.message
        )


def test_joint_map_checks_multiplier_and_offset(planar) -> None:
    planar.configuration(joint_positions={"drive": 0.5, "follow": -0.9})
    with pytest.raises(InvalidInputError) as e:
        planar.configuration(joint_positions={"drive": 0.5, "follow": 0.5})
    assert e.value.field == "joint_positions.follow" and "expected -0.9" in e.value.message


def test_unknown_joint_suggests_followers_too(registry) -> None:
    with pytest.raises(UnknownNameError) as e:
        registry.get("panda").configuration(joint_positions={"panda_finger_joint3": 0.0})
    assert e.value.field == "joint_positions.panda_finger_joint3"
    assert "panda_finger_joint2" in e.value.suggestions


PRISMATIC_MIMIC = """<?xml version="1.0"?>
<robot name="slides">
  <link name="base"/><link name="a"/><link name="b"/>
  <joint name="slide_a" type="prismatic">
    <parent link="base"/><child link="a"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="2" velocity="1" effort="1"/>
  </joint>
  <joint name="slide_b" type="prismatic">
    <parent link="base"/><child link="b"/><origin xyz="0 0 0.5"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="2" velocity="1" effort="1"/>
    <mimic joint="slide_a" multiplier="1.5" offset="-0.2"/>
  </joint>
</robot>"""


def test_reachability_bounds_include_a_followers_travel() -> None:
    """The default map box of a link moved by a prismatic follower holds all its positions."""
    robot = RobotModel("slides", PRISMATIC_MIMIC)
    assert reference_urdf(robot).actuated_joint_names == robot.joint_names == ["slide_a"]
    lo, hi = default_bounds(robot, "b")
    for a in np.linspace(0.0, 2.0, 9):
        p = reference_pose(robot, np.array([a]), "b")[:3, 3]
        assert np.all(lo <= p) and np.all(p <= hi), (a, p, lo, hi)
