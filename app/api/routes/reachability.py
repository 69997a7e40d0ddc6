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
:mod:`app.api.images`, the wire models in :mod:`app.api.schemas.reachability`.
A build runs in the worker process that accepted it, which keeps the job's state in the
SQLite database ``DENAVIT_DATA_DIR/maps/jobs.sqlite3``: with several uvicorn workers any
worker answers (and cancels) any job. A job whose worker stopped reads as failed once its
heartbeat is stale; finished maps are files under ``DENAVIT_DATA_DIR/maps`` and survive
restarts.
"""

from __future__ import annotations

from typing import Annotated

import numpy as np
from fastapi import APIRouter, Depends, Query, Request
from starlette.concurrency import run_in_threadpool
from starlette.responses import Response

from app.api.body import body_schema, decode_body, finite_matrix
from app.api.deps import BuildJobsDep, MapStoreDep, RobotDep, SettingsDep
from app.api.errors import ERROR_RESPONSES
from app.api.images import png_bytes, slice_image
from app.api.limits import check_batch_size
from app.api.offload import offload
from app.api.responses import ORJSONResponse
from app.api.schemas.common import RobotId
from app.api.schemas.reachability import (
    BuildRequest,
    JobId,
    JobList,
    JobResponse,
    MapId,
    MapInfo,
    MapList,
    QueryRequest,
    QueryResponse,
)
from app.api.security import require_token
from app.kinematics.errors import ConflictError, InvalidInputError
from app.kinematics.models import RobotModel
from app.kinematics.reachability.map import ReachabilityMap, meta_public, robot_fingerprint
from app.kinematics.reachability.spec import make_spec, self_collision_check
from app.kinematics.rotations import unit_quaternions
from app.storage.maps import MapStore

router = APIRouter(prefix="/robots/{robot_id}/reachability", tags=["reachability"])

ERRORS = {k: ERROR_RESPONSES[k] for k in (400, 404, 422)}


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
    robot: RobotDep, body: BuildRequest, request: Request, jobs: BuildJobsDep
) -> ORJSONResponse:
    """Start building a reachability map in the background; poll the returned job."""
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
        await offload(request, make, robot, spec.self_collision)
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
async def list_reachability_jobs(robot: RobotDep, jobs: BuildJobsDep) -> ORJSONResponse:
    """Build jobs of this robot (started through any worker), oldest first."""
    listed = await run_in_threadpool(jobs.list, robot.id)
    return ORJSONResponse({"jobs": [j.to_json() for j in listed]})


@router.get(
    "/jobs/{job_id}",
    operation_id="get_reachability_job",
    response_model=JobResponse,
    responses=ERRORS,
)
async def get_reachability_job(
    robot_id: RobotId, job_id: JobId, jobs: BuildJobsDep
) -> ORJSONResponse:
    """Status and progress (percent, samples/s, ETA) of a build."""
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
    robot_id: RobotId, job_id: JobId, jobs: BuildJobsDep
) -> ORJSONResponse:
    """Cancel a queued or running build; nothing is stored. Cancelling twice is fine.

    The build stops within a moment (any worker may be running it); until then the answer
    and the job still say ``queued`` or ``running``: poll the job until it is ``cancelled``.
    """
    job = await run_in_threadpool(jobs.cancel, robot_id, job_id)
    return ORJSONResponse(job.to_json())


@router.get("/maps", operation_id="list_reachability_maps", response_model=MapList)
async def list_reachability_maps(
    robot: RobotDep, request: Request, store: MapStoreDep
) -> ORJSONResponse:
    """Stored maps of this robot, oldest first."""
    metas = await offload(request, store.list, robot.id)
    return ORJSONResponse({"maps": [meta_public(m) for m in metas]})


@router.get(
    "/maps/{map_id}", operation_id="get_reachability_map", response_model=MapInfo, responses=ERRORS
)
async def get_reachability_map(
    robot_id: RobotId, map_id: MapId, request: Request, store: MapStoreDep
) -> ORJSONResponse:
    """One stored map's metadata."""
    m = await offload(request, store.get, robot_id, map_id)
    return ORJSONResponse(meta_public(m.meta))


@router.delete(
    "/maps/{map_id}",
    operation_id="delete_reachability_map",
    status_code=204,
    responses=ERRORS,
    dependencies=[Depends(require_token)],
)
async def delete_reachability_map(
    robot_id: RobotId, map_id: MapId, request: Request, store: MapStoreDep
) -> Response:
    """Delete a stored map."""
    await offload(request, store.delete, robot_id, map_id)
    return Response(status_code=204)


async def _map_for(
    request: Request, store: MapStore, robot: RobotModel, map_id: str
) -> ReachabilityMap:
    """The stored map ``map_id`` of ``robot``; 409 if it was built for another model."""
    m = await offload(request, store.get, robot.id, map_id)
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
        pos = np.empty((n, 3))
        quat = np.full((n, 4), np.nan)  # NaN row: any orientation
        for i, p in enumerate(body.poses):
            pl = p.placement(f"poses.{i}", need_position=True, need="for a reachability query")
            pos[i] = pl.translation
            if pl.quaternion is not None:
                quat[i] = pl.quaternion
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
    check_batch_size(n, limit, "poses", field)
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
    robot: RobotDep, request: Request, settings: SettingsDep, store: MapStoreDep
) -> ORJSONResponse:
    """Look poses up in a map: O(1) each. Outside the map's box → not reachable.

    Give ``poses`` (objects; orientation optional per pose) or the compact ``positions``
    (N×3) with optional ``orientations`` (N×4); a pose without orientation asks "reachable
    with any orientation" (the best over the voxel's bins).
    """
    raw = await request.body()
    map_id, pos, quat = await offload(request, _query_arrays, raw, settings.max_batch)
    m = await _map_for(request, store, robot, map_id)
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
    robot: RobotDep,
    map_id: MapId,
    request: Request,
    store: MapStoreDep,
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
    m = await _map_for(request, store, robot, map_id)
    rgb = slice_image(m, axis, value, scale)
    return Response(png_bytes(rgb), media_type="image/png")
