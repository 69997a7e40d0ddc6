"""Pieces every router shares: number types, configurations, poses, fast JSON responses."""

from __future__ import annotations

import asyncio
import contextvars
import functools
import json
import math
import os
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Annotated, Any, TypeVar

import numpy as np
import orjson
from fastapi import Path, Request
from fastapi.exceptions import RequestValidationError
from pydantic import AfterValidator, BaseModel, ConfigDict, Field, Strict, ValidationError
from starlette.concurrency import run_in_threadpool
from starlette.exceptions import HTTPException
from starlette.responses import Response

from app.api.errors import NESTED_TOO_DEEPLY, MalformedBodyError
from app.kinematics.errors import Cancelled, InvalidInputError
from app.kinematics.models import MAX_JOINT_VALUE, MAX_POSITION, RobotModel
from app.kinematics.text import SURROGATE_REASON, find_surrogate, has_surrogate
from app.registry import Registry

#: A finite JSON number (ints accepted; strings, booleans, NaN and ±Infinity rejected).
Finite = Annotated[float, Strict(), Field(allow_inf_nan=False)]
Vec3 = Annotated[list[Finite], Field(min_length=3, max_length=3)]
Quat = Annotated[list[Finite], Field(min_length=4, max_length=4)]
Vec4 = Annotated[list[Finite], Field(min_length=4, max_length=4)]
Matrix4 = Annotated[list[Vec4], Field(min_length=4, max_length=4)]
# Response twins of the above (plain floats: the service's own output). Same fixed lengths
# as the request types, so a generated client can pass an answer's pose back in a request.
Vec3Out = Annotated[list[float], Field(min_length=3, max_length=3)]
QuatOut = Annotated[list[float], Field(min_length=4, max_length=4)]
Vec4Out = Annotated[list[float], Field(min_length=4, max_length=4)]
Matrix4Out = Annotated[list[Vec4Out], Field(min_length=4, max_length=4)]
#: A joint value (rad or m) within ±MAX_JOINT_VALUE, the one bound of every configuration
#: (:data:`app.kinematics.models.MAX_JOINT_VALUE`; fast paths check it with
#: :func:`~app.kinematics.models.check_joint_values`).
JointValue = Annotated[Finite, Field(ge=-MAX_JOINT_VALUE, le=MAX_JOINT_VALUE)]
#: A target coordinate (m) within ±MAX_POSITION.
Coordinate = Annotated[Finite, Field(ge=-MAX_POSITION, le=MAX_POSITION)]
Position3 = Annotated[list[Coordinate], Field(min_length=3, max_length=3)]


def _valid_text(value: str) -> str:
    if has_surrogate(value):
        raise ValueError(SURROGATE_REASON)
    return value


#: A string of valid Unicode: every text field that is stored or echoed uses it (a lone
#: UTF-16 surrogate, ``"\ud800"`` in JSON, cannot be encoded in a response or a file).
Text = Annotated[str, AfterValidator(_valid_text)]


T = TypeVar("T")
S = TypeVar("S", bound=BaseModel)

RobotId = Annotated[str, Path(description="Robot id, as listed by GET /robots.", max_length=64)]


