"""Numeric inverse kinematics: damped least squares with restarts, in wire joint space.

The package, one concept per module:

- :mod:`.problem`: the options (:class:`~.problem.IKOptions`), targets and seeds, validated
  once for every caller;
- :mod:`.precompute`: what is built once per (robot, frame) (:class:`~.precompute.IKChain`:
  active joints, restart table and its poses);
- :mod:`.search`: one query's state, the verification of candidates, restarts, the result;
- :mod:`.dls`: the damped least-squares loop in Python (every mode, every chain);
- :mod:`.parameters`: every tunable of the solver, by name
  (:class:`~.parameters.SolverParameters`, :data:`~.parameters.DEFAULT_PARAMETERS`);
- :mod:`.kernel`, :mod:`.search_kernel`: the compiled attempt and the compiled whole search
  (Numba), and the named tuples they take;
- :mod:`.compiled`: the driver of the compiled search, full pose only;
- :mod:`.single`, :mod:`.query_kernel`: the fast path when one solution nearest the seed is
  wanted (the HTTP default): the closed form or the search and the answer's annotation in
  one compiled call per chunk, one Pinocchio check, the general path's answers;
- :mod:`.annotate`: an answer's branch label and manipulability in compiled code;
- :mod:`.joint_frames`: the chain's joint frames in compiled code (axes, origins, wrist
  point), for the annotation and the paths' compiled point;
- :mod:`.warmup`: compiling every kernel once per process;
- here: :func:`solve`, which ties them together.

Problem
-------
Find a wire configuration q within the joint limits such that the placement of ``frame``,
oMf(q) = (R, p), equals the target oMt = (R_t, p_t) in the root (world) frame.

Error and its Jacobian
----------------------
The error is the *decoupled* SE(3) error in **world axes**::

    e(q) = [ e_p ; e_R ] = [ p − p_t ; log3(R R_tᵀ) ]                  (6,)

so ‖e_p‖ is the position error (m) and ‖e_R‖ the rotation angle between the frame and the
target (rad), exactly the two numbers the tolerances bound. With the frame Jacobian
J = [J_v; J_ω] in Pinocchio's ``LOCAL_WORLD_ALIGNED`` (ṗ = J_v q̇, Ṙ = [J_ω q̇]× R) and
R_e = R R_tᵀ:

    d e_p / dq = J_v
    d e_R / dq = Jlog3(R_e)ᵀ · J_ω

Derivation: Ṙ_e = [ω]× R_e is a *left* perturbation, R_e(t + dt) = exp(ω dt)·R_e =
R_e·exp(R_eᵀ ω dt); Pinocchio's Jlog3 is the right-Jacobian inverse J_r⁻¹ (the derivative
of log3(R_e·exp(δ)) at δ = 0), so d log3(R_e) = J_r⁻¹(φ) R_eᵀ ω = J_l⁻¹(φ) ω, and
J_l⁻¹(φ) = J_r⁻¹(−φ) = J_r⁻¹(φ)ᵀ. (Checked against finite differences in the tests.)

The step below needs J_e only through the linear system J_e·Δq = −e. With
L = blockdiag(I, Jlog3(R_e)ᵀ), J_e = L·J and L⁻¹e = [e_p; J_r(φ)ᵀ φ] = e, because the
rotation vector φ is an eigenvector of the right Jacobian J_r(φ) (J_r(φ)·φ = J_r(φ)ᵀ·φ = φ).
So J_e·Δq = −e ⟺ J·Δq = −e: the Gauss–Newton step, and the minimum-norm one of a redundant
chain ((L·J)⁺ = J⁺·L⁻¹ for full row rank), are exactly those of the plain frame Jacobian, and
the solver skips the product with L (it differs only through the damping term). When the
task keeps only some of the rotation rows (a zero weight), that equivalence no longer holds
and the rows of J_e are used.

Unlike the coupled ``log6`` error (whose translation part is V(ω)⁻¹·Rᵀp, a screw motion),
the decoupled error drives the origin along a straight line and the orientation along the
geodesic independently (the error KDL and TRAC-IK use). Both have the same zero set.

Step (Levenberg–Marquardt damped least squares)
-----------------------------------------------
With the task rows selected by ``mode``/``weights`` (row i scaled by √w_i), J_e the error
Jacobian restricted to the joints supporting the frame, and, for redundant chains (more
joints than task rows) during the attempt from the seed, a null-space preference
z = α(E)·(q_ref − q) towards the seed (restarts start far from the seed, where that pull
would only fight convergence)::

    A  = J_e J_eᵀ + λ² I,        λ² = c·‖e‖² + μ        (error-proportional LM damping)
    Δq = z − J_eᵀ A⁻¹ (e + J_e z)

which is the damped least-squares step Δq = −J_eᵀ A⁻¹ e plus the projection of z on the
(damped) null space, (I − J_eᵀ A⁻¹ J_e) z, in one linear solve (LAPACK ``posv``: A is
symmetric positive definite). The damping shrinks with the error, so the iteration is
Gauss–Newton (quadratic convergence) near a solution and a bounded step far from it or near
singularities. The null-space gain α fades with the error (α ∝ ‖e‖² below 0.1): a constant
pull leaves a second-order task error at every step and makes convergence linear.

Limits and restarts
-------------------
Every iterate is clipped to the joint limits; continuous joints are wrapped to (−π, π]. On
redundant chains, joints already at a limit that the step pushes further are locked for that
step (their columns removed and the step recomputed), so the other joints take over. When
the error stalls (no 10 % decrease in two iterations, or 20 iterations in one attempt) the
solver restarts: first from the samples of a fixed per-chain table (4096 configurations
uniform within the limits, with their FK poses) nearest the target pose
(‖p − p_t‖² + 0.2·‖R − R_t‖²_F), then from uniform random configurations (TRAC-IK's random
jumps), until the time budget or the iteration cap is spent. When the seed's pose is more
than twice as far from the target (in that distance) as the nearest table sample, the
solver jumps to that sample right after the first iteration: a seed close to the target
(trajectory following, a good guess) is always used, a far one (the benchmark's mid-range
seed) costs one evaluation. Only the joints that support the frame move; the others keep
their seed value.

Every solution is verified by a separate forward-kinematics evaluation at the returned
wire configuration (error against the target, joint limits, and the optional ``accept``
predicate, e.g. collision-free) before it is reported as a success.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Mapping, Sequence

import numpy as np
import pinocchio as pin

from app.kinematics.analytic_ik import candidates
from app.kinematics.errors import Cancelled, KinematicsError
from app.kinematics.groups import default_frame, group
from app.kinematics.ik import precompute
from app.kinematics.ik.compiled import run_compiled
from app.kinematics.ik.dls import run_python
from app.kinematics.ik.failure import UNREACHABLE_ITERATIONS, unreachable_detail
from app.kinematics.ik.parameters import DEFAULT_PARAMETERS, SolverParameters
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.ik.problem import (
    IKOptions,
    IKProblem,
    check_target,
    frame_name,
    seed_configuration,
)
from app.kinematics.ik.ranking import check_rank_by
from app.kinematics.ik.search import Clock, IKResult, Search
from app.kinematics.ik.single import applies, solve_single
from app.kinematics.ik.version import SOLVER_VERSION
from app.kinematics.models import RobotModel

__all__ = [
    "DEFAULT_PARAMETERS",
    "SOLVER_VERSION",
    "IKResult",
    "SolverParameters",
    "chain_ready",
    "solve",
]

_DEFAULT_OPTIONS = IKOptions()


def solve(
    robot: RobotModel,
    target: pin.SE3,
    options: IKOptions = _DEFAULT_OPTIONS,
    *,
    seed: Sequence[float] | np.ndarray | Mapping[str, float] | None = None,
    accept: Callable[[np.ndarray], bool] | None = None,
    rng: np.random.Generator | None = None,
    cancel: threading.Event | None = None,
    clearance: Callable[[np.ndarray], float] | None = None,
    annotate: bool = False,
    parameters: SolverParameters = DEFAULT_PARAMETERS,
    clock: Clock = time.perf_counter,
) -> IKResult:
    """Joint configurations placing ``options.frame`` at ``target``.

    Parameters
    ----------
    robot
        The robot.
    target
        Desired placement of the frame in the root (world) frame.
    options
        Frame, mode, weights, tolerances, budget, solutions wanted, closed forms
        (:class:`~app.kinematics.ik.problem.IKOptions`, validated when built).
    seed
        Configuration to start from: one value per joint (wire order) or joint → value (see
        :func:`~app.kinematics.ik.problem.seed_configuration`); default the middle of the
        joint limits. Joints that do not support the frame keep their seed value in every
        answer.
    accept
        Optional predicate on a converged wire configuration; a rejected solution is dropped
        and the search continues (e.g. collision-aware IK).
    rng
        Random generator for restarts (default: a fixed per-chain table of uniform samples,
        so answers are reproducible).
    cancel
        Optional event: once set (the caller's client went away), the search stops within
        one iteration (the Python loop) or one chunk of attempts (compiled,
        ``parameters.chunk_attempts`` attempts of ≤ 20 iterations) and
        :class:`~app.kinematics.errors.Cancelled` is raised.
    clearance
        Optional ``q ↦`` smallest robot–obstacle distance (m)
        (:func:`~app.kinematics.ik.ranking.clearance_function`): reported with each solution,
        and required by ``options.rank_by == "clearance"`` (else InvalidInputError naming
        ``rank_by``).
    annotate
        Label every answered solution with its ``branch`` and ``manipulability`` (the HTTP
        answer). Default False: only what the ranking needs (labels when several solutions
        are wanted, manipulability when ranked by it), so a single solution nearest the seed
        costs no label nor Jacobian (the benchmark's and trajectories' hot path).
    parameters
        The solver's tunables (:class:`~app.kinematics.ik.parameters.SolverParameters`;
        default :data:`~app.kinematics.ik.parameters.DEFAULT_PARAMETERS`, what every
        endpoint uses). The chain and its restart table are built and cached per parameters.
    clock
        The clock the time budget is measured on (s; default ``time.perf_counter``): a test
        passes a fake one to exhaust the budget deterministically.

    Returns
    -------
    IKResult
        ``success`` when at least one verified solution was found; the solutions come back
        one per branch, labelled and ranked by ``options.rank_by`` (:mod:`.ranking`), and the
        search stops early once ``options.num_solutions`` branches are found (closed forms:
        every closed-form candidate is verified first when several solutions are wanted or
        the ranking is not by seed distance). Otherwise ``q`` is the lowest-error
        configuration met, ``status`` says whether the time budget (``timeout``) or the
        iteration cap (``not_converged``) ended the search, and ``reason``/``detail`` say why
        (:mod:`.failure`; ``unreachable`` skips the search).
    """
    grp = group(robot, options.group)
    frame = frame_name(robot, default_frame(robot, grp, options.frame))
    ch = ik_chain(robot, frame, grp, parameters)
    # The budget starts once the chain is prepared: its one-time set-up (restart table,
    # ~20 ms on the first query of a robot and frame) is not charged to the first query.
    t_start = clock()
    q_seed = ch.mid_range.copy() if seed is None else np.array(seed_configuration(robot, seed))
    check_target(target)
    deadline = t_start + options.timeout_ms * 1e-3
    if cancel is not None and cancel.is_set():
        raise Cancelled()
    check_rank_by(options.rank_by, clearance)
    task = options.task()
    if applies(ch, options, task, accept, rng, clearance):
        res = solve_single(
            robot, ch, target, options, task, q_seed, t_start=t_start, deadline=deadline,
            clock=clock, cancel=cancel, annotate=annotate,
        )  # fmt: skip
        if res is not None:
            return res
    problem = IKProblem(robot, ch, target, q_seed, options, task)
    search = Search(
        problem,
        accept=accept,
        cancel=cancel,
        rng=rng,
        clearance=clearance,
        annotate=annotate,
        clock=clock,
    )
    far = unreachable_detail(robot, ch, q_seed, target, task, search.tol_p)
    if far is not None:
        # No solution exists: a short best-effort descent towards the target, then the reason.
        cap = min(options.max_iterations or UNREACHABLE_ITERATIONS, UNREACHABLE_ITERATIONS)
        _descend(search, deadline, cap)
        res = search.result("numeric", t_start)
        res.reason, res.detail = "unreachable", far
        return res

    method = "numeric"
    if options.analytic:
        cands = candidates(robot, ch, target, options.mode, q_seed)
        if cands is not None:
            method = "analytic"
            every = options.num_solutions > 1 or options.rank_by != "seed_distance"
            for qa in cands:
                search.offer(qa)
                if search.done() and not every:
                    break
    if not search.done():
        if method == "analytic":
            method = "analytic+numeric"
        _descend(search, deadline, options.max_iterations)
    return search.result(method, t_start)


def chain_ready(
    robot: RobotModel, options: IKOptions, parameters: SolverParameters = DEFAULT_PARAMETERS
) -> bool:
    """Whether the chain :func:`solve` needs for ``options`` is built already: else the first
    query builds it (the restart table's poses, tens of ms), and a caller on an event loop
    runs that query elsewhere. False for a bad frame or group too (:func:`solve` raises the
    error, wherever it runs)."""
    try:
        grp = group(robot, options.group)
        frame = frame_name(robot, default_frame(robot, grp, options.frame))
    except KinematicsError:
        return False
    return precompute.chain_ready(robot, frame, grp, parameters)


def _descend(search: Search, deadline: float, max_iterations: int | None) -> None:
    """The numeric search: the compiled loop where it applies (full pose), else Python."""
    if search.full_pose and search.ch.compiled is not None:
        run_compiled(search, deadline, max_iterations)
    else:
        run_python(search, deadline, max_iterations)
