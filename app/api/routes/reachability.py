"""Reachability maps over HTTP: background builds, stored maps, O(1) queries, PNG slices.

- POST   /robots/{robot_id}/reachability                      start a build (write, 202)
- GET    /robots/{robot_id}/reachability/jobs                 builds of this robot
- GET    /robots/{robot_id}/reachability/jobs/{job_id}        status and progress
- DELETE /robots/{robot_id}/reachability/jobs/{job_id}        cancel (write)
- GET    /robots/{robot_id}/reachability/maps                 stored maps
- GET    /robots/{robot_id}/reachability/maps/{map_id}        one map's metadata
- DELETE /robots/{robot_id}/reachability/maps/{map_id}        delete (write)
- POST   /robots/{robot_id}/reachability/query                poses → reachable, manipulability
- GET    /robots/{robot_id}/reachability/maps/{map_id}/slice.png   heat map of one voxel layer

The grid, orientation bins and sampling are described in :mod:`app.kinematics.reachability`,
storage in :mod:`app.storage.maps`, jobs in :mod:`app.storage.build_jobs`, the PNG in
:mod:`app.api.images`.
A build runs in the worker process that accepted it, which keeps the job's state in the
SQLite database ``DENAVIT_DATA_DIR/maps/jobs.sqlite3``: with several uvicorn workers any
worker answers (and cancels) any job. A job whose worker stopped reads as failed once its
heartbeat is stale; finished maps are files under ``DENAVIT_DATA_DIR/maps`` and survive
restarts.
"""

from __future__ import annotations

import threading
from typing import Annotated, Literal

import numpy as np
from fastapi import APIRouter, Depends, Query, Request
from fastapi import Path as PathParam
from pydantic import BaseModel, Field
from starlette.concurrency import run_in_threadpool
from starlette.responses import Response

from app.api.body import body_schema, decode_body, finite_matrix
from app.api.deps import RegistryDep, load_robot
from app.api.errors import ERROR_RESPONSES
from app.api.images import png_bytes, slice_image
from app.api.offload import offload
from app.api.responses import ORJSONResponse
from app.api.schemas.common import Finite, Quat, RobotId, Schema, Vec3
from app.api.security import require_token
from app.kinematics.analysis import Part
from app.kinematics.errors import ConflictError, InvalidInputError
from app.kinematics.reachability.map import ReachabilityMap, meta_public, robot_fingerprint
from app.kinematics.reachability.spec import (
    MAX_ORIENTATION_DIVISIONS,
    MAX_SAMPLES,
    make_spec,
    self_collision_check,
)
from app.kinematics.rotations import unit_quaternions
from app.robots.registry import Registry
from app.storage.build_jobs import BuildJobs
from app.storage.maps import MapStore

router = APIRouter(prefix="/robots/{robot_id}/reachability", tags=["reachability"])

JobId = Annotated[str, PathParam(description="Build job id.", max_length=64)]
MapId = Annotated[
    str, PathParam(description="Map id, as listed by …/reachability/maps.", max_length=64)
]
ERRORS = {k: ERROR_RESPONSES[k] for k in (400, 404, 422)}

_STATE_LOCK = threading.Lock()


def _state(request: Request) -> tuple[MapStore, BuildJobs]:
    """The app's map store and build queue (created on first use)."""
    app = request.app
    state = getattr(app.state, "reachability", None)
    if state is None:
        with _STATE_LOCK:
            state = getattr(app.state, "reachability", None)
            if state is None:
                store = MapStore(app.state.settings.data_dir / "maps")
                state = app.state.reachability = (store, BuildJobs(store))
    return state


# --------------------------------------------------------------------------- models
class Bounds(Schema):
    """An axis-aligned box of the root frame (m)."""

    min: Vec3 = Field(description="[x, y, z] lower corner (m).")
    max: Vec3 = Field(description="[x, y, z] upper corner (m); larger than min on every axis.")


