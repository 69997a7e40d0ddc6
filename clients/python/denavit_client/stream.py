"""The WebSocket stream ``/robots/{robot_id}/stream``, synchronous (hand-written: the
OpenAPI document has no WebSockets, so the generator has nothing to generate).

One socket serves one robot and answers FK, Jacobian and IK requests with the bodies and
answers of the HTTP routes, in order (docs/stream.md). :class:`Stream` sends the generated
request models and returns the generated answer models; binary frames (float64 arrays) are
:meth:`Stream.fk_pose` and :meth:`Stream.ik_step`. An IK without a seed starts from the last
successful IK solution on the socket.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from websockets.sync.client import ClientConnection
from websockets.sync.client import connect as ws_connect

from .models.fk_request import FKRequest
from .models.fk_response import FKResponse
from .models.ik_request import IKRequest
from .models.ik_response import IKResponse
from .models.jacobian_request import JacobianRequest
from .models.jacobian_response import JacobianResponse
from .models.problem import Problem

#: Op codes of binary frames.
FK, JACOBIAN, IK = 1.0, 2.0, 3.0


class StreamError(Exception):
    """An error answer: the HTTP route's problem body (``problem.status``, ``.field``...)."""

    def __init__(self, problem: Problem) -> None:
        super().__init__(f"{problem.status}: {problem.detail}")
        self.problem = problem


class Stream:
    """One open stream socket (see :func:`open_stream`)."""

    def __init__(self, ws: ClientConnection) -> None:
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
        target = np.concatenate([np.asarray(position, np.float64), orientation])
        values = self._binary(IK, target)
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
    # The service offers no compression: do not ask for it.
    with ws_connect(url, compression=None, additional_headers=headers) as ws:
        yield Stream(ws)
