"""The answer of :func:`app.kinematics.paths.follow.follow`: its points and the outcome."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.kinematics.paths.failures import PathFailure


@dataclass(slots=True)
class PathPoint:
    """One point of the answer: wire configuration, its pose errors against the path's pose
    at ``s`` (m, rad), and ``s``."""

    q: np.ndarray
    position_error: float
    orientation_error: float
    s: float


@dataclass(slots=True)
class PathResult:
    """Outcome of :func:`app.kinematics.paths.follow.follow`.

    ``points`` start with the start configuration (s = 0); ``fraction`` is the s of the last
    one (1.0 when the path was completed); ``failure`` is None then. ``branch`` is the
    start's label, ``waypoints`` the number of sampled waypoints (densified points come on
    top), ``iterations`` the Jacobian evaluations of every IK solve, ``solve_time_ms`` the
    wall time.
    """

    points: list[PathPoint]
    fraction: float
    failure: PathFailure | None
    branch: str | None
    waypoints: int
    iterations: int
    solve_time_ms: float
