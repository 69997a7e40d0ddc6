"""``python -m app``: serve Denavit with uvicorn, configured from ``DENAVIT_*`` settings.

The one entry point of ``make run`` and of the Docker image::

    python -m app               # serve (host, port, workers... from DENAVIT_* variables)
    python -m app healthcheck   # exit 0 if GET /health on this host's port answers "ok"
    python -m app openapi PATH  # write the OpenAPI schema the app serves (make openapi)
    python -m app warm-up [--require-cache]
                                # compile the IK kernels into Numba's cache (the image's
                                # build); with the flag, exit 1 unless all came from it

Server options and why (measured in docs/benchmarks.md, "Forward kinematics over HTTP"):
uvloop event loop and httptools parser (the fastest uvicorn pair; its protocol subclassed in
:mod:`app.server.http_protocol` to bound request heads, which httptools buffers without limit: 431
beyond 64 KiB or 256 fields), uvicorn's access log off
(:mod:`app.middleware.observability` writes one JSON line per request instead, and every log line is
JSON), ``timeout_graceful_shutdown`` so SIGTERM lets in-flight requests finish, and a
listen backlog of 2048 for bursts.

WebSockets (``WS /robots/{id}/stream``, docs/stream.md): uvicorn's ``websockets-sansio``
implementation, named rather than left to ``ws="auto"`` (which picks it while the
``websockets`` package is installed, else wsproto), without permessage-deflate and with
``ws_max_size`` = ``DENAVIT_STREAM_MAX_MESSAGE_BYTES``. That implementation checks each
frame's declared length against what is left of the limit for its message (fragments
summed) before it reads the payload, and closes the socket with 1009 beyond it; with
compression on, every message a socket read was inflated (up to the limit, 16 MiB by
default) before the application could refuse it, authenticated or not.
"""

from __future__ import annotations

import json
import sys
import urllib.error
import urllib.request
from pathlib import Path
from typing import Any

import orjson

from app.operations.logs import logging_config
from app.operations.settings import Settings, get_settings

USAGE = "usage: python -m app [healthcheck | openapi PATH | warm-up [--require-cache]]"


def server_options(settings: Settings) -> dict[str, Any]:
    """Keyword arguments of ``uvicorn.run`` for ``settings``."""
    return {
        "host": settings.host,
        "port": settings.port,
        "workers": settings.workers,
        "loop": "uvloop",
        "http": "app.server.http_protocol:HttpToolsProtocol",  # httptools, request heads bounded
        "access_log": False,
        "log_level": settings.log_level,
        "log_config": logging_config(settings.log_level),
        "timeout_graceful_shutdown": settings.graceful_timeout_s,
        "backlog": 2048,
        "server_header": False,
        "ws": "websockets-sansio",
        "ws_per_message_deflate": False,
        "ws_max_size": settings.stream_max_message_bytes,
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


def openapi_text() -> str:
    """The OpenAPI schema the app serves, as indented JSON (the form of docs/openapi.json)."""
    from app.main import app

    return json.dumps(app.openapi(), indent=2, ensure_ascii=False) + "\n"


def write_openapi(path: Path) -> None:
    """Write :func:`openapi_text` to ``path`` (atomically)."""
    from app.storage.store import atomic_write_bytes

    atomic_write_bytes(path, openapi_text().encode())


def warm_up(require_cache: bool) -> int:
    """Compile (or load) the core's kernels; one JSON line on stdout saying which and where.
    1 if ``require_cache`` and any kernel had to be compiled (the cache missed)."""
    import os
    import time

    from app.kinematics import kernels

    start = time.perf_counter()
    kernels.warm_up()
    stats = kernels.kernel_cache_stats()
    report = {
        **stats,
        "seconds": round(time.perf_counter() - start, 3),
        "module": kernels.__file__,
        "numba_cache_dir": os.environ.get("NUMBA_CACHE_DIR"),
    }
    print(json.dumps(report))
    if require_cache and (stats["compiled"] or not stats["loaded"]):
        print("denavit: the kernels were not all loaded from Numba's cache", file=sys.stderr)
        return 1
    return 0


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if args and args[0] == "warm-up" and args[1:] in ([], ["--require-cache"]):
        return warm_up(require_cache=args[1:] == ["--require-cache"])
    if not (args in ([], ["healthcheck"]) or (len(args) == 2 and args[0] == "openapi")):
        print(USAGE, file=sys.stderr)
        return 2
    settings = get_settings()
    if args == ["healthcheck"]:
        return healthcheck(settings)
    if args and args[0] == "openapi":
        write_openapi(Path(args[1]))
        return 0
    serve(settings)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
