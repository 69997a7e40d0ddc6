"""The error guard (app.middleware.guard) at the ASGI level: a request task cancelled by the
server is answered 503 and stays cancelled; a bug is a 500 and the task ends normally."""

from __future__ import annotations

import asyncio
import logging

import orjson
from starlette.types import Message, Receive, Scope, Send

from app.middleware.guard import RETRY_AFTER_S, ErrorGuardMiddleware

SCOPE: Scope = {"type": "http", "method": "POST", "path": "/robots/ur5/ik/batch",
                "headers": [], "query_string": b""}  # fmt: skip


async def _request() -> Message:
    return {"type": "http.request", "body": b"", "more_body": False}


def _run(app, *, cancel: bool) -> tuple[asyncio.Task, list[Message]]:
    """Run ``ErrorGuardMiddleware(app)`` as a request task; cancel it once the app waits."""
    sent: list[Message] = []

    async def send(message: Message) -> None:
        sent.append(message)

    async def main() -> asyncio.Task:
        task = asyncio.ensure_future(ErrorGuardMiddleware(app)(SCOPE, _request, send))
        if cancel:
            await app.waiting.wait()
            task.cancel()
        await asyncio.wait([task])
        return task

    return asyncio.run(main()), sent


class WaitsForever:
    """An endpoint still working when the server cancels it."""

    def __init__(self) -> None:
        self.waiting = asyncio.Event()

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        self.waiting.set()
        await asyncio.Event().wait()


def test_a_cancelled_request_is_answered_503_and_stays_cancelled(caplog) -> None:
    """Before: the guard un-cancelled the task (Task.uncancel) and returned normally, so a
    cancellation (uvicorn's at the graceful-shutdown timeout, or any timeout or task group
    around the app) was swallowed."""
    with caplog.at_level(logging.WARNING, logger="denavit"):
        task, sent = _run(WaitsForever(), cancel=True)
    assert task.cancelled(), "the guard swallowed the cancellation"
    start, body = sent
    assert start["status"] == 503
    headers = {k.decode(): v.decode() for k, v in start["headers"]}
    assert headers["content-type"] == "application/problem+json"
    assert headers["connection"] == "close" and headers["retry-after"] == str(RETRY_AFTER_S)
    problem = orjson.loads(body["body"])
    assert problem["status"] == 503 and "shutting down" in problem["detail"]
    assert not body.get("more_body")
    assert "cancelled by the server" in caplog.text


def test_a_bug_is_answered_500_and_the_task_ends_normally(caplog) -> None:
    async def buggy(scope: Scope, receive: Receive, send: Send) -> None:
        raise ZeroDivisionError("a bug, on purpose")

    with caplog.at_level(logging.ERROR, logger="denavit"):
        task, sent = _run(buggy, cancel=False)
    assert not task.cancelled() and task.exception() is None
    assert sent[0]["status"] == 500
    [record] = [r for r in caplog.records if r.exc_info is not None]
    assert record.exc_info[0] is ZeroDivisionError


def test_a_cancellation_after_the_response_started_goes_on() -> None:
    """Nothing can be answered any more: the cancellation reaches the server untouched."""

    class StartsThenWaits(WaitsForever):
        async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
            await send({"type": "http.response.start", "status": 200, "headers": []})
            await super().__call__(scope, receive, send)

    task, sent = _run(StartsThenWaits(), cancel=True)
    assert task.cancelled()
    assert [m["type"] for m in sent] == ["http.response.start"]
