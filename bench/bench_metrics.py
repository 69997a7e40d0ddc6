"""Metrics recording: what the observability middleware costs per request, in process.

1. ``Metrics.observe`` alone (one request's counters: status count, latency bucket, sum).
2. The whole middleware (request id, in-flight gauge, status capture, metrics; access log
   off) around a trivial ASGI app that answers 200 with an empty body, minus the same app
   called directly: the middleware's own cost per request.

With counters shared between worker processes (``Metrics.share``, what the service does at
start-up), each value lives in prometheus_client's memory-mapped file of the process; the
rows say which mode was measured. For reference, the same five updates of a request
(in flight +1 and −1, status count, latency bucket and sum) through prometheus_client's own
``Counter``/``Histogram``/``Gauge`` objects in multiprocess mode, children cached.

No server, no network: the numbers isolate the recording itself. Times
are CPU time of this process (``time.process_time``), so that other load on the machine
inflates them less than wall-clock time would.
"""

from __future__ import annotations

import asyncio
import os
import tempfile
import time
from pathlib import Path
from typing import Any

from app.middleware.observability import ObservabilityMiddleware
from app.operations.metrics import LATENCY_BUCKETS, Metrics

ROUTES = [f"/robots/{{robot_id}}/route{i}" for i in range(20)]


class _Route:
    def __init__(self, path: str) -> None:
        self.path = path


async def _app(scope: dict[str, Any], receive: Any, send: Any) -> None:
    scope["route"] = scope["_route"]
    await send({"type": "http.response.start", "status": 200, "headers": []})
    await send({"type": "http.response.body", "body": b""})


async def _receive() -> dict[str, Any]:
    return {"type": "http.request", "body": b"", "more_body": False}


async def _send(message: dict[str, Any]) -> None:
    return None


def _observe_us(metrics: Metrics, n: int, repeats: int = 5) -> float:
    best = float("inf")
    for _ in range(repeats):
        t0 = time.process_time()
        for i in range(n):
            metrics.observe("POST", ROUTES[i % 20], 200, 0.0004)
        best = min(best, (time.process_time() - t0) / n)
    return best * 1e6


def _library_us(directory: str, n: int, repeats: int = 5) -> float:
    """One request's updates through prometheus_client's metric objects, multiprocess mode."""
    from prometheus_client import Counter, Gauge, Histogram, values

    saved_class, saved_env = values.ValueClass, os.environ.get("PROMETHEUS_MULTIPROC_DIR")
    os.environ["PROMETHEUS_MULTIPROC_DIR"] = directory
    values.ValueClass = values.MultiProcessValue()
    try:
        labels = ["method", "route", "status"]
        requests = Counter("bench_requests_total", "h", labels, registry=None)
        latency = Histogram(
            "bench_seconds", "h", ["method", "route"], buckets=LATENCY_BUCKETS, registry=None
        )
        in_flight = Gauge("bench_in_flight", "h", registry=None, multiprocess_mode="livesum")
        counts: dict[str, Any] = {}
        hists: dict[str, Any] = {}
        best = float("inf")
        for _ in range(repeats):
            t0 = time.process_time()
            for i in range(n):
                route = ROUTES[i % 20]
                in_flight.inc()
                count = counts.get(route)
                if count is None:
                    count = counts[route] = requests.labels("POST", route, "200")
                hist = hists.get(route)
                if hist is None:
                    hist = hists[route] = latency.labels("POST", route)
                in_flight.dec()
                count.inc()
                hist.observe(0.0004)
            best = min(best, (time.process_time() - t0) / n)
        return best * 1e6
    finally:
        values.ValueClass = saved_class
        if saved_env is None:
            os.environ.pop("PROMETHEUS_MULTIPROC_DIR", None)
        else:
            os.environ["PROMETHEUS_MULTIPROC_DIR"] = saved_env


def _enter_finish_us(metrics: Metrics, n: int, repeats: int = 5) -> float:
    best = float("inf")
    for _ in range(repeats):
        t0 = time.process_time()
        for i in range(n):
            metrics.enter()
            metrics.finish("POST", ROUTES[i % 20], 200, 0.0004)
        best = min(best, (time.process_time() - t0) / n)
    return best * 1e6


def _asgi_us(app: Any, n: int, repeats: int = 5) -> float:
    scopes = [
        {
            "type": "http",
            "method": "POST",
            "path": "/robots/panda/fk",
            "headers": [(b"content-type", b"application/json")],
            "_route": _Route(ROUTES[i % 20]),
        }
        for i in range(20)
    ]

    async def run() -> float:
        best = float("inf")
        for _ in range(repeats):
            t0 = time.process_time()
            for i in range(n):
                await app(dict(scopes[i % 20]), _receive, _send)
            best = min(best, (time.process_time() - t0) / n)
        return best

    return asyncio.run(run()) * 1e6


def rows(n: int = 100_000) -> list[tuple[str, float]]:
    out: list[tuple[str, float]] = []
    with tempfile.TemporaryDirectory() as tmp:
        modes: list[tuple[str, Metrics]] = [("process-local", Metrics())]
        if hasattr(Metrics, "share"):
            shared = Metrics()
            shared.share(Path(tmp))
            modes.append(("shared (mmap file)", shared))
        bare = _asgi_us(_app, n)
        for label, metrics in modes:
            out.append((f"Metrics.observe, {label}", _observe_us(metrics, n)))
            out.append((f"Metrics.enter + finish, {label}", _enter_finish_us(metrics, n)))
            mw = ObservabilityMiddleware(_app, access_log=False, metrics=metrics)
            out.append((f"middleware minus bare app, {label}", _asgi_us(mw, n) - bare))
            t0 = time.process_time()
            for _ in range(20):
                metrics.render()
            out.append((f"render (scrape), {label}", (time.process_time() - t0) / 20 * 1e6))
        out.append(("bare ASGI app (reference)", bare))
        if hasattr(Metrics, "share"):
            with tempfile.TemporaryDirectory() as lib:
                label = "prometheus_client objects, multiprocess (enter + finish)"
                out.append((label, _library_us(lib, n)))
    return out


def main() -> None:
    print("\n### Metrics recording in process (CPU time, best of 5 passes of 100 000)\n")
    print("| operation | µs per call |\n|---|---|")
    for label, us in rows():
        print(f"| {label} | {us:,.2f} |")


if __name__ == "__main__":
    main()
