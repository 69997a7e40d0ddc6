"""The compiled driver: the search's attempts run by :func:`app.kinematics.ik_kernel.attempt`.

For the full pose (all six rows, unit weights) on a chain the kernel supports, each attempt
(at most :data:`~app.kinematics.ik.dls.ATTEMPT_CAP` iterations, a few tens of µs) runs
compiled; this driver does what :func:`app.kinematics.ik.dls.run_python` does between
attempts (the nearest-sample jump from a far seed, restarts, the budget, cancellation,
offering converged iterates to the search), so both loops take the same iterates.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from app.kinematics import analytic_ik, ik_kernel
from app.kinematics.ik.dls import (
    ATTEMPT_CAP,
    CLAMP,
    DAMP,
    MAX_STEP,
    MU,
    NEAREST_FIRST,
    NULL_ENERGY,
    NULL_FLOOR,
    NULL_GAIN,
    STALL,
)

if TYPE_CHECKING:
    from app.kinematics.ik.search import Search


def warm_up() -> None:
    """Compile (or load from Numba's cache) the solver's compiled parts: the DLS attempt
    (:mod:`ik_kernel`) and the UR closed form. Idempotent; a few seconds the first time on
    a machine, well under one from the cache."""
    if ik_kernel.available() and not ik_kernel.warmed():
        ik_kernel.warm_up()
        analytic_ik.warm_up()


def kernel_cache_stats() -> dict[str, int]:
    """How this process got its compiled kernels: ``loaded`` from Numba's on-disk cache,
    ``compiled`` anew (each counts kernel × argument types; both 0 before :func:`warm_up`)."""
    if not ik_kernel.available():
        return {"loaded": 0, "compiled": 0}
    from numba.core.dispatcher import Dispatcher

    loaded = compiled = 0
    for module in (ik_kernel, analytic_ik.ur):
        for obj in vars(module).values():
            if isinstance(obj, Dispatcher):
                loaded += sum(obj.stats.cache_hits.values())
                compiled += sum(obj.stats.cache_misses.values())
    return {"loaded": loaded, "compiled": compiled}


def run_compiled(s: Search, deadline: float, max_iterations: int | None) -> None:
    """:func:`~app.kinematics.ik.dls.run_python` for the full pose with the attempts
    compiled (:func:`ik_kernel.attempt`): the same iterates, restarts and budget, checked
    between attempts (an attempt is at most ``ATTEMPT_CAP`` iterations, a few tens of µs).
    Requires ``s.ch.compiled``."""
    ch, cc = s.ch, s.ch.compiled
    Rt = np.ascontiguousarray(s.target.rotation)
    pt = np.ascontiguousarray(s.target.translation)
    lo, hi = ch.clip_lo, ch.clip_hi
    q_ref = np.ascontiguousarray(s.q_seed[ch.active])
    redundant = ch.k > 6
    clamp = CLAMP and redundant
    null_on = redundant and NULL_GAIN > 0.0
    tol_p2, tol_r2 = s.tol_p**2, s.tol_r**2
    cap = max_iterations if max_iterations is not None else 1 << 62
    best = np.array([s.best_energy])
    best_q = q_ref.copy()
    have_best = False
    attempt = ik_kernel.attempt
    args = (cc.C, cc.t, cc.prism, cc.last_C, cc.last_t, lo, hi, ch.cont_mask, Rt, pt, q_ref)
    qa = q_ref.copy()
    it = s.iterations
    try:
        if NEAREST_FIRST and it < cap:
            # The seed's pose against the nearest table sample: jump at once when the
            # sample is much closer (one evaluation, counted as an iteration then).
            ep2, er2, tr = ik_kernel.pose_error(qa, *args[:5], Rt, pt)
            if not (ep2 <= tol_p2 and er2 <= tol_r2):
                if s.seed_is_far(ep2, tr):
                    it += 1
                    if ep2 + er2 < best[0]:
                        best[0], best_q[:], have_best = ep2 + er2, qa, True
                    qa = np.array(s.restart())
        while True:
            if s.out_of_budget(it, cap, deadline):
                return
            before = best[0]
            outcome, n = attempt(
                qa, *args,
                null_on and not s.restarts, clamp, tol_p2, tol_r2, cap - it,
                STALL, ATTEMPT_CAP, DAMP, MU, NULL_GAIN, 1.0 / NULL_ENERGY,
                NULL_FLOOR, MAX_STEP, best, best_q,
            )  # fmt: skip
            it += n
            have_best = have_best or best[0] < before
            if outcome == ik_kernel.CAPPED:
                return
            if outcome == ik_kernel.CONVERGED:
                s.iterations = it
                if s.offer(qa.copy()) and s.done():
                    return
            qa = np.array(s.restart())
    finally:
        s.iterations = it
        if have_best and best[0] < s.best_energy:
            s.best_energy, s.best_q = float(best[0]), s.wire(best_q)
