"""The ASGI application: ``uvicorn app.main:app``."""

from __future__ import annotations

from fastapi import FastAPI

from app import api
from app.api import errors
from app.api.common import EXTRA_SCHEMAS
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
    app.state.registry = Registry(settings.data_dir)
    errors.install(app)
    for router in api.ROUTERS:
        app.include_router(router)
    _document_self_decoded_bodies(app)
    return app


def _document_self_decoded_bodies(app: FastAPI) -> None:
    """Add the request models of routes that decode their own bodies to the schema."""
    build = app.openapi

    def openapi() -> dict:
        if app.openapi_schema is None:
            schema = build()  # FastAPI caches it in app.openapi_schema
            components = schema.setdefault("components", {}).setdefault("schemas", {})
            for model in EXTRA_SCHEMAS:
                defs = model.model_json_schema(ref_template="#/components/schemas/{model}")
                components.update(defs.pop("$defs", {}))
                components[model.__name__] = defs
        return app.openapi_schema

    app.openapi = openapi


app = create_app()
