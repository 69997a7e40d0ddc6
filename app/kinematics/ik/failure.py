"""Why an IK query failed: ``reason`` and ``detail`` of an unsuccessful :class:`IKResult`.

Reasons, in the order they are tested
--------------------------------------
``unreachable``
    The target position is outside the chain's reach bound (modes ``pose`` and
    ``position``; tested before any search, which is then skipped). The bound: let
    j_1 … j_m be the joints on the path from the root to the frame (every joint there, moving
    or held), c_i the constant offset of joint j_i's placement in the frame of j_{i−1}
    (Pinocchio's ``jointPlacements``), f the frame's offset in the frame of j_m and b the
    origin of j_1's placement (a fixed point of the root frame). The frame origin is

        p(q) = b + R_0 t_1 + Σ_{i=2..m} R_{i−1} (c_i + R_{c_i} t_i) + R_m f,

    with R_i rotations and t_i = 0 for a revolute joint, t_i = q_i·a_i (unit axis a_i) for a
    prismatic one. By the triangle inequality, for every q within the limits

        |p(q) − b| ≤ R = Σ_{i=2..m} |c_i| + |f| + Σ_{prismatic i} max(|lower_i|, |upper_i|),

    (a joint held at its seed value counts its seed value instead of its travel). So a target
    with |P(p_t − b)| > R + tol_p (P: the checked position axes) cannot be reached within
    the position tolerance; the bound is reported in ``detail``. Chains with other joints
    (free-flyer, planar, helical) or unbounded prismatic travel have no bound. The search is
    then replaced by a short best-effort descent (at most :data:`UNREACHABLE_ITERATIONS`
    iterations, no closed forms) so that ``q`` still leans towards the target.
``collision``
    Solutions within tolerance and limits were found, but ``accept`` (collision-aware IK)
    rejected every one of them.
``joint_limits``
    A candidate (a closed-form solution, or a converged iterate) reached the target within
    tolerance only outside the joint limits; or a damped least-squares descent from the best
    iterate that ignores the limits (at most :data:`UNCONSTRAINED_ITERATIONS` steps) reaches
    the target within tolerance with some joint outside its limits; or the best iterate is
    pinned at a limit with the descent direction pushing out: some joint i sits at its lower
    (upper) limit and the gradient g = J_eᵀ e of the task error energy has g_i > 0 (< 0),
    with |g_i| at least :data:`PINNED_SHARE` of the largest component (the joint is a real
    part of the descent).
``singular``
    The best iterate's task Jacobian (task rows, weighted, the moving joints' columns) has a
    smallest singular value σ_min < :data:`SINGULAR_SIGMA` and the search stalled there
    (every attempt ended without converging). σ_min is that of the dimensionless Jacobian
    (:func:`app.kinematics.ik.scale.dimensionless`: lengths in units of the chain's length),
    so an arm and its copy at any scale get the same verdict.
``timeout``
    Otherwise: the budget ended the search; ``detail`` says which (``timeout_ms`` or
    ``max_iterations``) with the counts and the best errors.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

from app.kinematics.ik.scale import dimensionless, length_scale
from app.kinematics.joint_types import PRISMATIC_MODELS, REVOLUTE_MODELS
from app.kinematics.models import MAX_JOINT_VALUE

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.ik.problem import Task
    from app.kinematics.ik.search import Search
    from app.kinematics.models import RobotModel


#: Why an IK query failed (``IKResult.reason``), in the order the checks run.
REASONS = ("unreachable", "joint_limits", "collision", "singular", "timeout")

#: σ_min of the best iterate's dimensionless task Jacobian below this: ``singular`` (rad per
#: rad; lengths in units of the chain length, :mod:`app.kinematics.ik.scale`).
SINGULAR_SIGMA = 1e-3
#: A joint pinned at a limit counts when its gradient component is at least this share of
#: the largest component.
PINNED_SHARE = 0.01
#: Iteration cap of the best-effort descent towards an unreachable target.
UNREACHABLE_ITERATIONS = 60
#: Iteration cap of the descent that ignores the joint limits (``joint_limits`` test).
UNCONSTRAINED_ITERATIONS = 100
#: Relative slack on the reach bound (rounding of the sums).
REACH_SLACK = 1e-9


#: (b, the seed-independent part of R, wire indices of held prismatic joints).
ReachParts = tuple[np.ndarray, float, tuple[int, ...]]


def _reach_parts(robot: RobotModel, ch: IKChain) -> ReachParts | None:
    """(b, the seed-independent part of R, wire indices of held prismatic joints), or None
    when the chain has no bound. Cached on the chain (:attr:`IKChain.reach_parts`)."""
    return ch.reach_parts


def reach_parts_of(robot: RobotModel, ch: IKChain) -> ReachParts | None:
    """:func:`_reach_parts`, computed."""
    model = robot.model
    fr = model.frames[ch.frame_id]
    path = [int(j) for j in model.supports[fr.parentJoint] if int(j) > 0]
    if not path:
        return None
    by_pin = {j.pin_id: j for j in robot.joints}
    active = {int(w): i for i, w in enumerate(ch.active)}  # wire index → active position
    total = float(np.linalg.norm(fr.placement.translation))
    held: list[int] = []
    for k, jid in enumerate(path):
        name = model.joints[jid].shortname()
        if k > 0:
            total += float(np.linalg.norm(model.jointPlacements[jid].translation))
        if name in REVOLUTE_MODELS:
            continue
        if name not in PRISMATIC_MODELS:
            return None
        joint = by_pin.get(jid)
        if joint is None:  # a mimic follower: its own limits, from the model
            lo = model.lowerPositionLimit[model.idx_qs[jid]]
            hi = model.upperPositionLimit[model.idx_qs[jid]]
        elif joint.index in active:
            lo, hi = ch.lower[active[joint.index]], ch.upper[active[joint.index]]
        else:
            held.append(joint.index)
            continue
        travel = max(abs(float(lo)), abs(float(hi)))
        if not math.isfinite(travel) or travel > MAX_JOINT_VALUE:
            return None
        total += travel
    return model.jointPlacements[path[0]].translation.copy(), total, tuple(held)


def reach_bound(
    robot: RobotModel, ch: IKChain, seed: np.ndarray
) -> tuple[np.ndarray, float] | None:
    """(b, R): every configuration within the limits puts the frame origin within R (m) of
    the fixed point b (root frame), see the module doc; None when the chain has no bound."""
    parts = _reach_parts(robot, ch)
    if parts is None:
        return None
    b, total, held = parts
    for wire in held:
        total += abs(float(seed[wire]))
    return b, total


def unreachable_detail(
    robot: RobotModel,
    ch: IKChain,
    seed: np.ndarray,
    target: pin.SE3,
    task: Task,
    tol_p: float,
) -> str | None:
    """A ``detail`` sentence when the target position is beyond the reach bound on the
    position axes the task checks, else None."""
    if not task.check_pos:
        return None
    bound = reach_bound(robot, ch, seed)
    if bound is None:
        return None
    b, reach = bound
    x, y, z = target.translation.tolist()
    b0, b1, b2 = b.tolist()
    limit = reach * (1.0 + REACH_SLACK) + tol_p
    # hypot: no overflow of the squares. The distance over all three axes bounds the one over
    # the checked axes, so the common case (within reach) needs no row selection.
    if math.hypot(x - b0, y - b1, z - b2) <= limit:
        return None
    diff = target.translation - b
    rows = task.rows
    d = math.hypot(*(float(diff[i]) for i in rows[rows < 3]))
    if d <= limit:
        return None
    return (
        f"the target is {d:.6g} m from the chain's first joint at {np.round(b, 6).tolist()}, "
        f"but no configuration places frame {ch.frame!r} farther than {reach:.6g} m from it "
        "(the sum of the link offsets and prismatic travel)"
    )


def outside_limits(robot: RobotModel, q: np.ndarray, joints: Iterable[int]) -> str:
    """``"<joint> = <value> outside [<lower>, <upper>]"`` for each of the wire indices
    ``joints`` whose value in ``q`` lies outside its limits, joined by ``"; "`` ("" if none)."""
    return "; ".join(
        f"{robot.joints[i].name} = {q[i]:.6g} outside [{robot.lower[i]:.6g}, {robot.upper[i]:.6g}]"
        for i in joints
        if q[i] < robot.lower[i] or q[i] > robot.upper[i]
    )


def _task_jacobian(s: Search, q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The weighted task Jacobian J_e (active columns), the weighted task error and the full
    error e = [p − p_t; log3(R R_tᵀ)] at wire ``q``."""
    robot, ch = s.robot, s.ch
    model, data = robot.model, robot.data
    qp = robot.to_pin(q)
    pin.computeJointJacobians(model, data, qp)
    T = pin.updateFramePlacement(model, data, ch.frame_id)
    J = pin.getFrameJacobian(model, data, ch.frame_id, pin.LOCAL_WORLD_ALIGNED).reshape(6, -1)
    J = J[:, ch.cols].copy()
    Re = T.rotation @ s.target.rotation.T
    J[3:] = pin.Jlog3(Re).T @ J[3:]
    e = np.concatenate((T.translation - s.target.translation, pin.log3(Re)))
    rows = s.rows
    Je, et = J[rows], e[rows]
    if s.sw is not None:
        Je, et = Je * s.sw[:, None], et * s.sw
    return Je, et, e


