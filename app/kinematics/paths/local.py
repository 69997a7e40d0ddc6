"""The warm-started local solve of a path's next point, and its independent verification.

Along a path the next pose is a small step from the last point, so one damped least-squares
attempt from the last point's joints (the compiled kernel,
:func:`app.kinematics.ik.kernel.attempt`, at most :data:`LOCAL_ITERATIONS` Jacobian
evaluations, no restarts, no closed forms, no ranking) usually lands on the next point in
two or three iterations, for a fraction of the fixed cost of :func:`app.kinematics.ik.solve`
(its validation, reach bound, table distances and result). Nothing the kernel claims is
trusted: :func:`verify` re-checks the answer as :meth:`app.kinematics.ik.search.Search.offer`
does, by a separate forward kinematics at the wire configuration (Pinocchio), the pose
error against the waypoint on the task's components within the IK tolerance, the joint
limits, and the path's :class:`~app.kinematics.paths.failures.Guard` (joint step, branch
label, the caller's ``accept``). When the local attempt fails or its answer is refused,
:mod:`.follow` falls back to :func:`app.kinematics.ik.solve`.

The local solve applies to the full pose (six rows, unit weights) on chains the kernel
supports (``IKChain.compiled``); other tasks always use :func:`app.kinematics.ik.solve`.
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin

from app.kinematics import jit
from app.kinematics.fk import frame_pose
from app.kinematics.ik import kernel
from app.kinematics.ik.boundary import step_parameters
from app.kinematics.ik.precompute import IKChain
from app.kinematics.ik.problem import Task
from app.kinematics.models import RobotModel
from app.kinematics.paths.failures import Guard, residuals

#: Jacobian evaluations of the local attempt at a point (a warm step needs 2–4).
LOCAL_ITERATIONS = 30


class LocalSolver:
    """One damped least-squares attempt from the previous point (see the module docstring).

    Parameters
    ----------
    robot, chain
        The robot and the IK chain (frame, moving joints, compiled constants).
    task
        The IK task (rows checked); the solver only exists for the full pose.
    tolerance
        (position m, rotation rad) convergence bounds of the attempt.
    max_iterations
        Cap of the attempt (Jacobian evaluations), at most :data:`LOCAL_ITERATIONS`.
    """

    def __init__(
        self,
        robot: RobotModel,
        chain: IKChain,
        task: Task,
        tolerance: tuple[float, float],
        max_iterations: int | None,
    ) -> None:
        self.robot, self.ch = robot, chain
        cc = chain.compiled
        #: Whether the local attempt applies (full pose, compiled chain).
        self.available = bool(task.full_pose and cc is not None and jit.available())
        cap = LOCAL_ITERATIONS if max_iterations is None else min(max_iterations, LOCAL_ITERATIONS)
        self.cap = cap
        if not self.available:
            return
        redundant = chain.k > 6
        p = chain.parameters
        self._chain = chain.chain_constants
        # the attempt's cap is this solver's, not the search's
        self._step = step_parameters(p, attempt_cap=cap)
        self._flags = (redundant and p.null_gain > 0.0, p.clamp and redundant)
        self._tol2 = (float(tolerance[0]) ** 2, float(tolerance[1]) ** 2)
        self._best = np.empty(1)
        self._best_q = np.empty(chain.k)

    def attempt(self, q_prev: np.ndarray, target: pin.SE3) -> tuple[np.ndarray | None, int]:
        """One attempt towards ``target`` from the wire configuration ``q_prev``.

        Returns
        -------
        q, iterations
            The wire configuration the attempt converged to (unverified: see :func:`verify`)
            or None, and the Jacobian evaluations spent.
        """
        if not self.available or self.cap <= 0:
            return None, 0
        ch = self.ch
        qa = np.ascontiguousarray(q_prev[ch.active], dtype=float)
        q_ref = qa.copy()
        self._best[0] = np.inf
        null_on, clamp = self._flags
        args = (
            qa, self._chain,
            np.ascontiguousarray(target.rotation, dtype=np.float64),
            np.ascontiguousarray(target.translation, dtype=np.float64),
            q_ref, bool(null_on), bool(clamp), *self._tol2, int(self.cap), self._step,
            self._best, self._best_q,
        )  # fmt: skip
        outcome, n = jit.direct(kernel.attempt, *args)(*args)
        if outcome != kernel.CONVERGED:
            return None, int(n)
        q = q_prev.copy()
        q[ch.active] = qa
        return q, int(n)


def verify(
    robot: RobotModel,
    chain: IKChain,
    task: Task,
    tolerance: tuple[float, float],
    q: np.ndarray,
    target: pin.SE3,
    guard: Guard,
) -> tuple[np.ndarray, float, float] | None:
    """Check a candidate independently of the solver that produced it.

    Parameters
    ----------
    robot, chain, task
        The robot, the IK chain (frame) and the task rows checked.
    tolerance
        (position m, rotation rad) the pose error must be within.
    q
        Candidate wire configuration (continuous joints are wrapped to (−π, π]).
    target
        The pose it must reach (root frame).
    guard
        The path's guard from the previous point (joint step, branch, ``accept``).

    Returns
    -------
    (q, position_error, orientation_error) or None
        The wrapped configuration and its errors (m, rad) from a separate forward kinematics,
        or None when it is outside the limits, off the pose, or refused by the guard.
    """
    q = robot.wrap(q)
    if not ((q >= robot.lower) & (q <= robot.upper)).all():  # NaN fails too
        return None
    ep, er = residuals(frame_pose(robot, q, chain.frame_id), target, task)
    if not (ep <= tolerance[0] and er <= tolerance[1]):
        return None
    if not guard(q):
        return None
    return q, ep, er
