"""Orientation bins of reachability maps (cubed 3-sphere, equal-angle).

A rotation is its unit quaternion q = [x, y, z, w] with q and −q identified. The component
with the largest magnitude, k ∈ {x, y, z, w}, picks one of 4 *faces* (the 4-D hypercube's
8 faces, antipodal pairs identified); q is flipped so that q_k > 0. The other three
components (in x, y, z, w order without k) give the equal-angle coordinates
a_i = arctan(q_i / q_k) ∈ [−π/4, π/4], each cut into ``d`` equal intervals. So there are
4·d³ bins; a face spans rotations of ±90° about each axis (for face w and a rotation by θ
about x, a = θ/2), so a bin spans about 180°/d per axis (d = 4: 45°). Cell volumes (Haar
measure) differ by at most a factor of 2, unlike RPY bins, which crowd near pitch ±90°.
``d = 0`` keeps one bin: a position-only map.
Bin index = k·d³ + i₀·d² + i₁·d + i₂; ties between equal largest components go to the
first, for building and querying alike.
"""

from __future__ import annotations

import math

import numpy as np


def orientation_bins(divisions: int) -> int:
    """Number of orientation bins for ``divisions`` (4·d³, or 1 when d = 0)."""
    return 1 if divisions == 0 else 4 * divisions**3


def orientation_bin(quat: np.ndarray, divisions: int) -> np.ndarray:
    """Bin index (N,) of quaternions [x, y, z, w] (N, 4) (cubed 3-sphere, module doc)."""
    q = np.asarray(quat, dtype=float).reshape(-1, 4)
    n = q.shape[0]
    if divisions == 0:
        return np.zeros(n, dtype=np.int64)
    k = np.argmax(np.abs(q), axis=1)
    lead = q[np.arange(n), k]
    others = np.empty((n, 3))
    for face in range(4):
        sel = k == face
        if sel.any():
            others[sel] = q[sel][:, [c for c in range(4) if c != face]]
    # the sign of the lead component cancels the q ~ −q ambiguity
    return _bin_from_ratios(k, (others / lead[:, None]).T, divisions)


def orientation_bin_from_rotation(Rt: np.ndarray, divisions: int) -> np.ndarray:
    """Bin index (N,) of component-major rotations Rt (3, 3, N), same bins as
    :func:`orientation_bin` without building quaternions: 4q_c² are the Shepperd candidates
    (1 + tr, 1 + 2R_00 − tr, …), and q_i/q_k = (pair sum or difference)/(4q_k²)."""
    n = Rt.shape[2]
    if divisions == 0:
        return np.zeros(n, dtype=np.int64)
    r00, r11, r22 = Rt[0, 0], Rt[1, 1], Rt[2, 2]
    tr = r00 + r11 + r22
    cand = np.stack([1.0 + 2.0 * r00 - tr, 1.0 + 2.0 * r11 - tr, 1.0 + 2.0 * r22 - tr, 1.0 + tr])
    k = np.argmax(cand, axis=0)
    d21 = Rt[2, 1] - Rt[1, 2]
    d02 = Rt[0, 2] - Rt[2, 0]
    d10 = Rt[1, 0] - Rt[0, 1]
    s01 = Rt[0, 1] + Rt[1, 0]
    s02 = Rt[0, 2] + Rt[2, 0]
    s12 = Rt[1, 2] + Rt[2, 1]
    # the other three components, in x, y, z, w order without the largest, per face
    num = np.stack(
        [
            np.choose(k, [s01, s01, s02, d21]),
            np.choose(k, [s02, s12, s12, d02]),
            np.choose(k, [d21, d02, d10, d10]),
        ]
    )
    ratio = num / np.take_along_axis(cand, k[None], axis=0)
    return _bin_from_ratios(k, ratio, divisions)


def _bin_from_ratios(k: np.ndarray, ratio: np.ndarray, d: int) -> np.ndarray:
    a = np.arctan(ratio)
    idx = np.clip(np.floor((a / (math.pi / 2) + 0.5) * d).astype(np.int64), 0, d - 1)
    return k.astype(np.int64) * d**3 + idx[0] * d * d + idx[1] * d + idx[2]
