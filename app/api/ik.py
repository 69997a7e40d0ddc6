"""Inverse kinematics: POST /robots/{robot_id}/ik and /ik/batch."""

from __future__ import annotations

import threading
import time
from typing import Annotated, Any, Literal

import numpy as np
import pinocchio as pin
from fastapi import APIRouter, Request
from pydantic import BaseModel, Field

from app.api.deps import RegistryDep, load_robot, scene_store
from app.api.errors import ERROR_RESPONSES
from app.api.offload import offload_cancellable
from app.api.responses import ORJSONResponse
from app.api.scenes import ObstacleIn, resolve_obstacles
from app.api.schemas import Finite, Matrix4, Position3, Quat, RobotId, Schema, group_field
from app.kinematics import ik
from app.kinematics.collision import collision_filter
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import default_frame, group
from app.kinematics.ik.problem import IKOptions, frame_name, group_seed, target_placement
from app.kinematics.models import RobotModel
from app.kinematics.obstacles import Obstacle
from app.metrics import record_ik

router = APIRouter(prefix="/robots/{robot_id}", tags=["inverse kinematics"])

NonNegative = Annotated[float, Field(ge=0.0, allow_inf_nan=False, strict=True)]
Positive = Annotated[float, Field(gt=0.0, allow_inf_nan=False, strict=True)]

#: IK requests with a budget up to this run on the event loop (no thread hop).
INLINE_BUDGET_MS = 5.0

MODE_DOC = (
    "pose (default): full 6-D pose | position: the frame origin only, orientation free "
    "(3 task rows, fine for arms with fewer than 6 joints) | orientation: the rotation only."
)


class Target(Schema):
    """Desired placement of the frame in the root (world) frame."""

    position: Position3 | None = Field(None, description="[x, y, z] in metres.")
    orientation: Quat | None = Field(
        None, description="Quaternion [x, y, z, w]; normalised if |q| is within 1e-3 of 1."
    )
    matrix: Matrix4 | None = Field(
        None, description="4×4 homogeneous transform (instead of position/orientation)."
    )


class Tolerance(Schema):
    """Success thresholds."""

    position: Positive = Field(1e-5, description="Largest position error ‖p − p_t‖ (m).")
    orientation: Positive = Field(1e-5, description="Largest rotation angle to the target (rad).")


class IKOptionsIn(Schema):
    """Options shared by single and batch IK (the wire shape of :class:`IKOptions`)."""

    frame: str | None = Field(
        None, description="Frame to place; default the end effector (with `group`: its tip)."
    )
    group: str | None = group_field()
    mode: Literal["pose", "position", "orientation"] = Field("pose", description=MODE_DOC)
    weights: Annotated[list[NonNegative], Field(min_length=6, max_length=6)] | None = Field(
        None,
        description="Non-negative weights of the error [px, py, pz, rx, ry, rz] (world axes); "
        "0 frees a component (not checked against the tolerance).",
    )
    # Finite, not JointValue: the union's validation errors would be named
    # seed.list[constrained-float].4; seed_configuration checks the bound, naming seed.4.
    seed: list[Finite] | dict[str, Finite] | Annotated[str, Field(max_length=256)] | None = Field(
        None,
        description="Start configuration: one value per joint (joint order; with `group`, one "
        "per joint of the group is accepted too), joint → value (others: middle of their "
        'limits), or the name of a named state of the SRDF (e.g. "ready"; GET '
        "/robots/{id} lists them). Default: the middle of the joint limits. Values within "
        "±10000 (rad or m), as every configuration. IK answers always hold every joint.",
    )
    tolerance: Tolerance = Field(default_factory=Tolerance)
    timeout_ms: Positive = Field(
        5.0, description="Time budget (ms) per target; capped by the server's ik_max_timeout_ms."
    )
    max_iterations: int | None = Field(
        None, ge=1, le=10_000_000, description="Cap on solver iterations (Jacobian evaluations)."
    )
    avoid_collisions: bool = Field(
        False,
        strict=True,
        description="Return only solutions free of self-collision and of collision with "
        "`obstacles` / `scene` (other branches and restarts are searched within the budget).",
    )
    obstacles: list[ObstacleIn] | None = Field(
        None, max_length=1000, description="With avoid_collisions: obstacles (root frame)."
    )
    scene: str | None = Field(
        None, max_length=64, description="With avoid_collisions: a stored scene's name."
    )
    margin: NonNegative = Field(
        0.0, le=10.0, description="With avoid_collisions: clearance (m) a solution must keep."
    )
    collision_geometry: Literal["mesh", "convex"] = Field(
        "mesh", description="With avoid_collisions: meshes, or their convex hulls (faster)."
    )


