"""Request-body size limit (``DENAVIT_MAX_BODY_BYTES``), enforced before any parsing.

A pure ASGI middleware:

- a request whose ``Content-Length`` exceeds the limit is answered 413 at once; its body is
  never read and the connection is closed (``Connection: close``) so the client stops sending;
- a chunked request (``Transfer-Encoding: chunked``, no length) is read chunk by chunk while
  the bytes are counted; past the limit it is answered 413, otherwise the counted body is
  handed to the application as one message;
- requests with a length within the limit, and requests without a body, pass through
  untouched (no per-message wrapper).

The 413 body is RFC 9457 problem details like every other error, with ``field: "body"``.
"""

from __future__ import annotations

from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.api.errors import problem


class BodyLimitMiddleware:
    """Answer 413 to request bodies larger than ``max_body_bytes``."""

    def __init__(self, app: ASGIApp, *, max_body_bytes: int) -> None:
        self.app = app
        self.max_body_bytes = max_body_bytes

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        length: bytes | None = None
        chunked = False
        for name, value in scope["headers"]:
            if name == b"content-length":
                length = value
            elif name == b"transfer-encoding":
                chunked = b"chunked" in value.lower()
        if length is not None:
            try:
                size = int(length)
            except ValueError:
                await _reject(
                    scope,
                    receive,
                    send,
                    400,
                    "content-length: not a number",
                    field="content-length",
                )
                return
            if size > self.max_body_bytes:
                await self._too_large(scope, receive, send, f"{size} bytes")
                return
            await self.app(scope, receive, send)
            return
        if not chunked:
            await self.app(scope, receive, send)
            return

        chunks: list[bytes] = []
        total = 0
        while True:
            message = await receive()
            if message["type"] != "http.request":  # the client went away
                return
            chunk = message.get("body", b"")
            total += len(chunk)
            if total > self.max_body_bytes:
                await self._too_large(
                    scope, receive, send, f"more than {self.max_body_bytes} bytes"
                )
                return
            chunks.append(chunk)
            if not message.get("more_body", False):
                break
        body = b"".join(chunks)
        delivered = False

        async def replay() -> Message:
            nonlocal delivered
            if not delivered:
                delivered = True
                return {"type": "http.request", "body": body, "more_body": False}
            return await receive()

        await self.app(scope, replay, send)

    async def _too_large(self, scope: Scope, receive: Receive, send: Send, size: str) -> None:
        detail = (
            f"body: {size} exceed the limit of {self.max_body_bytes} bytes (DENAVIT_MAX_BODY_BYTES)"
        )
        await _reject(scope, receive, send, 413, detail, kind="content-too-large", field="body")


async def _reject(
    scope: Scope,
    receive: Receive,
    send: Send,
    status: int,
    detail: str,
    *,
    field: str,
    kind: str | None = None,
) -> None:
    response = problem(
        status,
        detail,
        kind=kind,
        field=field,
        instance=scope.get("path"),
        headers={"connection": "close"},
    )
    await response(scope, receive, send)
