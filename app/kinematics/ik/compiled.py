"""The compiled driver: the numeric search run by :func:`app.kinematics.ik.search_kernel.search`.

For the full pose (all six rows, unit weights) on a chain the kernel supports, the whole
search of :func:`app.kinematics.ik.dls.run_python` (the nearest-sample jump from a far seed,
the attempts of :func:`app.kinematics.ik.kernel.attempt`, the restarts) runs compiled, in
chunks of ``chunk_attempts`` attempts (:class:`~app.kinematics.ik.parameters.SolverParameters`);
between chunks this driver reads the budget's clock (the search's) and the cancel flag, and
it offers every converged iterate to the search
(:meth:`~app.kinematics.ik.search.Search.offer`: Pinocchio's verification) before resuming.
Both loops take the same iterates. The chain's constants
(:attr:`~app.kinematics.ik.precompute.IKChain.search_constants`) are built once per chain.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING

import numpy as np

from app.kinematics.errors import Cancelled
from app.kinematics.ik import search_kernel
from app.kinematics.ik.boundary import ITERATIONS, RESTARTS, SearchState, new_state, reset_state
from app.kinematics.ik.kernel import CAPPED, CONVERGED
from app.kinematics.ik.search_kernel import JUMP
from app.kinematics.jit import direct

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.ik.search import Search


def run_compiled(s: Search, deadline: float, max_iterations: int | None) -> None:
    """:func:`~app.kinematics.ik.dls.run_python` for the full pose, compiled whole
    (:func:`search_kernel.search`): the same iterates, restarts and budget; the clock
    (``s.clock``) and ``s.cancel`` are read between chunks of ``chunk_attempts``
    attempts, every converged iterate is verified by :meth:`Search.offer` (Pinocchio).
    Requires ``s.ch.compiled``."""
    ch, clock = s.ch, s.clock
    consts = ch.search_constants
    chunk_attempts = s.parameters.chunk_attempts
    H = np.ascontiguousarray(s.target.homogeneous, dtype=np.float64)
    tol_p2, tol_r2 = s.tol_p**2, s.tol_r**2
    best0 = s.best_energy
    n_table = consts.table.shape[0]
    n_near = min(s.parameters.nearest, n_table)
    state = _take_state(ch)
    if state is None:
        qa = np.ascontiguousarray(s.q_seed[ch.active], dtype=np.float64)  # a fresh copy
        state = new_state(qa, best0, n_near, n_table)
        state.counters[ITERATIONS], state.counters[RESTARTS] = s.iterations, s.restarts
    else:
        reset_state(state, s.q_seed[ch.active], best0, s.iterations, s.restarts, n_near)
    st, qa = state.counters, state.qa
    cap = max_iterations if max_iterations is not None else 1 << 62
    table_restarts = s.rng is None
    # the first attempt runs even when the budget is already spent (as the Python loop)
    chunk = 1 if clock() >= deadline else chunk_attempts
    search = direct(search_kernel.search, state, consts, H, tol_p2, tol_r2, cap, chunk, True)
    try:
        while True:
            outcome = search(state, consts, H, tol_p2, tol_r2, cap, chunk, table_restarts)
            chunk = chunk_attempts
            if outcome == CAPPED:
                return
            if outcome == CONVERGED:
                s.iterations = int(st[ITERATIONS])
                if s.offer(qa) and s.done():
                    return
                chunk = 0  # the next restart is chosen before the budget is read
                continue
            if outcome == JUMP:
                qa[:] = s.random_start()
            if st[ITERATIONS] >= cap:
                return
            if clock() >= deadline:
                s.timed_out = True
                return
            if s.cancel is not None and s.cancel.is_set():
                raise Cancelled()
    finally:
        s.iterations, s.restarts = int(st[ITERATIONS]), int(st[RESTARTS])
        best = state.best
        if best[0] < best0:
            s.best_energy = float(best[0])
            if not s.solutions:  # (only a failure reports the best iterate)
                s.best_q = s.wire(state.best_q)
        ch.idle_states[threading.get_ident()] = state  # free again for this thread


def _take_state(ch: IKChain) -> SearchState | None:
    """This thread's idle :class:`SearchState` of ``ch`` (:attr:`IKChain.idle_states`),
    removed until the query puts it back; None: a fresh one (the first query on this
    thread, or a re-entrant solve from an ``accept`` predicate)."""
    return ch.idle_states.pop(threading.get_ident(), None)
