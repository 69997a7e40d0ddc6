"""Observability: JSON logs with request ids, Prometheus metrics, one cheap ASGI middleware.

- **Request ids.** Every HTTP request gets an id: the client's ``X-Request-ID`` header when it
  is a sane token (1–128 characters of ``[A-Za-z0-9._:/+=@-]``), else 24 random hex digits.
  The id is echoed in the ``X-Request-ID`` response header and attached to every log line
  written while the request is handled (a :data:`REQUEST_ID` context variable).
- **Logs.** One JSON object per line on stderr: ``ts`` (UTC, ISO 8601, ms), ``level``,
  ``logger``, ``message``, ``request_id`` when inside a request, any ``extra`` fields, and
  ``exc_info`` (the formatted traceback) for exceptions. With ``DENAVIT_ACCESS_LOG`` on (the
  default) each request writes one ``denavit.access`` line with ``method``, ``path``,
  ``route`` (the path template), ``status`` and ``duration_ms``.
- **Metrics.** ``GET /metrics`` (Prometheus text format 0.0.4): request counts by method,
  route template and status, latency histograms by method and route template, requests in
  flight, IK outcomes (:func:`record_ik`), resident memory and CPU time. Counters live in the
  worker process that served the request: with ``DENAVIT_WORKERS`` > 1 a scrape answers for
  one worker (the ``pid`` of ``denavit_process_info`` tells which).

The middleware is pure ASGI (no ``BaseHTTPMiddleware``, which copies every message through
an extra task and costs a large share of the throughput of sub-millisecond endpoints): per
request it scans the request headers once, wraps ``send`` to read the status and append one
header, and updates a histogram under a lock.
"""

from __future__ import annotations

import logging
import os
import re
import resource
import sys
import threading
import time
from bisect import bisect_left
from contextvars import ContextVar
from datetime import UTC, datetime
from typing import Any

import orjson
from starlette.types import ASGIApp, Message, Receive, Scope, Send

#: The id of the request being handled (``None`` outside requests).
REQUEST_ID: ContextVar[str | None] = ContextVar("denavit_request_id", default=None)

_REQUEST_ID_OK = re.compile(rb"^[A-Za-z0-9._:/+=@-]{1,128}$")

#: Upper bounds (s) of the latency histogram buckets (``+Inf`` is implicit).
LATENCY_BUCKETS: tuple[float, ...] = (
    0.0005,
    0.001,
    0.0025,
    0.005,
    0.01,
    0.025,
    0.05,
    0.1,
    0.25,
    0.5,
    1.0,
    2.5,
    5.0,
    10.0,
    30.0,
)

_METHODS = frozenset({"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS"})


def current_request_id() -> str | None:
    """The id of the request being handled, or ``None``."""
    return REQUEST_ID.get()


# --------------------------------------------------------------------------------------------
# Logging


_RECORD_FIELDS = frozenset(vars(logging.makeLogRecord({}))) | {
    "message",
    "asctime",
    "taskName",
    "color_message",  # uvicorn's ANSI-coloured copy of the message
}


class JsonFormatter(logging.Formatter):
    """One JSON object per record (``ts``, ``level``, ``logger``, ``message``, extras)."""

    def format(self, record: logging.LogRecord) -> str:
        doc: dict[str, Any] = {
            "ts": datetime.fromtimestamp(record.created, UTC).isoformat(timespec="milliseconds"),
            "level": record.levelname.lower(),
            "logger": record.name,
            "message": record.getMessage(),
        }
        request_id = REQUEST_ID.get()
        if request_id is not None:
            doc["request_id"] = request_id
        for key, value in record.__dict__.items():
            if key not in _RECORD_FIELDS and not key.startswith("_"):
                doc[key] = value
        if record.exc_info:
            doc["exc_info"] = self.formatException(record.exc_info)
        elif record.exc_text:
            doc["exc_info"] = record.exc_text
        return orjson.dumps(doc, default=str).decode()


class JsonStderrHandler(logging.StreamHandler):
    """A stream handler that always writes to the *current* ``sys.stderr``."""

    def __init__(self) -> None:
        super().__init__(sys.stderr)
        self.setFormatter(JsonFormatter())

    @property  # type: ignore[override]
    def stream(self) -> Any:
        return sys.stderr

    @stream.setter
    def stream(self, value: Any) -> None:  # StreamHandler.__init__ assigns it
        pass


_UVICORN_LOGGERS = ("uvicorn", "uvicorn.error")
#: uvicorn's access log is replaced by ``denavit.access`` (JSON, with the request id).
_UVICORN_ACCESS = "uvicorn.access"


