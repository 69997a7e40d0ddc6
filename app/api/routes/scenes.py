"""Scenes: POST /scenes, GET /scenes, GET /scenes/{name}, DELETE /scenes/{name}.

A scene is a named set of obstacles, stored under ``<data_dir>/scenes/<name>.json``
(:mod:`app.storage.scenes`); collision and IK requests may name a ``scene`` instead of giving
``obstacles`` inline. This module also holds the obstacle request schema and the helper
that turns ``obstacles`` / ``scene`` request fields into validated obstacles.
"""

from __future__ import annotations

from typing import Annotated, Literal

from fastapi import APIRouter, Depends, Path
from pydantic import BaseModel, Field, Strict
from starlette.responses import Response

from app.api.deps import SceneStoreDep
from app.api.errors import ERROR_RESPONSES
from app.api.responses import ORJSONResponse
from app.api.schemas.common import Quat, Schema, Text, Vec3, Vec3Out
from app.api.security import require_token
from app.kinematics.errors import InvalidInputError
from app.kinematics.obstacles import MAX_NAME_LENGTH, MAX_OBSTACLES, Obstacle, parse_obstacles
from app.storage.scenes import MAX_DESCRIPTION, NAME_PATTERN, SceneStore

router = APIRouter(prefix="/scenes", tags=["collisions"])

#: A finite, strictly positive length (m).
PositiveLength = Annotated[float, Strict(), Field(gt=0, allow_inf_nan=False)]
SceneName = Annotated[
    str, Path(description="Scene name (letters, digits, '_', '-').", max_length=64)
]


class ObstaclePose(Schema):
    """Placement of an obstacle in the robot's root frame."""

    position: Vec3 = Field([0.0, 0.0, 0.0], description="Centre [x, y, z] (m).")
    orientation: Quat = Field(
        [0.0, 0.0, 0.0, 1.0], description="Unit quaternion [x, y, z, w] (root ← obstacle)."
    )


class ObstacleIn(Schema):
    """A box, sphere, cylinder or capsule in the robot's root frame."""

    name: Text = Field(
        min_length=1, max_length=MAX_NAME_LENGTH, description="Unique name in the set."
    )
    shape: Literal["box", "sphere", "cylinder", "capsule"] = Field(description="Solid type.")
    size: Annotated[list[PositiveLength], Field(min_length=3, max_length=3)] | None = Field(
        None, description="box: full edge lengths [x, y, z] (m)."
    )
    radius: PositiveLength | None = Field(
        None, description="sphere, cylinder, capsule: radius (m)."
    )
    length: PositiveLength | None = Field(
        None,
        description="cylinder: full height along local z (m); capsule: length of the "
        "segment between the hemisphere centres (m).",
    )
    pose: ObstaclePose | None = Field(None, description="Placement; default the identity.")


class ObstacleOut(BaseModel):
    """A stored obstacle (normalised orientation)."""

    name: str
    shape: str
    size: Vec3Out | None = None
    radius: float | None = None
    length: float | None = None
    pose: ObstaclePose


class SceneIn(Schema):
    """A new scene."""

    name: str = Field(pattern=NAME_PATTERN, description="Scene name (1-64 of A-Z a-z 0-9 _ -).")
    description: Text = Field("", max_length=MAX_DESCRIPTION)
    obstacles: list[ObstacleIn] = Field(max_length=MAX_OBSTACLES, description="The obstacles.")


class SceneOut(BaseModel):
    """A stored scene."""

    name: str
    description: str
    obstacles: list[ObstacleOut]


class SceneSummary(BaseModel):
    """A scene in the list."""

    name: str
    description: str
    obstacles: int = Field(description="Number of obstacles.")


class SceneList(BaseModel):
    """Every stored scene."""

    scenes: list[SceneSummary]


def resolve_obstacles(
    store: SceneStore, obstacles: list[ObstacleIn] | None, scene: str | None
) -> tuple[Obstacle, ...]:
    """Validated obstacles from a request's ``obstacles`` or ``scene`` (not both).

    Raises 422 naming the field for a bad obstacle or when both are given, 404 for an
    unknown scene.
    """
    if obstacles is not None and scene is not None:
        raise InvalidInputError("give either obstacles or scene, not both", "scene")
    if scene is not None:
        return store.get(scene, field="scene").obstacles
    if not obstacles:
        return ()
    return parse_obstacles([o.model_dump(exclude_none=True) for o in obstacles])


@router.post(
    "",
    operation_id="create_scene",
    status_code=201,
    response_model=SceneOut,
    dependencies=[Depends(require_token)],
    responses={
        **{k: ERROR_RESPONSES[k] for k in (400, 422)},
        409: {**ERROR_RESPONSES[422], "description": "A scene with this name exists."},
    },
)
def create_scene(body: SceneIn, store: SceneStoreDep) -> ORJSONResponse:
    """Store a named set of obstacles (409 if the name is taken; persisted across restarts)."""
    scene = store.create(
        body.name,
        [o.model_dump(exclude_none=True) for o in body.obstacles],
        body.description,
    )
    return ORJSONResponse(scene.to_json(), status_code=201)


@router.get("", operation_id="list_scenes", response_model=SceneList)
def list_scenes(store: SceneStoreDep) -> ORJSONResponse:
    """List the stored scenes."""
    return ORJSONResponse(
        {
            "scenes": [
                {"name": s.name, "description": s.description, "obstacles": len(s.obstacles)}
                for s in store.list()
            ]
        }
    )


@router.get(
    "/{name}",
    operation_id="get_scene",
    response_model=SceneOut,
    responses={404: ERROR_RESPONSES[404]},
)
def get_scene(name: SceneName, store: SceneStoreDep) -> ORJSONResponse:
    """A stored scene with its obstacles."""
    return ORJSONResponse(store.get(name, field="name").to_json())


@router.delete(
    "/{name}",
    operation_id="delete_scene",
    status_code=204,
    dependencies=[Depends(require_token)],
    responses={404: ERROR_RESPONSES[404]},
)
def delete_scene(name: SceneName, store: SceneStoreDep) -> Response:
    """Delete a stored scene."""
    store.delete(name, field="name")
    return Response(status_code=204)
