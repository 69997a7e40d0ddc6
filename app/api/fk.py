"""Forward kinematics: POST /robots/{robot_id}/fk and /fk/batch."""

from __future__ import annotations

import numpy as np
from fastapi import APIRouter, Request
from pydantic import BaseModel, Field

from app.api.common import (
    ConfigurationIn,
    JointValue,
    ORJSONResponse,
    Pose,
    QuatOut,
    RobotId,
    Schema,
    Vec3Out,
    body_schema,
    finite_matrix,
    load_robot,
    offload,
    parse_json,
    pose_json,
    validate_body,
)
from app.api.deps import RegistryDep, SettingsDep
from app.api.errors import ERROR_RESPONSES
from app.kinematics.errors import InvalidInputError
from app.kinematics.fk import forward_kinematics, forward_kinematics_batch
from app.kinematics.models import RobotModel, check_joint_values

router = APIRouter(prefix="/robots/{robot_id}", tags=["kinematics"])


class FKRequest(ConfigurationIn):
    """Configuration and the frames to place."""

    frames: list[str] | None = Field(
        None,
        description='Frame names; default the end effector; ["*"] for every frame.',
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
        description="N configurations, each one value per joint in joint order (rad, m).",
    )
    frame: str | None = Field(None, description="Frame to place; default the end effector.")


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
    robot = await load_robot(reg, robot_id)
    q = body.config(robot)
    frames = body.frames if body.frames else [robot.ee_frame]
    poses = forward_kinematics(robot, q, frames)
    outside = robot.limit_violations(q)
    return ORJSONResponse(
        {
            "robot_id": robot.id,
            "q": q.tolist(),
            "poses": {name: pose_json(T) for name, T in poses.items()},
            "within_limits": not outside,
            "joints_outside_limits": outside,
        }
    )


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
    vectorised (see ``app.kinematics.fk.BatchChain``).
    """
    robot = await load_robot(reg, robot_id)
    raw = await request.body()
    frame, positions, quats = await offload(_fk_batch, robot, raw, settings.max_batch)
    return ORJSONResponse(
        {"robot_id": robot.id, "frame": frame, "positions": positions, "orientations": quats}
    )


def _fk_batch(robot: RobotModel, raw: bytes, limit: int) -> tuple[str, np.ndarray, np.ndarray]:
    obj = parse_json(raw)
    qs = None
    frame = None
    # Fast path: exactly the expected shape, numbers only (no true/false, which NumPy would
    # turn into 1/0). Anything else gets full validation, which names the bad element.
    if (
        isinstance(obj, dict)
        and obj.keys() <= {"configurations", "frame"}
        and isinstance(obj.get("frame"), str | None)
        and b"true" not in raw
        and b"false" not in raw
    ):
        qs = finite_matrix(obj.get("configurations"), robot.n)
        frame = obj.get("frame")
    if qs is None:
        body = validate_body(FKBatchRequest, obj)
        frame = body.frame
        for i, row in enumerate(body.configurations):
            if len(row) != robot.n:
                raise InvalidInputError(
                    f"expected {robot.n} values (one per joint), got {len(row)}",
                    f"configurations.{i}",
                )
        if not body.configurations:
            raise InvalidInputError("give at least one configuration", "configurations")
        qs = np.array(body.configurations, dtype=float)
    if qs.shape[0] > limit:
        raise InvalidInputError(
            f"{qs.shape[0]} configurations exceed the limit of {limit}", "configurations"
        )
    check_joint_values(qs, "configurations")
    frame = frame or robot.ee_frame
    positions, quats = forward_kinematics_batch(robot, qs, frame)
    return frame, positions, quats
