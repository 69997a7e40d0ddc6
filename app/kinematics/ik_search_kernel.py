"""The numeric IK search compiled whole: seed check, nearest-sample jump, attempts, restarts.

:func:`app.kinematics.ik_kernel.attempt` runs one damped-least-squares attempt (at most 20
iterations, a few tens of µs). Driving the attempts from Python (restart choice, ranking
the restart table, the budget) cost more than the attempts themselves; :func:`search` does
the same driving compiled, for a bounded chunk of attempts per call, and returns to Python
only when

- an iterate converged (``CONVERGED``: Python verifies it by Pinocchio before it counts,
  :meth:`app.kinematics.ik.search.Search.offer`, then resumes the search or stops),
- the iteration cap is spent (``CAPPED``),
- the chunk of attempts is done (``PAUSED``: Python reads the clock and the cancel flag,
  which Numba cannot, then resumes),
- or a random restart is due and the caller draws restarts from its own generator
  (``JUMP``: Python writes the start into ``qa`` and resumes).

The iterates are those of :mod:`app.kinematics.ik.dls` (the Python loop): the seed's pose
against the nearest sample of the restart table, the jump there when the seed is far, then
restarts from the :data:`~app.kinematics.ik.search.NEAREST` samples nearest the target pose
(ties broken by table index), then the table in order.

State between calls
-------------------
``st`` (int64): ``[iterations, restarts, phase, distances known, nearest sample, nearest
ranked, cap, chunk, flags, stall, attempt cap, nearest count, nearest indices…]``; phase 0:
the seed not checked yet, 1: a restart is due, 2: ``qa`` is the start of the next attempt.
``cp``: the chain's constants packed once by :func:`pack_chain`.
"""

from __future__ import annotations

import numpy as np

from app.kinematics import ik_kernel
from app.kinematics.ik_kernel import CAPPED, CONVERGED, jit

#: Outcomes of :func:`search` besides ``CONVERGED`` and ``CAPPED`` (:mod:`ik_kernel`).
PAUSED, JUMP = 3, 4
#: Flags in ``st[8]``.
NULL_ON, CLAMP_ON, TABLE_RESTARTS, NEAREST_FIRST_ON = 1, 2, 4, 8
#: Indices of the header of ``st`` and of the packed float constants of ``cp``.
HEADER = 12
_NF = 8  # damp, mu, gain, null_scale, null_floor, max_step, nearest_ratio, rot_weight


def pack_chain(
    C, t, prism, last_C, last_t, lo, hi, cont, damp, mu, gain, null_scale, null_floor,
    max_step, nearest_ratio, rot_weight,
) -> np.ndarray:  # fmt: skip
    """The constants :func:`search` reads, in one float64 array (one argument to pass)."""
    head = np.array(
        [damp, mu, gain, null_scale, null_floor, max_step, nearest_ratio, rot_weight], float
    )
    parts = (head, C, t, prism, last_C, last_t, lo, hi, cont)
    return np.ascontiguousarray(np.concatenate([np.asarray(a, float).ravel() for a in parts]))


@jit
def _rank_nearest(d, near, count):  # pragma: no cover
    """The ``count`` smallest entries of ``d`` in increasing order (ties: lower index first)
    into ``near``: one pass with an insertion into the sorted prefix."""
    n = 0
    for i in range(d.shape[0]):
        v = d[i]
        if n == count and not v < d[near[n - 1]]:
            continue
        j = n if n < count else count - 1
        while j > 0 and v < d[near[j - 1]]:
            near[j] = near[j - 1]
            j -= 1
        near[j] = i
        if n < count:
            n += 1
    return n


