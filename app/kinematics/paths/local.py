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

Once :meth:`LocalSolver.prepare` has the path's start, joint step and branch label,
:meth:`LocalSolver.point` makes the attempt and every check above but the caller's
``accept`` in one compiled call (:mod:`.point_kernel`, its forward kinematics composed
afresh from the chain constants, tested against Pinocchio's and against :func:`verify`),
and :meth:`LocalSolver.walk` the same for a run of waypoints (:mod:`.walk_kernel`);
:meth:`LocalSolver.attempt` and :func:`verify` remain the path where it does not apply
(no compiled kernel, or the compiled flags of the start disagree with its label).
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin

from app.kinematics import jit
from app.kinematics.fk import frame_pose
from app.kinematics.ik import branch_kernel, kernel
from app.kinematics.ik.boundary import step_parameters
from app.kinematics.ik.joint_frames import wrist_in_kernel_frame
from app.kinematics.ik.precompute import IKChain
from app.kinematics.ik.problem import Task
from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel
from app.kinematics.paths import point_kernel, walk_kernel
from app.kinematics.paths.failures import Guard, residuals
from app.kinematics.paths.pose_kernel import PieceArrays
from app.kinematics.paths.segments import Samples

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
        self._tol = (float(tolerance[0]), float(tolerance[1]))
        self._tol2 = (self._tol[0] ** 2, self._tol[1] ** 2)
        self._best = np.empty(1)
        self._best_q = np.empty(chain.k)
        #: The compiled point's constants once :meth:`prepare` accepted them, else None.
        self.compiled: point_kernel.PointConstants | None = None
        self._label = point_kernel.NO_LABELS
        self._q = np.empty(robot.n)
        self._out = np.empty(5)
        self._err = np.empty(2)
        self._iterations = np.empty(1)

    def constants(self, max_joint_step: float) -> point_kernel.PointConstants | None:
        """The compiled point's constants for ``max_joint_step`` (rad or m), or None when
        the local solve does not apply."""
        if not self.available:
            return None
        ch = self.ch
        key = LazyKey(f"paths.point:{ch.frame_id}:{ch.active.tolist()}", tuple)
        fixed = self.robot.lazy(key, lambda robot: _fixed_constants(robot, ch))
        null_on, clamp = self._flags
        return point_kernel.PointConstants(
            self._chain, self._step, *fixed, bool(null_on), bool(clamp),
            *self._tol, float(max_joint_step), int(self.cap),
        )  # fmt: skip

    def prepare(self, q0: np.ndarray, label: str | None, max_joint_step: float) -> bool:
        """Turn the compiled point on for a path from ``q0`` (wire) on branch ``label``
        under ``max_joint_step``; returns whether it is on. Off where the local solve does
        not apply, or where the compiled flags of ``q0`` name another label than ``label``
        (a start exactly on a branch boundary): the Python checks decide then."""
        self.compiled = None
        pc = self.constants(max_joint_step)
        if pc is None or self.cap <= 0:
            return False
        code = point_kernel.NO_LABELS
        if label is not None:
            if pc.kind == point_kernel.NO_LABELS:
                return False
            q = np.ascontiguousarray(q0, dtype=np.float64)
            code = int(jit.direct(point_kernel.label_code, q, pc)(q, pc))
            if branch_kernel.label(self.ch.branch_form, code) != label:
                return False
        self.compiled, self._label = pc, code
        return True

    def point(
        self, q_prev: np.ndarray, R: np.ndarray, p: np.ndarray, middle: tuple[PieceArrays, float]
    ) -> tuple[int, np.ndarray | None, float, float, int, float, float]:
        """The attempt from ``q_prev`` towards the target pose (``R`` (3, 3), ``p`` (3,):
        C-contiguous float64, root frame) and its checks in one compiled call
        (:func:`app.kinematics.paths.point_kernel.step`; :meth:`prepare` first).

        Returns
        -------
        status, q, position_error, orientation_error, iterations, dev_p, dev_r
            The status (:data:`app.kinematics.paths.point_kernel.STATUSES`); on ``OK`` the
            checked wire configuration (wrapped), its errors against the target (m, rad), and
            the frame's deviation from ``middle`` (the path's pose half-way: a segment and its
            parameter, :meth:`CartesianPath.piece_at`) at the middle of the joint-space step
            (m, rad); ``q`` None otherwise.
        """
        pc = self.compiled
        assert pc is not None, "prepare() first"
        q, out = self._q, self._out
        args = (
            np.ascontiguousarray(q_prev, dtype=np.float64), pc, R, p, self._label,
            middle[0], float(middle[1]), q, out,
        )  # fmt: skip
        status = int(jit.direct(point_kernel.step, *args)(*args))
        n = int(out[2])
        if status != point_kernel.OK:
            return status, None, 0.0, 0.0, n, 0.0, 0.0
        return status, q.copy(), float(out[0]), float(out[1]), n, float(out[3]), float(out[4])

    def walk(
        self,
        q_prev: np.ndarray,
        samples: Samples,
        first: int,
        stop: int,
        run: int,
        half: tuple[float, float],
        Q: np.ndarray,
        E: np.ndarray,
    ) -> tuple[int, int]:
        """The plain points of waypoints ``first ≤ k < stop`` of ``samples`` (all on the
        segment ``samples.runs[run]``) from the last point ``q_prev`` in one compiled call
        (:func:`app.kinematics.paths.walk_kernel.run`; :meth:`prepare` first), ``half``
        half the deviation bounds (m, rad); rows k of ``Q`` (N, n) and ``E`` (N, 2) receive
        the accepted waypoints' configurations and errors (m, rad).

        Returns
        -------
        accepted, iterations
            How many waypoints from ``first`` on are plain points (the next one, if any
            before ``stop``, is not: the Python walk takes it), and their attempts'
            Jacobian evaluations.
        """
        pc = self.compiled
        assert pc is not None, "prepare() first"
        _, _, a, b, piece = samples.runs[run]
        args = (
            np.ascontiguousarray(q_prev, dtype=np.float64), pc, self._label, samples.R,
            samples.p, samples.s, int(first), int(stop), piece, a, b, half[0], half[1], Q, E,
            self._iterations,
        )  # fmt: skip
        accepted = int(jit.direct(walk_kernel.run, *args)(*args))
        return accepted, int(self._iterations[0])

    def check(
        self, q_prev: np.ndarray, q: np.ndarray, target: pin.SE3
    ) -> tuple[int, np.ndarray, float, float]:
        """The compiled checks alone (:func:`app.kinematics.paths.point_kernel.checks`) of
        the candidate wire configuration ``q`` from ``q_prev`` towards ``target``
        (:meth:`prepare` first): the status, ``q`` wrapped, and the errors (m, rad; NaN
        when the check stopped before the forward kinematics)."""
        pc = self.compiled
        assert pc is not None, "prepare() first"
        qw = np.array(q, dtype=np.float64, order="C")
        err = np.full(2, np.nan)
        args = (
            qw, np.ascontiguousarray(q_prev, dtype=np.float64), pc,
            np.array(target.rotation, dtype=np.float64, order="C"),
            np.array(target.translation, dtype=np.float64, order="C"), self._label, err,
        )  # fmt: skip
        status = int(jit.direct(point_kernel.checks, *args)(*args))
        return status, qw, float(err[0]), float(err[1])

    def residuals_at(self, qa: np.ndarray, target: pin.SE3) -> tuple[float, float]:
        """Position and rotation error (m, rad) of the frame at the chain configuration
        ``qa`` (k,) against ``target``, by the compiled forward kinematics (:meth:`prepare`
        first)."""
        pc = self.compiled
        assert pc is not None, "prepare() first"
        args = (
            np.ascontiguousarray(qa, dtype=np.float64), pc.chain,
            np.ascontiguousarray(target.rotation, dtype=np.float64),
            np.ascontiguousarray(target.translation, dtype=np.float64), self._err,
        )  # fmt: skip
        jit.direct(point_kernel.pose_residuals, *args)(*args)
        return float(self._err[0]), float(self._err[1])

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


def _fixed_constants(robot: RobotModel, ch: IKChain) -> tuple:
    """The fields of :class:`~app.kinematics.paths.point_kernel.PointConstants` that depend
    on the chain only, from ``active`` to ``tip_axis4`` (cached per chain)."""
    form = ch.branch_form
    kind, elbow, tip4, wrist = point_kernel.NO_LABELS, False, False, np.zeros(3)
    if form is not None:
        kind, elbow, tip4 = branch_kernel.form_arrays(form)
        wrist = wrist_in_kernel_frame(robot, ch)
    cont = np.zeros(robot.n, dtype=np.bool_)
    cont[[i for i, j in enumerate(robot.joints) if j.continuous]] = True
    return (
        np.ascontiguousarray(ch.active, dtype=np.int64),
        np.ascontiguousarray(robot.lower, dtype=np.float64),
        np.ascontiguousarray(robot.upper, dtype=np.float64), cont,
        np.ascontiguousarray(wrist, dtype=np.float64), int(kind), bool(elbow), bool(tip4),
    )  # fmt: skip


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
