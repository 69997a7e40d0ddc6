"""The fast path of :func:`app.kinematics.ik.solve`: one solution nearest the seed, full pose.

The HTTP default (one solution, ranked by seed distance, no ``accept`` predicate, no
clearance, no random generator, the full pose on a chain with the compiled search) spent
three quarters of its served time in Python around the compiled search: the query's
:class:`~.search.Search`, the named tuples unboxed into each compiled call, the
verification and the ranking's bookkeeping. Here the same query is

1. the unreachable check (:func:`~.failure.unreachable_detail`, in Python: a few floats);
2. :func:`.query_kernel.query`: the compiled UR closed form where the chain has one (its
   first candidate, as :func:`~.solve` offers them) or else the compiled search, and the
   branch code and manipulability of the answered configuration, in one call per chunk of
   attempts (the clock and the cancel flag are read between chunks, as
   :func:`.compiled.run_compiled` does); other closed forms (the planar 2-link arm) run in
   Python first, as in :func:`~.solve`;
4. :func:`verify`: Pinocchio's independent check of the answered configuration (the wire
   configuration within the joint limits, ``forwardKinematics`` + ``updateFramePlacement``
   on this thread's Data, the pose error against the target within the tolerances), exactly
   :meth:`.search.Search.offer`'s for the full pose. Nothing is answered as a success that
   it has not passed.

The answer is the general path's: the same iterates, counts and clock readings, the same
solution, errors, ``seed_distance``, label and manipulability. Whenever the general path
would do more (the unreachable descent, a candidate or a converged iterate that Pinocchio
refuses, after which the general search continues), :func:`solve_single` returns None
before the result is built, and :func:`~.solve` runs the general path from the start with
the same deadline. A search that ends without a solution is answered through a
:class:`~.search.Search` holding the kernel's counts and best iterate, whose ``result``
gives the failure's reason as the general path does.
"""

from __future__ import annotations

import math
import threading
from operator import sub
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

from app.kinematics.errors import Cancelled
from app.kinematics.ik import branch_kernel
from app.kinematics.ik.boundary import ITERATIONS, RESTARTS
from app.kinematics.ik.failure import unreachable_detail
from app.kinematics.ik.kernel import CAPPED, CONVERGED
from app.kinematics.ik.problem import IKProblem
from app.kinematics.ik.query_kernel import (
    ANALYTIC,
    NO_CANDIDATE,
    QueryState,
    entry,
    new_query_state,
)
from app.kinematics.ik.search import (
    IKResult,
    IKSolution,
    Search,
    frame_placement,
    full_pose_error,
    wire_candidate,
    within_limits,
)

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.ik.problem import IKOptions, Task
    from app.kinematics.ik.search import Clock
    from app.kinematics.models import RobotModel

_hypot, _isfinite = math.hypot, math.isfinite


def verify(
    robot: RobotModel, ch: IKChain, q_seed: np.ndarray, qa: np.ndarray, target: pin.SE3,
    tol_p: float, tol_r: float,
) -> tuple[np.ndarray, float, float] | None:  # fmt: skip
    """(wire q, position error (m), orientation error (rad)) of the chain configuration
    ``qa`` (k,) when Pinocchio confirms it: the seed with the active joints replaced,
    continuous joints wrapped, within every wire joint's limits, and the frame's placement
    T (``forwardKinematics`` + ``updateFramePlacement``) within the tolerances of ``target``
    on the errors ‖R_tᵀ(p − p_t)‖ = ‖p − p_t‖ and ‖log3(R_tᵀ R)‖ = ‖log3(R R_tᵀ)‖ (both
    finite); else None. The check of :meth:`.search.Search.offer` for the full pose."""
    q = wire_candidate(robot, ch, q_seed, qa)
    if not within_limits(ch, q):
        return None
    x, y, z, a, b, c = full_pose_error(frame_placement(robot, ch, q), target)
    ep, er = _hypot(x, y, z), _hypot(a, b, c)
    if not (ep <= tol_p and er <= tol_r and _isfinite(ep) and _isfinite(er)):
        return None
    return q, ep, er


def applies(
    ch: IKChain, options: IKOptions, task: Task, accept: object, rng: object, clearance: object
) -> bool:
    """Whether the fast path answers this query as the general path would: one solution
    ranked by seed distance, no ``accept``, ``rng`` nor ``clearance``, the full pose on a
    chain with the compiled search and annotation."""
    return (
        options.num_solutions == 1
        and options.rank_by == "seed_distance"
        and accept is None
        and rng is None
        and clearance is None
        and task.full_pose
        and ch.query_constants is not None
    )


def solve_single(
    robot: RobotModel,
    ch: IKChain,
    target: pin.SE3,
    options: IKOptions,
    task: Task,
    q_seed: np.ndarray,
    *,
    t_start: float,
    deadline: float,
    clock: Clock,
    cancel: threading.Event | None,
    annotate: bool,
) -> IKResult | None:
    """The query's result by the fast path (module doc), or None: the general path must
    answer it (the target is beyond the reach bound, or Pinocchio refused a candidate)."""
    tol_p, tol_r = float(options.tolerance[0]), float(options.tolerance[1])
    if unreachable_detail(robot, ch, q_seed, target, task, tol_p) is not None:
        return None
    if options.analytic and ch.query_constants.ur.size:
        method = "analytic"  # the UR closed form, compiled with the search (query_kernel)
    elif options.analytic:
        from app.kinematics.analytic_ik import candidates

        cands = candidates(robot, ch, target, options.mode, q_seed)
        if cands is not None:
            for qa in cands:
                checked = verify(robot, ch, q_seed, qa, target, tol_p, tol_r)
                if checked is None:
                    return None  # the general path goes on with what it learnt
                return _success(robot, ch, checked, q_seed, qa, None, annotate, 0, 0, "analytic",
                                (clock() - t_start) * 1e3)  # fmt: skip
            method = "analytic+numeric"
        else:
            method = "numeric"
    else:
        method = "numeric"
    return _search(robot, ch, target, options, task, q_seed, tol_p, tol_r, t_start, deadline,
                   clock, cancel, annotate, method)  # fmt: skip


