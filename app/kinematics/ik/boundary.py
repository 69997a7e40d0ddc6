"""What crosses the Numba boundary of the solver: named tuples, no positional soup.

The compiled kernels (:mod:`.kernel`: one attempt; :mod:`.search_kernel`: the whole search)
take these instead of dozens of positional arguments; Numba compiles a ``NamedTuple`` into a
struct, so fields are read by name at no cost inside compiled code.

- :class:`ChainConstants`: one chain's kinematics and limits (built once per chain);
- :class:`StepParameters`: the loop's tunables as the kernels read them (from
  :class:`~app.kinematics.ik.parameters.SolverParameters`);
- :class:`SearchConstants`: the above plus the restart table and the search's switches;
- :class:`SearchState`: one query's arrays, updated in place between calls, with its
  :data:`COUNTERS`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np

if TYPE_CHECKING:
    from app.kinematics.ik.parameters import SolverParameters


class ChainConstants(NamedTuple):
    """What the kernels read of one (robot, frame) chain of k 1-DoF joints (root frame, m).

    ``C`` (k, 3, 3), ``t`` (k, 3): each joint's fixed placement in its parent (the joint
    axis is the local z); ``prism`` (k,): prismatic (else revolute or continuous);
    ``last_C`` (3, 3), ``last_t`` (3,): the frame's placement in the last joint;
    ``lo``, ``hi`` (k,): the limits every iterate is clipped to (±inf: none); ``cont``
    (k,): continuous joints (wrapped to (−π, π]).
    """

    C: np.ndarray
    t: np.ndarray
    prism: np.ndarray
    last_C: np.ndarray
    last_t: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    cont: np.ndarray


class StepParameters(NamedTuple):
    """The loop's tunables as the kernels read them
    (:class:`~app.kinematics.ik.parameters.SolverParameters`, :func:`step_parameters`)."""

    damp: float
    mu: float
    gain: float
    null_scale: float  # 1 / null_energy
    null_floor: float
    max_step: float
    progress: float
    stall: int
    attempt_cap: int


def step_parameters(p: SolverParameters, attempt_cap: int | None = None) -> StepParameters:
    """The kernels' view of ``p`` (``attempt_cap`` overrides ``p.attempt_cap``)."""
    return StepParameters(
        float(p.damp), float(p.mu), float(p.null_gain), 1.0 / p.null_energy,
        float(p.null_floor), float(p.max_step), float(p.progress), int(p.stall),
        int(p.attempt_cap if attempt_cap is None else attempt_cap),
    )  # fmt: skip


#: The search's counters, in order, in ``SearchState.counters`` (int64): Jacobian
#: evaluations so far; restarts taken; phase (0: the seed not checked yet, 1: a restart is
#: due, 2: ``qa`` starts the next attempt); whether the table distances are known; index of
#: the nearest table sample; whether the nearest samples are ranked; how many are.
COUNTERS = ("iterations", "restarts", "phase", "distances_known", "nearest_one", "ranked", "n_near")
ITERATIONS, RESTARTS, PHASE, DISTANCES_KNOWN, NEAREST_ONE, RANKED, N_NEAR = range(len(COUNTERS))
_COUNTERS0 = np.zeros(len(COUNTERS), dtype=np.int64)


class SearchConstants(NamedTuple):
    """What :func:`search` reads of a chain and the parameters, built once with the chain.

    ``nearest_ratio``, ``rot_weight``: :class:`~app.kinematics.ik.parameters.SolverParameters`'
    fields; ``null_on``: the null-space pull on the attempt from the seed (redundant chains);
    ``clamp``: lock joints pushed against a limit (redundant chains); ``nearest_first``: the
    jump from a far seed; ``tab32`` (13, N) float32: the restart table's poses
    (−2·[p | c·vec(R)] transposed, then ‖p‖² + 3c); ``table`` (N, k): its configurations.
    """

    chain: ChainConstants
    step: StepParameters
    nearest_ratio: float
    rot_weight: float
    null_on: bool
    clamp: bool
    nearest_first: bool
    tab32: np.ndarray
    table: np.ndarray


class SearchState(NamedTuple):
    """One query's arrays, updated in place by :func:`search` (see :func:`new_state`).

    ``qa`` (k,): the current start or, on ``CONVERGED``, the converged iterate; ``q_ref``
    (k,): the seed (the null-space reference); ``best_q`` (k,), ``best`` (1,): the
    lowest-energy unconverged iterate and its energy ‖e‖²; ``d`` (N,) float32: the table
    distances; ``near`` (nearest,) int64: the nearest samples; ``counters``: :data:`COUNTERS`.
    """

    qa: np.ndarray
    q_ref: np.ndarray
    best_q: np.ndarray
    best: np.ndarray
    d: np.ndarray
    near: np.ndarray
    counters: np.ndarray


def reset_state(
    state: SearchState, qa: np.ndarray, best: float, iterations: int, restarts: int, n_near: int
) -> None:
    """Make a used ``state`` a fresh one (as :func:`new_state`) starting from ``qa``, with
    ``best`` the best energy so far, the iteration and restart counts so far and ``n_near``
    nearest samples to rank; every other counter 0 (phase 0: the search copies ``qa`` into
    ``q_ref`` and ``best_q``, and recomputes the table distances and the nearest samples),
    so nothing of the last query is read. A few writes instead of seven allocations; the
    arrays stay in cache."""
    state.qa[:] = qa
    state.best[0] = best
    c = state.counters
    c.fill(0)
    c[ITERATIONS] = iterations
    c[RESTARTS] = restarts
    c[N_NEAR] = n_near


def new_state(qa: np.ndarray, best: float, n_near: int, n_table: int) -> SearchState:
    """A fresh state starting from ``qa`` ((k,) float64, C-contiguous: taken, not copied),
    ``best`` the best energy so far, ``n_near`` nearest samples to rank (at most the table's
    ``n_table`` samples)."""
    counters = _COUNTERS0.copy()
    counters[N_NEAR] = n_near
    return SearchState(
        qa, qa.copy(), qa.copy(), np.array([best]), np.empty(n_table, dtype=np.float32),
        np.empty(n_near, dtype=np.int64), counters,
    )  # fmt: skip
