"""WS /robots/{id}/stream: the HTTP endpoints' answers and errors, in order, on one socket.

References are independent of the stream: the HTTP endpoints' own answers for the same
inputs (bit for bit: FK, Jacobian, IK with ``max_iterations`` and ``random_seed``), FK by
Pinocchio in the test, and the raw ASGI protocol for backpressure.
"""

from __future__ import annotations

import asyncio
import threading
from pathlib import Path

import httpx
import numpy as np
import orjson
import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect
from websockets.sync.client import connect

from app.main import create_app
from app.operations.settings import Settings
from tests.helpers import fk_target, serve

Q_UR5 = [0.3, -1.1, 1.4, -0.6, 1.2, 0.4]
Q_PANDA = [0.2, -0.5, 0.1, -2.0, 0.3, 1.6, 0.6, 0.02]
#: IK whose answer does not depend on the machine's speed (iteration cap, generous budget).
EXACT_IK = {"max_iterations": 2000, "timeout_ms": 1000.0, "random_seed": 7}


def send(ws, message: dict) -> None:
    """A JSON text message (a TestClient socket, or a ``websockets`` client's)."""
    text = orjson.dumps(message).decode()
    ws.send_text(text) if hasattr(ws, "send_text") else ws.send(text)


def answer_body(answer: dict) -> dict:
    return {k: v for k, v in answer.items() if k not in ("id", "op")}


@pytest.fixture
def stream_app(tmp_path: Path):
    def make(**settings):
        return create_app(Settings(data_dir=tmp_path / "data", **settings))

    return make


# ------------------------------------------------------------------- live, 8 sockets
def _client(url: str, robot_id: str, k: int, registry, results: dict) -> None:
    """One thread: its own socket and HTTP client; pipelined messages, answers in order."""
    rng = np.random.default_rng(100 + k)
    q0, frame = (Q_UR5, "tool0") if robot_id == "ur5" else (Q_PANDA, "panda_link8")
    msgs = [("fk", {"q": q0}), ("jacobian", {"q": q0})]
    for _ in range(6):  # IK near q0: the first from the default seed, then chained
        q = (np.array(q0) + rng.uniform(-0.15, 0.15, len(q0))).tolist()
        msgs.append(("ik", {"target": fk_target(registry, q, robot_id, frame), **EXACT_IK}))
        msgs.append(("fk", {"q": q}))
    ws_url = url.replace("http://", "ws://") + f"/robots/{robot_id}/stream"
    with connect(ws_url, proxy=None, open_timeout=60) as ws, httpx.Client(timeout=60) as http:
        for i, (op, body) in enumerate(msgs):  # all sent before any answer is read
            send(ws, {"id": f"{k}-{i}", "op": op, **body})
        answers = [orjson.loads(ws.recv(timeout=120)) for _ in msgs]
        last_q = None
        for i, ((op, body), ans) in enumerate(zip(msgs, answers, strict=True)):
            assert (ans["id"], ans["op"]) == (f"{k}-{i}", op)
            http_body = dict(body)
            if op == "ik" and last_q is not None:
                http_body["seed"] = last_q  # the stream seeded it with its last solution
            ref = http.post(f"{url}/robots/{robot_id}/{op}", json=http_body)
            assert ref.status_code == 200, ref.text
            expected = ref.json()
            if op == "ik":
                assert ans["success"], ans
                last_q = ans["q"]
                expected.pop("solve_time_ms"), ans.pop("solve_time_ms")
            assert answer_body(ans) == expected, (op, i)
    results[k] = len(msgs)


