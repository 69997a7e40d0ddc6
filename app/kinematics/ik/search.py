"""The search state of one IK query: candidates, their verification, restarts, the result.

:class:`Search` holds what every loop shares: the verified solutions, the iteration and
restart counts, the best iterate so far. Candidates come from the closed forms
(:mod:`app.kinematics.analytic_ik`) and from the loops (:mod:`app.kinematics.ik.dls`,
:mod:`app.kinematics.ik.compiled`); :meth:`Search.offer` verifies each by a separate
forward-kinematics evaluation at the wire configuration (error against the target on the
checked components, joint limits, distinctness, the optional ``accept`` predicate) before
it counts as a solution. :meth:`Search.restart` picks the next start: the table samples
nearest the target pose first (full pose), then uniform random configurations.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

from app.kinematics.errors import Cancelled, InvalidInputError
from app.kinematics.ik.failure import classify, outside_limits
from app.kinematics.ik.parameters import SolverParameters
from app.kinematics.ik.precompute import k_smallest
from app.kinematics.ik.problem import IKProblem, Status
from app.kinematics.ik.ranking import Grouping, joint_distance, representatives

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.models import RobotModel

#: The budget's clock (s): ``time.perf_counter`` unless the caller injects another.
Clock = Callable[[], float]


@dataclass(slots=True)
class IKSolution:
    """One verified solution: wire configuration and its errors against the target; once
    answered, its branch, seed distance, manipulability and clearance
    (:mod:`app.kinematics.ik.ranking`)."""

    q: np.ndarray
    position_error: float
    orientation_error: float
    branch: str | None = None
    seed_distance: float = 0.0
    manipulability: float | None = None
    clearance: float | None = None


@dataclass(slots=True)
class IKResult:
    """Outcome of :func:`solve`.

    ``q`` is the best configuration (the first solution, or the lowest-error iterate when
    nothing converged); ``solutions`` are verified solutions, one per branch, ranked by the
    options' ``rank_by`` (:mod:`app.kinematics.ik.ranking`). ``iterations`` counts Jacobian
    evaluations over all attempts, ``restarts`` the random jumps, ``method`` is
    ``analytic``, ``numeric`` or ``analytic+numeric``. A failure has a ``reason`` and a
    ``detail`` sentence (:mod:`app.kinematics.ik.failure`); both are None on success.
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
    reason: str | None = None
    detail: str | None = None


def _within(q: list[float], lower: list[float], upper: list[float]) -> bool:
    """Whether every value lies within its limits (False for NaN)."""
    for v, lo, hi in zip(q, lower, upper, strict=True):
        if not lo <= v <= hi:
            return False
    return True


def wire_candidate(
    robot: RobotModel, ch: IKChain, q_seed: np.ndarray, qa: np.ndarray
) -> np.ndarray:
    """The wire configuration of chain configuration ``qa`` (k,): the seed with the active
    joints replaced, continuous joints wrapped to (−π, π]."""
    q = q_seed.copy()
    q[ch.active] = qa
    return robot.wrap(q) if robot.has_continuous else q


def within_limits(ch: IKChain, q: np.ndarray) -> bool:
    """Whether wire configuration ``q`` lies within every wire joint's limits (False for NaN)."""
    return _within(q.tolist(), ch.wire_lower, ch.wire_upper)


def frame_placement(robot: RobotModel, ch: IKChain, q: np.ndarray) -> pin.SE3:
    """The chain frame's placement at wire configuration ``q`` in the root frame, by
    Pinocchio (``forwardKinematics`` + ``updateFramePlacement`` on this thread's Data): the
    independent check of every candidate, however it was found."""
    model, data = robot.model, robot.data
    pin.forwardKinematics(model, data, q if ch.wire_is_pin else robot.to_pin(q))
    return pin.updateFramePlacement(model, data, ch.frame_id)


def full_pose_error(T: pin.SE3, target: pin.SE3) -> tuple[float, float, float, float, float, float]:
    """(x, y, z, a, b, c): T_t⁻¹·T = (R_tᵀR, R_tᵀ(p − p_t)) as its translation and the log3
    of its rotation, in one Pinocchio call: the same two norms as p − p_t and log3(R R_tᵀ) in
    world axes (m, rad)."""
    E = target.actInv(T)
    x, y, z = E.translation.tolist()
    a, b, c = pin.log3(E.rotation).tolist()
    return x, y, z, a, b, c


def pose_errors(T: pin.SE3, target: pin.SE3) -> tuple[float, float, np.ndarray]:
    """Position error (m), rotation angle (rad) and e = [p − p_t; log3(R R_tᵀ)] (world axes)."""
    ep = T.translation - target.translation
    eR = pin.log3(T.rotation @ target.rotation.T)
    return math.hypot(*ep), math.hypot(*eR), np.concatenate([ep, eR])


