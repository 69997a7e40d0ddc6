"""Inverse kinematics: POST /robots/{robot_id}/ik and /ik/batch.

The query's plan (inline or pooled) is :mod:`app.api.ik_plan`'s, the answers are written by
:mod:`app.api.ik_answers`, the wire models are :mod:`app.api.schemas.ik`'s.
"""

from __future__ import annotations

import threading
import time

import numpy as np
import pinocchio as pin
from fastapi import APIRouter, Request

from app.api.deps import RobotDep, SettingsDep
from app.api.errors import ERROR_RESPONSES
from app.api.ik_answers import batch_answer, ik_answer
from app.api.ik_plan import prepare_ik
from app.api.ik_request import collisions_of, options_of, target_of
from app.api.limits import check_batch_size, check_budget, check_request_budget
from app.api.offload import offload_cancellable
from app.api.responses import ORJSONResponse
from app.api.schemas.ik import IKBatchRequest, IKBatchResponse, IKRequest, IKResponse
from app.api.state import services
from app.kinematics import ik
from app.kinematics.groups import group
from app.kinematics.ik.batch import BatchAnswers, BatchTask, collision_accept
from app.kinematics.ik.problem import group_seed
from app.kinematics.models import RobotModel
from app.operations.metrics import record_ik
from app.workers.ik_batch import BatchPool

router = APIRouter(prefix="/robots/{robot_id}", tags=["inverse kinematics"])


def _solve_batch(
    robot: RobotModel,
    targets: list[pin.SE3],
    task: BatchTask,
    chain: bool,
    pool: BatchPool,
    cancel: threading.Event | None = None,
) -> dict:
    """Solve ``targets`` in order; ``cancel`` (set when the client left) is checked between
    targets and inside each solve. With ``chain`` each target is seeded by the previous
    solution (one generator for the batch); without, the targets are independent and
    spread over the app's batch worker processes (``pool``, :mod:`app.workers.ik_batch`)."""
    t0 = time.perf_counter()
    options = task.options
    if chain:
        results = BatchAnswers.allocate(len(targets), len(robot.joint_names))
        current = task.seed
        accept = collision_accept(robot, task.collisions)
        rng = None if task.random_seed is None else np.random.default_rng(task.random_seed)
        for i, T in enumerate(targets):
            res = ik.solve(robot, T, options, seed=current, accept=accept, rng=rng, cancel=cancel)
            record_ik(res.success)
            if res.success:
                current = res.q
            results.put(i, res)
    else:
        results = pool.solve(robot, targets, task, cancel=cancel, record=record_ik)
    return batch_answer(robot, options, results, (time.perf_counter() - t0) * 1e3)


# ------------------------------------------------------------------------------ routes
@router.post(
    "/ik",
    operation_id="solve_ik",
    response_model=IKResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def solve_ik(
    robot: RobotDep, body: IKRequest, request: Request, settings: SettingsDep
) -> ORJSONResponse:
    """Joint configurations that place a frame at a target pose.

    Damped least squares (Levenberg–Marquardt) on the SE(3) error with random restarts
    within the time budget, seeded by closed forms where the chain admits one (see
    docs/ik.md). Every solution is verified by forward kinematics and lies within the joint
    limits. An unreachable target is not an error: 200 with `success: false`, the best
    configuration found and its errors.
    """
    check_budget(settings, body.timeout_ms)
    plan, solve = prepare_ik(request, robot, body)
    # inline only once the chain is built: its first build (the restart table, tens of ms)
    # runs in the pool, never on the event loop
    inline = plan.inline and ik.chain_ready(robot, plan.options)
    res = solve() if inline else await offload_cancellable(request, solve)
    return ORJSONResponse(ik_answer(robot, plan.options, res))


@router.post(
    "/ik/batch",
    operation_id="solve_ik_batch",
    response_model=IKBatchResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def solve_ik_batch(
    robot: RobotDep, body: IKBatchRequest, request: Request, settings: SettingsDep
) -> ORJSONResponse:
    """IK for many targets of one frame, in order, computed in the work pool.

    With `chain_seeds` (default) each target is seeded with the previous solution, which
    keeps a trajectory on one branch; otherwise every target starts from `seed`. The
    request's total budget, targets × `timeout_ms`, may not exceed the server's
    `ik_max_request_s` (default 30 s; else 422 naming `targets`), and the work stops when
    the client disconnects.
    """
    check_budget(settings, body.timeout_ms)
    check_batch_size(len(body.targets), settings.max_batch, "targets", "targets")
    check_request_budget(
        settings,
        len(body.targets),
        "targets",
        body.timeout_ms,
        "send fewer targets per request, or a smaller timeout_ms",
        "targets",
    )
    options = options_of(robot, body)
    collisions = collisions_of(request, body)
    targets = [target_of(t, body.mode, field=f"targets.{i}") for i, t in enumerate(body.targets)]
    seed = group_seed(robot, group(robot, body.group), body.seed)
    task = BatchTask(seed, options, collisions, body.random_seed)
    pool = services(request).ik_batch
    out = await offload_cancellable(
        request, _solve_batch, robot, targets, task, body.chain_seeds, pool
    )
    return ORJSONResponse(out)