def test_eight_concurrent_sockets_answer_as_http_in_order(tmp_path, registry) -> None:
    results: dict[int, int] = {}
    errors: list[BaseException] = []

    def run(k: int) -> None:
        try:
            _client(server.url, "ur5" if k % 2 else "panda", k, registry, results)
        except BaseException as exc:  # noqa: BLE001 - reported by the main thread
            errors.append(exc)

    with serve(tmp_path / "data") as server:
        threads = [threading.Thread(target=run, args=(k,)) for k in range(8)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(timeout=600)
    assert not errors, errors
    assert sorted(results) == list(range(8))


# -------------------------------------------------------------- in-process protocol
def test_ik_without_seed_starts_from_the_last_solution(client, registry) -> None:
    """UR5: a branch other than the default one, given as the seed once, keeps being the
    answer for the same target when later messages give no seed (HTTP: the default)."""
    target = fk_target(registry, Q_UR5, "ur5", "tool0")
    default = client.post("/robots/ur5/ik", json={"target": target}).json()["q"]
    every = client.post("/robots/ur5/ik", json={"target": target, "num_solutions": 8}).json()
    other = next(
        s["q"] for s in every["solutions"] if np.abs(np.subtract(s["q"], default)).max() > 0.5
    )
    with client.websocket_connect("/robots/ur5/stream") as ws:
        send(ws, {"id": 1, "op": "ik", "target": target})
        np.testing.assert_allclose(ws.receive_json()["q"], default, atol=1e-12)
        send(ws, {"id": 2, "op": "ik", "target": target, "seed": other})
        np.testing.assert_allclose(ws.receive_json()["q"], other, atol=1e-12)
        for i in range(3, 6):
            send(ws, {"id": i, "op": "ik", "target": target})
            np.testing.assert_allclose(ws.receive_json()["q"], other, atol=1e-12)


BAD = [
    ("not json", 400, "message", None),
    ("[1, 2]", 422, "message", None),
    ('{"id": 5, "op": "fkk", "q": [0]}', 422, "op", None),
    ('{"id": 6, "q": [0]}', 422, "op", None),
    ('{"id": [1], "op": "fk"}', 422, "id", None),
    # what the JSON parser turns into inf or nan: not echoable, refused
    ('{"id": 1e999, "op": "fk", "q": [0, 0, 0, 0, 0, 0]}', 422, "id", None),
    ('{"id": -1e999, "op": "fk", "q": [0, 0, 0, 0, 0, 0]}', 422, "id", None),
    ('{"id": NaN, "op": "fk", "q": [0, 0, 0, 0, 0, 0]}', 422, "id", None),
    ('{"id": Infinity, "op": "fk", "q": [0, 0, 0, 0, 0, 0]}', 422, "id", None),
    ('{"id": 8, "op": "fk", "q": [1, "a", 0, 0, 0, 0]}', 422, "q.1", "fk"),
    ('{"id": 9, "op": "fk", "q": [0, 0, 0, 0, 0, 0], "frames": ["nope"]}', 422, "frames", "fk"),
    ('{"id": 10, "op": "jacobian", "q": [0, 0, 0], "bogus": 1}', 422, "bogus", "jacobian"),
    (
        '{"id": 11, "op": "ik", "target": {"position": [0.3, 0, 0.3]}}',
        422,
        "target.orientation",
        "ik",
    ),
    (
        '{"id": 12, "op": "ik", "target": {"position": [0.3, 0, 0.3], "orientation": '
        '[0, 0, 0, 1]}, "timeout_ms": 1e9}',
        422,
        "timeout_ms",
        "ik",
    ),  # fmt: skip
    ('{"id": 13, "op": "dynamics", "q": [0, 0, 0, 0, 0, 0], "velocities": [1]}', 422,
     "velocities", "dynamics"),
    ('{"id": 14, "op": "dynamics", "q": [0, 0, 0, 0, 0, 0], "velocities": {"x": 1}}', 422,
     "velocities.x", "dynamics"),
    ('{"id": 15, "op": "dynamics", "q": [0, 0, 0, 0, 0, 0], "payload": {"mass": -1}}', 422,
     "payload.mass", "dynamics"),
    ('{"id": 16, "op": "dynamics", "q": [0, 0, 0, 0, 0, 0], "accelerations": '
     '[0, 0, 2e6, 0, 0, 0]}', 422, "accelerations.2", "dynamics"),
]  # fmt: skip


def test_bad_messages_get_the_http_error_and_the_socket_stays_usable(client) -> None:
    with client.websocket_connect("/robots/ur5/stream") as ws:
        for text, status, field, op in BAD:
            ws.send_text(text)
            err = ws.receive_json()
            problem = err["error"]
            assert problem["status"] == status, (text, problem)
            if field is not None:
                assert problem["field"].startswith(field), (text, problem)
                assert problem["field"] in problem["detail"]
            if op is not None:  # the very body the HTTP route answers
                body = orjson.loads(text)
                msg_id = body.pop("id")
                assert (err["id"], err["op"]) == (msg_id, op)
                del body["op"]
                http = client.post(f"/robots/ur5/{op}", json=body)
                assert http.status_code == status
                assert problem == http.json(), text
            send(ws, {"id": "ok", "op": "fk", "q": Q_UR5})  # still usable
            assert ws.receive_json()["id"] == "ok"
        ws.send_bytes(b"\x00" * 5)  # not float64 values
        assert ws.receive_json()["error"]["field"] == "message"
        ws.send_bytes(np.array([9.0, 1.0], "<f8").tobytes())
        assert ws.receive_json()["error"]["field"] == "op"
        ws.send_bytes(np.array([1.0, 2.0, 0.0, np.nan], "<f8").tobytes())
        assert ws.receive_json()["error"]["field"] == "q.1"
        for bad_id in (np.nan, np.inf, -np.inf):  # answered in JSON (text), naming the id
            ws.send_bytes(np.array([1.0, bad_id, *Q_UR5], "<f8").tobytes())
            err = ws.receive_json()
            assert (err["id"], err["error"]["status"], err["error"]["field"]) == (None, 422, "id")
            assert "finite" in err["error"]["detail"]
        send(ws, {"id": "ok", "op": "fk", "q": Q_UR5})
        assert ws.receive_json()["id"] == "ok"


def test_dynamics_answers_as_http(client) -> None:
    """The dynamics op answers exactly the HTTP endpoint's body (UR5; the Panda with its
    mimic finger, a group, rate maps, a payload and a wrench), in order among other ops."""
    rng = np.random.default_rng(4)
    bodies = [
        ("ur5", {"q": Q_UR5}),
        (
            "ur5",
            {
                "q": Q_UR5,
                "velocities": rng.normal(size=6).tolist(),
                "accelerations": {"elbow_joint": 0.7},
                "payload": {
                    "mass": 1.2,
                    "com": [0, 0, 0.04],
                    "inertia": [0.01, 0, 0, 0.01, 0, 0.01],
                },
                "wrench": {"values": [1, 2, -3, 0, 0.1, 0], "reference": "local"},
            },
        ),
        ("panda", {"q": Q_PANDA, "velocities": rng.normal(size=8).tolist()}),
        ("panda", {"q": Q_PANDA[:7], "group": "arm", "accelerations": [0.3] * 7}),
    ]
    for robot_id in ("ur5", "panda"):
        with client.websocket_connect(f"/robots/{robot_id}/stream") as ws:
            mine = [b for rid, b in bodies if rid == robot_id]
            for i, body in enumerate(mine):  # pipelined, with an fk between them
                send(ws, {"id": i, "op": "dynamics", **body})
                send(ws, {"id": f"fk{i}", "op": "fk", "q": body["q"]})
            for i, body in enumerate(mine):
                ans = ws.receive_json()
                assert (ans["id"], ans["op"]) == (i, "dynamics")
                http = client.post(f"/robots/{robot_id}/dynamics", json=body)
                assert http.status_code == 200, http.text
                assert answer_body(ans) == http.json()
                assert ws.receive_json()["id"] == f"fk{i}"


def test_binary_frames_round_trip(client) -> None:
    """Binary fk/jacobian/ik answers hold the JSON answers' floats, bit for bit."""
    with client.websocket_connect("/robots/ur5/stream") as ws:
        send(ws, {"id": 1, "op": "fk", "q": Q_UR5})
        pose = ws.receive_json()["poses"]["tool0"]
        ws.send_bytes(np.array([1.0, 42.0, *Q_UR5], "<f8").tobytes())
        got = np.frombuffer(ws.receive_bytes(), "<f8")
        assert got.tolist() == [1.0, 42.0, *pose["position"], *pose["orientation"]]

        send(ws, {"id": 2, "op": "jacobian", "q": Q_UR5})
        J = ws.receive_json()["jacobian"]
        ws.send_bytes(np.array([2.0, 43.0, *Q_UR5], "<f8").tobytes())
        got = np.frombuffer(ws.receive_bytes(), "<f8")
        assert got.tolist() == [2.0, 43.0, *np.ravel(J)]

        target = {"position": pose["position"], "orientation": pose["orientation"]}
        send(ws, {"id": 3, "op": "ik", "target": target, "seed": Q_UR5, **EXACT_IK})
        ik = ws.receive_json()
        frame = [3.0, 44.0, *pose["position"], *pose["orientation"]]
        ws.send_bytes(np.array(frame, "<f8").tobytes())  # seeded by ik["q"], same options
        got = np.frombuffer(ws.receive_bytes(), "<f8")
        expected = [3.0, 44.0, 1.0, *ik["q"], ik["position_error"], ik["orientation_error"]]
        assert got.tolist() == expected
        np.testing.assert_allclose(ik["q"], Q_UR5, atol=1e-9)


def test_unknown_robot_closes_4404(client) -> None:
    with client.websocket_connect("/robots/nope/stream") as ws:
        with pytest.raises(WebSocketDisconnect) as info:
            ws.receive_text()
    assert info.value.code == 4404
    assert "nope" in info.value.reason


def test_a_message_over_the_size_limit_closes_1009(stream_app) -> None:
    with TestClient(stream_app(stream_max_message_bytes=2048)) as client:
        with client.websocket_connect("/robots/ur5/stream") as ws:
            send(ws, {"id": 1, "op": "fk", "q": Q_UR5})
            assert ws.receive_json()["id"] == 1
            send(ws, {"id": 2, "op": "fk", "q": Q_UR5, "frames": ["tool0"] * 400})
            with pytest.raises(WebSocketDisconnect) as info:
                ws.receive_json()
    assert info.value.code == 1009
    assert "2048" in info.value.reason


def test_the_token_is_required_when_set(stream_app) -> None:
    fk = {"id": 1, "op": "fk", "q": Q_UR5}
    with TestClient(stream_app(api_token="s3cret")) as client:
        for headers, first in [
            ({}, fk),  # no token at all
            ({}, {"token": "wrong"}),
            ({"Authorization": "Bearer wrong"}, fk),
            ({"Authorization": "Basic s3cret"}, fk),
        ]:
            with client.websocket_connect("/robots/ur5/stream", headers=headers) as ws:
                send(ws, first)
                with pytest.raises(WebSocketDisconnect) as info:
                    ws.receive_json()
            assert info.value.code == 1008, (headers, first)
            assert "authorization" in info.value.reason
        with client.websocket_connect(
            "/robots/ur5/stream", headers={"Authorization": "Bearer s3cret"}
        ) as ws:
            send(ws, fk)
            assert ws.receive_json()["poses"]
            send(ws, {"token": "s3cret"})  # later token messages are answered too
            assert ws.receive_json() == {"id": None, "op": "auth", "authenticated": True}
        with client.websocket_connect("/robots/ur5/stream") as ws:
            send(ws, {"id": "a", "token": "s3cret"})
            assert ws.receive_json() == {"id": "a", "op": "auth", "authenticated": True}
            send(ws, fk)
            assert ws.receive_json()["poses"]


def test_a_long_first_message_of_an_unauthenticated_socket_is_refused_unread(
    stream_app, monkeypatch
) -> None:
    """Authentication by message: a first message over 64 KiB closes with 1008 before it
    is parsed (an unauthenticated client cannot make the server build Python objects from
    up to 1 MiB of JSON); a token message with a long id within it is accepted."""
    from app.api.routes import stream

    parsed: list[int] = []
    real = stream.parse_text

    def counting(text, *args):
        parsed.append(len(text))
        return real(text, *args)

    monkeypatch.setattr(stream, "parse_text", counting)
    with TestClient(stream_app(api_token="s3cret")) as client:
        with client.websocket_connect("/robots/ur5/stream") as ws:
            send(ws, {"id": "x" * (64 << 10), "token": "s3cret"})
            with pytest.raises(WebSocketDisconnect) as info:
                ws.receive_json()
        assert info.value.code == 1008
        assert "authorization" in info.value.reason and "65536" in info.value.reason
        assert parsed == []
        with client.websocket_connect("/robots/ur5/stream") as ws:
            send(ws, {"id": "x" * 60_000, "token": "s3cret"})
            assert ws.receive_json()["authenticated"] is True
        assert len(parsed) == 1


# ------------------------------------------------------------------------ backpressure
def test_a_client_that_stops_reading_is_no_longer_read(stream_app) -> None:
    """Raw ASGI: the client offers endless messages and never takes an answer (the first
    send blocks): the server reads exactly the in-flight limit, then stops reading."""
    app = stream_app(stream_max_in_flight=4)
    fk = orjson.dumps({"op": "fk", "q": Q_UR5}).decode()
    received, sent = [], []
    blocked = asyncio.Event()

    async def receive() -> dict:
        if not received:
            received.append("connect")
            return {"type": "websocket.connect"}
        received.append("message")
        return {"type": "websocket.receive", "text": fk}

    async def send_(message: dict) -> None:
        sent.append(message["type"])
        if message["type"] == "websocket.send":
            blocked.set()
            await asyncio.Event().wait()  # the client never reads

    scope = {"type": "websocket", "path": "/robots/ur5/stream", "raw_path": b"/robots/ur5/stream",
             "root_path": "", "query_string": b"", "headers": [], "scheme": "ws",
             "client": ("127.0.0.1", 1), "server": ("127.0.0.1", 80), "subprotocols": [],
             "asgi": {"version": "3.0"}, "state": {}}  # fmt: skip

    async def main() -> None:
        task = asyncio.ensure_future(app(scope, receive, send_))
        await asyncio.wait_for(blocked.wait(), timeout=120)
        for _ in range(1000):  # let every runnable task run: only the reader could
            await asyncio.sleep(0)
        task.cancel()
        with pytest.raises(asyncio.CancelledError):
            await task

    asyncio.run(main())
    assert sent[:2] == ["websocket.accept", "websocket.send"]
    assert received.count("message") == 4


def test_a_bug_in_one_message_is_a_500_error_message_and_the_socket_stays_usable(
    client, monkeypatch
) -> None:
    """An unexpected exception while answering: logged, answered as the HTTP guard's 500."""
    from app.api.routes import stream

    real = stream.jacobian_answer

    def buggy(robot, body):
        raise RuntimeError("a bug, on purpose")

    monkeypatch.setattr(stream, "jacobian_answer", buggy)
    with client.websocket_connect("/robots/ur5/stream") as ws:
        send(ws, {"id": 1, "op": "jacobian", "q": Q_UR5})
        err = ws.receive_json()
        assert (err["id"], err["op"], err["error"]["status"]) == (1, "jacobian", 500)
        assert err["error"]["detail"] == "internal error"
        monkeypatch.setattr(stream, "jacobian_answer", real)
        send(ws, {"id": 2, "op": "jacobian", "q": Q_UR5})
        assert ws.receive_json()["jacobian"]


def test_a_reader_crash_closes_1011_and_logs_its_traceback(client, monkeypatch, caplog) -> None:
    """A bug in the socket's reader (here: measuring a message) ends the socket with 1011
    and leaves its traceback in the log (before: a silent 1011)."""
    from app.api.routes import stream

    def buggy_size(message: dict) -> int:
        raise ZeroDivisionError("a bug in the reader, on purpose")

    monkeypatch.setattr(stream, "_size", buggy_size)
    with caplog.at_level("ERROR", logger="denavit"):
        with client.websocket_connect("/robots/ur5/stream") as ws:
            send(ws, {"id": 1, "op": "fk", "q": Q_UR5})
            with pytest.raises(WebSocketDisconnect) as info:
                ws.receive_json()
    assert info.value.code == 1011
    [record] = [r for r in caplog.records if r.exc_info is not None]
    assert record.exc_info[0] is ZeroDivisionError and "/robots/ur5/stream" in record.getMessage()
    assert "buggy_size" in caplog.text


def test_plain_http_to_the_stream_is_told_to_upgrade(client) -> None:
    resp = client.get("/robots/ur5/stream")
    assert resp.status_code == 426
    assert resp.headers["content-type"] == "application/problem+json"
    assert resp.headers["upgrade"] == "websocket"
    assert "WebSocket" in resp.json()["detail"]


def test_collision_aware_ik_runs_as_over_http(client, registry) -> None:
    """Obstacles (in the work pool), then a binary frame reusing those options."""
    target = fk_target(registry, Q_UR5, "ur5", "tool0")
    ball = {"name": "ball", "shape": "sphere", "radius": 0.05, "pose": {"position": [2, 2, 2]}}
    body = {"target": target, "avoid_collisions": True, "obstacles": [ball], "seed": Q_UR5,
            **EXACT_IK}  # fmt: skip
    expected = client.post("/robots/ur5/ik", json=body).json()
    with client.websocket_connect("/robots/ur5/stream") as ws:
        send(ws, {"id": 1, "op": "ik", **body})
        ans = ws.receive_json()
        assert ans["success"]
        ans.pop("solve_time_ms"), expected.pop("solve_time_ms")
        assert answer_body(ans) == expected
        ws.send_bytes(
            np.array([3.0, 2.0, *target["position"], *target["orientation"]], "<f8").tobytes()
        )
        got = np.frombuffer(ws.receive_bytes(), "<f8")
        assert got[:3].tolist() == [3.0, 2.0, 1.0]
        assert got[3:-2].tolist() == ans["q"]


def test_a_binary_frame_read_while_an_answer_is_sent_waits_for_it(stream_app, monkeypatch) -> None:
    """Raw ASGI: binary ik frames, the first answer's send held (the client reads slowly):
    the frames read meanwhile are answered after it, in order. (A frame that comes while
    nothing is being answered is answered by the reader itself; one that comes while an
    answer is pending must not overtake it.)"""
    from app.kinematics import ik

    monkeypatch.setattr(ik, "chain_ready", lambda *a, **k: True)  # solved on the loop
    app = stream_app()
    pose = [0.4, 0.1, 0.3, 0.0, 0.0, 0.0, 1.0]
    frames = [np.array([3.0, float(i), *pose], "<f8").tobytes() for i in range(1, 5)]
    received, done = [], []
    finished = asyncio.Event()

    async def receive() -> dict:
        if not received:
            received.append("connect")
            return {"type": "websocket.connect"}
        if len(received) <= len(frames):
            received.append("frame")
            return {"type": "websocket.receive", "bytes": frames[len(received) - 2]}
        await finished.wait()
        return {"type": "websocket.disconnect", "code": 1000}

    async def send_(message: dict) -> None:
        if message["type"] != "websocket.send":
            return
        answer = np.frombuffer(message["bytes"], "<f8")
        if answer[1] == 1.0:
            for _ in range(1000):  # the first answer's send is slow: the reader reads on
                await asyncio.sleep(0)
        done.append(answer[1])
        if len(done) == len(frames):
            finished.set()

    scope = {"type": "websocket", "path": "/robots/ur5/stream", "raw_path": b"/robots/ur5/stream",
             "root_path": "", "query_string": b"", "headers": [], "scheme": "ws",
             "client": ("127.0.0.1", 1), "server": ("127.0.0.1", 80), "subprotocols": [],
             "asgi": {"version": "3.0"}, "state": {}}  # fmt: skip

    asyncio.run(asyncio.wait_for(app(scope, receive, send_), timeout=120))
    assert received.count("frame") == len(frames)
    assert done == [1.0, 2.0, 3.0, 4.0]


def test_one_binary_frame_at_a_time_is_answered_by_the_reader(client, monkeypatch) -> None:
    """A servo loop's binary ik frames, one at a time, once the first has made the socket's
    plan: answered by the reading task itself (no hop), with the answers of the HTTP route
    seeded the same way (bit for bit)."""
    from app.api.routes import stream

    seen = []
    real = stream._Session._answered_inline

    def spy(self, message):
        seen.append(real(self, message))
        return seen[-1]

    monkeypatch.setattr(stream._Session, "_answered_inline", spy)
    with client.websocket_connect("/robots/ur5/stream") as ws:
        send(ws, {"id": 0, "op": "fk", "q": Q_UR5})
        pose = ws.receive_json()["poses"]["tool0"]
        seed = Q_UR5
        for i in range(1, 6):
            position = (np.array(pose["position"]) + [0.002 * i, 0.0, 0.0]).tolist()
            ws.send_bytes(np.array([3.0, i, *position, *pose["orientation"]], "<f8").tobytes())
            got = np.frombuffer(ws.receive_bytes(), "<f8").tolist()
            target = {"position": position, "orientation": pose["orientation"]}
            ref = client.post("/robots/ur5/ik", json={"target": target, "seed": seed}).json()
            assert got == [3.0, i, 1.0, *ref["q"], ref["position_error"], ref["orientation_error"]]
            seed = ref["q"]
    assert seen[:2] == [False, False] and all(seen[2:]) and len(seen) == 6, seen  # fk, first


def test_a_binary_frame_whose_chain_is_not_built_is_solved_in_the_pool(client, monkeypatch) -> None:
    """While the chain of the socket's plan is not built (its first build, tens of ms, must
    not stall the loop) a binary ik frame is solved in the pool; once it is, on the loop,
    and the check is not repeated for every frame."""
    from app.api.routes import stream
    from app.kinematics import ik

    checks, pooled = [], []
    real_offload = stream.offload

    def chain_ready(*args, **kwargs) -> bool:
        checks.append(1)
        return len(checks) > 1  # not built at the first check, built from then on

    async def offload(*args, **kwargs):
        pooled.append(1)
        return await real_offload(*args, **kwargs)

    monkeypatch.setattr(ik, "chain_ready", chain_ready)
    monkeypatch.setattr(stream, "offload", offload)
    with client.websocket_connect("/robots/ur5/stream") as ws:
        send(ws, {"id": 0, "op": "fk", "q": Q_UR5})
        pose = ws.receive_json()["poses"]["tool0"]
        for i in range(1, 6):
            ws.send_bytes(
                np.array([3.0, i, *pose["position"], *pose["orientation"]], "<f8").tobytes()
            )
            assert np.frombuffer(ws.receive_bytes(), "<f8")[:3].tolist() == [3.0, i, 1.0]
    assert (len(pooled), len(checks)) == (1, 2)