class IKRequest(IKOptionsIn):
    """One IK query."""

    target: Target
    num_solutions: int = Field(
        1, ge=1, le=64, description="Distinct solutions wanted (e.g. elbow up/down)."
    )


class IKSolutionOut(BaseModel):
    """A verified solution."""

    q: list[float] = Field(description="Configuration in joint order (rad, m).")
    joint_positions: dict[str, float]
    position_error: float = Field(description="‖p − p_t‖ (m), by forward kinematics.")
    orientation_error: float = Field(description="Rotation angle to the target (rad).")


class IKResponse(BaseModel):
    """Result; no solution is not an error (success false, best configuration found)."""

    robot_id: str
    frame: str
    mode: str
    success: bool
    status: Literal["converged", "not_converged", "timeout"]
    q: list[float] = Field(description="Best configuration (first solution, or lowest error).")
    joint_positions: dict[str, float]
    position_error: float = Field(description="Of q: ‖p − p_t‖ (m).")
    orientation_error: float = Field(description="Of q: rotation angle to the target (rad).")
    solutions: list[IKSolutionOut] = Field(description="Distinct solutions, nearest seed first.")
    iterations: int
    restarts: int
    solve_time_ms: float
    method: str = Field(description="analytic | numeric | analytic+numeric")


class IKBatchRequest(IKOptionsIn):
    """Many targets for one frame."""

    targets: list[Target] = Field(min_length=1, description="Targets, solved in order.")
    chain_seeds: bool = Field(
        True,
        description="Seed each target with the previous solution (trajectories); false: every "
        "target starts from `seed`.",
    )


class IKBatchItem(BaseModel):
    """Result for one target."""

    success: bool
    status: Literal["converged", "not_converged", "timeout"]
    q: list[float]
    position_error: float
    orientation_error: float
    iterations: int
    restarts: int
    solve_time_ms: float


class IKBatchResponse(BaseModel):
    """Results in target order."""

    robot_id: str
    frame: str
    mode: str
    joint_names: list[str]
    solved: int = Field(description="How many targets succeeded.")
    results: list[IKBatchItem]
    total_time_ms: float


# ----------------------------------------------------------------------------- parsing
def _target(target: Target, mode: str, field: str = "target") -> pin.SE3:
    """The target's placement (validated by the core, naming ``field``)."""
    return target_placement(target.position, target.orientation, target.matrix, mode, field)


def _budget(request: Request, timeout_ms: float) -> None:
    cap = request.app.state.settings.ik_max_timeout_ms
    if timeout_ms > cap:
        raise InvalidInputError(
            f"{timeout_ms} ms exceeds the server's cap of {cap} ms", "timeout_ms"
        )


#: What collision-aware IK checks a solution against: obstacles (root frame), clearance (m),
#: and the collision geometry (``mesh`` or ``convex``).
Collisions = tuple[tuple[Obstacle, ...], float, str]


def _collisions(request: Request, body: IKOptionsIn) -> Collisions | None:
    """(obstacles, margin, geometry) for collision-aware IK, or None (validated here)."""
    if not body.avoid_collisions:
        for name in ("obstacles", "scene"):
            if getattr(body, name) is not None:
                raise InvalidInputError("only used with avoid_collisions: true", name)
        return None
    obstacles = resolve_obstacles(scene_store(request), body.obstacles, body.scene)
    return obstacles, body.margin, body.collision_geometry


def _accept(robot: RobotModel, collisions: Collisions | None) -> Any:
    """The collision-free predicate of collision-aware IK (builds the collision model)."""
    if collisions is None:
        return None
    obstacles, margin, geometry = collisions
    return collision_filter(robot, obstacles, margin=margin, mode=geometry)


def _options(robot: RobotModel, body: IKOptionsIn, num_solutions: int = 1) -> IKOptions:
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
    )


def _named(robot: RobotModel, q: np.ndarray) -> dict[str, float]:
    return dict(zip(robot.joint_names, q.tolist(), strict=True))


def _solve_one(
    robot: RobotModel,
    target: pin.SE3,
    seed: np.ndarray,
    options: IKOptions,
    collisions: Collisions | None,
    cancel: threading.Event | None = None,
) -> dict:
    res = ik.solve(
        robot, target, options, seed=seed, accept=_accept(robot, collisions), cancel=cancel
    )
    record_ik(res.success)
    return {
        "robot_id": robot.id,
        "frame": options.frame,
        "mode": options.mode,
        "success": res.success,
        "status": res.status,
        "q": res.q.tolist(),
        "joint_positions": _named(robot, res.q),
        "position_error": res.position_error,
        "orientation_error": res.orientation_error,
        "solutions": [
            {
                "q": s.q.tolist(),
                "joint_positions": _named(robot, s.q),
                "position_error": s.position_error,
                "orientation_error": s.orientation_error,
            }
            for s in res.solutions
        ],
        "iterations": res.iterations,
        "restarts": res.restarts,
        "solve_time_ms": res.solve_time_ms,
        "method": res.method,
    }


