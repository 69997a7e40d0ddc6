"""Work off the event loop: two bounded pools, and cancelling work whose client has left.

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
import os
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any, TypeVar

from fastapi import Request
from starlette.exceptions import HTTPException

from app.kinematics.errors import Cancelled

T = TypeVar("T")

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


_UPLOAD_POOLS: dict[int, ThreadPoolExecutor] = {}
_UPLOAD_LOCK = threading.Lock()


def upload_pool(workers: int) -> ThreadPoolExecutor:
    """The bounded pool of robot uploads (``workers`` threads, ``DENAVIT_UPLOAD_WORKERS``);
    never the compute pool, whose threads stay free for compute requests."""
    with _UPLOAD_LOCK:
        executor = _UPLOAD_POOLS.get(workers)
        if executor is None:
            executor = _UPLOAD_POOLS[workers] = ThreadPoolExecutor(
                max_workers=workers, thread_name_prefix="upload"
            )
        return executor


async def _run_in(executor: ThreadPoolExecutor, fn: Callable[..., T], *args: Any, **kw: Any) -> T:
    loop = asyncio.get_running_loop()
    context = contextvars.copy_context()  # the request id follows into the pool's logs
    return await loop.run_in_executor(executor, context.run, functools.partial(fn, *args, **kw))


async def offload(fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
    """Run ``fn(*args, **kwargs)`` in the bounded compute pool and await its result."""
    return await _run_in(pool(), fn, *args, **kwargs)


async def offload_upload(request: Request, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
    """Run the upload ``fn(*args, **kwargs)`` in the upload pool and await its result."""
    workers = request.app.state.settings.upload_workers
    return await _run_in(upload_pool(workers), fn, *args, **kwargs)


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
