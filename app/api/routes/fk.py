"""Forward kinematics: POST /robots/{robot_id}/fk and /fk/batch (wire models:
:mod:`app.api.schemas.fk`; the answer body: :func:`app.api.answers.fk_answer`)."""

from __future__ import annotations

import numpy as np
from fastapi import APIRouter, Request

from app.api.answers import fk_answer
from app.api.body import body_schema, decode_body, group_configurations
from app.api.deps import RobotDep, SettingsDep
from app.api.errors import ERROR_RESPONSES
from app.api.offload import offload
from app.api.responses import ORJSONResponse
from app.api.schemas.fk import FKBatchRequest, FKBatchResponse, FKRequest, FKResponse
from app.kinematics.fk import forward_kinematics_batch
from app.kinematics.groups import default_frame, group
from app.kinematics.models import RobotModel

router = APIRouter(prefix="/robots/{robot_id}", tags=["kinematics"])


@router.post(
    "/fk",
    operation_id="compute_fk",
    response_model=FKResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def compute_fk(robot: RobotDep, body: FKRequest) -> ORJSONResponse:
    """Poses of frames at one configuration.

    Out-of-limit configurations are computed, and flagged with ``within_limits: false``.
    """
    return ORJSONResponse(fk_answer(robot, body))


@router.post(
    "/fk/batch",
    operation_id="compute_fk_batch",
    response_model=FKBatchResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
    openapi_extra=body_schema(FKBatchRequest),
)
async def compute_fk_batch(
    robot: RobotDep, request: Request, settings: SettingsDep
) -> ORJSONResponse:
    """Position and orientation of one frame for many configurations.

    The body (up to ``DENAVIT_MAX_BATCH`` configurations) is decoded and computed in the
    work pool: decoding takes orjson and one NumPy conversion, and FK of serial chains is
    vectorised (see ``app.kinematics.chain.SerialChain``).
    """
    raw = await request.body()
    frame, positions, quats = await offload(request, _fk_batch, robot, raw, settings.max_batch)
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