class BuildRequest(Schema):
    """What to build: grid, orientation bins, manipulability rows, sampling."""

    frame: str | None = Field(None, description="Frame; default the end effector.")
    voxel_size: Finite = Field(0.05, gt=0, description="Edge of a position voxel (m).")
    bounds: Bounds | None = Field(
        None,
        description="Box to cover; default a box that contains every reachable position "
        "(centred on the chain's first joint, half-size the chain's total length).",
    )
    orientation_divisions: int = Field(
        4,
        ge=0,
        le=MAX_ORIENTATION_DIVISIONS,
        description="d: 4·d³ orientation bins (cubed 3-sphere, each ≈ 180°/d of rotation per "
        "axis); 0 = one bin (position-only map).",
    )
    part: Part | None = Field(
        None, description="Manipulability rows: full (default) | translation | rotation."
    )
    rows: list[str | int] | None = Field(
        None, description='Explicit manipulability rows, e.g. ["vx", "vy"].', max_length=6
    )
    samples: int = Field(
        200_000, ge=1, le=MAX_SAMPLES, description="Joint-space samples (grid: rounded)."
    )
    sampling: Literal["random", "grid"] = Field(
        "random",
        description="random: uniform within joint limits | grid: g = round(samples^(1/k)) "
        "values per joint.",
    )
    seed: int = Field(0, ge=0, le=2**63 - 1, description="Seed of the random samples.")
    self_collision: Literal["ignore", "mesh", "convex"] = Field(
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
    status: Literal["queued", "running", "done", "failed", "cancelled"]
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
    sampling: str
    seed: int
    self_collision: str
    samples_per_second: float | None
    build_seconds: float | None
    robot_fingerprint: str
    reachable_cells: int
    reachable_voxels: int
    max_manipulability: float | None


class MapList(BaseModel):
    maps: list[MapInfo]


class PoseIn(Schema):
    """A pose to look up; without orientation, any orientation (best over the voxel)."""

    position: Vec3 = Field(description="[x, y, z] (m), root frame.")
    orientation: Quat | None = Field(None, description="Unit quaternion [x, y, z, w].")


class QueryRequest(Schema):
    """Poses to look up in a map: ``poses``, or the compact ``positions``/``orientations``."""

    map_id: str = Field(description="The map to query.", max_length=64)
    poses: list[PoseIn] | None = Field(None, description="Poses (root frame).")
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


# ---------------------------------------------------------------------------- routes
@router.post(
    "",
    operation_id="build_reachability_map",
    status_code=202,
    response_model=JobResponse,
    responses={**ERRORS, 409: {"description": "Too many builds queued or running."}},
    dependencies=[Depends(require_token)],
)
async def build_reachability_map(
    robot_id: RobotId,
    body: BuildRequest,
    request: Request,
    reg: RegistryDep,
) -> ORJSONResponse:
    """Start building a reachability map in the background; poll the returned job."""
    robot = await load_robot(reg, robot_id)
    frame = body.frame or robot.ee_frame
    spec = make_spec(
        robot,
        frame,
        voxel_size=body.voxel_size,
        lower=body.bounds.min if body.bounds else None,
        upper=body.bounds.max if body.bounds else None,
        orientation_divisions=body.orientation_divisions,
        part=body.part,
        rows=body.rows,
        samples=body.samples,
        sampling=body.sampling,
        seed=body.seed,
        self_collision=body.self_collision,
    )
    if spec.self_collision != "ignore":
        # build (and cache) the collision model now: a robot whose geometry cannot be
        # loaded is refused here, not reported later as a failed job
        make = self_collision_check()
        await offload(make, robot, spec.self_collision)
    _, jobs = _state(request)
    # the job database is read and written: off the event loop (short work, not the bounded pool)
    job = await run_in_threadpool(jobs.submit, robot, spec)
    return ORJSONResponse(
        job.to_json(),
        status_code=202,
        headers={"Location": f"/robots/{robot.id}/reachability/jobs/{job.job_id}"},
    )


@router.get(
    "/jobs", operation_id="list_reachability_jobs", response_model=JobList, responses=ERRORS
)
async def list_reachability_jobs(
    robot_id: RobotId, request: Request, reg: RegistryDep
) -> ORJSONResponse:
    """Build jobs of this robot (started through any worker), oldest first."""
    await load_robot(reg, robot_id)
    _, jobs = _state(request)
    listed = await run_in_threadpool(jobs.list, robot_id)
    return ORJSONResponse({"jobs": [j.to_json() for j in listed]})


@router.get(
    "/jobs/{job_id}",
    operation_id="get_reachability_job",
    response_model=JobResponse,
    responses=ERRORS,
)
async def get_reachability_job(
    robot_id: RobotId, job_id: JobId, request: Request
) -> ORJSONResponse:
    """Status and progress (percent, samples/s, ETA) of a build."""
    _, jobs = _state(request)
    job = await run_in_threadpool(jobs.get, robot_id, job_id)
    return ORJSONResponse(job.to_json())


@router.delete(
    "/jobs/{job_id}",
    operation_id="cancel_reachability_job",
    response_model=JobResponse,
    responses={**ERRORS, 409: {"description": "The job has already finished."}},
    dependencies=[Depends(require_token)],
)
async def cancel_reachability_job(
    robot_id: RobotId, job_id: JobId, request: Request
) -> ORJSONResponse:
    """Cancel a queued or running build; nothing is stored. Cancelling twice is fine.

    The build stops within a moment (any worker may be running it); until then the answer
    and the job still say ``queued`` or ``running``: poll the job until it is ``cancelled``.
    """
    _, jobs = _state(request)
    job = await run_in_threadpool(jobs.cancel, robot_id, job_id)
    return ORJSONResponse(job.to_json())


@router.get("/maps", operation_id="list_reachability_maps", response_model=MapList)
async def list_reachability_maps(
    robot_id: RobotId, request: Request, reg: RegistryDep
) -> ORJSONResponse:
    """Stored maps of this robot, oldest first."""
    await load_robot(reg, robot_id)
    store, _ = _state(request)
    metas = await offload(store.list, robot_id)
    return ORJSONResponse({"maps": [meta_public(m) for m in metas]})


@router.get(
    "/maps/{map_id}", operation_id="get_reachability_map", response_model=MapInfo, responses=ERRORS
)
async def get_reachability_map(
    robot_id: RobotId, map_id: MapId, request: Request
) -> ORJSONResponse:
    """One stored map's metadata."""
    store, _ = _state(request)
    m = await offload(store.get, robot_id, map_id)
    return ORJSONResponse(meta_public(m.meta))


@router.delete(
    "/maps/{map_id}",
    operation_id="delete_reachability_map",
    status_code=204,
    responses=ERRORS,
    dependencies=[Depends(require_token)],
)
async def delete_reachability_map(robot_id: RobotId, map_id: MapId, request: Request) -> Response:
    """Delete a stored map."""
    store, _ = _state(request)
    await offload(store.delete, robot_id, map_id)
    return Response(status_code=204)


async def _map_for(request: Request, reg: Registry, robot_id: str, map_id: str) -> ReachabilityMap:
    robot = await load_robot(reg, robot_id)
    store, _ = _state(request)
    m = await offload(store.get, robot_id, map_id)
    if m.meta["robot_fingerprint"] != robot_fingerprint(robot):
        raise ConflictError(
            "the map was built for another model of this robot (its URDF has changed)", "map_id"
        )
    return m


def _query_arrays(raw: bytes, limit: int) -> tuple[str, np.ndarray, np.ndarray | None]:
    """Decode and validate a query body: map id, positions (N, 3), quaternions (N, 4) with
    NaN rows for "any orientation" (or ``None``: any orientation for all)."""
    body, rows = decode_body(
        raw, QueryRequest, {"positions": 3, "orientations": 4}, fast=_pose_columns
    )
    if (body.poses is None) == (body.positions is None):
        raise InvalidInputError("give exactly one of poses or positions", "poses")
    if "poses.position" in rows:  # fast path: all poses with an orientation, or none
        quat = rows.get("poses.orientation")
        if quat is not None:
            quat = unit_quaternions(quat, "poses.{}.orientation")
        return _check_query(body.map_id, rows["poses.position"], quat, "poses", limit)
    if body.poses is not None:
        n = len(body.poses)
        pos = np.array([p.position for p in body.poses], dtype=float).reshape(n, 3)
        quat = np.full((n, 4), np.nan)
        for i, p in enumerate(body.poses):
            if p.orientation is not None:
                quat[i] = p.orientation
        given = ~np.isnan(quat[:, 0])
        if given.any():
            rows_given = np.flatnonzero(given)
            quat[given] = unit_quaternions(quat[given], "poses.{}.orientation", rows_given)
        return _check_query(body.map_id, pos, quat, "poses", limit)
    pos = np.asarray(rows["positions"], dtype=float).reshape(-1, 3)
    quat = rows.get("orientations")
    quat = None if quat is None else np.asarray(quat, dtype=float)
    return _check_query(body.map_id, pos, quat, "positions", limit)


def _pose_columns(obj: dict) -> dict[str, np.ndarray] | None:
    """The fast form of ``poses``: position (and orientation) columns when every pose has
    the same keys and plain numbers (:data:`app.api.body.FastForm`)."""
    poses = obj.get("poses")
    if not (isinstance(poses, list) and poses and all(isinstance(p, dict) for p in poses)):
        return None
    keys = {frozenset(p) for p in poses}
    if keys not in ({frozenset({"position"})}, {frozenset({"position", "orientation"})}):
        return None
    pos = finite_matrix([p["position"] for p in poses], 3)
    if pos is None:
        return None
    if "orientation" not in poses[0]:
        return {"poses.position": pos}
    quat = finite_matrix([p["orientation"] for p in poses], 4)
    return None if quat is None else {"poses.position": pos, "poses.orientation": quat}


def _check_query(
    map_id: str, pos: np.ndarray, quat: np.ndarray | None, field: str, limit: int
) -> tuple[str, np.ndarray, np.ndarray | None]:
    n = pos.shape[0]
    if n == 0:
        raise InvalidInputError("give at least one pose", field)
    if n > limit:
        raise InvalidInputError(f"{n} poses exceed the limit of {limit}", field)
    if field == "positions" and quat is not None:
        if quat.shape[0] != n:
            raise InvalidInputError(
                f"expected {n} orientations (one per position), got {quat.shape[0]}",
                "orientations",
            )
        quat = unit_quaternions(quat.reshape(n, 4), "orientations.{}")
    return map_id, pos, quat


@router.post(
    "/query",
    operation_id="query_reachability",
    response_model=QueryResponse,
    responses={**ERRORS, 409: {"description": "The map belongs to an older robot model."}},
    openapi_extra=body_schema(QueryRequest),
)
async def query_reachability(
    robot_id: RobotId, request: Request, reg: RegistryDep
) -> ORJSONResponse:
    """Look poses up in a map: O(1) each. Outside the map's box → not reachable.

    Give ``poses`` (objects; orientation optional per pose) or the compact ``positions``
    (N×3) with optional ``orientations`` (N×4); a pose without orientation asks "reachable
    with any orientation" (the best over the voxel's bins).
    """
    raw = await request.body()
    limit = request.app.state.settings.max_batch
    map_id, pos, quat = await offload(_query_arrays, raw, limit)
    m = await _map_for(request, reg, robot_id, map_id)
    reach, val, ok = m.query(pos, quat)
    return ORJSONResponse(
        {
            "map_id": map_id,
            "reachable": reach,
            "manipulability": [None if np.isnan(v) else float(v) for v in val],
            "in_bounds": ok,
        }
    )


@router.get(
    "/maps/{map_id}/slice.png",
    operation_id="get_reachability_slice",
    responses={
        **ERRORS,
        200: {"content": {"image/png": {}}, "description": "The heat map (PNG)."},
    },
    response_class=Response,
)
async def get_reachability_slice(
    robot_id: RobotId,
    map_id: MapId,
    request: Request,
    reg: RegistryDep,
    x: Annotated[float | None, Query(description="Slice at this x (m).")] = None,
    y: Annotated[float | None, Query(description="Slice at this y (m).")] = None,
    z: Annotated[float | None, Query(description="Slice at this z (m).")] = None,
    scale: Annotated[
        int | None, Query(ge=1, le=64, description="Pixels per voxel (default: ~512 px).")
    ] = None,
) -> Response:
    """Heat map of one voxel layer: colour = best manipulability over orientations (viridis,
    scaled to the map's maximum), light grey = unreached. Give exactly one of x, y, z."""
    given = [(a, v) for a, v in enumerate((x, y, z)) if v is not None]
    if len(given) != 1:
        raise InvalidInputError("give exactly one of the query parameters x, y, z", "z")
    axis, value = given[0]
    if not np.isfinite(value):
        raise InvalidInputError("must be a finite number", "xyz"[axis])
    m = await _map_for(request, reg, robot_id, map_id)
    rgb = slice_image(m, axis, value, scale)
    return Response(png_bytes(rgb), media_type="image/png")
