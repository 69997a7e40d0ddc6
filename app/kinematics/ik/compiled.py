"""The compiled driver: the numeric search run by :func:`app.kinematics.ik_search_kernel.search`.

For the full pose (all six rows, unit weights) on a chain the kernel supports, the whole
search of :func:`app.kinematics.ik.dls.run_python` (the nearest-sample jump from a far seed,
the attempts of :func:`app.kinematics.ik_kernel.attempt`, the restarts) runs compiled, in
chunks of :data:`CHUNK_ATTEMPTS` attempts; between chunks this driver reads the budget's
:data:`clock` and the cancel flag, and it offers every converged iterate to the search
(:meth:`~app.kinematics.ik.search.Search.offer`: Pinocchio's verification) before resuming.
Both loops take the same iterates. :func:`pack` builds the kernel's per-chain constants once.
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

import numpy as np

from app.kinematics import analytic_ik, ik_kernel, ik_search_kernel
from app.kinematics.errors import Cancelled
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
from app.kinematics.ik.precompute import ROT_WEIGHT, TABLE
from app.kinematics.ik.scale import rotation_weight
from app.kinematics.ik.search import NEAREST, NEAREST_RATIO

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.ik.search import Search

#: Attempts (each at most ``ATTEMPT_CAP`` iterations, a few tens of µs) per compiled call,
#: between two reads of the clock and the cancel flag: the deadline is overrun by at most
#: one chunk (~0.1 ms).
CHUNK_ATTEMPTS = 4


def clock() -> float:
    """The budget's clock (s): ``time.perf_counter`` looked up at each read, the clock
    :func:`app.kinematics.ik.solve` starts the budget with, so a fake clock of either
    (``time.perf_counter`` or this function, replaced by a test) is the solver's."""
    return time.perf_counter()


def warm_up() -> None:
    """Compile (or load from Numba's cache) the solver's compiled parts: the DLS attempt
    (:mod:`ik_kernel`) and the UR closed form. Idempotent; a few seconds the first time on
    a machine, well under one from the cache."""
    if ik_kernel.available() and not ik_kernel.warmed():
        ik_kernel.warm_up()
        ik_search_kernel.warm_up()
        analytic_ik.warm_up()


def kernel_cache_stats() -> dict[str, int]:
    """How this process got its compiled kernels: ``loaded`` from Numba's on-disk cache,
    ``compiled`` anew (each counts kernel × argument types; both 0 before :func:`warm_up`)."""
    if not ik_kernel.available():
        return {"loaded": 0, "compiled": 0}
    from numba.core.dispatcher import Dispatcher

    loaded = compiled = 0
    for module in (ik_kernel, ik_search_kernel, analytic_ik.ur):
        for obj in vars(module).values():
            # a kernel imported by another module is counted in its own module only
            if isinstance(obj, Dispatcher) and obj.__module__ == module.__name__:
                loaded += sum(obj.stats.cache_hits.values())
                compiled += sum(obj.stats.cache_misses.values())
    return {"loaded": loaded, "compiled": compiled}


def pack(ch: IKChain) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """What :func:`ik_search_kernel.search` reads of a chain, built once with it: the packed
    constants, the restart table's poses ((13, N) float32) and the state template."""
    cc = ch.compiled
    redundant = ch.k > 6
    cp = ik_search_kernel.pack_chain(
        cc.C, cc.t, cc.prism, cc.last_C, cc.last_t, ch.clip_lo, ch.clip_hi, ch.cont_mask,
        DAMP, MU, NULL_GAIN, 1.0 / NULL_ENERGY, NULL_FLOOR, MAX_STEP, NEAREST_RATIO,
        rotation_weight(ch._robot, ch.frame_id, ROT_WEIGHT),  # the chain's (ik.scale)
    )  # fmt: skip
    M, W2 = ch.sample_poses()
    tab32 = np.ascontiguousarray(np.vstack((M.T, W2[None])), dtype=np.float32)
    n_near = min(NEAREST, TABLE)
    st = np.zeros(ik_search_kernel.HEADER + n_near, dtype=np.int64)
    flags = (
        (ik_search_kernel.NULL_ON if redundant and NULL_GAIN > 0.0 else 0)
        | (ik_search_kernel.CLAMP_ON if CLAMP and redundant else 0)
        | (ik_search_kernel.NEAREST_FIRST_ON if NEAREST_FIRST else 0)
    )
    st[7], st[8], st[9], st[10], st[11] = CHUNK_ATTEMPTS, flags, STALL, ATTEMPT_CAP, n_near
    return cp, tab32, st


def run_compiled(s: Search, deadline: float, max_iterations: int | None) -> None:
    """:func:`~app.kinematics.ik.dls.run_python` for the full pose, compiled whole
    (:func:`ik_search_kernel.search`): the same iterates, restarts and budget; the clock
    (:data:`clock`) and ``s.cancel`` are read between chunks of :data:`CHUNK_ATTEMPTS`
    attempts, every converged iterate is verified by :meth:`Search.offer` (Pinocchio).
    Requires ``s.ch.compiled``."""
    ch = s.ch
    cp, tab32, template = ch.search_pack
    H = s.target.homogeneous
    tol_p2, tol_r2 = s.tol_p**2, s.tol_r**2
    best = np.array([s.best_energy])
    best0 = s.best_energy
    st = template.copy()
    st[0], st[1] = s.iterations, s.restarts
    st[6] = cap = max_iterations if max_iterations is not None else 1 << 62
    if s.rng is None:
        st[8] |= ik_search_kernel.TABLE_RESTARTS
    qa = s.q_seed[ch.active]
    q_ref, best_q = qa.copy(), qa.copy()
    d = np.empty(TABLE, dtype=np.float32)
    table = ch.restart_table
    search = ik_search_kernel.search
    if clock() >= deadline:
        st[7] = 0  # the seed check only (as the Python loop), then the budget says stop
    try:
        while True:
            outcome = search(qa, q_ref, best_q, best, H, tol_p2, tol_r2, st, d, cp, tab32, table)
            st[7] = CHUNK_ATTEMPTS
            if outcome == ik_kernel.CAPPED:
                return
            if outcome == ik_kernel.CONVERGED:
                s.iterations = int(st[0])
                if s.offer(qa) and s.done():
                    return
                st[7] = 0  # the next restart is chosen before the budget is read
                continue
            if outcome == ik_search_kernel.JUMP:
                qa[:] = s.random_start()
            if st[0] >= cap:
                return
            if clock() >= deadline:
                s.timed_out = True
                return
            if s.cancel is not None and s.cancel.is_set():
                raise Cancelled()
    finally:
        s.iterations, s.restarts = int(st[0]), int(st[1])
        if best[0] < best0:
            s.best_energy = float(best[0])
            if not s.solutions:  # (only a failure reports the best iterate)
                s.best_q = s.wire(best_q)
