"""The routes' dependencies, as typed aliases: ``reg: RegistryDep``, ``settings: SettingsDep``.

Each resolves to an object made once per app by ``create_app`` (or, for the scene store, on
first use) and kept on ``app.state``; the ``async`` ones run on the event loop without a
thread hop. :func:`load_robot` gives a route its robot from the registry.
"""

from __future__ import annotations

from typing import Annotated

from fastapi import Depends, Request
from starlette.concurrency import run_in_threadpool
from starlette.requests import HTTPConnection

from app.kinematics.models import RobotModel
from app.operations.settings import Settings
from app.robots.registry import Registry
from app.storage.scenes import SceneStore


async def registry(request: Request) -> Registry:
    """The app's robot registry (``async``: FastAPI runs sync dependencies in a thread)."""
    return request.app.state.registry


async def app_settings(request: Request) -> Settings:
    """The app's settings (those given to ``create_app``); ``async``, no thread hop."""
    return request.app.state.settings


def scene_store(request: HTTPConnection) -> SceneStore:
    """The app's scene store (``<data_dir>/scenes``), created on first use."""
    store = getattr(request.app.state, "scenes", None)
    if store is None:
        store = SceneStore(request.app.state.settings.data_dir / "scenes")
        request.app.state.scenes = store
    return store


RegistryDep = Annotated[Registry, Depends(registry)]
SettingsDep = Annotated[Settings, Depends(app_settings)]
SceneStoreDep = Annotated[SceneStore, Depends(scene_store)]


async def load_robot(reg: Registry, robot_id: str) -> RobotModel:
    """The robot's model; a first load (URDF parsing) runs off the event loop."""
    robot = reg.cached(robot_id)
    if robot is None:
        robot = await run_in_threadpool(reg.get, robot_id)
    return robot
