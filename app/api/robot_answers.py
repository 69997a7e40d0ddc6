"""The answers of the robot routes (robots and packages): a robot's wire description, the
201 of a robot write, and the documented errors of writes."""

from __future__ import annotations

from typing import Any

from app.api.errors import Problem
from app.api.responses import ORJSONResponse
from app.api.schemas.semantics import semantics_detail
from app.kinematics.collision_pairs import collision_link_pairs
from app.kinematics.models import RobotModel

#: The error answers of robot writes, as documented in the OpenAPI document.
WRITE_ERRORS: dict[int | str, dict[str, Any]] = {
    code: {"model": Problem, "content": {"application/problem+json": {}}, "description": text}
    for code, text in {
        400: "The body is not JSON (or YAML).",
        401: "A bearer token is required.",
        403: "Wrong token, or a built-in robot.",
        409: "The robot id is taken.",
        413: "The body exceeds DENAVIT_MAX_UPLOAD_BYTES.",
        415: "Unsupported Content-Type.",
        422: "A field failed validation; `field` names it.",
    }.items()
}


def robot_detail(robot: RobotModel, files: tuple[Any, str] | None = None) -> dict[str, Any]:
    """The wire description of a robot (GET /robots/{robot_id}); ``files`` as returned by
    :meth:`Registry.files_root`."""
    return {
        "id": robot.id,
        "name": robot.name,
        "source": robot.source,
        "description": robot.description,
        "joints": [robot.describe_joint(j) for j in robot.joints],
        "mimic_joints": [m.describe() for m in robot.mimic_joints],
        "frames": [
            {"name": f.name, "kind": f.kind, "parent_joint": f.parent_joint} for f in robot.frames
        ],
        "end_effector": robot.ee_frame,
        **semantics_detail(robot),
        "neutral": robot.neutral().tolist(),
        "has_collision_geometry": robot.has_collision_geometry,
        "collision_pairs": [list(p) for p in collision_link_pairs(robot)],
        "files": ({"uri_prefix": files[1], "url": f"/robots/{robot.id}/files/"} if files else None),
    }


def created(detail: dict[str, Any]) -> ORJSONResponse:
    """201 with the new robot's description (built in the pool, like the robot itself)."""
    return ORJSONResponse(detail, status_code=201, headers={"Location": f"/robots/{detail['id']}"})
