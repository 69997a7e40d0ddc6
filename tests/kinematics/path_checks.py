"""Shared checks of path answers (app.kinematics.paths.follow) against independent
references: every point's pose by yourdfpy against the path's pose at its s, every step
within the joint step, fraction and failure consistent."""

from __future__ import annotations

import numpy as np
import pytest

from app.kinematics.ik.problem import IKOptions
from app.kinematics.ik.search import joint_distance
from app.kinematics.models import RobotModel
from app.kinematics.paths.follow import PathOptions, PathResult
from app.kinematics.paths.segments import CartesianPath
from tests.kinematics.reference import pose_error, reference_chain_pose

REASONS = {
    "unreachable",
    "joint_limits",
    "collision",
    "singular",
    "timeout",
    "joint_step",
    "branch",
}
TOL = 1e-6


def ik_options(frame: str, **kw) -> IKOptions:
    return IKOptions(frame=frame, tolerance=(TOL, TOL), max_iterations=200, timeout_ms=5000, **kw)


def check_points(
    robot: RobotModel,
    frame: str,
    q0: np.ndarray,
    path: CartesianPath,
    res: PathResult,
    options: PathOptions,
    tol: float = TOL,
    rotation: bool = True,
) -> None:
    """The invariants of every answer: starts at q0, s increasing, every step within the
    joint step, every pose (yourdfpy) on the path at its s (its position only unless
    ``rotation``), fraction and failure agree."""
    pts = res.points
    np.testing.assert_array_equal(pts[0].q, q0)
    assert pts[0].s == 0.0
    for a, b in zip(pts, pts[1:], strict=False):
        assert b.s > a.s
        assert joint_distance(robot, a.q, b.q).max() <= options.max_joint_step + 1e-12
    for p in pts:
        T = reference_chain_pose(robot, p.q, frame)
        dp, dr = pose_error(T, path.pose_at(p.s).homogeneous)
        assert dp <= tol * 1.01 and (dr <= tol * 1.01 or not rotation), (p.s, dp, dr)
        assert p.position_error == pytest.approx(dp, abs=1e-8)
    assert res.fraction == pts[-1].s
    if res.failure is None:
        assert res.fraction == 1.0
    else:
        assert res.fraction < 1.0 and res.failure.reason in REASONS
        assert res.failure.s > res.fraction and res.failure.detail
