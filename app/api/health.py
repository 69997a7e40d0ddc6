"""GET /health: liveness; answers without loading any robot."""

from __future__ import annotations

from fastapi import APIRouter
from pydantic import BaseModel

from app.api.common import ORJSONResponse

router = APIRouter(tags=["service"])


class Health(BaseModel):
    """Liveness answer."""

    status: str


@router.get("/health", operation_id="get_health", response_model=Health)
async def get_health() -> ORJSONResponse:
    """The process is up and serving."""
    return ORJSONResponse({"status": "ok"})
