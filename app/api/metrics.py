"""GET /metrics: Prometheus text exposition of this worker's counters (see app.observability)."""

from __future__ import annotations

from fastapi import APIRouter
from starlette.responses import Response

from app.observability import METRICS

router = APIRouter(tags=["service"])

CONTENT_TYPE = "text/plain; version=0.0.4; charset=utf-8"


@router.get(
    "/metrics",
    operation_id="get_metrics",
    response_class=Response,
    responses={
        200: {
            "content": {CONTENT_TYPE: {"schema": {"type": "string"}}},
            "description": "Prometheus text format 0.0.4: request counts and latency "
            "histograms per route template, requests in flight, IK outcomes, process memory.",
        }
    },
)
async def get_metrics() -> Response:
    """Counters of the worker process that answers (Prometheus text format)."""
    return Response(METRICS.render(), media_type=CONTENT_TYPE)
