"""``kernels.kernel_cache_stats`` counts every compiled kernel of the core.

The container build runs ``python -m app warm-up --require-cache`` and trusts these counts to
prove that every kernel loads from the image's Numba cache; a kernel module the count
forgets would be compiled at the first request instead, unnoticed.
"""

from __future__ import annotations

import importlib
import pkgutil

import pytest

import app.kinematics
from app.kinematics import jit
from app.kinematics.kernels import kernel_cache_stats, warm_up

pytestmark = pytest.mark.skipif(not jit.available(), reason="Numba not installed")


def _dispatchers() -> list[object]:
    from numba.core.dispatcher import Dispatcher

    found = []
    for info in pkgutil.walk_packages(app.kinematics.__path__, "app.kinematics."):
        module = importlib.import_module(info.name)
        found += [
            obj
            for obj in vars(module).values()
            if isinstance(obj, Dispatcher) and obj.__module__ == module.__name__
        ]
    return found


def test_stats_count_every_compiled_signature_of_every_core_kernel() -> None:
    warm_up()
    dispatchers = _dispatchers()
    modules = {d.__module__ for d in dispatchers}
    assert {"app.kinematics.ik.kernel", "app.kinematics.analytic_ik.ur"} <= modules
    signatures = sum(len(d.signatures) for d in dispatchers)
    stats = kernel_cache_stats()
    assert signatures > 0
    assert stats["loaded"] + stats["compiled"] == signatures
