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