def logging_config(level: str = "info") -> dict[str, Any]:
    """A :func:`logging.config.dictConfig` dict: JSON on stderr for every logger.

    Given to ``uvicorn.run(log_config=...)`` so that uvicorn's own messages (start-up,
    shutdown, errors) are JSON too, in every worker process.
    """
    lvl = level.upper()
    return {
        "version": 1,
        "disable_existing_loggers": False,
        "handlers": {"stderr": {"()": "app.observability.JsonStderrHandler"}},
        "root": {"handlers": ["stderr"], "level": lvl},
        "loggers": {
            **{
                name: {"handlers": [], "propagate": True, "level": lvl} for name in _UVICORN_LOGGERS
            },
            _UVICORN_ACCESS: {"handlers": [], "propagate": False},
        },
    }


def configure_logging(level: str = "info") -> None:
    """JSON logs on stderr (idempotent; keeps handlers others installed on the root logger).

    Called at application start-up, so ``uvicorn app.main:app`` run without our log config
    also logs JSON.
    """
    lvl = level.upper()
    root = logging.getLogger()
    if not any(isinstance(h, JsonStderrHandler) for h in root.handlers):
        root.addHandler(JsonStderrHandler())
    root.setLevel(lvl)
    for name in _UVICORN_LOGGERS:
        logger = logging.getLogger(name)
        logger.handlers = [h for h in logger.handlers if isinstance(h, JsonStderrHandler)]
        logger.propagate = True
        logger.setLevel(lvl)
    access = logging.getLogger(_UVICORN_ACCESS)
    access.handlers = []
    access.propagate = False


# --------------------------------------------------------------------------------------------
# Metrics


class _RouteStats:
    __slots__ = ("statuses", "buckets", "total", "count")

    def __init__(self) -> None:
        self.statuses: dict[int, int] = {}
        self.buckets = [0] * (len(LATENCY_BUCKETS) + 1)
        self.total = 0.0
        self.count = 0