def _unconstrained(s: Search, q: np.ndarray) -> str | None:
    """Descend from ``q`` ignoring the joint limits (damped least squares, at most
    :data:`UNCONSTRAINED_ITERATIONS` steps); when that reaches the target within the
    tolerances with joints outside their limits, the joints and values, else None."""
    q = q.copy()
    active = s.ch.active
    for _ in range(UNCONSTRAINED_ITERATIONS):
        Je, et, e = _task_jacobian(s, q)
        if not (np.isfinite(e).all() and np.isfinite(Je).all()):
            return None
        ep, er = s._checked(e)
        if ep <= s.tol_p and er <= s.tol_r:
            return outside_limits(s.robot, q, active) or None
        lam2 = 1e-6 + 1e-3 * float(et @ et)
        A = Je @ Je.T + lam2 * np.eye(Je.shape[0])
        q[active] -= Je.T @ np.linalg.solve(A, et)
    return None


def _pinned(s: Search, Je: np.ndarray, et: np.ndarray, qa: np.ndarray) -> str | None:
    """The joints of the best iterate pinned at a limit with the descent pushing out."""
    g = Je.T @ et
    big = float(np.abs(g).max(initial=0.0))
    if not big > 0.0:
        return None
    ch = s.ch
    out = []
    for i, (v, lo, hi) in enumerate(zip(qa, ch.lower, ch.upper, strict=True)):
        if abs(g[i]) < PINNED_SHARE * big:
            continue
        if (v <= lo and g[i] > 0.0) or (v >= hi and g[i] < 0.0):
            joint = s.robot.joints[int(ch.active[i])]
            side = "lower" if v <= lo else "upper"
            out.append(f"{joint.name} at its {side} limit {v:.6g}")
    return ", ".join(out) or None


