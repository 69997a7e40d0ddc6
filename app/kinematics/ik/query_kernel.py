"""One single-answer IK query in one compiled call: the search and the answer's annotation.

:func:`query` is :func:`app.kinematics.ik.search_kernel.search` (seed check, nearest-sample
jump, attempts, restarts, in chunks of attempts) and, when an iterate converges,
:func:`app.kinematics.ik.annotate.annotation` at it (branch code and Yoshikawa's
manipulability): the compiled part of :mod:`.single`, the fast path of
:func:`app.kinematics.ik.solve` when one solution nearest the seed is wanted.

What crosses the boundary
-------------------------
Unboxing a named tuple of arrays costs ~0.1 µs an array at every call (3.4 µs for the
search's :class:`~.boundary.SearchConstants` and :class:`~.boundary.SearchState`). Here the
chain's constants are two packed arrays built once per chain (:func:`pack`), the query's
state three (:class:`QueryState`), and the named tuples the search reads are rebuilt inside
compiled code from views of them (no copies, nothing unboxed).

``f`` (float64), in order: C (k, 3, 3), t (k, 3), last_C (3, 3), last_t (3,), lo (k,),
hi (k,), the wrist point (3,) of :class:`~.annotate.AnnotationConstants`, the step
parameters damp, mu, gain, null_scale, null_floor, max_step, progress
(:class:`~.boundary.StepParameters`), nearest_ratio, rot_weight.

``g`` (int64), in order: k, stall, attempt_cap, null_on, clamp, nearest_first, labelled,
kind, elbow, tip_axis4, then prism (k,), cont (k,) as 0/1 and the active joints' wire
indices (k,).

``ur`` (float64): the chain's compiled UR closed form
(:attr:`app.kinematics.analytic_ik.ur.URType.consts`: w (6, 3), p (6, 3), h (3,), s (6,),
c0 (3,), the frame's rotation (3, 3) and position (3,) at zero, the arm's origin, u, v (3,)
each, r1, r2 (2,) each, sign2), empty when the chain has none.

State ``sf`` (float64): qa (k,), q_ref (k,), best_q (k,), best (1,), then the answer's
branch code and manipulability (2,); ``d`` (N,) float32: the table distances; ``si``
(int64): the :data:`~.boundary.COUNTERS` then the nearest samples (n_near,).
"""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from app.kinematics.analytic_ik import ur as ur_form
from app.kinematics.ik import annotate, search_kernel
from app.kinematics.ik.boundary import (
    COUNTERS,
    N_NEAR,
    ChainConstants,
    SearchConstants,
    SearchState,
    StepParameters,
)
from app.kinematics.ik.kernel import CONVERGED
from app.kinematics.jit import direct, jit

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain

_NC = len(COUNTERS)
#: Outcomes of :func:`query` besides :func:`~.search_kernel.search`'s: the first closed-form
#: candidate is in ``sf[:k]`` (annotated); the closed form has no candidate (search next).
ANALYTIC, NO_CANDIDATE = 5, 6
#: Fixed entries of ``g`` before the per-joint ones.
_G0 = 10


class QueryConstants(NamedTuple):
    """One chain's packed constants (module doc): ``f``, ``g``, the restart table (N, k)
    float64 and its poses ``tab32`` (13, N) float32, ``ur`` (the compiled UR closed form,
    empty without one); ``k`` joints, ``n_near`` nearest samples ranked."""

    f: np.ndarray
    g: np.ndarray
    table: np.ndarray
    tab32: np.ndarray
    ur: np.ndarray
    k: int
    n_near: int


class QueryState(NamedTuple):
    """One query's packed arrays (module doc), reused by the next query on the thread."""

    sf: np.ndarray
    d: np.ndarray
    si: np.ndarray


