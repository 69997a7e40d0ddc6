"""A minimal blocking WebSocket client for the stream benchmarks (one thread, one socket).

The ``websockets`` sync client (docs/stream.md's example, the Python client's
:mod:`denavit_client.stream`) reads the socket in a background thread and hands each message
to the caller through a lock: measured in ``python -m bench stream``, that hand-off is
~0.07 ms of a one-at-a-time round trip on the 2-core machine. A servo loop that waits for
each answer can read the socket itself; this client does, so the benchmark can show the
server's share of a round trip without the client's thread hop.

RFC 6455 client framing only as far as the benchmarks need it: masked frames (a zero
masking key, which leaves the payload as it is: a valid key, only a predictable one; fine
on loopback, not for a client facing proxies), unfragmented messages, text and binary
opcodes; a close frame raises :class:`ConnectionError`.
"""

from __future__ import annotations

import base64
import os
import socket
import struct

ZERO_MASK = b"\x00\x00\x00\x00"


class BlockingWebSocket:
    """A WebSocket to ``ws://host:port/path``: :meth:`send` a message, :meth:`recv` one."""

    def __init__(self, host: str, port: int, path: str, timeout: float = 60.0) -> None:
        self.sock = socket.create_connection((host, port), timeout=timeout)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        key = base64.b64encode(os.urandom(16)).decode()
        request = (
            f"GET {path} HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\n"
            f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n"
            "Sec-WebSocket-Version: 13\r\n\r\n"
        )
        self.sock.sendall(request.encode())
        buf = b""
        while b"\r\n\r\n" not in buf:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise ConnectionError("closed during the handshake")
            buf += chunk
        head, _, self.buf = buf.partition(b"\r\n\r\n")
        status = head.split(b"\r\n", 1)[0]
        if b" 101 " not in status:
            raise ConnectionError(f"upgrade refused: {status!r}")

    def send(self, message: bytes | str) -> None:
        """One message: binary for bytes, text for str."""
        opcode = 0x82 if isinstance(message, bytes) else 0x81
        data = message if isinstance(message, bytes) else message.encode()
        n = len(data)
        if n < 126:
            head = struct.pack("!BB", opcode, 0x80 | n)
        elif n < 1 << 16:
            head = struct.pack("!BBH", opcode, 0x80 | 126, n)
        else:
            head = struct.pack("!BBQ", opcode, 0x80 | 127, n)
        self.sock.sendall(head + ZERO_MASK + data)

    def _fill(self, k: int) -> None:
        while len(self.buf) < k:
            chunk = self.sock.recv(1 << 16)
            if not chunk:
                raise ConnectionError("closed")
            self.buf += chunk

    def recv(self) -> bytes | str:
        """The next message (the server's frames are unmasked and unfragmented)."""
        self._fill(2)
        opcode, n, at = self.buf[0] & 0x0F, self.buf[1] & 0x7F, 2
        if n == 126:
            self._fill(4)
            n, at = struct.unpack_from("!H", self.buf, 2)[0], 4
        elif n == 127:
            self._fill(10)
            n, at = struct.unpack_from("!Q", self.buf, 2)[0], 10
        self._fill(at + n)
        data, self.buf = self.buf[at : at + n], self.buf[at + n :]
        if opcode == 0x8:
            raise ConnectionError(f"closed by the server: {data!r}")
        return data.decode() if opcode == 0x1 else data

    def close(self) -> None:
        self.sock.close()
