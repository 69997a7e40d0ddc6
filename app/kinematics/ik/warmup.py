"""Compiling the solver's kernels once per process: :func:`warm_up`, :func:`warmed`.

The kernels (:mod:`.kernel`, :mod:`.search_kernel`, the UR closed form of
:mod:`app.kinematics.analytic_ik.ur`, the branch flags of :mod:`.branch_kernel`, a path's
compiled point, :mod:`app.kinematics.paths.point_kernel` and
:mod:`~app.kinematics.paths.pose_kernel`) are compiled by Numba on first use, or loaded from its
on-disk cache. :func:`warm_up` does all of it before any query (at start-up, in each worker
process), so that no query's time budget pays for compiling; :func:`warmed` is True only
once every kernel is ready.
"""

from __future__ import annotations

import threading

from app.kinematics import analytic_ik
from app.kinematics.ik import annotate, branch_kernel, kernel, search_kernel
from app.kinematics.jit import available
from app.kinematics.paths import point_kernel, pose_kernel

_LOCK = threading.Lock()
_warmed = False


def warmed() -> bool:
    """Whether every kernel is compiled (or loaded) in this process."""
    return _warmed


def warm_up() -> None:
    """Compile (or load from Numba's cache) every compiled part of the solver: the DLS
    attempt, the whole search, the UR closed form. Idempotent and thread-safe: a caller that
    comes while another compiles waits until all kernels are ready (a few seconds the first
    time on a machine, well under one from the cache)."""
    global _warmed
    if _warmed or not available():
        return
    with _LOCK:
        if _warmed:
            return
        kernel.warm_up()
        search_kernel.warm_up()
        analytic_ik.warm_up()
        annotate.warm_up()
        point_kernel.warm_up()  # the branch flags and a segment's pose with it
        _warmed = True  # only now: every kernel is ready


def kernel_cache_stats() -> dict[str, int]:
    """How this process got its compiled kernels: ``loaded`` from Numba's on-disk cache,
    ``compiled`` anew (each counts kernel × argument types; both 0 before :func:`warm_up`)."""
    if not available():
        return {"loaded": 0, "compiled": 0}
    from numba.core.dispatcher import Dispatcher

    loaded = compiled = 0
    kernels = (kernel, search_kernel, annotate, branch_kernel, analytic_ik.ur)
    for module in (*kernels, point_kernel, pose_kernel):
        for obj in vars(module).values():
            # a kernel imported by another module is counted in its own module only
            if isinstance(obj, Dispatcher) and obj.__module__ == module.__name__:
                loaded += sum(obj.stats.cache_hits.values())
                compiled += sum(obj.stats.cache_misses.values())
    return {"loaded": loaded, "compiled": compiled}
