"""Collision checks: POST /robots/{robot_id}/collisions, …/collisions/batch and
GET /robots/{robot_id}/collision_pairs.

The rules (which pairs are checked, mesh vs convex-hull geometry, margins, signed
distances) are those of :mod:`app.kinematics.collision`; see docs/collisions.md.
"""

from __future__ import annotations

import threading
from typing import Annotated, Literal

import numpy as np
from fastapi import APIRouter, Request
from pydantic import BaseModel, Field, Strict

from app.api.body import group_configurations
from app.api.deps import RegistryDep, SceneStoreDep, load_robot
from app.api.errors import ERROR_RESPONSES
from app.api.offload import offload, offload_cancellable
from app.api.responses import ORJSONResponse
from app.api.routes.scenes import ObstacleIn, resolve_obstacles
from app.api.schemas.common import (
    ConfigurationIn,
    JointValue,
    RobotId,
    Schema,
    Vec3Out,
    group_field,
)
from app.kinematics.collision import collision_model, collision_model_built, report_json
from app.kinematics.collision_pairs import collision_link_pairs, collision_links
from app.kinematics.groups import group
from app.kinematics.models import RobotModel
from app.kinematics.obstacles import MAX_OBSTACLES, Obstacle

router = APIRouter(prefix="/robots/{robot_id}", tags=["collisions"])

#: Obstacle counts above this are checked in the work pool rather than on the event loop.
INLINE_OBSTACLES = 8
GeometryMode = Literal["mesh", "convex"]
Margin = Annotated[float, Strict(), Field(ge=0.0, le=10.0, allow_inf_nan=False)]
Flag = Annotated[bool, Strict()]


class CollisionOptions(Schema):
    """What to check against and how."""

    obstacles: list[ObstacleIn] | None = Field(
        None, max_length=MAX_OBSTACLES, description="Obstacles in the robot's root frame."
    )
    scene: str | None = Field(
        None, max_length=64, description="Name of a stored scene (instead of obstacles)."
    )
    margin: Margin = Field(
        0.0, description="Safety margin (m): pairs closer than this count as in collision."
    )
    distances: Flag = Field(
        False,
        description="Compute every checked pair's distance and witness points "
        "(slower, especially with meshes).",
    )
    geometry: GeometryMode = Field(
        "mesh",
        description="mesh: the URDF collision meshes (exact); convex: their convex hulls "
        "(faster, conservative, signed distances).",
    )


class CollisionRequest(ConfigurationIn, CollisionOptions):
    """A configuration to check."""


class PairOut(BaseModel):
    """A checked pair: two links (self) or a link and an obstacle (environment)."""

    a: str = Field(description="Link name.")
    b: str = Field(description="Link name (self) or obstacle name (environment).")
    kind: Literal["self", "environment"]
    in_collision: bool = Field(description="Closer than the margin.")
    distance: float | None = Field(
        description="Distance (m); negative = penetration depth where coal computes it "
        "(convex hulls, primitives); 0 for penetrating meshes."
    )
    point_a: Vec3Out | None = Field(
        None, description="Witness point on a, root frame (m); with distances."
    )
    point_b: Vec3Out | None = Field(
        None, description="Witness point on b, root frame (m); with distances."
    )


class CollisionResponse(BaseModel):
    """The verdict for one configuration."""

    robot_id: str
    q: list[float] = Field(description="The configuration checked, in joint order.")
    geometry: str
    margin: float
    in_collision: bool = Field(description="Any pair closer than the margin.")
    self_collision: bool = Field(description="Two links of the robot collide.")
    environment_collision: bool = Field(description="A link collides with an obstacle.")
    min_distance: float | None = Field(
        description="Smallest distance (m) over the checked pairs with distances; otherwise "
        "over the pairs in collision (null when none)."
    )
    pairs: list[PairOut] = Field(
        description="Pairs in collision, or every checked pair with distances; closest first."
    )
    checked_pairs: int = Field(description="Number of link/link and link/obstacle pairs checked.")


class CollisionBatchRequest(CollisionOptions):
    """Many configurations (e.g. the waypoints of a trajectory)."""

    configurations: list[list[JointValue]] = Field(
        description="N configurations, each one value per joint in joint order (rad, m); "
        "with `group`, rows of the group's joints only are accepted too (others neutral)."
    )
    group: str | None = group_field()


class CollisionBatchResponse(BaseModel):
    """Compact per-configuration answers: entry i for configuration i."""

    robot_id: str
    geometry: str
    margin: float
    count: int
    num_in_collision: int
    first_collision: int | None = Field(description="Index of the first colliding configuration.")
    in_collision: list[bool]
    self_collision: list[bool]
    environment_collision: list[bool]
    pairs: list[list[list[str]]] = Field(description="Per configuration: colliding [a, b] pairs.")
    min_distance: list[float] | None = Field(
        None, description="Per configuration: smallest distance (m); only with distances."
    )


class CollisionPairsResponse(BaseModel):
    """Which self-collision pairs are checked."""

    robot_id: str
    links: list[str] = Field(description="Links with collision geometry.")
    pairs: list[list[str]] = Field(description="Checked link pairs [a, b].")
    srdf: bool = Field(description="Whether an SRDF disabled pairs.")


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
    robot_id: RobotId,
    body: CollisionRequest,
    reg: RegistryDep,
    store: SceneStoreDep,
) -> ORJSONResponse:
    """Self-collision and collision with obstacles at one configuration.

    Obstacles come inline (``obstacles``) or from a stored ``scene``. Links fixed to the
    world are not checked against obstacles; adjacent links and SRDF-disabled pairs are
    never checked (GET /robots/{robot_id}/collision_pairs lists the checked pairs).
    """
    robot = await load_robot(reg, robot_id)
    _, q = body.group_config(robot)
    obstacles = resolve_obstacles(store, body.obstacles, body.scene)
    built = collision_model_built(robot, body.geometry)
    heavy = (
        not built
        or len(obstacles) > INLINE_OBSTACLES
        or (body.distances and body.geometry == "mesh")
    )
    if heavy:
        return ORJSONResponse(await offload(_check, robot, q, obstacles, body))
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
    robot_id: RobotId,
    body: CollisionBatchRequest,
    reg: RegistryDep,
    store: SceneStoreDep,
    request: Request,
) -> ORJSONResponse:
    """Check many configurations (e.g. a trajectory's waypoints) in the work pool."""
    robot = await load_robot(reg, robot_id)
    grp = group(robot, body.group)
    limit = request.app.state.settings.max_batch
    qs = group_configurations(robot, grp, body.configurations, limit)
    obstacles = resolve_obstacles(store, body.obstacles, body.scene)
    out = await offload_cancellable(request, _check_batch, robot, qs, obstacles, body)
    return ORJSONResponse(out)


@router.get(
    "/collision_pairs",
    operation_id="get_collision_pairs",
    response_model=CollisionPairsResponse,
    responses={404: ERROR_RESPONSES[404]},
)
def get_collision_pairs(robot_id: RobotId, reg: RegistryDep) -> ORJSONResponse:
    """The self-collision link pairs checked (after removing same-body, adjacent and
    SRDF-disabled pairs); computed from the URDF without loading meshes."""
    robot = reg.get(robot_id)
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
