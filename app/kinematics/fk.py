"""Forward kinematics: frame placements in the robot's root (world) frame.

All poses are ``oMf``: the placement of frame f in the root frame, as 4×4 homogeneous
matrices (metres). Configurations are wire configurations (see :mod:`.models`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

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


def _z_to(axis: np.ndarray) -> np.ndarray:
    """A rotation A with A·e_z = axis (unit), so that rot(axis, θ) = A·Rz(θ)·Aᵀ."""
    z = np.array([0.0, 0.0, 1.0])
    c = float(axis @ z)
    if c > 1.0 - 1e-15:
        return np.eye(3)
    if c < -1.0 + 1e-15:
        return np.diag([1.0, -1.0, -1.0])  # rotation by π about x
    return pin.exp3(np.cross(z, axis) / np.linalg.norm(np.cross(z, axis)) * np.arccos(c))


@dataclass(frozen=True)
class _ChainStep:
    """One joint: a constant transform into its z-aligned frame, then motion along/about z."""

    C: np.ndarray  # rotation from the previous z-aligned frame to this one
    t: np.ndarray  # translation, in the previous z-aligned frame
    wire: int  # index of the joint's value in wire configurations
    prismatic: bool


class BatchChain:
    """Vectorised FK of one frame over many configurations (NumPy, no Python loop).

    The frame's placement is the product, along its supporting joints, of each joint's
    fixed placement M_j and its motion: exp(θ·axis) for revolute and continuous joints (θ is
    the wire angle, so no (cos, sin) round trip), a translation θ·axis for prismatic ones;
    then the frame's own placement in its parent joint. Each joint is rewritten in a frame
    whose z axis is the joint axis (rot(axis, θ) = A·Rz(θ)·Aᵀ, the constants folded into
    the fixed placements), so a joint's motion is a rotation of two columns of R or a shift
    along its third column: O(N) work with no per-sample matrix products. Built only when
    every joint of the chain is a 1-DoF revolute, continuous or prismatic wire joint;
    ``build`` returns ``None`` otherwise and callers fall back to Pinocchio in a loop.
    """

    def __init__(self, steps: list[_ChainStep], last_C: np.ndarray, last_t: np.ndarray) -> None:
        self.steps = steps
        self.last_C = last_C
        self.last_t = last_t

    @classmethod
    def build(cls, robot: RobotModel, frame_id: int) -> BatchChain | None:
        model = robot.model
        f = model.frames[frame_id]
        by_pin = {j.pin_id: j for j in robot.joints}
        steps = []
        prev_At = np.eye(3)  # Aᵀ of the previous joint: its real frame → its z-aligned frame
        for jid in list(model.supports[f.parentJoint])[1:]:
            joint = by_pin.get(jid)
            if joint is None or model.joints[jid].nv != 1:
                return None  # mimic or multi-DoF joint: not handled here
            axis = np.asarray(joint.axis, dtype=float)
            A = _z_to(axis / np.linalg.norm(axis))
            M = model.jointPlacements[jid]
            steps.append(
                _ChainStep(
                    prev_At @ M.rotation @ A,
                    prev_At @ M.translation,
                    joint.index,
                    joint.type == "prismatic",
                )
            )
            prev_At = A.T
        return cls(steps, prev_At @ f.placement.rotation, prev_At @ f.placement.translation)

    def __call__(self, qs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Rotations (N, 3, 3) and positions (N, 3) of the frame for wire configurations."""
        n = qs.shape[0]
        R = np.broadcast_to(np.eye(3), (n, 3, 3))
        p = np.zeros((n, 3))
        for s in self.steps:
            p = p + (R.reshape(-1, 3) @ s.t).reshape(n, 3)
            R = (R.reshape(-1, 3) @ s.C).reshape(n, 3, 3)
            th = qs[:, s.wire]
            if s.prismatic:
                p = p + th[:, None] * R[:, :, 2]
            else:
                c, si = np.cos(th)[:, None], np.sin(th)[:, None]
                x, y = R[:, :, 0].copy(), R[:, :, 1]
                R[:, :, 0] = c * x + si * y
                R[:, :, 1] = c * y - si * x
        p = p + (R.reshape(-1, 3) @ self.last_t).reshape(n, 3)
        R = (R.reshape(-1, 3) @ self.last_C).reshape(n, 3, 3)
        return R, p


def forward_kinematics_batch(
    robot: RobotModel, qs: np.ndarray, frame: str
) -> tuple[np.ndarray, np.ndarray]:
    """Positions (N, 3) and quaternions [x, y, z, w] (N, 4) of ``frame`` for N configurations.

    Serial chains of revolute, continuous and prismatic joints use :class:`BatchChain`
    (vectorised); anything else runs Pinocchio's FK configuration by configuration.
    """
    fid = robot.frame_id(frame)
    qs = np.asarray(qs, dtype=float)
    chain = robot.lazy(f"batch_chain:{fid}", lambda r: BatchChain.build(r, fid) or False)
    if chain:
        rotations, positions = chain(qs)
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
