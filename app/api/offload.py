"""Work off the event loop: the app's two bounded pools, and cancelling work whose client has
left. The pools are the app's (:class:`~app.api.state.Services`, made by the lifespan).

The event loop serves sub-millisecond endpoints and /health; anything longer (IK with big
budgets, batches, reachability) runs in the compute pool (:func:`offload`), and long work
stops when its client disconnects (:func:`offload_cancellable`). Robot uploads (DH tables,
URDF, packages: unpacking, checks, waiting on their xacro, MJCF and mesh child processes)
run in a pool of their own (:func:`offload_upload`, ``DENAVIT_UPLOAD_WORKERS`` threads),
so however many slow uploads are in flight, a compute request never waits for one.
"""

from __future__ import annotations

import asyncio
import contextvars
import functools
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any, TypeVar

from fastapi import Request
from starlette.exceptions import HTTPException
from starlette.requests import HTTPConnection

from app.api.state import services
from app.kinematics.errors import Cancelled

T = TypeVar("T")


async def _run_in(executor: ThreadPoolExecutor, fn: Callable[..., T], *args: Any, **kw: Any) -> T:
    loop = asyncio.get_running_loop()
    context = contextvars.copy_context()  # the request id follows into the pool's logs
    return await loop.run_in_executor(executor, context.run, functools.partial(fn, *args, **kw))


async def offload(conn: HTTPConnection, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
    """Run ``fn(*args, **kwargs)`` in the app's bounded compute pool
    (:attr:`~app.api.state.Services.compute`) and await its result."""
    return await _run_in(services(conn).compute, fn, *args, **kwargs)


async def offload_upload(request: Request, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
    """Run the upload ``fn(*args, **kwargs)`` in the app's upload pool
    (:attr:`~app.api.state.Services.uploads`) and await its result."""
    return await _run_in(services(request).uploads, fn, *args, **kwargs)


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
    work = asyncio.ensure_future(offload(request, fn, *args, cancel=cancel, **kwargs))
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
