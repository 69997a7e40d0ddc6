"""Wire models of the Jacobian: POST /robots/{robot_id}/jacobian (rows [vx, vy, vz, ωx, ωy,
ωz], columns in joint order; references as :data:`app.kinematics.jacobian.Reference`)."""

from __future__ import annotations

from pydantic import BaseModel, Field

from app.api.schemas.common import Configuration, ConfigurationIn
from app.api.schemas.values import JacobianReference

REFERENCE_DOC = (
    "world (default): origin velocity and angular velocity in world axes (Pinocchio "
    "LOCAL_WORLD_ALIGNED; the textbook geometric Jacobian) | local: the same in the frame's "
    "own axes (LOCAL) | world_spatial: spatial velocity at the world origin (WORLD)."
)


class JacobianRequest(ConfigurationIn):
    """Configuration, frame and reference."""

    frame: str | None = Field(
        None, description="Frame; default the end effector (with `group`: the group's tip)."
    )
    reference: JacobianReference = Field("world", description=REFERENCE_DOC)


class JacobianResponse(BaseModel):
    """The Jacobian, rows [vx, vy, vz, ωx, ωy, ωz], columns in joint order (with `group`:
    the group's joints, in the group's order)."""

    robot_id: str
    frame: str
    reference: JacobianReference
    q: Configuration
    jacobian: list[list[float]] = Field(
        description="6×n (with `group`: 6×k, k the group's joints); linear rows in m/rad or m/m."
    )
    joint_names: list[str] = Field(description="The joint of each column.")
