"""Last-resort answers that leave the connection usable: 500 on a bug, 503 at shutdown.

A pure ASGI middleware just inside :class:`~app.middleware.observability.ObservabilityMiddleware`
(so
its answers carry the request id and are counted and access-logged like any other):

- **An unexpected exception** (a bug: every expected failure is mapped to a 4xx in
  :mod:`app.api.errors`) is logged with its traceback and answered ``500`` problem+json.
  It is *not* re-raised: Starlette's ``ServerErrorMiddleware`` re-raises after answering,
  and uvicorn then closes the keep-alive connection without ``Connection: close``, so the
  client's next request on it failed with a reset. Handled here, the connection stays open
  for the next request.
- **A request cancelled by the server** (uvicorn cancels the requests still running when
  ``DENAVIT_GRACEFUL_TIMEOUT_S`` runs out after SIGTERM; a client that disconnects does not
  cancel the task, :func:`app.api.offload.offload_cancellable` answers it 499) is answered
  ``503`` problem+json with ``Connection: close`` and ``Retry-After`` instead of uvicorn's
  plain-text 500, and the ``CancelledError`` is raised again: the task stays cancelled
  (whoever cancelled it, e.g. a timeout or task group around the app, sees it end
  cancelled). uvicorn then logs the cancellation ("Exception in ASGI application") and
  closes the connection after the 503, which said ``Connection: close``.

If the response had already started, neither can be answered any more: the exception goes
on to uvicorn, which closes the connection (the only way left to tell the client that the
body is cut short).
"""

from __future__ import annotations

import asyncio
import logging

from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.api.errors import problem

log = logging.getLogger("denavit")

#: ``Retry-After`` (s) of the 503 sent to a request cut off by the shutdown.
RETRY_AFTER_S = 1


class ErrorGuardMiddleware:
    """Answer unexpected exceptions (500) and shutdown cancellations (503) as problems."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        started = False

        async def send_tracked(message: Message) -> None:
            nonlocal started
            if message["type"] == "http.response.start":
                started = True
            await send(message)

        try:
            await self.app(scope, receive, send_tracked)
        except Exception:
            if started:
                raise
            log.exception("unhandled error on %s %s", scope["method"], scope["path"])
            await _answer(scope, receive, send, 500, "internal error")
        except asyncio.CancelledError:
            if started:
                raise
            log.warning(
                "request on %s %s cancelled by the server (graceful shutdown timeout)",
                scope["method"],
                scope["path"],
            )
            await _answer(
                scope,
                receive,
                send,
                503,
                "the service is shutting down and stopped this request before it finished "
                "(DENAVIT_GRACEFUL_TIMEOUT_S); send it again",
                kind="shutting-down",
                headers={"connection": "close", "retry-after": str(RETRY_AFTER_S)},
            )
            raise  # answered, and still cancelled: never swallow a cancellation


async def _answer(
    scope: Scope,
    receive: Receive,
    send: Send,
    status: int,
    detail: str,
    *,
    kind: str | None = None,
    headers: dict[str, str] | None = None,
) -> None:
    response = problem(status, detail, kind=kind, instance=scope.get("path"), headers=headers)
    await response(scope, receive, send)
