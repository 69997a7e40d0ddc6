"""POST /robots/{robot_id}/jacobian: the 6×n geometric Jacobian of a frame."""

from __future__ import annotations

from fastapi import APIRouter
from pydantic import BaseModel, Field

from app.api.deps import RegistryDep, load_robot
from app.api.errors import ERROR_RESPONSES
from app.api.responses import ORJSONResponse
from app.api.schemas.common import ConfigurationIn, RobotId
from app.kinematics.groups import default_frame
from app.kinematics.jacobian import Reference, frame_jacobian
from app.kinematics.models import RobotModel

router = APIRouter(prefix="/robots/{robot_id}", tags=["kinematics"])

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
    reference: Reference = Field("world", description=REFERENCE_DOC)


class JacobianResponse(BaseModel):
    """The Jacobian, rows [vx, vy, vz, ωx, ωy, ωz], columns in joint order (with `group`:
    the group's joints, in the group's order)."""

    robot_id: str
    frame: str
    reference: str
    q: list[float]
    jacobian: list[list[float]] = Field(
        description="6×n (with `group`: 6×k, k the group's joints); linear rows in m/rad or m/m."
    )
    joint_names: list[str] = Field(description="The joint of each column.")


@router.post(
    "/jacobian",
    operation_id="compute_jacobian",
    response_model=JacobianResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def compute_jacobian(
    robot_id: RobotId, body: JacobianRequest, reg: RegistryDep
) -> ORJSONResponse:
    """Geometric Jacobian of a frame at one configuration."""
    return ORJSONResponse(jacobian_answer(await load_robot(reg, robot_id), body))


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
