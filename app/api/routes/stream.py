"""``WS /robots/{robot_id}/stream``: FK, Jacobian, IK and dynamics requests on one WebSocket.

The protocol is in docs/stream.md; messages are parsed in :mod:`app.api.schemas.stream`.
Answers are built by the HTTP routes' own functions (:func:`~app.api.answers.fk_answer`,
:func:`~app.api.answers.jacobian_answer`, :func:`~app.api.ik_plan.prepare_ik`,
:func:`~app.api.ik_answers.ik_answer` and
:func:`~app.api.dynamics_answers.dynamics_answer`), with the same budget rules
(``ik_max_timeout_ms``; an IK budget above 5 ms or collision checks run in the work pool),
and errors carry the HTTP route's problem body.

Answers go out in order. A reader task reads the socket while fewer than
``stream_max_in_flight`` messages are read but unanswered; at that many it stops reading
(uvicorn then stops reading the TCP socket), so a client that does not read its answers
holds at most that many messages in the server.
"""

from __future__ import annotations

import asyncio
import contextlib
import hmac
import logging
import threading
from collections.abc import Callable
from typing import Any

import numpy as np
from fastapi import APIRouter, WebSocket
from starlette.responses import Response
from starlette.websockets import WebSocketDisconnect, WebSocketState

from app.api.answers import fk_answer, jacobian_answer
from app.api.deps import load_robot
from app.api.dynamics_answers import dynamics_answer
from app.api.errors import json_bytes, kinematics_problem, problem, problem_body
from app.api.ik_answers import ik_answer
from app.api.ik_plan import IKPlan, plan_ik, prepare_ik
from app.api.limits import check_budget
from app.api.offload import offload
from app.api.responses import dumps
from app.api.schemas.ik import IKRequest
from app.api.schemas.stream import (
    BINARY_IK_BYTES,
    Message,
    StreamMessageError,
    binary_answer,
    binary_ik_answer,
    parse_binary,
    parse_text,
    route_path,
)
from app.kinematics import ik
from app.kinematics.errors import Cancelled, KinematicsError
from app.kinematics.models import RobotModel
from app.kinematics.placement import pose_se3
from app.operations.settings import Settings

log = logging.getLogger("denavit")

router = APIRouter(tags=["stream"])

#: Close codes (RFC 6455 and the application range); see docs/stream.md.
POLICY_VIOLATION = 1008  # authorization missing or wrong
MESSAGE_TOO_BIG = 1009
#: A robot that cannot be loaded: 4000 + the HTTP status (4404: unknown robot id).
ROBOT_ERROR_BASE = 4000
#: Seconds a socket that must authenticate by its first message may take to send it.
AUTH_TIMEOUT_S = 10.0
#: Largest first message of a socket that must authenticate by it ({"token": ...}, an id):
#: a longer one is refused unread, so an unauthenticated client cannot make the server
#: parse a message of up to the stream's limit (1 MiB of ``[{},{},...]`` is ~30 MB of
#: Python objects).
AUTH_MESSAGE_MAX_BYTES = 64 * 1024
#: The options of binary ik frames before any JSON ik message: an ik message that sets none
#: (the HTTP defaults; its placeholder target is never read).
DEFAULT_IK = IKRequest.model_validate({"target": {"position": [0.0, 0.0, 0.0]}})
AUTH_HELP = (
    "authorization: this stream needs 'Authorization: Bearer <token>' on the upgrade "
    'request or {"token": "<token>"} as its first message'
)


class _Close(Exception):
    """Close the socket with ``code`` and ``reason`` (after the answers before it)."""

    def __init__(self, code: int, reason: str) -> None:
        super().__init__(reason)
        self.code, self.reason = code, reason


def _reason(text: str) -> str:
    """A close reason within the protocol's 123 bytes."""
    return text.encode()[:123].decode(errors="ignore")


@router.get("/robots/{robot_id}/stream", include_in_schema=False)
async def stream_over_http(robot_id: str) -> Response:
    """A plain HTTP request to the stream: 426, naming the WebSocket upgrade it needs."""
    return problem(
        426,
        "this is a WebSocket endpoint: connect with ws:// (an HTTP/1.1 Upgrade request); "
        "see docs/stream.md",
        kind="upgrade-required",
        instance=f"/robots/{robot_id}/stream",
        headers={"Upgrade": "websocket", "Connection": "Upgrade"},
    )


