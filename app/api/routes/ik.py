"""Inverse kinematics: POST /robots/{robot_id}/ik and /ik/batch."""

from __future__ import annotations

import functools
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pinocchio as pin
from fastapi import APIRouter, Request
from starlette.requests import HTTPConnection

from app.api.deps import RegistryDep, load_robot
from app.api.errors import ERROR_RESPONSES
from app.api.ik_request import (
    Collisions,
    accept_of,
    check_budget,
    check_request_budget,
    clearance_of,
    collisions_of,
    options_of,
    rng_of,
    target_of,
)
from app.api.offload import offload_cancellable
from app.api.responses import ORJSONResponse
from app.api.schemas.common import RobotId
from app.api.schemas.ik import IKBatchRequest, IKBatchResponse, IKRequest, IKResponse
from app.kinematics import ik
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import group
from app.kinematics.ik.batch import BatchTask, collision_accept, result_entry
from app.kinematics.ik.problem import IKOptions, group_seed
from app.kinematics.models import RobotModel
from app.operations.metrics import record_ik
from app.workers import default_processes
from app.workers.ik_batch import batch_pool

router = APIRouter(prefix="/robots/{robot_id}", tags=["inverse kinematics"])

#: IK requests with a budget up to this run on the event loop (no thread hop).
INLINE_BUDGET_MS = 5.0


def _named(robot: RobotModel, q: np.ndarray) -> dict[str, float]:
    return dict(zip(robot.joint_names, q.tolist(), strict=True))


def _solve_one(
    robot: RobotModel,
    target: pin.SE3,
    seed: np.ndarray | None,
    options: IKOptions,
    collisions: Collisions | None,
    rng: np.random.Generator | None = None,
    cancel: threading.Event | None = None,
    annotate: bool = True,
) -> dict:
    res = ik.solve(
        robot,
        target,
        options,
        seed=seed,
        accept=accept_of(robot, collisions),
        rng=rng,
        cancel=cancel,
        clearance=clearance_of(robot, collisions),
        annotate=annotate,
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
                "branch": s.branch,
                "seed_distance": s.seed_distance,
                "manipulability": s.manipulability,
                "clearance": s.clearance,
            }
            for s in res.solutions
        ],
        "iterations": res.iterations,
        "restarts": res.restarts,
        "solve_time_ms": res.solve_time_ms,
        "method": res.method,
        "reason": res.reason,
        "detail": res.detail,
        "solver_version": ik.SOLVER_VERSION,
    }


def _solve_batch(
    robot: RobotModel,
    targets: list[pin.SE3],
    task: BatchTask,
    chain: bool,
    processes: int,
    cancel: threading.Event | None = None,
) -> dict:
    """Solve ``targets`` in order; ``cancel`` (set when the client left) is checked between
    targets and inside each solve. With ``chain`` each target is seeded by the previous
    solution (one generator for the batch); without, the targets are independent and
    spread over ``processes`` worker processes (:mod:`app.workers.ik_batch`)."""
    t0 = time.perf_counter()
    options = task.options
    if chain:
        results = []
        current = task.seed
        accept = collision_accept(robot, task.collisions)
        rng = None if task.random_seed is None else np.random.default_rng(task.random_seed)
        for T in targets:
            res = ik.solve(robot, T, options, seed=current, accept=accept, rng=rng, cancel=cancel)
            record_ik(res.success)
            if res.success:
                current = res.q
            results.append(result_entry(res))
    else:
        results = batch_pool(processes).solve(robot, targets, task, cancel=cancel, record=record_ik)
    return {
        "robot_id": robot.id,
        "frame": options.frame,
        "mode": options.mode,
        "joint_names": robot.joint_names,
        "solved": sum(r["success"] for r in results),
        "results": results,
        "total_time_ms": (time.perf_counter() - t0) * 1e3,
        "solver_version": ik.SOLVER_VERSION,
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
    check_budget(request, body.timeout_ms)
    robot = await load_robot(reg, robot_id)
    plan, solve = prepare_ik(request, robot, body)
    # inline only once the chain is built: its first build (the restart table, tens of ms)
    # runs in the pool, never on the event loop
    inline = plan.inline and ik.chain_ready(robot, plan.options)
    out = solve() if inline else await offload_cancellable(request, solve)
    return ORJSONResponse(out)


@dataclass(frozen=True, slots=True)
class IKPlan:
    """What an IK request's options make, whatever its target and seed: the core's options,
    the collisions to avoid, the request (its ``random_seed`` and ``group``), and whether it
    may run on the event loop (a budget up to :data:`INLINE_BUDGET_MS`, no collision checks).
    The stream keeps one for its binary IK frames (:mod:`app.api.routes.stream`)."""

    options: IKOptions
    collisions: Collisions | None
    body: IKRequest
    inline: bool

    def call(
        self, robot: RobotModel, target: pin.SE3, seed: np.ndarray | None, annotate: bool = True
    ) -> Callable[..., dict]:
        """The query as a call giving its answer body; it takes an optional ``cancel``
        event (:func:`offload_cancellable`). Without ``annotate`` (the stream's binary
        answers, which carry no labels) the solutions' ``branch`` and ``manipulability`` are
        computed only where the ranking needs them: the same ``q``."""
        return functools.partial(
            _solve_one,
            robot,
            target,
            seed,
            self.options,
            self.collisions,
            rng_of(self.body),
            annotate=annotate,
        )


def plan_ik(conn: HTTPConnection, robot: RobotModel, body: IKRequest) -> IKPlan:
    """The :class:`IKPlan` of ``body`` (validated by the core, naming the fields)."""
    options = options_of(robot, body, body.num_solutions, body.rank_by)
    collisions = collisions_of(conn, body)
    inline = body.timeout_ms <= INLINE_BUDGET_MS and collisions is None
    return IKPlan(options, collisions, body, inline)


def prepare_ik(
    conn: HTTPConnection,
    robot: RobotModel,
    body: IKRequest,
    last_q: np.ndarray | None = None,
) -> tuple[IKPlan, Callable[..., dict]]:
    """One IK query (HTTP or the stream): its :class:`IKPlan` (whether it may run on the
    event loop; the stream keeps it for binary frames) and a call giving its answer body.

    ``last_q`` seeds the query when the body gives no ``seed`` (the stream's last solution);
    without either, the solver's default (the middle of the joint limits).
    """
    plan = plan_ik(conn, robot, body)
    target = target_of(body.target, body.mode)
    seed = last_q if body.seed is None else group_seed(robot, group(robot, body.group), body.seed)
    return plan, plan.call(robot, target, seed)


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
    check_budget(request, body.timeout_ms)
    limit = request.app.state.settings.max_batch
    if len(body.targets) > limit:
        raise InvalidInputError(
            f"{len(body.targets)} targets exceed the limit of {limit}", "targets"
        )
    check_request_budget(
        request,
        len(body.targets),
        "targets",
        body.timeout_ms,
        "send fewer targets per request, or a smaller timeout_ms",
        "targets",
    )
    robot = await load_robot(reg, robot_id)
    options = options_of(robot, body)
    collisions = collisions_of(request, body)
    targets = [target_of(t, body.mode, field=f"targets.{i}") for i, t in enumerate(body.targets)]
    seed = group_seed(robot, group(robot, body.group), body.seed)
    task = BatchTask(seed, options, collisions, body.random_seed)
    processes = request.app.state.settings.ik_batch_processes or default_processes()
    out = await offload_cancellable(
        request, _solve_batch, robot, targets, task, body.chain_seeds, processes
    )
    return ORJSONResponse(out)
