"""Work in processes of its own: batch IK across processes (``ik_batch``), reachability
builds (``map_build``), and processes that die with the worker that started them
(``procwatch``, ``forkserver_init``). The pure core (:mod:`app.kinematics`) starts no
process."""

from __future__ import annotations

import os


def default_processes() -> int:
    """Worker processes by default (batch IK, reachability builds): every core this process
    may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        return os.cpu_count() or 1
