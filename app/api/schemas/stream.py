"""The messages of ``WS /robots/{robot_id}/stream`` (docs/stream.md): parsing and framing.

Text messages are JSON objects ``{"id": <any JSON scalar>, "op": "fk" | "jacobian" | "ik"
| "dynamics", ...}`` whose other members are exactly the body of the HTTP endpoint of
``op``, validated by the same request model; answers are ``{"id", "op", ...}`` plus the
HTTP answer's body, or ``{"id", "op", "error": <the HTTP route's problem body>}``.
``{"token": "..."}`` authenticates (answered with ``{"id", "op": "auth", "authenticated":
true}``).

Binary frames are little-endian float64 arrays: ``[op code, id, payload...]``
(:data:`OP_CODES`; see :func:`parse_binary` and :func:`binary_answer`).
"""

from __future__ import annotations

import json
import math
import struct
from dataclasses import dataclass
from typing import Any

import numpy as np
from pydantic import ValidationError

from app.api.errors import NESTED_TOO_DEEPLY, problem_body, validation_problem
from app.api.schemas.common import Schema
from app.api.schemas.dynamics import DynamicsRequest
from app.api.schemas.fk import FKRequest
from app.api.schemas.ik import IKRequest
from app.api.schemas.jacobian import JacobianRequest
from app.kinematics.ik import IKResult
from app.kinematics.text import printable

#: Each op: its HTTP request model (the message's body is validated by it).
OPS: dict[str, type[Schema]] = {
    "fk": FKRequest,
    "jacobian": JacobianRequest,
    "ik": IKRequest,
    "dynamics": DynamicsRequest,
}
#: The op codes of binary frames (the frame's first float); dynamics is a text op only.
OP_CODES: dict[str, int] = {"fk": 1, "jacobian": 2, "ik": 3}
_OP_OF_CODE = {float(code): op for op, code in OP_CODES.items()}
_OPS_TEXT = "fk, jacobian, ik or dynamics"
#: Floats of a binary IK target: position [x, y, z] (m), quaternion [x, y, z, w].
POSE_FLOATS = 7
LITTLE_F8 = np.dtype("<f8")
IK_CODE = float(OP_CODES["ik"])
#: A binary ik frame: [3, id, x, y, z, qx, qy, qz, qw].
_IK_FRAME = struct.Struct(f"<{2 + POSE_FLOATS}d")
BINARY_IK_BYTES = _IK_FRAME.size


class StreamMessageError(Exception):
    """A message that gets an error answer (the socket stays usable): its problem body."""

    def __init__(self, problem: dict[str, Any], msg_id: Any = None, op: str | None = None):
        super().__init__(problem["detail"])
        self.problem, self.msg_id, self.op = problem, msg_id, op


@dataclass
class Message:
    """A parsed request: the client's id, the op, its validated body (``None`` for a token
    message, whose ``token`` is set, and for a binary ik frame, whose ``pose`` is), and
    whether it came as a binary frame."""

    msg_id: Any
    op: str
    body: Schema | None
    binary: bool = False
    token: str | None = None
    #: A binary ik frame's target, [x, y, z, qx, qy, qz, qw] (its body is ``None``: the
    #: options are the socket's, see :meth:`app.api.routes.stream._Session._binary_plan`).
    pose: list[float] | None = None


def route_path(robot_id: str, op: str) -> str:
    """The HTTP path of ``op`` (the ``instance`` of its problem bodies)."""
    return f"/robots/{robot_id}/{op}"


def _invalid(field: str, reason: str, instance: str, msg_id: Any = None, op: str | None = None):
    return StreamMessageError(
        problem_body(
            422, f"{field}: {reason}", kind="invalid-input", field=field, instance=instance
        ),
        msg_id,
        op,
    )


def parse_text(text: str, robot_id: str, stream_path: str) -> Message:
    """A text message → :class:`Message`, or :class:`StreamMessageError`.

    JSON is decoded as the HTTP routes decode bodies (the standard library's parser), and the
    body validated by the op's request model, so errors name the same fields (``q.3``)."""
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        detail = f"message: malformed JSON ({exc.msg})"
        raise StreamMessageError(_malformed(detail, stream_path)) from None
    except RecursionError:
        detail = NESTED_TOO_DEEPLY.replace("body:", "message:", 1)
        raise StreamMessageError(_malformed(detail, stream_path)) from None
    if not isinstance(data, dict):
        raise _invalid("message", "must be a JSON object", stream_path)
    msg_id = data.pop("id", None)
    if isinstance(msg_id, dict | list) or (isinstance(msg_id, int) and abs(msg_id) >= 2**63):
        reason = "must be a JSON scalar (string, finite number within 64 bits, boolean or null)"
        raise _invalid("id", reason, stream_path)
    if isinstance(msg_id, float) and not math.isfinite(msg_id):  # 1e999, NaN, Infinity
        raise _invalid("id", f"must be a finite number: got {msg_id}", stream_path)
    if isinstance(msg_id, str):
        msg_id = printable(msg_id)  # echoed: a lone surrogate cannot be sent back
    op = data.pop("op", None)
    if op is None and "token" in data:
        token = data.pop("token")
        if not isinstance(token, str) or data:
            raise _invalid("token", 'a token message is {"token": "<token>"}', stream_path, msg_id)
        return Message(msg_id, "auth", None, token=token)
    if not isinstance(op, str) or op not in OPS:
        reason = "required" if op is None else f"unknown op {op!r}"
        raise _invalid("op", f"{reason}: {_OPS_TEXT}", stream_path, msg_id)
    return Message(msg_id, op, validate(op, data, robot_id, msg_id))