@router.websocket("/robots/{robot_id}/stream")
async def robot_stream(websocket: WebSocket, robot_id: str) -> None:
    """FK, Jacobian, IK and dynamics of one robot on a WebSocket (docs/stream.md).

    Notes
    -----
    A message over ``stream_max_message_bytes`` (1 MiB by default) closes the socket with
    code 1009. Served by ``python -m app`` (``make run``, the image), uvicorn's WebSocket
    layer has that limit as ``ws_max_size``: it closes the socket with 1009 (reason ``frame
    with N bytes exceeds limit of L bytes``) as soon as a frame header declares more than
    what is left of the limit for its message, before the payload is read, and answers to
    messages still in flight are dropped. Where the server has a larger limit (another
    server, the in-process test client), the size check below closes with 1009 (reason ``a
    message of N bytes exceeds L``) after the answers to the earlier messages. Compression
    (permessage-deflate) is not offered: frames with the RSV1 bit set close with 1002. An
    unauthenticated socket's first message over :data:`AUTH_MESSAGE_MAX_BYTES` closes with
    1008 unread.
    """
    await websocket.accept()
    session = _Session(websocket, robot_id)
    try:
        await session.run()
    except _Close as close:
        if websocket.client_state == WebSocketState.CONNECTED:
            with contextlib.suppress(RuntimeError, OSError, WebSocketDisconnect):
                await websocket.close(close.code, _reason(close.reason))
    except (WebSocketDisconnect, Cancelled, OSError):
        pass  # the client left: nothing to answer
    finally:
        session.cancel.set()


