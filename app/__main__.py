"""``python -m app``: serve Denavit with uvicorn, configured from ``DENAVIT_*`` settings.

The one entry point of ``make run`` and of the Docker image::

    python -m app               # serve (host, port, workers... from DENAVIT_* variables)
    python -m app healthcheck   # exit 0 if GET /health on this host's port answers "ok"

Server options and why (measured in docs/benchmarks.md, "Forward kinematics over HTTP"):
uvloop event loop and httptools parser (the fastest uvicorn pair), uvicorn's access log off
(:mod:`app.observability` writes one JSON line per request instead, and every log line is
JSON), ``timeout_graceful_shutdown`` so SIGTERM lets in-flight requests finish, and a
listen backlog of 2048 for bursts.
"""

from __future__ import annotations

import sys
import urllib.error
import urllib.request
from typing import Any

import orjson

from app.observability import logging_config
from app.settings import Settings, get_settings

USAGE = "usage: python -m app [healthcheck]"


def server_options(settings: Settings) -> dict[str, Any]:
    """Keyword arguments of ``uvicorn.run`` for ``settings``."""
    return {
        "host": settings.host,
        "port": settings.port,
        "workers": settings.workers,
        "loop": "uvloop",
        "http": "httptools",
        "access_log": False,
        "log_level": settings.log_level,
        "log_config": logging_config(settings.log_level),
        "timeout_graceful_shutdown": settings.graceful_timeout_s,
        "backlog": 2048,
        "server_header": False,
    }


def serve(settings: Settings) -> None:
    """Run uvicorn until SIGINT/SIGTERM."""
    import uvicorn

    uvicorn.run("app.main:app", **server_options(settings))


def local_url(settings: Settings, path: str) -> str:
    """URL of ``path`` on this machine's instance (a wildcard bind is reached on loopback)."""
    host = settings.host
    if host in {"0.0.0.0", ""}:
        host = "127.0.0.1"
    elif host == "::":
        host = "::1"
    if ":" in host:
        host = f"[{host}]"
    return f"http://{host}:{settings.port}{path}"


def healthcheck(settings: Settings, timeout: float = 3.0) -> int:
    """0 if GET /health answers ``{"status": "ok"}``, else 1 (with one line on stderr)."""
    url = local_url(settings, "/health")
    try:
        with urllib.request.urlopen(url, timeout=timeout) as response:  # noqa: S310
            body = orjson.loads(response.read())
    except (urllib.error.URLError, OSError, orjson.JSONDecodeError) as exc:
        print(f"denavit: healthcheck {url} failed: {exc}", file=sys.stderr)
        return 1
    if body != {"status": "ok"}:
        print(f"denavit: healthcheck {url} answered {body!r}", file=sys.stderr)
        return 1
    return 0


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if args not in ([], ["healthcheck"]):
        print(USAGE, file=sys.stderr)
        return 2
    settings = get_settings()
    if args == ["healthcheck"]:
        return healthcheck(settings)
    serve(settings)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
