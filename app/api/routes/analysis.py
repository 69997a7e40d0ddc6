"""Jacobian analysis over HTTP: manipulability (one and many configurations) and statics.

- POST /robots/{robot_id}/manipulability
- POST /robots/{robot_id}/manipulability/batch
- POST /robots/{robot_id}/statics

Definitions (task rows, supporting joints, rank tolerance, ellipsoids, statics sign) are
those of :mod:`app.kinematics.analysis`; wire models: :mod:`app.api.schemas.analysis`.
"""

from __future__ import annotations

import numpy as np
from fastapi import APIRouter, Request

from app.api.body import body_schema, decode_body, group_configurations
from app.api.deps import RobotDep, SettingsDep
from app.api.errors import ERROR_RESPONSES
from app.api.offload import offload
from app.api.responses import ORJSONResponse
from app.api.schemas.analysis import (
    ManipulabilityBatchRequest,
    ManipulabilityBatchResponse,
    ManipulabilityRequest,
    ManipulabilityResponse,
    StaticsRequest,
    StaticsResponse,
)
from app.kinematics.analysis import (
    compute_manipulability as manipulability_core,
)
from app.kinematics.analysis import (
    manipulability_batch,
    torques_from_wrench,
    wrench_from_torques,
)
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import Group, default_frame, group
from app.kinematics.models import RobotModel

router = APIRouter(prefix="/robots/{robot_id}", tags=["analysis"])


def _manip_json(robot_id: str, frame: str, reference: str, q: np.ndarray, res) -> dict:
    out = {"robot_id": robot_id, "frame": frame, "reference": reference, "q": q}
    out.update(res.to_json())
    return out


@router.post(
    "/manipulability",
    operation_id="compute_manipulability",
    response_model=ManipulabilityResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def compute_manipulability(robot: RobotDep, body: ManipulabilityRequest) -> ORJSONResponse:
    """Manipulability, singularity and ellipsoids of a frame at one configuration."""
    grp, q = body.group_config(robot)
    frame = default_frame(robot, grp, body.frame)
    res = manipulability_core(
        robot,
        q,
        frame,
        part=body.part,
        rows=body.rows,
        reference=body.reference,
        relative_tolerance=body.relative_tolerance,
        joints=None if grp is None else grp.indices,
    )
    return ORJSONResponse(_manip_json(robot.id, frame, body.reference, q, res))


def _batch_body(
    raw: bytes, robot: RobotModel, limit: int
) -> tuple[ManipulabilityBatchRequest, Group | None, np.ndarray]:
    """Decode a batch body: the task options, the group and the checked (full)
    configurations."""
    body, rows = decode_body(raw, ManipulabilityBatchRequest, {"configurations": None})
    grp = group(robot, body.group)
    return body, grp, group_configurations(robot, grp, rows["configurations"], limit)


@router.post(
    "/manipulability/batch",
    operation_id="compute_manipulability_batch",
    response_model=ManipulabilityBatchResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
    openapi_extra=body_schema(ManipulabilityBatchRequest),
)
async def compute_manipulability_batch(
    robot: RobotDep, request: Request, settings: SettingsDep
) -> ORJSONResponse:
    """Scalar manipulability measures for many configurations (computed off the event loop)."""
    raw = await request.body()
    body, grp, qs = await offload(request, _batch_body, raw, robot, settings.max_batch)
    frame = default_frame(robot, grp, body.frame)
    out = await offload(
        request,
        manipulability_batch,
        robot,
        qs,
        frame,
        part=body.part,
        rows=body.rows,
        reference=body.reference,
        relative_tolerance=body.relative_tolerance,
        joints=None if grp is None else grp.indices,
    )
    return ORJSONResponse(
        {"robot_id": robot.id, "frame": frame, "reference": body.reference, **out}
    )


@router.post(
    "/statics",
    operation_id="compute_statics",
    response_model=StaticsResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def compute_statics(robot: RobotDep, body: StaticsRequest) -> ORJSONResponse:
    """Joint torques τ = Jᵀ·F from a wrench at a frame, or the least-squares wrench from τ."""
    if (body.wrench is None) == (body.torques is None):
        raise InvalidInputError("give exactly one of wrench or torques", "wrench")
    grp, q = body.group_config(robot)
    frame = default_frame(robot, grp, body.frame)
    joints = None if grp is None else grp.indices
    names = robot.joint_names if grp is None else list(grp.joints)
    if body.wrench is not None:
        st = torques_from_wrench(robot, q, frame, np.array(body.wrench), body.reference, joints)
    else:
        if len(body.torques) != len(names):
            raise InvalidInputError(
                f"expected {len(names)} values (one per joint: {', '.join(names)}), "
                f"got {len(body.torques)}",
                "torques",
            )
        st = wrench_from_torques(
            robot, q, frame, np.array(body.torques), body.reference, joints=joints
        )
    return ORJSONResponse(
        {
            "robot_id": robot.id,
            "frame": frame,
            "reference": body.reference,
            "q": q,
            "wrench": st.wrench,
            "torques": st.torques,
            "joint_names": names,
            "residual": st.residual,
            "residual_norm": st.residual_norm,
            "rank": st.rank,
        }
    )