def classify(
    s: Search, q: np.ndarray, ep: float, er: float, max_iterations: int | None
) -> tuple[str, str]:
    """(reason, detail) of a search that found no solution; ``q`` is the best iterate (wire)
    with its position and orientation errors ``ep``, ``er``."""
    errors = f"best position error {ep:.3g} m, orientation error {er:.3g} rad"
    if s.rejected:
        return "collision", (
            f"{s.rejected} configuration(s) reached the target within tolerance and limits, "
            "but every one collides (self-collision or obstacles)"
        )
    if s.outside_limits is not None:
        return (
            "joint_limits",
            f"the target is reached only outside the joint limits: {s.outside_limits}",
        )
    outside = _unconstrained(s, q)
    if outside is not None:
        return "joint_limits", (
            f"the target is reached only outside the joint limits (a descent ignoring them "
            f"reaches it with {outside}); {errors}"
        )
    qa = q[s.ch.active]
    Je, et, _ = _task_jacobian(s, q)
    if not (np.isfinite(Je).all() and np.isfinite(et).all()):
        return "timeout", f"the budget ran out; {errors}"  # no finite Jacobian to judge by
    pinned = _pinned(s, Je, et, qa)
    if pinned is not None:
        return "joint_limits", (
            f"the best configuration is pinned at a joint limit with the error decreasing "
            f"outwards ({pinned}); {errors}"
        )
    prismatic = np.array([s.robot.joints[int(i)].type == "prismatic" for i in s.ch.active])
    length = length_scale(s.robot, s.ch.frame_id)
    sv = np.linalg.svd(dimensionless(Je, s.rows, prismatic, length), compute_uv=False)
    smin = float(sv[-1]) if sv.size else 0.0
    if smin < SINGULAR_SIGMA:
        return "singular", (
            f"the search stalled at a singular configuration (smallest singular value of the "
            f"task Jacobian {smin:.3g} < {SINGULAR_SIGMA:g}); {errors}"
        )
    counts = f"{s.iterations} iterations, {s.restarts} restarts"
    if s.timed_out or max_iterations is None:
        return "timeout", f"the time budget (timeout_ms) ran out after {counts}; {errors}"
    return (
        "timeout",
        f"the iteration cap (max_iterations = {max_iterations}) was reached after {counts}; "
        f"{errors}",
    )
