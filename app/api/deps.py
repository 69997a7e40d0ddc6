"""The routes' dependencies, as typed aliases: ``robot: RobotDep``, ``settings: SettingsDep``.

Each resolves to an object of the app: the settings and registry given to or made by
``create_app``, the stores made by the lifespan (:mod:`app.api.state`), or the robot named
by the path. All are ``async``: FastAPI runs them on the event loop without a thread hop
(a sync dependency costs a hop to the thread pool on every request), and each reads
``app.state`` directly rather than through another dependency (a nested dependency costs
a few µs per request on the hot FK/Jacobian/IK routes).
"""

from __future__ import annotations

from typing import Annotated

from fastapi import Depends, Request
from starlette.concurrency import run_in_threadpool
from starlette.requests import HTTPConnection

from app.api.schemas.common import RobotId
from app.api.state import services
from app.kinematics.models import RobotModel
from app.operations.settings import Settings
from app.robots.registry import Registry
from app.storage.build_jobs import BuildJobs
from app.storage.maps import MapStore
from app.storage.scenes import SceneStore


async def registry(request: Request) -> Registry:
    """The app's robot registry."""
    return request.app.state.registry


async def app_settings(request: Request) -> Settings:
    """The app's settings (those given to ``create_app``)."""
    return request.app.state.settings


async def load_robot(reg: Registry, robot_id: str) -> RobotModel:
    """The robot's model; a first load (URDF parsing) runs off the event loop.

    Raises the registry's errors: :class:`~app.kinematics.errors.UnknownNameError` (404,
    field ``robot_id``) for an unknown id, and those of a robot that cannot be built.
    """
    robot = reg.cached(robot_id)
    if robot is None:
        robot = await run_in_threadpool(reg.get, robot_id)
    return robot


async def path_robot(robot_id: RobotId, request: Request) -> RobotModel:
    """The robot named by the path's ``robot_id`` (:func:`load_robot`)."""
    return await load_robot(request.app.state.registry, robot_id)


async def scene_store(conn: HTTPConnection) -> SceneStore:
    """The app's scene store (``<data_dir>/scenes``)."""
    return services(conn).scenes


async def map_store(request: Request) -> MapStore:
    """The app's reachability map store (``<data_dir>/maps``)."""
    return services(request).maps


async def build_jobs(request: Request) -> BuildJobs:
    """The app's reachability build queue."""
    return services(request).jobs


RegistryDep = Annotated[Registry, Depends(registry)]
SettingsDep = Annotated[Settings, Depends(app_settings)]
RobotDep = Annotated[RobotModel, Depends(path_robot)]
SceneStoreDep = Annotated[SceneStore, Depends(scene_store)]
MapStoreDep = Annotated[MapStore, Depends(map_store)]
BuildJobsDep = Annotated[BuildJobs, Depends(build_jobs)]
