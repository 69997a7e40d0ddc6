"""How to follow a Cartesian path: :class:`PathOptions`, validated once for every caller of
:func:`app.kinematics.paths.follow.follow` (as :class:`app.kinematics.ik.problem.IKOptions`
is for IK)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from app.kinematics.errors import InvalidInputError
from app.kinematics.paths.segments import check_max_step


@dataclass(frozen=True, slots=True)
class PathOptions:
    """How to follow a path (validated on construction, InvalidInputError naming the field).

    Attributes
    ----------
    max_step
        (position m, rotation rad): the most two consecutive waypoints of the sampled path
        differ by.
    max_joint_step
        The most any joint may move between two consecutive points (rad or m).
    max_deviation
        (position m, rotation rad): the most the frame may stray from the path while the
        joints move linearly between two points; points are inserted until it holds.
    branch
        The branch label the start must be on
        (:func:`app.kinematics.paths.follow.branch_of`); None: any. Every point keeps the
        start's label either way.
    """

    max_step: tuple[float, float] = (0.01, 0.05)
    max_joint_step: float = 0.1
    max_deviation: tuple[float, float] = (1e-3, 1e-2)
    branch: str | None = None

    def __post_init__(self) -> None:
        check_max_step(float(self.max_step[0]), float(self.max_step[1]), "max_step")
        if not (math.isfinite(self.max_joint_step) and self.max_joint_step > 0.0):
            raise InvalidInputError("must be positive and finite", "max_joint_step")
        check_max_step(float(self.max_deviation[0]), float(self.max_deviation[1]), "max_deviation")