class Schema(BaseModel):
    """Base of request models: unknown fields are errors, numbers must be finite."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)


class ConfigurationIn(Schema):
    """A configuration: ``q`` in joint order, or a ``joint_positions`` map (not both)."""

    q: list[JointValue] | None = Field(
        None,
        description="One value per actuated joint, in the order of GET /robots/{id} "
        "(rad for revolute and continuous joints, m for prismatic ones).",
        max_length=1024,
    )
    joint_positions: dict[str, JointValue] | None = Field(
        None,
        description="Joint name → value (rad or m); joints not given take their neutral value.",
        max_length=1024,
    )

    def config(self, robot: RobotModel) -> np.ndarray:
        """The validated wire configuration for ``robot``."""
        return robot.configuration(self.q, self.joint_positions)


class Pose(BaseModel):
    """A frame's placement in the robot's root (world) frame."""

    position: Vec3Out = Field(description="[x, y, z] in metres.")
    orientation: QuatOut = Field(description="Unit quaternion [x, y, z, w], w ≥ 0.")
    rpy: Vec3Out = Field(description="[roll, pitch, yaw] in rad, R = Rz(yaw)·Ry(pitch)·Rx(roll).")
    matrix: Matrix4Out = Field(description="4×4 homogeneous transform (metres).")


def pose_json(T: np.ndarray) -> dict[str, Any]:
    """Wire form of a 4×4 placement.

    One pose at a time, the rotation conversions run on Python floats
    (:func:`quaternion_rpy`): NumPy's per-call overhead made the vectorised ones cost
    ~60 µs here, a third of a single-pose FK request.
    """
    M = T.tolist()
    quat, rpy = quaternion_rpy(M)
    return {
        "position": [M[0][3], M[1][3], M[2][3]],
        "orientation": quat,
        "rpy": rpy,
        "matrix": M,
    }


def quaternion_rpy(M: list[list[float]]) -> tuple[list[float], list[float]]:
    """Quaternion [x, y, z, w] (w ≥ 0) and rpy of the rotation in ``M``'s top-left 3×3.

    The scalar twins of :func:`~app.kinematics.rotations.matrix_to_quaternion` (Shepperd's
    method, same branch choice and normalisation) and
    :func:`~app.kinematics.rotations.matrix_to_rpy` (R = Rz(yaw)·Ry(pitch)·Rx(roll); at the
    gimbal lock roll = 0), for one matrix given as nested lists.
    """
    (m00, m01, m02), (m10, m11, m12), (m20, m21, m22) = (row[:3] for row in M[:3])
    cand = (
        1.0 + m00 + m11 + m22,
        1.0 + m00 - m11 - m22,
        1.0 - m00 + m11 - m22,
        1.0 - m00 - m11 + m22,
    )
    k = max(range(4), key=cand.__getitem__)  # first maximum, like np.argmax
    s = 2.0 * math.sqrt(cand[k])
    if k == 0:
        q = [(m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s]
    elif k == 1:
        q = [0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s]
    elif k == 2:
        q = [(m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s]
    else:
        q = [(m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s]
    norm = math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3])
    q = [v / norm for v in q] if q[3] / norm >= 0.0 else [-v / norm for v in q]
    h = math.hypot(m00, m10)
    pitch = math.atan2(-m20, h)
    if h < 1e-12:
        roll, yaw = 0.0, math.atan2(-m01, m11)
    else:
        roll, yaw = math.atan2(m21, m22), math.atan2(m10, m00)
    return q, [roll, pitch, yaw]


class ORJSONResponse(Response):
    """JSON via orjson (NumPy arrays serialised natively)."""

    media_type = "application/json"

    def render(self, content: Any) -> bytes:
        return orjson.dumps(content, option=orjson.OPT_SERIALIZE_NUMPY, default=_fallback)


def _fallback(obj: Any) -> Any:
    if isinstance(obj, np.ndarray):  # non-contiguous views
        return np.ascontiguousarray(obj)
    if isinstance(obj, np.generic):
        return obj.item()
    raise TypeError(f"cannot serialise {type(obj).__name__}")


async def load_robot(reg: Registry, robot_id: str) -> RobotModel:
    """The robot's model; a first load (URDF parsing) runs off the event loop."""
    robot = reg.cached(robot_id)
    if robot is None:
        robot = await run_in_threadpool(reg.get, robot_id)
    return robot


_POOL: ThreadPoolExecutor | None = None


def pool() -> ThreadPoolExecutor:
    """The bounded pool for long work (IK with big budgets, batches, reachability).

    One worker per core: Pinocchio work holds the GIL for short stretches only, and the
    event loop stays free for sub-millisecond endpoints and /health.
    """
    global _POOL
    if _POOL is None:
        _POOL = ThreadPoolExecutor(max_workers=os.cpu_count() or 2, thread_name_prefix="work")
    return _POOL


