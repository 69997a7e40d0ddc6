"""The numeric IK search compiled whole: seed check, nearest-sample jump, attempts, restarts.

:func:`app.kinematics.ik.kernel.attempt` runs one damped-least-squares attempt (at most
``attempt_cap`` iterations, a few tens of µs). Driving the attempts from Python (restart
choice, ranking the restart table, the budget) cost more than the attempts themselves;
:func:`search` does the same driving compiled, for a bounded chunk of attempts per call, and
returns to Python only when

- an iterate converged (``CONVERGED``: Python verifies it by Pinocchio before it counts,
  :meth:`app.kinematics.ik.search.Search.offer`, then resumes the search or stops),
- the iteration cap is spent (``CAPPED``),
- the chunk of attempts is done (``PAUSED``: Python reads the clock and the cancel flag,
  which Numba cannot, then resumes),
- or a random restart is due and the caller draws restarts from its own generator
  (``JUMP``: Python writes the start into ``qa`` and resumes).

The iterates are those of :mod:`app.kinematics.ik.dls` (the Python loop): the seed's pose
against the nearest sample of the restart table, the jump there when the seed is far, then
restarts from the ``nearest`` samples nearest the target pose (ties broken by table index),
then the table in order.

What crosses the boundary
-------------------------
:class:`SearchConstants` (built once per chain and parameters: the chain's
:class:`~app.kinematics.ik.kernel.ChainConstants`, the loop's
:class:`~app.kinematics.ik.kernel.StepParameters`, the restart table and its poses, the
switches) and :class:`SearchState` (one query's arrays, updated in place between calls:
the iterate, the best iterate, the table distances, the nearest samples and the
:data:`COUNTERS`).
"""

from __future__ import annotations

import numpy as np

from app.kinematics.ik import kernel
from app.kinematics.ik.boundary import (
    DISTANCES_KNOWN,
    ITERATIONS,
    N_NEAR,
    NEAREST_ONE,
    PHASE,
    RANKED,
    RESTARTS,
    ChainConstants,
    SearchConstants,
    StepParameters,
    new_state,
)
from app.kinematics.ik.kernel import CAPPED, CONVERGED
from app.kinematics.jit import jit

#: Outcomes of :func:`search` besides ``CONVERGED`` and ``CAPPED`` (:mod:`.kernel`).
PAUSED, JUMP = 3, 4


@jit
def _rank_nearest(d, near, count):  # pragma: no cover
    """The ``count`` smallest entries of ``d`` in increasing order (ties: lower index first)
    into ``near``: one pass with an insertion into the sorted prefix. Once the prefix is
    full, an entry enters only if it is below the prefix's largest, kept in a register."""
    n_d = d.shape[0]
    n = 0
    i = 0
    while i < n_d and n < count:  # the first ``count`` entries, sorted by insertion
        v = d[i]
        j = n
        while j > 0 and v < d[near[j - 1]]:
            near[j] = near[j - 1]
            j -= 1
        near[j] = i
        n += 1
        i += 1
    if n == 0:
        return 0
    largest = d[near[n - 1]]
    while i < n_d:
        v = d[i]
        if v < largest:
            j = count - 1
            while j > 0 and v < d[near[j - 1]]:
                near[j] = near[j - 1]
                j -= 1
            near[j] = i
            largest = d[near[count - 1]]
        i += 1
    return n


