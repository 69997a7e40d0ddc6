"""Angles of continuous joints: the one wrapping convention, (−π, π].

A continuous joint is one angle on the wire. Every angle the service computes for one
(:meth:`app.kinematics.models.RobotModel.from_pin`, whose ``arctan2`` gives (−π, π]) and
every wrap it applies (:func:`wrap_angle`) lands in the same half-open interval, so the
same configuration never comes out as −π in one answer and +π in another.
"""

from __future__ import annotations

import math

import numpy as np

TWO_PI = 2.0 * math.pi


def wrap_angle(x: np.ndarray | float) -> np.ndarray:
    """Angles (rad) wrapped to (−π, π]: ``x − 2π·ceil((x − π) / 2π)``, as ``arctan2``
    returns them (+π stays +π, −π becomes +π)."""
    x = np.asarray(x, dtype=float)
    return x - TWO_PI * np.ceil((x - math.pi) / TWO_PI)


def wrap_scalar(x: float) -> float:
    """One angle (rad) wrapped to (−π, π], as :func:`wrap_angle`. The compiled kernels
    (Numba) write the same expression inline."""
    return x - TWO_PI * math.ceil((x - math.pi) / TWO_PI)
