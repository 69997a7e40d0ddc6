"""Why a path stops: the guards a solution must pass, and the typed failure of a waypoint.

:class:`Guard` is the ``accept`` predicate :mod:`.follow` hands to
:func:`app.kinematics.ik.solve`: a converged candidate passes when no joint moves more than
``max_joint_step`` from the previous point, its branch label is the path's, and the caller's
``accept`` (collision-free) holds. It remembers why it refused candidates, and
:func:`classify` turns that (with the IK result) into the ``reason`` of
:class:`PathFailure`:

- ``collision``: a solution within the joint step (on the branch) exists, but it collides;
- ``branch``: the only solutions within the joint step are on another branch;
- ``joint_step``: every solution found moves some joint more than ``max_joint_step``;
- ``singular``: instead of ``joint_step`` or ``branch`` when the smallest singular value of
  the dimensionless frame Jacobian (task rows, moving joints, lengths in units of the
  chain's length) at the last point reached (for ``branch``:
  or half-way to the refused solution, where the flags change sign) is below
  :data:`SINGULAR_SIGMA`: the continuation needs unbounded joint speed there;
- ``joint_limits``: every solution found jumps, and the linearised step from the last point
  towards the waypoint, Δq = J⁺·e, takes a joint outside its limits;
- no solution at all: the solver's own ``reason`` (:mod:`app.kinematics.ik.failure`:
  ``unreachable``, ``joint_limits``, ``singular`` or ``timeout``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

from app.kinematics.fk import frame_pose
from app.kinematics.ik.failure import REASONS
from app.kinematics.ik.precompute import IKChain
from app.kinematics.ik.problem import Task
from app.kinematics.ik.scale import dimensionless, length_scale
from app.kinematics.ik.search import IKResult, joint_distance
from app.kinematics.jacobian import frame_jacobian_by_id
from app.kinematics.models import RobotModel

if TYPE_CHECKING:
    from app.kinematics.paths.result import PathPoint

#: Smallest singular value of the dimensionless task Jacobian below which a point is called
#: singular: position rows in chain lengths per rad (per chain length for a prismatic
#: joint), rotation rows in rad per rad (:func:`app.kinematics.ik.scale.dimensionless`).
#: Why a path stops (the first point that cannot be reached): an IK query's reasons and
#: the path's own guards.
PATH_REASONS = (*REASONS, "joint_step", "branch")
SINGULAR_SIGMA = 0.02


@dataclass(slots=True)
class PathFailure:
    """The first waypoint that could not be reached.

    ``index`` is its index among the sampled waypoints (:meth:`CartesianPath.sample`), ``s``
    the path parameter of the pose last attempted (a midpoint when the step was halved),
    ``reason`` one of the module docstring's, ``detail`` a sentence with the numbers, ``q``
    the best configuration met (a refused solution when there was one) and its pose errors
    against that pose (m, rad).
    """

    index: int
    s: float
    reason: str
    detail: str
    q: np.ndarray
    position_error: float
    orientation_error: float


def residuals(T: pin.SE3, target: pin.SE3, task: Task) -> tuple[float, float]:
    """Position (m) and rotation (rad) error of ``T`` against ``target`` on the components the
    task checks (0 for one it does not)."""
    dp = T.translation - target.translation
    if task.full_pose:
        # The angle of R·R_tᵀ is that of its conjugate R_tᵀ·R (one product in Pinocchio,
        # no 3×3 NumPy product); hypot of plain floats: no overflow, no array access.
        phi = pin.log3(target.actInv(T).rotation)
        return math.hypot(*dp.tolist()), math.hypot(*phi.tolist())
    phi = pin.log3(T.rotation @ target.rotation.T)
    e = np.concatenate((dp, phi))
    r = task.rows
    ep = float(np.linalg.norm(e[r[r < 3]])) if task.check_pos else 0.0
    er = float(np.linalg.norm(e[r[r >= 3]])) if task.check_rot else 0.0
    return ep, er


class Guard:
    """``accept`` predicate of one IK solve along a path, remembering its refusals.

    Parameters
    ----------
    robot, chain
        The robot and the IK chain (its ``active`` joints are the ones that move).
    q_prev
        The previous point's wire configuration.
    max_joint_step
        Largest move of any joint (rad or m).
    label, branch_of
        The path's branch label (None: not checked) and the labelling function.
    accept
        The caller's predicate (collision-free), or None.
    record_all
        Evaluate every test on every candidate (for :func:`classify`); otherwise stop at the
        first refusal (cheap: the joint step first, the collision check last).
    """

    def __init__(
        self,
        robot: RobotModel,
        chain: IKChain,
        q_prev: np.ndarray,
        max_joint_step: float,
        label: str | None,
        branch_of: Callable[[np.ndarray], str | None],
        accept: Callable[[np.ndarray], bool] | None,
        record_all: bool = False,
    ) -> None:
        self.robot, self.active, self.q_prev = robot, chain.active, q_prev
        self.max_joint_step, self.label, self.branch_of = max_joint_step, label, branch_of
        self.accept, self.record_all = accept, record_all
        #: Smallest jump among the candidates refused for it: (jump, wire index, q).
        self.jump: tuple[float, int, np.ndarray] | None = None
        #: Branch labels of candidates within the step but on another branch.
        self.other_branches: list[tuple[str | None, np.ndarray]] = []
        #: Candidates within the step, on the branch, refused by ``accept``.
        self.collisions: list[np.ndarray] = []
        #: Set by the densification when it gave up: (position m, rotation rad, depth).
        self.deviation: tuple[float, float, int] | None = None

    def __call__(self, q: np.ndarray) -> bool:
        d = joint_distance(self.robot, q, self.q_prev)[self.active]
        j = int(np.argmax(d))
        step_ok = bool(d[j] <= self.max_joint_step)
        if not step_ok and (self.jump is None or d[j] < self.jump[0]):
            self.jump = (float(d[j]), int(self.active[j]), q.copy())
        if not step_ok and not self.record_all:
            return False
        branch_ok = True
        if self.label is not None:
            lab = self.branch_of(q)
            branch_ok = lab == self.label
            if not branch_ok and step_ok:
                self.other_branches.append((lab, q.copy()))
        if not branch_ok and not self.record_all:
            return False
        free = self.accept is None or self.accept(q)
        if not free and step_ok and branch_ok:
            self.collisions.append(q.copy())
        return step_ok and branch_ok and free


def smallest_singular_value(robot: RobotModel, chain: IKChain, task: Task, q: np.ndarray) -> float:
    """σ_min of the frame Jacobian at ``q`` (world-aligned), task rows, moving joints, made
    dimensionless by the chain's length (:func:`app.kinematics.ik.scale.dimensionless`)."""
    J = frame_jacobian_by_id(robot, robot.to_pin(q), chain.frame_id, pin.LOCAL_WORLD_ALIGNED)
    J = J[task.rows][:, chain.active]
    prismatic = np.array([robot.joints[int(i)].type == "prismatic" for i in chain.active])
    J = dimensionless(J, task.rows, prismatic, length_scale(robot, chain.frame_id))
    return float(np.linalg.svd(J, compute_uv=False).min())


