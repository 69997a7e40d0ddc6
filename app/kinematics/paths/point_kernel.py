"""The compiled local solve of a path's next point and its independent checks, in one call.

:func:`step` is what :mod:`.local` calls once per point on chains the compiled IK kernel
supports: the warm damped least-squares attempt from the previous point
(:func:`app.kinematics.ik.kernel.attempt`), then, on the configuration it claims converged,
every check :func:`app.kinematics.paths.local.verify` and the path's guard
(:class:`~app.kinematics.paths.failures.Guard`) make in Python, and the deviation at the
middle of the joint-space step (:meth:`app.kinematics.paths.follow._Walk.deviation`'s first
fraction). It returns a status code (:data:`STATUSES`); the Python side turns it into the
same outcome as the Python checks (a point, or a refused attempt). The caller's ``accept``
predicate (collisions) stays in Python, after an ``OK``.

Checks (in the order of the Python ones)
----------------------------------------
On the wire configuration q = the previous one with the chain's joints replaced by the
attempt's answer:

1. continuous joints wrapped to (−π, π] (:meth:`RobotModel.wrap`), then every joint within
   its limits (a NaN fails): else ``LIMITS``;
2. an independent forward kinematics of q: the chain's placements composed afresh from the
   chain constants (:class:`~app.kinematics.ik.boundary.ChainConstants`, the same
   composition as :mod:`app.kinematics.chain`), not the attempt's last iterate; the
   position error ‖p − p_t‖ (m) and the rotation error ‖log3(R_tᵀ R)‖ (rad) within the IK
   tolerance: else ``OFF_POSE`` (the full pose: the local solve exists only for it);
3. no joint of the chain moves more than ``max_joint_step`` from the previous point
   (continuous joints around the circle, :func:`app.kinematics.ik.ranking.joint_distance`):
   else ``JOINT_STEP``;
4. the branch flags of q (:func:`app.kinematics.ik.branch_kernel.flags`, from the axes,
   axis points, wrist point and frame origin of the same forward kinematics) equal the
   path's: else ``BRANCH`` (not checked when the path has no label).

An attempt that does not converge is ``UNCONVERGED``. Errors are those of the forward
kinematics of step 2, which the answer reports.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from app.kinematics.ik import branch_kernel, joint_frames, kernel, warmup
from app.kinematics.ik.boundary import ChainConstants, StepParameters
from app.kinematics.jit import jit
from app.kinematics.paths.pose_kernel import piece_pose

#: Status codes of :func:`step` and :func:`checks`, indices into :data:`STATUSES`.
OK, UNCONVERGED, LIMITS, OFF_POSE, JOINT_STEP, BRANCH = range(6)
STATUSES = ("ok", "unconverged", "limits", "off_pose", "joint_step", "branch")
#: ``PointConstants.kind`` of a chain without branch labels.
NO_LABELS = -1


class PointConstants(NamedTuple):
    """What :func:`step` reads of one path's chain and options (built once per call of
    :func:`app.kinematics.paths.follow.follow`).

    ``chain``, ``step``: the attempt's constants; ``active`` (k,) int64: the chain's wire
    indices; ``lower``, ``upper`` (n,): every wire joint's limits (±inf: none); ``cont``
    (n,) bool: continuous wire joints; ``wrist`` (3,): the wrist point in the chain frame of
    the fifth moving joint (6R forms; zeros otherwise); ``kind``, ``elbow``, ``tip_axis4``:
    :func:`app.kinematics.ik.branch_kernel.form_arrays` (``kind`` :data:`NO_LABELS` for a
    chain without labels); ``null_on``, ``clamp``: the attempt's switches; ``tol_p``,
    ``tol_r``: the IK tolerance (m, rad); ``max_joint_step``: the guard's bound (rad or m);
    ``cap``: Jacobian evaluations of the attempt.
    """

    chain: ChainConstants
    step: StepParameters
    active: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    cont: np.ndarray
    wrist: np.ndarray
    kind: int
    elbow: bool
    tip_axis4: bool
    null_on: bool
    clamp: bool
    tol_p: float
    tol_r: float
    max_joint_step: float
    cap: int


@jit
def frames(qa, chain, R, p, z, o, w, wrist):  # pragma: no cover
    """:func:`app.kinematics.ik.joint_frames.frames` of ``chain``
    (:class:`~app.kinematics.ik.boundary.ChainConstants`)."""
    joint_frames.frames(
        qa, chain.C, chain.t, chain.prism, chain.last_C, chain.last_t, R, p, z, o, w, wrist
    )


@jit
def residuals(R, p, Rt, pt, out):  # pragma: no cover
    """out[0] = ‖p − p_t‖ (m), out[1] = ‖log3(R_tᵀ R)‖ (rad) (as
    :func:`app.kinematics.paths.failures.residuals` for the full pose)."""
    Re = np.empty((3, 3))
    for i in range(3):
        for j in range(3):
            Re[i, j] = Rt[0, i] * R[0, j] + Rt[1, i] * R[1, j] + Rt[2, i] * R[2, j]
    phi = np.empty(3)
    kernel._log3(Re, phi)
    dx, dy, dz = p[0] - pt[0], p[1] - pt[1], p[2] - pt[2]
    out[0] = math.sqrt(dx * dx + dy * dy + dz * dz)
    out[1] = math.sqrt(phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2])


@jit
def pose_residuals(qa, chain, Rt, pt, out):  # pragma: no cover
    """:func:`residuals` of the frame at the chain configuration ``qa`` against (Rt, pt)."""
    k = qa.shape[0]
    R = np.empty((3, 3))
    p = np.empty(3)
    z = np.empty((k, 3))
    o = np.empty((k, 3))
    w = np.zeros(3)
    frames(qa, chain, R, p, z, o, w, w)
    residuals(R, p, Rt, pt, out)


@jit
def _wrapped(v):  # pragma: no cover
    """v wrapped to (−π, π] (app.kinematics.angles.wrap_scalar)."""
    two_pi = 2.0 * math.pi
    return v - two_pi * math.ceil((v - math.pi) / two_pi)


@jit
def label_code(q, pc):  # pragma: no cover
    """The branch flags of the wire configuration ``q`` (:data:`NO_LABELS` for a chain
    without labels)."""
    if pc.kind == NO_LABELS:
        return NO_LABELS
    active = pc.active
    k = active.shape[0]
    qa = np.empty(k)
    for s in range(k):
        qa[s] = q[active[s]]
    R = np.empty((3, 3))
    p = np.empty(3)
    z = np.empty((k, 3))
    o = np.empty((k, 3))
    w = np.zeros(3)
    frames(qa, pc.chain, R, p, z, o, w, pc.wrist)
    return branch_kernel.flags(z, o, w, p, pc.kind, pc.elbow, pc.tip_axis4)


@jit
def checks(q, q_prev, pc, Rt, pt, label, out):  # pragma: no cover
    """The checks of the module docstring on the wire configuration ``q`` (n,), wrapped in
    place, against the target (Rt, pt) and the previous point ``q_prev`` (n,); ``label``
    the path's flags (:data:`NO_LABELS`: not checked). ``out[0]``, ``out[1]``: the position
    and rotation errors (m, rad) once the forward kinematics ran. Returns the status."""
    n = q.shape[0]
    for i in range(n):
        v = q[i]
        if pc.cont[i]:
            v = _wrapped(v)
            q[i] = v
        if not (v >= pc.lower[i] and v <= pc.upper[i]):
            return LIMITS
    active = pc.active
    k = active.shape[0]
    qa = np.empty(k)
    for s in range(k):
        qa[s] = q[active[s]]
    R = np.empty((3, 3))
    p = np.empty(3)
    z = np.empty((k, 3))
    o = np.empty((k, 3))
    w = np.zeros(3)
    frames(qa, pc.chain, R, p, z, o, w, pc.wrist)
    residuals(R, p, Rt, pt, out)
    if not (out[0] <= pc.tol_p and out[1] <= pc.tol_r):
        return OFF_POSE
    for s in range(k):
        i = active[s]
        d = q[i] - q_prev[i]
        if pc.cont[i]:
            d = _wrapped(d)
        if not abs(d) <= pc.max_joint_step:
            return JOINT_STEP
    if label != NO_LABELS and pc.kind != NO_LABELS:
        if branch_kernel.flags(z, o, w, p, pc.kind, pc.elbow, pc.tip_axis4) != label:
            return BRANCH
    return OK


@jit
def step(q_prev, pc, Rt, pt, label, piece, u, q, out):  # pragma: no cover
    """The next point from the wire configuration ``q_prev`` (n,) towards (Rt, pt): the
    attempt, :func:`checks`, and on ``OK`` the deviation at the middle of the joint-space
    step against the path's pose there, the segment ``piece``
    (:class:`~app.kinematics.paths.pose_kernel.PieceArrays`) at its parameter ``u``.

    ``q`` (n,) receives the checked configuration (wrapped); ``out`` (5,): position and
    rotation errors (m, rad), Jacobian evaluations, position and rotation deviation at the
    middle (m, rad). Returns the status (:data:`STATUSES`).
    """
    active = pc.active
    k = active.shape[0]
    qa = np.empty(k)
    for s in range(k):
        qa[s] = q_prev[active[s]]
    q_ref = qa.copy()
    best = np.full(1, np.inf)
    best_q = np.empty(k)
    tol_p2, tol_r2 = pc.tol_p * pc.tol_p, pc.tol_r * pc.tol_r
    outcome, n = kernel.attempt(
        qa, pc.chain, Rt, pt, q_ref, pc.null_on, pc.clamp, tol_p2, tol_r2, pc.cap, pc.step,
        best, best_q,
    )  # fmt: skip
    out[2] = n
    if outcome != kernel.CONVERGED:
        return UNCONVERGED
    for i in range(q.shape[0]):
        q[i] = q_prev[i]
    for s in range(k):
        q[active[s]] = qa[s]
    status = checks(q, q_prev, pc, Rt, pt, label, out)
    if status != OK:
        return status
    # the middle of the joint-space step (follow's deviation, first fraction)
    for s in range(k):
        i = active[s]
        d = q[i] - q_prev[i]
        if pc.cont[i]:
            d = _wrapped(d)
        qa[s] = q_prev[i] + 0.5 * d
    Rm = np.empty((3, 3))
    pm = np.empty(3)
    piece_pose(piece, u, Rm, pm)
    dev = np.empty(2)
    pose_residuals(qa, pc.chain, Rm, pm, dev)
    out[3] = dev[0]
    out[4] = dev[1]
    return OK


def warm_up_arguments() -> tuple:
    """Arguments of :func:`step` of the types :mod:`.local` passes (a dummy one-joint
    chain, 1 wire joint): what :func:`warm_up` compiles for."""
    from app.kinematics.paths.pose_kernel import PieceArrays

    k = n = 1
    chain = ChainConstants(
        np.ascontiguousarray(np.eye(3)[None]), np.zeros((k, 3)), np.zeros(k, dtype=np.bool_),
        np.eye(3), np.zeros(3), np.full(k, -1.0), np.full(k, 1.0), np.zeros(k, dtype=np.bool_),
    )  # fmt: skip
    step_p = StepParameters(0.01, 1e-10, 0.2, 100.0, 1e-8, 2.0, 0.81, 2, 20)
    pc = PointConstants(
        chain, step_p, np.zeros(k, dtype=np.int64), np.full(n, -1.0), np.full(n, 1.0),
        np.zeros(n, dtype=np.bool_), np.zeros(3), NO_LABELS, False, False, False, False,
        1e-6, 1e-6, 0.1, 1,
    )  # fmt: skip
    z3, eye = np.zeros(3), np.eye(3)
    piece = PieceArrays(
        False, z3, z3, z3, z3, z3, 0.0, 0.0, eye, z3, False, eye, z3, False, 1.0, eye, z3,
        eye, z3,
    )  # fmt: skip
    return (np.zeros(n), pc, eye, z3, NO_LABELS, piece, 0.5, np.zeros(n), np.zeros(5))


def warm_up() -> None:
    """Compile (or load from the cache) :func:`step`, :func:`checks`, :func:`label_code`
    and :func:`pose_residuals` once, with the argument types :mod:`.local` passes, so that
    the first path does not wait for the compiler (for a caller's start-up)."""
    args = warm_up_arguments()
    step(*args)
    q, pc, eye, z3 = args[0], args[1], args[2], args[3]
    checks(q.copy(), q, pc, eye, z3, NO_LABELS, np.zeros(2))
    label_code(q, pc)
    pose_residuals(np.zeros(1), pc.chain, eye, z3, np.zeros(2))


# Compiled with the solver's kernels, before any query's budget starts (ik.warmup.register).
warmup.register(warm_up)
