"""The ASGI application: ``python -m app`` (or ``uvicorn app.main:app``).

Importing this module reads the ``DENAVIT_*`` settings; a bad value exits with one line
naming the variable (see :mod:`app.operations.settings`).

Middleware, outermost first (all pure ASGI, see docs/deployment.md):

1. :class:`~app.middleware.observability.ObservabilityMiddleware` — request id, metrics, access log,
   ``X-Content-Type-Options: nosniff`` on every answer;
2. :class:`~app.middleware.guard.ErrorGuardMiddleware` — 500 problem for a bug, 503 for a request
cut
   off by the shutdown; the connection stays usable;
3. CORS, only when ``DENAVIT_CORS_ORIGINS`` is set;
4. :class:`~app.middleware.body_limit.BodyLimitMiddleware` — 413 past ``DENAVIT_MAX_BODY_BYTES``;
5. :class:`~app.middleware.methods.MethodsMiddleware` — ``HEAD`` on ``GET`` routes, 405 with the
exact
   ``Allow`` of the path.
"""

from __future__ import annotations

import logging
import threading
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from dataclasses import replace

from fastapi import FastAPI
from starlette.middleware.cors import CORSMiddleware

from app.api import errors, static_files
from app.api.routes import ROUTERS, docs_pages, metrics, viewer
from app.api.state import open_services
from app.kinematics.kernels import warm_up as warm_up_kernels
from app.kinematics.meshes import MeshLimits
from app.kinematics.xmldoc import XmlLimits
from app.middleware import openapi
from app.middleware.body_limit import BodyLimitMiddleware
from app.middleware.guard import ErrorGuardMiddleware
from app.middleware.methods import MethodsMiddleware
from app.middleware.observability import ObservabilityMiddleware
from app.operations.logs import configure_logging
from app.operations.settings import Settings, get_settings
from app.robots.documents.archive import ArchiveLimits
from app.robots.documents.limits import UploadLimits
from app.robots.documents.sandbox import PARSE_LIMITS
from app.robots.documents.urdf import UrdfLimits
from app.robots.documents.xacro import XacroLimits
from app.robots.registry import Registry
from app.storage.store import remove_stale_temporaries
from app.workers import procwatch

DESCRIPTION = """\
Kinematics of robot arms over HTTP: forward kinematics, Jacobians, inverse kinematics,
manipulability, statics, rigid-body dynamics and collision checks, computed by Pinocchio.

Conventions: SI units; quaternions [x, y, z, w]; rpy with R = Rz(yaw)·Ry(pitch)·Rx(roll);
poses in the robot's root frame; configurations in the joint order of GET /robots/{id}
(continuous joints as one angle); errors as RFC 9457 problem details.

Real-time clients: the WebSocket `WS /robots/{robot_id}/stream` (not listed below, as
OpenAPI has no WebSockets) answers FK, Jacobian, IK and dynamics requests, the bodies of
these endpoints as JSON messages (or little-endian float64 binary frames for FK, Jacobian
and IK), in order, the last IK solution seeding the next. See docs/stream.md.
"""

log = logging.getLogger("denavit")


@asynccontextmanager
async def lifespan(app: FastAPI) -> AsyncIterator[None]:
    """Start-up: JSON logging, data directory ready, the app's stores and work pools made
    (:class:`~app.api.state.Services`, ``app.state.services``); shutdown: builds cancelled,
    pools and batch IK workers stopped, a last log line.

    In-flight requests are finished by uvicorn before shutdown runs (SIGTERM, up to
    ``DENAVIT_GRACEFUL_TIMEOUT_S``).
    """
    settings: Settings = app.state.settings
    configure_logging(settings.log_level)
    try:
        settings.data_dir.mkdir(parents=True, exist_ok=True)
        removed = remove_stale_temporaries(settings.data_dir)
    except OSError as exc:  # /ready reports it; reads keep working
        log.error("data directory %s is unusable: %s", settings.data_dir, exc)
        removed = 0
    log.info(
        "denavit started",
        extra={
            "data_dir": str(settings.data_dir),
            "write_protection": settings.api_token is not None,
            "cors_origins": settings.cors_origins,
            "max_body_bytes": settings.max_body_bytes,
            "stale_temporaries_removed": removed,
        },
    )
    # Compile the kernels in the background: the first IK request does not wait for it.
    threading.Thread(target=warm_up_kernels, name="kernel-warm-up", daemon=True).start()
    procwatch.exit_with_supervisor(settings.graceful_timeout_s + 5)  # no worker outlives it
    services = app.state.services = open_services(settings)
    try:
        yield
    finally:
        app.state.services = None
        services.close()
        log.info("denavit stopped")


def upload_limits(settings: Settings) -> UploadLimits:
    """The bounds of an upload, from the ``DENAVIT_*`` settings."""
    urdf = UrdfLimits(
        xml=XmlLimits(
            max_elements=settings.max_xml_elements,
            max_attributes=settings.max_xml_attributes,
            max_attributes_per_element=settings.max_xml_attributes_per_element,
            max_depth=settings.max_xml_depth,
        ),
        max_joints=settings.max_urdf_joints,
        max_dof=settings.max_robot_dof,
    )
    return UploadLimits(
        urdf=urdf,
        archive=ArchiveLimits(settings.max_package_files, settings.max_package_unpacked_bytes),
        xacro=XacroLimits(
            settings.xacro_timeout_s, settings.xacro_memory_bytes, settings.xacro_max_output_chars
        ),
        mesh=MeshLimits(
            settings.max_mesh_vertices,
            settings.max_collision_triangles,
            settings.max_collision_mesh_triangles,
        ),
        parse=replace(
            PARSE_LIMITS,
            timeout_s=settings.parse_timeout_s,
            memory_bytes=settings.parse_memory_bytes,
        ),
    )


def create_app(settings: Settings | None = None) -> FastAPI:
    """Build the application (robots are loaded lazily, on first use); its stores and work
    pools are made when its lifespan starts (:func:`lifespan`)."""
    settings = settings or get_settings()
    app = FastAPI(
        title="Denavit",
        version="0.1.0",
        description=DESCRIPTION,
        lifespan=lifespan,
        # FastAPI's pages load from CDNs: app.api.routes.docs_pages serves them offline
        docs_url=None,
        redoc_url=None,
    )
    app.state.settings = settings
    app.state.registry = Registry(settings.data_dir, upload_limits(settings))
    errors.install(app)
    for router in ROUTERS:
        app.include_router(router)
    app.include_router(metrics.router)
    app.include_router(viewer.router)  # GET /viewer (not in the OpenAPI document)
    openapi.install(app)  # error responses documented as sent (problem+json)
    docs_pages.install(app)  # /docs and /redoc, offline
    static_files.mount(app)  # their scripts and styles, from the package
    # add_middleware puts each new one outside the previous ones.
    app.add_middleware(MethodsMiddleware)
    app.add_middleware(BodyLimitMiddleware, max_body_bytes=settings.max_body_bytes)
    if settings.cors_origins:
        app.add_middleware(
            CORSMiddleware,
            allow_origins=settings.cors_origins,
            allow_methods=["GET", "POST", "PUT", "PATCH", "DELETE"],
            allow_headers=["Authorization", "Content-Type", "X-Request-ID"],
            expose_headers=["X-Request-ID"],
            max_age=600,
        )
    app.add_middleware(ErrorGuardMiddleware)
    app.add_middleware(ObservabilityMiddleware, access_log=settings.access_log)
    return app


app = create_app()
