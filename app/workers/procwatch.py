"""Processes that die with their parent, so that killing a process leaves nothing behind.

Two mechanisms, used together where they apply:

- :func:`set_parent_death_signal`: on Linux, ``prctl(PR_SET_PDEATHSIG, sig)`` asks the
  kernel to send ``sig`` to this process when its parent *thread* exits (a process killed
  with SIGKILL included). Nothing to run in user space, so it works even while this process
  is busy in C code. The parent is the thread that created the process: use it only where
  that thread lives as long as the work (the forkserver started by a build thread, the
  build processes forked by the forkserver).
- :func:`watch_parent`: a daemon thread that waits on the ``multiprocessing`` parent's
  sentinel (a pipe whose other end only the parent holds: it reads end-of-file when the
  parent exits, however it exits) and then acts. Portable, and it names the process that
  started this one with ``Process.start()``, which for a forkserver child is the process
  that asked for it, not the forkserver.

This module imports nothing from the rest of ``app`` (it is part of the core).
"""

from __future__ import annotations

import ctypes
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Callable

#: ``PR_SET_PDEATHSIG`` of ``<linux/prctl.h>``.
PR_SET_PDEATHSIG = 1


def set_parent_death_signal(sig: int = signal.SIGKILL, parent: int | None = None) -> bool:
    """Have the kernel send ``sig`` to this process when its parent exits (Linux only).

    Returns whether it was set. If the parent has already exited (this process was
    re-parented, before or while this is being set), ``sig`` is sent at once. ``parent``
    is the PID of the process that started this one, when known (passed down by it):
    without it, only a re-parenting while this runs is seen.
    """
    if not sys.platform.startswith("linux"):
        return False
    if parent is None:
        parent = os.getppid()
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        if libc.prctl(PR_SET_PDEATHSIG, int(sig), 0, 0, 0) != 0:
            return False
    except (OSError, AttributeError):  # pragma: no cover - no libc prctl
        return False
    if os.getppid() != parent:  # the parent exited before the kernel knew to signal
        os.kill(os.getpid(), sig)
    return True


def kill_self() -> None:
    """End this process at once (SIGKILL: no clean-up runs, nothing can block it)."""
    os.kill(os.getpid(), signal.SIGKILL)


def watch_parent(
    action: Callable[[], None] = kill_self, name: str = "parent-watch"
) -> threading.Thread | None:
    """Run ``action`` in a daemon thread once the ``multiprocessing`` parent of this process
    has exited; ``None`` (nothing watched) when this process was not started by
    ``multiprocessing``."""
    parent = multiprocessing.parent_process()
    if parent is None:
        return None

    def wait() -> None:
        parent.join()  # waits on the parent's sentinel: end-of-file when the parent exits
        action()

    thread = threading.Thread(target=wait, name=name, daemon=True)
    thread.start()
    return thread


def exit_with_supervisor(grace_s: float) -> threading.Thread | None:
    """In a server worker started by ``multiprocessing`` (uvicorn with ``--workers`` > 1 or
    ``--reload``): when the supervisor exits, even by SIGKILL, stop this worker as SIGTERM
    does (in-flight requests may finish), and kill it if it is still there ``grace_s`` s
    later. Does nothing in a process not started by ``multiprocessing``."""

    def stop() -> None:
        os.kill(os.getpid(), signal.SIGTERM)
        time.sleep(grace_s)
        kill_self()

    return watch_parent(stop, name="supervisor-watch")
