"""The largest payload the joints' effort limits hold statically (MoveIt's ``getMaxPayload``).

At rest the torques are the gravity torques ``g(q)`` of the robot (with any tool already
attached, ``load``) plus those of the payload: a point mass ``m`` at ``p`` (the frame's
origin plus the payload's centre-of-mass offset ``c`` in the frame's axes) adds
``m · b(q)`` with ``b = J_p(q)ᵀ [0, 0, GRAVITY]`` (N·m per kg; ``J_p`` the world-aligned
translation Jacobian of ``p``). Gravity is linear in mass, so ``b`` is the gravity torque of
1 kg at ``p`` and the payload's rotational inertia plays no part at rest.

Joint ``i`` with limit ``L_i`` holds ``m`` while ``|g_i + m b_i| ≤ L_i``: for ``b_i > 0``,
``m ≤ (L_i − g_i) / b_i``; for ``b_i < 0``, ``m ≤ (L_i + g_i) / −b_i``; for ``|b_i| ≤``
:data:`PER_KG_TOLERANCE` the payload does not load the joint. The maximum payload is the
smallest of these bounds over the joints with a limit and its joint the limiting one; 0 when
the arm already exceeds a limit holding itself (``holds_itself`` False); unbounded
(``math.inf``) when the payload loads no limited joint (e.g. the weight along every joint
axis).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from app.kinematics.dynamics import Payload, effort_limits, gravity_torques, payload
from app.kinematics.models import RobotModel

#: |torque per kg| (N·m/kg, N/kg) below which a payload does not load a joint: a lever of
#: 1e-10 m, rounding residue of an exactly zero moment (a payload straight above the axis).
PER_KG_TOLERANCE = 1e-9


@dataclass
class MaxPayload:
    """The static payload bound at one configuration (module doc)."""

    mass: float  # kg; math.inf when unbounded
    limiting_joint: str | None
    per_joint: np.ndarray  # each joint's bound (kg), inf where it does not bind or has no limit
    gravity: np.ndarray  # g(q) without the payload (N·m or N)
    per_kg: np.ndarray  # b(q): torque per kg of payload
    torques: np.ndarray  # g + mass · b (at a finite mass; g when unbounded)
    holds_itself: bool  # every |g_i| ≤ L_i


def joint_bounds(gravity: np.ndarray, per_kg: np.ndarray, limits: np.ndarray) -> np.ndarray:
    """Each joint's largest payload (kg, module doc), for ``(…, n)`` arrays; inf where the
    joint has no limit or the payload does not load it, 0 where it is over its limit."""
    with np.errstate(divide="ignore", invalid="ignore"):
        up = (limits - gravity) / per_kg
        down = (limits + gravity) / -per_kg
    bound = np.where(
        per_kg > PER_KG_TOLERANCE, up, np.where(per_kg < -PER_KG_TOLERANCE, down, np.inf)
    )
    bound = np.where(np.isnan(limits), np.inf, bound)
    over = np.abs(gravity) > limits  # False for NaN limits
    return np.where(over, 0.0, np.maximum(bound, 0.0))


def max_payloads(
    robot: RobotModel,
    qs: np.ndarray,
    frame: str | None = None,
    com: object = (0.0, 0.0, 0.0),
    *,
    load: Payload | None = None,
) -> list[MaxPayload]:
    """:class:`MaxPayload` at each configuration of ``qs`` (N, n) for a payload at ``frame``
    (the tip by default) with its centre of mass at ``com`` (m, frame axes), on top of
    ``load``. Raises :class:`~app.kinematics.errors.MissingInertiaError` for a robot with a
    massless moving body."""
    qs = np.atleast_2d(np.asarray(qs, dtype=float))
    unit = payload(robot, 1.0, frame, com)
    g0 = gravity_torques(robot, qs, load=load)
    # gravity torques are linear in the masses: b is the difference 1 kg at p makes alone
    per_kg = gravity_torques(robot, qs, load=unit) - gravity_torques(robot, qs)
    limits = effort_limits(robot)
    out = []
    for k in range(qs.shape[0]):
        bounds = joint_bounds(g0[k], per_kg[k], limits)
        i = int(np.argmin(bounds))
        mass = float(bounds[i])
        holds = bool(np.all(~(np.abs(g0[k]) > limits)))
        limiting = robot.joint_names[i] if math.isfinite(mass) else None
        torques = g0[k] + mass * per_kg[k] if math.isfinite(mass) else g0[k].copy()
        out.append(MaxPayload(mass, limiting, bounds, g0[k], per_kg[k], torques, holds))
    return out


def max_payload(
    robot: RobotModel,
    q: np.ndarray,
    frame: str | None = None,
    com: object = (0.0, 0.0, 0.0),
    *,
    load: Payload | None = None,
) -> MaxPayload:
    """:class:`MaxPayload` at one configuration (:func:`max_payloads`)."""
    return max_payloads(robot, np.asarray(q, dtype=float)[None, :], frame, com, load=load)[0]
