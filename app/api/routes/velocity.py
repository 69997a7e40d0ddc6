"""Velocity kinematics: POST /robots/{robot_id}/velocity (forward twist or inverse q̇; wire
models: :mod:`app.api.schemas.velocity`)."""

from __future__ import annotations

import numpy as np
from fastapi import APIRouter

from app.api.deps import RobotDep
from app.api.errors import ERROR_RESPONSES
from app.api.responses import ORJSONResponse
from app.api.schemas.velocity import VelocityRequest, VelocityResponse
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import default_frame
from app.kinematics.velocity import forward_velocity, inverse_velocity

router = APIRouter(prefix="/robots/{robot_id}", tags=["kinematics"])


@router.post(
    "/velocity",
    operation_id="compute_velocity",
    response_model=VelocityResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def compute_velocity(robot: RobotDep, body: VelocityRequest) -> ORJSONResponse:
    """Forward twist J·q̇, or inverse q̇ = J⁺·twist damped near singularities."""
    if (body.joint_velocities is None) == (body.twist is None):
        raise InvalidInputError("give exactly one of joint_velocities or twist", "twist")
    grp, q = body.group_config(robot)
    frame = default_frame(robot, grp, body.frame)
    robot.frame_id(frame)
    out = {"robot_id": robot.id, "frame": frame, "reference": body.reference, "q": q}
    if body.joint_velocities is not None:
        qdot = body.joint_velocities
        if grp is not None and len(qdot) == grp.size != robot.n:
            qdot = np.zeros(robot.n)
            qdot[grp.indices] = body.joint_velocities
        twist = forward_velocity(robot, q, qdot, frame, body.reference)
        out |= {
            "direction": "forward",
            "joint_velocities": qdot,
            "twist": twist,
            "residual": None,
            "damping": None,
            "sigma_min": None,
        }
    else:
        inv = inverse_velocity(
            robot,
            q,
            body.twist,
            frame,
            body.reference,
            mode=body.mode,
            threshold=body.singular_threshold,
            max_damping=body.max_damping,
            joints=None if grp is None else grp.indices,
        )
        out |= {
            "direction": "inverse",
            "joint_velocities": inv.joint_velocities,
            "twist": inv.twist,
            "residual": inv.residual,
            "damping": inv.damping,
            "sigma_min": inv.sigma_min,
        }
    return ORJSONResponse(out)