@jit
def search(state, consts, H, tol_p2, tol_r2, cap, chunk, table_restarts):  # pragma: no cover
    """Run the search from ``state`` (:class:`SearchState`) for at most ``chunk`` attempts.

    ``consts`` is the chain's :class:`SearchConstants`; ``H`` the target (4×4 homogeneous,
    root frame); ``tol_p2``, ``tol_r2`` the squared tolerances (m², rad²); ``cap`` the
    iteration cap; ``table_restarts``: restarts past the nearest samples come from the table
    in order (else the caller draws them: ``JUMP``). Returns the outcome.
    """
    qa, q_ref, best_q, best = state.qa, state.q_ref, state.best_q, state.best
    d, near, st = state.d, state.near, state.counters
    chain, step, table = consts.chain, consts.step, consts.table
    ratio, rot_w = consts.nearest_ratio, consts.rot_weight
    pt = np.empty(3)
    Rt = np.empty((3, 3))
    for i in range(3):
        pt[i] = H[i, 3]
        for j in range(3):
            Rt[i, j] = H[i, j]
    k_t = pt[0] * pt[0] + pt[1] * pt[1] + pt[2] * pt[2] + 3.0 * rot_w
    n_table = table.shape[0]
    n_near = st[N_NEAR]
    if st[PHASE] == 0:  # the seed: jump to the nearest table sample when it is far
        st[PHASE] = 2
        q_ref[:] = qa  # a reused state (:func:`.boundary.reset_state`) starts from the seed
        best_q[:] = qa
        if consts.nearest_first and st[ITERATIONS] < cap:
            ep2, er2, tr = kernel.pose_error(qa, chain, Rt, pt)
            if not (ep2 <= tol_p2 and er2 <= tol_r2):
                _distances(pt, Rt, consts.tab32, d, st)
                d_seed = ep2 + (2.0 * rot_w) * (3.0 - tr)
                # in float32, as NumPy 2 adds and compares a float32 with floats
                # (Search.seed_is_far)
                if d[st[NEAREST_ONE]] + np.float32(k_t) < np.float32(ratio * d_seed):
                    st[ITERATIONS] += 1
                    if ep2 + er2 < best[0]:
                        best[0] = ep2 + er2
                        best_q[:] = qa
                    st[PHASE] = 1
    done = 0
    while True:
        if st[PHASE] == 1:  # the next restart (Search.restart)
            i = st[RESTARTS]
            st[RESTARTS] = i + 1
            st[PHASE] = 2
            if n_near > 0:
                if st[DISTANCES_KNOWN] == 0:
                    _distances(pt, Rt, consts.tab32, d, st)
                if i == 0:
                    qa[:] = table[st[NEAREST_ONE]]
                    continue
                if st[RANKED] == 0:
                    n_near = _rank_nearest(d, near, n_near)
                    st[N_NEAR] = n_near
                    st[RANKED] = 1
                if i < n_near:
                    qa[:] = table[near[i]]
                    continue
            if not table_restarts:
                return JUMP
            qa[:] = table[i % n_table]
        if st[ITERATIONS] >= cap:
            return CAPPED
        if done >= chunk:
            return PAUSED
        done += 1
        outcome, n = kernel.attempt(
            qa, chain, Rt, pt, q_ref, consts.null_on and st[RESTARTS] == 0, consts.clamp,
            tol_p2, tol_r2, cap - st[ITERATIONS], step, best, best_q,
        )  # fmt: skip
        st[ITERATIONS] += n
        st[PHASE] = 1
        if outcome == CAPPED:
            return CAPPED
        if outcome == CONVERGED:
            return CONVERGED


@jit
def _distances(pt, Rt, tab32, d, st):  # pragma: no cover
    """Pose distances of the table samples to the target (up to K_t) into ``d``, the
    nearest's index into ``st[NEAREST_ONE]`` (as :meth:`IKChain.sample_distances_argmin`)."""
    x = np.empty(12, dtype=np.float32)
    for j in range(3):
        x[j] = np.float32(pt[j])
    for j in range(9):
        x[3 + j] = np.float32(Rt[j // 3, j % 3])
    st[NEAREST_ONE] = kernel.sample_distances(tab32[:12], tab32[12], x, d)
    st[DISTANCES_KNOWN] = 1


def warm_up() -> None:
    """Compile :func:`search` for the argument types the solver passes (dummy 1-joint
    chain)."""
    z = np.zeros(1)
    chain = ChainConstants(
        np.eye(3)[None].copy(), np.zeros((1, 3)), np.zeros(1, np.bool_), np.eye(3), np.zeros(3),
        -np.ones(1), np.ones(1), np.zeros(1, np.bool_),
    )  # fmt: skip
    step = StepParameters(0.01, 1e-10, 0.2, 100.0, 1e-8, 2.0, 0.81, 2, 20)
    tab32 = np.zeros((13, 4), dtype=np.float32)
    consts = SearchConstants(chain, step, 0.5, 0.2, True, True, True, tab32, np.zeros((4, 1)))
    state = new_state(z.copy(), np.inf, 4, 4)
    search(state, consts, np.eye(4), 1e-10, 1e-10, 1, 1, True)
