"""The WebSocket stream ``/robots/{robot_id}/stream``, synchronous (hand-written: the
OpenAPI document has no WebSockets, so the generator has nothing to generate).

One socket serves one robot and answers FK, Jacobian and IK requests with the bodies and
answers of the HTTP routes, in order (docs/stream.md). :class:`Stream` sends the generated
request models and returns the generated answer models; binary frames (float64 arrays) are
:meth:`Stream.fk_pose` and :meth:`Stream.ik_step`. An IK without a seed starts from the last
successful IK solution on the socket.

The socket is read in the calling thread (:class:`CallingThreadWebSocket`): the
``websockets`` package's own RFC 6455 protocol (its sans-I/O ``ClientProtocol``: handshake,
fragmented messages, pings answered, the closing handshake, invalid UTF-8 and the message
size bound failing the connection) over a plain blocking socket, with the two frames a servo
loop exchanges framed here: a whole message sent (masked with a random key, RFC 6455 §5.3)
and a whole unfragmented text or binary message received (~2 µs each, against ~9 µs for the
protocol's own framing; docs/stream.md, "Speed"). Every other frame goes to the protocol
whole. Its sync client reads in a background thread and hands each message over through a
lock, which a servo loop waiting for every answer pays on each round trip.
"""

from __future__ import annotations

import json
import os
import socket
import ssl
import struct
from collections import deque
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray
from websockets.client import ClientProtocol
from websockets.frames import CloseCode, Frame, Opcode
from websockets.http11 import Response
from websockets.protocol import State
from websockets.uri import parse_uri

try:  # websockets' own masking, compiled where its speedups are built (as its framing does)
    from websockets.speedups import apply_mask
except ImportError:  # pragma: no cover - a pure-Python websockets
    from websockets.utils import apply_mask

from .models.fk_request import FKRequest
from .models.fk_response import FKResponse
from .models.ik_request import IKRequest
from .models.ik_response import IKResponse
from .models.jacobian_request import JacobianRequest
from .models.jacobian_response import JacobianResponse
from .models.problem import Problem

#: Op codes of binary frames.
FK, JACOBIAN, IK = 1.0, 2.0, 3.0
#: A binary ik frame: op code, id, position (3), quaternion [x, y, z, w] (4), little-endian.
_IK_FRAME = struct.Struct("<9d")
#: First byte of a whole (FIN) text and binary frame, no extension bits.
_TEXT, _BINARY = 0x81, 0x82
#: A frame header's second byte: the mask bit; 126 and 127: a 16- or 64-bit length follows.
_MASKED, _LEN16, _LEN64 = 0x80, 126, 127
_HEAD16, _HEAD64 = struct.Struct("!BBH"), struct.Struct("!BBQ")


class StreamError(Exception):
    """An error answer: the HTTP route's problem body (``problem.status``, ``.field``...)."""

    def __init__(self, problem: Problem) -> None:
        super().__init__(f"{problem.status}: {problem.detail}")
        self.problem = problem