def pack(ch: IKChain) -> QueryConstants | None:
    """The packed constants of ``ch`` (None without the compiled search and annotation)."""
    sc, ac = ch.search_constants, ch.annotation
    if sc is None or ac is None:
        return None
    c, s = sc.chain, sc.step
    k = int(c.C.shape[0])
    f = np.concatenate([
        c.C.ravel(), c.t.ravel(), c.last_C.ravel(), c.last_t.ravel(), c.lo, c.hi,
        ac.wrist.ravel(),
        [s.damp, s.mu, s.gain, s.null_scale, s.null_floor, s.max_step, s.progress,
         sc.nearest_ratio, sc.rot_weight],
    ]).astype(np.float64)  # fmt: skip
    head = [k, s.stall, s.attempt_cap, sc.null_on, sc.clamp, sc.nearest_first, ac.labelled,
            ac.kind, ac.elbow, ac.tip_axis4]  # fmt: skip
    g = np.concatenate([np.array(head, dtype=np.int64), c.prism, c.cont, ch.active])
    g = np.ascontiguousarray(g, dtype=np.int64)
    n_near = min(ch.parameters.nearest, sc.table.shape[0])
    geo = ch.closed_form[0]
    ur = np.zeros(0)
    if geo is not None:
        ur = np.concatenate([np.ravel(np.asarray(x, dtype=np.float64)) for x in geo.consts])
    return QueryConstants(
        np.ascontiguousarray(f), g, sc.table, sc.tab32, np.ascontiguousarray(ur), k, n_near
    )


def new_query_state(qc: QueryConstants) -> QueryState:
    """Fresh arrays for a query on ``qc`` (the kernel resets them at each query's start)."""
    return QueryState(
        np.zeros(3 * qc.k + 3), np.empty(qc.table.shape[0], dtype=np.float32),
        np.zeros(_NC + qc.n_near, dtype=np.int64),
    )  # fmt: skip


@jit
def query(  # pragma: no cover
    f, g, table, tab32, ur, sf, d, si, q_seed, fresh, analytic, H, tol_p2, tol_r2, cap, chunk
):
    """Run the search for at most ``chunk`` attempts; on ``CONVERGED`` also write the branch
    code and manipulability at the converged iterate ``sf[:k]`` into ``sf[3k + 1]``,
    ``sf[3k + 2]``. Restarts past the nearest samples come from the table in order.

    With ``fresh`` and ``analytic`` and a closed form (``ur`` not empty), the closed form
    runs instead of the search (:func:`app.kinematics.analytic_ik.ur.ur_candidates_compiled`:
    its candidates in its order, moved into the limits nearest the seed): the first one is
    written into ``sf[:k]`` and annotated (``ANALYTIC``), or there is none
    (``NO_CANDIDATE``: the state is the fresh one, the caller searches next).

    ``fresh``: the query's first call: the state is reset from the wire seed ``q_seed``
    (n,) (the active joints' values start the search; best energy ∞; counters 0), as
    :func:`~.boundary.reset_state`. ``H`` (4, 4): the target in the root frame; ``tol_p2``,
    ``tol_r2``: the squared tolerances (m², rad²); ``cap``: the iteration cap. Returns the
    outcome of :func:`~.search_kernel.search`.
    """
    k = g[0]
    o = 0
    C = f[o : o + 9 * k].reshape((k, 3, 3))
    o += 9 * k
    t = f[o : o + 3 * k].reshape((k, 3))
    o += 3 * k
    last_C = f[o : o + 9].reshape((3, 3))
    o += 9
    last_t = f[o : o + 3]
    o += 3
    lo = f[o : o + k]
    o += k
    hi = f[o : o + k]
    o += k
    wrist = f[o : o + 3]
    o += 3
    step = StepParameters(
        f[o], f[o + 1], f[o + 2], f[o + 3], f[o + 4], f[o + 5], f[o + 6], g[1], g[2]
    )
    ratio, rot_w = f[o + 7], f[o + 8]
    prism = g[_G0 : _G0 + k] != 0
    cont = g[_G0 + k : _G0 + 2 * k] != 0
    active = g[_G0 + 2 * k : _G0 + 3 * k]
    chain = ChainConstants(C, t, prism, last_C, last_t, lo, hi, cont)
    consts = SearchConstants(
        chain, step, ratio, rot_w, g[3] != 0, g[4] != 0, g[5] != 0, tab32, table
    )
    qa = sf[0:k]
    best = sf[3 * k : 3 * k + 1]
    counters = si[0:_NC]
    if fresh:
        for s in range(k):
            qa[s] = q_seed[active[s]]
        best[0] = np.inf
        for i in range(_NC):
            counters[i] = 0
        counters[N_NEAR] = si.shape[0] - _NC
    if fresh and analytic and ur.shape[0] > 0:
        outcome = _closed_form(ur, H, lo, hi, qa)
        if outcome == NO_CANDIDATE:
            return outcome
    else:
        state = SearchState(qa, sf[k : 2 * k], sf[2 * k : 3 * k], best, d, si[_NC:], counters)
        outcome = search_kernel.search(state, consts, H, tol_p2, tol_r2, cap, chunk, True)
    if outcome == CONVERGED or outcome == ANALYTIC:
        code, w = annotate.annotation(
            qa, C, t, prism, last_C, last_t, g[6] != 0, g[7], g[8] != 0, g[9] != 0, wrist
        )
        sf[3 * k + 1] = code
        sf[3 * k + 2] = w
    return outcome


