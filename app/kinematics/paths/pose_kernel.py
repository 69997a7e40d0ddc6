"""The pose of a path's segment at its parameter u, in compiled code.

:func:`piece_pose` is :meth:`app.kinematics.paths.segments._Piece.pose` for the compiled
point (:mod:`.point_kernel`), which measures the deviation from the path at the middle of a
step without building a :class:`pinocchio.SE3` in Python: the same formulas on the same
constants (:class:`PieceArrays`, from :meth:`app.kinematics.paths.segments._Piece.arrays`),
position linear along a line or at constant speed along an arc, orientation by slerp
R₀·exp3(t·w) (Rodrigues' formula here, Pinocchio's ``exp3`` there: they agree to rounding),
the start at u ≤ 0 and exactly the end at u ≥ 1. Root frame, metres and radians.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from app.kinematics.jit import jit


class PieceArrays(NamedTuple):
    """One segment's constants (see :class:`app.kinematics.paths.segments._Piece`).

    ``arc``: a circular segment (else a line); ``p0``, ``dp`` (3,): a line's start and
    displacement; ``c``, ``e1``, ``e2`` (3,), ``r``, ``phi``: an arc's centre, in-plane unit
    vectors, radius and swept angle; ``R0`` (3, 3), ``w1`` (3,), ``turn1``: the first slerp
    (from the start) and whether it turns; ``Rv``, ``w2``, ``turn2``: the second (from
    ``via``; a line has none); ``u_via``: where the first ends (1 for a line); ``Rs``, ``ps``,
    ``Re``, ``pe``: the start and end poses.
    """

    arc: bool
    p0: np.ndarray
    dp: np.ndarray
    c: np.ndarray
    e1: np.ndarray
    e2: np.ndarray
    r: float
    phi: float
    R0: np.ndarray
    w1: np.ndarray
    turn1: bool
    Rv: np.ndarray
    w2: np.ndarray
    turn2: bool
    u_via: float
    Rs: np.ndarray
    ps: np.ndarray
    Re: np.ndarray
    pe: np.ndarray


@jit
def _slerp(R0, w, t, R):  # pragma: no cover
    """R = R0·exp3(t·w) (Rodrigues)."""
    vx, vy, vz = t * w[0], t * w[1], t * w[2]
    th2 = vx * vx + vy * vy + vz * vz
    th = math.sqrt(th2)
    if th < 1e-8:
        a = 1.0 - th2 / 6.0
        b = 0.5 - th2 / 24.0
    else:
        a = math.sin(th) / th
        b = (1.0 - math.cos(th)) / th2
    E = np.empty((3, 3))
    E[0, 0] = 1.0 - b * (vy * vy + vz * vz)
    E[1, 1] = 1.0 - b * (vx * vx + vz * vz)
    E[2, 2] = 1.0 - b * (vx * vx + vy * vy)
    E[0, 1] = -a * vz + b * vx * vy
    E[1, 0] = a * vz + b * vx * vy
    E[0, 2] = a * vy + b * vx * vz
    E[2, 0] = -a * vy + b * vx * vz
    E[1, 2] = -a * vx + b * vy * vz
    E[2, 1] = a * vx + b * vy * vz
    for i in range(3):
        for j in range(3):
            R[i, j] = R0[i, 0] * E[0, j] + R0[i, 1] * E[1, j] + R0[i, 2] * E[2, j]


@jit
def piece_pose(pa, u, R, p):  # pragma: no cover
    """The pose (R (3, 3), p (3,), written in place) of the segment ``pa`` at u."""
    if u >= 1.0 or u <= 0.0:
        Rx, px = (pa.Re, pa.pe) if u >= 1.0 else (pa.Rs, pa.ps)
        for i in range(3):
            p[i] = px[i]
            for j in range(3):
                R[i, j] = Rx[i, j]
        return
    if pa.arc:
        a = u * pa.phi
        ca, sa = math.cos(a), math.sin(a)
        for i in range(3):
            p[i] = pa.c[i] + pa.r * (ca * pa.e1[i] + sa * pa.e2[i])
    else:
        for i in range(3):
            p[i] = pa.p0[i] + u * pa.dp[i]
    if u <= pa.u_via:
        R0, w, turns, t = pa.R0, pa.w1, pa.turn1, u / pa.u_via
    else:
        R0, w, turns, t = pa.Rv, pa.w2, pa.turn2, (u - pa.u_via) / (1.0 - pa.u_via)
    if turns:
        _slerp(R0, w, t, R)
    else:
        for i in range(3):
            for j in range(3):
                R[i, j] = R0[i, j]