class _Session:
    """One socket: its robot, the last IK solution (the next IK's default seed), the
    options of binary IK frames, and the in-flight bound."""

    def __init__(self, websocket: WebSocket, robot_id: str) -> None:
        self.ws, self.robot_id = websocket, robot_id
        self.settings: Settings = websocket.app.state.settings
        self.path = f"/robots/{robot_id}/stream"
        self.robot: RobotModel | None = None
        self.last_q: np.ndarray | None = None
        self.ik_body: IKRequest = DEFAULT_IK  # the last JSON ik message: binary frames' options
        self.ik_plan: IKPlan | None = None  # its plan (None with collision checks)
        self.cancel = threading.Event()  # set when the socket ends: stops pooled IK
        #: The answering task waits for the inbox (every earlier answer is sent).
        self.idle = False
        #: The last plan found to run on the loop with its chain built (a robot model's
        #: chains are never dropped, so it stays so): spares the check on every frame.
        self.ready_plan: IKPlan | None = None

    # -------------------------------------------------------------------- set-up
    async def run(self) -> None:
        pending = await self._authorize()
        try:
            self.robot = await load_robot(self.ws.app.state.registry, self.robot_id)
        except KinematicsError as exc:
            problem = kinematics_problem(exc, self.path)
            raise _Close(ROBOT_ERROR_BASE + problem["status"], problem["detail"]) from None
        if pending is not None:
            await self._send(pending)
        await self._serve()

    async def _authorize(self) -> str | None:
        """Check the token (header or first message); the first message's answer, if any."""
        expected = self.settings.api_token
        if not expected:
            return None
        header = self.ws.headers.get("authorization", "")
        if header:
            scheme, _, token = header.partition(" ")
            if scheme.lower() != "bearer" or not token:
                raise _Close(POLICY_VIOLATION, AUTH_HELP)
            self._check_token(token.strip())
            return None
        try:
            first = await asyncio.wait_for(self.ws.receive(), AUTH_TIMEOUT_S)
        except TimeoutError:
            detail = f"{AUTH_HELP} (none within {AUTH_TIMEOUT_S:g} s)"
            raise _Close(POLICY_VIOLATION, detail) from None
        if first["type"] == "websocket.disconnect":
            raise WebSocketDisconnect(first.get("code", 1000))
        if (size := _size(first)) > AUTH_MESSAGE_MAX_BYTES:
            detail = f"authorization: a token message of {size} bytes exceeds "
            raise _Close(POLICY_VIOLATION, detail + str(AUTH_MESSAGE_MAX_BYTES))
        text = first.get("text")
        try:
            message = None if text is None else parse_text(text, self.robot_id, self.path)
        except StreamMessageError:
            message = None
        if message is None or message.token is None:
            raise _Close(POLICY_VIOLATION, AUTH_HELP)
        return self._auth_answer(message)

    def _check_token(self, token: str) -> None:
        expected = self.settings.api_token
        if expected and not hmac.compare_digest(token.encode(), expected.encode()):
            raise _Close(POLICY_VIOLATION, "authorization: the token is not valid")

    def _auth_answer(self, message: Message) -> str:
        self._check_token(message.token or "")
        return dumps({"id": message.msg_id, "op": "auth", "authenticated": True}).decode()

    # ------------------------------------------------------------------ the loop
    async def _serve(self) -> None:
        """Read (bounded by the in-flight limit) in one task, answer in order here."""
        slots = asyncio.Semaphore(self.settings.stream_max_in_flight)
        inbox: asyncio.Queue[dict[str, Any] | BaseException] = asyncio.Queue()
        reader = asyncio.ensure_future(self._read(slots, inbox))
        try:
            while True:
                self.idle = True
                item = await inbox.get()
                self.idle = False
                if isinstance(item, BaseException):
                    raise item
                await self._send(await self._answer(item))
                slots.release()
        finally:
            reader.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await reader

    async def _read(self, slots: asyncio.Semaphore, inbox: asyncio.Queue) -> None:
        """Read messages while a slot is free; a disconnect or a message over the size limit
        goes into the inbox as the exception that ends the loop (after the earlier answers).

        A binary frame of 9 floats (an ik frame, or a 7-joint arm's fk frame) that comes
        while the answering task waits with every earlier answer sent, once the socket's ik
        plan runs on the loop and its chain is built, is answered and sent here: the hop to
        that task (~10 µs of a servo loop's round trip) is saved, and the order is the same
        (nothing is before it). Its answer awaits nothing but the send, so the reader is
        never held by a solve in the pool."""
        limit = self.settings.stream_max_message_bytes
        try:
            while True:
                await slots.acquire()
                message = await self.ws.receive()
                if message["type"] == "websocket.disconnect":
                    self.cancel.set()
                    inbox.put_nowait(WebSocketDisconnect(message.get("code", 1000)))
                    return
                size = _size(message)
                if size > limit:
                    inbox.put_nowait(
                        _Close(MESSAGE_TOO_BIG, f"a message of {size} bytes exceeds {limit}")
                    )
                    return
                if self.idle and inbox.empty() and self._answered_inline(message):
                    try:
                        await self._send(await self._answer(message))
                    except (_Close, Cancelled, WebSocketDisconnect, OSError) as exc:
                        inbox.put_nowait(exc)  # ends the loop as the answering task's would
                        return
                    slots.release()
                    continue
                inbox.put_nowait(message)
                # Let the answering task, just woken, run before this one reads again: the
                # answer is then computed and sent before the read is re-armed (Starlette's
                # and uvicorn's receive, ~10 µs with the caches cold), not after.
                await asyncio.sleep(0)
        except WebSocketDisconnect as exc:
            inbox.put_nowait(exc)
        except Exception:  # a bug: logged with its traceback, the socket closed with 1011
            log.exception("stream reader on %s crashed", self.path)
            inbox.put_nowait(_Close(1011, ""))

    def _answered_inline(self, message: dict[str, Any]) -> bool:
        """Whether ``message`` is a binary frame of 9 floats whose answer awaits nothing: its
        ik plan (the socket's) runs on the loop and its chain is built (fk needs neither)."""
        raw = message.get("bytes")
        if raw is None or len(raw) != BINARY_IK_BYTES:
            return False
        plan = self.ik_plan
        return plan is not None and self._on_loop(plan)

    def _on_loop(self, plan: IKPlan) -> bool:
        """Whether ``plan`` runs on the loop: an inline plan whose chain is built (its first
        build, the restart table, runs in the pool, never on the loop)."""
        if plan is self.ready_plan:
            return True
        if plan.inline and ik.chain_ready(self.robot, plan.options):  # type: ignore[arg-type]
            self.ready_plan = plan
            return True
        return False

    async def _send(self, answer: str | bytes) -> None:
        if isinstance(answer, bytes):
            await self.ws.send_bytes(answer)
        else:
            await self.ws.send_text(answer)

    # --------------------------------------------------------------- one message
    async def _answer(self, frame: dict[str, Any]) -> str | bytes:
        """The answer to one frame: a text or binary answer, or a text error message."""
        message: Message | None = None
        try:
            if frame.get("text") is not None:
                message = parse_text(frame["text"], self.robot_id, self.path)
            else:
                raw = frame.get("bytes") or b""
                message = parse_binary(raw, self.robot_id, self.path)
            if message.token is not None:
                return self._auth_answer(message)
            if message.pose is not None:  # a binary ik frame: no JSON answer is built
                res = await self._binary_ik(message.pose)
                return binary_ik_answer(message.msg_id, res)
            out = await self._compute(message)
            if message.binary:
                return binary_answer(message.op, message.msg_id, out)
            return dumps({"id": message.msg_id, "op": message.op, **out}).decode()
        except StreamMessageError as exc:
            return _error(exc.msg_id, exc.op, exc.problem)
        except KinematicsError as exc:
            assert message is not None
            problem = kinematics_problem(exc, route_path(self.robot_id, message.op))
            return _error(message.msg_id, message.op, problem)
        except (_Close, Cancelled, WebSocketDisconnect):
            raise
        except Exception:  # a bug: logged, answered as the HTTP guard's 500
            log.exception("unhandled error on %s", self.path)
            msg_id = None if message is None else message.msg_id
            op = None if message is None else message.op
            return _error(msg_id, op, problem_body(500, "internal error", instance=self.path))

    async def _compute(self, message: Message) -> dict[str, Any]:
        """The HTTP answer body of a validated message (the same functions as the routes)."""
        robot, body = self.robot, message.body
        assert robot is not None
        if message.op == "fk":
            return fk_answer(robot, body)  # type: ignore[arg-type]
        if message.op == "jacobian":
            return jacobian_answer(robot, body)  # type: ignore[arg-type]
        if message.op == "dynamics":
            return dynamics_answer(robot, body)  # type: ignore[arg-type]
        check_budget(self.settings, body.timeout_ms)  # type: ignore[union-attr]
        plan, solve = prepare_ik(self.ws, robot, body, self.last_q)  # type: ignore[arg-type]
        self.ik_body = body  # type: ignore[assignment]
        self.ik_plan = plan if plan.collisions is None else None
        return ik_answer(robot, plan.options, await self._solve(plan, solve))

    async def _binary_ik(self, pose: list[float]) -> ik.IKResult:
        """A binary ik frame's result: its target with the last JSON ik message's options,
        seeded by the socket's last solution; no branch labels (its answer has none)."""
        plan, robot = self._binary_plan(), self.robot
        assert robot is not None
        target = pose_se3(pose, "target")  # checked as a JSON target is (any mode: both given)
        return await self._solve(plan, plan.call(robot, target, self.last_q, annotate=False))

    async def _solve(self, plan: IKPlan, solve: Callable[..., ik.IKResult]) -> ik.IKResult:
        """Run ``solve`` on the loop when the plan allows it (and the chain is built: its
        first build, the restart table, runs in the pool, never on the loop), else in the
        pool; a success seeds the socket's next IK."""
        if self._on_loop(plan):
            res = solve()
        else:
            res = await offload(self.ws, solve, cancel=self.cancel)
        if res.success:
            self.last_q = res.q
        return res

    def _binary_plan(self) -> IKPlan:
        """The plan of binary ik frames: the last JSON ik message's (the HTTP defaults',
        made once, before one); with collision checks it is made anew each frame, so a
        changed scene is seen as by a JSON message."""
        plan = self.ik_plan
        if plan is None:
            check_budget(self.settings, self.ik_body.timeout_ms)
            plan = plan_ik(self.ws, self.robot, self.ik_body)  # type: ignore[arg-type]
            if plan.collisions is None:
                self.ik_plan = plan
        return plan


def _size(message: dict[str, Any]) -> int:
    """Bytes of a received message (UTF-8 for text)."""
    text = message.get("text")
    if text is not None:
        return len(text) if text.isascii() else len(text.encode())
    return len(message.get("bytes") or b"")


def _error(msg_id: Any, op: str | None, problem: dict[str, Any]) -> str:
    return json_bytes({"id": msg_id, "op": op, "error": problem}).decode()
