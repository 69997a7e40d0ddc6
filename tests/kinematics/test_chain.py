"""The vectorised serial chain (app.kinematics.chain): poses and world Jacobians against
Pinocchio's FK and Jacobian, prismatic joints and axes not aligned with any frame axis."""

from __future__ import annotations

import numpy as np
import pytest

from app.kinematics.chain import PinocchioChain, SerialChain
from app.kinematics.fk import forward_kinematics
from app.kinematics.jacobian import frame_jacobian
from app.kinematics.models import RobotModel

PRISMATIC_URDF = """<?xml version="1.0"?>
<robot name="rrp_test">
  <link name="base"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="tip"/>
  <joint name="j1" type="continuous">
    <parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.4" rpy="0 0 0"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="j2" type="revolute">
    <parent link="l1"/><child link="l2"/>
    <origin xyz="0.3 0 0.05" rpy="0.3 0 0"/><axis xyz="0 0.6 0.8"/>
    <limit lower="-3" upper="3" velocity="1" effort="1"/>
  </joint>
  <joint name="j3" type="prismatic">
    <parent link="l2"/><child link="l3"/>
    <origin xyz="0.1 0 0" rpy="0 0.4 0"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.5" velocity="1" effort="1"/>
  </joint>
  <joint name="tip_joint" type="fixed">
    <parent link="l3"/><child link="tip"/>
    <origin xyz="0.05 0.02 0" rpy="0 0.2 -1.0"/>
  </joint>
</robot>"""


@pytest.mark.parametrize("robot_id", ["panda", "ur5", "kinova"])
def test_chain_matches_pinocchio(registry, robot_id):
    robot = registry.get(robot_id)
    chain = SerialChain.build(robot, robot.ee_frame)
    assert chain is not None
    rng = np.random.default_rng(7)
    Q = rng.uniform(-3, 3, size=(6, chain.wire.size))
    R, p, J = chain(Q)
    for i in range(len(Q)):
        q = robot.neutral()
        q[chain.wire] = Q[i]
        T = forward_kinematics(robot, q, [robot.ee_frame])[robot.ee_frame]
        np.testing.assert_allclose(R[i], T[:3, :3], atol=1e-12)
        np.testing.assert_allclose(p[i], T[:3, 3], atol=1e-12)
        Jr = frame_jacobian(robot, q, robot.ee_frame, "world")[:, chain.wire]
        np.testing.assert_allclose(J[i], Jr, atol=1e-12)


def test_chain_prismatic_and_unaligned_axes():
    robot = RobotModel("rrp_test", PRISMATIC_URDF, ee_frame="tip")
    chain = SerialChain.build(robot, "tip")
    slow = PinocchioChain(robot, "tip", chain.wire)
    Q = np.random.default_rng(2).uniform([-3, -3, 0], [3, 3, 0.5], size=(8, 3))
    for a, b in zip(chain(Q), slow(Q), strict=True):
        np.testing.assert_allclose(a, b, atol=1e-12)
