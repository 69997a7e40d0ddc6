"""Scenes: POST /scenes, GET /scenes, GET /scenes/{name}, DELETE /scenes/{name}.

A scene is a named set of obstacles, stored under ``<data_dir>/scenes/<name>.json``
(:mod:`app.storage.scenes`); collision and IK requests may name a ``scene`` instead of giving
``obstacles`` inline (:mod:`app.api.obstacles`). Wire models: :mod:`app.api.schemas.scenes`.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Depends
from starlette.responses import Response

from app.api.deps import SceneStoreDep
from app.api.errors import ERROR_RESPONSES
from app.api.obstacles import obstacle_items, obstacle_json
from app.api.responses import ORJSONResponse
from app.api.schemas.scenes import SceneIn, SceneList, SceneName, SceneOut
from app.api.security import require_token
from app.storage.scenes import Scene

router = APIRouter(prefix="/scenes", tags=["collisions"])


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
        obstacle_items(body.obstacles),
        body.description,
    )
    return ORJSONResponse(_scene_json(scene), status_code=201)


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
    return ORJSONResponse(_scene_json(store.get(name, field="name")))


def _scene_json(scene: Scene) -> dict[str, Any]:
    """A scene's answer: its wire form with every obstacle pose filled (position,
    orientation, rpy, matrix)."""
    out = scene.to_json()
    out["obstacles"] = [obstacle_json(o) for o in out["obstacles"]]
    return out


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
