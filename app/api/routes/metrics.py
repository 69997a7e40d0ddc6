"""GET /metrics: Prometheus text exposition of the service's counters, summed over its worker
processes (see app.middleware.observability and app.operations.metrics)."""

from __future__ import annotations

from fastapi import APIRouter
from starlette.responses import Response

from app.operations.metrics import METRICS

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
            "histograms per route template, requests in flight, IK outcomes, and per worker "
            "(`pid` label) resident memory, CPU time and start time. Every scrape reports "
            "the whole service, whichever worker answers it: counters are summed over all "
            "the worker processes of the service, including workers that have exited (a "
            "replaced worker's counts stay), so they never go down while the service runs; "
            "a restart of the service starts them from zero. `denavit_http_requests_in_flight`"
            " sums the live workers; `denavit_worker_processes{state}` counts the live and "
            "exited workers summed; `denavit_process_info{pid}` names the answering worker. "
            "A request is counted before the last byte of its response is sent.",
        }
    },
)
async def get_metrics() -> Response:
    """The service's counters, summed over its worker processes (Prometheus text format)."""
    return Response(METRICS.render(), media_type=CONTENT_TYPE)