class Search:
    """State of one IK query: the verified solutions, the best iterate, the counts.

    Parameters
    ----------
    problem
        The validated query (robot, chain, target, seed, options and task rows).
    accept
        Optional predicate on a converged wire configuration; a rejected solution is dropped
        and the search continues (e.g. collision-aware IK).
    cancel
        Optional event the loops check between iterations (attempts, compiled).
    rng
        Random generator for the restarts after the nearest samples (default: the chain's
        fixed table in order, so answers are reproducible).
    clearance
        Optional ``q ↦`` robot–obstacle distance (m), reported with each answered solution.
    annotate
        Label every answered solution's branch and manipulability (else only what the
        ranking needs, :func:`~.ranking.representatives`).
    clock
        The clock the deadline is read on (s; default ``time.perf_counter``).
    """

    def __init__(
        self,
        problem: IKProblem,
        *,
        accept: Callable[[np.ndarray], bool] | None = None,
        cancel: threading.Event | None = None,
        rng: np.random.Generator | None = None,
        clearance: Callable[[np.ndarray], float] | None = None,
        annotate: bool = True,
        clock: Clock = time.perf_counter,
    ) -> None:
        task, options = problem.task, problem.options
        self.clock = clock
        #: The solver's tunables (the chain's: its table was built with them).
        self.parameters: SolverParameters = problem.chain.parameters
        self.options = options
        self.robot, self.ch, self.target = problem.robot, problem.chain, problem.target
        self.q_seed = problem.seed
        self.rows, self.sw = task.rows, task.sw
        self.full_pose = task.full_pose
        self.check_pos, self.check_rot = task.check_pos, task.check_rot
        self.tol_p, self.tol_r = float(options.tolerance[0]), float(options.tolerance[1])
        self.accept = accept
        self.cancel = cancel
        self.rng = rng
        self.wanted = options.num_solutions
        self.clearance = clearance
        self.annotate = annotate
        self.solutions: list[IKSolution] = []
        #: Branches of the solutions (only needed to count them when several are wanted).
        self.grouping = Grouping(self.robot, self.ch) if self.wanted > 1 else None
        self.rejected = 0  # solutions ``accept`` refused
        self.outside_limits: str | None = None  # the first target reached outside the limits
        self.iterations = 0
        self.restarts = 0
        self.timed_out = False
        self.nearest: np.ndarray | None = None
        self.distances: np.ndarray | None = None
        self.nearest_one = 0  # index of the nearest table sample, once distances are known
        # Best unconverged iterate (weighted task error energy).
        self.best_energy = math.inf
        self.best_q = problem.seed.copy()

    # --------------------------------------------------------------- verification
    def done(self) -> bool:
        """Whether ``wanted`` distinct branches (one solution when one is wanted) are found."""
        if self.grouping is None:
            return len(self.solutions) >= self.wanted
        return self.grouping.count >= self.wanted

    def wire(self, qa: np.ndarray) -> np.ndarray:
        """Full wire configuration: the seed with the active joints replaced."""
        q = self.q_seed.copy()
        q[self.ch.active] = qa
        return q

    def offer(self, qa: np.ndarray) -> bool:
        """Verify a candidate (active joints) by FK, limits and ``accept``; keep if new.

        The check is Pinocchio's, independent of how the candidate was found: the wire
        configuration within the joint limits, ``pin.forwardKinematics`` and
        ``updateFramePlacement`` of the frame, its errors against the target within the
        tolerances (on the checked components).
        """
        robot, ch = self.robot, self.ch
        q = wire_candidate(robot, ch, self.q_seed, qa)
        if not within_limits(ch, q):
            if self.outside_limits is None:
                self._note_outside_limits(q)
            return False
        T = frame_placement(robot, ch, q)
        target = self.target
        if self.full_pose:
            x, y, z, a, b, c = full_pose_error(T, target)
            # hypot: no overflow of the squares (the errors of huge robots stay numbers)
            ep = ep_full = math.hypot(x, y, z)
            er = er_full = math.hypot(a, b, c)
            energy = x * x + y * y + z * z + a * a + b * b + c * c
        else:
            ep_full, er_full, e = pose_errors(T, target)
            ep, er = self._checked(e)
            energy = self._energy(e)
        if energy < self.best_energy:
            self.best_energy, self.best_q = energy, q
        if not (ep <= self.tol_p and er <= self.tol_r):
            return False
        if not (math.isfinite(ep_full) and math.isfinite(er_full)):
            return False  # a pose that overflows float64 (even on unchecked components)
        for s in self.solutions:
            if (joint_distance(robot, s.q, q) <= self.ch.distinct).all():
                return False
        if self.accept is not None and not self.accept(q):
            self.rejected += 1
            return False
        self.solutions.append(IKSolution(q, ep_full, er_full))
        if self.grouping is not None:
            self.grouping.add(q)
        return True

    def _note_outside_limits(self, q: np.ndarray) -> None:
        """Record (for ``reason: joint_limits``) a candidate outside the limits that reaches
        the target within the tolerances."""
        robot = self.robot
        if not np.isfinite(q).all():
            return
        T = frame_placement(robot, self.ch, q)
        ep, er = self._checked(pose_errors(T, self.target)[2])
        if ep <= self.tol_p and er <= self.tol_r:
            self.outside_limits = outside_limits(robot, q, range(robot.n))

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

    def out_of_budget(self, iterations: int, cap: int, deadline: float) -> bool:
        """Whether the loop must stop before another iteration (attempt, compiled): the
        iteration cap is reached, or the deadline (:attr:`clock`) has passed (then
        ``timed_out`` is set). Raises :class:`Cancelled` once ``cancel`` is set."""
        if iterations >= cap:
            return True
        if self.clock() >= deadline:
            self.timed_out = True
            return True
        if self.cancel is not None and self.cancel.is_set():
            raise Cancelled()
        return False

    # --------------------------------------------------------------------- restarts
    def seed_is_far(self, ep2: float, trace: float) -> bool:
        """Whether the nearest table sample's pose is much closer to the target than the
        seed's (distance ratio below ``nearest_ratio``): then the loop jumps there at once.

        ``ep2`` is ‖p − p_t‖² at the seed and ``trace`` tr(R R_tᵀ), so that the seed's
        distance is ‖p − p_t‖² + c‖R − R_t‖²_F = ep2 + 2c(3 − trace). Ranks the table (kept
        for :meth:`restart`).
        """
        d, k_t, i = self.ch.sample_distances_argmin(self.target)
        self.distances, self.nearest_one = d, i
        p = self.parameters
        d_seed = ep2 + (2.0 * self.ch.rot_weight) * (3.0 - trace)
        return d[i] + k_t < p.nearest_ratio * d_seed

    def restart(self) -> np.ndarray:
        """The next restart configuration of the active joints.

        The first ``nearest`` restarts start from the samples of the chain's table whose
        pose is nearest the target (full pose only); then uniform random jumps (TRAC-IK):
        drawn from ``rng`` when given, else the table in order.
        """
        self.restarts += 1
        ch = self.ch
        i = self.restarts - 1
        nearest = self.parameters.nearest
        if self.full_pose and nearest > 0:
            if self.distances is None:
                self.distances, _, self.nearest_one = ch.sample_distances_argmin(self.target)
            if i == 0:  # the nearest sample alone: no need to rank the others yet
                return ch.restart_table[self.nearest_one]
            if self.nearest is None:
                self.nearest = k_smallest(self.distances, nearest)
            if i < len(self.nearest):
                return ch.restart_table[self.nearest[i]]
        if self.rng is None:
            return ch.restart_table[i % ch.restart_table.shape[0]]
        return self.random_start()

    def random_start(self) -> np.ndarray:
        """A configuration of the active joints drawn uniformly in the sampling box from
        ``rng`` (TRAC-IK's random jump)."""
        ch = self.ch
        return ch.sample_lo + (ch.sample_hi - ch.sample_lo) * self.rng.random(ch.k)

    # ------------------------------------------------------------------- result
    def result(self, method: str, t_start: float) -> IKResult:
        """The outcome: one verified solution per branch, ranked (:mod:`.ranking`), or the
        best iterate with the reason of the failure (:mod:`.failure`)."""
        robot = self.robot
        sols = representatives(
            robot,
            self.ch,
            self.solutions,
            self.grouping,
            self.q_seed,
            rank_by=self.options.rank_by,
            clearance=self.clearance,
            wanted=self.wanted,
            annotate=self.annotate,
        )
        elapsed = (self.clock() - t_start) * 1e3
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
        q, ep, er = self.best_iterate()
        reason, detail = classify(self, q, ep, er, self.options.max_iterations)
        status: Status = "timeout" if self.timed_out else "not_converged"
        return IKResult(
            False,
            status,
            q,
            ep,
            er,
            [],
            self.iterations,
            self.restarts,
            (self.clock() - t_start) * 1e3,
            method,
            reason,
            detail,
        )

    def best_iterate(self) -> tuple[np.ndarray, float, float]:
        """The lowest-error configuration met (wire, continuous joints wrapped) and its
        position (m) and orientation (rad) errors."""
        robot = self.robot
        q = robot.wrap(self.best_q)
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
        return q, ep, er
