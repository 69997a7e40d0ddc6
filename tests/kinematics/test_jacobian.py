"""Jacobians against finite differences of FK and the course's geometric construction."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.fk import forward_kinematics
from app.kinematics.jacobian import frame_jacobian
from app.kinematics.models import RobotModel
from tests.kinematics.chains import continuous_arm, rrp_like
from tests.kinematics.reference import random_configurations

H = 1e-6


def fd_jacobian(robot: RobotModel, q: np.ndarray, frame: str) -> np.ndarray:
    """Central differences of FK: [d position; ω] in world axes (the `world` reference)."""
    J = np.zeros((6, robot.n))
    for i in range(robot.n):
        dq = np.zeros(robot.n)
        dq[i] = H
        Tp = forward_kinematics(robot, q + dq, [frame])[frame]
        Tm = forward_kinematics(robot, q - dq, [frame])[frame]
        J[:3, i] = (Tp[:3, 3] - Tm[:3, 3]) / (2 * H)
        J[3:, i] = pin.log3(Tp[:3, :3] @ Tm[:3, :3].T) / (2 * H)
    return J


def interior(robot: RobotModel, n: int, seed: int) -> np.ndarray:
    """Configurations at least H away from the limits, so differences stay inside."""
    qs = random_configurations(robot, n, seed)
    return np.clip(qs, robot.lower + 10 * H, robot.upper - 10 * H)


@pytest.mark.parametrize("robot_id", ["panda", "ur5", "kinova", "xarm", "z1", "so100"])
def test_world_jacobian_matches_finite_differences(registry, robot_id: str) -> None:
    robot = registry.get(robot_id)
    for q in interior(robot, 5, seed=11):
        J = frame_jacobian(robot, q, robot.ee_frame, "world")
        np.testing.assert_allclose(J, fd_jacobian(robot, q, robot.ee_frame), atol=1e-6)


def test_mimic_finger_column(registry) -> None:
    """Panda's finger_joint2 mimics finger_joint1: the right finger moves with joint 8."""
    robot = registry.get("panda")
    q = interior(robot, 1, seed=2)[0]
    J = frame_jacobian(robot, q, "panda_rightfinger", "world")
    np.testing.assert_allclose(J, fd_jacobian(robot, q, "panda_rightfinger"), atol=1e-6)
    assert np.linalg.norm(J[:3, 7]) > 0.5


def geometric_jacobian(robot: RobotModel, q: np.ndarray, frame: str, axes: list) -> np.ndarray:
    """The course's construction: [z × (o_n − o_i); z] revolute, [z; 0] prismatic.

    z is the joint axis in world axes and o_i a point on it (the child link's origin, where
    URDF puts the joint), both from FK of the links, not from any Jacobian routine.
    """
    links = [j.child for j in robot.joints]
    T = forward_kinematics(robot, q, [*links, frame])
    o_n = T[frame][:3, 3]
    J = np.zeros((6, robot.n))
    for i, (joint, axis) in enumerate(zip(robot.joints, axes, strict=True)):
        Ti = T[joint.child]
        z = Ti[:3, :3] @ np.asarray(axis, dtype=float)
        if joint.type == "prismatic":
            J[:3, i] = z
        else:
            J[:3, i] = np.cross(z, o_n - Ti[:3, 3])
            J[3:, i] = z
    return J


def test_geometric_construction_revolute_prismatic_chain() -> None:
    robot = RobotModel("rrp", rrp_like(), ee_frame="tip")
    assert [j.type for j in robot.joints] == ["revolute", "revolute", "prismatic"]
    for q in interior(robot, 20, seed=4):
        J = frame_jacobian(robot, q, "tip", "world")
        Jg = geometric_jacobian(robot, q, "tip", [(0, 0, 1), (0, 1, 0), (1, 0, 0)])
        Jfd = fd_jacobian(robot, q, "tip")
        np.testing.assert_allclose(J, Jg, atol=1e-12)
        np.testing.assert_allclose(J, Jfd, atol=1e-6)
        np.testing.assert_allclose(Jg, Jfd, atol=1e-6)


def test_continuous_joint_column() -> None:
    robot = RobotModel("c", continuous_arm())
    for q in [np.array([0.4, 0.3]), np.array([3.5, -0.2])]:
        J = frame_jacobian(robot, q, "l2", "world")
        np.testing.assert_allclose(J, fd_jacobian(robot, q, "l2"), atol=1e-6)
        assert J.shape == (6, 2)


@pytest.mark.parametrize("robot_id", ["panda", "kinova"])
def test_references_consistent(registry, robot_id: str) -> None:
    """local = blockdiag(Rᵀ, Rᵀ)·world; world_spatial linear = v + p × ω."""
    robot = registry.get(robot_id)
    for q in random_configurations(robot, 5, seed=8):
        frame = robot.ee_frame
        T = forward_kinematics(robot, q, [frame])[frame]
        R, p = T[:3, :3], T[:3, 3]
        Jw = frame_jacobian(robot, q, frame, "world")
        Jl = frame_jacobian(robot, q, frame, "local")
        Js = frame_jacobian(robot, q, frame, "world_spatial")
        np.testing.assert_allclose(Jl[:3], R.T @ Jw[:3], atol=1e-12)
        np.testing.assert_allclose(Jl[3:], R.T @ Jw[3:], atol=1e-12)
        np.testing.assert_allclose(Js[3:], Jw[3:], atol=1e-12)
        np.testing.assert_allclose(Js[:3], Jw[:3] + np.cross(p, Jw[3:].T).T, atol=1e-12)