def _limit_hit(
    robot: RobotModel, chain: IKChain, task: Task, q: np.ndarray, target: pin.SE3
) -> str | None:
    """A sentence naming the joint that the linearised step q + J⁺·e (towards ``target``)
    takes outside its limits, or None."""
    T = frame_pose(robot, q, chain.frame_id)
    e = np.concatenate(
        (target.translation - T.translation, pin.log3(target.rotation @ T.rotation.T))
    )[task.rows]
    J = frame_jacobian_by_id(robot, robot.to_pin(q), chain.frame_id, pin.LOCAL_WORLD_ALIGNED)
    dq = np.linalg.lstsq(J[task.rows][:, chain.active], e, rcond=None)[0]
    qa = q[chain.active] + dq
    for k in np.flatnonzero((qa < chain.lower) | (qa > chain.upper)):
        i = int(chain.active[k])
        return (
            f"joint {robot.joints[i].name} would go to {qa[k]:.4f}, outside its limits "
            f"[{robot.lower[i]:g}, {robot.upper[i]:g}], to follow the path"
        )
    return None


def classify(
    robot: RobotModel,
    chain: IKChain,
    task: Task,
    index: int,
    s: float,
    last: PathPoint,
    res: IKResult,
    guard: Guard,
    target: pin.SE3,
) -> PathFailure:
    """The failure of waypoint ``index`` after the last (full-budget, ``record_all``) attempt
    at ``target`` (path parameter ``s``) from the point ``last``; see the module docstring."""
    sigma = smallest_singular_value(robot, chain, task, last.q)
    singular = sigma < SINGULAR_SIGMA
    near = (
        f"the smallest singular value of the Jacobian at the last point reached (s = "
        f"{last.s:.4f}) is {sigma:.3g} < {SINGULAR_SIGMA:g}"
    )
    where = f"waypoint {index} (s = {s:.4f})"
    q = res.q
    reason, detail = "unreachable", ""
    if guard.deviation is not None:
        dp, dr, depth = guard.deviation
        reason = "singular" if singular else "joint_step"
        detail = (
            f"moving the joints linearly towards {where} strays {dp:.3g} m and {dr:.3g} rad "
            f"from the path even after {depth} levels of inserted points"
            + (f": {near}" if singular else "")
        )
    elif guard.collisions:
        q = guard.collisions[0]
        reason = "collision"
        detail = f"every solution found for {where} within max_joint_step is in collision"
    elif guard.other_branches:
        lab, q = guard.other_branches[0]
        # The flags change sign where the arm is singular: look half-way to the solution too.
        dq = robot.difference(last.q, q)
        sigma_mid = smallest_singular_value(robot, chain, task, last.q + 0.5 * dq)
        singular = singular or sigma_mid < SINGULAR_SIGMA
        near = (
            f"the smallest singular value of the Jacobian between the last point reached "
            f"(s = {last.s:.4f}) and that solution is {min(sigma, sigma_mid):.3g} < "
            f"{SINGULAR_SIGMA:g}"
        )
        reason = "singular" if singular else "branch"
        detail = (
            f"the solutions found for {where} within max_joint_step are on branch {lab!r}, "
            f"not the path's {guard.label!r}" + (f"; {near}" if singular else "")
        )
    elif guard.jump is not None:
        jump, i, q = guard.jump
        hit = _limit_hit(robot, chain, task, last.q, target)
        name = robot.joints[i].name
        moved = (
            f"the nearest solution found for {where} moves joint {name} by {jump:.4f}, more "
            f"than max_joint_step = {guard.max_joint_step:g}"
        )
        if singular:
            reason, detail = "singular", f"{moved}: {near}"
        elif hit is not None:
            reason, detail = "joint_limits", f"{hit} ({moved})"
        else:
            reason, detail = "joint_step", moved
    elif res.reason is not None:  # no solution at all: the solver's own reason
        reason = res.reason
        detail = f"no solution of {where} found: {res.detail}"
    else:
        reason = "timeout" if res.status == "timeout" else "unreachable"
        detail = (
            f"no solution of {where} found: the closest configuration met is "
            f"{res.position_error:.3g} m and {res.orientation_error:.3g} rad away"
        )
    ep, er = residuals(frame_pose(robot, q, chain.frame_id), target, task)
    if not (math.isfinite(ep) and math.isfinite(er)):
        ep, er = res.position_error, res.orientation_error
    return PathFailure(index, s, reason, detail, np.asarray(q, dtype=float).copy(), ep, er)
