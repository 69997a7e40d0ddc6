"""From an IK-like request body to the core's inputs: options, targets, budget, collisions.

Shared by /ik, /ik/batch and /ik/path; every semantic check is the core's
(:mod:`app.kinematics.ik.problem`), these only gather the pieces.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pinocchio as pin
from starlette.requests import HTTPConnection

from app.api.deps import scene_store
from app.api.routes.scenes import resolve_obstacles
from app.api.schemas.ik import IKTaskIn, Target
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import default_frame, group
from app.kinematics.ik.batch import Collisions, collision_accept
from app.kinematics.ik.problem import IKOptions, frame_name, target_placement
from app.kinematics.ik.ranking import clearance_function
from app.kinematics.models import RobotModel


def target_of(target: Target, mode: str, field: str = "target") -> pin.SE3:
    """The target's placement (validated by the core, naming ``field``)."""
    return target_placement(target.position, target.orientation, target.matrix, mode, field)


def check_budget(request: HTTPConnection, timeout_ms: float) -> None:
    """Refuse a per-target budget above the server's ``ik_max_timeout_ms`` (``timeout_ms``)."""
    cap = request.app.state.settings.ik_max_timeout_ms
    if timeout_ms > cap:
        raise InvalidInputError(
            f"{timeout_ms} ms exceeds the server's cap of {cap} ms", "timeout_ms"
        )


def check_request_budget(
    request: HTTPConnection, count: int, noun: str, timeout_ms: float, remedy: str, field: str
) -> None:
    """Refuse a request whose total budget, ``count`` solves × ``timeout_ms``, exceeds the
    server's ``ik_max_request_s`` (InvalidInputError naming ``field``; ``noun`` names what is
    counted, ``remedy`` says how to stay within it)."""
    total_s = count * timeout_ms * 1e-3
    cap_s = request.app.state.settings.ik_max_request_s
    if total_s > cap_s:
        raise InvalidInputError(
            f"{count} {noun} × {timeout_ms:g} ms = {total_s:g} s exceeds the server's budget "
            f"of {cap_s:g} s per request: {remedy}",
            field,
        )


def collisions_of(request: HTTPConnection, body: IKTaskIn) -> Collisions | None:
    """(obstacles, margin, geometry) for collision-aware IK, or None (validated here)."""
    if not body.avoid_collisions:
        for name in ("obstacles", "scene"):
            if getattr(body, name) is not None:
                raise InvalidInputError("only used with avoid_collisions: true", name)
        return None
    obstacles = resolve_obstacles(scene_store(request), body.obstacles, body.scene)
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
