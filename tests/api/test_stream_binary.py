"""Binary frames of WS /robots/{id}/stream: decoding, the IK answer written straight from
the solve's result, and the error answers of bad binary IK frames.

References: NumPy's reading and writing of little-endian float64 (``np.frombuffer``,
``ndarray.tobytes``) and docs/stream.md's layout of the binary ik answer, encoded by NumPy
from the JSON answer's fields (as the stream's binary answers were before they were written
from the result).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import orjson
import pytest

from app.api.schemas.stream import (
    StreamMessageError,
    binary_ik_answer,
    parse_binary,
)

Q_UR5 = [0.3, -1.1, 1.4, -0.6, 1.2, 0.4]


def _floats(rng: np.random.Generator, n: int) -> np.ndarray:
    """n float64 of every kind: ordinary, tiny, huge, ±0, subnormal; NaN and inf aside."""
    pool = np.concatenate(
        [
            rng.normal(size=n),
            rng.normal(size=n) * 10.0 ** rng.integers(-300, 300, n),
            [0.0, -0.0, 5e-324, -5e-324, 1.7976931348623157e308],
        ]
    )
    return rng.choice(pool, n)


def test_binary_frames_decode_as_numpy_reads_them() -> None:
    """fk/jacobian/ik frames of random floats: the decoded id and payload are the floats
    NumPy reads from the same bytes, bit for bit."""
    rng = np.random.default_rng(5)
    for _ in range(300):
        op = int(rng.integers(1, 4))
        n = 7 if op == 3 else 6
        values = np.concatenate([[float(op)], _floats(rng, n + 1)])
        data = values.astype("<f8").tobytes()
        reference = np.frombuffer(data, "<f8")
        try:
            message = parse_binary(data, "ur5", "/robots/ur5/stream")
        except StreamMessageError as exc:  # fk/jacobian joint values beyond their bound
            assert op != 3 and exc.problem["field"].startswith("q."), exc.problem
            continue
        assert np.array([message.msg_id]).tobytes() == reference[1:2].tobytes()
        payload = message.pose if op == 3 else message.body.q  # type: ignore[union-attr]
        assert np.array(payload, "<f8").tobytes() == reference[2:].tobytes()


def _documented_ik_answer(msg_id: float, out: dict) -> bytes:
    """docs/stream.md's binary ik answer of the JSON answer ``out``: ``[3, id, success,
    q..., position_error, orientation_error]`` little-endian float64 (NumPy's encoding)."""
    body = [float(out["success"]), *out["q"], out["position_error"], out["orientation_error"]]
    return np.array([3.0, msg_id, *body], dtype="<f8").tobytes()


def test_the_binary_ik_answer_is_the_json_answers_floats() -> None:
    """Written from the result, the answer is byte for byte the documented layout of the JSON
    answer's fields (random results of 6 and 7 joints, success and failure)."""
    rng = np.random.default_rng(11)
    for k in range(500):
        n = 6 + k % 2
        res = SimpleNamespace(
            success=bool(rng.integers(0, 2)),
            q=_floats(rng, n),
            position_error=float(_floats(rng, 1)[0]),
            orientation_error=float(_floats(rng, 1)[0]),
        )
        msg_id = float(_floats(rng, 1)[0])
        out = {
            "success": res.success,
            "q": res.q.tolist(),
            "position_error": res.position_error,
            "orientation_error": res.orientation_error,
        }
        assert binary_ik_answer(msg_id, res) == _documented_ik_answer(msg_id, out)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("frame", "field"),
    [
        ([3.0, 1.0, 0.4, 0.1, 0.3, 0.0, 0.0, 0.0], "target"),  # 6 floats, not 7
        ([3.0, 1.0, 0.4, 0.1, 0.3, 0.0, 0.0, 0.0, 1.0, 0.0], "target"),  # 8
        ([3.0, 1.0, np.nan, 0.1, 0.3, 0.0, 0.0, 0.0, 1.0], "target.position.0"),
        ([3.0, 1.0, 0.4, 0.1, 1e9, 0.0, 0.0, 0.0, 1.0], "target.position.2"),
        ([3.0, 1.0, 0.4, 0.1, 0.3, 0.0, 0.0, 0.0, 2.0], "target.orientation"),
        ([3.0, 1.0, 0.4, 0.1, 0.3, 0.0, np.inf, 0.0, 1.0], "target.orientation"),
    ],
)
def test_a_bad_binary_ik_frame_gets_an_error_naming_the_field(client, frame, field) -> None:
    """The error answer (JSON text, the id echoed) names the field; the socket stays usable
    and the next good frame is answered."""
    with client.websocket_connect("/robots/ur5/stream") as ws:
        ws.send_text(orjson.dumps({"id": 0, "op": "fk", "q": Q_UR5}).decode())
        pose = ws.receive_json()["poses"]["tool0"]
        ws.send_bytes(np.array(frame, "<f8").tobytes())
        err = ws.receive_json()
        assert (err["id"], err["op"], err["error"]["status"]) == (1.0, "ik", 422), err
        assert err["error"]["field"] == field, err
        assert err["error"]["instance"] == "/robots/ur5/ik"
        good = [3.0, 2.0, *pose["position"], *pose["orientation"]]
        ws.send_bytes(np.array(good, "<f8").tobytes())
        answer = np.frombuffer(ws.receive_bytes(), "<f8")
        assert answer[:3].tolist() == [3.0, 2.0, 1.0]


@pytest.mark.parametrize(
    ("code", "msg_id", "field"),
    [(3.0, np.nan, "id"), (3.0, np.inf, "id"), (3.0, -np.inf, "id"), (5.0, 1.0, "op")],
)
def test_a_bad_nine_float_frame_is_refused(code, msg_id, field) -> None:
    """Frames of 9 floats (the size of an ik frame) with an id JSON cannot echo, or an
    unknown op code: the error names ``id`` or ``op``."""
    data = np.array([code, msg_id, 0.4, 0.1, 0.3, 0.0, 0.0, 0.0, 1.0], "<f8").tobytes()
    with pytest.raises(StreamMessageError) as exc:
        parse_binary(data, "ur5", "/robots/ur5/stream")
    assert exc.value.problem["field"] == field, exc.value.problem
    assert exc.value.problem["status"] == 422


def test_a_seven_joint_fk_frame_is_an_fk_frame() -> None:
    """9 floats with op code 1 (a 7-joint arm's fk frame) is fk with its q, not an ik frame."""
    q = [0.1, -0.2, 0.3, -1.4, 0.5, 1.6, 0.7]
    message = parse_binary(np.array([1.0, 4.0, *q], "<f8").tobytes(), "panda", "/s")
    assert (message.op, message.msg_id, message.pose) == ("fk", 4.0, None)
    assert message.body.q == q  # type: ignore[union-attr]