async def offload(fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
    """Run ``fn(*args, **kwargs)`` in the bounded pool and await its result."""
    loop = asyncio.get_running_loop()
    context = contextvars.copy_context()  # the request id follows into the pool's logs
    return await loop.run_in_executor(pool(), context.run, functools.partial(fn, *args, **kwargs))


#: How often (s) a request whose work runs in the pool checks that its client is still there.
DISCONNECT_POLL_S = 0.1


#: Status logged for a request whose client went away (nginx's "client closed request").
CLIENT_CLOSED = 499


class ClientDisconnected(HTTPException):
    """The client of a request went away while its work ran; the work was cancelled.

    An HTTP exception, so the app's handler logs and counts it as a 499 problem answer
    (which reaches nobody) rather than an internal error.
    """

    def __init__(self) -> None:
        super().__init__(CLIENT_CLOSED, "the client closed the request; its work was cancelled")


async def offload_cancellable(
    request: Request, fn: Callable[..., T], *args: Any, **kwargs: Any
) -> T:
    """:func:`offload` for long work that gives up when its client disconnects.

    ``fn`` is called with ``cancel=`` a ``threading.Event`` it must check between units of
    work (and raise :class:`~app.kinematics.errors.Cancelled` once set). While it runs (or
    waits for a free worker), the request's ASGI channel is polled every
    :data:`DISCONNECT_POLL_S`; on ``http.disconnect``, or if this coroutine is itself
    cancelled, the event is set, so an abandoned batch frees its pool worker within one
    solver iteration instead of running to the end of its budget for nobody.

    Raises :class:`ClientDisconnected` when the work stopped because the client left (the
    answer would reach no one).
    """
    cancel = threading.Event()
    work = asyncio.ensure_future(offload(fn, *args, cancel=cancel, **kwargs))
    watcher = asyncio.ensure_future(_watch_disconnect(request, cancel))
    try:
        return await work
    except Cancelled:
        raise ClientDisconnected() from None
    except BaseException:
        cancel.set()  # e.g. this task cancelled at shutdown: stop the worker too
        raise
    finally:
        watcher.cancel()


async def _watch_disconnect(request: Request, cancel: threading.Event) -> None:
    """Set ``cancel`` once the request's client has disconnected."""
    while not cancel.is_set():
        if await request.is_disconnected():
            cancel.set()
            return
        await asyncio.sleep(DISCONNECT_POLL_S)


def parse_json(raw: bytes) -> Any:
    """Decode a JSON body: orjson, or the standard library for NaN/Infinity tokens.

    The standard library accepts NaN and ±Infinity (not JSON, but what many clients send);
    the request models then reject them with the field's name. It also decodes a lone
    UTF-16 surrogate escape (``"\ud800"``), which orjson refuses: that is a 422 naming the
    field holding it. Anything else that does not decode, including arrays and objects
    nested deeper than orjson's 1024 levels (where the standard library would exceed the
    recursion limit), raises :class:`MalformedBodyError` (a 400 naming the body).
    """
    try:
        return orjson.loads(raw)
    except orjson.JSONDecodeError:
        try:
            obj = json.loads(raw)
        except RecursionError:  # nested deeper than the interpreter's recursion limit
            raise MalformedBodyError(NESTED_TOO_DEEPLY) from None
        except (ValueError, UnicodeDecodeError) as exc:
            raise MalformedBodyError(f"body: malformed JSON ({exc})") from None
        where = find_surrogate(obj)
        if where is not None:
            raise InvalidInputError(SURROGATE_REASON, where) from None
        return obj


def validate_body(model: type[S], obj: Any) -> S:
    """Validate a decoded body against a request model, errors as FastAPI's (HTTP 422)."""
    try:
        return model.model_validate(obj)
    except ValidationError as exc:
        raise RequestValidationError(
            [{**e, "loc": ("body", *e["loc"])} for e in exc.errors(include_url=False)]
        ) from None


def finite_matrix(obj: Any, width: int | None = None) -> np.ndarray | None:
    """A list of lists of JSON numbers as an (N, width) float array, or ``None``.

    The fast path for big batches: ``None`` whenever anything is off (ragged rows,
    non-numbers, booleans, non-finite values, wrong width), so the caller can fall back to
    full validation, which names the offending element.
    """
    if not isinstance(obj, list) or not obj:
        return None
    try:
        arr = np.array(obj)
    except (ValueError, TypeError, OverflowError):
        return None
    if arr.ndim != 2 or arr.dtype.kind not in "if" or (width is not None and arr.shape[1] != width):
        return None
    arr = arr.astype(float, copy=False)
    if not np.isfinite(arr).all():
        return None
    return arr


def body_schema(model: type[BaseModel]) -> dict[str, Any]:
    """``openapi_extra`` documenting a body that a route decodes itself (fast paths)."""
    EXTRA_SCHEMAS.append(model)
    ref = {"$ref": f"#/components/schemas/{model.__name__}"}
    return {"requestBody": {"required": True, "content": {"application/json": {"schema": ref}}}}


#: Request models of routes that decode their own bodies; added to the OpenAPI components.
EXTRA_SCHEMAS: list[type[BaseModel]] = []