class Metrics:
    """Process-local request counters and latency histograms, rendered as Prometheus text."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._routes: dict[tuple[str, str], _RouteStats] = {}
        self._ik = {True: 0, False: 0}
        self.in_flight = 0
        self.started = time.time()

    def observe(self, method: str, route: str, status: int, seconds: float) -> None:
        """Count one request of ``route`` (a path template) that took ``seconds``."""
        key = (method, route)
        with self._lock:
            stats = self._routes.get(key)
            if stats is None:
                stats = self._routes[key] = _RouteStats()
            stats.statuses[status] = stats.statuses.get(status, 0) + 1
            stats.buckets[bisect_left(LATENCY_BUCKETS, seconds)] += 1
            stats.total += seconds
            stats.count += 1

    def record_ik(self, success: bool) -> None:
        """Count one IK solve by outcome."""
        with self._lock:
            self._ik[bool(success)] += 1

    def render(self) -> bytes:
        """The Prometheus text exposition (format 0.0.4)."""
        with self._lock:
            routes = [
                (m, r, dict(s.statuses), list(s.buckets), s.total, s.count)
                for (m, r), s in sorted(self._routes.items())
            ]
            ik = dict(self._ik)
            in_flight = self.in_flight
        out: list[str] = [
            "# HELP denavit_http_requests_total HTTP requests by method, route template, status.",
            "# TYPE denavit_http_requests_total counter",
        ]
        for method, route, statuses, _, _, _ in routes:
            for status, n in sorted(statuses.items()):
                labels = _labels(method=method, route=route, status=str(status))
                out.append(f"denavit_http_requests_total{labels} {n}")
        out += [
            "# HELP denavit_http_request_duration_seconds HTTP request latency (s).",
            "# TYPE denavit_http_request_duration_seconds histogram",
        ]
        for method, route, _, buckets, total, count in routes:
            cumulative = 0
            for bound, n in zip((*LATENCY_BUCKETS, float("inf")), buckets, strict=True):
                cumulative += n
                le = "+Inf" if bound == float("inf") else repr(bound)
                labels = _labels(method=method, route=route, le=le)
                out.append(f"denavit_http_request_duration_seconds_bucket{labels} {cumulative}")
            labels = _labels(method=method, route=route)
            out.append(f"denavit_http_request_duration_seconds_sum{labels} {total!r}")
            out.append(f"denavit_http_request_duration_seconds_count{labels} {count}")
        out += [
            "# HELP denavit_http_requests_in_flight HTTP requests being handled.",
            "# TYPE denavit_http_requests_in_flight gauge",
            f"denavit_http_requests_in_flight {in_flight}",
            "# HELP denavit_ik_requests_total IK solves by outcome.",
            "# TYPE denavit_ik_requests_total counter",
            f'denavit_ik_requests_total{{result="success"}} {ik[True]}',
            f'denavit_ik_requests_total{{result="failure"}} {ik[False]}',
            "# HELP denavit_process_info The worker process answering this scrape.",
            "# TYPE denavit_process_info gauge",
            f'denavit_process_info{{pid="{os.getpid()}"}} 1',
            "# HELP process_resident_memory_bytes Resident memory size in bytes.",
            "# TYPE process_resident_memory_bytes gauge",
            f"process_resident_memory_bytes {resident_memory_bytes()}",
            "# HELP process_cpu_seconds_total User and system CPU time spent in seconds.",
            "# TYPE process_cpu_seconds_total counter",
            f"process_cpu_seconds_total {_cpu_seconds()!r}",
            "# HELP process_start_time_seconds Start time of the process (Unix time, s).",
            "# TYPE process_start_time_seconds gauge",
            f"process_start_time_seconds {self.started!r}",
        ]
        return ("\n".join(out) + "\n").encode()


def _escape(value: str) -> str:
    return value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")


def _labels(**labels: str) -> str:
    return "{" + ",".join(f'{k}="{_escape(v)}"' for k, v in labels.items()) + "}"


def resident_memory_bytes() -> int:
    """Current resident set size of this process (bytes; peak RSS where /proc is missing)."""
    try:
        with open("/proc/self/statm", "rb") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def _cpu_seconds() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


#: The process's metrics (every app in the process shares them).
METRICS = Metrics()


def record_ik(success: bool) -> None:
    """Count one IK solve (``success``: a solution within tolerance was found).

    Thread-safe: call it from the route or from the work pool.
    """
    METRICS.record_ik(success)


# --------------------------------------------------------------------------------------------
# Middleware

_access = logging.getLogger("denavit.access")


def access_line(method: str, path: str, status: int, fields: dict[str, Any]) -> None:
    """Write the access-log line of a request.

    When our JSON handler is the root's (the service's logging set-up) and nothing else
    listens to ``denavit.access``, the line is built and written directly, under the
    handler's lock: the same JSON as :class:`JsonFormatter` would write, at a fifth of the
    cost of a ``logging`` call (no LogRecord, no caller lookup). Otherwise it goes through
    ``logging`` like any other record.
    """
    message = f"{method} {path} {status}"
    root = logging.getLogger()
    handler = root.handlers[0] if len(root.handlers) == 1 else None
    if not isinstance(handler, JsonStderrHandler) or _access.handlers:
        _access.info(message, extra=fields)
        return
    doc: dict[str, Any] = {
        "ts": datetime.now(UTC).isoformat(timespec="milliseconds"),
        "level": "info",
        "logger": _access.name,
        "message": message,
    }
    request_id = REQUEST_ID.get()
    if request_id is not None:
        doc["request_id"] = request_id
    doc.update(fields)
    line = orjson.dumps(doc, default=str).decode() + "\n"
    handler.acquire()
    try:
        sys.stderr.write(line)
        sys.stderr.flush()
    finally:
        handler.release()


class ObservabilityMiddleware:
    """Pure ASGI middleware: request id, latency/status metrics, one access-log line."""

    def __init__(self, app: ASGIApp, *, access_log: bool = True, metrics: Metrics = METRICS):
        self.app = app
        self.access_log = access_log
        self.metrics = metrics

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
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

        async def send_with_id(message: Message) -> None:
            nonlocal status
            if message["type"] == "http.response.start":
                status = message["status"]
                message["headers"] = [*message.get("headers", ()), id_header]
            await send(message)

        metrics = self.metrics
        metrics.in_flight += 1
        failed = True
        try:
            await self.app(scope, receive, send_with_id)
        except Exception:
            # Answer the 500 here, so it carries the request id; the exception goes on to
            # the server-error handler (which logs it, with the id: REQUEST_ID stays set).
            if not status:
                from app.api.errors import problem  # here: `python -m app healthcheck` stays light

                await problem(500, "internal error", instance=scope["path"])(
                    scope, receive, send_with_id
                )
            raise
        else:
            failed = False
        finally:
            metrics.in_flight -= 1
            elapsed = time.perf_counter() - start
            route = scope.get("route")
            template = getattr(route, "path", None) or "unmatched"
            method = scope["method"] if scope["method"] in _METHODS else "other"
            metrics.observe(method, template, status, elapsed)
            if self.access_log and _access.isEnabledFor(logging.INFO):
                access_line(
                    method,
                    scope["path"],
                    status,
                    {
                        "method": method,
                        "path": scope["path"],
                        "route": template,
                        "status": status,
                        "duration_ms": round(elapsed * 1000.0, 3),
                    },
                )
            if not failed:
                REQUEST_ID.reset(token)
