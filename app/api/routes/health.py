"""GET /health (liveness) and GET /ready (readiness).

``/health`` answers ``{"status": "ok"}`` whenever the process serves requests; it loads
no robot and touches no disk, so it stays fast under load (long work runs in the bounded
pool, off the event loop). ``/ready`` checks what serving needs: the data directory is
readable and writable (a temporary file is created and removed) and the robot catalog is
available (its URDF files exist); 200 when both hold, else 503 problem details listing the
failed ``checks``.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from fastapi import APIRouter
from starlette.concurrency import run_in_threadpool
from starlette.responses import Response

from app.api.deps import RegistryDep, SettingsDep
from app.api.errors import Problem, problem
from app.api.responses import ORJSONResponse
from app.api.schemas.health import Health, Ready
from app.robots.registry import Registry
from app.storage.store import TMP_PREFIX

router = APIRouter(tags=["service"])


@router.get("/health", operation_id="get_health", response_model=Health)
async def get_health() -> ORJSONResponse:
    """The process is up and serving."""
    return ORJSONResponse({"status": "ok"})


@router.get(
    "/ready",
    operation_id="get_ready",
    response_model=Ready,
    responses={
        503: {
            "model": Problem,
            "content": {"application/problem+json": {}},
            "description": "Not ready: `checks` says which check failed and why.",
        }
    },
)
async def get_ready(settings: SettingsDep, registry: RegistryDep) -> Response:
    """Whether the service can serve: data directory writable, catalog available."""
    checks = await run_in_threadpool(readiness_checks, Path(settings.data_dir), registry)
    failed = {name: why for name, why in checks.items() if why != "ok"}
    if failed:
        detail = "; ".join(f"{name}: {why}" for name, why in failed.items())
        return problem(
            503, f"not ready: {detail}", kind="not-ready", instance="/ready", checks=checks
        )
    return ORJSONResponse({"status": "ready", "checks": checks})


def readiness_checks(data_dir: Path, registry: Registry) -> dict[str, str]:
    """Check name → ``"ok"`` or the reason it failed."""
    return {"data_dir": check_data_dir(data_dir), "catalog": check_catalog(registry)}


def check_data_dir(data_dir: Path) -> str:
    """``"ok"`` if ``data_dir`` exists (or can be created), is listable and writable."""
    try:
        data_dir.mkdir(parents=True, exist_ok=True)
        os.listdir(data_dir)
        fd, tmp = tempfile.mkstemp(prefix=TMP_PREFIX + "ready-", dir=data_dir)
        os.close(fd)
        os.unlink(tmp)
    except OSError as exc:
        return f"{data_dir} is not a readable, writable directory ({exc.strerror or exc})"
    return "ok"


def check_catalog(registry: Registry) -> str:
    """``"ok"`` if the built-in catalog has robots and every one of its URDF files exists."""
    try:
        if not registry.catalog:
            return "the robot catalog is empty"
        missing = [e.id for e in registry.catalog.values() if not e.urdf_path.is_file()]
    except (OSError, RuntimeError) as exc:
        return f"the robot catalog is unavailable ({exc})"
    if missing:
        return "URDF files missing for " + ", ".join(missing)
    return "ok"
