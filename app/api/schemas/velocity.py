"""Wire models of velocity kinematics: POST /robots/{robot_id}/velocity (twists [vx, vy, vz,
wx, wy, wz] in m/s and rad/s; joint rates in joint order, rad/s or m/s)."""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, Field

from app.api.schemas.common import Configuration, ConfigurationIn, Finite
from app.api.schemas.values import IKMode, TwistReference, VelocityDirection
from app.kinematics.velocity import MAX_DAMPING, MAX_RATE, SINGULAR_THRESHOLD

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
    reference: TwistReference = Field(
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
    mode: IKMode = Field(
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
    reference: TwistReference
    direction: VelocityDirection
    q: Configuration
    joint_velocities: list[float] = Field(description="q̇ in joint order (rad/s, m/s).")
    twist: list[float] = Field(description="J·q̇ = [vx, vy, vz, wx, wy, wz] (m/s, rad/s).")
    residual: float | None = Field(None, description="Inverse: ‖J q̇ − twist‖ on the task rows.")
    damping: float | None = Field(None, description="Inverse: damping λ used (0: none).")
    sigma_min: float | None = Field(
        None, description="Inverse: smallest singular value of the task Jacobian."
    )
