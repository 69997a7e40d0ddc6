"""Timestamps at each stage of a stream message, in a benchmark's server (never the service's).

``python -m bench stream`` runs the service with this module imported first
(:data:`SERVER_CODE`): it wraps uvicorn's WebSocket protocol and the stream's functions so
that each stage of a binary IK frame records ``time.perf_counter_ns()`` (CLOCK_MONOTONIC on
Linux: the same clock as the client process's), and writes the stamps as JSON to
``$BENCH_STREAM_STAMPS`` when the server stops. The client matches them to its own send and
receive times (:mod:`bench._stream_profile`).
"""

from __future__ import annotations

import json
import os
import time
from typing import Any

#: The stages, in the order a binary IK frame passes them.
STAGES = (
    "socket read by uvicorn",  # WebSocketsSansIOProtocol.data_received entered
    "frame parsed, queued",  # data_received done (websockets parser, ASGI queue, pause)
    "ASGI receive returned",  # in the stream's reader task
    "answer started",  # the stream's answering task (reader → inbox → answerer)
    "frame decoded",  # parse_binary
    "target built",  # pose_se3
    "solve started",  # plan, chain check, call
    "solved",  # the solve (IK)
    "answer encoded",  # binary_ik_answer
    "answer returned",  # _answer's epilogue
    "ASGI send entered",  # Starlette's send wrappers
    "written",  # websockets framing + transport.write
)

_REC: list[tuple[int, int]] = []


def _stamp(stage: int) -> None:
    _REC.append((stage, time.perf_counter_ns()))


def _around(owner: Any, name: str, before: int | None, after: int) -> None:
    """Wrap ``owner.name`` (sync or async) to stamp ``before`` on entry and ``after`` on exit."""
    import inspect

    real = getattr(owner, name)
    if inspect.iscoroutinefunction(real):

        async def wrapped(*args: Any, **kwargs: Any) -> Any:
            if before is not None:
                _stamp(before)
            out = await real(*args, **kwargs)
            _stamp(after)
            return out
    else:

        def wrapped(*args: Any, **kwargs: Any) -> Any:  # type: ignore[misc]
            if before is not None:
                _stamp(before)
            out = real(*args, **kwargs)
            _stamp(after)
            return out

    setattr(owner, name, wrapped)


def install() -> None:
    """Wrap the stages' functions (before the app is imported by uvicorn)."""
    from uvicorn.protocols.websockets.websockets_sansio_impl import WebSocketsSansIOProtocol

    import app.api.ik_plan as plan
    import app.api.routes.stream as stream

    _around(WebSocketsSansIOProtocol, "data_received", 0, 1)
    _around(WebSocketsSansIOProtocol, "receive", None, 2)
    _around(WebSocketsSansIOProtocol, "send", 10, 11)
    _around(stream._Session, "_answer", 3, 9)
    _around(stream, "parse_binary", None, 4)
    _around(stream, "pose_se3", None, 5)
    _around(plan, "_solve_one", 6, 7)
    _around(stream, "binary_ik_answer", None, 8)


def dump(*_: Any) -> None:
    """Write the stamps (uvicorn re-raises the SIGTERM that stopped it once it has shut
    down, with the handler it found restored: this one, installed before it runs)."""
    with open(os.environ["BENCH_STREAM_STAMPS"], "w") as f:
        json.dump(_REC, f)
    os._exit(0)


#: ``python -c`` code of the stamped server (run by :func:`bench._http.serve`).
SERVER_CODE = """
import signal, uvicorn
from bench import _stream_stamps
_stream_stamps.install()
signal.signal(signal.SIGTERM, _stream_stamps.dump)
from app.__main__ import server_options
from app.operations.settings import get_settings
uvicorn.run("app.main:app", **server_options(get_settings()))
"""
