"""Numeric inverse kinematics: damped least squares with restarts, in wire joint space.

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

import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
import pinocchio as pin
from scipy.linalg.lapack import dposv as _posv

from app.kinematics import analytic_ik, ik_kernel
from app.kinematics.analytic_ik import candidates
from app.kinematics.errors import Cancelled, InvalidInputError
from app.kinematics.models import MAX_JOINT_VALUE, MAX_POSITION, RobotModel, check_joint_values

Mode = Literal["pose", "position", "orientation"]
Status = Literal["converged", "not_converged", "timeout"]

MODES: tuple[str, ...] = ("pose", "position", "orientation")
#: Task rows of each mode in e = [e_p; e_R].
MODE_ROWS = {"pose": (0, 1, 2, 3, 4, 5), "position": (0, 1, 2), "orientation": (3, 4, 5)}

#: Default tolerances: position (m) and orientation (rad).
DEFAULT_TOLERANCE = (1e-5, 1e-5)
#: Default time budget (ms).
DEFAULT_TIMEOUT_MS = 5.0
#: Two solutions are distinct when some joint differs by more than this (rad or m).
DISTINCT = 1e-3

_TWO_PI = 2.0 * math.pi
#: Damping floor μ added to λ² (keeps A invertible at exact singularities).
_MU = 1e-10
#: Error-proportional damping: λ² = _DAMP·‖e‖² + μ.
_DAMP = 0.01
#: Null-space gain α towards the reference configuration (redundant chains only).
_NULL_GAIN = 0.2
#: Squared task error below which the null-space gain fades proportionally (a constant pull
#: would leave a second-order task error each step and make convergence linear).
_NULL_ENERGY = 1e-2
#: Squared task error below which the (faded) null-space term is skipped altogether.
_NULL_FLOOR = 1e-8
#: Largest joint step per iteration (rad or m), keeps the linearisation honest.
_MAX_STEP = 2.0
#: Iterations without a 10 % error decrease before a restart.
_STALL = 2
#: Iteration cap of one attempt (from the seed or a restart).
_ATTEMPT_CAP = 20
#: Restarts taken from the table samples nearest the target before random jumps, and the
#: weight of the rotation distance (‖R − R_t‖²_F) against the position distance (m²).
_NEAREST = 32
_ROT_WEIGHT = 0.2
#: Jump from the seed to the nearest table sample at once when that sample's pose is much
#: closer to the target (distance ratio below _NEAREST_RATIO).
_NEAREST_FIRST = True
_NEAREST_RATIO = 0.5
#: Seed and size of the per-chain table of restart configurations.
_RNG_SEED = 0x1C0DE
_TABLE = 4096
#: Lock joints pushed against a limit for the step (active-set clamping).
_CLAMP = True


@dataclass(slots=True)
class IKSolution:
    """One verified solution: wire configuration and its errors against the target."""

    q: np.ndarray
    position_error: float
    orientation_error: float


@dataclass(slots=True)
class IKResult:
    """Outcome of :func:`solve`.

    ``q`` is the best configuration (the first solution, or the lowest-error iterate when
    nothing converged); ``solutions`` are distinct verified solutions sorted by distance to
    the seed. ``iterations`` counts Jacobian evaluations over all attempts, ``restarts`` the
    random jumps, ``method`` is ``analytic``, ``numeric`` or ``analytic+numeric``.
    """

    success: bool
    status: Status
    q: np.ndarray
    position_error: float
    orientation_error: float
    solutions: list[IKSolution] = field(default_factory=list)
    iterations: int = 0
    restarts: int = 0
    solve_time_ms: float = 0.0
    method: str = "numeric"


class Chain:
    """What the solver precomputes for one (robot, frame): the joints that move it.

    Built once per model and frame (``RobotModel.lazy``) and read-only afterwards.
    """

    def __init__(self, robot: RobotModel, frame: str) -> None:
        self.frame = frame
        self.frame_id = robot.frame_id(frame)
        self.active = robot.supporting_joints(frame)  # wire indices
        joints = [robot.joints[i] for i in self.active]
        self.k = len(joints)
        self.cols = np.array([j.idx_v for j in joints], dtype=int)
        cont = np.array([j.continuous for j in joints], dtype=bool)
        self.has_continuous = bool(cont.any())
        self.plain = np.flatnonzero(~cont)  # positions within the active set
        self.plain_q = np.array([j.idx_q for j in joints if not j.continuous], dtype=int)
        self.cont = np.flatnonzero(cont)
        self.cont_q = np.array([j.idx_q for j in joints if j.continuous], dtype=int)
        self.cont_q1 = self.cont_q + 1
        # Searched within the limits, and within ±MAX_JOINT_VALUE (what every endpoint accepts
        # back) when a URDF gives wider limits; continuous joints (±inf) are wrapped instead.
        lo, hi = robot.lower[self.active], robot.upper[self.active]
        self.lower = np.where(np.isfinite(lo), np.maximum(lo, -MAX_JOINT_VALUE), lo)
        self.upper = np.where(np.isfinite(hi), np.minimum(hi, MAX_JOINT_VALUE), hi)
        # Restart sampling box: the limits, or one turn for continuous joints.
        self.sample_lo = np.where(np.isfinite(self.lower), self.lower, -math.pi)
        self.sample_hi = np.where(np.isfinite(self.upper), self.upper, math.pi)
        # A fixed table of restart configurations (uniform in the box): restarts cost no
        # random-number setup per query, and answers are reproducible.
        u = np.random.default_rng(_RNG_SEED).random((_TABLE, self.k))
        self.restart_table = self.sample_lo + (self.sample_hi - self.sample_lo) * u
        self.clip_lo = np.where(np.isfinite(self.lower), self.lower, -np.inf)
        self.clip_hi = np.where(np.isfinite(self.upper), self.upper, np.inf)
        # Index objects of the hot loop: slices (views, no copies) when contiguous.
        self.cols_sel = _as_slice(self.cols)
        self.plain_q_sel = _as_slice(self.plain_q) if not self.has_continuous else self.plain_q
        self.mid_range = robot.mid_range()
        #: Closed-form geometry of the chain, set on first use by ``analytic_ik``.
        self.closed_form: tuple | None = None
        self._robot = robot
        self._poses: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
        self._poses_T: np.ndarray | None = None  # M transposed, for the compiled distances
        self.sample_poses()  # built now, so no query pays for it
        #: The compiled loop's constants (:mod:`ik_kernel`), or None: the Python loop.
        self.compiled = (
            ik_kernel.CompiledChain.build(robot, frame, self.active)
            if ik_kernel.available()
            else None
        )
        warm_up()  # compiled now, outside any query's time budget
        analytic_ik.prepare(robot, self)
        self.cont_mask = cont

    def sample_poses(self) -> tuple[np.ndarray, np.ndarray]:
        """Poses of the restart table: M = −2·[p | c·vec(R)] (N, 12) and ‖p‖² + 3c (N,).

        With them the pose distance to a target is one matrix-vector product:
        ‖p − p_t‖² + c‖R − R_t‖²_F = (‖p‖² + 3c) − 2·[p | c·vec(R)]·[p_t; vec(R_t)] + K_t,
        K_t = ‖p_t‖² + 3c, using ‖R − R_t‖²_F = 6 − 2 vec(R)·vec(R_t). Computed when the chain
        is built (one FK per sample).
        """
        if self._poses is None:
            robot = self._robot
            model, data = robot.model, robot.model.createData()
            q = self.mid_range.copy()
            W = np.empty((_TABLE, 12))
            for i, row in enumerate(self.restart_table):
                q[self.active] = row
                pin.forwardKinematics(model, data, robot.to_pin(q))
                T = pin.updateFramePlacement(model, data, self.frame_id)
                W[i, :3] = T.translation
                W[i, 3:] = _ROT_WEIGHT * T.rotation.ravel()
            P = W[:, :3]
            # float32: the ranking needs no more, and the product runs twice as fast.
            M = (-2.0 * W).astype(np.float32)
            self._poses = (M, (np.einsum("ij,ij->i", P, P) + 3.0 * _ROT_WEIGHT).astype(np.float32))
            if ik_kernel.available():
                self._poses_T = np.ascontiguousarray(M.T)
        return self._poses

    def sample_distances(self, target: pin.SE3) -> tuple[np.ndarray, float]:
        """Pose distances of the table samples to ``target``, up to the constant K_t returned
        with them (‖p − p_t‖² + c‖R − R_t‖²_F = d_i + K_t)."""
        return self.sample_distances_argmin(target)[:2]

    def sample_distances_argmin(self, target: pin.SE3) -> tuple[np.ndarray, float, int]:
        """:meth:`sample_distances` and the index of the nearest sample."""
        M, W2 = self.sample_poses()
        pt = target.translation
        x = np.concatenate((pt, target.rotation.ravel())).astype(np.float32)
        k_t = float(pt @ pt) + 3.0 * _ROT_WEIGHT
        if self._poses_T is not None:
            d = np.empty(_TABLE, dtype=np.float32)
            i = ik_kernel.sample_distances(self._poses_T, W2, x, d)
            return d, k_t, int(i)
        d = M @ x
        d += W2
        return d, k_t, int(d.argmin())

    def nearest_samples(self, target: pin.SE3, k: int) -> np.ndarray:
        """Indices of the k table samples nearest ``target``, nearest first."""
        return _k_smallest(self.sample_distances(target)[0], k)


def _frame_jacobian_6xn(
    model: pin.Model, data: pin.Data, fid: int, rf: pin.ReferenceFrame
) -> np.ndarray:
    """``pin.getFrameJacobian`` as a (6, nv) array whatever nv (Pinocchio returns (6,) for 1)."""
    return pin.getFrameJacobian(model, data, fid, rf).reshape(6, -1)


def _never() -> bool:
    """The ``cancel.is_set`` of a search nobody can cancel."""
    return False


def _k_smallest(d: np.ndarray, k: int) -> np.ndarray:
    """Indices of the k smallest entries of ``d``, in increasing order."""
    k = min(k, d.size)
    idx = np.argpartition(d, k - 1)[:k]
    return idx[np.argsort(d[idx])]


def _as_slice(idx: np.ndarray) -> slice | np.ndarray:
    """``idx`` as a slice when it is a run of consecutive integers."""
    if idx.size and np.array_equal(idx, np.arange(idx[0], idx[0] + idx.size)):
        return slice(int(idx[0]), int(idx[0]) + idx.size)
    return idx


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


def chain(robot: RobotModel, frame: str) -> Chain:
    """The cached :class:`Chain` of ``frame`` (raises UnknownNameError for a bad frame)."""
    robot.frame_id(frame)
    return robot.lazy(f"ik.chain:{frame}", lambda r: Chain(r, frame))


def pose_errors(T: pin.SE3, target: pin.SE3) -> tuple[float, float, np.ndarray]:
    """Position error (m), rotation angle (rad) and e = [p − p_t; log3(R R_tᵀ)] (world axes)."""
    ep = T.translation - target.translation
    eR = pin.log3(T.rotation @ target.rotation.T)
    return math.hypot(*ep), math.hypot(*eR), np.concatenate([ep, eR])


def wrap_angle(x: np.ndarray) -> np.ndarray:
    """Angles wrapped to [−π, π)."""
    return (x + math.pi) % _TWO_PI - math.pi


def joint_distance(robot: RobotModel, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Per-joint |a − b| on the wire, continuous joints measured around the circle."""
    d = np.abs(a - b)
    if robot.has_continuous:
        c = robot._cont_wire
        d[c] = np.abs(wrap_angle(a[c] - b[c]))
    return d


