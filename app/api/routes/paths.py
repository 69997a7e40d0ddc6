"""Cartesian paths: POST /robots/{robot_id}/ik/path."""

from __future__ import annotations

import threading
import time

import numpy as np
import pinocchio as pin
from fastapi import APIRouter, Request

from app.api.deps import RobotDep, SettingsDep
from app.api.errors import ERROR_RESPONSES
from app.api.ik_request import (
    Collisions,
    accept_of,
    collisions_of,
    options_of,
    rng_of,
    target_of,
)
from app.api.limits import check_budget, check_request_budget
from app.api.offload import offload_cancellable
from app.api.responses import ORJSONResponse
from app.api.schemas.paths import ArcSegment, PathRequest, PathResponse
from app.api.schemas.poses import Pose
from app.api.schemas.timing import TimingIn, timing_of
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import Group, group
from app.kinematics.ik import SOLVER_VERSION
from app.kinematics.ik.problem import IKOptions, group_seed
from app.kinematics.models import RobotModel
from app.kinematics.paths.follow import PathOptions, follow, start_pose
from app.kinematics.paths.segments import Arc, CartesianPath, Line
from app.operations.metrics import record_ik

router = APIRouter(prefix="/robots/{robot_id}", tags=["inverse kinematics"])


def _pose(target: Pose, mode: str, previous: pin.SE3, field: str) -> pin.SE3:
    """A path pose: the target, its missing orientation (mode ``position``) or position (mode
    ``orientation``) taken from the previous pose of the path."""
    return target_of(target, mode, field, previous)


def _path(body: PathRequest, start: pin.SE3) -> CartesianPath:
    """The Cartesian path of the request from the start pose (exactly one of waypoints and
    segments; fields named as the wire spells them)."""
    if (body.waypoints is None) == (body.segments is None):
        raise InvalidInputError("give exactly one of waypoints and segments", "segments")
    mode = body.mode
    previous = start
    if body.waypoints is not None:
        poses = []
        for i, t in enumerate(body.waypoints):
            previous = _pose(t, mode, previous, f"waypoints.{i}")
            poses.append(previous)
        return CartesianPath.from_waypoints(start, poses)
    segments: list[Line | Arc] = []
    for i, seg in enumerate(body.segments or ()):
        if isinstance(seg, ArcSegment):
            via = _pose(seg.via, mode, previous, f"segments.{i}.via")
            previous = _pose(seg.to, mode, via, f"segments.{i}.to")
            segments.append(Arc(via, previous))
        else:
            previous = _pose(seg.to, mode, previous, f"segments.{i}.to")
            segments.append(Line(previous))
    return CartesianPath.from_segments(start, segments)


def _follow(
    robot: RobotModel,
    start: np.ndarray,
    path: CartesianPath,
    ik_options: IKOptions,
    options: PathOptions,
    collisions: Collisions | None,
    rng: np.random.Generator | None,
    timing: TimingIn | None,
    grp: Group | None,
    deadline: float,
    cancel: threading.Event | None = None,
) -> dict:
    res = follow(
        robot,
        start,
        path,
        ik_options,
        options,
        accept=accept_of(robot, collisions),
        rng=rng,
        cancel=cancel,
        deadline=deadline,
    )
    record_ik(res.failure is None)
    failure = res.failure
    return {
        "robot_id": robot.id,
        "frame": ik_options.frame,
        "mode": ik_options.mode,
        "joint_names": robot.joint_names,
        "fraction": res.fraction,
        "points": [
            {
                "q": p.q.tolist(),
                "position_error": p.position_error,
                "orientation_error": p.orientation_error,
                "s": p.s,
            }
            for p in res.points
        ],
        "failure": None
        if failure is None
        else {
            "index": failure.index,
            "s": failure.s,
            "reason": failure.reason,
            "detail": failure.detail,
            "q": failure.q.tolist(),
            "position_error": failure.position_error,
            "orientation_error": failure.orientation_error,
        },
        "branch": res.branch,
        "waypoints": res.waypoints,
        "iterations": res.iterations,
        "solve_time_ms": res.solve_time_ms,
        "solver_version": SOLVER_VERSION,
        "timing": None if timing is None else _timing(robot, res.points, timing, grp),
    }


def _timing(robot: RobotModel, points: list, timing: TimingIn, grp: Group | None) -> dict:
    """The timing of the accepted points: continuous joints unwrapped (the path crosses ±π
    as a small move, not a 2π one), limit lists in the group's joints when there is one."""
    qs = robot.unwrap_path(np.array([p.q for p in points]))
    return timing_of(robot, qs, timing, None if grp is None else grp.indices)


@router.post(
    "/ik/path",
    operation_id="solve_ik_path",
    response_model=PathResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def solve_ik_path(
    robot: RobotDep, body: PathRequest, request: Request, settings: SettingsDep
) -> ORJSONResponse:
    """A joint path that moves a frame along lines and arcs, on one branch.

    The path (position linear, orientation by slerp) is interpolated at `max_step`; each
    point is solved seeded by the previous solution and accepted only if no joint moves more
    than `max_joint_step`, the branch does not change and (with `avoid_collisions`) the
    configuration is collision-free. Between accepted points the path is densified until
    the joint-linear motion stays within `max_deviation` of the Cartesian path. A path that
    cannot be completed is not an error: 200 with `fraction` < 1, the points up to there,
    and `failure` (index, reason, detail) of the first point that failed. See docs/paths.md.
    The request's total budget, points × `timeout_ms`, may not exceed the server's
    `ik_max_request_s` (else 422 naming `max_step`), which is also the path's deadline (past
    it, the path stops with `failure.reason: timeout`); the work stops when the client leaves.
    """
    check_budget(settings, body.timeout_ms)
    ik_options = options_of(robot, body)
    options = PathOptions(
        max_step=(body.max_step.position, body.max_step.orientation),
        max_joint_step=body.max_joint_step,
        max_deviation=(body.max_deviation.position, body.max_deviation.orientation),
        branch=body.branch,
    )
    collisions = collisions_of(request, body)
    grp = group(robot, body.group)
    start = group_seed(robot, grp, body.start, "start")
    path = _path(body, start_pose(robot, start, ik_options))
    check_request_budget(
        settings,
        path.count(options.max_step),
        "points",
        body.timeout_ms,
        "a larger max_step, a shorter path or a smaller timeout_ms",
        "max_step",
    )
    out = await offload_cancellable(
        request,
        _follow,
        robot,
        start,
        path,
        ik_options,
        options,
        collisions,
        rng_of(body),
        body.timing,
        grp,
        time.perf_counter() + settings.ik_max_request_s,
    )
    return ORJSONResponse(out)
