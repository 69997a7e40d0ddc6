"""Random straight tool lines inside an arm's reachable set (the path benchmark's and the
path tests' workload).

A line starts at the frame's pose at a random configuration (uniform within the joint
limits, continuous joints in [−π, π]) whose task Jacobian is not near-singular, and moves
the tool 0.1–0.5 m along a random direction with the orientation fixed. It is kept only when
it lies inside the reachable set: every one of ``checks`` evenly spaced poses along it
(both ends included) has an IK solution (any branch, from the closed forms or restarts).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics import ik
from app.kinematics.fk import frame_pose
from app.kinematics.ik.problem import IKOptions
from app.kinematics.models import RobotModel

#: Smallest σ of the start's Jacobian (a start next to a singularity is not a fair test).
START_SIGMA = 0.05


@dataclass(frozen=True, slots=True)
class RandomLine:
    """A start configuration, its frame pose, and the end pose of the line (root frame)."""

    q0: np.ndarray
    start: pin.SE3
    end: pin.SE3


def random_lines(
    robot: RobotModel,
    frame: str,
    count: int,
    seed: int,
    *,
    length: tuple[float, float] = (0.1, 0.5),
    checks: int = 11,
) -> list[RandomLine]:
    """``count`` lines drawn with ``numpy.random.default_rng(seed)`` (see the module)."""
    rng = np.random.default_rng(seed)
    fid = robot.frame_id(frame)
    opts = IKOptions(frame=frame, max_iterations=300, timeout_ms=10_000)
    lo = np.where(np.isfinite(robot.lower), robot.lower, -np.pi)
    hi = np.where(np.isfinite(robot.upper), robot.upper, np.pi)
    cols = robot.supporting_joints(frame)
    out: list[RandomLine] = []
    while len(out) < count:
        q0 = rng.uniform(lo, hi)
        J = pin.computeFrameJacobian(
            robot.model, robot.data, robot.to_pin(q0), fid, pin.LOCAL_WORLD_ALIGNED
        )
        if np.linalg.svd(np.asarray(J)[:, robot.v_index][:, cols], compute_uv=False).min() < (
            START_SIGMA
        ):
            continue
        T0 = frame_pose(robot, q0, fid)
        d = rng.normal(size=3)
        d *= rng.uniform(*length) / np.linalg.norm(d)
        ok = True
        for t in np.linspace(0.0, 1.0, checks)[1:]:
            T = pin.SE3(T0.rotation, T0.translation + t * d)
            if not ik.solve(robot, T, opts, seed=q0, rng=np.random.default_rng(0)).success:
                ok = False
                break
        if ok:
            out.append(RandomLine(q0, T0, pin.SE3(T0.rotation, T0.translation + d)))
    return out
