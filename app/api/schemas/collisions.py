"""Wire models of collision checks: POST /robots/{robot_id}/collisions, …/collisions/batch and
GET /robots/{robot_id}/collision_pairs (distances and witness points in m, root frame)."""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, Field, Strict

from app.api.schemas.common import (
    Configuration,
    ConfigurationIn,
    JointValue,
    Schema,
    Vec3Out,
    group_field,
)
from app.api.schemas.scenes import ObstacleIn
from app.api.schemas.values import CollisionGeometry, CollisionPairKind
from app.kinematics.obstacles import MAX_OBSTACLES

Margin = Annotated[float, Strict(), Field(ge=0.0, le=10.0, allow_inf_nan=False)]
Flag = Annotated[bool, Strict()]


class CollisionOptions(Schema):
    """What to check against and how."""

    obstacles: list[ObstacleIn] | None = Field(
        None, max_length=MAX_OBSTACLES, description="Obstacles in the robot's root frame."
    )
    scene: str | None = Field(
        None, max_length=64, description="Name of a stored scene (instead of obstacles)."
    )
    margin: Margin = Field(
        0.0, description="Safety margin (m): pairs closer than this count as in collision."
    )
    distances: Flag = Field(
        False,
        description="Compute every checked pair's distance and witness points "
        "(slower, especially with meshes).",
    )
    geometry: CollisionGeometry = Field(
        "mesh",
        description="mesh: the URDF collision meshes (exact); convex: their convex hulls "
        "(faster, conservative, signed distances).",
    )


class CollisionRequest(ConfigurationIn, CollisionOptions):
    """A configuration to check."""


class PairOut(BaseModel):
    """A checked pair: two links (self) or a link and an obstacle (environment)."""

    a: str = Field(description="Link name.")
    b: str = Field(description="Link name (self) or obstacle name (environment).")
    kind: CollisionPairKind
    in_collision: bool = Field(description="Closer than the margin.")
    distance: float | None = Field(
        description="Distance (m); negative = penetration depth where coal computes it "
        "(convex hulls, primitives); 0 for penetrating meshes."
    )
    point_a: Vec3Out | None = Field(
        None, description="Witness point on a, root frame (m); with distances."
    )
    point_b: Vec3Out | None = Field(
        None, description="Witness point on b, root frame (m); with distances."
    )


class CollisionResponse(BaseModel):
    """The verdict for one configuration."""

    robot_id: str
    q: Configuration = Field(description="The configuration checked, in joint order.")
    geometry: CollisionGeometry
    margin: float
    in_collision: bool = Field(description="Any pair closer than the margin.")
    self_collision: bool = Field(description="Two links of the robot collide.")
    environment_collision: bool = Field(description="A link collides with an obstacle.")
    min_distance: float | None = Field(
        description="Smallest distance (m) over the checked pairs with distances; otherwise "
        "over the pairs in collision (null when none)."
    )
    pairs: list[PairOut] = Field(
        description="Pairs in collision, or every checked pair with distances; closest first."
    )
    checked_pairs: int = Field(description="Number of link/link and link/obstacle pairs checked.")


class CollisionBatchRequest(CollisionOptions):
    """Many configurations (e.g. the waypoints of a trajectory)."""

    configurations: list[list[JointValue]] = Field(
        description="N configurations, each one value per joint in joint order (rad, m); "
        "with `group`, rows of the group's joints only are accepted too (others neutral)."
    )
    group: str | None = group_field()


class CollisionBatchResponse(BaseModel):
    """Compact per-configuration answers: entry i for configuration i."""

    robot_id: str
    geometry: CollisionGeometry
    margin: float
    count: int
    num_in_collision: int
    first_collision: int | None = Field(description="Index of the first colliding configuration.")
    in_collision: list[bool]
    self_collision: list[bool]
    environment_collision: list[bool]
    pairs: list[list[list[str]]] = Field(description="Per configuration: colliding [a, b] pairs.")
    min_distance: list[float] | None = Field(
        None, description="Per configuration: smallest distance (m); only with distances."
    )


class CollisionPairsResponse(BaseModel):
    """Which self-collision pairs are checked."""

    robot_id: str
    links: list[str] = Field(description="Links with collision geometry.")
    pairs: list[list[str]] = Field(description="Checked link pairs [a, b].")
    srdf: bool = Field(description="Whether an SRDF disabled pairs.")
