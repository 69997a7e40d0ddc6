"""The Python client's WebSocket (``denavit_client.stream.CallingThreadWebSocket``) against an
independent server: ``websockets``' own threaded server, which checks the client's side of
RFC 6455 (masked frames, the handshake, the closing handshake) and can do what the service
never does (fragment a message, ping, refuse the upgrade, send a message over the size
bound, close with a code of its own).

And the binary ik frame ``Stream.ik_step`` packs at once: byte for byte the frame the
generic NumPy construction builds, for every kind of input a lab passes; anything that is
not 3 and 4 numbers goes the generic way and gets the service's own answer.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager

import numpy as np
import pytest
from denavit_client.stream import IK, CallingThreadWebSocket, Stream
from websockets.exceptions import ConnectionClosed, InvalidStatus
from websockets.http11 import Response
from websockets.sync.server import ServerConnection, serve


@contextmanager
def server(
    handler: Callable[[ServerConnection], None], **options: object
) -> Iterator[tuple[str, list[object]]]:
    """A ``websockets`` server on a free loopback port running ``handler`` per connection;
    yields its URL and a list the handler may record into."""
    seen: list[object] = []

    def run(ws: ServerConnection) -> None:
        handler(ws)

    with serve(run, "127.0.0.1", 0, compression=None, **options) as srv:  # type: ignore[arg-type]
        port = srv.socket.getsockname()[1]
        thread = threading.Thread(target=srv.serve_forever, daemon=True)
        thread.start()
        try:
            yield f"ws://127.0.0.1:{port}/robots/x/stream", seen
        finally:
            srv.shutdown()
            thread.join(10)


def test_messages_keep_their_type_and_bytes() -> None:
    def echo(ws: ServerConnection) -> None:
        for message in ws:
            ws.send(message)

    with server(echo) as (url, _):
        ws = CallingThreadWebSocket(url)
        try:
            # every length encoding both ways, at its bounds: 7-bit (≤ 125), 16-bit (126 …
            # 65535), 64-bit (≥ 65536); the server checks the client's masking
            sizes = [0, 1, 125, 126, 127, 65_535, 65_536, 200_000]
            binary = [bytes((i * 7) % 256 for i in range(n)) for n in sizes]
            text = ["é" * (n // 2) for n in sizes]  # 2 bytes each in UTF-8
            for message in ["héllo", b"\x00\xff" * 40, "", b"", *binary, *text]:
                ws.send(message)
                got = ws.recv()
                assert type(got) is type(message) and got == message
        finally:
            ws.close()


def test_messages_that_come_together_are_taken_in_order() -> None:
    """200 messages sent at once by the server (many whole frames, and frames cut, in one
    read of the socket): every one received, in order, with its type."""

    def burst(ws: ServerConnection) -> None:
        ws.recv()
        for i in range(200):
            ws.send(f"t{i}" if i % 3 == 0 else i.to_bytes(4, "little") * (1 + i % 50))
        ws.recv()

    with server(burst) as (url, _):
        ws = CallingThreadWebSocket(url)
        try:
            ws.send("go")
            for i in range(200):
                want = f"t{i}" if i % 3 == 0 else i.to_bytes(4, "little") * (1 + i % 50)
                assert ws.recv() == want, i
            ws.send("done")
        finally:
            ws.close()


def test_invalid_utf8_text_fails_the_connection_as_websockets_does() -> None:
    """A text frame that is not UTF-8: the connection fails with 1007, as ``websockets``'
    own client fails it."""

    def bad(ws: ServerConnection) -> None:
        ws.send(b"ok", text=True)
        ws.send(b"\xff\xfe", text=True)
        try:
            ws.recv()
        except ConnectionClosed:
            pass

    with server(bad) as (url, _):
        ws = CallingThreadWebSocket(url)
        assert ws.recv() == "ok"
        with pytest.raises(ConnectionClosed) as closed:
            ws.recv()
        assert closed.value.sent is not None and closed.value.sent.code == 1007
        ws.close()


def test_fragmented_messages_are_joined_and_pings_answered() -> None:
    pongs: list[bool] = []

    def fragments(ws: ServerConnection) -> None:
        ws.recv()
        ws.send(iter([b"ab", b"cd", b"ef"]))  # one binary message in three frames
        pongs.append(ws.ping().wait(5))  # answered by the client while it waits
        ws.send(iter(["g", "hi"]))  # one text message in two frames
        ws.send(b"last")
        ws.recv()

    with server(fragments) as (url, _):
        ws = CallingThreadWebSocket(url)
        try:
            ws.send("go")
            assert ws.recv() == b"abcdef"
            assert ws.recv() == "ghi"
            assert ws.recv() == b"last"
            ws.send("done")
        finally:
            ws.close()
    assert pongs == [True]


def test_a_close_code_is_raised_as_websockets_does() -> None:
    def refuse(ws: ServerConnection) -> None:
        ws.close(4404, "robot_id: unknown robot 'x'")

    with server(refuse) as (url, _):
        ws = CallingThreadWebSocket(url)
        with pytest.raises(ConnectionClosed) as closed:
            ws.recv()
        assert closed.value.rcvd is not None
        assert closed.value.rcvd.code == 4404
        assert closed.value.rcvd.reason == "robot_id: unknown robot 'x'"
        with pytest.raises(ConnectionClosed):  # and stays closed
            ws.recv()
        ws.close()


def test_a_message_over_the_size_bound_fails_the_connection() -> None:
    def big(ws: ServerConnection) -> None:
        ws.send(bytes(2048))
        try:
            ws.recv()
        except ConnectionClosed:
            pass

    with server(big) as (url, _):
        ws = CallingThreadWebSocket(url, max_size=1024)
        with pytest.raises(ConnectionClosed) as closed:
            ws.recv()
        assert closed.value.sent is not None and closed.value.sent.code == 1009
        ws.close()


def test_a_refused_upgrade_raises_its_status_and_headers_go_out() -> None:
    def check(connection: ServerConnection, request) -> Response | None:
        if request.headers.get("Authorization") != "Bearer s3cret":
            return connection.respond(401, "no token\n")
        return None

    def echo(ws: ServerConnection) -> None:
        for message in ws:
            ws.send(message)

    with server(echo, process_request=check) as (url, _):
        with pytest.raises(InvalidStatus) as refused:
            CallingThreadWebSocket(url)
        assert refused.value.response.status_code == 401
        ws = CallingThreadWebSocket(url, additional_headers={"Authorization": "Bearer s3cret"})
        ws.send(b"ok")
        assert ws.recv() == b"ok"
        ws.close()


class _Recorder:
    """Stands in for the socket: records the frames, answers a fixed ik reply."""

    def __init__(self, dof: int) -> None:
        self.sent: list[bytes] = []
        self.dof = dof

    def send(self, frame: bytes) -> None:
        self.sent.append(frame)

    def recv(self) -> bytes:
        frame_id = np.frombuffer(self.sent[-1], "<f8")[1]
        values = [IK, frame_id, 1.0, *np.arange(self.dof) * 0.1, 1e-9, 2e-9]
        return np.array(values, "<f8").tobytes()


def _generic_frame(frame_id: int, position: object, orientation: object) -> bytes:
    """The frame as the generic path (``Stream._binary``) builds it."""
    target = np.concatenate([np.asarray(position, np.float64), orientation])
    frame = np.concatenate([[IK, float(frame_id)], np.asarray(target, np.float64)])
    return frame.astype("<f8").tobytes()


@pytest.mark.parametrize(
    ("position", "orientation"),
    [
        ([0.1, -0.2, 0.3], [0.0, 0.0, 0.0, 1.0]),
        ((1, 2, 3), (0.5, 0.5, 0.5, 0.5)),  # ints and tuples
        (np.array([0.1, 0.2, 0.3]), np.array([0.1, 0.2, 0.3, 0.927])),
        (np.array([0.1, 0.2, 0.3], np.float32), np.array([0, 0, 1, 0], np.float32)),
        ([np.float64(1e-300), -0.0, 7.5], [np.float32(0.7071), 0, 0, 0.7071]),
    ],
)
def test_the_packed_ik_frame_is_the_generic_one(position: object, orientation: object) -> None:
    stream = Stream(_Recorder(dof=6))  # type: ignore[arg-type]
    for k in (1, 2):
        ok, q, position_error, orientation_error = stream.ik_step(position, orientation)
        assert stream.ws.sent[-1] == _generic_frame(k, position, orientation)  # type: ignore[attr-defined]
        assert ok and position_error == 1e-9 and orientation_error == 2e-9
        np.testing.assert_array_equal(q, np.arange(6) * 0.1)


def test_other_shapes_go_the_generic_way() -> None:
    stream = Stream(_Recorder(dof=6))  # type: ignore[arg-type]
    stream.ik_step([0.1, 0.2, 0.3, 0.4], [0.0, 0.0, 1.0])  # 7 numbers, split otherwise
    assert stream.ws.sent[-1] == _generic_frame(1, [0.1, 0.2, 0.3, 0.4], [0.0, 0.0, 1.0])  # type: ignore[attr-defined]
    stream.ik_step([0.1, 0.2], [0.0, 0.0, 0.0, 1.0])  # 6 numbers: the service answers 422
    assert len(stream.ws.sent[-1]) == 8 * 8  # type: ignore[attr-defined]
    with pytest.raises(ValueError):  # not numbers: NumPy's own error, as before
        stream.ik_step(["a", "b", "c"], [0.0, 0.0, 0.0, 1.0])
