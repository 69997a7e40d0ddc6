"""Velocity kinematics against finite differences of FK and numpy's SVD pseudo-inverse."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.errors import InvalidInputError
from app.kinematics.fk import forward_kinematics
from app.kinematics.velocity import damping_for, forward_velocity, inverse_velocity

H = 1e-6


def fd_twist(robot, q, qdot, frame, reference):
    """Central differences of FK along q̇: origin velocity and angular velocity."""
    Tp = forward_kinematics(robot, q + H * qdot, [frame])[frame]
    Tm = forward_kinematics(robot, q - H * qdot, [frame])[frame]
    T = forward_kinematics(robot, q, [frame])[frame]
    v = (Tp[:3, 3] - Tm[:3, 3]) / (2 * H)
    w = pin.log3(Tp[:3, :3] @ Tm[:3, :3].T) / (2 * H)  # world axes
    if reference == "local":
        v, w = T[:3, :3].T @ v, T[:3, :3].T @ w
    return np.concatenate([v, w])


@pytest.mark.parametrize("robot_id", ["ur5", "panda", "kinova", "rrp"])
@pytest.mark.parametrize("reference", ["world", "local"])
def test_forward_twist_matches_finite_differences(registry, robot_id, reference) -> None:
    robot = registry.get(robot_id)
    rng = np.random.default_rng(11)
    lo = np.where(np.isfinite(robot.lower), robot.lower, -np.pi)
    hi = np.where(np.isfinite(robot.upper), robot.upper, np.pi)
    for _ in range(3):
        q = rng.uniform(lo, hi)
        qdot = rng.normal(size=robot.n)
        twist = forward_velocity(robot, q, qdot, robot.ee_frame, reference)
        expected = fd_twist(robot, q, qdot, robot.ee_frame, reference)
        np.testing.assert_allclose(twist, expected, atol=1e-6)


def test_inverse_is_exact_at_a_regular_configuration(registry) -> None:
    robot = registry.get("ur5")
    q = np.array([0.3, -1.0, 1.2, 0.2, 0.5, 0.1])
    twist = np.array([0.05, -0.02, 0.1, 0.2, -0.1, 0.3])
    inv = inverse_velocity(robot, q, twist, "tool0", "world")
    assert inv.damping == 0.0 and inv.residual < 1e-12
    # Square and regular: the unique solution J⁻¹ t (numpy reference).
    J = pin.computeFrameJacobian(
        robot.model, robot.data, robot.to_pin(q), robot.frame_id("tool0"), pin.LOCAL_WORLD_ALIGNED
    )
    np.testing.assert_allclose(inv.joint_velocities, np.linalg.solve(J, twist), atol=1e-10)
    np.testing.assert_allclose(
        forward_velocity(robot, q, inv.joint_velocities, "tool0", "world"), twist, atol=1e-12
    )


def test_inverse_redundant_is_minimum_norm(registry) -> None:
    robot = registry.get("panda")
    q = robot.mid_range()
    q[:7] = [0.1, 0.3, -0.2, -1.9, 0.2, 1.8, 0.4]
    twist = np.array([0.1, 0.0, -0.05, 0.0, 0.2, 0.0])
    inv = inverse_velocity(robot, q, twist, "panda_link8", "local")
    J = pin.computeFrameJacobian(
        robot.model, robot.data, robot.to_pin(q), robot.frame_id("panda_link8"), pin.LOCAL
    )[:, :7]
    np.testing.assert_allclose(inv.joint_velocities[:7], np.linalg.pinv(J) @ twist, atol=1e-10)
    assert inv.joint_velocities[7:] == pytest.approx(0.0)  # fingers do not move the flange
    assert inv.residual < 1e-12


def test_inverse_damps_at_a_singularity(registry) -> None:
    """Planar 2-link at θ2 = 0 (det J = l1 l2 sin θ2 = 0): damping reported, q̇ bounded."""
    robot = registry.get("planar2")
    q = np.array([0.4, 0.0])
    twist = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    twist[:2] = [np.cos(0.4), np.sin(0.4)]  # along the stretched arm: unachievable
    inv = inverse_velocity(robot, q, twist, robot.ee_frame, "world", mode="position")
    assert inv.sigma_min == pytest.approx(0.0, abs=1e-12)
    assert inv.damping > 0.0
    assert np.isfinite(inv.joint_velocities).all()
    assert inv.residual == pytest.approx(1.0, abs=1e-9)  # nothing of it is achievable
    regular = inverse_velocity(
        robot, np.array([0.4, 1.0]), twist, robot.ee_frame, "world", mode="position"
    )
    assert regular.damping == 0.0 and regular.residual < 1e-12


def test_damping_schedule() -> None:
    assert damping_for(0.5, 0.01, 0.1) == 0.0
    assert damping_for(0.0, 0.01, 0.1) == pytest.approx(0.1)
    assert 0.0 < damping_for(0.005, 0.01, 0.1) < 0.1


def test_bad_shapes(registry) -> None:
    robot = registry.get("ur5")
    q = np.zeros(6)
    with pytest.raises(InvalidInputError) as e:
        forward_velocity(robot, q, np.zeros(5), "tool0", "world")
    assert e.value.field == "joint_velocities"
    with pytest.raises(InvalidInputError) as e:
        inverse_velocity(robot, q, np.zeros(5), "tool0", "world")
    assert e.value.field == "twist"


def test_inverse_with_a_damping_that_underflows_stays_finite(registry) -> None:
    """λ² underflows to 0 at an exact singularity (σ = 0): the lost direction gets no
    velocity (was 0/0 = NaN, a 200 with nulls found by schemathesis)."""
    robot = registry.get("planar2")
    out = inverse_velocity(
        robot,
        np.array([-2412.7813776535213, 1.9898734364016856e-87]),
        np.array([3e5, 1e5, 0.0, 8e3, 4e5, 6e-8]),
        "tool",
        "local",
        mode="orientation",
        threshold=75560.0,
        max_damping=5e-167,
    )
    assert np.all(np.isfinite(out.joint_velocities)) and np.all(np.isfinite(out.twist))
    assert np.isfinite(out.residual)