def _search(
    robot, ch, target, options, task, q_seed, tol_p, tol_r, t_start, deadline, clock, cancel,
    annotate, method,
) -> IKResult | None:  # fmt: skip
    """The compiled search and its verified answer (or its failure)."""
    qc = ch.query_constants
    k = qc.k
    state = ch.idle_query_states.pop(threading.get_ident(), None)
    if state is None:
        state = new_query_state(qc)
    sf, d, si = state
    H = np.ascontiguousarray(target.homogeneous, dtype=np.float64)
    cap = options.max_iterations if options.max_iterations is not None else 1 << 62
    chunk_attempts = ch.parameters.chunk_attempts
    analytic = method == "analytic"
    # the first attempt runs even when the budget is already spent (as run_compiled); the
    # closed form first, before the clock is read (as solve)
    chunk = 0 if analytic else (1 if clock() >= deadline else chunk_attempts)
    run = entry()
    f, g, table, tab32, ur = qc.f, qc.g, qc.table, qc.tab32, qc.ur
    tol_p2, tol_r2 = tol_p**2, tol_r**2
    timed_out = False
    fresh = True
    try:
        while True:
            outcome = run(f, g, table, tab32, ur, sf, d, si, q_seed, fresh, analytic, H, tol_p2,
                          tol_r2, cap, chunk)  # fmt: skip
            fresh = False
            chunk = chunk_attempts
            if outcome == ANALYTIC:
                qa = sf[:k].copy()
                checked = verify(robot, ch, q_seed, qa, target, tol_p, tol_r)
                if checked is None:
                    return None  # the general path goes on with what it learnt
                code, w = float(sf[3 * k + 1]), float(sf[3 * k + 2])
                return _success(robot, ch, checked, q_seed, qa, (code, w), annotate, 0, 0,
                                method, (clock() - t_start) * 1e3)  # fmt: skip
            if outcome == NO_CANDIDATE:  # the closed form proves nothing: search
                method, analytic = "analytic+numeric", False
                chunk = 1 if clock() >= deadline else chunk_attempts
                continue
            if outcome == CAPPED:
                break
            if outcome == CONVERGED:
                qa = sf[:k].copy()
                checked = verify(robot, ch, q_seed, qa, target, tol_p, tol_r)
                if checked is None:
                    return None  # the general search would go on from here: run it whole
                code, w = float(sf[3 * k + 1]), float(sf[3 * k + 2])
                return _success(robot, ch, checked, q_seed, qa, (code, w), annotate,
                                int(si[ITERATIONS]), int(si[RESTARTS]), method,
                                (clock() - t_start) * 1e3)  # fmt: skip
            if si[ITERATIONS] >= cap:
                break
            if clock() >= deadline:
                timed_out = True
                break
            if cancel is not None and cancel.is_set():
                raise Cancelled()
        return _failure(robot, ch, target, options, task, q_seed, state, timed_out, clock,
                        cancel, annotate, method, t_start)  # fmt: skip
    finally:
        ch.idle_query_states[threading.get_ident()] = state  # free again for this thread


def _success(
    robot, ch, checked, q_seed, qa, annotation, annotate, iterations, restarts, method, elapsed
) -> IKResult:
    """The answer of a verified configuration (as :func:`.ranking.representatives`' single
    solution): its seed distance and, with ``annotate``, its label and manipulability (from
    the kernel's ``annotation`` (code, w), else compiled here for the closed forms)."""
    q, ep, er = checked
    if robot.has_continuous:
        sd = float(np.abs(robot.difference(q, q_seed)).max(initial=0.0))
    else:
        sd = max(map(abs, map(sub, q.tolist(), q_seed.tolist())), default=0.0)
    sol = IKSolution(q, ep, er, seed_distance=sd)
    if annotate:
        if annotation is None:
            from app.kinematics.ik.annotate import annotate as compiled_annotation

            label, sol.manipulability = compiled_annotation(ch, q[ch.active])
        else:
            code, sol.manipulability = annotation
            label = branch_kernel.label(ch.branch_form, int(code)) if ch.branch_form else None
        sol.branch = "cluster_0" if label is None else label
    return IKResult(True, "converged", q, ep, er, [sol], iterations, restarts, elapsed, method)


def _failure(
    robot, ch, target, options, task, q_seed, state: QueryState, timed_out, clock, cancel,
    annotate, method, t_start,
) -> IKResult:  # fmt: skip
    """The result of a search without a solution, through a :class:`Search` holding the
    kernel's counts and best iterate (its reason, :mod:`.failure`)."""
    k = ch.k
    sf, _, si = state
    s = Search(IKProblem(robot, ch, target, q_seed, options, task), cancel=cancel,
               annotate=annotate, clock=clock)  # fmt: skip
    s.iterations, s.restarts, s.timed_out = int(si[ITERATIONS]), int(si[RESTARTS]), timed_out
    best = float(sf[3 * k])
    if best < s.best_energy:
        s.best_energy = best
        s.best_q = s.wire(sf[2 * k : 3 * k].copy())
    return s.result(method, t_start)