@jit
def search(qa, q_ref, best_q, best, H, tol_p2, tol_r2, st, d, cp, tab32, table):  # pragma: no cover
    """Run the search from its state (module doc) for at most ``st[7]`` attempts.

    ``qa`` (k,) is the current start or, on ``CONVERGED``, the converged iterate;
    ``best_q`` (k,) and ``best`` (1,) the lowest-energy unconverged iterate and its energy
    ‖e‖²; ``H`` the target (4×4 homogeneous, root frame); ``tol_p2``, ``tol_r2`` the squared
    tolerances (m², rad²). ``tab32`` is the
    restart table's poses ((13, N) float32: −2·[p | c·vec(R)] transposed, then ‖p‖² + 3c),
    ``table`` (N, k) its configurations. Returns the outcome.
    """
    k = qa.shape[0]
    damp, mu, gain, null_scale = cp[0], cp[1], cp[2], cp[3]
    null_floor, max_step, ratio, rot_w = cp[4], cp[5], cp[6], cp[7]
    o = _NF
    C = cp[o : o + 9 * k].reshape((k, 3, 3))
    o += 9 * k
    t = cp[o : o + 3 * k].reshape((k, 3))
    o += 3 * k
    prism = cp[o : o + k] != 0.0
    o += k
    last_C = cp[o : o + 9].reshape((3, 3))
    last_t = cp[o + 9 : o + 12]
    o += 12
    lo = cp[o : o + k]
    hi = cp[o + k : o + 2 * k]
    cont = cp[o + 2 * k : o + 3 * k] != 0.0
    pt = np.empty(3)
    Rt = np.empty((3, 3))
    for i in range(3):
        pt[i] = H[i, 3]
        for j in range(3):
            Rt[i, j] = H[i, j]
    k_t = pt[0] * pt[0] + pt[1] * pt[1] + pt[2] * pt[2] + 3.0 * rot_w
    cap, chunk, flags = st[6], st[7], st[8]
    n_table = table.shape[0]
    n_near = st[11]
    near = st[HEADER : HEADER + n_near]
    if st[2] == 0:  # the seed: jump to the nearest table sample when it is far
        st[2] = 2
        if flags & NEAREST_FIRST_ON and st[0] < cap:
            ep2, er2, tr = ik_kernel.pose_error(qa, C, t, prism, last_C, last_t, Rt, pt)
            if not (ep2 <= tol_p2 and er2 <= tol_r2):
                _distances(pt, Rt, tab32, d, st)
                d_seed = ep2 + (2.0 * rot_w) * (3.0 - tr)
                # in float32, as NumPy 2 adds and compares a float32 with floats
                # (Search.seed_is_far)
                if d[st[4]] + np.float32(k_t) < np.float32(ratio * d_seed):
                    st[0] += 1
                    if ep2 + er2 < best[0]:
                        best[0] = ep2 + er2
                        best_q[:] = qa
                    st[2] = 1
    done = 0
    while True:
        if st[2] == 1:  # the next restart (Search.restart)
            i = st[1]
            st[1] = i + 1
            st[2] = 2
            if n_near > 0:
                if st[3] == 0:
                    _distances(pt, Rt, tab32, d, st)
                if i == 0:
                    qa[:] = table[st[4]]
                    continue
                if st[5] == 0:
                    n_near = _rank_nearest(d, near, n_near)
                    st[11] = n_near
                    st[5] = 1
                if i < n_near:
                    qa[:] = table[near[i]]
                    continue
            if not flags & TABLE_RESTARTS:
                return JUMP
            qa[:] = table[i % n_table]
        if st[0] >= cap:
            return CAPPED
        if done >= chunk:
            return PAUSED
        done += 1
        outcome, n = ik_kernel.attempt(
            qa, C, t, prism, last_C, last_t, lo, hi, cont, Rt, pt, q_ref,
            (flags & NULL_ON) != 0 and st[1] == 0, (flags & CLAMP_ON) != 0,
            tol_p2, tol_r2, cap - st[0], st[9], st[10], damp, mu, gain, null_scale,
            null_floor, max_step, best, best_q,
        )  # fmt: skip
        st[0] += n
        st[2] = 1
        if outcome == CAPPED:
            return CAPPED
        if outcome == CONVERGED:
            return CONVERGED


@jit
def _distances(pt, Rt, tab32, d, st):  # pragma: no cover
    """Pose distances of the table samples to the target (up to K_t) into ``d``, the
    nearest's index into ``st[4]`` (as :meth:`IKChain.sample_distances_argmin`)."""
    x = np.empty(12, dtype=np.float32)
    for j in range(3):
        x[j] = np.float32(pt[j])
    for j in range(9):
        x[3 + j] = np.float32(Rt[j // 3, j % 3])
    st[4] = ik_kernel.sample_distances(tab32[:12], tab32[12], x, d)
    st[3] = 1


def warm_up() -> None:
    """Compile :func:`search` for the argument types the solver passes (dummy 1-joint
    chain)."""
    z = np.zeros(1)
    cp = pack_chain(
        np.eye(3)[None], np.zeros((1, 3)), z, np.eye(3), np.zeros(3), -np.ones(1),
        np.ones(1), z, 0.01, 1e-10, 0.2, 100.0, 1e-8, 2.0, 0.5, 0.2,
    )  # fmt: skip
    st = np.zeros(HEADER + 4, dtype=np.int64)
    st[6], st[7], st[8], st[9], st[10], st[11] = 1, 1, 15, 2, 20, 4
    tab32 = np.zeros((13, 4), dtype=np.float32)
    d = np.empty(4, np.float32)
    best = np.array([np.inf])
    table = np.zeros((4, 1))
    search(z.copy(), z.copy(), z.copy(), best, np.eye(4), 1e-10, 1e-10, st, d, cp, tab32, table)
