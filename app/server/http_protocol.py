"""uvicorn's httptools HTTP protocol with the request head bounded (``python -m app``).

httptools (llhttp) and uvicorn's protocol keep a request's URL and header fields in memory,
without any limit, until the head is complete; nothing reads the socket on a timer before
then. One client, before any authentication, could make a worker hold as much as it sent,
and more: 64 MiB of 8-byte header lines grew a worker by ~900 MB (a Python tuple of two
bytes objects each). :class:`HttpToolsProtocol` answers ``431`` (problem+json, field
``headers``) and closes the connection when

- the request line's URL and the header fields, counted as httptools hands them over,
  exceed :data:`MAX_HEAD_BYTES`, or there are more than :data:`MAX_HEADERS` fields;
- the bytes received while a head is incomplete exceed :data:`MAX_RAW_HEAD_BYTES`:
  httptools buffers a header line whole before handing it over, so one endless line is
  only seen this way. The count starts with the connection and again after each request,
  and a read of the socket that finishes one head may carry part of the body, so this bound
  is wider than :data:`MAX_HEAD_BYTES` by more than a read (256 KiB).

The WebSocket upgrade request is an HTTP request too: bounded the same way.
"""

from __future__ import annotations

from typing import Any

from uvicorn.protocols.http.httptools_impl import STATUS_LINE
from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol as _HttpToolsProtocol

from app.api.errors import json_bytes, problem_body

#: Largest URL plus header fields of one request (names, values and their separators).
MAX_HEAD_BYTES = 64 * 1024
#: Most header fields in one request.
MAX_HEADERS = 256
#: Most bytes received while a request head is incomplete.
MAX_RAW_HEAD_BYTES = 1024 * 1024


class _HeadTooLarge(Exception):
    """Raised in a parser callback: httptools stops and uvicorn answers (see
    :meth:`HttpToolsProtocol.send_400_response`)."""


class HttpToolsProtocol(_HttpToolsProtocol):
    """uvicorn's ``httptools`` protocol, refusing request heads over the bounds above."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.in_head = True  # the next bytes belong to a request head
        self.raw_head_bytes = 0
        self.head_bytes = 0
        self.refusal: str | None = None

    def data_received(self, data: bytes) -> None:
        if self.refusal is not None:
            return
        if self.in_head:
            self.raw_head_bytes += len(data)
            if self.raw_head_bytes > MAX_RAW_HEAD_BYTES:
                self.refusal = f"headers: a request head of more than {MAX_HEAD_BYTES} bytes"
                self._send_431()
                return
        super().data_received(data)

    def on_message_begin(self) -> None:
        super().on_message_begin()
        self.in_head, self.head_bytes = True, 0

    def on_url(self, url: bytes) -> None:
        super().on_url(url)
        self._count(len(url))

    def on_header(self, name: bytes, value: bytes) -> None:
        super().on_header(name, value)
        self._count(len(name) + len(value) + 4)
        if len(self.headers) > MAX_HEADERS:
            self.refusal = f"headers: more than {MAX_HEADERS} header fields"
            raise _HeadTooLarge(self.refusal)

    def on_headers_complete(self) -> None:
        self.in_head = False
        super().on_headers_complete()

    def on_message_complete(self) -> None:
        super().on_message_complete()
        self.in_head, self.raw_head_bytes = True, 0

    def send_400_response(self, msg: str) -> None:
        """uvicorn's answer to a parser error: 431 when a callback above refused the head."""
        if self.refusal is None:
            super().send_400_response(msg)
        else:
            self._send_431()

    def _count(self, n: int) -> None:
        self.head_bytes += n
        if self.head_bytes > MAX_HEAD_BYTES:
            self.refusal = f"headers: the URL and header fields exceed {MAX_HEAD_BYTES} bytes"
            raise _HeadTooLarge(self.refusal)

    def _send_431(self) -> None:
        assert self.refusal is not None
        body = json_bytes(problem_body(431, self.refusal, field="headers"))
        content = [STATUS_LINE[431]]
        for name, value in self.server_state.default_headers:
            content.extend([name, b": ", value, b"\r\n"])
        content.extend(
            [
                b"content-type: application/problem+json\r\n",
                b"content-length: " + str(len(body)).encode("ascii") + b"\r\n",
                b"connection: close\r\n",
                b"\r\n",
                body,
            ]
        )
        self.transport.write(b"".join(content))
        self.transport.close()
