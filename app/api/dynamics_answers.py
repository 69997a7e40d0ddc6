"""The answer body of the dynamics at one state, shared by the HTTP route
(``POST /robots/{robot_id}/dynamics``, :mod:`app.api.routes.dynamics`) and the stream's
``dynamics`` op (:mod:`app.api.routes.stream`).

Every vector and matrix is in joint order (with a group, over the group's joints); torques
N·m (N for prismatic joints), the centre of mass in the world frame (m), NaN effort limits
and ratios (no limit in the URDF) serialised as JSON ``null``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from app.api.schemas.dynamics import DynamicsRequest, PayloadIn, rates
from app.kinematics.dynamics import Payload, check_inertias, compute_dynamics
from app.kinematics.groups import Group, default_frame
from app.kinematics.models import RobotModel


def load_of(
    robot: RobotModel, grp: Group | None, body: PayloadIn | None, field: str = "payload"
) -> Payload | None:
    """The request's checked payload (its frame by default the tip, or the group's), or
    ``None``."""
    return None if body is None else body.to_core(robot, default_frame(robot, grp, None), field)


def binding(names: list[str], ratios: np.ndarray) -> str | None:
    """The joint with the largest ratio (None when every ratio is NaN: no limits)."""
    best, name = -1.0, None
    for value, joint in zip(ratios.tolist(), names, strict=True):
        if value > best:  # False for NaN
            best, name = value, joint
    return name


def dynamics_answer(robot: RobotModel, body: DynamicsRequest) -> dict[str, Any]:
    """The body of a dynamics answer (module doc); raises the core's errors naming the
    request's fields (``velocities.3``, ``payload.mass``, ``wrench.frame``, …)."""
    grp, q = body.group_config(robot)
    check_inertias(robot)
    qd = rates(robot, grp, body.velocities, "velocities")
    qdd = rates(robot, grp, body.accelerations, "accelerations")
    load = load_of(robot, grp, body.payload)
    wrench = body.wrench
    wrench_frame = None if wrench is None else default_frame(robot, grp, wrench.frame)
    if wrench_frame is not None:
        robot.frame_id(wrench_frame, field="wrench.frame")
    dyn = compute_dynamics(
        robot,
        q,
        qd,
        qdd,
        load=load,
        wrench=None if wrench is None else np.array(wrench.values),
        wrench_frame=wrench_frame,
        wrench_reference="world" if wrench is None else wrench.reference,
    )
    if grp is None:
        names, idx = robot.joint_names, slice(None)
        mass_matrix, coriolis_matrix, joint = dyn.mass_matrix, dyn.coriolis_matrix, dyn.binding
    else:
        names, idx = list(grp.joints), grp.indices
        cols = np.ix_(idx, idx)
        mass_matrix, coriolis_matrix = dyn.mass_matrix[cols], dyn.coriolis_matrix[cols]
        joint = binding(names, dyn.ratios[idx])
    return {
        "robot_id": robot.id,
        "q": q,
        "joint_names": names,
        "torques": dyn.torques[idx],
        "gravity_torques": dyn.gravity[idx],
        "coriolis_torques": dyn.coriolis[idx],
        "inertial_torques": dyn.inertial[idx],
        "wrench_torques": dyn.wrench_torques[idx],
        "mass_matrix": mass_matrix,
        "coriolis_matrix": coriolis_matrix,
        "center_of_mass": dyn.com,
        "total_mass": dyn.mass,
        "effort_limits": dyn.effort_limits[idx],  # NaN → null
        "effort_ratios": dyn.ratios[idx],
        "binding_joint": joint,
        "payload": None if load is None else load.to_json(),
    }
