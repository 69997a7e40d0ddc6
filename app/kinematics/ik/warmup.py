"""Compiling the solver's kernels once per process: :func:`warm_up`, :func:`warmed`.

The solver's kernels (:mod:`.kernel`, :mod:`.search_kernel`, the UR closed form of
:mod:`app.kinematics.analytic_ik.ur`, the annotation of :mod:`.annotate` with the branch flags
of :mod:`.branch_kernel`, the fast path's query of :mod:`.query_kernel`) are compiled by
Numba on first use, or loaded from its on-disk cache. :func:`warm_up` does all of it before
any query (when a chain is prepared, in each worker process), so that no query's time
budget pays for compiling; :func:`warmed` is True only once every kernel is ready. The whole
core's kernels (the paths' too) and their cache counts: :mod:`app.kinematics.kernels`.
"""

from __future__ import annotations

import threading
from collections.abc import Callable

from app.kinematics import analytic_ik
from app.kinematics.ik import annotate, kernel, query_kernel, search_kernel
from app.kinematics.jit import available

_LOCK = threading.Lock()
_warmed = False
#: Warm-ups of compiled callers of the solver's kernels elsewhere in the core (:func:`register`).
_CALLERS: list[Callable[[], None]] = []


def register(warm: Callable[[], None]) -> None:
    """Run ``warm`` (the warm-up of a kernel module elsewhere in the core that calls the
    solver's kernels, e.g. the paths' compiled point) in :func:`warm_up`, under its lock
    after the solver's kernels: a query's chain is prepared only once it is compiled too,
    so no query's time budget competes with its compiler for the interpreter. Registered
    after a warm-up, it runs at the next one (which :func:`warmed` then awaits)."""
    global _warmed
    with _LOCK:
        if warm not in _CALLERS:
            _CALLERS.append(warm)
            _warmed = False


def warmed() -> bool:
    """Whether every kernel is compiled (or loaded) in this process."""
    return _warmed


def warm_up() -> None:
    """Compile (or load from Numba's cache) every compiled part of the solver: the DLS
    attempt, the whole search, the UR closed form, the answer's annotation, then the
    registered callers' (:func:`register`). Idempotent and thread-safe: a caller that
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
        query_kernel.warm_up()
        for warm in _CALLERS:
            warm()
        _warmed = True  # only now: every kernel is ready
