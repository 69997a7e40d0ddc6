"""Wire models of scenes and obstacles: POST /scenes, GET /scenes, GET /scenes/{name}, and
the ``obstacles`` of collision and IK requests (shapes, sizes in m, poses in the robot's
root frame, quaternions [x, y, z, w])."""

from __future__ import annotations

from typing import Annotated

from fastapi import Path
from pydantic import BaseModel, Field, Strict

from app.api.schemas.common import Schema, Text, Vec3Out
from app.api.schemas.poses import Pose
from app.api.schemas.values import ObstacleShape
from app.kinematics.obstacles import MAX_NAME_LENGTH, MAX_OBSTACLES
from app.storage.scenes import MAX_DESCRIPTION, NAME_PATTERN

#: A finite, strictly positive length (m).
PositiveLength = Annotated[float, Strict(), Field(gt=0, allow_inf_nan=False)]
SceneName = Annotated[
    str, Path(description="Scene name (letters, digits, '_', '-').", max_length=64)
]


class ObstacleIn(Schema):
    """A box, sphere, cylinder or capsule in the robot's root frame."""

    name: Text = Field(
        min_length=1, max_length=MAX_NAME_LENGTH, description="Unique name in the set."
    )
    shape: ObstacleShape = Field(description="Solid type.")
    size: Annotated[list[PositiveLength], Field(min_length=3, max_length=3)] | None = Field(
        None, description="box: full edge lengths [x, y, z] (m)."
    )
    radius: PositiveLength | None = Field(
        None, description="sphere, cylinder, capsule: radius (m)."
    )
    length: PositiveLength | None = Field(
        None,
        description="cylinder: full height along local z (m); capsule: length of the "
        "segment between the hemisphere centres (m).",
    )
    pose: Pose | None = Field(
        None,
        description="Placement root ← obstacle; default the identity (a missing position is "
        "the origin, a missing rotation the identity).",
    )


class ObstacleOut(BaseModel):
    """A stored obstacle (normalised orientation)."""

    name: str
    shape: ObstacleShape
    size: Vec3Out | None = None
    radius: float | None = None
    length: float | None = None
    pose: Pose = Field(description="Placement root ← obstacle (every field filled).")


class SceneIn(Schema):
    """A new scene."""

    name: str = Field(pattern=NAME_PATTERN, description="Scene name (1-64 of A-Z a-z 0-9 _ -).")
    description: Text = Field("", max_length=MAX_DESCRIPTION)
    obstacles: list[ObstacleIn] = Field(max_length=MAX_OBSTACLES, description="The obstacles.")


class SceneOut(BaseModel):
    """A stored scene."""

    name: str
    description: str
    obstacles: list[ObstacleOut]


class SceneSummary(BaseModel):
    """A scene in the list."""

    name: str
    description: str
    obstacles: int = Field(description="Number of obstacles.")


class SceneList(BaseModel):
    """Every stored scene."""

    scenes: list[SceneSummary]
