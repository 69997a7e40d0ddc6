"""Forward kinematics: frame placements in the robot's root (world) frame.

All poses are ``oMf``: the placement of frame f in the root frame, as 4×4 homogeneous
matrices (metres). Configurations are wire configurations (see :mod:`.models`).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pinocchio as pin

from app.kinematics.chain import SerialChain
from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel
from app.kinematics.rotations import matrix_to_quaternion


def forward_kinematics(
    robot: RobotModel, q: np.ndarray, frames: Sequence[str]
) -> dict[str, np.ndarray]:
    """Placements (4×4) of ``frames`` in the root frame at wire configuration ``q``.

    ``frames == ["*"]`` means every named frame of the robot.
    """
    names = robot.frame_names if list(frames) == ["*"] else list(frames)
    ids = [robot.frame_id(name, field=f"frames.{i}") for i, name in enumerate(names)]
    model, data = robot.model, robot.data
    pin.forwardKinematics(model, data, robot.to_pin(q))
    return {
        name: pin.updateFramePlacement(model, data, fid).homogeneous
        for name, fid in zip(names, ids, strict=True)
    }


def frame_pose(robot: RobotModel, q: np.ndarray, frame_id: int) -> pin.SE3:
    """Placement of one frame (by Pinocchio id) at wire configuration ``q``."""
    model, data = robot.model, robot.data
    pin.forwardKinematics(model, data, robot.to_pin(q))
    return pin.updateFramePlacement(model, data, frame_id)


def forward_kinematics_batch(
    robot: RobotModel, qs: np.ndarray, frame: str
) -> tuple[np.ndarray, np.ndarray]:
    """Positions (N, 3) and quaternions [x, y, z, w] (N, 4) of ``frame`` for N configurations.

    Serial chains of revolute, continuous and prismatic joints use
    :class:`app.kinematics.chain.SerialChain` (vectorised); anything else runs Pinocchio's
    FK configuration by configuration.
    """
    fid = robot.frame_id(frame)
    qs = np.asarray(qs, dtype=float)
    chain = robot.lazy(
        LazyKey(f"serial_chain:{fid}", SerialChain), lambda r: SerialChain.build(r, frame)
    )
    if chain is not None:
        rotations, positions = chain.pose(qs[:, chain.wire])
        return positions, matrix_to_quaternion(rotations)
    model, data = robot.model, robot.data
    qp = robot.to_pin_batch(qs)
    n = qp.shape[0]
    positions = np.empty((n, 3))
    rotations = np.empty((n, 3, 3))
    fk, upd = pin.forwardKinematics, pin.updateFramePlacement
    for i in range(n):
        fk(model, data, qp[i])
        m = upd(model, data, fid)
        positions[i] = m.translation
        rotations[i] = m.rotation
    return positions, matrix_to_quaternion(rotations)
