"""The request middleware: request ids, request metrics, one access-log line per request.

- **Request ids.** Every HTTP request gets an id: the client's ``X-Request-ID`` header when it
  is a sane token (1–128 characters of ``[A-Za-z0-9._:/+=@-]``), else 24 random hex digits.
  The id is echoed in the ``X-Request-ID`` response header and attached to every log line
  written while the request is handled (:data:`app.operations.logs.REQUEST_ID`).
- **Metrics.** Each request is counted in :data:`app.operations.metrics.METRICS` (by method, route
  template and status, with its latency) before the last byte of its response is sent, so
  a scrape that follows a completed request always includes it.
- **nosniff.** Every answer carries ``X-Content-Type-Options: nosniff``: a browser keeps
  to the declared content type (a JSON answer or an uploaded file is never sniffed into a
  page or a script); it is appended with the request id, so it costs nothing more.
- **Access log.** With ``DENAVIT_ACCESS_LOG`` on (the default) each request writes one
  ``denavit.access`` line with ``method``, ``path``, ``route`` (the path template),
  ``status`` and ``duration_ms`` (:func:`app.operations.logs.access_line`).

The middleware is pure ASGI (no ``BaseHTTPMiddleware``, which copies every message through
an extra task and costs a large share of the throughput of sub-millisecond endpoints): per
request it scans the request headers once, wraps ``send`` to read the status and append two
headers, and updates a few memory-mapped values under a lock (no system call).
"""

from __future__ import annotations

import logging
import os
import re
import time

from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.operations.logs import ACCESS_LOGGER, REQUEST_ID, access_line
from app.operations.metrics import METRICS, Metrics

_REQUEST_ID_OK = re.compile(rb"^[A-Za-z0-9._:/+=@-]{1,128}$")

#: Sent on every answer: browsers keep to the declared content type.
NOSNIFF = (b"x-content-type-options", b"nosniff")

_METHODS = frozenset({"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS"})


class ObservabilityMiddleware:
    """Pure ASGI middleware: request id, latency/status metrics, one access-log line."""

    def __init__(self, app: ASGIApp, *, access_log: bool = True, metrics: Metrics = METRICS):
        self.app = app
        self.access_log = access_log
        self.metrics = metrics

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            if scope["type"] == "lifespan":
                self._share_metrics()
            await self.app(scope, receive, send)
            return
        start = time.perf_counter()
        request_id = None
        for name, value in scope["headers"]:
            if name == b"x-request-id":
                if _REQUEST_ID_OK.match(value):
                    request_id = value.decode("latin-1")
                break
        if request_id is None:
            request_id = os.urandom(12).hex()
        token = REQUEST_ID.set(request_id)
        id_header = (b"x-request-id", request_id.encode("latin-1"))
        status = 0
        metrics = self.metrics
        # Set when the request is counted: just before the last body message is sent (a
        # scrape that follows the response sees it), else when the app returns or fails.
        elapsed: float | None = None
        method = scope["method"] if scope["method"] in _METHODS else "other"

        async def send_with_id(message: Message) -> None:
            nonlocal status, elapsed
            if message["type"] == "http.response.start":
                status = message["status"]
                message["headers"] = [*message.get("headers", ()), id_header, NOSNIFF]
            elif (
                elapsed is None
                and not message.get("more_body")
                and message["type"] == "http.response.body"
            ):
                elapsed = time.perf_counter() - start
                route = getattr(scope.get("route"), "path", None) or "unmatched"
                metrics.finish(method, route, status, elapsed)
            await send(message)

        metrics.enter()
        failed = True
        try:
            # Exceptions reach this far only once a response has started
            # (app.middleware.guard answers every other one): the server closes the
            # connection; REQUEST_ID stays set for its log line.
            await self.app(scope, receive, send_with_id)
            failed = False
        finally:
            route = getattr(scope.get("route"), "path", None) or "unmatched"
            if elapsed is None:  # no complete response was sent
                elapsed = time.perf_counter() - start
                metrics.finish(method, route, status, elapsed)
            if self.access_log and ACCESS_LOGGER.isEnabledFor(logging.INFO):
                access_line(
                    method,
                    scope["path"],
                    status,
                    {
                        "method": method,
                        "path": scope["path"],
                        "route": route,
                        "status": status,
                        "duration_ms": round(elapsed * 1000.0, 3),
                    },
                )
            if not failed:
                REQUEST_ID.reset(token)

    def _share_metrics(self) -> None:
        """At application start-up: share the counters with the other workers (once)."""
        if self.metrics.directory is not None:
            return
        try:
            self.metrics.share()
        except OSError as exc:  # e.g. no writable temporary directory
            logging.getLogger("denavit").warning(
                "metrics stay per worker process: cannot share them (%s)", exc
            )
