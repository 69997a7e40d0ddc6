"""Collision checks: POST /robots/{robot_id}/collisions, …/collisions/batch and
GET /robots/{robot_id}/collision_pairs.

The rules (which pairs are checked, mesh vs convex-hull geometry, margins, signed
distances) are those of :mod:`app.kinematics.collision`; see docs/collisions.md. Wire
models: :mod:`app.api.schemas.collisions`.
"""

from __future__ import annotations

import threading

import numpy as np
from fastapi import APIRouter, Request

from app.api.body import group_configurations
from app.api.deps import RobotDep, SceneStoreDep, SettingsDep
from app.api.errors import ERROR_RESPONSES
from app.api.obstacles import resolve_obstacles
from app.api.offload import offload, offload_cancellable
from app.api.responses import ORJSONResponse
from app.api.schemas.collisions import (
    CollisionBatchRequest,
    CollisionBatchResponse,
    CollisionPairsResponse,
    CollisionRequest,
    CollisionResponse,
)
from app.kinematics.collision import collision_model, collision_model_built, report_json
from app.kinematics.collision_pairs import collision_link_pairs, collision_links
from app.kinematics.groups import group
from app.kinematics.models import RobotModel
from app.kinematics.obstacles import Obstacle

router = APIRouter(prefix="/robots/{robot_id}", tags=["collisions"])

#: Obstacle counts above this are checked in the work pool rather than on the event loop.
INLINE_OBSTACLES = 8


def _check(robot: RobotModel, q: np.ndarray, obstacles: tuple[Obstacle, ...], body) -> dict:
    cm = collision_model(robot, body.geometry)
    report = cm.check(q, obstacles, margin=body.margin, distances=body.distances)
    out = report_json(report, witness=body.distances)
    return {
        "robot_id": robot.id,
        "q": q.tolist(),
        "geometry": body.geometry,
        "margin": body.margin,
        **out,
    }


@router.post(
    "/collisions",
    operation_id="check_collisions",
    response_model=CollisionResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def check_collisions(
    robot: RobotDep, body: CollisionRequest, store: SceneStoreDep, request: Request
) -> ORJSONResponse:
    """Self-collision and collision with obstacles at one configuration.

    Obstacles come inline (``obstacles``) or from a stored ``scene``. Links fixed to the
    world are not checked against obstacles; adjacent links and SRDF-disabled pairs are
    never checked (GET /robots/{robot_id}/collision_pairs lists the checked pairs).
    """
    _, q = body.group_config(robot)
    obstacles = resolve_obstacles(store, body.obstacles, body.scene)
    built = collision_model_built(robot, body.geometry)
    heavy = (
        not built
        or len(obstacles) > INLINE_OBSTACLES
        or (body.distances and body.geometry == "mesh")
    )
    if heavy:
        return ORJSONResponse(await offload(request, _check, robot, q, obstacles, body))
    return ORJSONResponse(_check(robot, q, obstacles, body))


def _check_batch(
    robot: RobotModel,
    qs: np.ndarray,
    obstacles: tuple[Obstacle, ...],
    body,
    cancel: threading.Event | None = None,
) -> dict:
    cm = collision_model(robot, body.geometry)
    reports = cm.check_batch(
        qs, obstacles, margin=body.margin, distances=body.distances, cancel=cancel
    )
    flags = [r.in_collision for r in reports]
    first = next((i for i, f in enumerate(flags) if f), None)
    out = {
        "robot_id": robot.id,
        "geometry": body.geometry,
        "margin": body.margin,
        "count": len(reports),
        "num_in_collision": sum(flags),
        "first_collision": first,
        "in_collision": flags,
        "self_collision": [r.self_collision for r in reports],
        "environment_collision": [r.environment_collision for r in reports],
        "pairs": [[[p.a, p.b] for p in r.pairs if p.in_collision] for r in reports],
    }
    if body.distances:
        out["min_distance"] = [r.min_distance for r in reports]
    return out


@router.post(
    "/collisions/batch",
    operation_id="check_collisions_batch",
    response_model=CollisionBatchResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def check_collisions_batch(
    robot: RobotDep,
    body: CollisionBatchRequest,
    store: SceneStoreDep,
    request: Request,
    settings: SettingsDep,
) -> ORJSONResponse:
    """Check many configurations (e.g. a trajectory's waypoints) in the work pool."""
    grp = group(robot, body.group)
    qs = group_configurations(robot, grp, body.configurations, settings.max_batch)
    obstacles = resolve_obstacles(store, body.obstacles, body.scene)
    out = await offload_cancellable(request, _check_batch, robot, qs, obstacles, body)
    return ORJSONResponse(out)


@router.get(
    "/collision_pairs",
    operation_id="get_collision_pairs",
    response_model=CollisionPairsResponse,
    responses={404: ERROR_RESPONSES[404]},
)
def get_collision_pairs(robot: RobotDep) -> ORJSONResponse:
    """The self-collision link pairs checked (after removing same-body, adjacent and
    SRDF-disabled pairs); computed from the URDF without loading meshes."""
    pairs = collision_link_pairs(robot)
    links = sorted(collision_links(robot), key=robot.frame_id)
    return ORJSONResponse(
        {
            "robot_id": robot.id,
            "links": links,
            "pairs": [list(p) for p in pairs],
            "srdf": bool(robot.srdf_text),
        }
    )
