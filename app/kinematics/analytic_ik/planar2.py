"""Planar 2-link (RR) arms
-----------------------
A chain of exactly two revolute joints with parallel axes (the course's planar 2-link arm,
any placement in space, any link offsets). In the plane normal to axis 1 through joint 1,
with r1 the vector from axis 1 to axis 2 and r2 the vector from axis 2 to the frame origin at
q = 0 (l1 = |r1|, l2 = |r2|, β = ∠(r1, r2)), the frame origin is

    P(q) = Rot(q1) · (r1 + Rot(s·q2) · r2),       s = ±1 (axis 2 parallel or antiparallel)

so for a target t in the plane, |t|² = l1² + l2² + 2 l1 l2 cos(s·q2 + β), i.e. the course's

    c2 = (|t|² − l1² − l2²) / (2 l1 l2),   solvable iff |c2| ≤ 1,
    s·q2 + β = ±acos(c2)                   (the two elbow solutions),
    q1 = atan2(t) − atan2(r1 + Rot(±acos c2 − β) r2).

With the planar DH table (robots/dh/planar2.yaml: β = 0, s = 1) this is θ2 = ±acos(c2) and
θ1 = atan2(y, x) − atan2(l2 sin θ2, l1 + l2 cos θ2). Each angle is moved by a multiple of 2π
into the joint's limits when possible (closest to the seed); continuous joints are wrapped
to (−π, π].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.angles import wrap_scalar
from app.kinematics.models import RobotModel

PARALLEL = 1e-9  # |a1 × a2| below this: parallel axes
REACH = 1e-12  # slack on |c2| ≤ 1 for targets on the workspace boundary


@dataclass(frozen=True, slots=True)
class Planar2:
    """Geometry of a planar 2-link chain at q = 0 (world frame)."""

    origin: np.ndarray  # a point of axis 1
    u: np.ndarray  # in-plane basis: u, v = a1 × u
    v: np.ndarray
    r1: np.ndarray  # 2-D, axis 1 → axis 2
    r2: np.ndarray  # 2-D, axis 2 → frame origin
    sign2: float  # +1 if axis 2 is parallel to axis 1, −1 if antiparallel

    @property
    def l1(self) -> float:
        return float(np.hypot(*self.r1))

    @property
    def l2(self) -> float:
        return float(np.hypot(*self.r2))


def _rot2(theta: float, r: np.ndarray) -> np.ndarray:
    c, s = math.cos(theta), math.sin(theta)
    return np.array([c * r[0] - s * r[1], s * r[0] + c * r[1]])


def planar2_geometry(robot: RobotModel, active: np.ndarray, frame_id: int) -> Planar2 | None:
    """The :class:`Planar2` description of a chain, or ``None`` if it is not one."""
    if len(active) != 2:
        return None
    joints = [robot.joints[i] for i in active]
    if any(j.type == "prismatic" for j in joints):
        return None
    for j in joints:
        if robot.model.joints[j.pin_id].nv != 1:
            return None
    model = robot.model
    data = model.createData()
    pin.forwardKinematics(model, data, robot.to_pin(np.zeros(robot.n)))
    f0 = pin.updateFramePlacement(model, data, frame_id).translation.copy()
    axes, points = [], []
    for j in joints:
        M = data.oMi[j.pin_id]
        a = np.asarray(j.axis, dtype=float)
        a = a / np.linalg.norm(a)
        axes.append(M.rotation @ a)
        points.append(M.translation.copy())
    a1, a2 = axes
    if np.linalg.norm(np.cross(a1, a2)) > PARALLEL:
        return None
    # Plane basis: u ⟂ a1 (any), v = a1 × u.
    helper = np.array([1.0, 0.0, 0.0]) if abs(a1[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(helper, a1)
    u /= np.linalg.norm(u)
    v = np.cross(a1, u)
    o = points[0]

    def proj(x: np.ndarray) -> np.ndarray:
        d = x - o
        return np.array([d @ u, d @ v])

    r1 = proj(points[1])
    r2 = proj(f0) - r1
    if np.hypot(*r1) < 1e-12 or np.hypot(*r2) < 1e-12:
        return None
    return Planar2(o, u, v, r1, r2, float(np.sign(a1 @ a2)))


def planar2_solutions(geo: Planar2, point: np.ndarray) -> list[tuple[float, float]]:
    """Both elbow solutions (q1, q2) placing the frame origin over ``point`` (may be [])."""
    d = point - geo.origin
    t = np.array([d @ geo.u, d @ geo.v])
    l1, l2 = geo.l1, geo.l2
    c2 = (t @ t - l1 * l1 - l2 * l2) / (2.0 * l1 * l2)
    if abs(c2) > 1.0 + REACH:
        return []
    c2 = min(1.0, max(-1.0, c2))
    beta = math.atan2(geo.r2[1], geo.r2[0]) - math.atan2(geo.r1[1], geo.r1[0])
    out = []
    for phi in (math.acos(c2), -math.acos(c2)):
        w = geo.r1 + _rot2(phi - beta, geo.r2)
        q1 = math.atan2(t[1], t[0]) - math.atan2(w[1], w[0])
        q2 = geo.sign2 * (phi - beta)
        out.append((q1, q2))
    return out


def into_limits(q: float, lower: float, upper: float, seed: float) -> float:
    """``q`` shifted by a multiple of 2π into [lower, upper] (closest to ``seed``).

    Continuous joints (infinite limits) are wrapped to (−π, π]. When no shift fits, ``q``
    wrapped to (−π, π] is returned (and fails the caller's limit check). A non-finite ``q``
    (a closed form on overflowing geometry) is returned as is: FK verification rejects it.
    """
    if not math.isfinite(q):
        return q
    if not (math.isfinite(lower) and math.isfinite(upper)):
        return wrap_scalar(q)
    two_pi = 2.0 * math.pi
    k_lo = math.ceil((lower - q) / two_pi - 1e-12)
    k_hi = math.floor((upper - q) / two_pi + 1e-12)
    if k_lo > k_hi:
        return wrap_scalar(q)
    options = [min(upper, max(lower, q + k * two_pi)) for k in range(k_lo, k_hi + 1)]
    return min(options, key=lambda x: abs(x - seed))