class CallingThreadWebSocket:
    """A WebSocket client connection read and written in the calling thread.

    ``websockets``' sans-I/O :class:`~websockets.client.ClientProtocol` does the protocol;
    this class only moves its bytes over a blocking socket (TCP_NODELAY; TLS for ``wss://``
    with the default context). :meth:`recv` raises ``websockets``'
    :class:`~websockets.exceptions.ConnectionClosed` (with the close code and reason) once
    the connection is closed, as its sync client does.

    Parameters
    ----------
    url
        ``ws://host[:port]/path`` or ``wss://…``.
    additional_headers
        Extra headers of the upgrade request (e.g. ``Authorization``).
    open_timeout
        Seconds allowed for the TCP connection and the handshake; afterwards :meth:`recv`
        blocks until a message comes (the service answers every request).
    max_size
        Largest message accepted (bytes), as the sync client's ``max_size``.
    """

    def __init__(
        self,
        url: str,
        *,
        additional_headers: Mapping[str, str] | None = None,
        open_timeout: float = 10.0,
        max_size: int = 1 << 20,
    ) -> None:
        uri = parse_uri(url)
        self.protocol = ClientProtocol(uri, max_size=max_size)
        sock = socket.create_connection((uri.host, uri.port), timeout=open_timeout)
        try:
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            if uri.secure:
                sock = ssl.create_default_context().wrap_socket(sock, server_hostname=uri.host)
            self.sock = sock
            self._messages: deque[str | bytes] = deque()
            self._parts: list[bytes | bytearray | memoryview] = []
            self._text = False
            self._max_size = max_size
            #: Bytes read and not yet parsed into frames (:meth:`_frames`).
            self._buffer = bytearray()
            #: Every byte read goes to the protocol as it comes (the handshake; a frame over
            #: the size bound, which fails the connection; the closing handshake).
            self._raw = True
            request = self.protocol.connect()
            for name, value in (additional_headers or {}).items():
                request.headers[name] = value
            self.protocol.send_request(request)
            self._flush()
            while not any(isinstance(e, Response) for e in self._read()):
                if self.closed:
                    break
            if self.protocol.handshake_exc is not None:
                raise self.protocol.handshake_exc
            if self.protocol.state is not State.OPEN:
                raise ConnectionError(f"{url}: the connection closed during the handshake")
            sock.settimeout(None)
            self._raw = False
        except BaseException:
            sock.close()
            raise

    def _flush(self) -> None:
        """Send what the protocol has to send (frames, pongs, the close reply, EOF)."""
        for data in self.protocol.data_to_send():
            if data:
                self.sock.sendall(data)
            else:  # the protocol's end of the stream
                try:
                    self.sock.shutdown(socket.SHUT_WR)
                except OSError:
                    pass

    def _read(self) -> list[Any]:
        """One read of the socket fed to the protocol; its events (frames, the response)."""
        data = self.sock.recv(1 << 16)
        if data:
            self.protocol.receive_data(data)
        else:
            self.protocol.receive_eof()
        self._flush()
        return self.protocol.events_received()

    def _to_protocol(self, data: bytes | bytearray) -> None:
        """Bytes for the protocol (whole frames, or anything once :attr:`_raw`); its frames
        taken as messages, its replies (pongs, the close) sent."""
        self.protocol.receive_data(bytes(data))
        self._flush()
        for event in self.protocol.events_received():
            if isinstance(event, Frame):
                self._take(event)

    def _frames(self) -> None:
        """The whole frames at the start of :attr:`_buffer`, each taken out: a whole text or
        binary message (FIN, no extension bits, unmasked as a server's must be, within the
        size bound, valid UTF-8 for text) straight to the messages, any other frame to the
        protocol whole (so it never holds part of a frame, and its state stays its own). A
        frame over the size bound goes to the protocol as it is, which fails the connection,
        and the socket is the protocol's from then on."""
        buf = self._buffer
        while len(buf) >= 2 and not self._raw:
            first, second = buf[0], buf[1]
            size, at = second & 0x7F, 2
            if size == _LEN16:
                if len(buf) < 4:
                    return
                size, at = _HEAD16.unpack_from(buf)[2], 4
            elif size == _LEN64:
                if len(buf) < 10:
                    return
                size, at = _HEAD64.unpack_from(buf)[2], 10
            if size > self._max_size:
                self._raw = True
                break
            end = at + size + (4 if second & _MASKED else 0)
            if len(buf) < end:
                return
            frame = bytes(buf[:end])
            del buf[:end]
            if (first == _TEXT or first == _BINARY) and not second & _MASKED and not self._parts:
                if first == _BINARY:
                    self._messages.append(frame[at:])
                    continue
                try:
                    self._messages.append(frame[at:].decode())
                    continue
                except UnicodeDecodeError:
                    pass  # the protocol fails the connection (1007)
            self._to_protocol(frame)
        if self._raw and buf:
            data = bytes(buf)
            buf.clear()
            self._to_protocol(data)

    def send(self, message: str | bytes) -> None:
        """One message: a text frame for ``str``, a binary frame for ``bytes``, masked with a
        new random key (RFC 6455 §5.3)."""
        text = isinstance(message, str)
        data = cast(str, message).encode() if text else cast(bytes, message)
        if self.protocol.state is not State.OPEN:  # the protocol raises as it does
            if text:
                self.protocol.send_text(data)
            else:
                self.protocol.send_binary(data)
            self._flush()
            return
        first, size = _TEXT if text else _BINARY, len(data)
        if size < _LEN16:
            head = bytes((first, _MASKED | size))
        elif size < 1 << 16:
            head = _HEAD16.pack(first, _MASKED | _LEN16, size)
        else:
            head = _HEAD64.pack(first, _MASKED | _LEN64, size)
        key = os.urandom(4)
        self.sock.sendall(head + key + apply_mask(data, key))

    def recv(self) -> str | bytes:
        """The next message (``str`` for text, ``bytes`` for binary), fragments joined."""
        while not self._messages:
            if self.closed:
                raise self.protocol.close_exc
            data = self.sock.recv(1 << 16)
            if not data:
                self._raw = True
                if self._buffer:
                    self._to_protocol(self._buffer)
                    self._buffer.clear()
                self.protocol.receive_eof()
                self._flush()
                continue
            if self._raw:
                self._to_protocol(data)
            else:
                self._buffer += data
                self._frames()
        return self._messages.popleft()

    def _take(self, frame: Frame) -> None:
        if frame.opcode is Opcode.TEXT or frame.opcode is Opcode.BINARY:
            self._text, self._parts = frame.opcode is Opcode.TEXT, [frame.data]
        elif frame.opcode is Opcode.CONT:
            self._parts.append(frame.data)
        else:  # ping, pong, close: the protocol answers them
            return
        if frame.fin:
            data, self._parts = b"".join(self._parts), []
            if not self._text:
                self._messages.append(data)
                return
            try:
                self._messages.append(data.decode())
            except UnicodeDecodeError as exc:  # as websockets' own clients: fail with 1007
                self.protocol.fail(CloseCode.INVALID_DATA, f"{exc.reason} at position {exc.start}")
                self._flush()

    def close(self, code: int = 1000) -> None:
        """The closing handshake (the server's close frame awaited up to 2 s), then the
        socket closed."""
        try:
            self._raw = True  # the closing handshake is the protocol's
            if self._buffer:
                self._to_protocol(self._buffer)
                self._buffer.clear()
            if self.protocol.state is State.OPEN:
                self.protocol.send_close(code)
                self._flush()
                self.sock.settimeout(2.0)
                while not self.closed:
                    self._read()
        except OSError:
            pass
        finally:
            self.sock.close()

    @property
    def closed(self) -> bool:
        """Whether the connection is closed (the closing handshake done, or the socket gone)."""
        return self.protocol.state is State.CLOSED


