"""Velocity kinematics: POST /robots/{robot_id}/velocity (forward twist or inverse q̇)."""

from __future__ import annotations

from typing import Annotated, Literal

import numpy as np
from fastapi import APIRouter
from pydantic import BaseModel, Field

from app.api.deps import RegistryDep, load_robot
from app.api.errors import ERROR_RESPONSES
from app.api.responses import ORJSONResponse
from app.api.schemas.common import ConfigurationIn, Finite, RobotId
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import default_frame
from app.kinematics.velocity import (
    MAX_DAMPING,
    MAX_RATE,
    SINGULAR_THRESHOLD,
    forward_velocity,
    inverse_velocity,
)

router = APIRouter(prefix="/robots/{robot_id}", tags=["kinematics"])

#: A rate (rad/s, m/s) within ±MAX_RATE.
Rate = Annotated[Finite, Field(ge=-MAX_RATE, le=MAX_RATE)]
Twist = Annotated[list[Rate], Field(min_length=6, max_length=6)]
Positive = Annotated[float, Field(gt=0.0, le=MAX_RATE, allow_inf_nan=False, strict=True)]
NonNegative = Annotated[float, Field(ge=0.0, le=MAX_RATE, allow_inf_nan=False, strict=True)]


class VelocityRequest(ConfigurationIn):
    """A configuration plus exactly one of ``joint_velocities`` (forward) or ``twist``."""

    frame: str | None = Field(
        None, description="Frame; default the end effector (with `group`: the group's tip)."
    )
    reference: Literal["world", "local"] = Field(
        "world",
        description="Axes of the twist: world (origin velocity and angular velocity in world "
        "axes, Pinocchio LOCAL_WORLD_ALIGNED) | local (the frame's own axes, LOCAL).",
    )
    joint_velocities: list[Rate] | None = Field(
        None,
        description="Forward: q̇, one per joint in joint order (rad/s, m/s); with `group`, one "
        "per joint of the group is accepted too (the others at rest).",
        max_length=1024,
    )
    twist: Twist | None = Field(
        None, description="Inverse: [vx, vy, vz, wx, wy, wz] (m/s, rad/s) to realise."
    )
    mode: Literal["pose", "position", "orientation"] = Field(
        "pose",
        description="Inverse only: task rows to match (position: vx, vy, vz only; "
        "orientation: wx, wy, wz only).",
    )
    singular_threshold: Positive = Field(
        SINGULAR_THRESHOLD, description="Inverse: σ_min below which damping starts."
    )
    max_damping: NonNegative = Field(
        MAX_DAMPING, description="Inverse: damping λ at an exact singularity."
    )


class VelocityResponse(BaseModel):
    """Both directions fill ``twist`` and ``joint_velocities``; inverse adds its diagnostics."""

    robot_id: str
    frame: str
    reference: str
    direction: Literal["forward", "inverse"]
    q: list[float]
    joint_velocities: list[float] = Field(description="q̇ in joint order (rad/s, m/s).")
    twist: list[float] = Field(description="J·q̇ = [vx, vy, vz, wx, wy, wz] (m/s, rad/s).")
    residual: float | None = Field(None, description="Inverse: ‖J q̇ − twist‖ on the task rows.")
    damping: float | None = Field(None, description="Inverse: damping λ used (0: none).")
    sigma_min: float | None = Field(
        None, description="Inverse: smallest singular value of the task Jacobian."
    )


@router.post(
    "/velocity",
    operation_id="compute_velocity",
    response_model=VelocityResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def compute_velocity(
    robot_id: RobotId, body: VelocityRequest, reg: RegistryDep
) -> ORJSONResponse:
    """Forward twist J·q̇, or inverse q̇ = J⁺·twist damped near singularities."""
    if (body.joint_velocities is None) == (body.twist is None):
        raise InvalidInputError("give exactly one of joint_velocities or twist", "twist")
    robot = await load_robot(reg, robot_id)
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
