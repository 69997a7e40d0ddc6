"""The wire form of IK results: one place writes every IK answer (HTTP single IK, batch IK
and the stream, JSON and binary alike start from these bodies).

The core returns :class:`~app.kinematics.ik.IKResult` objects (``q`` in joint order, rad
and m; errors in m and rad); these functions turn them into the JSON bodies of
:mod:`app.api.schemas.ik` (``IKResponse``, ``IKBatchResponse``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from app.kinematics import ik
from app.kinematics.ik.batch import BatchAnswers
from app.kinematics.ik.problem import IKOptions
from app.kinematics.ik.search import IKSolution
from app.kinematics.models import RobotModel


def named(robot: RobotModel, q: np.ndarray) -> dict[str, float]:
    """Joint name → value (rad or m) of a configuration in joint order."""
    return dict(zip(robot.joint_names, q.tolist(), strict=True))


def solution_json(robot: RobotModel, s: IKSolution) -> dict[str, Any]:
    """One verified solution of a single IK answer (``IKSolutionOut``)."""
    return {
        "q": s.q.tolist(),
        "joint_positions": named(robot, s.q),
        "position_error": s.position_error,
        "orientation_error": s.orientation_error,
        "branch": s.branch,
        "seed_distance": s.seed_distance,
        "manipulability": s.manipulability,
        "clearance": s.clearance,
    }


def ik_answer(robot: RobotModel, options: IKOptions, res: ik.IKResult) -> dict[str, Any]:
    """The body of a single IK answer (``IKResponse``: HTTP and the stream's ik messages)."""
    return {
        "robot_id": robot.id,
        "frame": options.frame,
        "mode": options.mode,
        "success": res.success,
        "status": res.status,
        "q": res.q.tolist(),
        "joint_positions": named(robot, res.q),
        "position_error": res.position_error,
        "orientation_error": res.orientation_error,
        "solutions": [solution_json(robot, s) for s in res.solutions],
        "iterations": res.iterations,
        "restarts": res.restarts,
        "solve_time_ms": res.solve_time_ms,
        "method": res.method,
        "reason": res.reason,
        "detail": res.detail,
        "solver_version": ik.SOLVER_VERSION,
    }


def batch_entries(answers: BatchAnswers) -> list[dict[str, Any]]:
    """Every target's entry of a batch answer (``IKBatchResult``), in target order, read
    from the columns (each column turned into Python values at once)."""
    notes = answers.notes
    none = (None, None)
    return [
        {
            "success": success,
            "status": status,
            "q": q,
            "position_error": pe,
            "orientation_error": oe,
            "iterations": it,
            "restarts": rs,
            "solve_time_ms": ms,
            "reason": notes.get(i, none)[0],
            "detail": notes.get(i, none)[1],
        }
        for i, (success, status, q, pe, oe, it, rs, ms) in enumerate(
            zip(
                answers.success.tolist(),
                answers.statuses(),
                answers.q.tolist(),
                answers.position_error.tolist(),
                answers.orientation_error.tolist(),
                answers.iterations.tolist(),
                answers.restarts.tolist(),
                answers.solve_time_ms.tolist(),
                strict=True,
            )
        )
    ]


def batch_answer(
    robot: RobotModel, options: IKOptions, answers: BatchAnswers, total_time_ms: float
) -> dict[str, Any]:
    """The body of a batch IK answer (``IKBatchResponse``), results in target order."""
    return {
        "robot_id": robot.id,
        "frame": options.frame,
        "mode": options.mode,
        "joint_names": robot.joint_names,
        "solved": answers.solved,
        "results": batch_entries(answers),
        "total_time_ms": total_time_ms,
        "solver_version": ik.SOLVER_VERSION,
    }