def _task(
    mode: str, weights: np.ndarray | None
) -> tuple[np.ndarray, np.ndarray | None, bool, bool]:
    """Rows of e to drive, their √weights (None when all 1), and which errors are checked."""
    if weights is None:
        return _TASKS[mode]
    rows = np.array(MODE_ROWS[mode], dtype=int)
    sw = None
    if weights is not None:
        w = np.asarray(weights, dtype=float)[rows]
        keep = w > 0.0
        rows = rows[keep]
        w = w[keep]
        if rows.size == 0:
            raise InvalidInputError("every weight of the chosen mode is zero", "weights")
        if not np.all(w == 1.0):
            sw = np.sqrt(w)
    check_pos = bool(np.any(rows < 3))
    check_rot = bool(np.any(rows >= 3))
    return rows, sw, check_pos, check_rot


_EYES = [np.eye(i) for i in range(7)]
_TASKS = {
    mode: (np.array(rows, dtype=int), None, rows[0] < 3, rows[-1] >= 3)
    for mode, rows in MODE_ROWS.items()
}


def solve(
    robot: RobotModel,
    frame: str,
    target: pin.SE3,
    *,
    mode: Mode = "pose",
    weights: np.ndarray | None = None,
    seed: np.ndarray | None = None,
    tolerance: tuple[float, float] = DEFAULT_TOLERANCE,
    timeout_ms: float = DEFAULT_TIMEOUT_MS,
    max_iterations: int | None = None,
    num_solutions: int = 1,
    accept: Callable[[np.ndarray], bool] | None = None,
    analytic: bool = True,
    rng: np.random.Generator | None = None,
    cancel: threading.Event | None = None,
) -> IKResult:
    """Joint configurations placing ``frame`` at ``target``.

    Parameters
    ----------
    robot, frame
        The robot and the frame to place (any named frame).
    target
        Desired placement of the frame in the root (world) frame.
    mode
        ``pose`` (6-D), ``position`` (orientation free) or ``orientation`` (position free).
    weights
        Optional non-negative weights of the six error components [e_p; e_R] (world
        axes). A zero weight frees that component; tolerances are checked only on the
        components with positive weight, position and orientation separately.
    seed
        Wire configuration to start from (default: middle of the joint limits). Joints that do
        not support ``frame`` keep their seed value in every answer.
    tolerance
        (position m, orientation rad): success when ‖e_p‖ and ‖e_R‖ (over the checked
        components) are within them.
    timeout_ms, max_iterations
        Budget (``time.perf_counter``) and optional cap on Jacobian evaluations.
    num_solutions
        How many distinct solutions to collect; they come back sorted by their distance to
        the seed. The search stops early once this many are found.
    accept
        Optional predicate on a converged wire configuration; a rejected solution is dropped
        and the search continues (e.g. collision-aware IK).
    analytic
        Try closed forms (:mod:`app.kinematics.analytic_ik`) first where the chain admits one.
    rng
        Random generator for restarts (default: a fixed per-chain table of uniform samples,
        so answers are reproducible).
    cancel
        Optional event: once set (the caller's client went away), the search stops within
        one iteration (the Python loop) or one attempt (compiled, ≤ 20 iterations) and
        :class:`~app.kinematics.errors.Cancelled` is raised.

    Returns
    -------
    IKResult
        ``success`` when at least one verified solution was found. Otherwise ``q`` is the
        lowest-error configuration met and ``status`` says whether the time budget
        (``timeout``) or the iteration cap (``not_converged``) ended the search.
    """
    if mode not in MODE_ROWS:
        raise InvalidInputError(f"unknown mode {mode!r}; use one of {', '.join(MODES)}", "mode")
    if num_solutions < 1:
        raise InvalidInputError("must be at least 1", "num_solutions")
    if not timeout_ms > 0.0:
        raise InvalidInputError("must be positive", "timeout_ms")
    if max_iterations is not None and max_iterations < 1:
        raise InvalidInputError("must be at least 1", "max_iterations")
    tol_p, tol_r = float(tolerance[0]), float(tolerance[1])
    if not (tol_p > 0.0 and tol_r > 0.0):
        raise InvalidInputError("tolerances must be positive", "tolerance")
    if weights is not None:
        w = np.asarray(weights, dtype=float)
        if w.shape != (6,) or not np.all(np.isfinite(w)) or np.any(w < 0.0):
            raise InvalidInputError("give 6 finite, non-negative weights", "weights")
    ch = chain(robot, frame)
    # The budget starts once the chain is prepared: its one-time set-up (restart table,
    # ~20 ms on the first query of a robot and frame) is not charged to the first query.
    t_start = time.perf_counter()
    q_seed = ch.mid_range.copy() if seed is None else np.array(seed, dtype=float)
    if q_seed.shape != (robot.n,):
        raise InvalidInputError(f"expected {robot.n} values", "seed")
    check_joint_values(q_seed, "seed")
    if not all(math.isfinite(v) and abs(v) <= MAX_POSITION for v in target.translation):
        raise InvalidInputError(f"must be finite, within ±{MAX_POSITION:g} m", "target.position")
    rows, sw, check_pos, check_rot = _task(mode, weights)
    deadline = t_start + timeout_ms * 1e-3
    if cancel is not None and cancel.is_set():
        raise Cancelled()
    search = _Search(robot, ch, target, q_seed, rows, sw, check_pos, check_rot, tol_p, tol_r)
    search.accept = accept
    search.wanted = num_solutions
    search.cancel = cancel

    method = "numeric"
    if analytic:
        cands = candidates(robot, ch, target, mode, q_seed)
        if cands is not None:
            method = "analytic"
            for qa in cands:
                search.offer(qa)
                if search.done():
                    break
    if not search.done():
        if method == "analytic":
            method = "analytic+numeric"
        search.rng = rng
        search.run(deadline, max_iterations)
    return search.result(method, t_start)