@jit
def _closed_form(ur, H, lo, hi, qa):  # pragma: no cover
    """The UR closed form's first candidate for the target ``H`` into ``qa`` (the seed on
    entry) and ``ANALYTIC``, or ``NO_CANDIDATE`` (``qa`` untouched)."""
    w = ur[0:18].reshape((6, 3))
    p = ur[18:36].reshape((6, 3))
    MR = ur[48:57].reshape((3, 3))
    Rt = np.empty((3, 3))
    pt = np.empty(3)
    for i in range(3):
        pt[i] = H[i, 3]
        for j in range(3):
            Rt[i, j] = H[i, j]
    seed = qa.copy()
    out = np.empty((8, 6))
    n = ur_form._ur_all(
        w, p, ur[36:39], ur[39:45], ur[45:48], MR, ur[57:60], ur[60:63], ur[63:66],
        ur[66:69], ur[69:71], ur[71:73], ur[73], Rt, pt, seed, out,
    )  # fmt: skip
    ur_form._into_limits_nb(out, n, lo, hi, seed)
    if n == 0:
        return NO_CANDIDATE
    for i in range(6):
        qa[i] = out[0, i]
    return ANALYTIC


@functools.cache
def entry():
    """:func:`query`'s compiled entry point (:func:`app.kinematics.jit.direct`), found once
    per process (without building :func:`_example`'s arguments at every query)."""
    return direct(query, *_example())


def _example() -> tuple:
    """Arguments of the types :func:`app.kinematics.ik.single` passes (a 1-joint chain)."""
    k, n = 1, 4
    f = np.zeros(9 * k + 3 * k + 9 + 3 + 2 * k + 3 + 9)
    f[0] = f[4] = f[8] = 1.0  # C = I
    o = 12 * k
    f[o] = f[o + 4] = f[o + 8] = 1.0  # last_C = I
    o = 12 * k + 12
    f[o] = -1.0  # lo
    f[o + 1] = 1.0  # hi
    f[o + 5 : o + 14] = [0.01, 1e-10, 0.2, 100.0, 1e-8, 2.0, 0.81, 0.5, 0.2]
    g = np.array([k, 2, 20, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0], dtype=np.int64)
    table = np.zeros((n, k))
    tab32 = np.zeros((13, n), dtype=np.float32)
    sf, d, si = np.zeros(3 * k + 3), np.empty(n, np.float32), np.zeros(_NC + 4, np.int64)
    ur = np.zeros(0)
    return (f, g, table, tab32, ur, sf, d, si, np.zeros(1), True, True, np.eye(4), 1e-10, 1e-10,
            1, 1)  # fmt: skip


def warm_up() -> None:
    """Compile :func:`query` for the argument types :mod:`.single` passes."""
    entry()(*_example())
