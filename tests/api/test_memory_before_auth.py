"""What an unauthenticated client can make a worker of a live ``python -m app`` (2 workers,
a token set) buffer: WebSocket frames on ``WS /robots/{id}/stream``, HTTP request heads.

The clients are raw TCP connections that write frames and requests by hand, so a frame can
claim compression (RSV1) or a length it never sends, and a request head can go on without
end. The workers' memory is read from ``/proc/<pid>/status``: ``VmRSS`` before and after,
and ``VmHWM``, the peak, reset to the current size just before the clients connect
(``/proc/<pid>/clear_refs``), so a buffer that was freed again still counts. No timing:
every client reads until the server's close (or its answer).
"""

from __future__ import annotations

import base64
import contextlib
import os
import socket
import struct
import sys
import time
import zlib
from collections.abc import Iterator
from pathlib import Path

import orjson
import pytest
from websockets.sync.client import connect

from tests.helpers import Server, serve, worker_pids

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="reads worker memory from /proc"
)

TOKEN = "s3cret"
PATH = "/robots/ur5/stream"
Q_UR5 = [0.3, -1.1, 1.4, -0.6, 1.2, 0.4]
LIMIT = 1 << 20  # DENAVIT_STREAM_MAX_MESSAGE_BYTES, the default
#: What the hostile clients of one test may add to the two workers together, lasting or
#: at the peak (generous: a socket may buffer one message of at most the limit, a request
#: head at most 1 MiB, plus the reads).
BOUND = 64 << 20
TEXT, CONT, CLOSE = 0x1, 0x0, 0x8


def _status(pid: int, key: str) -> int:
    """A ``/proc/<pid>/status`` memory line (``VmRSS``, ``VmHWM``) in bytes."""
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
    raise AssertionError(f"no {key} for {pid}")


def _baseline(pids: list[int]) -> dict[int, int]:
    """Each worker's ``VmRSS`` now; its peak (``VmHWM``) restarts from it."""
    rss = {pid: _status(pid, "VmRSS") for pid in pids}
    for pid in pids:
        Path(f"/proc/{pid}/clear_refs").write_text("5")
    return rss


def _growth(rss: dict[int, int]) -> tuple[int, int]:
    """What the workers added since :func:`_baseline`, together: (lasting, at the peak)."""
    grown = sum(_status(pid, "VmRSS") - before for pid, before in rss.items())
    peak = sum(_status(pid, "VmHWM") - before for pid, before in rss.items())
    return grown, peak


@pytest.fixture(scope="module")
def server(tmp_path_factory) -> Iterator[Server]:
    """``python -m app`` with 2 workers and a token. Numba's JIT is off: the IK kernels'
    warm-up (compiling for seconds when Numba's cache is cold, growing each worker by
    ~150 MB) would run in the background while memory is measured; the stream's
    authorization and FK never use them."""
    data = tmp_path_factory.mktemp("stream-memory") / "data"
    settings = {"workers": "2", "api_token": TOKEN}
    with serve(data, settings=settings, env={"NUMBA_DISABLE_JIT": "1"}) as server:
        end = time.monotonic() + 90  # backstop: both workers log their start-up
        while sum(line.get("message") == "Application startup complete."
                  for line in server.log_lines()) < 2:  # fmt: skip
            assert time.monotonic() < end, server.log.read_text()[-3000:]
            time.sleep(0.05)
        assert len(worker_pids(server)) == 2
        yield server


# ------------------------------------------------------------------------- raw frames
def _frame(opcode: int, payload: bytes, *, fin: bool = True, rsv1: bool = False) -> bytes:
    """A client frame (masked with the zero key, so the payload is sent as it is)."""
    head = bytes([(0x80 if fin else 0) | (0x40 if rsv1 else 0) | opcode])
    return head + _length(len(payload)) + b"\0\0\0\0" + payload


def _length(n: int) -> bytes:
    """The second header byte (mask bit set) and the extended length of ``n`` bytes."""
    if n < 126:
        return bytes([0x80 | n])
    if n < 1 << 16:
        return bytes([0x80 | 126]) + struct.pack("!H", n)
    return bytes([0x80 | 127]) + struct.pack("!Q", n)


def _deflated(data: bytes) -> bytes:
    """``data`` as a permessage-deflate payload (RFC 7692: raw deflate, 4 KiB window, the
    sync flush's trailing 00 00 ff ff removed)."""
    z = zlib.compressobj(9, zlib.DEFLATED, -12)
    out = z.compress(data) + z.flush(zlib.Z_SYNC_FLUSH)
    assert out.endswith(b"\x00\x00\xff\xff")
    return out[:-4]