def validate(op: str, data: dict[str, Any], robot_id: str, msg_id: Any = None) -> Schema:
    """``data`` validated by ``op``'s request model (errors as the HTTP route's)."""
    try:
        return OPS[op].model_validate(data)
    except ValidationError as exc:
        problem = validation_problem(exc.errors(), route_path(robot_id, op))
        raise StreamMessageError(problem, msg_id, op) from None


def _malformed(detail: str, instance: str) -> dict[str, Any]:
    return problem_body(400, detail, kind="malformed-json", field="message", instance=instance)


def parse_binary(data: bytes, robot_id: str, stream_path: str) -> Message:
    """A binary frame → :class:`Message` (or :class:`StreamMessageError`).

    Layout, little-endian float64: ``[op code, id, payload]``; payload ``q`` (one value per
    joint) for fk and jacobian, the target ``[x, y, z, qx, qy, qz, qw]`` for ik (checked by
    the core when solved; its other options are those of the socket's last valid JSON ik
    message). The id must be finite: a NaN or infinite id is an error naming ``id`` (the
    JSON answers could not echo it)."""
    if len(data) == _IK_FRAME.size:  # the servo loop's frame: one unpack, no copies
        code, msg_id, *pose = _IK_FRAME.unpack(data)
        if code == IK_CODE and math.isfinite(msg_id):
            return Message(msg_id, "ik", None, binary=True, pose=pose)
    if len(data) % 8 or len(data) < 16:
        raise _invalid(
            "message",
            f"a binary frame is float64 values [op, id, ...]: got {len(data)} bytes",
            stream_path,
        )
    values = struct.unpack(f"<{len(data) >> 3}d", data)  # Python floats, bit for bit
    code, msg_id = values[0], values[1]
    if not math.isfinite(msg_id):  # NaN or ±inf: not echoable (JSON has no such number)
        raise _invalid("id", f"must be a finite number: got {msg_id}", stream_path)
    op = _OP_OF_CODE.get(code)
    if op is None:
        codes = ", ".join(f"{c} ({o})" for o, c in OP_CODES.items())
        raise _invalid("op", f"unknown op code {code:g}: {codes}", stream_path, msg_id)
    payload = list(values[2:])
    if op == "ik":
        if len(payload) != POSE_FLOATS:
            raise _invalid(
                "target",
                f"a binary ik frame holds 7 floats [x, y, z, qx, qy, qz, qw]: got {len(payload)}",
                route_path(robot_id, op),
                msg_id,
                op,
            )
        return Message(msg_id, op, None, binary=True, pose=payload)
    return Message(msg_id, op, validate(op, {"q": payload}, robot_id, msg_id), binary=True)


def binary_answer(op: str, msg_id: float, out: dict[str, Any]) -> bytes:
    """The binary answer of an fk or jacobian frame: ``[op code, id, ...]`` little-endian
    float64; fk: the first pose as ``[x, y, z, qx, qy, qz, qw]``; jacobian: the 6×n matrix
    row-major (ik frames: :func:`binary_ik_answer`)."""
    head = [float(OP_CODES[op]), msg_id]
    if op == "fk":
        pose = next(iter(out["poses"].values()))
        body = [*pose["position"], *pose["orientation"]]
    else:
        body = np.asarray(out["jacobian"], dtype=float).ravel().tolist()
    return np.array(head + body, dtype=LITTLE_F8).tobytes()


def binary_ik_answer(msg_id: float, res: IKResult) -> bytes:
    """A binary ik frame's answer straight from the solve's result ``res`` (no JSON answer
    built): ``[3, id, success (1 or 0), q (n values), position_error (m),
    orientation_error (rad)]`` little-endian float64."""
    q = res.q.tolist()
    return struct.pack(
        f"<{len(q) + 5}d",
        OP_CODES["ik"],
        msg_id,
        float(res.success),
        *q,
        res.position_error,
        res.orientation_error,
    )
