"""Rigid-body dynamics over HTTP (docs/dynamics.md).

- POST /robots/{robot_id}/dynamics: every term of τ = M q̈ + C q̇ + g + Jᵀ F at one state
- POST /robots/{robot_id}/dynamics/batch: τ and g(q) for many states (off the event loop)
- POST /robots/{robot_id}/dynamics/max_payload: the largest payload at rest, at one
  configuration or along a path

The computations are :mod:`app.kinematics.dynamics` and :mod:`app.kinematics.payload`; wire
models: :mod:`app.api.schemas.dynamics`. A robot whose moving links carry no inertia is a
422 ``missing-inertia`` naming the link.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from fastapi import APIRouter, Request

from app.api.body import body_schema, decode_body, group_configurations
from app.api.deps import RobotDep, SettingsDep
from app.api.dynamics_answers import dynamics_answer, load_of
from app.api.errors import ERROR_RESPONSES
from app.api.limits import check_batch_size
from app.api.offload import offload
from app.api.responses import ORJSONResponse
from app.api.schemas.dynamics import (
    DynamicsBatchRequest,
    DynamicsBatchResponse,
    DynamicsRequest,
    DynamicsResponse,
    MaxPayloadRequest,
    MaxPayloadResponse,
)
from app.kinematics.dynamics import (
    check_inertias,
    check_rates,
    gravity_torques,
    inverse_dynamics,
)
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import Group, default_frame, group
from app.kinematics.models import RobotModel
from app.kinematics.payload import MaxPayload, max_payloads

router = APIRouter(prefix="/robots/{robot_id}", tags=["dynamics"])

RESPONSES = {k: ERROR_RESPONSES[k] for k in (400, 404, 422)}


@router.post(
    "/dynamics",
    operation_id="compute_dynamics",
    response_model=DynamicsResponse,
    responses=RESPONSES,
)
async def compute_dynamics(robot: RobotDep, body: DynamicsRequest) -> ORJSONResponse:
    """Joint torques τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F at one state, each term, the mass
    and Coriolis matrices, the centre of mass and the effort ratios.

    Velocities and accelerations are zeros when absent; a payload is a rigid body fixed to a
    frame; the wrench is the one the frame exerts on its environment (as in statics). With
    `group`, every vector and matrix is over the group's joints.
    """
    return ORJSONResponse(dynamics_answer(robot, body))


def _rate_rows(
    robot: RobotModel, grp: Group | None, rows: Any, count: int, width: int, field: str
) -> np.ndarray | None:
    """A batch's velocity or acceleration rows as (N, n), zeros for the joints outside the
    group; rows as wide as the configurations' rows."""
    if rows is None:
        return None
    if len(rows) != count:
        raise InvalidInputError(
            f"expected {count} rows (one per configuration), got {len(rows)}", field
        )
    for i, row in enumerate(rows):
        if len(row) != width:
            raise InvalidInputError(
                f"expected {width} values (as many as each configuration), got {len(row)}",
                f"{field}.{i}",
            )
    arr = np.array(rows, dtype=float).reshape(count, width)
    check_rates(arr, field)
    if width == robot.n:
        return arr
    out = np.zeros((count, robot.n))
    out[:, grp.indices] = arr
    return out


def _batch(robot: RobotModel, raw: bytes, limit: int) -> dict[str, Any]:
    body, rows = decode_body(
        raw,
        DynamicsBatchRequest,
        {"configurations": None, "velocities": None, "accelerations": None},
    )
    grp = group(robot, body.group)
    configs = rows["configurations"]
    qs = group_configurations(robot, grp, configs, limit)
    width = len(configs[0])
    check_inertias(robot)
    qds = _rate_rows(robot, grp, rows.get("velocities"), len(qs), width, "velocities")
    qdds = _rate_rows(robot, grp, rows.get("accelerations"), len(qs), width, "accelerations")
    load = load_of(robot, grp, body.payload)
    torques = inverse_dynamics(robot, qs, qds, qdds, load=load)
    gravity = torques if qds is None and qdds is None else gravity_torques(robot, qs, load=load)
    names = robot.joint_names if grp is None else list(grp.joints)
    if grp is not None:
        torques, gravity = torques[:, grp.indices], gravity[:, grp.indices]
    return {
        "robot_id": robot.id,
        "joint_names": names,
        "torques": np.ascontiguousarray(torques),
        "gravity_torques": np.ascontiguousarray(gravity),
        "payload": None if load is None else load.to_json(),
    }


