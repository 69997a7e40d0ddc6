"""The ASGI application: ``uvicorn app.main:app``."""

from __future__ import annotations

from fastapi import FastAPI

from app import api
from app.api import errors
from app.registry import Registry
from app.settings import Settings, get_settings

DESCRIPTION = """\
Kinematics of robot arms over HTTP: forward kinematics, Jacobians, inverse kinematics,
manipulability, statics and collision checks, computed by Pinocchio.

Conventions: SI units; quaternions [x, y, z, w]; rpy with R = Rz(yaw)·Ry(pitch)·Rx(roll);
poses in the robot's root frame; configurations in the joint order of GET /robots/{id}
(continuous joints as one angle); errors as RFC 9457 problem details.
"""


def create_app(settings: Settings | None = None) -> FastAPI:
    """Build the application (robots are loaded lazily, on first use)."""
    settings = settings or get_settings()
    app = FastAPI(title="Denavit", version="0.1.0", description=DESCRIPTION)
    app.state.settings = settings
    app.state.registry = Registry()
    errors.install(app)
    for router in api.ROUTERS:
        app.include_router(router)
    return app


app = create_app()
