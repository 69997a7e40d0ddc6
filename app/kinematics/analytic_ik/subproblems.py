"""Paden–Kahan subproblems used by the closed forms (angles about a unit axis k).

- SP1 (:func:`sp1`): the angle θ that rotates a onto b about k.
- SP4 (:func:`sp4`): every θ with hᵀ Rot(k, θ) p = d.
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin


def unit(x: np.ndarray) -> np.ndarray:
    return x / np.linalg.norm(x)


def rot(k: np.ndarray, theta: float) -> np.ndarray:
    """Rotation matrix about unit axis k by theta (Rodrigues)."""
    return pin.exp3(k * theta)


def sp1(k: np.ndarray, a: np.ndarray, b: np.ndarray, K: np.ndarray | None = None) -> float:
    """Subproblem 1: the angle θ with Rot(k, θ)·a ∥ b in the plane normal to k.

    With a⊥, b⊥ the projections on that plane: θ = atan2(k·(a⊥ × b⊥), a⊥·b⊥), where
    k·(a⊥ × b⊥) = k·(a × b) = (k × a)·b and a⊥·b⊥ = a·b − (k·a)(k·b). ``K`` is the
    cross-product matrix of k (precomputed by callers; np.cross is slow on 3-vectors).
    """
    if K is None:
        K = pin.skew(k)
    return math.atan2((K @ a) @ b, a @ b - (k @ a) * (k @ b))


def sp4(
    h: np.ndarray, k: np.ndarray, p: np.ndarray, d: float, K: np.ndarray | None = None
) -> list[float]:
    """Subproblem 4: all θ with hᵀ·Rot(k, θ)·p = d (0, 1 or 2 angles).

    Rot(k, θ)p = (k·p)k + cos θ (p − (k·p)k) + sin θ (k × p), so with
    A = hᵀ(p − (k·p)k), B = hᵀ(k × p), C = (k·p)(h·k): A cos θ + B sin θ = d − C, i.e.
    θ = atan2(B, A) ± acos((d − C)/√(A² + B²)) when the right side is in [−1, 1].
    """
    if K is None:
        K = pin.skew(k)
    kp = K @ p
    par = (k @ p) * k
    A = h @ (p - par)
    B = h @ kp
    C = h @ par
    r = math.hypot(A, B)
    if r < 1e-12:
        return []
    x = (d - C) / r
    if abs(x) > 1.0 + 1e-9:
        return []
    x = min(1.0, max(-1.0, x))
    phi = math.atan2(B, A)
    a = math.acos(x)
    return [phi + a] if a < 1e-12 else [phi + a, phi - a]
