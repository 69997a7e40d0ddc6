"""Wire models of forward kinematics: POST /robots/{robot_id}/fk and /fk/batch (poses in the
robot's root frame, m; quaternions [x, y, z, w]; configurations in joint order, rad or m)."""

from __future__ import annotations

from pydantic import BaseModel, Field

from app.api.schemas.common import (
    Configuration,
    ConfigurationIn,
    JointValue,
    QuatOut,
    Schema,
    Vec3Out,
    group_field,
)
from app.api.schemas.poses import Pose


class FKRequest(ConfigurationIn):
    """Configuration and the frames to place."""

    frames: list[str] | None = Field(
        None,
        description="Frame names; default the end effector (with `group`: the group's tip); "
        '["*"] for every frame.',
        max_length=4096,
    )


class FKResponse(BaseModel):
    """Frame poses in the root frame."""

    robot_id: str
    q: Configuration = Field(description="The configuration used, in joint order.")
    poses: dict[str, Pose] = Field(description="Frame name → pose in the root frame.")
    within_limits: bool = Field(description="Whether every joint lies within its limits.")
    joints_outside_limits: list[str] = Field(description="Joints outside their limits.")


class FKBatchRequest(Schema):
    """Many configurations, one frame."""

    configurations: list[list[JointValue]] = Field(
        description="N configurations, each one value per joint in joint order (rad, m); "
        "with `group`, rows of the group's joints only are accepted too (others neutral).",
    )
    frame: str | None = Field(
        None, description="Frame to place; default the end effector (or the group's tip)."
    )
    group: str | None = group_field()


class FKBatchResponse(BaseModel):
    """Compact arrays, row i for configuration i."""

    robot_id: str
    frame: str
    positions: list[Vec3Out] = Field(description="N×3 positions (m) in the root frame.")
    orientations: list[QuatOut] = Field(description="N×4 quaternions [x, y, z, w].")