class _Search:
    """State of one IK query: the hot loop, the verified solutions, the best iterate."""

    def __init__(
        self,
        robot: RobotModel,
        ch: Chain,
        target: pin.SE3,
        q_seed: np.ndarray,
        rows: np.ndarray,
        sw: np.ndarray | None,
        check_pos: bool,
        check_rot: bool,
        tol_p: float,
        tol_r: float,
    ) -> None:
        self.robot, self.ch, self.target = robot, ch, target
        self.q_seed = q_seed
        self.rows, self.sw = rows, sw
        self.full_pose = rows.size == 6 and sw is None
        self.check_pos, self.check_rot = check_pos, check_rot
        self.tol_p, self.tol_r = tol_p, tol_r
        self.accept: Callable[[np.ndarray], bool] | None = None
        self.cancel: threading.Event | None = None
        self.wanted = 1
        self.solutions: list[IKSolution] = []
        self.iterations = 0
        self.restarts = 0
        self.timed_out = False
        self.rng: np.random.Generator | None = None
        self.nearest: np.ndarray | None = None
        self.distances: np.ndarray | None = None
        self.nearest_one = 0  # index of the nearest table sample, once distances are known
        # Best unconverged iterate (weighted task error energy).
        self.best_energy = math.inf
        self.best_q = q_seed.copy()

    # --------------------------------------------------------------- verification
    def done(self) -> bool:
        return len(self.solutions) >= self.wanted

    def wire(self, qa: np.ndarray) -> np.ndarray:
        """Full wire configuration: the seed with the active joints replaced."""
        q = self.q_seed.copy()
        q[self.ch.active] = qa
        return q

    def offer(self, qa: np.ndarray) -> bool:
        """Verify a candidate (active joints) by FK, limits and ``accept``; keep if new."""
        robot = self.robot
        q = self.wire(qa)
        if robot.has_continuous:
            c = robot._cont_wire
            q[c] = wrap_angle(q[c])
        if (q < robot.lower).any() or (q > robot.upper).any():
            return False
        model, data = robot.model, robot.data
        pin.forwardKinematics(model, data, robot.to_pin(q))
        T = pin.updateFramePlacement(model, data, self.ch.frame_id)
        target = self.target
        dp = T.translation - target.translation
        phi = pin.log3(T.rotation @ target.rotation.T)
        ep2, er2 = float(dp @ dp), float(phi @ phi)
        # hypot: no overflow of the squares (the errors of huge robots stay numbers)
        ep_full, er_full = math.hypot(*dp), math.hypot(*phi)
        if self.full_pose:
            ep, er, energy = ep_full, er_full, ep2 + er2
        else:
            e = np.concatenate((dp, phi))
            ep, er = self._checked(e)
            energy = self._energy(e)
        if energy < self.best_energy:
            self.best_energy, self.best_q = energy, q
        if not (ep <= self.tol_p and er <= self.tol_r):
            return False
        if not (math.isfinite(ep_full) and math.isfinite(er_full)):
            return False  # a pose that overflows float64 (even on unchecked components)
        for s in self.solutions:
            if joint_distance(robot, s.q, q).max() <= DISTINCT:
                return False
        if self.accept is not None and not self.accept(q):
            return False
        self.solutions.append(IKSolution(q, ep_full, er_full))
        return True

    def _checked(self, e: np.ndarray) -> tuple[float, float]:
        """Position and orientation errors over the checked (positive-weight) rows."""
        r = self.rows
        ep = float(np.linalg.norm(e[r[r < 3]])) if self.check_pos else 0.0
        er = float(np.linalg.norm(e[r[r >= 3]])) if self.check_rot else 0.0
        return ep, er

    def _energy(self, e: np.ndarray) -> float:
        v = e[self.rows]
        if self.sw is not None:
            v = v * self.sw
        return float(v @ v)

    # ------------------------------------------------------------------- hot loop
    def run(self, deadline: float, max_iterations: int | None) -> None:
        """Damped least squares from the seed, then from random restarts, until done."""
        if self.full_pose and self.ch.compiled is not None:
            self._run_compiled(deadline, max_iterations)
        else:
            self._run_python(deadline, max_iterations)

    def _run_compiled(self, deadline: float, max_iterations: int | None) -> None:
        """:meth:`_run_python` for the full pose with the attempts compiled
        (:func:`ik_kernel.attempt`): the same iterates, restarts and budget, checked between
        attempts (an attempt is at most ``_ATTEMPT_CAP`` iterations, a few tens of µs)."""
        ch, cc = self.ch, self.ch.compiled
        Rt = np.ascontiguousarray(self.target.rotation)
        pt = np.ascontiguousarray(self.target.translation)
        lo, hi = ch.clip_lo, ch.clip_hi
        q_ref = np.ascontiguousarray(self.q_seed[ch.active])
        redundant = ch.k > 6
        clamp = _CLAMP and redundant
        null_on = redundant and _NULL_GAIN > 0.0
        tol_p2, tol_r2 = self.tol_p**2, self.tol_r**2
        cap = max_iterations if max_iterations is not None else 1 << 62
        best = np.array([self.best_energy])
        best_q = q_ref.copy()
        have_best = False
        perf = time.perf_counter
        cancelled = self.cancel.is_set if self.cancel is not None else _never
        attempt = ik_kernel.attempt
        args = (cc.C, cc.t, cc.prism, cc.last_C, cc.last_t, lo, hi, ch.cont_mask, Rt, pt, q_ref)
        qa = q_ref.copy()
        it = self.iterations
        try:
            if _NEAREST_FIRST and it < cap:
                # The seed's pose against the nearest table sample: jump at once when the
                # sample is much closer (one evaluation, counted as an iteration then).
                ep2, er2, tr = ik_kernel.pose_error(qa, *args[:5], Rt, pt)
                if not (ep2 <= tol_p2 and er2 <= tol_r2):
                    d, k_t, i = ch.sample_distances_argmin(self.target)
                    self.distances, self.nearest_one = d, i
                    d_seed = ep2 + (2.0 * _ROT_WEIGHT) * (3.0 - tr)
                    if d[i] + k_t < _NEAREST_RATIO * d_seed:
                        it += 1
                        if ep2 + er2 < best[0]:
                            best[0], best_q[:], have_best = ep2 + er2, qa, True
                        qa = np.array(self._restart(self.rng))
            while True:
                if it >= cap:
                    return
                if perf() >= deadline:
                    self.timed_out = True
                    return
                if cancelled():
                    raise Cancelled()
                before = best[0]
                outcome, n = attempt(
                    qa, *args,
                    null_on and not self.restarts, clamp, tol_p2, tol_r2, cap - it,
                    _STALL, _ATTEMPT_CAP, _DAMP, _MU, _NULL_GAIN, 1.0 / _NULL_ENERGY,
                    _NULL_FLOOR, _MAX_STEP, best, best_q,
                )  # fmt: skip
                it += n
                have_best = have_best or best[0] < before
                if outcome == ik_kernel.CAPPED:
                    return
                if outcome == ik_kernel.CONVERGED:
                    self.iterations = it
                    if self.offer(qa.copy()) and self.done():
                        return
                qa = np.array(self._restart(self.rng))
        finally:
            self.iterations = it
            if have_best and best[0] < self.best_energy:
                self.best_energy, self.best_q = float(best[0]), self.wire(best_q)

    def _run_python(self, deadline: float, max_iterations: int | None) -> None:
        """The loop in Python around Pinocchio calls: every mode, every chain."""
        robot, ch = self.robot, self.ch
        model, data = robot.model, robot.data
        fid, cols = ch.frame_id, ch.cols
        lo, hi = ch.clip_lo, ch.clip_hi
        Rt = self.target.rotation
        RtT = np.ascontiguousarray(Rt.T)
        pt = self.target.translation
        rows, sw = self.rows, self.sw
        full_pose = rows.size == 6 and sw is None
        m = rows.size
        eye = _EYES[m]
        redundant = ch.k > m
        q_ref = self.q_seed[ch.active]
        tol_p2, tol_r2 = self.tol_p**2, self.tol_r**2
        check_pos, check_rot = self.check_pos, self.check_rot
        rows_p, rows_r = rows[rows < 3], rows[rows >= 3]
        plain, plain_q = ch.plain, ch.plain_q
        all_plain = plain.size == ch.k
        if all_plain:
            plain_q = ch.plain_q_sel
        has_cont = ch.has_continuous
        cont, cont_q, cont_q1 = ch.cont, ch.cont_q, ch.cont_q1
        perf = time.perf_counter
        cjj, gfj, upd, log3, jlog3 = (
            pin.computeJointJacobians,
            pin.getFrameJacobian,
            pin.updateFramePlacement,
            pin.log3,
            pin.Jlog3,
        )
        if model.nv == 1:
            # Pinocchio hands back a 1-D array (6,) for a model with one degree of freedom
            # (a 1-DoF arm, or one joint and its mimic followers): keep it a 6×1 matrix.
            gfj = _frame_jacobian_6xn
        LWA = pin.LOCAL_WORLD_ALIGNED
        posv = _posv
        mu, damp, gain = _MU, _DAMP, _NULL_GAIN
        max_step = _MAX_STEP
        max_step2 = max_step * max_step
        null_scale = 1.0 / _NULL_ENERGY
        clamp = _CLAMP and redundant  # a locked joint leaves a square chain short of a task row
        redundant = redundant and gain > 0.0
        stall_limit, attempt_cap = _STALL, _ATTEMPT_CAP
        cols = ch.cols_sel
        cap = max_iterations if max_iterations is not None else 1 << 62

        qp = robot.to_pin(self.q_seed)
        qa = q_ref.copy()
        e = np.empty(6)
        ev, ew = e[:3], e[3:]
        L = np.eye(6)  # blockdiag(I, Jlog3(R_e)ᵀ): J_e = L · J_LWA (active columns)
        Lw = L[3:, 3:]
        attempt_iters = 0
        best_attempt = math.inf
        stall = 0
        it = self.iterations
        best_energy, best_qa = self.best_energy, None
        sub, inner, dot = np.subtract, np.inner, np.dot
        # With all three rotation rows in the task, J·dq = −e gives the exact Gauss–Newton
        # step (see the module docstring: Jlog3ᵀ·φ = φ); a strict subset of them needs the
        # exact rows of J_e = [J_v; Jlog3(R_e)ᵀ J_ω].
        use_jlog = 0 < rows_r.size < 3
        nearest_first, nearest_ratio, rot_w = _NEAREST_FIRST, _NEAREST_RATIO, _ROT_WEIGHT
        null_floor = _NULL_FLOOR
        cancelled = self.cancel.is_set if self.cancel is not None else _never
        try:
            while True:
                if it >= cap:
                    return
                if perf() >= deadline:
                    self.timed_out = True
                    return
                if cancelled():
                    raise Cancelled()
                # ---- kinematics at qa
                if all_plain:
                    qp[plain_q] = qa
                else:
                    qp[plain_q] = qa[plain]
                    th = qa[cont]
                    qp[cont_q] = np.cos(th)
                    qp[cont_q1] = np.sin(th)
                cjj(model, data, qp)
                T = upd(model, data, fid)
                it += 1
                attempt_iters += 1
                # e = [p − p_t; log3(R R_tᵀ)] in world axes
                Re = T.rotation @ RtT
                sub(T.translation, pt, out=ev)
                ew[:] = log3(Re)
                energy = e @ e
                ep2 = ev @ ev
                # ---- converged on the checked components?
                if full_pose:
                    conv = ep2 <= tol_p2 and energy - ep2 <= tol_r2
                else:
                    conv = True
                    if check_pos:
                        v = e[rows_p]
                        conv = v @ v <= tol_p2
                    if conv and check_rot:
                        v = e[rows_r]
                        conv = v @ v <= tol_r2
                    et = e[rows]
                    if sw is not None:
                        et = et * sw
                    energy = et @ et
                if conv:
                    self.iterations = it
                    if self.offer(qa.copy()) and self.done():
                        return
                    # Converged but rejected or a duplicate: jump elsewhere.
                    qa = self._restart(self.rng)
                    attempt_iters, best_attempt, stall = 0, math.inf, 0
                    continue
                # ---- first iterate far from the target: jump to the nearest table sample
                if it == 1 and nearest_first and not conv and full_pose:
                    d, k_t, i_min = ch.sample_distances_argmin(self.target)
                    self.distances, self.nearest_one = d, i_min
                    d_seed = ep2 + (2.0 * rot_w) * (3.0 - (Re[0, 0] + Re[1, 1] + Re[2, 2]))
                    if d[i_min] + k_t < nearest_ratio * d_seed:
                        qa = self._restart(self.rng)
                        attempt_iters, best_attempt, stall = 0, math.inf, 0
                        continue
                # ---- stall / restart logic
                if energy < best_energy:
                    best_energy, best_qa = energy, qa
                if energy < 0.81 * best_attempt:  # ‖e‖ decreased by 10 %
                    best_attempt = energy
                    stall = 0
                else:
                    stall += 1
                    if stall >= stall_limit or attempt_iters >= attempt_cap:
                        qa = self._restart(self.rng)
                        attempt_iters, best_attempt, stall = 0, math.inf, 0
                        continue
                # ---- damped least-squares step on the task rows
                if use_jlog:
                    Lw[:] = jlog3(Re).T
                    Je = L @ gfj(model, data, fid, LWA)[:, cols]
                else:
                    Je = gfj(model, data, fid, LWA)[:, cols]
                if full_pose:
                    Jt, et = Je, e
                else:
                    Jt = Je[rows]
                    if sw is not None:
                        Jt = Jt * sw[:, None]
                lam2 = damp * energy + mu
                A = inner(Jt, Jt)  # J Jᵀ
                A += lam2 * eye
                # nd = −Δq (the sign folded into the update below)
                if redundant and energy > null_floor and not self.restarts:
                    # Preference gain fades with the error (quadratic convergence kept).
                    z = (q_ref - qa) * (gain * min(1.0, energy * null_scale))
                    nd = posv(A, et + dot(Jt, z))[1] @ Jt - z
                else:
                    nd = posv(A, et)[1] @ Jt
                n2 = nd @ nd
                if n2 > max_step2:
                    nd *= max_step / math.sqrt(n2)
                q_old = qa
                q_new = q_old - nd
                if has_cont:
                    q_new[cont] = (q_new[cont] + math.pi) % _TWO_PI - math.pi
                qa = np.minimum(np.maximum(q_new, lo), hi)
                if clamp and (qa != q_new).any():
                    # Joints already at a limit and pushed further are locked for this step
                    # (their columns removed) so the other joints take over their share.
                    locked = ((q_new < lo) & (q_old <= lo)) | ((q_new > hi) & (q_old >= hi))
                    if locked.any() and not locked.all():
                        Jl = Jt * ~locked
                        A = inner(Jl, Jl)
                        A += lam2 * eye
                        nd = posv(A, et)[1] @ Jl
                        n2 = nd @ nd
                        if n2 > max_step2:
                            nd *= max_step / math.sqrt(n2)
                        q_new = q_old - nd
                        if has_cont:
                            q_new[cont] = (q_new[cont] + math.pi) % _TWO_PI - math.pi
                        qa = np.minimum(np.maximum(q_new, lo), hi)
        finally:
            self.iterations = it
            if best_qa is not None and best_energy < self.best_energy:
                self.best_energy, self.best_q = best_energy, self.wire(best_qa)

    def _restart(self, rng: np.random.Generator | None) -> np.ndarray:
        """The next restart configuration of the active joints.

        The first ``_NEAREST`` restarts start from the samples of the chain's table whose
        pose is nearest the target (full pose only); then uniform random jumps (TRAC-IK).
        """
        self.restarts += 1
        ch = self.ch
        i = self.restarts - 1
        if self.full_pose and _NEAREST > 0:
            if self.distances is None:
                self.distances, _, self.nearest_one = ch.sample_distances_argmin(self.target)
            if i == 0:  # the nearest sample alone: no need to rank the others yet
                return ch.restart_table[self.nearest_one]
            if self.nearest is None:
                self.nearest = _k_smallest(self.distances, _NEAREST)
            if i < len(self.nearest):
                return ch.restart_table[self.nearest[i]]
        if rng is None:
            return ch.restart_table[i % _TABLE]
        return ch.sample_lo + (ch.sample_hi - ch.sample_lo) * rng.random(ch.k)

    # ------------------------------------------------------------------- result
    def result(self, method: str, t_start: float) -> IKResult:
        """The outcome: verified solutions sorted by distance to the seed, or the best iterate."""
        robot = self.robot
        sols = self.solutions
        if len(sols) > 1:
            sols = sorted(
                sols, key=lambda s: float(np.linalg.norm(joint_distance(robot, s.q, self.q_seed)))
            )
        elapsed = (time.perf_counter() - t_start) * 1e3
        if sols:
            best = sols[0]
            return IKResult(
                True,
                "converged",
                best.q,
                best.position_error,
                best.orientation_error,
                sols,
                self.iterations,
                self.restarts,
                elapsed,
                method,
            )
        q = self.best_q
        if robot.has_continuous:
            c = robot._cont_wire
            q = q.copy()
            q[c] = wrap_angle(q[c])
        model, data = robot.model, robot.data
        pin.forwardKinematics(model, data, robot.to_pin(q))
        T = pin.updateFramePlacement(model, data, self.ch.frame_id)
        ep, er, _ = pose_errors(T, self.target)
        if not (math.isfinite(ep) and math.isfinite(er)):
            # The pose itself overflows float64 (a robot hundreds of orders of magnitude too
            # big): there is no error to report, so no answer rather than a null one.
            raise InvalidInputError(
                f"frame {self.ch.frame!r} has no finite pose at the configurations searched: "
                "the robot's dimensions overflow double precision",
                "robot_id",
            )
        status: Status = "timeout" if self.timed_out else "not_converged"
        return IKResult(
            False, status, q, ep, er, [], self.iterations, self.restarts, elapsed, method
        )
