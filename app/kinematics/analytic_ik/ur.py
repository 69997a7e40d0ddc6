"""UR-type 6R arms (three parallel axes, intersecting last two)
------------------------------------------------------------
Six revolute joints whose axes 2, 3, 4 are parallel (direction h) and whose axes 5 and 6
intersect (the UR family). With the product of exponentials at q = 0, T(q) = E1⋯E6·M
(E_i a rotation by q_i about axis i: direction ω_i through p_i), R_d = R_t·R_Mᵀ, the point
c0 where axes 5 and 6 meet (moved to c_d = T_t·M⁻¹·c0 by the target), every solution
follows from Paden–Kahan subproblems (SP1: rotate a onto b about k; SP4: hᵀ Rot(k, θ) p = d):

1. q1 (SP4, ≤ 2 solutions, shoulder left/right): rotations about axes parallel to h keep
   the h-component, so (Rot(ω1, q1) h)ᵀ (c_d − p1) = hᵀ (c0 − p1).
2. q5 (SP4, ≤ 2, wrist up/down): hᵀ Rot(ω5, q5) ω6 = hᵀ R1ᵀ R_d ω6, since
   R1ᵀ R_d = Rot(h, θ) R5 R6 with θ = q2 + q3 + q4 and Rot(h, θ)ᵀ h = h.
3. q6 (SP1): Rot(ω6, q6) (R_dᵀ R1 h) = R5ᵀ h.
4. θ (SP1 about h): Rot(h, θ) = R1ᵀ R_d R6ᵀ R5ᵀ.
5. q2, q3 (planar 2-link above, ≤ 2, elbow up/down): E2 E3 p4 = E1⁻¹ c_d − Rot(h, θ)(c0 − p4),
   then q4 = θ − q2 − q3 (signs flipped for antiparallel axes).

Up to 8 candidates, moved into the limits (±2π limits admit two values per angle: the one
closest to the seed is used), sorted by distance to the seed and verified by FK. Near a
singularity (wrist: q5 ≈ 0; shoulder: c_d on axis 1; elbow stretched) a subproblem loses
its solution or becomes ill-conditioned; the numeric solver then takes over.

The Python form (:func:`ur_solutions`) and its compiled copy (:func:`ur_candidates_compiled`,
Numba; same steps, same order) are kept side by side so that one reads against the other.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.analytic_ik.planar2 import PARALLEL, REACH, Planar2, planar2_solutions
from app.kinematics.analytic_ik.subproblems import rot, sp1, sp4, unit
from app.kinematics.jit import available as compiled_available
from app.kinematics.jit import jit
from app.kinematics.models import RobotModel


@dataclass(frozen=True, slots=True)
class URType:
    """Zero-configuration geometry of a UR-type 6R chain (world frame)."""

    w: np.ndarray  # (6, 3) axis directions ω_i
    p: np.ndarray  # (6, 3) points on the axes
    h: np.ndarray  # common direction of axes 2-4 (= ω2)
    s: np.ndarray  # (6,) +1/−1: ω_i = s_i h for i = 2, 3, 4 (1 elsewhere)
    c0: np.ndarray  # intersection of axes 5 and 6
    K: np.ndarray  # (6, 3, 3) cross-product matrices of the ω_i
    M: pin.SE3  # frame placement at q = 0
    arm: Planar2  # the 2-link arm of axes 2, 3 with tip on axis 4
    #: The geometry as the compiled form's arguments (C-ordered arrays), built once.
    consts: tuple = ()


def _line_intersection(p1, w1, p2, w2) -> np.ndarray | None:
    """The common point of two lines, or None if they are parallel or skew."""
    n = np.cross(w1, w2)
    nn = n @ n
    if nn < 1e-12:
        return None
    d = p2 - p1
    if abs(d @ n) / math.sqrt(nn) > 1e-9:
        return None
    t1 = np.cross(d, w2) @ n / nn
    return p1 + t1 * w1


def ur_geometry(robot: RobotModel, active: np.ndarray, frame_id: int) -> URType | None:
    """The :class:`URType` description of a chain, or ``None`` if it is not one."""
    if len(active) != 6:
        return None
    joints = [robot.joints[i] for i in active]
    model = robot.model
    if any(j.type == "prismatic" or model.joints[j.pin_id].nv != 1 for j in joints):
        return None
    data = model.createData()
    pin.forwardKinematics(model, data, robot.to_pin(np.zeros(robot.n)))
    M = pin.updateFramePlacement(model, data, frame_id).copy()
    w = np.array([data.oMi[j.pin_id].rotation @ unit(np.asarray(j.axis, float)) for j in joints])
    p = np.array([data.oMi[j.pin_id].translation for j in joints])
    h = w[1]
    s = np.ones(6)
    for i in (2, 3):
        if np.linalg.norm(np.cross(w[i], h)) > PARALLEL:
            return None
        s[i] = float(np.sign(w[i] @ h))
    if np.linalg.norm(np.cross(w[0], h)) < 1e-6 or np.linalg.norm(np.cross(w[4], h)) < 1e-6:
        return None
    c0 = _line_intersection(p[4], w[4], p[5], w[5])
    if c0 is None:
        return None
    helper = np.array([1.0, 0.0, 0.0]) if abs(h[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = unit(np.cross(helper, h))
    v = np.cross(h, u)

    def proj(x: np.ndarray) -> np.ndarray:
        d = x - p[1]
        return np.array([d @ u, d @ v])

    r1 = proj(p[2])
    r2 = proj(p[3]) - r1
    if np.hypot(*r1) < 1e-9 or np.hypot(*r2) < 1e-9:
        return None
    arm = Planar2(p[1].copy(), u, v, r1, r2, float(s[2]))
    K = np.array([pin.skew(x) for x in w])
    c = np.ascontiguousarray
    consts = (w, p, h, s, c0, c(M.rotation), c(M.translation), arm.origin, arm.u, arm.v)
    consts += (arm.r1, arm.r2, arm.sign2)
    return URType(
        w, p, h, s, c0, K, M, arm, tuple(c(x) if isinstance(x, np.ndarray) else x for x in consts)
    )


def _nearest_first(angles: list[float], seed: float) -> list[float]:
    """Angles ordered by their circular distance to ``seed``."""
    return sorted(angles, key=lambda x: abs(math.remainder(x - seed, 2.0 * math.pi)))


def ur_solutions(
    geo: URType, target: pin.SE3, seed: np.ndarray | None = None
) -> Iterator[np.ndarray]:
    """Every closed-form solution (up to 8) of a UR-type chain, angles unwrapped.

    With a ``seed`` (active joints), branches are generated nearest-first (shoulder, then
    wrist, then elbow), so a caller that needs one solution stops after one branch.
    """
    w, p, h, s = geo.w, geo.p, geo.h, geo.s
    Rd = target.rotation @ geo.M.rotation.T
    c_d = target.act(geo.M.actInv(geo.c0))
    u = geo.arm.u
    c0_p4 = geo.c0 - p[3]
    K = geo.K
    q1s = sp4(c_d - p[0], w[0], h, h @ (geo.c0 - p[0]), K[0])
    if seed is not None:
        q1s = _nearest_first(q1s, seed[0])
    for q1 in q1s:
        R1 = rot(w[0], q1)
        R1h = R1 @ h
        RdT_R1h = Rd.T @ R1h
        q5s = sp4(h, w[4], w[5], R1h @ Rd @ w[5], K[4])
        if seed is not None:
            q5s = _nearest_first(q5s, seed[4])
        arm_base = p[0] + R1.T @ (c_d - p[0])
        for q5 in q5s:
            R5 = rot(w[4], q5)
            R5T = R5.T
            q6 = sp1(w[5], RdT_R1h, R5T @ h, K[5])
            Rth = R1.T @ Rd @ rot(w[5], -q6) @ R5T
            theta = sp1(h, u, Rth @ u, K[1])
            wrist = arm_base - rot(h, theta) @ c0_p4
            elbows = planar2_solutions(geo.arm, wrist)
            if seed is not None and len(elbows) == 2:
                elbows.sort(key=lambda e: abs(math.remainder(e[1] - seed[2], 2.0 * math.pi)))
            for q2, q3 in elbows:
                q4 = s[3] * (theta - q2 - s[2] * q3)
                yield np.array([q1, q2, q3, q4, q5, q6])


# ----------------------------------------------------------------- compiled UR closed form
@jit
def _sp4_nb(h, k, p, d, out):  # pragma: no cover
    """:func:`sp4` into ``out`` (2,); returns the number of angles (0, 1 or 2)."""
    kp0 = k[1] * p[2] - k[2] * p[1]
    kp1 = k[2] * p[0] - k[0] * p[2]
    kp2 = k[0] * p[1] - k[1] * p[0]
    kdp = k[0] * p[0] + k[1] * p[1] + k[2] * p[2]
    A = h[0] * (p[0] - kdp * k[0]) + h[1] * (p[1] - kdp * k[1]) + h[2] * (p[2] - kdp * k[2])
    B = h[0] * kp0 + h[1] * kp1 + h[2] * kp2
    C = kdp * (h[0] * k[0] + h[1] * k[1] + h[2] * k[2])
    r = math.hypot(A, B)
    if r < 1e-12:
        return 0
    x = (d - C) / r
    if abs(x) > 1.0 + 1e-9:
        return 0
    x = min(1.0, max(-1.0, x))
    phi = math.atan2(B, A)
    a = math.acos(x)
    out[0] = phi + a
    if a < 1e-12:
        return 1
    out[1] = phi - a
    return 2


@jit
def _sp1_nb(k, a, b):  # pragma: no cover
    """:func:`sp1`: atan2((k × a)·b, a·b − (k·a)(k·b))."""
    ka0 = k[1] * a[2] - k[2] * a[1]
    ka1 = k[2] * a[0] - k[0] * a[2]
    ka2 = k[0] * a[1] - k[1] * a[0]
    ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    kak = (k[0] * a[0] + k[1] * a[1] + k[2] * a[2]) * (k[0] * b[0] + k[1] * b[1] + k[2] * b[2])
    return math.atan2(ka0 * b[0] + ka1 * b[1] + ka2 * b[2], ab - kak)


@jit
def _rot_nb(k, theta):  # pragma: no cover
    """Rodrigues: I + sin θ [k]× + (1 − cos θ) [k]×² (k unit)."""
    c, s = math.cos(theta), math.sin(theta)
    v = 1.0 - c
    x, y, z = k[0], k[1], k[2]
    R = np.empty((3, 3))
    R[0, 0], R[0, 1], R[0, 2] = c + x * x * v, x * y * v - z * s, x * z * v + y * s
    R[1, 0], R[1, 1], R[1, 2] = y * x * v + z * s, c + y * y * v, y * z * v - x * s
    R[2, 0], R[2, 1], R[2, 2] = z * x * v - y * s, z * y * v + x * s, c + z * z * v
    return R


@jit
def _circ(x, seed):  # pragma: no cover
    """|x − seed| around the circle (as abs(math.remainder(x − seed, 2π)))."""
    two_pi = 2.0 * math.pi
    d = x - seed
    return abs(d - two_pi * math.floor(d / two_pi + 0.5))


@jit
def _order2(vals, n, seed):  # pragma: no cover
    """Two angles ordered by circular distance to ``seed`` (as :func:`_nearest_first`)."""
    if n == 2 and _circ(vals[1], seed) < _circ(vals[0], seed):
        vals[0], vals[1] = vals[1], vals[0]


@jit
def _dot(a, b):  # pragma: no cover
    """a·b of two 3-vectors (inline: NumPy's ``@`` is a BLAS call per product in Numba)."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@jit
def _mv(M, x):  # pragma: no cover
    """M x for a 3×3 M (any layout, e.g. a transposed view) and a 3-vector."""
    y = np.empty(3)
    for i in range(3):
        y[i] = M[i, 0] * x[0] + M[i, 1] * x[1] + M[i, 2] * x[2]
    return y


@jit
def _mm(A, B):  # pragma: no cover
    """A B for 3×3 matrices (any layout)."""
    C = np.empty((3, 3))
    for i in range(3):
        for j in range(3):
            C[i, j] = A[i, 0] * B[0, j] + A[i, 1] * B[1, j] + A[i, 2] * B[2, j]
    return C


@jit
def _ur_all(  # pragma: no cover
    w, p, h, s, c0, MR, Mp, origin, u, v, r1, r2, sign2, Rt, pt, seed, out
):
    """Every UR-type branch (:func:`ur_solutions`, same order) into ``out`` (8, 6);
    returns how many."""
    Rd = _mm(Rt, MR.T)
    c_loc = _mv(MR.T, c0 - Mp)
    c_d = _mv(Rt, c_loc) + pt
    c0_p4 = c0 - p[3]
    l1 = math.hypot(r1[0], r1[1])
    l2 = math.hypot(r2[0], r2[1])
    beta = math.atan2(r2[1], r2[0]) - math.atan2(r1[1], r1[0])
    q1s = np.empty(2)
    q5s = np.empty(2)
    n1 = _sp4_nb(c_d - p[0], w[0], h, _dot(h, c0 - p[0]), q1s)
    _order2(q1s, n1, seed[0])
    n = 0
    for i1 in range(n1):
        q1 = q1s[i1]
        R1 = _rot_nb(w[0], q1)
        R1h = _mv(R1, h)
        RdT_R1h = _mv(Rd.T, R1h)
        n5 = _sp4_nb(h, w[4], w[5], _dot(R1h, _mv(Rd, w[5])), q5s)
        _order2(q5s, n5, seed[4])
        arm_base = p[0] + _mv(R1.T, c_d - p[0])
        for i5 in range(n5):
            q5 = q5s[i5]
            R5T = _rot_nb(w[4], q5).T
            q6 = _sp1_nb(w[5], RdT_R1h, _mv(R5T, h))
            Rth = _mm(_mm(_mm(R1.T, Rd), _rot_nb(w[5], -q6)), R5T)
            theta = _sp1_nb(h, u, _mv(Rth, u))
            wrist = arm_base - _mv(_rot_nb(h, theta), c0_p4)
            # planar 2-link (axes 2, 3) to the wrist point
            d = wrist - origin
            t0 = _dot(d, u)
            t1 = _dot(d, v)
            c2 = (t0 * t0 + t1 * t1 - l1 * l1 - l2 * l2) / (2.0 * l1 * l2)
            if abs(c2) > 1.0 + REACH:
                continue
            c2 = min(1.0, max(-1.0, c2))
            ac = math.acos(c2)
            e1 = np.empty(2)
            e2 = np.empty(2)
            for j in range(2):
                phi = ac if j == 0 else -ac
                a = phi - beta
                ca, sa = math.cos(a), math.sin(a)
                wx = r1[0] + ca * r2[0] - sa * r2[1]
                wy = r1[1] + sa * r2[0] + ca * r2[1]
                e1[j] = math.atan2(t1, t0) - math.atan2(wy, wx)
                e2[j] = sign2 * a
            order = (0, 1)
            if _circ(e2[1], seed[2]) < _circ(e2[0], seed[2]):
                order = (1, 0)
            for j in order:
                q2, q3 = e1[j], e2[j]
                out[n, 0] = q1
                out[n, 1] = q2
                out[n, 2] = q3
                out[n, 3] = s[3] * (theta - q2 - s[2] * q3)
                out[n, 4] = q5
                out[n, 5] = q6
                n += 1
    return n


@jit
def _into_limits_nb(Q, n, lower, upper, seed):  # pragma: no cover
    """:func:`into_limits` applied to the first n rows of Q (n, k), in place."""
    two_pi = 2.0 * math.pi
    for r in range(n):
        for i in range(Q.shape[1]):
            q = Q[r, i]
            lo, hi = lower[i], upper[i]
            # wrapped to (−π, π] (app.kinematics.angles.wrap_scalar)
            wrapped = q - two_pi * math.ceil((q - math.pi) / two_pi)
            if not (math.isfinite(lo) and math.isfinite(hi)):
                Q[r, i] = wrapped
                continue
            k_lo = math.ceil((lo - q) / two_pi - 1e-12)
            k_hi = math.floor((hi - q) / two_pi + 1e-12)
            if k_lo > k_hi:
                Q[r, i] = wrapped
                continue
            best, best_d = 0.0, np.inf
            for k in range(k_lo, k_hi + 1):
                x = min(hi, max(lo, q + k * two_pi))
                dd = abs(x - seed[i])
                if dd < best_d:
                    best, best_d = x, dd
            Q[r, i] = best


def ur_candidates_compiled(
    geo: URType, target: pin.SE3, seed: np.ndarray, lower: np.ndarray, upper: np.ndarray
) -> np.ndarray:
    """The candidates of :func:`ur_solutions` (same order), moved into the limits as
    :func:`into_limits` does, from the compiled form: an (m, 6) array, m ≤ 8."""
    out = np.empty((8, 6))
    c = np.ascontiguousarray
    n = _ur_all(*geo.consts, c(target.rotation), c(target.translation), seed, out)
    _into_limits_nb(out, n, lower, upper, seed)
    return out[:n]


def warm_up() -> None:
    """Compile the UR closed form for the argument types :func:`prepare` passes (C-ordered
    float64 arrays), from dummy geometry."""
    if not compiled_available():
        return
    z3, e3 = np.zeros(3), np.eye(3)
    _ur_all(
        np.zeros((6, 3)), np.zeros((6, 3)), z3, np.ones(6), z3, e3, z3,
        z3, z3, z3, np.ones(2), np.ones(2), 1.0, e3, z3, np.zeros(6), np.empty((8, 6)),
    )  # fmt: skip
    _into_limits_nb(np.zeros((8, 6)), 0, np.zeros(6), np.zeros(6), np.zeros(6))
