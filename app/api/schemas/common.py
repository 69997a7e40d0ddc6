"""Wire types every router shares: finite numbers, joint values, text, configurations.

The request side is strict (unknown fields are errors, numbers must be finite JSON
numbers); the ``*Out`` twins type the service's own answers with the same fixed lengths,
so a generated client can pass an answer's pose back in a request.
"""

from __future__ import annotations

from typing import Annotated, Any

import numpy as np
from fastapi import Path
from pydantic import AfterValidator, BaseModel, ConfigDict, Field, Strict
from typing_extensions import TypeAliasType

from app.kinematics.groups import Group, configuration, group
from app.kinematics.models import MAX_JOINT_VALUE, MAX_POSITION, RobotModel
from app.kinematics.text import SURROGATE_REASON, has_surrogate

#: A finite JSON number (ints accepted; strings, booleans, NaN and ±Infinity rejected).
Finite = Annotated[float, Strict(), Field(allow_inf_nan=False)]
Vec3 = Annotated[list[Finite], Field(min_length=3, max_length=3)]
Quat = Annotated[list[Finite], Field(min_length=4, max_length=4)]
Vec4 = Annotated[list[Finite], Field(min_length=4, max_length=4)]
Matrix4 = Annotated[list[Vec4], Field(min_length=4, max_length=4)]
# Response twins of the above (plain floats: the service's own output). Same fixed lengths
# as the request types, so a generated client can pass an answer's pose back in a request.
Vec3Out = Annotated[list[float], Field(min_length=3, max_length=3)]
QuatOut = Annotated[list[float], Field(min_length=4, max_length=4)]
Vec4Out = Annotated[list[float], Field(min_length=4, max_length=4)]
Matrix4Out = Annotated[list[Vec4Out], Field(min_length=4, max_length=4)]
#: A joint value (rad or m) within ±MAX_JOINT_VALUE, the one bound of every configuration
#: (:data:`app.kinematics.models.MAX_JOINT_VALUE`; fast paths check it with
#: :func:`~app.kinematics.models.check_joint_values`).
JointValue = Annotated[Finite, Field(ge=-MAX_JOINT_VALUE, le=MAX_JOINT_VALUE)]
#: A target coordinate (m) within ±MAX_POSITION.
Coordinate = Annotated[Finite, Field(ge=-MAX_POSITION, le=MAX_POSITION)]
Position3 = Annotated[list[Coordinate], Field(min_length=3, max_length=3)]
#: Joint name → value (rad for revolute and continuous joints, m for prismatic ones): one
#: named component (``JointPositions``) for every request and answer (configurations, IK
#: seeds, path starts, named states). Finite numbers here; the core checks each value
#: against ±MAX_JOINT_VALUE naming ``<field>.<joint>``
#: (:meth:`~app.kinematics.models.RobotModel.apply_joint_map`), so a seed's union does not
#: blur the error.
JointPositions = TypeAliasType(
    "JointPositions",
    Annotated[
        dict[str, Finite],
        Field(
            max_length=1024,
            description="Joint name → value: rad for revolute and continuous joints, m for "
            "prismatic ones, each within ±10000 (a value beyond is a 422 naming "
            "`<field>.<joint>`).",
        ),
    ],
)
#: One value per actuated joint in joint order (rad or m): the ``Configuration`` component.
Configuration = TypeAliasType(
    "Configuration",
    Annotated[
        list[JointValue],
        Field(
            max_length=1024,
            description="One value per actuated joint in joint order (GET /robots/{id}): rad "
            "for revolute and continuous joints, m for prismatic ones.",
        ),
    ],
)


def _valid_text(value: str) -> str:
    if has_surrogate(value):
        raise ValueError(SURROGATE_REASON)
    return value


#: A string of valid Unicode: every text field that is stored or echoed uses it (a lone
#: UTF-16 surrogate, ``"\ud800"`` in JSON, cannot be encoded in a response or a file).
Text = Annotated[str, AfterValidator(_valid_text)]

RobotId = Annotated[str, Path(description="Robot id, as listed by GET /robots.", max_length=64)]


class Schema(BaseModel):
    """Base of request models: unknown fields are errors, numbers must be finite."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)


#: The ``group`` field of every request that takes a configuration and a frame.
GROUP_DOC = (
    "A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the "
    "configuration may hold the group's joints only (in the group's order; the other joints "
    "at neutral, or at the seed's values for IK), the default frame is the group's tip, and "
    "Jacobians and IK move only the group's joints."
)


def group_field() -> Any:
    """The ``group`` request field (optional group name)."""
    return Field(None, max_length=256, description=GROUP_DOC)


class ConfigurationIn(Schema):
    """A configuration: ``q`` in joint order, or a ``joint_positions`` map (not both)."""

    q: Configuration | None = Field(
        None,
        description="One value per actuated joint, in the order of GET /robots/{id} "
        "(rad for revolute and continuous joints, m for prismatic ones); with `group`, "
        "one per joint of the group (in the group's order) is accepted too.",
    )
    joint_positions: JointPositions | None = Field(
        None,
        description="Joint name → value (rad or m); joints not given take their neutral value. "
        "Mimic joints may be named (a ROS JointState as is): their value must equal "
        "multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}).",
    )

    group: str | None = group_field()

    def group_config(self, robot: RobotModel) -> tuple[Group | None, np.ndarray]:
        """The ``group`` resolved on ``robot`` (``None`` without one) and the validated wire
        configuration (with a group, ``q`` may hold its joints only)."""
        grp = group(robot, self.group)
        return grp, configuration(robot, grp, self.q, self.joint_positions)
