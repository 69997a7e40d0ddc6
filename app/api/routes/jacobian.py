"""POST /robots/{robot_id}/jacobian: the 6×n geometric Jacobian of a frame (wire models:
:mod:`app.api.schemas.jacobian`; the answer body: :func:`app.api.answers.jacobian_answer`)."""

from __future__ import annotations

from fastapi import APIRouter

from app.api.answers import jacobian_answer
from app.api.deps import RobotDep
from app.api.errors import ERROR_RESPONSES
from app.api.responses import ORJSONResponse
from app.api.schemas.jacobian import JacobianRequest, JacobianResponse

router = APIRouter(prefix="/robots/{robot_id}", tags=["kinematics"])


@router.post(
    "/jacobian",
    operation_id="compute_jacobian",
    response_model=JacobianResponse,
    responses={k: ERROR_RESPONSES[k] for k in (400, 404, 422)},
)
async def compute_jacobian(robot: RobotDep, body: JacobianRequest) -> ORJSONResponse:
    """Geometric Jacobian of a frame at one configuration."""
    return ORJSONResponse(jacobian_answer(robot, body))
