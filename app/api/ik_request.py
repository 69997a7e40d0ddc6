"""From an IK-like request body to the core's inputs: options, targets, budget, collisions.

Shared by /ik, /ik/batch and /ik/path; every semantic check is the core's
(:mod:`app.kinematics.ik.problem`), these only gather the pieces.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pinocchio as pin
from starlette.requests import HTTPConnection

from app.api.obstacles import resolve_obstacles
from app.api.schemas.ik import IKTaskIn
from app.api.schemas.poses import Pose
from app.api.state import services
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import default_frame, group
from app.kinematics.ik.batch import Collisions, collision_accept
from app.kinematics.ik.problem import IKOptions, frame_name, target_placement
from app.kinematics.ik.ranking import clearance_function
from app.kinematics.models import RobotModel


def target_of(
    target: Pose, mode: str, field: str = "target", default: pin.SE3 | None = None
) -> pin.SE3:
    """The target's placement (validated by the core, naming ``field``; the part mode
    position or orientation leaves out is ``default``'s, the identity's without one)."""
    return target_placement(
        target.position, target.orientation, target.matrix, mode, field, target.rpy, default
    )


def collisions_of(conn: HTTPConnection, body: IKTaskIn) -> Collisions | None:
    """(obstacles, margin, geometry) for collision-aware IK, or None (validated here)."""
    if not body.avoid_collisions:
        for name in ("obstacles", "scene"):
            if getattr(body, name) is not None:
                raise InvalidInputError("only used with avoid_collisions: true", name)
        return None
    obstacles = resolve_obstacles(services(conn).scenes, body.obstacles, body.scene)
    return obstacles, body.margin, body.collision_geometry


def accept_of(robot: RobotModel, collisions: Collisions | None) -> Any:
    """The collision-free predicate of collision-aware IK (builds the collision model)."""
    return collision_accept(robot, collisions)


def clearance_of(robot: RobotModel, collisions: Collisions | None) -> Any:
    """``q ↦`` the smallest robot–obstacle distance, or None without obstacles."""
    if collisions is None:
        return None
    obstacles, _, geometry = collisions
    return clearance_function(robot, obstacles, geometry)


def options_of(
    robot: RobotModel, body: IKTaskIn, num_solutions: int = 1, rank_by: str = "seed_distance"
) -> IKOptions:
    """The core's options from the request body (validated there)."""
    return IKOptions(
        frame=frame_name(robot, default_frame(robot, group(robot, body.group), body.frame)),
        group=body.group,
        mode=body.mode,
        weights=None if body.weights is None else tuple(body.weights),
        tolerance=(body.tolerance.position, body.tolerance.orientation),
        timeout_ms=body.timeout_ms,
        max_iterations=body.max_iterations,
        num_solutions=num_solutions,
        rank_by=rank_by,
    )


def rng_of(body: IKTaskIn) -> np.random.Generator | None:
    """The restarts' random generator of ``random_seed`` (None: the fixed restart table)."""
    return None if body.random_seed is None else np.random.default_rng(body.random_seed)
