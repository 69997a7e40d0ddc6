"""Forward kinematics: POST /robots/{robot_id}/fk and /fk/batch."""

from __future__ import annotations

import numpy as np
from fastapi import APIRouter, Request
from pydantic import BaseModel, Field

from app.api.body import body_schema, decode_body, group_configurations
from app.api.deps import RegistryDep, SettingsDep, load_robot
from app.api.errors import ERROR_RESPONSES
from app.api.offload import offload
from app.api.responses import ORJSONResponse
from app.api.schemas.common import (
    ConfigurationIn,
    JointValue,
    QuatOut,
    RobotId,
    Schema,
    Vec3Out,
    group_field,
)
from app.api.schemas.poses import Pose, pose_json
from app.kinematics.fk import forward_kinematics, forward_kinematics_batch
from app.kinematics.groups import default_frame, group
from app.kinematics.models import RobotModel

router = APIRouter(prefix="/robots/{robot_id}", tags=["kinematics"])


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
    q: list[float] = Field(description="The configuration used, in joint order.")
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


@router.post(
    "/fk",
    operation_id="compute_fk",
    response_model=FKResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def compute_fk(robot_id: RobotId, body: FKRequest, reg: RegistryDep) -> ORJSONResponse:
    """Poses of frames at one configuration.

    Out-of-limit configurations are computed, and flagged with ``within_limits: false``.
    """
    return ORJSONResponse(fk_answer(await load_robot(reg, robot_id), body))


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


@router.post(
    "/fk/batch",
    operation_id="compute_fk_batch",
    response_model=FKBatchResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
    openapi_extra=body_schema(FKBatchRequest),
)
async def compute_fk_batch(
    robot_id: RobotId,
    request: Request,
    reg: RegistryDep,
    settings: SettingsDep,
) -> ORJSONResponse:
    """Position and orientation of one frame for many configurations.

    The body (up to ``DENAVIT_MAX_BATCH`` configurations) is decoded and computed in the
    work pool: decoding takes orjson and one NumPy conversion, and FK of serial chains is
    vectorised (see ``app.kinematics.chain.SerialChain``).
    """
    robot = await load_robot(reg, robot_id)
    raw = await request.body()
    frame, positions, quats = await offload(_fk_batch, robot, raw, settings.max_batch)
    return ORJSONResponse(
        {"robot_id": robot.id, "frame": frame, "positions": positions, "orientations": quats}
    )


def _fk_batch(robot: RobotModel, raw: bytes, limit: int) -> tuple[str, np.ndarray, np.ndarray]:
    body, rows = decode_body(raw, FKBatchRequest, {"configurations": None})
    grp = group(robot, body.group)
    qs = group_configurations(robot, grp, rows["configurations"], limit)
    frame = default_frame(robot, grp, body.frame)
    positions, quats = forward_kinematics_batch(robot, qs, frame)
    return frame, positions, quats
