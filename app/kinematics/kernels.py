"""Every compiled kernel of the core, once per process: :func:`warm_up`,
:func:`kernel_cache_stats`.

The solver's kernels (:mod:`app.kinematics.ik.warmup`) and the paths' compiled point
(:mod:`app.kinematics.paths.point_kernel`, with a segment's pose of
:mod:`~app.kinematics.paths.pose_kernel`, and the walk over a run of waypoints of
:mod:`~app.kinematics.paths.walk_kernel`) are compiled by Numba on first use, or loaded from
its on-disk cache. The service warms them all at start-up; the image's build runs
``python -m app warm-up --require-cache`` and trusts :func:`kernel_cache_stats` to prove that
every kernel loads from the image's cache.
"""

from __future__ import annotations

from app.kinematics import analytic_ik
from app.kinematics.ik import (
    annotate,
    branch_kernel,
    joint_frames,
    kernel,
    query_kernel,
    search_kernel,
    warmup,
)
from app.kinematics.jit import available
from app.kinematics.paths import point_kernel, pose_kernel, walk_kernel

#: The modules whose Numba dispatchers are the core's kernels.
KERNEL_MODULES = (
    kernel,
    search_kernel,
    query_kernel,
    annotate,
    branch_kernel,
    joint_frames,
    analytic_ik.ur,
    point_kernel,
    pose_kernel,
    walk_kernel,
)


def warm_up() -> None:
    """Compile (or load) the solver's kernels, then the paths' (registered by
    :mod:`~app.kinematics.paths.point_kernel` with the solver's warm-up, so that a query's
    chain waits for them too): idempotent, thread-safe, done when
    :func:`app.kinematics.ik.warmup.warmed`."""
    warmup.warm_up()


def kernel_cache_stats() -> dict[str, int]:
    """How this process got its compiled kernels: ``loaded`` from Numba's on-disk cache,
    ``compiled`` anew (each counts kernel × argument types; both 0 before :func:`warm_up`)."""
    if not available():
        return {"loaded": 0, "compiled": 0}
    from numba.core.dispatcher import Dispatcher

    loaded = compiled = 0
    for module in KERNEL_MODULES:
        for obj in vars(module).values():
            # a kernel imported by another module is counted in its own module only
            if isinstance(obj, Dispatcher) and obj.__module__ == module.__name__:
                loaded += sum(obj.stats.cache_hits.values())
                compiled += sum(obj.stats.cache_misses.values())
    return {"loaded": loaded, "compiled": compiled}
