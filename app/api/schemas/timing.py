"""The wire shapes of a path's time parameterization (``timing`` of /ik/path) and the call
from a request's options to the core (:mod:`app.kinematics.paths.timing`)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Annotated, Any

import numpy as np
from pydantic import BaseModel, Field, ValidationError, ValidatorFunctionWrapHandler, WrapValidator
from pydantic_core import InitErrorDetails, PydanticCustomError

from app.api.schemas.common import Finite, Schema
from app.kinematics.models import RobotModel
from app.kinematics.paths.limits import DEFAULT_ACCELERATION_FRACTION, LIMIT_RANGE
from app.kinematics.paths.timing import parameterize


def _one_form(value: Any, handler: ValidatorFunctionWrapHandler) -> Any:
    """Validate a list-or-map field, naming the error by the form given (``3`` for a list's
    item, the joint for a map's entry) rather than by pydantic's union branch
    (``list[float].3``)."""
    try:
        return handler(value)
    except ValidationError as exc:
        if not isinstance(value, list | dict):
            raise PydanticCustomError(
                "joint_limits", "must be a list (one number per joint) or a map joint → number"
            ) from None
        form = "list" if isinstance(value, list) else "dict"
        error = next(e for e in exc.errors() if str(e["loc"][0]).startswith(form))
        detail = InitErrorDetails(
            type=PydanticCustomError(error["type"], error["msg"]),
            loc=error["loc"][1:],
            input=error["input"],
        )
        raise ValidationError.from_exception_data("joint limits", [detail]) from None


#: A per-joint limit list or joint → limit map, each within LIMIT_RANGE: errors name
#: ``timing.velocity_limits.3`` or ``timing.velocity_limits.<joint>``.
Limit = Annotated[Finite, Field(ge=LIMIT_RANGE[0], le=LIMIT_RANGE[1])]
JointLimits = Annotated[
    Annotated[list[Limit], Field(max_length=1000)]
    | Annotated[dict[Annotated[str, Field(max_length=256)], Limit], Field(max_length=1000)],
    WrapValidator(_one_form),
]


class TimingIn(Schema):
    """Time-optimal parameterization of the joint path: the fastest rest-to-rest motion along
    it within joint velocity and acceleration limits (TOPP-RA), verified on the output."""

    velocity_limits: JointLimits | None = Field(
        None,
        description="Joint velocity limits (rad/s or m/s, each within [1e-6, 1e9]): one per "
        "joint in joint "
        "order (with `group`: one per joint of the group), or joint → limit (the others keep "
        "theirs). Default: the robot description's (URDF `<limit velocity>`); a joint that "
        "moves and has none (missing, 0) is an error naming timing.velocity_limits.<joint>.",
    )
    acceleration_limits: JointLimits | None = Field(
        None,
        description="Joint acceleration limits (rad/s² or m/s², each within [1e-6, 1e9]), as "
        "velocity_limits; "
        "joints not given: acceleration_fraction × their velocity limit. Not with "
        "acceleration_fraction.",
    )
    acceleration_fraction: Finite | None = Field(
        None,
        gt=0.0,
        le=1e6,
        description="Acceleration limit of every joint as a fraction of its velocity limit, "
        "per second: f gives a_max = f · v_max / (1 s) (v_max before velocity_scale). "
        f"Default {DEFAULT_ACCELERATION_FRACTION:g} (URDF has no acceleration limits). Not "
        "with acceleration_limits.",
    )
    velocity_scale: Finite = Field(
        1.0, gt=0.0, le=1.0, description="Every velocity limit multiplied by this, in (0, 1]."
    )


class TimingOut(BaseModel):
    """Times, joint velocities and accelerations at the path's points (joint order). The
    limits hold at every point and at samples between them (``time_scale``)."""

    t: list[float] = Field(description="Time of each point (s), 0 at the first.")
    velocities: list[list[float]] = Field(
        description="Joint velocities at each point (rad/s or m/s); 0 at both ends."
    )
    accelerations: list[list[float]] = Field(
        description="Joint accelerations at each point (rad/s² or m/s²), just after it (at the "
        "last point: just before)."
    )
    duration: float = Field(description="Time of the last point (s).")
    velocity_limits: list[float | None] = Field(
        description="The velocity limit applied to each joint; null: the joint does not move."
    )
    acceleration_limits: list[float | None] = Field(
        description="The acceleration limit applied to each joint; null: the joint does not move."
    )
    time_scale: float = Field(
        description="How much the motion was slowed after TOPP-RA so that every verified "
        "sample keeps its limits (1.0: not at all)."
    )


def _limits(values: np.ndarray) -> list[float | None]:
    return [None if np.isnan(v) else float(v) for v in values]


def timing_of(
    robot: RobotModel, qs: np.ndarray, timing: TimingIn, joints: Sequence[int] | None = None
) -> dict[str, Any]:
    """The ``timing`` answer (:class:`TimingOut`) of the joint path ``qs`` ((N, n) wire
    configurations); ``joints``: the wire indices limit lists refer to (a group's joints),
    default every joint. Errors name ``timing.<option>[.<i or joint>]``."""
    result = parameterize(
        robot,
        qs,
        velocity_limits=timing.velocity_limits,
        acceleration_limits=timing.acceleration_limits,
        acceleration_fraction=timing.acceleration_fraction,
        velocity_scale=timing.velocity_scale,
        joints=joints,
        field="timing",
    )
    return {
        "t": result.t.tolist(),
        "velocities": result.qd.tolist(),
        "accelerations": result.qdd.tolist(),
        "duration": result.duration,
        "velocity_limits": _limits(result.velocity_limits),
        "acceleration_limits": _limits(result.acceleration_limits),
        "time_scale": result.time_scale,
    }
