"""Wire models of reachability maps: builds, jobs, stored maps and queries (positions in m,
root frame; quaternions [x, y, z, w]; the grid and bins of
:mod:`app.kinematics.reachability`)."""

from __future__ import annotations

from typing import Annotated

from fastapi import Path as PathParam
from pydantic import BaseModel, Field

from app.api.schemas.common import Finite, Quat, Schema, Vec3
from app.api.schemas.poses import Pose
from app.api.schemas.values import (
    JacobianPart,
    JobStatus,
    ReachabilitySampling,
    SelfCollisionMode,
)
from app.kinematics.reachability.spec import (
    DEFAULT_VOXELS_PER_EDGE,
    MAX_CELLS,
    MAX_ORIENTATION_DIVISIONS,
    MAX_SAMPLES,
)

JobId = Annotated[str, PathParam(description="Build job id.", max_length=64)]
MapId = Annotated[
    str, PathParam(description="Map id, as listed by …/reachability/maps.", max_length=64)
]


class Bounds(Schema):
    """An axis-aligned box of the root frame (m)."""

    min: Vec3 = Field(description="[x, y, z] lower corner (m).")
    max: Vec3 = Field(description="[x, y, z] upper corner (m); larger than min on every axis.")


class BuildRequest(Schema):
    """What to build: grid, orientation bins, manipulability rows, sampling."""

    frame: str | None = Field(
        None, description="Frame whose poses are mapped; default the robot's end effector."
    )
    voxel_size: Finite | None = Field(
        None,
        gt=0,
        description="Edge of a position voxel (m). Default: the box's longest edge / "
        f"{DEFAULT_VOXELS_PER_EDGE} (with the default box, the chain's total length / "
        f"{DEFAULT_VOXELS_PER_EDGE // 2}: a coarse map of any arm), larger by steps of 5 % "
        f"when voxels × orientation bins would exceed {MAX_CELLS:,} cells.",
    )
    bounds: Bounds | None = Field(
        None,
        description="Box to cover (m, root frame); default a box that contains every reachable "
        "position (centred on the chain's first joint, half-size the chain's total length).",
    )
    orientation_divisions: int = Field(
        4,
        ge=0,
        le=MAX_ORIENTATION_DIVISIONS,
        description="d: 4·d³ orientation bins (cubed 3-sphere, each ≈ 180°/d of rotation per "
        "axis); 0 = one bin (position-only map).",
    )
    part: JacobianPart | None = Field(
        None, description="Manipulability rows: full (default) | translation | rotation."
    )
    rows: list[str | int] | None = Field(
        None, description='Explicit manipulability rows, e.g. ["vx", "vy"].', max_length=6
    )
    samples: int = Field(
        200_000,
        ge=1,
        le=MAX_SAMPLES,
        description="Joint-space samples (grid: rounded); the default builds in well under a "
        "second on a 7-joint arm.",
    )
    sampling: ReachabilitySampling = Field(
        "random",
        description="random: uniform within joint limits | grid: g = round(samples^(1/k)) "
        "values per joint.",
    )
    seed: int = Field(0, ge=0, le=2**63 - 1, description="Seed of the random samples.")
    self_collision: SelfCollisionMode = Field(
        "ignore",
        description="Drop self-colliding samples using the collision module's geometry "
        "(mesh or convex hulls); one collision query per sample, far slower.",
    )


class ProgressOut(BaseModel):
    """How far a build is."""

    percent: float
    samples_done: int
    samples_total: int
    samples_per_second: float | None
    elapsed_seconds: float
    eta_seconds: float | None = Field(description="Seconds left at the current rate.")


class JobResponse(BaseModel):
    """A build job."""

    job_id: str
    robot_id: str
    frame: str
    status: JobStatus
    map_id: str | None = Field(description="The stored map, once done.")
    error: str | None
    progress: ProgressOut


class JobList(BaseModel):
    jobs: list[JobResponse]


class MapBounds(BaseModel):
    min: list[float]
    max: list[float]


class MapInfo(BaseModel):
    """A stored map's metadata."""

    map_id: str
    robot_id: str
    frame: str
    created_at: str
    bounds: MapBounds = Field(description="The grid's box (max = min + shape·voxel_size).")
    voxel_size: float
    shape: list[int] = Field(description="Voxels along x, y, z.")
    orientation_divisions: int
    orientation_bins: int
    cells: int
    rows: list[str]
    joints: list[str] = Field(description="The sampled joints (those that move the frame).")
    samples: int
    sampling: ReachabilitySampling
    seed: int
    self_collision: SelfCollisionMode
    samples_per_second: float | None
    build_seconds: float | None
    robot_fingerprint: str
    reachable_cells: int
    reachable_voxels: int
    max_manipulability: float | None


class MapList(BaseModel):
    maps: list[MapInfo]


class QueryRequest(Schema):
    """Poses to look up in a map: ``poses``, or the compact ``positions``/``orientations``."""

    map_id: str = Field(description="The map to query.", max_length=64)
    poses: list[Pose] | None = Field(
        None,
        description="Poses (root frame): each needs a position (`position` or `matrix`); "
        "without a rotation (`orientation`, `rpy` or `matrix`), any orientation (best over "
        "the voxel).",
    )
    positions: list[Vec3] | None = Field(None, description="Compact form: N×3 positions (m).")
    orientations: list[Quat] | None = Field(
        None, description="Compact form: N×4 quaternions [x, y, z, w] (omit: any orientation)."
    )


class QueryResponse(BaseModel):
    """Entry i answers pose i."""

    map_id: str
    reachable: list[bool]
    manipulability: list[float | None] = Field(
        description="Best Yoshikawa manipulability seen in the pose's cell; null if unreachable."
    )
    in_bounds: list[bool] = Field(description="Whether the position lies inside the map's box.")
