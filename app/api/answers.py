"""The answer bodies of FK and the Jacobian at one configuration, shared by the HTTP routes
and the stream (:mod:`app.api.routes.stream`, whose binary answers start from them too).

Poses are in the robot's root frame (m, quaternions [x, y, z, w]); the Jacobian's rows are
[vx, vy, vz, ωx, ωy, ωz] in the requested reference, its columns the joints (with a group,
the group's joints in the group's order).
"""

from __future__ import annotations

from app.api.schemas.fk import FKRequest
from app.api.schemas.jacobian import JacobianRequest
from app.api.schemas.poses import pose_json
from app.kinematics.fk import forward_kinematics
from app.kinematics.groups import default_frame
from app.kinematics.jacobian import frame_jacobian
from app.kinematics.models import RobotModel


def fk_answer(robot: RobotModel, body: FKRequest) -> dict:
    """The body of an FK answer (HTTP and the stream): poses in the root frame."""
    grp, q = body.group_config(robot)
    frames = body.frames if body.frames else [default_frame(robot, grp, None)]
    poses = forward_kinematics(robot, q, frames)
    outside = robot.limit_violations(q)
    return {
        "robot_id": robot.id,
        "q": q.tolist(),
        "poses": {name: pose_json(T) for name, T in poses.items()},
        "within_limits": not outside,
        "joints_outside_limits": outside,
    }


def jacobian_answer(robot: RobotModel, body: JacobianRequest) -> dict:
    """The body of a Jacobian answer (HTTP and the stream)."""
    grp, q = body.group_config(robot)
    frame = default_frame(robot, grp, body.frame)
    J = frame_jacobian(robot, q, frame, body.reference)
    names = robot.joint_names
    if grp is not None:  # the group's columns (a joint not moving the frame: a zero column)
        J, names = J[:, grp.indices], list(grp.joints)
    return {
        "robot_id": robot.id,
        "frame": frame,
        "reference": body.reference,
        "q": q,
        "jacobian": J,
        "joint_names": names,
    }
