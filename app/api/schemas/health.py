"""Wire models of the service's liveness (GET /health) and readiness (GET /ready)."""

from __future__ import annotations

from pydantic import BaseModel, Field


class Health(BaseModel):
    """Liveness answer."""

    status: str = Field(description='Always "ok".')


class Ready(BaseModel):
    """Readiness answer: every check passed."""

    status: str = Field(description='"ready".')
    checks: dict[str, str] = Field(description='Check name → "ok" (data_dir, catalog).')