class Stream:
    """One open stream socket (see :func:`open_stream`)."""

    def __init__(self, ws: CallingThreadWebSocket) -> None:
        self.ws = ws
        self._next_id = 0

    def _ask(self, op: str, body: dict[str, Any]) -> dict[str, Any]:
        self._next_id += 1
        self.ws.send(json.dumps({"id": self._next_id, "op": op, **body}))
        answer = self._json(self.ws.recv())
        if "error" in answer:
            raise StreamError(Problem.from_dict(answer["error"]))
        if answer.get("id") != self._next_id:
            raise RuntimeError(f"answer to id {answer.get('id')!r}, expected {self._next_id}")
        return {k: v for k, v in answer.items() if k not in ("id", "op")}

    @staticmethod
    def _json(message: str | bytes) -> dict[str, Any]:
        if isinstance(message, bytes):
            raise RuntimeError("a binary answer to a JSON request")
        answer: dict[str, Any] = json.loads(message)
        return answer

    def fk(self, request: FKRequest) -> FKResponse:
        """Forward kinematics, as ``POST /robots/{robot_id}/fk``."""
        return FKResponse.from_dict(self._ask("fk", request.to_dict()))

    def jacobian(self, request: JacobianRequest) -> JacobianResponse:
        """The Jacobian, as ``POST /robots/{robot_id}/jacobian``."""
        return JacobianResponse.from_dict(self._ask("jacobian", request.to_dict()))

    def ik(self, request: IKRequest) -> IKResponse:
        """Inverse kinematics, as ``POST /robots/{robot_id}/ik`` (seeded by the socket's last
        solution when the request has no ``seed``)."""
        return IKResponse.from_dict(self._ask("ik", request.to_dict()))

    def _binary(self, op: float, payload: ArrayLike) -> NDArray[np.float64]:
        self._next_id += 1
        frame = np.concatenate([[op, float(self._next_id)], np.asarray(payload, np.float64)])
        self.ws.send(frame.astype("<f8").tobytes())
        return self._binary_answer()

    def _binary_answer(self) -> NDArray[np.float64]:
        """The answer to the last binary frame: its values after the op code and id."""
        reply = self.ws.recv()
        if isinstance(reply, str):
            raise StreamError(Problem.from_dict(self._json(reply)["error"]))
        values = np.frombuffer(reply, "<f8")
        if values[1] != self._next_id:
            raise RuntimeError(f"answer to id {values[1]}, expected {self._next_id}")
        return values[2:].copy()

    def fk_pose(self, q: ArrayLike) -> NDArray[np.float64]:
        """The end effector's pose ``[x, y, z, qx, qy, qz, qw]`` (m; quaternion, w ≥ 0) at
        ``q``, by a binary frame."""
        return self._binary(FK, q)

    def jacobian_matrix(self, q: ArrayLike) -> NDArray[np.float64]:
        """The 6×n world Jacobian of the default frame at ``q``, by a binary frame."""
        values = self._binary(JACOBIAN, q)
        return values.reshape(6, -1)

    def ik_step(
        self, position: ArrayLike, orientation: ArrayLike
    ) -> tuple[bool, NDArray[np.float64], float, float]:
        """IK of one target by a binary frame: ``(success, q, position_error,
        orientation_error)``; options from the socket's last JSON ``ik`` request."""
        try:  # the frame packed at once (the common case: 3 and 4 numbers)
            x, y, z = cast(Sequence[float], position)
            qx, qy, qz, qw = cast(Sequence[float], orientation)
            frame = _IK_FRAME.pack(IK, float(self._next_id + 1), x, y, z, qx, qy, qz, qw)
        except (TypeError, ValueError, struct.error):  # anything else: as the server says
            target = np.concatenate([np.asarray(position, np.float64), orientation])
            values = self._binary(IK, target)
        else:
            self._next_id += 1
            self.ws.send(frame)
            values = self._binary_answer()
        return bool(values[0] == 1.0), values[1:-2], float(values[-2]), float(values[-1])


@contextmanager
def open_stream(base_url: str, robot_id: str, token: str | None = None) -> Iterator[Stream]:
    """Open the stream of ``robot_id`` at the service ``base_url`` (``http://...`` or
    ``https://...``; the socket is ``ws://`` or ``wss://`` on the same host).

    Parameters
    ----------
    base_url
        The service's root URL.
    robot_id
        The robot the socket serves (an unknown one closes it with code 4404).
    token
        The service's token when it has one (sent on the upgrade request), else ``None``.
    """
    url = base_url.replace("http", "ws", 1).rstrip("/") + f"/robots/{robot_id}/stream"
    headers = {"Authorization": f"Bearer {token}"} if token else None
    # The service offers no compression: none is asked for (no extensions).
    ws = CallingThreadWebSocket(url, additional_headers=headers)
    try:
        yield Stream(ws)
    finally:
        ws.close()
