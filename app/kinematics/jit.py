"""Numba, where available: :func:`jit` compiles a kernel, :func:`available` says whether it can.

The compiled kernels (:mod:`app.kinematics.ik.kernel`, :mod:`app.kinematics.ik.search_kernel`,
:mod:`app.kinematics.analytic_ik.ur`) are written once, in the subset of Python Numba
compiles; without Numba they are plain Python functions, and the solvers use their Python
loops instead.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

try:  # pragma: no cover - numba is a pinned dependency; the fallback is the Python loop
    import numba

    _NUMBA = True
except ImportError:  # pragma: no cover
    numba = None
    _NUMBA = False


def available() -> bool:
    """Whether the compiled loops can be used (numba importable)."""
    return _NUMBA


def jit(fn: Callable[..., Any]) -> Any:
    """Numba's ``njit`` (releasing the GIL), or ``fn`` itself without Numba.

    Cached on disk when Numba finds a writable place (``NUMBA_CACHE_DIR``, next to the
    sources, or the user's cache directory); where it finds none (a read-only install, no
    home directory) Numba refuses ``cache=True`` at import, and the kernels are compiled
    in memory by every process instead: slower start, same service.
    """
    if numba is None:  # pragma: no cover
        return fn
    try:
        return numba.njit(cache=True, nogil=True)(fn)
    except RuntimeError:  # "cannot cache function ...: no locator available"
        return numba.njit(cache=False, nogil=True)(fn)


def direct(fn: Callable[..., Any], *example: Any) -> Callable[..., Any]:
    """``fn`` as a call of its compiled code for the argument types of ``example``, without
    Numba's per-call type dispatch; ``fn`` itself when it is not a Numba dispatcher (no
    Numba, or a test's stand-in).

    Numba's dispatcher finds the machine code of a call from the types of its arguments;
    for plain arrays and numbers that costs well under a microsecond, but for named tuples
    (:mod:`app.kinematics.ik.boundary`) it runs in Python, ~10 µs per call. The solver's
    named tuples are built with fixed types (C-contiguous float64, int64 and bool arrays,
    Python floats, ints and bools), so their machine code is found once per process here
    (compiled or loaded from the cache if need be); every later call must pass arguments of
    exactly those types.
    """
    entry = _DIRECT.get(fn)
    if entry is not None:
        return entry
    if numba is None or not isinstance(fn, numba.core.dispatcher.Dispatcher):
        return fn
    sig = tuple(numba.typeof(a) for a in example)
    fn.compile(sig)
    entry = _DIRECT[fn] = fn.overloads[sig].entry_point
    return entry


#: The entry points found by :func:`direct`, by dispatcher.
_DIRECT: dict[Callable[..., Any], Callable[..., Any]] = {}