def _solve_batch(
    robot: RobotModel,
    targets: list[pin.SE3],
    seed: np.ndarray,
    options: IKOptions,
    collisions: Collisions | None,
    chain: bool,
    cancel: threading.Event | None = None,
) -> dict:
    """Solve ``targets`` in order; ``cancel`` (set when the client left) is checked between
    targets and inside each solve."""
    t0 = time.perf_counter()
    results = []
    solved = 0
    current = seed
    accept = _accept(robot, collisions)
    for T in targets:
        res = ik.solve(robot, T, options, seed=current, accept=accept, cancel=cancel)
        record_ik(res.success)
        solved += res.success
        if chain and res.success:
            current = res.q
        results.append(
            {
                "success": res.success,
                "status": res.status,
                "q": res.q.tolist(),
                "position_error": res.position_error,
                "orientation_error": res.orientation_error,
                "iterations": res.iterations,
                "restarts": res.restarts,
                "solve_time_ms": res.solve_time_ms,
            }
        )
    return {
        "robot_id": robot.id,
        "frame": options.frame,
        "mode": options.mode,
        "joint_names": robot.joint_names,
        "solved": solved,
        "results": results,
        "total_time_ms": (time.perf_counter() - t0) * 1e3,
    }


# ------------------------------------------------------------------------------ routes
@router.post(
    "/ik",
    operation_id="solve_ik",
    response_model=IKResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def solve_ik(
    robot_id: RobotId,
    body: IKRequest,
    request: Request,
    reg: RegistryDep,
) -> ORJSONResponse:
    """Joint configurations that place a frame at a target pose.

    Damped least squares (Levenberg–Marquardt) on the SE(3) error with random restarts
    within the time budget, seeded by closed forms where the chain admits one (see
    docs/ik.md). Every solution is verified by forward kinematics and lies within the joint
    limits. An unreachable target is not an error: 200 with `success: false`, the best
    configuration found and its errors.
    """
    _budget(request, body.timeout_ms)
    robot = await load_robot(reg, robot_id)
    options = _options(robot, body, body.num_solutions)
    collisions = _collisions(request, body)
    target = _target(body.target, body.mode)
    seed = group_seed(robot, group(robot, body.group), body.seed)
    if body.timeout_ms <= INLINE_BUDGET_MS and collisions is None:
        out = _solve_one(robot, target, seed, options, None)
    else:
        out = await offload_cancellable(
            request, _solve_one, robot, target, seed, options, collisions
        )
    return ORJSONResponse(out)


@router.post(
    "/ik/batch",
    operation_id="solve_ik_batch",
    response_model=IKBatchResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def solve_ik_batch(
    robot_id: RobotId,
    body: IKBatchRequest,
    request: Request,
    reg: RegistryDep,
) -> ORJSONResponse:
    """IK for many targets of one frame, in order, computed in the work pool.

    With `chain_seeds` (default) each target is seeded with the previous solution, which
    keeps a trajectory on one branch; otherwise every target starts from `seed`. The
    request's total budget, targets × `timeout_ms`, may not exceed the server's
    `ik_max_request_s` (default 30 s; else 422 naming `targets`), and the work stops when
    the client disconnects.
    """
    _budget(request, body.timeout_ms)
    limit = request.app.state.settings.max_batch
    if len(body.targets) > limit:
        raise InvalidInputError(
            f"{len(body.targets)} targets exceed the limit of {limit}", "targets"
        )
    total_s = len(body.targets) * body.timeout_ms * 1e-3
    cap_s = request.app.state.settings.ik_max_request_s
    if total_s > cap_s:
        raise InvalidInputError(
            f"{len(body.targets)} targets × {body.timeout_ms:g} ms = {total_s:g} s exceeds the "
            f"server's budget of {cap_s:g} s per request: send fewer targets per request, or "
            "a smaller timeout_ms",
            "targets",
        )
    robot = await load_robot(reg, robot_id)
    options = _options(robot, body)
    collisions = _collisions(request, body)
    targets = [_target(t, body.mode, field=f"targets.{i}") for i, t in enumerate(body.targets)]
    seed = group_seed(robot, group(robot, body.group), body.seed)
    out = await offload_cancellable(
        request, _solve_batch, robot, targets, seed, options, collisions, body.chain_seeds
    )
    return ORJSONResponse(out)