class RawSocket:
    """An unauthenticated WebSocket that offers permessage-deflate; the server's answer
    headers in :attr:`headers`."""

    def __init__(self, url: str) -> None:
        host, port = url.removeprefix("http://").split(":")
        self.sock = socket.create_connection((host, int(port)), timeout=60)  # backstop
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall(
            f"GET {PATH} HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\n"
            f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
            "Sec-WebSocket-Extensions: permessage-deflate; client_max_window_bits\r\n\r\n".encode()
        )
        self.buf = b""
        while b"\r\n\r\n" not in self.buf:
            chunk = self.sock.recv(65536)
            assert chunk, f"closed during the handshake: {self.buf!r}"
            self.buf += chunk
        head, self.buf = self.buf.split(b"\r\n\r\n", 1)
        status, *lines = head.decode("latin-1").split("\r\n")
        assert status.startswith("HTTP/1.1 101"), head
        self.headers = {k.strip().lower(): v.strip() for k, v in (x.split(":", 1) for x in lines)}

    def send(self, data: bytes) -> None:
        self.sock.sendall(data)

    def _read(self, n: int) -> bytes | None:
        while len(self.buf) < n:
            chunk = self.sock.recv(65536)
            if not chunk:
                return None
            self.buf += chunk
        out, self.buf = self.buf[:n], self.buf[n:]
        return out

    def close_code(self) -> int | None:
        """Read frames until the server's close frame: its code (``None``: no close frame,
        the connection just ended)."""
        while (head := self._read(2)) is not None:
            opcode, n = head[0] & 0x0F, head[1] & 0x7F
            if n >= 126:
                raw = self._read(2 if n == 126 else 8)
                assert raw is not None
                n = struct.unpack("!H" if len(raw) == 2 else "!Q", raw)[0]
            payload = self._read(n)
            assert payload is not None
            if opcode == CLOSE:
                return struct.unpack("!H", payload[:2])[0] if payload else 1005
        return None

    def close(self) -> None:
        self.sock.close()


# ---------------------------------------------------------------------------- tests
def test_compression_is_not_negotiated(server: Server) -> None:
    """A client offering permessage-deflate gets no extension, and the socket works."""
    url = server.url.replace("http://", "ws://") + PATH
    headers = {"Authorization": f"Bearer {TOKEN}"}
    with connect(url, compression="deflate", additional_headers=headers, proxy=None) as ws:
        assert "Sec-WebSocket-Extensions" not in ws.response.headers
        assert ws.protocol.extensions == []
        ws.send(orjson.dumps({"id": 1, "op": "fk", "q": Q_UR5}).decode())
        assert orjson.loads(ws.recv(timeout=60))["poses"]


