"""Velocity kinematics: twist from joint velocities and its damped inverse.

Forward: the twist of a frame is t = J(q)·q̇ with the 6×n geometric Jacobian of
:mod:`app.kinematics.jacobian` (rows [vx, vy, vz, ωx, ωy, ωz]; reference ``world`` = origin
velocity and angular velocity in world axes, ``local`` = the same in the frame's axes).

Inverse: q̇ = J⁺·t, damped near singularities (Nakamura–Hanafusa / Maciejewski–Klein).
With the SVD J_t = Σ σ_i u_i v_iᵀ of the task rows (all six, or the position or orientation
rows only) and the damping

    λ² = 0                                 if σ_min ≥ ε
    λ² = (1 − (σ_min/ε)²) · λ_max²         otherwise,

the answer is the damped least-squares solution q̇ = Σ σ_i/(σ_i² + λ²) · (u_iᵀ t) · v_i
= J_tᵀ(J_t J_tᵀ + λ²I)⁻¹ t. Away from singularities it is the exact minimum-norm
pseudo-inverse solution (residual ‖J_t q̇ − t‖ = 0 when t is achievable); near one, the
damping bounds ‖q̇‖ and the residual reports what could not be achieved.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.kinematics.errors import InvalidInputError
from app.kinematics.ik.problem import MODE_ROWS
from app.kinematics.jacobian import Reference, frame_jacobian
from app.kinematics.models import RobotModel

#: Singular-value threshold ε below which damping starts (m/rad or rad/rad).
SINGULAR_THRESHOLD = 1e-2
#: Damping at an exact singularity, λ_max.
MAX_DAMPING = 1e-1
#: Largest |joint velocity| (rad/s, m/s) and |twist component| (m/s, rad/s) accepted, and
#: largest threshold and damping: far above any machine, and far enough below float64's
#: range (1.8e308) that J·q̇, J⁺·t and their residuals cannot overflow to ±inf or NaN.
MAX_RATE = 1e6
#: The two problems: joint velocities → twist, twist → joint velocities.
DIRECTIONS = ("forward", "inverse")


@dataclass(slots=True)
class InverseVelocity:
    """Result of :func:`inverse_velocity`."""

    joint_velocities: np.ndarray  # (n,) wire order
    twist: np.ndarray  # achieved J q̇ on all six rows
    residual: float  # ‖J_t q̇ − t‖ over the task rows
    damping: float  # λ used
    sigma_min: float  # smallest singular value of the task Jacobian


def forward_velocity(
    robot: RobotModel, q: np.ndarray, qdot: np.ndarray, frame: str, reference: Reference
) -> np.ndarray:
    """Twist [v; ω] (m/s, rad/s) of ``frame`` for joint velocities ``qdot`` at ``q``."""
    qdot = np.asarray(qdot, dtype=float)
    if qdot.shape != (robot.n,):
        raise InvalidInputError(f"expected {robot.n} values (one per joint)", "joint_velocities")
    return frame_jacobian(robot, q, frame, reference) @ qdot


def damping_for(sigma_min: float, threshold: float, max_damping: float) -> float:
    """λ from the smallest singular value: 0 above ``threshold``, growing to ``max_damping``."""
    if threshold <= 0.0:
        raise InvalidInputError("must be positive", "singular_threshold")
    if sigma_min >= threshold:
        return 0.0
    return float(max_damping * np.sqrt(1.0 - (sigma_min / threshold) ** 2))


def inverse_velocity(
    robot: RobotModel,
    q: np.ndarray,
    twist: np.ndarray,
    frame: str,
    reference: Reference,
    *,
    mode: str = "pose",
    threshold: float = SINGULAR_THRESHOLD,
    max_damping: float = MAX_DAMPING,
    joints: np.ndarray | None = None,
) -> InverseVelocity:
    """Joint velocities realising ``twist`` (damped least squares, see the module doc).

    Only the joints that support ``frame`` move; ``mode`` selects the task rows (``pose``:
    all six, ``position``: the linear rows, ``orientation``: the angular rows; the other
    components of ``twist`` are ignored). ``joints`` (wire indices, e.g. a planning
    group's) restricts the moving joints further.
    """
    twist = np.asarray(twist, dtype=float)
    if twist.shape != (6,):
        raise InvalidInputError("expected 6 values [vx, vy, vz, wx, wy, wz]", "twist")
    if mode not in MODE_ROWS:
        raise InvalidInputError("use pose, position or orientation", "mode")
    rows = np.array(MODE_ROWS[mode])
    cols = robot.supporting_joints(frame, joints)
    J = frame_jacobian(robot, q, frame, reference)
    Jt = J[np.ix_(rows, cols)]
    t = twist[rows]
    qdot = np.zeros(robot.n)
    if cols.size == 0:
        return InverseVelocity(qdot, J @ qdot, float(np.linalg.norm(t)), 0.0, 0.0)
    U, s, Vt = np.linalg.svd(Jt, full_matrices=False)
    sigma_min = float(s[-1])
    lam = damping_for(sigma_min, threshold, max_damping)
    # = 1/σ_i when λ = 0 (then every σ_i ≥ ε > 0); a direction whose σ_i² + λ² underflows
    # to 0 (σ_i = 0 and a tiny λ) gets no velocity instead of 0/0
    denom = s * s + lam * lam
    gain = np.divide(s, denom, out=np.zeros_like(s), where=denom > 0.0)
    qdot[cols] = Vt.T @ (gain * (U.T @ t))
    achieved = J @ qdot
    residual = float(np.linalg.norm(achieved[rows] - t))
    return InverseVelocity(qdot, achieved, residual, lam, sigma_min)