@router.post(
    "/dynamics/batch",
    operation_id="compute_dynamics_batch",
    response_model=DynamicsBatchResponse,
    responses=RESPONSES,
    openapi_extra=body_schema(DynamicsBatchRequest),
)
async def compute_dynamics_batch(
    robot: RobotDep, request: Request, settings: SettingsDep
) -> ORJSONResponse:
    """Joint torques τ (RNEA) and gravity torques g(q) for many states (q, q̇, q̈), with an
    optional payload, computed off the event loop; up to ``DENAVIT_MAX_BATCH`` states."""
    raw = await request.body()
    return ORJSONResponse(await offload(request, _batch, robot, raw, settings.max_batch))


def _sample(robot: RobotModel, mp: MaxPayload) -> dict[str, Any]:
    return {
        "max_payload": mp.mass,  # inf → null
        "limiting_joint": mp.limiting_joint,
        "per_joint": dict(zip(robot.joint_names, mp.per_joint.tolist(), strict=True)),
        "gravity_torques": mp.gravity,
        "torques_at_max": mp.torques,
        "holds_itself": mp.holds_itself,
    }


def _max_payload(robot: RobotModel, body: MaxPayloadRequest, limit: int) -> dict[str, Any]:
    if body.path is not None and (body.q is not None or body.joint_positions is not None):
        raise InvalidInputError("give either path or q/joint_positions, not both", "path")
    grp = group(robot, body.group)
    if body.path is None:
        qs = body.group_config(robot)[1][None, :]
    else:
        check_batch_size(len(body.path), limit, "configurations", "path")
        if not body.path:
            raise InvalidInputError("give at least one configuration", "path")
        try:
            qs = group_configurations(robot, grp, body.path, limit)
        except InvalidInputError as exc:  # the batch check names `configurations`
            field = exc.field or "configurations"
            raise InvalidInputError(
                exc.message,
                "path" + field.removeprefix("configurations"),
            ) from None
    frame = default_frame(robot, grp, body.frame)
    check_inertias(robot)
    load = load_of(robot, grp, body.payload)
    results = max_payloads(robot, qs, frame, body.com, load=load)
    k = int(np.argmin([r.mass for r in results]))
    out: dict[str, Any] = {
        "robot_id": robot.id,
        "frame": frame,
        "com": body.com,
        "joint_names": robot.joint_names,
        **_sample(robot, results[k]),
        "min_max_payload": None,
        "min_sample": None,
        "samples": None,
    }
    if body.path is not None:
        out["min_max_payload"] = results[k].mass if math.isfinite(results[k].mass) else None
        out["min_sample"] = k
        out["samples"] = [_sample(robot, r) for r in results]
    return out


@router.post(
    "/dynamics/max_payload",
    operation_id="compute_max_payload",
    response_model=MaxPayloadResponse,
    responses=RESPONSES,
)
async def compute_max_payload(
    robot: RobotDep, body: MaxPayloadRequest, request: Request, settings: SettingsDep
) -> ORJSONResponse:
    """The largest payload mass the joints' effort limits hold at rest, at one configuration
    or along a path (its minimum and the sample it occurs at), the limiting joint and each
    joint's bound. A payload that loads no joint with a limit is unbounded (null)."""
    out = await offload(request, _max_payload, robot, body, settings.max_batch)
    return ORJSONResponse(out)