def test_unauthenticated_sockets_cannot_make_workers_buffer(server: Server) -> None:
    """12 sockets without a token, each offering permessage-deflate (none is agreed):
    6 send one compressed frame (RSV1) of under 64 KiB that inflates to 15 MiB of JSON
    (``[{}, {}, ...]``, ~5 million Python objects once parsed); 2 send a 600 KiB fragment,
    then the header of a second one (together over the 1 MiB limit); 2 the header of an
    8 MiB frame; 2 a 1 MiB ``[{}, {}, ...]`` message, within the limit but no token message.
    Each is closed (1002: compression not agreed; 1009: over the limit, told by a header;
    1008: no token), the workers' memory grows by less than :data:`BOUND` (peak and
    lasting), and the same workers serve on.

    Before compression was turned off and ``ws_max_size`` set: every socket closed 1008,
    peak +610 to +980 MiB, lasting +139 to +155 MiB."""
    bomb = _deflated(b"[" + b"{}," * (5 << 20) + b"{}]")
    assert len(bomb) < 64 << 10
    # Headers without their payload (nor mask key): a server that refuses the frame by
    # its header has read everything sent, so its close frame is never lost to a reset.
    fragment = _frame(TEXT, b" " * (600 << 10), fin=False)
    hostile = {
        "compressed": _frame(TEXT, bomb, rsv1=True),
        "fragments": fragment + bytes([0x80 | CONT]) + _length(600 << 10),
        "header": bytes([0x80 | TEXT]) + _length(8 << 20),
        "json": _frame(TEXT, b"[" + b"{}," * ((LIMIT - 8) // 3) + b"{}]"),  # within the limit
    }
    kinds = ["compressed"] * 6 + ["fragments"] * 2 + ["header"] * 2 + ["json"] * 2

    for _ in range(4):  # first use of the socket code in the workers: not the attack's cost
        warm = RawSocket(server.url)
        warm.send(_frame(TEXT, b'{"token": "wrong"}'))
        assert warm.close_code() == 1008
        warm.close()
    pids = worker_pids(server)
    rss = _baseline(pids)

    sockets = [RawSocket(server.url) for _ in kinds]
    for ws, kind in zip(sockets, kinds, strict=True):
        ws.send(hostile[kind])
    codes = []
    for ws in sockets:
        codes.append(ws.close_code())
        ws.close()

    grown, peak = _growth(rss)
    report = f"codes {codes}; RSS +{grown / 2**20:.1f} MiB, peak +{peak / 2**20:.1f} MiB"
    assert peak < BOUND and grown < BOUND, report
    assert not any("sec-websocket-extensions" in ws.headers for ws in sockets)
    expected = {"compressed": 1002, "fragments": 1009, "header": 1009, "json": 1008}
    assert codes == [expected[kind] for kind in kinds], report
    assert worker_pids(server) == pids, report
    with connect(
        server.url.replace("http://", "ws://") + PATH,
        additional_headers={"Authorization": f"Bearer {TOKEN}"},
        proxy=None,
    ) as ws:
        ws.send(orjson.dumps({"id": 1, "op": "fk", "q": Q_UR5}).decode())
        assert orjson.loads(ws.recv(timeout=60))["poses"]


# ----------------------------------------------------------------------- HTTP heads
def _answer(url: str, head: bytes) -> tuple[int, dict]:
    """Send ``head`` (a whole request head) on a new connection: the answer's status and
    JSON body."""
    host, port = url.removeprefix("http://").split(":")
    with socket.create_connection((host, int(port)), timeout=60) as sock:  # backstop
        sock.sendall(head)
        buf = b""
        while b"\r\n\r\n" not in buf:
            chunk = sock.recv(65536)
            assert chunk, f"closed without an answer: {buf!r}"
            buf += chunk
        top, body = buf.split(b"\r\n\r\n", 1)
        lines = top.decode("latin-1").split("\r\n")
        fields = {k.strip().lower(): v.strip() for k, v in (x.split(":", 1) for x in lines[1:])}
        while len(body) < int(fields["content-length"]):
            chunk = sock.recv(65536)
            assert chunk, "closed before the end of the body"
            body += chunk
    return int(lines[0].split()[1]), orjson.loads(body)


def _get(path: str, fields: bytes = b"") -> bytes:
    return f"GET {path} HTTP/1.1\r\nHost: denavit\r\n".encode() + fields + b"\r\n"


UPGRADE = (
    b"Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n"
    b"Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
)


@pytest.mark.parametrize(
    ("head", "detail"),
    [
        (_get("/health", b"X-A: b\r\n" * 300), "more than 256 header fields"),
        (_get(PATH, UPGRADE + b"X-A: b\r\n" * 300), "more than 256 header fields"),
        (_get("/health", b"X-Big: " + b"a" * (65 << 10) + b"\r\n"), "exceed 65536 bytes"),
        # the URL's last bytes pass the limit: the server has read all before it answers
        (_get("/health?" + "a" * ((64 << 10) + 50)), "exceed 65536 bytes"),
    ],
    ids=["fields", "upgrade-fields", "one-field", "url"],
)
def test_a_request_head_over_the_bounds_is_431(server: Server, head: bytes, detail: str) -> None:
    status, body = _answer(server.url, head)
    assert (status, body["status"], body["field"]) == (431, 431, "headers"), body
    assert detail in body["detail"] and body["detail"].startswith("headers:")


def test_heads_within_the_bounds_and_large_bodies_are_served(server: Server) -> None:
    """60 KiB of header fields, 200 of them: served; a 4 MiB body (read while the head
    bound counts the reads of the socket: never mistaken for a head)."""
    fields = (b"X-A: " + b"b" * 300 + b"\r\n") * 200
    status, body = _answer(server.url, _get("/health", fields))
    assert (status, body) == (200, {"status": "ok"})
    payload = orjson.dumps({"q": Q_UR5}) + b" " * (4 << 20)
    head = (
        f"POST /robots/ur5/fk HTTP/1.1\r\nHost: denavit\r\nContent-Type: application/json\r\n"
        f"Content-Length: {len(payload)}\r\n\r\n"
    ).encode()
    status, body = _answer(server.url, head + payload)
    assert status == 200 and body["poses"], body


def test_endless_request_heads_cannot_make_workers_buffer(server: Server) -> None:
    """Two connections each send 64 MiB of a head that never ends: 8-byte header lines
    (each a Python tuple of two bytes objects in uvicorn), one header line. Each is closed
    after at most 1 MiB; the workers grow by less than :data:`BOUND`, the same workers
    serve on.

    Before the bound: the workers peaked ~+900 MiB and kept it."""
    host, port = server.url.removeprefix("http://").split(":")
    heads = {
        "fields": (_get("/health")[:-2], b"X-A: b\r\n" * 8192),
        "one line": (_get("/health")[:-2] + b"X-Big: ", b"a" * (64 << 10)),
    }
    _answer(server.url, _get("/health"))  # first use of the code in a worker
    pids = worker_pids(server)
    rss = _baseline(pids)
    sent = {}
    for kind, (start, chunk) in heads.items():
        with socket.create_connection((host, int(port)), timeout=60) as sock:
            sock.sendall(start)
            sent[kind] = 0
            with contextlib.suppress(OSError):  # the server closes the connection
                while sent[kind] < 64 << 20:
                    sock.sendall(chunk)
                    sent[kind] += len(chunk)
            with contextlib.suppress(OSError):
                sock.shutdown(socket.SHUT_WR)
                while sock.recv(65536):  # until the server has closed it
                    pass
    grown, peak = _growth(rss)
    report = f"sent {sent}; RSS +{grown / 2**20:.1f} MiB, peak +{peak / 2**20:.1f} MiB"
    assert peak < BOUND and grown < BOUND, report
    assert all(n < 64 << 20 for n in sent.values()), report
    assert worker_pids(server) == pids, report
    assert _answer(server.url, _get("/health")) == (200, {"status": "ok"})
