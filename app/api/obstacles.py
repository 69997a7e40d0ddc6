"""The obstacles of a request: given inline (``obstacles``) or by a stored ``scene``, validated
into the core's :class:`~app.kinematics.obstacles.Obstacle` (collision checks, collision-aware
IK)."""

from __future__ import annotations

from typing import Any

import numpy as np

from app.api.schemas.poses import pose_json
from app.api.schemas.scenes import ObstacleIn
from app.kinematics.errors import InvalidInputError
from app.kinematics.obstacles import Obstacle, parse_obstacles
from app.kinematics.rotations import quaternion_to_matrix
from app.storage.scenes import SceneStore


def resolve_obstacles(
    store: SceneStore, obstacles: list[ObstacleIn] | None, scene: str | None
) -> tuple[Obstacle, ...]:
    """Validated obstacles from a request's ``obstacles`` or ``scene`` (not both).

    Raises 422 naming the field for a bad obstacle or when both are given, 404 for an
    unknown scene.
    """
    if obstacles is not None and scene is not None:
        raise InvalidInputError("give either obstacles or scene, not both", "scene")
    if scene is not None:
        return store.get(scene, field="scene").obstacles
    if not obstacles:
        return ()
    return parse_obstacles(obstacle_items(obstacles))


def obstacle_items(obstacles: list[ObstacleIn], field: str = "obstacles") -> list[dict[str, Any]]:
    """The core's form of wire obstacles: each pose (any fields of :class:`Pose` that agree)
    validated and reduced to ``{position, orientation}`` (the given quaternion if any)."""
    items = []
    for i, o in enumerate(obstacles):
        item = o.model_dump(exclude_none=True, exclude={"pose"})
        if o.pose is not None:
            pl = o.pose.placement(f"{field}.{i}.pose")
            pose: dict[str, Any] = {}
            if pl.translation is not None:
                pose["position"] = pl.translation.tolist()
            if pl.quaternion is not None:
                pose["orientation"] = pl.quaternion.tolist()
            item["pose"] = pose
        items.append(item)
    return items


def obstacle_json(obstacle: dict[str, Any]) -> dict[str, Any]:
    """An obstacle's answer: its stored ``{position, orientation}`` pose as a full
    :class:`Pose` (position, orientation, rpy, matrix)."""
    pose = obstacle["pose"]
    T = np.eye(4)
    T[:3, :3] = quaternion_to_matrix(np.array(pose["orientation"], dtype=float))
    T[:3, 3] = pose["position"]
    full = pose_json(T)
    full["orientation"] = list(pose["orientation"])  # the stored (normalised) quaternion
    return {**obstacle, "pose": full}
