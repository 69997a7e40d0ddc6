"""Geometric Jacobians of a frame, in the three references the API speaks.

Rows are [vx, vy, vz, ωx, ωy, ωz]; columns follow the wire joint order.

- ``world`` (Pinocchio ``LOCAL_WORLD_ALIGNED``): linear velocity of the frame's origin and
  angular velocity, both in world axes. This is the course's
  J_i = [z_{i-1} × (o_n − o_{i-1}); z_{i-1}] (revolute) and [z_{i-1}; 0] (prismatic).
- ``local`` (Pinocchio ``LOCAL``): the same twist in the frame's own axes.
- ``world_spatial`` (Pinocchio ``WORLD``): the spatial velocity, i.e. the linear part is
  the velocity of the point of the body that is momentarily at the world origin.
"""

from __future__ import annotations

from typing import Literal

import numpy as np
import pinocchio as pin

from app.kinematics.models import RobotModel

Reference = Literal["world", "local", "world_spatial"]
#: The references a twist is given in (velocity IK): the frame origin's velocity in world
#: axes, or in the frame's own axes.
TWIST_REFERENCES = ("world", "local")

REFERENCE_FRAMES: dict[str, pin.ReferenceFrame] = {
    "world": pin.LOCAL_WORLD_ALIGNED,
    "local": pin.LOCAL,
    "world_spatial": pin.WORLD,
}


def frame_jacobian(
    robot: RobotModel, q: np.ndarray, frame: str, reference: Reference = "world"
) -> np.ndarray:
    """The 6×n Jacobian of ``frame`` at wire configuration ``q``."""
    fid = robot.frame_id(frame)
    return frame_jacobian_by_id(robot, robot.to_pin(q), fid, REFERENCE_FRAMES[reference])


def frame_jacobian_by_id(
    robot: RobotModel, q_pin: np.ndarray, frame_id: int, rf: pin.ReferenceFrame
) -> np.ndarray:
    """6×n Jacobian from a Pinocchio configuration and frame id (hot-path form)."""
    J = pin.computeFrameJacobian(robot.model, robot.data, q_pin, frame_id, rf)
    # Pinocchio hands back a 1-D array when the model has a single degree of freedom.
    return np.asarray(J).reshape(6, -1)[:, robot.v_index]
