"""The obstacles of a request: given inline (``obstacles``) or by a stored ``scene``, validated
into the core's :class:`~app.kinematics.obstacles.Obstacle` (collision checks, collision-aware
IK)."""

from __future__ import annotations

from app.api.schemas.scenes import ObstacleIn
from app.kinematics.errors import InvalidInputError
from app.kinematics.obstacles import Obstacle, parse_obstacles
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
    return parse_obstacles([o.model_dump(exclude_none=True) for o in obstacles])
