"""One IK query's plan, for HTTP and the stream: its options, the collisions to avoid, and
whether it may run on the event loop.

A query with a budget up to :data:`INLINE_BUDGET_MS` and no collision checks is solved on
the event loop (no thread hop); anything else goes to the compute pool
(:mod:`app.api.offload`). The call a plan makes returns the core's
:class:`~app.kinematics.ik.IKResult`; its wire form is written by
:func:`app.api.ik_answers.ik_answer`.
"""

from __future__ import annotations

import functools
import threading
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pinocchio as pin
from starlette.requests import HTTPConnection

from app.api.ik_request import (
    Collisions,
    accept_of,
    clearance_of,
    collisions_of,
    options_of,
    rng_of,
    target_of,
)
from app.api.schemas.ik import IKRequest
from app.kinematics import ik
from app.kinematics.groups import group
from app.kinematics.ik.problem import IKOptions, group_seed
from app.kinematics.models import RobotModel
from app.operations.metrics import record_ik

#: IK requests with a budget up to this (ms) run on the event loop (no thread hop).
INLINE_BUDGET_MS = 5.0


def _solve_one(
    robot: RobotModel,
    target: pin.SE3,
    seed: np.ndarray | None,
    options: IKOptions,
    collisions: Collisions | None,
    rng: np.random.Generator | None = None,
    cancel: threading.Event | None = None,
    annotate: bool = True,
) -> ik.IKResult:
    """Solve one target (counted in the IK metrics)."""
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
    return res


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
    ) -> Callable[..., ik.IKResult]:
        """The query as a call giving its result; it takes an optional ``cancel`` event
        (:func:`~app.api.offload.offload_cancellable`). Without ``annotate`` (the stream's
        binary answers, which carry no labels) the solutions' ``branch`` and
        ``manipulability`` are computed only where the ranking needs them: the same ``q``."""
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
) -> tuple[IKPlan, Callable[..., ik.IKResult]]:
    """One IK query (HTTP or the stream): its :class:`IKPlan` (whether it may run on the
    event loop; the stream keeps it for binary frames) and a call giving its result.

    ``last_q`` seeds the query when the body gives no ``seed`` (the stream's last solution);
    without either, the solver's default (the middle of the joint limits).
    """
    plan = plan_ik(conn, robot, body)
    target = target_of(body.target, body.mode)
    seed = last_q if body.seed is None else group_seed(robot, group(robot, body.group), body.seed)
    return plan, plan.call(robot, target, seed)
