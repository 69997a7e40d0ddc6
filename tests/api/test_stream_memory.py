"""WS /robots/{id}/stream on a live ``python -m app`` (2 workers, a token set): what an
unauthenticated client can make a worker buffer.

The sockets are raw TCP connections that write WebSocket frames by hand, so a frame can
claim compression (RSV1) or a length it never sends. The workers' memory is read from
``/proc/<pid>/status``: ``VmRSS`` before and after, and ``VmHWM``, the peak, reset to the
current size just before the sockets connect (``/proc/<pid>/clear_refs``), so a buffer
that was freed again still counts. No timing: every socket is read until its close frame.
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

from tests.helpers import Server, proc_stat, serve

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="reads worker memory from /proc"
)

TOKEN = "s3cret"
PATH = "/robots/ur5/stream"
Q_UR5 = [0.3, -1.1, 1.4, -0.6, 1.2, 0.4]
LIMIT = 1 << 20  # DENAVIT_STREAM_MAX_MESSAGE_BYTES, the default
#: What 12 hostile sockets may add to the two workers together, lasting or at the peak
#: (generous: a socket may buffer one message of at most the limit, plus the reads).
BOUND = 64 << 20
TEXT, CONT, CLOSE = 0x1, 0x0, 0x8


def _status(pid: int, key: str) -> int:
    """A ``/proc/<pid>/status`` memory line (``VmRSS``, ``VmHWM``) in bytes."""
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
    raise AssertionError(f"no {key} for {pid}")


def _workers(server: Server) -> list[int]:
    """The uvicorn workers: children of the server process started by ``spawn_main``."""
    pids = []
    for name in os.listdir("/proc"):
        if name.isdigit() and (stat := proc_stat(int(name))) and stat[1] == server.proc.pid:
            with contextlib.suppress(OSError), open(f"/proc/{name}/cmdline", "rb") as f:
                if b"spawn_main" in f.read():
                    pids.append(int(name))
    return sorted(pids)


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
        assert len(_workers(server)) == 2
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
    pids = _workers(server)
    rss = {pid: _status(pid, "VmRSS") for pid in pids}
    for pid in pids:  # the peak (VmHWM) restarts from the current size
        Path(f"/proc/{pid}/clear_refs").write_text("5")

    sockets = [RawSocket(server.url) for _ in kinds]
    for ws, kind in zip(sockets, kinds, strict=True):
        ws.send(hostile[kind])
    codes = []
    for ws in sockets:
        codes.append(ws.close_code())
        ws.close()

    grown = sum(_status(pid, "VmRSS") - rss[pid] for pid in pids)
    peak = sum(_status(pid, "VmHWM") - rss[pid] for pid in pids)
    report = f"codes {codes}; RSS +{grown / 2**20:.1f} MiB, peak +{peak / 2**20:.1f} MiB"
    assert peak < BOUND and grown < BOUND, report
    assert not any("sec-websocket-extensions" in ws.headers for ws in sockets)
    expected = {"compressed": 1002, "fragments": 1009, "header": 1009, "json": 1008}
    assert codes == [expected[kind] for kind in kinds], report
    assert _workers(server) == pids, report
    with connect(
        server.url.replace("http://", "ws://") + PATH,
        additional_headers={"Authorization": f"Bearer {TOKEN}"},
        proxy=None,
    ) as ws:
        ws.send(orjson.dumps({"id": 1, "op": "fk", "q": Q_UR5}).decode())
        assert orjson.loads(ws.recv(timeout=60))["poses"]
